// expect: SV
// No new processes in the run jail (no audit hook watches a binary): the seccomp filter kills it.
#include <cstdio>
#include <unistd.h>
int main() {
    if (fork() == 0) { puts("0 1"); return 0; }
    puts("0 1");
    return 0;
}
