"""The only place where model-written code runs.

    from sartco.program import execute, compare, Execution, Comparison, Limits
    ex = execute(code, rows=8, cols=8, limits=None)   # -> Execution(ok, error, message, cells, puts)
    cmp = compare(built_cells, target_cells)          # -> Comparison(es, category, precision, recall, f1)

The program gets a fresh `board` (Board(rows, cols)), `put` and `init_board(rows, cols)`. The
board that counts is the global `board` at the end if it is a Board, else the most recently
created one; `cells` is that board also when the program failed part way.

Layers (each module's docstring has the details):
  check.py    parse + check against the allowed subset + instrument for the budgets (pure)
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
