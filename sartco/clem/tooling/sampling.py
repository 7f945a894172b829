"""`sartco sample -g GAME -m MODEL -n N -t T [-r RESULTS] [-b B] [-i FILE] [-e EXP] [-l TOKENS]`:
N samples of every episode, for pass@k (`sartco report -r RESULTS` writes passk.md / .csv).

The samples are N ordinary runs (`clem run`, then `clem score`) into sibling folders
RESULTS/samples/s1 .. sN, one clemcore results folder each, with the same game, model,
temperature T and instances; clemcore numbers the episodes the same way in each, so episode k of
s1 and episode k of s2 are two samples of one episode. Ordinary runs (not clemcore's
BranchingRunner) because they work with every backend and runner, `-b` with `openai_batching`
included, and a results folder of one sample is what `sartco report` and `clem eval` already
read. They are played in this process through clemcore's own `run` and `score` (what `clem run`
and `clem score` call; clemcore is imported once, not twice per sample), with the run's options
in the game selector (sartco.clem.core.benchmark.run_selector), so that each sample's run.json
says what `clem run` would have written. `sartco report -r RESULTS` leaves RESULTS/samples out of
its other tables. The runs read the current working directory and the environment as a plain
`clem run` does (key.json, model_registry.json, CLEMBENCH_HOME).

The model, the game, the instance file and the experiment are checked before any sample is played
(sartco.clem.tooling.selectors). The same command again, after a sample failed or was stopped,
completes what is there with `sartco resume` (its settings as run.json records them; one given
that differs is refused) and plays the samples still missing.
"""
from __future__ import annotations

import argparse
from pathlib import Path

from sartco.errors import UserError

SAMPLES = "samples"   # the folder name sartco.report.passk reads (RESULTS/samples/s1..sN)


def configure(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("-g", "--game", required=True, help="the clemgame (e.g. cobot_instruct)")
    parser.add_argument("-m", "--model", required=True, help="the model (a clemcore model name)")
    parser.add_argument("-n", "--samples", required=True, type=int, help="samples per episode (N >= 1)")
    parser.add_argument("-t", "--temperature", required=True, type=float, help="sampling temperature (clem run -t)")
    parser.add_argument("-r", "--results", type=Path, default=Path("results"),
                        help="results folder; the samples go to RESULTS/samples/s1..sN (default: results)")
    parser.add_argument("-b", "--batch-size", type=int, help="clem run -b")
    parser.add_argument("-i", "--instances", help="clem run -i (instance file name)")
    parser.add_argument("-e", "--experiment", help="clem run -e (one experiment)")
    parser.add_argument("-l", "--max-tokens", type=int, help="clem run -l")


def play(args: argparse.Namespace, folder: Path) -> None:
    """One sample: `clem run` of the game and model into `folder`, then `clem score` of it."""
    from clemcore import cli as clem_cli
    from clemcore.backends import ModelSpec

    from sartco.clem.core.benchmark import run_selector

    from .resume import CLEM_DEFAULTS  # clem run's -l and -b when not given

    batch_size = int(args.batch_size or CLEM_DEFAULTS["batch_size"])
    max_tokens = args.max_tokens if args.max_tokens is not None else CLEM_DEFAULTS["max_tokens"]
    try:
        clem_cli.run(run_selector(args.game, folder, experiment=args.experiment, batch_size=batch_size),
                     ModelSpec.from_strings([args.model]),
                     gen_args=dict(temperature=args.temperature, max_tokens=max_tokens),
                     experiment_name=args.experiment, instances_filename=args.instances, results_dir_path=folder,
                     batch_size=batch_size)
    except SystemExit as stop:  # clemcore: 1 after logging an episode's exception; a bad instance file: 2
        if stop.code:
            raise UserError(f"the run of {folder} failed (exit {stop.code}; its message is above): fix what it "
                            f"names, then run the same `sartco sample` command again: it completes that sample "
                            f"and plays the ones still missing") from None
    clem_cli.score(args.game, results_dir=str(folder))


def complete(args: argparse.Namespace, folder: Path, game_dir: Path) -> None:
    """A sample played before (a failed or stopped run): its missing episodes, by `sartco resume`."""
    from .resume import run as resume

    status = resume(argparse.Namespace(results=folder, game=args.game, models=[args.model],
                                       temperature=args.temperature, max_tokens=args.max_tokens,
                                       batch_size=args.batch_size))
    if status:
        raise UserError(f"{game_dir}: still incomplete (its message is above); run the same command again")


def run(args: argparse.Namespace) -> int:
    from .resume import run_folder
    from .selectors import check_instances, check_models

    if args.samples < 1:
        raise UserError(f"-n {args.samples}: at least one sample expected (give -n 1 or more)")
    check_models([args.model])
    check_instances(args.game, args.instances, args.experiment)
    root = args.results / SAMPLES
    for k in range(1, args.samples + 1):
        folder = root / f"s{k}"
        game_dir = folder / run_folder([args.model]) / args.game
        if game_dir.is_dir():
            complete(args, folder, game_dir)
        elif folder.exists():
            raise UserError(f"{folder} holds samples of another game or model: choose another -r, or remove "
                            f"{root} (rm -r {root})")
        else:
            play(args, folder)
        print(f"sartco sample: sample {k} of {args.samples} in {folder}", flush=True)
    print(f"sartco sample: {args.samples} samples in {root}; `sartco report -r {args.results}` writes passk.md")
    return 0
