"""Our seeds and templates reproduce the published samples: every published object is one of
our enumerated objects; for it we render byte-identical code (all styles) and instructions
(simple boards), the same object function and, up to white space, the same arrangement
instruction (regular boards), and the board their gold program builds."""
import json
import re

import pytest

from sartco.instances.arrangements import anchors
from sartco.instances.objects import enumerate_objects
from sartco.instances.boards import regular_record, simple_record
from sartco.program import execute

PUBLISHED = __import__("pathlib").Path(__file__).resolve().parents[3] / "shared" / "sartco-data" / "published"

pytestmark = pytest.mark.skipif(not PUBLISHED.is_dir(), reason="shared published data not present")


def _samples(name, board_type):
    data = json.loads((PUBLISHED / name).read_text())[board_type]
    for object_type, counts in data.items():
        for per_combo in counts.values():
            for samples in per_combo.values():
                for s in samples:
                    yield object_type, s


def test_published_combos_are_ours(v1_config):
    ours = {o.combo for o in enumerate_objects(v1_config.seeds, v1_config.colors)}
    theirs = set()
    for name in ("sb_so_val.json", "sb_so_test.json", "rb_so_train.json", "rb_cho_val.json"):
        for _, s in _samples(name, "simple" if name.startswith("sb") else "regular"):
            theirs.add(s["combo_name"])
    assert theirs == ours


@pytest.mark.parametrize("name", ["sb_so_val.json", "sb_so_test.json"])
def test_simple_samples(v1_config, name):
    objects = {(o.seed, o.shapes, o.dxs, o.dys): o for o in enumerate_objects(v1_config.seeds, v1_config.colors)}
    n = 0
    for _, s in _samples(name, "simple"):
        x0, y0 = s["x"][0], s["y"][0]
        seed = s["seed_template"]["single_turn"].rsplit("/", 1)[1].removesuffix(".j2")
        obj = objects[(seed, tuple(s["shapes"]), tuple(x - x0 for x in s["x"]), tuple(y - y0 for y in s["y"]))]
        r = simple_record(obj, s["colors"], s["quadrant"], x0, y0)
        assert r["code"]["first_order"]["steps"] == s["code"]["multi_turn"]["output"]
        assert r["code"]["first_order"]["total_code"] == s["code"]["multi_turn"]["total_code"]
        for ours, theirs in (("sequence_function", "single_turn_sc"), ("optimal_function", "single_turn")):
            for key in ("function", "usage", "total_code"):
                assert r["code"][ours][key] == s["code"][theirs][key]
        dialogues = s["dialogues"]
        assert r["instructions"]["template"]["single_turn"] == dialogues["single_turn"]["instructions"][0]["<Programmer>"]
        assert r["instructions"]["template"]["multi_turn"] == [t["<Programmer>"] for t in dialogues["multi_turn"]["instructions"]]
        assert r["placement"]["orientations"] == s["orientations"]
        n += 1
    assert n == 130


@pytest.mark.parametrize("name", ["rb_so_val.json", "rb_so_test.json", "rb_cho_val.json", "rb_cho_test.json"])
def test_regular_samples(v1_config, name):
    objects = {}
    for o in enumerate_objects(v1_config.seeds, v1_config.colors):
        objects.setdefault((o.shapes, o.dxs, o.dys), o)
    norm = lambda t: " ".join(t.split())  # noqa: E731
    n = 0
    for object_type, s in _samples(name, "regular"):
        function = s["code"]["function"]
        shapes = tuple(re.findall(r"'([\w-]+)'", function.split("shapes = ", 1)[1].split("\n", 1)[0]))
        offsets = re.search(r"zip\(shapes, colors, (\[[\d, ]*\]), (\[[\d, ]*\])\)", function)
        zeros = (0,) * len(shapes)
        dxs, dys = (tuple(json.loads(offsets[1])), tuple(json.loads(offsets[2]))) if offsets else (zeros, zeros)
        obj = objects[(shapes, dxs, dys)]
        arrangement = s["seed_template"].rsplit("/", 1)[1].removesuffix(".j2")
        where = anchors(arrangement, obj)
        assert where is not None
        r = regular_record(obj, s["colors"], arrangement, where, "simple" if object_type == "simple" else "complex")
        assert r["code"]["repetition"]["function"] == function
        assert (r["occupied_rows"], r["occupied_cols"]) == (s["occupied_rows"], s["occupied_cols"])
        assert norm(r["instructions"]["template"]["regular"]) == norm(s["dialogues"]["regular"]["instructions"][0]["<Programmer>"])
        ex = execute(s["code"]["total_code"])
        assert ex.ok and ex.cells == r["target"]
        n += 1
    assert n == 130
