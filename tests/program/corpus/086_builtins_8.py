list = [3, 4]
type = 'nut'
object = 'washer'
put(board, object, 'red', list[0], list[1])
put(board, type, 'blue', list[0], list[1])
