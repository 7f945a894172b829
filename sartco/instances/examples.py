"""In-context examples: k records of the train split that share neither the component
combination nor the location with the item, deterministic for a seed.

Location: for a simple board the cell of its first put (its anchor); for a regular board its
arrangement (where on the board the copies go). Examples come from the item's own board and
object type (so they are in the task's code style) and, where the pool allows, differ from one
another in their combination too.
"""
from __future__ import annotations

import random
from typing import Iterable

from sartco.dataset import SIMPLE

MAX_EXAMPLES = 10


def location(record: dict) -> tuple:
    if record["board_type"] == SIMPLE.board:
        p = record["placement"]
        return ("cell", p["x"][0], p["y"][0])
    return ("arrangement", record["arrangement"])


def eligible(item: dict, pool: Iterable[dict]) -> list[dict]:
    loc = location(item)
    return [r for r in pool
            if r["split"] == "train" and r["id"] != item["id"]
            and r["board_type"] == item["board_type"] and r["object_type"] == item["object_type"]
            and r["combo_name"] != item["combo_name"] and location(r) != loc]


def select_examples(item: dict, pool: Iterable[dict], k: int = 5,
                    rng: random.Random | int = 0) -> list[dict]:
    """k examples for item from pool (train records). rng: a random.Random passed down, or an
    int seed; with an int the choice depends only on (seed, item id), not on call order."""
    if not 0 <= k <= MAX_EXAMPLES:
        raise ValueError(f"k must be between 0 and {MAX_EXAMPLES}, got {k}")
    if isinstance(rng, int):
        rng = random.Random(f"{rng}:{item['id']}")
    candidates = sorted(eligible(item, pool), key=lambda r: r["id"])
    rng.shuffle(candidates)
    chosen, combos = [], set()
    for r in candidates:  # first distinct combinations, then whatever is left
        if len(chosen) < k and r["combo_name"] not in combos:
            chosen.append(r)
            combos.add(r["combo_name"])
    for r in candidates:
        if len(chosen) >= k:
            break
        if r not in chosen:
            chosen.append(r)
    return chosen
