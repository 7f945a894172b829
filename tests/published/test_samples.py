"""sartco.published.samples: one published sample -> our board record, and a variant's instructions."""
from __future__ import annotations

import copy

import pytest

from sartco.dataset import RECORD_KEYS
from sartco.published import samples
from sartco.published.files import PUBLISHED, read_samples

pytestmark = pytest.mark.skipif(not PUBLISHED.is_dir(), reason=f"published SARTCo data not found at {PUBLISHED}")


@pytest.fixture(scope="module")
def sb_so_test():
    return dict(read_samples(PUBLISHED / "sb_so_test.json"))


@pytest.fixture(scope="module")
def sb_so_test_mg():
    return dict(read_samples(PUBLISHED / "sb_so_test_mg.json"))


def test_variant_keys_in_the_records_style_order():
    assert samples.variant_keys("human") == ["single_turn_hai", "single_turn_hai_sc", "regular_hai"]
    assert samples.variant_keys("codellama") == samples.variant_keys("claude") == ["single_turn_mg", "regular_mg"]


def test_a_simple_sample_becomes_a_record(sb_so_test):
    sid = "simple/simple/2/wn/0"
    found = []
    r = samples.base_record("sb_so_test.json", sid, sb_so_test[sid], found)
    assert found == [] and tuple(r) == RECORD_KEYS
    assert (r["id"], r["board_type"], r["object_type"], r["split"]) == (f"sb_so_test/{sid}", "simple", "simple", "test")
    assert list(r["code"]) == ["first_order", "sequence_function", "optimal_function"]
    assert r["target"] is None and r["provenance"] == {"source": "published", "file": "sb_so_test.json", "sample": sid}
    assert len(r["placement"]["x"]) == len(r["shapes"]) == len(r["instructions"]["template"]["multi_turn"])


def test_fields_the_code_contradicts_are_reported_and_the_code_kept(sb_so_test):
    sid = "simple/simple/2/wn/0"
    sample = copy.deepcopy(sb_so_test[sid])
    truth = (list(sample["x"]), list(sample["shapes"]))
    sample["x"] = [0] * len(sample["x"])
    sample["shapes"] = ["screw"] * len(sample["shapes"])
    found = []
    r = samples.base_record("sb_so_test.json", sid, sample, found)
    assert [d.kind for d in found] == ["placement_mismatch", "shapes_mismatch"]
    assert (r["placement"]["x"], r["shapes"]) == truth


@pytest.mark.parametrize("change, message", [
    (lambda s: s.pop("quadrant"), "field(s) quadrant missing"),
    (lambda s: s["code"]["multi_turn"].update(output="put(board"), "field 'code.multi_turn.output' is a str"),
    (lambda s: s["dialogues"]["single_turn"]["instructions"].append({"<Programmer>": "more"}),
     "field 'dialogues.single_turn' has 2 instructions, expected 1"),
])
def test_a_malformed_sample_is_a_sample_error(sb_so_test, change, message):
    sample = copy.deepcopy(sb_so_test["simple/simple/2/wn/0"])
    change(sample)
    with pytest.raises(samples.SampleError, match=message.replace("(", r"\(").replace(")", r"\)")):
        samples.base_record("sb_so_test.json", "simple/simple/2/wn/0", sample, [])


def test_a_variant_adds_its_texts_without_the_stray_prefix(sb_so_test, sb_so_test_mg):
    """A variant's sample is its test sample plus its own key: the fingerprints agree on the real data."""
    for sid, sample in sb_so_test_mg.items():
        assert samples.fingerprint(sample, ("single_turn_mg",)) == samples.fingerprint(sb_so_test[sid], ()), sid
    sid = "simple/simple/2/wn/0"
    base = samples.base_record("sb_so_test.json", sid, sb_so_test[sid], [])
    variant = copy.deepcopy(sb_so_test_mg[sid])
    text = "Place a red washer in the last row, 4th column. Stack a blue nut on top of it."
    variant["dialogues"]["single_turn_mg"]["instructions"][0]["<Programmer>"] = "s: " + text
    found = []
    texts = samples.variant_texts("sb_so_test_mg.json", sid, variant, (base, samples.fingerprint(sb_so_test[sid], ())), found)
    assert texts == {"single_turn": text}
    assert [(d.kind, d.id) for d in found] == [("stray_prefix", base["id"])]


def test_a_variant_that_differs_from_its_test_sample_is_left_out(sb_so_test, sb_so_test_mg):
    sid = "simple/simple/2/wn/0"
    base = samples.base_record("sb_so_test.json", sid, sb_so_test[sid], [])
    variant = copy.deepcopy(sb_so_test_mg[sid])
    variant["colors"] = list(reversed(variant["colors"])) + ["red"]
    found = []
    base_print = samples.fingerprint(sb_so_test[sid], ())
    assert samples.variant_texts("sb_so_test_mg.json", sid, variant, (base, base_print), found) is None
    assert [(d.kind, d.id) for d in found] == [("variant_mismatch", base["id"])]
    found = []
    assert samples.variant_texts("sb_so_test_mg.json", sid, variant, None, found) is None
    assert [(d.kind, d.id) for d in found] == [("variant_mismatch", None)]
    with pytest.raises(samples.SampleError, match="no single_turn_mg or regular_mg dialogue"):
        samples.variant_texts("sb_so_test_mg.json", sid, sb_so_test[sid], (base, base_print), [])
