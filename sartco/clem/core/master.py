"""The game master base of the games that end in a build: `BuildGameMaster`, which each game's
master inherits (its benchmark inherits sartco.clem.core.benchmark.BuildBenchmark).

It holds clemcore's DialogueGameMaster behind the game core's three mixins, in the one order that
works (each calls the next through super()):

  ScoreCard           (card.py) logs the score card when the episode ends; its `setup` registers
                      the card's recorder after every other base has set up, when clemcore
                      registers its own, so that both see the same events
  HarnessGuard        (harness.py) turns any exception of a step into a harness_error episode;
                      before MarkdownTranscript, so that it sees a NoAnswer (a str that carries
                      the model server's reason) before the transcript escapes it into plain
                      text, and catches whatever the transcript's step raises
  MarkdownTranscript  (transcript.py) escapes each answer once and logs every message in display
                      form; right before DialogueGameMaster, whose step and log methods it wraps
  DialogueGameMaster  clemcore's: the turns, _on_setup / _parse_response / _advance_game / ...

A game master names its scorer (`scorer_class`, the class `clem score` uses too) and implements
clemcore's hooks; it re-states none of the bases.
"""
from __future__ import annotations

from functools import partial

from clemcore.clemgame import DialogueGameMaster

from sartco.scores.metrics import analyse_gold

from . import ahead
from .card import ScoreCard
from .harness import HarnessGuard
from .probes import draw_ahead
from .transcript import MarkdownTranscript


class BuildGameMaster(ScoreCard, HarnessGuard, MarkdownTranscript, DialogueGameMaster):
    """The base of every game master of a game that ends in a build (see the module doc)."""

    def setup(self, **instance):
        super().setup(**instance)
        if self.setup_fault is None:  # (an episode whose setup failed plays no step that would take them)
            # made while the model's first request is out (ahead.py): a probed episode's gold draws,
            # the gold program's half of CodeBLEU
            draw_ahead(instance)
            ahead.submit(partial(analyse_gold, instance.get("gold_code")))
