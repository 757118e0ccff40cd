"""Named types of the MicroStrain MIP: enums, bitfields, structs and unions.

Enums are IntEnums; decoding keeps values that are not members as plain ints. Bitfields are ints
whose members are properties (bool for one bit, int for several) with UPPER_CASE mask constants.
Structs are dataclasses; a union value is the selected member's struct (None: member without data).
"""

from __future__ import annotations

import dataclasses as _dc
import typing as _ty

from . import codec as _c


class AckCode(_c.Enum):
    """Ack/Nack code (u8).

    Second byte of the ack/nack field; 0 is an ACK, any other value a NACK giving the reason.
    """

    OK = 0x00  # Success (ACK).
    UNKNOWN_COMMAND = 0x01  # The command descriptor is not supported by this device.
    BAD_CHECKSUM = 0x02  # An otherwise complete packet has a bad checksum (GX5-45: invalid checksum).
    # One or more parameters are invalid: out of the allowed range, or not the expected size or type.
    INVALID_PARAMETER = 0x03
    COMMAND_FAILED = 0x04  # Device could not complete the command.
    COMMAND_TIMEOUT = 0x05  # Device could not complete the command within the expected time.
    UNKNOWN_DESCRIPTOR_SET = 0x06  # Unknown descriptor set (CV7 only). (devices: cv7_ins)


class ActionGpioMode(_c.Enum):
    """GPIO action mode (u8)."""

    DISABLED = 0x00  # Pin state will not be changed.
    ACTIVE_HIGH = 0x01  # High while the trigger is active, low otherwise.
    ACTIVE_LOW = 0x02  # Low while the trigger is active, high otherwise.
    ONESHOT_HIGH = 0x05  # Set high each time the trigger activates.
    ONESHOT_LOW = 0x06  # Set low each time the trigger activates.
    TOGGLE = 0x07  # Toggle each time the trigger activates.


class ActionType(_c.Enum):
    """Event action type (u8)."""

    NONE = 0x00  # No action. Parameters should be empty.
    GPIO = 0x01  # Control the state of a GPIO pin.
    MESSAGE = 0x02  # Output a data packet.


class AdaptiveFilterLevel(_c.Enum):
    """Auto-adaptive filter operating level (u8)."""

    OFF = 0x00  # Adaptive filtering off.
    CONSERVATIVE = 0x01  # Conservative.
    MODERATE = 0x02  # Moderate (default).
    AGGRESSIVE = 0x03  # Aggressive.


class AdaptiveMeasurementMode(_c.Enum):
    """Adaptive measurement mode (u8)."""

    DISABLED = 0x00  # No adaptive measurement.
    FIXED = 0x01  # Fixed adaptive measurement using the specified filter and limit parameters.
    # Auto-adaptive: the Kalman filter re-weights the measurement by its perceived quality (3DM-GX5 and later); limits
    # are ignored.
    AUTO = 0x02


class AidingEchoMode(_c.Enum):
    """Aiding command echo mode (u8)."""

    SUPPRESS_ACK = 0x00  # The aiding measurement commands are not acknowledged.
    STANDARD = 0x01  # Normal ack/nack behavior.
    RESPONSE = 0x02  # The device echoes the aiding data back as a response.


class AidingFrameFormat(_c.Enum):
    """Aiding frame rotation format (u8)."""

    EULER = 0x01  # Translation vector followed by Euler angles (roll, pitch, yaw).
    QUATERNION = 0x02  # Translation vector followed by a quaternion (w, x, y, z).


@_c.bitfield("u16")
class AidingLlhValidFlags(_c.Bitfield):
    """LLH position aiding valid flags (u16 bitfield)."""

    _MEMBERS = (
        ("latitude", "latitude", "LATITUDE", 0, 1),
        ("longitude", "longitude", "LONGITUDE", 1, 1),
        ("height", "height", "HEIGHT", 2, 1),
    )
    LATITUDE = 0x0001  # bit 0: Latitude valid.
    LONGITUDE = 0x0002  # bit 1: Longitude valid.
    HEIGHT = 0x0004  # bit 2: Height valid.

    latitude = _c.bit(0)
    longitude = _c.bit(1)
    height = _c.bit(2)


class AidingMeasurementSource(_c.Enum):
    """Aiding measurement source (u16)."""

    GNSS_POS_VEL = 0x00  # GNSS position and velocity.
    GNSS_HEADING = 0x01  # GNSS heading (dual antenna).
    ALTIMETER = 0x02  # Pressure altimeter (built-in sensor).
    SPEED = 0x03  # Speed sensor / odometer.
    MAGNETOMETER = 0x04  # Magnetometer (built-in sensor).
    EXTERNAL_HEADING = 0x05  # External heading input.
    EXTERNAL_ALTIMETER = 0x06  # External pressure altimeter input.
    EXTERNAL_MAGNETOMETER = 0x07  # External magnetometer input.
    BODY_FRAME_VEL = 0x08  # External body frame velocity input.
    ALL = 0xFFFF  # All sources (for save, load and default).


class AidingTimebase(_c.Enum):
    """Aiding measurement timebase (u8).

    Clock in which the timestamp of an aiding measurement is expressed.
    """

    INTERNAL_REFERENCE = 0x01  # Timestamp in the device's internal reference time (nanoseconds since power-on).
    EXTERNAL_TIME = 0x02  # Timestamp in external time, synchronised by the PPS source and GPS time update.
    TIME_OF_ARRIVAL = 0x03  # No timestamp: the measurement is taken at its arrival time, with a fixed latency.


@_c.bitfield("u16")
class AidingVectorValidFlags(_c.Bitfield):
    """Aiding vector valid flags (u16 bitfield).

    Which axes of a 3-axis aiding measurement are valid; axes with 0 are ignored.
    """

    _MEMBERS = (
        ("x", "x", "X", 0, 1),
        ("y", "y", "Y", 1, 1),
        ("z", "z", "Z", 2, 1),
    )
    X = 0x0001  # bit 0: X (or north) component valid.
    Y = 0x0002  # bit 1: Y (or east) component valid.
    Z = 0x0004  # bit 2: Z (or down) component valid.

    x = _c.bit(0)
    y = _c.bit(1)
    z = _c.bit(2)


class AltitudeAidingSource(_c.Enum):
    """Altitude aiding source (u8)."""

    NONE = 0x00  # No altitude aiding (disabled).
    PRESSURE = 0x01  # Pressure sensor aiding enabled.


class AssistedFixOption(_c.Enum):
    """Assisted fix option (u8)."""

    NONE = 0x00  # No assisted fix (default).
    ENABLED = 0x01  # Assisted fix enabled.


@_c.bitfield("u16")
class ConstellationOptions(_c.Bitfield):
    """GNSS constellation option flags (u16 bitfield)."""

    _MEMBERS = (("l1saif", "l1saif", "L1SAIF", 0, 1),)
    L1SAIF = 0x0001  # bit 0: L1SAIF signal (QZSS only).

    l1saif = _c.bit(0)


@_c.bitfield("u32")
class Cv7BitFlags(_c.Bitfield):
    """3DM-CV7 commanded built-in test result (u32 bitfield)."""

    _MEMBERS = (
        ("general_hardware_fault", "general_hardware_fault", "GENERAL_HARDWARE_FAULT", 0, 1),
        ("general_firmware_fault", "general_firmware_fault", "GENERAL_FIRMWARE_FAULT", 1, 1),
        ("timing_overload", "timing_overload", "TIMING_OVERLOAD", 2, 1),
        ("buffer_overrun", "buffer_overrun", "BUFFER_OVERRUN", 3, 1),
        ("reserved_system", "reserved_system", "RESERVED_SYSTEM", 4, 4),
        ("reserved_comms", "reserved_comms", "RESERVED_COMMS", 8, 4),
        ("accelerometer_fault", "accelerometer_fault", "ACCELEROMETER_FAULT", 12, 1),
        ("gyroscope_fault", "gyroscope_fault", "GYROSCOPE_FAULT", 13, 1),
        ("magnetometer_fault", "magnetometer_fault", "MAGNETOMETER_FAULT", 14, 1),
        ("pressure_sensor_fault", "pressure_sensor_fault", "PRESSURE_SENSOR_FAULT", 15, 1),
        ("reserved_imu", "reserved_imu", "RESERVED_IMU", 16, 2),
        ("calibration_error", "calibration_error", "CALIBRATION_ERROR", 18, 1),
        ("general_imu_fault", "general_imu_fault", "GENERAL_IMU_FAULT", 19, 1),
        ("reserved_filter", "reserved_filter", "RESERVED_FILTER", 20, 2),
        ("filter_solution_fault", "filter_solution_fault", "FILTER_SOLUTION_FAULT", 22, 1),
        ("general_filter_fault", "general_filter_fault", "GENERAL_FILTER_FAULT", 23, 1),
        ("reserved", "reserved", "RESERVED", 24, 8),
    )
    GENERAL_HARDWARE_FAULT = 0x00000001  # bit 0: A critical hardware component has failed or is not operating properly.
    # bit 1: System firmware has detected a serious, unexpected or abnormal condition.
    GENERAL_FIRMWARE_FAULT = 0x00000002
    TIMING_OVERLOAD = 0x00000004  # bit 2: The system cannot keep up with the processing demand.
    BUFFER_OVERRUN = 0x00000008  # bit 3: A data buffer has reached its capacity.
    RESERVED_SYSTEM = 0x000000F0  # bits 4-7: Reserved (system). (reserved)
    RESERVED_COMMS = 0x00000F00  # bits 8-11: Reserved (comms). (reserved)
    ACCELEROMETER_FAULT = 0x00001000  # bit 12: The accelerometer has been damaged or is inoperative.
    GYROSCOPE_FAULT = 0x00002000  # bit 13: The gyroscope has been damaged or is inoperative.
    MAGNETOMETER_FAULT = 0x00004000  # bit 14: The magnetometer has been damaged or is inoperative.
    PRESSURE_SENSOR_FAULT = 0x00008000  # bit 15: The pressure sensor has been damaged or is inoperative.
    RESERVED_IMU = 0x00030000  # bits 16-17: Reserved (IMU). (reserved)
    CALIBRATION_ERROR = 0x00040000  # bit 18: One or more IMU calibration tables are invalid.
    GENERAL_IMU_FAULT = 0x00080000  # bit 19: A problem has been detected in the IMU subsystem.
    RESERVED_FILTER = 0x00300000  # bits 20-21: Reserved (filter). (reserved)
    FILTER_SOLUTION_FAULT = 0x00400000  # bit 22: The filter solution is invalid (NaN in the filter output).
    GENERAL_FILTER_FAULT = 0x00800000  # bit 23: A problem has been detected in the filter subsystem.
    RESERVED = 0xFF000000  # bits 24-31: Reserved. (reserved)

    general_hardware_fault = _c.bit(0)
    general_firmware_fault = _c.bit(1)
    timing_overload = _c.bit(2)
    buffer_overrun = _c.bit(3)
    reserved_system = _c.bits(4, 4)
    reserved_comms = _c.bits(8, 4)
    accelerometer_fault = _c.bit(12)
    gyroscope_fault = _c.bit(13)
    magnetometer_fault = _c.bit(14)
    pressure_sensor_fault = _c.bit(15)
    reserved_imu = _c.bits(16, 2)
    calibration_error = _c.bit(18)
    general_imu_fault = _c.bit(19)
    reserved_filter = _c.bits(20, 2)
    filter_solution_fault = _c.bit(22)
    general_filter_fault = _c.bit(23)
    reserved = _c.bits(24, 8)


class DeviceStatusSelector(_c.Enum):
    """Device status selector (u8)."""

    BASIC = 0x01  # Basic status structure.
    DIAGNOSTIC = 0x02  # Diagnostic status structure.


@_c.bitfield("u16")
class EstimationControlFlags(_c.Bitfield):
    """Estimation control flags (u16 bitfield).

    Which optional states the Kalman filter estimates.
    """

    _MEMBERS = (
        ("gyro_bias", "gyro_bias", "GYRO_BIAS", 0, 1),
        ("accel_bias", "accel_bias", "ACCEL_BIAS", 1, 1),
        ("gyro_scale_factor", "gyro_scale_factor", "GYRO_SCALE_FACTOR", 2, 1),
        ("accel_scale_factor", "accel_scale_factor", "ACCEL_SCALE_FACTOR", 3, 1),
        ("antenna_offset", "antenna_offset", "ANTENNA_OFFSET", 4, 1),
        ("hard_iron_auto_cal", "hard_iron_auto_cal", "HARD_IRON_AUTO_CAL", 5, 1),
        ("soft_iron_auto_cal", "soft_iron_auto_cal", "SOFT_IRON_AUTO_CAL", 6, 1),
        ("reserved", "reserved", "RESERVED", 7, 9),
    )
    GYRO_BIAS = 0x0001  # bit 0: Estimate gyro bias (recommended).
    ACCEL_BIAS = 0x0002  # bit 1: Estimate accelerometer bias (recommended).
    GYRO_SCALE_FACTOR = 0x0004  # bit 2: Estimate gyro scale factor (optional).
    ACCEL_SCALE_FACTOR = 0x0008  # bit 3: Estimate accelerometer scale factor (optional).
    ANTENNA_OFFSET = 0x0010  # bit 4: Estimate the GNSS antenna offset (optional).
    HARD_IRON_AUTO_CAL = 0x0020  # bit 5: Hard iron auto-calibration (optional).
    SOFT_IRON_AUTO_CAL = 0x0040  # bit 6: Soft iron auto-calibration (optional).
    RESERVED = 0xFF80  # bits 7-15: Not named by the manual. (reserved)

    gyro_bias = _c.bit(0)
    accel_bias = _c.bit(1)
    gyro_scale_factor = _c.bit(2)
    accel_scale_factor = _c.bit(3)
    antenna_offset = _c.bit(4)
    hard_iron_auto_cal = _c.bit(5)
    soft_iron_auto_cal = _c.bit(6)
    reserved = _c.bits(7, 9)


class EventControlMode(_c.Enum):
    """Event trigger control mode (u8)."""

    DISABLED = 0x00  # Trigger is disabled.
    ENABLED = 0x01  # Trigger is enabled and will work normally.
    TEST = 0x02  # Forces the trigger to the active state for testing purposes.
    TEST_PULSE = 0x03  # Trigger is forced active for one event cycle only, then reverts.


class ExternalHeadingType(_c.Enum):
    """External heading type (u8).

    Reference of an externally supplied heading angle.
    """

    TRUE_HEADING = 0x01  # True heading (from true north).
    MAGNETIC_HEADING = 0x02  # Magnetic heading (from magnetic north).


class FactoryStreamingAction(_c.Enum):
    """Factory streaming action (u8)."""

    OVERWRITE = 0x00  # Replace the message formats, dropping the descriptors already there.
    MERGE = 0x01  # Merge the support descriptors into the existing formats (order may change).
    ADD = 0x02  # Append the support descriptors to the existing formats (duplicates possible).


@_c.bitfield("u8")
class FilterAidingMeasurementIndicator(_c.Bitfield):
    """Aiding measurement indicator (u8 bitfield).

    State of one aiding measurement over the last measurement interval.
    """

    _MEMBERS = (
        ("enabled", "enabled", "ENABLED", 0, 1),
        ("used", "used", "USED", 1, 1),
        ("residual_high_warning", "residual_high_warning", "RESIDUAL_HIGH_WARNING", 2, 1),
        ("sample_time_warning", "sample_time_warning", "SAMPLE_TIME_WARNING", 3, 1),
        ("configuration_error", "configuration_error", "CONFIGURATION_ERROR", 4, 1),
        ("max_num_meas_exceeded", "max_num_meas_exceeded", "MAX_NUM_MEAS_EXCEEDED", 5, 1),
    )
    ENABLED = 0x01  # bit 0: The measurement is enabled.
    USED = 0x02  # bit 1: The measurement was used by the filter.
    RESIDUAL_HIGH_WARNING = 0x04  # bit 2: Measurement residual is high.
    SAMPLE_TIME_WARNING = 0x08  # bit 3: Problem with the measurement's sample time.
    CONFIGURATION_ERROR = 0x10  # bit 4: The measurement is misconfigured.
    MAX_NUM_MEAS_EXCEEDED = 0x20  # bit 5: More measurements than the filter can process.

    enabled = _c.bit(0)
    used = _c.bit(1)
    residual_high_warning = _c.bit(2)
    sample_time_warning = _c.bit(3)
    configuration_error = _c.bit(4)
    max_num_meas_exceeded = _c.bit(5)


class FilterAidingMeasurementType(_c.Enum):
    """Aiding measurement type (u8).

    Which aiding measurement an Aiding Measurement Summary (0x82,0x46) describes. Values 0x20 and
    above are the measurements commanded through the Aiding command set (0x13); their value is the
    descriptor of that command.
    """

    GNSS = 0x01  # GNSS receiver measurement.
    DUAL_ANTENNA = 0x02  # GNSS dual-antenna heading.
    HEADING = 0x03  # Heading measurement.
    PRESSURE = 0x04  # Pressure (barometric altitude).
    MAGNETOMETER = 0x05  # Magnetometer.
    SPEED = 0x06  # Speed sensor (odometer).
    AIDING_POS_ECEF = 0x21  # ECEF position aiding command (0x13,0x21).
    AIDING_POS_LLH = 0x22  # LLH position aiding command (0x13,0x22).
    AIDING_HEIGHT_ABOVE_ELLIPSOID = 0x23  # Height above ellipsoid aiding command (0x13,0x23).
    AIDING_VEL_ECEF = 0x28  # ECEF velocity aiding command (0x13,0x28).
    AIDING_VEL_NED = 0x29  # NED velocity aiding command (0x13,0x29).
    AIDING_VEL_BODY_FRAME = 0x2A  # Body-frame velocity aiding command (0x13,0x2A).
    AIDING_HEADING_TRUE = 0x31  # True heading aiding command (0x13,0x31).
    AIDING_MAGNETIC_FIELD = 0x32  # Magnetic field aiding command (0x13,0x32).
    AIDING_PRESSURE = 0x33  # Pressure aiding command (0x13,0x33).


class FilterDualAntennaFixType(_c.Enum):
    """Dual-antenna fix type (u8).

    Kind of GNSS dual-antenna heading solution.
    """

    FIX_NONE = 0x00  # No dual-antenna fix.
    FIX_DA_FLOAT = 0x01  # Dual-antenna float solution.
    FIX_DA_FIXED = 0x02  # Dual-antenna fixed (integer) solution.


@_c.bitfield("u16")
class FilterDualAntennaStatusFlags(_c.Bitfield):
    """Dual-antenna status flags (u16 bitfield)."""

    _MEMBERS = (
        ("rcv_1_data_valid", "rcv_1_data_valid", "RCV_1_DATA_VALID", 0, 1),
        ("rcv_2_data_valid", "rcv_2_data_valid", "RCV_2_DATA_VALID", 1, 1),
        ("antenna_offsets_valid", "antenna_offsets_valid", "ANTENNA_OFFSETS_VALID", 2, 1),
    )
    RCV_1_DATA_VALID = 0x0001  # bit 0: Data from receiver 1 are valid.
    RCV_2_DATA_VALID = 0x0002  # bit 1: Data from receiver 2 are valid.
    ANTENNA_OFFSETS_VALID = 0x0004  # bit 2: The antenna offsets are valid.

    rcv_1_data_valid = _c.bit(0)
    rcv_2_data_valid = _c.bit(1)
    antenna_offsets_valid = _c.bit(2)


class FilterDynamicsModeCv7(_c.Enum):
    """Filter dynamics mode (3DM-CV7) (u16).

    Dynamics mode reported in Status (0x82,0x10) by the CV7 (GQ7-family filter).
    """

    DEFAULT = 0x01  # Default dynamics mode (printed GQ7_DEFAULT).


class FilterDynamicsModeGx5(_c.Enum):
    """Filter dynamics mode (3DM-GX5-45) (u16).

    Vehicle dynamics mode the GX5-45 filter runs with, as reported in Filter Status (0x82,0x10).
    """

    PORTABLE = 0x01  # Portable (low-acceleration applications).
    AUTOMOTIVE = 0x02  # Automotive (wheeled vehicles, low vertical acceleration).
    AIRBORNE = 0x03  # Airborne (up to 2 g).


@_c.bitfield("u16")
class FilterGnssAidingStatusFlags(_c.Bitfield):
    """GNSS position aiding status (u16 bitfield).

    What the filter does with the measurements of one GNSS receiver.
    """

    _MEMBERS = (
        ("tight_coupling", "tight_coupling", "TIGHT_COUPLING", 0, 1),
        ("differential", "differential", "DIFFERENTIAL", 1, 1),
        ("integer_fix", "integer_fix", "INTEGER_FIX", 2, 1),
        ("gps_l1", "gps_l1", "GPS_L1", 3, 1),
        ("gps_l2", "gps_l2", "GPS_L2", 4, 1),
        ("gps_l5", "gps_l5", "GPS_L5", 5, 1),
        ("glo_l1", "glo_l1", "GLO_L1", 6, 1),
        ("glo_l2", "glo_l2", "GLO_L2", 7, 1),
        ("gal_e1", "gal_e1", "GAL_E1", 8, 1),
        ("gal_e5", "gal_e5", "GAL_E5", 9, 1),
        ("gal_e6", "gal_e6", "GAL_E6", 10, 1),
        ("bei_b1", "bei_b1", "BEI_B1", 11, 1),
        ("bei_b2", "bei_b2", "BEI_B2", 12, 1),
        ("bei_b3", "bei_b3", "BEI_B3", 13, 1),
        ("no_fix", "no_fix", "NO_FIX", 14, 1),
        ("config_error", "config_error", "CONFIG_ERROR", 15, 1),
    )
    TIGHT_COUPLING = 0x0001  # bit 0: The filter is processing raw range information from this receiver.
    DIFFERENTIAL = 0x0002  # bit 1: The filter is processing RTK corrections from this receiver.
    INTEGER_FIX = 0x0004  # bit 2: The filter has an RTK integer fix from this receiver.
    GPS_L1 = 0x0008  # bit 3: GPS L1 measurements used.
    GPS_L2 = 0x0010  # bit 4: GPS L2 measurements used.
    GPS_L5 = 0x0020  # bit 5: GPS L5 measurements used.
    GLO_L1 = 0x0040  # bit 6: GLONASS L1 measurements used.
    GLO_L2 = 0x0080  # bit 7: GLONASS L2 measurements used.
    GAL_E1 = 0x0100  # bit 8: Galileo E1 measurements used.
    GAL_E5 = 0x0200  # bit 9: Galileo E5 measurements used.
    GAL_E6 = 0x0400  # bit 10: Galileo E6 measurements used.
    BEI_B1 = 0x0800  # bit 11: BeiDou B1 measurements used.
    BEI_B2 = 0x1000  # bit 12: BeiDou B2 measurements used.
    BEI_B3 = 0x2000  # bit 13: BeiDou B3 measurements used.
    NO_FIX = 0x4000  # bit 14: This receiver reports no position fix.
    CONFIG_ERROR = 0x8000  # bit 15: Probably a problem with this receiver's antenna offset.

    tight_coupling = _c.bit(0)
    differential = _c.bit(1)
    integer_fix = _c.bit(2)
    gps_l1 = _c.bit(3)
    gps_l2 = _c.bit(4)
    gps_l5 = _c.bit(5)
    glo_l1 = _c.bit(6)
    glo_l2 = _c.bit(7)
    gal_e1 = _c.bit(8)
    gal_e5 = _c.bit(9)
    gal_e6 = _c.bit(10)
    bei_b1 = _c.bit(11)
    bei_b2 = _c.bit(12)
    bei_b3 = _c.bit(13)
    no_fix = _c.bit(14)
    config_error = _c.bit(15)


class FilterGnssSource(_c.Enum):
    """Filter GNSS source (u8).

    Where the filter takes its GNSS position and velocity updates from.
    """

    ALL_INTERNAL = 0x01  # The internal GNSS receiver(s) (GX5-45: Internal GNSS; CV7: ALL_INT, all internal receivers).
    EXTERNAL = 0x02  # External GNSS messages supplied by the user (GX5-45: External GNSS Update 0x0D,0x16).
    INTERNAL_1 = 0x03  # Internal GNSS receiver 1 only. (devices: cv7_ins)
    INTERNAL_2 = 0x04  # Internal GNSS receiver 2 only. (devices: cv7_ins)


@_c.bitfield("u16")
class FilterHeadingSourceFlags(_c.Bitfield):
    """Heading update sources in use (u16 bitfield).

    Sources currently providing heading updates; 0 means none (heading updates disabled).
    """

    _MEMBERS = (
        ("magnetometer", "magnetometer", "MAGNETOMETER", 0, 1),
        ("gnss_velocity", "gnss_velocity", "GNSS_VELOCITY", 1, 1),
        ("external", "external", "EXTERNAL", 2, 1),
    )
    MAGNETOMETER = 0x0001  # bit 0: Internal magnetometer.
    GNSS_VELOCITY = 0x0002  # bit 1: GNSS velocity vector.
    EXTERNAL = 0x0004  # bit 2: External Heading Update messages (0x0D,0x17), with or without timestamp (0x0D,0x1F).

    magnetometer = _c.bit(0)
    gnss_velocity = _c.bit(1)
    external = _c.bit(2)


@_c.bitfield("u16")
class FilterHeadingUpdateValidFlags(_c.Bitfield):
    """Heading update state valid flags (u16 bitfield)."""

    _MEMBERS = (("updated_within_2s", "updated_within_2s", "UPDATED_WITHIN_2S", 0, 1),)
    # bit 0: The heading update source provided data within the last 2 seconds (0: no update for 2 seconds).
    UPDATED_WITHIN_2S = 0x0001

    updated_within_2s = _c.bit(0)


class FilterInitialConditionSource(_c.Enum):
    """Navigation filter initial condition source (u8)."""

    AUTO_POS_VEL_ATT = 0x00  # Automatic position, velocity and attitude.
    AUTO_POS_VEL_PITCH_ROLL = 0x01  # Automatic position, velocity, pitch and roll; heading as specified.
    AUTO_POS_VEL = 0x02  # Automatic position and velocity; attitude fully user-specified.
    MANUAL = 0x03  # User-specified position, velocity and attitude.


class FilterModeCv7(_c.Enum):
    """Filter mode (3DM-CV7) (u16).

    Mode the CV7 navigation filter has reached, reported as the filter state in Status (0x82,0x10);
    it depends on the initial conditions the filter was given.
    """

    INIT = 0x01  # Initialization: initial conditions incomplete or invalid, or waiting for user input.
    VERT_GYRO = 0x02  # Vertical gyro: valid pitch and roll, heading relative to the initial heading.
    AHRS = 0x03  # AHRS: as vertical gyro, with an absolute heading reference.
    FULL_NAV = 0x04  # Full navigation: valid position, velocity, pitch, roll and heading.


@_c.bitfield("u16")
class FilterOutputValidFlags(_c.Bitfield):
    """Filter output valid flags (u16 bitfield).

    Valid flags of a filter output field: 0x0000 the values are invalid, 0x0001 they are valid.
    """

    _MEMBERS = (("valid", "valid", "VALID", 0, 1),)
    VALID = 0x0001  # bit 0: The values of this field are valid.

    valid = _c.bit(0)


class FilterReferenceFrame(_c.Enum):
    """Reference frame of user-specified positions and velocities (u8)."""

    ECEF = 0x01  # WGS84 Earth-centered, Earth-fixed coordinates.
    LLH = 0x02  # WGS84 latitude, longitude and height above ellipsoid.


class FilterStateGx5(_c.Enum):
    """Filter state (3DM-GX5-45) (u16).

    Operating state of the GX5-45 estimation filter, reported in Filter Status (0x82,0x10).
    """

    STARTUP = 0x00  # Filter starting up.
    INIT = 0x01  # Initializing; the status flags tell what is still missing.
    RUN_SOLUTION_VALID = 0x02  # Running, the solution is valid.
    RUN_SOLUTION_ERROR = 0x03  # Running, the solution has an error; the status flags tell which.


@_c.bitfield("u16")
class FilterStatusFlagsCv7(_c.Bitfield):
    """Filter status flags (3DM-CV7) (u16 bitfield).

    CV7 (GQ7-family) filter status flags: the filter condition in bits 0-1 (1 stable, 2 converging,
    3 unstable/recovering), estimate warnings in bits 2-10 and solution error flags in bits 12-15.
    """

    _MEMBERS = (
        ("filter_condition", "filter_condition", "FILTER_CONDITION", 0, 2),
        ("roll_pitch_warning", "roll_pitch_warning", "ROLL_PITCH_WARNING", 2, 1),
        ("heading_warning", "heading_warning", "HEADING_WARNING", 3, 1),
        ("position_warning", "position_warning", "POSITION_WARNING", 4, 1),
        ("velocity_warning", "velocity_warning", "VELOCITY_WARNING", 5, 1),
        ("imu_bias_warning", "imu_bias_warning", "IMU_BIAS_WARNING", 6, 1),
        ("gnss_clk_warning", "gnss_clk_warning", "GNSS_CLK_WARNING", 7, 1),
        ("antenna_lever_arm_warning", "antenna_lever_arm_warning", "ANTENNA_LEVER_ARM_WARNING", 8, 1),
        ("mounting_transform_warning", "mounting_transform_warning", "MOUNTING_TRANSFORM_WARNING", 9, 1),
        ("time_sync_warning", "time_sync_warning", "TIME_SYNC_WARNING", 10, 1),
        ("reserved", "reserved", "RESERVED", 11, 1),
        ("solution_error", "solution_error", "SOLUTION_ERROR", 12, 4),
    )
    FILTER_CONDITION = 0x0003  # bits 0-1: Filter condition: 1 stable, 2 converging, 3 unstable/recovering.
    ROLL_PITCH_WARNING = 0x0004  # bit 2: Low confidence in roll/pitch (e.g. sensor not aligned with the vehicle frame).
    HEADING_WARNING = 0x0008  # bit 3: Low confidence in heading (heading source not valid).
    POSITION_WARNING = 0x0010  # bit 4: Low confidence in position.
    VELOCITY_WARNING = 0x0020  # bit 5: Low confidence in velocity.
    IMU_BIAS_WARNING = 0x0040  # bit 6: IMU bias estimate warning (gyro bias high).
    GNSS_CLK_WARNING = 0x0080  # bit 7: GNSS clock warning (affects the filter timestamp).
    ANTENNA_LEVER_ARM_WARNING = 0x0100  # bit 8: Antenna lever arm offsets are likely incorrect.
    MOUNTING_TRANSFORM_WARNING = 0x0200  # bit 9: Mounting transform is likely incorrect.
    # bit 10: No time synchronization (PPS) pulse detected, or external heading timestamp too old.
    TIME_SYNC_WARNING = 0x0400
    RESERVED = 0x0800  # bit 11: Not listed. (reserved)
    # bits 12-15: Filter computation error flags (NaN in the solution); if any is set, all filter outputs are invalid.
    SOLUTION_ERROR = 0xF000

    filter_condition = _c.bits(0, 2)
    roll_pitch_warning = _c.bit(2)
    heading_warning = _c.bit(3)
    position_warning = _c.bit(4)
    velocity_warning = _c.bit(5)
    imu_bias_warning = _c.bit(6)
    gnss_clk_warning = _c.bit(7)
    antenna_lever_arm_warning = _c.bit(8)
    mounting_transform_warning = _c.bit(9)
    time_sync_warning = _c.bit(10)
    reserved = _c.bit(11)
    solution_error = _c.bits(12, 4)


@_c.bitfield("u16")
class FilterStatusFlagsGx5(_c.Bitfield):
    """Filter status flags (3DM-GX5-45) (u16 bitfield).

    GX5-45 filter status flags. Bits 12 and 13 mean different things depending on the filter state:
    in the initialization state they say what is not initialized, while running they are estimate
    warnings.
    """

    _MEMBERS = (
        ("run_imu_unavailable", "run_imu_unavailable", "RUN_IMU_UNAVAILABLE", 0, 1),
        ("run_gps_unavailable", "run_gps_unavailable", "RUN_GPS_UNAVAILABLE", 1, 1),
        ("reserved", "reserved", "RESERVED", 2, 1),
        ("run_matrix_singularity", "run_matrix_singularity", "RUN_MATRIX_SINGULARITY", 3, 1),
        ("run_position_covariance_warning", "run_position_covariance_warning", "RUN_POSITION_COVARIANCE_WARNING", 4, 1),
        ("run_velocity_covariance_warning", "run_velocity_covariance_warning", "RUN_VELOCITY_COVARIANCE_WARNING", 5, 1),
        ("run_attitude_covariance_warning", "run_attitude_covariance_warning", "RUN_ATTITUDE_COVARIANCE_WARNING", 6, 1),
        ("run_nan_in_solution_warning", "run_nan_in_solution_warning", "RUN_NAN_IN_SOLUTION_WARNING", 7, 1),
        ("run_gyro_bias_est_high_warning", "run_gyro_bias_est_high_warning", "RUN_GYRO_BIAS_EST_HIGH_WARNING", 8, 1),
        ("run_accel_bias_est_high_warning", "run_accel_bias_est_high_warning", "RUN_ACCEL_BIAS_EST_HIGH_WARNING", 9, 1),
        (
            "run_gyro_scale_factor_est_high_warning",
            "run_gyro_scale_factor_est_high_warning",
            "RUN_GYRO_SCALE_FACTOR_EST_HIGH_WARNING",
            10,
            1,
        ),
        (
            "run_accel_scale_factor_est_high_warning",
            "run_accel_scale_factor_est_high_warning",
            "RUN_ACCEL_SCALE_FACTOR_EST_HIGH_WARNING",
            11,
            1,
        ),
        ("run_mag_bias_est_high_warning", "run_mag_bias_est_high_warning", "RUN_MAG_BIAS_EST_HIGH_WARNING", 12, 1),
        (
            "run_ant_offset_correction_est_high_warning",
            "run_ant_offset_correction_est_high_warning",
            "RUN_ANT_OFFSET_CORRECTION_EST_HIGH_WARNING",
            13,
            1,
        ),
        (
            "run_mag_hard_iron_est_high_warning",
            "run_mag_hard_iron_est_high_warning",
            "RUN_MAG_HARD_IRON_EST_HIGH_WARNING",
            14,
            1,
        ),
        (
            "run_mag_soft_iron_est_high_warning",
            "run_mag_soft_iron_est_high_warning",
            "RUN_MAG_SOFT_IRON_EST_HIGH_WARNING",
            15,
            1,
        ),
        ("init_no_attitude", "init_no_attitude", "INIT_NO_ATTITUDE", 12, 1),
        ("init_no_position_velocity", "init_no_position_velocity", "INIT_NO_POSITION_VELOCITY", 13, 1),
    )
    RUN_IMU_UNAVAILABLE = 0x0001  # bit 0: Running: IMU unavailable.
    RUN_GPS_UNAVAILABLE = 0x0002  # bit 1: Running: GNSS unavailable.
    RESERVED = 0x0004  # bit 2: Not listed (0x0004). (reserved)
    RUN_MATRIX_SINGULARITY = 0x0008  # bit 3: Running: matrix singularity in the calculation.
    # bit 4: Running: position covariance high (some axis beyond normal limits).
    RUN_POSITION_COVARIANCE_WARNING = 0x0010
    # bit 5: Running: velocity covariance high (some axis beyond normal limits).
    RUN_VELOCITY_COVARIANCE_WARNING = 0x0020
    # bit 6: Running: attitude covariance high (some axis beyond normal limits).
    RUN_ATTITUDE_COVARIANCE_WARNING = 0x0040
    RUN_NAN_IN_SOLUTION_WARNING = 0x0080  # bit 7: Running: NaN in the solution.
    RUN_GYRO_BIAS_EST_HIGH_WARNING = 0x0100  # bit 8: Running: gyro bias estimate high.
    RUN_ACCEL_BIAS_EST_HIGH_WARNING = 0x0200  # bit 9: Running: accel bias estimate high.
    RUN_GYRO_SCALE_FACTOR_EST_HIGH_WARNING = 0x0400  # bit 10: Running: gyro scale factor estimate high.
    RUN_ACCEL_SCALE_FACTOR_EST_HIGH_WARNING = 0x0800  # bit 11: Running: accel scale factor estimate high.
    RUN_MAG_BIAS_EST_HIGH_WARNING = 0x1000  # bit 12: Running: magnetometer bias estimate high.
    # bit 13: Running: GNSS antenna offset correction estimate high.
    RUN_ANT_OFFSET_CORRECTION_EST_HIGH_WARNING = 0x2000
    RUN_MAG_HARD_IRON_EST_HIGH_WARNING = 0x4000  # bit 14: Running: hard iron offset estimate high.
    RUN_MAG_SOFT_IRON_EST_HIGH_WARNING = 0x8000  # bit 15: Running: soft iron correction estimate high.
    # bit 12: Initialization: attitude not initialized (same bit as run_mag_bias_est_high_warning). (alias mask)
    INIT_NO_ATTITUDE = 0x1000
    # bit 13: Initialization: position and velocity not initialized (same bit as
    # run_ant_offset_correction_est_high_warning). (alias mask)
    INIT_NO_POSITION_VELOCITY = 0x2000

    run_imu_unavailable = _c.bit(0)
    run_gps_unavailable = _c.bit(1)
    reserved = _c.bit(2)
    run_matrix_singularity = _c.bit(3)
    run_position_covariance_warning = _c.bit(4)
    run_velocity_covariance_warning = _c.bit(5)
    run_attitude_covariance_warning = _c.bit(6)
    run_nan_in_solution_warning = _c.bit(7)
    run_gyro_bias_est_high_warning = _c.bit(8)
    run_accel_bias_est_high_warning = _c.bit(9)
    run_gyro_scale_factor_est_high_warning = _c.bit(10)
    run_accel_scale_factor_est_high_warning = _c.bit(11)
    run_mag_bias_est_high_warning = _c.bit(12)
    run_ant_offset_correction_est_high_warning = _c.bit(13)
    run_mag_hard_iron_est_high_warning = _c.bit(14)
    run_mag_soft_iron_est_high_warning = _c.bit(15)
    init_no_attitude = _c.bit(12)
    init_no_position_velocity = _c.bit(13)


class FunctionSelector(_c.Enum):
    """Function selector (u8).

    First parameter of settings commands; chooses what the command does. Only a read returns a
    response field (with the ack); parameters not needed for a function may be left out, or sent as
    placeholders.
    """

    WRITE = 0x01  # Apply new setting.
    READ = 0x02  # Read back the current setting (the only function that returns response data).
    SAVE = 0x03  # Save the current setting to non-volatile memory as the startup setting.
    LOAD = 0x04  # Load the saved startup setting from non-volatile memory.
    DEFAULT = 0x05  # Reset to the factory default.
    WRITE_NO_ACK = 0x06  # Apply new setting with no ACK/NACK reply (GX5-45 only). (devices: gx5_45)


@_c.bitfield("u8")
class GnssBeidouSignals(_c.Bitfield):
    """BeiDou signals enabled (u8 bitfield)."""

    _MEMBERS = (
        ("b1", "b1", "B1", 0, 1),
        ("b2", "b2", "B2", 1, 1),
        ("b2a", "b2a", "B2A", 2, 1),
    )
    B1 = 0x01  # bit 0: Enable B1.
    B2 = 0x02  # bit 1: Enable B2.
    B2A = 0x04  # bit 2: Enable B2A.

    b1 = _c.bit(0)
    b2 = _c.bit(1)
    b2a = _c.bit(2)


@_c.bitfield("u8")
class GnssGalileoSignals(_c.Bitfield):
    """Galileo signals enabled (u8 bitfield)."""

    _MEMBERS = (
        ("e1", "e1", "E1", 0, 1),
        ("e5b", "e5b", "E5B", 1, 1),
        ("e5a", "e5a", "E5A", 2, 1),
    )
    E1 = 0x01  # bit 0: Enable E1.
    E5B = 0x02  # bit 1: Enable E5B.
    E5A = 0x04  # bit 2: Enable E5A.

    e1 = _c.bit(0)
    e5b = _c.bit(1)
    e5a = _c.bit(2)


@_c.bitfield("u8")
class GnssGlonassSignals(_c.Bitfield):
    """GLONASS signals enabled (u8 bitfield)."""

    _MEMBERS = (
        ("l1of", "l1of", "L1OF", 0, 1),
        ("l2of", "l2of", "L2OF", 1, 1),
    )
    L1OF = 0x01  # bit 0: Enable L1OF.
    L2OF = 0x02  # bit 1: Enable L2OF.

    l1of = _c.bit(0)
    l2of = _c.bit(1)


@_c.bitfield("u8")
class GnssGpsSignals(_c.Bitfield):
    """GPS signals enabled (u8 bitfield)."""

    _MEMBERS = (
        ("l1ca", "l1ca", "L1CA", 0, 1),
        ("l2c", "l2c", "L2C", 1, 1),
        ("l5", "l5", "L5", 2, 1),
    )
    L1CA = 0x01  # bit 0: Enable L1 C/A.
    L2C = 0x02  # bit 1: Enable L2C.
    L5 = 0x04  # bit 2: Enable L5.

    l1ca = _c.bit(0)
    l2c = _c.bit(1)
    l5 = _c.bit(2)


class GpioEncoderBehavior(_c.Enum):
    """GPIO behavior for the ENCODER feature (u8)."""

    UNUSED = 0x00  # No behavior.
    ENCODER_A = 0x01  # ENCODER_A: quadrature input A; one pin at most (the latest command wins).
    ENCODER_B = 0x02  # ENCODER_B: quadrature input B; one pin at most (the latest command wins).


class GpioFeature(_c.Enum):
    """GPIO pin feature (u8).

    What a user GPIO pin is used for; selects how the behavior byte is read.
    """

    UNUSED = 0x00  # Pin not used; reading its state may or may not work.
    GPIO = 0x01  # General purpose input or output (direct control or monitoring of the pin state).
    PPS = 0x02  # Pulse-per-second input or output.
    ENCODER = 0x03  # Motor encoder / odometer input.
    TIMESTAMP = 0x04  # Precision timestamping of edges (for event triggers, 0x0C,0x2E).
    UART = 0x05  # UART data or control line.


class GpioIoBehavior(_c.Enum):
    """GPIO behavior for the GPIO feature (u8)."""

    UNUSED = 0x00  # No behavior.
    INPUT = 0x01  # GPIO_INPUT: the pin is an input that can be streamed or polled (the default).
    OUTPUT_LOW = 0x02  # GPIO_OUTPUT_LOW: output, initially low (restored at startup if saved).
    OUTPUT_HIGH = 0x03  # GPIO_OUTPUT_HIGH: output, initially high (restored at startup if saved).


@_c.bitfield("u8")
class GpioPinMode(_c.Bitfield):
    """GPIO pin electrical mode (u8 bitfield).

    Electrical configuration of a GPIO pin; which combinations a (feature, behavior) pair supports
    is listed in the User GPIO pin-mode table (line 1338).
    """

    _MEMBERS = (
        ("open_drain", "open_drain", "OPEN_DRAIN", 0, 1),
        ("pulldown", "pulldown", "PULLDOWN", 1, 1),
        ("pullup", "pullup", "PULLUP", 2, 1),
    )
    OPEN_DRAIN = 0x01  # bit 0: Open-drain output: LOW or floating instead of LOW or HIGH; usually with a pull-up.
    PULLDOWN = 0x02  # bit 1: Internal pull-down resistor enabled (not with pullup).
    PULLUP = 0x04  # bit 2: Internal pull-up resistor enabled (not with pulldown); may lower the allowed input voltage.

    open_drain = _c.bit(0)
    pulldown = _c.bit(1)
    pullup = _c.bit(2)


class GpioPpsBehavior(_c.Enum):
    """GPIO behavior for the PPS feature (u8)."""

    UNUSED = 0x00  # No behavior.
    INPUT = 0x01  # PPS_INPUT: receives the PPS signal; one pin at most; needs PPS source GPIO (0x0C,0x28).
    OUTPUT = 0x02  # PPS_OUTPUT: transmits the device's PPS signal.


class GpioTimestampBehavior(_c.Enum):
    """GPIO behavior for the TIMESTAMP feature (u8)."""

    UNUSED = 0x00  # No behavior.
    RISING = 0x01  # TIMESTAMP_RISING: rising edges are timestamped.
    FALLING = 0x02  # TIMESTAMP_FALLING: falling edges are timestamped.
    EITHER = 0x03  # TIMESTAMP_EITHER: both edges are timestamped.


class GpioUartBehavior(_c.Enum):
    """GPIO behavior for the UART feature (u8)."""

    UNUSED = 0x00  # No behavior.
    PORT2_TX = 0x21  # UART_PORT2_TX: UART port 2 transmit.
    PORT2_RX = 0x22  # UART_PORT2_RX: UART port 2 receive.
    PORT3_TX = 0x31  # UART_PORT3_TX: UART port 3 transmit.
    PORT3_RX = 0x32  # UART_PORT3_RX: UART port 3 receive.


class GpioUnusedBehavior(_c.Enum):
    """GPIO behavior for the UNUSED feature (u8)."""

    UNUSED = 0x00  # No behavior (0 unless otherwise specified).


class GpsTimeField(_c.Enum):
    """GPS time field selector (u8)."""

    WEEK_NUMBER = 0x01  # Week number (GX5-45: GPS Week Number).
    TIME_OF_WEEK = 0x02  # Time of week in seconds (GX5-45: GPS Seconds).


@_c.bitfield("u32")
class Gx5BitFlags(_c.Bitfield):
    """3DM-GX5-45 built-in test error flags (u32 bitfield)."""

    _MEMBERS = (
        ("processor_wdt_reset", "processor_wdt_reset", "PROCESSOR_WDT_RESET", 0, 1),
        ("imu_communication_fault", "imu_communication_fault", "IMU_COMMUNICATION_FAULT", 8, 1),
        ("magnetometer_fault", "magnetometer_fault", "MAGNETOMETER_FAULT", 9, 1),
        ("pressure_sensor_fault", "pressure_sensor_fault", "PRESSURE_SENSOR_FAULT", 10, 1),
        ("filter_solution_fault", "filter_solution_fault", "FILTER_SOLUTION_FAULT", 24, 1),
    )
    # bit 0: Processor board: watchdog reset (latching, cleared after first commanded BIT).
    PROCESSOR_WDT_RESET = 0x00000001
    IMU_COMMUNICATION_FAULT = 0x00000100  # bit 8: Sensor board: IMU communication fault.
    MAGNETOMETER_FAULT = 0x00000200  # bit 9: Sensor board: magnetometer fault (if applicable).
    PRESSURE_SENSOR_FAULT = 0x00000400  # bit 10: Sensor board: pressure sensor fault (if applicable).
    FILTER_SOLUTION_FAULT = 0x01000000  # bit 24: Kalman filter: solution fault.

    processor_wdt_reset = _c.bit(0)
    imu_communication_fault = _c.bit(8)
    magnetometer_fault = _c.bit(9)
    pressure_sensor_fault = _c.bit(10)
    filter_solution_fault = _c.bit(24)


class Gx5ConstellationId(_c.Enum):
    """GNSS constellation ID (GX5-45 constellation settings) (u8)."""

    GPS = 0x00  # GPS (G1-G32).
    SBAS = 0x01  # SBAS (S120-S158).
    GALILEO = 0x02  # Galileo (E1-E36).
    BEIDOU = 0x03  # BeiDou (B1-B37).
    QZSS = 0x05  # QZSS (Q1-Q5).
    GLONASS = 0x06  # GLONASS (R1-R32).


class Gx5PollOption(_c.Enum):
    """Poll option selector (u8).

    First byte of the GX5-45 poll commands; chooses whether the ACK/NACK is sent.
    """

    NORMAL = 0x00  # Normal ACK/NACK reply.
    SUPPRESS_ACK = 0x01  # No ACK/NACK reply; only the data packet is sent.


class Gx5StreamSelector(_c.Enum):
    """Continuous data stream selector (GX5-45) (u8).

    Which data stream the GX5-45 Enable/Disable Continuous Data Stream command controls.
    """

    IMU = 0x01  # IMU data stream (set 0x80).
    ESTIMATION_FILTER = 0x03  # Estimation filter data stream (set 0x82).


@_c.bitfield("u8")
class HeadingAlignmentMethods(_c.Bitfield):
    """Allowed automatic heading alignment methods (u8 bitfield)."""

    _MEMBERS = (
        ("dual_antenna", "dual_antenna", "DUAL_ANTENNA", 0, 1),
        ("kinematic", "kinematic", "KINEMATIC", 1, 1),
        ("magnetometer", "magnetometer", "MAGNETOMETER", 2, 1),
        ("external", "external", "EXTERNAL", 3, 1),
    )
    DUAL_ANTENNA = 0x01  # bit 0: Dual-antenna GNSS alignment.
    KINEMATIC = 0x02  # bit 1: GNSS kinematic alignment: the GNSS velocity (above 2 m/s) determines the initial heading.
    MAGNETOMETER = 0x04  # bit 2: The internal magnetometer determines the initial heading.
    EXTERNAL = 0x08  # bit 3: An external heading input determines the initial heading.

    dual_antenna = _c.bit(0)
    kinematic = _c.bit(1)
    magnetometer = _c.bit(2)
    external = _c.bit(3)


class HeadingUpdateSource(_c.Enum):
    """Heading update source (u8).

    Which aiding sources the filter uses for heading updates.
    """

    NONE = 0x00  # No heading aiding; heading still converges from GNSS under sufficient acceleration.
    MAGNETOMETER = 0x01  # Internal magnetometer.
    # Internal GNSS velocity vector (needs little side-slip and the vehicle X axis along the direction of travel).
    GNSS_VELOCITY = 0x02
    EXTERNAL = 0x03  # External heading messages (0x0D,0x17 / 0x0D,0x1F).
    GNSS_VELOCITY_AND_MAGNETOMETER = 0x04  # GNSS velocity vector and magnetometer.
    GNSS_VELOCITY_AND_EXTERNAL = 0x05  # GNSS velocity vector and external heading messages.
    MAGNETOMETER_AND_EXTERNAL = 0x06  # Magnetometer and external heading messages.
    GNSS_VELOCITY_MAGNETOMETER_AND_EXTERNAL = 0x07  # GNSS velocity vector, magnetometer and external heading messages.


class MagneticParamSource(_c.Enum):
    """Source of a magnetic field parameter (declination, inclination, magnitude) (u8).

    Where the filter takes a local magnetic field parameter from: nowhere (a fixed fallback), the
    internal World Magnetic Model, or a value the user supplies.
    """

    NONE = 0x01  # No source: no correction (declination, inclination) or a fixed 0.5 gauss (magnitude).
    WMM = 0x02  # Internal World Magnetic Model at the current position estimate (default).
    MANUAL = 0x03  # Value supplied by the user; the device does not validate it.


class OdometerMode(_c.Enum):
    """Odometer mode (u8)."""

    DISABLED = 0x00  # Encoder disabled.
    QUADRATURE = 0x02  # Quadrature encoder mode.


class PitchRollAidingSource(_c.Enum):
    """Pitch/roll aiding source (u8)."""

    NONE = 0x00  # No pitch/roll aiding (disabled).
    GRAVITY_VECTOR = 0x01  # Gravity vector aiding enabled.


class PpsSource(_c.Enum):
    """PPS source (u8)."""

    DISABLED = 0x00  # No PPS (the table says it is not valid as a command value; see note).
    RECEIVER_1 = 0x01  # PPS from GNSS receiver 1.
    RECEIVER_2 = 0x02  # PPS from GNSS receiver 2.
    GPIO = 0x03  # PPS applied to a GPIO pin (pin chosen with GPIO Configuration 0x0C,0x41).
    GENERATED = 0x04  # PPS generated from the system oscillator.


class ReferencePointSelector(_c.Enum):
    """Filter reference point (u8)."""

    VEH = 0x01  # The origin of the vehicle (the only value; the parameter is reserved and must be 1).


class RelativePositionSource(_c.Enum):
    """Reference location source for relative position outputs (u8)."""

    AUTO = 0x00  # Automatic: the RTK base station location.
    MANUAL = 0x01  # The reference coordinates given in the command.


@_c.bitfield("u16")
class SbasOptions(_c.Bitfield):
    """SBAS options (u16 bitfield)."""

    _MEMBERS = (
        ("enable_ranging", "enable_ranging", "ENABLE_RANGING", 0, 1),
        ("enable_corrections", "enable_corrections", "ENABLE_CORRECTIONS", 1, 1),
        ("apply_integrity", "apply_integrity", "APPLY_INTEGRITY", 2, 1),
    )
    ENABLE_RANGING = 0x0001  # bit 0: Use SBAS pseudoranges in the position solution (GX5-45 default on).
    ENABLE_CORRECTIONS = 0x0002  # bit 1: Use SBAS differential corrections (GX5-45 default on).
    APPLY_INTEGRITY = 0x0004  # bit 2: Use SBAS integrity information; only satellites with integrity data are used.

    enable_ranging = _c.bit(0)
    enable_corrections = _c.bit(1)
    apply_integrity = _c.bit(2)


class SensorRangeType(_c.Enum):
    """Sensor whose range is set or queried (u8)."""

    ALL = 0x00  # All sensors; only with save, load and default.
    ACCEL = 0x01  # Accelerometer; range in g.
    GYRO = 0x02  # Gyroscope; range in degrees/s.
    MAG = 0x03  # Magnetometer; range in Gauss.
    PRESS = 0x04  # Pressure sensor; range in hPa.


class SpartnConnectionType(_c.Enum):
    """SPARTN connection type (u8)."""

    NONE = 0x00  # No SPARTN connection.
    NETWORK = 0x01  # Corrections over a network connection (e.g. NTRIP).
    L_BAND = 0x02  # Corrections from an L-band correction receiver.


class SupportedEventsQuery(_c.Enum):
    """Supported events query (u8)."""

    TRIGGER_TYPES = 0x01  # Report the supported trigger types and how many of each.
    ACTION_TYPES = 0x02  # Report the supported action types and how many of each.


class SystemCommMode(_c.Enum):
    """Communication mode (u8)."""

    STANDARD = 0x01  # 3DM-GX5-45 MIP packets (default).
    SENSOR_DIRECT = 0x02  # Direct to the internal IMU: MIP IMU protocol.
    GNSS_DIRECT = 0x03  # Direct to the GNSS receiver: NMEA and UBX (GNSS models only).


@_c.bitfield("u8")
class TareAxes(_c.Bitfield):
    """Tare orientation axes (u8 bitfield).

    Axes to tare; 0 (no bit set) resets all axes.
    """

    _MEMBERS = (
        ("roll", "roll", "ROLL", 0, 1),
        ("pitch", "pitch", "PITCH", 1, 1),
        ("yaw", "yaw", "YAW", 2, 1),
    )
    ROLL = 0x01  # bit 0: Tare the roll axis.
    PITCH = 0x02  # bit 1: Tare the pitch axis.
    YAW = 0x04  # bit 2: Tare the yaw axis.

    roll = _c.bit(0)
    pitch = _c.bit(1)
    yaw = _c.bit(2)


class ThresholdType(_c.Enum):
    """Threshold comparison type (u8)."""

    WINDOW = 0x01  # Active if low_thres <= value <= high_thres (reversed thresholds invert it).
    INTERVAL = 0x02  # Active when (value % high_thres) <= low_thres: periodic triggering.


class TriggerGpioMode(_c.Enum):
    """GPIO trigger mode (u8)."""

    DISABLED = 0x00  # The pin has no effect and the trigger never activates.
    WHILE_HIGH = 0x01  # Active while the pin is high.
    WHILE_LOW = 0x02  # Active while the pin is low.
    EDGE = 0x04  # Use if the pin is configured for timestamping (0x0C,0x41).


@_c.bitfield("u8")
class TriggerStatus(_c.Bitfield):
    """Event trigger status (u8 bitfield)."""

    _MEMBERS = (
        ("active", "active", "ACTIVE", 0, 1),
        ("enabled", "enabled", "ENABLED", 1, 1),
        ("test", "test", "TEST", 2, 1),
    )
    ACTIVE = 0x01  # bit 0: The trigger is currently active (by its logic or in test mode).
    ENABLED = 0x02  # bit 1: The trigger is enabled.
    TEST = 0x04  # bit 2: The trigger is in test mode.

    active = _c.bit(0)
    enabled = _c.bit(1)
    test = _c.bit(2)


class TriggerType(_c.Enum):
    """Event trigger type (u8)."""

    NONE = 0x00  # No trigger selected. The state will always be inactive.
    GPIO = 0x01  # Trigger based on the state of a GPIO pin.
    THRESHOLD = 0x02  # Compare a data quantity against a high and low threshold.
    COMBINATION = 0x03  # Logical combination of two or more triggers.


class VehicleDynamicsMode(_c.Enum):
    """Vehicle dynamics mode (u8).

    Dynamics model the filter assumes for the vehicle (altitude and velocity limits).
    """

    PORTABLE = 0x01  # Low-acceleration applications (default); up to 12,000 m, 310 m/s horizontal, 50 m/s vertical.
    # Wheeled vehicles with low vertical acceleration; up to 6,000 m, 84 m/s horizontal, 15 m/s vertical.
    AUTOMOTIVE = 0x02
    AIRBORNE = 0x03  # Airborne up to 2 g; up to 50,000 m, 250 m/s horizontal, 100 m/s vertical.
    AIRBORNE_HIGH_G = 0x04  # Airborne up to 4 g; same altitude and velocity limits as airborne.


@_dc.dataclass
class ActionGpioParams(_c.Struct):
    """ActionGpioParams (struct, 2 bytes)."""

    pin: int = 0  # GPIO pin number.
    mode: ActionGpioMode = ActionGpioMode.DISABLED  # Behavior of the pin.

    _ATTRS = ("pin", "mode")
    _OPS = (_c.Run(_c.P("pin", _c.U8), _c.P("mode", _c.enum(ActionGpioMode, "u8"))),)
    _SIZE = 2


@_dc.dataclass
class MessageParams(_c.Struct):
    """MessageParams (struct, 4..16 bytes)."""

    desc_set: int = 0  # MIP data descriptor set.
    decimation: int = 0  # Decimation from the base rate; 0 emits one packet per activation.
    num_fields: int = 0  # Number of fields in the packet (at most 12).
    descriptors: _ty.List[int] = _dc.field(default_factory=list)  # Field descriptors. (count: num_fields)

    _ATTRS = ("desc_set", "decimation", "num_fields", "descriptors")
    _OPS = (
        _c.Run(_c.P("desc_set", _c.U8), _c.P("decimation", _c.U16), _c.P("num_fields", _c.U8)),
        _c.Counted("descriptors", _c.U8, count="num_fields", maximum=12),
    )


class ActionParams(_c.Union):
    """ActionParams (union selected by ActionType).

    The value of a union parameter is the selected member's struct, or None for a member without
    data.
    """

    _SELECTOR = ActionType
    _MEMBERS = {
        0x00: None,  # none
        0x01: ActionGpioParams,  # gpio
        0x02: MessageParams,  # message
    }


@_dc.dataclass
class ActionStatusEntry(_c.Struct):
    """ActionStatusEntry (struct, 2 bytes)."""

    action_type: ActionType = ActionType.NONE  # Configured action type.
    trigger_id: int = 0  # Associated trigger instance.

    _ATTRS = ("action_type", "trigger_id")
    _OPS = (_c.Run(_c.P("action_type", _c.enum(ActionType, "u8")), _c.P("trigger_id", _c.U8)),)
    _SIZE = 2


@_dc.dataclass
class AidingFrameEuler(_c.Struct):
    """Aiding frame rotation as Euler angles (struct, 12 bytes)."""

    # Roll, pitch, yaw of the frame relative to the vehicle frame, each within +/- pi. [rad]
    euler: _ty.List[float] = _dc.field(default_factory=lambda: [0.0] * 3)

    _ATTRS = ("euler",)
    _OPS = (_c.Run(_c.P("euler", _c.F32, 3)),)
    _SIZE = 12


@_dc.dataclass
class AidingFrameQuaternion(_c.Struct):
    """Aiding frame rotation as a quaternion (struct, 16 bytes)."""

    # Rotation of the frame relative to the vehicle frame, (w, x, y, z).
    quaternion: _ty.List[float] = _dc.field(default_factory=lambda: [0.0] * 4)

    _ATTRS = ("quaternion",)
    _OPS = (_c.Run(_c.P("quaternion", _c.F32, 4)),)
    _SIZE = 16


class AidingFrameRotation(_c.Union):
    """Aiding frame rotation (union selected by AidingFrameFormat).

    Rotation of an aiding frame, as Euler angles or as a quaternion depending on the format.

    The value of a union parameter is the selected member's struct, or None for a member without
    data.
    """

    _SELECTOR = AidingFrameFormat
    _MEMBERS = {
        0x01: AidingFrameEuler,  # euler
        0x02: AidingFrameQuaternion,  # quaternion
    }


@_dc.dataclass
class AidingTime(_c.Struct):
    """Aiding measurement timestamp (struct, 10 bytes).

    Timestamp carried first in every aiding measurement command.
    """

    timebase: AidingTimebase = AidingTimebase.INTERNAL_REFERENCE  # Clock of the timestamp.
    reserved: int = 0  # Reserved.
    nanoseconds: int = 0  # Time of the measurement in nanoseconds, in the timebase's clock. [ns]

    _ATTRS = ("timebase", "reserved", "nanoseconds")
    _OPS = (
        _c.Run(_c.P("timebase", _c.enum(AidingTimebase, "u8")), _c.P("reserved", _c.U8), _c.P("nanoseconds", _c.U64)),
    )
    _SIZE = 10


@_dc.dataclass
class CombinationParams(_c.Struct):
    """CombinationParams (struct, 6 bytes)."""

    logic_table: int = 0  # Last column of the truth table of the inputs.
    # Trigger IDs of the inputs; 0 for unused inputs.
    input_triggers: _ty.List[int] = _dc.field(default_factory=lambda: [0] * 4)

    _ATTRS = ("logic_table", "input_triggers")
    _OPS = (_c.Run(_c.P("logic_table", _c.U16), _c.P("input_triggers", _c.U8, 4)),)
    _SIZE = 6


@_dc.dataclass
class ConstellationSettings(_c.Struct):
    """GNSS constellation configuration entry (struct, 6 bytes)."""

    constellation_id: Gx5ConstellationId = Gx5ConstellationId.GPS  # Constellation.
    enable: int = 0  # 0x00 disable, 0x01 enable.
    # Tracking channels reserved for this constellation (0-32; all constellations together at most 32).
    reserved_channels: int = 0
    max_channels: int = 0  # Maximum tracking channels for this constellation (0-32, not below reserved_channels).
    option_flags: ConstellationOptions = ConstellationOptions(0)  # Constellation options.

    _ATTRS = ("constellation_id", "enable", "reserved_channels", "max_channels", "option_flags")
    _OPS = (
        _c.Run(
            _c.P("constellation_id", _c.enum(Gx5ConstellationId, "u8")),
            _c.P("enable", _c.U8),
            _c.P("reserved_channels", _c.U8),
            _c.P("max_channels", _c.U8),
            _c.P("option_flags", _c.flags(ConstellationOptions)),
        ),
    )
    _SIZE = 6


@_dc.dataclass
class DescriptorRate(_c.Struct):
    """Descriptor and rate decimation (struct, 3 bytes).

    One entry of a message format list.
    """

    descriptor: int = 0  # Data field descriptor.
    decimation: int = 0  # Rate decimation: the field is output at base rate / decimation.

    _ATTRS = ("descriptor", "decimation")
    _OPS = (_c.Run(_c.P("descriptor", _c.U8), _c.P("decimation", _c.U16)),)
    _SIZE = 3


@_dc.dataclass
class DeviceInfo(_c.Struct):
    """Device information (struct, 82 bytes).

    Firmware version and five 16-character identification strings, padded with spaces.
    """

    firmware_version: int = 0  # Firmware version number.
    model_name: bytes = b" " * 16  # Model name.
    model_number: bytes = b" " * 16  # Model number.
    serial_number: bytes = b" " * 16  # Serial number.
    lot_number: bytes = b" " * 16  # Lot number.
    device_options: bytes = b" " * 16  # Device options (e.g. sensor ranges).

    _ATTRS = ("firmware_version", "model_name", "model_number", "serial_number", "lot_number", "device_options")
    _OPS = (
        _c.Run(
            _c.P("firmware_version", _c.U16),
            _c.P("model_name", _c.string(16)),
            _c.P("model_number", _c.string(16)),
            _c.P("serial_number", _c.string(16)),
            _c.P("lot_number", _c.string(16)),
            _c.P("device_options", _c.string(16)),
        ),
    )
    _SIZE = 82


@_dc.dataclass
class GnssReceiverInfoEntry(_c.Struct):
    """GNSS receiver information (struct, 34 bytes).

    Identity of one physical GNSS receiver in the device.
    """

    receiver_id: int = 0  # Receiver id (1, 2, ...).
    mip_data_descriptor_set: int = 0  # MIP data descriptor set of this receiver's data.
    description: bytes = b"\x00" * 32  # ASCII, comma-delimited: module name/model, firmware version.

    _ATTRS = ("receiver_id", "mip_data_descriptor_set", "description")
    _OPS = (
        _c.Run(_c.P("receiver_id", _c.U8), _c.P("mip_data_descriptor_set", _c.U8), _c.P("description", _c.string(32))),
    )
    _SIZE = 34


@_dc.dataclass
class GpioBehaviorUnused(_c.Struct):
    """GpioBehaviorUnused (struct, 1 bytes)."""

    behavior: GpioUnusedBehavior = GpioUnusedBehavior.UNUSED  # Behavior value (0).

    _ATTRS = ("behavior",)
    _OPS = (_c.Run(_c.P("behavior", _c.enum(GpioUnusedBehavior, "u8"))),)
    _SIZE = 1


@_dc.dataclass
class GpioBehaviorIo(_c.Struct):
    """GpioBehaviorIo (struct, 1 bytes)."""

    behavior: GpioIoBehavior = GpioIoBehavior.UNUSED  # Input, or output with its initial state.

    _ATTRS = ("behavior",)
    _OPS = (_c.Run(_c.P("behavior", _c.enum(GpioIoBehavior, "u8"))),)
    _SIZE = 1


@_dc.dataclass
class GpioBehaviorPps(_c.Struct):
    """GpioBehaviorPps (struct, 1 bytes)."""

    behavior: GpioPpsBehavior = GpioPpsBehavior.UNUSED  # PPS input or output.

    _ATTRS = ("behavior",)
    _OPS = (_c.Run(_c.P("behavior", _c.enum(GpioPpsBehavior, "u8"))),)
    _SIZE = 1


@_dc.dataclass
class GpioBehaviorEncoder(_c.Struct):
    """GpioBehaviorEncoder (struct, 1 bytes)."""

    behavior: GpioEncoderBehavior = GpioEncoderBehavior.UNUSED  # Quadrature channel A or B.

    _ATTRS = ("behavior",)
    _OPS = (_c.Run(_c.P("behavior", _c.enum(GpioEncoderBehavior, "u8"))),)
    _SIZE = 1


@_dc.dataclass
class GpioBehaviorTimestamp(_c.Struct):
    """GpioBehaviorTimestamp (struct, 1 bytes)."""

    behavior: GpioTimestampBehavior = GpioTimestampBehavior.UNUSED  # Which edges are timestamped.

    _ATTRS = ("behavior",)
    _OPS = (_c.Run(_c.P("behavior", _c.enum(GpioTimestampBehavior, "u8"))),)
    _SIZE = 1


@_dc.dataclass
class GpioBehaviorUart(_c.Struct):
    """GpioBehaviorUart (struct, 1 bytes)."""

    behavior: GpioUartBehavior = GpioUartBehavior.UNUSED  # UART port and direction.

    _ATTRS = ("behavior",)
    _OPS = (_c.Run(_c.P("behavior", _c.enum(GpioUartBehavior, "u8"))),)
    _SIZE = 1


class GpioBehavior(_c.Union):
    """GPIO behavior, read according to the feature (union selected by GpioFeature).

    The behavior byte's meaning depends on the feature: the same number names a different behavior
    per feature (2 is GPIO_OUTPUT_LOW for GPIO, PPS_OUTPUT for PPS, ENCODER_B for ENCODER,
    TIMESTAMP_FALLING for TIMESTAMP). Every member is one u8.

    The value of a union parameter is the selected member's struct, or None for a member without
    data.
    """

    _SELECTOR = GpioFeature
    _MEMBERS = {
        0x00: GpioBehaviorUnused,  # unused: Feature UNUSED: behavior 0.
        0x01: GpioBehaviorIo,  # gpio: Feature GPIO: GPIO_INPUT / GPIO_OUTPUT_LOW / GPIO_OUTPUT_HIGH.
        0x02: GpioBehaviorPps,  # pps: Feature PPS: PPS_INPUT / PPS_OUTPUT.
        0x03: GpioBehaviorEncoder,  # encoder: Feature ENCODER: ENCODER_A / ENCODER_B.
        0x04: GpioBehaviorTimestamp,  # timestamp: Feature TIMESTAMP: TIMESTAMP_RISING / _FALLING / _EITHER.
        0x05: GpioBehaviorUart,  # uart: Feature UART: UART_PORT2_TX/RX, UART_PORT3_TX/RX.
    }


@_dc.dataclass
class Gx5BasicStatus(_c.Struct):
    """GX5-45 basic device status (struct, 10 bytes).

    Remainder of the basic device status reply after the model number and selector echoes.
    """

    status_flags: int = 0  # Status flags (reserved).
    system_state: int = 0  # System state (values not documented).
    system_timer: int = 0  # Time since start-up. [ms]

    _ATTRS = ("status_flags", "system_state", "system_timer")
    _OPS = (_c.Run(_c.P("status_flags", _c.U32), _c.P("system_state", _c.U16), _c.P("system_timer", _c.U32)),)
    _SIZE = 10


@_dc.dataclass
class Gx5DiagnosticStatus(_c.Struct):
    """GX5-45 diagnostic device status (struct, 70 bytes).

    Remainder of the diagnostic device status reply after the model number and selector echoes.
    """

    status_flags: int = 0  # Status flags (reserved).
    system_state: int = 0  # System state (values not documented).
    system_timer: int = 0  # Time since start-up. [ms]
    gnss_power_state: int = 0  # GNSS receiver power: 1 on, 0 off.
    pps_pulse_count: int = 0  # Number of 1PPS pulses received. [count]
    last_pps_time: int = 0  # System timer value at the last 1PPS pulse. [ms]
    imu_stream_enabled: int = 0  # IMU stream: 1 on, 0 off.
    gnss_stream_enabled: int = 0  # GNSS stream: 1 on, 0 off.
    filter_stream_enabled: int = 0  # Estimation filter stream: 1 on, 0 off.
    imu_dropped_packets: int = 0  # Outgoing IMU stream packets dropped. [count]
    gnss_dropped_packets: int = 0  # Outgoing GNSS stream packets dropped. [count]
    filter_dropped_packets: int = 0  # Outgoing estimation filter stream packets dropped. [count]
    com_bytes_written: int = 0  # Bytes written to the com port. [count]
    com_bytes_read: int = 0  # Bytes read from the com port. [count]
    com_write_overruns: int = 0  # Overruns when writing to the com port. [count]
    imu_parse_errors: int = 0  # IMU message parsing errors. [count]
    imu_messages_read: int = 0  # IMU messages read in total. [count]
    last_imu_message_time: int = 0  # System timer value at the last IMU message read. [ms]
    gnss_parse_errors: int = 0  # GNSS message parsing errors. [count]
    gnss_messages_read: int = 0  # GNSS messages read in total. [count]
    last_gnss_message_time: int = 0  # System timer value at the last GNSS message read. [ms]

    _ATTRS = (
        "status_flags",
        "system_state",
        "system_timer",
        "gnss_power_state",
        "pps_pulse_count",
        "last_pps_time",
        "imu_stream_enabled",
        "gnss_stream_enabled",
        "filter_stream_enabled",
        "imu_dropped_packets",
        "gnss_dropped_packets",
        "filter_dropped_packets",
        "com_bytes_written",
        "com_bytes_read",
        "com_write_overruns",
        "imu_parse_errors",
        "imu_messages_read",
        "last_imu_message_time",
        "gnss_parse_errors",
        "gnss_messages_read",
        "last_gnss_message_time",
    )
    _OPS = (
        _c.Run(
            _c.P("status_flags", _c.U32),
            _c.P("system_state", _c.U16),
            _c.P("system_timer", _c.U32),
            _c.P("gnss_power_state", _c.U8),
            _c.P("pps_pulse_count", _c.U32),
            _c.P("last_pps_time", _c.U32),
            _c.P("imu_stream_enabled", _c.U8),
            _c.P("gnss_stream_enabled", _c.U8),
            _c.P("filter_stream_enabled", _c.U8),
            _c.P("imu_dropped_packets", _c.U32),
            _c.P("gnss_dropped_packets", _c.U32),
            _c.P("filter_dropped_packets", _c.U32),
            _c.P("com_bytes_written", _c.U32),
            _c.P("com_bytes_read", _c.U32),
            _c.P("com_write_overruns", _c.U32),
            _c.P("imu_parse_errors", _c.U32),
            _c.P("imu_messages_read", _c.U32),
            _c.P("last_imu_message_time", _c.U32),
            _c.P("gnss_parse_errors", _c.U32),
            _c.P("gnss_messages_read", _c.U32),
            _c.P("last_gnss_message_time", _c.U32),
        ),
    )
    _SIZE = 70


class Gx5DeviceStatus(_c.Union):
    """GX5-45 device status structure (union selected by DeviceStatusSelector).

    The value of a union parameter is the selected member's struct, or None for a member without
    data.
    """

    _SELECTOR = DeviceStatusSelector
    _MEMBERS = {
        0x01: Gx5BasicStatus,  # basic
        0x02: Gx5DiagnosticStatus,  # diagnostic
    }


@_dc.dataclass
class Gx5PollDescriptor(_c.Struct):
    """Poll format entry (GX5-45) (struct, 3 bytes)."""

    descriptor: int = 0  # Data field descriptor to include in the polled packet.
    reserved: int = 0  # Reserved; 0 in every example.

    _ATTRS = ("descriptor", "reserved")
    _OPS = (_c.Run(_c.P("descriptor", _c.U8), _c.P("reserved", _c.U16)),)
    _SIZE = 3


@_dc.dataclass
class NmeaMessage(_c.Struct):
    """NMEA message format entry (struct, 5 bytes)."""

    # NMEA sentence type (GGA, GLL, GSV, RMC, VTG, HDT, ZDA, GST, PMSRA, PMSRR; codes not documented).
    message_id: int = 0
    talker_id: int = 0  # Talker ID (GN, GP, GA, GL; ignored for GSV and proprietary sentences; codes not documented).
    source_desc_set: int = 0  # Data descriptor set the sentence is built from (IMU, filter, GNSS 1 or 2).
    decimation: int = 0  # Decimation relative to the base rate of the source descriptor set.

    _ATTRS = ("message_id", "talker_id", "source_desc_set", "decimation")
    _OPS = (
        _c.Run(
            _c.P("message_id", _c.U8),
            _c.P("talker_id", _c.U8),
            _c.P("source_desc_set", _c.U8),
            _c.P("decimation", _c.U16),
        ),
    )
    _SIZE = 5


@_dc.dataclass
class SensorRangeEntry(_c.Struct):
    """Calibrated sensor range entry (struct, 5 bytes)."""

    setting: int = 0  # Value to use as setting in Sensor Range (0x0C,0x52).
    range: float = 0.0  # Range this setting gives; units depend on the sensor (see SensorRangeType).

    _ATTRS = ("setting", "range")
    _OPS = (_c.Run(_c.P("setting", _c.U8), _c.P("range", _c.F32)),)
    _SIZE = 5


@_dc.dataclass
class SupportedActionType(_c.Struct):
    """Supported action type (struct, 2 bytes)."""

    type: ActionType = ActionType.NONE  # Action type, as in Event Action Configuration (0x0C,0x2F).
    count: int = 0  # Maximum number of instances of this type.

    _ATTRS = ("type", "count")
    _OPS = (_c.Run(_c.P("type", _c.enum(ActionType, "u8")), _c.P("count", _c.U8)),)
    _SIZE = 2


@_dc.dataclass
class SupportedActions(_c.Struct):
    """Supported actions (query = action types) (struct, 2..252 bytes)."""

    max_instances: int = 0  # Number of action slots; instance numbers run 1..max_instances.
    num_entries: int = 0  # Number of supported action types.
    # Supported action types. (count: num_entries)
    entries: _ty.List[SupportedActionType] = _dc.field(default_factory=list)

    _ATTRS = ("max_instances", "num_entries", "entries")
    _OPS = (
        _c.Run(_c.P("max_instances", _c.U8), _c.P("num_entries", _c.U8)),
        _c.Counted("entries", SupportedActionType, count="num_entries", maximum=125),
    )


@_dc.dataclass
class SupportedTriggerType(_c.Struct):
    """Supported trigger type (struct, 2 bytes)."""

    type: TriggerType = TriggerType.NONE  # Trigger type, as in Event Trigger Configuration (0x0C,0x2E).
    count: int = 0  # Maximum number of instances of this type.

    _ATTRS = ("type", "count")
    _OPS = (_c.Run(_c.P("type", _c.enum(TriggerType, "u8")), _c.P("count", _c.U8)),)
    _SIZE = 2


@_dc.dataclass
class SupportedTriggers(_c.Struct):
    """Supported triggers (query = trigger types) (struct, 2..252 bytes)."""

    max_instances: int = 0  # Number of trigger slots; instance numbers run 1..max_instances.
    num_entries: int = 0  # Number of supported trigger types.
    # Supported trigger types. (count: num_entries)
    entries: _ty.List[SupportedTriggerType] = _dc.field(default_factory=list)

    _ATTRS = ("max_instances", "num_entries", "entries")
    _OPS = (
        _c.Run(_c.P("max_instances", _c.U8), _c.P("num_entries", _c.U8)),
        _c.Counted("entries", SupportedTriggerType, count="num_entries", maximum=125),
    )


class SupportedEventsInfo(_c.Union):
    """Supported event types, by query (union selected by SupportedEventsQuery).

    The value of a union parameter is the selected member's struct, or None for a member without
    data.
    """

    _SELECTOR = SupportedEventsQuery
    _MEMBERS = {
        0x01: SupportedTriggers,  # trigger_types
        0x02: SupportedActions,  # action_types
    }


@_dc.dataclass
class ThresholdParams(_c.Struct):
    """ThresholdParams (struct, 20 bytes)."""

    desc_set: int = 0  # Descriptor set of the target data quantity.
    field_desc: int = 0  # Field descriptor of the target data quantity.
    param_id: int = 0  # 1-based index of the target parameter within the field.
    type: ThresholdType = ThresholdType.WINDOW  # Type of comparison.
    low_thres: float = 0.0  # Low threshold (window) or active time (interval).
    high_thres: float = 0.0  # High threshold (window) or interval (interval).

    _ATTRS = ("desc_set", "field_desc", "param_id", "type", "low_thres", "high_thres")
    _OPS = (
        _c.Run(
            _c.P("desc_set", _c.U8),
            _c.P("field_desc", _c.U8),
            _c.P("param_id", _c.U8),
            _c.P("type", _c.enum(ThresholdType, "u8")),
            _c.P("low_thres", _c.F64),
            _c.P("high_thres", _c.F64),
        ),
    )
    _SIZE = 20


@_dc.dataclass
class TriggerGpioParams(_c.Struct):
    """TriggerGpioParams (struct, 2 bytes)."""

    pin: int = 0  # GPIO pin number.
    mode: TriggerGpioMode = TriggerGpioMode.DISABLED  # How the pin state affects the trigger.

    _ATTRS = ("pin", "mode")
    _OPS = (_c.Run(_c.P("pin", _c.U8), _c.P("mode", _c.enum(TriggerGpioMode, "u8"))),)
    _SIZE = 2


class TriggerParams(_c.Union):
    """TriggerParams (union selected by TriggerType).

    The value of a union parameter is the selected member's struct, or None for a member without
    data.
    """

    _SELECTOR = TriggerType
    _MEMBERS = {
        0x00: None,  # none
        0x01: TriggerGpioParams,  # gpio
        0x02: ThresholdParams,  # threshold
        0x03: CombinationParams,  # combination
    }


@_dc.dataclass
class TriggerStatusEntry(_c.Struct):
    """TriggerStatusEntry (struct, 2 bytes)."""

    type: TriggerType = TriggerType.NONE  # Configured trigger type.
    status: TriggerStatus = TriggerStatus(0)  # Trigger status.

    _ATTRS = ("type", "status")
    _OPS = (_c.Run(_c.P("type", _c.enum(TriggerType, "u8")), _c.P("status", _c.flags(TriggerStatus))),)
    _SIZE = 2
