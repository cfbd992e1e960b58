"""The teaching code: the readable Bowyer-Watson (``bowyer_watson``, with its step trace for the
widgets), the original tutorial's code with its bugs (``tutorial_bugs``), and lesson 13's theory in
checkable code (``theory``, ``locate``, ``segment``, ``cavity3d``).

Imports only ``reference_impl.exact``, ``reference_impl.validate`` and ``mesh.ordering``.
"""
