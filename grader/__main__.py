"""Entry point: ``python -m grader --help`` (see grader/cli.py)."""
import sys

from .cli import main

sys.exit(main())
