"""Bad golden-vector files give located errors, never a traceback."""

import re
from pathlib import Path

import pytest

from generator.diagnostics import SpecErrors
from generator.spec import load_spec
from generator.vectors import load_vectors

IR = load_spec()

CASES = [
    (
        "missing set",
        "[{fields: [{descriptor: 1, name: ping, values: {}}]}]",
        "cases.0.packets.0: missing required key 'set'",
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
