"""SARTCo for training: clemcore's gym environment over our games, on the train split, with our reward.

The episodes: cobot_instruct's in/instances_train.json (`python games/cobot_instruct/
instancegenerator.py --train`: one experiment per Table 3 cell, `<cell>_train`, over the
generated train boards; never the test cells). Any instances file of the game can be chosen.

What a step gives (clemcore's GameMasterEnv; observation = the builder's context
{"role": "user", "content": ...}, action = the answer text):
  info    at the episode's last step: `es` (0/1), `cell_f1` (0..1), `error_category` ("success",
          an ErrorCode value, a mismatch category or "parse_error") and `puts` of the final build
          (sartco.clem.core.building.record_build); {} at the other steps (the next instruction of a
          multi-turn episode, the feedback after a failed attempt)
  observation  at the episode's last step the builder's context carries the same four facts under
          "sartco_scores" (sartco.clem.core.building.CONTEXT_KEY), its text unchanged: `clem serve`
          (clemcore's OpenEnv server) sends the observation's context and drops `info`, so a
          trainer reads the scores of a served episode there
  reward  REWARDS[name](observation, action, state, info):
          "es"       (default) execution success of the final build: 1.0 when the built board
                     equals the target, else 0.0 (no code, an error, a wrong board); 0.0 before
                     the last step. The paper's measure.
          "cell_f1"  the dense alternative: cell F1 of the final build against the target
                     (partial credit for partly right boards; 0.0 when nothing ran).
          "outcome"  clemcore's default: 1 success, 0 lost, -1 aborted (no code found).
  done    when the episode ends (after the last instruction's answer, or the last attempt).

    from sartco.games.instruct.training import gym_env
    env = gym_env(reward="cell_f1")           # cobot_instruct, in/instances_train.json
    observation, info = env.reset()
    observation, reward, done, truncated, info = env.step(answer)
"""
from __future__ import annotations

from typing import Callable

from clemcore.clemgame.envs.pettingzoo import (AECToGymWrapper, GameBenchmarkWrapper, GameInstanceIteratorWrapper,
                                               GameMasterEnv, SinglePlayerWrapper)
from clemcore.clemgame.instances import GameInstances
from clemcore.clemgame.registry import GameRegistry
from pettingzoo.utils.wrappers import OrderEnforcingWrapper

GAME = "cobot_instruct"
TRAIN_INSTANCES = "instances_train"


def es_reward(observation: dict, action: str, state, info: dict) -> float:
    return float(info.get("es", 0))


def cell_f1_reward(observation: dict, action: str, state, info: dict) -> float:
    return float(info.get("cell_f1", 0.0))


REWARDS: dict[str, Callable | None] = {
    "es": es_reward,
    "cell_f1": cell_f1_reward,
    "outcome": None,  # clemcore's GameMasterEnv default
}


def gym_env(game: str = GAME, *, instances: str = TRAIN_INSTANCES, reward: str = "es",
            instances_filter: Callable[[dict], bool] | None = None, single_pass: bool = False,
            learner_agent: str = "player_0", env_agents: dict | None = None, callbacks=None):
    """clemcore's `gym_env` (clemcore.clemgame.envs.pettingzoo) for `game`, but over the
    instances file `instances` (a name in the game's in/ folder, or a path without .json: what
    `clem run -i` takes) instead of the game's default file, and with our reward."""
    if reward not in REWARDS:
        raise ValueError(f"unknown reward {reward!r}; choose one of {', '.join(REWARDS)}")
    spec = GameRegistry.from_directories_and_cwd_files().get_game_specs_that_unify_with(game)[0]
    spec.instances = instances  # as `clem run -i` does
    env = GameBenchmarkWrapper(GameMasterEnv, game_spec=spec, callbacks=callbacks, reward_func=REWARDS[reward])
    env = OrderEnforcingWrapper(env)
    env = GameInstanceIteratorWrapper(env, GameInstances.from_game_spec(spec).filter(instances_filter),
                                      single_pass=single_pass)
    env = SinglePlayerWrapper(env, learner_agent, env_agents=env_agents)
    return AECToGymWrapper(env)
