"""Shared by every test folder: pytest puts this folder on sys.path (rootdir conftest, no
packages), so tests import the helpers beside it (play_helpers, paper_helpers) and share the
fixtures below."""

import pytest


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
# are built once. The files start in this order, longest first, so that no long one is left to
# run alone at the end: the wheel in a fresh venv (minutes), then the files holding `slow` tests
# (clem runs end to end, browsers), then the rest as collected.
LONGEST = ("tests/packaging/test_wheel.py",)


def pytest_collection_modifyitems(config, items):
    slow_files = {item.nodeid.split("::")[0] for item in items if item.get_closest_marker("slow")}

    def rank(item):
        path = item.nodeid.split("::")[0]
        return 0 if path in LONGEST else 1 if path in slow_files else 2

    items.sort(key=rank)  # stable: the collection order within each rank
