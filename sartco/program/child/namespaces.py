"""The paper protocol's namespace: a program runs as the authors' scorer ran it (and our
protocol's `__main__`: script()).

The authors called `exec(code)` inside `_execute_instructions(instruction, board)`, a function of
their scorer module (../shared/sartco-data/paper-protocol/README.md, "How the authors ran a
program"). `paper(env, source)` turns the module namespace that runtime.run built into the two
dictionaries of `exec(code, globals, locals)`:
- globals: the scorer module's names: `put`, `init_board`, `np` (numpy; runtime.namespace binds it
  for our protocol too), `json`, `re`, `Counter`, `deepcopy` (each the sandbox's stand-in), `__name__` = MODULE_NAME (not "__main__", so an
  `if __name__ == "__main__":` block never runs); no `board`;
- locals: the function's `instruction` (the program text) and `board`.
So the program's top level sees both; its top-level assignments go to the locals (rebinding
`board` is lost: runtime.run scores the board object passed in); the functions it defines look
names up in the globals only (`board`, its own helpers and top-level variables are NameError
there, `put`, `np`, ... are not). `global x` writes the globals, as in the authors' scorer.

The scorer module's real name is not in the README; any name but "__main__" gives the same
verdicts. As the authors' module was, it is importable (sys.modules holds a module of that
name, SCORER): dataclasses looks a class's module up there to read string annotations
(`from __future__ import annotations`, `x: "int"`) and to make the methods it writes. It is an
empty module (dataclasses only asks it whether a name is typing's ClassVar or its own InitVar
or KW_ONLY, which no name of the authors' globals was), so those methods see Python's builtins
as under the authors' exec; no program can reach it (no import of it is allowed).

`re` stays refused (a pattern can backtrack in C code beyond every budget): its functions are
there and each refuses, naming why. The simulator's error classes are not bound (their names
are not in the README).
"""
from __future__ import annotations

import re as _re
import sys
import types
from typing import Any, NoReturn

from ..standins.budget import Forbidden
from ..standins.modules import REFUSED, load
from ..standins.standin import Module

MODULE_NAME = "cocobots_scorer"


class _RefusedFunction:
    """A function of a module the authors' namespace bound but the sandbox cannot offer."""

    __slots__ = ("name",)

    def __init__(self, name: str):
        self.name = name

    def __call__(self, *args: object, **kwargs: object) -> NoReturn:
        raise Forbidden(f"{self.name} is not available in the sandbox: {REFUSED[self.name.partition('.')[0]]}")

    def __repr__(self) -> str:
        return f"<{self.name}: not available in the sandbox>"


SCORER = sys.modules.setdefault(MODULE_NAME, types.ModuleType(MODULE_NAME, "the paper protocol's namespace"))
_RE = {name: _RefusedFunction(f"re.{name}") for name in _re.__all__ if name.islower()}


class _Script:
    """A script's module as sys.modules["__main__"] holds it: its names are the program's globals."""


def script(env: dict[str, Any]) -> tuple[dict[str, Any], dict[str, Any]]:
    """(globals, locals) of our protocol: one module namespace, `__main__` in sys.modules as a
    script's is (in the program's process only), so that dataclasses reads a string annotation
    (`from __future__ import annotations`: `x: ClassVar[int]`, `_: KW_ONLY`) in the program's
    names, as under plain exec."""
    main = _Script()
    main.__dict__ = env
    sys.modules["__main__"] = main  # type: ignore[assignment]
    return env, env


def paper(env: dict[str, Any], source: str) -> tuple[dict[str, Any], dict[str, Any]]:
    """(globals, locals) of the authors' exec, from runtime.run's module namespace `env`
    (which loses `board`: it moves to the locals)."""
    board = env.pop("board")
    env.update({
        # (np: runtime.namespace binds it, in both protocols)
        "__name__": MODULE_NAME, "json": load("json"), "re": Module("re", dict(_RE)),
        "Counter": vars(load("collections"))["Counter"], "deepcopy": vars(load("copy"))["deepcopy"],
    })
    return env, {"instruction": source, "board": board}
