"""tests/bench/run.py's pure functions on synthetic BENCH lines: the aggregation over processes
(median, spread, the fraction of bulk paired by process, decode/frame), the table, the JSON rows,
the session column, the instruction counts (callgrind's summary, the fixed cost) and the
compile-cost table."""

from __future__ import annotations

import json

import pytest

from tests.bench.run import (
    COMPILE_UNITS,
    ROOT,
    STD_UNIT,
    aggregate,
    callgrind_total,
    compile_command,
    compile_table,
    instructions_table,
    merge_instructions,
    order,
    parse,
    per_packet,
    previous,
    spread_pct,
    std_headers,
    table,
)


def _rows(lines: list[str]) -> list[dict[str, str]]:
    rows = [parse(line) for line in lines]
    assert all(r is not None for r in rows)
    return [r for r in rows if r is not None]


def _lines(text: str) -> dict[tuple[str, ...], list[str]]:
    """Table rows by (language, stream, mode), as their stripped cells."""
    out = {}
    for line in text.splitlines()[2:]:
        cells = [c.strip() for c in line.strip().strip("|").split("|")]
        out[tuple(cells[:3])] = cells
    return out


def _by_key(records: list[dict]) -> dict[tuple[str, str, str], dict]:
    return {(r["lang"], r["stream"], r["mode"]): r for r in records}


def _processes(lang: str, stream: str, mode: str, seconds: list[float], packets=1000, nbytes=36000) -> list[str]:
    return [
        f"BENCH lang={lang} stream={stream} mode={mode} packets={packets} bytes={nbytes} seconds={s!r} process={i}"
        for i, s in enumerate(seconds)
    ]


def test_parse_needs_every_key():
    assert parse("BENCH lang=c stream=s mode=frame packets=1 bytes=2") is None
    assert parse("# extra: lang=c stream=s mode=frame packets=1 bytes=2 seconds=1") is None
    assert parse("BENCH lang=c stream=s mode=frame packets=1 bytes=2 seconds=1 rss_kb=5")["rss_kb"] == "5"


def test_spread():
    assert spread_pct([1.0]) is None
    assert spread_pct([]) is None
    # half the range (1.2 - 0.8) over the median (1.0)
    assert spread_pct([1.0, 0.8, 1.2]) == pytest.approx(20.0)
    assert spread_pct([2.0, 2.0]) == 0.0


def test_aggregate_median_spread_and_bulk_by_process():
    rows = _rows(
        _processes("c", "accel_gyro", "bulk", [0.001, 0.002, 0.001])
        + _processes("c", "accel_gyro", "frame", [0.004, 0.004, 0.002])
        + _processes("c", "accel_gyro", "decode", [0.008, 0.005, 0.004])
    )
    rec = _by_key(aggregate(rows))
    frame = rec[("c", "accel_gyro", "frame")]
    assert frame["seconds"] == 0.004  # the median of the processes
    assert frame["processes"] == [0.004, 0.004, 0.002]
    assert frame["spread_pct"] == pytest.approx(25.0)  # (0.004 - 0.002) / 2 / 0.004
    assert frame["packets"] == 1000 and frame["bytes"] == 36000
    # bulk over frame in the same process: 0.25, 0.5, 0.5 -> median 0.5 (not 0.001 / 0.004)
    assert frame["bulk_fraction"] == pytest.approx(0.5)
    assert frame["bulk_fraction_spread_pct"] == pytest.approx(25.0)
    decode = rec[("c", "accel_gyro", "decode")]
    # frame over decode in the same process: 0.5, 0.8, 0.5
    assert decode["decode_over_frame"] == pytest.approx(0.5)
    assert "decode_over_frame" not in frame
    assert rec[("c", "accel_gyro", "bulk")]["bulk_fraction"] == 1.0


def test_aggregate_pairs_bulk_of_the_same_language_and_stream():
    rows = _rows(
        _processes("c", "mixed", "bulk", [0.001])
        + _processes("cpp", "mixed", "bulk", [0.002])
        + _processes("cpp", "mixed", "frame", [0.004])
        + _processes("cpp", "accel_gyro", "frame", [0.004])
        + _processes("python", "mixed", "bulk", [0.001])
        + _processes("python-columns", "mixed", "decode", [0.01])
    )
    rec = _by_key(aggregate(rows))
    assert rec[("cpp", "mixed", "frame")]["bulk_fraction"] == pytest.approx(0.5)  # cpp's bulk, not c's
    assert "bulk_fraction" not in rec[("cpp", "accel_gyro", "frame")]  # no bulk of that stream
    assert "spread_pct" not in rec[("cpp", "mixed", "frame")]  # one process: no spread
    # python-columns runs in the python process: its bulk is python's
    assert rec[("python-columns", "mixed", "decode")]["bulk_fraction"] == pytest.approx(0.1)


def test_aggregate_without_process_key_and_extra_keys():
    rows = _rows(
        [
            "BENCH lang=c-cli stream=accel_gyro mode=decode-cli packets=10 bytes=340 seconds=2.5 rss_kb=1800 cpu=2.25",
        ]
    )
    (rec,) = aggregate(rows)
    assert rec["seconds"] == 2.5 and rec["rss_kb"] == 1800 and rec["cpu"] == 2.25
    assert rec["processes"] == [2.5] and "process" not in rec


def test_table_columns_order_and_json():
    rows = _rows(
        _processes("c", "accel_gyro", "copy-per-packet", [0.002, 0.002])
        + _processes("c", "accel_gyro", "decode", [0.008, 0.008])
        + _processes("c", "accel_gyro", "frame", [0.004, 0.004])
        + _processes("c", "accel_gyro", "bulk", [0.001, 0.001])
        + _processes("c", "mixed", "bulk", [0.001, 0.001])
        + _processes("rust", "accel_gyro", "frame", [0.002, 0.002])
        + _processes("rust", "accel_gyro", "bulk", [0.001, 0.001])
        + _processes("c", "accel_gyro", "csv", [0.3, 0.3])
    )
    records = aggregate(rows)
    text = table(records, ["c", "rust"])
    head = [c.strip() for c in text.splitlines()[0].strip("|").split("|")]
    assert head == ["language", "stream", "mode", "Mpkt/s", "GB/s", "±", "x bulk", "±", "decode/frame", "session"]
    lines = _lines(text)
    frame = lines[("c", "accel_gyro", "frame")]
    assert frame[3:8] == ["0.25", "0.009", "±0.0%", "0.25", "±0.0%"]  # 1000 packets, 36000 bytes in 4 ms
    assert lines[("c", "accel_gyro", "decode")][8] == "0.50"
    assert lines[("c", "accel_gyro", "bulk")][6] == "1.00"
    assert lines[("c", "accel_gyro", "csv")][6] == "0.0033"  # small fractions: two significant digits
    # language (--langs order), stream, then bulk, frame, decode, ..., the copy-per-packet diagnostic
    assert list(lines) == [
        ("c", "accel_gyro", "bulk"),
        ("c", "accel_gyro", "frame"),
        ("c", "accel_gyro", "decode"),
        ("c", "accel_gyro", "copy-per-packet"),
        ("c", "accel_gyro", "csv"),
        ("c", "mixed", "bulk"),
        ("rust", "accel_gyro", "bulk"),
        ("rust", "accel_gyro", "frame"),
    ]
    # the JSON rows: every record with the keys, serialisable, in table order
    out = json.loads(json.dumps(order(records, ["c", "rust"])))
    assert [(r["lang"], r["stream"], r["mode"]) for r in out] == list(lines)
    for r in out:
        assert {"lang", "stream", "mode", "packets", "bytes", "seconds"} <= set(r)
        assert isinstance(r["packets"], int) and isinstance(r["seconds"], float)


def test_session_column():
    rows = _rows(
        [
            "BENCH lang=python stream=accel_gyro mode=bulk packets=100 bytes=3400 seconds=0.001",
            "BENCH lang=python stream=accel_gyro mode=decode packets=100 bytes=3400 seconds=0.009",
            "BENCH lang=python stream=accel_gyro mode=session-ingest packets=100 bytes=3400 seconds=0.010",
            "BENCH lang=python stream=mixed mode=session-ingest packets=10 bytes=3400 seconds=0.010",
            "BENCH lang=python stream=loopback-tcp mode=session-roundtrip packets=2000 bytes=36000 seconds=0.080",
            "BENCH lang=c stream=accel_gyro mode=decode packets=100 bytes=3400 seconds=0.001",
        ]
    )
    lines = _lines(table(aggregate(rows), ["c", "python"]))
    assert lines[("python", "accel_gyro", "session-ingest")][9] == "0.90 x decode"
    # no decode row of that language and stream: no ratio
    assert lines[("python", "mixed", "session-ingest")][9] == "-"
    assert lines[("python", "loopback-tcp", "session-roundtrip")][9] == "25,000/s, 40.0 us each"
    # the rows come in the order language, stream, mode; the round trip after the streams
    order_ = [k for k in lines if k[0] == "python"]
    assert order_ == [
        ("python", "accel_gyro", "bulk"),
        ("python", "accel_gyro", "decode"),
        ("python", "accel_gyro", "session-ingest"),
        ("python", "mixed", "session-ingest"),
        ("python", "loopback-tcp", "session-roundtrip"),
    ]
    assert lines[("c", "accel_gyro", "decode")][9] == ""
    assert lines[("c", "accel_gyro", "decode")][6] == "-"  # no bulk in that process


CALLGRIND = """==4242== Callgrind, a call-graph generating cache profiler
==4242== Command: build/bench/bin/bench-c build/bench/small --passes 1 --stream accel_gyro --mode frame
==4242==
==4242== Events    : Ir
==4242== Collected : 2255409
==4242==
==4242== I   refs:      2,255,409
"""


def test_callgrind_total_and_per_packet():
    assert callgrind_total(CALLGRIND) == 2255409
    with pytest.raises(ValueError):
        callgrind_total("==1== Events : Ir\n")
    assert per_packet(2255409, 175409, 10000) == pytest.approx(208.0)
    with pytest.raises(ValueError):
        per_packet(10, 5, 0)


def test_merge_instructions():
    records = aggregate(_rows(_processes("c", "accel_gyro", "frame", [0.004])))
    count = {
        "lang": "c",
        "stream": "accel_gyro",
        "mode": "frame",
        "instructions": 2255409,
        "instructions_fixed": 175409,
        "instructions_packets": 10000,
        "instructions_per_packet": 208.0,
    }
    other = dict(count, mode="decode", instructions_per_packet=450.0)
    merged = _by_key(merge_instructions(records, [count, other]))
    assert merged[("c", "accel_gyro", "frame")]["instructions_per_packet"] == 208.0
    assert merged[("c", "accel_gyro", "frame")]["seconds"] == 0.004
    alone = merged[("c", "accel_gyro", "decode")]
    assert alone["seconds"] is None and alone["packets"] == 10000
    lines = _lines(table(list(merged.values()), ["c"]))
    assert lines[("c", "accel_gyro", "frame")][-1] == "208"  # the instr/pkt column
    assert ("c", "accel_gyro", "decode") not in lines  # no time: not in the timed table
    assert "| c        | accel_gyro | decode |" in instructions_table([count, other])


def test_previous_keeps_timed_rows_without_counts(tmp_path):
    path = tmp_path / "results.json"
    path.write_text(
        json.dumps(
            [
                {"lang": "c", "stream": "s", "mode": "frame", "seconds": 0.5, "instructions_per_packet": 9.0},
                {"lang": "c", "stream": "s", "mode": "decode", "seconds": None, "instructions_per_packet": 9.0},
                ["not", "a", "row"],
            ]
        )
    )
    assert previous(path) == [{"lang": "c", "stream": "s", "mode": "frame", "seconds": 0.5}]
    path.write_text("{not json")
    assert previous(path) == []
    assert previous(tmp_path / "missing.json") == []


def test_compile_table_ratios_to_the_c_unit():
    """The compile-cost table divides each row by minimal.c's CPU seconds and peak memory (the
    first unit of COMPILE_UNITS): 0.05 s and 32768 kB here, so 2.50 s is x50 and 327680 kB x10.0;
    and each C++ row by the standard-header row's CPU seconds (0.5 s here: 2.50 s is x5.0)."""
    assert COMPILE_UNITS[0][:2] == ("minimal.c", "c")
    rows = [
        {"lang": "compile", "unit": "minimal.c", "cpu_seconds": 0.05, "peak_rss_kb": 32768},
        {"lang": "compile", "unit": "minimal.cpp", "cpu_seconds": 2.5, "peak_rss_kb": 327680},
        {
            "lang": "compile",
            "unit": STD_UNIT,
            "source": "build/bench/compile/std_headers.cpp",
            "cpu_seconds": 0.5,
            "peak_rss_kb": 65536,
        },
    ]
    lines = compile_table(rows).splitlines()
    assert lines[0] == "| translation unit | CPU s | peak MB | x C CPU | x C memory | x std headers CPU |"
    assert lines[2] == "| minimal.c | 0.05 | 32 | 1 | 1.0 | - |"
    assert lines[3] == "| minimal.cpp | 2.50 | 320 | 50 | 10.0 | 5.0 |"
    assert lines[4] == f"| {STD_UNIT} | 0.50 | 64 | 10 | 2.0 | 1.0 |"
    # without the C row and the standard-header row the ratios are not invented
    assert compile_table(rows[1:2]).splitlines()[2] == "| minimal.cpp | 2.50 | 320 | - | - | - |"


def test_std_headers_from_g_plus_plus_h_output():
    """The standard-header unit lists the extension-less headers directly under the C++ include
    directory at any depth of `g++ -H` output, once each, sorted: not bits/, not C headers."""
    out = "\n".join(
        [
            ". /usr/include/c++/12/vector",
            ".. /usr/include/c++/12/bits/stl_vector.h",
            ".. /usr/include/x86_64-linux-gnu/c++/12/bits/c++config.h",
            "... /usr/include/c++/12/optional",
            ". /work/generated/cpp/mipcodec/include/mipcodec/types.hpp",
            ".. /usr/include/c++/12/vector",
            ".... /usr/include/stdint.h",
            "Multiple include guards may be useful for:",
        ]
    )
    assert std_headers(out) == ["optional", "vector"]


def test_compile_units_exist_and_are_compiled_with_strict_flags(tmp_path):
    """Every translation unit of the section exists, and each is compiled -O2 with -Werror."""
    for _name, lang, rel in COMPILE_UNITS:
        assert (ROOT / rel).is_file(), rel
        cmd = compile_command(lang, ROOT / rel, tmp_path / "x.o")
        assert "-O2" in cmd and "-Werror" in cmd and "-c" in cmd and cmd[-2:] == ["-o", str(tmp_path / "x.o")]
