"""`sartco resume -r RESULTS -g GAME -m MODEL [-m MODEL2] [-t T] [-l L] [-b B]`: complete an
interrupted run in place.

clemcore has no resume; its results folder has one folder per episode (results/<model-pair>/
<game>/<experiment>/instance_<game_id>), so the episodes still to do are known
(sartco.clem.tooling.completeness). Resume plays exactly the missing and errored episodes (and those
whose interactions.json is unreadable, and the harness_error ones the model server gave no answer
to) through clemcore's own `run` with an instance filter, into the same folder and under the
same episode ids, then scores them and the played-but-unscored ones (as `clem score` does; nothing else is played again or rescored). The instance file is
run.json's (sartco.clem.core.provenance); `-t` / `-l` default to run.json's generation settings.

Exit status: 0 when the folder is complete afterwards (also when nothing was to do); 2 when it
refuses (no such results folder, the instance file changed since the first run, runs of
different instance files in one folder); 3 (sartco.clem.tooling.completeness.INCOMPLETE_STATUS) when
episodes are still not scored afterwards, or the model server again gave no answer to some.
"""
from __future__ import annotations

import argparse
import json
import shutil
from pathlib import Path

from sartco.clem.core import provenance
from sartco.clem.core.benchmark import resume_selector
from sartco.clem.core.outcomes import NO_ANSWER
from sartco.episode import HARNESS_REASON
from sartco.errors import UserError

from .completeness import INCOMPLETE_STATUS, Unverifiable, check_game, episode_folder, needs_play


def configure(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("-r", "--results", required=True, type=Path, help="the results folder of the first run")
    parser.add_argument("-g", "--game", required=True, help="the game entry (e.g. cobot_instruct)")
    parser.add_argument("-m", "--models", required=True, nargs="+", help="the model(s), as given to clem run")
    parser.add_argument("-t", "--temperature", type=float, default=None,
                        help="sampling temperature (default: the first run's, from run.json; else 0.0)")
    parser.add_argument("-l", "--max_tokens", type=int, default=None,
                        help="maximum tokens per turn (default: the first run's, from run.json; else 300)")
    parser.add_argument("-b", "--batch_size", type=int, default=1, help="as clem run's -b (default 1)")


def run_folder(models: list[str]) -> str:
    """The results/<model-pair> folder name clemcore gives these model selectors."""
    from clemcore.backends import Model, ModelSpec
    from clemcore.backends.model_registry import ModelRegistry

    registry = ModelRegistry.from_packaged_and_cwd_files()
    specs = [registry.get_first_model_spec_that_unify_with(s) for s in ModelSpec.from_strings(models)]
    return Model.to_identifier([type("Named", (), {"__str__": lambda self, n=s.model_name: n})() for s in specs])


def unanswered(game_dir: Path, problems: list[dict]) -> list[dict]:
    """The scored episodes that are harness_error because the model server gave no answer (a
    NoAnswer: sartco.clem.core.outcomes): played again, as a missing episode is."""
    known = {(p["experiment"], p["game_id"]) for p in problems}
    out = []
    for path in sorted(Path(game_dir).glob("*/instance_*/scores.json")):
        try:
            reason = json.loads(path.read_text(encoding="utf-8"))["episode scores"].get(HARNESS_REASON)
        except (OSError, ValueError, KeyError, AttributeError):
            continue  # an unreadable scores.json is a problem of its own (completeness)
        key = (path.parent.parent.name, int(path.parent.name.split("_")[-1]))
        if isinstance(reason, str) and reason.startswith(NO_ANSWER) and key not in known:
            out.append({"experiment": key[0], "game_id": key[1], "problem": "no answer"})
    return out


def _problems(game_dir: Path):
    try:
        expected, problems, run = check_game(game_dir)
    except (provenance.ProvenanceError, Unverifiable) as exc:
        raise UserError(str(exc)) from None
    return sum(expected.values()), problems, run


def run(args: argparse.Namespace) -> int:
    from clemcore import cli as clem_cli
    from clemcore.backends import ModelSpec
    from clemcore.clemgame import GameBenchmark, GameRegistry

    game_dir = args.results / run_folder(args.models) / args.game
    if not game_dir.is_dir():
        raise UserError(f"{game_dir}: no such folder (nothing was played for this game and model; use clem run)")
    expected, problems, run_json = _problems(game_dir)
    instance_path, _ = provenance.played_instance_file(game_dir, run_json)
    replay = [p for p in problems if needs_play(game_dir, p)] + unanswered(game_dir, problems)
    rescore = [p for p in problems if p not in replay]
    print(f"sartco resume: {game_dir}: {expected} episodes in {instance_path.name}, {len(replay)} to play, "
          f"{len(rescore)} to score" + ("" if run_json else " (no run.json: the game's default instance file)"))
    if replay:
        generation = (run_json or {}).get("generation") or {}
        gen_args = dict(temperature=args.temperature if args.temperature is not None else generation.get("temperature", 0.0),
                        max_tokens=args.max_tokens if args.max_tokens is not None else generation.get("max_tokens", 300))
        for p in replay:  # a stale scores.json or error.json of the failed play must not survive it
            shutil.rmtree(episode_folder(game_dir, p), ignore_errors=True)
        wanted = {(p["experiment"], p["game_id"]) for p in replay}
        # the game's benchmark records this session in run.json as a resume of len(replay) episodes
        selector = resume_selector(args.game, args.results, len(replay))
        try:
            clem_cli.run(selector, ModelSpec.from_strings(args.models), gen_args=gen_args,
                         instances_filename=str(instance_path.with_suffix("")), results_dir_path=args.results,
                         batch_size=args.batch_size,
                         instances_filter=lambda row: (row["experiment"]["name"], row["game_instance"]["game_id"]) in wanted)
        except SystemExit:  # clemcore exits 1 after logging an episode's exception; the check below tells
            pass
    files = [episode_folder(game_dir, p) / "interactions.json" for p in replay + rescore]
    files = [f for f in files if f.is_file()]
    if files:
        spec = next(s for s in GameRegistry.from_directories_and_cwd_files().get_game_specs_that_unify_with(args.game)
                    if s.game_name == args.game)
        with GameBenchmark.load_from_spec(spec) as bench:
            bench.compute_scores(files)
    _, left, _ = _problems(game_dir)
    if left:
        print(f"sartco resume: still {len(left)} of {expected} episodes not scored (first: {left[0]['experiment']} "
              f"game_id {left[0]['game_id']}: {left[0]['problem']}); run sartco resume again", flush=True)
        return INCOMPLETE_STATUS
    still = unanswered(game_dir, [])
    if still:
        print(f"sartco resume: the model server gave no answer again to {len(still)} of {expected} episodes "
              f"(harness_error; first: {still[0]['experiment']} game_id {still[0]['game_id']}); run sartco resume again",
              flush=True)
        return INCOMPLETE_STATUS
    print(f"sartco resume: {game_dir}: all {expected} episodes scored")
    return 0
