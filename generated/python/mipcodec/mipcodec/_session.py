"""What the MicroStrain MIP spec says about every command, for the session layer (session/):
how a reply is matched, and per command layout (set, descriptor) -> rows of
(class, device, devices, functions, replies, ack suppression, timeout allowance).

functions: the function selector values the layout accepts (None: no selector). replies:
(descriptor, function or None, parameter or None, value or None) -- the reply field sent with
the ack when the function is that one and the parameter has that value (None: any non-zero).
ack suppression: ("function", value) or ("param", attribute, value or None: any non-zero).
timeout allowance: (ms, parameter whose value adds milliseconds or None, functions or None).
"""

from __future__ import annotations

from typing import Any, Dict, Tuple

from . import aiding, base, filter, gnss, system, threedm

ACK_DESCRIPTOR = 0xF1
ACK_ECHO = "command_descriptor"
ACK_CODE = "ack_code"
ACK_OK = 0

FUNCTION_NAMES: Dict[int, str] = {
    1: "write",
    2: "read",
    3: "save",
    4: "load",
    5: "default",
    6: "write_no_ack",
}

# Function selector values that only some devices accept.
FUNCTION_DEVICES: Dict[int, Tuple[str, ...]] = {
    6: ("gx5_45",),
}

COMMANDS: Dict[Tuple[int, int], Tuple[Tuple[Any, ...], ...]] = {
    (0x01, 0x01): ((base.Ping, None, ("gx5_45", "cv7_ins"), None, (), None, None),),
    (0x01, 0x02): ((base.SetToIdle, None, ("gx5_45", "cv7_ins"), None, (), None, None),),
    (0x01, 0x03): ((base.GetDeviceInfo, None, ("gx5_45", "cv7_ins"), None, ((0x81, None, None, None),), None, None),),
    (0x01, 0x04): (
        (base.GetDeviceDescriptors, None, ("gx5_45", "cv7_ins"), None, ((0x82, None, None, None),), None, None),
    ),
    (0x01, 0x05): (
        (base.BuiltInTest, None, ("gx5_45", "cv7_ins"), None, ((0x83, None, None, None),), None, (5000, None, None)),
    ),
    (0x01, 0x06): ((base.Resume, None, ("gx5_45", "cv7_ins"), None, (), None, None),),
    (0x01, 0x07): (
        (base.GetExtendedDescriptors, None, ("gx5_45", "cv7_ins"), None, ((0x86, None, None, None),), None, None),
    ),
    (0x01, 0x08): ((base.ContinuousBit, None, ("cv7_ins",), None, ((0x88, None, None, None),), None, None),),
    (0x01, 0x09): ((base.CommPortSpeed, None, ("cv7_ins",), (1, 2, 3, 4, 5), ((0x89, 2, None, None),), None, None),),
    (0x01, 0x72): (
        (
            base.GpsTimeUpdate_gx5_45,
            "gx5_45",
            ("gx5_45",),
            (1, 2, 6),
            ((0x84, 2, "field_id", 1), (0x85, 2, "field_id", 2)),
            ("function", 6),
            None,
        ),
        (base.GpsTimeUpdate_cv7_ins, "cv7_ins", ("cv7_ins",), (1,), (), None, None),
    ),
    (0x01, 0x7E): ((base.DeviceReset, None, ("gx5_45", "cv7_ins"), None, (), None, None),),
    (0x0C, 0x2B): ((threedm.EventControl, None, ("cv7_ins",), (1, 2, 3, 4, 5), ((0xB5, 2, None, None),), None, None),),
    (0x0C, 0x2C): ((threedm.GetEventTriggerStatus, None, ("cv7_ins",), None, ((0xB6, None, None, None),), None, None),),
    (0x0C, 0x2D): ((threedm.GetEventActionStatus, None, ("cv7_ins",), None, ((0xB7, None, None, None),), None, None),),
    (0x0C, 0x2E): (
        (threedm.EventTriggerConfig, None, ("cv7_ins",), (1, 2, 3, 4, 5), ((0xB8, 2, None, None),), None, None),
    ),
    (0x0C, 0x2F): (
        (threedm.EventActionConfig, None, ("cv7_ins",), (1, 2, 3, 4, 5), ((0xB9, 2, None, None),), None, None),
    ),
    (0x0C, 0x30): (
        (threedm.DeviceStartupSettings_gx5_45, "gx5_45", ("gx5_45",), (2, 3, 4, 5), (), None, None),
        (threedm.DeviceStartupSettings_cv7_ins, "cv7_ins", ("cv7_ins",), (3, 4, 5), (), None, (1000, None, None)),
    ),
    (0x0C, 0x31): (
        (threedm.SensorToVehicleEuler, None, ("cv7_ins",), (1, 2, 3, 4, 5), ((0xB1, 2, None, None),), None, None),
    ),
    (0x0C, 0x32): (
        (threedm.SensorToVehicleQuaternion, None, ("cv7_ins",), (1, 2, 3, 4, 5), ((0xB2, 2, None, None),), None, None),
    ),
    (0x0C, 0x33): (
        (threedm.SensorToVehicleDcm, None, ("cv7_ins",), (1, 2, 3, 4, 5), ((0xB3, 2, None, None),), None, None),
    ),
    (0x0C, 0x37): (
        (
            threedm.AccelBias_gx5_45,
            "gx5_45",
            ("gx5_45",),
            (1, 2, 3, 4, 5, 6),
            ((0x9A, 2, None, None),),
            ("function", 6),
            None,
        ),
        (threedm.AccelBias_cv7_ins, "cv7_ins", ("cv7_ins",), (1, 2, 3, 4, 5), ((0x9A, 2, None, None),), None, None),
    ),
    (0x0C, 0x38): (
        (
            threedm.GyroBias_gx5_45,
            "gx5_45",
            ("gx5_45",),
            (1, 2, 3, 4, 5, 6),
            ((0x9B, 2, None, None),),
            ("function", 6),
            None,
        ),
        (threedm.GyroBias_cv7_ins, "cv7_ins", ("cv7_ins",), (1, 2, 3, 4, 5), ((0x9B, 2, None, None),), None, None),
    ),
    (0x0C, 0x39): (
        (
            threedm.CaptureGyroBias,
            None,
            ("gx5_45", "cv7_ins"),
            None,
            ((0x9B, None, None, None),),
            None,
            (0, "averaging_time_ms", None),
        ),
    ),
    (0x0C, 0x3A): (
        (
            threedm.MagHardIronOffset_gx5_45,
            "gx5_45",
            ("gx5_45",),
            (1, 2, 3, 4, 5, 6),
            ((0x9C, 2, None, None),),
            ("function", 6),
            None,
        ),
        (
            threedm.MagHardIronOffset_cv7_ins,
            "cv7_ins",
            ("cv7_ins",),
            (1, 2, 3, 4, 5),
            ((0x9C, 2, None, None),),
            None,
            None,
        ),
    ),
    (0x0C, 0x3B): (
        (
            threedm.MagSoftIronMatrix_gx5_45,
            "gx5_45",
            ("gx5_45",),
            (1, 2, 3, 4, 5, 6),
            ((0x9D, 2, None, None),),
            ("function", 6),
            None,
        ),
        (
            threedm.MagSoftIronMatrix_cv7_ins,
            "cv7_ins",
            ("cv7_ins",),
            (1, 2, 3, 4, 5),
            ((0x9D, 2, None, None),),
            None,
            None,
        ),
    ),
    (0x0C, 0x3E): (
        (threedm.ConingScullingEnable, None, ("gx5_45",), (1, 2, 3, 4, 5), ((0x9E, 2, None, None),), None, None),
    ),
    (0x0C, 0x40): (
        (threedm.UartBaudrate, None, ("gx5_45", "cv7_ins"), (1, 2, 3, 4, 5), ((0x87, 2, None, None),), None, None),
    ),
    (0x0C, 0x41): ((threedm.GpioConfig, None, ("cv7_ins",), (1, 2, 3, 4, 5), ((0xC1, 2, None, None),), None, None),),
    (0x0C, 0x42): ((threedm.GpioState, None, ("cv7_ins",), (1, 2), ((0xC2, 2, None, None),), None, None),),
    (0x0C, 0x43): (
        (threedm.OdometerConfig, None, ("cv7_ins",), (1, 2, 3, 4, 5), ((0xC3, 2, None, None),), None, None),
    ),
    (0x0C, 0x50): (
        (
            threedm.AdvancedLowpassFilter,
            None,
            ("gx5_45", "cv7_ins"),
            (1, 2, 3, 4, 5),
            ((0x8B, 2, None, None),),
            None,
            None,
        ),
    ),
    (0x0C, 0x51): (
        (
            threedm.ComplementaryFilter,
            None,
            ("gx5_45", "cv7_ins"),
            (1, 2, 3, 4, 5),
            ((0x97, 2, None, None),),
            None,
            None,
        ),
    ),
    (0x0C, 0x52): ((threedm.SensorRange, None, ("cv7_ins",), (1, 2, 3, 4, 5), ((0xD2, 2, None, None),), None, None),),
    (0x0C, 0x53): (
        (threedm.GetCalibratedSensorRanges, None, ("cv7_ins",), None, ((0xD3, None, None, None),), None, None),
    ),
    (0x0C, 0x54): ((threedm.LowpassFilter, None, ("cv7_ins",), (1, 2, 3, 4, 5), ((0xD4, 2, None, None),), None, None),),
    (0x0C, 0x01): ((threedm.PollImuData, None, ("gx5_45",), None, (), ("param", "option", 1), None),),
    (0x0C, 0x02): ((threedm.PollGnssData, None, ("gx5_45",), None, (), ("param", "option", 1), None),),
    (0x0C, 0x03): ((threedm.PollFilterData, None, ("gx5_45",), None, (), ("param", "option", 1), None),),
    (0x0C, 0x04): ((threedm.PollNmeaData, None, ("cv7_ins",), None, (), ("param", "suppress_ack", None), None),),
    (0x0C, 0x0D): ((threedm.PollData, None, ("cv7_ins",), None, (), ("param", "suppress_ack", None), None),),
    (0x0C, 0x06): ((threedm.GetImuBaseRate, None, ("gx5_45",), None, ((0x83, None, None, None),), None, None),),
    (0x0C, 0x07): ((threedm.GetGnssBaseRate, None, ("gx5_45",), None, ((0x84, None, None, None),), None, None),),
    (0x0C, 0x0B): ((threedm.GetFilterBaseRate, None, ("gx5_45",), None, ((0x8A, None, None, None),), None, None),),
    (0x0C, 0x0E): ((threedm.GetBaseRate, None, ("cv7_ins",), None, ((0x8E, None, None, None),), None, None),),
    (0x0C, 0x08): (
        (threedm.ImuMessageFormat, None, ("gx5_45",), (1, 2, 3, 4, 5), ((0x80, 2, None, None),), None, None),
    ),
    (0x0C, 0x09): (
        (threedm.GnssMessageFormat, None, ("gx5_45",), (1, 2, 3, 4, 5), ((0x81, 2, None, None),), None, None),
    ),
    (0x0C, 0x0A): (
        (threedm.FilterMessageFormat, None, ("gx5_45",), (1, 2, 3, 4, 5), ((0x82, 2, None, None),), None, None),
    ),
    (0x0C, 0x0C): (
        (threedm.NmeaMessageFormat, None, ("cv7_ins",), (1, 2, 3, 4, 5), ((0x8C, 2, None, None),), None, None),
    ),
    (0x0C, 0x0F): ((threedm.MessageFormat, None, ("cv7_ins",), (1, 2, 3, 4, 5), ((0x8F, 2, None, None),), None, None),),
    (0x0C, 0x10): ((threedm.FactoryStreaming, None, ("cv7_ins",), None, (), None, None),),
    (0x0C, 0x11): (
        (
            threedm.DataStreamControl_gx5_45,
            "gx5_45",
            ("gx5_45",),
            (1, 2, 3, 4, 5),
            ((0x85, 2, None, None),),
            None,
            None,
        ),
        (
            threedm.DataStreamControl_cv7_ins,
            "cv7_ins",
            ("cv7_ins",),
            (1, 2, 3, 4, 5),
            ((0x85, 2, None, None),),
            None,
            None,
        ),
    ),
    (0x0C, 0x20): ((threedm.RawRtcmMessage, None, ("gx5_45",), None, (), None, None),),
    (0x0C, 0x21): (
        (threedm.GnssConstellationSettings, None, ("gx5_45",), (1, 2, 3, 4, 5), ((0xA0, 2, None, None),), None, None),
    ),
    (0x0C, 0x22): (
        (threedm.GnssSbasSettings, None, ("gx5_45", "cv7_ins"), (1, 2, 3, 4, 5), ((0xA1, 2, None, None),), None, None),
    ),
    (0x0C, 0x23): (
        (threedm.GnssAssistedFixControl, None, ("gx5_45",), (1, 2, 3, 4, 5), ((0xA2, 2, None, None),), None, None),
    ),
    (0x0C, 0x24): ((threedm.GnssAssistTimeUpdate, None, ("gx5_45",), (1, 2), ((0xA3, 2, None, None),), None, None),),
    (0x0C, 0x28): ((threedm.PpsSource, None, ("cv7_ins",), (1, 2, 3, 4, 5), ((0xA8, 2, None, None),), None, None),),
    (0x0C, 0x2A): ((threedm.GetSupportedEvents, None, ("cv7_ins",), None, ((0xB4, None, None, None),), None, None),),
    (0x0C, 0x64): ((threedm.DeviceStatus, None, ("gx5_45",), None, ((0x90, None, None, None),), None, None),),
    (0x0D, 0x01): ((filter.ResetFilter, None, ("gx5_45", "cv7_ins"), None, (), None, None),),
    (0x0D, 0x02): ((filter.SetInitialAttitude, None, ("gx5_45",), None, (), None, None),),
    (0x0D, 0x03): ((filter.SetInitialHeading, None, ("gx5_45", "cv7_ins"), None, (), None, None),),
    (0x0D, 0x05): ((filter.RunFilter, None, ("cv7_ins",), None, (), None, None),),
    (0x0D, 0x10): (
        (filter.VehicleDynamicsMode, None, ("gx5_45",), (1, 2, 3, 4, 5), ((0x80, 2, None, None),), None, None),
    ),
    (0x0D, 0x11): (
        (filter.SensorToVehicleTransform, None, ("gx5_45",), (1, 2, 3, 4, 5), ((0x81, 2, None, None),), None, None),
    ),
    (0x0D, 0x12): (
        (filter.SensorToVehicleOffset, None, ("gx5_45",), (1, 2, 3, 4, 5), ((0x82, 2, None, None),), None, None),
    ),
    (0x0D, 0x13): (
        (filter.AntennaOffset, None, ("gx5_45", "cv7_ins"), (1, 2, 3, 4, 5), ((0x83, 2, None, None),), None, None),
    ),
    (0x0D, 0x14): (
        (filter.EstimationControl, None, ("gx5_45",), (1, 2, 3, 4, 5), ((0x84, 2, None, None),), None, None),
    ),
    (0x0D, 0x15): (
        (filter.GnssSourceControl, None, ("gx5_45", "cv7_ins"), (1, 2, 3, 4, 5), ((0x86, 2, None, None),), None, None),
    ),
    (0x0D, 0x16): ((filter.ExternalGnssUpdate, None, ("gx5_45",), None, (), None, None),),
    (0x0D, 0x17): ((filter.ExternalHeadingUpdate, None, ("gx5_45", "cv7_ins"), None, (), None, None),),
    (0x0D, 0x18): (
        (filter.HeadingUpdateControl, None, ("gx5_45",), (1, 2, 3, 4, 5), ((0x87, 2, None, None),), None, None),
    ),
    (0x0D, 0x19): ((filter.AutoInitControl, None, ("gx5_45",), (1, 2, 3, 4, 5), ((0x88, 2, None, None),), None, None),),
    (0x0D, 0x1A): (
        (filter.AccelNoise, None, ("gx5_45", "cv7_ins"), (1, 2, 3, 4, 5), ((0x89, 2, None, None),), None, None),
    ),
    (0x0D, 0x1B): (
        (filter.GyroNoise, None, ("gx5_45", "cv7_ins"), (1, 2, 3, 4, 5), ((0x8A, 2, None, None),), None, None),
    ),
    (0x0D, 0x1C): (
        (filter.AccelBiasModel, None, ("gx5_45", "cv7_ins"), (1, 2, 3, 4, 5), ((0x8B, 2, None, None),), None, None),
    ),
    (0x0D, 0x1D): (
        (filter.GyroBiasModel, None, ("gx5_45", "cv7_ins"), (1, 2, 3, 4, 5), ((0x8C, 2, None, None),), None, None),
    ),
    (0x0D, 0x1E): ((filter.ZuptControl, None, ("gx5_45",), (1, 2, 3, 4, 5), ((0x8D, 2, None, None),), None, None),),
    (0x0D, 0x1F): ((filter.ExternalHeadingUpdateWithTime, None, ("gx5_45", "cv7_ins"), None, (), None, None),),
    (0x0D, 0x20): (
        (
            filter.ZeroAngularRateUpdateControl,
            None,
            ("gx5_45", "cv7_ins"),
            (1, 2, 3, 4, 5),
            ((0x8E, 2, None, None),),
            None,
            None,
        ),
    ),
    (0x0D, 0x21): ((filter.TareOrientation, None, ("gx5_45",), (1, 3, 4, 5), (), None, None),),
    (0x0D, 0x22): ((filter.CommandedZupt, None, ("gx5_45",), None, (), None, None),),
    (0x0D, 0x23): ((filter.CommandedZeroAngularRateUpdate, None, ("gx5_45",), None, (), None, None),),
    (0x0D, 0x27): ((filter.MagCaptureAutoCalibration, None, ("gx5_45",), (1, 3), (), None, None),),
    (0x0D, 0x28): (
        (filter.GravityNoiseStdDev, None, ("gx5_45", "cv7_ins"), (1, 2, 3, 4, 5), ((0x93, 2, None, None),), None, None),
    ),
    (0x0D, 0x29): (
        (filter.PressureAltitudeNoiseStdDev, None, ("gx5_45",), (1, 2, 3, 4, 5), ((0x94, 2, None, None),), None, None),
    ),
    (0x0D, 0x2B): (
        (filter.HardIronOffsetNoise, None, ("gx5_45",), (1, 2, 3, 4, 5), ((0x96, 2, None, None),), None, None),
    ),
    (0x0D, 0x2C): (
        (filter.SoftIronMatrixNoise, None, ("gx5_45",), (1, 2, 3, 4, 5), ((0x97, 2, None, None),), None, None),
    ),
    (0x0D, 0x42): ((filter.MagNoiseStdDev, None, ("gx5_45",), (1, 2, 3, 4, 5), ((0xB1, 2, None, None),), None, None),),
    (0x0D, 0x43): (
        (filter.DeclinationSource, None, ("gx5_45", "cv7_ins"), (1, 2, 3, 4, 5), ((0xB2, 2, None, None),), None, None),
    ),
    (0x0D, 0x44): (
        (
            filter.GravityMagnitudeAdaptiveMeasurement,
            None,
            ("gx5_45",),
            (1, 2, 3, 4, 5),
            ((0xB3, 2, None, None),),
            None,
            None,
        ),
    ),
    (0x0D, 0x45): (
        (
            filter.MagMagnitudeAdaptiveMeasurement,
            None,
            ("gx5_45",),
            (1, 2, 3, 4, 5),
            ((0xB4, 2, None, None),),
            None,
            None,
        ),
    ),
    (0x0D, 0x46): (
        (
            filter.MagDipAngleAdaptiveMeasurement,
            None,
            ("gx5_45",),
            (1, 2, 3, 4, 5),
            ((0xB5, 2, None, None),),
            None,
            None,
        ),
    ),
    (0x0D, 0x47): (
        (filter.AltitudeAidingControl, None, ("gx5_45",), (1, 2, 3, 4, 5), ((0xB7, 2, None, None),), None, None),
    ),
    (0x0D, 0x4B): (
        (filter.PitchRollAidingControl, None, ("gx5_45",), (1, 2, 3, 4, 5), ((0xBB, 2, None, None),), None, None),
    ),
    (0x0D, 0x4C): (
        (filter.InclinationSource, None, ("gx5_45",), (1, 2, 3, 4, 5), ((0xBC, 2, None, None),), None, None),
    ),
    (0x0D, 0x4D): (
        (filter.MagneticFieldMagnitudeSource, None, ("gx5_45",), (1, 2, 3, 4, 5), ((0xBD, 2, None, None),), None, None),
    ),
    (0x0D, 0x50): (
        (filter.AidingMeasurementControl, None, ("cv7_ins",), (1, 2, 3, 4, 5), ((0xD0, 2, None, None),), None, None),
    ),
    (0x0D, 0x52): (
        (filter.InitializationConfiguration, None, ("cv7_ins",), (1, 2, 3, 4, 5), ((0xD2, 2, None, None),), None, None),
    ),
    (0x0D, 0x53): (
        (filter.AdaptiveFilterControl, None, ("cv7_ins",), (1, 2, 3, 4, 5), ((0xD3, 2, None, None),), None, None),
    ),
    (0x0D, 0x54): (
        (filter.MultiAntennaOffset, None, ("cv7_ins",), (1, 2, 3, 4, 5), ((0xD4, 2, None, None),), None, None),
    ),
    (0x0D, 0x55): (
        (
            filter.RelativePositionConfiguration,
            None,
            ("cv7_ins",),
            (1, 2, 3, 4, 5),
            ((0xD5, 2, None, None),),
            None,
            None,
        ),
    ),
    (0x0D, 0x56): (
        (filter.ReferencePointLeverArm, None, ("cv7_ins",), (1, 2, 3, 4, 5), ((0xD6, 2, None, None),), None, None),
    ),
    (0x0D, 0x61): ((filter.SpeedLeverArm, None, ("cv7_ins",), (1, 2, 3, 4, 5), ((0xE1, 2, None, None),), None, None),),
    (0x0D, 0x63): (
        (
            filter.WheeledVehicleConstraintControl,
            None,
            ("cv7_ins",),
            (1, 2, 3, 4, 5),
            ((0xE3, 2, None, None),),
            None,
            None,
        ),
    ),
    (0x0D, 0x64): (
        (
            filter.GnssAntennaCalibrationControl,
            None,
            ("cv7_ins",),
            (1, 2, 3, 4, 5),
            ((0xE4, 2, None, None),),
            None,
            None,
        ),
    ),
    (0x0E, 0x01): ((gnss.ReceiverInfo, None, ("cv7_ins",), None, ((0x81, None, None, None),), None, None),),
    (0x0E, 0x02): (
        (gnss.SignalConfiguration, None, ("cv7_ins",), (1, 2, 3, 4, 5), ((0x82, 2, None, None),), None, None),
    ),
    (0x0E, 0x20): (
        (gnss.SpartnConfiguration, None, ("cv7_ins",), (1, 2, 3, 4, 5), ((0xA0, 2, None, None),), None, None),
    ),
    (0x13, 0x01): ((aiding.FrameConfig, None, ("cv7_ins",), (1, 2, 3, 4, 5), ((0x81, 2, None, None),), None, None),),
    (0x13, 0x1F): ((aiding.EchoControl, None, ("cv7_ins",), (1, 2, 3, 4, 5), ((0x9F, 2, None, None),), None, None),),
    (0x13, 0x21): ((aiding.EcefPosition, None, ("cv7_ins",), None, (), None, None),),
    (0x13, 0x22): ((aiding.LlhPosition, None, ("cv7_ins",), None, (), None, None),),
    (0x13, 0x23): ((aiding.HeightAboveEllipsoid, None, ("cv7_ins",), None, (), None, None),),
    (0x13, 0x28): ((aiding.EcefVelocity, None, ("cv7_ins",), None, (), None, None),),
    (0x13, 0x29): ((aiding.NedVelocity, None, ("cv7_ins",), None, (), None, None),),
    (0x13, 0x2A): ((aiding.BodyFrameVelocity, None, ("cv7_ins",), None, (), None, None),),
    (0x13, 0x31): ((aiding.TrueHeading, None, ("cv7_ins",), None, (), None, None),),
    (0x13, 0x32): ((aiding.MagneticField, None, ("cv7_ins",), None, (), None, None),),
    (0x13, 0x33): ((aiding.Pressure, None, ("cv7_ins",), None, (), None, None),),
    (0x7F, 0x10): (
        (system.CommunicationMode, None, ("gx5_45",), (1, 2, 3, 4, 5), ((0x90, 2, None, None),), None, None),
    ),
}


def function_name(value: int) -> str:
    return FUNCTION_NAMES.get(value, str(value))
