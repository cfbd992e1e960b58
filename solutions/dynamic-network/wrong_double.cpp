// A wireless network under joins and failures (problem dynamic-network), C++17 stdio: WRONG. The
// accepted program with plain double orientation and in-circle determinants: at 1e-300 they
// underflow to 0 (every triple collinear, every quadruple cocircular), at 1e300 they overflow, and
// a grid at 1e200 or points near 1e9 round ties (the square's diagonals) the wrong way.
// Expected verdict: see solutions/dynamic-network/expected_cpp.yaml (fails degenerate).
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

#define REBUILD_PER_QUERY 0
#define ORIENT orient_double
#define INCIRCLE incircle_double

// BUG: the plain double determinants, no error bound and no exact fallback
static int orient_double(double ax, double ay, double bx, double by, double cx, double cy) {
    double det = (ax - cx) * (by - cy) - (ay - cy) * (bx - cx);
    return (det > 0) - (det < 0);
}
static int incircle_double(double ax, double ay, double bx, double by, double cx, double cy, double dx, double dy) {
    double adx = ax - dx, ady = ay - dy, bdx = bx - dx, bdy = by - dy, cdx = cx - dx, cdy = cy - dy;
    double det = (adx * adx + ady * ady) * (bdx * cdy - cdx * bdy) - (bdx * bdx + bdy * bdy) * (adx * cdy - cdx * ady) +
                 (cdx * cdx + cdy * cdy) * (adx * bdy - bdx * ady);
    return (det > 0) - (det < 0);
}

static const int INF = -1;  // the infinite vertex of ghost triangles

vector<array<double, 2>> V;                 // vertex id -> position (one vertex per distinct position)
map<pair<double, double>, int> vertex_at;   // position -> vertex id
vector<vector<int>> nodes_at;               // vertex id -> live node ids there
set<pair<pair<double, double>, int>> live;  // live positions, sorted (for the collinear case)
bool has_tri = false;                       // false: the live positions are collinear or fewer than 3
unordered_map<uint64_t, int> tri;           // directed edge (u, v) -> w of the CCW triangle (u, v, w)
vector<int> edge_of;                        // vertex id + 1 -> a neighbour v with (vertex, v) in tri
long long real_tris = 0;
pair<int, int> last_edge{-2, -2};
bool dirty = false;                         // REBUILD_PER_QUERY: changed since the last build

static inline uint64_t key(int u, int v) { return ((uint64_t)(uint32_t)(u + 1) << 32) | (uint32_t)(v + 1); }
static inline int orient(int a, int b, int c) {
    return ORIENT(V[a][0], V[a][1], V[b][0], V[b][1], V[c][0], V[c][1]);
}
static inline int incircle(int a, int b, int c, int d) {
    return INCIRCLE(V[a][0], V[a][1], V[b][0], V[b][1], V[c][0], V[c][1], V[d][0], V[d][1]);
}
static inline bool has(int u, int v) { return tri.count(key(u, v)) > 0; }
static inline int third(int u, int v) { return tri.at(key(u, v)); }

// ghost (u, v, INF): the real triangle is on the right of u -> v
static bool in_ghost(int u, int v, int p) {
    int s = orient(u, v, p);
    if (s != 0) return s > 0;
    return min(V[u][0], V[v][0]) <= V[p][0] && V[p][0] <= max(V[u][0], V[v][0]) &&
           min(V[u][1], V[v][1]) <= V[p][1] && V[p][1] <= max(V[u][1], V[v][1]);
}

static bool conflict(int u, int v, int w, int p) {
    if (w == INF) return in_ghost(u, v, p);
    if (u == INF) return in_ghost(v, w, p);
    if (v == INF) return in_ghost(w, u, p);
    return incircle(u, v, w, p) > 0;
}

static void add(int u, int v, int w) {
    tri[key(u, v)] = w, tri[key(v, w)] = u, tri[key(w, u)] = v;
    edge_of[u + 1] = v, edge_of[v + 1] = w, edge_of[w + 1] = u;
    real_tris += (u != INF && v != INF && w != INF);
}

static void remove_tri(int u, int v, int w) {
    tri.erase(key(u, v)), tri.erase(key(v, w)), tri.erase(key(w, u));
    real_tris -= (u != INF && v != INF && w != INF);
}

static array<int, 3> canon(int a, int b, int c) {  // the rotation starting at the smallest id
    if (a <= b && a <= c) return {a, b, c};
    if (b <= a && b <= c) return {b, c, a};
    return {c, a, b};
}

static void insert(int p) {
    int u, v;
    if (last_edge.first != -2 && has(last_edge.first, last_edge.second)) {
        tie(u, v) = last_edge;
    } else {
        uint64_t k = tri.begin()->first;
        u = (int)(k >> 32) - 1, v = (int)(uint32_t)k - 1;
    }
    int w = third(u, v);
    if (u == INF || v == INF || w == INF) {  // start from the real triangle next to this ghost
        while (w != INF) tie(u, v, w) = make_tuple(v, w, u);
        swap(u, v);
        w = third(u, v);
    }
    while (true) {  // visibility walk
        if (orient(u, v, p) < 0) swap(u, v);
        else if (orient(v, w, p) < 0) u = w;  // (u, v) = (w, v)
        else if (orient(w, u, p) < 0) v = w;  // (u, v) = (u, w)
        else break;
        w = third(u, v);
        if (w == INF) break;
    }
    vector<array<int, 3>> bad{canon(u, v, w)}, stack{{u, v, w}};
    vector<pair<int, int>> boundary;
    while (!stack.empty()) {
        auto tr = stack.back();
        stack.pop_back();
        for (int e = 0; e < 3; ++e) {
            int x = tr[e], y = tr[(e + 1) % 3];
            int z = third(y, x);
            auto c = canon(y, x, z);
            if (find(bad.begin(), bad.end(), c) != bad.end()) continue;
            if (conflict(y, x, z, p)) {
                bad.push_back(c);
                stack.push_back({y, x, z});
            } else {
                boundary.push_back({x, y});
            }
        }
    }
    for (auto& t : bad) remove_tri(t[0], t[1], t[2]);
    for (auto [x, y] : boundary) add(x, y, p);
    last_edge = boundary[0];
}

// triangulate the live positions from scratch (has_tri false when collinear or fewer than 3)
static void rebuild() {
    vector<int> pts;
    for (auto& e : live) pts.push_back(e.second);
    has_tri = false;
    tri.clear();
    real_tris = 0;
    if (pts.size() < 3) return;
    int a = pts[0], b = pts[1], c = -2;
    for (size_t i = 2; i < pts.size(); ++i)
        if (orient(a, b, pts[i]) != 0) { c = pts[i]; break; }
    if (c == -2) return;
    if (orient(a, b, c) < 0) swap(b, c);
    has_tri = true;
    add(a, b, c), add(b, a, INF), add(c, b, INF), add(a, c, INF);
    last_edge = {a, b};
    for (int p : pts)
        if (p != a && p != b && p != c) insert(p);
}

static vector<int> ring_of(int p) {  // neighbours of p, CCW (INF among them when p is on the hull)
    int first = edge_of[p + 1];
    vector<int> ring{first};
    while (true) {
        int nxt = third(p, ring.back());
        if (nxt == first) return ring;
        ring.push_back(nxt);
    }
}

static bool ear_ok(int a, int b, int c, const vector<int>& ring) {
    if (a != INF && b != INF && c != INF && orient(a, b, c) <= 0) return false;
    for (int x : ring)
        if (x != a && x != b && x != c && x != INF && conflict(a, b, c, x)) return false;
    return true;
}

// remove vertex p: take out its star, fill the hole with Delaunay ears of its ring
static void delete_vertex(int p) {
    if (live.size() < 3) { rebuild(); return; }
    vector<int> ring = ring_of(p);
    for (size_t i = 0; i < ring.size(); ++i) remove_tri(p, ring[i], ring[(i + 1) % ring.size()]);
    while (ring.size() > 3) {
        bool cut = false;
        int m = (int)ring.size();
        for (int i = 0; i < m; ++i) {
            int a = ring[(i - 1 + m) % m], b = ring[i], c = ring[(i + 1) % m];
            if (ear_ok(a, b, c, ring)) {
                add(a, b, c);
                ring.erase(ring.begin() + i);
                cut = true;
                break;
            }
        }
        if (!cut) { rebuild(); return; }  // the remaining positions are degenerate: start again
    }
    int a = ring[0], b = ring[1], c = ring[2];
    if (a != INF && b != INF && c != INF && orient(a, b, c) <= 0) { rebuild(); return; }
    add(a, b, c);
    if (real_tris == 0) { rebuild(); return; }  // the remaining positions are collinear
    last_edge = {-2, -2};
    for (int i = 0; i < 2; ++i)
        if (ring[i] != INF && ring[i + 1] != INF) { last_edge = {ring[i], ring[i + 1]}; break; }
}

// -- the walk start: the live position joined last in the finest grid cell around a join ---------
double bx0, by0, bw, bh;
int levels;
unordered_map<long long, int> cells;

static vector<long long> cell_keys(double x, double y) {
    double fx = (x / 2 - bx0 / 2) / bw, fy = (y / 2 - by0 / 2) / bh;  // halves: no overflow at 1e308
    vector<long long> out;
    for (int k = levels; k >= 1; --k)
        out.push_back(((long long)k << 48) | ((long long)(fx * (double)(1LL << k)) << 24) |
                      (long long)(fy * (double)(1LL << k)));
    return out;
}

static void locate_start(double x, double y) {
    for (long long k : cell_keys(x, y)) {
        auto it = cells.find(k);
        if (it == cells.end()) continue;
        int q = it->second;
        if (!nodes_at[q].empty() && edge_of[q + 1] != -2 && has(q, edge_of[q + 1])) {
            last_edge = {q, edge_of[q + 1]};
            return;
        }
    }
}

static vector<int> neighbour_positions(int p) {
    vector<int> out;
    if (!has_tri) {  // collinear (or fewer than 3 positions): the adjacent ones on the line
        auto it = live.find({{V[p][0], V[p][1]}, p});
        if (it != live.begin()) out.push_back(prev(it)->second);
        if (next(it) != live.end()) out.push_back(next(it)->second);
        return out;
    }
    for (int u : ring_of(p)) {
        if (u == INF) continue;
        int w = third(p, u), z = third(u, p);
        if (w != INF && z != INF && incircle(p, u, w, z) == 0) continue;  // a tie diagonal
        out.push_back(u);
    }
    return out;
}

vector<int> node_vertex;
vector<char> node_alive;

static long long join(double x, double y) {
    int node = (int)node_vertex.size();
    x += 0.0, y += 0.0;  // -0.0 and 0.0 are one position
    auto [it, fresh] = vertex_at.emplace(make_pair(x, y), (int)V.size());
    if (fresh) {
        V.push_back({x, y});
        nodes_at.emplace_back();
        edge_of.push_back(-2);
    }
    int p = it->second;
    node_vertex.push_back(p);
    node_alive.push_back(1);
    bool coincident = !nodes_at[p].empty();
    nodes_at[p].push_back(node);
    if (coincident) return node;
    live.insert({{x, y}, p});
    if (REBUILD_PER_QUERY) {
        dirty = true;
    } else if (!has_tri) {
        rebuild();
    } else {
        locate_start(x, y);
        insert(p);
    }
    for (long long k : cell_keys(x, y)) cells[k] = p;
    return node;
}

static bool valid(long long node) { return node >= 0 && node < (long long)node_vertex.size() && node_alive[node]; }

static bool fail(long long node) {
    if (!valid(node)) return false;
    node_alive[node] = 0;
    int p = node_vertex[node];
    auto& here = nodes_at[p];
    here.erase(find(here.begin(), here.end(), (int)node));
    if (here.empty()) {
        live.erase({{V[p][0], V[p][1]}, p});
        if (REBUILD_PER_QUERY) dirty = true;
        else if (has_tri) delete_vertex(p);
    }
    return true;
}

int main() {
    int m;
    if (scanf("%d", &m) != 1) return 0;
    vector<string> kind(m);
    vector<double> ax(m), ay(m);
    vector<long long> arg(m);
    char buf[64];
    for (int i = 0; i < m; ++i) {
        if (scanf("%63s", buf) != 1) return 1;
        kind[i] = buf;
        if (kind[i] == "join") {
            if (scanf("%lf %lf", &ax[i], &ay[i]) != 2) return 1;
        } else if (kind[i] != "count") {
            if (scanf("%lld", &arg[i]) != 1) return 1;
        }
    }
    // the grid for the walk starts: the bounding box of every join, about one join per finest cell
    double xmin = INFINITY, xmax = -INFINITY, ymin = INFINITY, ymax = -INFINITY;
    long long joins = 0;
    for (int i = 0; i < m; ++i)
        if (kind[i] == "join") {
            ++joins;
            xmin = min(xmin, ax[i]), xmax = max(xmax, ax[i]), ymin = min(ymin, ay[i]), ymax = max(ymax, ay[i]);
        }
    if (!joins) xmin = xmax = ymin = ymax = 0.0, joins = 1;
    bx0 = xmin, by0 = ymin;
    bw = (xmax / 2 - xmin / 2) * 1.000001, bh = (ymax / 2 - ymin / 2) * 1.000001;
    if (bw == 0) bw = 1.0;
    if (bh == 0) bh = 1.0;
    int bits = 0;
    while ((1LL << bits) <= joins) ++bits;  // bit_length
    levels = max(1, (bits + 1) / 2);
    edge_of.push_back(-2);  // the slot of INF
    long long count = 0;
    string out;
    for (int i = 0; i < m; ++i) {
        if (kind[i] == "join") {
            out += to_string(join(ax[i], ay[i])) + '\n';
            ++count;
        } else if (kind[i] == "fail") {
            bool ok = fail(arg[i]);
            count -= ok;
            out += ok ? "ok\n" : "error\n";
        } else if (kind[i] == "neighbors") {
            if (!valid(arg[i])) {
                out += "error\n";
                continue;
            }
            if (REBUILD_PER_QUERY && dirty) {
                rebuild();
                dirty = false;
            }
            int p = node_vertex[arg[i]];
            vector<int> res;
            for (int v : nodes_at[p])
                if (v != arg[i]) res.push_back(v);
            for (int q : neighbour_positions(p)) res.insert(res.end(), nodes_at[q].begin(), nodes_at[q].end());
            sort(res.begin(), res.end());
            out += to_string(res.size());
            for (int v : res) out += ' ' + to_string(v);
            out += '\n';
        } else {
            out += to_string(count) + '\n';
        }
    }
    fputs(out.c_str(), stdout);
    return 0;
}
