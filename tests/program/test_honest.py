"""The sandbox's contract: a program that plain `exec` with the authors' names (`board`, `put`,
`init_board`, `np`) runs correctly, and that reaches nothing outside the task's world, builds the
same board here.

Two corpora, one program a file, of the kinds models write for the task: tests/program/corpus
(straight puts, loops, helpers, classes, generators, numpy coordinates, ...) and
tests/program/modern (issue 43: programs in the style of recent models' answers, each built around
a construct of recent Python: match with every pattern kind, enum, abc, heapq, bisect, __slots__,
functools.cache and cache_info, OrderedDict.move_to_end, typing's ClassVar, Final, TypedDict,
Protocol and Generic, walrus, pairwise, zip(strict=True), `type(self).__name__`, ...), the
modern one under both semantics. tools/honest_corpus.py runs each program under plain exec (the
oracle: a script's module for MODULE; for PAPER the authors' exec with separate globals and
locals, where a Python error is an outcome too) and in the sandbox, and compares outcome and
cells. A program listed in a corpus's known_disagreements.json (name -> reason, also listed in
docs/sandbox.md) must still disagree, so that the list stays honest; every other program must
agree; the agreement over each corpus must be at least 0.97.
"""
import importlib.util
import sys
from pathlib import Path

import pytest

from sartco.program import MODULE, PAPER

REPO = Path(__file__).resolve().parents[2]
_spec = importlib.util.spec_from_file_location("honest_corpus", REPO / "tools" / "honest_corpus.py")
honest_corpus = sys.modules["honest_corpus"] = importlib.util.module_from_spec(_spec)  # dataclasses look it up
_spec.loader.exec_module(honest_corpus)

CORPORA = {"corpus": honest_corpus.CORPUS, "modern": REPO / "tests" / "program" / "modern"}
SMALLEST = {"corpus": 250, "modern": 140}
RUNS = [("corpus", MODULE), ("modern", MODULE), ("modern", PAPER)]
PROGRAMS = {corpus: honest_corpus.load(path) for corpus, path in CORPORA.items()}
KNOWN = {corpus: honest_corpus.known(path) for corpus, path in CORPORA.items()}


@pytest.fixture(scope="module")
def results():
    """(corpus, semantics) -> {name: Result}, each run once, when a test first asks for it."""
    done: dict = {}

    def of(corpus, semantics):
        if (corpus, semantics) not in done:
            done[corpus, semantics] = {r.name: r for r in honest_corpus.run(PROGRAMS[corpus], semantics)}
        return done[corpus, semantics]
    return of


@pytest.mark.parametrize("corpus,semantics", RUNS)
def test_corpus_is_big_distinct_and_agrees(results, corpus, semantics):
    programs = PROGRAMS[corpus]
    assert len(programs) >= SMALLEST[corpus]
    assert len({source for _, source in programs}) == len(programs), "two programs of the corpus are the same"
    got = results(corpus, semantics)
    agree = sum(r.agrees for r in got.values())
    assert agree / len(got) >= 0.97, honest_corpus.report(list(got.values()), KNOWN[corpus])


@pytest.mark.parametrize("corpus", CORPORA)
def test_every_listed_disagreement_is_a_program_with_a_reason_in_the_docs(corpus):
    page = (REPO / "docs" / "sandbox.md").read_text(encoding="utf-8")
    names = [name for name, _ in PROGRAMS[corpus]]
    for name, reason in KNOWN[corpus].items():
        assert name in names, f"{name} is listed in known_disagreements.json but is not in the corpus"
        assert reason.strip() and "\n" not in reason, f"{name}: the reason must be one line"
        assert f"`{name}`" in page, f"{name} is a known disagreement but docs/sandbox.md does not list it"


@pytest.mark.parametrize("corpus,semantics,name",
                         [(c, s, name) for c, s in RUNS for name, _ in PROGRAMS[c]])
def test_honest_program_builds_what_plain_exec_builds(results, corpus, semantics, name):
    r = results(corpus, semantics)[name]
    assert r.honest, f"not an honest program: {r.plain}"
    if semantics == MODULE:  # (under PAPER a main guard never runs, a function may not see `board`)
        assert r.pieces, "every program of the corpus places something under plain exec"
    if name in KNOWN[corpus]:
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


def test_the_paper_oracle_scores_the_board_passed_in_and_names_python_errors():
    """Under PAPER a rebound `board` is not the one scored, and a function that reads a
    top-level name fails there as under the authors' exec (NameError: name_error)."""
    rebound, scoping = honest_corpus.run([
        ("rebound", "put(board, 'washer', 'red', 0, 0)\nboard = init_board(8, 8)\nput(board, 'nut', 'red', 1, 1)"),
        ("scoping", "n = 3\ndef f():\n    return n\nput(board, 'washer', 'red', 0, 0)\nput(board, 'nut', 'red', f(), 0)"),
    ], PAPER)
    assert rebound.agrees and rebound.plain == "ok" and rebound.pieces == 1
    assert scoping.agrees and scoping.plain == "name_error" and scoping.pieces == 1
