"""The teaching code: the readable Bowyer-Watson (``bowyer_watson``, with its step trace for the
widgets) and the original tutorial's code with its bugs (``tutorial_bugs``).

Imports only ``reference_impl.exact``, ``reference_impl.validate`` and ``mesh.ordering``.
"""
