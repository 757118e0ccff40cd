"""Python benchmark (issue 8): frame and decode the benchmark streams with the generated mipcodec.

    python tests/bench/python/bench.py DIR [--passes 5] [--pure-passes 1] [--only python|python-pure]
                                           [--streams accel_gyro,...] [--gc] [--count MODE]
(--count MODE: only MODE's passes over the first stream, no output: for the instruction counts of
tests/bench/python/instructions.py.)
(--passes 0 or --pure-passes 0 leaves that flavour out; the pure-Python passes take about a
minute per stream.)

DIR holds the streams written by tests/bench/streams.py (<name>.bin + <name>.json sidecar).
Two flavours, each in its own process (the choice is made when the package is imported):
  lang=python       the package with its C accelerator, built in place by `tests/lang/python.sh ext`
                    into build/python/ext/mipcodec (the package's own setup.py, nothing installed)
  lang=python-pure  the same package with MIPCODEC_PURE=1 (the pure-Python fallback)
Modes (one BENCH line each, see tests/bench/run.py); the in-memory file is fed in 64 KiB chunks:
  bulk    (each flavour, in its own process) one memcpy of the whole stream into a bytearray of
          the same size (`memoryview(into)[:] = data`, written once before timing): the limit that
          tests/bench/run.py divides the rows of the same process by (best of at least 3 passes)
  frame   mipcodec.Parser: every RawPacket (offset, bytes) and Skip run, packets counted
  decode  mipcodec.Decoder: every packet decoded into Packet / DecodedField / typed dataclass
          values (the objects decode_packet(raw.data, raw.offset) returns), packets and fields
          counted; each chunk's objects are dropped before the next, as when processing a log
  session-ingest  (lang=python) a Session with one command pending whose reply never comes (deadline
          far away), every data packet routed to a per-packet handler that counts it and its fields
  session-roundtrip  (lang=python, stream=loopback-tcp) --roundtrips pings through the blocking API
          (mipcodec.connect over a loopback TCP socket) to a responder thread that acks each one;
          bytes = bytes sent + received
lang=python also prints `# extra:` lines for mode decode-values (decode, and every field's typed
value read: with the accelerator a DecodedField builds its value when `value` is first read) and
for mipcodec.decode_all(data) (whole stream, every object kept until the end of the pass), and lang=python-columns mode=decode lines for
mipcodec.decode_columns(data): the columnar fast API (per-field tables of numbers built in C, no
Python object per packet for the fields it reads; every other field entry as an object). Each pass runs over the whole file (read once, not
timed); the best of the passes is printed. As in timeit, the garbage collector is off during a
timed pass (--gc leaves it on). lang=python-export modes csv and parquet: `python -m mipcodec export
<stream> --format csv|parquet --out TMP` on the accel_gyro streams (one table per field; the
columnar path: decode_columns, numpy, pyarrow), file read and tables written included. The packet and field counts of every timed pass are checked
against the sidecar (exit 1 on a mismatch); an untimed decode_all pass checks that every field
decoded to a typed value and prints a checksum of one number of each.
"""

from __future__ import annotations

import argparse
import gc
import json
import math
import os
import subprocess
import sys
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[3]
STREAMS = ["accel_gyro", "mixed", "accel_gyro_garbage", "mixed_garbage"]


def first_number(value) -> float:
    """One number of a typed value (its first scalar, depth first) as a mantissa in [0.5, 1) (0 for
    zero, NaN and infinities), so that the checksum of random floats stays finite."""
    for f in value.__dataclass_fields__:
        v = getattr(value, f)
        while isinstance(v, list) and v:
            v = v[0]
        if hasattr(v, "__dataclass_fields__"):
            return first_number(v)
        if isinstance(v, (int, float)):
            x = float(v)
            return math.frexp(x)[0] if math.isfinite(x) else 0.0
    return 0.0


CHUNK = 65536  # bytes fed to the parser at a time, as when reading a large log


def frame_pass(mipcodec, data):
    """Parser fed CHUNK bytes at a time: (packets, fields=0, None)."""
    raw = mipcodec.RawPacket
    parser = mipcodec.Parser()
    packets = 0
    for i in range(0, len(data), CHUNK):
        for e in parser.feed(data[i : i + CHUNK]):
            packets += type(e) is raw
    for e in parser.flush():
        packets += type(e) is raw
    return packets, 0


def decode_pass(mipcodec, data):
    """Decoder fed CHUNK bytes at a time (every packet decoded to typed values): (packets, fields)."""
    packet = mipcodec.Packet
    decoder = mipcodec.Decoder()
    packets = fields = 0
    for i in range(0, len(data), CHUNK):
        for e in decoder.feed(data[i : i + CHUNK]):
            if type(e) is packet:
                packets += 1
                fields += len(e.fields)
    for e in decoder.flush():
        if type(e) is packet:
            packets += 1
            fields += len(e.fields)
    return packets, fields


def session_ingest_pass(mipcodec, data):
    """A session with one command pending (a ping whose reply never comes, deadline far away) fed
    CHUNK bytes at a time: every data packet goes to a per-packet handler, which counts it and its
    fields as decode_pass does: (packets, fields)."""
    session = mipcodec.Session(timeout_ms=1 << 40)
    packets = fields = 0

    def on_packet(packet):
        nonlocal packets, fields
        packets += 1
        fields += len(packet.fields)

    session.on_packet(on_packet)
    pending = session.start(mipcodec.base.Ping(), 0)
    for i in range(0, len(data), CHUNK):
        session.feed(data[i : i + CHUNK], 0)
    session.close(0)
    if pending.result is not None or len(session.pending) != 1:
        raise SystemExit(f"bench.py: session-ingest: the pending ping completed: {pending.result!r}")
    return packets, fields


def roundtrip(mipcodec, count: int) -> tuple[float, int]:
    """`count` pings through the blocking API (Device over a loopback TCP socket) to a responder
    thread that answers each with its ack: (seconds, bytes sent + received)."""
    import socket
    import threading

    srv = socket.create_server(("127.0.0.1", 0))
    port = srv.getsockname()[1]
    ack = mipcodec.build_packet(0x01, mipcodec.reserved.AckNack(command_descriptor=0x01))
    counted = {"in": 0}

    def responder() -> None:
        conn, _ = srv.accept()
        conn.setsockopt(socket.IPPROTO_TCP, socket.TCP_NODELAY, 1)
        parser = mipcodec.Parser()
        with conn:
            while True:
                data = conn.recv(65536)
                if not data:
                    return
                counted["in"] += len(data)
                replies = [ack for e in parser.feed(data) if type(e) is mipcodec.RawPacket and e.set == 0x01]
                if replies:
                    conn.sendall(b"".join(replies))

    thread = threading.Thread(target=responder, daemon=True)
    thread.start()
    device = mipcodec.connect(f"tcp:127.0.0.1:{port}", timeout_ms=5000)
    device.base.ping()  # warm-up: connection set up, code paths loaded
    t0 = time.perf_counter()
    for _ in range(count):
        device.base.ping()
    seconds = time.perf_counter() - t0
    device.close()
    thread.join(10)
    srv.close()
    return seconds, (count + 1) * (len(ack) + len(mipcodec.build_packet(0x01, mipcodec.base.Ping())))


def decode_values_pass(mipcodec, data):
    """decode_pass that also reads every field's typed value (`value`: with the accelerator, built
    when first read): (packets, fields)."""
    packet = mipcodec.Packet
    decoded = mipcodec.DecodedField
    decoder = mipcodec.Decoder()
    packets = fields = 0
    for i in range(0, len(data) + CHUNK, CHUNK):
        events = decoder.feed(data[i : i + CHUNK]) if i < len(data) else decoder.flush()
        for e in events:
            if type(e) is packet:
                packets += 1
                for f in e.fields:
                    fields += type(f) is not decoded or f.value is not None
    return packets, fields


def decode_all_pass(mipcodec, data):
    """decode_all over the whole stream, every object kept until the end of the pass."""
    events = mipcodec.decode_all(data)
    packet = mipcodec.Packet
    return sum(1 for e in events if type(e) is packet), sum(len(e.fields) for e in events if type(e) is packet)


def columns_pass(mipcodec, data):
    """decode_columns over the whole stream: per-field tables of numbers (C) plus other entries."""
    cols = mipcodec.decode_columns(data)
    fields = sum(len(t) for t in cols.tables.values()) + sum(1 for _o, k, _e in cols.others if k >= 0)
    return cols.packets, fields


PASSES = [
    ("frame", frame_pass),
    ("decode", decode_pass),
    ("decode-values", decode_values_pass),
    ("decode_all", decode_all_pass),
    ("columns", columns_pass),
]


def timed(fn, mipcodec, data, passes: int, use_gc: bool):
    """Best thread CPU time of `passes` passes, and the counts of the last."""
    best = math.inf
    counts = (0, 0)
    for _ in range(passes):
        if not use_gc:
            gc.disable()
        t0 = time.thread_time()
        counts = fn(mipcodec, data)
        seconds = time.thread_time() - t0
        gc.enable()
        best = min(best, seconds)
    return best, counts


def bulk_pass(data: bytes, passes: int) -> float:
    """Best thread CPU time of copying `data` into a bytearray of the same size (one memcpy)."""
    into = bytearray(len(data))
    view = memoryview(into)  # `into[:] = data` would first copy bytes into a new bytearray
    best = math.inf
    for _ in range(passes):
        t0 = time.thread_time()
        view[:] = data
        best = min(best, time.thread_time() - t0)
    if into != data:
        raise SystemExit("bench.py: bulk: the copy differs from the stream")
    return best


def check_values(mipcodec, data, lang, name, side) -> int:
    """Untimed: every field of every packet is a typed value; prints a checksum of their numbers."""
    fields = bad = 0
    checksum = 0.0
    for e in mipcodec.decode_all(data):
        if type(e) is mipcodec.Packet:
            for f in e.fields:
                if type(f) is mipcodec.DecodedField:
                    fields += 1
                    checksum += first_number(f.value)
                else:
                    bad += 1
    print(f"# {lang} {name}: {fields} typed fields, {bad} undecoded, checksum {checksum!r}")
    if fields != side["fields"] or bad:
        print(
            f"bench.py: {lang} {name}: {fields} typed fields, {bad} undecoded, expected {side['fields']}",
            file=sys.stderr,
        )
        return 1
    return 0


def export_pass(mipcodec, path: Path, fmt: str, passes: int) -> tuple[float, int]:
    """`python -m mipcodec export PATH --format FMT` (in this process, the columnar path with the
    accelerator): best wall time of the passes (reading the file included) and the rows written."""
    import contextlib
    import importlib
    import io
    import tempfile

    tools = importlib.import_module("mipcodec.logs.commands")
    best = math.inf
    rows = 0
    for _ in range(passes):
        with tempfile.TemporaryDirectory() as out:
            text = io.StringIO()
            t0 = time.perf_counter()
            with contextlib.redirect_stdout(text), contextlib.redirect_stderr(io.StringIO()):
                status = tools.main(["export", str(path), "--format", fmt, "--out", out])
            best = min(best, time.perf_counter() - t0)
            if status != 0:
                raise SystemExit(f"bench.py: export {path.name} --format {fmt}: exit status {status}")
            rows = sum(int(line.rsplit(": ", 1)[1].split()[0]) for line in text.getvalue().splitlines())
    return best, rows


def run_flavour(lang: str, directory: Path, streams: list[str], passes: int, use_gc: bool, roundtrips: int) -> int:
    import mipcodec

    if mipcodec.ACCELERATED != (lang == "python"):
        print(f"bench.py: {lang}: mipcodec.ACCELERATED is {mipcodec.ACCELERATED}", file=sys.stderr)
        return 1
    status = 0
    for name in streams:
        data = (directory / f"{name}.bin").read_bytes()
        side = json.loads((directory / f"{name}.json").read_text())
        if len(data) != side["bytes"]:
            print(f"bench.py: {name}.bin has {len(data)} bytes, the sidecar says {side['bytes']}", file=sys.stderr)
            return 1
        status |= check_values(mipcodec, data, lang, name, side)
        seconds = bulk_pass(data, max(3, passes))
        print(
            f"BENCH lang={lang} stream={name} mode=bulk packets={side['packets']} bytes={len(data)} seconds={seconds:.9f}"
        )
        runs = [("frame", frame_pass), ("decode", decode_pass)]
        if lang == "python":
            runs += [("session-ingest", session_ingest_pass)]
            runs += [("decode-values", decode_values_pass), ("decode_all", decode_all_pass), ("columns", columns_pass)]
        for mode, fn in runs:
            seconds, (packets, fields) = timed(fn, mipcodec, data, passes, use_gc)
            if mode == "columns":
                head = f"BENCH lang=python-columns stream={name} mode=decode"
            elif mode in ("decode_all", "decode-values"):
                head = f"# extra: lang={lang} stream={name} mode={mode}"
            else:
                head = f"BENCH lang={lang} stream={name} mode={mode}"
            print(f"{head} packets={packets} bytes={len(data)} seconds={seconds:.6f}")
            if packets != side["packets"] or (mode != "frame" and fields != side["fields"]):
                print(
                    f"bench.py: {lang} {mode} {name}: {packets} packets, {fields} fields;"
                    f" expected {side['packets']} and {side['fields']}",
                    file=sys.stderr,
                )
                status = 1
            sys.stdout.flush()
        if lang == "python" and name.startswith("accel_gyro"):
            for fmt in ("csv", "parquet"):
                seconds, rows = export_pass(mipcodec, directory / f"{name}.bin", fmt, max(1, min(passes, 3)))
                print(
                    f"BENCH lang=python-export stream={name} mode={fmt} packets={side['packets']} bytes={len(data)} seconds={seconds:.6f}"
                )
                if rows != side["fields"]:
                    print(f"bench.py: export {name} {fmt}: {rows} rows, expected {side['fields']}", file=sys.stderr)
                    status = 1
                sys.stdout.flush()
    if lang == "python" and roundtrips > 0:
        seconds, nbytes = roundtrip(mipcodec, roundtrips)
        print(
            f"BENCH lang={lang} stream=loopback-tcp mode=session-roundtrip packets={roundtrips} bytes={nbytes} seconds={seconds:.6f}"
        )
    return status


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("dir", type=Path, help="directory of the benchmark streams (tests/bench/streams.py)")
    ap.add_argument("--passes", type=int, default=5, help="timed passes with the C accelerator (best is printed)")
    ap.add_argument("--pure-passes", type=int, default=1, help="timed passes of the pure-Python code (slow)")
    ap.add_argument("--only", choices=["python", "python-pure"], help="run one flavour in this process")
    ap.add_argument("--streams", default=",".join(STREAMS), help="comma-separated stream names")
    ap.add_argument("--gc", action="store_true", help="leave the garbage collector on during the timed passes")
    ap.add_argument("--roundtrips", type=int, default=2000, help="ping round trips of mode session-roundtrip (0: none)")
    ap.add_argument(
        "--count",
        metavar="MODE",
        help="for instruction counts (instructions.py): run MODE (frame, decode, decode-values, decode_all,"
        " columns) --passes times over the one stream of --streams in this process, print nothing",
    )
    args = ap.parse_args()
    streams = [s for s in args.streams.split(",") if s]

    if args.count:
        import mipcodec

        fn = dict(PASSES)[args.count]
        data = (args.dir / f"{streams[0]}.bin").read_bytes()
        gc.disable()
        for _ in range(args.passes):
            fn(mipcodec, data)
        return 0

    if args.only:
        passes = args.passes if args.only == "python" else args.pure_passes
        return run_flavour(args.only, args.dir, streams, passes, args.gc, args.roundtrips)

    # Build the accelerated copy (no-op when up to date), then one process per flavour.
    built = subprocess.run(
        [str(ROOT / "tests/lang/python.sh"), "ext"], check=True, capture_output=True, text=True
    ).stdout.split()
    ext_dir = next(d for d in built if d.endswith("/mipcodec"))
    status = 0
    for lang, path in (("python", ext_dir), ("python-pure", str(ROOT / "generated/python/mipcodec"))):
        if (args.passes if lang == "python" else args.pure_passes) <= 0:
            continue  # --passes 0 / --pure-passes 0 leave a flavour out
        env = dict(os.environ, PYTHONPATH=path)
        env.pop("MIPCODEC_PURE", None)
        if lang == "python-pure":
            env["MIPCODEC_PURE"] = "1"
        cmd = [sys.executable, __file__, str(args.dir), "--only", lang, "--streams", ",".join(streams)]
        cmd += [
            "--passes",
            str(args.passes),
            "--pure-passes",
            str(args.pure_passes),
            "--roundtrips",
            str(args.roundtrips),
        ]
        cmd += ["--gc"] if args.gc else []
        status |= subprocess.run(cmd, env=env).returncode
    return status


if __name__ == "__main__":
    sys.exit(main())
