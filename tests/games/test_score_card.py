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
from browser_helpers import browse, chromium
from episode_helpers import FULL, experiments_of, wrong_code
from paper_helpers import PAPER_GAME, experiment, instances
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
    """What the card holds: its exact values (data-scores, data-turns), its rows of text (label ->
    shown value), the paper turn table's cells, the outcome and verdict texts, every element id."""

    def __init__(self):
        super().__init__()
        self.data, self.turns, self.rows, self.turn_rows = None, None, {}, []
        self.texts, self.stack, self.ids = {}, [], set()

    def handle_starttag(self, tag, attrs):
        attrs = dict(attrs)
        self.ids.add(attrs.get("id"))
        if "data-scores" in attrs and self.data is None:
            self.data = json.loads(attrs["data-scores"])
        if "data-turns" in attrs:
            self.turns = json.loads(attrs["data-turns"])
        if tag == "tr":
            self.turn_rows.append([])
        self.stack.append(attrs.get("class") or tag)

    def handle_endtag(self, tag):
        if self.stack:
            self.stack.pop()

    def handle_data(self, data):
        where = self.stack[-1] if self.stack else None
        if where == "td":
            self.turn_rows[-1].append(data)
        elif where in ("sartco-outcome", "sartco-verdict"):
            self.texts[where] = self.texts.get(where, "") + data
        elif where == "div" and "sartco-scores" in self.stack:  # a row: its label, then the value in a column
            label, _, value = data.partition("  ")
            self.rows[label] = value.strip()

    def row(self, label: str) -> str:
        """The value shown in the row whose label starts with `label`."""
        [value] = [v for k, v in self.rows.items() if k.startswith(label)]
        return value


def card_of(html: str) -> Card:
    start = html.index('class="sartco-card"')
    parser = Card()
    parser.feed(html[html.rindex("<", 0, start):])
    return parser


def same(a, b) -> bool:
    if isinstance(a, dict) and isinstance(b, dict):
        return a.keys() == b.keys() and all(same(a[k], b[k]) for k in a)
    return (isinstance(a, float) and isinstance(b, float) and math.isnan(a) and math.isnan(b)) or a == b


def shown(value) -> str:
    """A value as a reader should see it: 4 significant digits, n/a for NaN."""
    if isinstance(value, float) and math.isnan(value):
        return "n/a"
    return format(value, ".4g") if isinstance(value, (int, float)) else str(value)


def assert_card_matches(html: str, scores: dict):
    """The card holds scores.json's values exactly and shows them to 4 digits beside their labels;
    the category's meaning, the verdict and (paper protocol) every turn's EM / CB / ES are shown."""
    card = card_of(html)
    episode = scores["episode scores"]
    assert same(card.data, episode), (card.data, episode)
    assert card.row("Main Score") == shown(episode["Main Score"])
    assert card.row("ES (") == shown(episode["Execution Success"])  # "(execution success)", "(ours: ...)"
    assert card.row("Cell F1 (P / R)") == (f'{shown(episode["Cell F1"])} (P {shown(episode["Cell Precision"])} / '
                                           f'R {shown(episode["Cell Recall"])})')
    category = episode["Error Category"]
    assert card.row("Error category") == (f'{category} ({episode["Error Family"]}): {category_meaning(category)}')
    for name, label in (("Exact Match", "EM ("), ("CodeBLEU", "CodeBLEU"), ("Puts", "Puts")):
        if name in episode:
            assert card.row(label) == shown(episode[name]), name
    rounds = sorted((n for n in episode if n.startswith("ES Round ")), key=lambda n: int(n.split()[-1]))
    if rounds:
        assert card.row("ES by round") == " · ".join(f"round {n.split()[-1]}: {shown(episode[n])}" for n in rounds)
    for name, value in episode.items():  # every other score of the game in a row of its own name
        if name in card.rows:
            assert card.rows[name] == shown(value), name
    per_turn = {k: {n: v for n, v in s.items() if n.startswith("Paper ")} for k, s in scores["round scores"].items()}
    per_turn = {k: v for k, v in per_turn.items() if v}
    assert same(card.turns or {}, per_turn), (card.turns, per_turn)
    assert [row[1:] for row in card.turn_rows[1:]] == [[shown(v) for v in per_turn[k].values()]
                                                       for k in sorted(per_turn, key=int)]
    verdict = {(0, 1, 0): "won", (0, 0, 1): "lost", (1, 0, 0): "aborted"}
    assert card.texts["sartco-verdict"] == verdict[(episode["Aborted"], episode["Success"], episode["Lose"])]
    return card


def read_scores(path: Path) -> dict:
    return json.loads(path.read_text(encoding="utf-8"))  # json reads NaN as float("nan")


@pytest.fixture(scope="module")
def played(tmp_path_factory, paper_episodes):
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
    assert won.row("Main Score") == "100" and won.row("EM (exact match)") == "1" and won.data["Exact Match"] == 1
    assert lost.row("Error category").startswith("mismatch_location") and lost.row("Cell F1").startswith("0.6 ")
    assert "lost" == lost.texts["sartco-verdict"] and "mismatch_location" in lost.texts["sartco-outcome"]
    assert aborted.row("Main Score") == "n/a" and math.isnan(aborted.data["Main Score"])
    assert aborted.texts["sartco-verdict"] == "aborted"
    assert hostile.row("Error category").startswith("key_error")
    assert '<b id="pwned">' in hostile.texts["sartco-outcome"] and "pwned" not in hostile.ids  # text, not markup
    dialogue = next(card for (game, _), card in cards.items() if game == "cobot_describe")
    assert dialogue.data["ES Round 0"] == 0 and dialogue.data["ES Round 1"] == 1
    assert dialogue.row("ES by round").startswith("round 0: 0 · round 1: 1")
    paper = cards[(PAPER_GAME, 0)]
    turns = [paper.turns[k]["Paper ES"] for k in sorted(paper.turns, key=int)]
    assert turns == [1, 0] + [1] * (len(turns) - 2), turns  # turn 2 (index 1) wrong
    assert [row[3] for row in paper.turn_rows[1:]] == [str(es) for es in turns]  # shown in the turn table
    n = len(turns)
    assert paper.data["Paper ES"] == pytest.approx((n - 1) / n)
    assert paper.row("Main Score (100 x paper ES)") == shown(100 * (n - 1) / n)


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
    assert card.row("Error category").startswith("harness_error") and card.texts["sartco-verdict"] == "aborted"
    assert card.row("Error category").endswith(": the harness failed, not the model; left out of the scores.")
    assert "no worker for the card" in card.row("Harness failure")


def test_a_fault_of_the_card_loses_nothing(play_episodes, monkeypatch):
    import sartco.clem.core.card as card

    def broken(*args):
        raise RuntimeError("the card broke")
    monkeypatch.setattr(card, "card_scores", broken)
    [result] = play_episodes([scripted_episode(0, TARGET, GOLD, ["Build the board."])], INSTRUCT)
    last = result["interactions"]["turns"][-1][-1]["action"]
    assert last["type"] == "score card" and "no score card: score card: RuntimeError: the card broke" in last["content"]
    assert result["scores"]["episode scores"]["Main Score"] == 100  # the episode and its scores are unharmed
