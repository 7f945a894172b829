"""The values of an instance file, checked before any model is asked (sartco.clem.core.benchmark
checks the fields' JSON types, then asks these): a bad value is the file's fault, never the
model's, so it stops `clem run` with one line instead of being scored as a mismatch or losing
the episode mid-run.

    experiment_problem(experiment) -> str | None   known board kinds, tasks, splits, modes, variants
    episode_problem(episode) -> str | None         board size, target, turns
    InstanceGenerator                              the games' generator base: it never writes an
                                                   instance file without episodes (require_episodes)

Each problem is one phrase naming the field and its value (the caller puts file and episode in
front). The board size is the world's (DEFAULT_ROWS x DEFAULT_COLS: every prompt, ours and the
authors', describes an 8x8 grid); a target is canonical cells (sartco.world.board) inside that
board, of the world's shapes and colours, at most MAX_DEPTH high, and buildable through `put`
(its pieces, level by level, rebuild exactly these cells).
"""
from __future__ import annotations

import json
from pathlib import Path

from clemcore.clemgame import GameInstanceGenerator

from sartco.dataset import BOARD_TYPES, OBJECT_TYPES, SPLITS, TASKS
from sartco.episode import DIALOGUE_MODES
from sartco.errors import UserError
from sartco.follower.correct import pieces
from sartco.paper.vocabulary import VARIANTS
from sartco.settings import data_error
from sartco.world import COLORS, DEFAULT_COLS, DEFAULT_ROWS, MAX_DEPTH, SHAPES, Board, WorldError, put
from sartco.world.board import KEY, parse_key

KNOWN = {"board_type": BOARD_TYPES, "object_type": OBJECT_TYPES, "task": TASKS, "split": SPLITS,
         "mode": DIALOGUE_MODES, "variant": VARIANTS}
SIZE = {"rows": DEFAULT_ROWS, "cols": DEFAULT_COLS}
TURN_LISTS = ("turns", "messages", "gold")  # what a master plays turn by turn (paper: messages, gold)


def _shown(value) -> str:
    text = json.dumps(value, ensure_ascii=True)
    return text if len(text) <= 60 else text[:57] + "..."


def _unknown(record: dict) -> str | None:
    for field, known in KNOWN.items():
        if field in record and record[field] not in known:
            return f"field '{field}' is {_shown(record[field])}, expected one of {', '.join(known)}"
    return None


def experiment_problem(experiment: dict) -> str | None:
    return _unknown(experiment)


def _target_problem(target: dict, rows: int, cols: int) -> str | None:
    for key, stack in target.items():
        where = f"target cell {_shown(key)}"
        if not KEY.fullmatch(key):
            return f"{where}: not a \"row:col\" key"
        row, col = parse_key(key)
        if row >= rows or col >= cols:
            return f"{where}: outside the {rows}x{cols} board"
        if not isinstance(stack, list):
            return f"{where}: {_shown(stack)} is not a list of pieces"
        if not 1 <= len(stack) <= MAX_DEPTH:
            return f"{where}: a stack of {len(stack)} pieces (1 to {MAX_DEPTH} expected)"
        for piece in stack:
            if not (isinstance(piece, list) and len(piece) == 2):
                return f"{where}: {_shown(piece)} is not a [shape, colour] pair"
            shape, color = piece
            if shape not in SHAPES:
                return f"{where}: unknown shape {_shown(shape)} (shapes: {', '.join(SHAPES)})"
            if color not in COLORS:
                return f"{where}: unknown colour {_shown(color)} (colours: {', '.join(COLORS)})"
    board = Board(rows, cols)
    try:
        for _, p in pieces(target):
            put(board, p.shape, p.color, p.x, p.y)
    except WorldError as exc:
        return f"target cannot be built through put ({exc.code}: {exc.message})"
    if board.cells() != target:
        return "target cannot be built through put (a bridge listed in one of its two cells only?)"
    return None


def episode_problem(episode: dict) -> str | None:
    for field, size in SIZE.items():
        if field in episode and episode[field] != size:
            return f"field '{field}' is {_shown(episode[field])}, expected {size} (the board every prompt describes)"
    problem = _unknown(episode)
    if problem:
        return problem
    for field in TURN_LISTS:
        if field in episode and not episode[field]:
            return f"field '{field}' is empty (an episode has at least one turn)"
    if isinstance(episode.get("target"), dict):
        return _target_problem(episode["target"], DEFAULT_ROWS, DEFAULT_COLS)
    return None


def require_episodes(instances: dict, source) -> None:
    """UserError unless the generated instances hold an episode: a generator whose input is
    missing (e.g. ../shared) must say so, not replace an instance file with an empty one."""
    if not any(e.get("game_instances") for e in instances.get("experiments", [])):
        if not Path(source).exists():  # a missing data folder: the setting to give, not a path that stands for none
            missing = data_error(source)
            raise UserError(f"{missing or f'{source}: no such file or folder'}; no instance file written")
        raise UserError(f"{source}: no episodes were generated from it; no instance file written")


class InstanceGenerator(GameInstanceGenerator):
    """The games' GameInstanceGenerator: it writes no instance file without episodes (on_generate
    sets `source`, the input that the line names)."""

    source: str | Path = "the generator's input"

    def store_file(self, data, file_name: str, sub_dir: str | None = None) -> str:
        if sub_dir == "in":
            require_episodes(data, self.source)
        return super().store_file(data, file_name, sub_dir=sub_dir)
