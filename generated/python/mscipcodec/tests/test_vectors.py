"""Golden vectors (generated from tests/vectors/mscip/): decode whole and byte by byte, encode back."""

# ruff: noqa: I001  (whether the package is first- or third-party depends on where ruff runs)

import pytest
from mscipcodec import decode_bytes, decode_stream, encode_lines

CASES = []


@pytest.mark.parametrize("case", CASES, ids=[c["name"] for c in CASES])
def test_decode_whole(case):
    assert decode_bytes(bytes.fromhex(case["hex"]), case["device"]) == case["expect"], case["where"]


@pytest.mark.parametrize("case", CASES, ids=[c["name"] for c in CASES])
def test_decode_byte_by_byte(case):
    data = bytes.fromhex(case["hex"])
    lines = list(decode_stream((data[i : i + 1] for i in range(len(data))), case["device"]))
    assert lines == case["expect"], case["where"]


@pytest.mark.parametrize("case", CASES, ids=[c["name"] for c in CASES])
def test_encode(case):
    assert encode_lines(case["expect"]).hex() == case["hex"], case["where"]
