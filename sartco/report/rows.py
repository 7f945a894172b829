"""The report's row: one scored episode as every table of `sartco report` reads it, typed
(EpisodeRow), built in one place (episode_row) from the episode's own files and read for a
whole results folder by `collect` (every table, passk.py for each sample folder, compare.py).

The model is the episode's own record: clemcore writes the run's model identifier (the results
folder name of the model pair, e.g. `mock` or `gpt-4o-t0.0--gpt-4o-t0.0`) into interactions.json
as meta.results_folder; only an episode without a readable interactions.json falls back to the
name of the folder it lies in (results/<model>/<game>/<experiment>/<episode>).
"""
from pathlib import Path
from typing import NotRequired, TypedDict

from sartco.episode import (ATTEMPTS, CELL_F1, CODEBLEU, ERROR_CATEGORY, ES_AT_1, EXACT_MATCH, EXECUTION_SUCCESS,
                            FUNCTION_GENERALISATION, HARNESS_REASON, MAX_ATTEMPTS)
from sartco.clem.tooling.sampling import SAMPLES  # RESULTS/samples/s1..sN: passk.py reads them
from sartco.errors import UserError
from sartco.world import ErrorCode

from .files import load_json, number


class EpisodeRow(TypedDict):  # (no `from __future__ import annotations`: NotRequired must be seen)
    game: str                   # the game entry (experiment.json's game_name)
    model: str                  # the model pair's identifier (see the module doc)
    experiment: str
    episode: str                # the episode folder, instance_<game_id>
    board_type: str
    object_type: str
    task: str
    source: str                 # instruction source ("" when the experiment has none)
    split: str
    ablation: object            # the experiment's ablation field (None: not an ablation)
    aborted: int                # 0 | 1
    em: float | None            # the episode scores, None when missing or NaN (files.number)
    cb: float | None
    es: float | None
    f1: float | None
    fg: float | None
    probed: bool                # the scores have Function Generalisation
    category: str               # the error category; parse_error for an aborted episode without one
    harness_reason: str         # why the harness failed ("" when it did not)
    max_attempts: int           # 1 unless a feedback experiment
    feedback_of: str
    mode: str                   # cobot_describe's dialogue mode, "oneshot" elsewhere
    es1: float | None           # ES of the first attempt (= es with one attempt)
    attempts_used: float | None
    experiment_fields: dict     # experiment.json as read
    scores: dict                # scores.json's episode scores
    player_models: dict | None  # scores.json's player_models
    experiment_counts: NotRequired[tuple | None]   # added by sartco.report.completeness

# how the tables and report.html name a task
TASK_NAMES = {"first_order": "first-order (multi-turn)", "sequence_function": "function from puts",
              "optimal_function": "optimal function", "repetition": "repetition"}


def model_of(episode_dir: Path) -> str:
    """The model pair an episode was played by (see the module doc)."""
    try:
        return str(load_json(episode_dir / "interactions.json")["meta"]["results_folder"])
    except (UserError, KeyError, TypeError):
        return episode_dir.parent.parent.parent.name


def episode_row(game: str, exp: dict, episode_dir: Path, data: dict) -> EpisodeRow:
    """The row of one episode: its game, its experiment.json, its folder and its scores.json."""
    scores = data.get("episode scores", {})
    return EpisodeRow(
        game=game, model=model_of(episode_dir), experiment=exp["name"], episode=episode_dir.name,
        board_type=exp["board_type"], object_type=exp["object_type"], task=exp["task"],
        source=exp.get("source", ""), split=exp.get("split", ""), ablation=exp.get("ablation"),
        aborted=int(scores.get("Aborted", 0) or 0),
        em=number(scores.get(EXACT_MATCH)), cb=number(scores.get(CODEBLEU)),
        es=number(scores.get(EXECUTION_SUCCESS)), f1=number(scores.get(CELL_F1)),
        fg=number(scores.get(FUNCTION_GENERALISATION)), probed=FUNCTION_GENERALISATION in scores,
        category=scores.get(ERROR_CATEGORY) or (str(ErrorCode.PARSE_ERROR) if scores.get("Aborted") else "unknown"),
        harness_reason=scores.get(HARNESS_REASON) or "",
        max_attempts=int(scores.get(MAX_ATTEMPTS, 1)),  # logged by the scorer of a feedback experiment
        feedback_of=exp.get("feedback_of", ""), mode=exp.get("mode") or "oneshot",
        es1=number(scores.get(ES_AT_1, scores.get(EXECUTION_SUCCESS))),
        attempts_used=number(scores.get(ATTEMPTS)),
        experiment_fields=exp, scores=scores, player_models=data.get("player_models"),
    )


def collect(results: Path, games: list[str] | None = None) -> list[EpisodeRow]:
    """One row per scored episode (sartco.report.rows.episode_row)."""
    if not results.is_dir():
        raise UserError(f"{results}: no such results folder")
    experiments: dict[Path, dict | None] = {}
    episodes = []
    for path in sorted(results.rglob("scores.json")):
        if path.relative_to(results).parts[0] == SAMPLES:  # `sartco sample`'s runs: passk.md
            continue
        episode_dir = path.parent
        exp_dir = episode_dir.parent
        if exp_dir not in experiments:
            exp_file = exp_dir / "experiment.json"
            experiments[exp_dir] = load_json(exp_file) if exp_file.is_file() else None
        exp = experiments[exp_dir]
        if not exp or "task" not in exp or "board_type" not in exp:
            continue  # not a SARTCo experiment
        game = exp.get("game_name") or exp_dir.parent.name
        if games and game not in games:
            continue
        try:
            data = load_json(path)
        except UserError:
            continue  # listed as unreadable by sartco.report.completeness
        episodes.append(episode_row(game, exp, episode_dir, data))
    if not episodes:
        raise UserError(f"{results}: no scored SARTCo episodes (run `clem score -r {results}` first)")
    return episodes
