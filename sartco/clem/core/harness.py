"""Harness faults are never the model's error: the one place per path where they are caught.

A harness fault is anything the model did not cause: the model server gave no answer (the
backend's retries given up: a `NoAnswer`, sartco.clem.tooling.batching), the sandbox could not run the
program or gave no usable answer (ErrorCode.HARNESS_ERROR from sartco.program, raised as HarnessFault by
sartco.clem.core.answer_builds.build_for and sartco.games.instruct.paper.finish_paper), or the game master or the
scorer raised. Such an episode is recorded with its reason and counts as not played:
- playing (`HarnessGuard`, BuildGameMaster's second base, after ScoreCard and before
  MarkdownTranscript: sartco.clem.core.master): an exception in a step ends the
  episode at once with a `harness_error` build record (its reason as the message) under
  BUILD_KEY, a board event for the transcript, Aborted 1 (clemcore: not played) and the
  interactions.json written as usual; a `NoAnswer` answer takes the same path before the game
  master sees it (the turn's messages and the request logged as clemcore's step logs them; no parse);
  so does a fault of the game master's setup, at the episode's first step: clemcore drops an
  episode whose setup raised (no record at all), so `HarnessGuard.setup` keeps the reason and seats
  one `SetupFailed` player, which asks no model;
- scoring (`sartco.clem.core.scoring.BuildScorer.compute_scores`, every scorer's base): an exception
  replaces the episode's scores with `harness_scores`: Main Score and the build scores NaN,
  Aborted 1, Error Category harness_error, its reason under HARNESS_REASON.
`sartco report` counts these episodes apart (harness.md) and exits with status 3.
"""
from __future__ import annotations

import math
import traceback
from pathlib import Path

from clemcore.backends import CustomResponseModel
from clemcore.clemgame import Player, metrics

from sartco.episode import BUILD_SCORES, ERROR_CATEGORY, ERROR_FAMILY, HARNESS_REASON, PUTS
from sartco.program.execution import clean
from sartco.world import ErrorCode

from .building import parse_failure_for, record_build
from .errors import HarnessFault
from .outcomes import NoAnswer, log_outcome

REASON_CHARS = 500
HARNESS = ErrorCode.HARNESS_ERROR


def fault_reason(where: str, exc: BaseException) -> str:
    """One clean line: where the harness failed and why (a HarnessFault: its own reason; any
    other exception: its type, text and the harness line that raised it)."""
    if isinstance(exc, HarnessFault):
        text = exc.reason
    else:
        frames = traceback.extract_tb(exc.__traceback__)
        at = f" at {Path(frames[-1].filename).name}:{frames[-1].lineno}" if frames else ""
        text = f"{where}: {type(exc).__name__}: {exc}{at}"
    return clean(text)[:REASON_CHARS]


class HarnessGuard:
    """BuildGameMaster's second base (sartco.clem.core.master): a step that raises ends the episode as
    harness_error. It comes before MarkdownTranscript, whose step escapes the answer: a NoAnswer
    must be seen before that turns it into plain text, and a fault of that step is caught here."""

    def setup(self, **instance):
        self.harness_instance = instance  # the target and board size of the record of a fault
        self.setup_fault: str | None = None
        try:
            super().setup(**instance)
        except Exception as exc:  # recorded at the first step: clemcore would drop the episode
            self.setup_fault = fault_reason("game master setup", exc)
            self.players_by_names.clear()
            self.context_for_player.clear()
            self._current_player_idx = 0
            self._current_player = SetupFailed()
            self.add_player(self._current_player, initial_context=self.setup_fault)
            self.state.game_id = instance.get("game_id")

    def step(self, response):
        try:
            if self.setup_fault is not None:
                raise HarnessFault(self.setup_fault)
            if isinstance(response, NoAnswer):  # the model server gave none: the model is not charged
                self.log_gm_to_player(self.get_context_for(self.current_player), self.current_player)
                self.log_player_to_gm(response, self.current_player)  # as clemcore's step: the turn's
                self.count_request()                                  # messages, a request (not parsed)
                raise HarnessFault(response.reason)
            return super().step(response)
        except Exception as exc:  # a fault of the game master or the sandbox, never the model's
            record = parse_failure_for(self.harness_instance, fault_reason("game master", exc), error=HARNESS)
            record_build(self, [record], final=True)
            log_outcome(self)
            self.log_game_end()
            return True, {}


class SetupFailed(Player):
    """The one player of an episode whose setup raised (HarnessGuard.setup). Its model answers in
    this process (a CustomResponseModel: no request in either of clemcore's runners), and its answer
    is never read: the first step records the fault."""

    def __init__(self):
        super().__init__(CustomResponseModel())

    def _custom_response(self, context) -> str:
        return ""


def harness_scores(scorer, reason: str) -> None:
    """Replace an episode's game scores by those of a harness fault (clemcore's request counts stay)."""
    scores = scorer.scores[metrics.KEY_EPISODE_SCORES]
    kept = {name: scores[name] for name in (metrics.METRIC_REQUEST_COUNT, metrics.METRIC_REQUEST_COUNT_PARSED,
                                            metrics.METRIC_REQUEST_COUNT_VIOLATED, metrics.METRIC_REQUEST_SUCCESS_RATIO)
            if name in scores}
    scores.clear()
    scores.update(kept)
    scores.update({metrics.METRIC_ABORTED: 1, metrics.METRIC_SUCCESS: 0, metrics.METRIC_LOSE: 0,
                   **dict.fromkeys(BUILD_SCORES, math.nan), ERROR_CATEGORY: str(HARNESS),
                   ERROR_FAMILY: HARNESS.family, PUTS: 0, HARNESS_REASON: reason, metrics.BENCH_SCORE: math.nan})
