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
