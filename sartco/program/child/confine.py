"""The kernel's walls around one program's process: a seccomp filter and rlimits.

These walls hold when every Python-level check of the sandbox has fallen (a program that reached
the real builtins, ctypes, any syscall): what the filter does not allow fails with EPERM, and the
rlimits stop what the program may take. The template process (template.py) builds the filter once
(`Filter()`, through libseccomp: the `pyseccomp` binding of the system's libseccomp.so.2); each
forked child applies it with `Filter.apply(limits, base)` before the program's first line.

The filter is an allow-list, for this machine's architecture only (a call through another ABI,
such as int 0x80 on x86_64, kills the process): what a program's process needs to compute and to
write its answer to the pipe it was given. Everything else fails with EPERM, among it: opening,
creating, renaming or removing files (open, openat, openat2, creat, mkdir, unlink, rename, link,
symlink, mknod, truncate, chmod, chown, utime, open_by_handle_at, memfd_create), looking at paths
(stat, access, readlink, getdents, chdir), sockets of every kind, exec, fork/vfork/clone/clone3 (no
new process or thread), signals to any process (kill, tkill, tgkill, rt_sigqueueinfo, pidfd_*),
ptrace and process_vm_*, raising limits (setrlimit, prlimit64 with a new value), io_uring, bpf,
perf_event_open, userfaultfd, SysV and POSIX IPC (which would outlive the process), keyrings,
mount, namespaces, module loading, clocks, reboot.

rlimits: address space (the template's size at start + Limits.memory: a blow-up is a
MemoryError or the kernel's refusal, reported `resource_limit`), CPU seconds (the wall time,
rounded up, plus one: SIGXCPU is `resource_limit`; the template's kill at the wall time normally
comes first), file size 0, open files (the four descriptors the child keeps), processes 0, no
core files.

Where the kernel cannot confine (no libseccomp, no seccomp in the kernel, not Linux),
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
import tempfile
from typing import TYPE_CHECKING

if TYPE_CHECKING:
    from ..execution import Limits

# what a program's process may call (names libseccomp knows; a name this architecture lacks is skipped)
ALLOWED = (
    # memory
    "brk", "mmap", "munmap", "mremap", "mprotect", "madvise", "membarrier",
    # the descriptors it was given (0-2: /dev/null, 3: its answer pipe)
    "read", "write", "readv", "writev", "pread64", "pwrite64", "close", "lseek", "fstat", "fcntl", "dup",
    "dup2", "dup3", "poll", "ppoll", "select", "pselect6",
    # its own signals and threads' bookkeeping (no new thread can start: clone is not allowed)
    "rt_sigaction", "rt_sigprocmask", "rt_sigreturn", "sigaltstack", "futex", "set_robust_list", "rseq",
    "sched_yield", "sched_getaffinity", "restart_syscall",
    # who and when
    "getpid", "gettid", "getppid", "getuid", "geteuid", "getgid", "getegid", "getrandom", "clock_gettime",
    "clock_getres", "clock_nanosleep", "nanosleep", "gettimeofday", "time", "getrusage", "times",
    "getrlimit", "uname", "sysinfo", "getpriority",
    # the end
    "exit", "exit_group", "wait4", "waitid",
)
# fstat is newfstatat(fd, "", buf, AT_EMPTY_PATH) in glibc 2.33 and later; a path given with
# AT_EMPTY_PATH would be looked at too, so only the empty-path form of the descriptors 0-3 passes
AT_EMPTY_PATH = 0x1000
KEPT_FDS = 4  # 0, 1, 2 (/dev/null) and 3 (the answer pipe)

PR_SET_NO_NEW_PRIVS = 38
PR_SET_SECCOMP = 22
SECCOMP_MODE_FILTER = 2
PR_SET_PDEATHSIG = 1
SIGKILL = 9


class Unconfinable(Exception):
    """The kernel's walls cannot be built here: the reason, for a message."""


class _SockFprog(ctypes.Structure):
    _fields_ = [("len", ctypes.c_ushort), ("filter", ctypes.c_void_p)]


def compile_filter() -> bytes:
    """The filter as a BPF program (bytes), compiled by libseccomp through pyseccomp in the parent
    (the template runs without site-packages: it gets these bytes and needs only ctypes)."""
    try:
        import pyseccomp as seccomp
    except (ImportError, RuntimeError, OSError) as exc:  # RuntimeError: pyseccomp finds no libseccomp
        raise Unconfinable(f"libseccomp is not usable ({exc}); install the system's libseccomp2 and "
                           f"`pip install pyseccomp` (a dependency of sartco-bench)") from None
    try:
        rules = seccomp.SyscallFilter(seccomp.ERRNO(errno.EPERM))
        for name in ALLOWED:
            try:
                rules.add_rule(seccomp.ALLOW, name)
            except (OSError, ValueError, RuntimeError):  # not a syscall of this architecture
                pass
        rules.add_rule(seccomp.ALLOW, "newfstatat", seccomp.Arg(0, seccomp.LT, KEPT_FDS),
                       seccomp.Arg(3, seccomp.MASKED_EQ, AT_EMPTY_PATH, AT_EMPTY_PATH))
        rules.add_rule(seccomp.ALLOW, "prlimit64", seccomp.Arg(0, seccomp.EQ, 0), seccomp.Arg(2, seccomp.EQ, 0))
        with tempfile.TemporaryFile() as file:
            rules.export_bpf(file)
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
