"""clem as a clembench user runs it, outside this repository: from a folder of their own (or a
clembench checkout) with their own model_registry.json, which does not mention `rulebased`, and a
game_registry.json pointing at our games. `sartco register` (sartco.register) adds sartco's model
entries after the user's and writes the backend files; nothing patches clemcore."""
import json
import sys
from pathlib import Path

import pytest

from forkserver import command

REPO = Path(__file__).resolve().parents[3]
CLEM = str(Path(sys.executable).parent / "clem")
SARTCO = str(Path(sys.executable).parent / "sartco")
USER_MODELS = [{"model_name": "my-model", "model_id": "my-model", "backend": "openai_compatible"}]
EXPERIMENT = "sb_so_optimal_function_template"


def clem(*args, cwd):
    done = command([CLEM, *args], cwd=cwd, capture_output=True, text=True, timeout=600)
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


def sartco(*args, cwd):
    return command([SARTCO, *args], cwd=cwd, capture_output=True, text=True, timeout=120)


def test_rulebased_beside_the_users_registry(user_dir):
    (user_dir / "game_registry.json").write_text(json.dumps([{"benchmark_path": str(REPO / "games")}]))
    done = sartco("register", cwd=user_dir)
    assert done.returncode == 0 and "added rulebased, erring" in done.stdout, done.stderr
    listing = clem("list", "models", cwd=user_dir)
    assert "my-model -> openai_compatible" in listing and "rulebased -> rulebased" in listing
    assert play_and_score(user_dir, "rulebased") == [100.0, 100.0]
    entries = json.loads((user_dir / "model_registry.json").read_text())
    assert entries[:1] == USER_MODELS and [e["model_name"] for e in entries[1:]] == ["rulebased", "erring"]
    before = {p.name: p.read_bytes() for p in user_dir.iterdir() if p.is_file()}
    again = sartco("register", str(user_dir), cwd=REPO)
    assert again.returncode == 0 and "already registered" in again.stdout
    assert {p.name: p.read_bytes() for p in user_dir.iterdir() if p.is_file()} == before  # a second run: same files
    # (__pycache__: Python's own cache of the backend files clem imported, unless PYTHONDONTWRITEBYTECODE is set)
    assert sorted(p.name for p in user_dir.iterdir() if p.name != "__pycache__") == [
        "clembench.log", "game_registry.json", "games", "model_registry.json", "openai_batching_api.py", "res",
        "rulebased_api.py"]


def test_game_path_entry(user_dir):
    spec = json.loads((REPO / "games" / "cobot_instruct" / "clemgame.json").read_text())[0]
    (user_dir / "game_registry.json").write_text(json.dumps(
        [dict(spec, game_path=str(REPO / "games" / "cobot_instruct"))]))
    assert play_and_score(user_dir, "mock") == [100.0, 100.0]


def test_users_entry_of_the_same_name_wins(tmp_path, monkeypatch):
    """A user's own `rulebased` entry stays as written (and first); sartco's other entry is added."""
    from clemcore.backends import BackendRegistry, ModelRegistry
    mine = [{"model_name": "rulebased", "backend": "mine"}]
    (tmp_path / "model_registry.json").write_text(json.dumps(mine))
    done = sartco("register", str(tmp_path), cwd=REPO)
    assert done.returncode == 0 and "own entry 'rulebased': kept" in done.stderr
    entries = json.loads((tmp_path / "model_registry.json").read_text())
    assert entries[0] == mine[0] and [e["model_name"] for e in entries] == ["rulebased", "erring"]
    monkeypatch.chdir(tmp_path)
    registry = ModelRegistry.from_packaged_and_cwd_files()
    assert [s.backend for s in registry if s.model_name == "rulebased"] == ["mine"]
    backend = BackendRegistry.from_packaged_and_cwd_files().get_backend_for("rulebased")
    assert type(backend).__name__ == "RulebasedBackend"


@pytest.mark.parametrize("text", ["[{\"model_name\": ", "{\"model_name\": \"x\"}", "[1, 2]"])
def test_a_malformed_registry_is_one_error_and_nothing_is_written(tmp_path, text):
    (tmp_path / "model_registry.json").write_text(text)
    done = sartco("register", str(tmp_path), cwd=REPO)
    assert done.returncode == 2 and len(done.stderr.strip().splitlines()) == 1
    assert "model_registry.json" in done.stderr and "nothing was written" in done.stderr
    assert sorted(p.name for p in tmp_path.iterdir()) == ["model_registry.json"]
    assert (tmp_path / "model_registry.json").read_text() == text


def test_the_checkouts_registration_is_current():
    """The committed model_registry.json and *_api.py at the top of the checkout are what `sartco
    register .` writes: registering the checkout again changes nothing."""
    done = sartco("register", str(REPO), cwd=REPO)
    assert (done.returncode, done.stderr) == (0, "") and "already registered" in done.stdout
