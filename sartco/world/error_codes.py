"""The one vocabulary of failures: the paper's error taxonomy plus the sandbox's own codes, their
families (ErrorCode.family, category_family), their meanings in plain words (MEANINGS,
category_meaning: one sentence each, what transcripts' score cards and reports show) and
WorldError, what put/init_board raise.

World errors never import clemcore; the game masters translate them in one place.
"""
from enum import StrEnum
from typing import Final, Literal, TypeAlias


class ErrorCode(StrEnum):
    # raised by the Python program itself (the paper's names)
    SYNTAX_ERROR = "syntax_error"
    KEY_ERROR = "key_error"
    NAME_ERROR = "name_error"
    TYPE_ERROR = "type_error"
    VALUE_ERROR = "value_error"
    INDEX_ERROR = "index_error"
    ZERO_DIVISION = "zero_division"
    RUNTIME_ERROR = "runtime_error"
    # raised by the world's assembly rules (the paper's names)
    DIMENSIONS_MISMATCH = "dimensions_mismatch"
    DEPTH_MISMATCH = "depth_mismatch"
    BRIDGE_PLACEMENT = "bridge_placement"
    SAME_SHAPE_STACKING = "same_shape_stacking"
    SAME_SHAPE_AT_ALTERNATE_LEVELS = "same_shape_at_alternate_levels"
    NOT_ON_TOP_OF_SCREW = "not_on_top_of_screw"
    # a program that ran but built another board than the target (the paper's names)
    MISMATCH_LOCATION = "mismatch_location"
    MISMATCH_COUNT = "mismatch_count"
    MISMATCH_SHAPE = "mismatch_shape"
    MISMATCH_ORDER = "mismatch_order"
    MISMATCH_COLOR = "mismatch_color"
    # the sandbox's own
    FORBIDDEN = "forbidden"
    TIMEOUT = "timeout"
    RESOURCE_LIMIT = "resource_limit"
    # the game's own: an answer in which no code was found
    PARSE_ERROR = "parse_error"
    # the harness's own fault, never the model's: the sandbox could not run the program or gave
    # no usable answer, or the game master or scorer failed (the episode counts as not played)
    HARNESS_ERROR = "harness_error"

    @property
    def family(self) -> str:
        """parse | python | world | sandbox | mismatch | harness: the kind of failure, for reports and
        transcripts."""
        return _FAMILIES[self]


# families of error codes, for reports and transcripts (ErrorCode.family)
PYTHON_CODES = frozenset({
    ErrorCode.SYNTAX_ERROR, ErrorCode.KEY_ERROR, ErrorCode.NAME_ERROR, ErrorCode.TYPE_ERROR,
    ErrorCode.VALUE_ERROR, ErrorCode.INDEX_ERROR, ErrorCode.ZERO_DIVISION, ErrorCode.RUNTIME_ERROR,
})
WORLD_CODES = frozenset({
    ErrorCode.DIMENSIONS_MISMATCH, ErrorCode.DEPTH_MISMATCH, ErrorCode.BRIDGE_PLACEMENT,
    ErrorCode.SAME_SHAPE_STACKING, ErrorCode.SAME_SHAPE_AT_ALTERNATE_LEVELS, ErrorCode.NOT_ON_TOP_OF_SCREW,
})
SANDBOX_CODES = frozenset({ErrorCode.FORBIDDEN, ErrorCode.TIMEOUT, ErrorCode.RESOURCE_LIMIT})
MISMATCH_CODES = frozenset(c for c in ErrorCode if c.value.startswith("mismatch_"))
_FAMILIES = {
    ErrorCode.PARSE_ERROR: "parse", ErrorCode.HARNESS_ERROR: "harness", **dict.fromkeys(PYTHON_CODES, "python"), **dict.fromkeys(WORLD_CODES, "world"),
    **dict.fromkeys(SANDBOX_CODES, "sandbox"), **dict.fromkeys(MISMATCH_CODES, "mismatch"),
}
SUCCESS_CATEGORY: Final = "success"  # the category recorded for a build that equals its target
# a recorded category: the program's error, the mismatch, or SUCCESS_CATEGORY (as JSON: its string)
Category: TypeAlias = ErrorCode | Literal["success"]


def category_of(value: str) -> Category:
    """A category read back from JSON (ValueError for an unknown one)."""
    return SUCCESS_CATEGORY if value == SUCCESS_CATEGORY else ErrorCode(value)


# what each category means, in plain words (one sentence each; the one place for these texts)
MEANINGS = {
    SUCCESS_CATEGORY: "the program ran and built exactly the target board.",
    ErrorCode.SYNTAX_ERROR: "the code is not valid Python, so nothing ran.",
    ErrorCode.KEY_ERROR: "the program looked up a key that does not exist (such as an unknown shape or colour).",
    ErrorCode.NAME_ERROR: "the program used a name that was never defined.",
    ErrorCode.TYPE_ERROR: "the program called something with arguments of the wrong kind or number.",
    ErrorCode.VALUE_ERROR: "the program passed a value of the right kind but not a valid one.",
    ErrorCode.INDEX_ERROR: "the program indexed a list or sequence outside its length.",
    ErrorCode.ZERO_DIVISION: "the program divided by zero.",
    ErrorCode.RUNTIME_ERROR: "the program raised another Python error while it ran.",
    ErrorCode.DIMENSIONS_MISMATCH: "a piece was put outside the board.",
    ErrorCode.DEPTH_MISMATCH: "a bridge was put across two cells whose stacks have different heights.",
    ErrorCode.BRIDGE_PLACEMENT: "a bridge was put above level 2 (bridges go on level 1 or 2).",
    ErrorCode.SAME_SHAPE_STACKING: "a piece was stacked directly on one of the same shape, which the rules forbid.",
    ErrorCode.SAME_SHAPE_AT_ALTERNATE_LEVELS: "a piece repeats the shape two levels below it, which the rules forbid.",
    ErrorCode.NOT_ON_TOP_OF_SCREW: "a piece was put on top of a screw, and nothing goes on a screw.",
    ErrorCode.MISMATCH_LOCATION: ("the program ran, but a target cell stayed empty or a piece stands where the "
                                  "target has none."),
    ErrorCode.MISMATCH_COUNT: "the program ran, but a stack has more or fewer pieces than in the target.",
    ErrorCode.MISMATCH_SHAPE: "the program ran, but a stack holds other shapes than in the target.",
    ErrorCode.MISMATCH_ORDER: "the program ran, but a stack holds the right shapes in another order.",
    ErrorCode.MISMATCH_COLOR: "the program ran, every stack has the right shapes in order, but some colours differ.",
    ErrorCode.FORBIDDEN: "the program tried something the sandbox does not allow (files, imports, internals).",
    ErrorCode.TIMEOUT: "the program ran longer than its time or step budget.",
    ErrorCode.RESOURCE_LIMIT: "the program used more memory or output than its budget allows.",
    ErrorCode.PARSE_ERROR: "no code was found in the answer, so the episode was not played.",
    ErrorCode.HARNESS_ERROR: "the harness failed, not the model; left out of the scores.",
}


def category_meaning(category: str | None) -> str:
    """The plain-words meaning of a recorded category (None and "" mean success); ValueError for
    an unknown category."""
    if category in (None, ""):
        category = SUCCESS_CATEGORY
    if category != SUCCESS_CATEGORY:
        category = ErrorCode(category)
    return MEANINGS[category]


def category_family(category: str | None) -> str:
    """The family of a recorded category: "success" for a build that equals its target (None, ""
    or SUCCESS_CATEGORY), else its ErrorCode's family (ValueError for an unknown category)."""
    if category in (None, "", SUCCESS_CATEGORY):
        return "success"
    return ErrorCode(category).family


class WorldError(Exception):
    """A rule violation or a bad argument to put/init_board; carries its code."""

    def __init__(self, code: ErrorCode, message: str):
        super().__init__(message)
        self.code = ErrorCode(code)
        self.message = message

    def __reduce__(self) -> "tuple[type[WorldError], tuple[ErrorCode, str]]":  # picklable across the worker boundary
        return (WorldError, (self.code, self.message))
