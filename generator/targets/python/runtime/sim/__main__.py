"""python -m <package>.sim: the simulated device (see <package>.sim)."""

import sys

from .cli import main

sys.exit(main())
