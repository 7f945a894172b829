"""`sartco suite` (make main's driver) writes what `clem run`, `clem score`, `clem transcribe` and
`clem eval` write for the same game and model, and keeps main.sh's plan."""
from __future__ import annotations

import importlib.util
import os
import sys
from pathlib import Path

import pytest

from forkserver import command
from sartco import schedule, suite

REPO = Path(__file__).resolve().parents[2]
BIN = Path(sys.executable).parent


def _compare():
    spec = importlib.util.spec_from_file_location("compare_results", REPO / "scripts" / "compare_results.py")
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def test_the_plan_is_make_mains_order_of_runs():
    """The plays in the order clem eval added them to raw.csv (scripts/main.sh before the suite)."""
    tasks = suite.plan(["mock", "rulebased"], ["erring"], 7, "DATA")
    plays = [(t.game, t.model, t.settings) for t in tasks if t.kind == "play"]
    clem, paper = (0.0, 300), (0.0, 250)
    expected = [(g, m, clem) for m in ("mock", "rulebased") for g in
                ("cobot_instruct", "cobot_instruct_published", "cobot_describe", "cobot_describe_dialogue")]
    expected += [("cobot_instruct_fresh", "mock", clem), ("cobot_instruct_fresh", "rulebased", clem),
                 ("cobot_instruct_paper", "mock", paper), ("cobot_instruct_ablations", "mock", clem),
                 ("cobot_instruct_feedback", "mock", clem), ("cobot_instruct_feedback", "erring", clem),
                 ("cobot_describe_dialogue", "erring", clem)]
    assert plays == expected
    waits = {t.game: t.after for t in tasks if t.kind == "play"}
    assert waits["cobot_instruct_published"] == ("published instances",)
    assert waits["cobot_instruct_paper"] == ("paper instances",)
    assert waits["cobot_instruct"] == ()


def test_only_keeps_the_games_asked_for_and_what_they_wait_for():
    tasks = suite.only(suite.plan(["mock"], [], 7, "DATA"), ["cobot_instruct_published"])
    assert [t.name for t in tasks] == ["import", "published instances", "cobot_instruct_published (mock)"]
    with pytest.raises(Exception, match="cobot_nothing: not in the plan"):
        suite.only(suite.plan(["mock"], [], 7, "DATA"), ["cobot_nothing"])


def test_the_next_task_of_a_worker_is_of_the_group_it_played():
    a, b, c = (schedule.Task(f"t{n}", "play", game=g, group=g[0], index=n) for n, g in enumerate(["g1", "h2", "g3"]))
    assert schedule._pick([a, b, c], "h", set(), [a, b, c]) is b
    assert schedule._pick([a, b, c], None, {"g"}, [a, b, c]) is b
    assert schedule._pick([a, c], "x", {"g"}, [a, c]) is a          # two of the busy group wait: share them
    assert schedule._pick([c], "x", {"g"}, [c]) is None             # the busy group's last one: wait for it
    tasks = suite.plan(["mock"], ["erring"], 7, "DATA")
    groups = {t.game: t.group for t in tasks if t.kind == "play"}
    assert groups["cobot_describe_dialogue"] == groups["cobot_instruct"] == groups["cobot_instruct_feedback"]
    assert groups["cobot_instruct_fresh"] == groups["cobot_instruct_published"] != groups["cobot_instruct"]


def _run(args, cwd=REPO):
    env = {**os.environ, "PATH": f"{BIN}{os.pathsep}{os.environ['PATH']}"}
    return command([BIN / args[0], *args[1:]] if args[0] in ("clem", "sartco") else args, cwd=cwd, env=env,
                   timeout=900)


@pytest.mark.slow
def test_the_suite_writes_what_the_clem_commands_write(tmp_path):
    ours, theirs = tmp_path / "ours", tmp_path / "theirs"
    done = _run(["sartco", "suite", "-r", str(ours), "--out", str(tmp_path / "tables"), "-m", "rulebased", "erring",
                 "--erring", "-g", "cobot_instruct", "-i", "instances_smoke", "-j", "2"])
    assert done.returncode == 0, done.stdout + done.stderr
    assert "== cobot_instruct (erring): done in" in done.stdout
    for argv in (["clem", "run", "-g", "cobot_instruct", "-m", "rulebased", "-r", str(theirs), "-i", "instances_smoke"],
                 ["clem", "run", "-g", "cobot_instruct", "-m", "erring", "-r", str(theirs), "-i", "instances_smoke"],
                 ["clem", "score", "-r", str(theirs)], ["clem", "transcribe", "-r", str(theirs)],
                 ["rm", "-f", str(theirs / "raw.csv")],
                 ["clem", "eval", "-r", str(theirs), "-g", "cobot_instruct", "-m", "rulebased"],
                 ["clem", "eval", "-r", str(theirs), "-g", "cobot_instruct", "-m", "erring"]):
        step = _run(argv)
        assert step.returncode == 0, step.stdout + step.stderr
    compare = _compare()
    everything = {**compare.files(theirs)}
    assert set(compare.files(ours)) - {"main.log"} == set(everything) - {"clembench.log"}
    assert (ours / "rulebased" / "run.json").is_file() and (ours / "erring" / "run.json").is_file()
    places = ({ours.resolve(): b"<results>"}, {theirs.resolve(): b"<results>"})
    mine = compare.files(ours)
    differ = {name: why for name, path in everything.items() if name in mine
              for why in [compare.compare(name, mine[name], path, places,
                                          Path(name).name in ("scores.json", "raw.csv", "results.csv", "interactions.json"))]
              if why is not None}
    assert not differ, differ


def test_one_instance_file_for_every_game_needs_the_games(tmp_path):
    done = _run(["sartco", "suite", "-r", str(tmp_path), "-i", "instances_smoke"])
    assert done.returncode == 2 and "give the games with -g" in done.stderr


def test_a_results_folder_that_holds_a_run_of_the_plan_is_refused(tmp_path):
    (tmp_path / "rulebased" / "cobot_describe").mkdir(parents=True)
    done = _run(["sartco", "suite", "-r", str(tmp_path), "-m", "rulebased", "--erring", "-g", "cobot_describe"])
    assert done.returncode == 2
    assert "cobot_describe exists" in done.stderr and "make clean-results" in done.stderr


@pytest.mark.parametrize("dies", [False, True])
def test_the_tables_beside_the_report_fail_the_suite_when_they_fail(tmp_path, monkeypatch, capsys, dies):
    """clem eval's tables run in a forked process beside `sartco report`: an exception there, or a
    process that ends without a word, is exit 1 with a line that says so (never a hang)."""
    from sartco import cli
    from sartco.clem.tooling import evaluate

    def broken(results, pairs):
        if dies:
            os._exit(3)
        raise RuntimeError("no score files")

    monkeypatch.setattr(evaluate, "evaluate", broken)
    monkeypatch.setattr(cli, "main", lambda argv: 0)
    assert suite._tables(tmp_path, tmp_path / "scores", []) == 1
    out = capsys.readouterr().out.splitlines()
    if dies:
        assert out[0] == "== clem eval's tables: ended without a result (exit code 3)"
    else:
        assert out[0].startswith("== clem eval's tables (raw.csv, results.csv, results.html): exit 1 in ")
    assert out[1].startswith("== sartco report: exit 0 in ")
    if not dies:
        assert "RuntimeError: no score files" in (tmp_path / schedule.LOG).read_text()
