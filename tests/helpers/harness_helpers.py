"""Injected harness faults, shared by tests/program and tests/games (issue 21).

- fake_worker(monkeypatch, misbehave)   the pool's next workers are a stand-in that says ready,
                                        reads each batch, then runs `misbehave` (Python, with
                                        `n` the batch's item count): garbage answers, an exit
- no_worker(monkeypatch, why)           no worker can start ("sandbox unavailable: <why>")
- answering_worker(monkeypatch, misbehave)  a stand-in that answers each program "ok, no board"
                                        after running `misbehave` (Python, with `source` the
                                        program's text): dies or hangs on some (issue 42)
"""
import base64

from sartco.program import handle

_STAND_IN = """
import base64, json, marshal, os, sys, time
sys.stdin.readline()  # the seccomp filter
print('"ready"', flush=True)
while True:
    header = sys.stdin.readline()
    if not header:
        sys.exit(0)
    n = json.loads(header)["items"]
"""
FAKE_WORKER = _STAND_IN + """
    for _ in range(n):
        sys.stdin.readline()
    {misbehave}
"""
ANSWERING_WORKER = _STAND_IN + """
    for _ in range(n):
        source = marshal.loads(base64.b64decode(sys.stdin.readline()))[1]  # (code, source): compiled.prepare
        {misbehave}
        print("exit 0 {answer}", flush=True)
"""
OK_NO_BOARD = base64.b64encode(b'[true, null, "", 0, 0, []]').decode()


def fake_worker(monkeypatch, misbehave: str) -> None:
    monkeypatch.setattr(handle, "_BOOT", FAKE_WORKER.format(misbehave=misbehave))


def answering_worker(monkeypatch, misbehave: str) -> None:
    monkeypatch.setattr(handle, "_BOOT", ANSWERING_WORKER.format(misbehave=misbehave, answer=OK_NO_BOARD))


def no_worker(monkeypatch, why: str) -> None:
    def cannot_start(self):
        raise handle._Dead(why)

    monkeypatch.setattr(handle.TemplateHandle, "start", cannot_start)
