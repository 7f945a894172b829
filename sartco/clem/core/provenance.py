"""run.json: what produced a game's results (results/<model-pair>/<game>/run.json), enough to repeat it.

Written by the game itself (sartco.clem.core.benchmark.BuildBenchmark) under `clem run` and under
`sartco resume`: each time an episode starts (so a killed run's file counts the episodes played up
to the one that was playing, and has no `end`) and again when clemcore closes the game. One
`sessions` entry per invocation into the same folder (a first run, its resumes), each with:
  start, end                 ISO times of the invocation
  instance_file              {path (relative to the workspace when inside it: sartco.settings),
                             name, sha256, generated: how the file was made (its own `dataset`,
                             `seed` and `generator` fields: dataset version and seed, generator
                             seed, in-context examples; and dataset_manifest: path and sha256 of
                             the dataset's manifest.json, which holds its generation config;
                             null for a file without them)}
  experiment                 the `-e` experiment or null (all experiments of the file)
  models                     clemcore's model entries, without secrets (keys named like key,
                             token, secret, password, auth are left out; a base_url stays)
  generation                 the models' generation settings (clem run's -t temperature, -l max_tokens)
  batch_size                 clem run's -b
  episodes_selected          episodes the invocation was asked to play (file, -e, resume's list)
  episodes_played            episodes it started
  resume                     true for `sartco resume`; its `episodes` lists [experiment, game_id]
                             of each episode it played again. A resume session selects nothing
                             new: the episodes a folder should hold are those of its other
                             sessions (selection), and resume plays each with the settings of the
                             session that selected it (settings_for)
The top level repeats what holds for the whole folder: game, model (the results folder name),
sartco version and git commit (when the repository is a git checkout), clemcore version, the
interpreter (python), the version of every package a score depends on (packages: SCORE_PACKAGES),
the built-in players' and probes' seeds (seeds), the walls around programs (walls: name/up/why
each, sartco.program.walls), the first session's instance file, models,
generation and batch size, the first start and the last end, and the counts summed over sessions.
clemcore's own results/<model-pair>/run.json is a different file (its timing per game) and is left alone.
"""
from __future__ import annotations

import hashlib
import json
import re
import platform
import subprocess
import sys
from datetime import datetime, timezone
from importlib import metadata
from pathlib import Path
from urllib.parse import urlsplit, urlunsplit

from sartco.program.walls import recorded as recorded_walls
from sartco.settings import CHECKOUT, ERRING_FIX, ERRING_RATE, ERRING_SEED, workspace

from .probes import PROBE_SEED

RUN_FILE = "run.json"
# the words of a key name that make its value a secret (api_key, x-api-token, Authorization, apiKey;
# not max_tokens)
SECRET = {"key", "keys", "apikey", "token", "secret", "password", "passwd", "auth", "authorization", "credential",
          "credentials", "bearer", "cookie"}


def sha256_of(path: Path) -> str:
    digest = hashlib.sha256()
    with open(path, "rb") as f:
        for block in iter(lambda: f.read(1 << 20), b""):
            digest.update(block)
    return digest.hexdigest()


def is_secret(name: str) -> bool:
    """Does a key name name a secret (one of its words, split at _ - . and camelCase, is in SECRET)?"""
    words = re.split(r"[^a-z0-9]+", re.sub(r"([a-z0-9])([A-Z])", r"\1_\2", str(name)).lower())
    return any(w in SECRET for w in words)


def without_secrets(value):
    """A JSON value with every object key that names a secret left out (recursively)."""
    if isinstance(value, dict):
        return {k: without_secrets(v) for k, v in value.items() if not is_secret(k)}
    if isinstance(value, list):
        return [without_secrets(v) for v in value]
    return value


def _version(package: str) -> str | None:
    try:
        return metadata.version(package)
    except metadata.PackageNotFoundError:
        return None


# the packages whose versions decide a score (the game and clemcore, CodeBLEU and its parser, numpy)
SCORE_PACKAGES = ("sartco-bench", "clemcore", "codebleu", "tree-sitter", "tree-sitter-python", "numpy")


def environment() -> dict:
    """What the top level of run.json says about the software: interpreter, package versions, seeds."""
    return {"python": {"version": platform.python_version(), "implementation": platform.python_implementation(),
                       "executable": sys.executable},
            "packages": {name: _version(name) for name in SCORE_PACKAGES},
            "seeds": {"erring_players": ERRING_SEED, "erring_slip_rate": ERRING_RATE, "erring_fix_rate": ERRING_FIX,
                      "function_probes": PROBE_SEED}, "walls": recorded_walls()}


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


GENERATION_FIELDS = ("dataset", "seed", "generator")  # an instance file's fields that say how it was made


def instance_file_info(path: Path) -> dict:
    path = Path(path).resolve()
    root = workspace()
    shown = path.relative_to(root) if path.is_relative_to(root) else path
    try:
        data = json.loads(path.read_text(encoding="utf-8"))
    except (OSError, ValueError):
        data = None  # checked before anything is played (benchmark.check_instances)
    made = {k: data[k] for k in GENERATION_FIELDS if k in data} if isinstance(data, dict) else {}
    dataset = made.get("dataset")
    manifest = root / dataset["path"] / "manifest.json" if isinstance(dataset, dict) and isinstance(
        dataset.get("path"), str) else None
    if manifest is not None and manifest.is_file():  # the dataset's generation config, by its hash
        made["dataset_manifest"] = {"path": str(manifest.relative_to(root)) if manifest.is_relative_to(root)
                                    else str(manifest), "sha256": sha256_of(manifest)}
    return {"path": str(shown), "name": path.stem, "sha256": sha256_of(path), "generated": made or None}


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
        raise ProvenanceError(f"{path}: cannot read ({exc}); repair it, or remove it to check the folder against "
                              f"its game's default instance file") from None
    if not isinstance(data, dict) or not isinstance(data.get("instance_file"), dict):
        raise ProvenanceError(f"{path}: not a SARTCo run.json (no 'instance_file'); remove it to check the folder "
                              f"against its game's default instance file")
    return data


def model_entry(model) -> dict:
    """A model's entry for run.json: clemcore's model spec without secrets, and the base_url of its
    server when it has one (an OpenAI-style client; user and password of the URL left out)."""
    entry = without_secrets(model.model_spec.to_dict())
    url = getattr(getattr(model, "client", None), "base_url", None)
    if url is not None:
        parts = urlsplit(str(url))
        entry["base_url"] = urlunsplit((parts.scheme, parts.hostname + (f":{parts.port}" if parts.port else "")
                                        if parts.hostname else parts.netloc, parts.path, "", ""))
    return entry


class RunRecorder:
    """Keeps one invocation's session and writes run.json (see the module doc).

    results_dir: the `-r` folder; instance_path: the instance file played; experiment: `-e` or
    None; selected: episodes the invocation was asked to play; batch_size: -b; episodes: what a
    resume plays ([experiment, game_id] each)."""

    def __init__(self, game_name: str, results_dir: Path, instance_path: Path, experiment: str | None,
                 selected: int, batch_size: int, resume: bool = False, episodes: list | None = None):
        self.game_name, self.results_dir = game_name, Path(results_dir)
        self.session = {"start": _now(), "end": None, "instance_file": instance_file_info(instance_path),
                        "experiment": experiment, "models": None, "generation": None, "batch_size": batch_size,
                        "episodes_selected": selected, "episodes_played": 0, "resume": resume}
        if resume:
            self.session["episodes"] = episodes or []
        self.path: Path | None = None
        self.software = {"git_commit": git_commit(), **environment()}

    def episode_started(self, player_models) -> None:
        """Called for every game master clemcore creates (one per episode): run.json is written
        each time, so that a run killed part-way says how far it got."""
        if self.path is None:
            from clemcore.backends import Model
            self.path = self.results_dir / Model.to_identifier(player_models) / self.game_name / RUN_FILE
            self.session["models"] = [model_entry(m) for m in player_models]
            self.session["generation"] = without_secrets(dict(player_models[0].gen_args)) if player_models else {}
            try:
                previous = load_run(self.path.parent) or {}
            except ProvenanceError:  # an unreadable run.json: this session starts a new one
                previous = {}
            self.previous_sessions = list(previous.get("sessions", []))
        self.session["episodes_played"] += 1
        self.write()

    def close(self) -> None:
        if self.path is not None:
            self.session["end"] = _now()
            self.write()

    def write(self) -> None:
        path = self.path
        if path is None:  # no episode yet: nothing to record
            return
        sessions = self.previous_sessions + [self.session]
        first = sessions[0]
        data = {"game": self.game_name, "model": path.parent.parent.name,
                "sartco_version": self.software["packages"]["sartco-bench"], "git_commit": self.software["git_commit"],
                "clemcore_version": self.software["packages"]["clemcore"], "python": self.software["python"],
                "packages": self.software["packages"], "seeds": self.software["seeds"], "walls": self.software["walls"],
                "instance_file": first["instance_file"], "models": first["models"], "generation": first["generation"],
                "batch_size": first.get("batch_size"), "start": first["start"], "end": sessions[-1]["end"],
                "counts": {"sessions": len(sessions),
                           "episodes_played": sum(s["episodes_played"] for s in sessions)},
                "sessions": sessions}
        path.parent.mkdir(parents=True, exist_ok=True)
        tmp = path.with_suffix(".json.tmp")
        tmp.write_text(json.dumps(data, indent=2) + "\n", encoding="utf-8")
        tmp.replace(path)


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
