"""session/clock.py: the host clock model runs the corpus tests/clock/cases.txt (docs/time.md), as C, C++
and Rust do."""

from pathlib import Path

import pytest
from testproto.session.clock import ClockModel

CASES = Path(__file__).resolve().parents[5] / "tests" / "clock" / "cases.txt"


def _cases() -> list[tuple[str, list[tuple[int, int]], list[list[str]]]]:
    cases, name, packets, expects = [], None, [], []
    for line in CASES.read_text().splitlines():
        words = line.split()
        if not words or words[0].startswith("#"):
            continue
        if words[0] == "case":
            name, packets, expects = words[1], [], []
        elif words[0] == "p":
            packets.append((int(words[1]), int(words[2])))
        elif words[0] == "expect":
            expects.append(words[1:])
        elif words[0] == "end":
            cases.append((name, packets, expects))
        else:
            raise AssertionError(f"{CASES}: unknown line {line!r}")
    return cases


@pytest.mark.parametrize("name,packets,expects", _cases(), ids=lambda v: v if isinstance(v, str) else "")
def test_clock_corpus(name, packets, expects):
    model = ClockModel()
    for d, a in packets:
        host = model.add(d, a)
        assert (host is None) == (not model.estimated)
    assert expects, name
    for what, *args in expects:
        if what == "estimated":
            assert model.estimated == bool(int(args[0]))
            if not model.estimated:
                assert model.drift_ppm is None and model.offset_ns is None and model.host_time(packets[-1][0]) is None
        elif what == "restarts":
            assert model.restarts == int(args[0])
        elif what == "drift_ppm":
            assert abs(model.drift_ppm - float(args[0])) <= float(args[1]), model.drift_ppm
        elif what == "host_ns":
            d, host, tol = (int(v) for v in args)
            assert abs(model.host_time(d) - host) <= tol, model.host_time(d) - host
            assert model.offset_ns == model.host_time(packets[-1][0]) - packets[-1][0]
        elif what == "bound_max_ns":
            assert 0 <= model.bound_ns <= int(args[0]), model.bound_ns
        else:
            raise AssertionError(f"unknown expectation {what}")


def test_clock_restarts_when_device_time_goes_back():
    model = ClockModel()
    for k in range(300):
        model.add(10**9 + k * 10**7, 5 * 10**12 + k * 10**7)
    assert model.estimated and model.restarts == 0
    model.add(10**6, 5 * 10**12 + 301 * 10**7)  # a reset: the reference time restarts
    assert model.restarts == 1 and not model.estimated
