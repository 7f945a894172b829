for i, name in enumerate(['Red', 'GREEN', 'bLuE']):
    put(board, 'washer', name.lower(), i, 6)
