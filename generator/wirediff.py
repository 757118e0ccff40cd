"""`mipgen diff OLD NEW`: what changed between two specs, on the wire and in the generated API.

OLD and NEW are spec directories or git revisions (their spec/) of the current directory's
repository (else of this checkout). Both are loaded into the IR (generator/spec.py) and compared protocol by protocol: framing, devices,
enums and bitfields (values and bits by number), structs, descriptor sets, and per descriptor
its device support, functions, responses and each layout's parameters (name, type, count and
offset). Every change is classified:

- wire-breaking: the same bytes decode to other values, or something the old spec had is gone
  (a removed descriptor, value, bit, function or device; a parameter whose type or offset moved);
- wire-compatible: an addition (a set, descriptor, device, enum value, bit, function, response,
  an optional parameter at the end of a command);
- API-only: the bytes are the same but a generated name changes (a rename), listed per language;
- documentation: titles and descriptions only.

The release rules of docs/versioning.md follow: any wire-breaking or API-only change is a MAJOR
bump (MINOR while the major version is 0), wire-compatible additions a MINOR one (PATCH under 0.x),
documentation alone a PATCH. Exit status: 0 when nothing breaks the wire, 1 when something does,
2 for a usage error (a spec that does not load, a revision that does not exist).
"""

from __future__ import annotations

import json
import subprocess
import tarfile
import tempfile
from dataclasses import dataclass, field
from io import BytesIO
from pathlib import Path

from .resources import CHECKOUT
from .spec import load_spec
from .targets import TARGETS

BREAKING, COMPATIBLE, API, DOC = "wire-breaking", "wire-compatible", "api-only", "documentation"
ORDER = (BREAKING, API, COMPATIBLE, DOC)


class DiffError(Exception):
    """A usage error: OLD or NEW is neither a spec directory nor a revision, or does not load."""


@dataclass
class Change:
    kind: str  # one of ORDER
    protocol: str
    where: str  # "0x80,0x41 sensor.wheel_temperature", "enum AckCode", "framing", ...
    what: str
    names: dict[str, list[str]] = field(default_factory=dict)  # language -> "old -> new" (renames)
    detail: dict = field(default_factory=dict)  # parameter, old/new type and offset, ...

    def as_json(self) -> dict:
        out = {"kind": self.kind, "protocol": self.protocol, "where": self.where, "what": self.what}
        if self.names:
            out["names"] = self.names
        if self.detail:
            out["detail"] = self.detail
        return out


# ------------------------------------------------------------------------------ loading
def load_side(arg: str, root: Path | None = None, overlays: list[Path] = ()) -> tuple[dict, str]:
    """The IR of a spec directory or of a git revision's spec/, with overlay directories laid over
    it in order (as `mipgen generate --spec DIR OVERLAY...` does), and how to call it. Revisions
    are those of the git repository of the current directory (as for `git diff`), else of this
    checkout; root names another repository."""
    root = root or _repository()
    overlays = list(overlays)
    for d in overlays:
        if not Path(d).is_dir():
            raise DiffError(f"overlay {d}: no such directory")
    suffix = "".join(f" + {d}" for d in overlays)
    path = Path(arg)
    if path.is_dir():
        spec_dir = path / "spec" if (path / "spec").is_dir() and not _has_protocol(path) else path
        return _load(spec_dir, str(arg) + suffix, overlays), str(arg) + suffix
    rev = subprocess.run(
        ["git", "-C", str(root), "rev-parse", "--verify", "--quiet", f"{arg}^{{commit}}"],
        capture_output=True,
        text=True,
    )
    if rev.returncode != 0:
        raise DiffError(f"'{arg}' is neither a spec directory nor a git revision of {root}")
    archive = subprocess.run(["git", "-C", str(root), "archive", "--format=tar", arg, "spec"], capture_output=True)
    if archive.returncode != 0:
        raise DiffError(f"revision '{arg}' has no spec/: {archive.stderr.decode(errors='replace').strip()}")
    with tempfile.TemporaryDirectory(prefix="mipgen-diff-") as tmp:
        with tarfile.open(fileobj=BytesIO(archive.stdout)) as tar:
            tar.extractall(tmp, filter="data")
        label = f"{arg} ({rev.stdout.strip()[:12]}){suffix}"
        return _load(Path(tmp) / "spec", f"{arg}:spec{suffix}", overlays), label


def _repository() -> Path:
    cwd = Path.cwd()
    inside = subprocess.run(["git", "-C", str(cwd), "rev-parse", "--show-toplevel"], capture_output=True, text=True)
    if inside.returncode == 0 and inside.stdout.strip():
        return Path(inside.stdout.strip())
    return CHECKOUT or cwd


def _has_protocol(path: Path) -> bool:
    return any(p.is_dir() and any(p.glob("*.yaml")) for p in path.iterdir() if p.name != "schema")


def _load(spec_dir: Path, label: str, overlays: list[Path] = ()) -> dict:
    from .diagnostics import SpecError, SpecErrors

    try:
        return load_spec(spec_dir, root=spec_dir.parent, overlays=list(overlays))
    except SpecErrors as e:
        raise DiffError(f"{label} does not load:\n" + "\n".join(str(x) for x in e.errors[:10])) from None
    except SpecError as e:
        raise DiffError(f"{label} does not load: {e}") from None


# ------------------------------------------------------------------------------ names
def public_names(p: dict, kind: str, *path) -> dict[str, str]:
    """The public name(s) of a spec element in every target language, as each target names it
    (generator/targets/<lang>/backend.py public_name): kind "set" (set), "field" (set or None,
    field: its type per device when it has per-device layouts, from each back end's `api_names`),
    "value" (enum type, value), "member" (owner name, member name: `owner.member` in every language)."""
    if kind == "member":
        return {lang: f"{path[0]}.{path[1]}" for lang in TARGETS}
    if kind == "field":
        names = {lang: mod.api_names(p, path[0], path[1]) for lang, mod in TARGETS.items()}
        return {lang: n.get("variants") or n.get("type") or n["class"] for lang, n in names.items()}
    return {lang: mod.public_name(p, kind, *path) for lang, mod in TARGETS.items()}


def _renamed(old: dict[str, str], new: dict[str, str]) -> dict[str, list[str]]:
    return {lang: [f"{old[lang]} -> {new[lang]}"] for lang in old if old[lang] != new[lang]}


# ------------------------------------------------------------------------------ comparing
def type_text(q: dict) -> str:
    t = q["type"]
    text = t["name"] if t["kind"] != "string" else f"string[{t.get('length')}]"
    c = q.get("count")
    if c:
        text += f"[{c['value']}]" if c["kind"] == "fixed" else f"[{c.get('param') or c['kind']}]"
    return text


class Differ:
    def __init__(self, old: dict, new: dict):
        self.old, self.new = old, new
        self.changes: list[Change] = []

    def add(self, kind, p, where, what, names=None, **detail) -> None:
        self.changes.append(Change(kind, p["name"], where, what, names or {}, detail))

    def run(self) -> list[Change]:
        olds = {p["name"]: p for p in self.old["protocols"]}
        news = {p["name"]: p for p in self.new["protocols"]}
        for name in sorted(set(olds) | set(news)):
            if name not in news:
                self.add(BREAKING, olds[name], "protocol", f"protocol {name} removed")
            elif name not in olds:
                self.add(COMPATIBLE, news[name], "protocol", f"protocol {name} added")
            else:
                self.protocol(olds[name], news[name])
        return self.changes

    def protocol(self, a: dict, b: dict) -> None:
        for key in ("framing", "byte_order", "set_kinds", "shared_data", "reserved_fields", "function_selector"):
            if json.dumps(a.get(key), sort_keys=True) != json.dumps(b.get(key), sort_keys=True):
                self.add(BREAKING, b, key, f"{key} changed")
        for key in ("samples", "session"):
            # Rules the packages promise (docs/conformance.md sections 6 and 8): how samples group,
            # how a reply is matched. Not bytes, but a consumer's results change with them.
            if json.dumps(a.get(key), sort_keys=True) != json.dumps(b.get(key), sort_keys=True):
                self.add(BREAKING, b, key, f"{key} rule changed")
        da = {d["id"]: d for d in a["devices"]}
        db = {d["id"]: d for d in b["devices"]}
        for d in sorted(set(da) | set(db)):
            if d not in db:
                self.add(BREAKING, b, f"device {d}", f"device {d} removed")
            elif d not in da:
                self.add(COMPATIBLE, b, f"device {d}", f"device {d} added ({db[d]['title']})")
        self.types(a, b)
        self.sets(a, b)

    # -- types
    def types(self, a: dict, b: dict) -> None:
        ta = {t["name"]: t for t in a["types"]}
        tb = {t["name"]: t for t in b["types"]}
        for name in sorted(set(ta) | set(tb)):
            x, y = ta.get(name), tb.get(name)
            if y is None:
                self.add(BREAKING, b, f"{x['kind']} {name}", f"type {name} removed")
                continue
            if x is None:
                self.add(COMPATIBLE, b, f"{y['kind']} {name}", f"type {name} added")
                continue
            where = f"{y['kind']} {name}"
            for key in ("title", "description", "notes", "sources"):
                if json.dumps(x.get(key), sort_keys=True) != json.dumps(y.get(key), sort_keys=True):
                    self.add(DOC, b, where, f"{key} changed")
            if x["kind"] != y["kind"] or x.get("base") != y.get("base"):
                self.add(
                    BREAKING,
                    b,
                    where,
                    f"{name} changed from {x['kind']} {x.get('base') or ''} to {y['kind']} {y.get('base') or ''}",
                )
                continue
            if y["kind"] == "enum":
                self.enum(b, name, x, y)
            elif y["kind"] == "bitfield":
                self.bitfield(b, name, x, y)
            elif y["kind"] == "struct":
                self.params(b, where, name, x["params"], y["params"], command=False)
            elif json.dumps(x.get("members"), sort_keys=True) != json.dumps(y.get("members"), sort_keys=True):
                self.add(BREAKING, b, where, f"union {name} members changed")

    def enum(self, p: dict, name: str, x: dict, y: dict) -> None:
        def by_number(t):
            out: dict[int, list[dict]] = {}
            for v in t["values"]:
                out.setdefault(v["value"], []).append(v)
            return out

        va, vb = by_number(x), by_number(y)
        where = f"enum {name}"
        for n in sorted(set(va) | set(vb)):
            na = sorted(v["name"] for v in va.get(n, []))
            nb = sorted(v["name"] for v in vb.get(n, []))
            if not nb:
                self.add(BREAKING, p, where, f"value {n} ({', '.join(na)}) removed", value=n)
            elif not na:
                self.add(COMPATIBLE, p, where, f"value {n} ({', '.join(nb)}) added", value=n)
            elif na != nb:
                names: dict[str, list[str]] = {}
                for o, w in zip(na, nb):
                    old = public_names(p, "value", x, {"name": o})
                    for lang, r in _renamed(old, public_names(p, "value", y, {"name": w})).items():
                        names.setdefault(lang, []).extend(r)
                self.add(API, p, where, f"value {n} renamed {', '.join(na)} -> {', '.join(nb)}", names, value=n)
            else:
                self._devices(p, where + f" value {n}", va[n][0].get("devices"), vb[n][0].get("devices"))

    def bitfield(self, p: dict, name: str, x: dict, y: dict) -> None:
        ma = {(m["first_bit"], m["width"]): m for m in x["members"]}
        mb = {(m["first_bit"], m["width"]): m for m in y["members"]}
        where = f"bitfield {name}"
        for key in sorted(set(ma) | set(mb)):
            bits = f"bit {key[0]}" if key[1] == 1 else f"bits {key[0]}-{key[0] + key[1] - 1}"
            m, n = ma.get(key), mb.get(key)
            if n is None:
                self.add(BREAKING, p, where, f"{bits} ({m['name']}) removed", mask=m["mask"])
            elif m is None:
                self.add(COMPATIBLE, p, where, f"{bits} ({n['name']}) added", mask=n["mask"])
            elif m["name"] != n["name"]:
                names = _renamed(public_names(p, "member", name, m["name"]), public_names(p, "member", name, n["name"]))
                self.add(API, p, where, f"{bits} renamed {m['name']} -> {n['name']}", names, mask=n["mask"])

    # -- sets and fields
    def sets(self, a: dict, b: dict) -> None:
        sa = {s["id"]: s for s in a["sets"]}
        sb = {s["id"]: s for s in b["sets"]}
        for sid in sorted(set(sa) | set(sb)):
            x, y = sa.get(sid), sb.get(sid)
            if y is None:
                self.add(BREAKING, b, f"set 0x{sid:02X} {x['name']}", "descriptor set removed")
                continue
            if x is None:
                self.add(
                    COMPATIBLE,
                    b,
                    f"set 0x{sid:02X} {y['name']}",
                    f"descriptor set added ({len(y['fields'])} descriptors)",
                )
                continue
            if x["name"] != y["name"]:
                names = _renamed(public_names(a, "set", x), public_names(b, "set", y))
                self.add(API, b, f"set 0x{sid:02X} {y['name']}", f"set renamed {x['name']} -> {y['name']}", names)
            fa = {f["id"]: f for f in x["fields"]}
            fb = {f["id"]: f for f in y["fields"]}
            for fid in sorted(set(fa) | set(fb)):
                f, g = fa.get(fid), fb.get(fid)
                where = f"0x{sid:02X},0x{fid:02X} {y['name']}.{(g or f)['name']}"
                if g is None:
                    self.add(BREAKING, b, where, f"{f['role']} descriptor removed")
                elif f is None:
                    self.add(COMPATIBLE, b, where, f"{g['role']} descriptor added", devices=g["devices"])
                else:
                    self.field(b, where, y["name"], f, g, (a, x))

    def field(self, p: dict, where: str, set_name: str, f: dict, g: dict, old: tuple[dict, dict]) -> None:
        """Field f of the old protocol and set `old` against field g of set set_name of p."""
        if f["name"] != g["name"]:
            new_set = next(s for s in p["sets"] if s["name"] == set_name)
            names = _renamed(public_names(old[0], "field", old[1], f), public_names(p, "field", new_set, g))
            self.add(API, p, where, f"descriptor renamed {f['name']} -> {g['name']}", names)
        if f["role"] != g["role"]:
            self.add(BREAKING, p, where, f"role changed {f['role']} -> {g['role']}")
        if f["repeats"] != g["repeats"] or f["length_byte_adjust"] != g["length_byte_adjust"]:
            self.add(BREAKING, p, where, "repeats or length_byte_adjust changed")
        self._devices(p, where, f["devices"], g["devices"])
        va = {v["device"]: v for v in f["variants"]}
        vb = {v["device"]: v for v in g["variants"]}
        if set(va) != set(vb) and len(va) == 1 and len(vb) == 1:
            va = {None: next(iter(va.values()))}
            vb = {None: next(iter(vb.values()))}
        for dev in sorted(set(va) | set(vb), key=lambda d: d or ""):
            label = where + (f" [{dev}]" if dev else "")
            v, w = va.get(dev), vb.get(dev)
            if w is None:
                self.add(BREAKING, p, label, f"layout for device {dev} removed")
            elif v is None:
                self.add(COMPATIBLE, p, label, f"layout for device {dev} added")
            else:
                self.variant(p, label, g["name"], g["role"], v, w)
        for key in ("title", "description", "notes", "sources"):
            if json.dumps(f.get(key), sort_keys=True) != json.dumps(g.get(key), sort_keys=True):
                self.add(DOC, p, where, f"{key} changed")

    def variant(self, p: dict, where: str, name: str, role: str, v: dict, w: dict) -> None:
        fa, fb = v["functions"] or [], w["functions"] or []
        for fn in fa:
            if fn not in fb:
                self.add(BREAKING, p, where, f"function {fn} removed")
        for fn in fb:
            if fn not in fa:
                self.add(COMPATIBLE, p, where, f"function {fn} added")
        ra = {(r["id"], r["name"]): r for r in v["responses"]}
        rb = {(r["id"], r["name"]): r for r in w["responses"]}
        for r in ra:
            if r not in rb:
                self.add(BREAKING, p, where, f"response 0x{r[0]:02X} {r[1]} removed")
            elif ra[r].get("when") != rb[r].get("when"):
                # The reply a session waits for changes (docs/conformance.md section 8).
                self.add(
                    BREAKING,
                    p,
                    where,
                    f"response 0x{r[0]:02X} {r[1]}: answers {_when(ra[r].get('when'))} -> {_when(rb[r].get('when'))}",
                )
        for r in rb:
            if r not in ra:
                self.add(COMPATIBLE, p, where, f"response 0x{r[0]:02X} {r[1]} added")
        if v.get("timeout") != w.get("timeout"):
            self.add(
                COMPATIBLE,
                p,
                where,
                f"reply timeout allowance {_timeout(v.get('timeout'))} -> {_timeout(w.get('timeout'))}",
            )
        self.params(p, where, name, v["params"], w["params"], command=role == "command")

    def params(self, p: dict, where: str, owner: str, pa: list, pb: list, command: bool) -> None:
        for i in range(max(len(pa), len(pb))):
            q = pa[i] if i < len(pa) else None
            r = pb[i] if i < len(pb) else None
            if r is None:
                self.add(
                    BREAKING,
                    p,
                    where,
                    f"parameter {q['name']} removed",
                    parameter=q["name"],
                    old_type=type_text(q),
                    old_offset=q.get("offset"),
                )
            elif q is None:
                optional = r.get("optional") or r.get("functions")
                kind = COMPATIBLE if command and optional else BREAKING
                why = "optional, at the end" if kind == COMPATIBLE else "old decoders reject the longer data"
                self.add(
                    kind,
                    p,
                    where,
                    f"parameter {r['name']} added ({why})",
                    parameter=r["name"],
                    new_type=type_text(r),
                    new_offset=r.get("offset"),
                )
            else:
                self.param(p, where, owner, q, r)

    def param(self, p: dict, where: str, owner: str, q: dict, r: dict) -> None:
        oq, orr = q.get("offset"), r.get("offset")
        # An offset that became variable (an earlier parameter turned optional) moves nothing in
        # the full form; two fixed offsets that differ do.
        moved = oq is not None and orr is not None and oq != orr
        if type_text(q) != type_text(r) or moved:
            self.add(
                BREAKING,
                p,
                where,
                f"parameter {r['name']}: {type_text(q)} at offset {_off(oq)} -> {type_text(r)} at offset {_off(orr)}",
                parameter=r["name"],
                old_type=type_text(q),
                new_type=type_text(r),
                old_offset=oq,
                new_offset=orr,
            )
        if q["name"] != r["name"]:
            names = _renamed(public_names(p, "member", owner, q["name"]), public_names(p, "member", owner, r["name"]))
            self.add(API, p, where, f"parameter renamed {q['name']} -> {r['name']}", names, parameter=r["name"])
        if bool(q.get("optional")) != bool(r.get("optional")):
            kind = COMPATIBLE if r.get("optional") else BREAKING
            state = "optional" if r.get("optional") else "required"
            self.add(kind, p, where, f"parameter {r['name']} is now {state}", parameter=r["name"])
        for key, what in (("functions", "sent with functions"), ("optional_for", "optional for functions")):
            a, b = set(q.get(key) or []), set(r.get(key) or [])
            if a == b or (key == "optional_for" and bool(q.get("optional")) != bool(r.get("optional"))):
                continue
            # `functions`: no list means every function; a list that grows or becomes None widens.
            wider = (key == "optional_for" and a <= b) or (
                key == "functions" and (not r.get(key) or (q.get(key) and a <= b))
            )
            self.add(
                COMPATIBLE if wider else BREAKING,
                p,
                where,
                f"parameter {r['name']} {what}: {_names(a, key)} -> {_names(b, key)}",
                parameter=r["name"],
            )

    def _devices(self, p: dict, where: str, a, b) -> None:
        a, b = set(a or []), set(b or [])
        if a and b and a != b:
            if a - b:
                self.add(BREAKING, p, where, "no longer on " + ", ".join(sorted(a - b)))
            if b - a:
                self.add(COMPATIBLE, p, where, "now also on " + ", ".join(sorted(b - a)))


def _names(items: set, key: str) -> str:
    return ", ".join(sorted(items)) if items else ("all" if key == "functions" else "none")


def _when(when) -> str:
    return "always" if not when else "when " + ", ".join(f"{k} {v}" for k, v in sorted(when.items()))


def _timeout(t) -> str:
    if not t:
        return "none"
    text = f"{t['ms']} ms" + (f" + {t['param']}" if t.get("param") else "")
    return text + (f" (functions {', '.join(t['functions'])})" if t.get("functions") else "")


def _off(offset) -> str:
    return "variable" if offset is None else str(offset)


# ------------------------------------------------------------------------------ report
def diff(old: dict, new: dict) -> list[Change]:
    return Differ(old, new).run()


def verdict(changes: list[Change]) -> str:
    kinds = {c.kind for c in changes}
    return next((k for k in ORDER if k in kinds), "unchanged")


def bump(changes: list[Change], version: str) -> str:
    """The part of the version a release with these changes bumps (docs/versioning.md)."""
    v = verdict(changes)
    major = int(version.split(".")[0]) if version[:1].isdigit() else 1
    level = {BREAKING: 0, API: 0, COMPATIBLE: 1, DOC: 2}.get(v)
    if level is None:
        return "none"
    if major == 0:
        level = min(level + 1, 2)
    return ("major", "minor", "patch")[level]


def text_report(changes: list[Change], old_label: str, new_label: str, version: str) -> str:
    lines = [f"mipgen diff {old_label} -> {new_label}"]
    for kind in ORDER:
        group = [c for c in changes if c.kind == kind]
        if not group:
            continue
        lines.append(f"\n{kind} ({len(group)}):")
        for c in group:
            lines.append(f"  {c.protocol} {c.where}: {c.what}")
            for lang, renames in sorted(c.names.items()):
                for r in renames:
                    lines.append(f"      {lang}: {r}")
    lines.append(
        f"\nverdict: {verdict(changes)}; version {version}: {bump(changes, version)} bump (docs/versioning.md)"
    )
    return "\n".join(lines) + "\n"


def changelog(changes: list[Change], version: str) -> str:
    """A Markdown changelog section for a release with these changes."""
    heads = {
        BREAKING: "Breaking (wire)",
        API: "Breaking (API: renamed)",
        COMPATIBLE: "Added",
        DOC: "Documentation",
    }
    out = [f"## {version}", "", f"Spec changes: {verdict(changes)} ({bump(changes, version)} release).", ""]
    for kind in ORDER:
        group = [c for c in changes if c.kind == kind]
        if group:
            out.append(f"### {heads[kind]}")
            out.append("")
            out += [f"- {c.protocol} `{c.where}`: {c.what}" for c in group]
            out.append("")
    return "\n".join(out)


def json_report(changes: list[Change], old_label: str, new_label: str, version: str) -> str:
    doc = {
        "old": old_label,
        "new": new_label,
        "verdict": verdict(changes),
        "bump": bump(changes, version),
        "counts": {k: sum(1 for c in changes if c.kind == k) for k in ORDER},
        "changes": [c.as_json() for c in changes],
    }
    return json.dumps(doc, indent=2) + "\n"
