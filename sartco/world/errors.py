"""The one vocabulary of failures: the paper's error taxonomy plus the sandbox's own codes.

World errors never import clemcore; the game masters translate them in one place.
"""
from enum import StrEnum


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


# families of error codes, for reports and transcripts (sartco.clem.outcomes.family)
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


class WorldError(Exception):
    """A rule violation or a bad argument to put/init_board; carries its code."""

    def __init__(self, code: ErrorCode, message: str):
        super().__init__(message)
        self.code = ErrorCode(code)
        self.message = message

    def __reduce__(self):  # picklable across the worker boundary
        return (WorldError, (self.code, self.message))
