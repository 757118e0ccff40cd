"""The typed command API of the Demo protocol with every spec feature, generated per command and function.

A `Device` (session/) has one attribute per command set and, in it, one object per command
with one method per function it supports (or a plain call):

    device = connect("tcp:192.168.1.10:5000", device="dev_b")
    device.commands.ping()

Each method builds the command, sends it, waits for its result and returns the typed reply field
(or None when the command has none); it raises CommandRefused when the selected device does not
support the command or function (nothing is sent; `check_device=False` sends it anyway), Nack,
CommandTimeout or InvalidReply. `timeout_ms` replaces the device's reply timeout for the call (the
spec's allowance for long commands is added to it).
"""

from __future__ import annotations

import typing as _ty

from . import commands
from . import session as _s
from . import types as _t


class _Command:
    """One command bound to a Device."""

    def __init__(self, device: _s.Device) -> None:
        self._device = device

    def _pick(self, layouts: _ty.Dict[str, _ty.Any]) -> _ty.Any:
        return layouts.get(self._device.device or "", next(iter(layouts.values())))

    def _call(self, command: _ty.Any, timeout_ms: _ty.Optional[int], check_device: _ty.Optional[bool]) -> _ty.Any:
        return self._device.call(command, timeout_ms, check_device).response


class Ping(_Command):
    """Ping (set 0x01, descriptor 0x01)."""

    def __call__(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Send the command; raises on a NACK, timeout or refusal."""
        cls = commands.Ping
        command = cls()
        self._call(command, timeout_ms, check_device)


class Configure(_Command):
    """Configure (set 0x01, descriptor 0x02)."""

    def write(
        self,
        instance: int,
        mode: _ty.Union[_t.Mode, int],
        params: _ty.Union[_t.GpioParams, _t.ThresholdParams],
        suppress_ack: bool,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function write; raises on a NACK, timeout or refusal."""
        cls = commands.Configure
        command = cls(
            function=_t.Function.WRITE,
            instance=instance,
            mode=mode,
            params=params,
            suppress_ack=suppress_ack,
        )
        self._call(command, timeout_ms, check_device)

    def read(
        self,
        instance: int,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> commands.Configuration:
        """Function read: returns the reply field."""
        cls = commands.Configure
        command = cls(
            function=_t.Function.READ,
            instance=instance,
        )
        return _ty.cast("commands.Configuration", self._call(command, timeout_ms, check_device))

    def save(
        self,
        instance: int,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function save; raises on a NACK, timeout or refusal."""
        cls = commands.Configure
        command = cls(
            function=_t.Function.SAVE,
            instance=instance,
        )
        self._call(command, timeout_ms, check_device)


class PerDevice(_Command):
    """Per-device command (set 0x01, descriptor 0x03)."""

    def call_dev_a(
        self,
        a: int,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Send the command (layout for dev_a); raises on a NACK, timeout or refusal."""
        cls = self._pick({"dev_a": commands.PerDevice_dev_a})
        command = cls(
            a=a,
        )
        self._call(command, timeout_ms, check_device)

    def call_dev_b(
        self,
        b: int,
        extra: _ty.Optional[int] = None,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Send the command (layout for dev_b); raises on a NACK, timeout or refusal."""
        cls = self._pick({"dev_b": commands.PerDevice_dev_b})
        command = cls(
            b=b,
            extra=extra,
        )
        self._call(command, timeout_ms, check_device)


class CommandsCommands:
    """Commands commands (set 0x01)."""

    def __init__(self, device: _s.Device) -> None:
        self.ping = Ping(device)
        self.configure = Configure(device)
        self.per_device = PerDevice(device)


class DeviceCommands:
    """The command sets of a Device, as type checkers see them (session.Device derives from this
    class when type checking; `bind` sets the attributes)."""

    commands: CommandsCommands


def bind(device: _s.Device) -> None:
    """Give a Device its command sets (called by Device itself)."""
    device.commands = CommandsCommands(device)
