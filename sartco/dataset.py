"""The dataset's nouns, in one place and free of dependencies (the bottom layer: it imports only
sartco.settings, for the data folder, so every layer may use it).

A board kind is a board type with an object type. Each kind has one spelling per use:

    kind             board    object   key              prefix  cell
    SIMPLE           simple   simple   simple_simple    sb_so   sb_so
    REGULAR_SIMPLE   regular  simple   regular_simple   rb_so   rb_so
    REGULAR_COMPLEX  regular  complex  regular_complex  rb_cho  rb_co

key: our dataset's file names (`<key>_<split>.json`), config sections and record ids;
prefix: the published SARTCo file names (`<prefix>_<split>[_<suffix>].json`);
cell: the experiment names of both games (Table 3 rows), by the one rule of `experiment_name`:
<cell>_<task>_<source>[_<variant>...] (sb_so_optimal_function_template,
rb_co_repetition_describer_clarify). The published files call complex objects "challenge"
(`published_object`).

Instruction sources: template (generated), human (`_hc` files), codellama / gpt4 / claude (`_mg`,
`_gpt4_mg`, `_claude_mg`: model-written). Tasks are the paper's code styles. The published dialogue
keys (`DIALOGUE_KEYS`: multi_turn, single_turn_hai, regular_mg, ...) name a task and who wrote the
instructions. A dataset file is a list of `BoardRecord`s (`RECORD_KEYS` their key order).
"""
from __future__ import annotations

import re
from typing import Any, NamedTuple, TypedDict

from sartco.settings import data_path

# the shared data (published files, gold boards, paper protocol), read where it lies (sartco.settings.DATA)
SHARED_DATA = data_path()

SPLITS = ("train", "val", "test")
BOARD_TYPES = ("simple", "regular")
OBJECT_TYPES = ("simple", "complex")
TASKS = ("first_order", "sequence_function", "optimal_function", "repetition")
SOURCES = ("template", "human", "codellama", "gpt4", "claude")
# the published file suffix of each instruction source (template: the base file, no suffix)
PUBLISHED_SUFFIX = {"template": None, "human": "hc", "codellama": "mg", "gpt4": "gpt4_mg", "claude": "claude_mg"}
# the published dialogue key (instruction style) of each task; sequence_function reads
# single_turn_sc where a file has it
INSTRUCTION_STYLE = {"first_order": "multi_turn", "sequence_function": "single_turn",
                     "optimal_function": "single_turn", "repetition": "regular"}


class DialogueKey(NamedTuple):
    task: str          # TASKS
    instructions: str  # template | human | model (instructions_kind of the file's source)
    style: str         # the template dialogue key (and our records' instruction style) it is written in


# every dialogue key of the published files, in Table 3 order (template, human, model; first-order,
# sequence, optimal; simple before regular boards). A variant file (_hc, _mg, ...) repeats its test
# file's template keys and adds its own.
DIALOGUE_KEYS = {
    "multi_turn": DialogueKey("first_order", "template", "multi_turn"),
    "single_turn_sc": DialogueKey("sequence_function", "template", "single_turn_sc"),
    "single_turn": DialogueKey("optimal_function", "template", "single_turn"),
    "regular": DialogueKey("repetition", "template", "regular"),
    "single_turn_hai_sc": DialogueKey("sequence_function", "human", "single_turn_sc"),
    "single_turn_hai": DialogueKey("optimal_function", "human", "single_turn"),
    "regular_hai": DialogueKey("repetition", "human", "regular"),
    "single_turn_mg": DialogueKey("optimal_function", "model", "single_turn"),
    "regular_mg": DialogueKey("repetition", "model", "regular"),
}

# the builder's task when a describer (or a model) wrote the instruction: the paper's
# model-written-instruction tasks
DESCRIBED_TASK = {"simple": "optimal_function", "regular": "repetition"}


class BoardRecord(TypedDict):
    """One board of a dataset file (docs/ARCHITECTURE.md "Datasets"), the keys in file order."""
    id: str                      # simple_simple_test_0007 | sb_so_test/simple/simple/2/wn/0
    board_type: str              # BOARD_TYPES
    object_type: str             # OBJECT_TYPES
    split: str                   # SPLITS
    combo_name: str
    shapes: list[str]
    colors: list[str]
    quadrant: str
    rows: int
    cols: int
    seed: str | None             # the object's code seed template
    arrangement: str | None      # regular boards: the arrangement template
    placement: dict[str, list[Any]] | None   # simple boards: {"x", "y", "orientations"}, one per put
    occupied_rows: int | None    # regular boards
    occupied_cols: int | None
    target: dict[str, list[list[str]]]  # the board the gold code builds, canonical cells
    code: dict[str, dict[str, Any]]     # task -> its code ("total_code" the whole program)
    instructions: dict[str, dict[str, Any]]  # source -> style -> text (multi_turn: a list of texts)
    provenance: dict[str, Any]   # {"source": "generated"} | {"source": "published", "file", "sample"} | ...


RECORD_KEYS = tuple(BoardRecord.__annotations__)


class BoardKind(NamedTuple):
    board: str             # simple | regular
    object: str            # simple | complex
    key: str               # simple_simple: our dataset files and configs
    prefix: str            # sb_so: the published files
    cell: str              # sb_so: the experiments of both games (experiment_name)
    published_object: str  # simple | challenge: the object type as the published files spell it

    def dataset_file(self, split: str) -> str:
        """Our dataset's file of one split: simple_simple_test.json."""
        return f"{self.key}_{split}.json"

    def published_stem(self, split: str, source: str = "template") -> str:
        """The published file of one split and instruction source, without .json: rb_so_test_hc."""
        suffix = PUBLISHED_SUFFIX[source]
        return f"{self.prefix}_{split}" + (f"_{suffix}" if suffix else "")

    def tasks(self) -> tuple[str, ...]:
        """The tasks of this kind's boards: the simple-board styles, or repetition."""
        return TASKS[:3] if self.board == "simple" else TASKS[3:]


SIMPLE = BoardKind("simple", "simple", "simple_simple", "sb_so", "sb_so", "simple")
REGULAR_SIMPLE = BoardKind("regular", "simple", "regular_simple", "rb_so", "rb_so", "simple")
REGULAR_COMPLEX = BoardKind("regular", "complex", "regular_complex", "rb_cho", "rb_co", "challenge")
BOARD_KINDS = (SIMPLE, REGULAR_SIMPLE, REGULAR_COMPLEX)


def experiment_name(kind: BoardKind, task: str, source: str, *variants: str | None) -> str:
    """The one rule of experiment names, every instance file of both games:
    <cell>_<task>_<source>, then _<variant> for each variant given (None and "" are left out):
    sb_so_first_order_template, rb_so_repetition_template_examples_3, sb_so_optimal_function_describer_clarify.
    A "/" of the source (a describer model's name) becomes "_": the name is one results folder."""
    return "_".join([kind.cell, task, source.replace("/", "_"), *(v for v in variants if v)])


def board_kind(board: str, object_type: str) -> BoardKind:
    """The kind of a (board type, object type) pair; ValueError for an unknown pair."""
    for kind in BOARD_KINDS:
        if (kind.board, kind.object) == (board, object_type):
            return kind
    raise ValueError(f"unknown board kind {board!r}/{object_type!r}")


def kind_named(name: str) -> BoardKind:
    """The kind of any of its spellings (key, prefix or cell); ValueError otherwise."""
    for kind in BOARD_KINDS:
        if name in (kind.key, kind.prefix, kind.cell):
            return kind
    raise ValueError(f"unknown board kind {name!r}; expected one of "
                     + ", ".join(k.key for k in BOARD_KINDS))


class PublishedName(NamedTuple):
    kind: BoardKind
    split: str
    source: str

    @property
    def stem(self) -> str:
        return self.kind.published_stem(self.split, self.source)


_SUFFIX_SOURCE = {suffix: source for source, suffix in PUBLISHED_SUFFIX.items()}
PUBLISHED_NAME_RE = re.compile(
    "^(?P<prefix>" + "|".join(k.prefix for k in BOARD_KINDS) + ")_(?P<split>" + "|".join(SPLITS) + ")"
    "(?:_(?P<suffix>" + "|".join(s for s in PUBLISHED_SUFFIX.values() if s) + "))?(?:\\.json)?$")


def parse_published_name(name: str) -> PublishedName | None:
    """sb_so_test_hc(.json) -> (SIMPLE, test, human); None for a name that is not a published file's."""
    m = PUBLISHED_NAME_RE.match(name)
    if m is None:
        return None
    return PublishedName(kind_named(m["prefix"]), m["split"], _SUFFIX_SOURCE[m["suffix"]])


def instructions_kind(source: str) -> str:
    """template | human | model: how Table 3 groups an instruction source."""
    return source if source in ("template", "human") else "model"
