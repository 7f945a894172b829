put(board, 'washer', 'blue', int('0x5', 16), int('0b11', 2))
put(board, 'nut', 'blue', len(bin(6)) - 2, len(hex(255)) - 2)
