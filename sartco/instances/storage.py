"""A dataset folder on disk (docs/ARCHITECTURE.md "Datasets"): manifest.json beside one JSON list of
board records per board kind and split, written deterministically and read back."""
from __future__ import annotations

import json
from pathlib import Path
from typing import Any

from sartco.dataset import BOARD_KINDS, SPLITS, BoardRecord
from sartco.errors import UserError

FORMAT = "sartco-dataset/1"
# the dataset files in their order in a folder and a manifest: board kind, then split
FILE_ORDER = tuple(kind.dataset_file(split) for kind in BOARD_KINDS for split in SPLITS)


def dumps(obj: Any) -> str:
    return json.dumps(obj, indent=1, ensure_ascii=False, sort_keys=False) + "\n"


def dumps_records(records: list[BoardRecord]) -> str:
    """A JSON list with one compact record per line: the same data as indent=1 at a third of the
    size (the generated train splits are large), still diff-friendly record by record."""
    if not records:
        return "[]\n"
    return "[\n" + ",\n".join(json.dumps(r, ensure_ascii=False, sort_keys=False) for r in records) + "\n]\n"


def in_file_order(names) -> list[str]:
    """Dataset file names sorted by board kind, then split."""
    return sorted(names, key=FILE_ORDER.index)


def make_folder(out: Path) -> None:
    try:
        out.mkdir(parents=True, exist_ok=True)
    except OSError as exc:
        raise UserError(f"--out {out}: cannot create the folder: {exc.strerror}") from None


def load_dataset(folder: str | Path) -> tuple[dict, dict[str, list[BoardRecord]]]:
    """The manifest and the records by file name of one dataset folder (the files its manifest lists)."""
    folder = Path(folder)
    manifest_file = folder / "manifest.json"
    if not manifest_file.is_file():
        raise UserError(f"{manifest_file}: no dataset manifest (expected a folder written by `sartco generate` "
                        f"or `sartco import`)")
    manifest = _read_json(manifest_file)
    listed = manifest.get("files") if isinstance(manifest, dict) else None
    if not isinstance(listed, dict):
        raise UserError(f"{manifest_file}: no \"files\" object (not a dataset manifest)")
    files = {}
    for name in listed:
        if not (folder / name).is_file():
            raise UserError(f"{folder / name}: listed in the manifest but missing")
        files[name] = _read_json(folder / name)
    return manifest, files


_loaded: dict[tuple, tuple[dict, dict[str, list[BoardRecord]]]] = {}


def loaded_dataset(folder: str | Path) -> tuple[dict, dict[str, list[BoardRecord]]]:
    """load_dataset(folder), read once in a process while the folder's JSON files keep their names,
    sizes and modification times: one command writes several instance files from one dataset
    (cobot_instruct's four, cobot_describe's five), and each read of the generated dataset's 17 MB
    took 0.4 s. Every caller gets the same objects: it reads them and never changes them."""
    folder = Path(folder)
    files = sorted(folder.glob("*.json")) if folder.is_dir() else []
    key = (folder.resolve(), tuple((p.name, s.st_size, s.st_mtime_ns) for p in files for s in [p.stat()]))
    if key not in _loaded:
        while len(_loaded) >= 2:  # a file of published episodes reads two datasets in turn
            del _loaded[next(iter(_loaded))]
        _loaded[key] = load_dataset(folder)
    return _loaded[key]


def _read_json(path: Path):
    try:
        return json.loads(path.read_text(encoding="utf-8"))
    except (ValueError, OSError) as exc:
        raise UserError(f"{path}: not readable as JSON ({exc})") from None


def shared_boards(files: dict[str, list[BoardRecord]]) -> list[list[tuple[str, str]]]:
    """Every board (target) found more than once, in two files or twice in one: its (file, record
    id) places in the order of the files and records given; the boards in order of first place."""
    seen: dict[str, list[tuple[str, str]]] = {}
    for name, records in files.items():
        for record in records:
            seen.setdefault(json.dumps(record["target"], sort_keys=True), []).append((name, record["id"]))
    return [places for places in seen.values() if len(places) > 1]
