"""`sartco import` over the published SARTCo files (read from ../shared, never copied here)."""
from __future__ import annotations

import json
import shutil
from collections import Counter

import pytest

from sartco.cli import main
from sartco.program import execute_many
from sartco.published import importer
from sartco.published.files import GOLD_BOARDS as GOLD
from sartco.published.files import PUBLISHED

pytestmark = pytest.mark.skipif(not PUBLISHED.is_dir(), reason=f"published SARTCo data not found at {PUBLISHED}")

OUT_FILES = {
    "simple_simple_val.json": 130, "simple_simple_test.json": 130,
    "regular_simple_train.json": 1168, "regular_simple_val.json": 130, "regular_simple_test.json": 130,
    "regular_complex_val.json": 130, "regular_complex_test.json": 130,
}
BASE_FILES = {"sb_so_val.json": "simple_simple_val.json", "sb_so_test.json": "simple_simple_test.json",
              "rb_so_train.json": "regular_simple_train.json", "rb_so_val.json": "regular_simple_val.json",
              "rb_so_test.json": "regular_simple_test.json", "rb_cho_val.json": "regular_complex_val.json",
              "rb_cho_test.json": "regular_complex_test.json"}


@pytest.fixture(scope="module")
def imported(tmp_path_factory):
    out = tmp_path_factory.mktemp("published")
    assert main(["import", str(PUBLISHED), "--out", str(out), "--quiet"]) == 0
    manifest = json.loads((out / "manifest.json").read_text())
    data = {name: json.loads((out / name).read_text()) for name in manifest["files"]}
    return out, manifest, data


def _defects(manifest, kind):
    return [d for d in manifest["defects"] if d["kind"] == kind]


def test_all_sixteen_files_are_read_and_counts_match(imported):
    _, manifest, data = imported
    read = manifest["config"]["samples_read"]
    assert len(read) == 16
    assert read["rb_so_train.json"] == 1168
    assert all(n == 130 for name, n in read.items() if name != "rb_so_train.json")
    assert manifest["files"] == OUT_FILES
    assert {name: len(records) for name, records in data.items()} == OUT_FILES
    assert manifest["format"] == "sartco-dataset/1" and manifest["source"] == "published"


def test_every_gold_program_builds_its_gold_board(imported):
    _, manifest, data = imported
    assert not [d for d in manifest["defects"] if d["kind"] in ("gold_error", "gold_mismatch", "no_gold_board")]
    assert manifest["config"]["gold_boards_checked"] == manifest["config"]["gold_programs_run"] == 130 * 2 * 3 + 1168 + 130 * 4
    for base, out in BASE_FILES.items():
        gold = json.loads((GOLD / base).read_text())
        programs = [(record, style["total_code"]) for record in data[out] for style in record["code"].values()]
        assert len(gold) == len(data[out])
        # independently of the importer's own check: run the written records' programs again
        for (record, _), ex in zip(programs, execute_many([code for _, code in programs])):
            sample = record["provenance"]["sample"]
            assert ex.ok, (record["id"], ex.message)
            assert ex.cells == gold[sample] == record["target"], record["id"]


def test_records_follow_the_architecture(imported):
    _, _, data = imported
    keys = ["id", "board_type", "object_type", "split", "combo_name", "shapes", "colors", "quadrant", "rows", "cols",
            "seed", "arrangement", "placement", "occupied_rows", "occupied_cols", "target", "code", "instructions", "provenance"]
    for name, records in data.items():
        board_type, object_type, split = name.removesuffix(".json").split("_")
        ids = [r["id"] for r in records]
        assert len(set(ids)) == len(ids)
        for r in records:
            assert list(r) == keys
            assert (r["board_type"], r["object_type"], r["split"]) == (board_type, object_type, split)
            assert r["provenance"]["source"] == "published"
            assert r["id"] == r["provenance"]["file"].removesuffix(".json") + "/" + r["provenance"]["sample"]
            if board_type == "simple":
                assert set(r["code"]) == {"first_order", "sequence_function", "optimal_function"}
                assert r["code"]["first_order"]["steps"] and len(r["placement"]["x"]) == len(r["shapes"])
                assert set(r["instructions"]["template"]) <= {"single_turn", "single_turn_sc", "multi_turn"}
                assert isinstance(r["instructions"]["template"]["multi_turn"], list)
            else:
                assert set(r["code"]) == {"repetition"} and r["placement"] is None
                assert set(r["instructions"]["template"]) == {"regular"}
    assert "complex" in {r["object_type"] for r in data["regular_complex_test.json"]}


def test_variants_are_merged_as_instruction_sources(imported):
    _, _, data = imported
    sources = lambda name: Counter(tuple(r["instructions"]) for r in data[name])  # noqa: E731
    assert sources("simple_simple_test.json") == {("template", "human", "codellama", "gpt4", "claude"): 130}
    assert sources("regular_simple_test.json") == {("template", "human", "codellama", "gpt4", "claude"): 130}
    assert sources("regular_complex_test.json") == {("template", "human"): 130}
    assert sources("simple_simple_val.json") == {("template",): 130}
    first = data["simple_simple_test.json"][0]["instructions"]
    assert set(first["human"]) == {"single_turn", "single_turn_sc"}
    assert set(first["gpt4"]) == {"single_turn"}
    assert set(data["regular_simple_test.json"][0]["instructions"]["claude"]) == {"regular"}


def test_known_defects_are_reported(imported):
    _, manifest, data = imported
    junk = _defects(manifest, "junk_instruction")
    assert [(d["file"], d["sample"]) for d in junk] == [
        ("rb_cho_test_hc.json", "regular/challenge/2/bs/2"), ("rb_cho_test_hc.json", "regular/challenge/4/bnws/0"),
        ("rb_cho_test_hc.json", "regular/challenge/4/bbbs/0"), ("rb_cho_test_hc.json", "regular/challenge/5/bwbws/0")]

    truncated = Counter(d["file"] for d in _defects(manifest, "truncated_instruction"))
    assert {"rb_so_test_mg.json", "rb_so_test_gpt4_mg.json", "rb_so_test_claude_mg.json"} <= set(truncated)
    assert all(name.endswith("_mg.json") for name in truncated)

    prefixes = _defects(manifest, "stray_prefix")
    assert {"sb_so_test_mg.json", "sb_so_test_claude_mg.json"} <= {d["file"] for d in prefixes}
    for records in data.values():
        for r in records:
            for source in ("codellama", "gpt4", "claude"):
                for text in r["instructions"].get(source, {}).values():
                    assert not text.startswith(("s: ", ": ", "s Place")), (r["id"], text[:20])

    shapes = _defects(manifest, "shapes_mismatch")
    assert len(shapes) == 11 and all("/bbbb/" in d["sample"] for d in shapes)
    fixed = {d["id"] for d in shapes}
    for records in data.values():
        for r in records:
            if r["id"] in fixed:
                assert r["shapes"] == ["bridge-h", "bridge-h", "bridge-v", "bridge-v"]

    overlaps = _defects(manifest, "split_overlap")
    assert any("regular_simple_train.json and regular_simple_test.json" in d["detail"] for d in overlaps)
    kinds = set(Counter(d["kind"] for d in manifest["defects"]))
    assert kinds <= {"junk_instruction", "truncated_instruction", "unterminated_instruction", "stray_prefix",
                     "shapes_mismatch", "split_overlap"}


def test_output_is_deterministic(imported, tmp_path):
    out, _, _ = imported
    assert main(["import", str(PUBLISHED), "--out", str(tmp_path), "--quiet"]) == 0
    for path in sorted(out.iterdir()):
        assert (tmp_path / path.name).read_bytes() == path.read_bytes(), path.name


def test_summary_is_printed(tmp_path, capsys):
    src = tmp_path / "src"
    src.mkdir()
    shutil.copy(PUBLISHED / "rb_cho_test.json", src)
    shutil.copy(PUBLISHED / "rb_cho_test_hc.json", src)
    assert main(["import", str(src), "--out", str(tmp_path / "out"), "--gold", str(GOLD)]) == 0
    out = capsys.readouterr().out
    lines = [" ".join(line.split()) for line in out.splitlines()]
    assert "rb_cho_test_hc.json 130 samples" in lines and "regular_complex_test.json 130 records" in lines
    assert "junk_instruction 4" in lines and "shapes_mismatch 2" in lines
    assert "junk_instruction: rb_cho_test_hc.json regular/challenge/5/bwbws/0" in out


# ---------------------------------------------------------------------------- malformed input

def _src_with(tmp_path, name, text):
    src = tmp_path / "src"
    src.mkdir()
    (src / name).write_text(text)
    return src


@pytest.mark.parametrize("text, message", [
    ('{"simple": {"simple": {"2": {"wn": [', "sb_so_test.json: not valid JSON: Expecting value at line 1"),
    ('{"regular": {}}', "sb_so_test.json: field 'simple' missing"),
    ('{"simple": {"challenge": {}}}', "sb_so_test.json: field 'simple.simple' missing"),
    ('{"simple": {"simple": {"2": {"wn": {}}}}}', "sb_so_test.json: field 'simple.simple.2.wn' must be a list"),
    ('[]', "sb_so_test.json: expected a JSON object"),
])
def test_a_malformed_file_gives_one_clear_line(tmp_path, capsys, text, message):
    src = _src_with(tmp_path, "sb_so_test.json", text)
    assert main(["import", str(src), "--out", str(tmp_path / "out")]) == 2
    err = capsys.readouterr().err
    assert err.startswith("sartco import: " + message), err
    assert "Traceback" not in err and err.count("\n") == 1


def test_a_variant_without_its_test_file_is_a_user_error(tmp_path, capsys):
    src = tmp_path / "src"
    src.mkdir()
    shutil.copy(PUBLISHED / "rb_so_test_hc.json", src)
    assert main(["import", str(src), "--out", str(tmp_path / "out")]) == 2
    assert "rb_so_test_hc.json: its test file rb_so_test.json is missing" in capsys.readouterr().err


def test_an_empty_folder_is_a_user_error(tmp_path, capsys):
    assert main(["import", str(tmp_path), "--out", str(tmp_path / "out")]) == 2
    assert "no published SARTCo files" in capsys.readouterr().err


def test_bad_samples_become_defects_and_the_rest_is_imported(tmp_path):
    data = json.loads((PUBLISHED / "sb_so_val.json").read_text())
    combo = data["simple"]["simple"]["2"]["wn"]
    del combo[0]["code"]
    combo[1]["dialogues"]["single_turn"]["instructions"] = "oops"
    data["simple"]["simple"]["2"]["ws"][0] = 7
    data["simple"]["simple"]["2"]["ws"][1]["code"]["multi_turn"]["output"][0] = "put(board, 'washer'"
    data["simple"]["simple"]["2"]["nw"][0]["code"]["multi_turn"]["total_code"] = "board = init_board(8, 8)\nput(board, 'nut', 'red', 9, 0)"
    src = _src_with(tmp_path, "sb_so_val.json", json.dumps(data))
    manifest = importer.import_published(src, tmp_path / "out", GOLD)
    bad = [(d["kind"], d["sample"]) for d in manifest["defects"]]
    assert ("malformed_sample", "simple/simple/2/wn/0") in bad
    assert ("malformed_sample", "simple/simple/2/wn/1") in bad
    assert ("malformed_sample", "simple/simple/2/ws/0") in bad
    assert ("malformed_sample", "simple/simple/2/ws/1") in bad
    assert ("gold_error", "simple/simple/2/nw/0") in bad
    assert manifest["files"] == {"simple_simple_val.json": 125}


@pytest.mark.parametrize("key", ["combo_name", "shapes", "colors", "x", "y", "orientations", "quadrant",
                                 "seed_template", "code", "dialogues", "rows"])
def test_any_missing_or_retyped_field_is_a_defect_not_a_traceback(tmp_path, key):
    data = json.loads((PUBLISHED / "sb_so_test.json").read_text())
    variant = json.loads((PUBLISHED / "sb_so_test_hc.json").read_text())
    for d in (data, variant):
        d["simple"]["simple"]["2"]["wn"][0].pop(key)
        d["simple"]["simple"]["2"]["wn"][1][key] = {"not": "expected"}
    src = _src_with(tmp_path, "sb_so_test.json", json.dumps(data))
    (src / "sb_so_test_hc.json").write_text(json.dumps(variant))
    manifest = importer.import_published(src, tmp_path / "out", GOLD)
    assert manifest["files"]["simple_simple_test.json"] >= 128


def test_an_out_path_that_is_a_file_is_a_user_error(tmp_path, capsys):
    (tmp_path / "taken").write_text("")
    assert main(["import", str(PUBLISHED), "--out", str(tmp_path / "taken")]) == 2
    assert "--out" in capsys.readouterr().err
