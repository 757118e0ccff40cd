"""The typed command API of the MicroStrain MIP, generated per command and function.

A `Device` (session/) has one attribute per command set and, in it, one object per command
with one method per function it supports (or a plain call):

    device = connect("tcp:192.168.1.10:5000", device="cv7_ins")
    device.base.ping()

Each method builds the command, sends it, waits for its result and returns the typed reply field
(or None when the command has none); it raises CommandRefused when the selected device does not
support the command or function (nothing is sent; `check_device=False` sends it anyway), Nack,
CommandTimeout or InvalidReply. `timeout_ms` replaces the device's reply timeout for the call (the
spec's allowance for long commands is added to it).
"""

from __future__ import annotations

import typing as _ty

from . import aiding, base, filter, gnss, system, threedm
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
        cls = base.Ping
        command = cls()
        self._call(command, timeout_ms, check_device)


class SetToIdle(_Command):
    """Set to idle (set 0x01, descriptor 0x02)."""

    def __call__(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Send the command; raises on a NACK, timeout or refusal."""
        cls = base.SetToIdle
        command = cls()
        self._call(command, timeout_ms, check_device)


class GetDeviceInfo(_Command):
    """Get device information (set 0x01, descriptor 0x03)."""

    def __call__(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> base.DeviceInfo:
        """Send the command: returns the reply field."""
        cls = base.GetDeviceInfo
        command = cls()
        return _ty.cast("base.DeviceInfo", self._call(command, timeout_ms, check_device))


class GetDeviceDescriptors(_Command):
    """Get device descriptor sets (set 0x01, descriptor 0x04)."""

    def __call__(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> base.DeviceDescriptors:
        """Send the command: returns the reply field."""
        cls = base.GetDeviceDescriptors
        command = cls()
        return _ty.cast("base.DeviceDescriptors", self._call(command, timeout_ms, check_device))


class BuiltInTest(_Command):
    """Built-in test (set 0x01, descriptor 0x05)."""

    def __call__(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> _ty.Any:
        """Send the command: returns the reply field."""
        cls = base.BuiltInTest
        command = cls()
        return _ty.cast("_ty.Any", self._call(command, timeout_ms, check_device))


class Resume(_Command):
    """Resume (set 0x01, descriptor 0x06)."""

    def __call__(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Send the command; raises on a NACK, timeout or refusal."""
        cls = base.Resume
        command = cls()
        self._call(command, timeout_ms, check_device)


class GetExtendedDescriptors(_Command):
    """Get extended device descriptor sets (set 0x01, descriptor 0x07)."""

    def __call__(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> base.ExtendedDescriptors:
        """Send the command: returns the reply field."""
        cls = base.GetExtendedDescriptors
        command = cls()
        return _ty.cast("base.ExtendedDescriptors", self._call(command, timeout_ms, check_device))


class ContinuousBit(_Command):
    """Continuous built-in test (set 0x01, descriptor 0x08)."""

    def __call__(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> base.ContinuousBitResult:
        """Send the command: returns the reply field."""
        cls = base.ContinuousBit
        command = cls()
        return _ty.cast("base.ContinuousBitResult", self._call(command, timeout_ms, check_device))


class CommPortSpeed(_Command):
    """Comm port speed (set 0x01, descriptor 0x09)."""

    def write(
        self,
        port: int,
        baud: int,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function write; raises on a NACK, timeout or refusal."""
        cls = base.CommPortSpeed
        command = cls(
            function=_t.FunctionSelector.WRITE,
            port=port,
            baud=baud,
        )
        self._call(command, timeout_ms, check_device)

    def read(
        self,
        port: int,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> base.CommPortSpeedResponse:
        """Function read: returns the reply field."""
        cls = base.CommPortSpeed
        command = cls(
            function=_t.FunctionSelector.READ,
            port=port,
        )
        return _ty.cast("base.CommPortSpeedResponse", self._call(command, timeout_ms, check_device))

    def save(
        self,
        port: int,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function save; raises on a NACK, timeout or refusal."""
        cls = base.CommPortSpeed
        command = cls(
            function=_t.FunctionSelector.SAVE,
            port=port,
        )
        self._call(command, timeout_ms, check_device)

    def load(
        self,
        port: int,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function load; raises on a NACK, timeout or refusal."""
        cls = base.CommPortSpeed
        command = cls(
            function=_t.FunctionSelector.LOAD,
            port=port,
        )
        self._call(command, timeout_ms, check_device)

    def default(
        self,
        port: int,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function default; raises on a NACK, timeout or refusal."""
        cls = base.CommPortSpeed
        command = cls(
            function=_t.FunctionSelector.DEFAULT,
            port=port,
        )
        self._call(command, timeout_ms, check_device)


class GpsTimeUpdate(_Command):
    """GPS time update (set 0x01, descriptor 0x72)."""

    def write(
        self,
        field_id: _ty.Union[_t.GpsTimeField, int],
        value: int,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function write; raises on a NACK, timeout or refusal."""
        cls = self._pick({"gx5_45": base.GpsTimeUpdate_gx5_45, "cv7_ins": base.GpsTimeUpdate_cv7_ins})
        command = cls(
            function=_t.FunctionSelector.WRITE,
            field_id=field_id,
            value=value,
        )
        self._call(command, timeout_ms, check_device)

    def read(
        self,
        field_id: _ty.Union[_t.GpsTimeField, int],
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> _ty.Any:
        """Function read: returns the reply field."""
        cls = self._pick({"gx5_45": base.GpsTimeUpdate_gx5_45})
        command = cls(
            function=_t.FunctionSelector.READ,
            field_id=field_id,
        )
        return _ty.cast("_ty.Any", self._call(command, timeout_ms, check_device))

    def write_no_ack(
        self,
        field_id: _ty.Union[_t.GpsTimeField, int],
        value: int,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function write_no_ack; raises on a NACK, timeout or refusal."""
        cls = self._pick({"gx5_45": base.GpsTimeUpdate_gx5_45})
        command = cls(
            function=_t.FunctionSelector.WRITE_NO_ACK,
            field_id=field_id,
            value=value,
        )
        self._call(command, timeout_ms, check_device)


class DeviceReset(_Command):
    """Device reset (set 0x01, descriptor 0x7E)."""

    def __call__(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Send the command; raises on a NACK, timeout or refusal."""
        cls = base.DeviceReset
        command = cls()
        self._call(command, timeout_ms, check_device)


class BaseCommands:
    """Base Command Set commands (set 0x01)."""

    def __init__(self, device: _s.Device) -> None:
        self.ping = Ping(device)
        self.set_to_idle = SetToIdle(device)
        self.get_device_info = GetDeviceInfo(device)
        self.get_device_descriptors = GetDeviceDescriptors(device)
        self.built_in_test = BuiltInTest(device)
        self.resume = Resume(device)
        self.get_extended_descriptors = GetExtendedDescriptors(device)
        self.continuous_bit = ContinuousBit(device)
        self.comm_port_speed = CommPortSpeed(device)
        self.gps_time_update = GpsTimeUpdate(device)
        self.device_reset = DeviceReset(device)


class EventControl(_Command):
    """Event control (set 0x0C, descriptor 0x2B)."""

    def write(
        self,
        instance: int,
        mode: _ty.Union[_t.EventControlMode, int],
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function write; raises on a NACK, timeout or refusal."""
        cls = threedm.EventControl
        command = cls(
            function=_t.FunctionSelector.WRITE,
            instance=instance,
            mode=mode,
        )
        self._call(command, timeout_ms, check_device)

    def read(
        self,
        instance: int,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> threedm.EventControlResponse:
        """Function read: returns the reply field."""
        cls = threedm.EventControl
        command = cls(
            function=_t.FunctionSelector.READ,
            instance=instance,
        )
        return _ty.cast("threedm.EventControlResponse", self._call(command, timeout_ms, check_device))

    def save(
        self,
        instance: int,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function save; raises on a NACK, timeout or refusal."""
        cls = threedm.EventControl
        command = cls(
            function=_t.FunctionSelector.SAVE,
            instance=instance,
        )
        self._call(command, timeout_ms, check_device)

    def load(
        self,
        instance: int,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function load; raises on a NACK, timeout or refusal."""
        cls = threedm.EventControl
        command = cls(
            function=_t.FunctionSelector.LOAD,
            instance=instance,
        )
        self._call(command, timeout_ms, check_device)

    def default(
        self,
        instance: int,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function default; raises on a NACK, timeout or refusal."""
        cls = threedm.EventControl
        command = cls(
            function=_t.FunctionSelector.DEFAULT,
            instance=instance,
        )
        self._call(command, timeout_ms, check_device)


class GetEventTriggerStatus(_Command):
    """Get event trigger status (set 0x0C, descriptor 0x2C)."""

    def __call__(
        self,
        requested_instances: _ty.List[int],
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> threedm.EventTriggerStatus:
        """Send the command: returns the reply field."""
        cls = threedm.GetEventTriggerStatus
        command = cls(
            requested_instances=requested_instances,
            requested_count=None if requested_instances is None else len(requested_instances),
        )
        return _ty.cast("threedm.EventTriggerStatus", self._call(command, timeout_ms, check_device))


class GetEventActionStatus(_Command):
    """Get event action status (set 0x0C, descriptor 0x2D)."""

    def __call__(
        self,
        requested_instances: _ty.List[int],
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> threedm.EventActionStatus:
        """Send the command: returns the reply field."""
        cls = threedm.GetEventActionStatus
        command = cls(
            requested_instances=requested_instances,
            requested_count=None if requested_instances is None else len(requested_instances),
        )
        return _ty.cast("threedm.EventActionStatus", self._call(command, timeout_ms, check_device))


class EventTriggerConfig(_Command):
    """Event trigger configuration (set 0x0C, descriptor 0x2E)."""

    def write(
        self,
        instance: int,
        type: _ty.Union[_t.TriggerType, int],
        parameters: _ty.Union[_t.TriggerGpioParams, _t.ThresholdParams, _t.CombinationParams],
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function write; raises on a NACK, timeout or refusal."""
        cls = threedm.EventTriggerConfig
        command = cls(
            function=_t.FunctionSelector.WRITE,
            instance=instance,
            type=type,
            parameters=parameters,
        )
        self._call(command, timeout_ms, check_device)

    def read(
        self,
        instance: int,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> threedm.EventTriggerConfigResponse:
        """Function read: returns the reply field."""
        cls = threedm.EventTriggerConfig
        command = cls(
            function=_t.FunctionSelector.READ,
            instance=instance,
        )
        return _ty.cast("threedm.EventTriggerConfigResponse", self._call(command, timeout_ms, check_device))

    def save(
        self,
        instance: int,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function save; raises on a NACK, timeout or refusal."""
        cls = threedm.EventTriggerConfig
        command = cls(
            function=_t.FunctionSelector.SAVE,
            instance=instance,
        )
        self._call(command, timeout_ms, check_device)

    def load(
        self,
        instance: int,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function load; raises on a NACK, timeout or refusal."""
        cls = threedm.EventTriggerConfig
        command = cls(
            function=_t.FunctionSelector.LOAD,
            instance=instance,
        )
        self._call(command, timeout_ms, check_device)

    def default(
        self,
        instance: int,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function default; raises on a NACK, timeout or refusal."""
        cls = threedm.EventTriggerConfig
        command = cls(
            function=_t.FunctionSelector.DEFAULT,
            instance=instance,
        )
        self._call(command, timeout_ms, check_device)


class EventActionConfig(_Command):
    """Event action configuration (set 0x0C, descriptor 0x2F)."""

    def write(
        self,
        instance: int,
        trigger: int,
        type: _ty.Union[_t.ActionType, int],
        parameters: _ty.Union[_t.ActionGpioParams, _t.MessageParams],
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function write; raises on a NACK, timeout or refusal."""
        cls = threedm.EventActionConfig
        command = cls(
            function=_t.FunctionSelector.WRITE,
            instance=instance,
            trigger=trigger,
            type=type,
            parameters=parameters,
        )
        self._call(command, timeout_ms, check_device)

    def read(
        self,
        instance: int,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> threedm.EventActionConfigResponse:
        """Function read: returns the reply field."""
        cls = threedm.EventActionConfig
        command = cls(
            function=_t.FunctionSelector.READ,
            instance=instance,
        )
        return _ty.cast("threedm.EventActionConfigResponse", self._call(command, timeout_ms, check_device))

    def save(
        self,
        instance: int,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function save; raises on a NACK, timeout or refusal."""
        cls = threedm.EventActionConfig
        command = cls(
            function=_t.FunctionSelector.SAVE,
            instance=instance,
        )
        self._call(command, timeout_ms, check_device)

    def load(
        self,
        instance: int,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function load; raises on a NACK, timeout or refusal."""
        cls = threedm.EventActionConfig
        command = cls(
            function=_t.FunctionSelector.LOAD,
            instance=instance,
        )
        self._call(command, timeout_ms, check_device)

    def default(
        self,
        instance: int,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function default; raises on a NACK, timeout or refusal."""
        cls = threedm.EventActionConfig
        command = cls(
            function=_t.FunctionSelector.DEFAULT,
            instance=instance,
        )
        self._call(command, timeout_ms, check_device)


class DeviceStartupSettings(_Command):
    """Device startup settings (set 0x0C, descriptor 0x30)."""

    def read(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function read; raises on a NACK, timeout or refusal."""
        cls = self._pick({"gx5_45": threedm.DeviceStartupSettings_gx5_45})
        command = cls(
            function=_t.FunctionSelector.READ,
        )
        self._call(command, timeout_ms, check_device)

    def save(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function save; raises on a NACK, timeout or refusal."""
        cls = self._pick(
            {"gx5_45": threedm.DeviceStartupSettings_gx5_45, "cv7_ins": threedm.DeviceStartupSettings_cv7_ins}
        )
        command = cls(
            function=_t.FunctionSelector.SAVE,
        )
        self._call(command, timeout_ms, check_device)

    def load(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function load; raises on a NACK, timeout or refusal."""
        cls = self._pick(
            {"gx5_45": threedm.DeviceStartupSettings_gx5_45, "cv7_ins": threedm.DeviceStartupSettings_cv7_ins}
        )
        command = cls(
            function=_t.FunctionSelector.LOAD,
        )
        self._call(command, timeout_ms, check_device)

    def default(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function default; raises on a NACK, timeout or refusal."""
        cls = self._pick(
            {"gx5_45": threedm.DeviceStartupSettings_gx5_45, "cv7_ins": threedm.DeviceStartupSettings_cv7_ins}
        )
        command = cls(
            function=_t.FunctionSelector.DEFAULT,
        )
        self._call(command, timeout_ms, check_device)


class SensorToVehicleEuler(_Command):
    """Sensor-to-vehicle frame transformation (Euler) (set 0x0C, descriptor 0x31)."""

    def write(
        self,
        roll: float,
        pitch: float,
        yaw: float,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function write; raises on a NACK, timeout or refusal."""
        cls = threedm.SensorToVehicleEuler
        command = cls(
            function=_t.FunctionSelector.WRITE,
            roll=roll,
            pitch=pitch,
            yaw=yaw,
        )
        self._call(command, timeout_ms, check_device)

    def read(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> threedm.SensorToVehicleEulerResponse:
        """Function read: returns the reply field."""
        cls = threedm.SensorToVehicleEuler
        command = cls(
            function=_t.FunctionSelector.READ,
        )
        return _ty.cast("threedm.SensorToVehicleEulerResponse", self._call(command, timeout_ms, check_device))

    def save(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function save; raises on a NACK, timeout or refusal."""
        cls = threedm.SensorToVehicleEuler
        command = cls(
            function=_t.FunctionSelector.SAVE,
        )
        self._call(command, timeout_ms, check_device)

    def load(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function load; raises on a NACK, timeout or refusal."""
        cls = threedm.SensorToVehicleEuler
        command = cls(
            function=_t.FunctionSelector.LOAD,
        )
        self._call(command, timeout_ms, check_device)

    def default(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function default; raises on a NACK, timeout or refusal."""
        cls = threedm.SensorToVehicleEuler
        command = cls(
            function=_t.FunctionSelector.DEFAULT,
        )
        self._call(command, timeout_ms, check_device)


class SensorToVehicleQuaternion(_Command):
    """Sensor-to-vehicle frame transformation (quaternion) (set 0x0C, descriptor 0x32)."""

    def write(
        self,
        q: _ty.List[float],
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function write; raises on a NACK, timeout or refusal."""
        cls = threedm.SensorToVehicleQuaternion
        command = cls(
            function=_t.FunctionSelector.WRITE,
            q=q,
        )
        self._call(command, timeout_ms, check_device)

    def read(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> threedm.SensorToVehicleQuaternionResponse:
        """Function read: returns the reply field."""
        cls = threedm.SensorToVehicleQuaternion
        command = cls(
            function=_t.FunctionSelector.READ,
        )
        return _ty.cast("threedm.SensorToVehicleQuaternionResponse", self._call(command, timeout_ms, check_device))

    def save(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function save; raises on a NACK, timeout or refusal."""
        cls = threedm.SensorToVehicleQuaternion
        command = cls(
            function=_t.FunctionSelector.SAVE,
        )
        self._call(command, timeout_ms, check_device)

    def load(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function load; raises on a NACK, timeout or refusal."""
        cls = threedm.SensorToVehicleQuaternion
        command = cls(
            function=_t.FunctionSelector.LOAD,
        )
        self._call(command, timeout_ms, check_device)

    def default(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function default; raises on a NACK, timeout or refusal."""
        cls = threedm.SensorToVehicleQuaternion
        command = cls(
            function=_t.FunctionSelector.DEFAULT,
        )
        self._call(command, timeout_ms, check_device)


class SensorToVehicleDcm(_Command):
    """Sensor-to-vehicle frame transformation (direction cosine matrix) (set 0x0C, descriptor 0x33)."""

    def write(
        self,
        dcm: _ty.List[float],
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function write; raises on a NACK, timeout or refusal."""
        cls = threedm.SensorToVehicleDcm
        command = cls(
            function=_t.FunctionSelector.WRITE,
            dcm=dcm,
        )
        self._call(command, timeout_ms, check_device)

    def read(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> threedm.SensorToVehicleDcmResponse:
        """Function read: returns the reply field."""
        cls = threedm.SensorToVehicleDcm
        command = cls(
            function=_t.FunctionSelector.READ,
        )
        return _ty.cast("threedm.SensorToVehicleDcmResponse", self._call(command, timeout_ms, check_device))

    def save(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function save; raises on a NACK, timeout or refusal."""
        cls = threedm.SensorToVehicleDcm
        command = cls(
            function=_t.FunctionSelector.SAVE,
        )
        self._call(command, timeout_ms, check_device)

    def load(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function load; raises on a NACK, timeout or refusal."""
        cls = threedm.SensorToVehicleDcm
        command = cls(
            function=_t.FunctionSelector.LOAD,
        )
        self._call(command, timeout_ms, check_device)

    def default(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function default; raises on a NACK, timeout or refusal."""
        cls = threedm.SensorToVehicleDcm
        command = cls(
            function=_t.FunctionSelector.DEFAULT,
        )
        self._call(command, timeout_ms, check_device)


class AccelBias(_Command):
    """Accelerometer bias (set 0x0C, descriptor 0x37)."""

    def write(
        self,
        bias: _ty.List[float],
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function write; raises on a NACK, timeout or refusal."""
        cls = self._pick({"gx5_45": threedm.AccelBias_gx5_45, "cv7_ins": threedm.AccelBias_cv7_ins})
        command = cls(
            function=_t.FunctionSelector.WRITE,
            bias=bias,
        )
        self._call(command, timeout_ms, check_device)

    def read(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> threedm.AccelBiasResponse:
        """Function read: returns the reply field."""
        cls = self._pick({"gx5_45": threedm.AccelBias_gx5_45, "cv7_ins": threedm.AccelBias_cv7_ins})
        command = cls(
            function=_t.FunctionSelector.READ,
        )
        return _ty.cast("threedm.AccelBiasResponse", self._call(command, timeout_ms, check_device))

    def save(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function save; raises on a NACK, timeout or refusal."""
        cls = self._pick({"gx5_45": threedm.AccelBias_gx5_45, "cv7_ins": threedm.AccelBias_cv7_ins})
        command = cls(
            function=_t.FunctionSelector.SAVE,
        )
        self._call(command, timeout_ms, check_device)

    def load(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function load; raises on a NACK, timeout or refusal."""
        cls = self._pick({"gx5_45": threedm.AccelBias_gx5_45, "cv7_ins": threedm.AccelBias_cv7_ins})
        command = cls(
            function=_t.FunctionSelector.LOAD,
        )
        self._call(command, timeout_ms, check_device)

    def default(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function default; raises on a NACK, timeout or refusal."""
        cls = self._pick({"gx5_45": threedm.AccelBias_gx5_45, "cv7_ins": threedm.AccelBias_cv7_ins})
        command = cls(
            function=_t.FunctionSelector.DEFAULT,
        )
        self._call(command, timeout_ms, check_device)

    def write_no_ack(
        self,
        bias: _ty.List[float],
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function write_no_ack; raises on a NACK, timeout or refusal."""
        cls = self._pick({"gx5_45": threedm.AccelBias_gx5_45})
        command = cls(
            function=_t.FunctionSelector.WRITE_NO_ACK,
            bias=bias,
        )
        self._call(command, timeout_ms, check_device)


class GyroBias(_Command):
    """Gyro bias (set 0x0C, descriptor 0x38)."""

    def write(
        self,
        bias: _ty.List[float],
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function write; raises on a NACK, timeout or refusal."""
        cls = self._pick({"gx5_45": threedm.GyroBias_gx5_45, "cv7_ins": threedm.GyroBias_cv7_ins})
        command = cls(
            function=_t.FunctionSelector.WRITE,
            bias=bias,
        )
        self._call(command, timeout_ms, check_device)

    def read(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> threedm.GyroBiasResponse:
        """Function read: returns the reply field."""
        cls = self._pick({"gx5_45": threedm.GyroBias_gx5_45, "cv7_ins": threedm.GyroBias_cv7_ins})
        command = cls(
            function=_t.FunctionSelector.READ,
        )
        return _ty.cast("threedm.GyroBiasResponse", self._call(command, timeout_ms, check_device))

    def save(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function save; raises on a NACK, timeout or refusal."""
        cls = self._pick({"gx5_45": threedm.GyroBias_gx5_45, "cv7_ins": threedm.GyroBias_cv7_ins})
        command = cls(
            function=_t.FunctionSelector.SAVE,
        )
        self._call(command, timeout_ms, check_device)

    def load(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function load; raises on a NACK, timeout or refusal."""
        cls = self._pick({"gx5_45": threedm.GyroBias_gx5_45, "cv7_ins": threedm.GyroBias_cv7_ins})
        command = cls(
            function=_t.FunctionSelector.LOAD,
        )
        self._call(command, timeout_ms, check_device)

    def default(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function default; raises on a NACK, timeout or refusal."""
        cls = self._pick({"gx5_45": threedm.GyroBias_gx5_45, "cv7_ins": threedm.GyroBias_cv7_ins})
        command = cls(
            function=_t.FunctionSelector.DEFAULT,
        )
        self._call(command, timeout_ms, check_device)

    def write_no_ack(
        self,
        bias: _ty.List[float],
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function write_no_ack; raises on a NACK, timeout or refusal."""
        cls = self._pick({"gx5_45": threedm.GyroBias_gx5_45})
        command = cls(
            function=_t.FunctionSelector.WRITE_NO_ACK,
            bias=bias,
        )
        self._call(command, timeout_ms, check_device)


class CaptureGyroBias(_Command):
    """Capture gyro bias (set 0x0C, descriptor 0x39)."""

    def __call__(
        self,
        averaging_time_ms: int,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> threedm.GyroBiasResponse:
        """Send the command: returns the reply field."""
        cls = threedm.CaptureGyroBias
        command = cls(
            averaging_time_ms=averaging_time_ms,
        )
        return _ty.cast("threedm.GyroBiasResponse", self._call(command, timeout_ms, check_device))


class MagHardIronOffset(_Command):
    """Magnetometer hard iron offset (set 0x0C, descriptor 0x3A)."""

    def write(
        self,
        offset: _ty.List[float],
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function write; raises on a NACK, timeout or refusal."""
        cls = self._pick({"gx5_45": threedm.MagHardIronOffset_gx5_45, "cv7_ins": threedm.MagHardIronOffset_cv7_ins})
        command = cls(
            function=_t.FunctionSelector.WRITE,
            offset=offset,
        )
        self._call(command, timeout_ms, check_device)

    def read(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> threedm.MagHardIronOffsetResponse:
        """Function read: returns the reply field."""
        cls = self._pick({"gx5_45": threedm.MagHardIronOffset_gx5_45, "cv7_ins": threedm.MagHardIronOffset_cv7_ins})
        command = cls(
            function=_t.FunctionSelector.READ,
        )
        return _ty.cast("threedm.MagHardIronOffsetResponse", self._call(command, timeout_ms, check_device))

    def save(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function save; raises on a NACK, timeout or refusal."""
        cls = self._pick({"gx5_45": threedm.MagHardIronOffset_gx5_45, "cv7_ins": threedm.MagHardIronOffset_cv7_ins})
        command = cls(
            function=_t.FunctionSelector.SAVE,
        )
        self._call(command, timeout_ms, check_device)

    def load(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function load; raises on a NACK, timeout or refusal."""
        cls = self._pick({"gx5_45": threedm.MagHardIronOffset_gx5_45, "cv7_ins": threedm.MagHardIronOffset_cv7_ins})
        command = cls(
            function=_t.FunctionSelector.LOAD,
        )
        self._call(command, timeout_ms, check_device)

    def default(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function default; raises on a NACK, timeout or refusal."""
        cls = self._pick({"gx5_45": threedm.MagHardIronOffset_gx5_45, "cv7_ins": threedm.MagHardIronOffset_cv7_ins})
        command = cls(
            function=_t.FunctionSelector.DEFAULT,
        )
        self._call(command, timeout_ms, check_device)

    def write_no_ack(
        self,
        offset: _ty.List[float],
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function write_no_ack; raises on a NACK, timeout or refusal."""
        cls = self._pick({"gx5_45": threedm.MagHardIronOffset_gx5_45})
        command = cls(
            function=_t.FunctionSelector.WRITE_NO_ACK,
            offset=offset,
        )
        self._call(command, timeout_ms, check_device)


class MagSoftIronMatrix(_Command):
    """Magnetometer soft iron matrix (set 0x0C, descriptor 0x3B)."""

    def write(
        self,
        matrix: _ty.List[float],
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function write; raises on a NACK, timeout or refusal."""
        cls = self._pick({"gx5_45": threedm.MagSoftIronMatrix_gx5_45, "cv7_ins": threedm.MagSoftIronMatrix_cv7_ins})
        command = cls(
            function=_t.FunctionSelector.WRITE,
            matrix=matrix,
        )
        self._call(command, timeout_ms, check_device)

    def read(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> threedm.MagSoftIronMatrixResponse:
        """Function read: returns the reply field."""
        cls = self._pick({"gx5_45": threedm.MagSoftIronMatrix_gx5_45, "cv7_ins": threedm.MagSoftIronMatrix_cv7_ins})
        command = cls(
            function=_t.FunctionSelector.READ,
        )
        return _ty.cast("threedm.MagSoftIronMatrixResponse", self._call(command, timeout_ms, check_device))

    def save(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function save; raises on a NACK, timeout or refusal."""
        cls = self._pick({"gx5_45": threedm.MagSoftIronMatrix_gx5_45, "cv7_ins": threedm.MagSoftIronMatrix_cv7_ins})
        command = cls(
            function=_t.FunctionSelector.SAVE,
        )
        self._call(command, timeout_ms, check_device)

    def load(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function load; raises on a NACK, timeout or refusal."""
        cls = self._pick({"gx5_45": threedm.MagSoftIronMatrix_gx5_45, "cv7_ins": threedm.MagSoftIronMatrix_cv7_ins})
        command = cls(
            function=_t.FunctionSelector.LOAD,
        )
        self._call(command, timeout_ms, check_device)

    def default(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function default; raises on a NACK, timeout or refusal."""
        cls = self._pick({"gx5_45": threedm.MagSoftIronMatrix_gx5_45, "cv7_ins": threedm.MagSoftIronMatrix_cv7_ins})
        command = cls(
            function=_t.FunctionSelector.DEFAULT,
        )
        self._call(command, timeout_ms, check_device)

    def write_no_ack(
        self,
        matrix: _ty.List[float],
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function write_no_ack; raises on a NACK, timeout or refusal."""
        cls = self._pick({"gx5_45": threedm.MagSoftIronMatrix_gx5_45})
        command = cls(
            function=_t.FunctionSelector.WRITE_NO_ACK,
            matrix=matrix,
        )
        self._call(command, timeout_ms, check_device)


class ConingScullingEnable(_Command):
    """Coning and sculling enable (set 0x0C, descriptor 0x3E)."""

    def write(
        self,
        enable: bool,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function write; raises on a NACK, timeout or refusal."""
        cls = threedm.ConingScullingEnable
        command = cls(
            function=_t.FunctionSelector.WRITE,
            enable=enable,
        )
        self._call(command, timeout_ms, check_device)

    def read(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> threedm.ConingScullingEnableResponse:
        """Function read: returns the reply field."""
        cls = threedm.ConingScullingEnable
        command = cls(
            function=_t.FunctionSelector.READ,
        )
        return _ty.cast("threedm.ConingScullingEnableResponse", self._call(command, timeout_ms, check_device))

    def save(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function save; raises on a NACK, timeout or refusal."""
        cls = threedm.ConingScullingEnable
        command = cls(
            function=_t.FunctionSelector.SAVE,
        )
        self._call(command, timeout_ms, check_device)

    def load(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function load; raises on a NACK, timeout or refusal."""
        cls = threedm.ConingScullingEnable
        command = cls(
            function=_t.FunctionSelector.LOAD,
        )
        self._call(command, timeout_ms, check_device)

    def default(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function default; raises on a NACK, timeout or refusal."""
        cls = threedm.ConingScullingEnable
        command = cls(
            function=_t.FunctionSelector.DEFAULT,
        )
        self._call(command, timeout_ms, check_device)


class UartBaudrate(_Command):
    """UART baud rate (set 0x0C, descriptor 0x40)."""

    def write(
        self,
        baud: int,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function write; raises on a NACK, timeout or refusal."""
        cls = threedm.UartBaudrate
        command = cls(
            function=_t.FunctionSelector.WRITE,
            baud=baud,
        )
        self._call(command, timeout_ms, check_device)

    def read(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> threedm.UartBaudrateResponse:
        """Function read: returns the reply field."""
        cls = threedm.UartBaudrate
        command = cls(
            function=_t.FunctionSelector.READ,
        )
        return _ty.cast("threedm.UartBaudrateResponse", self._call(command, timeout_ms, check_device))

    def save(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function save; raises on a NACK, timeout or refusal."""
        cls = threedm.UartBaudrate
        command = cls(
            function=_t.FunctionSelector.SAVE,
        )
        self._call(command, timeout_ms, check_device)

    def load(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function load; raises on a NACK, timeout or refusal."""
        cls = threedm.UartBaudrate
        command = cls(
            function=_t.FunctionSelector.LOAD,
        )
        self._call(command, timeout_ms, check_device)

    def default(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function default; raises on a NACK, timeout or refusal."""
        cls = threedm.UartBaudrate
        command = cls(
            function=_t.FunctionSelector.DEFAULT,
        )
        self._call(command, timeout_ms, check_device)


class GpioConfig(_Command):
    """GPIO configuration (set 0x0C, descriptor 0x41)."""

    def write(
        self,
        pin: int,
        feature: _ty.Union[_t.GpioFeature, int],
        behavior: _ty.Union[
            _t.GpioBehaviorUnused,
            _t.GpioBehaviorIo,
            _t.GpioBehaviorPps,
            _t.GpioBehaviorEncoder,
            _t.GpioBehaviorTimestamp,
            _t.GpioBehaviorUart,
        ],
        pin_mode: _t.GpioPinMode,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function write; raises on a NACK, timeout or refusal."""
        cls = threedm.GpioConfig
        command = cls(
            function=_t.FunctionSelector.WRITE,
            pin=pin,
            feature=feature,
            behavior=behavior,
            pin_mode=pin_mode,
        )
        self._call(command, timeout_ms, check_device)

    def read(
        self,
        pin: int,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> threedm.GpioConfigResponse:
        """Function read: returns the reply field."""
        cls = threedm.GpioConfig
        command = cls(
            function=_t.FunctionSelector.READ,
            pin=pin,
        )
        return _ty.cast("threedm.GpioConfigResponse", self._call(command, timeout_ms, check_device))

    def save(
        self,
        pin: int,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function save; raises on a NACK, timeout or refusal."""
        cls = threedm.GpioConfig
        command = cls(
            function=_t.FunctionSelector.SAVE,
            pin=pin,
        )
        self._call(command, timeout_ms, check_device)

    def load(
        self,
        pin: int,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function load; raises on a NACK, timeout or refusal."""
        cls = threedm.GpioConfig
        command = cls(
            function=_t.FunctionSelector.LOAD,
            pin=pin,
        )
        self._call(command, timeout_ms, check_device)

    def default(
        self,
        pin: int,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function default; raises on a NACK, timeout or refusal."""
        cls = threedm.GpioConfig
        command = cls(
            function=_t.FunctionSelector.DEFAULT,
            pin=pin,
        )
        self._call(command, timeout_ms, check_device)


class GpioState(_Command):
    """GPIO state (set 0x0C, descriptor 0x42)."""

    def write(
        self,
        pin: int,
        state: bool,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function write; raises on a NACK, timeout or refusal."""
        cls = threedm.GpioState
        command = cls(
            function=_t.FunctionSelector.WRITE,
            pin=pin,
            state=state,
        )
        self._call(command, timeout_ms, check_device)

    def read(
        self,
        pin: int,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> threedm.GpioStateResponse:
        """Function read: returns the reply field."""
        cls = threedm.GpioState
        command = cls(
            function=_t.FunctionSelector.READ,
            pin=pin,
        )
        return _ty.cast("threedm.GpioStateResponse", self._call(command, timeout_ms, check_device))


class OdometerConfig(_Command):
    """Odometer configuration (set 0x0C, descriptor 0x43)."""

    def write(
        self,
        mode: _ty.Union[_t.OdometerMode, int],
        scaling: float,
        uncertainty: float,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function write; raises on a NACK, timeout or refusal."""
        cls = threedm.OdometerConfig
        command = cls(
            function=_t.FunctionSelector.WRITE,
            mode=mode,
            scaling=scaling,
            uncertainty=uncertainty,
        )
        self._call(command, timeout_ms, check_device)

    def read(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> threedm.OdometerConfigResponse:
        """Function read: returns the reply field."""
        cls = threedm.OdometerConfig
        command = cls(
            function=_t.FunctionSelector.READ,
        )
        return _ty.cast("threedm.OdometerConfigResponse", self._call(command, timeout_ms, check_device))

    def save(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function save; raises on a NACK, timeout or refusal."""
        cls = threedm.OdometerConfig
        command = cls(
            function=_t.FunctionSelector.SAVE,
        )
        self._call(command, timeout_ms, check_device)

    def load(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function load; raises on a NACK, timeout or refusal."""
        cls = threedm.OdometerConfig
        command = cls(
            function=_t.FunctionSelector.LOAD,
        )
        self._call(command, timeout_ms, check_device)

    def default(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function default; raises on a NACK, timeout or refusal."""
        cls = threedm.OdometerConfig
        command = cls(
            function=_t.FunctionSelector.DEFAULT,
        )
        self._call(command, timeout_ms, check_device)


class AdvancedLowpassFilter(_Command):
    """Advanced low-pass filter settings (set 0x0C, descriptor 0x50)."""

    def write(
        self,
        target_descriptor: int,
        enable: bool,
        manual: bool,
        frequency: int,
        reserved: int,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function write; raises on a NACK, timeout or refusal."""
        cls = threedm.AdvancedLowpassFilter
        command = cls(
            function=_t.FunctionSelector.WRITE,
            target_descriptor=target_descriptor,
            enable=enable,
            manual=manual,
            frequency=frequency,
            reserved=reserved,
        )
        self._call(command, timeout_ms, check_device)

    def read(
        self,
        target_descriptor: int,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> threedm.AdvancedLowpassFilterResponse:
        """Function read: returns the reply field."""
        cls = threedm.AdvancedLowpassFilter
        command = cls(
            function=_t.FunctionSelector.READ,
            target_descriptor=target_descriptor,
        )
        return _ty.cast("threedm.AdvancedLowpassFilterResponse", self._call(command, timeout_ms, check_device))

    def save(
        self,
        target_descriptor: int,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function save; raises on a NACK, timeout or refusal."""
        cls = threedm.AdvancedLowpassFilter
        command = cls(
            function=_t.FunctionSelector.SAVE,
            target_descriptor=target_descriptor,
        )
        self._call(command, timeout_ms, check_device)

    def load(
        self,
        target_descriptor: int,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function load; raises on a NACK, timeout or refusal."""
        cls = threedm.AdvancedLowpassFilter
        command = cls(
            function=_t.FunctionSelector.LOAD,
            target_descriptor=target_descriptor,
        )
        self._call(command, timeout_ms, check_device)

    def default(
        self,
        target_descriptor: int,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function default; raises on a NACK, timeout or refusal."""
        cls = threedm.AdvancedLowpassFilter
        command = cls(
            function=_t.FunctionSelector.DEFAULT,
            target_descriptor=target_descriptor,
        )
        self._call(command, timeout_ms, check_device)


class ComplementaryFilter(_Command):
    """Complementary filter settings (set 0x0C, descriptor 0x51)."""

    def write(
        self,
        pitch_roll_enable: bool,
        heading_enable: bool,
        pitch_roll_time_constant: float,
        heading_time_constant: float,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function write; raises on a NACK, timeout or refusal."""
        cls = threedm.ComplementaryFilter
        command = cls(
            function=_t.FunctionSelector.WRITE,
            pitch_roll_enable=pitch_roll_enable,
            heading_enable=heading_enable,
            pitch_roll_time_constant=pitch_roll_time_constant,
            heading_time_constant=heading_time_constant,
        )
        self._call(command, timeout_ms, check_device)

    def read(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> threedm.ComplementaryFilterResponse:
        """Function read: returns the reply field."""
        cls = threedm.ComplementaryFilter
        command = cls(
            function=_t.FunctionSelector.READ,
        )
        return _ty.cast("threedm.ComplementaryFilterResponse", self._call(command, timeout_ms, check_device))

    def save(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function save; raises on a NACK, timeout or refusal."""
        cls = threedm.ComplementaryFilter
        command = cls(
            function=_t.FunctionSelector.SAVE,
        )
        self._call(command, timeout_ms, check_device)

    def load(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function load; raises on a NACK, timeout or refusal."""
        cls = threedm.ComplementaryFilter
        command = cls(
            function=_t.FunctionSelector.LOAD,
        )
        self._call(command, timeout_ms, check_device)

    def default(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function default; raises on a NACK, timeout or refusal."""
        cls = threedm.ComplementaryFilter
        command = cls(
            function=_t.FunctionSelector.DEFAULT,
        )
        self._call(command, timeout_ms, check_device)


class SensorRange(_Command):
    """Sensor range (set 0x0C, descriptor 0x52)."""

    def write(
        self,
        sensor: _ty.Union[_t.SensorRangeType, int],
        setting: int,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function write; raises on a NACK, timeout or refusal."""
        cls = threedm.SensorRange
        command = cls(
            function=_t.FunctionSelector.WRITE,
            sensor=sensor,
            setting=setting,
        )
        self._call(command, timeout_ms, check_device)

    def read(
        self,
        sensor: _ty.Union[_t.SensorRangeType, int],
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> threedm.SensorRangeResponse:
        """Function read: returns the reply field."""
        cls = threedm.SensorRange
        command = cls(
            function=_t.FunctionSelector.READ,
            sensor=sensor,
        )
        return _ty.cast("threedm.SensorRangeResponse", self._call(command, timeout_ms, check_device))

    def save(
        self,
        sensor: _ty.Union[_t.SensorRangeType, int],
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function save; raises on a NACK, timeout or refusal."""
        cls = threedm.SensorRange
        command = cls(
            function=_t.FunctionSelector.SAVE,
            sensor=sensor,
        )
        self._call(command, timeout_ms, check_device)

    def load(
        self,
        sensor: _ty.Union[_t.SensorRangeType, int],
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function load; raises on a NACK, timeout or refusal."""
        cls = threedm.SensorRange
        command = cls(
            function=_t.FunctionSelector.LOAD,
            sensor=sensor,
        )
        self._call(command, timeout_ms, check_device)

    def default(
        self,
        sensor: _ty.Union[_t.SensorRangeType, int],
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function default; raises on a NACK, timeout or refusal."""
        cls = threedm.SensorRange
        command = cls(
            function=_t.FunctionSelector.DEFAULT,
            sensor=sensor,
        )
        self._call(command, timeout_ms, check_device)


class GetCalibratedSensorRanges(_Command):
    """Get calibrated sensor ranges (set 0x0C, descriptor 0x53)."""

    def __call__(
        self,
        sensor: _ty.Union[_t.SensorRangeType, int],
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> threedm.CalibratedSensorRanges:
        """Send the command: returns the reply field."""
        cls = threedm.GetCalibratedSensorRanges
        command = cls(
            sensor=sensor,
        )
        return _ty.cast("threedm.CalibratedSensorRanges", self._call(command, timeout_ms, check_device))


class LowpassFilter(_Command):
    """Low-pass anti-aliasing filter (set 0x0C, descriptor 0x54)."""

    def write(
        self,
        desc_set: int,
        field_desc: int,
        enable: bool,
        manual: bool,
        frequency: float,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function write; raises on a NACK, timeout or refusal."""
        cls = threedm.LowpassFilter
        command = cls(
            function=_t.FunctionSelector.WRITE,
            desc_set=desc_set,
            field_desc=field_desc,
            enable=enable,
            manual=manual,
            frequency=frequency,
        )
        self._call(command, timeout_ms, check_device)

    def read(
        self,
        desc_set: int,
        field_desc: int,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> threedm.LowpassFilterResponse:
        """Function read: returns the reply field."""
        cls = threedm.LowpassFilter
        command = cls(
            function=_t.FunctionSelector.READ,
            desc_set=desc_set,
            field_desc=field_desc,
        )
        return _ty.cast("threedm.LowpassFilterResponse", self._call(command, timeout_ms, check_device))

    def save(
        self,
        desc_set: int,
        field_desc: int,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function save; raises on a NACK, timeout or refusal."""
        cls = threedm.LowpassFilter
        command = cls(
            function=_t.FunctionSelector.SAVE,
            desc_set=desc_set,
            field_desc=field_desc,
        )
        self._call(command, timeout_ms, check_device)

    def load(
        self,
        desc_set: int,
        field_desc: int,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function load; raises on a NACK, timeout or refusal."""
        cls = threedm.LowpassFilter
        command = cls(
            function=_t.FunctionSelector.LOAD,
            desc_set=desc_set,
            field_desc=field_desc,
        )
        self._call(command, timeout_ms, check_device)

    def default(
        self,
        desc_set: int,
        field_desc: int,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function default; raises on a NACK, timeout or refusal."""
        cls = threedm.LowpassFilter
        command = cls(
            function=_t.FunctionSelector.DEFAULT,
            desc_set=desc_set,
            field_desc=field_desc,
        )
        self._call(command, timeout_ms, check_device)


class PollImuData(_Command):
    """Poll IMU data (set 0x0C, descriptor 0x01)."""

    def __call__(
        self,
        option: _ty.Union[_t.Gx5PollOption, int],
        descriptors: _ty.List[_t.Gx5PollDescriptor],
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Send the command; raises on a NACK, timeout or refusal."""
        cls = threedm.PollImuData
        command = cls(
            option=option,
            descriptors=descriptors,
            num_descriptors=None if descriptors is None else len(descriptors),
        )
        self._call(command, timeout_ms, check_device)


class PollGnssData(_Command):
    """Poll GNSS data (set 0x0C, descriptor 0x02)."""

    def __call__(
        self,
        option: _ty.Union[_t.Gx5PollOption, int],
        descriptors: _ty.List[_t.Gx5PollDescriptor],
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Send the command; raises on a NACK, timeout or refusal."""
        cls = threedm.PollGnssData
        command = cls(
            option=option,
            descriptors=descriptors,
            num_descriptors=None if descriptors is None else len(descriptors),
        )
        self._call(command, timeout_ms, check_device)


class PollFilterData(_Command):
    """Poll estimation filter data (set 0x0C, descriptor 0x03)."""

    def __call__(
        self,
        option: _ty.Union[_t.Gx5PollOption, int],
        descriptors: _ty.List[_t.Gx5PollDescriptor],
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Send the command; raises on a NACK, timeout or refusal."""
        cls = threedm.PollFilterData
        command = cls(
            option=option,
            descriptors=descriptors,
            num_descriptors=None if descriptors is None else len(descriptors),
        )
        self._call(command, timeout_ms, check_device)


class PollNmeaData(_Command):
    """Poll NMEA data (set 0x0C, descriptor 0x04)."""

    def __call__(
        self,
        suppress_ack: bool,
        format_entries: _ty.List[_t.NmeaMessage],
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Send the command; raises on a NACK, timeout or refusal."""
        cls = threedm.PollNmeaData
        command = cls(
            suppress_ack=suppress_ack,
            format_entries=format_entries,
            count=None if format_entries is None else len(format_entries),
        )
        self._call(command, timeout_ms, check_device)


class PollData(_Command):
    """Poll data (set 0x0C, descriptor 0x0D)."""

    def __call__(
        self,
        desc_set: int,
        suppress_ack: bool,
        descriptors: _ty.List[int],
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Send the command; raises on a NACK, timeout or refusal."""
        cls = threedm.PollData
        command = cls(
            desc_set=desc_set,
            suppress_ack=suppress_ack,
            descriptors=descriptors,
            num_descriptors=None if descriptors is None else len(descriptors),
        )
        self._call(command, timeout_ms, check_device)


class GetImuBaseRate(_Command):
    """Get IMU data base rate (set 0x0C, descriptor 0x06)."""

    def __call__(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> threedm.ImuBaseRate:
        """Send the command: returns the reply field."""
        cls = threedm.GetImuBaseRate
        command = cls()
        return _ty.cast("threedm.ImuBaseRate", self._call(command, timeout_ms, check_device))


class GetGnssBaseRate(_Command):
    """Get GNSS data base rate (set 0x0C, descriptor 0x07)."""

    def __call__(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> threedm.GnssBaseRate:
        """Send the command: returns the reply field."""
        cls = threedm.GetGnssBaseRate
        command = cls()
        return _ty.cast("threedm.GnssBaseRate", self._call(command, timeout_ms, check_device))


class GetFilterBaseRate(_Command):
    """Get estimation filter data base rate (set 0x0C, descriptor 0x0B)."""

    def __call__(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> threedm.FilterBaseRate:
        """Send the command: returns the reply field."""
        cls = threedm.GetFilterBaseRate
        command = cls()
        return _ty.cast("threedm.FilterBaseRate", self._call(command, timeout_ms, check_device))


class GetBaseRate(_Command):
    """Get data base rate (set 0x0C, descriptor 0x0E)."""

    def __call__(
        self,
        desc_set: int,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> threedm.BaseRate:
        """Send the command: returns the reply field."""
        cls = threedm.GetBaseRate
        command = cls(
            desc_set=desc_set,
        )
        return _ty.cast("threedm.BaseRate", self._call(command, timeout_ms, check_device))


class ImuMessageFormat(_Command):
    """IMU message format (set 0x0C, descriptor 0x08)."""

    def write(
        self,
        descriptors: _ty.List[_t.DescriptorRate],
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function write; raises on a NACK, timeout or refusal."""
        cls = threedm.ImuMessageFormat
        command = cls(
            function=_t.FunctionSelector.WRITE,
            descriptors=descriptors,
            num_descriptors=None if descriptors is None else len(descriptors),
        )
        self._call(command, timeout_ms, check_device)

    def read(
        self,
        descriptors: _ty.Optional[_ty.List[_t.DescriptorRate]] = None,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> threedm.ImuMessageFormatResponse:
        """Function read: returns the reply field."""
        cls = threedm.ImuMessageFormat
        command = cls(
            function=_t.FunctionSelector.READ,
            descriptors=descriptors,
            num_descriptors=None if descriptors is None else len(descriptors),
        )
        return _ty.cast("threedm.ImuMessageFormatResponse", self._call(command, timeout_ms, check_device))

    def save(
        self,
        descriptors: _ty.Optional[_ty.List[_t.DescriptorRate]] = None,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function save; raises on a NACK, timeout or refusal."""
        cls = threedm.ImuMessageFormat
        command = cls(
            function=_t.FunctionSelector.SAVE,
            descriptors=descriptors,
            num_descriptors=None if descriptors is None else len(descriptors),
        )
        self._call(command, timeout_ms, check_device)

    def load(
        self,
        descriptors: _ty.Optional[_ty.List[_t.DescriptorRate]] = None,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function load; raises on a NACK, timeout or refusal."""
        cls = threedm.ImuMessageFormat
        command = cls(
            function=_t.FunctionSelector.LOAD,
            descriptors=descriptors,
            num_descriptors=None if descriptors is None else len(descriptors),
        )
        self._call(command, timeout_ms, check_device)

    def default(
        self,
        descriptors: _ty.Optional[_ty.List[_t.DescriptorRate]] = None,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function default; raises on a NACK, timeout or refusal."""
        cls = threedm.ImuMessageFormat
        command = cls(
            function=_t.FunctionSelector.DEFAULT,
            descriptors=descriptors,
            num_descriptors=None if descriptors is None else len(descriptors),
        )
        self._call(command, timeout_ms, check_device)


class GnssMessageFormat(_Command):
    """GNSS message format (set 0x0C, descriptor 0x09)."""

    def write(
        self,
        descriptors: _ty.List[_t.DescriptorRate],
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function write; raises on a NACK, timeout or refusal."""
        cls = threedm.GnssMessageFormat
        command = cls(
            function=_t.FunctionSelector.WRITE,
            descriptors=descriptors,
            num_descriptors=None if descriptors is None else len(descriptors),
        )
        self._call(command, timeout_ms, check_device)

    def read(
        self,
        descriptors: _ty.Optional[_ty.List[_t.DescriptorRate]] = None,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> threedm.GnssMessageFormatResponse:
        """Function read: returns the reply field."""
        cls = threedm.GnssMessageFormat
        command = cls(
            function=_t.FunctionSelector.READ,
            descriptors=descriptors,
            num_descriptors=None if descriptors is None else len(descriptors),
        )
        return _ty.cast("threedm.GnssMessageFormatResponse", self._call(command, timeout_ms, check_device))

    def save(
        self,
        descriptors: _ty.Optional[_ty.List[_t.DescriptorRate]] = None,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function save; raises on a NACK, timeout or refusal."""
        cls = threedm.GnssMessageFormat
        command = cls(
            function=_t.FunctionSelector.SAVE,
            descriptors=descriptors,
            num_descriptors=None if descriptors is None else len(descriptors),
        )
        self._call(command, timeout_ms, check_device)

    def load(
        self,
        descriptors: _ty.Optional[_ty.List[_t.DescriptorRate]] = None,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function load; raises on a NACK, timeout or refusal."""
        cls = threedm.GnssMessageFormat
        command = cls(
            function=_t.FunctionSelector.LOAD,
            descriptors=descriptors,
            num_descriptors=None if descriptors is None else len(descriptors),
        )
        self._call(command, timeout_ms, check_device)

    def default(
        self,
        descriptors: _ty.Optional[_ty.List[_t.DescriptorRate]] = None,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function default; raises on a NACK, timeout or refusal."""
        cls = threedm.GnssMessageFormat
        command = cls(
            function=_t.FunctionSelector.DEFAULT,
            descriptors=descriptors,
            num_descriptors=None if descriptors is None else len(descriptors),
        )
        self._call(command, timeout_ms, check_device)


class FilterMessageFormat(_Command):
    """Estimation filter message format (set 0x0C, descriptor 0x0A)."""

    def write(
        self,
        descriptors: _ty.List[_t.DescriptorRate],
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function write; raises on a NACK, timeout or refusal."""
        cls = threedm.FilterMessageFormat
        command = cls(
            function=_t.FunctionSelector.WRITE,
            descriptors=descriptors,
            num_descriptors=None if descriptors is None else len(descriptors),
        )
        self._call(command, timeout_ms, check_device)

    def read(
        self,
        descriptors: _ty.Optional[_ty.List[_t.DescriptorRate]] = None,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> threedm.FilterMessageFormatResponse:
        """Function read: returns the reply field."""
        cls = threedm.FilterMessageFormat
        command = cls(
            function=_t.FunctionSelector.READ,
            descriptors=descriptors,
            num_descriptors=None if descriptors is None else len(descriptors),
        )
        return _ty.cast("threedm.FilterMessageFormatResponse", self._call(command, timeout_ms, check_device))

    def save(
        self,
        descriptors: _ty.Optional[_ty.List[_t.DescriptorRate]] = None,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function save; raises on a NACK, timeout or refusal."""
        cls = threedm.FilterMessageFormat
        command = cls(
            function=_t.FunctionSelector.SAVE,
            descriptors=descriptors,
            num_descriptors=None if descriptors is None else len(descriptors),
        )
        self._call(command, timeout_ms, check_device)

    def load(
        self,
        descriptors: _ty.Optional[_ty.List[_t.DescriptorRate]] = None,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function load; raises on a NACK, timeout or refusal."""
        cls = threedm.FilterMessageFormat
        command = cls(
            function=_t.FunctionSelector.LOAD,
            descriptors=descriptors,
            num_descriptors=None if descriptors is None else len(descriptors),
        )
        self._call(command, timeout_ms, check_device)

    def default(
        self,
        descriptors: _ty.Optional[_ty.List[_t.DescriptorRate]] = None,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function default; raises on a NACK, timeout or refusal."""
        cls = threedm.FilterMessageFormat
        command = cls(
            function=_t.FunctionSelector.DEFAULT,
            descriptors=descriptors,
            num_descriptors=None if descriptors is None else len(descriptors),
        )
        self._call(command, timeout_ms, check_device)


class NmeaMessageFormat(_Command):
    """NMEA message format (set 0x0C, descriptor 0x0C)."""

    def write(
        self,
        format_entries: _ty.List[_t.NmeaMessage],
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function write; raises on a NACK, timeout or refusal."""
        cls = threedm.NmeaMessageFormat
        command = cls(
            function=_t.FunctionSelector.WRITE,
            format_entries=format_entries,
            count=None if format_entries is None else len(format_entries),
        )
        self._call(command, timeout_ms, check_device)

    def read(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> threedm.NmeaMessageFormatResponse:
        """Function read: returns the reply field."""
        cls = threedm.NmeaMessageFormat
        command = cls(
            function=_t.FunctionSelector.READ,
        )
        return _ty.cast("threedm.NmeaMessageFormatResponse", self._call(command, timeout_ms, check_device))

    def save(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function save; raises on a NACK, timeout or refusal."""
        cls = threedm.NmeaMessageFormat
        command = cls(
            function=_t.FunctionSelector.SAVE,
        )
        self._call(command, timeout_ms, check_device)

    def load(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function load; raises on a NACK, timeout or refusal."""
        cls = threedm.NmeaMessageFormat
        command = cls(
            function=_t.FunctionSelector.LOAD,
        )
        self._call(command, timeout_ms, check_device)

    def default(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function default; raises on a NACK, timeout or refusal."""
        cls = threedm.NmeaMessageFormat
        command = cls(
            function=_t.FunctionSelector.DEFAULT,
        )
        self._call(command, timeout_ms, check_device)


class MessageFormat(_Command):
    """Message format (set 0x0C, descriptor 0x0F)."""

    def write(
        self,
        desc_set: int,
        descriptors: _ty.List[_t.DescriptorRate],
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function write; raises on a NACK, timeout or refusal."""
        cls = threedm.MessageFormat
        command = cls(
            function=_t.FunctionSelector.WRITE,
            desc_set=desc_set,
            descriptors=descriptors,
            num_descriptors=None if descriptors is None else len(descriptors),
        )
        self._call(command, timeout_ms, check_device)

    def read(
        self,
        desc_set: int,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> threedm.MessageFormatResponse:
        """Function read: returns the reply field."""
        cls = threedm.MessageFormat
        command = cls(
            function=_t.FunctionSelector.READ,
            desc_set=desc_set,
        )
        return _ty.cast("threedm.MessageFormatResponse", self._call(command, timeout_ms, check_device))

    def save(
        self,
        desc_set: int,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function save; raises on a NACK, timeout or refusal."""
        cls = threedm.MessageFormat
        command = cls(
            function=_t.FunctionSelector.SAVE,
            desc_set=desc_set,
        )
        self._call(command, timeout_ms, check_device)

    def load(
        self,
        desc_set: int,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function load; raises on a NACK, timeout or refusal."""
        cls = threedm.MessageFormat
        command = cls(
            function=_t.FunctionSelector.LOAD,
            desc_set=desc_set,
        )
        self._call(command, timeout_ms, check_device)

    def default(
        self,
        desc_set: int,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function default; raises on a NACK, timeout or refusal."""
        cls = threedm.MessageFormat
        command = cls(
            function=_t.FunctionSelector.DEFAULT,
            desc_set=desc_set,
        )
        self._call(command, timeout_ms, check_device)


class FactoryStreaming(_Command):
    """Factory streaming (set 0x0C, descriptor 0x10)."""

    def __call__(
        self,
        action: _ty.Union[_t.FactoryStreamingAction, int],
        reserved: int,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Send the command; raises on a NACK, timeout or refusal."""
        cls = threedm.FactoryStreaming
        command = cls(
            action=action,
            reserved=reserved,
        )
        self._call(command, timeout_ms, check_device)


class DataStreamControl(_Command):
    """Data stream control (set 0x0C, descriptor 0x11)."""

    def write_gx5_45(
        self,
        device_selector: _ty.Union[_t.Gx5StreamSelector, int],
        enable: int,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function write (layout for gx5_45); raises on a NACK, timeout or refusal."""
        cls = self._pick({"gx5_45": threedm.DataStreamControl_gx5_45})
        command = cls(
            function=_t.FunctionSelector.WRITE,
            device_selector=device_selector,
            enable=enable,
        )
        self._call(command, timeout_ms, check_device)

    def write_cv7_ins(
        self,
        desc_set: int,
        enable: bool,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function write (layout for cv7_ins); raises on a NACK, timeout or refusal."""
        cls = self._pick({"cv7_ins": threedm.DataStreamControl_cv7_ins})
        command = cls(
            function=_t.FunctionSelector.WRITE,
            desc_set=desc_set,
            enable=enable,
        )
        self._call(command, timeout_ms, check_device)

    def read_gx5_45(
        self,
        device_selector: _ty.Union[_t.Gx5StreamSelector, int],
        enable: _ty.Optional[int] = None,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> _ty.Any:
        """Function read (layout for gx5_45): returns the reply field."""
        cls = self._pick({"gx5_45": threedm.DataStreamControl_gx5_45})
        command = cls(
            function=_t.FunctionSelector.READ,
            device_selector=device_selector,
            enable=enable,
        )
        return _ty.cast("_ty.Any", self._call(command, timeout_ms, check_device))

    def read_cv7_ins(
        self,
        desc_set: int,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> _ty.Any:
        """Function read (layout for cv7_ins): returns the reply field."""
        cls = self._pick({"cv7_ins": threedm.DataStreamControl_cv7_ins})
        command = cls(
            function=_t.FunctionSelector.READ,
            desc_set=desc_set,
        )
        return _ty.cast("_ty.Any", self._call(command, timeout_ms, check_device))

    def save_gx5_45(
        self,
        device_selector: _ty.Union[_t.Gx5StreamSelector, int],
        enable: _ty.Optional[int] = None,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function save (layout for gx5_45); raises on a NACK, timeout or refusal."""
        cls = self._pick({"gx5_45": threedm.DataStreamControl_gx5_45})
        command = cls(
            function=_t.FunctionSelector.SAVE,
            device_selector=device_selector,
            enable=enable,
        )
        self._call(command, timeout_ms, check_device)

    def save_cv7_ins(
        self,
        desc_set: int,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function save (layout for cv7_ins); raises on a NACK, timeout or refusal."""
        cls = self._pick({"cv7_ins": threedm.DataStreamControl_cv7_ins})
        command = cls(
            function=_t.FunctionSelector.SAVE,
            desc_set=desc_set,
        )
        self._call(command, timeout_ms, check_device)

    def load_gx5_45(
        self,
        device_selector: _ty.Union[_t.Gx5StreamSelector, int],
        enable: _ty.Optional[int] = None,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function load (layout for gx5_45); raises on a NACK, timeout or refusal."""
        cls = self._pick({"gx5_45": threedm.DataStreamControl_gx5_45})
        command = cls(
            function=_t.FunctionSelector.LOAD,
            device_selector=device_selector,
            enable=enable,
        )
        self._call(command, timeout_ms, check_device)

    def load_cv7_ins(
        self,
        desc_set: int,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function load (layout for cv7_ins); raises on a NACK, timeout or refusal."""
        cls = self._pick({"cv7_ins": threedm.DataStreamControl_cv7_ins})
        command = cls(
            function=_t.FunctionSelector.LOAD,
            desc_set=desc_set,
        )
        self._call(command, timeout_ms, check_device)

    def default_gx5_45(
        self,
        device_selector: _ty.Union[_t.Gx5StreamSelector, int],
        enable: _ty.Optional[int] = None,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function default (layout for gx5_45); raises on a NACK, timeout or refusal."""
        cls = self._pick({"gx5_45": threedm.DataStreamControl_gx5_45})
        command = cls(
            function=_t.FunctionSelector.DEFAULT,
            device_selector=device_selector,
            enable=enable,
        )
        self._call(command, timeout_ms, check_device)

    def default_cv7_ins(
        self,
        desc_set: int,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function default (layout for cv7_ins); raises on a NACK, timeout or refusal."""
        cls = self._pick({"cv7_ins": threedm.DataStreamControl_cv7_ins})
        command = cls(
            function=_t.FunctionSelector.DEFAULT,
            desc_set=desc_set,
        )
        self._call(command, timeout_ms, check_device)


class RawRtcmMessage(_Command):
    """Raw RTCM 2.3 message (set 0x0C, descriptor 0x20)."""

    def __call__(
        self,
        data: _ty.List[int],
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Send the command; raises on a NACK, timeout or refusal."""
        cls = threedm.RawRtcmMessage
        command = cls(
            data=data,
        )
        self._call(command, timeout_ms, check_device)


class GnssConstellationSettings(_Command):
    """GNSS constellation settings (set 0x0C, descriptor 0x21)."""

    def write(
        self,
        max_channels: int,
        settings: _ty.List[_t.ConstellationSettings],
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function write; raises on a NACK, timeout or refusal."""
        cls = threedm.GnssConstellationSettings
        command = cls(
            function=_t.FunctionSelector.WRITE,
            max_channels=max_channels,
            settings=settings,
            config_count=None if settings is None else len(settings),
        )
        self._call(command, timeout_ms, check_device)

    def read(
        self,
        max_channels: _ty.Optional[int] = None,
        settings: _ty.Optional[_ty.List[_t.ConstellationSettings]] = None,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> threedm.GnssConstellationSettingsResponse:
        """Function read: returns the reply field."""
        cls = threedm.GnssConstellationSettings
        command = cls(
            function=_t.FunctionSelector.READ,
            max_channels=max_channels,
            settings=settings,
            config_count=None if settings is None else len(settings),
        )
        return _ty.cast("threedm.GnssConstellationSettingsResponse", self._call(command, timeout_ms, check_device))

    def save(
        self,
        max_channels: _ty.Optional[int] = None,
        settings: _ty.Optional[_ty.List[_t.ConstellationSettings]] = None,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function save; raises on a NACK, timeout or refusal."""
        cls = threedm.GnssConstellationSettings
        command = cls(
            function=_t.FunctionSelector.SAVE,
            max_channels=max_channels,
            settings=settings,
            config_count=None if settings is None else len(settings),
        )
        self._call(command, timeout_ms, check_device)

    def load(
        self,
        max_channels: _ty.Optional[int] = None,
        settings: _ty.Optional[_ty.List[_t.ConstellationSettings]] = None,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function load; raises on a NACK, timeout or refusal."""
        cls = threedm.GnssConstellationSettings
        command = cls(
            function=_t.FunctionSelector.LOAD,
            max_channels=max_channels,
            settings=settings,
            config_count=None if settings is None else len(settings),
        )
        self._call(command, timeout_ms, check_device)

    def default(
        self,
        max_channels: _ty.Optional[int] = None,
        settings: _ty.Optional[_ty.List[_t.ConstellationSettings]] = None,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function default; raises on a NACK, timeout or refusal."""
        cls = threedm.GnssConstellationSettings
        command = cls(
            function=_t.FunctionSelector.DEFAULT,
            max_channels=max_channels,
            settings=settings,
            config_count=None if settings is None else len(settings),
        )
        self._call(command, timeout_ms, check_device)


class GnssSbasSettings(_Command):
    """GNSS SBAS settings (set 0x0C, descriptor 0x22)."""

    def write(
        self,
        enable_sbas: int,
        sbas_options: _t.SbasOptions,
        included_prns: _ty.List[int],
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function write; raises on a NACK, timeout or refusal."""
        cls = threedm.GnssSbasSettings
        command = cls(
            function=_t.FunctionSelector.WRITE,
            enable_sbas=enable_sbas,
            sbas_options=sbas_options,
            included_prns=included_prns,
            num_included_prns=None if included_prns is None else len(included_prns),
        )
        self._call(command, timeout_ms, check_device)

    def read(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> threedm.GnssSbasSettingsResponse:
        """Function read: returns the reply field."""
        cls = threedm.GnssSbasSettings
        command = cls(
            function=_t.FunctionSelector.READ,
        )
        return _ty.cast("threedm.GnssSbasSettingsResponse", self._call(command, timeout_ms, check_device))

    def save(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function save; raises on a NACK, timeout or refusal."""
        cls = threedm.GnssSbasSettings
        command = cls(
            function=_t.FunctionSelector.SAVE,
        )
        self._call(command, timeout_ms, check_device)

    def load(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function load; raises on a NACK, timeout or refusal."""
        cls = threedm.GnssSbasSettings
        command = cls(
            function=_t.FunctionSelector.LOAD,
        )
        self._call(command, timeout_ms, check_device)

    def default(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function default; raises on a NACK, timeout or refusal."""
        cls = threedm.GnssSbasSettings
        command = cls(
            function=_t.FunctionSelector.DEFAULT,
        )
        self._call(command, timeout_ms, check_device)


class GnssAssistedFixControl(_Command):
    """GNSS assisted fix control (set 0x0C, descriptor 0x23)."""

    def write(
        self,
        option: _ty.Union[_t.AssistedFixOption, int],
        flags: int,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function write; raises on a NACK, timeout or refusal."""
        cls = threedm.GnssAssistedFixControl
        command = cls(
            function=_t.FunctionSelector.WRITE,
            option=option,
            flags=flags,
        )
        self._call(command, timeout_ms, check_device)

    def read(
        self,
        option: _ty.Optional[_ty.Union[_t.AssistedFixOption, int]] = None,
        flags: _ty.Optional[int] = None,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> threedm.GnssAssistedFixControlResponse:
        """Function read: returns the reply field."""
        cls = threedm.GnssAssistedFixControl
        command = cls(
            function=_t.FunctionSelector.READ,
            option=option,
            flags=flags,
        )
        return _ty.cast("threedm.GnssAssistedFixControlResponse", self._call(command, timeout_ms, check_device))

    def save(
        self,
        option: _ty.Optional[_ty.Union[_t.AssistedFixOption, int]] = None,
        flags: _ty.Optional[int] = None,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function save; raises on a NACK, timeout or refusal."""
        cls = threedm.GnssAssistedFixControl
        command = cls(
            function=_t.FunctionSelector.SAVE,
            option=option,
            flags=flags,
        )
        self._call(command, timeout_ms, check_device)

    def load(
        self,
        option: _ty.Optional[_ty.Union[_t.AssistedFixOption, int]] = None,
        flags: _ty.Optional[int] = None,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function load; raises on a NACK, timeout or refusal."""
        cls = threedm.GnssAssistedFixControl
        command = cls(
            function=_t.FunctionSelector.LOAD,
            option=option,
            flags=flags,
        )
        self._call(command, timeout_ms, check_device)

    def default(
        self,
        option: _ty.Optional[_ty.Union[_t.AssistedFixOption, int]] = None,
        flags: _ty.Optional[int] = None,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function default; raises on a NACK, timeout or refusal."""
        cls = threedm.GnssAssistedFixControl
        command = cls(
            function=_t.FunctionSelector.DEFAULT,
            option=option,
            flags=flags,
        )
        self._call(command, timeout_ms, check_device)


class GnssAssistTimeUpdate(_Command):
    """GNSS assist time update (set 0x0C, descriptor 0x24)."""

    def write(
        self,
        tow: float,
        week_number: int,
        accuracy: float,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function write; raises on a NACK, timeout or refusal."""
        cls = threedm.GnssAssistTimeUpdate
        command = cls(
            function=_t.FunctionSelector.WRITE,
            tow=tow,
            week_number=week_number,
            accuracy=accuracy,
        )
        self._call(command, timeout_ms, check_device)

    def read(
        self,
        tow: _ty.Optional[float] = None,
        week_number: _ty.Optional[int] = None,
        accuracy: _ty.Optional[float] = None,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> threedm.GnssAssistTimeUpdateResponse:
        """Function read: returns the reply field."""
        cls = threedm.GnssAssistTimeUpdate
        command = cls(
            function=_t.FunctionSelector.READ,
            tow=tow,
            week_number=week_number,
            accuracy=accuracy,
        )
        return _ty.cast("threedm.GnssAssistTimeUpdateResponse", self._call(command, timeout_ms, check_device))


class PpsSource(_Command):
    """PPS source control (set 0x0C, descriptor 0x28)."""

    def write(
        self,
        source: _ty.Union[_t.PpsSource, int],
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function write; raises on a NACK, timeout or refusal."""
        cls = threedm.PpsSource
        command = cls(
            function=_t.FunctionSelector.WRITE,
            source=source,
        )
        self._call(command, timeout_ms, check_device)

    def read(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> threedm.PpsSourceResponse:
        """Function read: returns the reply field."""
        cls = threedm.PpsSource
        command = cls(
            function=_t.FunctionSelector.READ,
        )
        return _ty.cast("threedm.PpsSourceResponse", self._call(command, timeout_ms, check_device))

    def save(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function save; raises on a NACK, timeout or refusal."""
        cls = threedm.PpsSource
        command = cls(
            function=_t.FunctionSelector.SAVE,
        )
        self._call(command, timeout_ms, check_device)

    def load(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function load; raises on a NACK, timeout or refusal."""
        cls = threedm.PpsSource
        command = cls(
            function=_t.FunctionSelector.LOAD,
        )
        self._call(command, timeout_ms, check_device)

    def default(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function default; raises on a NACK, timeout or refusal."""
        cls = threedm.PpsSource
        command = cls(
            function=_t.FunctionSelector.DEFAULT,
        )
        self._call(command, timeout_ms, check_device)


class GetSupportedEvents(_Command):
    """Get supported events (set 0x0C, descriptor 0x2A)."""

    def __call__(
        self,
        query: _ty.Union[_t.SupportedEventsQuery, int],
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> threedm.SupportedEvents:
        """Send the command: returns the reply field."""
        cls = threedm.GetSupportedEvents
        command = cls(
            query=query,
        )
        return _ty.cast("threedm.SupportedEvents", self._call(command, timeout_ms, check_device))


class DeviceStatus(_Command):
    """Device status (set 0x0C, descriptor 0x64)."""

    def __call__(
        self,
        model_number: int,
        status_selector: _ty.Union[_t.DeviceStatusSelector, int],
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> threedm.DeviceStatusResponse:
        """Send the command: returns the reply field."""
        cls = threedm.DeviceStatus
        command = cls(
            model_number=model_number,
            status_selector=status_selector,
        )
        return _ty.cast("threedm.DeviceStatusResponse", self._call(command, timeout_ms, check_device))


class ThreedmCommands:
    """3DM Command Set commands (set 0x0C)."""

    def __init__(self, device: _s.Device) -> None:
        self.event_control = EventControl(device)
        self.get_event_trigger_status = GetEventTriggerStatus(device)
        self.get_event_action_status = GetEventActionStatus(device)
        self.event_trigger_config = EventTriggerConfig(device)
        self.event_action_config = EventActionConfig(device)
        self.device_startup_settings = DeviceStartupSettings(device)
        self.sensor_to_vehicle_euler = SensorToVehicleEuler(device)
        self.sensor_to_vehicle_quaternion = SensorToVehicleQuaternion(device)
        self.sensor_to_vehicle_dcm = SensorToVehicleDcm(device)
        self.accel_bias = AccelBias(device)
        self.gyro_bias = GyroBias(device)
        self.capture_gyro_bias = CaptureGyroBias(device)
        self.mag_hard_iron_offset = MagHardIronOffset(device)
        self.mag_soft_iron_matrix = MagSoftIronMatrix(device)
        self.coning_sculling_enable = ConingScullingEnable(device)
        self.uart_baudrate = UartBaudrate(device)
        self.gpio_config = GpioConfig(device)
        self.gpio_state = GpioState(device)
        self.odometer_config = OdometerConfig(device)
        self.advanced_lowpass_filter = AdvancedLowpassFilter(device)
        self.complementary_filter = ComplementaryFilter(device)
        self.sensor_range = SensorRange(device)
        self.get_calibrated_sensor_ranges = GetCalibratedSensorRanges(device)
        self.lowpass_filter = LowpassFilter(device)
        self.poll_imu_data = PollImuData(device)
        self.poll_gnss_data = PollGnssData(device)
        self.poll_filter_data = PollFilterData(device)
        self.poll_nmea_data = PollNmeaData(device)
        self.poll_data = PollData(device)
        self.get_imu_base_rate = GetImuBaseRate(device)
        self.get_gnss_base_rate = GetGnssBaseRate(device)
        self.get_filter_base_rate = GetFilterBaseRate(device)
        self.get_base_rate = GetBaseRate(device)
        self.imu_message_format = ImuMessageFormat(device)
        self.gnss_message_format = GnssMessageFormat(device)
        self.filter_message_format = FilterMessageFormat(device)
        self.nmea_message_format = NmeaMessageFormat(device)
        self.message_format = MessageFormat(device)
        self.factory_streaming = FactoryStreaming(device)
        self.data_stream_control = DataStreamControl(device)
        self.raw_rtcm_message = RawRtcmMessage(device)
        self.gnss_constellation_settings = GnssConstellationSettings(device)
        self.gnss_sbas_settings = GnssSbasSettings(device)
        self.gnss_assisted_fix_control = GnssAssistedFixControl(device)
        self.gnss_assist_time_update = GnssAssistTimeUpdate(device)
        self.pps_source = PpsSource(device)
        self.get_supported_events = GetSupportedEvents(device)
        self.device_status = DeviceStatus(device)


class ResetFilter(_Command):
    """Reset filter (set 0x0D, descriptor 0x01)."""

    def __call__(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Send the command; raises on a NACK, timeout or refusal."""
        cls = filter.ResetFilter
        command = cls()
        self._call(command, timeout_ms, check_device)


class SetInitialAttitude(_Command):
    """Set initial attitude (set 0x0D, descriptor 0x02)."""

    def __call__(
        self,
        roll: float,
        pitch: float,
        heading: float,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Send the command; raises on a NACK, timeout or refusal."""
        cls = filter.SetInitialAttitude
        command = cls(
            roll=roll,
            pitch=pitch,
            heading=heading,
        )
        self._call(command, timeout_ms, check_device)


class SetInitialHeading(_Command):
    """Set initial heading (set 0x0D, descriptor 0x03)."""

    def __call__(
        self,
        heading: float,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Send the command; raises on a NACK, timeout or refusal."""
        cls = filter.SetInitialHeading
        command = cls(
            heading=heading,
        )
        self._call(command, timeout_ms, check_device)


class RunFilter(_Command):
    """Run navigation filter (set 0x0D, descriptor 0x05)."""

    def __call__(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Send the command; raises on a NACK, timeout or refusal."""
        cls = filter.RunFilter
        command = cls()
        self._call(command, timeout_ms, check_device)


class VehicleDynamicsMode(_Command):
    """Vehicle dynamics mode (set 0x0D, descriptor 0x10)."""

    def write(
        self,
        mode: _ty.Union[_t.VehicleDynamicsMode, int],
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function write; raises on a NACK, timeout or refusal."""
        cls = filter.VehicleDynamicsMode
        command = cls(
            function=_t.FunctionSelector.WRITE,
            mode=mode,
        )
        self._call(command, timeout_ms, check_device)

    def read(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> filter.VehicleDynamicsModeResponse:
        """Function read: returns the reply field."""
        cls = filter.VehicleDynamicsMode
        command = cls(
            function=_t.FunctionSelector.READ,
        )
        return _ty.cast("filter.VehicleDynamicsModeResponse", self._call(command, timeout_ms, check_device))

    def save(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function save; raises on a NACK, timeout or refusal."""
        cls = filter.VehicleDynamicsMode
        command = cls(
            function=_t.FunctionSelector.SAVE,
        )
        self._call(command, timeout_ms, check_device)

    def load(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function load; raises on a NACK, timeout or refusal."""
        cls = filter.VehicleDynamicsMode
        command = cls(
            function=_t.FunctionSelector.LOAD,
        )
        self._call(command, timeout_ms, check_device)

    def default(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function default; raises on a NACK, timeout or refusal."""
        cls = filter.VehicleDynamicsMode
        command = cls(
            function=_t.FunctionSelector.DEFAULT,
        )
        self._call(command, timeout_ms, check_device)


class SensorToVehicleTransform(_Command):
    """Sensor to vehicle frame transformation (set 0x0D, descriptor 0x11)."""

    def write(
        self,
        roll: float,
        pitch: float,
        yaw: float,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function write; raises on a NACK, timeout or refusal."""
        cls = filter.SensorToVehicleTransform
        command = cls(
            function=_t.FunctionSelector.WRITE,
            roll=roll,
            pitch=pitch,
            yaw=yaw,
        )
        self._call(command, timeout_ms, check_device)

    def read(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> filter.SensorToVehicleTransformResponse:
        """Function read: returns the reply field."""
        cls = filter.SensorToVehicleTransform
        command = cls(
            function=_t.FunctionSelector.READ,
        )
        return _ty.cast("filter.SensorToVehicleTransformResponse", self._call(command, timeout_ms, check_device))

    def save(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function save; raises on a NACK, timeout or refusal."""
        cls = filter.SensorToVehicleTransform
        command = cls(
            function=_t.FunctionSelector.SAVE,
        )
        self._call(command, timeout_ms, check_device)

    def load(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function load; raises on a NACK, timeout or refusal."""
        cls = filter.SensorToVehicleTransform
        command = cls(
            function=_t.FunctionSelector.LOAD,
        )
        self._call(command, timeout_ms, check_device)

    def default(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function default; raises on a NACK, timeout or refusal."""
        cls = filter.SensorToVehicleTransform
        command = cls(
            function=_t.FunctionSelector.DEFAULT,
        )
        self._call(command, timeout_ms, check_device)


class SensorToVehicleOffset(_Command):
    """Sensor to vehicle frame offset (set 0x0D, descriptor 0x12)."""

    def write(
        self,
        offset: _ty.List[float],
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function write; raises on a NACK, timeout or refusal."""
        cls = filter.SensorToVehicleOffset
        command = cls(
            function=_t.FunctionSelector.WRITE,
            offset=offset,
        )
        self._call(command, timeout_ms, check_device)

    def read(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> filter.SensorToVehicleOffsetResponse:
        """Function read: returns the reply field."""
        cls = filter.SensorToVehicleOffset
        command = cls(
            function=_t.FunctionSelector.READ,
        )
        return _ty.cast("filter.SensorToVehicleOffsetResponse", self._call(command, timeout_ms, check_device))

    def save(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function save; raises on a NACK, timeout or refusal."""
        cls = filter.SensorToVehicleOffset
        command = cls(
            function=_t.FunctionSelector.SAVE,
        )
        self._call(command, timeout_ms, check_device)

    def load(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function load; raises on a NACK, timeout or refusal."""
        cls = filter.SensorToVehicleOffset
        command = cls(
            function=_t.FunctionSelector.LOAD,
        )
        self._call(command, timeout_ms, check_device)

    def default(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function default; raises on a NACK, timeout or refusal."""
        cls = filter.SensorToVehicleOffset
        command = cls(
            function=_t.FunctionSelector.DEFAULT,
        )
        self._call(command, timeout_ms, check_device)


class AntennaOffset(_Command):
    """GNSS antenna offset (set 0x0D, descriptor 0x13)."""

    def write(
        self,
        offset: _ty.List[float],
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function write; raises on a NACK, timeout or refusal."""
        cls = filter.AntennaOffset
        command = cls(
            function=_t.FunctionSelector.WRITE,
            offset=offset,
        )
        self._call(command, timeout_ms, check_device)

    def read(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> filter.AntennaOffsetResponse:
        """Function read: returns the reply field."""
        cls = filter.AntennaOffset
        command = cls(
            function=_t.FunctionSelector.READ,
        )
        return _ty.cast("filter.AntennaOffsetResponse", self._call(command, timeout_ms, check_device))

    def save(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function save; raises on a NACK, timeout or refusal."""
        cls = filter.AntennaOffset
        command = cls(
            function=_t.FunctionSelector.SAVE,
        )
        self._call(command, timeout_ms, check_device)

    def load(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function load; raises on a NACK, timeout or refusal."""
        cls = filter.AntennaOffset
        command = cls(
            function=_t.FunctionSelector.LOAD,
        )
        self._call(command, timeout_ms, check_device)

    def default(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function default; raises on a NACK, timeout or refusal."""
        cls = filter.AntennaOffset
        command = cls(
            function=_t.FunctionSelector.DEFAULT,
        )
        self._call(command, timeout_ms, check_device)


class EstimationControl(_Command):
    """Estimation control flags (set 0x0D, descriptor 0x14)."""

    def write(
        self,
        flags: _t.EstimationControlFlags,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function write; raises on a NACK, timeout or refusal."""
        cls = filter.EstimationControl
        command = cls(
            function=_t.FunctionSelector.WRITE,
            flags=flags,
        )
        self._call(command, timeout_ms, check_device)

    def read(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> filter.EstimationControlResponse:
        """Function read: returns the reply field."""
        cls = filter.EstimationControl
        command = cls(
            function=_t.FunctionSelector.READ,
        )
        return _ty.cast("filter.EstimationControlResponse", self._call(command, timeout_ms, check_device))

    def save(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function save; raises on a NACK, timeout or refusal."""
        cls = filter.EstimationControl
        command = cls(
            function=_t.FunctionSelector.SAVE,
        )
        self._call(command, timeout_ms, check_device)

    def load(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function load; raises on a NACK, timeout or refusal."""
        cls = filter.EstimationControl
        command = cls(
            function=_t.FunctionSelector.LOAD,
        )
        self._call(command, timeout_ms, check_device)

    def default(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function default; raises on a NACK, timeout or refusal."""
        cls = filter.EstimationControl
        command = cls(
            function=_t.FunctionSelector.DEFAULT,
        )
        self._call(command, timeout_ms, check_device)


class GnssSourceControl(_Command):
    """GNSS source control (set 0x0D, descriptor 0x15)."""

    def write(
        self,
        source: _ty.Union[_t.FilterGnssSource, int],
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function write; raises on a NACK, timeout or refusal."""
        cls = filter.GnssSourceControl
        command = cls(
            function=_t.FunctionSelector.WRITE,
            source=source,
        )
        self._call(command, timeout_ms, check_device)

    def read(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> filter.GnssSourceControlResponse:
        """Function read: returns the reply field."""
        cls = filter.GnssSourceControl
        command = cls(
            function=_t.FunctionSelector.READ,
        )
        return _ty.cast("filter.GnssSourceControlResponse", self._call(command, timeout_ms, check_device))

    def save(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function save; raises on a NACK, timeout or refusal."""
        cls = filter.GnssSourceControl
        command = cls(
            function=_t.FunctionSelector.SAVE,
        )
        self._call(command, timeout_ms, check_device)

    def load(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function load; raises on a NACK, timeout or refusal."""
        cls = filter.GnssSourceControl
        command = cls(
            function=_t.FunctionSelector.LOAD,
        )
        self._call(command, timeout_ms, check_device)

    def default(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function default; raises on a NACK, timeout or refusal."""
        cls = filter.GnssSourceControl
        command = cls(
            function=_t.FunctionSelector.DEFAULT,
        )
        self._call(command, timeout_ms, check_device)


class ExternalGnssUpdate(_Command):
    """External GNSS update (set 0x0D, descriptor 0x16)."""

    def __call__(
        self,
        gps_tow: float,
        gps_week: int,
        latitude: float,
        longitude: float,
        height: float,
        velocity: _ty.List[float],
        position_uncertainty: _ty.List[float],
        velocity_uncertainty: _ty.List[float],
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Send the command; raises on a NACK, timeout or refusal."""
        cls = filter.ExternalGnssUpdate
        command = cls(
            gps_tow=gps_tow,
            gps_week=gps_week,
            latitude=latitude,
            longitude=longitude,
            height=height,
            velocity=velocity,
            position_uncertainty=position_uncertainty,
            velocity_uncertainty=velocity_uncertainty,
        )
        self._call(command, timeout_ms, check_device)


class ExternalHeadingUpdate(_Command):
    """External heading update (set 0x0D, descriptor 0x17)."""

    def __call__(
        self,
        heading: float,
        heading_uncertainty: float,
        type: _ty.Union[_t.ExternalHeadingType, int],
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Send the command; raises on a NACK, timeout or refusal."""
        cls = filter.ExternalHeadingUpdate
        command = cls(
            heading=heading,
            heading_uncertainty=heading_uncertainty,
            type=type,
        )
        self._call(command, timeout_ms, check_device)


class HeadingUpdateControl(_Command):
    """Heading update control (set 0x0D, descriptor 0x18)."""

    def write(
        self,
        source: _ty.Union[_t.HeadingUpdateSource, int],
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function write; raises on a NACK, timeout or refusal."""
        cls = filter.HeadingUpdateControl
        command = cls(
            function=_t.FunctionSelector.WRITE,
            source=source,
        )
        self._call(command, timeout_ms, check_device)

    def read(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> filter.HeadingUpdateControlResponse:
        """Function read: returns the reply field."""
        cls = filter.HeadingUpdateControl
        command = cls(
            function=_t.FunctionSelector.READ,
        )
        return _ty.cast("filter.HeadingUpdateControlResponse", self._call(command, timeout_ms, check_device))

    def save(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function save; raises on a NACK, timeout or refusal."""
        cls = filter.HeadingUpdateControl
        command = cls(
            function=_t.FunctionSelector.SAVE,
        )
        self._call(command, timeout_ms, check_device)

    def load(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function load; raises on a NACK, timeout or refusal."""
        cls = filter.HeadingUpdateControl
        command = cls(
            function=_t.FunctionSelector.LOAD,
        )
        self._call(command, timeout_ms, check_device)

    def default(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function default; raises on a NACK, timeout or refusal."""
        cls = filter.HeadingUpdateControl
        command = cls(
            function=_t.FunctionSelector.DEFAULT,
        )
        self._call(command, timeout_ms, check_device)


class AutoInitControl(_Command):
    """Auto-initialization control (set 0x0D, descriptor 0x19)."""

    def write(
        self,
        enable: int,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function write; raises on a NACK, timeout or refusal."""
        cls = filter.AutoInitControl
        command = cls(
            function=_t.FunctionSelector.WRITE,
            enable=enable,
        )
        self._call(command, timeout_ms, check_device)

    def read(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> filter.AutoInitControlResponse:
        """Function read: returns the reply field."""
        cls = filter.AutoInitControl
        command = cls(
            function=_t.FunctionSelector.READ,
        )
        return _ty.cast("filter.AutoInitControlResponse", self._call(command, timeout_ms, check_device))

    def save(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function save; raises on a NACK, timeout or refusal."""
        cls = filter.AutoInitControl
        command = cls(
            function=_t.FunctionSelector.SAVE,
        )
        self._call(command, timeout_ms, check_device)

    def load(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function load; raises on a NACK, timeout or refusal."""
        cls = filter.AutoInitControl
        command = cls(
            function=_t.FunctionSelector.LOAD,
        )
        self._call(command, timeout_ms, check_device)

    def default(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function default; raises on a NACK, timeout or refusal."""
        cls = filter.AutoInitControl
        command = cls(
            function=_t.FunctionSelector.DEFAULT,
        )
        self._call(command, timeout_ms, check_device)


class AccelNoise(_Command):
    """Accelerometer noise standard deviation (set 0x0D, descriptor 0x1A)."""

    def write(
        self,
        noise: _ty.List[float],
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function write; raises on a NACK, timeout or refusal."""
        cls = filter.AccelNoise
        command = cls(
            function=_t.FunctionSelector.WRITE,
            noise=noise,
        )
        self._call(command, timeout_ms, check_device)

    def read(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> filter.AccelNoiseResponse:
        """Function read: returns the reply field."""
        cls = filter.AccelNoise
        command = cls(
            function=_t.FunctionSelector.READ,
        )
        return _ty.cast("filter.AccelNoiseResponse", self._call(command, timeout_ms, check_device))

    def save(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function save; raises on a NACK, timeout or refusal."""
        cls = filter.AccelNoise
        command = cls(
            function=_t.FunctionSelector.SAVE,
        )
        self._call(command, timeout_ms, check_device)

    def load(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function load; raises on a NACK, timeout or refusal."""
        cls = filter.AccelNoise
        command = cls(
            function=_t.FunctionSelector.LOAD,
        )
        self._call(command, timeout_ms, check_device)

    def default(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function default; raises on a NACK, timeout or refusal."""
        cls = filter.AccelNoise
        command = cls(
            function=_t.FunctionSelector.DEFAULT,
        )
        self._call(command, timeout_ms, check_device)


class GyroNoise(_Command):
    """Gyroscope noise standard deviation (set 0x0D, descriptor 0x1B)."""

    def write(
        self,
        noise: _ty.List[float],
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function write; raises on a NACK, timeout or refusal."""
        cls = filter.GyroNoise
        command = cls(
            function=_t.FunctionSelector.WRITE,
            noise=noise,
        )
        self._call(command, timeout_ms, check_device)

    def read(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> filter.GyroNoiseResponse:
        """Function read: returns the reply field."""
        cls = filter.GyroNoise
        command = cls(
            function=_t.FunctionSelector.READ,
        )
        return _ty.cast("filter.GyroNoiseResponse", self._call(command, timeout_ms, check_device))

    def save(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function save; raises on a NACK, timeout or refusal."""
        cls = filter.GyroNoise
        command = cls(
            function=_t.FunctionSelector.SAVE,
        )
        self._call(command, timeout_ms, check_device)

    def load(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function load; raises on a NACK, timeout or refusal."""
        cls = filter.GyroNoise
        command = cls(
            function=_t.FunctionSelector.LOAD,
        )
        self._call(command, timeout_ms, check_device)

    def default(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function default; raises on a NACK, timeout or refusal."""
        cls = filter.GyroNoise
        command = cls(
            function=_t.FunctionSelector.DEFAULT,
        )
        self._call(command, timeout_ms, check_device)


class AccelBiasModel(_Command):
    """Accelerometer bias model parameters (set 0x0D, descriptor 0x1C)."""

    def write(
        self,
        beta: _ty.List[float],
        noise: _ty.List[float],
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function write; raises on a NACK, timeout or refusal."""
        cls = filter.AccelBiasModel
        command = cls(
            function=_t.FunctionSelector.WRITE,
            beta=beta,
            noise=noise,
        )
        self._call(command, timeout_ms, check_device)

    def read(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> filter.AccelBiasModelResponse:
        """Function read: returns the reply field."""
        cls = filter.AccelBiasModel
        command = cls(
            function=_t.FunctionSelector.READ,
        )
        return _ty.cast("filter.AccelBiasModelResponse", self._call(command, timeout_ms, check_device))

    def save(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function save; raises on a NACK, timeout or refusal."""
        cls = filter.AccelBiasModel
        command = cls(
            function=_t.FunctionSelector.SAVE,
        )
        self._call(command, timeout_ms, check_device)

    def load(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function load; raises on a NACK, timeout or refusal."""
        cls = filter.AccelBiasModel
        command = cls(
            function=_t.FunctionSelector.LOAD,
        )
        self._call(command, timeout_ms, check_device)

    def default(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function default; raises on a NACK, timeout or refusal."""
        cls = filter.AccelBiasModel
        command = cls(
            function=_t.FunctionSelector.DEFAULT,
        )
        self._call(command, timeout_ms, check_device)


class GyroBiasModel(_Command):
    """Gyroscope bias model parameters (set 0x0D, descriptor 0x1D)."""

    def write(
        self,
        beta: _ty.List[float],
        noise: _ty.List[float],
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function write; raises on a NACK, timeout or refusal."""
        cls = filter.GyroBiasModel
        command = cls(
            function=_t.FunctionSelector.WRITE,
            beta=beta,
            noise=noise,
        )
        self._call(command, timeout_ms, check_device)

    def read(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> filter.GyroBiasModelResponse:
        """Function read: returns the reply field."""
        cls = filter.GyroBiasModel
        command = cls(
            function=_t.FunctionSelector.READ,
        )
        return _ty.cast("filter.GyroBiasModelResponse", self._call(command, timeout_ms, check_device))

    def save(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function save; raises on a NACK, timeout or refusal."""
        cls = filter.GyroBiasModel
        command = cls(
            function=_t.FunctionSelector.SAVE,
        )
        self._call(command, timeout_ms, check_device)

    def load(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function load; raises on a NACK, timeout or refusal."""
        cls = filter.GyroBiasModel
        command = cls(
            function=_t.FunctionSelector.LOAD,
        )
        self._call(command, timeout_ms, check_device)

    def default(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function default; raises on a NACK, timeout or refusal."""
        cls = filter.GyroBiasModel
        command = cls(
            function=_t.FunctionSelector.DEFAULT,
        )
        self._call(command, timeout_ms, check_device)


class ZuptControl(_Command):
    """Zero velocity update (ZUPT) control (set 0x0D, descriptor 0x1E)."""

    def write(
        self,
        enable: int,
        threshold: float,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function write; raises on a NACK, timeout or refusal."""
        cls = filter.ZuptControl
        command = cls(
            function=_t.FunctionSelector.WRITE,
            enable=enable,
            threshold=threshold,
        )
        self._call(command, timeout_ms, check_device)

    def read(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> filter.ZuptControlResponse:
        """Function read: returns the reply field."""
        cls = filter.ZuptControl
        command = cls(
            function=_t.FunctionSelector.READ,
        )
        return _ty.cast("filter.ZuptControlResponse", self._call(command, timeout_ms, check_device))

    def save(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function save; raises on a NACK, timeout or refusal."""
        cls = filter.ZuptControl
        command = cls(
            function=_t.FunctionSelector.SAVE,
        )
        self._call(command, timeout_ms, check_device)

    def load(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function load; raises on a NACK, timeout or refusal."""
        cls = filter.ZuptControl
        command = cls(
            function=_t.FunctionSelector.LOAD,
        )
        self._call(command, timeout_ms, check_device)

    def default(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function default; raises on a NACK, timeout or refusal."""
        cls = filter.ZuptControl
        command = cls(
            function=_t.FunctionSelector.DEFAULT,
        )
        self._call(command, timeout_ms, check_device)


class ExternalHeadingUpdateWithTime(_Command):
    """External heading update with timestamp (set 0x0D, descriptor 0x1F)."""

    def __call__(
        self,
        gps_tow: float,
        gps_week: int,
        heading: float,
        heading_uncertainty: float,
        type: _ty.Union[_t.ExternalHeadingType, int],
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Send the command; raises on a NACK, timeout or refusal."""
        cls = filter.ExternalHeadingUpdateWithTime
        command = cls(
            gps_tow=gps_tow,
            gps_week=gps_week,
            heading=heading,
            heading_uncertainty=heading_uncertainty,
            type=type,
        )
        self._call(command, timeout_ms, check_device)


class ZeroAngularRateUpdateControl(_Command):
    """Zero angular rate update control (set 0x0D, descriptor 0x20)."""

    def write(
        self,
        enable: int,
        threshold: float,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function write; raises on a NACK, timeout or refusal."""
        cls = filter.ZeroAngularRateUpdateControl
        command = cls(
            function=_t.FunctionSelector.WRITE,
            enable=enable,
            threshold=threshold,
        )
        self._call(command, timeout_ms, check_device)

    def read(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> filter.ZeroAngularRateUpdateControlResponse:
        """Function read: returns the reply field."""
        cls = filter.ZeroAngularRateUpdateControl
        command = cls(
            function=_t.FunctionSelector.READ,
        )
        return _ty.cast("filter.ZeroAngularRateUpdateControlResponse", self._call(command, timeout_ms, check_device))

    def save(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function save; raises on a NACK, timeout or refusal."""
        cls = filter.ZeroAngularRateUpdateControl
        command = cls(
            function=_t.FunctionSelector.SAVE,
        )
        self._call(command, timeout_ms, check_device)

    def load(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function load; raises on a NACK, timeout or refusal."""
        cls = filter.ZeroAngularRateUpdateControl
        command = cls(
            function=_t.FunctionSelector.LOAD,
        )
        self._call(command, timeout_ms, check_device)

    def default(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function default; raises on a NACK, timeout or refusal."""
        cls = filter.ZeroAngularRateUpdateControl
        command = cls(
            function=_t.FunctionSelector.DEFAULT,
        )
        self._call(command, timeout_ms, check_device)


class TareOrientation(_Command):
    """Tare orientation (set 0x0D, descriptor 0x21)."""

    def write(
        self,
        axes: _t.TareAxes,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function write; raises on a NACK, timeout or refusal."""
        cls = filter.TareOrientation
        command = cls(
            function=_t.FunctionSelector.WRITE,
            axes=axes,
        )
        self._call(command, timeout_ms, check_device)

    def save(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function save; raises on a NACK, timeout or refusal."""
        cls = filter.TareOrientation
        command = cls(
            function=_t.FunctionSelector.SAVE,
        )
        self._call(command, timeout_ms, check_device)

    def load(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function load; raises on a NACK, timeout or refusal."""
        cls = filter.TareOrientation
        command = cls(
            function=_t.FunctionSelector.LOAD,
        )
        self._call(command, timeout_ms, check_device)

    def default(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function default; raises on a NACK, timeout or refusal."""
        cls = filter.TareOrientation
        command = cls(
            function=_t.FunctionSelector.DEFAULT,
        )
        self._call(command, timeout_ms, check_device)


class CommandedZupt(_Command):
    """Commanded zero velocity update (set 0x0D, descriptor 0x22)."""

    def __call__(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Send the command; raises on a NACK, timeout or refusal."""
        cls = filter.CommandedZupt
        command = cls()
        self._call(command, timeout_ms, check_device)


class CommandedZeroAngularRateUpdate(_Command):
    """Commanded zero angular rate update (set 0x0D, descriptor 0x23)."""

    def __call__(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Send the command; raises on a NACK, timeout or refusal."""
        cls = filter.CommandedZeroAngularRateUpdate
        command = cls()
        self._call(command, timeout_ms, check_device)


class MagCaptureAutoCalibration(_Command):
    """Magnetometer capture auto calibration (set 0x0D, descriptor 0x27)."""

    def write(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function write; raises on a NACK, timeout or refusal."""
        cls = filter.MagCaptureAutoCalibration
        command = cls(
            function=_t.FunctionSelector.WRITE,
        )
        self._call(command, timeout_ms, check_device)

    def save(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function save; raises on a NACK, timeout or refusal."""
        cls = filter.MagCaptureAutoCalibration
        command = cls(
            function=_t.FunctionSelector.SAVE,
        )
        self._call(command, timeout_ms, check_device)


class GravityNoiseStdDev(_Command):
    """Gravity noise standard deviation (set 0x0D, descriptor 0x28)."""

    def write(
        self,
        noise: _ty.List[float],
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function write; raises on a NACK, timeout or refusal."""
        cls = filter.GravityNoiseStdDev
        command = cls(
            function=_t.FunctionSelector.WRITE,
            noise=noise,
        )
        self._call(command, timeout_ms, check_device)

    def read(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> filter.GravityNoiseStdDevResponse:
        """Function read: returns the reply field."""
        cls = filter.GravityNoiseStdDev
        command = cls(
            function=_t.FunctionSelector.READ,
        )
        return _ty.cast("filter.GravityNoiseStdDevResponse", self._call(command, timeout_ms, check_device))

    def save(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function save; raises on a NACK, timeout or refusal."""
        cls = filter.GravityNoiseStdDev
        command = cls(
            function=_t.FunctionSelector.SAVE,
        )
        self._call(command, timeout_ms, check_device)

    def load(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function load; raises on a NACK, timeout or refusal."""
        cls = filter.GravityNoiseStdDev
        command = cls(
            function=_t.FunctionSelector.LOAD,
        )
        self._call(command, timeout_ms, check_device)

    def default(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function default; raises on a NACK, timeout or refusal."""
        cls = filter.GravityNoiseStdDev
        command = cls(
            function=_t.FunctionSelector.DEFAULT,
        )
        self._call(command, timeout_ms, check_device)


class PressureAltitudeNoiseStdDev(_Command):
    """Pressure altitude noise standard deviation (set 0x0D, descriptor 0x29)."""

    def write(
        self,
        noise: float,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function write; raises on a NACK, timeout or refusal."""
        cls = filter.PressureAltitudeNoiseStdDev
        command = cls(
            function=_t.FunctionSelector.WRITE,
            noise=noise,
        )
        self._call(command, timeout_ms, check_device)

    def read(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> filter.PressureAltitudeNoiseStdDevResponse:
        """Function read: returns the reply field."""
        cls = filter.PressureAltitudeNoiseStdDev
        command = cls(
            function=_t.FunctionSelector.READ,
        )
        return _ty.cast("filter.PressureAltitudeNoiseStdDevResponse", self._call(command, timeout_ms, check_device))

    def save(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function save; raises on a NACK, timeout or refusal."""
        cls = filter.PressureAltitudeNoiseStdDev
        command = cls(
            function=_t.FunctionSelector.SAVE,
        )
        self._call(command, timeout_ms, check_device)

    def load(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function load; raises on a NACK, timeout or refusal."""
        cls = filter.PressureAltitudeNoiseStdDev
        command = cls(
            function=_t.FunctionSelector.LOAD,
        )
        self._call(command, timeout_ms, check_device)

    def default(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function default; raises on a NACK, timeout or refusal."""
        cls = filter.PressureAltitudeNoiseStdDev
        command = cls(
            function=_t.FunctionSelector.DEFAULT,
        )
        self._call(command, timeout_ms, check_device)


class HardIronOffsetNoise(_Command):
    """Hard iron offset process noise (set 0x0D, descriptor 0x2B)."""

    def write(
        self,
        noise: _ty.List[float],
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function write; raises on a NACK, timeout or refusal."""
        cls = filter.HardIronOffsetNoise
        command = cls(
            function=_t.FunctionSelector.WRITE,
            noise=noise,
        )
        self._call(command, timeout_ms, check_device)

    def read(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> filter.HardIronOffsetNoiseResponse:
        """Function read: returns the reply field."""
        cls = filter.HardIronOffsetNoise
        command = cls(
            function=_t.FunctionSelector.READ,
        )
        return _ty.cast("filter.HardIronOffsetNoiseResponse", self._call(command, timeout_ms, check_device))

    def save(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function save; raises on a NACK, timeout or refusal."""
        cls = filter.HardIronOffsetNoise
        command = cls(
            function=_t.FunctionSelector.SAVE,
        )
        self._call(command, timeout_ms, check_device)

    def load(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function load; raises on a NACK, timeout or refusal."""
        cls = filter.HardIronOffsetNoise
        command = cls(
            function=_t.FunctionSelector.LOAD,
        )
        self._call(command, timeout_ms, check_device)

    def default(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function default; raises on a NACK, timeout or refusal."""
        cls = filter.HardIronOffsetNoise
        command = cls(
            function=_t.FunctionSelector.DEFAULT,
        )
        self._call(command, timeout_ms, check_device)


class SoftIronMatrixNoise(_Command):
    """Soft iron matrix process noise (set 0x0D, descriptor 0x2C)."""

    def write(
        self,
        noise: _ty.List[float],
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function write; raises on a NACK, timeout or refusal."""
        cls = filter.SoftIronMatrixNoise
        command = cls(
            function=_t.FunctionSelector.WRITE,
            noise=noise,
        )
        self._call(command, timeout_ms, check_device)

    def read(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> filter.SoftIronMatrixNoiseResponse:
        """Function read: returns the reply field."""
        cls = filter.SoftIronMatrixNoise
        command = cls(
            function=_t.FunctionSelector.READ,
        )
        return _ty.cast("filter.SoftIronMatrixNoiseResponse", self._call(command, timeout_ms, check_device))

    def save(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function save; raises on a NACK, timeout or refusal."""
        cls = filter.SoftIronMatrixNoise
        command = cls(
            function=_t.FunctionSelector.SAVE,
        )
        self._call(command, timeout_ms, check_device)

    def load(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function load; raises on a NACK, timeout or refusal."""
        cls = filter.SoftIronMatrixNoise
        command = cls(
            function=_t.FunctionSelector.LOAD,
        )
        self._call(command, timeout_ms, check_device)

    def default(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function default; raises on a NACK, timeout or refusal."""
        cls = filter.SoftIronMatrixNoise
        command = cls(
            function=_t.FunctionSelector.DEFAULT,
        )
        self._call(command, timeout_ms, check_device)


class MagNoiseStdDev(_Command):
    """Magnetometer noise standard deviation (set 0x0D, descriptor 0x42)."""

    def write(
        self,
        noise: _ty.List[float],
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function write; raises on a NACK, timeout or refusal."""
        cls = filter.MagNoiseStdDev
        command = cls(
            function=_t.FunctionSelector.WRITE,
            noise=noise,
        )
        self._call(command, timeout_ms, check_device)

    def read(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> filter.MagNoiseStdDevResponse:
        """Function read: returns the reply field."""
        cls = filter.MagNoiseStdDev
        command = cls(
            function=_t.FunctionSelector.READ,
        )
        return _ty.cast("filter.MagNoiseStdDevResponse", self._call(command, timeout_ms, check_device))

    def save(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function save; raises on a NACK, timeout or refusal."""
        cls = filter.MagNoiseStdDev
        command = cls(
            function=_t.FunctionSelector.SAVE,
        )
        self._call(command, timeout_ms, check_device)

    def load(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function load; raises on a NACK, timeout or refusal."""
        cls = filter.MagNoiseStdDev
        command = cls(
            function=_t.FunctionSelector.LOAD,
        )
        self._call(command, timeout_ms, check_device)

    def default(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function default; raises on a NACK, timeout or refusal."""
        cls = filter.MagNoiseStdDev
        command = cls(
            function=_t.FunctionSelector.DEFAULT,
        )
        self._call(command, timeout_ms, check_device)


class DeclinationSource(_Command):
    """Declination source (set 0x0D, descriptor 0x43)."""

    def write(
        self,
        source: _ty.Union[_t.MagneticParamSource, int],
        declination: float,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function write; raises on a NACK, timeout or refusal."""
        cls = filter.DeclinationSource
        command = cls(
            function=_t.FunctionSelector.WRITE,
            source=source,
            declination=declination,
        )
        self._call(command, timeout_ms, check_device)

    def read(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> filter.DeclinationSourceResponse:
        """Function read: returns the reply field."""
        cls = filter.DeclinationSource
        command = cls(
            function=_t.FunctionSelector.READ,
        )
        return _ty.cast("filter.DeclinationSourceResponse", self._call(command, timeout_ms, check_device))

    def save(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function save; raises on a NACK, timeout or refusal."""
        cls = filter.DeclinationSource
        command = cls(
            function=_t.FunctionSelector.SAVE,
        )
        self._call(command, timeout_ms, check_device)

    def load(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function load; raises on a NACK, timeout or refusal."""
        cls = filter.DeclinationSource
        command = cls(
            function=_t.FunctionSelector.LOAD,
        )
        self._call(command, timeout_ms, check_device)

    def default(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function default; raises on a NACK, timeout or refusal."""
        cls = filter.DeclinationSource
        command = cls(
            function=_t.FunctionSelector.DEFAULT,
        )
        self._call(command, timeout_ms, check_device)


class GravityMagnitudeAdaptiveMeasurement(_Command):
    """Gravity magnitude error adaptive measurement (set 0x0D, descriptor 0x44)."""

    def write(
        self,
        mode: _ty.Union[_t.AdaptiveMeasurementMode, int],
        frequency: float,
        low_limit: float,
        high_limit: float,
        low_limit_uncertainty: float,
        high_limit_uncertainty: float,
        minimum_uncertainty: float,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function write; raises on a NACK, timeout or refusal."""
        cls = filter.GravityMagnitudeAdaptiveMeasurement
        command = cls(
            function=_t.FunctionSelector.WRITE,
            mode=mode,
            frequency=frequency,
            low_limit=low_limit,
            high_limit=high_limit,
            low_limit_uncertainty=low_limit_uncertainty,
            high_limit_uncertainty=high_limit_uncertainty,
            minimum_uncertainty=minimum_uncertainty,
        )
        self._call(command, timeout_ms, check_device)

    def read(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> filter.GravityMagnitudeAdaptiveMeasurementResponse:
        """Function read: returns the reply field."""
        cls = filter.GravityMagnitudeAdaptiveMeasurement
        command = cls(
            function=_t.FunctionSelector.READ,
        )
        return _ty.cast(
            "filter.GravityMagnitudeAdaptiveMeasurementResponse", self._call(command, timeout_ms, check_device)
        )

    def save(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function save; raises on a NACK, timeout or refusal."""
        cls = filter.GravityMagnitudeAdaptiveMeasurement
        command = cls(
            function=_t.FunctionSelector.SAVE,
        )
        self._call(command, timeout_ms, check_device)

    def load(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function load; raises on a NACK, timeout or refusal."""
        cls = filter.GravityMagnitudeAdaptiveMeasurement
        command = cls(
            function=_t.FunctionSelector.LOAD,
        )
        self._call(command, timeout_ms, check_device)

    def default(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function default; raises on a NACK, timeout or refusal."""
        cls = filter.GravityMagnitudeAdaptiveMeasurement
        command = cls(
            function=_t.FunctionSelector.DEFAULT,
        )
        self._call(command, timeout_ms, check_device)


class MagMagnitudeAdaptiveMeasurement(_Command):
    """Magnetometer magnitude error adaptive measurement (set 0x0D, descriptor 0x45)."""

    def write(
        self,
        mode: _ty.Union[_t.AdaptiveMeasurementMode, int],
        frequency: float,
        low_limit: float,
        high_limit: float,
        low_limit_uncertainty: float,
        high_limit_uncertainty: float,
        minimum_uncertainty: float,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function write; raises on a NACK, timeout or refusal."""
        cls = filter.MagMagnitudeAdaptiveMeasurement
        command = cls(
            function=_t.FunctionSelector.WRITE,
            mode=mode,
            frequency=frequency,
            low_limit=low_limit,
            high_limit=high_limit,
            low_limit_uncertainty=low_limit_uncertainty,
            high_limit_uncertainty=high_limit_uncertainty,
            minimum_uncertainty=minimum_uncertainty,
        )
        self._call(command, timeout_ms, check_device)

    def read(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> filter.MagMagnitudeAdaptiveMeasurementResponse:
        """Function read: returns the reply field."""
        cls = filter.MagMagnitudeAdaptiveMeasurement
        command = cls(
            function=_t.FunctionSelector.READ,
        )
        return _ty.cast("filter.MagMagnitudeAdaptiveMeasurementResponse", self._call(command, timeout_ms, check_device))

    def save(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function save; raises on a NACK, timeout or refusal."""
        cls = filter.MagMagnitudeAdaptiveMeasurement
        command = cls(
            function=_t.FunctionSelector.SAVE,
        )
        self._call(command, timeout_ms, check_device)

    def load(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function load; raises on a NACK, timeout or refusal."""
        cls = filter.MagMagnitudeAdaptiveMeasurement
        command = cls(
            function=_t.FunctionSelector.LOAD,
        )
        self._call(command, timeout_ms, check_device)

    def default(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function default; raises on a NACK, timeout or refusal."""
        cls = filter.MagMagnitudeAdaptiveMeasurement
        command = cls(
            function=_t.FunctionSelector.DEFAULT,
        )
        self._call(command, timeout_ms, check_device)


class MagDipAngleAdaptiveMeasurement(_Command):
    """Magnetometer dip angle error adaptive measurement (set 0x0D, descriptor 0x46)."""

    def write(
        self,
        mode: _ty.Union[_t.AdaptiveMeasurementMode, int],
        frequency: float,
        high_limit: float,
        high_limit_uncertainty: float,
        minimum_uncertainty: float,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function write; raises on a NACK, timeout or refusal."""
        cls = filter.MagDipAngleAdaptiveMeasurement
        command = cls(
            function=_t.FunctionSelector.WRITE,
            mode=mode,
            frequency=frequency,
            high_limit=high_limit,
            high_limit_uncertainty=high_limit_uncertainty,
            minimum_uncertainty=minimum_uncertainty,
        )
        self._call(command, timeout_ms, check_device)

    def read(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> filter.MagDipAngleAdaptiveMeasurementResponse:
        """Function read: returns the reply field."""
        cls = filter.MagDipAngleAdaptiveMeasurement
        command = cls(
            function=_t.FunctionSelector.READ,
        )
        return _ty.cast("filter.MagDipAngleAdaptiveMeasurementResponse", self._call(command, timeout_ms, check_device))

    def save(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function save; raises on a NACK, timeout or refusal."""
        cls = filter.MagDipAngleAdaptiveMeasurement
        command = cls(
            function=_t.FunctionSelector.SAVE,
        )
        self._call(command, timeout_ms, check_device)

    def load(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function load; raises on a NACK, timeout or refusal."""
        cls = filter.MagDipAngleAdaptiveMeasurement
        command = cls(
            function=_t.FunctionSelector.LOAD,
        )
        self._call(command, timeout_ms, check_device)

    def default(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function default; raises on a NACK, timeout or refusal."""
        cls = filter.MagDipAngleAdaptiveMeasurement
        command = cls(
            function=_t.FunctionSelector.DEFAULT,
        )
        self._call(command, timeout_ms, check_device)


class AltitudeAidingControl(_Command):
    """Altitude aiding control (set 0x0D, descriptor 0x47)."""

    def write(
        self,
        source: _ty.Union[_t.AltitudeAidingSource, int],
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function write; raises on a NACK, timeout or refusal."""
        cls = filter.AltitudeAidingControl
        command = cls(
            function=_t.FunctionSelector.WRITE,
            source=source,
        )
        self._call(command, timeout_ms, check_device)

    def read(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> filter.AltitudeAidingControlResponse:
        """Function read: returns the reply field."""
        cls = filter.AltitudeAidingControl
        command = cls(
            function=_t.FunctionSelector.READ,
        )
        return _ty.cast("filter.AltitudeAidingControlResponse", self._call(command, timeout_ms, check_device))

    def save(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function save; raises on a NACK, timeout or refusal."""
        cls = filter.AltitudeAidingControl
        command = cls(
            function=_t.FunctionSelector.SAVE,
        )
        self._call(command, timeout_ms, check_device)

    def load(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function load; raises on a NACK, timeout or refusal."""
        cls = filter.AltitudeAidingControl
        command = cls(
            function=_t.FunctionSelector.LOAD,
        )
        self._call(command, timeout_ms, check_device)

    def default(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function default; raises on a NACK, timeout or refusal."""
        cls = filter.AltitudeAidingControl
        command = cls(
            function=_t.FunctionSelector.DEFAULT,
        )
        self._call(command, timeout_ms, check_device)


class PitchRollAidingControl(_Command):
    """Pitch/roll aiding control (set 0x0D, descriptor 0x4B)."""

    def write(
        self,
        source: _ty.Union[_t.PitchRollAidingSource, int],
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function write; raises on a NACK, timeout or refusal."""
        cls = filter.PitchRollAidingControl
        command = cls(
            function=_t.FunctionSelector.WRITE,
            source=source,
        )
        self._call(command, timeout_ms, check_device)

    def read(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> filter.PitchRollAidingControlResponse:
        """Function read: returns the reply field."""
        cls = filter.PitchRollAidingControl
        command = cls(
            function=_t.FunctionSelector.READ,
        )
        return _ty.cast("filter.PitchRollAidingControlResponse", self._call(command, timeout_ms, check_device))

    def save(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function save; raises on a NACK, timeout or refusal."""
        cls = filter.PitchRollAidingControl
        command = cls(
            function=_t.FunctionSelector.SAVE,
        )
        self._call(command, timeout_ms, check_device)

    def load(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function load; raises on a NACK, timeout or refusal."""
        cls = filter.PitchRollAidingControl
        command = cls(
            function=_t.FunctionSelector.LOAD,
        )
        self._call(command, timeout_ms, check_device)

    def default(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function default; raises on a NACK, timeout or refusal."""
        cls = filter.PitchRollAidingControl
        command = cls(
            function=_t.FunctionSelector.DEFAULT,
        )
        self._call(command, timeout_ms, check_device)


class InclinationSource(_Command):
    """Inclination source (set 0x0D, descriptor 0x4C)."""

    def write(
        self,
        source: _ty.Union[_t.MagneticParamSource, int],
        inclination: float,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function write; raises on a NACK, timeout or refusal."""
        cls = filter.InclinationSource
        command = cls(
            function=_t.FunctionSelector.WRITE,
            source=source,
            inclination=inclination,
        )
        self._call(command, timeout_ms, check_device)

    def read(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> filter.InclinationSourceResponse:
        """Function read: returns the reply field."""
        cls = filter.InclinationSource
        command = cls(
            function=_t.FunctionSelector.READ,
        )
        return _ty.cast("filter.InclinationSourceResponse", self._call(command, timeout_ms, check_device))

    def save(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function save; raises on a NACK, timeout or refusal."""
        cls = filter.InclinationSource
        command = cls(
            function=_t.FunctionSelector.SAVE,
        )
        self._call(command, timeout_ms, check_device)

    def load(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function load; raises on a NACK, timeout or refusal."""
        cls = filter.InclinationSource
        command = cls(
            function=_t.FunctionSelector.LOAD,
        )
        self._call(command, timeout_ms, check_device)

    def default(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function default; raises on a NACK, timeout or refusal."""
        cls = filter.InclinationSource
        command = cls(
            function=_t.FunctionSelector.DEFAULT,
        )
        self._call(command, timeout_ms, check_device)


class MagneticFieldMagnitudeSource(_Command):
    """Magnetic field magnitude source (set 0x0D, descriptor 0x4D)."""

    def write(
        self,
        source: _ty.Union[_t.MagneticParamSource, int],
        magnitude: float,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function write; raises on a NACK, timeout or refusal."""
        cls = filter.MagneticFieldMagnitudeSource
        command = cls(
            function=_t.FunctionSelector.WRITE,
            source=source,
            magnitude=magnitude,
        )
        self._call(command, timeout_ms, check_device)

    def read(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> filter.MagneticFieldMagnitudeSourceResponse:
        """Function read: returns the reply field."""
        cls = filter.MagneticFieldMagnitudeSource
        command = cls(
            function=_t.FunctionSelector.READ,
        )
        return _ty.cast("filter.MagneticFieldMagnitudeSourceResponse", self._call(command, timeout_ms, check_device))

    def save(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function save; raises on a NACK, timeout or refusal."""
        cls = filter.MagneticFieldMagnitudeSource
        command = cls(
            function=_t.FunctionSelector.SAVE,
        )
        self._call(command, timeout_ms, check_device)

    def load(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function load; raises on a NACK, timeout or refusal."""
        cls = filter.MagneticFieldMagnitudeSource
        command = cls(
            function=_t.FunctionSelector.LOAD,
        )
        self._call(command, timeout_ms, check_device)

    def default(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function default; raises on a NACK, timeout or refusal."""
        cls = filter.MagneticFieldMagnitudeSource
        command = cls(
            function=_t.FunctionSelector.DEFAULT,
        )
        self._call(command, timeout_ms, check_device)


class AidingMeasurementControl(_Command):
    """Aiding measurement control (set 0x0D, descriptor 0x50)."""

    def write(
        self,
        source: _ty.Union[_t.AidingMeasurementSource, int],
        enable: bool,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function write; raises on a NACK, timeout or refusal."""
        cls = filter.AidingMeasurementControl
        command = cls(
            function=_t.FunctionSelector.WRITE,
            source=source,
            enable=enable,
        )
        self._call(command, timeout_ms, check_device)

    def read(
        self,
        source: _ty.Union[_t.AidingMeasurementSource, int],
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> filter.AidingMeasurementControlResponse:
        """Function read: returns the reply field."""
        cls = filter.AidingMeasurementControl
        command = cls(
            function=_t.FunctionSelector.READ,
            source=source,
        )
        return _ty.cast("filter.AidingMeasurementControlResponse", self._call(command, timeout_ms, check_device))

    def save(
        self,
        source: _ty.Union[_t.AidingMeasurementSource, int],
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function save; raises on a NACK, timeout or refusal."""
        cls = filter.AidingMeasurementControl
        command = cls(
            function=_t.FunctionSelector.SAVE,
            source=source,
        )
        self._call(command, timeout_ms, check_device)

    def load(
        self,
        source: _ty.Union[_t.AidingMeasurementSource, int],
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function load; raises on a NACK, timeout or refusal."""
        cls = filter.AidingMeasurementControl
        command = cls(
            function=_t.FunctionSelector.LOAD,
            source=source,
        )
        self._call(command, timeout_ms, check_device)

    def default(
        self,
        source: _ty.Union[_t.AidingMeasurementSource, int],
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function default; raises on a NACK, timeout or refusal."""
        cls = filter.AidingMeasurementControl
        command = cls(
            function=_t.FunctionSelector.DEFAULT,
            source=source,
        )
        self._call(command, timeout_ms, check_device)


class InitializationConfiguration(_Command):
    """Navigation filter initialization (set 0x0D, descriptor 0x52)."""

    def write(
        self,
        wait_for_run_command: int,
        initial_cond_src: _ty.Union[_t.FilterInitialConditionSource, int],
        auto_heading_alignment_selector: _t.HeadingAlignmentMethods,
        initial_heading: float,
        initial_pitch: float,
        initial_roll: float,
        initial_position: _ty.List[float],
        initial_velocity: _ty.List[float],
        reference_frame_selector: _ty.Union[_t.FilterReferenceFrame, int],
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function write; raises on a NACK, timeout or refusal."""
        cls = filter.InitializationConfiguration
        command = cls(
            function=_t.FunctionSelector.WRITE,
            wait_for_run_command=wait_for_run_command,
            initial_cond_src=initial_cond_src,
            auto_heading_alignment_selector=auto_heading_alignment_selector,
            initial_heading=initial_heading,
            initial_pitch=initial_pitch,
            initial_roll=initial_roll,
            initial_position=initial_position,
            initial_velocity=initial_velocity,
            reference_frame_selector=reference_frame_selector,
        )
        self._call(command, timeout_ms, check_device)

    def read(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> filter.InitializationConfigurationResponse:
        """Function read: returns the reply field."""
        cls = filter.InitializationConfiguration
        command = cls(
            function=_t.FunctionSelector.READ,
        )
        return _ty.cast("filter.InitializationConfigurationResponse", self._call(command, timeout_ms, check_device))

    def save(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function save; raises on a NACK, timeout or refusal."""
        cls = filter.InitializationConfiguration
        command = cls(
            function=_t.FunctionSelector.SAVE,
        )
        self._call(command, timeout_ms, check_device)

    def load(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function load; raises on a NACK, timeout or refusal."""
        cls = filter.InitializationConfiguration
        command = cls(
            function=_t.FunctionSelector.LOAD,
        )
        self._call(command, timeout_ms, check_device)

    def default(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function default; raises on a NACK, timeout or refusal."""
        cls = filter.InitializationConfiguration
        command = cls(
            function=_t.FunctionSelector.DEFAULT,
        )
        self._call(command, timeout_ms, check_device)


class AdaptiveFilterControl(_Command):
    """Adaptive filter control (set 0x0D, descriptor 0x53)."""

    def write(
        self,
        level: _ty.Union[_t.AdaptiveFilterLevel, int],
        time_limit: int,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function write; raises on a NACK, timeout or refusal."""
        cls = filter.AdaptiveFilterControl
        command = cls(
            function=_t.FunctionSelector.WRITE,
            level=level,
            time_limit=time_limit,
        )
        self._call(command, timeout_ms, check_device)

    def read(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> filter.AdaptiveFilterControlResponse:
        """Function read: returns the reply field."""
        cls = filter.AdaptiveFilterControl
        command = cls(
            function=_t.FunctionSelector.READ,
        )
        return _ty.cast("filter.AdaptiveFilterControlResponse", self._call(command, timeout_ms, check_device))

    def save(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function save; raises on a NACK, timeout or refusal."""
        cls = filter.AdaptiveFilterControl
        command = cls(
            function=_t.FunctionSelector.SAVE,
        )
        self._call(command, timeout_ms, check_device)

    def load(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function load; raises on a NACK, timeout or refusal."""
        cls = filter.AdaptiveFilterControl
        command = cls(
            function=_t.FunctionSelector.LOAD,
        )
        self._call(command, timeout_ms, check_device)

    def default(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function default; raises on a NACK, timeout or refusal."""
        cls = filter.AdaptiveFilterControl
        command = cls(
            function=_t.FunctionSelector.DEFAULT,
        )
        self._call(command, timeout_ms, check_device)


class MultiAntennaOffset(_Command):
    """GNSS multi-antenna offset (set 0x0D, descriptor 0x54)."""

    def write(
        self,
        receiver_id: int,
        antenna_offset: _ty.List[float],
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function write; raises on a NACK, timeout or refusal."""
        cls = filter.MultiAntennaOffset
        command = cls(
            function=_t.FunctionSelector.WRITE,
            receiver_id=receiver_id,
            antenna_offset=antenna_offset,
        )
        self._call(command, timeout_ms, check_device)

    def read(
        self,
        receiver_id: int,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> filter.MultiAntennaOffsetResponse:
        """Function read: returns the reply field."""
        cls = filter.MultiAntennaOffset
        command = cls(
            function=_t.FunctionSelector.READ,
            receiver_id=receiver_id,
        )
        return _ty.cast("filter.MultiAntennaOffsetResponse", self._call(command, timeout_ms, check_device))

    def save(
        self,
        receiver_id: int,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function save; raises on a NACK, timeout or refusal."""
        cls = filter.MultiAntennaOffset
        command = cls(
            function=_t.FunctionSelector.SAVE,
            receiver_id=receiver_id,
        )
        self._call(command, timeout_ms, check_device)

    def load(
        self,
        receiver_id: int,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function load; raises on a NACK, timeout or refusal."""
        cls = filter.MultiAntennaOffset
        command = cls(
            function=_t.FunctionSelector.LOAD,
            receiver_id=receiver_id,
        )
        self._call(command, timeout_ms, check_device)

    def default(
        self,
        receiver_id: int,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function default; raises on a NACK, timeout or refusal."""
        cls = filter.MultiAntennaOffset
        command = cls(
            function=_t.FunctionSelector.DEFAULT,
            receiver_id=receiver_id,
        )
        self._call(command, timeout_ms, check_device)


class RelativePositionConfiguration(_Command):
    """Relative position configuration (set 0x0D, descriptor 0x55)."""

    def write(
        self,
        source: _ty.Union[_t.RelativePositionSource, int],
        reference_frame_selector: _ty.Union[_t.FilterReferenceFrame, int],
        reference_coordinates: _ty.List[float],
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function write; raises on a NACK, timeout or refusal."""
        cls = filter.RelativePositionConfiguration
        command = cls(
            function=_t.FunctionSelector.WRITE,
            source=source,
            reference_frame_selector=reference_frame_selector,
            reference_coordinates=reference_coordinates,
        )
        self._call(command, timeout_ms, check_device)

    def read(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> filter.RelativePositionConfigurationResponse:
        """Function read: returns the reply field."""
        cls = filter.RelativePositionConfiguration
        command = cls(
            function=_t.FunctionSelector.READ,
        )
        return _ty.cast("filter.RelativePositionConfigurationResponse", self._call(command, timeout_ms, check_device))

    def save(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function save; raises on a NACK, timeout or refusal."""
        cls = filter.RelativePositionConfiguration
        command = cls(
            function=_t.FunctionSelector.SAVE,
        )
        self._call(command, timeout_ms, check_device)

    def load(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function load; raises on a NACK, timeout or refusal."""
        cls = filter.RelativePositionConfiguration
        command = cls(
            function=_t.FunctionSelector.LOAD,
        )
        self._call(command, timeout_ms, check_device)

    def default(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function default; raises on a NACK, timeout or refusal."""
        cls = filter.RelativePositionConfiguration
        command = cls(
            function=_t.FunctionSelector.DEFAULT,
        )
        self._call(command, timeout_ms, check_device)


class ReferencePointLeverArm(_Command):
    """Reference point lever arm (set 0x0D, descriptor 0x56)."""

    def write(
        self,
        ref_point_sel: _ty.Union[_t.ReferencePointSelector, int],
        lever_arm_offset: _ty.List[float],
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function write; raises on a NACK, timeout or refusal."""
        cls = filter.ReferencePointLeverArm
        command = cls(
            function=_t.FunctionSelector.WRITE,
            ref_point_sel=ref_point_sel,
            lever_arm_offset=lever_arm_offset,
        )
        self._call(command, timeout_ms, check_device)

    def read(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> filter.ReferencePointLeverArmResponse:
        """Function read: returns the reply field."""
        cls = filter.ReferencePointLeverArm
        command = cls(
            function=_t.FunctionSelector.READ,
        )
        return _ty.cast("filter.ReferencePointLeverArmResponse", self._call(command, timeout_ms, check_device))

    def save(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function save; raises on a NACK, timeout or refusal."""
        cls = filter.ReferencePointLeverArm
        command = cls(
            function=_t.FunctionSelector.SAVE,
        )
        self._call(command, timeout_ms, check_device)

    def load(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function load; raises on a NACK, timeout or refusal."""
        cls = filter.ReferencePointLeverArm
        command = cls(
            function=_t.FunctionSelector.LOAD,
        )
        self._call(command, timeout_ms, check_device)

    def default(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function default; raises on a NACK, timeout or refusal."""
        cls = filter.ReferencePointLeverArm
        command = cls(
            function=_t.FunctionSelector.DEFAULT,
        )
        self._call(command, timeout_ms, check_device)


class SpeedLeverArm(_Command):
    """Measurement speed lever arm (set 0x0D, descriptor 0x61)."""

    def write(
        self,
        source: int,
        lever_arm_offset: _ty.List[float],
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function write; raises on a NACK, timeout or refusal."""
        cls = filter.SpeedLeverArm
        command = cls(
            function=_t.FunctionSelector.WRITE,
            source=source,
            lever_arm_offset=lever_arm_offset,
        )
        self._call(command, timeout_ms, check_device)

    def read(
        self,
        source: int,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> filter.SpeedLeverArmResponse:
        """Function read: returns the reply field."""
        cls = filter.SpeedLeverArm
        command = cls(
            function=_t.FunctionSelector.READ,
            source=source,
        )
        return _ty.cast("filter.SpeedLeverArmResponse", self._call(command, timeout_ms, check_device))

    def save(
        self,
        source: int,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function save; raises on a NACK, timeout or refusal."""
        cls = filter.SpeedLeverArm
        command = cls(
            function=_t.FunctionSelector.SAVE,
            source=source,
        )
        self._call(command, timeout_ms, check_device)

    def load(
        self,
        source: int,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function load; raises on a NACK, timeout or refusal."""
        cls = filter.SpeedLeverArm
        command = cls(
            function=_t.FunctionSelector.LOAD,
            source=source,
        )
        self._call(command, timeout_ms, check_device)

    def default(
        self,
        source: int,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function default; raises on a NACK, timeout or refusal."""
        cls = filter.SpeedLeverArm
        command = cls(
            function=_t.FunctionSelector.DEFAULT,
            source=source,
        )
        self._call(command, timeout_ms, check_device)


class WheeledVehicleConstraintControl(_Command):
    """Wheeled vehicle constraint control (set 0x0D, descriptor 0x63)."""

    def write(
        self,
        enable: int,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function write; raises on a NACK, timeout or refusal."""
        cls = filter.WheeledVehicleConstraintControl
        command = cls(
            function=_t.FunctionSelector.WRITE,
            enable=enable,
        )
        self._call(command, timeout_ms, check_device)

    def read(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> filter.WheeledVehicleConstraintControlResponse:
        """Function read: returns the reply field."""
        cls = filter.WheeledVehicleConstraintControl
        command = cls(
            function=_t.FunctionSelector.READ,
        )
        return _ty.cast("filter.WheeledVehicleConstraintControlResponse", self._call(command, timeout_ms, check_device))

    def save(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function save; raises on a NACK, timeout or refusal."""
        cls = filter.WheeledVehicleConstraintControl
        command = cls(
            function=_t.FunctionSelector.SAVE,
        )
        self._call(command, timeout_ms, check_device)

    def load(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function load; raises on a NACK, timeout or refusal."""
        cls = filter.WheeledVehicleConstraintControl
        command = cls(
            function=_t.FunctionSelector.LOAD,
        )
        self._call(command, timeout_ms, check_device)

    def default(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function default; raises on a NACK, timeout or refusal."""
        cls = filter.WheeledVehicleConstraintControl
        command = cls(
            function=_t.FunctionSelector.DEFAULT,
        )
        self._call(command, timeout_ms, check_device)


class GnssAntennaCalibrationControl(_Command):
    """GNSS antenna offset calibration control (set 0x0D, descriptor 0x64)."""

    def write(
        self,
        enable: int,
        max_offset: float,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function write; raises on a NACK, timeout or refusal."""
        cls = filter.GnssAntennaCalibrationControl
        command = cls(
            function=_t.FunctionSelector.WRITE,
            enable=enable,
            max_offset=max_offset,
        )
        self._call(command, timeout_ms, check_device)

    def read(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> filter.GnssAntennaCalibrationControlResponse:
        """Function read: returns the reply field."""
        cls = filter.GnssAntennaCalibrationControl
        command = cls(
            function=_t.FunctionSelector.READ,
        )
        return _ty.cast("filter.GnssAntennaCalibrationControlResponse", self._call(command, timeout_ms, check_device))

    def save(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function save; raises on a NACK, timeout or refusal."""
        cls = filter.GnssAntennaCalibrationControl
        command = cls(
            function=_t.FunctionSelector.SAVE,
        )
        self._call(command, timeout_ms, check_device)

    def load(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function load; raises on a NACK, timeout or refusal."""
        cls = filter.GnssAntennaCalibrationControl
        command = cls(
            function=_t.FunctionSelector.LOAD,
        )
        self._call(command, timeout_ms, check_device)

    def default(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function default; raises on a NACK, timeout or refusal."""
        cls = filter.GnssAntennaCalibrationControl
        command = cls(
            function=_t.FunctionSelector.DEFAULT,
        )
        self._call(command, timeout_ms, check_device)


class FilterCommands:
    """Filter Command Set commands (set 0x0D)."""

    def __init__(self, device: _s.Device) -> None:
        self.reset_filter = ResetFilter(device)
        self.set_initial_attitude = SetInitialAttitude(device)
        self.set_initial_heading = SetInitialHeading(device)
        self.run_filter = RunFilter(device)
        self.vehicle_dynamics_mode = VehicleDynamicsMode(device)
        self.sensor_to_vehicle_transform = SensorToVehicleTransform(device)
        self.sensor_to_vehicle_offset = SensorToVehicleOffset(device)
        self.antenna_offset = AntennaOffset(device)
        self.estimation_control = EstimationControl(device)
        self.gnss_source_control = GnssSourceControl(device)
        self.external_gnss_update = ExternalGnssUpdate(device)
        self.external_heading_update = ExternalHeadingUpdate(device)
        self.heading_update_control = HeadingUpdateControl(device)
        self.auto_init_control = AutoInitControl(device)
        self.accel_noise = AccelNoise(device)
        self.gyro_noise = GyroNoise(device)
        self.accel_bias_model = AccelBiasModel(device)
        self.gyro_bias_model = GyroBiasModel(device)
        self.zupt_control = ZuptControl(device)
        self.external_heading_update_with_time = ExternalHeadingUpdateWithTime(device)
        self.zero_angular_rate_update_control = ZeroAngularRateUpdateControl(device)
        self.tare_orientation = TareOrientation(device)
        self.commanded_zupt = CommandedZupt(device)
        self.commanded_zero_angular_rate_update = CommandedZeroAngularRateUpdate(device)
        self.mag_capture_auto_calibration = MagCaptureAutoCalibration(device)
        self.gravity_noise_std_dev = GravityNoiseStdDev(device)
        self.pressure_altitude_noise_std_dev = PressureAltitudeNoiseStdDev(device)
        self.hard_iron_offset_noise = HardIronOffsetNoise(device)
        self.soft_iron_matrix_noise = SoftIronMatrixNoise(device)
        self.mag_noise_std_dev = MagNoiseStdDev(device)
        self.declination_source = DeclinationSource(device)
        self.gravity_magnitude_adaptive_measurement = GravityMagnitudeAdaptiveMeasurement(device)
        self.mag_magnitude_adaptive_measurement = MagMagnitudeAdaptiveMeasurement(device)
        self.mag_dip_angle_adaptive_measurement = MagDipAngleAdaptiveMeasurement(device)
        self.altitude_aiding_control = AltitudeAidingControl(device)
        self.pitch_roll_aiding_control = PitchRollAidingControl(device)
        self.inclination_source = InclinationSource(device)
        self.magnetic_field_magnitude_source = MagneticFieldMagnitudeSource(device)
        self.aiding_measurement_control = AidingMeasurementControl(device)
        self.initialization_configuration = InitializationConfiguration(device)
        self.adaptive_filter_control = AdaptiveFilterControl(device)
        self.multi_antenna_offset = MultiAntennaOffset(device)
        self.relative_position_configuration = RelativePositionConfiguration(device)
        self.reference_point_lever_arm = ReferencePointLeverArm(device)
        self.speed_lever_arm = SpeedLeverArm(device)
        self.wheeled_vehicle_constraint_control = WheeledVehicleConstraintControl(device)
        self.gnss_antenna_calibration_control = GnssAntennaCalibrationControl(device)


class ReceiverInfo(_Command):
    """Receiver info (set 0x0E, descriptor 0x01)."""

    def __call__(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> gnss.ReceiverInfoResponse:
        """Send the command: returns the reply field."""
        cls = gnss.ReceiverInfo
        command = cls()
        return _ty.cast("gnss.ReceiverInfoResponse", self._call(command, timeout_ms, check_device))


class SignalConfiguration(_Command):
    """Signal configuration (set 0x0E, descriptor 0x02)."""

    def write(
        self,
        gps_enable: _t.GnssGpsSignals,
        glonass_enable: _t.GnssGlonassSignals,
        galileo_enable: _t.GnssGalileoSignals,
        beidou_enable: _t.GnssBeidouSignals,
        reserved: _ty.List[int],
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function write; raises on a NACK, timeout or refusal."""
        cls = gnss.SignalConfiguration
        command = cls(
            function=_t.FunctionSelector.WRITE,
            gps_enable=gps_enable,
            glonass_enable=glonass_enable,
            galileo_enable=galileo_enable,
            beidou_enable=beidou_enable,
            reserved=reserved,
        )
        self._call(command, timeout_ms, check_device)

    def read(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> gnss.SignalConfigurationResponse:
        """Function read: returns the reply field."""
        cls = gnss.SignalConfiguration
        command = cls(
            function=_t.FunctionSelector.READ,
        )
        return _ty.cast("gnss.SignalConfigurationResponse", self._call(command, timeout_ms, check_device))

    def save(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function save; raises on a NACK, timeout or refusal."""
        cls = gnss.SignalConfiguration
        command = cls(
            function=_t.FunctionSelector.SAVE,
        )
        self._call(command, timeout_ms, check_device)

    def load(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function load; raises on a NACK, timeout or refusal."""
        cls = gnss.SignalConfiguration
        command = cls(
            function=_t.FunctionSelector.LOAD,
        )
        self._call(command, timeout_ms, check_device)

    def default(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function default; raises on a NACK, timeout or refusal."""
        cls = gnss.SignalConfiguration
        command = cls(
            function=_t.FunctionSelector.DEFAULT,
        )
        self._call(command, timeout_ms, check_device)


class SpartnConfiguration(_Command):
    """SPARTN configuration (set 0x0E, descriptor 0x20)."""

    def write(
        self,
        enable: int,
        type: _ty.Union[_t.SpartnConnectionType, int],
        current_key_tow: int,
        current_key_week: int,
        current_key: bytes,
        next_key_tow: int,
        next_key_week: int,
        next_key: bytes,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function write; raises on a NACK, timeout or refusal."""
        cls = gnss.SpartnConfiguration
        command = cls(
            function=_t.FunctionSelector.WRITE,
            enable=enable,
            type=type,
            current_key_tow=current_key_tow,
            current_key_week=current_key_week,
            current_key=current_key,
            next_key_tow=next_key_tow,
            next_key_week=next_key_week,
            next_key=next_key,
        )
        self._call(command, timeout_ms, check_device)

    def read(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> gnss.SpartnConfigurationResponse:
        """Function read: returns the reply field."""
        cls = gnss.SpartnConfiguration
        command = cls(
            function=_t.FunctionSelector.READ,
        )
        return _ty.cast("gnss.SpartnConfigurationResponse", self._call(command, timeout_ms, check_device))

    def save(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function save; raises on a NACK, timeout or refusal."""
        cls = gnss.SpartnConfiguration
        command = cls(
            function=_t.FunctionSelector.SAVE,
        )
        self._call(command, timeout_ms, check_device)

    def load(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function load; raises on a NACK, timeout or refusal."""
        cls = gnss.SpartnConfiguration
        command = cls(
            function=_t.FunctionSelector.LOAD,
        )
        self._call(command, timeout_ms, check_device)

    def default(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function default; raises on a NACK, timeout or refusal."""
        cls = gnss.SpartnConfiguration
        command = cls(
            function=_t.FunctionSelector.DEFAULT,
        )
        self._call(command, timeout_ms, check_device)


class GnssCommands:
    """GNSS Command Set commands (set 0x0E)."""

    def __init__(self, device: _s.Device) -> None:
        self.receiver_info = ReceiverInfo(device)
        self.signal_configuration = SignalConfiguration(device)
        self.spartn_configuration = SpartnConfiguration(device)


class FrameConfig(_Command):
    """Frame configuration (set 0x13, descriptor 0x01)."""

    def write(
        self,
        frame_id: int,
        format: _ty.Union[_t.AidingFrameFormat, int],
        tracking_enabled: bool,
        translation: _ty.List[float],
        rotation: _ty.Union[_t.AidingFrameEuler, _t.AidingFrameQuaternion],
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function write; raises on a NACK, timeout or refusal."""
        cls = aiding.FrameConfig
        command = cls(
            function=_t.FunctionSelector.WRITE,
            frame_id=frame_id,
            format=format,
            tracking_enabled=tracking_enabled,
            translation=translation,
            rotation=rotation,
        )
        self._call(command, timeout_ms, check_device)

    def read(
        self,
        frame_id: int,
        format: _ty.Union[_t.AidingFrameFormat, int],
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> aiding.FrameConfigResponse:
        """Function read: returns the reply field."""
        cls = aiding.FrameConfig
        command = cls(
            function=_t.FunctionSelector.READ,
            frame_id=frame_id,
            format=format,
        )
        return _ty.cast("aiding.FrameConfigResponse", self._call(command, timeout_ms, check_device))

    def save(
        self,
        frame_id: int,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function save; raises on a NACK, timeout or refusal."""
        cls = aiding.FrameConfig
        command = cls(
            function=_t.FunctionSelector.SAVE,
            frame_id=frame_id,
        )
        self._call(command, timeout_ms, check_device)

    def load(
        self,
        frame_id: int,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function load; raises on a NACK, timeout or refusal."""
        cls = aiding.FrameConfig
        command = cls(
            function=_t.FunctionSelector.LOAD,
            frame_id=frame_id,
        )
        self._call(command, timeout_ms, check_device)

    def default(
        self,
        frame_id: int,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function default; raises on a NACK, timeout or refusal."""
        cls = aiding.FrameConfig
        command = cls(
            function=_t.FunctionSelector.DEFAULT,
            frame_id=frame_id,
        )
        self._call(command, timeout_ms, check_device)


class EchoControl(_Command):
    """Echo control (set 0x13, descriptor 0x1F)."""

    def write(
        self,
        mode: _ty.Union[_t.AidingEchoMode, int],
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function write; raises on a NACK, timeout or refusal."""
        cls = aiding.EchoControl
        command = cls(
            function=_t.FunctionSelector.WRITE,
            mode=mode,
        )
        self._call(command, timeout_ms, check_device)

    def read(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> aiding.EchoControlResponse:
        """Function read: returns the reply field."""
        cls = aiding.EchoControl
        command = cls(
            function=_t.FunctionSelector.READ,
        )
        return _ty.cast("aiding.EchoControlResponse", self._call(command, timeout_ms, check_device))

    def save(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function save; raises on a NACK, timeout or refusal."""
        cls = aiding.EchoControl
        command = cls(
            function=_t.FunctionSelector.SAVE,
        )
        self._call(command, timeout_ms, check_device)

    def load(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function load; raises on a NACK, timeout or refusal."""
        cls = aiding.EchoControl
        command = cls(
            function=_t.FunctionSelector.LOAD,
        )
        self._call(command, timeout_ms, check_device)

    def default(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function default; raises on a NACK, timeout or refusal."""
        cls = aiding.EchoControl
        command = cls(
            function=_t.FunctionSelector.DEFAULT,
        )
        self._call(command, timeout_ms, check_device)


class EcefPosition(_Command):
    """ECEF position (set 0x13, descriptor 0x21)."""

    def __call__(
        self,
        time: _t.AidingTime,
        frame_id: int,
        position: _ty.List[float],
        uncertainty: _ty.List[float],
        valid_flags: _t.AidingVectorValidFlags,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Send the command; raises on a NACK, timeout or refusal."""
        cls = aiding.EcefPosition
        command = cls(
            time=time,
            frame_id=frame_id,
            position=position,
            uncertainty=uncertainty,
            valid_flags=valid_flags,
        )
        self._call(command, timeout_ms, check_device)


class LlhPosition(_Command):
    """LLH position (set 0x13, descriptor 0x22)."""

    def __call__(
        self,
        time: _t.AidingTime,
        frame_id: int,
        latitude: float,
        longitude: float,
        height: float,
        uncertainty: _ty.List[float],
        valid_flags: _t.AidingLlhValidFlags,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Send the command; raises on a NACK, timeout or refusal."""
        cls = aiding.LlhPosition
        command = cls(
            time=time,
            frame_id=frame_id,
            latitude=latitude,
            longitude=longitude,
            height=height,
            uncertainty=uncertainty,
            valid_flags=valid_flags,
        )
        self._call(command, timeout_ms, check_device)


class HeightAboveEllipsoid(_Command):
    """Height above ellipsoid (set 0x13, descriptor 0x23)."""

    def __call__(
        self,
        time: _t.AidingTime,
        frame_id: int,
        height: float,
        uncertainty: float,
        valid_flags: int,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Send the command; raises on a NACK, timeout or refusal."""
        cls = aiding.HeightAboveEllipsoid
        command = cls(
            time=time,
            frame_id=frame_id,
            height=height,
            uncertainty=uncertainty,
            valid_flags=valid_flags,
        )
        self._call(command, timeout_ms, check_device)


class EcefVelocity(_Command):
    """ECEF velocity (set 0x13, descriptor 0x28)."""

    def __call__(
        self,
        time: _t.AidingTime,
        frame_id: int,
        velocity: _ty.List[float],
        uncertainty: _ty.List[float],
        valid_flags: _t.AidingVectorValidFlags,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Send the command; raises on a NACK, timeout or refusal."""
        cls = aiding.EcefVelocity
        command = cls(
            time=time,
            frame_id=frame_id,
            velocity=velocity,
            uncertainty=uncertainty,
            valid_flags=valid_flags,
        )
        self._call(command, timeout_ms, check_device)


class NedVelocity(_Command):
    """NED velocity (set 0x13, descriptor 0x29)."""

    def __call__(
        self,
        time: _t.AidingTime,
        frame_id: int,
        velocity: _ty.List[float],
        uncertainty: _ty.List[float],
        valid_flags: _t.AidingVectorValidFlags,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Send the command; raises on a NACK, timeout or refusal."""
        cls = aiding.NedVelocity
        command = cls(
            time=time,
            frame_id=frame_id,
            velocity=velocity,
            uncertainty=uncertainty,
            valid_flags=valid_flags,
        )
        self._call(command, timeout_ms, check_device)


class BodyFrameVelocity(_Command):
    """Body frame velocity (set 0x13, descriptor 0x2A)."""

    def __call__(
        self,
        time: _t.AidingTime,
        frame_id: int,
        velocity: _ty.List[float],
        uncertainty: _ty.List[float],
        valid_flags: _t.AidingVectorValidFlags,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Send the command; raises on a NACK, timeout or refusal."""
        cls = aiding.BodyFrameVelocity
        command = cls(
            time=time,
            frame_id=frame_id,
            velocity=velocity,
            uncertainty=uncertainty,
            valid_flags=valid_flags,
        )
        self._call(command, timeout_ms, check_device)


class TrueHeading(_Command):
    """True heading (set 0x13, descriptor 0x31)."""

    def __call__(
        self,
        time: _t.AidingTime,
        frame_id: int,
        heading: float,
        uncertainty: float,
        valid_flags: int,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Send the command; raises on a NACK, timeout or refusal."""
        cls = aiding.TrueHeading
        command = cls(
            time=time,
            frame_id=frame_id,
            heading=heading,
            uncertainty=uncertainty,
            valid_flags=valid_flags,
        )
        self._call(command, timeout_ms, check_device)


class MagneticField(_Command):
    """Magnetic field (set 0x13, descriptor 0x32)."""

    def __call__(
        self,
        time: _t.AidingTime,
        frame_id: int,
        magnetic_field: _ty.List[float],
        uncertainty: _ty.List[float],
        valid_flags: _t.AidingVectorValidFlags,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Send the command; raises on a NACK, timeout or refusal."""
        cls = aiding.MagneticField
        command = cls(
            time=time,
            frame_id=frame_id,
            magnetic_field=magnetic_field,
            uncertainty=uncertainty,
            valid_flags=valid_flags,
        )
        self._call(command, timeout_ms, check_device)


class Pressure(_Command):
    """Pressure (set 0x13, descriptor 0x33)."""

    def __call__(
        self,
        time: _t.AidingTime,
        frame_id: int,
        pressure: float,
        uncertainty: float,
        valid_flags: int,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Send the command; raises on a NACK, timeout or refusal."""
        cls = aiding.Pressure
        command = cls(
            time=time,
            frame_id=frame_id,
            pressure=pressure,
            uncertainty=uncertainty,
            valid_flags=valid_flags,
        )
        self._call(command, timeout_ms, check_device)


class AidingCommands:
    """Aiding Command Set commands (set 0x13)."""

    def __init__(self, device: _s.Device) -> None:
        self.frame_config = FrameConfig(device)
        self.echo_control = EchoControl(device)
        self.ecef_position = EcefPosition(device)
        self.llh_position = LlhPosition(device)
        self.height_above_ellipsoid = HeightAboveEllipsoid(device)
        self.ecef_velocity = EcefVelocity(device)
        self.ned_velocity = NedVelocity(device)
        self.body_frame_velocity = BodyFrameVelocity(device)
        self.true_heading = TrueHeading(device)
        self.magnetic_field = MagneticField(device)
        self.pressure = Pressure(device)


class CommunicationMode(_Command):
    """Communication mode (set 0x7F, descriptor 0x10)."""

    def write(
        self,
        mode: _ty.Union[_t.SystemCommMode, int],
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function write; raises on a NACK, timeout or refusal."""
        cls = system.CommunicationMode
        command = cls(
            function=_t.FunctionSelector.WRITE,
            mode=mode,
        )
        self._call(command, timeout_ms, check_device)

    def read(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> system.CommunicationModeResponse:
        """Function read: returns the reply field."""
        cls = system.CommunicationMode
        command = cls(
            function=_t.FunctionSelector.READ,
        )
        return _ty.cast("system.CommunicationModeResponse", self._call(command, timeout_ms, check_device))

    def save(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function save; raises on a NACK, timeout or refusal."""
        cls = system.CommunicationMode
        command = cls(
            function=_t.FunctionSelector.SAVE,
        )
        self._call(command, timeout_ms, check_device)

    def load(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function load; raises on a NACK, timeout or refusal."""
        cls = system.CommunicationMode
        command = cls(
            function=_t.FunctionSelector.LOAD,
        )
        self._call(command, timeout_ms, check_device)

    def default(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function default; raises on a NACK, timeout or refusal."""
        cls = system.CommunicationMode
        command = cls(
            function=_t.FunctionSelector.DEFAULT,
        )
        self._call(command, timeout_ms, check_device)


class SystemCommands:
    """System Command Set commands (set 0x7F)."""

    def __init__(self, device: _s.Device) -> None:
        self.communication_mode = CommunicationMode(device)


class DeviceCommands:
    """The command sets of a Device, as type checkers see them (session.Device derives from this
    class when type checking; `bind` sets the attributes)."""

    base: BaseCommands

    threedm: ThreedmCommands

    filter: FilterCommands

    gnss: GnssCommands

    aiding: AidingCommands

    system: SystemCommands


def bind(device: _s.Device) -> None:
    """Give a Device its command sets (called by Device itself)."""
    device.base = BaseCommands(device)
    device.threedm = ThreedmCommands(device)
    device.filter = FilterCommands(device)
    device.gnss = GnssCommands(device)
    device.aiding = AidingCommands(device)
    device.system = SystemCommands(device)
