"""in/instances_fresh.json (game entry cobot_instruct_fresh; issue 24 item 3): the contamination
check, written by `python games/cobot_instruct/instancegenerator.py --fresh SEED`.

For every Table 3 cell two experiments that differ in the boards alone, so that their scores
compare like with like (same prompt, same in-context examples from the generated train split,
same template instructions, same generator seed):
  <cell>_<task>_template_published   the published test boards (imported, `sartco import`)
  <cell>_<task>_template_fresh<SEED>  as many fresh boards (sartco.instances.fresh), one per
                                      published board, of its stratum, in no published file and
                                      no seed-42 file
Each records `boards` ("published" | "fresh") and `fresh_seed`; `sartco report` puts them side by
side in contamination.md (sartco.report.contamination). Only the template source: the fresh boards
have no human- or model-written instructions.
"""
from __future__ import annotations

from argparse import Namespace
from pathlib import Path

from sartco.errors import UserError
from sartco.instances.config import parse_config
from sartco.instances.fresh import board_keys, fresh_boards
from sartco.instances.storage import load_dataset
from sartco.settings import shown

from .instancegenerator import CELLS, DEFAULT_PUBLISHED, InstructGenerator, write

SOURCE = "template"


class FreshInstanceGenerator(InstructGenerator):
    """cells: the game's Table 3 cells, (board kind, task, ...) tuples."""

    def __init__(self, game_dir: str, cells: list[tuple]):
        super().__init__(game_dir)
        self.cells = cells

    def on_generate(self, seed: int, dataset_dir: Path, fresh_seed: int, published_dir: Path | None = None,
                    n_examples: int = 5, per_experiment: int | None = None):
        """seed: the in-context examples' (as in the other files); dataset_dir: the seed-42 dataset (its
        config is the fresh boards' config, its train split the examples' pool); per_experiment: the
        first N boards of each cell (None: all)."""
        published_dir = self.source = published_dir or DEFAULT_PUBLISHED
        manifest, files = load_dataset(dataset_dir)
        if "config" not in manifest:
            raise UserError(f"{dataset_dir / 'manifest.json'}: no 'config' (the fresh boards follow the config "
                            f"of a dataset written by `sartco generate`)")
        for train in (kind.dataset_file("train") for kind, *_ in self.cells):
            if train not in files:
                raise UserError(f"{dataset_dir / train}: missing (the in-context examples come from its train split)")
        pub_manifest, pub_files = load_dataset(published_dir)
        config = parse_config(manifest["config"], str(dataset_dir / "manifest.json"))
        fresh, report = fresh_boards(config, fresh_seed, pub_files, board_keys(pub_files, files))
        where = {"published": shown(published_dir), "generated": shown(dataset_dir)}
        self.instances["dataset"] = {**where, "fresh_seed": fresh_seed, "generator_seed": seed,
                                     "n_examples": n_examples}
        for kind, task, *_ in self.cells:
            name, pool = kind.dataset_file("test"), files[kind.dataset_file("train")]
            for boards, records in (("published", pub_files.get(name, [])), ("fresh", fresh.get(name, []))):
                dataset = {"version": pub_manifest["version"] if boards == "published" else f"fresh{fresh_seed}",
                           "source": boards, "seed": fresh_seed if boards == "fresh" else None, **where,
                           "generator_seed": seed, "n_examples": n_examples}
                suffix = "published" if boards == "published" else f"fresh{fresh_seed}"
                exp = self.experiment(kind, task, SOURCE, "test", dataset, variant=suffix, boards=boards,
                                      fresh_seed=fresh_seed)
                self.add_episodes(exp, records[:per_experiment], task, SOURCE, pool, seed, n_examples)
        print(f"fresh boards (seed {fresh_seed}): {sum(report.boards.values())} "
              f"({', '.join(f'{k} {n}' for k, n in report.boards.items())}); also in the published data or the "
              f"seed-42 dataset: {report.overlap}; candidates rejected for being one: {report.rejected}; "
              f"stratum fallbacks: {report.fallbacks}")


def instances_fresh(options: Namespace, game_dir: Path) -> str:
    """The file function of `sartco instances instruct-fresh` (as the others of instancegenerator)."""
    return write(FreshInstanceGenerator(str(game_dir), CELLS), "instances_fresh.json", options.seed,
                 dataset_dir=options.dataset, n_examples=options.examples, fresh_seed=options.fresh,
                 published_dir=options.published, per_experiment=options.fresh_episodes or None)
