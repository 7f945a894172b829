"""CPU time as the benchmarks and `sartco suite` report it."""
from __future__ import annotations

import resource


def cpu_seconds() -> float:
    """CPU seconds of this process and of its reaped children (the sandbox's templates and their
    children once restarted, the suite's workers once joined)."""
    own, kids = resource.getrusage(resource.RUSAGE_SELF), resource.getrusage(resource.RUSAGE_CHILDREN)
    return own.ru_utime + own.ru_stime + kids.ru_utime + kids.ru_stime
