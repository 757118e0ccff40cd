/* Sensor (IMU) Data Set (descriptor set 0x80): one struct per field layout, with its
 * encoder and decoder. Generated from the spec: do not edit. */
#ifndef MIP_SETS_SENSOR_H
#define MIP_SETS_SENSOR_H

#include "mipcodec/types.h"

#ifdef __cplusplus
extern "C" {
#endif

#define MIP_SENSOR_SET 0x80

/* ---- scaled_accel (data): Scaled accelerometer vector */
#define MIP_SENSOR_SCALED_ACCEL_DESCRIPTOR 0x04

/** Scaled accelerometer vector. Sensed acceleration, temperature compensated, in g (1 g = 9.80665 m/s^2), X,
 * Y, Z in the sensor (GX5-45) or vehicle (CV7) frame. */
typedef struct {
    float scaled_accel[3]; /* (x, y, z) acceleration. [g] */
} mip_sensor_scaled_accel_t;

/* Largest encoded data (after the field header). */
#define MIP_SENSOR_SCALED_ACCEL_MAX_SIZE 12

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mip_status_t mip_sensor_scaled_accel_encode(const mip_sensor_scaled_accel_t *value, uint8_t *buf, size_t cap,
                                            size_t *len_out);
/** Decodes field data; on MIP_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mip_status_t mip_sensor_scaled_accel_decode(const uint8_t *data, size_t len, mip_sensor_scaled_accel_t *out,
                                            mip_decode_error_t *err);

/* ---- scaled_gyro (data): Scaled gyro vector */
#define MIP_SENSOR_SCALED_GYRO_DESCRIPTOR 0x05

/** Scaled gyro vector. Sensed angular rate, temperature compensated, in radians/second, X, Y, Z. */
typedef struct {
    float scaled_gyro[3]; /* (x, y, z) angular rate. [rad/s] */
} mip_sensor_scaled_gyro_t;

/* Largest encoded data (after the field header). */
#define MIP_SENSOR_SCALED_GYRO_MAX_SIZE 12

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mip_status_t mip_sensor_scaled_gyro_encode(const mip_sensor_scaled_gyro_t *value, uint8_t *buf, size_t cap,
                                           size_t *len_out);
/** Decodes field data; on MIP_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mip_status_t mip_sensor_scaled_gyro_decode(const uint8_t *data, size_t len, mip_sensor_scaled_gyro_t *out,
                                           mip_decode_error_t *err);

/* ---- scaled_mag (data): Scaled magnetometer vector */
#define MIP_SENSOR_SCALED_MAG_DESCRIPTOR 0x06

/** Scaled magnetometer vector. Sensed magnetic field, temperature compensated, in Gauss, X, Y, Z. */
typedef struct {
    float scaled_mag[3]; /* (x, y, z) magnetic field. [gauss] */
} mip_sensor_scaled_mag_t;

/* Largest encoded data (after the field header). */
#define MIP_SENSOR_SCALED_MAG_MAX_SIZE 12

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mip_status_t mip_sensor_scaled_mag_encode(const mip_sensor_scaled_mag_t *value, uint8_t *buf, size_t cap,
                                          size_t *len_out);
/** Decodes field data; on MIP_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mip_status_t mip_sensor_scaled_mag_decode(const uint8_t *data, size_t len, mip_sensor_scaled_mag_t *out,
                                          mip_decode_error_t *err);

#ifdef __cplusplus
}
#endif

#endif
