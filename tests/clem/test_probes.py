"""Function probes (sartco.clem.core.probes): the model's function, found by the documented rule, run at
K held-out arguments in the sandbox and compared with the gold function's boards."""
from __future__ import annotations

import json
import os
import subprocess
import sys
from pathlib import Path

import pytest

from sartco.clem.core.probe_program import probed_function, without_usage
from sartco.clem.core.probes import DEFAULT_PROBES, NO_FUNCTION, probed, run_probes

INSTANCES = Path(__file__).resolve().parents[2] / "games" / "cobot_instruct" / "in" / "instances.json"


def first_episode(task: str, object_type: str = "simple") -> dict:
    for e in json.loads(INSTANCES.read_text())["experiments"]:
        ep = e["game_instances"][0]
        if ep["task"] == task and ep["object_type"] == object_type:
            return ep
    raise AssertionError(task)


@pytest.fixture(scope="module")
def optimal():
    ep = first_episode("optimal_function")
    assert ep["combo_name"] == "bn" and ep["target"] == {  # the answers below are written for it
        "4:3": [["bridge-v", "green"], ["nut", "red"]], "5:3": [["bridge-v", "green"]]}
    return ep


HARD_CODED = """def bn(board, colors, x, y):
    put(board, 'bridge-v', 'green', 4, 3)
    put(board, 'nut', 'red', 4, 3)
bn(board, ('green', 'red'), 4, 3)"""
GENERAL = """def bn(board, colors, x, y):
    put(board, 'bridge-v', colors[0], x, y)
    put(board, 'nut', colors[1], x, y)
bn(board, ('green', 'red'), 4, 3)"""


def test_a_hard_coding_function_passes_es_and_fails_every_probe(optimal):
    from sartco.clem.core.answer_builds import build_for
    assert build_for(optimal, HARD_CODED).es == 1
    result = run_probes(optimal, HARD_CODED)
    assert (result["function"], result["source"], result["share"]) == ("bn", "model", 0.0)
    assert len(result["probes"]) == DEFAULT_PROBES
    assert {p["category"] for p in result["probes"]} <= {"mismatch_location", "mismatch_color"}


def test_a_general_function_passes_es_and_every_probe(optimal):
    from sartco.clem.core.answer_builds import build_for
    assert build_for(optimal, GENERAL).es == 1
    result = run_probes(optimal, GENERAL)
    assert result["share"] == 1.0 and {p["category"] for p in result["probes"]} == {"success"}


def test_probe_arguments_are_held_out_valid_and_byte_identical_across_runs(optimal):
    a, b = run_probes(optimal, GENERAL), run_probes(optimal, GENERAL)
    assert json.dumps(a, sort_keys=True) == json.dumps(b, sort_keys=True)
    # another interpreter, another hash seed, no sandbox cache shared: the same bytes
    script = ("import json, sys; from sartco.clem.core.probes import run_probes; "
              "ep, code = json.load(sys.stdin); print(json.dumps(run_probes(ep, code), sort_keys=True))")
    other = subprocess.run([sys.executable, "-c", script], input=json.dumps([optimal, GENERAL]), text=True,
                           capture_output=True, env={**os.environ, "PYTHONHASHSEED": "123"}, check=True, timeout=300)
    assert other.stdout.strip() == json.dumps(a, sort_keys=True)
    args = [(tuple(p["colors"]), p["x"], p["y"]) for p in a["probes"]]
    assert len(set(args)) == len(args) and (("green", "red"), 4, 3) not in args
    for colors, x, y in args:
        assert len(colors) == 2 and colors[0] != colors[1]  # the nut lies on the bridge: two colours
        assert 0 <= x < 7 and 0 <= y < 8  # a vertical bridge needs the row below


def test_the_wrong_colour_order_and_a_crash_at_other_arguments_are_categorised(optimal):
    swapped = GENERAL.replace("colors[0], x, y)\n", "colors[1], x, y)\n", 1).replace(
        "'nut', colors[1]", "'nut', colors[0]").replace("('green', 'red')", "('red', 'green')")
    assert {p["category"] for p in run_probes(optimal, swapped)["probes"]} == {"mismatch_color"}
    crashing = GENERAL.replace("    put(board, 'bridge-v'", "    assert x == 4\n    put(board, 'bridge-v'")
    result = run_probes(optimal, crashing)
    assert result["share"] < 1.0
    assert {p["category"] for p in result["probes"] if p["x"] != 4} == {"runtime_error"}


def test_an_answer_without_a_function_gets_no_function_probes(optimal):
    result = run_probes(optimal, "put(board, 'bridge-v', 'green', 4, 3)\nput(board, 'nut', 'red', 4, 3)")
    assert result["function"] is None and result["share"] == 0.0
    assert {p["category"] for p in result["probes"]} == {NO_FUNCTION}


def test_the_rule_for_finding_the_function():
    given = "def bn(board, colors, x, y):\n    put(board, 'nut', colors[0], x, y)\n"
    helper = "def helper(a):\n    return a\ndef obj(board, colors, x, y):\n    helper(1)\n"
    assert probed_function(helper + "z = helper(2)\nobj(board, ['red'], 1, 1)") == "obj"  # board first
    assert probed_function("for r in range(2):\n    bn(board=board, colors=['red'], x=r, y=0)", given) == "bn"
    assert probed_function("bn(board, ['red'], 1, 1)", "") is None  # not defined in the program
    assert probed_function("def f(board):\n    bn(board, ['red'], 1, 1)", given) is None  # inside a def
    assert without_usage(helper + "obj(board, ['red'], 1, 1)\nx = 3", "obj") == helper + "x = 3"


def test_repetition_probes_the_function_the_loop_calls(optimal):
    rep = first_episode("repetition")
    gold = run_probes(rep, rep["gold_code"])
    assert (gold["function"], gold["source"], gold["share"]) == ("bn", "given", 1.0)
    own = "def bn(board, colors, x, y):\n    put(board, 'bridge-v', 'red', 0, 0)\n" + rep["gold_code"]
    result = run_probes(rep, own)
    assert (result["source"], result["share"]) == ("model", 0.0)  # the answer's def wins, as when it runs


def test_an_answers_probes_parse_its_code_once(optimal, monkeypatch):
    """An answer's probe programs parse its code once (probe_program keeps the last trees), and
    whose def the probed function is comes with the function itself (the kept `probed_call`): once
    they are made, reading the probes' verdicts parses nothing. Both readings come while the
    sandbox's cores wait for the parent (before a batch's first run, after its last)."""
    from sartco.clem.core import probe_program
    from sartco.clem.core.probes import gold_draws, probe_programs

    parsed: list[str] = []
    real = probe_program.parse
    monkeypatch.setattr(probe_program, "parse", lambda code: parsed.append(code) or real(code))
    answer = GENERAL + "\n# a text no other test parses"
    assert probe_programs(optimal, answer, gold_draws(optimal))[0] == "bn"
    assert parsed.count(answer) == 1  # the function, whose def it is and the usage to drop: one parse
    parsed.clear()
    result = run_probes(optimal, answer)
    assert (result["function"], result["source"]) == ("bn", "model")
    assert parsed == []


def test_which_episodes_are_probed(optimal):
    assert probed(optimal) and probed(first_episode("repetition", "complex"))
    assert not probed(first_episode("sequence_function")) and not probed(first_episode("first_order"))
    assert not probed({**optimal, "probes": 0})


def test_draws_started_at_setup_are_the_ones_the_step_uses(optimal, monkeypatch):
    """BuildGameMaster.setup starts a probed episode's gold draws on a background thread
    (draw_ahead): the step then waits for those draws instead of drawing, and they are the draws
    gold_draws makes itself. A draw that failed there is drawn again in the step."""
    import threading

    from sartco.clem.core import probes

    drew_in = []
    real = probes.draw_arguments

    def counted(*args, **kwargs):
        drew_in.append(threading.current_thread().name)
        return real(*args, **kwargs)

    monkeypatch.setattr(probes, "draw_arguments", counted)
    monkeypatch.setattr(probes, "_drawn", probes.OrderedDict())
    own = probes.gold_draws(optimal)   # drawn in the step, as without draw_ahead
    assert drew_in == ["MainThread"]
    monkeypatch.setattr(probes, "_drawn", probes.OrderedDict())
    probes.draw_ahead(optimal)
    probes.draw_ahead(optimal)   # once per episode
    ahead = probes.gold_draws(optimal)
    assert drew_in[1:] and all(name.startswith("sartco-ahead-setup") for name in drew_in[1:]) and len(drew_in) == 2
    assert json.dumps(ahead.draws) == json.dumps(own.draws) and ahead.function == own.function == "bn"

    def failing(*args, **kwargs):
        if threading.current_thread().name.startswith("sartco-ahead-setup"):
            raise probes.HarnessFault("sandbox (gold probe): the template died")
        return counted(*args, **kwargs)

    monkeypatch.setattr(probes, "draw_arguments", failing)
    monkeypatch.setattr(probes, "_drawn", probes.OrderedDict())
    probes.draw_ahead(optimal)
    assert json.dumps(probes.gold_draws(optimal).draws) == json.dumps(own.draws) and drew_in[-1] == "MainThread"
    probes.draw_ahead(dict(optimal, task="first_order"))   # an episode without probes: nothing drawn
    probes.draw_ahead({"task": "optimal_function"})   # nor for what is no episode
    assert not probes._ahead and len(drew_in) == 3


def test_a_plan_that_fails_at_setup_is_made_again_in_the_step(optimal, monkeypatch):
    """Whatever planning the draws raises at setup (CI once saw a spurious SystemError of
    CPython's parser there, and clemcore dropped the episode), the setup goes on and the step
    draws: work ahead never fails an episode."""
    from sartco.clem.core import probes

    want = json.dumps(probes.gold_draws(optimal).draws)
    real, calls = probes._plan, []

    def fails_once(*args):
        calls.append(args)
        if len(calls) == 1:
            raise SystemError("AST constructor recursion depth mismatch (before=168, after=30)")
        return real(*args)

    monkeypatch.setattr(probes, "_plan", fails_once)
    monkeypatch.setattr(probes, "_drawn", probes.OrderedDict())
    queued = len(probes._ahead)
    probes.draw_ahead(optimal)
    assert len(calls) == 1 and len(probes._ahead) == queued
    assert json.dumps(probes.gold_draws(optimal).draws) == want and len(calls) == 2


def test_draws_still_queued_at_exit_are_dropped(tmp_path):
    """An interrupted run exits at once: the draws its setups queued are not all made first (the
    drawer is a daemon thread, stopped before the sandbox shuts down)."""
    script = f"""
import json, sys
from sartco.clem.core import probes
real = probes.draw_arguments
def counted(*args, **kwargs):
    with open({str(tmp_path / "drawn")!r}, "a") as f:
        f.write("x")
    return real(*args, **kwargs)
probes.draw_arguments = counted
episodes = [ep for e in json.load(open({str(INSTANCES)!r}))["experiments"] for ep in e["game_instances"] if probes.probed(ep)]
for ep in episodes:
    probes.draw_ahead(ep)
print(len(probes._ahead))
"""
    done = subprocess.run([sys.executable, "-c", script], capture_output=True, text=True, timeout=300)
    assert done.returncode == 0, done.stderr
    queued = int(done.stdout)
    drawn = (tmp_path / "drawn").read_text() if (tmp_path / "drawn").exists() else ""
    assert queued > 50 and len(drawn) < queued // 2, (queued, len(drawn))


def test_a_process_forked_while_the_drawer_held_its_lock_draws(optimal):
    """A process forked (sartco suite's workers, clem eval's tables) while the parent's drawer
    held the draws' lock gets a lock of its own and a drawer of its own, and draws."""
    from fork_helpers import forked_while_held

    from sartco.clem.core import probes

    want = json.dumps(probes.gold_draws(optimal).draws)

    def draws() -> bool:
        probes._drawn.clear()
        probes.draw_ahead(optimal)
        return json.dumps(probes.gold_draws(optimal).draws) == want

    assert forked_while_held(probes._drawn_lock, draws) == 0   # the child's own sandbox starts: seconds
