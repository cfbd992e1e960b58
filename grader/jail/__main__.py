"""``python -m grader.jail``: the doctor (:mod:`grader.jail.doctor`)."""
import sys

from .doctor import main

sys.exit(main(sys.argv[1:]))
