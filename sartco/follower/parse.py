"""Instruction text -> structured records (placements, arrangements), by the tables of grammar.py."""
from __future__ import annotations

import re
from dataclasses import dataclass

from sartco.syntax import literal
from sartco.world import DEFAULT_COLS, DEFAULT_ROWS

from . import grammar


class FollowError(ValueError):
    """The follower could not understand an instruction; the message says what was missing."""


@dataclass(frozen=True, slots=True)
class Placement:
    """One put: shape (bridge-h/bridge-v resolved), colour and 0-based cell."""
    shape: str
    color: str
    x: int
    y: int


@dataclass(frozen=True, slots=True)
class Arrangement:
    """A regular board: the object's name and colours, and the anchors where it goes."""
    name: str | None
    colors: tuple[str, ...]
    positions: tuple[tuple[int, int], ...]
    rows: tuple[int, ...] | None = None   # set when positions = rows x cols (a nested loop)
    cols: tuple[int, ...] | None = None


# --- numbers ---------------------------------------------------------------------------------------
def ordinal(text: str) -> int:
    """'8th' / '8' / 'eighth' / 'eight' -> 8 (1-based)."""
    t = text.strip().lower()
    if t in grammar.ORDINAL_WORDS:
        return grammar.ORDINAL_WORDS[t]
    if t in grammar.CARDINAL_WORDS:
        return grammar.CARDINAL_WORDS[t]
    m = re.fullmatch(r"(\d{1,2})(?:st|nd|rd|th)?", t)
    if not m:
        raise FollowError(f"not an ordinal: {text!r}")
    return int(m.group(1))


def ordinal_list(text: str) -> list[int]:
    """'first, fourth, and seventh' -> [1, 4, 7]."""
    return [ordinal(m.group(0)) for m in re.finditer(grammar.ORD, text, re.IGNORECASE)]


def _index(one_based: int, size: int, what: str) -> int:
    if not 1 <= one_based <= size:
        raise FollowError(f"{what} {one_based} is outside 1..{size}")
    return one_based - 1


# --- simple boards ---------------------------------------------------------------------------------
def object_name(text: str) -> str | None:
    """The name after 'build', if the instruction gives one ('These are the instructions to build wn.')."""
    for m in grammar.OBJECT_NAME.finditer(text):
        name = m.group("name")
        if name.lower() not in grammar.NAME_STOPWORDS and name.lower() not in grammar.SHAPE_WORDS:
            return name
    return None


class _Piece:
    __slots__ = ("shape", "color", "orientation", "row", "col", "same")

    def __init__(self):
        self.shape = self.color = self.orientation = self.row = self.col = None
        self.same = False


def placements(text: str, rows: int = DEFAULT_ROWS, cols: int = DEFAULT_COLS,
               previous: Placement | None = None) -> list[Placement]:
    """Every placement in a text, in order. `previous` resolves 'on top of it' in the first clause.

    Each clause is read as a stream of tokens (colour, shape, orientation, row, column, 'on top');
    a shape word opens a new piece. A colour is an adjective: it goes to the next shape (or, at
    the end of a clause, to the last piece still without one). Other words fill the current
    piece's empty fields, or wait for the next piece. A piece without a cell goes on the previous one.
    """
    out: list[Placement] = []
    last = previous
    for clause in grammar.CLAUSE_SPLIT.split(text):
        pending = _Piece()
        current: _Piece | None = None
        pieces: list[_Piece] = []
        for m in grammar.TOKEN.finditer(clause):
            kind = m.lastgroup
            value = m.group(kind)
            if kind in ("bridge_h", "bridge_v"):
                kind, value = "shape", "bridge"
                pending.orientation = pending.orientation or grammar.ORIENTATION_WORDS[m.group(0).lower()]
            if kind == "shape":
                current, pending = pending, _Piece()
                current.shape = grammar.SHAPE_WORDS[value.lower()]
                pieces.append(current)
                continue
            field, val = _token_value(kind, value, rows, cols)
            target = pending if current is None or field == "color" else current
            if getattr(target, field) not in (None, False):
                target = pending          # already set: it belongs to the next piece
            if getattr(target, field) in (None, False):
                setattr(target, field, val)
        colorless = [piece for piece in pieces if piece.color is None]
        if pending.color and colorless:   # "... a nut in the 8th row, red"
            colorless[-1].color = pending.color
        for piece in pieces:
            last = _resolve(piece, last, rows, cols, clause)
            out.append(last)
    return out


def _token_value(kind: str, value: str, rows: int, cols: int):
    low = value.lower()
    if kind == "color":
        return "color", grammar.COLOR_WORDS[low]
    if kind == "orient":
        return "orientation", grammar.ORIENTATION_WORDS[low]
    if kind in ("row_ord", "row_num"):
        return "row", ordinal(value)
    if kind in ("col_ord", "col_num"):
        return "col", ordinal(value)
    if kind == "row_edge":
        v = grammar.ROW_EDGES[low]
        return "row", rows if v == "last" else v
    if kind == "col_edge":
        v = grammar.COL_EDGES[low]
        return "col", cols if v == "last" else v
    if kind == "same":
        return "same", True
    raise AssertionError(kind)


def _resolve(piece: _Piece, last: Placement | None, rows: int, cols: int, clause: str) -> Placement:
    where = f" in {clause.strip()!r:.120}"
    shape = piece.shape
    if shape == "bridge":
        if piece.orientation is None:
            raise FollowError(f"a bridge without an orientation (horizontally/vertically){where}")
        shape = piece.orientation
    if piece.color is None:
        raise FollowError(f"a {shape} without a colour{where}")
    if piece.row is None and piece.col is None:
        if last is None:
            raise FollowError(f"a {shape} without a row and column{where}")
        return Placement(shape, piece.color, last.x, last.y)
    if piece.row is None or piece.col is None:
        if last is None:
            raise FollowError(f"a {shape} without a {'row' if piece.row is None else 'column'}{where}")
    x = last.x if piece.row is None else _index(piece.row, rows, "row")
    y = last.y if piece.col is None else _index(piece.col, cols, "column")
    return Placement(shape, piece.color, x, y)


# --- regular boards --------------------------------------------------------------------------------
def colors_of(text: str) -> tuple[str, ...]:
    """The object's colours: a Python list after 'colors', else the colour words after 'colors'."""
    m = grammar.COLOR_LIST.search(text)
    if m:
        try:
            value = literal(m.group("list"))
        except (ValueError, SyntaxError):
            value = None
        if isinstance(value, list) and value and all(isinstance(c, str) for c in value):
            return tuple(c.strip().lower() for c in value)
    m = grammar.COLOR_PHRASE.search(text)
    scope = m.group("rest") if m else text
    found = re.findall(rf"\b(?:{'|'.join(grammar.COLOR_WORDS)})\b", scope, re.IGNORECASE)
    if not found and m:
        found = re.findall(rf"\b(?:{'|'.join(grammar.COLOR_WORDS)})\b", text, re.IGNORECASE)
    if not found:
        raise FollowError("no colours found (expected e.g. \"Use only these colors: ['red', 'blue']\")")
    return tuple(c.lower() for c in found)


def size_of(text: str) -> tuple[int, int] | None:
    """'each occupying a 2x1 space' -> (2, 1) (rows x columns), or None."""
    m = grammar.SIZE.search(text)
    return (int(m.group("h")), int(m.group("w"))) if m else None


def regular_name(text: str) -> str | None:
    m = grammar.QUOTED_OBJECT.search(text)
    return m.group("name") if m else None


def arrangement_kind(text: str) -> tuple[str, re.Match]:
    for kind, pattern in grammar.ARRANGEMENTS:
        m = pattern.search(text)
        if m:
            return kind, m
    raise FollowError(f"no known arrangement (corners, diagonal, alternating, fill a column, "
                      f"columns of a row) in {text.strip()!r:.160}")
