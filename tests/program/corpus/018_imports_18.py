import numpy as np
put(board, 'washer', 'green', int(np.sqrt(16)), int(np.floor(2.5)))
