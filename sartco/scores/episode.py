"""One episode's score: the recorded facts of a played episode turned into numbers.

Both games use it: cobot_instruct scores the builder's code, cobot_describe the code built from a
model's description. The scorer computes it from what the game master recorded (the answer's
code, the gold code of the same style, the Execution and the Comparison of `sartco.program`) and
logs its fields; `sartco report` reads them back with `from_dict`.
"""
from __future__ import annotations

import math
from dataclasses import asdict, dataclass, fields
from typing import Any, Protocol

from sartco.world import ErrorCode

from .metrics import code_bleu, exact_match


class _Execution(Protocol):  # sartco.program.Execution
    ok: bool
    error: ErrorCode | None
    message: str
    puts: int


class _Comparison(Protocol):  # sartco.program.Comparison
    es: int
    category: ErrorCode | None
    precision: float
    recall: float
    f1: float


@dataclass(frozen=True, slots=True)
class EpisodeScore:
    """em, codebleu: against the gold code of the same style; None when the episode has no gold code.
    es: 1 when the built board equals the target. precision/recall/f1: over (cell, level, piece)
    of the built board (also a partial one) against the target. category: the first thing that went
    wrong (parse_error, a program/world/sandbox error, else the mismatch category), None on success;
    error: its message. puts: pieces placed. aborted: no code was found in the answer (clemcore's
    Aborted; Main Score NaN)."""

    em: int | None
    codebleu: float | None
    es: int
    precision: float
    recall: float
    f1: float
    category: ErrorCode | None
    puts: int
    error: str = ""
    aborted: bool = False

    @property
    def main_score(self) -> float:
        """clemcore's Main Score: 100 x ES, NaN when the episode was aborted."""
        return math.nan if self.aborted else 100.0 * self.es

    @classmethod
    def from_run(cls, code: str, gold: str | None, execution: _Execution, comparison: _Comparison) -> "EpisodeScore":
        """A played episode: the answer's code ran (successfully or not) and its board was compared."""
        category = comparison.category if execution.ok else execution.error
        return cls(
            em=None if gold is None else exact_match(code, gold),
            codebleu=None if gold is None else code_bleu(code, gold),
            es=int(bool(execution.ok and comparison.es)),
            precision=float(comparison.precision),
            recall=float(comparison.recall),
            f1=float(comparison.f1),
            category=None if category is None else ErrorCode(category),
            puts=int(execution.puts),
            error="" if execution.ok else execution.message,
        )

    @classmethod
    def from_abort(cls, message: str, gold: str | None = None, category: ErrorCode = ErrorCode.PARSE_ERROR) -> "EpisodeScore":
        """An aborted episode (no code in the answer): nothing ran, nothing matches."""
        return cls(
            em=None if gold is None else 0,
            codebleu=None if gold is None else 0.0,
            es=0, precision=0.0, recall=0.0, f1=0.0,
            category=ErrorCode(category), puts=0, error=message, aborted=True,
        )

    def as_dict(self) -> dict[str, Any]:
        """snake_case, JSON-ready (the category as its string value)."""
        out = asdict(self)
        out["category"] = None if self.category is None else self.category.value
        return out

    @classmethod
    def from_dict(cls, data: dict[str, Any]) -> "EpisodeScore":
        names = {f.name for f in fields(cls)}
        unknown = set(data) - names
        if unknown:
            raise ValueError(f"EpisodeScore: unknown field(s) {sorted(unknown)}")
        values = dict(data)
        if values.get("category") is not None:
            values["category"] = ErrorCode(values["category"])
        return cls(**values)
