"""The only place where model-written code runs.

    from sartco.program import execute, compare, judge, Execution, Comparison, Limits
    ex = execute(code, rows=8, cols=8, limits=None)   # -> Execution(ok, error, message, cells, puts)
    cmp = compare(built_cells, target_cells)          # -> Comparison(es, category, precision, recall, f1)
    verdict = judge(ex.ok, ex.error, ex.cells, target_cells)  # the same, ES 0 + the error unless ex.ok

The program gets a fresh `board` (Board(rows, cols)), `put` and `init_board(rows, cols)`. The
board that counts is the global `board` at the end if it is a Board, else the most recently
created one; `cells` is that board also when the program failed part way.

The contract: any program that plain `exec` with `board`, `put` and `init_board` runs correctly,
run as a script (`__name__ == "__main__"`), and that reaches nothing outside the task's world,
builds the same board here. Ordinary Python works: functions, lambdas, decorators, loops,
comprehensions, generators, classes (with the ordinary dunder methods, also bound as
`__rmul__ = __mul__`, properties, static and class methods, inheritance, super()), attributes on
the program's own functions, `with contextlib.suppress(...)`, try/except/else/finally, raise, assert, del,
global/nonlocal, annotations, `_` names, set/dict/list displays, the common methods of
str/list/dict/set/tuple (and of collections' defaultdict/Counter/deque), f-strings,
`str.format` and `%` formatting, map, filter, isinstance, float, next/iter, and imports of math,
itertools, functools, typing, collections, copy, operator, string, json, dataclasses (with
`fields`), contextlib (suppress, nullcontext), random (CPython's
sequence; seeded with 0 unless the program seeds it) and numpy (arrays with numpy's semantics
for the subset models use), all under the budgets of Limits.

Refused (`forbidden`, with the reason in the message), because they reach the interpreter, the
file system, the network or the scoring:
- names and attributes with two leading underscores (`__class__`, `__import__`, ...) except the
  dunder methods a class may define (by def or by assignment in its body) and `__name__`; any
  other attribute than the allowed methods, module members and what the program defines;
  attribute stores except on the program's own objects and functions (attributes.py has the rule);
- eval, exec, compile, open, input, getattr/setattr, type, object, globals/vars, breakpoint and
  Python's other builtins that are not listed above (unless the program binds the name itself);
- imports of anything but the stand-in modules (os, sys, subprocess, re, ...), and the
  members they do not offer (typing.get_type_hints, numpy.linalg, ...);
- metaclasses, class keywords, bases other than the program's classes, exceptions and
  NamedTuple, and dunder definitions that change how Python treats an object (classes.py);
- `with` on anything but contextlib's suppress/nullcontext (a program's class cannot define
  __enter__/__exit__), async/await, match, try/except*;
- redefining `put` or `init_board`;
- format fields that read attributes or items (`{0.x}`, `{0[k]}`), widths above 999, `*` widths.
Budget stops: `timeout` (steps, wall time) and `resource_limit` (depth, length, integer size,
memory, source size); no handler catches them (nor a refusal), and they stay the verdict when a
program swallows them (an except handler re-raises them; a `finally` body's first statement
remembers a RecursionError or MemoryError passing through). A program that crashes its process
gets `runtime_error` "crashed its process (SIGSEGV)".

The walls (issue 32): the checks above refuse early and explain, but no score and no host
resource depends on them. Every program runs in a fresh process forked from a template that has
imported what programs need and has run no program (worker.py); before the program's first line
that child keeps only /dev/null and its answer pipe, takes rlimits (address space, CPU, file
size, open files, processes) and a seccomp allow-list (confine.py: no file opened or created, no
socket, exec, new process or thread, signal to another process, ptrace, ...), and it exits after
the one program. It sends back only a put log of plain values and its outcome; the parent
replays the log with the world's own `put` on its own board (verdict.py), so only `put` changes a
board whatever happened in the child. However a child ends (a crash, an exit, garbage, too much,
nothing) it is the program's `runtime_error`, `resource_limit` or `timeout`; `harness_error` is
the parent's and the template's own failure alone (no template could start, the kernel cannot
confine programs here: then nothing runs, never unconfined). Messages escape control characters,
lone surrogates and bidi overrides (sartco.text) before anything writes them; templates and
children die with their parent process. A second wall stands alone behind these (issue 42): the
template starts with an environment of three fixed variables, in new user, pid, net, ipc, uts and
mount namespaces (it is pid 1 there, on an empty read-only root, without capabilities), so a
program that got past the filter still sees no host process, file or network; `walls()` says which
walls hold on this machine.

Modules (each one's docstring has the details):
  allowed.py      the allowed subset as data: builtins, attribute names, node types and fields
  nodes.py        the check and instrumentation of each node type (rules and wraps)
  instrument.py   parse + check + instrument in one linear pass (pure): prepare(source)
  budget.py       the current program's budgets and stops, checked operators and builtins
  conversions.py  int/str/repr/ascii with budgets;  formatting.py  %, str.format, format(), f-strings
  methods.py      the methods a program may call per type, and the checked ones
  modules.py      the stand-in modules a program may import
  classes.py      ProgramClass: what a program's class may define and derive from
  records.py      class statements (build_class), dataclass (and fields), namedtuple, NamedTuple
  attributes.py   the one rule for `obj.name` (reads: $attr, writes: $fields)
  chance.py       random: CPython's generator, one per program
  arrays.py       numpy's arrays;  numpy_members.py  numpy's functions
  runtime.py      run one prepared program in its namespace() (a `__main__` module), map outcomes,
                  the answer a child sends (answer);  breach.py  the assume-breach tests' run
  namespaces.py   the paper protocol's namespace (the authors' exec: separate globals and locals;
                  the scorer's module registered in sys.modules, importable as the authors' was)
  json_module.py  the json stand-in (plain data, output counted against the length budget)
  confine.py      the kernel's walls: the seccomp filter (compiled by libseccomp) and rlimits;
                  the namespaces, empty root and dropped capabilities of the template
  walls.py        walls(): which walls hold on this machine (Wall(name, up, why)), summary()
  worker.py       the template process: one confined child per program, its end and answer
                  (mode "gold": the harness's own gold programs of a batch in one child)
  verdict.py      the parent decides: a child's end and put log -> Execution, the board replayed
  driver.py       the parent's side of one template: chunks, answers, the template's failures
  pool.py         LocalSandbox: templates, batching, restarts
  sandbox.py      the Sandbox interface (execute, execute_many, close), current(), use()
  execution.py    Limits, Execution; clean() for every message written
  compare.py      Comparison: ES, mismatch category, cell precision/recall/F1; judge()
  lines.py        one line of the `sartco execute` contract (parsed and answered inside the workers)
  serve.py        `sartco execute` (JSON lines; `sartco bench-execute`, sartco.bench_execute, measures it)

Semantics (`execute(..., semantics=PAPER)`, also execute_many): MODULE (the default, our protocol)
runs the program as a script's module; PAPER (the paper protocol) as the authors' scorer ran it,
`exec(code)` inside a function: separate globals and locals, `np`, `json`, `Counter`, `deepcopy`
bound without an import, `__name__` not "__main__", the board passed in is the one scored
(namespaces.py; json_module.py is the json stand-in).

`execute_many(programs, rows, cols, limits, workers=None)` runs a batch (split over up to two
template processes) in the sandbox in use (`current()`; `use(sandbox)` puts another Sandbox in
use: the games, the paper protocol, the probes, `sartco execute` and bench-execute all run
programs through these two functions); `shutdown()` kills the local templates (they restart on
the next call).
"""
from .compare import Comparison, compare, judge
from .execution import MODULE, PAPER, Execution, Limits
from .pool import LocalSandbox, shutdown
from .sandbox import Sandbox, current, execute, execute_many, use
from .walls import Wall, walls

__all__ = ["execute", "execute_many", "shutdown", "compare", "judge", "Execution", "Comparison", "Limits",
           "MODULE", "PAPER", "Sandbox", "LocalSandbox", "current", "use", "Wall", "walls"]
