"""One published sample -> our board record (sartco.dataset.BoardRecord).

A template file's sample becomes a record (`base_record`): the code in our styles (first_order,
sequence_function, optimal_function; regular boards: repetition), the fields checked against what
the code builds (the code's truth is kept), the template instructions. A variant file's sample
adds the instructions of its own dialogue keys to that record (`variant_texts`) under its source
(human, codellama, gpt4, claude), when it is the test file's sample plus those keys.
"""
from __future__ import annotations

import ast
import hashlib
import json
from pathlib import Path
from typing import Any

from sartco.dataset import DIALOGUE_KEYS, INSTRUCTION_STYLE, SIMPLE, BoardRecord, instructions_kind
from sartco.syntax import literal, parse
from sartco.world import DEFAULT_COLS, DEFAULT_ROWS, LETTERS

from .defects import Defect, without_stray_prefix
from .files import base_file, name_of

SIMPLE_KEYS = ("combo_name", "shapes", "colors", "x", "y", "orientations", "quadrant", "seed_template", "code", "dialogues")
REGULAR_KEYS = ("combo_name", "shapes", "colors", "quadrant", "seed_template", "occupied_rows", "occupied_cols", "code", "dialogues")
REGULAR_STYLE = INSTRUCTION_STYLE["repetition"]  # regular
# a record's instruction styles in the order the importer writes them (a variant's as its template's)
STYLE_ORDER = ("single_turn", "single_turn_sc", "multi_turn", "regular")


class SampleError(Exception):
    """One published sample is malformed: recorded as a defect, the sample left out."""


def variant_keys(source: str) -> list[str]:
    """The dialogue keys a variant file of this instruction source adds, in the record's style order."""
    kind = instructions_kind(source)
    return sorted((key for key, d in DIALOGUE_KEYS.items() if d.instructions == kind),
                  key=lambda key: STYLE_ORDER.index(DIALOGUE_KEYS[key].style))


def _need(sample: Any, keys: tuple[str, ...]) -> None:
    if not isinstance(sample, dict):
        raise SampleError(f"sample is a {type(sample).__name__}, not an object")
    missing = [k for k in keys if k not in sample]
    if missing:
        raise SampleError(f"field(s) {', '.join(missing)} missing")


def _get(obj: Any, *path: str, kind: type | tuple[type, ...] = str) -> Any:
    cur = obj
    for i, key in enumerate(path):
        if not isinstance(cur, dict) or key not in cur:
            raise SampleError(f"field '{'.'.join(path[: i + 1])}' missing")
        cur = cur[key]
    if not isinstance(cur, kind):
        raise SampleError(f"field '{'.'.join(path)}' is a {type(cur).__name__}")
    return cur


def _texts(dialogue: Any, path: str) -> list[str]:
    turns = _get({"d": dialogue}, "d", "instructions", kind=list) if isinstance(dialogue, dict) else None
    if turns is None:
        raise SampleError(f"field '{path}' is not a dialogue object")
    out = []
    for i, turn in enumerate(turns):
        if not isinstance(turn, dict) or not isinstance(turn.get("<Programmer>"), str):
            raise SampleError(f"field '{path}.instructions[{i}].<Programmer>' missing or not text")
        out.append(turn["<Programmer>"])
    return out


def _one_text(dialogue: Any, path: str) -> str:
    texts = _texts(dialogue, path)
    if len(texts) != 1:
        raise SampleError(f"field '{path}' has {len(texts)} instructions, expected 1")
    return texts[0]


def template_stem(template_path: str) -> str:
    """A sample's seed_template path as our records name it: .../regular_seed12.j2 -> regular_seed12."""
    return Path(template_path).name.removesuffix(".j2")


def _put_calls(code: str) -> list[ast.Call]:
    try:
        tree = parse(code)
    except SyntaxError as exc:
        raise SampleError(f"gold code does not parse: {exc.msg}") from None
    return [n for n in ast.walk(tree) if isinstance(n, ast.Call) and isinstance(n.func, ast.Name) and n.func.id == "put"]


def _literal_step(step: str) -> tuple[str, str, int, int]:
    """shape, color, x, y of one first-order put(board, 'shape', 'color', x, y)."""
    calls = _put_calls(step)
    try:
        (call,) = calls
        shape, color, x, y = (literal(a) for a in call.args[1:5])
    except (ValueError, TypeError):
        raise SampleError(f"first-order step is not one literal put: {step!r:.80}") from None
    return shape, color, x, y


def _function_shapes(function: str) -> list[str] | None:
    """The `shapes = [...]` list of an object function, or None when it has none."""
    try:
        tree = parse(function)
    except SyntaxError as exc:
        raise SampleError(f"object function does not parse: {exc.msg}") from None
    for node in ast.walk(tree):
        if isinstance(node, ast.Assign) and any(isinstance(t, ast.Name) and t.id == "shapes" for t in node.targets):
            try:
                value = literal(node.value)
            except ValueError:
                return None
            return list(value) if isinstance(value, (list, tuple)) else None
    return None


def base_record(file: str, sample_path: str, sample: Any, defects: list[Defect]) -> BoardRecord:
    """The record of one sample of a template file, its target still None (the importer runs the
    gold code); SampleError for a sample it cannot read, defects for fields the code contradicts."""
    name = name_of(file)
    rid = f"{file.removesuffix('.json')}/{sample_path}"
    simple = name.kind.board == SIMPLE.board

    def defect(kind: str, detail: str) -> None:
        defects.append(Defect(kind, file, sample_path, rid, detail))

    _need(sample, SIMPLE_KEYS if simple else REGULAR_KEYS)
    combo = _get(sample, "combo_name")
    shapes = _get(sample, "shapes", kind=list)
    colors = _get(sample, "colors", kind=list)
    dialogues = _get(sample, "dialogues", kind=dict)
    rows = sample.get("rows", DEFAULT_ROWS)
    cols = sample.get("cols", DEFAULT_COLS)
    if type(rows) is not int or type(cols) is not int:
        raise SampleError("fields 'rows' and 'cols' must be integers")
    quadrant = _get(sample, "quadrant")
    if simple:
        steps_text = _get(sample, "code", "multi_turn", "output", kind=list)
        if not all(isinstance(t, str) for t in steps_text):
            raise SampleError("field 'code.multi_turn.output' must be a list of code lines")
        first = {"steps": list(steps_text),
                 "total_code": _get(sample, "code", "multi_turn", "total_code")}
        styles = {"first_order": first}
        for ours, theirs in (("sequence_function", "single_turn_sc"), ("optimal_function", "single_turn")):
            styles[ours] = {k: _get(sample, "code", theirs, k) for k in ("function", "usage", "total_code")}
        steps = [_literal_step(s) for s in first["steps"]]
        code_shapes = [s[0] for s in steps]
        code_colors = [s[1] for s in steps]
        xs, ys = [s[2] for s in steps], [s[3] for s in steps]
        if (xs, ys) != (_get(sample, "x", kind=list), _get(sample, "y", kind=list)):
            defect("placement_mismatch", f"x, y fields {sample['x']}, {sample['y']} but the code puts at {xs}, {ys}; "
                                         f"kept the code's")
        placement = {"x": xs, "y": ys, "orientations": list(_get(sample, "orientations", kind=list))}
        instructions = {"template": template_simple(dialogues)}
        seed = template_stem(_get(sample, "seed_template", "single_turn"))
        arrangement = None
        occupied = (None, None)
    else:
        repetition = {k: _get(sample, "code", k) for k in ("function", "output", "total_code")}
        styles = {"repetition": repetition}
        code_shapes = _function_shapes(repetition["function"])
        code_colors = colors
        placement = None
        instructions = {"template": {"regular": _one_text(dialogues.get("regular"), "dialogues.regular")}}
        seed = None  # the published regular samples do not name the object's code seed
        arrangement = template_stem(_get(sample, "seed_template"))
        occupied = (_get(sample, "occupied_rows", kind=int), _get(sample, "occupied_cols", kind=int))
    if code_shapes is not None and code_shapes != shapes:
        defect("shapes_mismatch", f"shapes field {shapes} but the code builds {code_shapes}; kept the code's")
        shapes = code_shapes
    if code_colors != colors:
        defect("colors_mismatch", f"colors field {colors} but the code uses {code_colors}; kept the code's")
        colors = code_colors
    letters = "".join(LETTERS.get(s, "?") if isinstance(s, str) else "?" for s in shapes)
    if letters != combo:
        defect("combo_mismatch", f"combo_name {combo!r} but the shapes spell {letters!r}")

    return {
        "id": rid,
        "board_type": name.kind.board,
        "object_type": name.kind.object,
        "split": name.split,
        "combo_name": combo,
        "shapes": shapes,
        "colors": colors,
        "quadrant": quadrant,
        "rows": rows,
        "cols": cols,
        "seed": seed,
        "arrangement": arrangement,
        "placement": placement,
        "occupied_rows": occupied[0],
        "occupied_cols": occupied[1],
        "target": None,
        "code": styles,
        "instructions": instructions,
        "provenance": {"source": "published", "file": file, "sample": sample_path},
    }


def template_simple(dialogues: dict) -> dict:
    single = _one_text(dialogues.get("single_turn"), "dialogues.single_turn")
    out: dict[str, Any] = {"single_turn": single}
    if "single_turn_sc" in dialogues:
        sc = _one_text(dialogues["single_turn_sc"], "dialogues.single_turn_sc")
        if sc != single:
            out["single_turn_sc"] = sc
    out["multi_turn"] = _texts(dialogues.get("multi_turn"), "dialogues.multi_turn")
    return out


def variant_texts(file: str, sample_path: str, sample: Any, found: tuple[BoardRecord, str] | None,
                  defects: list[Defect]) -> dict[str, str] | None:
    """The instructions a variant file's sample adds to its test file's record (found: that record
    and the fingerprint of its sample), style -> text; None (and a defect) when the variant's sample
    is not its test sample plus its own dialogue keys; SampleError when it has no such key."""
    source = name_of(file).source
    base = base_file(file)
    _need(sample, ("dialogues",))
    dialogues = _get(sample, "dialogues", kind=dict)
    own = variant_keys(source)
    keys = [k for k in own if k in dialogues]
    if not keys:
        raise SampleError(f"no {' or '.join(own)} dialogue")
    if found is None:
        defects.append(Defect("variant_mismatch", file, sample_path, None,
                              f"no such sample imported from {base}; instructions left out"))
        return None
    record, base_print = found

    def defect(kind: str, detail: str) -> None:
        defects.append(Defect(kind, file, sample_path, record["id"], detail))

    if fingerprint(sample, tuple(keys)) != base_print:
        defect("variant_mismatch", f"board, code or template dialogues differ from {base}; instructions left out")
        return None
    texts = {}
    for key in keys:
        style = DIALOGUE_KEYS[key].style
        code_style = None if style == REGULAR_STYLE else style  # a regular dialogue's editor holds the whole code
        dialogue = dialogues[key]
        text = _one_text(dialogue, f"dialogues.{key}")
        editor = dialogue["instructions"][0].get("<Editor>")
        code = sample.get("code")
        expected = (code.get(code_style) if code_style else code) if isinstance(code, dict) else None
        if isinstance(editor, dict) and isinstance(expected, dict) and {k: editor.get(k) for k in expected} != expected:
            defect("editor_code_mismatch", f"the code of dialogues.{key} differs from the sample's code")
        if source != "human":
            cleaned = without_stray_prefix(text)
            if cleaned != text:
                defect("stray_prefix", f"removed {text[: len(text) - len(cleaned)]!r} before {cleaned[:30]!r}")
                text = cleaned
        texts[style] = text
    return texts


def fingerprint(sample: Any, extra_keys: tuple[str, ...]) -> str:
    """The sample without the variant's own dialogue keys, for comparing a variant with its test file."""
    if not isinstance(sample, dict):
        return ""
    rest = {k: v for k, v in sample.items() if k != "dialogues"}
    dialogues = sample.get("dialogues")
    if isinstance(dialogues, dict):
        rest["dialogues"] = {k: v for k, v in dialogues.items() if k not in extra_keys}
    return hashlib.sha256(json.dumps(rest, sort_keys=True).encode()).hexdigest()
