"""Typed round trips (generated): every layout class with sample values; every bitfield member."""

# ruff: noqa: I001  (whether the package is first- or third-party depends on where ruff runs)

import pytest
from mipcodec import aiding, base, filter, gnss, reserved, sensor, system, threedm, types
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
    ("filter.ResetFilter", lambda: filter.ResetFilter()),
    ("filter.SetInitialAttitude", lambda: filter.SetInitialAttitude(roll=-0.0, pitch=1.5, heading=-2.25)),
    ("filter.SetInitialHeading", lambda: filter.SetInitialHeading(heading=0.375)),
    ("filter.RunFilter", lambda: filter.RunFilter()),
    (
        "filter.VehicleDynamicsMode",
        lambda: filter.VehicleDynamicsMode(
            function=types.FunctionSelector.DEFAULT, mode=types.VehicleDynamicsMode.AIRBORNE
        ),
    ),
    (
        "filter.VehicleDynamicsModeResponse",
        lambda: filter.VehicleDynamicsModeResponse(mode=types.VehicleDynamicsMode.AIRBORNE_HIGH_G),
    ),
    (
        "filter.SensorToVehicleTransform",
        lambda: filter.SensorToVehicleTransform(
            function=types.FunctionSelector.DEFAULT, roll=1.5, pitch=-2.25, yaw=0.375
        ),
    ),
    (
        "filter.SensorToVehicleTransformResponse",
        lambda: filter.SensorToVehicleTransformResponse(roll=1024.0, pitch=-0.0, yaw=1.5),
    ),
    (
        "filter.SensorToVehicleOffset",
        lambda: filter.SensorToVehicleOffset(function=types.FunctionSelector.DEFAULT, offset=[-2.25, 0.375, 1024.0]),
    ),
    ("filter.SensorToVehicleOffsetResponse", lambda: filter.SensorToVehicleOffsetResponse(offset=[-0.0, 1.5, -2.25])),
    (
        "filter.AntennaOffset",
        lambda: filter.AntennaOffset(function=types.FunctionSelector.DEFAULT, offset=[0.375, 1024.0, -0.0]),
    ),
    ("filter.AntennaOffsetResponse", lambda: filter.AntennaOffsetResponse(offset=[1.5, -2.25, 0.375])),
    (
        "filter.EstimationControl",
        lambda: filter.EstimationControl(
            function=types.FunctionSelector.DEFAULT, flags=types.EstimationControlFlags(0x4)
        ),
    ),
    (
        "filter.EstimationControlResponse",
        lambda: filter.EstimationControlResponse(flags=types.EstimationControlFlags(0x8)),
    ),
    (
        "filter.GnssSourceControl",
        lambda: filter.GnssSourceControl(
            function=types.FunctionSelector.DEFAULT, source=types.FilterGnssSource.ALL_INTERNAL
        ),
    ),
    (
        "filter.GnssSourceControlResponse",
        lambda: filter.GnssSourceControlResponse(source=types.FilterGnssSource.EXTERNAL),
    ),
    (
        "filter.ExternalGnssUpdate",
        lambda: filter.ExternalGnssUpdate(
            gps_tow=1e16,
            gps_week=47,
            latitude=-0.0,
            longitude=0.1,
            height=-2.5e-310,
            velocity=[0.375, 1024.0, -0.0],
            position_uncertainty=[1.5, -2.25, 0.375],
            velocity_uncertainty=[1024.0, -0.0, 1.5],
        ),
    ),
    (
        "filter.ExternalHeadingUpdate",
        lambda: filter.ExternalHeadingUpdate(
            heading=-2.25, heading_uncertainty=0.375, type=types.ExternalHeadingType.TRUE_HEADING
        ),
    ),
    (
        "filter.HeadingUpdateControl",
        lambda: filter.HeadingUpdateControl(
            function=types.FunctionSelector.DEFAULT,
            source=types.HeadingUpdateSource.GNSS_VELOCITY_MAGNETOMETER_AND_EXTERNAL,
        ),
    ),
    (
        "filter.HeadingUpdateControlResponse",
        lambda: filter.HeadingUpdateControlResponse(source=types.HeadingUpdateSource.NONE),
    ),
    ("filter.AutoInitControl", lambda: filter.AutoInitControl(function=types.FunctionSelector.DEFAULT, enable=211)),
    ("filter.AutoInitControlResponse", lambda: filter.AutoInitControlResponse(enable=248)),
    (
        "filter.AccelNoise",
        lambda: filter.AccelNoise(function=types.FunctionSelector.DEFAULT, noise=[1024.0, -0.0, 1.5]),
    ),
    ("filter.AccelNoiseResponse", lambda: filter.AccelNoiseResponse(noise=[-2.25, 0.375, 1024.0])),
    ("filter.GyroNoise", lambda: filter.GyroNoise(function=types.FunctionSelector.DEFAULT, noise=[-0.0, 1.5, -2.25])),
    ("filter.GyroNoiseResponse", lambda: filter.GyroNoiseResponse(noise=[0.375, 1024.0, -0.0])),
    (
        "filter.AccelBiasModel",
        lambda: filter.AccelBiasModel(
            function=types.FunctionSelector.DEFAULT, beta=[1.5, -2.25, 0.375], noise=[1024.0, -0.0, 1.5]
        ),
    ),
    (
        "filter.AccelBiasModelResponse",
        lambda: filter.AccelBiasModelResponse(beta=[-2.25, 0.375, 1024.0], noise=[-0.0, 1.5, -2.25]),
    ),
    (
        "filter.GyroBiasModel",
        lambda: filter.GyroBiasModel(
            function=types.FunctionSelector.DEFAULT, beta=[0.375, 1024.0, -0.0], noise=[1.5, -2.25, 0.375]
        ),
    ),
    (
        "filter.GyroBiasModelResponse",
        lambda: filter.GyroBiasModelResponse(beta=[1024.0, -0.0, 1.5], noise=[-2.25, 0.375, 1024.0]),
    ),
    (
        "filter.ZuptControl",
        lambda: filter.ZuptControl(function=types.FunctionSelector.DEFAULT, enable=111, threshold=1.5),
    ),
    ("filter.ZuptControlResponse", lambda: filter.ZuptControlResponse(enable=185, threshold=0.375)),
    (
        "filter.ExternalHeadingUpdateWithTime",
        lambda: filter.ExternalHeadingUpdateWithTime(
            gps_tow=123.456,
            gps_week=45,
            heading=1.5,
            heading_uncertainty=-2.25,
            type=types.ExternalHeadingType.MAGNETIC_HEADING,
        ),
    ),
    ("gnss.ReceiverInfo", lambda: gnss.ReceiverInfo()),
    (
        "gnss.ReceiverInfoResponse",
        lambda: gnss.ReceiverInfoResponse(
            num_receivers=2,
            receiver_info=[
                types.GnssReceiverInfoEntry(
                    receiver_id=230,
                    mip_data_descriptor_set=16,
                    description=b"pqr\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00",
                ),
                types.GnssReceiverInfoEntry(
                    receiver_id=127,
                    mip_data_descriptor_set=164,
                    description=b"tuv\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00",
                ),
            ],
        ),
    ),
    (
        "gnss.SignalConfiguration",
        lambda: gnss.SignalConfiguration(
            function=types.FunctionSelector.DEFAULT,
            gps_enable=types.GnssGpsSignals(0x4),
            glonass_enable=types.GnssGlonassSignals(0x2),
            galileo_enable=types.GnssGalileoSignals(0x2),
            beidou_enable=types.GnssBeidouSignals(0x4),
            reserved=[135, 172, 209, 246],
        ),
    ),
    (
        "gnss.SignalConfigurationResponse",
        lambda: gnss.SignalConfigurationResponse(
            gps_enable=types.GnssGpsSignals(0x2),
            glonass_enable=types.GnssGlonassSignals(0x2),
            galileo_enable=types.GnssGalileoSignals(0x1),
            beidou_enable=types.GnssBeidouSignals(0x2),
            reserved=[180, 217, 3, 40],
        ),
    ),
    (
        "gnss.SpartnConfiguration",
        lambda: gnss.SpartnConfiguration(
            function=types.FunctionSelector.DEFAULT,
            enable=77,
            type=types.SpartnConnectionType.NETWORK,
            current_key_tow=151,
            current_key_week=188,
            current_key=b"opq\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00",
            next_key_tow=11,
            next_key_week=48,
            next_key=b"rst\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00",
        ),
    ),
    (
        "gnss.SpartnConfigurationResponse",
        lambda: gnss.SpartnConfigurationResponse(
            enable=122,
            type=types.SpartnConnectionType.NONE,
            current_key_tow=196,
            current_key_week=233,
            current_key=b"wxy\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00",
            next_key_tow=56,
            next_key_week=93,
            next_key=b"zab\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00",
        ),
    ),
    (
        "aiding.FrameConfig",
        lambda: aiding.FrameConfig(
            function=types.FunctionSelector.DEFAULT,
            frame_id=167,
            format=types.AidingFrameFormat.EULER,
            tracking_enabled=True,
            translation=[1.5, -2.25, 0.375],
            rotation=types.AidingFrameEuler(euler=[1024.0, -0.0, 1.5]),
        ),
    ),
    (
        "aiding.FrameConfigResponse",
        lambda: aiding.FrameConfigResponse(
            frame_id=212,
            format=types.AidingFrameFormat.EULER,
            tracking_enabled=True,
            translation=[1024.0, -0.0, 1.5],
            rotation=types.AidingFrameEuler(euler=[-2.25, 0.375, 1024.0]),
        ),
    ),
    (
        "aiding.EchoControl",
        lambda: aiding.EchoControl(function=types.FunctionSelector.DEFAULT, mode=types.AidingEchoMode.RESPONSE),
    ),
    ("aiding.EchoControlResponse", lambda: aiding.EchoControlResponse(mode=types.AidingEchoMode.SUPPRESS_ACK)),
    (
        "aiding.EcefPosition",
        lambda: aiding.EcefPosition(
            time=types.AidingTime(timebase=types.AidingTimebase.TIME_OF_ARRIVAL, reserved=154, nanoseconds=191),
            frame_id=228,
            position=[-2.5e-310, 1e16, 123.456],
            uncertainty=[-0.0, 1.5, -2.25],
            valid_flags=types.AidingVectorValidFlags(0x1),
        ),
    ),
    (
        "aiding.LlhPosition",
        lambda: aiding.LlhPosition(
            time=types.AidingTime(timebase=types.AidingTimebase.TIME_OF_ARRIVAL, reserved=96, nanoseconds=133),
            frame_id=170,
            latitude=123.456,
            longitude=-0.0,
            height=0.1,
            uncertainty=[-2.25, 0.375, 1024.0],
            valid_flags=types.AidingLlhValidFlags(0x1),
        ),
    ),
    (
        "aiding.HeightAboveEllipsoid",
        lambda: aiding.HeightAboveEllipsoid(
            time=types.AidingTime(timebase=types.AidingTimebase.TIME_OF_ARRIVAL, reserved=38, nanoseconds=75),
            frame_id=112,
            height=1.5,
            uncertainty=-2.25,
            valid_flags=223,
        ),
    ),
    (
        "aiding.EcefVelocity",
        lambda: aiding.EcefVelocity(
            time=types.AidingTime(timebase=types.AidingTimebase.EXTERNAL_TIME, reserved=83, nanoseconds=120),
            frame_id=157,
            velocity=[1024.0, -0.0, 1.5],
            uncertainty=[-2.25, 0.375, 1024.0],
            valid_flags=types.AidingVectorValidFlags(0x4),
        ),
    ),
    (
        "aiding.NedVelocity",
        lambda: aiding.NedVelocity(
            time=types.AidingTime(timebase=types.AidingTimebase.EXTERNAL_TIME, reserved=25, nanoseconds=62),
            frame_id=99,
            velocity=[1.5, -2.25, 0.375],
            uncertainty=[1024.0, -0.0, 1.5],
            valid_flags=types.AidingVectorValidFlags(0x4),
        ),
    ),
    (
        "aiding.BodyFrameVelocity",
        lambda: aiding.BodyFrameVelocity(
            time=types.AidingTime(timebase=types.AidingTimebase.EXTERNAL_TIME, reserved=218, nanoseconds=4),
            frame_id=41,
            velocity=[0.375, 1024.0, -0.0],
            uncertainty=[1.5, -2.25, 0.375],
            valid_flags=types.AidingVectorValidFlags(0x4),
        ),
    ),
    (
        "aiding.TrueHeading",
        lambda: aiding.TrueHeading(
            time=types.AidingTime(timebase=types.AidingTimebase.EXTERNAL_TIME, reserved=160, nanoseconds=197),
            frame_id=234,
            heading=-0.0,
            uncertainty=1.5,
            valid_flags=94,
        ),
    ),
    (
        "aiding.MagneticField",
        lambda: aiding.MagneticField(
            time=types.AidingTime(timebase=types.AidingTimebase.INTERNAL_REFERENCE, reserved=205, nanoseconds=242),
            frame_id=28,
            magnetic_field=[0.375, 1024.0, -0.0],
            uncertainty=[1.5, -2.25, 0.375],
            valid_flags=types.AidingVectorValidFlags(0x2),
        ),
    ),
    (
        "aiding.Pressure",
        lambda: aiding.Pressure(
            time=types.AidingTime(timebase=types.AidingTimebase.INTERNAL_REFERENCE, reserved=147, nanoseconds=184),
            frame_id=221,
            pressure=-0.0,
            uncertainty=1.5,
            valid_flags=81,
        ),
    ),
    (
        "system.CommunicationMode",
        lambda: system.CommunicationMode(
            function=types.FunctionSelector.DEFAULT, mode=types.SystemCommMode.SENSOR_DIRECT
        ),
    ),
    (
        "system.CommunicationModeResponse",
        lambda: system.CommunicationModeResponse(mode=types.SystemCommMode.GNSS_DIRECT),
    ),
    ("sensor.ScaledAccel", lambda: sensor.ScaledAccel(scaled_accel=[-0.0, 1.5, -2.25])),
    ("sensor.ScaledGyro", lambda: sensor.ScaledGyro(scaled_gyro=[0.375, 1024.0, -0.0])),
    ("sensor.ScaledMag", lambda: sensor.ScaledMag(scaled_mag=[1.5, -2.25, 0.375])),
    ("reserved.AckNack", lambda: reserved.AckNack(command_descriptor=23, ack_code=types.AckCode.COMMAND_TIMEOUT)),
    ("types.ActionGpioParams", lambda: types.ActionGpioParams(pin=97, mode=types.ActionGpioMode.DISABLED)),
    (
        "types.MessageParams",
        lambda: types.MessageParams(desc_set=171, decimation=208, num_fields=2, descriptors=[245, 31]),
    ),
    ("types.ActionStatusEntry", lambda: types.ActionStatusEntry(action_type=types.ActionType.MESSAGE, trigger_id=105)),
    ("types.AidingFrameEuler", lambda: types.AidingFrameEuler(euler=[1024.0, -0.0, 1.5])),
    ("types.AidingFrameQuaternion", lambda: types.AidingFrameQuaternion(quaternion=[-2.25, 0.375, 1024.0, -0.0])),
    (
        "types.AidingTime",
        lambda: types.AidingTime(timebase=types.AidingTimebase.TIME_OF_ARRIVAL, reserved=187, nanoseconds=224),
    ),
    ("types.CombinationParams", lambda: types.CombinationParams(logic_table=10, input_triggers=[47, 84, 121, 158])),
    (
        "types.DeviceInfo",
        lambda: types.DeviceInfo(
            firmware_version=195,
            model_name=b"vwx             ",
            model_number=b"wxy             ",
            serial_number=b"xyz             ",
            lot_number=b"yza             ",
            device_options=b"zab             ",
        ),
    ),
    (
        "types.GnssReceiverInfoEntry",
        lambda: types.GnssReceiverInfoEntry(
            receiver_id=166,
            mip_data_descriptor_set=203,
            description=b"cde\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00",
        ),
    ),
    (
        "types.ThresholdParams",
        lambda: types.ThresholdParams(
            desc_set=26,
            field_desc=63,
            param_id=100,
            type=types.ThresholdType.WINDOW,
            low_thres=-2.5e-310,
            high_thres=1e16,
        ),
    ),
    ("types.TriggerGpioParams", lambda: types.TriggerGpioParams(pin=248, mode=types.TriggerGpioMode.WHILE_LOW)),
    (
        "types.TriggerStatusEntry",
        lambda: types.TriggerStatusEntry(type=types.TriggerType.COMBINATION, status=types.TriggerStatus(0x2)),
    ),
]

BITFIELD_MEMBERS = [
    (types.AidingLlhValidFlags, "latitude", "LATITUDE", 0, 1, 0x1),
    (types.AidingLlhValidFlags, "longitude", "LONGITUDE", 1, 1, 0x2),
    (types.AidingLlhValidFlags, "height", "HEIGHT", 2, 1, 0x4),
    (types.AidingVectorValidFlags, "x", "X", 0, 1, 0x1),
    (types.AidingVectorValidFlags, "y", "Y", 1, 1, 0x2),
    (types.AidingVectorValidFlags, "z", "Z", 2, 1, 0x4),
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
    (types.EstimationControlFlags, "gyro_bias", "GYRO_BIAS", 0, 1, 0x1),
    (types.EstimationControlFlags, "accel_bias", "ACCEL_BIAS", 1, 1, 0x2),
    (types.EstimationControlFlags, "gyro_scale_factor", "GYRO_SCALE_FACTOR", 2, 1, 0x4),
    (types.EstimationControlFlags, "accel_scale_factor", "ACCEL_SCALE_FACTOR", 3, 1, 0x8),
    (types.EstimationControlFlags, "antenna_offset", "ANTENNA_OFFSET", 4, 1, 0x10),
    (types.EstimationControlFlags, "hard_iron_auto_cal", "HARD_IRON_AUTO_CAL", 5, 1, 0x20),
    (types.EstimationControlFlags, "soft_iron_auto_cal", "SOFT_IRON_AUTO_CAL", 6, 1, 0x40),
    (types.EstimationControlFlags, "reserved", "RESERVED", 7, 9, 0xFF80),
    (types.GnssBeidouSignals, "b1", "B1", 0, 1, 0x1),
    (types.GnssBeidouSignals, "b2", "B2", 1, 1, 0x2),
    (types.GnssBeidouSignals, "b2a", "B2A", 2, 1, 0x4),
    (types.GnssGalileoSignals, "e1", "E1", 0, 1, 0x1),
    (types.GnssGalileoSignals, "e5b", "E5B", 1, 1, 0x2),
    (types.GnssGalileoSignals, "e5a", "E5A", 2, 1, 0x4),
    (types.GnssGlonassSignals, "l1of", "L1OF", 0, 1, 0x1),
    (types.GnssGlonassSignals, "l2of", "L2OF", 1, 1, 0x2),
    (types.GnssGpsSignals, "l1ca", "L1CA", 0, 1, 0x1),
    (types.GnssGpsSignals, "l2c", "L2C", 1, 1, 0x2),
    (types.GnssGpsSignals, "l5", "L5", 2, 1, 0x4),
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
