"""The build step of the `mipgen` wheel (metadata: pyproject.toml; docs/packaging.md).

The generator reads templates/, spec/schema/, spec/common/, VERSION, LICENSE and the formatter configurations
from the checkout, and the runtimes from generator/targets/<lang>/runtime/ (generator/resources.py).
A wheel has no checkout: this step copies them into the built package (generator/_data/ and the
runtime directories) so that git keeps one copy of each. An editable install reads the checkout.
"""

from __future__ import annotations

import shutil
import sys
from pathlib import Path

from setuptools import setup
from setuptools.command.build_py import build_py

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE / "generator"))
from resources import SHIPPED  # noqa: E402  (generator/resources.py, without importing the package)

sys.path.pop(0)
sys.path.insert(0, str(HERE))
from generator.targets import NAMES as LANGS  # noqa: E402  (the target registry; imports no back end)

sys.path.pop(0)
# Build products and caches that may lie in a checkout's runtime directories.
_IGNORE = shutil.ignore_patterns("target", "Cargo.lock", "__pycache__", "*.pyc", "build", "*.egg-info", ".*cache")


class BuildWithResources(build_py):
    def run(self) -> None:
        super().run()
        if getattr(self, "editable_mode", False):
            return  # an editable install reads the checkout (generator/resources.py CHECKOUT)
        package = Path(self.build_lib, "generator")
        data = package / "_data"
        shutil.rmtree(data, ignore_errors=True)
        for name in SHIPPED:
            src, dest = HERE / name, data / name
            if src.is_dir():
                shutil.copytree(src, dest, ignore=_IGNORE)
            elif src.is_file():
                dest.parent.mkdir(parents=True, exist_ok=True)
                shutil.copy2(src, dest)
            else:
                raise SystemExit(f"mipgen build: {name} is missing from {HERE}")
        for lang in LANGS:
            dest = package / "targets" / lang / "runtime"
            shutil.rmtree(dest, ignore_errors=True)
            shutil.copytree(HERE / "generator" / "targets" / lang / "runtime", dest, ignore=_IGNORE)


setup(cmdclass={"build_py": BuildWithResources})
