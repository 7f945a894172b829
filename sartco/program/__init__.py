"""The only place where model-written code runs.

    from sartco.program import execute, compare, Execution, Comparison, Limits
    ex = execute(code, rows=8, cols=8, limits=None)   # -> Execution(ok, error, message, cells, puts)
    cmp = compare(built_cells, target_cells)          # -> Comparison(es, category, precision, recall, f1)

The program gets a fresh `board` (Board(rows, cols)), `put` and `init_board(rows, cols)`. The
board that counts is the global `board` at the end if it is a Board, else the most recently
created one; `cells` is that board also when the program failed part way.

The contract: any program that plain `exec` with `board`, `put` and `init_board` runs correctly,
and that reaches nothing outside the task's world, builds the same board here. Ordinary
Python works: functions, lambdas, decorators, loops,
comprehensions, try/except/else/finally, raise, assert, del, global/nonlocal, annotations,
`_` names, set/dict/list displays, the common methods of str/list/dict/set/tuple (and of
collections' defaultdict/Counter/deque), f-strings, `str.format` and `%` formatting, map, filter,
isinstance, float, next/iter, and imports of math, itertools, functools, typing, collections,
copy, operator, string and numpy (a stand-in: `np.ndarray` for annotations, small helpers that
return lists), all under the budgets of Limits.

Refused (`forbidden`, with the reason in the message), because they reach the interpreter, the
file system, the network or the scoring:
- names and attributes with two leading underscores (`__class__`, `__import__`, ...), any
  other attribute than the allowed methods and module members, any attribute store;
- eval, exec, compile, open, input, getattr/setattr, type, object, globals/vars, breakpoint and
  Python's other builtins that are not listed above (unless the program binds the name itself);
- imports of anything but the stand-in modules (os, sys, subprocess, random, re, ...), and the
  members they do not offer (typing.get_type_hints, collections.namedtuple, numpy.linalg, ...);
- class, with, yield, async/await, match, try/except*;
- redefining `put` or `init_board`;
- format fields that read attributes or items (`{0.x}`, `{0[k]}`), widths above 999, `*` widths.
Budget stops: `timeout` (steps, wall time) and `resource_limit` (depth, length, integer size,
memory, source size); no handler catches them (nor a refusal), and they stay the verdict when a
program swallows them. A program that crashes its worker gets `runtime_error` "crashed (SIGSEGV)".

No program spoils another: a worker retires after a budget stop, a MemoryError, an internal
error, or a program after which it holds 64 MB more than at its start, and the next program
runs in a fresh one; verdicts are cached only when they depend on the source alone; messages are cleaned of control characters
and lone surrogates before anything writes them; workers die with their parent process.


Layers (each module's docstring has the details):
  check.py    parse + check against the allowed subset + instrument for the budgets (pure)
  budget.py   the length/integer budgets inside operators, conversions, formatting, str methods
  modules.py  the stand-in modules a program may import
  runtime.py  run one prepared program in a minimal namespace, map outcomes to ErrorCode
  worker.py   the worker process loop (JSON lines over pipes, rlimits)
  pool.py     persistent workers, batching, hard kill on wall time, restarts; execute()
  compare.py  ES, mismatch category, cell precision/recall/F1
  lines.py    one line of the `sartco execute` contract (parsed and answered inside the workers)
  cli.py      `sartco execute` (JSON lines); bench.py `sartco bench-execute`
  gold.py     the published gold programs with the authors' boards (tests, benchmark)

`execute_many(programs, rows, cols, limits, workers=None)` runs a batch (split over up to two
worker processes); `shutdown()` kills the workers (they restart on the next call).
"""
from .compare import compare
from .pool import execute, execute_many, shutdown
from .records import Comparison, Execution, Limits

__all__ = ["execute", "execute_many", "shutdown", "compare", "Execution", "Comparison", "Limits"]
