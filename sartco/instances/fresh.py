"""Fresh test boards (issue 24, item 3): boards no published file and no seed-42 dataset holds, drawn
from a new seed with the reference test set's distribution, to measure contamination.

Rule: for every test board of the reference (the imported published data, in file order), one
fresh board of the same stratum: the same board kind and combination (so the same object count),
the same quadrant (simple boards) or arrangement (regular boards); within the stratum the object
(filling), colouring and anchor are drawn from random.Random(seed). A draw whose board (its
target) is in an excluded dataset (every file of the published data and of the seed-42 dataset)
or already drawn is rejected and drawn again; when a stratum has nothing left the draw falls back
(regular boards) to the combination under any arrangement of the kind, then to any combination of
as many pieces (each step counted in `fallbacks`: small combinations of complex objects run out,
the seed-42 train split holding most of their boards). The marginals of board kind and object
count are therefore those of the reference exactly, the combinations' nearly (the fallbacks);
colours and anchors follow the generator (sartco.instances.generate). The same config, seed and datasets
give the same records (ids `<kind>_fresh<seed>_<NNNN>`, split "test").
"""
from __future__ import annotations

import json
import random
from collections import Counter
from dataclasses import dataclass, field

from sartco.dataset import BOARD_KINDS, SIMPLE, BoardKind, BoardRecord, RECORD_KEYS

from .arrangements import anchors
from .boards import anchors_in_quadrant, regular_record, simple_record
from .config import Config
from .objects import ObjectSpec, enumerate_objects, place_target

TRIES = 64  # random draws in a stratum before the remaining candidates are listed


def board_key(target) -> str:
    """A board's identity: its target, as sartco.instances.storage.shared_boards compares boards."""
    return json.dumps(target, sort_keys=True)


def board_keys(*datasets: dict[str, list[BoardRecord]]) -> set[str]:
    """The boards of every file of the datasets (records without a target are skipped)."""
    return {board_key(r["target"]) for files in datasets for records in files.values() for r in records
            if r.get("target") is not None}


@dataclass
class FreshReport:
    """What a fresh draw met: candidates that were excluded boards, fallbacks, the overlap left."""
    rejected: int = 0                     # candidates drawn or listed that were excluded boards
    fallbacks: int = 0
    overlap: int = 0                      # fresh boards found in the excluded datasets (0 by construction)
    boards: Counter = field(default_factory=Counter)   # kind key -> fresh boards


class _Strata:
    """Candidates per stratum: (object index, colouring index, where) with `where` an anchor (simple)
    or an arrangement name (regular); built on first use, in enumeration order."""

    def __init__(self, config: Config, kind: BoardKind, objects: tuple[ObjectSpec, ...]):
        self.config, self.kind, self.objects, self.cache = config, kind, objects, {}

    def candidates(self, combo: str | int, where: str | None) -> list[tuple]:
        """combo: a combination name, or an object count (any combination of that many pieces)."""
        key = (combo, where)
        if key not in self.cache:
            out = []
            for oi, obj in enumerate(self.objects):
                if obj.combo != combo and len(obj.shapes) != combo:
                    continue
                if self.kind == SIMPLE:
                    places = [(where, x, y) for x, y in anchors_in_quadrant(obj, where)]
                else:
                    names = [where] if where is not None else self.config.arrangements[self.kind.key]
                    places = [(a,) for a in names if anchors(a, obj) is not None]
                out += [(oi, ci, *p) for ci in range(len(obj.colorings)) for p in places]
            self.cache[key] = out
        return self.cache[key]

    def target(self, cand: tuple):
        obj = self.objects[cand[0]]
        colors = obj.colorings[cand[1]]
        if self.kind == SIMPLE:
            return place_target(obj, colors, [(cand[3], cand[4])])
        return place_target(obj, colors, anchors(cand[2], obj))

    def record(self, cand: tuple) -> dict:
        obj = self.objects[cand[0]]
        colors = obj.colorings[cand[1]]
        if self.kind == SIMPLE:
            return simple_record(obj, colors, cand[2], cand[3], cand[4])
        return regular_record(obj, colors, cand[2], anchors(cand[2], obj), self.kind.object)


def _pick(pool: list[tuple], strata: _Strata, excluded: set[str], taken: set[str], rng: random.Random,
          report: FreshReport):
    def free(cand) -> bool:
        key = board_key(strata.target(cand))
        if key in excluded:
            report.rejected += 1
        return key not in excluded and key not in taken

    for _ in range(TRIES if pool else 0):
        cand = pool[rng.randrange(len(pool))]
        if free(cand):
            return cand
    rest = [c for c in pool if free(c)]
    return rng.choice(rest) if rest else None


def _strata_of(ref: BoardRecord, where: str, kind: BoardKind) -> list[tuple]:
    """The strata tried in turn: the combination where the reference lies, then (regular boards)
    under any arrangement, then any combination of as many pieces, there and anywhere."""
    combo, size = ref["combo_name"], len(ref["shapes"])
    if kind == SIMPLE:
        return [(combo, where), (size, where)]
    return [(combo, where), (combo, None), (size, where), (size, None)]


def fresh_boards(config: Config, seed: int, reference: dict[str, list[BoardRecord]],
                 excluded: set[str]) -> tuple[dict[str, list[BoardRecord]], FreshReport]:
    """Test file name -> fresh records, one per test record of `reference` (a dataset's files)."""
    rng = random.Random(seed)
    objects = enumerate_objects(config.seeds, config.colors)
    report, taken, files = FreshReport(), set(), {}
    for kind in BOARD_KINDS:
        name = kind.dataset_file("test")
        strata = _Strata(config, kind, objects)
        out = []
        for ref in reference.get(name, []):
            where = ref["quadrant"] if kind == SIMPLE else ref["arrangement"]
            cand = None
            for stratum in _strata_of(ref, where, kind):
                cand = _pick(strata.candidates(*stratum), strata, excluded, taken, rng, report)
                if cand is not None:
                    break
                report.fallbacks += 1
            if cand is None:
                raise ValueError(f"no fresh board left for {ref['id']} ({ref['combo_name']}, {where})")
            record = strata.record(cand)
            taken.add(board_key(record["target"]))
            record = dict(record, id=f"{kind.key}_fresh{seed}_{len(out):04d}", split="test",
                          provenance={"source": "fresh", "seed": seed, "matches": ref["id"]})
            out.append({k: record[k] for k in RECORD_KEYS})
        if out:
            files[name] = out
            report.boards[kind.key] = len(out)
    report.overlap = sum(board_key(r["target"]) in excluded for records in files.values() for r in records)
    return files, report


def marginals(records: list[BoardRecord]) -> dict[str, Counter]:
    """The distributions a fresh set must share with its reference, as counts."""
    return {"board_kind": Counter(f"{r['board_type']}_{r['object_type']}" for r in records),
            "object_count": Counter(len(r["shapes"]) for r in records),
            "combo": Counter(r["combo_name"] for r in records),
            "color": Counter(c for r in records for c in r["colors"])}


def total_variation(a: Counter, b: Counter) -> float:
    """Total variation distance between two count distributions (0: equal shares, 1: disjoint)."""
    na, nb = sum(a.values()) or 1, sum(b.values()) or 1
    return 0.5 * sum(abs(a[k] / na - b[k] / nb) for k in set(a) | set(b))
