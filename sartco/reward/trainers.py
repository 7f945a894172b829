"""The reward API in the trainers' own interfaces (issue 36 item 3).

TRL: `grpo_reward(...)` is a reward function as `trl.GRPOTrainer(reward_funcs=...)` calls it:
`f(prompts, completions, **columns) -> list[float | None]`, over a dataset of `sartco
export-dataset` rows (the columns `id` and `episode` reach it as keyword arguments). A
completion is TRL's: a text, or the assistant's messages (conversational prompts: the last
message's content). The rewards are those of sartco.reward.score: "es" (default) or "cell_f1";
None for a harness_error (the sandbox failed, not the model: TRL leaves it out of the mean).
Single-turn rows only (`turns == 1`): a completion answers the first turn, and a first_order
episode of several turns is played through the gym environment (sartco.clem.instruct.training).
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
