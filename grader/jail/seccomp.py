"""A small seccomp-BPF deny-list for the sandbox, assembled by hand (no dependency).

The filter returns ``EPERM`` for system calls a submission never needs and that widen the
attack surface of the kernel: ``ptrace``, ``mount`` and the new mount API, ``unshare``,
``setns``, namespace-creating ``clone`` flags, ``kexec_*``, ``bpf``, ``perf_event_open``,
keyring calls, ``process_vm_*``, ``personality``, module loading, ``userfaultfd``, ... ;
``clone3`` gets ``ENOSYS`` (its flags cannot be inspected; glibc then falls back to ``clone``).
Every other call is allowed, except, with ``program(no_processes=True)`` (the non-root jail,
which has no cgroup to charge helpers to), new processes: ``fork``, ``vfork`` and ``clone``
without ``CLONE_THREAD`` kill the process (``SIGSYS``, judged SV); threads still start; and
``shmget`` and ``memfd_create`` get ``EPERM`` (RAM outside RLIMIT_AS that no cgroup charges there).
With ``program(shared_jail=True)`` (each test's process in a jail that outlives the test: a
compiled submission's, whose C launcher installs it) the IPC objects that would outlive the
process (``shmget``, ``semget``, ``msgget``, ``mq_open``) get ``EPERM`` too.
Only x86-64 is supported; elsewhere :func:`program` returns None
and the sandbox reports "no seccomp".

Two ways to install it: bubblewrap reads the raw program from a file descriptor
(``bwrap --seccomp FD``), or :func:`install` loads it into the calling process
(``prctl(PR_SET_NO_NEW_PRIVS)`` then ``prctl(PR_SET_SECCOMP)``), as the fallback jail does
just before ``exec``.

:func:`install` resolves nothing at call time: libc is loaded when this module is imported, in
the parent, because the child calls it after RLIMIT_NOFILE is set (looking libc up there runs
``ctypes.util.find_library``, which opens temporary files and failed with EMFILE).

Run ``python -m grader.jail.seccomp`` to print the denied calls and the program length.

Example:
    >>> prog = program()
    >>> prog is None or len(prog) % 8 == 0
    True
"""

from __future__ import annotations

import ctypes
import ctypes.util
import errno
import os
import platform
import struct

# BPF opcodes (linux/bpf_common.h) and seccomp constants (linux/seccomp.h, linux/audit.h)
_LD_W_ABS, _JEQ_K, _JSET_K, _JGE_K, _RET_K = 0x20, 0x15, 0x45, 0x35, 0x06
SECCOMP_RET_ALLOW, SECCOMP_RET_ERRNO, SECCOMP_RET_KILL_PROCESS = 0x7FFF0000, 0x00050000, 0x80000000
AUDIT_ARCH_X86_64 = 0xC000003E
X32_SYSCALL_BIT = 0x40000000
PR_SET_NO_NEW_PRIVS, PR_SET_SECCOMP, SECCOMP_MODE_FILTER = 38, 22, 2
#: CLONE_NEWNS | NEWCGROUP | NEWUTS | NEWIPC | NEWUSER | NEWPID | NEWNET
CLONE_NAMESPACE_FLAGS = 0x00020000 | 0x02000000 | 0x04000000 | 0x08000000 | 0x10000000 | 0x20000000 | 0x40000000

#: x86-64 numbers of the denied calls (arch/x86/entry/syscalls/syscall_64.tbl)
DENIED_X86_64 = {
    "ptrace": 101, "syslog": 103, "personality": 135, "vhangup": 153, "pivot_root": 155,
    "adjtimex": 159, "chroot": 161, "acct": 163, "settimeofday": 164, "mount": 165, "umount2": 166,
    "swapon": 167, "swapoff": 168, "reboot": 169, "iopl": 172, "ioperm": 173, "init_module": 175,
    "delete_module": 176, "quotactl": 179, "clock_settime": 227, "kexec_load": 246, "add_key": 248,
    "request_key": 249, "keyctl": 250, "unshare": 272, "perf_event_open": 298,
    "name_to_handle_at": 303, "open_by_handle_at": 304, "setns": 308, "process_vm_readv": 310,
    "process_vm_writev": 311, "finit_module": 313, "kexec_file_load": 320, "bpf": 321,
    "userfaultfd": 323, "open_tree": 428, "move_mount": 429, "fsopen": 430, "fsconfig": 431,
    "fsmount": 432, "fspick": 433, "mount_setattr": 442,
}
#: Also denied where nothing charges memory outside the process (an ordinary account's jail, no
#: cgroup): SysV shared memory, whose segments outlive ``shmdt`` outside RLIMIT_AS (measured: 40
#: segments of 8 MB kept 320 MB on the host for a 256 MB problem), and memfd files, RAM outside
#: RLIMIT_AS up to RLIMIT_FSIZE each (64 open: 1 GB with a 16 MB output limit).
ACCOUNT_DENIED_X86_64 = {"shmget": 29, "memfd_create": 319}
#: Also denied to a test's process in a jail that outlives the test (one jail per compiled
#: submission, :mod:`grader.jail.launcher`'s server): the IPC objects that would outlive the
#: process in the jail's IPC namespace and carry state to the next test (SysV message queues and
#: semaphores, POSIX message queues, SysV shared memory).
SHARED_JAIL_DENIED_X86_64 = {"shmget": 29, "semget": 64, "msgget": 68, "mq_open": 240}
_CLONE, _CLONE3, _FORK, _VFORK = 56, 435, 57, 58
CLONE_THREAD = 0x00010000

_LIBC = ctypes.CDLL(ctypes.util.find_library("c") or "libc.so.6", use_errno=True)
_LIBC.prctl.argtypes = [ctypes.c_int, ctypes.c_ulong, ctypes.c_void_p, ctypes.c_ulong, ctypes.c_ulong]


def _insn(code: int, jt: int, jf: int, k: int) -> bytes:
    return struct.pack("=HBBI", code, jt, jf, k)


def program(no_processes: bool = False, shared_jail: bool = False) -> bytes | None:
    """The filter as raw ``struct sock_filter`` bytes, or None on an unsupported architecture;
    ``no_processes`` also kills the process on any attempt to start another one and denies
    :data:`ACCOUNT_DENIED_X86_64`; ``shared_jail`` also denies :data:`SHARED_JAIL_DENIED_X86_64`."""
    if platform.machine() not in ("x86_64", "AMD64"):
        return None
    eperm = SECCOMP_RET_ERRNO | errno.EPERM
    denied = set(DENIED_X86_64.values()) | (set(ACCOUNT_DENIED_X86_64.values()) if no_processes else set()) \
        | (set(SHARED_JAIL_DENIED_X86_64.values()) if shared_jail else set())
    denied = sorted(denied)
    out = [
        _insn(_LD_W_ABS, 0, 0, 4),  # seccomp_data.arch
        _insn(_JEQ_K, 1, 0, AUDIT_ARCH_X86_64),
        _insn(_RET_K, 0, 0, SECCOMP_RET_KILL_PROCESS),  # a foreign ABI (i386 int 0x80): kill
        _insn(_LD_W_ABS, 0, 0, 0),  # seccomp_data.nr
        _insn(_JGE_K, 0, 1, X32_SYSCALL_BIT),
        _insn(_RET_K, 0, 0, eperm),  # the x32 ABI aliases every call: deny it as a whole
        _insn(_JEQ_K, 0, 1, _CLONE3),
        _insn(_RET_K, 0, 0, SECCOMP_RET_ERRNO | errno.ENOSYS),
        _insn(_JEQ_K, 0, 5 if no_processes else 3, _CLONE),
        _insn(_LD_W_ABS, 0, 0, 16),  # low 32 bits of args[0] (the clone flags)
        _insn(_JSET_K, 0, 1, CLONE_NAMESPACE_FLAGS),
        _insn(_RET_K, 0, 0, eperm),
    ]
    if no_processes:  # a clone that is not a thread is a new process
        out += [_insn(_JSET_K, 1, 0, CLONE_THREAD), _insn(_RET_K, 0, 0, SECCOMP_RET_KILL_PROCESS)]
    # after the clone branch the accumulator may hold the flags: reload nr before the list
    out.append(_insn(_LD_W_ABS, 0, 0, 0))
    if no_processes:
        for nr in (_FORK, _VFORK):
            out += [_insn(_JEQ_K, 0, 1, nr), _insn(_RET_K, 0, 0, SECCOMP_RET_KILL_PROCESS)]
    n = len(denied)
    for i, nr in enumerate(denied):
        out.append(_insn(_JEQ_K, n - i, 0, nr))  # jump to the final "deny"
    out.append(_insn(_RET_K, 0, 0, SECCOMP_RET_ALLOW))
    out.append(_insn(_RET_K, 0, 0, eperm))
    return b"".join(out)


class _SockFprog(ctypes.Structure):
    _fields_ = [("len", ctypes.c_ushort), ("filter", ctypes.c_void_p)]


def install(prog: bytes) -> None:
    """Set NO_NEW_PRIVS and load ``prog`` into the calling process (irreversible; child side:
    nothing here opens a file)."""
    libc = _LIBC
    if libc.prctl(PR_SET_NO_NEW_PRIVS, 1, None, 0, 0) != 0:
        raise OSError(ctypes.get_errno(), "prctl(PR_SET_NO_NEW_PRIVS)")
    buf = ctypes.create_string_buffer(prog, len(prog))
    fprog = _SockFprog(len(prog) // 8, ctypes.cast(buf, ctypes.c_void_p))
    if libc.prctl(PR_SET_SECCOMP, SECCOMP_MODE_FILTER, ctypes.cast(ctypes.byref(fprog), ctypes.c_void_p), 0, 0) != 0:
        raise OSError(ctypes.get_errno(), "prctl(PR_SET_SECCOMP)")


def program_fd(prog: bytes) -> int:
    """A readable file descriptor holding ``prog`` from offset 0 (for ``bwrap --seccomp FD``)."""
    fd = os.memfd_create("grader-seccomp", 0)
    os.write(fd, prog)
    os.lseek(fd, 0, os.SEEK_SET)
    return fd


def main() -> None:
    """The command ``python -m grader.jail.seccomp``."""
    p = program()
    print("seccomp:", "unsupported architecture" if p is None else f"{len(p) // 8} instructions, denies "
          + ", ".join(sorted(DENIED_X86_64)) + ", namespace clone flags, clone3 (ENOSYS)")


if __name__ == "__main__":
    main()
