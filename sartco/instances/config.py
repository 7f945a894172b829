"""Dataset configs (resources/<version>.yaml): loaded, checked, frozen.

A mistake gives one line naming the file, the field and what was expected (UserError)."""
from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path
from typing import Any

import yaml

from sartco.dataset import BOARD_KINDS, REGULAR_COMPLEX, REGULAR_SIMPLE, SIMPLE, SPLITS
from sartco.errors import UserError
from sartco.world import COLORS

from .templates import resources_dir

FORMAT = "sartco-config/1"
SECTIONS = tuple(kind.key for kind in BOARD_KINDS)  # the config's per-kind sections: simple_simple, ...
REGULAR_SECTIONS = (REGULAR_SIMPLE.key, REGULAR_COMPLEX.key)
QUADRANTS = ("tl", "tr", "bl", "br")


@dataclass(frozen=True, slots=True)
class SplitSpec:
    size: int
    quadrants: tuple[str, ...]


@dataclass(frozen=True, slots=True)
class Config:
    path: str
    version: str
    colors: tuple[str, ...]
    seeds: tuple[str, ...]
    arrangements: dict[str, tuple[str, ...]]          # regular_simple / regular_complex -> names
    splits: dict[str, dict[str, SplitSpec]]           # board kind key -> split -> spec
    raw: dict[str, Any]                               # as read, for the manifest


def default_config_path() -> Path:
    return resources_dir() / "v1.yaml"


def load_config(path: str | Path | None = None) -> Config:
    path = Path(path) if path is not None else default_config_path()
    try:
        raw = yaml.safe_load(path.read_text(encoding="utf-8"))
    except OSError as exc:
        raise UserError(f"{path}: cannot read the config ({exc.strerror})") from None
    except yaml.YAMLError as exc:
        mark = getattr(exc, "problem_mark", None)
        where = f" at line {mark.line + 1}" if mark else ""
        raise UserError(f"{path}: not valid YAML{where}") from None
    return parse_config(raw, str(path))


def parse_config(raw: Any, path: str = "<config>") -> Config:
    def fail(field: str, expected: str, got: Any = ...) -> None:
        tail = "" if got is ... else f", got {got!r:.60}"
        raise UserError(f"{path}: field '{field}': expected {expected}{tail}")

    if not isinstance(raw, dict):
        fail("(top level)", "a mapping", raw)
    if raw.get("format") != FORMAT:
        fail("format", f"'{FORMAT}'", raw.get("format"))
    version = raw.get("version")
    if not isinstance(version, str) or not version or "/" in version:
        fail("version", "a non-empty name such as 'v1'", version)

    def names(field: str, value: Any, allowed=None) -> tuple[str, ...]:
        if not isinstance(value, list) or not value or not all(isinstance(v, str) for v in value):
            fail(field, "a non-empty list of names", value)
        if len(set(value)) != len(value):
            fail(field, "names without repeats", value)
        for v in value:
            if allowed is not None and v not in allowed:
                fail(field, f"names from {list(allowed)}", v)
        return tuple(value)

    colors = names("colors", raw.get("colors"), COLORS)
    seeds = names("seeds", raw.get("seeds"))
    templates = resources_dir() / "templates"
    for s in seeds:
        if not (templates / "code" / "simple" / f"{s}.j2").is_file():
            fail("seeds", f"seed names with a template in {templates / 'code' / 'simple'}", s)
    arr_raw = raw.get("arrangements")
    if not isinstance(arr_raw, dict) or set(arr_raw) != set(REGULAR_SECTIONS):
        fail("arrangements", f"a mapping with keys {' and '.join(REGULAR_SECTIONS)}", arr_raw)
    arrangements = {}
    for key in REGULAR_SECTIONS:
        arrangements[key] = names(f"arrangements.{key}", arr_raw[key])
        for a in arrangements[key]:
            if not (templates / "code" / "regular" / f"{a}.j2").is_file():
                fail(f"arrangements.{key}", f"arrangement names with a template in {templates / 'code' / 'regular'}", a)
    splits_raw = raw.get("splits")
    if not isinstance(splits_raw, dict) or set(splits_raw) != set(SECTIONS):
        fail("splits", f"a mapping with keys {', '.join(SECTIONS)}", splits_raw)
    splits: dict[str, dict[str, SplitSpec]] = {}
    for bt in SECTIONS:
        per = splits_raw[bt]
        if not isinstance(per, dict) or set(per) != set(SPLITS):
            fail(f"splits.{bt}", f"a mapping with keys {', '.join(SPLITS)}", per)
        splits[bt] = {}
        used: set[str] = set()
        for split in SPLITS:
            spec = per[split]
            field = f"splits.{bt}.{split}"
            if not isinstance(spec, dict) or "size" not in spec or set(spec) - {"size", "quadrants"}:
                fail(field, "a mapping with 'size' (and for simple boards 'quadrants')", spec)
            size = spec["size"]
            if type(size) is not int or size < 0:
                fail(f"{field}.size", "a non-negative integer", size)
            if bt == SIMPLE.key:
                quadrants = names(f"{field}.quadrants", spec.get("quadrants"), QUADRANTS)
                if used & set(quadrants):
                    fail(f"{field}.quadrants", "quadrants that no other split uses", list(quadrants))
                used |= set(quadrants)
            else:
                if "quadrants" in spec:
                    fail(f"{field}.quadrants", "nothing: regular boards start in the top-left corner", spec["quadrants"])
                quadrants = ("tl",)
            splits[bt][split] = SplitSpec(size, quadrants)
    return Config(path, version, colors, seeds, arrangements, splits, raw)
