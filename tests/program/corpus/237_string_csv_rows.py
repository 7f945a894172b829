data = "bridge-h,green,3,3\nnut,red,3,3"
for row in data.split("\n"):
    fields = row.split(",")
    put(board, fields[0], fields[1], int(fields[2]), int(fields[3]))
