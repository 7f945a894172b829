"""Helpers of the tests that play the games: one copy each (tests/games, tests/clem).

- play(instances, experiment, results_dir, ...)   cobot_instruct episodes through clemcore's real
                                                  loop in-process (the `play_episodes` fixture)
- scripted_episode(...)                           a cobot_instruct episode as the generator writes
                                                  one (sartco.episode.InstructEpisode), with
                                                  the `script` mock answers instead of gold code
- fence(code)                                     an answer with its code in a fenced block
- sh(*args)                                       a command that must succeed (its own process:
                                                  tests/helpers/forkserver.py)
- clem_process(args, cwd)                         the `clem` process in `cwd` (its own process, as
                                                  sartco.clem.tooling.benchrun.clem starts it)
- clem(*args)                                     clemcore's CLI in this process, must succeed
- sartco(*args)                                   the `sartco` command in this process: its exit
                                                  status, stdout and stderr
"""
from __future__ import annotations

import contextlib
import io
import json
import os
import subprocess
import sys
from pathlib import Path

from forkserver import command
from sartco.episode import InstructEpisode

REPO = Path(__file__).resolve().parents[2]
GAMES = REPO / "games"


def fence(code: str) -> str:
    return f"Here is the code:\n```python\n{code}\n```"


def scripted_episode(game_id: int, target: dict, gold: list[str], turns: list[str], *,
                     script: list[str] | None = None, single_turn: bool = True) -> InstructEpisode:
    """A first_order episode of a simple board: `turns` the builder's messages; `gold` the puts,
    answered by `mock` all at once (single_turn) or one per turn; `script`: the raw answers
    `mock` gives instead (the last one repeated)."""
    code = "\n".join(gold)
    episode = InstructEpisode(
        game_id=game_id, task="first_order", rows=8, cols=8, target=target, given_code="", gold_code=code,
        board_id=f"scripted_{game_id}", board_type="simple", object_type="simple", combo_name="scripted",
        source="template", turns=turns, instructions=[], gold_turns=[code] if single_turn else list(gold), examples=[])
    if script is not None:
        episode["script"] = script
    return episode


def play(instances: list[dict], experiment: dict, results_dir: Path, model: str = "mock",
         game: str = "cobot_instruct", gen_args: dict | None = None, score: bool = True) -> list[dict]:
    """Run the instances as one experiment of a game entry of games/*/clemgame.json;
    return, per instance, {"interactions", "scores" (None unless `score`), "dir"}."""
    from clemcore import backends
    from clemcore.clemgame import (ExperimentFileSaver, GameBenchmark, GameBenchmarkCallbackList, GameInstances,
                                   GameSpec, InstanceFileSaver, InteractionsFileSaver, ResultsFolder)
    from clemcore.clemgame.runners import sequential

    spec = next(s for folder in ("cobot_instruct", "cobot_describe")
                for s in GameSpec.from_directory(str(GAMES / folder)) if s.game_name == game)
    models = backends.load_models([model], gen_args or dict(temperature=0.0, max_tokens=300))
    folder = ResultsFolder(Path(results_dir), run_dir=backends.Model.to_identifier(models))
    infos = backends.Model.to_infos(models)
    callbacks = GameBenchmarkCallbackList([
        InstanceFileSaver(folder), ExperimentFileSaver(folder, player_model_infos=infos),
        InteractionsFileSaver(folder, player_model_infos=infos),
    ])
    rows = [{"game_name": spec.game_name, "experiment": experiment, "game_instance": inst} for inst in instances]
    with GameBenchmark.load_from_spec(spec) as bench:
        sequential.run(bench, GameInstances(spec.game_name, rows), models, callbacks=callbacks)
        if score:
            bench.compute_scores(sorted(Path(results_dir).rglob("interactions.json")))
    out = []
    for inst in instances:
        d = Path(results_dir) / folder.run_dir / spec.game_name / experiment["name"] / f"instance_{inst['game_id']:05d}"
        out.append({"interactions": json.loads((d / "interactions.json").read_text()),
                    "scores": json.loads((d / "scores.json").read_text().replace("NaN", "null")) if score else None,
                    "dir": d})
    return out


def sh(*args, cwd=REPO, timeout=900) -> subprocess.CompletedProcess:
    """Run a command; fail the test with the end of its output when it fails."""
    done = command(args, cwd=cwd, timeout=timeout)
    assert done.returncode == 0, f"{' '.join(map(str, args))} failed:\n{done.stdout[-2000:]}\n{done.stderr[-2000:]}"
    return done


def clem_process(args: list, cwd: Path) -> float:
    """The `clem` process of sartco.clem.tooling.benchrun.clem (the games of this checkout, the
    registries and key.json of `cwd`), which must succeed, from tests/helpers/forkserver.py; its wall time."""
    import time

    from sartco.clem.tooling import benchrun
    env = benchrun.clem_env()
    start = time.monotonic()
    done = command([Path(sys.executable).parent / "clem", *args], cwd=cwd, env=env, timeout=900)
    assert done.returncode == 0, f"clem {' '.join(map(str, args))} failed:\n{done.stdout[-2000:]}\n{done.stderr[-2000:]}"
    return time.monotonic() - start


def clem(*args, cwd=REPO) -> None:
    """clemcore's CLI (`clem ...`: clemcore.cli.main reading its command line) in this process, from
    `cwd` (where clem finds the registries); fails the test when it exits non-zero. For the tests
    that check what the commands write, not the process: a `clem` process spends about 4 s
    importing clemcore.clemgame, this one imported it once. argv[0] is not `clem`, as under the
    `python -c "from clemcore.cli import main; main()"` this replaces: no run.json (the tests that
    check it run the real `clem`, tests/games/test_runs.py)."""
    from clemcore.cli import main
    argv, here = sys.argv, os.getcwd()
    sys.argv = ["clemcore.cli", *map(str, args)]
    os.chdir(cwd)
    try:
        main()
    except SystemExit as stop:
        assert stop.code in (None, 0), f"clem {' '.join(map(str, args))} exited with {stop.code}"
    finally:
        sys.argv = argv
        os.chdir(here)


def sartco(*args, cwd=REPO) -> subprocess.CompletedProcess:
    """`sartco ...` in this process (sartco.cli.main, which `python -m sartco` and the `sartco`
    script call), from `cwd`: its exit status and what it printed, as a finished process. For the
    tests that check what a command does and says, not the process: most commands import clemcore
    (about 4 s in a new process)."""
    from sartco.cli import main
    out, err, here = io.StringIO(), io.StringIO(), os.getcwd()
    os.chdir(cwd)
    try:
        with contextlib.redirect_stdout(out), contextlib.redirect_stderr(err):
            try:
                status = main([str(a) for a in args])
            except SystemExit as stop:  # argparse's usage errors, a command's exit: as the process ends
                status = stop.code if isinstance(stop.code, int) else 0 if stop.code is None else 1
                if isinstance(stop.code, str):
                    print(stop.code, file=err)
    finally:
        os.chdir(here)
    return subprocess.CompletedProcess(["sartco", *map(str, args)], status, out.getvalue(), err.getvalue())


def stub_scratch(folder: Path, base_url: str, experiments: list[str], episodes: int = 2, **config) -> tuple[dict, Path]:
    """A clem working folder for the model `stub` on openai_batching at `base_url` (key.json,
    model_registry.json with `config` in its model_config) and an instance file of the first
    `episodes` of each cobot_instruct experiment; (the instances, the file without .json: clem run -i)."""
    from sartco.clem.tooling import benchrun

    folder.mkdir(parents=True, exist_ok=True)
    instances = benchrun.select_instances(experiments, episodes)
    file = folder / "instances_small.json"
    file.write_text(json.dumps(instances))
    benchrun.write_scratch(folder, base_url, "openai_batching", 4)
    registry = json.loads((folder / "model_registry.json").read_text())
    registry[0]["model_config"].update(config)
    (folder / "model_registry.json").write_text(json.dumps(registry))
    return instances, file.with_suffix("")
