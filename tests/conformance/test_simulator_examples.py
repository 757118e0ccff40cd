"""Each package's configure-and-stream example (`examples/configure_and_stream.<ext>`, generator/
examples.py session_example) against the simulated device (docs/conformance.md section 9), over TCP
and a pseudo-terminal: `tests/conformance/simulate --listen ... --protocol P --device D` with the
example's protocol and device, then `tests/lang/<lang>.sh configure ADDRESS COUNT`, for every
language whose package has the example (test_configure_example.py's rule and helpers).

Checks: exit 0; the `device` line names the model; the setting read back holds the values the
example wrote (the simulator keeps settings: its factory values differ); COUNT lines per data field
in order, each value plausible for a device at rest (an accelerometer vector of magnitude 1 g,
other values small noise).
"""

from __future__ import annotations

import math
import re

import pytest

from generator.examples import device_variant, session_example
from tests.conformance.test_configure_example import CASES, COUNT, PROTOCOLS, run_example
from tests.conformance.test_simulator import TRANSPORTS, Sim, listen_for

NUMBER = r"[-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?"
GRAVITY = {"g": 1.0, "m/s^2": 9.80665, "m/s/s": 9.80665, "m/s²": 9.80665}


def values_of(line: str, name: str) -> list[float]:
    """The numbers printed for parameter `name` (`name=...`, Rust's `name: ...`, JSON's `"name":...`; a list in [])."""
    m = re.search(rf"\b{name}\"?\s*[=:]\s*(\[[^\]]*\]|{NUMBER})", line)
    assert m, (name, line)
    return [float(x) for x in re.findall(NUMBER, m.group(1))]


CASES_T = [(lang, proto, t) for lang, proto in CASES for t in TRANSPORTS]


@pytest.mark.parametrize("lang,protocol,transport", CASES_T, ids=[f"{a}-{b}-{c}" for a, b, c in CASES_T])
def test_configure_example_against_simulator(lang, protocol, transport):
    proto = PROTOCOLS[protocol]
    ex = session_example(proto)
    built = run_example(lang, protocol, timeout=1800)  # builds the program first (usage: exit 2)
    assert built.returncode == 2 and "usage" in built.stderr, built.stderr
    with Sim(protocol, ex["device"], listen_for(transport)) as sim:
        r = run_example(lang, protocol, sim.address, str(COUNT), timeout=60)
    assert r.returncode == 0, r.stderr
    lines = r.stdout.splitlines()
    # The model name the simulated device reports: the spec's identity for the model (the MS-CIP
    # manual's example reply, "MS_IMU3020", line 294), else the device's title.
    identity = (proto["simulation"] or {}).get("identity") or {}
    named = [e["values"].get("model_name") for e in identity.get("devices", []) if e["device"] == ex["device"]]
    title = named[0] if named and named[0] else next(d["title"] for d in proto["devices"] if d["id"] == ex["device"])
    assert lines[0].startswith("device ") and title in lines[0], lines[0]
    assert lines[1].startswith("setting "), r.stdout
    written = ex["setting"]["values"]
    assert written
    for name, value in written.items():
        assert values_of(lines[1], name) == pytest.approx([float(value)], abs=1e-6), (name, lines[1])
    fields = {f["name"]: device_variant(proto, f, ex["device"]) for f in ex["data"]["fields"]}
    assert [ln.split()[0] for ln in lines[2:]] == list(fields) * COUNT, r.stdout
    for ln in lines[2:]:
        for q in fields[ln.split()[0]]["params"]:
            got = values_of(ln, q["name"])
            assert got and all(math.isfinite(x) for x in got), (q["name"], ln)
            g = GRAVITY.get(q.get("units") or "")
            if g is not None:
                assert math.hypot(*got) == pytest.approx(g, rel=0.05), (q["name"], ln)
            else:
                assert max(abs(x) for x in got) < 1.0, (q["name"], ln)
