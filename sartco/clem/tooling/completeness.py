"""Which episodes of a results/<model>/<game> folder are not (validly) played and scored, against
the instance file it was played from (sartco.clem.core.runs.played_instance_file). Shared by
`sartco report` (sartco.report.completeness) and `sartco resume` (sartco.clem.tooling.resume).

An episode of the instance file is one of
  missing     no episode folder, or no interactions.json in it (never played, or the run stopped)
  errored     error.json without completed.json: clemcore caught an exception (e.g. the model
              server failed) and went on; a harness fault, not the model's error
  unscored    interactions.json without scores.json (`clem score` not run on it)
  unreadable  interactions.json or scores.json is not valid JSON
  scored      everything else.
The experiments checked: with run.json those its sessions chose (all of the file when one of
them had no -e; a resume chooses nothing new: sartco.clem.core.runs.selection). A folder without run.json (played before run.json existed, or in-process by
tests) is checked against its game's default instance file only when every episode it holds is
an episode of that file (its instance.json); else it is "unverifiable" (listed, not an error).
"""
from __future__ import annotations

import json
from pathlib import Path

from sartco.clem.core.errors import ProvenanceError
from sartco.clem.core.runs import played_instance_file, selection

INCOMPLETE_STATUS = 3  # exit status of `sartco report` / `sartco resume` when an episode is not scored
PROBLEMS = ("missing", "errored", "unscored", "unreadable")


def readable(path: Path) -> bool:
    try:
        json.loads(path.read_text(encoding="utf-8"))
        return True
    except (OSError, ValueError):
        return False


def episode_state(folder: Path) -> str:
    """One of PROBLEMS or "scored" for an episode folder (see the module doc)."""
    interactions, scores = folder / "interactions.json", folder / "scores.json"
    if not interactions.is_file():
        return "missing"
    if (folder / "error.json").is_file() and not (folder / "completed.json").is_file():
        return "errored"
    if not readable(interactions):
        return "unreadable"
    if not scores.is_file():
        return "unscored"
    return "scored" if readable(scores) else "unreadable"


class Unverifiable(Exception):
    """A folder without run.json that was not played from its game's default instance file (or that
    file is gone): which episodes it should hold is unknown; the message says why."""


def _played_from(game_dir: Path, data: dict, instance_path: Path) -> None:
    """Without run.json: raise Unverifiable unless every episode in the folder is, field for
    field (its instance.json), an episode of the default instance file under the same experiment."""
    episodes = {(e["name"], i["game_id"]): i for e in data.get("experiments", []) for i in e["game_instances"]}
    for path in sorted(Path(game_dir).glob("*/instance_*/instance.json")):
        key = (path.parent.parent.name, int(path.parent.name.split("_")[-1]))
        if not readable(path) or episodes.get(key) != json.loads(path.read_text(encoding="utf-8")):
            raise Unverifiable(f"{game_dir}: no run.json, and {key[0]}/{path.parent.name} is not an episode of "
                               f"{instance_path.name} (played from another instance file)")


def check_game(game_dir: Path) -> tuple[dict[str, int], list[dict], dict | None]:
    """(experiment -> expected episodes, problems, run.json or None) of results/<model>/<game>.
    Raises ProvenanceError (see played_instance_file) and Unverifiable."""
    instance_path, run = played_instance_file(game_dir)
    try:
        data = json.loads(instance_path.read_text(encoding="utf-8"))
    except FileNotFoundError:
        raise Unverifiable(f"{game_dir}: no run.json, and the default instance file {instance_path} does not exist") from None
    except (OSError, ValueError) as exc:
        raise ProvenanceError(f"{game_dir}: cannot read its instance file {instance_path} ({exc}); restore the "
                              f"file the run was played from") from None
    if run is None:
        _played_from(game_dir, data, instance_path)
    chosen = selection(run) if run is not None else {p.name for p in game_dir.iterdir() if p.is_dir()}
    expected, problems = {}, []
    model, game = game_dir.parent.name, game_dir.name
    for experiment in data.get("experiments", []):
        name = experiment["name"]
        if chosen is not None and name not in chosen:
            continue
        expected[name] = len(experiment["game_instances"])
        for instance in experiment["game_instances"]:
            state = episode_state(episode_folder(game_dir, {"experiment": name, "game_id": instance["game_id"]}))
            if state != "scored":
                problems.append({"model": model, "game": game, "experiment": name,
                                 "game_id": instance["game_id"], "problem": state})
    return expected, problems, run


def episode_folder(game_dir: Path, problem: dict) -> Path:
    return Path(game_dir) / problem["experiment"] / f"instance_{problem['game_id']:05d}"


def needs_play(game_dir: Path, problem: dict) -> bool:
    """Must this episode be played again (no readable record of a finished play), or only scored?"""
    folder = episode_folder(game_dir, problem)
    return problem["problem"] in ("missing", "errored") or not readable(folder / "interactions.json")


