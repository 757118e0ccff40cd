/* IMU Data Message (descriptor set 0xA2): one struct per field layout, with its
 * encoder and decoder. Generated from the spec: do not edit. */
#ifndef MSCIPC_SETS_IMU_DATA_H
#define MSCIPC_SETS_IMU_DATA_H

#include "mscipcodec/types.h"
#include "mscipcodec/field_iter.h"

#ifdef __cplusplus
extern "C" {
#endif

#define MSCIPC_IMU_DATA_SET 0xA2

/* ---- scaled_accel (data): Scaled acceleration vector */
#define MSCIPC_IMU_DATA_SCALED_ACCEL_DESCRIPTOR 0x81

/** Scaled acceleration vector. X, Y and Z acceleration in g. */
typedef struct {
    float accel[3]; /* Acceleration [x, y, z]. [g] */
} mscipc_imu_data_scaled_accel_t;

/* Largest encoded data (after the field header). */
#define MSCIPC_IMU_DATA_SCALED_ACCEL_MAX_SIZE 12

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mscipc_status_t mscipc_imu_data_scaled_accel_encode(const mscipc_imu_data_scaled_accel_t *value, uint8_t *buf,
                                                    size_t cap, size_t *len_out);
/** Decodes field data; on MSCIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mscipc_status_t mscipc_imu_data_scaled_accel_decode(const uint8_t *data, size_t len,
                                                    mscipc_imu_data_scaled_accel_t *out,
                                                    mscipc_decode_error_t *err);

/* ---- scaled_gyro (data): Scaled angular rate vector */
#define MSCIPC_IMU_DATA_SCALED_GYRO_DESCRIPTOR 0x82

/** Scaled angular rate vector. X, Y and Z angular rate in degrees per second. */
typedef struct {
    float gyro[3]; /* Angular rate [x, y, z]. [deg/s] */
} mscipc_imu_data_scaled_gyro_t;

/* Largest encoded data (after the field header). */
#define MSCIPC_IMU_DATA_SCALED_GYRO_MAX_SIZE 12

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mscipc_status_t mscipc_imu_data_scaled_gyro_encode(const mscipc_imu_data_scaled_gyro_t *value, uint8_t *buf,
                                                   size_t cap, size_t *len_out);
/** Decodes field data; on MSCIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mscipc_status_t mscipc_imu_data_scaled_gyro_decode(const uint8_t *data, size_t len,
                                                   mscipc_imu_data_scaled_gyro_t *out,
                                                   mscipc_decode_error_t *err);

/* ---- scaled_mag (data): Scaled magnetic field vector */
#define MSCIPC_IMU_DATA_SCALED_MAG_DESCRIPTOR 0x83

/** Scaled magnetic field vector. X, Y and Z magnetic field in gauss. */
typedef struct {
    float mag[3]; /* Magnetic field [x, y, z]. [gauss] */
} mscipc_imu_data_scaled_mag_t;

/* Largest encoded data (after the field header). */
#define MSCIPC_IMU_DATA_SCALED_MAG_MAX_SIZE 12

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mscipc_status_t mscipc_imu_data_scaled_mag_encode(const mscipc_imu_data_scaled_mag_t *value, uint8_t *buf,
                                                  size_t cap, size_t *len_out);
/** Decodes field data; on MSCIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mscipc_status_t mscipc_imu_data_scaled_mag_decode(const uint8_t *data, size_t len,
                                                  mscipc_imu_data_scaled_mag_t *out,
                                                  mscipc_decode_error_t *err);

/* ---- delta_theta (data): Scaled delta theta vector */
#define MSCIPC_IMU_DATA_DELTA_THETA_DESCRIPTOR 0x84

/** Scaled delta theta vector. X, Y and Z change in angle in radians. */
typedef struct {
    float delta_theta[3]; /* Change in angle [x, y, z]. [rad] */
} mscipc_imu_data_delta_theta_t;

/* Largest encoded data (after the field header). */
#define MSCIPC_IMU_DATA_DELTA_THETA_MAX_SIZE 12

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mscipc_status_t mscipc_imu_data_delta_theta_encode(const mscipc_imu_data_delta_theta_t *value, uint8_t *buf,
                                                   size_t cap, size_t *len_out);
/** Decodes field data; on MSCIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mscipc_status_t mscipc_imu_data_delta_theta_decode(const uint8_t *data, size_t len,
                                                   mscipc_imu_data_delta_theta_t *out,
                                                   mscipc_decode_error_t *err);

/* ---- delta_velocity (data): Scaled delta velocity vector */
#define MSCIPC_IMU_DATA_DELTA_VELOCITY_DESCRIPTOR 0x85

/** Scaled delta velocity vector. X, Y and Z change in velocity in metres per second. */
typedef struct {
    float delta_velocity[3]; /* Change in velocity [x, y, z]. [m/s] */
} mscipc_imu_data_delta_velocity_t;

/* Largest encoded data (after the field header). */
#define MSCIPC_IMU_DATA_DELTA_VELOCITY_MAX_SIZE 12

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mscipc_status_t mscipc_imu_data_delta_velocity_encode(const mscipc_imu_data_delta_velocity_t *value,
                                                      uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MSCIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mscipc_status_t mscipc_imu_data_delta_velocity_decode(const uint8_t *data, size_t len,
                                                      mscipc_imu_data_delta_velocity_t *out,
                                                      mscipc_decode_error_t *err);

/* ---- scaled_pressure (data): Scaled pressure */
#define MSCIPC_IMU_DATA_SCALED_PRESSURE_DESCRIPTOR 0x86

/** Scaled pressure. Atmospheric pressure in millibar. */
typedef struct {
    float pressure; /* Pressure. [mbar] */
} mscipc_imu_data_scaled_pressure_t;

/* Largest encoded data (after the field header). */
#define MSCIPC_IMU_DATA_SCALED_PRESSURE_MAX_SIZE 4

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mscipc_status_t mscipc_imu_data_scaled_pressure_encode(const mscipc_imu_data_scaled_pressure_t *value,
                                                       uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MSCIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mscipc_status_t mscipc_imu_data_scaled_pressure_decode(const uint8_t *data, size_t len,
                                                       mscipc_imu_data_scaled_pressure_t *out,
                                                       mscipc_decode_error_t *err);

/* ---- scaled_temperature (data): Scaled temperature */
#define MSCIPC_IMU_DATA_SCALED_TEMPERATURE_DESCRIPTOR 0x87

/** Scaled temperature. IMU temperature in degrees Celsius. */
typedef struct {
    float temperature; /* Temperature. [degC] */
} mscipc_imu_data_scaled_temperature_t;

/* Largest encoded data (after the field header). */
#define MSCIPC_IMU_DATA_SCALED_TEMPERATURE_MAX_SIZE 4

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mscipc_status_t mscipc_imu_data_scaled_temperature_encode(const mscipc_imu_data_scaled_temperature_t *value,
                                                          uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MSCIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mscipc_status_t mscipc_imu_data_scaled_temperature_decode(const uint8_t *data, size_t len,
                                                          mscipc_imu_data_scaled_temperature_t *out,
                                                          mscipc_decode_error_t *err);

/* ---- gps_correlated_time (data): GPS correlated time */
#define MSCIPC_IMU_DATA_GPS_CORRELATED_TIME_DESCRIPTOR 0x88

/** GPS correlated time. GPS time of the sample: seconds of the week (precision follows the output rate, 5 ms
 * at 200 Hz), week number, and the correlation flags. */
typedef struct {
    double seconds;                /* GPS seconds of the week. [s] */
    uint16_t week;                 /* GPS week number. [weeks] */
    mscipc_gps_time_flags_t flags; /* GPS correlated time flags. */
} mscipc_imu_data_gps_correlated_time_t;

/* Largest encoded data (after the field header). */
#define MSCIPC_IMU_DATA_GPS_CORRELATED_TIME_MAX_SIZE 12

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mscipc_status_t mscipc_imu_data_gps_correlated_time_encode(const mscipc_imu_data_gps_correlated_time_t *value,
                                                           uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MSCIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mscipc_status_t mscipc_imu_data_gps_correlated_time_decode(const uint8_t *data, size_t len,
                                                           mscipc_imu_data_gps_correlated_time_t *out,
                                                           mscipc_decode_error_t *err);

/* ---- scaled_aux_accel (data): Scaled aux accel vector */
#define MSCIPC_IMU_DATA_SCALED_AUX_ACCEL_DESCRIPTOR 0x89

/** Scaled aux accel vector. X, Y and Z acceleration of the auxiliary accelerometer in g. */
typedef struct {
    float accel[3]; /* Auxiliary acceleration [x, y, z]. [g] */
} mscipc_imu_data_scaled_aux_accel_t;

/* Largest encoded data (after the field header). */
#define MSCIPC_IMU_DATA_SCALED_AUX_ACCEL_MAX_SIZE 12

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mscipc_status_t mscipc_imu_data_scaled_aux_accel_encode(const mscipc_imu_data_scaled_aux_accel_t *value,
                                                        uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MSCIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mscipc_status_t mscipc_imu_data_scaled_aux_accel_decode(const uint8_t *data, size_t len,
                                                        mscipc_imu_data_scaled_aux_accel_t *out,
                                                        mscipc_decode_error_t *err);

/**
 * The fields of one packet of this set, decoded in place by mscipc_imu_data_decode_packet: one member per
 * field the set defines with a single layout (its own, the reserved fields of its kind and the
 * shared data fields); `index` says which members hold a field of the packet, in packet order.
 */
typedef struct {
    mscipc_packet_index_t index;
    mscipc_imu_data_scaled_accel_t imu_data_scaled_accel;               /* 0x81 */
    mscipc_imu_data_scaled_gyro_t imu_data_scaled_gyro;                 /* 0x82 */
    mscipc_imu_data_scaled_mag_t imu_data_scaled_mag;                   /* 0x83 */
    mscipc_imu_data_delta_theta_t imu_data_delta_theta;                 /* 0x84 */
    mscipc_imu_data_delta_velocity_t imu_data_delta_velocity;           /* 0x85 */
    mscipc_imu_data_scaled_pressure_t imu_data_scaled_pressure;         /* 0x86 */
    mscipc_imu_data_scaled_temperature_t imu_data_scaled_temperature;   /* 0x87 */
    mscipc_imu_data_gps_correlated_time_t imu_data_gps_correlated_time; /* 0x88 */
    mscipc_imu_data_scaled_aux_accel_t imu_data_scaled_aux_accel;       /* 0x89 */
} mscipc_imu_data_packet_t;

/**
 * The straight-line decoder of a packet of this set (issue 38): walks the fields of the payload
 * (len bytes at payload) with a switch on the descriptor and decodes each field's layout into its
 * member of *out, giving the value mscipc_decode_field gives; no general value, no indirect call. Every
 * other entry goes to other (may be NULL: they are dropped) with ctx, in packet order with the
 * fields: a descriptor without a member (undefined, or a field with per-device variants), a field
 * that does not decode (its member is then unspecified), a second field with a descriptor already
 * decoded, trailing bytes. Returns out->index.count, the number of fields decoded into members.
 */
size_t mscipc_imu_data_decode_packet(const uint8_t *payload, size_t len, mscipc_imu_data_packet_t *out,
                                     mscipc_field_entry_fn other, void *ctx);

/* Private (mscipc_decode_packet_cached): the members of mscipc_imu_data_packet_t: descriptor, offset,
 * loader. */
extern const mscipc_layout_member_t mscipc_imu_data_layout_members_[9];

#ifdef __cplusplus
}
#endif

#endif
