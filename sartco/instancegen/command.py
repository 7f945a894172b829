"""`sartco instances MODE [options]`: the games' instance files (games/<game>/in/) from a dataset,
one mode per set of files, each file written by its own function in its game's package
(sartco.games.instruct.instancegenerator, sartco.games.describe.instancegenerator):

  instruct             cobot_instruct in/instances.json, instances_ablations.json, instances_feedback.json,
                       instances_smoke.json (the committed files)
  instruct-published   in/instances_published.json, instances_published_feedback.json (--published DIR)
  instruct-paper       in/instances_paper.json, the paper protocol (--paper-data DIR)
  instruct-fresh FRESH_SEED  in/instances_fresh.json: published beside fresh boards of FRESH_SEED
  instruct-train       in/instances_train.json, the train split
  instruct-describers DIR  in/instances_describers.json, from `sartco import-instructions`
  describe             cobot_describe in/instances.json, instances_smoke.json, instances_dialogue.json
                       (and --slice N: the _slice files, the committed ones use --slice 2)

The game scripts (games/*/instancegenerator.py) are the same command with the flags they always had
(script_main; sartco.instancegen.legacy). A wrong value is a UserError: one line naming the option
and value, exit code 2, no file written.
"""
from __future__ import annotations

import argparse
import sys
from pathlib import Path

from sartco.errors import UserError
from sartco.games.describe import instancegenerator as describe
from sartco.games.instruct import fresh
from sartco.games.instruct import instancegenerator as instruct
from sartco.settings import workspace

from .legacy import parse
from .options import DEFAULTS, add_option, check

GAMES = workspace() / "games"


def _describe_files(options: argparse.Namespace) -> list:
    slices = options.slice is not None
    return [describe.instances, describe.instances_smoke, *[describe.instances_slice] * slices,
            describe.instances_dialogue, *[describe.instances_dialogue_slice] * slices]


# mode -> (game, the files it writes: options -> functions (options, game folder) -> path, help)
MODES = {
    "instruct": ("cobot_instruct", lambda options: [instruct.instances, instruct.instances_ablations,
                                                    instruct.instances_feedback, instruct.instances_smoke],
                 "cobot_instruct's committed files: the Table 3 template cells, ablations, feedback, smoke"),
    "instruct-published": ("cobot_instruct", lambda options: [instruct.instances_published,
                                                              instruct.instances_published_feedback],
                           "the human- and model-written cells from the imported published data"),
    "instruct-paper": ("cobot_instruct", lambda options: [instruct.instances_paper], "the paper protocol (../shared)"),
    "instruct-fresh": ("cobot_instruct", lambda options: [fresh.instances_fresh],
                       "the published test boards beside fresh boards of FRESH_SEED"),
    "instruct-train": ("cobot_instruct", lambda options: [instruct.instances_train], "the train split, for training"),
    "instruct-describers": ("cobot_instruct", lambda options: [instruct.instances_describers],
                            "builder episodes from a `sartco import-instructions` dataset"),
    "describe": ("cobot_describe", _describe_files, "cobot_describe's files: one-shot and dialogue modes"),
}


def generate(mode: str, options: argparse.Namespace, game_dir: Path | None = None) -> list[str]:
    """Write the files of `mode` into game_dir/in (default games/<game>/in); the paths written."""
    check(options)
    game, files, _ = MODES[mode]
    for name in ("dataset", "published", "paper_data", "describers"):
        if getattr(options, name) is not None:
            setattr(options, name, Path(getattr(options, name)).resolve())
    return [write(options, Path(game_dir or GAMES / game)) for write in files(options)]


def configure(parser: argparse.ArgumentParser) -> None:
    sub = parser.add_subparsers(dest="mode", metavar="MODE", required=True)
    modes = {mode: sub.add_parser(mode, help=text, description=text) for mode, (_, _, text) in MODES.items()}
    for mode, mode_parser in modes.items():
        mode_parser.set_defaults(**DEFAULTS)
        # the paper protocol keeps the authors' prompts: no example choice of ours
        for name in ("dataset",) if mode == "instruct-paper" else ("dataset", "seed", "examples"):
            add_option(mode_parser, name)
    # (mode, option, positional) for every option a mode offers beyond those
    for mode, name, positional in [("instruct", "ablation_episodes", False), ("instruct", "smoke", False),
                                   ("instruct", "attempts", False), ("instruct-published", "attempts", False),
                                   ("instruct-published", "published", False), ("instruct-fresh", "published", False),
                                   ("instruct-paper", "paper_data", False), ("instruct-fresh", "fresh", True),
                                   ("instruct-fresh", "fresh_episodes", False),
                                   ("instruct-train", "train_episodes", False), ("instruct-describers", "describers", True),
                                   ("describe", "smoke", False), ("describe", "questions", False), ("describe", "corrections", False),
                                   ("describe", "slice", False)]:
        add_option(modes[mode], name, positional=positional)


def run(args: argparse.Namespace) -> int:
    generate(args.mode, args)
    return 0


def script_main(game: str, game_dir: Path, argv: list[str] | None = None) -> int:
    """games/<game>/instancegenerator.py: the flags it always had, the same files and code."""
    try:
        mode, options = parse(game, sys.argv[1:] if argv is None else argv)
        generate(mode, options, game_dir)
    except UserError as exc:
        print(f"instancegenerator: {exc}", file=sys.stderr)
        return 2
    return 0
