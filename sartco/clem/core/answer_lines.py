"""What one line of an answer is (the line recognisers of sartco.clem.core.parsing and the describer's
readers): a label ("Output:", "**Function:**", "### Usage:"), the in-context tail a small model
repeats, a markdown fence, a line of Python; and which lines sit inside a fence.

Inside a fence a line starting with `#` is a Python comment, never a label (`# Usage: ...` above
a call, `# Code: build bn`); a label is read outside fences, or inside one on a line of prose.
"""
from __future__ import annotations

import re

# "Output:", "**Function:**", "### Usage:", "<Editor>:" ... (the rest of the line may hold code)
LABEL = re.compile(
    r"^\s*(?:#+\s*)?(?:\*\*|__)?\s*(?P<label>output|function|usage|code|answer|python code|python|editor|<editor>)"
    r"\s*(?:\*\*|__)?\s*:\s*(?:\*\*|__)?(?P<rest>.*)$",
    re.IGNORECASE,
)
# the in-context pattern that small models repeat after their answer
TAIL = re.compile(r"^\s*(?:#+\s*)?(?:\*\*|__)?\s*(?:instructions?|<programmer>|programmer|input)\s*(?:\*\*|__)?\s*(?::|$)",
                   re.IGNORECASE)
FENCE = re.compile(r"^\s*(`{3,}|~{3,})\s*([\w+-]*)\s*$")
PYTHON_TAGS = {"python", "python3", "py", "py3"}
INLINE = re.compile(r"(?<!`)`([^`\n]+)`(?!`)")  # `code` in a line of prose

KEYWORD_LINE = re.compile(
    r"""^\s*(?:
        def\s+\w+\s*\(.*\)\s*(?:->.*)?:\s*(?:\#.*)?$
      | class\s+\w+.*:\s*$
      | for\s+.+\s+in\s+.+:\s*(?:\#.*)?$
      | (?:if|elif|while|with)\s+.+:\s*(?:\#.*)?$
      | (?:else|try|finally)\s*:\s*(?:\#.*)?$
      | except\b.*:\s*$
      | return\b.*
      | (?:pass|break|continue)\s*(?:\#.*)?$
      | (?:import|from)\s+[\w.]+.*
      | (?:raise|assert|del|global|nonlocal)\b.*
    )""",
    re.VERBOSE,
)
# a call or an assignment: put(board, ...), wn(board, ...), board = init_board(8, 8), x += 1
STATEMENT_LINE = re.compile(
    r"^\s*[A-Za-z_][\w.]*(?:\[[^\]]*\])?\s*(?:\(.*|(?:[-+*/%]|//)?=(?!=)\s*\S.*|,\s*[A-Za-z_][\w.]*\s*=\s*\S.*)$")
COMMENT_LINE = re.compile(r"^\s*#")


def balance(line: str) -> int:
    """How many brackets this line leaves open (strings are ignored roughly)."""
    line = re.sub(r"'[^'\\]*(?:\\.[^'\\]*)*'|\"[^\"\\]*(?:\\.[^\"\\]*)*\"", "", line)
    line = line.split("#", 1)[0]
    return sum(line.count(c) for c in "([{") - sum(line.count(c) for c in ")]}")


def looks_like_prose(line: str) -> bool:
    """A sentence that happens to start like a call: "Place (carefully) a red washer." """
    s = line.strip()
    words = re.findall(r"[A-Za-z]+", s)
    return s.endswith(".") and not s.endswith(")") and len(words) > 6 and "board" not in s


def code_lines(lines: list[str]) -> list[str]:
    """Keep the lines that are Python: statements, their indented bodies, continuation lines of
    open brackets, and comments next to code. Prose lines are dropped."""
    kept: list[str] = []
    in_code = False      # the previous non-blank line was kept as code
    block_open = False   # a kept line opened a block (ends with ":"): indented lines below are its body
    open_brackets = 0    # brackets left open by kept lines: the next lines continue the statement
    comments: list[str] = []  # comment lines waiting for the code they precede
    for line in lines:
        if not in_code and COMMENT_LINE.match(line):
            comments.append(line.rstrip())
            continue
        if not line.strip():
            if in_code:
                kept.append("")
            continue
        indent = len(line) - len(line.lstrip())
        is_code = (
            open_brackets > 0
            or bool(KEYWORD_LINE.match(line))
            or (bool(STATEMENT_LINE.match(line)) and not looks_like_prose(line))
            or (in_code and block_open and indent > 0)
            or (bool(COMMENT_LINE.match(line)) and (in_code or indent > 0))
        )
        if is_code:
            kept.extend(comments)
            comments = []
            kept.append(line.rstrip())
            open_brackets = max(0, open_brackets + balance(line))
            if line.split("#", 1)[0].rstrip().endswith(":"):
                block_open = True
            in_code = True
        else:
            in_code = block_open = False
            open_brackets = 0
            comments = []
    while kept and not kept[-1].strip():
        kept.pop()
    return kept


def in_fence(lines: list[str]) -> list[bool]:
    """For each line, whether it sits inside a markdown fence (the fence lines themselves count)."""
    inside, flags = False, []
    for line in lines:
        fence = bool(FENCE.match(line))
        flags.append(inside or fence)
        inside = inside != fence
    return flags


def label_at(line: str, *, fenced: bool, after_code: bool = False) -> re.Match | None:
    """The label on this line, or None: inside a fence, or right after a line of code, a line
    starting with `#` is a Python comment, not a label (not a markdown heading)."""
    if (fenced or after_code) and COMMENT_LINE.match(line):
        return None
    return LABEL.match(line)


def is_code_line(line: str) -> bool:
    """A line of Python: a statement or keyword line, or an indented line (a body)."""
    return bool(KEYWORD_LINE.match(line) or STATEMENT_LINE.match(line)) or (line[:1] in " \t" and bool(line.strip()))
