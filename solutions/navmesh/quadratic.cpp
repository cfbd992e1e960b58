// Shortest path in a room with pillars (problem navmesh), C++17 stdio: correct but too slow. The
// accepted program's visibility test, but every polygon corner is a node (it misses that a shortest
// path bends only at reflex corners) and each pair is tested against every wall: O(V^3) for V
// corners. The large group's round rooms have thousands of convex corners.
// Expected verdict: TLE on large (solutions/navmesh/expected_cpp.yaml).
#include <bits/stdc++.h>
using namespace std;

#define NODES_REFLEX_ONLY 0  // every corner is a node

struct Room {
    vector<double> X, Y, BX, BY;   // wall k: (X[k], Y[k]) -> (BX[k], BY[k])
    vector<int> ring, first;       // ring of wall k; first wall of each ring
    vector<array<double, 2>> original;
    vector<int> reflex;
    double ox = 0, oy = 0, scale = 1;
    int rings = 0;

    array<double, 2> norm(double x, double y) const { return {(x - ox) * scale, (y - oy) * scale}; }

    Room(vector<vector<array<double, 2>>> rs, array<double, 2> start, array<double, 2> goal) {
        ox = rs[0][0][0], oy = rs[0][0][1];
        double big = 0;
        for (auto& r : rs)
            for (auto& p : r) big = max({big, fabs(p[0] - ox), fabs(p[1] - oy)});
        for (auto& p : {start, goal}) big = max({big, fabs(p[0] - ox), fabs(p[1] - oy)});
        if (big > 0) {
            int e;
            frexp(big, &e);
            scale = ldexp(1.0, -e);
        }
        rings = (int)rs.size();
        vector<int> prv, nxt;
        for (int r = 0; r < rings; ++r) {
            auto ring_pts = rs[r];
            int n = (int)ring_pts.size();
            double area = 0;
            for (int i = 0; i < n; ++i) {
                auto a = norm(ring_pts[i][0], ring_pts[i][1]), b = norm(ring_pts[(i + 1) % n][0], ring_pts[(i + 1) % n][1]);
                area += a[0] * b[1] - a[1] * b[0];
            }
            if ((area > 0) != (r == 0)) reverse(ring_pts.begin(), ring_pts.end());  // free space on the left
            int base = (int)X.size();
            first.push_back(base);
            for (int i = 0; i < n; ++i) {
                original.push_back(ring_pts[i]);
                auto q = norm(ring_pts[i][0], ring_pts[i][1]);
                X.push_back(q[0]);
                Y.push_back(q[1]);
                ring.push_back(r);
                prv.push_back(base + (i - 1 + n) % n);
                nxt.push_back(base + (i + 1) % n);
            }
        }
        int V = (int)X.size();
        BX.resize(V), BY.resize(V);
        for (int k = 0; k < V; ++k) BX[k] = X[nxt[k]], BY[k] = Y[nxt[k]];
        for (int k = 0; k < V; ++k) {
            double turn = (X[k] - X[prv[k]]) * (BY[k] - Y[k]) - (Y[k] - Y[prv[k]]) * (BX[k] - X[k]);
            if (turn < 0) reflex.push_back(k);
        }
    }

    // closed free space: on a wall, or inside the boundary and outside every hole
    bool free_at(double mx, double my) const {
        int V = (int)X.size();
        vector<long long> wind(rings, 0);
        for (int k = 0; k < V; ++k) {
            double AX = X[k], AY = Y[k], bx = BX[k], by = BY[k];
            double o = (bx - AX) * (my - AY) - (by - AY) * (mx - AX);
            if (o == 0 && min(AX, bx) <= mx && mx <= max(AX, bx) && min(AY, by) <= my && my <= max(AY, by)) return true;
            if (AY <= my && my < by && o > 0) wind[ring[k]]++;
            if (by <= my && my < AY && o < 0) wind[ring[k]]--;
        }
        if (wind[0] == 0) return false;
        for (int r = 1; r < rings; ++r)
            if (wind[r] != 0) return false;
        return true;
    }

    // the segment p -> q lies in the closed free space
    bool visible(double px, double py, double qx, double qy) const {
        int V = (int)X.size();
        double dx = qx - px, dy = qy - py, dd = dx * dx + dy * dy;
        vector<double> ts;
        for (int k = 0; k < V; ++k) {
            double AX = X[k], AY = Y[k], bx = BX[k], by = BY[k];
            double o1 = dx * (AY - py) - dy * (AX - px);
            double o2 = dx * (by - py) - dy * (bx - px);
            double o3 = (bx - AX) * (py - AY) - (by - AY) * (px - AX);
            double o4 = (bx - AX) * (qy - AY) - (by - AY) * (qx - AX);
            if (o1 * o2 < 0 && o3 * o4 < 0) return false;  // a proper crossing
            double t = (dx * (AX - px) + dy * (AY - py)) / (dd == 0 ? 1 : dd);
            if (o1 == 0 && t > 0 && t < 1 && dd > 0) ts.push_back(t);  // a corner inside the segment
        }
        if (!free_at(px + (qx - px) / 2, py + (qy - py) / 2)) return false;
        if (ts.empty()) return true;
        sort(ts.begin(), ts.end());
        ts.insert(ts.begin(), 0.0);
        ts.push_back(1.0);
        for (size_t i = 0; i + 1 < ts.size(); ++i) {
            double m = (ts[i] + ts[i + 1]) / 2;
            if (!free_at(px + m * (qx - px), py + m * (qy - py))) return false;
        }
        return true;
    }
};

int main() {
    vector<double> tok;
    {
        string s;
        while (cin >> s) tok.push_back(strtod(s.c_str(), nullptr));
    }
    size_t pos = 0;
    auto read_ring = [&]() {
        int n = (int)tok[pos++];
        vector<array<double, 2>> r(n);
        for (int i = 0; i < n; ++i) r[i] = {tok[pos], tok[pos + 1]}, pos += 2;
        return r;
    };
    vector<vector<array<double, 2>>> rs{read_ring()};
    int h = (int)tok[pos++];
    for (int i = 0; i < h; ++i) rs.push_back(read_ring());
    array<double, 2> s{tok[pos], tok[pos + 1]}, g{tok[pos + 2], tok[pos + 3]};
    Room room(rs, s, g);
    auto ns = room.norm(s[0], s[1]), ng = room.norm(g[0], g[1]);
    if (!room.free_at(ns[0], ns[1]) || !room.free_at(ng[0], ng[1])) {
        printf("0\n");
        return 0;
    }
    if (s == g) {
        printf("1\n%.17g %.17g\n", s[0], s[1]);
        return 0;
    }
    vector<array<double, 2>> nodes{s, g}, at{ns, ng};
    vector<int> corners;
    if (NODES_REFLEX_ONLY) {
        corners = room.reflex;
    } else {
        corners.resize(room.X.size());
        iota(corners.begin(), corners.end(), 0);
    }
    for (int k : corners) nodes.push_back(room.original[k]), at.push_back({room.X[k], room.Y[k]});
    int n = (int)nodes.size();
    vector<vector<pair<int, double>>> adj(n);
    for (int i = 0; i + 1 < n; ++i)
        for (int j = i + 1; j < n; ++j)
            if (room.visible(at[i][0], at[i][1], at[j][0], at[j][1])) {
                double w = hypot(nodes[i][0] - nodes[j][0], nodes[i][1] - nodes[j][1]);
                adj[i].push_back({j, w});
                adj[j].push_back({i, w});
            }
    vector<double> dist(n, INFINITY);
    vector<int> back(n, -1);
    priority_queue<pair<double, int>, vector<pair<double, int>>, greater<>> heap;
    dist[0] = 0;
    heap.push({0.0, 0});
    while (!heap.empty()) {
        auto [d, u] = heap.top();
        heap.pop();
        if (d > dist[u]) continue;
        if (u == 1) break;
        for (auto [v, w] : adj[u])
            if (d + w < dist[v]) dist[v] = d + w, back[v] = u, heap.push({d + w, v});
    }
    if (back[1] < 0) {
        printf("0\n");
        return 0;
    }
    vector<int> path;
    for (int v = 1; v != -1; v = back[v]) path.push_back(v);
    reverse(path.begin(), path.end());
    printf("%zu\n", path.size());
    for (int v : path) printf("%.17g %.17g\n", nodes[v][0], nodes[v][1]);
    return 0;
}
