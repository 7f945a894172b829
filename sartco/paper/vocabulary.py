"""The nouns of the paper protocol, in one place: protocol names, the published test files, the
dialogue keys (variants) and the Table 3 cell each belongs to, answer labels and prompt templates.

File prefixes (board and object type) and file suffixes (instruction source) are the importer's
(sartco.instances.importer.PREFIXES / SOURCES); task names are sartco.instances.prompts.TASKS.
"""
from __future__ import annotations

from typing import NamedTuple

from sartco.instances.importer import PREFIXES, SOURCES
from sartco.instances.prompts import TASKS

PROTOCOL = "paper"       # the measurement behind the paper's Table 3
OUR_PROTOCOL = "sartco"  # the project's own protocol (sartco.instances prompts, sartco.clem scoring)
PROTOCOLS = (OUR_PROTOCOL, PROTOCOL)

TEST_SPLIT = "test"
TRAIN_SPLIT = "train"


class Variant(NamedTuple):
    task: str            # sartco.instances.prompts.TASKS
    instructions: str    # template | human | model (table3.json's "instructions")
    training: str        # the training file's dialogue key whose turns are the example candidates
    family: str          # multi_turn | single_turn | regular: template, labels, gold keys


# dialogue key -> its cell; order: Table 3's (template, human, model; first-order, sequence, optimal)
VARIANTS: dict[str, Variant] = {
    "multi_turn": Variant("first_order", "template", "multi_turn", "multi_turn"),
    "single_turn_sc": Variant("sequence_function", "template", "single_turn_sc", "single_turn"),
    "single_turn": Variant("optimal_function", "template", "single_turn", "single_turn"),
    "regular": Variant("repetition", "template", "regular", "regular"),
    "single_turn_hai_sc": Variant("sequence_function", "human", "single_turn_sc", "single_turn"),
    "single_turn_hai": Variant("optimal_function", "human", "single_turn", "single_turn"),
    "regular_hai": Variant("repetition", "human", "regular", "regular"),
    "single_turn_mg": Variant("optimal_function", "model", "single_turn", "single_turn"),
    "regular_mg": Variant("repetition", "model", "regular", "regular"),
}
assert all(v.task in TASKS for v in VARIANTS.values())

# the answer labels per family, in the order they appear in an answer
LABELS = {"multi_turn": ("Output",), "single_turn": ("Function", "Usage"), "regular": ("Output",)}
INSTRUCTION_LABEL = "Instruction"
# the gold keys of one turn per family (README "Scoring"); usage is never executed
GOLD_KEYS = {"multi_turn": ("output",), "single_turn": ("function", "usage"), "regular": ("output",)}
NOT_EXECUTED = frozenset({"usage"})


def template_name(variant: str) -> str:
    """The builder prompt template of a variant: builder_<family>.template."""
    return f"builder_{VARIANTS[variant].family}.template"


def instructions_kind(source: str) -> str:
    """template | human | model for an instruction source (template, human, codellama, gpt4, claude)."""
    return source if source in ("template", "human") else "model"


class PublishedFile(NamedTuple):
    stem: str        # e.g. rb_so_test_hc
    prefix: str      # sb_so | rb_so | rb_cho
    board: str       # simple | regular
    object: str      # simple | complex
    source: str      # template | human | codellama | gpt4 | claude


def published_test_files() -> list[PublishedFile]:
    """Every published test file name with its board, object type and instruction source, in Table 3
    order: prefix (sb_so, rb_so, rb_cho), then source (template, human, codellama, gpt4, claude).
    Not every combination is published (rb_cho has no model-written file); callers keep those
    that exist."""
    out = []
    for prefix, (board, obj) in PREFIXES.items():
        for suffix, source in SOURCES.items():
            stem = f"{prefix}_{TEST_SPLIT}" + (f"_{suffix}" if suffix else "")
            out.append(PublishedFile(stem, prefix, board, obj, source))
    return out


def variants_of(board: str, source: str) -> list[str]:
    """The dialogue keys a test file of this board type and source is scored on: its own
    instructions (a variant file repeats its base file's keys; those belong to the base file)."""
    kind = instructions_kind(source)
    return [key for key, v in VARIANTS.items()
            if v.instructions == kind and (v.family == "regular") == (board == "regular")]


def training_stem(prefix: str) -> str:
    return f"{prefix}_{TRAIN_SPLIT}"
