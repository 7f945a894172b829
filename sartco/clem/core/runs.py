"""run.json read back (written by sartco.clem.core.provenance): what a results/<model>/<game> folder
was played from and what it should hold, for `sartco resume` (sartco.clem.tooling.resume), the
completeness check (sartco.clem.tooling.completeness) and the report (sartco.report.completeness).

    load_run(game_dir) -> dict | None          the folder's run.json (ProvenanceError: unreadable)
    played_instance_file(game_dir) -> (path, run)   run.json's instance file, else the game entry's
                                                default; refuses mixed files and a file changed since
    selecting(run) / selection(run)            the sessions that chose episodes / the experiments
                                                the folder should hold (None: all of the file)
    settings_for(run, experiment)              temperature, max_tokens, batch size it was played with
    game_entries()                             game name -> default instance file (games/*/clemgame.json)
"""
from __future__ import annotations

import hashlib
import json
from pathlib import Path

from sartco.settings import workspace

from .errors import ProvenanceError

RUN_FILE = "run.json"


def sha256_of(path: Path) -> str:
    digest = hashlib.sha256()
    with open(path, "rb") as f:
        for block in iter(lambda: f.read(1 << 20), b""):
            digest.update(block)
    return digest.hexdigest()


def load_run(game_dir: Path) -> dict | None:
    """The run.json of a results/<model>/<game> folder, or None when there is none."""
    path = Path(game_dir) / RUN_FILE
    if not path.is_file():
        return None
    try:
        data = json.loads(path.read_text(encoding="utf-8"))
    except (OSError, ValueError) as exc:
        raise ProvenanceError(f"{path}: cannot read ({exc}); repair it, or remove it to check the folder against "
                              f"its game's default instance file") from None
    if not isinstance(data, dict) or not isinstance(data.get("instance_file"), dict):
        raise ProvenanceError(f"{path}: not a SARTCo run.json (no 'instance_file'); remove it to check the folder "
                              f"against its game's default instance file")
    return data


def selecting(run: dict) -> list[dict]:
    """The sessions of a run.json that chose episodes: every session but the resumes (a resume
    plays again what these chose)."""
    return [s for s in run.get("sessions", []) if not s.get("resume")]


def selection(run: dict) -> set[str] | None:
    """The experiments a results folder should hold by its run.json: those its sessions chose with
    -e, None (all of the instance file) when one of them had no -e."""
    chosen = selecting(run)
    if not chosen or any(not s.get("experiment") for s in chosen):
        return None
    return {s["experiment"] for s in chosen}


def settings_for(run: dict | None, experiment: str) -> dict:
    """{temperature, max_tokens, batch_size} an experiment was played with: those the last session
    that chose it recorded (None for what it did not record, and without run.json)."""
    chose = [s for s in selecting(run or {}) if s.get("experiment") in (None, experiment)]
    session = chose[-1] if chose else {}
    generation = session.get("generation") or {}
    return {"temperature": generation.get("temperature"), "max_tokens": generation.get("max_tokens"),
            "batch_size": session.get("batch_size")}


def game_entries() -> dict[str, Path]:
    """game name -> its default instance file, for every entry of the workspace's games/*/clemgame.json (sartco.settings)."""
    found = {}
    for spec_file in sorted((workspace() / "games").glob("*/clemgame.json")):
        entries = json.loads(spec_file.read_text(encoding="utf-8"))
        for entry in entries if isinstance(entries, list) else [entries]:
            name = entry.get("instances") or "instances"
            found[entry["game_name"]] = spec_file.parent / "in" / (name if name.endswith(".json") else f"{name}.json")
    return found


def played_instance_file(game_dir: Path, run: dict | None = None) -> tuple[Path, dict | None]:
    """(the instance file a results/<model>/<game> folder was played from, its run.json or None):
    run.json's when there is one, else the game entry's default. Raises ProvenanceError when the
    sessions of run.json name different instance files (hashes) or the file changed since."""
    game_dir = Path(game_dir)
    run = run if run is not None else load_run(game_dir)
    if run is None:
        entries = game_entries()
        if game_dir.name not in entries:
            raise ProvenanceError(f"{game_dir}: no run.json and no game entry '{game_dir.name}' in games/*/clemgame.json "
                                  f"(run sartco from the checkout or the folder `sartco games` wrote)")
        return entries[game_dir.name], None
    files = {(s["instance_file"]["path"], s["instance_file"]["sha256"]) for s in run.get("sessions", [])}
    if len({sha for _, sha in files}) > 1:
        listing = ", ".join(f"{path} sha256 {sha[:12]}" for path, sha in sorted(files))
        raise ProvenanceError(f"{game_dir}: refusing to merge runs played from different instance files ({listing}); "
                              f"play each instance file into a results folder (-r) of its own")
    recorded = run["instance_file"]
    path = Path(recorded["path"])
    path = path if path.is_absolute() else workspace() / path
    if not path.is_file():
        raise ProvenanceError(f"{game_dir}: its instance file {recorded['path']} (run.json) no longer exists; "
                              f"regenerate it (run.json's instance_file.generated) or play the run again into a new -r folder")
    if sha256_of(path) != recorded["sha256"]:
        raise ProvenanceError(f"{game_dir}: instance file {recorded['path']} changed since the run "
                              f"(sha256 {recorded['sha256'][:12]} in run.json, now {sha256_of(path)[:12]}); restore the "
                              f"file the run was played from (e.g. git checkout) or play it again into a new -r folder")
    return path, run
