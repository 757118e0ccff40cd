"""What each Memsense MS-CIP model supports, as its manual documents it (the IR's
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
    "ms_imu3020": Model(
        "ms_imu3020",
        "MS-IMU3020",
        "ms-cip-doc00419-revM.txt",
        (
            (0x01, 0x02),
            (0x01, 0x03),
            (0x01, 0x04),
            (0x01, 0x05),
            (0x01, 0x06),
            (0x01, 0x07),
            (0x01, 0x08),
            (0x01, 0x09),
            (0x02, 0x01),
            (0x02, 0x03),
            (0x02, 0x04),
            (0x02, 0x05),
            (0x02, 0x06),
            (0x02, 0x07),
            (0x02, 0x08),
            (0x02, 0x09),
            (0x02, 0x0A),
            (0x02, 0x0B),
            (0x02, 0x0C),
            (0x02, 0x0D),
        ),
        (
            (0xA2, 0x81),
            (0xA2, 0x82),
            (0xA2, 0x83),
            (0xA2, 0x84),
            (0xA2, 0x85),
            (0xA2, 0x86),
            (0xA2, 0x87),
            (0xA2, 0x88),
            (0xA2, 0x89),
        ),
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
