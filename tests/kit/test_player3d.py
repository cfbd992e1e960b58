"""The 3D player (kit/canvas3d.py) and the browser-drawn panels (kit/panels.py), without a browser.

    .venv/bin/python -m pytest tests/kit/test_player3d.py -q

What the kernel sends the page (the geometry once, the steps once, the links that let the page
play without the kernel), what it refuses, and the static pictures for a notebook run headless.
The page's half (drawing, turning, playing every step) is tests/browser/test_player3d.py.
"""
from __future__ import annotations

import io
import math

import numpy as np
import pytest
from PIL import Image

from reference_impl import delaunay_3d
from reference_impl.kit import Player3D
from reference_impl.kit.canvas3d import KEYS_3D, geometry_3d, project
from reference_impl.kit.theory import cavity_player
from reference_impl.teaching.cavity3d import cavity_3d

CUBE = [(x, y, z) for x in (0, 1) for y in (0, 1) for z in (0, 1)]


def png_size(png: bytes) -> tuple[int, int]:
    return Image.open(io.BytesIO(png)).size


def test_geometry_is_centred_in_the_unit_ball_and_flat():
    P = np.random.default_rng(0).random((30, 3)) * 50 + 7
    g = geometry_3d(P, edges=[(0, 1), (2, 3)], faces=[(0, 1, 2)], marks=[5])
    xyz = np.asarray(g["xyz"]).reshape(-1, 3)
    assert np.sqrt((xyz ** 2).sum(axis=1)).max() == pytest.approx(1.0, abs=1e-5)
    assert np.allclose((xyz.min(axis=0) + xyz.max(axis=0)) / 2, 0, atol=1e-5)
    assert g["edges"] == [0, 1, 2, 3] and g["faces"] == [0, 1, 2] and g["marks"] == [5]


@pytest.mark.parametrize("kwargs, message", [
    ({"points": [(0, 0)]}, "non-empty \\(n, 3\\)"),
    ({"points": "abc"}, "got text"),
    ({"points": [(0, 0, math.nan)]}, "finite"),
    ({"points": CUBE, "edges": [(0, 8)]}, "edges: vertex 8 is not a point index"),
    ({"points": CUBE, "faces": [(0, 1)]}, "faces: expected rows of 3"),
    ({"points": CUBE, "edges": [(0, 1.5)]}, "whole numbers"),
    ({"points": CUBE, "marks": [-1]}, "marks: vertex -1"),
    ({"points": CUBE, "colour": "red"}, "unknown style 'colour'"),
])
def test_bad_geometry_is_refused_by_name(kwargs, message):
    points = kwargs.pop("points")
    with pytest.raises(ValueError, match=message):
        geometry_3d(points, **kwargs)


def test_projection_is_a_rotation():
    P = np.random.default_rng(1).normal(size=(50, 3))
    xy, z = project(P, 0.7, -0.4)
    Q = np.c_[xy, z]
    assert np.allclose(np.linalg.norm(Q, axis=1), np.linalg.norm(P, axis=1))
    assert np.allclose(Q[:, :2] @ Q[:, :2].T + np.outer(z, z), P @ P.T)      # angles kept


def test_player_steps_clamp_and_the_page_is_linked_without_the_kernel():
    angles = np.linspace(0, np.pi, 6, endpoint=False)
    p = Player3D(CUBE, edges=[(0, 1), (1, 3)], angles=angles, title="cube")
    assert [s["yaw"] for s in p.view.steps] == pytest.approx(list(angles))
    assert p.view.steps[2]["caption"] == "turned 60 degrees"
    p.prev.click()
    assert p.index == 0
    p.index = 99
    assert p.index == 5 and p.view.step == 6 and p.caption.value.startswith("<b>step 6/6</b>")
    # the page plays: Play's value drives the slider and the picture, Play's playing the picture's, in the page
    links = {(tuple(lk.source), tuple(lk.target)) for lk in p.links}
    assert links == {((p.play, "value"), (p.slider, "value")), ((p.play, "value"), (p.view, "step")),
                     ((p.play, "playing"), (p.view, "playing"))}
    assert "arrow keys to turn it" in p.view.label and any("arrow keys" in k for k, _ in KEYS_3D)
    with pytest.raises(ValueError, match="at least one finite angle"):
        Player3D(CUBE, angles=[])


def test_static_picture_is_a_filmstrip_that_follows_the_viewers_turn():
    p = Player3D(CUBE, edges=[(0, 1), (0, 2), (0, 4), (7, 3)], angles=[0.0, 1.0, 2.0], depth_colors=False)
    bundle = p._repr_mimebundle_()
    assert "image/png" in bundle and bundle["text/plain"].startswith("Player3D (3 steps; step 1: turned 0 degrees)")
    first = p.static_png()
    assert png_size(first) == (660, 190)                    # three frames side by side
    p.view.yaw = 0.5                                        # the page saved a drag
    assert p.static_png() != first


def test_cavity_player_draws_only_the_cavity_and_q():
    P = np.random.default_rng(2).random((40, 3))
    P2 = np.r_[P, [[0.5, 0.5, 0.5]]]
    cav = cavity_3d(P2, delaunay_3d(P), 40)
    player = cavity_player(P2, cav, turns=4)
    g = player.view.geometry
    used = {int(v) for v in np.asarray(cav.boundary).ravel()}
    assert len(g["xyz"]) // 3 == len(used) + 1 and g["marks"] == [len(used)]
    assert len(g["faces"]) // 3 == len(cav.boundary) and max(g["faces"]) < len(used)
    # every face edge drawn once: a closed surface has 3F / 2 edges
    assert len(g["edges"]) // 2 == 3 * len(cav.boundary) // 2
    assert not g["depth_colors"] and len(player.steps) == 4
