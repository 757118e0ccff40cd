"""python -m mscipcodec decode|encode (see mscipcodec.cli)."""

import sys

from .cli import main

sys.exit(main())
