"""The follower's whole vocabulary: words and regular expressions, in one place.

Everything the rule-based builder understands is listed here as data; parse.py only walks these
tables. Positions in instructions are 1-based ("the 8th row" is x = 7); a board has `rows` rows
(x, 0 = top) and `cols` columns (y, 0 = left).
"""
from __future__ import annotations

import re

# --- numbers --------------------------------------------------------------------------------
ORDINAL_WORDS = {
    "first": 1, "second": 2, "third": 3, "fourth": 4, "fifth": 5, "sixth": 6, "seventh": 7,
    "eighth": 8, "ninth": 9, "tenth": 10, "eleventh": 11, "twelfth": 12,
}
CARDINAL_WORDS = {
    "one": 1, "two": 2, "three": 3, "four": 4, "five": 5, "six": 6, "seven": 7, "eight": 8,
    "nine": 9, "ten": 10, "eleven": 11, "twelve": 12,
}
# an ordinal: "8th", "8", "eighth" (a bare number counts as 1-based too)
ORD = r"(?:\d{1,2}(?:st|nd|rd|th)?|" + "|".join(ORDINAL_WORDS) + ")"
NUM = r"(?:\d{1,2}|" + "|".join(CARDINAL_WORDS) + ")"
# edge words standing for a row or column: value is 1-based, or "last" for the far edge
ROW_EDGES = {"top": 1, "topmost": 1, "uppermost": 1, "bottom": "last", "bottommost": "last",
             "lowest": "last", "last": "last", "final": "last"}
COL_EDGES = {"left": 1, "leftmost": 1, "left-most": 1, "right": "last", "rightmost": "last",
             "right-most": "last", "last": "last", "final": "last"}

# --- components -------------------------------------------------------------------------------
COLOR_WORDS = {"red": "red", "green": "green", "blue": "blue", "yellow": "yellow"}
SHAPE_WORDS = {  # word (singular or plural) -> shape; a bridge needs an orientation
    "washer": "washer", "washers": "washer",
    "nut": "nut", "nuts": "nut",
    "screw": "screw", "screws": "screw",
    "bridge": "bridge", "bridges": "bridge",
}
ORIENTATION_WORDS = {
    "horizontally": "bridge-h", "horizontal": "bridge-h", "bridge-h": "bridge-h",
    "vertically": "bridge-v", "vertical": "bridge-v", "bridge-v": "bridge-v",
}

# --- simple boards: one token stream per clause -------------------------------------------------
# A clause is split into tokens by this one regex; parse.py groups them into placements.
_w = lambda words: "|".join(sorted(map(re.escape, words), key=len, reverse=True))  # noqa: E731
TOKEN = re.compile(
    r"(?P<bridge_h>\bbridge-h\b)|(?P<bridge_v>\bbridge-v\b)"
    rf"|\b(?P<orient>{_w(k for k in ORIENTATION_WORDS if not k.startswith('bridge'))})\b"
    rf"|\b(?P<color>{_w(COLOR_WORDS)})\b"
    rf"|\b(?P<shape>{_w(SHAPE_WORDS)})\b"
    # "8th row", "the eighth row", "row 8", "row number 8", "Row(8)" (the grid explanation's form,
    # sartco.world.render), "top row", "the last row"
    rf"|\b(?P<row_ord>{ORD})\s+rows?\b"
    rf"|\brows?\s*(?:\(\s*|number\s+|no\.?\s*|#\s*)?(?P<row_num>{NUM})\b"
    rf"|\b(?P<row_edge>{_w(ROW_EDGES)})\s+rows?\b"
    rf"|\b(?P<col_ord>{ORD})\s+(?:columns?|cols?)\b"
    rf"|\b(?:columns?|cols?)\s*(?:\(\s*|number\s+|no\.?\s*|#\s*)?(?P<col_num>{NUM})\b"
    rf"|\b(?P<col_edge>{_w(COL_EDGES)})\s*-?\s*(?:most\s+)?(?:columns?|cols?)\b"
    # "on top of it", "on it", "on top", "above it", "in the same position": the previous cell
    r"|\b(?P<same>on\s+top(?:\s+of\s+(?:it|that|this|them))?|on\s+(?:it|that)|above\s+it"
    r"|(?:at|in)\s+the\s+same\s+(?:position|place|location|cell|spot))\b",
    re.IGNORECASE,
)
# clauses: sentences, semicolons, new lines, "then", "and then", "next", "after that"
CLAUSE_SPLIT = re.compile(r"(?<!\d)\.(?!\d)|;|\n|\bthen\b|\bnext\b|\bafter\s+that\b|\bfinally\b",
                          re.IGNORECASE)
# the object's name: "These are the instructions to build wn." / "to build the object 'bnw'"
OBJECT_NAME = re.compile(
    r"\bbuild\s+(?:an?\s+|the\s+)?(?:object\s+|structure\s+)?['\"`]?(?P<name>[A-Za-z_]\w*)['\"`]?",
    re.IGNORECASE)
NAME_STOPWORDS = {"a", "an", "the", "object", "structure", "it", "this", "following"}

# --- regular boards: arrangements -----------------------------------------------------------------
# the object's name and its colours
QUOTED_OBJECT = re.compile(r"['\"`](?P<name>[A-Za-z_]\w*)['\"`]\s+objects?", re.IGNORECASE)
COLOR_LIST = re.compile(r"colou?rs?\s*:?\s*(?P<list>\[[^\]]*\])", re.IGNORECASE)
COLOR_PHRASE = re.compile(r"colou?rs?\b(?P<rest>.*)", re.IGNORECASE | re.DOTALL)
# the footprint: "each occupying a 2x1 space", "each taking a 1 x 3 space" (rows x columns)
SIZE = re.compile(r"\b(?P<h>\d)\s*(?:x|by|\*|×)\s*(?P<w>\d)\b", re.IGNORECASE)

# An ordinal list: "first, fourth, and seventh" / "1st and 5th"
ORD_LIST = rf"(?:{ORD})(?:\s*,\s*(?:and\s+)?(?:{ORD})|\s+and\s+(?:{ORD}))*"
_AX = r"(?P<{0}>rows?|columns?)"

ARRANGEMENTS: list[tuple[str, re.Pattern]] = [
    # "Place a 'ns' object at all the corners of the grid." (not "from the top-left corner")
    ("corners", re.compile(r"\b(?:all|four|each|every)\s+(?:of\s+)?(?:the\s+)?(?:four\s+|4\s+)?corners?\b"
                           r"|\bcorners\s+of\s+the\s+(?:grid|board)\b", re.IGNORECASE)),
    # "Start from the top-left corner and diagonally place 'bn' objects ..." /
    # "Starting from the top-left corner, fill the grid with 'ns' objects diagonally."
    ("diagonal", re.compile(r"\bdiagonal(?:ly)?\b", re.IGNORECASE)),
    # "place the 'ns' object in alternating columns of the first row ... Then, repeat this
    #  pattern in alternating rows."
    ("alternate_grid", re.compile(
        r"\balternat\w*\s+columns?\b.*\b(?:alternat\w*|every\s+other)\s+rows?\b"
        r"|\balternat\w*\s+rows?\b.*\b(?:alternat\w*|every\s+other)\s+columns?\b",
        re.IGNORECASE | re.DOTALL)),
    # "Fill the first column with the 'ns' object, each occupying a 1x1 space. ... Then repeat
    #  this action in every alternate column."  /  "Fill the fourth column with ..."
    ("fill_column", re.compile(
        rf"\bfill\s+(?:the\s+|up\s+the\s+)?(?P<first>{ORD})\s+column\b"
        r"(?P<repeat>.*\b(?:every\s+(?:alternate|other)|alternat\w*|each\s+other)\s+columns?\b)?",
        re.IGNORECASE | re.DOTALL)),
    ("fill_row", re.compile(
        rf"\bfill\s+(?:the\s+|up\s+the\s+)?(?P<first>{ORD})\s+row\b"
        r"(?P<repeat>.*\b(?:every\s+(?:alternate|other)|alternat\w*|each\s+other)\s+rows?\b)?",
        re.IGNORECASE | re.DOTALL)),
    # "Place a 'bw' object in the first, fourth, and seventh columns of the first row. Then,
    #  repeat this pattern of placement in the remaining rows." / "... in the fifth row."
    ("list_of_line", re.compile(
        rf"\b(?P<list>{ORD_LIST})\s+{_AX.format('axis')}\s+(?:of|in)\s+the\s+(?P<line>{ORD})\s+"
        rf"{_AX.format('line_axis')}"
        rf"(?:.*?\brepeat\b.*?\b(?:in|on|for|across|over|to)\s+(?:all\s+)?(?:of\s+)?(?:the\s+)?"
        rf"(?:(?P<remaining>remaining|other|rest\s+of\s+the|all|every|each)\s+{_AX.format('rem_axis')}"
        rf"|(?P<more>{ORD_LIST})\s+{_AX.format('more_axis')}))?",
        re.IGNORECASE | re.DOTALL)),
]
