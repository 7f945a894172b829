"""The game entry cobot_instruct_paper through clemcore's real loop (runner, game master,
sandbox, scorer) with mock and scripted answers, and `sartco report`'s paper table on the results."""
import argparse
import json

import pytest

from paper_helpers import PAPER_GAME as GAME
from paper_helpers import PAPER_SETTINGS, experiment, instances
from sartco.clem.core.transcript import display
from sartco.clem.tooling.completeness import INCOMPLETE_STATUS
from sartco.dataset import SHARED_DATA as DEFAULT_DATA

pytestmark = pytest.mark.skipif(not (DEFAULT_DATA / "published").is_dir(), reason="shared data missing")

def scores_of(result):
    return result["scores"]["episode scores"]


def paper_turns(result):
    return result["interactions"]["sartco_paper"]["turns"]


def test_mock_answers_the_authors_gold_es_1_em_0_on_functions(paper_episodes, play_episodes):
    eps = list(paper_episodes.values())
    results = play_episodes(instances(eps), experiment(eps[0], "paper_mock"), game=GAME, gen_args=PAPER_SETTINGS)
    for ep, result in zip(eps, results):
        s = scores_of(result)
        em = 1.0 if ep["variant"] == "multi_turn" else 0.0  # a def/for line never matches (the paper's EM 0)
        assert (s["Paper ES"], s["Paper CB"], s["Paper EM"]) == (1.0, 1.0, em), ep["variant"]
        assert (s["Main Score"], s["Aborted"], s["Success"], s["Lose"]) == (100.0, 0, 1, 0)
        assert s["Execution Success"] == 1 and s["Error Category"] == "success"  # our build of the same answers
        n = len(ep["messages"])
        assert len(paper_turns(result)) == n
        assert [result["scores"]["round scores"][str(k)]["Paper ES"] for k in range(n)] == [1] * n
        # every turn is the authors' user message, verbatim, and nothing else is sent
        sent = [e["action"] for t in result["interactions"]["turns"] for e in t if e["action"]["type"] == "send message"]
        assert [a["text"] for a in sent] == ep["messages"]
        assert [a["content"] for a in sent] == [display(m) for m in ep["messages"]]  # what transcripts show
        events = [e for t in result["interactions"]["turns"] for e in t if e["action"]["type"] == "paper_turn"]
        assert len(events) == n and events[0]["action"]["scores"]["reading"]


def test_an_answer_without_labels_or_without_code_is_read_never_aborted(paper_episodes, play_episodes):
    ep = paper_episodes["single_turn"]
    gold = ep["gold"][0]["function"]  # the gold function and its usage line, no labels, no fences
    scripts = [[gold], ["I am not sure how to write this."], [""]]
    results = play_episodes(instances([ep] * 3, scripts), experiment(ep, "paper_unlabelled"), game=GAME)
    plain, prose, empty = (scores_of(r) for r in results)
    assert paper_turns(results[0])[0]["reading"] == {"function": gold.strip(), "usage": ""}
    assert (plain["Paper ES"], plain["Paper EM"], plain["Main Score"], plain["Execution Success"]) == (1.0, 0.0, 100.0, 1)
    for s, result in ((prose, results[1]), (empty, results[2])):
        assert (s["Aborted"], s["Lose"], s["Paper ES"], s["Main Score"]) == (0, 1, 0.0, 0.0)
        assert s["Error Category"] == "parse_error"  # our parser found no code; the episode still counts
    assert paper_turns(results[1])[0]["category"] == "syntax_error"  # the prose was executed as the authors did
    assert paper_turns(results[2])[0]["category"] == "parse_error"  # an empty answer fails every metric


def test_one_wrong_turn_of_a_multi_turn_dialogue(paper_episodes, play_episodes):
    ep = paper_episodes["multi_turn"]
    n = len(ep["messages"])
    assert n >= 2
    script = list(ep["mock_answers"])
    script[1] = "Output\nput(board, 'washer', 'red', 9, 9)\n"
    [result] = play_episodes(instances([ep], [script]), experiment(ep, "paper_wrong_turn"), game=GAME)
    s = scores_of(result)
    assert s["Paper ES"] == pytest.approx((n - 1) / n) and s["Main Score"] == pytest.approx(100 * (n - 1) / n)
    assert (s["Aborted"], s["Lose"]) == (0, 1)
    turns = paper_turns(result)
    assert [t["es"] for t in turns] == [k != 1 for k in range(n)]
    assert turns[1]["category"] == "dimensions_mismatch" and turns[1]["em"] is False
    assert result["scores"]["round scores"]["1"]["Paper ES"] == 0
    assert (s["Execution Success"], s["Error Category"]) == (0, "dimensions_mismatch")  # our whole program fails


def test_a_while_loop_fails_the_paper_es_of_its_turn_but_not_ours(paper_episodes, play_episodes):
    ep = paper_episodes["regular"]
    answer = ep["mock_answers"][0] + "while False:\n    pass\n"
    [result] = play_episodes(instances([ep], [[answer]]), experiment(ep, "paper_while"), game=GAME)
    s = scores_of(result)
    [turn] = paper_turns(result)
    assert (turn["es"], turn["category"], turn["message"]) == (False, "forbidden", "While loop not supported")
    assert (s["Paper ES"], s["Main Score"], s["Aborted"]) == (0.0, 0.0, 0)
    assert s["Execution Success"] == 1  # our protocol allows while loops under the step budget


def _report(results_dir, out):
    from sartco.report import tables as report
    code = report.run(argparse.Namespace(results=results_dir, out=out, game=None))
    # the episodes are a slice of the paper's instance file: once `make main` generated that file
    # (games/cobot_instruct/in/instances_paper.json), the report rightly calls the run incomplete
    assert code == 0 or (code == INCOMPLETE_STATUS and (out / "completeness.md").exists())
    return (out / "paper_table3.md").read_text()


def test_report_puts_the_run_beside_the_papers_figures(paper_episodes, play_episodes, tmp_path, capsys):
    eps = [paper_episodes["multi_turn"], paper_episodes["regular_hai"]]
    cells = {"multi_turn": "paper_sb_so_first_order_template", "regular_hai": "paper_rb_so_repetition_human"}
    for ep in eps:
        results = play_episodes(instances([ep]), experiment(ep, cells[ep["variant"]]), game=GAME,
                                gen_args=PAPER_SETTINGS)
    results_dir = results[0]["dir"].parents[3]
    md = _report(results_dir, tmp_path / "scores")
    printed = capsys.readouterr().out
    assert "Table 3 in the paper protocol" in printed
    table3 = json.loads((DEFAULT_DATA / "paper-protocol" / "table3.json").read_text())
    first = [line for line in md.splitlines() if "first_order (multi_turn)" in line]  # EM, CB, ES tables
    paper = table3["cells"][0]["scores"]
    # EM, CB, ES, then ours beyond the paper: ES leak-free and FG (no paper figure; no probes here)
    assert len(first) == 5 and all(line.startswith("| template | simple | simple | first_order (multi_turn) | template | ")
                                   for line in first)
    for i, line in enumerate(first[:3]):
        assert line.endswith(" | " + " | ".join(f"{paper[m][i]:.2f}" for m in ("codellama", "gpt4", "claude")) + " | 1.00 |")
    assert first[3].endswith("| no figure | no figure | no figure | 1.00 |")
    assert first[4].endswith("| no figure | no figure | no figure | n/a |")
    human = [line for line in md.splitlines() if "repetition (regular_hai)" in line and " regular | simple |" in line]
    # mock: EM 0, CB 1, ES 1; its loop alone names a function it never defines (leak-free ES 0); FG 1
    assert [line[-8:] for line in human] == ["| 0.00 |", "| 1.00 |", "| 1.00 |", "| 0.00 |", "| 1.00 |"]
    assert "(!)" not in md
    assert "# SARTCo results (paper Table 3 layout)" in md  # the project-protocol table follows


def test_report_flags_a_run_with_other_generation_settings(paper_episodes, play_episodes, tmp_path):
    ep = paper_episodes["single_turn"]
    [result] = play_episodes(instances([ep]), experiment(ep, "paper_sb_so_optimal_function_template"), game=GAME,
                             gen_args={"temperature": 0.7, "max_tokens": 300})
    md = _report(result["dir"].parents[3], tmp_path / "scores")
    assert "| mock, paper protocol (!) |" in md
    assert "mock: run with temperature 0.7, max_tokens 300" in md


def test_the_generator_makes_one_experiment_per_cell_with_the_papers_settings():
    from pathlib import Path

    from sartco.games.instruct.instancegenerator import InstructFile, paper

    GAME_DIR = Path(__file__).resolve().parents[3] / "games" / "cobot_instruct"
    gen = InstructFile(GAME_DIR, paper)
    gen.on_generate(42, dataset_dir=GAME_DIR.parents[1] / "instances" / "v1")  # in memory: nothing written
    exps = {e["name"]: e for e in gen.instances["experiments"]}
    table3 = json.loads((DEFAULT_DATA / "paper-protocol" / "table3.json").read_text())
    assert len(exps) == 15 and sum(len(e["game_instances"]) for e in exps.values()) == 1950
    for cell in table3["cells"]:  # every Table 3 cell is an experiment (model-written: the CodeLlama files)
        board = {("simple", "simple"): "sb_so", ("regular", "simple"): "rb_so", ("regular", "complex"): "rb_co"}[
            cell["board"], cell["object"]]
        source = cell["instructions"] if cell["instructions"] != "model" else "codellama"
        exp = exps[f"paper_{board}_{cell['task']}_{source}"]
        assert (exp["protocol"], exp["variant"], exp["split"]) == ("paper", cell["variant"], "test")
        assert exp["generation"] == {"temperature": 0.0, "max_tokens": 250}
        if board == "rb_so":
            assert exp["examples_from"] == "published rb_so_train"
        else:  # the authors' sb_so_train / rb_cho_train were never published
            assert exp["examples_from"].startswith("generated v1 train split")
        inst = exp["game_instances"][0]
        assert inst["protocol"] == "paper" and inst["messages"] and len(inst["mock_answers"]) == len(inst["gold"])
        assert inst["target"] and inst["task"] == cell["task"]


def test_leak_free_es_runs_the_answer_without_the_gold_function(paper_episodes, play_episodes):
    ep = paper_episodes["regular"]
    gold = ep["mock_answers"][0]
    loop = gold.split("\n", 1)[1]  # the right usage loop, after the "Output" label
    name = ep["given_function"].split("(")[0].removeprefix("def ")
    misnamed = f"Output\ndef {name}_object(board, colors, x, y):\n    put(board, 'washer', 'red', 0, 0)\n" + loop
    wrong = f"Output\ndef {name}(board, colors, x, y):\n    put(board, 'washer', 'red', 0, 0)\n" + loop
    right = f"Output\n{ep['given_function']}\n" + loop
    scripts = [[gold], [misnamed], [wrong], [right]]
    results = play_episodes(instances([ep] * 4, scripts), experiment(ep, "paper_leak"), game=GAME)
    gold_s, misnamed_s, wrong_s, right_s = (scores_of(r) for r in results)
    # the usage is right, the function absent or wrong under another name: the gold function in
    # front makes the paper's ES pass; the answer alone calls a name it never defines
    for s in (gold_s, misnamed_s):
        assert (s["Paper ES"], s["Paper ES Leak-free"], s["Main Score"]) == (1.0, 0.0, 100.0)
    # a wrong function under the called name shadows the gold one: both fail; a right one: both pass
    assert (wrong_s["Paper ES"], wrong_s["Paper ES Leak-free"]) == (0.0, 0.0)
    assert (right_s["Paper ES"], right_s["Paper ES Leak-free"]) == (1.0, 1.0)
    # the probes call the function the loop calls: the given one unless the answer redefines it
    assert (gold_s["Function Generalisation"], gold_s["Probe Function"]) == (1.0, "given")
    assert (wrong_s["Function Generalisation"], wrong_s["Probe Function"]) == (0.0, "model")
    assert (right_s["Function Generalisation"], right_s["Probe Function"]) == (1.0, "model")


def test_paper_function_cells_are_probed_and_sequence_cells_are_not(paper_episodes, play_episodes):
    eps = [paper_episodes["single_turn"], paper_episodes["single_turn_sc"]]
    results = play_episodes(instances(eps), experiment(eps[0], "paper_probes"), game=GAME)
    optimal, sequence = (scores_of(r) for r in results)
    assert optimal["Function Generalisation"] == 1.0 and optimal["Probe Categories"] == ",".join(["success"] * 8)
    assert optimal["Paper ES Leak-free"] == optimal["Paper ES"] == 1.0  # no function given in front
    assert "Function Generalisation" not in sequence and "sartco_probes" not in results[1]["interactions"]
