"""The fields of a game episode that come from one board record and a task, the same in every
game that ends in a build (the game's instance generator adds its prompts and turns):

    board_fields(record, task) -> {board_id, board_type, object_type, combo_name, task, rows, cols,
                                   target, given_code, gold_code}
    instruct_episode(record, task, source, examples, sections) -> a cobot_instruct episode

given_code: the code the program starts with (repetition: the given object function);
gold_code: the gold answer in the task's style (exact match and CodeBLEU compare with it).
"""
from __future__ import annotations

from sartco.episode import BuildEpisode, InstructEpisode
from sartco.instances.prompts import SECTIONS, builder_prompt, builder_turn, gold_code, instruction_text


def board_fields(record: dict, task: str) -> BuildEpisode:
    """(without clemcore's game_id, which GameInstanceGenerator.add_game_instance sets)"""
    return {
        "board_id": record["id"], "board_type": record["board_type"], "object_type": record["object_type"],
        "combo_name": record["combo_name"], "task": task, "rows": record["rows"], "cols": record["cols"],
        "target": record["target"],
        "given_code": record["code"]["repetition"]["function"] if task == "repetition" else "",
        "gold_code": gold_code(record, task),
    }


def instruct_episode(record: dict, task: str, source: str, examples: list[dict], sections=SECTIONS) -> InstructEpisode:
    """One cobot_instruct game instance: the board's fields, what the builder is told (the prompt
    with `examples` and `sections`; multi-turn: one message per later step), and what `mock`
    answers per turn."""
    code = record["code"]
    if task == "first_order":
        steps = instruction_text(record, task, source)
        turns = [builder_prompt(record, task, examples, sections, source, step=0)]
        turns += [builder_turn(record, k, source) for k in range(1, len(steps))]
        instructions, gold_turns = list(steps), list(code["first_order"]["steps"])
    else:
        turns = [builder_prompt(record, task, examples, sections, source)]
        instructions = [instruction_text(record, task, source)]
        gold_turns = [gold_code(record, task)]
    return {**board_fields(record, task), "source": source, "turns": turns, "instructions": instructions,
            "gold_turns": gold_turns, "examples": [ex["id"] for ex in examples]}
