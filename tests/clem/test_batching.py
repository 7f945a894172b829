"""The openai_batching backend against the local stub server: concurrency limit, order, retries
with backoff, the same answers as sequential; and `sartco bench-run` on a small run (the batched
run's scores.json files equal the sequential run's)."""
import json
import time

import openai
import pytest
from clemcore.backends import ModelSpec

from play_helpers import clem_process
from sartco.clem.core.outcomes import NoAnswer
from sartco.clem.tooling import benchrun
from sartco.clem.tooling.batching import OpenAIBatchingBackend, retry_delay
from sartco.clem.tooling.stub_server import NO_CODE, StubServer, answer_table, conversation_key

TURNS = {f"Instruction {k}.": f"put(board, 'nut', 'red', {k}, 0)" for k in range(8)}


def answers():
    return {conversation_key([turn]): f"```python\n{code}\n```" for turn, code in TURNS.items()}


def model_for(server: StubServer, tmp_path, monkeypatch, base_url=None, **config):
    """The backend as clemcore loads it: key.json in the working directory, a registry entry."""
    (tmp_path / "key.json").write_text(json.dumps(
        {"openai_compatible": {"api_key": "none", "base_url": base_url or server.base_url}}))
    monkeypatch.chdir(tmp_path)
    spec = ModelSpec(model_name="stub", model_id="stub", backend="openai_batching",
                     model_config={"backoff": 0.01, **config})
    model = OpenAIBatchingBackend().get_model_for(spec)
    model.set_gen_args(temperature=0.0, max_tokens=100)
    return model


def overlap(intervals) -> int:
    """The most requests in flight at once."""
    events = sorted([(a, 1) for a, _ in intervals] + [(b, -1) for _, b in intervals], key=lambda e: (e[0], e[1]))
    most = now = 0
    for _, step in events:
        now += step
        most = max(most, now)
    return most


def test_batch_is_concurrent_up_to_the_limit_and_in_order(tmp_path, monkeypatch):
    with StubServer(answers(), latency=1.0) as server:
        model = model_for(server, tmp_path, monkeypatch, concurrency=4)
        assert model.supports_batching()  # what makes clem run -b N take the batchwise runner
        turns = list(TURNS)
        results = model.generate_batch_response([[{"role": "user", "content": t}] for t in turns])
    assert [text for _, _, text in results] == [answers()[conversation_key([t])] for t in turns]
    assert overlap(server.intervals) == 4 and len(server.intervals) == 8
    assert results[0][1]["clem_player"]["model_name"] == "stub"  # clemcore's response object


def test_sequential_call_gives_the_same_answer(tmp_path, monkeypatch):
    with StubServer(answers(), latency=0.0) as server:
        model = model_for(server, tmp_path, monkeypatch)
        messages = [{"role": "user", "content": "Instruction 3."}]
        assert model.generate_response(messages)[2] == model.generate_batch_response([messages])[0][2]
        assert model.generate_response([{"role": "user", "content": "unknown"}])[2] == NO_CODE


def test_5xx_is_retried_with_backoff(tmp_path, monkeypatch):
    with StubServer(answers(), latency=0.0, fail_first=2) as server:
        model = model_for(server, tmp_path, monkeypatch, retries=2)
        text = model.generate_response([{"role": "user", "content": "Instruction 1."}])[2]
    assert text == answers()[conversation_key(["Instruction 1."])]
    assert server.requests == 3  # two failures, then the answer: each try is one request (the client retries none)


def test_retries_run_out(tmp_path, monkeypatch):
    with StubServer(answers(), latency=0.0, fail_first=10) as server:
        model = model_for(server, tmp_path, monkeypatch, retries=1)
        prompt, response, text = model.generate_response([{"role": "user", "content": "Instruction 1."}])
    assert server.requests == 2
    assert isinstance(text, NoAnswer) and text == "" and text.reason == response["error"]  # not an exception
    assert text.reason.startswith("model server: InternalServerError") and "after 2 tries" in text.reason


def test_other_errors_are_not_retried(tmp_path, monkeypatch):
    with StubServer(answers(), latency=0.0) as server:
        model = model_for(server, tmp_path, monkeypatch, base_url=server.base_url.replace("/v1", "/nowhere"))
        text = model.generate_response([{"role": "user", "content": "Instruction 1."}])[2]
    assert (server.misrouted, server.requests) == (1, 0)  # the 404 was not retried
    assert text.reason.startswith("model server: NotFoundError") and "after 1 try in 0 s" in text.reason


def test_retry_delay():
    class Error(Exception):
        def __init__(self, headers):
            self.response = type("R", (), {"headers": headers})()
    assert retry_delay(Error({"retry-after": "3"}), 0, 1.0) == 3.0
    assert [retry_delay(Error({}), k, 0.5) for k in range(4)] == [0.5, 1.0, 2.0, 4.0]
    assert retry_delay(Error({}), 20, 1.0) == 60.0
    assert retry_delay(ValueError(), 1, 1.0) == 2.0


def test_bad_model_config(tmp_path, monkeypatch):
    with StubServer({}, latency=0.0) as server:
        with pytest.raises(ValueError, match="concurrency >= 1"):
            model_for(server, tmp_path, monkeypatch, concurrency=0)


def test_stub_server_stops_after_its_request_budget():
    with StubServer(answers(), latency=0.0, max_requests=1) as server:
        client = openai.OpenAI(base_url=server.base_url, api_key="none", max_retries=0)
        client.chat.completions.create(model="stub", messages=[{"role": "user", "content": "Instruction 0."}])
        with pytest.raises(openai.InternalServerError):  # 503
            client.chat.completions.create(model="stub", messages=[{"role": "user", "content": "Instruction 0."}])


def test_answer_table_covers_every_turn():
    instance = {"turns": ["prompt + turn 1", "turn 2"], "gold_turns": ["a = 1", "b = 2"]}
    table = answer_table([instance])
    assert table[conversation_key(["prompt + turn 1"])] == "```python\na = 1\n```"
    assert table[conversation_key(["prompt + turn 1", "turn 2"])] == "```python\nb = 2\n```"


@pytest.mark.slow
def test_bench_run_batched_scores_equal_sequential(tmp_path, monkeypatch):
    # its clem processes forked from the tests' warm parent (tests/helpers/forkserver.py), as the other runs here
    monkeypatch.setattr(benchrun, "clem", clem_process)
    # multi-turn (first-order, 2-5 requests per episode) and single-turn episodes
    result = benchrun.bench(["sb_so_first_order_template", "rb_co_repetition_template"], episodes=5, latency=0.05,
                            concurrency=4, batch=4, out=tmp_path / "bench", max_seconds=600)
    assert result["episodes"] == 10 and result["unknown"] == 0 and result["scores"] == 10
    assert result["scores_equal"]
    assert result["sequential"]["requests"] == result["batched"]["requests"] == result["requests"] > 10
    one = json.loads(next((tmp_path / "bench" / "batched" / "results").rglob("scores.json")).read_text())
    assert one["episode scores"]["Main Score"] == 100.0  # the stub answered with the gold code


def test_bench_runs_clem_as_a_process_and_names_its_failure(tmp_path):
    """benchrun.clem, which the test above replaces: the installed `clem` in a process of its own."""
    from sartco.errors import UserError
    with pytest.raises(UserError, match="clem run -g no_such_game -m mock failed"):
        benchrun.clem(["run", "-g", "no_such_game", "-m", "mock"], tmp_path)


def test_bench_run_rejects_an_unknown_experiment(tmp_path):
    from sartco.errors import UserError
    with pytest.raises(UserError, match="unknown cobot_instruct experiment"):
        benchrun.select_instances(["no_such_experiment"], 0)


def test_a_hung_server_ends_each_request_after_its_timeout_and_retries(tmp_path, monkeypatch, caplog):
    with StubServer(answers(), hang=True, max_seconds=120) as server:
        model = model_for(server, tmp_path, monkeypatch, timeout=2, retries=2, retry_budget=600)
        start = time.monotonic()
        text = model.generate_response([{"role": "user", "content": "Instruction 1."}])[2]
        took = time.monotonic() - start
    assert server.requests == 3                  # the first try and two retries, each cut at 2 s
    assert 6.0 <= took < 20.0, took               # not the client's default 600 s per try
    assert "APITimeoutError after 3 tries" in caplog.text and "request aborted" in caplog.text
    assert text.reason.startswith("model server: no answer after 3 tries in ") and text.reason.endswith("(timeout 2 s)")


def test_the_retry_budget_stops_retrying_early(tmp_path, monkeypatch):
    with StubServer(answers(), hang=True, max_seconds=120) as server:
        model = model_for(server, tmp_path, monkeypatch, timeout=2, retries=10, retry_budget=3)
        start = time.monotonic()
        text = model.generate_response([{"role": "user", "content": "Instruction 1."}])[2]
    assert isinstance(text, NoAnswer) and server.requests == 2 and time.monotonic() - start < 10   # 2 s + 2 s > the 3 s budget: no third try


def test_the_cache_answers_a_repeated_request_without_the_server(tmp_path, monkeypatch):
    messages = [[{"role": "user", "content": f"Instruction {k}."}] for k in range(4)]
    with StubServer(answers(), latency=0.0) as server:
        first = model_for(server, tmp_path, monkeypatch, cache=str(tmp_path / "cache"))
        texts = [t for _, _, t in first.generate_batch_response(messages)]
        assert server.requests == 4 and (first.cache.hits, first.cache.misses) == (0, 4)
        again = model_for(server, tmp_path, monkeypatch, cache=str(tmp_path / "cache"))
        assert [t for _, _, t in again.generate_batch_response(messages)] == texts
        assert server.requests == 4 and again.cache.hits == 4          # no request reached the server
        again.set_gen_args(temperature=0.0, max_tokens=50)              # other settings: another key
        again.generate_response(messages[0])
        assert server.requests == 5
        again.set_gen_args(temperature=0.7, max_tokens=100)             # sampling: never served from the cache
        again.generate_response(messages[0])
        again.generate_response(messages[0])
        assert server.requests == 7


def test_a_failing_request_fails_only_its_item_of_the_batch_and_is_never_cached(tmp_path, monkeypatch):
    messages = [[{"role": "user", "content": f"Instruction {k}."}] for k in range(3)]
    failing = frozenset({conversation_key(["Instruction 1."])})
    with StubServer(answers(), latency=0.0, failing=failing) as server:
        model = model_for(server, tmp_path, monkeypatch, retries=1, cache=str(tmp_path / "cache"))
        texts = [t for _, _, t in model.generate_batch_response(messages)]
        assert [isinstance(t, NoAnswer) for t in texts] == [False, True, False]
        assert texts[0] == answers()[conversation_key(["Instruction 0."])]
        assert server.requests == 2 + 2                                 # the failing one: 2 tries
        model.generate_batch_response(messages)
        assert server.requests == 4 + 2                                 # the failure asked again, the answers cached
