// expect: AC
// A correct closest pair (brute force, enough for tiny tests) after a recursion two million calls
// deep (over 100 MB of stack, far beyond the usual 8 MB): the stack may grow to the memory limit.
#include <cstdio>
#include <vector>
__attribute__((noinline)) long deep(long k) {
    volatile char pad[48];
    pad[k % 48] = (char)k;
    if (k == 0) return 0;
    long r = deep(k - 1);
    return r + pad[k % 48];
}
int main() {
    if (deep(2000000) == 42) std::puts("never");
    int n;
    if (std::scanf("%d", &n) != 1) return 1;
    std::vector<long double> x(n), y(n);
    for (int i = 0; i < n; ++i) {
        double a, b;
        std::scanf("%lf %lf", &a, &b);
        x[i] = a, y[i] = b;
    }
    int bi = 0, bj = 1;
    long double best = -1;
    for (int i = 0; i < n; ++i)
        for (int j = i + 1; j < n; ++j) {
            long double d = (x[i] - x[j]) * (x[i] - x[j]) + (y[i] - y[j]) * (y[i] - y[j]);
            if (best < 0 || d < best) best = d, bi = i, bj = j;
        }
    std::printf("%d %d\n", bi, bj);
    return 0;
}
