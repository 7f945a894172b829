"""`sartco serve-reward` (sartco.reward.serve): OpenRLHF's remote reward request over HTTP, the
rewards of sartco.reward.score, a 400 naming the field for bad input. OpenRLHF's own client
calling it: tests/reward/test_trainers.py (`make test-train`)."""
from __future__ import annotations

import json
import threading
import urllib.error
import urllib.request

import pytest

from play_helpers import GAMES, fence
from sartco.cli import main
from sartco.reward import Episodes, score
from sartco.reward.dataset import rows_of
from sartco.reward.serve import RewardServer

SMOKE = GAMES / "cobot_instruct" / "in" / "instances_smoke.json"
ROWS = [r for r in rows_of(SMOKE) if r["turns"] == 1][:4]


def post(url: str, body: bytes) -> tuple[int, dict]:
    request = urllib.request.Request(url, data=body, headers={"Content-Type": "application/json"})
    try:
        with urllib.request.urlopen(request, timeout=60) as response:
            return response.status, json.loads(response.read())
    except urllib.error.HTTPError as exc:
        return exc.code, json.loads(exc.read())


def request_of(rows, answers) -> dict:
    prompts = [f"<|user|>\n{r['prompt'][0]['content']}\n<|assistant|>\n" for r in rows]
    return {"query": [p + a for p, a in zip(prompts, answers)], "prompts": prompts, "labels": [r["episode"] for r in rows]}


@pytest.fixture(scope="module")
def server():
    with RewardServer(reward="cell_f1") as running:
        yield running


def test_the_rewards_are_those_of_the_reward_api(server):
    gold = [fence(json.loads(r["episode"])["gold_code"]) for r in ROWS]
    answers = [g if k % 2 == 0 else "no code, sorry" for k, g in enumerate(gold)]
    status, got = post(server.url, json.dumps(request_of(ROWS, answers)).encode())
    results = score([(r["id"], a) for r, a in zip(ROWS, answers)], Episodes.from_rows(ROWS), probes=False)
    assert status == 200
    assert got == {"rewards": [r.cell_f1 for r in results], "scores": [r.cell_f1 for r in results],
                   "extra_logs": {"es": [float(r.es) for r in results], "cell_f1": [r.cell_f1 for r in results]}}
    assert got["extra_logs"]["es"] == [1.0, 0.0, 1.0, 0.0]


def test_concurrent_requests_each_get_their_own_reward(server):
    """OpenRLHF posts one request per rollout, many at once (the server scores those waiting together)."""
    gold = [fence(json.loads(r["episode"])["gold_code"]) for r in ROWS]
    jobs = [(k, row, gold[k % len(ROWS)] if k % 3 else "nothing") for k, row in enumerate(ROWS * 3)]
    got: dict[int, tuple[int, dict]] = {}

    def one(k, row, answer):
        got[k] = post(server.url, json.dumps(request_of([row], [answer])).encode())

    threads = [threading.Thread(target=one, args=job) for job in jobs]
    for thread in threads:
        thread.start()
    for thread in threads:
        thread.join(60)
    assert [got[k][0] for k, _, _ in jobs] == [200] * len(jobs)
    assert [got[k][1]["extra_logs"]["es"] for k, _, _ in jobs] == [[float(k % 3 > 0)] for k, _, _ in jobs]


@pytest.mark.parametrize("body, named", [
    (b"{not json", "the body is not JSON"),
    (b"[1, 2]", "must be a JSON object"),
    (json.dumps({"query": ["a"], "prompts": ["a"]}).encode(), "missing field(s) 'labels'"),
    (json.dumps({"query": "a", "prompts": ["a"], "labels": ["{}"]}).encode(), "'query' must be a list of strings"),
    (json.dumps({"query": ["a"], "prompts": ["a", "b"], "labels": ["x"]}).encode(), "differ in length (1, 2, 1)"),
    (json.dumps({"query": ["xa"], "prompts": ["a"], "labels": [ROWS[0]["episode"]]}).encode(),
     "query[0] does not start with prompts[0]"),
    (json.dumps({"query": ["ab"], "prompts": ["a"], "labels": ["<b>not an episode</b>"]}).encode(),
     "'labels': the episode column of sartco export-dataset expected"),
    (json.dumps({"query": ["ab"], "prompts": ["a"], "labels": ["{\"id\": 1}"]}).encode(), "no 'turns'"),
])
def test_bad_input_gets_400_naming_the_field(server, body, named):
    status, got = post(server.url, body)
    assert status == 400 and named in got["error"] and "\n" not in got["error"]


def test_another_path_is_404(server):
    status, got = post(server.url.replace("/get_reward", "/score"), b"{}")
    assert status == 404 and "POST /get_reward" in got["error"]


def test_a_port_in_use_is_one_line(server, capsys):
    port = server.url.rsplit(":", 1)[1].split("/")[0]
    assert main(["serve-reward", "--port", port]) == 2
    assert f"cannot listen on 127.0.0.1:{port}" in capsys.readouterr().err
