"""Injected harness faults, shared by tests/program and tests/games (issue 21).

- fake_worker(monkeypatch, misbehave)   the pool's next workers are a stand-in that says ready,
                                        reads each batch, then runs `misbehave` (Python, with
                                        `n` the batch's item count): garbage answers, an exit
- no_worker(monkeypatch, why)           no worker can start ("sandbox unavailable: <why>")
"""
from sartco.program import handle

FAKE_WORKER = """
import json, sys
sys.stdin.readline()  # the seccomp filter
print('"ready"', flush=True)
while True:
    header = sys.stdin.readline()
    if not header:
        sys.exit(0)
    n = json.loads(header)["items"]
    for _ in range(n):
        sys.stdin.readline()
    {misbehave}
"""


def fake_worker(monkeypatch, misbehave: str) -> None:
    monkeypatch.setattr(handle, "_BOOT", FAKE_WORKER.format(misbehave=misbehave))


def no_worker(monkeypatch, why: str) -> None:
    def cannot_start(self):
        raise handle._Dead(why)

    monkeypatch.setattr(handle.TemplateHandle, "start", cannot_start)
