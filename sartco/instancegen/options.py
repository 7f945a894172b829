"""The options of `sartco instances` and the game scripts: every mode's namespace holds every option
(the defaults below), and one check of their bounds."""
from __future__ import annotations

import argparse

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


def check(o: argparse.Namespace) -> None:
    """UserError naming the first option whose value is out of its bounds."""
    for name, low, high in BOUNDS:
        value = getattr(o, name)
        if value is not None and (value < low or (high is not None and value > high)):
            flag = "the fresh seed" if name == "fresh" else "--" + name.replace("_", "-")
            span = f"between {low} and {high}" if high is not None else f"at least {low}"
            raise UserError(f"{flag} must be {span}, not {value}")
