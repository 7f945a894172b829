"""The one Jinja2 environment of sartco.instances: templates under resources/templates/.

Strict (`StrictUndefined`): a template that names a missing variable fails at generation time,
never renders a blank. `keep_trailing_newline=True`: what a template file ends with is kept.
"""
from __future__ import annotations

from functools import lru_cache
from pathlib import Path

from jinja2 import Environment, FileSystemLoader, StrictUndefined

from sartco import settings

ORDINAL_SUFFIX = {1: "st", 2: "nd", 3: "rd"}


def resources_dir() -> Path:
    """resources/ of the checkout, or the package's copy (or $SARTCO_RESOURCES): sartco.settings."""
    return settings.resources_dir()


def ordinal(n: int) -> str:
    """1 -> "1st", 2 -> "2nd", 11 -> "11th" (1-based positions in instructions)."""
    suffix = "th" if 10 <= n % 100 <= 20 else ORDINAL_SUFFIX.get(n % 10, "th")
    return f"{n}{suffix}"


def _py(value) -> str:
    """Python source of a list/str/int, as the published code writes it: ['red', 'blue']."""
    return repr(list(value) if isinstance(value, tuple) else value)


def _pytuple(value) -> str:
    return repr(tuple(value))


def _pytuples(cells) -> str:
    return "[" + ", ".join(repr(tuple(c)) for c in cells) + "]"


@lru_cache(maxsize=None)
def environment(root: str | None = None) -> Environment:
    root = root or str(resources_dir() / "templates")
    env = Environment(loader=FileSystemLoader(root), undefined=StrictUndefined,
                      keep_trailing_newline=True, autoescape=False)
    env.filters.update(ordinal=ordinal, py=_py, pytuple=_pytuple, pytuples=_pytuples)
    return env


def render(template: str, /, **context) -> str:
    return environment().get_template(template).render(**context)

