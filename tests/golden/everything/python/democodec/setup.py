"""Build of democodec: pyproject.toml holds the metadata; this adds the optional C accelerator.

`democodec/codec/_speedups*.c` (the stream parser and packet decoder in C) are compiled when a C compiler
and the Python headers are there. Without them the build still succeeds (the extension is
optional) and the package runs its pure-Python code, which gives the same results. At run time
DEMOCODEC_PURE=1 forces the pure-Python code; `democodec.ACCELERATED` tells which is in use.
DEMOCODEC_NO_EXTENSION=1 at build time skips the extension.
"""

import glob
import os

from setuptools import Extension, setup

extensions = []
if os.environ.get("DEMOCODEC_NO_EXTENSION", "") in ("", "0"):
    # The C files of the codec room, compiled together into one module; _protocol.h (the
    # protocol's constants, generated), grisu3.h (the float digits) and the files' shared header are
    # #included: listed so that a change rebuilds the extension and the sdist carries them.
    sources = sorted(glob.glob("democodec/codec/_speedups*.c"))
    depends = sorted(glob.glob("democodec/codec/*.h"))
    extensions.append(Extension("democodec.codec._speedups", sources, depends=depends, optional=True))

setup(ext_modules=extensions)
