"""Paths and readers shared by the paper-protocol tests."""
import json
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
DATA = ROOT.parent / "shared" / "sartco-data"
PUBLISHED = DATA / "published"
PROTOCOL_DIR = DATA / "paper-protocol"
GENERATED = ROOT / "instances" / "v1"


def read_json(path: Path):
    return json.loads(path.read_text(encoding="utf-8"))
