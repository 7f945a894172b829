"""The scorer shared by the games that end in a build: turns the recorded build into numbers.

Episode scores (scores.json):
  Main Score         100 x execution success; NaN when the episode was aborted (no code found)
  Execution Success  0/1 (NaN when aborted), as the paper's ES
  Exact Match        0/1, whitespace-normalised, against the gold code of the same style (NaN when aborted)
  CodeBLEU           0..1, codebleu weights 0.25 x 4, against the same gold code (NaN when aborted)
  Cell Precision / Cell Recall / Cell F1   of the built board against the target (NaN when aborted)
  Error Category     "success", an ErrorCode value (python/world/sandbox error or mismatch) or "parse_error"
  Error Family       success | parse | python | world | sandbox | mismatch
  Puts               pieces placed by the executed program
Aborted / Success / Lose come from the game's own log (sartco.clem.outcomes.log_outcome).
"""
from __future__ import annotations

import math

from clemcore.clemgame import GameScorer, metrics

from .building import BUILD_KEY, BuildRecord

NAN = float("nan")
SCORES = ("Execution Success", "Exact Match", "CodeBLEU", "Cell Precision", "Cell Recall", "Cell F1")


class BuildScorer(GameScorer):
    """`gold_key` names the instance field holding the gold code of the builder's style."""

    gold_key = "gold_code"

    def __init__(self, game_name: str, experiment: dict, game_instance: dict):
        super().__init__(game_name, experiment, game_instance)

    def compute_round_score(self, round_idx, round_events) -> None:
        pass  # the build is judged once, at the end of the episode

    def compute_episode_scores(self, interactions: dict) -> None:
        from sartco.scores import code_bleu, exact_match

        aborted = bool(interactions.get(metrics.METRIC_ABORTED, 0))
        data = interactions.get(BUILD_KEY)
        record = BuildRecord.from_json(data) if data else None
        if aborted or record is None:
            for name in SCORES:
                self.log_episode_score(name, NAN)
            category = record.category if record else "parse_error"
            self.log_episode_score("Error Category", category)
            self.log_episode_score("Error Family", record.family if record else "parse")
            self.log_episode_score("Puts", 0)
            self.log_episode_score(metrics.BENCH_SCORE, NAN)
            return
        gold = self.game_instance[self.gold_key]
        self.log_episode_score("Execution Success", int(record.es))
        self.log_episode_score("Exact Match", int(exact_match(record.builder_code, gold)))
        self.log_episode_score("CodeBLEU", float(code_bleu(record.builder_code, gold)))
        self.log_episode_score("Cell Precision", record.precision)
        self.log_episode_score("Cell Recall", record.recall)
        self.log_episode_score("Cell F1", record.f1)
        self.log_episode_score("Error Category", record.category)
        self.log_episode_score("Error Family", record.family)
        self.log_episode_score("Puts", record.puts)
        self.log_episode_score(metrics.BENCH_SCORE, 100.0 * record.es)


def is_nan(value) -> bool:
    return isinstance(value, float) and math.isnan(value)
