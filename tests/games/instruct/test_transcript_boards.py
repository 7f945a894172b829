"""Board pictures as a leaderboard reader sees them (issue 23): in headless Chromium, at the width
a transcript really shows them, every picture loads whether `clem transcribe` ran before or after
`clem score`, every label of it is at least 11 px high, each links to its full-size SVG (written
by `clem score`, relative to the episode folder, so it travels with a moved results folder), and
grids and code are in a monospace font. Episodes: `mock` solving (cobot_instruct_ablations) and a
scripted answer that builds the wrong board (cobot_instruct)."""
import http.server
import json
import re
import shutil
import threading
from functools import partial
from pathlib import Path

import pytest

from play_helpers import clem, fence, play, scripted_episode
from browser_helpers import browse, chromium
from test_transcript import EXPERIMENT, GAME

from sartco.world.render import MIN_LABEL

TARGET = {"1:1": [["washer", "blue"], ["nut", "green"]], "7:3": [["screw", "red"]]}
GOLD = ["put(board, 'washer', 'blue', 1, 1)", "put(board, 'nut', 'green', 1, 1)", "put(board, 'screw', 'red', 7, 3)"]
WRONG = "put(board, 'nut', 'blue', 1, 1)"  # one wrong stack, one missing piece

# A page at the top of the results folder that loads each transcript (EPISODES: their folders) in
# turn in a frame as wide as a desktop window and reports, per transcript, every picture (loaded?
# shown how wide? its smallest label in px at that width, from the SVG's viewBox and font sizes;
# its link and whether the link resolves) and the font of every text block. One browser for all.
PROBE = """<!doctype html><html><body>
<pre id="out">pending</pre>
<script>
const EPISODES = %s;
function loaded(frame) { return new Promise(done => frame.addEventListener("load", done, {once: true})); }
window.addEventListener("load", async () => {
  const found = {};
  for (const episode of EPISODES) {
    const frame = document.createElement("iframe");
    frame.style = "width: 1000px; height: 3000px";
    const ready = loaded(frame);
    frame.src = episode + "/transcript.html";
    document.body.appendChild(frame);
    await ready;
    const d = frame.contentDocument;
    const pictures = [];
    for (const img of d.images) {
      const svg = new DOMParser().parseFromString(atob(img.src.split(",")[1]), "image/svg+xml").documentElement;
      const sizes = [...svg.querySelectorAll("text")].map(t => parseFloat(t.getAttribute("font-size")));
      const shown = img.getBoundingClientRect().width;
      const a = img.closest("a");
      let status = null;
      if (a) { try { status = (await fetch(a.href)).status; } catch (e) { status = String(e); } }
      pictures.push({loaded: img.complete && img.naturalWidth > 0, shown,
                     label: shown / svg.viewBox.baseVal.width * Math.min(...sizes), labels: sizes.length,
                     texts: [...svg.querySelectorAll("text")].map(t => t.textContent),
                     href: a ? a.getAttribute("href") : null, status});
    }
    const fonts = [...d.querySelectorAll(".sartco-text, .sartco-code")].map(e => getComputedStyle(e).fontFamily);
    found[episode] = {pictures, fonts};
    frame.remove();
  }
  document.getElementById("out").textContent = JSON.stringify(found);
});
</script></body></html>
"""


def look(browser, folder: Path, tmp_path: Path, tag: str) -> dict:
    """Serve `folder` on 127.0.0.1 and probe every transcript in it: {episode: probe result}."""
    server = http.server.ThreadingHTTPServer(
        ("127.0.0.1", 0), partial(http.server.SimpleHTTPRequestHandler, directory=str(folder)))
    threading.Thread(target=server.serve_forever, daemon=True).start()
    episodes = [page.parent.relative_to(folder).as_posix() for page in sorted(folder.rglob("transcript.html"))]
    (folder / "probe.html").write_text(PROBE % json.dumps(episodes), encoding="utf-8")
    try:
        dom = browse(browser, tmp_path / f"profile-{tag}", "--virtual-time-budget=60000", "--dump-dom",
                     f"http://127.0.0.1:{server.server_address[1]}/probe.html").stdout
    finally:
        server.shutdown()
    return json.loads(re.search(r'<pre id="out">(.*?)</pre>', dom, re.S).group(1)
                      .replace("&quot;", '"').replace("&amp;", "&"))


def check(found: dict, scored: bool) -> None:
    assert len(found) == 11, sorted(found)  # 10 mock episodes, 1 scripted
    for episode, seen in found.items():
        assert seen["pictures"], episode
        for pic in seen["pictures"]:
            assert pic["loaded"] and pic["shown"] > 250, (episode, pic)
            assert pic["label"] >= MIN_LABEL, (episode, pic)  # titles, row/column numbers, legend
            assert {"target", "built", "1", "8", "washer", "nut", "screw", "bridge", "red", "differs"} <= set(pic["texts"])
            assert pic["href"] == "boards_1.svg", (episode, pic)  # relative: it travels with the folder
            assert pic["status"] == (200 if scored else 404), (episode, pic)  # the full-size file: `clem score`
        assert seen["fonts"] and all("monospace" in f for f in seen["fonts"]), (episode, seen["fonts"])


@pytest.mark.slow
def test_board_pictures_read_in_a_moved_folder_whatever_the_order_of_score_and_transcribe(tmp_path):
    browser = chromium()
    results = tmp_path / "results"
    clem("run", "-g", GAME, "-m", "mock", "-e", EXPERIMENT, "-r", str(results))
    play([scripted_episode(0, TARGET, GOLD, ["Build it."], script=[fence(WRONG)])],
                     {"name": "scripted_wrong", "attempts": 1}, results, score=False)
    clem("transcribe", "-r", str(results))  # before any score: no boards_*.svg exists yet
    assert not list(results.rglob("boards_*.svg"))
    check(look(browser, results, tmp_path, "before"), scored=False)

    clem("score", "-r", str(results))
    clem("transcribe", "-r", str(results))
    moved = tmp_path / "elsewhere" / "runs"
    shutil.move(results, moved)  # nothing may point back to where it was scored
    found = look(browser, moved, tmp_path, "after")
    check(found, scored=True)
    svg = (moved / next(e for e in found if "scripted_wrong" in e) / "boards_1.svg").read_text()
    assert svg.count('stroke="#e0007a" stroke-width="3"') == 2 * 2 + 1  # 2 differing cells framed on both grids + legend
