/* grader-launcher: starts a compiled submission inside the run jail (standard C and POSIX only).
 *
 * It does exactly what the Python bootstrap's exec mode did (grader/jail/child_bootstrap.py,
 * _exec_program), without an interpreter's start-up being charged to the student's CPU time:
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
 * Built once per machine and account by grader/jail/launcher.py (gcc -O2 -static -s) into the
 * grader's trusted cache; `python -m grader warm` builds it.
 *
 * Usage (what the parent runs in the jail):
 *   grader-launcher NPROC STACK_BYTES CTL_IN CTL_OUT PROGRAM
 *   grader-launcher 0 268435456 5 6 /submission/program
 */
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

int main(int argc, char **argv) {
    if (argc != 6)
        refuse("grader-launcher: usage: NPROC STACK_BYTES CTL_IN CTL_OUT PROGRAM");
    long long nproc = number(argv[1]), stack = number(argv[2]);
    long long ctl_in = number(argv[3]), ctl_out = number(argv[4]);
    if (nproc < 0 || stack < 0 || ctl_in < 3 || ctl_out < 3 || ctl_in > 65535 || ctl_out > 65535)
        refuse("grader-launcher: bad arguments");

    signal(SIGPIPE, SIG_IGN);
    signal(SIGXFSZ, SIG_IGN);

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
    close((int)ctl_in);
    close((int)ctl_out);

    char *program_argv[] = {argv[5], NULL};
    execv(argv[5], program_argv);
    refuse(strerror(errno));
    return 127;
}
