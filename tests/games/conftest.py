"""Play cobot_instruct episodes through clemcore's real loop (GameBenchmark, GameMasterEnv,
the sequential runner, the file-saving callbacks, the game's scorer) in-process."""
from __future__ import annotations

import json
from pathlib import Path

REPO = Path(__file__).resolve().parents[2]
GAME_DIR = REPO / "games" / "cobot_instruct"


def play(instances: list[dict], experiment: dict, results_dir: Path, model: str = "mock",
         game: str = "cobot_instruct", gen_args: dict | None = None) -> list[dict]:
    """Run the instances as one experiment of a game entry of games/cobot_instruct/clemgame.json;
    return, per instance, {"interactions", "scores"}."""
    from clemcore import backends
    from clemcore.clemgame import (ExperimentFileSaver, GameBenchmark, GameBenchmarkCallbackList, GameInstances,
                                   GameSpec, InstanceFileSaver, InteractionsFileSaver, ResultsFolder)
    from clemcore.clemgame.runners import sequential

    spec = next(s for s in GameSpec.from_directory(str(GAME_DIR)) if s.game_name == game)
    models = backends.load_models([model], gen_args or dict(temperature=0.0, max_tokens=300))
    folder = ResultsFolder(Path(results_dir), run_dir=backends.Model.to_identifier(models))
    infos = backends.Model.to_infos(models)
    callbacks = GameBenchmarkCallbackList([
        InstanceFileSaver(folder), ExperimentFileSaver(folder, player_model_infos=infos),
        InteractionsFileSaver(folder, player_model_infos=infos),
    ])
    rows = [{"game_name": spec.game_name, "experiment": experiment, "game_instance": inst} for inst in instances]
    with GameBenchmark.load_from_spec(spec) as bench:
        sequential.run(bench, GameInstances(spec.game_name, rows), models, callbacks=callbacks)
        files = sorted(Path(results_dir).rglob("interactions.json"))
        bench.compute_scores(files)
    out = []
    for inst in instances:
        d = Path(results_dir) / folder.run_dir / spec.game_name / experiment["name"] / f"instance_{inst['game_id']:05d}"
        out.append({"interactions": json.loads((d / "interactions.json").read_text()),
                    "scores": json.loads((d / "scores.json").read_text().replace("NaN", "null")),
                    "dir": d})
    return out


import pytest  # noqa: E402


@pytest.fixture
def play_episodes(tmp_path):
    """play_episodes(instances, experiment, model="mock", game="cobot_instruct", gen_args=None)
    -> results per instance."""
    def _play(instances, experiment, model="mock", **kwargs):
        return play(instances, experiment, tmp_path / "results", model, **kwargs)
    return _play
