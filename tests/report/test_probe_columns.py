"""Function Generalisation in table3 (sartco.report.tables): the probed cells' FG with its
interval, computed by hand; n/a in the cells without probes."""
import math

from sartco.report import intervals, tables


def episode(task: str, es: float, fg: float | None, probed: bool, aborted: int = 0) -> dict:
    return {"game": "cobot_instruct", "board_type": "simple", "object_type": "simple", "task": task,
            "source": "template", "split": "test", "model": "m", "ablation": None, "max_attempts": 1,
            "mode": "oneshot", "aborted": aborted, "em": es, "cb": es, "es": es, "f1": es, "fg": fg,
            "probed": probed, "experiment_fields": {}}


def test_fg_beside_es_in_table3():
    eps = [episode("optimal_function", 1.0, 1.0, True), episode("optimal_function", 1.0, 0.25, True),
           episode("optimal_function", None, None, True, aborted=1),   # aborted: counts 0, as for ES
           episode("first_order", 1.0, None, False)]
    header, rows = tables.table3(eps)
    assert header[header.index("es"):header.index("fg") + 3] == ["es", "es_lo", "es_hi", "fg", "fg_lo", "fg_hi"]
    optimal = next(r for r in rows if r["task"] == "optimal_function")
    first = next(r for r in rows if r["task"] == "first_order")
    assert optimal["fg"] == round(100 * 1.25 / 3, 2) == 41.67 and optimal["es"] == 66.67
    lo, hi = intervals.interval([1.0, 0.25, 0.0])
    assert (optimal["fg_lo"], optimal["fg_hi"]) == (round(100 * lo, 2), round(100 * hi, 2))
    assert all(math.isnan(first[k]) for k in ("fg", "fg_lo", "fg_hi"))
    md = tables.table3_markdown(rows, "cobot_instruct", ["board_type", "object_type", "task", "source"])
    assert "### cobot_instruct: FG" in md and "| n/a |" in md and f"| {intervals.shown(optimal, 'fg')} |" in md
