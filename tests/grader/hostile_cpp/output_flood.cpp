// expect: OLE
// Endless output: stopped at the output limit.
#include <cstdio>
int main() {
    static char line[4096];
    for (auto& c : line) c = 'x';
    for (;;) std::fwrite(line, 1, sizeof line, stdout);
}
