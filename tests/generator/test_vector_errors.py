"""Bad golden-vector files give located errors, never a traceback."""

import re
from pathlib import Path

import pytest

from generator.diagnostics import SpecErrors
from generator.spec import load_spec
from generator.vectors import load_corpus, load_vectors

IR = load_spec()

CASES = [
    (
        "missing set",
        "[{fields: [{descriptor: 1, name: ping, values: {}}]}]",
        "cases[bad].packets.0: missing required key 'set'",
    ),
    ("field not a mapping", '[{set: 1, fields: ["junk"]}]', "'junk' has the wrong type (expected object)"),
    (
        "unknown descriptor",
        "[{set: 1, fields: [{descriptor: 0x55, name: x, values: {}}]}]",
        "no field 0x55 in set 0x01",
    ),
    (
        "wrong name",
        "[{set: 1, fields: [{descriptor: 1, name: pong, values: {}}]}]",
        "descriptor 0x01 is 'ping', the vector says 'pong'",
    ),
    (
        "value out of range",
        "[{set: 1, fields: [{descriptor: 9, name: comm_port_speed, values: {function: write, port: 300}}]}]",
        "300 is not a valid u8",
    ),
    (
        "missing parameter",
        "[{set: 1, fields: [{descriptor: 0x89, name: comm_port_speed_response, values: {port: 1}}]}]",
        "missing parameter 'baud'",
    ),
    (
        "unknown enum name",
        "[{set: 1, fields: [{descriptor: 0xF1, name: ack_nack, values: {command_descriptor: 1, ack_code: okay}}]}]",
        "'okay' is not a value of enum AckCode",
    ),
    (
        "variant not named",
        "[{set: 1, fields: [{descriptor: 0x83, name: built_in_test_result, values: {flags: 0}}]}]",
        "has per-device variants; name one with device:",
    ),
    (
        "empty optional array last",
        "[{set: 12, fields: [{descriptor: 8, name: imu_message_format,"
        " values: {function: read, num_descriptors: 0, descriptors: []}}]}]",
        "optional parameter 'descriptors' is empty and last: decoders print it absent (expected leave 'descriptors' out)",
    ),
]


@pytest.mark.parametrize("case", CASES, ids=[c[0] for c in CASES])
def test_bad_vector_is_located(tmp_path: Path, case):
    _id, packets, expected = case
    d = tmp_path / "vectors" / "mip"
    d.mkdir(parents=True)
    (d / "bad.yaml").write_text(f'cases:\n  - name: bad\n    derivation: test\n    hex: "00"\n    packets: {packets}\n')
    with pytest.raises(SpecErrors) as exc:
        load_vectors(IR, tmp_path / "vectors")
    messages = [str(e) for e in exc.value.errors]
    assert any(expected in m for m in messages), messages
    # every message is located: <...>/vectors/mip/bad.yaml:LINE:COLUMN: error: ...
    assert all(re.search(r"vectors/mip/bad\.yaml:\d+:\d+: error: ", m) for m in messages), messages


PING = "756501020201E0C6"
PING_PACKET = "{set: 1, fields: [{descriptor: 1, name: ping, values: {}}]}"
TILING = [
    (
        "packet offset wrong",
        f"00{PING}",
        f"[{{offset: 2, {PING_PACKET[1:]}]",
        "skipped: [{offset: 0, count: 1}]",
        "an event starts at offset 2, but the previous one ends at 1",
    ),
    (
        "skipped bytes not the input's",
        f"00{PING}",
        f"[{{offset: 1, {PING_PACKET[1:]}]",
        "skipped: [{offset: 0, hex: '01'}]",
        "skipped bytes at offset 0 are not the input's (00)",
    ),
    (
        "skip runs not merged",
        f"0000{PING}",
        f"[{{offset: 2, {PING_PACKET[1:]}]",
        "skipped: [{offset: 0, count: 1}, {offset: 1, count: 1}]",
        "are adjacent; they are one run",
    ),
    (
        "bad checksum",
        "756501020201E0C7",
        f"[{PING_PACKET}]",
        "skipped: []",
        "the packet at offset 0 is truncated or its checksum is wrong",
    ),
    ("bytes left over", f"{PING}00", f"[{PING_PACKET}]", "skipped: []", "the events end at offset 8, the input at 9"),
    (
        "skip past the input",
        f"{PING}00",
        f"[{PING_PACKET}]",
        "skipped: [{offset: 8, count: 2}]",
        "skip run at 8 of 2 bytes runs past the input",
    ),
    ("wrong set", PING, "[{set: 2, fields: []}]", "skipped: []", "the packet at offset 0 is of set 1, not 2"),
]


@pytest.mark.parametrize("case", TILING, ids=[c[0] for c in TILING])
def test_events_must_tile_the_input(tmp_path: Path, case):
    """A hand-written case whose events do not account for every byte exactly once is refused
    with a located message (tests/streams/ and tests/vectors/ alike)."""
    _id, hexs, packets, skipped, expected = case
    d = tmp_path / "streams" / "mip"
    d.mkdir(parents=True)
    (d / "bad.yaml").write_text(
        f"cases:\n  - name: bad\n    derivation: test\n    hex: {hexs}\n    packets: {packets}\n    {skipped}\n"
    )
    with pytest.raises(SpecErrors) as exc:
        load_vectors(IR, tmp_path / "streams")
    messages = [str(e) for e in exc.value.errors]
    assert any(expected in m for m in messages), messages
    assert all(re.search(r"streams/mip/bad\.yaml:\d+:\d+: error: ", m) for m in messages), messages


def test_stream_case_names_must_not_repeat_vector_names(tmp_path: Path):
    for corpus in ("vectors", "streams"):
        d = tmp_path / "tests" / corpus / "mip"
        d.mkdir(parents=True)
        (d / "a.yaml").write_text(
            f"cases:\n  - name: same\n    derivation: test\n    hex: {PING}\n    packets: [{PING_PACKET}]\n"
        )
    with pytest.raises(SpecErrors) as exc:
        load_corpus(IR, tmp_path)
    assert "case 'same' of tests/streams/mip/a.yaml is also in tests/vectors/mip/a.yaml" in str(exc.value.errors[0])


def test_empty_case_has_no_events(tmp_path: Path):
    d = tmp_path / "streams" / "mip"
    d.mkdir(parents=True)
    (d / "a.yaml").write_text('cases:\n  - name: empty\n    derivation: test\n    hex: ""\n')
    (case,) = load_vectors(IR, tmp_path / "streams")
    assert case["expect"] == [] and case["corpus"] == "streams"
