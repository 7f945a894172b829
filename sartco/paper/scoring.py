"""Per-turn and per-dialogue scores of the paper protocol (paper-protocol README, "Scoring").

    score_turn(prediction, gold, variant, given_function="") -> TurnScore(em, cb, es, category, message)
    score_dialogue(responses, episode) -> DialogueScore(em, cb, es, turns)

Per turn, over the keys present in both gold and prediction (output; or function and usage):
- EM: for each key with a non-empty gold, the gold's non-empty stripped lines equal the
  prediction's non-empty stripped lines, where every one of those containing ":" is then
  replaced by the text after its first ":" up to any second ":" (stripped; an empty result
  stays as a line; see prediction_lines). A `def ...:` or `for ...:` line therefore never matches: EM is 0 on
  every function and repetition cell, as in the paper. An empty prediction fails.
- CB: for each such key, CodeBLEU (sartco.scores.code_bleu: codebleu's calc_codebleu([gold],
  [pred], lang="python", weights 0.25 x 4) with its data-flow order fixed, see its docstring),
  rounded to 3 decimals, > 0.5; an empty prediction fails. Table 3's CB is this pass rate.
- ES: each key but usage runs alone on a fresh 8x8 board through sartco.program.execute (the
  sandbox; never exec) with PAPER semantics (the authors' exec inside a function: separate
  globals and locals, the board passed in is the one scored; sartco.program.child.namespaces), after dropping one trailing newline, ";", "." or ","; regular boards get
  the sample's gold object function + "\n" in front of both gold and prediction. A program
  containing the text "while" fails (the authors' scorer refused it: category `forbidden`,
  message "While loop not supported"); a program that raises fails with its ErrorCode; a board
  other than the gold program's board fails with the mismatch category; a gold program that
  raises (never on the published data) leaves no board to equal: the turn fails. The leak-free
  ES (`alone=True`, beyond the paper) runs the prediction without the gold function in front.
A turn succeeds on a metric when every compared key does. An empty answer fails all three
(category parse_error, "empty answer"; the authors' scorer crashed on it).
Per dialogue: each metric is the share of successful turns; Table 3 is the mean over a cell's
dialogues. `category` is None exactly when ES succeeded.
"""
from __future__ import annotations

from dataclasses import asdict, dataclass
from functools import lru_cache

from sartco.program import PAPER, compare, execute
from sartco.scores import code_bleu
from sartco.world import ErrorCode

from .reading import read_answer
from .vocabulary import NOT_EXECUTED, VARIANTS

WHILE_REFUSAL = "While loop not supported"
CB_THRESHOLD = 0.5
CB_DECIMALS = 3
TRAILING = ("\n", ";", ".", ",")


@dataclass(frozen=True, slots=True)
class TurnScore:
    em: bool
    cb: bool
    es: bool
    category: str | None      # ErrorCode value when ES failed, None on ES success
    message: str = ""         # why ES failed (the error's message, the while refusal, ...)

    def to_json(self) -> dict:
        return asdict(self)


@dataclass(frozen=True, slots=True)
class DialogueScore:
    em: float                 # share of turns with EM success
    cb: float
    es: float
    turns: list

    def to_json(self) -> dict:
        return {"em": self.em, "cb": self.cb, "es": self.es, "turns": [t.to_json() for t in self.turns]}


EMPTY = TurnScore(False, False, False, str(ErrorCode.PARSE_ERROR), "empty answer")


def gold_lines(text: str) -> list[str]:
    return [line.strip() for line in text.split("\n") if line.strip()]


def prediction_lines(text: str) -> list[str]:
    """The non-empty stripped lines; then each of them containing ":" is replaced by the text after
    its first ":" up to a second one (`line.split(":")[1]`, as the authors' scorer), stripped.
    A cut line never contains ":", so it never equals a gold `def ...:` / `for ...:` line, even
    when the answer's label shares the line ("Function: def f(...):") -- the README's reason for
    the paper's EM of 0 on every function cell. A line the cut leaves empty ("Here is the code:",
    "# step 1:") stays in the list as "" (the empty lines are dropped before the cut)."""
    return [line.split(":")[1].strip() if ":" in line else line for line in gold_lines(text)]


def exact_match(prediction: str, gold: str) -> bool:
    return bool(prediction.strip()) and prediction_lines(prediction) == gold_lines(gold)


def codebleu_pass(prediction: str, gold: str) -> bool:
    return bool(prediction.strip()) and round(code_bleu(prediction, gold), CB_DECIMALS) > CB_THRESHOLD


def es_program(code: str, given_function: str = "") -> str:
    """What ES runs for one key: one trailing newline/;/./, dropped, the given function in front."""
    if code.endswith(TRAILING):
        code = code[:-1]
    return f"{given_function}\n{code}" if given_function else code


@lru_cache(maxsize=4096)
def _gold_run(program: str):
    return execute(program, semantics=PAPER)


def execution(prediction: str, gold: str, given_function: str = "", alone: bool = False) -> tuple[bool, str | None, str]:
    """(es, category, message) of one executed key; `alone`: the prediction without the given
    function in front (the leak-free ES), the gold program with it."""
    program = es_program(prediction, "" if alone else given_function)
    if "while" in program:
        return False, str(ErrorCode.FORBIDDEN), WHILE_REFUSAL
    ex = execute(program, semantics=PAPER)
    if not ex.ok:
        return False, str(ErrorCode(ex.error)), ex.message or ""
    gold_run = _gold_run(es_program(gold, given_function))
    if gold_run.error == ErrorCode.HARNESS_ERROR:  # the sandbox's fault: never kept for later turns
        _gold_run.cache_clear()
    if not gold_run.ok:  # no gold board to equal (the authors' scorer fails the turn too)
        return False, str(ErrorCode(gold_run.error)), f"the gold program failed: {gold_run.message or ''}"
    cmp = compare(ex.cells, gold_run.cells)
    if cmp.es:
        return True, None, ""
    return False, str(ErrorCode(cmp.category)), "the program built another board than the gold program"


def score_turn(prediction: dict, gold: dict, variant: str, given_function: str = "", alone: bool = False) -> TurnScore:
    """One turn's EM, CB pass and ES (see the module doc). prediction: read_answer's dict."""
    if variant not in VARIANTS:
        raise ValueError(f"unknown variant {variant!r}; expected one of {', '.join(VARIANTS)}")
    keys = [k for k in gold if k in prediction and gold[k].strip()]
    if not keys:
        return TurnScore(False, False, False, str(ErrorCode.PARSE_ERROR),
                         f"the prediction has none of the keys {', '.join(gold)}")
    if not any(prediction[k].strip() for k in keys):
        return EMPTY
    em = all(exact_match(prediction[k], gold[k]) for k in keys)
    cb = all(codebleu_pass(prediction[k], gold[k]) for k in keys)
    executed = [k for k in keys if k not in NOT_EXECUTED]
    if not executed:
        return TurnScore(em, cb, False, str(ErrorCode.PARSE_ERROR), "no code to execute")
    es, category, message = True, None, ""
    for key in executed:
        ok, category, message = execution(prediction[key], gold[key], given_function, alone)
        if not ok:
            es = False
            break
    return TurnScore(em, cb, es, category if not es else None, message if not es else "")


def score_dialogue(responses: list[str], episode, alone: bool = False) -> DialogueScore:
    """Score the raw answers of one dialogue (one per turn). episode: a PaperEpisode or its
    to_json() dict. Missing answers at the end count as empty answers; more answers than turns
    or a non-string answer is a ValueError. `alone`: every answer runs without the given function
    in front (the leak-free ES; the gold programs keep it)."""
    ep = episode if isinstance(episode, dict) else episode.to_json()
    golds, variant, given = ep["gold"], ep["variant"], ep.get("given_function", "")
    if not isinstance(responses, list) or not all(isinstance(r, str) for r in responses):
        raise ValueError("responses must be a list of strings, one raw answer per turn")
    if len(responses) > len(golds):
        raise ValueError(f"{len(responses)} responses for {len(golds)} turn(s)")
    turns = []
    for i, gold in enumerate(golds):
        answer = responses[i] if i < len(responses) else ""
        turns.append(EMPTY if not answer.strip() else score_turn(read_answer(answer, variant), gold, variant, given, alone))
    n = len(turns)
    return DialogueScore(em=sum(t.em for t in turns) / n, cb=sum(t.cb for t in turns) / n,
                         es=sum(t.es for t in turns) / n, turns=turns)
