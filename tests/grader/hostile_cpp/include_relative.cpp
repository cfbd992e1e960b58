// expect: CE
// Climbing out of the compile folder with ../ reaches the jail's root, not the host's.
#include "../../../../../../../../../etc/shadow"
int main() { return 0; }
