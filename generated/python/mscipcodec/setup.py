"""Build of mscipcodec: pyproject.toml holds the metadata; this adds the optional C accelerator.

`mscipcodec/codec/_speedups*.c` (the stream parser and packet decoder in C) are compiled when a C compiler
and the Python headers are there. Without them the build still succeeds (the extension is
optional) and the package runs its pure-Python code, which gives the same results. At run time
MSCIPCODEC_PURE=1 forces the pure-Python code; `mscipcodec.ACCELERATED` tells which is in use.
MSCIPCODEC_NO_EXTENSION=1 at build time skips the extension.
"""

import glob
import os

from setuptools import Extension, setup

extensions = []
if os.environ.get("MSCIPCODEC_NO_EXTENSION", "") in ("", "0"):
    # The C files of the codec room, compiled together into one module; _protocol.h (the
    # protocol's constants, generated), grisu3.h (the float digits) and the files' shared header are
    # #included: listed so that a change rebuilds the extension and the sdist carries them.
    sources = sorted(glob.glob("mscipcodec/codec/_speedups*.c"))
    depends = sorted(glob.glob("mscipcodec/codec/*.h"))
    extensions.append(Extension("mscipcodec.codec._speedups", sources, depends=depends, optional=True))

setup(ext_modules=extensions)
