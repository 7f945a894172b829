"""A model answer can carry markup and script; no element or script of it may exist in a
published transcript. Answers of cobot_instruct (our protocol: the answer, its code, the
sandbox's message about it) and of the paper protocol (the paper_turn event: what the authors'
scorer read) go through clemcore's real loop, `clem transcribe`, and headless Chromium's DOM.
Before, the paper_turn event logged the read answer unescaped: `<img src=x onerror=...>` ran."""
import html.parser

import pytest

from play_helpers import clem, fence, play, scripted_episode
from browser_helpers import browse, chromium

from sartco.games.instruct.paper import instance_fields, experiment_fields
from sartco.dataset import SHARED_DATA

# every piece of markup carries an id "pwned..." or a javascript: URL, so the DOM shows whether it became an element
MARKUP = ("<img src=x onerror=\"document.title='PWNED'\" id=pwned1> <script id=pwned2>document.title='PWNED'</script> "
          "[click](javascript:alert('pwned3')) <b id=pwned4>bold</b> <a href=\"javascript:alert(1)\" id=pwned5>a</a> "
          "\\input{secret} \x00 \u202e")
INSTRUCT_ANSWER = (f"Sure! {MARKUP}\n" + fence(
    "put(board, 'nut', 'red', 0, 0)  # <script id=pwned6>document.title='PWNED'</script>\n"
    "put(board, 'nut', '<img src=x onerror=alert(7) id=pwned7>', 1, 1)"))
PAPER_ANSWER = ("Function:\n```python\ndef f(board):\n    # <img src=x onerror=\"document.title='PWNED'\" id=pwned8>\n"
                "    put(board, 'nut', 'red', 0, 0)\n```\nUsage: f(board) <script id=pwned9>document.title='PWNED'</script>")


class Elements(html.parser.HTMLParser):
    def __init__(self):
        super().__init__()
        self.found = []  # (tag, attrs) of every element

    def handle_starttag(self, tag, attrs):
        self.found.append((tag, dict(attrs)))


def injected(dom: str) -> list:
    parser = Elements()
    parser.feed(dom)
    return [(tag, attrs) for tag, attrs in parser.found
            if str(attrs.get("id", "")).startswith("pwned") or "onerror" in attrs
            or any("javascript:" in str(v) for v in attrs.values())]


@pytest.mark.slow
@pytest.mark.skipif(not (SHARED_DATA / "published").is_dir(), reason="shared data missing")
def test_markup_in_answers_never_reaches_the_dom(tmp_path):
    from sartco.paper.episodes import build_episodes
    browser = chromium()
    results = tmp_path / "results"
    target = {"0:0": [["nut", "red"]]}
    play([scripted_episode(0, target, ["put(board, 'nut', 'red', 0, 0)"], ["Place a red nut at (0, 0)."],
                           script=[INSTRUCT_ANSWER])], {"name": "markup", "attempts": 1}, results)
    ep = next(e for e in build_episodes(files=["sb_so_test"], variants=["single_turn"])).to_json()
    (paper,) = play([{"game_id": 0, **instance_fields(ep), "script": [PAPER_ANSWER]}],
                    {"name": "paper_markup", **experiment_fields(ep)}, results, game="cobot_instruct_paper")
    event = next(e["action"] for t in paper["interactions"]["turns"] for e in t if e["action"]["type"] == "paper_turn")
    code = event["content"].split('<code class="language-python">')[1]
    assert code.lstrip().startswith("def f(board):\n    # &lt;img src=x")  # a code block that keeps its lines

    clem("transcribe", "-r", str(results))
    pages = sorted(results.rglob("transcript.html"))
    assert len(pages) == 2
    for page in pages:
        dom = browse(browser, tmp_path / "profile", "--dump-dom", page.as_uri()).stdout
        assert "sartco-code" in dom and "onerror" in dom  # the answers are shown (as text) ...
        assert injected(dom) == []                        # ... and none of their markup is an element
        assert "<title>PWNED" not in dom and "\x00" not in dom and "\u202e" not in dom
        tex = (page.parent / "transcript.tex").read_text(encoding="utf-8")
        assert "\\input{secret}" not in tex and "\x00" not in tex  # LaTeX escapes, no control characters
    dom = browse(browser, tmp_path / "profile", "--dump-dom", pages[0].as_uri()).stdout
    assert "pwned7" in dom  # the sandbox's message about the markup colour is shown too, escaped
