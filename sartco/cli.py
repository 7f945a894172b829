"""The `sartco` command. Each subcommand lives in its own module, imported only when chosen,
so that `sartco execute` starts fast. A module exposes `configure(parser)` and `run(args) -> int`
(`module:x` in COMMANDS: configure_x and run_x).
"""
from __future__ import annotations

import argparse
import importlib
import os
import sys
from pathlib import Path

from sartco.errors import UserError

COMMANDS = {
    "execute": ("sartco.program.serve", "run programs from JSON lines on stdin in the sandbox"),
    "bench-execute": ("sartco.bench_execute", "throughput of `sartco execute` against a bare process forking as many children"),
    "generate": ("sartco.instances.generate", "write a dataset version from a YAML config and a seed"),
    "instances": ("sartco.instancegen.command", "write the games' instance files (games/*/in/) from a dataset"),
    "stats": ("sartco.instances.stats", "table 1 of the paper, computed by enumeration"),
    "import": ("sartco.published.importer", "convert the published SARTCo files into the dataset format"),
    "import-instructions": ("sartco.instances.describer_import", "turn describer results into a dataset"),
    "report": ("sartco.report.tables", "paper-style tables from a clemcore results folder"),
    "compare": ("sartco.report.compare", "two models on the same episodes: paired differences, McNemar test"),
    "sample": ("sartco.clem.tooling.sampling", "N samples of every episode (clem run N times) for pass@k"),
    "check-instances": ("sartco.clem.core.check", "check an instance file as clem run does before any model is asked"),
    "resume": ("sartco.clem.tooling.resume", "play and score exactly the missing episodes of an interrupted clem run"),
    "export-prompts": ("sartco.protocols.export", "the prompts of a protocol's episodes (paper or sartco) as JSON lines"),
    "score-responses": ("sartco.protocols.score", "score raw answers (JSON lines) in a protocol (paper or sartco)"),
    "bench-reward": ("sartco.reward.bench", "rewards/s of sartco.reward over the gold and the erring players' answers"),
    "export-dataset": ("sartco.reward.dataset", "cobot_instruct episodes as a Hugging Face dataset (JSON lines, parquet)"),
    "suite": ("sartco.suite", "make main's job: many clem runs, scored, transcribed, evaluated, reported, on every core"),
    "serve-reward": ("sartco.reward.serve", "the reward over HTTP for OpenRLHF's --remote_rm_url (POST /get_reward)"),
    "bench-run": ("sartco.clem.tooling.benchrun", "clem run against a stub model server: sequential vs the batching backend"),
    "register": ("sartco.register", "write sartco's models and backends into a folder's clemcore files (model_registry.json)"),
    "games": ("sartco.register:games", "copy the games into DIR and register them in ./game_registry.json"),
}


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(prog="sartco", description=__doc__.splitlines()[0])
    parser.add_argument("--data", metavar="DIR", default=None, dest="data_folder",
                        help="the SARTCo data folder (published/, gold_boards/, paper-protocol/); sets $SARTCO_DATA "
                             "for this command (default: $SARTCO_DATA, else ../shared/sartco-data beside the checkout)")
    sub = parser.add_subparsers(dest="command", metavar="COMMAND", required=True)
    argv = sys.argv[1:] if argv is None else argv
    data, rest = _data_option(argv)
    if data is not None:  # before any module reads sartco.settings (it resolves the data folder once)
        known = sys.modules.get("sartco.settings")
        if known is not None and known.DATA != Path(data).expanduser().resolve():
            print(f"sartco: --data {data}: this process already uses the data folder {known.DATA} "
                  f"(give --data, or $SARTCO_DATA, when the process starts)", file=sys.stderr)
            return 2
        os.environ["SARTCO_DATA"] = data
    chosen = next((a for a in rest if not a.startswith("-")), None)
    modules = {}
    for name, (module, help_text) in COMMANDS.items():
        p = sub.add_parser(name, help=help_text, description=help_text)
        if name == chosen:
            module, _, suffix = module.partition(":")
            modules[name] = importlib.import_module(module), f"_{suffix}" if suffix else ""
            getattr(modules[name][0], "configure" + modules[name][1])(p)
    args = parser.parse_args(argv)
    try:
        module, suffix = modules[args.command]
        return int(getattr(module, "run" + suffix)(args) or 0)
    except UserError as exc:
        print(f"sartco {args.command}: {exc}", file=sys.stderr)
        return 2


def _data_option(argv: list[str]) -> tuple[str | None, list[str]]:
    """The global `--data DIR` (before the command's name) and the arguments without it."""
    for i, arg in enumerate(argv):
        if not arg.startswith("-"):
            return None, argv
        if arg == "--data" and i + 1 < len(argv):
            return argv[i + 1], argv[:i] + argv[i + 2:]
        if arg.startswith("--data="):
            return arg.split("=", 1)[1], argv[:i] + argv[i + 1:]
    return None, argv


if __name__ == "__main__":
    sys.exit(main())
