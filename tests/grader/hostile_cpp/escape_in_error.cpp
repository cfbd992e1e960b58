// expect: CE
// Terminal escapes in the source, quoted by the compiler: shown escaped.
int main() { return [2J[31mred; }
