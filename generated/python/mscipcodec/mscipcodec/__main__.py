"""python -m mscipcodec decode|encode|export|... (see mscipcodec.cli). A Ctrl-C while the command
line's modules load (a slow start on a busy machine) ends it as a later one does: status 130, no
traceback."""

import sys

try:
    from .cli import main
except KeyboardInterrupt:
    sys.exit(130)

sys.exit(main())
