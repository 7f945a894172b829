"""One small experiment through the clem command line, as a user runs it from the repository
root: clem run (mock) -> clem score -> clem transcribe -> sartco report."""
import csv
import json
import subprocess
import sys
from pathlib import Path

import pytest

REPO = Path(__file__).resolve().parents[2]
EXPERIMENT = "rb_so_repetition_template_examples_0"  # 10 val episodes, the smallest kind


def sh(*args, cwd=REPO):
    done = subprocess.run(args, cwd=cwd, capture_output=True, text=True, timeout=600)
    assert done.returncode == 0, f"{' '.join(args)} failed:\n{done.stdout[-2000:]}\n{done.stderr[-2000:]}"
    return done


@pytest.mark.slow
@pytest.mark.parametrize("model", ["mock", "rulebased"])
def test_run_score_transcribe_report(tmp_path, model):
    results = tmp_path / "results"
    bin_dir = Path(sys.executable).parent
    sh(str(bin_dir / "clem"), "run", "-g", "cobot_instruct", "-m", model, "-e", EXPERIMENT, "-r", str(results))
    sh(str(bin_dir / "clem"), "score", "-g", "cobot_instruct", "-r", str(results))
    sh(str(bin_dir / "clem"), "transcribe", "-g", "cobot_instruct", "-r", str(results))
    sh(str(bin_dir / "sartco"), "report", "-r", str(results), "--out", str(tmp_path / "scores"))

    scores = sorted(results.rglob("scores.json"))
    assert len(scores) == 10
    for path in scores:
        episode = json.loads(path.read_text())["episode scores"]
        assert episode["Main Score"] == 100.0 and episode["Aborted"] == 0, path
        if model == "mock":
            assert episode["Exact Match"] == 1 and episode["CodeBLEU"] == 1.0
        assert (path.parent / "boards.svg").is_file() and (path.parent / "boards_1.svg").is_file()
        assert '<img src="boards_1.svg"' in (path.parent / "transcript.html").read_text()  # relative: travels
    rows = list(csv.DictReader((tmp_path / "scores" / "ablations.csv").open()))
    assert [(r["model"], r["ablation"], r["value"], int(r["episodes"]), float(r["es"])) for r in rows] == \
        [(model, "examples", "0", 10, 100.0)]
    errors = list(csv.DictReader((tmp_path / "scores" / "errors.csv").open()))
    assert errors[0]["success"] == "10"
