"""Both games have a smoke file (issue 44): the first episodes of each experiment of the game's
instances.json, written by the generator byte for byte as committed."""
from __future__ import annotations

import argparse
import json
from pathlib import Path

import pytest

from sartco.games.describe import instancegenerator as describe
from sartco.games.instruct import instancegenerator as instruct
from sartco.instancegen.options import DEFAULTS

REPO = Path(__file__).resolve().parents[2]


@pytest.mark.parametrize("game, write", [("cobot_instruct", instruct.instances_smoke),
                                         ("cobot_describe", describe.instances_smoke)])
def test_the_smoke_file_is_the_first_episodes_and_regenerates_byte_for_byte(tmp_path, game, write):
    committed = REPO / "games" / game / "in" / "instances_smoke.json"
    smoke, whole = (json.loads((REPO / "games" / game / "in" / f"{n}.json").read_text())
                    for n in ("instances_smoke", "instances"))
    assert [e["name"] for e in smoke["experiments"]] == [e["name"] for e in whole["experiments"]]
    for mine, theirs in zip(smoke["experiments"], whole["experiments"]):
        assert mine["game_instances"] == theirs["game_instances"][:DEFAULTS["smoke"]]
    (tmp_path / "in").mkdir()
    options = argparse.Namespace(**{**DEFAULTS, "dataset": REPO / "instances" / "v1"})
    written = Path(write(options, tmp_path))
    assert written.read_bytes() == committed.read_bytes()
