"""The IR's `link` entry (generator/passes/link.py) as the back ends print it: language-neutral
records, each fact with the manual lines it comes from (`lines`: "3dm-gx5-45-dcp.txt:363, ..."),
so the four packages' constants say the same thing in the same words."""

from __future__ import annotations


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
    }


def bandwidth_sources(proto: dict) -> str:
    """The manual lines of the spec's `link: bandwidth` (the UART bandwidth calculation), for the
    device command lines' messages."""
    bw = (proto.get("link") or {}).get("bandwidth") or {}
    return ", ".join(f"{x['manual']} line {x['line']}" for x in bw.get("sources", []) if "line" in x)
