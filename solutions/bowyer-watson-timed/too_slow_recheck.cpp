// Delaunay triangulation (problem bowyer-watson-timed), C++17 stdio: correct and TOO SLOW, the C++
// port of too_slow_recheck.py: a quadratic Bowyer-Watson that, after every insertion, re-checks the
// empty-circle property of every triangle against every point inserted so far "to be safe", and
// does it with exact big-integer arithmetic every time (no floating-point filter), as the Python
// file does with integers. That is O(n^3) exact in-circle tests (about 10^7 at n = 250): fine on the
// small groups, far over the C++ time limit on the group 'random', which exists to stop it.
// Expected verdict: TLE random (solutions/bowyer-watson-timed/expected_cpp.yaml).
// BEGIN PREDICATES
// ---- exact predicates: a floating-point filter with Shewchuk's error bounds, else exact ----
// The filter is trusted only when every coordinate difference d is 0 or 1e-60 <= |d| <= 1e60:
// then no product of up to five differences underflows or overflows, every rounding is relative
// and the bound holds. Otherwise (coordinates near 1e-300 or 1e300) the sign is computed exactly:
// each double is an integer mantissa times a power of two, shifted onto the smallest exponent of
// the predicate's inputs, and the determinant is evaluated on a small big-integer type.
#include <bits/stdc++.h>

namespace exact {

struct Big {  // sign-magnitude integer, 32-bit limbs, little-endian
    bool neg = false;
    std::vector<uint32_t> d;
    bool zero() const { return d.empty(); }
    void trim() {
        while (!d.empty() && d.back() == 0) d.pop_back();
        if (d.empty()) neg = false;
    }
};

inline int cmp_mag(const Big& a, const Big& b) {
    if (a.d.size() != b.d.size()) return a.d.size() < b.d.size() ? -1 : 1;
    for (size_t i = a.d.size(); i-- > 0;)
        if (a.d[i] != b.d[i]) return a.d[i] < b.d[i] ? -1 : 1;
    return 0;
}

inline Big add(const Big& a, const Big& b) {
    Big r;
    if (a.neg == b.neg) {
        r.neg = a.neg;
        size_t n = std::max(a.d.size(), b.d.size());
        r.d.resize(n + 1);
        uint64_t carry = 0;
        for (size_t i = 0; i < n; ++i) {
            uint64_t s = carry + (i < a.d.size() ? a.d[i] : 0) + (i < b.d.size() ? b.d[i] : 0);
            r.d[i] = (uint32_t)s;
            carry = s >> 32;
        }
        r.d[n] = (uint32_t)carry;
    } else {
        int c = cmp_mag(a, b);
        if (c == 0) return r;
        const Big& big = c > 0 ? a : b;
        const Big& small = c > 0 ? b : a;
        r.neg = big.neg;
        r.d.resize(big.d.size());
        int64_t borrow = 0;
        for (size_t i = 0; i < big.d.size(); ++i) {
            int64_t s = (int64_t)big.d[i] - borrow - (i < small.d.size() ? small.d[i] : 0);
            borrow = s < 0;
            r.d[i] = (uint32_t)(s + (borrow << 32));
        }
    }
    r.trim();
    return r;
}

inline Big neg(Big a) {
    if (!a.zero()) a.neg = !a.neg;
    return a;
}
inline Big sub(const Big& a, const Big& b) { return add(a, neg(b)); }

inline Big mul(const Big& a, const Big& b) {
    Big r;
    if (a.zero() || b.zero()) return r;
    r.neg = a.neg != b.neg;
    r.d.assign(a.d.size() + b.d.size(), 0);
    for (size_t i = 0; i < a.d.size(); ++i) {
        uint64_t carry = 0;
        for (size_t j = 0; j < b.d.size(); ++j) {
            uint64_t cur = (uint64_t)a.d[i] * b.d[j] + r.d[i + j] + carry;
            r.d[i + j] = (uint32_t)cur;
            carry = cur >> 32;
        }
        size_t k = i + b.d.size();
        while (carry) {
            uint64_t cur = (uint64_t)r.d[k] + carry;
            r.d[k++] = (uint32_t)cur;
            carry = cur >> 32;
        }
    }
    r.trim();
    return r;
}

inline int sign(const Big& a) { return a.zero() ? 0 : (a.neg ? -1 : 1); }

// v = m * 2^e exactly, with m an integer of at most 53 bits (m = 0 for v = 0)
inline void split(double v, int64_t& m, int& e) {
    if (v == 0) { m = 0; e = INT_MAX; return; }
    int ex;
    double f = std::frexp(v, &ex);          // v = f * 2^ex, 0.5 <= |f| < 1
    m = (int64_t)std::ldexp(f, 53);         // exact
    e = ex - 53;
}

// The doubles vs[0..k) as big integers on the common exponent min(e): vs[i] = out[i] * 2^emin.
inline std::vector<Big> to_big(const double* vs, int k) {
    std::vector<int64_t> m(k);
    std::vector<int> e(k);
    int emin = INT_MAX;
    for (int i = 0; i < k; ++i) {
        split(vs[i], m[i], e[i]);
        if (m[i] != 0) emin = std::min(emin, e[i]);
    }
    std::vector<Big> out(k);
    for (int i = 0; i < k; ++i) {
        if (m[i] == 0) continue;
        Big& b = out[i];
        b.neg = m[i] < 0;
        uint64_t mag = (uint64_t)(m[i] < 0 ? -m[i] : m[i]);
        int sh = e[i] - emin;
        b.d.assign(sh / 32 + 3, 0);
        int limb = sh / 32, bit = sh % 32;
        unsigned __int128 x = (unsigned __int128)mag << bit;  // at most 53 + 31 bits
        for (int j = 0; j < 3; ++j) b.d[limb + j] = (uint32_t)(x >> (32 * j));
        b.trim();
        b.neg = m[i] < 0;
    }
    return out;
}

inline bool safe(double d) {  // a difference the filter may use
    double a = std::fabs(d);
    return a == 0 || (a >= 1e-60 && a <= 1e60);
}

const double EPS = 1.1102230246251565e-16;  // 2^-53
const double CCW_BOUND = (3.0 + 16.0 * EPS) * EPS;
const double ICC_BOUND = (10.0 + 96.0 * EPS) * EPS;

inline int orient2d_exact(double ax, double ay, double bx, double by, double cx, double cy) {
    const double v[6] = {ax, ay, bx, by, cx, cy};
    std::vector<Big> B = to_big(v, 6);
    Big l = mul(sub(B[2], B[0]), sub(B[5], B[1]));
    Big r = mul(sub(B[3], B[1]), sub(B[4], B[0]));
    return sign(sub(l, r));
}

// > 0 when a, b, c turn counter-clockwise, < 0 clockwise, 0 collinear (exact)
inline int orient2d(double ax, double ay, double bx, double by, double cx, double cy) {
    double acx = ax - cx, bcx = bx - cx, acy = ay - cy, bcy = by - cy;
    if (safe(acx) && safe(bcx) && safe(acy) && safe(bcy)) {
        double l = acx * bcy, r = acy * bcx, det = l - r;
        double bound = CCW_BOUND * (std::fabs(l) + std::fabs(r));
        if (det > bound) return 1;
        if (-det > bound) return -1;
        if (l == 0 && r == 0) return 0;
    }
    return orient2d_exact(ax, ay, bx, by, cx, cy);
}

inline int incircle_exact(double ax, double ay, double bx, double by, double cx, double cy, double dx,
                          double dy) {
    const double v[8] = {ax, ay, bx, by, cx, cy, dx, dy};
    std::vector<Big> B = to_big(v, 8);
    Big adx = sub(B[0], B[6]), ady = sub(B[1], B[7]);
    Big bdx = sub(B[2], B[6]), bdy = sub(B[3], B[7]);
    Big cdx = sub(B[4], B[6]), cdy = sub(B[5], B[7]);
    Big alift = add(mul(adx, adx), mul(ady, ady));
    Big blift = add(mul(bdx, bdx), mul(bdy, bdy));
    Big clift = add(mul(cdx, cdx), mul(cdy, cdy));
    Big t1 = mul(alift, sub(mul(bdx, cdy), mul(cdx, bdy)));
    Big t2 = mul(blift, sub(mul(cdx, ady), mul(adx, cdy)));
    Big t3 = mul(clift, sub(mul(adx, bdy), mul(bdx, ady)));
    return sign(add(add(t1, t2), t3));
}

// > 0 when d lies strictly inside the circle through a, b, c (counter-clockwise), 0 on it (exact)
inline int incircle(double ax, double ay, double bx, double by, double cx, double cy, double dx, double dy) {
    double adx = ax - dx, bdx = bx - dx, cdx = cx - dx;
    double ady = ay - dy, bdy = by - dy, cdy = cy - dy;
    if (safe(adx) && safe(bdx) && safe(cdx) && safe(ady) && safe(bdy) && safe(cdy)) {
        double bdxcdy = bdx * cdy, cdxbdy = cdx * bdy, alift = adx * adx + ady * ady;
        double cdxady = cdx * ady, adxcdy = adx * cdy, blift = bdx * bdx + bdy * bdy;
        double adxbdy = adx * bdy, bdxady = bdx * ady, clift = cdx * cdx + cdy * cdy;
        double det = alift * (bdxcdy - cdxbdy) + blift * (cdxady - adxcdy) + clift * (adxbdy - bdxady);
        double perm = (std::fabs(bdxcdy) + std::fabs(cdxbdy)) * alift +
                      (std::fabs(cdxady) + std::fabs(adxcdy)) * blift +
                      (std::fabs(adxbdy) + std::fabs(bdxady)) * clift;
        double bound = ICC_BOUND * perm;
        if (det > bound) return 1;
        if (-det > bound) return -1;
        if (perm == 0) return 0;
    }
    return incircle_exact(ax, ay, bx, by, cx, cy, dx, dy);
}

// sign of |a - b|^2 - |c - d|^2 (exact): compares two squared distances
inline int cmp_dist2(double ax, double ay, double bx, double by, double cx, double cy, double dx, double dy) {
    double x1 = ax - bx, y1 = ay - by, x2 = cx - dx, y2 = cy - dy;
    if (safe(x1) && safe(y1) && safe(x2) && safe(y2)) {
        double l = x1 * x1 + y1 * y1, r = x2 * x2 + y2 * y2, det = l - r;
        double bound = 4.0 * EPS * (l + r);  // each of l, r has relative error <= 2 eps (1 + eps)
        if (det > bound) return 1;
        if (-det > bound) return -1;
    }
    const double v[8] = {ax, ay, bx, by, cx, cy, dx, dy};
    std::vector<Big> B = to_big(v, 8);
    Big p = sub(B[0], B[2]), q = sub(B[1], B[3]), s = sub(B[4], B[6]), t = sub(B[5], B[7]);
    return sign(sub(add(mul(p, p), mul(q, q)), add(mul(s, s), mul(t, t))));
}

// sign of (a - c) . (b - c) (exact): > 0 when the angle a-c-b is acute, i.e. c lies strictly
// outside the closed disc with diameter ab; <= 0 when c lies in that closed disc
inline int dot2(double ax, double ay, double bx, double by, double cx, double cy) {
    double acx = ax - cx, bcx = bx - cx, acy = ay - cy, bcy = by - cy;
    if (safe(acx) && safe(bcx) && safe(acy) && safe(bcy)) {
        double l = acx * bcx, r = acy * bcy, det = l + r;
        double bound = CCW_BOUND * (std::fabs(l) + std::fabs(r));
        if (det > bound) return 1;
        if (-det > bound) return -1;
        if (l == 0 && r == 0) return 0;
    }
    const double v[6] = {ax, ay, bx, by, cx, cy};
    std::vector<Big> B = to_big(v, 6);
    return sign(add(mul(sub(B[0], B[4]), sub(B[2], B[4])), mul(sub(B[1], B[5]), sub(B[3], B[5]))));
}

// ---- 3D: orient3d and insphere (Shewchuk's conventions and first-stage error bounds) ----
const double O3D_BOUND = (7.0 + 56.0 * EPS) * EPS;
const double ISP_BOUND = (16.0 + 224.0 * EPS) * EPS;

inline Big det3(const Big& ax, const Big& ay, const Big& az, const Big& bx, const Big& by, const Big& bz,
                const Big& cx, const Big& cy, const Big& cz) {
    Big t1 = mul(ax, sub(mul(by, cz), mul(bz, cy)));
    Big t2 = mul(ay, sub(mul(bx, cz), mul(bz, cx)));
    Big t3 = mul(az, sub(mul(bx, cy), mul(by, cx)));
    return add(sub(t1, t2), t3);
}

inline int orient3d_exact(const double* a, const double* b, const double* c, const double* d) {
    const double v[12] = {a[0], a[1], a[2], b[0], b[1], b[2], c[0], c[1], c[2], d[0], d[1], d[2]};
    std::vector<Big> B = to_big(v, 12);
    Big r[9];
    for (int i = 0; i < 3; ++i)
        for (int k = 0; k < 3; ++k) r[3 * i + k] = sub(B[3 * i + k], B[9 + k]);
    return sign(det3(r[0], r[1], r[2], r[3], r[4], r[5], r[6], r[7], r[8]));
}

// > 0 when d lies below the plane through a, b, c (counter-clockwise seen from above), < 0 above,
// 0 coplanar (exact); points are double[3]
inline int orient3d(const double* a, const double* b, const double* c, const double* d) {
    double adx = a[0] - d[0], bdx = b[0] - d[0], cdx = c[0] - d[0];
    double ady = a[1] - d[1], bdy = b[1] - d[1], cdy = c[1] - d[1];
    double adz = a[2] - d[2], bdz = b[2] - d[2], cdz = c[2] - d[2];
    if (safe(adx) && safe(bdx) && safe(cdx) && safe(ady) && safe(bdy) && safe(cdy) && safe(adz) && safe(bdz) &&
        safe(cdz)) {
        double bdxcdy = bdx * cdy, cdxbdy = cdx * bdy, cdxady = cdx * ady;
        double adxcdy = adx * cdy, adxbdy = adx * bdy, bdxady = bdx * ady;
        double det = adz * (bdxcdy - cdxbdy) + bdz * (cdxady - adxcdy) + cdz * (adxbdy - bdxady);
        double perm = (std::fabs(bdxcdy) + std::fabs(cdxbdy)) * std::fabs(adz) +
                      (std::fabs(cdxady) + std::fabs(adxcdy)) * std::fabs(bdz) +
                      (std::fabs(adxbdy) + std::fabs(bdxady)) * std::fabs(cdz);
        double bound = O3D_BOUND * perm + 1e-290;  // + 1e-290: covers any gradual underflow
        if (det > bound) return 1;
        if (-det > bound) return -1;
        if (perm == 0) return 0;
    }
    return orient3d_exact(a, b, c, d);
}

inline int insphere_exact(const double* a, const double* b, const double* c, const double* d, const double* e) {
    const double v[15] = {a[0], a[1], a[2], b[0], b[1], b[2], c[0], c[1], c[2],
                          d[0], d[1], d[2], e[0], e[1], e[2]};
    std::vector<Big> B = to_big(v, 15);
    Big r[12], lift[4];
    for (int i = 0; i < 4; ++i) {
        for (int k = 0; k < 3; ++k) r[3 * i + k] = sub(B[3 * i + k], B[12 + k]);
        lift[i] = add(add(mul(r[3 * i], r[3 * i]), mul(r[3 * i + 1], r[3 * i + 1])), mul(r[3 * i + 2], r[3 * i + 2]));
    }
    const Big *A = r, *Bq = r + 3, *C = r + 6, *D = r + 9;
    Big abc = det3(A[0], A[1], A[2], Bq[0], Bq[1], Bq[2], C[0], C[1], C[2]);
    Big dab = det3(D[0], D[1], D[2], A[0], A[1], A[2], Bq[0], Bq[1], Bq[2]);
    Big cda = det3(C[0], C[1], C[2], D[0], D[1], D[2], A[0], A[1], A[2]);
    Big bcd = det3(Bq[0], Bq[1], Bq[2], C[0], C[1], C[2], D[0], D[1], D[2]);
    Big det = add(sub(mul(lift[3], abc), mul(lift[2], dab)), sub(mul(lift[1], cda), mul(lift[0], bcd)));
    return sign(det);
}

// > 0 when e lies strictly inside the sphere through a, b, c, d (orient3d(a, b, c, d) > 0), 0 on it
inline int insphere(const double* a, const double* b, const double* c, const double* d, const double* e) {
    double aex = a[0] - e[0], bex = b[0] - e[0], cex = c[0] - e[0], dex = d[0] - e[0];
    double aey = a[1] - e[1], bey = b[1] - e[1], cey = c[1] - e[1], dey = d[1] - e[1];
    double aez = a[2] - e[2], bez = b[2] - e[2], cez = c[2] - e[2], dez = d[2] - e[2];
    if (safe(aex) && safe(bex) && safe(cex) && safe(dex) && safe(aey) && safe(bey) && safe(cey) && safe(dey) &&
        safe(aez) && safe(bez) && safe(cez) && safe(dez)) {
        double aexbey = aex * bey, bexaey = bex * aey, ab = aexbey - bexaey;
        double bexcey = bex * cey, cexbey = cex * bey, bc = bexcey - cexbey;
        double cexdey = cex * dey, dexcey = dex * cey, cd = cexdey - dexcey;
        double dexaey = dex * aey, aexdey = aex * dey, da = dexaey - aexdey;
        double aexcey = aex * cey, cexaey = cex * aey, ac = aexcey - cexaey;
        double bexdey = bex * dey, dexbey = dex * bey, bd = bexdey - dexbey;
        double abc = aez * bc - bez * ac + cez * ab;
        double bcd = bez * cd - cez * bd + dez * bc;
        double cda = cez * da + dez * ac + aez * cd;
        double dab = dez * ab + aez * bd + bez * da;
        double alift = aex * aex + aey * aey + aez * aez, blift = bex * bex + bey * bey + bez * bez;
        double clift = cex * cex + cey * cey + cez * cez, dlift = dex * dex + dey * dey + dez * dez;
        double det = (dlift * abc - clift * dab) + (blift * cda - alift * bcd);
        double aez_ = std::fabs(aez), bez_ = std::fabs(bez), cez_ = std::fabs(cez), dez_ = std::fabs(dez);
        double aexbey_ = std::fabs(aexbey), bexaey_ = std::fabs(bexaey), bexcey_ = std::fabs(bexcey);
        double cexbey_ = std::fabs(cexbey), cexdey_ = std::fabs(cexdey), dexcey_ = std::fabs(dexcey);
        double dexaey_ = std::fabs(dexaey), aexdey_ = std::fabs(aexdey), aexcey_ = std::fabs(aexcey);
        double cexaey_ = std::fabs(cexaey), bexdey_ = std::fabs(bexdey), dexbey_ = std::fabs(dexbey);
        double perm = ((cexdey_ + dexcey_) * bez_ + (dexbey_ + bexdey_) * cez_ + (bexcey_ + cexbey_) * dez_) * alift +
                      ((dexaey_ + aexdey_) * cez_ + (aexcey_ + cexaey_) * dez_ + (cexdey_ + dexcey_) * aez_) * blift +
                      ((aexbey_ + bexaey_) * dez_ + (bexdey_ + dexbey_) * aez_ + (dexaey_ + aexdey_) * bez_) * clift +
                      ((bexcey_ + cexbey_) * aez_ + (cexaey_ + aexcey_) * bez_ + (aexbey_ + bexaey_) * cez_) * dlift;
        double bound = ISP_BOUND * perm + 1e-290;  // + 1e-290: covers any gradual underflow
        if (det > bound) return 1;
        if (-det > bound) return -1;
        if (perm == 0) return 0;
    }
    return insphere_exact(a, b, c, d, e);
}

}  // namespace exact
// END PREDICATES

// ---- Delaunay triangulation: incremental Bowyer-Watson, ghost triangles, Hilbert order, walk ----
using namespace std;

#ifndef ORIENT
#define ORIENT exact::orient2d
#define INCIRCLE exact::incircle
#endif

static vector<double> X, Y;
static long rechecks = 0;  // triangles found not Delaunay by the re-check: always 0 (it is correct)

static int orient(int a, int b, int c) { return ORIENT(X[a], Y[a], X[b], Y[b], X[c], Y[c]); }
static int incircle(int a, int b, int c, int d) {
    return INCIRCLE(X[a], Y[a], X[b], Y[b], X[c], Y[c], X[d], Y[d]);
}

struct Mesh {
    // triangle t: vertices v[3t..3t+2] counter-clockwise, -1 = the vertex at infinity (a ghost);
    // nb[3t+i] = the triangle across the edge opposite v[3t+i]
    vector<int> v, nb;
    vector<char> dead, mark;
    vector<int> free_list;
    int new_tri(int a, int b, int c) {
        int t;
        if (!free_list.empty()) {
            t = free_list.back();
            free_list.pop_back();
            dead[t] = 0;
        } else {
            t = (int)dead.size();
            v.resize(3 * t + 3);
            nb.resize(3 * t + 3, -1);
            dead.push_back(0);
            mark.push_back(0);
        }
        v[3 * t] = a, v[3 * t + 1] = b, v[3 * t + 2] = c;
        nb[3 * t] = nb[3 * t + 1] = nb[3 * t + 2] = -1;
        return t;
    }
    bool ghost(int t) const { return v[3 * t] < 0 || v[3 * t + 1] < 0 || v[3 * t + 2] < 0; }
    // does p lie strictly inside the circumcircle of t (for a ghost: the open outer half-plane of
    // its hull edge, or the open edge itself)?
    bool conflict(int t, int p) const {
        int a = v[3 * t], b = v[3 * t + 1], c = v[3 * t + 2];
        if (a < 0 || b < 0 || c < 0) {
            while (c >= 0) { int tmp = a; a = b; b = c; c = tmp; }  // rotate: (a, b, infinity)
            int o = orient(a, b, p);
            if (o != 0) return o > 0;
            // collinear with the hull edge: in conflict when strictly between a and b
            double ax = X[a], bx = X[b], px = X[p];
            if (ax != bx) return (ax < px && px < bx) || (bx < px && px < ax);
            double ay = Y[a], by = Y[b], py = Y[p];
            return (ay < py && py < by) || (by < py && py < ay);
        }
        return incircle(a, b, c, p) > 0;
    }
};

static uint64_t hilbert(uint32_t x, uint32_t y, int order) {
    uint64_t d = 0;
    for (uint32_t s = 1u << (order - 1); s > 0; s >>= 1) {
        uint32_t rx = (x & s) > 0, ry = (y & s) > 0;
        d += (uint64_t)s * s * ((3 * rx) ^ ry);
        if (ry == 0) {
            if (rx == 1) { x = s - 1 - x; y = s - 1 - y; }
            swap(x, y);
        }
    }
    return d;
}

// Delaunay triangles (counter-clockwise) of the points X, Y; duplicates are referred to by their
// first index; collinear or fewer than 3 distinct points: none.
static vector<array<int, 3>> delaunay() {
    int n = (int)X.size();
    vector<array<int, 3>> out;
    // merge duplicates: keep the first index of each position
    vector<int> idx(n);
    iota(idx.begin(), idx.end(), 0);
    sort(idx.begin(), idx.end(), [](int a, int b) {
        if (X[a] != X[b]) return X[a] < X[b];
        if (Y[a] != Y[b]) return Y[a] < Y[b];
        return a < b;
    });
    vector<int> pts;
    for (int k = 0; k < n; ++k)
        if (k == 0 || X[idx[k]] != X[idx[k - 1]] || Y[idx[k]] != Y[idx[k - 1]]) pts.push_back(idx[k]);
    int m = (int)pts.size();
    if (m < 3) return out;
    // spatial sort (Hilbert curve on the bounding box)
    double x0 = X[pts[0]], x1 = X[pts[m - 1]], y0 = Y[pts[0]], y1 = Y[pts[0]];
    for (int p : pts) y0 = min(y0, Y[p]), y1 = max(y1, Y[p]);
    double wx = x1 - x0, wy = y1 - y0;
    const int ORDER = 16;
    const double cells = 65535.0;
    vector<pair<uint64_t, int>> key(m);
    for (int k = 0; k < m; ++k) {
        int p = pts[k];
        double fx = wx > 0 ? (X[p] - x0) / wx : 0, fy = wy > 0 ? (Y[p] - y0) / wy : 0;
        if (!(fx >= 0)) fx = 0;
        if (!(fy >= 0)) fy = 0;
        uint32_t ix = (uint32_t)min(cells, fx * cells), iy = (uint32_t)min(cells, fy * cells);
        key[k] = {hilbert(ix, iy, ORDER), p};
    }
    sort(key.begin(), key.end());
    for (int k = 0; k < m; ++k) pts[k] = key[k].second;
    // the first triangle: the first two points and the first point off their line
    int third = -1;
    for (int k = 2; k < m; ++k)
        if (orient(pts[0], pts[1], pts[k]) != 0) { third = k; break; }
    if (third < 0) return out;  // all collinear
    rotate(pts.begin() + 2, pts.begin() + third, pts.begin() + third + 1);
    Mesh M;
    int a = pts[0], b = pts[1], c = pts[2];
    if (orient(a, b, c) < 0) swap(b, c);
    int t0 = M.new_tri(a, b, c);
    int g0 = M.new_tri(c, b, -1), g1 = M.new_tri(a, c, -1), g2 = M.new_tri(b, a, -1);
    // t0's edge opposite a is (b, c), shared with ghost g0 = (c, b, inf) opposite inf (index 2)
    auto link = [&](int t, int i, int u, int j) { M.nb[3 * t + i] = u; M.nb[3 * u + j] = t; };
    link(t0, 0, g0, 2);
    link(t0, 1, g1, 2);
    link(t0, 2, g2, 2);
    // ghosts share edges (x, inf): g0 = (c, b, inf), g1 = (a, c, inf), g2 = (b, a, inf)
    for (int g : {g0, g1, g2})
        for (int h : {g0, g1, g2}) {
            if (g == h) continue;
            // g = (p, q, inf): its edge opposite p is (q, inf), which is h's edge (inf, q) opposite
            // h's second vertex when h = (q, r, inf)
            if (M.v[3 * g + 1] == M.v[3 * h]) { M.nb[3 * g] = h; M.nb[3 * h + 1] = g; }
        }
    vector<int> start_of(X.size() + 1, -1);  // new triangle (u, w, p) by u; infinity is n
    vector<int> cavity, created;
    int last = t0;  // unused: no walk
    for (int k = 3; k < m; ++k) {
        int p = pts[k];
        // the textbook loop: test EVERY live triangle against p (O(n) per point, O(n^2) in all)
        cavity.clear();
        for (int t = 0; t < (int)M.dead.size(); ++t)
            if (!M.dead[t] && M.conflict(t, p)) { M.mark[t] = 1; cavity.push_back(t); }
        (void)last;
        // its boundary edges (u, w) -> new triangles (u, w, p)
        created.clear();
        for (int s : cavity)
            for (int i = 0; i < 3; ++i) {
                int o = M.nb[3 * s + i];
                if (M.mark[o]) continue;
                int u = M.v[3 * s + (i + 1) % 3], w = M.v[3 * s + (i + 2) % 3];
                // find which edge of o is (w, u)
                int j = 0;
                while (M.nb[3 * o + j] != s) ++j;
                int nt = M.new_tri(u, w, p);  // cavity slots are freed only after this loop
                created.push_back(nt);
                M.nb[3 * nt + 2] = o;
                M.nb[3 * o + j] = nt;
                int ku = u < 0 ? n : u;
                start_of[ku] = nt;
            }
        for (int nt : created) {
            int w = M.v[3 * nt + 1];
            int kw = w < 0 ? n : w;
            int nxt = start_of[kw];  // the new triangle (w, z, p): across (w, p)
            M.nb[3 * nt] = nxt;
            M.nb[3 * nxt + 1] = nt;
        }
        for (int s : cavity) { M.mark[s] = 0; M.dead[s] = 1; M.free_list.push_back(s); }
        // "to be safe": every live triangle against every point inserted so far, exactly
        for (int t = 0; t < (int)M.dead.size(); ++t) {
            if (M.dead[t] || M.ghost(t)) continue;
            int ta = M.v[3 * t], tb = M.v[3 * t + 1], tc = M.v[3 * t + 2];
            for (int q = 0; q <= k; ++q) {
                int r = pts[q];
                if (r == ta || r == tb || r == tc) continue;
                rechecks += exact::incircle_exact(X[ta], Y[ta], X[tb], Y[tb], X[tc], Y[tc], X[r], Y[r]) > 0;
            }
        }
    }
    for (int t = 0; t < (int)M.dead.size(); ++t)
        if (!M.dead[t] && !M.ghost(t)) out.push_back({M.v[3 * t], M.v[3 * t + 1], M.v[3 * t + 2]});
    return out;
}

// ---- input / output ----
static string read_all() {
    string s;
    char buf[1 << 16];
    size_t r;
    while ((r = fread(buf, 1, sizeof buf, stdin)) > 0) s.append(buf, r);
    return s;
}

int main() {
    string in = read_all();
    char* p = in.data();
    char* end;
    long n = strtol(p, &end, 10);
    p = end;
    X.resize(n), Y.resize(n);
    for (long i = 0; i < n; ++i) {
        X[i] = strtod(p, &end); p = end;
        Y[i] = strtod(p, &end); p = end;
    }
    vector<array<int, 3>> tris = delaunay();
    string out;
    out.reserve(tris.size() * 24 + 16);
    out += to_string(tris.size());
    out += '\n';
    char line[64];
    for (auto& t : tris) {
        int len = snprintf(line, sizeof line, "%d %d %d\n", t[0], t[1], t[2]);
        out.append(line, len);
    }
    fwrite(out.data(), 1, out.size(), stdout);
    if (rechecks) fprintf(stderr, "re-check found %ld non-Delaunay triangles\n", rechecks);
    return 0;
}
