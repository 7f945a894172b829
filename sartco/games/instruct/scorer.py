"""cobot_instruct's scorer: what `clem score` (and the transcript's score card) computes from an
episode's interactions.json, for every episode of every cobot_instruct entry.

InstructScorer = BuildScorer's scores (ours: ES, EM, CodeBLEU, cell F1, error category, probes,
attempts) plus, for an episode of the paper protocol (sartco.games.instruct.paper), "Paper EM",
"Paper CB", "Paper ES" (shares of the dialogue's turns, 0..1), the same per turn as round scores,
Main Score = 100 x Paper ES, and "Paper ES Leak-free": Paper ES with each answer run without the
gold object function in front (regular cells; elsewhere it equals Paper ES). Probed cells
(sartco.clem.core.probes) also get the function probes of our build's code.
"""
from __future__ import annotations

from sartco.clem.core.scoring import BuildScorer
from sartco.episode import LEAK_FREE_ES, PAPER_KEY, PAPER_SCORES


class InstructScorer(BuildScorer):
    """Scores every cobot_instruct episode: BuildScorer's, plus the paper protocol's for an episode
    played in it."""

    def compute_episode_scores(self, interactions: dict) -> None:
        super().compute_episode_scores(interactions)
        paper = interactions.get(PAPER_KEY)
        if paper is None:
            return
        for key, name in PAPER_SCORES.items():
            self.log_episode_score(name, float(paper[key]))
            for turn in paper["turns"]:
                self.log_round_score(turn["turn"], name, int(turn[key]))
        if "es_leak_free" in paper:
            self.log_episode_score(LEAK_FREE_ES, float(paper["es_leak_free"]))

    def bench_score(self, interactions: dict, record) -> float:
        paper = interactions.get(PAPER_KEY)
        return super().bench_score(interactions, record) if paper is None else 100.0 * float(paper["es"])
