"""What a worker process of `sartco suite` (sartco/suite.py) runs: a preparation (a command's
argv) or a play (clem run, clem score and clem transcribe of one game/model pair in its stage
folder RESULTS/.suite/<n>, then moved into place; a pair half played before is completed by
`sartco resume`), and the task's last error line for the terminal.
"""
from __future__ import annotations

import argparse
import contextlib
import logging
import os
import shutil
import sys
import time
import traceback
from pathlib import Path

from sartco.clock import cpu_seconds
from sartco.schedule import Done, Task

STAGE = ".suite"  # RESULTS/.suite/<n>: where play n is played, before it moves into place


def prepare(argv: tuple) -> int:
    if argv[0] == "sartco":
        from sartco import cli
        return cli.main(list(argv[1:]))
    from sartco.instancegen.command import script_main
    return script_main("cobot_instruct", Path("games/cobot_instruct").resolve(), list(argv[1:]))


def play(task: Task, results: Path) -> int:
    """clem run, clem score and clem transcribe of one pair, in its stage folder; then into place.
    A pair already in place is done; one half played (its run.json there) is completed by `sartco
    resume` (which plays what is missing, scores and transcribes)."""
    from clemcore import cli as clem_cli
    from clemcore.backends import ModelSpec
    from clemcore.clemgame import GameBenchmark, GameRegistry
    from clemcore.clemgame.transcripts.builder import build_transcripts

    from sartco.clem.core.benchmark import run_selector
    from sartco.clem.core.runs import RUN_FILE
    from sartco.clem.tooling import resume

    stage = results / STAGE / str(task.index)
    run_dir = resume.run_folder([task.model])
    target, game_dir = results / run_dir / task.game, stage / run_dir / task.game
    if target.is_dir():
        return 0
    if (game_dir / RUN_FILE).is_file():
        status = resume.run(argparse.Namespace(results=stage, game=task.game, models=[task.model], temperature=None,
                                               max_tokens=None, batch_size=None))
        if status:
            return status
    else:
        shutil.rmtree(stage, ignore_errors=True)
        temperature, max_tokens = task.settings
        try:
            clem_cli.run(run_selector(task.game, stage, batch_size=task.batch_size), ModelSpec.from_strings([task.model]),
                         gen_args=dict(temperature=temperature, max_tokens=max_tokens), results_dir_path=stage,
                         instances_filename=task.instances, batch_size=task.batch_size)
        except SystemExit as exc:  # clemcore exits 1 after logging a game's exception; a bad instance file: 2
            if exc.code:
                return int(exc.code) if isinstance(exc.code, int) else 1
        files = sorted(game_dir.rglob("interactions.json"))
        spec = next(s for s in GameRegistry.from_directories_and_cwd_files().get_game_specs_that_unify_with(task.game)
                    if s.game_name == task.game)
        played = cpu_seconds()
        with GameBenchmark.load_from_spec(spec) as bench:
            bench.compute_scores(files)
        scored = cpu_seconds()
        build_transcripts(str(game_dir))
        print(f"== suite: {task.name}: CPU s of scoring {scored - played:.1f}, of transcribing "
              f"{cpu_seconds() - scored:.1f}", flush=True)
    target.parent.mkdir(parents=True, exist_ok=True)
    os.rename(game_dir, target)
    return 0


class LastError(logging.Handler):
    """The last error line of a task: what it wrote to stderr (a progress bar's redraw aside) or
    logged at ERROR, its last line."""

    def __init__(self, stream) -> None:
        super().__init__(logging.ERROR)
        self.stream, self.line = stream, ""

    def keep(self, text: str) -> None:
        lines = [line.strip() for line in str(text).splitlines() if line.strip()]
        if lines:
            self.line = lines[-1]

    def emit(self, record: logging.LogRecord) -> None:
        self.keep(record.getMessage())

    def write(self, text: str) -> int:
        if "\r" not in text:
            self.keep(text)
        return self.stream.write(text)

    def flush(self) -> None:
        self.stream.flush()


def run(task: Task, results: str) -> Done:
    from sartco.clem.core.sandbox import restart

    start, cpu = time.monotonic(), cpu_seconds()
    print(f"== suite: {task.name}", flush=True)
    last = LastError(sys.stderr)
    logging.getLogger().addHandler(last)
    try:
        with contextlib.redirect_stderr(last):  # type: ignore[type-var]
            status = prepare(task.argv) if task.kind == "prepare" else play(task, Path(results))
        message = "" if status == 0 else f"{last.line} (exit status {status})" if last.line else f"exit status {status}"
    except BaseException as exc:  # noqa: BLE001 - the parent reports it and stops
        traceback.print_exc()
        status, message = 1, f"{type(exc).__name__}: {exc}"
    finally:
        logging.getLogger().removeHandler(last)
        restart()  # the sandbox's templates end, so that their CPU time counts here
        sys.stdout.flush()
        sys.stderr.flush()
    return Done(task.name, status == 0, time.monotonic() - start, cpu_seconds() - cpu, message)
