"""Headless Chromium for the tests that look at transcripts and reports as a reader does
(tests/games/instruct/test_transcript*.py, tests/games/test_score_card.py, test_leaderboard_view.py)."""
import os
import shutil
import subprocess
from pathlib import Path

import pytest


def chromium() -> str:
    found = shutil.which("chromium") or shutil.which("chromium-browser")
    if found is None:
        if os.environ.get("SARTCO_REQUIRE_BROWSER"):  # .ci/run installs Chromium: there it must run
            pytest.fail("SARTCO_REQUIRE_BROWSER is set but chromium is not on PATH")
        pytest.skip("chromium is not installed (apt-get install chromium; .ci/run does)")
    return found


def browse(browser: str, profile: Path, *args: str) -> subprocess.CompletedProcess:
    flags = ["--headless", "--no-sandbox", "--disable-gpu", "--disable-background-networking",
             "--disable-component-update", "--disable-sync", "--no-first-run", "--hide-scrollbars",
             f"--user-data-dir={profile}"]
    done = subprocess.run([browser, *flags, *args], capture_output=True, text=True, timeout=180)
    assert done.returncode == 0, done.stderr[-2000:]
    return done
