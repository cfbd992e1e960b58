// expect: CE
// Millions of errors from a few lines: the messages are capped, the compiler stopped.
#define E1 undefined_name();
#define E2 E1 E1 E1 E1 E1 E1 E1 E1 E1 E1
#define E3 E2 E2 E2 E2 E2 E2 E2 E2 E2 E2
#define E4 E3 E3 E3 E3 E3 E3 E3 E3 E3 E3
#define E5 E4 E4 E4 E4 E4 E4 E4 E4 E4 E4
#define E6 E5 E5 E5 E5 E5 E5 E5 E5 E5 E5
#define E7 E6 E6 E6 E6 E6 E6 E6 E6 E6 E6
int main() { E7 return 0; }
