"""The 2.5D SARTCo world: components, the board, the assembly rules and the error vocabulary."""
from .board import Board, Cells, parse_key
from .components import BRIDGES, COLORS, DEFAULT_COLS, DEFAULT_ROWS, LETTERS, MAX_DEPTH, SHAPES
from .error_codes import (MISMATCH_CODES, PYTHON_CODES, SANDBOX_CODES, SUCCESS_CATEGORY, WORLD_CODES, Category, ErrorCode,
                          WorldError, category_family, category_meaning, category_of)
from .rules import check, put

__all__ = [
    "Board", "Cells", "parse_key", "BRIDGES", "COLORS", "DEFAULT_COLS", "DEFAULT_ROWS",
    "LETTERS", "MAX_DEPTH", "SHAPES", "MISMATCH_CODES", "PYTHON_CODES", "SANDBOX_CODES", "WORLD_CODES",
    "SUCCESS_CATEGORY", "Category", "ErrorCode", "WorldError", "category_family", "category_meaning", "category_of",
    "check", "put",
]
