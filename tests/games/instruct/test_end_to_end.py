"""Small runs through the clem command line, as a user runs them from the repository root:
clem run -> clem score -> clem transcribe -> clem eval -> sartco report. The smoke file's Table 3
cells play as `cobot_instruct`, an ablation as `cobot_instruct_ablations`: clem eval keeps them apart."""
import csv
import json
import sys
from pathlib import Path

import pytest

from play_helpers import sh
EXPERIMENT = "rb_so_repetition_template_examples_0"  # 10 val episodes, the smallest kind


@pytest.mark.slow
@pytest.mark.parametrize("model", ["mock", "rulebased"])
def test_run_score_transcribe_report(tmp_path, model):
    results = tmp_path / "results"
    bin_dir = Path(sys.executable).parent
    clem = str(bin_dir / "clem")
    sh(clem, "run", "-g", "cobot_instruct_ablations", "-m", model, "-e", EXPERIMENT, "-r", str(results))
    sh(clem, "run", "-g", "cobot_instruct", "-m", model, "-i", "instances_smoke", "-r", str(results))
    sh(clem, "score", "-r", str(results))
    sh(clem, "transcribe", "-r", str(results))
    sh(clem, "eval", "-r", str(results))
    sh(str(bin_dir / "sartco"), "report", "-r", str(results), "--out", str(tmp_path / "scores"))

    # clemcore's table: one column group per game, so the leaderboard game holds the test cells only
    [header, row] = list(csv.reader((results / "results.csv").open()))
    table = dict(zip(header, row))
    assert table["cobot_instruct, % Played"] == table["cobot_instruct_ablations, % Played"] == "100.0"
    assert not any(h.startswith("cobot_instruct_feedback") for h in header)
    assert len(list((results / model / "cobot_instruct").glob("*/instance_*/scores.json"))) == 10  # 2 per cell
    assert {p.parent.name for p in (results / model / "cobot_instruct").glob("*/experiment.json")} == {
        "sb_so_first_order_template", "sb_so_sequence_function_template", "sb_so_optimal_function_template",
        "rb_so_repetition_template", "rb_co_repetition_template"}
    table3 = list(csv.DictReader((tmp_path / "scores" / "table3.csv").open()))
    assert [(r["game"], r["split"], int(r["episodes"]), float(r["es"])) for r in table3] == \
        [("cobot_instruct", "test", 2, 100.0)] * 5

    scores = sorted((results / model / "cobot_instruct_ablations").rglob("scores.json"))
    assert len(scores) == 10
    for path in scores:
        episode = json.loads(path.read_text())["episode scores"]
        assert episode["Main Score"] == 100.0 and episode["Aborted"] == 0, path
        if model == "mock":
            assert episode["Exact Match"] == 1 and episode["CodeBLEU"] == 1.0
        assert (path.parent / "boards.svg").is_file() and (path.parent / "boards_1.svg").is_file()
        assert '<a href="boards_1.svg"' in (path.parent / "transcript.html").read_text()  # relative: travels
    rows = list(csv.DictReader((tmp_path / "scores" / "ablations.csv").open()))
    assert [(r["model"], r["ablation"], r["value"], int(r["episodes"]), float(r["es"])) for r in rows] == \
        [(model, "examples", "0", 10, 100.0)]
    errors = list(csv.DictReader((tmp_path / "scores" / "errors.csv").open()))
    assert [(r["game"], r["success"]) for r in errors if r["experiment"] == EXPERIMENT] == \
        [("cobot_instruct_ablations", "10")]
