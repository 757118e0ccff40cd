/* Estimation Filter Data Set (descriptor set 0x82): one struct per field layout, with its
 * encoder and decoder. Generated from the spec: do not edit. */
#ifndef MIPC_SETS_FILTER_DATA_H
#define MIPC_SETS_FILTER_DATA_H

#include "mipcodec/types.h"
#include "mipcodec/field_iter.h"
#include "mipcodec/sets/shared.h"

#ifdef __cplusplus
extern "C" {
#endif

#define MIPC_FILTER_DATA_SET 0x82

/* ---- llh_position (data): LLH position */
#define MIPC_FILTER_DATA_LLH_POSITION_DESCRIPTOR 0x01

/** LLH position. Estimated position as WGS84 geodetic latitude, longitude and height above the ellipsoid. */
typedef struct {
    double latitude;                              /* Latitude. [deg] */
    double longitude;                             /* Longitude. [deg] */
    double ellipsoid_height;                      /* Height above the WGS84 ellipsoid. [m] */
    mipc_filter_output_valid_flags_t valid_flags; /* Whether latitude, longitude and height are valid. */
} mipc_filter_data_llh_position_t;

/* Largest encoded data (after the field header). */
#define MIPC_FILTER_DATA_LLH_POSITION_MAX_SIZE 26

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_filter_data_llh_position_encode(const mipc_filter_data_llh_position_t *value, uint8_t *buf,
                                                   size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_filter_data_llh_position_decode(const uint8_t *data, size_t len,
                                                   mipc_filter_data_llh_position_t *out,
                                                   mipc_decode_error_t *err);

/* ---- ned_velocity (data): NED velocity */
#define MIPC_FILTER_DATA_NED_VELOCITY_DESCRIPTOR 0x02

/** NED velocity. Estimated velocity in the local-level north-east-down frame. */
typedef struct {
    float north;                                  /* North velocity. [m/s] */
    float east;                                   /* East velocity. [m/s] */
    float down;                                   /* Down velocity. [m/s] */
    mipc_filter_output_valid_flags_t valid_flags; /* Whether the velocity is valid. */
} mipc_filter_data_ned_velocity_t;

/* Largest encoded data (after the field header). */
#define MIPC_FILTER_DATA_NED_VELOCITY_MAX_SIZE 14

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_filter_data_ned_velocity_encode(const mipc_filter_data_ned_velocity_t *value, uint8_t *buf,
                                                   size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_filter_data_ned_velocity_decode(const uint8_t *data, size_t len,
                                                   mipc_filter_data_ned_velocity_t *out,
                                                   mipc_decode_error_t *err);

/* ---- attitude_quaternion (data): Attitude quaternion */
#define MIPC_FILTER_DATA_ATTITUDE_QUATERNION_DESCRIPTOR 0x03

/** Attitude quaternion. Estimated orientation as a quaternion (q0, q1 i, q2 j, q3 k) rotating vectors from
 * the earth-fixed local-level (NED) frame into the device (vehicle) frame. */
typedef struct {
    float q[4]; /* Quaternion (q0, q1, q2, q3); the GX5-45 lists the four floats separately. */
    mipc_filter_output_valid_flags_t valid_flags; /* Whether the quaternion is valid. */
} mipc_filter_data_attitude_quaternion_t;

/* Largest encoded data (after the field header). */
#define MIPC_FILTER_DATA_ATTITUDE_QUATERNION_MAX_SIZE 18

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_filter_data_attitude_quaternion_encode(const mipc_filter_data_attitude_quaternion_t *value,
                                                          uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_filter_data_attitude_quaternion_decode(const uint8_t *data, size_t len,
                                                          mipc_filter_data_attitude_quaternion_t *out,
                                                          mipc_decode_error_t *err);

/* ---- attitude_dcm (data): Attitude direction cosine matrix */
#define MIPC_FILTER_DATA_ATTITUDE_DCM_DESCRIPTOR 0x04

/** Attitude direction cosine matrix. Estimated orientation as a 3x3 direction cosine matrix, row-major (M11,
 * M12, M13, M21, ...), that transforms a vector from the earth-fixed local-level (NED) frame into the device
 * (vehicle) frame. */
typedef struct {
    float dcm[9]; /* Matrix elements in row-major order; the GX5-45 lists M1,1 ... M3,3 at offsets 0-32. */
    mipc_filter_output_valid_flags_t valid_flags; /* Whether the matrix is valid. */
} mipc_filter_data_attitude_dcm_t;

/* Largest encoded data (after the field header). */
#define MIPC_FILTER_DATA_ATTITUDE_DCM_MAX_SIZE 38

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_filter_data_attitude_dcm_encode(const mipc_filter_data_attitude_dcm_t *value, uint8_t *buf,
                                                   size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_filter_data_attitude_dcm_decode(const uint8_t *data, size_t len,
                                                   mipc_filter_data_attitude_dcm_t *out,
                                                   mipc_decode_error_t *err);

/* ---- euler_angles (data): Euler angles */
#define MIPC_FILTER_DATA_EULER_ANGLES_DESCRIPTOR 0x05

/** Euler angles. Estimated roll, pitch and yaw relative to the local-level (NED) frame, in 3-2-1
 * (yaw-pitch-roll, aircraft) order. */
typedef struct {
    float roll;                                   /* Roll angle. [rad] */
    float pitch;                                  /* Pitch angle. [rad] */
    float yaw;                                    /* Yaw (heading) angle. [rad] */
    mipc_filter_output_valid_flags_t valid_flags; /* Whether the angles are valid. */
} mipc_filter_data_euler_angles_t;

/* Largest encoded data (after the field header). */
#define MIPC_FILTER_DATA_EULER_ANGLES_MAX_SIZE 14

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_filter_data_euler_angles_encode(const mipc_filter_data_euler_angles_t *value, uint8_t *buf,
                                                   size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_filter_data_euler_angles_decode(const uint8_t *data, size_t len,
                                                   mipc_filter_data_euler_angles_t *out,
                                                   mipc_decode_error_t *err);

/* ---- gyro_bias (data): Gyro bias */
#define MIPC_FILTER_DATA_GYRO_BIAS_DESCRIPTOR 0x06

/** Gyro bias. Estimated gyro bias, in the sensor frame. */
typedef struct {
    float bias[3];                                /* (x, y, z) gyro bias. [rad/s] */
    mipc_filter_output_valid_flags_t valid_flags; /* Whether the bias is valid. */
} mipc_filter_data_gyro_bias_t;

/* Largest encoded data (after the field header). */
#define MIPC_FILTER_DATA_GYRO_BIAS_MAX_SIZE 14

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_filter_data_gyro_bias_encode(const mipc_filter_data_gyro_bias_t *value, uint8_t *buf,
                                                size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_filter_data_gyro_bias_decode(const uint8_t *data, size_t len,
                                                mipc_filter_data_gyro_bias_t *out, mipc_decode_error_t *err);

/* ---- accel_bias (data): Accel bias */
#define MIPC_FILTER_DATA_ACCEL_BIAS_DESCRIPTOR 0x07

/** Accel bias. Estimated accelerometer bias, in the sensor frame. */
typedef struct {
    float bias[3];                                /* (x, y, z) accelerometer bias. [m/s^2] */
    mipc_filter_output_valid_flags_t valid_flags; /* Whether the bias is valid. */
} mipc_filter_data_accel_bias_t;

/* Largest encoded data (after the field header). */
#define MIPC_FILTER_DATA_ACCEL_BIAS_MAX_SIZE 14

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_filter_data_accel_bias_encode(const mipc_filter_data_accel_bias_t *value, uint8_t *buf,
                                                 size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_filter_data_accel_bias_decode(const uint8_t *data, size_t len,
                                                 mipc_filter_data_accel_bias_t *out,
                                                 mipc_decode_error_t *err);

/* ---- llh_position_uncertainty (data): LLH position uncertainty */
#define MIPC_FILTER_DATA_LLH_POSITION_UNCERTAINTY_DESCRIPTOR 0x08

/** LLH position uncertainty. 1-sigma uncertainty of the estimated position, along the local-level north, east
 * and down axes. */
typedef struct {
    float north;                                  /* North 1-sigma uncertainty. [m] */
    float east;                                   /* East 1-sigma uncertainty. [m] */
    float down;                                   /* Down 1-sigma uncertainty. [m] */
    mipc_filter_output_valid_flags_t valid_flags; /* Whether the uncertainties are valid. */
} mipc_filter_data_llh_position_uncertainty_t;

/* Largest encoded data (after the field header). */
#define MIPC_FILTER_DATA_LLH_POSITION_UNCERTAINTY_MAX_SIZE 14

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t
mipc_filter_data_llh_position_uncertainty_encode(const mipc_filter_data_llh_position_uncertainty_t *value,
                                                 uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t
mipc_filter_data_llh_position_uncertainty_decode(const uint8_t *data, size_t len,
                                                 mipc_filter_data_llh_position_uncertainty_t *out,
                                                 mipc_decode_error_t *err);

/* ---- ned_velocity_uncertainty (data): NED velocity uncertainty */
#define MIPC_FILTER_DATA_NED_VELOCITY_UNCERTAINTY_DESCRIPTOR 0x09

/** NED velocity uncertainty. 1-sigma uncertainty of the estimated velocity, along the local-level north, east
 * and down axes. */
typedef struct {
    float north;                                  /* North 1-sigma uncertainty. [m/s] */
    float east;                                   /* East 1-sigma uncertainty. [m/s] */
    float down;                                   /* Down 1-sigma uncertainty. [m/s] */
    mipc_filter_output_valid_flags_t valid_flags; /* Whether the uncertainties are valid. */
} mipc_filter_data_ned_velocity_uncertainty_t;

/* Largest encoded data (after the field header). */
#define MIPC_FILTER_DATA_NED_VELOCITY_UNCERTAINTY_MAX_SIZE 14

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t
mipc_filter_data_ned_velocity_uncertainty_encode(const mipc_filter_data_ned_velocity_uncertainty_t *value,
                                                 uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t
mipc_filter_data_ned_velocity_uncertainty_decode(const uint8_t *data, size_t len,
                                                 mipc_filter_data_ned_velocity_uncertainty_t *out,
                                                 mipc_decode_error_t *err);

/* ---- euler_angles_uncertainty (data): Euler angles uncertainty */
#define MIPC_FILTER_DATA_EULER_ANGLES_UNCERTAINTY_DESCRIPTOR 0x0A

/** Euler angles uncertainty. 1-sigma uncertainty of the estimated roll, pitch and yaw. The GX5-45 derives
 * these from the quaternion uncertainty and flags them invalid when the pitch exceeds +/-70 degrees. */
typedef struct {
    float roll;                                   /* Roll 1-sigma uncertainty. [rad] */
    float pitch;                                  /* Pitch 1-sigma uncertainty. [rad] */
    float yaw;                                    /* Yaw 1-sigma uncertainty. [rad] */
    mipc_filter_output_valid_flags_t valid_flags; /* Whether the uncertainties are valid. */
} mipc_filter_data_euler_angles_uncertainty_t;

/* Largest encoded data (after the field header). */
#define MIPC_FILTER_DATA_EULER_ANGLES_UNCERTAINTY_MAX_SIZE 14

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t
mipc_filter_data_euler_angles_uncertainty_encode(const mipc_filter_data_euler_angles_uncertainty_t *value,
                                                 uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t
mipc_filter_data_euler_angles_uncertainty_decode(const uint8_t *data, size_t len,
                                                 mipc_filter_data_euler_angles_uncertainty_t *out,
                                                 mipc_decode_error_t *err);

/* ---- gyro_bias_uncertainty (data): Gyro bias uncertainty */
#define MIPC_FILTER_DATA_GYRO_BIAS_UNCERTAINTY_DESCRIPTOR 0x0B

/** Gyro bias uncertainty. 1-sigma uncertainty of the estimated gyro bias, in the sensor frame. */
typedef struct {
    float bias_uncertainty[3];                    /* (x, y, z) 1-sigma uncertainty. [rad/s] */
    mipc_filter_output_valid_flags_t valid_flags; /* Whether the uncertainties are valid. */
} mipc_filter_data_gyro_bias_uncertainty_t;

/* Largest encoded data (after the field header). */
#define MIPC_FILTER_DATA_GYRO_BIAS_UNCERTAINTY_MAX_SIZE 14

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t
mipc_filter_data_gyro_bias_uncertainty_encode(const mipc_filter_data_gyro_bias_uncertainty_t *value,
                                              uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_filter_data_gyro_bias_uncertainty_decode(const uint8_t *data, size_t len,
                                                            mipc_filter_data_gyro_bias_uncertainty_t *out,
                                                            mipc_decode_error_t *err);

/* ---- accel_bias_uncertainty (data): Accel bias uncertainty */
#define MIPC_FILTER_DATA_ACCEL_BIAS_UNCERTAINTY_DESCRIPTOR 0x0C

/** Accel bias uncertainty. 1-sigma uncertainty of the estimated accelerometer bias, in the sensor frame. */
typedef struct {
    float bias_uncertainty[3];                    /* (x, y, z) 1-sigma uncertainty. [m/s^2] */
    mipc_filter_output_valid_flags_t valid_flags; /* Whether the uncertainties are valid. */
} mipc_filter_data_accel_bias_uncertainty_t;

/* Largest encoded data (after the field header). */
#define MIPC_FILTER_DATA_ACCEL_BIAS_UNCERTAINTY_MAX_SIZE 14

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t
mipc_filter_data_accel_bias_uncertainty_encode(const mipc_filter_data_accel_bias_uncertainty_t *value,
                                               uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_filter_data_accel_bias_uncertainty_decode(const uint8_t *data, size_t len,
                                                             mipc_filter_data_accel_bias_uncertainty_t *out,
                                                             mipc_decode_error_t *err);

/* ---- linear_accel (data): Linear acceleration */
#define MIPC_FILTER_DATA_LINEAR_ACCEL_DESCRIPTOR 0x0D

/** Linear acceleration. Filter-compensated acceleration with the estimated gravity removed, in the vehicle
 * frame (GX5-45: in the sensor frame when no sensor-to-vehicle rotation is set). */
typedef struct {
    float accel[3];                               /* (x, y, z) linear acceleration. [m/s^2] */
    mipc_filter_output_valid_flags_t valid_flags; /* Whether the acceleration is valid. */
} mipc_filter_data_linear_accel_t;

/* Largest encoded data (after the field header). */
#define MIPC_FILTER_DATA_LINEAR_ACCEL_MAX_SIZE 14

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_filter_data_linear_accel_encode(const mipc_filter_data_linear_accel_t *value, uint8_t *buf,
                                                   size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_filter_data_linear_accel_decode(const uint8_t *data, size_t len,
                                                   mipc_filter_data_linear_accel_t *out,
                                                   mipc_decode_error_t *err);

/* ---- comp_angular_rate (data): Compensated angular rate */
#define MIPC_FILTER_DATA_COMP_ANGULAR_RATE_DESCRIPTOR 0x0E

/** Compensated angular rate. Angular rate with the estimated gyro bias removed, in the vehicle frame (GX5-45:
 * in the sensor frame when no sensor-to-vehicle rotation is set). */
typedef struct {
    float gyro[3];                                /* (x, y, z) angular rate. [rad/s] */
    mipc_filter_output_valid_flags_t valid_flags; /* Whether the angular rate is valid. */
} mipc_filter_data_comp_angular_rate_t;

/* Largest encoded data (after the field header). */
#define MIPC_FILTER_DATA_COMP_ANGULAR_RATE_MAX_SIZE 14

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_filter_data_comp_angular_rate_encode(const mipc_filter_data_comp_angular_rate_t *value,
                                                        uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_filter_data_comp_angular_rate_decode(const uint8_t *data, size_t len,
                                                        mipc_filter_data_comp_angular_rate_t *out,
                                                        mipc_decode_error_t *err);

/* ---- wgs84_gravity_magnitude (data): WGS84 local gravity magnitude */
#define MIPC_FILTER_DATA_WGS84_GRAVITY_MAGNITUDE_DESCRIPTOR 0x0F

/** WGS84 local gravity magnitude. Magnitude of the local gravity from the WGS84 gravity model (valid for
 * altitudes up to 20 km). GX5-45 only. */
typedef struct {
    float gravity_magnitude;                      /* Local gravity magnitude. [m/s^2] */
    mipc_filter_output_valid_flags_t valid_flags; /* Whether the gravity value is valid. */
} mipc_filter_data_wgs84_gravity_magnitude_t;

/* Largest encoded data (after the field header). */
#define MIPC_FILTER_DATA_WGS84_GRAVITY_MAGNITUDE_MAX_SIZE 6

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t
mipc_filter_data_wgs84_gravity_magnitude_encode(const mipc_filter_data_wgs84_gravity_magnitude_t *value,
                                                uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_filter_data_wgs84_gravity_magnitude_decode(const uint8_t *data, size_t len,
                                                              mipc_filter_data_wgs84_gravity_magnitude_t *out,
                                                              mipc_decode_error_t *err);

/* ---- filter_status (data, 2 per-device variants): Filter status */
#define MIPC_FILTER_DATA_FILTER_STATUS_DESCRIPTOR 0x10

/** Filter status (gx5_45). Filter state (or mode), dynamics mode and status flags. All three are
 * device-specific: the same numbers mean different things on the GX5-45 and on the CV7. */
typedef struct {
    mipc_filter_state_gx5_t filter_state;          /* Filter state. */
    mipc_filter_dynamics_mode_gx5_t dynamics_mode; /* Vehicle dynamics mode. */
    mipc_filter_status_flags_gx5_t
        status_flags; /* Status flags; their meaning depends on the filter state. */
} mipc_filter_data_filter_status_gx5_45_t;

/* Largest encoded data (after the field header). */
#define MIPC_FILTER_DATA_FILTER_STATUS_GX5_45_MAX_SIZE 6

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t
mipc_filter_data_filter_status_gx5_45_encode(const mipc_filter_data_filter_status_gx5_45_t *value,
                                             uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_filter_data_filter_status_gx5_45_decode(const uint8_t *data, size_t len,
                                                           mipc_filter_data_filter_status_gx5_45_t *out,
                                                           mipc_decode_error_t *err);

/** Filter status (cv7_ins). Filter state (or mode), dynamics mode and status flags. All three are
 * device-specific: the same numbers mean different things on the GX5-45 and on the CV7. */
typedef struct {
    mipc_filter_mode_cv7_t filter_state;           /* Filter mode reached (Filter States page). */
    mipc_filter_dynamics_mode_cv7_t dynamics_mode; /* Dynamics mode. */
    mipc_filter_status_flags_cv7_t status_flags;   /* Filter condition and warning flags. */
} mipc_filter_data_filter_status_cv7_ins_t;

/* Largest encoded data (after the field header). */
#define MIPC_FILTER_DATA_FILTER_STATUS_CV7_INS_MAX_SIZE 6

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t
mipc_filter_data_filter_status_cv7_ins_encode(const mipc_filter_data_filter_status_cv7_ins_t *value,
                                              uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_filter_data_filter_status_cv7_ins_decode(const uint8_t *data, size_t len,
                                                            mipc_filter_data_filter_status_cv7_ins_t *out,
                                                            mipc_decode_error_t *err);

/* ---- gps_timestamp (data): GPS timestamp */
#define MIPC_FILTER_DATA_GPS_TIMESTAMP_DESCRIPTOR 0x11

/** GPS timestamp. GPS time of the filter solution in this packet. The CV7 notes that it may be deprecated in
 * favour of the shared GPS timestamp field (0xD3). */
typedef struct {
    double tow;                                   /* GPS time of week. [s] */
    uint16_t week_number;                         /* GPS week number since 1980. [weeks] */
    mipc_filter_output_valid_flags_t valid_flags; /* Whether the time is valid. */
} mipc_filter_data_gps_timestamp_t;

/* Largest encoded data (after the field header). */
#define MIPC_FILTER_DATA_GPS_TIMESTAMP_MAX_SIZE 12

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_filter_data_gps_timestamp_encode(const mipc_filter_data_gps_timestamp_t *value,
                                                    uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_filter_data_gps_timestamp_decode(const uint8_t *data, size_t len,
                                                    mipc_filter_data_gps_timestamp_t *out,
                                                    mipc_decode_error_t *err);

/* ---- quaternion_attitude_uncertainty (data): Quaternion attitude uncertainty */
#define MIPC_FILTER_DATA_QUATERNION_ATTITUDE_UNCERTAINTY_DESCRIPTOR 0x12

/** Quaternion attitude uncertainty. 1-sigma uncertainty of the attitude quaternion, one value per quaternion
 * element (dimensionless). */
typedef struct {
    float q[4];                                   /* 1-sigma uncertainty of (q0, q1, q2, q3). */
    mipc_filter_output_valid_flags_t valid_flags; /* Whether the uncertainties are valid. */
} mipc_filter_data_quaternion_attitude_uncertainty_t;

/* Largest encoded data (after the field header). */
#define MIPC_FILTER_DATA_QUATERNION_ATTITUDE_UNCERTAINTY_MAX_SIZE 18

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_filter_data_quaternion_attitude_uncertainty_encode(
    const mipc_filter_data_quaternion_attitude_uncertainty_t *value, uint8_t *buf, size_t cap,
    size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_filter_data_quaternion_attitude_uncertainty_decode(
    const uint8_t *data, size_t len, mipc_filter_data_quaternion_attitude_uncertainty_t *out,
    mipc_decode_error_t *err);

/* ---- gravity_vector (data): Gravity vector */
#define MIPC_FILTER_DATA_GRAVITY_VECTOR_DESCRIPTOR 0x13

/** Gravity vector. Estimated gravity vector. GX5-45: in the sensor frame, or in the vehicle frame when a
 * sensor-to-vehicle transformation is set; CV7: in the vehicle frame. */
typedef struct {
    float gravity[3];                             /* (x, y, z) gravity. [m/s^2] */
    mipc_filter_output_valid_flags_t valid_flags; /* Gravity vector valid. */
} mipc_filter_data_gravity_vector_t;

/* Largest encoded data (after the field header). */
#define MIPC_FILTER_DATA_GRAVITY_VECTOR_MAX_SIZE 14

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_filter_data_gravity_vector_encode(const mipc_filter_data_gravity_vector_t *value,
                                                     uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_filter_data_gravity_vector_decode(const uint8_t *data, size_t len,
                                                     mipc_filter_data_gravity_vector_t *out,
                                                     mipc_decode_error_t *err);

/* ---- heading_update_state (data): Heading update source state */
#define MIPC_FILTER_DATA_HEADING_UPDATE_STATE_DESCRIPTOR 0x14

/** Heading update source state. The last heading update the filter received: heading (relative to true
 * north), its uncertainty and the sources in use. */
typedef struct {
    float heading;                             /* Heading, from true north. [rad] */
    float heading_uncertainty;                 /* 1-sigma heading uncertainty. [rad] */
    mipc_filter_heading_source_flags_t source; /* Heading update sources in use (may be combined). */
    mipc_filter_heading_update_valid_flags_t
        valid_flags; /* Whether a heading update arrived within 2 seconds. */
} mipc_filter_data_heading_update_state_t;

/* Largest encoded data (after the field header). */
#define MIPC_FILTER_DATA_HEADING_UPDATE_STATE_MAX_SIZE 12

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t
mipc_filter_data_heading_update_state_encode(const mipc_filter_data_heading_update_state_t *value,
                                             uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_filter_data_heading_update_state_decode(const uint8_t *data, size_t len,
                                                           mipc_filter_data_heading_update_state_t *out,
                                                           mipc_decode_error_t *err);

/* ---- magnetic_model (data): Magnetic model solution */
#define MIPC_FILTER_DATA_MAGNETIC_MODEL_DESCRIPTOR 0x15

/** Magnetic model solution. Earth magnetic field at the current position from the World Magnetic Model
 * (GX5-45: WMM 2010), in the NED frame; needs a valid GNSS position. Invalid while the model is being
 * recalculated and when GNSS is unavailable. */
typedef struct {
    float intensity_north;                        /* North component of the field. [gauss] */
    float intensity_east;                         /* East component of the field. [gauss] */
    float intensity_down;                         /* Down component of the field. [gauss] */
    float inclination;                            /* Inclination (dip) angle. [rad] */
    float declination;                            /* Declination angle. [rad] */
    mipc_filter_output_valid_flags_t valid_flags; /* Model solution valid. */
} mipc_filter_data_magnetic_model_t;

/* Largest encoded data (after the field header). */
#define MIPC_FILTER_DATA_MAGNETIC_MODEL_MAX_SIZE 22

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_filter_data_magnetic_model_encode(const mipc_filter_data_magnetic_model_t *value,
                                                     uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_filter_data_magnetic_model_decode(const uint8_t *data, size_t len,
                                                     mipc_filter_data_magnetic_model_t *out,
                                                     mipc_decode_error_t *err);

/* ---- gyro_scale_factor (data): Gyro scale factor */
#define MIPC_FILTER_DATA_GYRO_SCALE_FACTOR_DESCRIPTOR 0x16

/** Gyro scale factor. Estimated gyro scale factor errors in the sensor body frame. */
typedef struct {
    float scale_factor[3]; /* (x, y, z) scale factor, as a fraction (percent / 100). [%/100] */
    mipc_filter_output_valid_flags_t valid_flags; /* Scale factor values valid. */
} mipc_filter_data_gyro_scale_factor_t;

/* Largest encoded data (after the field header). */
#define MIPC_FILTER_DATA_GYRO_SCALE_FACTOR_MAX_SIZE 14

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_filter_data_gyro_scale_factor_encode(const mipc_filter_data_gyro_scale_factor_t *value,
                                                        uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_filter_data_gyro_scale_factor_decode(const uint8_t *data, size_t len,
                                                        mipc_filter_data_gyro_scale_factor_t *out,
                                                        mipc_decode_error_t *err);

/* ---- accel_scale_factor (data): Accelerometer scale factor */
#define MIPC_FILTER_DATA_ACCEL_SCALE_FACTOR_DESCRIPTOR 0x17

/** Accelerometer scale factor. Estimated accelerometer scale factor errors in the sensor body frame. */
typedef struct {
    float scale_factor[3]; /* (x, y, z) scale factor, as a fraction (percent / 100). [%/100] */
    mipc_filter_output_valid_flags_t valid_flags; /* Scale factor values valid. */
} mipc_filter_data_accel_scale_factor_t;

/* Largest encoded data (after the field header). */
#define MIPC_FILTER_DATA_ACCEL_SCALE_FACTOR_MAX_SIZE 14

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_filter_data_accel_scale_factor_encode(const mipc_filter_data_accel_scale_factor_t *value,
                                                         uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_filter_data_accel_scale_factor_decode(const uint8_t *data, size_t len,
                                                         mipc_filter_data_accel_scale_factor_t *out,
                                                         mipc_decode_error_t *err);

/* ---- gyro_scale_factor_uncertainty (data): Gyro scale factor uncertainty */
#define MIPC_FILTER_DATA_GYRO_SCALE_FACTOR_UNCERTAINTY_DESCRIPTOR 0x18

/** Gyro scale factor uncertainty. 1-sigma uncertainty of the estimated gyro scale factors, sensor body frame.
 */
typedef struct {
    float scale_factor_uncertainty[3];            /* (x, y, z) 1-sigma uncertainty. [%/100] */
    mipc_filter_output_valid_flags_t valid_flags; /* Uncertainties valid. */
} mipc_filter_data_gyro_scale_factor_uncertainty_t;

/* Largest encoded data (after the field header). */
#define MIPC_FILTER_DATA_GYRO_SCALE_FACTOR_UNCERTAINTY_MAX_SIZE 14

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_filter_data_gyro_scale_factor_uncertainty_encode(
    const mipc_filter_data_gyro_scale_factor_uncertainty_t *value, uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t
mipc_filter_data_gyro_scale_factor_uncertainty_decode(const uint8_t *data, size_t len,
                                                      mipc_filter_data_gyro_scale_factor_uncertainty_t *out,
                                                      mipc_decode_error_t *err);

/* ---- accel_scale_factor_uncertainty (data): Accelerometer scale factor uncertainty */
#define MIPC_FILTER_DATA_ACCEL_SCALE_FACTOR_UNCERTAINTY_DESCRIPTOR 0x19

/** Accelerometer scale factor uncertainty. 1-sigma uncertainty of the estimated accelerometer scale factors,
 * sensor body frame. */
typedef struct {
    float scale_factor_uncertainty[3];            /* (x, y, z) 1-sigma uncertainty. [%/100] */
    mipc_filter_output_valid_flags_t valid_flags; /* Uncertainties valid. */
} mipc_filter_data_accel_scale_factor_uncertainty_t;

/* Largest encoded data (after the field header). */
#define MIPC_FILTER_DATA_ACCEL_SCALE_FACTOR_UNCERTAINTY_MAX_SIZE 14

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_filter_data_accel_scale_factor_uncertainty_encode(
    const mipc_filter_data_accel_scale_factor_uncertainty_t *value, uint8_t *buf, size_t cap,
    size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t
mipc_filter_data_accel_scale_factor_uncertainty_decode(const uint8_t *data, size_t len,
                                                       mipc_filter_data_accel_scale_factor_uncertainty_t *out,
                                                       mipc_decode_error_t *err);

/* ---- compensated_accel (data): Compensated acceleration */
#define MIPC_FILTER_DATA_COMPENSATED_ACCEL_DESCRIPTOR 0x1C

/** Compensated acceleration. Acceleration with the filter's bias estimate removed (gravity included; 0x0D is
 * the linear acceleration without gravity). GX5-45: sensor frame, or vehicle frame when a sensor-to-vehicle
 * transformation is set; CV7: vehicle frame. */
typedef struct {
    float accel[3];                               /* (x, y, z) compensated acceleration. [m/s^2] */
    mipc_filter_output_valid_flags_t valid_flags; /* Compensated accelerations valid. */
} mipc_filter_data_compensated_accel_t;

/* Largest encoded data (after the field header). */
#define MIPC_FILTER_DATA_COMPENSATED_ACCEL_MAX_SIZE 14

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_filter_data_compensated_accel_encode(const mipc_filter_data_compensated_accel_t *value,
                                                        uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_filter_data_compensated_accel_decode(const uint8_t *data, size_t len,
                                                        mipc_filter_data_compensated_accel_t *out,
                                                        mipc_decode_error_t *err);

/* ---- standard_atmosphere (data): Standard atmosphere model */
#define MIPC_FILTER_DATA_STANDARD_ATMOSPHERE_DESCRIPTOR 0x20

/** Standard atmosphere model. US 1976 Standard Atmosphere values at the current altitude; needs a valid GNSS
 * location (invalid while GNSS is unavailable). */
typedef struct {
    float geometric_altitude;                     /* Geometric altitude. [m] */
    float geopotential_altitude;                  /* Geopotential altitude. [m] */
    float temperature;                            /* Standard temperature. [degC] */
    float pressure;                               /* Standard pressure. [mbar] */
    float density;                                /* Standard air density. [kg/m^3] */
    mipc_filter_output_valid_flags_t valid_flags; /* Atmosphere model solution valid. */
} mipc_filter_data_standard_atmosphere_t;

/* Largest encoded data (after the field header). */
#define MIPC_FILTER_DATA_STANDARD_ATMOSPHERE_MAX_SIZE 22

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_filter_data_standard_atmosphere_encode(const mipc_filter_data_standard_atmosphere_t *value,
                                                          uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_filter_data_standard_atmosphere_decode(const uint8_t *data, size_t len,
                                                          mipc_filter_data_standard_atmosphere_t *out,
                                                          mipc_decode_error_t *err);

/* ---- pressure_altitude (data): Pressure altitude */
#define MIPC_FILTER_DATA_PRESSURE_ALTITUDE_DESCRIPTOR 0x21

/** Pressure altitude. Altitude from the pressure sensor through the US 1976 Standard Atmosphere model; needs
 * a valid pressure reading. The model supports pressures down to 0.0037 mbar (84,852 m). */
typedef struct {
    float pressure_altitude;                      /* Pressure altitude. [m] */
    mipc_filter_output_valid_flags_t valid_flags; /* Pressure altitude valid. */
} mipc_filter_data_pressure_altitude_t;

/* Largest encoded data (after the field header). */
#define MIPC_FILTER_DATA_PRESSURE_ALTITUDE_MAX_SIZE 6

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_filter_data_pressure_altitude_encode(const mipc_filter_data_pressure_altitude_t *value,
                                                        uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_filter_data_pressure_altitude_decode(const uint8_t *data, size_t len,
                                                        mipc_filter_data_pressure_altitude_t *out,
                                                        mipc_decode_error_t *err);

/* ---- mag_auto_hard_iron_offset (data): Magnetometer auto hard iron offset */
#define MIPC_FILTER_DATA_MAG_AUTO_HARD_IRON_OFFSET_DESCRIPTOR 0x25

/** Magnetometer auto hard iron offset. Offset vector the filter adds to the hard iron offset to compensate
 * in-run magnetometer bias errors. */
typedef struct {
    float hard_iron_offset[3];                    /* (x, y, z) offset. [gauss] */
    mipc_filter_output_valid_flags_t valid_flags; /* Vector valid. */
} mipc_filter_data_mag_auto_hard_iron_offset_t;

/* Largest encoded data (after the field header). */
#define MIPC_FILTER_DATA_MAG_AUTO_HARD_IRON_OFFSET_MAX_SIZE 14

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t
mipc_filter_data_mag_auto_hard_iron_offset_encode(const mipc_filter_data_mag_auto_hard_iron_offset_t *value,
                                                  uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t
mipc_filter_data_mag_auto_hard_iron_offset_decode(const uint8_t *data, size_t len,
                                                  mipc_filter_data_mag_auto_hard_iron_offset_t *out,
                                                  mipc_decode_error_t *err);

/* ---- mag_auto_soft_iron_matrix (data): Magnetometer auto soft iron matrix */
#define MIPC_FILTER_DATA_MAG_AUTO_SOFT_IRON_MATRIX_DESCRIPTOR 0x26

/** Magnetometer auto soft iron matrix. Matrix the filter applies to the soft iron calibration matrix to
 * compensate in-run magnetometer errors. */
typedef struct {
    float soft_iron_matrix[9];                    /* M11..M33, row-major (dimensionless). */
    mipc_filter_output_valid_flags_t valid_flags; /* Matrix valid. */
} mipc_filter_data_mag_auto_soft_iron_matrix_t;

/* Largest encoded data (after the field header). */
#define MIPC_FILTER_DATA_MAG_AUTO_SOFT_IRON_MATRIX_MAX_SIZE 38

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t
mipc_filter_data_mag_auto_soft_iron_matrix_encode(const mipc_filter_data_mag_auto_soft_iron_matrix_t *value,
                                                  uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t
mipc_filter_data_mag_auto_soft_iron_matrix_decode(const uint8_t *data, size_t len,
                                                  mipc_filter_data_mag_auto_soft_iron_matrix_t *out,
                                                  mipc_decode_error_t *err);

/* ---- mag_auto_hard_iron_offset_uncertainty (data): Magnetometer auto hard iron offset uncertainty */
#define MIPC_FILTER_DATA_MAG_AUTO_HARD_IRON_OFFSET_UNCERTAINTY_DESCRIPTOR 0x28

/** Magnetometer auto hard iron offset uncertainty. 1-sigma uncertainty of the auto hard iron offset
 * (0x82,0x25). */
typedef struct {
    float hard_iron_offset_uncertainty[3];        /* (x, y, z) 1-sigma uncertainty. [gauss] */
    mipc_filter_output_valid_flags_t valid_flags; /* Vector valid. */
} mipc_filter_data_mag_auto_hard_iron_offset_uncertainty_t;

/* Largest encoded data (after the field header). */
#define MIPC_FILTER_DATA_MAG_AUTO_HARD_IRON_OFFSET_UNCERTAINTY_MAX_SIZE 14

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_filter_data_mag_auto_hard_iron_offset_uncertainty_encode(
    const mipc_filter_data_mag_auto_hard_iron_offset_uncertainty_t *value, uint8_t *buf, size_t cap,
    size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_filter_data_mag_auto_hard_iron_offset_uncertainty_decode(
    const uint8_t *data, size_t len, mipc_filter_data_mag_auto_hard_iron_offset_uncertainty_t *out,
    mipc_decode_error_t *err);

/* ---- mag_auto_soft_iron_matrix_uncertainty (data): Magnetometer auto soft iron matrix uncertainty */
#define MIPC_FILTER_DATA_MAG_AUTO_SOFT_IRON_MATRIX_UNCERTAINTY_DESCRIPTOR 0x29

/** Magnetometer auto soft iron matrix uncertainty. 1-sigma uncertainty of each element of the auto soft iron
 * matrix (0x82,0x26). */
typedef struct {
    float soft_iron_matrix_uncertainty[9]; /* 1-sigma uncertainty of M11..M33, row-major (dimensionless). */
    mipc_filter_output_valid_flags_t valid_flags; /* Matrix valid. */
} mipc_filter_data_mag_auto_soft_iron_matrix_uncertainty_t;

/* Largest encoded data (after the field header). */
#define MIPC_FILTER_DATA_MAG_AUTO_SOFT_IRON_MATRIX_UNCERTAINTY_MAX_SIZE 38

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_filter_data_mag_auto_soft_iron_matrix_uncertainty_encode(
    const mipc_filter_data_mag_auto_soft_iron_matrix_uncertainty_t *value, uint8_t *buf, size_t cap,
    size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_filter_data_mag_auto_soft_iron_matrix_uncertainty_decode(
    const uint8_t *data, size_t len, mipc_filter_data_mag_auto_soft_iron_matrix_uncertainty_t *out,
    mipc_decode_error_t *err);

/* ---- gnss_antenna_offset_correction (data): GNSS antenna offset correction */
#define MIPC_FILTER_DATA_GNSS_ANTENNA_OFFSET_CORRECTION_DESCRIPTOR 0x30

/** GNSS antenna offset correction. Estimated correction of the GNSS antenna offset (the vector from the IMU
 * to the antenna), in the sensor body frame. */
typedef struct {
    float offset[3];                              /* (x, y, z) offset correction. [m] */
    mipc_filter_output_valid_flags_t valid_flags; /* Offset correction values valid. */
} mipc_filter_data_gnss_antenna_offset_correction_t;

/* Largest encoded data (after the field header). */
#define MIPC_FILTER_DATA_GNSS_ANTENNA_OFFSET_CORRECTION_MAX_SIZE 14

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_filter_data_gnss_antenna_offset_correction_encode(
    const mipc_filter_data_gnss_antenna_offset_correction_t *value, uint8_t *buf, size_t cap,
    size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t
mipc_filter_data_gnss_antenna_offset_correction_decode(const uint8_t *data, size_t len,
                                                       mipc_filter_data_gnss_antenna_offset_correction_t *out,
                                                       mipc_decode_error_t *err);

/* ---- gnss_antenna_offset_correction_uncertainty (data): GNSS antenna offset correction uncertainty */
#define MIPC_FILTER_DATA_GNSS_ANTENNA_OFFSET_CORRECTION_UNCERTAINTY_DESCRIPTOR 0x31

/** GNSS antenna offset correction uncertainty. 1-sigma uncertainty of the GNSS antenna offset correction,
 * sensor body frame. */
typedef struct {
    float offset_uncertainty[3];                  /* (x, y, z) 1-sigma uncertainty. [m] */
    mipc_filter_output_valid_flags_t valid_flags; /* Uncertainties valid. */
} mipc_filter_data_gnss_antenna_offset_correction_uncertainty_t;

/* Largest encoded data (after the field header). */
#define MIPC_FILTER_DATA_GNSS_ANTENNA_OFFSET_CORRECTION_UNCERTAINTY_MAX_SIZE 14

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_filter_data_gnss_antenna_offset_correction_uncertainty_encode(
    const mipc_filter_data_gnss_antenna_offset_correction_uncertainty_t *value, uint8_t *buf, size_t cap,
    size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_filter_data_gnss_antenna_offset_correction_uncertainty_decode(
    const uint8_t *data, size_t len, mipc_filter_data_gnss_antenna_offset_correction_uncertainty_t *out,
    mipc_decode_error_t *err);

/* ---- multi_antenna_offset_correction (data): Multi-antenna offset correction */
#define MIPC_FILTER_DATA_MULTI_ANTENNA_OFFSET_CORRECTION_DESCRIPTOR 0x34

/** Multi-antenna offset correction. Estimated correction of one GNSS antenna's offset, in the vehicle frame;
 * added to the stored offset vector to compensate errors in its definition. */
typedef struct {
    uint8_t receiver_id;                          /* Receiver to which the antenna is attached. */
    float offset[3];                              /* (x, y, z) offset correction. [m] */
    mipc_filter_output_valid_flags_t valid_flags; /* Offset correction valid. */
} mipc_filter_data_multi_antenna_offset_correction_t;

/* Largest encoded data (after the field header). */
#define MIPC_FILTER_DATA_MULTI_ANTENNA_OFFSET_CORRECTION_MAX_SIZE 15

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_filter_data_multi_antenna_offset_correction_encode(
    const mipc_filter_data_multi_antenna_offset_correction_t *value, uint8_t *buf, size_t cap,
    size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_filter_data_multi_antenna_offset_correction_decode(
    const uint8_t *data, size_t len, mipc_filter_data_multi_antenna_offset_correction_t *out,
    mipc_decode_error_t *err);

/* ---- multi_antenna_offset_correction_uncertainty (data): Multi-antenna offset correction uncertainty */
#define MIPC_FILTER_DATA_MULTI_ANTENNA_OFFSET_CORRECTION_UNCERTAINTY_DESCRIPTOR 0x35

/** Multi-antenna offset correction uncertainty. 1-sigma uncertainty of one GNSS antenna's offset correction,
 * vehicle frame. */
typedef struct {
    uint8_t receiver_id;                          /* Receiver to which the antenna is attached. */
    float offset_uncertainty[3];                  /* (x, y, z) 1-sigma uncertainty. [m] */
    mipc_filter_output_valid_flags_t valid_flags; /* Uncertainties valid. */
} mipc_filter_data_multi_antenna_offset_correction_uncertainty_t;

/* Largest encoded data (after the field header). */
#define MIPC_FILTER_DATA_MULTI_ANTENNA_OFFSET_CORRECTION_UNCERTAINTY_MAX_SIZE 15

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_filter_data_multi_antenna_offset_correction_uncertainty_encode(
    const mipc_filter_data_multi_antenna_offset_correction_uncertainty_t *value, uint8_t *buf, size_t cap,
    size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_filter_data_multi_antenna_offset_correction_uncertainty_decode(
    const uint8_t *data, size_t len, mipc_filter_data_multi_antenna_offset_correction_uncertainty_t *out,
    mipc_decode_error_t *err);

/* ---- ecef_position_uncertainty (data): ECEF position uncertainty */
#define MIPC_FILTER_DATA_ECEF_POSITION_UNCERTAINTY_DESCRIPTOR 0x36

/** ECEF position uncertainty. 1-sigma position uncertainty in the ECEF frame. */
typedef struct {
    float position_uncertainty[3];                /* (x, y, z) 1-sigma uncertainty. [m] */
    mipc_filter_output_valid_flags_t valid_flags; /* Uncertainties valid. */
} mipc_filter_data_ecef_position_uncertainty_t;

/* Largest encoded data (after the field header). */
#define MIPC_FILTER_DATA_ECEF_POSITION_UNCERTAINTY_MAX_SIZE 14

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t
mipc_filter_data_ecef_position_uncertainty_encode(const mipc_filter_data_ecef_position_uncertainty_t *value,
                                                  uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t
mipc_filter_data_ecef_position_uncertainty_decode(const uint8_t *data, size_t len,
                                                  mipc_filter_data_ecef_position_uncertainty_t *out,
                                                  mipc_decode_error_t *err);

/* ---- ecef_velocity_uncertainty (data): ECEF velocity uncertainty */
#define MIPC_FILTER_DATA_ECEF_VELOCITY_UNCERTAINTY_DESCRIPTOR 0x37

/** ECEF velocity uncertainty. 1-sigma velocity uncertainty in the ECEF frame. */
typedef struct {
    float velocity_uncertainty[3];                /* (x, y, z) 1-sigma uncertainty. [m/s] */
    mipc_filter_output_valid_flags_t valid_flags; /* Uncertainties valid. */
} mipc_filter_data_ecef_velocity_uncertainty_t;

/* Largest encoded data (after the field header). */
#define MIPC_FILTER_DATA_ECEF_VELOCITY_UNCERTAINTY_MAX_SIZE 14

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t
mipc_filter_data_ecef_velocity_uncertainty_encode(const mipc_filter_data_ecef_velocity_uncertainty_t *value,
                                                  uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t
mipc_filter_data_ecef_velocity_uncertainty_decode(const uint8_t *data, size_t len,
                                                  mipc_filter_data_ecef_velocity_uncertainty_t *out,
                                                  mipc_decode_error_t *err);

/* ---- ecef_position (data): ECEF position */
#define MIPC_FILTER_DATA_ECEF_POSITION_DESCRIPTOR 0x40

/** ECEF position. Estimated position in the ECEF frame. */
typedef struct {
    double position[3];                           /* (x, y, z) ECEF position. [m] */
    mipc_filter_output_valid_flags_t valid_flags; /* Position valid. */
} mipc_filter_data_ecef_position_t;

/* Largest encoded data (after the field header). */
#define MIPC_FILTER_DATA_ECEF_POSITION_MAX_SIZE 26

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_filter_data_ecef_position_encode(const mipc_filter_data_ecef_position_t *value,
                                                    uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_filter_data_ecef_position_decode(const uint8_t *data, size_t len,
                                                    mipc_filter_data_ecef_position_t *out,
                                                    mipc_decode_error_t *err);

/* ---- ecef_velocity (data): ECEF velocity */
#define MIPC_FILTER_DATA_ECEF_VELOCITY_DESCRIPTOR 0x41

/** ECEF velocity. Estimated velocity in the ECEF frame. */
typedef struct {
    float velocity[3];                            /* (x, y, z) ECEF velocity. [m/s] */
    mipc_filter_output_valid_flags_t valid_flags; /* Velocity valid. */
} mipc_filter_data_ecef_velocity_t;

/* Largest encoded data (after the field header). */
#define MIPC_FILTER_DATA_ECEF_VELOCITY_MAX_SIZE 14

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_filter_data_ecef_velocity_encode(const mipc_filter_data_ecef_velocity_t *value,
                                                    uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_filter_data_ecef_velocity_decode(const uint8_t *data, size_t len,
                                                    mipc_filter_data_ecef_velocity_t *out,
                                                    mipc_decode_error_t *err);

/* ---- ned_relative_position (data): NED relative position */
#define MIPC_FILTER_DATA_NED_RELATIVE_POSITION_DESCRIPTOR 0x42

/** NED relative position. Estimated position relative to the reference position set with Relative Position
 * Configuration (0x0D,0x55), as north, east, down. */
typedef struct {
    double relative_position[3]; /* (north, east, down) position relative to the reference. [m] */
    mipc_filter_output_valid_flags_t valid_flags; /* Relative position valid. */
} mipc_filter_data_ned_relative_position_t;

/* Largest encoded data (after the field header). */
#define MIPC_FILTER_DATA_NED_RELATIVE_POSITION_MAX_SIZE 26

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t
mipc_filter_data_ned_relative_position_encode(const mipc_filter_data_ned_relative_position_t *value,
                                              uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_filter_data_ned_relative_position_decode(const uint8_t *data, size_t len,
                                                            mipc_filter_data_ned_relative_position_t *out,
                                                            mipc_decode_error_t *err);

/* ---- gnss_position_aiding_status (data): GNSS position aiding status */
#define MIPC_FILTER_DATA_GNSS_POSITION_AIDING_STATUS_DESCRIPTOR 0x43

/** GNSS position aiding status. How the filter is using the position measurements of one GNSS receiver. */
typedef struct {
    uint8_t receiver_id; /* GNSS receiver the status refers to. */
    float time_of_week;  /* GPS time of week of the last GNSS aiding measurement. [s] */
    mipc_filter_gnss_aiding_status_flags_t status; /* Aiding measurement status. */
    uint8_t reserved[8];                           /* Reserved. */
} mipc_filter_data_gnss_position_aiding_status_t;

/* Largest encoded data (after the field header). */
#define MIPC_FILTER_DATA_GNSS_POSITION_AIDING_STATUS_MAX_SIZE 15

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_filter_data_gnss_position_aiding_status_encode(
    const mipc_filter_data_gnss_position_aiding_status_t *value, uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t
mipc_filter_data_gnss_position_aiding_status_decode(const uint8_t *data, size_t len,
                                                    mipc_filter_data_gnss_position_aiding_status_t *out,
                                                    mipc_decode_error_t *err);

/* ---- aiding_measurement_summary (data): Aiding measurement summary */
#define MIPC_FILTER_DATA_AIDING_MEASUREMENT_SUMMARY_DESCRIPTOR 0x46

/** Aiding measurement summary. Summary of one aiding measurement over the measurement interval ending at the
 * given time: whether it is enabled and used, and any warnings. */
typedef struct {
    float time_of_week; /* GPS time of week at the end of the measurement interval. [s] */
    uint8_t source;     /* Measurement source (not described by the manual). */
    mipc_filter_aiding_measurement_type_t type;           /* Which aiding measurement is summarised. */
    mipc_filter_aiding_measurement_indicator_t indicator; /* Measurement state and warnings. */
} mipc_filter_data_aiding_measurement_summary_t;

/* Largest encoded data (after the field header). */
#define MIPC_FILTER_DATA_AIDING_MEASUREMENT_SUMMARY_MAX_SIZE 7

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t
mipc_filter_data_aiding_measurement_summary_encode(const mipc_filter_data_aiding_measurement_summary_t *value,
                                                   uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t
mipc_filter_data_aiding_measurement_summary_decode(const uint8_t *data, size_t len,
                                                   mipc_filter_data_aiding_measurement_summary_t *out,
                                                   mipc_decode_error_t *err);

/* ---- odometer_scale_factor_error (data): Odometer scale factor error */
#define MIPC_FILTER_DATA_ODOMETER_SCALE_FACTOR_ERROR_DESCRIPTOR 0x47

/** Odometer scale factor error. Estimated odometer scale factor error; the total scale factor is the user
 * scale factor times (1 + this error). */
typedef struct {
    float scale_factor_error;                     /* Scale factor error (dimensionless). */
    mipc_filter_output_valid_flags_t valid_flags; /* Estimate valid. */
} mipc_filter_data_odometer_scale_factor_error_t;

/* Largest encoded data (after the field header). */
#define MIPC_FILTER_DATA_ODOMETER_SCALE_FACTOR_ERROR_MAX_SIZE 6

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_filter_data_odometer_scale_factor_error_encode(
    const mipc_filter_data_odometer_scale_factor_error_t *value, uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t
mipc_filter_data_odometer_scale_factor_error_decode(const uint8_t *data, size_t len,
                                                    mipc_filter_data_odometer_scale_factor_error_t *out,
                                                    mipc_decode_error_t *err);

/* ---- odometer_scale_factor_error_uncertainty (data): Odometer scale factor error uncertainty */
#define MIPC_FILTER_DATA_ODOMETER_SCALE_FACTOR_ERROR_UNCERTAINTY_DESCRIPTOR 0x48

/** Odometer scale factor error uncertainty. 1-sigma uncertainty of the odometer scale factor error. */
typedef struct {
    float scale_factor_error_uncertainty;         /* 1-sigma uncertainty (dimensionless). */
    mipc_filter_output_valid_flags_t valid_flags; /* Uncertainty valid. */
} mipc_filter_data_odometer_scale_factor_error_uncertainty_t;

/* Largest encoded data (after the field header). */
#define MIPC_FILTER_DATA_ODOMETER_SCALE_FACTOR_ERROR_UNCERTAINTY_MAX_SIZE 6

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_filter_data_odometer_scale_factor_error_uncertainty_encode(
    const mipc_filter_data_odometer_scale_factor_error_uncertainty_t *value, uint8_t *buf, size_t cap,
    size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_filter_data_odometer_scale_factor_error_uncertainty_decode(
    const uint8_t *data, size_t len, mipc_filter_data_odometer_scale_factor_error_uncertainty_t *out,
    mipc_decode_error_t *err);

/* ---- gnss_dual_antenna_status (data): GNSS dual antenna status */
#define MIPC_FILTER_DATA_GNSS_DUAL_ANTENNA_STATUS_DESCRIPTOR 0x49

/** GNSS dual antenna status. State of the GNSS dual-antenna heading measurement the filter last used. */
typedef struct {
    float time_of_week;        /* GPS time of week of the last dual-antenna aiding measurement. [s] */
    float heading;             /* Dual-antenna heading. [rad] */
    float heading_uncertainty; /* 1-sigma heading uncertainty. [rad] */
    mipc_filter_dual_antenna_fix_type_t fix_type;         /* Fix type. */
    mipc_filter_dual_antenna_status_flags_t status_flags; /* Receiver and antenna-offset validity. */
    mipc_filter_output_valid_flags_t valid_flags;         /* Field valid. */
} mipc_filter_data_gnss_dual_antenna_status_t;

/* Largest encoded data (after the field header). */
#define MIPC_FILTER_DATA_GNSS_DUAL_ANTENNA_STATUS_MAX_SIZE 17

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t
mipc_filter_data_gnss_dual_antenna_status_encode(const mipc_filter_data_gnss_dual_antenna_status_t *value,
                                                 uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t
mipc_filter_data_gnss_dual_antenna_status_decode(const uint8_t *data, size_t len,
                                                 mipc_filter_data_gnss_dual_antenna_status_t *out,
                                                 mipc_decode_error_t *err);

/* ---- aiding_frame_config_error (data): Aiding frame configuration error */
#define MIPC_FILTER_DATA_AIDING_FRAME_CONFIG_ERROR_DESCRIPTOR 0x50

/** Aiding frame configuration error. Estimated error of one user aiding frame configuration (Aiding Frame
 * Configuration, 0x13,0x01), used to compensate small errors in it. */
typedef struct {
    uint8_t frame_id;     /* Aiding reference frame id (as in 0x13,0x01). */
    float translation[3]; /* Translation error, X, Y, Z. [m] */
    float attitude[4];    /* Attitude error quaternion. */
} mipc_filter_data_aiding_frame_config_error_t;

/* Largest encoded data (after the field header). */
#define MIPC_FILTER_DATA_AIDING_FRAME_CONFIG_ERROR_MAX_SIZE 29

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t
mipc_filter_data_aiding_frame_config_error_encode(const mipc_filter_data_aiding_frame_config_error_t *value,
                                                  uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t
mipc_filter_data_aiding_frame_config_error_decode(const uint8_t *data, size_t len,
                                                  mipc_filter_data_aiding_frame_config_error_t *out,
                                                  mipc_decode_error_t *err);

/* ---- aiding_frame_config_error_uncertainty (data): Aiding frame configuration error uncertainty */
#define MIPC_FILTER_DATA_AIDING_FRAME_CONFIG_ERROR_UNCERTAINTY_DESCRIPTOR 0x51

/** Aiding frame configuration error uncertainty. 1-sigma uncertainty of the estimated aiding frame
 * configuration error (0x82,0x50). */
typedef struct {
    uint8_t frame_id;                 /* Aiding reference frame id (as in 0x13,0x01). */
    float translation_uncertainty[3]; /* 1-sigma translation uncertainty, X, Y, Z. [m] */
    float attitude_uncertainty[3];    /* 1-sigma attitude uncertainty, X, Y, Z. [rad] */
} mipc_filter_data_aiding_frame_config_error_uncertainty_t;

/* Largest encoded data (after the field header). */
#define MIPC_FILTER_DATA_AIDING_FRAME_CONFIG_ERROR_UNCERTAINTY_MAX_SIZE 25

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_filter_data_aiding_frame_config_error_uncertainty_encode(
    const mipc_filter_data_aiding_frame_config_error_uncertainty_t *value, uint8_t *buf, size_t cap,
    size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_filter_data_aiding_frame_config_error_uncertainty_decode(
    const uint8_t *data, size_t len, mipc_filter_data_aiding_frame_config_error_uncertainty_t *out,
    mipc_decode_error_t *err);

/**
 * The fields of one packet of this set, decoded in place by mipc_filter_data_decode_packet: one member per
 * field the set defines with a single layout (its own, the reserved fields of its kind and the
 * shared data fields); `index` says which members hold a field of the packet, in packet order.
 */
typedef struct {
    mipc_packet_index_t index;
    mipc_filter_data_llh_position_t filter_data_llh_position;                                       /* 0x01 */
    mipc_filter_data_ned_velocity_t filter_data_ned_velocity;                                       /* 0x02 */
    mipc_filter_data_attitude_quaternion_t filter_data_attitude_quaternion;                         /* 0x03 */
    mipc_filter_data_attitude_dcm_t filter_data_attitude_dcm;                                       /* 0x04 */
    mipc_filter_data_euler_angles_t filter_data_euler_angles;                                       /* 0x05 */
    mipc_filter_data_gyro_bias_t filter_data_gyro_bias;                                             /* 0x06 */
    mipc_filter_data_accel_bias_t filter_data_accel_bias;                                           /* 0x07 */
    mipc_filter_data_llh_position_uncertainty_t filter_data_llh_position_uncertainty;               /* 0x08 */
    mipc_filter_data_ned_velocity_uncertainty_t filter_data_ned_velocity_uncertainty;               /* 0x09 */
    mipc_filter_data_euler_angles_uncertainty_t filter_data_euler_angles_uncertainty;               /* 0x0A */
    mipc_filter_data_gyro_bias_uncertainty_t filter_data_gyro_bias_uncertainty;                     /* 0x0B */
    mipc_filter_data_accel_bias_uncertainty_t filter_data_accel_bias_uncertainty;                   /* 0x0C */
    mipc_filter_data_linear_accel_t filter_data_linear_accel;                                       /* 0x0D */
    mipc_filter_data_comp_angular_rate_t filter_data_comp_angular_rate;                             /* 0x0E */
    mipc_filter_data_wgs84_gravity_magnitude_t filter_data_wgs84_gravity_magnitude;                 /* 0x0F */
    mipc_filter_data_gps_timestamp_t filter_data_gps_timestamp;                                     /* 0x11 */
    mipc_filter_data_quaternion_attitude_uncertainty_t filter_data_quaternion_attitude_uncertainty; /* 0x12 */
    mipc_filter_data_gravity_vector_t filter_data_gravity_vector;                                   /* 0x13 */
    mipc_filter_data_heading_update_state_t filter_data_heading_update_state;                       /* 0x14 */
    mipc_filter_data_magnetic_model_t filter_data_magnetic_model;                                   /* 0x15 */
    mipc_filter_data_gyro_scale_factor_t filter_data_gyro_scale_factor;                             /* 0x16 */
    mipc_filter_data_accel_scale_factor_t filter_data_accel_scale_factor;                           /* 0x17 */
    mipc_filter_data_gyro_scale_factor_uncertainty_t filter_data_gyro_scale_factor_uncertainty;     /* 0x18 */
    mipc_filter_data_accel_scale_factor_uncertainty_t filter_data_accel_scale_factor_uncertainty;   /* 0x19 */
    mipc_filter_data_compensated_accel_t filter_data_compensated_accel;                             /* 0x1C */
    mipc_filter_data_standard_atmosphere_t filter_data_standard_atmosphere;                         /* 0x20 */
    mipc_filter_data_pressure_altitude_t filter_data_pressure_altitude;                             /* 0x21 */
    mipc_filter_data_mag_auto_hard_iron_offset_t filter_data_mag_auto_hard_iron_offset;             /* 0x25 */
    mipc_filter_data_mag_auto_soft_iron_matrix_t filter_data_mag_auto_soft_iron_matrix;             /* 0x26 */
    mipc_filter_data_mag_auto_hard_iron_offset_uncertainty_t
        filter_data_mag_auto_hard_iron_offset_uncertainty; /* 0x28 */
    mipc_filter_data_mag_auto_soft_iron_matrix_uncertainty_t
        filter_data_mag_auto_soft_iron_matrix_uncertainty;                                        /* 0x29 */
    mipc_filter_data_gnss_antenna_offset_correction_t filter_data_gnss_antenna_offset_correction; /* 0x30 */
    mipc_filter_data_gnss_antenna_offset_correction_uncertainty_t
        filter_data_gnss_antenna_offset_correction_uncertainty;                                     /* 0x31 */
    mipc_filter_data_multi_antenna_offset_correction_t filter_data_multi_antenna_offset_correction; /* 0x34 */
    mipc_filter_data_multi_antenna_offset_correction_uncertainty_t
        filter_data_multi_antenna_offset_correction_uncertainty;                            /* 0x35 */
    mipc_filter_data_ecef_position_uncertainty_t filter_data_ecef_position_uncertainty;     /* 0x36 */
    mipc_filter_data_ecef_velocity_uncertainty_t filter_data_ecef_velocity_uncertainty;     /* 0x37 */
    mipc_filter_data_ecef_position_t filter_data_ecef_position;                             /* 0x40 */
    mipc_filter_data_ecef_velocity_t filter_data_ecef_velocity;                             /* 0x41 */
    mipc_filter_data_ned_relative_position_t filter_data_ned_relative_position;             /* 0x42 */
    mipc_filter_data_gnss_position_aiding_status_t filter_data_gnss_position_aiding_status; /* 0x43 */
    mipc_filter_data_aiding_measurement_summary_t filter_data_aiding_measurement_summary;   /* 0x46 */
    mipc_filter_data_odometer_scale_factor_error_t filter_data_odometer_scale_factor_error; /* 0x47 */
    mipc_filter_data_odometer_scale_factor_error_uncertainty_t
        filter_data_odometer_scale_factor_error_uncertainty;                            /* 0x48 */
    mipc_filter_data_gnss_dual_antenna_status_t filter_data_gnss_dual_antenna_status;   /* 0x49 */
    mipc_filter_data_aiding_frame_config_error_t filter_data_aiding_frame_config_error; /* 0x50 */
    mipc_filter_data_aiding_frame_config_error_uncertainty_t
        filter_data_aiding_frame_config_error_uncertainty;          /* 0x51 */
    mipc_shared_event_source_t shared_event_source;                 /* 0xD0 (shared) */
    mipc_shared_gps_timestamp_t shared_gps_timestamp;               /* 0xD3 (shared) */
    mipc_shared_delta_time_t shared_delta_time;                     /* 0xD4 (shared) */
    mipc_shared_reference_timestamp_t shared_reference_timestamp;   /* 0xD5 (shared) */
    mipc_shared_reference_time_delta_t shared_reference_time_delta; /* 0xD6 (shared) */
    mipc_shared_external_timestamp_t shared_external_timestamp;     /* 0xD7 (shared) */
    mipc_shared_external_time_delta_t shared_external_time_delta;   /* 0xD8 (shared) */
} mipc_filter_data_packet_t;

/**
 * The straight-line decoder of a packet of this set (issue 38): walks the fields of the payload
 * (len bytes at payload) with a switch on the descriptor and decodes each field's layout into its
 * member of *out, giving the value mipc_decode_field gives; no general value, no indirect call. Every
 * other entry goes to other (may be NULL: they are dropped) with ctx, in packet order with the
 * fields: a descriptor without a member (undefined, or a field with per-device variants), a field
 * that does not decode (its member is then unspecified), a second field with a descriptor already
 * decoded, trailing bytes. Returns out->index.count, the number of fields decoded into members.
 */
size_t mipc_filter_data_decode_packet(const uint8_t *payload, size_t len, mipc_filter_data_packet_t *out,
                                      mipc_field_entry_fn other, void *ctx);

/* Private (mipc_decode_packet_cached): the members of mipc_filter_data_packet_t: descriptor, offset,
 * loader. */
extern const mipc_layout_member_t mipc_filter_data_layout_members_[54];

#ifdef __cplusplus
}
#endif

#endif
