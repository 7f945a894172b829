def builder(x, y):
    level = 0

    def add(shape, color):
        nonlocal level
        put(board, shape, color, x, y)
        level += 1
        return level

    return add

add = builder(2, 4)
add('washer', 'red')
add('nut', 'green')
