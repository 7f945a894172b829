print(f'placing {1}')
put(board, 'washer', 'red', 1, 1)
print('done', 'ok', sep='-')
