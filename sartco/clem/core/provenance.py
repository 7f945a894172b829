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
What a results folder's run.json says is read back by sartco.clem.core.runs.
"""
from __future__ import annotations

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

from .errors import ProvenanceError
from .probes import PROBE_SEED
from .runs import RUN_FILE, load_run, sha256_of

# the words of a key name that make its value a secret (api_key, x-api-token, Authorization, apiKey;
# not max_tokens)
SECRET = {"key", "keys", "apikey", "token", "secret", "password", "passwd", "auth", "authorization", "credential",
          "credentials", "bearer", "cookie"}


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
        data = None  # checked before anything is played (instance_checks.check_instances)
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
