"""The fields of a game episode that come from one board record and a task, the same in every
game that ends in a build (the game's instance generator adds its prompts and turns:
sartco.games.instruct.episodes, sartco.games.describe.instancegenerator):

    board_fields(record, task) -> {board_id, board_type, object_type, combo_name, task, rows, cols,
                                   target, given_code, gold_code}

given_code: the code the program starts with (repetition: the given object function);
gold_code: the gold answer in the task's style (exact match and CodeBLEU compare with it).
"""
from __future__ import annotations

from sartco.episode import BuildEpisode
from sartco.instances.prompts import gold_code


def board_fields(record: dict, task: str) -> BuildEpisode:
    """(without clemcore's game_id, which GameInstanceGenerator.add_game_instance sets)"""
    return {
        "board_id": record["id"], "board_type": record["board_type"], "object_type": record["object_type"],
        "combo_name": record["combo_name"], "task": task, "rows": record["rows"], "cols": record["cols"],
        "target": record["target"],
        "given_code": record["code"]["repetition"]["function"] if task == "repetition" else "",
        "gold_code": gold_code(record, task),
    }

