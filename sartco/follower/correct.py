"""Corrections of a built board, piece by piece: what a describer who compares the built board
with the target asks to change, and how the rule-based builder reads such a correction.

    pieces(cells)                      the board as the puts that rebuild it, lowest level first
    correction_steps(built, target)    (removals top first, additions bottom first)
    read_correction(text, rows, cols)  the removals and additions written in a correction
    apply_correction(steps, text)      the puts after a correction: the rule-based builder's
                                       complete corrected program (emit it in any code style)

A piece is a Placement (shape, colour, the cell it is put at: a bridge's first cell) at a level
of its stack. The cells form lists a bridge in both its cells; `pieces` pairs them again (the
left cell of a bridge-h, the upper cell of a bridge-v). A piece is kept only if everything below
it is kept, so a correction can always be carried out in its order on the built board.
The wording is the template wording of the instructions (resources/templates/instructions/
simple/correction.j2, rendered by sartco.games.describe.dialogue): "Remove the blue nut in the 8th row,
4th column. Place a red washer in the 8th row, 4th column."
"""
from __future__ import annotations

import re

from sartco.world.board import parse_key
from sartco.world import BRIDGES, DEFAULT_COLS, DEFAULT_ROWS

from .parse import FollowError, Placement, placements

Piece = tuple[int, Placement]  # (level, placement)
_SENTENCE = re.compile(r"(?<=[.!?])\s+|\n+")
_REMOVE = re.compile(r"^\W*(?:remove|take\s+(?:away|off)|delete)\b", re.IGNORECASE)


def covered(p: Placement) -> list[tuple[int, int]]:
    """The cells a placement occupies."""
    offset = BRIDGES.get(p.shape)
    return [(p.x, p.y)] if offset is None else [(p.x, p.y), (p.x + offset[0], p.y + offset[1])]


def pieces(cells: dict) -> list[Piece]:
    """The pieces of a board in canonical cells form, level by level, row-major within a level."""
    stacks = {parse_key(key): [tuple(c) for c in stack] for key, stack in cells.items()}
    used: set[tuple[int, int, int]] = set()
    out: list[Piece] = []
    for level in range(max((len(s) for s in stacks.values()), default=0)):
        for (r, c) in sorted(stacks):
            stack = stacks[(r, c)]
            if level >= len(stack) or (r, c, level) in used:
                continue
            shape, color = stack[level]
            p = Placement(shape, color, r, c)
            for cell in covered(p):
                used.add((*cell, level))
            out.append((level, p))
    return out


def correction_steps(built: dict, target: dict) -> tuple[list[Placement], list[Placement]]:
    """What turns the built board into the target: the pieces to remove (top first) and the
    pieces to place (bottom first). Empty lists when the boards are equal."""
    wanted = set(pieces(target))
    removed: list[Piece] = []
    gone: set[tuple[int, int, int]] = set()  # (row, col, level) of removed pieces
    standing = pieces(built)
    for level, p in standing:  # lowest level first: a removal reaches everything above it
        below = any((r, c, lv) in gone for r, c in covered(p) for lv in range(level))
        if below or (level, p) not in wanted:
            removed.append((level, p))
            gone.update((r, c, level) for r, c in covered(p))
    kept = set(standing) - set(removed)
    additions = [p for level, p in pieces(target) if (level, p) not in kept]
    return [p for _, p in sorted(removed, key=lambda lp: -lp[0])], additions


def read_correction(text: str, rows: int = DEFAULT_ROWS,
                    cols: int = DEFAULT_COLS) -> tuple[list[Placement], list[Placement]]:
    """The removals and additions in a correction, sentence by sentence: a sentence starting
    with "Remove" (take away, delete) names pieces to remove, any other names pieces to place.
    FollowError when a sentence names a piece it does not fully describe."""
    removals: list[Placement] = []
    additions: list[Placement] = []
    for sentence in _SENTENCE.split(text or ""):
        if not sentence.strip():
            continue
        found = placements(sentence, rows, cols, previous=(additions or removals or [None])[-1])
        (removals if _REMOVE.match(sentence) else additions).extend(found)
    return removals, additions


def apply_correction(steps: list[Placement], text: str, rows: int = DEFAULT_ROWS,
                     cols: int = DEFAULT_COLS) -> list[Placement]:
    """The puts after a correction: each removal takes away the last put of that piece, the
    additions follow in their order. FollowError when the correction names no piece at all."""
    removals, additions = read_correction(text, rows, cols)
    if not removals and not additions:
        raise FollowError(f"no piece to remove or place in {text.strip()!r:.160}")
    out = list(steps)
    for p in removals:
        for i in range(len(out) - 1, -1, -1):
            if out[i] == p:
                del out[i]
                break
    return out + additions
