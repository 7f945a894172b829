"""Harness faults through clemcore's real loop (issue 21): each injected fault ends the episode as
`harness_error` with its reason in interactions.json / scores.json, Aborted (clemcore: not played),
Main Score NaN, the episode after it unharmed; `sartco report` counts it apart, leaves it out of
every score and exits with status 3."""
import argparse
import csv
import json

import pytest
from harness_helpers import fake_worker, no_worker

import sartco.clem.core.building as building
import sartco.clem.core.master as core_master
import sartco.scores as scores
from sartco.clem.core.outcomes import NoAnswer
from sartco.clem.players.sourced import SourcedPlayer
from sartco.games.describe.master import CobotDescribe
from sartco.games.instruct.master import CobotInstruct
from sartco.program import pool
from sartco.report import tables
from sartco.report.harness_table import HARNESS_STATUS

from play_helpers import GAMES
from episode_helpers import GOLD, SINGLE, instance, outcome
from play_helpers import fence
from paper_helpers import VARIANTS
from paper_helpers import experiment as paper_experiment, instances as paper_instances

FEEDBACK = dict(SINGLE, name="harness_feedback", attempts=3)
GAME_MASTERS = {"cobot_instruct": CobotInstruct, "cobot_describe": CobotDescribe}


@pytest.fixture
def fresh_pool():
    pool.shutdown()
    yield
    pool.shutdown()


def _harness(result, reason: str):
    s = result["scores"]["episode scores"]
    assert outcome(result["scores"]) == "aborted"
    assert (s["Error Category"], s["Error Family"]) == ("harness_error", "harness")
    assert s["Main Score"] is None and s["Execution Success"] is None  # NaN: not counted as 0
    assert reason in s["Harness Error"]
    return s


def _report(tmp_path, capsys):
    status = tables.run(argparse.Namespace(results=tmp_path / "results", out=tmp_path / "scores", game=None))
    return status, capsys.readouterr().err


def test_sandbox_unavailable(play_episodes, monkeypatch, fresh_pool, tmp_path, capsys):
    no_worker(monkeypatch, "the sandbox worker did not start")
    result, = play_episodes([instance(0, [fence("\n".join(GOLD))])], SINGLE)
    _harness(result, "sandbox unavailable: the sandbox worker did not start")
    record = result["interactions"]["sartco_build"]
    assert record["category"] == "harness_error" and "sandbox unavailable" in record["message"]
    assert result["interactions"]["Aborted"] == 1
    status, err = _report(tmp_path, capsys)
    assert status == HARNESS_STATUS and "1 harness error" in err
    harness = (tmp_path / "scores" / "harness.csv").read_text()
    assert "mock,cobot_instruct,1,1,sandbox: sandbox unavailable" in harness
    table3 = (tmp_path / "scores" / "table3.csv").read_text().splitlines()
    assert len(table3) == 1  # the header alone: no row scoring the model 0 for the harness's fault


def test_a_worker_that_answers_garbage_is_no_model_error(play_episodes, monkeypatch, fresh_pool):
    fake_worker(monkeypatch, "for _ in range(n): print('x', flush=True)")
    result, = play_episodes([instance(0, [fence("\n".join(GOLD))])], SINGLE)
    _harness(result, "garbled answer from the sandbox worker")


def test_exception_in_the_masters_build_step(play_episodes, monkeypatch, tmp_path, capsys):
    real = building.build

    def broken(code, *args, **kwargs):
        if "bridge" not in code:
            raise RuntimeError("build step bug")
        return real(code, *args, **kwargs)

    monkeypatch.setattr(building, "build", broken)
    results = play_episodes([instance(0, [fence(GOLD[0])]), instance(1, [fence("\n".join(GOLD))])], SINGLE)
    _harness(results[0], "game master: RuntimeError: build step bug")
    s = results[1]["scores"]["episode scores"]  # the next episode is played and scored as usual
    assert (outcome(results[1]["scores"]), s["Main Score"]) == ("success", 100.0)
    status, _ = _report(tmp_path, capsys)
    assert status == HARNESS_STATUS
    row = list(csv.DictReader((tmp_path / "scores" / "table3.csv").open()))[-1]
    assert [row[k] for k in ("episodes", "played", "em", "cb", "es")] == ["1", "100.0", "100.0", "100.0", "100.0"]  # the fault left out


def test_exception_inside_the_scorer(play_episodes, monkeypatch):
    def broken(*args):
        raise ZeroDivisionError("scorer bug")

    monkeypatch.setattr(scores, "exact_match", broken)
    result, = play_episodes([instance(0, [fence("\n".join(GOLD))])], SINGLE)
    s = _harness(result, "scorer: ZeroDivisionError: scorer bug")
    assert s["Success"] == 0 and s["Lose"] == 0 and s["Cell F1"] is None
    assert json.loads((result["dir"] / "scores.json").read_text().replace("NaN", "null"))  # written


def test_a_harness_fault_in_a_repair_episode_ends_it_without_feedback(play_episodes, monkeypatch, fresh_pool):
    no_worker(monkeypatch, "no worker")
    result, = play_episodes([instance(0, [fence(GOLD[0]), fence("\n".join(GOLD))])], FEEDBACK)
    _harness(result, "sandbox unavailable: no worker")
    turns = [e for t in result["interactions"]["turns"] for e in t]
    assert not any("failed with" in str(e["action"].get("content", "")) for e in turns)  # the model was told nothing


def test_a_program_that_exhausts_memory_stays_the_models(play_episodes):
    result, = play_episodes([instance(0, [fence("x = [[0] * 10**6 for i in range(1000)]")])], SINGLE)
    s = result["scores"]["episode scores"]
    assert outcome(result["scores"]) == "lose" and s["Error Category"] in ("resource_limit", "timeout")
    assert s["Main Score"] == 0.0 and "Harness Error" not in s


def test_cobot_describe_records_a_harness_fault(play_episodes, monkeypatch, fresh_pool):
    episodes = json.loads((GAMES / "cobot_describe" / "in" / "instances.json").read_text())["experiments"][0]
    experiment = {k: v for k, v in episodes.items() if k != "game_instances"}
    no_worker(monkeypatch, "no worker for the describe game")
    result, = play_episodes([episodes["game_instances"][0]], experiment, game="cobot_describe")
    _harness(result, "sandbox unavailable: no worker for the describe game")


def no_answer_first(monkeypatch, reason: str) -> None:
    """The first answer of the run is a NoAnswer (what sartco.clem.tooling.batching gives when the model
    server never answered); every later answer is the player's own."""
    real, calls = SourcedPlayer._custom_response, []

    def first_unanswered(self, context):
        calls.append(1)
        return NoAnswer(reason) if len(calls) == 1 else real(self, context)

    monkeypatch.setattr(SourcedPlayer, "_custom_response", first_unanswered)


def test_a_model_server_without_answer_is_no_model_error(play_episodes, monkeypatch, tmp_path, capsys):
    no_answer_first(monkeypatch, "model server: no answer after 3 tries in 6 s (timeout 2 s)")
    results = play_episodes([instance(0, [fence("\n".join(GOLD))]), instance(1, [fence("\n".join(GOLD))])], SINGLE)
    s = _harness(results[0], "model server: no answer after 3 tries in 6 s (timeout 2 s)")
    assert (s["Request Count"], s["Violated Request Count"]) == (1, 0)  # asked, but no violation charged
    turn = results[0]["interactions"]["turns"][0]
    assert [a["action"]["type"] for a in turn[:2]] == ["send message", "get message"]  # the turn is logged
    assert (outcome(results[1]["scores"]), results[1]["scores"]["episode scores"]["Main Score"]) == ("success", 100.0)
    status, err = _report(tmp_path, capsys)
    assert status == HARNESS_STATUS and "1 harness error" in err
    assert "model server: no answer after 3 tries" in (tmp_path / "scores" / "harness.md").read_text()


def test_cobot_describe_records_a_model_server_without_answer(play_episodes, monkeypatch):
    episodes = json.loads((GAMES / "cobot_describe" / "in" / "instances.json").read_text())["experiments"][0]
    experiment = {k: v for k, v in episodes.items() if k != "game_instances"}
    no_answer_first(monkeypatch, "model server: InternalServerError after 2 tries in 0 s (timeout 2 s)")
    result, = play_episodes([episodes["game_instances"][0]], experiment, game="cobot_describe")
    _harness(result, "model server: InternalServerError after 2 tries")


def test_the_paper_protocol_records_a_harness_fault(paper_episodes, play_episodes, monkeypatch, fresh_pool):
    ep = paper_episodes[VARIANTS[0]]
    no_worker(monkeypatch, "no worker for the paper protocol")
    result, = play_episodes(paper_instances([ep]), paper_experiment(ep, "harness_paper"),
                            game="cobot_instruct_paper")
    _harness(result, "sandbox unavailable: no worker for the paper protocol")
    assert "sartco_paper" not in result["interactions"]  # no turn scored 0 for the harness's fault


def test_score_responses_answers_a_harness_fault_with_an_error_line(monkeypatch, fresh_pool):
    from sartco.protocols.score import answer_line, score_ours

    episode = {"id": "f/s/single_turn", "protocol": "sartco", "file": "f", "sample": "s", "variant": "single_turn",
               "instance": dict(instance(0), turns=["build it"])}
    no_worker(monkeypatch, "no worker for score-responses")
    line = answer_line({"id": episode["id"], "responses": [fence("\n".join(GOLD))], "where": "-:1"},
                       {episode["id"]: episode}, score_ours)
    assert line == {"id": "f/s/single_turn", "error": "-:1: harness_error: sandbox: sandbox unavailable: "
                                                     "no worker for score-responses"}


@pytest.mark.parametrize("game", ["cobot_instruct", "cobot_describe"])
def test_a_fault_in_the_masters_setup_is_recorded_and_asks_no_model(play_episodes, monkeypatch, tmp_path, capsys,
                                                                     game):
    """clemcore drops an episode whose setup raised, without a file; ours is a harness_error episode."""
    episodes = json.loads((GAMES / game / "in" / "instances.json").read_text())["experiments"][0]
    experiment = {k: v for k, v in episodes.items() if k != "game_instances"}
    first, second = episodes["game_instances"][:2]
    master = GAME_MASTERS[game]
    real = master._on_setup

    def broken(self, **instance):
        if instance["game_id"] == first["game_id"]:
            raise RuntimeError("setup bug")
        return real(self, **instance)

    monkeypatch.setattr(master, "_on_setup", broken)
    ahead = []  # the episodes whose work ahead (gold draws) was started
    monkeypatch.setattr(core_master, "draw_ahead", lambda instance: ahead.append(instance["game_id"]))
    results = play_episodes([first, second], experiment, game=game)
    assert ahead == [second["game_id"]]  # none for an episode that plays no step
    _harness(results[0], "game master setup: RuntimeError: setup bug")
    played = results[0]["interactions"]
    assert played["sartco_build"]["category"] == "harness_error" and sum(played["Request Count"]) == 0
    assert {(e["from"], e["to"]) for turn in played["turns"] for e in turn} == {("GM", "GM")}  # no model asked
    assert outcome(results[1]["scores"]) == "success"  # the next episode is played as usual
    status, err = _report(tmp_path, capsys)
    assert status == HARNESS_STATUS and "1 harness error" in err
    assert "game master setup: RuntimeError: setup bug" in (tmp_path / "scores" / "harness.md").read_text()
