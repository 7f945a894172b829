"""`sartco export-dataset` (sartco.reward.dataset) against the game: the exported prompt is what a
model playing the episode receives in its first turn; the files load with Hugging Face `datasets`
and give back the episodes the reward API scores. `sartco bench-reward` prints its figures."""
from __future__ import annotations

import json
import re
from copy import deepcopy

import pytest

from play_helpers import GAMES
from sartco.cli import main
from sartco.reward import Episodes, score

SMOKE = GAMES / "cobot_instruct" / "in" / "instances_smoke.json"


@pytest.fixture(scope="module")
def exported(tmp_path_factory):
    out = tmp_path_factory.mktemp("dataset")
    assert main(["export-dataset", "--instances", str(SMOKE), "--out", str(out), "--parquet"]) == 0
    return out


def played_first_turns() -> list[list[dict]]:
    """The messages a model receives in the first turn of every smoke episode, in file order:
    each episode played through clemcore's runner by a model that records its input and answers
    without code (the episode ends there)."""
    from clemcore.backends import Model, ModelSpec
    from clemcore.clemgame import GameBenchmark, GameBenchmarkCallbackList, GameInstances, GameSpec
    from clemcore.clemgame.runners import sequential

    class Recorder(Model):
        def __init__(self):
            super().__init__(ModelSpec(model_name="recorder"))
            self.set_gen_args(temperature=0.0, max_tokens=300)
            self.seen = []

        def generate_response(self, messages):
            self.seen.append(deepcopy(messages))
            return messages, {}, "I will not write code."

    spec = next(s for s in GameSpec.from_directory(str(GAMES / "cobot_instruct")) if s.game_name == "cobot_instruct")
    recorder = Recorder()
    rows = [{"game_name": spec.game_name, "experiment": {k: v for k, v in e.items() if k != "game_instances"},
             "game_instance": instance}
            for e in json.loads(SMOKE.read_text())["experiments"] for instance in e["game_instances"]]
    with GameBenchmark.load_from_spec(spec) as bench:
        sequential.run(bench, GameInstances(spec.game_name, rows), [recorder], callbacks=GameBenchmarkCallbackList())
    return recorder.seen


def test_the_exported_prompt_is_what_the_game_sends_in_its_first_turn(exported):
    rows = [json.loads(line) for line in (exported / "instances_smoke.jsonl").read_text().splitlines()]
    seen = played_first_turns()
    assert len(rows) == len(seen) == 10
    for row, messages in zip(rows, seen):
        assert row["prompt"] == messages, row["id"]
    assert rows[0]["id"] == "sb_so_first_order_template/simple_simple_test_0000/first_order"
    assert [r["turns"] for r in rows[:2]] == [2, 2] and {r["turns"] for r in rows[2:]} == {1}


def test_the_files_load_with_datasets_and_give_back_the_episodes(exported):
    datasets = pytest.importorskip("datasets")
    from_files = Episodes.from_files([SMOKE])
    for kind in ("json", "parquet"):
        suffix = "jsonl" if kind == "json" else kind
        ds = datasets.load_dataset(kind, data_files=str(exported / f"instances_smoke.{suffix}"), split="train")
        assert ds.column_names == ["id", "prompt", "turns", "experiment", "game_id", "board_id", "task",
                                   "board_type", "object_type", "source", "split", "episode"]
        episodes = Episodes.from_rows(ds)
        assert dict(episodes) == dict(from_files)
    gold = [(row["id"], json.loads(row["episode"])["gold_turns"]) for row in ds]
    rewards = score([(key, [f"```python\n{code}\n```" for code in answers]) for key, answers in gold], episodes)
    assert [r.es for r in rewards] == [1] * 10


def test_bad_rows_and_missing_files_are_named(tmp_path, capsys):
    with pytest.raises(ValueError, match="row 1: not a row of sartco export-dataset"):
        Episodes.from_rows([{"id": "a", "episode": '{"turns": ["put a nut"]}'}, {"id": "b"}])
    with pytest.raises(ValueError, match=r"row 0: .* no cobot_instruct instance \(no 'turns'\)"):
        Episodes.from_rows([{"id": "a", "episode": "{}"}])
    assert main(["export-dataset", "--out", str(tmp_path / "out")]) == 2
    assert "instances_train.json: no such instance file (write it with `sartco instances instruct-train`)" \
        in capsys.readouterr().err
    assert not (tmp_path / "out").exists()


def test_bench_reward_prints_rewards_per_second(capsys):
    assert main(["bench-reward", "--instances", str(SMOKE), "--repeat", "1", "--batch", "4"]) == 0
    out = capsys.readouterr().out.splitlines()
    assert out[0].startswith("sartco bench-reward: 10 episodes of ")
    assert out[1].startswith("gold probe draws (once per episode, kept): 6 episodes in ")
    kinds = [line.split()[0] + " " + line.split()[1] for line in out[3:7]]
    assert kinds == ["erring, single-turn", "gold, single-turn", "erring, multi-turn", "gold, multi-turn"]
    assert out[-3].startswith("single-turn answers, all: ") and "rewards/s with probes" in out[-3]
    assert re.fullmatch(r"  at the CPU these rewards took, \d+ CPUs fully used would give at most [\d,]+ with "
                        r"probes, [\d,]+ without", out[-2]), out[-2]
    # the CPU in its parts, with probes / without: they add up to the single-turn rows' CPU column
    parts = re.fullmatch(r"  that CPU, ms per reward with probes / without: this process (.+), templates (.+), "
                         r"zygotes (.+), programs' processes (.+)", out[-1])
    assert parts, out[-1]
    rows = [re.fullmatch(r"\S+, single-turn +(\d+) +[\d,]+ \(([\d.]+)\), +[\d,]+ \(([\d.]+)\)", line)
            for line in out[3:5]]
    assert all(rows), out[3:5]
    for k in (0, 1):
        split = [float(part.split(" / ")[k]) for part in parts.groups()]
        whole = sum(int(r[1]) * float(r[2 + k]) for r in rows) / sum(int(r[1]) for r in rows)
        assert abs(sum(split) - whole) < 0.03, (split, whole)
