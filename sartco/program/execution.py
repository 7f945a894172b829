"""One execution's records: Limits (its budgets, in) and Execution (what it did, out), frozen,
slotted and JSON-friendly; and the text rules every answer of the sandbox obeys (clean,
not_a_str). The comparison with a target is compare.py's."""
from __future__ import annotations

from dataclasses import dataclass, field

from sartco import settings
from sartco.text import one_line
from sartco.world import ErrorCode

# how a program's names are bound (namespaces.py): MODULE, a script's module namespace (our
# protocol); PAPER, the authors' exec(code) inside a function of their scorer (the paper protocol)
MODULE, PAPER = "module", "paper"
SEMANTICS = (MODULE, PAPER)


@dataclass(frozen=True, slots=True)
class Limits:
    """Budgets for one program. Exhausting one gives `timeout` (steps, wall time) or
    `resource_limit` (everything else).

    steps       loop iterations + function/lambda calls + comprehension items, counted by
                instrumentation (a C-level counter call inserted into every loop body,
                function body, lambda and comprehension)
    depth       nested Python calls the program may make (recursion)
    length      longest range / list / tuple / str / bytes a checked operation may create
    int_bits    largest integer (in bits) that `*`, `**` and `<<` may create
    wall_time   seconds per program, from the fork of its process: the template kills the
                process then (catches loops inside C code that no Python-level counter sees);
                its CPU time is capped at the wall time rounded up + 1 s (RLIMIT_CPU)
    memory      bytes of address space the program's process may add to the template's (RLIMIT_AS)
    source      characters of source text
    """

    steps: int = settings.SANDBOX_STEPS          # the defaults: sartco.settings, "Budgets"
    depth: int = settings.SANDBOX_DEPTH
    length: int = settings.SANDBOX_LENGTH
    int_bits: int = settings.SANDBOX_INT_BITS
    wall_time: float = settings.SANDBOX_WALL_TIME
    memory: int = settings.SANDBOX_MEMORY
    source: int = settings.SANDBOX_SOURCE

    def as_list(self) -> list:
        return [self.steps, self.depth, self.length, self.int_bits, self.wall_time, self.memory, self.source]


@dataclass(frozen=True, slots=True)
class Execution:
    """What running one program did. `cells` is the result board in canonical form, also when
    the program failed part way (the board so far); `puts` counts the pieces placed on it."""

    ok: bool
    error: ErrorCode | None
    message: str
    cells: dict = field(default_factory=dict)
    puts: int = 0


def not_a_str(program) -> str:
    """What is wrong with a program that is not a str (said by the parent and the worker alike)."""
    return f"the program must be a str, not {type(program).__name__}"


# every message the sandbox writes is one line with model text escaped (sartco.text's one rule)
clean = one_line
