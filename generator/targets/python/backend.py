"""Python back end: one installable, dependency-free package per protocol (Python 3.9+).

generated/python/<package>/
    pyproject.toml, setup.py, MANIFEST.in (what the sdist adds), README.md
    <package>/            the library: the runtime (plain files of generator/targets/python/runtime/,
                          copied), _protocol.py and _protocol.h (the protocol's constants: the runtime's
                          only protocol input), types.py (enums, bitfields, structs, unions), one module
                          per descriptor set, reserved.py (reserved fields such as ack/nack) and
                          registry.py (dispatch tables)
    tests/                golden vectors, typed round trips, the accelerator on every fixed layout
                          (generated; the runtime's own unit tests run in place, runtime/tests/)

All naming and type mapping happens here, with the language's facts as data in facts.py; templates
only loop and print. Layouts are described to the runtime as tuples of operations (`_c.Run`,
`_c.Counted`, `_c.Choice`, ...), so the generated modules read like declarations: each parameter is
classified by the layout model (generator/model.py), named here, and written by
templates/python/layout_macros.j2.
"""

from __future__ import annotations

import textwrap

from generator import columns, commands, mcap_schemas, model, simulation
from generator.examples import example_context, example_literal, session_example, session_example_context
from generator.linkfacts import bandwidth_sources, link_facts
from generator.naming import camel, upper
from generator.primitives import PRIMITIVES
from generator.release import Release, load_release
from generator.render import copy_runtime, environment, runtime_dir
from generator.settings_rows import setting_rows, settings_schema
from generator.targets.python import facts
from generator.testcases import (
    EnumValue,
    Flags,
    Sample,
    StructValue,
    bitfield_cases,
    canonical_literals,
    layout_sample,
    struct_sample,
    vector_cases,
)

OUTPUT_DIRS = ["python"]

# Names the package exports at top level (a set module must not shadow them).
EXPORTED = {name for names in facts.EXPORTS.values() for name in names}
# The runtime: the files of generator/targets/python/runtime/ and its rooms (codec/, session/,
# device/, sim/, logs/; docs/design.md), copied folder by folder into every package, except the
# runtime's own unit tests (tests/), the package tests' plain files (package_tests/) and the
# modules of one protocol (protocols/<protocol name>/, copied only into that protocol's package).
RUNTIME_EXCLUDED = ("tests", "package_tests", "protocols")


def runtime_files(folder: str = "", excluded: tuple[str, ...] = RUNTIME_EXCLUDED) -> list[str]:
    """The runtime's files under `folder` (a path under runtime/), as paths under runtime/, sorted;
    the `excluded` folders of runtime/, hidden files and folders (tool caches) and Python's caches
    left out."""
    root = runtime_dir("python")
    base = root / folder
    if not base.is_dir():
        return []
    return [
        p.relative_to(root).as_posix()
        for p in sorted(base.rglob("*"))
        if p.is_file()
        and "__pycache__" not in p.parts
        and not any(part.startswith(".") for part in p.relative_to(root).parts)  # caches, editor files
        and p.suffix != ".pyc"
        and p.relative_to(root).parts[0] not in excluded
    ]


RUNTIME_FILES = runtime_files()
# The rooms: the runtime's folders with an __init__.py.
RUNTIME_ROOMS = sorted({name.split("/")[0] for name in RUNTIME_FILES if name.endswith("/__init__.py")})
# Plain files of runtime/package_tests/, copied into every package's tests/ directory; the test
# files import the protocol's cases from generated modules beside them (tests/vector_cases.py,
# tests/canonical_cases.py, tests/typed_cases.py).
PACKAGE_TEST_FILES = ["conftest.py", "test_vectors.py", "test_canonical.py", "test_typed.py"]
# Templates of the package directory that do not need a model of their own (the protocol's
# constants, the package's exports).
PACKAGE_TEMPLATES = ["__init__.py", "_protocol.py", "_protocol.h", "_extras.py"]
# Templates of the session layer (docs/conformance.md section 8): the spec facts of every command
# and the typed command API.
SESSION_TEMPLATES = ["_session.py", "command_api.py"]
# Modules of every package; a descriptor set whose name collides gets a "_set" suffix.
# (the top modules and rooms of the runtime, and the module names of the flat runtime before its
# rooms, so that no set module changes its name)
RUNTIME_MODULES = {
    name.split("/")[0].split(".")[0]
    for name in RUNTIME_FILES + PACKAGE_TEMPLATES
    if "/" in name or name.endswith(".py")
} | {
    "canonical",
    "codec",
    "framing",
    "packets",
    "samples",
    "session_tool",
    "sim_world",
    "fleet",
    "query",
    "transport",
    "tools",
    "dataset",
    "timebase",
    "spark",
    "budget",
    "settings",
    "device_cli",
    "_speedups",
    "registry",
    "reserved",
    "types",
    "tests",
    "_session",
    "_sim",
    "_settings",
    "command_api",
    "capabilities",
    "_link",
}

SCALARS = {name: f"_c.{p.scalar}" for name, p in facts.PRIMITIVES.items()}
# Attribute names a parameter / bitfield member must not take (it gets a "_" suffix instead).
LAYOUT_RESERVED = facts.LAYOUT_ATTRIBUTES
BITFIELD_RESERVED = facts.INT_ATTRIBUTES | facts.BITFIELD_ATTRIBUTES


# ------------------------------------------------------------------------------------------ naming
def py_attr(name: str, reserved: frozenset[str] = LAYOUT_RESERVED) -> str:
    """A parameter/member name as a Python attribute (keywords and runtime names get a '_')."""
    if name in facts.KEYWORDS or name in reserved or name in facts.AMBIGUOUS_NAMES:
        return name + "_"
    return name


def const_name(name: str) -> str:
    return upper(name)


def set_module(set_: dict) -> str:
    name = set_["name"]
    if name in RUNTIME_MODULES or name in EXPORTED or name in facts.KEYWORDS:
        return name + "_set"
    return name


def _layout_classes(fields: list[dict]) -> dict[tuple[str, str | None], str]:
    """Class name of every layout of the given fields: (field name, device or None) -> class name."""
    out: dict[tuple[str, str | None], str] = {}
    used: set[str] = set()
    for f, _v, dev in model.layouts_of(fields):
        base = camel(f["name"]) + (f"_{dev}" if dev else "")
        name = base
        if name in used:
            name = f"{base}_0x{f['id']:02X}"
        used.add(name)
        out[(f["name"], dev)] = name
    return out


def api_names(protocol: dict, set_: dict | None, field: dict) -> dict[str, str]:
    """The names a Python user types for a field (used by the documentation back end)."""
    pkg = protocol["package"]
    is_reserved = set_ is None or field.get("role") == "ack" or "applies_to" in field
    module = f"{pkg}.reserved" if is_reserved else f"{pkg}.{set_module(set_)}"
    names = _layout_classes(protocol["reserved_fields"] if is_reserved else set_["fields"])
    multi = model.per_device(field)
    classes = [f"{module}.{names[(field['name'], v['device'] if multi else None)]}" for v in field["variants"]]
    out = {
        "class": classes[0],
        "module": module,
        "decode": f"{classes[0]}.decode(data)",
        "encode": "value.encode()",
        "packet": f"{pkg}.PacketBuilder(set).add(value).build()",
        "json": "value.to_json()",
    }
    if multi:
        out["variants"] = ", ".join(classes)
        for v, c in zip(field["variants"], classes):
            out[f"class_{v['device']}"] = c
    if not is_reserved and field.get("role") == "command" and set_["kind"] == "command":
        # The typed command API (command_api.py.j2): device.<set>.<command>.<function>(...).
        attr = set_module(set_)
        attr = attr + "_set" if attr in DEVICE_ATTRIBUTES else attr
        call = f"device.{attr}.{py_attr(field['name'])}"
        functions = list(dict.fromkeys(fn for v in field["variants"] for fn in v["functions"] or []))
        if len(functions) > 1:
            out["session"] = f"{call}.{{{','.join(py_attr(fn) for fn in functions)}}}(...)"
        else:
            out["session"] = f"{call}.{py_attr(functions[0])}(...)" if functions else f"{call}(...)"
    return out


# ------------------------------------------------------------------------------------------ text
def docstring(*paragraphs: str, indent: int = 4) -> str:
    """A safe triple-quoted docstring body: paragraphs wrapped, backslashes and quotes escaped."""
    parts = []
    for p in paragraphs:
        p = " ".join((p or "").split())
        if p:
            lines = textwrap.wrap(p, 100 - indent, break_long_words=False, break_on_hyphens=False)
            parts.append(("\n" + " " * indent).join(lines))
    text = ("\n\n" + " " * indent).join(parts) or "(no description)"
    text = text.replace("\\", "\\\\").replace('"""', '\\"\\"\\"')
    if text.endswith('"'):
        text += " "
    if "\n" in text:
        text += "\n"
    return text


def comment(text: str) -> str:
    return " ".join((text or "").split())


def decl(code: str, note: str, indent: int = 4) -> list[str]:
    """A declaration with its note: a trailing comment when it fits in 120 columns, else comment lines above."""
    note = comment(note)
    if not note:
        return [code]
    inline = f"{code}  # {note}"
    if indent + len(inline) <= 120:
        return [inline]
    wrapped = textwrap.wrap(note, 116 - indent, break_long_words=False, break_on_hyphens=False)
    return [f"# {line}" for line in wrapped] + [code]


def tuple_literal(items: list[str]) -> str:
    if len(items) == 1:
        return f"({items[0]},)"
    return "(" + ", ".join(items) + ")"


def pyrepr(value) -> str:
    return repr(value)


# ------------------------------------------------------------------------------------------ model
class _Protocol:
    """Everything the templates need for one protocol, with names and types mapped to Python."""

    def __init__(self, proto: dict):
        self.p = proto
        self.package = proto["package"]
        self.types = {t["name"]: t for t in proto["types"]}
        fs = proto.get("function_selector") or {}
        self.function_enum = fs.get("enum")
        self.byte_order = ">" if proto["byte_order"] == "big" else "<"
        # The Python syntax of a parameter's declaration lives in the layout template; field_decl
        # calls its macros because where the comment goes depends on the declaration's length.
        self.syntax = environment().get_template("python/layout_macros.j2").module

    # -------------------------------------------------------------- layouts
    def param(self, p: model.Param, tp: str) -> dict:
        """Names and Python types of one parameter of the layout model (`tp` qualifies the names of
        the spec's types); layout_macros.j2 writes its runtime operation and its declaration."""
        e = p.elem
        if p.function:
            first = p.functions[0]
        elif e.kind == "enum":
            first = self.types[e.name]["values"][0]["name"]
        else:
            first = None
        members = []
        if e.kind == "union":
            members = list(dict.fromkeys(f"{tp}{m.type}" for m in p.members if m.type))
        return {
            "name": p.name,
            "attr": py_attr(p.name),
            "kind": p.kind,
            "array": p.array,
            "optional": p.optional,
            "elem_kind": e.kind,
            "codec": SCALARS[e.name] if e.kind == "primitive" else None,
            "py_kind": PRIMITIVES[e.name][1] if e.kind == "primitive" else None,
            "py_type": facts.PRIMITIVES[e.name].annotation if e.kind == "primitive" else None,
            "cls": f"{tp}{e.name}" if e.named else None,
            "base": e.primitive,
            "length": e.length,
            "padding": e.padding,
            "first_value": const_name(first) if first else None,
            "member_classes": members,
            "count": p.count,
            "max_count": p.max_count,
            "count_param": p.count_param,
            "selector": p.selector,
            # Scalars and fixed arrays of numbers, strings, enums and bitfields: the runtime reads
            # a run of consecutive ones with one struct format (_c.Run).
            "flat": e.kind not in ("struct", "union") and p.kind in (model.SCALAR, model.FIXED, model.STRING),
        }

    def field_decl(self, p: model.Param, view: dict) -> dict:
        """Dataclass field of one parameter: its declaration (from the template) and its note."""
        if p.function:
            et = self.types[self.function_enum]
            notes = [comment(et.get("title", "")) + " (one of: " + ", ".join(p.functions) + ")"]
        else:
            notes = [comment(p.description)]
            if p.units:
                notes.append(f"[{p.units}]")
            if p.optional and p.functions is not None:
                notes.append("(sent for: " + ", ".join(p.functions) + ")")
            if p.kind == model.COUNTED:
                notes.append(f"(count: {p.count_param})")
            elif p.kind == model.REMAINING:
                notes.append("(to the end of the field)")
        syntax = self.syntax
        annotation, default = syntax.annotation(view), syntax.default(view)
        return {
            "attr": view["attr"],
            "name": p.name,
            "annotation": annotation,
            "default": default,
            "lines": decl(syntax.declaration(view), " ".join(n for n in notes if n)),
        }

    def layout(self, params: list[dict], tp: str, function_names: list[str] | None) -> dict:
        plist = model.params(self.p, params, function_names)
        views = [self.param(p, tp) for p in plist]
        fields = [self.field_decl(p, v) for p, v in zip(plist, views)]
        # The runtime operations: runs of consecutive flat required parameters, then one
        # operation per other parameter (layout_macros.j2 `op`).
        ops: list[dict] = []
        for v in views:
            if v["flat"] and not v["optional"]:
                if ops and ops[-1]["run"]:
                    ops[-1]["run"].append(v)
                else:
                    ops.append({"run": [v], "param": None})
            else:
                ops.append({"run": None, "param": v})
        return {
            "fields": fields,
            "ops": ops,
            "uses_types": any(v["cls"] for v in views),
        }

    # -------------------------------------------------------------- types module
    def enum_model(self, t: dict) -> dict:
        values = []
        for v in t["values"]:
            text = comment(v.get("description", ""))
            if v.get("devices"):
                text = (text + " " if text else "") + "(devices: " + ", ".join(v["devices"]) + ")"
            lit = str(v["value"]) if v["value"] < 0 else f"0x{v['value']:02X}"
            values.append({"lines": decl(f"{const_name(v['name'])} = {lit}", text)})
        return {
            "kind": "enum",
            "name": t["name"],
            "doc": docstring(f"{t.get('title', t['name'])} ({t['base']}).", t.get("description", "")),
            "values": values,
        }

    def bitfield_model(self, t: dict) -> dict:
        digits = PRIMITIVES[t["base"]][0] * 2
        members = []
        for m in t["members"]:
            attr = py_attr(m["name"], BITFIELD_RESERVED)
            text = comment(m.get("description", ""))
            flags = []
            if m.get("reserved"):
                flags.append("reserved")
            if m.get("alias"):
                flags.append("alias mask")
            if m.get("devices"):
                flags.append("devices: " + ", ".join(m["devices"]))
            if flags:
                text = (text + " " if text else "") + "(" + "; ".join(flags) + ")"
            bits = f"bit {m['first_bit']}" if m["width"] == 1 else f"bits {m['first_bit']}-{m['last_bit']}"
            members.append(
                {
                    "name": m["name"],
                    "attr": attr,
                    "const": const_name(m["name"]),
                    "first": m["first_bit"],
                    "width": m["width"],
                    "mask": f"0x{m['mask']:0{digits}X}",
                    "prop": f"_c.bit({m['first_bit']})"
                    if m["width"] == 1
                    else f"_c.bits({m['first_bit']}, {m['width']})",
                    "lines": decl(
                        f"{const_name(m['name'])} = 0x{m['mask']:0{digits}X}", f"{bits}: {text}" if text else bits
                    ),
                }
            )
        return {
            "kind": "bitfield",
            "name": t["name"],
            "base": t["base"],
            "doc": docstring(f"{t.get('title', t['name'])} ({t['base']} bitfield).", t.get("description", "")),
            "members": members,
        }

    def struct_model(self, t: dict) -> dict:
        lay = self.layout(t["params"], "", None)
        size = t["size"]
        size_text = f"{size['min']} bytes" if size["fixed"] else f"{size['min']}..{size['max']} bytes"
        return {
            "kind": "struct",
            "name": t["name"],
            "doc": docstring(f"{t.get('title', t['name'])} (struct, {size_text}).", t.get("description", "")),
            "size": size["min"] if size["fixed"] else None,
            **lay,
        }

    def union_model(self, t: dict) -> dict:
        sel = self.types[t["selector_enum"]]
        by_name = {v["name"]: v["value"] for v in sel["values"]}
        members = []
        for m in t["members"]:
            members.append(
                {
                    "value": f"0x{by_name.get(m['when'], m['value']):02X}"
                    if by_name.get(m["when"], m["value"]) >= 0
                    else str(by_name.get(m["when"], m["value"])),
                    "type": m["type"] or "None",
                    "comment": f"{m['when']}"
                    + (f": {comment(m.get('description', ''))}" if m.get("description") else ""),
                }
            )
        return {
            "kind": "union",
            "name": t["name"],
            "selector": t["selector_enum"],
            "doc": docstring(
                f"{t.get('title', t['name'])} (union selected by {t['selector_enum']}).",
                t.get("description", ""),
                "The value of a union parameter is the selected member's struct, or None for a member without data.",
            ),
            "members": members,
        }

    def types_module(self) -> dict:
        models = []
        for t in model.type_order(self.p):
            models.append(getattr(self, f"{t['kind']}_model")(t))
        uses = {"typing": False, "dataclasses": False}
        for m in models:
            if m["kind"] == "struct":
                uses["dataclasses"] = True
                if any("_ty." in f["annotation"] for f in m["fields"]):
                    uses["typing"] = True
        return {"types": models, "uses": uses}

    # -------------------------------------------------------------- field modules
    def field_models(self, fields: list[dict], set_: dict | None) -> list[dict]:
        names = _layout_classes(fields)
        out = []
        for f, v, dev in model.layouts_of(fields):
            cls = names[(f["name"], dev)]
            lay = self.layout(v["params"], "_t.", v["functions"])
            if set_ is not None:
                where = f"set 0x{set_['id']:02X}, descriptor 0x{f['id']:02X}"
            else:
                where = f"descriptor 0x{f['id']:02X} in every {f['applies_to']} set"
            head = f"{f['title']} ({where}, {f['role']})" + (f", device {dev}." if dev else ".")
            extra = []
            if v["functions"]:
                extra.append("Functions: " + ", ".join(v["functions"]) + ".")
            if v.get("responses"):
                extra.append(
                    "Responses: "
                    + ", ".join(f"0x{r['id']:02X} {r.get('name', '')}".strip() for r in v["responses"])
                    + "."
                )
            srcs = v.get("sources") or f.get("sources") or []
            if srcs:
                extra.append(
                    "Sources: "
                    + "; ".join(f"{s['manual']}" + (f" line {s['line']}" if s.get("line") else "") for s in srcs)
                    + "."
                )
            size = v["size"]
            size_text = f"{size['min']}" if size["fixed"] else f"{size['min']}..{size['max']}"
            extra.append(f"Field data: {size_text} bytes.")
            out.append(
                {
                    "cls": cls,
                    "doc": docstring(head, f.get("description", ""), " ".join(extra)),
                    "set": f"0x{set_['id']:02X}" if set_ is not None else "None",
                    "applies_to": repr(f.get("applies_to")) if set_ is None else "None",
                    "descriptor": f"0x{f['id']:02X}",
                    "name": f["name"],
                    "role": f["role"],
                    "device": repr(dev),
                    "field_name": f["name"],
                    "variant": dev,
                    **lay,
                }
            )
        return out

    def module_uses(self, classes: list[dict]) -> dict:
        text = " ".join(" ".join(f["annotation"] + " " + f["default"] for f in c["fields"]) for c in classes)
        return {
            "typing": "_ty." in text,
            "types": "_t." in text or any(c["uses_types"] for c in classes),
            "dataclasses": bool(classes),
        }

    def set_model(self, s: dict) -> dict:
        classes = self.field_models(s["fields"], s)
        return {
            "module": set_module(s),
            "set": s,
            "set_hex": f"0x{s['id']:02X}",
            "doc": docstring(
                f"{s['title']} (descriptor set 0x{s['id']:02X}, {s['kind']}"
                + (", shared data descriptors" if s.get("shared") else "")
                + ").",
                s.get("description", ""),
                indent=0,
            ),
            "classes": classes,
            "fields_tuple": tuple_literal([c["cls"] for c in classes]) if classes else "()",
            "uses": self.module_uses(classes),
        }

    def reserved_model(self) -> dict:
        classes = self.field_models(self.p["reserved_fields"], None)
        return {
            "module": "reserved",
            "doc": docstring(
                "Reserved fields: descriptors reserved in every set of a kind (e.g. ack/nack in command sets).",
                indent=0,
            ),
            "classes": classes,
            "fields_tuple": tuple_literal([c["cls"] for c in classes]) if classes else "()",
            "uses": self.module_uses(classes),
        }

    # -------------------------------------------------------------- registry
    def registry(self, sets: list[dict], reserved: dict) -> dict:
        entries = []
        for sm in sets:
            s = sm["set"]
            by_field: dict[str, list[str]] = {}
            for c in sm["classes"]:
                by_field.setdefault(c["field_name"], []).append(f"{sm['module']}.{c['cls']}")
            for f in s["fields"]:
                entries.append(
                    {
                        "key": f"(0x{s['id']:02X}, 0x{f['id']:02X})",
                        "names": tuple_literal([f'"{c}"' for c in by_field[f["name"]]]),
                    }
                )
        res: dict[str, list[dict]] = {}
        by_field = {}
        for c in reserved["classes"]:
            by_field.setdefault(c["field_name"], []).append(f"reserved.{c['cls']}")
        for r in self.p["reserved_fields"]:
            res.setdefault(r["applies_to"], []).append(
                {"key": f"0x{r['id']:02X}", "names": tuple_literal([f'"{c}"' for c in by_field[r["name"]]])}
            )
        shared = self.p.get("shared_data")
        return {
            "modules": sorted({sm["module"] for sm in sets} | ({"reserved"} if reserved["classes"] else set())),
            "entries": entries,
            "reserved": [{"kind": k, "entries": v} for k, v in res.items()],
            "set_names": [{"id": f"0x{sm['set']['id']:02X}", "name": sm["set"]["name"]} for sm in sets],
            "set_kinds": [
                {"kind": k, "first": f"0x{r['first']:02X}", "last": f"0x{r['last']:02X}"}
                for k, r in self.p["set_kinds"].items()
            ],
            "shared_set": f"0x{shared['set']:02X}" if shared else "None",
            "devices": tuple_literal([f'"{d["id"]}"' for d in self.p["devices"]]),
        }

    # -------------------------------------------------------------- samples (typed round-trip tests)
    def sample_literal(self, value: Sample, tp: str) -> str:
        """A sample value (generator/testcases.py) as a Python expression."""
        if isinstance(value, StructValue):
            return f"{tp}{value.type}(" + self.sample_args(value.args, tp) + ")"
        if isinstance(value, EnumValue):
            return f"{tp}{value.type}.{const_name(value.name)}"
        if isinstance(value, Flags):
            return f"{tp}{value.type}(0x{value.mask:X})"
        if isinstance(value, list):
            return "[" + ", ".join(self.sample_literal(v, tp) for v in value) + "]"
        return repr(value)  # int, float, bool, bytes, None

    def sample_args(self, args: list[tuple[str, Sample]], tp: str) -> str:
        return ", ".join(f"{py_attr(name)}={self.sample_literal(v, tp)}" for name, v in args)

    def samples(self, sets: list[dict]) -> list[dict]:
        out = []
        for sm in sets:
            s = sm["set"]
            names = _layout_classes(s["fields"])
            for f, v, dev in model.layouts_of(s["fields"]):
                cls = f"{sm['module']}.{names[(f['name'], dev)]}"
                args = layout_sample(self.p, s, f, v)
                out.append({"cls": cls, "expr": f"{cls}(" + self.sample_args(args, "types.") + ")"})
        names = _layout_classes(self.p["reserved_fields"])
        for f in self.p["reserved_fields"]:
            cls = f"reserved.{names[(f['name'], None)]}"
            args = layout_sample(self.p, None, f, f["variants"][0])
            out.append({"cls": cls, "expr": f"{cls}(" + self.sample_args(args, "types.") + ")"})
        for t in model.type_order(self.p):
            if t["kind"] == "struct":
                out.append(
                    {"cls": f"types.{t['name']}", "expr": self.sample_literal(struct_sample(self.p, t), "types.")}
                )
        return out

    def bitfield_cases(self) -> list[dict]:
        return [
            {
                "cls": f"types.{b.name}",
                "attr": py_attr(m.name, BITFIELD_RESERVED),
                "const": const_name(m.name),
                "first": m.first_bit,
                "width": m.width,
                "mask": m.mask,
            }
            for b in bitfield_cases(self.p)
            for m in b.members
        ]


# ------------------------------------------------------------------------------------------ render
def _vector_cases(vectors: list[dict], proto: dict) -> list[dict]:
    return [
        {
            "name": c.name,
            "hex": c.hex,
            "device": c.device,
            "rejected": c.rejected,
            "where": c.source,
            "expect": list(c.expect),
        }
        for c in vector_cases(vectors, proto)
    ]


def render(ir: dict, vectors: list[dict], release: Release | None = None, sessions: list[dict] = ()) -> dict[str, str]:
    """sessions: the session corpus, which the Python back end does not render into its package."""
    release = release or load_release()
    env = environment()
    env.filters["pyrepr"] = pyrepr
    files: dict[str, str] = {}
    for proto in ir["protocols"]:
        m = _Protocol(proto)
        pkg = m.package
        root = f"python/{pkg}"
        sets = [m.set_model(s) for s in proto["sets"]]
        reserved = m.reserved_model()
        framing = proto["framing"]
        ctx = {
            "proto": proto,
            "package": pkg,
            "framing": framing,
            "byte_order": m.byte_order,
            "sync": "".join(f"\\x{b:02x}" for b in framing["sync"]),
            "sum1_first": framing["checksum"]["order"][0] == "sum1",
            "sets": sets,
            "reserved": reserved,
            "registry": m.registry(sets, reserved),
            "modules": sorted([sm["module"] for sm in sets] + ["reserved", "types"]),
            "exports": facts.EXPORTS,
            "lazy_exports": facts.LAZY_EXPORTS,
            # submodules the package's __getattr__ imports on first use: the sets, types, reserved
            # and the modules whose names it re-exports lazily (`pkg.session` keeps working)
            "lazy_modules": sorted([sm["module"] for sm in sets] + ["reserved", "types", *facts.LAZY_EXPORTS]),
            # the package and its rooms (pyproject.toml's packages)
            "python_packages": [pkg] + [f"{pkg}.{room}" for room in RUNTIME_ROOMS],
            "devices": [d["id"] for d in proto["devices"]],
            "sample_rule": proto["samples"],
            **extras(pkg),
            **release.stamp(proto),
        }
        files[f"{root}/LICENSE"] = release.license
        files.update(_runtime(proto, root))
        for name in PACKAGE_TEMPLATES:
            # (_protocol.h: beside the accelerator's C sources that #include it, in the codec room)
            where = f"codec/{name}" if name.endswith(".h") else name
            files[f"{root}/{pkg}/{where}"] = env.get_template(f"python/package/{name}.j2").render(**ctx)
        files[f"{root}/{pkg}/types.py"] = env.get_template("python/package/types.py.j2").render(
            **ctx, **m.types_module()
        )
        tmpl = env.get_template("python/package/fields.py.j2")
        for sm in sets:
            files[f"{root}/{pkg}/{sm['module']}.py"] = tmpl.render(**ctx, mod=sm)
        files[f"{root}/{pkg}/reserved.py"] = tmpl.render(**ctx, mod=reserved)
        files[f"{root}/{pkg}/registry.py"] = env.get_template("python/package/registry.py.j2").render(**ctx)
        session = session_context(m, sets)
        for name in SESSION_TEMPLATES:
            files[f"{root}/{pkg}/{name}"] = env.get_template(f"python/package/{name}.j2").render(**ctx, **session)
        files[f"{root}/{pkg}/capabilities.py"] = env.get_template("python/package/capabilities.py.j2").render(
            **ctx, capabilities=_capabilities(proto)
        )
        files[f"{root}/{pkg}/_link.py"] = env.get_template("python/package/_link.py.j2").render(
            **ctx, link_facts=link_facts(proto)
        )
        sim_ctx = _sim_context(m, sets)
        files[f"{root}/{pkg}/_sim.py"] = env.get_template("python/package/_sim.py.j2").render(**ctx, **sim_ctx)
        files[f"{root}/{pkg}/_identity.py"] = env.get_template("python/package/_identity.py.j2").render(
            **ctx,
            identity_reports=sim_ctx["identity_reports"],
            identity=sim_ctx["identity"],
            identity_modules=sorted({c["cls"].split(".")[0] for c in sim_ctx["identity_reports"]}),
        )
        settings = _settings_context(m, sets)
        files[f"{root}/{pkg}/_settings.py"] = env.get_template("python/package/_settings.py.j2").render(
            **ctx, **settings
        )
        files[f"{root}/{pkg}/settings.schema.json"] = settings["schema"]
        files[f"{root}/{pkg}/_columns.py"] = env.get_template("python/package/_columns.py.j2").render(
            **ctx, **_columns_context(proto)
        )
        files[f"{root}/{pkg}/_mcap_schemas.py"] = env.get_template("python/package/_mcap_schemas.py.j2").render(
            **ctx, mcap_schemas=mcap_schemas.schemas(proto, py_attr)
        )
        files[f"{root}/pyproject.toml"] = env.get_template("python/pyproject.toml.j2").render(**ctx)
        files[f"{root}/setup.py"] = env.get_template("python/setup.py.j2").render(**ctx)
        files[f"{root}/MANIFEST.in"] = env.get_template("python/MANIFEST.in.j2").render(**ctx)
        files[f"{root}/README.md"] = env.get_template("python/README.md.j2").render(**ctx, **session)
        files[f"{root}/examples/getting_started.py"] = env.get_template("python/examples/getting_started.py.j2").render(
            **ctx, example=_example(proto)
        )
        configure = _configure_example(proto, session)
        if configure is not None:
            files[f"{root}/examples/{configure['program']}.py"] = env.get_template(
                "python/examples/configure_and_stream.py.j2"
            ).render(**ctx, example=configure)
        tests = {
            "vector_cases.py": {"cases": _vector_cases(vectors, proto)},
            "typed_cases.py": _typed_context(m, sets),
            "canonical_cases.py": {"canonical": canonical_literals(repr)},
            "test_runtime.py": {},
        }
        for name, extra in tests.items():
            files[f"{root}/tests/{name}"] = env.get_template(f"python/tests/{name}.j2").render(**ctx, **extra)
    return files


def extras(package: str) -> dict:
    """The optional extras (facts.EXTRAS) for pyproject.toml and the runtime's _extras.py:
    `extras` [{name, note, requires}] (`all` last, the union of the others' requirements),
    `extra_home` (import name -> the first extra listing it), `extra_distributions` (import name ->
    what pip installs)."""
    rows = []
    every: list[str] = []
    for name, (note, modules) in facts.EXTRAS.items():
        libs = [facts.LIBRARIES[m] for m in modules]
        rows.append(
            {
                "name": name,
                "note": note.format(package=package),
                "requires": [f"{x.distribution}>={x.minimum}" for x in libs],
            }
        )
        every += [m for m in modules if m not in every]
    rows.append(
        {
            "name": "all",
            "note": "every extra above",
            "requires": [f"{facts.LIBRARIES[m].distribution}>={facts.LIBRARIES[m].minimum}" for m in every],
        }
    )
    home: dict[str, str] = {}
    for name, (_note, modules) in facts.EXTRAS.items():
        for m in modules:
            home.setdefault(m, name)
    return {
        "extras": rows,
        "extra_home": home,
        "extra_distributions": {m: lib.distribution for m, lib in facts.LIBRARIES.items()},
    }


def _capabilities(proto: dict) -> list[dict]:
    """The IR's per-device capabilities with each device's title and manual (capabilities.py)."""
    devices = {d["id"]: d for d in proto["devices"]}
    return [{**devices[c["device"]], **c, "id": c["device"]} for c in proto["capabilities"]["devices"]]


def _columns_context(proto: dict) -> dict:
    """The export table of `_columns.py` (generator/columns.py), with paths as Python attributes."""
    layouts = []
    for s, f, v in columns.data_layouts(proto):
        cols = []
        for c in columns.layout_columns(proto, f, v):
            path = tuple(x if isinstance(x, int) else py_attr(x) for x in c.path)
            cols.append(
                {"name": c.name, "path": pyrepr(path), "units": pyrepr(c.units), "kind": c.kind, "enum": pyrepr(c.enum)}
            )
        shapes = {
            py_attr(q["name"]): columns.SHAPES[q["alias"]]
            for q in v["params"]
            if q.get("alias") in columns.SHAPES and q["count"] and q["count"].get("value") == columns.SIZES[q["alias"]]
        }
        key = f"(0x{s['id']:02X}, 0x{f['id']:02X}, {pyrepr(v['device'])})"
        descriptions = tuple(c.description for c in columns.layout_columns(proto, f, v))
        frames = tuple(c.frame for c in columns.layout_columns(proto, f, v))
        layouts.append(
            {
                "key": key,
                "columns": cols,
                "shapes": pyrepr(shapes),
                "title": f["title"],
                "descriptions": pyrepr(descriptions),
                "frames": pyrepr(frames) if any(frames) else None,
            }
        )
    used = {c["enum"] for lay in layouts for c in lay["columns"] if c["kind"] == "enum"}
    enums = [
        {"name": name, "values": sorted(values.items())}
        for name, values in sorted(columns.enums(proto).items())
        if pyrepr(name) in used
    ]
    return {
        "layouts": layouts,
        "enums": enums,
        "times": [
            {"set": f"0x{t[0]:02X}", "descriptor": f"0x{t[1]:02X}", "attr": py_attr(t[2]), "per_second": t[3]}
            for t in columns.time_sources(proto)
        ],
        "time_facts": columns.time_facts(proto, py_attr),
    }


def _runtime(proto: dict, dest: str) -> dict[str, str]:
    """The runtime files of the package in `dest` (generated/python/<package>), and the plain files
    of its tests/. Their code takes what it needs of the protocol from the generated _protocol.py /
    _protocol.h; only their docstrings and comments name the package, with these placeholders (each
    replaced in every file that has it)."""
    placeholders = [
        ("<package>", proto["package"]),
        ("<PACKAGE>", proto["package"].upper()),
        ("<protocol title>", proto["title"]),
    ]
    mapping = {name: f"{dest}/{proto['package']}/{name}" for name in RUNTIME_FILES}
    # the modules of this protocol only (e.g. the MIP package's fleet simulation): at the package's top
    own = f"protocols/{proto['name']}"
    mapping.update(
        {name: f"{dest}/{proto['package']}/{name[len(own) + 1 :]}" for name in runtime_files(own, excluded=())}
    )
    mapping.update({f"package_tests/{name}": f"{dest}/tests/{name}" for name in PACKAGE_TEST_FILES})
    # grisu3.h, #included by _speedups.c: the C runtime's file (one source for the C JSON printer
    # and the accelerator's), copied verbatim.
    grisu = copy_runtime("c", {"src/grisu3.h": f"{dest}/{proto['package']}/codec/grisu3.h"})
    return {**copy_runtime("python", mapping, placeholders), **grisu}


def _example(proto: dict) -> dict:
    """The getting-started example (generator/examples.py), with its class split for the import."""
    example = example_context(proto, api_names)
    example["module"], example["class_name"] = example["api"]["class"].rsplit(".", 1)
    return example


def _configure_example(proto: dict, session: dict) -> dict | None:
    """The configure-and-stream example (generator/examples.py session_example): per step the
    call of the typed command API (command_api.py) and its literal arguments as
    examples.example_literal records (lists of them for arrays) with Python's names, which
    configure_and_stream.py.j2 `literal` spells."""
    ex = session_example(proto)
    if ex is None:
        return None
    types = {t["name"]: t for t in proto["types"]}
    methods = session["methods"]

    def literal(tref: dict, v) -> dict:
        if isinstance(v, list):
            return {"kind": "list", "elems": [literal(tref, x) for x in v]}
        return example_literal(
            types, tref, v, "Python", lambda k, n: {"field": py_attr, "member": const_name}.get(k, str)(n)
        )

    def call(step: str, fn: str | None) -> dict:
        st = ex[step]
        c = st["calls"][fn]
        params = {q["name"]: q for q in st["variant"]["params"]}
        given = st["values"] if fn in (None, "write") else {}
        return {
            **methods[c],
            "args": [{"attr": py_attr(k), "value": literal(params[k]["type"], v)} for k, v in given.items()],
        }

    return {
        **session_example_context(ex, call),
        "device": ex["device"],
        "data_fields": [
            {"descriptor": f["id"], "name": f["name"], "handler": f"on_{py_attr(f['name'])}"}
            for f in ex["data"]["fields"]
        ],
    }


def _typed_context(m: _Protocol, sets: list[dict]) -> dict:
    samples = m.samples(sets)
    bitfields = m.bitfield_cases()
    used = {s["cls"].split(".")[0] for s in samples} | ({"types"} if bitfields else set())
    text = " ".join(s["expr"] for s in samples)
    used |= {mod for mod in ("types",) if f"{mod}." in text}
    return {"samples": samples, "bitfields": bitfields, "sample_modules": sorted(used)}


# ------------------------------------------------------------------------------------------ session
# Attributes of session.Device a command set must not shadow (it gets a "_set" suffix instead).
DEVICE_ATTRIBUTES = {"transport", "session", "device", "run", "call", "pump", "listen", "close", "now_ms"}
DEVICE_ATTRIBUTES |= {"on_packet", "on_field", "on_sample", "on_event"}


def session_context(m: _Protocol, sets: list[dict]) -> dict:
    """What _session.py.j2 (the spec facts of every command layout) and command_api.py.j2 (the typed
    command API) print: the command model of generator/commands.py with Python's names (classes,
    attributes, methods, annotations); the templates spell the rows and calls."""
    cm = commands.commands(m.p)
    module = {sm["set"]["id"]: sm["module"] for sm in sets}
    sets_by_id = {s["id"]: s for s in m.p["sets"]}
    classes = {s["id"]: _layout_classes(s["fields"]) for s in m.p["sets"] if s["kind"] == "command"}
    fields = {(s["id"], f["name"]): f for s in m.p["sets"] for f in s["fields"]}

    def cls(set_id: int, field: str, device: str | None) -> str:
        multi = model.per_device(fields[(set_id, field)])
        return f"{module[set_id]}.{classes[set_id][(field, device if multi else None)]}"

    rows: list[dict] = []
    for lay in cm.layouts:
        entry = {"layout": lay, "cls": cls(lay.set, lay.field, lay.device), "attr": {q: py_attr(q) for q in lay.reads}}
        if rows and (rows[-1]["set"], rows[-1]["descriptor"]) == (lay.set, lay.descriptor):
            rows[-1]["layouts"].append(entry)
        else:
            rows.append({"set": lay.set, "descriptor": lay.descriptor, "layouts": [entry]})
    methods: dict[commands.Call, dict] = {}
    api_sets: list[dict] = []
    for g in cm.api_sets():
        s = sets_by_id[g.set]
        attr = set_module(s)
        attr += "_set" if attr in DEVICE_ATTRIBUTES else ""
        api_sets.append(
            {"set": g.set, "attr": attr, "cls": camel(s["name"]) + "Commands", "title": s["title"], "commands": []}
        )
        for cmd in g.commands:
            f = fields[(g.set, cmd.field)]
            cattr = py_attr(cmd.field)
            ms = [_method(m, f, c, cls) for c in cmd.calls]
            api_sets[-1]["commands"].append(
                {
                    "descriptor": cmd.descriptor,
                    "attr": cattr,
                    "cls": camel(cmd.field),
                    "title": f["title"],
                    "methods": ms,
                }
            )
            methods.update(
                {c: {"set_attr": attr, "command_attr": cattr, "method": x["name"]} for c, x in zip(cmd.calls, ms)}
            )
    return {
        "session_example": _session_example(api_sets),
        "session_rule": m.p["session"],
        "code_enum": m.p["session"]["code_enum"] if m.p["session"] else None,
        "functions": cm.functions,
        "command_rows": rows,
        "api_sets": api_sets,
        "methods": methods,
        "set_modules": sorted({sm["module"] for sm in sets if sm["set"]["kind"] == "command" and sm["classes"]}),
    }


def _method(m: _Protocol, f: dict, c: commands.Call, cls) -> dict:
    """One method of the typed API (a call of generator/commands.py): its name, argument
    annotations, the classes it builds and what it returns."""
    name = "__call__" if c.function is None else py_attr(c.function)
    if c.device is not None:
        name = f"{name}_{c.device}" if c.function is not None else f"call_{c.device}"
    v = f["variants"][c.variants[0]]
    decls = {d["name"]: d for d in m.layout(v["params"], "_t.", v["functions"])["fields"]}
    args = []
    for a in c.arguments:
        ann = decls[a.name]["annotation"]
        if a.required and ann.startswith("_ty.Optional[") and ann.endswith("]"):
            ann = ann[len("_ty.Optional[") : -1]
        args.append({"attr": decls[a.name]["attr"], "annotation": ann, "required": a.required})
    if c.reply_kind == commands.NO_REPLY:
        returns = "None"
    elif c.reply_kind == commands.ANY or c.reply.per_device:
        returns = "_ty.Any"
    else:
        returns = cls(c.set, c.reply.name, None)
    devices = [d for d in c.devices if d is not None]
    return {
        "name": name,
        "fn_const": f"_t.{m.function_enum}.{const_name(c.function)}" if c.function is not None else None,
        "cls": cls(c.set, c.field, c.devices[0]),
        "choose": [{"device": d, "cls": cls(c.set, c.field, d)} for d in devices] if model.per_device(f) else None,
        "args": args,
        "counts": [{"attr": py_attr(k.param), "array": py_attr(k.array)} for k in c.counts],
        "returns": returns,
        "doc": (f"Function {c.function}" if c.function else "Send the command")
        + (f" (layout for {', '.join(devices)})" if c.device is not None else "")
        + (": returns the reply field." if returns != "None" else "; raises on a NACK, timeout or refusal."),
    }


def _session_example(api_sets: list[dict]) -> dict | None:
    """The call the README's session snippet makes: the first without arguments that returns a
    reply field, else the first without arguments."""
    calls = [
        {"set_attr": s["attr"], "command_attr": c["attr"], "method": m["name"], "returns": m["returns"] != "None"}
        for s in api_sets
        for c in s["commands"]
        for m in c["methods"]
        if not m["args"]
    ]
    return next((c for c in calls if c["returns"]), calls[0] if calls else None)


# -------------------------------------------------------------------------------------- simulator
# The simulated device (runtime sim.py, issue 21) answers from the IR: which parameters a function
# sends, which are enums, the reply fields and their `when`, and the protocol's `simulation` entry
# (spec protocol file, generator/passes/simulation.py: the ack code of each refusal, the streaming
# commands, base rates, the navigation filter per device), with names resolved to values by
# generator/simulation.py. Here they are only named and put in the shapes the runtime's tables
# take (_sim.py): a set is a number, or the parameter that carries it, or a list of alternatives,
# each a parameter or (parameter, {selector value: set}).
def _streaming(sim: dict | None) -> dict:
    if sim is None:
        return {}

    def where(e: dict):
        return e["set"] if "set" in e else e["set_param"]

    def enable_sets(e: dict):
        if "selector" not in e:
            return where(e)
        alternatives: list = [(e["selector"]["param"], {p["value"]: p["set"] for p in e["selector"]["sets"]})]
        return alternatives + ([e["set_param"]] if "set_param" in e else [])

    return {
        "formats": {
            e["command"]: (where(e), e["list"], e.get("descriptor"), e.get("decimation")) for e in sim["formats"]
        },
        "enables": {e["command"]: (enable_sets(e), e["flag"]) for e in sim["enables"]},
        "rates": {e["command"]: where(e) for e in sim["rates"]},
        "polls": {e["command"]: (where(e), e["list"]) for e in sim["polls"]},
        "base_rates": {e["device"]: {r["set"]: r["hz"] for r in e["rates"]} for e in sim["base_rates"]},
        "decimation": (sim["decimation"]["command"], sim["decimation"]["param"]) if sim["decimation"] else None,
        "all_settings": list(sim["all_settings"]),
        "unaddressed": {e["device"]: list(e["sets"]) for e in sim["unaddressed"]},
        "baud": {e["command"]: e["param"] for e in sim["baud"]},
    }


def _action(a: dict) -> tuple:
    """The _sim.ACTIONS entry of one world action of the spec (simulation.actions; sim.py _act)."""
    if a["action"] == "aid":
        return ("aid", a["kind"], tuple(a["enabled_by_values"]), tuple(a["values"]))
    return (a["action"],) + tuple(a[k] for k in ("param", "flag") if k in a)


def _sim_context(m: _Protocol, sets: list[dict]) -> dict:
    """What _sim.py.j2 prints: per command layout class the parameters each function sends and the
    enum parameters; per data layout class the units of its parameters; the streaming table."""
    proto = m.p
    commands = []
    data = []
    world: list[dict] = []
    defaults = []
    by_name: dict[str, list[str]] = {}
    groups = (proto["simulation"] or {}).get("world", [])
    shown = {(s, f): shows for g in groups for s in g["sets"] for f, shows in g["fields"].items()}
    for sm in sets:
        s = sm["set"]
        names = _layout_classes(s["fields"])
        for f, v, dev in model.layouts_of(s["fields"]):
            cls = f"{sm['module']}.{names[(f['name'], dev)]}"
            if f["role"] == "command":
                by_name.setdefault(f["name"], []).append(cls)
                facts_ = simulation.command_facts(proto, v, py_attr)
                commands.append(
                    {
                        "cls": cls,
                        "sends": pyrepr(facts_["sends"]),
                        "enums": pyrepr(facts_["enums"]),
                        "ignored": pyrepr(facts_["ignored"]) if facts_["ignored"] else None,
                    }
                )
                for dev, factory in facts_["factory"].items():  # as its manual states them
                    defaults.append({"device": dev, "cls": cls, "value": pyrepr(_records(factory, v, proto))})
            elif s["kind"] == "data" or f["role"] == "data":
                units = tuple(
                    (py_attr(q["name"]), q.get("units"), (q["count"] or {}).get("value"))
                    for q in v["params"]
                    if q["type"]["kind"] == "primitive"
                )
                data.append({"cls": cls, "units": pyrepr(units)})
                shows = shown.get((s["name"], f["name"]), {})
                mapped = tuple((py_attr(q["name"]), shows[q["name"]]) for q in v["params"] if q["name"] in shows)
                if mapped:
                    world.append({"cls": cls, "value": pyrepr(mapped)})
    streaming = _streaming(proto["simulation"])

    def classes(table: dict) -> list[dict]:
        return [{"cls": c, "value": pyrepr(value)} for name, value in table.items() for c in by_name.get(name, [])]

    return {
        "nack": simulation.nack_codes(proto),
        "sim_commands": commands,
        "factory": {
            d["id"]: [c for c in defaults if c["device"] == d["id"]]
            for d in proto["devices"]
            if any(c["device"] == d["id"] for c in defaults)
        },
        "sim_data": data,
        "sim_world": world,
        "sim_filter": pyrepr(simulation.filters(proto, py_attr)),
        "formats": classes(streaming.get("formats", {})),
        "enables": classes(streaming.get("enables", {})),
        "rates": classes(streaming.get("rates", {})),
        "polls": classes(streaming.get("polls", {})),
        "base_rates": pyrepr(streaming.get("base_rates", {})),
        "decimation": [
            {"cls": c, "value": pyrepr(streaming["decimation"][1])}
            for c in by_name.get((streaming.get("decimation") or ("",))[0], [])
        ],
        "all_settings": [c for n in streaming.get("all_settings", []) for c in by_name.get(n, [])],
        "unaddressed": pyrepr(streaming.get("unaddressed", {})),
        "baud": classes(streaming.get("baud", {})),
        "actions": [
            {"cls": c, "value": pyrepr(_action(a))}
            for a in (proto["simulation"] or {}).get("actions", [])
            for c in by_name.get(a["command"], [])
        ],
        "device_titles": pyrepr({d["id"]: d["title"] for d in proto["devices"]}),
        "nmea": pyrepr(simulation.nmea(proto, py_attr)),
        "nmea_commands": classes(simulation.nmea_commands(proto, py_attr)),
        "time_sync": pyrepr(_time_sync(proto)),
        "sim_modules": sorted(
            {sm["module"] for sm in sets if sm["classes"]} | ({"types"} if "types." in str(defaults) else set())
        ),
        **_sim_identity(proto, sets),
    }


def _time_sync(proto: dict) -> dict:
    """The spec's `time.sync` per device (sim/clocks.py, device/timesync.py), names as attributes."""
    out = {}
    for e in (proto.get("time") or {}).get("sync", []):
        d = {k: v for k, v in e.items() if k not in ("device", "notes", "sources")}
        u = dict(d["update"], selector=py_attr(d["update"]["selector"]), value=py_attr(d["update"]["value"]))
        d["update"] = u
        if "pps_source" in d:
            d["pps_source"] = dict(d["pps_source"], param=py_attr(d["pps_source"]["param"]))
        if "status" in d:
            st = d["status"]
            d["status"] = dict(st, synced=py_attr(st["synced"]), last_pps=py_attr(st["last_pps"]))
        d["external"] = [
            {k: (py_attr(v) if k in ("flags", "tow", "week", "ns") else v) for k, v in x.items()} for x in d["external"]
        ]
        if "correlation" in d:
            d["correlation"] = dict(d["correlation"], flags=py_attr(d["correlation"]["flags"]))
        out[e["device"]] = d
    return out


class _Code(str):
    """Python source text printed as it is by pyrepr (a struct record's constructor)."""

    def __repr__(self) -> str:
        return str(self)


def _records(factory: dict, v: dict, proto: dict) -> dict:
    """A command's factory values with struct records (a counted struct list's default, IR dicts)
    written as constructors of the package's types module (`types.Name(member=value, ...)`)."""
    structs = {py_attr(q["name"]): q["type"]["name"] for q in v["params"] if q["type"]["kind"] == "struct"}
    types_by_name = {t["name"]: t for t in proto["types"]}

    def member(struct: str, key: str, x: object) -> str:
        # A bitfield member is written as its type's constructor (the struct's annotation is the
        # bitfield class, not int: mypy --strict).
        q = next((q for q in types_by_name[struct]["params"] if q["name"] == key), None)
        if q is not None and q["type"]["kind"] == "bitfield":
            return f"types.{camel(q['type']['name'])}({x!r})"
        return repr(x)

    out = dict(factory)
    for attr, name in structs.items():
        if isinstance(out.get(attr), list):
            out[attr] = [
                _Code(f"types.{name}(" + ", ".join(f"{py_attr(k)}={member(name, k, x)}" for k, x in r.items()) + ")")
                for r in out[attr]
            ]
    return out


def _sim_identity(proto: dict, sets: list[dict]) -> dict:
    """The descriptor lists and the identity of the spec's simulation section, by reply class."""
    sim = proto["simulation"] or {}
    classes: dict[tuple[int, int], str] = {}
    for sm in sets:
        names = _layout_classes(sm["set"]["fields"])
        for f in sm["set"]["fields"]:
            if not model.per_device(f):
                classes[(sm["set"]["id"], f["id"])] = f"{sm['module']}.{names[(f['name'], None)]}"
    struct_types = {t["name"]: t for t in proto["types"]}
    lists = []
    dl = sim.get("descriptor_lists")
    for i, entry in enumerate((dl or {}).get("lists", [])):
        item = None if entry["item"] == "u16" else f"types.{camel(entry['item'])}"
        if item is not None and entry["item"] not in struct_types:
            item = None
        cls = classes[(entry["set"], entry["reply_descriptor"])]
        lists.append({"cls": cls, "value": pyrepr((i, entry["capacity"], py_attr(entry["param"]))), "item": item})
    reports: dict[str, list] = {}
    ident = sim.get("identity") or {"reports": [], "devices": [], "items": {}}
    for r in ident["reports"]:
        t = r["type"]  # the reported parameter's type (the simulation pass)
        fmt = (t["length"], " " if t["padding"] == "space" else "\x00", t["justify"]) if t["kind"] == "string" else None
        path = tuple(py_attr(n) for n in r["param"].split("."))
        reports.setdefault(classes[(r["set"], r["descriptor"])], []).append((path, r["item"], fmt))
    status = []
    for e in sim.get("status", []):  # the device status replies (sim/status.py): roles by attribute
        roles = {
            "timer": tuple(py_attr(n) for n in e.get("timer", [])),
            "power": tuple(py_attr(n) for n in e.get("power", [])),
            "streams": {py_attr(n): s for n, s in e.get("streams", {}).items()},
            "bytes": {k: py_attr(n) for k, n in e.get("bytes", {}).items()},
            "pps": {k: py_attr(n) for k, n in e.get("pps", {}).items()},
            "messages": tuple(
                (m["set"], py_attr(m["count"]), py_attr(m["last"]), bool(m.get("while_fix")))
                for m in e.get("messages", [])
            ),
        }
        status.append({"cls": classes[(e["set"], e["descriptor"])], "value": pyrepr(roles)})
    return {
        "status": status,
        "descriptor_lists": lists,
        "descriptor_contents": pyrepr(tuple((dl or {}).get("contents", []))),
        "identity_reports": [{"cls": c, "value": pyrepr(tuple(v))} for c, v in reports.items()],
        "identity": pyrepr({d["device"]: d["values"] for d in ident["devices"]}),
        "identity_items": pyrepr({k: (v["kind"], v["max"]) for k, v in ident["items"].items()}),
    }


def public_name(protocol: dict, kind: str, *path) -> str:
    """The Python name of a set (`kind` "set") or enum value (kind "value": enum type, value), for
    `mipgen diff` (generator/wirediff.py public_names, which names fields and members itself)."""
    if kind == "set":
        return f"{protocol['package']}.{set_module(path[0])}"
    return f"{protocol['package']}.{path[0]['name']}.{const_name(path[1]['name'])}"


# --------------------------------------------------------------------------- settings files
def _settings_context(m: _Protocol, sets: list[dict]) -> dict:
    """What _settings.py.j2 and settings.schema.json hold: per device its settings (command name,
    class, response class, the attributes a file entry holds with their units, the count
    attributes set from lists, the key combinations read), per device the largest size of every
    data field with its header (the link budget, runtime budget.py), and the file's JSON Schema."""
    proto = m.p
    rows: dict[str, list[str]] = {d["id"]: [] for d in proto["devices"]}
    modules = set()
    by_set = {sm["set"]["id"]: sm for sm in sets}
    found, sizes = setting_rows(proto, [sm["set"] for sm in sets])
    for r in found:
        sm = by_set[r["set"]["id"]]
        f, v, rf = r["field"], r["variant"], r["reply_field"]
        names = _layout_classes(sm["set"]["fields"])
        keyed = r["keyed"]
        attrs = tuple((py_attr(q), py_attr(rq), units) for q, rq, units, _ in r["attrs"])
        fill = tuple((py_attr(q), [] if is_list else 0) for q, is_list in r["fill"])
        cls = f"{sm['module']}.{names[(f['name'], r['dev'])]}"
        rcls = f"{sm['module']}.{names[(rf['name'], r['reply_dev'])]}"
        modules.add(sm["module"])
        for d in v["devices"]:
            keys = [{py_attr(n): x for n, x in combo.items()} for combo in r["keys"][d]]
            row = (
                f["name"],
                (sm["set"]["id"], f["id"]),
                tuple(py_attr(n) for n in keyed),
                attrs,
                tuple((py_attr(c), py_attr(lst)) for c, lst in r["counts"].items()),
                tuple(tuple(sorted(k.items())) for k in keys),
                fill,
            )
            rows[d].append(f"({cls}, {rcls}, {pyrepr(row)})")
    return {
        "settings_modules": sorted(modules),
        "settings_rows": rows,
        "data_sizes": {d: pyrepr(dict(sorted(v.items()))) for d, v in sizes.items()},
        # the manual lines of the UART bandwidth calculation (the spec's link section), for messages
        "bandwidth_sources": pyrepr(bandwidth_sources(proto)),
        "schema": settings_schema(proto, m.package, found),
    }
