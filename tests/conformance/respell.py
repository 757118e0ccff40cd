"""Other spellings of canonical JSON lines, and lines made invalid (docs/conformance.md §5).

`respell` rewrites a line as printed by decode into another line with exactly the same values
under the encoder-input rules of §5: whitespace between tokens, keys in any order, any offset,
integers 0 as -0, floats written with other exponents, extra zeros or integer syntax (the same
decimal value, so the same double and float), NaN bits in either case and the canonical NaN as
its bits, strings with characters escaped as \\u00XX (either case), short escapes or literal
UTF-8, hex in either case, and any text (lone surrogates included) for the unused "error".
`invalidate` makes one change that §5 says must be refused. Both are used by the differential
test; neither calls generated code.
"""

from __future__ import annotations

import random
import re

WS = [" ", "\t", "  ", "\r", ""]
SHORT = {0x08: "\\b", 0x0C: "\\f", 0x0A: "\\n", 0x0D: "\\r", 0x09: "\\t", 0x2F: "\\/"}


# -- a JSON parser that keeps number text ------------------------------------------------------
class _P:
    def __init__(self, s: str):
        self.s = s
        self.i = 0

    def ws(self):
        while self.i < len(self.s) and self.s[self.i] in " \t\r\n":
            self.i += 1

    def value(self):
        self.ws()
        c = self.s[self.i]
        if c == "{":
            self.i += 1
            items = []
            self.ws()
            if self.s[self.i] == "}":
                self.i += 1
                return ("obj", items)
            while True:
                self.ws()
                k = self.string()
                self.ws()
                assert self.s[self.i] == ":"
                self.i += 1
                items.append((k, self.value()))
                self.ws()
                c = self.s[self.i]
                self.i += 1
                if c == "}":
                    return ("obj", items)
                assert c == ","
        if c == "[":
            self.i += 1
            items = []
            self.ws()
            if self.s[self.i] == "]":
                self.i += 1
                return ("arr", items)
            while True:
                items.append(self.value())
                self.ws()
                c = self.s[self.i]
                self.i += 1
                if c == "]":
                    return ("arr", items)
                assert c == ","
        if c == '"':
            return ("str", self.string())
        m = re.compile(r"-?(0|[1-9][0-9]*)(\.[0-9]+)?([eE][+-]?[0-9]+)?").match(self.s, self.i)
        if m and m.end() > self.i:
            self.i = m.end()
            return ("num", m.group(0))
        for lit in ("true", "false", "null"):
            if self.s.startswith(lit, self.i):
                self.i += len(lit)
                return ("lit", lit)
        raise ValueError(f"bad JSON at {self.i}: {self.s[self.i : self.i + 20]!r}")

    def string(self) -> str:
        assert self.s[self.i] == '"'
        self.i += 1
        out = []
        while self.s[self.i] != '"':
            c = self.s[self.i]
            if c == "\\":
                e = self.s[self.i + 1]
                if e == "u":
                    out.append(chr(int(self.s[self.i + 2 : self.i + 6], 16)))
                    self.i += 6
                    continue
                out.append({"b": "\b", "f": "\f", "n": "\n", "r": "\r", "t": "\t"}.get(e, e))
                self.i += 2
                continue
            out.append(c)
            self.i += 1
        self.i += 1
        return "".join(out)


def parse(line: str):
    p = _P(line)
    v = p.value()
    p.ws()
    assert p.i == len(line), line
    return v


# -- spellings ---------------------------------------------------------------------------------
def respell_number(text: str, rng: random.Random) -> str:
    """The same decimal value written differently (an integer stays an integer, see §5)."""
    if not re.search(r"[.eE]", text):
        return "-0" if text == "0" and rng.random() < 0.5 else text
    m = re.fullmatch(r"(-?)([0-9]+)(?:\.([0-9]+))?(?:[eE]([+-]?[0-9]+))?", text)
    sign, ip, fp, ex = m.group(1), m.group(2), m.group(3) or "", int(m.group(4) or 0)
    digits = (ip + fp).lstrip("0")  # value = int(digits) * 10**exp
    exp = ex - len(fp)
    if not digits:  # zero: keep the sign
        return sign + rng.choice(["0", "0.0", "0e5", "0.000E-3", "0.0e+0"])
    z = rng.choice([0, 0, 1, 3])
    digits += "0" * z
    exp -= z
    k = rng.choice([1, len(digits), 0, rng.randint(0, len(digits))])
    return _place(sign, digits, k, exp, rng)


def _place(sign: str, digits: str, k: int, exp: int, rng: random.Random) -> str:
    """sign + digits with the point after k digits, value int(digits) * 10**exp."""
    # int(digits) * 10**exp = d1.d2... with point after k digits -> exponent e = exp + len(digits) - k
    e = exp + len(digits) - k
    if k == 0:
        mant = "0." + digits
    elif k == len(digits):
        mant = digits
        if rng.random() < 0.5:
            mant += ".0"
    else:
        mant = digits[:k] + "." + digits[k:]
    if e == 0 and rng.random() < 0.5:
        return sign + mant
    mark = rng.choice(["e", "E"])
    es = str(e) if e < 0 else rng.choice(["", "+"]) + str(e)
    return f"{sign}{mant}{mark}{es}"


def respell_string(s: str, rng: random.Random, kind: str) -> str:
    if kind == "error":  # not used by the encoder: any text
        s = rng.choice(["", "x", "\\ud800", "\u00e9\u4e2d", "\\udfff\\ud800", "line\\n2"]) if rng.random() < 0.7 else s
        if "\\" in s:
            return '"' + s + '"'
    if kind == "hex":
        s = "".join(c.upper() if rng.random() < 0.5 else c for c in s)
    out = ['"']
    for ch in s:
        b = ord(ch)
        r = rng.random()
        if ch == '"':
            out.append(rng.choice(['\\"', "\\u0022"]))
        elif ch == "\\":
            out.append(rng.choice(["\\\\", "\\u005c", "\\u005C"]))
        elif b < 0x20:
            out.append(SHORT.get(b) if b in SHORT and r < 0.5 else "\\u%04x" % b if r < 0.75 else "\\u%04X" % b)
        elif b == 0x2F and r < 0.3:
            out.append("\\/")
        elif r < 0.2:
            out.append(("\\u%04x" if rng.random() < 0.5 else "\\u%04X") % b)
        else:
            out.append(ch)  # printable ASCII, DEL and U+0080..U+00FF literal (UTF-8 on the wire)
    out.append('"')
    return "".join(out)


def _ws(rng):
    return rng.choice(WS) if rng.random() < 0.3 else ""


def emit(node, rng: random.Random, ctx: str = "top", key: str = "") -> str:
    """A spelling of node; ctx is where it stands: "top" (the line), "field" (an entry of
    fields), "values" (anything under values)."""
    kind, v = node
    if kind == "obj":
        items = list(v)
        rng.shuffle(items)
        parts = []
        for k, x in items:
            if ctx == "top" and k == "offset":
                x = ("num", str(rng.choice([0, 1, 2**64 - 1, rng.randrange(2**64)])))
            inner = "field" if ctx == "top" and k == "fields" else "values" if ctx in ("field", "values") else ctx
            key_text = respell_string(k, rng, "key")
            parts.append(_ws(rng) + key_text + _ws(rng) + ":" + _ws(rng) + emit(x, rng, inner, k))
        return "{" + ",".join(parts) + _ws(rng) + "}"
    if kind == "arr":
        return "[" + ",".join(_ws(rng) + emit(x, rng, ctx, key) + _ws(rng) for x in v) + "]"
    if kind == "num":
        return respell_number(v, rng)
    if kind == "lit":
        return v
    if ctx in ("top", "field") and key in ("data", "trailing", "skipped"):
        return respell_string(v, rng, "hex")
    if ctx == "field" and key == "error":
        return respell_string(v, rng, "error")
    if ctx == "values" and (v == "nan" or v.startswith("nan:0x") or v in ("inf", "-inf")):
        return _nan_text(v, rng)
    return respell_string(v, rng, "text")


def _nan_text(v: str, rng: random.Random) -> str:
    if v.startswith("nan:0x"):
        return '"nan:0x' + "".join(c.upper() if rng.random() < 0.5 else c for c in v[6:]) + '"'
    return '"' + v + '"'


def respell(line: str, rng: random.Random) -> str:
    """Another spelling of a canonical line with the same bytes (§5)."""
    return _ws(rng) + emit(parse(line), rng) + _ws(rng)


# -- lines that must be refused ----------------------------------------------------------------
def _canon(node) -> str:
    kind, v = node
    if kind == "obj":
        return "{" + ",".join(_json_str(k) + ":" + _canon(x) for k, x in v) + "}"
    if kind == "arr":
        return "[" + ",".join(_canon(x) for x in v) + "]"
    if kind == "str":
        return _json_str(v)
    return v


def _json_str(s: str) -> str:
    out = ['"']
    for ch in s:
        b = ord(ch)
        if ch in '"\\':
            out.append("\\" + ch)
        elif b < 0x20 or b >= 0x7F:
            out.append("\\u%04x" % b)
        else:
            out.append(ch)
    out.append('"')
    return "".join(out)


def _spots(node, path=()):
    """(path, node) of every value under a decoded field's "values" (the parameters)."""
    kind, v = node
    if kind == "obj":
        for k, x in v:
            yield from _spots(x, path + (k,))
    elif kind == "arr":
        for i, x in enumerate(v):
            yield from _spots(x, path + (i,))
    if "values" in path and path[-1] != "values":
        yield path, node


def _replace(node, path, new):
    if not path:
        return new
    kind, v = node
    head, rest = path[0], path[1:]
    if kind == "obj":
        return ("obj", [(k, _replace(x, rest, new) if k == head else x) for k, x in v])
    return ("arr", [_replace(x, rest, new) if i == head else x for i, x in enumerate(v)])


def invalidate(line: str, rng: random.Random) -> tuple[str, str]:
    """One change §5 says every encoder must refuse, and what it was."""
    tree = parse(line)
    values = [(p, n) for p, n in _spots(tree) if n[0] in ("num", "str", "lit")]
    r = rng.random()
    if values and r < 0.6:
        path, (kind, v) = rng.choice(values)
        where = ".".join(map(str, path))
        if kind == "num" and not re.search(r"[.eE]", v):
            new, what = ("num", rng.choice(["1.5", "1e2", "18446744073709551616", "-9223372036854775809"])), "integer"
        elif kind == "num":
            new, what = ("num", rng.choice(["1e999", "-1e999", "1.8e308"])), "float overflow"
        elif kind == "str" and (v.startswith("nan") or v in ("inf", "-inf")):
            # (none of these is a string of the same length, should v be a string parameter)
            options = ["nan:0x", "Infinity", v + "0"] + (["NaN"] if len(v) != 3 else [])
            new, what = ("str", rng.choice(options)), "float text"
        elif kind == "str":
            new, what = ("str", v + rng.choice(["a", "\u00ff", "\u0100"])), "string length"
        elif v in ("true", "false"):
            new, what = ("num", rng.choice(["0", "1"])), "bool"
        else:  # null (a union member without data)
            new, what = ("obj", [("zz", ("num", "1"))]), "null"
        return _canon(_replace(tree, path, new)), f"{where}: {what} {_canon(new)}"
    kind, top = tree
    keys = [k for k, _ in top]
    choice = rng.choice(["drop", "extra", "dup", "garbage", "hex", "name"])
    if choice == "hex" and "skipped" in keys:
        return _canon(("obj", [(k, ("str", x[1] + "a") if k == "skipped" else x) for k, x in top])), "odd hex"
    if choice == "name" and "fields" in keys:
        fields = dict(top)["fields"][1]
        for i, f in enumerate(fields):
            if any(k == "name" for k, _ in f[1]):
                new = ("obj", [(k, ("str", x[1] + "_") if k == "name" else x) for k, x in f[1]])
                return _canon(_replace(tree, ("fields", i), new)), f"fields[{i}].name"
    if choice == "drop":
        k = rng.choice(keys)
        return _canon(("obj", [(a, x) for a, x in top if a != k])), f"without {k}"
    if choice == "dup":
        k, x = rng.choice(top)
        return _canon(("obj", top + [(k, x)])), f"{k} twice"
    if choice == "garbage":
        return _canon(tree) + rng.choice([" x", ",", "}", " {}"]), "text after the object"
    return _canon(("obj", top + [("sample", ("num", "0"))])), "extra key"
