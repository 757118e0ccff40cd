"""Each extra alone (issue 50 item 5): `mipcodec[EXTRA]` installed by itself into a fresh virtualenv
from the package's wheel and PyPI, then its documentation's example run there, so an extra that
forgets a library fails here. `make test-extras` (not part of `make test`: it needs PyPI; `.ci/run`
runs it after `make test`); the convention is docs/conformance.md §11.

- The extras are the generated package's own (`mipcodec._extras.REQUIRES`, from the generator's
  table): a new extra is covered as soon as it exists, and one without an example fails.
- The wheel is tests/consumer/test_python_package.py's (reused through test_outside_user.wheels()).
- uv stands in for pip (the version pinned in requirements.txt): `uv venv` (no pip, no .pth: the
  project's .venv libraries are not seen) and `uv pip install 'mipcodec[EXTRA] @ file:///...whl'`
  with the project's pinned versions as constraints (the extras' lower bounds; a constraint adds
  no library, so a forgotten one stays missing); `--offline` first, so a warm cache (UV_CACHE_DIR,
  else ~/.cache/uv) installs without the network and without building pyspark's sdist again.
- The examples stay in the user pages (one source): a block marked `<!-- extra-example: EXTRA[,EXTRA]
  [INPUT...] -->` on a line just before its fence (beside an `outside-user` marker, either order)
  is run with test_outside_user's Runner in the extra's virtualenv, the blocks of one extra in
  page order in one directory. A `pip install` command of such a block is not run (uv installed the
  extra) but must name exactly that extra. INPUTs are what the extra cannot make, made before by the
  project's .venv: `NAME.bin` a simulated device log, `NAME/` a directory of them (the `files`
  marker's placeholders), `dataset:NAME` a dataset of them (`export --dataset`).
- `[all]` is the union of every other extra, and runs its examples too.
- A missing library is one line naming it and its extra: `export --dataset` in the `[query]`-only
  virtualenv exits 2 naming numpy or pyarrow and `mipcodec[export]`.
"""

from __future__ import annotations

import importlib
import os
import re
import shutil
import subprocess
import sys
import sysconfig
import time
from pathlib import Path

import pytest

from tests.consumer.test_outside_user import PAGES, Block, Runner, blocks, fleet_logs, strip_comment, wheels
from tests.consumer.test_python_package import TIMINGS
from tests.helpers.generated import python_package

ROOT = Path(__file__).resolve().parents[2]
BUILD = ROOT / "build" / "extras"
PACKAGE = "mipcodec"
REQUIRES: dict[str, tuple[str, ...]] = importlib.import_module(f"{python_package(PACKAGE).__name__}._extras").REQUIRES
ENVS: dict[str, dict[str, str]] = {}  # extra -> the environment of its virtualenv (made once)


def examples() -> dict[str, list[tuple[Block, list[str]]]]:
    """extra -> its example's blocks in page order, each with its inputs."""
    found: dict[str, list[tuple[Block, list[str]]]] = {}
    for page in PAGES:
        for b in blocks(page):
            if b.extra_example:
                extras, *inputs = b.extra_example.split()
                for extra in extras.split(","):
                    found.setdefault(extra, []).append((b, inputs))
    return found


def uv() -> str:
    """The pinned uv of the project's .venv (requirements.txt), else one on PATH."""
    found = Path(sys.executable).with_name("uv")
    path = str(found) if found.exists() else shutil.which("uv")
    assert path, "uv is not installed: it is pinned in requirements.txt (make installs it into .venv)"
    return path


def constraints() -> Path:
    """The versions the project's tests run (requirements.txt, requirements-spark.txt): the extras'
    libraries are installed at these (their lower bounds), the same on every run; a library an
    extra forgets is not added by a constraint."""
    out = BUILD / "constraints.txt"
    pins = [
        line
        for name in ("requirements.txt", "requirements-spark.txt")
        for line in (ROOT / name).read_text().splitlines()
        if re.match(r"^[A-Za-z0-9_.-]+==\S+$", line)
    ]
    out.parent.mkdir(parents=True, exist_ok=True)
    out.write_text("\n".join(pins) + "\n")
    return out


def timed(cmd: list[str], what: str, **kwargs) -> subprocess.CompletedProcess:
    start = time.monotonic()
    proc = subprocess.run(cmd, capture_output=True, text=True, **kwargs)
    TIMINGS[f"extras alone: {what}"] = time.monotonic() - start
    assert proc.returncode == 0, f"{what}: exit {proc.returncode}\n{proc.stdout[-3000:]}\n{proc.stderr[-3000:]}"
    return proc


@pytest.fixture(scope="module")
def wheel() -> Path:
    (found,) = wheels().glob(f"{PACKAGE}-*.whl")
    return found


@pytest.fixture(scope="module")
def logs() -> Path:
    return fleet_logs(BUILD / "logs", "extras alone")


def extra_env(extra: str, wheel: Path) -> dict[str, str]:
    """A fresh virtualenv with only `PACKAGE[extra]` (the wheel, its libraries from PyPI), first on
    PATH; the user's environment (no PYTHONPATH, HOME in the work directory). Made once per extra."""
    if extra in ENVS:
        return ENVS[extra]
    home = BUILD / extra
    shutil.rmtree(home, ignore_errors=True)
    venv = home / "venv"
    env = {k: v for k, v in os.environ.items() if not k.startswith(("PYTHON", "VIRTUAL_ENV", "PIP_", "UV_"))}
    uv_env = {**env, "UV_PYTHON_DOWNLOADS": "never", "UV_NO_PROGRESS": "1"}
    if "UV_CACHE_DIR" in os.environ:
        uv_env["UV_CACHE_DIR"] = os.environ["UV_CACHE_DIR"]
    timed([uv(), "venv", "--quiet", "--python", sys.executable, str(venv)], f"[{extra}]: uv venv", env=uv_env)
    python = str(venv / "bin" / "python")
    cmd = [uv(), "pip", "install", "--quiet", "--python", python, "--constraint", str(constraints())]
    cmd.append(f"{PACKAGE}[{extra}] @ {wheel.as_uri()}")
    # from the cache alone when it has everything (uv finds PyPI's cached responses stale and would
    # build pyspark's sdist again), else from PyPI
    start = time.monotonic()
    proc = subprocess.run([*cmd, "--offline"], capture_output=True, text=True, env=uv_env)
    how = "from the cache"
    if proc.returncode != 0:
        proc, how = subprocess.run(cmd, capture_output=True, text=True, env=uv_env), "from PyPI"
    TIMINGS[f"extras alone: [{extra}]: uv pip install ({how})"] = time.monotonic() - start
    assert proc.returncode == 0, f"[{extra}]: {' '.join(cmd)}: exit {proc.returncode}\n{proc.stderr[-3000:]}"
    (home / "work").mkdir()
    env.update(HOME=str(home), PATH=f"{venv / 'bin'}{os.pathsep}{env.get('PATH', '')}", VIRTUAL_ENV=str(venv))
    # the virtualenv sees none of the project's libraries
    seen = subprocess.run([python, "-c", "import sys; print(sys.path)"], capture_output=True, text=True, env=env)
    assert sysconfig.get_paths()["purelib"] not in seen.stdout, seen.stdout
    ENVS[extra] = env
    return env


class ExtraRunner(Runner):
    """test_outside_user's Runner in the virtualenv of one extra: the example's `pip install`
    command is checked (it installs exactly that extra), not run."""

    def __init__(self, extra: str, env: dict[str, str], logs: Path, work: Path) -> None:
        super().__init__(f"[{extra}]", env, logs, work)
        self.extra = extra

    def run(self, command: str, shown: str, cwd: Path, where: str, package: str = "") -> None:
        line = self.substitute(strip_comment(command), package)
        if re.match(r"pip3? install ", line):
            assert line.split()[2:] == [f"'{PACKAGE}[{self.extra}]'"], (
                f"{where}: the example of [{self.extra}] installs `{line}`, not '{PACKAGE}[{self.extra}]'"
            )
            return
        super().run(command, shown, cwd, where, package)

    def inputs(self, names: list[str], cwd: Path) -> None:
        """The inputs the extra cannot make, by the project's .venv."""
        for name in names:
            if (cwd / name.removeprefix("dataset:")).exists():
                continue
            if name.startswith("dataset:"):
                out = cwd / name.removeprefix("dataset:")
                logs = [str(log) for log in sorted(self.logs.glob("*.mip"))]
                cmd = [sys.executable, "-m", PACKAGE, "export", "--dataset", str(out), *logs]
                env = {**os.environ, "PYTHONPATH": str(ROOT / "generated" / "python" / PACKAGE)}
                timed(cmd, f"[{self.extra}]: {name} (placeholder, the project's .venv)", env=env)
            else:
                self.files([name], cwd)


def test_every_extra_has_an_example() -> None:
    """Every extra of the package has an example on a user page, and every example's extra exists."""
    found = examples()
    assert sorted(found) == sorted(REQUIRES), (
        f"extras without an example (mark one with <!-- extra-example: EXTRA -->): {sorted(set(REQUIRES) - set(found))}; "
        f"examples of unknown extras: {sorted(set(found) - set(REQUIRES))}"
    )


def test_all_is_every_extra() -> None:
    union = {r for extra, reqs in REQUIRES.items() if extra != "all" for r in reqs}
    assert set(REQUIRES["all"]) == union
    assert len(REQUIRES["all"]) == len(union)


@pytest.mark.parametrize("extra", sorted(REQUIRES))
def test_extra_alone(extra: str, wheel: Path, logs: Path) -> None:
    """The extra alone in a fresh virtualenv runs its documentation's example."""
    example = examples().get(extra)
    assert example, f"[{extra}] has no example: mark its documented commands with <!-- extra-example: {extra} -->"
    env = extra_env(extra, wheel)
    runner = ExtraRunner(extra, env, logs, Path(env["HOME"]) / "work")
    start = time.monotonic()
    try:
        for b, inputs in example:
            runner.inputs(inputs, runner.work)
            runner.block(b)
    finally:
        runner.close()
    TIMINGS[f"extras alone: [{extra}]: its example ({runner.count} commands)"] = time.monotonic() - start


def test_missing_library_names_it_and_its_extra(wheel: Path, logs: Path) -> None:
    """In the `[query]`-only virtualenv (no numpy, no pyarrow), `export --dataset` is one line on
    stderr naming the library and `mipcodec[export]`, exit status 2 (docs/log-to-csv.md)."""
    env = extra_env("query", wheel)
    log = sorted(logs.glob("*.mip"))[0]
    cwd = Path(env["HOME"])
    proc = subprocess.run(
        ["python", "-m", PACKAGE, "export", "--dataset", "out", str(log)],
        capture_output=True,
        text=True,
        env=env,
        cwd=cwd,
    )
    assert proc.returncode == 2, (proc.returncode, proc.stderr)
    lines = proc.stderr.splitlines()
    assert len(lines) == 1, proc.stderr
    assert re.search(r"\b(numpy|pyarrow)\b.*\bis not installed\b.*'mipcodec\[export\]'", lines[0]), lines[0]
    assert not (cwd / "out").exists()
