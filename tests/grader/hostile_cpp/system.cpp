// expect: SV
// system() starts a shell: a new process, refused.
#include <cstdio>
#include <cstdlib>
int main() {
    int r = std::system("cat /etc/passwd");
    std::printf("0 1\n");
    return r == 0 ? 0 : 0;
}
