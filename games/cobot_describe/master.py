"""cobot_describe: a Describer looks at the target board and writes instructions; a Builder who
sees only those instructions writes Python; the game master runs the code and scores the board.

Player 1, the Describer: the describer prompt (environment, the board as the paper's text grid,
the object's name, the grid explanation; answer under "Instruction:"), sartco.clem.describer.
Player 2, the Builder: cobot_instruct's builder prompt (with its in-context examples) holding the
describer's instruction, sartco.clem.builder; its code runs through sartco.clem.building.
`clem run -g cobot_describe -m A B`: A describes, B builds; `-m A`: A plays both roles.
Programmatic players: `mock` and `rulebased` describe with the episode's template instruction;
as builders both are the rule-based follower reading the describer's text (never gold code).

Episode = one instance of in/instances.json (instancegenerator.py):
  describer_prompt      the Describer's prompt
  builder_prompt        the Builder's prompt with INSTRUCTION_SLOT where the instruction goes
  template_instruction  what the programmatic describer writes
  board_id, board_type, object_type, combo_name, task, rows, cols, target, given_code, gold_code
  record                the board record (what `sartco import-instructions` turns into a dataset)
  describer_script / builder_script (optional)  raw answers of `mock`, for scripted tests
Modes (experiment field `mode`, sartco.clem.dialogue): oneshot; clarify (the builder may ask up to
K questions, the describer answers); correct (the describer sees each built board and answers
"Done" or a correction, the builder rebuilds from scratch, up to R corrections); clarify_correct.
Every build is logged (a board event each, all records under `sartco_attempts`), the last one
under `sartco_build` (scored); what was said under `sartco_dialogue`.
Outcomes: no instruction, or no code in any builder answer -> aborted; otherwise the last build
decides (sartco.clem.outcomes; an answer without code after a build loses). A describer who
answers a review with neither "Done" nor a correction, or gives no answer to a question after
a build, leaves the last board standing.
"""
from __future__ import annotations

from clemcore.clemgame import DialogueGameMaster, Player
from clemcore.clemgame.errors import ParseError

from sartco.clem import benchmark
from sartco.clem.building import ATTEMPTS_KEY, BUILD_KEY, BuildRecord, build_for, log_build, parse_failure_for
from sartco.clem.describer import Describer, fill_builder_prompt, log_instruction, parse_instruction
from sartco.clem.dialogue import (DIALOGUE_KEY, DONE, BuilderView, DialogueBuilder, DialogueLog, DialogueScorer,
                                  answer_message, correction_message, parse_answer, parse_builder_answer,
                                  parse_review, programmatic_review, question_message, review_message, settings_of)
from sartco.clem.outcomes import log_outcome, set_attempts_outcome
from sartco.clem.transcript import MarkdownTranscript
from sartco.world import ErrorCode

DESCRIBER_PARSERS = {"instruction": parse_instruction, "answer": parse_answer, "review": parse_review}


class CobotDescribe(MarkdownTranscript, DialogueGameMaster):

    def _on_setup(self, **instance):
        self.episode = instance
        self.settings = settings_of(self.experiment)
        self.log = DialogueLog(self.settings.mode, self.settings.questions, self.settings.corrections)
        self.expect = "instruction"          # the describer's next answer: instruction | answer | review
        self.instruction: str | None = None
        self.answers: list[str] = []         # the describer's answers since the last build
        self.correction: str | None = None   # pending for the builder
        self.builds: list[BuildRecord] = []
        describer_model = self.player_models[0]
        builder_model = self.player_models[1] if len(self.player_models) > 1 else describer_model
        self.describer = Describer(describer_model, template=instance["template_instruction"],
                                   script=instance.get("describer_script"), reply=self._programmatic_reply)
        self.builder = DialogueBuilder(builder_model, view=self._builder_view, script=instance.get("builder_script"))
        self.add_player(self.describer, initial_context=instance["describer_prompt"])
        self.add_player(self.builder)

    def _programmatic_reply(self) -> str:
        """The mock describer after its instruction: answers from the target, reviews by comparing."""
        if self.expect == "answer":
            return f"Answer: {self.episode['template_instruction']}"
        return programmatic_review(self.builds[-1].cells, self.episode["target"])

    def _builder_view(self) -> BuilderView:
        e = self.episode
        return BuilderView(e["task"], e["given_code"], e["rows"], e["cols"], self.instruction or "", list(self.answers),
                           self.correction, self.builds[-1].cells if self.builds else None, self._left("question"))

    def _left(self, kind: str) -> int:
        limit = self.settings.questions if kind == "question" else self.settings.corrections
        return limit - self.log.count(kind)

    def _parse_response(self, player: Player, response: str):
        if player is self.builder:
            return parse_builder_answer(response, self.settings, self.log.count("question"))
        return DESCRIBER_PARSERS[self.expect](response)

    def _advance_game(self, player: Player, parsed):
        e = self.episode
        if player is self.builder:
            kind, text = parsed
            if kind == "question":
                self.log.add("question", text, len(self.builds))
                self.expect = "answer"
                self.set_context_for(self.describer, question_message(text))
            else:
                self._built(build_for(e, text))
            return
        if self.expect == "instruction":
            self.instruction = parsed
            log_instruction(self, parsed, e["combo_name"])
            self.log.add("instruction", parsed, 0, describer=True)
            self.set_context_for(self.builder, fill_builder_prompt(e["builder_prompt"], parsed))
        elif self.expect == "answer":
            self.answers.append(parsed)
            self.log.add("answer", parsed, len(self.builds), describer=True)
            self.set_context_for(self.builder, answer_message(parsed, self._left("question")))
        elif parsed is None:  # the review says Done: the board stands
            self.log.add("done", DONE, len(self.builds))
            self._end()
        else:
            self.correction = parsed
            self.log.add("correction", parsed, len(self.builds), describer=True)
            self.set_context_for(self.builder, correction_message(parsed, self._left("question")))

    def _built(self, record: BuildRecord):
        """A build (or a builder answer without code) is over: the describer reviews it while
        corrections are left, else the episode ends with it."""
        self.builds.append(record)
        self.answers, self.correction = [], None
        log_build(self, record, final=False, attempt=len(self.builds))
        if record.error != ErrorCode.PARSE_ERROR and self._left("correction") > 0:
            self.expect = "review"
            self.set_context_for(self.describer, review_message(record, self._left("correction")))
        else:
            self._end()

    def _end(self):
        """The last build is the episode's result (its board event is logged already)."""
        self.log_key(BUILD_KEY, self.builds[-1].to_json())
        set_attempts_outcome(self.state, [b.category for b in self.builds])

    def _on_parse_error(self, error: ParseError):
        e = self.episode
        role = self.current_player.game_role
        if self.current_player is self.builder:
            self._built(parse_failure_for(e, f"{role}: {error.reason}"))
            return
        if self.expect == "instruction":
            log_instruction(self, None, e["combo_name"], error=error.reason)
        self.log.add(f"no_{self.expect}", error.reason, len(self.builds))
        if self.builds:
            self._end()  # the board stands
        else:
            self._built(parse_failure_for(e, f"{role}: {error.reason}"))

    def _on_after_game(self):
        self.log_key(ATTEMPTS_KEY, [b.to_json() for b in self.builds])
        self.log_key(DIALOGUE_KEY, self.log.to_json())
        log_outcome(self)


class CobotDescribeBenchmark(benchmark.BuildBenchmark):
    master_class = CobotDescribe
    scorer_class = DialogueScorer
