"""The typed command API of the Memsense MS-CIP, generated per command and function.

A `Device` (session/) has one attribute per command set and, in it, one object per command
with one method per function it supports (or a plain call):

    device = connect("tcp:192.168.1.10:5000", device="ms_imu3020")
    device.base.ping()

Each method builds the command, sends it, waits for its result and returns the typed reply field
(or None when the command has none); it raises CommandRefused when the selected device does not
support the command or function (nothing is sent; `check_device=False` sends it anyway), Nack,
CommandTimeout or InvalidReply. `timeout_ms` replaces the device's reply timeout for the call (the
spec's allowance for long commands is added to it).
"""

from __future__ import annotations

import typing as _ty

from . import base, imu_config
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
    """Ping (set 0x01, descriptor 0x02)."""

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


class GetDeviceMessages(_Command):
    """Get device messages (set 0x01, descriptor 0x03)."""

    def __call__(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> base.DeviceMessages:
        """Send the command: returns the reply field."""
        cls = base.GetDeviceMessages
        command = cls()
        return _ty.cast("base.DeviceMessages", self._call(command, timeout_ms, check_device))


class DeviceReset(_Command):
    """Device reset (set 0x01, descriptor 0x04)."""

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


class GetDeviceModel(_Command):
    """Get device model (set 0x01, descriptor 0x05)."""

    def __call__(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> base.DeviceModel:
        """Send the command: returns the reply field."""
        cls = base.GetDeviceModel
        command = cls()
        return _ty.cast("base.DeviceModel", self._call(command, timeout_ms, check_device))


class GetDeviceSn(_Command):
    """Get device serial number (set 0x01, descriptor 0x06)."""

    def __call__(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> base.DeviceSn:
        """Send the command: returns the reply field."""
        cls = base.GetDeviceSn
        command = cls()
        return _ty.cast("base.DeviceSn", self._call(command, timeout_ms, check_device))


class GetDeviceFw(_Command):
    """Get device firmware (set 0x01, descriptor 0x07)."""

    def __call__(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> base.DeviceFw:
        """Send the command: returns the reply field."""
        cls = base.GetDeviceFw
        command = cls()
        return _ty.cast("base.DeviceFw", self._call(command, timeout_ms, check_device))


class GetDeviceCal(_Command):
    """Get device calibration date (set 0x01, descriptor 0x08)."""

    def __call__(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> base.DeviceCal:
        """Send the command: returns the reply field."""
        cls = base.GetDeviceCal
        command = cls()
        return _ty.cast("base.DeviceCal", self._call(command, timeout_ms, check_device))


class CorrelateGpsTime(_Command):
    """Correlate GPS time (set 0x01, descriptor 0x09)."""

    def __call__(
        self,
        week: int,
        seconds: int,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Send the command; raises on a NACK, timeout or refusal."""
        cls = base.CorrelateGpsTime
        command = cls(
            week=week,
            seconds=seconds,
        )
        self._call(command, timeout_ms, check_device)


class BaseCommands:
    """Base Messages commands (set 0x01)."""

    def __init__(self, device: _s.Device) -> None:
        self.ping = Ping(device)
        self.get_device_messages = GetDeviceMessages(device)
        self.device_reset = DeviceReset(device)
        self.get_device_model = GetDeviceModel(device)
        self.get_device_sn = GetDeviceSn(device)
        self.get_device_fw = GetDeviceFw(device)
        self.get_device_cal = GetDeviceCal(device)
        self.correlate_gps_time = CorrelateGpsTime(device)


class UartBaudRate(_Command):
    """UART baud rate configure (set 0x02, descriptor 0x01)."""

    def write(
        self,
        baud_rate: _ty.Union[_t.BaudRate, int],
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function write; raises on a NACK, timeout or refusal."""
        cls = imu_config.UartBaudRate
        command = cls(
            function=_t.FunctionCode.WRITE,
            baud_rate=baud_rate,
        )
        self._call(command, timeout_ms, check_device)

    def read(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> imu_config.UartBaudRateResponse:
        """Function read: returns the reply field."""
        cls = imu_config.UartBaudRate
        command = cls(
            function=_t.FunctionCode.READ,
        )
        return _ty.cast("imu_config.UartBaudRateResponse", self._call(command, timeout_ms, check_device))

    def save(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function save; raises on a NACK, timeout or refusal."""
        cls = imu_config.UartBaudRate
        command = cls(
            function=_t.FunctionCode.SAVE,
        )
        self._call(command, timeout_ms, check_device)

    def load(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function load; raises on a NACK, timeout or refusal."""
        cls = imu_config.UartBaudRate
        command = cls(
            function=_t.FunctionCode.LOAD,
        )
        self._call(command, timeout_ms, check_device)

    def default(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function default; raises on a NACK, timeout or refusal."""
        cls = imu_config.UartBaudRate
        command = cls(
            function=_t.FunctionCode.DEFAULT,
        )
        self._call(command, timeout_ms, check_device)


class Filter(_Command):
    """Configure filter (set 0x02, descriptor 0x03)."""

    def write(
        self,
        bandwidth: _ty.Union[_t.FilterBandwidth, int],
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function write; raises on a NACK, timeout or refusal."""
        cls = imu_config.Filter
        command = cls(
            function=_t.FunctionCode.WRITE,
            bandwidth=bandwidth,
        )
        self._call(command, timeout_ms, check_device)

    def read(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> imu_config.FilterResponse:
        """Function read: returns the reply field."""
        cls = imu_config.Filter
        command = cls(
            function=_t.FunctionCode.READ,
        )
        return _ty.cast("imu_config.FilterResponse", self._call(command, timeout_ms, check_device))

    def save(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function save; raises on a NACK, timeout or refusal."""
        cls = imu_config.Filter
        command = cls(
            function=_t.FunctionCode.SAVE,
        )
        self._call(command, timeout_ms, check_device)

    def load(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function load; raises on a NACK, timeout or refusal."""
        cls = imu_config.Filter
        command = cls(
            function=_t.FunctionCode.LOAD,
        )
        self._call(command, timeout_ms, check_device)

    def default(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function default; raises on a NACK, timeout or refusal."""
        cls = imu_config.Filter
        command = cls(
            function=_t.FunctionCode.DEFAULT,
        )
        self._call(command, timeout_ms, check_device)


class SampleRate(_Command):
    """IMU sample rate configure (set 0x02, descriptor 0x04)."""

    def write(
        self,
        decimation: int,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function write; raises on a NACK, timeout or refusal."""
        cls = imu_config.SampleRate
        command = cls(
            function=_t.FunctionCode.WRITE,
            decimation=decimation,
        )
        self._call(command, timeout_ms, check_device)

    def read(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> imu_config.SampleRateResponse:
        """Function read: returns the reply field."""
        cls = imu_config.SampleRate
        command = cls(
            function=_t.FunctionCode.READ,
        )
        return _ty.cast("imu_config.SampleRateResponse", self._call(command, timeout_ms, check_device))

    def save(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function save; raises on a NACK, timeout or refusal."""
        cls = imu_config.SampleRate
        command = cls(
            function=_t.FunctionCode.SAVE,
        )
        self._call(command, timeout_ms, check_device)

    def load(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function load; raises on a NACK, timeout or refusal."""
        cls = imu_config.SampleRate
        command = cls(
            function=_t.FunctionCode.LOAD,
        )
        self._call(command, timeout_ms, check_device)

    def default(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function default; raises on a NACK, timeout or refusal."""
        cls = imu_config.SampleRate
        command = cls(
            function=_t.FunctionCode.DEFAULT,
        )
        self._call(command, timeout_ms, check_device)


class SelectSensors(_Command):
    """Select sensors (Rev A) (set 0x02, descriptor 0x05)."""

    def write(
        self,
        reserved: int,
        sensors: _ty.List[_ty.Union[_t.SensorCode, int]],
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function write; raises on a NACK, timeout or refusal."""
        cls = imu_config.SelectSensors
        command = cls(
            function=_t.FunctionCode.WRITE,
            reserved=reserved,
            sensors=sensors,
        )
        self._call(command, timeout_ms, check_device)

    def read(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> imu_config.SelectSensorsResponse:
        """Function read: returns the reply field."""
        cls = imu_config.SelectSensors
        command = cls(
            function=_t.FunctionCode.READ,
        )
        return _ty.cast("imu_config.SelectSensorsResponse", self._call(command, timeout_ms, check_device))

    def save(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function save; raises on a NACK, timeout or refusal."""
        cls = imu_config.SelectSensors
        command = cls(
            function=_t.FunctionCode.SAVE,
        )
        self._call(command, timeout_ms, check_device)

    def load(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function load; raises on a NACK, timeout or refusal."""
        cls = imu_config.SelectSensors
        command = cls(
            function=_t.FunctionCode.LOAD,
        )
        self._call(command, timeout_ms, check_device)

    def default(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function default; raises on a NACK, timeout or refusal."""
        cls = imu_config.SelectSensors
        command = cls(
            function=_t.FunctionCode.DEFAULT,
        )
        self._call(command, timeout_ms, check_device)


class GetInternalSampleRate(_Command):
    """Get IMU internal sample rate (set 0x02, descriptor 0x06)."""

    def __call__(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> imu_config.InternalSampleRate:
        """Send the command: returns the reply field."""
        cls = imu_config.GetInternalSampleRate
        command = cls()
        return _ty.cast("imu_config.InternalSampleRate", self._call(command, timeout_ms, check_device))


class AccelRange(_Command):
    """Config accel range (set 0x02, descriptor 0x07)."""

    def write(
        self,
        range: _ty.Union[_t.AccelRange, int],
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function write; raises on a NACK, timeout or refusal."""
        cls = imu_config.AccelRange
        command = cls(
            function=_t.FunctionCode.WRITE,
            range=range,
        )
        self._call(command, timeout_ms, check_device)

    def read(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> imu_config.AccelRangeResponse:
        """Function read: returns the reply field."""
        cls = imu_config.AccelRange
        command = cls(
            function=_t.FunctionCode.READ,
        )
        return _ty.cast("imu_config.AccelRangeResponse", self._call(command, timeout_ms, check_device))

    def save(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function save; raises on a NACK, timeout or refusal."""
        cls = imu_config.AccelRange
        command = cls(
            function=_t.FunctionCode.SAVE,
        )
        self._call(command, timeout_ms, check_device)

    def load(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function load; raises on a NACK, timeout or refusal."""
        cls = imu_config.AccelRange
        command = cls(
            function=_t.FunctionCode.LOAD,
        )
        self._call(command, timeout_ms, check_device)

    def default(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function default; raises on a NACK, timeout or refusal."""
        cls = imu_config.AccelRange
        command = cls(
            function=_t.FunctionCode.DEFAULT,
        )
        self._call(command, timeout_ms, check_device)


class GyroRange(_Command):
    """Configure gyro range (set 0x02, descriptor 0x08)."""

    def write(
        self,
        range: _ty.Union[_t.GyroRange, int],
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function write; raises on a NACK, timeout or refusal."""
        cls = imu_config.GyroRange
        command = cls(
            function=_t.FunctionCode.WRITE,
            range=range,
        )
        self._call(command, timeout_ms, check_device)

    def read(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> imu_config.GyroRangeResponse:
        """Function read: returns the reply field."""
        cls = imu_config.GyroRange
        command = cls(
            function=_t.FunctionCode.READ,
        )
        return _ty.cast("imu_config.GyroRangeResponse", self._call(command, timeout_ms, check_device))

    def save(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function save; raises on a NACK, timeout or refusal."""
        cls = imu_config.GyroRange
        command = cls(
            function=_t.FunctionCode.SAVE,
        )
        self._call(command, timeout_ms, check_device)

    def load(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function load; raises on a NACK, timeout or refusal."""
        cls = imu_config.GyroRange
        command = cls(
            function=_t.FunctionCode.LOAD,
        )
        self._call(command, timeout_ms, check_device)

    def default(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function default; raises on a NACK, timeout or refusal."""
        cls = imu_config.GyroRange
        command = cls(
            function=_t.FunctionCode.DEFAULT,
        )
        self._call(command, timeout_ms, check_device)


class ConfigAll(_Command):
    """Configure all (set 0x02, descriptor 0x09)."""

    def save(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function save; raises on a NACK, timeout or refusal."""
        cls = imu_config.ConfigAll
        command = cls(
            function=_t.FunctionCode.SAVE,
        )
        self._call(command, timeout_ms, check_device)

    def load(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function load; raises on a NACK, timeout or refusal."""
        cls = imu_config.ConfigAll
        command = cls(
            function=_t.FunctionCode.LOAD,
        )
        self._call(command, timeout_ms, check_device)

    def default(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function default; raises on a NACK, timeout or refusal."""
        cls = imu_config.ConfigAll
        command = cls(
            function=_t.FunctionCode.DEFAULT,
        )
        self._call(command, timeout_ms, check_device)


class DataOnOff(_Command):
    """Data on/off (set 0x02, descriptor 0x0A)."""

    def write(
        self,
        control: _ty.Union[_t.OnOff, int],
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function write; raises on a NACK, timeout or refusal."""
        cls = imu_config.DataOnOff
        command = cls(
            function=_t.FunctionCode.WRITE,
            control=control,
        )
        self._call(command, timeout_ms, check_device)

    def read(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> imu_config.DataOnOffResponse:
        """Function read: returns the reply field."""
        cls = imu_config.DataOnOff
        command = cls(
            function=_t.FunctionCode.READ,
        )
        return _ty.cast("imu_config.DataOnOffResponse", self._call(command, timeout_ms, check_device))

    def save(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function save; raises on a NACK, timeout or refusal."""
        cls = imu_config.DataOnOff
        command = cls(
            function=_t.FunctionCode.SAVE,
        )
        self._call(command, timeout_ms, check_device)

    def load(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function load; raises on a NACK, timeout or refusal."""
        cls = imu_config.DataOnOff
        command = cls(
            function=_t.FunctionCode.LOAD,
        )
        self._call(command, timeout_ms, check_device)

    def default(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function default; raises on a NACK, timeout or refusal."""
        cls = imu_config.DataOnOff
        command = cls(
            function=_t.FunctionCode.DEFAULT,
        )
        self._call(command, timeout_ms, check_device)


class XtrigOnOff(_Command):
    """XTRIG on/off (set 0x02, descriptor 0x0B)."""

    def write(
        self,
        control: _ty.Union[_t.OnOff, int],
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function write; raises on a NACK, timeout or refusal."""
        cls = imu_config.XtrigOnOff
        command = cls(
            function=_t.FunctionCode.WRITE,
            control=control,
        )
        self._call(command, timeout_ms, check_device)

    def read(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> imu_config.XtrigOnOffResponse:
        """Function read: returns the reply field."""
        cls = imu_config.XtrigOnOff
        command = cls(
            function=_t.FunctionCode.READ,
        )
        return _ty.cast("imu_config.XtrigOnOffResponse", self._call(command, timeout_ms, check_device))

    def save(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function save; raises on a NACK, timeout or refusal."""
        cls = imu_config.XtrigOnOff
        command = cls(
            function=_t.FunctionCode.SAVE,
        )
        self._call(command, timeout_ms, check_device)

    def load(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function load; raises on a NACK, timeout or refusal."""
        cls = imu_config.XtrigOnOff
        command = cls(
            function=_t.FunctionCode.LOAD,
        )
        self._call(command, timeout_ms, check_device)

    def default(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function default; raises on a NACK, timeout or refusal."""
        cls = imu_config.XtrigOnOff
        command = cls(
            function=_t.FunctionCode.DEFAULT,
        )
        self._call(command, timeout_ms, check_device)


class SelectSensorsRevB(_Command):
    """Select sensors (Rev B) (set 0x02, descriptor 0x0C)."""

    def write(
        self,
        sensors: _ty.List[_ty.Union[_t.SensorCode, int]],
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function write; raises on a NACK, timeout or refusal."""
        cls = imu_config.SelectSensorsRevB
        command = cls(
            function=_t.FunctionCode.WRITE,
            sensors=sensors,
        )
        self._call(command, timeout_ms, check_device)

    def read(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> imu_config.SelectSensorsRevBResponse:
        """Function read: returns the reply field."""
        cls = imu_config.SelectSensorsRevB
        command = cls(
            function=_t.FunctionCode.READ,
        )
        return _ty.cast("imu_config.SelectSensorsRevBResponse", self._call(command, timeout_ms, check_device))

    def save(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function save; raises on a NACK, timeout or refusal."""
        cls = imu_config.SelectSensorsRevB
        command = cls(
            function=_t.FunctionCode.SAVE,
        )
        self._call(command, timeout_ms, check_device)

    def load(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function load; raises on a NACK, timeout or refusal."""
        cls = imu_config.SelectSensorsRevB
        command = cls(
            function=_t.FunctionCode.LOAD,
        )
        self._call(command, timeout_ms, check_device)

    def default(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function default; raises on a NACK, timeout or refusal."""
        cls = imu_config.SelectSensorsRevB
        command = cls(
            function=_t.FunctionCode.DEFAULT,
        )
        self._call(command, timeout_ms, check_device)


class AuxAccelRange(_Command):
    """Config aux accel range (set 0x02, descriptor 0x0D)."""

    def write(
        self,
        range: _ty.Union[_t.AccelRange, int],
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function write; raises on a NACK, timeout or refusal."""
        cls = imu_config.AuxAccelRange
        command = cls(
            function=_t.FunctionCode.WRITE,
            range=range,
        )
        self._call(command, timeout_ms, check_device)

    def read(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> imu_config.AuxAccelRangeResponse:
        """Function read: returns the reply field."""
        cls = imu_config.AuxAccelRange
        command = cls(
            function=_t.FunctionCode.READ,
        )
        return _ty.cast("imu_config.AuxAccelRangeResponse", self._call(command, timeout_ms, check_device))

    def save(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function save; raises on a NACK, timeout or refusal."""
        cls = imu_config.AuxAccelRange
        command = cls(
            function=_t.FunctionCode.SAVE,
        )
        self._call(command, timeout_ms, check_device)

    def load(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function load; raises on a NACK, timeout or refusal."""
        cls = imu_config.AuxAccelRange
        command = cls(
            function=_t.FunctionCode.LOAD,
        )
        self._call(command, timeout_ms, check_device)

    def default(
        self,
        *,
        timeout_ms: _ty.Optional[int] = None,
        check_device: _ty.Optional[bool] = None,
    ) -> None:
        """Function default; raises on a NACK, timeout or refusal."""
        cls = imu_config.AuxAccelRange
        command = cls(
            function=_t.FunctionCode.DEFAULT,
        )
        self._call(command, timeout_ms, check_device)


class ImuConfigCommands:
    """IMU Configuration Messages commands (set 0x02)."""

    def __init__(self, device: _s.Device) -> None:
        self.uart_baud_rate = UartBaudRate(device)
        self.filter = Filter(device)
        self.sample_rate = SampleRate(device)
        self.select_sensors = SelectSensors(device)
        self.get_internal_sample_rate = GetInternalSampleRate(device)
        self.accel_range = AccelRange(device)
        self.gyro_range = GyroRange(device)
        self.config_all = ConfigAll(device)
        self.data_on_off = DataOnOff(device)
        self.xtrig_on_off = XtrigOnOff(device)
        self.select_sensors_rev_b = SelectSensorsRevB(device)
        self.aux_accel_range = AuxAccelRange(device)


class DeviceCommands:
    """The command sets of a Device, as type checkers see them (session.Device derives from this
    class when type checking; `bind` sets the attributes)."""

    base: BaseCommands

    imu_config: ImuConfigCommands


def bind(device: _s.Device) -> None:
    """Give a Device its command sets (called by Device itself)."""
    device.base = BaseCommands(device)
    device.imu_config = ImuConfigCommands(device)
