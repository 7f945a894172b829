"""The Describer side of cobot_describe: the player who looks at the target board and writes the
instructions a builder then follows (the paper's model-written instructions).

- Describer                      the player: a clemcore model; `mock` / `rulebased` answer from
                                 sartco.games.describe.players; `human` types in the terminal
- parse_instruction / ParseError the text under the "Instruction:" label (none -> aborted)
- INSTRUCTION_SLOT / fill_builder_prompt   the builder prompt's place for the instruction
- log_instruction / INSTRUCTION_KEY   the instruction as the game master passed it on, recorded
                                 in interactions.json for the scorer and for
                                 `sartco import-instructions`
- instruction_facts              length in words and characters, whether the object is named
- DescribeScorer                 BuildScorer's scores of the rebuilt board + the facts above
"""
from __future__ import annotations

import re

from sartco.clem.core.answer_lines import in_fence
from sartco.clem.core.parsing import ParseError
from sartco.clem.core.scoring import NAN, BuildScorer
from sartco.clem.players.sourced import AnswerSource, SourcedPlayer, terminal_answer
from sartco.episode import (DESCRIBER_ANSWERED, INSTRUCTION_CHARACTERS, INSTRUCTION_KEY, INSTRUCTION_WORDS,
                            OBJECT_NAMED)

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


_LABEL = label(r"instructions?")
# what ends a labelled text: another answer label or a code fence (a model going on with a program)
_END = re.compile(r"^\s*(?:#+\s*)?(?:\*\*|__)?\s*(?:output|function|usage|code|answer|question|correction)\s*(?:\*\*|__)?\s*:"
                  r"|^\s*(?:`{3,}|~{3,})", re.IGNORECASE)


def text_under(text: str | None, pattern: re.Pattern) -> str | None:
    """The text after the first line outside code fences that matches `pattern` (a `label`), up to another answer
    label or a code fence, blank lines squeezed; None when no line matches; "" when nothing follows."""
    lines = str(text or "").replace("\r\n", "\n").replace("\r", "\n").split("\n")
    fenced = in_fence(lines)  # a label inside a fence is part of the code there ("# Question: ..." a comment)
    start = next((i for i, line in enumerate(lines) if not fenced[i] and pattern.match(line)), None)
    if start is None:
        return None
    body = [pattern.match(lines[start]).group("rest")]
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
    instruction = text_under(text, _LABEL)
    if instruction is None:
        raise ParseError("no instruction found: the describer's answer has no 'Instruction:' label", response=text)
    if not instruction:
        raise ParseError("no instruction found: the describer's 'Instruction:' label is followed by nothing",
                         response=text)
    return instruction


def instruction_facts(text: str | None, combo_name: str) -> dict:
    """Instruction Words, Instruction Characters, Object Named (the combination's name, e.g. 'wn',
    as a word of its own, any case); NaN for all when there is no instruction."""
    if text is None:
        return {INSTRUCTION_WORDS: NAN, INSTRUCTION_CHARACTERS: NAN, OBJECT_NAMED: NAN}
    named = re.search(rf"(?<![A-Za-z0-9]){re.escape(combo_name)}(?![A-Za-z0-9])", text, re.IGNORECASE)
    return {INSTRUCTION_WORDS: len(text.split()), INSTRUCTION_CHARACTERS: len(text), OBJECT_NAMED: int(bool(named))}


def log_instruction(game_master, text: str | None, combo_name: str, error: str | None = None) -> None:
    game_master.log_key(INSTRUCTION_KEY, {"text": text, "error": error, "combo_name": combo_name})


class Describer(SourcedPlayer):
    """The role that looks at the target and writes instructions (answers: what `mock` and
    `rulebased` say, sartco.games.describe.players.describer_answers)."""

    def __init__(self, model, answers: AnswerSource, *, name: str | None = None):
        super().__init__(model, answers, game_role="Describer", name=name)

    def _terminal_response(self, context: dict) -> str:
        first = self.turn == 0
        self.turn += 1
        text = terminal_answer(context, "your instructions as Describer" if first else "your answer as Describer")
        return text if not first or _LABEL.match(text.split("\n", 1)[0]) else f"Instruction: {text}"


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
