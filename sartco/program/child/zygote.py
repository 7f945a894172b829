"""Where a program's child is forked from (issue 43): one process, the zygote, forked by the
template once it is set up and before it has run anything, whose memory is the same at every
fork. The template's own work between two programs (reading chunks, json, select, base64, reads
that depend on timing) leaves Python's allocator in a different state each time; a child forked
from the template would lay the same program's objects at other addresses, and Python hashes
functions, bound methods, NaN, exceptions, ... by address (set orders follow). The zygote does
the same few steps per child and frees what it allocated before the next, so every child starts
from one allocator state; with the template's fixed address layout (isolation.fixed_layout) the
same program then gets the same addresses in every child of every template of one machine and
build (tests/program/test_address_determinism.py).

The zygote shares the template's descriptor table (CLONE_FILES): the template opens a child's
work (a memfd holding the job, pickled) and its answer pipe and asks the zygote for a child
(2 bytes: the two descriptors); the zygote forks it with a pidfd in that table (CLONE_PIDFD),
with which the template watches it and kills it, waits for it and tells the template its wait
status. Where the template has namespaces, the zygote is pid 1 of a pid namespace of its own
(CLONE_NEWPID), without capabilities: a child sees no process but the zygote and cannot signal
it (pid 1 ignores what it does not handle); it dies with the zygote, the zygote with the template.
"""
from __future__ import annotations

import ctypes
import errno
import gc
import os
import pickle
import select
from collections.abc import Callable
from typing import Any

from .confine import PR_SET_PDEATHSIG, SIGKILL
from .isolation import drop_capabilities

CLONE_FILES, CLONE_PIDFD, CLONE_NEWPID, SIGCHLD = 0x400, 0x1000, 0x20000000, 17
# children the template runs before the first program (its self-test, WARM times): the zygote's
# loop starts from states that drift while CPython's adaptive interpreter specialises its code
# (measured once: the 1st-6th children from one state, every later one of 150 from another)
WARM = 16
CLONE = {"x86_64": 56, "aarch64": 220}  # clone(2)'s syscall number (glibc's wrapper needs a stack)


class Zygote:
    """The template's end: `fork(job, answer)` -> a pidfd of a new child that calls born(job,
    answer) (and never returns); `status()` -> its wait status once it has ended."""

    def __init__(self, born: Callable[[Any, int], None]):
        number = CLONE.get(os.uname().machine)
        if number is None:
            raise OSError(errno.ENOSYS, f"clone: no syscall number known for {os.uname().machine}")
        libc = ctypes.PyDLL(None, use_errno=True)  # the GIL held: the template has one thread
        self.ask, ask = os.pipe()[::-1]
        self.tell, tell = os.pipe()
        template, pidfd = os.getpid(), ctypes.c_int(-1)
        for flags in (CLONE_FILES | CLONE_NEWPID | SIGCHLD, CLONE_FILES | SIGCHLD):  # no namespaces: no NEWPID
            pid = libc.syscall(number, flags | CLONE_PIDFD, 0, ctypes.byref(pidfd), 0, 0)
            if pid >= 0 or ctypes.get_errno() not in (errno.EPERM, errno.EINVAL):
                break
        if pid < 0:
            raise OSError(ctypes.get_errno(), "clone")
        if pid == 0:
            try:
                _serve(libc, number, ask, tell, template, flags & CLONE_NEWPID, born)
            finally:
                os._exit(0)
        self.pid, self.pidfd = pid, pidfd.value
        ready = self.status()
        if ready:
            raise OSError(-ready, "the zygote did not start")

    def fork(self, job: Any, answer: int) -> int:
        work = os.memfd_create("work")
        try:
            data = memoryview(pickle.dumps(job))
            while data:
                data = data[os.write(work, data):]
            if max(work, answer) > 255:
                raise OSError(errno.EMFILE, "a child's descriptors must be under 256")
            os.write(self.ask, bytes((work, answer)))
            pidfd = self.status()
        finally:
            os.close(work)
        if pidfd < 0:
            raise OSError(-pidfd, "clone")
        return pidfd

    def status(self) -> int:
        """The zygote's next word; OSError if it has ended (a breached program without namespaces may kill it)."""
        if self.tell not in select.select([self.tell, self.pidfd], [], [])[0]:
            raise OSError(errno.EPIPE, "the zygote ended")
        told = os.read(self.tell, 4)
        if len(told) != 4:
            raise OSError(errno.EPIPE, "the zygote ended")
        return int.from_bytes(told, "little", signed=True)


def _serve(libc: ctypes.CDLL, number: int, ask: int, tell: int, template: int, alone: int,
           born: Callable[[Any, int], None]) -> None:
    """The zygote's life: one child per request, each forked from the same memory (every object
    of an iteration is freed before the next; the garbage collector is off here)."""
    try:
        libc.prctl(PR_SET_PDEATHSIG, SIGKILL, 0, 0, 0)
        if os.getppid() != (0 if alone else template):  # 0: the parent is outside its pid namespace
            return
        if alone:
            drop_capabilities()
        me, pidfd = os.getpid(), ctypes.c_int()
        where = ctypes.byref(pidfd)
    except BaseException:
        os.write(tell, (-errno.EIO).to_bytes(4, "little", signed=True))
        raise
    gc.disable()
    os.write(tell, bytes(4))
    while True:
        fds = os.read(ask, 2)
        if len(fds) != 2:
            return
        pid = libc.syscall(number, CLONE_PIDFD | SIGCHLD, 0, where, 0, 0)
        if pid == 0:
            gc.enable()
            libc.prctl(PR_SET_PDEATHSIG, SIGKILL, 0, 0, 0)
            if os.getppid() == me:
                born(pickle.loads(os.pread(fds[0], os.lseek(fds[0], 0, os.SEEK_END), 0)), fds[1])
            return
        if pid < 0:
            os.write(tell, (-ctypes.get_errno()).to_bytes(4, "little", signed=True))
        else:
            os.write(tell, pidfd.value.to_bytes(4, "little", signed=True))
            status = os.waitpid(pid, 0)[1]
            os.write(tell, status.to_bytes(4, "little", signed=True))
            del status
        del fds, pid
