"""Dispatch tables of the MicroStrain MIP: (set, descriptor) -> layout classes.

A field with per-device variants maps to several classes, tried in IR order (docs/conformance.md
section 2). Reserved fields apply to every set of a kind; shared data descriptors to every data set.
"""

from __future__ import annotations

import importlib
from typing import TYPE_CHECKING, Any, Dict, Iterable, Optional, Tuple, Type

from .codec.layout import Field

DEVICES: Tuple[str, ...] = ("gx5_45", "cv7_ins")

SET_NAMES: Dict[int, str] = {
    0x01: "base",
    0x0C: "threedm",
    0x0D: "filter",
    0x0E: "gnss",
    0x13: "aiding",
    0x7F: "system",
    0x80: "sensor",
    0x81: "gnss_data",
    0x82: "filter_data",
    0x91: "gnss_receiver_1",
    0x92: "gnss_receiver_2",
    0x93: "gnss_corrections",
    0x94: "gnss_external",
    0xA0: "system_data",
    0xFF: "shared",
}

SET_KINDS: Tuple[Tuple[str, int, int], ...] = (
    ("command", 0x01, 0x7F),
    ("data", 0x80, 0xFF),
)

SHARED_SET: Optional[int] = 0xFF

# (set, descriptor) -> the layout classes as "module.Class": a set's module is imported when one of
# its fields is first looked up, so that decoding a log loads only the sets it holds.
_FIELD_CLASSES: Dict[Tuple[int, int], Tuple[str, ...]] = {
    (0x01, 0x01): ("base.Ping",),
    (0x01, 0x02): ("base.SetToIdle",),
    (0x01, 0x03): ("base.GetDeviceInfo",),
    (0x01, 0x81): ("base.DeviceInfo",),
    (0x01, 0x04): ("base.GetDeviceDescriptors",),
    (0x01, 0x82): ("base.DeviceDescriptors",),
    (0x01, 0x05): ("base.BuiltInTest",),
    (0x01, 0x83): ("base.BuiltInTestResult_gx5_45", "base.BuiltInTestResult_cv7_ins"),
    (0x01, 0x06): ("base.Resume",),
    (0x01, 0x07): ("base.GetExtendedDescriptors",),
    (0x01, 0x86): ("base.ExtendedDescriptors",),
    (0x01, 0x08): ("base.ContinuousBit",),
    (0x01, 0x88): ("base.ContinuousBitResult",),
    (0x01, 0x09): ("base.CommPortSpeed",),
    (0x01, 0x89): ("base.CommPortSpeedResponse",),
    (0x01, 0x72): ("base.GpsTimeUpdate_gx5_45", "base.GpsTimeUpdate_cv7_ins"),
    (0x01, 0x84): ("base.GpsWeek",),
    (0x01, 0x85): ("base.GpsSeconds",),
    (0x01, 0x7E): ("base.DeviceReset",),
    (0x0C, 0x2B): ("threedm.EventControl",),
    (0x0C, 0xB5): ("threedm.EventControlResponse",),
    (0x0C, 0x2C): ("threedm.GetEventTriggerStatus",),
    (0x0C, 0xB6): ("threedm.EventTriggerStatus",),
    (0x0C, 0x2D): ("threedm.GetEventActionStatus",),
    (0x0C, 0xB7): ("threedm.EventActionStatus",),
    (0x0C, 0x2E): ("threedm.EventTriggerConfig",),
    (0x0C, 0xB8): ("threedm.EventTriggerConfigResponse",),
    (0x0C, 0x2F): ("threedm.EventActionConfig",),
    (0x0C, 0xB9): ("threedm.EventActionConfigResponse",),
    (0x0C, 0x30): ("threedm.DeviceStartupSettings_gx5_45", "threedm.DeviceStartupSettings_cv7_ins"),
    (0x0C, 0x31): ("threedm.SensorToVehicleEuler",),
    (0x0C, 0xB1): ("threedm.SensorToVehicleEulerResponse",),
    (0x0C, 0x32): ("threedm.SensorToVehicleQuaternion",),
    (0x0C, 0xB2): ("threedm.SensorToVehicleQuaternionResponse",),
    (0x0C, 0x33): ("threedm.SensorToVehicleDcm",),
    (0x0C, 0xB3): ("threedm.SensorToVehicleDcmResponse",),
    (0x0C, 0x37): ("threedm.AccelBias_gx5_45", "threedm.AccelBias_cv7_ins"),
    (0x0C, 0x9A): ("threedm.AccelBiasResponse",),
    (0x0C, 0x38): ("threedm.GyroBias_gx5_45", "threedm.GyroBias_cv7_ins"),
    (0x0C, 0x9B): ("threedm.GyroBiasResponse",),
    (0x0C, 0x39): ("threedm.CaptureGyroBias",),
    (0x0C, 0x3A): ("threedm.MagHardIronOffset_gx5_45", "threedm.MagHardIronOffset_cv7_ins"),
    (0x0C, 0x9C): ("threedm.MagHardIronOffsetResponse",),
    (0x0C, 0x3B): ("threedm.MagSoftIronMatrix_gx5_45", "threedm.MagSoftIronMatrix_cv7_ins"),
    (0x0C, 0x9D): ("threedm.MagSoftIronMatrixResponse",),
    (0x0C, 0x3E): ("threedm.ConingScullingEnable",),
    (0x0C, 0x9E): ("threedm.ConingScullingEnableResponse",),
    (0x0C, 0x40): ("threedm.UartBaudrate",),
    (0x0C, 0x87): ("threedm.UartBaudrateResponse",),
    (0x0C, 0x41): ("threedm.GpioConfig",),
    (0x0C, 0xC1): ("threedm.GpioConfigResponse",),
    (0x0C, 0x42): ("threedm.GpioState",),
    (0x0C, 0xC2): ("threedm.GpioStateResponse",),
    (0x0C, 0x43): ("threedm.OdometerConfig",),
    (0x0C, 0xC3): ("threedm.OdometerConfigResponse",),
    (0x0C, 0x50): ("threedm.AdvancedLowpassFilter",),
    (0x0C, 0x8B): ("threedm.AdvancedLowpassFilterResponse",),
    (0x0C, 0x51): ("threedm.ComplementaryFilter",),
    (0x0C, 0x97): ("threedm.ComplementaryFilterResponse",),
    (0x0C, 0x52): ("threedm.SensorRange",),
    (0x0C, 0xD2): ("threedm.SensorRangeResponse",),
    (0x0C, 0x53): ("threedm.GetCalibratedSensorRanges",),
    (0x0C, 0xD3): ("threedm.CalibratedSensorRanges",),
    (0x0C, 0x54): ("threedm.LowpassFilter",),
    (0x0C, 0xD4): ("threedm.LowpassFilterResponse",),
    (0x0C, 0x01): ("threedm.PollImuData",),
    (0x0C, 0x02): ("threedm.PollGnssData",),
    (0x0C, 0x03): ("threedm.PollFilterData",),
    (0x0C, 0x04): ("threedm.PollNmeaData",),
    (0x0C, 0x0D): ("threedm.PollData",),
    (0x0C, 0x06): ("threedm.GetImuBaseRate",),
    (0x0C, 0x83): ("threedm.ImuBaseRate",),
    (0x0C, 0x07): ("threedm.GetGnssBaseRate",),
    (0x0C, 0x84): ("threedm.GnssBaseRate",),
    (0x0C, 0x0B): ("threedm.GetFilterBaseRate",),
    (0x0C, 0x8A): ("threedm.FilterBaseRate",),
    (0x0C, 0x0E): ("threedm.GetBaseRate",),
    (0x0C, 0x8E): ("threedm.BaseRate",),
    (0x0C, 0x08): ("threedm.ImuMessageFormat",),
    (0x0C, 0x80): ("threedm.ImuMessageFormatResponse",),
    (0x0C, 0x09): ("threedm.GnssMessageFormat",),
    (0x0C, 0x81): ("threedm.GnssMessageFormatResponse",),
    (0x0C, 0x0A): ("threedm.FilterMessageFormat",),
    (0x0C, 0x82): ("threedm.FilterMessageFormatResponse",),
    (0x0C, 0x0C): ("threedm.NmeaMessageFormat",),
    (0x0C, 0x8C): ("threedm.NmeaMessageFormatResponse",),
    (0x0C, 0x0F): ("threedm.MessageFormat",),
    (0x0C, 0x8F): ("threedm.MessageFormatResponse",),
    (0x0C, 0x10): ("threedm.FactoryStreaming",),
    (0x0C, 0x11): ("threedm.DataStreamControl_gx5_45", "threedm.DataStreamControl_cv7_ins"),
    (0x0C, 0x85): ("threedm.DataStreamControlResponse_gx5_45", "threedm.DataStreamControlResponse_cv7_ins"),
    (0x0C, 0x20): ("threedm.RawRtcmMessage",),
    (0x0C, 0x21): ("threedm.GnssConstellationSettings",),
    (0x0C, 0xA0): ("threedm.GnssConstellationSettingsResponse",),
    (0x0C, 0x22): ("threedm.GnssSbasSettings",),
    (0x0C, 0xA1): ("threedm.GnssSbasSettingsResponse",),
    (0x0C, 0x23): ("threedm.GnssAssistedFixControl",),
    (0x0C, 0xA2): ("threedm.GnssAssistedFixControlResponse",),
    (0x0C, 0x24): ("threedm.GnssAssistTimeUpdate",),
    (0x0C, 0xA3): ("threedm.GnssAssistTimeUpdateResponse",),
    (0x0C, 0x28): ("threedm.PpsSource",),
    (0x0C, 0xA8): ("threedm.PpsSourceResponse",),
    (0x0C, 0x2A): ("threedm.GetSupportedEvents",),
    (0x0C, 0xB4): ("threedm.SupportedEvents",),
    (0x0C, 0x64): ("threedm.DeviceStatus",),
    (0x0C, 0x90): ("threedm.DeviceStatusResponse",),
    (0x0D, 0x01): ("filter.ResetFilter",),
    (0x0D, 0x02): ("filter.SetInitialAttitude",),
    (0x0D, 0x03): ("filter.SetInitialHeading",),
    (0x0D, 0x05): ("filter.RunFilter",),
    (0x0D, 0x10): ("filter.VehicleDynamicsMode",),
    (0x0D, 0x80): ("filter.VehicleDynamicsModeResponse",),
    (0x0D, 0x11): ("filter.SensorToVehicleTransform",),
    (0x0D, 0x81): ("filter.SensorToVehicleTransformResponse",),
    (0x0D, 0x12): ("filter.SensorToVehicleOffset",),
    (0x0D, 0x82): ("filter.SensorToVehicleOffsetResponse",),
    (0x0D, 0x13): ("filter.AntennaOffset",),
    (0x0D, 0x83): ("filter.AntennaOffsetResponse",),
    (0x0D, 0x14): ("filter.EstimationControl",),
    (0x0D, 0x84): ("filter.EstimationControlResponse",),
    (0x0D, 0x15): ("filter.GnssSourceControl",),
    (0x0D, 0x86): ("filter.GnssSourceControlResponse",),
    (0x0D, 0x16): ("filter.ExternalGnssUpdate",),
    (0x0D, 0x17): ("filter.ExternalHeadingUpdate",),
    (0x0D, 0x18): ("filter.HeadingUpdateControl",),
    (0x0D, 0x87): ("filter.HeadingUpdateControlResponse",),
    (0x0D, 0x19): ("filter.AutoInitControl",),
    (0x0D, 0x88): ("filter.AutoInitControlResponse",),
    (0x0D, 0x1A): ("filter.AccelNoise",),
    (0x0D, 0x89): ("filter.AccelNoiseResponse",),
    (0x0D, 0x1B): ("filter.GyroNoise",),
    (0x0D, 0x8A): ("filter.GyroNoiseResponse",),
    (0x0D, 0x1C): ("filter.AccelBiasModel",),
    (0x0D, 0x8B): ("filter.AccelBiasModelResponse",),
    (0x0D, 0x1D): ("filter.GyroBiasModel",),
    (0x0D, 0x8C): ("filter.GyroBiasModelResponse",),
    (0x0D, 0x1E): ("filter.ZuptControl",),
    (0x0D, 0x8D): ("filter.ZuptControlResponse",),
    (0x0D, 0x1F): ("filter.ExternalHeadingUpdateWithTime",),
    (0x0D, 0x20): ("filter.ZeroAngularRateUpdateControl",),
    (0x0D, 0x8E): ("filter.ZeroAngularRateUpdateControlResponse",),
    (0x0D, 0x21): ("filter.TareOrientation",),
    (0x0D, 0x22): ("filter.CommandedZupt",),
    (0x0D, 0x23): ("filter.CommandedZeroAngularRateUpdate",),
    (0x0D, 0x27): ("filter.MagCaptureAutoCalibration",),
    (0x0D, 0x28): ("filter.GravityNoiseStdDev",),
    (0x0D, 0x93): ("filter.GravityNoiseStdDevResponse",),
    (0x0D, 0x29): ("filter.PressureAltitudeNoiseStdDev",),
    (0x0D, 0x94): ("filter.PressureAltitudeNoiseStdDevResponse",),
    (0x0D, 0x2B): ("filter.HardIronOffsetNoise",),
    (0x0D, 0x96): ("filter.HardIronOffsetNoiseResponse",),
    (0x0D, 0x2C): ("filter.SoftIronMatrixNoise",),
    (0x0D, 0x97): ("filter.SoftIronMatrixNoiseResponse",),
    (0x0D, 0x42): ("filter.MagNoiseStdDev",),
    (0x0D, 0xB1): ("filter.MagNoiseStdDevResponse",),
    (0x0D, 0x43): ("filter.DeclinationSource",),
    (0x0D, 0xB2): ("filter.DeclinationSourceResponse",),
    (0x0D, 0x44): ("filter.GravityMagnitudeAdaptiveMeasurement",),
    (0x0D, 0xB3): ("filter.GravityMagnitudeAdaptiveMeasurementResponse",),
    (0x0D, 0x45): ("filter.MagMagnitudeAdaptiveMeasurement",),
    (0x0D, 0xB4): ("filter.MagMagnitudeAdaptiveMeasurementResponse",),
    (0x0D, 0x46): ("filter.MagDipAngleAdaptiveMeasurement",),
    (0x0D, 0xB5): ("filter.MagDipAngleAdaptiveMeasurementResponse",),
    (0x0D, 0x47): ("filter.AltitudeAidingControl",),
    (0x0D, 0xB7): ("filter.AltitudeAidingControlResponse",),
    (0x0D, 0x4B): ("filter.PitchRollAidingControl",),
    (0x0D, 0xBB): ("filter.PitchRollAidingControlResponse",),
    (0x0D, 0x4C): ("filter.InclinationSource",),
    (0x0D, 0xBC): ("filter.InclinationSourceResponse",),
    (0x0D, 0x4D): ("filter.MagneticFieldMagnitudeSource",),
    (0x0D, 0xBD): ("filter.MagneticFieldMagnitudeSourceResponse",),
    (0x0D, 0x50): ("filter.AidingMeasurementControl",),
    (0x0D, 0xD0): ("filter.AidingMeasurementControlResponse",),
    (0x0D, 0x52): ("filter.InitializationConfiguration",),
    (0x0D, 0xD2): ("filter.InitializationConfigurationResponse",),
    (0x0D, 0x53): ("filter.AdaptiveFilterControl",),
    (0x0D, 0xD3): ("filter.AdaptiveFilterControlResponse",),
    (0x0D, 0x54): ("filter.MultiAntennaOffset",),
    (0x0D, 0xD4): ("filter.MultiAntennaOffsetResponse",),
    (0x0D, 0x55): ("filter.RelativePositionConfiguration",),
    (0x0D, 0xD5): ("filter.RelativePositionConfigurationResponse",),
    (0x0D, 0x56): ("filter.ReferencePointLeverArm",),
    (0x0D, 0xD6): ("filter.ReferencePointLeverArmResponse",),
    (0x0D, 0x61): ("filter.SpeedLeverArm",),
    (0x0D, 0xE1): ("filter.SpeedLeverArmResponse",),
    (0x0D, 0x63): ("filter.WheeledVehicleConstraintControl",),
    (0x0D, 0xE3): ("filter.WheeledVehicleConstraintControlResponse",),
    (0x0D, 0x64): ("filter.GnssAntennaCalibrationControl",),
    (0x0D, 0xE4): ("filter.GnssAntennaCalibrationControlResponse",),
    (0x0E, 0x01): ("gnss.ReceiverInfo",),
    (0x0E, 0x81): ("gnss.ReceiverInfoResponse",),
    (0x0E, 0x02): ("gnss.SignalConfiguration",),
    (0x0E, 0x82): ("gnss.SignalConfigurationResponse",),
    (0x0E, 0x20): ("gnss.SpartnConfiguration",),
    (0x0E, 0xA0): ("gnss.SpartnConfigurationResponse",),
    (0x13, 0x01): ("aiding.FrameConfig",),
    (0x13, 0x81): ("aiding.FrameConfigResponse",),
    (0x13, 0x1F): ("aiding.EchoControl",),
    (0x13, 0x9F): ("aiding.EchoControlResponse",),
    (0x13, 0x21): ("aiding.EcefPosition",),
    (0x13, 0x22): ("aiding.LlhPosition",),
    (0x13, 0x23): ("aiding.HeightAboveEllipsoid",),
    (0x13, 0x28): ("aiding.EcefVelocity",),
    (0x13, 0x29): ("aiding.NedVelocity",),
    (0x13, 0x2A): ("aiding.BodyFrameVelocity",),
    (0x13, 0x31): ("aiding.TrueHeading",),
    (0x13, 0x32): ("aiding.MagneticField",),
    (0x13, 0x33): ("aiding.Pressure",),
    (0x7F, 0x10): ("system.CommunicationMode",),
    (0x7F, 0x90): ("system.CommunicationModeResponse",),
    (0x80, 0x04): ("sensor.ScaledAccel",),
    (0x80, 0x05): ("sensor.ScaledGyro",),
    (0x80, 0x06): ("sensor.ScaledMag",),
    (0x80, 0x07): ("sensor.DeltaTheta",),
    (0x80, 0x08): ("sensor.DeltaVelocity",),
    (0x80, 0x09): ("sensor.CfOrientationMatrix",),
    (0x80, 0x0A): ("sensor.CfQuaternion",),
    (0x80, 0x0C): ("sensor.CfEulerAngles",),
    (0x80, 0x10): ("sensor.CfStabilizedNorth",),
    (0x80, 0x11): ("sensor.CfStabilizedUp",),
    (0x80, 0x12): ("sensor.GpsTimestamp",),
    (0x80, 0x14): ("sensor.TemperatureStatistics",),
    (0x80, 0x17): ("sensor.ScaledPressure",),
    (0x80, 0x18): ("sensor.OverrangeStatus",),
    (0x80, 0x40): ("sensor.OdometerData",),
    (0x81, 0x03): ("gnss_data.LlhPosition",),
    (0x81, 0x04): ("gnss_data.EcefPosition",),
    (0x81, 0x05): ("gnss_data.NedVelocity",),
    (0x81, 0x06): ("gnss_data.EcefVelocity",),
    (0x81, 0x07): ("gnss_data.Dop",),
    (0x81, 0x08): ("gnss_data.UtcTime",),
    (0x81, 0x09): ("gnss_data.GpsTime",),
    (0x81, 0x0A): ("gnss_data.ClockInfo",),
    (0x81, 0x0B): ("gnss_data.FixInfo",),
    (0x81, 0x0C): ("gnss_data.SvInfo",),
    (0x81, 0x0D): ("gnss_data.HardwareStatus",),
    (0x81, 0x0E): ("gnss_data.DgnssInfo",),
    (0x81, 0x0F): ("gnss_data.DgnssChannelStatus",),
    (0x82, 0x01): ("filter_data.LlhPosition",),
    (0x82, 0x02): ("filter_data.NedVelocity",),
    (0x82, 0x03): ("filter_data.AttitudeQuaternion",),
    (0x82, 0x04): ("filter_data.AttitudeDcm",),
    (0x82, 0x05): ("filter_data.EulerAngles",),
    (0x82, 0x06): ("filter_data.GyroBias",),
    (0x82, 0x07): ("filter_data.AccelBias",),
    (0x82, 0x08): ("filter_data.LlhPositionUncertainty",),
    (0x82, 0x09): ("filter_data.NedVelocityUncertainty",),
    (0x82, 0x0A): ("filter_data.EulerAnglesUncertainty",),
    (0x82, 0x0B): ("filter_data.GyroBiasUncertainty",),
    (0x82, 0x0C): ("filter_data.AccelBiasUncertainty",),
    (0x82, 0x0D): ("filter_data.LinearAccel",),
    (0x82, 0x0E): ("filter_data.CompAngularRate",),
    (0x82, 0x0F): ("filter_data.Wgs84GravityMagnitude",),
    (0x82, 0x10): ("filter_data.FilterStatus_gx5_45", "filter_data.FilterStatus_cv7_ins"),
    (0x82, 0x11): ("filter_data.GpsTimestamp",),
    (0x82, 0x12): ("filter_data.QuaternionAttitudeUncertainty",),
    (0x82, 0x13): ("filter_data.GravityVector",),
    (0x82, 0x14): ("filter_data.HeadingUpdateState",),
    (0x82, 0x15): ("filter_data.MagneticModel",),
    (0x82, 0x16): ("filter_data.GyroScaleFactor",),
    (0x82, 0x17): ("filter_data.AccelScaleFactor",),
    (0x82, 0x18): ("filter_data.GyroScaleFactorUncertainty",),
    (0x82, 0x19): ("filter_data.AccelScaleFactorUncertainty",),
    (0x82, 0x1C): ("filter_data.CompensatedAccel",),
    (0x82, 0x20): ("filter_data.StandardAtmosphere",),
    (0x82, 0x21): ("filter_data.PressureAltitude",),
    (0x82, 0x25): ("filter_data.MagAutoHardIronOffset",),
    (0x82, 0x26): ("filter_data.MagAutoSoftIronMatrix",),
    (0x82, 0x28): ("filter_data.MagAutoHardIronOffsetUncertainty",),
    (0x82, 0x29): ("filter_data.MagAutoSoftIronMatrixUncertainty",),
    (0x82, 0x30): ("filter_data.GnssAntennaOffsetCorrection",),
    (0x82, 0x31): ("filter_data.GnssAntennaOffsetCorrectionUncertainty",),
    (0x82, 0x34): ("filter_data.MultiAntennaOffsetCorrection",),
    (0x82, 0x35): ("filter_data.MultiAntennaOffsetCorrectionUncertainty",),
    (0x82, 0x36): ("filter_data.EcefPositionUncertainty",),
    (0x82, 0x37): ("filter_data.EcefVelocityUncertainty",),
    (0x82, 0x40): ("filter_data.EcefPosition",),
    (0x82, 0x41): ("filter_data.EcefVelocity",),
    (0x82, 0x42): ("filter_data.NedRelativePosition",),
    (0x82, 0x43): ("filter_data.GnssPositionAidingStatus",),
    (0x82, 0x46): ("filter_data.AidingMeasurementSummary",),
    (0x82, 0x47): ("filter_data.OdometerScaleFactorError",),
    (0x82, 0x48): ("filter_data.OdometerScaleFactorErrorUncertainty",),
    (0x82, 0x49): ("filter_data.GnssDualAntennaStatus",),
    (0x82, 0x50): ("filter_data.AidingFrameConfigError",),
    (0x82, 0x51): ("filter_data.AidingFrameConfigErrorUncertainty",),
    (0x91, 0x03): ("gnss_receiver_1.LlhPosition",),
    (0x91, 0x04): ("gnss_receiver_1.EcefPosition",),
    (0x91, 0x05): ("gnss_receiver_1.NedVelocity",),
    (0x91, 0x06): ("gnss_receiver_1.EcefVelocity",),
    (0x91, 0x07): ("gnss_receiver_1.Dop",),
    (0x91, 0x08): ("gnss_receiver_1.UtcTime",),
    (0x91, 0x09): ("gnss_receiver_1.GpsTime",),
    (0x91, 0x0B): ("gnss_receiver_1.FixInfo",),
    (0x91, 0x0D): ("gnss_receiver_1.HardwareStatus",),
    (0x91, 0x10): ("gnss_receiver_1.ClockInfo2",),
    (0x91, 0x11): ("gnss_receiver_1.GpsLeapSeconds",),
    (0x91, 0x12): ("gnss_receiver_1.SbasInfo",),
    (0x91, 0x20): ("gnss_receiver_1.SatelliteStatus",),
    (0x91, 0x22): ("gnss_receiver_1.Raw",),
    (0x91, 0x61): ("gnss_receiver_1.GpsEphemeris",),
    (0x91, 0x62): ("gnss_receiver_1.GlonassEphemeris",),
    (0x91, 0x63): ("gnss_receiver_1.GalileoEphemeris",),
    (0x91, 0x64): ("gnss_receiver_1.BeidouEphemeris",),
    (0x92, 0x03): ("gnss_receiver_2.LlhPosition",),
    (0x92, 0x04): ("gnss_receiver_2.EcefPosition",),
    (0x92, 0x05): ("gnss_receiver_2.NedVelocity",),
    (0x92, 0x06): ("gnss_receiver_2.EcefVelocity",),
    (0x92, 0x07): ("gnss_receiver_2.Dop",),
    (0x92, 0x08): ("gnss_receiver_2.UtcTime",),
    (0x92, 0x09): ("gnss_receiver_2.GpsTime",),
    (0x92, 0x0B): ("gnss_receiver_2.FixInfo",),
    (0x92, 0x0D): ("gnss_receiver_2.HardwareStatus",),
    (0x92, 0x10): ("gnss_receiver_2.ClockInfo2",),
    (0x92, 0x11): ("gnss_receiver_2.GpsLeapSeconds",),
    (0x92, 0x12): ("gnss_receiver_2.SbasInfo",),
    (0x92, 0x20): ("gnss_receiver_2.SatelliteStatus",),
    (0x92, 0x22): ("gnss_receiver_2.Raw",),
    (0x92, 0x61): ("gnss_receiver_2.GpsEphemeris",),
    (0x92, 0x62): ("gnss_receiver_2.GlonassEphemeris",),
    (0x92, 0x63): ("gnss_receiver_2.GalileoEphemeris",),
    (0x92, 0x64): ("gnss_receiver_2.BeidouEphemeris",),
    (0x93, 0x30): ("gnss_corrections.BaseStationInfo",),
    (0x93, 0x31): ("gnss_corrections.RtkCorrectionsStatus",),
    (0x94, 0x03): ("gnss_external.LlhPosition",),
    (0x94, 0x05): ("gnss_external.NedVelocity",),
    (0x94, 0x08): ("gnss_external.UtcTime",),
    (0x94, 0x0B): ("gnss_external.FixInfo",),
    (0x94, 0x20): ("gnss_external.SatelliteStatus",),
    (0xA0, 0x01): ("system_data.BuiltInTest",),
    (0xA0, 0x02): ("system_data.TimeSyncStatus",),
    (0xA0, 0x03): ("system_data.GpioState",),
    (0xFF, 0xD0): ("shared.EventSource",),
    (0xFF, 0xD3): ("shared.GpsTimestamp",),
    (0xFF, 0xD4): ("shared.DeltaTime",),
    (0xFF, 0xD5): ("shared.ReferenceTimestamp",),
    (0xFF, 0xD6): ("shared.ReferenceTimeDelta",),
    (0xFF, 0xD7): ("shared.ExternalTimestamp",),
    (0xFF, 0xD8): ("shared.ExternalTimeDelta",),
}

_RESERVED_CLASSES: Dict[str, Dict[int, Tuple[str, ...]]] = {
    "command": {
        0xF1: ("reserved.AckNack",),
    },
}

if TYPE_CHECKING:
    # Built on first access (module __getattr__ below), every set's module imported.
    FIELDS: Dict[Tuple[int, int], Tuple[Type[Field], ...]]
    RESERVED: Dict[str, Dict[int, Tuple[Type[Field], ...]]]

_resolved: Dict[Any, Tuple[Type[Field], ...]] = {}


def _classes(names: Iterable[str]) -> Tuple[Type[Field], ...]:
    out = []
    for name in names:
        module, _, cls = name.partition(".")
        out.append(getattr(importlib.import_module(f"{__package__}.{module}"), cls))
    return tuple(out)


def _field(set_id: int, descriptor: int) -> Optional[Tuple[Type[Field], ...]]:
    key = (set_id, descriptor)
    classes = _resolved.get(key)
    if classes is None:
        names = _FIELD_CLASSES.get(key)
        if names is None:
            return None
        classes = _resolved[key] = _classes(names)
    return classes


def _reserved(kind: str, descriptor: int) -> Optional[Tuple[Type[Field], ...]]:
    key = (kind, descriptor)
    classes = _resolved.get(key)
    if classes is None:
        names = _RESERVED_CLASSES.get(kind, {}).get(descriptor)
        if names is None:
            return None
        classes = _resolved[key] = _classes(names)
    return classes


def __getattr__(name: str) -> Any:
    """FIELDS ((set, descriptor) -> layout classes) and RESERVED (kind -> descriptor -> layout
    classes), built on first access."""
    value: Any
    if name == "FIELDS":
        value = {key: _field(*key) for key in _FIELD_CLASSES}
    elif name == "RESERVED":
        value = {k: {d: _reserved(k, d) for d in entries} for k, entries in _RESERVED_CLASSES.items()}
    else:
        raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
    globals()[name] = value
    return value


def set_kind(set_id: int) -> Optional[str]:
    """The kind of a descriptor set ("command", "data", ...) from the set_kinds ranges."""
    for kind, first, last in SET_KINDS:
        if first <= set_id <= last:
            return kind
    return None


def lookup(set_id: int, descriptor: int) -> Optional[Tuple[Type[Field], ...]]:
    """The layout classes for a field, or None: set's own field, reserved field, shared data field."""
    classes = _field(set_id, descriptor)
    if classes is not None:
        return classes
    kind = set_kind(set_id)
    classes = _reserved(kind or "", descriptor)
    if classes is not None:
        return classes
    if kind == "data" and SHARED_SET is not None:
        return _field(SHARED_SET, descriptor)
    return None
