"""The one place where sartco's error vocabulary meets clemcore's outcomes and logging.

- no code in the answer (ErrorCode.PARSE_ERROR)      -> Outcome.ABORTED (clemcore: not played)
- the program raised, broke a rule, hit a budget     -> Outcome.FAILURE (lost, category recorded)
- the program ran and built another board            -> Outcome.FAILURE (lost, mismatch category)
- the program built the target                       -> Outcome.SUCCESS
- the harness failed (ErrorCode.HARNESS_ERROR: the sandbox, the game master or the scorer, never
  the model)                                        -> Outcome.ABORTED (not played, Main Score NaN)
Feedback (repair) experiments, several attempts: the last attempt decides, except that a last
attempt without code loses (the builder did play) unless no attempt held code at all (aborted,
as in the paper's protocol) - `outcome_of_attempts`; a harness fault in any attempt aborts.
The paper protocol (sartco.games.instruct.paper) never aborts: its episode succeeds when every turn's ES
does (`set_share_outcome`).
Games call `set_attempts_outcome` or `set_share_outcome` (both through
sartco.clem.core.building.record_build), and `log_outcome`; nothing else maps codes to outcomes.
"""
from __future__ import annotations

from clemcore.clemgame import metrics
from clemcore.clemgame.master import Outcome

from sartco.world import ErrorCode, category_family


NO_ANSWER = "model server: "  # how the reason of a NoAnswer begins (sartco resume plays such episodes again)


class NoAnswer(str):
    """The answer of a request the model server never answered (sartco.clem.tooling.batching gave up:
    timeouts, 5xx or other API errors after its retries): empty text that carries the reason.
    The model did not answer, so it is never charged: the game master (sartco.clem.core.harness.
    HarnessGuard) records the episode as harness_error with this reason. A str, so it travels
    through clemcore's Player, batch runner and GameMasterEnv unchanged."""

    def __new__(cls, reason: str):
        text = super().__new__(cls, "")
        text.reason = reason
        return text


def outcome_for(category: str | ErrorCode | None) -> Outcome:
    """The clemcore outcome of an episode whose final build has this category (None = success)."""
    family = category_family(category)
    if family == "success":
        return Outcome.SUCCESS
    return Outcome.ABORTED if family in ("parse", "harness") else Outcome.FAILURE


def outcome_of_attempts(categories) -> Outcome:
    """The outcome of an episode whose attempts ended in these categories, in order (one
    attempt: the same as outcome_for)."""
    categories = list(categories)
    if not categories:
        raise ValueError("an episode without attempts has no outcome")
    if ErrorCode.HARNESS_ERROR in categories:
        return Outcome.ABORTED
    outcome = outcome_for(categories[-1])
    if outcome is Outcome.ABORTED and any(outcome_for(c) is not Outcome.ABORTED for c in categories):
        return Outcome.FAILURE
    return outcome


def set_attempts_outcome(state, categories) -> Outcome:
    """Move a clemcore GameState to the outcome of these attempts (outcome_of_attempts)."""
    return _enter(state, outcome_of_attempts(categories))


def set_share_outcome(state, share: float) -> Outcome:
    """The paper protocol (never aborted): success when every turn succeeded (share 1), else lost."""
    return _enter(state, Outcome.SUCCESS if share == 1 else Outcome.FAILURE)


def _enter(state, outcome: Outcome) -> Outcome:
    {Outcome.SUCCESS: state.succeed, Outcome.FAILURE: state.failed, Outcome.ABORTED: state.abort}[outcome]()
    return outcome


def log_outcome(game_master) -> None:
    """Log Aborted, Success and Lose (0/1 ints) from the game master's final state; clemcore's
    scorer copies them into scores.json and `clem eval` derives % played from Aborted."""
    outcome = game_master.state.outcome
    game_master.log_key(metrics.METRIC_ABORTED, int(outcome is Outcome.ABORTED))
    game_master.log_key(metrics.METRIC_SUCCESS, int(outcome is Outcome.SUCCESS))
    game_master.log_key(metrics.METRIC_LOSE, int(outcome is Outcome.FAILURE))
