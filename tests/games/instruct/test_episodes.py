"""Scripted answers through the real game loop (clemcore runner, game master, sandboxed
execution, scorer): each wrong answer ends with the right outcome and error category."""
from episode_helpers import GOLD, SINGLE, instance, outcome
from play_helpers import fence

WRONG = {
    # name: (answer, outcome, category)
    "missing code block": ("I would place the washer first and then the nut.", "aborted", "parse_error"),
    "syntax error": (fence("put(board, 'washer', 'red', 7, 3"), "lose", "syntax_error"),
    "bridge at the edge": (fence("put(board, 'bridge-h', 'yellow', 2, 7)"), "lose", "value_error"),
    "screw under a nut": (fence("put(board, 'screw', 'red', 7, 3)\nput(board, 'nut', 'blue', 7, 3)"),
                          "lose", "not_on_top_of_screw"),
    "wrong colours": (fence("\n".join(g.replace("'red'", "'green'") for g in GOLD)), "lose", "mismatch_color"),
    "shifted object": (fence("\n".join(g.replace(", 7, 3)", ", 6, 3)") for g in GOLD)), "lose", "mismatch_location"),
    "hostile program": (fence("import os\nos.system('touch /tmp/sartco_pwned')"), "lose", "forbidden"),
    "hostile dunder escape": (fence("().__class__.__base__.__subclasses__()"), "lose", "forbidden"),
    "endless loop": (fence("while True:\n    pass"), "lose", "timeout"),
}


def test_scripted_wrong_answers(play_episodes):
    names = list(WRONG)
    instances = [instance(i, [WRONG[n][0]]) for i, n in enumerate(names)]
    results = play_episodes(instances, SINGLE)
    for name, result in zip(names, results):
        _, expected_outcome, expected_category = WRONG[name]
        s = result["scores"]["episode scores"]
        assert (outcome(result["scores"]), s["Error Category"]) == (expected_outcome, expected_category), name
        if expected_outcome == "aborted":
            assert s["Main Score"] is None  # NaN in scores.json
            assert s["Violated Request Count"] == 1
        else:
            assert s["Main Score"] == 0.0 and s["Execution Success"] == 0
        # the transcript's board event carries the category and, after scoring, the picture
        board = [e for t in result["interactions"]["turns"] for e in t if e["action"]["type"] == "board"][-1]
        assert board["action"]["category"] == expected_category
        assert (result["dir"] / "boards.svg").is_file()


def test_mock_builds_the_target_single_and_multi_turn(play_episodes):
    results = play_episodes([instance(0), instance(1, turns=3)], dict(SINGLE, name="mock_gold"))
    for result in results:
        s = result["scores"]["episode scores"]
        assert (s["Main Score"], s["Exact Match"], s["CodeBLEU"], s["Error Category"]) == (100.0, 1, 1.0, "success")
        assert s["Puts"] == 3 and s["Cell F1"] == 1.0
    assert len(results[1]["interactions"]["turns"]) == 3  # one round per instruction


def test_multi_turn_parse_error_in_the_middle_aborts(play_episodes):
    script = [fence(GOLD[0]), "Sure, placing the nut now!", fence(GOLD[2])]
    [result] = play_episodes([instance(0, script, turns=3)], dict(SINGLE, name="multi_abort"))
    s = result["scores"]["episode scores"]
    assert outcome(result["scores"]) == "aborted" and s["Error Category"] == "parse_error"
    assert s["Main Score"] is None and s["Violated Request Count"] == 1


def test_repair_attempt_recovers(play_episodes):
    script = [fence("put(board, 'washer', 'green', 7, 3)\n" + "\n".join(GOLD[1:])), fence("\n".join(GOLD))]
    [result] = play_episodes([instance(0, script)], dict(SINGLE, name="repair", attempts=2))
    s = result["scores"]["episode scores"]
    assert outcome(result["scores"]) == "success" and s["Main Score"] == 100.0
    assert len(result["interactions"]["sartco_attempts"]) == 2


# The answer styles of real chat models (issue 16): each scores as the code inside it deserves.
CODE = "\n".join(GOLD)
GRID = "Row 8, Col 4: red washer, blue nut\nRow 3, Col 6-7: yellow bridge-h"
FUNCTION = "def build(board):\n" + "\n".join(f"    {g}" for g in GOLD)
STYLES = {
    # name: (answer, outcome, category, puts)
    "python block + text block": (f"```python\n{CODE}\n```\nResulting board:\n```text\n{GRID}\n```",
                                  "success", "success", 3),
    "python block + json block": (f"```python\n{CODE}\n```\n```json\n{{\"puts\": 3}}\n```", "success", "success", 3),
    "usage label outside the fence": (f"Function:\n```python\n{FUNCTION}\n```\nUsage: build(board)",
                                      "success", "success", 3),
    "inline usage outside the fence": (f"```python\n{FUNCTION}\n```\nCall it with `build(board)`.",
                                       "success", "success", 3),
    "inline code per line": ("**Output:**\n" + "\n".join(f"`{g}`" for g in GOLD), "success", "success", 3),
    "bold label + inline code, one put": (f"**Output:** `{GOLD[0]}`", "lose", "mismatch_location", 1),
    "function without usage": (f"```python\n{FUNCTION}\n```", "lose", "mismatch_location", 0),
    "text block only": (f"```text\n{GRID}\n```", "aborted", "parse_error", 0),
}


def test_answer_styles_score_as_their_code(play_episodes):
    names = list(STYLES)
    results = play_episodes([instance(i, [STYLES[n][0]]) for i, n in enumerate(names)], dict(SINGLE, name="styles"))
    got = {name: (outcome(r["scores"]), r["scores"]["episode scores"]["Error Category"],
                  r["scores"]["episode scores"]["Puts"]) for name, r in zip(names, results)}
    assert got == {name: tuple(expected) for name, (_, *expected) in STYLES.items()}
