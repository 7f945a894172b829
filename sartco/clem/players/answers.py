"""What the built-in players answer: small answer sources (sartco.clem.players.sourced.AnswerSource),
one chosen for a player when it is made, and cobot_instruct's choice (`instruct_answers`).

- Scripted    raw answers verbatim, one per turn (scripted episodes of the tests, the paper
              protocol's `mock_answers`); after the last one another source, or the last again
- GoldCode    the episode's gold code of each turn, fenced (`mock`: the harness's ceiling)
- InstructFollower   the rule-based follower (`rulebased`) on cobot_instruct's instructions:
              one turn's puts per multi-turn instruction, then (a repair after feedback) the
              whole program
- ErringFollower     the same with seeded slips and repairs (`erring`, sartco.clem.players.erring)
"""
from __future__ import annotations

from typing import Sequence

from sartco.world import DEFAULT_COLS, DEFAULT_ROWS

from .erring import ErringFollower
from .sourced import ERRING, RULEBASED, AnswerSource, cannot_follow, fenced

NO_CODE = "I have no code for this."  # what `mock` says to an episode without gold code


class Scripted:
    def __init__(self, answers: Sequence[str], then: AnswerSource | None = None):
        self.answers = list(answers)
        self.then = then

    def answer(self, turn: int) -> str:
        if turn < len(self.answers):
            return self.answers[turn]
        return self.answers[-1] if self.then is None else self.then.answer(turn)


class GoldCode:
    def __init__(self, gold_turns: Sequence[str]):
        self.gold_turns = list(gold_turns)

    def answer(self, turn: int) -> str:
        if not self.gold_turns:
            return NO_CODE
        return fenced(self.gold_turns[min(turn, len(self.gold_turns) - 1)])


class InstructFollower:
    """A multi-turn first_order episode sends one instruction per turn: the k-th answer is the
    puts of the k-th instruction; every answer after the last instruction (a repair, after
    feedback) and every single-turn answer is the program for all instructions."""

    def __init__(self, episode: dict):
        self.episode = episode

    def answer(self, turn: int) -> str:
        from sartco.follower import FollowError, follow_turn

        e = self.episode
        texts = e["instructions"]
        if e["task"] == "first_order" and len(texts) > 1 and turn < len(texts):
            try:
                return fenced(follow_turn(texts[turn], texts[:turn], e["rows"], e["cols"]))
            except FollowError as error:
                return fenced(f"# I cannot follow this instruction: {error}")
        return fenced(rulebased_code(texts, e["task"], e.get("given_code", ""), e["rows"], e["cols"]))


def rulebased_code(instructions, task: str, given_code: str = "", rows: int = DEFAULT_ROWS,
                   cols: int = DEFAULT_COLS) -> str:
    """What the rule-based follower writes for instructions (a text or a list of texts); a
    Python comment saying why when it cannot read them (it then builds nothing), never an error."""
    from sartco.follower import FollowError, follow
    try:
        return follow(instructions, task, given_code, rows, cols)
    except FollowError as error:
        return cannot_follow(error)


def instruct_answers(model_name: str, episode: dict, *, paper: bool = False) -> AnswerSource:
    """cobot_instruct's builder: `rulebased` follows the instructions, `erring` with slips
    (sartco.clem.players.erring); `mock` answers an episode's
    `script` (scripted tests), the paper protocol's `mock_answers` (the authors' gold in their
    label format), else the gold code. ValueError: the paper protocol has no rule-based builder
    (the follower does not write the authors' answer format), nor an erring one."""
    if model_name in (RULEBASED, ERRING):
        if paper:
            raise ValueError(f"the paper protocol has no rule-based builder ({model_name})")
        if model_name == ERRING:
            return ErringFollower(episode)
        return InstructFollower(episode)
    script = episode.get("script") or (episode["mock_answers"] if paper else None)
    return Scripted(script) if script else GoldCode(episode.get("gold_turns", ()))
