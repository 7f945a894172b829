"""Find the code in a builder's answer (our protocol; the paper protocol keeps the authors' reading).

Real answers wrap code in markdown fences, in labels (Output:, Function:, Usage:, Code:), in
prose ("Sure! Here is the code: ..."), in inline code (`put(board, ...)`), and small models go on
producing the in-context pattern ("Instruction: ... Output: ...") after their answer.
`parse_code` returns the code only, dedented:
- fenced blocks: the Python ones (tag python/py/python3 or no tag); a block tagged otherwise
  (```text, ```json, ```output ...) is never code; an untagged block is code if it parses or
  has lines that look like Python; a block repeated word for word counts once;
- beside fenced code: a call written outside the fences (a "Usage:" line, inline or bare) of a
  function the fenced code defines but never calls, with no other names in its arguments than
  `board` and the fenced code's own (a signature in prose is not a usage), is appended after
  the fenced code;
- no fenced code: the labelled sections, else the lines that look like Python; inline code
  spans that hold a statement count as such lines.
An answer in which no code is found raises ParseError (the episode is aborted). Code that is
found but does not compile is *not* a parse error: it is executed and lost as syntax_error.
"""
from __future__ import annotations

import ast
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
_PYTHON_TAGS = {"python", "python3", "py", "py3"}
_INLINE = re.compile(r"(?<!`)`([^`\n]+)`(?!`)")  # `code` in a line of prose

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


def _split_fences(lines: list[str]) -> tuple[list[tuple[str, list[str]]], list[str]]:
    """The markdown fences as (language tag, lowercased; "" for none, contents) (an unclosed last
    fence runs to the end), and the lines outside them."""
    blocks: list[tuple[str, list[str]]] = []
    outside: list[str] = []
    current: list[str] | None = None
    tag = ""
    for line in lines:
        m = _FENCE.match(line)
        if m:
            if current is None:
                current, tag = [], m.group(2).lower()
            else:
                blocks.append((tag, current))
                current = None
            continue
        (outside if current is None else current).append(line)
    if current:
        blocks.append((tag, current))
    return blocks, outside


def _block_code(tag: str, block: list[str]) -> str:
    """The code of one fenced block: "" for a block tagged with another language than Python, or
    an untagged block with nothing that looks like Python (a grid, the expected output)."""
    if tag and tag not in _PYTHON_TAGS:
        return ""
    # a label inside a fence ("Output:\nput(...)"): keep what follows it
    labelled = _labelled_sections(block)
    code = _clean([ln for sec in labelled for ln in sec] if labelled else block)
    if tag or not code:
        return code
    looks = _clean(_code_lines(code.split("\n")))
    if not looks:
        return ""
    try:
        ast.parse(code)
    except SyntaxError:
        return looks
    return code


def _usage_calls(fenced: str, outside: str) -> list[str]:
    """The top-level calls in `outside` of functions that `fenced` defines but never calls at its
    top level: the usage line a model writes after (or before) the fence of its function."""
    defined = set(re.findall(r"^def\s+(\w+)\s*\(", fenced, re.MULTILINE))
    called = set(re.findall(r"^(\w+)\s*\(", fenced, re.MULTILINE)) - {"def"}
    wanted = defined - called
    if not wanted or not outside:
        return []
    try:
        statements = [(node, ast.get_source_segment(outside, node)) for node in ast.parse(outside).body]
    except SyntaxError:  # one statement per line then
        statements = []
        for line in outside.split("\n"):
            try:
                statements += [(node, line.strip()) for node in ast.parse(line.strip()).body]
            except SyntaxError:
                continue
    # a call with other free names than board and the fenced code's own is the function's
    # signature mentioned in prose ("`wn(board, colors, x, y)` places ..."), not a usage
    known = {"board"} | set(re.findall(r"^(\w+)\s*=", fenced, re.MULTILINE))

    def usage(node) -> bool:
        if not (isinstance(node, ast.Expr) and isinstance(node.value, ast.Call)
                and isinstance(node.value.func, ast.Name) and node.value.func.id in wanted):
            return False
        args = [*node.value.args, *(k.value for k in node.value.keywords)]
        return all(n.id in known for arg in args for n in ast.walk(arg) if isinstance(n, ast.Name))

    return [text for node, text in statements if usage(node)]


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


def _inline_code(lines: list[str]) -> list[str]:
    """A line holding inline code spans that are statements (`put(board, ...)`) is replaced by
    those statements, one per line, after the line's label if it has one; other lines stay."""
    out = []
    for line in lines:
        label = _LABEL.match(line)
        head, rest = (line[:label.start("rest")], label.group("rest")) if label else ("", line)
        spans = [span.strip() for span in _INLINE.findall(rest)]
        code = [span for span in spans if _KEYWORD_LINE.match(span) or _STATEMENT_LINE.match(span)]
        if not code:
            out.append(line)
        elif head.strip():
            out += [head.rstrip()] + code
        else:
            indent = line[:len(line) - len(line.lstrip())]
            out += [indent + span for span in code]
    return out


def _unfenced_code(lines: list[str]) -> str:
    """The code of text without fences: the labelled sections, else the lines that look like Python."""
    lines = _inline_code(lines)
    sections = _labelled_sections(lines)
    parts = []
    for chunk in sections if sections is not None else [lines]:
        code = _clean(_code_lines(textwrap.dedent("\n".join(chunk)).split("\n")))
        if code:
            parts.append(code)
    return "\n".join(parts)


def _clean(lines: list[str]) -> str:
    code = textwrap.dedent("\n".join(lines)).strip("\n")
    return "\n".join(line.rstrip() for line in code.splitlines()).strip()


def parse_code(text: str) -> str:
    """The code in an answer, dedented and stripped; raises ParseError if there is none."""
    if text is None or not str(text).strip():
        raise ParseError("empty answer", response=text)
    lines = _cut_tail(str(text).replace("\r\n", "\n").replace("\r", "\n").split("\n"))
    blocks, outside = _split_fences(lines)
    # a block repeated word for word ("Final answer:" after the same code) counts once
    code = "\n".join(dict.fromkeys(c for c in (_block_code(tag, block) for tag, block in blocks) if c))
    if code:
        code = "\n".join([code, *_usage_calls(code, _unfenced_code(outside))])
    else:  # no fences, or none with Python in it: the text outside them
        code = _unfenced_code(outside)
    if not code.strip():
        raise ParseError("no code found in the answer", response=text)
    return code
