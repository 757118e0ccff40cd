"""Typed round trips (generated): every layout class with sample values; every bitfield member."""

# ruff: noqa: I001  (whether the package is first- or third-party depends on where ruff runs)

import pytest
from mipcodec import aiding, base, filter, filter_data, gnss, reserved, sensor, system, threedm, types
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
        lambda: threedm.SensorToVehicleEulerResponse(roll=0.375, pitch=1024.0, yaw=-0.0),
    ),
    (
        "threedm.SensorToVehicleQuaternion",
        lambda: threedm.SensorToVehicleQuaternion(
            function=types.FunctionSelector.DEFAULT, q=[1.5, -2.25, 0.375, 1024.0]
        ),
    ),
    (
        "threedm.SensorToVehicleQuaternionResponse",
        lambda: threedm.SensorToVehicleQuaternionResponse(q=[-0.0, 1.5, -2.25, 0.375]),
    ),
    (
        "threedm.SensorToVehicleDcm",
        lambda: threedm.SensorToVehicleDcm(
            function=types.FunctionSelector.DEFAULT, dcm=[1024.0, -0.0, 1.5, -2.25, 0.375, 1024.0, -0.0, 1.5, -2.25]
        ),
    ),
    (
        "threedm.SensorToVehicleDcmResponse",
        lambda: threedm.SensorToVehicleDcmResponse(dcm=[0.375, 1024.0, -0.0, 1.5, -2.25, 0.375, 1024.0, -0.0, 1.5]),
    ),
    (
        "threedm.AccelBias_gx5_45",
        lambda: threedm.AccelBias_gx5_45(function=types.FunctionSelector.WRITE_NO_ACK, bias=[-2.25, 0.375, 1024.0]),
    ),
    (
        "threedm.AccelBias_cv7_ins",
        lambda: threedm.AccelBias_cv7_ins(function=types.FunctionSelector.DEFAULT, bias=[-0.0, 1.5, -2.25]),
    ),
    ("threedm.AccelBiasResponse", lambda: threedm.AccelBiasResponse(bias=[0.375, 1024.0, -0.0])),
    (
        "threedm.GyroBias_gx5_45",
        lambda: threedm.GyroBias_gx5_45(function=types.FunctionSelector.WRITE_NO_ACK, bias=[1.5, -2.25, 0.375]),
    ),
    (
        "threedm.GyroBias_cv7_ins",
        lambda: threedm.GyroBias_cv7_ins(function=types.FunctionSelector.DEFAULT, bias=[1024.0, -0.0, 1.5]),
    ),
    ("threedm.GyroBiasResponse", lambda: threedm.GyroBiasResponse(bias=[-2.25, 0.375, 1024.0])),
    ("threedm.CaptureGyroBias", lambda: threedm.CaptureGyroBias(averaging_time_ms=71)),
    (
        "threedm.MagHardIronOffset_gx5_45",
        lambda: threedm.MagHardIronOffset_gx5_45(
            function=types.FunctionSelector.WRITE_NO_ACK, offset=[1.5, -2.25, 0.375]
        ),
    ),
    (
        "threedm.MagHardIronOffset_cv7_ins",
        lambda: threedm.MagHardIronOffset_cv7_ins(function=types.FunctionSelector.DEFAULT, offset=[1024.0, -0.0, 1.5]),
    ),
    ("threedm.MagHardIronOffsetResponse", lambda: threedm.MagHardIronOffsetResponse(offset=[-2.25, 0.375, 1024.0])),
    (
        "threedm.MagSoftIronMatrix_gx5_45",
        lambda: threedm.MagSoftIronMatrix_gx5_45(
            function=types.FunctionSelector.WRITE_NO_ACK,
            matrix=[-0.0, 1.5, -2.25, 0.375, 1024.0, -0.0, 1.5, -2.25, 0.375],
        ),
    ),
    (
        "threedm.MagSoftIronMatrix_cv7_ins",
        lambda: threedm.MagSoftIronMatrix_cv7_ins(
            function=types.FunctionSelector.DEFAULT, matrix=[1024.0, -0.0, 1.5, -2.25, 0.375, 1024.0, -0.0, 1.5, -2.25]
        ),
    ),
    (
        "threedm.MagSoftIronMatrixResponse",
        lambda: threedm.MagSoftIronMatrixResponse(matrix=[0.375, 1024.0, -0.0, 1.5, -2.25, 0.375, 1024.0, -0.0, 1.5]),
    ),
    (
        "threedm.ConingScullingEnable",
        lambda: threedm.ConingScullingEnable(function=types.FunctionSelector.DEFAULT, enable=True),
    ),
    ("threedm.ConingScullingEnableResponse", lambda: threedm.ConingScullingEnableResponse(enable=False)),
    ("threedm.UartBaudrate", lambda: threedm.UartBaudrate(function=types.FunctionSelector.DEFAULT, baud=8)),
    ("threedm.UartBaudrateResponse", lambda: threedm.UartBaudrateResponse(baud=45)),
    (
        "threedm.GpioConfig",
        lambda: threedm.GpioConfig(
            function=types.FunctionSelector.DEFAULT,
            pin=82,
            feature=types.GpioFeature.UNUSED,
            behavior=types.GpioBehaviorUnused(behavior=types.GpioUnusedBehavior.UNUSED),
            pin_mode=types.GpioPinMode(0x4),
        ),
    ),
    (
        "threedm.GpioConfigResponse",
        lambda: threedm.GpioConfigResponse(
            pin=193,
            feature=types.GpioFeature.UNUSED,
            behavior=types.GpioBehaviorUnused(behavior=types.GpioUnusedBehavior.UNUSED),
            pin_mode=types.GpioPinMode(0x4),
        ),
    ),
    ("threedm.GpioState", lambda: threedm.GpioState(function=types.FunctionSelector.READ, pin=53, state=False)),
    ("threedm.GpioStateResponse", lambda: threedm.GpioStateResponse(pin=127, state=False)),
    (
        "threedm.OdometerConfig",
        lambda: threedm.OdometerConfig(
            function=types.FunctionSelector.DEFAULT,
            mode=types.OdometerMode.QUADRATURE,
            scaling=-2.25,
            uncertainty=0.375,
        ),
    ),
    (
        "threedm.OdometerConfigResponse",
        lambda: threedm.OdometerConfigResponse(mode=types.OdometerMode.DISABLED, scaling=-0.0, uncertainty=1.5),
    ),
    (
        "threedm.AdvancedLowpassFilter",
        lambda: threedm.AdvancedLowpassFilter(
            function=types.FunctionSelector.DEFAULT,
            target_descriptor=172,
            enable=False,
            manual=True,
            frequency=32,
            reserved=69,
        ),
    ),
    (
        "threedm.AdvancedLowpassFilterResponse",
        lambda: threedm.AdvancedLowpassFilterResponse(
            target_descriptor=106, enable=True, manual=False, frequency=217, reserved=3
        ),
    ),
    (
        "threedm.ComplementaryFilter",
        lambda: threedm.ComplementaryFilter(
            function=types.FunctionSelector.DEFAULT,
            pitch_roll_enable=True,
            heading_enable=False,
            pitch_roll_time_constant=1024.0,
            heading_time_constant=-0.0,
        ),
    ),
    (
        "threedm.ComplementaryFilterResponse",
        lambda: threedm.ComplementaryFilterResponse(
            pitch_roll_enable=True, heading_enable=False, pitch_roll_time_constant=0.375, heading_time_constant=1024.0
        ),
    ),
    (
        "threedm.SensorRange",
        lambda: threedm.SensorRange(
            function=types.FunctionSelector.DEFAULT, sensor=types.SensorRangeType.PRESS, setting=122
        ),
    ),
    (
        "threedm.SensorRangeResponse",
        lambda: threedm.SensorRangeResponse(sensor=types.SensorRangeType.ACCEL, setting=196),
    ),
    ("threedm.GetCalibratedSensorRanges", lambda: threedm.GetCalibratedSensorRanges(sensor=types.SensorRangeType.MAG)),
    (
        "threedm.CalibratedSensorRanges",
        lambda: threedm.CalibratedSensorRanges(
            sensor=types.SensorRangeType.PRESS,
            num_ranges=2,
            ranges=[types.SensorRangeEntry(setting=93, range=0.375), types.SensorRangeEntry(setting=204, range=1.5)],
        ),
    ),
    (
        "threedm.LowpassFilter",
        lambda: threedm.LowpassFilter(
            function=types.FunctionSelector.DEFAULT,
            desc_set=27,
            field_desc=64,
            enable=True,
            manual=False,
            frequency=1.5,
        ),
    ),
    (
        "threedm.LowpassFilterResponse",
        lambda: threedm.LowpassFilterResponse(desc_set=212, field_desc=249, enable=False, manual=True, frequency=1.5),
    ),
    (
        "threedm.PollImuData",
        lambda: threedm.PollImuData(
            option=types.Gx5PollOption.SUPPRESS_ACK,
            num_descriptors=2,
            descriptors=[
                types.Gx5PollDescriptor(descriptor=220, reserved=6),
                types.Gx5PollDescriptor(descriptor=80, reserved=117),
            ],
        ),
    ),
    (
        "threedm.PollGnssData",
        lambda: threedm.PollGnssData(
            option=types.Gx5PollOption.NORMAL,
            num_descriptors=2,
            descriptors=[
                types.Gx5PollDescriptor(descriptor=228, reserved=14),
                types.Gx5PollDescriptor(descriptor=88, reserved=125),
            ],
        ),
    ),
    (
        "threedm.PollFilterData",
        lambda: threedm.PollFilterData(
            option=types.Gx5PollOption.SUPPRESS_ACK,
            num_descriptors=2,
            descriptors=[
                types.Gx5PollDescriptor(descriptor=236, reserved=22),
                types.Gx5PollDescriptor(descriptor=96, reserved=133),
            ],
        ),
    ),
    (
        "threedm.PollNmeaData",
        lambda: threedm.PollNmeaData(
            suppress_ack=False,
            count=2,
            format_entries=[
                types.NmeaMessage(message_id=244, talker_id=30, source_desc_set=67, decimation=104),
                types.NmeaMessage(message_id=178, talker_id=215, source_desc_set=1, decimation=38),
            ],
        ),
    ),
    (
        "threedm.PollData",
        lambda: threedm.PollData(desc_set=75, suppress_ack=False, num_descriptors=2, descriptors=[149, 186]),
    ),
    ("threedm.GetImuBaseRate", lambda: threedm.GetImuBaseRate()),
    ("threedm.ImuBaseRate", lambda: threedm.ImuBaseRate(rate=223)),
    ("threedm.GetGnssBaseRate", lambda: threedm.GetGnssBaseRate()),
    ("threedm.GnssBaseRate", lambda: threedm.GnssBaseRate(rate=9)),
    ("threedm.GetFilterBaseRate", lambda: threedm.GetFilterBaseRate()),
    ("threedm.FilterBaseRate", lambda: threedm.FilterBaseRate(rate=46)),
    ("threedm.GetBaseRate", lambda: threedm.GetBaseRate(desc_set=83)),
    ("threedm.BaseRate", lambda: threedm.BaseRate(desc_set=120, rate=157)),
    (
        "threedm.ImuMessageFormat",
        lambda: threedm.ImuMessageFormat(
            function=types.FunctionSelector.DEFAULT,
            num_descriptors=2,
            descriptors=[
                types.DescriptorRate(descriptor=231, decimation=17),
                types.DescriptorRate(descriptor=91, decimation=128),
            ],
        ),
    ),
    (
        "threedm.ImuMessageFormatResponse",
        lambda: threedm.ImuMessageFormatResponse(
            num_descriptors=2,
            descriptors=[
                types.DescriptorRate(descriptor=202, decimation=239),
                types.DescriptorRate(descriptor=62, decimation=99),
            ],
        ),
    ),
    (
        "threedm.GnssMessageFormat",
        lambda: threedm.GnssMessageFormat(
            function=types.FunctionSelector.DEFAULT,
            num_descriptors=2,
            descriptors=[
                types.DescriptorRate(descriptor=173, decimation=210),
                types.DescriptorRate(descriptor=33, decimation=70),
            ],
        ),
    ),
    (
        "threedm.GnssMessageFormatResponse",
        lambda: threedm.GnssMessageFormatResponse(
            num_descriptors=2,
            descriptors=[
                types.DescriptorRate(descriptor=144, decimation=181),
                types.DescriptorRate(descriptor=4, decimation=41),
            ],
        ),
    ),
    (
        "threedm.FilterMessageFormat",
        lambda: threedm.FilterMessageFormat(
            function=types.FunctionSelector.DEFAULT,
            num_descriptors=2,
            descriptors=[
                types.DescriptorRate(descriptor=115, decimation=152),
                types.DescriptorRate(descriptor=226, decimation=12),
            ],
        ),
    ),
    (
        "threedm.FilterMessageFormatResponse",
        lambda: threedm.FilterMessageFormatResponse(
            num_descriptors=2,
            descriptors=[
                types.DescriptorRate(descriptor=86, decimation=123),
                types.DescriptorRate(descriptor=197, decimation=234),
            ],
        ),
    ),
    (
        "threedm.NmeaMessageFormat",
        lambda: threedm.NmeaMessageFormat(
            function=types.FunctionSelector.DEFAULT,
            count=2,
            format_entries=[
                types.NmeaMessage(message_id=57, talker_id=94, source_desc_set=131, decimation=168),
                types.NmeaMessage(message_id=242, talker_id=28, source_desc_set=65, decimation=102),
            ],
        ),
    ),
    (
        "threedm.NmeaMessageFormatResponse",
        lambda: threedm.NmeaMessageFormatResponse(
            count=2,
            format_entries=[
                types.NmeaMessage(message_id=176, talker_id=213, source_desc_set=250, decimation=36),
                types.NmeaMessage(message_id=110, talker_id=147, source_desc_set=184, decimation=221),
            ],
        ),
    ),
    (
        "threedm.MessageFormat",
        lambda: threedm.MessageFormat(
            function=types.FunctionSelector.DEFAULT,
            desc_set=7,
            num_descriptors=2,
            descriptors=[
                types.DescriptorRate(descriptor=81, decimation=118),
                types.DescriptorRate(descriptor=192, decimation=229),
            ],
        ),
    ),
    (
        "threedm.MessageFormatResponse",
        lambda: threedm.MessageFormatResponse(
            desc_set=15,
            num_descriptors=2,
            descriptors=[
                types.DescriptorRate(descriptor=89, decimation=126),
                types.DescriptorRate(descriptor=200, decimation=237),
            ],
        ),
    ),
    (
        "threedm.FactoryStreaming",
        lambda: threedm.FactoryStreaming(action=types.FactoryStreamingAction.OVERWRITE, reserved=60),
    ),
    (
        "threedm.DataStreamControl_gx5_45",
        lambda: threedm.DataStreamControl_gx5_45(
            function=types.FunctionSelector.DEFAULT,
            device_selector=types.Gx5StreamSelector.ESTIMATION_FILTER,
            enable=134,
        ),
    ),
    (
        "threedm.DataStreamControl_cv7_ins",
        lambda: threedm.DataStreamControl_cv7_ins(function=types.FunctionSelector.DEFAULT, desc_set=171, enable=False),
    ),
    (
        "threedm.DataStreamControlResponse_gx5_45",
        lambda: threedm.DataStreamControlResponse_gx5_45(
            device_selector=types.Gx5StreamSelector.ESTIMATION_FILTER, enabled=31
        ),
    ),
    (
        "threedm.DataStreamControlResponse_cv7_ins",
        lambda: threedm.DataStreamControlResponse_cv7_ins(desc_set=68, enabled=False),
    ),
    ("threedm.RawRtcmMessage", lambda: threedm.RawRtcmMessage(data=[142, 179])),
    (
        "threedm.GnssConstellationSettings",
        lambda: threedm.GnssConstellationSettings(
            function=types.FunctionSelector.DEFAULT,
            max_channels=216,
            config_count=2,
            settings=[
                types.ConstellationSettings(
                    constellation_id=types.Gx5ConstellationId.GLONASS,
                    enable=76,
                    reserved_channels=113,
                    max_channels=150,
                    option_flags=types.ConstellationOptions(0x1),
                ),
                types.ConstellationSettings(
                    constellation_id=types.Gx5ConstellationId.GLONASS,
                    enable=47,
                    reserved_channels=84,
                    max_channels=121,
                    option_flags=types.ConstellationOptions(0x1),
                ),
            ],
        ),
    ),
    (
        "threedm.GnssConstellationSettingsResponse",
        lambda: threedm.GnssConstellationSettingsResponse(
            max_channels_available=195,
            max_channels=232,
            config_count=2,
            settings=[
                types.ConstellationSettings(
                    constellation_id=types.Gx5ConstellationId.SBAS,
                    enable=92,
                    reserved_channels=129,
                    max_channels=166,
                    option_flags=types.ConstellationOptions(0x1),
                ),
                types.ConstellationSettings(
                    constellation_id=types.Gx5ConstellationId.SBAS,
                    enable=63,
                    reserved_channels=100,
                    max_channels=137,
                    option_flags=types.ConstellationOptions(0x1),
                ),
            ],
        ),
    ),
    (
        "threedm.GnssSbasSettings",
        lambda: threedm.GnssSbasSettings(
            function=types.FunctionSelector.DEFAULT,
            enable_sbas=211,
            sbas_options=types.SbasOptions(0x2),
            num_included_prns=2,
            included_prns=[34, 71],
        ),
    ),
    (
        "threedm.GnssSbasSettingsResponse",
        lambda: threedm.GnssSbasSettingsResponse(
            enable_sbas=108, sbas_options=types.SbasOptions(0x4), num_included_prns=2, included_prns=[182, 219]
        ),
    ),
    (
        "threedm.GnssAssistedFixControl",
        lambda: threedm.GnssAssistedFixControl(
            function=types.FunctionSelector.DEFAULT, option=types.AssistedFixOption.NONE, flags=42
        ),
    ),
    (
        "threedm.GnssAssistedFixControlResponse",
        lambda: threedm.GnssAssistedFixControlResponse(option=types.AssistedFixOption.NONE, flags=116),
    ),
    (
        "threedm.GnssAssistTimeUpdate",
        lambda: threedm.GnssAssistTimeUpdate(
            function=types.FunctionSelector.READ, tow=-0.0, week_number=190, accuracy=-2.25
        ),
    ),
    (
        "threedm.GnssAssistTimeUpdateResponse",
        lambda: threedm.GnssAssistTimeUpdateResponse(tow=1e16, week_number=50, accuracy=-0.0),
    ),
    (
        "threedm.PpsSource",
        lambda: threedm.PpsSource(function=types.FunctionSelector.DEFAULT, source=types.PpsSource.DISABLED),
    ),
    ("threedm.PpsSourceResponse", lambda: threedm.PpsSourceResponse(source=types.PpsSource.RECEIVER_1)),
    ("threedm.GetSupportedEvents", lambda: threedm.GetSupportedEvents(query=types.SupportedEventsQuery.TRIGGER_TYPES)),
    (
        "threedm.SupportedEvents",
        lambda: threedm.SupportedEvents(
            query=types.SupportedEventsQuery.TRIGGER_TYPES,
            info=types.SupportedTriggers(
                max_instances=235,
                num_entries=2,
                entries=[
                    types.SupportedTriggerType(type=types.TriggerType.COMBINATION, count=95),
                    types.SupportedTriggerType(type=types.TriggerType.THRESHOLD, count=206),
                ],
            ),
        ),
    ),
    (
        "threedm.DeviceStatus",
        lambda: threedm.DeviceStatus(model_number=243, status_selector=types.DeviceStatusSelector.DIAGNOSTIC),
    ),
    (
        "threedm.DeviceStatusResponse",
        lambda: threedm.DeviceStatusResponse(
            model_number=66,
            status_selector=types.DeviceStatusSelector.BASIC,
            status=types.Gx5BasicStatus(status_flags=103, system_state=140, system_timer=177),
        ),
    ),
    ("filter.ResetFilter", lambda: filter.ResetFilter()),
    ("filter.SetInitialAttitude", lambda: filter.SetInitialAttitude(roll=-2.25, pitch=0.375, heading=1024.0)),
    ("filter.SetInitialHeading", lambda: filter.SetInitialHeading(heading=-0.0)),
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
            function=types.FunctionSelector.DEFAULT, roll=0.375, pitch=1024.0, yaw=-0.0
        ),
    ),
    (
        "filter.SensorToVehicleTransformResponse",
        lambda: filter.SensorToVehicleTransformResponse(roll=1.5, pitch=-2.25, yaw=0.375),
    ),
    (
        "filter.SensorToVehicleOffset",
        lambda: filter.SensorToVehicleOffset(function=types.FunctionSelector.DEFAULT, offset=[1024.0, -0.0, 1.5]),
    ),
    (
        "filter.SensorToVehicleOffsetResponse",
        lambda: filter.SensorToVehicleOffsetResponse(offset=[-2.25, 0.375, 1024.0]),
    ),
    (
        "filter.AntennaOffset",
        lambda: filter.AntennaOffset(function=types.FunctionSelector.DEFAULT, offset=[-0.0, 1.5, -2.25]),
    ),
    ("filter.AntennaOffsetResponse", lambda: filter.AntennaOffsetResponse(offset=[0.375, 1024.0, -0.0])),
    (
        "filter.EstimationControl",
        lambda: filter.EstimationControl(
            function=types.FunctionSelector.DEFAULT, flags=types.EstimationControlFlags(0x40)
        ),
    ),
    (
        "filter.EstimationControlResponse",
        lambda: filter.EstimationControlResponse(flags=types.EstimationControlFlags(0xFF80)),
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
            gps_tow=-0.0,
            gps_week=32,
            latitude=-2.5e-310,
            longitude=1e16,
            height=123.456,
            velocity=[-0.0, 1.5, -2.25],
            position_uncertainty=[0.375, 1024.0, -0.0],
            velocity_uncertainty=[1.5, -2.25, 0.375],
        ),
    ),
    (
        "filter.ExternalHeadingUpdate",
        lambda: filter.ExternalHeadingUpdate(
            heading=1024.0, heading_uncertainty=-0.0, type=types.ExternalHeadingType.TRUE_HEADING
        ),
    ),
    (
        "filter.HeadingUpdateControl",
        lambda: filter.HeadingUpdateControl(
            function=types.FunctionSelector.DEFAULT, source=types.HeadingUpdateSource.EXTERNAL
        ),
    ),
    (
        "filter.HeadingUpdateControlResponse",
        lambda: filter.HeadingUpdateControlResponse(source=types.HeadingUpdateSource.GNSS_VELOCITY_AND_MAGNETOMETER),
    ),
    ("filter.AutoInitControl", lambda: filter.AutoInitControl(function=types.FunctionSelector.DEFAULT, enable=196)),
    ("filter.AutoInitControlResponse", lambda: filter.AutoInitControlResponse(enable=233)),
    (
        "filter.AccelNoise",
        lambda: filter.AccelNoise(function=types.FunctionSelector.DEFAULT, noise=[1.5, -2.25, 0.375]),
    ),
    ("filter.AccelNoiseResponse", lambda: filter.AccelNoiseResponse(noise=[1024.0, -0.0, 1.5])),
    (
        "filter.GyroNoise",
        lambda: filter.GyroNoise(function=types.FunctionSelector.DEFAULT, noise=[-2.25, 0.375, 1024.0]),
    ),
    ("filter.GyroNoiseResponse", lambda: filter.GyroNoiseResponse(noise=[-0.0, 1.5, -2.25])),
    (
        "filter.AccelBiasModel",
        lambda: filter.AccelBiasModel(
            function=types.FunctionSelector.DEFAULT, beta=[0.375, 1024.0, -0.0], noise=[1.5, -2.25, 0.375]
        ),
    ),
    (
        "filter.AccelBiasModelResponse",
        lambda: filter.AccelBiasModelResponse(beta=[1024.0, -0.0, 1.5], noise=[-2.25, 0.375, 1024.0]),
    ),
    (
        "filter.GyroBiasModel",
        lambda: filter.GyroBiasModel(
            function=types.FunctionSelector.DEFAULT, beta=[-0.0, 1.5, -2.25], noise=[0.375, 1024.0, -0.0]
        ),
    ),
    (
        "filter.GyroBiasModelResponse",
        lambda: filter.GyroBiasModelResponse(beta=[1.5, -2.25, 0.375], noise=[1024.0, -0.0, 1.5]),
    ),
    (
        "filter.ZuptControl",
        lambda: filter.ZuptControl(function=types.FunctionSelector.DEFAULT, enable=96, threshold=0.375),
    ),
    ("filter.ZuptControlResponse", lambda: filter.ZuptControlResponse(enable=170, threshold=-0.0)),
    (
        "filter.ExternalHeadingUpdateWithTime",
        lambda: filter.ExternalHeadingUpdateWithTime(
            gps_tow=0.1,
            gps_week=30,
            heading=0.375,
            heading_uncertainty=1024.0,
            type=types.ExternalHeadingType.MAGNETIC_HEADING,
        ),
    ),
    (
        "filter.ZeroAngularRateUpdateControl",
        lambda: filter.ZeroAngularRateUpdateControl(
            function=types.FunctionSelector.DEFAULT, enable=178, threshold=-2.25
        ),
    ),
    (
        "filter.ZeroAngularRateUpdateControlResponse",
        lambda: filter.ZeroAngularRateUpdateControlResponse(enable=1, threshold=1024.0),
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
        lambda: filter.GravityNoiseStdDev(function=types.FunctionSelector.DEFAULT, noise=[1.5, -2.25, 0.375]),
    ),
    ("filter.GravityNoiseStdDevResponse", lambda: filter.GravityNoiseStdDevResponse(noise=[1024.0, -0.0, 1.5])),
    (
        "filter.PressureAltitudeNoiseStdDev",
        lambda: filter.PressureAltitudeNoiseStdDev(function=types.FunctionSelector.DEFAULT, noise=-2.25),
    ),
    ("filter.PressureAltitudeNoiseStdDevResponse", lambda: filter.PressureAltitudeNoiseStdDevResponse(noise=0.375)),
    (
        "filter.HardIronOffsetNoise",
        lambda: filter.HardIronOffsetNoise(function=types.FunctionSelector.DEFAULT, noise=[1024.0, -0.0, 1.5]),
    ),
    ("filter.HardIronOffsetNoiseResponse", lambda: filter.HardIronOffsetNoiseResponse(noise=[-2.25, 0.375, 1024.0])),
    (
        "filter.SoftIronMatrixNoise",
        lambda: filter.SoftIronMatrixNoise(
            function=types.FunctionSelector.DEFAULT, noise=[-0.0, 1.5, -2.25, 0.375, 1024.0, -0.0, 1.5, -2.25, 0.375]
        ),
    ),
    (
        "filter.SoftIronMatrixNoiseResponse",
        lambda: filter.SoftIronMatrixNoiseResponse(noise=[1024.0, -0.0, 1.5, -2.25, 0.375, 1024.0, -0.0, 1.5, -2.25]),
    ),
    (
        "filter.MagNoiseStdDev",
        lambda: filter.MagNoiseStdDev(function=types.FunctionSelector.DEFAULT, noise=[0.375, 1024.0, -0.0]),
    ),
    ("filter.MagNoiseStdDevResponse", lambda: filter.MagNoiseStdDevResponse(noise=[1.5, -2.25, 0.375])),
    (
        "filter.DeclinationSource",
        lambda: filter.DeclinationSource(
            function=types.FunctionSelector.DEFAULT, source=types.MagneticParamSource.NONE, declination=-0.0
        ),
    ),
    (
        "filter.DeclinationSourceResponse",
        lambda: filter.DeclinationSourceResponse(source=types.MagneticParamSource.MANUAL, declination=-2.25),
    ),
    (
        "filter.GravityMagnitudeAdaptiveMeasurement",
        lambda: filter.GravityMagnitudeAdaptiveMeasurement(
            function=types.FunctionSelector.DEFAULT,
            mode=types.AdaptiveMeasurementMode.FIXED,
            frequency=1024.0,
            low_limit=-0.0,
            high_limit=1.5,
            low_limit_uncertainty=-2.25,
            high_limit_uncertainty=0.375,
            minimum_uncertainty=1024.0,
        ),
    ),
    (
        "filter.GravityMagnitudeAdaptiveMeasurementResponse",
        lambda: filter.GravityMagnitudeAdaptiveMeasurementResponse(
            mode=types.AdaptiveMeasurementMode.AUTO,
            frequency=1.5,
            low_limit=-2.25,
            high_limit=0.375,
            low_limit_uncertainty=1024.0,
            high_limit_uncertainty=-0.0,
            minimum_uncertainty=1.5,
        ),
    ),
    (
        "filter.MagMagnitudeAdaptiveMeasurement",
        lambda: filter.MagMagnitudeAdaptiveMeasurement(
            function=types.FunctionSelector.DEFAULT,
            mode=types.AdaptiveMeasurementMode.DISABLED,
            frequency=0.375,
            low_limit=1024.0,
            high_limit=-0.0,
            low_limit_uncertainty=1.5,
            high_limit_uncertainty=-2.25,
            minimum_uncertainty=0.375,
        ),
    ),
    (
        "filter.MagMagnitudeAdaptiveMeasurementResponse",
        lambda: filter.MagMagnitudeAdaptiveMeasurementResponse(
            mode=types.AdaptiveMeasurementMode.FIXED,
            frequency=-0.0,
            low_limit=1.5,
            high_limit=-2.25,
            low_limit_uncertainty=0.375,
            high_limit_uncertainty=1024.0,
            minimum_uncertainty=-0.0,
        ),
    ),
    (
        "filter.MagDipAngleAdaptiveMeasurement",
        lambda: filter.MagDipAngleAdaptiveMeasurement(
            function=types.FunctionSelector.DEFAULT,
            mode=types.AdaptiveMeasurementMode.AUTO,
            frequency=-2.25,
            high_limit=0.375,
            high_limit_uncertainty=1024.0,
            minimum_uncertainty=-0.0,
        ),
    ),
    (
        "filter.MagDipAngleAdaptiveMeasurementResponse",
        lambda: filter.MagDipAngleAdaptiveMeasurementResponse(
            mode=types.AdaptiveMeasurementMode.FIXED,
            frequency=-2.25,
            high_limit=0.375,
            high_limit_uncertainty=1024.0,
            minimum_uncertainty=-0.0,
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
        lambda: filter.AltitudeAidingControlResponse(source=types.AltitudeAidingSource.NONE),
    ),
    (
        "filter.PitchRollAidingControl",
        lambda: filter.PitchRollAidingControl(
            function=types.FunctionSelector.DEFAULT, source=types.PitchRollAidingSource.GRAVITY_VECTOR
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
        lambda: filter.InclinationSourceResponse(source=types.MagneticParamSource.NONE, inclination=0.375),
    ),
    (
        "filter.MagneticFieldMagnitudeSource",
        lambda: filter.MagneticFieldMagnitudeSource(
            function=types.FunctionSelector.DEFAULT, source=types.MagneticParamSource.MANUAL, magnitude=-0.0
        ),
    ),
    (
        "filter.MagneticFieldMagnitudeSourceResponse",
        lambda: filter.MagneticFieldMagnitudeSourceResponse(source=types.MagneticParamSource.WMM, magnitude=-2.25),
    ),
    (
        "filter.AidingMeasurementControl",
        lambda: filter.AidingMeasurementControl(
            function=types.FunctionSelector.DEFAULT,
            source=types.AidingMeasurementSource.EXTERNAL_MAGNETOMETER,
            enable=False,
        ),
    ),
    (
        "filter.AidingMeasurementControlResponse",
        lambda: filter.AidingMeasurementControlResponse(source=types.AidingMeasurementSource.ALL, enable=False),
    ),
    (
        "filter.InitializationConfiguration",
        lambda: filter.InitializationConfiguration(
            function=types.FunctionSelector.DEFAULT,
            wait_for_run_command=150,
            initial_cond_src=types.FilterInitialConditionSource.AUTO_POS_VEL,
            auto_heading_alignment_selector=types.HeadingAlignmentMethods(0x8),
            initial_heading=-0.0,
            initial_pitch=1.5,
            initial_roll=-2.25,
            initial_position=[0.375, 1024.0, -0.0],
            initial_velocity=[1.5, -2.25, 0.375],
            reference_frame_selector=types.FilterReferenceFrame.LLH,
        ),
    ),
    (
        "filter.InitializationConfigurationResponse",
        lambda: filter.InitializationConfigurationResponse(
            wait_for_run_command=129,
            initial_cond_src=types.FilterInitialConditionSource.MANUAL,
            auto_heading_alignment_selector=types.HeadingAlignmentMethods(0x1),
            initial_heading=0.375,
            initial_pitch=1024.0,
            initial_roll=-0.0,
            initial_position=[1.5, -2.25, 0.375],
            initial_velocity=[1024.0, -0.0, 1.5],
            reference_frame_selector=types.FilterReferenceFrame.ECEF,
        ),
    ),
    (
        "filter.AdaptiveFilterControl",
        lambda: filter.AdaptiveFilterControl(
            function=types.FunctionSelector.DEFAULT, level=types.AdaptiveFilterLevel.AGGRESSIVE, time_limit=145
        ),
    ),
    (
        "filter.AdaptiveFilterControlResponse",
        lambda: filter.AdaptiveFilterControlResponse(level=types.AdaptiveFilterLevel.CONSERVATIVE, time_limit=219),
    ),
    (
        "filter.MultiAntennaOffset",
        lambda: filter.MultiAntennaOffset(
            function=types.FunctionSelector.DEFAULT, receiver_id=5, antenna_offset=[0.375, 1024.0, -0.0]
        ),
    ),
    (
        "filter.MultiAntennaOffsetResponse",
        lambda: filter.MultiAntennaOffsetResponse(receiver_id=153, antenna_offset=[-2.25, 0.375, 1024.0]),
    ),
    (
        "filter.RelativePositionConfiguration",
        lambda: filter.RelativePositionConfiguration(
            function=types.FunctionSelector.DEFAULT,
            source=types.RelativePositionSource.MANUAL,
            reference_frame_selector=types.FilterReferenceFrame.ECEF,
            reference_coordinates=[-2.5e-310, 1e16, 123.456],
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
            lever_arm_offset=[1.5, -2.25, 0.375],
        ),
    ),
    (
        "filter.ReferencePointLeverArmResponse",
        lambda: filter.ReferencePointLeverArmResponse(
            ref_point_sel=types.ReferencePointSelector.VEH, lever_arm_offset=[-0.0, 1.5, -2.25]
        ),
    ),
    (
        "filter.SpeedLeverArm",
        lambda: filter.SpeedLeverArm(
            function=types.FunctionSelector.DEFAULT, source=214, lever_arm_offset=[1024.0, -0.0, 1.5]
        ),
    ),
    (
        "filter.SpeedLeverArmResponse",
        lambda: filter.SpeedLeverArmResponse(source=111, lever_arm_offset=[0.375, 1024.0, -0.0]),
    ),
    (
        "filter.WheeledVehicleConstraintControl",
        lambda: filter.WheeledVehicleConstraintControl(function=types.FunctionSelector.DEFAULT, enable=8),
    ),
    (
        "filter.WheeledVehicleConstraintControlResponse",
        lambda: filter.WheeledVehicleConstraintControlResponse(enable=45),
    ),
    (
        "filter.GnssAntennaCalibrationControl",
        lambda: filter.GnssAntennaCalibrationControl(
            function=types.FunctionSelector.DEFAULT, enable=82, max_offset=1024.0
        ),
    ),
    (
        "filter.GnssAntennaCalibrationControlResponse",
        lambda: filter.GnssAntennaCalibrationControlResponse(enable=156, max_offset=1.5),
    ),
    ("gnss.ReceiverInfo", lambda: gnss.ReceiverInfo()),
    (
        "gnss.ReceiverInfoResponse",
        lambda: gnss.ReceiverInfoResponse(
            num_receivers=2,
            receiver_info=[
                types.GnssReceiverInfoEntry(
                    receiver_id=16,
                    mip_data_descriptor_set=53,
                    description=b"yza\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00",
                ),
                types.GnssReceiverInfoEntry(
                    receiver_id=164,
                    mip_data_descriptor_set=201,
                    description=b"cde\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00",
                ),
            ],
        ),
    ),
    (
        "gnss.SignalConfiguration",
        lambda: gnss.SignalConfiguration(
            function=types.FunctionSelector.DEFAULT,
            gps_enable=types.GnssGpsSignals(0x2),
            glonass_enable=types.GnssGlonassSignals(0x1),
            galileo_enable=types.GnssGalileoSignals(0x1),
            beidou_enable=types.GnssBeidouSignals(0x2),
            reserved=[172, 209, 246, 32],
        ),
    ),
    (
        "gnss.SignalConfigurationResponse",
        lambda: gnss.SignalConfigurationResponse(
            gps_enable=types.GnssGpsSignals(0x1),
            glonass_enable=types.GnssGlonassSignals(0x1),
            galileo_enable=types.GnssGalileoSignals(0x4),
            beidou_enable=types.GnssBeidouSignals(0x1),
            reserved=[217, 3, 40, 77],
        ),
    ),
    (
        "gnss.SpartnConfiguration",
        lambda: gnss.SpartnConfiguration(
            function=types.FunctionSelector.DEFAULT,
            enable=114,
            type=types.SpartnConnectionType.NONE,
            current_key_tow=188,
            current_key_week=225,
            current_key=b"xyz\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00",
            next_key_tow=48,
            next_key_week=85,
            next_key=b"abc\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00",
        ),
    ),
    (
        "gnss.SpartnConfigurationResponse",
        lambda: gnss.SpartnConfigurationResponse(
            enable=159,
            type=types.SpartnConnectionType.L_BAND,
            current_key_tow=233,
            current_key_week=19,
            current_key=b"fgh\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00",
            next_key_tow=93,
            next_key_week=130,
            next_key=b"ijk\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00",
        ),
    ),
    (
        "aiding.FrameConfig",
        lambda: aiding.FrameConfig(
            function=types.FunctionSelector.DEFAULT,
            frame_id=204,
            format=types.AidingFrameFormat.EULER,
            tracking_enabled=False,
            translation=[1024.0, -0.0, 1.5],
            rotation=types.AidingFrameEuler(euler=[-2.25, 0.375, 1024.0]),
        ),
    ),
    (
        "aiding.FrameConfigResponse",
        lambda: aiding.FrameConfigResponse(
            frame_id=249,
            format=types.AidingFrameFormat.EULER,
            tracking_enabled=False,
            translation=[-2.25, 0.375, 1024.0],
            rotation=types.AidingFrameEuler(euler=[-0.0, 1.5, -2.25]),
        ),
    ),
    (
        "aiding.EchoControl",
        lambda: aiding.EchoControl(function=types.FunctionSelector.DEFAULT, mode=types.AidingEchoMode.STANDARD),
    ),
    ("aiding.EchoControlResponse", lambda: aiding.EchoControlResponse(mode=types.AidingEchoMode.RESPONSE)),
    (
        "aiding.EcefPosition",
        lambda: aiding.EcefPosition(
            time=types.AidingTime(timebase=types.AidingTimebase.EXTERNAL_TIME, reserved=191, nanoseconds=228),
            frame_id=14,
            position=[-0.0, 0.1, -2.5e-310],
            uncertainty=[0.375, 1024.0, -0.0],
            valid_flags=types.AidingVectorValidFlags(0x4),
        ),
    ),
    (
        "aiding.LlhPosition",
        lambda: aiding.LlhPosition(
            time=types.AidingTime(timebase=types.AidingTimebase.EXTERNAL_TIME, reserved=133, nanoseconds=170),
            frame_id=207,
            latitude=-2.5e-310,
            longitude=1e16,
            height=123.456,
            uncertainty=[-0.0, 1.5, -2.25],
            valid_flags=types.AidingLlhValidFlags(0x4),
        ),
    ),
    (
        "aiding.HeightAboveEllipsoid",
        lambda: aiding.HeightAboveEllipsoid(
            time=types.AidingTime(timebase=types.AidingTimebase.EXTERNAL_TIME, reserved=75, nanoseconds=112),
            frame_id=149,
            height=1024.0,
            uncertainty=-0.0,
            valid_flags=9,
        ),
    ),
    (
        "aiding.EcefVelocity",
        lambda: aiding.EcefVelocity(
            time=types.AidingTime(timebase=types.AidingTimebase.INTERNAL_REFERENCE, reserved=120, nanoseconds=157),
            frame_id=194,
            velocity=[-2.25, 0.375, 1024.0],
            uncertainty=[-0.0, 1.5, -2.25],
            valid_flags=types.AidingVectorValidFlags(0x2),
        ),
    ),
    (
        "aiding.NedVelocity",
        lambda: aiding.NedVelocity(
            time=types.AidingTime(timebase=types.AidingTimebase.INTERNAL_REFERENCE, reserved=62, nanoseconds=99),
            frame_id=136,
            velocity=[1024.0, -0.0, 1.5],
            uncertainty=[-2.25, 0.375, 1024.0],
            valid_flags=types.AidingVectorValidFlags(0x2),
        ),
    ),
    (
        "aiding.BodyFrameVelocity",
        lambda: aiding.BodyFrameVelocity(
            time=types.AidingTime(timebase=types.AidingTimebase.INTERNAL_REFERENCE, reserved=4, nanoseconds=41),
            frame_id=78,
            velocity=[1.5, -2.25, 0.375],
            uncertainty=[1024.0, -0.0, 1.5],
            valid_flags=types.AidingVectorValidFlags(0x2),
        ),
    ),
    (
        "aiding.TrueHeading",
        lambda: aiding.TrueHeading(
            time=types.AidingTime(timebase=types.AidingTimebase.INTERNAL_REFERENCE, reserved=197, nanoseconds=234),
            frame_id=20,
            heading=0.375,
            uncertainty=1024.0,
            valid_flags=131,
        ),
    ),
    (
        "aiding.MagneticField",
        lambda: aiding.MagneticField(
            time=types.AidingTime(timebase=types.AidingTimebase.TIME_OF_ARRIVAL, reserved=242, nanoseconds=28),
            frame_id=65,
            magnetic_field=[1.5, -2.25, 0.375],
            uncertainty=[1024.0, -0.0, 1.5],
            valid_flags=types.AidingVectorValidFlags(0x1),
        ),
    ),
    (
        "aiding.Pressure",
        lambda: aiding.Pressure(
            time=types.AidingTime(timebase=types.AidingTimebase.TIME_OF_ARRIVAL, reserved=184, nanoseconds=221),
            frame_id=7,
            pressure=0.375,
            uncertainty=1024.0,
            valid_flags=118,
        ),
    ),
    (
        "system.CommunicationMode",
        lambda: system.CommunicationMode(function=types.FunctionSelector.DEFAULT, mode=types.SystemCommMode.STANDARD),
    ),
    (
        "system.CommunicationModeResponse",
        lambda: system.CommunicationModeResponse(mode=types.SystemCommMode.SENSOR_DIRECT),
    ),
    ("sensor.ScaledAccel", lambda: sensor.ScaledAccel(scaled_accel=[0.375, 1024.0, -0.0])),
    ("sensor.ScaledGyro", lambda: sensor.ScaledGyro(scaled_gyro=[1.5, -2.25, 0.375])),
    ("sensor.ScaledMag", lambda: sensor.ScaledMag(scaled_mag=[1024.0, -0.0, 1.5])),
    (
        "filter_data.LlhPosition",
        lambda: filter_data.LlhPosition(
            latitude=-2.5e-310, longitude=1e16, ellipsoid_height=123.456, valid_flags=types.FilterOutputValidFlags(0x1)
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
            q=[-0.0, 1.5, -2.25, 0.375], valid_flags=types.FilterOutputValidFlags(0x1)
        ),
    ),
    (
        "filter_data.AttitudeDcm",
        lambda: filter_data.AttitudeDcm(
            dcm=[-0.0, 1.5, -2.25, 0.375, 1024.0, -0.0, 1.5, -2.25, 0.375],
            valid_flags=types.FilterOutputValidFlags(0x1),
        ),
    ),
    (
        "filter_data.EulerAngles",
        lambda: filter_data.EulerAngles(roll=-0.0, pitch=1.5, yaw=-2.25, valid_flags=types.FilterOutputValidFlags(0x1)),
    ),
    (
        "filter_data.GyroBias",
        lambda: filter_data.GyroBias(bias=[1024.0, -0.0, 1.5], valid_flags=types.FilterOutputValidFlags(0x1)),
    ),
    (
        "filter_data.AccelBias",
        lambda: filter_data.AccelBias(bias=[0.375, 1024.0, -0.0], valid_flags=types.FilterOutputValidFlags(0x1)),
    ),
    (
        "filter_data.LlhPositionUncertainty",
        lambda: filter_data.LlhPositionUncertainty(
            north=-2.25, east=0.375, down=1024.0, valid_flags=types.FilterOutputValidFlags(0x1)
        ),
    ),
    (
        "filter_data.NedVelocityUncertainty",
        lambda: filter_data.NedVelocityUncertainty(
            north=1.5, east=-2.25, down=0.375, valid_flags=types.FilterOutputValidFlags(0x1)
        ),
    ),
    (
        "filter_data.EulerAnglesUncertainty",
        lambda: filter_data.EulerAnglesUncertainty(
            roll=-0.0, pitch=1.5, yaw=-2.25, valid_flags=types.FilterOutputValidFlags(0x1)
        ),
    ),
    (
        "filter_data.GyroBiasUncertainty",
        lambda: filter_data.GyroBiasUncertainty(
            bias_uncertainty=[1024.0, -0.0, 1.5], valid_flags=types.FilterOutputValidFlags(0x1)
        ),
    ),
    (
        "filter_data.AccelBiasUncertainty",
        lambda: filter_data.AccelBiasUncertainty(
            bias_uncertainty=[0.375, 1024.0, -0.0], valid_flags=types.FilterOutputValidFlags(0x1)
        ),
    ),
    (
        "filter_data.LinearAccel",
        lambda: filter_data.LinearAccel(accel=[-2.25, 0.375, 1024.0], valid_flags=types.FilterOutputValidFlags(0x1)),
    ),
    (
        "filter_data.CompAngularRate",
        lambda: filter_data.CompAngularRate(gyro=[1.5, -2.25, 0.375], valid_flags=types.FilterOutputValidFlags(0x1)),
    ),
    (
        "filter_data.Wgs84GravityMagnitude",
        lambda: filter_data.Wgs84GravityMagnitude(
            gravity_magnitude=-0.0, valid_flags=types.FilterOutputValidFlags(0x1)
        ),
    ),
    (
        "filter_data.FilterStatus_gx5_45",
        lambda: filter_data.FilterStatus_gx5_45(
            filter_state=types.FilterStateGx5.INIT,
            dynamics_mode=types.FilterDynamicsModeGx5.AIRBORNE,
            status_flags=types.FilterStatusFlagsGx5(0x80),
        ),
    ),
    (
        "filter_data.FilterStatus_cv7_ins",
        lambda: filter_data.FilterStatus_cv7_ins(
            filter_state=types.FilterModeCv7.INIT,
            dynamics_mode=types.FilterDynamicsModeCv7.DEFAULT,
            status_flags=types.FilterStatusFlagsCv7(0x80),
        ),
    ),
    (
        "filter_data.GpsTimestamp",
        lambda: filter_data.GpsTimestamp(tow=1e16, week_number=214, valid_flags=types.FilterOutputValidFlags(0x1)),
    ),
    (
        "filter_data.QuaternionAttitudeUncertainty",
        lambda: filter_data.QuaternionAttitudeUncertainty(
            q=[1.5, -2.25, 0.375, 1024.0], valid_flags=types.FilterOutputValidFlags(0x1)
        ),
    ),
    (
        "filter_data.GravityVector",
        lambda: filter_data.GravityVector(gravity=[1.5, -2.25, 0.375], valid_flags=types.FilterOutputValidFlags(0x1)),
    ),
    (
        "filter_data.HeadingUpdateState",
        lambda: filter_data.HeadingUpdateState(
            heading=-0.0,
            heading_uncertainty=1.5,
            source=types.FilterHeadingSourceFlags(0x1),
            valid_flags=types.FilterHeadingUpdateValidFlags(0x1),
        ),
    ),
    (
        "filter_data.MagneticModel",
        lambda: filter_data.MagneticModel(
            intensity_north=1024.0,
            intensity_east=-0.0,
            intensity_down=1.5,
            inclination=-2.25,
            declination=0.375,
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
            scale_factor=[1024.0, -0.0, 1.5], valid_flags=types.FilterOutputValidFlags(0x1)
        ),
    ),
    (
        "filter_data.GyroScaleFactorUncertainty",
        lambda: filter_data.GyroScaleFactorUncertainty(
            scale_factor_uncertainty=[0.375, 1024.0, -0.0], valid_flags=types.FilterOutputValidFlags(0x1)
        ),
    ),
    (
        "filter_data.AccelScaleFactorUncertainty",
        lambda: filter_data.AccelScaleFactorUncertainty(
            scale_factor_uncertainty=[-2.25, 0.375, 1024.0], valid_flags=types.FilterOutputValidFlags(0x1)
        ),
    ),
    (
        "filter_data.CompensatedAccel",
        lambda: filter_data.CompensatedAccel(accel=[1.5, -2.25, 0.375], valid_flags=types.FilterOutputValidFlags(0x1)),
    ),
    (
        "filter_data.StandardAtmosphere",
        lambda: filter_data.StandardAtmosphere(
            geometric_altitude=-0.0,
            geopotential_altitude=1.5,
            temperature=-2.25,
            pressure=0.375,
            density=1024.0,
            valid_flags=types.FilterOutputValidFlags(0x1),
        ),
    ),
    (
        "filter_data.PressureAltitude",
        lambda: filter_data.PressureAltitude(pressure_altitude=1.5, valid_flags=types.FilterOutputValidFlags(0x1)),
    ),
    (
        "filter_data.MagAutoHardIronOffset",
        lambda: filter_data.MagAutoHardIronOffset(
            hard_iron_offset=[0.375, 1024.0, -0.0], valid_flags=types.FilterOutputValidFlags(0x1)
        ),
    ),
    (
        "filter_data.MagAutoSoftIronMatrix",
        lambda: filter_data.MagAutoSoftIronMatrix(
            soft_iron_matrix=[-2.25, 0.375, 1024.0, -0.0, 1.5, -2.25, 0.375, 1024.0, -0.0],
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
            soft_iron_matrix_uncertainty=[1.5, -2.25, 0.375, 1024.0, -0.0, 1.5, -2.25, 0.375, 1024.0],
            valid_flags=types.FilterOutputValidFlags(0x1),
        ),
    ),
    (
        "filter_data.GnssAntennaOffsetCorrection",
        lambda: filter_data.GnssAntennaOffsetCorrection(
            offset=[1.5, -2.25, 0.375], valid_flags=types.FilterOutputValidFlags(0x1)
        ),
    ),
    (
        "filter_data.GnssAntennaOffsetCorrectionUncertainty",
        lambda: filter_data.GnssAntennaOffsetCorrectionUncertainty(
            offset_uncertainty=[-0.0, 1.5, -2.25], valid_flags=types.FilterOutputValidFlags(0x1)
        ),
    ),
    (
        "filter_data.MultiAntennaOffsetCorrection",
        lambda: filter_data.MultiAntennaOffsetCorrection(
            receiver_id=96, offset=[-0.0, 1.5, -2.25], valid_flags=types.FilterOutputValidFlags(0x1)
        ),
    ),
    (
        "filter_data.MultiAntennaOffsetCorrectionUncertainty",
        lambda: filter_data.MultiAntennaOffsetCorrectionUncertainty(
            receiver_id=30, offset_uncertainty=[-0.0, 1.5, -2.25], valid_flags=types.FilterOutputValidFlags(0x1)
        ),
    ),
    (
        "filter_data.EcefPositionUncertainty",
        lambda: filter_data.EcefPositionUncertainty(
            position_uncertainty=[1024.0, -0.0, 1.5], valid_flags=types.FilterOutputValidFlags(0x1)
        ),
    ),
    (
        "filter_data.EcefVelocityUncertainty",
        lambda: filter_data.EcefVelocityUncertainty(
            velocity_uncertainty=[0.375, 1024.0, -0.0], valid_flags=types.FilterOutputValidFlags(0x1)
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
        lambda: filter_data.EcefVelocity(velocity=[1.5, -2.25, 0.375], valid_flags=types.FilterOutputValidFlags(0x1)),
    ),
    (
        "filter_data.NedRelativePosition",
        lambda: filter_data.NedRelativePosition(
            relative_position=[-0.0, 0.1, -2.5e-310], valid_flags=types.FilterOutputValidFlags(0x1)
        ),
    ),
    (
        "filter_data.GnssPositionAidingStatus",
        lambda: filter_data.GnssPositionAidingStatus(
            receiver_id=202,
            time_of_week=-0.0,
            status=types.FilterGnssAidingStatusFlags(0x2),
            reserved=[62, 99, 136, 173, 210, 247, 33, 70],
        ),
    ),
    (
        "filter_data.AidingMeasurementSummary",
        lambda: filter_data.AidingMeasurementSummary(
            time_of_week=-0.0,
            source=144,
            type=types.FilterAidingMeasurementType.DUAL_ANTENNA,
            indicator=types.FilterAidingMeasurementIndicator(0x20),
        ),
    ),
    (
        "filter_data.OdometerScaleFactorError",
        lambda: filter_data.OdometerScaleFactorError(
            scale_factor_error=1024.0, valid_flags=types.FilterOutputValidFlags(0x1)
        ),
    ),
    (
        "filter_data.OdometerScaleFactorErrorUncertainty",
        lambda: filter_data.OdometerScaleFactorErrorUncertainty(
            scale_factor_error_uncertainty=1.5, valid_flags=types.FilterOutputValidFlags(0x1)
        ),
    ),
    (
        "filter_data.GnssDualAntennaStatus",
        lambda: filter_data.GnssDualAntennaStatus(
            time_of_week=0.375,
            heading=1024.0,
            heading_uncertainty=-0.0,
            fix_type=types.FilterDualAntennaFixType.FIX_DA_FLOAT,
            status_flags=types.FilterDualAntennaStatusFlags(0x4),
            valid_flags=types.FilterOutputValidFlags(0x1),
        ),
    ),
    (
        "filter_data.AidingFrameConfigError",
        lambda: filter_data.AidingFrameConfigError(
            frame_id=123, translation=[-0.0, 1.5, -2.25], attitude=[0.375, 1024.0, -0.0, 1.5]
        ),
    ),
    (
        "filter_data.AidingFrameConfigErrorUncertainty",
        lambda: filter_data.AidingFrameConfigErrorUncertainty(
            frame_id=168, translation_uncertainty=[0.375, 1024.0, -0.0], attitude_uncertainty=[1.5, -2.25, 0.375]
        ),
    ),
    ("reserved.AckNack", lambda: reserved.AckNack(command_descriptor=176, ack_code=types.AckCode.OK)),
    ("types.ActionGpioParams", lambda: types.ActionGpioParams(pin=250, mode=types.ActionGpioMode.ONESHOT_LOW)),
    (
        "types.MessageParams",
        lambda: types.MessageParams(desc_set=73, decimation=110, num_fields=2, descriptors=[147, 184]),
    ),
    ("types.ActionStatusEntry", lambda: types.ActionStatusEntry(action_type=types.ActionType.NONE, trigger_id=7)),
    ("types.AidingFrameEuler", lambda: types.AidingFrameEuler(euler=[1024.0, -0.0, 1.5])),
    ("types.AidingFrameQuaternion", lambda: types.AidingFrameQuaternion(quaternion=[-2.25, 0.375, 1024.0, -0.0])),
    (
        "types.AidingTime",
        lambda: types.AidingTime(timebase=types.AidingTimebase.INTERNAL_REFERENCE, reserved=89, nanoseconds=126),
    ),
    ("types.CombinationParams", lambda: types.CombinationParams(logic_table=163, input_triggers=[200, 237, 23, 60])),
    (
        "types.ConstellationSettings",
        lambda: types.ConstellationSettings(
            constellation_id=types.Gx5ConstellationId.GALILEO,
            enable=134,
            reserved_channels=171,
            max_channels=208,
            option_flags=types.ConstellationOptions(0x1),
        ),
    ),
    ("types.DescriptorRate", lambda: types.DescriptorRate(descriptor=31, decimation=68)),
    (
        "types.DeviceInfo",
        lambda: types.DeviceInfo(
            firmware_version=105,
            model_name=b"efg             ",
            model_number=b"fgh             ",
            serial_number=b"ghi             ",
            lot_number=b"hij             ",
            device_options=b"ijk             ",
        ),
    ),
    (
        "types.GnssReceiverInfoEntry",
        lambda: types.GnssReceiverInfoEntry(
            receiver_id=76,
            mip_data_descriptor_set=113,
            description=b"lmn\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00",
        ),
    ),
    ("types.GpioBehaviorUnused", lambda: types.GpioBehaviorUnused(behavior=types.GpioUnusedBehavior.UNUSED)),
    ("types.GpioBehaviorIo", lambda: types.GpioBehaviorIo(behavior=types.GpioIoBehavior.INPUT)),
    ("types.GpioBehaviorPps", lambda: types.GpioBehaviorPps(behavior=types.GpioPpsBehavior.OUTPUT)),
    ("types.GpioBehaviorEncoder", lambda: types.GpioBehaviorEncoder(behavior=types.GpioEncoderBehavior.UNUSED)),
    ("types.GpioBehaviorTimestamp", lambda: types.GpioBehaviorTimestamp(behavior=types.GpioTimestampBehavior.UNUSED)),
    ("types.GpioBehaviorUart", lambda: types.GpioBehaviorUart(behavior=types.GpioUartBehavior.PORT3_RX)),
    ("types.Gx5BasicStatus", lambda: types.Gx5BasicStatus(status_flags=158, system_state=195, system_timer=232)),
    (
        "types.Gx5DiagnosticStatus",
        lambda: types.Gx5DiagnosticStatus(
            status_flags=18,
            system_state=55,
            system_timer=92,
            gnss_power_state=129,
            pps_pulse_count=166,
            last_pps_time=203,
            imu_stream_enabled=240,
            gnss_stream_enabled=26,
            filter_stream_enabled=63,
            imu_dropped_packets=100,
            gnss_dropped_packets=137,
            filter_dropped_packets=174,
            com_bytes_written=211,
            com_bytes_read=248,
            com_write_overruns=34,
            imu_parse_errors=71,
            imu_messages_read=108,
            last_imu_message_time=145,
            gnss_parse_errors=182,
            gnss_messages_read=219,
            last_gnss_message_time=5,
        ),
    ),
    ("types.Gx5PollDescriptor", lambda: types.Gx5PollDescriptor(descriptor=42, reserved=79)),
    (
        "types.NmeaMessage",
        lambda: types.NmeaMessage(message_id=116, talker_id=153, source_desc_set=190, decimation=227),
    ),
    ("types.SensorRangeEntry", lambda: types.SensorRangeEntry(setting=13, range=-2.25)),
    ("types.SupportedActionType", lambda: types.SupportedActionType(type=types.ActionType.MESSAGE, count=124)),
    (
        "types.SupportedActions",
        lambda: types.SupportedActions(
            max_instances=161,
            num_entries=2,
            entries=[
                types.SupportedActionType(type=types.ActionType.NONE, count=21),
                types.SupportedActionType(type=types.ActionType.NONE, count=132),
            ],
        ),
    ),
    ("types.SupportedTriggerType", lambda: types.SupportedTriggerType(type=types.TriggerType.COMBINATION, count=206)),
    (
        "types.SupportedTriggers",
        lambda: types.SupportedTriggers(
            max_instances=243,
            num_entries=2,
            entries=[
                types.SupportedTriggerType(type=types.TriggerType.COMBINATION, count=103),
                types.SupportedTriggerType(type=types.TriggerType.THRESHOLD, count=214),
            ],
        ),
    ),
    (
        "types.ThresholdParams",
        lambda: types.ThresholdParams(
            desc_set=0, field_desc=37, param_id=74, type=types.ThresholdType.INTERVAL, low_thres=-0.0, high_thres=0.1
        ),
    ),
    ("types.TriggerGpioParams", lambda: types.TriggerGpioParams(pin=222, mode=types.TriggerGpioMode.EDGE)),
    (
        "types.TriggerStatusEntry",
        lambda: types.TriggerStatusEntry(type=types.TriggerType.NONE, status=types.TriggerStatus(0x4)),
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
    (types.EstimationControlFlags, "gyro_bias", "GYRO_BIAS", 0, 1, 0x1),
    (types.EstimationControlFlags, "accel_bias", "ACCEL_BIAS", 1, 1, 0x2),
    (types.EstimationControlFlags, "gyro_scale_factor", "GYRO_SCALE_FACTOR", 2, 1, 0x4),
    (types.EstimationControlFlags, "accel_scale_factor", "ACCEL_SCALE_FACTOR", 3, 1, 0x8),
    (types.EstimationControlFlags, "antenna_offset", "ANTENNA_OFFSET", 4, 1, 0x10),
    (types.EstimationControlFlags, "hard_iron_auto_cal", "HARD_IRON_AUTO_CAL", 5, 1, 0x20),
    (types.EstimationControlFlags, "soft_iron_auto_cal", "SOFT_IRON_AUTO_CAL", 6, 1, 0x40),
    (types.EstimationControlFlags, "reserved", "RESERVED", 7, 9, 0xFF80),
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
    (types.GpioPinMode, "open_drain", "OPEN_DRAIN", 0, 1, 0x1),
    (types.GpioPinMode, "pulldown", "PULLDOWN", 1, 1, 0x2),
    (types.GpioPinMode, "pullup", "PULLUP", 2, 1, 0x4),
    (types.Gx5BitFlags, "processor_wdt_reset", "PROCESSOR_WDT_RESET", 0, 1, 0x1),
    (types.Gx5BitFlags, "imu_communication_fault", "IMU_COMMUNICATION_FAULT", 8, 1, 0x100),
    (types.Gx5BitFlags, "magnetometer_fault", "MAGNETOMETER_FAULT", 9, 1, 0x200),
    (types.Gx5BitFlags, "pressure_sensor_fault", "PRESSURE_SENSOR_FAULT", 10, 1, 0x400),
    (types.Gx5BitFlags, "filter_solution_fault", "FILTER_SOLUTION_FAULT", 24, 1, 0x1000000),
    (types.HeadingAlignmentMethods, "dual_antenna", "DUAL_ANTENNA", 0, 1, 0x1),
    (types.HeadingAlignmentMethods, "kinematic", "KINEMATIC", 1, 1, 0x2),
    (types.HeadingAlignmentMethods, "magnetometer", "MAGNETOMETER", 2, 1, 0x4),
    (types.HeadingAlignmentMethods, "external", "EXTERNAL", 3, 1, 0x8),
    (types.SbasOptions, "enable_ranging", "ENABLE_RANGING", 0, 1, 0x1),
    (types.SbasOptions, "enable_corrections", "ENABLE_CORRECTIONS", 1, 1, 0x2),
    (types.SbasOptions, "apply_integrity", "APPLY_INTEGRITY", 2, 1, 0x4),
    (types.TareAxes, "roll", "ROLL", 0, 1, 0x1),
    (types.TareAxes, "pitch", "PITCH", 1, 1, 0x2),
    (types.TareAxes, "yaw", "YAW", 2, 1, 0x4),
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
