// expect: CE
// The account files are not in the compile jail: "No such file", never a quoted line of them.
#include "/etc/passwd"
int main() { return 0; }
