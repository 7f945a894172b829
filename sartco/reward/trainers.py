"""The reward API in the trainers' own interfaces (issue 36 item 3), each tested against the real
library by `make test-train` (tests/reward/test_trainers.py; versions: the `train` extra).

TRL: `grpo_reward(...)` is a reward function as `trl.GRPOTrainer(reward_funcs=...)` calls it:
`f(prompts, completions, **columns) -> list[float | None]`, over a dataset of `sartco
export-dataset` rows (the columns `id` and `episode` reach it as keyword arguments). A
completion is TRL's: a text, or the assistant's messages (conversational prompts: the last
message's content). The rewards are those of sartco.reward.score: "es" (default) or "cell_f1";
None for a harness_error (the sandbox failed, not the model: TRL leaves it out of the mean).
Single-turn rows only (`turns == 1`): a completion answers the first turn, and a first_order
episode of several turns is played through the gym environment (sartco.games.instruct.training).

verl: `compute_score` (verl's `custom_reward_function`, one answer a call: NaiveRewardManager) and
`compute_score_batch` (reward_manager "batch": one sandbox batch a call), below.

verifiers (its classic API, `import verifiers as vf`): `load_environment(...)`, found by
`vf.load_environment("sartco.reward.trainers", instances=[...])`: a vf.SingleTurnEnv over the
single-turn episodes whose vf.Rubric has the functions `sartco_es` and `sartco_cell_f1`.

OpenRLHF: `reward_func(queries, prompts, labels)` (`--remote_rm_url` = this file's path) and
`sartco serve-reward` (sartco.reward.serve: `--remote_rm_url http://HOST:PORT/get_reward`), both
over a dataset of `sartco export-dataset` rows read with `--input_key prompt --label_key episode
--apply_chat_template`.

Tested versions (docs/training.md): TRL 1.16.0, verl 0.9.1, verifiers 0.3.1 (0.4.0
requires anthropic>=1.0 against clemcore's <1.0, and dropped this API), OpenRLHF 0.11.2 installed
without its dependencies (flash-attn builds only with CUDA): its reward client runs for real, only
vLLM's generation is stood in for.

A harness_error is 0.0 wherever the trainer needs a number (verl, verifiers, OpenRLHF).
This file is loaded by path as well (verl's custom_reward_function, OpenRLHF's .py form): its
imports are absolute.
"""
from __future__ import annotations

import hashlib
from collections.abc import Callable, Sequence
from pathlib import Path

from sartco.reward.core import Episodes, Reward, score
from sartco.reward.dataset import TRAIN_FILE, rows_of

REWARDS = ("es", "cell_f1")


def checked(reward: str) -> str:
    if reward not in REWARDS:
        raise ValueError(f"unknown reward {reward!r}; choose one of {', '.join(REWARDS)}")
    return reward


def value(result: Reward, reward: str) -> float:
    """The reward a trainer gets: ES (0/1) or cell F1 (0..1)."""
    return float(result.es if reward == "es" else result.cell_f1)


def answer_text(completion) -> str:
    """A completion as TRL and verifiers give it: a text, or messages whose last one is the
    answer (its content; None: no text)."""
    if isinstance(completion, str):
        return completion
    content = completion[-1]["content"] if completion else ""
    return content or ""


def grpo_reward(reward: str = "es", *, episodes: Episodes | None = None, probes: bool = False) -> Callable:
    """A TRL reward function named `sartco_<reward>` (TRL logs `rewards/sartco_<reward>/mean`).
    `episodes`: the episodes to score against; default: read from the rows' `episode` column as
    they come (kept, so each episode's probe draws are computed once). `probes`: also probe the
    function (costs K more programs per function answer; the reward does not use it)."""
    checked(reward)
    known = episodes if episodes is not None else Episodes({})

    def sartco_reward(prompts, completions, id, episode=None, **columns) -> list[float | None]:
        if episodes is None:
            if episode is None:
                raise ValueError("the dataset has no 'episode' column (rows of sartco export-dataset), "
                                 "and no episodes were given to grpo_reward")
            known.include({"id": key, "episode": text} for key, text in zip(id, episode))
        results = score(list(zip(id, map(answer_text, completions))), known, probes=probes)
        return [None if r.harness_error else value(r, reward) for r in results]

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
    """verl's batch reward function (BatchRewardManager): the rewards of decoded answers, one sandbox batch."""
    checked(reward)
    ids = [(info or {}).get("id") for info in extra_infos]
    if not all(isinstance(i, str) for i in ids):
        raise ValueError("every extra_info needs the episode's 'id' (the id column of sartco export-dataset)")
    keys = [str(i) for i in ids]
    _VERL_EPISODES.include({"id": key, "episode": truth} for key, truth in zip(keys, ground_truths))
    results = score(list(zip(keys, solution_strs)), _VERL_EPISODES, probes=False)
    return [0.0 if r.harness_error else value(r, reward) for r in results]


def load_environment(instances: str | Path | Sequence[str | Path] | None = None, reward: str = "es"):
    """verifiers' entry point: a vf.SingleTurnEnv over the single-turn episodes of cobot_instruct
    instance files (default the train split), one row each: `prompt` (the game's first turn, as
    `sartco export-dataset` writes it) and `info` {"id": the episode id}. Its vf.Rubric has two
    group reward functions, `sartco_es` and `sartco_cell_f1` (a group is one sandbox batch, scored
    once for both); `reward` gets weight 1, the other weight 0 (a metric)."""
    import verifiers as vf
    from datasets import Dataset

    checked(reward)
    paths = [instances] if isinstance(instances, (str, Path)) else list(instances or [TRAIN_FILE])
    rows = [row for path in paths for row in rows_of(Path(path)) if row["turns"] == 1]
    if not rows:
        raise ValueError(f"no single-turn episode in {', '.join(map(str, paths))}")
    episodes = Episodes.from_rows(rows)

    def rewards(completions, infos, states) -> list[Reward]:
        """The group's Rewards, scored once (kept on the rollout states for the second function)."""
        todo = [k for k, state in enumerate(states) if "sartco_reward" not in state]
        pairs = [(infos[k]["id"], answer_text(completions[k])) for k in todo]
        for k, result in zip(todo, score(pairs, episodes, probes=False)):
            states[k]["sartco_reward"] = result
        return [state["sartco_reward"] for state in states]

    def sartco_es(completions, infos, states) -> list[float]:
        return [0.0 if r.harness_error else value(r, "es") for r in rewards(completions, infos, states)]

    def sartco_cell_f1(completions, infos, states) -> list[float]:
        return [0.0 if r.harness_error else value(r, "cell_f1") for r in rewards(completions, infos, states)]

    weights = [1.0, 0.0] if reward == "es" else [0.0, 1.0]
    rubric = vf.Rubric(funcs=[sartco_es, sartco_cell_f1], weights=weights)
    dataset = Dataset.from_list([{"prompt": row["prompt"], "info": {"id": row["id"]}} for row in rows])
    return vf.SingleTurnEnv(dataset=dataset, rubric=rubric)


# OpenRLHF: a rollout's `query` is the decoded prompt and response (prompt + answer text), `prompts`
# the prompt texts, `labels` the dataset's --label_key column: the `episode` column of sartco
# export-dataset (the episode as JSON text; an episode is known by its text's SHA-256).
_OPENRLHF_EPISODES = Episodes({})


def openrlhf_pairs(queries, prompts, labels) -> list[tuple[str, str]]:
    """The (episode key, answer) pairs of OpenRLHF's request fields, checked (a ValueError names the
    field and index of what is wrong); their episodes join _OPENRLHF_EPISODES."""
    for name, field in (("query", queries), ("prompts", prompts), ("labels", labels)):
        if not (isinstance(field, list) and all(isinstance(x, str) for x in field)):
            raise ValueError(f"'{name}' must be a list of strings")
    if not len(queries) == len(prompts) == len(labels):
        raise ValueError(f"'query', 'prompts' and 'labels' differ in length ({len(queries)}, {len(prompts)}, {len(labels)})")
    pairs = []
    for k, (query, prompt, label) in enumerate(zip(queries, prompts, labels)):
        if not query.startswith(prompt):
            raise ValueError(f"query[{k}] does not start with prompts[{k}]: the answer cannot be told from the prompt")
        pairs.append(("sha256:" + hashlib.sha256(label.encode("utf-8")).hexdigest(), query[len(prompt):]))
    try:
        _OPENRLHF_EPISODES.include({"id": key, "episode": label} for (key, _), label in zip(pairs, labels))
    except ValueError as exc:
        raise ValueError(f"'labels': the episode column of sartco export-dataset expected ({exc})") from None
    return pairs


def openrlhf_answer(results: Sequence[Reward], reward: str = "es") -> dict:
    """OpenRLHF's remote reward answer: {"rewards", "scores", "extra_logs": {"es", "cell_f1"}}, one
    number per query, as OpenRLHF's own reward server (openrlhf.cli.serve_rm) answers."""
    es = [0.0 if r.harness_error else value(r, "es") for r in results]
    f1 = [0.0 if r.harness_error else value(r, "cell_f1") for r in results]
    chosen = es if checked(reward) == "es" else f1
    return {"rewards": chosen, "scores": chosen, "extra_logs": {"es": es, "cell_f1": f1}}


def openrlhf_score(pairs: list[tuple[str, str]]) -> list[Reward]:
    """The Rewards of openrlhf_pairs' pairs, one sandbox batch."""
    return score(pairs, _OPENRLHF_EPISODES, probes=False)


def reward_func(queries, prompts, labels) -> dict:
    """OpenRLHF's reward function file (`--remote_rm_url <path of this file>`): ES, one sandbox batch a call."""
    return openrlhf_answer(openrlhf_score(openrlhf_pairs(queries, prompts, labels)))
