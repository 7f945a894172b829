"""Play episodes through clemcore's real loop (GameBenchmark, GameMasterEnv, the sequential runner,
the file-saving callbacks, the game's scorer) in-process, for every test folder of tests/games;
the paper protocol's episodes."""
from __future__ import annotations

import pytest

import paper_helpers
from play_helpers import play


@pytest.fixture
def play_episodes(tmp_path):
    """play_episodes(instances, experiment, model="mock", game="cobot_instruct", gen_args=None)
    -> results per instance."""
    def _play(instances, experiment, model="mock", **kwargs):
        return play(instances, experiment, tmp_path / "results", model, **kwargs)
    return _play


@pytest.fixture(scope="module")
def paper_episodes():
    """The first episode of each paper-protocol variant kind (paper_helpers.VARIANTS), as
    PaperEpisode.to_json() dicts."""
    from sartco.paper.episodes import build_episodes
    eps = build_episodes(files=["sb_so_test", "sb_so_test_hc", "rb_so_test", "rb_so_test_hc"], variants=paper_helpers.VARIANTS)
    first = {}
    for ep in eps:
        first.setdefault(ep.variant, ep.to_json())
    assert list(first) == paper_helpers.VARIANTS
    return first
