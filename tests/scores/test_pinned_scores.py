"""Scores that must not move with the installed versions of what computes them.

CodeBLEU (the `codebleu` package, parsed by `tree-sitter` with `tree-sitter-python`), exact match
and execution success (the sandbox, boards in `numpy`) of a fixed set of answers against published
gold programs (../shared/sartco-data/published, copied into pinned_scores.json when recorded):
each gold program against itself (known: CodeBLEU 1.0, EM 1, ES 1, cell F1 1), against the same board in
another of the paper's code styles, and against models' typical faults (a changed colour, a
dropped line, a syntax error, an empty answer). The expected numbers were recorded with the
versions of constraints.txt (`make install`). An install with other versions (`make upgrade-check`,
or `pip install` without `-c constraints.txt`) that changes any of these numbers fails here, and the
message names the installed and the recorded versions of the packages that decide a score.

Re-record after a deliberate upgrade (and update constraints.txt in the same commit):
    .venv/bin/python tests/scores/test_pinned_scores.py --record
"""
from __future__ import annotations

import json
import math
import sys
from importlib.metadata import PackageNotFoundError, version
from pathlib import Path

from sartco.clem.core.building import build
from sartco.program import execute
from sartco.scores.metrics import code_bleu_detail, exact_match

HERE = Path(__file__).resolve().parent
EXPECTED = HERE / "pinned_scores.json"
CONSTRAINTS = HERE.parents[1] / "constraints.txt"
PUBLISHED = HERE.parents[2] / "shared" / "sartco-data" / "published"
# the installed packages that compute a score (clemcore: the scorer and the episode records)
SCORE_PACKAGES = ("codebleu", "tree-sitter", "tree-sitter-python", "numpy", "clemcore")
CODEBLEU_PARTS = ("score", "ngram", "weighted_ngram", "syntax", "dataflow")
TOLERANCE = 1e-9   # far below the 3 decimals a table shows; above float noise of a reordered sum


def installed_versions() -> dict[str, str]:
    found = {}
    for name in SCORE_PACKAGES:
        try:
            found[name] = version(name)
        except PackageNotFoundError:
            found[name] = "not installed"
    return found


def scores(answer: str, gold: str) -> dict:
    """The game's scores of an answer (sartco.clem.core.building.build: the answer run on a fresh
    board against the gold program's board; CodeBLEU and EM against the gold code)."""
    detail = code_bleu_detail(answer, gold)
    record = build(answer, execute(gold).cells)
    return {"codebleu": {part: getattr(detail, part) for part in CODEBLEU_PARTS},
            "codebleu_reason": detail.reason, "exact_match": exact_match(answer, gold), "es": record.es,
            "category": record.category, "cell_f1": record.f1}


def differences(expected: dict, got: dict) -> list[str]:
    diffs = [f"{key} {got[key]!r:.160} (recorded {expected[key]!r})"
             for key in ("codebleu_reason", "exact_match", "es", "category") if got[key] != expected[key]]
    for part in CODEBLEU_PARTS:
        old, new = expected["codebleu"][part], got["codebleu"][part]
        if not math.isclose(old, new, rel_tol=0.0, abs_tol=TOLERANCE):
            diffs.append(f"CodeBLEU {part} {new!r} (recorded {old!r})")
    if not math.isclose(expected["cell_f1"], got["cell_f1"], rel_tol=0.0, abs_tol=TOLERANCE):
        diffs.append(f"cell F1 {got['cell_f1']!r} (recorded {expected['cell_f1']!r})")
    return diffs


def pinned() -> dict[str, str]:
    """name == version lines of constraints.txt (names lower-case, '_' as '-')."""
    pins = {}
    for line in CONSTRAINTS.read_text(encoding="utf-8").splitlines():
        line = line.split("#")[0].strip()
        if "==" in line:
            name, _, ver = line.partition("==")
            pins[name.strip().lower().replace("_", "-")] = ver.strip()
    return pins


# ----------------------------------------------------------------------------- the tests

def test_scores_of_the_fixed_answers_are_the_recorded_ones():
    record = json.loads(EXPECTED.read_text(encoding="utf-8"))
    moved = []
    for case in record["cases"]:
        diffs = differences(case["expected"], scores(case["answer"], case["gold"]))
        if diffs:
            moved.append(f"{case['name']}: " + "; ".join(diffs))
    now = installed_versions()
    assert not moved, (
        f"{len(moved)} of {len(record['cases'])} recorded scores changed with the installed versions "
        + ", ".join(f"{k} {v} (recorded with {record['versions'].get(k)})" for k, v in now.items())
        + ":\n  " + "\n  ".join(moved)
        + "\nPin the recorded versions (make install uses constraints.txt), or, if the change is meant, "
          "re-record: python tests/scores/test_pinned_scores.py --record")


def test_the_known_anchors_hold():
    """A gold program against itself: CodeBLEU 1.0, exact match, execution success, cell F1 1 (no recording needed)."""
    record = json.loads(EXPECTED.read_text(encoding="utf-8"))
    selfs = [c for c in record["cases"] if c["answer"] == c["gold"]]
    assert len(selfs) >= 3
    for case in selfs:
        got = scores(case["answer"], case["gold"])
        assert (got["codebleu"]["score"], got["exact_match"], got["es"], got["cell_f1"]) == (1.0, 1, 1, 1.0), case["name"]


def test_the_recording_was_made_with_the_pinned_versions():
    """constraints.txt and pinned_scores.json name the same versions: a pin moved without re-recording
    (or the reverse) fails here."""
    record = json.loads(EXPECTED.read_text(encoding="utf-8"))
    pins = pinned()
    assert {k: pins.get(k) for k in SCORE_PACKAGES} == record["versions"], (
        f"constraints.txt pins {', '.join(f'{k} {pins.get(k)}' for k in SCORE_PACKAGES)} but pinned_scores.json "
        f"was recorded with {record['versions']}: re-record (python tests/scores/test_pinned_scores.py --record) "
        "with the pinned install")


# ----------------------------------------------------------------------------- recording

def _published_cases() -> list[dict]:
    """The fixed answers: from each published test file, the first sample of its last object
    group at its largest count (the longest programs), in each code style the file has."""
    cases = []
    for name in ("sb_so_test.json", "rb_so_test.json", "rb_cho_test.json"):
        data = json.loads((PUBLISHED / name).read_text(encoding="utf-8"))
        group = data[list(data)[-1]]
        combos = group[list(group)[-1]]
        samples = combos[max(combos, key=int)]
        sample = samples[list(samples)[0]][0]
        stem, code = name.removesuffix(".json"), sample["code"]
        if "single_turn" in code:
            gold = code["single_turn"]["total_code"]
            others = {"sc_style": code["single_turn_sc"]["total_code"], "multi_turn": code["multi_turn"]["total_code"]}
        else:
            gold = code["total_code"]
            others = {"function_left_out": code["output"]}
        lines = gold.split("\n")
        faults = {
            "self": gold,
            "colour_changed": gold.replace("'red'", "'green'", 1) if "'red'" in gold else gold.replace("'blue'", "'green'", 1),
            "last_line_dropped": "\n".join(lines[:-1]),
            "syntax_error": gold.rstrip(")\n") + "(",
            "commented": "# the answer\n" + gold.replace("\n", "  # a note\n", 1),
        }
        for kind, answer in {**faults, **others}.items():
            cases.append({"name": f"{stem}/{kind}", "answer": answer, "gold": gold})
    cases.append({"name": "empty_answer", "answer": "", "gold": cases[0]["gold"]})
    return cases


def record() -> None:
    if not PUBLISHED.is_dir():
        sys.exit(f"{PUBLISHED}: no such folder (the published data, ../shared beside the repository)")
    cases = [{**case, "expected": scores(case["answer"], case["gold"])} for case in _published_cases()]
    data = {"versions": installed_versions(), "cases": cases}
    EXPECTED.write_text(json.dumps(data, indent=1, ensure_ascii=False) + "\n", encoding="utf-8")
    print(f"{EXPECTED}: {len(cases)} cases recorded with {data['versions']}")


if __name__ == "__main__":
    if sys.argv[1:] != ["--record"]:
        sys.exit(__doc__)
    record()
