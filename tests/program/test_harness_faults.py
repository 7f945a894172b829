"""Harness faults are not the model's errors (issue 21): every fault the program did not cause is
`harness_error`, with its reason; a worker killed by the program's own resource use stays the
program's `resource_limit` / `runtime_error`.

Faults are injected where they happen: no worker can start, a worker that answers garbage, a
worker that exits on its own (not killed while running the program), a pool that loses an answer
or fails itself, and the same through `sartco execute`. Who is blamed for a dead worker by its
exit status: test_runtime_safety.test_a_dead_worker_is_named."""
import io
import json

import pytest

from harness_helpers import fake_worker, no_worker

from sartco.program import Limits, execute, execute_many, pool
from sartco.program.serve import serve
from sartco.world import ErrorCode

E = ErrorCode
PUT = "put(board, 'nut', 'red', 0, 0)"


@pytest.fixture
def fresh_pool():
    pool.shutdown()
    yield
    pool.shutdown()


def test_no_worker_can_start(monkeypatch, fresh_pool):
    no_worker(monkeypatch, "the sandbox worker did not start")
    for ex in execute_many([PUT, "x = 1"]):
        assert (ex.ok, ex.error) == (False, E.HARNESS_ERROR)
        assert ex.message == "sandbox unavailable: the sandbox worker did not start"


def test_a_worker_that_answers_garbage(monkeypatch, fresh_pool):
    fake_worker(monkeypatch, "for _ in range(n): print('garbage', flush=True)")
    ex = execute(PUT)
    assert (ex.ok, ex.error) == (False, E.HARNESS_ERROR)
    assert ex.message.startswith("garbled answer from the sandbox worker")


def test_a_worker_that_exits_on_its_own_is_not_the_program(monkeypatch, fresh_pool):
    fake_worker(monkeypatch, "sys.exit(1)")
    ex = execute(PUT)
    assert (ex.ok, ex.error, ex.message) == (False, E.HARNESS_ERROR, "the sandbox worker ended unexpectedly (status 1)")


def test_lost_and_failed_batches(monkeypatch):
    monkeypatch.setattr(pool, "dispatch", lambda *a, **k: {})  # no Execution for the program
    ex = execute(PUT)
    assert (ex.error, ex.message) == (E.HARNESS_ERROR, "the sandbox returned no result")

    def broken(*args, **kwargs):
        raise RuntimeError("pool bug")

    monkeypatch.setattr(pool, "dispatch", broken)
    ex = execute(PUT)
    assert (ex.error, ex.message) == (E.HARNESS_ERROR, "sandbox failure: RuntimeError: pool bug")


@pytest.mark.parametrize("misbehave,reason", [
    ("sys.exit(1)", "the sandbox worker ended unexpectedly (status 1)"),
    ("for _ in range(n): print('garbage', flush=True)", "garbled answer from the sandbox worker: b'garbage'"),
])
def test_sartco_execute_answers_a_harness_error(monkeypatch, fresh_pool, misbehave, reason):
    fake_worker(monkeypatch, misbehave)
    out = io.BytesIO()
    serve(io.BytesIO(json.dumps({"id": "a", "code": PUT}).encode() + b"\n"), out)
    answer = json.loads(out.getvalue())
    assert (answer["id"], answer["ok"], answer["error"], answer["message"]) == ("a", False, "harness_error", reason)


def test_a_program_that_exhausts_memory_stays_resource_limit(fresh_pool):
    ex = execute("x = [[0] * 10**6 for i in range(1000)]", limits=Limits(memory=128 * 1024 * 1024, wall_time=20))
    assert (ex.ok, ex.error) == (False, E.RESOURCE_LIMIT), ex.message
