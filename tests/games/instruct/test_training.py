"""SARTCo as a training environment: the train split instance file and clemcore's gym env over
it (sartco.games.instruct.training), driven by a scripted policy: observations, rewards, info, episode ends."""
import json
from argparse import Namespace
from pathlib import Path

import pytest

from play_helpers import REPO
from sartco.clem.core.building import CONTEXT_KEY
from sartco.games.instruct.training import gym_env
from sartco.instancegen.command import generate
from sartco.instancegen.options import DEFAULTS

GAME_DIR = REPO / "games" / "cobot_instruct"


@pytest.fixture(scope="module")
def train_file(tmp_path_factory):
    """A small train instance file (2 episodes per cell), written outside the repository."""
    folder = tmp_path_factory.mktemp("train")
    [path] = generate("instruct-train", Namespace(**{**DEFAULTS, "train_episodes": 2}), game_dir=folder)
    return Path(path)


def test_train_split_is_its_own_file_of_train_boards(train_file):
    data = json.loads(train_file.read_text())
    names = [e["name"] for e in data["experiments"]]
    assert names == ["sb_so_first_order_template_train", "sb_so_sequence_function_template_train",
                     "sb_so_optimal_function_template_train", "rb_so_repetition_template_train",
                     "rb_co_repetition_template_train"]
    train_ids = set()
    for name in ("simple_simple_train", "regular_simple_train", "regular_complex_train"):
        train_ids |= {r["id"] for r in json.loads((REPO / "instances" / "v1" / f"{name}.json").read_text())}
    test_ids = {i["board_id"] for e in json.loads((GAME_DIR / "in" / "instances.json").read_text())["experiments"]
                for i in e["game_instances"]}
    for exp in data["experiments"]:
        assert exp["split"] == "train" and exp["source"] == "template" and len(exp["game_instances"]) == 2
        for inst in exp["game_instances"]:
            assert inst["board_id"] in train_ids and inst["board_id"] not in test_ids
            assert inst["board_id"] not in inst["examples"]  # never its own board as an example
    # the same seed gives the same file
    [again] = generate("instruct-train", Namespace(**{**DEFAULTS, "train_episodes": 2}),
                       game_dir=train_file.parents[1] / "again")
    assert Path(again).read_bytes() == train_file.read_bytes()


def episodes_of(train_file):
    data = json.loads(train_file.read_text())
    return [i for e in data["experiments"] for i in e["game_instances"]]


def wrong(code: str) -> str:
    """The gold code with its last put's colour changed: a partly right board."""
    lines = code.rstrip().splitlines()
    last = max(k for k, line in enumerate(lines) if "put(" in line or "(board" in line)
    for a, b in (("'red'", "'blue'"), ("'blue'", "'red'"), ("'green'", "'yellow'"), ("'yellow'", "'green'")):
        if a in lines[last]:
            lines[last] = lines[last].replace(a, b, 1)
            break
    return "\n".join(lines)


@pytest.mark.parametrize("reward", ["es", "cell_f1"])
def test_gym_env_with_a_scripted_policy(train_file, reward):
    """The first six train episodes in file order: two first-order ones (one step per
    instruction), then function tasks (one step); gold, wrong (last answer), no code, ..."""
    episodes = episodes_of(train_file)
    policies = ["gold", "wrong", "no code", "gold", "wrong", "gold"]
    env = gym_env(instances=str(train_file.with_suffix("")), reward=reward, single_pass=True)
    try:
        for policy, episode in zip(policies, episodes):
            observation, info = env.reset()
            rewards, infos, steps, done = [], [], 0, False
            while not done:
                assert observation["role"] == "user"
                assert observation["content"].endswith(episode["turns"][steps])  # this turn's instruction
                gold = episode["gold_turns"][steps]
                if policy == "no code":
                    answer = "I am not sure how to do this."
                elif policy == "wrong" and steps == len(episode["turns"]) - 1:
                    answer = f"```python\n{wrong(gold)}\n```"
                else:
                    answer = f"```python\n{gold}\n```"
                observation, r, done, truncated, info = env.step(answer)
                assert not truncated
                rewards.append(r)
                infos.append(info)
                steps += 1
            assert steps == (1 if policy == "no code" else len(episode["turns"]))
            assert all(i == {} for i in infos[:-1]) and all(x == 0.0 for x in rewards[:-1])
            final = infos[-1]
            assert set(final) >= {"es", "cell_f1", "error_category", "puts"}
            # the last observation carries the same scores (what clem serve passes on: sartco.clem.core.building)
            assert observation[CONTEXT_KEY] == {k: final[k] for k in ("es", "cell_f1", "error_category", "puts")}
            if policy == "gold":
                assert (final["es"], final["cell_f1"], final["error_category"]) == (1, 1.0, "success")
                assert rewards[-1] == 1.0 and final["puts"] > 0
            elif policy == "wrong":
                assert final["es"] == 0 and final["error_category"] == "mismatch_color" and 0 < final["cell_f1"] < 1
                assert rewards[-1] == (0.0 if reward == "es" else final["cell_f1"])
            else:
                assert (final["es"], final["cell_f1"], final["error_category"], final["puts"]) == \
                    (0, 0.0, "parse_error", 0)
                assert rewards[-1] == 0.0
        assert len(episodes) > 1 and episodes[0]["task"] == "first_order" and len(episodes[0]["turns"]) > 1
    finally:
        env.close()


def test_unknown_reward():
    with pytest.raises(ValueError, match="unknown reward"):
        gym_env(reward="bleu")
