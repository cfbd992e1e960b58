"""Make this folder's helper module (``fake_class``) importable for its tests."""
import os
import sys

sys.path.insert(0, os.path.dirname(__file__))
