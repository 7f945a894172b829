"""The two paths of issue 35, traced from the code itself: one real in-process run of one episode
of a game (clemcore's loop, the `mock` model), every call into the checkout's code recorded
(sys.setprofile), then cut in two:

  (a) an instance's way from its generator to its episode: the instance generation of one small
      file (the mode's `instances_smoke` / `instances_slice` function, as `sartco instances` finds
      it in sartco.instancegen.command.MODES), the instance file, the benchmark's instance check,
      up to the end of the game master's setup (`_on_setup`);
  (b) an answer's way to scores.json: everything after the setup: the model's answer, parsing,
      build, sandbox, judge, record, the score card, `clem score`'s scorer writing scores.json.

For each path it prints the files of sartco/ and games/ in the order of their first visit (how
often the path entered each), the returns (how often it entered a file it had already left: the
visits beyond each file's first), the folders, how often the path changed folder, and the calls that
go back up a layer: a call from a module into one of a higher layer of tests/architecture/
test_layers.py (the layers of the checkout it runs in), e.g. a shared base calling a game's hook.
The code run while a module is imported is left out (imports are not steps of a path).

    .venv/bin/python scripts/trace_paths.py [--game cobot_instruct|cobot_describe] [--json]

Run it in a checkout with its own venv: it reads that checkout's games/ and layers. It writes only
into a temporary folder (a copy of the game's clemgame.json and master.py, its instance file and
results).
"""
from __future__ import annotations

import argparse
import importlib.util
import json
import shutil
import sys
import tempfile
from pathlib import Path

REPO = Path(__file__).resolve().parents[1]
# the small instance file each game's path starts from: (game, generator flags, file function)
START = {"cobot_instruct": (["--smoke", "1"], "instances_smoke", "instances_smoke"),
         "cobot_describe": (["--slice", "1"], "instances_slice", "instances_slice")}


def layers():
    """(package_of, RANK) of the checkout's tests/architecture/test_layers.py."""
    spec = importlib.util.spec_from_file_location("_layers", REPO / "tests" / "architecture" / "test_layers.py")
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module.package_of, module.RANK


class Recorder:
    """Every call into a file of the checkout: (callee file, its function, the nearest caller
    file of the checkout, its function), in order; calls made while a module body runs (an
    import) are left out."""

    def __init__(self, aliases: dict[str, str]):
        self.aliases = aliases  # a file outside the checkout -> the checkout file it stands for
        self.calls: list[tuple[str, str, str | None, str | None]] = []  # callee file, function; caller's
        self.importing = 0
        self.marks: dict[str, int] = {}

    def ours(self, filename: str) -> str | None:
        if filename in self.aliases:
            return self.aliases[filename]
        path = Path(filename)
        if path.is_relative_to(REPO) and path.parts[len(REPO.parts)] in ("sartco", "games"):
            return str(path.relative_to(REPO))
        return None

    def __call__(self, frame, event, arg):
        if event not in ("call", "return"):
            return
        code = frame.f_code
        if code.co_name == "<module>":
            self.importing += 1 if event == "call" else -1
            return
        if self.importing:
            return
        mine = self.ours(code.co_filename)
        if mine is None:
            return
        if event == "return":
            if code.co_name == "_on_setup" and "setup" not in self.marks:
                self.marks["setup"] = len(self.calls)  # path (a) ends with the master's setup
            return
        caller, back = None, frame.f_back
        while back is not None and caller is None:
            caller, name, back = self.ours(back.f_code.co_filename), back.f_code.co_name, back.f_back
        self.calls.append((mine, code.co_name, caller, name if caller else None))


def run_episode(game: str, work: Path, recorder: Recorder) -> None:
    """Generate the game's small instance file into a copy of its folder and play its first
    episode with `mock`, then score it, all under the recorder."""
    from clemcore import backends
    from clemcore.clemgame import (ExperimentFileSaver, GameBenchmark, GameBenchmarkCallbackList, GameInstances,
                                   GameSpec, InstanceFileSaver, InteractionsFileSaver, ResultsFolder)
    from clemcore.clemgame.runners import sequential

    from sartco.instancegen.command import MODES, check
    from sartco.instancegen.legacy import parse

    flags, function, stem = START[game]
    game_dir = work / game
    (game_dir / "in").mkdir(parents=True)
    for name in ("clemgame.json", "master.py"):
        shutil.copy(REPO / "games" / game / name, game_dir / name)
    recorder.aliases[str(game_dir / "master.py")] = f"games/{game}/master.py"
    mode, options = parse(game, flags)
    check(options)
    options.dataset = Path(options.dataset).resolve()
    models = backends.load_models(["mock"] * (2 if game == "cobot_describe" else 1), dict(temperature=0.0, max_tokens=300))
    results = work / "results"
    folder = ResultsFolder(results, run_dir=backends.Model.to_identifier(models))
    infos = backends.Model.to_infos(models)
    callbacks = GameBenchmarkCallbackList([InstanceFileSaver(folder), ExperimentFileSaver(folder, player_model_infos=infos),
                                           InteractionsFileSaver(folder, player_model_infos=infos)])
    sys.setprofile(recorder)
    try:
        [write] = [f for f in MODES[mode][1](options) if f.__name__ == function]
        write(options, game_dir)  # (a) instance generation -> the instance file
        spec = next(s for s in GameSpec.from_directory(str(game_dir)) if s.game_name == game)
        instances = json.loads((game_dir / "in" / f"{stem}.json").read_text(encoding="utf-8"))
        experiment = instances["experiments"][0]
        rows = [{"game_name": game, "experiment": experiment, "game_instance": experiment["game_instances"][0]}]
        with GameBenchmark.load_from_spec(spec) as bench:  # the instance check, the master's setup, (b)
            sequential.run(bench, GameInstances(game, rows), models, callbacks=callbacks)
            bench.compute_scores(sorted(results.rglob("interactions.json")))
    finally:
        sys.setprofile(None)
    if not list(results.rglob("scores.json")):
        raise SystemExit(f"trace_paths: {game}: the episode wrote no scores.json under {results}")


def summary(calls: list[tuple[str, str, str | None, str | None]], package_of, rank) -> dict:
    """The path's files (first-visit order, times entered), folders, folder changes and the
    calls that go back up a layer."""
    def layer(file: str) -> int:
        module = ".".join(Path(file).with_suffix("").parts)
        return rank[package_of(module)]

    files: dict[str, int] = {}
    folders: list[str] = []
    changes, previous, up = 0, None, {}
    for callee, function, caller, caller_function in calls:
        if callee != previous:
            files[callee] = files.get(callee, 0) + 1
            if previous is not None and Path(callee).parent != Path(previous).parent:
                changes += 1
            previous = callee
        if str(Path(callee).parent) not in folders:
            folders.append(str(Path(callee).parent))
        if caller is not None and layer(callee) > layer(caller):
            edge = f"{caller}:{caller_function} -> {callee}:{function}"
            up[edge] = up.get(edge, 0) + 1
    return {"files": files, "returns": sum(n - 1 for n in files.values()), "folders": folders,
            "folder_changes": changes, "calls_back_up": up}


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--game", choices=sorted(START), action="append", help="default: both")
    parser.add_argument("--json", action="store_true", help="print the figures as JSON")
    args = parser.parse_args(argv)
    package_of, rank = layers()
    out = {}
    for game in args.game or sorted(START, reverse=True):
        with tempfile.TemporaryDirectory(prefix="trace_paths_") as tmp:
            recorder = Recorder({})
            run_episode(game, Path(tmp), recorder)
        if "setup" not in recorder.marks:
            raise SystemExit(f"trace_paths: {game}: no game master's _on_setup was traced")
        cut = recorder.marks["setup"]
        out[game] = {"a": summary(recorder.calls[:cut], package_of, rank),
                     "b": summary(recorder.calls[cut:], package_of, rank)}
    if args.json:
        print(json.dumps(out, indent=1))
        return 0
    names = {"a": "(a) an instance from its generator to its episode", "b": "(b) an answer to scores.json"}
    for game, paths in out.items():
        for key, path in paths.items():
            print(f"{game} {names[key]}: {len(path['files'])} files, {path['returns']} returns, {len(path['folders'])} folders, "
                  f"{path['folder_changes']} folder changes, {sum(path['calls_back_up'].values())} calls back up a layer")
            print("  folders: " + " > ".join(path["folders"]))
            print("  files:   " + ", ".join(f"{f}" + (f" x{n}" if n > 1 else "") for f, n in path["files"].items()))
            for edge, n in path["calls_back_up"].items():
                print(f"  up: {edge}" + (f" (x{n})" if n > 1 else ""))
    return 0


if __name__ == "__main__":
    sys.exit(main())
