"""The `sartco` command. Each subcommand lives in its own module, imported only when chosen,
so that `sartco execute` starts fast. A module exposes `configure(parser)` and `run(args) -> int`
(`module:x` in COMMANDS: configure_x and run_x).

What every command shares is here: a user's mistake (UserError, an option argparse refuses) is one
line and exit 2, naming the command; Ctrl-C (KeyboardInterrupt) is one line and exit 130.
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
    "doctor": ("sartco.doctor", "what this machine can do: the sandbox's walls, the data, models, games"),
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


DESCRIPTION = ("SARTCo bench: the cobot programming games for clembench, their data, scores and tools. "
               "When something fails, run `sartco doctor` first.")
# what a command's --help says below its options
EPILOGS = {
    "execute": """input: one JSON object a line, {"id": str, "code": str, "target": optional cells}; cells are
  {"row:col": [[shape, colour], ...]}, bottom to top.
output: one JSON line per input, in order: {"id", "ok", "error", "message", "cells"}, and with a
  target "es", "category", "precision", "recall", "f1".
example:
  echo '{"id": "a1", "code": "put(board, \\"washer\\", \\"red\\", 1, 1)", "target": {"1:1": [["washer", "red"]]}}' | sartco execute""",
}
INTERRUPTED = 130  # a shell's status for a process ended by Ctrl-C (128 + SIGINT)


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(prog="sartco", description=DESCRIPTION)
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
    try:
        return _run(parser, sub, argv, chosen)
    except UserError as exc:
        print(f"sartco {chosen}: {exc}", file=sys.stderr)
        return 2
    except KeyboardInterrupt as exc:
        print(f"sartco {chosen}: interrupted (Ctrl-C){': ' + str(exc) if str(exc) else ''}", file=sys.stderr)
        return INTERRUPTED


def _run(parser: argparse.ArgumentParser, sub, argv: list[str], chosen: str | None) -> int:
    """The chosen command's module imported and configured, its options read, its run."""
    modules = {}
    for name, (module, help_text) in COMMANDS.items():
        p = sub.add_parser(name, help=help_text, description=help_text, epilog=EPILOGS.get(name),
                           formatter_class=argparse.RawDescriptionHelpFormatter)
        if name == chosen:
            module, _, suffix = module.partition(":")
            modules[name] = importlib.import_module(module), f"_{suffix}" if suffix else ""
            getattr(modules[name][0], "configure" + modules[name][1])(p)
    args, extra = parser.parse_known_args(argv)
    if extra:  # said by the command's own parser: its usage line, not the top level's
        sub.choices[args.command].error(f"unrecognized arguments: {' '.join(extra)}")
    module, suffix = modules[args.command]
    return int(getattr(module, "run" + suffix)(args) or 0)


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
