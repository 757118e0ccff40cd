"""The "configure the device and stream data" example of every package (generator/examples.py
session_example), run through `tests/lang/<lang>.sh configure tcp:127.0.0.1:PORT COUNT` against the
scripted fake device (fake_device.py) over loopback TCP, for every language whose package has
`examples/configure_and_stream.<ext>` and every protocol.

The script is derived from the spec alone: for each step of the example (ping, device
information, setting write and read, message format, stream enable) the device reads one
command and answers with its ack and, where the spec gives the command a reply field, that
field (default values); after the stream enable it sends COUNT + 2 data packets with the
example's data fields, each after a stray byte the session must skip. The test checks the
commands the program sent (set, descriptor, function, the values it wrote), its output (one
`device`, one `setting` line, one line per data field of the first COUNT packets, each naming
the parameters it prints, `name=value`, `name: value` or `"name":value`) and its exit
status; then that a NACK ends it with status 1 and a message, that bad usage exits 2, and that
the source marks the parts the documentation quotes.
"""

from __future__ import annotations

import json
import re
import subprocess
from pathlib import Path

import pytest

from generator.examples import SESSION_PARTS, device_variant, session_example
from generator.spec import load_spec
from generator.targets import TARGETS
from tests.conformance.fake_device import FakeDevice
from tests.helpers.generated import python_package

ROOT = Path(__file__).resolve().parents[2]
IR = load_spec()
PROTOCOLS = {p["name"]: p for p in IR["protocols"] if session_example(p) is not None}
EXTENSIONS = {name: TARGETS[name].EXTENSION for name in TARGETS}  # the target registry
COUNT = 3


def _have(lang: str, protocol: str) -> bool:
    pkg = PROTOCOLS[protocol]["package"]
    return (ROOT / "generated" / lang / pkg / "examples" / f"configure_and_stream.{EXTENSIONS[lang]}").is_file()


CASES = [(lang, name) for lang in EXTENSIONS for name in PROTOCOLS if _have(lang, name)]


def run_example(lang: str, protocol: str, *args: str, timeout: float = 120) -> subprocess.CompletedProcess:
    script = '. "$1"; select_protocol --protocol "$2"; shift 2; exec "$@"'
    return subprocess.run(
        ["bash", "-c", script, "configure", str(ROOT / "tests/conformance/protocol.sh"), protocol]
        + [str(ROOT / "tests/lang" / f"{lang}.sh"), "configure", *args],
        capture_output=True,
        text=True,
        timeout=timeout,
    )


def _steps(protocol: dict) -> list[tuple[dict, str | None]]:
    """(step, function name or None) of every command the example sends, in order."""
    ex = session_example(protocol)
    assert ex is not None
    fn = {step: ("write" if ex[step]["field"]["functions"] else None) for step in ("format", "enable")}
    return [
        (ex["ping"], None),
        (ex["info"], None),
        (ex["setting"], "write"),
        (ex["setting"], "read"),
        (ex["format"], fn["format"]),
        (ex["enable"], fn["enable"]),
    ]


def _reply_ids(variant: dict, fn: str | None) -> list[int]:
    """The reply field the spec sends with the ack of the function (none: an empty list)."""
    ids = []
    for r in variant["responses"]:
        w = r["when"] or {}
        if "function" in w and w["function"] != fn:
            continue
        if "param" in w:
            continue
        ids.append(r["id"])
    return ids[:1]


def script(protocol: dict, nack_at: int | None = None) -> tuple[dict, list[tuple[dict, str | None]]]:
    """The fake device's case: each command answered (a NACK for step `nack_at`), then data."""
    pkg = python_package(protocol["package"])
    code_ok = protocol["session"]
    steps: list[dict] = []
    at = 0
    plan = _steps(protocol)
    ack_cls = pkg.registry.lookup(plan[0][0]["set"]["id"], code_ok["ack"])[0]
    for k, (st, fn) in enumerate(plan):
        at += 1
        steps.append({"send": "-", "at": at, "bytes": None})
        set_id = st["set"]["id"]
        b = pkg.PacketBuilder(set_id)
        ack = ack_cls(**{code_ok["echo"]: st["field"]["id"]})
        if k == nack_at:
            setattr(ack, code_ok["code"], 3)
            b.add(ack)
        else:
            b.add(ack)
            for rid in _reply_ids(st["variant"], fn):
                b.add(pkg.registry.lookup(set_id, rid)[0]())
        steps.append({"receive": b.build().hex(), "at": at})
        if k == nack_at:
            break
    if nack_at is None:
        ex = session_example(protocol)
        data = pkg.PacketBuilder(ex["data"]["set"]["id"])
        for f in ex["data"]["fields"]:
            data.add(pkg.registry.lookup(ex["data"]["set"]["id"], f["id"])[0]())
        steps.append({"receive": ("00" + data.build().hex()) * (COUNT + 2), "at": at + 1})
    return {"steps": steps, "expect": []}, plan


def _sent(protocol: dict, packets: list[bytes]) -> list[dict]:
    pkg = python_package(protocol["package"])
    device = session_example(protocol)["device"]
    return [json.loads(pkg.decode_packet(p, 0, device).line()) for p in packets]


@pytest.mark.parametrize("lang,protocol", CASES, ids=[f"{a}-{b}" for a, b in CASES])
def test_configure_and_stream(lang, protocol):
    proto = PROTOCOLS[protocol]
    case, plan = script(proto)
    framing = proto["framing"]
    built = run_example(lang, protocol, timeout=1800)  # builds the program: the fake device waits 30 s
    assert built.returncode == 2 and "usage" in built.stderr, built.stderr
    dev = FakeDevice(case, framing).start()
    r = run_example(lang, protocol, f"tcp:127.0.0.1:{dev.port}", str(COUNT))
    dev.join(30)
    assert r.returncode == 0, r.stderr
    assert dev.errors == []
    sent = _sent(proto, dev.received)
    selector = proto["function_selector"]
    enum = next((t for t in proto["types"] if selector and t["name"] == selector["enum"]), None)
    fn_values = {v["name"]: v["value"] for v in enum["values"]} if enum else {}
    assert [(p["set"], p["fields"][0]["descriptor"]) for p in sent] == [
        (st["set"]["id"], st["field"]["id"]) for st, _fn in plan
    ]
    for p, (st, fn) in zip(sent, plan):
        values = p["fields"][0]["values"]
        if fn is not None and fn_values:
            assert values.get("function") == fn_values[fn], (st["field"]["name"], values)
        if fn in (None, "write"):
            for k, v in st["values"].items():
                assert values[k] == v, (st["field"]["name"], k, values)
    lines = r.stdout.splitlines()
    ex = session_example(proto)
    assert lines[0].startswith("device ") and lines[1].startswith("setting ")
    names = [f["name"] for f in ex["data"]["fields"]]
    assert [ln.split()[0] for ln in lines[2:]] == names * COUNT, r.stdout
    # Every parameter of the setting's reply and of each data field is printed with its name
    # (name=value; Rust's Debug: name: value; C++'s JSON: "name":value).
    setting = ex["setting"]
    rid = _reply_ids(setting["variant"], "read")[0]
    reply = next(f for f in setting["set"]["fields"] if f["id"] == rid)
    for q in device_variant(proto, reply, ex["device"])["params"]:
        assert re.search(rf"\b{q['name']}\"?\s*[=:]", lines[1]), (q["name"], lines[1])
    fields = {f["name"]: device_variant(proto, f, ex["device"]) for f in ex["data"]["fields"]}
    for ln in lines[2:]:
        for q in fields[ln.split()[0]]["params"]:
            assert re.search(rf"\b{q['name']}\"?\s*[=:]", ln), (q["name"], ln)


@pytest.mark.parametrize("lang,protocol", CASES, ids=[f"{a}-{b}" for a, b in CASES])
def test_configure_and_stream_nack_and_usage(lang, protocol):
    proto = PROTOCOLS[protocol]
    case, plan = script(proto, nack_at=2)  # the setting write is refused by the device
    dev = FakeDevice(case, proto["framing"]).start()
    r = run_example(lang, protocol, f"tcp:127.0.0.1:{dev.port}")
    dev.join(30)
    assert r.returncode == 1
    assert "nack" in r.stderr.lower() and plan[2][0]["field"]["name"] in r.stderr, r.stderr
    assert "Traceback" not in r.stderr
    r = run_example(lang, protocol)
    assert r.returncode == 2 and "usage" in r.stderr
    r = run_example(lang, protocol, "tcp:127.0.0.1:1")
    assert r.returncode == 1 and "Traceback" not in r.stderr and r.stderr.strip()
    r = run_example(lang, protocol, "tcp:127.0.0.1:1", "many")
    assert r.returncode == 2 and "usage" in r.stderr


@pytest.mark.parametrize("lang,protocol", CASES, ids=[f"{a}-{b}" for a, b in CASES])
def test_configure_example_marks_its_parts(lang, protocol):
    """Each part the documentation cuts (generator/examples.py SESSION_PARTS) opens once with a
    `[part]` comment line and is closed by an `[end]` line before the next part opens."""
    pkg = PROTOCOLS[protocol]["package"]
    text = (ROOT / "generated" / lang / pkg / "examples" / f"configure_and_stream.{EXTENSIONS[lang]}").read_text()
    comments = [ln.split()[-1] for ln in text.splitlines() if ln.strip()[:2] in ("//", "# ")]
    marks = [m for m in comments if m in [f"[{part}]" for part in SESSION_PARTS + ("end",)]]
    assert sorted(marks[0::2]) == sorted(f"[{part}]" for part in SESSION_PARTS), marks
    assert marks[1::2] == ["[end]"] * len(SESSION_PARTS), marks
