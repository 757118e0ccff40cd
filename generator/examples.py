"""The "getting started" example program every language back end renders into its package.

Each package gets `examples/getting_started.<ext>`: run as `getting_started FILE`, it builds the
example command with the packet builder and its typed value and prints `command <hex>`, then
feeds FILE to the stream parser in blocks of `BLOCK_SIZE` bytes, flushes it at the end, and
prints `packet set=0xSS fields=NAME,...` (`?` for an entry that is not a decoded field) for
every packet and `skipped N` for every skip run. The documentation quotes the parts between the
marker comments `[build-command]`, `[parse-stream]`, `[read-file]` and `[end]`.

The example command is chosen from the IR by a data rule, never by name (see example_command);
the back ends only map it to their own names (their `api_names`).
"""

from __future__ import annotations

from typing import Callable

from .render import ToolError

# The source file of the example in each package, without its extension, and the block size the
# program reads its input in.
PROGRAM = "getting_started"
BLOCK_SIZE = 4096
# Comment lines that mark the parts the documentation cuts out (each part is closed by END).
PARTS = ("build-command", "parse-stream", "read-file")
END = "end"


class ExampleError(ToolError):
    """The spec has no command the example can send (reported like a tool error, no traceback)."""


def _is_plain_command(field: dict) -> bool:
    """A command without parameters, function selector or per-device layouts."""
    return (
        field["role"] == "command"
        and field["params"] == []
        and field["functions"] is None
        and len(field["variants"]) == 1
    )


def example_command(protocol: dict) -> tuple[dict, dict]:
    """(set, field) of the example command: in the command set with the lowest id, the first
    field (in spec order) with role "command", no parameters, one variant and no function
    selector. Raises ExampleError when no command set has one."""
    command_sets = sorted((s for s in protocol["sets"] if s["kind"] == "command"), key=lambda s: s["id"])
    if not command_sets:
        raise ExampleError(f"protocol {protocol['name']} has no command set for the getting-started example")
    first = command_sets[0]
    for field in first["fields"]:
        if _is_plain_command(field):
            return first, field
    raise ExampleError(
        f"protocol {protocol['name']}: command set {first['name']} (0x{first['id']:02X}) has no command without"
        " parameters for the getting-started example"
    )


def example_context(protocol: dict, api_names: Callable[[dict, dict, dict], dict]) -> dict:
    """What an example template prints besides the back end's own context: the chosen command
    (set and field of the IR, and the back end's names for it) and the block size."""
    set_, field = example_command(protocol)
    return {
        "program": PROGRAM,
        "block_size": BLOCK_SIZE,
        "set": set_,
        "field": field,
        "api": api_names(protocol, set_, field),
    }
