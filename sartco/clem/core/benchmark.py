"""A GameBenchmark base for the games that end in a build: the game names its master, and the
master its scorer (`scorer_class`: the master also runs it for the transcript's score card,
sartco.clem.core.card); scoring also writes the full-size board pictures the transcripts link to
(sartco.clem.core.pictures).

clemcore plays the one GameBenchmark subclass it finds among a games/<game>/master.py's module
members, so BuildBenchmark is a base beside GameBenchmark, not a subclass of it: a game's master
module (sartco.games.<game>.master) imports it by name and names both bases, and
games/<game>/master.py imports only the game's benchmark.

    from pathlib import Path

from clemcore.clemgame import GameSpec
    from sartco.clem.core.benchmark import BuildBenchmark, json_fields

    class MyGameMaster(ScoreCard, HarnessGuard, MarkdownTranscript, DialogueGameMaster):
        scorer_class = MyScorer

    class MyGameBenchmark(BuildBenchmark, GameBenchmark):
        master_class = MyGameMaster
        episode_fields = json_fields(MyEpisode)   # a TypedDict of sartco.episode

Instance files are checked up front. `clem run` loads the models, then the game (this class),
then the instance file, and plays; it hands the game neither the instance rows before playing
nor the `-e` experiment name, and logs any exception with a traceback and goes on (an unknown
experiment is "0 rows", exit 0). So when the game is built for a run (`run_options`: `sartco
resume` passes its options in the game spec; under `clem run` they are read from clem's command
line, the one place that reads it: clemcore hands a game neither -e nor -r) the constructor calls
`check_instances` with the instance file (`instance_file`: the one clemgame.json or `-i` names)
and the `-e` experiment, and before any model is asked stops with one line naming the file, the
experiment and the field (exit code 2): missing or truncated file, no experiments, an episode
without a field the master reads or with a field of the wrong JSON type, a bad value
(instance_values.py: board size, target shapes, colours, cells and buildability, empty turns,
unknown board kinds, tasks, modes, variants), an unknown experiment name (with the list).
`sartco check-instances FILE` (sartco.clem.core.check) makes the same check without clem.
"""
from __future__ import annotations

import argparse
import json
import os
import sys
import typing
from typing import Any

from pathlib import Path

from clemcore.clemgame import GameSpec

from sartco.episode import PlayedEpisode

from . import provenance
from .instance_values import episode_problem, experiment_problem
from .pictures import attach_all


def json_fields(episode_type) -> dict[str, type]:
    """field -> JSON type (int, str, dict, list) of every required field of an episode TypedDict
    of sartco.episode, in the order the type states them."""
    hints = typing.get_type_hints(episode_type)
    return {name: typing.get_origin(hint) or hint for name, hint in hints.items()
            if name in episode_type.__required_keys__}


# the fields every build episode needs (read by sartco.clem.core.building and the scorer)
EPISODE_FIELDS = json_fields(PlayedEpisode)
_JSON_TYPE = {int: "a number", str: "a string", dict: "an object", list: "a list"}


class InstanceFileError(Exception):
    """An instance file a game cannot play; the message is one line naming file, experiment, field."""


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
            problem = episode_problem(episode)  # the values (instance_values.py)
            if problem:
                raise InstanceFileError(f"{where}: {problem}")
    if experiment is not None and experiment not in names:
        raise InstanceFileError(f"{path}: no experiment '{experiment}' (experiments: {', '.join(names)})")
    return sum(len(e["game_instances"]) for e in experiments if experiment in (None, e["name"]))


class RunOptions(typing.NamedTuple):
    """What a benchmark is built to play (run.json's session, sartco.clem.core.provenance)."""
    results_dir: Path              # clem run -r / sartco resume -r
    experiment: str | None = None  # clem run -e: the one experiment to play, None for all
    batch_size: int = 1            # clem run -b / the resumed session's (recorded in run.json)
    resume_episodes: list | None = None  # sartco resume: [[experiment, game_id], ...] it plays again; None: a clem run


# the game spec entry through which `sartco resume` (sartco.clem.tooling.resume) and `sartco suite`
# (sartco.suite) hand a run's options to the benchmark clemcore builds: {"results_dir": str,
# "experiment": str | null, "batch_size": int, "episodes": [[experiment, game_id], ...] (a resume) or null}
RUN_KEY = "sartco_run"


def run_selector(game_name: str, results_dir: Path, *, experiment: str | None = None, batch_size: int = 1,
                 episodes: list | None = None) -> GameSpec:
    """The game selector a caller of clemcore's `run` gives it: the game entry plus RUN_KEY
    (clemcore unifies it with the registered entry and builds the benchmark from the result)."""
    return GameSpec(game_name=game_name, allow_underspecified=True,
                    **{RUN_KEY: {"results_dir": str(results_dir), "experiment": experiment, "batch_size": batch_size,
                                 "episodes": episodes}})


def resume_selector(game_name: str, results_dir: Path, episodes: list, batch_size: int) -> GameSpec:
    """`sartco resume`'s selector: a run of exactly `episodes` (run.json records it as a resume)."""
    return run_selector(game_name, results_dir, batch_size=batch_size, episodes=episodes)


def run_options(game_spec: GameSpec, argv: list[str] | None = None) -> RunOptions | None:
    """The run a benchmark is built for: the options the game spec carries (RUN_KEY: `sartco
    resume`, `sartco suite`), else `clem run`'s from clem's command line (clem_run_options); None
    when neither (clem score, sartco check-instances, the gym env)."""
    given = getattr(game_spec, RUN_KEY, None)
    if given is not None:
        episodes = given.get("episodes")
        return RunOptions(Path(given["results_dir"]), given.get("experiment"), int(given["batch_size"]),
                          None if episodes is None else list(episodes))
    return clem_run_options(argv)


def clem_run_options(argv: list[str] | None = None) -> RunOptions | None:
    """`clem run`'s -e, -r and -b, read from clem's command line (`argv`, default sys.argv); None when
    this process is not `clem run`.

    The one place the package reads the command line, and why it must: clemcore 3.7's `cli.run`
    keeps both options to itself (-e becomes a row filter applied after the game is built, -r the
    folder of its own callbacks, whose list a game cannot extend) and hands a GameBenchmark only
    the game spec (whose `instances` -i has already set). An unknown -e would otherwise play
    "0 rows" and exit 0."""
    argv = sys.argv if argv is None else argv
    if not argv or os.path.basename(argv[0]) not in ("clem", "clem.exe"):
        return None
    parser = argparse.ArgumentParser(add_help=False)
    parser.add_argument("command", nargs="?")
    parser.add_argument("-e", "--experiment_name", default=None)
    parser.add_argument("-r", "--results_dir", default="results")
    parser.add_argument("-b", "--batch_size", type=int, default=1)
    try:
        args, _ = parser.parse_known_args(argv[1:])
    except SystemExit:  # clem's own parser reports the command line's mistakes
        return None
    return RunOptions(Path(args.results_dir), args.experiment_name, args.batch_size) if args.command == "run" else None


def start_run(game_spec: GameSpec, run: RunOptions, fields) -> provenance.RunRecorder:
    """Check the instance file of a run before any model is asked (a problem: one line on stderr
    and SystemExit(2), not an Exception, which clemcore's loop would log and go past) and make
    the recorder of its run.json."""
    path = instance_file(game_spec)
    resuming = run.resume_episodes is not None
    try:
        selected = check_instances(path, fields, run.experiment)
    except InstanceFileError as error:
        print(f"{'sartco resume' if resuming else 'clem run'} -g {game_spec.game_name}: {error}", file=sys.stderr)
        raise SystemExit(2) from None
    if run.resume_episodes is not None:  # resume: the episodes it plays again, not the file's
        selected = len(run.resume_episodes)
    return provenance.RunRecorder(game_spec.game_name, run.results_dir, Path(path), run.experiment, selected,
                                  run.batch_size, resume=resuming, episodes=run.resume_episodes)


def instance_file(game_spec) -> str:
    """The instance file clemcore reads for a game spec: in/<instances>.json of its game folder
    (`instances` from clemgame.json or clem run -i; "instances" when neither names one)."""
    name = getattr(game_spec, "instances", None) or "instances"
    return os.path.join(game_spec.game_path, "in", name if name.endswith(".json") else f"{name}.json")


class BuildBenchmark:
    """The base of a game's GameBenchmark (see the module doc): `class X(BuildBenchmark, GameBenchmark)`."""
    master_class: Any   # a DialogueGameMaster subclass: (game_spec, experiment, player_models); its
                        # `scorer_class`: a GameScorer subclass (game_name, experiment, game_instance)
    episode_fields: dict[str, type] = EPISODE_FIELDS  # field -> JSON type every episode must have
    game_spec: GameSpec  # set by GameBenchmark, the other base
    game_name: str

    def __init__(self, game_spec: GameSpec) -> None:
        super().__init__(game_spec)  # type: ignore[call-arg]  # GameBenchmark's, next in the game class's MRO
        # writes run.json (sartco.clem.core.provenance) under clem run and sartco resume
        self.recorder: provenance.RunRecorder | None = None
        run = run_options(game_spec)
        if run is not None:
            self.recorder = start_run(game_spec, run, self.fields_of)

    @classmethod
    def fields_of(cls, episode: dict) -> dict:
        """The fields (name -> JSON type) the master reads from this episode."""
        return cls.episode_fields

    def create_game_master(self, experiment: dict, player_models):
        if self.recorder:
            self.recorder.episode_started(player_models)
        return self.master_class(self.game_spec, experiment, player_models)

    def close(self):
        super().close()
        if self.recorder:
            self.recorder.close()

    def create_game_scorer(self, experiment: dict, game_instance: dict):
        return self.master_class.scorer_class(self.game_name, experiment, game_instance)

    def compute_scores(self, interaction_files):
        super().compute_scores(interaction_files)
        attach_all(interaction_files)  # the full-size pictures the transcripts link to
