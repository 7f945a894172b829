"""The supported Pythons are stated once (pyproject's requires-python), said by the README, and
`make install` on another interpreter stops with one line naming the range and why (issue 44)."""
from __future__ import annotations

import os
import re
import subprocess
from pathlib import Path

REPO = Path(__file__).resolve().parents[2]


def test_make_install_on_python_3_13_stops_with_one_line(tmp_path):
    assert 'requires-python = ">=3.11,<3.13"' in (REPO / "pyproject.toml").read_text()
    assert "Python 3.11 or 3.12" in (REPO / "README.md").read_text()
    fake = tmp_path / "python3.13"
    fake.write_text("#!/bin/sh\necho 3.13\n")   # what the check asks an interpreter: its version
    fake.chmod(0o755)
    # a make of its own, also when the tests run under `make test` (no MAKELEVEL: no "make[1]:" lines)
    env = {k: v for k, v in os.environ.items() if k not in ("MAKELEVEL", "MAKEFLAGS", "MFLAGS")}
    done = subprocess.run(["make", "install", f"PYTHON={fake}", f"VENV={tmp_path / 'venv'}"], cwd=REPO,
                          capture_output=True, text=True, timeout=60, env=env)
    assert done.returncode != 0 and not (tmp_path / "venv").exists()
    [line] = [text for text in done.stderr.splitlines() if not re.match(r"make(\[\d+\])?: \*\*\*", text)]
    assert line == (f"make install: {fake} is Python 3.13; sartco-bench installs on Python 3.11 to 3.12 only "
                    "(pyproject.toml's requires-python: clemcore 3.7, which it runs on, declares <3.13 in every "
                    "release); give one: make install PYTHON=python3.11")
