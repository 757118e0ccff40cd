/* Sensor (IMU) Data Set (descriptor set 0x80): one struct per field layout, with its
 * encoder and decoder. Generated from the spec: do not edit. */
#ifndef MIPC_SETS_SENSOR_H
#define MIPC_SETS_SENSOR_H

#include "mipcodec/types.h"
#include "mipcodec/field_iter.h"
#include "mipcodec/sets/shared.h"

#ifdef __cplusplus
extern "C" {
#endif

#define MIPC_SENSOR_SET 0x80

/* ---- scaled_accel (data): Scaled accelerometer vector */
#define MIPC_SENSOR_SCALED_ACCEL_DESCRIPTOR 0x04

/** Scaled accelerometer vector. Sensed acceleration, temperature compensated, in g (1 g = 9.80665 m/s^2), X,
 * Y, Z in the sensor (GX5-45) or vehicle (CV7) frame. */
typedef struct {
    float scaled_accel[3]; /* (x, y, z) acceleration. [g] */
} mipc_sensor_scaled_accel_t;

/* Largest encoded data (after the field header). */
#define MIPC_SENSOR_SCALED_ACCEL_MAX_SIZE 12

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_sensor_scaled_accel_encode(const mipc_sensor_scaled_accel_t *value, uint8_t *buf,
                                              size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_sensor_scaled_accel_decode(const uint8_t *data, size_t len,
                                              mipc_sensor_scaled_accel_t *out, mipc_decode_error_t *err);

/* ---- scaled_gyro (data): Scaled gyro vector */
#define MIPC_SENSOR_SCALED_GYRO_DESCRIPTOR 0x05

/** Scaled gyro vector. Sensed angular rate, temperature compensated, in radians/second, X, Y, Z. */
typedef struct {
    float scaled_gyro[3]; /* (x, y, z) angular rate. [rad/s] */
} mipc_sensor_scaled_gyro_t;

/* Largest encoded data (after the field header). */
#define MIPC_SENSOR_SCALED_GYRO_MAX_SIZE 12

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_sensor_scaled_gyro_encode(const mipc_sensor_scaled_gyro_t *value, uint8_t *buf, size_t cap,
                                             size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_sensor_scaled_gyro_decode(const uint8_t *data, size_t len, mipc_sensor_scaled_gyro_t *out,
                                             mipc_decode_error_t *err);

/* ---- scaled_mag (data): Scaled magnetometer vector */
#define MIPC_SENSOR_SCALED_MAG_DESCRIPTOR 0x06

/** Scaled magnetometer vector. Sensed magnetic field, temperature compensated, in Gauss, X, Y, Z. */
typedef struct {
    float scaled_mag[3]; /* (x, y, z) magnetic field. [gauss] */
} mipc_sensor_scaled_mag_t;

/* Largest encoded data (after the field header). */
#define MIPC_SENSOR_SCALED_MAG_MAX_SIZE 12

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_sensor_scaled_mag_encode(const mipc_sensor_scaled_mag_t *value, uint8_t *buf, size_t cap,
                                            size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_sensor_scaled_mag_decode(const uint8_t *data, size_t len, mipc_sensor_scaled_mag_t *out,
                                            mipc_decode_error_t *err);

/* ---- delta_theta (data): Delta theta vector */
#define MIPC_SENSOR_DELTA_THETA_DESCRIPTOR 0x07

/** Delta theta vector. Time integral of the angular rate over the interval set by the IMU message format (the
 * output period), in radians, X, Y, Z in the sensor (GX5-45) or vehicle (CV7) frame. */
typedef struct {
    float delta_theta[3]; /* (x, y, z) integrated angular rate. [rad] */
} mipc_sensor_delta_theta_t;

/* Largest encoded data (after the field header). */
#define MIPC_SENSOR_DELTA_THETA_MAX_SIZE 12

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_sensor_delta_theta_encode(const mipc_sensor_delta_theta_t *value, uint8_t *buf, size_t cap,
                                             size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_sensor_delta_theta_decode(const uint8_t *data, size_t len, mipc_sensor_delta_theta_t *out,
                                             mipc_decode_error_t *err);

/* ---- delta_velocity (data): Delta velocity vector */
#define MIPC_SENSOR_DELTA_VELOCITY_DESCRIPTOR 0x08

/** Delta velocity vector. Time integral of the sensed (specific) acceleration over the interval set by the
 * IMU message format, in g*seconds (multiply by 9.80665 for m/s), X, Y, Z in the sensor (GX5-45) or vehicle
 * (CV7) frame. */
typedef struct {
    float delta_velocity[3]; /* (x, y, z) integrated acceleration. [g*s] */
} mipc_sensor_delta_velocity_t;

/* Largest encoded data (after the field header). */
#define MIPC_SENSOR_DELTA_VELOCITY_MAX_SIZE 12

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_sensor_delta_velocity_encode(const mipc_sensor_delta_velocity_t *value, uint8_t *buf,
                                                size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_sensor_delta_velocity_decode(const uint8_t *data, size_t len,
                                                mipc_sensor_delta_velocity_t *out, mipc_decode_error_t *err);

/* ---- cf_orientation_matrix (data): Complementary filter orientation matrix */
#define MIPC_SENSOR_CF_ORIENTATION_MATRIX_DESCRIPTOR 0x09

/** Complementary filter orientation matrix. 3x3 orientation (direction cosine) matrix from the complementary
 * filter, rotating a vector from the earth-fixed (NED local-level) frame into the sensor (GX5-45) or vehicle
 * (CV7) frame: v_local = M * v_earth. Elements sent row-major, M11 M12 M13 M21 ... M33. */
typedef struct {
    float m[9]; /* Orientation matrix, row-major (dimensionless). */
} mipc_sensor_cf_orientation_matrix_t;

/* Largest encoded data (after the field header). */
#define MIPC_SENSOR_CF_ORIENTATION_MATRIX_MAX_SIZE 36

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_sensor_cf_orientation_matrix_encode(const mipc_sensor_cf_orientation_matrix_t *value,
                                                       uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_sensor_cf_orientation_matrix_decode(const uint8_t *data, size_t len,
                                                       mipc_sensor_cf_orientation_matrix_t *out,
                                                       mipc_decode_error_t *err);

/* ---- cf_quaternion (data): Complementary filter quaternion */
#define MIPC_SENSOR_CF_QUATERNION_DESCRIPTOR 0x0A

/** Complementary filter quaternion. Orientation quaternion (q0, q1, q2, q3) from the complementary filter, of
 * the sensor (GX5-45) or vehicle (CV7) frame relative to the earth-fixed (NED) frame: v_local = Q^-1 *
 * v_earth * Q. */
typedef struct {
    float q[4]; /* Quaternion elements q0 (scalar), q1, q2, q3 (dimensionless). */
} mipc_sensor_cf_quaternion_t;

/* Largest encoded data (after the field header). */
#define MIPC_SENSOR_CF_QUATERNION_MAX_SIZE 16

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_sensor_cf_quaternion_encode(const mipc_sensor_cf_quaternion_t *value, uint8_t *buf,
                                               size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_sensor_cf_quaternion_decode(const uint8_t *data, size_t len,
                                               mipc_sensor_cf_quaternion_t *out, mipc_decode_error_t *err);

/* ---- cf_euler_angles (data): Complementary filter Euler angles */
#define MIPC_SENSOR_CF_EULER_ANGLES_DESCRIPTOR 0x0C

/** Complementary filter Euler angles. Roll, pitch and yaw (aircraft 3-2-1 order) from the complementary
 * filter, in radians, relative to the earth-fixed (NED local-level) frame. */
typedef struct {
    float roll;  /* Roll angle. [rad] */
    float pitch; /* Pitch angle. [rad] */
    float yaw;   /* Yaw angle. [rad] */
} mipc_sensor_cf_euler_angles_t;

/* Largest encoded data (after the field header). */
#define MIPC_SENSOR_CF_EULER_ANGLES_MAX_SIZE 12

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_sensor_cf_euler_angles_encode(const mipc_sensor_cf_euler_angles_t *value, uint8_t *buf,
                                                 size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_sensor_cf_euler_angles_decode(const uint8_t *data, size_t len,
                                                 mipc_sensor_cf_euler_angles_t *out,
                                                 mipc_decode_error_t *err);

/* ---- cf_stabilized_north (data): Complementary filter stabilized north vector */
#define MIPC_SENSOR_CF_STABILIZED_NORTH_DESCRIPTOR 0x10

/** Complementary filter stabilized north vector. The complementary filter's gyro-stabilized estimate of the
 * geomagnetic field vector (magnetic north), in Gauss, in the sensor frame. Equal to the magnetometer reading
 * without magnetic interference, but free of transient interference. */
typedef struct {
    float stabilized_north[3]; /* (x, y, z) stabilized magnetic field estimate. [gauss] */
} mipc_sensor_cf_stabilized_north_t;

/* Largest encoded data (after the field header). */
#define MIPC_SENSOR_CF_STABILIZED_NORTH_MAX_SIZE 12

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_sensor_cf_stabilized_north_encode(const mipc_sensor_cf_stabilized_north_t *value,
                                                     uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_sensor_cf_stabilized_north_decode(const uint8_t *data, size_t len,
                                                     mipc_sensor_cf_stabilized_north_t *out,
                                                     mipc_decode_error_t *err);

/* ---- cf_stabilized_up (data): Complementary filter stabilized up vector */
#define MIPC_SENSOR_CF_STABILIZED_UP_DESCRIPTOR 0x11

/** Complementary filter stabilized up vector. The complementary filter's gyro-stabilized estimate of the
 * gravity vector (vertical), in g, in the sensor frame. Equal to the accelerometer reading when stationary,
 * but free of linear acceleration. */
typedef struct {
    float stabilized_up[3]; /* (x, y, z) stabilized gravity estimate. [g] */
} mipc_sensor_cf_stabilized_up_t;

/* Largest encoded data (after the field header). */
#define MIPC_SENSOR_CF_STABILIZED_UP_MAX_SIZE 12

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_sensor_cf_stabilized_up_encode(const mipc_sensor_cf_stabilized_up_t *value, uint8_t *buf,
                                                  size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_sensor_cf_stabilized_up_decode(const uint8_t *data, size_t len,
                                                  mipc_sensor_cf_stabilized_up_t *out,
                                                  mipc_decode_error_t *err);

/* ---- gps_timestamp (data): GPS timestamp of sensor data (GX5-45 GPS correlation timestamp) */
#define MIPC_SENSOR_GPS_TIMESTAMP_DESCRIPTOR 0x12

/** GPS timestamp of sensor data (GX5-45 GPS correlation timestamp). GPS time of the sensor sample as time of
 * week and week number, with status flags. Without a PPS the device runs on its internal clock and the time
 * drifts; expect a jump when the PPS returns. The fractional part of the time of week is the time since the
 * last PPS. The CV7 recommends the shared GPS timestamp (0xD3) instead. */
typedef struct {
    double tow;                                    /* GPS time of week. [s] */
    uint16_t week_number;                          /* GPS week number since 1980. [weeks] */
    mipc_sensor_gps_timestamp_flags_t valid_flags; /* Timestamp status flags (GX5-45: Timestamp Flags). */
} mipc_sensor_gps_timestamp_t;

/* Largest encoded data (after the field header). */
#define MIPC_SENSOR_GPS_TIMESTAMP_MAX_SIZE 12

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_sensor_gps_timestamp_encode(const mipc_sensor_gps_timestamp_t *value, uint8_t *buf,
                                               size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_sensor_gps_timestamp_decode(const uint8_t *data, size_t len,
                                               mipc_sensor_gps_timestamp_t *out, mipc_decode_error_t *err);

/* ---- temperature_statistics (data): Temperature statistics */
#define MIPC_SENSOR_TEMPERATURE_STATISTICS_DESCRIPTOR 0x14

/** Temperature statistics. Minimum, maximum and mean sensor temperature since the last power-on or reset,
 * from the MEMS sensors or combined with board temperature sensors. */
typedef struct {
    float min_temp;  /* Minimum temperature. [degC] */
    float max_temp;  /* Maximum temperature. [degC] */
    float mean_temp; /* Mean temperature. [degC] */
} mipc_sensor_temperature_statistics_t;

/* Largest encoded data (after the field header). */
#define MIPC_SENSOR_TEMPERATURE_STATISTICS_MAX_SIZE 12

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_sensor_temperature_statistics_encode(const mipc_sensor_temperature_statistics_t *value,
                                                        uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_sensor_temperature_statistics_decode(const uint8_t *data, size_t len,
                                                        mipc_sensor_temperature_statistics_t *out,
                                                        mipc_decode_error_t *err);

/* ---- scaled_pressure (data): Scaled ambient pressure */
#define MIPC_SENSOR_SCALED_PRESSURE_DESCRIPTOR 0x17

/** Scaled ambient pressure. Sensed ambient pressure, temperature compensated, in millibar. */
typedef struct {
    float scaled_pressure; /* Ambient pressure. [mbar] */
} mipc_sensor_scaled_pressure_t;

/* Largest encoded data (after the field header). */
#define MIPC_SENSOR_SCALED_PRESSURE_MAX_SIZE 4

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_sensor_scaled_pressure_encode(const mipc_sensor_scaled_pressure_t *value, uint8_t *buf,
                                                 size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_sensor_scaled_pressure_decode(const uint8_t *data, size_t len,
                                                 mipc_sensor_scaled_pressure_t *out,
                                                 mipc_decode_error_t *err);

/* ---- overrange_status (data): Over-range status */
#define MIPC_SENSOR_OVERRANGE_STATUS_DESCRIPTOR 0x18

/** Over-range status. Which sensor axes are near or beyond their range, per axis (a smaller, faster form of
 * the over-range bits of the continuous BIT). */
typedef struct {
    mipc_overrange_status_flags_t status; /* Over-range flags, one per axis. */
} mipc_sensor_overrange_status_t;

/* Largest encoded data (after the field header). */
#define MIPC_SENSOR_OVERRANGE_STATUS_MAX_SIZE 2

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_sensor_overrange_status_encode(const mipc_sensor_overrange_status_t *value, uint8_t *buf,
                                                  size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_sensor_overrange_status_decode(const uint8_t *data, size_t len,
                                                  mipc_sensor_overrange_status_t *out,
                                                  mipc_decode_error_t *err);

/* ---- odometer_data (data): Odometer data */
#define MIPC_SENSOR_ODOMETER_DATA_DESCRIPTOR 0x40

/** Odometer data. Speed measured by the odometer (wheel encoder) input and its uncertainty. */
typedef struct {
    float speed;       /* Average speed over the interval; can be negative with quadrature encoders. [m/s] */
    float uncertainty; /* Uncertainty of the speed. [m/s] */
    mipc_odometer_data_valid_flags_t valid_flags; /* Bit 0 set when the odometer is configured. */
} mipc_sensor_odometer_data_t;

/* Largest encoded data (after the field header). */
#define MIPC_SENSOR_ODOMETER_DATA_MAX_SIZE 10

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_sensor_odometer_data_encode(const mipc_sensor_odometer_data_t *value, uint8_t *buf,
                                               size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_sensor_odometer_data_decode(const uint8_t *data, size_t len,
                                               mipc_sensor_odometer_data_t *out, mipc_decode_error_t *err);

/**
 * The fields of one packet of this set, decoded in place by mipc_sensor_decode_packet: one member per
 * field the set defines with a single layout (its own, the reserved fields of its kind and the
 * shared data fields); `index` says which members hold a field of the packet, in packet order.
 */
typedef struct {
    mipc_packet_index_t index;
    mipc_sensor_scaled_accel_t sensor_scaled_accel;                     /* 0x04 */
    mipc_sensor_scaled_gyro_t sensor_scaled_gyro;                       /* 0x05 */
    mipc_sensor_scaled_mag_t sensor_scaled_mag;                         /* 0x06 */
    mipc_sensor_delta_theta_t sensor_delta_theta;                       /* 0x07 */
    mipc_sensor_delta_velocity_t sensor_delta_velocity;                 /* 0x08 */
    mipc_sensor_cf_orientation_matrix_t sensor_cf_orientation_matrix;   /* 0x09 */
    mipc_sensor_cf_quaternion_t sensor_cf_quaternion;                   /* 0x0A */
    mipc_sensor_cf_euler_angles_t sensor_cf_euler_angles;               /* 0x0C */
    mipc_sensor_cf_stabilized_north_t sensor_cf_stabilized_north;       /* 0x10 */
    mipc_sensor_cf_stabilized_up_t sensor_cf_stabilized_up;             /* 0x11 */
    mipc_sensor_gps_timestamp_t sensor_gps_timestamp;                   /* 0x12 */
    mipc_sensor_temperature_statistics_t sensor_temperature_statistics; /* 0x14 */
    mipc_sensor_scaled_pressure_t sensor_scaled_pressure;               /* 0x17 */
    mipc_sensor_overrange_status_t sensor_overrange_status;             /* 0x18 */
    mipc_sensor_odometer_data_t sensor_odometer_data;                   /* 0x40 */
    mipc_shared_event_source_t shared_event_source;                     /* 0xD0 (shared) */
    mipc_shared_gps_timestamp_t shared_gps_timestamp;                   /* 0xD3 (shared) */
    mipc_shared_delta_time_t shared_delta_time;                         /* 0xD4 (shared) */
    mipc_shared_reference_timestamp_t shared_reference_timestamp;       /* 0xD5 (shared) */
    mipc_shared_reference_time_delta_t shared_reference_time_delta;     /* 0xD6 (shared) */
    mipc_shared_external_timestamp_t shared_external_timestamp;         /* 0xD7 (shared) */
    mipc_shared_external_time_delta_t shared_external_time_delta;       /* 0xD8 (shared) */
} mipc_sensor_packet_t;

/**
 * The straight-line decoder of a packet of this set (issue 38): walks the fields of the payload
 * (len bytes at payload) with a switch on the descriptor and decodes each field's layout into its
 * member of *out, giving the value mipc_decode_field gives; no general value, no indirect call. Every
 * other entry goes to other (may be NULL: they are dropped) with ctx, in packet order with the
 * fields: a descriptor without a member (undefined, or a field with per-device variants), a field
 * that does not decode (its member is then unspecified), a second field with a descriptor already
 * decoded, trailing bytes. Returns out->index.count, the number of fields decoded into members.
 */
size_t mipc_sensor_decode_packet(const uint8_t *payload, size_t len, mipc_sensor_packet_t *out,
                                 mipc_field_entry_fn other, void *ctx);

/* Private (mipc_decode_packet_cached): the members of mipc_sensor_packet_t: descriptor, offset,
 * loader. */
extern const mipc_layout_member_t mipc_sensor_layout_members_[22];

#ifdef __cplusplus
}
#endif

#endif
