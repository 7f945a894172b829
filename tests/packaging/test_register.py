"""`sartco register` and `sartco games` (sartco.register): clemcore's own files, merged into the
user's without overwriting or reordering their entries; a second run changes nothing."""
from __future__ import annotations

import json
from pathlib import Path

import pytest

from sartco.errors import UserError
from sartco.register import install_games, register

REPO = Path(__file__).resolve().parents[2]


def snapshot(folder: Path) -> dict[str, bytes]:
    return {str(p.relative_to(folder)): p.read_bytes() for p in sorted(folder.rglob("*")) if p.is_file()}


def test_register_appends_after_the_users_entries_and_is_idempotent(tmp_path):
    users = [{"model_name": "zeta", "backend": "openai_compatible"}, {"model_name": "erring", "backend": "mine"},
             {"model_name": "alpha", "backend": "openai_compatible", "model_config": {"x": 1}}]
    (tmp_path / "model_registry.json").write_text(json.dumps(users))
    lines = register(tmp_path)
    assert [line.split(": ", 1)[1] for line in lines] == ["written", "written", "added rulebased"]
    entries = json.loads((tmp_path / "model_registry.json").read_text())
    assert entries[:3] == users and [e["model_name"] for e in entries[3:]] == ["rulebased"]
    for name in ("rulebased_api.py", "openai_batching_api.py"):
        text = (tmp_path / name).read_text()
        assert text.startswith("# written by `sartco register`") and "\nfrom sartco.clem." in text
    before = snapshot(tmp_path)
    assert register(tmp_path) == [] and snapshot(tmp_path) == before


def test_a_users_backend_file_of_the_same_name_is_kept(tmp_path, capsys):
    (tmp_path / "rulebased_api.py").write_text("# mine\n")
    register(tmp_path)
    assert (tmp_path / "rulebased_api.py").read_text() == "# mine\n"
    assert "rulebased_api.py exists and differs: kept" in capsys.readouterr().err


def test_the_backend_files_load_in_clemcore(tmp_path, monkeypatch):
    from clemcore.backends import BackendRegistry
    register(tmp_path)
    (tmp_path / "key.json").write_text(json.dumps({"openai_compatible": {"api_key": "none",
                                                                         "base_url": "http://127.0.0.1:9/v1"}}))
    monkeypatch.chdir(tmp_path)
    backends = BackendRegistry.from_packaged_and_cwd_files()
    assert type(backends.get_backend_for("rulebased")).__name__ == "RulebasedBackend"
    assert type(backends.get_backend_for("openai_batching")).__name__ == "OpenAIBatchingBackend"


def test_games_go_outside_the_working_directory_and_into_its_game_registry(tmp_path):
    work, games = tmp_path / "work", tmp_path / "games"
    work.mkdir()
    theirs = [{"game_name": "othergame", "game_path": "/x"}]
    (work / "game_registry.json").write_text(json.dumps(theirs))
    install_games(games, work)
    entries = json.loads((work / "game_registry.json").read_text())
    assert entries[0] == theirs[0]
    paths = {e["game_name"]: e["game_path"] for e in entries[1:]}
    assert paths["cobot_instruct_feedback"] == str(games / "cobot_instruct")
    assert paths["cobot_describe_dialogue"] == str(games / "cobot_describe")
    for game in ("cobot_instruct", "cobot_describe"):
        assert (games / game / "in").is_dir()
        for name in ("clemgame.json", "master.py", "instancegenerator.py"):
            assert (games / game / name).read_bytes() == (REPO / "games" / game / name).read_bytes()
    before = snapshot(tmp_path)
    assert install_games(games, work) == [] and snapshot(tmp_path) == before


def test_games_inside_the_working_directory_are_refused(tmp_path):
    with pytest.raises(UserError, match="would list each twice"):
        install_games(tmp_path / "games", tmp_path)
    assert list(tmp_path.iterdir()) == []


def test_a_malformed_game_registry_stops_before_anything_is_written(tmp_path):
    work = tmp_path / "work"
    work.mkdir()
    (work / "game_registry.json").write_text('{"benchmark_path": "x"}')
    with pytest.raises(UserError, match="expected a JSON list"):
        install_games(tmp_path / "games", work)
    assert not (tmp_path / "games").exists()
