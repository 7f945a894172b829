"""The nouns of the paper protocol, in one place: protocol names, the published test files, the
dialogue keys (variants) and the Table 3 cell each belongs to, answer labels and prompt templates.

Board kinds, file names, instruction sources, tasks and dialogue keys are sartco.dataset's.
"""
from __future__ import annotations

from typing import NamedTuple

from sartco.dataset import BOARD_KINDS, DIALOGUE_KEYS, SOURCES, BoardKind, PublishedName, instructions_kind

PROTOCOL = "paper"       # the measurement behind the paper's Table 3
OUR_PROTOCOL = "sartco"  # the project's own protocol (sartco.instances prompts, sartco.clem scoring)
PROTOCOLS = (OUR_PROTOCOL, PROTOCOL)

TEST_SPLIT = "test"
TRAIN_SPLIT = "train"


class Variant(NamedTuple):
    task: str            # sartco.dataset.TASKS
    instructions: str    # template | human | model (table3.json's "instructions")
    training: str        # the training file's dialogue key whose turns are the example candidates
    family: str          # multi_turn | single_turn | regular: template, labels, gold keys


# a template dialogue key's family: the prompt template, answer labels and gold keys it uses
FAMILY = {"multi_turn": "multi_turn", "single_turn_sc": "single_turn", "single_turn": "single_turn",
          "regular": "regular"}
# dialogue key -> its cell; order: Table 3's (template, human, model; first-order, sequence, optimal)
VARIANTS: dict[str, Variant] = {key: Variant(d.task, d.instructions, d.style, FAMILY[d.style])
                                for key, d in DIALOGUE_KEYS.items()}

# the answer labels per family, in the order they appear in an answer
LABELS = {"multi_turn": ("Output",), "single_turn": ("Function", "Usage"), "regular": ("Output",)}
INSTRUCTION_LABEL = "Instruction"
# the gold keys of one turn per family (README "Scoring"); usage is never executed
GOLD_KEYS = {"multi_turn": ("output",), "single_turn": ("function", "usage"), "regular": ("output",)}
NOT_EXECUTED = frozenset({"usage"})


def template_name(variant: str) -> str:
    """The builder prompt template of a variant: builder_<family>.template."""
    return f"builder_{VARIANTS[variant].family}.template"


def published_test_files() -> list[PublishedName]:
    """Every published test file name (its board kind and instruction source; `.stem`), in Table 3
    order: board kind (sb_so, rb_so, rb_cho), then source (template, human, codellama, gpt4, claude).
    Not every combination is published (rb_cho has no model-written file); callers keep those
    that exist."""
    return [PublishedName(kind, TEST_SPLIT, source) for kind in BOARD_KINDS for source in SOURCES]


def variants_of(kind: BoardKind, source: str) -> list[str]:
    """The dialogue keys a test file of this board kind and source is scored on: its own
    instructions (a variant file repeats its base file's keys; those belong to the base file)."""
    return [key for key, v in VARIANTS.items() if v.instructions == instructions_kind(source) and v.task in kind.tasks()]


def training_stem(kind: BoardKind) -> str:
    return kind.published_stem(TRAIN_SPLIT)
