"""Builds the tests start on first use, safe when several pytest workers ask at once
(`make test-conformance` runs on `-n` workers): `build_lock(dir)` holds DIR/.build-lock (the lock
tests/lang/lock.sh takes in the shell runners) while a tree is configured and built; `c_device_tool`
is the C packages' device tool (`<package>-device`, tools/device/) with the project's strict flags."""

from __future__ import annotations

import contextlib
import fcntl
import shutil
import subprocess
from pathlib import Path
from typing import Iterator

ROOT = Path(__file__).resolve().parents[2]
SAN_FLAGS = "-fsanitize=address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer"


@contextlib.contextmanager
def build_lock(directory: Path) -> Iterator[None]:
    """Holds DIRECTORY's build lock (created with the directory when missing) for the block."""
    directory.mkdir(parents=True, exist_ok=True)
    with open(directory / ".build-lock", "w") as f:
        fcntl.flock(f, fcntl.LOCK_EX)
        try:
            yield
        finally:
            fcntl.flock(f, fcntl.LOCK_UN)


def c_device_tool(package: str, sanitize: bool = False) -> Path:
    """build/c-device/<package>/<package>-device (c-device-sanitize with AddressSanitizer and
    UndefinedBehaviorSanitizer), configured once and built (a no-op when up to date) with warnings
    as errors; the build's output in the assertion when it fails."""
    assert shutil.which("cmake"), "cmake is needed to build the C packages"
    build = ROOT / "build" / ("c-device-sanitize" if sanitize else "c-device") / package
    with build_lock(build):
        if not (build / "CMakeCache.txt").exists():
            configured = subprocess.run(
                [
                    "cmake",
                    *(["-G", "Ninja"] if shutil.which("ninja") else []),
                    "-S",
                    str(ROOT / "generated" / "c" / package),
                    "-B",
                    str(build),
                    "-DCMAKE_BUILD_TYPE=Debug",
                    f"-D{package.upper()}_WERROR=ON",
                    f"-D{package.upper()}_BUILD_TOOLS=ON",
                    f"-D{package.upper()}_BUILD_TESTS=OFF",
                    f"-D{package.upper()}_BUILD_EXAMPLES=OFF",
                    *([f"-DCMAKE_C_FLAGS={SAN_FLAGS}", f"-DCMAKE_EXE_LINKER_FLAGS={SAN_FLAGS}"] if sanitize else []),
                ],
                capture_output=True,
                text=True,
            )
            assert configured.returncode == 0, configured.stdout + configured.stderr
        built = subprocess.run(
            ["cmake", "--build", str(build), "--target", f"{package}_c_device"], capture_output=True, text=True
        )
        assert built.returncode == 0, built.stdout + built.stderr
    return build / f"{package}-device"
