"""Every answer is recorded, whatever it contains: lone surrogates, NUL and other control
characters, bidi overrides in a model's answer (and so in its code and the sandbox's messages)
through the real `clem run` process (sequential, clemcore's openai_compatible; batched `-b`,
openai_batching) against the local stub server, then `clem score` and `clem eval` (clemcore's
CLI in this process). Before, `-b 4` died at the first such answer and a sequential run lost
interactions.json and scores.json."""
import json
from pathlib import Path

import pytest

from play_helpers import clem, clem_process
from sartco.clem.players.sourced import fenced
from sartco.clem.tooling import benchrun
from sartco.clem.tooling.stub_server import StubServer, answer_table, conversation_key
from sartco.text import escape, exact_json

EXPERIMENT = "rb_so_repetition_template"  # single-turn: one request per episode
# answer k of the experiment's first episodes (None: the gold code as `mock` gives it)
HOSTILE = [
    lambda gold: fenced(gold + "\n# lone surrogate \ud800 in a comment"),        # runs as the gold
    lambda gold: "no code, just odd text \udfff\ud800 \x00 \x1b[31m \u202e",      # parse error
    lambda gold: fenced(gold + "\n# NUL \x00 and bidi \u202e override and \x07"),  # runs as the gold
    lambda gold: fenced(gold + "\nput(board, 'nut', '\ud800', 0, 0)"),             # a surrogate colour: a message
    None,
]


def strict_json(path: Path):
    return json.loads(path.read_bytes().decode("utf-8", errors="strict"))


@pytest.mark.slow
@pytest.mark.parametrize("backend,batch", [("openai_compatible", 1), ("openai_batching", 4)])
def test_odd_characters_lose_no_episode(tmp_path, backend, batch):
    instances = benchrun.select_instances([EXPERIMENT], len(HOSTILE))
    games = instances["experiments"][0]["game_instances"]
    answers = answer_table(games)
    sent = {}
    for game, make in zip(games, HOSTILE):
        key = conversation_key(game["turns"][:1])
        if make:
            answers[key] = make(game["gold_turns"][0])
        sent[game["game_id"]] = answers[key]
    instances_file = tmp_path / "instances_hostile.json"
    instances_file.write_text(json.dumps(instances), encoding="utf-8")
    folder, results = tmp_path / "run", tmp_path / "run" / "results"
    with StubServer(answers, latency=0.0, max_requests=50) as server:
        benchrun.write_scratch(folder, server.base_url, backend, 4)
        clem_process(["run", "-g", benchrun.GAME, "-m", benchrun.MODEL, "-b", str(batch), "-i",
                      str(instances_file.with_suffix("")), "-r", str(results)], folder)
    clem("score", "-g", benchrun.GAME, "-r", results)   # the same commands in this process
    clem("eval", "-r", results)

    for path in results.rglob("*.json"):
        strict_json(path)  # every file clemcore and we wrote is strict UTF-8 JSON
    episodes = {}
    for path in results.rglob("interactions.json"):
        episodes[strict_json(path)["meta"]["game_id"]] = (strict_json(path), strict_json(path.parent / "scores.json"))
    assert sorted(episodes) == sorted(sent)  # no episode lost
    for game_id, answer in sent.items():
        interactions, scores = episodes[game_id]
        got = [e["action"] for turn in interactions["turns"] for e in turn if e["action"]["type"] == "get message"]
        assert got[0]["text"] == escape(answer)  # escaped once, at the game master's entry
        if exact_json(answer):
            assert json.loads(got[0]["exact_json"]) == answer  # and the exact answer is recoverable
            assert "\\u" in got[0]["text"] or "\\x" in got[0]["text"]  # shown, not dropped
        else:
            assert "exact_json" not in got[0]
    main = {g: episodes[g][1]["episode scores"]["Main Score"] for g in sent}
    ids = list(sent)
    assert main[ids[0]] == main[ids[2]] == main[ids[4]] == 100.0  # a comment changes nothing
    assert episodes[ids[1]][1]["episode scores"]["Aborted"] == 1  # no code: aborted, and recorded
    build = episodes[ids[3]][0]["sartco_build"]
    assert not build["ok"] and "\\ud800" in build["message"]  # the sandbox's message, escaped alike
    assert (results / "results.csv").exists()  # clem eval ran over every episode
