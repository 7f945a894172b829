"""What every instance file of both games shares (the files: sartco.games.instruct.instancegenerator,
sartco.games.describe.instancegenerator; the command: sartco.instancegen): the generators' base, the
board fields of an episode, the records of a dataset split, the line that says what a written file
holds. Each game writes its files itself (its generator's `generate`, which calls its own
on_generate), so nothing here calls back into a game.

    InstanceGenerator                     the games' generator base: it never writes an instance
                                          file without episodes (require_episodes)
    written(gen, path) -> path            one line: the file, its experiments and episodes (after
                                          each game's write(gen, name, seed, **kwargs))
    board_fields(record, task)            an episode's fields from one board record and a task
    stamp(gen)                            the file's `generator` field: which release wrote it
    records(folder, files, kind, split)   one split's records (UserError if missing)
    spread(items, n)                      n items evenly spread (cobot_describe's slices)
"""
from __future__ import annotations

from importlib import metadata
from pathlib import Path

from clemcore.clemgame import GameInstanceGenerator

from sartco.dataset import BoardKind
from sartco.episode import BuildEpisode
from sartco.errors import UserError
from sartco.instances.prompts import gold_code
from sartco.settings import data_error

PACKAGE = "sartco-bench"


def require_episodes(instances: dict, source) -> None:
    """UserError unless the generated instances hold an episode: a generator whose input is
    missing (e.g. ../shared) must say so, not replace an instance file with an empty one."""
    if not any(e.get("game_instances") for e in instances.get("experiments", [])):
        if not Path(source).exists():  # a missing data folder: the setting to give, not a path that stands for none
            missing = data_error(source)
            raise UserError(f"{missing or f'{source}: no such file or folder'}; no instance file written")
        raise UserError(f"{source}: no episodes were generated from it; no instance file written")


class InstanceGenerator(GameInstanceGenerator):
    """The games' GameInstanceGenerator: it writes no instance file without episodes (on_generate
    sets `source`, the input that the line names)."""

    source: str | Path = "the generator's input"

    def store_file(self, data, file_name: str, sub_dir: str | None = None) -> str:
        if sub_dir == "in":
            require_episodes(data, self.source)
        return super().store_file(data, file_name, sub_dir=sub_dir)


def written(gen: GameInstanceGenerator, path: str) -> str:
    """Say in one line what the file at `path`, just written by gen.generate (clemcore's: it seeds
    random and numpy with the seed, then calls gen.on_generate), holds; return its path. Each game's
    `write(gen, name, seed, **kwargs)` calls gen.generate itself (so that nothing here calls back
    into a game) and then this."""
    exps = gen.instances["experiments"]
    print(f"{path}: {len(exps)} experiments, {sum(len(e['game_instances']) for e in exps)} episodes")
    return path


def board_fields(record: dict, task: str) -> BuildEpisode:
    """The fields of a game episode that come from one board record and a task, the same in every
    game that ends in a build (the game's generator adds its prompts and turns; clemcore's
    add_game_instance sets game_id). given_code: the code the program starts with (repetition: the
    given object function); gold_code: the gold answer in the task's style (EM and CodeBLEU)."""
    return {
        "board_id": record["id"], "board_type": record["board_type"], "object_type": record["object_type"],
        "combo_name": record["combo_name"], "task": task, "rows": record["rows"], "cols": record["cols"],
        "target": record["target"],
        "given_code": record["code"]["repetition"]["function"] if task == "repetition" else "",
        "gold_code": gold_code(record, task),
    }


def stamp(gen: GameInstanceGenerator) -> None:
    """Record in the file being generated which generator wrote it: {"package", "version"} (the
    installed release; the same for every commit of a release, so the same seed and config still
    give the same bytes). run.json copies it (sartco.clem.core.provenance.GENERATION_FIELDS)."""
    try:
        version = metadata.version(PACKAGE)
    except metadata.PackageNotFoundError:  # run from a checkout that was never installed
        version = None
    gen.instances["generator"] = {"package": PACKAGE, "version": version}


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
