"""The only place where model-written code runs.

    from sartco.program import execute, compare, judge, Execution, Comparison, Limits
    ex = execute(code, rows=8, cols=8, limits=None)   # -> Execution(ok, error, message, cells, puts)
    cmp = compare(built_cells, target_cells)          # -> Comparison(es, category, precision, recall, f1)
    verdict = judge(ex.ok, ex.error, ex.cells, target_cells)  # the same, ES 0 + the error unless ex.ok

`execute_many(programs, rows, cols, limits)` runs a batch in the sandbox in use (`current()`;
`use(sandbox)` puts another `Sandbox` in use, e.g. cluster.RaySandbox); `shutdown()` ends the
local templates. `semantics=PAPER` runs a program as the authors' scorer did.

docs/sandbox.md is the one page about this package: the contract (what plain `exec` runs, this
runs alike), what is refused and why, the kernel's walls, and "The sandbox's rooms": the module
map by side of the wall (standins/, check/, child/, the parent here) and where to edit to allow
a builtin, a method, a module member, a syntax form or a syscall.
"""
from __future__ import annotations

from importlib import import_module
from typing import TYPE_CHECKING

from .compare import Comparison, compare, judge
from .execution import MODULE, PAPER, Execution, Limits
from .walls import Wall, walls

if TYPE_CHECKING:
    from .pool import LocalSandbox, shutdown
    from .sandbox import Sandbox, current, execute, execute_many, use

__all__ = ["execute", "execute_many", "shutdown", "compare", "judge", "Execution", "Comparison", "Limits",
           "MODULE", "PAPER", "Sandbox", "LocalSandbox", "current", "use", "Wall", "walls"]
# the parent's names, imported on first use: the template imports this package on its way to
# child/, and so forks none of the parent's modules (pool, handle, subprocess, threads)
_LAZY = {"LocalSandbox": "pool", "shutdown": "pool", "Sandbox": "sandbox", "current": "sandbox",
         "execute": "sandbox", "execute_many": "sandbox", "use": "sandbox"}


def __getattr__(name: str) -> object:
    if name not in _LAZY:
        raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
    value = getattr(import_module(f".{_LAZY[name]}", __name__), name)
    globals()[name] = value
    return value
