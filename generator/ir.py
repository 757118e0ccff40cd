"""Build the one intermediate representation (IR) from loaded spec files, with semantic checks.

The IR is plain JSON-compatible data (dicts, lists, ints, strings) so that it can be exported
as generated/ir.json unchanged; every back end consumes exactly that structure. docs/ir.md
documents it. All decisions (sizes, offsets, optionality, dispatch tables, response links)
are made here, so templates stay dumb.

The build is a list of passes run in order over one shared Context (generator/passes/): each
pass is a module named for what it does, reads what the passes before it produced, adds its own
part and records located errors. Every pass runs even after errors, so one run reports as many
problems as it can; the caller raises them together.
"""

from __future__ import annotations

from .diagnostics import SpecError
from .passes import (
    assemble,
    capabilities,
    collect_types,
    field_layouts,
    irregular_lengths,
    link,
    link_responses,
    lookup_order,
    protocol_file,
    reserved_fields,
    resolve_types,
    sample_rule,
    session_example,
    session_rule,
    sets,
    settings,
    simulation,
    size_limits,
    time_facts,
    value_paths,
    variants,
)
from .passes.context import Context, SpecFile

IR_VERSION = 1

PASSES = (
    collect_types,  # named types and field layouts from every file; duplicates
    resolve_types,  # enums, bitfields, structs, unions in dependency order, with sizes
    protocol_file,  # derived framing constants, the function selector, the protocol's sources
    reserved_fields,  # the reserved fields (ack/nack) every set of a kind answers
    sets,  # descriptor sets and their fields (parts, descriptors, names, roles)
    variants,  # each field's layouts, one per device where the spec has variants
    link_responses,  # responses to response fields of the same set; the reply code rule
    irregular_lengths,  # length_byte_adjust checked; framing irregular_lengths
    size_limits,  # every layout's largest encoding fits one field (framing max_field_data)
    sample_rule,  # the sample-grouping rule (conformance.md section 6)
    session_rule,  # command timeouts; how a reply is matched (conformance.md section 7)
    session_example,  # the configure-and-stream example program's commands, checked
    time_facts,  # the fields giving a packet its GPS time, device clock and leap seconds
    simulation,  # the simulated device's streaming commands, base rates, filters, checked
    settings,  # the settings files' keyed reads and non-settings (device command line), checked
    capabilities,  # per device, the commands and data it supports (the descriptor lists)
    link,  # getting through: idle/ping/resume commands, baud rates, settle time, bandwidth
    field_layouts,  # each shared field layout once, with its users
    lookup_order,  # the (set, descriptor) search order resolved for every set
    value_paths,  # how deep and how long a value path can get
    assemble,  # the protocol entry in its exported shape
)


def build_protocol(pf: SpecFile, set_files: list[SpecFile], type_files: list[SpecFile]) -> tuple[dict, list[SpecError]]:
    """One protocol's IR entry (docs/ir.md) from its protocol, set and type files, and the spec
    errors found building it."""
    ctx = Context(pf, set_files, type_files)
    for step in PASSES:
        step.run(ctx)
    return ctx.ir, ctx.errors
