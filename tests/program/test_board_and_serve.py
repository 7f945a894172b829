"""Board.cells() gives the canonical row-major order; `sartco execute` answers pipelined batches in order."""
from sartco.world import Board, put


def test_cells_canonical_order():
    board = Board(12, 12)
    put(board, "nut", "red", 11, 2)
    put(board, "bridge-h", "blue", 2, 10)
    put(board, "washer", "green", 2, 3)
    assert list(board.cells()) == ["2:3", "2:10", "2:11", "11:2"]
    assert board.cells()["2:11"] == [["bridge-h", "blue"]]


def test_serve_pipelined_batches_answer_in_order():
    """Small batches, several in flight over two workers: every line answered once, in order."""
    import io
    import json

    from sartco.program.serve import serve

    lines = []
    for i in range(200):
        if i % 37 == 5:
            lines.append("not json")
        elif i % 11 == 3:
            lines.append("")  # blank: no answer
        else:
            lines.append(json.dumps({"id": f"p{i}", "code": f"put(board, 'nut', 'red', {i % 8}, {i // 8 % 8})\nx = {i}"}))
    out = io.BytesIO()
    n = serve(io.BytesIO("\n".join(lines).encode()), out, workers=2, batch=7, cache=False)
    rows = [json.loads(r) for r in out.getvalue().splitlines()]
    expected = [line for line in lines if line.strip()]
    assert n == len(rows) == len(expected)
    for line, row in zip(expected, rows):
        if line == "not json":
            assert row["error"] == "parse_error" and row["id"] is None
        else:
            i = int(json.loads(line)["id"][1:])
            assert row["id"] == f"p{i}" and row["ok"] and row["cells"] == {f"{i % 8}:{i // 8 % 8}": [["nut", "red"]]}
