def ordinal(s):
    return int(s.rstrip('stndrh')) - 1

put(board, 'nut', 'green', ordinal('5th'), ordinal('1st'))
put(board, 'nut', 'green', ordinal('3rd'), ordinal('22nd') - 20)
