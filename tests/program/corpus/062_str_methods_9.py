name = 'nut'
if name.isalpha() and '5'.isdigit() and name.find('u') == 1:
    put(board, name, 'red', 5, int('5'))
