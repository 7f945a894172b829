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
Outcomes: no "Instruction:" in the describer's answer or no code in the builder's -> aborted;
otherwise the build decides (sartco.clem.outcomes).
"""
from __future__ import annotations

from clemcore.clemgame import DialogueGameMaster, Player
from clemcore.clemgame.errors import ParseError

from sartco.clem import benchmark
from sartco.clem.builder import Builder, rulebased_code
from sartco.clem.building import build_for, finish_build, parse_failure_for
from sartco.clem.describer import DescribeScorer, Describer, fill_builder_prompt, log_instruction, parse_instruction
from sartco.clem.outcomes import log_outcome
from sartco.clem.parsing import parse_code
from sartco.clem.transcript import MarkdownTranscript


class CobotDescribe(MarkdownTranscript, DialogueGameMaster):

    def _on_setup(self, **instance):
        self.episode = instance
        self.instruction: str | None = None
        describer_model = self.player_models[0]
        builder_model = self.player_models[1] if len(self.player_models) > 1 else describer_model
        self.describer = Describer(describer_model, template=instance["template_instruction"],
                                   script=instance.get("describer_script"))
        self.builder = Builder(builder_model, rulebased=self._follow, mock_follows=True,
                               script=instance.get("builder_script"))
        self.add_player(self.describer, initial_context=instance["describer_prompt"])
        self.add_player(self.builder)

    def _follow(self, turn: int, context: dict) -> str:
        """The rule-based builder reads the describer's instruction, nothing else."""
        e = self.episode
        return rulebased_code(self.instruction, e["task"], e.get("given_code", ""), e["rows"], e["cols"])

    def _parse_response(self, player: Player, response: str) -> str:
        if player is self.describer:
            return parse_instruction(response)
        return parse_code(response)

    def _advance_game(self, player: Player, parsed: str):
        e = self.episode
        if player is self.describer:
            self.instruction = parsed
            log_instruction(self, parsed, e["combo_name"])
            self.set_context_for(self.builder, fill_builder_prompt(e["builder_prompt"], parsed))
            return
        finish_build(self, build_for(e, parsed))

    def _on_parse_error(self, error: ParseError):
        e = self.episode
        role = self.current_player.game_role
        if self.current_player is self.describer:
            log_instruction(self, None, e["combo_name"], error=error.reason)
        finish_build(self, parse_failure_for(e, f"{role}: {error.reason}"))

    def _on_after_game(self):
        log_outcome(self)


class CobotDescribeBenchmark(benchmark.BuildBenchmark):
    master_class = CobotDescribe
    scorer_class = DescribeScorer
