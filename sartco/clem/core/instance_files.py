"""What every instance file of both games shares (the files: sartco.games.instruct.instancegenerator,
sartco.games.describe.instancegenerator; the command: sartco.instancegen): the records of a dataset split,
the line that says what a written file holds. Each game writes its files itself (its generator's
`generate`, which calls its own on_generate), so nothing here calls back into a game.

    written(gen, path) -> path            one line: the file, its experiments and episodes
    stamp(gen)                            the file's `generator` field: which release wrote it
    records(folder, files, kind, split)   one split's records (UserError if missing)
    spread(items, n)                      n items evenly spread (cobot_describe's slices)
"""
from __future__ import annotations

from importlib import metadata
from pathlib import Path

from clemcore.clemgame import GameInstanceGenerator

from sartco.dataset import BoardKind
from sartco.errors import UserError


PACKAGE = "sartco-bench"


def stamp(gen: GameInstanceGenerator) -> None:
    """Record in the file being generated which generator wrote it: {"package", "version"} (the
    installed release; the same for every commit of a release, so the same seed and config still
    give the same bytes). run.json copies it (sartco.clem.core.provenance.GENERATION_FIELDS)."""
    try:
        version = metadata.version(PACKAGE)
    except metadata.PackageNotFoundError:  # run from a checkout that was never installed
        version = None
    gen.instances["generator"] = {"package": PACKAGE, "version": version}


def written(gen: GameInstanceGenerator, path: str) -> str:
    """Say in one line what the file at `path`, just written by gen.generate (clemcore's: it seeds
    random and numpy with the seed), holds; return its path."""
    exps = gen.instances["experiments"]
    print(f"{path}: {len(exps)} experiments, {sum(len(e['game_instances']) for e in exps)} episodes")
    return path


def records(folder: Path, files: dict, kind: BoardKind, split: str) -> list[dict]:
    """The records of one split (files: from sartco.instances.storage.load_dataset of folder)."""
    name = kind.dataset_file(split)
    if name not in files:
        raise UserError(f"{Path(folder) / name}: missing (a dataset of `sartco generate` has every split)")
    return files[name]


def spread(items: list, n: int | None) -> list:
    """n items evenly spread over the list (all when n is None or too large)."""
    if n is None or n >= len(items):
        return list(items)
    return [items[i * len(items) // n] for i in range(n)]
