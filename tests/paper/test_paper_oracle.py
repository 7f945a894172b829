"""An independent reference (oracle) of the paper-protocol README's reading and EM rules, written
from the README text alone, compared with sartco.paper on realistic answers of every style and
variant family; and the README's ES, CB and empty-answer rules on the same answers, scored end to
end through score_dialogue on published episodes.

The oracle shares no code with sartco.paper. Where the README is ambiguous it follows the
choices documented in sartco.paper.reading (the text after the first label: split(label, 1)).
"""
import pytest

from sartco.paper.reading import read_answer
from sartco.paper.scoring import exact_match, score_dialogue
from sartco.paper.vocabulary import VARIANTS


# ----------------------------------------------------------------------------- the oracle

def oracle_read(answer: str, variant: str) -> dict:
    """README "Reading an answer", rule by rule."""
    def after(label, missing):
        return answer.split(label, 1)[1].strip() if label in answer else missing

    def fences(text):
        return text.replace("```python", "").replace("```", "").strip()

    family = VARIANTS[variant].family
    if family == "single_turn":
        function = fences(after("Function", answer.strip()))
        usage = fences(after("Usage", ""))
        earlier = function
        if "Usage" in function:
            function = function.replace("Usage:", "") if "Usage:" in function else function.replace("Usage", "")
            function = function.strip()
            lines = function.split("\n")
            if lines[0] == ":":
                function = "\n".join(lines[1:])
        if "Function" in earlier:
            function = earlier.replace("Function", "")
        usage = usage.replace("Usage", "").strip()
        return {"function": function, "usage": usage}
    output = fences(after("Output", answer.strip()))
    if output[:1] == ":":
        output = output[1:].strip()
    return {"output": output}


def oracle_em(prediction: str, gold: str) -> bool:
    """README "Exact match (EM)" for one key: the prediction's non-empty stripped lines, each one
    containing ":" replaced by the text after its first ":" (stripped), equal the gold's non-empty
    stripped lines; an empty prediction fails. "After its first ':'" stops at a second ":": the
    README states the consequence that a `def ...:` / `for ...:` answer never matches, which
    only holds when a cut line cannot end in ":" (e.g. "Function: def f(x):" on one line)."""
    if not prediction:
        return False
    gold_lines = [line.strip() for line in gold.split("\n") if line.strip()]
    lines = [line.strip() for line in prediction.split("\n") if line.strip()]
    lines = [line.split(":")[1].strip() if ":" in line else line for line in lines]
    return lines == gold_lines


# ----------------------------------------------------------------------------- realistic answers

def multi_turn_answers(put: str) -> dict[str, str]:
    wrong = put.rsplit(",", 1)[0] + ", 0)" if not put.endswith(", 0)") else put.rsplit(",", 1)[0] + ", 1)"
    shape, color, x, y = put[len("put(board, "):-1].split(", ")
    keywords = f"put(board, shape={shape}, color={color}, x={x}, y={y})"
    return {
        "bare label": f"Output\n{put}",
        "label and colon": f"Output:\n{put}",
        "label and colon, same line": f"Output: {put}",
        "fenced after label": f"Output:\n```python\n{put}\n```",
        "fence around label": f"```\nOutput\n{put}\n```",
        "prose before and after": f"Sure! Here is the code for this step.\n\nOutput\n```python\n{put}\n```\nThis places the piece.",
        "prose line ending in a colon": f"Output\nHere is the code:\n{put}",
        "comment ending in a colon": f"Output\n# place the piece:\n{put}",
        "comment with text after the colon": f"Output\n# note: {put}",
        "no label": f"{put}\n",
        "no label, fenced": f"```python\n{put}\n```",
        "trailing semicolon": f"Output\n{put};",
        "trailing period": f"Output\n{put}.",
        "two trailing periods": f"Output\n{put}..",
        "CRLF line ends": f"Output\r\n{put}\r\n",
        "keyword arguments": f"Output\n{keywords}",
        "wrong coordinates": f"Output\n{wrong}",
        "continues with another example": f"Output\n{put}\n\nInstruction\nPlace a red nut on top.\n\nOutput\n{put}",
        "while loop": f"Output\ni = 0\nwhile i < 1:\n    {put}\n    i += 1",
        "label only": "Output\n",
        "label and colon only": "Output:",
        "prose only": "I am not sure what to place here.",
        "empty": "",
        "blank": "  \n ",
    }


def single_turn_answers(function: str, usage: str) -> dict[str, str]:
    assert "7" in function + usage
    return {
        "bare labels": f"Function\n{function}\n\nUsage\n{usage}\n",
        "labels with colons and fences": f"Function:\n```python\n{function}\n```\n\nUsage:\n```python\n{usage}\n```",
        "labels with colons, same line": f"Function: {function}\nUsage: {usage}",
        "prose, lower-case function, Usage label": f"Here is a function:\n```python\n{function}\n```\nUsage:\n```python\n{usage}\n```",
        "no labels, one fence": f"```python\n{function}\n{usage}\n```",
        "Function label, no Usage": f"Function\n{function}\n{usage}",
        "Function label with colon, no Usage": f"Function:\n{function}\n{usage}",
        "function without its call": f"Function\n{function}",
        "wrong coordinates": f"Function\n{function.replace('7', '6')}\n\nUsage\n{usage.replace('7', '6')}\n",
        "Usage with a colon only": f"Function\n{function}\n\nUsage:\n{usage}",
        "label word in a comment": f"Function\n{function}\n\nUsage\n# Usage example\n{usage}",
        "second Function label": f"Function\n{function}\n\nUsage\n{usage}\n\nInstruction\nBuild it again.\n\nFunction\n{function}",
        "while loop": f"Function\n{function}\n    while False:\n        pass\n\nUsage\n{usage}",
        "empty": "",
        "labels only": "Function\n\nUsage\n",
    }


def regular_answers(output: str, given: str) -> dict[str, str]:
    assert "'red'" in output
    return {
        "bare label": f"Output\n{output}",
        "fenced with colon": f"Output:\n```python\n{output}\n```",
        "function repeated in the answer": f"Output:\n{given}\n{output}",
        "prose around": f"Here is the loop.\nOutput\n```python\n{output}\n```\nEach row is filled.",
        "no label": f"```python\n{output}\n```",
        "other colour": f"Output\n{output.replace(chr(39) + 'red' + chr(39), chr(39) + 'green' + chr(39))}",
        "while loop": f"Output\nrow = 0\nwhile row < 8:\n    row += 1\n{output}",
        "empty": "",
    }


# expected (em, es) per answer style, derived from the README (CB: see below)
MULTI_TURN_EXPECTED = {
    "bare label": (True, True), "label and colon": (True, True), "label and colon, same line": (True, True),
    "fenced after label": (True, True), "fence around label": (True, True), "prose before and after": (False, False),
    "prose line ending in a colon": (False, False), "comment ending in a colon": (False, True),
    "comment with text after the colon": (True, False), "no label": (True, True), "no label, fenced": (True, True),
    "trailing semicolon": (False, True), "trailing period": (False, True), "two trailing periods": (False, False),
    "CRLF line ends": (True, True), "keyword arguments": (False, True), "wrong coordinates": (False, False),
    "continues with another example": (False, False), "while loop": (False, False), "label only": (False, False),
    "label and colon only": (False, False), "prose only": (False, False), "empty": (False, False), "blank": (False, False),
}
SINGLE_TURN_ES = {
    "bare labels": True, "labels with colons and fences": True, "labels with colons, same line": False,
    "prose, lower-case function, Usage label": False, "no labels, one fence": True, "Function label, no Usage": True,
    "Function label with colon, no Usage": False, "function without its call": False, "wrong coordinates": False,
    "Usage with a colon only": True, "label word in a comment": True, "second Function label": False,
    "while loop": False, "empty": False, "labels only": False,
}
REGULAR_ES = {"bare label": True, "fenced with colon": True, "function repeated in the answer": True,
              "prose around": False, "no label": True, "other colour": False, "while loop": False, "empty": False}


def _one(episodes, variant, file, n_turns=None):
    return next(e for e in episodes if e.variant == variant and e.file == file
                and (n_turns is None or len(e.gold) == n_turns))


def _cases(episodes):
    """(variant, style, answer, episode) for every style on an episode of every variant."""
    out = []
    for variant in VARIANTS:
        family = VARIANTS[variant].family
        e = next(e for e in episodes if e.variant == variant)
        gold = e.gold[0]
        if family == "multi_turn":
            styles = multi_turn_answers(gold["output"])
        elif family == "single_turn":
            function = gold["function"][: -len(gold["usage"]) - 1]
            styles = single_turn_answers(function, gold["usage"])
        else:
            styles = regular_answers(gold["output"], e.given_function)
        out += [(variant, style, answer, e) for style, answer in styles.items()]
    return out


def test_the_oracle_answers_cover_every_variant_and_the_issues_answer_kinds(episodes):
    cases = _cases(episodes)
    assert {v for v, *_ in cases} == set(VARIANTS)
    assert len(cases) == 1 * 24 + 5 * 15 + 3 * 8


def test_reading_agrees_with_the_oracle_on_every_answer_style(episodes):
    for variant, style, answer, _ in _cases(episodes):
        assert read_answer(answer, variant) == oracle_read(answer, variant), (variant, style)


def test_exact_match_agrees_with_the_oracle_on_every_answer_style(episodes):
    for variant, style, answer, e in _cases(episodes):
        prediction = oracle_read(answer, variant)
        for key, gold in e.gold[0].items():
            assert exact_match(prediction[key], gold) is oracle_em(prediction[key], gold), (variant, style, key)


@pytest.mark.parametrize("line", ["Here is the code:", "# place the piece:", "Step 1:"])
def test_em_a_line_that_ends_in_a_colon_stays_as_an_empty_line(line):
    put = "put(board, 'washer', 'red', 7, 3)"
    # README: the prediction's non-empty stripped lines, each with ":" cut to the text after its
    # first ":" -- the cut line is still one of those lines (empty), so it no longer matches
    assert oracle_em(f"{line}\n{put}", put) is False
    assert exact_match(f"{line}\n{put}", put) is False
    assert exact_match(f"{line} {put}", put) is True


def test_multi_turn_scores_of_every_answer_style(episodes):
    e = _one(episodes, "multi_turn", "sb_so_test", n_turns=2)
    for style, answer in multi_turn_answers(e.gold[0]["output"]).items():
        turn = score_dialogue([answer, e.mock_answers[1]], e).turns[0]
        assert (turn.em, turn.es) == MULTI_TURN_EXPECTED[style], style
        if not answer.strip() or not oracle_read(answer, "multi_turn")["output"]:
            assert not turn.cb, style                     # empty: fails all three
        if turn.es:
            assert turn.category is None
        if "while" in answer:
            assert turn.message == "While loop not supported"


@pytest.mark.parametrize("variant", [v for v, c in VARIANTS.items() if c.family == "single_turn"])
def test_single_turn_scores_of_every_answer_style(episodes, variant):
    e = next(e for e in episodes if e.variant == variant)
    gold = e.gold[0]
    function = gold["function"][: -len(gold["usage"]) - 1]
    for style, answer in single_turn_answers(function, gold["usage"]).items():
        turn = score_dialogue([answer], e).turns[0]
        assert turn.es is SINGLE_TURN_ES[style], (variant, style, turn)
        # every gold function starts with a def line: EM is 0 on every function cell
        assert turn.em is False, (variant, style)
        if not oracle_read(answer, variant)["usage"]:
            assert turn.cb is False, (variant, style)    # a missing or empty usage fails CB


@pytest.mark.parametrize("variant", [v for v, c in VARIANTS.items() if c.family == "regular"])
def test_regular_scores_of_every_answer_style(episodes, variant):
    e = next(e for e in episodes if e.variant == variant)
    for style, answer in regular_answers(e.gold[0]["output"], e.given_function).items():
        turn = score_dialogue([answer], e).turns[0]
        assert turn.es is REGULAR_ES[style], (variant, style, turn)
        assert turn.em is False, (variant, style)         # the gold's "for ...:" line never matches
        if style == "empty":
            assert (turn.cb, turn.category) == (False, "parse_error")


def test_a_multi_turn_episode_with_one_wrong_turn_scores_the_share_of_good_turns(episodes):
    e = _one(episodes, "multi_turn", "sb_so_test", n_turns=4)
    styles = [multi_turn_answers(g["output"]) for g in e.gold]
    answers = [styles[0]["label and colon"], styles[1]["fenced after label"], styles[2]["wrong coordinates"],
               styles[3]["prose line ending in a colon"]]
    s = score_dialogue(answers, e)
    assert [(t.em, t.es) for t in s.turns] == [(True, True), (True, True), (False, False), (False, False)]
    assert (s.em, s.es) == (0.5, 0.5)
    assert s.cb == sum(t.cb for t in s.turns) / 4


def test_em_is_zero_on_every_function_and_repetition_cell_even_with_the_label_on_the_def_line(episodes):
    # README: "This makes a `def ...:` or `for ...:` answer never match: the paper's EM of 0 on
    # every function cell comes from this" -- also for the gold code under labels with colons
    # on the same line, where the cut line would otherwise be the gold's def line itself
    for e in episodes:
        gold = e.gold[0]
        if VARIANTS[e.variant].family == "single_turn":
            function = gold["function"][: -len(gold["usage"]) - 1]
            answer = f"Function: {function}\nUsage: {gold['usage']}"
        elif VARIANTS[e.variant].family == "regular":
            answer = f"Output: {gold['output']}"
        else:
            continue
        assert score_dialogue([answer], e).em == 0, e.id


def test_em_cuts_a_line_between_its_first_and_second_colon():
    put = "put(board, 'washer', 'red', 7, 3)"
    assert exact_match(f"1: {put}", put) and exact_match(f"1: {put}: the washer", put)
    assert not exact_match("1: def f(board):", "def f(board):")


def test_score_responses_command_scores_every_answer_style_as_the_readme(capsys, monkeypatch, episodes):
    """`sartco score-responses --protocol paper` on every answer style of every variant, one line
    each (multi_turn: the style in the first turn, the gold answer in the others)."""
    import io
    import json

    from sartco.cli import main

    requests, expected = [], []
    for variant, style, answer, e in _cases(episodes):
        responses = [answer] + list(e.mock_answers[1:])
        requests.append({"id": e.id, "responses": responses})
        family = VARIANTS[variant].family
        if family == "multi_turn":
            em, es = MULTI_TURN_EXPECTED[style]
        else:
            em, es = False, (SINGLE_TURN_ES if family == "single_turn" else REGULAR_ES)[style]
        expected.append((variant, style, em, es, len(e.gold)))
    monkeypatch.setattr("sys.stdin", io.StringIO("".join(json.dumps(r) + "\n" for r in requests)))
    assert main(["score-responses", "--protocol", "paper"]) == 0
    out = [json.loads(line) for line in capsys.readouterr().out.splitlines()]
    assert len(out) == len(requests)
    for line, request, (variant, style, em, es, n) in zip(out, requests, expected):
        assert line["id"] == request["id"] and len(line["turns"]) == n, (variant, style)
        assert (line["turns"][0]["em"], line["turns"][0]["es"]) == (em, es), (variant, style)
        assert line["turns"][1:] == [{"em": True, "cb": True, "es": True, "category": None, "message": ""}] * (n - 1)
        assert line["es"] == (es + n - 1) / n and line["em"] == (em + (n - 1) * (variant == "multi_turn")) / n
        if not request["responses"][0].strip():
            assert line["turns"][0] == {"em": False, "cb": False, "es": False, "category": "parse_error",
                                        "message": "empty answer"}
