"""A GameBenchmark base for the games that end in a build: the game names its master, and the
master its scorer (`scorer_class`: the master also runs it for the transcript's score card,
sartco.clem.core.card); scoring also writes the full-size board pictures the transcripts link to
(sartco.clem.core.pictures).

clemcore takes the one GameBenchmark subclass it finds among a master.py's module members, so
import this module, not the class, into a master.py:

    from sartco.clem.core import benchmark

    class MyGameMaster(ScoreCard, HarnessGuard, MarkdownTranscript, DialogueGameMaster):
        scorer_class = MyScorer

    class MyGameBenchmark(benchmark.BuildBenchmark):
        master_class = MyGameMaster
        episode_fields = benchmark.json_fields(MyEpisode)   # a TypedDict of sartco.episode

Instance files are checked up front. `clem run` loads the models, then the game (this class),
then the instance file, and plays; it hands the game neither the instance rows before playing
nor the `-e` experiment name, and logs any exception with a traceback and goes on (an unknown
experiment is "0 rows", exit 0). So under `clem run` the constructor calls `check_instances` with
the instance file (`instance_file`: the one clemgame.json or `-i` names) and the `-e` experiment
(`clem_run_options`, the one reader of clem's command line: clemcore hands a game no -e), and
before any model is asked stops with one line naming the file, the experiment and the field
(exit code 2): missing or truncated file, no experiments, an episode without a field the master
reads or with a field of the wrong JSON type, a bad value (instance_values.py: board size, target
shapes, colours, cells and buildability, empty turns, unknown board kinds, tasks, modes, variants),
an unknown experiment name (with the list). `sartco check-instances FILE` (sartco.clem.core.check)
makes the same check without clem.
"""
from __future__ import annotations

import argparse
import json
import os
import sys
import typing

from clemcore.clemgame import GameBenchmark

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


class ClemRun(typing.NamedTuple):
    experiment: str | None  # clem run -e: the one experiment to play, None for all
    results_dir: str        # clem run -r
    batch_size: int = 1     # clem run -b (recorded in run.json)


def clem_run_options(argv: list[str] | None = None) -> ClemRun | None:
    """`clem run`'s -e, -r and -b, read from clem's command line (`argv`, default sys.argv); None when
    this process is not `clem run`.

    The one place the package reads the command line, and why it must: clemcore 3.7's `cli.run`
    keeps both options to itself (-e becomes a row filter applied after the game is built, -r the
    folder of its own callbacks) and hands a GameBenchmark only the game spec (whose `instances`
    -i has already set). An unknown -e would otherwise play "0 rows" and exit 0."""
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
    return ClemRun(args.experiment_name, args.results_dir, args.batch_size) if args.command == "run" else None


def instance_file(game_spec) -> str:
    """The instance file clemcore reads for a game spec: in/<instances>.json of its game folder
    (`instances` from clemgame.json or clem run -i; "instances" when neither names one)."""
    name = getattr(game_spec, "instances", None) or "instances"
    return os.path.join(game_spec.game_path, "in", name if name.endswith(".json") else f"{name}.json")


class BuildBenchmark(GameBenchmark):
    master_class = None   # a DialogueGameMaster subclass: (game_spec, experiment, player_models); its
                          # `scorer_class`: a GameScorer subclass (game_name, experiment, game_instance)
    episode_fields = EPISODE_FIELDS  # field -> JSON type every episode of the instance file must have

    def __init__(self, game_spec):
        super().__init__(game_spec)
        self.recorder = None  # writes run.json (sartco.clem.core.provenance) under clem run and sartco resume
        run, resuming = clem_run_options(), provenance.RESUMING
        if run or resuming:
            experiment = run.experiment if run else None
            path = instance_file(game_spec)
            try:
                selected = check_instances(path, self.fields_of, experiment)
            except InstanceFileError as error:
                print(f"{'sartco resume' if resuming else 'clem run'} -g {game_spec.game_name}: {error}", file=sys.stderr)
                raise SystemExit(2) from None  # not an Exception: clem's loop does not log and go on
            if resuming:
                results_dir, episodes, batch_size = resuming
                selected = len(episodes)
            else:
                results_dir, episodes, batch_size = run.results_dir, None, run.batch_size
            self.recorder = provenance.RunRecorder(game_spec.game_name, results_dir, path, experiment, selected,
                                                   batch_size, resume=bool(resuming), episodes=episodes)

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
