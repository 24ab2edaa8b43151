"""``python -m course``: the classroom's command line (:mod:`course.classroom.cli`)."""

import sys

from course.classroom.cli import main

if __name__ == "__main__":
    sys.exit(main())
