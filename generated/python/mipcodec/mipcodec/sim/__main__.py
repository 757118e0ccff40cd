"""python -m mipcodec.sim: the simulated device (see mipcodec.sim)."""

import sys

from .cli import main

sys.exit(main())
