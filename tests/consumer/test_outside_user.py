"""The outside user (issue 39): every command of every user-facing page, taken from the page and run
where an outside user runs it, never in the repository. `make test-outside` (part of `make test`,
after the consumer tests whose builds it reuses); the convention is docs/conformance.md §11.

The user's machine:
- a fresh virtualenv (`python -m venv`, with pip) in a temporary directory outside the repository,
  its `bin/` first on PATH, so `python`, `pip`, `mipcodec-device` are the virtualenv's; the pages'
  `pip install` commands run as written (the repository path `generated/python/PKG` read as the
  package name) against the wheels of the session (tests/consumer/test_python_package.py's, reused
  when they are newer than the package's sources) with PIP_NO_INDEX and PIP_FIND_LINKS; the
  extras' third-party libraries (numpy, pyarrow, PyYAML, pyserial, ...) are the pinned ones of the
  project's .venv, seen through a .pth file (no network);
- for the C path, no googletest (a CMAKE_PREFIX_PATH whose GTest config fails any find_package) and
  no C++ compiler (CXX names one that does not exist); the C and C++ packages' install recipes, a
  versioned find_package and pkg-config are tests/consumer/test_consumers.py's (same build tree);
- Rust offline (CARGO_NET_OFFLINE: the registry cache the repository's builds filled), one target
  directory kept under build/outside/ so a rerun only rebuilds what changed.

Per page, in order, in one temporary working directory: ```sh blocks (each line a command; `\\`
continues; a trailing `# comment` and `&` dropped), ```console blocks (`$ ` a command, `> ` its
continuation; a command ending in `; echo "exit $?"` must print the exit status the page shows,
any other must exit 0), ```python blocks marked `run`, ```yaml blocks whose first line is
`# NAME.yaml` (written to NAME.yaml, as the configure page's test does). A command
`python -m PKG.sim ...` starts the simulator in the background (a `--listen tcp:` port becomes 0)
and the address it prints replaces, in the commands after it, the page's example addresses
(`tcp:127.0.0.1:PORT` or a port number, `/dev/pts/N`). Sections whose heading names the repository
are not run; a block is marked by an HTML comment on the line before its fence:
`<!-- outside-user: not run: REASON -->`, `<!-- outside-user: run -->` (a Python listing),
`<!-- outside-user: files NAME... -->` (placeholders the test supplies: `NAME.bin` a simulated
device log, `NAME/` a directory of them, from `python -m mipcodec.fleet`),
`<!-- outside-user: cd generated/LANG/PKG -->` (run in a copy of that package directory, made
outside the repository, as a user who vendored it), `<!-- outside-user: project -->` (a
getting-started page's CMake or Cargo snippet built as the user's project: the package in
third_party/ by add_subdirectory or path dependency, its getting-started example the program).
A block may also carry `<!-- extra-example: EXTRA... [INPUT...] -->` (either order with the
outside-user marker): tests/consumer/test_extras_alone.py runs it in a virtualenv of that extra alone.
"""

from __future__ import annotations

import os
import re
import select
import shutil
import subprocess
import sys
import sysconfig
import tempfile
import time
from dataclasses import dataclass, field
from pathlib import Path

import pytest

from tests.consumer.test_python_package import LEFTOVERS, OUT, TIMINGS, get_built

ROOT = Path(__file__).resolve().parents[2]
BUILD = ROOT / "build" / "outside"
# The user-facing pages (README's documentation table and the pages they lead to).
PAGES = [
    "docs/simulator.md",
    "docs/application-against-the-simulator.md",
    "docs/configure-a-device.md",
    "docs/record.md",
    "docs/log-to-csv.md",
    "docs/dataset.md",
    "docs/mcap.md",
    "docs/rtk-and-nmea.md",
    "docs/timesync.md",
    "docs/time.md",
    "docs/fleet.md",
    "docs/packaging.md",
    "generated/docs/getting-started/c.md",
    "generated/docs/getting-started/cpp.md",
    "generated/docs/getting-started/python.md",
    "generated/docs/getting-started/rust.md",
]
PYTHON_PACKAGES = ["mipcodec", "mscipcodec"]
FENCE = re.compile(r"^(`{3,})(\w*)\n(.*?)^\1\n", re.S | re.M)
# A block's markers: the comments on the lines just before its fence, in either order.
MARKER = re.compile(r"<!-- outside-user: (.*?) -->\n(?:<!-- extra-example: .*? -->\n)?$")
# The example of an extra (tests/consumer/test_extras_alone.py): `EXTRA[,EXTRA...] [INPUT...]`.
EXTRA_MARKER = re.compile(r"<!-- extra-example: (.*?) -->\n(?:<!-- outside-user: .*? -->\n)?$")
# The pages' example addresses, replaced by the running simulator's.
ADDRESS = re.compile(r"tcp:127\.0\.0\.1:(?:PORT|[1-9]\d*)|/dev/pts/\d+")
SIM = re.compile(r"^python3? -m (\w+)\.sim\b")
COUNTS: dict[str, int] = {}


@dataclass
class Block:
    page: str
    line: int
    lang: str
    body: str
    marker: str = ""
    extra_example: str = ""  # the extra-example marker: the extras whose example it is, its inputs
    commands: list[tuple[str, str]] = field(default_factory=list)  # (command, the output shown)

    @property
    def where(self) -> str:
        return f"{self.page}:{self.line}"


def sh_commands(body: str) -> list[tuple[str, str]]:
    out: list[tuple[str, str]] = []
    pending = ""
    for raw in body.splitlines():
        line = raw.rstrip()
        if not pending and (not line.strip() or line.lstrip().startswith("#")):
            continue
        if line.endswith("\\"):
            pending += line[:-1] + " "
            continue
        out.append((pending + line, ""))
        pending = ""
    return out


def strip_comment(command: str) -> str:
    """The command without a trailing `   # comment` (shell comments after two or more spaces)."""
    return re.split(r"\s{2,}#\s", command, maxsplit=1)[0].rstrip()


def console_commands(body: str) -> list[tuple[str, str]]:
    out: list[list[str]] = []
    for line in body.splitlines(keepends=True):
        if line.startswith("$ "):
            out.append([line[2:], ""])
        elif line.startswith("> ") and out and not out[-1][1]:
            out[-1][0] += line[2:]
        elif out:
            out[-1][1] += line
    return [(c.rstrip("\n"), o) for c, o in out]


def blocks(page: str) -> list[Block]:
    """The page's fenced blocks outside the sections about the repository, with their markers."""
    text = (ROOT / page).read_text(encoding="utf-8")
    found = []
    for m in FENCE.finditer(text):
        before = text[: m.start()]
        headings = re.findall(r"^(#+) (.*)$", before, re.M)
        # the innermost heading and its parents: any that names the repository excludes the block
        chain: list[tuple[int, str]] = []
        for hashes, title in headings:
            chain = [(n, t) for n, t in chain if n < len(hashes)] + [(len(hashes), title)]
        if any("repository" in t.lower() for _, t in chain):
            continue
        marker = MARKER.search(before)
        extra = EXTRA_MARKER.search(before)
        block = Block(page, before.count("\n") + 1, m.group(2), m.group(3), marker.group(1) if marker else "")
        block.extra_example = extra.group(1) if extra else ""
        if block.lang == "sh":
            block.commands = sh_commands(block.body)
        elif block.lang == "console":
            block.commands = console_commands(block.body)
        found.append(block)
    return found


def test_every_page_is_linked_and_every_marker_is_known():
    """The pages run here are the ones README's documentation table leads to; every marker is one of
    the convention's, and a block not run says why."""
    readme = (ROOT / "README.md").read_text(encoding="utf-8")
    table = readme[readme.index("## Documentation") :]
    for page in re.findall(r"\]\((docs/[\w.-]+\.md)\)", table.split("docs/design.md")[0]):
        assert page in PAGES, f"README's documentation table lists {page}: add it to PAGES"
    for page in PAGES:
        assert (ROOT / page).is_file(), page
        for b in blocks(page):
            if b.marker:
                assert re.fullmatch(r"not run: .{10,}|run|project|files [\w./ -]+|cd generated/\w+/\w+", b.marker), (
                    b.where,
                    b.marker,
                )
            if b.extra_example:
                assert re.fullmatch(r"[a-z]+(,[a-z]+)*( [\w.-]+/?| dataset:[\w.-]+)*", b.extra_example), (
                    b.where,
                    b.extra_example,
                )


# --- the user's machine ----------------------------------------------------------------------


def wheels() -> Path:
    """A directory with the wheels of the Python packages: those tests/consumer/test_python_package.py
    built (this session's, or a previous session's when newer than every source file), else built now."""
    links = BUILD / "wheels"
    shutil.rmtree(links, ignore_errors=True)
    links.mkdir(parents=True)
    for pkg in PYTHON_PACKAGES:
        src = ROOT / "generated" / "python" / pkg
        newest = max(p.stat().st_mtime for p in src.rglob("*") if p.is_file() and "__pycache__" not in p.parts)
        found = sorted((OUT / pkg / "dist").glob("*.whl"))
        if not (len(found) == 1 and found[0].stat().st_mtime > newest):
            found = [get_built(pkg).wheel]
        shutil.copy2(found[0], links)
    return links


def no_gtest(where: Path) -> Path:
    """A prefix whose GTest config fails any find_package(GTest) (as test_consumers.no_gtest)."""
    config = where / "lib" / "cmake" / "GTest" / "GTestConfig.cmake"
    config.parent.mkdir(parents=True, exist_ok=True)
    config.write_text('message(FATAL_ERROR "find_package(GTest) was called")\n')
    return where


@pytest.fixture(scope="module")
def machine(tmp_path_factory: pytest.TempPathFactory) -> dict[str, str]:
    """The outside user's environment: a fresh virtualenv first on PATH, no PYTHONPATH, and the
    variables that point pip at the session's wheels and keep cargo offline."""
    home = Path(tempfile.mkdtemp(prefix="outside-user-"))
    assert ROOT not in home.parents
    venv = home / "venv"
    start = time.monotonic()
    subprocess.run([sys.executable, "-m", "venv", venv], check=True)
    # the extras' libraries: the project's pinned ones (numpy, pyarrow, PyYAML, pyserial, ...)
    site = Path(
        subprocess.check_output(
            [venv / "bin" / "python", "-c", "import sysconfig; print(sysconfig.get_paths()['purelib'])"], text=True
        ).strip()
    )
    (site / "project-libraries.pth").write_text(sysconfig.get_paths()["purelib"] + "\n")
    TIMINGS["outside user: python -m venv"] = time.monotonic() - start
    env = {k: v for k, v in os.environ.items() if not k.startswith(("PYTHON", "VIRTUAL_ENV", "PIP_", "CMAKE_"))}
    env.update(
        HOME=str(home),
        PATH=f"{venv / 'bin'}{os.pathsep}{env.get('PATH', '')}",
        VIRTUAL_ENV=str(venv),
        PIP_NO_INDEX="1",
        PIP_FIND_LINKS=str(wheels()),
        PIP_DISABLE_PIP_VERSION_CHECK="1",
        PIP_NO_CACHE_DIR="1",
        CARGO_NET_OFFLINE="true",
        CARGO_TARGET_DIR=str(BUILD / "cargo-target"),
        CARGO_HOME=os.environ.get("CARGO_HOME", str(Path.home() / ".cargo")),
        RUSTUP_HOME=os.environ.get("RUSTUP_HOME", str(Path.home() / ".rustup")),
        # the C path: no googletest, no C++ compiler (the C package never enables C++)
        CMAKE_PREFIX_PATH=str(no_gtest(home / "no-gtest")),
        CMAKE_GENERATOR="Ninja",
        OUTSIDE_HOME=str(home),
    )
    for d in (Path(env["CARGO_HOME"]) / "bin",):
        if (d / "cargo").exists() and not shutil.which("cargo", path=env["PATH"]):
            env["PATH"] += os.pathsep + str(d)
    yield env
    shutil.rmtree(home, ignore_errors=True)


@pytest.fixture(scope="module")
def logs(machine: dict[str, str]) -> Path:
    """Simulated device logs for the pages' placeholders (`python -m mipcodec.fleet` of the generated
    package: test data, made before the pages install anything into the virtualenv)."""
    return fleet_logs(BUILD / "logs", "outside user")


def fleet_logs(out: Path, who: str) -> Path:
    """Two simulated devices' logs of 400 kB in `out` (recreated), by the project's .venv."""
    shutil.rmtree(out, ignore_errors=True)
    start = time.monotonic()
    cmd = [sys.executable, "-m", "mipcodec.fleet", "--out", str(out), "--devices", "2", "--size", "400k"]
    env = {**os.environ, "PYTHONPATH": str(ROOT / "generated" / "python" / "mipcodec")}
    proc = subprocess.run(cmd, env=env, capture_output=True, text=True)
    assert proc.returncode == 0, proc.stderr
    TIMINGS[f"{who}: python -m mipcodec.fleet (placeholder logs)"] = time.monotonic() - start
    return out


# --- running a page ----------------------------------------------------------------------------


class Runner:
    def __init__(self, page: str, env: dict[str, str], logs: Path, work: Path) -> None:
        self.page, self.env, self.logs, self.work = page, env, logs, work
        self.sims: list[subprocess.Popen] = []
        # the latest simulator's address per (package, tcp or pty), and the latest started
        self.addresses: dict[tuple[str, str], str] = {}
        self.latest = ""
        self.count = 0

    def close(self) -> None:
        for sim in self.sims:
            sim.terminate()
        for sim in self.sims:
            try:
                sim.wait(timeout=10)
            except subprocess.TimeoutExpired:
                sim.kill()
                sim.wait()

    def substitute(self, command: str, package: str = "") -> str:
        """The command with the repository's package paths read as package names and the page's
        example addresses replaced by the simulator's: the one of the package the command (or the
        package directory it runs in) names, over TCP or a pseudo-terminal as the example."""
        command = re.sub(r"'?\.?/?generated/python/(\w+)(\[[\w,]+\])?'?", lambda m: f"'{m[1]}{m[2] or ''}'", command)
        if SIM.match(command):
            return command
        named = re.findall(r"\b(" + "|".join(PYTHON_PACKAGES) + r")\b", command)
        package = named[0] if named else package

        def address(m: re.Match) -> str:
            kind = "tcp" if m[0].startswith("tcp:") else "pty"
            found = self.addresses.get((package, kind)) or next(
                (a for (_, k), a in reversed(list(self.addresses.items())) if k == kind), ""
            )
            return found or self.latest or m[0]

        return ADDRESS.sub(address, command)

    def files(self, names: list[str], cwd: Path) -> None:
        logs = sorted(self.logs.glob("*.mip"))
        assert logs, "the fleet wrote no logs"
        for name in names:
            if name.endswith("/"):  # a directory of logs, named NAME.bin as the pages' `logs/*.bin`
                (cwd / name).mkdir(parents=True, exist_ok=True)
                for log in logs:
                    shutil.copy2(log, cwd / name / f"{log.stem}.bin")
            else:
                shutil.copy2(logs[0], cwd / name)

    def start_simulator(self, command: str, cwd: Path, where: str) -> None:
        command = re.sub(r"--listen tcp:127\.0\.0\.1:\d+", "--listen tcp:127.0.0.1:0", command.rstrip(" &"))
        sim = subprocess.Popen(
            ["bash", "-c", f"exec {command}"],
            stdout=subprocess.PIPE,
            stderr=subprocess.PIPE,
            text=True,
            env=self.env,
            cwd=cwd,
        )
        self.sims.append(sim)
        assert sim.stdout is not None
        ready, _, _ = select.select([sim.stdout], [], [], 60)
        address = sim.stdout.readline().strip() if ready else ""
        if not address:
            sim.kill()
            pytest.fail(f"{where}: `{command}` printed no address:\n{sim.stderr.read() if sim.stderr else ''}")
        assert address.startswith(("tcp:127.0.0.1:", "/dev/")), f"{where}: {address}"
        kind = "tcp" if address.startswith("tcp:") else "pty"
        self.addresses.pop((SIM.match(command)[1], kind), None)
        self.addresses[(SIM.match(command)[1], kind)] = address
        self.latest = address

    def run(self, command: str, shown: str, cwd: Path, where: str, package: str = "") -> None:
        self.count += 1
        command = self.substitute(strip_comment(command), package)
        if SIM.match(command):
            self.start_simulator(command, cwd, where)
            return
        start = time.monotonic()
        proc = subprocess.run(
            ["bash", "-c", command], capture_output=True, text=True, env=self.env, cwd=cwd, timeout=900
        )
        TIMINGS[f"outside user: {where}: {command[:60]}"] = time.monotonic() - start
        status = re.search(r'; echo "exit \$\?"$', command)
        if status:
            want = re.findall(r"^exit (\d+)$", shown, re.M)
            got = re.findall(r"^exit (\d+)$", proc.stdout, re.M)
            ok = proc.returncode == 0 and got[-1:] == want[-1:]
        else:
            ok = proc.returncode == 0
        assert ok, (
            f"{where}: `{command}` (in {cwd}) exit {proc.returncode}\n{proc.stdout[-3000:]}\n{proc.stderr[-3000:]}"
        )
        if re.search(r"configure[-_]and[-_]stream\S* \S+ (\d+)$", command):
            # the getting-started pages' example against the simulator: the device line, the setting
            # read back, then COUNT samples per field (at least one field)
            count = int(command.rsplit(" ", 1)[1])
            lines = proc.stdout.splitlines()
            assert lines and lines[0].startswith("device ") and len(lines) >= 2 + count, f"{where}: {proc.stdout}"

    def project(self, b: Block) -> None:
        """A getting-started page's CMake or Cargo snippet as a user's project: the package copied to
        third_party/PKG (a path dependency, add_subdirectory), the snippet in the project's build
        file around the package's getting-started example as the user's program, built and run on
        a device log."""
        (package,) = set(re.findall(r"third_party/(\w+)", b.body))
        lang = Path(b.page).stem
        app = self.work / f"project-{package}"
        shutil.copytree(ROOT / "generated" / lang / package, app / "third_party" / package, ignore=LEFTOVERS)
        self.files(["capture.bin"], app)
        example = (
            ROOT / "generated" / lang / package / "examples" / f"getting_started.{'rs' if lang == 'rust' else lang}"
        )
        if lang == "rust":
            (app / "src").mkdir()
            shutil.copy2(example, app / "src" / "main.rs")
            head = '[package]\nname = "your_app"\nversion = "0.1.0"\nedition = "2021"\npublish = false\n\n'
            (app / "Cargo.toml").write_text(head + b.body, encoding="utf-8")
            commands = ["cargo run --quiet -- capture.bin"]
        else:
            main = f"main.{lang}"
            shutil.copy2(example, app / main)
            language = "C" if lang == "c" else "CXX"
            head = f"cmake_minimum_required(VERSION 3.16)\nproject(your_app LANGUAGES {language})\n"
            if lang == "cpp":
                head += "set(CMAKE_CXX_STANDARD 17)\n"
            head += f"add_executable(your_app {main})\n"
            (app / "CMakeLists.txt").write_text(head + b.body, encoding="utf-8")
            commands = ["cmake -S . -B build && cmake --build build", "build/your_app capture.bin"]
        self.count += 1
        for command in commands:
            start = time.monotonic()
            proc = subprocess.run(
                ["bash", "-c", command], capture_output=True, text=True, env=self.env, cwd=app, timeout=900
            )
            TIMINGS[f"outside user: {b.where}: project: {command}"] = time.monotonic() - start
            assert proc.returncode == 0, (
                f"{b.where}: the snippet's project: `{command}` exit {proc.returncode}\n{proc.stdout[-3000:]}\n{proc.stderr[-3000:]}"
            )

    def block(self, b: Block) -> None:
        cwd = self.work
        package = ""
        if b.marker.startswith("cd "):
            rel = b.marker[3:].strip()
            cwd = self.work / Path(rel).name
            if not cwd.exists():
                shutil.copytree(ROOT / rel, cwd, ignore=LEFTOVERS)
            package = cwd.name
        if b.marker.startswith("files "):
            self.files(b.marker[len("files ") :].split(), cwd)
        if b.marker == "project":
            self.project(b)
            return
        if b.lang == "yaml":
            first = b.body.splitlines()[0] if b.body else ""
            if re.fullmatch(r"# [\w.-]+\.yaml", first):
                (cwd / first[2:]).write_text(b.body, encoding="utf-8")
            return
        if b.lang == "python":
            if b.marker == "run":
                self.count += 1
                script = cwd / f"listing-{b.line}.py"
                script.write_text(self.substitute(b.body, package), encoding="utf-8")
                proc = subprocess.run(
                    ["python", script.name], capture_output=True, text=True, env=self.env, cwd=cwd, timeout=300
                )
                assert proc.returncode == 0, f"{b.where}: the listing failed\n{proc.stdout}\n{proc.stderr}"
            return
        for command, shown in b.commands:
            self.run(command, shown, cwd, b.where, package)


@pytest.mark.parametrize("page", PAGES)
def test_page(page: str, machine: dict[str, str], logs: Path) -> None:
    """Every command of the page, in order, as the outside user runs it."""
    work = Path(machine["OUTSIDE_HOME"]) / "pages" / Path(page).stem
    work.mkdir(parents=True, exist_ok=True)
    runner = Runner(page, machine, logs, work)
    start = time.monotonic()
    # each page installs what it uses: nothing an earlier page installed stays
    uninstall = ["python", "-m", "pip", "uninstall", "--yes", "--quiet", *PYTHON_PACKAGES]
    subprocess.run(uninstall, env=machine, capture_output=True, check=True)
    try:
        for b in blocks(page):
            if b.marker.startswith("not run:"):
                continue
            runner.block(b)
    finally:
        runner.close()
    TIMINGS[f"outside user: {page} ({runner.count} commands)"] = time.monotonic() - start
    COUNTS[page] = runner.count
