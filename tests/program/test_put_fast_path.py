"""put()'s fast path must agree exactly with check() (the documented rule order)."""
import random

from sartco.world import Board, WorldError, put
from sartco.world.rules import check

SHAPES = ["washer", "nut", "screw", "bridge-h", "bridge-v", "bolt", "", 3, None, ["nut"]]
COLORS = ["red", "green", "blue", "yellow", "pink", 1, None]
COORDS = [0, 1, 2, 3, 6, 7, 8, -1, True, 1.0, "1"]


class Str(str):
    pass


def _reference(board, shape, color, x, y):
    piece = (shape, color)
    for cx, cy in check(board, shape, color, x, y):
        board.stacks[cx][cy].append(piece)
    board.puts += 1


def _outcome(fn, board, args):
    try:
        fn(board, *args)
        return None
    except WorldError as exc:
        return (exc.code, exc.message)
    except Exception as exc:  # noqa: BLE001
        return (type(exc).__name__,)


def test_fast_put_agrees_with_check():
    rng = random.Random(7)
    for _ in range(300):
        rows, cols = rng.choice([(8, 8), (3, 5), (1, 1), (2, 7)])
        fast, slow = Board(rows, cols), Board(rows, cols)
        for _ in range(60):
            if rng.random() < 0.8:
                args = (rng.choice(SHAPES[:5]), rng.choice(COLORS[:4]), rng.randrange(rows), rng.randrange(cols))
            else:
                args = (rng.choice(SHAPES), rng.choice(COLORS), rng.choice(COORDS), rng.choice(COORDS))
            if rng.random() < 0.05:
                args = (Str(args[0]) if type(args[0]) is str else args[0], args[1], args[2], args[3])
            assert _outcome(put, fast, args) == _outcome(_reference, slow, args), args
            assert fast.stacks == slow.stacks and fast.puts == slow.puts
            assert list(fast.cells().items()) == list(slow.cells().items())


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

    from sartco.program.cli import serve

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
