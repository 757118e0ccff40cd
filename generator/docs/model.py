"""The documentation as data: every page is a title, breadcrumbs and a list of blocks.

Built from the IR and the golden vectors only. The Markdown writer (generator/docs/markdown.py)
and the HTML writer (generator/docs/html.py) serialise the same pages, so the two formats never
disagree. Text inside blocks uses a small inline subset of Markdown: `code`, [text](link) and
**bold**; links are relative paths between pages ending in .md (the HTML writer maps them).

Block kinds:
  {"kind": "heading", "level": 2, "text": str, "id": anchor}
  {"kind": "para", "text": str}
  {"kind": "list", "items": [str]}
  {"kind": "table", "role": str, "head": [str], "rows": [[str]]}   (role: a CSS class, e.g. "layout")
  {"kind": "image", "src": relative path, "alt": str, "role": "diagram" | "bits"}
  {"kind": "code", "lang": str, "text": str, "outside": str}   (outside: the block's marker for the
      outside-user test, written before the fence as `<!-- outside-user: ... -->`; docs/conformance.md §11)
"""

from __future__ import annotations

import json
import posixpath
import re
from dataclasses import dataclass, field

from ..corpus import resolve_field
from ..errata import KIND_TITLES
from ..model import per_device
from ..passes.params import held_params as _held_params
from ..targets import TARGETS
from . import svg

MAX_VECTORS = 24  # golden vectors shown per descriptor page (every erratum is always shown)
LANG_TITLES = {name: TARGETS[name].TITLE for name in TARGETS}  # the target registry's languages


@dataclass
class Page:
    path: str  # relative to generated/docs/, ends in .md
    title: str
    crumbs: list[tuple[str, str]]  # (text, path) from the site root down to the parent
    blocks: list[dict] = field(default_factory=list)
    kind: str = "page"  # "descriptor" pages carry a layout table and a packet diagram

    def h(self, level: int, text: str, anchor: str | None = None) -> None:
        self.blocks.append({"kind": "heading", "level": level, "text": text, "id": anchor or slug(text)})

    def p(self, text: str) -> None:
        if text:
            self.blocks.append({"kind": "para", "text": text})

    def table(self, head: list[str], rows: list[list[str]], role: str = "") -> None:
        self.blocks.append({"kind": "table", "role": role, "head": head, "rows": rows})

    def items(self, items: list[str]) -> None:
        if items:
            self.blocks.append({"kind": "list", "items": items})

    def image(self, src: str, alt: str, role: str) -> None:
        self.blocks.append({"kind": "image", "src": src, "alt": alt, "role": role})

    def code(self, text: str, lang: str = "", outside: str = "") -> None:
        self.blocks.append({"kind": "code", "lang": lang, "text": text.rstrip("\n"), "outside": outside})

    def link_to(self, target: str, anchor: str = "") -> str:
        """Relative link from this page to target (a page path), with an optional #anchor."""
        rel = posixpath.relpath(target, posixpath.dirname(self.path) or ".") if target != self.path else ""
        return rel + (f"#{anchor}" if anchor else "")


def slug(text: str) -> str:
    return re.sub(r"[^a-z0-9]+", "-", text.lower()).strip("-")


def hx(v: int) -> str:
    return f"0x{v:02X}"


def esc(text) -> str:
    """Plain text made safe inside a table cell or paragraph of the inline subset."""
    return " ".join(str(text).split()).replace("|", "\\|").replace("`", "'").replace("[", "\\[").replace("]", "\\]")


def code(text) -> str:
    return f"`{str(text).replace('`', chr(39))}`"


def size_text(size: dict) -> str:
    if size["fixed"]:
        return f"{size['min']}"
    return f"{size['min']}–{size['max']}"


def source_text(s: dict) -> str:
    where = f"{s['manual']}:{s['line']}" if s.get("line") else s["manual"]
    title = s.get("title") or s.get("section") or ""
    out = f"{code(where)} {esc(title)}".strip()
    if s.get("stated_length") is not None:
        out += f" (stated length {s['stated_length']})"
    return out


def held_params(v: dict) -> list[dict]:
    """The values a setting command's variant holds (generator/passes/params.py held_params)."""
    return _held_params(v.get("functions"), v["params"])


def default_value_text(q: dict, types: dict) -> str:
    """A parameter's default as the spec writes it (enum values by name)."""
    value = q["default"]["value"]
    t = types.get(q["type"].get("name", ""))
    if t and t["kind"] == "enum":
        names = {v["value"]: v["name"] for v in t["values"]}
        value = [names.get(x, x) for x in value] if isinstance(value, list) else names.get(value, value)
    if isinstance(value, list):
        return "[" + ", ".join(str(x) for x in value) + "]"
    return str(value).lower() if isinstance(value, bool) else str(value)


def default_sources_text(d: dict) -> str:
    return ", ".join(code(f"{r['manual']}:{r['line']}") for r in [d["source"], *d.get("also", [])])


# The anchor of the "Configure the device and stream data" section of the getting-started pages.
CONFIGURE_ANCHOR = "configure-and-stream"


class Docs:
    """Builds every page. api: {lang: module with api_names}; examples: {(lang, package): source}."""

    def __init__(self, ir: dict, vectors: list[dict], api: dict, examples: dict[tuple[str, str], str]):
        self.ir = ir
        self.api = api
        self.examples = examples
        self.pages: dict[str, Page] = {}
        self.svgs: dict[str, str] = {}
        self.vectors_by_field: dict[tuple[str, int, int, str], list[dict]] = {}
        self._index_vectors(vectors)
        self.vectors = vectors

    # ------------------------------------------------------------------ paths and lookups
    @staticmethod
    def proto_dir(p: dict) -> str:
        return p["name"]

    def field_path(self, p: dict, s: dict | None, f: dict) -> str:
        return f"{p['name']}/{s['name'] if s else 'reserved'}/{f['name']}.md"

    def _index_vectors(self, vectors: list[dict]) -> None:
        protos = {p["name"]: p for p in self.ir["protocols"]}
        by_name = {v["name"]: v for v in vectors}
        for v in vectors:
            p = protos[v["protocol"]]
            keys = self._vector_keys(p, v)
            corrected = (v.get("erratum") or {}).get("corrected")
            if not keys and corrected in by_name:
                keys = self._vector_keys(p, by_name[corrected])
            for k in keys:
                self.vectors_by_field.setdefault(k, []).append(v)

    def _vector_keys(self, p: dict, v: dict) -> list[tuple[str, int, int, str]]:
        keys = []
        for line in v["expect"]:
            obj = json.loads(line)
            for f in obj.get("fields", []):
                if "descriptor" not in f:
                    continue
                hit = resolve_field(p, obj["set"], f["descriptor"])
                if hit:
                    s, fd = hit
                    k = (p["name"], s["id"] if s else -1, fd["id"], fd["name"])
                    if k not in keys:
                        keys.append(k)
        return keys

    def names(self, p: dict, s: dict | None, f: dict) -> list[list[str]]:
        """Rows (language, names) for the identity table, from each back end's api_names."""
        rows = []
        for lang, mod in self.api.items():
            n = mod.api_names(p, s, f)
            shown = []
            for key in ("type", "class", "variants", "encode", "decode", "module", "header", "namespace"):
                if key in n and not (key == "variants" and "type" not in n and "class" not in n):
                    shown.append(f"{key}: {code(n[key])}")
            rows.append([LANG_TITLES[lang], "<br>".join(shown)])
        return rows

    def session_calls(self, p: dict, s: dict | None, f: dict, pg: Page) -> list[list[str]]:
        """Rows (language, call) for every language whose api_names gives the field a session call."""
        rows = []
        for lang, mod in self.api.items():
            n = mod.api_names(p, s, f)
            if "session" in n:
                link = pg.link_to(f"getting-started/{lang}.md", CONFIGURE_ANCHOR)
                rows.append([f"[{LANG_TITLES[lang]}]({link})", code(n["session"])])
        return rows

    # ------------------------------------------------------------------ build
    def build(self) -> None:
        self._home()
        for p in self.ir["protocols"]:
            self._protocol_index(p)
            self._device_matrix(p)
            self._types_page(p)
            for r in p["reserved_fields"]:
                self._field_page(p, None, r)
            for s in p["sets"]:
                for f in s["fields"]:
                    self._field_page(p, s, f)
        self._errata_page()

    def add(self, page: Page) -> Page:
        self.pages[page.path] = page
        return page

    # ------------------------------------------------------------------ home
    def _home(self) -> None:
        pg = self.add(Page("README.md", "Protocol reference", []))
        pg.p(
            "Reference documentation generated from the IR (`generated/ir.json`) and the golden vectors "
            "(`tests/vectors/`) by `make`; do not edit. `make html` builds the same pages as an offline HTML site."
        )
        rows = []
        for p in self.ir["protocols"]:
            n = sum(len(s["fields"]) for s in p["sets"]) + len(p["reserved_fields"])
            devs = ", ".join(esc(d["title"]) for d in p["devices"])
            rows.append(
                [
                    f"[{esc(p['title'])}]({pg.link_to(p['name'] + '/README.md')})",
                    code(p["package"]),
                    str(len(p["sets"])),
                    str(n),
                    devs,
                    f"[device matrix]({pg.link_to(p['name'] + '/devices.md')}), [types]({pg.link_to(p['name'] + '/types.md')})",
                ]
            )
        pg.table(["protocol", "package", "descriptor sets", "descriptors", "devices", "also"], rows, "index")
        pg.h(2, "Getting started")
        pg.items(
            [
                f"[{LANG_TITLES[lang]}]({pg.link_to(f'getting-started/{lang}.md')}): build a command, parse a stream, decode a capture"
                for lang in self.api
            ]
        )
        pg.h(2, "Errata")
        pg.p(
            f"[Errata in the manuals]({pg.link_to('errata.md')}): every place where the manuals contradict "
            "themselves, the decision taken and its evidence, per descriptor."
        )

    # ------------------------------------------------------------------ protocol index
    def _protocol_index(self, p: dict) -> None:
        base = p["name"] + "/README.md"
        pg = self.add(Page(base, p["title"], [("Reference", "README.md")]))
        fr = p["framing"]
        pg.p(
            f"Package {code(p['package'])} in every language. Byte order: {p['byte_order']}-endian. "
            f"[Device matrix]({pg.link_to(p['name'] + '/devices.md')}) · [types]({pg.link_to(p['name'] + '/types.md')}) · "
            f"[errata]({pg.link_to('errata.md', slug(p['title']))})."
        )
        pg.h(2, "Framing")
        pg.image("framing.svg", f"{p['title']} packet framing", "diagram")
        self.svgs[p["name"] + "/framing.svg"] = svg.packet_diagram(
            self._frame_segments(p, None, None, [svg.Segment("field data", 4, "param", "field data", True)]),
            f"{p['title']} packet: header, one field, checksum",
        )
        fh = " then ".join(fr["field_header"])
        counts = "header and data" if fr["field_length_counts_header"] else "data only"
        rows = [
            ["sync", " ".join(f"{b:02X}" for b in fr["sync"])],
            ["header", ", ".join(fr["header"]) + f" ({fr['header_size']} bytes with sync)"],
            ["field header", f"{fh} ({fr['field_header_size']} bytes); the field length counts {counts}"],
            ["maximum payload", f"{fr['max_payload']} bytes (packet {fr['max_packet']} bytes)"],
            [
                "checksum",
                f"{fr['checksum']['algorithm']} over {fr['checksum']['covers'].replace('_', ' ')}, "
                f"{fr['checksum_size']} bytes ({', '.join(fr['checksum']['order'])})",
            ],
        ]
        for irr in fr.get("irregular_lengths", []):
            rows.append(["irregular size byte", f"({hx(irr['set'])},{hx(irr['descriptor'])}): adjust {irr['adjust']}"])
        if p.get("response_descriptor"):
            rows.append(["reply descriptor", f"command code OR {hx(p['response_descriptor']['command_or'])}"])
        rows.append(["strings", f"padded with {p['strings']['padding']}, {p['strings']['justify']}-justified"])
        pg.table(["", ""], rows, "facts")
        pg.h(2, "Devices")
        pg.table(
            ["device", "id", "manual"],
            [[esc(d["title"]), code(d["id"]), code(d["manual"])] for d in p["devices"]],
            "devices",
        )
        pg.h(2, "Descriptor sets")
        pg.table(
            ["set", "name", "kind", "descriptors"],
            [
                [hx(s["id"]), f"[{esc(s['title'])}](#{slug('set ' + s['name'])})", s["kind"], str(len(s["fields"]))]
                for s in p["sets"]
            ]
            + [["—", f"[Reserved fields](#{slug('reserved fields')})", "both", str(len(p["reserved_fields"]))]],
            "sets",
        )
        for s in p["sets"]:
            pg.h(2, f"{hx(s['id'])} {s['title']}", slug("set " + s["name"]))
            pg.p(esc(s["description"]))
            pg.items([source_text(x) for x in s["sources"]])
            pg.table(
                ["descriptor", "name", "role", "data bytes", "devices"],
                [self._field_row(pg, p, s, f) for f in s["fields"]],
                "descriptors",
            )
        pg.h(2, "Reserved fields", slug("reserved fields"))
        pg.table(
            ["descriptor", "name", "role", "data bytes", "devices"],
            [self._field_row(pg, p, None, r) for r in p["reserved_fields"]],
            "descriptors",
        )

    def _field_row(self, pg: Page, p: dict, s: dict | None, f: dict) -> list[str]:
        devs = {d["id"]: d["title"] for d in p["devices"]}
        return [
            hx(f["id"]),
            f"[{esc(f['title'])}]({pg.link_to(self.field_path(p, s, f))}) {code(f['name'])}",
            f["role"],
            size_text(f["size"]),
            ", ".join(esc(devs[d]) for d in f["devices"]),
        ]

    # ------------------------------------------------------------------ device matrix
    def _device_matrix(self, p: dict) -> None:
        pg = self.add(Page(p["name"] + "/devices.md", f"{p['title']}: device support matrix", self._crumbs(p)))
        pg.p(
            "Which descriptor each device's manual documents (✓), and where a device has a layout of its own "
            "(✓ with the variant). A descriptor a manual does not document is still decoded for every device."
        )
        devices = p["devices"]
        head = ["set", "descriptor", "name", "role"] + [esc(d["title"]) for d in devices]
        rows = []
        entries = [(None, r) for r in p["reserved_fields"]] + [(st, fd) for st in p["sets"] for fd in st["fields"]]
        for s, f in entries:
            cells = []
            for d in devices:
                if d["id"] not in f["devices"]:
                    cells.append("–")
                elif per_device(f):
                    own = [v for v in f["variants"] if d["id"] in v["devices"]]
                    cells.append("✓ " + (code(own[0]["device"]) if own else ""))
                else:
                    cells.append("✓")
            rows.append(
                [
                    hx(s["id"]) if s else "any",
                    hx(f["id"]),
                    f"[{esc(f['title'])}]({pg.link_to(self.field_path(p, s, f))})",
                    f["role"],
                ]
                + cells
            )
        totals = ["", "", "**total**", ""] + [
            str(
                sum(1 for r in p["reserved_fields"] if d["id"] in r["devices"])
                + sum(1 for s in p["sets"] for f in s["fields"] if d["id"] in f["devices"])
            )
            for d in devices
        ]
        pg.table(head, rows + [totals], "matrix")
        self._device_defaults(pg, p)

    def _device_defaults(self, pg: Page, p: dict) -> None:
        """The factory values the manuals state, per device, and the settings the simulated device
        holds without one (its assumptions; docs/conformance.md section 9)."""
        devices = p["devices"]
        types = {t["name"]: t for t in p["types"]}
        stated_rows, assumed = [], {d["id"]: [] for d in devices}
        plausible: list[str] = []
        for s in p["sets"]:
            for f in s["fields"]:
                for v in f["variants"]:
                    link = f"[{esc(f['title'])}]({pg.link_to(self.field_path(p, s, f))})"
                    for q in held_params(v):
                        d = q.get("default")
                        cells = []
                        for dev in devices:
                            if dev["id"] not in v["devices"]:
                                cells.append("–")
                            elif d and dev["id"] in d["devices"]:
                                cells.append(code(default_value_text(q, types)))
                            elif q.get("plausible"):
                                pl = q["plausible"]
                                shown = (
                                    "zero"
                                    if pl["value"] is None
                                    else default_value_text({"type": q["type"], "default": pl}, types)
                                )
                                cells.append("plausible " + code(shown))
                                plausible.append(f"{link} {code(q['name'])} = {code(shown)}: {esc(pl['why'])}")
                            else:
                                cells.append("assumed 0")
                                assumed[dev["id"]].append(f"{link} {code(q['name'])}")
                        if d:
                            stated_rows.append(
                                [hx(s["id"]), hx(f["id"]), link, code(q["name"])] + cells + [default_sources_text(d)]
                            )
        pg.h(2, "Factory defaults")
        pg.p(
            "The factory value of each setting parameter a manual states (the spec's `default`, with the lines "
            "stating it; `make audit` checks that every default the manuals state is here or decided in a note). "
            "The simulated device starts from these values on the devices whose manuals state them."
        )
        head = ["set", "descriptor", "name", "parameter"] + [esc(d["title"]) for d in devices] + ["stated at"]
        if stated_rows:
            pg.table(head, stated_rows, "defaults")
        else:
            pg.p("No manual of this protocol states a factory value.")
        pg.h(2, "Plausible values")
        pg.p(
            "Settings whose factory value no manual states: the simulated device starts from the spec's "
            "`plausible` value, for the reason given (`zero`: the type's zero, a union's first member or an "
            "empty string, where no value can be written)."
        )
        pg.items(sorted(set(plausible)) or ["none"])
        pg.h(2, "Settings without a stated default")
        pg.p(
            "Every value a setting command holds whose factory value no manual states and that has no plausible "
            "value: the generator refuses such a spec (generator/passes/params.py check_starting_values), so "
            "each list is empty."
        )
        for dev in devices:
            pg.h(3, f"{esc(dev['title'])}: {len(assumed[dev['id']])} assumed values")
            pg.items(assumed[dev["id"]] or ["none"])

    def _crumbs(self, p: dict) -> list[tuple[str, str]]:
        return [("Reference", "README.md"), (p["title"], p["name"] + "/README.md")]

    # ------------------------------------------------------------------ types
    def _types_page(self, p: dict) -> None:
        pg = self.add(Page(p["name"] + "/types.md", f"{p['title']}: types", self._crumbs(p)))
        pg.p("Every enum, bitfield, struct and union of the protocol. Descriptor pages repeat the types they use.")
        types = {t["name"]: t for t in p["types"]}
        pg.table(
            ["type", "kind", "bytes", "title"],
            [
                [f"[{t['name']}](#{slug('type ' + t['name'])})", t["kind"], size_text(t["size"]), esc(t["title"])]
                for t in p["types"]
            ],
            "types",
        )
        for t in p["types"]:
            self._type_section(pg, p, types, t)

    def _type_ref(self, pg: Page, t: dict) -> str:
        """Text of a type reference (without array count), linked to its section on this page."""
        k = t["kind"]
        if k == "primitive":
            return code(t["name"])
        if k == "string":
            return code(f"char[{t['length']}]")
        link = f"[{t['name']}](#{slug('type ' + t['name'])})"
        if k in ("enum", "bitfield"):
            return f"{link} ({t['base']})"
        if k == "union":
            return f"{link} (union by {code(t['selector'])})"
        return link

    def _param_type(self, pg: Page, q: dict) -> str:
        base = self._type_ref(pg, q["type"])
        c = q.get("count")
        if not c:
            return base
        if c["kind"] == "fixed":
            n = str(c["value"])
        elif c["kind"] == "param":
            n = code(c["param"])
        else:
            n = "rest of field"
        mx = f", at most {q['max_count']}" if q.get("max_count") and c["kind"] != "fixed" else ""
        return f"{base} × {n}{mx}"

    def _used_types(self, types: dict, params: list[dict]) -> list[dict]:
        out: list[dict] = []

        def visit(name: str | None) -> None:
            if not name or name not in types or types[name] in out:
                return
            t = types[name]
            out.append(t)
            if t["kind"] == "struct":
                for q in t["params"]:
                    visit(q["type"].get("name") if q["type"]["kind"] != "primitive" else None)
            if t["kind"] == "union":
                visit(t["selector_enum"])
                for m in t["members"]:
                    visit(m["type"])

        for q in params:
            if q["type"]["kind"] != "primitive":
                visit(q["type"].get("name"))
        return out

    def _type_section(self, pg: Page, p: dict, types: dict, t: dict, level: int = 3) -> None:
        pg.h(level, f"{t['name']} ({t['kind']}, {size_text(t['size'])} bytes)", slug("type " + t["name"]))
        if t.get("description") or t["title"] != t["name"]:
            pg.p(esc(t.get("description") or t["title"]))
        if t["kind"] == "enum":
            rows = []
            for v in t["values"]:
                devs = ", ".join(v["devices"]) if v.get("devices") else ""
                name = code(v["name"]) + (f" (manual: {esc(v['manual_name'])})" if v.get("manual_name") else "")
                rows.append(
                    [
                        hx(v["value"]) if v["value"] >= 0 else str(v["value"]),
                        str(v["value"]),
                        name,
                        esc(v["description"]),
                        devs,
                    ]
                )
            pg.table(["value", "decimal", "name", "description", "devices"], rows, "enum")
        elif t["kind"] == "bitfield":
            bits = t["size"]["min"] * 8
            src = f"{slug(t['name'])}.svg"
            target = f"{p['name']}/types/{src}"
            self.svgs[target] = svg.bit_diagram(bits, t["members"], f"{t['name']}: {bits}-bit bitfield")
            pg.image(pg.link_to(target), f"bit diagram of {t['name']}", "bits")
            rows = []
            for m in sorted(t["members"], key=lambda m: -m["first_bit"]):
                bitr = str(m["first_bit"]) if m["width"] == 1 else f"{m['last_bit']}..{m['first_bit']}"
                name = (
                    code(m["name"]) + (" (reserved)" if m["reserved"] else "") + (" (alias)" if m.get("alias") else "")
                )
                rows.append([bitr, f"0x{m['mask']:0{bits // 4}X}", name, esc(m["description"])])
            pg.table(["bits", "mask", "name", "description"], rows, "bitfield")
        elif t["kind"] == "struct":
            pg.table(
                ["offset", "bytes", "type", "name", "units", "description"],
                [self._param_row(pg, q, 0) for q in t["params"]],
                "struct",
            )
        elif t["kind"] == "union":
            pg.p(
                f"Selected by a {self._type_ref(pg, {'kind': 'enum', 'name': t['selector_enum'], 'base': types[t['selector_enum']]['base']})} value."
            )
            rows = []
            for m in t["members"]:
                member = f"[{m['type']}](#{slug('type ' + m['type'])})" if m["type"] else "no data"
                rows.append(
                    [code(m["when"]), hx(m["value"]), member, size_text(m["size"]), esc(m.get("description", ""))]
                )
            pg.table(["selector", "value", "member", "bytes", "description"], rows, "union")
        self._notes(pg, t.get("notes", []), f"type {t['name']}")

    def _param_row(self, pg: Page, q: dict, shift: int, letters: dict | None = None) -> list[str]:
        off = str(q["offset"] + shift) if q.get("offset") is not None else "after previous"
        desc = esc(q["description"])
        if q.get("manual_name"):
            desc += f" (manual: {esc(q['manual_name'])})"
        if q.get("optional"):
            desc += " Optional."
        row = [off, size_text(q["size"]), self._param_type(pg, q), code(q["name"]), esc(q.get("units") or ""), desc]
        if letters is not None:
            row.insert(4, " ".join(letters.get(f, f) for f in q["functions"]) if q.get("functions") else "")
        return row

    def _notes(self, pg: Page, notes: list[dict], label: str) -> None:
        for n in notes:
            lines = ", ".join(code(f"{r['manual']}:{r['line']}") for r in n.get("lines", []))
            pg.p(f"**{KIND_TITLES[n['kind']]}** ({esc(label)}): {esc(n['text'])}" + (f" (on {lines})" if lines else ""))

    # ------------------------------------------------------------------ one descriptor
    def _frame_segments(self, p: dict, s: dict | None, f: dict | None, data: list[svg.Segment]) -> list[svg.Segment]:
        fr = p["framing"]
        segs = [svg.Segment(f"{b:02X}", 1, "sync", f"sync byte 0x{b:02X}") for b in fr["sync"]]
        data_len = sum(x.size for x in data)
        var = any(x.variable for x in data)
        for h in fr["header"]:
            if h == "set":
                segs.append(svg.Segment(f"set {hx(s['id'])}" if s else "set", 1, "header", "descriptor set"))
            else:
                segs.append(
                    svg.Segment("length", 1, "header", "payload length (bytes after the header, before the checksum)")
                )
        for h in fr["field_header"]:
            if h == "descriptor":
                segs.append(svg.Segment(f"desc {hx(f['id'])}" if f else "desc", 1, "field_header", "field descriptor"))
            else:
                n = data_len + fr["field_length_adjust"]
                tip = f"field length: {'header + data' if fr['field_length_counts_header'] else 'data'}"
                segs.append(svg.Segment("f. len" if var or not f else f"len {hx(n)}", 1, "field_header", tip))
        segs += data
        names = {"sum1": "ck 1", "sum2": "ck 2"}
        for o in fr["checksum"]["order"]:
            segs.append(svg.Segment(names.get(o, o), 1, "checksum", f"{fr['checksum']['algorithm']} {o}"))
        return segs

    def _data_segments(self, v: dict) -> list[svg.Segment]:
        segs = []
        if v["functions"]:
            segs.append(svg.Segment("function", 1, "selector", "function selector: " + ", ".join(v["functions"])))
        alt = False
        for q in v["params"]:
            kind = "param_alt" if alt else "param"
            alt = not alt
            c = q.get("count")
            elem = q["type"]["size"]
            tip = f"{q['name']}: {q['type'].get('name', q['type']['kind'])}, {size_text(q['size'])} bytes"
            if c and c["kind"] == "fixed" and c["value"] <= 4 and elem["fixed"] and c["value"] > 1:
                for i in range(c["value"]):
                    segs.append(svg.Segment(f"{q['name']}[{i}]", elem["min"], kind, tip))
            elif c and c["kind"] != "fixed":
                per = elem["min"] if elem["fixed"] else max(1, elem["min"])
                segs.append(svg.Segment(f"{q['name']}[…]", max(1, min(per, 16)), kind, tip + " (repeated)", True))
            elif not q["size"]["fixed"]:
                segs.append(svg.Segment(q["name"], max(1, min(q["size"]["max"], 4)), kind, tip, True))
            elif q["size"]["min"] == 0:
                continue
            else:
                segs.append(svg.Segment(q["name"], q["size"]["min"], kind, tip))
        return segs

    def _field_page(self, p: dict, s: dict | None, f: dict) -> None:
        path = self.field_path(p, s, f)
        set_label = f"{hx(s['id'])} {s['title']}" if s else "reserved"
        title = f"{f['title']} ({hx(s['id']) + ',' if s else ''}{hx(f['id'])})"
        pg = self.add(Page(path, title, self._crumbs(p), kind="descriptor"))
        types = {t["name"]: t for t in p["types"]}
        devs = {d["id"]: d["title"] for d in p["devices"]}
        pg.p(esc(f["description"]))
        ident = [
            ["protocol", f"[{esc(p['title'])}]({pg.link_to(p['name'] + '/README.md')})"],
            [
                "descriptor set",
                f"[{esc(set_label)}]({pg.link_to(p['name'] + '/README.md', slug('set ' + s['name']))}) {code(s['name'])}"
                if s
                else f"reserved in every {f.get('applies_to', '')} set",
            ],
            [
                "descriptor",
                f"{hx(f['id'])} {code(f['name'])}"
                + (f" (manual: {esc(f['manual_name'])})" if f.get("manual_name") else ""),
            ],
            ["role", f["role"] + (" (shared data; repeats)" if f.get("repeats") else "")],
            ["field data", f"{size_text(f['size'])} bytes"],
        ]
        if f.get("length_byte_adjust"):
            fr = p["framing"]
            ident.append(
                [
                    "size byte",
                    f"irregular: data length {f['length_byte_adjust']:+d}"
                    + (" + field header" if fr["field_length_counts_header"] else "")
                    + " (`length_byte_adjust`; the device expects it, see the notes)",
                ]
            )
        ident += [
            ["devices", ", ".join(esc(devs[d]) for d in f["devices"])],
        ]
        replies = self._reply_of(p, s, f)
        if replies:
            ident.append(["reply to", ", ".join(replies)])
        pg.table(["", ""], ident, "identity")
        pg.h(2, "Names in each language")
        pg.table(["language", "names"], self.names(p, s, f), "names")
        calls = self.session_calls(p, s, f, pg)
        if calls:
            pg.h(2, "Session call")
            pg.p(
                "The call of each language's typed command API: it sends the command through a session, waits "
                "for its ack or NACK and returns the typed reply (the language links to a complete example)."
            )
            pg.table(["language", "session call"], calls, "session-call")
        pg.h(2, "Sources")
        pg.items([source_text(x) for x in f["sources"]])
        multi = per_device(f)
        letters = {v: k for k, v in p["function_selector"].get("letters", {}).items()}
        fsel = types.get(p["function_selector"]["enum"])
        shown_types: set[str] = set()
        for v in f["variants"]:
            suffix = f" on {', '.join(devs[d] for d in v['devices'])}" if multi else ""
            anchor = slug("layout " + (v["device"] or ""))
            pg.h(2, "Layout" + suffix, anchor)
            if multi:
                pg.items([source_text(x) for x in v["sources"]])
            diagram = posixpath.basename(path)[:-3] + (f"-{v['device']}" if multi else "") + ".svg"
            self.svgs[posixpath.join(posixpath.dirname(path), diagram)] = svg.packet_diagram(
                self._frame_segments(p, s, f, self._data_segments(v)),
                f"{f['title']}{suffix}: packet with this field alone",
            )
            pg.image(diagram, f"packet diagram of {f['title']}{suffix}", "diagram")
            shift = 1 if v["functions"] else 0
            head = ["offset", "bytes", "type", "name", "units", "description"]
            rows = []
            if v["functions"]:
                head.insert(4, "functions")
                rows.append(
                    [
                        "0",
                        "1",
                        f"[{p['function_selector']['enum']}](#{slug('type ' + p['function_selector']['enum'])}) (u8)",
                        code("function"),
                        " ".join(letters.get(x, x) for x in v["functions"]),
                        "",
                        "Function selector.",
                    ]
                )
            rows += [self._param_row(pg, q, shift, letters if v["functions"] else None) for q in v["params"]]
            if not rows:
                pg.p("No field data: the field is its header alone.")
            pg.table(head, rows or [["—", "0", "", "", "", "no data"]], "layout")
            pg.p("Offsets count from the first byte of field data (after the field header).")
            self._defaults_section(pg, p, types, v, suffix, devs)
            if v["functions"]:
                pg.h(3, "Function selectors" + suffix, slug("functions " + (v["device"] or "")))
                fvals = {x["name"]: x["value"] for x in fsel["values"]} if fsel else {}
                rows = []
                for fn in v["functions"]:
                    carried = [code(q["name"]) for q in v["params"] if fn in (q.get("functions") or [])]
                    rows.append(
                        [code(fn), hx(fvals.get(fn, 0)), ", ".join(carried) or "none", self._ack_text(pg, p, v, fn)]
                    )
                pg.table(["function", "code", "parameters carried", "ack"], rows, "functions")
            if f["role"] == "command":
                pg.h(3, "Reply" + suffix, slug("reply " + (v["device"] or "")))
                if not v["functions"]:
                    pg.p("Ack: " + self._ack_text(pg, p, v, None) + ".")
                responses = self._responses(pg, p, s, v)
                pg.p("Response field(s):" if responses else "No response field: the reply is the ack alone.")
                pg.items(responses)
            selector = [{"type": {"kind": "enum", "name": fsel["name"]}}] if v["functions"] and fsel else []
            for t in self._used_types(types, selector + v["params"]):
                if t["name"] not in shown_types:
                    shown_types.add(t["name"])
                    self._type_section(pg, p, types, t)
            self._notes(pg, v.get("notes", []), "variant " + (v["device"] or ""))
        self._vector_section(pg, p, s, f)
        notes = list(f.get("notes", []))
        params_notes = [(q["name"], n) for v in f["variants"] for q in v["params"] for n in q.get("notes", [])]
        if notes or params_notes:
            pg.h(2, "Notes and errata")
            self._notes(pg, notes, f["name"])
            for qn, n in params_notes:
                self._notes(pg, [n], f"parameter {qn}")

    def _defaults_section(self, pg: Page, p: dict, types: dict, v: dict, suffix: str, devs: dict) -> None:
        """A setting's factory values: those the manuals state (with the line) and the values the
        simulated device assumes (docs/conformance.md section 9)."""
        held = held_params(v)
        if not held:
            return
        pg.h(3, "Factory defaults" + suffix, slug("defaults " + (v["device"] or "")))
        stated = [q for q in held if q.get("default")]
        if stated:
            pg.table(
                ["parameter", "factory value", "on", "stated at"],
                [
                    [
                        code(q["name"]),
                        code(default_value_text(q, types)),
                        ", ".join(esc(devs[d]) for d in q["default"]["devices"] if d in v["devices"]),
                        default_sources_text(q["default"]),
                    ]
                    for q in stated
                ],
                "defaults",
            )
        unstated = [
            q["name"]
            + (
                f" (on {', '.join(devs[d] for d in v['devices'] if d not in q['default']['devices'])})"
                if q.get("default")
                else ""
            )
            for q in held
            if not q.get("default") or set(v["devices"]) - set(q["default"]["devices"])
        ]
        if unstated:
            pg.p(
                "No manual states the factory value of "
                + ", ".join(
                    code(n.split(" ", 1)[0]) + (" " + esc(n.split(" ", 1)[1]) if " " in n else "") for n in unstated
                )
                + ": the simulated device assumes zero ("
                + f"[assumptions]({pg.link_to(p['name'] + '/devices.md')}#{slug('settings without a stated default')}))."
            )

    def _reply_of(self, p: dict, s: dict | None, f: dict) -> list[str]:
        if not s or f["role"] != "response":
            return []
        out = []
        for g in s["fields"]:
            for v in g["variants"]:
                if any(r["id"] == f["id"] for r in v["responses"]):
                    ref = f"[{esc(g['title'])}]({posixpath.relpath(self.field_path(p, s, g), posixpath.dirname(self.field_path(p, s, f)))})"
                    if ref not in out:
                        out.append(ref)
        return out

    def _ack_text(self, pg: Page, p: dict, v: dict, fn: str | None) -> str:
        ack = next((r for r in p["reserved_fields"] if r["role"] == "ack"), None)
        if not ack:
            return "none"
        sup = v.get("ack_suppressed_by") or {}
        if sup.get("function") and sup["function"] == fn:
            return "none (this function suppresses the ack)"
        link = f"[{esc(ack['title'])}]({pg.link_to(self.field_path(p, None, ack))})"
        if sup.get("param"):
            link += f" (none when {code(sup['param'])}" + (f" = {sup['value']})" if "value" in sup else " is set)")
        return link

    def _responses(self, pg: Page, p: dict, s: dict | None, v: dict) -> list[str]:
        by_id = {g["id"]: g for g in s["fields"]} if s else {}
        out = []
        for r in v["responses"]:
            g = by_id.get(r["id"])
            if not g:
                continue
            w = r.get("when")
            if not w:
                cond = "no condition stated in the spec"
            else:
                parts = []
                if w.get("function"):
                    parts.append(f"function {code(w['function'])}")
                if w.get("param"):
                    parts.append(f"{code(w['param'])}" + (f" = {code(w['value'])}" if "value" in w else " present"))
                cond = "when " + " and ".join(parts)
            out.append(
                f"[{esc(g['title'])}]({pg.link_to(self.field_path(p, s, g))}) {code(g['name'])} ({hx(g['id'])}): {cond}"
            )
        return out

    def _vector_section(self, pg: Page, p: dict, s: dict | None, f: dict) -> None:
        cases = self.vectors_by_field.get((p["name"], s["id"] if s else -1, f["id"], f["name"]), [])
        pg.h(2, "Golden vectors", "golden-vectors")
        if not cases:
            pg.p(
                "No golden vector carries this descriptor on its own page yet; the spec round-trip and "
                "cross-language suites still encode and decode it in every language."
            )
            return
        pg.p(
            f"{len(cases)} case(s) from the golden vectors (`tests/vectors/`) and the stream corpus "
            "(`tests/streams/`), checked byte for byte in C, C++, Python and Rust "
            "(decoded to the canonical JSON lines shown, fed whole and in chunks of every size, and encoded back)."
        )
        shown = [c for c in cases if c.get("erratum")]
        shown += [c for c in cases if not c.get("erratum")][: max(0, MAX_VECTORS - len(shown))]
        shown.sort(key=cases.index)
        if len(shown) < len(cases):
            pg.p(
                f"{len(shown)} of {len(cases)} are shown (every erratum among them); the rest are in `tests/vectors/{p['name']}/` and `tests/streams/{p['name']}/`."
            )
        for c in shown:
            status = "rejected (negative case)" if c["rejected"] else "accepted"
            pg.h(3, c["name"], "vector-" + slug(c["name"]))
            facts = [f"{status}", f"{c['size']} bytes"]
            if c.get("device"):
                facts.append(f"device {code(c['device'])}")
            facts.append(f"{code(c['file'])} line {c['line']}")
            pg.p(" · ".join(facts))
            if c["sources"]:
                pg.items(["published at " + source_text(x) for x in c["sources"]])
            if c.get("derivation"):
                pg.p("Derivation: " + esc(c["derivation"]))
            e = c.get("erratum")
            if e:
                corr = f" Corrected vector: {code(e['corrected'])}." if e.get("corrected") else ""
                pg.p(f"**Erratum** ({code(e['kind'])}): {esc(e['evidence'])}{corr}")
            pg.code(_hex_lines(c["hex"]), "text")
            pg.code("\n".join(c["expect"]), "json")

    # ------------------------------------------------------------------ errata
    def _errata_page(self) -> None:
        from ..errata import spec_notes

        pg = self.add(Page("errata.md", "Errata in the manuals", [("Reference", "README.md")]))
        pg.p(
            "Where a manual contradicts itself, the spec transcribes the truth and records the decision and its "
            "evidence next to the entry; published examples that are wrong stay in the tests as negative cases. "
            "This page collects them per protocol, linked to the descriptor pages (the same facts as `docs/errata.md`)."
        )
        for p in self.ir["protocols"]:
            pg.h(2, p["title"], slug(p["title"]))
            rows = []
            for c in self.vectors:
                e = c.get("erratum")
                if c["protocol"] != p["name"] or not e:
                    continue
                rows.append(
                    [
                        code(c["name"]),
                        self._vector_links(pg, p, c),
                        "; ".join(source_text(x) for x in c["sources"]),
                        code(e["kind"]),
                        esc(e["evidence"]),
                    ]
                )
            pg.h(3, "Published examples", slug(p["name"] + " examples"))
            pg.table(["vector", "descriptor", "published at", "kind", "evidence"], rows, "errata")
            rows = []
            only = {"protocols": [p]}
            for _proto, label, sources, n in spec_notes(only):
                rows.append(
                    [esc(label), "; ".join(source_text(x) for x in sources), KIND_TITLES[n["kind"]], esc(n["text"])]
                )
            pg.h(3, "Spec entries", slug(p["name"] + " spec notes"))
            pg.table(["entry", "source", "kind", "note"], rows, "errata")

    def _vector_links(self, pg: Page, p: dict, c: dict) -> str:
        out = []
        for (proto, sid, fid, name), cases in self.vectors_by_field.items():
            if proto != p["name"] or c not in cases:
                continue
            hit = self._resolve_by_id(p, sid, fid, name)
            if hit:
                s, f = hit
                out.append(f"[{esc(f['title'])}]({pg.link_to(self.field_path(p, s, f), 'vector-' + slug(c['name']))})")
        return ", ".join(out) or "—"

    def _resolve_by_id(self, p: dict, sid: int, fid: int, name: str):
        if sid == -1:
            return next(((None, r) for r in p["reserved_fields"] if r["id"] == fid and r["name"] == name), None)
        for s in p["sets"]:
            if s["id"] == sid:
                return next(((s, f) for f in s["fields"] if f["id"] == fid), None)
        return None


def _hex_lines(h: str) -> str:
    b = [h[i : i + 2].upper() for i in range(0, len(h), 2)]
    return "\n".join(" ".join(b[i : i + 16]) for i in range(0, len(b), 16))
