"""run.json: what produced a game's results (results/<model-pair>/<game>/run.json).

Written by the game itself (sartco.clem.core.benchmark.BuildBenchmark) under `clem run` and under
`sartco resume`: once when the first episode starts (no `end` yet: a run that was killed keeps
it so) and again when clemcore closes the game. One `sessions` entry per invocation into the same
folder (a first run, its resumes), each with:
  start, end                 ISO times of the invocation
  instance_file              {path (relative to the workspace when inside it:
                             sartco.settings), name, sha256}
  experiment                 the `-e` experiment or null (all experiments of the file)
  models                     clemcore's model entries, without secrets (keys named like key,
                             token, secret, password, auth are left out)
  generation                 the models' generation settings (temperature, max_tokens)
  episodes_selected          episodes the invocation was asked to play (file, -e, resume filter)
  episodes_played            episodes it started
  resume                     true for `sartco resume`
The top level repeats what holds for the whole folder: game, model (the results folder name),
sartco version and git commit (when the repository is a git checkout), clemcore version, the
first session's instance file, models and generation, the first start and the last end, and
the counts summed over sessions. clemcore's own results/<model-pair>/run.json is a different
file (its timing per game) and is left alone.
"""
from __future__ import annotations

import hashlib
import json
import re
import subprocess
from datetime import datetime, timezone
from importlib import metadata
from pathlib import Path

from sartco.settings import CHECKOUT, workspace

RUN_FILE = "run.json"
SECRET = re.compile(r"key|token|secret|password|passwd|auth|credential", re.IGNORECASE)


def sha256_of(path: Path) -> str:
    digest = hashlib.sha256()
    with open(path, "rb") as f:
        for block in iter(lambda: f.read(1 << 20), b""):
            digest.update(block)
    return digest.hexdigest()


def without_secrets(value):
    """A JSON value with every object key that names a secret left out (recursively)."""
    if isinstance(value, dict):
        return {k: without_secrets(v) for k, v in value.items() if not SECRET.search(str(k))}
    if isinstance(value, list):
        return [without_secrets(v) for v in value]
    return value


def _version(package: str) -> str | None:
    try:
        return metadata.version(package)
    except metadata.PackageNotFoundError:
        return None


def git_commit() -> str | None:
    """HEAD of the checkout this package runs from (+ "-dirty" with uncommitted changes), or None (a
    wheel install: no checkout)."""
    if CHECKOUT is None:
        return None
    try:
        head = subprocess.run(["git", "-C", str(CHECKOUT), "rev-parse", "HEAD"], capture_output=True, text=True,
                              timeout=10)
        if head.returncode != 0:
            return None
        dirty = subprocess.run(["git", "-C", str(CHECKOUT), "status", "--porcelain", "--untracked-files=no"],
                               capture_output=True, text=True, timeout=10).stdout.strip()
        return head.stdout.strip() + ("-dirty" if dirty else "")
    except (OSError, subprocess.SubprocessError):
        return None


def instance_file_info(path: Path) -> dict:
    path = Path(path).resolve()
    root = workspace()
    shown = path.relative_to(root) if path.is_relative_to(root) else path
    return {"path": str(shown), "name": path.stem, "sha256": sha256_of(path)}


def _now() -> str:
    return datetime.now(timezone.utc).isoformat(timespec="seconds")


class ProvenanceError(Exception):
    """A results folder whose runs cannot be merged or checked; one line naming the folder."""


def load_run(game_dir: Path) -> dict | None:
    """The run.json of a results/<model>/<game> folder, or None when there is none."""
    path = Path(game_dir) / RUN_FILE
    if not path.is_file():
        return None
    try:
        data = json.loads(path.read_text(encoding="utf-8"))
    except (OSError, ValueError) as exc:
        raise ProvenanceError(f"{path}: cannot read ({exc})") from None
    if not isinstance(data, dict) or not isinstance(data.get("instance_file"), dict):
        raise ProvenanceError(f"{path}: not a SARTCo run.json (no 'instance_file')")
    return data


class RunRecorder:
    """Keeps one invocation's session and writes run.json (see the module doc).

    results_dir: the `-r` folder; instance_path: the instance file played; experiment: `-e` or
    None; selected: episodes the invocation was asked to play."""

    def __init__(self, game_name: str, results_dir: Path, instance_path: Path, experiment: str | None,
                 selected: int, resume: bool = False):
        self.game_name, self.results_dir = game_name, Path(results_dir)
        self.session = {"start": _now(), "end": None, "instance_file": instance_file_info(instance_path),
                        "experiment": experiment, "models": None, "generation": None,
                        "episodes_selected": selected, "episodes_played": 0, "resume": resume}
        self.path: Path | None = None

    def episode_started(self, player_models) -> None:
        """Called for every game master clemcore creates (one per episode)."""
        if self.path is None:
            from clemcore.backends import Model
            self.path = self.results_dir / Model.to_identifier(player_models) / self.game_name / RUN_FILE
            self.session["models"] = [without_secrets(m.model_spec.to_dict()) for m in player_models]
            self.session["generation"] = without_secrets(dict(player_models[0].gen_args)) if player_models else {}
            try:
                previous = load_run(self.path.parent) or {}
            except ProvenanceError:  # an unreadable run.json: this session starts a new one
                previous = {}
            self.previous_sessions = list(previous.get("sessions", []))
        self.session["episodes_played"] += 1
        if self.session["episodes_played"] == 1:
            self.write()

    def close(self) -> None:
        if self.path is not None:
            self.session["end"] = _now()
            self.write()

    def write(self) -> None:
        sessions = self.previous_sessions + [self.session]
        first = sessions[0]
        data = {"game": self.game_name, "model": self.path.parent.parent.name,
                "sartco_version": _version("sartco-bench"), "git_commit": git_commit(),
                "clemcore_version": _version("clemcore"), "instance_file": first["instance_file"],
                "models": first["models"], "generation": first["generation"],
                "start": first["start"], "end": sessions[-1]["end"],
                "counts": {"sessions": len(sessions),
                           "episodes_played": sum(s["episodes_played"] for s in sessions)},
                "sessions": sessions}
        self.path.parent.mkdir(parents=True, exist_ok=True)
        tmp = self.path.with_suffix(".json.tmp")
        tmp.write_text(json.dumps(data, indent=2) + "\n", encoding="utf-8")
        tmp.replace(self.path)


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
            raise ProvenanceError(f"{game_dir}: no run.json and no game entry '{game_dir.name}' in games/*/clemgame.json")
        return entries[game_dir.name], None
    files = {(s["instance_file"]["path"], s["instance_file"]["sha256"]) for s in run.get("sessions", [])}
    if len({sha for _, sha in files}) > 1:
        listing = ", ".join(f"{path} sha256 {sha[:12]}" for path, sha in sorted(files))
        raise ProvenanceError(f"{game_dir}: refusing to merge runs played from different instance files ({listing})")
    recorded = run["instance_file"]
    path = Path(recorded["path"])
    path = path if path.is_absolute() else workspace() / path
    if not path.is_file():
        raise ProvenanceError(f"{game_dir}: its instance file {recorded['path']} (run.json) no longer exists")
    if sha256_of(path) != recorded["sha256"]:
        raise ProvenanceError(f"{game_dir}: instance file {recorded['path']} changed since the run "
                              f"(sha256 {recorded['sha256'][:12]} in run.json, now {sha256_of(path)[:12]})")
    return path, run
