"""tests/bench/run.py's table: the session column (session-ingest against the same language's
decode of the same stream, session-roundtrip as round trips per second and microseconds each)."""

from __future__ import annotations

from tests.bench.run import parse, table


def _rows(lines: list[str]) -> list[dict[str, str]]:
    rows = [parse(line) for line in lines]
    assert all(r is not None for r in rows)
    return [r for r in rows if r is not None]


def test_session_column():
    rows = _rows(
        [
            "BENCH lang=baseline stream=accel_gyro mode=copy packets=100 bytes=3400 seconds=0.001",
            "BENCH lang=python stream=accel_gyro mode=decode packets=100 bytes=3400 seconds=0.009",
            "BENCH lang=python stream=accel_gyro mode=session-ingest packets=100 bytes=3400 seconds=0.010",
            "BENCH lang=python stream=mixed mode=session-ingest packets=10 bytes=3400 seconds=0.010",
            "BENCH lang=python stream=loopback-tcp mode=session-roundtrip packets=2000 bytes=36000 seconds=0.080",
            "BENCH lang=c stream=accel_gyro mode=decode packets=100 bytes=3400 seconds=0.001",
        ]
    )
    text = table(rows, ["c", "python"])
    lines = {tuple(c.strip() for c in line.strip("|").split("|")[:3]): line for line in text.splitlines()}
    assert "0.90 x decode" in lines[("python", "accel_gyro", "session-ingest")]
    # no decode row of that language and stream: no ratio
    assert lines[("python", "mixed", "session-ingest")].rstrip("| ").endswith("-")
    rt = lines[("python", "loopback-tcp", "session-roundtrip")]
    assert "25,000/s, 40.0 us each" in rt
    # the rows come in the order language, stream, mode; the round trip after the streams
    order = [k for k in lines if k[0] == "python"]
    assert order == [
        ("python", "accel_gyro", "decode"),
        ("python", "accel_gyro", "session-ingest"),
        ("python", "mixed", "session-ingest"),
        ("python", "loopback-tcp", "session-roundtrip"),
    ]
    assert "x decode" not in lines[("c", "accel_gyro", "decode")]
