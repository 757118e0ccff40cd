"""The log tools under misuse and faults (issue 37, "The log tools"; issue 39 item 7): outputs whole
or not at all (a full disk, Ctrl-C), existing outputs refused unless --force, bounded memory on
endless noise and long logs, --idle checked, one text per value on both CSV paths, --join rows
per sample (docs/conformance.md section 6).

Memory is compared between two input sizes in fresh processes (peak RSS from getrusage): the peak
must not follow the input; no wall-clock assertions.
"""

from __future__ import annotations

import errno
import importlib
import json
import math
import os
import random
import resource
import signal
import struct
import subprocess
import sys
import threading
import time
from pathlib import Path

import numpy as np
import pytest

from tests.export.test_export import CAPTURE, PACKAGES, ROOT, ext_build, pkg, read_table, vector_stream
from tests.helpers.procs import as_in_a_terminal

GENERATED = str(ROOT / "generated" / "python" / "mipcodec")


def tool(*args: str, accelerated: bool = False, **kw) -> subprocess.CompletedProcess:
    """`python -m mipcodec ARGS` in a fresh process (the generated package, or the build with the
    C accelerator)."""
    where = ext_build("mipcodec") if accelerated else GENERATED
    env = dict(os.environ, PYTHONPATH=where)
    env.pop("MIPCODEC_EXPORT_SLOW", None)
    env.update(kw.pop("env", {}))
    return subprocess.run([sys.executable, "-m", "mipcodec", *args], env=env, capture_output=True, **kw)


def accel_stream(n: int, start_ns: int = 1_000_000_000, step_ns: int = 8_000_000) -> bytes:
    """n packets of set 0x80 (reference timestamp, scaled accel) at 125 Hz, built from one packet
    made by PacketBuilder: the timestamps patched in and the Fletcher sums recomputed (numpy)."""
    mod = pkg("mipcodec")
    ts = mod.shared.ReferenceTimestamp(nanoseconds=0).encode()
    accel = mod.sensor.ScaledAccel(scaled_accel=[0.25, -0.5, -1.0]).encode()
    template = np.frombuffer(
        mod.codec.framing.PacketBuilder(0x80).add_field(0xD5, ts).add_field(0x04, accel).build(), np.uint8
    )
    # the timestamp's 8 data bytes follow the header (4 bytes) and the field header (2 bytes)
    assert bytes(template[4:6]) == bytes([2 + 8, 0xD5])
    rows = np.tile(template, (n, 1))
    ns = start_ns + step_ns * np.arange(n, dtype=np.uint64)
    rows[:, 6:14] = ns.astype(">u8").view(np.uint8).reshape(n, 8)
    prefix = np.cumsum(rows[:, :-2].astype(np.int64), axis=1)
    rows[:, -2] = prefix[:, -1] % 256  # sum1
    rows[:, -1] = prefix.sum(axis=1) % 256  # sum2 (the sum of the running sum1 values)
    data = rows.tobytes()
    assert mod.codec.framing.parse(data[: len(template)])[0].data == data[: len(template)]  # a valid packet
    return data


def one_line(stderr: bytes | str) -> str:
    text = stderr.decode() if isinstance(stderr, bytes) else stderr
    lines = text.strip().splitlines()
    assert len(lines) == 1, text
    return lines[0]


def leftovers(directory: Path) -> list:
    return sorted(p.name for p in directory.iterdir()) if directory.exists() else []


# --------------------------------------------------------------------- Ctrl-C with --follow
@pytest.mark.parametrize("join", [False, True])
def test_follow_stopped_by_ctrl_c_writes_what_was_read(tmp_path, join):
    """Ctrl-C, the documented way to stop `export --follow`, writes the tables of everything read
    so far and exits 0 (before: --join wrote nothing, exit 130)."""
    log = tmp_path / "grow.bin"
    log.write_bytes(accel_stream(300))
    out = tmp_path / "o"
    args = [sys.executable, "-m", "mipcodec", "export", str(log), "--follow", "--out", str(out)]
    proc = subprocess.Popen(
        args + (["--join"] if join else []),
        env=dict(os.environ, PYTHONPATH=GENERATED),
        stdout=subprocess.PIPE,
        stderr=subprocess.PIPE,
        preexec_fn=as_in_a_terminal,
    )
    time.sleep(1.5)
    with log.open("ab") as fh:  # more packets while it follows
        fh.write(accel_stream(200, start_ns=1_000_000_000 + 300 * 8_000_000))
    time.sleep(1.5)
    proc.send_signal(signal.SIGINT)
    stdout, stderr = proc.communicate(timeout=60)
    assert proc.returncode == 0, stderr
    name = "sensor.csv" if join else "sensor.scaled_accel.csv"
    headers, rows = read_table(out / name)
    assert len(rows) == 500
    # t_ns, time, offset: the stream has the device clock only, no GPS time (so no UTC time); its
    # 500 packets all the same size, one after the other
    assert headers[:3] == ["t_ns", "time", "offset"] and all(r[0] == r[1] == "" for r in rows)
    size = len(accel_stream(1))
    assert [int(r[2]) for r in rows] == [size * i for i in range(500)]
    assert f"{out / name}: 500 rows" in stdout.decode()
    assert "stopped by Ctrl-C" in stderr.decode()
    assert not [n for n in leftovers(out) if n.startswith(".")]


@pytest.mark.parametrize("delay", [0.8, 1.6, 2.4])
def test_ctrl_c_without_follow_leaves_whole_tables_or_none(tmp_path, delay):
    """Ctrl-C while a (non-follow) export writes: exit 130 and no table, or, when it came too late,
    exit 0 and whole tables; never a table cut short, never a temporary file left."""
    log = tmp_path / "log.bin"
    log.write_bytes(accel_stream(150_000))
    out = tmp_path / "o"
    proc = subprocess.Popen(
        [sys.executable, "-m", "mipcodec", "export", str(log), "--out", str(out), "--format", "jsonl"],
        env=dict(os.environ, PYTHONPATH=GENERATED),
        stdout=subprocess.PIPE,
        stderr=subprocess.PIPE,
        preexec_fn=as_in_a_terminal,
    )
    time.sleep(delay)
    proc.send_signal(signal.SIGINT)
    _out, err = proc.communicate(timeout=300)
    assert proc.returncode in (0, 130), err
    names = leftovers(out)
    if proc.returncode == 130:
        assert names == [], names
    else:
        assert names == ["sensor.scaled_accel.jsonl", "sensor.shared.reference_timestamp.jsonl"]
        assert len((out / names[0]).read_text().splitlines()) == 150_000


# ---------------------------------------------------------------- whole outputs or nothing
def fsize_limit(limit: int):
    """A process whose files cannot grow past `limit` bytes (RLIMIT_FSIZE: writes fail with EFBIG,
    SIGXFSZ ignored), the fault a full disk gives a writer, without root."""

    def pre() -> None:
        signal.signal(signal.SIGXFSZ, signal.SIG_IGN)
        resource.setrlimit(resource.RLIMIT_FSIZE, (limit, limit))

    return pre


@pytest.mark.parametrize(
    "mode", ["csv", "csv-columnar", "jsonl", "parquet", "parquet-columnar", "csv-join", "png", "svg", "html"]
)
def test_a_write_that_fails_leaves_no_partial_output(tmp_path, mode):
    """Every table or image a write fault hits mid-way is absent afterwards (not cut mid-row), the
    previous file untouched, the error one line, exit 2."""
    log = tmp_path / "log.bin"
    log.write_bytes(accel_stream(20000))  # tables of about 1 MB, images of tens of kB
    out = tmp_path / "o"
    accelerated = mode.endswith("-columnar")
    if mode in ("png", "svg", "html"):
        target = tmp_path / f"plot.{mode}"
        target.write_bytes(b"previous")
        args = ["plot", str(log), "--fields", "scaled_accel", "--out", str(target), "--force"]
        limit = 2000
    else:
        fmt = mode.split("-")[0]
        args = ["export", str(log), "--format", fmt, "--out", str(out)] + (["--join"] if "join" in mode else [])
        limit = 200_000
    run = tool(*args, accelerated=accelerated, preexec_fn=fsize_limit(limit), cwd=tmp_path)
    assert run.returncode == 2, run.stderr
    line = one_line(run.stderr)
    assert "File too large" in line and "cannot write" in line, line
    if mode in ("png", "svg", "html"):
        assert target.read_bytes() == b"previous"
        assert leftovers(tmp_path) == sorted(["log.bin", target.name])
    else:
        assert leftovers(out) == []  # no table, no temporary file
    # Without the limit the same command succeeds (the fault was the limit).
    run = tool(*args, accelerated=accelerated, cwd=tmp_path)
    assert run.returncode == 0, run.stderr


def test_no_space_left_mid_table_in_process(tmp_path, monkeypatch, capsys):
    """A writer that fails with ENOSPC after some rows (a full disk) leaves no table."""
    mod = pkg("mipcodec")
    log = tmp_path / "log.bin"
    log.write_bytes(accel_stream(10000))
    real = mod.logs.writers.CsvWriter.write
    calls = []

    def write(self, rows):
        calls.append(len(rows))
        real(self, rows[: len(rows) // 2])  # half the rows reach the file, then the disk is full
        self.file.flush()
        raise OSError(errno.ENOSPC, os.strerror(errno.ENOSPC))

    monkeypatch.setattr(mod.logs.writers.CsvWriter, "write", write)
    monkeypatch.setenv("MIPCODEC_EXPORT_SLOW", "1")
    assert mod.cli.main(["export", str(log), "--out", str(tmp_path / "o")]) == 2
    assert calls
    assert "No space left on device" in one_line(capsys.readouterr().err)
    assert leftovers(tmp_path / "o") == []


# ------------------------------------------------------------------------ existing outputs
def test_existing_outputs_are_refused_unless_force(tmp_path, capsys):
    mod = pkg("mipcodec")
    log = tmp_path / "log.bin"
    log.write_bytes(accel_stream(50))
    out = tmp_path / "o"
    assert mod.cli.main(["export", str(log), "--out", str(out)]) == 0
    table = out / "sensor.scaled_accel.csv"
    before = table.read_bytes()
    log.write_bytes(accel_stream(10))
    capsys.readouterr()
    for extra in ([], ["--join"]):
        if extra:
            (out / "sensor.csv").write_text("mine\n")
            table = out / "sensor.csv"
            before = table.read_bytes()
        assert mod.cli.main(["export", str(log), "--out", str(out)] + extra) == 2
        line = one_line(capsys.readouterr().err)
        assert str(out) in line and " exists: not overwritten (--force overwrites it)" in line, line
        # the prefix docs/log-to-csv.md quotes ("mipcodec export: DIR/NAME exists: ...")
        assert line.startswith(f"mipcodec export: {out}"), line
        page = (ROOT / "docs" / "log-to-csv.md").read_text()
        assert "`mipcodec export: DIR/NAME exists: not overwritten (--force overwrites it)`" in page
        assert table.read_bytes() == before
        assert not [n for n in leftovers(out) if n.startswith(".")]
    assert mod.cli.main(["export", str(log), "--out", str(out), "--force"]) == 0
    assert len(read_table(out / "sensor.scaled_accel.csv")[1]) == 10
    image = tmp_path / "p.svg"
    image.write_text("mine")
    capsys.readouterr()
    assert mod.cli.main(["plot", str(log), "--fields", "scaled_accel", "--out", str(image)]) == 2
    assert f"{image} exists" in one_line(capsys.readouterr().err)
    assert image.read_text() == "mine"
    assert mod.cli.main(["plot", str(log), "--fields", "scaled_accel", "--out", str(image), "--force"]) == 0
    assert "<svg" in image.read_text()


def test_existing_outputs_refused_on_the_columnar_path(tmp_path):
    log = tmp_path / "log.bin"
    log.write_bytes(accel_stream(50))
    out = tmp_path / "o"
    assert tool("export", str(log), "--out", str(out), accelerated=True).returncode == 0
    run = tool("export", str(log), "--out", str(out), accelerated=True)
    assert run.returncode == 2 and "exists" in one_line(run.stderr)
    assert tool("export", str(log), "--out", str(out), "--force", accelerated=True).returncode == 0


# -------------------------------------------------------------------------- bounded memory
# The peak RSS of the process's own memory image: VmHWM (reset by exec). getrusage's ru_maxrss is
# not: Linux carries it across fork and exec, so it starts at the (large) test process's RSS.
PEAK = """
import sys
sys.argv[0] = "mipcodec"
from mipcodec.cli import main
status = main(sys.argv[1:])
sys.stdout.flush()
hwm = next(line for line in open("/proc/self/status") if line.startswith("VmHWM:"))
print("PEAK", int(hwm.split()[1]), file=sys.stderr)
sys.exit(status)
"""


def peak_kib(args: list, feed: bytes | None = None, size: int = 0, accelerated: bool = True, cwd=None) -> int:
    """Peak RSS (KiB) of `python -m mipcodec ARGS` in a fresh process, fed `size` zero bytes (or
    `feed`) through a pipe when the log is `-`."""
    where = ext_build("mipcodec") if accelerated else GENERATED
    proc = subprocess.Popen(
        [sys.executable, "-c", PEAK, *args],
        env=dict(os.environ, PYTHONPATH=where),
        stdin=subprocess.PIPE,
        stdout=subprocess.PIPE,
        stderr=subprocess.PIPE,
        cwd=cwd,
    )
    err: list = []
    reader = threading.Thread(target=lambda: err.append(proc.stderr.read()))
    reader.start()
    out = threading.Thread(target=proc.stdout.read)
    out.start()
    try:
        if feed is not None:
            proc.stdin.write(feed)
        block = bytes(1 << 20)
        for _ in range(size >> 20):
            proc.stdin.write(block)
        proc.stdin.close()
    except BrokenPipeError:
        pass
    proc.wait(timeout=600)
    reader.join()
    out.join()
    text = err[0].decode()
    assert proc.returncode == 0, text
    return int(text.rsplit("PEAK", 1)[1])


MiB = 1 << 20


@pytest.mark.parametrize("command", ["info", "export", "export-join"])
def test_endless_noise_is_skipped_in_bounded_memory(tmp_path, command):
    """A stream without a packet start (zeros through a pipe, as /dev/zero gives) is skipped in
    bounded memory: 64 MiB of it peaks like 8 MiB (before: every skipped byte was held)."""
    args = {"info": ["info", "-"], "export": ["export", "-", "--out", "o"]}.get(
        command, ["export", "-", "--join", "--out", "o2"]
    )
    small = peak_kib(args, size=8 * MiB, cwd=tmp_path)
    large = peak_kib(args + (["--force"] if command != "info" else []), size=64 * MiB, cwd=tmp_path)
    assert large - small < 16 * 1024, (small, large)


def test_dev_zero_has_no_end_but_bounded_memory(tmp_path):
    """`info /dev/zero`: no end of file, so it runs until stopped, its memory flat meanwhile."""
    where = ext_build("mipcodec")
    proc = subprocess.Popen(
        [sys.executable, "-m", "mipcodec", "info", "/dev/zero"],
        env=dict(os.environ, PYTHONPATH=where),
        stdout=subprocess.PIPE,
        stderr=subprocess.PIPE,
        preexec_fn=as_in_a_terminal,
    )

    def rss() -> int:
        for line in Path(f"/proc/{proc.pid}/status").read_text().splitlines():
            if line.startswith("VmRSS:"):
                return int(line.split()[1])
        raise AssertionError("no VmRSS")

    def read_bytes() -> int:
        for line in Path(f"/proc/{proc.pid}/io").read_text().splitlines():
            if line.startswith("rchar:"):
                return int(line.split()[1])
        raise AssertionError("no rchar")

    try:
        while read_bytes() < 32 * MiB:
            assert proc.poll() is None
            time.sleep(0.1)
        early = rss()
        start = read_bytes()
        while read_bytes() < start + 256 * MiB:
            assert proc.poll() is None
            time.sleep(0.1)
        late = rss()
    finally:
        proc.send_signal(signal.SIGINT)
        try:
            proc.communicate(timeout=60)
        except subprocess.TimeoutExpired:  # never left reading /dev/zero after the test
            proc.kill()
            proc.communicate()
            raise
    assert late - early < 16 * 1024, (early, late)  # 256 MiB more read, memory flat
    assert proc.returncode == 130


def test_columnar_export_of_noise_in_bounded_memory(tmp_path):
    """The columnar path (a whole file in 16 MiB blocks) carries at most a packet's bytes from a
    block into the next: 160 MiB of zeros peaks like 32 MiB, give or take the copies of one block
    (before: the skipped run was carried, and copied, from block to block)."""
    small, large = tmp_path / "small.bin", tmp_path / "large.bin"
    with small.open("wb") as fh:  # sparse files: no disk used
        fh.truncate(32 * MiB)
    with large.open("wb") as fh:
        fh.truncate(160 * MiB)
    a = peak_kib(["export", str(small), "--out", str(tmp_path / "a")])
    b = peak_kib(["export", str(large), "--out", str(tmp_path / "b")])
    assert b - a < 32 * 1024, (a, b)


@pytest.mark.parametrize("command", ["info", "export-join"])
def test_memory_does_not_grow_with_the_entries(tmp_path, command):
    """`info` keeps a summary per (set, field) and `--join` spools its rows: four times the
    packets, the same peak (before: a time per entry, a row per sample, held to the end)."""
    n = 200_000 if command == "info" else 60_000
    for k, count in (("small", n), ("large", 4 * n)):
        (tmp_path / f"{k}.bin").write_bytes(accel_stream(count))
    if command == "info":
        run = lambda k: peak_kib(["info", str(tmp_path / f"{k}.bin")])  # noqa: E731
    else:
        run = lambda k: peak_kib(["export", str(tmp_path / f"{k}.bin"), "--join", "--out", str(tmp_path / k)])  # noqa: E731
    small, large = run("small"), run("large")
    assert large - small < 10 * 1024, (small, large)
    if command == "export-join":
        assert len(read_table(tmp_path / "large" / "sensor.csv")[1]) == 4 * n


def test_info_histogram_keeps_the_rate_gaps_and_drops():
    """The bounded interval histogram of `info`: exact while few distinct intervals; past
    MAX_BINS, the median within the bin width and the gaps (far from 1.5 times it) counted."""
    tools = pkg("mipcodec").logs.info
    rng = random.Random(7)
    exact = tools.Intervals()
    for dt in [0.01] * 90 + [0.03] * 3 + [0.02] * 2:
        exact.add(dt)
    assert exact.rate() == (100.0, 5, 2 * 3 + 1 * 2)
    jitter = tools.Intervals()
    dts = [0.01 * (1 + rng.uniform(-0.01, 0.01)) for _ in range(100_000)] + [0.05] * 7
    for dt in dts:
        jitter.add(dt)
    assert len(jitter.bins) <= tools.Intervals.MAX_BINS and jitter.scale > 0
    median = sorted(dts)[len(dts) // 2]
    hz, gaps, dropped = jitter.rate()
    assert abs(1 / hz - median) / median < 2 * jitter.scale
    assert (gaps, dropped) == (7, 7 * 4)


# ------------------------------------------------------------------------------------ --idle
@pytest.mark.parametrize("value", ["nan", "inf", "-1", "-inf", "soon"])
def test_idle_must_be_finite_seconds(tmp_path, value):
    log = tmp_path / "log.bin"
    log.write_bytes(accel_stream(5))
    run = tool("export", str(log), "--out", str(tmp_path / "o"), "--follow", f"--idle={value}", timeout=60)
    assert run.returncode == 2
    line = one_line(run.stderr)
    assert "--idle" in line and "seconds" in line, line
    assert leftovers(tmp_path / "o") == []


# ------------------------------------------------------------------ one text per value (39.7)
def test_f32_text_is_the_shortest_float32_digits_in_repr_layout():
    """Golden texts by the rule (fewest digits reading back as the float32, laid out as
    repr(float): positional from 1e-4 to below 1e16, else d.ddde-XX), then random values."""
    tools = pkg("mipcodec").logs.writers
    arrow = pkg("mipcodec").logs.arrow

    def f32(x: float) -> float:
        return struct.unpack("<f", struct.pack("<f", x))[0]

    assert tools.f32_text(f32(-4.1873427e-06)) == "-4.1873427e-06"  # the value of issue 39
    assert tools.f32_text(f32(0.1)) == "0.1"
    assert tools.f32_text(f32(1e-4)) == "0.0001"
    assert tools.f32_text(f32(1e-5)) == "1e-05"
    assert tools.f32_text(f32(111460500000.0)) == "111460500000.0"  # not 1.114605e+11
    assert tools.f32_text(f32(1e16)) == "1e+16"
    assert tools.f32_text(-0.0) == "-0.0"
    np_texts = arrow.f32_texts(np, np.zeros(0, dtype=np.float32))
    assert list(np_texts) == []
    rng = random.Random(39)
    values = []
    while len(values) < 20000:  # any float32 (mostly far from 1)
        v = struct.unpack("<f", struct.pack("<I", rng.getrandbits(32)))[0]
        if math.isfinite(v):
            values.append(v)
    for _ in range(20000):  # where pyarrow's text is used (sensor values), integral ones too
        v = f32(rng.gauss(0, 1) * 10 ** rng.uniform(-5, 16))
        values += [v, f32(float(round(v)))]
    texts = arrow.f32_texts(np, np.array(values, dtype=np.float32)).tolist()
    for v, fast in zip(values, texts):
        text = tools.f32_text(v)
        assert text == fast, (v, text, fast)
        assert f32(float(text)) == v and text == repr(float(text))
        digits = len(text.split("e")[0].replace("-", "").replace(".", "").strip("0"))
        assert digits <= 1 or f32(float(f"{v:.{digits - 1}g}")) != v, (v, text)


def test_time_text_of_the_columnar_csv_is_timebase_iso():
    """The CSV `time` cells of the columnar path (writers.iso_texts, digits from numpy) are
    timebase.iso's text of each t_ns (microseconds, truncated toward zero; empty where t_ns is
    null), also for times before 1970, rows out of order and a sliced column."""
    pa = pytest.importorskip("pyarrow")
    tools = pkg("mipcodec").logs.writers
    iso = importlib.import_module("mipcodec.logs.timebase").iso
    rng = random.Random(50)
    base = 1773479642 * 10**9  # 2026-03-14T09:14:02Z
    values = [base + k * 10_000_000 for k in range(300)]  # 100 Hz, rising
    values += [rng.randrange(-(10**18), 4 * 10**18) for _ in range(300)]  # any order, 1938..2096
    values += [None, -1, -999, -1000, -1001, 0, 999, 1000, None, 2**63 - 1, -(2**63) + 1]
    column = pa.array(values, type=pa.int64())
    for part in (column, column.slice(7, 400)):
        got = tools.iso_texts(np, pa, part).to_pylist()
        micro = [None if v is None else -(-v // 1000 * 1000) if v < 0 else v // 1000 * 1000 for v in part.to_pylist()]
        want = [None if v is None else iso(v) for v in micro]
        assert got == want


def capture_or_vectors() -> list:
    streams = [(protocol, vector_stream(protocol)) for protocol in sorted(PACKAGES)]
    if CAPTURE.exists():
        streams.append(("mip", CAPTURE.read_bytes()))
    return streams


def test_both_csv_paths_write_the_same_bytes(tmp_path):
    """The CSV of a log is the same bytes with and without the columnar path (pyarrow, numpy, the C
    accelerator): every table of the golden vectors of both protocols and of the device capture."""
    compared = 0
    for i, (protocol, data) in enumerate(capture_or_vectors()):
        package = PACKAGES[protocol]
        log = tmp_path / f"{i}.bin"
        log.write_bytes(data)
        where = ext_build(package)
        outs = {}
        for path, env in (("columnar", {}), ("packets", {package.upper() + "_EXPORT_SLOW": "1"})):
            out = tmp_path / f"{i}-{path}"
            run = subprocess.run(
                [sys.executable, "-m", package, "export", str(log), "--out", str(out)],
                env=dict(os.environ, PYTHONPATH=where, **env),
                capture_output=True,
                text=True,
            )
            assert run.returncode == 0, run.stderr
            assert ("(columnar path)" in run.stderr) == (path == "columnar")
            outs[path] = out
        names = leftovers(outs["packets"])
        assert names and names == leftovers(outs["columnar"])
        for name in names:
            a, b = (outs["packets"] / name).read_bytes(), (outs["columnar"] / name).read_bytes()
            assert a == b, (name, next(x for x in zip(a.splitlines(), b.splitlines()) if x[0] != x[1]))
            compared += a.count(b"\n")
    assert compared > 300


# ------------------------------------------------------------------------ --join per sample
@pytest.mark.skipif(not CAPTURE.exists(), reason="device capture absent")
def test_join_gives_one_row_per_sample_of_the_capture(tmp_path):
    """`--join` on the device capture: one row per sample as `decode --samples` numbers them
    (section 6), the row's offset that of the sample's first packet. In this capture no packet
    continues another: the magnetometer (100 Hz) and the filter's Euler angles (50 Hz) between
    the 125 Hz reference timestamps come in packets without a timestamp, samples of their own
    (rows with an empty time), while every timestamped packet has its own timestamp."""
    data = CAPTURE.read_bytes()
    log = tmp_path / "capture.bin"
    log.write_bytes(data)
    run = subprocess.run(
        [sys.executable, "-m", "mipcodec", "decode", "--samples", str(log)],
        env=dict(os.environ, PYTHONPATH=GENERATED),
        capture_output=True,
        text=True,
        check=True,
    )
    samples: dict = {}
    first: dict = {}
    for line in run.stdout.splitlines():
        obj = json.loads(line)
        if "sample" in obj and obj["sample"] not in first:
            first[obj["sample"]] = obj["offset"]
            samples.setdefault(obj["set"], []).append(obj["offset"])
    mod = pkg("mipcodec")
    assert mod.cli.main(["export", str(log), "--join", "--out", str(tmp_path / "o")]) == 0
    names = mod.registry.SET_NAMES
    for set_id, offsets in samples.items():
        headers, rows = read_table(tmp_path / "o" / f"{names[set_id]}.csv")
        assert [int(r[2]) for r in rows] == offsets, names[set_id]  # t_ns, time, offset
    headers, rows = read_table(tmp_path / "o" / "sensor.csv")
    # the capture has no GPS time: no UTC time; the samples without a reference timestamp
    assert all(r[0] == r[1] == "" for r in rows)
    untimed = [dict(zip(headers, r)) for r in rows if r[headers.index("reference_timestamp.nanoseconds [ns]")] == ""]
    assert len(untimed) == 2684  # the packets without a timestamp (info: 2684 scaled_mag entries)
    assert all(r["scaled_accel.x [g]"] == "" and r["scaled_mag.x [gauss]"] != "" for r in untimed)
