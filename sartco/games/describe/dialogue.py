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
- parse_instruction                              the describer's first answer: the text under the
                                                "Instruction:" label (none: ParseError, aborted)
- parse_builder_answer / parse_answer / parse_review   the labels of the later turns
- INSTRUCTION_SLOT / fill_builder_prompt         the builder prompt's place for the instruction
- log_instruction (INSTRUCTION_KEY)              the instruction as passed on, for the scorer and
                                                `sartco import-instructions`
- clarify_note / question_message / answer_message / review_message / correction_message
                                                the texts (resources/templates/dialogue/*.j2)
- turns: Dialogue / DialogueLog / State / BuilderTurn   the state machine of the turns and the record
The players are players.py's, the scores scorer.py's (DialogueScorer).
"""
from __future__ import annotations

import re
from dataclasses import dataclass

from sartco import settings
from sartco.clem.core.answer_lines import in_fence
from sartco.clem.core.building import BuildRecord
from sartco.clem.core.feedback import BOARD_FORM
from sartco.clem.core.errors import ParseError
from sartco.clem.core.parsing import parse_code
from sartco.episode import DIALOGUE_MODES, INSTRUCTION_KEY
from sartco.instances.templates import render
from sartco.world.render import grid_explanation, grid_text

from .turns import BuilderTurn

INSTRUCTION_SLOT = "<<DESCRIBER_INSTRUCTION>>"  # where a stored builder prompt takes the instruction


def fill_builder_prompt(prompt: str, instruction: str) -> str:
    """The builder's prompt (rendered with builder_prompt(..., instruction=INSTRUCTION_SLOT) at
    instance generation) with the describer's instruction in its slot."""
    if INSTRUCTION_SLOT not in prompt:
        raise ValueError("the builder prompt has no slot for the describer's instruction")
    head, _, tail = prompt.rpartition(INSTRUCTION_SLOT)
    return f"{head}{instruction}{tail}"

def label(words: str) -> re.Pattern:
    """A line that opens with one of these labels: "Instruction:", "**Instructions:**",
    "### Question:" (words: a regex alternative, e.g. r"instructions?"); group `rest` holds the
    rest of the line."""
    return re.compile(rf"^\s*(?:#+\s*)?(?:\*\*|__)?\s*(?:{words})\s*(?:\*\*|__)?\s*:\s*(?:\*\*|__)?\s*(?P<rest>.*)$",
                      re.IGNORECASE)


INSTRUCTION_LABEL = label(r"instructions?")
# what ends a labelled text: another answer label or a code fence (a model going on with a program)
_END = re.compile(r"^\s*(?:#+\s*)?(?:\*\*|__)?\s*(?:output|function|usage|code|answer|question|correction)\s*(?:\*\*|__)?\s*:"
                  r"|^\s*(?:`{3,}|~{3,})", re.IGNORECASE)


def text_under(text: str | None, pattern: re.Pattern) -> str | None:
    """The text after the first line outside code fences that matches `pattern` (a `label`), up to another answer
    label or a code fence, blank lines squeezed; None when no line matches; "" when nothing follows."""
    lines = str(text or "").replace("\r\n", "\n").replace("\r", "\n").split("\n")
    fenced = in_fence(lines)  # a label inside a fence is part of the code there ("# Question: ..." a comment)
    found = next(((i, m) for i, line in enumerate(lines) if not fenced[i] and (m := pattern.match(line))), None)
    if found is None:
        return None
    start, match = found
    body = [match.group("rest")]
    for line in lines[start + 1:]:
        if _END.match(line):
            break
        body.append(line)
    kept = [line.rstrip() for line in body]
    return re.sub(r"\n{3,}", "\n\n", "\n".join(kept)).strip().strip("*_").strip()


def parse_instruction(text: str) -> str:
    """The instruction in a describer's answer: the text after the first "Instruction:" label, up
    to an Output/Function/Usage/Code label or a code fence; blank lines squeezed. Raises
    ParseError when there is no label or nothing after it. Junk after the label is passed on:
    the builder has to cope with it, as with any bad instruction."""
    if text is None or not str(text).strip():
        raise ParseError("no instruction found: the describer gave an empty answer", response=text)
    instruction = text_under(text, INSTRUCTION_LABEL)
    if instruction is None:
        raise ParseError("no instruction found: the describer's answer has no 'Instruction:' label", response=text)
    if not instruction:
        raise ParseError("no instruction found: the describer's 'Instruction:' label is followed by nothing",
                         response=text)
    return instruction


def log_instruction(game_master, text: str | None, combo_name: str, error: str | None = None) -> None:
    game_master.log_key(INSTRUCTION_KEY, {"text": text, "error": error, "combo_name": combo_name})


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


# --- reading the later turns -------------------------------------------------------------------------
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
