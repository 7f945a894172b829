"""The episode contract, in one place and free of dependencies (the bottom layer, beside
sartco.dataset): what an instance file's experiments and episodes hold, the names of the scores a
scorer writes into scores.json, and the keys a game master logs into interactions.json.

The instance generators write these records, the masters and scorers read them, the report reads
the scores by these names, and the tests build episodes with them; a field or a score is named
here and nowhere else.
"""

from typing import Any, NotRequired, TypedDict

# ---------------------------------------------------------------------------- scores.json names
# every build episode (sartco.clem.core.scoring.BuildScorer); Main Score is clemcore's BENCH_SCORE
EXECUTION_SUCCESS = "Execution Success"
EXACT_MATCH = "Exact Match"
CODEBLEU = "CodeBLEU"
CELL_PRECISION = "Cell Precision"
CELL_RECALL = "Cell Recall"
CELL_F1 = "Cell F1"
ERROR_CATEGORY = "Error Category"
ERROR_FAMILY = "Error Family"
PUTS = "Puts"
HARNESS_REASON = "Harness Error"  # why the harness failed (a harness_error episode only; a string)
BUILD_SCORES = (EXECUTION_SUCCESS, EXACT_MATCH, CODEBLEU, CELL_PRECISION, CELL_RECALL, CELL_F1)
# feedback (repair) episodes and the describe dialogue: the first and the last build
ES_AT_1 = "ES@1"
ES_AT_N = "ES@N"
ATTEMPTS = "Attempts"
MAX_ATTEMPTS = "Max Attempts"
ATTEMPT_CATEGORIES = "Attempt Categories"
CATEGORY_SEPARATOR = ","  # in Attempt Categories
# the describe dialogue (sartco.games.describe.dialogue)
CELL_F1_AT_1 = "Cell F1@1"
CELL_F1_AT_N = "Cell F1@N"
FIRST_SUCCESS_ROUND = "First Success Round"
QUESTIONS_ASKED = "Questions Asked"
CORRECTIONS_SENT = "Corrections Sent"
DESCRIBER_WORDS = "Describer Words"
DIALOGUE_SCORES = (ES_AT_1, ES_AT_N, CELL_F1_AT_1, CELL_F1_AT_N, FIRST_SUCCESS_ROUND, QUESTIONS_ASKED,
                   CORRECTIONS_SENT, DESCRIBER_WORDS)
ROUND_PREFIX = "ES Round "
# the describer's instruction (sartco.games.describe.dialogue.log_instruction)
DESCRIBER_ANSWERED = "Describer Answered"
INSTRUCTION_WORDS = "Instruction Words"
INSTRUCTION_CHARACTERS = "Instruction Characters"
OBJECT_NAMED = "Object Named"
# the paper protocol (sartco.games.instruct.paper): shares of the dialogue's turns, 0..1
PAPER_SCORES = {"em": "Paper EM", "cb": "Paper CB", "es": "Paper ES"}
LEAK_FREE_ES = "Paper ES Leak-free"  # Paper ES with the answer run alone (no gold function in front)
# function probes (sartco.clem.core.probes): optimal_function and repetition episodes only
FUNCTION_GENERALISATION = "Function Generalisation"  # share of the probes built exactly, 0..1
PROBE_CATEGORIES = "Probe Categories"  # each probe's category in order, joined by CATEGORY_SEPARATOR
PROBE_FUNCTION = "Probe Function"      # whose function was probed: "model", "given" or "none"


def round_score(k: int) -> str:
    """The per-round ES score of a describe dialogue: "ES Round <k>"."""
    return f"{ROUND_PREFIX}{k}"


# ---------------------------------------------------------------------------- interactions.json keys
BUILD_KEY = "sartco_build"            # one build's record (sartco.clem.core.building.BuildRecord.to_json)
ATTEMPTS_KEY = "sartco_attempts"      # every build of an episode, in order
INSTRUCTION_KEY = "sartco_instruction"  # the describer's instruction: {"text", "error", "combo_name"}
DIALOGUE_KEY = "sartco_dialogue"      # the describe dialogue's log
PAPER_KEY = "sartco_paper"            # the paper protocol's reading: {"em", "cb", "es", "turns": [...]}
PROBES_KEY = "sartco_probes"          # the function probes (sartco.clem.core.probes.run_probes)
MARKDOWN_KEY = "markdown"             # clemcore renders the transcript's messages as Markdown


# ---------------------------------------------------------------------------- instance records
# An instance file: {"experiments": [Experiment, ...]}, each experiment's "game_instances" a list
# of episodes. The fields below are what the generators write; the games' benchmarks check an
# episode's fields against its type before `clem run` plays (sartco.clem.core.instance_checks.json_fields).

class PlayedEpisode(TypedDict):
    """What the game masters and BuildScorer read from every episode that ends in a build."""
    game_id: int           # clemcore's
    task: str              # sartco.dataset.TASKS
    rows: int
    cols: int
    target: dict[str, Any]  # sartco.world.Board.to_json
    given_code: str        # the code the program starts with (repetition: the object function)
    gold_code: str         # the gold answer in the task's style (exact match, CodeBLEU)
    # optional, written by no generator: answers `mock` gives verbatim, one per turn, instead of the
    # gold (scripted episodes of the tests and of hand-made instance files; sartco.clem.players.answers)
    script: NotRequired[list[str]]


class BuildEpisode(PlayedEpisode):
    """An episode of one board record of a dataset (sartco.clem.core.instance_files.board_fields)."""
    board_id: str
    board_type: str        # sartco.dataset.BOARD_TYPES
    object_type: str       # sartco.dataset.OBJECT_TYPES
    combo_name: str


class InstructEpisode(BuildEpisode):
    """A cobot_instruct episode of our protocol: the builder's messages and what mock answers."""
    source: str            # sartco.dataset.SOURCES
    turns: list[str]       # the builder's messages: the prompt with the first step, then one per later step
    instructions: list[str]  # the instruction text of each turn (what the rule-based follower reads)
    gold_turns: list[str]  # the gold answer of each turn (the mock player's answers)
    examples: list[str]    # ids of the in-context examples


class DescribeEpisode(BuildEpisode):
    """A cobot_describe episode: the describer's prompt, the builder's prompt with a slot for the
    instruction (sartco.games.describe.dialogue.INSTRUCTION_SLOT), what the mock describer writes."""
    example_ids: list[str]  # ids of the builder prompt's in-context examples
    describer_prompt: str
    builder_prompt: str
    template_instruction: str
    record: dict[str, Any]  # the board record (what `sartco import-instructions` reads back)


class PaperProtocolEpisode(PlayedEpisode):
    """A cobot_instruct_paper episode: sartco.paper.episodes.PaperEpisode.to_json() plus the board
    fields our own build reads (sartco.games.instruct.paper.instance_fields)."""
    id: str
    file: str              # the published file (stem) of the sample
    sample: str
    variant: str
    cell: dict[str, Any]   # the Table 3 cell: board, object, task, source, instructions
    messages: list[str]    # the authors' user messages, one per turn
    gold: list[dict[str, Any]]  # the authors' gold code of each turn
    given_function: str
    examples_from: str
    mock_answers: list[str]  # the gold in the authors' label format (what mock answers)
    protocol: str          # sartco.paper.PROTOCOL
    board_id: str
    board_type: str
    object_type: str


class Experiment(TypedDict):
    """What every experiment of the games records besides clemcore's name and game_instances."""
    board_type: str
    object_type: str
    task: str
    source: str
    split: str             # sartco.dataset.SPLITS


class _Feedback(TypedDict, total=False):
    attempts: int          # attempts per episode, the first included (sartco.clem.core.feedback)
    feedback_of: str       # the experiment it repeats with feedback


class InstructExperiment(Experiment, _Feedback):
    """cobot_instruct's experiments (instancegenerator.py)."""
    ablation: dict[str, Any] | None  # {"kind": "examples" | "without", "value"}; None in the Table 3 cells
    dataset: dict[str, Any]  # the dataset's version, source, seed, path, generator seed, examples


# cobot_describe's modes (experiment field `mode`; sartco.games.describe.dialogue plays them), in report order
DIALOGUE_MODES = ("oneshot", "clarify", "correct", "clarify_correct")


class _Dialogue(TypedDict, total=False):
    mode: str              # DIALOGUE_MODES; absent: oneshot
    questions: int
    corrections: int


class DescribeExperiment(Experiment, _Dialogue):
    """cobot_describe's experiments. Unlike cobot_instruct's, `dataset` is the dataset's version
    alone, beside its seed and the in-context examples' count and seed."""
    dataset: str
    dataset_seed: int
    examples: int
    example_seed: int


class PaperExperiment(Experiment):
    """cobot_instruct_paper's experiments (sartco.games.instruct.paper.experiment_fields)."""
    protocol: str
    instructions: str
    variant: str
    file: str
    ablation: None
    examples_from: str
    generation: dict[str, Any]  # the paper's generation settings (sartco.paper.table3.generation)
