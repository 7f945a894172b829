"""Paths, readers and episodes shared by the paper-protocol tests (tests/paper, tests/protocols,
tests/games/instruct/test_paper_protocol.py, tests/games/test_score_card.py)."""
import json
from pathlib import Path

from sartco.games.instruct.paper import experiment_fields, instance_fields

ROOT = Path(__file__).resolve().parents[2]
DATA = ROOT.parent / "shared" / "sartco-data"
PUBLISHED = DATA / "published"
PROTOCOL_DIR = DATA / "paper-protocol"
GENERATED = ROOT / "instances" / "v1"


def read_json(path: Path):
    return json.loads(path.read_text(encoding="utf-8"))


PAPER_GAME = "cobot_instruct_paper"
PAPER_SETTINGS = {"temperature": 0.0, "max_tokens": 250}
VARIANTS = ["multi_turn", "single_turn_sc", "single_turn", "single_turn_hai", "regular", "regular_hai"]


def instances(episodes, scripts=None):
    out = []
    for game_id, ep in enumerate(episodes):
        inst = {"game_id": game_id, **instance_fields(ep)}
        if scripts and scripts[game_id] is not None:
            inst["script"] = scripts[game_id]
        out.append(inst)
    return out


def experiment(ep, name):
    return {"name": name, **experiment_fields(ep)}
