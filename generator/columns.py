"""Table columns of the data fields: what a log exporter names each value, with its units.

Language-neutral and computed from the IR alone (a back end renders the result as a table in its
package; the Python package's `export`, `info` and `plot` commands read it). Each data field
layout (every field of a data set, shared fields included, one entry per device variant) becomes a
list of `Column`s, one per value a row holds:

- a scalar number, bool, enum or bitfield is one column named by its parameter path
  (`gps_timestamp.tow`); a parameter named like its field drops the repeat (`scaled_accel`);
- a fixed array is one column per element, named by the components its spec alias gives
  (`vector3f` -> x, y, z; `quatf` -> w, x, y, z; `matrix3f` -> m11 .. m33) or by index (`[0]`);
- a struct is flattened member by member (`satellites[0].prn`);
- what has no fixed shape (counted and remaining arrays, unions, strings) is one `json` column;
- units come from the parameter (`[g]` in the header), enum value names from the enum type.

`time_sources(proto)` says which shared field and parameter give a packet its time in seconds;
`time_facts(proto)` gives the time model's tables (the IR's `time` entry, the spec's `time` section).
"""

from __future__ import annotations

from dataclasses import dataclass

from generator import model
from generator.clock_model import clock_model

# Components of the spec's fixed-array aliases, and the array shape they stand for.
COMPONENTS: dict[str, tuple[str, ...]] = {
    "vector3f": ("x", "y", "z"),
    "vector3d": ("x", "y", "z"),
    "quatf": ("w", "x", "y", "z"),
    "matrix3f": tuple(f"m{r}{c}" for r in (1, 2, 3) for c in (1, 2, 3)),
}
SHAPES: dict[str, tuple[int, ...]] = {"vector3f": (3,), "vector3d": (3,), "quatf": (4,), "matrix3f": (3, 3)}
SIZES: dict[str, int] = {alias: len(names) for alias, names in COMPONENTS.items()}
# Unit -> counts per second, for the time column (the sample rule's timestamp fields): a time is
# value / counts, which a division rounds correctly (282893000000 ns -> 282.893 s).
TIME_UNITS: dict[str, int] = {"ns": 1_000_000_000, "us": 1_000_000, "ms": 1000, "s": 1}


@dataclass(frozen=True)
class Column:
    """One column: header `name` (without units), `path` to the value in the decoded layout
    (parameter names and element indices), `units` (or None), `kind` ("float32", "float64", "int",
    "bool", "enum", "bits", "json") and, for an enum, its type name."""

    name: str
    path: tuple
    units: str | None
    kind: str
    enum: str | None = None
    description: str = ""  # the parameter's description in the spec (whitespace runs as one space)
    frame: str | None = None  # the parameter's coordinate frame (`frame_text`), None when the spec states none


def _leaf_kind(e: model.Elem) -> tuple[str, str | None]:
    if e.kind == "enum":
        return "enum", e.name
    if e.kind == "bitfield":
        return "bits", None
    if e.kind == "primitive":
        if e.name == "bool":
            return "bool", None
        if e.name in ("f32", "f64", "float", "double"):
            return ("float32" if e.size.max == 4 else "float64"), None
        if e.name == "char":
            return "json", None
        return "int", None
    return "json", None


def _param_columns(proto: dict, p: model.Param, name: str, path: tuple, depth: int = 0) -> list[Column]:
    if p.kind in (model.COUNTED, model.REMAINING, model.UNION, model.STRING) or depth > 4:
        return [Column(name, path, p.units, "json", None, _text(p.description), frame_text(p))]
    if p.kind == model.FIXED:
        alias = p.ir.get("alias")
        names = COMPONENTS.get(alias) if alias in COMPONENTS and len(COMPONENTS[alias]) == p.count else None
        out: list[Column] = []
        for i in range(p.count):
            sub = f"{name}.{names[i]}" if names else f"{name}[{i}]"
            out += _elem_columns(proto, p, sub, path + (i,), depth)
        return out
    return _elem_columns(proto, p, name, path, depth)


def _elem_columns(proto: dict, p: model.Param, name: str, path: tuple, depth: int) -> list[Column]:
    e = p.elem
    if e.kind == "struct":
        struct = next(t for t in proto["types"] if t["name"] == e.name)
        out: list[Column] = []
        for q in model.struct(proto, struct):
            out += _param_columns(proto, q, f"{name}.{q.name}", path + (q.name,), depth + 1)
        return out
    kind, enum = _leaf_kind(e)
    return [Column(name, path, p.units, kind, enum, _text(p.description), frame_text(p))]


def frame_text(p: model.Param) -> str | None:
    """The parameter's `frame` as one text: the frame name, or `device: name` per device joined
    by `; ` when the manuals state a different frame per device (`gx5_45: sensor; cv7_ins: vehicle`)."""
    frame = p.ir.get("frame")
    if isinstance(frame, dict):
        return "; ".join(f"{d}: {f}" for d, f in frame.items())
    return frame


def _text(description: str) -> str:
    return " ".join(description.split())


def layout_columns(proto: dict, field: dict, variant: dict) -> list[Column]:
    """The columns of one data field layout (a variant of `field`)."""
    out: list[Column] = []
    plist = model.layout(proto, variant)
    for p in plist:
        if p.function:
            continue
        name = field["name"] if p.name == field["name"] else f"{field['name']}.{p.name}"
        out += _param_columns(proto, p, name, (p.name,))
    return out


def data_layouts(proto: dict):
    """(set id, field, variant) of every data field layout of `proto` (data sets and shared set)."""
    for s in proto["sets"]:
        if s["kind"] != "data":
            continue
        for f in s["fields"]:
            if f["role"] != "data":
                continue
            for v in f["variants"]:
                yield s, f, v


def enums(proto: dict) -> dict[str, dict[int, str]]:
    """Enum type name -> {value: name} (the first name of a value several devices name)."""
    out: dict[str, dict[int, str]] = {}
    for t in proto["types"]:
        if t["kind"] == "enum":
            names: dict[int, str] = {}
            for v in t["values"]:
                names.setdefault(v["value"], v["name"])
            out[t["name"]] = names
    return out


def time_sources(proto: dict) -> list[tuple[int, int, str, int]]:
    """(set, descriptor, parameter, counts per second) of the timestamp fields of the sample rule,
    monotonic device clocks (integer counts of ns, us, ms) before time of week in seconds."""
    rule = {t["descriptor"] for t in proto["samples"]["timestamps"]}
    shared = proto["shared_data"]["set"] if proto.get("shared_data") else None
    found = []
    for s in proto["sets"]:
        if s["id"] != shared:
            continue
        for f in s["fields"]:
            if f["id"] not in rule:
                continue
            for q in f["variants"][0]["params"]:
                if q.get("units") in TIME_UNITS and q["count"] is None and q["type"]["kind"] == "primitive":
                    found.append((s["id"], f["id"], q["name"], TIME_UNITS[q["units"]]))
                    break
    found.sort(key=lambda t: (t[3] == 1, t[1]))
    return found


def time_facts(proto: dict, attr=lambda name: name) -> dict:
    """The IR's `time` entry as the time model's tables: per kind (`gps_time`, `device_clock`,
    `leap_seconds`, `reference_time`, `external`, `sync_health`) a list of dicts with the set and descriptor as hex text, masks as hex text, and
    parameter names through `attr` (a back end's attribute naming); `clock_model` the host clock
    model's parameters (generator/clock_model.py); `gps_scale` the GPS time scale (the IR's
    `time.gps_scale`: `epoch_unix_s`, `leap_seconds` rows)."""
    t = proto.get("time") or {}
    out: dict = {}
    for kind in ("gps_time", "device_clock", "leap_seconds"):
        rows = []
        for e in t.get(kind, []):
            row = {"set": f"0x{e['set']:02X}", "descriptor": f"0x{e['descriptor']:02X}"}
            for key in ("tow", "week", "valid_flags", "param"):
                if key in e:
                    row[key] = attr(e[key])
            for key in ("mask", "inverted"):
                if key in e:
                    row[key] = f"0x{e[key]:04X}"
            if "per_second" in e:
                row["per_second"] = e["per_second"]
            rows.append(row)
        out[kind] = rows
    out["reference_time"] = [
        {
            "device": e["device"],
            "set": f"0x{e['set']:02X}",
            "descriptor": f"0x{e['descriptor']:02X}",
            "kind": e["kind"],
            "param": attr(e["param"]) if "param" in e else "",
            "per_second": e.get("per_second", 0),
            "tow": attr(e["tow"]) if "tow" in e else "",
            "week": attr(e["week"]) if "week" in e else "",
            "monotonic": e["monotonic"],
        }
        for e in t.get("reference_time", [])
    ]
    out["external"] = [
        {
            "set": f"0x{e['set']:02X}",
            "descriptor": f"0x{e['descriptor']:02X}",
            "param": attr(e["param"]),
            "per_second": e["per_second"],
            "valid_flags": attr(e["valid_flags"]),
            "mask": f"0x{e['mask']:04X}",
        }
        for e in t.get("external", [])
    ]
    out["sync_health"] = [
        {
            "set": f"0x{e['set']:02X}",
            "descriptor": f"0x{e['descriptor']:02X}",
            "attr": attr(e["param"] if e["kind"] == "bool" else e["valid_flags"]),
            "mask": f"0x{e.get('mask', 0):04X}",
        }
        for e in t.get("sync_health", [])
    ]
    out["clock_model"] = clock_model(proto)
    out["gps_scale"] = t["gps_scale"]  # the GPS epoch and GPS - UTC (generator/gps_scale.py)
    return out
