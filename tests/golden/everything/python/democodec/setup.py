"""Build of democodec: pyproject.toml holds the metadata; this adds the optional C accelerator.

`democodec/_speedups.c` (the stream parser and packet decoder in C) is compiled when a C compiler
and the Python headers are there. Without them the build still succeeds (the extension is
optional) and the package runs its pure-Python code, which gives the same results. At run time
DEMOCODEC_PURE=1 forces the pure-Python code; `democodec.ACCELERATED` tells which is in use.
DEMOCODEC_NO_EXTENSION=1 at build time skips the extension.
"""

import os

from setuptools import Extension, setup

extensions = []
if os.environ.get("DEMOCODEC_NO_EXTENSION", "") in ("", "0"):
    # _protocol.h (the protocol's constants, generated) and grisu3.h (the float digits) are
    # #included by _speedups.c: listed so that a change rebuilds the extension and the sdist carries them.
    extensions.append(
        Extension(
            "democodec._speedups",
            ["democodec/_speedups.c"],
            depends=["democodec/_protocol.h", "democodec/grisu3.h"],
            optional=True,
        )
    )

setup(ext_modules=extensions)
