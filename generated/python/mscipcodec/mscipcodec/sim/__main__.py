"""python -m mscipcodec.sim: the simulated device (see mscipcodec.sim)."""

import sys

from . import main

sys.exit(main())
