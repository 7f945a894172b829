"""sartco.syntax.parse: a parse that another parse cuts into (a finalizer of the same thread, or
another thread while the first lets the GIL go) still gives its tree. On CPython 3.11 a bare
ast.parse fails there with `SystemError: AST constructor recursion depth mismatch` (gh-106905):
CI saw it once, when the game master's setup parsed the gold program while a thread of the
harness parsed another program, and the episode was lost. Every parse of the project goes
through sartco.syntax."""
from __future__ import annotations

import ast
import gc
import sys
import threading
from pathlib import Path

import pytest

from sartco import syntax

ROOT = Path(__file__).resolve().parents[2]
SOURCE = "\n".join(f"def f{i}(board, x):\n    return [put(board, 'nut', 'red', x + {i}, y) for y in range(x) if y % 3]"
                   for i in range(200))
OTHER = "x = [1, 2, 3]\n" * 5
ON_311 = sys.version_info < (3, 12)  # where a bare ast.parse fails when cut


def deep(n: int, call):
    """call() from a stack n frames deeper: the other parse's counter starts elsewhere."""
    return deep(n - 1, call) if n else call()


class Cut:
    """Cyclic garbage whose finalizer runs `action` when the collector next runs."""

    def __init__(self, action):
        self.action, self.me = action, self

    def __del__(self):
        self.action()


def cut_by(action, parse):
    """parse(), with the collector due after 300 allocations: inside the tree's construction
    (SOURCE has thousands of nodes), where it finds a Cut and runs `action`."""
    threshold = gc.get_threshold()
    gc.collect()
    try:
        gc.set_threshold(300)
        Cut(action)
        return parse()
    finally:
        gc.set_threshold(*threshold)


def test_a_parse_cut_by_a_parse_of_its_own_thread_gives_its_tree():
    if ON_311:  # the control: the cut is real, and a bare parse fails on it
        with pytest.raises(SystemError, match="recursion depth mismatch"):
            cut_by(lambda: deep(50, lambda: ast.parse(OTHER)), lambda: ast.parse(SOURCE))
    inner = []
    tree = cut_by(lambda: inner.append(deep(50, lambda: syntax.parse(OTHER))), lambda: syntax.parse(SOURCE))
    assert len(inner) == 1 and ast.dump(inner[0]) == ast.dump(ast.parse(OTHER))
    assert ast.dump(tree) == ast.dump(ast.parse(SOURCE))


def test_a_parse_of_another_thread_waits_for_the_one_under_way():
    # the cut starts a thread that parses and waits for it (0.5 s at most): with the lock, that
    # parse ends after the first one, so neither cuts into the other
    order, threads = [], []

    def other():
        deep(50, lambda: syntax.parse(OTHER))
        order.append("other thread's parse")

    def start_other():
        thread = threading.Thread(target=other)
        thread.start()
        threads.append(thread)
        thread.join(0.5)

    tree = cut_by(start_other, lambda: syntax.parse(SOURCE))
    order.append("first parse")
    threads[0].join()
    assert order == ["first parse", "other thread's parse"]
    assert ast.dump(tree) == ast.dump(ast.parse(SOURCE))


def test_a_process_forked_while_a_thread_parsed_parses():
    """A process forked (sartco suite's workers, clem eval's tables) while a thread of its parent
    held the parse lock gets a lock of its own and parses."""
    from fork_helpers import forked_while_held

    assert forked_while_held(syntax._LOCK, lambda: ast.dump(syntax.parse(OTHER)) == ast.dump(ast.parse(OTHER)),
                             seconds=20) == 0


def test_literal_is_literal_eval():
    assert syntax.literal("  ['red', 'blue']") == ast.literal_eval("  ['red', 'blue']") == ["red", "blue"]
    assert syntax.literal(ast.parse("(1, 'a')", mode="eval").body) == (1, "a")
    for bad in ("[red]", "[1,"):
        with pytest.raises((ValueError, SyntaxError)) as ours:
            syntax.literal(bad)
        with pytest.raises((ValueError, SyntaxError)) as theirs:
            ast.literal_eval(bad)
        assert type(ours.value) is type(theirs.value)


def test_the_project_parses_only_through_sartco_syntax():
    offenders = []
    for path in sorted([*ROOT.joinpath("sartco").rglob("*.py"), *ROOT.joinpath("games").rglob("*.py"),
                        *ROOT.joinpath("tools").rglob("*.py")]):
        if path == ROOT / "sartco" / "syntax.py":
            continue
        for node in ast.walk(ast.parse(path.read_text(), str(path))):
            if isinstance(node, ast.Attribute) and node.attr in ("parse", "literal_eval", "PyCF_ONLY_AST") \
                    and isinstance(node.value, ast.Name) and node.value.id == "ast":
                offenders.append(f"{path.relative_to(ROOT)}:{node.lineno}: ast.{node.attr}")
    assert not offenders, "parse through sartco.syntax (parse, literal):\n" + "\n".join(offenders)
