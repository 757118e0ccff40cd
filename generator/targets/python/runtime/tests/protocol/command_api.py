"""The typed command API of the test protocol (cf. templates/python/package/command_api.py.j2)."""

from __future__ import annotations

import typing as _ty

from . import command
from . import types as _t
from .session import Device


class Ping:
    def __init__(self, device: Device) -> None:
        self._device = device

    def __call__(self, *, timeout_ms: _ty.Optional[int] = None, check_device: _ty.Optional[bool] = None) -> None:
        self._device.call(command.Ping(), timeout_ms, check_device)


class SetMode:
    def __init__(self, device: Device) -> None:
        self._device = device

    def __call__(
        self, mode: _t.Mode, *, timeout_ms: _ty.Optional[int] = None, check_device: _ty.Optional[bool] = None
    ) -> None:
        self._device.call(command.SetMode(mode=mode), timeout_ms, check_device)


class CommandCommands:
    def __init__(self, device: Device) -> None:
        self.ping = Ping(device)
        self.set_mode = SetMode(device)


class DeviceCommands:
    command: CommandCommands


def bind(device: Device) -> None:
    device.command = CommandCommands(device)
