"""The players of the games that end in a build, each with its built-in answers chosen once.

A player answers in one of three ways (clemcore's Player):
- a clemcore model: the model (the game master parses its answer);
- `mock`, `programmatic`, `rulebased`, `erring` (CustomResponseModel): the player's answer source, an object
  chosen once when the player is made (sartco.clem.players.answers for cobot_instruct's builder,
  sartco.games.describe.players for cobot_describe's players): `answers.answer(turn)`;
- `human`: the terminal; type the answer, end with a line holding only "." (or end of input).
The game master never answers for a player: it sends messages and reads answers.
"""
from __future__ import annotations

from collections.abc import Callable
from typing import Protocol

from clemcore.clemgame import Player

from sartco.text import escape, escape_all

RULEBASED = "rulebased"  # the model name of the rule-based follower (sartco.clem.tooling.rulebased)
ERRING = "erring"        # the model name of the rule-based players that make mistakes (sartco.clem.players.erring)


class AnswerSource(Protocol):
    def answer(self, turn: int) -> str:
        """The built-in player's raw answer to its turn-th message (0 = the first)."""


def fenced(code: str) -> str:
    """An answer as a careful model would give it."""
    return f"```python\n{code.strip()}\n```"


def cannot_follow(error) -> str:
    """The rule-based follower's answer to instructions it cannot read (a comment: it builds nothing)."""
    return f"# I cannot follow these instructions: {error}"


class SourcedPlayer(Player):
    """A player whose built-in answers come from one answer source."""

    def __init__(self, model, answers: AnswerSource, *, game_role: str, name: str | None = None):
        super().__init__(model, name=name, game_role=game_role)
        self.answers = answers
        self.turn = 0  # answers given so far
        # the game master's hook for an answer that came in, before clemcore steps the episode with it
        # (sartco.clem.core.answer_builds.start_build); what it raises is left to the step
        self.on_answer: Callable[[str], None] | None = None

    def _custom_response(self, context: dict) -> str:
        self.turn += 1
        return self.answers.answer(self.turn - 1)

    def perceive_response(self, response: str, *, log_event=True, memorize=True, metadata=None):
        """clemcore's, with the answer and its call record escaped (sartco.text) before the
        player logs or memorizes them: player_N.requests.json stays strict UTF-8. The game
        master escapes the answer it reads the same way (sartco.clem.core.transcript)."""
        answer = escape(response) if isinstance(response, str) else response
        perceived = super().perceive_response(answer, log_event=log_event, memorize=memorize,
                                              metadata=escape_all(metadata))
        if self.on_answer is not None and isinstance(answer, str):
            try:
                self.on_answer(answer)
            except Exception:  # work ahead only: the step meets the same answer and says what is wrong
                pass
        return perceived


class Builder(SourcedPlayer):
    """The role that writes code from instructions (cobot_instruct: the game master's; cobot_describe:
    the describer's)."""

    def __init__(self, model, answers: AnswerSource, *, name: str | None = None):
        super().__init__(model, answers, game_role="Builder", name=name)

    def _terminal_response(self, context: dict) -> str:
        self.turn += 1
        return terminal_answer(context, "your code as Builder")


def terminal_answer(context: dict | None, what: str) -> str:
    """Show the context on the terminal and read an answer: lines up to one holding only "."
    (or the end of input)."""
    print(f"\n{context['content'] if context else 'Nothing has been said yet.'}")
    print(f'\n{what[:1].upper()}{what[1:]} (end with a line holding only "."):')
    lines = []
    while True:
        try:
            line = input()
        except EOFError:
            break
        if line.strip() == ".":
            break
        lines.append(line)
    return "\n".join(lines)
