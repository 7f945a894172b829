"""Table 1 by enumeration, and the command forms of issue 3."""
import json

import pytest

from sartco.cli import main
from sartco.instances.stats import table


def test_table_1(v1_config):
    t = table(v1_config)
    assert len(t["seeds"]) == 18
    assert t["objects"] == 68
    assert t["objects_by_components"] == {"2": 7, "3": 15, "4": 28, "5": 18}
    assert t["colored_objects"] == 38088
    assert t["boards"] == {"simple_simple": 152352, "regular_simple": 45984, "regular_complex": 140904}
    assert sum(s["colored_objects"] for s in t["seeds"].values()) == 38088


def test_stats_json_command(capsys):
    assert main(["stats", "--json"]) == 0
    out = json.loads(capsys.readouterr().out)
    assert out["objects"] == 68 and out["boards"]["regular_simple"] == 45984
    assert set(out["seeds"]) >= {"twoshapes_seed1", "fiveshapes_seed3"}


def test_stats_table_command(capsys):
    assert main(["stats"]) == 0
    out = capsys.readouterr().out
    assert "152,352" in out and "45,984" in out and "140,904" in out


@pytest.mark.parametrize("edit, field", [
    (lambda c: c.update(format="x"), "format"),
    (lambda c: c["splits"]["simple_simple"]["val"].update(size=-1), "splits.simple_simple.val.size"),
    (lambda c: c["splits"]["simple_simple"]["val"].update(quadrants=["tl"]), "splits.simple_simple.val.quadrants"),
    (lambda c: c.update(seeds=["no_such_seed"]), "seeds"),
    (lambda c: c["arrangements"].update(regular_simple=["regular_seed99"]), "arrangements.regular_simple"),
    (lambda c: c.update(colors=["red", "black"]), "colors"),
])
def test_bad_config_is_one_line(tmp_path, capsys, edit, field):
    import yaml
    ROOT = __import__("pathlib").Path(__file__).resolve().parents[2]
    config = yaml.safe_load((ROOT / "resources" / "v1.yaml").read_text())
    edit(config)
    path = tmp_path / "bad.yaml"
    path.write_text(yaml.safe_dump(config))
    assert main(["generate", "--config", str(path), "--seed", "1", "--out", str(tmp_path / "o")]) == 2
    err = capsys.readouterr().err.strip()
    assert "\n" not in err and str(path) in err and f"'{field}'" in err and "expected" in err


def test_missing_config(tmp_path, capsys):
    assert main(["stats", "--config", str(tmp_path / "none.yaml")]) == 2
    assert "none.yaml" in capsys.readouterr().err
