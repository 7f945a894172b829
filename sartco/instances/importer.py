"""`sartco import SRC_DIR --out DIR`: the published SARTCo files -> our dataset format.

Reads the 16 files the SARTCo authors released (../shared/sartco-data/published): the val/test
(and rb_so train) files with their template instructions, plus the test variants with human-written
(`_hc`) and model-written (`_mg` CodeLlama-34B, `_gpt4_mg`, `_claude_mg`) instructions. A variant
is its test file plus one dialogue key, so it is merged into the test file's records as one more
instruction source. Output: docs/ARCHITECTURE.md "Datasets" (manifest.json + one file per
board type, object type and split).

Every gold program is run through `sartco.program.execute`; the board it builds is the record's
target, and it must equal the authors' own board in gold_boards/ (the conformance oracle).

Defects of the published data are reported, never fatal (one line each on stdout and a list in
manifest.json). Rules, so that a reader can check them:
- junk_instruction: fewer than 3 words of two or more letters, or no word of the task's
  vocabulary at all (a digit, an ordinal, row/column/cell/corner/diagonal/..., a shape or a colour).
  The text is kept verbatim (the paper evaluated it); consumers may drop the listed ids.
- truncated_instruction: a model-written text that does not end in . ! ? (optionally followed by
  a closing quote or bracket); these were cut off by the generating model's token budget. Kept.
- unterminated_instruction: the same test on a human-written text (a missing full stop, not a
  cut-off). Kept. Template texts are not checked (the multi-turn template has no full stops).
- stray_prefix: a model-written text starting with "s: ", "s " or ": " (left over from the
  generation prompt's "Instructions:"). Removed.
- shapes_mismatch / colors_mismatch / placement_mismatch / combo_mismatch: a field disagrees with
  what the gold code builds; the code's truth is kept.
- gold_error / gold_mismatch / no_gold_board: a gold program fails, builds another board than the
  oracle's, or has no oracle board. Failing or mismatching samples are left out of the dataset.
- split_overlap / duplicate_board: one board in two output files (two splits or two datasets), or
  twice in one file. Reported, not repaired (repairing would change the published test sets).
- variant_mismatch / editor_code_mismatch / malformed_sample: a variant sample that differs from
  its test sample beyond its dialogue key, a dialogue whose code differs from the sample's code,
  a sample with a missing or wrong-typed field. The sample (or its instruction) is left out.
A file that cannot be read at all (bad JSON, wrong top-level structure) is a UserError: one line
naming the file and the field.
"""
from __future__ import annotations

import argparse
import ast
import hashlib
import json
import re
import sys
from collections import Counter
from dataclasses import asdict, dataclass
from pathlib import Path
from typing import Any, Iterator

from sartco.errors import UserError
from sartco.program import execute_many
from sartco.world import DEFAULT_COLS, DEFAULT_ROWS, LETTERS, Cells

from .config import SPLITS
from .generate import FORMAT, dumps

FILE_RE = re.compile(
    r"^(?P<prefix>sb_so|rb_so|rb_cho)_(?P<split>train|val|test)(?:_(?P<variant>hc|mg|gpt4_mg|claude_mg))?\.json$"
)
PREFIXES = {"sb_so": ("simple", "simple"), "rb_so": ("regular", "simple"), "rb_cho": ("regular", "complex")}
PUBLISHED_OBJECT_TYPE = {"simple": "simple", "complex": "challenge"}  # ours -> theirs
SOURCES = {None: "template", "hc": "human", "mg": "codellama", "gpt4_mg": "gpt4", "claude_mg": "claude"}
SOURCE_ORDER = ("template", "human", "codellama", "gpt4", "claude")
# variant dialogue key -> (our style, the code style its <Editor> holds)
VARIANT_KEYS = {
    "human": {"single_turn_hai": ("single_turn", "single_turn"), "single_turn_hai_sc": ("single_turn_sc", "single_turn_sc"),
              "regular_hai": ("regular", None)},
    "model": {"single_turn_mg": ("single_turn", "single_turn"), "regular_mg": ("regular", None)},
}
SIMPLE_KEYS = ("combo_name", "shapes", "colors", "x", "y", "orientations", "quadrant", "seed_template", "code", "dialogues")
REGULAR_KEYS = ("combo_name", "shapes", "colors", "quadrant", "seed_template", "occupied_rows", "occupied_cols", "code", "dialogues")

WORD_RE = re.compile(r"[A-Za-z]{2,}")
VOCABULARY = frozenset(
    "row rows column columns col cols cell cells corner corners diagonal diagonally grid board edge top bottom left right "
    "first second third fourth fifth sixth seventh eighth last odd even "
    "washer washers nut nuts screw screws bridge bridges horizontal vertical object objects "
    "red green blue yellow place put stack fill position".split()
)
TERMINAL_RE = re.compile(r"[.!?][\"')\]]*$")
PREFIX_RE = re.compile(r"^(?:s:|s(?=\s+[A-Z])|:)\s*")


@dataclass(frozen=True, slots=True)
class Defect:
    kind: str
    file: str
    sample: str | None
    id: str | None
    detail: str

    def line(self) -> str:
        where = self.file + (f" {self.sample}" if self.sample else "")
        return f"{self.kind}: {where}: {self.detail}"


class SampleError(Exception):
    """One published sample is malformed: recorded as a defect, the sample left out."""


# ----------------------------------------------------------------------------- reading

def _load(path: Path) -> Any:
    try:
        text = path.read_text(encoding="utf-8")
    except (OSError, UnicodeDecodeError) as exc:
        raise UserError(f"{path.name}: cannot read: {exc}") from None
    try:
        return json.loads(text)
    except json.JSONDecodeError as exc:
        raise UserError(f"{path.name}: not valid JSON: {exc.msg} at line {exc.lineno} column {exc.colno}") from None


def _walk(data: Any, name: str, board_type: str, object_type: str) -> Iterator[tuple[str, Any]]:
    """Yield (sample path, sample) in file order; a wrong structure is a UserError."""
    theirs = PUBLISHED_OBJECT_TYPE[object_type]
    if not isinstance(data, dict):
        raise UserError(f"{name}: expected a JSON object at the top level, got {type(data).__name__}")
    if board_type not in data:
        raise UserError(f"{name}: field '{board_type}' missing (the board type of this file's prefix)")
    if set(data) != {board_type}:
        raise UserError(f"{name}: unexpected top-level field(s) {sorted(set(data) - {board_type})}; expected only '{board_type}'")
    by_object = data[board_type]
    if not isinstance(by_object, dict) or theirs not in by_object:
        raise UserError(f"{name}: field '{board_type}.{theirs}' missing (the object type of this file's prefix)")
    counts = by_object[theirs]
    if not isinstance(counts, dict):
        raise UserError(f"{name}: field '{board_type}.{theirs}' must be an object of counts")
    for count, combos in counts.items():
        if not isinstance(combos, dict):
            raise UserError(f"{name}: field '{board_type}.{theirs}.{count}' must be an object of combo names")
        for combo, samples in combos.items():
            if not isinstance(samples, list):
                raise UserError(f"{name}: field '{board_type}.{theirs}.{count}.{combo}' must be a list of samples")
            for index, sample in enumerate(samples):
                yield f"{board_type}/{theirs}/{count}/{combo}/{index}", sample


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


def _stem(template_path: str) -> str:
    return Path(template_path).name.removesuffix(".j2")


# ----------------------------------------------------------------------------- the code's truth

def _put_calls(code: str) -> list[ast.Call]:
    try:
        tree = ast.parse(code)
    except SyntaxError as exc:
        raise SampleError(f"gold code does not parse: {exc.msg}") from None
    return [n for n in ast.walk(tree) if isinstance(n, ast.Call) and isinstance(n.func, ast.Name) and n.func.id == "put"]


def _literal_step(step: str) -> tuple[str, str, int, int]:
    """shape, color, x, y of one first-order put(board, 'shape', 'color', x, y)."""
    calls = _put_calls(step)
    try:
        (call,) = calls
        shape, color, x, y = (ast.literal_eval(a) for a in call.args[1:5])
    except (ValueError, TypeError):
        raise SampleError(f"first-order step is not one literal put: {step!r:.80}") from None
    return shape, color, x, y


def _function_shapes(function: str) -> list[str] | None:
    """The `shapes = [...]` list of an object function, or None when it has none."""
    try:
        tree = ast.parse(function)
    except SyntaxError as exc:
        raise SampleError(f"object function does not parse: {exc.msg}") from None
    for node in ast.walk(tree):
        if isinstance(node, ast.Assign) and any(isinstance(t, ast.Name) and t.id == "shapes" for t in node.targets):
            try:
                value = ast.literal_eval(node.value)
            except ValueError:
                return None
            return list(value) if isinstance(value, (list, tuple)) else None
    return None


# ----------------------------------------------------------------------------- the importer

class Importer:
    def __init__(self, src: Path, gold_dir: Path | None):
        self.src = src
        self.gold_dir = gold_dir
        self.defects: list[Defect] = []
        self.records: dict[str, list[dict]] = {}         # output file -> records in order
        self.by_sample: dict[tuple[str, str], tuple[dict, str]] = {}  # (base file, sample) -> (record, fingerprint)
        self.read_counts: dict[str, int] = {}
        self.checked = Counter()                          # gold programs run / built their gold board

    def defect(self, kind: str, file: str, sample: str | None, detail: str, rid: str | None = None) -> None:
        self.defects.append(Defect(kind, file, sample, rid, detail))

    # -- files
    def discover(self) -> list[tuple[Path, re.Match]]:
        if not self.src.is_dir():
            raise UserError(f"{self.src}: not a directory")
        found, unknown = [], []
        for path in sorted(self.src.iterdir()):
            m = FILE_RE.match(path.name)
            if m:
                found.append((path, m))
            elif path.suffix == ".json":
                unknown.append(path.name)
        for name in unknown:
            print(f"sartco import: skipping {name}: not a published SARTCo file name", file=sys.stderr)
        if not found:
            raise UserError(f"{self.src}: no published SARTCo files (expected names like sb_so_test.json, rb_so_test_hc.json)")
        bases = {p.name for p, m in found if not m["variant"]}
        for path, m in found:
            base = f"{m['prefix']}_{m['split']}.json"
            if m["variant"] and base not in bases:
                raise UserError(f"{path.name}: its test file {base} is missing from {self.src}")
        # base files first, then variants in source order; each group in a fixed order
        def order(item):
            _, m = item
            return (m["variant"] is not None, list(SOURCES).index(m["variant"]), list(PREFIXES).index(m["prefix"]), SPLITS.index(m["split"]))
        return sorted(found, key=order)

    def gold_boards(self, base_name: str) -> dict[str, Cells] | None:
        if self.gold_dir is None:
            return None
        path = self.gold_dir / base_name
        if not path.is_file():
            return None
        data = _load(path)
        if not isinstance(data, dict):
            raise UserError(f"{path.name} (gold boards): expected an object of sample id -> cells")
        return data

    def run(self) -> None:
        for path, m in self.discover():
            board_type, object_type = PREFIXES[m["prefix"]]
            data = _load(path)
            samples = list(_walk(data, path.name, board_type, object_type))
            self.read_counts[path.name] = len(samples)
            if m["variant"] is None:
                out = f"{board_type}_{object_type}_{m['split']}.json"
                self.records.setdefault(out, [])
                gold = self.gold_boards(path.name)
                if gold is None:
                    self.defect("no_gold_board", path.name, None, "no gold_boards file; targets are not checked against the oracle")
                pending = []
                for sample_path, sample in samples:
                    try:
                        record = self.base_record(path.name, m, board_type, object_type, sample_path, sample)
                    except SampleError as exc:
                        self.defect("malformed_sample", path.name, sample_path, str(exc))
                        continue
                    pending.append((record, _fingerprint(sample, ())))
                for record, fingerprint in self.build_targets(path.name, pending, gold):
                    self.records[out].append(record)
                    self.by_sample[(path.name, record["provenance"]["sample"])] = (record, fingerprint)
            else:
                base = f"{m['prefix']}_{m['split']}.json"
                source = SOURCES[m["variant"]]
                for sample_path, sample in samples:
                    try:
                        self.merge_variant(path.name, base, source, board_type, sample_path, sample)
                    except SampleError as exc:
                        self.defect("malformed_sample", path.name, sample_path, str(exc))
        for records in self.records.values():
            for record in records:
                record["instructions"] = {s: record["instructions"][s] for s in SOURCE_ORDER if s in record["instructions"]}
        self.check_overlaps()

    # -- one sample of a base (template) file
    def base_record(self, file: str, m: re.Match, board_type: str, object_type: str, sample_path: str,
                    sample: Any) -> dict:
        """The record of one sample, its target still None (build_targets runs the gold code)."""
        rid = f"{file.removesuffix('.json')}/{sample_path}"
        simple = board_type == "simple"
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
                self.defect("placement_mismatch", file, sample_path,
                            f"x, y fields {sample['x']}, {sample['y']} but the code puts at {xs}, {ys}; kept the code's", rid)
            placement = {"x": xs, "y": ys, "orientations": list(_get(sample, "orientations", kind=list))}
            instructions = {"template": self.template_simple(dialogues)}
            seed = _stem(_get(sample, "seed_template", "single_turn"))
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
            arrangement = _stem(_get(sample, "seed_template"))
            occupied = (_get(sample, "occupied_rows", kind=int), _get(sample, "occupied_cols", kind=int))
        if code_shapes is not None and code_shapes != shapes:
            self.defect("shapes_mismatch", file, sample_path, f"shapes field {shapes} but the code builds {code_shapes}; kept the code's", rid)
            shapes = code_shapes
        if code_colors != colors:
            self.defect("colors_mismatch", file, sample_path, f"colors field {colors} but the code uses {code_colors}; kept the code's", rid)
            colors = code_colors
        letters = "".join(LETTERS.get(s, "?") if isinstance(s, str) else "?" for s in shapes)
        if letters != combo:
            self.defect("combo_mismatch", file, sample_path, f"combo_name {combo!r} but the shapes spell {letters!r}", rid)

        return {
            "id": rid,
            "board_type": board_type,
            "object_type": object_type,
            "split": m["split"],
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

    def build_targets(self, file: str, pending: list[tuple[dict, str]], gold: dict[str, Cells] | None):
        """Run every gold program of a file (in sartco.program's workers, one batch), keep the
        records whose programs all build the same board, the oracle's when there is one."""
        jobs: dict[tuple[int, int], list[tuple[int, str, str]]] = {}
        for i, (record, _) in enumerate(pending):
            for style, code in record["code"].items():
                jobs.setdefault((record["rows"], record["cols"]), []).append((i, style, code["total_code"]))
        results: dict[tuple[int, str], Any] = {}
        for (rows, cols), group in jobs.items():
            for (i, style, _), ex in zip(group, execute_many([code for _, _, code in group], rows, cols)):
                results[(i, style)] = ex
        for i, (record, fingerprint) in enumerate(pending):
            sample, rid = record["provenance"]["sample"], record["id"]
            gold_cells = gold.get(sample) if gold is not None else None
            if gold is not None and gold_cells is None:
                self.defect("no_gold_board", file, sample, "no board for this sample in gold_boards", rid)
            target, failed = None, False
            for style in record["code"]:
                ex = results[(i, style)]
                self.checked["run"] += 1
                if not ex.ok:
                    self.defect("gold_error", file, sample, f"{style} gold code fails: {ex.error}: {ex.message}; sample left out", rid)
                    failed = True
                    break
                if gold_cells is not None:
                    if ex.cells != gold_cells:
                        self.defect("gold_mismatch", file, sample, f"{style} gold code builds another board than gold_boards; sample left out", rid)
                        failed = True
                        break
                    self.checked["built_gold"] += 1
                if target is None:
                    target = ex.cells
                elif ex.cells != target:
                    self.defect("gold_mismatch", file, sample, f"{style} gold code builds another board than the first style's; sample left out", rid)
                    failed = True
                    break
            if not failed:
                record["target"] = target
                yield record, fingerprint

    @staticmethod
    def template_simple(dialogues: dict) -> dict:
        single = _one_text(dialogues.get("single_turn"), "dialogues.single_turn")
        out: dict[str, Any] = {"single_turn": single}
        if "single_turn_sc" in dialogues:
            sc = _one_text(dialogues["single_turn_sc"], "dialogues.single_turn_sc")
            if sc != single:
                out["single_turn_sc"] = sc
        out["multi_turn"] = _texts(dialogues.get("multi_turn"), "dialogues.multi_turn")
        return out

    # -- one sample of a variant file
    def merge_variant(self, file: str, base: str, source: str, board_type: str, sample_path: str, sample: Any) -> None:
        _need(sample, ("dialogues",))
        dialogues = _get(sample, "dialogues", kind=dict)
        family = "human" if source == "human" else "model"
        keys = [k for k in VARIANT_KEYS[family] if k in dialogues]
        if not keys:
            raise SampleError(f"no {' or '.join(VARIANT_KEYS[family])} dialogue")
        found = self.by_sample.get((base, sample_path))
        if found is None:
            self.defect("variant_mismatch", file, sample_path, f"no such sample imported from {base}; instructions left out")
            return
        record, fingerprint = found
        if _fingerprint(sample, tuple(keys)) != fingerprint:
            self.defect("variant_mismatch", file, sample_path, f"board, code or template dialogues differ from {base}; instructions left out", record["id"])
            return
        texts = {}
        for key in keys:
            style, code_style = VARIANT_KEYS[family][key]
            dialogue = dialogues[key]
            text = _one_text(dialogue, f"dialogues.{key}")
            editor = dialogue["instructions"][0].get("<Editor>")
            code = sample.get("code")
            expected = (code.get(code_style) if code_style else code) if isinstance(code, dict) else None
            if isinstance(editor, dict) and isinstance(expected, dict) and {k: editor.get(k) for k in expected} != expected:
                self.defect("editor_code_mismatch", file, sample_path, f"the code of dialogues.{key} differs from the sample's code", record["id"])
            if source != "human":
                cleaned = PREFIX_RE.sub("", text, count=1)
                if cleaned != text:
                    self.defect("stray_prefix", file, sample_path, f"removed {text[: len(text) - len(cleaned)]!r} before {cleaned[:30]!r}", record["id"])
                    text = cleaned
            texts[style] = text
        record["instructions"][source] = texts

    # -- checks over the finished records
    def check_instructions(self) -> None:
        for out, records in self.records.items():
            for record in records:
                prov = record["provenance"]
                for source, styles in record["instructions"].items():
                    file = prov["file"] if source == "template" else _variant_file(prov["file"], source)
                    for style, texts in styles.items():
                        for i, text in enumerate(texts if isinstance(texts, list) else [texts]):
                            where = f"{source}.{style}" + (f"[{i}]" if isinstance(texts, list) else "")
                            if is_junk(text):
                                self.defect("junk_instruction", file, prov["sample"], f"{where} {text!r:.60}", record["id"])
                            elif source != "template" and not TERMINAL_RE.search(text.rstrip()):
                                kind = "unterminated_instruction" if source == "human" else "truncated_instruction"
                                self.defect(kind, file, prov["sample"], f"{where} ends {text.rstrip()[-40:]!r}", record["id"])

    def check_overlaps(self) -> None:
        seen: dict[str, list[tuple[str, str]]] = {}
        for out in _ordered(self.records):
            for record in self.records[out]:
                key = json.dumps(record["target"], sort_keys=True)
                seen.setdefault(key, []).append((out, record["id"]))
        for places in seen.values():
            files = sorted({out for out, _ in places}, key=_ordered_key)
            ids = ", ".join(rid for _, rid in places)
            if len(files) > 1:
                self.defect("split_overlap", places[0][0], None, f"one board in {' and '.join(files)}: {ids}", places[0][1])
            elif len(places) > 1:
                self.defect("duplicate_board", places[0][0], None, f"one board {len(places)} times: {ids}", places[0][1])


def _fingerprint(sample: Any, extra_keys: tuple[str, ...]) -> str:
    """The sample without the variant's own dialogue keys, for comparing a variant with its test file."""
    if not isinstance(sample, dict):
        return ""
    rest = {k: v for k, v in sample.items() if k != "dialogues"}
    dialogues = sample.get("dialogues")
    if isinstance(dialogues, dict):
        rest["dialogues"] = {k: v for k, v in dialogues.items() if k not in extra_keys}
    return hashlib.sha256(json.dumps(rest, sort_keys=True).encode()).hexdigest()


def _variant_file(base: str, source: str) -> str:
    suffix = next(k for k, v in SOURCES.items() if v == source)
    return f"{base.removesuffix('.json')}_{suffix}.json"


def is_junk(text: str) -> bool:
    """Fewer than 3 words of two or more letters, or none of the task's vocabulary."""
    words = [w.lower() for w in WORD_RE.findall(text)]
    if len(words) < 3:
        return True
    if re.search(r"\d", text):
        return False
    return not any(w in VOCABULARY or re.fullmatch(r"\d*(st|nd|rd|th)", w) for w in words)


def _ordered_key(out: str) -> tuple[int, int, int]:
    board_type, object_type, split = out.removesuffix(".json").split("_")
    return (["simple", "regular"].index(board_type), ["simple", "complex"].index(object_type), SPLITS.index(split))


def _ordered(records: dict[str, list]) -> list[str]:
    return sorted(records, key=_ordered_key)


def import_published(src: Path, out: Path, gold_dir: Path | None) -> dict:
    """Convert the published files in src into a dataset in out; returns the manifest."""
    importer = Importer(src, gold_dir)
    importer.run()
    importer.check_instructions()
    files = {}
    try:
        out.mkdir(parents=True, exist_ok=True)
    except OSError as exc:
        raise UserError(f"--out {out}: cannot create the folder: {exc.strerror}") from None
    for name in _ordered(importer.records):
        (out / name).write_text(dumps(importer.records[name]), encoding="utf-8")
        files[name] = len(importer.records[name])
    inputs = {name: hashlib.sha256((src / name).read_bytes()).hexdigest() for name in sorted(importer.read_counts)}
    manifest = {
        "format": FORMAT,
        "version": "published",
        "source": "published",
        "seed": None,
        "config": {
            "inputs": inputs,
            "samples_read": dict(sorted(importer.read_counts.items())),
            "gold_boards_checked": importer.checked["built_gold"],
            "gold_programs_run": importer.checked["run"],
        },
        "files": files,
        "defects": [asdict(d) for d in importer.defects],
    }
    (out / "manifest.json").write_text(dumps(manifest), encoding="utf-8")
    return manifest


def summary(manifest: dict) -> str:
    config = manifest["config"]
    lines = ["read:"]
    lines += [f"  {name:28} {n:5} samples" for name, n in config["samples_read"].items()]
    lines.append("wrote:")
    lines += [f"  {name:28} {n:5} records" for name, n in manifest["files"].items()]
    lines.append(f"gold programs: {config['gold_programs_run']} run, {config['gold_boards_checked']} built their gold board")
    kinds = Counter(d["kind"] for d in manifest["defects"])
    lines.append(f"defects: {len(manifest['defects'])}" + ("" if kinds else " (none)"))
    lines += [f"  {kind:28} {n:5}" for kind, n in sorted(kinds.items())]
    return "\n".join(lines)


def configure(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("src", type=Path, metavar="SRC_DIR", help="folder with the published files (sb_so_test.json, ...)")
    parser.add_argument("--out", type=Path, required=True, metavar="DIR", help="dataset folder to write")
    parser.add_argument("--gold", type=Path, default=None, metavar="DIR",
                        help="the authors' gold boards (default: SRC_DIR/../gold_boards when it exists)")
    parser.add_argument("--quiet", action="store_true", help="print only the summary, not each defect")


def run(args: argparse.Namespace) -> int:
    gold = args.gold
    if gold is None:
        candidate = args.src / ".." / "gold_boards"
        gold = candidate if candidate.is_dir() else None
    elif not gold.is_dir():
        raise UserError(f"--gold {gold}: not a directory")
    manifest = import_published(args.src, args.out, gold)
    if not args.quiet:
        for d in manifest["defects"]:
            print(Defect(**d).line())
    print(summary(manifest))
    return 0
