import pytest

from sartco.paper.episodes import build_episodes


@pytest.fixture(scope="session")
def episodes():
    """Every paper-protocol episode (1,950), built once."""
    return build_episodes()


@pytest.fixture(scope="session")
def by_id(episodes):
    return {e.id: e for e in episodes}
