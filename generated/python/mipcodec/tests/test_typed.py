"""Typed round trips (generated): every layout class with sample values; every bitfield member."""

# ruff: noqa: I001  (whether the package is first- or third-party depends on where ruff runs)

import pytest
from mipcodec import base, reserved, sensor, threedm, types
from mipcodec.canonical import loads
from mipcodec.framing import MAX_FIELD_DATA, PacketBuilder
from mipcodec.packets import DecodedField, decode_packet
from mipcodec.registry import SET_KINDS

SAMPLES = [
    ("base.Ping", lambda: base.Ping()),
    ("base.SetToIdle", lambda: base.SetToIdle()),
    ("base.GetDeviceInfo", lambda: base.GetDeviceInfo()),
    (
        "base.DeviceInfo",
        lambda: base.DeviceInfo(
            info=types.DeviceInfo(
                firmware_version=75,
                model_name=b"def             ",
                model_number=b"efg             ",
                serial_number=b"fgh             ",
                lot_number=b"ghi             ",
                device_options=b"hij             ",
            )
        ),
    ),
    ("base.GetDeviceDescriptors", lambda: base.GetDeviceDescriptors()),
    ("base.DeviceDescriptors", lambda: base.DeviceDescriptors(descriptors=[46, 83])),
    ("base.BuiltInTest", lambda: base.BuiltInTest()),
    ("base.BuiltInTestResult_gx5_45", lambda: base.BuiltInTestResult_gx5_45(flags=types.Gx5BitFlags(0x1))),
    ("base.BuiltInTestResult_cv7_ins", lambda: base.BuiltInTestResult_cv7_ins(flags=types.Cv7BitFlags(0x40000))),
    ("base.Resume", lambda: base.Resume()),
    ("base.GetExtendedDescriptors", lambda: base.GetExtendedDescriptors()),
    ("base.ExtendedDescriptors", lambda: base.ExtendedDescriptors(descriptors=[194, 231])),
    ("base.ContinuousBit", lambda: base.ContinuousBit()),
    (
        "base.ContinuousBitResult",
        lambda: base.ContinuousBitResult(
            result=[17, 54, 91, 128, 165, 202, 239, 25, 62, 99, 136, 173, 210, 247, 33, 70]
        ),
    ),
    ("base.CommPortSpeed", lambda: base.CommPortSpeed(function=types.FunctionSelector.DEFAULT, port=107, baud=144)),
    ("base.CommPortSpeedResponse", lambda: base.CommPortSpeedResponse(port=181, baud=218)),
    (
        "base.GpsTimeUpdate_gx5_45",
        lambda: base.GpsTimeUpdate_gx5_45(
            function=types.FunctionSelector.WRITE_NO_ACK, field_id=types.GpsTimeField.WEEK_NUMBER, value=41
        ),
    ),
    (
        "base.GpsTimeUpdate_cv7_ins",
        lambda: base.GpsTimeUpdate_cv7_ins(
            function=types.FunctionSelector.WRITE, field_id=types.GpsTimeField.WEEK_NUMBER, value=115
        ),
    ),
    ("base.GpsWeek", lambda: base.GpsWeek(week=152)),
    ("base.GpsSeconds", lambda: base.GpsSeconds(seconds=189)),
    ("base.DeviceReset", lambda: base.DeviceReset()),
    (
        "threedm.EventControl",
        lambda: threedm.EventControl(
            function=types.FunctionSelector.DEFAULT, instance=226, mode=types.EventControlMode.ENABLED
        ),
    ),
    (
        "threedm.EventControlResponse",
        lambda: threedm.EventControlResponse(instance=49, mode=types.EventControlMode.TEST_PULSE),
    ),
    (
        "threedm.GetEventTriggerStatus",
        lambda: threedm.GetEventTriggerStatus(requested_count=2, requested_instances=[123, 160]),
    ),
    (
        "threedm.EventTriggerStatus",
        lambda: threedm.EventTriggerStatus(
            count=2,
            triggers=[
                types.TriggerStatusEntry(type=types.TriggerType.COMBINATION, status=types.TriggerStatus(0x1)),
                types.TriggerStatusEntry(type=types.TriggerType.THRESHOLD, status=types.TriggerStatus(0x1)),
            ],
        ),
    ),
    (
        "threedm.GetEventActionStatus",
        lambda: threedm.GetEventActionStatus(requested_count=2, requested_instances=[168, 205]),
    ),
    (
        "threedm.EventActionStatus",
        lambda: threedm.EventActionStatus(
            count=2,
            actions=[
                types.ActionStatusEntry(action_type=types.ActionType.GPIO, trigger_id=65),
                types.ActionStatusEntry(action_type=types.ActionType.GPIO, trigger_id=176),
            ],
        ),
    ),
    (
        "threedm.EventTriggerConfig",
        lambda: threedm.EventTriggerConfig(
            function=types.FunctionSelector.DEFAULT,
            instance=213,
            type=types.TriggerType.GPIO,
            parameters=types.TriggerGpioParams(pin=250, mode=types.TriggerGpioMode.WHILE_LOW),
        ),
    ),
    (
        "threedm.EventTriggerConfigResponse",
        lambda: threedm.EventTriggerConfigResponse(
            instance=73,
            type=types.TriggerType.GPIO,
            parameters=types.TriggerGpioParams(pin=110, mode=types.TriggerGpioMode.WHILE_HIGH),
        ),
    ),
    (
        "threedm.EventActionConfig",
        lambda: threedm.EventActionConfig(
            function=types.FunctionSelector.DEFAULT,
            instance=184,
            trigger=221,
            type=types.ActionType.GPIO,
            parameters=types.ActionGpioParams(pin=7, mode=types.ActionGpioMode.ONESHOT_HIGH),
        ),
    ),
    (
        "threedm.EventActionConfigResponse",
        lambda: threedm.EventActionConfigResponse(
            instance=81,
            trigger=118,
            type=types.ActionType.GPIO,
            parameters=types.ActionGpioParams(pin=155, mode=types.ActionGpioMode.ACTIVE_HIGH),
        ),
    ),
    ("sensor.ScaledAccel", lambda: sensor.ScaledAccel(scaled_accel=[-0.0, 1.5, -2.25])),
    ("sensor.ScaledGyro", lambda: sensor.ScaledGyro(scaled_gyro=[0.375, 1024.0, -0.0])),
    ("sensor.ScaledMag", lambda: sensor.ScaledMag(scaled_mag=[1.5, -2.25, 0.375])),
    ("reserved.AckNack", lambda: reserved.AckNack(command_descriptor=60, ack_code=types.AckCode.OK)),
    ("types.ActionGpioParams", lambda: types.ActionGpioParams(pin=134, mode=types.ActionGpioMode.ACTIVE_LOW)),
    (
        "types.MessageParams",
        lambda: types.MessageParams(desc_set=208, decimation=245, num_fields=2, descriptors=[31, 68]),
    ),
    ("types.ActionStatusEntry", lambda: types.ActionStatusEntry(action_type=types.ActionType.GPIO, trigger_id=142)),
    ("types.CombinationParams", lambda: types.CombinationParams(logic_table=179, input_triggers=[216, 2, 39, 76])),
    (
        "types.DeviceInfo",
        lambda: types.DeviceInfo(
            firmware_version=113,
            model_name=b"vwx             ",
            model_number=b"wxy             ",
            serial_number=b"xyz             ",
            lot_number=b"yza             ",
            device_options=b"zab             ",
        ),
    ),
    (
        "types.ThresholdParams",
        lambda: types.ThresholdParams(
            desc_set=84,
            field_desc=121,
            param_id=158,
            type=types.ThresholdType.INTERVAL,
            low_thres=123.456,
            high_thres=-0.0,
        ),
    ),
    ("types.TriggerGpioParams", lambda: types.TriggerGpioParams(pin=55, mode=types.TriggerGpioMode.EDGE)),
    (
        "types.TriggerStatusEntry",
        lambda: types.TriggerStatusEntry(type=types.TriggerType.NONE, status=types.TriggerStatus(0x4)),
    ),
]

BITFIELD_MEMBERS = [
    (types.Cv7BitFlags, "general_hardware_fault", "GENERAL_HARDWARE_FAULT", 0, 1, 0x1),
    (types.Cv7BitFlags, "general_firmware_fault", "GENERAL_FIRMWARE_FAULT", 1, 1, 0x2),
    (types.Cv7BitFlags, "timing_overload", "TIMING_OVERLOAD", 2, 1, 0x4),
    (types.Cv7BitFlags, "buffer_overrun", "BUFFER_OVERRUN", 3, 1, 0x8),
    (types.Cv7BitFlags, "reserved_system", "RESERVED_SYSTEM", 4, 4, 0xF0),
    (types.Cv7BitFlags, "reserved_comms", "RESERVED_COMMS", 8, 4, 0xF00),
    (types.Cv7BitFlags, "accelerometer_fault", "ACCELEROMETER_FAULT", 12, 1, 0x1000),
    (types.Cv7BitFlags, "gyroscope_fault", "GYROSCOPE_FAULT", 13, 1, 0x2000),
    (types.Cv7BitFlags, "magnetometer_fault", "MAGNETOMETER_FAULT", 14, 1, 0x4000),
    (types.Cv7BitFlags, "pressure_sensor_fault", "PRESSURE_SENSOR_FAULT", 15, 1, 0x8000),
    (types.Cv7BitFlags, "reserved_imu", "RESERVED_IMU", 16, 2, 0x30000),
    (types.Cv7BitFlags, "calibration_error", "CALIBRATION_ERROR", 18, 1, 0x40000),
    (types.Cv7BitFlags, "general_imu_fault", "GENERAL_IMU_FAULT", 19, 1, 0x80000),
    (types.Cv7BitFlags, "reserved_filter", "RESERVED_FILTER", 20, 2, 0x300000),
    (types.Cv7BitFlags, "filter_solution_fault", "FILTER_SOLUTION_FAULT", 22, 1, 0x400000),
    (types.Cv7BitFlags, "general_filter_fault", "GENERAL_FILTER_FAULT", 23, 1, 0x800000),
    (types.Cv7BitFlags, "reserved", "RESERVED", 24, 8, 0xFF000000),
    (types.Gx5BitFlags, "processor_wdt_reset", "PROCESSOR_WDT_RESET", 0, 1, 0x1),
    (types.Gx5BitFlags, "imu_communication_fault", "IMU_COMMUNICATION_FAULT", 8, 1, 0x100),
    (types.Gx5BitFlags, "magnetometer_fault", "MAGNETOMETER_FAULT", 9, 1, 0x200),
    (types.Gx5BitFlags, "pressure_sensor_fault", "PRESSURE_SENSOR_FAULT", 10, 1, 0x400),
    (types.Gx5BitFlags, "filter_solution_fault", "FILTER_SOLUTION_FAULT", 24, 1, 0x1000000),
    (types.TriggerStatus, "active", "ACTIVE", 0, 1, 0x1),
    (types.TriggerStatus, "enabled", "ENABLED", 1, 1, 0x2),
    (types.TriggerStatus, "test", "TEST", 2, 1, 0x4),
]


@pytest.mark.parametrize("name,make", SAMPLES, ids=[s[0] for s in SAMPLES])
def test_encode_decode_round_trip(name, make):
    value = make()
    data = value.encode()
    back = type(value).decode(data)
    assert back == value
    assert back.encode() == data
    assert type(value).from_json(loads(value.to_json())) == value


FIELD_SAMPLES = [s for s in SAMPLES if not s[0].startswith("types.")]


@pytest.mark.parametrize("name,make", FIELD_SAMPLES, ids=[s[0] for s in FIELD_SAMPLES])
def test_in_a_packet(name, make):
    value = make()
    data = value.encode()
    assert len(data) <= MAX_FIELD_DATA, "a sample value must fit in one field"
    set_id = value.SET
    if set_id is None:
        set_id = next(first for kind, first, _last in SET_KINDS if kind == value.APPLIES_TO)
    packet = PacketBuilder(set_id).add(value).build()
    decoded = decode_packet(packet, device=value.DEVICE)
    assert len(decoded.fields) == 1
    entry = decoded.fields[0]
    assert isinstance(entry, DecodedField), entry
    assert entry.value == value


@pytest.mark.parametrize(
    "cls,attr,const,first,width,mask", BITFIELD_MEMBERS, ids=[f"{b[0].__name__}.{b[1]}" for b in BITFIELD_MEMBERS]
)
def test_bitfield_member(cls, attr, const, first, width, mask):
    constant = getattr(cls, const)
    assert isinstance(constant, cls) and constant == mask
    value = cls(mask)
    got = getattr(value, attr)
    if width == 1:
        assert got is True
        assert getattr(cls(0), attr) is False
    else:
        assert got == (1 << width) - 1
    assert cls(0).replace(**{attr: (1 << width) - 1}) == mask
    assert constant in (constant | cls(0))
    assert isinstance(cls(0) | constant, cls)
    assert int(~cls(0)) == cls._ALL
