// expect: TLE
// Computes forever: stopped at the CPU time limit.
int main() {
    volatile unsigned long x = 0;
    for (;;) x = x + 1;
}
