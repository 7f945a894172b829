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
- the compile runs with the recursion headroom a child had (REMAINING frames below the limit:
  how deeply nested a program may be before "too deeply nested to compile" does not depend on
  the caller's stack);
- a compile that takes longer than the wall time is `timeout`, as it was when the child's clock
  covered its compile (the run then gets the whole wall time);
- the code does not depend on the parent's hash seed or -O: compile() is told optimize=0, and
  a program whose code holds a frozenset constant (a set display of three or more constants,
  `for c in {'red', 'blue', 'green'}`, `x in {1, 2}`) is compiled in its child as before: how a
  set iterates can depend on the order its elements went in, which the compiler's steps and
  marshal (it writes them sorted) would change, and on the hash seed.
"""
from __future__ import annotations

import base64
import marshal
import sys
import threading
import time
from types import CodeType, FrameType
from typing import Any

from .execution import Execution, Limits

# frames between a compile and the recursion limit in a template's child before issue 46
# (runtime._depth() == 10 where the child called compile_program, under the default limit 1000)
REMAINING = 990


def _depth() -> int:
    frame: FrameType | None = sys._getframe()
    n = 0
    while frame is not None:
        frame, n = frame.f_back, n + 1
    return n


def _at_headroom(source: str, limits: Limits, thread: bool = False) -> tuple[Any, Any, str]:
    """runtime.compile_program(source, limits) with REMAINING frames of headroom: deeper calls
    pad the stack up to it, a caller already deeper runs it in a fresh thread."""
    from .child.runtime import compile_program

    depth = _depth()  # as runtime._depth() counts it in this frame
    target = sys.getrecursionlimit() - REMAINING
    if depth < target:
        return _at_headroom(source, limits, thread)
    if depth == target or thread:
        compiled: tuple[Any, Any, str] = compile_program(source, limits)
        return compiled
    out: list[tuple[Any, Any, str]] = []
    fresh = threading.Thread(target=lambda: out.append(_at_headroom(source, limits, True)), daemon=True)
    fresh.start()
    fresh.join()
    return out[0]


def prepare(source: str, limits: Limits) -> bytes | Execution:
    """The template's item for one program (a line: base64 of the marshalled (code, source); the
    paper protocol's program sees its own text; code None: compile it in the child;
    child/runtime.answer_item reads it), or the Execution of a program that never runs (refused,
    or a compile longer than the wall time)."""
    from .child.runtime import encode
    from .verdict import decide

    start = time.perf_counter()
    code, error, message = _at_headroom(source, limits)
    if time.perf_counter() - start > limits.wall_time:
        return decide(b"timeout", 0, b"", limits.wall_time)
    if code is None:
        return decide(b"exit", 0, encode(False, error, message, None), limits.wall_time)
    if _frozensets(code):  # compiled in the child, as before (see the module docstring)
        return base64.b64encode(marshal.dumps((None, source)))
    return base64.b64encode(marshal.dumps((code, source)))


def _frozensets(code: CodeType) -> bool:
    """Whether the code (or a function in it) has a frozenset constant."""
    return any(type(const) is frozenset or (hasattr(const, "co_consts") and _frozensets(const))
               for const in code.co_consts)
