"""cobot_describe as a dialogue: clarification questions and corrections after seeing the build.

Modes (experiment field `mode`; an experiment without it is `oneshot`):
  oneshot          the describer writes, the builder codes once, the board is scored
  clarify          before code, the builder may ask up to `questions` K (default 2) questions
                   under "Question:"; the describer, who sees the target, answers under "Answer:";
                   a question past the limit counts as an answer without code
  correct          after each build the describer sees the built board (the grid form and the
                   grid explanation it saw for the target) and answers "Done" or "Correction:";
                   the builder answers with the complete corrected program, run on a fresh
                   board; at most `corrections` R (default 3) corrections
  clarify_correct  both
The builder never sees the target; the describer never sees code (only the error code when the
program stopped, and the board it left).

- settings_of(experiment) -> Settings          mode, K, R (one-line ValueError on a bad field)
- parse_builder_answer / parse_answer / parse_review   the labels of the new turns
- clarify_note / question_message / answer_message / review_message / correction_message
                                                the texts (resources/templates/dialogue/*.j2)
- turns: Dialogue / DialogueLog / State / BuilderTurn   the state machine of the turns and the record
- DialogueScorer                                 DescribeScorer + ES/F1 after the first and the
                                                last build, ES after round k, first success round,
                                                questions, corrections, describer words
"""
from __future__ import annotations

import math
import re
from dataclasses import dataclass

from clemcore.clemgame import metrics

from sartco import settings
from sartco.clem.core.building import BuildRecord
from sartco.clem.core.feedback import BOARD_FORM
from sartco.clem.core.parsing import ParseError, parse_code
from sartco.episode import (ATTEMPTS_KEY, CELL_F1_AT_1, CELL_F1_AT_N, CORRECTIONS_SENT, DESCRIBER_WORDS, DIALOGUE_KEY,
                            DIALOGUE_MODES, DIALOGUE_SCORES, ES_AT_1, ES_AT_N, FIRST_SUCCESS_ROUND, QUESTIONS_ASKED,
                            round_score)
from sartco.instances.templates import render
from sartco.world.render import grid_explanation, grid_text

from .describer import DescribeScorer, label, text_under
from .turns import BuilderTurn, DialogueLog, Said

MODES = DIALOGUE_MODES
MODE_FIELD, QUESTIONS_FIELD, CORRECTIONS_FIELD = "mode", "questions", "corrections"
DEFAULT_QUESTIONS, DEFAULT_CORRECTIONS = settings.QUESTIONS, settings.CORRECTIONS

_QUESTION = label(r"questions?")
_ANSWER = label(r"answers?")
_CORRECTION = label(r"corrections?")
_DONE = re.compile(r"^[\s*_#`>\"']*done\b", re.IGNORECASE)


@dataclass(frozen=True, slots=True)
class Settings:
    mode: str = "oneshot"
    questions: int = 0       # K: questions the builder may ask (0 unless the mode clarifies)
    corrections: int = 0     # R: corrections the describer may send (0 unless the mode corrects)


def settings_of(experiment: dict) -> Settings:
    """The dialogue settings of an experiment; ValueError (one line) on an unknown mode or a
    count that is not an integer >= 0."""
    name = experiment.get("name")
    mode = experiment.get(MODE_FIELD) or "oneshot"
    if mode not in MODES:
        raise ValueError(f"experiment {name!r}: field {MODE_FIELD!r} must be one of {', '.join(MODES)}, not {mode!r}")
    counts = {}
    for key, default, on in ((QUESTIONS_FIELD, DEFAULT_QUESTIONS, "clarify" in mode),
                             (CORRECTIONS_FIELD, DEFAULT_CORRECTIONS, "correct" in mode)):
        value = experiment.get(key, default)
        if isinstance(value, bool) or not isinstance(value, int) or value < 0:
            raise ValueError(f"experiment {name!r}: field {key!r} must be an integer >= 0, not {value!r}")
        counts[key] = value if on else 0
    return Settings(mode, counts[QUESTIONS_FIELD], counts[CORRECTIONS_FIELD])


# --- reading the new turns --------------------------------------------------------------------------
def parse_builder_answer(text: str, settings: Settings, asked: int) -> BuilderTurn:
    """A question when a clarifying builder asks (a "Question:" label), else the code. ParseError
    for a question past the limit (it counts as an answer without code), an empty question, or an
    answer without code."""
    if settings.questions:
        question = text_under(text, _QUESTION)
        if question is not None:
            if asked >= settings.questions:
                raise ParseError(f"a question past the limit of {settings.questions} (no code)", response=text)
            if not question:
                raise ParseError("the builder's 'Question:' label is followed by nothing", response=text)
            return BuilderTurn.question(question)
    return BuilderTurn.code(parse_code(text))


def parse_answer(text: str) -> str:
    """The describer's answer to a question: the text under "Answer:", or the whole answer
    when it has no label; ParseError when it is empty."""
    answer = text_under(text, _ANSWER)
    if answer is None:
        answer = str(text or "").strip()
    if not answer:
        raise ParseError("the describer gave no answer to the builder's question", response=text)
    return answer


def parse_review(text: str) -> str | None:
    """The describer's verdict on a built board: None for "Done", else the correction (the text
    under "Correction:"). ParseError when it is neither."""
    correction = text_under(text, _CORRECTION)
    if correction:
        return correction
    if correction is None and _DONE.match(str(text or "")):
        return None
    raise ParseError("the describer's review is neither 'Done' nor a 'Correction:'", response=text)


# --- what the players are told ----------------------------------------------------------------------
def clarify_note(questions: int) -> str:
    """The builder prompt's paragraph on questions (clarify modes; appended at generation)."""
    return render("dialogue/clarify.j2", questions=questions).strip()


def question_message(question: str) -> str:
    return render("dialogue/question.j2", question=question).strip()


def answer_message(answer: str, questions_left: int) -> str:
    return render("dialogue/answer.j2", answer=answer, questions_left=questions_left).strip()


def review_message(record: BuildRecord, corrections_left: int) -> str:
    """The describer's view of a build: the board as built (and the error code when the program
    stopped), never the code."""
    explanation = grid_explanation(record.cells).strip() or "(the board is empty)"
    return render("dialogue/review.j2", error=record.error, board_form=BOARD_FORM,
                  grid=grid_text(record.cells, record.rows, record.cols), explanation=explanation,
                  corrections_left=corrections_left).strip()


def correction_message(correction: str, questions_left: int) -> str:
    return render("dialogue/correction.j2", correction=correction, questions_left=questions_left).strip()


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
