"""python -m mipcodec.sim: the simulated device (see mipcodec.sim)."""

import sys

from . import main

sys.exit(main())
