"""Overlays: a user's spec directories given after the project's (`mipgen generate --spec spec DIR`).

An overlay mirrors the spec's layout: `DIR/<protocol>/*.yaml`. Its set files and types files join
those of the protocol of the same directory name (a set file with the number of an existing set
adds descriptors to it, as a "part"; a descriptor defined twice is a located error naming both
places). Additions to what the protocol file or another file already defines come in an
extension file (`extends: <protocol>`): devices, and values or members appended to existing
enums and bitfields. The additions are appended to the data of the file that defines the thing,
and every path into an appended item is located in the extension file, so the IR passes check
them (and report their errors) exactly as if the spec had them.
"""

from __future__ import annotations

import difflib

from .diagnostics import Location, SpecError
from .passes.context import SpecFile


class _Redirects:
    """A file's locate function, with the items appended from extension files located there."""

    def __init__(self, base):
        self.base = base
        # (list path in this file, number of items it had, extension file, list path there)
        self.moves: list[tuple[tuple, int, SpecFile, tuple]] = []

    def __call__(self, path: tuple) -> Location:
        for prefix, count, ext, ext_prefix in self.moves:
            n = len(prefix)
            if path[:n] == prefix and len(path) > n and isinstance(path[n], int) and path[n] >= count:
                return ext.locate(ext_prefix + (path[n] - count,) + tuple(path[n + 1 :]))
        return self.base(path)


def _redirects(sf: SpecFile) -> _Redirects:
    if not isinstance(sf.locate, _Redirects):
        sf.locate = _Redirects(sf.locate)
    return sf.locate


def _append(target: SpecFile, prefix: tuple, items: list, ext: SpecFile, ext_prefix: tuple) -> None:
    container = target.data
    for key in prefix[:-1]:
        container = container[key]
    lst = container.setdefault(prefix[-1], [])
    _redirects(target).moves.append((prefix, len(lst), ext, ext_prefix))
    lst.extend(items)


def _named_types(files: list[SpecFile], key: str) -> dict[str, tuple[SpecFile, int]]:
    """name -> (file, index in its `key` list) for the enums or bitfields of every file."""
    out: dict[str, tuple[SpecFile, int]] = {}
    for sf in files:
        for i, t in enumerate(sf.data.get(key) or []):
            if isinstance(t, dict) and isinstance(t.get("name"), str):
                out.setdefault(t["name"], (sf, i))
    return out


def closest(name: str, candidates, n: int = 3) -> str:
    """'did you mean ...' text for an unknown name ('' when nothing is close)."""
    near = difflib.get_close_matches(name, sorted(candidates), n=n, cutoff=0.6)
    return ("did you mean " + " or ".join(f"'{x}'" for x in near) + "?") if near else ""


def apply_extensions(protocol_file: SpecFile, others: list[SpecFile], extensions: list[SpecFile]) -> list[SpecError]:
    """Appends the additions of the extension files to the files that define what they extend;
    the located errors of additions that cannot apply."""
    errors: list[SpecError] = []
    files = [protocol_file, *others]
    pid = protocol_file.data.get("protocol")
    for ext in extensions:
        d = ext.data
        if d["extends"] != pid:
            errors.append(
                SpecError(
                    ext.locate(("extends",)),
                    f"this file extends protocol '{d['extends']}' but sits in the directory of '{pid}'",
                    f"extends: {pid}, or the file moved to the directory of its protocol",
                )
            )
            continue
        if d.get("devices"):
            known_ids = {x["id"]: x for x in protocol_file.data["devices"]}
            known_manuals = {x["manual"]: x for x in protocol_file.data["devices"]}
            before = len(errors)
            for i, dev in enumerate(d["devices"]):
                for key, known in (("id", known_ids), ("manual", known_manuals)):
                    if dev[key] in known:
                        errors.append(
                            SpecError(
                                ext.locate(("devices", i, key)),
                                f"device {key} '{dev[key]}' is already defined by {protocol_file.path}"
                                f" (device '{known[dev[key]]['id']}')",
                                f"a new device {key}",
                            )
                        )
            if len(errors) == before:
                _append(protocol_file, ("devices",), d["devices"], ext, ("devices",))
        for key, items_key, what in (("enums", "values", "enum"), ("bitfields", "members", "bitfield")):
            defined = _named_types(files, key)
            for i, add in enumerate(d.get(key) or []):
                where = defined.get(add["name"])
                if where is None:
                    hint = closest(add["name"], defined)
                    errors.append(
                        SpecError(
                            ext.locate((key, i, "name")),
                            f"no {what} named '{add['name']}' to extend" + (f"; {hint}" if hint else ""),
                            f"the name of an {what} of protocol '{pid}' (a new {what} goes in a types file)",
                        )
                    )
                    continue
                target, index = where
                _append(target, (key, index, items_key), add[items_key], ext, (key, i, items_key))
    return errors
