base = {"shape": "washer", "color": "red"}
extra = {"color": "yellow"}
merged = base | extra
merged |= {"x": 2}
put(board, merged["shape"], merged["color"], merged["x"], 2)
