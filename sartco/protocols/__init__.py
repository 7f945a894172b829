"""The two protocols' episodes behind `sartco export-prompts` and `sartco score-responses`, for
users who generate answers outside clemcore (their own inference stack):

    sartco export-prompts --protocol paper|sartco [--file STEM] [--variant V] [--data DIR]
        -> JSON lines {"id", "protocol", "file", "sample", "variant", "messages": [user message per turn]}
    sartco score-responses --protocol paper|sartco [--data DIR] [FILE ...]   (default: stdin)
        <- JSON lines {"id", "file", "sample", "variant", "responses": [raw answer per turn]}
        -> one line per input line, in order: {"id", "em", "cb", "es", "turns": [...], ...} or
           {"id"?, "error": reason} for a line that cannot be scored (never a crash, nothing dropped)

Protocols:
- `paper` (sartco.paper): the measurement behind the paper's Table 3. file = published test file
  stem, sample = sample id (as in gold_boards/), variant = dialogue key; messages as the authors'
  game sends them; scores per turn (EM, CB pass, ES) and em/cb/es = share of successful turns.
  --data: the SARTCo data folder (published/, gold_boards/, paper-protocol/; default
  ../shared/sartco-data); --generated: the dataset whose train split gives the sb_so / rb_cho
  examples (default instances/v1).
- `sartco` (ours): the episodes of games/cobot_instruct/in/instances.json (and
  instances_published.json when present). file = experiment name, sample = board id, variant =
  task; messages = what the Builder receives per turn (the episode's `turns`: the first holds the
  whole prompt). Scored as the game scores: each
  answer's code found by sartco.clem.core.parsing.parse_code (an answer without code aborts the
  episode: category parse_error, "aborted": true, all scores 0), the turns' code joined and run by
  sartco.clem.core.building.build; em/cb of the whole program against the gold code (sartco.scores),
  es, f1, precision, recall, category; "turns" holds one entry, the whole program (our protocol
  has no CodeBLEU pass: its "cb" is the CodeBLEU score).
  --data: the folder of the instance files (default games/cobot_instruct/in).
"""
from __future__ import annotations

import json
import os
import sys
from pathlib import Path
from typing import Iterable

from sartco.errors import UserError
from sartco.published.files import require_data
from sartco.settings import workspace
from sartco.paper.vocabulary import OUR_PROTOCOL, PROTOCOL, PROTOCOLS
from sartco.text import escape_all

INSTANCES_DIR = workspace() / "games" / "cobot_instruct" / "in"
INSTANCE_FILES = ("instances.json", "instances_published.json")  # the main episodes (not the feedback ones)


def add_common(parser) -> None:
    parser.add_argument("--protocol", choices=PROTOCOLS, required=True,
                        help=f"'{PROTOCOL}': the paper's Table 3 measurement; '{OUR_PROTOCOL}': the project's own")
    parser.add_argument("--data", type=Path, default=None,
                        help="paper: the SARTCo data folder (published/, gold_boards/, paper-protocol/); "
                             "sartco: the folder of cobot_instruct's instance files")
    parser.add_argument("--generated", type=Path, default=None,
                        help="paper: the generated dataset whose train split gives the sb_so and rb_cho examples "
                             "(default instances/v1)")


def paper_episodes(data: Path | None, generated: Path | None, files: Iterable[str] | None = None,
                   variants: Iterable[str] | None = None) -> list[dict]:
    from sartco.paper.episodes import DEFAULT_GENERATED, DEFAULT_PUBLISHED, build_episodes

    published = DEFAULT_PUBLISHED if data is None else Path(data) / "published"
    require_data(published)
    if not published.is_dir():
        raise UserError(f"{published}: no published SARTCo files here (give the data folder with --data)")
    episodes = build_episodes(published, generated or DEFAULT_GENERATED,
                              files=None if files is None else list(files),
                              variants=None if variants is None else list(variants))
    return [e.to_json() for e in episodes]


def our_episodes(data: Path | None) -> list[dict]:
    """Every episode of cobot_instruct's main instance files: the instance plus id, file, sample,
    variant and messages."""
    folder = INSTANCES_DIR if data is None else Path(data)
    present = [folder / name for name in INSTANCE_FILES if (folder / name).is_file()]
    if not present:
        raise UserError(f"{folder}: no {INSTANCE_FILES[0]} (give cobot_instruct's in/ folder with --data)")
    return [episode for path in present for episode in file_episodes(path)]


def file_episodes(path: Path) -> list[dict]:
    """Every episode of one cobot_instruct instance file (our protocol), as `our_episode`; a
    UserError naming the file when it cannot be read as one."""
    try:
        experiments = json.loads(Path(path).read_text(encoding="utf-8"))["experiments"]
        return [our_episode(experiment["name"], instance)
                for experiment in experiments for instance in experiment["game_instances"]]
    except (OSError, ValueError, KeyError, TypeError, IndexError) as exc:
        raise UserError(f"{path}: not a cobot_instruct instance file ({type(exc).__name__}: {exc})") from None


def our_episode(experiment: str, instance: dict) -> dict:
    messages = list(instance["turns"])  # what the Builder receives per turn (the first holds the whole prompt)
    sample, variant = instance["board_id"], instance["task"]
    return {"id": episode_id(experiment, instance), "protocol": OUR_PROTOCOL, "file": experiment,
            "sample": sample, "variant": variant, "messages": messages, "instance": instance}


def episode_id(experiment: str, instance: dict) -> str:
    """An episode's id in our protocol: "<experiment>/<board id>/<task>"."""
    return f"{experiment}/{instance['board_id']}/{instance['task']}"


def write_lines(items: Iterable[dict]) -> int:
    """Write JSON lines to stdout; a reader that stops early (`| head`) ends the output quietly."""
    try:
        for item in items:
            sys.stdout.write(json.dumps(escape_all(item), ensure_ascii=False) + "\n")  # strict UTF-8
        sys.stdout.flush()
    except BrokenPipeError:
        os.dup2(os.open(os.devnull, os.O_WRONLY), sys.stdout.fileno())  # no second error at exit
    return 0
