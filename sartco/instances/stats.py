"""`sartco stats [--json] [--config resources/v1.yaml]`: the paper's Table 1, by enumeration.

Every number is counted at run time from the seed and arrangement templates and the world's
rules: objects (distinct combination names), coloured objects, simple boards (coloured objects
x quadrants in which the object can be anchored), regular boards (arrangements x coloured
objects whose board builds without error).
"""
from __future__ import annotations

import json
from collections import Counter, defaultdict
from typing import Any

from sartco.dataset import REGULAR_COMPLEX, REGULAR_SIMPLE, SIMPLE

from .arrangements import anchors
from .boards import anchors_in_quadrant
from .config import QUADRANTS, Config, load_config
from .objects import enumerate_objects


def table(config: Config) -> dict[str, Any]:
    objects = enumerate_objects(config.seeds, config.colors)
    seeds: dict[str, dict[str, int]] = {}
    per_seed = defaultdict(list)
    for obj in objects:
        per_seed[obj.seed].append(obj)
    for name in config.seeds:
        objs = per_seed[name]
        seeds[name] = {"components": len(objs[0].shapes) if objs else 0, "fillings": len(objs),
                       "combos": len({o.combo for o in objs}),
                       "colored_objects": sum(len(o.colorings) for o in objs)}
    combos = {o.combo for o in objects}
    by_size = Counter(len(c) for c in combos)
    simple = sum(len(o.colorings) for o in objects for q in QUADRANTS if anchors_in_quadrant(o, q))
    arrangements: dict[str, dict[str, int]] = {}
    boards = {SIMPLE.key: simple}
    for board_type in (REGULAR_SIMPLE.key, REGULAR_COMPLEX.key):
        total = 0
        for name in config.arrangements[board_type]:
            ok = [o for o in objects if anchors(name, o) is not None]
            n = sum(len(o.colorings) for o in ok)
            arrangements[name] = {"board_type": board_type, "objects": len(ok),
                                  "combos": len({o.combo for o in ok}), "boards": n}
            total += n
        boards[board_type] = total
    return {
        "config": config.path,
        "seeds": seeds,
        "objects": len(combos),
        "objects_by_components": {str(k): by_size[k] for k in sorted(by_size)},
        "fillings": len(objects),
        "colored_objects": sum(len(o.colorings) for o in objects),
        "arrangements": arrangements,
        "boards": boards,
    }


def text(t: dict[str, Any]) -> str:
    lines = [f"SARTCo Table 1 by enumeration ({t['config']})", "",
             f"{'seed':<20}{'components':>11}{'fillings':>10}{'combos':>8}{'coloured':>10}"]
    for name, s in t["seeds"].items():
        lines.append(f"{name:<20}{s['components']:>11}{s['fillings']:>10}{s['combos']:>8}{s['colored_objects']:>10}")
    by = ", ".join(f"{k}: {v}" for k, v in t["objects_by_components"].items())
    lines += ["", f"objects (distinct combinations): {t['objects']}  (by components {by})",
              f"fillings: {t['fillings']}   coloured objects: {t['colored_objects']:,}", "",
              f"{'arrangement':<20}{'board type':<18}{'objects':>8}{'combos':>8}{'boards':>10}"]
    for name, a in t["arrangements"].items():
        lines.append(f"{name:<20}{a['board_type']:<18}{a['objects']:>8}{a['combos']:>8}{a['boards']:>10,}")
    lines += ["", "boards:"] + [f"  {k:<18}{v:>10,}" for k, v in t["boards"].items()]
    return "\n".join(lines)


def configure(parser) -> None:
    parser.add_argument("--json", action="store_true", help="print JSON instead of a table")
    parser.add_argument("--config", default=None, help="dataset config (default resources/v1.yaml)")


def run(args) -> int:
    t = table(load_config(args.config))
    print(json.dumps(t, indent=1) if args.json else text(t))
    return 0
