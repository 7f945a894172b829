"""A big call's programs on their way to the templates (issue 46).

`parts` cuts a call's programs for the parent's compile: FIRST, then twice as many each time,
never inside one answer's programs. A `Feed` holds each part once it is compiled, and each
template's run takes its next programs from it whenever the template runs low
(handle.TemplateHandle.run's `more`): the templates start on the first part while the parent
compiles the next, none waits for another between parts, and they end a call together (a take
hands out a share of what is left, smaller as the call ends). `Background` runs a call's dispatch
on a daemon thread while the parent compiles.
"""
from __future__ import annotations

import threading
from collections import deque
from collections.abc import Callable
from typing import Generic, TypeVar

FIRST = 64  # programs of a big call compiled before the templates start on them (parts)
GRAIN = 8  # the fewest programs a take hands out while more are ready (an answer's are never split)
AHEAD = 32  # programs a template may have left to run before its run asks `more` for the next
T = TypeVar("T")
More = Callable[[], tuple[list[bytes], frozenset[int]]]  # TemplateHandle.run's `more`: the next items, their starts


def parts(todo: list[int], labels: list[object] | None = None) -> list[list[int]]:
    """The programs of a call (`todo`, their indices), in the order given, in parts of FIRST,
    2 x FIRST, 4 x FIRST, ... programs: the templates start on the first part while the parent
    compiles the next, and the parts soon outgrow their compiles (a compile is a fraction of a
    run). A part never ends inside one answer's programs (`labels`, mode ANSWER: one child each)."""
    cuts: list[list[int]] = []
    start, size = 0, FIRST
    while start < len(todo):
        end = min(start + size, len(todo))
        while labels is not None and end < len(todo) and labels[todo[end]] == labels[todo[end - 1]]:
            end += 1
        cuts.append(todo[start:end])
        start, size = end, 2 * size
    return cuts


class Feed:
    """The compiled programs of one call (their indices), in order, for `takers` templates.
    `labels` (mode ANSWER): one per index; a take never splits one answer's programs."""

    def __init__(self, total: int, takers: int, labels: list[object] | None = None):
        self.takers, self.labels = takers, labels
        self._ready: deque[int] = deque()
        self._left = total  # programs not taken yet, compiled or not
        self._open, self._stopped = True, False
        self._cv = threading.Condition()

    def put(self, indices: list[int], of: int) -> None:
        """A compiled part: the indices that run, of `of` programs (the others never run)."""
        with self._cv:
            self._ready.extend(indices)
            self._left -= of - len(indices)
            self._cv.notify_all()

    def close(self) -> None:
        """Every part is in."""
        with self._cv:
            self._open = False
            self._cv.notify_all()

    def stop(self) -> None:
        """The call has ended (or failed): nothing more is handed out."""
        with self._cv:
            self._stopped = True
            self._cv.notify_all()

    def take(self) -> list[int]:
        """The next programs of one template, once some are ready ([]: none will be): a share of
        what is left (of what is ready, while the parent compiles), whole answers, GRAIN at least;
        with one taker, all that is ready."""
        with self._cv:
            while not self._ready and self._open and not self._stopped:
                self._cv.wait()
            if self._stopped or not self._ready:
                return []
            share = len(self._ready) if self.takers == 1 else \
                min(-(-self._left // (2 * self.takers)), -(-len(self._ready) // self.takers))
            batch = [self._ready.popleft() for _ in range(min(max(GRAIN, share), len(self._ready)))]
            while self.labels is not None and self._ready and self.labels[self._ready[0]] == self.labels[batch[-1]]:
                batch.append(self._ready.popleft())
            self._left -= len(batch)
            return batch

    def done(self) -> bool:
        """Nothing more will be handed out: every part is in and taken."""
        with self._cv:
            return self._stopped or not (self._ready or self._open)

    def starts(self, batch: list[int]) -> frozenset[int]:
        """Where a new answer starts in a batch (mode ANSWER; else none)."""
        if self.labels is None:
            return frozenset()
        labels = self.labels
        return frozenset(k for k, i in enumerate(batch) if k == 0 or labels[i] != labels[batch[k - 1]])


class Stream:
    """The items of one template's run (handle.TemplateHandle.run) as they grow: the reader waits here for items to
    read answers of, the writer for the template to run low before it asks `more` for the next."""

    def __init__(self, items: list[bytes], starts: set[int], more: More | None,
                 longest: Callable[[list[bytes], frozenset[int]], int]):
        self.items, self.starts, self.more, self._measure = items, starts, more, longest
        self.ended = more is None  # `more` has handed out its last
        self.dead = False  # the reader gave up on this template: the writer stops
        self.answered = 0
        self.longest = longest(items, frozenset(starts))  # the most items of one chunk so far
        self.error: BaseException | None = None
        self.cv = threading.Condition()

    def next(self, answered: int) -> bool:
        """The reader's wait for item `answered` to be sent: False when there is none to come."""
        with self.cv:
            self.answered = answered
            self.cv.notify_all()
            while answered == len(self.items) and not self.ended:
                self.cv.wait()
            return answered < len(self.items)

    def write(self, send: Callable[..., None], items: list[bytes], starts: frozenset[int]) -> None:
        """The writer of a run: send(items, starts=...) the items not sent yet, then what `more`
        hands out while the template runs the last of them, until it hands out none or the
        template has failed (`dead`)."""
        while items:
            send(items, starts=starts)
            items, starts = self.pull()

    def pull(self) -> tuple[list[bytes], frozenset[int]]:
        """The writer's next items and their chunks' starts, once the template has fewer than AHEAD
        left ([]: no more)."""
        with self.cv:
            while not self.dead and not self.ended and len(self.items) - self.answered > AHEAD:
                self.cv.wait()
            if self.dead or self.ended:
                return [], frozenset()
        try:
            got, starts = self.more()  # type: ignore[misc]
        except BaseException as exc:  # raised by run(), in its caller's thread
            got, starts, self.error = [], frozenset(), exc
        with self.cv:
            if got:
                self.starts.update(len(self.items) + k for k in starts)
                self.longest = max(self.longest, self._measure(got, starts))
                self.items.extend(got)
            self.ended = not got
            self.cv.notify_all()
            return ([], frozenset()) if self.dead else (got, starts)

    def stop(self) -> None:
        """The template failed: the writer asks for nothing more."""
        with self.cv:
            self.dead = True
            self.cv.notify_all()

    def drain(self) -> None:
        """Everything `more` has left, into items (to be failed: no template could start)."""
        while not self.ended:
            got, starts = self.more()  # type: ignore[misc]
            self.ended = not got
            self.items.extend(got)


class Background(Generic[T]):
    """`job` on a daemon thread of its own: a caller interrupted meanwhile (Ctrl-C) and a process
    that ends do not wait for it (nor for the template threads it starts, daemons too)."""

    def __init__(self, job: Callable[[], T]):
        self._job = job
        self._out: T | BaseException | None = None
        self._thread = threading.Thread(target=self._run, daemon=True, name="sartco-feeder")
        self._thread.start()

    def _run(self) -> None:
        try:
            self._out = self._job()
        except BaseException as exc:  # raised by result(), in the caller's thread
            self._out = exc

    def result(self) -> T:
        self._thread.join()
        if isinstance(self._out, BaseException):
            raise self._out
        return self._out  # type: ignore[return-value]
