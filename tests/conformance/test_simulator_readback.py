"""Read, write back unchanged, read again (docs/conformance.md section 9, issue 51 item 6).

For every command with a read function on every simulated device (the IR's commands whose
variant for the device has `read`), in every language's conformance session tool
(`tests/conformance/session LANG`, one simulator and one session per device and language):
read the setting, write the values the read reported back with the write function (the read
reply's parameters under the command's names), then read it again. The write must be
acknowledged and the second read must report the same values: what the device reports is a
value it accepts. A setting read per key (a port, a data set, an instance) is read for each key
combination the spec's `settings: keys` resolves for the model, else for each one the read
samples (tests/conformance/samples.py) hold. A command with read but no write (device startup
settings) is read twice: the same reply.

The session is driven line by line (the tool answers each command line before it reads the
next), so the write-back line is built from the read's result line.
"""

from __future__ import annotations

import json
import os
import select
import subprocess

import pytest

from tests.conformance.samples import field_samples
from tests.conformance.test_simulator import IR, MODELS, PROTOCOLS, SESSION, SESSION_LANGUAGES, Sim

READ, WRITE = "read", "write"
ANSWER_S = 60  # the longest wait for one result line (a tool building under load answers late)


def _function_value(protocol: dict, name: str) -> int:
    enum = protocol["function_selector"]["enum"]
    t = next(t for t in protocol["types"] if t["name"] == enum)
    return next(v["value"] for v in t["values"] if v["name"] == name)


def _keys(protocol: dict, name: str, device: str, key_params: list[str], samples: list) -> list[dict]:
    """The key combinations a keyed setting is read for: the spec's resolved settings keys for
    the model, else those of the read samples; [{}] for a setting without key parameters."""
    if not key_params:
        return [{}]
    for entry in (protocol.get("settings") or {}).get("keys") or []:
        resolved = (entry.get("resolved") or {}).get(device)
        if entry["command"] == name and resolved and set(resolved[0]) == set(key_params):
            return [dict(r) for r in resolved]
    out: dict[str, dict] = {}
    for x in samples:
        key = {k: x.values[k] for k in key_params if k in x.values}
        if len(key) == len(key_params):
            out.setdefault(json.dumps(key, sort_keys=True), key)
    return list(out.values())


def readback_plan(protocol: dict, device: str) -> list[dict]:
    """Per command with read on `device` and per key combination: the command's set, field,
    whether it has write, its write parameter names, and the read reply's parameter names."""
    read = _function_value(protocol, READ)
    samples = field_samples(protocol)
    plan = []
    for s in protocol["sets"]:
        if s["kind"] != "command":
            continue
        for f in s["fields"]:
            if f["role"] != "command" or device not in f["devices"]:
                continue
            v = next((v for v in f["variants"] if v["device"] in (None, device) and device in v["devices"]), None)
            if v is None or READ not in (v["functions"] or []):
                continue
            key_params = [q["name"] for q in v["params"] if READ in (q["functions"] or []) and not q["optional"]]
            reads = [
                x
                for x in samples
                if (x.set_id, x.descriptor) == (s["id"], f["id"])
                and x.device in (None, device)
                and x.values.get("function") == read
            ]
            rid = next((r["id"] for r in v["responses"] if (r["when"] or {}).get("function") == READ), None)
            reply = next((r for r in s["fields"] if r["id"] == rid), None)
            rv = next((x for x in reply["variants"] if x["device"] in (None, device)), None) if reply else None
            writes = [(q["name"], q["count"] is not None) for q in v["params"] if WRITE in (q["functions"] or [])]
            for key in _keys(protocol, f["name"], device, key_params, reads):
                plan.append(
                    {
                        "set": s["id"],
                        "field": f,
                        "key": key,
                        "write": WRITE in v["functions"],
                        "params": writes,
                        "reply": [q["name"] for q in rv["params"]] if rv else [],
                    }
                )
    return plan


def _line(protocol: dict, device: str, item: dict, function: str, values: dict) -> str:
    f = item["field"]
    entry = {"descriptor": f["id"], "name": f["name"]}
    if len(f["variants"]) > 1:
        entry["device"] = device
    entry["values"] = {"function": _function_value(protocol, function), **values}
    return json.dumps({"offset": 0, "set": item["set"], "fields": [entry]}, separators=(",", ":"))


def write_back(item: dict, reported: dict) -> dict:
    """The write's values from a read reply's: by name, else (a reply parameter named otherwise,
    enable -> enabled) by position when the reply has as many parameters as the write; the key
    parameters as read; a parameter the read does not report (a reserved byte) as zero (a list:
    empty), as the device command line's settings apply does (generator/settings_rows.py fill)."""
    values = {}
    by_position = len(item["reply"]) == len(item["params"])
    for i, (name, is_list) in enumerate(item["params"]):
        if name in item["key"]:
            values[name] = item["key"][name]
        elif name in reported:
            values[name] = reported[name]
        elif by_position and item["reply"][i] in reported:
            values[name] = reported[item["reply"][i]]
        else:
            values[name] = [] if is_list else 0
    return values


class Tool:
    """A session tool driven line by line: `ask` sends one command line and returns its result."""

    def __init__(self, lang: str, protocol: str, address: str, device: str) -> None:
        cmd = [str(SESSION), lang, "--connect", address, "--protocol", protocol, "--device", device]
        cmd += ["--timeout-ms", "1000"]
        self.proc = subprocess.Popen(
            cmd, stdin=subprocess.PIPE, stdout=subprocess.PIPE, stderr=subprocess.PIPE, bufsize=0
        )
        self.number = 0
        self.pending = b""

    def ask(self, line: str) -> dict:
        self.number += 1
        assert self.proc.stdin is not None and self.proc.stdout is not None
        self.proc.stdin.write(line.encode() + b"\n")
        self.proc.stdin.flush()
        fd = self.proc.stdout.fileno()
        while True:
            while b"\n" not in self.pending:
                ready, _, _ = select.select([fd], [], [], ANSWER_S)
                chunk = os.read(fd, 65536) if ready else b""
                if not chunk:
                    self.proc.kill()
                    err = self.proc.stderr.read().decode() if self.proc.stderr else ""
                    raise AssertionError(f"no result for line {self.number} ({line}): {err}")
                self.pending += chunk
            out, self.pending = self.pending.split(b"\n", 1)
            got = json.loads(out)
            if "result" in got:
                assert got["line"] == self.number, got
                return got

    def close(self) -> int:
        assert self.proc.stdin is not None
        self.proc.stdin.close()
        return self.proc.wait(60)


def run_readback(lang: str, protocol: str, device: str) -> list[str]:
    """The failures of the read-write-read cycle of every command: empty when all pass."""
    proto = PROTOCOLS[protocol]
    plan = readback_plan(proto, device)
    assert plan, (protocol, device)
    failures: list[str] = []
    # the tool built first (a compiled language's first run builds it; the answers' timeout is not for that)
    subprocess.run([str(SESSION), lang, "--help", "--protocol", protocol], capture_output=True, timeout=900)
    with Sim(protocol, device, "tcp:127.0.0.1:0") as sim:
        tool = Tool(lang, protocol, sim.address, device)
        try:
            for item in plan:
                what = f"{item['field']['name']} {item['key']}"
                first = tool.ask(_line(proto, device, item, READ, item["key"]))
                if first["result"] != "ack" or bool(first["reply"]) != bool(item["reply"]):
                    failures.append(f"{what}: read: {first}")
                    continue
                reported = first["reply"][0]["values"] if first["reply"] else {}
                if item["write"]:
                    written = tool.ask(_line(proto, device, item, WRITE, write_back(item, reported)))
                    if written["result"] != "ack":
                        failures.append(f"{what}: write back of {reported}: {written}")
                        continue
                again = tool.ask(_line(proto, device, item, READ, item["key"]))
                if again["result"] != "ack" or (again["reply"][0]["values"] if again["reply"] else {}) != reported:
                    failures.append(f"{what}: read after the write back: {again}, first {reported}")
        finally:
            code = tool.close()
    assert code == 0, (lang, device, code)
    return failures


@pytest.mark.parametrize("lang", SESSION_LANGUAGES)
@pytest.mark.parametrize("protocol,device", MODELS)
def test_read_write_back_read(lang: str, protocol: str, device: str) -> None:
    failures = run_readback(lang, protocol, device)
    assert not failures, "\n".join(failures)


def test_the_plan_covers_every_read() -> None:
    """Every command with read on every model is in the plan (both MIP devices and the MS-IMU3020)."""
    for protocol, device in MODELS:
        proto = PROTOCOLS[protocol]
        plan = readback_plan(proto, device)
        names = {item["field"]["name"] for item in plan}
        assert len(names) >= (10 if protocol == "mscip" else 46), (device, sorted(names))
    gx5 = readback_plan(PROTOCOLS["mip"], "gx5_45")
    assert [i["field"]["name"] for i in gx5 if not i["write"]] == ["device_startup_settings"]  # read twice
    cv7 = readback_plan(PROTOCOLS["mip"], "cv7_ins")
    assert len([i for i in cv7 if i["field"]["name"] == "event_control"]) == 12  # the spec's settings keys
    assert IR["protocols"]
