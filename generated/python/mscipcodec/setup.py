"""Build of mscipcodec: pyproject.toml holds the metadata; this adds the optional C accelerator.

`mscipcodec/_speedups.c` (the stream parser and packet decoder in C) is compiled when a C compiler
and the Python headers are there. Without them the build still succeeds (the extension is
optional) and the package runs its pure-Python code, which gives the same results. At run time
MSCIPCODEC_PURE=1 forces the pure-Python code; `mscipcodec.ACCELERATED` tells which is in use.
MSCIPCODEC_NO_EXTENSION=1 at build time skips the extension.
"""

import os

from setuptools import Extension, setup

extensions = []
if os.environ.get("MSCIPCODEC_NO_EXTENSION", "") in ("", "0"):
    # _protocol.h (the protocol's constants, generated) and grisu3.h (the float digits) are
    # #included by _speedups.c: listed so that a change rebuilds the extension and the sdist carries them.
    extensions.append(
        Extension(
            "mscipcodec._speedups",
            ["mscipcodec/_speedups.c"],
            depends=["mscipcodec/_protocol.h", "mscipcodec/grisu3.h"],
            optional=True,
        )
    )

setup(ext_modules=extensions)
