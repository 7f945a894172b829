"""A trainer's reading of a `clem serve` episode gets the final build's scores: clemcore's OpenEnv
app (the one `clem serve` runs) over cobot_instruct, driven over HTTP; the episode's last
observation carries ES, cell F1, the category and puts in its context (sartco.clem.core.building
CONTEXT_KEY), which the OpenEnv serialisation keeps (it drops the step info)."""
from __future__ import annotations

import json

import pytest

from play_helpers import GAMES, REPO
from sartco.clem.core.building import CONTEXT_KEY

INSTANCES = GAMES / "cobot_instruct" / "in" / "instances.json"


def wrong(code: str) -> str:
    """The code with its last red piece blue: a partly right board (mismatch_color)."""
    head, _, tail = code.rpartition("'red'")
    assert head, "the gold code has a red piece"
    return head + "'blue'" + tail


@pytest.fixture
def client(tmp_path, monkeypatch):
    from fastapi.testclient import TestClient
    from clemcore.clemgame.envs.openenv.server.app import create_clemv_app

    monkeypatch.chdir(REPO)  # clemcore finds the games from the working directory
    app = create_clemv_app("cobot_instruct", learner_agent="player_0", env_agents={}, gen_args={},
                           single_pass=True, results_dir=str(tmp_path / "records"), run_id="test")
    with TestClient(app) as c:
        yield c


def test_the_last_observation_of_a_served_episode_carries_the_scores(client):
    episode = json.loads(INSTANCES.read_text())["experiments"][0]["game_instances"][0]
    turns, gold = episode["turns"], episode["gold_turns"]
    assert len(turns) == 2  # a first_order episode: one instruction per turn
    first = client.post("/reset", json={}).json()
    assert first["observation"]["context"]["content"] == turns[0] and not first["done"]
    middle = client.post("/step", json={"action": {"response": f"```python\n{gold[0]}\n```"}}).json()
    assert not middle["done"] and CONTEXT_KEY not in middle["observation"]["context"]
    assert middle["observation"]["context"]["content"] == turns[1]
    last = client.post("/step", json={"action": {"response": f"```python\n{wrong(gold[1])}\n```"}}).json()
    assert last["done"] and last["reward"] == 0.0  # clemcore's outcome reward: lost
    scores = last["observation"]["context"][CONTEXT_KEY]
    assert scores["es"] == 0 and scores["error_category"] == "mismatch_color" and 0 < scores["cell_f1"] < 1
    assert scores["puts"] == len(gold[0].splitlines()) + len(gold[1].splitlines())
    assert last["observation"]["context"]["content"] == turns[1]  # the text the learner saw, unchanged
    assert "metadata" not in last["observation"] or not last["observation"]["metadata"]  # info is dropped
    again = client.post("/reset", json={}).json()  # the next episode starts without the old scores
    assert CONTEXT_KEY not in again["observation"]["context"]
