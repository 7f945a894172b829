"""Shared by every test folder. The test folders are no packages (pytest puts each test file's own
folder on sys.path); the helpers every folder uses live in tests/helpers/ (play_helpers,
paper_helpers, forkserver, ...), which this file puts on sys.path once, before any test module is
imported, so a test imports a helper by its bare name (`from play_helpers import play`) from any
folder, and the helpers import each other the same way. Tests share the fixtures below."""

import sys
from pathlib import Path

import pytest

HELPERS = str(Path(__file__).resolve().parent / "helpers")
if HELPERS not in sys.path:
    sys.path.insert(0, HELPERS)


@pytest.fixture(scope="session")
def episodes():
    """Every paper-protocol episode (1,950), built once (tests/paper, tests/protocols)."""
    from sartco.paper.episodes import build_episodes
    return build_episodes()


@pytest.fixture(scope="session")
def by_id(episodes):
    return {e.id: e for e in episodes}


# `make test` runs the tests on every core (pytest-xdist, `-n auto --dist loadfile`): each test
# file on one worker, so a file's module-scoped fixtures (a results folder several tests read)
# are built once. A worker takes the next file when its own is nearly done, so the files start
# longest first, that no long one is left to run alone at the end: LONGEST in its order (each
# file alone, `pytest -p no:xdist --durations=0`, README "The tests on both cores"), then the
# other files holding `slow` tests, then the rest as collected.
LONGEST = (
    "tests/packaging/test_wheel.py",
    "tests/docs/test_doc_commands.py",
    "tests/clem/test_backend_runs.py",
    "tests/clem/test_batching.py",
    "tests/cli/test_suite_own_models.py",
    "tests/games/instruct/test_end_to_end.py",
    "tests/packaging/test_local_model.py",
    "tests/clem/test_suite.py",
    "tests/clem/test_resume_settings.py",
    "tests/protocols/test_commands.py",
    "tests/games/instruct/test_outside_repo.py",
    "tests/instances/test_generate.py",
    "tests/instances/test_fresh.py",
    "tests/program/test_poisoning.py",
    "tests/program/test_walls.py",
    "tests/clem/test_probes.py",
    "tests/follower/test_follower.py",
    "tests/report/test_passk.py",
    "tests/clem/test_instance_checks.py",
    "tests/packaging/test_forkserver.py",
    "tests/instancegen/test_instance_command.py",
    "tests/games/describe/test_dialogue_turns.py",
    "tests/program/test_conformance.py",
    "tests/world/test_agreement.py",
    "tests/games/test_runs.py",
    "tests/cli/test_doctor.py",
    "tests/program/test_gold_conformance.py",
    "tests/clem/test_hostile_text.py",
)


def pytest_collection_modifyitems(config, items):
    slow_files = {item.nodeid.split("::")[0] for item in items if item.get_closest_marker("slow")}

    def rank(item):
        path = item.nodeid.split("::")[0]
        return LONGEST.index(path) if path in LONGEST else len(LONGEST) + (0 if path in slow_files else 1)

    items.sort(key=rank)  # stable: the collection order within each rank
