"""A GameBenchmark base for the games that end in a build: the game names its master and its
scorer; scoring also writes the board pictures for `clem transcribe` (sartco.clem.pictures).

clemcore takes the one GameBenchmark subclass it finds among a master.py's module members, so
import this module, not the class, into a master.py:

    from sartco.clem import benchmark

    class MyGameBenchmark(benchmark.BuildBenchmark):
        master_class = MyGameMaster
        scorer_class = MyScorer
"""
from __future__ import annotations

from clemcore.clemgame import GameBenchmark

from .pictures import attach_all


class BuildBenchmark(GameBenchmark):
    master_class = None   # a DialogueGameMaster subclass: (game_spec, experiment, player_models)
    scorer_class = None   # a GameScorer subclass: (game_name, experiment, game_instance)

    def create_game_master(self, experiment: dict, player_models):
        return self.master_class(self.game_spec, experiment, player_models)

    def create_game_scorer(self, experiment: dict, game_instance: dict):
        return self.scorer_class(self.game_name, experiment, game_instance)

    def compute_scores(self, interaction_files):
        super().compute_scores(interaction_files)
        attach_all(interaction_files)  # board pictures for `clem transcribe`
