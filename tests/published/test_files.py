"""sartco.published.files: the published file names, the one walk over a file's samples and the
gold boards a file is checked against (the shared data read where it lies)."""
from __future__ import annotations

import json

import pytest

from sartco.errors import UserError
from sartco.published import files
from sartco.published.files import GOLD_BOARDS, PUBLISHED

pytestmark = pytest.mark.skipif(not PUBLISHED.is_dir(), reason=f"published SARTCo data not found at {PUBLISHED}")

NAMES = sorted(p.name for p in PUBLISHED.glob("*.json"))


@pytest.mark.parametrize("name", NAMES)
def test_the_walk_yields_exactly_the_samples_of_the_gold_boards(name):
    """Every sample id the walk makes is one the authors gave a board, and none is missed."""
    ids = [sid for sid, _ in files.read_samples(PUBLISHED / name)]
    gold = files.gold_boards(GOLD_BOARDS, name)
    assert len(ids) == len(set(ids)) == len(gold) == (1168 if name == "rb_so_train.json" else 130)
    assert set(ids) == set(gold)
    kind = files.name_of(name).kind
    assert all(sid.startswith(f"{kind.board}/{kind.published_object}/") for sid in ids)


def test_a_variant_has_its_test_files_gold_boards_and_names_round_trip():
    assert files.gold_boards(GOLD_BOARDS, "rb_so_test_hc.json") == json.loads((GOLD_BOARDS / "rb_so_test.json").read_text())
    assert files.base_file("rb_so_test_hc.json") == "rb_so_test.json" == files.base_file("rb_so_test")
    assert files.variant_file("sb_so_test.json", "claude") == "sb_so_test_claude_mg.json"
    for name in NAMES:
        parsed = files.name_of(name)
        assert files.variant_file(files.base_file(name), parsed.source) == name


def test_no_gold_folder_or_file_gives_none(tmp_path):
    assert files.gold_boards(None, "sb_so_test.json") is None
    assert files.gold_boards(tmp_path, "sb_so_test_hc.json") is None
    (tmp_path / "sb_so_test.json").write_text("[]")
    with pytest.raises(UserError, match=r"sb_so_test.json \(gold boards\): expected an object"):
        files.gold_boards(tmp_path, "sb_so_test_mg.json")


def test_another_name_is_a_user_error():
    with pytest.raises(UserError, match="notes.json: not a published SARTCo file name"):
        files.name_of("notes.json")
    with pytest.raises(UserError, match="sb_so_xx.json: not a published SARTCo file name"):
        list(files.walk({}, "sb_so_xx.json"))


@pytest.mark.parametrize("name, data, message", [
    ("rb_cho_test.json", {"regular": {"complex": {}}}, "field 'regular.challenge' missing"),
    ("rb_cho_test_hc.json", {"regular": {"challenge": []}}, "field 'regular.challenge' must be an object of counts"),
    ("sb_so_val.json", {"simple": {"simple": {}}, "regular": {}}, "unexpected top-level field(s) ['regular']"),
    ("sb_so_val.json", {"simple": {"simple": {"2": []}}}, "field 'simple.simple.2' must be an object of combo names"),
])
def test_the_walk_checks_the_structure_of_the_files_kind(name, data, message):
    with pytest.raises(UserError) as err:
        list(files.walk(data, name))
    assert str(err.value).startswith(f"{name}: {message}")


def test_discover_orders_templates_then_variants_and_skips_other_json(tmp_path, capsys):
    assert [name.stem for _, name in files.discover(PUBLISHED)] == [
        "sb_so_val", "sb_so_test", "rb_so_train", "rb_so_val", "rb_so_test", "rb_cho_val", "rb_cho_test",
        "sb_so_test_hc", "rb_so_test_hc", "rb_cho_test_hc", "sb_so_test_mg", "rb_so_test_mg",
        "sb_so_test_gpt4_mg", "rb_so_test_gpt4_mg", "sb_so_test_claude_mg", "rb_so_test_claude_mg"]
    (tmp_path / "sb_so_test.json").write_text("{}")
    (tmp_path / "readme.json").write_text("{}")
    assert [p.name for p, _ in files.discover(tmp_path)] == ["sb_so_test.json"]
    assert "skipping readme.json: not a published SARTCo file name" in capsys.readouterr().err
