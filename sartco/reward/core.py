"""The reward API: many (episode id, completion) pairs scored at once, as cobot_instruct scores
its episodes (see the package docstring).

One implementation with the game: the answers are escaped as the game master escapes them
(sartco.text.escape), read by sartco.clem.core.parsing (building.answers_job), run in
sandbox batches and judged (sartco.clem.core.sandbox; each answer's build and probes in one
confined child: `together`), probed as the master probes
(probes.run_probes_many, after the same condition as probes.log_probes) and turned into the
scores.json names by the scorer's own functions (scoring.build_scores, probe_scores).
"""
from __future__ import annotations

import json
import math
from collections.abc import Iterable, Iterator, Mapping, Sequence
from dataclasses import dataclass, field
from pathlib import Path

from clemcore.clemgame.master import Outcome

from sartco.clem.core.building import (BuildJob, BuildRecord, answers_job, build_jobs, escaped, parse_failure,
                                       program_of, sandbox_fault)
from sartco.clem.core.harness import fault_reason
from sartco.clem.core.errors import HarnessFault
from sartco.clem.core.outcomes import outcome_for
from sartco.clem.core.probes import GoldDraws, Probes, gold_draws, probe_programs, probed, run_probes_many
from sartco.clem.core.sandbox import together
from sartco.clem.core.scoring import build_scores, probe_scores
from sartco.collector import paused
from sartco.errors import UserError
from sartco.episode import CATEGORY_SEPARATOR, FUNCTION_GENERALISATION, PROBE_CATEGORIES
from sartco.protocols import file_episodes
from sartco.text import escape
from sartco.world import ErrorCode, category_family


@dataclass(frozen=True, slots=True)
class Reward:
    """The scores of one completion. The numbers are rewards (never NaN): an answer without code
    (aborted) has es 0, cell_f1 0.0; `scores` holds the same in scores.json's names and values,
    as `clem score` writes them (NaN when aborted)."""
    id: str
    es: int                      # 1 when the program ran and built the target
    cell_f1: float               # cell F1 of the built board against the target (0..1)
    precision: float
    recall: float
    category: str                # "success", an ErrorCode value, a mismatch, "parse_error" or "harness_error"
    family: str                  # success | parse | python | world | sandbox | mismatch | harness
    puts: int
    aborted: bool                # the game would abort the episode: no code found, or the harness failed
    function_generalisation: float | None  # share of the probes built exactly; None: not probed or aborted
    probe_categories: tuple[str, ...]
    message: str                 # the program's error message, or why the harness failed
    scores: dict = field(compare=False, repr=False)

    @property
    def harness_error(self) -> bool:
        """The harness, not the model, failed: no reward should be given for this completion."""
        return self.category == ErrorCode.HARNESS_ERROR


class Episodes(Mapping):
    """The episodes rewards are computed for: id -> cobot_instruct instance (the fields
    sartco.episode.InstructEpisode names). Holds each episode's gold probe draws once computed."""

    def __init__(self, instances: Mapping[str, dict]):
        self._instances = dict(instances)
        self._draws: dict[str, GoldDraws] = {}

    @classmethod
    def from_files(cls, paths: Iterable[str | Path]) -> "Episodes":
        """The episodes of cobot_instruct instance files, by id "<experiment>/<board id>/<task>"
        (the id of `sartco export-prompts --protocol sartco` and `sartco export-dataset`)."""
        instances: dict[str, dict] = {}
        for path in paths:
            for episode in file_episodes(Path(path)):
                if episode["id"] in instances:
                    raise UserError(f"{path}: episode id {episode['id']!r} occurs twice (ids must be unique)")
                instances[episode["id"]] = episode["instance"]
        return cls(instances)

    @classmethod
    def from_rows(cls, rows: Iterable[Mapping]) -> "Episodes":
        """The episodes of `sartco export-dataset` rows (a Hugging Face dataset or its JSON lines):
        id -> the row's `episode`."""
        episodes = cls({})
        episodes.include(rows)
        return episodes

    def include(self, rows: Iterable[Mapping]) -> None:
        """Add the episodes of `sartco export-dataset` rows whose id is not known yet."""
        for k, row in enumerate(rows):
            try:
                if row["id"] not in self._instances:
                    episode = json.loads(row["episode"])
                    if not (isinstance(episode, dict) and isinstance(episode.get("turns"), list)):
                        raise ValueError("the episode JSON is no cobot_instruct instance (no 'turns')")
                    self._instances[row["id"]] = episode
            except (KeyError, TypeError, ValueError) as exc:
                raise ValueError(f"row {k}: not a row of sartco export-dataset (an 'id' and an 'episode' "
                                 f"JSON text expected; {type(exc).__name__}: {exc})") from None

    def __getitem__(self, key: str) -> dict:
        return self._instances[key]

    def __iter__(self):
        return iter(self._instances)

    def __len__(self) -> int:
        return len(self._instances)

    def gold_draws(self, key: str) -> GoldDraws:
        """The episode's gold function and probe draws (computed once: they depend on the episode alone)."""
        if key not in self._draws:
            self._draws[key] = gold_draws(self._instances[key])
        return self._draws[key]


def answers_of(key: str, completion, turns: int) -> list[str]:
    """The completion as one escaped answer per turn (a str: the first turn's answer); missing
    turns are empty answers (no code: aborted), as in `sartco score-responses`."""
    answers = [completion] if isinstance(completion, str) else completion
    if not isinstance(answers, Sequence) or not all(isinstance(a, str) for a in answers):
        raise ValueError(f"episode {key!r}: the completion must be a str or a list of str (one per turn), "
                         f"got {type(completion).__name__}")
    if len(answers) > turns:
        raise ValueError(f"episode {key!r}: {len(answers)} answers for {turns} turn(s)")
    return [escape(a) for a in answers] + [""] * (turns - len(answers))


@paused()
def score(pairs: Iterable[tuple[str, str | Sequence[str]]], episodes: Episodes, *, probes: bool = True) -> list[Reward]:
    """The rewards of (episode id, completion) pairs, in input order. A completion is the answer
    text (single-turn episodes) or a list of answers, one per turn. Every pair is checked before
    anything runs (ValueError naming the pair: an unknown id, a completion of another type, more
    answers than turns). `probes`: probe the function of optimal_function and repetition answers
    (Function Generalisation), as the game does; off, those cells cost one program per answer.
    Python's cyclic collector is paused meanwhile (sartco.collector: no walk of the caller's
    whole heap in the middle of a batch)."""
    pairs = list(pairs)
    items = []
    for k, pair in enumerate(pairs):
        if not (isinstance(pair, (tuple, list)) and len(pair) == 2):
            raise ValueError(f"pair {k}: expected (episode id, completion), got {type(pair).__name__}")
        key, completion = pair
        if key not in episodes:
            raise ValueError(f"pair {k}: unknown episode id {key!r} ({len(episodes)} episodes are known)")
        instance = episodes[key]
        items.append((instance, answers_of(key, completion, len(instance["turns"]))))
    # each answer's build as build_many runs it (its texts escaped), or the record of no code
    jobs = [escaped(job) if isinstance(job, BuildJob) else job
            for job in (answers_job(instance, answers) for instance, answers in items)]
    results: list[dict | HarnessFault | None] = [None] * len(pairs)
    plans: dict[int, tuple[dict, str, GoldDraws]] = {}  # pair -> its probes' job
    for k, ((key, _), job) in enumerate(zip(pairs, jobs)):
        if probes and probed(episodes[key]) and isinstance(job, BuildJob):
            try:
                plans[k] = (episodes[key], job.builder_code, episodes.gold_draws(key))
            except HarnessFault as fault:
                results[k] = fault
    probe = {k: probe_programs(*plan) for k, plan in plans.items()}  # (its function, whose def, its programs)
    with together(_answer_programs(jobs, probe)):  # one child per answer
        records = build_jobs(jobs)
        places = [k for k in plans if records[k].error != ErrorCode.HARNESS_ERROR]
        for k, result in zip(places, run_probes_many([plans[k] for k in places], [probe[k] for k in places])):
            results[k] = result
    return [reward_of(key, record, probed(episodes[key]) and probes, result)
            for (key, _), record, result in zip(pairs, records, results)]


def _answer_programs(jobs: list[BuildJob | BuildRecord],
                     probe: Mapping[int, Probes]) -> Iterator[tuple[list[str], int, int]]:
    """Per answer with code: its build's program and its probe programs (`probe`: probe_programs'
    by answer), and its board size (sartco.clem.core.sandbox.together runs them in one child; the
    build and the probes then take their Executions)."""
    for k, job in enumerate(jobs):
        if isinstance(job, BuildJob):
            yield [program_of(job), *(probe[k].programs if k in probe else [])], job.rows, job.cols


def reward_of(key: str, record: BuildRecord, is_probed: bool, probe_result) -> Reward:
    """One completion's Reward from its build record and probe result (a HarnessFault: the
    probe's sandbox failed, the episode is harness_error as in the game)."""
    if record.error == ErrorCode.HARNESS_ERROR:
        probe_result = sandbox_fault(record)
    if isinstance(probe_result, HarnessFault):  # as HarnessGuard records it
        record = parse_failure(record.target, fault_reason("game master", probe_result), rows=record.rows,
                               cols=record.cols, error=ErrorCode.HARNESS_ERROR)
        probe_result = None
    aborted = outcome_for(record.category) is Outcome.ABORTED
    scores = build_scores(record, aborted)
    if is_probed:
        scores.update(probe_scores(None if aborted else probe_result))
    fg = scores.get(FUNCTION_GENERALISATION)
    categories = scores.get(PROBE_CATEGORIES) or ""
    return Reward(id=key, es=int(record.es), cell_f1=float(record.f1), precision=float(record.precision),
                  recall=float(record.recall), category=record.category, family=category_family(record.category),
                  puts=0 if aborted else int(record.puts), aborted=aborted,
                  function_generalisation=None if fg is None or math.isnan(fg) else fg,
                  probe_categories=tuple(categories.split(CATEGORY_SEPARATOR)) if categories else (), message=record.message,
                  scores=scores)

