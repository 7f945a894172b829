"""cobot_describe's scorer: what `clem score` (and the transcript's score card) computes from an
episode's interactions.json.

- DescribeScorer   BuildScorer's scores of the rebuilt board (Main Score = 100 x ES, cell F1,
                   category, ...) plus Describer Answered, Instruction Words, Instruction
                   Characters, Object Named (instruction_facts)
- DialogueScorer   the game's scorer (every episode, every mode): DescribeScorer + ES/F1 after the
                   first and the last build, ES after round k, first success round, questions,
                   corrections, describer words
"""
from __future__ import annotations

import math
import re

from clemcore.clemgame import metrics

from sartco.clem.core.building import BuildRecord
from sartco.clem.core.scoring import NAN, BuildScorer
from sartco.episode import (ATTEMPTS_KEY, CELL_F1_AT_1, CELL_F1_AT_N, CORRECTIONS_SENT, DESCRIBER_ANSWERED,
                            DESCRIBER_WORDS, DIALOGUE_KEY, DIALOGUE_SCORES, ES_AT_1, ES_AT_N, FIRST_SUCCESS_ROUND,
                            INSTRUCTION_CHARACTERS, INSTRUCTION_KEY, INSTRUCTION_WORDS, OBJECT_NAMED, QUESTIONS_ASKED,
                            round_score)

from .dialogue import settings_of
from .turns import DialogueLog, Said


def instruction_facts(text: str | None, combo_name: str) -> dict:
    """Instruction Words, Instruction Characters, Object Named (the combination's name, e.g. 'wn',
    as a word of its own, any case); NaN for all when there is no instruction."""
    if text is None:
        return {INSTRUCTION_WORDS: NAN, INSTRUCTION_CHARACTERS: NAN, OBJECT_NAMED: NAN}
    named = re.search(rf"(?<![A-Za-z0-9]){re.escape(combo_name)}(?![A-Za-z0-9])", text, re.IGNORECASE)
    return {INSTRUCTION_WORDS: len(text.split()), INSTRUCTION_CHARACTERS: len(text), OBJECT_NAMED: int(bool(named))}


class DescribeScorer(BuildScorer):
    """The rebuilt board's scores (BuildScorer: Main Score = 100 x ES, cell F1, category, ...)
    plus Describer Answered (0/1: an instruction was found), Instruction Words, Instruction
    Characters and Object Named."""

    def compute_episode_scores(self, interactions: dict) -> None:
        super().compute_episode_scores(interactions)
        record = interactions.get(INSTRUCTION_KEY) or {}
        text = record.get("text")
        self.log_episode_score(DESCRIBER_ANSWERED, int(text is not None))
        for name, value in instruction_facts(text, record.get("combo_name", "")).items():
            self.log_episode_score(name, value)


class DialogueScorer(DescribeScorer):
    """DescribeScorer (Main Score = 100 x final ES, ...) plus, from every build (ATTEMPTS_KEY)
    and the dialogue log (DIALOGUE_KEY): ES@1 and Cell F1@1 (the first build), ES@N and Cell
    F1@N (the last), "ES Round k" for k = 0..R (the board standing after k corrections; the
    last board carries on once the episode ended), First Success Round (NaN: never), Questions
    Asked, Corrections Sent, Describer Words (instruction, answers and corrections). NaN for
    the build scores when the episode was aborted."""

    def compute_episode_scores(self, interactions: dict) -> None:
        super().compute_episode_scores(interactions)
        settings = settings_of(self.experiment)
        log = DialogueLog(**interactions[DIALOGUE_KEY]) if interactions.get(DIALOGUE_KEY) else \
            DialogueLog(settings.mode, settings.questions, settings.corrections)
        builds = [BuildRecord.from_json(b) for b in interactions.get(ATTEMPTS_KEY) or []]
        played = bool(builds) and not interactions.get(metrics.METRIC_ABORTED, 0)
        nan = math.nan
        es = [b.es for b in builds]
        values = {
            ES_AT_1: es[0] if played else nan, ES_AT_N: es[-1] if played else nan,
            CELL_F1_AT_1: builds[0].f1 if played else nan, CELL_F1_AT_N: builds[-1].f1 if played else nan,
            FIRST_SUCCESS_ROUND: es.index(1) if 1 in es else nan,
            QUESTIONS_ASKED: log.count(Said.QUESTION), CORRECTIONS_SENT: log.count(Said.CORRECTION),
            DESCRIBER_WORDS: log.describer_words,
        }
        for name in DIALOGUE_SCORES:
            self.log_episode_score(name, values[name])
        for k in range(settings.corrections + 1):
            self.log_episode_score(round_score(k), es[min(k, len(es) - 1)] if played else nan)
