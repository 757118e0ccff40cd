"""What each Demo protocol with every spec feature model supports, as its manual documents it (the IR's
`capabilities`): per device the (set, descriptor) of every command and data quantity, ascending.

The sessions refuse a command the connected model does not support before sending it, naming the
model and its manual (`describe`). Generated from the spec: do not edit.
"""

from __future__ import annotations

from typing import Dict, NamedTuple, Tuple


class Model(NamedTuple):
    id: str
    title: str
    manual: str
    commands: Tuple[Tuple[int, int], ...]  # (set, descriptor), ascending
    data: Tuple[Tuple[int, int], ...]


MODELS: Dict[str, Model] = {
    "dev_a": Model(
        "dev_a",
        "Device A",
        "demo.txt",
        (
            (0x01, 0x01),
            (0x01, 0x02),
            (0x01, 0x03),
        ),
        (
            (0x90, 0x01),
            (0x91, 0x03),
            (0x92, 0x03),
        ),
    ),
    "dev_b": Model(
        "dev_b",
        "Device B",
        "demo-b.txt",
        ((0x01, 0x03),),
        (),
    ),
}


def supports(device: str, set_id: int, descriptor: int) -> bool:
    """True when the manual of `device` documents the command or data quantity (set, descriptor)."""
    model = MODELS.get(device)
    return model is not None and ((set_id, descriptor) in model.commands or (set_id, descriptor) in model.data)


def describe(device: str) -> str:
    """The model's title and manual, as session messages name them: "3DM-GX5-45 (3dm-gx5-45-dcp.txt)"."""
    model = MODELS.get(device)
    return f"{model.title} ({model.manual})" if model is not None else device
