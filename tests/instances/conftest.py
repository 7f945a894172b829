import json
from pathlib import Path

import pytest

from sartco.instances.config import load_config
from sartco.instances.generate import write_dataset

ROOT = Path(__file__).resolve().parents[2]
PUBLISHED = ROOT.parent / "shared" / "sartco-data" / "published"


@pytest.fixture(scope="session")
def v1_config():
    return load_config(ROOT / "resources" / "v1.yaml")


@pytest.fixture(scope="session")
def dataset(v1_config, tmp_path_factory):
    """A fresh dataset v1, seed 42: folder and file name -> records."""
    out = tmp_path_factory.mktemp("v1")
    write_dataset(v1_config, 42, out)
    manifest = json.loads((out / "manifest.json").read_text())
    return out, {name: json.loads((out / name).read_text()) for name in manifest["files"]}
