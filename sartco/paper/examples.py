"""The in-context examples of the paper protocol's episodes (5 per episode): candidates are the turns of the training samples with the test sample's
number of components and another combination (regular boards: another seed_template), in file
order, as (instruction, code) of the training variant (single_turn_hai/_mg -> single_turn,
single_turn_hai_sc -> single_turn_sc, regular_hai/_mg -> regular); random.seed("42") then
random.sample(candidates, 5). rb_so takes them from the published rb_so_train.json; sb_so and
rb_cho (whose training files were never published) from our generated train split
(instances/v1 by default), converted to the same candidate form.
"""
from __future__ import annotations

import random
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from sartco.dataset import REGULAR_SIMPLE, PublishedName
from sartco.errors import UserError
from sartco.instances.prompts import instruction_text
from sartco.instances.storage import load_dataset
from sartco.published.files import read_samples
from sartco.published.samples import template_stem

from .vocabulary import GOLD_KEYS, VARIANTS, training_stem

N_EXAMPLES = 5
EXAMPLE_SEED = "42"


def editor_code(editor: Any, family: str) -> dict:
    """The code of one dialogue turn's <Editor> (a multi-turn editor: the put line itself; else a
    code dict, ours or the authors') as the family's gold keys."""
    if family == "multi_turn":
        return {"output": editor}
    return {key: editor[key] for key in GOLD_KEYS[family]}


def dialogue_turns(dialogue: dict, family: str) -> list[dict]:
    """A published dialogue's turns as {"text": <Programmer>, "code": editor_code(<Editor>)}."""
    return [{"text": t["<Programmer>"], "code": editor_code(t["<Editor>"], family)} for t in dialogue["instructions"]]


def sample_key(sid: str, sample: dict) -> tuple[str, str, str | None]:
    """(number of components, combination, regular boards: seed_template stem) of a published sample:
    what the example rule compares."""
    board_type, _, count, combo, _ = sid.split("/")
    seed = template_stem(sample["seed_template"]) if board_type == REGULAR_SIMPLE.board else None
    return count, combo, seed


@dataclass(frozen=True, slots=True)
class TrainItem:
    count: str
    combo: str
    seed: str | None           # regular boards: the seed_template stem; simple boards: None
    turns: dict = field(default_factory=dict)   # training variant -> [{"text", "code"}, ...]


def published_pool(samples: list[tuple[str, dict]], family_of_training: dict[str, str]) -> list[TrainItem]:
    """A published training file's samples (sartco.published.files.read_samples) as candidates, in file order."""
    items = []
    for sid, sample in samples:
        turns = {}
        for training, family in family_of_training.items():
            dialogue = sample.get("dialogues", {}).get(training)
            if dialogue:
                turns[training] = dialogue_turns(dialogue, family)
        items.append(TrainItem(*sample_key(sid, sample), turns))
    return items


def generated_pool(records: list[dict], family_of_training: dict[str, str]) -> list[TrainItem]:
    """Our generated train records in the published candidate form and file order: by number of
    components, then combination in order of first appearance, then records in list order."""
    grouped: dict[int, dict[str, list[dict]]] = {}
    for r in records:
        grouped.setdefault(len(r["shapes"]), {}).setdefault(r["combo_name"], []).append(r)
    items = []
    for count in sorted(grouped):
        for combo, group in grouped[count].items():
            for r in group:
                turns = {}
                for training, family in family_of_training.items():
                    task = VARIANTS[training].task
                    code, text = r["code"][task], instruction_text(r, task, "template")
                    if family == "multi_turn":
                        turns[training] = [{"text": t, "code": editor_code(s, family)} for t, s in zip(text, code["steps"])]
                    else:
                        turns[training] = [{"text": text, "code": editor_code(code, family)}]
                seed = r["arrangement"] if r["board_type"] == REGULAR_SIMPLE.board else None
                items.append(TrainItem(str(count), combo, seed, turns))
    return items


def candidates(pool: list[TrainItem], training: str, count: str, combo: str, seed: str | None) -> list[dict]:
    """README: same number of components, another combination (regular: another seed_template),
    every turn of the training variant's dialogue, in file order."""
    return [turn for item in pool
            if item.count == count and item.combo != combo and (seed is None or item.seed != seed)
            for turn in item.turns.get(training, [])]


def select(cands: list[dict], k: int = N_EXAMPLES) -> list[dict]:
    """random.seed("42") immediately followed by random.sample(candidates, k)."""
    if len(cands) < k:
        raise UserError(f"only {len(cands)} in-context example candidates, {k} needed")
    return random.Random(EXAMPLE_SEED).sample(cands, k)


class Pools:
    """The example pool of each board kind, loaded once per build_episodes call."""

    def __init__(self, published_dir: Path, generated_dir: Path):
        self.published_dir, self.generated_dir = published_dir, generated_dir
        self.pools: dict[str, tuple[list[TrainItem], str]] = {}
        self.selected: dict[tuple, list[dict]] = {}
        self.generated: tuple[dict, dict] | None = None  # the generated dataset, read once for every kind

    def generated_dataset(self) -> tuple[dict, dict]:
        if self.generated is None:
            self.generated = load_dataset(self.generated_dir)
        return self.generated

    def pool(self, file: PublishedName) -> tuple[list[TrainItem], str]:
        kind = file.kind
        if kind.prefix not in self.pools:
            families = {v.training: v.family for v in VARIANTS.values() if v.task in kind.tasks()}
            path = self.published_dir / f"{training_stem(kind)}.json"
            if path.is_file():
                where, origin, records = path.name, f"published {path.stem}", read_samples(path)
                convert = published_pool
            else:
                manifest, files = self.generated_dataset()
                name = kind.dataset_file("train")
                if name not in files:
                    raise UserError(f"{self.generated_dir}: no {name} (the train split that stands in for "
                                    f"the unpublished {path.name})")
                version = manifest.get("version", self.generated_dir.name)
                where, records, convert = self.generated_dir / name, files[name], generated_pool
                origin = f"generated {version} train split (the authors' {path.stem} was never published)"
            try:
                self.pools[kind.prefix] = (convert(records, families), origin)
            except (KeyError, TypeError, ValueError, AttributeError) as exc:
                raise UserError(f"{where}: malformed training sample ({type(exc).__name__}: {exc})") from None
        return self.pools[kind.prefix]

    def examples(self, file: PublishedName, training, count, combo, seed) -> tuple[list[dict], str]:
        pool, origin = self.pool(file)
        key = (file.kind.prefix, training, count, combo, seed)
        if key not in self.selected:
            self.selected[key] = select(candidates(pool, training, count, combo, seed))
        return self.selected[key], origin


