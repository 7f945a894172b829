"""The benchmark base of the games that end in a build, and the run it is built for.

`BuildBenchmark` (a clemcore GameBenchmark) is what each game's benchmark inherits, beside
sartco.clem.core.master.BuildGameMaster for its game master: the game names its master
(`master_class`), the master its scorer (`scorer_class`: the master also runs it for the
transcript's score card, sartco.clem.core.card); scoring also writes the full-size board pictures
the transcripts link to (sartco.clem.core.pictures). clemcore plays the one GameBenchmark
subclass among a games/<game>/master.py's module members, so that file imports the game's
benchmark and nothing else.

    from sartco.clem.core.benchmark import BuildBenchmark
    from sartco.clem.core.instance_checks import json_fields
    from sartco.clem.core.master import BuildGameMaster

    class MyGameMaster(BuildGameMaster):
        scorer_class = MyScorer

    class MyGameBenchmark(BuildBenchmark):
        master_class = MyGameMaster
        episode_fields = json_fields(MyEpisode)   # a TypedDict of sartco.episode

The run. `clem run` loads the models, then the game (this class), then the instance file, and
plays; it hands the game neither the instance rows before playing nor the `-e` experiment name,
and logs any exception with a traceback and goes on (an unknown experiment is "0 rows", exit 0).
So when the game is built for a run (`run_options`: `sartco resume` and `sartco suite` pass their
options in the game spec, `run_selector`; under `clem run` they are read from clem's command line,
the one place that reads it: clemcore hands a game neither -e nor -r) the constructor checks the
instance file (`instance_file`: the one clemgame.json or `-i` names) and the `-e` experiment
(sartco.clem.core.instance_checks.check_instances), and before any model is asked stops with one
line naming the file, the experiment and the field (exit code 2); then it writes run.json
(sartco.clem.core.provenance.RunRecorder) for every episode it plays.
"""
from __future__ import annotations

import argparse
import os
import sys
import typing
from pathlib import Path
from typing import Any

from clemcore.clemgame import GameBenchmark, GameSpec

from . import provenance
from .errors import InstanceFileError
from .instance_checks import EPISODE_FIELDS, check_instances
from .pictures import attach_all


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


class BuildBenchmark(GameBenchmark):
    """The base of a game's GameBenchmark (see the module doc): `class X(BuildBenchmark)`."""
    master_class: Any   # a DialogueGameMaster subclass: (game_spec, experiment, player_models); its
                        # `scorer_class`: a GameScorer subclass (game_name, experiment, game_instance)
    episode_fields: dict[str, type] = EPISODE_FIELDS  # field -> JSON type every episode must have

    def __init__(self, game_spec: GameSpec) -> None:
        super().__init__(game_spec)
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
