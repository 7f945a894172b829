"""pass@k (sartco.report.passk): the estimator against its closed form and brute force, the
report of a synthetic sample set, and `sartco sample` with the deterministic models (their
pass@k equals pass@1)."""
import csv
import json
import sys
from itertools import combinations
from math import prod

import pytest

from forkserver import command
from play_helpers import GAMES, REPO, sartco, stub_scratch
from report_helpers import write_results
from sartco.cli import main as sartco_main
from sartco.report.passk import pass_all_k, pass_at_k


@pytest.mark.parametrize("n,c,k", [(10, 3, 1), (10, 3, 5), (10, 3, 10), (6, 0, 5), (6, 6, 5), (20, 7, 5), (5, 2, 3)])
def test_pass_at_k_is_the_closed_form(n, c, k):
    # Chen et al. 2021's numerically stable form, and the share of k-subsets with a success
    assert pass_at_k(n, c, k) == pytest.approx(1 - prod(1 - k / i for i in range(n - c + 1, n + 1)))
    outcomes = [1] * c + [0] * (n - c)
    subsets = list(combinations(outcomes, k))
    assert pass_at_k(n, c, k) == pytest.approx(sum(any(s) for s in subsets) / len(subsets))
    assert pass_all_k(n, c, k) == pytest.approx(sum(all(s) for s in subsets) / len(subsets))
    assert pass_at_k(n, c, 1) == pytest.approx(c / n) == pass_all_k(n, c, 1)


def test_k_beyond_the_samples_is_nan():
    assert pass_at_k(3, 1, 5) != pass_at_k(3, 1, 5)


def test_report_of_a_synthetic_sample_set(tmp_path):
    # 3 samples of 4 episodes: successes per episode 3, 1, 0, 2 of 3
    per_sample = [[1, 1, 0, 0], [1, 0, 0, 1], [1, 0, 0, 1]]
    for k, es in enumerate(per_sample, 1):
        write_results(tmp_path / "results" / "samples" / f"s{k}", "A", es)
    assert sartco_main(["report", "-r", str(tmp_path / "results"), "--out", str(tmp_path / "out")]) == 0
    row = next(csv.DictReader((tmp_path / "out" / "passk.csv").open()))
    assert (row["episodes"], row["samples"]) == ("4", "3")
    assert float(row["pass@1"]) == 50.0                         # (3 + 1 + 0 + 2) / 12
    assert float(row["pass@3"]) == 75.0 and float(row["pass^3"]) == 25.0
    assert "pass@5" not in row                                  # k = 5 > N = 3 is left out


def sample(tmp_path, model: str, n: int, instances) -> dict:
    """`sartco sample` of `instances` (a cobot_instruct instance file's content), then the report's passk rows."""
    file = tmp_path / f"{model}_instances.json"
    file.write_text(json.dumps(instances))
    results = tmp_path / model
    done = command([sys.executable, "-m", "sartco", "sample", "-g", "cobot_instruct", "-m", model,
                    "-n", str(n), "-t", "0.7", "-i", str(file.with_suffix("")), "-r", str(results)],
                   cwd=REPO, timeout=600)
    assert done.returncode == 0, done.stderr[-2000:]
    assert sartco_main(["report", "-r", str(results), "--out", str(tmp_path / f"{model}_out")]) == 0
    return list(csv.DictReader((tmp_path / f"{model}_out" / "passk.csv").open()))


def smoke(experiments: int):
    data = json.loads((GAMES / "cobot_instruct" / "in" / "instances_smoke.json").read_text())
    data["experiments"] = data["experiments"][:experiments]
    return data


@pytest.mark.parametrize("model,n", [("mock", 3), ("rulebased", 2)])
def test_deterministic_models_have_pass_at_k_equal_to_pass_at_1(tmp_path, model, n):
    instances = smoke(2)
    if model == "mock":  # one failing episode, so that pass@1 is not 100 and pass@k could exceed it
        instances["experiments"][0]["game_instances"][0]["script"] = ["I cannot do that."]
    rows = sample(tmp_path, model, n, instances)
    assert len(rows) == 2 and all(r["samples"] == str(n) for r in rows)
    for r in rows:
        assert float(r[f"pass@{n}"]) == float(r[f"pass^{n}"]) == float(r["pass@1"])
    if model == "mock":
        assert float(rows[0]["pass@1"]) == 50.0 or float(rows[1]["pass@1"]) == 50.0


def test_harness_error_samples_are_left_out_and_fail_the_report(tmp_path):
    """`sartco sample` against a model server that never answers one episode (HTTP 500): its
    samples are harness errors, not the model's failures; pass@k is computed without them, says how
    many it left out, and `sartco report` exits 3 naming the resume that plays them again."""

    from sartco.clem.tooling import benchrun
    from sartco.clem.tooling.stub_server import StubServer, answer_table, conversation_key
    from sartco.report.harness_table import HARNESS_STATUS

    chosen = benchrun.select_instances(["rb_so_repetition_template", "sb_so_first_order_template"], 2)
    games = [i for e in chosen["experiments"] for i in e["game_instances"]]
    failing = frozenset({conversation_key(games[0]["turns"][:1])})   # rb_so_repetition_template game 0
    with StubServer(answer_table(games), latency=0.0, failing=failing) as server:
        stub_scratch(tmp_path, server.base_url, ["rb_so_repetition_template", "sb_so_first_order_template"],
                     retries=1, backoff=0.01)
        done = command([sys.executable, "-m", "sartco", "sample", "-g", "cobot_instruct", "-m", benchrun.MODEL,
                        "-n", "2", "-t", "0.7", "-b", "4", "-i", str(tmp_path / "instances_small"), "-r", "res"],
                       cwd=tmp_path, env=benchrun.clem_env(), timeout=600)
        assert done.returncode == 0, done.stderr[-2000:]
    report = sartco("report", "-r", "res", "--out", "out", cwd=tmp_path)   # in this process (play_helpers)
    assert report.returncode == HARNESS_STATUS, report.stderr[-2000:]
    assert ("pass@k: 2 harness error sample(s) left out (the harness failed, not the model); play them again: "
            "sartco resume -r res/samples/s1 -g cobot_instruct -m stub; sartco resume -r res/samples/s2 -g "
            "cobot_instruct -m stub") in report.stderr
    rows = {r["experiment"]: r for r in csv.DictReader((tmp_path / "out" / "passk.csv").open())}
    spoiled, whole = rows["rb_so_repetition_template"], rows["sb_so_first_order_template"]
    # every answered sample built its board: 100, not the 50 the failures of the server would make it
    assert (spoiled["harness_errors"], spoiled["samples"], spoiled["pass@1"], spoiled["pass^2"]) == ("2", "0", "100.0", "100.0")
    assert (whole["harness_errors"], whole["samples"], whole["pass@1"], whole["pass^2"]) == ("0", "2", "100.0", "100.0")
    assert (tmp_path / "out" / "passk.md").read_text().startswith("> 2 harness error sample(s) left out of pass@k")
