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

from pathlib import Path
from typing import Iterator, NamedTuple

from sartco.dataset import SHARED_DATA, SIMPLE
from sartco.world import DEFAULT_COLS, DEFAULT_ROWS

from .files import gold_boards, name_of, read_samples, require_data


class GoldProgram(NamedTuple):
    file: str       # published file stem, e.g. sb_so_test_hc
    sample: str     # sample id
    kind: str       # code.single_turn, dialogue.multi_turn, dialogue.regular.0, ...
    code: str
    target: dict | None


def gold_programs(data: Path = SHARED_DATA) -> Iterator[GoldProgram]:
    data = Path(data)
    require_data(data)
    for path in sorted((data / "published").glob("*.json")):
        boards = gold_boards(data / "gold_boards", path.name) or {}
        simple = name_of(path.name).kind.board == SIMPLE.board
        for sid, sample in read_samples(path):
            target = boards.get(sid)
            for kind, code in _programs(simple, sample):
                yield GoldProgram(path.stem, sid, kind, code, target)


def _programs(simple: bool, sample: dict):
    code = sample["code"]
    if simple:
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
