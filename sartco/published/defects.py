"""Defects of the published data: reported (one line each on stdout and a list in manifest.json),
never fatal. The rules, so that a reader can check them:

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
naming the file and the field (sartco.published.files).
"""
from __future__ import annotations

import re
from collections import Counter
from dataclasses import dataclass

from sartco.dataset import BoardRecord
from sartco.instances.storage import shared_boards
from sartco.program import Execution

from .files import variant_file

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


def is_junk(text: str) -> bool:
    """Fewer than 3 words of two or more letters, or none of the task's vocabulary."""
    words = [w.lower() for w in WORD_RE.findall(text)]
    if len(words) < 3:
        return True
    if re.search(r"\d", text):
        return False
    return not any(w in VOCABULARY or re.fullmatch(r"\d*(st|nd|rd|th)", w) for w in words)


def without_stray_prefix(text: str) -> str:
    return PREFIX_RE.sub("", text, count=1)


def judge_gold(file: str, record: BoardRecord, runs: dict[str, Execution], gold: dict | None,
               defects: list[Defect], checked: Counter) -> dict | None:
    """The board every gold program of a record builds, the oracle's (gold: sample id -> cells) when
    there is one; None (and a gold_error / gold_mismatch defect) when one fails or builds another
    board. checked counts the programs looked at ("run") and those that built their oracle board
    ("built_gold")."""
    sample, rid = record["provenance"]["sample"], record["id"]
    gold_cells = gold.get(sample) if gold is not None else None
    if gold is not None and gold_cells is None:
        defects.append(Defect("no_gold_board", file, sample, rid, "no board for this sample in gold_boards"))
    target = None
    for style, ex in runs.items():
        checked["run"] += 1
        if not ex.ok:
            detail = f"{style} gold code fails: {ex.error}: {ex.message}; sample left out"
            defects.append(Defect("gold_error", file, sample, rid, detail))
            return None
        if gold_cells is not None:
            if ex.cells != gold_cells:
                detail = f"{style} gold code builds another board than gold_boards; sample left out"
                defects.append(Defect("gold_mismatch", file, sample, rid, detail))
                return None
            checked["built_gold"] += 1
        if target is None:
            target = ex.cells
        elif ex.cells != target:
            detail = f"{style} gold code builds another board than the first style's; sample left out"
            defects.append(Defect("gold_mismatch", file, sample, rid, detail))
            return None
    return target


def instruction_defects(files: dict[str, list[BoardRecord]]) -> list[Defect]:
    """junk_instruction, truncated_instruction and unterminated_instruction of every text of every
    record, in file, record, source and style order."""
    out = []
    for records in files.values():
        for record in records:
            prov = record["provenance"]
            for source, styles in record["instructions"].items():
                file = prov["file"] if source == "template" else variant_file(prov["file"], source)
                for style, texts in styles.items():
                    for i, text in enumerate(texts if isinstance(texts, list) else [texts]):
                        where = f"{source}.{style}" + (f"[{i}]" if isinstance(texts, list) else "")
                        if is_junk(text):
                            out.append(Defect("junk_instruction", file, prov["sample"], record["id"],
                                              f"{where} {text!r:.60}"))
                        elif source != "template" and not TERMINAL_RE.search(text.rstrip()):
                            kind = "unterminated_instruction" if source == "human" else "truncated_instruction"
                            out.append(Defect(kind, file, prov["sample"], record["id"],
                                              f"{where} ends {text.rstrip()[-40:]!r}"))
    return out


def overlap_defects(files: dict[str, list[BoardRecord]]) -> list[Defect]:
    """split_overlap (one board in two files) and duplicate_board (twice in one file); files in order."""
    out = []
    for places in shared_boards(files):
        names = list(dict.fromkeys(name for name, _ in places))
        ids = ", ".join(rid for _, rid in places)
        first, first_id = places[0]
        if len(names) > 1:
            out.append(Defect("split_overlap", first, None, first_id, f"one board in {' and '.join(names)}: {ids}"))
        else:
            out.append(Defect("duplicate_board", first, None, first_id, f"one board {len(places)} times: {ids}"))
    return out
