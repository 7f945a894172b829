"""The erring players of cobot_describe (`-m erring`; sartco.clem.players.erring has the rate, the seed
and the slips):

- ErringDescriber  writes the template instruction, but on a simple board each piece's sentence
                   is, with probability p, left out ("omitted") or written without its colour
                   ("garbled": "Place a nut in the 5th row, 4th column."); a regular board's
                   instruction loses its colour list with probability p ("garbled": "Use only
                   these colors for the 'bn' object."). Answers a question with the next missing fact: the full sentence
                   of the next garbled piece, else those of all omitted pieces, else the whole
                   template instruction. Reviews a build like the mock describer, but names each
                   removal and addition with probability 1 - p only (the first one always).
- ErringBuilder    the rule-based follower with slips: reads the instruction sentence by sentence,
                   putting the describer's answers in the place of the sentences it cannot read
                   (in order; more answers are added at the end); asks a question (clarify modes,
                   while questions are left) about the first sentence it still cannot read, or
                   when it found no piece at all; builds what it read, each piece slipping with
                   probability p. A correction it can read is carried out on its last board, the
                   added pieces slipping again with probability p (the repair: no gold, no target).
"""
from __future__ import annotations

import re

from sartco.clem.players.erring import RATE, draw_slips, emit_steps, rng_for, slip_arrangement, slip_steps
from sartco.clem.players.sourced import cannot_follow
from sartco.follower import FollowError, emit
from sartco.follower.correct import correction_steps, pieces, read_correction
from sartco.follower.parse import object_name, placements
from sartco.follower.regular import arrange
from sartco.instances.templates import render
from sartco.world import COLORS

from .turns import DONE, BuilderTurn, Dialogue, Said, State

_SENTENCE = re.compile(r"(?<=[.!?])\s+")
_COLOUR_LIST = re.compile(r"colors:\s*\[[^\]]*\]")
_COLOUR = re.compile(rf"\b(?:{'|'.join(COLORS)})\s+")


def sentences(text: str) -> list[str]:
    return [s for s in _SENTENCE.split(text.strip()) if s]


class ErringDescriber:
    def __init__(self, episode: dict, dialogue: Dialogue):
        self.episode, self.dialogue = episode, dialogue
        template = episode["template_instruction"]
        self.garbled: list[str] = []   # full sentences of the garbled pieces, not yet answered
        self.omitted: list[str] = []
        rng = rng_for(episode, "describe")
        if episode["task"] == "repetition":
            self.instruction = template
            colours = _COLOUR_LIST.search(template)
            if colours and rng.random() < RATE:
                self.garbled.append(next(s for s in sentences(template) if colours.group(0) in s))
                self.instruction = template.replace(colours.group(0), "colors", 1)
            return
        head, *rest = sentences(template)
        kept = [head]
        for sentence in rest:
            if rng.random() >= RATE:
                kept.append(sentence)
            elif rng.random() < 0.5:
                self.omitted.append(sentence)
            else:
                self.garbled.append(sentence)
                kept.append(_COLOUR.sub("", sentence, count=1))
        self.instruction = " ".join(kept)

    def answer(self, turn: int) -> str:
        d = self.dialogue
        if turn == 0:
            return f"Instruction: {self.instruction}"
        if d.state is State.ANSWER:
            if self.garbled:
                return f"Answer: {self.garbled.pop(0)}"
            if self.omitted:
                facts, self.omitted = self.omitted, []
                return f"Answer: I left out: {' '.join(facts)}"
            return f"Answer: {self.episode['template_instruction']}"
        return self.review(d.builds[-1].cells, len(d.builds))

    def review(self, built: dict, round_: int) -> str:
        removals, additions = correction_steps(built, self.episode["target"])
        if not removals and not additions:
            return DONE
        rng = rng_for(self.episode, "review", round_)
        named = [(i == 0) or rng.random() >= RATE for i in range(len(removals) + len(additions))]
        removals, additions = ([p for p, keep in zip(removals, named) if keep],
                               [p for p, keep in zip(additions, named[len(removals):]) if keep])
        text = render("instructions/simple/correction.j2", removals=removals, additions=additions).strip()
        return f"Correction: {text}"


def _question(what: str) -> str:
    return f"Question: {what} Which component of which color goes there (row and column)?"


class ErringBuilder:
    def __init__(self, episode: dict, dialogue: Dialogue):
        self.episode, self.dialogue = episode, dialogue

    def answer(self, turn: int) -> str:
        return self.turn().written()

    def turn(self) -> BuilderTurn:
        e, view = self.episode, self.dialogue  # what it heard; the cells its own last program built
        rows, cols, builds = e["rows"], e["cols"], len(view.builds)
        questions_left = view.left(Said.QUESTION)
        if view.correction is not None and view.builds:
            try:
                removals, additions = read_correction(view.correction, rows, cols)
            except FollowError as error:
                if questions_left:
                    return BuilderTurn.question(_question(f"I cannot read your correction: {error}."))
                removals, additions = [], []
            standing = [p for _, p in pieces(view.builds[-1].cells)]
            for p in removals:
                if p in standing:
                    del standing[len(standing) - 1 - standing[::-1].index(p)]
            slips = draw_slips(len(additions), rng_for(e, "correction", builds))
            added = [p for g in slip_steps(additions, slips, rows, cols) for p in g]
            steps = standing + added
            task = "first_order" if e["task"] == "repetition" else e["task"]
            return BuilderTurn.code(emit_steps(task, steps, None) if steps else "# the correction leaves nothing to build")
        if e["task"] == "repetition":
            return self._loop(view, questions_left)
        return self._pieces(view, questions_left)

    def _loop(self, view: Dialogue, questions_left: int) -> BuilderTurn:
        e = self.episode
        try:
            arr = arrange(" ".join([view.instruction or "", *view.answers]), e["given_code"], e["rows"], e["cols"])
            emit.repetition(arr)  # the follower's checks (a name, an anchor)
        except FollowError as error:
            if questions_left:
                return BuilderTurn.question(_question(f"I cannot read this: {error}."))
            return BuilderTurn.code(cannot_follow(error))
        slips = draw_slips(len(arr.positions), rng_for(e, "build"), chances=len(arr.colors))
        return BuilderTurn.code(emit.repetition(slip_arrangement(arr, slips, e["rows"], e["cols"]) if slips else arr,
                                                e["rows"], e["cols"]))

    def _pieces(self, view: Dialogue, questions_left: int) -> BuilderTurn:
        e = self.episode
        rows, cols = e["rows"], e["cols"]
        answers, steps, unread = list(view.answers), [], []
        for sentence in sentences(view.instruction or ""):
            for text in (sentence, *answers[:1]):
                try:
                    found = placements(text, rows, cols, previous=steps[-1] if steps else None)
                except FollowError:
                    continue
                if text is not sentence:
                    answers.pop(0)
                steps.extend(found)
                break
            else:
                unread.append(sentence)
        for text in answers:
            try:
                steps.extend(placements(text, rows, cols, previous=steps[-1] if steps else None))
            except FollowError:
                pass
        if questions_left and (unread or not steps):
            return BuilderTurn.question(_question(f"I cannot read this: {unread[0]!r}." if unread
                                                  else "I found no component to place in your instruction."))
        if not steps:
            return BuilderTurn.code(cannot_follow(FollowError("no placement found")))
        slips = draw_slips(len(steps), rng_for(e, "build"))
        puts = [p for g in slip_steps(steps, slips, rows, cols) for p in g]
        name = object_name(view.instruction or "")
        return BuilderTurn.code(emit_steps(e["task"], puts, name) if puts else "# I put nothing")
