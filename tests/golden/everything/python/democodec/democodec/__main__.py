"""python -m democodec decode|encode (see democodec.cli)."""

import sys

from .cli import main

sys.exit(main())
