"""The stage processes of `sartco bench-execute --breakdown` (sartco/program/costs.py has the
stages and the parent's side): each runs as a template does, with a template's imports and no
more (the parent's modules stay out, as tests/program/test_template_imports.py keeps them out of
a template), and counts the CPU and page faults per program of itself and its children."""
from __future__ import annotations

import base64
import ctypes
import gc
import json
import os
import resource
from array import array
from collections.abc import Callable, Iterator
from functools import partial
from typing import TYPE_CHECKING, BinaryIO

from ..execution import MODULE, Limits

if TYPE_CHECKING:
    from .template import Template


def stage(name: str, inp: BinaryIO, out: BinaryIO) -> int:
    """In a stage process, as a template reads and answers: the filter (a line of base64), then a
    line per program (JSON [source, item]); writes the answer of each (stage "program": base64;
    the others: an empty line), then the CPU ms and page faults per program (JSON). The
    zygotes are ended and reaped before the count, so that their children's CPU is in it."""
    bpf = base64.b64decode(inp.readline())
    programs = _preloaded(inp) if name == "least" else (json.loads(line) for line in iter(inp.readline, b""))

    from .template import Template
    from .zygote import Zygote

    template = Template(bpf)  # its imports, then every object frozen
    template.start()
    if name == "least":
        gc.disable()  # as in a zygote: this process collects nothing between its forks
    limits = Limits()
    bare = Zygote(_exit_at_once) if name == "template" else None
    fork = ctypes.PyDLL(None, use_errno=True).fork  # the GIL held: this process has one thread

    def run(source: str, item: bytes) -> bytes:
        if name == "least":
            return _least(template, fork, partial(_program, item, limits), limits)
        if bare is not None:
            read, write = os.pipe()
            pidfd = bare.fork(None, write)
            os.close(write)
            bare.status()  # the zygote waits for it
            for fd in (pidfd, read):
                os.close(fd)
            return b""
        work = {"walls": partial(_nothing), "program": partial(_program, item, limits),
                "compiled in the child": partial(_compiled_in_the_child, source, limits)}[name]
        return template.fork(work, limits)[2]

    start, faults, n = os.times(), _faults(), 0
    for source, item in programs:
        out.write(base64.b64encode(run(source, item.encode())) + b"\n")
        n += 1
    for zygote in (template.zygote, bare):
        if zygote is not None:
            os.close(zygote.ask)
            os.waitpid(zygote.pid, 0)
    end, faults = os.times(), _faults() - faults
    out.write(json.dumps([(sum(end[:4]) - sum(start[:4])) / max(1, n) * 1e3, faults / max(1, n)]).encode() + b"\n")
    return 0


# what a stage's children run (pickled to them by reference: module-level functions)
def _exit_at_once(job: object, answer: int) -> None:
    os._exit(0)


def _nothing() -> bytes:
    return b""


def _program(item: bytes, limits: Limits) -> bytes:
    from . import runtime

    return runtime.answer_item(item, 8, 8, limits, MODULE)


def _compiled_in_the_child(source: str, limits: Limits) -> bytes:
    from . import runtime

    return runtime.answer(runtime.compile_program(source, limits), 8, 8, limits, MODULE)


def _least(template: Template, fork: Callable[[], int], work: Callable[[], bytes], limits: Limits) -> bytes:
    """Stage "least": work() in a confined child forked straight from this process; its answer."""
    from .template import CONFINED, _one

    read, write = os.pipe()
    pid = fork()
    if pid == 0:
        gc.enable()
        template._child(partial(_one, work), limits, write)  # never returns
    os.close(write)
    chunks = []
    while chunk := os.read(read, 1 << 16):
        chunks.append(chunk)
    os.close(read)
    os.waitpid(pid, 0)
    return b"".join(chunks)[len(CONFINED):]


def _preloaded(inp: BinaryIO) -> Iterator[tuple[str, str]]:
    """Stage "least": every program's item read now, before the template's imports, into a
    memfd (this process then holds no more than a template does); yields ("", item) of each,
    read back one at a time."""
    fd, offsets = os.memfd_create("items"), array("q", [0])
    for line in iter(inp.readline, b""):
        item = json.loads(line)[1].encode()
        os.write(fd, item)
        offsets.append(offsets[-1] + len(item))
    return (("", os.pread(fd, offsets[i + 1] - offsets[i], offsets[i]).decode()) for i in range(len(offsets) - 1))


def _faults() -> int:
    """Page faults (minor and major) of this process and of the children it reaped."""
    return sum(r.ru_minflt + r.ru_majflt for r in map(resource.getrusage, (resource.RUSAGE_SELF,
                                                                            resource.RUSAGE_CHILDREN)))
