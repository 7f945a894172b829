"""The reward API in the trainers' interfaces (sartco.reward.trainers): the TRL reward function
called as GRPOTrainer calls it, and one real GRPO step on CPU of a tiny randomly initialised
model built from a config (no download), whose log carries the reward.

The GRPO step (marker `train`, left out of `make test`) needs the `train` extra (torch, trl):
`make test-train` installs it and sets SARTCO_REQUIRE_TRAIN=1, so that a missing library fails
instead of skipping."""
from __future__ import annotations

import asyncio
import importlib
import json
import os

import pytest

from play_helpers import GAMES, fence
from sartco.cli import main
from sartco.clem.players.answers import NO_CODE
from sartco.clem.tooling.stub_server import StubServer, conversation_key
from sartco.reward import Episodes, score
from sartco.reward.trainers import grpo_reward
from sartco.world.components import COLORS

SMOKE = GAMES / "cobot_instruct" / "in" / "instances_smoke.json"


def require(name: str):
    if os.environ.get("SARTCO_REQUIRE_TRAIN"):
        return importlib.import_module(name)
    return pytest.importorskip(name, reason="the train extra (make test-train)")


@pytest.fixture(scope="module")
def rows(tmp_path_factory) -> list[dict]:
    """The smoke file's single-turn rows of `sartco export-dataset`."""
    out = tmp_path_factory.mktemp("dataset")
    assert main(["export-dataset", "--instances", str(SMOKE), "--out", str(out)]) == 0
    rows = [json.loads(line) for line in (out / "instances_smoke.jsonl").read_text().splitlines()]
    return [r for r in rows if r["turns"] == 1]


def test_the_trl_reward_function_scores_as_the_reward_api(rows):
    """Called as GRPOTrainer calls it: prompts, completions (conversational: the assistant's
    messages) and every dataset column as keyword arguments."""
    gold = [f"```python\n{json.loads(r['episode'])['gold_code']}\n```" for r in rows]
    answers = [g if k % 2 else "no code, sorry" for k, g in enumerate(gold)]
    columns = {name: [r[name] for r in rows] for name in rows[0] if name != "prompt"}
    reward = grpo_reward("es")
    assert reward.__name__ == "sartco_es"
    got = reward([r["prompt"] for r in rows], [[{"role": "assistant", "content": a}] for a in answers], **columns)
    assert got == [float(k % 2) for k in range(len(rows))]
    f1 = grpo_reward("cell_f1", episodes=Episodes.from_files([SMOKE]))(None, answers, id=columns["id"])
    assert f1 == [r.cell_f1 for r in score(list(zip(columns["id"], answers)), Episodes.from_files([SMOKE]))]
    with pytest.raises(ValueError, match="no 'episode' column"):
        grpo_reward("es")(None, answers, id=columns["id"])
    with pytest.raises(ValueError, match="unknown reward 'bleu'"):
        grpo_reward("bleu")


def tiny_tokenizer(texts: list[str]):
    """A word-level tokenizer of the prompts' words, made here (nothing downloaded)."""
    from tokenizers import Tokenizer, models, pre_tokenizers, trainers
    from transformers import PreTrainedTokenizerFast

    tokenizer = Tokenizer(models.WordLevel(unk_token="[UNK]"))
    tokenizer.pre_tokenizer = pre_tokenizers.WhitespaceSplit()
    tokenizer.train_from_iterator(texts, trainers.WordLevelTrainer(special_tokens=["[UNK]", "[PAD]", "[EOS]"]))
    fast = PreTrainedTokenizerFast(tokenizer_object=tokenizer, unk_token="[UNK]", pad_token="[PAD]", eos_token="[EOS]")
    fast.chat_template = "{% for m in messages %}{{ m['content'] }} {% endfor %}"
    return fast


@pytest.mark.train
def test_one_grpo_step_of_a_tiny_model_logs_the_reward(rows, tmp_path):
    require("torch")
    trl = require("trl")
    datasets = require("datasets")
    from transformers import LlamaConfig, LlamaForCausalLM

    tokenizer = tiny_tokenizer([m["content"] for r in rows for m in r["prompt"]] + ["put(board, 'nut', 'red', 0, 0)"])
    config = LlamaConfig(vocab_size=len(tokenizer), hidden_size=16, intermediate_size=32, num_hidden_layers=1,
                         num_attention_heads=2, num_key_value_heads=2, max_position_embeddings=4096,
                         pad_token_id=tokenizer.pad_token_id, eos_token_id=tokenizer.eos_token_id,
                         bos_token_id=tokenizer.eos_token_id)
    model = LlamaForCausalLM(config)
    inner, calls = grpo_reward("es"), []

    def sartco_es(prompts, completions, **columns):
        out = inner(prompts, completions, **columns)
        calls.append((columns["id"], out))
        return out

    args = trl.GRPOConfig(output_dir=str(tmp_path / "out"), per_device_train_batch_size=2, num_generations=2,
                          max_completion_length=8, max_steps=1, use_cpu=True, report_to="none", logging_steps=1,
                          save_strategy="no", beta=0.0, disable_tqdm=True, seed=0)
    trainer = trl.GRPOTrainer(model=model, reward_funcs=sartco_es, args=args, processing_class=tokenizer,
                              train_dataset=datasets.Dataset.from_list(rows))
    trainer.train()
    assert calls and all(len(ids) == len(out) == 2 for ids, out in calls)
    assert all(i in {r["id"] for r in rows} for ids, _ in calls for i in ids)
    logged = [entry for entry in trainer.state.log_history if "rewards/sartco_es/mean" in entry]
    assert logged, trainer.state.log_history
    rewards = [x for _, out in calls for x in out]
    assert logged[0]["rewards/sartco_es/mean"] == pytest.approx(sum(rewards) / len(rewards))


def byte_tokenizer(texts: list[str]):
    """A byte-level BPE tokenizer made from the texts: decoding gives the exact text back."""
    from tokenizers import Tokenizer, decoders, models, pre_tokenizers, trainers
    from transformers import PreTrainedTokenizerFast

    tokenizer = Tokenizer(models.BPE())
    tokenizer.pre_tokenizer = pre_tokenizers.ByteLevel(add_prefix_space=False)
    tokenizer.decoder = decoders.ByteLevel()
    tokenizer.train_from_iterator(texts, trainers.BpeTrainer(vocab_size=600, special_tokens=["[PAD]"],
                                                             initial_alphabet=pre_tokenizers.ByteLevel.alphabet()))
    return PreTrainedTokenizerFast(tokenizer_object=tokenizer, pad_token="[PAD]")


@pytest.mark.train
@pytest.mark.parametrize("manager", ["naive", "batch"])
def test_verl_reward_managers_call_compute_score(rows, manager):
    """verl's own reward managers decode the responses of a DataProto and call our compute_score
    (naive: one answer a call) or compute_score_batch (batch), loaded as verl loads a
    custom_reward_function (path: this file, name); the reward sits on each response's last token."""
    torch = require("torch")
    require("verl")
    from omegaconf import OmegaConf
    from verl import DataProto
    from verl.trainer.ppo.reward import get_custom_reward_fn
    from verl.workers.reward_manager.batch import BatchRewardManager
    from verl.workers.reward_manager.naive import NaiveRewardManager

    import sartco.reward.trainers as trainers

    def custom(name: str):
        return get_custom_reward_fn(OmegaConf.create({"reward": {"custom_reward_function": {"path": trainers.__file__, "name": name}}}))

    gold = [json.loads(r["episode"])["gold_code"] for r in rows]
    answers = [f"```python\n{g}\n```" if k % 2 else f"```python\n{g}\nraise ValueError(1)\n```" for k, g in enumerate(gold)]
    prompts = [r["prompt"][0]["content"][-200:] for r in rows]
    tokenizer = byte_tokenizer(prompts + answers)
    assert tokenizer.decode(tokenizer(answers[0])["input_ids"]) == answers[0]

    def padded(texts, side):
        tokenizer.padding_side = side
        out = tokenizer(texts, padding=True, return_tensors="pt")
        return out["input_ids"], out["attention_mask"]

    prompt_ids, prompt_mask = padded(prompts, "left")
    response_ids, response_mask = padded(answers, "right")
    data = DataProto.from_dict(
        tensors={"prompts": prompt_ids, "responses": response_ids,
                 "attention_mask": torch.cat([prompt_mask, response_mask], dim=1)},
        non_tensors={"data_source": ["sartco"] * len(rows),
                     "reward_model": [{"ground_truth": r["episode"]} for r in rows],
                     "extra_info": [{"id": r["id"]} for r in rows]})
    if manager == "naive":
        rewards = NaiveRewardManager(tokenizer, num_examine=0, compute_score=custom("compute_score"))(data)
    else:
        rewards = BatchRewardManager(tokenizer, num_examine=0, compute_score=custom("compute_score_batch"))(data)
    last = response_mask.sum(dim=1) - 1
    got = [float(rewards[i, last[i]]) for i in range(len(rows))]
    assert got == [float(k % 2) for k in range(len(rows))]
    assert float(rewards.sum()) == sum(got)  # nothing anywhere else


def wrong(code: str) -> str:
    """The code with one of its colours another: a partly right board (ES 0, cell F1 < 1)."""
    _, colour = min((code.find(f"'{c}'"), c) for c in COLORS if f"'{c}'" in code)
    return code.replace(f"'{colour}'", f"'{COLORS[(COLORS.index(colour) + 1) % len(COLORS)]}'")


def scripted_answers(rows) -> list[str]:
    """Per row: the gold answer, a wrong-colour one, or no code, in turn."""
    gold = [json.loads(r["episode"])["gold_code"] for r in rows]
    return [fence(g) if k % 3 == 0 else fence(wrong(g)) if k % 3 == 1 else NO_CODE for k, g in enumerate(gold)]


def expected(rows, answers) -> list:
    results = score([(r["id"], a) for r, a in zip(rows, answers)], Episodes.from_rows(rows), probes=False)
    assert [r.category for r in results[::3]] == ["success"] * len(results[::3])
    assert all(r.category.startswith("mismatch") and r.cell_f1 < 1 for r in results[1::3])
    assert any(0 < r.cell_f1 < 1 for r in results) and all(r.category == "parse_error" for r in results[2::3])
    return results


@pytest.mark.train
@pytest.mark.parametrize("reward", ["es", "cell_f1"])
def test_a_verifiers_environment_scores_rollouts_with_its_rubric(rows, reward):
    """vf.load_environment finds sartco.reward.trainers.load_environment; verifiers' own evaluate
    runs the rollouts against an OpenAI-compatible model server (the project's stub server answering
    the scripted answers) through its own client, and its Rubric scores them with sartco_es and
    sartco_cell_f1 (group functions); reward and metrics equal sartco.reward.score's."""
    vf = require("verifiers")
    from openai import AsyncOpenAI
    from verifiers.clients import OpenAIChatCompletionsClient

    answers = scripted_answers(rows)
    want = {r["id"]: result for r, result in zip(rows, expected(rows, answers))}
    table = {conversation_key([r["prompt"][0]["content"]]): a for r, a in zip(rows, answers) if a != NO_CODE}
    env = vf.load_environment("sartco.reward.trainers", instances=[str(SMOKE)], reward=reward)
    assert isinstance(env, vf.SingleTurnEnv)
    ours = env.rubric.rubrics[0]  # SingleTurnEnv groups the rubric with its turn counter
    assert [f.__name__ for f in ours.funcs] == ["sartco_es", "sartco_cell_f1"]
    assert ours.weights == ([1.0, 0.0] if reward == "es" else [0.0, 1.0])
    with StubServer(table, latency=0.0, max_requests=4 * len(rows), max_seconds=120) as server:
        client = OpenAIChatCompletionsClient(AsyncOpenAI(base_url=server.base_url, api_key="none"))
        out = asyncio.run(env.evaluate(client=client, model="stub", rollouts_per_example=2,
                                       on_progress=lambda *a, **k: None))
    outputs = out["outputs"]
    assert server.requests == len(outputs) == 2 * len(rows)
    assert sorted(o["info"]["id"] for o in outputs) == sorted(r["id"] for r in rows for _ in range(2))
    for o in outputs:
        result = want[o["info"]["id"]]
        assert o["metrics"]["sartco_es"] == result.es and o["metrics"]["sartco_cell_f1"] == result.cell_f1
        assert o["reward"] == (result.es if reward == "es" else result.cell_f1)
    assert {o["reward"] for o in outputs if want[o["info"]["id"]].es} == {1.0}  # gold
    assert max(o["reward"] for o in outputs if not want[o["info"]["id"]].es) < 1.0  # wrong colour, no code


class Engine:
    """Stands in for OpenRLHF's vLLM engine (CUDA only): "generates" a fixed answer's tokens."""

    def __init__(self, tokenizer, answers: dict[str, str]):
        self.tokenizer, self.answers = tokenizer, answers

    async def generate(self, prompt_token_ids, sampling_params, multi_modal_data=None):
        from types import SimpleNamespace

        prompt = self.tokenizer.decode(prompt_token_ids)
        tokens = self.tokenizer(self.answers[prompt], add_special_tokens=False)["input_ids"]
        return SimpleNamespace(outputs=[SimpleNamespace(token_ids=tokens, finish_reason="stop", logprobs=None)])


@pytest.mark.train
@pytest.mark.parametrize("form", ["http", "file"])
def test_openrlhf_single_turn_executor_gets_the_reward(rows, form):
    """OpenRLHF's own PromptDataset reads the export-dataset rows (--input_key prompt --label_key
    episode --apply_chat_template), and its SingleTurnAgentExecutor (what its rollout actors run
    after vLLM generates) decodes prompt + answer and fetches the reward: over HTTP from `sartco
    serve-reward`'s server (--remote_rm_url URL) or from our reward_func (--remote_rm_url FILE).
    All rollouts run at once; each gets its own reward, equal to sartco.reward.score's."""
    from types import SimpleNamespace

    require("openrlhf")
    datasets = require("datasets")
    from openrlhf.datasets import PromptDataset
    from openrlhf.utils.agent import SingleTurnAgentExecutor

    import sartco.reward.trainers as trainers
    from sartco.reward.serve import RewardServer

    answers = scripted_answers(rows)
    results = expected(rows, answers)
    tokenizer = byte_tokenizer([m["content"] for r in rows for m in r["prompt"]] + answers)
    tokenizer.chat_template = "{% for m in messages %}<|{{ m['role'] }}|>\n{{ m['content'] }}\n{% endfor %}<|assistant|>\n"
    strategy = SimpleNamespace(is_rank_0=lambda: True, args=SimpleNamespace(
        data=SimpleNamespace(input_key="prompt", label_key="episode", apply_chat_template=True)))
    data = PromptDataset(datasets.Dataset.from_list(rows), tokenizer, strategy)
    assert data.labels == [r["episode"] for r in rows]
    engine = Engine(tokenizer, dict(zip(data.prompts, answers)))
    params = SimpleNamespace(max_tokens=None, logprobs=None)

    async def rollouts(executor):
        return await asyncio.gather(*(executor.execute(p, label, params, 10 ** 6, tokenizer, engine)
                                      for p, label in zip(data.prompts, data.labels)))

    if form == "http":
        with RewardServer() as server:
            outputs = asyncio.run(rollouts(SingleTurnAgentExecutor(server.url)))
    else:
        outputs = asyncio.run(rollouts(SingleTurnAgentExecutor(trainers.__file__)))
    for output, result in zip(outputs, results):
        assert output["reward"] == output["scores"] == [float(result.es)]
        assert output["extra_logs"] == {"es": [float(result.es)], "cell_f1": [result.cell_f1]}
