"""Pass: the protocol file's `simulation` section, what the simulated device needs beyond the
layouts (docs/spec-format.md "Simulation"; docs/conformance.md section 9), checked against the rest
of the spec and exported as the protocol's `simulation` entry (null without the section).

Checked: every command named is a command of the protocol; every parameter named is a parameter of
one of its layouts (a list's `descriptor`/`decimation` members of the list's struct); every set
number is a data set of the protocol; every device is one of the protocol's devices; the `nack`
members are members of the ack code enum; the filter's enums exist and name their members, and its internal
aiding (the status flag roles, heading update sources, aiding measurement control sources, heading
alignment methods, antenna offsets, dual-antenna status, RTK fix members, aiding status flags,
uncertainties, and the RTCM3 types: station and observation types among the supported ones, the
SPARTN command's parameter) names commands, their parameters, enum and
bitfield members; the descriptor lists' commands, replies and list parameters exist (a reply of that
command whose list runs to the end of the field, of u16 items or of a struct of two u8: set,
descriptor), each gaining its `capacity`, the most entries that fit beside the ack in one packet;
the identity's reply parameters exist (an unsigned integer or a string) and every device gives a
fitting value for every item; each device status reply (`status`) is a response and names unsigned
integer parameters of it or of the structures and union members it holds, and data sets; the world table's sets are data sets and its fields and parameters
exist; every world action's command, parameters and flag exist, it has the keys its action needs,
and an aid's `enabled_by` are members of the enum of the `enable` action's parameter (each aid
gains `enabled_by_values`). The entry keeps the section's shape with sources resolved (each gains
its `title` from the manual).
"""

from __future__ import annotations

from .context import Context, SpecFile

_COMMAND_LISTS = ("formats", "enables", "rates", "polls", "baud")
_UNSIGNED = {"u8", "u16", "u32", "u64"}
# The keys each world action needs besides `command` (the others need none).
_ACTION_KEYS = {
    "capture": ("param",),
    "auto_init": ("param",),
    "frame": ("param",),
    "wait_run": ("param",),
    "enable": ("param", "flag"),
    "aid": ("kind", "enabled_by", "values"),
}


def run(ctx: Context) -> None:
    spec = ctx.pf.data.get("simulation")
    ctx.simulation = None
    if spec is None:
        return
    check = _Checker(ctx, ctx.pf)
    sim = dict(spec)
    check.nack(spec["nack"])
    for key in _COMMAND_LISTS:
        for i, entry in enumerate(spec.get(key, [])):
            check.command_entry(key, (key, i), entry)
    if spec.get("decimation"):
        check.command_entry("decimation", ("decimation",), spec["decimation"])
    for i, name in enumerate(spec.get("all_settings", [])):
        check.command(("all_settings", i), name)
    for key in ("base_rates", "unaddressed", "filters"):
        resolved = []
        for i, entry in enumerate(spec.get(key, [])):
            path = (key, i)
            check.device(path + ("device",), entry["device"])
            for j, r in enumerate(entry.get("rates", [])):
                check.data_set(path + ("rates", j, "set"), r["set"])
            for j, s in enumerate(entry.get("sets", [])):
                check.data_set(path + ("sets", j), s)
            if key == "filters":
                check.members(path + ("states",), entry["states"]["enum"], entry["states"]["members"])
                check.members(path + ("fix",), entry["fix"]["enum"], [entry["fix"]["fix"], entry["fix"]["none"]])
                check.filter_aiding(path, entry)
            resolved.append(
                {**entry, "sources": ctx.check_sources(ctx.pf, ("simulation",) + path + ("sources",), entry["sources"])}
            )
        sim[key] = resolved
    for key in _COMMAND_LISTS + ("all_settings", "base_rates", "unaddressed", "filters"):
        sim.setdefault(key, [])
    sim.setdefault("decimation", None)
    sim["actions"] = check.actions(spec.get("actions", []))
    for i, group in enumerate(spec.get("world", [])):
        check.world(("world", i), group)
    sim.setdefault("world", [])
    sim["descriptor_lists"] = check.descriptor_lists(spec.get("descriptor_lists"))
    sim["identity"] = check.identity(spec.get("identity"))
    sim["status"] = [check.status(("status", i), e) for i, e in enumerate(spec.get("status", []))]
    sim["nmea"] = check.nmea(spec.get("nmea"))
    ctx.simulation = sim


class _Checker:
    def __init__(self, ctx: Context, sf: SpecFile) -> None:
        self.ctx = ctx
        self.sf = sf
        self.commands: dict[str, list[dict]] = {}
        for s in ctx.sets:
            for f in s["fields"]:
                if f["role"] == "command":
                    self.commands.setdefault(f["name"], []).extend(f["variants"])
        self.data_sets = {s["id"] for s in ctx.sets if s["kind"] == "data"}
        self.fields: dict[str, list[tuple[dict, dict]]] = {}
        for s in ctx.sets:
            for f in s["fields"]:
                self.fields.setdefault(f["name"], []).append((s, f))

    def descriptor_lists(self, spec: dict | None) -> dict | None:
        if spec is None:
            return None
        path = ("descriptor_lists",)
        ack = next((r for r in self.ctx.reserved if r["role"] == "ack"), None)
        header = self.ctx.framing.get("field_header_size", 2)
        room = self.ctx.framing.get("max_payload", 255) - header
        if ack is not None:
            room -= header + ack["size"]["max"]
        lists = []
        for i, entry in enumerate(spec["lists"]):
            p = path + ("lists", i)
            out = dict(entry)
            self.command(p + ("command",), entry["command"])
            command = next((f for _, f in self.fields.get(entry["command"], []) if f["role"] == "command"), None)
            reply = next(((s, f) for s, f in self.fields.get(entry["reply"], []) if f["role"] == "response"), None)
            if command is not None and (reply is None or reply[1]["id"] not in command["responses"]):
                self.err(
                    p + ("reply",), f"simulation descriptor_lists: '{entry['reply']}' is not a reply of {entry['command']}",
                    f"the name of a response of {entry['command']}",
                )  # fmt: skip
                reply = None
            item_size = 0
            if reply is not None:
                param = next((q for q in reply[1]["params"] if q["name"] == entry["param"]), None)
                t = (param or {}).get("type", {})
                two_bytes = t.get("kind") == "primitive" and t.get("name") == "u16"
                if t.get("kind") == "struct":
                    members = self.ctx.types[t["name"]]["params"]
                    two_bytes = [q["type"].get("name") for q in members] == ["u8", "u8"]
                if param is None or (param["count"] or {}).get("kind") != "remaining" or not two_bytes:
                    self.err(
                        p + ("param",),
                        f"simulation descriptor_lists: '{entry['param']}' is not a list of {entry['reply']} running to the end of the field, of u16 or of a struct of two u8",
                        "a remaining-count parameter of u16 or {set: u8, descriptor: u8}",
                    )  # fmt: skip
                else:
                    item_size = 2
                out["set"] = reply[0]["id"]
                out["command_descriptor"] = command["id"]
                out["reply_descriptor"] = reply[1]["id"]
                out["item"] = "u16" if t.get("kind") == "primitive" else t.get("name")
            out["capacity"] = room // item_size if item_size else 0
            lists.append(out)
        return {
            **spec,
            "lists": lists,
            "sources": self.ctx.check_sources(self.sf, ("simulation",) + path + ("sources",), spec["sources"]),
            "notes": spec.get("notes", []),
        }

    def status(self, path: tuple, entry: dict) -> dict:
        """A device status reply (sim/status.py): a response whose parameters, in it or in the
        structures and union members it holds, include every named one, each an unsigned integer;
        the stream and message sets are data sets."""
        reply = next((f for _, f in self.fields.get(entry["reply"], []) if f["role"] == "response"), None)
        if reply is None:
            self.err(path + ("reply",), f"simulation status: '{entry['reply']}' is not a response", "a response")
            return dict(entry)
        found: dict[str, str] = {}
        todo = [reply["params"]]
        while todo:
            for q in todo.pop():
                t = q["type"]
                found.setdefault(q["name"], t.get("name", "") if q["count"] is None else "")
                known = self.ctx.types.get(t.get("name", ""), {})
                if t["kind"] == "struct":
                    todo.append(known.get("params", []))
                elif t["kind"] == "union":
                    todo.extend(self.ctx.types[m["type"]]["params"] for m in known.get("members", []))
        named = [(("timer", i), n) for i, n in enumerate(entry.get("timer", []))]
        named += [(("power", i), n) for i, n in enumerate(entry.get("power", []))]
        named += [(("streams", n), n) for n in entry.get("streams", {})]
        named += [(("bytes", k), n) for k, n in entry.get("bytes", {}).items()]
        named += [(("pps", k), n) for k, n in entry.get("pps", {}).items()]
        for i, m in enumerate(entry.get("messages", [])):
            named += [(("messages", i, k), m[k]) for k in ("count", "last")]
            self.data_set(path + ("messages", i, "set"), m["set"])
        for j, number in enumerate(entry.get("streams", {}).values()):
            self.data_set(path + ("streams", j), number)
        for p, name in named:
            if found.get(name) not in _UNSIGNED:
                self.err(
                    path + p, f"simulation status: '{name}' is not an unsigned integer parameter of {entry['reply']}",
                    "the name of an unsigned integer parameter of the reply or of a structure it holds",
                )  # fmt: skip
        sources = self.ctx.check_sources(self.sf, ("simulation",) + path + ("sources",), entry["sources"])
        set_id = next(s["id"] for s, f in self.fields[entry["reply"]] if f is reply)
        return {**entry, "set": set_id, "descriptor": reply["id"], "sources": sources}

    def identity(self, spec: dict | None) -> dict | None:
        if spec is None:
            return None
        items: dict[str, dict] = {}
        reports = []
        for i, r in enumerate(spec["reports"]):
            p = ("identity", "reports", i)
            reply = next((f for _, f in self.fields.get(r["reply"], []) if f["role"] == "response"), None)
            if reply is None:
                self.err(
                    p + ("reply",), f"simulation identity: '{r['reply']}' is not a response", "the name of a response"
                )
                continue
            params, param = reply["params"], None
            for name in r["param"].split("."):
                param = next((q for q in params if q["name"] == name), None)
                if param is None:
                    break
                t = param["type"]
                params = self.ctx.types[t["name"]]["params"] if t["kind"] == "struct" else []
            t = (param or {}).get("type", {})
            kind = "string" if t.get("kind") == "string" else "integer" if t.get("name") in _UNSIGNED else None
            if param is None or kind is None or param["count"] is not None:
                self.err(
                    p + ("param",), f"simulation identity: '{r['param']}' is not a string or unsigned integer parameter of {r['reply']}",
                    "a path of parameter names (a.b) ending at a string or an unsigned integer",
                )  # fmt: skip
                continue
            limit = {"kind": kind, "max": t["length"] if kind == "string" else 256 ** t["size"]["max"] - 1}
            if items.setdefault(r["item"], limit) != limit:
                self.err(
                    p + ("item",),
                    f"simulation identity: item '{r['item']}' is reported by parameters of different types",
                    "one type per item",
                )
            set_id = next(s["id"] for s, f in self.fields[r["reply"]] if f is reply)
            reports.append({**r, "set": set_id, "descriptor": reply["id"], "type": t})
        devices = []
        for i, d in enumerate(spec["devices"]):
            p = ("identity", "devices", i)
            self.device(p + ("device",), d["device"])
            for item, limit in items.items():
                v = d["values"].get(item)
                ok = (
                    isinstance(v, str) and len(v) <= limit["max"] and v.isascii()
                    if limit["kind"] == "string"
                    else isinstance(v, int) and not isinstance(v, bool) and 0 <= v <= limit["max"]
                )
                if not ok:
                    what = (
                        f"an ASCII string of at most {limit['max']} characters"
                        if limit["kind"] == "string"
                        else f"an integer 0..{limit['max']}"
                    )
                    self.err(p + ("values",), f"simulation identity: {d['device']} gives no fitting '{item}'", what)
            for item in d["values"]:
                if item not in items:
                    self.err(
                        p + ("values", item),
                        f"simulation identity: '{item}' is reported by no reply",
                        "an item of reports",
                    )
            devices.append(
                {**d, "sources": self.ctx.check_sources(self.sf, ("simulation",) + p + ("sources",), d["sources"])}
            )
        return {"reports": reports, "items": items, "devices": devices, "notes": spec.get("notes", [])}

    def nmea(self, spec: dict | None) -> dict | None:
        """NMEA output and input (sim/nmea.py): the format and poll commands with their list of
        structs holding the entry's members; the nack a member of the ack code enum; the origins'
        sets data sets; codes and names unique; each sentence's sources origins; the input's set a
        data set and its sentences output sentences. Gains each command's set and descriptor."""
        if spec is None:
            return None
        path = ("nmea",)
        out = dict(spec)
        for key in ("format", "poll"):
            if key not in spec:
                continue
            entry = spec[key]
            variants = self.command(path + (key, "command"), entry["command"])
            params = {q["name"]: q for v in variants for q in v["params"]}
            item = params.get(entry["list"], {}).get("type", {})
            if variants and (entry["list"] not in params or item.get("kind") != "struct"):
                self.err(
                    path + (key, "list"), f"simulation nmea: '{entry['list']}' is not a struct list of {entry['command']}",
                    f"a list parameter of {entry['command']}",
                )  # fmt: skip
                continue
            members = {q["name"] for q in self.ctx.types.get(item.get("name", ""), {}).get("params", [])}
            for role, name in spec["entry"].items():
                if variants and name not in members:
                    self.err(
                        path + ("entry", role), f"simulation nmea: '{name}' is not a member of the entries of {entry['list']}",
                        "a member of the list's struct",
                    )  # fmt: skip
        session = self.ctx.session or {}
        codes = self.ctx.types.get(session.get("code_enum") or "", {}).get("values", [])
        if spec["nack"] not in {v["name"] for v in codes}:
            self.err(
                path + ("nack",), f"simulation nmea: '{spec['nack']}' is not a member of the ack code enum",
                "a member of the ack code enum",
            )  # fmt: skip
        kinds = set()
        for i, o in enumerate(spec["origins"]):
            if o["kind"] in kinds:
                self.err(
                    path + ("origins", i, "kind"), f"simulation nmea: origin '{o['kind']}' twice", "one entry per kind"
                )
            kinds.add(o["kind"])
            for j, number in enumerate(o["sets"]):
                self.data_set(path + ("origins", i, "sets", j), number)
        for key, attr in (("talkers", "id"), ("talkers", "code"), ("sentences", "name"), ("sentences", "code")):
            seen = set()
            for i, e in enumerate(spec[key]):
                if e[attr] in seen:
                    self.err(path + (key, i, attr), f"simulation nmea: {key} {attr} {e[attr]!r} twice", "unique values")
                seen.add(e[attr])
        names = {e["name"] for e in spec["sentences"]}
        for i, e in enumerate(spec["sentences"]):
            for j, kind in enumerate(e["sources"]):
                if kind not in kinds:
                    self.err(
                        path + ("sentences", i, "sources", j),
                        f"simulation nmea: '{kind}' is not an origin",
                        "an origin kind",
                    )
        if "input" in spec:
            self.data_set(path + ("input", "set"), spec["input"]["set"])
            for j, name in enumerate(spec["input"]["sentences"]):
                if name not in names:
                    self.err(
                        path + ("input", "sentences", j),
                        f"simulation nmea: '{name}' is not a sentence",
                        "a sentence name",
                    )
        out["sources"] = self.ctx.check_sources(self.sf, ("simulation",) + path + ("sources",), spec["sources"])
        out["notes"] = spec.get("notes", [])
        return out

    def err(self, path: tuple, message: str, expected: str) -> None:
        self.ctx.err(self.sf, ("simulation",) + path, message, expected)

    def nack(self, nack: dict) -> None:
        session = self.ctx.session or {}
        enum = session.get("code_enum")
        members = {v["name"] for v in self.ctx.types[enum]["values"]} if enum in self.ctx.types else set()
        for role, name in nack.items():
            if name not in members:
                self.err(
                    ("nack", role), f"simulation nack '{role}': '{name}' is not a member of the ack code enum {enum}",
                    "a member of the ack code enum",
                )  # fmt: skip

    def command(self, path: tuple, name: str) -> list[dict]:
        variants = self.commands.get(name)
        if variants is None:
            self.err(path, f"simulation: '{name}' is not a command of the protocol", "the name of a command field")
            return []
        return variants

    def command_entry(self, key: str, path: tuple, entry: dict) -> None:
        variants = self.command(path + ("command",), entry["command"])
        if not variants:
            return
        params = {q["name"]: q for v in variants for q in v["params"]}
        named = [(k, entry[k]) for k in ("set_param", "list", "flag", "param") if k in entry]
        if "selector" in entry:
            named.append(("selector", entry["selector"]["param"]))
        for k, name in named:
            if name not in params:
                self.err(
                    path + (k,), f"simulation {key}: '{name}' is not a parameter of {entry['command']}",
                    f"a parameter of {entry['command']}",
                )  # fmt: skip
        if "set" in entry:
            self.data_set(path + ("set",), entry["set"])
        for j, pair in enumerate((entry.get("selector") or {}).get("sets", [])):
            self.data_set(path + ("selector", "sets", j, "set"), pair["set"])
        item = params.get(entry.get("list", ""), {}).get("type", {})
        members = {q["name"] for q in self.ctx.types.get(item.get("name", ""), {}).get("params", [])}
        for k in ("descriptor", "decimation"):
            if k in entry and entry[k] not in members:
                self.err(
                    path + (k,), f"simulation {key}: '{entry[k]}' is not a member of the entries of {entry['list']}",
                    "a member of the list's struct",
                )  # fmt: skip

    def data_set(self, path: tuple, number: int) -> None:
        if number not in self.data_sets:
            self.err(path, f"simulation: 0x{number:02X} is not a data set of the protocol", "a data set number")

    def device(self, path: tuple, device: str) -> None:
        if device not in self.ctx.device_ids:
            self.err(path, f"simulation: '{device}' is not a device of the protocol", "a device id")

    def members(self, path: tuple, enum: str, names: list[str]) -> None:
        t = self.ctx.types.get(enum)
        if t is None or t["kind"] != "enum":
            self.err(path + ("enum",), f"simulation: '{enum}' is not an enum of the protocol", "an enum name")
            return
        values = {v["name"] for v in t["values"]}
        for name in names:
            if name not in values:
                self.err(path, f"simulation: '{name}' is not a member of {enum}", f"a member of {enum}")

    def bits(self, path: tuple, bitfield: str, names: list[str]) -> None:
        t = self.ctx.types.get(bitfield)
        if t is None or t["kind"] != "bitfield":
            self.err(path + ("type",), f"simulation: '{bitfield}' is not a bitfield of the protocol", "a bitfield name")
            return
        members = {m["name"] for m in t["members"]}
        for name in names:
            if name not in members:
                self.err(path, f"simulation: '{name}' is not a member of {bitfield}", f"a member of {bitfield}")

    def params(self, path: tuple, command: str, names: list[str]) -> None:
        variants = self.command(path + ("command",), command)
        params = {q["name"] for v in variants for q in v["params"]}
        for name in names:
            if variants and name not in params:
                self.err(path, f"simulation: '{name}' is not a parameter of {command}", f"a parameter of {command}")

    def world(self, path: tuple, group: dict) -> None:
        """One group of the world table: its sets are data sets of the protocol, and every field
        and parameter it names is a field of one of them and a parameter of one of its layouts."""
        fields: dict[str, set[str]] = {}
        for j, name in enumerate(group["sets"]):
            found = [s for s in self.ctx.sets if s["name"] == name and s["kind"] == "data"]
            if not found:
                self.err(
                    path + ("sets", j),
                    f"simulation world: '{name}' is not a data set of the protocol",
                    "a data set name",
                )
            for f in (f for s in found for f in s["fields"]):
                fields.setdefault(f["name"], set()).update(q["name"] for v in f["variants"] for q in v["params"])
        for field, shows in group["fields"].items():
            if field not in fields:
                self.err(
                    path + ("fields", field),
                    f"simulation world: '{field}' is not a field of {group['sets']}",
                    "a field name",
                )
                continue
            for param in shows:
                if param not in fields[field]:
                    self.err(
                        path + ("fields", field, param),
                        f"simulation world: '{param}' is not a parameter of {field}",
                        f"a parameter of {field}",
                    )

    def actions(self, actions: list[dict]) -> list[dict]:
        """What commands do to the world: every command, parameter and flag named exists, each
        action has the keys it needs, and an aid's `enabled_by` are members of the enum of the
        `enable` action's parameter (each aid gains their numbers, `enabled_by_values`)."""
        enable = next((a for a in actions if a["action"] == "enable"), {})
        variants = self.commands.get(enable.get("command"), [])
        enum = next(
            (q["type"].get("name") for v in variants for q in v["params"] if q["name"] == enable.get("param")), None
        )
        out = []
        for i, a in enumerate(actions):
            path, entry = ("actions", i), dict(a)
            for k in _ACTION_KEYS.get(a["action"], ()):
                if k not in a:
                    self.err(path, f"simulation: the {a['action']} action of {a['command']} needs `{k}`", k)
            self.params(path, a["command"], [a[k] for k in ("param", "flag") if k in a] + a.get("values", []))
            if "enabled_by" in a:
                if enum not in self.ctx.types or self.ctx.types[enum]["kind"] != "enum":
                    self.err(
                        path + ("enabled_by",), "simulation: `enabled_by` needs an enable action whose `param` is an enum",
                        "an enable action on an enum parameter",
                    )  # fmt: skip
                    continue
                self.members(path + ("enabled_by",), enum, a["enabled_by"])
                numbers = {v["name"]: v["value"] for v in self.ctx.types[enum]["values"]}
                entry["enabled_by_values"] = [numbers.get(n) for n in a["enabled_by"]]
            out.append(entry)
        return out

    def filter_aiding(self, path: tuple, entry: dict) -> None:
        """The internal aiding of one filter (docs/simulator-world.md "Internal aiding")."""
        if "flags" in entry:
            self.bits(path + ("flags",), entry["flags"]["type"], list(entry["flags"]["members"].values()))
        heading = entry.get("heading")
        if heading:
            self.params(path + ("heading",), heading["command"], [heading["param"]])
            self.members(path + ("heading",), heading["enum"], list(heading["members"]))
            if "without_aids" in heading:
                member = heading["without_aids"]["member"]
                self.members(path + ("heading", "without_aids"), heading["enum"], [member])
                if heading["members"].get(member):
                    self.err(
                        path + ("heading", "without_aids", "member"),
                        f"simulation heading: '{member}' enables heading sources: not without aids",
                        "the member that enables no heading source",
                    )
            if "in_use" in heading:
                used = sorted({s for sources in heading["members"].values() for s in sources})
                self.bits(path + ("heading", "in_use"), heading["in_use"], used)
            for i, name in enumerate(heading.get("external", [])):
                self.params(path + ("heading", "external", i), name, ["heading"])
        internal = entry.get("internal")
        if internal:
            self.params(path + ("internal",), internal["command"], [internal["param"], internal["enable"]])
            named = list(internal["members"]) + ([internal["all"]] if "all" in internal else [])
            self.members(path + ("internal",), internal["enum"], named)
        alignment = entry.get("alignment")
        if alignment:
            self.params(path + ("alignment",), alignment["command"], [alignment["param"]])
            self.bits(path + ("alignment",), alignment["type"], list(alignment["members"]))
        antennas = entry.get("antennas")
        if antennas:
            self.params(path + ("antennas",), antennas["command"], [antennas["receiver"], antennas["offset"]])
        dual = entry.get("dual_antenna")
        if dual:
            self.members(path + ("dual_antenna", "fix"), dual["fix"]["enum"], [dual["fix"]["fix"], dual["fix"]["none"]])
            self.bits(path + ("dual_antenna", "flags"), dual["flags"]["type"], list(dual["flags"]["members"].values()))
        rtk = entry.get("rtk")
        if rtk:
            self.members(path + ("rtk", "fix"), rtk["fix"]["enum"], [rtk["fix"]["float"], rtk["fix"]["fixed"]])
            if rtk["fix"]["enum"] != entry["fix"]["enum"]:
                self.err(
                    path + ("rtk", "fix", "enum"),
                    f"simulation: the RTK fix enum '{rtk['fix']['enum']}' is not the filter's fix enum '{entry['fix']['enum']}'",
                    "the enum of the filter's `fix`",
                )
            status = rtk["aiding_status"]
            self.bits(path + ("rtk", "aiding_status"), status["type"], list(status["members"].values()))
            u = rtk["uncertainty"]
            if not u["single"] > u["float"] > u["fixed"]:
                self.err(
                    path + ("rtk", "uncertainty"),
                    "simulation: the position uncertainties must shrink from single point to RTK float to RTK fixed",
                    "single > float > fixed",
                )
            if rtk.get("corrections"):
                self.corrections(path + ("rtk", "corrections"), rtk["corrections"])

    def corrections(self, path: tuple, c: dict) -> None:
        """RTCM3 intake: the station and observation types are supported types, the SPARTN
        command and its parameter exist."""
        for key in ("station", "observations"):
            extra = sorted(set(c[key]) - set(c["types"]))
            if extra:
                self.err(
                    path + (key,),
                    f"simulation: RTCM message types {extra} of `{key}` are not among the supported `types`",
                    "a subset of `types`",
                )
        if set(c["station"]) & set(c["observations"]):
            self.err(
                path + ("station",),
                "simulation: an RTCM message type is both a station position and an observation",
                "disjoint lists",
            )
        if c.get("spartn"):
            self.params(path + ("spartn",), c["spartn"]["command"], [c["spartn"]["param"]])
