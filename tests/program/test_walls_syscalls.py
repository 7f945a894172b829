"""docs/sandbox.md's table of the seccomp allow-list is confine.RULES (issue 42): it cannot drift."""
from pathlib import Path

from sartco.program.child import confine

DOCS = Path(__file__).resolve().parents[2] / "docs" / "sandbox.md"


def test_the_docs_table_is_the_filters_list():
    text = DOCS.read_text(encoding="utf-8")
    shown = text.split("<!-- syscalls: generated from confine.table() -->\n", 1)[1].split("\n<!-- /syscalls -->", 1)[0]
    assert shown == confine.table(), "regenerate the table: python -c 'from sartco.program.child import confine; print(confine.table())'"


def test_every_rule_says_why_and_with_which_arguments():
    names = [rule.name for rule in confine.RULES]
    assert len(names) == len(set(names))
    for rule in confine.RULES:
        assert rule.why and rule.arguments, rule
    for gone in ("fcntl", "uname", "sysinfo", "membarrier", "sched_getaffinity", "kill", "openat", "socket", "clone"):
        assert gone not in names, gone
