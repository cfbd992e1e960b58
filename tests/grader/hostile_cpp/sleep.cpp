// expect: TLE
// Sleeps instead of computing: stopped by the idle limit.
#include <unistd.h>
int main() { sleep(100); return 0; }
