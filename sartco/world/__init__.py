"""The 2.5D SARTCo world: components, the board, the assembly rules and the error vocabulary."""
from .board import Board, Cells, parse_key, sort_cells
from .components import BRIDGES, COLORS, DEFAULT_COLS, DEFAULT_ROWS, LETTERS, MAX_DEPTH, SHAPES
from .errors import MISMATCH_CODES, ErrorCode, WorldError
from .rules import check, put

__all__ = [
    "Board", "Cells", "parse_key", "sort_cells", "BRIDGES", "COLORS", "DEFAULT_COLS", "DEFAULT_ROWS",
    "LETTERS", "MAX_DEPTH", "SHAPES", "MISMATCH_CODES", "ErrorCode", "WorldError", "check", "put",
]
