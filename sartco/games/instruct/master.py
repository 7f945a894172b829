"""cobot_instruct: a Builder model writes Python that builds a target board from instructions.

Thin by design: _parse_response only finds the code (sartco.clem.core.parsing), _advance_game
collects it and, after the last instruction, runs it through sartco.program and records the
result (sartco.clem.core.building); the scorer turns the recorded build into numbers
(sartco.clem.core.scoring); the transcript ends with a score card of those numbers (sartco.clem.core.card).
The builder never sees the target board.

Episode = one instance of in/instances.json (sartco.episode.InstructEpisode):
  turns         the text of each turn: one for single-turn tasks, one per put for multi-turn; the
                first holds the prompt (environment, examples, context)
  instructions  the bare instruction texts (what the rule-based follower reads)
  given_code    code the builder is given and the program starts with (repetition: the object function)
  gold_code     the gold answer in the task's code style (exact match, CodeBLEU)
  gold_turns    the gold code of each turn (what `mock` answers)
  target        the target board in canonical cells form; rows, cols; task
Multi-turn: the builder's code accumulates over the turns and is executed once at the end.
Feedback experiments (experiment field `attempts` N > 1):
after a failed attempt the builder gets sartco.clem.core.feedback's message (error code and message,
or "the board you built differs", with the built board as grid_text; never the target) and
answers with the complete corrected code, run on a fresh board, up to N attempts. An answer
without code is then a failed attempt (parse_error) like any other; the episode is aborted only
when no attempt held code. Every attempt's record is logged under `sartco_attempts`, the last one
under `sartco_build` (scored).

The paper protocol (game entry cobot_instruct_paper, in/instances_paper.json; instance field
`protocol: "paper"`): the turns are the authors' user messages (`messages`), `mock` answers the
episode's `mock_answers`, no answer is refused, and after the last one sartco.games.instruct.paper scores
every turn as the authors' scorer did and records our build beside it.
"""
from __future__ import annotations

from clemcore.clemgame import Player
from clemcore.clemgame.errors import ParseError

from sartco.clem.core.benchmark import BuildBenchmark
from sartco.clem.core.answer_builds import build_for, start_build
from sartco.clem.core.building import BuildRecord, parse_failure_for, record_build
from sartco.clem.core.feedback import feedback_for, max_attempts
from sartco.clem.core.instance_checks import json_fields
from sartco.clem.core.master import BuildGameMaster
from sartco.clem.core.outcomes import log_outcome
from sartco.clem.core.parsing import parse_code
from sartco.games.instruct.paper import PAPER_EPISODE_FIELDS, finish_paper, is_paper
from sartco.games.instruct.scorer import InstructScorer
from sartco.clem.players.answers import instruct_answers
from sartco.clem.players.sourced import Builder
from sartco.episode import ATTEMPTS_KEY, InstructEpisode, PaperProtocolEpisode


class CobotInstruct(BuildGameMaster):
    scorer_class = InstructScorer  # BuildScorer's scores, plus the paper's in a paper-protocol episode

    def _on_setup(self, **instance):
        self.instance: InstructEpisode | PaperProtocolEpisode = instance
        self.paper = is_paper(instance)
        self.turns: list[str] = instance["messages"] if self.paper else instance["turns"]
        self.codes: list[str] = []  # the code of each turn (paper protocol: the raw answers)
        self.attempts: list[BuildRecord] = []
        self.max_attempts = max_attempts(self.experiment)
        model = self.player_models[0]
        self.builder = Builder(model, instruct_answers(model.name, instance, paper=self.paper))
        self.add_player(self.builder, initial_context=self.turns[0])
        if not self.paper:  # the paper protocol builds every turn at the end (finish_paper)
            self.builder.on_answer = self._build_ahead

    def _parse_response(self, player: Player, response: str) -> str:
        return response if self.paper else parse_code(response)  # the paper protocol reads answers at the end

    def _codes_with(self, code: str) -> list[str]:
        """The codes of the attempt once this answer's code is in."""
        return [code] if self.attempts else [*self.codes, code]  # a repair is the complete program

    def _builds(self, codes: list[str]) -> bool:
        """Whether the attempt ends with these codes: a repair, or the last turn's answer."""
        return bool(self.attempts) or len(codes) >= len(self.turns)

    def _build_ahead(self, response: str) -> None:
        """The build this answer will lead to, started as it comes in (answer_builds.start_build)."""
        codes = self._codes_with(parse_code(response))
        if self._builds(codes):
            start_build(self.instance, "\n".join(codes), turn_codes=codes)

    def _advance_game(self, player: Player, code: str):
        self.codes = self._codes_with(code)
        if not self._builds(self.codes):
            self.set_context_for(self.builder, self.turns[len(self.codes)])
            return
        if self.paper:
            finish_paper(self, self.instance, self.codes)
            return
        self._end_attempt(build_for(self.instance, "\n".join(self.codes), turn_codes=self.codes))

    def _on_parse_error(self, error: ParseError):
        self._end_attempt(parse_failure_for(self.instance, error.reason or "no code found", turn_codes=self.codes))

    def _end_attempt(self, record: BuildRecord):
        """One attempt is over: end the episode (success or no attempt left) or feed the failure back."""
        self.attempts.append(record)
        left = self.max_attempts - len(self.attempts)
        if record.es or left <= 0:
            record_build(self, self.attempts, final=True, instance=self.instance)
            return
        record_build(self, self.attempts, final=False)
        self.codes = []
        self.set_context_for(self.builder, feedback_for(record, attempts_left=left))

    def _on_after_game(self):
        if self.max_attempts > 1:
            self.log_key(ATTEMPTS_KEY, [a.to_json() for a in self.attempts])
        log_outcome(self)


class CobotInstructBenchmark(BuildBenchmark):
    master_class = CobotInstruct
    episode_fields = json_fields(InstructEpisode)

    @classmethod
    def fields_of(cls, episode: dict) -> dict:
        """A paper-protocol episode carries the authors' messages and gold answers instead of turns."""
        return PAPER_EPISODE_FIELDS if is_paper(episode) else cls.episode_fields
