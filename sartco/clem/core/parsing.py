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

from sartco.syntax import parse

from .answer_lines import (FENCE, LABEL, INLINE, KEYWORD_LINE, PYTHON_TAGS, STATEMENT_LINE, TAIL, code_lines,
                           is_code_line, label_at)
from .errors import ParseError


def _cut_tail(lines: list[str]) -> list[str]:
    """Drop everything from the first repeated "Instruction ..." line that follows code; an
    echoed instruction before any code is dropped on its own."""
    out: list[str] = []
    seen_code = False
    in_fence = False
    for line in lines:
        if FENCE.match(line):
            in_fence = not in_fence
            seen_code = True
            out.append(line)
            continue
        if not in_fence and TAIL.match(line):
            if seen_code:
                break
            continue
        if in_fence or LABEL.match(line) or KEYWORD_LINE.match(line) or STATEMENT_LINE.match(line):
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
        m = FENCE.match(line)
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
    if tag and tag not in PYTHON_TAGS:
        return ""
    # a label inside a fence ("Output:\nput(...)"): keep what follows it
    labelled = _labelled_sections(block, fenced=True)
    code = _clean([ln for sec in labelled for ln in sec] if labelled else block)
    if tag or not code:
        return code
    looks = _clean(code_lines(code.split("\n")))
    if not looks:
        return ""
    try:
        parse(code)
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
        statements = [(node, ast.get_source_segment(outside, node)) for node in parse(outside).body]
    except SyntaxError:  # one statement per line then
        statements = []
        for line in outside.split("\n"):
            try:
                statements += [(node, line.strip()) for node in parse(line.strip()).body]
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


def _labelled_sections(lines: list[str], *, fenced: bool = False) -> list[list[str]] | None:
    """The text after each label (the label line's remainder, then the following lines). A `#`
    line inside a fence or right after code is a comment (answer_lines.label_at); inside a fence
    a label's remainder is kept only if it is code ("Code: build bn" is prose)."""
    sections: list[list[str]] = []
    current: list[str] | None = None
    after_code = False
    for line in lines:
        m = label_at(line, fenced=fenced, after_code=after_code)
        if line.strip():
            after_code = is_code_line(line)
        if m:
            current = []
            sections.append(current)
            rest = m.group("rest").strip()
            if rest and (not fenced or is_code_line(rest)):
                current.append(rest)
            continue
        if current is not None:
            current.append(line)
    return sections if sections else None


def _inline_code(lines: list[str]) -> list[str]:
    """A line holding inline code spans that are statements (`put(board, ...)`) is replaced by
    those statements, one per line, after the line's label if it has one; other lines stay."""
    out = []
    for line in lines:
        label = LABEL.match(line)
        head, rest = (line[:label.start("rest")], label.group("rest")) if label else ("", line)
        spans = [span.strip() for span in INLINE.findall(rest)]
        code = [span for span in spans if KEYWORD_LINE.match(span) or STATEMENT_LINE.match(span)]
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
        code = _clean(code_lines(textwrap.dedent("\n".join(chunk)).split("\n")))
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
