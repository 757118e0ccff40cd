"""The IR's `link` entry (generator/passes/link.py) as the back ends print it: language-neutral
records, each fact with the manual lines it comes from (`lines`: "3dm-gx5-45-dcp.txt:363, ..."),
so the four packages' constants say the same thing in the same words."""

from __future__ import annotations

from . import model


def lines(sources: list[dict]) -> str:
    """ "manual:line, manual:line" of a sources list ("" for none)."""
    return ", ".join(f"{s['manual']}:{s['line']}" if s.get("line") else s["manual"] for s in sources or [])


def link_facts(proto: dict) -> dict:
    """What every package prints from the IR's `link`: the commands (set, descriptor, name,
    lines; None where the spec names none), the idle attempts, the settle time (None: the manual
    states none), the bandwidth calculation (None: none) and per device of the protocol, in its
    order, the baud rates (ascending, empty when the manual lists none) and default (None: none)."""
    link = proto.get("link") or {}

    def command(role: str) -> dict | None:
        c = link.get(role)
        if not c:
            return None
        return {"command": c["command"], "set": c["set"], "descriptor": c["descriptor"], "lines": lines(c["sources"])}

    settle = link.get("baud_settle")
    bandwidth = link.get("bandwidth")
    attempts = link.get("idle_attempts") or {"count": 3, "sources": []}
    rates = {e["device"]: e for e in link.get("baud_rates") or []}
    devices = []
    for d in proto["devices"]:
        e = rates.get(d["id"])
        devices.append(
            {
                "id": d["id"],
                "rates": list(e["rates"]) if e else [],
                "default": e["default"] if e else None,
                "port": (e or {}).get("port"),
                "lines": lines(e["sources"]) if e else "",
            }
        )
    return {
        "idle": command("idle"),
        "ping": command("ping"),
        "resume": command("resume"),
        "idle_attempts": attempts["count"],
        "idle_attempts_lines": lines(attempts["sources"]),
        "baud_settle_ms": settle["ms"] if settle else None,
        "baud_settle_lines": lines(settle["sources"]) if settle else "",
        "bandwidth": (
            {
                "uart_word_bits": bandwidth["uart_word_bits"],
                "packet_overhead": bandwidth["packet_overhead"],
                "field_overhead": bandwidth["field_overhead"],
                "lines": lines(bandwidth["sources"]),
            }
            if bandwidth
            else None
        ),
        "devices": devices,
        "identity": identity_facts(proto),
    }


def plain_name(text: str) -> str:
    """A model name as the wrong-model check compares it: upper case, without spaces and
    punctuation; a character outside ASCII is kept (it matches no model name of the spec)."""
    return "".join(c for c in text.upper() if (c.isascii() and c.isalnum()) or not c.isascii())


def identity_facts(proto: dict) -> dict | None:
    """What a session needs to say "connected device is NAME, this session was told ID" (issue
    39; Python's Device.model_mismatch): the identity command (the command answered by the reply
    of the spec's first `simulation.identity` report, as the device command lines read it), the
    byte offset and length of the model name (item `model_name`, a fixed-length string) in that
    reply's data, the NACK codes of a command the device does not know (`simulation.nack`
    unknown_descriptor and unknown_set) and per device of the protocol, in its order, the names
    it answers to (its title and its identity model name, each as `plain_name` spells it). None
    when the spec gives no such identity."""
    sim = proto.get("simulation") or {}
    ident = sim.get("identity") or {}
    reports = ident.get("reports") or []
    if not reports:
        return None
    first = reports[0]
    at = (first["set"], first["descriptor"])
    report = next((r for r in reports if (r["set"], r["descriptor"]) == at and r["item"] == "model_name"), None)
    if report is None:
        return None
    sets = {s["id"]: s for s in proto["sets"]}
    reply = next(f for f in sets[at[0]]["fields"] if f["id"] == at[1])
    command = next(
        (
            f
            for f in sets[at[0]]["fields"]
            if f["role"] == "command" and any(x["id"] == at[1] for v in f["variants"] for x in v["responses"])
        ),
        None,
    )
    if command is None or model.per_device(reply):
        return None
    types = {t["name"]: t for t in proto["types"]}
    params, offset, param = reply["variants"][0]["params"], 0, None
    for name in report["param"].split("."):
        param = next(q for q in params if q["name"] == name)
        if param.get("offset") is None:
            return None  # after a parameter of variable size: not at a fixed place
        offset += param["offset"]
        t = param["type"]
        params = types[t["name"]]["params"] if t["kind"] == "struct" else []
    assert param is not None and param["type"]["kind"] == "string", report
    codes = types[(proto.get("session") or {}).get("code_enum")]["values"]
    value = {v["name"]: int(v["value"]) for v in codes}
    nack = sim.get("nack") or {}
    unknown = sorted({value[nack[k]] for k in ("unknown_descriptor", "unknown_set") if nack.get(k) in value})
    models = {d["device"]: str(d["values"].get("model_name", "")) for d in ident.get("devices") or []}
    devices = []
    for d in proto["devices"]:
        names = [n for n in (d["title"], models.get(d["id"], "")) if n]
        plain = []
        for n in names:
            if not n.isascii():
                raise ValueError(f"device {d['id']}: model name {n!r} is not ASCII")
            if plain_name(n) and plain_name(n) not in plain:
                plain.append(plain_name(n))
        devices.append({"id": d["id"], "names": names, "plain": plain})
    return {
        "command": {"name": command["name"], "set": at[0], "descriptor": command["id"]},
        "reply": {"name": reply["name"], "set": at[0], "descriptor": at[1]},
        "model_offset": offset,
        "model_length": param["type"]["length"],
        "unknown_codes": unknown,
        "devices": devices,
    }


def bandwidth_sources(proto: dict) -> str:
    """The manual lines of the spec's `link: bandwidth` (the UART bandwidth calculation), for the
    device command lines' messages."""
    bw = (proto.get("link") or {}).get("bandwidth") or {}
    return ", ".join(f"{x['manual']} line {x['line']}" for x in bw.get("sources", []) if "line" in x)
