"""Prompts with the paper's structure, rendered from resources/templates/prompts/.

builder_prompt(record, task, examples, sections=SECTIONS, source="template", step=0, instruction=None) -> str
    The builder's (programmer's) prompt: system, environment, context, task, in-context samples,
    other details, in this order (each section removable for the ablations; 0..10 examples),
    then the item's instruction. Tasks (= code styles):
      first_order        simple boards, one instruction step -> one put (label "Output:")
      sequence_function  simple boards -> a function made of puts + usage ("Function:", "Usage:")
      optimal_function   simple boards -> the optimal function + usage ("Function:", "Usage:")
      repetition         regular boards, the object function given in the context -> code that
                         repeats it ("Output:")
    `instruction` replaces the record's own instruction (e.g. one written by a describer).
gold_code(record, task) -> str
    The gold answer's code in the task's style (first_order: the puts; function tasks: function
    and usage; repetition: the repeating code), one line after another.
builder_turn(record, step, source="template") -> str
    The message of a later step of a first_order episode: "Instruction: <step text>".
describer_prompt(record) -> str
    The describer's prompt: environment, the board as text grid (sartco.world.render.grid_text),
    the object's name and the grid explanation; answer under "Instruction:".
"""
from __future__ import annotations

from typing import Iterable

from sartco.dataset import INSTRUCTION_STYLE, SIMPLE, TASKS
from sartco.world import COLORS, MAX_DEPTH, SHAPES
from sartco.world.render import grid_explanation, grid_text

from .examples import MAX_EXAMPLES
from .templates import render

SECTIONS = ("system", "environment", "context", "task", "examples", "details")
LABELS = {"first_order": ("Output",), "sequence_function": ("Function", "Usage"),
          "optimal_function": ("Function", "Usage"), "repetition": ("Output",)}


def _check_task(record: dict, task: str) -> None:
    if task not in TASKS:
        raise ValueError(f"unknown task {task!r}; expected one of {', '.join(TASKS)}")
    regular = record["board_type"] != SIMPLE.board
    if regular != (task == "repetition"):
        raise ValueError(f"task {task!r} does not fit a {record['board_type']} board ({record['id']})")


def instruction_text(record: dict, task: str, source: str = "template", step: int | None = None):
    """The instruction of a record for a task: a string (a list for first_order without step)."""
    by_source = record["instructions"].get(source)
    if by_source is None:
        raise KeyError(f"{record['id']} has no instructions from source {source!r}")
    style = INSTRUCTION_STYLE[task]
    if task == "sequence_function" and "single_turn_sc" in by_source:
        style = "single_turn_sc"
    if style not in by_source:
        raise KeyError(f"{record['id']} has no {style} instructions from source {source!r}")
    text = by_source[style]
    if task == "first_order" and step is not None:
        return text[step]
    return text


def answer(record: dict, task: str) -> list[list[tuple[str, str]]]:
    """The gold answer as (instruction, [(label, code), ...]) pairs: one pair per step for
    first_order, a single pair otherwise."""
    code = record["code"][task]  # a task is named after its code style
    if task == "first_order":
        return [(text, [("Output", put)]) for text, put in zip(instruction_text(record, task), code["steps"])]
    if task == "repetition":
        return [(instruction_text(record, task), [("Output", code["output"])])]
    return [(instruction_text(record, task), [("Function", code["function"]), ("Usage", code["usage"])])]


def _environment(rows: int, cols: int) -> str:
    return render("prompts/environment.j2", rows=rows, cols=cols, shapes=list(SHAPES),
                  colors=list(COLORS), max_depth=MAX_DEPTH)


def builder_prompt(record: dict, task: str, examples: Iterable[dict] = (), sections: Iterable[str] = SECTIONS,
                   source: str = "template", step: int = 0, instruction: str | None = None) -> str:
    """The builder's prompt for one record (see the module doc). `examples` are records (e.g. from
    select_examples); they always show template instructions and gold code of the task's style.
    `instruction`, when given, is shown instead of the record's instruction from `source`."""
    _check_task(record, task)
    sections = tuple(sections)
    unknown = set(sections) - set(SECTIONS)
    if unknown:
        raise ValueError(f"unknown prompt sections {sorted(unknown)}; expected some of {', '.join(SECTIONS)}")
    examples = list(examples)
    if len(examples) > MAX_EXAMPLES:
        raise ValueError(f"at most {MAX_EXAMPLES} in-context examples, got {len(examples)}")
    name = record["combo_name"]
    function = record["code"]["repetition"]["function"] if task == "repetition" else ""
    parts = []
    for section in SECTIONS:  # the paper's order, whatever order the caller gives
        if section not in sections:
            continue
        if section == "system":
            parts.append(render("prompts/system.j2"))
        elif section == "environment":
            parts.append(_environment(record["rows"], record["cols"]))
        elif section == "context":
            text = render("prompts/context.j2", task=task, name=name, function=function)
            if text.strip():
                parts.append(text)
        elif section == "task":
            parts.append(render("prompts/task.j2", task=task, name=name))
        elif section == "examples" and examples:
            pairs = [[{"instruction": i, "answer": a} for i, a in answer(ex, task)] for ex in examples]
            parts.append(render("prompts/examples.j2", examples=pairs))
        elif section == "details":
            parts.append(render("prompts/details.j2", labels=list(LABELS[task])))
    if instruction is None:
        instruction = instruction_text(record, task, source, step if task == "first_order" else None)
    return render("prompts/builder.j2", parts=parts, instruction=instruction).strip() + "\n"


def gold_code(record: dict, task: str) -> str:
    """The gold answer's code in the task's style (what exact match and CodeBLEU compare with)."""
    _check_task(record, task)
    return "\n".join(code for _, pairs in answer(record, task) for _, code in pairs)


def builder_turn(record: dict, step: int, source: str = "template") -> str:
    """A later step of a first_order episode."""
    _check_task(record, "first_order")
    return f"Instruction: {instruction_text(record, 'first_order', source, step)}\n"


def describer_prompt(record: dict) -> str:
    cells = record["target"]
    return render("prompts/describer.j2",
                  environment=_environment(record["rows"], record["cols"]), name=record["combo_name"],
                  grid=grid_text(cells, record["rows"], record["cols"]),
                  explanation=grid_explanation(cells),
                  regular=record["board_type"] != SIMPLE.board).strip() + "\n"
