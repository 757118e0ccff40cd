"""What the IR passes share: the loaded spec files, the errors found so far, and the IR under
construction. Each pass reads what earlier passes left here and adds its own part."""

from __future__ import annotations

from typing import Callable

from ..diagnostics import Location, SpecError


class SpecFile:
    """A loaded spec file: its data and a function that locates any path in it."""

    def __init__(self, path: str, data: dict, locate: Callable[[tuple], Location]):
        self.path = path
        self.data = data
        self.locate = locate


class Context:
    """The state of one protocol's build, passed to every pass in order.

    Spec-side entries (`raw_types`, `field_layouts`) hold the spec data with its file and path so
    later passes can locate their errors; IR-side entries hold plain JSON-compatible data. Fields
    and responses carry their location under keys starting with `_` until `assemble` drops them.
    """

    def __init__(self, protocol_file: SpecFile, set_files: list[SpecFile], type_files: list[SpecFile]):
        self.pf = protocol_file
        self.set_files = set_files
        self.type_files = type_files
        self.errors: list[SpecError] = []
        # Devices: manual -> device id, and the device ids in the protocol file's order.
        self.manual_devices: dict[str, str] = {d["manual"]: d["id"] for d in protocol_file.data["devices"]}
        self.device_ids: list[str] = [d["id"] for d in protocol_file.data["devices"]]
        # Protocol-wide defaults for string parameters (MS-CIP: space padding, right-justified).
        self.string_defaults: dict = protocol_file.data.get("strings", {})
        # collect_types: name -> (kind, spec data, file, path) and where each name was defined.
        self.raw_types: dict[str, tuple[str, dict, SpecFile, tuple]] = {}
        self.type_locs: dict[str, Location] = {}
        # Named field layouts shared by several fields (e.g. the GNSS receiver sets).
        self.field_layouts: dict[str, tuple[dict, SpecFile, tuple]] = {}
        # resolve_types: name -> type definition (IR form).
        self.types: dict[str, dict] = {}
        # protocol: the framing with its derived constants, selector name -> value, the sources.
        self.framing: dict = {}
        self.function_values: dict[str, int] = {}
        self.sources: list[dict] = []
        # Later passes: the reserved fields, the sets (sorted by id), the rest of the protocol entry.
        self.reserved: list[dict] = []
        self.sets: list[dict] = []
        self.samples: dict = {}
        self.session: dict | None = None  # session_rule: how replies are matched
        self.session_example: dict | None = None  # session_example: the example program's steps
        self.time: dict = {}  # time_facts: the fields giving a packet its time
        self.simulation: dict | None = None  # simulation: what the simulated device needs
        self.settings: dict | None = None  # settings: the settings files' keyed reads (device command line)
        self.capabilities: dict = {}  # capabilities: per device, the commands and data it supports
        self.link: dict = {}  # link: idle/ping/resume commands, baud rates, bandwidth calculation
        self.layouts: list[dict] = []  # field_layouts in IR form
        self.lookup: dict = {}
        self.value_paths: dict = {}
        self.ir: dict = {}  # assemble: the finished IR document

    def err(self, sf: SpecFile, path: tuple, message: str, expected: str | None = None) -> None:
        self.errors.append(SpecError(sf.locate(path), message, expected))

    def check_sources(self, sf: SpecFile, path: tuple, sources: list[dict]) -> list[dict]:
        """Copies of a `sources:` list, each manual checked against the protocol's devices."""
        known = set(self.manual_devices)
        out = []
        for i, s in enumerate(sources or []):
            if s["manual"] not in known:
                self.err(
                    sf,
                    path + (i, "manual"),
                    f"unknown manual '{s['manual']}'",
                    "one of the manuals listed under devices in the protocol file: " + ", ".join(sorted(known)),
                )
            out.append(dict(s))
        return out

    def devices_of(self, sources: list[dict]) -> list[str]:
        """The devices whose manuals the sources cite, in the protocol file's order."""
        devs = {self.manual_devices[s["manual"]] for s in sources if s["manual"] in self.manual_devices}
        return [d for d in self.device_ids if d in devs]
