"""The score card at the end of every transcript (`ScoreCard`, the first of BuildGameMaster's bases:
sartco.clem.core.master holds them in their one order).

When an episode ends (clemcore's `log_game_end`, also after a harness fault) the game master runs
the game's own scorer (`scorer_class`, the very class `clem score` uses: sartco.clem.core.benchmark)
on a copy of its own interactions record, exactly as `clem score` will read it from
interactions.json, and logs the result as a last GM->GM event of type "score card". So the card
is in the transcript whether `clem score` runs before or after `clem transcribe`, and its numbers
are those of scores.json: one computation, no metric computed twice in two ways.

The card shows: the verdict (won / lost / aborted, from Success / Lose / Aborted) and the outcome
line of the final build; Main Score; ES; cell F1 with P and R; the error category, its family and
its meaning in plain words (sartco.world.category_meaning); the harness's reason for a
harness_error; EM and CodeBLEU where the scorer computed them; puts; for the paper protocol its
EM / CB / ES and the same per turn; for dialogues ES by round; then every other score of the game.
The rows are lines of monospace text (`.sartco-scores`, a <div> each: label, then the value in an
aligned column that a long value wraps to), each value rounded to 4 significant digits, "n/a" for
NaN. The exact values are on the card as scores.json has them (JSON, NaN as NaN): the episode
scores in the card's `data-scores`, the paper protocol's per-turn scores in its turn table's
`data-turns` (keyed as scores.json's "round scores"). Every text is escaped (sartco.text.escape /
one_line, then HTML).

The card has as few tags as it can (a line of text per row, not a table with a tag per cell and
value): clemcore's transcript builder parses every tag of every message with Python-Markdown's HTML
parser, and a card of ~100 tags cost about as much as the rest of an episode's transcript
(issue 23's 10 % budget for make main).

The record the card is computed from is a second clemcore GameInteractionsRecorder registered on
the game master after setup, i.e. when clemcore registers the one that writes interactions.json
(clemcore's public `register`): it sees the same events, keys and request counts.
"""
from __future__ import annotations

import copy
import functools
import html
import json
import math

from clemcore.clemgame import metrics
from clemcore.clemgame.recorder import GameInteractionsRecorder

from sartco.episode import (BUILD_KEY, CELL_F1, CELL_PRECISION, CELL_RECALL, CODEBLEU, ERROR_CATEGORY, ERROR_FAMILY,
                            EXACT_MATCH, EXECUTION_SUCCESS, HARNESS_REASON, MARKDOWN_KEY, PAPER_SCORES, PUTS,
                            ROUND_PREFIX)
from sartco.text import escape, one_line
from sartco.world import category_meaning

from .building import BuildRecord
from .harness import fault_reason
from .transcript import text_block

CARD_EVENT = "score card"
VERDICTS = ((metrics.METRIC_SUCCESS, "won"), (metrics.METRIC_LOSE, "lost"), (metrics.METRIC_ABORTED, "aborted"))
FRAMEWORK = {metrics.METRIC_REQUEST_COUNT, metrics.METRIC_REQUEST_COUNT_PARSED, metrics.METRIC_REQUEST_COUNT_VIOLATED,
             metrics.METRIC_REQUEST_SUCCESS_RATIO, metrics.METRIC_ABORTED, metrics.METRIC_SUCCESS, metrics.METRIC_LOSE}
SHOWN_FIRST = (metrics.BENCH_SCORE, EXECUTION_SUCCESS, CELL_F1, CELL_PRECISION, CELL_RECALL, ERROR_CATEGORY,
               ERROR_FAMILY, HARNESS_REASON, EXACT_MATCH, CODEBLEU, PUTS, *PAPER_SCORES.values())
VERDICT_COLOURS = {"won": "#1a7f37", "lost": "#cf222e", "aborted": "#57606a", "unknown": "#57606a"}
# the card's message is wider than clemcore's other GM->GM messages, its labels stay on one line
CARD_STYLE = ("<style>.msg:has(.sartco-card) {margin-left: 5%; margin-right: 5%; font-size: 0.9rem} "
              ".sartco-card {margin: 4px 0; padding: 8px 12px; border: 2px solid #444; border-radius: 6px; "
              "background: #fff} .sartco-scores {margin-top: 4px; white-space: pre-wrap; overflow-wrap: anywhere; "
              "font-family: monospace} "
              ".sartco-turns th, .sartco-turns td {text-align: left; padding: 2px 12px 2px 0}</style>")


def card_scores(scorer_class, game_name: str, experiment: dict, instance: dict, interactions: dict) -> dict:
    """What `clem score` writes to scores.json for this record: the game's scorer on the record as
    it is read back from interactions.json (a JSON round trip)."""
    scorer = scorer_class(game_name, {k: v for k, v in experiment.items() if k != "game_instances"}, instance)
    scorer.compute_scores(json.loads(json.dumps(interactions)))
    return scorer.scores


def shown(value) -> str:
    """A score as the card shows it: 4 significant digits, n/a for NaN or a missing value."""
    if value is None or (isinstance(value, float) and math.isnan(value)):
        return "n/a"
    if isinstance(value, (int, float)) and not isinstance(value, bool):
        return format(value, ".4g")
    return str(value)


def _rows(ep: dict, paper: bool) -> list[tuple[str, str]]:
    """The card's rows (label, shown value), plain text, in the order a reader wants them."""
    # the paper protocol's Main Score is 100 x its ES; ES, EM and CodeBLEU are ours (the whole program)
    ours = "ours: whole program" if paper else None
    rows = [("Main Score" + (" (100 x paper ES)" if paper else ""), shown(ep.get(metrics.BENCH_SCORE))),
            (f"ES ({ours or 'execution success'})", shown(ep.get(EXECUTION_SUCCESS)))]
    if CELL_F1 in ep:
        rows.append(("Cell F1 (P / R)", f"{shown(ep[CELL_F1])} (P {shown(ep.get(CELL_PRECISION))} / "
                                        f"R {shown(ep.get(CELL_RECALL))})"))
    category = ep.get(ERROR_CATEGORY)
    if category is not None:
        try:
            meaning = category_meaning(category)
        except ValueError:
            meaning = "an unknown category."
        rows.append(("Error category", f"{shown(category)} ({shown(ep.get(ERROR_FAMILY))}): {meaning}"))
    for name, label in ((HARNESS_REASON, "Harness failure"), (EXACT_MATCH, f"EM ({ours or 'exact match'})"),
                        (CODEBLEU, f"CodeBLEU ({ours})" if ours else "CodeBLEU"), (PUTS, "Puts")):
        if name in ep:
            rows.append((label, shown(ep[name])))
    if paper:
        rows.append(("Paper (share of turns)",
                     " / ".join(f"{n.split()[1]} {shown(ep.get(n))}" for n in PAPER_SCORES.values())))
    by_round = sorted((n for n in ep if n.startswith(ROUND_PREFIX)), key=lambda n: int(n[len(ROUND_PREFIX):]))
    if by_round:
        rows.append(("ES by round (after k corrections)",
                     " · ".join(f"round {n[len(ROUND_PREFIX):]}: {shown(ep[n])}" for n in by_round)))
    rows.extend((name, shown(ep[name])) for name in ep
                if name not in FRAMEWORK and name not in SHOWN_FIRST and name not in by_round)
    return rows


def _data(values) -> str:
    return html.escape(json.dumps(values), quote=True)


def card_html(scores: dict, outcome_line: str | None) -> str:
    """The card of an episode's scores (clemcore's scores dict: "episode scores", "round scores")."""
    ep, rounds = scores.get(metrics.KEY_EPISODE_SCORES, {}), scores.get(metrics.KEY_ROUND_SCORES, {})
    verdict = next((word for key, word in VERDICTS if ep.get(key)), "unknown")
    rows = _rows(ep, any(name in ep for name in PAPER_SCORES.values()))
    width = max(len(label) for label, _ in rows) + 2  # the value column; a long value wraps to it
    table = "".join(f"<div>{html.escape(f'{label:{width}}{one_line(text)}', quote=False)}</div>" for label, text in rows)
    parts = [f'{CARD_STYLE}<div class="sartco-card" data-scores="{_data(ep)}"><b>Score card</b>: '
             f'<b class="sartco-verdict" style="color: {VERDICT_COLOURS[verdict]}">{verdict}</b>']
    if outcome_line:
        parts.append(f'<div class="sartco-outcome">{html.escape(escape(outcome_line), quote=False)}</div>')
    parts.append(f'<div class="sartco-scores" style="padding-left: {width}ch; text-indent: -{width}ch">{table}</div>')
    turns = [k for k in sorted(rounds, key=int) if PAPER_SCORES["em"] in rounds[k]]
    if turns:
        head = "".join(f'<th>{html.escape(n.split()[1])}</th>' for n in PAPER_SCORES.values())
        body = "".join(f"<tr><td>{int(k) + 1}</td>" + "".join(f"<td>{html.escape(shown(rounds[k].get(n)))}</td>"
                                                            for n in PAPER_SCORES.values()) + "</tr>" for k in turns)
        data = _data({k: {n: rounds[k][n] for n in PAPER_SCORES.values() if n in rounds[k]} for k in turns})
        parts.append(f'<table class="sartco-turns" data-turns="{data}"><tr><th>paper turn</th>{head}</tr>{body}</table>')
    return "".join(parts) + "</div>"


@functools.cache
def _blank_recorder() -> GameInteractionsRecorder:
    return GameInteractionsRecorder("", "", 0, "", {})


def card_recorder(game_name: str, experiment_name: str, game_id) -> GameInteractionsRecorder:
    """A fresh clemcore recorder for one episode's card: a copy of one made once per process
    (clemcore's constructor reads its own version from the package metadata, about 2 ms, which is
    most of the card's cost in a mock run), its meta filled as clemcore's constructor would."""
    recorder = copy.deepcopy(_blank_recorder())
    recorder.interactions["meta"].update(game_name=game_name, experiment_name=experiment_name, game_id=game_id)
    return recorder


class ScoreCard:
    """BuildGameMaster's first base (sartco.clem.core.master): logs the score card when the episode
    ends. The game master class names its scorer in `scorer_class` (the benchmark scores with the
    same class)."""
    scorer_class: type | None = None

    def setup(self, **instance):
        super().setup(**instance)
        self.card_instance = instance
        self.card_record = card_recorder(self.game_spec.game_name, self.experiment.get("name"), instance.get("game_id"))
        self.register(self.card_record)  # from here on it sees what clemcore's own recorder sees

    def log_game_end(self, auto_count_logging: bool = True):
        super().log_game_end(auto_count_logging)
        try:
            interactions = self.card_record.interactions
            scores = card_scores(self.scorer_class, self.game_spec.game_name, self.experiment, self.card_instance,
                                 interactions)
            record = interactions.get(BUILD_KEY)
            content = card_html(scores, BuildRecord.from_json(record).summary() if record else None)
        except Exception as exc:  # a fault of the card never loses the episode
            content = text_block(f"no score card: {fault_reason('score card', exc)}")
        self.log_key(MARKDOWN_KEY, True)
        self.log_event(from_="GM", to="GM", action={"type": CARD_EVENT, "content": content})
