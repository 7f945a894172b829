"""The one place that turns Python source into a syntax tree: `parse`, and `literal` (ast.literal_eval,
which parses a text).

CPython 3.11 keeps the depth counter of its AST constructor (the step of ast.parse that builds the
Python tree) in the interpreter, not in the call (CPython gh-106905). Each call sets the counter
from its own stack depth and checks at the end that it came back to it. When another parse runs in
the middle of one (another thread, when the constructor's allocations let the GIL go; or a finalizer
that the collector runs there), the first ends in a spurious `SystemError: AST constructor
recursion depth mismatch`, or in a spurious RecursionError when the other started deeper. This
project parses in several threads of one process (the game's work ahead, the pool, the players),
so a model's program could fail for a reason of the harness.

`parse` therefore holds one lock for the whole process, so no two of the project's parses overlap,
and parses again after the spurious error (a parse outside the project, like the traceback module's
when it formats an error, can still cut in). A process forked while one of its threads parsed
gets a lock of its own. Free of dependencies but the standard library's `ast`, `os` and `_thread`
(a template of the sandbox imports it: no `threading` there).
"""
from __future__ import annotations

import _thread
import ast
import os
from typing import Any, cast

_LOCK = _thread.RLock()  # re-entrant: a finalizer that parses may run inside a parse of its own thread
_SPURIOUS = "recursion depth mismatch"
_ATTEMPTS = 3


def _forked() -> None:
    """In a forked child: a lock that no thread holds (a thread of the parent may have held it at the fork)."""
    global _LOCK
    _LOCK = _thread.RLock()


os.register_at_fork(after_in_child=_forked)


def _parsed(source: str, filename: str, mode: str) -> ast.AST:
    with _LOCK:
        for _ in range(_ATTEMPTS - 1):
            try:
                return ast.parse(source, filename, mode)
            except SystemError as exc:
                if _SPURIOUS not in str(exc):
                    raise
        return ast.parse(source, filename, mode)


def parse(source: str, filename: str = "<unknown>") -> ast.Module:
    """ast.parse(source, filename): the same tree and the same SyntaxError or ValueError, never
    overlapping another parse of the process's threads (module doc)."""
    return cast(ast.Module, _parsed(source, filename, "exec"))


def literal(value: str | ast.AST) -> Any:
    """ast.literal_eval of a tree or of a text (parsed by `parse`'s rule): the same value and the
    same errors."""
    return ast.literal_eval(_parsed(value.lstrip(" \t"), "<unknown>", "eval") if isinstance(value, str) else value)
