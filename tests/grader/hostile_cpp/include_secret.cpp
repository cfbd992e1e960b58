// expect: CE
// An instructor's file the grader can read (/grader-secret stands for it): not in the compile jail.
#include "/grader-secret"
int main() { return 0; }
