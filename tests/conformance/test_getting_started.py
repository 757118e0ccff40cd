"""The getting-started example of every package (generator/examples.py), run in every language
for every protocol through `tests/lang/<lang>.sh example FILE`.

FILE is made of golden vectors (those decoded without a device) with garbage bytes between them
(never a sync byte, so the garbage cannot start or complete a packet), repeated until it spans
several of the example's read blocks. The expected output is derived from the vectors' canonical
JSON lines alone: `packet set=0xSS fields=...` with each field's `name` (`?` for a raw field or
trailing bytes) and `skipped N` for each skip run, merged with the garbage around it. The
expected command is the bytes of the golden vector that decodes to exactly that command.
"""

import copy
import json
import random
import subprocess
from pathlib import Path

import pytest

from generator.examples import BLOCK_SIZE, END, PARTS, ExampleError, example_command
from generator.spec import load_spec
from generator.vectors import load_corpus
from tests.helpers.langs import langs

ROOT = Path(__file__).resolve().parents[2]
LANGS = langs()  # the target registry (generator/targets/__init__.py)
IR = load_spec()
VECTORS = load_corpus(IR, ROOT)
PROTOCOLS = {p["name"]: p for p in IR["protocols"]}
# Where each back end renders the example, and how its marker comments start.
SOURCES = {
    "c": ("c/{pkg}/examples/getting_started.c", "//"),
    "cpp": ("cpp/{pkg}/examples/getting_started.cpp", "//"),
    "python": ("python/{pkg}/examples/getting_started.py", "#"),
    "rust": ("rust/{pkg}/examples/getting_started.rs", "//"),
}


def run_example(lang: str, protocol: str, *args: str) -> subprocess.CompletedProcess:
    """tests/lang/<lang>.sh example ARGS for the protocol's package, chosen as the decode and
    encode wrappers choose it (select_protocol of tests/conformance/protocol.sh)."""
    script = '. "$1"; select_protocol --protocol "$2"; shift 2; exec "$@"'
    return subprocess.run(
        ["bash", "-c", script, "example", str(ROOT / "tests/conformance/protocol.sh"), protocol]
        + [str(ROOT / "tests/lang" / f"{lang}.sh"), "example", *args],
        capture_output=True,
    )


def command_line(protocol: str) -> str:
    """The canonical JSON line of a packet holding only the example command."""
    set_, field = example_command(PROTOCOLS[protocol])
    fields = [{"descriptor": field["id"], "name": field["name"], "values": {}}]
    return json.dumps({"offset": 0, "set": set_["id"], "fields": fields}, separators=(",", ":"))


def command_hex(protocol: str) -> str:
    """The bytes of the golden vector(s) whose only line is the example command."""
    hexes = {c["hex"] for c in VECTORS if c["protocol"] == protocol and c["expect"] == [command_line(protocol)]}
    assert len(hexes) == 1, f"{protocol}: want one golden packet of the example command, found {sorted(hexes)}"
    return hexes.pop()


def event_lines(case: dict) -> list:
    """('packet', line) and ('skipped', count) from the canonical JSON lines of a vector."""
    out = []
    for line in case["expect"]:
        rec = json.loads(line)
        if "skipped" in rec:
            out.append(("skipped", len(rec["skipped"]) // 2))
        else:
            names = ",".join(f.get("name", "?") for f in rec["fields"])
            out.append(("packet", f"packet set=0x{rec['set']:02x} fields={names}"))
    return out


def build_stream(protocol: str) -> tuple:
    """(bytes, expected output lines after the command, vectors used, one that crosses a block)."""
    sync = set(PROTOCOLS[protocol]["framing"]["sync"])
    garbage_bytes = [b for b in range(256) if b not in sync]
    # (not the cases with NMEA or RTCM3 lines: the examples print packets and skipped bytes only)
    cases = [
        c
        for c in VECTORS
        if c["protocol"] == protocol
        and not c["device"]
        and not any('"nmea":' in line or '"rtcm":' in line for line in c["expect"])
    ]
    rng = random.Random(20261121)
    data = bytearray()
    events: list = []
    crossing = None
    while len(data) < 3 * BLOCK_SIZE:
        for case in cases:
            garbage = bytes(rng.choice(garbage_bytes) for _ in range(rng.randrange(1, 6)))
            data += garbage
            events.append(("skipped", len(garbage)))
            start = len(data)
            data += bytes.fromhex(case["hex"])
            if crossing is None and start // BLOCK_SIZE != (len(data) - 1) // BLOCK_SIZE and not case["rejected"]:
                crossing = case["name"]
            events.extend(event_lines(case))
    data += b"\x00"
    events.append(("skipped", 1))
    lines: list = []
    pending = 0  # adjacent skip runs are one run
    for kind, what in events:
        if kind == "skipped":
            pending += what
            continue
        if pending:
            lines.append(f"skipped {pending}")
            pending = 0
        lines.append(what)
    if pending:
        lines.append(f"skipped {pending}")
    return bytes(data), lines, cases, crossing


@pytest.fixture(scope="module")
def streams(tmp_path_factory):
    out = {}
    for protocol in PROTOCOLS:
        data, lines, cases, crossing = build_stream(protocol)
        path = tmp_path_factory.mktemp("getting-started") / f"{protocol}.bin"
        path.write_bytes(data)
        out[protocol] = (path, lines, cases, crossing)
    return out


def test_example_command_is_the_first_plain_command_of_the_lowest_command_set():
    picked = {name: (s["id"], f["id"], f["name"]) for name, p in PROTOCOLS.items() for s, f in [example_command(p)]}
    assert picked == {"mip": (0x01, 0x01, "ping"), "mscip": (0x01, 0x02, "ping")}


def test_example_command_is_chosen_by_data_not_by_name():
    mip = copy.deepcopy(PROTOCOLS["mip"])
    base = next(s for s in mip["sets"] if s["id"] == 0x01)
    base["fields"][0]["name"] = "renamed"
    assert example_command(mip)[1]["name"] == "renamed"
    base["fields"][0]["params"] = [{"name": "x"}]  # a parameter: no longer the example
    assert example_command(mip)[1]["name"] == "set_to_idle"
    base["id"] = 0x70  # now 3DM (0x0C) is the command set with the lowest id
    assert [example_command(mip)[i]["name"] for i in (0, 1)] == ["threedm", "get_imu_base_rate"]
    threedm = next(s for s in mip["sets"] if s["id"] == 0x0C)
    threedm["fields"] = [f for f in threedm["fields"] if f["params"]]
    with pytest.raises(ExampleError, match="threedm"):  # no fallback to another set: a clear error
        example_command(mip)


def test_expected_command_is_the_published_packet():
    # MIP ping as printed in the manual: 75 65 01 02 02 01 E0 C6.
    assert command_hex("mip") == "756501020201e0c6"
    assert command_hex("mscip").startswith("a5a501")


def test_stream_covers_the_interesting_cases(streams):
    for protocol, (path, lines, cases, crossing) in streams.items():
        assert any(c["rejected"] for c in cases), protocol
        assert any("unknown descriptor" in line for c in cases for line in c["expect"]), protocol
        assert any('"trailing"' in line for c in cases for line in c["expect"]), protocol
        assert crossing, f"{protocol}: no packet crosses a {BLOCK_SIZE}-byte block boundary"
        assert path.stat().st_size > 2 * BLOCK_SIZE
        assert any("=?" in line or ",?" in line for line in lines)


@pytest.mark.parametrize("protocol", sorted(PROTOCOLS))
@pytest.mark.parametrize("lang", LANGS)
def test_example_output(lang, protocol, streams):
    path, lines, _cases, _crossing = streams[protocol]
    proc = run_example(lang, protocol, str(path))
    assert proc.returncode == 0, proc.stderr.decode(errors="replace")
    got = proc.stdout.decode().splitlines()
    want = [f"command {command_hex(protocol)}", *lines]
    assert got[0] == want[0]
    assert len(got) == len(want), f"{len(got)} lines, want {len(want)}"
    diff = [f"line {i + 1}: got {g!r}, want {w!r}" for i, (g, w) in enumerate(zip(got, want)) if g != w]
    assert not diff, "\n".join(diff[:20])


@pytest.mark.parametrize("lang", LANGS)
def test_example_errors_are_messages(lang, tmp_path):
    missing = tmp_path / "missing.bin"
    for args, what in (((str(missing),), "missing.bin"), ((), "usage: getting_started"), (("a", "b"), "usage")):
        proc = run_example(lang, "mip", *args)
        err = proc.stderr.decode(errors="replace")
        assert proc.returncode != 0, f"{lang} {args}: exit 0"
        assert what in err, f"{lang} {args}: {err!r}"
        assert "Traceback" not in err and "panicked" not in err


@pytest.mark.parametrize("lang", LANGS)
def test_example_source_marks_its_parts(lang):
    template, comment = SOURCES[lang]
    for protocol in PROTOCOLS.values():
        text = (ROOT / "generated" / template.format(pkg=protocol["package"])).read_text()
        marks = [line.strip() for line in text.splitlines() if line.strip().startswith(f"{comment} [")]
        want = [m for part in PARTS for m in (f"{comment} [{part}]", f"{comment} [{END}]")]
        assert sorted(marks) == sorted(want), f"{lang} {protocol['name']}: {marks}"
        for part in PARTS:  # each part is closed before the next opens
            start = marks.index(f"{comment} [{part}]")
            assert marks[start + 1] == f"{comment} [{END}]"
