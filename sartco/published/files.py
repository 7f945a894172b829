"""The published SARTCo files (../shared/sartco-data): their names, reading them, and the one walk
over their structure.

A published file `<prefix>_<split>[_<suffix>].json` (sartco.dataset.parse_published_name) holds
`{board type: {object type: {count: {combo: [sample, ...]}}}}` with the board and object type of its
prefix (complex objects spelt "challenge"); a sample's id is the path to it,
`<board type>/<object type>/<count>/<combo>/<index>`, as in gold_boards/. A variant file (`_hc`,
`_mg`, ...) repeats its test file's samples with its own dialogue key added; its gold boards are its
test file's (gold_boards/<test file>.json).
"""
from __future__ import annotations

import json
import sys
from pathlib import Path
from typing import Any, Iterator

from sartco.dataset import BOARD_KINDS, SHARED_DATA, SOURCES, SPLITS, PublishedName, parse_published_name
from sartco.errors import UserError
from sartco.settings import data_error

PUBLISHED = SHARED_DATA / "published"
GOLD_BOARDS = SHARED_DATA / "gold_boards"


def require_data(path: Path) -> None:
    """One line naming the data setting when `path` is in a data folder that is not there."""
    message = data_error(path)
    if message:
        raise UserError(message)


def read_json(path: Path) -> Any:
    """The JSON content of a file; a UserError naming the file when it cannot be read."""
    require_data(path)
    try:
        text = path.read_text(encoding="utf-8")
    except (OSError, UnicodeDecodeError) as exc:
        raise UserError(f"{path.name}: cannot read: {exc}") from None
    try:
        return json.loads(text)
    except json.JSONDecodeError as exc:
        raise UserError(f"{path.name}: not valid JSON: {exc.msg} at line {exc.lineno} column {exc.colno}") from None


def name_of(file: str) -> PublishedName:
    """The parts of a published file's name (or stem); a UserError for another name."""
    name = parse_published_name(file)
    if name is None:
        raise UserError(f"{file}: not a published SARTCo file name (expected names like sb_so_test.json, "
                        f"rb_so_test_hc.json)")
    return name


def walk(data: Any, file: str) -> Iterator[tuple[str, Any]]:
    """(sample id, sample) of one published file's content, in file order. The structure must be the
    one of the file's name (its board and object type); otherwise a UserError naming file and field."""
    kind = name_of(file).kind
    board, theirs = kind.board, kind.published_object
    if not isinstance(data, dict):
        raise UserError(f"{file}: expected a JSON object at the top level, got {type(data).__name__}")
    if board not in data:
        raise UserError(f"{file}: field '{board}' missing (the board type of this file's prefix)")
    if set(data) != {board}:
        raise UserError(f"{file}: unexpected top-level field(s) {sorted(set(data) - {board})}; expected only '{board}'")
    by_object = data[board]
    if not isinstance(by_object, dict) or theirs not in by_object:
        raise UserError(f"{file}: field '{board}.{theirs}' missing (the object type of this file's prefix)")
    counts = by_object[theirs]
    if not isinstance(counts, dict):
        raise UserError(f"{file}: field '{board}.{theirs}' must be an object of counts")
    for count, combos in counts.items():
        if not isinstance(combos, dict):
            raise UserError(f"{file}: field '{board}.{theirs}.{count}' must be an object of combo names")
        for combo, samples in combos.items():
            if not isinstance(samples, list):
                raise UserError(f"{file}: field '{board}.{theirs}.{count}.{combo}' must be a list of samples")
            for index, sample in enumerate(samples):
                yield f"{board}/{theirs}/{count}/{combo}/{index}", sample


def read_samples(path: Path) -> list[tuple[str, Any]]:
    """(sample id, sample) of one published file, in file order."""
    return list(walk(read_json(path), path.name))


def base_file(file: str) -> str:
    """The template file (test, val or train split) of a published file: rb_so_test_hc -> rb_so_test.json."""
    name = name_of(file)
    return name.kind.published_stem(name.split) + ".json"


def variant_file(file: str, source: str) -> str:
    """The published file of one instruction source of a template file: sb_so_test.json, human -> sb_so_test_hc.json."""
    name = name_of(file)
    return name.kind.published_stem(name.split, source) + ".json"


def gold_boards(gold_dir: Path | None, file: str) -> dict[str, Any] | None:
    """The authors' boards (sample id -> cells) of a published file (a variant: its test file's), or
    None when gold_dir has none."""
    if gold_dir is None:
        return None
    require_data(gold_dir)
    path = gold_dir / base_file(file)
    if not path.is_file():
        return None
    data = read_json(path)
    if not isinstance(data, dict):
        raise UserError(f"{path.name} (gold boards): expected an object of sample id -> cells")
    return data


def discover(src: Path) -> list[tuple[Path, PublishedName]]:
    """The published files of a folder: template files first, then the variants in source order, each
    group by board kind and split. Other .json files are skipped with a line on stderr."""
    require_data(src)
    if not src.is_dir():
        raise UserError(f"{src}: not a directory")
    found, unknown = [], []
    for path in sorted(src.iterdir()):
        name = parse_published_name(path.name) if path.suffix == ".json" else None
        if name is not None:
            found.append((path, name))
        elif path.suffix == ".json":
            unknown.append(path.name)
    for file in unknown:
        print(f"sartco import: skipping {file}: not a published SARTCo file name", file=sys.stderr)
    if not found:
        raise UserError(f"{src}: no published SARTCo files (expected names like sb_so_test.json, rb_so_test_hc.json)")
    present = {path.name for path, _ in found}
    for path, name in found:
        if name.source != "template" and base_file(path.name) not in present:
            raise UserError(f"{path.name}: its test file {base_file(path.name)} is missing from {src}")
    return sorted(found, key=lambda item: (item[1].source != "template", SOURCES.index(item[1].source),
                                           BOARD_KINDS.index(item[1].kind), SPLITS.index(item[1].split)))
