"""The episode contract, in one place and free of dependencies (the bottom layer, beside
sartco.dataset): what an instance file's experiments and episodes hold, the names of the scores a
scorer writes into scores.json, and the keys a game master logs into interactions.json.

The instance generators write these records, the masters and scorers read them, the report reads
the scores by these names, and the tests build episodes with them; a field or a score is named
here and nowhere else.
"""
from __future__ import annotations

from typing import TypedDict

# ---------------------------------------------------------------------------- scores.json names
# every build episode (sartco.clem.scoring.BuildScorer); Main Score is clemcore's BENCH_SCORE
EXECUTION_SUCCESS = "Execution Success"
EXACT_MATCH = "Exact Match"
CODEBLEU = "CodeBLEU"
CELL_PRECISION = "Cell Precision"
CELL_RECALL = "Cell Recall"
CELL_F1 = "Cell F1"
ERROR_CATEGORY = "Error Category"
ERROR_FAMILY = "Error Family"
PUTS = "Puts"
BUILD_SCORES = (EXECUTION_SUCCESS, EXACT_MATCH, CODEBLEU, CELL_PRECISION, CELL_RECALL, CELL_F1)
# feedback (repair) episodes and the describe dialogue: the first and the last build
ES_AT_1 = "ES@1"
ES_AT_N = "ES@N"
ATTEMPTS = "Attempts"
MAX_ATTEMPTS = "Max Attempts"
ATTEMPT_CATEGORIES = "Attempt Categories"
CATEGORY_SEPARATOR = ","  # in Attempt Categories
# the describe dialogue (sartco.clem.dialogue)
CELL_F1_AT_1 = "Cell F1@1"
CELL_F1_AT_N = "Cell F1@N"
FIRST_SUCCESS_ROUND = "First Success Round"
QUESTIONS_ASKED = "Questions Asked"
CORRECTIONS_SENT = "Corrections Sent"
DESCRIBER_WORDS = "Describer Words"
DIALOGUE_SCORES = (ES_AT_1, ES_AT_N, CELL_F1_AT_1, CELL_F1_AT_N, FIRST_SUCCESS_ROUND, QUESTIONS_ASKED,
                   CORRECTIONS_SENT, DESCRIBER_WORDS)
ROUND_PREFIX = "ES Round "
# the describer's instruction (sartco.clem.describer)
DESCRIBER_ANSWERED = "Describer Answered"
INSTRUCTION_WORDS = "Instruction Words"
INSTRUCTION_CHARACTERS = "Instruction Characters"
OBJECT_NAMED = "Object Named"
# the paper protocol (sartco.clem.paper): shares of the dialogue's turns, 0..1
PAPER_SCORES = {"em": "Paper EM", "cb": "Paper CB", "es": "Paper ES"}


def round_score(k: int) -> str:
    """The per-round ES score of a describe dialogue: "ES Round <k>"."""
    return f"{ROUND_PREFIX}{k}"


# ---------------------------------------------------------------------------- interactions.json keys
BUILD_KEY = "sartco_build"            # one build's record (sartco.clem.building.BuildRecord.to_json)
ATTEMPTS_KEY = "sartco_attempts"      # every build of an episode, in order
MAX_ATTEMPTS_KEY = "sartco_max_attempts"  # the attempts the experiment allows (sartco.clem.feedback.max_attempts)
INSTRUCTION_KEY = "sartco_instruction"  # the describer's instruction: {"text", "error", "combo_name"}
DIALOGUE_KEY = "sartco_dialogue"      # the describe dialogue's log
PAPER_KEY = "sartco_paper"            # the paper protocol's reading: {"em", "cb", "es", "turns": [...]}
MARKDOWN_KEY = "markdown"             # clemcore renders the transcript's messages as Markdown


# ---------------------------------------------------------------------------- instance records
class BuildEpisode(TypedDict):
    """The fields of every episode that ends in a build (sartco.clem.episodes.board_fields), plus
    clemcore's game_id."""
    game_id: int
    board_id: str
    board_type: str        # sartco.dataset.BOARD_TYPES
    object_type: str       # sartco.dataset.OBJECT_TYPES
    combo_name: str
    task: str              # sartco.dataset.TASKS
    rows: int
    cols: int
    target: dict           # sartco.world.Board.to_json
    given_code: str        # the code the program starts with (repetition: the object function)
    gold_code: str         # the gold answer in the task's style


class InstructEpisode(BuildEpisode):
    """A cobot_instruct episode of our protocol: the builder's messages and what mock answers."""
    source: str            # sartco.dataset.SOURCES
    turns: list            # the builder's messages: the prompt, then one per later step
    instructions: list     # the instruction text of each turn
    gold_turns: list       # the gold answer of each turn (the mock player's answers)
    examples: list         # ids of the in-context examples
