"""The flags games/*/instancegenerator.py always took, read into a mode of `sartco instances` and
its options (sartco.instancegen.command; sartco.instancegen.options): the scripts and the command write the same files.

cobot_instruct: no flag -> instruct; --published DIR -> instruct-published; --protocol paper ->
instruct-paper; --fresh SEED (with --published DIR: the published boards) -> instruct-fresh; --train
-> instruct-train; --describers DIR -> instruct-describers. Two of them at once are a UserError
(the scripts used to take one and ignore the other). cobot_describe: always describe.
"""
from __future__ import annotations

import argparse
from pathlib import Path

from sartco.errors import UserError

from .options import DEFAULTS as D

# the flags that choose cobot_instruct's mode
CHOOSERS = {"instruct-paper": "--protocol paper", "instruct-fresh": "--fresh", "instruct-describers": "--describers",
            "instruct-train": "--train"}


def _parser(description: str) -> argparse.ArgumentParser:
    parser = argparse.ArgumentParser(description=description)
    parser.add_argument("--dataset", type=Path, default=D["dataset"], help="generated dataset folder")
    parser.add_argument("--seed", type=int, default=D["seed"], help="seed of the in-context example choice")
    parser.add_argument("--examples", type=int, default=D["examples"], help="in-context examples per prompt (0..10)")
    return parser


def _instruct_parser() -> argparse.ArgumentParser:
    parser = _parser("Build the episodes of cobot_instruct from SARTCo datasets (= sartco instances instruct...).")
    add = parser.add_argument
    add("--published", type=Path, help="imported published dataset folder: write in/instances_published.json "
                                        "and in/instances_published_feedback.json instead")
    add("--describers", type=Path, help="dataset from `sartco import-instructions`: write in/instances_describers.json")
    add("--protocol", choices=("sartco", "paper"), default="sartco",
        help="paper: write in/instances_paper.json, the paper protocol on the published test files")
    add("--paper-data", type=Path, help="--protocol paper: the published SARTCo files")
    add("--ablation-episodes", type=int, default=D["ablation_episodes"])
    add("--smoke", type=int, default=D["smoke"], help="episodes per experiment in in/instances_smoke.json")
    add("--attempts", type=int, default=D["attempts"], help="attempts per episode in the feedback experiments")
    add("--train", action="store_true", help="write in/instances_train.json (the train split) instead")
    add("--train-episodes", type=int, default=D["train_episodes"], help="with --train: episodes per cell (0: all)")
    add("--fresh", type=int, metavar="SEED", help="write in/instances_fresh.json: published beside fresh boards")
    add("--fresh-episodes", type=int, default=D["fresh_episodes"], help="with --fresh: boards per cell (0: all)")
    return parser


def _describe_parser() -> argparse.ArgumentParser:
    parser = _parser("Instances of cobot_describe from a generated dataset's test split (= sartco instances describe).")
    parser.add_argument("--questions", type=int, default=D["questions"], help="questions in the clarify modes")
    parser.add_argument("--corrections", type=int, default=D["corrections"], help="corrections in the correct modes")
    parser.add_argument("--slice", type=int, metavar="N", help="also write the _slice files, N episodes per experiment")
    return parser


def instruct_mode(args: argparse.Namespace) -> str:
    chosen = {"instruct-paper": args.protocol == "paper", "instruct-fresh": args.fresh is not None,
              "instruct-describers": args.describers is not None, "instruct-train": args.train}
    given = [mode for mode, on in chosen.items() if on]
    if args.published is not None and given not in ([], ["instruct-fresh"]):
        given.append("instruct-published")
    if len(given) > 1:
        flags = [CHOOSERS.get(mode, "--published") for mode in given]
        raise UserError(f"{' and '.join(flags)} write different files: give one of them "
                        "(--published goes alone or with --fresh)")
    return given[0] if given else ("instruct-published" if args.published is not None else "instruct")


def parse(game: str, argv: list[str]) -> tuple[str, argparse.Namespace]:
    """(mode, options with every option of DEFAULTS) from a game script's command line."""
    if game == "cobot_instruct":
        args = _instruct_parser().parse_args(argv)
        mode = instruct_mode(args)
    elif game == "cobot_describe":
        args, mode = _describe_parser().parse_args(argv), "describe"
    else:
        raise UserError(f"no instance generator for game {game!r}")
    return mode, argparse.Namespace(**{**D, **vars(args)})
