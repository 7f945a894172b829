"""The score card at the end of every transcript (sartco.clem.core.card), through clemcore's real loop:
a won, a lost (mismatch), an aborted (no code) and a hostile failing cobot_instruct episode, a
cobot_describe dialogue (correct mode: ES by round) and a paper-protocol episode with one wrong
turn (per-turn EM/CB/ES). The transcripts are made BEFORE `clem score` writes scores.json, and the
card must then show exactly the values of that scores.json; the same in headless Chromium's DOM."""
from __future__ import annotations

import copy
import http.server
import json
import math
import threading
from functools import partial
from html.parser import HTMLParser
from pathlib import Path

import pytest

from feedback_cases import GOLD, TARGET, WRONG
from play_helpers import clem, fence, play, scripted_episode
from test_cobot_describe_dialogue import FULL, experiments_of, wrong_code
from test_paper_protocol import GAME as PAPER_GAME
from test_paper_protocol import VARIANTS, experiment, instances, paper_episodes  # noqa: F401 - a fixture
from test_transcript import browse, chromium
from sartco.world import category_meaning

INSTRUCT = {"name": "card_instruct", "board_type": "simple", "object_type": "simple", "task": "first_order",
            "source": "template", "split": "test", "ablation": None}
HOSTILE = "put(board, '<b id=\"pwned\">x</b>', 'red', 0, 0)"  # a key_error whose message repeats the shape


def instruct_instances():
    one = ["Build the board."]
    return [scripted_episode(0, TARGET, GOLD, one), scripted_episode(1, TARGET, GOLD, one, script=[fence(WRONG)]),
            scripted_episode(2, TARGET, GOLD, one, script=["I would rather not write code."]),
            scripted_episode(3, TARGET, GOLD, one, script=[fence(HOSTILE)])]


def dialogue_case():
    source = next(e for e in experiments_of(FULL) if e.get("mode") == "correct" and e["board_type"] == "simple")
    inst = copy.deepcopy(source["game_instances"][0])
    inst["builder_script"] = [fence(wrong_code(inst["target"]))]  # wrong first, then the follower repairs
    return [inst], {k: v for k, v in source.items() if k != "game_instances"}


class Card(HTMLParser):
    """The card's values (data-score -> (data-value, shown text)), meaning and outcome texts."""

    def __init__(self):
        super().__init__()
        self.values, self.texts, self.stack, self.ids = {}, {}, [], set()

    def handle_starttag(self, tag, attrs):
        attrs = dict(attrs)
        self.ids.add(attrs.get("id"))
        key = attrs.get("data-score") or attrs.get("class")
        if tag == "span" and "data-score" in attrs:
            key = attrs["data-score"] + (f"#{attrs['data-round']}" if "data-round" in attrs else "")
            self.values.setdefault(key, []).append([attrs["data-value"], ""])
        self.stack.append(key if key in ("sartco-meaning", "sartco-outcome", "sartco-verdict") or "data-score" in attrs
                          else None)

    def handle_endtag(self, tag):
        if self.stack:
            self.stack.pop()

    def handle_data(self, data):
        key = next((k for k in reversed(self.stack) if k), None)
        if key in self.values:
            self.values[key][-1][1] += data
        elif key:
            self.texts[key] = self.texts.get(key, "") + data


def card_of(html: str) -> Card:
    start = html.index('class="sartco-card"')
    parser = Card()
    parser.feed(html[html.rindex("<", 0, start):])
    return parser


def same(a, b) -> bool:
    return (isinstance(a, float) and isinstance(b, float) and math.isnan(a) and math.isnan(b)) or a == b


def assert_card_matches(html: str, scores: dict):
    """Every value of the card is scores.json's, shown to 4 digits; the category's meaning is shown."""
    card = card_of(html)
    episode = scores["episode scores"]
    for name in ("Main Score", "Execution Success", "Cell F1", "Cell Precision", "Cell Recall", "Error Category"):
        assert name in card.values, (name, card.values)
    for key, shown in card.values.items():
        name, _, round_idx = key.partition("#")
        want = scores["round scores"][round_idx][name] if round_idx else episode[name]
        assert len(shown) == 1, (key, shown)
        for raw, text in shown:
            assert same(json.loads(raw), want), (name, raw, want)
            text = text.split(": ")[-1].split(" ")[-1]  # "P 0.6", "0: 1" -> the number
            if isinstance(want, str):
                assert text == want or want.endswith(text)
            elif math.isnan(want):
                assert text == "n/a", (name, text)
            else:
                assert abs(float(text) - want) <= 5e-4 * max(1.0, abs(want)), (name, text, want)
    assert card.texts["sartco-meaning"] == category_meaning(episode["Error Category"])
    verdict = {(0, 1, 0): "won", (0, 0, 1): "lost", (1, 0, 0): "aborted"}
    assert card.texts["sartco-verdict"] == verdict[(episode["Aborted"], episode["Success"], episode["Lose"])]
    return card


def read_scores(path: Path) -> dict:
    return json.loads(path.read_text(encoding="utf-8"))  # json reads NaN as float("nan")


@pytest.fixture(scope="module")
def played(tmp_path_factory, paper_episodes):  # noqa: F811 - the imported fixture
    """Each game played in-process, its scores.json removed, transcribed, then `clem score`d."""
    from clemcore.clemgame.transcripts.builder import build_transcripts

    tmp = tmp_path_factory.mktemp("card")
    ep = paper_episodes["multi_turn"]
    script = list(ep["mock_answers"])
    script[1] = "Output\nput(board, 'washer', 'red', 9, 9)\n"
    dialogue, dialogue_experiment = dialogue_case()
    games = {"cobot_instruct": (instruct_instances(), INSTRUCT),
             "cobot_describe": (dialogue, {**dialogue_experiment, "name": "card_dialogue"}),
             PAPER_GAME: (instances([ep], [script]), experiment(ep, "card_paper"))}
    out = {}
    for game, (episodes, exp) in games.items():
        results = tmp / game
        for r in play(episodes, exp, results, game=game):
            (r["dir"] / "scores.json").unlink()
            out[(game, r["interactions"]["meta"]["game_id"])] = r["dir"]
        build_transcripts(str(results), [game])  # what `clem transcribe` does, before any scores.json
        assert not list(results.rglob("scores.json"))
        clem("score", "-g", game, "-r", str(results))
    return tmp, out


def test_the_card_shows_the_values_of_scores_json_whatever_the_order(played):
    _, dirs = played
    cards = {}
    for key, folder in dirs.items():
        html = (folder / "transcript.html").read_text(encoding="utf-8")
        assert html.rindex('class="sartco-card"') > html.rindex('class="msg'), "the card is the last event"
        cards[key] = assert_card_matches(html, read_scores(folder / "scores.json"))
    won, lost, aborted, hostile = (cards[("cobot_instruct", k)] for k in range(4))
    assert won.values["Main Score"] == [["100.0", "100"]] and won.values["Exact Match"] == [["1", "1"]]
    assert lost.values["Error Category"][0][1] == "mismatch_location" and lost.values["Cell F1"][0][1] == "0.6"
    assert "lost" == lost.texts["sartco-verdict"] and "mismatch_location" in lost.texts["sartco-outcome"]
    assert aborted.values["Main Score"] == [["NaN", "n/a"]] and aborted.texts["sartco-verdict"] == "aborted"
    assert hostile.values["Error Category"][0][1] == "key_error"
    assert '<b id="pwned">' in hostile.texts["sartco-outcome"] and "pwned" not in hostile.ids  # text, not markup
    dialogue = next(card for (game, _), card in cards.items() if game == "cobot_describe")
    assert [v for v, _ in dialogue.values["ES Round 0"]] == ["0"] and dialogue.values["ES Round 1"][0][0] == "1"
    paper = cards[(PAPER_GAME, 0)]
    turns = sorted((int(k.split("#")[1]), v[0][0]) for k, v in paper.values.items() if k.startswith("Paper ES#"))
    assert [es for _, es in turns] == ["1", "0"] + ["1"] * (len(turns) - 2), turns  # turn 2 (index 1) wrong
    n = len(turns)
    assert json.loads(paper.values["Paper ES"][0][0]) == pytest.approx((n - 1) / n)


@pytest.mark.slow
def test_the_card_in_a_browser(played, tmp_path):
    browser = chromium()
    root, dirs = played
    server = http.server.ThreadingHTTPServer(
        ("127.0.0.1", 0), partial(http.server.SimpleHTTPRequestHandler, directory=str(root)))
    threading.Thread(target=server.serve_forever, daemon=True).start()
    try:
        for k, (key, folder) in enumerate(sorted(dirs.items())):
            url = f"http://127.0.0.1:{server.server_address[1]}/{folder.relative_to(root).as_posix()}/transcript.html"
            dom = browse(browser, tmp_path / f"profile{k}", "--virtual-time-budget=5000", "--dump-dom", url).stdout
            card = assert_card_matches(dom, read_scores(folder / "scores.json"))
            assert "pwned" not in card.ids
    finally:
        server.shutdown()


@pytest.fixture
def fresh_pool():
    from sartco.program import pool
    pool.shutdown()
    yield
    pool.shutdown()


def test_a_harness_fault_has_its_card_and_its_meaning(play_episodes, monkeypatch, fresh_pool):
    from clemcore.clemgame.transcripts.builder import build_transcript
    from harness_helpers import no_worker

    no_worker(monkeypatch, "no worker for the card")
    [result] = play_episodes([scripted_episode(0, TARGET, GOLD, ["Build the board."])], INSTRUCT)
    card = assert_card_matches(build_transcript(result["interactions"]), read_scores(result["dir"] / "scores.json"))
    assert card.values["Error Category"][0][1] == "harness_error" and card.texts["sartco-verdict"] == "aborted"
    assert card.texts["sartco-meaning"] == "the harness failed, not the model; left out of the scores."
    assert "no worker for the card" in card.values["Harness Error"][0][1]


def test_a_fault_of_the_card_loses_nothing(play_episodes, monkeypatch):
    import sartco.clem.core.card as card

    def broken(*args):
        raise RuntimeError("the card broke")
    monkeypatch.setattr(card, "card_scores", broken)
    [result] = play_episodes([scripted_episode(0, TARGET, GOLD, ["Build the board."])], INSTRUCT)
    last = result["interactions"]["turns"][-1][-1]["action"]
    assert last["type"] == "score card" and "no score card: score card: RuntimeError: the card broke" in last["content"]
    assert result["scores"]["episode scores"]["Main Score"] == 100  # the episode and its scores are unharmed
