"""cobot_describe's players: the Describer (the player who looks at the target board and writes the
instructions a builder then follows; a clemcore model, `human` types in the terminal; the Builder
is sartco.clem.players.sourced's), and what the built-in players answer in the dialogue (answer
sources, sartco.clem.players.sourced.AnswerSource), chosen once when the players are made:

- DescriberMock     `mock` / `rulebased` describer: the episode's template instruction, then the
                    same text as the answer to a question, and a review of each build: "Done" or
                    the pieces to remove and to add (programmatic_review, sartco.follower.correct)
- DialogueFollower  `mock` / `rulebased` builder: the rule-based follower reading what the
                    describer said (rulebased_turn on a BuilderView): code, or a question when it
                    cannot read the instruction (there is no gold answer for instructions written
                    during the game)
- ErringDescriber / ErringBuilder   `erring`: the same with seeded omissions, garbles and slips
                    (sartco.games.describe.erring_dialogue)
- describer_answers / builder_answers   the choice, with the episode's `describer_script` /
  `builder_script` answered first (scripted tests; `rulebased` as builder ignores the script)
Both read what they heard from the episode's Dialogue record (sartco.games.describe.dialogue), which the game
master writes; neither asks the game master for an answer.
"""
from __future__ import annotations

from dataclasses import dataclass, field

from sartco.clem.players.answers import Scripted, cannot_follow
from sartco.clem.players.sourced import ERRING, RULEBASED, AnswerSource, SourcedPlayer, terminal_answer
from sartco.follower import FollowError, emit, follow
from sartco.follower.correct import apply_correction, correction_steps, pieces
from sartco.instances.templates import render

from .dialogue import INSTRUCTION_LABEL
from .erring_dialogue import ErringBuilder, ErringDescriber
from .turns import DONE, BuilderTurn, Dialogue, Said, State


# --- the Describer ----------------------------------------------------------------------------------
class Describer(SourcedPlayer):
    """The role that looks at the target and writes instructions (answers: what `mock` and
    `rulebased` say, describer_answers below)."""

    def __init__(self, model, answers: AnswerSource, *, name: str | None = None):
        super().__init__(model, answers, game_role="Describer", name=name)

    def _terminal_response(self, context: dict) -> str:
        first = self.turn == 0
        self.turn += 1
        text = terminal_answer(context, "your instructions as Describer" if first else "your answer as Describer")
        return text if not first or INSTRUCTION_LABEL.match(text.split("\n", 1)[0]) else f"Instruction: {text}"



# --- the mock describer -----------------------------------------------------------------------------
def correction_text(built: dict, target: dict) -> str:
    """The pieces to remove and to add, in the template wording; "" when the boards are equal."""
    removals, additions = correction_steps(built, target)
    return render("instructions/simple/correction.j2", removals=removals, additions=additions).strip()


def programmatic_review(built: dict, target: dict) -> str:
    text = correction_text(built, target)
    return f"Correction: {text}" if text else DONE


class DescriberMock:
    def __init__(self, episode: dict, dialogue: Dialogue):
        self.episode, self.dialogue = episode, dialogue

    def answer(self, turn: int) -> str:
        template = self.episode["template_instruction"]
        if turn == 0:
            return f"Instruction: {template}"
        if self.dialogue.state is State.ANSWER:
            return f"Answer: {template}"
        return programmatic_review(self.dialogue.builds[-1].cells, self.episode["target"])


# --- the rule-based builder -------------------------------------------------------------------------
@dataclass
class BuilderView:
    """What the builder knows: the describer's words and what its own last program built (it
    knows its code); never the target."""
    task: str
    given_code: str
    rows: int
    cols: int
    instruction: str = ""
    answers: list[str] = field(default_factory=list)   # answers to its questions since its last build
    correction: str | None = None      # the correction of its last build, when one came
    built: dict | None = None          # the cells its last program built
    questions_left: int = 0


def builder_view(episode: dict, dialogue: Dialogue) -> BuilderView:
    d = dialogue
    return BuilderView(episode["task"], episode["given_code"], episode["rows"], episode["cols"], d.instruction or "",
                       list(d.answers), d.correction, d.builds[-1].cells if d.builds else None, d.left(Said.QUESTION))


def _question(problem: str) -> str:
    return (f"Question: I cannot read this: {problem}. Which component of which color goes where "
            f"(row and column of each)?")


def rulebased_turn(view: BuilderView) -> BuilderTurn:
    """Code, or a question. It follows the newest answer it can read; else,
    after a correction, the puts of its last board with the correction applied; else the
    instruction. When it can read none of them and may still ask, it asks."""
    problem = None
    for text in reversed(view.answers):
        try:
            return BuilderTurn.code(_follow(text, view))
        except FollowError as error:
            problem = problem or str(error)
    if view.correction is not None and view.built is not None:
        standing = [p for _, p in pieces(view.built)]
        try:
            steps = apply_correction(standing, view.correction, view.rows, view.cols)
        except FollowError as error:
            if view.questions_left:
                return BuilderTurn.question(_question(str(error)))
            steps = standing  # it cannot read the correction: the same board again
        if not steps:
            return BuilderTurn.code("# the correction leaves nothing to build")
        return BuilderTurn.code(emit.optimal_function(steps, None) if view.task == "optimal_function"
                                else emit.first_order(steps))
    try:
        return BuilderTurn.code(_follow(view.instruction, view))
    except FollowError as error:
        if view.questions_left:
            return BuilderTurn.question(_question(problem or str(error)))
        return BuilderTurn.code(cannot_follow(error))


def _follow(text: str, view: BuilderView) -> str:
    return follow(text, view.task, view.given_code, view.rows, view.cols)


class DialogueFollower:
    def __init__(self, episode: dict, dialogue: Dialogue):
        self.episode, self.dialogue = episode, dialogue

    def answer(self, turn: int) -> str:
        return rulebased_turn(builder_view(self.episode, self.dialogue)).written()


# --- the choice -------------------------------------------------------------------------------------
def describer_answers(model_name: str, episode: dict, dialogue: Dialogue) -> AnswerSource:
    if model_name == ERRING:
        return ErringDescriber(episode, dialogue)
    mock = DescriberMock(episode, dialogue)
    script = episode.get("describer_script")
    return Scripted(script, then=mock) if script else mock


def builder_answers(model_name: str, episode: dict, dialogue: Dialogue) -> AnswerSource:
    if model_name == ERRING:
        return ErringBuilder(episode, dialogue)
    follower = DialogueFollower(episode, dialogue)
    script = episode.get("builder_script")
    return Scripted(script, then=follower) if script and model_name != RULEBASED else follower
