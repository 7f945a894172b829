"""`sartco instances MODE [options]`: the games' instance files (games/<game>/in/) from a dataset,
one mode per set of files, each file written by its own function (sartco.instancegen.instruct and
.describe):

  instruct             cobot_instruct in/instances.json, instances_ablations.json, instances_feedback.json,
                       instances_smoke.json (the committed files)
  instruct-published   in/instances_published.json, instances_published_feedback.json (--published DIR)
  instruct-paper       in/instances_paper.json, the paper protocol (--paper-data DIR)
  instruct-fresh FRESH_SEED  in/instances_fresh.json: published beside fresh boards of FRESH_SEED
  instruct-train       in/instances_train.json, the train split
  instruct-describers DIR  in/instances_describers.json, from `sartco import-instructions`
  describe             cobot_describe in/instances.json, instances_dialogue.json (and --slice N: their
                       _slice files, the committed ones use --slice 2)

The game scripts (games/*/instancegenerator.py) are the same command with the flags they always had
(script_main; sartco.instancegen.legacy). A wrong value is a UserError: one line naming the option
and value, exit code 2, no file written.
"""
from __future__ import annotations

import argparse
import sys
from pathlib import Path

from sartco.errors import UserError
from sartco.instances.examples import MAX_EXAMPLES

from . import describe, instruct
from .common import GAMES
from .legacy import parse
from .options import DEFAULTS as D
from .options import check


def _describe_files(o) -> list:
    slices = o.slice is not None
    return [describe.instances, *[describe.instances_slice] * slices,
            describe.instances_dialogue, *[describe.instances_dialogue_slice] * slices]


# mode -> (game, the files it writes: options -> functions (options, game folder) -> path, help)
MODES = {
    "instruct": ("cobot_instruct", lambda o: [instruct.instances, instruct.instances_ablations,
                                              instruct.instances_feedback, instruct.instances_smoke],
                 "cobot_instruct's committed files: the Table 3 template cells, ablations, feedback, smoke"),
    "instruct-published": ("cobot_instruct", lambda o: [instruct.instances_published,
                                                        instruct.instances_published_feedback],
                           "the human- and model-written cells from the imported published data"),
    "instruct-paper": ("cobot_instruct", lambda o: [instruct.instances_paper], "the paper protocol (../shared)"),
    "instruct-fresh": ("cobot_instruct", lambda o: [instruct.instances_fresh],
                       "the published test boards beside fresh boards of FRESH_SEED"),
    "instruct-train": ("cobot_instruct", lambda o: [instruct.instances_train], "the train split, for training"),
    "instruct-describers": ("cobot_instruct", lambda o: [instruct.instances_describers],
                            "builder episodes from a `sartco import-instructions` dataset"),
    "describe": ("cobot_describe", _describe_files, "cobot_describe's files: one-shot and dialogue modes"),
}
def generate(mode: str, o: argparse.Namespace, game_dir: Path | None = None) -> list[str]:
    """Write the files of `mode` into game_dir/in (default games/<game>/in); the paths written."""
    check(o)
    game, files, _ = MODES[mode]
    for name in ("dataset", "published", "paper_data", "describers"):
        if getattr(o, name) is not None:
            setattr(o, name, Path(getattr(o, name)).resolve())
    return [write(o, Path(game_dir or GAMES / game)) for write in files(o)]


def _common(p: argparse.ArgumentParser, examples: bool = True) -> None:
    p.add_argument("--dataset", type=Path, default=D["dataset"], help="generated dataset folder (default instances/v1)")
    if examples:
        p.add_argument("--seed", type=int, default=D["seed"], help="seed of the in-context example choice")
        p.add_argument("--examples", type=int, default=D["examples"],
                       help=f"in-context examples per prompt (0..{MAX_EXAMPLES}, default {D['examples']})")


def configure(parser: argparse.ArgumentParser) -> None:
    sub = parser.add_subparsers(dest="mode", metavar="MODE", required=True)
    p = {mode: sub.add_parser(mode, help=text, description=text) for mode, (_, _, text) in MODES.items()}
    for mode, q in p.items():
        q.set_defaults(**D)
        _common(q, examples=mode != "instruct-paper")
    p["instruct"].add_argument("--ablation-episodes", type=int, default=D["ablation_episodes"],
                               help="val boards per ablation experiment")
    p["instruct"].add_argument("--smoke", type=int, default=D["smoke"], help="episodes per cell in instances_smoke.json")
    for mode in ("instruct", "instruct-published"):
        p[mode].add_argument("--attempts", type=int, default=D["attempts"],
                             help="attempts per episode in the feedback experiments (at least 2)")
    for mode in ("instruct-published", "instruct-fresh"):
        p[mode].add_argument("--published", type=Path, help="imported published dataset (default instances/published)")
    p["instruct-paper"].add_argument("--paper-data", type=Path,
                                     help="the published SARTCo files (default ../shared/sartco-data/published)")
    p["instruct-fresh"].add_argument("fresh", type=int, metavar="FRESH_SEED", help="seed of the fresh boards")
    p["instruct-fresh"].add_argument("--fresh-episodes", type=int, default=0, help="boards per cell (0: all)")
    p["instruct-train"].add_argument("--train-episodes", type=int, default=0, help="boards per cell (0: all)")
    p["instruct-describers"].add_argument("describers", type=Path, metavar="DIR",
                                          help="a dataset written by `sartco import-instructions`")
    p["describe"].add_argument("--questions", type=int, default=D["questions"],
                               help="questions the builder may ask in the clarify modes")
    p["describe"].add_argument("--corrections", type=int, default=D["corrections"],
                               help="corrections the describer may send in the correct modes")
    p["describe"].add_argument("--slice", type=int, metavar="N", help="also the _slice files, N episodes per experiment")


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
