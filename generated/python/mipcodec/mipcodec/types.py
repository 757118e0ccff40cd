"""Named types of the MicroStrain MIP: enums, bitfields, structs and unions.

Enums are IntEnums; decoding keeps values that are not members as plain ints. Bitfields are ints
whose members are properties (bool for one bit, int for several) with UPPER_CASE mask constants.
Structs are dataclasses; a union value is the selected member's struct (None: member without data).
"""

from __future__ import annotations

import dataclasses as _dc
import typing as _ty

from .codec import layout as _c


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


@_c.bitfield("u8")
class Cv7ContinuousBitGnss13(_c.Bitfield):
    """Continuous BIT byte 13: GNSS receivers (bits 104-111) (u8 bitfield)."""

    _MEMBERS = (
        ("reserved_104", "reserved_104", "RESERVED_104", 0, 1),
        ("receiver_1_fault", "receiver_1_fault", "RECEIVER_1_FAULT", 1, 1),
        ("reserved_106_107", "reserved_106_107", "RESERVED_106_107", 2, 2),
        ("receiver_1_no_solution", "receiver_1_no_solution", "RECEIVER_1_NO_SOLUTION", 4, 1),
        ("reserved_109", "reserved_109", "RESERVED_109", 5, 1),
        ("receiver_2_fault", "receiver_2_fault", "RECEIVER_2_FAULT", 6, 1),
        ("reserved_111", "reserved_111", "RESERVED_111", 7, 1),
    )
    RESERVED_104 = 0x01  # bit 0: Bit 104 (13.0): GNSS reserved. (reserved)
    RECEIVER_1_FAULT = 0x02  # bit 1: Bit 105 (13.1): no communication with internal GNSS receiver 1.
    RESERVED_106_107 = 0x0C  # bits 2-3: Bits 106-107 (13.2-13.3): GNSS reserved. (reserved)
    # bit 4: Bit 108 (13.4): internal receiver 1 has no valid solution (check antenna and sky view).
    RECEIVER_1_NO_SOLUTION = 0x10
    RESERVED_109 = 0x20  # bit 5: Bit 109 (13.5): GNSS reserved. (reserved)
    RECEIVER_2_FAULT = 0x40  # bit 6: Bit 110 (13.6): no communication with internal GNSS receiver 2.
    RESERVED_111 = 0x80  # bit 7: Bit 111 (13.7): GNSS reserved. (reserved)

    reserved_104 = _c.bit(0)
    receiver_1_fault = _c.bit(1)
    reserved_106_107 = _c.bits(2, 2)
    receiver_1_no_solution = _c.bit(4)
    reserved_109 = _c.bit(5)
    receiver_2_fault = _c.bit(6)
    reserved_111 = _c.bit(7)


@_c.bitfield("u8")
class Cv7ContinuousBitGnss14(_c.Bitfield):
    """Continuous BIT byte 14: GNSS receivers (bits 112-119) (u8 bitfield)."""

    _MEMBERS = (
        ("reserved_112", "reserved_112", "RESERVED_112", 0, 1),
        ("receiver_2_no_solution", "receiver_2_no_solution", "RECEIVER_2_NO_SOLUTION", 1, 1),
        ("reserved_114_119", "reserved_114_119", "RESERVED_114_119", 2, 6),
    )
    RESERVED_112 = 0x01  # bit 0: Bit 112 (14.0): GNSS reserved. (reserved)
    # bit 1: Bit 113 (14.1): internal receiver 2 has no valid solution (check antenna and sky view).
    RECEIVER_2_NO_SOLUTION = 0x02
    RESERVED_114_119 = 0xFC  # bits 2-7: Bits 114-119 (14.2-14.7): GNSS reserved. (reserved)

    reserved_112 = _c.bit(0)
    receiver_2_no_solution = _c.bit(1)
    reserved_114_119 = _c.bits(2, 6)


@_c.bitfield("u8")
class Cv7ContinuousBitImu4(_c.Bitfield):
    """Continuous BIT byte 4: IMU (bits 32-39) (u8 bitfield)."""

    _MEMBERS = (
        ("reserved_32", "reserved_32", "RESERVED_32", 0, 1),
        ("imu_communication_fault", "imu_communication_fault", "IMU_COMMUNICATION_FAULT", 1, 1),
        ("imu_timing_overrun", "imu_timing_overrun", "IMU_TIMING_OVERRUN", 2, 1),
        ("reserved_35", "reserved_35", "RESERVED_35", 3, 1),
        (
            "imu_calibration_error_accelerometer",
            "imu_calibration_error_accelerometer",
            "IMU_CALIBRATION_ERROR_ACCELEROMETER",
            4,
            1,
        ),
        ("imu_calibration_error_gyroscope", "imu_calibration_error_gyroscope", "IMU_CALIBRATION_ERROR_GYROSCOPE", 5, 1),
        (
            "imu_calibration_error_magnetometer",
            "imu_calibration_error_magnetometer",
            "IMU_CALIBRATION_ERROR_MAGNETOMETER",
            6,
            1,
        ),
        ("reserved_39", "reserved_39", "RESERVED_39", 7, 1),
    )
    RESERVED_32 = 0x01  # bit 0: Bit 32 (4.0): IMU reserved. (reserved)
    IMU_COMMUNICATION_FAULT = 0x02  # bit 1: Bit 33 (4.1): no communication with the IMU.
    IMU_TIMING_OVERRUN = 0x04  # bit 2: Bit 34 (4.2): IMU core processes take longer than their allotted time.
    RESERVED_35 = 0x08  # bit 3: Bit 35 (4.3): IMU reserved. (reserved)
    IMU_CALIBRATION_ERROR_ACCELEROMETER = 0x10  # bit 4: Bit 36 (4.4): problem with the accelerometer calibration.
    IMU_CALIBRATION_ERROR_GYROSCOPE = 0x20  # bit 5: Bit 37 (4.5): problem with the gyroscope calibration.
    IMU_CALIBRATION_ERROR_MAGNETOMETER = 0x40  # bit 6: Bit 38 (4.6): problem with the magnetometer calibration.
    RESERVED_39 = 0x80  # bit 7: Bit 39 (4.7): IMU calibration error, reserved. (reserved)

    reserved_32 = _c.bit(0)
    imu_communication_fault = _c.bit(1)
    imu_timing_overrun = _c.bit(2)
    reserved_35 = _c.bit(3)
    imu_calibration_error_accelerometer = _c.bit(4)
    imu_calibration_error_gyroscope = _c.bit(5)
    imu_calibration_error_magnetometer = _c.bit(6)
    reserved_39 = _c.bit(7)


@_c.bitfield("u8")
class Cv7ContinuousBitImu5(_c.Bitfield):
    """Continuous BIT byte 5: IMU accelerometer and gyroscope (bits 40-47) (u8 bitfield)."""

    _MEMBERS = (
        ("accelerometer_general_fault", "accelerometer_general_fault", "ACCELEROMETER_GENERAL_FAULT", 0, 1),
        ("accelerometer_overrange", "accelerometer_overrange", "ACCELEROMETER_OVERRANGE", 1, 1),
        ("accelerometer_self_test_fail", "accelerometer_self_test_fail", "ACCELEROMETER_SELF_TEST_FAIL", 2, 1),
        ("reserved_43", "reserved_43", "RESERVED_43", 3, 1),
        ("gyroscope_general_fault", "gyroscope_general_fault", "GYROSCOPE_GENERAL_FAULT", 4, 1),
        ("gyroscope_overrange", "gyroscope_overrange", "GYROSCOPE_OVERRANGE", 5, 1),
        ("gyroscope_self_test_fail", "gyroscope_self_test_fail", "GYROSCOPE_SELF_TEST_FAIL", 6, 1),
        ("reserved_47", "reserved_47", "RESERVED_47", 7, 1),
    )
    ACCELEROMETER_GENERAL_FAULT = 0x01  # bit 0: Bit 40 (5.0): the accelerometer will not initialize.
    ACCELEROMETER_OVERRANGE = 0x02  # bit 1: Bit 41 (5.1): one or more axes near or beyond the selected range.
    # bit 2: Bit 42 (5.2): accelerometer self-test failed (updated by the commanded BIT only).
    ACCELEROMETER_SELF_TEST_FAIL = 0x04
    RESERVED_43 = 0x08  # bit 3: Bit 43 (5.3): accelerometer reserved. (reserved)
    GYROSCOPE_GENERAL_FAULT = 0x10  # bit 4: Bit 44 (5.4): the gyroscope will not initialize.
    GYROSCOPE_OVERRANGE = 0x20  # bit 5: Bit 45 (5.5): one or more axes near or beyond the selected range.
    # bit 6: Bit 46 (5.6): gyroscope self-test failed (updated by the commanded BIT only).
    GYROSCOPE_SELF_TEST_FAIL = 0x40
    RESERVED_47 = 0x80  # bit 7: Bit 47 (5.7): gyroscope reserved. (reserved)

    accelerometer_general_fault = _c.bit(0)
    accelerometer_overrange = _c.bit(1)
    accelerometer_self_test_fail = _c.bit(2)
    reserved_43 = _c.bit(3)
    gyroscope_general_fault = _c.bit(4)
    gyroscope_overrange = _c.bit(5)
    gyroscope_self_test_fail = _c.bit(6)
    reserved_47 = _c.bit(7)


@_c.bitfield("u8")
class Cv7ContinuousBitImu6(_c.Bitfield):
    """Continuous BIT byte 6: IMU magnetometer and pressure sensor (bits 48-55) (u8 bitfield)."""

    _MEMBERS = (
        ("magnetometer_general_fault", "magnetometer_general_fault", "MAGNETOMETER_GENERAL_FAULT", 0, 1),
        ("magnetometer_overrange", "magnetometer_overrange", "MAGNETOMETER_OVERRANGE", 1, 1),
        ("magnetometer_self_test_fail", "magnetometer_self_test_fail", "MAGNETOMETER_SELF_TEST_FAIL", 2, 1),
        ("reserved_51", "reserved_51", "RESERVED_51", 3, 1),
        ("pressure_sensor_general_fault", "pressure_sensor_general_fault", "PRESSURE_SENSOR_GENERAL_FAULT", 4, 1),
        ("pressure_sensor_overrange", "pressure_sensor_overrange", "PRESSURE_SENSOR_OVERRANGE", 5, 1),
        ("pressure_sensor_self_test_fail", "pressure_sensor_self_test_fail", "PRESSURE_SENSOR_SELF_TEST_FAIL", 6, 1),
        ("reserved_55", "reserved_55", "RESERVED_55", 7, 1),
    )
    MAGNETOMETER_GENERAL_FAULT = 0x01  # bit 0: Bit 48 (6.0): the magnetometer will not initialize.
    MAGNETOMETER_OVERRANGE = 0x02  # bit 1: Bit 49 (6.1): one or more axes near or beyond the supported range.
    # bit 2: Bit 50 (6.2): magnetometer self-test failed (updated by the commanded BIT only).
    MAGNETOMETER_SELF_TEST_FAIL = 0x04
    RESERVED_51 = 0x08  # bit 3: Bit 51 (6.3): magnetometer reserved. (reserved)
    PRESSURE_SENSOR_GENERAL_FAULT = 0x10  # bit 4: Bit 52 (6.4): the pressure sensor will not initialize.
    PRESSURE_SENSOR_OVERRANGE = 0x20  # bit 5: Bit 53 (6.5): pressure outside the supported range.
    # bit 6: Bit 54 (6.6): pressure sensor self-test failed (updated by the commanded BIT only).
    PRESSURE_SENSOR_SELF_TEST_FAIL = 0x40
    RESERVED_55 = 0x80  # bit 7: Bit 55 (6.7): pressure sensor reserved. (reserved)

    magnetometer_general_fault = _c.bit(0)
    magnetometer_overrange = _c.bit(1)
    magnetometer_self_test_fail = _c.bit(2)
    reserved_51 = _c.bit(3)
    pressure_sensor_general_fault = _c.bit(4)
    pressure_sensor_overrange = _c.bit(5)
    pressure_sensor_self_test_fail = _c.bit(6)
    reserved_55 = _c.bit(7)


@_c.bitfield("u8")
class Cv7ContinuousBitImu7(_c.Bitfield):
    """Continuous BIT byte 7: IMU (bits 56-63) (u8 bitfield)."""

    _MEMBERS = (
        ("factory_bits_invalid", "factory_bits_invalid", "FACTORY_BITS_INVALID", 0, 1),
        ("reserved_57_63", "reserved_57_63", "RESERVED_57_63", 1, 7),
    )
    FACTORY_BITS_INVALID = 0x01  # bit 0: Bit 56 (7.0): the device has lost its configuration; contact support.
    RESERVED_57_63 = 0xFE  # bits 1-7: Bits 57-63 (7.1-7.7): reserved. (reserved)

    factory_bits_invalid = _c.bit(0)
    reserved_57_63 = _c.bits(1, 7)


@_c.bitfield("u8")
class Cv7ContinuousBitNav8(_c.Bitfield):
    """Continuous BIT byte 8: navigation filter (bits 64-71) (u8 bitfield)."""

    _MEMBERS = (
        ("reserved_64", "reserved_64", "RESERVED_64", 0, 1),
        ("reserved_65", "reserved_65", "RESERVED_65", 1, 1),
        ("filter_timing_overrun", "filter_timing_overrun", "FILTER_TIMING_OVERRUN", 2, 1),
        ("filter_timing_underrun", "filter_timing_underrun", "FILTER_TIMING_UNDERRUN", 3, 1),
        ("reserved_68_71", "reserved_68_71", "RESERVED_68_71", 4, 4),
    )
    RESERVED_64 = 0x01  # bit 0: Bit 64 (8.0): reserved. (reserved)
    RESERVED_65 = 0x02  # bit 1: Bit 65 (8.1): reserved. (reserved)
    FILTER_TIMING_OVERRUN = 0x04  # bit 2: Bit 66 (8.2): filter processes take longer than their allotted time.
    FILTER_TIMING_UNDERRUN = 0x08  # bit 3: Bit 67 (8.3): filter processes are being skipped.
    RESERVED_68_71 = 0xF0  # bits 4-7: Bits 68-71 (8.4-8.7): reserved (printed as GNSS reserved). (reserved)

    reserved_64 = _c.bit(0)
    reserved_65 = _c.bit(1)
    filter_timing_overrun = _c.bit(2)
    filter_timing_underrun = _c.bit(3)
    reserved_68_71 = _c.bits(4, 4)


@_c.bitfield("u8")
class Cv7ContinuousBitSystem0(_c.Bitfield):
    """Continuous BIT byte 0: system (bits 0-7) (u8 bitfield)."""

    _MEMBERS = (
        ("system_clock_failure", "system_clock_failure", "SYSTEM_CLOCK_FAILURE", 0, 1),
        ("power_fault", "power_fault", "POWER_FAULT", 1, 1),
        ("reserved_2_3", "reserved_2_3", "RESERVED_2_3", 2, 2),
        ("firmware_fault", "firmware_fault", "FIRMWARE_FAULT", 4, 1),
        ("timing_overload", "timing_overload", "TIMING_OVERLOAD", 5, 1),
        ("buffer_overrun", "buffer_overrun", "BUFFER_OVERRUN", 6, 1),
        ("reserved_7", "reserved_7", "RESERVED_7", 7, 1),
    )
    # bit 0: Bit 0 (0.0): the system clock is not operating properly; timing may be inaccurate.
    SYSTEM_CLOCK_FAILURE = 0x01
    POWER_FAULT = 0x02  # bit 1: Bit 1 (0.1): supply voltage out of the recommended range, or an internal power fault.
    RESERVED_2_3 = 0x0C  # bits 2-3: Bits 2-3 (0.2-0.3): reserved. (reserved)
    FIRMWARE_FAULT = 0x10  # bit 4: Bit 4 (0.4): firmware detected an unexpected or abnormal condition.
    # bit 5: Bit 5 (0.5): the system cannot keep up with the processing demand (e.g. too many descriptors).
    TIMING_OVERLOAD = 0x20
    # bit 6: Bit 6 (0.6): a data buffer filled up and data may have been lost (bandwidth exceeded).
    BUFFER_OVERRUN = 0x40
    RESERVED_7 = 0x80  # bit 7: Bit 7 (0.7): reserved. (reserved)

    system_clock_failure = _c.bit(0)
    power_fault = _c.bit(1)
    reserved_2_3 = _c.bits(2, 2)
    firmware_fault = _c.bit(4)
    timing_overload = _c.bit(5)
    buffer_overrun = _c.bit(6)
    reserved_7 = _c.bit(7)


@_c.bitfield("u8")
class Cv7ContinuousBitSystem2(_c.Bitfield):
    """Continuous BIT byte 2: system, IMU and filter processes (bits 16-23) (u8 bitfield)."""

    _MEMBERS = (
        ("imu_process_fault", "imu_process_fault", "IMU_PROCESS_FAULT", 0, 1),
        ("imu_data_process_time_exceeded", "imu_data_process_time_exceeded", "IMU_DATA_PROCESS_TIME_EXCEEDED", 1, 1),
        ("imu_data_rate_error", "imu_data_rate_error", "IMU_DATA_RATE_ERROR", 2, 1),
        ("imu_stall", "imu_stall", "IMU_STALL", 3, 1),
        ("filter_process_fault", "filter_process_fault", "FILTER_PROCESS_FAULT", 4, 4),
        ("filter_major_cycle_fault", "filter_major_cycle_fault", "FILTER_MAJOR_CYCLE_FAULT", 4, 1),
        ("filter_minor_cycle_fault", "filter_minor_cycle_fault", "FILTER_MINOR_CYCLE_FAULT", 5, 1),
        ("filter_data_rate_error", "filter_data_rate_error", "FILTER_DATA_RATE_ERROR", 6, 1),
        ("filter_process_stall", "filter_process_stall", "FILTER_PROCESS_STALL", 7, 1),
    )
    IMU_PROCESS_FAULT = 0x01  # bit 0: Bit 16 (2.0): the IMU subsystem is not running or did not start.
    IMU_DATA_PROCESS_TIME_EXCEEDED = 0x02  # bit 1: Bit 17 (2.1): IMU data processing took longer than allowed.
    IMU_DATA_RATE_ERROR = 0x04  # bit 2: Bit 18 (2.2): IMU data is not produced at the expected base rate.
    IMU_STALL = 0x08  # bit 3: Bit 19 (2.3): the IMU subsystem has stalled.
    # bits 4-7: Bits 20-23 (2.4-2.7): any filter process fault (the four bits below). (alias mask)
    FILTER_PROCESS_FAULT = 0xF0
    FILTER_MAJOR_CYCLE_FAULT = 0x10  # bit 4: Bit 20 (2.4): problem with the navigation filter major cycle.
    FILTER_MINOR_CYCLE_FAULT = 0x20  # bit 5: Bit 21 (2.5): problem with the navigation filter minor cycle.
    FILTER_DATA_RATE_ERROR = 0x40  # bit 6: Bit 22 (2.6): a navigation filter process is not running at its base rate.
    FILTER_PROCESS_STALL = 0x80  # bit 7: Bit 23 (2.7): a navigation filter process has stalled.

    imu_process_fault = _c.bit(0)
    imu_data_process_time_exceeded = _c.bit(1)
    imu_data_rate_error = _c.bit(2)
    imu_stall = _c.bit(3)
    filter_process_fault = _c.bits(4, 4)
    filter_major_cycle_fault = _c.bit(4)
    filter_minor_cycle_fault = _c.bit(5)
    filter_data_rate_error = _c.bit(6)
    filter_process_stall = _c.bit(7)


@_c.bitfield("u8")
class Cv7ContinuousBitSystem3(_c.Bitfield):
    """Continuous BIT byte 3: system, GNSS processes (bits 24-31) (u8 bitfield)."""

    _MEMBERS = (
        ("gnss_subsystem_fault", "gnss_subsystem_fault", "GNSS_SUBSYSTEM_FAULT", 0, 4),
        ("gnss_main_process_fault", "gnss_main_process_fault", "GNSS_MAIN_PROCESS_FAULT", 0, 1),
        ("gnss_receiver_1_stall", "gnss_receiver_1_stall", "GNSS_RECEIVER_1_STALL", 1, 1),
        ("gnss_receiver_2_stall", "gnss_receiver_2_stall", "GNSS_RECEIVER_2_STALL", 2, 1),
        ("reserved_27", "reserved_27", "RESERVED_27", 3, 1),
        ("reserved_28_31", "reserved_28_31", "RESERVED_28_31", 4, 4),
    )
    # bits 0-3: Bits 24-27 (3.0-3.3): any GNSS subsystem fault (the bits below). (alias mask)
    GNSS_SUBSYSTEM_FAULT = 0x0F
    GNSS_MAIN_PROCESS_FAULT = 0x01  # bit 0: Bit 24 (3.0): the master GNSS process has not run within its timeout.
    GNSS_RECEIVER_1_STALL = 0x02  # bit 1: Bit 25 (3.1): no data processed from internal receiver 1 within the timeout.
    GNSS_RECEIVER_2_STALL = 0x04  # bit 2: Bit 26 (3.2): no data processed from internal receiver 2 within the timeout.
    RESERVED_27 = 0x08  # bit 3: Bit 27 (3.3): reserved. (reserved)
    RESERVED_28_31 = 0xF0  # bits 4-7: Bits 28-31 (3.4-3.7): system reserved. (reserved)

    gnss_subsystem_fault = _c.bits(0, 4)
    gnss_main_process_fault = _c.bit(0)
    gnss_receiver_1_stall = _c.bit(1)
    gnss_receiver_2_stall = _c.bit(2)
    reserved_27 = _c.bit(3)
    reserved_28_31 = _c.bits(4, 4)


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


@_c.bitfield("u16")
class ExternalTimeDeltaValidFlags(_c.Bitfield):
    """External time delta valid flags (u16 bitfield)."""

    _MEMBERS = (
        ("dt_nanos", "dt_nanos", "DT_NANOS", 0, 1),
        ("reserved", "reserved", "RESERVED", 1, 15),
    )
    DT_NANOS = 0x0001  # bit 0: The delta is valid.
    RESERVED = 0xFFFE  # bits 1-15: Not listed. (reserved)

    dt_nanos = _c.bit(0)
    reserved = _c.bits(1, 15)


@_c.bitfield("u16")
class ExternalTimestampValidFlags(_c.Bitfield):
    """External timestamp valid flags (u16 bitfield)."""

    _MEMBERS = (
        ("nanoseconds", "nanoseconds", "NANOSECONDS", 0, 1),
        ("reserved", "reserved", "RESERVED", 1, 15),
    )
    NANOSECONDS = 0x0001  # bit 0: The nanoseconds value is valid (external clock synchronised via PPS).
    RESERVED = 0xFFFE  # bits 1-15: Not listed. (reserved)

    nanoseconds = _c.bit(0)
    reserved = _c.bits(1, 15)


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


class GnssAntennaPower(_c.Enum):
    """GNSS antenna power (u8).

    Whether the receiver powers the antenna.
    """

    OFF = 0x00  # Antenna power off.
    ON = 0x01  # Antenna power on.
    UNKNOWN = 0x02  # Power state unknown.


class GnssAntennaState(_c.Enum):
    """GNSS antenna state (u8).

    State of the GNSS antenna connection. There is no value 0.
    """

    INIT = 0x01  # Antenna initialising.
    SHORT = 0x02  # Antenna short circuit.
    OPEN = 0x03  # Antenna open circuit (not connected).
    GOOD = 0x04  # Antenna good.
    UNKNOWN = 0x05  # State unknown.


@_c.bitfield("u16")
class GnssBaseStationIndicators(_c.Bitfield):
    """Base station indicators (u16 bitfield).

    Indicator bits of the base station, as reported in RTCM message 1005/1006.
    """

    _MEMBERS = (
        ("gps", "gps", "GPS", 0, 1),
        ("glonass", "glonass", "GLONASS", 1, 1),
        ("galileo", "galileo", "GALILEO", 2, 1),
        ("beidou", "beidou", "BEIDOU", 3, 1),
        ("ref_station", "ref_station", "REF_STATION", 4, 1),
        ("single_receiver", "single_receiver", "SINGLE_RECEIVER", 5, 1),
        ("quarter_cycle_bit1", "quarter_cycle_bit1", "QUARTER_CYCLE_BIT1", 6, 1),
        ("quarter_cycle_bit2", "quarter_cycle_bit2", "QUARTER_CYCLE_BIT2", 7, 1),
        ("quarter_cycle_bits", "quarter_cycle_bits", "QUARTER_CYCLE_BITS", 6, 2),
        ("reserved", "reserved", "RESERVED", 8, 8),
    )
    GPS = 0x0001  # bit 0: GPS indicator.
    GLONASS = 0x0002  # bit 1: GLONASS indicator.
    GALILEO = 0x0004  # bit 2: Galileo indicator.
    BEIDOU = 0x0008  # bit 3: BeiDou indicator.
    REF_STATION = 0x0010  # bit 4: Reference station indicator.
    SINGLE_RECEIVER = 0x0020  # bit 5: Single receiver oscillator indicator.
    QUARTER_CYCLE_BIT1 = 0x0040  # bit 6: Quarter cycle indicator, first bit.
    QUARTER_CYCLE_BIT2 = 0x0080  # bit 7: Quarter cycle indicator, second bit.
    QUARTER_CYCLE_BITS = 0x00C0  # bits 6-7: Quarter cycle indicator (both bits). (alias mask)
    RESERVED = 0xFF00  # bits 8-15: Not named by the manual. (reserved)

    gps = _c.bit(0)
    glonass = _c.bit(1)
    galileo = _c.bit(2)
    beidou = _c.bit(3)
    ref_station = _c.bit(4)
    single_receiver = _c.bit(5)
    quarter_cycle_bit1 = _c.bit(6)
    quarter_cycle_bit2 = _c.bit(7)
    quarter_cycle_bits = _c.bits(6, 2)
    reserved = _c.bits(8, 8)


@_c.bitfield("u16")
class GnssBaseStationInfoValidFlags(_c.Bitfield):
    """Base station information valid flags (u16 bitfield).

    Which parameters of the base station information field are valid.
    """

    _MEMBERS = (
        ("tow", "tow", "TOW", 0, 1),
        ("week_number", "week_number", "WEEK_NUMBER", 1, 1),
        ("ecef_position", "ecef_position", "ECEF_POSITION", 2, 1),
        ("height", "height", "HEIGHT", 3, 1),
        ("station_id", "station_id", "STATION_ID", 4, 1),
        ("indicators", "indicators", "INDICATORS", 5, 1),
        ("flags", "flags", "FLAGS", 0, 6),
        ("reserved", "reserved", "RESERVED", 6, 10),
    )
    TOW = 0x0001  # bit 0: Time of week valid.
    WEEK_NUMBER = 0x0002  # bit 1: Week number valid.
    ECEF_POSITION = 0x0004  # bit 2: ECEF position valid.
    HEIGHT = 0x0008  # bit 3: Antenna height valid.
    STATION_ID = 0x0010  # bit 4: Station id valid.
    INDICATORS = 0x0020  # bit 5: Indicators valid.
    FLAGS = 0x003F  # bits 0-5: All flags. (alias mask)
    RESERVED = 0xFFC0  # bits 6-15: Not named by the manual. (reserved)

    tow = _c.bit(0)
    week_number = _c.bit(1)
    ecef_position = _c.bit(2)
    height = _c.bit(3)
    station_id = _c.bit(4)
    indicators = _c.bit(5)
    flags = _c.bits(0, 6)
    reserved = _c.bits(6, 10)


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


@_c.bitfield("u16")
class GnssClockInfo2ValidFlags(_c.Bitfield):
    """GNSS clock information 2 valid flags (u16 bitfield).

    Which receiver clock parameters are valid.
    """

    _MEMBERS = (
        ("bias", "bias", "BIAS", 0, 1),
        ("drift", "drift", "DRIFT", 1, 1),
        ("bias_accuracy", "bias_accuracy", "BIAS_ACCURACY", 2, 1),
        ("drift_accuracy", "drift_accuracy", "DRIFT_ACCURACY", 3, 1),
        ("flags", "flags", "FLAGS", 0, 4),
        ("reserved", "reserved", "RESERVED", 4, 12),
    )
    BIAS = 0x0001  # bit 0: Clock bias valid.
    DRIFT = 0x0002  # bit 1: Clock drift valid.
    BIAS_ACCURACY = 0x0004  # bit 2: Bias accuracy estimate valid.
    DRIFT_ACCURACY = 0x0008  # bit 3: Drift accuracy estimate valid.
    FLAGS = 0x000F  # bits 0-3: All flags. (alias mask)
    RESERVED = 0xFFF0  # bits 4-15: Not named by the manual. (reserved)

    bias = _c.bit(0)
    drift = _c.bit(1)
    bias_accuracy = _c.bit(2)
    drift_accuracy = _c.bit(3)
    flags = _c.bits(0, 4)
    reserved = _c.bits(4, 12)


@_c.bitfield("u16")
class GnssClockInfoValidFlags(_c.Bitfield):
    """GNSS clock information valid flags (u16 bitfield).

    Which clock parameters are valid.
    """

    _MEMBERS = (
        ("bias", "bias", "BIAS", 0, 1),
        ("drift", "drift", "DRIFT", 1, 1),
        ("accuracy_estimate", "accuracy_estimate", "ACCURACY_ESTIMATE", 2, 1),
        ("reserved", "reserved", "RESERVED", 3, 13),
    )
    BIAS = 0x0001  # bit 0: Clock bias valid.
    DRIFT = 0x0002  # bit 1: Clock drift valid.
    ACCURACY_ESTIMATE = 0x0004  # bit 2: Accuracy estimate valid.
    RESERVED = 0xFFF8  # bits 3-15: Not named by the manual. (reserved)

    bias = _c.bit(0)
    drift = _c.bit(1)
    accuracy_estimate = _c.bit(2)
    reserved = _c.bits(3, 13)


class GnssConstellationId(_c.Enum):
    """GNSS constellation (CV7 GNSS data) (u8)."""

    UNKNOWN = 0x00  # Constellation unknown or not given.
    GPS = 0x01  # GPS.
    GLONASS = 0x02  # GLONASS.
    GALILEO = 0x03  # Galileo.
    BEIDOU = 0x04  # BeiDou.
    SBAS = 0x05  # SBAS.


class GnssDgnssBaseStationStatus(_c.Enum):
    """DGNSS base station status (s16).

    Health of the DGNSS reference station as its UDRE (user differential range error) scale factor.
    """

    UDRE_SCALE_1_0 = 0x00  # UDRE scale factor 1.0.
    UDRE_SCALE_0_75 = 0x01  # UDRE scale factor 0.75.
    UDRE_SCALE_0_5 = 0x02  # UDRE scale factor 0.5.
    UDRE_SCALE_0_3 = 0x03  # UDRE scale factor 0.3.
    UDRE_SCALE_0_2 = 0x04  # UDRE scale factor 0.2.
    UDRE_SCALE_0_1 = 0x05  # UDRE scale factor 0.1.
    TRANSMISSION_NOT_MONITORED = 0x06  # Reference station transmission not monitored.
    STATION_NOT_WORKING = 0x07  # Reference station not working.


@_c.bitfield("u16")
class GnssDgnssChannelStatusValidFlags(_c.Bitfield):
    """DGNSS channel status valid flags (u16 bitfield).

    Which parameters of a DGNSS channel status entry are valid.
    """

    _MEMBERS = (
        ("sv_id", "sv_id", "SV_ID", 0, 1),
        ("age", "age", "AGE", 1, 1),
        ("pseudorange_correction", "pseudorange_correction", "PSEUDORANGE_CORRECTION", 2, 1),
        ("pseudorange_rate_correction", "pseudorange_rate_correction", "PSEUDORANGE_RATE_CORRECTION", 3, 1),
        ("reserved", "reserved", "RESERVED", 4, 12),
    )
    SV_ID = 0x0001  # bit 0: Space vehicle id valid.
    AGE = 0x0002  # bit 1: Correction age valid.
    PSEUDORANGE_CORRECTION = 0x0004  # bit 2: Pseudorange correction valid.
    PSEUDORANGE_RATE_CORRECTION = 0x0008  # bit 3: Pseudorange rate correction valid.
    RESERVED = 0xFFF0  # bits 4-15: Not named by the manual. (reserved)

    sv_id = _c.bit(0)
    age = _c.bit(1)
    pseudorange_correction = _c.bit(2)
    pseudorange_rate_correction = _c.bit(3)
    reserved = _c.bits(4, 12)


@_c.bitfield("u16")
class GnssDgnssInfoValidFlags(_c.Bitfield):
    """DGNSS information valid flags (u16 bitfield).

    Which parameters of the DGNSS information field are valid.
    """

    _MEMBERS = (
        ("latest_age", "latest_age", "LATEST_AGE", 0, 1),
        ("base_station_id", "base_station_id", "BASE_STATION_ID", 1, 1),
        ("base_station_status", "base_station_status", "BASE_STATION_STATUS", 2, 1),
        ("num_channels", "num_channels", "NUM_CHANNELS", 3, 1),
        ("reserved", "reserved", "RESERVED", 4, 12),
    )
    LATEST_AGE = 0x0001  # bit 0: Newest (latest) correction age valid.
    BASE_STATION_ID = 0x0002  # bit 1: Base station id valid.
    BASE_STATION_STATUS = 0x0004  # bit 2: Base station status valid.
    NUM_CHANNELS = 0x0008  # bit 3: Number of DGNSS channels valid.
    RESERVED = 0xFFF0  # bits 4-15: Not named by the manual. (reserved)

    latest_age = _c.bit(0)
    base_station_id = _c.bit(1)
    base_station_status = _c.bit(2)
    num_channels = _c.bit(3)
    reserved = _c.bits(4, 12)


@_c.bitfield("u16")
class GnssDopValidFlags(_c.Bitfield):
    """GNSS DOP valid flags (u16 bitfield).

    Which dilution-of-precision values are valid.
    """

    _MEMBERS = (
        ("gdop", "gdop", "GDOP", 0, 1),
        ("pdop", "pdop", "PDOP", 1, 1),
        ("hdop", "hdop", "HDOP", 2, 1),
        ("vdop", "vdop", "VDOP", 3, 1),
        ("tdop", "tdop", "TDOP", 4, 1),
        ("ndop", "ndop", "NDOP", 5, 1),
        ("edop", "edop", "EDOP", 6, 1),
        ("flags", "flags", "FLAGS", 0, 7),
        ("reserved", "reserved", "RESERVED", 7, 9),
    )
    GDOP = 0x0001  # bit 0: Geometric DOP valid.
    PDOP = 0x0002  # bit 1: Position DOP valid.
    HDOP = 0x0004  # bit 2: Horizontal DOP valid.
    VDOP = 0x0008  # bit 3: Vertical DOP valid.
    TDOP = 0x0010  # bit 4: Time DOP valid.
    NDOP = 0x0020  # bit 5: Northing DOP valid.
    EDOP = 0x0040  # bit 6: Easting DOP valid.
    FLAGS = 0x007F  # bits 0-6: All flags. (alias mask)
    RESERVED = 0xFF80  # bits 7-15: Not named by the manuals. (reserved)

    gdop = _c.bit(0)
    pdop = _c.bit(1)
    hdop = _c.bit(2)
    vdop = _c.bit(3)
    tdop = _c.bit(4)
    ndop = _c.bit(5)
    edop = _c.bit(6)
    flags = _c.bits(0, 7)
    reserved = _c.bits(7, 9)


@_c.bitfield("u16")
class GnssEcefPositionValidFlags(_c.Bitfield):
    """GNSS ECEF position valid flags (u16 bitfield).

    Which parameters of a GNSS ECEF position field are valid.
    """

    _MEMBERS = (
        ("position", "position", "POSITION", 0, 1),
        ("position_accuracy", "position_accuracy", "POSITION_ACCURACY", 1, 1),
        ("flags", "flags", "FLAGS", 0, 2),
        ("reserved", "reserved", "RESERVED", 2, 14),
    )
    POSITION = 0x0001  # bit 0: ECEF position valid.
    POSITION_ACCURACY = 0x0002  # bit 1: Position accuracy valid.
    FLAGS = 0x0003  # bits 0-1: All flags. (alias mask)
    RESERVED = 0xFFFC  # bits 2-15: Not named by the manuals. (reserved)

    position = _c.bit(0)
    position_accuracy = _c.bit(1)
    flags = _c.bits(0, 2)
    reserved = _c.bits(2, 14)


@_c.bitfield("u16")
class GnssEcefVelocityValidFlags(_c.Bitfield):
    """GNSS ECEF velocity valid flags (u16 bitfield).

    Which parameters of a GNSS ECEF velocity field are valid.
    """

    _MEMBERS = (
        ("velocity", "velocity", "VELOCITY", 0, 1),
        ("velocity_accuracy", "velocity_accuracy", "VELOCITY_ACCURACY", 1, 1),
        ("flags", "flags", "FLAGS", 0, 2),
        ("reserved", "reserved", "RESERVED", 2, 14),
    )
    VELOCITY = 0x0001  # bit 0: ECEF velocity valid.
    VELOCITY_ACCURACY = 0x0002  # bit 1: Velocity accuracy valid.
    FLAGS = 0x0003  # bits 0-1: All flags. (alias mask)
    RESERVED = 0xFFFC  # bits 2-15: Not named by the manuals. (reserved)

    velocity = _c.bit(0)
    velocity_accuracy = _c.bit(1)
    flags = _c.bits(0, 2)
    reserved = _c.bits(2, 14)


@_c.bitfield("u16")
class GnssEphemerisValidFlags(_c.Bitfield):
    """GPS/Galileo/BeiDou ephemeris valid flags (u16 bitfield)."""

    _MEMBERS = (
        ("ephemeris", "ephemeris", "EPHEMERIS", 0, 1),
        ("modern_data", "modern_data", "MODERN_DATA", 1, 1),
        ("isc_l5", "isc_l5", "ISC_L5", 2, 1),
        ("flags", "flags", "FLAGS", 0, 3),
        ("reserved", "reserved", "RESERVED", 3, 13),
    )
    EPHEMERIS = 0x0001  # bit 0: Ephemeris data valid.
    # bit 1: Modernized navigation data present (the manual gives only the name, not which parameters it covers).
    MODERN_DATA = 0x0002
    ISC_L5 = 0x0004  # bit 2: isc_l2c holds the L5 inter-signal correction instead of L2.
    FLAGS = 0x0007  # bits 0-2: All valid flags (the manual's 'flags 0-2' entry). (alias mask)
    RESERVED = 0xFFF8  # bits 3-15: Not named by the manual. (reserved)

    ephemeris = _c.bit(0)
    modern_data = _c.bit(1)
    isc_l5 = _c.bit(2)
    flags = _c.bits(0, 3)
    reserved = _c.bits(3, 13)


@_c.bitfield("u16")
class GnssFixFlags(_c.Bitfield):
    """GNSS fix flags (u16 bitfield).

    Corrections used in the position fix.
    """

    _MEMBERS = (
        ("sbas_used", "sbas_used", "SBAS_USED", 0, 1),
        ("dgnss_used", "dgnss_used", "DGNSS_USED", 1, 1),
        ("reserved", "reserved", "RESERVED", 2, 14),
    )
    SBAS_USED = 0x0001  # bit 0: SBAS corrections used.
    DGNSS_USED = 0x0002  # bit 1: Differential (DGNSS) corrections used.
    RESERVED = 0xFFFC  # bits 2-15: Not named by the manuals. (reserved)

    sbas_used = _c.bit(0)
    dgnss_used = _c.bit(1)
    reserved = _c.bits(2, 14)


@_c.bitfield("u16")
class GnssFixInfoValidFlags(_c.Bitfield):
    """GNSS fix information valid flags (u16 bitfield).

    Which parameters of a GNSS fix information field are valid.
    """

    _MEMBERS = (
        ("fix_type", "fix_type", "FIX_TYPE", 0, 1),
        ("num_sv", "num_sv", "NUM_SV", 1, 1),
        ("fix_flags", "fix_flags", "FIX_FLAGS", 2, 1),
        ("flags", "flags", "FLAGS", 0, 3),
        ("reserved", "reserved", "RESERVED", 3, 13),
    )
    FIX_TYPE = 0x0001  # bit 0: Fix type valid.
    NUM_SV = 0x0002  # bit 1: Number of satellites valid.
    FIX_FLAGS = 0x0004  # bit 2: Fix flags valid.
    FLAGS = 0x0007  # bits 0-2: All flags. (alias mask)
    RESERVED = 0xFFF8  # bits 3-15: Not named by the manuals. (reserved)

    fix_type = _c.bit(0)
    num_sv = _c.bit(1)
    fix_flags = _c.bit(2)
    flags = _c.bits(0, 3)
    reserved = _c.bits(3, 13)


class GnssFixTypeCv7(_c.Enum):
    """GNSS fix type (CV7) (u8).

    Type of position fix a CV7 GNSS receiver reports.
    """

    FIX_3D = 0x00  # 3D fix.
    FIX_2D = 0x01  # 2D fix.
    FIX_TIME_ONLY = 0x02  # Time only.
    FIX_NONE = 0x03  # No fix.
    FIX_INVALID = 0x04  # Invalid.
    FIX_RTK_FLOAT = 0x05  # RTK solution, float ambiguities.
    FIX_RTK_FIXED = 0x06  # RTK solution, fixed ambiguities.
    FIX_DIFFERENTIAL = 0x07  # Differential (DGNSS) solution.


class GnssFixTypeGx5(_c.Enum):
    """GNSS fix type (GX5-45) (u8).

    Type of position fix the GX5-45 GNSS receiver reports.
    """

    FIX_3D = 0x00  # 3D fix.
    FIX_2D = 0x01  # 2D fix.
    FIX_TIME_ONLY = 0x02  # Time only.
    FIX_NONE = 0x03  # No fix.
    FIX_INVALID = 0x04  # Invalid.


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


@_c.bitfield("u16")
class GnssGlonassEphemerisValidFlags(_c.Bitfield):
    """GLONASS ephemeris valid flags (u16 bitfield)."""

    _MEMBERS = (
        ("ephemeris", "ephemeris", "EPHEMERIS", 0, 1),
        ("flags", "flags", "FLAGS", 0, 1),
        ("reserved", "reserved", "RESERVED", 1, 15),
    )
    EPHEMERIS = 0x0001  # bit 0: Ephemeris data valid.
    FLAGS = 0x0001  # bit 0: All valid flags (the manual's 'flags 0' entry: the single bit 0). (alias mask)
    RESERVED = 0xFFFE  # bits 1-15: Not named by the manual. (reserved)

    ephemeris = _c.bit(0)
    flags = _c.bit(0)
    reserved = _c.bits(1, 15)


class GnssGlonassSatelliteType(_c.Enum):
    """GLONASS satellite type (u8)."""

    GLONASS = 0x00  # GLONASS satellite.
    GLONASS_M = 0x01  # GLONASS-M satellite.


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


@_c.bitfield("u16")
class GnssGpsTimeValidFlags(_c.Bitfield):
    """GNSS GPS time valid flags (u16 bitfield).

    Validity of a GNSS GPS time field.
    """

    _MEMBERS = (
        ("tow", "tow", "TOW", 0, 1),
        ("week_number", "week_number", "WEEK_NUMBER", 1, 1),
        ("flags", "flags", "FLAGS", 0, 2),
        ("reserved", "reserved", "RESERVED", 2, 14),
    )
    TOW = 0x0001  # bit 0: Time of week valid.
    WEEK_NUMBER = 0x0002  # bit 1: Week number valid.
    FLAGS = 0x0003  # bits 0-1: All flags. (alias mask)
    RESERVED = 0xFFFC  # bits 2-15: Not named by the manuals. (reserved)

    tow = _c.bit(0)
    week_number = _c.bit(1)
    flags = _c.bits(0, 2)
    reserved = _c.bits(2, 14)


@_c.bitfield("u16")
class GnssHardwareStatusValidFlags(_c.Bitfield):
    """GNSS hardware status valid flags (u16 bitfield).

    Which parameters of a GNSS hardware status field are valid.
    """

    _MEMBERS = (
        ("sensor_state", "sensor_state", "SENSOR_STATE", 0, 1),
        ("antenna_state", "antenna_state", "ANTENNA_STATE", 1, 1),
        ("antenna_power", "antenna_power", "ANTENNA_POWER", 2, 1),
        ("flags", "flags", "FLAGS", 0, 3),
        ("reserved", "reserved", "RESERVED", 3, 13),
    )
    SENSOR_STATE = 0x0001  # bit 0: Receiver (sensor) state valid.
    ANTENNA_STATE = 0x0002  # bit 1: Antenna state valid.
    ANTENNA_POWER = 0x0004  # bit 2: Antenna power valid.
    FLAGS = 0x0007  # bits 0-2: All flags. (alias mask)
    RESERVED = 0xFFF8  # bits 3-15: Not named by the manuals. (reserved)

    sensor_state = _c.bit(0)
    antenna_state = _c.bit(1)
    antenna_power = _c.bit(2)
    flags = _c.bits(0, 3)
    reserved = _c.bits(3, 13)


@_c.bitfield("u16")
class GnssLeapSecondsValidFlags(_c.Bitfield):
    """GPS leap seconds valid flags (u16 bitfield).

    Validity of the GPS leap seconds field.
    """

    _MEMBERS = (
        ("reserved_0", "reserved_0", "RESERVED_0", 0, 1),
        ("leap_seconds", "leap_seconds", "LEAP_SECONDS", 1, 1),
        ("reserved", "reserved", "RESERVED", 2, 14),
    )
    RESERVED_0 = 0x0001  # bit 0: Not named by the manual. (reserved)
    LEAP_SECONDS = 0x0002  # bit 1: Leap seconds valid.
    RESERVED = 0xFFFC  # bits 2-15: Not named by the manual. (reserved)

    reserved_0 = _c.bit(0)
    leap_seconds = _c.bit(1)
    reserved = _c.bits(2, 14)


@_c.bitfield("u16")
class GnssLlhPositionValidFlags(_c.Bitfield):
    """GNSS LLH position valid flags (u16 bitfield).

    Which parameters of a GNSS LLH position field are valid.
    """

    _MEMBERS = (
        ("lat_lon", "lat_lon", "LAT_LON", 0, 1),
        ("ellipsoid_height", "ellipsoid_height", "ELLIPSOID_HEIGHT", 1, 1),
        ("msl_height", "msl_height", "MSL_HEIGHT", 2, 1),
        ("horizontal_accuracy", "horizontal_accuracy", "HORIZONTAL_ACCURACY", 3, 1),
        ("vertical_accuracy", "vertical_accuracy", "VERTICAL_ACCURACY", 4, 1),
        ("flags", "flags", "FLAGS", 0, 5),
        ("reserved", "reserved", "RESERVED", 5, 11),
    )
    LAT_LON = 0x0001  # bit 0: Latitude and longitude valid.
    ELLIPSOID_HEIGHT = 0x0002  # bit 1: Height above ellipsoid valid.
    MSL_HEIGHT = 0x0004  # bit 2: Height above mean sea level valid.
    HORIZONTAL_ACCURACY = 0x0008  # bit 3: Horizontal accuracy valid.
    VERTICAL_ACCURACY = 0x0010  # bit 4: Vertical accuracy valid.
    FLAGS = 0x001F  # bits 0-4: All flags. (alias mask)
    RESERVED = 0xFFE0  # bits 5-15: Not named by the manuals. (reserved)

    lat_lon = _c.bit(0)
    ellipsoid_height = _c.bit(1)
    msl_height = _c.bit(2)
    horizontal_accuracy = _c.bit(3)
    vertical_accuracy = _c.bit(4)
    flags = _c.bits(0, 5)
    reserved = _c.bits(5, 11)


@_c.bitfield("u16")
class GnssNedVelocityValidFlags(_c.Bitfield):
    """GNSS NED velocity valid flags (u16 bitfield).

    Which parameters of a GNSS NED velocity field are valid.
    """

    _MEMBERS = (
        ("velocity", "velocity", "VELOCITY", 0, 1),
        ("speed_3d", "speed_3d", "SPEED_3D", 1, 1),
        ("ground_speed", "ground_speed", "GROUND_SPEED", 2, 1),
        ("heading", "heading", "HEADING", 3, 1),
        ("speed_accuracy", "speed_accuracy", "SPEED_ACCURACY", 4, 1),
        ("heading_accuracy", "heading_accuracy", "HEADING_ACCURACY", 5, 1),
        ("flags", "flags", "FLAGS", 0, 6),
        ("reserved", "reserved", "RESERVED", 6, 10),
    )
    VELOCITY = 0x0001  # bit 0: NED velocity vector valid.
    SPEED_3D = 0x0002  # bit 1: 3D speed valid.
    GROUND_SPEED = 0x0004  # bit 2: Ground speed valid.
    HEADING = 0x0008  # bit 3: Heading valid.
    SPEED_ACCURACY = 0x0010  # bit 4: Speed accuracy valid.
    HEADING_ACCURACY = 0x0020  # bit 5: Heading accuracy valid.
    FLAGS = 0x003F  # bits 0-5: All flags. (alias mask)
    RESERVED = 0xFFC0  # bits 6-15: Not named by the manuals. (reserved)

    velocity = _c.bit(0)
    speed_3d = _c.bit(1)
    ground_speed = _c.bit(2)
    heading = _c.bit(3)
    speed_accuracy = _c.bit(4)
    heading_accuracy = _c.bit(5)
    flags = _c.bits(0, 6)
    reserved = _c.bits(6, 10)


@_c.bitfield("u16")
class GnssRawValidFlags(_c.Bitfield):
    """Raw observation valid flags (u16 bitfield).

    Which parameters of a raw observation field hold valid data.
    """

    _MEMBERS = (
        ("tow", "tow", "TOW", 0, 1),
        ("week_number", "week_number", "WEEK_NUMBER", 1, 1),
        ("receiver_id", "receiver_id", "RECEIVER_ID", 2, 1),
        ("tracking_channel", "tracking_channel", "TRACKING_CHANNEL", 3, 1),
        ("gnss_id", "gnss_id", "GNSS_ID", 4, 1),
        ("satellite_id", "satellite_id", "SATELLITE_ID", 5, 1),
        ("signal_id", "signal_id", "SIGNAL_ID", 6, 1),
        ("signal_strength", "signal_strength", "SIGNAL_STRENGTH", 7, 1),
        ("quality", "quality", "QUALITY", 8, 1),
        ("pseudorange", "pseudorange", "PSEUDORANGE", 9, 1),
        ("carrier_phase", "carrier_phase", "CARRIER_PHASE", 10, 1),
        ("doppler", "doppler", "DOPPLER", 11, 1),
        ("range_uncertainty", "range_uncertainty", "RANGE_UNCERTAINTY", 12, 1),
        ("carrier_phase_uncertainty", "carrier_phase_uncertainty", "CARRIER_PHASE_UNCERTAINTY", 13, 1),
        ("doppler_uncertainty", "doppler_uncertainty", "DOPPLER_UNCERTAINTY", 14, 1),
        ("lock_time", "lock_time", "LOCK_TIME", 15, 1),
        ("flags", "flags", "FLAGS", 0, 16),
    )
    TOW = 0x0001  # bit 0: Time of week valid.
    WEEK_NUMBER = 0x0002  # bit 1: Week number valid.
    RECEIVER_ID = 0x0004  # bit 2: Receiver id valid.
    TRACKING_CHANNEL = 0x0008  # bit 3: Tracking channel valid.
    GNSS_ID = 0x0010  # bit 4: Constellation id valid.
    SATELLITE_ID = 0x0020  # bit 5: Satellite id valid.
    SIGNAL_ID = 0x0040  # bit 6: Signal id valid.
    SIGNAL_STRENGTH = 0x0080  # bit 7: Signal strength valid.
    QUALITY = 0x0100  # bit 8: Quality valid.
    PSEUDORANGE = 0x0200  # bit 9: Pseudorange valid.
    CARRIER_PHASE = 0x0400  # bit 10: Carrier phase valid.
    DOPPLER = 0x0800  # bit 11: Doppler valid.
    RANGE_UNCERTAINTY = 0x1000  # bit 12: Pseudorange uncertainty valid.
    CARRIER_PHASE_UNCERTAINTY = 0x2000  # bit 13: Carrier phase uncertainty valid.
    DOPPLER_UNCERTAINTY = 0x4000  # bit 14: Doppler uncertainty valid.
    LOCK_TIME = 0x8000  # bit 15: Lock time valid.
    FLAGS = 0xFFFF  # bits 0-15: All valid flags (the manual's 'flags 0-15' entry). (alias mask)

    tow = _c.bit(0)
    week_number = _c.bit(1)
    receiver_id = _c.bit(2)
    tracking_channel = _c.bit(3)
    gnss_id = _c.bit(4)
    satellite_id = _c.bit(5)
    signal_id = _c.bit(6)
    signal_strength = _c.bit(7)
    quality = _c.bit(8)
    pseudorange = _c.bit(9)
    carrier_phase = _c.bit(10)
    doppler = _c.bit(11)
    range_uncertainty = _c.bit(12)
    carrier_phase_uncertainty = _c.bit(13)
    doppler_uncertainty = _c.bit(14)
    lock_time = _c.bit(15)
    flags = _c.bits(0, 16)


class GnssReceiverState(_c.Enum):
    """GNSS receiver (sensor) state (u8).

    Power state of the GNSS receiver (GX5-45 "Sensor State", CV7 "Receiver State").
    """

    OFF = 0x00  # Receiver off.
    ON = 0x01  # Receiver on.
    UNKNOWN = 0x02  # State unknown.


@_c.bitfield("u16")
class GnssSatelliteStatusValidFlags(_c.Bitfield):
    """Satellite status valid flags (u16 bitfield).

    Which parameters of a satellite status field hold valid data.
    """

    _MEMBERS = (
        ("tow", "tow", "TOW", 0, 1),
        ("week_number", "week_number", "WEEK_NUMBER", 1, 1),
        ("gnss_id", "gnss_id", "GNSS_ID", 2, 1),
        ("satellite_id", "satellite_id", "SATELLITE_ID", 3, 1),
        ("elevation", "elevation", "ELEVATION", 4, 1),
        ("azimuth", "azimuth", "AZIMUTH", 5, 1),
        ("health", "health", "HEALTH", 6, 1),
        ("flags", "flags", "FLAGS", 0, 7),
        ("reserved", "reserved", "RESERVED", 7, 9),
    )
    TOW = 0x0001  # bit 0: Time of week valid.
    WEEK_NUMBER = 0x0002  # bit 1: Week number valid.
    GNSS_ID = 0x0004  # bit 2: Constellation id valid.
    SATELLITE_ID = 0x0008  # bit 3: Satellite id valid.
    ELEVATION = 0x0010  # bit 4: Elevation valid.
    AZIMUTH = 0x0020  # bit 5: Azimuth valid.
    HEALTH = 0x0040  # bit 6: Health valid.
    FLAGS = 0x007F  # bits 0-6: All valid flags (the manual's 'flags 0-6' entry). (alias mask)
    RESERVED = 0xFF80  # bits 7-15: Not named by the manual. (reserved)

    tow = _c.bit(0)
    week_number = _c.bit(1)
    gnss_id = _c.bit(2)
    satellite_id = _c.bit(3)
    elevation = _c.bit(4)
    azimuth = _c.bit(5)
    health = _c.bit(6)
    flags = _c.bits(0, 7)
    reserved = _c.bits(7, 9)


@_c.bitfield("u16")
class GnssSbasInfoValidFlags(_c.Bitfield):
    """SBAS information valid flags (u16 bitfield).

    Which parameters of the SBAS information field are valid.
    """

    _MEMBERS = (
        ("tow", "tow", "TOW", 0, 1),
        ("week_number", "week_number", "WEEK_NUMBER", 1, 1),
        ("sbas_system", "sbas_system", "SBAS_SYSTEM", 2, 1),
        ("sbas_id", "sbas_id", "SBAS_ID", 3, 1),
        ("count", "count", "COUNT", 4, 1),
        ("sbas_status", "sbas_status", "SBAS_STATUS", 5, 1),
        ("flags", "flags", "FLAGS", 0, 6),
        ("reserved", "reserved", "RESERVED", 6, 10),
    )
    TOW = 0x0001  # bit 0: Time of week valid.
    WEEK_NUMBER = 0x0002  # bit 1: Week number valid.
    SBAS_SYSTEM = 0x0004  # bit 2: SBAS system valid.
    SBAS_ID = 0x0008  # bit 3: SBAS satellite id valid.
    COUNT = 0x0010  # bit 4: Number of corrections valid.
    SBAS_STATUS = 0x0020  # bit 5: SBAS status valid.
    FLAGS = 0x003F  # bits 0-5: All flags. (alias mask)
    RESERVED = 0xFFC0  # bits 6-15: Not named by the manual. (reserved)

    tow = _c.bit(0)
    week_number = _c.bit(1)
    sbas_system = _c.bit(2)
    sbas_id = _c.bit(3)
    count = _c.bit(4)
    sbas_status = _c.bit(5)
    flags = _c.bits(0, 6)
    reserved = _c.bits(6, 10)


@_c.bitfield("u8")
class GnssSbasStatus(_c.Bitfield):
    """SBAS status (u8 bitfield).

    Status of the SBAS service.
    """

    _MEMBERS = (
        ("range_available", "range_available", "RANGE_AVAILABLE", 0, 1),
        ("corrections_available", "corrections_available", "CORRECTIONS_AVAILABLE", 1, 1),
        ("integrity_available", "integrity_available", "INTEGRITY_AVAILABLE", 2, 1),
        ("test_mode", "test_mode", "TEST_MODE", 3, 1),
        ("reserved", "reserved", "RESERVED", 4, 4),
    )
    RANGE_AVAILABLE = 0x01  # bit 0: SBAS ranging available.
    CORRECTIONS_AVAILABLE = 0x02  # bit 1: SBAS corrections available.
    INTEGRITY_AVAILABLE = 0x04  # bit 2: SBAS integrity information available.
    TEST_MODE = 0x08  # bit 3: SBAS is in test mode.
    RESERVED = 0xF0  # bits 4-7: Not named by the manual. (reserved)

    range_available = _c.bit(0)
    corrections_available = _c.bit(1)
    integrity_available = _c.bit(2)
    test_mode = _c.bit(3)
    reserved = _c.bits(4, 4)


class GnssSbasSystem(_c.Enum):
    """SBAS system (u8).

    Satellite-based augmentation system the receiver is using.
    """

    UNKNOWN = 0x00  # Unknown.
    WAAS = 0x01  # WAAS (North America).
    EGNOS = 0x02  # EGNOS (Europe).
    MSAS = 0x03  # MSAS (Japan).
    GAGAN = 0x04  # GAGAN (India).


class GnssSignalId(_c.Enum):
    """GNSS signal identifier (u8).

    The constellation, frequency band and code/channel component of one observation.
    """

    UNKNOWN = 0x00  # Unknown or unspecified signal.
    GPS_L1CA = 0x01  # GPS L1 C/A.
    GPS_L1P = 0x02  # GPS L1 P.
    GPS_L1Z = 0x03  # GPS L1 Z-tracking.
    GPS_L2CA = 0x04  # GPS L2 C/A.
    GPS_L2P = 0x05  # GPS L2 P.
    GPS_L2Z = 0x06  # GPS L2 Z-tracking.
    GPS_L2CL = 0x07  # GPS L2C long code (L).
    GPS_L2CM = 0x08  # GPS L2C medium code (M).
    GPS_L2CML = 0x09  # GPS L2C combined M+L.
    GPS_L5I = 0x0A  # GPS L5 I (data).
    GPS_L5Q = 0x0B  # GPS L5 Q (pilot).
    GPS_L5IQ = 0x0C  # GPS L5 combined I+Q.
    GPS_L1CD = 0x0D  # GPS L1C data (D).
    GPS_L1CP = 0x0E  # GPS L1C pilot (P).
    GPS_L1CDP = 0x0F  # GPS L1C combined D+P.
    GLONASS_G1CA = 0x20  # GLONASS G1 C/A.
    GLONASS_G1P = 0x21  # GLONASS G1 P.
    GLONASS_G2C = 0x22  # GLONASS G2 C/A.
    GLONASS_G2P = 0x23  # GLONASS G2 P.
    GALILEO_E1C = 0x40  # Galileo E1 C (pilot).
    GALILEO_E1A = 0x41  # Galileo E1 A (PRS).
    GALILEO_E1B = 0x42  # Galileo E1 B (data).
    GALILEO_E1BC = 0x43  # Galileo E1 combined B+C.
    GALILEO_E1ABC = 0x44  # Galileo E1 combined A+B+C.
    GALILEO_E6C = 0x45  # Galileo E6 C (pilot).
    GALILEO_E6A = 0x46  # Galileo E6 A (PRS).
    GALILEO_E6B = 0x47  # Galileo E6 B (data).
    GALILEO_E6BC = 0x48  # Galileo E6 combined B+C.
    GALILEO_E6ABC = 0x49  # Galileo E6 combined A+B+C.
    GALILEO_E5BI = 0x4A  # Galileo E5b I (data).
    GALILEO_E5BQ = 0x4B  # Galileo E5b Q (pilot).
    GALILEO_E5BIQ = 0x4C  # Galileo E5b combined I+Q.
    GALILEO_E5ABI = 0x4D  # Galileo E5 AltBOC (E5a+E5b) I (data).
    GALILEO_E5ABQ = 0x4E  # Galileo E5 AltBOC (E5a+E5b) Q (pilot).
    GALILEO_E5ABIQ = 0x4F  # Galileo E5 AltBOC (E5a+E5b) combined I+Q.
    GALILEO_E5AI = 0x50  # Galileo E5a I (data).
    GALILEO_E5AQ = 0x51  # Galileo E5a Q (pilot).
    GALILEO_E5AIQ = 0x52  # Galileo E5a combined I+Q.
    SBAS_L1CA = 0x60  # SBAS L1 C/A.
    SBAS_L5I = 0x61  # SBAS L5 I (data).
    SBAS_L5Q = 0x62  # SBAS L5 Q (pilot).
    SBAS_L5IQ = 0x63  # SBAS L5 combined I+Q.
    QZSS_L1CA = 0x80  # QZSS L1 C/A.
    QZSS_LEXS = 0x81  # QZSS LEX short code (S).
    QZSS_LEXL = 0x82  # QZSS LEX long code (L).
    QZSS_LEXSL = 0x83  # QZSS LEX combined S+L.
    QZSS_L2CM = 0x84  # QZSS L2C medium code (M).
    QZSS_L2CL = 0x85  # QZSS L2C long code (L).
    QZSS_L2CML = 0x86  # QZSS L2C combined M+L.
    QZSS_L5I = 0x87  # QZSS L5 I (data).
    QZSS_L5Q = 0x88  # QZSS L5 Q (pilot).
    QZSS_L5IQ = 0x89  # QZSS L5 combined I+Q.
    QZSS_L1CD = 0x8A  # QZSS L1C data (D).
    QZSS_L1CP = 0x8B  # QZSS L1C pilot (P).
    QZSS_L1CDP = 0x8C  # QZSS L1C combined D+P.
    BEIDOU_B1I = 0xA0  # BeiDou B1 I.
    BEIDOU_B1Q = 0xA1  # BeiDou B1 Q.
    BEIDOU_B1IQ = 0xA2  # BeiDou B1 combined I+Q.
    BEIDOU_B3I = 0xA3  # BeiDou B3 I.
    BEIDOU_B3Q = 0xA4  # BeiDou B3 Q.
    BEIDOU_B3IQ = 0xA5  # BeiDou B3 combined I+Q.
    BEIDOU_B2I = 0xA6  # BeiDou B2 I.
    BEIDOU_B2Q = 0xA7  # BeiDou B2 Q.
    BEIDOU_B2IQ = 0xA8  # BeiDou B2 combined I+Q.
    BEIDOU_B2A = 0xA9  # BeiDou B2a.


class GnssSignalQuality(_c.Enum):
    """GNSS raw observation signal quality (u8).

    Tracking state of the signal an observation comes from.
    """

    NONE = 0x00  # No signal.
    SEARCHING = 0x01  # Searching for the signal.
    ACQUIRED = 0x02  # Signal acquired.
    UNUSABLE = 0x03  # Signal detected but unusable.
    TIME_LOCKED = 0x04  # Time locked.
    FULLY_LOCKED = 0x05  # Fully locked.


@_c.bitfield("u16")
class GnssSvFlags(_c.Bitfield):
    """Space vehicle flags (u16 bitfield).

    Use and health of one space vehicle.
    """

    _MEMBERS = (
        ("used_for_navigation", "used_for_navigation", "USED_FOR_NAVIGATION", 0, 1),
        ("healthy", "healthy", "HEALTHY", 1, 1),
        ("reserved", "reserved", "RESERVED", 2, 14),
    )
    USED_FOR_NAVIGATION = 0x0001  # bit 0: The SV is used in the navigation solution.
    HEALTHY = 0x0002  # bit 1: The SV is healthy.
    RESERVED = 0xFFFC  # bits 2-15: Not named by the manual. (reserved)

    used_for_navigation = _c.bit(0)
    healthy = _c.bit(1)
    reserved = _c.bits(2, 14)


@_c.bitfield("u16")
class GnssSvInfoValidFlags(_c.Bitfield):
    """Space vehicle information valid flags (u16 bitfield).

    Which parameters of a space vehicle information entry are valid.
    """

    _MEMBERS = (
        ("channel", "channel", "CHANNEL", 0, 1),
        ("sv_id", "sv_id", "SV_ID", 1, 1),
        ("reserved_2", "reserved_2", "RESERVED_2", 2, 1),
        ("carrier_to_noise_ratio", "carrier_to_noise_ratio", "CARRIER_TO_NOISE_RATIO", 3, 1),
        ("azimuth", "azimuth", "AZIMUTH", 4, 1),
        ("elevation", "elevation", "ELEVATION", 5, 1),
        ("sv_flags", "sv_flags", "SV_FLAGS", 6, 1),
        ("reserved", "reserved", "RESERVED", 7, 9),
    )
    CHANNEL = 0x0001  # bit 0: Channel valid.
    SV_ID = 0x0002  # bit 1: Space vehicle id valid.
    RESERVED_2 = 0x0004  # bit 2: Not named by the manual (its list skips 0x0004). (reserved)
    CARRIER_TO_NOISE_RATIO = 0x0008  # bit 3: Carrier to noise ratio valid.
    AZIMUTH = 0x0010  # bit 4: Azimuth valid.
    ELEVATION = 0x0020  # bit 5: Elevation valid.
    SV_FLAGS = 0x0040  # bit 6: Space vehicle flags valid.
    RESERVED = 0xFF80  # bits 7-15: Not named by the manual. (reserved)

    channel = _c.bit(0)
    sv_id = _c.bit(1)
    reserved_2 = _c.bit(2)
    carrier_to_noise_ratio = _c.bit(3)
    azimuth = _c.bit(4)
    elevation = _c.bit(5)
    sv_flags = _c.bit(6)
    reserved = _c.bits(7, 9)


@_c.bitfield("u16")
class GnssUtcTimeValidFlagsCv7(_c.Bitfield):
    """GNSS UTC time valid flags (CV7) (u16 bitfield).

    Validity of a CV7 GNSS UTC time field.
    """

    _MEMBERS = (
        ("gnss_date_time", "gnss_date_time", "GNSS_DATE_TIME", 0, 1),
        ("leap_seconds_known", "leap_seconds_known", "LEAP_SECONDS_KNOWN", 1, 1),
        ("flags", "flags", "FLAGS", 0, 2),
        ("reserved", "reserved", "RESERVED", 2, 14),
    )
    GNSS_DATE_TIME = 0x0001  # bit 0: Date and time valid.
    LEAP_SECONDS_KNOWN = 0x0002  # bit 1: The GPS-UTC leap second offset is known, so the UTC time is exact.
    FLAGS = 0x0003  # bits 0-1: All flags. (alias mask)
    RESERVED = 0xFFFC  # bits 2-15: Not named by the manual. (reserved)

    gnss_date_time = _c.bit(0)
    leap_seconds_known = _c.bit(1)
    flags = _c.bits(0, 2)
    reserved = _c.bits(2, 14)


@_c.bitfield("u16")
class GnssUtcTimeValidFlagsGx5(_c.Bitfield):
    """GNSS UTC time valid flags (GX5-45) (u16 bitfield).

    Validity of the GX5-45 GNSS UTC time field.
    """

    _MEMBERS = (
        ("date_valid", "date_valid", "DATE_VALID", 0, 1),
        ("time_valid", "time_valid", "TIME_VALID", 1, 1),
        ("reserved", "reserved", "RESERVED", 2, 14),
    )
    DATE_VALID = 0x0001  # bit 0: Date valid.
    TIME_VALID = 0x0002  # bit 1: Time valid.
    RESERVED = 0xFFFC  # bits 2-15: Not named by the manual. (reserved)

    date_valid = _c.bit(0)
    time_valid = _c.bit(1)
    reserved = _c.bits(2, 14)


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


@_c.bitfield("u8")
class GpioPinStates(_c.Bitfield):
    """GPIO pin states (u8 bitfield)."""

    _MEMBERS = (
        ("pin_1", "pin_1", "PIN_1", 0, 1),
        ("pin_2", "pin_2", "PIN_2", 1, 1),
        ("pin_3", "pin_3", "PIN_3", 2, 1),
        ("pin_4", "pin_4", "PIN_4", 3, 1),
        ("reserved", "reserved", "RESERVED", 4, 4),
    )
    PIN_1 = 0x01  # bit 0: State of GPIO pin 1.
    PIN_2 = 0x02  # bit 1: State of GPIO pin 2.
    PIN_3 = 0x04  # bit 2: State of GPIO pin 3.
    PIN_4 = 0x08  # bit 3: State of GPIO pin 4.
    RESERVED = 0xF0  # bits 4-7: No such pins; read as 0. (reserved)

    pin_1 = _c.bit(0)
    pin_2 = _c.bit(1)
    pin_3 = _c.bit(2)
    pin_4 = _c.bit(3)
    reserved = _c.bits(4, 4)


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


@_c.bitfield("u16")
class OdometerDataValidFlags(_c.Bitfield):
    """Odometer data valid flags (u16 bitfield)."""

    _MEMBERS = (
        ("valid", "valid", "VALID", 0, 1),
        ("reserved", "reserved", "RESERVED", 1, 15),
    )
    VALID = 0x0001  # bit 0: Set when the odometer is configured (speed and uncertainty are valid).
    RESERVED = 0xFFFE  # bits 1-15: Not described. (reserved)

    valid = _c.bit(0)
    reserved = _c.bits(1, 15)


class OdometerMode(_c.Enum):
    """Odometer mode (u8)."""

    DISABLED = 0x00  # Encoder disabled.
    QUADRATURE = 0x02  # Quadrature encoder mode.


@_c.bitfield("u16")
class OverrangeStatusFlags(_c.Bitfield):
    """Sensor over-range status (u16 bitfield).

    One bit per sensor axis that is near or beyond its range.
    """

    _MEMBERS = (
        ("accel_x", "accel_x", "ACCEL_X", 0, 1),
        ("accel_y", "accel_y", "ACCEL_Y", 1, 1),
        ("accel_z", "accel_z", "ACCEL_Z", 2, 1),
        ("reserved_3", "reserved_3", "RESERVED_3", 3, 1),
        ("gyro_x", "gyro_x", "GYRO_X", 4, 1),
        ("gyro_y", "gyro_y", "GYRO_Y", 5, 1),
        ("gyro_z", "gyro_z", "GYRO_Z", 6, 1),
        ("reserved_7", "reserved_7", "RESERVED_7", 7, 1),
        ("mag_x", "mag_x", "MAG_X", 8, 1),
        ("mag_y", "mag_y", "MAG_Y", 9, 1),
        ("mag_z", "mag_z", "MAG_Z", 10, 1),
        ("reserved_11", "reserved_11", "RESERVED_11", 11, 1),
        ("press", "press", "PRESS", 12, 1),
        ("reserved_13_15", "reserved_13_15", "RESERVED_13_15", 13, 3),
    )
    ACCEL_X = 0x0001  # bit 0: Accelerometer X axis over range.
    ACCEL_Y = 0x0002  # bit 1: Accelerometer Y axis over range.
    ACCEL_Z = 0x0004  # bit 2: Accelerometer Z axis over range.
    RESERVED_3 = 0x0008  # bit 3: Not listed. (reserved)
    GYRO_X = 0x0010  # bit 4: Gyroscope X axis over range.
    GYRO_Y = 0x0020  # bit 5: Gyroscope Y axis over range.
    GYRO_Z = 0x0040  # bit 6: Gyroscope Z axis over range.
    RESERVED_7 = 0x0080  # bit 7: Not listed. (reserved)
    MAG_X = 0x0100  # bit 8: Magnetometer X axis over range.
    MAG_Y = 0x0200  # bit 9: Magnetometer Y axis over range.
    MAG_Z = 0x0400  # bit 10: Magnetometer Z axis over range.
    RESERVED_11 = 0x0800  # bit 11: Not listed. (reserved)
    PRESS = 0x1000  # bit 12: Pressure sensor over range.
    RESERVED_13_15 = 0xE000  # bits 13-15: Not listed. (reserved)

    accel_x = _c.bit(0)
    accel_y = _c.bit(1)
    accel_z = _c.bit(2)
    reserved_3 = _c.bit(3)
    gyro_x = _c.bit(4)
    gyro_y = _c.bit(5)
    gyro_z = _c.bit(6)
    reserved_7 = _c.bit(7)
    mag_x = _c.bit(8)
    mag_y = _c.bit(9)
    mag_z = _c.bit(10)
    reserved_11 = _c.bit(11)
    press = _c.bit(12)
    reserved_13_15 = _c.bits(13, 3)


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
class RtkCorrectionsEpochStatus(_c.Bitfield):
    """RTK corrections epoch status (u16 bitfield).

    Status of the corrections received during the epoch.
    """

    _MEMBERS = (
        ("antenna_location_received", "antenna_location_received", "ANTENNA_LOCATION_RECEIVED", 0, 1),
        ("antenna_description_received", "antenna_description_received", "ANTENNA_DESCRIPTION_RECEIVED", 1, 1),
        ("gps_received", "gps_received", "GPS_RECEIVED", 2, 1),
        ("glonass_received", "glonass_received", "GLONASS_RECEIVED", 3, 1),
        ("galileo_received", "galileo_received", "GALILEO_RECEIVED", 4, 1),
        ("beidou_received", "beidou_received", "BEIDOU_RECEIVED", 5, 1),
        ("using_gps_msm_messages", "using_gps_msm_messages", "USING_GPS_MSM_MESSAGES", 6, 1),
        ("using_glonass_msm_messages", "using_glonass_msm_messages", "USING_GLONASS_MSM_MESSAGES", 7, 1),
        ("dongle_status_read_failed", "dongle_status_read_failed", "DONGLE_STATUS_READ_FAILED", 8, 1),
        ("reserved", "reserved", "RESERVED", 9, 7),
    )
    ANTENNA_LOCATION_RECEIVED = 0x0001  # bit 0: Antenna location (station coordinates) received.
    ANTENNA_DESCRIPTION_RECEIVED = 0x0002  # bit 1: Antenna description received.
    GPS_RECEIVED = 0x0004  # bit 2: GPS corrections received.
    GLONASS_RECEIVED = 0x0008  # bit 3: GLONASS corrections received.
    GALILEO_RECEIVED = 0x0010  # bit 4: Galileo corrections received.
    BEIDOU_RECEIVED = 0x0020  # bit 5: BeiDou corrections received.
    USING_GPS_MSM_MESSAGES = 0x0040  # bit 6: GPS corrections come from MSM messages rather than RTCM 1001-1004.
    USING_GLONASS_MSM_MESSAGES = 0x0080  # bit 7: GLONASS corrections come from MSM messages rather than RTCM 1009-1012.
    DONGLE_STATUS_READ_FAILED = 0x0100  # bit 8: Reading the dongle status was attempted and failed.
    RESERVED = 0xFE00  # bits 9-15: Not named by the manual. (reserved)

    antenna_location_received = _c.bit(0)
    antenna_description_received = _c.bit(1)
    gps_received = _c.bit(2)
    glonass_received = _c.bit(3)
    galileo_received = _c.bit(4)
    beidou_received = _c.bit(5)
    using_gps_msm_messages = _c.bit(6)
    using_glonass_msm_messages = _c.bit(7)
    dongle_status_read_failed = _c.bit(8)
    reserved = _c.bits(9, 7)


@_c.bitfield("u16")
class RtkCorrectionsStatusValidFlags(_c.Bitfield):
    """RTK corrections status valid flags (u16 bitfield).

    Which parameters of the RTK corrections status field are valid.
    """

    _MEMBERS = (
        ("tow", "tow", "TOW", 0, 1),
        ("week_number", "week_number", "WEEK_NUMBER", 1, 1),
        ("epoch_status", "epoch_status", "EPOCH_STATUS", 2, 1),
        ("dongle_status", "dongle_status", "DONGLE_STATUS", 3, 1),
        ("gps_latency", "gps_latency", "GPS_LATENCY", 4, 1),
        ("glonass_latency", "glonass_latency", "GLONASS_LATENCY", 5, 1),
        ("galileo_latency", "galileo_latency", "GALILEO_LATENCY", 6, 1),
        ("beidou_latency", "beidou_latency", "BEIDOU_LATENCY", 7, 1),
        ("flags", "flags", "FLAGS", 0, 8),
        ("reserved", "reserved", "RESERVED", 8, 8),
    )
    TOW = 0x0001  # bit 0: Time of week valid.
    WEEK_NUMBER = 0x0002  # bit 1: Week number valid.
    EPOCH_STATUS = 0x0004  # bit 2: Epoch status valid.
    DONGLE_STATUS = 0x0008  # bit 3: Dongle status valid.
    GPS_LATENCY = 0x0010  # bit 4: GPS correction latency valid.
    GLONASS_LATENCY = 0x0020  # bit 5: GLONASS correction latency valid.
    GALILEO_LATENCY = 0x0040  # bit 6: Galileo correction latency valid.
    BEIDOU_LATENCY = 0x0080  # bit 7: BeiDou correction latency valid.
    FLAGS = 0x00FF  # bits 0-7: All flags. (alias mask)
    RESERVED = 0xFF00  # bits 8-15: Not named by the manual. (reserved)

    tow = _c.bit(0)
    week_number = _c.bit(1)
    epoch_status = _c.bit(2)
    dongle_status = _c.bit(3)
    gps_latency = _c.bit(4)
    glonass_latency = _c.bit(5)
    galileo_latency = _c.bit(6)
    beidou_latency = _c.bit(7)
    flags = _c.bits(0, 8)
    reserved = _c.bits(8, 8)


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


@_c.bitfield("u16")
class SensorGpsTimestampFlags(_c.Bitfield):
    """Sensor GPS timestamp flags (0x80,0x12) (u16 bitfield).

    Status of the GPS timestamp attached to sensor data. Bits 0-2 mean the same on both devices (the
    GX5-45 calls them PPS Beacon Good, GPS Time Refresh and GPS Time Initialized); bits 3 and 4
    exist only on the CV7.
    """

    _MEMBERS = (
        ("pps_valid", "pps_valid", "PPS_VALID", 0, 1),
        ("time_refresh", "time_refresh", "TIME_REFRESH", 1, 1),
        ("time_initialized", "time_initialized", "TIME_INITIALIZED", 2, 1),
        ("tow_valid", "tow_valid", "TOW_VALID", 3, 1),
        ("week_number_valid", "week_number_valid", "WEEK_NUMBER_VALID", 4, 1),
        ("reserved", "reserved", "RESERVED", 5, 11),
    )
    # bit 0: PPS signal present (GX5-45: PPS Beacon Good); when clear the internal clock stands in for the PPS.
    PPS_VALID = 0x0001
    # bit 1: Toggles each time the time is updated (GPS time, or the GPS Time Update command 0x01,0x72).
    TIME_REFRESH = 0x0002
    # bit 2: Set once the time has been set at least once (the first time refresh); stays set.
    TIME_INITIALIZED = 0x0004
    TOW_VALID = 0x0008  # bit 3: Time of week is valid. (devices: cv7_ins)
    WEEK_NUMBER_VALID = 0x0010  # bit 4: Week number is valid. (devices: cv7_ins)
    RESERVED = 0xFFE0  # bits 5-15: Not defined by either manual (GX5-45: bits 3-15). (reserved)

    pps_valid = _c.bit(0)
    time_refresh = _c.bit(1)
    time_initialized = _c.bit(2)
    tow_valid = _c.bit(3)
    week_number_valid = _c.bit(4)
    reserved = _c.bits(5, 11)


class SensorRangeType(_c.Enum):
    """Sensor whose range is set or queried (u8)."""

    ALL = 0x00  # All sensors; only with save, load and default.
    ACCEL = 0x01  # Accelerometer; range in g.
    GYRO = 0x02  # Gyroscope; range in degrees/s.
    MAG = 0x03  # Magnetometer; range in Gauss.
    PRESS = 0x04  # Pressure sensor; range in hPa.


@_c.bitfield("u16")
class SharedGpsTimestampValidFlags(_c.Bitfield):
    """Shared GPS timestamp valid flags (u16 bitfield)."""

    _MEMBERS = (
        ("tow", "tow", "TOW", 0, 1),
        ("week_number", "week_number", "WEEK_NUMBER", 1, 1),
        ("time_valid", "time_valid", "TIME_VALID", 0, 2),
        ("reserved", "reserved", "RESERVED", 2, 14),
    )
    TOW = 0x0001  # bit 0: The whole-second time of week has been set.
    WEEK_NUMBER = 0x0002  # bit 1: The week number has been set.
    TIME_VALID = 0x0003  # bits 0-1: Both time of week and week number have been set. (alias mask)
    RESERVED = 0xFFFC  # bits 2-15: Not listed. (reserved)

    tow = _c.bit(0)
    week_number = _c.bit(1)
    time_valid = _c.bits(0, 2)
    reserved = _c.bits(2, 14)


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
    mode: _ty.Union[ActionGpioMode, int] = ActionGpioMode.DISABLED  # Behavior of the pin.

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

    action_type: _ty.Union[ActionType, int] = ActionType.NONE  # Configured action type.
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

    timebase: _ty.Union[AidingTimebase, int] = AidingTimebase.INTERNAL_REFERENCE  # Clock of the timestamp.
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

    constellation_id: _ty.Union[Gx5ConstellationId, int] = Gx5ConstellationId.GPS  # Constellation.
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
class Cv7ContinuousBit(_c.Struct):
    """3DM-CV7 continuous built-in test result (128 bits) (struct, 16 bytes).

    The 16-byte continuous BIT bit map, one member per byte in wire order. Bit n of the map is bit
    (n mod 8) of byte n div 8 ("Relative Index (Byte.Bit)"). Bytes 0-3 are system bits, 4-7 IMU
    bits, 8-11 navigation filter bits and 12-15 GNSS bits. The bits latch until the message is sent;
    all unspecified bits are reserved and must be ignored.
    """

    system_byte_0: Cv7ContinuousBitSystem0 = Cv7ContinuousBitSystem0(0)  # Bits 0-7: system.
    reserved_byte_1: int = 0  # Bits 8-15: reserved (0.7-1.7).
    system_byte_2: Cv7ContinuousBitSystem2 = Cv7ContinuousBitSystem2(0)  # Bits 16-23: IMU and filter process faults.
    system_byte_3: Cv7ContinuousBitSystem3 = Cv7ContinuousBitSystem3(0)  # Bits 24-31: GNSS process faults.
    imu_byte_4: Cv7ContinuousBitImu4 = Cv7ContinuousBitImu4(0)  # Bits 32-39: IMU communication, timing, calibration.
    imu_byte_5: Cv7ContinuousBitImu5 = Cv7ContinuousBitImu5(0)  # Bits 40-47: accelerometer and gyroscope.
    imu_byte_6: Cv7ContinuousBitImu6 = Cv7ContinuousBitImu6(0)  # Bits 48-55: magnetometer and pressure sensor.
    imu_byte_7: Cv7ContinuousBitImu7 = Cv7ContinuousBitImu7(0)  # Bits 56-63: factory bits.
    nav_byte_8: Cv7ContinuousBitNav8 = Cv7ContinuousBitNav8(0)  # Bits 64-71: filter timing.
    reserved_byte_9: int = 0  # Bits 72-79: reserved.
    reserved_byte_10: int = 0  # Bits 80-87: reserved.
    reserved_byte_11: int = 0  # Bits 88-95: reserved.
    reserved_byte_12: int = 0  # Bits 96-103: reserved.
    gnss_byte_13: Cv7ContinuousBitGnss13 = Cv7ContinuousBitGnss13(0)  # Bits 104-111: GNSS receivers.
    gnss_byte_14: Cv7ContinuousBitGnss14 = Cv7ContinuousBitGnss14(0)  # Bits 112-119: GNSS receivers.
    reserved_byte_15: int = 0  # Bits 120-127: reserved.

    _ATTRS = (
        "system_byte_0",
        "reserved_byte_1",
        "system_byte_2",
        "system_byte_3",
        "imu_byte_4",
        "imu_byte_5",
        "imu_byte_6",
        "imu_byte_7",
        "nav_byte_8",
        "reserved_byte_9",
        "reserved_byte_10",
        "reserved_byte_11",
        "reserved_byte_12",
        "gnss_byte_13",
        "gnss_byte_14",
        "reserved_byte_15",
    )
    _OPS = (
        _c.Run(
            _c.P("system_byte_0", _c.flags(Cv7ContinuousBitSystem0)),
            _c.P("reserved_byte_1", _c.U8),
            _c.P("system_byte_2", _c.flags(Cv7ContinuousBitSystem2)),
            _c.P("system_byte_3", _c.flags(Cv7ContinuousBitSystem3)),
            _c.P("imu_byte_4", _c.flags(Cv7ContinuousBitImu4)),
            _c.P("imu_byte_5", _c.flags(Cv7ContinuousBitImu5)),
            _c.P("imu_byte_6", _c.flags(Cv7ContinuousBitImu6)),
            _c.P("imu_byte_7", _c.flags(Cv7ContinuousBitImu7)),
            _c.P("nav_byte_8", _c.flags(Cv7ContinuousBitNav8)),
            _c.P("reserved_byte_9", _c.U8),
            _c.P("reserved_byte_10", _c.U8),
            _c.P("reserved_byte_11", _c.U8),
            _c.P("reserved_byte_12", _c.U8),
            _c.P("gnss_byte_13", _c.flags(Cv7ContinuousBitGnss13)),
            _c.P("gnss_byte_14", _c.flags(Cv7ContinuousBitGnss14)),
            _c.P("reserved_byte_15", _c.U8),
        ),
    )
    _SIZE = 16


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

    behavior: _ty.Union[GpioUnusedBehavior, int] = GpioUnusedBehavior.UNUSED  # Behavior value (0).

    _ATTRS = ("behavior",)
    _OPS = (_c.Run(_c.P("behavior", _c.enum(GpioUnusedBehavior, "u8"))),)
    _SIZE = 1


@_dc.dataclass
class GpioBehaviorIo(_c.Struct):
    """GpioBehaviorIo (struct, 1 bytes)."""

    behavior: _ty.Union[GpioIoBehavior, int] = GpioIoBehavior.UNUSED  # Input, or output with its initial state.

    _ATTRS = ("behavior",)
    _OPS = (_c.Run(_c.P("behavior", _c.enum(GpioIoBehavior, "u8"))),)
    _SIZE = 1


@_dc.dataclass
class GpioBehaviorPps(_c.Struct):
    """GpioBehaviorPps (struct, 1 bytes)."""

    behavior: _ty.Union[GpioPpsBehavior, int] = GpioPpsBehavior.UNUSED  # PPS input or output.

    _ATTRS = ("behavior",)
    _OPS = (_c.Run(_c.P("behavior", _c.enum(GpioPpsBehavior, "u8"))),)
    _SIZE = 1


@_dc.dataclass
class GpioBehaviorEncoder(_c.Struct):
    """GpioBehaviorEncoder (struct, 1 bytes)."""

    behavior: _ty.Union[GpioEncoderBehavior, int] = GpioEncoderBehavior.UNUSED  # Quadrature channel A or B.

    _ATTRS = ("behavior",)
    _OPS = (_c.Run(_c.P("behavior", _c.enum(GpioEncoderBehavior, "u8"))),)
    _SIZE = 1


@_dc.dataclass
class GpioBehaviorTimestamp(_c.Struct):
    """GpioBehaviorTimestamp (struct, 1 bytes)."""

    behavior: _ty.Union[GpioTimestampBehavior, int] = GpioTimestampBehavior.UNUSED  # Which edges are timestamped.

    _ATTRS = ("behavior",)
    _OPS = (_c.Run(_c.P("behavior", _c.enum(GpioTimestampBehavior, "u8"))),)
    _SIZE = 1


@_dc.dataclass
class GpioBehaviorUart(_c.Struct):
    """GpioBehaviorUart (struct, 1 bytes)."""

    behavior: _ty.Union[GpioUartBehavior, int] = GpioUartBehavior.UNUSED  # UART port and direction.

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

    type: _ty.Union[ActionType, int] = ActionType.NONE  # Action type, as in Event Action Configuration (0x0C,0x2F).
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

    type: _ty.Union[TriggerType, int] = TriggerType.NONE  # Trigger type, as in Event Trigger Configuration (0x0C,0x2E).
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
    type: _ty.Union[ThresholdType, int] = ThresholdType.WINDOW  # Type of comparison.
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
    mode: _ty.Union[TriggerGpioMode, int] = TriggerGpioMode.DISABLED  # How the pin state affects the trigger.

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

    type: _ty.Union[TriggerType, int] = TriggerType.NONE  # Configured trigger type.
    status: TriggerStatus = TriggerStatus(0)  # Trigger status.

    _ATTRS = ("type", "status")
    _OPS = (_c.Run(_c.P("type", _c.enum(TriggerType, "u8")), _c.P("status", _c.flags(TriggerStatus))),)
    _SIZE = 2
