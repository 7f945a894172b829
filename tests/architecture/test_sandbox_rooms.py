"""docs/sandbox.md's "The sandbox's rooms" is the one module map of sartco/program: every module is
in it, in the room (subpackage) it lives in, and nothing it names is missing."""
from __future__ import annotations

import re
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
PROGRAM = ROOT / "sartco" / "program"


def documented() -> set[str]:
    """The modules the rooms table names, as paths relative to sartco/program."""
    text = (ROOT / "docs" / "sandbox.md").read_text(encoding="utf-8")
    section = text[text.index("\n## The sandbox's rooms"):]
    section = section[:section.index("\nTo allow ")]
    out, room = set(), ""
    for row in section.splitlines():
        if not row.startswith("| ") or row.startswith("| room") or row.startswith("|---"):
            continue
        first, second = row.split("|")[1:3]
        if first.strip():
            found = re.match(r"\s*`([a-z_]+)/`", first)
            room = found[1] + "/" if found else ""
            if re.match(r"\s*`[a-z_]+\.py`", first):  # a module of the top room named in the first column
                out.update(re.findall(r"`([a-z_]+\.py)`", first))
        out.update(room + name for name in re.findall(r"`([a-z_]+\.py)`", second))
    return out


def test_every_module_of_the_sandbox_is_in_its_room():
    present = {str(p.relative_to(PROGRAM)) for p in PROGRAM.rglob("*.py") if p.name != "__init__.py"}
    assert documented() == present
