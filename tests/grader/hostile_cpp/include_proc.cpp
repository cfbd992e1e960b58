// expect: CE
// The compiler's environment and the grader's processes: there is no /proc in the compile jail.
#include "/proc/self/environ"
int main() { return 0; }
