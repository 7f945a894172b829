"""The erring players (`-m erring`): the rule-based follower with mistakes, seeded, so that the
repair paths (execution feedback, clarification questions, describer corrections) run with a
built-in player and the recovery curves are real.

The builder's slips: it reads the instructions as the rule-based follower does (sartco.follower),
then each piece it writes slips with probability RATE (p = 0.3), one kind each, drawn uniformly:

    colour   the piece in another colour
    row      the piece one row off (column: one column off); the other way at the board's edge
    missing  the piece left out
    extra    the piece put once more, one cell away
    swap     the piece put after the next one (before the previous one, for the last)

In a repetition program (a loop over the given object function) the slips fall on the loop's
anchors (row, column, missing, extra) and on the colour list (colour; swap = two colours swapped),
with one chance per piece of the object.
Repair: after execution feedback (cobot_instruct, field `attempts`) the builder fixes the first of
its remaining slips and each other one with probability FIX (1/2), then writes the whole program
again; the describe game's builder carries out a describer's correction it can read, slipping
again at the rate p on the pieces it adds (sartco.games.describe.erring_dialogue).

Seeding: every draw comes from random.Random("SEED:board_id:game_id:task:purpose:round") (SEED =
42, the player seed; str seeds hash the same in every process), so a run is byte-identical to
the next one. game_id counts from 0 in each experiment and cobot_describe's modes play the same
boards in the same order, so a board meets the same draws in every mode: the modes are paired.

- Slip, draw_slips(n, rng), slip_steps(steps, slips, ...), slip_arrangement(arr, slips, ...)
- repaired(slips, rng)   the slips left after one readable feedback
- ErringFollower         cobot_instruct's erring builder (an AnswerSource)
"""
from __future__ import annotations

import random
from dataclasses import dataclass, replace

from sartco.follower import FollowError, emit, read_placements
from sartco.follower.parse import Arrangement, Placement, object_name
from sartco.follower.regular import arrange
from sartco.settings import ERRING_FIX, ERRING_RATE, ERRING_SEED
from sartco.world import COLORS

from .sourced import cannot_follow, fenced

SEED = ERRING_SEED      # the player seed (sartco.settings, recorded in run.json)
RATE = ERRING_RATE      # p: the share of pieces that slip
FIX = ERRING_FIX        # the chance that a slip other than the first is fixed after a feedback
KINDS = ("colour", "row", "column", "missing", "extra", "swap")
_NEIGHBOURS = ((0, 1), (1, 0), (0, -1), (-1, 0))


def rng_for(episode: dict, purpose: str, round_: int = 0) -> random.Random:
    key = f"{SEED}:{episode.get('board_id')}:{episode.get('game_id')}:{episode.get('task')}:{purpose}:{round_}"
    return random.Random(key)


@dataclass(frozen=True, slots=True)
class Slip:
    index: int      # the piece (anchor, or colour for colour/swap of a repetition program)
    kind: str
    value: int      # colour: index among the other colours; row/column: -1/+1; extra: a neighbour


def draw_slips(n: int, rng: random.Random, rate: float = RATE, chances: int | None = None) -> list[Slip]:
    """Slips over n pieces: one chance per piece (or `chances` chances at random pieces)."""
    out: list[Slip] = []
    for i in range(n if chances is None else chances):
        if rng.random() >= rate:
            continue
        kind = rng.choice(KINDS)
        index = i if chances is None else rng.randrange(n)
        value = {"colour": rng.randrange(len(COLORS) - 1), "extra": rng.randrange(4)}.get(kind, rng.choice((-1, 1)))
        if n and all(s.index != index for s in out):
            out.append(Slip(index, kind, value))
    return out


def repaired(slips: list[Slip], rng: random.Random) -> list[Slip]:
    """The slips left after a feedback the builder can read: the first is fixed, each other one
    with probability FIX."""
    return [s for s in slips[1:] if rng.random() >= FIX]


def _other_colour(colour: str, value: int) -> str:
    others = [c for c in COLORS if c != colour]
    return others[value % len(others)]


def _shift(v: int, d: int, size: int) -> int:
    return v + d if 0 <= v + d < size else v - d


def slip_steps(steps: list[Placement], slips: list[Slip], rows: int, cols: int) -> list[list[Placement]]:
    """Per position of the program, the puts written there (a list per piece: [] when missing)."""
    out = [[s] for s in steps]
    swaps = []
    for slip in slips:
        if slip.index >= len(steps):
            continue
        p = steps[slip.index]
        if slip.kind == "colour":
            out[slip.index] = [replace(p, color=_other_colour(p.color, slip.value))]
        elif slip.kind == "row":
            out[slip.index] = [replace(p, x=_shift(p.x, slip.value, rows))]
        elif slip.kind == "column":
            out[slip.index] = [replace(p, y=_shift(p.y, slip.value, cols))]
        elif slip.kind == "missing":
            out[slip.index] = []
        elif slip.kind == "extra":
            dx, dy = _NEIGHBOURS[slip.value]
            out[slip.index] = [p, replace(p, x=_shift(p.x, dx, rows), y=_shift(p.y, dy, cols))]
        else:
            swaps.append(slip.index)
    for i in swaps:
        j = i + 1 if i + 1 < len(out) else i - 1
        if j >= 0:
            out[i], out[j] = out[j], out[i]
    return out


def slip_arrangement(arr: Arrangement, slips: list[Slip], rows: int, cols: int) -> Arrangement:
    """The arrangement with its slips (the anchors of the loop, the colour list); as a list loop."""
    anchors = [[a] for a in arr.positions]
    colours = list(arr.colors)
    for slip in slips:
        if slip.kind in ("colour", "swap"):
            i = slip.index % len(colours)
            if slip.kind == "colour":
                colours[i] = _other_colour(colours[i], slip.value)
            elif len(colours) > 1:
                j = (i + 1) % len(colours)
                colours[i], colours[j] = colours[j], colours[i]
            continue
        x, y = arr.positions[slip.index]
        if slip.kind == "row":
            anchors[slip.index] = [(_shift(x, slip.value, rows), y)]
        elif slip.kind == "column":
            anchors[slip.index] = [(x, _shift(y, slip.value, cols))]
        elif slip.kind == "missing":
            anchors[slip.index] = []
        else:
            dx, dy = _NEIGHBOURS[slip.value]
            anchors[slip.index] = [(x, y), (_shift(x, dx, rows), _shift(y, dy, cols))]
    return Arrangement(arr.name, tuple(colours), tuple(a for group in anchors for a in group))


def emit_steps(task: str, steps: list[Placement], name: str | None) -> str:
    """The puts in the task's code style (a repetition answer after a correction: first-order puts)."""
    if task == "sequence_function":
        return emit.sequence_function(steps, name)
    if task == "optimal_function":
        return emit.optimal_function(steps, name)
    return emit.first_order(steps)


class ErringFollower:
    """cobot_instruct's erring builder: the rule-based follower's reading with slips; a
    multi-turn first_order episode gets one turn's puts per answer. Every answer after the
    last instruction answers a feedback (the game sends nothing else then): the whole program,
    with the slips left after one more repair."""

    def __init__(self, episode: dict):
        self.episode = episode
        e = episode
        self.texts = list(e["instructions"])
        self.repetition = e["task"] == "repetition"
        try:
            if self.repetition:
                self.arrangement = arrange(" ".join(self.texts), e.get("given_code") or "", e["rows"], e["cols"])
                if not self.arrangement.name or not self.arrangement.positions:
                    emit.repetition(self.arrangement)  # raises FollowError, as the follower does
                n, chances = len(self.arrangement.positions), len(self.arrangement.colors)
            else:
                self.steps = read_placements(self.texts, e["rows"], e["cols"])
                if not self.steps:
                    raise FollowError("no placement found")
                n, chances = len(self.steps), None
            self.error = None
        except FollowError as error:
            self.error, n, chances = error, 0, None
        self.slips = draw_slips(n, rng_for(e, "build"), chances=chances)
        self.repairs = 0

    def answer(self, turn: int) -> str:
        e = self.episode
        if self.error is not None:
            return fenced(cannot_follow(self.error))
        multi = e["task"] == "first_order" and len(self.texts) > 1
        last = len(self.texts) - 1 if multi else 0
        while self.repairs < turn - last:  # one repair per feedback answered
            self.repairs += 1
            self.slips = repaired(self.slips, rng_for(e, "repair", self.repairs))
        if self.repetition:
            arr = slip_arrangement(self.arrangement, self.slips, e["rows"], e["cols"]) if self.slips \
                else self.arrangement
            return fenced(emit.repetition(arr, e["rows"], e["cols"]))
        groups = slip_steps(self.steps, self.slips, e["rows"], e["cols"])
        if multi and turn <= last:
            before = len(read_placements(self.texts[:turn], e["rows"], e["cols"]))
            mine = len(read_placements(self.texts[:turn + 1], e["rows"], e["cols"]))
            puts = [p for g in groups[before:mine] for p in g]
            return fenced(emit.first_order(puts) if puts else "# (nothing to put in this turn)")
        puts = [p for g in groups for p in g]
        name = next((n for n in map(object_name, self.texts) if n), None)
        return fenced(emit_steps(e["task"], puts, name) if puts else "# I put nothing")
