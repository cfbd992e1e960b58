// expect: RE
// At run time a program may read what a Python submission may (the system, the Python installation,
// /dev/urandom) and nothing of the grader: the secret, the checkout, the tests and answers, the
// account files. Exit code 3: every forbidden read failed and every allowed one worked; a leak is
// printed (and the test looks for it in every output).
#include <cstdio>
#include <cstdlib>
static bool dump(const char* path) {
    FILE* f = std::fopen(path, "rb");
    if (!f) return false;
    char buf[4096];
    size_t n = std::fread(buf, 1, sizeof buf, f);
    std::fwrite(buf, 1, n, stdout);
    std::fclose(f);
    return true;
}
int main() {
    const char* forbidden[] = {"/grader-secret", "/work/main/assignments/closest-pair/course.yaml",
                               "/work/main/tests/grader/fixtures/tiny-closest-pair/data/sample/1-tutorial.ans",
                               "/grader-cache-file", "/etc/passwd", "/etc/shadow",
                               "/root/.bash_history", "/home"};
    bool leaked = false;
    for (const char* p : forbidden) leaked |= dump(p);
    if (leaked) return 0;
    const char* allowed[] = {"/usr/include/stdio.h", "/dev/urandom"};
    for (const char* p : allowed) {
        FILE* f = std::fopen(p, "rb");
        if (!f) return 4;
        std::fclose(f);
    }
    return 3;
}
