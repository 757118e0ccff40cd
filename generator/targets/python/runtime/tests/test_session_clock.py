"""The session's host clock model (Session.host_clock, host_ns; clock.py, docs/time.md): fed the
device's reference time (the spec's time.reference_time: alpha's shared 0xD5) of every data
packet at the feed's host time."""

import pytest
from testproto import shared
from testproto.codec.framing import PacketBuilder
from testproto.codec.packets import Packet
from testproto.session import Session

HOST0 = 9_000_000_000_000


def _stream(ppm: float, seconds: int, rate: int = 50):
    """(packet bytes, host arrival ns): a device clock `ppm` fast, no link delay or jitter."""
    for k in range(seconds * rate):
        d = 3_000_000_000 + k * (1_000_000_000 // rate)
        a = HOST0 + round((d - 3_000_000_000) / (1 + ppm * 1e-6))
        yield PacketBuilder(0x80).add(shared.ReferenceTimestamp(nanoseconds=d)).build(), a, d


@pytest.mark.parametrize("samples", [False, True], ids=["packets", "samples"])
def test_the_session_feeds_the_model_the_reference_time_at_the_read_time(samples):
    session = Session("alpha")
    if samples:  # the session then parses raw packets (another route to the handlers)
        session.on_sample(lambda sample: None)
    model = session.host_clock
    got = []
    for data, a, d in _stream(100.0, 10):
        for e in session.feed(data, a // 1_000_000, now_ns=a):
            if isinstance(e, Packet):
                got.append((session.host_ns(e), a, d))
    assert model.estimated and model.restarts == 0
    # No delay and no jitter: every bucket's point is on the true line, so the fit is that line
    # (to the rounding of arrival times to whole ns over 1 s steps: < 0.01 ppm).
    assert abs(model.drift_ppm - 100.0) < 0.01
    assert got[0][0] is None  # nothing before two buckets closed
    host, a, d = got[-1]
    assert abs(host - a) <= 1 and model.host_time(d) == host
    assert model.offset_ns == host - d


def test_without_the_reference_time_the_model_is_not_fed():
    session = Session("beta")  # beta has no reference time in the spec
    model = session.host_clock
    for data, a, _ in _stream(100.0, 4):
        session.feed(data, a // 1_000_000, now_ns=a)
    assert not model.estimated and session.host_ns(Packet(0, 0x80, [])) is None


def test_the_model_runs_only_once_used():
    session = Session("alpha")
    for data, a, _ in _stream(0.0, 3):
        session.feed(data, a // 1_000_000, now_ns=a)
    assert not session.host_clock.estimated  # started now: nothing fed before
