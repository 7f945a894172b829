"""cobot_describe: a Describer looks at the target board and writes instructions; a Builder who
sees only those instructions writes Python; the game master runs the code and scores the board.

Player 1, the Describer: the describer prompt (environment, the board as the paper's text grid,
the object's name, the grid explanation; answer under "Instruction:"), sartco.games.describe.players.
Player 2, the Builder: cobot_instruct's builder prompt (with its in-context examples) holding the
describer's instruction, sartco.clem.players.sourced; its code runs through sartco.clem.core.building.
`clem run -g cobot_describe -m A B`: A describes, B builds; `-m A`: A plays both roles.
Programmatic players (sartco.games.describe.players): `mock` and `rulebased` describe with the
episode's template instruction; as builders both are the rule-based follower reading the
describer's text (never gold code); `erring` omits and garbles pieces as describer and slips as
builder (sartco.games.describe.erring_dialogue).

Episode = one instance of in/instances.json (instancegenerator.py; sartco.episode.DescribeEpisode):
  describer_prompt      the Describer's prompt
  builder_prompt        the Builder's prompt with INSTRUCTION_SLOT where the instruction goes
  template_instruction  what the programmatic describer writes
  board_id, board_type, object_type, combo_name, task, rows, cols, target, given_code, gold_code
  record                the board record (what `sartco import-instructions` turns into a dataset)
  describer_script / builder_script (optional)  raw answers of `mock`, for scripted tests
Modes (experiment field `mode`, sartco.games.describe.dialogue): oneshot; clarify (the builder may ask up to
K questions, the describer answers); correct (the describer sees each built board and answers
"Done" or a correction, the builder rebuilds from scratch, up to R corrections); clarify_correct.
Every build is logged (a board event each, all records under `sartco_attempts`), the last one
under `sartco_build` (scored); what was said under `sartco_dialogue`.
Outcomes: no instruction, or no code in any builder answer -> aborted; otherwise the last build
decides (sartco.clem.core.outcomes; an answer without code after a build loses). A describer who
answers a review with neither "Done" nor a correction, or gives no answer to a question after
a build, leaves the last board standing.
"""
from __future__ import annotations

from clemcore.clemgame import Player
from clemcore.clemgame.errors import ParseError

from sartco.clem.core.benchmark import BuildBenchmark
from sartco.clem.core.answer_builds import build_for
from sartco.clem.core.building import BuildRecord, parse_failure_for, record_build
from sartco.clem.core.instance_checks import json_fields
from sartco.clem.core.master import BuildGameMaster
from sartco.clem.core.outcomes import log_outcome
from sartco.games.describe.dialogue import (answer_message, correction_message, fill_builder_prompt, log_instruction,
                                           parse_answer, parse_builder_answer, parse_instruction, parse_review,
                                           question_message, review_message, settings_of)
from sartco.games.describe.players import Describer, builder_answers, describer_answers
from sartco.games.describe.scorer import DialogueScorer
from sartco.games.describe.turns import BuilderTurn, Dialogue, DialogueLog, Move, Said, State
from sartco.clem.players.sourced import Builder
from sartco.episode import ATTEMPTS_KEY, DIALOGUE_KEY, DescribeEpisode

DESCRIBER_PARSERS = {State.INSTRUCTION: parse_instruction, State.ANSWER: parse_answer, State.REVIEW: parse_review}


class CobotDescribe(BuildGameMaster):
    scorer_class = DialogueScorer

    def _on_setup(self, **instance):
        self.episode: DescribeEpisode = instance
        self.settings = settings_of(self.experiment)
        self.dialogue = Dialogue(DialogueLog(self.settings.mode, self.settings.questions, self.settings.corrections))
        describer_model = self.player_models[0]
        builder_model = self.player_models[1] if len(self.player_models) > 1 else describer_model
        self.describer = Describer(describer_model, describer_answers(describer_model.name, instance, self.dialogue))
        self.builder = Builder(builder_model, builder_answers(builder_model.name, instance, self.dialogue))
        self.add_player(self.describer, initial_context=instance["describer_prompt"])
        self.add_player(self.builder)

    def _parse_response(self, player: Player, response: str):
        if player is self.builder:
            return parse_builder_answer(response, self.settings, self.dialogue.log.count(Said.QUESTION))
        return DESCRIBER_PARSERS[self.dialogue.state](response)

    def _advance_game(self, player: Player, parsed):
        episode, dialogue = self.episode, self.dialogue
        if player is self.builder:
            turn: BuilderTurn = parsed
            if turn.move is Move.QUESTION:
                dialogue.ask(turn.text)
                self.set_context_for(self.describer, question_message(turn.text))
            else:
                self._built(build_for(episode, turn.text))
            return
        if dialogue.state is State.INSTRUCTION:
            dialogue.instruct(parsed)
            log_instruction(self, parsed, episode["combo_name"])
            self.set_context_for(self.builder, fill_builder_prompt(episode["builder_prompt"], parsed))
        elif dialogue.state is State.ANSWER:
            dialogue.answer(parsed)
            self.set_context_for(self.builder, answer_message(parsed, dialogue.left(Said.QUESTION)))
        elif parsed is None:  # the review says Done: the board stands
            dialogue.done()
            self._end()
        else:
            dialogue.correct(parsed)
            self.set_context_for(self.builder, correction_message(parsed, dialogue.left(Said.QUESTION)))

    def _built(self, record: BuildRecord):
        """A build (or a builder answer without code) is over: the describer reviews it while
        corrections are left, else the episode ends with it."""
        dialogue = self.dialogue
        dialogue.build(record)
        record_build(self, dialogue.builds, final=False)
        if dialogue.state is State.REVIEW:
            self.set_context_for(self.describer, review_message(record, dialogue.left(Said.CORRECTION)))
        else:
            self._end()

    def _end(self):
        """The last build is the episode's result (its board event is logged already)."""
        record_build(self, self.dialogue.builds, final=True, shown=True, instance=self.episode)

    def _on_parse_error(self, error: ParseError):
        episode, dialogue = self.episode, self.dialogue
        role = self.current_player.game_role
        if self.current_player is self.builder:
            self._built(parse_failure_for(episode, f"{role}: {error.reason}"))
            return
        if dialogue.state is State.INSTRUCTION:
            log_instruction(self, None, episode["combo_name"], error=error.reason)
        dialogue.fail(error.reason)
        if dialogue.state is State.OVER:
            self._end()  # the board stands
        else:
            self._built(parse_failure_for(episode, f"{role}: {error.reason}"))

    def _on_after_game(self):
        self.log_key(ATTEMPTS_KEY, [b.to_json() for b in self.dialogue.builds])
        self.log_key(DIALOGUE_KEY, self.dialogue.log.to_json())
        log_outcome(self)


class CobotDescribeBenchmark(BuildBenchmark):
    master_class = CobotDescribe
    episode_fields = json_fields(DescribeEpisode)
