"""clem as a clembench user runs it, outside this repository: from a folder of their own (or a
clembench checkout) with their own model_registry.json, which does not mention `rulebased`, and a
game_registry.json pointing at our games. The packaged backend and model entry
(sartco.clem.packaged, installed with sartco) still give `-m rulebased`; nothing is written into
the user's folder but clemcore's results and log."""
import json
import subprocess
import sys
from pathlib import Path

import pytest

REPO = Path(__file__).resolve().parents[2]
CLEM = str(Path(sys.executable).parent / "clem")
USER_MODELS = [{"model_name": "my-model", "model_id": "my-model", "backend": "openai_compatible"}]
EXPERIMENT = "sb_so_optimal_function_template"


def clem(*args, cwd):
    done = subprocess.run([CLEM, *args], cwd=cwd, capture_output=True, text=True, timeout=600)
    assert done.returncode == 0, f"clem {' '.join(args)} failed:\n{done.stdout[-2000:]}\n{done.stderr[-2000:]}"
    return done.stdout


@pytest.fixture
def user_dir(tmp_path):
    """A clembench checkout: a game of its own below the folder (so clemcore ignores
    CLEMBENCH_HOME), the user's model registry, no file of ours."""
    (tmp_path / "games" / "othergame").mkdir(parents=True)
    (tmp_path / "games" / "othergame" / "clemgame.json").write_text(json.dumps(
        {"game_name": "othergame", "players": 1, "benchmark": ["x"], "instances": "instances"}))
    (tmp_path / "model_registry.json").write_text(json.dumps(USER_MODELS))
    return tmp_path


def play_and_score(user_dir, model):
    clem("run", "-g", "cobot_instruct", "-m", model, "-i", "instances_smoke", "-e", EXPERIMENT, "-r", "res",
         cwd=user_dir)
    clem("score", "-g", "cobot_instruct", "-r", "res", cwd=user_dir)
    files = sorted((user_dir / "res").rglob("scores.json"))
    return [json.loads(f.read_text())["episode scores"]["Main Score"] for f in files]


def test_rulebased_beside_the_users_registry(user_dir):
    (user_dir / "game_registry.json").write_text(json.dumps([{"benchmark_path": str(REPO / "games")}]))
    listing = clem("list", "models", cwd=user_dir)
    assert "my-model -> openai_compatible" in listing and "rulebased -> rulebased (sartco)" in listing
    assert play_and_score(user_dir, "rulebased") == [100.0, 100.0]
    assert json.loads((user_dir / "model_registry.json").read_text()) == USER_MODELS  # untouched
    assert sorted(p.name for p in user_dir.iterdir()) == [
        "clembench.log", "game_registry.json", "games", "model_registry.json", "res"]


def test_game_path_entry(user_dir):
    spec = json.loads((REPO / "games" / "cobot_instruct" / "clemgame.json").read_text())[0]
    (user_dir / "game_registry.json").write_text(json.dumps(
        [dict(spec, game_path=str(REPO / "games" / "cobot_instruct"))]))
    assert play_and_score(user_dir, "mock") == [100.0, 100.0]


def test_users_entry_of_the_same_name_wins(tmp_path, monkeypatch):
    """The working directory comes first, as in clemcore: a user's own `rulebased` entry is used."""
    from clemcore.backends import BackendRegistry, ModelRegistry
    (tmp_path / "model_registry.json").write_text(json.dumps([{"model_name": "rulebased", "backend": "mine"}]))
    monkeypatch.chdir(tmp_path)
    registry = ModelRegistry.from_packaged_and_cwd_files()
    entries = [(s.backend, s.lookup_source) for s in registry if s.model_name == "rulebased"]
    assert entries == [("mine", str(tmp_path / "model_registry.json")), ("rulebased", "sartco")]
    backend = BackendRegistry.from_packaged_and_cwd_files().get_backend_for("rulebased")
    assert type(backend).__name__ == "RulebasedBackend"
