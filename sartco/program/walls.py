"""The walls the sandbox can raise on this machine (`sartco doctor`): one record per wall, up or
not, and why. Provisional: seccomp and rlimits are up when a template can start confined (the
filter compiles, child/confine.compile_filter, and the template's self-test answers "ready"); they stand
or fall together, since the confined child takes both. The sandbox raises no namespaces yet.
"""
from __future__ import annotations

from dataclasses import dataclass


@dataclass(frozen=True, slots=True)
class Wall:
    name: str
    up: bool
    why: str


def _confined() -> str | None:
    """None when a template starts confined here, else why not."""
    from .child.confine import Unconfinable, compile_filter
    from .handle import TemplateHandle, _Dead

    try:
        compile_filter()
    except Unconfinable as exc:
        return str(exc)
    worker = TemplateHandle()
    try:
        worker.start()  # type: ignore[no-untyped-call]  # handle.py is not typed yet
    except _Dead as exc:
        return str(exc)
    finally:
        worker.kill()
    return None


def walls() -> tuple[Wall, ...]:
    why = _confined()
    held = "a confined template started: every program's process runs under it"
    return (Wall("seccomp", why is None, why or f"{held} (an allow-list of system calls)"),
            Wall("rlimits", why is None, why or f"{held} (memory, CPU, files, processes)"),
            Wall("namespaces", False, "this sandbox raises no namespaces yet"))
