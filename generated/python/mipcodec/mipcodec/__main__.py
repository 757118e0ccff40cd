"""python -m mipcodec decode|encode (see mipcodec.cli)."""

import sys

from .cli import main

sys.exit(main())
