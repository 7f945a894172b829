"""Find the code in a builder's answer.

Real answers wrap code in markdown fences, in labels (Output:, Function:, Usage:, Code:), in
prose ("Sure! Here is the code: ..."), and small models go on producing the in-context pattern
("Instruction: ... Output: ...") after their answer. `parse_code` returns the code only, dedented;
an answer in which no code is found raises ParseError (the episode is aborted). Code that is found
but does not compile is *not* a parse error: it is executed and lost as syntax_error.
"""
from __future__ import annotations

import re
import textwrap

from clemcore.clemgame.errors import ParseError as _ClemParseError

from sartco.world import ErrorCode


class ParseError(_ClemParseError):
    """No code in the answer. A clemcore ParseError, so DialogueGameMaster.step counts it as a
    violated request; `code` is the sartco error vocabulary's name for it."""

    code = ErrorCode.PARSE_ERROR

    def __init__(self, reason: str, response: str | None = None):
        super().__init__(reason=reason, response=response, key=ErrorCode.PARSE_ERROR.value)


# "Output:", "**Function:**", "### Usage:", "<Editor>:" ... (the rest of the line may hold code)
_LABEL = re.compile(
    r"^\s*(?:#+\s*)?(?:\*\*|__)?\s*(?P<label>output|function|usage|code|answer|python code|python|editor|<editor>)"
    r"\s*(?:\*\*|__)?\s*:\s*(?:\*\*|__)?(?P<rest>.*)$",
    re.IGNORECASE,
)
# the in-context pattern that small models repeat after their answer
_TAIL = re.compile(r"^\s*(?:#+\s*)?(?:\*\*|__)?\s*(?:instructions?|<programmer>|programmer|input)\s*(?:\*\*|__)?\s*(?::|$)",
                   re.IGNORECASE)
_FENCE = re.compile(r"^\s*(`{3,}|~{3,})\s*([\w+-]*)\s*$")

_KEYWORD_LINE = re.compile(
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
_STATEMENT_LINE = re.compile(
    r"^\s*[A-Za-z_][\w.]*(?:\[[^\]]*\])?\s*(?:\(.*|(?:[-+*/%]|//)?=(?!=)\s*\S.*|,\s*[A-Za-z_][\w.]*\s*=\s*\S.*)$")
_COMMENT_LINE = re.compile(r"^\s*#")


def _balance(line: str) -> int:
    """How many brackets this line leaves open (strings are ignored roughly)."""
    line = re.sub(r"'[^'\\]*(?:\\.[^'\\]*)*'|\"[^\"\\]*(?:\\.[^\"\\]*)*\"", "", line)
    line = line.split("#", 1)[0]
    return sum(line.count(c) for c in "([{") - sum(line.count(c) for c in ")]}")


def _looks_like_prose(line: str) -> bool:
    """A sentence that happens to start like a call: "Place (carefully) a red washer." """
    s = line.strip()
    words = re.findall(r"[A-Za-z]+", s)
    return s.endswith(".") and not s.endswith(")") and len(words) > 6 and "board" not in s


def _code_lines(lines: list[str]) -> list[str]:
    """Keep the lines that are Python: statements, their indented bodies, continuation lines of
    open brackets, and comments next to code. Prose lines are dropped."""
    kept: list[str] = []
    in_code = False      # the previous non-blank line was kept as code
    block_open = False   # a kept line opened a block (ends with ":"): indented lines below are its body
    open_brackets = 0    # brackets left open by kept lines: the next lines continue the statement
    comments: list[str] = []  # comment lines waiting for the code they precede
    for line in lines:
        if not in_code and _COMMENT_LINE.match(line):
            comments.append(line.rstrip())
            continue
        if not line.strip():
            if in_code:
                kept.append("")
            continue
        indent = len(line) - len(line.lstrip())
        is_code = (
            open_brackets > 0
            or bool(_KEYWORD_LINE.match(line))
            or (bool(_STATEMENT_LINE.match(line)) and not _looks_like_prose(line))
            or (in_code and block_open and indent > 0)
            or (bool(_COMMENT_LINE.match(line)) and (in_code or indent > 0))
        )
        if is_code:
            kept.extend(comments)
            comments = []
            kept.append(line.rstrip())
            open_brackets = max(0, open_brackets + _balance(line))
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


def _cut_tail(lines: list[str]) -> list[str]:
    """Drop everything from the first repeated "Instruction ..." line that follows code; an
    echoed instruction before any code is dropped on its own."""
    out: list[str] = []
    seen_code = False
    in_fence = False
    for line in lines:
        if _FENCE.match(line):
            in_fence = not in_fence
            seen_code = True
            out.append(line)
            continue
        if not in_fence and _TAIL.match(line):
            if seen_code:
                break
            continue
        if in_fence or _LABEL.match(line) or _KEYWORD_LINE.match(line) or _STATEMENT_LINE.match(line):
            seen_code = True
        out.append(line)
    return out


def _fenced_blocks(lines: list[str]) -> list[list[str]] | None:
    """The contents of the markdown fences (an unclosed last fence runs to the end), or None."""
    blocks: list[list[str]] = []
    current: list[str] | None = None
    for line in lines:
        if _FENCE.match(line):
            if current is None:
                current = []
            else:
                blocks.append(current)
                current = None
            continue
        if current is not None:
            current.append(line)
    if current:
        blocks.append(current)
    return blocks if blocks else None


def _labelled_sections(lines: list[str]) -> list[list[str]] | None:
    """The text after each label (the label line's remainder, then the following lines)."""
    sections: list[list[str]] = []
    current: list[str] | None = None
    for line in lines:
        m = _LABEL.match(line)
        if m:
            current = []
            sections.append(current)
            if m.group("rest").strip():
                current.append(m.group("rest").strip())
            continue
        if current is not None:
            current.append(line)
    return sections if sections else None


def _strip_inline_backticks(lines: list[str]) -> list[str]:
    out = []
    for line in lines:
        s = line.strip()
        if len(s) > 2 and s.startswith("`") and s.endswith("`") and not s.startswith("``"):
            line = line.replace("`", "")
        out.append(line)
    return out


def _clean(lines: list[str]) -> str:
    code = textwrap.dedent("\n".join(lines)).strip("\n")
    return "\n".join(line.rstrip() for line in code.splitlines()).strip()


def parse_code(text: str) -> str:
    """The code in an answer, dedented and stripped; raises ParseError if there is none."""
    if text is None or not str(text).strip():
        raise ParseError("empty answer", response=text)
    lines = _strip_inline_backticks(_cut_tail(str(text).replace("\r\n", "\n").replace("\r", "\n").split("\n")))
    fenced = _fenced_blocks(lines)
    if fenced is not None:
        parts = []
        for block in fenced:
            # a label inside a fence ("Output:\nput(...)"): keep what follows it
            labelled = _labelled_sections(block)
            body = [ln for sec in labelled for ln in sec] if labelled else block
            code = _clean(body)
            if code:
                parts.append(code)
        code = "\n".join(parts)
    else:
        sections = _labelled_sections(lines)
        chunks = sections if sections is not None else [lines]
        parts = []
        for chunk in chunks:
            code = _clean(_code_lines(textwrap.dedent("\n".join(chunk)).split("\n")))
            if code:
                parts.append(code)
        code = "\n".join(parts)
    if not code.strip():
        raise ParseError("no code found in the answer", response=text)
    return code
