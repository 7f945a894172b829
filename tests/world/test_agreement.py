"""tools/world_agreement.py: its model of the authors' simulator builds the authors' gold boards,
and our world gives the authors' category on every mutant that meets none of their documented
defects (the published simple boards; the tool adds the generated ones)."""
import importlib.util
import json
from pathlib import Path

import pytest

from sartco.dataset import SHARED_DATA as DEFAULT_DATA
from sartco.published.files import read_samples

REPO = Path(__file__).resolve().parents[2]
_spec = importlib.util.spec_from_file_location("world_agreement", REPO / "tools" / "world_agreement.py")
world_agreement = importlib.util.module_from_spec(_spec)
_spec.loader.exec_module(world_agreement)

pytestmark = pytest.mark.skipif(not (DEFAULT_DATA / "published").is_dir(), reason="shared data missing")


def test_the_model_builds_the_authors_gold_boards():
    n = 0
    for stem in world_agreement.PUBLISHED:
        gold = json.loads((DEFAULT_DATA / "gold_boards" / f"{stem}.json").read_text())
        for sid, sample in read_samples(DEFAULT_DATA / "published" / f"{stem}.json"):
            board = world_agreement.AuthorsBoard()
            for p in world_agreement.parse_puts(sample["code"]["multi_turn"]["output"]):
                board.put(*p)
            assert board.cells() == gold[sid], sid
            n += 1
    assert n == 260


def test_we_agree_with_the_authors_except_where_a_documented_defect_is_met():
    result = world_agreement.measure(seed=0, dataset=None)
    assert result["boards"] == 260 and result["mutants"] > 3000
    assert set(result["by_kind"]) == set(world_agreement.MUTATIONS)
    assert result["clean"]["n"] > 0.7 * result["mutants"]
    assert result["clean"]["agreement"] == 1.0, [d for d in result["disagreements"] if not d["defects"]][:3]
    assert all(d["defects"] for d in result["disagreements"])


def test_the_corpus_is_deterministic():
    first = list(world_agreement.corpus(seed=3, dataset=None))
    assert first == list(world_agreement.corpus(seed=3, dataset=None))
    assert first != list(world_agreement.corpus(seed=4, dataset=None))
