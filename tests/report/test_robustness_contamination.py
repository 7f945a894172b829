"""robustness.md and contamination.md of `sartco report` on results folders written by hand, their
figures computed by hand."""
from __future__ import annotations

import csv
import json
from pathlib import Path

from sartco.cli import main
from sartco.episode import CELL_F1, CODEBLEU, EXACT_MATCH, EXECUTION_SUCCESS


def episode(root: Path, model: str, game: str, experiment: str, fields: dict, k: int, board: str, es: int) -> None:
    exp_dir = root / model / game / experiment
    exp_dir.mkdir(parents=True, exist_ok=True)
    (exp_dir / "experiment.json").write_text(json.dumps({
        "name": experiment, "game_name": game, "board_type": "simple", "object_type": "simple",
        "task": "optimal_function", "split": "test", "ablation": None, **fields}))
    ep = exp_dir / f"instance_{k:05d}"
    ep.mkdir()
    (ep / "instance.json").write_text(json.dumps({"game_id": k, "board_id": board}))
    (ep / "scores.json").write_text(json.dumps({"episode scores": {
        EXECUTION_SUCCESS: es, EXACT_MATCH: es, CODEBLEU: 0.5, CELL_F1: es, "Aborted": 0}}))


def play(root: Path, model: str, game: str, source: str, solved: dict[str, int], **fields) -> None:
    name = f"sb_so_optimal_function_{source}" + (f"_{fields['boards']}" if fields else "")
    for k, (board, es) in enumerate(solved.items()):
        episode(root, model, game, name, {"source": source, **fields}, k, board, es)


def rows(path: Path) -> list[dict]:
    with path.open(encoding="utf-8") as f:
        return list(csv.DictReader(f))


def test_robustness_table_by_hand(tmp_path):
    results, out = tmp_path / "results", tmp_path / "scores"
    # boards b1..b4; b1 solved under all three sources, b2 under the template only, b3 under none,
    # b4 played under one source only (left out); the template cell is in the fresh game
    play(results, "m", "cobot_instruct_fresh", "template", {"b1": 1, "b2": 1, "b3": 0}, boards="published", fresh_seed=7)
    play(results, "m", "cobot_instruct_published", "human", {"b1": 1, "b2": 0, "b3": 0, "b4": 1})
    play(results, "m", "cobot_instruct_published", "gpt4", {"b1": 1, "b2": 0, "b3": 0})
    assert main(["report", "-r", str(results), "--out", str(out)]) == 0
    table = rows(out / "robustness.csv")
    assert [(r["board_type"], r["task"]) for r in table] == [("simple", "optimal_function"), ("all", "all")]
    for r in table:
        assert (r["boards"], r["sources"]) == ("3", "template human gpt4")
        assert (float(r["all"]), float(r["some"]), float(r["none"])) == (33.33, 33.33, 33.33)
        assert (float(r["es_template"]), float(r["es_human"]), float(r["es_gpt4"]), r["es_claude"]) == (
            66.67, 33.33, 33.33, "")
        assert float(r["spread"]) == 33.33  # 2/3 - 1/3
        assert float(r["all_lo"]) <= 33.33 <= float(r["all_hi"])
    md = (out / "robustness.md").read_text()
    assert "| m | simple | simple | optimal_function | 3 | template human gpt4 |" in md
    assert "Robustness to the instruction source" in (out / "report.html").read_text()


def test_contamination_gap_by_hand(tmp_path):
    results, out = tmp_path / "results", tmp_path / "scores"
    play(results, "m", "cobot_instruct_fresh", "template", {f"p{i}": int(i < 4) for i in range(5)},
         boards="published", fresh_seed=7)
    play(results, "m", "cobot_instruct_fresh", "template", {f"f{i}": int(i < 1) for i in range(5)},
         boards="fresh", fresh_seed=7)
    assert main(["report", "-r", str(results), "--out", str(out)]) == 0
    cell, pooled = rows(out / "contamination.csv")
    assert (cell["task"], pooled["task"]) == ("optimal_function", "all")
    for r in (cell, pooled):
        assert (r["published_episodes"], r["fresh_episodes"]) == ("5", "5")
        assert (float(r["es_published"]), float(r["es_fresh"]), float(r["gap"])) == (80.0, 20.0, 60.0)
        assert float(r["gap_lo"]) <= 60.0 <= float(r["gap_hi"]) and float(r["gap_hi"]) <= 100.0
    # the two board sets are one row of contamination.md, never merged in table3
    assert "optimal" not in (out / "table3.md").read_text()
    assert "Contamination: published vs fresh boards" in (out / "report.html").read_text()
