"""An instance file, checked before any model is asked (by the benchmark a run is built for,
sartco.clem.core.benchmark, and by `sartco check-instances`, sartco.clem.core.check): its layout,
each episode's fields and their JSON types, then their values. A bad file is the file's fault,
never the model's, so it stops `clem run` with one line (InstanceFileError, naming the file, the
experiment and the field) instead of being scored as a mismatch or losing the episode mid-run.

    check_instances(path, fields, experiment) -> episodes selected   the whole check
    json_fields(EpisodeType) -> {field: JSON type}   the fields a master reads (sartco.episode's
                                                   TypedDicts); EPISODE_FIELDS: every build episode's
    experiment_problem(experiment) -> str | None   known board kinds, tasks, splits, modes, variants
    episode_problem(episode) -> str | None         board size, target, turns

Each problem is one phrase naming the field and its value (the caller puts file and episode in
front). The board size is the world's (DEFAULT_ROWS x DEFAULT_COLS: every prompt, ours and the
authors', describes an 8x8 grid); a target is canonical cells (sartco.world.board) inside that
board, of the world's shapes and colours, at most MAX_DEPTH high, and buildable through `put`
(its pieces, level by level, rebuild exactly these cells).
"""
from __future__ import annotations

import json
import os
import typing

from sartco.dataset import BOARD_TYPES, OBJECT_TYPES, SPLITS, TASKS
from sartco.episode import DIALOGUE_MODES, PlayedEpisode
from sartco.follower.correct import pieces
from sartco.paper.vocabulary import VARIANTS
from sartco.world import COLORS, DEFAULT_COLS, DEFAULT_ROWS, MAX_DEPTH, SHAPES, Board, WorldError, put
from sartco.world.board import KEY, parse_key

from .errors import InstanceFileError

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


def json_fields(episode_type) -> dict[str, type]:
    """field -> JSON type (int, str, dict, list) of every required field of an episode TypedDict
    of sartco.episode, in the order the type states them."""
    hints = typing.get_type_hints(episode_type)
    return {name: typing.get_origin(hint) or hint for name, hint in hints.items()
            if name in episode_type.__required_keys__}


# the fields every build episode needs (read by sartco.clem.core.building and the scorer)
EPISODE_FIELDS = json_fields(PlayedEpisode)
_JSON_TYPE = {int: "a number", str: "a string", dict: "an object", list: "a list"}


# the fields every build episode needs (read by sartco.clem.core.building and the scorer)
EPISODE_FIELDS = json_fields(PlayedEpisode)
_JSON_TYPE = {int: "a number", str: "a string", dict: "an object", list: "a list"}


def check_instances(path: str, fields, experiment: str | None = None) -> int:
    """Check an instance file (clemcore's layout: {"experiments": [{"name", "game_instances":
    [{...}]}]}); return the number of episodes that `experiment` (None: all) selects. `fields`:
    field -> JSON type every episode must have, or a function of the episode giving that dict."""
    fields_of = fields if callable(fields) else (lambda _episode: fields)
    try:
        with open(path, encoding="utf-8") as f:
            data = json.load(f)
    except FileNotFoundError:
        folder = os.path.dirname(path)
        found = sorted(n[:-5] for n in os.listdir(folder) if n.endswith(".json")) if os.path.isdir(folder) else []
        raise InstanceFileError(f"{path}: no such instance file (files in {folder}: {', '.join(found) or 'none'})")
    except (OSError, UnicodeDecodeError) as exc:
        raise InstanceFileError(f"{path}: cannot read ({exc})")
    except json.JSONDecodeError as exc:
        raise InstanceFileError(f"{path}: not valid JSON, truncated or broken at line {exc.lineno} column "
                                f"{exc.colno} ({exc.msg})")
    experiments = data.get("experiments") if isinstance(data, dict) else None
    if not isinstance(experiments, list) or not experiments:
        raise InstanceFileError(f"{path}: no 'experiments' list (expected {{\"experiments\": [...]}})")
    names = []
    for k, exp in enumerate(experiments):
        if not isinstance(exp, dict) or not isinstance(exp.get("name"), str):
            raise InstanceFileError(f"{path}: experiment {k}: no 'name'")
        name = exp["name"]
        names.append(name)
        episodes = exp.get("game_instances")
        if not isinstance(episodes, list):
            raise InstanceFileError(f"{path}: experiment {name}: no 'game_instances' list")
        problem = experiment_problem(exp)
        if problem:
            raise InstanceFileError(f"{path}: experiment {name}: {problem}")
        for i, episode in enumerate(episodes):
            where = f"{path}: experiment {name}, episode {i}"
            if not isinstance(episode, dict):
                raise InstanceFileError(f"{where}: not an object")
            if "game_id" in episode:
                where = f"{path}: experiment {name}, game_id {episode['game_id']}"
            for field, kind in fields_of(episode).items():
                if field not in episode:
                    raise InstanceFileError(f"{where}: missing field '{field}'")
                value = episode[field]
                if not isinstance(value, kind) or (kind is int and isinstance(value, bool)):
                    raise InstanceFileError(f"{where}: field '{field}' is {type(value).__name__} "
                                            f"{json.dumps(value)[:40]}, expected {_JSON_TYPE.get(kind, kind.__name__)}")
            problem = episode_problem(episode)  # the values (above)
            if problem:
                raise InstanceFileError(f"{where}: {problem}")
    if experiment is not None and experiment not in names:
        raise InstanceFileError(f"{path}: no experiment '{experiment}' (experiments: {', '.join(names)})")
    return sum(len(e["game_instances"]) for e in experiments if experiment in (None, e["name"]))
