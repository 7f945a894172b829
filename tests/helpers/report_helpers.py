"""Result folders written by hand for the report tests (tests/report): one experiment of cobot_instruct, an
episode per entry of `es` (execution success 0/1; EM and cell F1 the same, CodeBLEU 0.5)."""
import json
from pathlib import Path

from sartco.episode import CELL_F1, CODEBLEU, EXACT_MATCH, EXECUTION_SUCCESS


def write_results(root: Path, model: str, es: list[int], experiment: str = "sb_so_first_order_template") -> None:
    exp_dir = root / model / "cobot_instruct" / experiment
    exp_dir.mkdir(parents=True)
    (exp_dir / "experiment.json").write_text(json.dumps({
        "name": experiment, "game_name": "cobot_instruct", "task": "first_order", "board_type": "simple",
        "object_type": "simple", "source": "template", "split": "test"}))
    for k, success in enumerate(es):
        episode = exp_dir / f"instance_{k:05d}"
        episode.mkdir()
        (episode / "scores.json").write_text(json.dumps({"episode scores": {
            EXECUTION_SUCCESS: success, EXACT_MATCH: success, CODEBLEU: 0.5, CELL_F1: success, "Aborted": 0}}))
