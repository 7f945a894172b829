"""The one rule for model text that reaches a record or a screen: `escape`.

A model's answer may hold anything: lone surrogates (not Unicode: no UTF-8 file can hold them,
and clemcore's store_json raises), NUL and other control characters (they reach terminals and
transcripts raw), bidirectional overrides (they make shown text read otherwise than it runs).
`escape` writes each such character as a visible Python escape (`\\ud800`, `\\x00`, `\\u202e`)
and keeps everything else, tabs and line breaks included; the result is printable and strict
UTF-8, and escaping it again changes nothing. Where the exact text matters, the caller keeps it
beside the escaped one as ASCII JSON (`exact_json`). `one_line` is the same escape for a
message of one line: tabs, \\n and \\r become spaces and the other line breaks of
str.splitlines() are escaped too (\\v, \\f, \\x1c-\\x1e and \\x85 already are; U+2028, U+2029),
so a message is one line to every reader. Free of dependencies: the bottom layer.
"""
from __future__ import annotations

import json
import re

# C0 controls but tab and line breaks, DEL, C1 controls, surrogates, bidi embeddings/overrides/isolates
UNSAFE = re.compile("[\x00-\x08\x0b\x0c\x0e-\x1f\x7f-\x9f\ud800-\udfff\u202a-\u202e\u2066-\u2069]")
_BREAKS = re.compile("[\t\n\r]")
_SEPARATORS = re.compile("[\u2028\u2029]")  # the line breaks of str.splitlines() that escape keeps, but \n and \r


def _visible(match: re.Match[str]) -> str:
    code = ord(match.group())
    return f"\\x{code:02x}" if code < 0x100 else f"\\u{code:04x}"


def escape(text: str) -> str:
    """`text` with every unsafe character written as a visible escape; line breaks and tabs kept."""
    return text if text.isascii() and text.isprintable() else UNSAFE.sub(_visible, text)


def one_line(text: str) -> str:
    """`escape` for a message of one line: tabs, \\n and \\r become spaces, every other line break
    a visible escape (`\\u2028`): str.splitlines() finds one line."""
    return _SEPARATORS.sub(_visible, _BREAKS.sub(" ", escape(text)))


def exact_json(text: str) -> str | None:
    """The exact text as ASCII JSON (json.loads gives it back) when `escape` changed it, else None."""
    return None if escape(text) == text else json.dumps(text)


def escape_all(value: object) -> object:
    """`escape` on every str inside nested dicts, lists and tuples (a record about to be stored)."""
    if isinstance(value, str):
        return escape(value)
    if isinstance(value, dict):
        return {escape_all(k): escape_all(v) for k, v in value.items()}
    if isinstance(value, (list, tuple)):
        return [escape_all(v) for v in value]
    return value
