"""The second wall, around the template (issue 42): new user, pid, net, ipc, uts and mount
namespaces, entered once when it starts (template.main), an empty read-only root once it has
imported what programs need, and no capability. A program's child is born inside them and pays
nothing for them. The template is pid 1 of its pid namespace: its children are the only other
processes there, and pid 1 ignores every signal from inside that it does not handle (it handles
none). Where the kernel refuses, the template goes on behind the first wall (confine.py) and
reports which namespaces are down on its ready line (walls.py shows them).

Also the template process's own settings, taken before anything else: death with its parent
(`die_with_parent`) and one address layout in every start (`fixed_layout`: ASLR off for it
alone, docs/sandbox.md says what that makes deterministic).
"""
from __future__ import annotations

import ctypes
import errno
import os
import signal
import sys

from .confine import PR_SET_PDEATHSIG, SIGKILL

CLONE = {"user": 0x10000000, "pid": 0x20000000, "net": 0x40000000, "ipc": 0x08000000, "uts": 0x04000000,
         "mount": 0x00020000}
HELD = {  # what each namespace keeps from a program's process (walls.py shows these)
    "user": "ids mapped to the user's own, every capability dropped in the template",
    "pid": "the template is pid 1: no host process can be seen, signalled or named (kill, F_SETOWN)",
    "net": "a loopback that is down and nothing else: no network",
    "ipc": "no SysV or POSIX IPC object of the host",
    "uts": "its own host name",
    "mount": "an empty, read-only root: no file of the host is there",
}
HOSTNAME = b"sandbox"
MS_RDONLY, MS_NOSUID, MS_NODEV, MS_NOEXEC, MS_REMOUNT, MS_BIND, MS_REC, MS_PRIVATE = (
    0x1, 0x2, 0x4, 0x8, 0x20, 0x1000, 0x4000, 0x40000)
MNT_DETACH = 2
PIVOT_ROOT = {"x86_64": 155, "aarch64": 41}  # glibc has no wrapper
_LINUX_CAPABILITY_VERSION_3 = 0x20080522
PR_CAPBSET_DROP = 24


def _libc() -> ctypes.CDLL:
    libc = ctypes.CDLL(None, use_errno=True)
    libc.mount.argtypes = (ctypes.c_char_p, ctypes.c_char_p, ctypes.c_char_p, ctypes.c_ulong, ctypes.c_char_p)
    return libc


def _check(result: int, what: str) -> None:
    if result != 0:
        number = ctypes.get_errno()
        raise OSError(number, f"{what}: {os.strerror(number)}")


def enter_namespaces() -> str:
    """Move this process (the template at its start: one thread, nothing of a program imported)
    into new user, pid, net, ipc, uts and mount namespaces and make it pid 1 of the new pid
    namespace: it forks, the child returns "" and goes on as the template, and this process waits
    for it and ends as it ends (it never returns). Where the kernel refuses, nothing has changed:
    the refusal in words."""
    libc = _libc()
    uid, gid = os.getuid(), os.getgid()
    if libc.unshare(sum(CLONE.values())) != 0:
        return f"the kernel refused unshare(2): {os.strerror(ctypes.get_errno())}"
    for name, text in (("setgroups", "deny"), ("uid_map", f"{uid} {uid} 1"), ("gid_map", f"{gid} {gid} 1")):
        with open(f"/proc/self/{name}", "w") as f:  # always allowed right after unshare: the ids map to themselves
            f.write(text)
    child = os.fork()
    if child:
        _end_as(child)
    _check(libc.prctl(PR_SET_PDEATHSIG, SIGKILL, 0, 0, 0), "prctl(PR_SET_PDEATHSIG)")
    _check(libc.sethostname(HOSTNAME, len(HOSTNAME)), "sethostname")
    signal.signal(signal.SIGINT, signal.SIG_DFL)  # pid 1 ignores what it does not handle: no signal from inside ends it
    return ""


def _end_as(child: int) -> None:
    """The process that made the namespaces: hold no end of the template's pipes, wait for it
    (pid 1 of the namespace), end with its status. Killed (by the parent), it takes it along:
    the template's parent-death signal."""
    null = os.open(os.devnull, os.O_RDWR)
    for fd in (0, 1):
        os.dup2(null, fd)
    while True:
        try:
            _, status = os.waitpid(child, 0)
            break
        except ChildProcessError:
            os._exit(1)
        except InterruptedError:
            continue
    if os.WIFSIGNALED(status):
        signal.signal(os.WTERMSIG(status), signal.SIG_DFL)
        os.kill(os.getpid(), os.WTERMSIG(status))
    os._exit(os.WEXITSTATUS(status) if os.WIFEXITED(status) else 1)


def empty_root() -> None:
    """Make this process's root an empty, read-only tmpfs and let go of the host's file tree
    (the mount namespace is its own): after this the template opens nothing; what it needs is
    imported and open already. Raises OSError where the kernel refuses."""
    libc = _libc()
    _check(libc.mount(None, b"/", None, MS_REC | MS_PRIVATE, None), "mount(MS_PRIVATE)")
    place = b"/proc"  # a directory every Linux has: the new root is mounted over it, in this namespace only
    _check(libc.mount(b"sandbox", place, b"tmpfs", MS_NOSUID | MS_NODEV | MS_NOEXEC, b"size=4k,nr_inodes=2,mode=0555"),
           "mount(tmpfs)")
    os.chdir(place)
    number = PIVOT_ROOT.get(os.uname().machine)
    if number is None:
        raise OSError(errno.ENOSYS, f"pivot_root: no syscall number known for {os.uname().machine}")
    _check(libc.syscall(number, b".", b"."), "pivot_root")
    _check(libc.umount2(b".", MNT_DETACH), "umount2")
    os.chdir("/")
    _check(libc.mount(None, b"/", None, MS_REMOUNT | MS_BIND | MS_RDONLY | MS_NOSUID | MS_NODEV | MS_NOEXEC, None),
           "mount(MS_RDONLY)")


def drop_capabilities() -> None:
    """No capability left in this process or its children (the user namespace gave it all of its own)."""
    libc = _libc()
    cap = 0
    while libc.prctl(PR_CAPBSET_DROP, cap, 0, 0, 0) == 0:  # the bounding set too (EINVAL past the last one)
        cap += 1
    header = (ctypes.c_uint32 * 2)(_LINUX_CAPABILITY_VERSION_3, 0)
    data = (ctypes.c_uint32 * 6)()
    _check(libc.capset(header, data), "capset")


def finish(refused: str) -> tuple[int, list[list[object]]]:
    """After the template's imports (and with `refused` what enter_namespaces said): the empty
    root and no capability. Returns this process's pid outside and [name, up, why] of each
    namespace. Raises OSError when capabilities cannot be dropped (then nothing may run)."""
    down = dict.fromkeys(CLONE, refused)
    pid = os.getpid()
    if not refused:
        pid = int(os.readlink("/proc/self"))  # this process's id outside (the host's /proc is still there)
        try:
            empty_root()
        except OSError as exc:
            down["mount"] = f"the root stays the host's: {exc}"
        drop_capabilities()
    return pid, [[name, not down[name], down[name] or HELD[name]] for name in CLONE]



def die_with_parent(parent: int) -> None:
    """SIGKILL when the thread that started this process (handle.py's spawner) ends."""
    try:
        ctypes.CDLL(None, use_errno=True).prctl(PR_SET_PDEATHSIG, signal.SIGKILL, 0, 0, 0)
    except (OSError, AttributeError):  # not Linux: the stdin pipe still ends the template
        pass
    if parent and os.getppid() != parent:  # the parent died before prctl
        os._exit(0)


ADDR_NO_RANDOMIZE = 0x0040000  # personality(2)


def fixed_layout() -> None:
    """Run the template (and so its children) with the address space laid out alike in every
    start: ASLR off for it alone (personality(2), then exec again). Python hashes functions,
    None (3.11), NaN, exceptions, ... by their address, which then no longer differs between
    templates of one machine and build (docs/sandbox.md says what it covers). Where the kernel
    refuses the flag, the template runs as it is."""
    try:
        personality = ctypes.CDLL(None, use_errno=True).personality
    except (OSError, AttributeError):
        return
    current = personality(0xFFFFFFFF)
    if current == -1 or current & ADDR_NO_RANDOMIZE or personality(current | ADDR_NO_RANDOMIZE) == -1:
        return
    try:
        os.execv(sys.executable, sys.orig_argv)
    except OSError:  # the flag is inherited by nothing then: run on as we are
        personality(current)
