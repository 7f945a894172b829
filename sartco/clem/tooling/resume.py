"""`sartco resume -r RESULTS -g GAME -m MODEL [-m MODEL2]`: complete an interrupted run in place.

clemcore has no resume; its results folder has one folder per episode (results/<model-pair>/
<game>/<experiment>/instance_<game_id>), so the episodes still to do are known
(sartco.clem.tooling.completeness): those of the experiments the run's sessions chose (run.json;
a resume chooses nothing new). Resume first scores the played-but-unscored episodes (as `clem
score` does), then plays exactly the missing and errored ones (and those whose interactions.json
is unreadable, and the harness_error ones the model server gave no answer to, scored just now
included) through clemcore's own `run` with an instance filter, into the same folder and under
the same episode ids, and scores them; nothing else is played again or rescored. A folder complete
afterwards is transcribed (as `clem transcribe`: every episode's transcript.html). The instance
file is run.json's (sartco.clem.core.runs); each episode is played with the temperature,
max_tokens and batch size of the session that chose it (runs.settings_for), so the result
equals an uninterrupted run's. `-t` / `-l` / `-b` only fill in what run.json does not record
(else clem run's defaults, CLEM_DEFAULTS); one that contradicts run.json is refused.

Exit status: 0 when the folder is complete afterwards (also when nothing was to do); 2 when it
refuses (a model or game clem does not know, no such results folder, the instance file changed since the first run, runs of
different instance files in one folder, a setting that contradicts run.json); 3
(sartco.clem.tooling.completeness.INCOMPLETE_STATUS) when episodes are still not scored
afterwards, or the model server again gave no answer to some.
"""
from __future__ import annotations

import argparse
import json
import shutil
from pathlib import Path

from sartco.clem.core import runs
from sartco.clem.core.errors import ProvenanceError
from sartco.clem.core.benchmark import resume_selector
from sartco.clem.core.outcomes import NO_ANSWER
from sartco.episode import HARNESS_REASON
from sartco.errors import UserError

from .selectors import check_models, game_spec
from .completeness import INCOMPLETE_STATUS, Unverifiable, check_game, episode_folder, needs_play


def configure(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("-r", "--results", required=True, type=Path, help="the results folder of the first run")
    parser.add_argument("-g", "--game", required=True, help="the game entry (e.g. cobot_instruct)")
    parser.add_argument("-m", "--models", required=True, nargs="+", help="the model(s), as given to clem run")
    parser.add_argument("-t", "--temperature", type=float, default=None,
                        help="sampling temperature, only for a run.json that does not record it (else 0.0)")
    parser.add_argument("-l", "--max_tokens", type=int, default=None,
                        help="maximum tokens per turn, only for a run.json that does not record it (else 300)")
    parser.add_argument("-b", "--batch_size", type=int, default=None,
                        help="as clem run's -b, only for a run.json that does not record it (else 1)")


# clem run's defaults (clemcore 3.7's cli): what a run played with when run.json does not say
CLEM_DEFAULTS = {"temperature": 0.0, "max_tokens": 300, "batch_size": 1}
OPTIONS = {"temperature": "-t", "max_tokens": "-l", "batch_size": "-b"}


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
    except (ProvenanceError, Unverifiable) as exc:
        raise UserError(str(exc)) from None
    return sum(expected.values()), problems, run


def settings(args: argparse.Namespace, game_dir: Path, run_json: dict | None, experiment: str) -> tuple:
    """(temperature, max_tokens, batch_size) to play an episode of `experiment` again with: run.json's
    (the session that chose it), else the option given, else CLEM_DEFAULTS. UserError when an option
    given contradicts run.json."""
    recorded = runs.settings_for(run_json, experiment)
    out = []
    for name, option in OPTIONS.items():
        given = getattr(args, name)
        if recorded[name] is not None and given is not None and given != recorded[name]:
            raise UserError(f"{game_dir}: {option} {given} differs from the {name} {recorded[name]} that {experiment} "
                            f"was played with (run.json); leave {option} out: resume plays with the run's settings")
        out.append(next(v for v in (recorded[name], given, CLEM_DEFAULTS[name]) if v is not None))
    return tuple(out)


def score(game: str, game_dir: Path, problems: list[dict]) -> None:
    """Score the played episodes among `problems` (clemcore's scoring, as `clem score`)."""
    from clemcore.clemgame import GameBenchmark, GameRegistry

    files = [f for f in (episode_folder(game_dir, p) / "interactions.json" for p in problems) if f.is_file()]
    if files:
        spec = next(s for s in GameRegistry.from_directories_and_cwd_files().get_game_specs_that_unify_with(game)
                    if s.game_name == game)
        with GameBenchmark.load_from_spec(spec) as bench:
            bench.compute_scores(files)


def play(args: argparse.Namespace, instance_path: Path, episodes: list[dict], temperature: float, max_tokens: int,
         batch_size: int) -> None:
    """Play `episodes` again with one set of settings, through clemcore's `run`."""
    from clemcore import cli as clem_cli
    from clemcore.backends import ModelSpec

    wanted = {(p["experiment"], p["game_id"]) for p in episodes}
    # the game's benchmark records this session in run.json as a resume of these episodes
    selector = resume_selector(args.game, args.results, [[p["experiment"], p["game_id"]] for p in episodes], batch_size)
    try:
        clem_cli.run(selector, ModelSpec.from_strings(args.models),
                     gen_args=dict(temperature=temperature, max_tokens=max_tokens),
                     instances_filename=str(instance_path.with_suffix("")), results_dir_path=args.results,
                     batch_size=batch_size,
                     instances_filter=lambda row: (row["experiment"]["name"], row["game_instance"]["game_id"]) in wanted)
    except SystemExit:  # clemcore exits 1 after logging an episode's exception; the check afterwards tells
        pass


def run(args: argparse.Namespace) -> int:
    check_models(args.models)
    game_spec(args.game)
    game_dir = args.results / run_folder(args.models) / args.game
    if not game_dir.is_dir():
        raise UserError(f"{game_dir}: no such folder (nothing was played for this game and model; play it with "
                        f"`clem run -g {args.game} -m {' '.join(args.models)} -r {args.results}`)")
    expected, problems, run_json = _problems(game_dir)
    instance_path, _ = runs.played_instance_file(game_dir, run_json)
    # first score what was played: a harness_error among them (no answer from the model server) is played again below
    rescore = [p for p in problems if not needs_play(game_dir, p)]
    score(args.game, game_dir, rescore)
    if rescore:
        expected, problems, run_json = _problems(game_dir)
    replay = [p for p in problems if needs_play(game_dir, p)] + unanswered(game_dir, problems)
    groups: dict[tuple, list[dict]] = {}
    for p in replay:
        groups.setdefault(settings(args, game_dir, run_json, p["experiment"]), []).append(p)
    shown = ("; ".join(f"temperature {t}, max_tokens {m}, batch size {b}" for t, m, b in groups) or "nothing to play")
    chosen = runs.selection(run_json) if run_json else None
    scope = f"experiment {', '.join(sorted(chosen))}" if chosen else "all experiments"
    print(f"sartco resume: {game_dir}: {expected} episodes in {instance_path.name} ({scope}), {len(replay)} to play, "
          f"{len(rescore)} to score ({shown})" + ("" if run_json else " (no run.json: the game's default instance file)"),
          flush=True)
    for p in replay:  # a stale scores.json or error.json of the failed play must not survive it
        shutil.rmtree(episode_folder(game_dir, p), ignore_errors=True)
    for (temperature, max_tokens, batch_size), episodes in groups.items():
        play(args, instance_path, episodes, temperature, max_tokens, batch_size)
    score(args.game, game_dir, replay)
    _, left, _ = _problems(game_dir)
    if left:
        print(f"sartco resume: still {len(left)} of {expected} episodes not scored (first: {left[0]['experiment']} "
              f"game_id {left[0]['game_id']}: {left[0]['problem']}); run sartco resume again", flush=True)
        return INCOMPLETE_STATUS
    still = unanswered(game_dir, [])
    if still:
        print(f"sartco resume: the model server gave no answer again to {len(still)} of the {len(replay)} episodes "
              f"played (harness_error; first: {still[0]['experiment']} game_id {still[0]['game_id']}); check the "
              f"server (its address: run.json's models, base_url), then run sartco resume again", flush=True)
        return INCOMPLETE_STATUS
    from clemcore.clemgame.transcripts.builder import build_transcripts

    build_transcripts(str(game_dir))
    print(f"sartco resume: {game_dir}: all {expected} episodes scored and transcribed")
    return 0
