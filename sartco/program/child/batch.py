"""The sandbox's modes "gold" and "answer" (template.py): the programs of one chunk in one child.

Mode "gold" is for the harness's own reference programs (an instance's gold function at the
probes' candidate arguments, sartco.clem.core.probes); mode "answer" for the programs of ONE
model answer (its function probes: the parent never puts two answers in one chunk, pool.py).
Sharing a child within one answer gives that answer nothing: in each of its processes a program
already decides what it builds, and the walls between answers, models and the host are the
same. The chunk's programs run one after another in ONE confined child, each on its own fresh
board and namespace with its own budgets (runtime.RAN: np, typing's caches, random and the
serials afresh), each answer framed (4-byte length + answer) and written as it finishes; every
item has Limits.wall_time from the end of the one before. The walls are the same (the CPU rlimit
covers the chunk). Answers equal those of a child per program: a program's verdict depends only
on its source, board and budgets. What could depend on the programs before it in the same
process (a `timeout` or `resource_limit` answer, a child that ended or was killed before the
last answer) is not used: that item and every one after it run again, each in a child of its
own, as in mode "code". Why: a fork, its page faults and its exit cost about 2 ms here, a probe
candidate's run 0.15-0.3 ms; a board's probe draw runs about 21 candidates and an answer's
probes 8 programs (the 1,560 draws of the paper protocol took 29.0 s a child per program, 7.6 s
a child per round).
"""
from __future__ import annotations

import json
import re
from collections.abc import Iterator
from dataclasses import replace
from functools import partial
from types import ModuleType
from typing import TYPE_CHECKING, Callable, Iterable, Protocol

if TYPE_CHECKING:
    from ..execution import Limits


class Template(Protocol):
    """What run() needs of worker.Template: its runtime module and its two ways to fork."""
    runtime: ModuleType

    def fork(self, work: Callable[[], bytes], limits: Limits) -> tuple[bytes, int, bytes]: ...

    def spawn(self, work: Callable[[], Iterable[bytes]], limits: Limits, walls: Limits,
              frames: int) -> tuple[bytes, int, bytes]: ...

# an answer that could depend on the programs run before it in the same child
UNSURE = frozenset({"timeout", "resource_limit", None})
ENDS = (b"exit", b"signal", b"timeout", b"overflow")  # a child that ran (it may have left answers)


def _spans(data: bytes | bytearray, at: int) -> Iterator[tuple[int, int]]:
    """(start, end) of each complete frame (4-byte big-endian length + answer) from offset `at`."""
    while at + 4 <= len(data):
        end = at + 4 + int.from_bytes(data[at:at + 4], "big")
        if end > len(data):
            return
        yield at + 4, end
        at = end


def frames(data: bytes) -> list[bytes]:
    """The complete framed answers at the start of data."""
    return [data[start:end] for start, end in _spans(data, 0)]


def advance(data: bytes | bytearray, at: int) -> tuple[int, int]:
    """How many frames complete from offset `at` of data, and the offset after them (the
    template counts a child's answers as its output grows, without reading any byte twice)."""
    n = 0
    for _, end in _spans(data, at):
        n, at = n + 1, end
    return n, at


# an answer's first two values as runtime.encode writes them (json.dumps: ok, then the code or null)
_HEAD = re.compile(rb'\[(?:true|false), (?:null|"([a-z_]+)"), ')


def outcome(answer: bytes) -> str | None:
    """An answer's error code ("" for a program that ran to the end), None for no answer. An
    answer that starts as runtime.encode writes one is read from its start alone (a JSON parse of
    each answer was a fifth of a template's work); what follows only decides that answer's own
    verdict, which the parent reads whole (verdict.py)."""
    head = _HEAD.match(answer)
    if head is not None:
        return (head[1] or b"").decode("ascii")
    try:
        code = json.loads(answer)[1]
    except (ValueError, LookupError, TypeError):  # (a JSON object: KeyError)
        return None
    if code is None:
        return ""
    return code if isinstance(code, str) else None


def answers(answer: Callable[..., bytes], items: list[bytes], rows: int, cols: int, limits: Limits,
            semantics: str) -> Iterator[bytes]:
    """In the child: each item's framed answer as it finishes."""
    for item in items:
        data = answer(item, rows, cols, limits, semantics)
        yield len(data).to_bytes(4, "big") + data


def run(template: Template, items: list[bytes], rows: int, cols: int, limits: Limits,
        semantics: str) -> list[tuple[bytes, int, bytes]]:
    """(how, status, answer) per item (a program as the parent compiled it, sartco/program/compiled.py), as the
    template reports them: the items in one child; from the first answer that the programs
    before it could have changed (or none came), each in a child of its own."""
    runtime = template.runtime
    walls = replace(limits, wall_time=limits.wall_time * len(items))  # the CPU rlimit covers the chunk
    work = partial(answers, runtime.answer_item, items, rows, cols, limits, semantics)
    how, _, data = template.spawn(work, limits, walls, len(items))
    done: list[tuple[bytes, int, bytes]] = []
    for answer in frames(data) if how in ENDS else []:
        if outcome(answer) in UNSURE:
            break
        done.append((b"exit", 0, answer))
    return done + [template.fork(partial(runtime.answer_item, item, rows, cols, limits, semantics), limits)
                   for item in items[len(done):]]
