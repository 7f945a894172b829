"""The data folder is one setting (sartco.settings): $SARTCO_DATA or `sartco --data DIR`, by default
../shared/sartco-data beside the checkout; a missing one is one line naming the setting."""
from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path

import pytest

from sartco import settings

REPO = Path(__file__).resolve().parents[2]
SHARED = REPO.parent / "shared" / "sartco-data"


def sartco(*args, env_data: str | None = None, cwd: Path = REPO) -> subprocess.CompletedProcess:
    env = {k: v for k, v in os.environ.items() if k != settings.ENV_DATA}
    if env_data is not None:
        env[settings.ENV_DATA] = env_data
    return subprocess.run([sys.executable, "-m", "sartco", *map(str, args)], cwd=cwd, env=env,
                          capture_output=True, text=True, timeout=300)


def test_the_checkout_defaults():
    assert settings.CHECKOUT == REPO
    assert settings.resources_dir() == REPO / "resources" and settings.GAMES == REPO / "games"
    if settings.ENV_DATA not in os.environ:
        assert settings.DATA == SHARED


@pytest.mark.parametrize("how", ["option", "environment"])
@pytest.mark.parametrize("command", [["export-prompts", "--protocol", "paper"], ["bench-execute", "--repeat", "1"]])
def test_a_missing_data_folder_is_one_line_naming_the_setting(tmp_path, how, command):
    missing = tmp_path / "no-such-data"
    done = sartco("--data", missing, *command) if how == "option" else sartco(*command, env_data=str(missing))
    assert done.returncode == 2 and done.stdout == ""
    assert len(done.stderr.strip().splitlines()) == 1, done.stderr
    assert str(missing) in done.stderr and "SARTCO_DATA" in done.stderr and "--data" in done.stderr


@pytest.mark.skipif(not (SHARED / "published").is_dir(), reason="shared data missing")
def test_the_data_option_points_anywhere(tmp_path):
    """The same data folder through a link elsewhere, named by --data or $SARTCO_DATA, gives the same
    prompts as the default, from a working folder that is not the checkout."""
    link = tmp_path / "elsewhere"
    link.symlink_to(SHARED)
    args = ["export-prompts", "--protocol", "paper", "--file", "sb_so_test_hc"]
    default = sartco(*args)
    by_option = sartco("--data", link, *args, cwd=tmp_path)
    by_env = sartco(*args, env_data=str(link), cwd=tmp_path)
    assert default.returncode == by_option.returncode == by_env.returncode == 0, by_option.stderr
    assert default.stdout == by_option.stdout == by_env.stdout and default.stdout.count("\n") == 260


def test_every_default_budget_is_the_settings_one():
    """One place for budgets: the sandbox's limits, an episode's attempts, probes, questions and
    corrections, and the batching backend's waits are sartco.settings' values where they apply."""
    from dataclasses import asdict

    from sartco.clem.core.feedback import max_attempts
    from sartco.clem.core.probes import DEFAULT_PROBES
    from sartco.games.describe.dialogue import settings_of
    from sartco.clem.tooling.batching import DEFAULTS
    from sartco.instancegen.options import DEFAULTS as GENERATION
    from sartco.program.execution import Limits

    assert asdict(Limits()) == {name.removeprefix("SANDBOX_").lower(): getattr(settings, name)
                                for name in dir(settings) if name.startswith("SANDBOX_")}
    assert max_attempts({"name": "e"}) == settings.ATTEMPTS and GENERATION["attempts"] == settings.FEEDBACK_ATTEMPTS
    assert DEFAULT_PROBES == settings.PROBES
    dialogue = settings_of({"name": "e", "mode": "clarify_correct"})
    assert (dialogue.questions, dialogue.corrections) == (settings.QUESTIONS, settings.CORRECTIONS)
    assert {k: DEFAULTS[k] for k in settings.MODEL_SERVER} == settings.MODEL_SERVER
