"""`sartco export-prompts`: the user messages of every episode of a protocol as JSON lines
(see sartco.protocols)."""
from __future__ import annotations

from sartco.errors import UserError
from sartco.paper.vocabulary import PROTOCOL

from . import add_common, our_episodes, paper_episodes, write_lines

FIELDS = ("id", "protocol", "file", "sample", "variant", "messages")


def configure(parser) -> None:
    add_common(parser)
    parser.add_argument("--file", action="append", default=None, metavar="STEM",
                        help="only this file (paper: published test file stem, e.g. rb_so_test_hc; "
                             "sartco: experiment name); repeatable")
    parser.add_argument("--variant", action="append", default=None, metavar="V",
                        help="only this variant (paper: dialogue key, e.g. regular_hai; sartco: task); repeatable")


def episodes(args) -> list[dict]:
    if args.protocol == PROTOCOL:
        return paper_episodes(args.data, args.generated, args.file, args.variant)
    found = our_episodes(args.data)
    for name, wanted, have in (("experiment", args.file, {e["file"] for e in found}),
                               ("task", args.variant, {e["variant"] for e in found})):
        unknown = sorted(set(wanted or ()) - have)
        if unknown:
            raise UserError(f"unknown {name}(s) {', '.join(unknown)}; there are {len(have)}, e.g. "
                            f"{', '.join(sorted(have)[:4])}")
    return [e for e in found
            if (args.file is None or e["file"] in args.file) and (args.variant is None or e["variant"] in args.variant)]


def run(args) -> int:
    return write_lines({k: episode[k] for k in FIELDS} for episode in episodes(args))
