"""python -m mscipcodec.sim: the simulated device (see mscipcodec.sim)."""

import sys

from .cli import main

sys.exit(main())
