"""Pass: the protocol file's `link` section, what a session needs to get through to a device
(docs/spec-format.md "Link"; docs/conformance.md section 8 "Getting through"), exported as the
protocol's `link` entry (every key present, null where the manual states nothing).

- `idle`, `ping`, `resume`: a command of the protocol without parameters (the session sends it as
  it is), each resolved to its `set` and `descriptor`;
- `idle_attempts`: how many times a session sends the idle command before it gives up (3 when
  not given);
- `baud_settle`: the milliseconds after a baud-rate change before the device answers at the new
  rate;
- `baud_rates`: per device of the protocol (each once), the rates of its main port, ascending
  and distinct, and its default (one of them, or null when the manual states none);
- `bandwidth`: the manuals' UART bandwidth calculation, bits per UART word, bytes of packet
  overhead (checked: the sync, header and checksum sizes of the framing) and bytes per field
  header (checked: the framing's field header size).

Every fact keeps its sources (each manual one of the protocol's).
"""

from __future__ import annotations

from .context import Context

_COMMANDS = ("idle", "ping", "resume")
DEFAULT_IDLE_ATTEMPTS = 3


def run(ctx: Context) -> None:
    spec = ctx.pf.data.get("link") or {}
    out: dict = {}
    for role in _COMMANDS:
        out[role] = _command(ctx, role, spec.get(role))
    attempts = spec.get("idle_attempts")
    out["idle_attempts"] = {
        "count": attempts["count"] if attempts else DEFAULT_IDLE_ATTEMPTS,
        "sources": _sources(ctx, ("idle_attempts",), attempts),
    }
    settle = spec.get("baud_settle")
    out["baud_settle"] = {"ms": settle["ms"], "sources": _sources(ctx, ("baud_settle",), settle)} if settle else None
    out["baud_rates"] = _baud_rates(ctx, spec.get("baud_rates") or [])
    out["bandwidth"] = _bandwidth(ctx, spec.get("bandwidth"))
    ctx.link = out


def _sources(ctx: Context, path: tuple, entry: dict | None) -> list[dict]:
    if not entry:
        return []
    return ctx.check_sources(ctx.pf, ("link",) + path + ("sources",), entry.get("sources") or [])


def _command(ctx: Context, role: str, entry: dict | None) -> dict | None:
    if entry is None:
        return None
    name = entry["command"]
    found = [(s, f) for s in ctx.sets for f in s["fields"] if f["role"] == "command" and f["name"] == name]
    path = ("link", role, "command")
    if not found:
        ctx.err(ctx.pf, path, f"link {role}: '{name}' is not a command of the protocol", "the name of a command field")
        return None
    if len(found) > 1:
        ctx.err(
            ctx.pf, path, f"link {role}: '{name}' names a command in several sets",
            "a command name used in one set only",
        )  # fmt: skip
        return None
    s, f = found[0]
    if any(v["params"] for v in f["variants"]):
        ctx.err(
            ctx.pf, path, f"link {role}: {name} has parameters; a session sends it as it is",
            "a command without parameters",
        )  # fmt: skip
    return {
        "command": name,
        "set": s["id"],
        "descriptor": f["id"],
        "sources": _sources(ctx, (role,), entry),
    }


def _baud_rates(ctx: Context, entries: list[dict]) -> list[dict]:
    out, seen = [], set()
    for i, e in enumerate(entries):
        path = ("link", "baud_rates", i)
        device = e["device"]
        if device not in ctx.device_ids:
            ctx.err(
                ctx.pf,
                path + ("device",),
                f"link baud_rates: '{device}' is not a device of the protocol",
                "a device id",
            )
        elif device in seen:
            ctx.err(ctx.pf, path + ("device",), f"link baud_rates: {device} is listed twice", "one entry per device")
        seen.add(device)
        rates = e["rates"]
        if rates != sorted(set(rates)):
            ctx.err(
                ctx.pf, path + ("rates",), f"link baud_rates: the rates of {device} are not ascending and distinct",
                "the manual's rates, ascending",
            )  # fmt: skip
        default = e.get("default")
        if default is not None and default not in rates:
            ctx.err(
                ctx.pf, path + ("default",), f"link baud_rates: default {default} of {device} is not one of its rates",
                "one of the listed rates, or null",
            )  # fmt: skip
        out.append(
            {
                "device": device,
                "port": e.get("port"),
                "rates": list(rates),
                "default": default,
                "sources": _sources(ctx, ("baud_rates", i), e),
            }
        )
    order = {d: k for k, d in enumerate(ctx.device_ids)}
    return sorted(out, key=lambda e: order.get(e["device"], len(order)))


def _bandwidth(ctx: Context, b: dict | None) -> dict | None:
    if b is None:
        return None
    fr = ctx.framing
    if fr:
        wrapper = fr["header_size"] + fr["checksum_size"]  # the header counts the sync bytes
        if b["packet_overhead"] != wrapper:
            ctx.err(
                ctx.pf, ("link", "bandwidth", "packet_overhead"),
                f"link bandwidth: packet_overhead {b['packet_overhead']} is not the framing's {wrapper} bytes (sync, header, checksum)",
                str(wrapper),
            )  # fmt: skip
        if b["field_overhead"] != fr["field_header_size"]:
            ctx.err(
                ctx.pf, ("link", "bandwidth", "field_overhead"),
                f"link bandwidth: field_overhead {b['field_overhead']} is not the framing's field header size {fr['field_header_size']}",
                str(fr["field_header_size"]),
            )  # fmt: skip
    return {
        "uart_word_bits": b["uart_word_bits"],
        "packet_overhead": b["packet_overhead"],
        "field_overhead": b["field_overhead"],
        "sources": _sources(ctx, ("bandwidth",), b),
    }
