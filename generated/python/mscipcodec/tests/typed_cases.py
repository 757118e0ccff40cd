"""Typed samples of mscipcodec (generated): a sample value of every layout class and every bitfield
member, checked by tests/test_typed.py."""

# ruff: noqa: I001  (whether the package is first- or third-party depends on where ruff runs)

from mscipcodec import base, imu_config, imu_data, reserved, types
from mscipcodec import registry
from mscipcodec.codec import canonical, framing, packets

__all__ = ["BITFIELD_MEMBERS", "SAMPLES", "canonical", "framing", "packets", "registry"]

SAMPLES = [
    ("base.Ping", lambda: base.Ping()),
    ("base.GetDeviceMessages", lambda: base.GetDeviceMessages()),
    (
        "base.DeviceMessages",
        lambda: base.DeviceMessages(
            messages=[
                types.MessageId(message_type=117, message_code=154),
                types.MessageId(message_type=228, message_code=14),
            ]
        ),
    ),
    ("base.DeviceReset", lambda: base.DeviceReset()),
    ("base.GetDeviceModel", lambda: base.GetDeviceModel()),
    ("base.DeviceModel", lambda: base.DeviceModel(model=b"rst             ")),
    ("base.GetDeviceSn", lambda: base.GetDeviceSn()),
    ("base.DeviceSn", lambda: base.DeviceSn(serial_number=b"zab             ")),
    ("base.GetDeviceFw", lambda: base.GetDeviceFw()),
    ("base.DeviceFw", lambda: base.DeviceFw(firmware=b"zab             ")),
    ("base.GetDeviceCal", lambda: base.GetDeviceCal()),
    ("base.DeviceCal", lambda: base.DeviceCal(date=b"klm             ")),
    ("base.CorrelateGpsTime", lambda: base.CorrelateGpsTime(week=171, seconds=208)),
    (
        "imu_config.UartBaudRate",
        lambda: imu_config.UartBaudRate(function=types.FunctionCode.DEFAULT, baud_rate=types.BaudRate.BAUD_19200),
    ),
    ("imu_config.UartBaudRateResponse", lambda: imu_config.UartBaudRateResponse(baud_rate=types.BaudRate.BAUD_9600)),
    (
        "imu_config.Filter",
        lambda: imu_config.Filter(function=types.FunctionCode.DEFAULT, bandwidth=types.FilterBandwidth.IIR_200HZ),
    ),
    ("imu_config.FilterResponse", lambda: imu_config.FilterResponse(bandwidth=types.FilterBandwidth.IIR_75HZ)),
    ("imu_config.SampleRate", lambda: imu_config.SampleRate(function=types.FunctionCode.DEFAULT, decimation=60)),
    ("imu_config.SampleRateResponse", lambda: imu_config.SampleRateResponse(decimation=103)),
    (
        "imu_config.SelectSensors",
        lambda: imu_config.SelectSensors(
            function=types.FunctionCode.DEFAULT,
            reserved=210,
            sensors=[types.SensorCode.SCALED_AUX_ACCEL, types.SensorCode.SCALED_ACCEL],
        ),
    ),
    (
        "imu_config.SelectSensorsResponse",
        lambda: imu_config.SelectSensorsResponse(sensors=[types.SensorCode.SCALED_ACCEL, types.SensorCode.SCALED_GYRO]),
    ),
    ("imu_config.GetInternalSampleRate", lambda: imu_config.GetInternalSampleRate()),
    ("imu_config.InternalSampleRate", lambda: imu_config.InternalSampleRate(rate=214)),
    (
        "imu_config.AccelRange",
        lambda: imu_config.AccelRange(function=types.FunctionCode.DEFAULT, range=types.AccelRange.RANGE_40G),
    ),
    ("imu_config.AccelRangeResponse", lambda: imu_config.AccelRangeResponse(range=types.AccelRange.RANGE_40G)),
    (
        "imu_config.GyroRange",
        lambda: imu_config.GyroRange(function=types.FunctionCode.DEFAULT, range=types.GyroRange.RANGE_240DPS),
    ),
    ("imu_config.GyroRangeResponse", lambda: imu_config.GyroRangeResponse(range=types.GyroRange.RANGE_240DPS)),
    ("imu_config.ConfigAll", lambda: imu_config.ConfigAll(function=types.FunctionCode.DEFAULT)),
    ("imu_config.DataOnOff", lambda: imu_config.DataOnOff(function=types.FunctionCode.DEFAULT, control=types.OnOff.ON)),
    ("imu_config.DataOnOffResponse", lambda: imu_config.DataOnOffResponse(control=types.OnOff.ON)),
    (
        "imu_config.XtrigOnOff",
        lambda: imu_config.XtrigOnOff(function=types.FunctionCode.DEFAULT, control=types.OnOff.OFF),
    ),
    ("imu_config.XtrigOnOffResponse", lambda: imu_config.XtrigOnOffResponse(control=types.OnOff.OFF)),
    (
        "imu_config.SelectSensorsRevB",
        lambda: imu_config.SelectSensorsRevB(
            function=types.FunctionCode.DEFAULT,
            sensors=[types.SensorCode.SCALED_TEMPERATURE, types.SensorCode.GPS_CORRELATED_TIME],
        ),
    ),
    (
        "imu_config.SelectSensorsRevBResponse",
        lambda: imu_config.SelectSensorsRevBResponse(
            sensors=[types.SensorCode.SCALED_ACCEL, types.SensorCode.SCALED_GYRO]
        ),
    ),
    (
        "imu_config.AuxAccelRange",
        lambda: imu_config.AuxAccelRange(function=types.FunctionCode.DEFAULT, range=types.AccelRange.RANGE_20G),
    ),
    ("imu_config.AuxAccelRangeResponse", lambda: imu_config.AuxAccelRangeResponse(range=types.AccelRange.RANGE_2G)),
    ("imu_data.ScaledAccel", lambda: imu_data.ScaledAccel(accel=[1024.0, -0.0, 1.5])),
    ("imu_data.ScaledGyro", lambda: imu_data.ScaledGyro(gyro=[-2.25, 0.375, 1024.0])),
    ("imu_data.ScaledMag", lambda: imu_data.ScaledMag(mag=[1024.0, -0.0, 1.5])),
    ("imu_data.DeltaTheta", lambda: imu_data.DeltaTheta(delta_theta=[-2.25, 0.375, 1024.0])),
    ("imu_data.DeltaVelocity", lambda: imu_data.DeltaVelocity(delta_velocity=[1.5, -2.25, 0.375])),
    ("imu_data.ScaledPressure", lambda: imu_data.ScaledPressure(pressure=-2.25)),
    ("imu_data.ScaledTemperature", lambda: imu_data.ScaledTemperature(temperature=1024.0)),
    (
        "imu_data.GpsCorrelatedTime",
        lambda: imu_data.GpsCorrelatedTime(seconds=123.456, week=164, flags=types.GpsTimeFlags(0x1)),
    ),
    ("imu_data.ScaledAuxAccel", lambda: imu_data.ScaledAuxAccel(accel=[-0.0, 1.5, -2.25])),
    ("reserved.Ack", lambda: reserved.Ack(command_code=213, error_code=types.ErrorCode.INVALID_MESSAGE_CODE)),
    ("types.MessageId", lambda: types.MessageId(message_type=49, message_code=86)),
]

BITFIELD_MEMBERS = [
    (types.GpsTimeFlags, "pps_received", "PPS_RECEIVED", 0, 1, 0x1),
    (types.GpsTimeFlags, "time_set", "TIME_SET", 1, 1, 0x2),
    (types.GpsTimeFlags, "time_not_set", "TIME_NOT_SET", 2, 1, 0x4),
    (types.GpsTimeFlags, "pps_lost", "PPS_LOST", 3, 1, 0x8),
    (types.GpsTimeFlags, "reserved", "RESERVED", 4, 12, 0xFFF0),
]
