"""The tables of report.html beside the cells x models table of sartco.report.html, one per Markdown
table of `sartco report` that has them: the dialogue modes' cells x models with ES by round
(dialogue.md), the paper protocol beside the paper's own figures (paper_table3.md), the ablations
(ablations.md) and the repair after execution feedback (repair.md). The same figures as the
Markdown tables, computed by the same functions; every text escaped (model names are folder names).

sections(episodes, ablation_rows, repair_rows) -> {game: [HTML]} for sartco.report.html.write.
"""
from __future__ import annotations

from collections import defaultdict

from . import dialogue_table, harness_table, paper_table
from .charts import esc
from .completeness import INCOMPLETE_MARK
from .intervals import shown


def grid(head: list[str], lines: dict[tuple, dict[str, str]], models: list[str], cls: str) -> str:
    """A table: the key columns `head`, then a column per model (cell HTML; "not run" when absent)."""
    out = [f"<table class='{cls}'><tr>" + "".join(f"<th>{esc(h)}</th>" for h in head)
           + "".join(f"<th>{esc(m)}</th>" for m in models) + "</tr>"]
    for key, by_model in lines.items():
        out.append("<tr>" + "".join(f"<td>{esc(v)}</td>" for v in key) + "".join(
            f"<td>{by_model[m]}</td>" if m in by_model else "<td class='notrun'>not run</td>" for m in models) + "</tr>")
    return "\n".join(out) + "</table>\n"


def dialogue(episodes: list[dict]) -> dict[str, str]:
    """game -> its dialogue experiments x models: ES@1, ES@N, cell F1 and ES after each round (%)."""
    eps = [e for e in dialogue_table.dialogue_episodes(episodes) if e["mode"] != "oneshot"]  # the cells table has it
    groups: dict[tuple, list] = defaultdict(list)
    for e in eps:
        groups[(e["model"], e["game"], e["experiment"])].append(e)
    by_game: dict[str, dict[tuple, dict]] = defaultdict(dict)
    for r in dialogue_table.rows_of(eps):
        [curve] = dialogue_table.curves(groups[(r["model"], r["game"], r["experiment"])]).values()
        key = (r["experiment"], r["mode"], r["questions"], r["corrections"])
        by_game[r["game"]].setdefault(key, {})[r["model"]] = (
            f"ES@1 {r['es_at_1']:.1f} · ES@N {r['es_at_n']:.1f}<br>F1@1 {r['f1_at_1']:.1f} · F1@N {r['f1_at_n']:.1f}"
            f"<br><span class='rounds'>ES by round: {' → '.join(f'{v:.0f}' for v in curve)}</span>"
            f"<br><small>n = {r['episodes']}</small>")
    return {game: ("<h3>Dialogue modes x models: ES and cell F1 (%) after the first / the last build, ES after each "
                   "round (K questions, R corrections allowed; aborted = 0)</h3>"
                   + grid(["experiment", "mode", "K", "R"], lines, sorted({m for by in lines.values() for m in by}),
                          "dialogue")) for game, lines in by_game.items()}


def paper(episodes: list[dict]) -> dict[str, str]:
    """game -> Table 3 in the paper protocol: the paper's EM / CB / ES (shares 0..1), then each model's."""
    rows = paper_table.paper_episodes(episodes)
    if not rows:
        return {}
    table3 = paper_table.load_table3(paper_table.TABLE3)
    notes = paper_table.settings_note(rows, paper_table.generation(table3))
    _, long_rows = paper_table.table(table3, rows)
    lines: dict[tuple, dict] = {}
    models: list[str] = []
    for r in long_rows:
        label = paper_table.column_label(r, notes)
        models += [label] if label not in models else []
        key = (r["instructions"], r["board"], r["object"], f"{r['task']} ({r['variant']})", r["source"])
        lines.setdefault(key, {})[label] = " / ".join(paper_table.shown_score(r, m) for m in paper_table.PAPER_SCORES)
    note = "".join(f"<p>{paper_table.FLAG} {esc(m)}: {esc(why)} (not comparable with the paper)</p>"
                   for m, why in sorted(notes.items()))
    games = {e["game"] for e in episodes if paper_table.is_paper_episode(e)}
    html = ("<h3>Table 3 in the paper protocol: EM / CB / ES (shares 0..1) as the paper measured them; the paper's "
            "figures first, then these results (scored by the authors' rules only)</h3>"
            + grid(["instructions", "board", "object", "task", "source"], lines, models, "paper") + note)
    return dict.fromkeys(games, html)


def ablations(rows: list[dict]) -> dict[str, str]:
    """game -> the val-split ablations x models: EM / CB / ES (%) with their intervals."""
    by_game: dict[str, dict[tuple, dict]] = defaultdict(dict)
    for r in rows:
        key = (r["board_type"], r["object_type"], r["task"], r["source"], r["ablation"], r["value"])
        mark = INCOMPLETE_MARK if r["episodes_scored"] < r["episodes_expected"] else ""
        by_game[r["game"]].setdefault(key, {})[r["model"]] = "<br>".join(
            f"{name} {shown(r, x)}{mark}" for name, x in (("EM", "em"), ("CB", "cb"), ("ES", "es")))
    return {game: "<h3>Ablations (val split) x models: EM / CB / ES (%) with 95 % bootstrap intervals</h3>" + grid(
        ["board", "object", "task", "source", "ablation", "value"], lines,
        sorted({m for by in lines.values() for m in by}), "ablations") for game, lines in by_game.items()}


def repair(rows: list[dict]) -> dict[str, str]:
    """game -> the feedback experiments x models: ES@1, ES@N (%), repaired share, mean attempts."""
    by_game: dict[str, dict[tuple, dict]] = defaultdict(dict)
    for r in rows:
        by_game[r["game"]].setdefault((r["experiment"], r["feedback_of"], r["attempts"]), {})[r["model"]] = (
            f"ES@1 {r['es_at_1']:.1f} · ES@N {r['es_at_n']:.1f}<br>repaired {r['repaired']} of {r['first_failures']} "
            f"({r['repaired_share']:.1f} %)<br><small>n = {r['episodes']}; mean attempts {r['mean_attempts']}</small>")
    return {game: "<h3>Repair after execution feedback x models (N attempts)</h3>" + grid(
        ["experiment", "of", "N"], lines, sorted({m for by in lines.values() for m in by}), "repair")
        for game, lines in by_game.items()}


def sections(episodes: list[dict], ablation_rows: list[dict], repair_rows: list[dict]) -> dict[str, list[str]]:
    """game -> the HTML tables above, in this order (harness-error episodes left out, as in the Markdown)."""
    measured = [e for e in episodes if not harness_table.is_harness(e)]
    out: dict[str, list[str]] = defaultdict(list)
    for part in (paper(measured), dialogue(measured), ablations(ablation_rows), repair(repair_rows)):
        for game, html in part.items():
            out[game].append(html)
    return out
