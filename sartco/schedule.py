"""The scheduler of `sartco suite` (sartco/suite.py): tasks that wait for each other, on a few
forked worker processes whose output goes to a log file; a worker keeps to one group of tasks
while the group has tasks to run (its process keeps the probe draws of the boards it probed), and the
CPU time of each task is measured where it ran (its sandbox processes included).
"""
from __future__ import annotations

import multiprocessing
import os
import queue
import sys
from dataclasses import dataclass
from pathlib import Path

LOG = "main.log"
CLEM_SETTINGS = (0.0, 300)    # clem run's defaults


@dataclass(frozen=True)
class Task:
    """One step: `kind` prepare (a command's argv) or play (a game/model pair), and the steps it waits for."""
    name: str
    kind: str
    argv: tuple = ()
    game: str = ""
    model: str = ""
    settings: tuple = CLEM_SETTINGS
    after: tuple = ()
    index: int = 0          # a play's place in the plan (its stage folder)
    instances: str | None = None  # a play's instance file (clem run's -i), None: the game's own
    group: str = ""         # plays that share work a process keeps (a worker keeps to one group)
    batch_size: int = 1     # a play's clem run -b


@dataclass
class Done:
    name: str
    ok: bool
    wall: float
    cpu: float
    message: str = ""


def _worker_start(log: str) -> None:
    """A worker's output (clemcore's logs, progress bars) goes to the log file."""
    fd = os.open(log, os.O_WRONLY | os.O_APPEND | os.O_CREAT, 0o644)
    sys.stdout.flush()
    sys.stderr.flush()
    os.dup2(fd, 1)
    os.dup2(fd, 2)
    os.close(fd)


def _serve(work, inbox, outbox, results: str, log: str) -> None:
    """A worker process: tasks from its inbox until None, each work(task, results) (a Done) to the outbox."""
    _worker_start(log)
    while (task := inbox.get()) is not None:
        outbox.put(work(task, results))


def _pick(ready: list[Task], last: str | None, busy: set[str], pending: list[Task]) -> Task | None:
    """The task a free worker takes: the next of the group it played last (its process keeps what
    that group shares: the probe draws of the same boards), else one of a group no other worker
    is playing, else one of a group with more tasks waiting than this one; None (wait) when the
    only ready task is the last of a group another worker is playing: that worker will find the
    group's work done."""
    same = next((t for t in ready if t.group and t.group == last), None)
    free = next((t for t in ready if t.group not in busy), None)
    shared = next((t for t in ready if sum(p.group == t.group for p in pending) > 1), None)
    return same or free or shared


def schedule(work, tasks: list[Task], workers: int, results: Path, say, priority: tuple = ()) -> list[Done]:
    """Run work(task, results) for the tasks on `workers` processes (forked now: what the caller
    imported is imported there), each as soon as
    the ones it waits for are done: the preparations first, then the plays by `priority` (games), a worker
    keeping to one group while it has plays to run; stop starting new ones after a failure."""
    context = multiprocessing.get_context("fork")
    outbox = context.Queue()
    order = {game: n for n, game in enumerate(priority)}
    pending = sorted(tasks, key=lambda t: (t.kind != "prepare", order.get(t.game, len(order)), t.index))
    inboxes = [context.Queue() for _ in range(workers)]
    procs = [context.Process(target=_serve, args=(work, inbox, outbox, str(results), str(results / LOG)), daemon=True)
             for inbox in inboxes]
    for proc in procs:
        proc.start()
    done: dict[str, Done] = {}
    last: list[str | None] = [None] * workers
    running: dict[int, Task] = {}
    try:
        while pending or running:
            failed = any(not d.ok for d in done.values())
            for w in range(workers):
                ready = [t for t in pending if all(a in done and done[a].ok for a in t.after)]
                if w in running or failed or not ready:
                    continue
                task = _pick(ready, last[w], {t.group for t in running.values()}, pending)
                if task is None:
                    continue
                pending.remove(task)
                running[w], last[w] = task, task.group or last[w]
                inboxes[w].put(task)
            if failed and not running:
                break
            try:
                finished = outbox.get(timeout=5)
            except queue.Empty:
                dead = [w for w in running if not procs[w].is_alive()]
                if not dead:
                    continue
                task = running[dead[0]]
                finished = Done(task.name, False, 0.0, 0.0, f"its worker process died (exit {procs[dead[0]].exitcode})")
            done[finished.name] = finished
            del running[next(w for w, t in running.items() if t.name == finished.name)]
            say(finished)
    finally:
        for inbox in inboxes:
            inbox.put(None)
        for proc in procs:
            proc.join(timeout=30)
            if proc.is_alive():
                proc.kill()
    return [done[t.name] for t in tasks if t.name in done]
