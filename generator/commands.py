"""The language-neutral command model: every command layout and every typed call, decided once.

The IR says what a command is on the wire (its layouts, functions, parameters, replies with their
`when`, ack suppression, timeout allowance); a session back end needs the same reading of it in
every language: which calls the typed API has (one per command and function, split per device
when the layouts of the devices need different arguments), which parameters are arguments and
which of them are required (`optional_for`), which counts the call sets from their arrays, which
reply field a call returns, and for the session facts, per layout, the expected replies with
their conditions, the ack suppression and the timeout allowance, with function names resolved to
selector values and enum value names to integers. This module answers those questions once, as
frozen records, so that a back end only names them and its templates own the syntax (as
generator/model.py does for parameter layouts).

`commands(proto)` is a pure function of one protocol's IR (no naming, no target syntax);
`export(proto)` is its JSON form, the protocol entry's `commands` in generated/ir.json
(docs/ir.md), so a third-party back end gets the same answers.
"""

from __future__ import annotations

from dataclasses import dataclass

from generator import model

# What a call returns (Call.reply_kind).
NO_REPLY = "none"  # no reply field for this function: the call returns when the ack comes
FIELD = "field"  # exactly one reply field: the call returns it
ANY = "any"  # several possible reply fields: the call returns whichever field came
REPLY_KINDS = (NO_REPLY, FIELD, ANY)


@dataclass(frozen=True)
class Function:
    """One value of the protocol's function selector (`devices`: the devices it is limited to,
    empty for all)."""

    name: str
    value: int
    devices: tuple[str, ...] = ()


@dataclass(frozen=True)
class Condition:
    """When a reply is expected or an ack suppressed: the function selected (name and value), a
    parameter of the layout and the integer value it must have (an enum value name resolved;
    `value` None with a `param`: any non-zero value), each None when it does not matter."""

    function: str | None = None
    function_value: int | None = None
    param: str | None = None
    value: int | None = None


@dataclass(frozen=True)
class Reply:
    """One reply field a command layout may answer with (a response of the same set), and when."""

    descriptor: int
    name: str
    when: Condition | None


@dataclass(frozen=True)
class Allowance:
    """Extra time a long command gets (the IR's `timeout`): `ms`, plus the value of `param` in
    milliseconds when given, for the listed functions (None: every function)."""

    ms: int
    param: str | None
    functions: tuple[str, ...] | None
    function_values: tuple[int, ...] | None


@dataclass(frozen=True)
class Layout:
    """The session facts of one command layout (a variant of a command field): the row every
    session's command table holds."""

    protocol: str
    set: int
    set_name: str
    descriptor: int
    field: str
    variant: int  # index in the field's `variants`
    device: str | None  # the layout's device when the field has per-device layouts, else None
    devices: tuple[str, ...]  # the devices this layout applies to
    field_devices: tuple[str, ...]  # the devices any layout of the field applies to, sorted
    functions: tuple[str, ...] | None  # the layout's functions (None: no function selector)
    function_values: tuple[int, ...] | None
    replies: tuple[Reply, ...]
    ack_suppressed_by: Condition | None
    timeout: Allowance | None
    # The parameters the conditions above read (reply `when`, ack suppression, allowance), in the
    # order first read: a session keeps their values per pending command.
    reads: tuple[str, ...]


@dataclass(frozen=True)
class Argument:
    """A parameter of a layout that a call takes as an argument. `required`: the caller must give
    it (not optional in the layout, or optional but limited to functions and not optional for
    this one: `optional_for`); `optional`: the layout may leave it out (so a required argument
    of an optional parameter is stored as present)."""

    name: str
    required: bool
    optional: bool
    param: model.Param  # the parameter's model (its kind, element type, count)


@dataclass(frozen=True)
class Count:
    """A count parameter the call sets from the length of the array it counts."""

    param: str
    optional: bool  # the count parameter is optional in the layout
    array: str
    array_optional: bool  # the array parameter is optional in the layout
    array_required: bool  # the array is a required argument of this call
    elem: model.Elem  # the count parameter's type


@dataclass(frozen=True)
class ReplyField:
    """The reply field a call returns (a field of the command's set)."""

    descriptor: int
    name: str
    per_device: bool  # the field has per-device layouts (no single type to return)


@dataclass(frozen=True)
class Call:
    """One call of the typed command API: a command with one function (or none, for a command
    without a function selector), for the layouts that take the same arguments. `device` is set
    when the function's layouts need different arguments per device (one call per device: this
    call is for the layouts `variants`, named by the device of the first); else None."""

    protocol: str
    set: int
    set_name: str
    descriptor: int
    field: str
    function: str | None
    function_value: int | None
    device: str | None
    variants: tuple[int, ...]  # indexes of the field's layouts this call builds, spec order
    devices: tuple[str | None, ...]  # their `device` (None for a field with one layout)
    arguments: tuple[Argument, ...]  # required first, then optional; layout order within each
    counts: tuple[Count, ...]  # in layout order
    reply_kind: str  # NO_REPLY, FIELD or ANY
    reply: ReplyField | None  # for FIELD


@dataclass(frozen=True)
class ApiCommand:
    """The calls of one command (a field of a command set), as a typed API groups them."""

    descriptor: int
    field: str
    calls: tuple[Call, ...]


@dataclass(frozen=True)
class ApiSet:
    """The commands of one command set that have calls, as a typed API groups them."""

    set: int
    set_name: str
    commands: tuple[ApiCommand, ...]


@dataclass(frozen=True)
class Commands:
    """A protocol's command model: its function selector values, every command layout and every
    call, in spec order (sets, then fields, then layouts or functions)."""

    protocol: str
    function_enum: str | None
    functions: tuple[Function, ...]
    layouts: tuple[Layout, ...]
    calls: tuple[Call, ...]

    def api_sets(self) -> tuple[ApiSet, ...]:
        """The calls grouped as every typed API presents them: per set, per command, spec order."""
        groups: dict[int, dict[int, list[Call]]] = {}
        for c in self.calls:
            groups.setdefault(c.set, {}).setdefault(c.descriptor, []).append(c)
        out = []
        for by_descriptor in groups.values():
            cmds = tuple(ApiCommand(cs[0].descriptor, cs[0].field, tuple(cs)) for cs in by_descriptor.values())
            out.append(ApiSet(cmds[0].calls[0].set, cmds[0].calls[0].set_name, cmds))
        return tuple(out)

    def calls_of(self, set_id: int, field: str) -> tuple[Call, ...]:
        return tuple(c for c in self.calls if c.set == set_id and c.field == field)

    def layouts_of(self, set_id: int, field: str) -> tuple[Layout, ...]:
        return tuple(x for x in self.layouts if x.set == set_id and x.field == field)

    def call(self, set_id: int, field: str, function: str | None, device: str | None) -> Call | None:
        """The call of function (None: the plain command) that a program for `device` makes: the
        one split off for that device, else the one for every device."""
        calls = [c for c in self.calls_of(set_id, field) if c.function == function]
        for c in calls:
            if c.device is not None and c.device == device:
                return c
        return next((c for c in calls if c.device is None), None)


# ---------------------------------------------------------------------------------------- building
def _int_value(types: dict, tref: dict, value) -> int | None:
    """An enum value name (or an integer) of a parameter's type as an integer."""
    if value is None or isinstance(value, int):
        return value
    t = types[tref["name"]]
    return next(v["value"] for v in t["values"] if v["name"] == value)


def _condition(types: dict, fvalues: dict, params: dict, w: dict | None) -> Condition | None:
    if not w:
        return None
    param = w.get("param")
    return Condition(
        function=w.get("function"),
        function_value=fvalues[w["function"]] if "function" in w else None,
        param=param,
        value=_int_value(types, params[param]["type"], w.get("value")) if param else None,
    )


def _layout(proto: dict, types: dict, fvalues: dict, s: dict, f: dict, index: int) -> Layout:
    v = f["variants"][index]
    params = {q["name"]: q for q in v["params"]}
    reads: list[str] = []
    replies = []
    for r in v["responses"]:
        when = _condition(types, fvalues, params, r["when"])
        if when is not None and when.param:
            reads.append(when.param)
        replies.append(Reply(r["id"], r["name"], when))
    ack = _condition(types, fvalues, params, v["ack_suppressed_by"])
    if ack is not None and ack.param:
        reads.append(ack.param)
    t = v.get("timeout")
    timeout = None
    if t is not None:
        fns = tuple(t["functions"]) if t["functions"] else None
        timeout = Allowance(t["ms"], t["param"], fns, tuple(fvalues[x] for x in fns) if fns else None)
        if t["param"]:
            reads.append(t["param"])
    functions = tuple(v["functions"]) if v["functions"] is not None else None
    return Layout(
        protocol=proto["name"],
        set=s["id"],
        set_name=s["name"],
        descriptor=f["id"],
        field=f["name"],
        variant=index,
        device=v["device"],
        devices=tuple(v["devices"]),
        field_devices=tuple(sorted({d for x in f["variants"] for d in x["devices"]})),
        functions=functions,
        function_values=tuple(fvalues[x] for x in functions) if functions is not None else None,
        replies=tuple(replies),
        ack_suppressed_by=ack,
        timeout=timeout,
        reads=tuple(dict.fromkeys(reads)),
    )


def required(q: dict, function: str | None) -> bool:
    """Whether IR parameter q is a required argument of the call of `function`: it is not
    optional, or it is limited to functions and is not optional for this one (`optional_for`)."""
    return (q["functions"] is not None and function not in (q["optional_for"] or [])) or not q["optional"]


def _signature(proto: dict, v: dict, fn: str | None) -> tuple[tuple[Argument, ...], tuple[Count, ...]]:
    """The arguments and counts of the call of function fn for layout v."""
    pm = model.layout(proto, v)
    counted = {q.count_param: q for q in pm.params if q.count_param}
    args: list[Argument] = []
    counts: list[model.Param] = []
    for q in pm.params:
        if q.function:
            continue
        if q.functions is not None and fn not in q.functions:
            continue
        if q.name in counted:
            counts.append(q)
            continue
        args.append(Argument(q.name, required(q.ir, fn), q.optional, q))
    by_name = {a.name: a for a in args}
    out_counts = []
    for q in counts:
        arr = counted[q.name]
        out_counts.append(
            Count(
                param=q.name,
                optional=q.optional,
                array=arr.name,
                array_optional=arr.optional,
                array_required=by_name[arr.name].required if arr.name in by_name else False,
                elem=q.elem,
            )
        )
    ordered = [a for a in args if a.required] + [a for a in args if not a.required]
    return tuple(ordered), tuple(out_counts)


def _key(args: tuple[Argument, ...]) -> tuple:
    """What makes two layouts' calls the same call: the same arguments, each with the same name,
    required-ness, type and count (whether the layout may leave a required argument's parameter
    out does not change what the caller gives)."""
    return tuple((a.name, a.required, repr(a.param.ir["type"]), repr(a.param.ir["count"])) for a in args)


def _reply(s: dict, variants: list[dict], fn: str | None) -> tuple[str, ReplyField | None]:
    """What a call of function fn for these layouts returns: the replies whose `when` does not
    name another function."""
    ids: list[int] = []
    for v in variants:
        for r in v["responses"]:
            w = r["when"] or {}
            if "function" in w and w["function"] != fn:
                continue
            if r["id"] not in ids:
                ids.append(r["id"])
    if not ids:
        return NO_REPLY, None
    if len(ids) > 1:
        return ANY, None
    target = next(f for f in s["fields"] if f["id"] == ids[0])
    return FIELD, ReplyField(target["id"], target["name"], model.per_device(target))


def _calls(proto: dict, fvalues: dict, s: dict, f: dict) -> list[Call]:
    variants = f["variants"]
    plain = variants[0]["functions"] is None
    functions: list[str] = []
    for v in variants:
        for fn in v["functions"] or []:
            if fn not in functions:
                functions.append(fn)
    out = []
    for fn in [None] if plain else functions:
        groups: dict[tuple, list[tuple[int, tuple, tuple]]] = {}
        for i, v in enumerate(variants):
            if fn is not None and fn not in (v["functions"] or []):
                continue
            args, counts = _signature(proto, v, fn)
            groups.setdefault(_key(args), []).append((i, args, counts))
        split = len(groups) > 1
        for group in groups.values():
            first, args, counts = group[0]
            kind, reply = _reply(s, [variants[i] for i, _a, _c in group], fn)
            out.append(
                Call(
                    protocol=proto["name"],
                    set=s["id"],
                    set_name=s["name"],
                    descriptor=f["id"],
                    field=f["name"],
                    function=fn,
                    function_value=fvalues[fn] if fn is not None else None,
                    device=variants[first]["device"] if split else None,
                    variants=tuple(i for i, _a, _c in group),
                    devices=tuple(variants[i]["device"] for i, _a, _c in group),
                    arguments=args,
                    counts=counts,
                    reply_kind=kind,
                    reply=reply,
                )
            )
    return out


def commands(proto: dict) -> Commands:
    """The command model of one protocol's IR entry."""
    types = {t["name"]: t for t in proto["types"]}
    fenum = (proto.get("function_selector") or {}).get("enum")
    functions = (
        tuple(Function(v["name"], v["value"], tuple(v.get("devices") or ())) for v in types[fenum]["values"])
        if fenum
        else ()
    )
    fvalues = {fn.name: fn.value for fn in functions}
    layouts: list[Layout] = []
    calls: list[Call] = []
    for s in proto["sets"]:
        if s["kind"] != "command":
            continue
        for f in s["fields"]:
            if f["role"] != "command":
                continue
            layouts.extend(_layout(proto, types, fvalues, s, f, i) for i in range(len(f["variants"])))
            calls.extend(_calls(proto, fvalues, s, f))
    return Commands(proto["name"], fenum, functions, tuple(layouts), tuple(calls))


# ------------------------------------------------------------------------------------------ export
def _condition_json(c: Condition | None) -> dict | None:
    if c is None:
        return None
    return {"function": c.function, "function_value": c.function_value, "param": c.param, "value": c.value}


def export(proto: dict) -> dict:
    """The command model of a protocol as plain JSON data (the `commands` entry of ir.json)."""
    m = commands(proto)
    return {
        "functions": [{"name": x.name, "value": x.value, "devices": list(x.devices)} for x in m.functions],
        "layouts": [
            {
                "set": x.set,
                "descriptor": x.descriptor,
                "field": x.field,
                "variant": x.variant,
                "device": x.device,
                "devices": list(x.devices),
                "functions": list(x.functions) if x.functions is not None else None,
                "function_values": list(x.function_values) if x.function_values is not None else None,
                "replies": [
                    {"descriptor": r.descriptor, "name": r.name, "when": _condition_json(r.when)} for r in x.replies
                ],
                "ack_suppressed_by": _condition_json(x.ack_suppressed_by),
                "timeout": (
                    None
                    if x.timeout is None
                    else {
                        "ms": x.timeout.ms,
                        "param": x.timeout.param,
                        "functions": list(x.timeout.functions) if x.timeout.functions else None,
                        "function_values": list(x.timeout.function_values) if x.timeout.function_values else None,
                    }
                ),
                "reads": list(x.reads),
            }
            for x in m.layouts
        ],
        "calls": [
            {
                "set": c.set,
                "descriptor": c.descriptor,
                "field": c.field,
                "function": c.function,
                "function_value": c.function_value,
                "device": c.device,
                "variants": list(c.variants),
                "arguments": [{"name": a.name, "required": a.required, "optional": a.optional} for a in c.arguments],
                "counts": [{"param": k.param, "array": k.array} for k in c.counts],
                "reply": c.reply_kind,
                "reply_field": None if c.reply is None else {"descriptor": c.reply.descriptor, "name": c.reply.name},
            }
            for c in m.calls
        ],
    }
