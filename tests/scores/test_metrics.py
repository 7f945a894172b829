"""Exact match and CodeBLEU (sartco.scores.metrics)."""
from __future__ import annotations

import json
import logging
import os
import random
import subprocess
import sys
from pathlib import Path

import pytest
from hypothesis import given
from hypothesis import strategies as st

from sartco.scores import metrics
from sartco.scores.metrics import code_bleu, code_bleu_detail, exact_match, normalize_code

PUBLISHED = Path(__file__).resolve().parents[2].parent / "shared" / "sartco-data" / "published"

FIRST_ORDER = "board = init_board(8, 8)\nput(board, 'washer', 'red', 7, 3)\nput(board, 'nut', 'blue', 7, 3)"
OPTIMAL = (
    "def wn(board, colors, x, y):\n    shapes = ['washer', 'nut']\n"
    "    for shape, color, dx, dy in zip(shapes, colors, [0, 0], [0, 0]):\n"
    "            put(board, shape, color, x + dx, y + dy)\nboard = init_board(8, 8)\nwn(board, ('red', 'blue'), 7, 3)"
)
REPETITION = (
    "def bw(board, colors, x, y):\n    shapes = ['bridge-h', 'washer']\n"
    "    for shape, color, dx, dy in zip(shapes, colors, [0, 0], [0, 0]):\n"
    "            put(board, shape, color, x + dx, y + dy)\nboard = init_board(8, 8)\n"
    "for row in range(8):\n    for col in [0, 3, 6]:\n        bw(board, colors=['red', 'yellow'],x=row, y=col)"
)
HANDWRITTEN = [FIRST_ORDER, OPTIMAL, REPETITION,
               "board = init_board(8, 8)\nfor r in range(8):\n    put(board, 'screw', 'red', r, r)",
               "x = 1\ny = x + 2\nprint(y)", "put(board, 'nut', 'green', 0, 0)", "def f(:", "pass"]


def _gold_programs() -> list[str]:
    if not PUBLISHED.is_dir():
        return HANDWRITTEN
    programs = []
    for name in ("sb_so_test.json", "rb_so_test.json", "rb_cho_test.json"):
        data = json.loads((PUBLISHED / name).read_text())
        for objects in data.values():
            for counts in objects.values():
                for combos in counts.values():
                    for samples in combos.values():
                        for s in samples:
                            code = s["code"]
                            programs += [code[k]["total_code"] for k in ("multi_turn", "single_turn", "single_turn_sc")] \
                                if "multi_turn" in code else [code["total_code"], code["output"]]
    return programs


def _pairs(n: int, seed: int = 0) -> list[tuple[str, str]]:
    programs = _gold_programs()
    rng = random.Random(seed)
    pairs = [(rng.choice(programs), rng.choice(programs)) for _ in range(n)]
    # near misses, as models make them: a changed colour, a shifted coordinate, a missing line
    for gold in rng.sample(programs, min(n // 4, len(programs))):
        pairs += [(gold.replace("'red'", "'blue'"), gold), (gold.replace("7", "6"), gold),
                  ("\n".join(gold.splitlines()[:-1]), gold)]
    return pairs + [(a, b) for a in HANDWRITTEN for b in HANDWRITTEN]


# ---------------------------------------------------------------------------- exact match

@pytest.mark.parametrize("pred", [
    FIRST_ORDER, FIRST_ORDER + "\n", "\n\n" + FIRST_ORDER + "\n\n", FIRST_ORDER.replace("\n", "\r\n"),
    FIRST_ORDER.replace("\n", "   \n"), FIRST_ORDER.replace("\n", "\n\n"), FIRST_ORDER.replace("\n", "\t\n"),
])
def test_exact_match_forgives_line_ends_trailing_spaces_and_blank_lines(pred):
    assert exact_match(pred, FIRST_ORDER) == 1


@pytest.mark.parametrize("pred", [
    FIRST_ORDER.replace("'red'", '"red"'),           # quote style is code text
    FIRST_ORDER.replace(", 7", ",7"),                # so is spacing inside a line
    OPTIMAL.replace("            put", "        put"),  # and indentation
    FIRST_ORDER + "\n# done",                        # and comments
    FIRST_ORDER.replace("7, 3", "7, 4"), "", "board = init_board(8, 8)",
])
def test_exact_match_keeps_everything_else(pred):
    assert exact_match(pred, FIRST_ORDER) == 0


@given(st.text(alphabet=st.sampled_from(list("ab ()'\"\n\r\t=:")), max_size=40))
def test_exact_match_is_reflexive_and_ignores_added_blank_lines(text):
    assert exact_match(text, text) == 1
    assert exact_match("\n" + text.replace("\n", "\n\n") + "  \n", text) == 1
    assert normalize_code(normalize_code(text)) == normalize_code(text)


# ---------------------------------------------------------------------------- CodeBLEU

@pytest.mark.parametrize("gold", HANDWRITTEN[:4])
def test_a_gold_program_scores_one_against_itself(gold):
    assert code_bleu(gold, gold) == pytest.approx(1.0)


@pytest.mark.parametrize("pred", ["", "   ", "\n\n\t"])
def test_an_empty_prediction_scores_zero(pred):
    detail = code_bleu_detail(pred, FIRST_ORDER)
    assert detail.score == 0.0 and detail.reason == "empty prediction"


def test_bad_inputs_score_zero_with_a_reason():
    assert code_bleu_detail(None, FIRST_ORDER).score == 0.0  # type: ignore[arg-type]
    assert code_bleu_detail(FIRST_ORDER, "").reason == "empty gold code"


def test_an_exception_inside_codebleu_scores_zero_with_its_reason(monkeypatch):
    def broken(code):
        raise RuntimeError("parser exploded")

    monkeypatch.setattr(metrics, "_analyse", broken)
    metrics._code_bleu.cache_clear()
    detail = code_bleu_detail("put(board, 'nut', 'red', 0, 1)", FIRST_ORDER)
    metrics._code_bleu.cache_clear()
    assert detail.score == 0.0
    assert detail.reason == "codebleu failed: RuntimeError: parser exploded"


@pytest.mark.parametrize("pred", ["\x00\x01", "def f(:\n  '''", "(" * 500, "x = " + "+".join(["1"] * 300), "é ü 中文",
                                  "\n".join(f"put(board, 'nut', 'red', {i % 8}, 0)" for i in range(2000))],
                         ids=["control", "unclosed", "parens", "long-sum", "unicode", "2000-puts"])
def test_strange_answers_never_raise(pred):
    score = code_bleu(pred, OPTIMAL)
    assert 0.0 <= score <= 1.0


def test_a_pathologically_nested_answer_is_refused_quickly():
    import time

    start = time.perf_counter()
    detail = code_bleu_detail("x = " + "+".join(["1"] * 20000), OPTIMAL)
    assert time.perf_counter() - start < 2.0  # codebleu itself would need minutes and gigabytes
    assert detail.score == 0.0 and "too large or deeply nested" in detail.reason


def test_every_published_gold_program_is_far_below_the_size_budget():
    from tree_sitter import Parser

    parser = Parser()
    parser.language = metrics._resources().language
    for code in _gold_programs():
        metrics._check_size(parser.parse(code.encode()).root_node)  # raises TooLarge if not


def test_the_number_is_the_codebleu_package_number(monkeypatch):
    """Bit for bit `calc_codebleu([gold], [pred], "python", (0.25,) * 4)`, given the same order of
    the data-flow parent lists (codebleu leaves that order to the string hash seed; we sort)."""
    from codebleu import calc_codebleu, dataflow_match

    original = dataflow_match.normalize_dataflow
    monkeypatch.setattr(dataflow_match, "normalize_dataflow",
                        lambda flow: original([(d[0], d[1], d[2], sorted(d[3]), d[4]) for d in flow]))
    logging.disable(logging.WARNING)
    try:
        pairs = _pairs(150)
        for pred, gold in pairs:
            ours = code_bleu_detail(pred, gold)
            theirs = calc_codebleu([gold], [pred], "python", (0.25, 0.25, 0.25, 0.25))
            assert ours.score == theirs["codebleu"], (pred, gold)
            assert (ours.ngram, ours.weighted_ngram, ours.syntax, ours.dataflow) == (
                theirs["ngram_match_score"], theirs["weighted_ngram_match_score"],
                theirs["syntax_match_score"], theirs["dataflow_match_score"])
    finally:
        logging.disable(logging.NOTSET)


def test_memoised_and_fresh_results_agree():
    pairs = _pairs(20, seed=1)
    first = [code_bleu(p, g) for p, g in pairs]
    metrics._code_bleu.cache_clear()
    metrics._analyse.cache_clear()
    assert [code_bleu(p, g) for p, g in reversed(pairs)] == list(reversed(first))


def test_scores_do_not_depend_on_the_hash_seed(tmp_path):
    pairs = _pairs(120, seed=2)
    (tmp_path / "pairs.json").write_text(json.dumps(pairs))
    script = ("import json, sys\nfrom sartco.scores import code_bleu\n"
              "pairs = json.load(open(sys.argv[1]))\nprint(json.dumps([code_bleu(p, g) for p, g in pairs]))")
    outputs = set()
    for seed in ("1", "2", "3"):
        env = dict(os.environ, PYTHONHASHSEED=seed)
        done = subprocess.run([sys.executable, "-c", script, str(tmp_path / "pairs.json")],
                              env=env, capture_output=True, text=True, check=True)
        outputs.add(done.stdout)
    assert len(outputs) == 1
