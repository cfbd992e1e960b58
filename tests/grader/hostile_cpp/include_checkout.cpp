// expect: CE
// The checkout (/work/main stands for it): a problem's settings and hidden tests are not visible.
#include "/work/main/assignments/closest-pair/course.yaml"
int main() { return 0; }
