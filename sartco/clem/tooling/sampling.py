"""`sartco sample -g GAME -m MODEL -n N -t T [-r RESULTS] [-b B] [-i FILE] [-e EXP] [-l TOKENS]`:
N samples of every episode, for pass@k (`sartco report -r RESULTS` writes passk.md / .csv).

The samples are N ordinary `clem run`s (then `clem score`) into sibling folders
RESULTS/samples/s1 .. sN, one clemcore results folder each, with the same game, model,
temperature T and instances; clemcore numbers the episodes the same way in each, so episode k of
s1 and episode k of s2 are two samples of one episode. Ordinary runs (not clemcore's
BranchingRunner) because they work with every backend and runner, `-b` with `openai_batching`
included, and a results folder of one sample is what `sartco report` and `clem eval` already
read. `sartco report -r RESULTS` leaves RESULTS/samples out of its other tables.
clem runs in the current working directory with the environment as given (key.json,
model_registry.json, CLEMBENCH_HOME as for a plain `clem run`).
"""
from __future__ import annotations

import argparse
import subprocess
import sys
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


def clem_args(args: argparse.Namespace, folder: Path) -> list[str]:
    """The `clem run` of one sample."""
    out = ["run", "-g", args.game, "-m", args.model, "-t", str(args.temperature), "-r", str(folder)]
    for flag, value in (("-b", args.batch_size), ("-i", args.instances), ("-e", args.experiment),
                        ("-l", args.max_tokens)):
        if value is not None:
            out += [flag, str(value)]
    return out


def clem(argv: list[str]) -> None:
    clem_bin = Path(sys.executable).parent / "clem"
    done = subprocess.run([str(clem_bin), *argv])
    if done.returncode != 0:
        raise UserError(f"clem {' '.join(argv)} failed (exit {done.returncode}; clem's message is above): fix what it "
                        f"names, then complete that sample with `sartco resume`, or remove the samples folder and sample again")


def run(args: argparse.Namespace) -> int:
    if args.samples < 1:
        raise UserError(f"-n {args.samples}: at least one sample expected (give -n 1 or more)")
    root = args.results / SAMPLES
    if root.exists():
        raise UserError(f"{root} exists already: choose another -r or remove it")
    for k in range(1, args.samples + 1):
        folder = root / f"s{k}"
        clem(clem_args(args, folder))
        clem(["score", "-g", args.game, "-r", str(folder)])
        print(f"sartco sample: sample {k} of {args.samples} in {folder}", flush=True)
    print(f"sartco sample: {args.samples} samples in {root}; `sartco report -r {args.results}` writes passk.md")
    return 0
