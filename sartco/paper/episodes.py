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

In-context examples: sartco.paper.examples.
"""
from __future__ import annotations

from dataclasses import asdict, dataclass
from functools import lru_cache
from pathlib import Path
from string import Template
from typing import Iterable

from sartco.dataset import PublishedName
from sartco.errors import UserError
from sartco.settings import workspace
from sartco.published.files import PUBLISHED, gold_boards, read_samples

from .examples import Pools, dialogue_turns, sample_key
from .vocabulary import INSTRUCTION_LABEL, LABELS, PROTOCOL, VARIANTS, published_test_files, template_name, variants_of

DEFAULT_PUBLISHED = PUBLISHED
DEFAULT_GENERATED = workspace() / "instances" / "v1"


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


# ----------------------------------------------------------------------------- answers

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


def gold_of(code: dict, family: str) -> dict:
    """README "Scoring": single_turn's function key holds function + "\n" + usage."""
    if family == "single_turn":
        return {"function": code["function"] + "\n" + code["usage"], "usage": code["usage"]}
    return dict(code)


# ----------------------------------------------------------------------------- the episodes

@lru_cache(maxsize=8)
def _template(path: Path) -> Template:
    if not path.is_file():
        raise UserError(f"{path}: paper-protocol prompt template missing")
    return Template(path.read_text(encoding="utf-8"))


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
    pools = Pools(published_dir, generated_dir)
    episodes = []
    for file in known:
        if files is not None and file.stem not in files:
            continue
        keys = [v for v in variants_of(file.kind, file.source) if variants is None or v in variants]
        path = published_dir / f"{file.stem}.json"
        if not keys or not path.is_file():
            if files is not None and not path.is_file():
                raise UserError(f"{path}: published test file missing")
            continue
        boards = gold_boards(data_dir / "gold_boards", path.name) or {}
        for sid, sample in read_samples(path):
            for variant in keys:
                try:
                    episodes.append(_episode(pools, data_dir, file, sid, sample, variant, boards.get(sid)))
                except (KeyError, TypeError, IndexError) as exc:
                    raise UserError(f"{path.name} {sid}: malformed sample for {variant} ({type(exc).__name__}: {exc})") from None
    return episodes


def _episode(pools: Pools, data_dir: Path, file: PublishedName, sid: str, sample: dict, variant: str,
             target: dict | None) -> PaperEpisode:
    v = VARIANTS[variant]
    turns = dialogue_turns(sample["dialogues"][variant], v.family)
    texts, codes = [t["text"] for t in turns], [t["code"] for t in turns]
    examples, origin = pools.examples(file, v.training, *sample_key(sid, sample))
    template = _template(data_dir / "paper-protocol" / template_name(variant))
    messages = [first_message(template, sample, variant, examples, texts[0])] + [instruction(t) for t in texts[1:]]
    return PaperEpisode(
        id=f"{file.stem}/{sid}/{variant}", file=file.stem, sample=sid, variant=variant,
        cell={"instructions": v.instructions, "board": file.kind.board, "object": file.kind.object, "task": v.task,
              "source": file.source},
        messages=messages, gold=[gold_of(c, v.family) for c in codes],
        given_function=sample["code"]["function"] if v.family == "regular" else "",
        target=target if target is not None else {}, examples_from=origin,
        mock_answers=[labelled(c, v.family) for c in codes],
    )
