"""The options of `sartco instances` and the game scripts, declared once (OPTIONS: type, metavar,
help; DEFAULTS; BOUNDS) and added to a parser by `add_option`: every mode's namespace holds every
option (the defaults below), and one check of their bounds."""
from __future__ import annotations

import argparse
from pathlib import Path

from sartco import settings
from sartco.errors import UserError
from sartco.instances.examples import MAX_EXAMPLES
from sartco.settings import workspace

MAX_SEED = 2**32 - 1  # numpy's: clemcore seeds numpy with it
DEFAULTS = dict(dataset=workspace() / "instances" / "v1", seed=42, examples=5, ablation_episodes=10, smoke=2,
                attempts=settings.FEEDBACK_ATTEMPTS, published=None, paper_data=None, describers=None, fresh=None, fresh_episodes=0, train_episodes=0,
                questions=settings.QUESTIONS, corrections=settings.CORRECTIONS, slice=None)

# (option, least value, greatest value); every mode's namespace holds every option (DEFAULTS)
BOUNDS = [("seed", 0, MAX_SEED), ("examples", 0, MAX_EXAMPLES), ("ablation_episodes", 1, None), ("smoke", 1, None),
          ("attempts", 2, None), ("fresh", 0, MAX_SEED), ("fresh_episodes", 0, None), ("train_episodes", 0, None),
          ("questions", 0, None), ("corrections", 0, None), ("slice", 1, None)]


# option -> (type, metavar or None, help): what `sartco instances` (sartco.instancegen.command) and the
# game scripts (sartco.instancegen.legacy) both offer
OPTIONS: dict[str, tuple[type, str | None, str]] = {
    "dataset": (Path, None, "generated dataset folder (default instances/v1)"),
    "seed": (int, None, "seed of the in-context example choice"),
    "examples": (int, None, f"in-context examples per prompt (0..{MAX_EXAMPLES}, default {DEFAULTS['examples']})"),
    "ablation_episodes": (int, None, "val boards per ablation experiment"),
    "smoke": (int, None, "episodes per experiment in instances_smoke.json (the first of each)"),
    "attempts": (int, None, "attempts per episode in the feedback experiments (at least 2)"),
    "published": (Path, None, "imported published dataset (default instances/published)"),
    "paper_data": (Path, None, "the published SARTCo files (default ../shared/sartco-data/published)"),
    "describers": (Path, "DIR", "a dataset written by `sartco import-instructions`"),
    "fresh": (int, "FRESH_SEED", "seed of the fresh boards"),
    "fresh_episodes": (int, None, "fresh boards: boards per cell (0: all)"),
    "train_episodes": (int, None, "train split: boards per cell (0: all)"),
    "questions": (int, None, "questions the builder may ask in the clarify modes"),
    "corrections": (int, None, "corrections the describer may send in the correct modes"),
    "slice": (int, "N", "also the _slice files, N episodes per experiment"),
}


def add_option(parser: argparse.ArgumentParser, name: str, *, positional: bool = False, help: str | None = None) -> None:
    """Add OPTIONS[name] to a parser: `--name-with-dashes` with its default, or a positional
    argument; `help` replaces the declared text where the option does more (a script's mode flag)."""
    kind, metavar, text = OPTIONS[name]
    if positional:
        parser.add_argument(name, type=kind, metavar=metavar or name.upper(), help=help or text)
    else:
        parser.add_argument("--" + name.replace("_", "-"), type=kind, default=DEFAULTS[name], metavar=metavar,
                            help=help or text)


def check(options: argparse.Namespace) -> None:
    """UserError naming the first option whose value is out of its bounds."""
    for name, low, high in BOUNDS:
        value = getattr(options, name)
        if value is not None and (value < low or (high is not None and value > high)):
            flag = "the fresh seed" if name == "fresh" else "--" + name.replace("_", "-")
            span = f"between {low} and {high}" if high is not None else f"at least {low}"
            raise UserError(f"{flag} must be {span}, not {value}")
