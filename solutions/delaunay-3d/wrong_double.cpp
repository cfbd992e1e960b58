// Delaunay tetrahedralisation (problem delaunay-3d), C++17 stdio: WRONG. The accepted program with
// plain double orient3d/insphere determinants (no error bound, no exact fallback): at 1e-300 every
// product underflows to 0, at 1e300 it overflows to inf/nan, and near-cospherical grids far from the
// origin round the wrong way; the walk then loses its way or the cavity is not star-shaped.
// Expected verdict: see solutions/delaunay-3d/expected_cpp.yaml (fails degenerate).
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

using namespace std;

#define LOCATE_BY_SCAN 0
#define ORIENT orient3d_double
#define INSPHERE insphere_double

// BUG: the plain double determinants, no error bound and no exact fallback
static int orient3d_double(const double* a, const double* b, const double* c, const double* d) {
    double adx = a[0] - d[0], bdx = b[0] - d[0], cdx = c[0] - d[0];
    double ady = a[1] - d[1], bdy = b[1] - d[1], cdy = c[1] - d[1];
    double adz = a[2] - d[2], bdz = b[2] - d[2], cdz = c[2] - d[2];
    double det = adz * (bdx * cdy - cdx * bdy) + bdz * (cdx * ady - adx * cdy) + cdz * (adx * bdy - bdx * ady);
    return (det > 0) - (det < 0);
}
static int insphere_double(const double* a, const double* b, const double* c, const double* d, const double* e) {
    double r[4][3];
    const double* q[4] = {a, b, c, d};
    for (int i = 0; i < 4; ++i)
        for (int k = 0; k < 3; ++k) r[i][k] = q[i][k] - e[k];
    auto det3 = [](const double* x, const double* y, const double* z) {
        return x[0] * (y[1] * z[2] - y[2] * z[1]) - x[1] * (y[0] * z[2] - y[2] * z[0]) + x[2] * (y[0] * z[1] - y[1] * z[0]);
    };
    double lift[4];
    for (int i = 0; i < 4; ++i) lift[i] = r[i][0] * r[i][0] + r[i][1] * r[i][1] + r[i][2] * r[i][2];
    double det = lift[3] * det3(r[0], r[1], r[2]) - lift[2] * det3(r[3], r[0], r[1]) + lift[1] * det3(r[2], r[3], r[0]) -
                 lift[0] * det3(r[1], r[2], r[3]);
    return (det > 0) - (det < 0);
}

static const int INF = -1;  // the vertex at infinity
// face k of tetrahedron (v0, v1, v2, v3) is opposite vertex k, listed so that vertex k is on its
// positive side (orient3d(face, v_k) > 0) for a positively oriented tetrahedron
static const int FACES[4][3] = {{1, 3, 2}, {0, 2, 3}, {0, 3, 1}, {0, 1, 2}};

vector<array<double, 3>> P;
vector<array<int, 4>> tv, nb;
vector<char> alive;

static int orient(int a, int b, int c, int d) { return ORIENT(P[a].data(), P[b].data(), P[c].data(), P[d].data()); }
static int insph(int a, int b, int c, int d, int e) {
    return INSPHERE(P[a].data(), P[b].data(), P[c].data(), P[d].data(), P[e].data());
}

static int new_tet(array<int, 4> v) {
    tv.push_back(v);
    nb.push_back({-1, -1, -1, -1});
    alive.push_back(1);
    return (int)tv.size() - 1;
}

static array<int, 3> face(int t, int k) {
    const auto& v = tv[t];
    return {v[FACES[k][0]], v[FACES[k][1]], v[FACES[k][2]]};
}

// the new tetrahedra around `apex` linked to each other across their faces through it
static void glue(const vector<int>& tets, int apex) {
    unordered_map<uint64_t, pair<int, int>> table;
    table.reserve(tets.size() * 4);
    for (int t : tets) {
        const auto& v = tv[t];
        for (int k = 0; k < 4; ++k) {
            if (v[k] == apex) continue;  // the face opposite the apex is already linked
            int e[2], m = 0;
            for (int i = 0; i < 3; ++i) {
                int x = v[FACES[k][i]];
                if (x != apex) e[m++] = x;
            }
            if (e[0] > e[1]) swap(e[0], e[1]);
            uint64_t key = ((uint64_t)(uint32_t)(e[0] + 1) << 32) | (uint32_t)(e[1] + 1);
            auto it = table.find(key);
            if (it == table.end()) {
                table[key] = {t, k};
            } else {
                auto [u, ku] = it->second;
                nb[t][k] = u, nb[u][ku] = t;
                table.erase(it);
            }
        }
    }
}

static bool conflict(int t, int p) {
    const auto& v = tv[t];
    if (v[3] != INF) return insph(v[0], v[1], v[2], v[3], p) > 0;
    int s = orient(v[0], v[1], v[2], p);
    if (s != 0) return s > 0;  // p strictly outside this hull face
    // coplanar: in conflict when strictly inside the face's circumcircle, that is inside the sphere
    // through the face and the opposite vertex of the real tetrahedron below it
    const auto& below = tv[nb[t][3]];
    int q = -1;
    for (int x : below)
        if (x != v[0] && x != v[1] && x != v[2]) q = x;
    return insph(v[1], v[0], v[2], q, p) > 0;
}

// insertion order: a 3D Morton curve over a 1024^3 grid, in BRIO rounds (random halves)
static vector<int> insertion_order(vector<int> idx) {
    double lo[3], hi[3], span[3];
    for (int k = 0; k < 3; ++k) {
        lo[k] = INFINITY, hi[k] = -INFINITY;
        for (int i : idx) lo[k] = min(lo[k], P[i][k]), hi[k] = max(hi[k], P[i][k]);
        span[k] = (hi[k] - lo[k]) != 0 ? hi[k] - lo[k] : 1.0;
    }
    vector<uint32_t> key(P.size(), 0);
    for (int i : idx) {
        int c[3];
        for (int k = 0; k < 3; ++k) {
            double f = (P[i][k] - lo[k]) / span[k];
            c[k] = isfinite(f) ? min(1023, (int)(f * 1023.0)) : 0;
        }
        uint32_t m = 0;
        for (int bit = 9; bit >= 0; --bit)
            for (int k = 0; k < 3; ++k) m = (m << 1) | ((c[k] >> bit) & 1);
        key[i] = m;
    }
    mt19937 rng(12345);
    vector<vector<int>> rounds;
    vector<int> rest = idx;
    while (rest.size() > 64) {
        shuffle(rest.begin(), rest.end(), rng);
        size_t half = rest.size() / 2;
        rounds.emplace_back(rest.begin() + half, rest.end());
        rest.resize(half);
    }
    rounds.push_back(rest);
    vector<int> out;
    for (auto r = rounds.rbegin(); r != rounds.rend(); ++r) {
        stable_sort(r->begin(), r->end(), [&](int a, int b) { return key[a] < key[b]; });
        out.insert(out.end(), r->begin(), r->end());
    }
    return out;
}

static bool collinear(int a, int b, int k) {
    const auto &A = P[a], &B = P[b], &K = P[k];
    return exact::orient2d(A[0], A[1], B[0], B[1], K[0], K[1]) == 0 &&
           exact::orient2d(A[1], A[2], B[1], B[2], K[1], K[2]) == 0 &&
           exact::orient2d(A[0], A[2], B[0], B[2], K[0], K[2]) == 0;
}

int main() {
    int n;
    if (scanf("%d", &n) != 1) return 0;
    P.resize(n);
    for (auto& p : P) {
        if (scanf("%lf %lf %lf", &p[0], &p[1], &p[2]) != 3) return 1;
        for (double& c : p) c += 0.0;  // -0.0 -> 0.0
    }
    map<array<double, 3>, int> seen;
    vector<int> uniq;
    for (int i = 0; i < n; ++i)
        if (seen.emplace(P[i], i).second) uniq.push_back(i);
    auto none = [] { printf("0\n"); return 0; };
    if (uniq.size() < 4) return none();
    vector<int> order = insertion_order(uniq);
    int a = order[0], b = order[1], c = -1, d = -1;
    for (size_t i = 2; i < order.size(); ++i) {
        int k = order[i];
        if (c < 0) {
            if (!collinear(a, b, k)) c = k;
        } else if (orient(a, b, c, k) != 0) {
            d = k;
            break;
        }
    }
    if (d < 0) return none();  // all coplanar: no tetrahedron
    if (orient(a, b, c, d) < 0) swap(a, b);
    vector<int> rest;
    for (int k : order)
        if (k != a && k != b && k != c && k != d) rest.push_back(k);
    tv.reserve(8 * n + 16), nb.reserve(8 * n + 16), alive.reserve(8 * n + 16);
    int t0 = new_tet({a, b, c, d});
    vector<int> ghosts;
    for (int k = 0; k < 4; ++k) {
        auto f = face(t0, k);
        int g = new_tet({f[0], f[2], f[1], INF});  // the hull face reversed: outside on its positive side
        nb[t0][k] = g, nb[g][3] = t0;
        ghosts.push_back(g);
    }
    glue(ghosts, INF);
    mt19937 rng(7);
    int last = t0;
    vector<int> mark;  // mark[t] == stamp: t is in the current cavity
    vector<int> stack, inside, created;
    vector<array<int, 3>> horizon;
    int stamp = 0;
    for (int p : rest) {
        int t = last;
        if (LOCATE_BY_SCAN) {
            t = -1;
            for (int s = 0; s < (int)tv.size() && t < 0; ++s)
                if (alive[s] && conflict(s, p)) t = s;
        } else {
            long long steps = 4LL * (long long)tv.size() + 100;
            for (long long step = 0; step < steps; ++step) {  // visibility walk
                int ks[4] = {0, 1, 2, 3};
                shuffle(ks, ks + 4, rng);
                bool moved = false;
                for (int k : ks) {
                    auto f = face(t, k);
                    if (orient(f[0], f[1], f[2], p) < 0) {
                        t = nb[t][k];
                        moved = true;
                        break;
                    }
                }
                if (!moved) break;              // p in the closed tetrahedron t
                if (tv[t][3] == INF) break;     // p strictly outside the hull, beyond t's face
            }
        }
        if (t < 0 || !conflict(t, p)) {
            fprintf(stderr, "point location failed\n");
            return 1;
        }
        ++stamp;
        mark.resize(tv.size(), 0);
        inside.assign(1, t);
        stack.assign(1, t);
        horizon.clear();
        mark[t] = stamp;
        while (!stack.empty()) {  // the cavity: every tetrahedron whose sphere holds p, connected
            int s = stack.back();
            stack.pop_back();
            for (int k = 0; k < 4; ++k) {
                int o = nb[s][k];
                if (mark[o] == stamp) continue;
                if (conflict(o, p)) {
                    mark[o] = stamp;
                    inside.push_back(o);
                    stack.push_back(o);
                } else {
                    horizon.push_back({s, k, o});
                }
            }
        }
        created.clear();
        for (auto [s, k, o] : horizon) {  // join every horizon face to p
            auto f = face(s, k);
            array<int, 4> v{f[0], f[1], f[2], p};
            int j = -1;
            for (int i = 0; i < 4; ++i)
                if (v[i] == INF) j = i;
            if (j >= 0 && j != 3) {  // INF to position 3 by an even permutation
                swap(v[j], v[3]);
                swap(v[0], v[1]);
            }
            int nt = new_tet(v);
            for (int i = 0; i < 4; ++i)
                if (v[i] == p) nb[nt][i] = o;
            for (int i = 0; i < 4; ++i)
                if (nb[o][i] == s) nb[o][i] = nt;
            created.push_back(nt);
        }
        for (int s : inside) alive[s] = 0;
        glue(created, p);
        last = -1;
        for (int x : created)
            if (tv[x][3] != INF) { last = x; break; }
        if (last < 0) last = nb[created[0]][3];
    }
    string out;
    int m = 0;
    for (size_t t = 0; t < tv.size(); ++t)
        if (alive[t] && tv[t][3] != INF) {
            ++m;
            out += to_string(tv[t][0]) + ' ' + to_string(tv[t][1]) + ' ' + to_string(tv[t][2]) + ' ' +
                   to_string(tv[t][3]) + '\n';
        }
    printf("%d\n%s", m, out.c_str());
    return 0;
}
