"""The scorer shared by the games that end in a build: turns the recorded build into numbers.

Episode scores (scores.json):
  Main Score         100 x execution success; NaN when the episode was aborted (no code found)
  Execution Success  0/1 (NaN when aborted), as the paper's ES
  Exact Match        0/1, whitespace-normalised, against the gold code of the same style (NaN when aborted)
  CodeBLEU           0..1, codebleu weights 0.25 x 4, against the same gold code (NaN when aborted)
  Cell Precision / Cell Recall / Cell F1   of the built board against the target (NaN when aborted)
  Error Category     "success", an ErrorCode value (python/world/sandbox error or mismatch), "parse_error"
                     or "harness_error" (the harness failed, not the model: aborted, sartco.clem.core.harness)
  Error Family       success | parse | python | world | sandbox | mismatch | harness
  Harness Error      why the harness failed (harness_error episodes only)
  Puts               pieces placed by the executed program
Aborted / Success / Lose come from the game's own log (sartco.clem.core.outcomes.log_outcome).

Feedback experiments (experiment field `attempts` N > 1, sartco.clem.core.feedback) add:
  ES@1               execution success of the first attempt (0/1; NaN when aborted)
  ES@N               execution success of the last attempt (= Execution Success)
  Attempts           attempts used (1..N)
  Max Attempts       N
  Attempt Categories the category of each attempt in order, joined by "," (a string, like
                     Error Category: clem eval keeps it in raw.csv and uses only Main Score/Aborted)
The other scores (and Main Score = 100 x final ES) are those of the last attempt. A last
attempt without code after attempts with code is lost, not aborted: ES/EM/CodeBLEU/cell scores 0.

Probed episodes (optimal_function and repetition, sartco.clem.core.probes) add:
  Function Generalisation  share of the K probes built exactly (NaN when aborted or not probed)
  Probe Categories   each probe's category in order ("success", an ErrorCode value or
                     "no_function"), joined by ","
  Probe Function     whose function was probed: "model", "given" (a repetition answer calling the
                     given function) or "none"
"""
from __future__ import annotations

from clemcore.clemgame import GameScorer, metrics

from sartco.episode import (ATTEMPT_CATEGORIES, ATTEMPTS, ATTEMPTS_KEY, BUILD_KEY, BUILD_SCORES, CATEGORY_SEPARATOR,
                            CELL_F1, CELL_PRECISION, CELL_RECALL, CODEBLEU, ERROR_CATEGORY, ERROR_FAMILY, ES_AT_1,
                            ES_AT_N, EXACT_MATCH, EXECUTION_SUCCESS, FUNCTION_GENERALISATION, HARNESS_REASON,
                            MAX_ATTEMPTS, PROBE_CATEGORIES, PROBE_FUNCTION, PROBES_KEY, PUTS)
from sartco.world import ErrorCode, category_family

from .building import BuildRecord
from .feedback import max_attempts
from .harness import fault_reason, harness_scores
from .probes import probed

NAN = float("nan")


# the order of a build's scores in scores.json
SCORE_ORDER = (EXECUTION_SUCCESS, EXACT_MATCH, CODEBLEU, CELL_PRECISION, CELL_RECALL, CELL_F1, ERROR_CATEGORY,
               ERROR_FAMILY, HARNESS_REASON, PUTS, metrics.BENCH_SCORE)


def build_scores(record: BuildRecord | None, aborted: bool) -> dict:
    """The scores of an episode's final build that need no gold code: Execution Success, cell
    precision / recall / F1, Error Category and Family, Puts (and Harness Error); when the
    episode was aborted (no record: no code was found) the numbers and Main Score are NaN."""
    if aborted or record is None:
        category = record.category if record else str(ErrorCode.PARSE_ERROR)
        scores = {**dict.fromkeys(BUILD_SCORES, NAN), ERROR_CATEGORY: category, ERROR_FAMILY: category_family(category)}
        if category == ErrorCode.HARNESS_ERROR:
            scores[HARNESS_REASON] = record.message
        return {**scores, PUTS: 0, metrics.BENCH_SCORE: NAN}
    return {EXECUTION_SUCCESS: int(record.es), CELL_PRECISION: record.precision, CELL_RECALL: record.recall,
            CELL_F1: record.f1, ERROR_CATEGORY: record.category, ERROR_FAMILY: record.family, PUTS: record.puts}


def _played_fault(interactions: dict) -> str | None:
    """The reason of the harness fault recorded while the episode was played, if it was one."""
    try:
        record = BuildRecord.from_json(interactions[BUILD_KEY])
    except Exception:  # no record, or one the scorer cannot read: the scorer's own fault is the reason
        return None
    return record.message if record.category == ErrorCode.HARNESS_ERROR else None


def probe_scores(probes: dict | None) -> dict:
    """Function Generalisation, Probe Categories, Probe Function of a probed episode from its
    probes record (sartco.clem.core.probes.run_probes; None when aborted or nothing was probed:
    FG NaN)."""
    share = probes["share"] if probes else None
    return {FUNCTION_GENERALISATION: NAN if share is None else float(share),
            PROBE_CATEGORIES: CATEGORY_SEPARATOR.join(p["category"] for p in (probes or {}).get("probes", [])),
            PROBE_FUNCTION: (probes or {}).get("source") or "none"}


class BuildScorer(GameScorer):
    """The scores of an episode's recorded build, against the episode's gold code."""

    def compute_scores(self, interactions: dict) -> None:
        """clemcore's scoring, unchanged, inside the one guard of every scorer of ours: an exception
        makes the episode a harness_error (sartco.clem.core.harness), never a model's score or a lost
        scores.json. An episode recorded as a harness fault while it was played keeps that reason
        (a setup fault made no request, and clemcore's request ratios then divide by zero)."""
        try:
            super().compute_scores(interactions)
        except Exception as exc:  # a fault of the scorer, never the model's
            harness_scores(self, _played_fault(interactions) or fault_reason("scorer", exc))

    def compute_round_score(self, round_idx, round_events) -> None:
        pass  # the build is judged once, at the end of the episode

    def compute_episode_scores(self, interactions: dict) -> None:
        from sartco.scores import code_bleu, exact_match

        aborted = bool(interactions.get(metrics.METRIC_ABORTED, 0))
        data = interactions.get(BUILD_KEY)
        record = BuildRecord.from_json(data) if data else None
        self.log_attempt_scores(interactions, record, aborted)
        if probed(self.game_instance):
            self.log_scores(probe_scores(None if aborted else interactions.get(PROBES_KEY)))
        scores = build_scores(record, aborted)
        if not (aborted or record is None):
            gold = self.game_instance["gold_code"]
            no_code = record.error == ErrorCode.PARSE_ERROR  # a feedback episode's last answer held no code
            scores[EXACT_MATCH] = 0 if no_code else int(exact_match(record.builder_code, gold))
            scores[CODEBLEU] = 0.0 if no_code else float(code_bleu(record.builder_code, gold))
            scores[metrics.BENCH_SCORE] = self.bench_score(interactions, record)
        self.log_scores({name: scores[name] for name in SCORE_ORDER if name in scores})

    def bench_score(self, interactions: dict, record: BuildRecord) -> float:
        """Main Score of a played episode: 100 x execution success of the build."""
        return 100.0 * record.es

    def log_scores(self, scores: dict) -> None:
        for name, value in scores.items():
            self.log_episode_score(name, value)

    def log_attempt_scores(self, interactions: dict, final: BuildRecord | None, aborted: bool) -> None:
        """ES@1, ES@N, Attempts, Max Attempts, Attempt Categories - only in feedback experiments
        (the experiment allows more than one attempt: sartco.clem.core.feedback.max_attempts)."""
        n = max_attempts(self.experiment)
        if n <= 1:
            return
        attempts = [BuildRecord.from_json(a) for a in interactions.get(ATTEMPTS_KEY) or []]
        if not attempts and final is not None:
            attempts = [final]
        self.log_episode_score(ES_AT_1, NAN if aborted or not attempts else int(attempts[0].es))
        self.log_episode_score(ES_AT_N, NAN if aborted or not attempts else int(attempts[-1].es))
        self.log_episode_score(ATTEMPTS, len(attempts))
        self.log_episode_score(MAX_ATTEMPTS, n)
        self.log_episode_score(ATTEMPT_CATEGORIES, CATEGORY_SEPARATOR.join(a.category for a in attempts))
