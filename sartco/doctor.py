"""`sartco doctor`: what this machine can do, one line each, for a new user and for the first
question when something fails:

  python       the interpreter and the supported range (pyproject's requires-python)
  walls        the sandbox's walls here (seccomp, rlimits, namespaces), and why one is missing
  data         the SARTCo data folder (published/, gold_boards/, paper-protocol/) and the
               dataset's manifest (instances/v1/manifest.json: version, seed)
  registries   clemcore's model registries (its own and ./model_registry.json) and the models they name
  model NAME   each openai_compatible / openai_batching model of ./model_registry.json: does its
               server answer a one-token request (within --timeout seconds)?
  games        the games clem sees from here

Exit 0 when everything `make main` needs is there (the sandbox confines programs, the data
folder, the dataset, the built-in models and both games); else 1, and the lines marked "missing"
say what to fix. A model server that does not answer is said, not counted: make main needs none.
"""
from __future__ import annotations

import argparse
import json
import re
import sys
import urllib.request
from pathlib import Path

SERVED = ("openai_compatible", "openai_batching")  # the backends that reach a server through key.json's openai_compatible
NEEDED_MODELS = ("rulebased", "erring")  # sartco register's; mock is clemcore's programmatic model
NEEDED_GAMES = ("cobot_instruct", "cobot_describe")


def configure(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("--timeout", type=float, default=10.0, help="seconds a model server may take to answer (10)")


def _python() -> tuple[str, bool]:
    """The interpreter against the installed package's Requires-Python (pyproject.toml's requires-python)."""
    from importlib import metadata

    wanted = metadata.metadata("sartco-bench")["Requires-Python"] or ""
    bounds = dict(re.findall(r"(>=|<)\s*3\.(\d+)", wanted))
    minor = sys.version_info.minor
    ok = sys.version_info.major == 3 and int(bounds.get(">=", 0)) <= minor < int(bounds.get("<", 99))
    return (f"python: {sys.version.split()[0]} ({sys.executable}); supported: {wanted} (clemcore 3.7 declares <3.13)"
            + ("" if ok else " (missing: another interpreter, see the README)"), ok)


def _walls() -> tuple[str, bool]:
    from sartco.program.walls import walls

    found = walls()
    shown = "; ".join(f"{w.name} {'up' if w.up else 'down'}" + ("" if w.up else f" ({w.why})") for w in found)
    ok = all(w.up for w in found if w.name in ("seccomp", "rlimits"))
    return f"walls: {shown}" + ("" if ok else " (missing: without them no program runs: every episode harness_error)"), ok


def _data() -> tuple[str, bool]:
    from sartco import settings

    folder = settings.DATA
    parts = {name: (folder / name).is_dir() for name in ("published", "gold_boards", "paper-protocol")} if folder else {}
    dataset = settings.workspace() / "instances" / "v1" / "manifest.json"
    try:
        manifest = json.loads(dataset.read_text(encoding="utf-8"))
        shown = f"{dataset}: version {manifest.get('version')}, seed {manifest.get('seed')}"
    except (OSError, ValueError) as exc:
        manifest, shown = None, f"{dataset}: unreadable ({type(exc).__name__})"
    ok = bool(parts) and all(parts.values()) and manifest is not None
    where = (f"{folder}: " + ", ".join(f"{n}/ {'there' if there else 'missing'}" for n, there in parts.items())
             if folder else f"no data folder ({settings.DATA_SETTING})")
    return f"data: {where}; dataset {shown}" + ("" if ok else " (missing: set SARTCO_DATA, or regenerate the dataset)"), ok


def _models(timeout: float) -> tuple[list[str], bool]:
    from clemcore.backends.model_registry import ModelRegistry

    registry = ModelRegistry.from_packaged_and_cwd_files()
    names = list(dict.fromkeys(s.model_name for s in registry))
    mine = Path.cwd() / "model_registry.json"
    missing = [m for m in NEEDED_MODELS if m not in names]
    lines = [f"registries: clemcore's own and {mine} ({'there' if mine.is_file() else 'none'}): {len(names)} models: "
             f"{', '.join(names)}" + (f" (missing: {', '.join(missing)}; run `sartco register`)" if missing else "")]
    served = [s for s in registry if getattr(s, "backend", None) in SERVED and mine.is_file()
              and getattr(s, "lookup_source", str(mine)) == str(mine)]
    for spec in served:
        lines.append(f"model {spec.model_name} ({spec.backend}): {_answers(spec, timeout)}")
    return lines, not missing


def _answers(spec, timeout: float) -> str:
    """Whether the server of key.json's openai_compatible entry answers a one-token request."""
    from sartco.text import escape

    try:
        from clemcore.backends.key_registry import KeyRegistry

        key = KeyRegistry.from_json().get_key_for("openai_compatible")
        base_url, api_key = key["base_url"], key.get("api_key", "none")
    except Exception as exc:  # noqa: BLE001 - a missing key.json or entry, said as it is
        return f"no answer: key.json has no openai_compatible base_url ({type(exc).__name__})"
    body = json.dumps({"model": getattr(spec, "model_id", spec.model_name), "max_tokens": 1,
                       "messages": [{"role": "user", "content": "Say OK."}]}).encode()
    request = urllib.request.Request(base_url.rstrip("/") + "/chat/completions", data=body, method="POST",
                                     headers={"Content-Type": "application/json", "Authorization": f"Bearer {api_key}"})
    try:
        with urllib.request.urlopen(request, timeout=timeout) as answer:
            json.loads(answer.read())
    except Exception as exc:  # noqa: BLE001 - any failure is the line's news
        return f"no answer from {escape(base_url)} within {timeout:g} s ({escape(str(exc))[:200]})"
    return f"answers at {escape(base_url)}"


def _games() -> tuple[str, bool]:
    from clemcore.clemgame import GameRegistry

    names = sorted({s.game_name for s in GameRegistry.from_directories_and_cwd_files().get_game_specs()})
    missing = [g for g in NEEDED_GAMES if g not in names]
    return (f"games: {', '.join(names) or 'none'}" + (f" (missing: {', '.join(missing)}; run it in the checkout's "
                                                       f"root, or `sartco games DIR`)" if missing else ""), not missing)


def run(args: argparse.Namespace) -> int:
    ok = True
    for check in (_python, _walls, _data):
        line, fine = check()
        print(line, flush=True)
        ok &= fine
    lines, fine = _models(args.timeout)
    print("\n".join(lines), flush=True)
    line, games = _games()
    print(line, flush=True)
    ok = ok and fine and games
    print(f"sartco doctor: {'everything make main needs is here' if ok else 'something make main needs is missing (above)'}")
    return 0 if ok else 1
