"""What every kit widget shares: callbacks that report their errors, and a static picture.

Run the examples:  python -m pytest reference_impl/kit/widget.py

* JupyterLab swallows exceptions raised in widget callbacks.  ``KitWidget.guard``
  wraps a callback so that its traceback is printed into the widget's own
  ``Output`` area (``.errors``), visible under the widget.
* A notebook executed without a browser (nbclient, nbconvert, CI) has no widget
  front end.  ``KitWidget._repr_mimebundle_`` adds a PNG (``static_png``) and a
  line of text (``static_text``) next to the widget view, so the exported
  notebook still shows a picture; JupyterLab with a live kernel shows the widget.

>>> import ipywidgets as widgets
>>> class Hello(KitWidget):
...     def static_text(self): return "hello"
>>> w = Hello([widgets.Label("hi")])
>>> sorted(w._repr_mimebundle_())
['application/vnd.jupyter.widget-view+json', 'text/plain']
>>> boom = w.guard(lambda *_: 1 / 0)
>>> boom()                      # no exception escapes; the traceback went to w.errors
>>> "ZeroDivisionError" in str(w.errors.outputs)
True
"""
from __future__ import annotations

import base64
import functools
import traceback
from typing import Any, Callable

import ipywidgets as widgets

__all__ = ["KitWidget", "button", "png_image"]


class KitWidget(widgets.VBox):
    """A VBox with an error log (``.errors``), guarded callbacks and a static fallback picture."""

    def __init__(self, children=(), **kwargs: Any) -> None:
        self.errors = widgets.Output(layout=widgets.Layout(max_height="12em", overflow="auto"))
        super().__init__(list(children) + [self.errors], **kwargs)

    def guard(self, fn: Callable[..., Any]) -> Callable[..., Any]:
        """``fn`` wrapped so that an exception prints its traceback into ``.errors`` instead of vanishing."""

        @functools.wraps(fn)
        def wrapped(*args: Any, **kwargs: Any) -> Any:
            try:
                return fn(*args, **kwargs)
            except Exception:  # noqa: BLE001 - shown to the student, never swallowed silently
                self.errors.append_stdout(traceback.format_exc())
                return None

        return wrapped

    # -- the static fallback
    def static_png(self) -> bytes | None:
        """PNG bytes shown where no widget front end is attached (``None``: no picture)."""
        return None

    def static_text(self) -> str:
        """One line that says what the widget shows."""
        return type(self).__name__

    def _repr_mimebundle_(self, **kwargs: Any) -> dict:
        bundle = super()._repr_mimebundle_(**kwargs) or {}
        if isinstance(bundle, tuple):  # (data, metadata) in some ipywidgets versions
            bundle = bundle[0]
        bundle = dict(bundle)
        png = self.static_png()
        if png is not None:
            bundle["image/png"] = base64.b64encode(png).decode("ascii")
        bundle["text/plain"] = self.static_text()
        return bundle


def button(description: str, icon: str = "", width: str = "8.5em", **kwargs: Any) -> widgets.Button:
    """A kit button: a label, a Font Awesome icon, a fixed width."""
    return widgets.Button(description=description, icon=icon, layout=widgets.Layout(width=width), **kwargs)


def png_image(width: int) -> widgets.Image:
    """An empty PNG ``Image`` shown ``width`` pixels wide (the kit draws into it)."""
    return widgets.Image(format="png", layout=widgets.Layout(width=f"{width}px"))
