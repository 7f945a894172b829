"""`sartco export-prompts` and `sartco score-responses` end to end, both protocols."""
import io
import json


from forkserver import command
from sartco.cli import main

from paper_helpers import ROOT


def run(capsys, monkeypatch, argv, stdin=""):
    monkeypatch.setattr("sys.stdin", io.StringIO(stdin))
    code = main(argv)
    out, err = capsys.readouterr()
    return code, [json.loads(line) for line in out.splitlines()], err


def lines(*items):
    return "".join((item if isinstance(item, str) else json.dumps(item, ensure_ascii=False)) + "\n" for item in items)


def test_export_prompts_paper_matches_the_library(capsys, monkeypatch, by_id):
    code, out, _ = run(capsys, monkeypatch, ["export-prompts", "--protocol", "paper", "--file", "sb_so_test",
                                             "--variant", "multi_turn"])
    assert code == 0 and len(out) == 130
    for item in out:
        assert set(item) == {"id", "protocol", "file", "sample", "variant", "messages"}
        e = by_id[item["id"]]
        assert (item["protocol"], item["file"], item["sample"], item["variant"], item["messages"]) == \
               ("paper", e.file, e.sample, e.variant, e.messages)


def test_score_responses_paper_on_every_mock_answer(capsys, monkeypatch, episodes):
    """The mock answers of all episodes: ES 1 everywhere, EM 0 on every function cell."""
    stdin = lines(*({"id": e.id, "file": e.file, "sample": e.sample, "variant": e.variant,
                     "responses": e.mock_answers} for e in episodes))
    code, out, _ = run(capsys, monkeypatch, ["score-responses", "--protocol", "paper"], stdin)
    assert code == 0 and [o["id"] for o in out] == [e.id for e in episodes]
    for o, e in zip(out, episodes):
        assert o["es"] == 1.0 and o["cb"] == 1.0, o["id"]
        assert o["em"] == (1.0 if e.variant == "multi_turn" else 0.0), o["id"]
        assert len(o["turns"]) == len(e.gold) and all(t["category"] is None for t in o["turns"])
        assert o["cell"] == e.cell


def test_score_responses_paper_malformed_lines_get_error_lines_in_place(capsys, monkeypatch, by_id, tmp_path):
    e = by_id["rb_so_test_mg/regular/simple/2/bw/0/regular_mg"]
    wrong = e.mock_answers[0].replace("[0, 3, 6]", "[0, 3]")
    stdin = lines(
        {"id": e.id, "responses": e.mock_answers},
        "{not json",
        "",                                                       # blank: skipped
        [1, 2],
        {"id": "rb_so_test/regular/simple/9/xx/0/regular", "responses": ["Output\nx"]},
        {"id": e.id, "responses": "Output\nx"},
        {"id": e.id, "file": "rb_so_test", "sample": e.sample, "variant": e.variant, "responses": []},
        {"file": e.file, "sample": e.sample, "variant": e.variant, "responses": [wrong]},
        {"id": e.id, "responses": [""]},
        {"id": e.id, "responses": ["a", "b"]},
        {"responses": ["x"]},
    )
    path = tmp_path / "more.jsonl"
    path.write_text(lines({"id": e.id, "responses": ["```python\nwhile True:\n    pass\n```"]},
                          {"id": e.id, "responses": ["Output\u2028" + e.gold[0]["output"]]}), encoding="utf-8")
    code, out, err = run(capsys, monkeypatch, ["score-responses", "--protocol", "paper", "-", str(path)], stdin)
    assert code == 0 and err == "" and len(out) == 12
    assert out[0]["es"] == 1.0 and out[0]["id"] == e.id
    assert "not valid JSON" in out[1]["error"] and out[1]["error"].startswith("stdin:2: ")
    assert out[3]["error"].startswith("stdin:5: ")   # the blank line 3 is skipped but counted
    assert "expected a JSON object" in out[2]["error"]
    assert "unknown episode id" in out[3]["error"] and out[3]["id"].startswith("rb_so_test/")
    assert "list of strings" in out[4]["error"] and out[4]["id"] == e.id
    assert "disagrees" in out[5]["error"]
    assert out[6]["id"] == e.id and out[6]["es"] == 0.0 and out[6]["turns"][0]["category"] == "mismatch_location"
    assert out[7]["turns"][0] == {"em": False, "cb": False, "es": False, "category": "parse_error", "message": "empty answer"}
    assert "2 responses for 1 turn" in out[8]["error"]
    assert '"id"' in out[9]["error"]
    assert out[10]["turns"][0]["category"] == "forbidden" and out[10]["turns"][0]["message"] == "While loop not supported"
    assert out[11]["id"] == e.id and out[11]["es"] == 1.0      # a U+2028 inside an answer does not end the line


def our_instances():
    data = json.loads((ROOT / "games" / "cobot_instruct" / "in" / "instances.json").read_text())
    return {e["name"]: e for e in data["experiments"]}


def test_export_prompts_sartco_sends_what_the_game_sends(capsys, monkeypatch):
    code, out, _ = run(capsys, monkeypatch, ["export-prompts", "--protocol", "sartco", "--file", "sb_so_first_order_template"])
    experiment = our_instances()["sb_so_first_order_template"]
    assert code == 0 and len(out) == len(experiment["game_instances"])
    for item, instance in zip(out, experiment["game_instances"]):
        assert item["id"] == f"sb_so_first_order_template/{instance['board_id']}/first_order"
        assert (item["file"], item["sample"], item["variant"]) == ("sb_so_first_order_template", instance["board_id"], "first_order")
        assert item["messages"] == instance["turns"]
    code, _, err = run(capsys, monkeypatch, ["export-prompts", "--protocol", "sartco", "--variant", "nope"])
    assert code == 2 and "unknown task(s) nope" in err


def test_score_responses_sartco(capsys, monkeypatch):
    experiments = our_instances()
    multi = experiments["sb_so_first_order_template"]["game_instances"][0]
    rep = experiments["rb_so_repetition_template"]["game_instances"][0]
    mid = f"sb_so_first_order_template/{multi['board_id']}/first_order"
    rid = f"rb_so_repetition_template/{rep['board_id']}/repetition"
    fenced = ["```python\n" + t + "\n```" for t in multi["gold_turns"]]
    stdin = lines(
        {"id": mid, "responses": fenced},
        {"id": rid, "responses": ["Output:\n" + rep["gold_turns"][0]]},
        {"id": mid, "responses": fenced[:1] + ["I am not sure."]},
        {"id": mid, "responses": [fenced[0], fenced[0]]},
        {"id": mid, "responses": fenced + ["x"]},
        "oops",
    )
    code, out, _ = run(capsys, monkeypatch, ["score-responses", "--protocol", "sartco"], stdin)
    assert code == 0 and len(out) == 6
    assert (out[0]["em"], out[0]["cb"], out[0]["es"], out[0]["f1"], out[0]["category"]) == (1, 1.0, 1, 1.0, "success")
    assert out[0]["turns"] == [{"em": True, "cb": 1.0, "es": True, "category": None}]
    assert out[1]["es"] == 1 and out[1]["em"] == 1          # ours: whole-program EM, labels and fences read by parse_code
    assert out[2]["aborted"] and out[2]["category"] == "parse_error" and out[2]["es"] == 0
    assert out[3]["es"] == 0 and out[3]["category"] != "success" and 0 < out[3]["f1"] < 1
    assert "responses for" in out[4]["error"]
    assert "not valid JSON" in out[5]["error"]


def test_bad_data_folder_is_one_line(capsys, monkeypatch, tmp_path):
    code, out, err = run(capsys, monkeypatch, ["export-prompts", "--protocol", "paper", "--data", str(tmp_path)])
    assert code == 2 and out == [] and err.count("\n") == 1 and "no published SARTCo files" in err
    code, out, err = run(capsys, monkeypatch, ["score-responses", "--protocol", "sartco", "--data", str(tmp_path)], "")
    assert code == 2 and "no instances.json" in err


def test_export_is_byte_identical_across_processes_and_hash_seeds():
    import os
    import subprocess
    import sys
    outputs = []
    for seed in ("1", "2"):
        env = {**os.environ, "PYTHONHASHSEED": seed}
        done = subprocess.run([sys.executable, "-m", "sartco", "export-prompts", "--protocol", "paper",
                               "--file", "sb_so_test_hc", "--file", "rb_cho_test"],
                              capture_output=True, env=env, cwd=ROOT, check=True)
        outputs.append(done.stdout)
    assert outputs[0] == outputs[1] and outputs[0].count(b"\n") == 3 * 130


def test_score_responses_with_odd_characters_is_strict_utf8_and_scores_as_clem_does():
    """A lone surrogate or NUL in a response (or its id) gives one strict UTF-8 line each, and the
    answer is read as the game master reads it (escaped: a comment stays a comment)."""
    import sys
    rep = our_instances()["rb_so_repetition_template"]["game_instances"][0]
    rid = f"rb_so_repetition_template/{rep['board_id']}/repetition"
    odd = "```python\n" + rep["gold_turns"][0] + "\n# \ud800 \x00 \u202e\n```"
    requests = [{"id": rid, "responses": [odd]}, {"id": "nope/\ud800/x", "responses": ["\ud800"]}]
    stdin = "".join(json.dumps(r) + "\n" for r in requests)  # ASCII JSON: the surrogates as \ud800 escapes
    done = command([sys.executable, "-m", "sartco", "score-responses", "--protocol", "sartco"],
                   input=stdin.encode(), capture_output=True, text=False, cwd=ROOT)
    assert done.returncode == 0, done.stderr.decode(errors="replace")[-500:]
    out = [json.loads(line) for line in done.stdout.decode("utf-8", errors="strict").splitlines()]
    assert out[0]["es"] == 1 and out[0]["category"] == "success"
    assert "error" in out[1] and "\\ud800" in out[1]["id"]
