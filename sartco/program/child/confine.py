"""The kernel's walls around one program's process, in two layers that each stand alone.

Layer 1, in every child: a seccomp filter and rlimits. These hold when every Python-level check
of the sandbox has fallen (a program that reached the real builtins, ctypes, any syscall): what
the filter does not allow fails with EPERM, and the rlimits stop what the program may take. The
parent compiles the filter once (`compile_filter()`, through libseccomp: the `pyseccomp` binding
of the system's libseccomp.so.2); the template (template.py) loads it (`Walls`), and each forked
child applies it with `Walls.apply(limits, base)` before the program's first line.

The filter is an allow-list that names the arguments it allows (RULES, with the reason for each;
docs/sandbox.md shows it as a table, `table()`), for this machine's architecture only (a call
through another ABI, x32 or int 0x80 on x86_64, kills the process): memory that is never
executable, the four descriptors the child was given, its own signal handling, its own id, the
clock, the end. Everything else fails with EPERM, among it: opening, creating, renaming or
removing files, looking at paths, sockets of every kind, exec, fork/vfork/clone/clone3 (no new
process or thread), signals to any process (kill, tkill, tgkill, rt_sigqueueinfo, pidfd_*, and
fcntl, whose F_SETOWN/F_SETSIG with O_ASYNC on the answer pipe made the kernel signal any pid),
ptrace and process_vm_*, raising limits, io_uring, bpf, perf_event_open, userfaultfd, IPC,
keyrings, mount, namespaces, module loading, uname, sysinfo, reboot.

rlimits: address space (the template's size at start + Limits.memory: a blow-up is a
MemoryError or the kernel's refusal, reported `resource_limit`), CPU seconds (the wall time,
rounded up, plus one: SIGXCPU is `resource_limit`; the template's kill at the wall time normally
comes first), file size 0, open files (the four descriptors the child keeps), processes 0, no
core files.

Layer 2, entered once by the template at its start (isolation.py): new user, pid, net, ipc, uts
and mount namespaces. The template is pid 1
of its pid namespace (its children are the only other processes there; pid 1 ignores every
signal it does not handle, and it handles none), it has no network, its root is an empty
read-only tmpfs, and it holds no capability. Where the kernel refuses them the template goes on
with layer 1 and says which walls are down (walls.py). A program's child costs nothing more.

Where the kernel cannot build layer 1 (no libseccomp, no seccomp in the kernel, not Linux),
`compile_filter()` or the template's self-test (a confined child that tries to open a file)
raises Unconfinable with the reason; then no program runs at all (the parent reports every
program `harness_error`, "sandbox unavailable: the sandbox cannot confine programs here: ...").
A sandbox never runs a program unconfined.
"""
from __future__ import annotations

import ctypes
import errno
import math
import resource
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any

if TYPE_CHECKING:
    from ..execution import Limits

KEPT_FDS = 4  # 0, 1, 2 (/dev/null) and 3 (the answer pipe)
# flags the rules name (Linux's values, the same on every architecture this runs on)
PROT_EXEC, MAP_ANONYMOUS, MREMAP_MAYMOVE = 0x4, 0x20, 0x1
FUTEX_WAIT, FUTEX_WAKE, FUTEX_WAIT_BITSET, FUTEX_WAKE_BITSET = 0, 1, 9, 10
FUTEX_PRIVATE_FLAG, FUTEX_CLOCK_REALTIME = 128, 256
CLOCK_BOOTTIME = 7  # the highest of the system-wide and own clocks (lower ids; negative ones are other processes')
LOW32 = 0xFFFFFFFF  # the kernel reads an int argument from the low 32 bits of its register


@dataclass(frozen=True)
class Rule:
    """One syscall a program's process may make: why, and with which arguments. `when` holds the
    alternatives (any one passes), each a tuple of conditions that must all hold: (argument index,
    "eq" | "lt" | "le", value) or (argument index, "masked", mask, value): (arg & mask) == value.
    An empty `when` allows any arguments."""
    name: str
    why: str
    arguments: str  # `when` in words, for docs/sandbox.md
    when: tuple[tuple[tuple[Any, ...], ...], ...] = ()


_OWN_FD = ((0, "lt", KEPT_FDS),)
_FUTEX_OPS = tuple(((1, "masked", LOW32 & ~(FUTEX_PRIVATE_FLAG | FUTEX_CLOCK_REALTIME), op),)
                   for op in (FUTEX_WAIT, FUTEX_WAKE, FUTEX_WAIT_BITSET, FUTEX_WAKE_BITSET))
# The allow-list, measured: under strace -f, the confined children of the honest corpus (both
# semantics), 600 gold programs (each alone and in gold mode), the budget stops (memory, time,
# depth, integer size) and growing lists, strings and dicts made only write (fd 3), exit_group,
# brk, mmap (anonymous, read/write), munmap and mremap (MREMAP_MAYMOVE), on Python 3.11.7, 3.12.1
# and 3.13.0 (numpy is not loaded: the template runs without site-packages). The rest is what
# glibc and CPython may call on the same paths (a signal handler's return, abort, a lock, the
# clock where the vDSO cannot read it) and reaches nothing outside the process.
RULES = (
    Rule("brk", "the heap (malloc)", "any"),
    Rule("mmap", "memory for objects (malloc, Python's arenas)", "anonymous (MAP_ANONYMOUS), never PROT_EXEC",
         (((2, "masked", PROT_EXEC, 0), (3, "masked", MAP_ANONYMOUS, MAP_ANONYMOUS)),)),
    Rule("munmap", "memory given back", "any (its own memory)"),
    Rule("mremap", "a big block grown or shrunk (realloc)", "flags 0 or MREMAP_MAYMOVE",
         (((3, "masked", LOW32 & ~MREMAP_MAYMOVE, 0),),)),
    Rule("mprotect", "glibc's heaps and guard pages", "never PROT_EXEC", (((2, "masked", PROT_EXEC, 0),),)),
    Rule("write", "the answer to its pipe", "descriptors 0-3 (/dev/null, the answer pipe)", (_OWN_FD,)),
    Rule("read", "its descriptors (nothing reads them today)", "descriptors 0-3", (_OWN_FD,)),
    Rule("close", "its descriptors", "descriptors 0-3", (_OWN_FD,)),
    Rule("rt_sigaction", "its own signal handlers (CPython's, glibc's abort)", "any (this process only)"),
    Rule("rt_sigprocmask", "its own signal mask (glibc's abort)", "any (this process only)"),
    Rule("rt_sigreturn", "the return from a signal handler (e.g. SIGINT of a Ctrl-C)", "none"),
    Rule("sigaltstack", "its own signal stack", "any (this process only)"),
    Rule("restart_syscall", "a call interrupted by a signal, restarted by the kernel", "none"),
    Rule("futex", "glibc's and CPython's locks", "FUTEX_WAIT, FUTEX_WAKE and their _BITSET forms, private or "
         "not (no requeue, no PI, no FUTEX_FD)", _FUTEX_OPS),
    Rule("getpid", "its own id (glibc's abort/raise)", "none"),
    Rule("gettid", "its own id (glibc's abort/raise)", "none"),
    Rule("clock_gettime", "the time, where the vDSO falls back to the kernel", f"clocks 0-{CLOCK_BOOTTIME} "
         "(the system's and its own; not another process's CPU clock)", (((0, "le", CLOCK_BOOTTIME),),)),
    Rule("exit", "the end", "any"),
    Rule("exit_group", "the end", "any"),
)
# Not allowed (EPERM), among them the calls issue 32's list had and no program's process makes:
# fcntl (F_SETOWN/F_SETOWN_EX/F_SETSIG with O_ASYNC made the kernel signal any pid), dup*, fstat,
# lseek, readv/writev/pread/pwrite, poll/select, madvise, membarrier, sched_yield/getaffinity,
# set_robust_list, rseq, getppid/getuid/..., getrandom, the other clocks and sleeps, getrusage,
# times, getrlimit/prlimit64, uname, sysinfo, getpriority, wait4/waitid.


def table() -> str:
    """RULES as docs/sandbox.md's table (tests/program/test_walls_syscalls.py keeps the two equal)."""
    rows = ["| syscall | why a program's process may make it | arguments allowed |", "|---|---|---|"]
    rows += [f"| `{rule.name}` | {rule.why} | {rule.arguments} |" for rule in RULES]
    return "\n".join(rows)


PR_SET_NO_NEW_PRIVS = 38
PR_SET_SECCOMP = 22
SECCOMP_MODE_FILTER = 2
PR_SET_PDEATHSIG = 1
SIGKILL = 9


class Unconfinable(Exception):
    """The kernel's walls cannot be built here: the reason, for a message."""


class _SockFprog(ctypes.Structure):
    _fields_ = [("len", ctypes.c_ushort), ("filter", ctypes.c_void_p)]


def compile_filter(rules: tuple[Rule, ...] = RULES) -> bytes:
    """The filter as a BPF program (bytes), compiled by libseccomp through pyseccomp in the parent
    (the template runs without site-packages: it gets these bytes and needs only ctypes)."""
    import tempfile  # here: the template, which only loads the filter, never imports it

    try:
        import pyseccomp as seccomp
    except (ImportError, RuntimeError, OSError) as exc:  # RuntimeError: pyseccomp finds no libseccomp
        raise Unconfinable(f"libseccomp is not usable ({exc}); install the system's libseccomp2 and "
                           f"`pip install pyseccomp` (a dependency of sartco-bench)") from None
    try:
        built = seccomp.SyscallFilter(seccomp.ERRNO(errno.EPERM))
        ops = {"eq": seccomp.EQ, "lt": seccomp.LT, "le": seccomp.LE, "masked": seccomp.MASKED_EQ}
        for rule in rules:
            for conditions in rule.when or ((),):
                built.add_rule(seccomp.ALLOW, rule.name, *(seccomp.Arg(i, ops[op], *values) for i, op, *values in conditions))
        with tempfile.TemporaryFile() as file:
            built.export_bpf(file)
            file.seek(0)
            return file.read()
    except Exception as exc:
        raise Unconfinable(f"libseccomp could not build the filter: {type(exc).__name__}: {exc}") from None


class Walls:
    """The rlimits and the compiled filter, applied by `apply` to a freshly forked child."""

    def __init__(self, bpf: bytes):
        if not bpf or len(bpf) % 8:
            raise Unconfinable(f"the seccomp filter is not a BPF program ({len(bpf)} bytes)")
        try:
            libc = ctypes.CDLL(None, use_errno=True)
            self._prctl = libc.prctl
        except (OSError, AttributeError) as exc:
            raise Unconfinable(f"no prctl here ({exc})") from None
        self._prctl.argtypes = (ctypes.c_int, ctypes.c_ulong, ctypes.c_void_p, ctypes.c_ulong, ctypes.c_ulong)
        self.bpf = ctypes.create_string_buffer(bpf, len(bpf))
        self.program = _SockFprog(len(bpf) // 8, ctypes.addressof(self.bpf))

    def apply(self, limits: Limits, base: int) -> None:
        """Confine this process (a freshly forked child): the rlimits, death with the template,
        no new privileges, the filter. Raises OSError when the kernel refuses one of them."""
        for kind, value in (
            (resource.RLIMIT_AS, base + limits.memory),
            (resource.RLIMIT_CPU, math.ceil(limits.wall_time) + 1),
            (resource.RLIMIT_FSIZE, 0), (resource.RLIMIT_NOFILE, KEPT_FDS),
            (resource.RLIMIT_NPROC, 0), (resource.RLIMIT_CORE, 0),
        ):
            resource.setrlimit(kind, (value, value))
        for option, arg in ((PR_SET_PDEATHSIG, SIGKILL), (PR_SET_NO_NEW_PRIVS, 1)):
            if self._prctl(option, arg, None, 0, 0) != 0:
                raise OSError(ctypes.get_errno(), "prctl")
        if self._prctl(PR_SET_SECCOMP, SECCOMP_MODE_FILTER, ctypes.addressof(self.program), 0, 0) != 0:
            raise OSError(ctypes.get_errno(), "prctl(PR_SET_SECCOMP)")
