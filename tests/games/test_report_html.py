"""report.html of `sartco report` as a reader opens it: a small hand-written results folder (two
models, failed builds with their build records, a transcript per episode), reported, moved together
with the report, served on 127.0.0.1 and loaded in headless Chromium."""
import html
import http.server
import json
import re
import shutil
import threading
import urllib.parse
import urllib.request
from functools import partial
from pathlib import Path

from sartco.cli import main as sartco_main
from sartco.episode import BUILD_KEY, ERROR_CATEGORY
from sartco.report import charts
from sartco.report.files import MANIFEST

from report_helpers import write_results
from browser_helpers import browse, chromium

HOSTILE = "B<b>&x"   # a model name (a folder name) with markup: shown as text, never as markup


def add_builds(results: Path, model: str, failed: dict[int, str]) -> None:
    """The failed episodes of write_results get an error category and a build record whose built
    board differs from the target in cells (0, 0) and (0, 1); every episode gets a transcript."""
    for episode in sorted((results / model).rglob("instance_*")):
        (episode / "transcript.html").write_text("<html><body>transcript</body></html>", encoding="utf-8")
        k = int(episode.name.split("_")[1])
        if k not in failed:
            continue
        scores = json.loads((episode / "scores.json").read_text())
        scores["episode scores"][ERROR_CATEGORY] = failed[k]
        (episode / "scores.json").write_text(json.dumps(scores))
        record = {"cells": {"0:1": [["nut", "red"]], "3:3": [["screw", "blue"]]},
                  "target": {"0:0": [["nut", "red"]], "3:3": [["screw", "blue"]]}, "rows": 8, "cols": 8}
        (episode / "interactions.json").write_text(json.dumps({BUILD_KEY: record}))


def test_report_html_in_a_browser(tmp_path):
    browser = chromium()
    results, out = tmp_path / "run" / "results", tmp_path / "run" / "scores"
    write_results(results, "A", [1, 1, 0, 0])
    write_results(results, HOSTILE, [1, 0, 0])
    add_builds(results, "A", {2: "mismatch_location", 3: "mismatch_color"})
    add_builds(results, HOSTILE, {1: "mismatch_location", 2: "harness_error"})  # the harness failed: no score
    out.mkdir(parents=True)
    (out / "old_table.md").write_text("stale")      # written by an earlier report (its manifest says so)
    (out / "notes.txt").write_text("mine")          # not the report's: kept
    (out / MANIFEST).write_text("old_table.md\ntable3.md\n")
    # the helper's experiment holds fewer episodes than the instance file: incomplete (exit status 3)
    assert sartco_main(["report", "-r", str(results), "--out", str(out)]) == 3
    assert not (out / "old_table.md").exists() and (out / "notes.txt").read_text() == "mine"
    assert "report.html" in (out / MANIFEST).read_text().split()
    page = (out / "report.html").read_text(encoding="utf-8")
    assert HOSTILE not in page and "B&lt;b&gt;&amp;x" in page
    assert "not run" not in page  # both models played the one cell

    moved = tmp_path / "published"
    shutil.move(str(tmp_path / "run"), str(moved))  # the report travels with the results folder
    server = http.server.ThreadingHTTPServer(
        ("127.0.0.1", 0), partial(http.server.SimpleHTTPRequestHandler, directory=str(moved)))
    threading.Thread(target=server.serve_forever, daemon=True).start()
    try:
        url = f"http://127.0.0.1:{server.server_address[1]}/scores/report.html"
        dom = browse(browser, tmp_path / "profile", "--dump-dom", url).stdout
        links = re.findall(r'<a class="transcript" href="([^"]+)"', dom)
        for href in links:
            with urllib.request.urlopen(urllib.parse.urljoin(url, html.unescape(href))) as answer:
                assert answer.status == 200 and b"transcript" in answer.read()
    finally:
        server.shutdown()
    assert "SARTCo report" in dom and 'id="warning"' in dom and "incomplete (" in dom
    assert f"harness errors (the harness failed, not the model; left out of the scores): {html.escape(HOSTILE)}" in dom
    assert "<b>" not in dom  # the hostile name stayed text in the browser's DOM
    # one bar per (model, experiment), a segment per category counted:
    # A: success, location, color; B: success, location, harness
    assert dom.count('<g class="bar">') == 2 and dom.count('class="segment"') == 3 + 3
    # the heat map: 8 x 8 squares; (0, 0) and (0, 1) differ in the 3 failed builds (not the harness error), (3, 3) never
    heat = [int(n) for n in re.findall(r'class="heat" data-count="(\d+)"', dom)]
    assert len(heat) == 64 and heat[0] == heat[1] == 3 and sum(heat) == 6
    # one transcript per (model, experiment, category): A success, location, color; B success, location, harness
    assert len(links) == 6


def test_line_plot_keeps_identical_series_apart_and_full_names():
    names = [(f"gpt-4o-2024-08-06--Meta-Llama-3.1-405B-Instruct-Turbo-{i}", "clarify_correct") for i in range(24)]
    svg = charts.line_plot({key: [50.0, 75.0, 100.0] for key in names})  # identical series
    assert svg.count('<g class="series"') == 24
    for model, _ in names:
        assert f">{model} — clarify_correct</text>" in svg  # the legend keeps the full name
    assert len({charts.style(i) for i in range(24)}) == 24
    assert all(len(set(charts.style(i)) & set(charts.style(i + 1))) == 0 for i in range(23))  # neighbours differ
    height = int(re.search(r'height="(\d+)"', svg).group(1))
    legend_y = [float(y) for y in re.findall(r'<text class="legend" x="[\d.]+" y="([\d.]+)"', svg)]
    assert max(legend_y) < height and len(set(legend_y)) == 24  # every entry inside the picture, one line each
