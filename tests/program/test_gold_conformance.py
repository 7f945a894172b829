"""Every gold program of the published SARTCo files builds exactly the authors' board."""
from collections import Counter

import pytest

from sartco.program import execute_many
from sartco.dataset import SHARED_DATA as DEFAULT_DATA
from sartco.published.gold import gold_programs

pytestmark = pytest.mark.skipif(not (DEFAULT_DATA / "published").is_dir(), reason="shared data missing")


@pytest.fixture(scope="module")
def gold():
    return list(gold_programs())


def test_corpus_is_complete(gold):
    files = Counter(p.file for p in gold)
    assert len(files) == len(list((DEFAULT_DATA / "published").glob("*.json")))
    assert all(p.target is not None for p in gold), "every published file maps to a gold_boards file"
    assert len(gold) == 10_656  # 4,678 total_codes + 780 multi-turn dialogues + 5,198 single-turn editors


def test_every_gold_program_builds_the_gold_board(gold):
    results = execute_many([p.code for p in gold])
    wrong = [
        (p.file, p.sample, p.kind, ex.error, ex.message)
        for p, ex in zip(gold, results)
        if not ex.ok or ex.cells != p.target
    ]
    assert not wrong, f"{len(wrong)} of {len(gold)} differ, e.g. {wrong[:3]}"
    assert sum(ex.puts for ex in results) > 0
