"""The flags games/*/instancegenerator.py always took, read into a mode of `sartco instances` and
its options (sartco.instancegen.command; sartco.instancegen.options): the scripts and the command write the same files.

cobot_instruct: no flag -> instruct; --published DIR -> instruct-published; --protocol paper ->
instruct-paper; --fresh SEED (with --published DIR: the published boards) -> instruct-fresh; --train
-> instruct-train; --describers DIR -> instruct-describers. Two of them at once are a UserError
(the scripts used to take one and ignore the other). cobot_describe: always describe.
"""
from __future__ import annotations

import argparse

from sartco.errors import UserError

from .options import DEFAULTS, add_option

# the flags that choose cobot_instruct's mode
CHOOSERS = {"instruct-paper": "--protocol paper", "instruct-fresh": "--fresh", "instruct-describers": "--describers",
            "instruct-train": "--train"}


def _parser(description: str) -> argparse.ArgumentParser:
    parser = argparse.ArgumentParser(description=description)
    for name in ("dataset", "seed", "examples"):
        add_option(parser, name)
    return parser


def _instruct_parser() -> argparse.ArgumentParser:
    parser = _parser("Build the episodes of cobot_instruct from SARTCo datasets (= sartco instances instruct...).")
    add_option(parser, "published", help="imported published dataset folder: write in/instances_published.json "
                                         "and in/instances_published_feedback.json instead")
    add_option(parser, "describers", help="dataset from `sartco import-instructions`: write in/instances_describers.json")
    parser.add_argument("--protocol", choices=("sartco", "paper"), default="sartco",
                        help="paper: write in/instances_paper.json, the paper protocol on the published test files")
    add_option(parser, "paper_data", help="--protocol paper: the published SARTCo files")
    for name in ("ablation_episodes", "smoke", "attempts"):
        add_option(parser, name)
    parser.add_argument("--train", action="store_true", help="write in/instances_train.json (the train split) instead")
    add_option(parser, "train_episodes", help="with --train: episodes per cell (0: all)")
    add_option(parser, "fresh", help="write in/instances_fresh.json: published beside fresh boards")
    add_option(parser, "fresh_episodes", help="with --fresh: boards per cell (0: all)")
    return parser


def _describe_parser() -> argparse.ArgumentParser:
    parser = _parser("Instances of cobot_describe from a generated dataset's test split (= sartco instances describe).")
    for name in ("smoke", "questions", "corrections", "slice"):
        add_option(parser, name)
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
    return mode, argparse.Namespace(**{**DEFAULTS, **vars(args)})
