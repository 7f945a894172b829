"""The `sartco` command. Each subcommand lives in its own module, imported only when chosen,
so that `sartco execute` starts fast. A module exposes `configure(parser)` and `run(args) -> int`.
"""
from __future__ import annotations

import argparse
import importlib
import sys

from sartco.errors import UserError

COMMANDS = {
    "execute": ("sartco.program.serve", "run programs from JSON lines on stdin in the sandbox"),
    "bench-execute": ("sartco.bench_execute", "throughput of `sartco execute` against bare compile()"),
    "generate": ("sartco.instances.generate", "write a dataset version from a YAML config and a seed"),
    "stats": ("sartco.instances.stats", "table 1 of the paper, computed by enumeration"),
    "import": ("sartco.published.importer", "convert the published SARTCo files into the dataset format"),
    "import-instructions": ("sartco.instances.describer_import", "turn describer results into a dataset"),
    "report": ("sartco.report.tables", "paper-style tables from a clemcore results folder"),
    "compare": ("sartco.report.compare", "two models on the same episodes: paired differences, McNemar test"),
    "sample": ("sartco.clem.tooling.sampling", "N samples of every episode (clem run N times) for pass@k"),
    "resume": ("sartco.clem.tooling.resume", "play and score exactly the missing episodes of an interrupted clem run"),
    "export-prompts": ("sartco.protocols.export", "the prompts of a protocol's episodes (paper or sartco) as JSON lines"),
    "score-responses": ("sartco.protocols.score", "score raw answers (JSON lines) in a protocol (paper or sartco)"),
    "bench-run": ("sartco.clem.tooling.benchrun", "clem run against a stub model server: sequential vs the batching backend"),
}


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(prog="sartco", description=__doc__.splitlines()[0])
    sub = parser.add_subparsers(dest="command", metavar="COMMAND", required=True)
    argv = sys.argv[1:] if argv is None else argv
    chosen = next((a for a in argv if not a.startswith("-")), None)
    modules = {}
    for name, (module, help_text) in COMMANDS.items():
        p = sub.add_parser(name, help=help_text, description=help_text)
        if name == chosen:
            modules[name] = importlib.import_module(module)
            modules[name].configure(p)
    args = parser.parse_args(argv)
    try:
        return int(modules[args.command].run(args) or 0)
    except UserError as exc:
        print(f"sartco {args.command}: {exc}", file=sys.stderr)
        return 2


if __name__ == "__main__":
    sys.exit(main())
