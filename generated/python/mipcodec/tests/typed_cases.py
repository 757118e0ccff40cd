"""Typed samples of mipcodec (generated): a sample value of every layout class and every bitfield
member, checked by tests/test_typed.py."""

# ruff: noqa: I001  (whether the package is first- or third-party depends on where ruff runs)

from mipcodec import (
    aiding,
    base,
    filter,
    filter_data,
    gnss,
    gnss_corrections,
    gnss_data,
    gnss_external,
    gnss_receiver_1,
    gnss_receiver_2,
    reserved,
    sensor,
    shared,
    system,
    system_data,
    threedm,
    types,
)
from mipcodec import registry
from mipcodec.codec import canonical, framing, packets

__all__ = ["BITFIELD_MEMBERS", "SAMPLES", "canonical", "framing", "packets", "registry"]

SAMPLES = [
    ("base.Ping", lambda: base.Ping()),
    ("base.SetToIdle", lambda: base.SetToIdle()),
    ("base.GetDeviceInfo", lambda: base.GetDeviceInfo()),
    (
        "base.DeviceInfo",
        lambda: base.DeviceInfo(
            info=types.DeviceInfo(
                firmware_version=56,
                model_name=b"rst             ",
                model_number=b"stu             ",
                serial_number=b"tuv             ",
                lot_number=b"uvw             ",
                device_options=b"vwx             ",
            )
        ),
    ),
    ("base.GetDeviceDescriptors", lambda: base.GetDeviceDescriptors()),
    ("base.DeviceDescriptors", lambda: base.DeviceDescriptors(descriptors=[21, 58])),
    ("base.BuiltInTest", lambda: base.BuiltInTest()),
    ("base.BuiltInTestResult_gx5_45", lambda: base.BuiltInTestResult_gx5_45(flags=types.Gx5BitFlags(0x100))),
    ("base.BuiltInTestResult_cv7_ins", lambda: base.BuiltInTestResult_cv7_ins(flags=types.Cv7BitFlags(0x4000))),
    ("base.Resume", lambda: base.Resume()),
    ("base.GetExtendedDescriptors", lambda: base.GetExtendedDescriptors()),
    ("base.ExtendedDescriptors", lambda: base.ExtendedDescriptors(descriptors=[248, 34])),
    ("base.ContinuousBit", lambda: base.ContinuousBit()),
    (
        "base.ContinuousBitResult",
        lambda: base.ContinuousBitResult(
            result=types.Cv7ContinuousBit(
                system_byte_0=types.Cv7ContinuousBitSystem0(0x10),
                reserved_byte_1=227,
                system_byte_2=types.Cv7ContinuousBitSystem2(0x2),
                system_byte_3=types.Cv7ContinuousBitSystem3(0x8),
                imu_byte_4=types.Cv7ContinuousBitImu4(0x8),
                imu_byte_5=types.Cv7ContinuousBitImu5(0x10),
                imu_byte_6=types.Cv7ContinuousBitImu6(0x20),
                imu_byte_7=types.Cv7ContinuousBitImu7(0x1),
                nav_byte_8=types.Cv7ContinuousBitNav8(0x8),
                reserved_byte_9=21,
                reserved_byte_10=58,
                reserved_byte_11=95,
                reserved_byte_12=132,
                gnss_byte_13=types.Cv7ContinuousBitGnss13(0xC),
                gnss_byte_14=types.Cv7ContinuousBitGnss14(0x2),
                reserved_byte_15=243,
            )
        ),
    ),
    ("base.CommPortSpeed", lambda: base.CommPortSpeed(function=types.FunctionSelector.DEFAULT, port=126, baud=163)),
    ("base.CommPortSpeedResponse", lambda: base.CommPortSpeedResponse(port=63, baud=100)),
    (
        "base.GpsTimeUpdate_gx5_45",
        lambda: base.GpsTimeUpdate_gx5_45(
            function=types.FunctionSelector.WRITE_NO_ACK, field_id=types.GpsTimeField.WEEK_NUMBER, value=147
        ),
    ),
    (
        "base.GpsTimeUpdate_cv7_ins",
        lambda: base.GpsTimeUpdate_cv7_ins(
            function=types.FunctionSelector.WRITE, field_id=types.GpsTimeField.TIME_OF_WEEK, value=199
        ),
    ),
    ("base.GpsWeek", lambda: base.GpsWeek(week=105)),
    ("base.GpsSeconds", lambda: base.GpsSeconds(seconds=190)),
    ("base.DeviceReset", lambda: base.DeviceReset()),
    (
        "threedm.EventControl",
        lambda: threedm.EventControl(
            function=types.FunctionSelector.DEFAULT, instance=172, mode=types.EventControlMode.DISABLED
        ),
    ),
    (
        "threedm.EventControlResponse",
        lambda: threedm.EventControlResponse(instance=18, mode=types.EventControlMode.TEST),
    ),
    (
        "threedm.GetEventTriggerStatus",
        lambda: threedm.GetEventTriggerStatus(requested_count=2, requested_instances=[237, 23]),
    ),
    (
        "threedm.EventTriggerStatus",
        lambda: threedm.EventTriggerStatus(
            count=2,
            triggers=[
                types.TriggerStatusEntry(type=types.TriggerType.NONE, status=types.TriggerStatus(0x4)),
                types.TriggerStatusEntry(type=types.TriggerType.COMBINATION, status=types.TriggerStatus(0x4)),
            ],
        ),
    ),
    (
        "threedm.GetEventActionStatus",
        lambda: threedm.GetEventActionStatus(requested_count=2, requested_instances=[160, 197]),
    ),
    (
        "threedm.EventActionStatus",
        lambda: threedm.EventActionStatus(
            count=2,
            actions=[
                types.ActionStatusEntry(action_type=types.ActionType.NONE, trigger_id=227),
                types.ActionStatusEntry(action_type=types.ActionType.NONE, trigger_id=87),
            ],
        ),
    ),
    (
        "threedm.EventTriggerConfig",
        lambda: threedm.EventTriggerConfig(
            function=types.FunctionSelector.DEFAULT,
            instance=196,
            type=types.TriggerType.GPIO,
            parameters=types.TriggerGpioParams(pin=233, mode=types.TriggerGpioMode.WHILE_LOW),
        ),
    ),
    (
        "threedm.EventTriggerConfigResponse",
        lambda: threedm.EventTriggerConfigResponse(
            instance=125,
            type=types.TriggerType.GPIO,
            parameters=types.TriggerGpioParams(pin=162, mode=types.TriggerGpioMode.WHILE_LOW),
        ),
    ),
    (
        "threedm.EventActionConfig",
        lambda: threedm.EventActionConfig(
            function=types.FunctionSelector.DEFAULT,
            instance=40,
            trigger=77,
            type=types.ActionType.GPIO,
            parameters=types.ActionGpioParams(pin=114, mode=types.ActionGpioMode.DISABLED),
        ),
    ),
    (
        "threedm.EventActionConfigResponse",
        lambda: threedm.EventActionConfigResponse(
            instance=123,
            trigger=160,
            type=types.ActionType.GPIO,
            parameters=types.ActionGpioParams(pin=197, mode=types.ActionGpioMode.ONESHOT_HIGH),
        ),
    ),
    (
        "threedm.DeviceStartupSettings_gx5_45",
        lambda: threedm.DeviceStartupSettings_gx5_45(function=types.FunctionSelector.DEFAULT),
    ),
    (
        "threedm.DeviceStartupSettings_cv7_ins",
        lambda: threedm.DeviceStartupSettings_cv7_ins(function=types.FunctionSelector.DEFAULT),
    ),
    (
        "threedm.SensorToVehicleEuler",
        lambda: threedm.SensorToVehicleEuler(function=types.FunctionSelector.DEFAULT, roll=-0.0, pitch=1.5, yaw=-2.25),
    ),
    (
        "threedm.SensorToVehicleEulerResponse",
        lambda: threedm.SensorToVehicleEulerResponse(roll=-0.0, pitch=1.5, yaw=-2.25),
    ),
    (
        "threedm.SensorToVehicleQuaternion",
        lambda: threedm.SensorToVehicleQuaternion(
            function=types.FunctionSelector.DEFAULT, q=[0.375, 1024.0, -0.0, 1.5]
        ),
    ),
    (
        "threedm.SensorToVehicleQuaternionResponse",
        lambda: threedm.SensorToVehicleQuaternionResponse(q=[0.375, 1024.0, -0.0, 1.5]),
    ),
    (
        "threedm.SensorToVehicleDcm",
        lambda: threedm.SensorToVehicleDcm(
            function=types.FunctionSelector.DEFAULT, dcm=[1.5, -2.25, 0.375, 1024.0, -0.0, 1.5, -2.25, 0.375, 1024.0]
        ),
    ),
    (
        "threedm.SensorToVehicleDcmResponse",
        lambda: threedm.SensorToVehicleDcmResponse(dcm=[-0.0, 1.5, -2.25, 0.375, 1024.0, -0.0, 1.5, -2.25, 0.375]),
    ),
    (
        "threedm.AccelBias_gx5_45",
        lambda: threedm.AccelBias_gx5_45(function=types.FunctionSelector.WRITE_NO_ACK, bias=[-2.25, 0.375, 1024.0]),
    ),
    (
        "threedm.AccelBias_cv7_ins",
        lambda: threedm.AccelBias_cv7_ins(function=types.FunctionSelector.DEFAULT, bias=[0.375, 1024.0, -0.0]),
    ),
    ("threedm.AccelBiasResponse", lambda: threedm.AccelBiasResponse(bias=[-2.25, 0.375, 1024.0])),
    (
        "threedm.GyroBias_gx5_45",
        lambda: threedm.GyroBias_gx5_45(function=types.FunctionSelector.WRITE_NO_ACK, bias=[1024.0, -0.0, 1.5]),
    ),
    (
        "threedm.GyroBias_cv7_ins",
        lambda: threedm.GyroBias_cv7_ins(function=types.FunctionSelector.DEFAULT, bias=[1.5, -2.25, 0.375]),
    ),
    ("threedm.GyroBiasResponse", lambda: threedm.GyroBiasResponse(bias=[1.5, -2.25, 0.375])),
    ("threedm.CaptureGyroBias", lambda: threedm.CaptureGyroBias(averaging_time_ms=65)),
    (
        "threedm.MagHardIronOffset_gx5_45",
        lambda: threedm.MagHardIronOffset_gx5_45(
            function=types.FunctionSelector.WRITE_NO_ACK, offset=[1024.0, -0.0, 1.5]
        ),
    ),
    (
        "threedm.MagHardIronOffset_cv7_ins",
        lambda: threedm.MagHardIronOffset_cv7_ins(function=types.FunctionSelector.DEFAULT, offset=[-0.0, 1.5, -2.25]),
    ),
    ("threedm.MagHardIronOffsetResponse", lambda: threedm.MagHardIronOffsetResponse(offset=[0.375, 1024.0, -0.0])),
    (
        "threedm.MagSoftIronMatrix_gx5_45",
        lambda: threedm.MagSoftIronMatrix_gx5_45(
            function=types.FunctionSelector.WRITE_NO_ACK,
            matrix=[1.5, -2.25, 0.375, 1024.0, -0.0, 1.5, -2.25, 0.375, 1024.0],
        ),
    ),
    (
        "threedm.MagSoftIronMatrix_cv7_ins",
        lambda: threedm.MagSoftIronMatrix_cv7_ins(
            function=types.FunctionSelector.DEFAULT, matrix=[-0.0, 1.5, -2.25, 0.375, 1024.0, -0.0, 1.5, -2.25, 0.375]
        ),
    ),
    (
        "threedm.MagSoftIronMatrixResponse",
        lambda: threedm.MagSoftIronMatrixResponse(matrix=[-0.0, 1.5, -2.25, 0.375, 1024.0, -0.0, 1.5, -2.25, 0.375]),
    ),
    (
        "threedm.ConingScullingEnable",
        lambda: threedm.ConingScullingEnable(function=types.FunctionSelector.DEFAULT, enable=True),
    ),
    ("threedm.ConingScullingEnableResponse", lambda: threedm.ConingScullingEnableResponse(enable=False)),
    ("threedm.UartBaudrate", lambda: threedm.UartBaudrate(function=types.FunctionSelector.DEFAULT, baud=11)),
    ("threedm.UartBaudrateResponse", lambda: threedm.UartBaudrateResponse(baud=176)),
    (
        "threedm.GpioConfig",
        lambda: threedm.GpioConfig(
            function=types.FunctionSelector.DEFAULT,
            pin=41,
            feature=types.GpioFeature.UNUSED,
            behavior=types.GpioBehaviorUnused(behavior=types.GpioUnusedBehavior.UNUSED),
            pin_mode=types.GpioPinMode(0x2),
        ),
    ),
    (
        "threedm.GpioConfigResponse",
        lambda: threedm.GpioConfigResponse(
            pin=15,
            feature=types.GpioFeature.UNUSED,
            behavior=types.GpioBehaviorUnused(behavior=types.GpioUnusedBehavior.UNUSED),
            pin_mode=types.GpioPinMode(0x2),
        ),
    ),
    ("threedm.GpioState", lambda: threedm.GpioState(function=types.FunctionSelector.READ, pin=92, state=True)),
    ("threedm.GpioStateResponse", lambda: threedm.GpioStateResponse(pin=114, state=False)),
    (
        "threedm.OdometerConfig",
        lambda: threedm.OdometerConfig(
            function=types.FunctionSelector.DEFAULT, mode=types.OdometerMode.DISABLED, scaling=0.375, uncertainty=1024.0
        ),
    ),
    (
        "threedm.OdometerConfigResponse",
        lambda: threedm.OdometerConfigResponse(mode=types.OdometerMode.DISABLED, scaling=0.375, uncertainty=1024.0),
    ),
    (
        "threedm.AdvancedLowpassFilter",
        lambda: threedm.AdvancedLowpassFilter(
            function=types.FunctionSelector.DEFAULT,
            target_descriptor=82,
            enable=True,
            manual=False,
            frequency=193,
            reserved=230,
        ),
    ),
    (
        "threedm.AdvancedLowpassFilterResponse",
        lambda: threedm.AdvancedLowpassFilterResponse(
            target_descriptor=175, enable=False, manual=True, frequency=35, reserved=72
        ),
    ),
    (
        "threedm.ComplementaryFilter",
        lambda: threedm.ComplementaryFilter(
            function=types.FunctionSelector.DEFAULT,
            pitch_roll_enable=False,
            heading_enable=True,
            pitch_roll_time_constant=1024.0,
            heading_time_constant=-0.0,
        ),
    ),
    (
        "threedm.ComplementaryFilterResponse",
        lambda: threedm.ComplementaryFilterResponse(
            pitch_roll_enable=False, heading_enable=True, pitch_roll_time_constant=1024.0, heading_time_constant=-0.0
        ),
    ),
    (
        "threedm.SensorRange",
        lambda: threedm.SensorRange(
            function=types.FunctionSelector.DEFAULT, sensor=types.SensorRangeType.ACCEL, setting=221
        ),
    ),
    (
        "threedm.SensorRangeResponse",
        lambda: threedm.SensorRangeResponse(sensor=types.SensorRangeType.ACCEL, setting=16),
    ),
    ("threedm.GetCalibratedSensorRanges", lambda: threedm.GetCalibratedSensorRanges(sensor=types.SensorRangeType.GYRO)),
    (
        "threedm.CalibratedSensorRanges",
        lambda: threedm.CalibratedSensorRanges(
            sensor=types.SensorRangeType.ACCEL,
            num_ranges=2,
            ranges=[types.SensorRangeEntry(setting=137, range=-0.0), types.SensorRangeEntry(setting=248, range=0.375)],
        ),
    ),
    (
        "threedm.LowpassFilter",
        lambda: threedm.LowpassFilter(
            function=types.FunctionSelector.DEFAULT,
            desc_set=176,
            field_desc=213,
            enable=True,
            manual=False,
            frequency=0.375,
        ),
    ),
    (
        "threedm.LowpassFilterResponse",
        lambda: threedm.LowpassFilterResponse(desc_set=91, field_desc=128, enable=False, manual=True, frequency=-0.0),
    ),
    (
        "threedm.PollImuData",
        lambda: threedm.PollImuData(
            option=types.Gx5PollOption.NORMAL,
            num_descriptors=2,
            descriptors=[
                types.Gx5PollDescriptor(descriptor=47, reserved=84),
                types.Gx5PollDescriptor(descriptor=158, reserved=195),
            ],
        ),
    ),
    (
        "threedm.PollGnssData",
        lambda: threedm.PollGnssData(
            option=types.Gx5PollOption.SUPPRESS_ACK,
            num_descriptors=2,
            descriptors=[
                types.Gx5PollDescriptor(descriptor=209, reserved=246),
                types.Gx5PollDescriptor(descriptor=69, reserved=106),
            ],
        ),
    ),
    (
        "threedm.PollFilterData",
        lambda: threedm.PollFilterData(
            option=types.Gx5PollOption.SUPPRESS_ACK,
            num_descriptors=2,
            descriptors=[
                types.Gx5PollDescriptor(descriptor=147, reserved=184),
                types.Gx5PollDescriptor(descriptor=7, reserved=44),
            ],
        ),
    ),
    (
        "threedm.PollNmeaData",
        lambda: threedm.PollNmeaData(
            suppress_ack=False,
            count=2,
            format_entries=[
                types.NmeaMessage(message_id=82, talker_id=119, source_desc_set=156, decimation=193),
                types.NmeaMessage(message_id=16, talker_id=53, source_desc_set=90, decimation=127),
            ],
        ),
    ),
    (
        "threedm.PollData",
        lambda: threedm.PollData(desc_set=130, suppress_ack=False, num_descriptors=2, descriptors=[204, 241]),
    ),
    ("threedm.GetImuBaseRate", lambda: threedm.GetImuBaseRate()),
    ("threedm.ImuBaseRate", lambda: threedm.ImuBaseRate(rate=210)),
    ("threedm.GetGnssBaseRate", lambda: threedm.GetGnssBaseRate()),
    ("threedm.GnssBaseRate", lambda: threedm.GnssBaseRate(rate=198)),
    ("threedm.GetFilterBaseRate", lambda: threedm.GetFilterBaseRate()),
    ("threedm.FilterBaseRate", lambda: threedm.FilterBaseRate(rate=226)),
    ("threedm.GetBaseRate", lambda: threedm.GetBaseRate(desc_set=147)),
    ("threedm.BaseRate", lambda: threedm.BaseRate(desc_set=93, rate=130)),
    (
        "threedm.ImuMessageFormat",
        lambda: threedm.ImuMessageFormat(
            function=types.FunctionSelector.DEFAULT,
            num_descriptors=2,
            descriptors=[
                types.DescriptorRate(descriptor=124, decimation=161),
                types.DescriptorRate(descriptor=235, decimation=21),
            ],
        ),
    ),
    (
        "threedm.ImuMessageFormatResponse",
        lambda: threedm.ImuMessageFormatResponse(
            num_descriptors=2,
            descriptors=[
                types.DescriptorRate(descriptor=64, decimation=101),
                types.DescriptorRate(descriptor=175, decimation=212),
            ],
        ),
    ),
    (
        "threedm.GnssMessageFormat",
        lambda: threedm.GnssMessageFormat(
            function=types.FunctionSelector.DEFAULT,
            num_descriptors=2,
            descriptors=[
                types.DescriptorRate(descriptor=82, decimation=119),
                types.DescriptorRate(descriptor=193, decimation=230),
            ],
        ),
    ),
    (
        "threedm.GnssMessageFormatResponse",
        lambda: threedm.GnssMessageFormatResponse(
            num_descriptors=2,
            descriptors=[
                types.DescriptorRate(descriptor=136, decimation=173),
                types.DescriptorRate(descriptor=247, decimation=33),
            ],
        ),
    ),
    (
        "threedm.FilterMessageFormat",
        lambda: threedm.FilterMessageFormat(
            function=types.FunctionSelector.DEFAULT,
            num_descriptors=2,
            descriptors=[
                types.DescriptorRate(descriptor=225, decimation=11),
                types.DescriptorRate(descriptor=85, decimation=122),
            ],
        ),
    ),
    (
        "threedm.FilterMessageFormatResponse",
        lambda: threedm.FilterMessageFormatResponse(
            num_descriptors=2,
            descriptors=[
                types.DescriptorRate(descriptor=51, decimation=88),
                types.DescriptorRate(descriptor=162, decimation=199),
            ],
        ),
    ),
    (
        "threedm.NmeaMessageFormat",
        lambda: threedm.NmeaMessageFormat(
            function=types.FunctionSelector.DEFAULT,
            count=2,
            format_entries=[
                types.NmeaMessage(message_id=186, talker_id=223, source_desc_set=9, decimation=46),
                types.NmeaMessage(message_id=120, talker_id=157, source_desc_set=194, decimation=231),
            ],
        ),
    ),
    (
        "threedm.NmeaMessageFormatResponse",
        lambda: threedm.NmeaMessageFormatResponse(
            count=2,
            format_entries=[
                types.NmeaMessage(message_id=3, talker_id=40, source_desc_set=77, decimation=114),
                types.NmeaMessage(message_id=188, talker_id=225, source_desc_set=11, decimation=48),
            ],
        ),
    ),
    (
        "threedm.MessageFormat",
        lambda: threedm.MessageFormat(
            function=types.FunctionSelector.DEFAULT,
            desc_set=142,
            num_descriptors=2,
            descriptors=[
                types.DescriptorRate(descriptor=216, decimation=2),
                types.DescriptorRate(descriptor=76, decimation=113),
            ],
        ),
    ),
    (
        "threedm.MessageFormatResponse",
        lambda: threedm.MessageFormatResponse(
            desc_set=40,
            num_descriptors=2,
            descriptors=[
                types.DescriptorRate(descriptor=114, decimation=151),
                types.DescriptorRate(descriptor=225, decimation=11),
            ],
        ),
    ),
    (
        "threedm.FactoryStreaming",
        lambda: threedm.FactoryStreaming(action=types.FactoryStreamingAction.OVERWRITE, reserved=119),
    ),
    (
        "threedm.DataStreamControl_gx5_45",
        lambda: threedm.DataStreamControl_gx5_45(
            function=types.FunctionSelector.DEFAULT, device_selector=types.Gx5StreamSelector.IMU, enable=29
        ),
    ),
    (
        "threedm.DataStreamControl_cv7_ins",
        lambda: threedm.DataStreamControl_cv7_ins(function=types.FunctionSelector.DEFAULT, desc_set=246, enable=False),
    ),
    (
        "threedm.DataStreamControlResponse_gx5_45",
        lambda: threedm.DataStreamControlResponse_gx5_45(device_selector=types.Gx5StreamSelector.IMU, enabled=179),
    ),
    (
        "threedm.DataStreamControlResponse_cv7_ins",
        lambda: threedm.DataStreamControlResponse_cv7_ins(desc_set=9, enabled=False),
    ),
    ("threedm.RawRtcmMessage", lambda: threedm.RawRtcmMessage(data=[80, 117])),
    (
        "threedm.GnssConstellationSettings",
        lambda: threedm.GnssConstellationSettings(
            function=types.FunctionSelector.DEFAULT,
            max_channels=35,
            config_count=2,
            settings=[
                types.ConstellationSettings(
                    constellation_id=types.Gx5ConstellationId.SBAS,
                    enable=146,
                    reserved_channels=183,
                    max_channels=220,
                    option_flags=types.ConstellationOptions(0x1),
                ),
                types.ConstellationSettings(
                    constellation_id=types.Gx5ConstellationId.SBAS,
                    enable=117,
                    reserved_channels=154,
                    max_channels=191,
                    option_flags=types.ConstellationOptions(0x1),
                ),
            ],
        ),
    ),
    (
        "threedm.GnssConstellationSettingsResponse",
        lambda: threedm.GnssConstellationSettingsResponse(
            max_channels_available=18,
            max_channels=55,
            config_count=2,
            settings=[
                types.ConstellationSettings(
                    constellation_id=types.Gx5ConstellationId.GLONASS,
                    enable=166,
                    reserved_channels=203,
                    max_channels=240,
                    option_flags=types.ConstellationOptions(0x1),
                ),
                types.ConstellationSettings(
                    constellation_id=types.Gx5ConstellationId.GLONASS,
                    enable=137,
                    reserved_channels=174,
                    max_channels=211,
                    option_flags=types.ConstellationOptions(0x1),
                ),
            ],
        ),
    ),
    (
        "threedm.GnssSbasSettings",
        lambda: threedm.GnssSbasSettings(
            function=types.FunctionSelector.DEFAULT,
            enable_sbas=81,
            sbas_options=types.SbasOptions(0x2),
            num_included_prns=2,
            included_prns=[155, 192],
        ),
    ),
    (
        "threedm.GnssSbasSettingsResponse",
        lambda: threedm.GnssSbasSettingsResponse(
            enable_sbas=223, sbas_options=types.SbasOptions(0x2), num_included_prns=2, included_prns=[46, 83]
        ),
    ),
    (
        "threedm.GnssAssistedFixControl",
        lambda: threedm.GnssAssistedFixControl(
            function=types.FunctionSelector.DEFAULT, option=types.AssistedFixOption.ENABLED, flags=99
        ),
    ),
    (
        "threedm.GnssAssistedFixControlResponse",
        lambda: threedm.GnssAssistedFixControlResponse(option=types.AssistedFixOption.ENABLED, flags=137),
    ),
    (
        "threedm.GnssAssistTimeUpdate",
        lambda: threedm.GnssAssistTimeUpdate(
            function=types.FunctionSelector.READ, tow=1e16, week_number=30, accuracy=-0.0
        ),
    ),
    (
        "threedm.GnssAssistTimeUpdateResponse",
        lambda: threedm.GnssAssistTimeUpdateResponse(tow=123.456, week_number=240, accuracy=1.5),
    ),
    (
        "threedm.PpsSource",
        lambda: threedm.PpsSource(function=types.FunctionSelector.DEFAULT, source=types.PpsSource.DISABLED),
    ),
    ("threedm.PpsSourceResponse", lambda: threedm.PpsSourceResponse(source=types.PpsSource.GPIO)),
    ("threedm.GetSupportedEvents", lambda: threedm.GetSupportedEvents(query=types.SupportedEventsQuery.ACTION_TYPES)),
    (
        "threedm.SupportedEvents",
        lambda: threedm.SupportedEvents(
            query=types.SupportedEventsQuery.TRIGGER_TYPES,
            info=types.SupportedTriggers(
                max_instances=1,
                num_entries=2,
                entries=[
                    types.SupportedTriggerType(type=types.TriggerType.GPIO, count=112),
                    types.SupportedTriggerType(type=types.TriggerType.NONE, count=223),
                ],
            ),
        ),
    ),
    (
        "threedm.DeviceStatus",
        lambda: threedm.DeviceStatus(model_number=114, status_selector=types.DeviceStatusSelector.BASIC),
    ),
    (
        "threedm.DeviceStatusResponse",
        lambda: threedm.DeviceStatusResponse(
            model_number=138,
            status_selector=types.DeviceStatusSelector.BASIC,
            status=types.Gx5BasicStatus(status_flags=175, system_state=212, system_timer=249),
        ),
    ),
    ("filter.ResetFilter", lambda: filter.ResetFilter()),
    ("filter.SetInitialAttitude", lambda: filter.SetInitialAttitude(roll=1.5, pitch=-2.25, heading=0.375)),
    ("filter.SetInitialHeading", lambda: filter.SetInitialHeading(heading=-2.25)),
    ("filter.RunFilter", lambda: filter.RunFilter()),
    (
        "filter.VehicleDynamicsMode",
        lambda: filter.VehicleDynamicsMode(
            function=types.FunctionSelector.DEFAULT, mode=types.VehicleDynamicsMode.PORTABLE
        ),
    ),
    (
        "filter.VehicleDynamicsModeResponse",
        lambda: filter.VehicleDynamicsModeResponse(mode=types.VehicleDynamicsMode.PORTABLE),
    ),
    (
        "filter.SensorToVehicleTransform",
        lambda: filter.SensorToVehicleTransform(
            function=types.FunctionSelector.DEFAULT, roll=1024.0, pitch=-0.0, yaw=1.5
        ),
    ),
    (
        "filter.SensorToVehicleTransformResponse",
        lambda: filter.SensorToVehicleTransformResponse(roll=-0.0, pitch=1.5, yaw=-2.25),
    ),
    (
        "filter.SensorToVehicleOffset",
        lambda: filter.SensorToVehicleOffset(function=types.FunctionSelector.DEFAULT, offset=[0.375, 1024.0, -0.0]),
    ),
    (
        "filter.SensorToVehicleOffsetResponse",
        lambda: filter.SensorToVehicleOffsetResponse(offset=[0.375, 1024.0, -0.0]),
    ),
    (
        "filter.AntennaOffset",
        lambda: filter.AntennaOffset(function=types.FunctionSelector.DEFAULT, offset=[1024.0, -0.0, 1.5]),
    ),
    ("filter.AntennaOffsetResponse", lambda: filter.AntennaOffsetResponse(offset=[1024.0, -0.0, 1.5])),
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
            function=types.FunctionSelector.DEFAULT, source=types.FilterGnssSource.INTERNAL_1
        ),
    ),
    (
        "filter.GnssSourceControlResponse",
        lambda: filter.GnssSourceControlResponse(source=types.FilterGnssSource.ALL_INTERNAL),
    ),
    (
        "filter.ExternalGnssUpdate",
        lambda: filter.ExternalGnssUpdate(
            gps_tow=1e16,
            gps_week=142,
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
            function=types.FunctionSelector.DEFAULT, source=types.HeadingUpdateSource.MAGNETOMETER_AND_EXTERNAL
        ),
    ),
    (
        "filter.HeadingUpdateControlResponse",
        lambda: filter.HeadingUpdateControlResponse(source=types.HeadingUpdateSource.MAGNETOMETER_AND_EXTERNAL),
    ),
    ("filter.AutoInitControl", lambda: filter.AutoInitControl(function=types.FunctionSelector.DEFAULT, enable=165)),
    ("filter.AutoInitControlResponse", lambda: filter.AutoInitControlResponse(enable=236)),
    (
        "filter.AccelNoise",
        lambda: filter.AccelNoise(function=types.FunctionSelector.DEFAULT, noise=[1.5, -2.25, 0.375]),
    ),
    ("filter.AccelNoiseResponse", lambda: filter.AccelNoiseResponse(noise=[-0.0, 1.5, -2.25])),
    (
        "filter.GyroNoise",
        lambda: filter.GyroNoise(function=types.FunctionSelector.DEFAULT, noise=[0.375, 1024.0, -0.0]),
    ),
    ("filter.GyroNoiseResponse", lambda: filter.GyroNoiseResponse(noise=[0.375, 1024.0, -0.0])),
    (
        "filter.AccelBiasModel",
        lambda: filter.AccelBiasModel(
            function=types.FunctionSelector.DEFAULT, beta=[0.375, 1024.0, -0.0], noise=[1.5, -2.25, 0.375]
        ),
    ),
    (
        "filter.AccelBiasModelResponse",
        lambda: filter.AccelBiasModelResponse(beta=[-0.0, 1.5, -2.25], noise=[0.375, 1024.0, -0.0]),
    ),
    (
        "filter.GyroBiasModel",
        lambda: filter.GyroBiasModel(
            function=types.FunctionSelector.DEFAULT, beta=[-0.0, 1.5, -2.25], noise=[0.375, 1024.0, -0.0]
        ),
    ),
    (
        "filter.GyroBiasModelResponse",
        lambda: filter.GyroBiasModelResponse(beta=[-0.0, 1.5, -2.25], noise=[0.375, 1024.0, -0.0]),
    ),
    (
        "filter.ZuptControl",
        lambda: filter.ZuptControl(function=types.FunctionSelector.DEFAULT, enable=43, threshold=-0.0),
    ),
    ("filter.ZuptControlResponse", lambda: filter.ZuptControlResponse(enable=120, threshold=1024.0)),
    (
        "filter.ExternalHeadingUpdateWithTime",
        lambda: filter.ExternalHeadingUpdateWithTime(
            gps_tow=1e16,
            gps_week=140,
            heading=-0.0,
            heading_uncertainty=1.5,
            type=types.ExternalHeadingType.TRUE_HEADING,
        ),
    ),
    (
        "filter.ZeroAngularRateUpdateControl",
        lambda: filter.ZeroAngularRateUpdateControl(function=types.FunctionSelector.DEFAULT, enable=32, threshold=1.5),
    ),
    (
        "filter.ZeroAngularRateUpdateControlResponse",
        lambda: filter.ZeroAngularRateUpdateControlResponse(enable=33, threshold=-0.0),
    ),
    (
        "filter.TareOrientation",
        lambda: filter.TareOrientation(function=types.FunctionSelector.DEFAULT, axes=types.TareAxes(0x1)),
    ),
    ("filter.CommandedZupt", lambda: filter.CommandedZupt()),
    ("filter.CommandedZeroAngularRateUpdate", lambda: filter.CommandedZeroAngularRateUpdate()),
    (
        "filter.MagCaptureAutoCalibration",
        lambda: filter.MagCaptureAutoCalibration(function=types.FunctionSelector.SAVE),
    ),
    (
        "filter.GravityNoiseStdDev",
        lambda: filter.GravityNoiseStdDev(function=types.FunctionSelector.DEFAULT, noise=[1024.0, -0.0, 1.5]),
    ),
    ("filter.GravityNoiseStdDevResponse", lambda: filter.GravityNoiseStdDevResponse(noise=[1.5, -2.25, 0.375])),
    (
        "filter.PressureAltitudeNoiseStdDev",
        lambda: filter.PressureAltitudeNoiseStdDev(function=types.FunctionSelector.DEFAULT, noise=-2.25),
    ),
    ("filter.PressureAltitudeNoiseStdDevResponse", lambda: filter.PressureAltitudeNoiseStdDevResponse(noise=-0.0)),
    (
        "filter.HardIronOffsetNoise",
        lambda: filter.HardIronOffsetNoise(function=types.FunctionSelector.DEFAULT, noise=[-0.0, 1.5, -2.25]),
    ),
    ("filter.HardIronOffsetNoiseResponse", lambda: filter.HardIronOffsetNoiseResponse(noise=[-0.0, 1.5, -2.25])),
    (
        "filter.SoftIronMatrixNoise",
        lambda: filter.SoftIronMatrixNoise(
            function=types.FunctionSelector.DEFAULT, noise=[-0.0, 1.5, -2.25, 0.375, 1024.0, -0.0, 1.5, -2.25, 0.375]
        ),
    ),
    (
        "filter.SoftIronMatrixNoiseResponse",
        lambda: filter.SoftIronMatrixNoiseResponse(noise=[-2.25, 0.375, 1024.0, -0.0, 1.5, -2.25, 0.375, 1024.0, -0.0]),
    ),
    (
        "filter.MagNoiseStdDev",
        lambda: filter.MagNoiseStdDev(function=types.FunctionSelector.DEFAULT, noise=[-0.0, 1.5, -2.25]),
    ),
    ("filter.MagNoiseStdDevResponse", lambda: filter.MagNoiseStdDevResponse(noise=[1024.0, -0.0, 1.5])),
    (
        "filter.DeclinationSource",
        lambda: filter.DeclinationSource(
            function=types.FunctionSelector.DEFAULT, source=types.MagneticParamSource.WMM, declination=0.375
        ),
    ),
    (
        "filter.DeclinationSourceResponse",
        lambda: filter.DeclinationSourceResponse(source=types.MagneticParamSource.NONE, declination=-2.25),
    ),
    (
        "filter.GravityMagnitudeAdaptiveMeasurement",
        lambda: filter.GravityMagnitudeAdaptiveMeasurement(
            function=types.FunctionSelector.DEFAULT,
            mode=types.AdaptiveMeasurementMode.DISABLED,
            frequency=-0.0,
            low_limit=1.5,
            high_limit=-2.25,
            low_limit_uncertainty=0.375,
            high_limit_uncertainty=1024.0,
            minimum_uncertainty=-0.0,
        ),
    ),
    (
        "filter.GravityMagnitudeAdaptiveMeasurementResponse",
        lambda: filter.GravityMagnitudeAdaptiveMeasurementResponse(
            mode=types.AdaptiveMeasurementMode.AUTO,
            frequency=0.375,
            low_limit=1024.0,
            high_limit=-0.0,
            low_limit_uncertainty=1.5,
            high_limit_uncertainty=-2.25,
            minimum_uncertainty=0.375,
        ),
    ),
    (
        "filter.MagMagnitudeAdaptiveMeasurement",
        lambda: filter.MagMagnitudeAdaptiveMeasurement(
            function=types.FunctionSelector.DEFAULT,
            mode=types.AdaptiveMeasurementMode.FIXED,
            frequency=-2.25,
            low_limit=0.375,
            high_limit=1024.0,
            low_limit_uncertainty=-0.0,
            high_limit_uncertainty=1.5,
            minimum_uncertainty=-2.25,
        ),
    ),
    (
        "filter.MagMagnitudeAdaptiveMeasurementResponse",
        lambda: filter.MagMagnitudeAdaptiveMeasurementResponse(
            mode=types.AdaptiveMeasurementMode.DISABLED,
            frequency=1.5,
            low_limit=-2.25,
            high_limit=0.375,
            low_limit_uncertainty=1024.0,
            high_limit_uncertainty=-0.0,
            minimum_uncertainty=1.5,
        ),
    ),
    (
        "filter.MagDipAngleAdaptiveMeasurement",
        lambda: filter.MagDipAngleAdaptiveMeasurement(
            function=types.FunctionSelector.DEFAULT,
            mode=types.AdaptiveMeasurementMode.DISABLED,
            frequency=-0.0,
            high_limit=1.5,
            high_limit_uncertainty=-2.25,
            minimum_uncertainty=0.375,
        ),
    ),
    (
        "filter.MagDipAngleAdaptiveMeasurementResponse",
        lambda: filter.MagDipAngleAdaptiveMeasurementResponse(
            mode=types.AdaptiveMeasurementMode.DISABLED,
            frequency=-0.0,
            high_limit=1.5,
            high_limit_uncertainty=-2.25,
            minimum_uncertainty=0.375,
        ),
    ),
    (
        "filter.AltitudeAidingControl",
        lambda: filter.AltitudeAidingControl(
            function=types.FunctionSelector.DEFAULT, source=types.AltitudeAidingSource.PRESSURE
        ),
    ),
    (
        "filter.AltitudeAidingControlResponse",
        lambda: filter.AltitudeAidingControlResponse(source=types.AltitudeAidingSource.PRESSURE),
    ),
    (
        "filter.PitchRollAidingControl",
        lambda: filter.PitchRollAidingControl(
            function=types.FunctionSelector.DEFAULT, source=types.PitchRollAidingSource.NONE
        ),
    ),
    (
        "filter.PitchRollAidingControlResponse",
        lambda: filter.PitchRollAidingControlResponse(source=types.PitchRollAidingSource.NONE),
    ),
    (
        "filter.InclinationSource",
        lambda: filter.InclinationSource(
            function=types.FunctionSelector.DEFAULT, source=types.MagneticParamSource.WMM, inclination=1.5
        ),
    ),
    (
        "filter.InclinationSourceResponse",
        lambda: filter.InclinationSourceResponse(source=types.MagneticParamSource.WMM, inclination=0.375),
    ),
    (
        "filter.MagneticFieldMagnitudeSource",
        lambda: filter.MagneticFieldMagnitudeSource(
            function=types.FunctionSelector.DEFAULT, source=types.MagneticParamSource.WMM, magnitude=1.5
        ),
    ),
    (
        "filter.MagneticFieldMagnitudeSourceResponse",
        lambda: filter.MagneticFieldMagnitudeSourceResponse(source=types.MagneticParamSource.NONE, magnitude=-0.0),
    ),
    (
        "filter.AidingMeasurementControl",
        lambda: filter.AidingMeasurementControl(
            function=types.FunctionSelector.DEFAULT, source=types.AidingMeasurementSource.ALL, enable=False
        ),
    ),
    (
        "filter.AidingMeasurementControlResponse",
        lambda: filter.AidingMeasurementControlResponse(
            source=types.AidingMeasurementSource.EXTERNAL_MAGNETOMETER, enable=False
        ),
    ),
    (
        "filter.InitializationConfiguration",
        lambda: filter.InitializationConfiguration(
            function=types.FunctionSelector.DEFAULT,
            wait_for_run_command=170,
            initial_cond_src=types.FilterInitialConditionSource.AUTO_POS_VEL,
            auto_heading_alignment_selector=types.HeadingAlignmentMethods(0x8),
            initial_heading=1024.0,
            initial_pitch=-0.0,
            initial_roll=1.5,
            initial_position=[-2.25, 0.375, 1024.0],
            initial_velocity=[-0.0, 1.5, -2.25],
            reference_frame_selector=types.FilterReferenceFrame.LLH,
        ),
    ),
    (
        "filter.InitializationConfigurationResponse",
        lambda: filter.InitializationConfigurationResponse(
            wait_for_run_command=100,
            initial_cond_src=types.FilterInitialConditionSource.AUTO_POS_VEL_ATT,
            auto_heading_alignment_selector=types.HeadingAlignmentMethods(0x2),
            initial_heading=-0.0,
            initial_pitch=1.5,
            initial_roll=-2.25,
            initial_position=[0.375, 1024.0, -0.0],
            initial_velocity=[1.5, -2.25, 0.375],
            reference_frame_selector=types.FilterReferenceFrame.LLH,
        ),
    ),
    (
        "filter.AdaptiveFilterControl",
        lambda: filter.AdaptiveFilterControl(
            function=types.FunctionSelector.DEFAULT, level=types.AdaptiveFilterLevel.MODERATE, time_limit=45
        ),
    ),
    (
        "filter.AdaptiveFilterControlResponse",
        lambda: filter.AdaptiveFilterControlResponse(level=types.AdaptiveFilterLevel.CONSERVATIVE, time_limit=86),
    ),
    (
        "filter.MultiAntennaOffset",
        lambda: filter.MultiAntennaOffset(
            function=types.FunctionSelector.DEFAULT, receiver_id=220, antenna_offset=[-0.0, 1.5, -2.25]
        ),
    ),
    (
        "filter.MultiAntennaOffsetResponse",
        lambda: filter.MultiAntennaOffsetResponse(receiver_id=113, antenna_offset=[1024.0, -0.0, 1.5]),
    ),
    (
        "filter.RelativePositionConfiguration",
        lambda: filter.RelativePositionConfiguration(
            function=types.FunctionSelector.DEFAULT,
            source=types.RelativePositionSource.MANUAL,
            reference_frame_selector=types.FilterReferenceFrame.ECEF,
            reference_coordinates=[0.1, -2.5e-310, 1e16],
        ),
    ),
    (
        "filter.RelativePositionConfigurationResponse",
        lambda: filter.RelativePositionConfigurationResponse(
            source=types.RelativePositionSource.AUTO,
            reference_frame_selector=types.FilterReferenceFrame.LLH,
            reference_coordinates=[-2.5e-310, 1e16, 123.456],
        ),
    ),
    (
        "filter.ReferencePointLeverArm",
        lambda: filter.ReferencePointLeverArm(
            function=types.FunctionSelector.DEFAULT,
            ref_point_sel=types.ReferencePointSelector.VEH,
            lever_arm_offset=[0.375, 1024.0, -0.0],
        ),
    ),
    (
        "filter.ReferencePointLeverArmResponse",
        lambda: filter.ReferencePointLeverArmResponse(
            ref_point_sel=types.ReferencePointSelector.VEH, lever_arm_offset=[-2.25, 0.375, 1024.0]
        ),
    ),
    (
        "filter.SpeedLeverArm",
        lambda: filter.SpeedLeverArm(
            function=types.FunctionSelector.DEFAULT, source=164, lever_arm_offset=[0.375, 1024.0, -0.0]
        ),
    ),
    (
        "filter.SpeedLeverArmResponse",
        lambda: filter.SpeedLeverArmResponse(source=187, lever_arm_offset=[1024.0, -0.0, 1.5]),
    ),
    (
        "filter.WheeledVehicleConstraintControl",
        lambda: filter.WheeledVehicleConstraintControl(function=types.FunctionSelector.DEFAULT, enable=174),
    ),
    (
        "filter.WheeledVehicleConstraintControlResponse",
        lambda: filter.WheeledVehicleConstraintControlResponse(enable=195),
    ),
    (
        "filter.GnssAntennaCalibrationControl",
        lambda: filter.GnssAntennaCalibrationControl(
            function=types.FunctionSelector.DEFAULT, enable=184, max_offset=0.375
        ),
    ),
    (
        "filter.GnssAntennaCalibrationControlResponse",
        lambda: filter.GnssAntennaCalibrationControlResponse(enable=144, max_offset=-0.0),
    ),
    ("gnss.ReceiverInfo", lambda: gnss.ReceiverInfo()),
    (
        "gnss.ReceiverInfoResponse",
        lambda: gnss.ReceiverInfoResponse(
            num_receivers=2,
            receiver_info=[
                types.GnssReceiverInfoEntry(
                    receiver_id=147,
                    mip_data_descriptor_set=184,
                    description=b"jkl\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00",
                ),
                types.GnssReceiverInfoEntry(
                    receiver_id=44,
                    mip_data_descriptor_set=81,
                    description=b"nop\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00",
                ),
            ],
        ),
    ),
    (
        "gnss.SignalConfiguration",
        lambda: gnss.SignalConfiguration(
            function=types.FunctionSelector.DEFAULT,
            gps_enable=types.GnssGpsSignals(0x4),
            glonass_enable=types.GnssGlonassSignals(0x1),
            galileo_enable=types.GnssGalileoSignals(0x2),
            beidou_enable=types.GnssBeidouSignals(0x4),
            reserved=[112, 149, 186, 223],
        ),
    ),
    (
        "gnss.SignalConfigurationResponse",
        lambda: gnss.SignalConfigurationResponse(
            gps_enable=types.GnssGpsSignals(0x2),
            glonass_enable=types.GnssGlonassSignals(0x2),
            galileo_enable=types.GnssGalileoSignals(0x1),
            beidou_enable=types.GnssBeidouSignals(0x2),
            reserved=[212, 249, 35, 72],
        ),
    ),
    (
        "gnss.SpartnConfiguration",
        lambda: gnss.SpartnConfiguration(
            function=types.FunctionSelector.DEFAULT,
            enable=234,
            type=types.SpartnConnectionType.L_BAND,
            current_key_tow=57,
            current_key_week=94,
            current_key=b"wxy\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00",
            next_key_tow=168,
            next_key_week=205,
            next_key=b"zab\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00",
        ),
    ),
    (
        "gnss.SpartnConfigurationResponse",
        lambda: gnss.SpartnConfigurationResponse(
            enable=62,
            type=types.SpartnConnectionType.NONE,
            current_key_tow=136,
            current_key_week=173,
            current_key=b"bcd\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00",
            next_key_tow=247,
            next_key_week=33,
            next_key=b"efg\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00",
        ),
    ),
    (
        "aiding.FrameConfig",
        lambda: aiding.FrameConfig(
            function=types.FunctionSelector.DEFAULT,
            frame_id=241,
            format=types.AidingFrameFormat.EULER,
            tracking_enabled=True,
            translation=[1.5, -2.25, 0.375],
            rotation=types.AidingFrameEuler(euler=[1024.0, -0.0, 1.5]),
        ),
    ),
    (
        "aiding.FrameConfigResponse",
        lambda: aiding.FrameConfigResponse(
            frame_id=146,
            format=types.AidingFrameFormat.EULER,
            tracking_enabled=False,
            translation=[-0.0, 1.5, -2.25],
            rotation=types.AidingFrameEuler(euler=[0.375, 1024.0, -0.0]),
        ),
    ),
    (
        "aiding.EchoControl",
        lambda: aiding.EchoControl(function=types.FunctionSelector.DEFAULT, mode=types.AidingEchoMode.STANDARD),
    ),
    ("aiding.EchoControlResponse", lambda: aiding.EchoControlResponse(mode=types.AidingEchoMode.STANDARD)),
    (
        "aiding.EcefPosition",
        lambda: aiding.EcefPosition(
            time=types.AidingTime(timebase=types.AidingTimebase.INTERNAL_REFERENCE, reserved=90, nanoseconds=127),
            frame_id=164,
            position=[-0.0, 0.1, -2.5e-310],
            uncertainty=[0.375, 1024.0, -0.0],
            valid_flags=types.AidingVectorValidFlags(0x2),
        ),
    ),
    (
        "aiding.LlhPosition",
        lambda: aiding.LlhPosition(
            time=types.AidingTime(timebase=types.AidingTimebase.EXTERNAL_TIME, reserved=67, nanoseconds=104),
            frame_id=141,
            latitude=0.1,
            longitude=-2.5e-310,
            height=1e16,
            uncertainty=[1024.0, -0.0, 1.5],
            valid_flags=types.AidingLlhValidFlags(0x4),
        ),
    ),
    (
        "aiding.HeightAboveEllipsoid",
        lambda: aiding.HeightAboveEllipsoid(
            time=types.AidingTime(timebase=types.AidingTimebase.TIME_OF_ARRIVAL, reserved=145, nanoseconds=182),
            frame_id=219,
            height=0.375,
            uncertainty=1024.0,
            valid_flags=79,
        ),
    ),
    (
        "aiding.EcefVelocity",
        lambda: aiding.EcefVelocity(
            time=types.AidingTime(timebase=types.AidingTimebase.INTERNAL_REFERENCE, reserved=23, nanoseconds=60),
            frame_id=97,
            velocity=[0.375, 1024.0, -0.0],
            uncertainty=[1.5, -2.25, 0.375],
            valid_flags=types.AidingVectorValidFlags(0x2),
        ),
    ),
    (
        "aiding.NedVelocity",
        lambda: aiding.NedVelocity(
            time=types.AidingTime(timebase=types.AidingTimebase.EXTERNAL_TIME, reserved=134, nanoseconds=171),
            frame_id=208,
            velocity=[0.375, 1024.0, -0.0],
            uncertainty=[1.5, -2.25, 0.375],
            valid_flags=types.AidingVectorValidFlags(0x4),
        ),
    ),
    (
        "aiding.BodyFrameVelocity",
        lambda: aiding.BodyFrameVelocity(
            time=types.AidingTime(timebase=types.AidingTimebase.INTERNAL_REFERENCE, reserved=56, nanoseconds=93),
            frame_id=130,
            velocity=[0.375, 1024.0, -0.0],
            uncertainty=[1.5, -2.25, 0.375],
            valid_flags=types.AidingVectorValidFlags(0x2),
        ),
    ),
    (
        "aiding.TrueHeading",
        lambda: aiding.TrueHeading(
            time=types.AidingTime(timebase=types.AidingTimebase.TIME_OF_ARRIVAL, reserved=129, nanoseconds=166),
            frame_id=203,
            heading=1.5,
            uncertainty=-2.25,
            valid_flags=63,
        ),
    ),
    (
        "aiding.MagneticField",
        lambda: aiding.MagneticField(
            time=types.AidingTime(timebase=types.AidingTimebase.INTERNAL_REFERENCE, reserved=1, nanoseconds=38),
            frame_id=75,
            magnetic_field=[0.375, 1024.0, -0.0],
            uncertainty=[1.5, -2.25, 0.375],
            valid_flags=types.AidingVectorValidFlags(0x2),
        ),
    ),
    (
        "aiding.Pressure",
        lambda: aiding.Pressure(
            time=types.AidingTime(timebase=types.AidingTimebase.INTERNAL_REFERENCE, reserved=221, nanoseconds=7),
            frame_id=44,
            pressure=0.375,
            uncertainty=1024.0,
            valid_flags=155,
        ),
    ),
    (
        "system.CommunicationMode",
        lambda: system.CommunicationMode(function=types.FunctionSelector.DEFAULT, mode=types.SystemCommMode.STANDARD),
    ),
    (
        "system.CommunicationModeResponse",
        lambda: system.CommunicationModeResponse(mode=types.SystemCommMode.GNSS_DIRECT),
    ),
    ("sensor.ScaledAccel", lambda: sensor.ScaledAccel(scaled_accel=[-0.0, 1.5, -2.25])),
    ("sensor.ScaledGyro", lambda: sensor.ScaledGyro(scaled_gyro=[-2.25, 0.375, 1024.0])),
    ("sensor.ScaledMag", lambda: sensor.ScaledMag(scaled_mag=[-0.0, 1.5, -2.25])),
    ("sensor.DeltaTheta", lambda: sensor.DeltaTheta(delta_theta=[1.5, -2.25, 0.375])),
    ("sensor.DeltaVelocity", lambda: sensor.DeltaVelocity(delta_velocity=[1024.0, -0.0, 1.5])),
    (
        "sensor.CfOrientationMatrix",
        lambda: sensor.CfOrientationMatrix(m=[0.375, 1024.0, -0.0, 1.5, -2.25, 0.375, 1024.0, -0.0, 1.5]),
    ),
    ("sensor.CfQuaternion", lambda: sensor.CfQuaternion(q=[-0.0, 1.5, -2.25, 0.375])),
    ("sensor.CfEulerAngles", lambda: sensor.CfEulerAngles(roll=0.375, pitch=1024.0, yaw=-0.0)),
    ("sensor.CfStabilizedNorth", lambda: sensor.CfStabilizedNorth(stabilized_north=[1024.0, -0.0, 1.5])),
    ("sensor.CfStabilizedUp", lambda: sensor.CfStabilizedUp(stabilized_up=[-0.0, 1.5, -2.25])),
    (
        "sensor.GpsTimestamp",
        lambda: sensor.GpsTimestamp(tow=1e16, week_number=129, valid_flags=types.SensorGpsTimestampFlags(0x4)),
    ),
    (
        "sensor.TemperatureStatistics",
        lambda: sensor.TemperatureStatistics(min_temp=0.375, max_temp=1024.0, mean_temp=-0.0),
    ),
    ("sensor.ScaledPressure", lambda: sensor.ScaledPressure(scaled_pressure=1.5)),
    ("sensor.OverrangeStatus", lambda: sensor.OverrangeStatus(status=types.OverrangeStatusFlags(0x1))),
    (
        "sensor.OdometerData",
        lambda: sensor.OdometerData(speed=-0.0, uncertainty=1.5, valid_flags=types.OdometerDataValidFlags(0x1)),
    ),
    (
        "gnss_data.LlhPosition",
        lambda: gnss_data.LlhPosition(
            latitude=1e16,
            longitude=123.456,
            ellipsoid_height=-0.0,
            msl_height=0.1,
            horizontal_accuracy=-2.25,
            vertical_accuracy=0.375,
            valid_flags=types.GnssLlhPositionValidFlags(0x1),
        ),
    ),
    (
        "gnss_data.EcefPosition",
        lambda: gnss_data.EcefPosition(
            position=[-0.0, 0.1, -2.5e-310], position_accuracy=0.375, valid_flags=types.GnssEcefPositionValidFlags(0x1)
        ),
    ),
    (
        "gnss_data.NedVelocity",
        lambda: gnss_data.NedVelocity(
            velocity=[1.5, -2.25, 0.375],
            speed=1024.0,
            ground_speed=-0.0,
            heading=1.5,
            speed_accuracy=-2.25,
            heading_accuracy=0.375,
            valid_flags=types.GnssNedVelocityValidFlags(0x20),
        ),
    ),
    (
        "gnss_data.EcefVelocity",
        lambda: gnss_data.EcefVelocity(
            velocity=[0.375, 1024.0, -0.0], velocity_accuracy=1.5, valid_flags=types.GnssEcefVelocityValidFlags(0x1)
        ),
    ),
    (
        "gnss_data.Dop",
        lambda: gnss_data.Dop(
            gdop=1.5,
            pdop=-2.25,
            hdop=0.375,
            vdop=1024.0,
            tdop=-0.0,
            ndop=1.5,
            edop=-2.25,
            valid_flags=types.GnssDopValidFlags(0x20),
        ),
    ),
    (
        "gnss_data.UtcTime",
        lambda: gnss_data.UtcTime(
            year=112,
            month=149,
            day=186,
            hour=223,
            minute=9,
            second=46,
            millisecond=83,
            valid_flags=types.GnssUtcTimeValidFlagsGx5(0xFFFC),
        ),
    ),
    (
        "gnss_data.GpsTime",
        lambda: gnss_data.GpsTime(tow=1e16, week_number=228, valid_flags=types.GnssGpsTimeValidFlags(0x1)),
    ),
    (
        "gnss_data.ClockInfo",
        lambda: gnss_data.ClockInfo(
            bias=-2.5e-310, drift=1e16, accuracy_estimate=123.456, valid_flags=types.GnssClockInfoValidFlags(0x1)
        ),
    ),
    (
        "gnss_data.FixInfo",
        lambda: gnss_data.FixInfo(
            fix_type=types.GnssFixTypeGx5.FIX_2D,
            num_sv=65,
            fix_flags=types.GnssFixFlags(0x2),
            valid_flags=types.GnssFixInfoValidFlags(0x4),
        ),
    ),
    (
        "gnss_data.SvInfo",
        lambda: gnss_data.SvInfo(
            channel=136,
            sv_id=173,
            carrier_to_noise_ratio=210,
            azimuth=-92,
            elevation=33,
            sv_flags=types.GnssSvFlags(0x1),
            valid_flags=types.GnssSvInfoValidFlags(0x4),
        ),
    ),
    (
        "gnss_data.HardwareStatus",
        lambda: gnss_data.HardwareStatus(
            receiver_state=types.GnssReceiverState.ON,
            antenna_state=types.GnssAntennaState.OPEN,
            antenna_power=types.GnssAntennaPower.OFF,
            valid_flags=types.GnssHardwareStatusValidFlags(0x1),
        ),
    ),
    (
        "gnss_data.DgnssInfo",
        lambda: gnss_data.DgnssInfo(
            newest_age=-0.0,
            base_station_id=-76,
            base_station_status=types.GnssDgnssBaseStationStatus.UDRE_SCALE_1_0,
            num_channels=147,
            valid_flags=types.GnssDgnssInfoValidFlags(0x8),
        ),
    ),
    (
        "gnss_data.DgnssChannelStatus",
        lambda: gnss_data.DgnssChannelStatus(
            sv_id=190,
            age=1024.0,
            pseudorange_correction=-0.0,
            pseudorange_rate_correction=1.5,
            valid_flags=types.GnssDgnssChannelStatusValidFlags(0x2),
        ),
    ),
    (
        "filter_data.LlhPosition",
        lambda: filter_data.LlhPosition(
            latitude=1e16, longitude=123.456, ellipsoid_height=-0.0, valid_flags=types.FilterOutputValidFlags(0x1)
        ),
    ),
    (
        "filter_data.NedVelocity",
        lambda: filter_data.NedVelocity(
            north=1.5, east=-2.25, down=0.375, valid_flags=types.FilterOutputValidFlags(0x1)
        ),
    ),
    (
        "filter_data.AttitudeQuaternion",
        lambda: filter_data.AttitudeQuaternion(
            q=[1024.0, -0.0, 1.5, -2.25], valid_flags=types.FilterOutputValidFlags(0x1)
        ),
    ),
    (
        "filter_data.AttitudeDcm",
        lambda: filter_data.AttitudeDcm(
            dcm=[1.5, -2.25, 0.375, 1024.0, -0.0, 1.5, -2.25, 0.375, 1024.0],
            valid_flags=types.FilterOutputValidFlags(0x1),
        ),
    ),
    (
        "filter_data.EulerAngles",
        lambda: filter_data.EulerAngles(
            roll=1.5, pitch=-2.25, yaw=0.375, valid_flags=types.FilterOutputValidFlags(0x1)
        ),
    ),
    (
        "filter_data.GyroBias",
        lambda: filter_data.GyroBias(bias=[0.375, 1024.0, -0.0], valid_flags=types.FilterOutputValidFlags(0x1)),
    ),
    (
        "filter_data.AccelBias",
        lambda: filter_data.AccelBias(bias=[1024.0, -0.0, 1.5], valid_flags=types.FilterOutputValidFlags(0x1)),
    ),
    (
        "filter_data.LlhPositionUncertainty",
        lambda: filter_data.LlhPositionUncertainty(
            north=0.375, east=1024.0, down=-0.0, valid_flags=types.FilterOutputValidFlags(0x1)
        ),
    ),
    (
        "filter_data.NedVelocityUncertainty",
        lambda: filter_data.NedVelocityUncertainty(
            north=-0.0, east=1.5, down=-2.25, valid_flags=types.FilterOutputValidFlags(0x1)
        ),
    ),
    (
        "filter_data.EulerAnglesUncertainty",
        lambda: filter_data.EulerAnglesUncertainty(
            roll=-2.25, pitch=0.375, yaw=1024.0, valid_flags=types.FilterOutputValidFlags(0x1)
        ),
    ),
    (
        "filter_data.GyroBiasUncertainty",
        lambda: filter_data.GyroBiasUncertainty(
            bias_uncertainty=[-0.0, 1.5, -2.25], valid_flags=types.FilterOutputValidFlags(0x1)
        ),
    ),
    (
        "filter_data.AccelBiasUncertainty",
        lambda: filter_data.AccelBiasUncertainty(
            bias_uncertainty=[-2.25, 0.375, 1024.0], valid_flags=types.FilterOutputValidFlags(0x1)
        ),
    ),
    (
        "filter_data.LinearAccel",
        lambda: filter_data.LinearAccel(accel=[1.5, -2.25, 0.375], valid_flags=types.FilterOutputValidFlags(0x1)),
    ),
    (
        "filter_data.CompAngularRate",
        lambda: filter_data.CompAngularRate(gyro=[-0.0, 1.5, -2.25], valid_flags=types.FilterOutputValidFlags(0x1)),
    ),
    (
        "filter_data.Wgs84GravityMagnitude",
        lambda: filter_data.Wgs84GravityMagnitude(gravity_magnitude=1.5, valid_flags=types.FilterOutputValidFlags(0x1)),
    ),
    (
        "filter_data.FilterStatus_gx5_45",
        lambda: filter_data.FilterStatus_gx5_45(
            filter_state=types.FilterStateGx5.RUN_SOLUTION_VALID,
            dynamics_mode=types.FilterDynamicsModeGx5.AIRBORNE,
            status_flags=types.FilterStatusFlagsGx5(0x1),
        ),
    ),
    (
        "filter_data.FilterStatus_cv7_ins",
        lambda: filter_data.FilterStatus_cv7_ins(
            filter_state=types.FilterModeCv7.VERT_GYRO,
            dynamics_mode=types.FilterDynamicsModeCv7.DEFAULT,
            status_flags=types.FilterStatusFlagsCv7(0x10),
        ),
    ),
    (
        "filter_data.GpsTimestamp",
        lambda: filter_data.GpsTimestamp(tow=-0.0, week_number=208, valid_flags=types.FilterOutputValidFlags(0x1)),
    ),
    (
        "filter_data.QuaternionAttitudeUncertainty",
        lambda: filter_data.QuaternionAttitudeUncertainty(
            q=[-0.0, 1.5, -2.25, 0.375], valid_flags=types.FilterOutputValidFlags(0x1)
        ),
    ),
    (
        "filter_data.GravityVector",
        lambda: filter_data.GravityVector(gravity=[1024.0, -0.0, 1.5], valid_flags=types.FilterOutputValidFlags(0x1)),
    ),
    (
        "filter_data.HeadingUpdateState",
        lambda: filter_data.HeadingUpdateState(
            heading=-2.25,
            heading_uncertainty=0.375,
            source=types.FilterHeadingSourceFlags(0x2),
            valid_flags=types.FilterHeadingUpdateValidFlags(0x1),
        ),
    ),
    (
        "filter_data.MagneticModel",
        lambda: filter_data.MagneticModel(
            intensity_north=1.5,
            intensity_east=-2.25,
            intensity_down=0.375,
            inclination=1024.0,
            declination=-0.0,
            valid_flags=types.FilterOutputValidFlags(0x1),
        ),
    ),
    (
        "filter_data.GyroScaleFactor",
        lambda: filter_data.GyroScaleFactor(
            scale_factor=[-0.0, 1.5, -2.25], valid_flags=types.FilterOutputValidFlags(0x1)
        ),
    ),
    (
        "filter_data.AccelScaleFactor",
        lambda: filter_data.AccelScaleFactor(
            scale_factor=[0.375, 1024.0, -0.0], valid_flags=types.FilterOutputValidFlags(0x1)
        ),
    ),
    (
        "filter_data.GyroScaleFactorUncertainty",
        lambda: filter_data.GyroScaleFactorUncertainty(
            scale_factor_uncertainty=[-0.0, 1.5, -2.25], valid_flags=types.FilterOutputValidFlags(0x1)
        ),
    ),
    (
        "filter_data.AccelScaleFactorUncertainty",
        lambda: filter_data.AccelScaleFactorUncertainty(
            scale_factor_uncertainty=[1024.0, -0.0, 1.5], valid_flags=types.FilterOutputValidFlags(0x1)
        ),
    ),
    (
        "filter_data.CompensatedAccel",
        lambda: filter_data.CompensatedAccel(accel=[1.5, -2.25, 0.375], valid_flags=types.FilterOutputValidFlags(0x1)),
    ),
    (
        "filter_data.StandardAtmosphere",
        lambda: filter_data.StandardAtmosphere(
            geometric_altitude=1024.0,
            geopotential_altitude=-0.0,
            temperature=1.5,
            pressure=-2.25,
            density=0.375,
            valid_flags=types.FilterOutputValidFlags(0x1),
        ),
    ),
    (
        "filter_data.PressureAltitude",
        lambda: filter_data.PressureAltitude(pressure_altitude=1024.0, valid_flags=types.FilterOutputValidFlags(0x1)),
    ),
    (
        "filter_data.MagAutoHardIronOffset",
        lambda: filter_data.MagAutoHardIronOffset(
            hard_iron_offset=[-0.0, 1.5, -2.25], valid_flags=types.FilterOutputValidFlags(0x1)
        ),
    ),
    (
        "filter_data.MagAutoSoftIronMatrix",
        lambda: filter_data.MagAutoSoftIronMatrix(
            soft_iron_matrix=[-0.0, 1.5, -2.25, 0.375, 1024.0, -0.0, 1.5, -2.25, 0.375],
            valid_flags=types.FilterOutputValidFlags(0x1),
        ),
    ),
    (
        "filter_data.MagAutoHardIronOffsetUncertainty",
        lambda: filter_data.MagAutoHardIronOffsetUncertainty(
            hard_iron_offset_uncertainty=[-2.25, 0.375, 1024.0], valid_flags=types.FilterOutputValidFlags(0x1)
        ),
    ),
    (
        "filter_data.MagAutoSoftIronMatrixUncertainty",
        lambda: filter_data.MagAutoSoftIronMatrixUncertainty(
            soft_iron_matrix_uncertainty=[-0.0, 1.5, -2.25, 0.375, 1024.0, -0.0, 1.5, -2.25, 0.375],
            valid_flags=types.FilterOutputValidFlags(0x1),
        ),
    ),
    (
        "filter_data.GnssAntennaOffsetCorrection",
        lambda: filter_data.GnssAntennaOffsetCorrection(
            offset=[-0.0, 1.5, -2.25], valid_flags=types.FilterOutputValidFlags(0x1)
        ),
    ),
    (
        "filter_data.GnssAntennaOffsetCorrectionUncertainty",
        lambda: filter_data.GnssAntennaOffsetCorrectionUncertainty(
            offset_uncertainty=[1.5, -2.25, 0.375], valid_flags=types.FilterOutputValidFlags(0x1)
        ),
    ),
    (
        "filter_data.MultiAntennaOffsetCorrection",
        lambda: filter_data.MultiAntennaOffsetCorrection(
            receiver_id=35, offset=[-0.0, 1.5, -2.25], valid_flags=types.FilterOutputValidFlags(0x1)
        ),
    ),
    (
        "filter_data.MultiAntennaOffsetCorrectionUncertainty",
        lambda: filter_data.MultiAntennaOffsetCorrectionUncertainty(
            receiver_id=211, offset_uncertainty=[0.375, 1024.0, -0.0], valid_flags=types.FilterOutputValidFlags(0x1)
        ),
    ),
    (
        "filter_data.EcefPositionUncertainty",
        lambda: filter_data.EcefPositionUncertainty(
            position_uncertainty=[0.375, 1024.0, -0.0], valid_flags=types.FilterOutputValidFlags(0x1)
        ),
    ),
    (
        "filter_data.EcefVelocityUncertainty",
        lambda: filter_data.EcefVelocityUncertainty(
            velocity_uncertainty=[-2.25, 0.375, 1024.0], valid_flags=types.FilterOutputValidFlags(0x1)
        ),
    ),
    (
        "filter_data.EcefPosition",
        lambda: filter_data.EcefPosition(
            position=[-2.5e-310, 1e16, 123.456], valid_flags=types.FilterOutputValidFlags(0x1)
        ),
    ),
    (
        "filter_data.EcefVelocity",
        lambda: filter_data.EcefVelocity(velocity=[1024.0, -0.0, 1.5], valid_flags=types.FilterOutputValidFlags(0x1)),
    ),
    (
        "filter_data.NedRelativePosition",
        lambda: filter_data.NedRelativePosition(
            relative_position=[1e16, 123.456, -0.0], valid_flags=types.FilterOutputValidFlags(0x1)
        ),
    ),
    (
        "filter_data.GnssPositionAidingStatus",
        lambda: filter_data.GnssPositionAidingStatus(
            receiver_id=53,
            time_of_week=0.375,
            status=types.FilterGnssAidingStatusFlags(0x4000),
            reserved=[164, 201, 238, 24, 61, 98, 135, 172],
        ),
    ),
    (
        "filter_data.AidingMeasurementSummary",
        lambda: filter_data.AidingMeasurementSummary(
            time_of_week=1024.0,
            source=203,
            type=types.FilterAidingMeasurementType.SPEED,
            indicator=types.FilterAidingMeasurementIndicator(0x8),
        ),
    ),
    (
        "filter_data.OdometerScaleFactorError",
        lambda: filter_data.OdometerScaleFactorError(
            scale_factor_error=0.375, valid_flags=types.FilterOutputValidFlags(0x1)
        ),
    ),
    (
        "filter_data.OdometerScaleFactorErrorUncertainty",
        lambda: filter_data.OdometerScaleFactorErrorUncertainty(
            scale_factor_error_uncertainty=-0.0, valid_flags=types.FilterOutputValidFlags(0x1)
        ),
    ),
    (
        "filter_data.GnssDualAntennaStatus",
        lambda: filter_data.GnssDualAntennaStatus(
            time_of_week=-2.25,
            heading=0.375,
            heading_uncertainty=1024.0,
            fix_type=types.FilterDualAntennaFixType.FIX_DA_FLOAT,
            status_flags=types.FilterDualAntennaStatusFlags(0x4),
            valid_flags=types.FilterOutputValidFlags(0x1),
        ),
    ),
    (
        "filter_data.AidingFrameConfigError",
        lambda: filter_data.AidingFrameConfigError(
            frame_id=102, translation=[1024.0, -0.0, 1.5], attitude=[-2.25, 0.375, 1024.0, -0.0]
        ),
    ),
    (
        "filter_data.AidingFrameConfigErrorUncertainty",
        lambda: filter_data.AidingFrameConfigErrorUncertainty(
            frame_id=166, translation_uncertainty=[-0.0, 1.5, -2.25], attitude_uncertainty=[0.375, 1024.0, -0.0]
        ),
    ),
    (
        "gnss_receiver_1.LlhPosition",
        lambda: gnss_receiver_1.LlhPosition(
            latitude=123.456,
            longitude=-0.0,
            ellipsoid_height=0.1,
            msl_height=-2.5e-310,
            horizontal_accuracy=0.375,
            vertical_accuracy=1024.0,
            valid_flags=types.GnssLlhPositionValidFlags(0x8),
        ),
    ),
    (
        "gnss_receiver_1.EcefPosition",
        lambda: gnss_receiver_1.EcefPosition(
            position=[-2.5e-310, 1e16, 123.456],
            position_accuracy=-0.0,
            valid_flags=types.GnssEcefPositionValidFlags(0xFFFC),
        ),
    ),
    (
        "gnss_receiver_1.NedVelocity",
        lambda: gnss_receiver_1.NedVelocity(
            velocity=[1024.0, -0.0, 1.5],
            speed=-2.25,
            ground_speed=0.375,
            heading=1024.0,
            speed_accuracy=-0.0,
            heading_accuracy=1.5,
            valid_flags=types.GnssNedVelocityValidFlags(0x20),
        ),
    ),
    (
        "gnss_receiver_1.EcefVelocity",
        lambda: gnss_receiver_1.EcefVelocity(
            velocity=[-0.0, 1.5, -2.25], velocity_accuracy=0.375, valid_flags=types.GnssEcefVelocityValidFlags(0x1)
        ),
    ),
    (
        "gnss_receiver_1.Dop",
        lambda: gnss_receiver_1.Dop(
            gdop=1024.0,
            pdop=-0.0,
            hdop=1.5,
            vdop=-2.25,
            tdop=0.375,
            ndop=1024.0,
            edop=-0.0,
            valid_flags=types.GnssDopValidFlags(0x20),
        ),
    ),
    (
        "gnss_receiver_1.UtcTime",
        lambda: gnss_receiver_1.UtcTime(
            year=9,
            month=46,
            day=83,
            hour=120,
            minute=157,
            second=194,
            millisecond=231,
            valid_flags=types.GnssUtcTimeValidFlagsCv7(0x2),
        ),
    ),
    (
        "gnss_receiver_1.GpsTime",
        lambda: gnss_receiver_1.GpsTime(tow=-0.0, week_number=218, valid_flags=types.GnssGpsTimeValidFlags(0x2)),
    ),
    (
        "gnss_receiver_1.FixInfo",
        lambda: gnss_receiver_1.FixInfo(
            fix_type=types.GnssFixTypeCv7.FIX_RTK_FLOAT,
            num_sv=124,
            fix_flags=types.GnssFixFlags(0x1),
            valid_flags=types.GnssFixInfoValidFlags(0x1),
        ),
    ),
    (
        "gnss_receiver_1.HardwareStatus",
        lambda: gnss_receiver_1.HardwareStatus(
            receiver_state=types.GnssReceiverState.ON,
            antenna_state=types.GnssAntennaState.SHORT,
            antenna_power=types.GnssAntennaPower.OFF,
            valid_flags=types.GnssHardwareStatusValidFlags(0x1),
        ),
    ),
    (
        "gnss_receiver_1.ClockInfo2",
        lambda: gnss_receiver_1.ClockInfo2(
            bias=0.1,
            drift=-2.5e-310,
            bias_accuracy_estimate=1e16,
            drift_accuracy_estimate=123.456,
            valid_flags=types.GnssClockInfo2ValidFlags(0xFFF0),
        ),
    ),
    (
        "gnss_receiver_1.GpsLeapSeconds",
        lambda: gnss_receiver_1.GpsLeapSeconds(leap_seconds=151, valid_flags=types.GnssLeapSecondsValidFlags(0x2)),
    ),
    (
        "gnss_receiver_1.SbasInfo",
        lambda: gnss_receiver_1.SbasInfo(
            tow=1e16,
            week_number=159,
            sbas_system=types.GnssSbasSystem.GAGAN,
            sbas_id=233,
            count=19,
            sbas_status=types.GnssSbasStatus(0x4),
            valid_flags=types.GnssSbasInfoValidFlags(0x1),
        ),
    ),
    (
        "gnss_receiver_1.SatelliteStatus",
        lambda: gnss_receiver_1.SatelliteStatus(
            index=25,
            count=62,
            tow=123.456,
            week_number=136,
            gnss_id=types.GnssConstellationId.GPS,
            satellite_id=210,
            elevation=0.375,
            azimuth=1024.0,
            health=True,
            valid_flags=types.GnssSatelliteStatusValidFlags(0x4),
        ),
    ),
    (
        "gnss_receiver_1.Raw",
        lambda: gnss_receiver_1.Raw(
            index=29,
            count=66,
            tow=1e16,
            week_number=140,
            receiver_id=177,
            tracking_channel=214,
            gnss_id=types.GnssConstellationId.GPS,
            satellite_id=37,
            signal_id=types.GnssSignalId.BEIDOU_B1Q,
            signal_strength=-0.0,
            quality=types.GnssSignalQuality.FULLY_LOCKED,
            pseudorange=-2.5e-310,
            carrier_phase=1e16,
            doppler=1024.0,
            range_uncert=-0.0,
            phase_uncert=1.5,
            doppler_uncert=-2.25,
            lock_time=0.375,
            valid_flags=types.GnssRawValidFlags(0x80),
        ),
    ),
    (
        "gnss_receiver_1.GpsEphemeris",
        lambda: gnss_receiver_1.GpsEphemeris(
            index=83,
            count=120,
            tow=1e16,
            week_number=194,
            satellite_id=231,
            health=17,
            iodc=54,
            iode=91,
            t_oc=123.456,
            af0=-0.0,
            af1=0.1,
            af2=-2.5e-310,
            t_gd=1e16,
            isc_l1ca=123.456,
            isc_l2c=-0.0,
            t_oe=0.1,
            a=-2.5e-310,
            a_dot=1e16,
            mean_anomaly=123.456,
            delta_mean_motion=-0.0,
            delta_mean_motion_dot=0.1,
            eccentricity=-2.5e-310,
            argument_of_perigee=1e16,
            omega=123.456,
            omega_dot=-0.0,
            inclination=0.1,
            inclination_dot=-2.5e-310,
            c_ic=1e16,
            c_is=123.456,
            c_uc=-0.0,
            c_us=0.1,
            c_rc=-2.5e-310,
            c_rs=1e16,
            valid_flags=types.GnssEphemerisValidFlags(0x2),
        ),
    ),
    (
        "gnss_receiver_1.GlonassEphemeris",
        lambda: gnss_receiver_1.GlonassEphemeris(
            index=103,
            count=140,
            tow=-2.5e-310,
            week_number=214,
            satellite_id=0,
            freq_number=-60,
            tk=74,
            tb=111,
            sat_type=types.GnssGlonassSatelliteType.GLONASS,
            gamma=123.456,
            tau_n=-0.0,
            x=[0.1, -2.5e-310, 1e16],
            v=[1024.0, -0.0, 1.5],
            a=[-2.25, 0.375, 1024.0],
            health=90,
            p=127,
            nt=164,
            delta_tau_n=0.375,
            ft=238,
            en=24,
            p1=61,
            p2=98,
            p3=135,
            p4=172,
            valid_flags=types.GnssGlonassEphemerisValidFlags(0x1),
        ),
    ),
    (
        "gnss_receiver_1.GalileoEphemeris",
        lambda: gnss_receiver_1.GalileoEphemeris(
            index=234,
            count=20,
            tow=-2.5e-310,
            week_number=94,
            satellite_id=131,
            health=168,
            iodc=205,
            iode=242,
            t_oc=1e16,
            af0=123.456,
            af1=-0.0,
            af2=0.1,
            t_gd=-2.5e-310,
            isc_l1ca=1e16,
            isc_l2c=123.456,
            t_oe=-0.0,
            a=0.1,
            a_dot=-2.5e-310,
            mean_anomaly=1e16,
            delta_mean_motion=123.456,
            delta_mean_motion_dot=-0.0,
            eccentricity=0.1,
            argument_of_perigee=-2.5e-310,
            omega=1e16,
            omega_dot=123.456,
            inclination=-0.0,
            inclination_dot=0.1,
            c_ic=-2.5e-310,
            c_is=1e16,
            c_uc=123.456,
            c_us=-0.0,
            c_rc=0.1,
            c_rs=-2.5e-310,
            valid_flags=types.GnssEphemerisValidFlags(0xFFF8),
        ),
    ),
    (
        "gnss_receiver_1.BeidouEphemeris",
        lambda: gnss_receiver_1.BeidouEphemeris(
            index=244,
            count=30,
            tow=-0.0,
            week_number=104,
            satellite_id=141,
            health=178,
            iodc=215,
            iode=1,
            t_oc=0.1,
            af0=-2.5e-310,
            af1=1e16,
            af2=123.456,
            t_gd=-0.0,
            isc_l1ca=0.1,
            isc_l2c=-2.5e-310,
            t_oe=1e16,
            a=123.456,
            a_dot=-0.0,
            mean_anomaly=0.1,
            delta_mean_motion=-2.5e-310,
            delta_mean_motion_dot=1e16,
            eccentricity=123.456,
            argument_of_perigee=-0.0,
            omega=0.1,
            omega_dot=-2.5e-310,
            inclination=1e16,
            inclination_dot=123.456,
            c_ic=-0.0,
            c_is=0.1,
            c_uc=-2.5e-310,
            c_us=1e16,
            c_rc=123.456,
            c_rs=-0.0,
            valid_flags=types.GnssEphemerisValidFlags(0x2),
        ),
    ),
    (
        "gnss_receiver_2.LlhPosition",
        lambda: gnss_receiver_2.LlhPosition(
            latitude=0.1,
            longitude=-2.5e-310,
            ellipsoid_height=1e16,
            msl_height=123.456,
            horizontal_accuracy=-0.0,
            vertical_accuracy=1.5,
            valid_flags=types.GnssLlhPositionValidFlags(0xFFE0),
        ),
    ),
    (
        "gnss_receiver_2.EcefPosition",
        lambda: gnss_receiver_2.EcefPosition(
            position=[-2.5e-310, 1e16, 123.456],
            position_accuracy=-0.0,
            valid_flags=types.GnssEcefPositionValidFlags(0x2),
        ),
    ),
    (
        "gnss_receiver_2.NedVelocity",
        lambda: gnss_receiver_2.NedVelocity(
            velocity=[-0.0, 1.5, -2.25],
            speed=0.375,
            ground_speed=1024.0,
            heading=-0.0,
            speed_accuracy=1.5,
            heading_accuracy=-2.25,
            valid_flags=types.GnssNedVelocityValidFlags(0x2),
        ),
    ),
    (
        "gnss_receiver_2.EcefVelocity",
        lambda: gnss_receiver_2.EcefVelocity(
            velocity=[-0.0, 1.5, -2.25], velocity_accuracy=0.375, valid_flags=types.GnssEcefVelocityValidFlags(0x2)
        ),
    ),
    (
        "gnss_receiver_2.Dop",
        lambda: gnss_receiver_2.Dop(
            gdop=0.375,
            pdop=1024.0,
            hdop=-0.0,
            vdop=1.5,
            tdop=-2.25,
            ndop=0.375,
            edop=1024.0,
            valid_flags=types.GnssDopValidFlags(0x2),
        ),
    ),
    (
        "gnss_receiver_2.UtcTime",
        lambda: gnss_receiver_2.UtcTime(
            year=131,
            month=168,
            day=205,
            hour=242,
            minute=28,
            second=65,
            millisecond=102,
            valid_flags=types.GnssUtcTimeValidFlagsCv7(0xFFFC),
        ),
    ),
    (
        "gnss_receiver_2.GpsTime",
        lambda: gnss_receiver_2.GpsTime(tow=123.456, week_number=35, valid_flags=types.GnssGpsTimeValidFlags(0x1)),
    ),
    (
        "gnss_receiver_2.FixInfo",
        lambda: gnss_receiver_2.FixInfo(
            fix_type=types.GnssFixTypeCv7.FIX_3D,
            num_sv=36,
            fix_flags=types.GnssFixFlags(0x1),
            valid_flags=types.GnssFixInfoValidFlags(0xFFF8),
        ),
    ),
    (
        "gnss_receiver_2.HardwareStatus",
        lambda: gnss_receiver_2.HardwareStatus(
            receiver_state=types.GnssReceiverState.ON,
            antenna_state=types.GnssAntennaState.UNKNOWN,
            antenna_power=types.GnssAntennaPower.OFF,
            valid_flags=types.GnssHardwareStatusValidFlags(0x1),
        ),
    ),
    (
        "gnss_receiver_2.ClockInfo2",
        lambda: gnss_receiver_2.ClockInfo2(
            bias=1e16,
            drift=123.456,
            bias_accuracy_estimate=-0.0,
            drift_accuracy_estimate=0.1,
            valid_flags=types.GnssClockInfo2ValidFlags(0x2),
        ),
    ),
    (
        "gnss_receiver_2.GpsLeapSeconds",
        lambda: gnss_receiver_2.GpsLeapSeconds(leap_seconds=235, valid_flags=types.GnssLeapSecondsValidFlags(0x2)),
    ),
    (
        "gnss_receiver_2.SbasInfo",
        lambda: gnss_receiver_2.SbasInfo(
            tow=-0.0,
            week_number=39,
            sbas_system=types.GnssSbasSystem.WAAS,
            sbas_id=113,
            count=150,
            sbas_status=types.GnssSbasStatus(0xF0),
            valid_flags=types.GnssSbasInfoValidFlags(0x4),
        ),
    ),
    (
        "gnss_receiver_2.SatelliteStatus",
        lambda: gnss_receiver_2.SatelliteStatus(
            index=168,
            count=205,
            tow=-0.0,
            week_number=28,
            gnss_id=types.GnssConstellationId.BEIDOU,
            satellite_id=102,
            elevation=1024.0,
            azimuth=-0.0,
            health=False,
            valid_flags=types.GnssSatelliteStatusValidFlags(0x8),
        ),
    ),
    (
        "gnss_receiver_2.Raw",
        lambda: gnss_receiver_2.Raw(
            index=136,
            count=173,
            tow=123.456,
            week_number=247,
            receiver_id=33,
            tracking_channel=70,
            gnss_id=types.GnssConstellationId.UNKNOWN,
            satellite_id=144,
            signal_id=types.GnssSignalId.BEIDOU_B1I,
            signal_strength=1.5,
            quality=types.GnssSignalQuality.TIME_LOCKED,
            pseudorange=1e16,
            carrier_phase=123.456,
            doppler=-0.0,
            range_uncert=1.5,
            phase_uncert=-2.25,
            doppler_uncert=0.375,
            lock_time=1024.0,
            valid_flags=types.GnssRawValidFlags(0x400),
        ),
    ),
    (
        "gnss_receiver_2.GpsEphemeris",
        lambda: gnss_receiver_2.GpsEphemeris(
            index=79,
            count=116,
            tow=1e16,
            week_number=190,
            satellite_id=227,
            health=13,
            iodc=50,
            iode=87,
            t_oc=123.456,
            af0=-0.0,
            af1=0.1,
            af2=-2.5e-310,
            t_gd=1e16,
            isc_l1ca=123.456,
            isc_l2c=-0.0,
            t_oe=0.1,
            a=-2.5e-310,
            a_dot=1e16,
            mean_anomaly=123.456,
            delta_mean_motion=-0.0,
            delta_mean_motion_dot=0.1,
            eccentricity=-2.5e-310,
            argument_of_perigee=1e16,
            omega=123.456,
            omega_dot=-0.0,
            inclination=0.1,
            inclination_dot=-2.5e-310,
            c_ic=1e16,
            c_is=123.456,
            c_uc=-0.0,
            c_us=0.1,
            c_rc=-2.5e-310,
            c_rs=1e16,
            valid_flags=types.GnssEphemerisValidFlags(0x2),
        ),
    ),
    (
        "gnss_receiver_2.GlonassEphemeris",
        lambda: gnss_receiver_2.GlonassEphemeris(
            index=36,
            count=73,
            tow=-2.5e-310,
            week_number=147,
            satellite_id=184,
            freq_number=-70,
            tk=7,
            tb=44,
            sat_type=types.GnssGlonassSatelliteType.GLONASS,
            gamma=123.456,
            tau_n=-0.0,
            x=[0.1, -2.5e-310, 1e16],
            v=[1024.0, -0.0, 1.5],
            a=[-2.25, 0.375, 1024.0],
            health=23,
            p=60,
            nt=97,
            delta_tau_n=0.375,
            ft=171,
            en=208,
            p1=245,
            p2=31,
            p3=68,
            p4=105,
            valid_flags=types.GnssGlonassEphemerisValidFlags(0x1),
        ),
    ),
    (
        "gnss_receiver_2.GalileoEphemeris",
        lambda: gnss_receiver_2.GalileoEphemeris(
            index=231,
            count=17,
            tow=123.456,
            week_number=91,
            satellite_id=128,
            health=165,
            iodc=202,
            iode=239,
            t_oc=-0.0,
            af0=0.1,
            af1=-2.5e-310,
            af2=1e16,
            t_gd=123.456,
            isc_l1ca=-0.0,
            isc_l2c=0.1,
            t_oe=-2.5e-310,
            a=1e16,
            a_dot=123.456,
            mean_anomaly=-0.0,
            delta_mean_motion=0.1,
            delta_mean_motion_dot=-2.5e-310,
            eccentricity=1e16,
            argument_of_perigee=123.456,
            omega=-0.0,
            omega_dot=0.1,
            inclination=-2.5e-310,
            inclination_dot=1e16,
            c_ic=123.456,
            c_is=-0.0,
            c_uc=0.1,
            c_us=-2.5e-310,
            c_rc=1e16,
            c_rs=123.456,
            valid_flags=types.GnssEphemerisValidFlags(0x4),
        ),
    ),
    (
        "gnss_receiver_2.BeidouEphemeris",
        lambda: gnss_receiver_2.BeidouEphemeris(
            index=218,
            count=4,
            tow=0.1,
            week_number=78,
            satellite_id=115,
            health=152,
            iodc=189,
            iode=226,
            t_oc=-2.5e-310,
            af0=1e16,
            af1=123.456,
            af2=-0.0,
            t_gd=0.1,
            isc_l1ca=-2.5e-310,
            isc_l2c=1e16,
            t_oe=123.456,
            a=-0.0,
            a_dot=0.1,
            mean_anomaly=-2.5e-310,
            delta_mean_motion=1e16,
            delta_mean_motion_dot=123.456,
            eccentricity=-0.0,
            argument_of_perigee=0.1,
            omega=-2.5e-310,
            omega_dot=1e16,
            inclination=123.456,
            inclination_dot=-0.0,
            c_ic=0.1,
            c_is=-2.5e-310,
            c_uc=1e16,
            c_us=123.456,
            c_rc=-0.0,
            c_rs=0.1,
            valid_flags=types.GnssEphemerisValidFlags(0x4),
        ),
    ),
    (
        "gnss_corrections.BaseStationInfo",
        lambda: gnss_corrections.BaseStationInfo(
            tow=-0.0,
            week_number=242,
            ecef_position=[-2.5e-310, 1e16, 123.456],
            height=-0.0,
            station_id=176,
            indicators=types.GnssBaseStationIndicators(0x4),
            valid_flags=types.GnssBaseStationInfoValidFlags(0xFFC0),
        ),
    ),
    (
        "gnss_corrections.RtkCorrectionsStatus",
        lambda: gnss_corrections.RtkCorrectionsStatus(
            tow=1e16,
            week_number=182,
            epoch_status=types.RtkCorrectionsEpochStatus(0xFE00),
            dongle_status=5,
            gps_correction_latency=-2.25,
            glonass_correction_latency=0.375,
            galileo_correction_latency=1024.0,
            beidou_correction_latency=-0.0,
            reserved=[190, 227, 13, 50],
            valid_flags=types.RtkCorrectionsStatusValidFlags(0x80),
        ),
    ),
    (
        "gnss_external.LlhPosition",
        lambda: gnss_external.LlhPosition(
            latitude=123.456,
            longitude=-0.0,
            ellipsoid_height=0.1,
            msl_height=-2.5e-310,
            horizontal_accuracy=0.375,
            vertical_accuracy=1024.0,
            valid_flags=types.GnssLlhPositionValidFlags(0x4),
        ),
    ),
    (
        "gnss_external.NedVelocity",
        lambda: gnss_external.NedVelocity(
            velocity=[-2.25, 0.375, 1024.0],
            speed=-0.0,
            ground_speed=1.5,
            heading=-2.25,
            speed_accuracy=0.375,
            heading_accuracy=1024.0,
            valid_flags=types.GnssNedVelocityValidFlags(0x2),
        ),
    ),
    (
        "gnss_external.UtcTime",
        lambda: gnss_external.UtcTime(
            year=145,
            month=182,
            day=219,
            hour=5,
            minute=42,
            second=79,
            millisecond=116,
            valid_flags=types.GnssUtcTimeValidFlagsCv7(0x2),
        ),
    ),
    (
        "gnss_external.FixInfo",
        lambda: gnss_external.FixInfo(
            fix_type=types.GnssFixTypeCv7.FIX_TIME_ONLY,
            num_sv=102,
            fix_flags=types.GnssFixFlags(0xFFFC),
            valid_flags=types.GnssFixInfoValidFlags(0x2),
        ),
    ),
    (
        "gnss_external.SatelliteStatus",
        lambda: gnss_external.SatelliteStatus(
            index=100,
            count=137,
            tow=-2.5e-310,
            week_number=211,
            gnss_id=types.GnssConstellationId.SBAS,
            satellite_id=34,
            elevation=1.5,
            azimuth=-2.25,
            health=True,
            valid_flags=types.GnssSatelliteStatusValidFlags(0x40),
        ),
    ),
    (
        "system_data.BuiltInTest",
        lambda: system_data.BuiltInTest(
            result=types.Cv7ContinuousBit(
                system_byte_0=types.Cv7ContinuousBitSystem0(0x2),
                reserved_byte_1=51,
                system_byte_2=types.Cv7ContinuousBitSystem2(0x10),
                system_byte_3=types.Cv7ContinuousBitSystem3(0x8),
                imu_byte_4=types.Cv7ContinuousBitImu4(0x40),
                imu_byte_5=types.Cv7ContinuousBitImu5(0x80),
                imu_byte_6=types.Cv7ContinuousBitImu6(0x1),
                imu_byte_7=types.Cv7ContinuousBitImu7(0xFE),
                nav_byte_8=types.Cv7ContinuousBitNav8(0x8),
                reserved_byte_9=96,
                reserved_byte_10=133,
                reserved_byte_11=170,
                reserved_byte_12=207,
                gnss_byte_13=types.Cv7ContinuousBitGnss13(0x1),
                gnss_byte_14=types.Cv7ContinuousBitGnss14(0xFC),
                reserved_byte_15=67,
            )
        ),
    ),
    ("system_data.TimeSyncStatus", lambda: system_data.TimeSyncStatus(time_sync=True, last_pps_rcvd=112)),
    ("system_data.GpioState", lambda: system_data.GpioState(states=types.GpioPinStates(0xF0))),
    ("shared.EventSource", lambda: shared.EventSource(trigger_id=159)),
    (
        "shared.GpsTimestamp",
        lambda: shared.GpsTimestamp(tow=123.456, week_number=18, valid_flags=types.SharedGpsTimestampValidFlags(0x2)),
    ),
    ("shared.DeltaTime", lambda: shared.DeltaTime(seconds=-0.0)),
    ("shared.ReferenceTimestamp", lambda: shared.ReferenceTimestamp(nanoseconds=4)),
    ("shared.ReferenceTimeDelta", lambda: shared.ReferenceTimeDelta(dt_nanos=139)),
    (
        "shared.ExternalTimestamp",
        lambda: shared.ExternalTimestamp(nanoseconds=134, valid_flags=types.ExternalTimestampValidFlags(0x1)),
    ),
    (
        "shared.ExternalTimeDelta",
        lambda: shared.ExternalTimeDelta(dt_nanos=156, valid_flags=types.ExternalTimeDeltaValidFlags(0x1)),
    ),
    ("reserved.AckNack", lambda: reserved.AckNack(command_descriptor=33, ack_code=types.AckCode.COMMAND_FAILED)),
    ("types.ActionGpioParams", lambda: types.ActionGpioParams(pin=184, mode=types.ActionGpioMode.TOGGLE)),
    (
        "types.MessageParams",
        lambda: types.MessageParams(desc_set=216, decimation=2, num_fields=2, descriptors=[39, 76]),
    ),
    ("types.ActionStatusEntry", lambda: types.ActionStatusEntry(action_type=types.ActionType.GPIO, trigger_id=32)),
    ("types.AidingFrameEuler", lambda: types.AidingFrameEuler(euler=[0.375, 1024.0, -0.0])),
    ("types.AidingFrameQuaternion", lambda: types.AidingFrameQuaternion(quaternion=[-2.25, 0.375, 1024.0, -0.0])),
    (
        "types.AidingTime",
        lambda: types.AidingTime(timebase=types.AidingTimebase.INTERNAL_REFERENCE, reserved=37, nanoseconds=74),
    ),
    ("types.CombinationParams", lambda: types.CombinationParams(logic_table=98, input_triggers=[135, 172, 209, 246])),
    (
        "types.ConstellationSettings",
        lambda: types.ConstellationSettings(
            constellation_id=types.Gx5ConstellationId.GPS,
            enable=249,
            reserved_channels=35,
            max_channels=72,
            option_flags=types.ConstellationOptions(0x1),
        ),
    ),
    (
        "types.Cv7ContinuousBit",
        lambda: types.Cv7ContinuousBit(
            system_byte_0=types.Cv7ContinuousBitSystem0(0x20),
            reserved_byte_1=70,
            system_byte_2=types.Cv7ContinuousBitSystem2(0x1),
            system_byte_3=types.Cv7ContinuousBitSystem3(0x4),
            imu_byte_4=types.Cv7ContinuousBitImu4(0x4),
            imu_byte_5=types.Cv7ContinuousBitImu5(0x8),
            imu_byte_6=types.Cv7ContinuousBitImu6(0x10),
            imu_byte_7=types.Cv7ContinuousBitImu7(0xFE),
            nav_byte_8=types.Cv7ContinuousBitNav8(0x4),
            reserved_byte_9=115,
            reserved_byte_10=152,
            reserved_byte_11=189,
            reserved_byte_12=226,
            gnss_byte_13=types.Cv7ContinuousBitGnss13(0x10),
            gnss_byte_14=types.Cv7ContinuousBitGnss14(0x2),
            reserved_byte_15=86,
        ),
    ),
    ("types.DescriptorRate", lambda: types.DescriptorRate(descriptor=77, decimation=114)),
    (
        "types.DeviceInfo",
        lambda: types.DeviceInfo(
            firmware_version=236,
            model_name=b"yza             ",
            model_number=b"zab             ",
            serial_number=b"abc             ",
            lot_number=b"bcd             ",
            device_options=b"cde             ",
        ),
    ),
    (
        "types.GnssReceiverInfoEntry",
        lambda: types.GnssReceiverInfoEntry(
            receiver_id=125,
            mip_data_descriptor_set=162,
            description=b"yza\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00",
        ),
    ),
    ("types.GpioBehaviorUnused", lambda: types.GpioBehaviorUnused(behavior=types.GpioUnusedBehavior.UNUSED)),
    ("types.GpioBehaviorIo", lambda: types.GpioBehaviorIo(behavior=types.GpioIoBehavior.INPUT)),
    ("types.GpioBehaviorPps", lambda: types.GpioBehaviorPps(behavior=types.GpioPpsBehavior.UNUSED)),
    ("types.GpioBehaviorEncoder", lambda: types.GpioBehaviorEncoder(behavior=types.GpioEncoderBehavior.UNUSED)),
    ("types.GpioBehaviorTimestamp", lambda: types.GpioBehaviorTimestamp(behavior=types.GpioTimestampBehavior.UNUSED)),
    ("types.GpioBehaviorUart", lambda: types.GpioBehaviorUart(behavior=types.GpioUartBehavior.PORT3_TX)),
    ("types.Gx5BasicStatus", lambda: types.Gx5BasicStatus(status_flags=98, system_state=135, system_timer=172)),
    (
        "types.Gx5DiagnosticStatus",
        lambda: types.Gx5DiagnosticStatus(
            status_flags=161,
            system_state=198,
            system_timer=235,
            gnss_power_state=21,
            pps_pulse_count=58,
            last_pps_time=95,
            imu_stream_enabled=132,
            gnss_stream_enabled=169,
            filter_stream_enabled=206,
            imu_dropped_packets=243,
            gnss_dropped_packets=29,
            filter_dropped_packets=66,
            com_bytes_written=103,
            com_bytes_read=140,
            com_write_overruns=177,
            imu_parse_errors=214,
            imu_messages_read=0,
            last_imu_message_time=37,
            gnss_parse_errors=74,
            gnss_messages_read=111,
            last_gnss_message_time=148,
        ),
    ),
    ("types.Gx5PollDescriptor", lambda: types.Gx5PollDescriptor(descriptor=217, reserved=3)),
    ("types.NmeaMessage", lambda: types.NmeaMessage(message_id=20, talker_id=57, source_desc_set=94, decimation=131)),
    ("types.SensorRangeEntry", lambda: types.SensorRangeEntry(setting=202, range=1024.0)),
    ("types.SupportedActionType", lambda: types.SupportedActionType(type=types.ActionType.NONE, count=97)),
    (
        "types.SupportedActions",
        lambda: types.SupportedActions(
            max_instances=65,
            num_entries=2,
            entries=[
                types.SupportedActionType(type=types.ActionType.GPIO, count=176),
                types.SupportedActionType(type=types.ActionType.GPIO, count=36),
            ],
        ),
    ),
    ("types.SupportedTriggerType", lambda: types.SupportedTriggerType(type=types.TriggerType.COMBINATION, count=65)),
    (
        "types.SupportedTriggers",
        lambda: types.SupportedTriggers(
            max_instances=119,
            num_entries=2,
            entries=[
                types.SupportedTriggerType(type=types.TriggerType.NONE, count=230),
                types.SupportedTriggerType(type=types.TriggerType.COMBINATION, count=90),
            ],
        ),
    ),
    (
        "types.ThresholdParams",
        lambda: types.ThresholdParams(
            desc_set=89,
            field_desc=126,
            param_id=163,
            type=types.ThresholdType.INTERVAL,
            low_thres=-2.5e-310,
            high_thres=1e16,
        ),
    ),
    ("types.TriggerGpioParams", lambda: types.TriggerGpioParams(pin=107, mode=types.TriggerGpioMode.WHILE_HIGH)),
    (
        "types.TriggerStatusEntry",
        lambda: types.TriggerStatusEntry(type=types.TriggerType.THRESHOLD, status=types.TriggerStatus(0x1)),
    ),
]

BITFIELD_MEMBERS = [
    (types.AidingLlhValidFlags, "latitude", "LATITUDE", 0, 1, 0x1),
    (types.AidingLlhValidFlags, "longitude", "LONGITUDE", 1, 1, 0x2),
    (types.AidingLlhValidFlags, "height", "HEIGHT", 2, 1, 0x4),
    (types.AidingVectorValidFlags, "x", "X", 0, 1, 0x1),
    (types.AidingVectorValidFlags, "y", "Y", 1, 1, 0x2),
    (types.AidingVectorValidFlags, "z", "Z", 2, 1, 0x4),
    (types.ConstellationOptions, "l1saif", "L1SAIF", 0, 1, 0x1),
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
    (types.Cv7ContinuousBitGnss13, "reserved_104", "RESERVED_104", 0, 1, 0x1),
    (types.Cv7ContinuousBitGnss13, "receiver_1_fault", "RECEIVER_1_FAULT", 1, 1, 0x2),
    (types.Cv7ContinuousBitGnss13, "reserved_106_107", "RESERVED_106_107", 2, 2, 0xC),
    (types.Cv7ContinuousBitGnss13, "receiver_1_no_solution", "RECEIVER_1_NO_SOLUTION", 4, 1, 0x10),
    (types.Cv7ContinuousBitGnss13, "reserved_109", "RESERVED_109", 5, 1, 0x20),
    (types.Cv7ContinuousBitGnss13, "receiver_2_fault", "RECEIVER_2_FAULT", 6, 1, 0x40),
    (types.Cv7ContinuousBitGnss13, "reserved_111", "RESERVED_111", 7, 1, 0x80),
    (types.Cv7ContinuousBitGnss14, "reserved_112", "RESERVED_112", 0, 1, 0x1),
    (types.Cv7ContinuousBitGnss14, "receiver_2_no_solution", "RECEIVER_2_NO_SOLUTION", 1, 1, 0x2),
    (types.Cv7ContinuousBitGnss14, "reserved_114_119", "RESERVED_114_119", 2, 6, 0xFC),
    (types.Cv7ContinuousBitImu4, "reserved_32", "RESERVED_32", 0, 1, 0x1),
    (types.Cv7ContinuousBitImu4, "imu_communication_fault", "IMU_COMMUNICATION_FAULT", 1, 1, 0x2),
    (types.Cv7ContinuousBitImu4, "imu_timing_overrun", "IMU_TIMING_OVERRUN", 2, 1, 0x4),
    (types.Cv7ContinuousBitImu4, "reserved_35", "RESERVED_35", 3, 1, 0x8),
    (
        types.Cv7ContinuousBitImu4,
        "imu_calibration_error_accelerometer",
        "IMU_CALIBRATION_ERROR_ACCELEROMETER",
        4,
        1,
        0x10,
    ),
    (types.Cv7ContinuousBitImu4, "imu_calibration_error_gyroscope", "IMU_CALIBRATION_ERROR_GYROSCOPE", 5, 1, 0x20),
    (
        types.Cv7ContinuousBitImu4,
        "imu_calibration_error_magnetometer",
        "IMU_CALIBRATION_ERROR_MAGNETOMETER",
        6,
        1,
        0x40,
    ),
    (types.Cv7ContinuousBitImu4, "reserved_39", "RESERVED_39", 7, 1, 0x80),
    (types.Cv7ContinuousBitImu5, "accelerometer_general_fault", "ACCELEROMETER_GENERAL_FAULT", 0, 1, 0x1),
    (types.Cv7ContinuousBitImu5, "accelerometer_overrange", "ACCELEROMETER_OVERRANGE", 1, 1, 0x2),
    (types.Cv7ContinuousBitImu5, "accelerometer_self_test_fail", "ACCELEROMETER_SELF_TEST_FAIL", 2, 1, 0x4),
    (types.Cv7ContinuousBitImu5, "reserved_43", "RESERVED_43", 3, 1, 0x8),
    (types.Cv7ContinuousBitImu5, "gyroscope_general_fault", "GYROSCOPE_GENERAL_FAULT", 4, 1, 0x10),
    (types.Cv7ContinuousBitImu5, "gyroscope_overrange", "GYROSCOPE_OVERRANGE", 5, 1, 0x20),
    (types.Cv7ContinuousBitImu5, "gyroscope_self_test_fail", "GYROSCOPE_SELF_TEST_FAIL", 6, 1, 0x40),
    (types.Cv7ContinuousBitImu5, "reserved_47", "RESERVED_47", 7, 1, 0x80),
    (types.Cv7ContinuousBitImu6, "magnetometer_general_fault", "MAGNETOMETER_GENERAL_FAULT", 0, 1, 0x1),
    (types.Cv7ContinuousBitImu6, "magnetometer_overrange", "MAGNETOMETER_OVERRANGE", 1, 1, 0x2),
    (types.Cv7ContinuousBitImu6, "magnetometer_self_test_fail", "MAGNETOMETER_SELF_TEST_FAIL", 2, 1, 0x4),
    (types.Cv7ContinuousBitImu6, "reserved_51", "RESERVED_51", 3, 1, 0x8),
    (types.Cv7ContinuousBitImu6, "pressure_sensor_general_fault", "PRESSURE_SENSOR_GENERAL_FAULT", 4, 1, 0x10),
    (types.Cv7ContinuousBitImu6, "pressure_sensor_overrange", "PRESSURE_SENSOR_OVERRANGE", 5, 1, 0x20),
    (types.Cv7ContinuousBitImu6, "pressure_sensor_self_test_fail", "PRESSURE_SENSOR_SELF_TEST_FAIL", 6, 1, 0x40),
    (types.Cv7ContinuousBitImu6, "reserved_55", "RESERVED_55", 7, 1, 0x80),
    (types.Cv7ContinuousBitImu7, "factory_bits_invalid", "FACTORY_BITS_INVALID", 0, 1, 0x1),
    (types.Cv7ContinuousBitImu7, "reserved_57_63", "RESERVED_57_63", 1, 7, 0xFE),
    (types.Cv7ContinuousBitNav8, "reserved_64", "RESERVED_64", 0, 1, 0x1),
    (types.Cv7ContinuousBitNav8, "reserved_65", "RESERVED_65", 1, 1, 0x2),
    (types.Cv7ContinuousBitNav8, "filter_timing_overrun", "FILTER_TIMING_OVERRUN", 2, 1, 0x4),
    (types.Cv7ContinuousBitNav8, "filter_timing_underrun", "FILTER_TIMING_UNDERRUN", 3, 1, 0x8),
    (types.Cv7ContinuousBitNav8, "reserved_68_71", "RESERVED_68_71", 4, 4, 0xF0),
    (types.Cv7ContinuousBitSystem0, "system_clock_failure", "SYSTEM_CLOCK_FAILURE", 0, 1, 0x1),
    (types.Cv7ContinuousBitSystem0, "power_fault", "POWER_FAULT", 1, 1, 0x2),
    (types.Cv7ContinuousBitSystem0, "reserved_2_3", "RESERVED_2_3", 2, 2, 0xC),
    (types.Cv7ContinuousBitSystem0, "firmware_fault", "FIRMWARE_FAULT", 4, 1, 0x10),
    (types.Cv7ContinuousBitSystem0, "timing_overload", "TIMING_OVERLOAD", 5, 1, 0x20),
    (types.Cv7ContinuousBitSystem0, "buffer_overrun", "BUFFER_OVERRUN", 6, 1, 0x40),
    (types.Cv7ContinuousBitSystem0, "reserved_7", "RESERVED_7", 7, 1, 0x80),
    (types.Cv7ContinuousBitSystem2, "imu_process_fault", "IMU_PROCESS_FAULT", 0, 1, 0x1),
    (types.Cv7ContinuousBitSystem2, "imu_data_process_time_exceeded", "IMU_DATA_PROCESS_TIME_EXCEEDED", 1, 1, 0x2),
    (types.Cv7ContinuousBitSystem2, "imu_data_rate_error", "IMU_DATA_RATE_ERROR", 2, 1, 0x4),
    (types.Cv7ContinuousBitSystem2, "imu_stall", "IMU_STALL", 3, 1, 0x8),
    (types.Cv7ContinuousBitSystem2, "filter_process_fault", "FILTER_PROCESS_FAULT", 4, 4, 0xF0),
    (types.Cv7ContinuousBitSystem2, "filter_major_cycle_fault", "FILTER_MAJOR_CYCLE_FAULT", 4, 1, 0x10),
    (types.Cv7ContinuousBitSystem2, "filter_minor_cycle_fault", "FILTER_MINOR_CYCLE_FAULT", 5, 1, 0x20),
    (types.Cv7ContinuousBitSystem2, "filter_data_rate_error", "FILTER_DATA_RATE_ERROR", 6, 1, 0x40),
    (types.Cv7ContinuousBitSystem2, "filter_process_stall", "FILTER_PROCESS_STALL", 7, 1, 0x80),
    (types.Cv7ContinuousBitSystem3, "gnss_subsystem_fault", "GNSS_SUBSYSTEM_FAULT", 0, 4, 0xF),
    (types.Cv7ContinuousBitSystem3, "gnss_main_process_fault", "GNSS_MAIN_PROCESS_FAULT", 0, 1, 0x1),
    (types.Cv7ContinuousBitSystem3, "gnss_receiver_1_stall", "GNSS_RECEIVER_1_STALL", 1, 1, 0x2),
    (types.Cv7ContinuousBitSystem3, "gnss_receiver_2_stall", "GNSS_RECEIVER_2_STALL", 2, 1, 0x4),
    (types.Cv7ContinuousBitSystem3, "reserved_27", "RESERVED_27", 3, 1, 0x8),
    (types.Cv7ContinuousBitSystem3, "reserved_28_31", "RESERVED_28_31", 4, 4, 0xF0),
    (types.EstimationControlFlags, "gyro_bias", "GYRO_BIAS", 0, 1, 0x1),
    (types.EstimationControlFlags, "accel_bias", "ACCEL_BIAS", 1, 1, 0x2),
    (types.EstimationControlFlags, "gyro_scale_factor", "GYRO_SCALE_FACTOR", 2, 1, 0x4),
    (types.EstimationControlFlags, "accel_scale_factor", "ACCEL_SCALE_FACTOR", 3, 1, 0x8),
    (types.EstimationControlFlags, "antenna_offset", "ANTENNA_OFFSET", 4, 1, 0x10),
    (types.EstimationControlFlags, "hard_iron_auto_cal", "HARD_IRON_AUTO_CAL", 5, 1, 0x20),
    (types.EstimationControlFlags, "soft_iron_auto_cal", "SOFT_IRON_AUTO_CAL", 6, 1, 0x40),
    (types.EstimationControlFlags, "reserved", "RESERVED", 7, 9, 0xFF80),
    (types.ExternalTimeDeltaValidFlags, "dt_nanos", "DT_NANOS", 0, 1, 0x1),
    (types.ExternalTimeDeltaValidFlags, "reserved", "RESERVED", 1, 15, 0xFFFE),
    (types.ExternalTimestampValidFlags, "nanoseconds", "NANOSECONDS", 0, 1, 0x1),
    (types.ExternalTimestampValidFlags, "reserved", "RESERVED", 1, 15, 0xFFFE),
    (types.FilterAidingMeasurementIndicator, "enabled", "ENABLED", 0, 1, 0x1),
    (types.FilterAidingMeasurementIndicator, "used", "USED", 1, 1, 0x2),
    (types.FilterAidingMeasurementIndicator, "residual_high_warning", "RESIDUAL_HIGH_WARNING", 2, 1, 0x4),
    (types.FilterAidingMeasurementIndicator, "sample_time_warning", "SAMPLE_TIME_WARNING", 3, 1, 0x8),
    (types.FilterAidingMeasurementIndicator, "configuration_error", "CONFIGURATION_ERROR", 4, 1, 0x10),
    (types.FilterAidingMeasurementIndicator, "max_num_meas_exceeded", "MAX_NUM_MEAS_EXCEEDED", 5, 1, 0x20),
    (types.FilterDualAntennaStatusFlags, "rcv_1_data_valid", "RCV_1_DATA_VALID", 0, 1, 0x1),
    (types.FilterDualAntennaStatusFlags, "rcv_2_data_valid", "RCV_2_DATA_VALID", 1, 1, 0x2),
    (types.FilterDualAntennaStatusFlags, "antenna_offsets_valid", "ANTENNA_OFFSETS_VALID", 2, 1, 0x4),
    (types.FilterGnssAidingStatusFlags, "tight_coupling", "TIGHT_COUPLING", 0, 1, 0x1),
    (types.FilterGnssAidingStatusFlags, "differential", "DIFFERENTIAL", 1, 1, 0x2),
    (types.FilterGnssAidingStatusFlags, "integer_fix", "INTEGER_FIX", 2, 1, 0x4),
    (types.FilterGnssAidingStatusFlags, "gps_l1", "GPS_L1", 3, 1, 0x8),
    (types.FilterGnssAidingStatusFlags, "gps_l2", "GPS_L2", 4, 1, 0x10),
    (types.FilterGnssAidingStatusFlags, "gps_l5", "GPS_L5", 5, 1, 0x20),
    (types.FilterGnssAidingStatusFlags, "glo_l1", "GLO_L1", 6, 1, 0x40),
    (types.FilterGnssAidingStatusFlags, "glo_l2", "GLO_L2", 7, 1, 0x80),
    (types.FilterGnssAidingStatusFlags, "gal_e1", "GAL_E1", 8, 1, 0x100),
    (types.FilterGnssAidingStatusFlags, "gal_e5", "GAL_E5", 9, 1, 0x200),
    (types.FilterGnssAidingStatusFlags, "gal_e6", "GAL_E6", 10, 1, 0x400),
    (types.FilterGnssAidingStatusFlags, "bei_b1", "BEI_B1", 11, 1, 0x800),
    (types.FilterGnssAidingStatusFlags, "bei_b2", "BEI_B2", 12, 1, 0x1000),
    (types.FilterGnssAidingStatusFlags, "bei_b3", "BEI_B3", 13, 1, 0x2000),
    (types.FilterGnssAidingStatusFlags, "no_fix", "NO_FIX", 14, 1, 0x4000),
    (types.FilterGnssAidingStatusFlags, "config_error", "CONFIG_ERROR", 15, 1, 0x8000),
    (types.FilterHeadingSourceFlags, "magnetometer", "MAGNETOMETER", 0, 1, 0x1),
    (types.FilterHeadingSourceFlags, "gnss_velocity", "GNSS_VELOCITY", 1, 1, 0x2),
    (types.FilterHeadingSourceFlags, "external", "EXTERNAL", 2, 1, 0x4),
    (types.FilterHeadingUpdateValidFlags, "updated_within_2s", "UPDATED_WITHIN_2S", 0, 1, 0x1),
    (types.FilterOutputValidFlags, "valid", "VALID", 0, 1, 0x1),
    (types.FilterStatusFlagsCv7, "filter_condition", "FILTER_CONDITION", 0, 2, 0x3),
    (types.FilterStatusFlagsCv7, "roll_pitch_warning", "ROLL_PITCH_WARNING", 2, 1, 0x4),
    (types.FilterStatusFlagsCv7, "heading_warning", "HEADING_WARNING", 3, 1, 0x8),
    (types.FilterStatusFlagsCv7, "position_warning", "POSITION_WARNING", 4, 1, 0x10),
    (types.FilterStatusFlagsCv7, "velocity_warning", "VELOCITY_WARNING", 5, 1, 0x20),
    (types.FilterStatusFlagsCv7, "imu_bias_warning", "IMU_BIAS_WARNING", 6, 1, 0x40),
    (types.FilterStatusFlagsCv7, "gnss_clk_warning", "GNSS_CLK_WARNING", 7, 1, 0x80),
    (types.FilterStatusFlagsCv7, "antenna_lever_arm_warning", "ANTENNA_LEVER_ARM_WARNING", 8, 1, 0x100),
    (types.FilterStatusFlagsCv7, "mounting_transform_warning", "MOUNTING_TRANSFORM_WARNING", 9, 1, 0x200),
    (types.FilterStatusFlagsCv7, "time_sync_warning", "TIME_SYNC_WARNING", 10, 1, 0x400),
    (types.FilterStatusFlagsCv7, "reserved", "RESERVED", 11, 1, 0x800),
    (types.FilterStatusFlagsCv7, "solution_error", "SOLUTION_ERROR", 12, 4, 0xF000),
    (types.FilterStatusFlagsGx5, "run_imu_unavailable", "RUN_IMU_UNAVAILABLE", 0, 1, 0x1),
    (types.FilterStatusFlagsGx5, "run_gps_unavailable", "RUN_GPS_UNAVAILABLE", 1, 1, 0x2),
    (types.FilterStatusFlagsGx5, "reserved", "RESERVED", 2, 1, 0x4),
    (types.FilterStatusFlagsGx5, "run_matrix_singularity", "RUN_MATRIX_SINGULARITY", 3, 1, 0x8),
    (types.FilterStatusFlagsGx5, "run_position_covariance_warning", "RUN_POSITION_COVARIANCE_WARNING", 4, 1, 0x10),
    (types.FilterStatusFlagsGx5, "run_velocity_covariance_warning", "RUN_VELOCITY_COVARIANCE_WARNING", 5, 1, 0x20),
    (types.FilterStatusFlagsGx5, "run_attitude_covariance_warning", "RUN_ATTITUDE_COVARIANCE_WARNING", 6, 1, 0x40),
    (types.FilterStatusFlagsGx5, "run_nan_in_solution_warning", "RUN_NAN_IN_SOLUTION_WARNING", 7, 1, 0x80),
    (types.FilterStatusFlagsGx5, "run_gyro_bias_est_high_warning", "RUN_GYRO_BIAS_EST_HIGH_WARNING", 8, 1, 0x100),
    (types.FilterStatusFlagsGx5, "run_accel_bias_est_high_warning", "RUN_ACCEL_BIAS_EST_HIGH_WARNING", 9, 1, 0x200),
    (
        types.FilterStatusFlagsGx5,
        "run_gyro_scale_factor_est_high_warning",
        "RUN_GYRO_SCALE_FACTOR_EST_HIGH_WARNING",
        10,
        1,
        0x400,
    ),
    (
        types.FilterStatusFlagsGx5,
        "run_accel_scale_factor_est_high_warning",
        "RUN_ACCEL_SCALE_FACTOR_EST_HIGH_WARNING",
        11,
        1,
        0x800,
    ),
    (types.FilterStatusFlagsGx5, "run_mag_bias_est_high_warning", "RUN_MAG_BIAS_EST_HIGH_WARNING", 12, 1, 0x1000),
    (
        types.FilterStatusFlagsGx5,
        "run_ant_offset_correction_est_high_warning",
        "RUN_ANT_OFFSET_CORRECTION_EST_HIGH_WARNING",
        13,
        1,
        0x2000,
    ),
    (
        types.FilterStatusFlagsGx5,
        "run_mag_hard_iron_est_high_warning",
        "RUN_MAG_HARD_IRON_EST_HIGH_WARNING",
        14,
        1,
        0x4000,
    ),
    (
        types.FilterStatusFlagsGx5,
        "run_mag_soft_iron_est_high_warning",
        "RUN_MAG_SOFT_IRON_EST_HIGH_WARNING",
        15,
        1,
        0x8000,
    ),
    (types.FilterStatusFlagsGx5, "init_no_attitude", "INIT_NO_ATTITUDE", 12, 1, 0x1000),
    (types.FilterStatusFlagsGx5, "init_no_position_velocity", "INIT_NO_POSITION_VELOCITY", 13, 1, 0x2000),
    (types.GnssBaseStationIndicators, "gps", "GPS", 0, 1, 0x1),
    (types.GnssBaseStationIndicators, "glonass", "GLONASS", 1, 1, 0x2),
    (types.GnssBaseStationIndicators, "galileo", "GALILEO", 2, 1, 0x4),
    (types.GnssBaseStationIndicators, "beidou", "BEIDOU", 3, 1, 0x8),
    (types.GnssBaseStationIndicators, "ref_station", "REF_STATION", 4, 1, 0x10),
    (types.GnssBaseStationIndicators, "single_receiver", "SINGLE_RECEIVER", 5, 1, 0x20),
    (types.GnssBaseStationIndicators, "quarter_cycle_bit1", "QUARTER_CYCLE_BIT1", 6, 1, 0x40),
    (types.GnssBaseStationIndicators, "quarter_cycle_bit2", "QUARTER_CYCLE_BIT2", 7, 1, 0x80),
    (types.GnssBaseStationIndicators, "quarter_cycle_bits", "QUARTER_CYCLE_BITS", 6, 2, 0xC0),
    (types.GnssBaseStationIndicators, "reserved", "RESERVED", 8, 8, 0xFF00),
    (types.GnssBaseStationInfoValidFlags, "tow", "TOW", 0, 1, 0x1),
    (types.GnssBaseStationInfoValidFlags, "week_number", "WEEK_NUMBER", 1, 1, 0x2),
    (types.GnssBaseStationInfoValidFlags, "ecef_position", "ECEF_POSITION", 2, 1, 0x4),
    (types.GnssBaseStationInfoValidFlags, "height", "HEIGHT", 3, 1, 0x8),
    (types.GnssBaseStationInfoValidFlags, "station_id", "STATION_ID", 4, 1, 0x10),
    (types.GnssBaseStationInfoValidFlags, "indicators", "INDICATORS", 5, 1, 0x20),
    (types.GnssBaseStationInfoValidFlags, "flags", "FLAGS", 0, 6, 0x3F),
    (types.GnssBaseStationInfoValidFlags, "reserved", "RESERVED", 6, 10, 0xFFC0),
    (types.GnssBeidouSignals, "b1", "B1", 0, 1, 0x1),
    (types.GnssBeidouSignals, "b2", "B2", 1, 1, 0x2),
    (types.GnssBeidouSignals, "b2a", "B2A", 2, 1, 0x4),
    (types.GnssClockInfo2ValidFlags, "bias", "BIAS", 0, 1, 0x1),
    (types.GnssClockInfo2ValidFlags, "drift", "DRIFT", 1, 1, 0x2),
    (types.GnssClockInfo2ValidFlags, "bias_accuracy", "BIAS_ACCURACY", 2, 1, 0x4),
    (types.GnssClockInfo2ValidFlags, "drift_accuracy", "DRIFT_ACCURACY", 3, 1, 0x8),
    (types.GnssClockInfo2ValidFlags, "flags", "FLAGS", 0, 4, 0xF),
    (types.GnssClockInfo2ValidFlags, "reserved", "RESERVED", 4, 12, 0xFFF0),
    (types.GnssClockInfoValidFlags, "bias", "BIAS", 0, 1, 0x1),
    (types.GnssClockInfoValidFlags, "drift", "DRIFT", 1, 1, 0x2),
    (types.GnssClockInfoValidFlags, "accuracy_estimate", "ACCURACY_ESTIMATE", 2, 1, 0x4),
    (types.GnssClockInfoValidFlags, "reserved", "RESERVED", 3, 13, 0xFFF8),
    (types.GnssDgnssChannelStatusValidFlags, "sv_id", "SV_ID", 0, 1, 0x1),
    (types.GnssDgnssChannelStatusValidFlags, "age", "AGE", 1, 1, 0x2),
    (types.GnssDgnssChannelStatusValidFlags, "pseudorange_correction", "PSEUDORANGE_CORRECTION", 2, 1, 0x4),
    (types.GnssDgnssChannelStatusValidFlags, "pseudorange_rate_correction", "PSEUDORANGE_RATE_CORRECTION", 3, 1, 0x8),
    (types.GnssDgnssChannelStatusValidFlags, "reserved", "RESERVED", 4, 12, 0xFFF0),
    (types.GnssDgnssInfoValidFlags, "latest_age", "LATEST_AGE", 0, 1, 0x1),
    (types.GnssDgnssInfoValidFlags, "base_station_id", "BASE_STATION_ID", 1, 1, 0x2),
    (types.GnssDgnssInfoValidFlags, "base_station_status", "BASE_STATION_STATUS", 2, 1, 0x4),
    (types.GnssDgnssInfoValidFlags, "num_channels", "NUM_CHANNELS", 3, 1, 0x8),
    (types.GnssDgnssInfoValidFlags, "reserved", "RESERVED", 4, 12, 0xFFF0),
    (types.GnssDopValidFlags, "gdop", "GDOP", 0, 1, 0x1),
    (types.GnssDopValidFlags, "pdop", "PDOP", 1, 1, 0x2),
    (types.GnssDopValidFlags, "hdop", "HDOP", 2, 1, 0x4),
    (types.GnssDopValidFlags, "vdop", "VDOP", 3, 1, 0x8),
    (types.GnssDopValidFlags, "tdop", "TDOP", 4, 1, 0x10),
    (types.GnssDopValidFlags, "ndop", "NDOP", 5, 1, 0x20),
    (types.GnssDopValidFlags, "edop", "EDOP", 6, 1, 0x40),
    (types.GnssDopValidFlags, "flags", "FLAGS", 0, 7, 0x7F),
    (types.GnssDopValidFlags, "reserved", "RESERVED", 7, 9, 0xFF80),
    (types.GnssEcefPositionValidFlags, "position", "POSITION", 0, 1, 0x1),
    (types.GnssEcefPositionValidFlags, "position_accuracy", "POSITION_ACCURACY", 1, 1, 0x2),
    (types.GnssEcefPositionValidFlags, "flags", "FLAGS", 0, 2, 0x3),
    (types.GnssEcefPositionValidFlags, "reserved", "RESERVED", 2, 14, 0xFFFC),
    (types.GnssEcefVelocityValidFlags, "velocity", "VELOCITY", 0, 1, 0x1),
    (types.GnssEcefVelocityValidFlags, "velocity_accuracy", "VELOCITY_ACCURACY", 1, 1, 0x2),
    (types.GnssEcefVelocityValidFlags, "flags", "FLAGS", 0, 2, 0x3),
    (types.GnssEcefVelocityValidFlags, "reserved", "RESERVED", 2, 14, 0xFFFC),
    (types.GnssEphemerisValidFlags, "ephemeris", "EPHEMERIS", 0, 1, 0x1),
    (types.GnssEphemerisValidFlags, "modern_data", "MODERN_DATA", 1, 1, 0x2),
    (types.GnssEphemerisValidFlags, "isc_l5", "ISC_L5", 2, 1, 0x4),
    (types.GnssEphemerisValidFlags, "flags", "FLAGS", 0, 3, 0x7),
    (types.GnssEphemerisValidFlags, "reserved", "RESERVED", 3, 13, 0xFFF8),
    (types.GnssFixFlags, "sbas_used", "SBAS_USED", 0, 1, 0x1),
    (types.GnssFixFlags, "dgnss_used", "DGNSS_USED", 1, 1, 0x2),
    (types.GnssFixFlags, "reserved", "RESERVED", 2, 14, 0xFFFC),
    (types.GnssFixInfoValidFlags, "fix_type", "FIX_TYPE", 0, 1, 0x1),
    (types.GnssFixInfoValidFlags, "num_sv", "NUM_SV", 1, 1, 0x2),
    (types.GnssFixInfoValidFlags, "fix_flags", "FIX_FLAGS", 2, 1, 0x4),
    (types.GnssFixInfoValidFlags, "flags", "FLAGS", 0, 3, 0x7),
    (types.GnssFixInfoValidFlags, "reserved", "RESERVED", 3, 13, 0xFFF8),
    (types.GnssGalileoSignals, "e1", "E1", 0, 1, 0x1),
    (types.GnssGalileoSignals, "e5b", "E5B", 1, 1, 0x2),
    (types.GnssGalileoSignals, "e5a", "E5A", 2, 1, 0x4),
    (types.GnssGlonassEphemerisValidFlags, "ephemeris", "EPHEMERIS", 0, 1, 0x1),
    (types.GnssGlonassEphemerisValidFlags, "flags", "FLAGS", 0, 1, 0x1),
    (types.GnssGlonassEphemerisValidFlags, "reserved", "RESERVED", 1, 15, 0xFFFE),
    (types.GnssGlonassSignals, "l1of", "L1OF", 0, 1, 0x1),
    (types.GnssGlonassSignals, "l2of", "L2OF", 1, 1, 0x2),
    (types.GnssGpsSignals, "l1ca", "L1CA", 0, 1, 0x1),
    (types.GnssGpsSignals, "l2c", "L2C", 1, 1, 0x2),
    (types.GnssGpsSignals, "l5", "L5", 2, 1, 0x4),
    (types.GnssGpsTimeValidFlags, "tow", "TOW", 0, 1, 0x1),
    (types.GnssGpsTimeValidFlags, "week_number", "WEEK_NUMBER", 1, 1, 0x2),
    (types.GnssGpsTimeValidFlags, "flags", "FLAGS", 0, 2, 0x3),
    (types.GnssGpsTimeValidFlags, "reserved", "RESERVED", 2, 14, 0xFFFC),
    (types.GnssHardwareStatusValidFlags, "sensor_state", "SENSOR_STATE", 0, 1, 0x1),
    (types.GnssHardwareStatusValidFlags, "antenna_state", "ANTENNA_STATE", 1, 1, 0x2),
    (types.GnssHardwareStatusValidFlags, "antenna_power", "ANTENNA_POWER", 2, 1, 0x4),
    (types.GnssHardwareStatusValidFlags, "flags", "FLAGS", 0, 3, 0x7),
    (types.GnssHardwareStatusValidFlags, "reserved", "RESERVED", 3, 13, 0xFFF8),
    (types.GnssLeapSecondsValidFlags, "reserved_0", "RESERVED_0", 0, 1, 0x1),
    (types.GnssLeapSecondsValidFlags, "leap_seconds", "LEAP_SECONDS", 1, 1, 0x2),
    (types.GnssLeapSecondsValidFlags, "reserved", "RESERVED", 2, 14, 0xFFFC),
    (types.GnssLlhPositionValidFlags, "lat_lon", "LAT_LON", 0, 1, 0x1),
    (types.GnssLlhPositionValidFlags, "ellipsoid_height", "ELLIPSOID_HEIGHT", 1, 1, 0x2),
    (types.GnssLlhPositionValidFlags, "msl_height", "MSL_HEIGHT", 2, 1, 0x4),
    (types.GnssLlhPositionValidFlags, "horizontal_accuracy", "HORIZONTAL_ACCURACY", 3, 1, 0x8),
    (types.GnssLlhPositionValidFlags, "vertical_accuracy", "VERTICAL_ACCURACY", 4, 1, 0x10),
    (types.GnssLlhPositionValidFlags, "flags", "FLAGS", 0, 5, 0x1F),
    (types.GnssLlhPositionValidFlags, "reserved", "RESERVED", 5, 11, 0xFFE0),
    (types.GnssNedVelocityValidFlags, "velocity", "VELOCITY", 0, 1, 0x1),
    (types.GnssNedVelocityValidFlags, "speed_3d", "SPEED_3D", 1, 1, 0x2),
    (types.GnssNedVelocityValidFlags, "ground_speed", "GROUND_SPEED", 2, 1, 0x4),
    (types.GnssNedVelocityValidFlags, "heading", "HEADING", 3, 1, 0x8),
    (types.GnssNedVelocityValidFlags, "speed_accuracy", "SPEED_ACCURACY", 4, 1, 0x10),
    (types.GnssNedVelocityValidFlags, "heading_accuracy", "HEADING_ACCURACY", 5, 1, 0x20),
    (types.GnssNedVelocityValidFlags, "flags", "FLAGS", 0, 6, 0x3F),
    (types.GnssNedVelocityValidFlags, "reserved", "RESERVED", 6, 10, 0xFFC0),
    (types.GnssRawValidFlags, "tow", "TOW", 0, 1, 0x1),
    (types.GnssRawValidFlags, "week_number", "WEEK_NUMBER", 1, 1, 0x2),
    (types.GnssRawValidFlags, "receiver_id", "RECEIVER_ID", 2, 1, 0x4),
    (types.GnssRawValidFlags, "tracking_channel", "TRACKING_CHANNEL", 3, 1, 0x8),
    (types.GnssRawValidFlags, "gnss_id", "GNSS_ID", 4, 1, 0x10),
    (types.GnssRawValidFlags, "satellite_id", "SATELLITE_ID", 5, 1, 0x20),
    (types.GnssRawValidFlags, "signal_id", "SIGNAL_ID", 6, 1, 0x40),
    (types.GnssRawValidFlags, "signal_strength", "SIGNAL_STRENGTH", 7, 1, 0x80),
    (types.GnssRawValidFlags, "quality", "QUALITY", 8, 1, 0x100),
    (types.GnssRawValidFlags, "pseudorange", "PSEUDORANGE", 9, 1, 0x200),
    (types.GnssRawValidFlags, "carrier_phase", "CARRIER_PHASE", 10, 1, 0x400),
    (types.GnssRawValidFlags, "doppler", "DOPPLER", 11, 1, 0x800),
    (types.GnssRawValidFlags, "range_uncertainty", "RANGE_UNCERTAINTY", 12, 1, 0x1000),
    (types.GnssRawValidFlags, "carrier_phase_uncertainty", "CARRIER_PHASE_UNCERTAINTY", 13, 1, 0x2000),
    (types.GnssRawValidFlags, "doppler_uncertainty", "DOPPLER_UNCERTAINTY", 14, 1, 0x4000),
    (types.GnssRawValidFlags, "lock_time", "LOCK_TIME", 15, 1, 0x8000),
    (types.GnssRawValidFlags, "flags", "FLAGS", 0, 16, 0xFFFF),
    (types.GnssSatelliteStatusValidFlags, "tow", "TOW", 0, 1, 0x1),
    (types.GnssSatelliteStatusValidFlags, "week_number", "WEEK_NUMBER", 1, 1, 0x2),
    (types.GnssSatelliteStatusValidFlags, "gnss_id", "GNSS_ID", 2, 1, 0x4),
    (types.GnssSatelliteStatusValidFlags, "satellite_id", "SATELLITE_ID", 3, 1, 0x8),
    (types.GnssSatelliteStatusValidFlags, "elevation", "ELEVATION", 4, 1, 0x10),
    (types.GnssSatelliteStatusValidFlags, "azimuth", "AZIMUTH", 5, 1, 0x20),
    (types.GnssSatelliteStatusValidFlags, "health", "HEALTH", 6, 1, 0x40),
    (types.GnssSatelliteStatusValidFlags, "flags", "FLAGS", 0, 7, 0x7F),
    (types.GnssSatelliteStatusValidFlags, "reserved", "RESERVED", 7, 9, 0xFF80),
    (types.GnssSbasInfoValidFlags, "tow", "TOW", 0, 1, 0x1),
    (types.GnssSbasInfoValidFlags, "week_number", "WEEK_NUMBER", 1, 1, 0x2),
    (types.GnssSbasInfoValidFlags, "sbas_system", "SBAS_SYSTEM", 2, 1, 0x4),
    (types.GnssSbasInfoValidFlags, "sbas_id", "SBAS_ID", 3, 1, 0x8),
    (types.GnssSbasInfoValidFlags, "count", "COUNT", 4, 1, 0x10),
    (types.GnssSbasInfoValidFlags, "sbas_status", "SBAS_STATUS", 5, 1, 0x20),
    (types.GnssSbasInfoValidFlags, "flags", "FLAGS", 0, 6, 0x3F),
    (types.GnssSbasInfoValidFlags, "reserved", "RESERVED", 6, 10, 0xFFC0),
    (types.GnssSbasStatus, "range_available", "RANGE_AVAILABLE", 0, 1, 0x1),
    (types.GnssSbasStatus, "corrections_available", "CORRECTIONS_AVAILABLE", 1, 1, 0x2),
    (types.GnssSbasStatus, "integrity_available", "INTEGRITY_AVAILABLE", 2, 1, 0x4),
    (types.GnssSbasStatus, "test_mode", "TEST_MODE", 3, 1, 0x8),
    (types.GnssSbasStatus, "reserved", "RESERVED", 4, 4, 0xF0),
    (types.GnssSvFlags, "used_for_navigation", "USED_FOR_NAVIGATION", 0, 1, 0x1),
    (types.GnssSvFlags, "healthy", "HEALTHY", 1, 1, 0x2),
    (types.GnssSvFlags, "reserved", "RESERVED", 2, 14, 0xFFFC),
    (types.GnssSvInfoValidFlags, "channel", "CHANNEL", 0, 1, 0x1),
    (types.GnssSvInfoValidFlags, "sv_id", "SV_ID", 1, 1, 0x2),
    (types.GnssSvInfoValidFlags, "reserved_2", "RESERVED_2", 2, 1, 0x4),
    (types.GnssSvInfoValidFlags, "carrier_to_noise_ratio", "CARRIER_TO_NOISE_RATIO", 3, 1, 0x8),
    (types.GnssSvInfoValidFlags, "azimuth", "AZIMUTH", 4, 1, 0x10),
    (types.GnssSvInfoValidFlags, "elevation", "ELEVATION", 5, 1, 0x20),
    (types.GnssSvInfoValidFlags, "sv_flags", "SV_FLAGS", 6, 1, 0x40),
    (types.GnssSvInfoValidFlags, "reserved", "RESERVED", 7, 9, 0xFF80),
    (types.GnssUtcTimeValidFlagsCv7, "gnss_date_time", "GNSS_DATE_TIME", 0, 1, 0x1),
    (types.GnssUtcTimeValidFlagsCv7, "leap_seconds_known", "LEAP_SECONDS_KNOWN", 1, 1, 0x2),
    (types.GnssUtcTimeValidFlagsCv7, "flags", "FLAGS", 0, 2, 0x3),
    (types.GnssUtcTimeValidFlagsCv7, "reserved", "RESERVED", 2, 14, 0xFFFC),
    (types.GnssUtcTimeValidFlagsGx5, "date_valid", "DATE_VALID", 0, 1, 0x1),
    (types.GnssUtcTimeValidFlagsGx5, "time_valid", "TIME_VALID", 1, 1, 0x2),
    (types.GnssUtcTimeValidFlagsGx5, "reserved", "RESERVED", 2, 14, 0xFFFC),
    (types.GpioPinMode, "open_drain", "OPEN_DRAIN", 0, 1, 0x1),
    (types.GpioPinMode, "pulldown", "PULLDOWN", 1, 1, 0x2),
    (types.GpioPinMode, "pullup", "PULLUP", 2, 1, 0x4),
    (types.GpioPinStates, "pin_1", "PIN_1", 0, 1, 0x1),
    (types.GpioPinStates, "pin_2", "PIN_2", 1, 1, 0x2),
    (types.GpioPinStates, "pin_3", "PIN_3", 2, 1, 0x4),
    (types.GpioPinStates, "pin_4", "PIN_4", 3, 1, 0x8),
    (types.GpioPinStates, "reserved", "RESERVED", 4, 4, 0xF0),
    (types.Gx5BitFlags, "processor_wdt_reset", "PROCESSOR_WDT_RESET", 0, 1, 0x1),
    (types.Gx5BitFlags, "imu_communication_fault", "IMU_COMMUNICATION_FAULT", 8, 1, 0x100),
    (types.Gx5BitFlags, "magnetometer_fault", "MAGNETOMETER_FAULT", 9, 1, 0x200),
    (types.Gx5BitFlags, "pressure_sensor_fault", "PRESSURE_SENSOR_FAULT", 10, 1, 0x400),
    (types.Gx5BitFlags, "filter_solution_fault", "FILTER_SOLUTION_FAULT", 24, 1, 0x1000000),
    (types.HeadingAlignmentMethods, "dual_antenna", "DUAL_ANTENNA", 0, 1, 0x1),
    (types.HeadingAlignmentMethods, "kinematic", "KINEMATIC", 1, 1, 0x2),
    (types.HeadingAlignmentMethods, "magnetometer", "MAGNETOMETER", 2, 1, 0x4),
    (types.HeadingAlignmentMethods, "external", "EXTERNAL", 3, 1, 0x8),
    (types.OdometerDataValidFlags, "valid", "VALID", 0, 1, 0x1),
    (types.OdometerDataValidFlags, "reserved", "RESERVED", 1, 15, 0xFFFE),
    (types.OverrangeStatusFlags, "accel_x", "ACCEL_X", 0, 1, 0x1),
    (types.OverrangeStatusFlags, "accel_y", "ACCEL_Y", 1, 1, 0x2),
    (types.OverrangeStatusFlags, "accel_z", "ACCEL_Z", 2, 1, 0x4),
    (types.OverrangeStatusFlags, "reserved_3", "RESERVED_3", 3, 1, 0x8),
    (types.OverrangeStatusFlags, "gyro_x", "GYRO_X", 4, 1, 0x10),
    (types.OverrangeStatusFlags, "gyro_y", "GYRO_Y", 5, 1, 0x20),
    (types.OverrangeStatusFlags, "gyro_z", "GYRO_Z", 6, 1, 0x40),
    (types.OverrangeStatusFlags, "reserved_7", "RESERVED_7", 7, 1, 0x80),
    (types.OverrangeStatusFlags, "mag_x", "MAG_X", 8, 1, 0x100),
    (types.OverrangeStatusFlags, "mag_y", "MAG_Y", 9, 1, 0x200),
    (types.OverrangeStatusFlags, "mag_z", "MAG_Z", 10, 1, 0x400),
    (types.OverrangeStatusFlags, "reserved_11", "RESERVED_11", 11, 1, 0x800),
    (types.OverrangeStatusFlags, "press", "PRESS", 12, 1, 0x1000),
    (types.OverrangeStatusFlags, "reserved_13_15", "RESERVED_13_15", 13, 3, 0xE000),
    (types.RtkCorrectionsEpochStatus, "antenna_location_received", "ANTENNA_LOCATION_RECEIVED", 0, 1, 0x1),
    (types.RtkCorrectionsEpochStatus, "antenna_description_received", "ANTENNA_DESCRIPTION_RECEIVED", 1, 1, 0x2),
    (types.RtkCorrectionsEpochStatus, "gps_received", "GPS_RECEIVED", 2, 1, 0x4),
    (types.RtkCorrectionsEpochStatus, "glonass_received", "GLONASS_RECEIVED", 3, 1, 0x8),
    (types.RtkCorrectionsEpochStatus, "galileo_received", "GALILEO_RECEIVED", 4, 1, 0x10),
    (types.RtkCorrectionsEpochStatus, "beidou_received", "BEIDOU_RECEIVED", 5, 1, 0x20),
    (types.RtkCorrectionsEpochStatus, "using_gps_msm_messages", "USING_GPS_MSM_MESSAGES", 6, 1, 0x40),
    (types.RtkCorrectionsEpochStatus, "using_glonass_msm_messages", "USING_GLONASS_MSM_MESSAGES", 7, 1, 0x80),
    (types.RtkCorrectionsEpochStatus, "dongle_status_read_failed", "DONGLE_STATUS_READ_FAILED", 8, 1, 0x100),
    (types.RtkCorrectionsEpochStatus, "reserved", "RESERVED", 9, 7, 0xFE00),
    (types.RtkCorrectionsStatusValidFlags, "tow", "TOW", 0, 1, 0x1),
    (types.RtkCorrectionsStatusValidFlags, "week_number", "WEEK_NUMBER", 1, 1, 0x2),
    (types.RtkCorrectionsStatusValidFlags, "epoch_status", "EPOCH_STATUS", 2, 1, 0x4),
    (types.RtkCorrectionsStatusValidFlags, "dongle_status", "DONGLE_STATUS", 3, 1, 0x8),
    (types.RtkCorrectionsStatusValidFlags, "gps_latency", "GPS_LATENCY", 4, 1, 0x10),
    (types.RtkCorrectionsStatusValidFlags, "glonass_latency", "GLONASS_LATENCY", 5, 1, 0x20),
    (types.RtkCorrectionsStatusValidFlags, "galileo_latency", "GALILEO_LATENCY", 6, 1, 0x40),
    (types.RtkCorrectionsStatusValidFlags, "beidou_latency", "BEIDOU_LATENCY", 7, 1, 0x80),
    (types.RtkCorrectionsStatusValidFlags, "flags", "FLAGS", 0, 8, 0xFF),
    (types.RtkCorrectionsStatusValidFlags, "reserved", "RESERVED", 8, 8, 0xFF00),
    (types.SbasOptions, "enable_ranging", "ENABLE_RANGING", 0, 1, 0x1),
    (types.SbasOptions, "enable_corrections", "ENABLE_CORRECTIONS", 1, 1, 0x2),
    (types.SbasOptions, "apply_integrity", "APPLY_INTEGRITY", 2, 1, 0x4),
    (types.SensorGpsTimestampFlags, "pps_valid", "PPS_VALID", 0, 1, 0x1),
    (types.SensorGpsTimestampFlags, "time_refresh", "TIME_REFRESH", 1, 1, 0x2),
    (types.SensorGpsTimestampFlags, "time_initialized", "TIME_INITIALIZED", 2, 1, 0x4),
    (types.SensorGpsTimestampFlags, "tow_valid", "TOW_VALID", 3, 1, 0x8),
    (types.SensorGpsTimestampFlags, "week_number_valid", "WEEK_NUMBER_VALID", 4, 1, 0x10),
    (types.SensorGpsTimestampFlags, "reserved", "RESERVED", 5, 11, 0xFFE0),
    (types.SharedGpsTimestampValidFlags, "tow", "TOW", 0, 1, 0x1),
    (types.SharedGpsTimestampValidFlags, "week_number", "WEEK_NUMBER", 1, 1, 0x2),
    (types.SharedGpsTimestampValidFlags, "time_valid", "TIME_VALID", 0, 2, 0x3),
    (types.SharedGpsTimestampValidFlags, "reserved", "RESERVED", 2, 14, 0xFFFC),
    (types.TareAxes, "roll", "ROLL", 0, 1, 0x1),
    (types.TareAxes, "pitch", "PITCH", 1, 1, 0x2),
    (types.TareAxes, "yaw", "YAW", 2, 1, 0x4),
    (types.TriggerStatus, "active", "ACTIVE", 0, 1, 0x1),
    (types.TriggerStatus, "enabled", "ENABLED", 1, 1, 0x2),
    (types.TriggerStatus, "test", "TEST", 2, 1, 0x4),
]
