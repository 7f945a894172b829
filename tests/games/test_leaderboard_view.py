"""What a leaderboard reader sees (issue 23, "Done when"): a small dialogue set played by `mock`,
`rulebased` and a scripted failing builder through clemcore's CLI as `make main` does it, except that
`clem transcribe` runs BEFORE `clem score` as well as after it (scripts/main.sh: run, score,
transcribe, eval per game and model, `sartco report`). The results folder and the report are then
moved elsewhere, served on 127.0.0.1, and one headless Chromium session loads every transcript (both
versions) and report.html in a frame and measures them: every picture loaded and its labels at least
MIN_LABEL px high as rendered at the transcript's width, each picture's full-size link resolving,
the score card holding the values of scores.json, grids and code in a monospace font and prose not,
report.html's charts with one bar per (model, experiment), one series per (model, mode), the heat
map's 8 x 8 squares, the dialogue table, and every transcript link of the report answering 200."""
from __future__ import annotations

import base64
import contextlib
import copy
import http.server
import json
import re
import shutil
import threading
from collections import Counter
from functools import partial
from pathlib import Path

import pytest

from play_helpers import clem, fence
from sartco.cli import main as sartco_main
from sartco.world.render import MIN_LABEL
from browser_helpers import browse, chromium
from episode_helpers import FULL, experiments_of, wrong_code
from test_score_card import assert_card_matches, read_scores

GAME = "cobot_describe_dialogue"
MODELS = ("mock", "rulebased")
BEFORE = "transcript_before_score.html"  # the transcript `clem transcribe` made before `clem score`

# A page at the served root: loads each page of PAGES in the frame, one after the other, and reports
# what it measured (base64 JSON, so nothing in it is escaped by the DOM dump).
PROBE = """<!doctype html><html><body>
<iframe id="f" style="width: 1000px; height: 2400px"></iframe><div id="lab"></div><pre id="out">pending</pre>
<script>
const PAGES = %s;
const open = (f, url) => new Promise(done => { f.onload = done; f.src = url; });
const status = async url => { try { const r = await fetch(url); return [r.status, await r.text()]; }
                              catch (e) { return [String(e), ""]; } };
function svgOf(img) {  // the picture's SVG (a base64 data: URL), drawn inline at the width the page shows it
  const bytes = Uint8Array.from(atob(img.src.split(",")[1]), c => c.charCodeAt(0));
  const svg = new DOMParser().parseFromString(new TextDecoder().decode(bytes), "image/svg+xml").documentElement;
  const lab = document.getElementById("lab");
  lab.replaceChildren(document.importNode(svg, true));
  const drawn = lab.firstChild, shown = img.getBoundingClientRect().width, box = drawn.viewBox.baseVal;
  drawn.setAttribute("width", shown); drawn.setAttribute("height", shown * box.height / box.width);
  const texts = [...drawn.querySelectorAll("text")];
  return {shown, labels: texts.length, texts: texts.map(t => t.textContent),
          rendered: Math.min(...texts.map(t => t.getBoundingClientRect().height)),
          font: shown / box.width * Math.min(...texts.map(t => parseFloat(t.getAttribute("font-size"))))};
}
async function transcript(d) {
  const pictures = [];
  for (const img of d.querySelectorAll(".sartco-picture img")) {
    const a = img.closest("a");
    pictures.push({loaded: img.complete && img.naturalWidth > 0, href: a.getAttribute("href"),
                   status: (await status(a.href))[0], ...svgOf(img)});
  }
  const fonts = sel => [...d.querySelectorAll(sel)].map(e => [getComputedStyle(e).fontFamily, e.textContent]);
  const card = d.querySelector(".sartco-card");
  return {pictures, literal: fonts(".sartco-text, .sartco-code"), prose: fonts(".sartco-prose"),
          card: card ? card.outerHTML : null, images: d.images.length};
}
async function report(d) {
  const links = [];
  for (const a of d.querySelectorAll("a.transcript")) {
    const [code, body] = await status(a.href);
    links.push([a.getAttribute("href"), code, body.includes('class="sartco-card"')]);
  }
  const count = sel => d.querySelectorAll(sel).length;
  const dialogue = [...d.querySelectorAll("table.dialogue tr")].map(tr => [...tr.cells].map(c => c.textContent));
  return {links, charts: count("svg.chart"), bars: count("svg g.bar"), segments: count("svg rect.segment"),
          series: count("svg g.series"), heat: count("svg rect.heat"), dialogue,
          bodyFont: getComputedStyle(d.body).fontFamily, title: d.title};
}
window.addEventListener("load", async () => {
  const f = document.getElementById("f"), out = {};
  for (const [url, kind] of PAGES) {
    await open(f, url);
    out[url] = kind === "report" ? await report(f.contentDocument) : await transcript(f.contentDocument);
  }
  document.getElementById("out").textContent = btoa(unescape(encodeURIComponent(JSON.stringify(out))));
});
</script></body></html>
"""


@contextlib.contextmanager
def serve(folder: Path):
    """`folder` over HTTP on 127.0.0.1 (a free port) while the block runs; yields its base URL."""
    server = http.server.ThreadingHTTPServer(
        ("127.0.0.1", 0), partial(http.server.SimpleHTTPRequestHandler, directory=str(folder)))
    threading.Thread(target=server.serve_forever, daemon=True).start()
    try:
        yield f"http://127.0.0.1:{server.server_address[1]}"
    finally:
        server.shutdown()


def instance_file(path: Path) -> None:
    """Two episodes of a `correct` experiment on simple boards, and one of a scripted builder that
    sends the same wrong code in every round (it loses: mismatch, all corrections used)."""
    source = next(e for e in experiments_of(FULL) if e.get("mode") == "correct" and e["board_type"] == "simple")
    played = {**source, "game_instances": copy.deepcopy(source["game_instances"][:2])}
    failing = copy.deepcopy(source["game_instances"][2])
    failing["builder_script"] = [fence(wrong_code(failing["target"]))] * 8
    scripted = {**source, "name": "scripted_failing_builder", "game_instances": [failing]}
    path.write_text(json.dumps({"experiments": [played, scripted]}), encoding="utf-8")


@pytest.fixture(scope="module")
def published(tmp_path_factory):
    """The set played, transcribed before and after scoring, evaluated, reported, and moved."""
    tmp = tmp_path_factory.mktemp("leaderboard")
    instance_file(tmp / "leaderboard.json")
    results, scores = tmp / "run" / "results", tmp / "run" / "scores"
    for model in MODELS:
        clem("run", "-g", GAME, "-m", model, "-i", str(tmp / "leaderboard"), "-r", str(results))
    clem("transcribe", "-r", str(results))  # before any scores.json: the pictures are made now
    assert not list(results.rglob("scores.json")) and not list(results.rglob("boards_*.svg"))
    for page in results.rglob("transcript.html"):
        shutil.copyfile(page, page.with_name(BEFORE))
    clem("score", "-r", str(results))
    clem("transcribe", "-r", str(results))
    for model in MODELS:  # as scripts/main.sh: one game and model at a time
        clem("eval", "-r", str(results), "-g", GAME, "-m", model)
    assert sartco_main(["report", "-r", str(results), "--out", str(scores)]) == 0
    moved = tmp / "elsewhere" / "published"
    shutil.move(tmp / "run", moved)  # nothing may point back to where it was made
    return moved


@pytest.fixture(scope="module")
def seen(published, tmp_path_factory):
    browser = chromium()
    pages = [[p.relative_to(published).as_posix(), "transcript"]
             for name in ("transcript.html", BEFORE) for p in sorted(published.rglob(name))]
    pages.append(["scores/report.html", "report"])
    (published / "probe.html").write_text(PROBE % json.dumps(pages), encoding="utf-8")
    with serve(published) as base:
        dom = browse(browser, tmp_path_factory.mktemp("profile"), "--virtual-time-budget=60000", "--dump-dom",
                     f"{base}/probe.html").stdout
    found = json.loads(base64.b64decode(re.search(r'<pre id="out">(.*?)</pre>', dom, re.S).group(1)))
    assert set(found) == {url for url, _ in pages}
    return found


def episodes(published: Path) -> dict[Path, dict]:
    return {p.parent: read_scores(p) for p in sorted((published / "results").rglob("scores.json"))}


def test_every_transcript_reads_before_and_after_scoring(published, seen):
    scored = episodes(published)
    assert len(scored) == len(MODELS) * 3
    categories = Counter(s["episode scores"]["Error Category"] for s in scored.values())
    assert categories["success"] and sum(categories.values()) > categories["success"], categories  # won and lost
    for folder, scores in scored.items():
        for name in ("transcript.html", BEFORE):
            page = seen[(folder / name).relative_to(published).as_posix()]
            assert page["pictures"] and page["images"] == len(page["pictures"]), (folder, name)
            for pic in page["pictures"]:
                where = (folder.name, name, pic["href"])
                assert pic["loaded"] and pic["shown"] > 250, where
                assert pic["font"] >= MIN_LABEL and pic["rendered"] >= MIN_LABEL, (where, pic["font"], pic["rendered"])
                assert {"target", "built", "1", "8", "washer", "nut", "screw"} <= set(pic["texts"]), where
                assert re.fullmatch(r"boards_\d+\.svg", pic["href"]) and pic["status"] == 200, where
            assert_card_matches(page["card"], scores)  # outcome, Main Score, ES, F1, category, ES by round
            assert page["literal"] and all("monospace" in font for font, _ in page["literal"]), page["literal"]
            assert any("\u2b1c" in text for _, text in page["literal"]), "the describer's grid view"
            assert page["prose"] and not any("monospace" in font for font, _ in page["prose"]), page["prose"]


def test_report_html_shows_the_set_played(published, seen):
    scored = episodes(published)
    report = seen["scores/report.html"]
    assert report["title"] == "SARTCo report" and "monospace" not in report["bodyFont"]
    experiments = {(f.parents[2].name, f.parent.name) for f in scored}  # (model, experiment)
    assert report["bars"] == len(experiments)  # the error taxonomy: one stacked bar per model and experiment
    kinds = {(f.parents[2].name, f.parent.name, s["episode scores"]["Error Category"]) for f, s in scored.items()}
    assert report["segments"] == len(kinds)  # a segment per category seen in each
    assert report["series"] == len(MODELS)  # ES by round: one series per model and mode (all `correct`)
    assert report["heat"] == 8 * 8  # where the failed builds differ from the target
    assert report["charts"] == 3
    links = report["links"]
    assert len(links) == len(kinds)  # one example transcript per (model, experiment, category)
    assert all(code == 200 and is_transcript for _, code, is_transcript in links), links
    head, *rows = report["dialogue"]  # experiments x models, ES by round in each cell
    assert head == ["experiment", "mode", "K", "R", *MODELS]
    assert sorted(r[0] for r in rows) == sorted({e for _, e in experiments})
    assert all("ES by round: " in cell for r in rows for cell in r[4:]), rows
