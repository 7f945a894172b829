"""`sartco compare` on two fixed result sets: the paired differences and the exact McNemar
p-value computed by hand."""
import csv

import pytest

from sartco.cli import main as sartco_main
from sartco.report.compare import mcnemar_p

from report_helpers import write_results


def test_mcnemar_by_hand():
    # b = 5, c = 1: p = 2 * (C(6,0) + C(6,1)) / 2^6 = 14/64
    assert mcnemar_p(5, 1) == pytest.approx(14 / 64)
    assert mcnemar_p(1, 5) == mcnemar_p(5, 1)
    assert mcnemar_p(0, 0) == 1.0 and mcnemar_p(3, 3) == 1.0
    assert mcnemar_p(10, 0) == pytest.approx(2 / 1024)


def test_compare_two_fixed_result_sets(tmp_path):
    results = tmp_path / "results"
    # A solves episodes 0-7, B solves 0-2 and 8: only A 3,4,5,6,7 (b = 5), only B 8 (c = 1)
    write_results(results, "A", [1] * 8 + [0, 0])
    write_results(results, "B", [1, 1, 1, 0, 0, 0, 0, 0, 1, 0] + [1, 1])  # two episodes A lacks: left out
    assert sartco_main(["compare", "-r", str(results), "A", "B", "--out", str(tmp_path / "out")]) == 0
    rows = list(csv.DictReader((tmp_path / "out" / "compare.csv").open()))
    assert [r["experiment"] for r in rows] == ["sb_so_first_order_template", "all"]
    one = rows[0]
    assert int(one["episodes"]) == 10
    assert (int(one["es_only_a"]), int(one["es_only_b"])) == (5, 1)
    assert float(one["mcnemar_p"]) == pytest.approx(14 / 64)
    assert float(one["d_es"]) == 40.0 and float(one["d_cb"]) == 0.0
    assert float(one["d_es_lo"]) < 40.0 < float(one["d_es_hi"])
    assert "40.00 [" in (tmp_path / "out" / "compare.md").read_text()


def test_compare_without_common_episodes(tmp_path, capsys):
    write_results(tmp_path / "results", "A", [1, 0])
    assert sartco_main(["compare", "-r", str(tmp_path / "results"), "A", "C", "--out", str(tmp_path / "out")]) == 2
    assert "no episodes played by both 'A' and 'C'" in capsys.readouterr().err
