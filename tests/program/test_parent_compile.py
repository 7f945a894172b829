"""The parent compiles (issue 46, sartco/program/compiled.py): a refused program gets its verdict
without a child, and every verdict is the one a compile in the child gave: the nesting limit
does not move with the caller's stack (the parent's -O and hash seed: test_determinism.py)."""
import base64
import marshal
import sys

import pytest

from sartco.program import Limits, compiled, pool
from sartco.world import ErrorCode


def _sum(terms: int) -> str:
    return "x = 1\ny = " + " + ".join(["x"] * terms) + "\nput(board, 'nut', 'red', 0, 0)"


def test_a_refused_program_runs_no_child(monkeypatch):
    sent: list[int] = []
    real = pool.dispatch
    monkeypatch.setattr(pool, "dispatch", lambda *args: (ran := real(*args), sent.append(len(ran)))[0])
    box = pool.LocalSandbox(workers=1)
    try:
        results = box.execute_many(["import os", "x = (", "y" * 200, "put(board, 'nut', 'red', 1, 1)"],
                                   limits=Limits(source=100), cache=False)
    finally:
        box.close()
    assert [ex.error for ex in results] == [ErrorCode.FORBIDDEN, ErrorCode.SYNTAX_ERROR, ErrorCode.RESOURCE_LIMIT, None]
    assert sent == [1]  # only the program that runs went to a template


def _deep(frames: int, source: str):
    return _deep(frames - 1, source) if frames else compiled.prepare(source, Limits())


# the figures are CPython 3.11's (its compiler counts the caller's C stack); 3.12 limits nesting its
# own way, where this test has no figure yet (make test-py312)
@pytest.mark.skipif(sys.version_info[:2] != (3, 11), reason="the nesting figures are CPython 3.11's")
def test_the_nesting_limit_is_the_childs_whatever_the_callers_depth():
    """986 terms compiled in a template's child, 987 were too deeply nested (issue 32's sandbox);
    also after a compile that failed too deep (CPython 3.11 may leave its thread's count off)."""
    for frames in (0, 100, 500, 0):
        assert type(_deep(frames, _sum(986))) is bytes, frames
        refused = _deep(frames, _sum(987))
        assert (refused.error, refused.message) == (ErrorCode.RESOURCE_LIMIT, "the program is too deeply nested to compile")



@pytest.mark.skipif(sys.version_info[:2] != (3, 11), reason="the nesting figures are CPython 3.11's")
def test_a_program_compiled_in_its_child_has_the_same_nesting_limit():
    """A program whose code holds a frozenset constant is compiled in its child (compiled.py); the
    child's deeper stack refuses nothing that the parent's compile let through."""
    def with_set(terms: int) -> str:
        return _sum(terms) + "\nfor c in {'red', 'blue', 'green'}:\n    pass"

    assert marshal.loads(base64.b64decode(compiled.prepare(with_set(986), Limits())))[0] is None  # compiled in the child
    box = pool.LocalSandbox(workers=1)
    try:
        deepest, refused = box.execute_many([with_set(986), with_set(987)], limits=Limits(), cache=False)
    finally:
        box.close()
    assert deepest.ok and deepest.cells == {"0:0": [["nut", "red"]]}
    assert (refused.error, refused.message) == (ErrorCode.RESOURCE_LIMIT, "the program is too deeply nested to compile")
