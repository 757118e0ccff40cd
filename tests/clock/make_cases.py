"""Writes tests/clock/cases.txt, the host clock model's corpus (docs/time.md), from stated parameters.

Run: python tests/clock/make_cases.py (seed 52; the output is checked in). Every case simulates a
device whose reference clock runs `drift_ppm` fast against the host's, sending `rate_hz` packets a
second; each packet arrives `base_ms` plus a uniform 0..`jitter_ms` later (plus 0..`burst_ms`
inside bursts). The expected values come from these parameters and the reasoning below, never
from a model's output:

- The model keeps per bucket of device time (1 s, BUCKET_NS) the packet with the smallest arrival -
  device time. Of n packets with uniform delay excess in [0, J], the smallest exceeds e = 10 J / n
  with probability (1 - 10/n)^n < e^-10, so every bucket minimum is within e of the lower envelope
  (true send time + base delay), a straight line since the drift is constant.
- The fitted line lies under every kept point and, being the highest such line at the points' mean
  x, is not below the envelope there. So over the kept span S it is within e of the envelope at the
  ends: its slope is off by at most e / (S / 2), i.e. drift within 1e6 e / (S / 2) ppm (+0.5 ppm
  for the slope's conversion at these drifts), the host time of the last packet within
  e + slope error x 1 s (it is at most one bucket past the last kept point), and every kept point's
  residual above the line (the reported bound) at most 2 e, plus J + B where a burst covers a bucket.
- A reset (device time goes back) or a jump (arrival and device time steps disagree by more than
  RESTART_NS) restarts the model: `restarts` counts them, and the estimate after it uses only later
  packets. There is an estimate once MIN_BUCKETS buckets have closed.

The model's parameters (BUCKET_NS, BUCKETS, MIN_BUCKETS, RESTART_NS) are the spec's
`time.clock_model` (spec/mip/protocol.yaml), the one source the four runtimes are generated from.
"""

from __future__ import annotations

import random
from pathlib import Path

import yaml

SPEC = Path(__file__).resolve().parents[2] / "spec" / "mip" / "protocol.yaml"
MODEL = yaml.safe_load(SPEC.read_text(encoding="utf-8"))["time"]["clock_model"]
BUCKET_NS = MODEL["bucket_ns"]  # device time per bucket (docs/time.md)
BUCKETS = MODEL["buckets"]  # closed buckets kept
MIN_BUCKETS = MODEL["min_buckets"]  # closed buckets before there is an estimate
RESTART_NS = MODEL["restart_ns"]  # a larger step disagreement restarts the model
OUT = Path(__file__).resolve().parent / "cases.txt"

CASES = [
    # name, drift ppm, jitter ms, rate Hz, seconds, events
    dict(name="steady_fast_100ppm", drift_ppm=100.0, jitter_ms=4.0, rate_hz=50, seconds=70.0),
    dict(name="steady_slow_250ppm", drift_ppm=-250.0, jitter_ms=1.0, rate_hz=50, seconds=70.0),
    dict(name="short_span_20ppm", drift_ppm=20.0, jitter_ms=0.5, rate_hz=100, seconds=12.0),
    dict(
        name="jitter_bursts",
        drift_ppm=30.0,
        jitter_ms=1.0,
        rate_hz=50,
        seconds=70.0,
        bursts=[(20.0, 25.0, 200.0), (40.0, 43.5, 600.0)],
    ),
    dict(name="device_reset", drift_ppm=50.0, jitter_ms=1.0, rate_hz=50, seconds=90.0, reset_at=30.0),
    dict(name="time_jump_forward", drift_ppm=-40.0, jitter_ms=1.0, rate_hz=50, seconds=80.0, jump_at=(25.0, 5.0)),
    dict(name="not_yet_estimated", drift_ppm=10.0, jitter_ms=1.0, rate_hz=50, seconds=1.9),
]


def simulate(rng: random.Random, c: dict) -> tuple[list[tuple[int, int]], dict]:
    ppm, j_ns = c["drift_ppm"], c["jitter_ms"] * 1e6
    base_ns = 2_500_000  # least link delay
    host0 = 7_000_000_123_456  # host clock at the device's power-on
    dev0 = 1_234_567_891  # device time of the first packet (ns since power-on)
    period_host = 1e9 / c["rate_hz"]  # the device's own period is 1/rate in device time
    packets, t_dev, k = [], dev0, 0
    epoch_start_s, restarts, last_true = 0.0, 0, None
    jump_done = reset_done = False
    while True:
        host_s = k * period_host / 1e9  # true host seconds since the first packet (approximately)
        if host_s >= c["seconds"]:
            break
        if c.get("reset_at") is not None and not reset_done and host_s >= c["reset_at"]:
            reset_done, restarts, epoch_start_s = True, restarts + 1, host_s
            t_dev = 400_000_000  # power-on again: reference time restarts near zero
            dev_at_reset, host_at_reset = t_dev, host0 + host_s * 1e9
        if c.get("jump_at") is not None and not jump_done and host_s >= c["jump_at"][0]:
            jump_done = True
            if c["jump_at"][1] * 1e9 > RESTART_NS:  # the steps disagree by the jump: a restart
                restarts, epoch_start_s = restarts + 1, host_s
            t_dev += int(c["jump_at"][1] * 1e9)
        # true host send time of device time t_dev: the device runs ppm fast
        if reset_done:
            send = host_at_reset + (t_dev - dev_at_reset) / (1 + ppm * 1e-6)
        else:
            send = host0 + (t_dev - dev0 - (int(c["jump_at"][1] * 1e9) if jump_done else 0)) / (1 + ppm * 1e-6)
        extra = rng.uniform(0.0, j_ns)
        for start, end, burst_ms in c.get("bursts", []):
            if start <= host_s < end:
                extra += rng.uniform(0.0, burst_ms * 1e6)
        packets.append((t_dev, int(send + base_ns + extra)))
        last_true = (t_dev, int(round(send + base_ns)))
        t_dev += int(round(1e9 / c["rate_hz"]))
        k += 1
    device_s = (c["seconds"] - epoch_start_s) * (1 + ppm * 1e-6)  # device time since the (re)start
    span_buckets = min(BUCKETS, int(device_s * 1e9 / BUCKET_NS)) - 1
    n = c["rate_hz"]  # packets per bucket
    e = 10 * j_ns / n
    expect: dict = {"restarts": restarts, "estimated": span_buckets >= MIN_BUCKETS - 1}
    if expect["estimated"]:
        span = (span_buckets - 1) * BUCKET_NS  # kept points span at least this much device time
        slope_err = e / (span / 2)
        burst = max((b for _, _, b in c.get("bursts", [])), default=0.0) * 1e6
        expect.update(
            drift=(ppm, 1e6 * slope_err + 0.5),
            host=(last_true[0], last_true[1], int(e + slope_err * BUCKET_NS) + 1),
            bound_max=int(2 * e + (burst + j_ns if burst else 0)) + 1,
        )
    return packets, expect


def main() -> None:
    rng = random.Random(52)
    out = [
        "# The host clock model's corpus (docs/time.md), written by tests/clock/make_cases.py (seed 52).",
        "# case NAME / p DEVICE_NS HOST_NS (one per packet) / expect estimated 0|1 / expect restarts N /",
        "# expect drift_ppm VALUE TOL / expect host_ns DEVICE_NS HOST_NS TOL / expect bound_max_ns N / end",
    ]
    for c in CASES:
        packets, ex = simulate(rng, c)
        params = ", ".join(f"{k} {v}" for k, v in c.items() if k != "name")
        out += [f"case {c['name']}", f"# {params}"]
        out += [f"p {d} {a}" for d, a in packets]
        out.append(f"expect estimated {int(ex['estimated'])}")
        out.append(f"expect restarts {ex['restarts']}")
        if ex["estimated"]:
            out.append(f"expect drift_ppm {ex['drift'][0]!r} {ex['drift'][1]:.3f}")
            out.append(f"expect host_ns {ex['host'][0]} {ex['host'][1]} {ex['host'][2]}")
            out.append(f"expect bound_max_ns {ex['bound_max']}")
        out.append("end")
    OUT.write_text("\n".join(out) + "\n")


if __name__ == "__main__":
    main()
