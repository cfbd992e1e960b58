"""What only the fast ``Delaunay`` has: neighbours, hull, point location,
incremental insertion, duplicate bookkeeping, large degenerate inputs, the JIT cache.

Run: python -m pytest tests/mesh/test_delaunay_fast.py -q
"""
from __future__ import annotations

import os
import shutil
import subprocess
import sys
import textwrap
from pathlib import Path

import numpy as np
import pytest
from hypothesis import given, strategies as st

import pointsets
from reference_impl import Delaunay
from reference_impl.exact.verify import (check_delaunay, convex_hull_exact, exact_coordinates,
                                   orient_exact)
from exact_oracle import canon

ROOT = Path(__file__).resolve().parents[2]


@pytest.mark.parametrize("name,pts", pointsets.degenerate_sets(), ids=lambda v: v if isinstance(v, str) else "")
def test_neighbors_are_consistent(name, pts):
    d = Delaunay(pts)
    s, nb = d.simplices, d.neighbors
    for t in range(len(s)):
        for k in range(3):
            u, v = s[t, (k + 1) % 3], s[t, (k + 2) % 3]
            o = nb[t, k]
            if o == -1:
                # a hull edge: no other triangle has the reversed edge
                assert not any((s[:, [0, 1]] == [v, u]).all(1) | (s[:, [1, 2]] == [v, u]).all(1)
                               | (s[:, [2, 0]] == [v, u]).all(1))
            else:
                assert u in s[o] and v in s[o] and t in nb[o]


@pytest.mark.parametrize("name,pts", pointsets.degenerate_sets(), ids=lambda v: v if isinstance(v, str) else "")
def test_hull_is_the_exact_convex_hull(name, pts):
    d = Delaunay(pts)
    P = exact_coordinates(pts)
    expected = convex_hull_exact(P, keep_collinear=True)
    got = d.hull.tolist()
    k = expected.index(min(expected))
    assert got == expected[k:] + expected[:k]


def test_flat_input_reports_the_sorted_chain():
    pts = np.array([(2, 5), (0, 1), (1, 3), (0, 1), (3, 7)], dtype=float)
    d = Delaunay(pts)
    assert d.simplices.shape == (0, 3)
    assert d.hull.tolist() == [1, 2, 0, 4]
    assert d.edges().tolist() == [[0, 2], [0, 4], [1, 2]]
    assert d.index_map.tolist() == [0, 1, 2, 1, 4]
    assert Delaunay([(1.0, 1.0)]).edges().shape == (0, 2)
    assert Delaunay([]).simplices.shape == (0, 3)


def test_index_map_merges_duplicates():
    pts = pointsets.with_duplicates(50, seed=3)
    d = Delaunay(pts)
    im = d.index_map
    for i in range(len(pts)):
        j = im[i]
        assert (pts[i] == pts[j]).all() and j <= i
        assert j == min(k for k in range(len(pts)) if (pts[k] == pts[i]).all())


def brute_contains(pts, tri, q):
    """Exact: is q in the closed triangle?"""
    P = exact_coordinates(np.vstack([pts[tri], [q]]))
    a, b, c, x = P
    return orient_exact(a, b, x) >= 0 and orient_exact(b, c, x) >= 0 and orient_exact(c, a, x) >= 0


@pytest.mark.parametrize("name,pts", [("uniform", pointsets.uniform(300)), ("grid", pointsets.grid(8)),
                                      ("circle", pointsets.circle(30, True))])
def test_find_simplex_against_brute_force(name, pts):
    d = Delaunay(pts)
    rng = np.random.default_rng(1)
    lo, hi = pts.min(0), pts.max(0)
    queries = np.vstack([lo - 0.2 * (hi - lo) + rng.random((300, 2)) * 1.4 * (hi - lo), pts[:20],
                         (pts[d.simplices[:10, 0]] + pts[d.simplices[:10, 1]]) / 2])
    found = d.find_simplex(queries)
    for q, t in zip(queries, found):
        inside = [k for k in range(len(d.simplices)) if brute_contains(pts, d.simplices[k], q)]
        if t == -1:
            assert not inside
        else:
            assert t in inside
    assert isinstance(d.find_simplex(queries[0]), int)


@pytest.mark.parametrize("name,pts", [("uniform", pointsets.uniform(400, 5)), ("grid", pointsets.grid(10)),
                                      ("duplicates", pointsets.with_duplicates(100, 2))])
def test_insert_keeps_a_valid_delaunay_triangulation(name, pts):
    d = Delaunay(pts[:3])
    for i, p in enumerate(pts[3:], start=3):
        assert d.insert(p) == i
        if i % 37 == 0:
            ok, msg = check_delaunay(pts[:i + 1], d.simplices)
            assert ok, msg
    ok, msg = check_delaunay(pts, d.simplices)
    assert ok, msg
    assert (d.points == pts).all()
    if name == "uniform":
        assert canon(d.simplices) == canon(Delaunay(pts).simplices)


def test_insert_from_collinear_start_and_outside_the_hull():
    d = Delaunay([(0, 0), (1, 1), (2, 2)])
    assert len(d.simplices) == 0
    d.insert((0, 2))
    assert len(d.simplices) == 2
    for p in [(10, 10), (-5, 3), (1, 1), (0.5, 0.5), (3, 3)]:
        d.insert(p)
        ok, msg = check_delaunay(d.points, d.simplices)
        assert ok, msg


@given(st.lists(st.tuples(st.integers(-5, 5), st.integers(-5, 5)), min_size=1, max_size=30))
def test_hypothesis_insert_one_by_one(pts):
    pts = np.array(pts, dtype=float)
    d = Delaunay(pts[:1])
    for p in pts[1:]:
        d.insert(p)
    ok, msg = check_delaunay(pts, d.simplices)
    assert ok, msg


@pytest.mark.parametrize("name,pts", [("grid-200", pointsets.grid(200)),
                                      ("rotated-grid-60", pointsets.rotated_grid(60, 0.3)),
                                      ("circle-2000", pointsets.circle(2000, True)),
                                      ("uniform-1e300", pointsets.uniform(20000, 9) * 1e300),
                                      ("uniform-1e-300", pointsets.uniform(20000, 9) * 1e-300)])
def test_larger_degenerate_inputs(name, pts):
    ok, msg = check_delaunay(pts, Delaunay(pts).simplices)
    assert ok, msg


def test_edges_and_vertex_neighbors():
    pts = pointsets.uniform(200, 4)
    d = Delaunay(pts)
    e = d.edges()
    assert len(e) == 3 * len(pts) - 3 - len(d.hull)            # Euler, points in general position
    assert (e[:, 0] < e[:, 1]).all() and len(np.unique(e, axis=0)) == len(e)
    nb = d.vertex_neighbors(7)
    assert set(nb.tolist()) == {int(v) for t in d.simplices if 7 in t for v in t} - {7}


def _run(code: str, env: dict) -> float:
    out = subprocess.run([sys.executable, "-c", code], env=env, capture_output=True, text=True, timeout=600)
    assert out.returncode == 0, out.stderr
    return float(out.stdout.strip().splitlines()[-1])


CODE = textwrap.dedent("""
    import time
    t = time.perf_counter()
    import numpy as np
    import reference_impl
    from reference_impl import Delaunay
    Delaunay(np.random.default_rng(0).random((100, 2))).simplices
    print(reference_impl.__file__)
    print(time.perf_counter() - t)
""")


def test_second_process_reuses_the_jit_cache(tmp_path):
    env = dict(os.environ, NUMBA_CACHE_DIR=str(tmp_path / "cache"), PYTHONPATH=str(ROOT))
    first = _run(CODE, env)
    files = list((tmp_path / "cache").rglob("*.nbi"))
    assert files, "numba wrote no cache index"
    second = _run(CODE, env)
    print(f"first call {first:.2f} s, cached start {second:.2f} s")
    assert second < first          # not a timing target: a cache miss would recompile everything


@pytest.mark.skipif(shutil.which("unshare") is None or os.geteuid() != 0,
                    reason="needs root and unshare to mount the package read-only")
def test_jit_cache_works_when_the_package_directory_is_read_only(tmp_path):
    pkg = tmp_path / "site" / "reference_impl"
    shutil.copytree(ROOT / "reference_impl", pkg, ignore=shutil.ignore_patterns("__pycache__"))
    home = tmp_path / "home"
    home.mkdir()
    env = {k: v for k, v in os.environ.items() if k != "NUMBA_CACHE_DIR"}
    env.update(HOME=str(home), PYTHONPATH=str(pkg.parent))
    script = (f"mount --bind {pkg} {pkg} && mount -o remount,ro,bind {pkg} && "
              f"! touch {pkg}/probe 2>/dev/null && "
              f"{sys.executable} -c '{CODE}' && {sys.executable} -c '{CODE}'")
    out = subprocess.run(["unshare", "-m", "sh", "-c", script], env=env, capture_output=True, text=True,
                         timeout=900, cwd=tmp_path)
    if out.returncode != 0 and "mount" in out.stderr:
        pytest.skip(f"cannot mount read-only here: {out.stderr.strip()[:200]}")
    assert out.returncode == 0, out.stderr
    lines = out.stdout.split()
    assert lines[0].startswith(str(pkg)), f"imported the wrong copy: {lines[0]}"
    first, second = float(lines[1]), float(lines[3])
    assert not list(pkg.rglob("*.nbi")), "nothing may be written into the read-only package"
    assert list(home.rglob("*.nbi")), "the cache should fall back to the user's cache directory"
    assert second < first


def test_hilbert_curve_visits_every_cell_with_unit_steps():
    from reference_impl.mesh.ordering import hilbert_index
    for bits in (1, 2, 3, 5):
        m = 1 << bits
        pos = {hilbert_index(x, y, bits): (x, y) for x in range(m) for y in range(m)}
        assert sorted(pos) == list(range(m * m))
        for d in range(m * m - 1):
            (x0, y0), (x1, y1) = pos[d], pos[d + 1]
            assert abs(x0 - x1) + abs(y0 - y1) == 1


@pytest.mark.parametrize("n", [500, 6000])          # one compiled call below 4096 points, numpy's sort above
@pytest.mark.parametrize("scale", [1.0, 1.6e308])  # 1.6e308: the span overflows, keys come from scaled points
def test_insertion_order_depends_only_on_the_point_set(n, scale):
    from reference_impl.mesh.ordering import _order_keys, insertion_order
    grid = pointsets.grid(10) / 9.0
    pts = np.vstack([pointsets.uniform(n, 3), grid, grid]) * scale  # duplicates too
    assert np.isfinite(pts).all()
    pts[::2] *= -1
    order = insertion_order(pts)
    assert sorted(order.tolist()) == list(range(len(pts)))
    ref = pts[order]
    # sorted by key, equal keys by coordinates
    keys = _order_keys(pts[:, 0].copy(), pts[:, 1].copy(), True)
    assert (ref == pts[np.lexsort((pts[:, 1], pts[:, 0], keys))]).all()
    perm = np.random.default_rng(0).permutation(len(pts))
    assert (pts[perm][insertion_order(pts[perm])] == ref).all()


def test_editing_a_dependency_drops_the_dependants_cache(tmp_path):
    """numba's cache misses edits in other modules; reference_impl._jitcache fixes that."""
    pkg = tmp_path / "site" / "reference_impl"
    shutil.copytree(ROOT / "reference_impl", pkg, ignore=shutil.ignore_patterns("__pycache__"))
    env = dict(os.environ, NUMBA_CACHE_DIR=str(tmp_path / "cache"), PYTHONPATH=str(pkg.parent))
    probe = ("import sys; from pathlib import Path; import reference_impl; "
             "assert 'numba' not in sys.modules, 'importing the package loaded numba'; "
             "from reference_impl._jitcache import cache_dir_of, purge_stale_cache; "
             "root = Path(reference_impl.__file__).parent; "
             "print(cache_dir_of(root / 'exact' / 'predicates.py')); print(cache_dir_of(root / 'mesh' / 'kernel.py')); "
             "print(sorted(purge_stale_cache()))")

    def run():
        out = subprocess.run([sys.executable, "-c", probe], env=env, cwd=tmp_path, capture_output=True,
                             text=True, timeout=300)
        assert out.returncode == 0, out.stderr
        exact_dir, mesh_dir, dropped = out.stdout.strip().splitlines()[-3:]
        return Path(exact_dir), Path(mesh_dir), dropped

    exact_dir, mesh_dir, _ = run()                      # first sight, nothing cached: stamps written
    assert exact_dir != mesh_dir                        # one cache directory per source directory
    assert (mesh_dir / "kernel.deps.sha1").exists()
    for d in (exact_dir, mesh_dir):
        d.mkdir(parents=True, exist_ok=True)
    files = [mesh_dir / "kernel.build-1.py311.nbi", exact_dir / "verify.x-1.py311.nbi",
             exact_dir / "predicates.orient2d_nb-1.py311.nbi"]
    for f in files:
        f.write_text("")
    _, _, dropped = run()                                       # compiled after the stamps
    assert dropped == "[]" and files[0].exists()
    _, _, dropped = run()                                       # nothing edited: nothing dropped
    assert dropped == "[]" and all(f.exists() for f in files)
    with open(pkg / "exact" / "expansion.py", "a") as f:
        f.write("\n# an edit\n")
    _, _, dropped = run()
    assert dropped == "['exact.predicates', 'mesh.kernel']"
    assert not files[0].exists()                                # mesh/kernel.py uses expansion.py
    assert not files[2].exists()
    assert files[1].exists()                                    # verify does not import expansion
    (mesh_dir / "kernel.deps.sha1").unlink()                    # cached code of unknown sources
    files[0].write_text("")
    _, _, dropped = run()
    assert dropped == "['mesh.kernel']" and not files[0].exists() and files[1].exists()
