"""Which episodes of a results/<model>/<game> folder are not (validly) played and scored, against
the instance file it was played from (sartco.clem.provenance.played_instance_file). Shared by
`sartco report` (sartco.report.completeness) and `sartco resume` (sartco.clem.resume).

An episode of the instance file is one of
  missing     no episode folder, or no interactions.json in it (never played, or the run stopped)
  errored     error.json without completed.json: clemcore caught an exception (e.g. the model
              server failed) and went on; a harness fault, not the model's error
  unscored    interactions.json without scores.json (`clem score` not run on it)
  unreadable  interactions.json or scores.json is not valid JSON
  scored      everything else.
The experiments checked: with run.json those its sessions played (all of the file when one of
them had no -e), without it those with a folder.
"""
from __future__ import annotations

import json
from pathlib import Path

from .provenance import ProvenanceError, played_instance_file

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


def check_game(game_dir: Path) -> tuple[dict[str, int], list[dict], dict | None]:
    """(experiment -> expected episodes, problems, run.json or None) of results/<model>/<game>."""
    instance_path, run = played_instance_file(game_dir)
    try:
        data = json.loads(instance_path.read_text(encoding="utf-8"))
    except (OSError, ValueError) as exc:
        raise ProvenanceError(f"{game_dir}: cannot read its instance file {instance_path} ({exc})") from None
    if run is not None and all(s.get("experiment") for s in run.get("sessions", [])):
        chosen = {s["experiment"] for s in run["sessions"]}
    else:
        chosen = None if run is not None else {p.name for p in game_dir.iterdir() if p.is_dir()}
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


