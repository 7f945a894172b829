"""cobot_describe's dialogue as a state machine: whose turn it is (State), what was said so far
(DialogueLog, logged under DIALOGUE_KEY for the scorer) and the transitions the game master
makes as the dialogue goes on (Dialogue's methods: instruct, ask, answer, build, done, correct,
fail); a builder's answer as read (BuilderTurn: a question or code); the kinds of what was said
(Said: the log's `kind` values). The built-in players read what they heard from the Dialogue
(sartco.games.describe.players).

    INSTRUCTION --instruct--> BUILD --ask--> ANSWER --answer--> BUILD
    BUILD --build--> REVIEW (corrections left, the answer held code) | OVER
    REVIEW --done--> OVER          REVIEW --correct--> BUILD
    INSTRUCTION | ANSWER | REVIEW --fail--> OVER (a board stands) | BUILD (a build without code follows)
"""
from __future__ import annotations

from dataclasses import asdict, dataclass, field
from enum import StrEnum
from typing import NamedTuple

from sartco.clem.core.building import BuildRecord
from sartco.clem.players.sourced import fenced
from sartco.world import ErrorCode

DONE = "Done"


class Move(StrEnum):
    QUESTION = "question"
    CODE = "code"


class BuilderTurn(NamedTuple):
    """A builder's answer as read: a question (clarify modes) or the code of a build."""
    move: Move
    text: str

    @classmethod
    def question(cls, text: str) -> BuilderTurn:
        return cls(Move.QUESTION, text)

    @classmethod
    def code(cls, text: str) -> BuilderTurn:
        return cls(Move.CODE, text)

    def written(self) -> str:
        """The answer as a built-in builder writes it (a question as it is, code fenced)."""
        return self.text if self.move is Move.QUESTION else fenced(self.text)


class Said(StrEnum):
    """The kind of a logged turn (DialogueLog's events' `kind`, as written to interactions.json)."""
    INSTRUCTION = "instruction"
    QUESTION = "question"
    ANSWER = "answer"
    CORRECTION = "correction"
    DONE = "done"
    # a describer's answer that could not be read, by the state it was given in (Dialogue.fail)
    NO_INSTRUCTION = "no_instruction"
    NO_ANSWER = "no_answer"
    NO_REVIEW = "no_review"


@dataclass
class DialogueLog:
    """What was said, in order: {"kind": a Said value, "text", "build": builds so far}."""
    mode: str
    questions: int
    corrections: int
    events: list[dict] = field(default_factory=list)
    describer_words: int = 0

    def add(self, kind: Said, text: str | None, builds: int, *, describer: bool = False) -> None:
        self.events.append({"kind": kind, "text": text, "build": builds})
        if describer and text:
            self.describer_words += len(text.split())

    def count(self, kind: Said) -> int:
        return sum(1 for event in self.events if event["kind"] == kind)

    def to_json(self) -> dict:
        return asdict(self)


class State(StrEnum):
    """Whose turn it is, and for the describer what its answer is (the parser the master uses)."""
    INSTRUCTION = "instruction"   # the describer writes the instruction (the first turn)
    BUILD = "build"               # the builder answers: code, or a question (clarify modes)
    ANSWER = "answer"             # the describer answers the builder's question
    REVIEW = "review"             # the describer reviews the built board: Done or a correction
    OVER = "over"                 # the last build is the episode's result


# the states whose describer answer may be unreadable, and what the log then says (Dialogue.fail)
UNREAD = {State.INSTRUCTION: Said.NO_INSTRUCTION, State.ANSWER: Said.NO_ANSWER, State.REVIEW: Said.NO_REVIEW}


@dataclass
class Dialogue:
    """What has been said in an episode so far and whose turn it is: the game master moves it
    with the transitions below as the dialogue goes on; the built-in players read what they
    heard from it (sartco.games.describe.players)."""
    log: DialogueLog
    state: State = State.INSTRUCTION
    instruction: str | None = None
    answers: list[str] = field(default_factory=list)   # the describer's answers since the last build
    correction: str | None = None      # the correction the builder has not answered yet
    builds: list[BuildRecord] = field(default_factory=list)

    def left(self, kind: Said) -> int:
        """Questions (Said.QUESTION) or corrections (Said.CORRECTION) left."""
        limits = {Said.QUESTION: self.log.questions, Said.CORRECTION: self.log.corrections}
        if kind not in limits:
            raise ValueError(f"dialogue: only questions and corrections are limited, not {kind!r}")
        return limits[kind] - self.log.count(kind)

    def _move(self, allowed: tuple[State, ...], to: State) -> None:
        if self.state not in allowed:
            raise RuntimeError(f"dialogue: no move from {self.state.value} to {to.value}")
        self.state = to

    def instruct(self, text: str) -> None:
        """INSTRUCTION -> BUILD: the describer's instruction."""
        self._move((State.INSTRUCTION,), State.BUILD)
        self.instruction = text
        self.log.add(Said.INSTRUCTION, text, 0, describer=True)

    def ask(self, question: str) -> None:
        """BUILD -> ANSWER: the builder asks."""
        self._move((State.BUILD,), State.ANSWER)
        self.log.add(Said.QUESTION, question, len(self.builds))

    def answer(self, text: str) -> None:
        """ANSWER -> BUILD: the describer answers the question."""
        self._move((State.ANSWER,), State.BUILD)
        self.answers.append(text)
        self.log.add(Said.ANSWER, text, len(self.builds), describer=True)

    def build(self, record: BuildRecord) -> None:
        """BUILD -> REVIEW while corrections are left and the answer held code, else OVER."""
        reviewed = record.error != ErrorCode.PARSE_ERROR and self.left(Said.CORRECTION) > 0
        self._move((State.BUILD,), State.REVIEW if reviewed else State.OVER)
        self.builds.append(record)
        self.answers, self.correction = [], None

    def done(self) -> None:
        """REVIEW -> OVER: the review says Done; the board stands."""
        self._move((State.REVIEW,), State.OVER)
        self.log.add(Said.DONE, DONE, len(self.builds))

    def correct(self, correction: str) -> None:
        """REVIEW -> BUILD: the describer's correction."""
        self._move((State.REVIEW,), State.BUILD)
        self.correction = correction
        self.log.add(Said.CORRECTION, correction, len(self.builds), describer=True)

    def fail(self, reason: str) -> None:
        """The describer's answer could not be read: OVER when a board stands, else BUILD (the
        master records a build without code for the builder)."""
        unread = self.state
        self._move(tuple(UNREAD), State.OVER if self.builds else State.BUILD)
        self.log.add(UNREAD[unread], reason, len(self.builds))
