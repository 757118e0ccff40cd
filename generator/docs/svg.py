"""SVG drawings for the reference documentation: packet diagrams and bit diagrams.

Pure functions from plain data (segments, bitfield members) to SVG text; what goes into a
diagram is decided by generator/docs/model.py. Output is deterministic: fixed geometry, no
fonts measured, no random ids.
"""

from __future__ import annotations

from dataclasses import dataclass
from xml.sax.saxutils import escape

# Colours by segment kind; the legend below each packet diagram repeats them.
FILL = {
    "sync": "#e5e7eb",
    "header": "#d1d5db",
    "field_header": "#bfdbfe",
    "selector": "#ddd6fe",
    "param": "#dcfce7",
    "param_alt": "#fef9c3",
    "variable": "#ffffff",
    "checksum": "#fed7aa",
}
LEGEND = [
    ("sync", "sync"),
    ("header", "packet header"),
    ("field_header", "field header"),
    ("selector", "function selector"),
    ("param", "parameters"),
    ("variable", "variable length"),
    ("checksum", "checksum"),
]

FONT = 'font-family="DejaVu Sans Mono, Menlo, Consolas, monospace"'
CHAR_W = 6.1  # width of one character at font-size 10 (monospace), used to fit labels


@dataclass(frozen=True)
class Segment:
    """One box run in a packet diagram. size: bytes drawn; variable: dashed, size is a placeholder."""

    label: str
    size: int
    kind: str
    tooltip: str
    variable: bool = False


def _fit(label: str, width: float) -> list[str]:
    """One or two lines of text that fit in width pixels (split at '_', else truncated with an ellipsis)."""
    room = max(1, int((width - 4) // CHAR_W))
    if len(label) <= room:
        return [label]
    for sep in (" ", "_"):
        cut = label.rfind(sep, 0, room + 1)
        if cut > 0:
            first, rest = label[: cut + (sep == "_")].rstrip(), label[cut + 1 :]
            if len(rest) <= room:
                return [first, rest]
            return [first, rest[: room - 1] + "…"] if room > 1 else [first, "…"]
    return [label[: room - 1] + "…"] if room > 1 else ["…"]


def _text(x: float, y: float, lines: list[str], size: int = 10, bold: bool = False) -> str:
    weight = ' font-weight="bold"' if bold else ""
    if len(lines) == 1:
        return (
            f'<text x="{x:g}" y="{y + 3.5:g}" font-size="{size}" text-anchor="middle"{weight}>{escape(lines[0])}</text>'
        )
    return "".join(
        f'<text x="{x:g}" y="{y - 2.5 + 11 * i:g}" font-size="{size}" text-anchor="middle"{weight}>{escape(t)}</text>'
        for i, t in enumerate(lines)
    )


def packet_diagram(segments: list[Segment], title: str, per_row: int = 16) -> str:
    """A byte grid, per_row bytes a row, offsets on the left; segments wrap across rows."""
    cell, row_h, left, top = 56, 40, 56, 34
    width = left + per_row * cell + 8
    # Place segments: (row, col, n, seg, piece_index)
    pieces: list[tuple[int, int, int, Segment, int]] = []
    pos = 0
    fixed_until = None  # byte position after which offsets are not fixed
    for seg in segments:
        n = max(1, seg.size)
        if seg.variable and fixed_until is None:
            fixed_until = pos
        remaining, k = n, 0
        while remaining:
            row, col = divmod(pos, per_row)
            take = min(remaining, per_row - col)
            pieces.append((row, col, take, seg, k))
            pos += take
            remaining -= take
            k += 1
    rows = (pos + per_row - 1) // per_row
    legend_y = top + rows * row_h + 18
    height = legend_y + 22
    out = [
        f'<svg xmlns="http://www.w3.org/2000/svg" width="{width}" height="{height}" viewBox="0 0 {width} {height}" {FONT} role="img">',
        f"<title>{escape(title)}</title>",
        f'<rect x="0" y="0" width="{width}" height="{height}" fill="#ffffff"/>',
    ]
    # Byte numbers across the top.
    for c in range(per_row):
        out.append(
            f'<text x="{left + c * cell + cell / 2:g}" y="{top - 8}" font-size="9" text-anchor="middle" fill="#6b7280">{c}</text>'
        )
    for r in range(rows):
        start = r * per_row
        label = str(start) if fixed_until is None or start <= fixed_until else f"+{start}"
        out.append(
            f'<text x="{left - 8}" y="{top + r * row_h + row_h / 2 + 3.5:g}" font-size="9" text-anchor="end" fill="#6b7280">{label}</text>'
        )
    # The label goes on the widest piece of each segment.
    widest: dict[int, tuple[int, int]] = {}
    for i, (_row, _col, take, seg, _k) in enumerate(pieces):
        key = id(seg)
        if key not in widest or take > widest[key][0]:
            widest[key] = (take, i)
    seen_order: list[int] = []
    for i, (row, col, take, seg, k) in enumerate(pieces):
        x, y, w = left + col * cell, top + row * row_h, take * cell
        dash = ' stroke-dasharray="4 3"' if seg.variable else ""
        fill = FILL.get(seg.kind, "#ffffff") if not seg.variable else FILL["variable"]
        out.append(
            f'<g><title>{escape(seg.tooltip)}</title><rect x="{x}" y="{y}" width="{w}" height="{row_h}" fill="{fill}" stroke="#374151" stroke-width="1"{dash}/>'
        )
        if widest[id(seg)][1] == i:
            out.append(_text(x + w / 2, y + row_h / 2, _fit(seg.label, w)))
        elif k:
            out.append(_text(x + w / 2, y + row_h / 2, ["…"]))
        out.append("</g>")
        if id(seg) not in seen_order:
            seen_order.append(id(seg))
    # Legend of the kinds used.
    used = {("variable" if s.variable else ("param" if s.kind == "param_alt" else s.kind)) for _, _, _, s, _ in pieces}
    x = left
    for kind, text in LEGEND:
        if kind not in used:
            continue
        dash = ' stroke-dasharray="4 3"' if kind == "variable" else ""
        out.append(
            f'<rect x="{x}" y="{legend_y - 9}" width="12" height="12" fill="{FILL[kind]}" stroke="#374151"{dash}/>'
        )
        out.append(f'<text x="{x + 16}" y="{legend_y + 1}" font-size="10">{escape(text)}</text>')
        x += 16 + int(len(text) * CHAR_W) + 18
    out.append("</svg>")
    return "\n".join(out) + "\n"


def bit_diagram(bits: int, members: list[dict], title: str) -> str:
    """Bits MSB first, 16 a row. members: [{name, first_bit, last_bit, reserved}]."""
    per_row = min(bits, 16)
    cell, row_h, left, top = 736 // per_row, 40, 8, 22
    width = left + per_row * cell + 8
    rows = bits // per_row
    height = top + rows * (row_h + 18) + 4
    out = [
        f'<svg xmlns="http://www.w3.org/2000/svg" width="{width}" height="{height}" viewBox="0 0 {width} {height}" {FONT} role="img">',
        f"<title>{escape(title)}</title>",
        f'<rect x="0" y="0" width="{width}" height="{height}" fill="#ffffff"/>',
        '<defs><pattern id="hatch" width="6" height="6" patternUnits="userSpaceOnUse" patternTransform="rotate(45)">'
        '<rect width="6" height="6" fill="#f3f4f6"/><line x1="0" y1="0" x2="0" y2="6" stroke="#9ca3af" stroke-width="2"/></pattern></defs>',
    ]
    owner: dict[int, dict] = {}
    # Aliases (a name for several bits that have names of their own) are listed in the table only.
    for m in sorted(members, key=lambda m: bool(m.get("alias"))):
        for b in range(m["first_bit"], m["last_bit"] + 1):
            owner.setdefault(b, m)
    for r in range(rows):
        hi = bits - 1 - r * per_row
        y = top + r * (row_h + 18)
        for c in range(per_row):
            b = hi - c
            out.append(
                f'<text x="{left + c * cell + cell / 2:g}" y="{y - 6}" font-size="9" text-anchor="middle" fill="#6b7280">{b}</text>'
            )
        # Runs of bits with the same owner within this row.
        c = 0
        while c < per_row:
            b = hi - c
            m = owner.get(b)
            n = 1
            while c + n < per_row and owner.get(hi - c - n) is m:
                n += 1
            x, w = left + c * cell, n * cell
            if m is None:
                fill, label, tip = "#ffffff", "", f"bit {b}: not defined"
            elif m["reserved"]:
                fill, label, tip = "url(#hatch)", m["name"], f"{m['name']} (reserved)"
            else:
                fill, label, tip = "#dcfce7", m["name"], m["name"]
            if m is not None:
                lo_bit, hi_bit = m["first_bit"], m["last_bit"]
                tip += f" (bit {lo_bit})" if lo_bit == hi_bit else f" (bits {hi_bit}..{lo_bit})"
            out.append(
                f'<g><title>{escape(tip)}</title><rect x="{x}" y="{y}" width="{w}" height="{row_h}" fill="{fill}" stroke="#374151"/>'
            )
            if label:
                out.append(_text(x + w / 2, y + row_h / 2, _fit(label, w)))
            out.append("</g>")
            c += n
    out.append("</svg>")
    return "\n".join(out) + "\n"
