"""Load the language-neutral session corpus (tests/sessions/<protocol>/*.yaml): scripted exchanges
between a command session and a device (docs/conformance.md section 8).

Each case lists timed steps -- commands the session sends (`send`: one command field, written as
in a golden vector) and bytes the device sends (`receive`: hex) -- and the exact lines the
session must report (`expect`): command results, packets that are not replies, skip runs. This
module checks every case against the IR (commands exist and are commands, values fit, reply fields
decode as written) and against its own bytes: the reply packets (the `offset` of a result), the
printed packets and the skip runs must cover the received stream exactly, in order, with valid
sync bytes and checksums. It returns the cases with every line rendered canonically, so each
language's runner only compares text.
"""

from __future__ import annotations

import json
from pathlib import Path

from .corpus import CorpusFile, fletcher16, json_str, packet_line, resolve_field
from .diagnostics import SpecError, SpecErrors
from .passes.context import SpecFile
from .yamlpos import load

RESULTS = ("ack", "nack", "timeout", "invalid", "sent", "refused")
CASE_KEYS = {"name", "description", "device", "timeout_ms", "inter_packet_timeout_ms", "live", "steps", "expect"}
DEFAULT_TIMEOUT_MS = 1000
DEFAULT_INTER_PACKET_TIMEOUT_MS = 100


def load_sessions(ir: dict, sessions_dir: Path, root: Path | None = None) -> list[dict]:
    """The cases of sessions_dir/<protocol>/*.yaml, checked; raises SpecErrors listing every problem."""
    protos = {p["name"]: p for p in ir["protocols"]}
    root = root or sessions_dir.parent.parent
    errors: list[SpecError] = []
    cases: list[dict] = []
    names: dict[str, str] = {}
    if not sessions_dir.is_dir():
        return []
    for proto_dir in sorted(p for p in sessions_dir.iterdir() if p.is_dir()):
        proto = protos.get(proto_dir.name)
        for path in sorted(proto_dir.glob("*.yaml")):
            rel = str(path.relative_to(root))
            try:
                data, locate = load(str(path), rel)
            except SpecError as e:
                errors.append(e)
                continue
            sf = SpecFile(rel, data, locate)
            if proto is None:
                errors.append(SpecError(locate(()), f"no protocol '{proto_dir.name}' in spec/", "a protocol directory"))
                continue
            ctx = CorpusFile(sf, proto)
            if not isinstance(data, dict) or not isinstance(data.get("cases"), list) or set(data) != {"cases"}:
                ctx.err((), "a session file is a mapping with only a 'cases' list", "cases: [...]")
                errors.extend(ctx.errors)
                continue
            for i, c in enumerate(data["cases"]):
                case = _case(ctx, ("cases", i), c)
                if case is None:
                    continue
                case["file"] = rel
                case["protocol"] = proto["name"]
                key = f"{proto['name']}/{case['name']}"
                if key in names:
                    ctx.err(("cases", i, "name"), f"case '{case['name']}' is also in {names[key]}", "unique names")
                names[key] = rel
                cases.append(case)
            errors.extend(ctx.errors)
    if errors:
        raise SpecErrors(errors)
    return cases


def _int(ctx: CorpusFile, path: tuple, v, lo: int, hi: int, what: str) -> bool:
    if isinstance(v, bool) or not isinstance(v, int) or not lo <= v <= hi:
        ctx.err(path, f"{what} must be an integer {lo}..{hi}", f"{lo}..{hi}")
        return False
    return True


def _hex(ctx: CorpusFile, path: tuple, v) -> bytes | None:
    if not isinstance(v, str):
        ctx.err(path, "expected hex bytes as a string", '"7565 0102 ..."')
        return None
    try:
        return bytes.fromhex(v.replace(" ", "").replace("\n", ""))
    except ValueError:
        ctx.err(path, "not hex bytes", "pairs of hex digits, spaces allowed")
        return None


def _case(ctx: CorpusFile, path: tuple, c) -> dict | None:
    if not isinstance(c, dict):
        ctx.err(path, "a case is a mapping", "name, steps, expect")
        return None
    bad = sorted(set(c) - CASE_KEYS)
    if bad:
        ctx.err(path + (bad[0],), f"unknown key '{bad[0]}'", ", ".join(sorted(CASE_KEYS)))
    for k in ("name", "steps", "expect"):
        if k not in c:
            ctx.err(path, f"case without '{k}'", k)
            return None
    name = c["name"]
    device = c.get("device")
    if device is not None and device not in [d["id"] for d in ctx.proto["devices"]]:
        ctx.err(path + ("device",), f"unknown device '{device}'", ", ".join(d["id"] for d in ctx.proto["devices"]))
    timeout = c.get("timeout_ms", DEFAULT_TIMEOUT_MS)
    inter = c.get("inter_packet_timeout_ms", DEFAULT_INTER_PACKET_TIMEOUT_MS)
    _int(ctx, path + ("timeout_ms",), timeout, 0, 600000, "timeout_ms")
    _int(ctx, path + ("inter_packet_timeout_ms",), inter, 0, 600000, "inter_packet_timeout_ms")
    steps, sends, stream = [], [], b""
    last_at = 0
    for k, s in enumerate(c["steps"] or []):
        sp = path + ("steps", k)
        if not isinstance(s, dict) or "at" not in s or len({"send", "receive"} & set(s)) != 1:
            ctx.err(
                sp, "a step has 'at' and one of 'send' or 'receive'", "{at: 0, send: {...}} or {at: 5, receive: hex}"
            )
            continue
        extra = set(s) - {"at", "send", "receive", "bytes"}
        if extra or ("bytes" in s and "send" not in s):
            ctx.err(sp, f"unknown step keys {sorted(extra) or ['bytes']}", "at, send (with bytes), receive")
        at = s["at"]
        if _int(ctx, sp + ("at",), at, 0, 10**9, "at") and at < last_at:
            ctx.err(sp + ("at",), f"step time {at} is before the previous step's {last_at}", "non-decreasing times")
        last_at = at if isinstance(at, int) else last_at
        if "receive" in s:
            data = _hex(ctx, sp + ("receive",), s["receive"])
            if data is not None:
                steps.append({"at": at, "receive": data.hex()})
                stream += data
            continue
        line = _send_line(ctx, sp + ("send",), s["send"])
        sent = _hex(ctx, sp + ("bytes",), s["bytes"]) if "bytes" in s else None
        sends.append({"set": (s["send"] or {}).get("set"), "path": sp})
        steps.append({"at": at, "send": line, "bytes": sent.hex() if sent is not None else None})
    expect, tiles, seen = [], [], {}
    for k, e in enumerate(c["expect"] or []):
        ep = path + ("expect", k)
        if not isinstance(e, dict):
            ctx.err(
                ep,
                "an expected line is a mapping",
                "{line: 1, result: ack, ...}, {packet: ...} or {skipped: hex, offset: N}",
            )
            continue
        if "packet" in e:
            p = e["packet"]
            expect.append(packet_line(ctx, ep + ("packet",), p, device))
            tiles.append(json.loads(expect[-1]))
        elif "skipped" in e:
            data = _hex(ctx, ep + ("skipped",), e["skipped"])
            if data is not None and _int(ctx, ep + ("offset",), e.get("offset"), 0, 10**9, "offset"):
                expect.append('{"offset":%d,"skipped":"%s"}' % (e["offset"], data.hex()))
                tiles.append(json.loads(expect[-1]))
        else:
            text = _result(ctx, ep, e, sends, device, seen)
            if text is not None:
                expect.append(text)
                if e.get("offset") is not None and (not tiles or tiles[-1].get("reply") != e["offset"]):
                    tiles.append({"offset": e["offset"], "reply": e["offset"], "set": e.get("_set")})
    for n in range(1, len(sends) + 1):
        if n not in seen:
            ctx.err(path + ("expect",), f"case '{name}': no result for send {n}", "one result per send step")
    _check_tiling(ctx, path, name, stream, tiles)
    return {
        "name": name,
        "description": c.get("description", ""),
        "device": device,
        "timeout_ms": timeout,
        "inter_packet_timeout_ms": inter,
        "live": c.get("live", True),
        "steps": steps,
        "expect": expect,
    }


def _send_line(ctx: CorpusFile, path: tuple, s) -> str:
    if not isinstance(s, dict) or set(s) - {"set", "descriptor", "name", "values", "device"} or "set" not in s:
        ctx.err(path, "a send is {set, descriptor, name, values}", "one command field")
        return ""
    hit = resolve_field(ctx.proto, s["set"], s.get("descriptor"))
    if hit is None or hit[1]["role"] != "command":
        ctx.err(
            path + ("descriptor",), f"no command 0x{s.get('descriptor', 0):02X} in set 0x{s['set']:02X}", "a command"
        )
        return ""
    field = {k: v for k, v in s.items() if k != "set"}
    return packet_line(ctx, path, {"offset": 0, "set": s["set"], "fields": [field]}, s.get("device"))


def _result(ctx: CorpusFile, path: tuple, e: dict, sends: list, device: str | None, seen: dict) -> str | None:
    extra = set(e) - {"line", "result", "code", "reply", "error", "offset"}
    if extra:
        ctx.err(path, f"unknown keys {sorted(extra)} in a result", "line, result, code, reply, error, offset")
    n, result = e.get("line"), e.get("result")
    if not _int(ctx, path + ("line",), n, 1, max(1, len(sends)), "line (a send step's number)"):
        return None
    if result not in RESULTS:
        ctx.err(path + ("result",), f"unknown result {result!r}", ", ".join(RESULTS))
        return None
    if n in seen:
        ctx.err(path + ("line",), f"a second result for send {n}", "one result per send")
    seen[n] = result
    code = e.get("code")
    answered = result in ("ack", "nack", "invalid")
    if answered:
        rule = ctx.proto["session"]
        if _int(ctx, path + ("code",), code, 0, 255, "code"):
            if (result == "nack") != (code != rule["ok"]):
                ctx.err(path + ("code",), f"a {result} with code {code}", "code 0 for ack/invalid, non-zero for nack")
        if e.get("offset") is None:
            ctx.err(path, f"a {result} needs the offset of the reply packet", "offset: N")
    elif code is not None or e.get("reply") or e.get("offset") is not None:
        ctx.err(path, f"a {result} result has no code, reply or offset", "code: null (or nothing)")
    if (result in ("invalid", "refused")) != ("error" in e):
        ctx.err(path, f"error goes with invalid and refused results only (here: {result})", "error: message")
    set_id = sends[n - 1]["set"]
    e["_set"] = set_id
    reply = packet_line(ctx, path + ("reply",), {"offset": 0, "set": set_id, "fields": e.get("reply") or []}, device)
    fields = reply[reply.index('"fields":[') + len('"fields":[') : -2]
    text = '{"line":%d,"result":"%s","code":%s,"reply":[%s]' % (n, result, "null" if code is None else code, fields)
    if "error" in e:
        text += ',"error":' + json_str(e["error"])
    return text + "}"


def _check_tiling(ctx: CorpusFile, path: tuple, name: str, raw: bytes, tiles: list[dict]) -> None:
    """Reply packets, printed packets and skip runs must cover the received bytes exactly, in order."""
    fr = ctx.proto["framing"]
    sync = bytes(fr["sync"])
    pos = 0

    def bad(msg: str) -> None:
        ctx.err(path, f"case '{name}': {msg}", "events that cover the received bytes exactly, in order")

    for ev in tiles:
        off = ev["offset"]
        if off != pos:
            return bad(f"an event starts at offset {off}, but the previous one ends at {pos}")
        if "skipped" in ev:
            got = bytes.fromhex(ev["skipped"])
            if raw[off : off + len(got)] != got:
                return bad(
                    f"skipped bytes at offset {off} are not the received ones ({raw[off : off + len(got)].hex()})"
                )
            pos += len(got)
            continue
        head = raw[off : off + fr["header_size"]]
        if len(head) < fr["header_size"] or not head.startswith(sync):
            return bad(f"no packet header at offset {off}")
        if ev.get("set") is not None and head[fr["set_offset"]] != ev["set"]:
            return bad(f"the packet at offset {off} is of set {head[fr['set_offset']]}, not {ev['set']}")
        end = off + fr["header_size"] + head[fr["length_offset"]] + fr["checksum_size"]
        body = raw[off : end - fr["checksum_size"]]
        if end > len(raw) or fletcher16(body) != raw[end - fr["checksum_size"] : end]:
            return bad(f"the packet at offset {off} is truncated or its checksum is wrong")
        pos = end
    if pos != len(raw):
        bad(f"the events end at offset {pos}, the received bytes at {len(raw)}")
