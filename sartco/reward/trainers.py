"""The reward API in the trainers' own interfaces (issue 36 item 3).

TRL: `grpo_reward(...)` is a reward function as `trl.GRPOTrainer(reward_funcs=...)` calls it:
`f(prompts, completions, **columns) -> list[float | None]`, over a dataset of `sartco
export-dataset` rows (the columns `id` and `episode` reach it as keyword arguments). A
completion is TRL's: a text, or the assistant's messages (conversational prompts: the last
message's content). The rewards are those of sartco.reward.score: "es" (default) or "cell_f1";
None for a harness_error (the sandbox failed, not the model: TRL leaves it out of the mean).
Single-turn rows only (`turns == 1`): a completion answers the first turn, and a first_order
episode of several turns is played through the gym environment (sartco.clem.instruct.training).

verl: `compute_score` (verl's `custom_reward_function`, one answer a call: NaiveRewardManager) and
`compute_score_batch` (reward_manager "batch": one sandbox batch a call), below.
verifiers 0.4.0 (requires anthropic>=1.0 against clemcore's <1.0) and OpenRLHF 0.11.2 (requires
flash-attn, built only with CUDA) cannot be installed beside clemcore here: no interface for them.
"""
from __future__ import annotations

from collections.abc import Callable

from .core import Episodes, score

REWARDS = ("es", "cell_f1")


def grpo_reward(reward: str = "es", *, episodes: Episodes | None = None, probes: bool = False) -> Callable:
    """A TRL reward function named `sartco_<reward>` (TRL logs `rewards/sartco_<reward>/mean`).
    `episodes`: the episodes to score against; default: read from the rows' `episode` column as
    they come (kept, so each episode's probe draws are computed once). `probes`: also probe the
    function (costs K more programs per function answer; the reward does not use it)."""
    if reward not in REWARDS:
        raise ValueError(f"unknown reward {reward!r}; choose one of {', '.join(REWARDS)}")
    known = episodes if episodes is not None else Episodes({})

    def sartco_reward(prompts, completions, id, episode=None, **columns) -> list[float | None]:
        if episodes is None:
            if episode is None:
                raise ValueError("the dataset has no 'episode' column (rows of sartco export-dataset), "
                                 "and no episodes were given to grpo_reward")
            known.include({"id": key, "episode": text} for key, text in zip(id, episode))
        texts = [c if isinstance(c, str) else c[-1]["content"] for c in completions]
        results = score(list(zip(id, texts)), known, probes=probes)
        return [None if r.harness_error else float(r.es if reward == "es" else r.cell_f1) for r in results]

    sartco_reward.__name__ = f"sartco_{reward}"
    return sartco_reward


# verl: `custom_reward_function.path` = this file, `name` = compute_score (verl's NaiveRewardManager:
# one answer a call) or compute_score_batch (reward_manager=batch: one batch a call, as sartco scores
# best). A row of verl's dataset: data_source "sartco", reward_model {"ground_truth": the `episode`
# column of sartco export-dataset}, extra_info {"id": the `id` column}.
_VERL_EPISODES = Episodes({})


def compute_score(data_source, solution_str, ground_truth, extra_info=None, reward: str = "es") -> float:
    """verl's reward function: the reward of one decoded answer (sartco.reward.score)."""
    return compute_score_batch([data_source], [solution_str], [ground_truth], [extra_info], reward=reward)[0]


def compute_score_batch(data_sources, solution_strs, ground_truths, extra_infos, reward: str = "es",
                        **_unused) -> list[float]:
    """verl's batch reward function (BatchRewardManager): the rewards of decoded answers, one sandbox batch.
    A harness_error is 0.0 here (verl needs a number)."""
    if reward not in REWARDS:
        raise ValueError(f"unknown reward {reward!r}; choose one of {', '.join(REWARDS)}")
    ids = [(info or {}).get("id") for info in extra_infos]
    if not all(isinstance(i, str) for i in ids):
        raise ValueError("every extra_info needs the episode's 'id' (the id column of sartco export-dataset)")
    keys = [str(i) for i in ids]
    _VERL_EPISODES.include({"id": key, "episode": truth} for key, truth in zip(keys, ground_truths))
    results = score(list(zip(keys, solution_strs)), _VERL_EPISODES, probes=False)
    return [0.0 if r.harness_error else float(r.es if reward == "es" else r.cell_f1) for r in results]
