"""`sartco generate --config resources/<version>.yaml --seed N --out DIR`: a dataset version.

seeds -> objects -> coloured objects -> boards -> splits -> code styles and instructions.
Every random choice draws from random.Random(seed), passed down; the same config and seed give
byte-identical files.

Splits (the paper's Table 2): for each board type the split sizes of the config. Boards are
drawn combination by combination (a shuffled round over the component combinations, again and
again), so that every split holds each combination at least once where its size allows, and
spreads evenly over them; within a combination every coloured object is equally likely. Simple
boards: one board per coloured object and quadrant, the quadrants of a split its own (train
top-left, val top-right, test the bottom quadrants), the anchor drawn among the quadrant's
cells from which the object fits on the board. Regular boards: one board per arrangement and
coloured object that builds without error; a combination's draws go round its arrangements.
No board is in two splits.
"""
from __future__ import annotations

import random
import time
from collections import defaultdict
from pathlib import Path
from typing import Any, Callable

from sartco.errors import UserError
from sartco.dataset import BOARD_KINDS, RECORD_KEYS, SIMPLE, SPLITS, BoardKind, BoardRecord

from .arrangements import anchors
from .boards import anchors_in_quadrant, regular_record, simple_record
from .config import Config, load_config
from .gold_code import check_dataset
from .objects import ObjectSpec, enumerate_objects
from .storage import FORMAT, dumps, dumps_records, make_folder, shared_boards

def _draw(pool: list, used: set, key: Callable[[Any], Any], rng: random.Random):
    """A random element of pool whose key is not used yet, or None."""
    for _ in range(32):
        cand = pool[rng.randrange(len(pool))]
        if key(cand) not in used:
            return cand
    rest = [c for c in pool if key(c) not in used]
    return rng.choice(rest) if rest else None


def _balanced(n: int, combos: list[str], draw: Callable[[str], Any], rng: random.Random) -> list:
    """n draws, round after round over the combinations in a fresh random order."""
    chosen: list = []
    active = list(combos)
    while len(chosen) < n and active:
        order = active[:]
        rng.shuffle(order)
        for combo in order:
            if len(chosen) >= n:
                break
            cand = draw(combo)
            if cand is None:
                active.remove(combo)
            else:
                chosen.append(cand)
    return chosen


def _finish(records: list[dict], kind: BoardKind, split: str) -> list[BoardRecord]:
    records.sort(key=lambda r: (len(r["combo_name"]), r["combo_name"]))  # stable: draw order within
    out = []
    for i, r in enumerate(records):
        r = dict(r, id=f"{kind.key}_{split}_{i:04d}", split=split)
        out.append({k: r[k] for k in RECORD_KEYS})
    return out


def simple_boards(config: Config, objects: tuple[ObjectSpec, ...], rng: random.Random) -> dict[str, list[BoardRecord]]:
    by_combo: dict[str, list[tuple[int, int]]] = defaultdict(list)
    for oi, obj in enumerate(objects):
        by_combo[obj.combo].extend((oi, ci) for ci in range(len(obj.colorings)))
    combos = sorted(by_combo, key=lambda c: (len(c), c))
    used: set = set()
    files = {}
    for split in SPLITS:
        spec = config.splits[SIMPLE.key][split]
        # a board: (object, colouring, quadrant); the quadrants of the splits are disjoint
        pools = {c: [(oi, ci, q) for q in spec.quadrants for oi, ci in by_combo[c]] for c in combos}

        def draw(combo):
            cand = _draw(pools[combo], used, lambda t: t, rng)
            if cand is not None:
                used.add(cand)
            return cand

        records = []
        for oi, ci, q in _balanced(spec.size, combos, draw, rng):
            obj = objects[oi]
            x, y = rng.choice(anchors_in_quadrant(obj, q))
            records.append(simple_record(obj, obj.colorings[ci], q, x, y))
        files[SIMPLE.dataset_file(split)] = _finish(records, SIMPLE, split)
    return files


def regular_pools(arrangement_names, objects) -> dict[str, dict[str, list[tuple[int, int]]]]:
    """combo -> arrangement -> objects (index, anchors) that build there."""
    pools: dict[str, dict[str, list]] = defaultdict(dict)
    for name in arrangement_names:
        for oi, obj in enumerate(objects):
            where = anchors(name, obj)
            if where is not None:
                pools[obj.combo].setdefault(name, []).append(oi)
    return pools


def regular_boards(config: Config, kind: BoardKind, objects, rng: random.Random) -> dict[str, list[BoardRecord]]:
    names = config.arrangements[kind.key]
    pools = regular_pools(names, objects)
    flat = {(c, a): [(oi, ci) for oi in ois for ci in range(len(objects[oi].colorings))]
            for c, per in pools.items() for a, ois in per.items()}
    combos = sorted(pools, key=lambda c: (len(c), c))
    used: set = set()
    files = {}
    for split in SPLITS:
        spec = config.splits[kind.key][split]
        cycles = {}
        for c in combos:
            arrs = [a for a in names if a in pools[c]]
            rng.shuffle(arrs)
            cycles[c] = arrs

        def draw(combo):
            arrs = cycles[combo]
            while arrs:
                a = arrs.pop(0)
                cand = _draw(flat[(combo, a)], used, lambda t: (a,) + t, rng)
                if cand is not None:
                    arrs.append(a)  # back to the end of the round
                    used.add((a,) + cand)
                    return (a,) + cand
            return None

        records = []
        for a, oi, ci in _balanced(spec.size, combos, draw, rng):
            obj = objects[oi]
            records.append(regular_record(obj, obj.colorings[ci], a, anchors(a, obj), kind.object))
        files[kind.dataset_file(split)] = _finish(records, kind, split)
    return files


def build_dataset(config: Config, seed: int) -> dict[str, list[BoardRecord]]:
    """File name -> records. Deterministic for (config, seed)."""
    rng = random.Random(seed)
    objects = enumerate_objects(config.seeds, config.colors)
    files: dict[str, list[BoardRecord]] = {}
    for kind in BOARD_KINDS:
        child = random.Random(rng.getrandbits(64))  # one stream per board kind, drawn in order
        if kind == SIMPLE:
            files.update(simple_boards(config, objects, child))
        else:
            files.update(regular_boards(config, kind, objects, child))
    _check_disjoint(files)
    return files


def _check_disjoint(files: dict[str, list[BoardRecord]]) -> None:
    """No board (target) in two splits of one board kind nor twice in one split (a regular board
    of simple objects may also be one of complex objects)."""
    for kind in BOARD_KINDS:
        overlaps = shared_boards({name: files[name] for name in map(kind.dataset_file, SPLITS) if name in files})
        if overlaps:
            (first_file, first_id), (file, rid) = overlaps[0][:2]
            raise AssertionError(f"board {rid} of {file} repeats a board of {first_file} ({first_id})")


def manifest(config: Config, seed: int, files: dict[str, list[BoardRecord]]) -> dict[str, Any]:
    return {"format": FORMAT, "version": config.version, "source": "generated", "seed": seed,
            "config": config.raw, "files": {name: len(records) for name, records in files.items()},
            "defects": []}


def write_dataset(config: Config, seed: int, out: str | Path) -> dict[str, int]:
    out = Path(out)
    files = build_dataset(config, seed)
    make_folder(out)
    (out / "manifest.json").write_text(dumps(manifest(config, seed, files)), encoding="utf-8")
    for name, records in files.items():
        (out / name).write_text(dumps_records(records), encoding="utf-8")
    return {name: len(records) for name, records in files.items()}


def configure(parser) -> None:
    parser.add_argument("--config", default=None,
                        help="dataset config, e.g. resources/v1.yaml (default: v1.yaml of sartco.settings' resources)")
    parser.add_argument("--seed", type=int, required=True, help="random seed (same seed, same files)")
    parser.add_argument("--out", required=True, help="output folder, e.g. instances/v1")
    parser.add_argument("--check", action="store_true",
                        help="also run every generated program and compare with its board")


def run(args) -> int:
    if args.seed < 0:  # random.Random(-1) is Random(1): a negative seed would write another seed's data
        raise UserError(f"--seed must be 0 or more, not {args.seed}")
    config = load_config(args.config)
    start = time.perf_counter()
    counts = write_dataset(config, args.seed, args.out)
    took = time.perf_counter() - start
    for name, n in counts.items():
        print(f"{args.out}/{name}: {n} boards")
    print(f"generated {sum(counts.values())} boards in {took:.1f} s")
    if args.check:
        problems = check_dataset(args.out)
        for p in problems[:20]:
            print(p)
        print(f"checked every program: {len(problems)} problems")
        return 1 if problems else 0
    return 0
