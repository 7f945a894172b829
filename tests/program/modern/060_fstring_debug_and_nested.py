width = 6
x, y = 2, 3
label = f"{x=}, {y=}"
aligned = f"{'washer':>{width}}"
percent = f"{0.5:.1%}"
put(board, aligned.strip(), "blue", x, y)
put(board, "nut", "blue", len(label) % 8, len(percent))
print(f"{board!r:.20}")
