"""The measurement panel: choose n, run, and see the timings on a log-log plot with fitted slopes.

Run the examples:  python -m pytest reference_impl/kit/measure.py

``MeasurePanel(run, ns)`` calls ``run(n)``, which returns a dict of timings in
seconds (one entry per contender, e.g. ``{"bowyer_watson": 0.8, "Delaunay": 0.01}``),
and plots every measurement so far against n on log-log axes (drawn by the browser: the kernel
sends the numbers, ``panels.js`` draws them; ``static_png`` is a matplotlib stand-in).  The legend gives
the slope of a least-squares line through each contender's points: about 2 for
a quadratic algorithm, a little above 1 for n log n.  ``time_call`` is the timer
the lessons use (best of a few runs, ``time.perf_counter``).

>>> panel = MeasurePanel(lambda n: {"sleepless": n * 1e-6}, [10, 100, 1000])
>>> round(panel.measure(10)["sleepless"], 9)
1e-05
>>> _ = panel.measure(1000); round(panel.slope("sleepless"), 6)
1.0
"""
from __future__ import annotations

import html
import time
from typing import Any, Callable, Sequence

import ipywidgets as widgets
import numpy as np

from .panels import PanelView, loglog_png
from .widget import KitWidget, button

__all__ = ["MeasurePanel", "time_call", "fit_exponent"]


def time_call(fn: Callable[..., Any], *args: Any, repeat: int = 3, **kwargs: Any) -> float:
    """Best wall-clock time of ``repeat`` calls of ``fn(*args, **kwargs)``, in seconds.

    >>> time_call(sum, range(10)) >= 0
    True
    """
    best = float("inf")
    for _ in range(max(1, repeat)):
        t0 = time.perf_counter()
        fn(*args, **kwargs)
        best = min(best, time.perf_counter() - t0)
    return best


def fit_exponent(ns: Sequence[float], ts: Sequence[float]) -> float:
    """The slope of the least-squares line through (log n, log t): t ~ n^slope.

    >>> round(fit_exponent([10, 100, 1000], [1, 100, 10000]), 6)
    2.0
    """
    n = np.asarray(ns, dtype=float)
    t = np.asarray(ts, dtype=float)
    ok = (n > 0) & (t > 0)
    if ok.sum() < 2 or len(np.unique(n[ok])) < 2:
        raise ValueError("fitting an exponent needs timings at two or more different n")
    return float(np.polyfit(np.log(n[ok]), np.log(t[ok]), 1)[0])


class MeasurePanel(KitWidget):
    """Pick n (``.n``), press "measure" (or call ``.measure(n)``), see all timings plotted.

    ``results[name][n]`` holds the seconds measured.
    """

    def __init__(self, run: Callable[[int], dict], ns: Sequence[int], *, label: str = "",
                 size: tuple[int, int] = (480, 340)) -> None:
        self.run = run
        self.ns = [int(n) for n in ns]
        if not self.ns:
            raise ValueError("MeasurePanel needs at least one n to measure")
        self.label = label
        self.results: dict[str, dict[int, float]] = {}
        self.size = (int(size[0]), int(size[1]))
        self.n = widgets.SelectionSlider(options=self.ns, value=self.ns[0], description="n")
        self.measure_button = button("measure", "play", "8em")
        self.all_button = button("measure all", "forward", "10em")
        self.image = PanelView(kind="loglog", width=self.size[0], height=self.size[1], title=label)
        self.table = widgets.HTML()
        super().__init__([widgets.HBox([self.n, self.measure_button, self.all_button]),
                          self.image, self.table])
        self.add_class("kit-measure-panel")
        self.measure_button.on_click(self.guard(lambda _: self.measure(self.n.value)))
        self.all_button.on_click(self.guard(lambda _: self.measure_all(show_progress=False)))
        self._render()

    def measure(self, n: int) -> dict[str, float]:
        """Run ``run(n)``, record and plot its timings, return them."""
        timings = self.run(int(n))
        if not isinstance(timings, dict) or not timings:
            raise ValueError("run(n) must return a non-empty dict of name -> seconds")
        for name, seconds in timings.items():
            self.results.setdefault(str(name), {})[int(n)] = float(seconds)
        self._render()
        return timings

    def measure_all(self, *, show_progress: bool = True) -> dict[str, dict[int, float]]:
        """Measure at every n of the slider, smallest first (a progress line says which n runs)."""
        from .progress import Progress

        line = Progress(self.label or "measuring", len(self.ns), show=show_progress)
        for k, n in enumerate(self.ns):
            line.step(k, f"n = {n}")
            self.measure(n)
        line.done()
        return self.results

    def slope(self, name: str) -> float:
        """The fitted log-log slope of one contender's timings."""
        points = self.results[name]
        return fit_exponent(list(points), list(points.values()))

    def series(self) -> list[dict]:
        """What the plot shows: per contender its n's, seconds and fitted slope (``None`` below two sizes)."""
        out = []
        for name, points in self.results.items():
            ns = sorted(points)
            out.append({"name": name, "ns": ns, "ts": [points[n] for n in ns],
                        "slope": self.slope(name) if len(ns) >= 2 else None})
        return out

    def _render(self) -> None:
        self.image.series = self.series()
        rows = "".join(f"<tr><td>{html.escape(name)}</td>"
                       + "".join(f"<td>{points.get(n, float('nan')):.4g}</td>" for n in self.ns) + "</tr>"
                       for name, points in self.results.items())
        head = "".join(f"<th>{n}</th>" for n in self.ns)
        self.table.value = (f'<table class="kit-timings"><tr><th>seconds</th>{head}</tr>{rows}</table>'
                            if rows else "")

    def static_png(self) -> bytes:
        return loglog_png(self.series(), self.label, self.size)

    def static_text(self) -> str:
        parts = []
        for name, points in self.results.items():
            part = f"{name}: {len(points)} sizes"
            if len(points) >= 2:
                part += f", slope {self.slope(name):.2f}"
            parts.append(part)
        return f"MeasurePanel{': ' + self.label if self.label else ''} (" + ("; ".join(parts) or "nothing measured yet") + ")"
