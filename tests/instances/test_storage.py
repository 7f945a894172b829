"""sartco.instances.storage (a dataset folder, the overlap check) and gold_code (the batch runner)."""
from __future__ import annotations

import pytest

from sartco.errors import UserError
from sartco.instances import gold_code, storage

A = {"0:0": [["washer", "red"]]}
B = {"1:1": [["nut", "blue"]]}


def rec(rid, target):
    return {"id": rid, "target": target}


def test_shared_boards_finds_a_board_in_two_files_and_twice_in_one():
    files = {"simple_simple_train.json": [rec("t0", A), rec("t1", B)],
             "simple_simple_val.json": [rec("v0", B), rec("v1", {"2:2": [["screw", "red"]]}), rec("v2", B)],
             "simple_simple_test.json": [rec("s0", A)]}
    assert storage.shared_boards(files) == [
        [("simple_simple_train.json", "t0"), ("simple_simple_test.json", "s0")],
        [("simple_simple_train.json", "t1"), ("simple_simple_val.json", "v0"), ("simple_simple_val.json", "v2")]]
    assert storage.shared_boards({"simple_simple_train.json": [rec("t0", A), rec("t1", B)]}) == []


def test_files_in_board_kind_then_split_order():
    names = ["regular_complex_test.json", "simple_simple_test.json", "regular_simple_train.json",
             "simple_simple_train.json", "simple_simple_val.json"]
    assert storage.in_file_order(names) == ["simple_simple_train.json", "simple_simple_val.json",
                                            "simple_simple_test.json", "regular_simple_train.json",
                                            "regular_complex_test.json"]


def test_load_dataset_names_a_missing_manifest_or_file(tmp_path):
    with pytest.raises(UserError, match="no dataset manifest"):
        storage.load_dataset(tmp_path)
    (tmp_path / "manifest.json").write_text(storage.dumps({"files": {"simple_simple_test.json": 1}}))
    with pytest.raises(UserError, match="simple_simple_test.json: listed in the manifest but missing"):
        storage.load_dataset(tmp_path)
    (tmp_path / "simple_simple_test.json").write_text(storage.dumps_records([rec("s0", A), rec("s1", B)]))
    manifest, files = storage.load_dataset(tmp_path)
    assert files == {"simple_simple_test.json": [rec("s0", A), rec("s1", B)]}


def test_a_dataset_is_read_once_until_one_of_its_files_changes(tmp_path, monkeypatch):
    """The instance generators write several files from one dataset (storage.loaded_dataset)."""
    (tmp_path / "manifest.json").write_text(storage.dumps({"files": {"simple_simple_test.json": 1}}))
    (tmp_path / "simple_simple_test.json").write_text(storage.dumps_records([rec("s0", A)]))
    read = []
    monkeypatch.setattr(storage, "_read_json", lambda path, real=storage._read_json: read.append(path.name) or real(path))
    first = storage.loaded_dataset(tmp_path)
    assert storage.loaded_dataset(str(tmp_path)) is first and first == storage.load_dataset(tmp_path)
    assert read == ["manifest.json", "simple_simple_test.json"] * 2   # loaded_dataset's once, load_dataset's
    (tmp_path / "simple_simple_test.json").write_text(storage.dumps_records([rec("s0", A), rec("s1", B)]))
    assert storage.loaded_dataset(tmp_path)[1] == {"simple_simple_test.json": [rec("s0", A), rec("s1", B)]}
    with pytest.raises(UserError, match="no dataset manifest"):   # a folder that is none: said, not kept
        storage.loaded_dataset(tmp_path / "none")


def _board(rows, cols, put=""):
    return {"total_code": f"board = init_board({rows}, {cols})\n{put}"}


def test_run_gold_code_gives_each_record_its_styles_runs_across_board_sizes():
    """Programs of several board sizes run in one batch per size; the results come back per record."""
    records = [
        {"id": "a", "rows": 8, "cols": 8, "code": {"first_order": _board(8, 8, "put(board, 'washer', 'red', 7, 7)"),
                                                    "optimal_function": _board(8, 8, "put(board, 'nut', 'red', 0, 0)")}},
        {"id": "b", "rows": 4, "cols": 5, "code": {"repetition": _board(4, 5, "put(board, 'screw', 'blue', 3, 4)")}},
        {"id": "c", "rows": 8, "cols": 8, "code": {"repetition": _board(8, 8, "put(board, 'washer', 'red', 8, 0)")}},
    ]
    runs = gold_code.run_gold_code(records)
    assert [list(r) for r in runs] == [["first_order", "optimal_function"], ["repetition"], ["repetition"]]
    assert runs[0]["first_order"].cells == {"7:7": [["washer", "red"]]}
    assert runs[0]["optimal_function"].cells == {"0:0": [["nut", "red"]]}
    assert runs[1]["repetition"].cells == {"3:4": [["screw", "blue"]]}
    assert not runs[2]["repetition"].ok
    records[0]["target"] = runs[0]["first_order"].cells
    records[1]["target"] = runs[1]["repetition"].cells
    records[2]["target"] = {}
    problems = gold_code.check_records(records)
    assert [p.split(":")[0] for p in problems] == ["a optimal_function", "c repetition"]
