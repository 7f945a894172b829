"""Generated datasets: split sizes, quadrants, disjoint splits, combinations, determinism, and
every generated program builds its board."""
import filecmp
import json
from collections import Counter

import pytest

from sartco.instances.gold_code import check_records
from sartco.instances.generate import write_dataset
from sartco.instances.objects import enumerate_objects

ROOT = __import__("pathlib").Path(__file__).resolve().parents[2]

SIZES = {"simple_simple": (1072, 130, 130), "regular_simple": (1168, 130, 130), "regular_complex": (2944, 130, 130)}
QUADS = {"train": {"tl"}, "val": {"tr"}, "test": {"bl", "br"}}


def test_split_sizes(dataset):
    _, files = dataset
    for kind, sizes in SIZES.items():
        for split, size in zip(("train", "val", "test"), sizes):
            assert len(files[f"{kind}_{split}.json"]) == size


def test_manifest(dataset, v1_config):
    out, files = dataset
    m = json.loads((out / "manifest.json").read_text())
    assert m["format"] == "sartco-dataset/1" and m["source"] == "generated" and m["seed"] == 42
    assert m["version"] == "v1" and m["files"] == {k: len(v) for k, v in files.items()}


def test_quadrant_rule(dataset):
    _, files = dataset
    for split, allowed in QUADS.items():
        for r in files[f"simple_simple_{split}.json"]:
            assert r["quadrant"] in allowed
            x, y = r["placement"]["x"][0], r["placement"]["y"][0]
            quadrant = ("t" if x < 4 else "b") + ("l" if y < 4 else "r")
            assert quadrant == r["quadrant"], r["id"]
    for kind in ("regular_simple", "regular_complex"):
        for split in QUADS:
            assert {r["quadrant"] for r in files[f"{kind}_{split}.json"]} == {"tl"}


def test_no_board_in_two_splits(dataset):
    _, files = dataset
    for kind in SIZES:
        seen = {}
        for split in ("train", "val", "test"):
            for r in files[f"{kind}_{split}.json"]:
                key = json.dumps(r["target"])
                assert key not in seen, f"{r['id']} repeats {seen[key]}"
                seen[key] = r["id"]


def test_every_combination_in_every_split(dataset, v1_config):
    _, files = dataset
    objects = enumerate_objects(v1_config.seeds, v1_config.colors)
    colored = Counter()
    for o in objects:
        colored[o.combo] += len(o.colorings)
    assert len(colored) == 68
    for name, records in files.items():
        counts = Counter(r["combo_name"] for r in records)
        assert set(counts) == set(colored), name
        split = name.removesuffix(".json").rsplit("_", 1)[1]
        top = max(counts.values())
        for combo, n in counts.items():  # spread evenly, except where a combination runs out
            capacity = colored[combo] * len(QUADS[split]) if name.startswith("simple") else None
            assert n >= top - 1 or n == capacity, (name, combo, n, top)


def test_ids_and_record_form(dataset):
    _, files = dataset
    for name, records in files.items():
        kind, split = name.removesuffix(".json").rsplit("_", 1)
        for i, r in enumerate(records):
            assert r["id"] == f"{kind}_{split}_{i:04d}" and r["split"] == split
            assert r["board_type"] == kind.split("_")[0] and r["object_type"] == kind.split("_")[1]
            assert r["provenance"] == {"source": "generated"}
            if r["board_type"] == "simple":
                assert set(r["code"]) == {"first_order", "sequence_function", "optimal_function"}
                assert len(r["instructions"]["template"]["multi_turn"]) == len(r["shapes"])
                assert r["arrangement"] is None and r["occupied_rows"] is None
            else:
                assert set(r["code"]) == {"repetition"} and "regular" in r["instructions"]["template"]
                assert r["occupied_rows"] >= 1 and r["arrangement"].startswith("regular_seed")


def test_every_program_builds_its_board(dataset):
    _, files = dataset
    problems = []
    for records in files.values():
        problems += check_records(records)
    assert problems == []


def test_same_seed_same_bytes(v1_config, tmp_path, dataset):
    first, _ = dataset
    second = tmp_path / "again"
    write_dataset(v1_config, 42, second)
    names = sorted(p.name for p in first.iterdir())
    assert names == sorted(p.name for p in second.iterdir())
    match, mismatch, errors = filecmp.cmpfiles(first, second, names, shallow=False)
    assert mismatch == [] and errors == []


def test_other_seed_other_boards(v1_config, tmp_path, dataset):
    first, _ = dataset
    write_dataset(v1_config, 7, tmp_path)
    assert (tmp_path / "simple_simple_val.json").read_bytes() != (first / "simple_simple_val.json").read_bytes()


def test_committed_v1_is_seed_42(dataset):
    """instances/v1 in the repository is what `sartco generate ... --seed 42` writes today."""
    first, _ = dataset
    committed = ROOT / "instances" / "v1"
    if not committed.is_dir():
        pytest.skip("instances/v1 not present")
    names = sorted(p.name for p in first.iterdir())
    _, mismatch, errors = filecmp.cmpfiles(first, committed, names, shallow=False)
    assert mismatch == [] and errors == [], "regenerate: sartco generate --config resources/v1.yaml --seed 42 --out instances/v1"
