"""Fresh test boards (sartco.instances.fresh, sartco.games.instruct.fresh): disjoint from the published data
and the seed-42 dataset, with the published test set's distribution, reproducible."""
from __future__ import annotations

import json

import pytest

from sartco.games.instruct.fresh import FreshInstanceGenerator
from sartco.dataset import REGULAR_COMPLEX, SIMPLE
from sartco.instances.config import load_config
from sartco.instances.fresh import board_key, board_keys, fresh_boards, marginals, total_variation
from sartco.instances.storage import load_dataset
from sartco.published import importer
from sartco.published.files import GOLD_BOARDS, PUBLISHED

ROOT = __import__("pathlib").Path(__file__).resolve().parents[2]

pytestmark = pytest.mark.skipif(not PUBLISHED.is_dir(), reason=f"published SARTCo data not found at {PUBLISHED}")

V1 = ROOT / "instances" / "v1"   # the committed seed-42 dataset
COMBO_TOLERANCE = 0.10           # total variation distance of the combinations (the fallbacks' share)


@pytest.fixture(scope="session")
def published(tmp_path_factory):
    out = tmp_path_factory.mktemp("published")
    importer.import_published(PUBLISHED, out, GOLD_BOARDS)
    return out


@pytest.fixture(scope="session")
def drawn(published):
    _, pub = load_dataset(published)
    _, v1 = load_dataset(V1)
    files, report = fresh_boards(load_config(), 7, pub, board_keys(pub, v1))
    return pub, v1, files, report


def test_fresh_boards_are_in_no_published_and_no_seed42_file(drawn):
    pub, v1, files, report = drawn
    fresh = [board_key(r["target"]) for records in files.values() for r in records]
    assert len(fresh) == len(set(fresh)) == 390
    assert not set(fresh) & board_keys(pub) and not set(fresh) & board_keys(v1)
    assert report.overlap == 0 and report.rejected > 0  # the exclusion did work: some draws hit a known board


def test_fresh_boards_have_the_published_marginals(drawn):
    pub, _, files, _ = drawn
    assert set(files) == {name for name in pub if name.endswith("_test.json")}
    for name, records in files.items():
        want, got = marginals(pub[name]), marginals(records)
        assert got["board_kind"] == want["board_kind"] and got["object_count"] == want["object_count"], name
        assert total_variation(want["combo"], got["combo"]) <= COMBO_TOLERANCE, name
        assert all(r["split"] == "test" and r["provenance"]["source"] == "fresh" for r in records)


def test_same_seed_same_boards_other_seed_other_boards(drawn, published):
    pub, v1, files, _ = drawn
    again, _ = fresh_boards(load_config(), 7, pub, board_keys(pub, v1))
    assert again == files
    other, _ = fresh_boards(load_config(), 8, pub, board_keys(pub, v1))
    assert [r["target"] for r in other["simple_simple_test.json"]] != [r["target"] for r in files["simple_simple_test.json"]]


def _instance_file(game_dir, published, seed):
    gen = FreshInstanceGenerator(str(game_dir), [(SIMPLE, "first_order"), (REGULAR_COMPLEX, "repetition")])
    return gen.generate("instances_fresh.json", seed=42, dataset_dir=V1, fresh_seed=seed, published_dir=published,
                        per_experiment=4)


def test_instance_file_is_byte_identical_for_a_seed_and_pairs_published_with_fresh(tmp_path, published):
    first = _instance_file(tmp_path / "a", published, 7)
    second = _instance_file(tmp_path / "b", published, 7)
    data = open(first, "rb").read()
    assert data == open(second, "rb").read()
    assert data != open(_instance_file(tmp_path / "c", published, 8), "rb").read()
    exps = json.loads(data)["experiments"]
    assert [(e["name"], e["boards"], len(e["game_instances"])) for e in exps] == [
        ("sb_so_first_order_template_published", "published", 4), ("sb_so_first_order_template_fresh7", "fresh", 4),
        ("rb_co_repetition_template_published", "published", 4), ("rb_co_repetition_template_fresh7", "fresh", 4)]
    assert all(e["source"] == "template" and e["split"] == "test" for e in exps)
