"""Predict, then reveal: the student commits to an answer before the answer is shown.

Run the examples:  python -m pytest reference_impl/kit/quiz.py

``PredictReveal`` asks one question with one right choice; ``PredictRevealMany``
asks for every right choice (e.g. "which triangles are bad?").  The choices are
locked when the student presses "commit", then the feedback and the explanation
appear.  ``bad_triangles_quiz`` and ``locally_delaunay_quiz`` build the two
questions the Bowyer-Watson and flip lessons ask, with a picture.  Without a
browser the quiz shows the question with the answer folded in ``<details>``.

>>> q = PredictReveal("Is 2 prime?", ["yes", "no"], "yes", explain="Its only divisors are 1 and 2.")
>>> q.choose("no"); q.submit()
False
>>> q.feedback.value.startswith('<div class="kit-feedback wrong"')
True
>>> m = PredictRevealMany("Which are even?", [1, 2, 3, 4], [2, 4])
>>> m.choose(2); m.choose(4); m.submit()
True
"""
from __future__ import annotations

import base64
import html
from typing import Any, Callable, Iterable, Sequence

import ipywidgets as widgets
import numpy as np

from reference_impl.teaching.bowyer_watson import INFINITE, Step, bowyer_watson
from reference_impl.validate import as_points
from reference_impl.exact.predicates import incircle, orient2d

from .render import (COLORS, Canvas, draw_circumcircle, draw_edges, draw_points, draw_triangles,
                     fill_triangles, fit_bounds)
from .widget import KitWidget, button

__all__ = ["PredictReveal", "PredictRevealMany", "bad_triangles_quiz", "locally_delaunay_quiz"]


def _pairs(choices: Iterable) -> list[tuple[str, Any]]:
    out = []
    for c in choices:
        out.append((str(c[0]), c[1]) if isinstance(c, tuple) and len(c) == 2 else (str(c), c))
    return out


class _Quiz(KitWidget):
    def __init__(self, question: str, choices: Sequence, explain: str,
                 figure: Callable[[Any], None] | None, bounds, size: tuple[int, int]) -> None:
        self.question = question
        self.choices = _pairs(choices)
        if len(self.choices) < 2:
            raise ValueError("a predict-then-reveal question needs at least two choices")
        self.explain = explain
        self.revealed = False
        self.correct: bool | None = None
        self._png = None
        children: list = [widgets.HTML(f'<div class="kit-question"><b>Predict:</b> {question}</div>')]
        if figure is not None:
            canvas = Canvas(*size)
            figure(canvas.clear(bounds=bounds))
            self._png = canvas.png()
            children.append(widgets.Image(value=self._png, format="png",
                                          layout=widgets.Layout(width=f"{size[0]}px")))
        self.submit_button = button("commit and reveal", "", "14em", button_style="primary", disabled=True)
        self.feedback = widgets.HTML()
        children += [self._selector(), self.submit_button, self.feedback]
        super().__init__(children)
        self.add_class("kit-predict-reveal")
        self.submit_button.on_click(self.guard(lambda _: self.submit()))

    # -- what subclasses define
    def _selector(self) -> widgets.Widget:
        raise NotImplementedError

    def _selected(self) -> Any:
        raise NotImplementedError

    def _is_right(self, value: Any) -> bool:
        raise NotImplementedError

    def _answer_text(self) -> str:
        raise NotImplementedError

    def _lock(self) -> None:
        raise NotImplementedError

    # -- shared
    def submit(self) -> bool:
        """Lock the choice, reveal the answer; returns whether the choice was right."""
        if self.revealed:
            return bool(self.correct)
        self.correct = bool(self._is_right(self._selected()))
        self.revealed = True
        self._lock()
        self.submit_button.disabled = True
        verdict = "Right." if self.correct else "Not quite."
        self.feedback.value = (f'<div class="kit-feedback {"right" if self.correct else "wrong"}" '
                               f'style="padding:4px;border-left:4px solid '
                               f'{"#2a7f2a" if self.correct else "#d62728"}">'
                               f'<b>{verdict}</b> The answer: {html.escape(self._answer_text())}. '
                               f'{self.explain}</div>')
        return self.correct

    def static_png(self) -> bytes | None:
        return self._png

    def static_text(self) -> str:
        return f"Predict: {html.unescape(self.question)} (answer: {self._answer_text()})"

    def _repr_mimebundle_(self, **kwargs: Any) -> dict:
        bundle = super()._repr_mimebundle_(**kwargs)
        img = ""
        if self._png is not None:
            img = f'<img src="data:image/png;base64,{base64.b64encode(self._png).decode()}"><br>'
        items = "".join(f"<li>{html.escape(label)}</li>" for label, _ in self.choices)
        bundle["text/html"] = (f'<div class="kit-predict-reveal-static"><p><b>Predict:</b> {self.question}</p>'
                               f"{img}<ul>{items}</ul><details><summary>Answer</summary>"
                               f"<p>{html.escape(self._answer_text())}. {self.explain}</p></details></div>")
        return bundle


class PredictReveal(_Quiz):
    """One question, one right choice; ``choose(value)`` then ``submit()``.

    ``choices``: values, or ``(label, value)`` pairs; ``figure(ax)`` draws an optional picture.
    """

    def __init__(self, question: str, choices: Sequence, answer: Any, explain: str = "", *,
                 figure: Callable[[Any], None] | None = None, bounds=None,
                 size: tuple[int, int] = (360, 300)) -> None:
        self.answer = answer
        super().__init__(question, choices, explain, figure, bounds, size)
        if answer not in [v for _, v in self.choices]:
            raise ValueError(f"the answer {answer!r} is not one of the choices")

    def _selector(self) -> widgets.Widget:
        self.options = widgets.RadioButtons(options=self.choices, value=None,
                                            layout=widgets.Layout(width="auto"))
        self.options.observe(self.guard(self._on_pick), names="value")
        return self.options

    def _on_pick(self, change) -> None:
        self.submit_button.disabled = change["new"] is None or self.revealed

    def choose(self, value: Any) -> None:
        """Select a choice by its value (as a click on it would)."""
        if self.revealed:
            raise ValueError("the answer was already revealed; the choice is locked")
        if value not in [v for _, v in self.choices]:
            raise ValueError(f"{value!r} is not one of the choices")
        self.options.value = value

    def _selected(self) -> Any:
        return self.options.value

    def _is_right(self, value: Any) -> bool:
        return value == self.answer

    def _answer_text(self) -> str:
        return next(label for label, v in self.choices if v == self.answer)

    def _lock(self) -> None:
        self.options.disabled = True


class PredictRevealMany(_Quiz):
    """Tick every right choice (a checkbox each); right means exactly the set of answers."""

    def __init__(self, question: str, choices: Sequence, answers: Iterable, explain: str = "", *,
                 figure: Callable[[Any], None] | None = None, bounds=None,
                 size: tuple[int, int] = (360, 300)) -> None:
        self.answers = list(answers)
        super().__init__(question, choices, explain, figure, bounds, size)
        values = [v for _, v in self.choices]
        missing = [a for a in self.answers if a not in values]
        if missing:
            raise ValueError(f"the answer {missing[0]!r} is not one of the choices")
        self.submit_button.disabled = False   # "none of them" is a valid prediction

    def _selector(self) -> widgets.Widget:
        self.boxes = [widgets.Checkbox(value=False, description=label, indent=False)
                      for label, _ in self.choices]
        return widgets.VBox(self.boxes)

    def choose(self, value: Any) -> None:
        """Tick the choice with this value."""
        if self.revealed:
            raise ValueError("the answer was already revealed; the choice is locked")
        values = [v for _, v in self.choices]
        if value not in values:
            raise ValueError(f"{value!r} is not one of the choices")
        self.boxes[values.index(value)].value = True

    def _selected(self) -> list:
        return [v for (_, v), box in zip(self.choices, self.boxes) if box.value]

    def _is_right(self, value: list) -> bool:
        return sorted(map(repr, value)) == sorted(map(repr, self.answers))

    def _answer_text(self) -> str:
        labels = [label for label, v in self.choices if v in self.answers]
        return ", ".join(labels) if labels else "none of them"

    def _lock(self) -> None:
        for box in self.boxes:
            box.disabled = True


# ----------------------------------------------------------------------------- ready-made questions
def _name(t, P: np.ndarray | None = None, startup: bool = False) -> str:
    """A choice's label.  A ghost triangle (a, b, inf) is named as the dry run names it, with the
    region it covers: the outside of hull edge a-b, or, while only two points exist (both ghosts
    share the line through them), the side of that line, which the figure draws."""
    if INFINITE in t:
        a, b = t[0], t[1]
        if startup and P is not None:
            dx, dy = P[b] - P[a]
            nx, ny = -dy, dx                   # the ghost (a, b, inf) covers the left of a->b
            side = (("above" if ny > 0 else "below") if abs(ny) >= abs(nx)
                    else ("left of" if nx < 0 else "right of"))
            return f"ghost ({a}, {b}, inf): the half-plane {side} the line through {a} and {b}"
        return f"ghost ({a}, {b}, inf): outside hull edge {min(a, b)}-{max(a, b)}"
    return "triangle (" + ", ".join(map(str, t)) + ")"


def bad_triangles_quiz(points, k: int, *, order: str = "input") -> PredictRevealMany:
    """"Point k is about to be inserted: which triangles are bad?" for the k-th inserted point.

    ``k`` counts insertions from 0 (the first two only start the triangulation,
    so ``k >= 2``).  The choices are the triangles before the insertion and the
    outside of every hull edge (a ghost triangle); the answer is the trace's ``bad``.

    >>> q = bad_triangles_quiz([(1, 1), (3, 2), (5, 1), (4, 4)], 3)
    >>> q.answers
    [(0, 1, -1), (1, 2, -1)]
    """
    P = as_points(points)
    steps: list[Step] = []
    bowyer_watson(P, trace=steps, order=order)
    if not 2 <= k < len(steps):
        raise ValueError(f"k must be between 2 and {len(steps) - 1} (the insertions that have bad triangles)")
    s, before = steps[k], steps[k - 1]
    tris = [tuple(t) for t in before.triangles.tolist()]
    # the ghost triangles before step k: (b, a, INFINITE) for each hull edge a->b of `before`
    if tris:
        edges = {(t[j], t[(j + 1) % 3]) for t in tris for j in range(3)}
        ghosts = sorted((b, a, INFINITE) for a, b in edges if (b, a) not in edges)
    else:   # only the two start-up ghosts of the first two points exist
        i, j = steps[0].index, steps[1].index
        ghosts = [(i, j, INFINITE), (j, i, INFINITE)]
    startup = not tris
    choices = [(_name(t, P, startup), t) for t in tris + ghosts]
    bounds = fit_bounds(P)

    def figure(ax) -> None:
        draw_triangles(ax, P, before.triangles)
        if startup:   # the line through the first two points: the ghosts are the half-planes on its sides
            i, j = steps[0].index, steps[1].index
            (x0, y0), (x1, y1) = P[i], P[j]
            span = 4 * max(bounds[2] - bounds[0], bounds[3] - bounds[1])
            d = np.array([x1 - x0, y1 - y0]) / np.hypot(x1 - x0, y1 - y0)
            ax.plot([x0 - span * d[0], x0 + span * d[0]], [y0 - span * d[1], y0 + span * d[1]],
                    linestyle="--", color=COLORS["circle"], linewidth=1)
            ax.set_xlim(bounds[0], bounds[2])
            ax.set_ylim(bounds[1], bounds[3])
        shown = [st.index for st in steps[:k]]
        draw_points(ax, P[shown], labels=[str(i) for i in shown])
        draw_points(ax, P[[s.index]], color=COLORS["new_point"], size=60, labels=[f"new {s.index}"])

    answers = [next(c for c in (t, t[1:] + t[:1], t[2:] + t[:2]) if c in tris + ghosts) for t in s.bad]
    return PredictRevealMany(
        f"Point {s.index} (red) is inserted next. Which triangles are <i>bad</i> "
        "(their circumcircle contains the new point)? The outside of a hull edge counts as bad "
        "when the point lies beyond that edge.", choices, answers,
        explain=f"{len(s.bad)} bad, cavity boundary of {len(s.boundary)} edges, {len(s.new)} new triangles.",
        figure=figure, bounds=bounds)


def locally_delaunay_quiz(points, edge: tuple[int, int], triangles) -> PredictReveal:
    """"Is edge (i, j) locally Delaunay?": the two triangles on it and one circumcircle drawn.

    >>> pts = [(0, 0), (4, 0), (4, 1), (0, 3)]
    >>> locally_delaunay_quiz(pts, (1, 3), [(0, 1, 3), (1, 2, 3)]).answer
    'no'
    """
    P = as_points(points)
    T = [tuple(int(v) for v in t) for t in np.asarray(triangles).reshape(-1, 3)]
    i, j = edge
    pair = [t for t in T if i in t and j in t]
    if len(pair) != 2:
        raise ValueError(f"edge {i}-{j} must be an interior edge (shared by two triangles)")
    t1, t2 = pair
    if orient2d(P[t1[0]], P[t1[1]], P[t1[2]]) < 0:
        t1 = t1[::-1]
    far = next(v for v in t2 if v not in (i, j))
    inside = incircle(P[t1[0]], P[t1[1]], P[t1[2]], P[far]) > 0
    bounds = fit_bounds(P)

    def figure(ax) -> None:
        fill_triangles(ax, P, pair, color=COLORS["located"], alpha=0.5)
        draw_triangles(ax, P, T)
        draw_edges(ax, P, [edge], color=COLORS["flip"], linewidth=3)
        draw_circumcircle(ax, *P[list(t1)])
        draw_points(ax, P, labels=True)

    return PredictReveal(
        f"Is the orange edge {i}-{j} locally Delaunay (is point {far} outside the dashed circle "
        f"through triangle {t1})?", [("yes", "yes"), ("no", "no")], "no" if inside else "yes",
        explain=(f"Point {far} is {'inside' if inside else 'not inside'} the circumcircle (exact "
                 "in-circle test), so " + ("a flip replaces the edge by the other diagonal."
                                           if inside else "the edge stays.")),
        figure=figure, bounds=bounds)
