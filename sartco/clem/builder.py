"""The Builder player: the role that writes code from instructions. Both games use it
(cobot_instruct: instructions from the game master; cobot_describe: from the describer).

Who answers:
- a clemcore model: the model (the game master parses its answer);
- `mock`/`programmatic`: the episode's gold code, one turn at a time, as a fenced block (or, if
  the instance carries a `script`, those raw answers verbatim: scripted episodes for tests; the
  paper protocol's episodes pass their `mock_answers`, the gold in the authors' label format);
- `rulebased` (model registry entry, see sartco.clem.rulebased): the rule-based follower
  (cobot_describe's builder, sartco.clem.dialogue.DialogueBuilder, makes `mock` the rule-based
  follower too: there is no gold answer for instructions written during the game);
- `human`: the terminal; type the code, end with a line holding only "." (or end of input).
"""
from __future__ import annotations

from typing import Callable, Sequence

from clemcore.clemgame import Player

from sartco.world import DEFAULT_COLS, DEFAULT_ROWS

RULEBASED = "rulebased"  # the model name of the rule-based follower


def fenced(code: str) -> str:
    """An answer as a careful model would give it."""
    return f"```python\n{code.strip()}\n```"


class Builder(Player):
    def __init__(self, model, *, gold_turns: Sequence[str] = (),
                 rulebased: Callable[[int, dict], str] | None = None, script: Sequence[str] | None = None,
                 name: str | None = None):
        """gold_turns: the gold code of each turn (what `mock` answers);
        rulebased: turn index, context -> code (what the `rulebased` model answers);
        script: raw answers that `mock` gives instead of the gold code (scripted episodes)."""
        super().__init__(model, name=name, game_role="Builder")
        self.gold_turns = list(gold_turns)
        self.rulebased = rulebased
        self.script = list(script) if script else None
        self.turn = 0  # answers given so far

    def _custom_response(self, context: dict) -> str:
        turn = self.turn
        self.turn += 1
        if self.model.name == RULEBASED:
            if self.rulebased is None:
                raise RuntimeError("this game has no rule-based builder")
            return fenced(self.rulebased(turn, context))
        if self.script is not None:
            return self.script[min(turn, len(self.script) - 1)]
        if not self.gold_turns:
            return "I have no code for this."
        return fenced(self.gold_turns[min(turn, len(self.gold_turns) - 1)])

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


def rulebased_code(instructions, task: str, given_code: str = "", rows: int = DEFAULT_ROWS,
                   cols: int = DEFAULT_COLS) -> str:
    """What the rule-based follower writes for instructions (a text or a list of texts); a
    Python comment saying why when it cannot read them (it then builds nothing), never an error."""
    from sartco.follower import FollowError, follow
    try:
        return follow(instructions, task, given_code, rows, cols)
    except FollowError as error:
        return f"# I cannot follow these instructions: {error}"
