"""python -m <package> decode|encode (see <package>.cli)."""

import sys

from .cli import main

sys.exit(main())
