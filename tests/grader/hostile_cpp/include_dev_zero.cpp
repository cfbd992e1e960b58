// expect: CE
// An endless include: /dev/zero is not in the compile jail (and the compile limits would stop it).
#include "/dev/zero"
int main() { return 0; }
