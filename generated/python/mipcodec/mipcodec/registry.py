"""Dispatch tables of the MicroStrain MIP: (set, descriptor) -> layout classes.

A field with per-device variants maps to several classes, tried in IR order (docs/conformance.md
section 2). Reserved fields apply to every set of a kind; shared data descriptors to every data set.
"""

from __future__ import annotations

from typing import Dict, Optional, Tuple

from . import aiding, base, filter, gnss, reserved, sensor, system, threedm

DEVICES: Tuple[str, ...] = ("gx5_45", "cv7_ins")

SET_NAMES: Dict[int, str] = {
    0x01: "base",
    0x0C: "threedm",
    0x0D: "filter",
    0x0E: "gnss",
    0x13: "aiding",
    0x7F: "system",
    0x80: "sensor",
}

SET_KINDS: Tuple[Tuple[str, int, int], ...] = (
    ("command", 0x01, 0x7F),
    ("data", 0x80, 0xFF),
)

SHARED_SET: Optional[int] = 0xFF

FIELDS: Dict[Tuple[int, int], Tuple[type, ...]] = {
    (0x01, 0x01): (base.Ping,),
    (0x01, 0x02): (base.SetToIdle,),
    (0x01, 0x03): (base.GetDeviceInfo,),
    (0x01, 0x81): (base.DeviceInfo,),
    (0x01, 0x04): (base.GetDeviceDescriptors,),
    (0x01, 0x82): (base.DeviceDescriptors,),
    (0x01, 0x05): (base.BuiltInTest,),
    (0x01, 0x83): (base.BuiltInTestResult_gx5_45, base.BuiltInTestResult_cv7_ins),
    (0x01, 0x06): (base.Resume,),
    (0x01, 0x07): (base.GetExtendedDescriptors,),
    (0x01, 0x86): (base.ExtendedDescriptors,),
    (0x01, 0x08): (base.ContinuousBit,),
    (0x01, 0x88): (base.ContinuousBitResult,),
    (0x01, 0x09): (base.CommPortSpeed,),
    (0x01, 0x89): (base.CommPortSpeedResponse,),
    (0x01, 0x72): (base.GpsTimeUpdate_gx5_45, base.GpsTimeUpdate_cv7_ins),
    (0x01, 0x84): (base.GpsWeek,),
    (0x01, 0x85): (base.GpsSeconds,),
    (0x01, 0x7E): (base.DeviceReset,),
    (0x0C, 0x2B): (threedm.EventControl,),
    (0x0C, 0xB5): (threedm.EventControlResponse,),
    (0x0C, 0x2C): (threedm.GetEventTriggerStatus,),
    (0x0C, 0xB6): (threedm.EventTriggerStatus,),
    (0x0C, 0x2D): (threedm.GetEventActionStatus,),
    (0x0C, 0xB7): (threedm.EventActionStatus,),
    (0x0C, 0x2E): (threedm.EventTriggerConfig,),
    (0x0C, 0xB8): (threedm.EventTriggerConfigResponse,),
    (0x0C, 0x2F): (threedm.EventActionConfig,),
    (0x0C, 0xB9): (threedm.EventActionConfigResponse,),
    (0x0D, 0x01): (filter.ResetFilter,),
    (0x0D, 0x02): (filter.SetInitialAttitude,),
    (0x0D, 0x03): (filter.SetInitialHeading,),
    (0x0D, 0x05): (filter.RunFilter,),
    (0x0D, 0x10): (filter.VehicleDynamicsMode,),
    (0x0D, 0x80): (filter.VehicleDynamicsModeResponse,),
    (0x0D, 0x11): (filter.SensorToVehicleTransform,),
    (0x0D, 0x81): (filter.SensorToVehicleTransformResponse,),
    (0x0D, 0x12): (filter.SensorToVehicleOffset,),
    (0x0D, 0x82): (filter.SensorToVehicleOffsetResponse,),
    (0x0D, 0x13): (filter.AntennaOffset,),
    (0x0D, 0x83): (filter.AntennaOffsetResponse,),
    (0x0D, 0x14): (filter.EstimationControl,),
    (0x0D, 0x84): (filter.EstimationControlResponse,),
    (0x0D, 0x15): (filter.GnssSourceControl,),
    (0x0D, 0x86): (filter.GnssSourceControlResponse,),
    (0x0D, 0x16): (filter.ExternalGnssUpdate,),
    (0x0D, 0x17): (filter.ExternalHeadingUpdate,),
    (0x0D, 0x18): (filter.HeadingUpdateControl,),
    (0x0D, 0x87): (filter.HeadingUpdateControlResponse,),
    (0x0D, 0x19): (filter.AutoInitControl,),
    (0x0D, 0x88): (filter.AutoInitControlResponse,),
    (0x0D, 0x1A): (filter.AccelNoise,),
    (0x0D, 0x89): (filter.AccelNoiseResponse,),
    (0x0D, 0x1B): (filter.GyroNoise,),
    (0x0D, 0x8A): (filter.GyroNoiseResponse,),
    (0x0D, 0x1C): (filter.AccelBiasModel,),
    (0x0D, 0x8B): (filter.AccelBiasModelResponse,),
    (0x0D, 0x1D): (filter.GyroBiasModel,),
    (0x0D, 0x8C): (filter.GyroBiasModelResponse,),
    (0x0D, 0x1E): (filter.ZuptControl,),
    (0x0D, 0x8D): (filter.ZuptControlResponse,),
    (0x0D, 0x1F): (filter.ExternalHeadingUpdateWithTime,),
    (0x0D, 0x20): (filter.ZeroAngularRateUpdateControl,),
    (0x0D, 0x8E): (filter.ZeroAngularRateUpdateControlResponse,),
    (0x0D, 0x21): (filter.TareOrientation,),
    (0x0D, 0x22): (filter.CommandedZupt,),
    (0x0D, 0x23): (filter.CommandedZeroAngularRateUpdate,),
    (0x0D, 0x27): (filter.MagCaptureAutoCalibration,),
    (0x0D, 0x28): (filter.GravityNoiseStdDev,),
    (0x0D, 0x93): (filter.GravityNoiseStdDevResponse,),
    (0x0D, 0x29): (filter.PressureAltitudeNoiseStdDev,),
    (0x0D, 0x94): (filter.PressureAltitudeNoiseStdDevResponse,),
    (0x0D, 0x2B): (filter.HardIronOffsetNoise,),
    (0x0D, 0x96): (filter.HardIronOffsetNoiseResponse,),
    (0x0D, 0x2C): (filter.SoftIronMatrixNoise,),
    (0x0D, 0x97): (filter.SoftIronMatrixNoiseResponse,),
    (0x0D, 0x42): (filter.MagNoiseStdDev,),
    (0x0D, 0xB1): (filter.MagNoiseStdDevResponse,),
    (0x0D, 0x43): (filter.DeclinationSource,),
    (0x0D, 0xB2): (filter.DeclinationSourceResponse,),
    (0x0D, 0x44): (filter.GravityMagnitudeAdaptiveMeasurement,),
    (0x0D, 0xB3): (filter.GravityMagnitudeAdaptiveMeasurementResponse,),
    (0x0D, 0x45): (filter.MagMagnitudeAdaptiveMeasurement,),
    (0x0D, 0xB4): (filter.MagMagnitudeAdaptiveMeasurementResponse,),
    (0x0D, 0x46): (filter.MagDipAngleAdaptiveMeasurement,),
    (0x0D, 0xB5): (filter.MagDipAngleAdaptiveMeasurementResponse,),
    (0x0D, 0x47): (filter.AltitudeAidingControl,),
    (0x0D, 0xB7): (filter.AltitudeAidingControlResponse,),
    (0x0D, 0x4B): (filter.PitchRollAidingControl,),
    (0x0D, 0xBB): (filter.PitchRollAidingControlResponse,),
    (0x0D, 0x4C): (filter.InclinationSource,),
    (0x0D, 0xBC): (filter.InclinationSourceResponse,),
    (0x0D, 0x4D): (filter.MagneticFieldMagnitudeSource,),
    (0x0D, 0xBD): (filter.MagneticFieldMagnitudeSourceResponse,),
    (0x0D, 0x50): (filter.AidingMeasurementControl,),
    (0x0D, 0xD0): (filter.AidingMeasurementControlResponse,),
    (0x0D, 0x52): (filter.InitializationConfiguration,),
    (0x0D, 0xD2): (filter.InitializationConfigurationResponse,),
    (0x0D, 0x53): (filter.AdaptiveFilterControl,),
    (0x0D, 0xD3): (filter.AdaptiveFilterControlResponse,),
    (0x0D, 0x54): (filter.MultiAntennaOffset,),
    (0x0D, 0xD4): (filter.MultiAntennaOffsetResponse,),
    (0x0D, 0x55): (filter.RelativePositionConfiguration,),
    (0x0D, 0xD5): (filter.RelativePositionConfigurationResponse,),
    (0x0D, 0x56): (filter.ReferencePointLeverArm,),
    (0x0D, 0xD6): (filter.ReferencePointLeverArmResponse,),
    (0x0D, 0x61): (filter.SpeedLeverArm,),
    (0x0D, 0xE1): (filter.SpeedLeverArmResponse,),
    (0x0D, 0x63): (filter.WheeledVehicleConstraintControl,),
    (0x0D, 0xE3): (filter.WheeledVehicleConstraintControlResponse,),
    (0x0D, 0x64): (filter.GnssAntennaCalibrationControl,),
    (0x0D, 0xE4): (filter.GnssAntennaCalibrationControlResponse,),
    (0x0E, 0x01): (gnss.ReceiverInfo,),
    (0x0E, 0x81): (gnss.ReceiverInfoResponse,),
    (0x0E, 0x02): (gnss.SignalConfiguration,),
    (0x0E, 0x82): (gnss.SignalConfigurationResponse,),
    (0x0E, 0x20): (gnss.SpartnConfiguration,),
    (0x0E, 0xA0): (gnss.SpartnConfigurationResponse,),
    (0x13, 0x01): (aiding.FrameConfig,),
    (0x13, 0x81): (aiding.FrameConfigResponse,),
    (0x13, 0x1F): (aiding.EchoControl,),
    (0x13, 0x9F): (aiding.EchoControlResponse,),
    (0x13, 0x21): (aiding.EcefPosition,),
    (0x13, 0x22): (aiding.LlhPosition,),
    (0x13, 0x23): (aiding.HeightAboveEllipsoid,),
    (0x13, 0x28): (aiding.EcefVelocity,),
    (0x13, 0x29): (aiding.NedVelocity,),
    (0x13, 0x2A): (aiding.BodyFrameVelocity,),
    (0x13, 0x31): (aiding.TrueHeading,),
    (0x13, 0x32): (aiding.MagneticField,),
    (0x13, 0x33): (aiding.Pressure,),
    (0x7F, 0x10): (system.CommunicationMode,),
    (0x7F, 0x90): (system.CommunicationModeResponse,),
    (0x80, 0x04): (sensor.ScaledAccel,),
    (0x80, 0x05): (sensor.ScaledGyro,),
    (0x80, 0x06): (sensor.ScaledMag,),
}

RESERVED: Dict[str, Dict[int, Tuple[type, ...]]] = {
    "command": {
        0xF1: (reserved.AckNack,),
    },
}


def set_kind(set_id: int) -> Optional[str]:
    """The kind of a descriptor set ("command", "data", ...) from the set_kinds ranges."""
    for kind, first, last in SET_KINDS:
        if first <= set_id <= last:
            return kind
    return None


def lookup(set_id: int, descriptor: int) -> Optional[Tuple[type, ...]]:
    """The layout classes for a field, or None: set's own field, reserved field, shared data field."""
    classes = FIELDS.get((set_id, descriptor))
    if classes is not None:
        return classes
    kind = set_kind(set_id)
    classes = RESERVED.get(kind or "", {}).get(descriptor)
    if classes is not None:
        return classes
    if kind == "data" and SHARED_SET is not None:
        return FIELDS.get((SHARED_SET, descriptor))
    return None
