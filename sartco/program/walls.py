"""Which walls stand around a program's process on this machine (docs/sandbox.md, "The walls").

    from sartco.program import walls
    for wall in walls():          # Wall(name, up, why), frozen
        print(wall.name, wall.up, wall.why)
    summary(walls())              # "seccomp, rlimits, environment, user+pid+net+ipc+uts+mount namespaces"

Layer 1 (seccomp and rlimits, in every child) holds wherever a template starts: where it cannot,
no program runs at all, and both are down with the reason. The template's environment is the
parent's choice (handle.ENVIRONMENT) and always holds. Layer 2, the namespaces, is what the
template reported when it started (child/isolation.py): up, or down with the kernel's
refusal. walls() asks the local sandbox's first template, starting it if it is not running (a
fraction of a second); `sartco execute`, `sartco bench-execute`, run.json (`recorded()`) and
`sartco doctor` show it.
"""
from __future__ import annotations

from dataclasses import dataclass
from typing import TYPE_CHECKING

from .child import confine, isolation

if TYPE_CHECKING:
    from .handle import TemplateHandle

LIMITS = "address space, CPU time, no file size, 4 descriptors, no process, no core file"


@dataclass(frozen=True, slots=True)
class Wall:
    name: str
    up: bool
    why: str


def walls() -> tuple[Wall, ...]:
    """The walls of the local sandbox's templates (see the module docstring)."""
    from .handle import _Dead
    from .pool import local

    template = local().templates(1)[0]
    with template.lock:
        failure = ""
        if template.proc is None:
            try:
                template.start()
            except (_Dead, OSError, ValueError) as exc:
                template.kill()
                failure = str(exc).removeprefix("the sandbox cannot confine programs here: ")  # the reason itself
        return of(template, failure)


def of(template: TemplateHandle, failure: str = "") -> tuple[Wall, ...]:
    """The walls of a started template (`failure`: why it could not start)."""
    from .handle import ENVIRONMENT

    environment = ", ".join(f"{k}={v}" for k, v in ENVIRONMENT.items())
    first = (
        Wall("seccomp", not failure, failure or f"an allow-list of {len(confine.RULES)} syscalls that names their "
                                                f"arguments; any other call fails with EPERM"),
        Wall("rlimits", not failure, failure or LIMITS),
        Wall("environment", True, f"only {environment}: nothing of the user's"),
    )
    reported = {name: (up, why) for name, up, why in template.walls}
    second = tuple(Wall(f"{name} namespace", *reported.get(name, (False, failure or "not reported by the template")))
                   for name in isolation.CLONE)
    return first + second


def recorded() -> list[dict[str, object]] | None:
    """walls() for run.json when this machine's sandbox runs the programs; None when another
    sandbox is in use (its own machine's walls hold there)."""
    from .pool import LocalSandbox
    from .sandbox import current

    if not isinstance(current(), LocalSandbox):
        return None
    return [{"name": w.name, "up": w.up, "why": w.why} for w in walls()]


def summary(shown: tuple[Wall, ...]) -> str:
    """One line: the walls that hold, then those that do not with the first reason."""
    up = [w.name for w in shown if w.up and not w.name.endswith(" namespace")]
    spaces = [w.name.removesuffix(" namespace") for w in shown if w.up and w.name.endswith(" namespace")]
    if spaces:
        up.append("+".join(spaces) + " namespaces")
    down = [w for w in shown if not w.up]
    text = ", ".join(up) or "none"
    if down:
        text += f"; down: {', '.join(w.name for w in down)} ({down[0].why})"
    return text
