"""The dialogue table of cobot_describe (`sartco report`): per model pair and experiment, what the
clarification questions and the corrections did, and ES after round k as a small SVG plot.

Score names (scores.json, written by sartco.games.describe.dialogue.DialogueScorer):
  ES@1, Cell F1@1      after the first build          ES@N, Cell F1@N   after the last build
  ES Round k           the board standing after k corrections (k = 0..R; the last board carries on)
  First Success Round  0 = the first build, k = after the k-th correction (NaN: never)
  Questions Asked, Corrections Sent, Describer Words   (instruction, answers and corrections)

write(episodes, out) writes dialogue.md, dialogue.csv and dialogue_rounds.svg from the episodes of
sartco.report.rows.collect (nothing when none has dialogue scores) and returns the names written. Percentages are over all
episodes of a row, an aborted episode counting 0, as in the other tables; the means of the
counts are over the played episodes, the first success round over the episodes that succeeded.
"""
from __future__ import annotations

from collections import defaultdict
from pathlib import Path

from sartco.episode import (CELL_F1_AT_1, CELL_F1_AT_N, CORRECTIONS_SENT, DESCRIBER_WORDS, DIALOGUE_MODES, DIALOGUE_SCORES,
                            ES_AT_1, ES_AT_N, FIRST_SUCCESS_ROUND, QUESTIONS_ASKED, ROUND_PREFIX, round_score)

from . import charts
from .files import markdown_table, mean, number, percent, write_csv

HEADER = ["model", "game", "experiment", "mode", "questions", "corrections", "episodes", "played", "es_at_1",
          "es_at_n", "f1_at_1", "f1_at_n", "first_success_round", "questions_asked", "corrections_sent",
          "describer_words"]


def dialogue_episodes(episodes: list[dict]) -> list[dict]:
    """The episodes of sartco.report.rows.collect that have dialogue scores, with their dialogue fields."""
    out = []
    for e in episodes:
        scores, exp = e["scores"], e["experiment_fields"]
        if round_score(0) not in scores:
            continue
        rounds = sorted(int(k[len(ROUND_PREFIX):]) for k in scores if k.startswith(ROUND_PREFIX))
        out.append({"model": e["model"], "game": e["game"], "experiment": e["experiment"], "mode": e["mode"],
                    "questions": exp.get("questions", 0) or 0, "corrections": exp.get("corrections", 0) or 0,
                    "aborted": e["aborted"], "rounds": [number(scores[round_score(k)]) for k in rounds],
                    **{name: number(scores.get(name)) for name in DIALOGUE_SCORES}})
    return out


def rows_of(episodes: list[dict]) -> list[dict]:
    groups: dict[tuple, list] = defaultdict(list)
    for e in episodes:
        groups[(e["model"], e["game"], e["experiment"])].append(e)
    rows = []
    for (model, game, experiment), group in sorted(groups.items(), key=lambda kv: (
            kv[0][0], kv[0][1], DIALOGUE_MODES.index(kv[1][0]["mode"]) if kv[1][0]["mode"] in DIALOGUE_MODES else 99, kv[0][2])):
        first = group[0]
        played = [e for e in group if not e["aborted"]]
        rows.append({
            "model": model, "game": game, "experiment": experiment, "mode": first["mode"],
            "questions": first["questions"] if "clarify" in first["mode"] else 0,
            "corrections": first["corrections"] if "correct" in first["mode"] else 0,
            "episodes": len(group), "played": mean([1.0 - e["aborted"] for e in group], pct=True),
            "es_at_1": percent([e[ES_AT_1] for e in group]),
            "es_at_n": percent([e[ES_AT_N] for e in group]),
            "f1_at_1": percent([e[CELL_F1_AT_1] for e in group]),
            "f1_at_n": percent([e[CELL_F1_AT_N] for e in group]),
            "first_success_round": mean([e[FIRST_SUCCESS_ROUND] for e in group]),
            "questions_asked": mean([e[QUESTIONS_ASKED] for e in played]),
            "corrections_sent": mean([e[CORRECTIONS_SENT] for e in played]),
            "describer_words": mean([e[DESCRIBER_WORDS] for e in played]),
        })
    return rows


def curves(episodes: list[dict]) -> dict[tuple[str, str], list[float]]:
    """(model pair, mode) -> mean ES (%, aborted = 0) after round k, over all its experiments."""
    groups: dict[tuple, list] = defaultdict(list)
    for e in episodes:
        groups[(e["model"], e["mode"])].append(e)
    out = {}
    for key in sorted(groups, key=lambda k: (k[0], DIALOGUE_MODES.index(k[1]) if k[1] in DIALOGUE_MODES else 99, k[1])):
        group = groups[key]
        n = max(len(e["rounds"]) for e in group)
        out[key] = [percent([e["rounds"][min(k, len(e["rounds"]) - 1)] for e in group])
                    for k in range(n)]
    return out


def curve_table(lines: dict[tuple[str, str], list[float]]) -> str:
    """The curves as a Markdown table: model, mode, ES after round 0..R (blank past a mode's last round)."""
    n = max(len(values) for values in lines.values())
    return markdown_table(["model", "mode", *(f"round {k}" for k in range(n))],
                          [[model, mode, *values, *[""] * (n - len(values))] for (model, mode), values in lines.items()])


def write(episodes: list[dict], out: Path) -> list[str]:
    """dialogue.md / .csv / dialogue_rounds.svg from the rows of sartco.report.rows.collect."""
    episodes = dialogue_episodes(episodes)
    if not episodes:
        return []
    rows, lines = rows_of(episodes), curves(episodes)
    write_csv(out / "dialogue.csv", HEADER, rows)
    (out / "dialogue_rounds.svg").write_text(charts.line_plot(lines), encoding="utf-8")
    md = ("# cobot_describe as a dialogue (clarification questions, corrections)\n\n"
          "## ES after round k\n\n"
          "The recovery curves: ES (%, aborted = 0) of the board standing after k corrections (round 0 = the "
          "first build), per model and mode over all its experiments.\n\n"
          "![ES after round k](dialogue_rounds.svg)\n\n" + curve_table(lines) + "\n"
          "## Per experiment\n\n"
          "ES@1 / ES@N, F1@1 / F1@N = execution success and cell F1 (%) after the first / the last build "
          "(aborted = 0); K / R = questions / corrections allowed; first success = mean round of the first "
          "success over the episodes that succeeded (0 = the first build); questions, corrections and "
          "describer words = means per played episode.\n\n")
    md += markdown_table(["model", "game", "experiment", "mode", "K", "R", "episodes", "played", "ES@1", "ES@N", "F1@1", "F1@N",
               "first success", "questions", "corrections", "describer words"],
              [[r[h] for h in HEADER] for r in rows])
    (out / "dialogue.md").write_text(md, encoding="utf-8")
    return ["dialogue.md", "dialogue.csv", "dialogue_rounds.svg"]
