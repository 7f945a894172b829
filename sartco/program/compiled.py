"""The parent's compile (issue 46): each program is parsed, checked, instrumented and compiled in
the warm parent (runtime.compile_program), and its child gets only what it runs: the code object,
marshalled. Compiling in a freshly forked child cost four times what it costs here (every page the
parser and the checks touch is a copy-on-write fault there; docs/sandbox.md has the breakdown).

Nothing of the program runs here: compile_program only parses (CPython's parser), walks the tree
(instrument.py) and compiles it. What comes out is data the child runs under every wall, and the
only thing the parent ever reads back is the child's answer (verdict.py), as before.

The verdicts are those of a compile in the child:
- a program refused here (forbidden, syntax_error, resource_limit, ...) gets the Execution its
  child would have answered (no board: it never ran), without a child;
- every compile runs on one thread of the parent, at the stack depth where a program may be
  as deeply nested as in a child (calibrated once: DEEPEST), whatever the caller's stack;
- a compile that takes longer than the wall time is `timeout`, as it was when the child's clock
  covered its compile (the run then gets the whole wall time);
- programs of one batch that differ only in their last line (an answer's probes, a gold draw's
  candidates: the same function at other arguments) share the parse, check and compile of the
  rest, their head, where their last lines allow (instrument.prepare): the code is then (the
  head's, the last line's), run in turn in one namespace; each program's compile counts its
  head's seconds;
- the code does not depend on the parent's hash seed or -O: compile() is told optimize=0, and
  a program whose code holds a frozenset constant (a set display of three or more constants,
  `for c in {'red', 'blue', 'green'}`, `x in {1, 2}`) is compiled in its child as before: how a
  set iterates can depend on the order its elements went in, which the compiler's steps and
  marshal (it writes them sorted) would change, and on the hash seed (its nesting was judged
  here: the child compiles it with room to spare, runtime.answer_item).
"""
from __future__ import annotations

import base64
import marshal
import os
import threading
import time
from collections import Counter
from collections.abc import Callable
from concurrent.futures import ThreadPoolExecutor
from functools import partial
from types import CodeType
from typing import TYPE_CHECKING, Any

from .execution import Execution, Limits

if TYPE_CHECKING:
    from .check.instrument import Head

# how deeply nested a program may be before "too deeply nested to compile" depends on the stack
# it is compiled on; in a template's child before issue 46, a sum of DEEPEST terms compiled and
# one more did not. The parent compiles on one thread of its own (per process), padded once to
# the stack depth that gives the same limit.
DEEPEST = 986
_compiler: tuple[int, ThreadPoolExecutor] | None = None
_compiler_lock = threading.Lock()
_pad: list[int] = []


def _sum(terms: int) -> str:
    return "x = 1\ny = " + " + ".join(["x"] * terms)


def _padded(frames: int, work: Callable[[], Any]) -> Any:
    return _padded(frames - 1, work) if frames > 0 else work()


def _calibrated() -> int:
    """The padding (frames) at which DEEPEST terms compile on a fresh compiler thread and one more
    does not; each try on a compiler thread of its own (see compile_all)."""

    def deepest(pad: int) -> bool:  # DEEPEST terms compile at this padding
        with ThreadPoolExecutor(1, thread_name_prefix="sartco-compiler") as once:
            return once.submit(_compile_all, [_sum(DEEPEST)], Limits(), pad).result()[0][0][0] is not None

    low, high = 0, 400  # deepest(low) holds; find the most padding at which it still does
    if not deepest(low):
        return 0
    while low < high:
        middle = (low + high + 1) // 2
        low, high = (middle, high) if deepest(middle) else (low, middle - 1)
    return low


def _compile_all(sources: list[str], limits: Limits, pad: int) -> list[tuple[tuple[Any, Any, str], float]]:
    """On the compiler thread: compile_program of each source and its seconds, up to and with the
    first resource_limit (after which this thread's recursion count may be off: CPython 3.11
    does not always restore it when a compile fails too deep)."""
    from sartco.world import ErrorCode

    from .check.instrument import split
    from .child.runtime import compile_program

    made: list[tuple[tuple[Any, Any, str], float]] = []
    parts = [split(source) if type(source) is str else None for source in sources]
    shared = Counter(part[0] for part in parts if part is not None)
    heads: dict[str, Head | None] = {}  # the heads of programs that share theirs (instrument.prepare)
    made_in: dict[str, float] = {}  # the seconds of the compile that made each head
    for source, part in zip(sources, parts):
        head = part[0] if part is not None and shared[part[0]] > 1 else None
        start = time.perf_counter()
        result = _padded(pad, partial(compile_program, source, limits, None if head is None else heads))
        seconds = time.perf_counter() - start
        if head is not None and head in heads and head not in made_in:
            made_in[head] = seconds  # (the compile that made the head)
        elif head is not None and type(result[0]) is tuple:  # a program whose code is a head's and its
            seconds += made_in[head]  # last line's counts the head's making, as a compile of it whole would
        made.append((result, seconds))
        if made[-1][0][1] is ErrorCode.RESOURCE_LIMIT:
            break
    return made


def compile_all(sources: list[str], limits: Limits) -> list[tuple[tuple[Any, Any, str], float]]:
    """runtime.compile_program of each source and the seconds it took, on the compiler thread
    (the nesting limit of a child); after a resource_limit, on a fresh one."""
    global _compiler
    made: list[tuple[tuple[Any, Any, str], float]] = []
    while len(made) < len(sources):
        with _compiler_lock:
            if _compiler is None or _compiler[0] != os.getpid():
                _pad[:] = [_calibrated()]
                _compiler = (os.getpid(), ThreadPoolExecutor(1, thread_name_prefix="sartco-compiler"))
            executor = _compiler[1]
        made += executor.submit(_compile_all, sources[len(made):], limits, _pad[0]).result()
        if len(made) < len(sources) or made[-1][0][1] == "resource_limit":
            with _compiler_lock:
                if _compiler is not None and _compiler[1] is executor:
                    executor.shutdown(wait=False)
                    _compiler = (os.getpid(), ThreadPoolExecutor(1, thread_name_prefix="sartco-compiler"))
    return made


def prepare(source: str, limits: Limits) -> bytes | Execution:
    """prepare_all of one source."""
    return prepare_all([source], limits)[0]


def prepare_all(sources: list[str], limits: Limits) -> list[bytes | Execution]:
    """The template's item for each program (a line: base64 of the marshalled (code, source); the
    paper protocol's program sees its own text; code None: compile it in the child;
    child/runtime.answer_item reads it), or the Execution of a program that never runs (refused,
    or a compile longer than the wall time)."""
    from .child.runtime import encode
    from .verdict import decide

    made: list[bytes | Execution] = []
    for source, ((code, error, message), seconds) in zip(sources, compile_all(sources, limits)):
        if seconds > limits.wall_time:
            made.append(decide(b"timeout", 0, b"", limits.wall_time))
        elif code is None:
            made.append(decide(b"exit", 0, encode(False, error, message, None), limits.wall_time))
        elif _frozensets(code):  # compiled in the child, as before (see the module docstring)
            made.append(base64.b64encode(marshal.dumps((None, source))))
        else:
            made.append(base64.b64encode(marshal.dumps((code, source))))
    return made


def _frozensets(code: CodeType | tuple[CodeType, ...]) -> bool:
    """Whether the code (or a function in it) has a frozenset constant."""
    if isinstance(code, tuple):
        return any(_frozensets(part) for part in code)
    return any(type(const) is frozenset or (hasattr(const, "co_consts") and _frozensets(const))
               for const in code.co_consts)
