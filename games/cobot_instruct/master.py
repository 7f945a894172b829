"""cobot_instruct: a Builder model writes Python that builds a target board from instructions.

Thin by design: _parse_response only finds the code (sartco.clem.parsing), _advance_game
collects it and, after the last instruction, runs it through sartco.program and records the
result (sartco.clem.building); the scorer turns the recorded build into numbers
(sartco.clem.scoring). The builder never sees the target board.

Episode = one instance of in/instances.json:
  prompt        the initial prompt (environment, examples, context), sent with the first turn
  turns         the text of each turn: one for single-turn tasks, one per put for multi-turn
  instructions  the bare instruction texts (what the rule-based follower reads)
  given_code    code the builder is given and the program starts with (repetition: the object function)
  gold_code     the gold answer in the task's code style (exact match, CodeBLEU)
  gold_turns    the gold code of each turn (what `mock` answers)
  target        the target board in canonical cells form; rows, cols; task
Multi-turn: the builder's code accumulates over the turns and is executed once at the end.
Repair (experiment field repair_attempts > 0): a failed build is fed back and the builder may
answer again with complete code, up to that many times.
"""
from __future__ import annotations

from clemcore.clemgame import DialogueGameMaster, Player
from clemcore.clemgame.errors import ParseError

from sartco.clem import benchmark  # the module, not the class: one GameBenchmark subclass per master.py
from sartco.clem.builder import Builder, rulebased_code
from sartco.clem.building import ATTEMPTS_KEY, BuildRecord, build, log_build, parse_failure
from sartco.clem.outcomes import log_outcome, set_outcome
from sartco.clem.parsing import parse_code
from sartco.clem.scoring import BuildScorer

GAME_NAME = "cobot_instruct"


def repair_prompt(record: BuildRecord) -> str:
    return ("Your code did not build the target board: "
            f"{record.summary()}\nWrite the complete corrected code.")


class CobotInstruct(DialogueGameMaster):

    def _on_setup(self, **instance):
        self.instance = instance
        self.turns: list[str] = instance["turns"]
        self.codes: list[str] = []
        self.attempts: list[dict] = []
        self.repairs_left = int(self.experiment.get("repair_attempts", 0))
        self.repairing = False
        self.builder = Builder(self.player_models[0], gold_turns=instance["gold_turns"], rulebased=self._follow,
                               script=instance.get("script"))
        self.add_player(self.builder, initial_prompt=instance.get("prompt") or None,
                        initial_context=self.turns[0])

    def _follow(self, turn: int, context: dict) -> str:
        """What the rule-based follower writes for this turn (model `rulebased`)."""
        from sartco.follower import FollowError, follow_turn
        i = self.instance
        rows, cols = i.get("rows", 8), i.get("cols", 8)
        if i["task"] == "first_order" and len(i["instructions"]) > 1:  # one turn's puts
            k = min(turn, len(i["instructions"]) - 1)
            try:
                return follow_turn(i["instructions"][k], i["instructions"][:k], rows, cols)
            except FollowError as error:
                return f"# I cannot follow this instruction: {error}"
        return rulebased_code(i["instructions"], i["task"], i.get("given_code", ""), rows, cols)

    def _parse_response(self, player: Player, response: str) -> str:
        return parse_code(response)

    def _advance_game(self, player: Player, code: str):
        if self.repairing:
            self.codes = [code]  # a repair answer is the complete program
        else:
            self.codes.append(code)
            if len(self.codes) < len(self.turns):
                self.set_context_for(self.builder, self.turns[len(self.codes)])
                return
        i = self.instance
        record = build("\n".join(self.codes), i["target"], given_code=i.get("given_code", ""),
                       rows=i.get("rows", 8), cols=i.get("cols", 8), turn_codes=self.codes)
        self.attempts.append(record.to_json())
        if record.es or self.repairs_left <= 0:
            log_build(self, record)
            set_outcome(self.state, record.category)
            return
        log_build(self, record, final=False)
        self.repairs_left -= 1
        self.repairing = True
        self.set_context_for(self.builder, repair_prompt(record))

    def _on_parse_error(self, error: ParseError):
        i = self.instance
        record = parse_failure(i["target"], error.reason or "no code found", turn_codes=self.codes,
                               rows=i.get("rows", 8), cols=i.get("cols", 8))
        self.attempts.append(record.to_json())
        log_build(self, record)
        set_outcome(self.state, record.category)

    def _on_after_game(self):
        if len(self.attempts) > 1:
            self.log_key(ATTEMPTS_KEY, self.attempts)
        log_outcome(self)


class CobotInstructBenchmark(benchmark.BuildBenchmark):
    master_class = CobotInstruct
    scorer_class = BuildScorer
