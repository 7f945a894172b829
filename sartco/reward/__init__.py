"""SARTCo as a reward for RL trainers: completions scored in batches, as cobot_instruct scores them.

    from sartco.reward import Episodes, score
    episodes = Episodes.from_files(["games/cobot_instruct/in/instances_train.json"])
    rewards = score([(episode_id, completion), ...], episodes)   # -> list[Reward], input order
    rewards[0].es, rewards[0].cell_f1, rewards[0].category, rewards[0].puts, rewards[0].function_generalisation

An episode id is "<experiment>/<board id>/<task>" (as `sartco export-prompts --protocol sartco`
and `sartco export-dataset` write it). A completion is the model's answer text (single-turn
episodes: every function and repetition cell), or a list of answers, one per turn (first_order
episodes have one turn per instruction; missing turns are answers without code). The answers are
read, built, judged and probed by the game's own code (sartco.reward.core's docstring), so a
Reward equals what `clem score` writes for the same answers (tests/reward/test_reward.py plays
episodes and compares); `Reward.scores` holds them under scores.json's names. EM and CodeBLEU
are not computed (they compare text with the gold code, not what it builds).

A harness_error reward (`Reward.harness_error`) means the sandbox failed, not the model: give
it no reward. `sartco bench-reward` measures rewards per second (sartco.reward.bench);
`sartco export-dataset` writes the prompts as a Hugging Face dataset (sartco.reward.dataset).
"""
from .core import Episodes, Reward, score

__all__ = ["Episodes", "Reward", "score"]
