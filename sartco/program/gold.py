"""The gold programs of the published SARTCo files, with the authors' boards as targets.

Used by the conformance test and by `sartco bench-execute`. The data is read where it lies
(default: ../shared/sartco-data next to the repository), never copied.

Per sample (id `<board_type>/<object_type>/<count>/<combo>/<index>`):
- simple boards: code.multi_turn / single_turn / single_turn_sc total_code;
- regular boards: code.total_code;
- every dialogue: multi-turn editors (one put line per turn) run cumulatively, as
  `board = init_board(8, 8)` + the turns joined; single-turn editors are dicts whose
  total_code runs on its own.
A variant file (`sb_so_test_hc.json`, ...) takes its targets from its base file's gold boards
(`gold_boards/sb_so_test.json`); a file without gold boards gives programs without targets.
"""
from __future__ import annotations

import json
from pathlib import Path
from typing import Iterator, NamedTuple

from sartco.world import DEFAULT_COLS, DEFAULT_ROWS

from sartco.dataset import SHARED_DATA as DEFAULT_DATA


class GoldProgram(NamedTuple):
    file: str       # published file stem, e.g. sb_so_test_hc
    sample: str     # sample id
    kind: str       # code.single_turn, dialogue.multi_turn, dialogue.regular.0, ...
    code: str
    target: dict | None


def base_of(stem: str, gold_stems) -> str | None:
    matches = [g for g in gold_stems if stem == g or stem.startswith(g + "_")]
    return max(matches, key=len) if matches else None


def samples(content: dict) -> Iterator[tuple[str, str, dict]]:
    """(board type, sample id, sample) of one published file's content, in file order."""
    for board_type, by_object in content.items():
        for object_type, by_count in by_object.items():
            for count, by_combo in by_count.items():
                for combo, items in by_combo.items():
                    for index, sample in enumerate(items):
                        yield board_type, f"{board_type}/{object_type}/{count}/{combo}/{index}", sample


def gold_programs(data: Path = DEFAULT_DATA) -> Iterator[GoldProgram]:
    data = Path(data)
    gold_dir = data / "gold_boards"
    gold_stems = sorted(p.stem for p in gold_dir.glob("*.json"))
    boards_cache: dict[str, dict] = {}
    for path in sorted((data / "published").glob("*.json")):
        base = base_of(path.stem, gold_stems)
        if base is not None and base not in boards_cache:
            boards_cache[base] = json.loads((gold_dir / f"{base}.json").read_text())
        boards = boards_cache.get(base, {})
        for board_type, sid, sample in samples(json.loads(path.read_text())):
            target = boards.get(sid)
            for kind, code in _programs(board_type, sample):
                yield GoldProgram(path.stem, sid, kind, code, target)


def _programs(board_type: str, sample: dict):
    code = sample["code"]
    if board_type == "simple":
        for style in ("multi_turn", "single_turn", "single_turn_sc"):
            yield f"code.{style}", code[style]["total_code"]
    else:
        yield "code", code["total_code"]
    for name, dialogue in sample.get("dialogues", {}).items():
        editors = [turn["<Editor>"] for turn in dialogue["instructions"]]
        if editors and all(isinstance(e, str) for e in editors):
            yield f"dialogue.{name}", f"board = init_board({DEFAULT_ROWS}, {DEFAULT_COLS})\n" + "\n".join(editors)
        else:
            for j, editor in enumerate(editors):
                yield f"dialogue.{name}.{j}", editor["total_code"]
