"""dialogue.md's recovery curves (ES after round k per model and mode), computed by hand on synthetic
episodes: the table make main prints and the plot dialogue_rounds.svg draw the same numbers."""
from __future__ import annotations

from sartco.report.dialogue_table import curve_table, curves


def episode(model, mode, rounds):
    return {"model": model, "mode": mode, "rounds": rounds}


def test_curves_average_each_round_and_carry_the_last_board_on():
    lines = curves([episode("erring", "correct", [0.0, 1.0, 1.0, 1.0]),
                    episode("erring", "correct", [0.0, 0.0, 1.0]),      # ended after 2 corrections: carried on
                    episode("erring", "clarify", [1.0]),
                    episode("erring", "clarify", [0.0])])
    assert lines == {("erring", "clarify"): [50.0], ("erring", "correct"): [0.0, 50.0, 100.0, 100.0]}
    table = curve_table(lines).splitlines()
    assert table[0] == "| model | mode | round 0 | round 1 | round 2 | round 3 |"
    assert table[2:] == ["| erring | clarify | 50.00 |  |  |  |",
                         "| erring | correct | 0.00 | 50.00 | 100.00 | 100.00 |"]
