// expect: RE
// A crash by signal: RE naming the signal.
#include <cstdio>
int main() {
    volatile int* p = nullptr;
    std::printf("%d\n", *p);
    return 0;
}
