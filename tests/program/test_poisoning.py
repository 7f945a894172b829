"""No program spoils another: after each memory, cycle, crash and cache attack, 50 gold programs
in the same process (the same templates, each program in a child of its own) all build their gold boards exactly, through
`execute()`, `execute_many()` and `sartco execute` fed line by line.

The attacks:
- memory: lists until the worker's address space is full (MemoryError);
- cycle: a list that contains itself and grows until MemoryError (the cycle outlives the
  program's namespace: only the worker's retirement frees it);
- crash: map() nested 300,000 deep, which overflows the C stack (SIGSEGV);
- cache: a program that ends `ok` but leaves 400 MB in a reference cycle, so that the next
  program would compile under memory pressure and a MemoryError would be cached as its verdict;
- swallowed: a MemoryError caught by `finally: return`, the cycle still alive.
"""
import json
import select
import signal
import subprocess
import sys
import time

import pytest

from sartco.program import execute, execute_many, pool, shutdown
from sartco.dataset import SHARED_DATA as DEFAULT_DATA
from sartco.published.gold import gold_programs
from sartco.world import ErrorCode

pytestmark = pytest.mark.skipif(not (DEFAULT_DATA / "published").is_dir(), reason="shared data missing")

E = ErrorCode
STOPS = {E.RESOURCE_LIMIT, E.TIMEOUT}  # a loaded machine may reach the wall time first
ATTACKS = {  # name: (program, the verdicts it may end in)
    "memory": ("x = [[0] * 10**6 for i in range(1000)]", STOPS),
    "cycle": ("L = []\nL.append(L)\nwhile True:\n    L.append([0] * 10**5)", STOPS),
    "crash": ("x = [1]\nfor i in range(300000):\n    x = map(abs, x)\ny = list(x)", {E.RUNTIME_ERROR}),
    "cache": ("L = []\nL.append(L)\nL.append([[0] * 10**6 for i in range(50)])", {None} | STOPS),
    "swallowed": ("L = []\nL.append(L)\ndef f():\n    try:\n        while True:\n            L.append([0] * 10**5)\n"
                  "    finally:\n        return 1\nf()", {None} | STOPS),
}
N_GOLD = 50


@pytest.fixture(scope="module")
def gold():
    firsts = {}
    for p in gold_programs():
        firsts.setdefault(p.code, p)
        if len(firsts) == N_GOLD:
            break
    return list(firsts.values())


def _exact(results, gold) -> int:
    return sum(1 for ex, p in zip(results, gold) if ex.ok and ex.cells == p.target)


@pytest.mark.parametrize("attack", list(ATTACKS))
def test_execute_after_attack(attack, gold):
    shutdown()
    program, verdicts = ATTACKS[attack]
    for _ in range(2):  # the attack twice: each in a process of its own, forked from the same template
        execute("x = 1")
        before = pool.local().pids()
        ex = execute(program)
        assert ex.error in verdicts, ex.message
        assert pool.local().pids() == before, "the template ran no program: nothing of the attack reached it"
        assert ex.message.isprintable()
        results = [execute(p.code) for p in gold]
        assert _exact(results, gold) == N_GOLD, [r.message for r in results if not r.ok][:3]


@pytest.mark.parametrize("attack", list(ATTACKS))
@pytest.mark.parametrize("workers", [1, 2])
def test_execute_many_after_attack(attack, workers, gold):
    shutdown()
    program, verdicts = ATTACKS[attack]
    # the attack first, in the middle and last of a batch that goes over the workers in chunks
    batch = [program] + [p.code for p in gold] + [program] + [p.code for p in gold] + [program]
    results = execute_many(batch, workers=workers, cache=True)
    attacks = [results[0], results[N_GOLD + 1], results[-1]]
    assert all(ex.error in verdicts for ex in attacks), [ex.message for ex in attacks]
    assert _exact(results[1:N_GOLD + 1], gold) == N_GOLD
    assert _exact(results[N_GOLD + 2:-1], gold) == N_GOLD
    # and a batch of gold alone afterwards, with the code cache on
    assert _exact(execute_many([p.code for p in gold], workers=workers), gold) == N_GOLD


def _readline(proc, timeout=60.0) -> bytes:
    ready = select.select([proc.stdout], [], [], timeout)[0]
    assert ready, "sartco execute did not answer"
    return proc.stdout.readline()


def test_sartco_execute_line_by_line_after_attacks(gold):
    proc = subprocess.Popen([sys.executable, "-m", "sartco", "execute"], stdin=subprocess.PIPE,
                            stdout=subprocess.PIPE, stderr=subprocess.PIPE)
    try:
        for attack, (program, verdicts) in ATTACKS.items():
            for k, code in enumerate([program] + [p.code for p in gold]):
                target = gold[k - 1].target if k else None
                line = json.dumps({"id": f"{attack}-{k}", "code": code, "target": target})
                proc.stdin.write(line.encode() + b"\n")
                proc.stdin.flush()  # one line at a time: each answer before the next line is sent
                answer = _readline(proc)
                answer.decode("utf-8", errors="strict")
                out = json.loads(answer)
                assert out["id"] == f"{attack}-{k}"
                if k == 0:
                    assert (None if out["error"] is None else E(out["error"])) in verdicts, out["message"]
                else:
                    assert out["es"] == 1, (attack, k, out["message"])
    finally:
        proc.stdin.close()
        proc.wait(timeout=60)
    assert proc.returncode == 0, proc.stderr.read().decode()


@pytest.mark.parametrize("how", [signal.SIGKILL, signal.SIGTERM])
def test_workers_die_with_their_parent(how):
    """A parent killed (SIGKILL, SIGTERM) while a program runs a long C loop takes the template
    and the program's process with it."""
    script = (
        "import sys, threading\n"
        "from sartco.program import execute, pool\n"
        "execute('x = 1')\n"
        "print(pool.local().pids()[0], flush=True)\n"
        "execute('x = sum(sum(range(10**6)) for i in range(10**6))', limits=__import__('sartco.program', "
        "fromlist=['Limits']).Limits(wall_time=600.0))\n"
    )
    proc = subprocess.Popen([sys.executable, "-c", script], stdout=subprocess.PIPE)
    template = int(_readline(proc))
    time.sleep(0.5)  # the program's process is inside the C loop now
    with open(f"/proc/{template}/task/{template}/children") as f:
        children = [int(pid) for pid in f.read().split()]
    assert len(children) == 1, children
    proc.send_signal(how)
    proc.wait()
    for _ in range(100):
        if not any(map(_alive, [template, *children])):
            break
        time.sleep(0.1)
    assert not any(map(_alive, [template, *children]))


def _alive(pid: int) -> bool:
    try:
        with open(f"/proc/{pid}/stat") as f:
            return f.read().rsplit(")", 1)[1].split()[0] != "Z"
    except OSError:
        return False


def test_worker_started_from_a_finished_thread_survives():
    """Workers are started by a long-lived thread: one started while a short-lived thread drove
    the pool is not killed by its parent-death signal when that thread ends."""
    import threading

    shutdown()
    t = threading.Thread(target=execute_many, args=(["x = 1"] * 100,), kwargs={"workers": 2})
    t.start()
    t.join()
    time.sleep(0.2)
    ex = execute("put(board, 'nut', 'red', 0, 0)")
    assert ex.ok and ex.cells == {"0:0": [["nut", "red"]]}, ex.message
