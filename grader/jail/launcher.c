/* grader-launcher: starts a compiled submission inside the run jail (standard C, POSIX and Linux
 * system calls only). Two modes.
 *
 * ONE PROGRAM (the per-test jail, `GRADER_LAUNCHER=per-test`): it does exactly what the Python
 * bootstrap's exec mode did (grader/jail/child_bootstrap.py, _exec_program), without an
 * interpreter's start-up being charged to the student's CPU time:
 *
 *   1. ignore SIGPIPE and SIGXFSZ, as the Python interpreter did (an ignored signal stays ignored
 *      across execv: a program writing past RLIMIT_FSIZE gets EFBIG, as before);
 *   2. NPROC > 0 (an ordinary account's jail): RLIMIT_NPROC = NPROC, set here, inside the sandbox's
 *      user namespace; if it cannot be set the program is not started;
 *   3. STACK_BYTES > 0: RLIMIT_STACK = STACK_BYTES, capped by the hard limit (errors ignored);
 *   4. close the two control pipes CTL_IN and CTL_OUT (the program cannot write on them);
 *   5. execv(PROGRAM, {PROGRAM}): same pid, same limits, same seccomp filter, same environment.
 *      If it cannot start: "the program could not be started: <strerror>" on stderr, exit 127.
 *
 *   grader-launcher NPROC STACK_BYTES CTL_IN CTL_OUT PROGRAM
 *   grader-launcher 0 268435456 5 6 /submission/program
 *
 * SERVE (one jail per submission, the default): the launcher is pid 1 of the jail's pid namespace
 * (bubblewrap --as-pid-1) and starts one FRESH process per test (the SERVE part below says how
 * and why it is safe):
 *
 *   grader-launcher serve CTL FILTER_FD NPROC STACK_BYTES WORKDIR PROGRAM
 *   grader-launcher serve 3 4 0 268435456 /tmp/work /submission/program
 *
 * Built once per machine and account by grader/jail/launcher.py (gcc -O2 -static -s) into the
 * grader's trusted cache; `python -m grader warm` builds it.
 */
#define _GNU_SOURCE
#include <errno.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <unistd.h>

/* A decimal number >= 0, or -1 for anything else. */
static long long number(const char *text) {
    char *end;
    errno = 0;
    long long value = strtoll(text, &end, 10);
    if (errno != 0 || end == text || *end != '\0' || value < 0)
        return -1;
    return value;
}

static void refuse(const char *why) {
    char line[256];
    int n = snprintf(line, sizeof line, "the program could not be started: %s\n", why);
    if (n > 0 && write(2, line, (size_t)n) < 0) { /* nothing more to do */ }
    _exit(127);
}

/* The limits both modes set before execv: RLIMIT_NPROC to NPROC when NPROC > 0 (the grader passes 0
 * where it sets none), RLIMIT_STACK to STACK bytes when STACK > 0 (capped at the hard limit). */
static void set_limits(long long nproc, long long stack) {
    if (nproc > 0) {
        struct rlimit limit = {(rlim_t)nproc, (rlim_t)nproc};
        if (setrlimit(RLIMIT_NPROC, &limit) != 0)
            refuse(strerror(errno));
    }
    if (stack > 0) {
        struct rlimit current;
        if (getrlimit(RLIMIT_STACK, &current) == 0) {
            rlim_t want = (rlim_t)stack;
            if (current.rlim_max != RLIM_INFINITY && current.rlim_max < want)
                want = current.rlim_max;
            struct rlimit limit = {want, want};
            (void)setrlimit(RLIMIT_STACK, &limit);
        }
    }
}

/* ---- SERVE: one jail per submission, one fresh process per test ---------------------------------
 *
 * The grader starts `grader-launcher serve ...` as pid 1 of a new bubblewrap jail, with the jail's
 * base seccomp deny-list (no ptrace, mount, namespaces, ...; new processes allowed) on it, and then
 * sends one request per test on CTL, a SOCK_SEQPACKET Unix socket:
 *
 *   request  "run CPU_S\n" with three descriptors attached (SCM_RIGHTS): the test's stdin, stdout
 *            and stderr (files the grader opened in its private folder);
 *   then     "started\n" once the test's process exists (before it: nothing of the test ran);
 *   report   "done KIND VALUE UTIME_US STIME_US MAXRSS_KB TMP_KB SHM_KB CLEAN\n": KIND "exit" (VALUE:
 *            the exit code) or "signal" (VALUE: the signal), the test process's CPU and peak RSS
 *            from wait4, what /tmp and /dev/shm held when it ended (KiB), CLEAN 1 when both were
 *            emptied and every process of the test is gone (0: the grader must not reuse the jail).
 *
 * Per test: fork; in the child setsid (own session and process group), dup2 the three descriptors
 * onto 0, 1, 2, RLIMIT_CPU = CPU_S, RLIMIT_NPROC (NPROC > 0) and RLIMIT_STACK as the one-program
 * mode sets them, chdir(WORKDIR), PR_SET_NO_NEW_PRIVS, then the per-test seccomp filter (read once
 * from FILTER_FD: the "no new processes" filter the per-test jail had, plus no SysV message queues,
 * semaphores or POSIX message queues: the IPC namespace now outlives a test), execv(PROGRAM). The
 * server waits for it, then kill(-1, SIGKILL) (pid 1 of a pid namespace: every other process of the
 * jail) and reaps until none is left, measures and empties /tmp and /dev/shm (never following a
 * link), makes WORKDIR again (0700) and reports.
 *
 * Why the student's process cannot reach the server: the server is not dumpable (PR_SET_DUMPABLE 0:
 * no /proc/1/mem, /proc/1/fd, ptrace; ptrace is denied by seccomp anyway); as pid 1 of its pid
 * namespace it gets no signal from inside it for which it has no handler, and it installs none
 * (SIGKILL and SIGSTOP included); its descriptors are close-on-exec (the test process has only 0, 1,
 * 2); nothing it reads comes from the jail. Any surprise (a bad request, a failed fork, an unclean
 * jail) is reported or ends the server: the grader then judges the test and starts a fresh jail.
 */
#include <dirent.h>
#include <fcntl.h>
#include <linux/filter.h>
#include <linux/seccomp.h>
#include <sys/prctl.h>
#include <sys/socket.h>
#include <sys/stat.h>
#include <sys/statvfs.h>
#include <sys/types.h>
#include <sys/wait.h>

#define MAX_FILTER_BYTES 65536
#define MAX_DEPTH 32

static struct sock_filter filter_insns[MAX_FILTER_BYTES / sizeof(struct sock_filter)];
static struct sock_fprog filter_prog;

/* Remove everything inside the directory dirfd (closed here); never follows a symbolic link.
 * Returns 0 when all of it is gone. */
static int empty_dir(int dirfd, int depth) {
    int bad = 0;
    DIR *dir = fdopendir(dirfd);
    if (dir == NULL) {
        close(dirfd);
        return -1;
    }
    for (int pass = 0; pass < 2; ++pass) { /* a second pass: entries renamed during the first */
        rewinddir(dir);
        struct dirent *e;
        while ((e = readdir(dir)) != NULL) {
            if (strcmp(e->d_name, ".") == 0 || strcmp(e->d_name, "..") == 0)
                continue;
            if (unlinkat(dirfd, e->d_name, 0) == 0)
                continue;
            if (errno != EISDIR && errno != EPERM && errno != EACCES)
                continue;
            /* a directory (or one we may not write): make it ours to empty, then remove it */
            (void)fchmodat(dirfd, e->d_name, 0700, 0);
            if (depth >= MAX_DEPTH) {
                bad = 1;
                continue;
            }
            int sub = openat(dirfd, e->d_name, O_RDONLY | O_DIRECTORY | O_NOFOLLOW | O_CLOEXEC);
            if (sub < 0 || empty_dir(sub, depth + 1) != 0)
                bad = 1;
            if (unlinkat(dirfd, e->d_name, AT_REMOVEDIR) != 0 && errno != ENOENT)
                bad = 1;
        }
    }
    rewinddir(dir);
    struct dirent *e;
    while ((e = readdir(dir)) != NULL)
        if (strcmp(e->d_name, ".") != 0 && strcmp(e->d_name, "..") != 0)
            bad = 1;
    closedir(dir);
    return bad ? -1 : 0;
}

/* KiB used in the file system at path, or 0. */
static unsigned long long used_kib(const char *path) {
    struct statvfs st;
    if (statvfs(path, &st) != 0 || st.f_blocks < st.f_bfree)
        return 0;
    return (unsigned long long)(st.f_blocks - st.f_bfree) * st.f_frsize / 1024;
}

/* Empty a writable tmpfs of the jail (mode 1777 again); 0 when done. */
static int empty_mount(const char *path) {
    (void)chmod(path, 01777);
    int fd = open(path, O_RDONLY | O_DIRECTORY | O_NOFOLLOW | O_CLOEXEC);
    return fd < 0 ? -1 : empty_dir(fd, 0);
}

/* The child of one test: never returns. */
static void start_test(int fds[3], long long cpu_s, long long nproc, long long stack, const char *workdir,
                       char *program) {
    setsid();
    for (int i = 0; i < 3; ++i)
        if (dup2(fds[i], i) < 0) /* dup2 clears close-on-exec on 0, 1, 2 */
            _exit(127);
    for (int i = 0; i < 3; ++i)
        if (fds[i] > 2)
            close(fds[i]);
    struct rlimit cpu = {(rlim_t)cpu_s, (rlim_t)cpu_s};
    if (setrlimit(RLIMIT_CPU, &cpu) != 0)
        refuse(strerror(errno));
    set_limits(nproc, stack);
    if (chdir(workdir) != 0)
        refuse(strerror(errno));
    if (prctl(PR_SET_NO_NEW_PRIVS, 1, 0, 0, 0) != 0 || prctl(PR_SET_SECCOMP, SECCOMP_MODE_FILTER, &filter_prog) != 0)
        refuse("the jail's seccomp filter could not be installed");
    char *program_argv[] = {program, NULL};
    execv(program, program_argv);
    refuse(strerror(errno));
}

/* Read one request: 0 and three descriptors (close-on-exec), 1 at the end of the stream, -1 bad. */
static int read_request(int ctl, long long *cpu_s, int fds[3]) {
    char data[64];
    union { struct cmsghdr align; char buf[CMSG_SPACE(8 * sizeof(int))]; } control;
    struct iovec iov = {data, sizeof data - 1};
    struct msghdr msg;
    memset(&msg, 0, sizeof msg);
    msg.msg_iov = &iov;
    msg.msg_iovlen = 1;
    msg.msg_control = control.buf;
    msg.msg_controllen = sizeof control.buf;
    ssize_t n;
    do
        n = recvmsg(ctl, &msg, MSG_CMSG_CLOEXEC);
    while (n < 0 && errno == EINTR);
    if (n == 0)
        return 1;
    if (n < 0)
        return -1;
    data[n] = '\0';
    int got = 0;
    for (struct cmsghdr *c = CMSG_FIRSTHDR(&msg); c != NULL; c = CMSG_NXTHDR(&msg, c)) {
        if (c->cmsg_level != SOL_SOCKET || c->cmsg_type != SCM_RIGHTS)
            continue;
        int count = (int)((c->cmsg_len - CMSG_LEN(0)) / sizeof(int));
        int *passed = (int *)CMSG_DATA(c);
        for (int i = 0; i < count; ++i) {
            if (got < 3)
                fds[got] = passed[i];
            else
                close(passed[i]);
            ++got;
        }
    }
    char *end = NULL;
    *cpu_s = -1;
    if (strncmp(data, "run ", 4) == 0) {
        errno = 0;
        *cpu_s = strtoll(data + 4, &end, 10);
    }
    if (got != 3 || (msg.msg_flags & (MSG_TRUNC | MSG_CTRUNC)) || *cpu_s <= 0 || errno != 0 || end == NULL ||
        *end != '\n') {
        for (int i = 0; i < got && i < 3; ++i)
            close(fds[i]);
        return -1;
    }
    return 0;
}

static int serve(char **argv) {
    long long ctl = number(argv[2]), filter_fd = number(argv[3]);
    long long nproc = number(argv[4]), stack = number(argv[5]);
    const char *workdir = argv[6];
    char *program = argv[7];
    if (ctl < 3 || ctl > 65535 || filter_fd < 3 || filter_fd > 65535 || nproc < 0 || stack < 0 || workdir[0] != '/')
        refuse("grader-launcher serve: bad arguments");
    if (getpid() != 1) /* kill(-1) below must mean "the jail", never "every process of this uid" */
        refuse("grader-launcher serve: not pid 1 of a jail's pid namespace");
    if (prctl(PR_SET_DUMPABLE, 0, 0, 0, 0) != 0)
        refuse("grader-launcher serve: PR_SET_DUMPABLE");
    signal(SIGPIPE, SIG_IGN); /* inherited by each test as in the one-program mode */
    signal(SIGXFSZ, SIG_IGN);

    size_t have = 0;
    for (;;) {
        ssize_t n = read((int)filter_fd, (char *)filter_insns + have, sizeof filter_insns - have);
        if (n < 0 && errno == EINTR)
            continue;
        if (n <= 0)
            break;
        have += (size_t)n;
    }
    close((int)filter_fd);
    if (have == 0 || have % sizeof(struct sock_filter) != 0 || have >= sizeof filter_insns)
        refuse("grader-launcher serve: bad seccomp filter");
    filter_prog.len = (unsigned short)(have / sizeof(struct sock_filter));
    filter_prog.filter = filter_insns;
    if (fcntl((int)ctl, F_SETFD, FD_CLOEXEC) != 0 || chdir("/") != 0)
        refuse("grader-launcher serve: set-up");
    if (send((int)ctl, "ready\n", 6, MSG_NOSIGNAL) != 6)
        return 1;

    for (;;) {
        long long cpu_s;
        int fds[3];
        int r = read_request((int)ctl, &cpu_s, fds);
        if (r == 1)
            return 0;
        if (r < 0) {
            (void)send((int)ctl, "bad request\n", 12, MSG_NOSIGNAL);
            return 1;
        }
        pid_t pid = fork();
        if (pid == 0)
            start_test(fds, cpu_s, nproc, stack, workdir, program);
        for (int i = 0; i < 3; ++i)
            close(fds[i]);
        if (pid < 0) {
            (void)send((int)ctl, "fork failed\n", 12, MSG_NOSIGNAL);
            return 1;
        }
        if (send((int)ctl, "started\n", 8, MSG_NOSIGNAL) != 8)
            return 1;
        int status = 0;
        struct rusage ru;
        memset(&ru, 0, sizeof ru);
        while (wait4(pid, &status, 0, &ru) < 0)
            if (errno != EINTR) {
                status = W_EXITCODE(127, 0);
                break;
            }
        /* everything the test left: every process of the jail but this one, reaped */
        for (int round = 0; round < 100000; ++round) {
            (void)kill(-1, SIGKILL);
            if (waitpid(-1, NULL, 0) < 0 && errno == ECHILD)
                break;
        }
        unsigned long long tmp_kib = used_kib("/tmp"), shm_kib = used_kib("/dev/shm");
        const char *unclean = empty_mount("/tmp") != 0 ? "/tmp could not be emptied"
                              : empty_mount("/dev/shm") != 0 ? "/dev/shm could not be emptied"
                              : mkdir(workdir, 0700) != 0 || chmod(workdir, 0700) != 0 ? "no working directory"
                              : NULL;
        errno = 0;
        if (unclean == NULL && (waitpid(-1, NULL, WNOHANG) != -1 || errno != ECHILD))
            unclean = "a process is left"; /* cannot happen: the kill loop reaped all */
        int clean = unclean == NULL;
        if (!clean) /* the server's log (a file in the grader's private folder) */
            dprintf(2, "grader-launcher serve: %s (%s)\n", unclean, strerror(errno));
        char line[200];
        int len = snprintf(line, sizeof line, "done %s %d %lld %lld %ld %llu %llu %d\n",
                           WIFSIGNALED(status) ? "signal" : "exit",
                           WIFSIGNALED(status) ? WTERMSIG(status) : WEXITSTATUS(status),
                           (long long)ru.ru_utime.tv_sec * 1000000 + ru.ru_utime.tv_usec,
                           (long long)ru.ru_stime.tv_sec * 1000000 + ru.ru_stime.tv_usec, ru.ru_maxrss, tmp_kib,
                           shm_kib, clean);
        if (len <= 0 || send((int)ctl, line, (size_t)len, MSG_NOSIGNAL) != len)
            return 1;
        if (!clean)
            return 1;
    }
}

int main(int argc, char **argv) {
    if (argc == 8 && strcmp(argv[1], "serve") == 0)
        return serve(argv);
    if (argc != 6)
        refuse("grader-launcher: usage: NPROC STACK_BYTES CTL_IN CTL_OUT PROGRAM");
    long long nproc = number(argv[1]), stack = number(argv[2]);
    long long ctl_in = number(argv[3]), ctl_out = number(argv[4]);
    if (nproc < 0 || stack < 0 || ctl_in < 3 || ctl_out < 3 || ctl_in > 65535 || ctl_out > 65535)
        refuse("grader-launcher: bad arguments");

    signal(SIGPIPE, SIG_IGN);
    signal(SIGXFSZ, SIG_IGN);

    set_limits(nproc, stack);
    close((int)ctl_in);
    close((int)ctl_out);

    char *program_argv[] = {argv[5], NULL};
    execv(argv[5], program_argv);
    refuse(strerror(errno));
    return 127;
}
