"""The sandbox's contract: a program that plain `exec` with the authors' names (`board`, `put`,
`init_board`, `np`) runs correctly, and that reaches nothing outside the task's world, builds the
same board here.

The corpus is tests/program/corpus (one program a file, of the kinds models write for the task);
tools/honest_corpus.py runs each program under plain exec (the oracle) and in the sandbox and
compares outcome and cells. A program listed in corpus/known_disagreements.json (name -> reason,
also listed in docs/sandbox.md) must still disagree, so that the list stays honest; every other program
must agree; the agreement over the whole corpus must be at least 0.97.
"""
import importlib.util
import sys
from pathlib import Path

import pytest

REPO = Path(__file__).resolve().parents[2]
_spec = importlib.util.spec_from_file_location("honest_corpus", REPO / "tools" / "honest_corpus.py")
honest_corpus = sys.modules["honest_corpus"] = importlib.util.module_from_spec(_spec)  # dataclasses look it up
_spec.loader.exec_module(honest_corpus)

PROGRAMS = honest_corpus.load()
KNOWN = honest_corpus.known()
NAMES = [name for name, _ in PROGRAMS]


@pytest.fixture(scope="module")
def results():
    return {r.name: r for r in honest_corpus.run(PROGRAMS)}


def test_corpus_is_big_distinct_and_agrees(results):
    assert len(PROGRAMS) >= 250
    assert len({source for _, source in PROGRAMS}) == len(PROGRAMS), "two programs of the corpus are the same"
    agree = sum(r.agrees for r in results.values())
    assert agree / len(results) >= 0.97, honest_corpus.report(list(results.values()), KNOWN)


def test_every_listed_disagreement_is_a_program_with_a_reason_in_the_docs():
    page = (REPO / "docs" / "sandbox.md").read_text(encoding="utf-8")
    for name, reason in KNOWN.items():
        assert name in NAMES, f"{name} is listed in known_disagreements.json but is not in the corpus"
        assert reason.strip() and "\n" not in reason, f"{name}: the reason must be one line"
        assert f"`{name}`" in page, f"{name} is a known disagreement but docs/sandbox.md does not list it"


@pytest.mark.parametrize("name", NAMES)
def test_honest_program_builds_what_plain_exec_builds(results, name):
    r = results[name]
    assert r.honest, f"not an honest program: {r.plain}"
    assert r.pieces, "every program of the corpus places something under plain exec"
    if name in KNOWN:
        assert not r.agrees, f"{name} agrees now: remove it from known_disagreements.json and docs/sandbox.md"
    else:
        assert r.agrees, r.detail


def test_the_oracle_tells_a_refusal_and_a_dishonest_program_apart():
    refused, dishonest, same = honest_corpus.run([
        ("refused", "import os\nput(board, 'washer', 'red', 0, 0)"),
        ("dishonest", "put(board, 'washer', 'red', 0, 0)\n{}['missing']"),
        ("same", "for y in {5, 1, 3}:\n    put(board, 'nut', 'blue', 0, y)"),
    ])
    assert refused.honest and not refused.agrees and refused.sandbox.startswith("forbidden")
    assert not dishonest.honest and "KeyError" in dishonest.plain
    assert same.agrees and same.pieces == 3
