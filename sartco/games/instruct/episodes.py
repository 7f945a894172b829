"""cobot_instruct's episodes: one game instance from a board record and a task (the board's fields
are every game's, sartco.clem.core.episodes.board_fields).

    instruct_episode(record, task, source, examples, sections) -> a cobot_instruct episode
"""
from __future__ import annotations

from sartco.clem.core.episodes import board_fields
from sartco.episode import InstructEpisode
from sartco.instances.prompts import SECTIONS, builder_prompt, builder_turn, gold_code, instruction_text


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
