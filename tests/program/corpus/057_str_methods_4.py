shape = 'washer'
if shape.startswith('wash') and shape.endswith('er'):
    put(board, shape, 'green', 3, 3)
