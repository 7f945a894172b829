"""Shared clemcore glue for the SARTCo games (installed, because clemcore unloads modules that
live inside a game folder). Reuse these from any game whose player writes code:

- parsing.parse_code / ParseError      find the code in an answer (no code -> aborted)
- outcomes                             the one ErrorCode -> clemcore outcome/logging translation
- building.build_for / parse_failure_for / finish_build / BuildRecord   execute, compare, record, end
- feedback.feedback_for / max_attempts   the one message after a failed attempt (feedback
                                       experiments: execution facts only, never the target)
- builder.Builder                      the Builder player (mock = gold, rulebased, human)
- scoring.BuildScorer                  scores.json from the recorded build
- pictures.attach_all                  board pictures for transcripts, written at `clem score`
- rulebased.RulebasedBackend           `-m rulebased` (the rule-based follower as a model)
- describer / dialogue                 cobot_describe's Describer, its dialogue modes (questions,
                                       corrections) and their scorer
"""
