"""What every instance file of both games shares: one generator class that runs a file's build
function, the records of a dataset split, what a file records about its dataset, writing a file.

    InstanceFile(game_dir, build, feedback_attempts=None)   build(gen, seed, **kwargs) fills gen
    write(gen, name, seed, **kwargs) -> path                  writes games/<game>/in/<name>, says what it holds
    records(folder, files, kind, split)                      one split's records (UserError if missing)
    dataset_info(manifest, path, seed, n_examples)           cobot_instruct's `dataset` field
    spread(items, n)                                         n items evenly spread (cobot_describe's slices)
"""
from __future__ import annotations

import os
from pathlib import Path
from typing import Callable

from clemcore.clemgame import GameInstanceGenerator

from sartco.clem.instruct.instruct_generator import InstructGenerator
from sartco.dataset import BoardKind
from sartco.errors import UserError
from sartco.settings import workspace

GAMES = workspace() / "games"


class InstanceFile(InstructGenerator):
    """One instance file: on_generate runs the file's build function, which fills `instances`
    (through add_experiment / experiment / add_game_instance / add_episodes) and sets `source`,
    the input an error line names when no episode came out of it."""

    def __init__(self, game_dir: str | Path, build: Callable, feedback_attempts: int | None = None):
        super().__init__(str(game_dir), feedback_attempts)
        self.build = build

    def on_generate(self, seed: int, **kwargs):
        self.build(self, seed, **kwargs)


def write(gen: GameInstanceGenerator, name: str, seed: int, **kwargs) -> str:
    """Write in/<name> of the generator's game folder (clemcore's GameInstanceGenerator.generate:
    it seeds random and numpy with `seed`) and print one line saying what it holds."""
    path = gen.generate(name, seed=seed, **kwargs)
    exps = gen.instances["experiments"]
    print(f"{path}: {len(exps)} experiments, {sum(len(e['game_instances']) for e in exps)} episodes")
    return path


def records(folder: Path, files: dict, kind: BoardKind, split: str) -> list[dict]:
    """The records of one split (files: from sartco.instances.storage.load_dataset of folder)."""
    name = kind.dataset_file(split)
    if name not in files:
        raise UserError(f"{Path(folder) / name}: missing (a dataset of `sartco generate` has every split)")
    return files[name]


def dataset_info(manifest: dict, path: Path, seed: int, n_examples: int, examples_from: dict | None = None) -> dict:
    """What a cobot_instruct instance file records about its dataset (examples_from: the dataset
    of the in-context examples when it is another one)."""
    info = {"version": manifest["version"], "source": manifest["source"], "seed": manifest.get("seed"),
            "path": os.path.relpath(path, workspace())}
    if examples_from is not None:
        info["examples_from"] = examples_from
    return {**info, "generator_seed": seed, "n_examples": n_examples}


def spread(items: list, n: int | None) -> list:
    """n items evenly spread over the list (all when n is None or too large)."""
    if n is None or n >= len(items):
        return list(items)
    return [items[i * len(items) // n] for i in range(n)]
