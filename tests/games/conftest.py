"""Play cobot_instruct episodes through clemcore's real loop (GameBenchmark, GameMasterEnv,
the sequential runner, the file-saving callbacks, the game's scorer) in-process."""
from __future__ import annotations

import pytest

from play_helpers import play


@pytest.fixture
def play_episodes(tmp_path):
    """play_episodes(instances, experiment, model="mock", game="cobot_instruct", gen_args=None)
    -> results per instance."""
    def _play(instances, experiment, model="mock", **kwargs):
        return play(instances, experiment, tmp_path / "results", model, **kwargs)
    return _play
