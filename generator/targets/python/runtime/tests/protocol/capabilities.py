"""What each model of the test protocol supports (cf. templates/python/package/capabilities.py.j2):
ping on both, set_mode on alpha only (as _session.COMMANDS says), the sensor set on both."""

from __future__ import annotations

from typing import Dict, NamedTuple, Tuple


class Model(NamedTuple):
    id: str
    title: str
    manual: str
    commands: Tuple[Tuple[int, int], ...]
    data: Tuple[Tuple[int, int], ...]


_SENSOR = ((0x80, 0x01), (0x80, 0x02), (0x80, 0x03), (0x80, 0x04), (0x80, 0x05))
MODELS: Dict[str, Model] = {
    "alpha": Model("alpha", "Alpha", "alpha.txt", ((0x01, 0x01), (0x01, 0x02)), _SENSOR),
    "beta": Model("beta", "Beta", "beta.txt", ((0x01, 0x01),), _SENSOR),
}


def supports(device: str, set_id: int, descriptor: int) -> bool:
    model = MODELS.get(device)
    return model is not None and ((set_id, descriptor) in model.commands or (set_id, descriptor) in model.data)


def describe(device: str) -> str:
    model = MODELS.get(device)
    return f"{model.title} ({model.manual})" if model is not None else device
