"""Transcripts as a leaderboard reader sees them: board pictures that travel with a copied results
folder, looked at in a real browser (headless Chromium) through clem run / score / transcribe
(the messages' display form on its own: tests/clem/test_transcript_display.py)."""
import http.server
import json
import os
import re
import shutil
import threading
from functools import partial
from pathlib import Path

import pytest

from browser_helpers import browse, chromium
from play_helpers import clem

REPO = Path(__file__).resolve().parents[3]
GAME, EXPERIMENT = "cobot_instruct_ablations", "rb_so_repetition_template_examples_0"  # 10 val episodes, loops in the gold code
SCREENSHOT = REPO / "docs" / "transcript.png"


# A page beside transcript.html that loads it in a frame (same origin: both from the local HTTP
# server) and reports, after load, every picture's link and size and the x position of each line of the
# first code block, measured with a DOM Range on the line's first visible character.
PROBE = """<!doctype html><html><body>
<iframe id="t" src="transcript.html" style="width: 1000px; height: 3000px"></iframe>
<pre id="out">pending</pre>
<script>
window.addEventListener("load", () => {
  const d = document.getElementById("t").contentDocument;
  const pictures = [...d.images].map(i => [i.closest("a").getAttribute("href"), i.complete, i.naturalWidth]);
  const lines = [];
  const code = d.querySelector("pre.sartco-code code");
  const node = code ? code.firstChild : null;
  if (node) {
    let start = 0;
    for (const line of node.textContent.split("\\n")) {
      const lead = line.length - line.trimStart().length;
      if (line.trim()) {
        const r = d.createRange();
        r.setStart(node, start + lead); r.setEnd(node, start + lead + 1);
        lines.push([line, r.getBoundingClientRect().left]);
      }
      start += line.length + 1;
    }
  }
  document.getElementById("out").textContent = JSON.stringify({pictures, lines});
});
</script></body></html>
"""


@pytest.mark.slow
def test_transcript_of_a_copied_results_folder_in_a_browser(tmp_path):
    browser = chromium()
    results = tmp_path / "results"
    for step in (["run", "-m", "mock", "-e", EXPERIMENT], ["score"], ["transcribe"]):
        clem(step[0], "-g", GAME, *step[1:], "-r", str(results))
    published = tmp_path / "elsewhere" / "runs"
    shutil.copytree(results, published)
    shutil.rmtree(results)  # nothing may point back to where it was scored
    episode = next(published.rglob("instance_00000"))
    (episode / "probe.html").write_text(PROBE, encoding="utf-8")

    server = http.server.ThreadingHTTPServer(
        ("127.0.0.1", 0), partial(http.server.SimpleHTTPRequestHandler, directory=str(published)))
    threading.Thread(target=server.serve_forever, daemon=True).start()
    try:
        base = f"http://127.0.0.1:{server.server_address[1]}/{episode.relative_to(published).as_posix()}"
        dom = browse(browser, tmp_path / "profile1", "--virtual-time-budget=10000", "--dump-dom",
                     f"{base}/probe.html").stdout
        shot = tmp_path / "transcript.png"
        browse(browser, tmp_path / "profile2", "--window-size=1000,1900", f"--screenshot={shot}",
               f"{base}/transcript.html")
    finally:
        server.shutdown()
    found = json.loads(re.search(r'<pre id="out">(.*?)</pre>', dom, re.S).group(1).replace("&quot;", '"'))
    assert [src for src, _, _ in found["pictures"]] == ["boards_1.svg"]
    assert all(complete and width > 100 for _, complete, width in found["pictures"]), found["pictures"]
    lines = found["lines"]
    assert lines, "no code block in the transcript"
    flush = [x for line, x in lines if not line.startswith(" ")]
    indented = [(line, x) for line, x in lines if line.startswith("    ")]
    assert indented, lines
    for line, x in indented:  # four spaces of monospace further right than the unindented lines
        assert x > min(flush) + 15, (line, x, min(flush))
    assert shot.stat().st_size > 10_000
    if os.environ.get("SARTCO_SCREENSHOT"):  # refresh docs/games.md's picture: SARTCO_SCREENSHOT=1 pytest ...
        shutil.copyfile(shot, SCREENSHOT)
