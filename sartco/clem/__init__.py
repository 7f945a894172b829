"""Shared clemcore glue for the SARTCo games (installed, because clemcore unloads modules that
live inside a game folder). Reuse these from any game whose player writes code:

- parsing.parse_code / ParseError      find the code in an answer (no code -> aborted);
                                       answer_lines: what one line is (labels, fences, Python)
- outcomes                             the one ErrorCode -> clemcore outcome/logging translation
- harness.HarnessGuard / harness_scores   harness faults (sandbox, master, scorer) -> harness_error,
                                       aborted, never the model's error
- building.build_for / parse_failure_for / finish_build / BuildRecord   execute, compare, record, end
- feedback.feedback_for / max_attempts   the one message after a failed attempt (feedback
                                       experiments: execution facts only, never the target)
- players.Builder / SourcedPlayer      the players; a built-in player's answers come from one
                                       answer source chosen when it is made (answers: Scripted,
                                       GoldCode = mock, InstructFollower = rulebased;
                                       dialogue_answers: cobot_describe's mock describer and follower)
- scoring.BuildScorer                  scores.json from the recorded build
- paper.finish_paper / PaperScorer     the paper protocol (cobot_instruct_paper): the authors' per-turn
                                       reading and scores at the end of a dialogue, ours beside them
- pictures.attach_all                  full-size board pictures (the transcript's links), written at `clem score`
- rulebased.RulebasedBackend           `-m rulebased` (the rule-based follower as a model) and
                                       `-m erring` (erring, erring_dialogue: the same players with
                                       seeded mistakes and repairs)
- backends/                            the backend files and model entries that `sartco register DIR`
                                       writes into DIR, where clemcore finds them (sartco.register)
- benchmark.BuildBenchmark             the GameBenchmark base; checks the instance file up front
                                       against the game's episode type (json_fields, sartco.episode)
- episodes.board_fields / instruct_episode   the episode fields the generators write
- transcript.MarkdownTranscript        messages as they read (code as code) in transcript.html
- batching.OpenAIBatchingBackend       `openai_batching`: concurrent requests to an OpenAI-compatible server
- stub_server.StubServer, benchrun     a local stub model server; `sartco bench-run`
- training.gym_env                     clemcore's gym env on the train split, ES / cell F1 rewards
- describer / dialogue                 cobot_describe's Describer, its dialogue modes (questions,
                                       corrections) and their scorer
"""
