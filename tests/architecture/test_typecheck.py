"""scripts/typecheck.py, the type check of `make lint`: mypy's errors per file against
scripts/mypy-baseline.txt, whose counts only shrink. (mypy itself runs in `make lint`, not here:
it takes a minute and a half.)"""
from __future__ import annotations

import importlib.util
from collections import Counter
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
_spec = importlib.util.spec_from_file_location("typecheck", ROOT / "scripts" / "typecheck.py")
typecheck = importlib.util.module_from_spec(_spec)
_spec.loader.exec_module(typecheck)

OUTPUT = """sartco/report/files.py:13: error: Function is missing a type annotation  [no-untyped-def]
sartco/report/files.py:21: error: Missing type arguments for generic type "dict"  [type-arg]
sartco/report/files.py:21: note: See https://mypy.rtfd.io
sartco/world/board.py:5: error: Name "x" is not defined  [name-defined]
Found 3 errors in 2 files (checked 151 source files)
"""


def test_errors_are_counted_per_file():
    assert typecheck.errors_per_file(OUTPUT) == Counter({"sartco/report/files.py": 2, "sartco/world/board.py": 1})


def test_more_errors_than_the_baseline_or_any_in_an_unlisted_file_fail():
    found = typecheck.errors_per_file(OUTPUT)
    over, under = typecheck.compare(found, {"sartco/report/files.py": 2})
    assert over == ["sartco/world/board.py: 1 errors, baseline 0"] and under == []
    over, under = typecheck.compare(found, {"sartco/report/files.py": 1, "sartco/world/board.py": 1})
    assert over == ["sartco/report/files.py: 2 errors, baseline 1"]


def test_fewer_errors_are_reported_so_the_baseline_shrinks(tmp_path):
    found = typecheck.errors_per_file(OUTPUT)
    over, under = typecheck.compare(found, {"sartco/report/files.py": 3, "sartco/world/board.py": 1, "sartco/cli.py": 2})
    assert over == [] and under == ["sartco/cli.py: 0 errors, baseline 2", "sartco/report/files.py: 2 errors, baseline 3"]
    typecheck.write_baseline(found, tmp_path / "baseline.txt")
    assert typecheck.read_baseline(tmp_path / "baseline.txt") == dict(found)


def test_settings_base_and_world_are_not_in_the_baseline():
    """settings, the base layer and world pass mypy's strict checks: none of their files is in the
    baseline. (sartco/program is strict too; its files' counts are listed while it is rewritten.)"""
    baseline = typecheck.read_baseline()
    strict = ("sartco/settings.py", "sartco/errors.py", "sartco/dataset.py", "sartco/episode.py", "sartco/text.py",
              "sartco/syntax.py", "sartco/world/")
    assert not [name for name in baseline if name.startswith(strict)]
