"""Components and colours of the SARTCo world, as data."""

SHAPES = ("washer", "nut", "screw", "bridge-h", "bridge-v")
COLORS = ("red", "green", "blue", "yellow")
BRIDGES = {"bridge-h": (0, 1), "bridge-v": (1, 0)}  # offset of a bridge's second cell
LETTERS = {"washer": "w", "nut": "n", "screw": "s", "bridge-h": "b", "bridge-v": "b"}
NOTHING_ON_TOP = frozenset({"screw"})  # the paper: nothing goes on a screw

DEFAULT_ROWS = 8
DEFAULT_COLS = 8
MAX_DEPTH = 4
