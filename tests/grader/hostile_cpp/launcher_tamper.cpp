// expect: RE
// The C launcher that started this program is shown read-only in the run jail, beside the program
// itself, and the judge's control pipes are closed before the program runs. Exit code 3: neither
// file could be opened for writing, removed or renamed, and no file descriptor above 2 was open.
// Running the launcher again gains nothing (it only lowers limits and starts this binary again).
#include <cstdio>
#include <fcntl.h>
#include <unistd.h>
int main(int argc, char** argv) {
    const char* files[] = {"/submission/launcher", "/submission/program"};
    for (const char* p : files) {
        int fd = open(p, O_WRONLY);
        if (fd >= 0) { std::printf("opened %s for writing\n", p); return 0; }
        if (unlink(p) == 0 || rename(p, "/tmp/x") == 0) { std::printf("moved %s\n", p); return 0; }
    }
    for (int fd = 3; fd < 64; ++fd)
        if (fcntl(fd, F_GETFD) != -1) { std::printf("fd %d is open\n", fd); return 0; }
    return 3;
}
