"""How often our world gives the same error category as the authors' simulator, on mutated gold programs.

    python tools/world_agreement.py [--data ../shared/sartco-data] [--dataset instances/v1]
                                    [--seed 0] [--json OUT] [--examples N]

Corpus: the first-order gold put sequences of every simple board (the published `sb_so_test` and
`sb_so_val`, code.multi_turn, and the generated dataset's simple boards, code.first_order), each
mutated once per mutation kind (MUTATIONS: coordinates shifted, negative or off the board, another
or an unknown shape, a bridge's orientation flipped, two puts swapped, another or an unknown
colour, a put dropped or repeated, a piece or a bridge stacked on an occupied cell). The mutations
depend only on the seed and the board id.

Ours: the mutated program (`board = init_board(8, 8)` + one put per line) run in the sandbox
(sartco.program.execute_many), category = the error, else the mismatch category of the built board
against the target, else "success". Theirs: AuthorsBoard, a model of the authors' simulator
written from the facts of ../shared/sartco-data/README.md, defects included (negative coordinates
wrap around, colours are stored by their first letter and never checked, a bridge may lie on a
screw, a failing bridge leaves its first half), fed the same puts as data (it runs no code);
category as ours, compared with the same sartco.program.compare.

Prints the agreement (share of mutants with the same category), the same share over the mutants
that meet none of the authors' documented defects (where we deviate on purpose), per mutation
kind, and the disagreements (ours -> theirs, with the defect met, if any).
"""
from __future__ import annotations

import argparse
import json
import random
import re
import sys
from collections import Counter, defaultdict
from pathlib import Path

from sartco.dataset import SHARED_DATA, SIMPLE, SPLITS
from sartco.program import compare, execute_many
from sartco.published import files as published
from sartco.world import BRIDGES, COLORS, DEFAULT_COLS, DEFAULT_ROWS, MAX_DEPTH, SHAPES

REPO = Path(__file__).resolve().parents[1]
DEFAULT_DATASET = REPO / "instances" / "v1"
PUBLISHED = (SIMPLE.published_stem("test"), SIMPLE.published_stem("val"))
SUCCESS = "success"
PUT = re.compile(r"put\(board, '([^']*)', '([^']*)', (-?\d+), (-?\d+)\)")
UNKNOWN_SHAPES = ("bridge", "bolt", "Washer")
UNKNOWN_COLORS = ("black", "purple", "orange", "white")


# --- the authors' simulator, as the shared README states it -------------------------------------

class AuthorsError(Exception):
    def __init__(self, category: str):
        super().__init__(category)
        self.category = category


class AuthorsBoard:
    """8x8 stacks of (shape, first letter of the colour), put in the authors' order of checks."""

    LETTERS = {c[0]: c for c in COLORS}  # how a stored letter reads back ('black' -> 'b' -> blue)

    def __init__(self, rows: int = DEFAULT_ROWS, cols: int = DEFAULT_COLS):
        self.rows, self.cols = rows, cols
        self.stacks = [[[] for _ in range(cols)] for _ in range(rows)]
        self.defects: set[str] = set()  # the documented defects this board's puts ran into

    def _cell(self, x: int, y: int) -> list:
        # Python list indexing: -rows <= x < 0 wraps around (x=-1 is the last row); below, IndexError
        if x < -self.rows or y < -self.cols:
            raise AuthorsError("index_error")
        if x < 0 or y < 0:
            self.defects.add("negative_coordinate")
        return self.stacks[x][y]

    def put(self, shape, color, x, y) -> None:
        if x >= self.rows or y >= self.cols:
            raise AuthorsError("dimensions_mismatch")
        anchor = self._cell(x, y)
        if len(anchor) >= MAX_DEPTH:
            raise AuthorsError("value_error")
        piece = (shape, color[0])  # colours never checked
        if color not in COLORS:
            self.defects.add("unknown_colour")
        if shape in BRIDGES:  # bridges: no screw check, no same-shape checks
            dx, dy = BRIDGES[shape]
            x2, y2 = x + dx, y + dy
            if x2 >= self.rows or y2 >= self.cols:
                raise AuthorsError("value_error")
            if len(anchor) >= 2:
                raise AuthorsError("bridge_placement")
            second = self._cell(x2, y2)
            if any(s and s[-1][0] == "screw" for s in (anchor, second)):
                self.defects.add("bridge_on_screw")
            anchor.append(piece)  # the first half stays when the second fails
            if len(second) >= MAX_DEPTH:
                raise AuthorsError("value_error")
            if len(second) != len(anchor) - 1:
                raise AuthorsError("depth_mismatch")
            second.append(piece)
            return
        if anchor:
            if anchor[-1][0] == "screw":
                raise AuthorsError("not_on_top_of_screw")
            if anchor[-1][0] == shape:
                raise AuthorsError("same_shape_stacking")
            if len(anchor) >= 2 and anchor[-2][0] == shape:
                raise AuthorsError("same_shape_at_alternate_levels")
        if shape not in SHAPES:
            raise AuthorsError("key_error")
        anchor.append(piece)

    def cells(self) -> dict:
        return {f"{r}:{c}": [[s, self.LETTERS.get(k, k)] for s, k in stack]
                for r, row in enumerate(self.stacks) for c, stack in enumerate(row) if stack}


def authors_category(puts, target: dict) -> tuple[str, frozenset]:
    """The category of the puts in the authors' simulator, and the defects they ran into."""
    board = AuthorsBoard()
    try:
        for p in puts:
            board.put(*p)
    except AuthorsError as error:
        return error.category, frozenset(board.defects)
    category = compare(board.cells(), target).category
    return SUCCESS if category is None else str(category), frozenset(board.defects)


# --- the corpus -----------------------------------------------------------------------------------

def parse_puts(lines) -> list[tuple]:
    out = []
    for line in lines:
        m = PUT.fullmatch(line.strip())
        if not m:
            raise ValueError(f"not a first-order put: {line!r}")
        out.append((m[1], m[2], int(m[3]), int(m[4])))
    return out


def gold_boards(data: Path = SHARED_DATA, dataset: Path | None = DEFAULT_DATASET):
    """(board id, gold puts, target) of every simple board of the corpus, in a fixed order."""
    for stem in PUBLISHED:
        boards = published.gold_boards(data / "gold_boards", f"{stem}.json")
        for sid, sample in published.read_samples(data / "published" / f"{stem}.json"):
            yield f"{stem}/{sid}", parse_puts(sample["code"]["multi_turn"]["output"]), boards[sid]
    if dataset is not None:
        for name in sorted(SIMPLE.dataset_file(split) for split in SPLITS):
            path = Path(dataset) / name
            if not path.is_file():
                continue
            for record in json.loads(path.read_text()):
                yield record["id"], parse_puts(record["code"]["first_order"]["steps"]), record["target"]


def _one(puts, rng):
    return rng.randrange(len(puts))


def _replace(puts, i, **changes):
    shape, color, x, y = puts[i]
    new = dict(dict(shape=shape, color=color, x=x, y=y), **changes)
    return puts[:i] + [(new["shape"], new["color"], new["x"], new["y"])] + puts[i + 1:]


def _coordinate(puts, rng, value):
    i = _one(puts, rng)
    axis = rng.choice("xy")
    return _replace(puts, i, **{axis: value(puts[i][2 if axis == "x" else 3])})


def _flip(puts, rng):
    bridges = [i for i, p in enumerate(puts) if p[0] in BRIDGES]
    if not bridges:
        return None
    i = rng.choice(bridges)
    return _replace(puts, i, shape="bridge-v" if puts[i][0] == "bridge-h" else "bridge-h")


def _swap(puts, rng):
    if len(puts) < 2:
        return None
    i = rng.randrange(len(puts) - 1)
    return puts[:i] + [puts[i + 1], puts[i]] + puts[i + 2:]


def _stack(puts, rng, shapes):
    """A piece of one of `shapes` on the cell of a random put, right after that put."""
    i = _one(puts, rng)
    _, _, x, y = puts[i]
    return puts[:i + 1] + [(rng.choice(shapes), rng.choice(COLORS), x, y)] + puts[i + 1:]


MUTATIONS = {
    "shift": lambda p, r: _coordinate(p, r, lambda v: v + r.choice((-2, -1, 1, 2))),
    "negative": lambda p, r: _coordinate(p, r, lambda v: -r.randint(1, 2)),
    "off_board": lambda p, r: _coordinate(p, r, lambda v: DEFAULT_ROWS + r.randint(0, 1)),
    "shape": lambda p, r: (lambda i: _replace(p, i, shape=r.choice([s for s in SHAPES if s != p[i][0]])))(_one(p, r)),
    "unknown_shape": lambda p, r: _replace(p, _one(p, r), shape=r.choice(UNKNOWN_SHAPES)),
    "orientation": _flip,
    "swap": _swap,
    "colour": lambda p, r: (lambda i: _replace(p, i, color=r.choice([c for c in COLORS if c != p[i][1]])))(_one(p, r)),
    "unknown_colour": lambda p, r: _replace(p, _one(p, r), color=r.choice(UNKNOWN_COLORS)),
    "drop": lambda p, r: (lambda i: p[:i] + p[i + 1:])(_one(p, r)) if len(p) > 1 else None,
    "repeat": lambda p, r: (lambda i: p[:i + 1] + [p[i]] + p[i + 1:])(_one(p, r)),
    "stack_piece": lambda p, r: _stack(p, r, ("washer", "nut", "screw")),
    "stack_bridge": lambda p, r: _stack(p, r, tuple(BRIDGES)),
}


def corpus(seed: int = 0, data: Path = SHARED_DATA, dataset: Path | None = DEFAULT_DATASET):
    """(board id, mutation kind, mutated puts, target): one mutant per board and kind that applies."""
    for board_id, puts, target in gold_boards(data, dataset):
        for kind, mutate in MUTATIONS.items():
            mutant = mutate(list(puts), random.Random(f"{seed}:{board_id}:{kind}"))
            if mutant is not None and mutant != puts:
                yield board_id, kind, mutant, target


def program(puts) -> str:
    lines = [f"put(board, {s!r}, {c!r}, {x}, {y})" for s, c, x, y in puts]
    return "\n".join([f"board = init_board({DEFAULT_ROWS}, {DEFAULT_COLS})", *lines]) + "\n"


def our_categories(mutants) -> list[str]:
    results = execute_many([program(puts) for _, _, puts, _ in mutants])
    out = []
    for (_, _, _, target), ex in zip(mutants, results):
        if not ex.ok:
            out.append(str(ex.error))
        else:
            category = compare(ex.cells, target).category
            out.append(SUCCESS if category is None else str(category))
    return out


def measure(seed: int = 0, data: Path = SHARED_DATA, dataset: Path | None = DEFAULT_DATASET) -> dict:
    mutants = list(corpus(seed, data, dataset))
    ours = our_categories(mutants)
    theirs = [authors_category(puts, target) for _, _, puts, target in mutants]
    by_kind: dict[str, list[int]] = defaultdict(lambda: [0, 0])
    pairs: Counter = Counter()
    examples: dict = {}
    clean = [0, 0]  # mutants that met none of the authors' documented defects
    for (board_id, kind, puts, _), o, (t, defects) in zip(mutants, ours, theirs):
        by_kind[kind][0] += o == t
        by_kind[kind][1] += 1
        if not defects:
            clean[0] += o == t
            clean[1] += 1
        if o != t:
            key = (o, t, ",".join(sorted(defects)))
            pairs[key] += 1
            examples.setdefault(key, (board_id, kind, program(puts)))
    agree = sum(by_kind[k][0] for k in by_kind)
    return {
        "mutants": len(mutants), "boards": len({m[0] for m in mutants}), "agree": agree,
        "agreement": agree / len(mutants) if mutants else float("nan"),
        "clean": {"agree": clean[0], "n": clean[1], "agreement": clean[0] / clean[1] if clean[1] else float("nan")},
        "by_kind": {k: {"agree": a, "n": n} for k, (a, n) in by_kind.items()},
        "disagreements": [{"ours": o, "theirs": t, "defects": d, "n": n, "example": examples[o, t, d]}
                          for (o, t, d), n in pairs.most_common()],
    }


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--data", type=Path, default=SHARED_DATA, help="the shared sartco-data folder")
    parser.add_argument("--dataset", type=Path, default=DEFAULT_DATASET, help="a generated dataset (simple boards)")
    parser.add_argument("--seed", type=int, default=0)
    parser.add_argument("--json", type=Path, help="also write the figures here")
    parser.add_argument("--examples", type=int, default=0, help="print a mutant program per disagreement (top N)")
    args = parser.parse_args(argv)
    result = measure(args.seed, args.data, args.dataset)
    print(f"category agreement with the authors' simulator: {result['agree']}/{result['mutants']} "
          f"= {result['agreement']:.4f} ({result['boards']} boards, seed {args.seed})")
    c = result["clean"]
    print(f"  where none of the authors' documented defects is met: {c['agree']}/{c['n']} = {c['agreement']:.4f}")
    for kind, c in result["by_kind"].items():
        print(f"  {kind:15s} {c['agree']:5d}/{c['n']:5d} = {c['agree'] / c['n']:.3f}")
    print("disagreements (ours -> theirs):")
    for i, d in enumerate(result["disagreements"]):
        print(f"  {d['n']:5d}  {d['ours']} -> {d['theirs']}" + (f"  (their defect: {d['defects']})" if d["defects"] else ""))
        if i < args.examples:
            print("        " + d["example"][2].replace("\n", "\n        "))
    if args.json:
        args.json.write_text(json.dumps(result, indent=1) + "\n")
    return 0


if __name__ == "__main__":
    sys.exit(main())
