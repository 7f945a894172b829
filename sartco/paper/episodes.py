"""Every Table 3 cell of the paper protocol on the published test files, as episodes.

    build_episodes(published_dir=DEFAULT_PUBLISHED, generated_dir=DEFAULT_GENERATED,
                   files=None, variants=None) -> list[PaperEpisode]

One episode per (published test file, sample, dialogue key) in a fixed order: files in Table 3
order (sb_so, rb_so, rb_cho; template, human, CodeLlama, GPT-4, Claude), samples in file order,
then the file's own variants (a variant file is scored only on the key it adds). Everything is
read at call time from ../shared/sartco-data: published/ (the samples), gold_boards/ (targets),
paper-protocol/*.template (the authors' prompts, filled with string.Template.safe_substitute).

PaperEpisode.to_json():
  id             "<file>/<sample>/<variant>", e.g. "rb_so_test_hc/regular/simple/2/bw/0/regular_hai"
  protocol       "paper"
  file, sample, variant   published file stem, sample id (as in gold_boards/), dialogue key
  cell           {"instructions", "board", "object", "task", "source"} (table3.json's cell fields;
                 source: template | human | codellama | gpt4 | claude)
  messages       the user message of each turn, exactly what the authors' game sends: the first is
                 the filled template + "\n" + "Instruction\n<text>\n"; later turns (multi_turn)
                 "Instruction\n<text>\n"
  gold           per turn the gold keys: {"output"} or {"function": function + "\n" + usage, "usage"}
  given_function regular boards: the sample's gold object function (put in front for ES); else ""
  target         the gold board of the whole sample, canonical cells form (gold_boards/)
  examples_from  "published rb_so_train" or "generated <version> train split (...never published)"
  mock_answers   per turn the gold answer in the authors' answer format ("Output\n<code>\n" or
                 "Function\n<function>\n\nUsage\n<usage>\n"); read_answer gives back the gold code

In-context examples (5): candidates are the turns of the training samples with the test sample's
number of components and another combination (regular boards: another seed_template), in file
order, as (instruction, code) of the training variant (single_turn_hai/_mg -> single_turn,
single_turn_hai_sc -> single_turn_sc, regular_hai/_mg -> regular); random.seed("42") then
random.sample(candidates, 5). rb_so takes them from the published rb_so_train.json; sb_so and
rb_cho (whose training files were never published) from our generated train split
(instances/v1 by default), converted to the same candidate form.
"""
from __future__ import annotations

import json
import random
from dataclasses import asdict, dataclass, field
from functools import lru_cache
from pathlib import Path
from string import Template
from typing import Any, Iterable

from sartco.errors import UserError
from sartco.instances.generate import load_dataset
from sartco.instances.prompts import instruction_text
from sartco.program.gold import DEFAULT_DATA, base_of, samples

from .vocabulary import (INSTRUCTION_LABEL, LABELS, PROTOCOL, VARIANTS, PublishedFile, published_test_files,
                         template_name, training_stem, variants_of)

DEFAULT_PUBLISHED = DEFAULT_DATA / "published"
DEFAULT_GENERATED = Path(__file__).resolve().parents[2] / "instances" / "v1"
N_EXAMPLES = 5
EXAMPLE_SEED = "42"


@dataclass(frozen=True, slots=True)
class PaperEpisode:
    id: str
    file: str
    sample: str
    variant: str
    cell: dict
    messages: list
    gold: list
    given_function: str
    target: dict
    examples_from: str
    mock_answers: list
    protocol: str = PROTOCOL

    def to_json(self) -> dict:
        return asdict(self)

    @classmethod
    def from_json(cls, data: dict) -> "PaperEpisode":
        return cls(**{k: data[k] for k in cls.__dataclass_fields__ if k in data})


# ----------------------------------------------------------------------------- answers and examples

def labelled(code: dict, family: str) -> str:
    """A turn's code under the authors' labels, as in the examples block (and the mock answer):
    "Output\n<output>\n" or "Function\n<function>\n\nUsage\n<usage>\n"."""
    if family == "single_turn":
        function, usage = LABELS[family]
        return f"{function}\n{code['function']}\n\n{usage}\n{code['usage']}\n"
    return f"{LABELS[family][0]}\n{code['output']}\n"


def instruction(text: str) -> str:
    return f"{INSTRUCTION_LABEL}\n{text}\n"


def examples_block(candidates: Iterable[dict], family: str) -> str:
    """The INCONTEXT_SAMPLES text: one entry per example, joined with "\n"."""
    return "\n".join(f"{INSTRUCTION_LABEL}\n{c['text']}\n\n{labelled(c['code'], family)}" for c in candidates)


def editor_code(editor: Any, family: str) -> dict:
    """The code of one dialogue turn's <Editor> as the family's answer keys."""
    if family == "multi_turn":
        return {"output": editor}
    if family == "single_turn":
        return {"function": editor["function"], "usage": editor["usage"]}
    return {"output": editor["output"]}


def gold_of(code: dict, family: str) -> dict:
    """README "Scoring": single_turn's function key holds function + "\n" + usage."""
    if family == "single_turn":
        return {"function": code["function"] + "\n" + code["usage"], "usage": code["usage"]}
    return dict(code)


@dataclass(frozen=True, slots=True)
class TrainItem:
    count: str
    combo: str
    seed: str | None           # regular boards: the seed_template stem; simple boards: None
    turns: dict = field(default_factory=dict)   # training variant -> [{"text", "code"}, ...]


def _stem(path: str) -> str:
    return Path(path).stem


def published_pool(content: dict, family_of_training: dict[str, str]) -> list[TrainItem]:
    """A published training file's samples as candidates, in file order."""
    items = []
    for board_type, sid, sample in samples(content):
        _, _, count, combo, _ = sid.split("/")
        turns = {}
        for training, family in family_of_training.items():
            dialogue = sample.get("dialogues", {}).get(training)
            if dialogue:
                turns[training] = [{"text": t["<Programmer>"], "code": editor_code(t["<Editor>"], family)}
                                   for t in dialogue["instructions"]]
        seed = _stem(sample["seed_template"]) if board_type == "regular" else None
        items.append(TrainItem(count, combo, seed, turns))
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
                    code = r["code"][task]
                    if family == "multi_turn":
                        texts = instruction_text(r, task, "template")
                        turns[training] = [{"text": t, "code": {"output": s}} for t, s in zip(texts, code["steps"])]
                    elif family == "single_turn":
                        turns[training] = [{"text": instruction_text(r, task, "template"),
                                            "code": {"function": code["function"], "usage": code["usage"]}}]
                    else:
                        turns[training] = [{"text": instruction_text(r, task, "template"), "code": {"output": code["output"]}}]
                seed = r["arrangement"] if r["board_type"] == "regular" else None
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


# ----------------------------------------------------------------------------- reading the data

def _read(path: Path) -> Any:
    try:
        return json.loads(path.read_text(encoding="utf-8"))
    except (OSError, ValueError) as exc:
        raise UserError(f"{path}: not readable as JSON ({exc})") from None


@lru_cache(maxsize=8)
def _template(path: Path) -> Template:
    if not path.is_file():
        raise UserError(f"{path}: paper-protocol prompt template missing")
    return Template(path.read_text(encoding="utf-8"))


class _Pools:
    """The example pool of each board/object type, loaded once per build_episodes call."""

    def __init__(self, published_dir: Path, generated_dir: Path):
        self.published_dir, self.generated_dir = published_dir, generated_dir
        self.pools: dict[str, tuple[list[TrainItem], str]] = {}
        self.selected: dict[tuple, list[dict]] = {}

    def pool(self, file: PublishedFile) -> tuple[list[TrainItem], str]:
        if file.prefix not in self.pools:
            families = {v.training: v.family for v in VARIANTS.values()
                        if (v.family == "regular") == (file.board == "regular")}
            path = self.published_dir / f"{training_stem(file.prefix)}.json"
            if path.is_file():
                where, origin, records = path.name, f"published {path.stem}", _read(path)
                convert = published_pool
            else:
                manifest, files = load_dataset(self.generated_dir)
                name = f"{file.board}_{file.object}_train.json"
                if name not in files:
                    raise UserError(f"{self.generated_dir}: no {name} (the train split that stands in for "
                                    f"the unpublished {path.name})")
                version = manifest.get("version", self.generated_dir.name)
                where, records, convert = self.generated_dir / name, files[name], generated_pool
                origin = f"generated {version} train split (the authors' {path.stem} was never published)"
            try:
                self.pools[file.prefix] = (convert(records, families), origin)
            except (KeyError, TypeError, ValueError, AttributeError) as exc:
                raise UserError(f"{where}: malformed training sample ({type(exc).__name__}: {exc})") from None
        return self.pools[file.prefix]

    def examples(self, file: PublishedFile, training, count, combo, seed) -> tuple[list[dict], str]:
        pool, origin = self.pool(file)
        key = (file.prefix, training, count, combo, seed)
        if key not in self.selected:
            self.selected[key] = select(candidates(pool, training, count, combo, seed))
        return self.selected[key], origin


def first_message(template: Template, sample: dict, variant: str, examples: list[dict], text: str) -> str:
    family = VARIANTS[variant].family
    fields = {"INSTRUCTION_LABEL": INSTRUCTION_LABEL, "INCONTEXT_SAMPLES": examples_block(examples, family)}
    if family == "single_turn":
        fields["OUTPUT_LABEL_HORDER"], fields["OUTPUT_LABEL_HORDER_USAGE"] = LABELS[family]
    else:
        fields["OUTPUT_LABEL"] = LABELS[family][0]
    if family == "regular":
        fields["COMBO_NAME"] = sample["combo_name"]
        fields["COLORS"] = str(sample["colors"])
    return template.safe_substitute(fields) + "\n" + instruction(text)


def build_episodes(published_dir: Path = DEFAULT_PUBLISHED, generated_dir: Path = DEFAULT_GENERATED,
                   files: list[str] | None = None, variants: list[str] | None = None) -> list[PaperEpisode]:
    """Every Table 3 cell of the paper protocol on the published test files (see the module doc).
    files / variants: keep only these file stems / dialogue keys (unknown names are a UserError)."""
    published_dir, generated_dir = Path(published_dir), Path(generated_dir)
    data_dir = published_dir.parent
    known = published_test_files()
    if files is not None:
        unknown = sorted(set(files) - {f.stem for f in known})
        if unknown:
            raise UserError(f"unknown test file(s) {', '.join(unknown)}; expected one of "
                            f"{', '.join(f.stem for f in known)}")
    if variants is not None:
        unknown = sorted(set(variants) - set(VARIANTS))
        if unknown:
            raise UserError(f"unknown variant(s) {', '.join(unknown)}; expected one of {', '.join(VARIANTS)}")
    gold_dir = data_dir / "gold_boards"
    gold_stems = sorted(p.stem for p in gold_dir.glob("*.json"))
    pools = _Pools(published_dir, generated_dir)
    episodes = []
    for file in known:
        if files is not None and file.stem not in files:
            continue
        keys = [v for v in variants_of(file.board, file.source) if variants is None or v in variants]
        path = published_dir / f"{file.stem}.json"
        if not keys or not path.is_file():
            if files is not None and not path.is_file():
                raise UserError(f"{path}: published test file missing")
            continue
        base = base_of(file.stem, gold_stems)
        boards = _read(gold_dir / f"{base}.json") if base else {}
        for _, sid, sample in samples(_read(path)):
            for variant in keys:
                try:
                    episodes.append(_episode(pools, data_dir, file, sid, sample, variant, boards.get(sid)))
                except (KeyError, TypeError, IndexError) as exc:
                    raise UserError(f"{path.name} {sid}: malformed sample for {variant} ({type(exc).__name__}: {exc})") from None
    return episodes


def _episode(pools: _Pools, data_dir: Path, file: PublishedFile, sid: str, sample: dict, variant: str,
             target: dict | None) -> PaperEpisode:
    v = VARIANTS[variant]
    turns = sample["dialogues"][variant]["instructions"]
    texts = [t["<Programmer>"] for t in turns]
    codes = [editor_code(t["<Editor>"], v.family) for t in turns]
    _, _, count, combo, _ = sid.split("/")
    seed = _stem(sample["seed_template"]) if file.board == "regular" else None
    examples, origin = pools.examples(file, v.training, count, combo, seed)
    template = _template(data_dir / "paper-protocol" / template_name(variant))
    messages = [first_message(template, sample, variant, examples, texts[0])] + [instruction(t) for t in texts[1:]]
    return PaperEpisode(
        id=f"{file.stem}/{sid}/{variant}", file=file.stem, sample=sid, variant=variant,
        cell={"instructions": v.instructions, "board": file.board, "object": file.object, "task": v.task,
              "source": file.source},
        messages=messages, gold=[gold_of(c, v.family) for c in codes],
        given_function=sample["code"]["function"] if v.family == "regular" else "",
        target=target if target is not None else {}, examples_from=origin,
        mock_answers=[labelled(c, v.family) for c in codes],
    )
