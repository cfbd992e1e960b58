// expect: CE
// Types that double in size at every level: the compiler runs out of its time or memory limit.
template <class A, class B> struct P {};
template <class T, int N> struct Bomb {
    using L = typename Bomb<P<T, T>, N - 1>::type;
    using R = typename Bomb<P<L, T>, N - 1>::type;
    using type = P<L, R>;
};
template <class T> struct Bomb<T, 0> { using type = T; };
int main() { return sizeof(typename Bomb<int, 40>::type); }
