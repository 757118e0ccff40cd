"""The host clock model's parameters a package is rendered with (docs/time.md): the IR's
`time.clock_model` (the protocol file's, generator/passes/time_facts.py), read by every back end so
that the four runtimes (C protocol.h, C++ framing.hpp, Rust framing.rs, Python _columns.py) and
tests/clock/make_cases.py take them from the spec.

A protocol file without `reference_time` states no clock model: nothing feeds the model there, and
its packages carry the model's code with UNUSED, a model that never estimates (two buckets kept,
three needed: its ring still has two places, so no index is taken modulo one)."""

from __future__ import annotations

UNUSED = {"bucket_ns": 1_000_000_000, "buckets": 2, "min_buckets": 3, "restart_ns": 1_000_000_000}


def clock_model(proto: dict) -> dict:
    """`bucket_ns`, `buckets`, `min_buckets`, `restart_ns` of the protocol's packages."""
    return (proto.get("time") or {}).get("clock_model") or dict(UNUSED)
