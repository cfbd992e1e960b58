"""Notebook CI: every lesson in notebooks/ is committed clean and runs top to bottom headless.

    .venv/bin/python -m pytest tests/notebooks -q            # add -n 2 to spread the lessons

One test per notebook (pytest-xdist spreads them): each lesson is executed with
nbclient in quick mode (``COURSE_QUICK=1``, small sizes) without storing widget
state, as a notebook without a browser would be; no cell may raise.  The
executed lesson is then exported to HTML with nbconvert, and every widget it
displayed must show its static picture there: the PNG of the widget (an
``<img>`` with exactly that data) or, for a predict-then-reveal question, its
text with the answer folded in ``<details>``.  New notebooks are picked up
automatically.
"""
from __future__ import annotations

import os
import time
from pathlib import Path

import nbformat
import pytest

ROOT = Path(__file__).resolve().parents[2]
NOTEBOOKS = sorted((ROOT / "notebooks").glob("*.ipynb"))
WIDGET = "application/vnd.jupyter.widget-view+json"


def test_there_are_lessons():
    names = [p.name for p in NOTEBOOKS]
    assert names[:5] == ["00-start-here.ipynb", "01-prerequisites.ipynb", "02-delaunay-property.ipynb",
                         "03-bowyer-watson-step-by-step.ipynb", "04-what-the-tutorial-gets-wrong.ipynb"]


@pytest.mark.parametrize("path", NOTEBOOKS, ids=[p.name for p in NOTEBOOKS])
def test_committed_without_outputs(path: Path):
    nb = nbformat.read(path, as_version=4)
    nbformat.validate(nb)
    dirty = [i for i, c in enumerate(nb.cells) if c.cell_type == "code"
             and (c.get("outputs") or c.get("execution_count") is not None)]
    assert not dirty, f"{path.name}: cells {dirty} have outputs or execution counts; run nbstripout on it"
    assert "widgets" not in nb.metadata, f"{path.name}: widget state is saved in the metadata; strip it"


@pytest.fixture(scope="session")
def warm_numba_cache():
    """Compile (or load) the numba kernels once, so that lessons do not all compile at once."""
    import numpy as np

    from reference_impl import Delaunay, voronoi
    from reference_impl.structures.flips import lawson_flip, mesh_quality

    from reference_impl import (ConstrainedDelaunay, DynamicNetwork, NavMesh, SphericalDelaunay, delaunay_3d,
                                euclidean_mst)

    pts = np.random.default_rng(0).random((50, 2))
    tris = Delaunay(pts).simplices
    voronoi(pts, (0, 0, 1, 1))
    lawson_flip(pts, tris)
    mesh_quality(pts, tris)
    # kernels that lessons 07-11 use (a cold compile of each takes 30-80 s on a loaded machine)
    euclidean_mst(pts)
    ConstrainedDelaunay(pts, [(0, 1)])
    delaunay_3d(np.random.default_rng(0).random((20, 3)))
    SphericalDelaunay(pts * 90)
    NavMesh([(0, 0), (4, 0), (4, 4), (2, 1), (0, 4)]).shortest_path((0.5, 3), (3.5, 3))
    net = DynamicNetwork()
    for x, y in pts[:10]:
        net.join(x, y)
    net.fail(3)


def widget_outputs(nb) -> list[dict]:
    return [o for c in nb.cells if c.cell_type == "code" for o in c.get("outputs", [])
            if o.get("output_type") in ("display_data", "execute_result") and WIDGET in o.get("data", {})]


@pytest.mark.parametrize("path", NOTEBOOKS, ids=[p.name for p in NOTEBOOKS])
def test_lesson_runs_headless_and_its_html_shows_every_widget(path: Path, warm_numba_cache, monkeypatch):
    from nbclient import NotebookClient
    from nbconvert import HTMLExporter

    monkeypatch.setenv("COURSE_QUICK", "1")
    monkeypatch.setenv("MPLBACKEND", "Agg")
    nb = nbformat.read(path, as_version=4)
    client = NotebookClient(nb, timeout=240, kernel_name="python3", store_widget_state=False,
                            resources={"metadata": {"path": str(path.parent)}})
    start = time.perf_counter()
    client.execute()   # raises CellExecutionError naming the cell on the first exception
    print(f"{path.name}: executed in {time.perf_counter() - start:.1f} s")
    errors = [o for c in nb.cells for o in c.get("outputs", []) if o.get("output_type") == "error"]
    assert not errors
    shown = widget_outputs(nb)
    assert shown, f"{path.name} displays no widget; every lesson has at least one"

    html, _ = HTMLExporter().from_notebook_node(nb)
    assert WIDGET not in html      # no widget state: nothing that would need JavaScript from a CDN
    for k, out in enumerate(shown):
        data = out["data"]
        label = data.get("text/plain", "")[:80]
        if "text/html" in data:      # a quiz: question, choices, the answer folded in <details>
            folded = data["text/html"].split("<details>", 1)
            assert len(folded) == 2, f"{path.name}: widget {k} ({label}) has no folded answer"
            assert "<details>" + folded[1].split("</details>")[0] in html, \
                f"{path.name}: widget {k} ({label}) lost its folded answer in the HTML export"
            if "image/png" in data:
                assert data["image/png"] in html, f"{path.name}: widget {k} ({label}) lost its picture"
        else:
            assert "image/png" in data, f"{path.name}: widget {k} ({label}) has no static picture"
            assert f'src="data:image/png;base64,{data["image/png"]}"' in html, \
                f"{path.name}: widget {k} ({label}) shows no picture in the HTML export"
    if os.environ.get("LESSON_HTML_DIR"):   # keep the export for a look: LESSON_HTML_DIR=build/html
        out_dir = Path(os.environ["LESSON_HTML_DIR"])
        out_dir.mkdir(parents=True, exist_ok=True)
        (out_dir / path.with_suffix(".html").name).write_text(html)
