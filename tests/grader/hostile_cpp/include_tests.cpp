// expect: CE
// The grader's cache of generated tests and answers (/grader-cache-file stands for one of its files).
#include "/grader-cache-file"
int main() { return 0; }
