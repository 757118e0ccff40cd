/* Encoders and decoders of Sensor (IMU) Data Set. Generated from the spec: do not edit. */
#include "mipcodec/sets/sensor.h"
#include "layouts_internal.h"
#include "types_internal.h"

#include <assert.h>
#include <stddef.h>
#include <string.h>

/* ---- mipc_sensor_scaled_accel_t */

static int mipc_sensor_scaled_accel_read(mipc_reader_t *r, mipc_sensor_scaled_accel_t *out) {
    size_t i;
    mipc_rd_push(r, "scaled_accel");
    for (i = 0; i < 3; i++) {
        mipc_rd_index(r, i);
        if (mipc_rd_f32(r, &out->scaled_accel[i])) {
            return -1;
        }
    }
    mipc_rd_pop(r);
    return mipc_rd_finish(r);
}

static mipc_status_t mipc_sensor_scaled_accel_write(mipc_writer_t *w, const mipc_sensor_scaled_accel_t *in) {
    mipc_status_t st;
    size_t i;
    for (i = 0; i < 3; i++) {
        if ((st = mipc_wr_f32(w, &in->scaled_accel[i])) != MIPC_OK) {
            return st;
        }
    }
    return MIPC_OK;
}

mipc_status_t mipc_sensor_scaled_accel_encode(const mipc_sensor_scaled_accel_t *value, uint8_t *buf,
                                              size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mipc_writer_init(&w, buf, cap);
    st = mipc_sensor_scaled_accel_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 12 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mipc_sensor_scaled_accel_load(const uint8_t *d, mipc_sensor_scaled_accel_t *out) {
    out->scaled_accel[0] = mipc_ld_f32(d + 0);
    out->scaled_accel[1] = mipc_ld_f32(d + 4);
    out->scaled_accel[2] = mipc_ld_f32(d + 8);
    return 0;
}

/* The general reader: lengths other than 12, bad bool bytes, error details. */
static MIPC_NOINLINE mipc_status_t mipc_sensor_scaled_accel_decode_read(const uint8_t *data, size_t len,
                                                                        mipc_sensor_scaled_accel_t *out,
                                                                        mipc_decode_error_t *err) {
    mipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_sensor_scaled_accel_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t mipc_sensor_scaled_accel_decode(const uint8_t *data, size_t len,
                                              mipc_sensor_scaled_accel_t *out, mipc_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 12 && mipc_sensor_scaled_accel_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_sensor_scaled_accel_decode_read(data, len, out, err);
}

/* ---- mipc_sensor_scaled_gyro_t */

static int mipc_sensor_scaled_gyro_read(mipc_reader_t *r, mipc_sensor_scaled_gyro_t *out) {
    size_t i;
    mipc_rd_push(r, "scaled_gyro");
    for (i = 0; i < 3; i++) {
        mipc_rd_index(r, i);
        if (mipc_rd_f32(r, &out->scaled_gyro[i])) {
            return -1;
        }
    }
    mipc_rd_pop(r);
    return mipc_rd_finish(r);
}

static mipc_status_t mipc_sensor_scaled_gyro_write(mipc_writer_t *w, const mipc_sensor_scaled_gyro_t *in) {
    mipc_status_t st;
    size_t i;
    for (i = 0; i < 3; i++) {
        if ((st = mipc_wr_f32(w, &in->scaled_gyro[i])) != MIPC_OK) {
            return st;
        }
    }
    return MIPC_OK;
}

mipc_status_t mipc_sensor_scaled_gyro_encode(const mipc_sensor_scaled_gyro_t *value, uint8_t *buf, size_t cap,
                                             size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mipc_writer_init(&w, buf, cap);
    st = mipc_sensor_scaled_gyro_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 12 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mipc_sensor_scaled_gyro_load(const uint8_t *d, mipc_sensor_scaled_gyro_t *out) {
    out->scaled_gyro[0] = mipc_ld_f32(d + 0);
    out->scaled_gyro[1] = mipc_ld_f32(d + 4);
    out->scaled_gyro[2] = mipc_ld_f32(d + 8);
    return 0;
}

/* The general reader: lengths other than 12, bad bool bytes, error details. */
static MIPC_NOINLINE mipc_status_t mipc_sensor_scaled_gyro_decode_read(const uint8_t *data, size_t len,
                                                                       mipc_sensor_scaled_gyro_t *out,
                                                                       mipc_decode_error_t *err) {
    mipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_sensor_scaled_gyro_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t mipc_sensor_scaled_gyro_decode(const uint8_t *data, size_t len, mipc_sensor_scaled_gyro_t *out,
                                             mipc_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 12 && mipc_sensor_scaled_gyro_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_sensor_scaled_gyro_decode_read(data, len, out, err);
}

/* ---- mipc_sensor_scaled_mag_t */

static int mipc_sensor_scaled_mag_read(mipc_reader_t *r, mipc_sensor_scaled_mag_t *out) {
    size_t i;
    mipc_rd_push(r, "scaled_mag");
    for (i = 0; i < 3; i++) {
        mipc_rd_index(r, i);
        if (mipc_rd_f32(r, &out->scaled_mag[i])) {
            return -1;
        }
    }
    mipc_rd_pop(r);
    return mipc_rd_finish(r);
}

static mipc_status_t mipc_sensor_scaled_mag_write(mipc_writer_t *w, const mipc_sensor_scaled_mag_t *in) {
    mipc_status_t st;
    size_t i;
    for (i = 0; i < 3; i++) {
        if ((st = mipc_wr_f32(w, &in->scaled_mag[i])) != MIPC_OK) {
            return st;
        }
    }
    return MIPC_OK;
}

mipc_status_t mipc_sensor_scaled_mag_encode(const mipc_sensor_scaled_mag_t *value, uint8_t *buf, size_t cap,
                                            size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mipc_writer_init(&w, buf, cap);
    st = mipc_sensor_scaled_mag_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 12 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mipc_sensor_scaled_mag_load(const uint8_t *d, mipc_sensor_scaled_mag_t *out) {
    out->scaled_mag[0] = mipc_ld_f32(d + 0);
    out->scaled_mag[1] = mipc_ld_f32(d + 4);
    out->scaled_mag[2] = mipc_ld_f32(d + 8);
    return 0;
}

/* The general reader: lengths other than 12, bad bool bytes, error details. */
static MIPC_NOINLINE mipc_status_t mipc_sensor_scaled_mag_decode_read(const uint8_t *data, size_t len,
                                                                      mipc_sensor_scaled_mag_t *out,
                                                                      mipc_decode_error_t *err) {
    mipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_sensor_scaled_mag_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t mipc_sensor_scaled_mag_decode(const uint8_t *data, size_t len, mipc_sensor_scaled_mag_t *out,
                                            mipc_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 12 && mipc_sensor_scaled_mag_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_sensor_scaled_mag_decode_read(data, len, out, err);
}

/* ---- mipc_sensor_delta_theta_t */

static int mipc_sensor_delta_theta_read(mipc_reader_t *r, mipc_sensor_delta_theta_t *out) {
    size_t i;
    mipc_rd_push(r, "delta_theta");
    for (i = 0; i < 3; i++) {
        mipc_rd_index(r, i);
        if (mipc_rd_f32(r, &out->delta_theta[i])) {
            return -1;
        }
    }
    mipc_rd_pop(r);
    return mipc_rd_finish(r);
}

static mipc_status_t mipc_sensor_delta_theta_write(mipc_writer_t *w, const mipc_sensor_delta_theta_t *in) {
    mipc_status_t st;
    size_t i;
    for (i = 0; i < 3; i++) {
        if ((st = mipc_wr_f32(w, &in->delta_theta[i])) != MIPC_OK) {
            return st;
        }
    }
    return MIPC_OK;
}

mipc_status_t mipc_sensor_delta_theta_encode(const mipc_sensor_delta_theta_t *value, uint8_t *buf, size_t cap,
                                             size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mipc_writer_init(&w, buf, cap);
    st = mipc_sensor_delta_theta_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 12 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mipc_sensor_delta_theta_load(const uint8_t *d, mipc_sensor_delta_theta_t *out) {
    out->delta_theta[0] = mipc_ld_f32(d + 0);
    out->delta_theta[1] = mipc_ld_f32(d + 4);
    out->delta_theta[2] = mipc_ld_f32(d + 8);
    return 0;
}

/* The general reader: lengths other than 12, bad bool bytes, error details. */
static MIPC_NOINLINE mipc_status_t mipc_sensor_delta_theta_decode_read(const uint8_t *data, size_t len,
                                                                       mipc_sensor_delta_theta_t *out,
                                                                       mipc_decode_error_t *err) {
    mipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_sensor_delta_theta_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t mipc_sensor_delta_theta_decode(const uint8_t *data, size_t len, mipc_sensor_delta_theta_t *out,
                                             mipc_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 12 && mipc_sensor_delta_theta_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_sensor_delta_theta_decode_read(data, len, out, err);
}

/* ---- mipc_sensor_delta_velocity_t */

static int mipc_sensor_delta_velocity_read(mipc_reader_t *r, mipc_sensor_delta_velocity_t *out) {
    size_t i;
    mipc_rd_push(r, "delta_velocity");
    for (i = 0; i < 3; i++) {
        mipc_rd_index(r, i);
        if (mipc_rd_f32(r, &out->delta_velocity[i])) {
            return -1;
        }
    }
    mipc_rd_pop(r);
    return mipc_rd_finish(r);
}

static mipc_status_t mipc_sensor_delta_velocity_write(mipc_writer_t *w,
                                                      const mipc_sensor_delta_velocity_t *in) {
    mipc_status_t st;
    size_t i;
    for (i = 0; i < 3; i++) {
        if ((st = mipc_wr_f32(w, &in->delta_velocity[i])) != MIPC_OK) {
            return st;
        }
    }
    return MIPC_OK;
}

mipc_status_t mipc_sensor_delta_velocity_encode(const mipc_sensor_delta_velocity_t *value, uint8_t *buf,
                                                size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mipc_writer_init(&w, buf, cap);
    st = mipc_sensor_delta_velocity_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 12 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mipc_sensor_delta_velocity_load(const uint8_t *d, mipc_sensor_delta_velocity_t *out) {
    out->delta_velocity[0] = mipc_ld_f32(d + 0);
    out->delta_velocity[1] = mipc_ld_f32(d + 4);
    out->delta_velocity[2] = mipc_ld_f32(d + 8);
    return 0;
}

/* The general reader: lengths other than 12, bad bool bytes, error details. */
static MIPC_NOINLINE mipc_status_t mipc_sensor_delta_velocity_decode_read(const uint8_t *data, size_t len,
                                                                          mipc_sensor_delta_velocity_t *out,
                                                                          mipc_decode_error_t *err) {
    mipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_sensor_delta_velocity_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t mipc_sensor_delta_velocity_decode(const uint8_t *data, size_t len,
                                                mipc_sensor_delta_velocity_t *out, mipc_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 12 && mipc_sensor_delta_velocity_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_sensor_delta_velocity_decode_read(data, len, out, err);
}

/* ---- mipc_sensor_cf_orientation_matrix_t */

static int mipc_sensor_cf_orientation_matrix_read(mipc_reader_t *r,
                                                  mipc_sensor_cf_orientation_matrix_t *out) {
    size_t i;
    mipc_rd_push(r, "m");
    for (i = 0; i < 9; i++) {
        mipc_rd_index(r, i);
        if (mipc_rd_f32(r, &out->m[i])) {
            return -1;
        }
    }
    mipc_rd_pop(r);
    return mipc_rd_finish(r);
}

static mipc_status_t mipc_sensor_cf_orientation_matrix_write(mipc_writer_t *w,
                                                             const mipc_sensor_cf_orientation_matrix_t *in) {
    mipc_status_t st;
    size_t i;
    for (i = 0; i < 9; i++) {
        if ((st = mipc_wr_f32(w, &in->m[i])) != MIPC_OK) {
            return st;
        }
    }
    return MIPC_OK;
}

mipc_status_t mipc_sensor_cf_orientation_matrix_encode(const mipc_sensor_cf_orientation_matrix_t *value,
                                                       uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mipc_writer_init(&w, buf, cap);
    st = mipc_sensor_cf_orientation_matrix_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 36 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mipc_sensor_cf_orientation_matrix_load(const uint8_t *d,
                                                  mipc_sensor_cf_orientation_matrix_t *out) {
    out->m[0] = mipc_ld_f32(d + 0);
    out->m[1] = mipc_ld_f32(d + 4);
    out->m[2] = mipc_ld_f32(d + 8);
    out->m[3] = mipc_ld_f32(d + 12);
    out->m[4] = mipc_ld_f32(d + 16);
    out->m[5] = mipc_ld_f32(d + 20);
    out->m[6] = mipc_ld_f32(d + 24);
    out->m[7] = mipc_ld_f32(d + 28);
    out->m[8] = mipc_ld_f32(d + 32);
    return 0;
}

/* The general reader: lengths other than 36, bad bool bytes, error details. */
static MIPC_NOINLINE mipc_status_t mipc_sensor_cf_orientation_matrix_decode_read(
    const uint8_t *data, size_t len, mipc_sensor_cf_orientation_matrix_t *out, mipc_decode_error_t *err) {
    mipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_sensor_cf_orientation_matrix_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t mipc_sensor_cf_orientation_matrix_decode(const uint8_t *data, size_t len,
                                                       mipc_sensor_cf_orientation_matrix_t *out,
                                                       mipc_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 36 && mipc_sensor_cf_orientation_matrix_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_sensor_cf_orientation_matrix_decode_read(data, len, out, err);
}

/* ---- mipc_sensor_cf_quaternion_t */

static int mipc_sensor_cf_quaternion_read(mipc_reader_t *r, mipc_sensor_cf_quaternion_t *out) {
    size_t i;
    mipc_rd_push(r, "q");
    for (i = 0; i < 4; i++) {
        mipc_rd_index(r, i);
        if (mipc_rd_f32(r, &out->q[i])) {
            return -1;
        }
    }
    mipc_rd_pop(r);
    return mipc_rd_finish(r);
}

static mipc_status_t mipc_sensor_cf_quaternion_write(mipc_writer_t *w,
                                                     const mipc_sensor_cf_quaternion_t *in) {
    mipc_status_t st;
    size_t i;
    for (i = 0; i < 4; i++) {
        if ((st = mipc_wr_f32(w, &in->q[i])) != MIPC_OK) {
            return st;
        }
    }
    return MIPC_OK;
}

mipc_status_t mipc_sensor_cf_quaternion_encode(const mipc_sensor_cf_quaternion_t *value, uint8_t *buf,
                                               size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mipc_writer_init(&w, buf, cap);
    st = mipc_sensor_cf_quaternion_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 16 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mipc_sensor_cf_quaternion_load(const uint8_t *d, mipc_sensor_cf_quaternion_t *out) {
    out->q[0] = mipc_ld_f32(d + 0);
    out->q[1] = mipc_ld_f32(d + 4);
    out->q[2] = mipc_ld_f32(d + 8);
    out->q[3] = mipc_ld_f32(d + 12);
    return 0;
}

/* The general reader: lengths other than 16, bad bool bytes, error details. */
static MIPC_NOINLINE mipc_status_t mipc_sensor_cf_quaternion_decode_read(const uint8_t *data, size_t len,
                                                                         mipc_sensor_cf_quaternion_t *out,
                                                                         mipc_decode_error_t *err) {
    mipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_sensor_cf_quaternion_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t mipc_sensor_cf_quaternion_decode(const uint8_t *data, size_t len,
                                               mipc_sensor_cf_quaternion_t *out, mipc_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 16 && mipc_sensor_cf_quaternion_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_sensor_cf_quaternion_decode_read(data, len, out, err);
}

/* ---- mipc_sensor_cf_euler_angles_t */

static int mipc_sensor_cf_euler_angles_read(mipc_reader_t *r, mipc_sensor_cf_euler_angles_t *out) {
    mipc_rd_push(r, "roll");
    if (mipc_rd_f32(r, &out->roll)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "pitch");
    if (mipc_rd_f32(r, &out->pitch)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "yaw");
    if (mipc_rd_f32(r, &out->yaw)) {
        return -1;
    }
    mipc_rd_pop(r);
    return mipc_rd_finish(r);
}

static mipc_status_t mipc_sensor_cf_euler_angles_write(mipc_writer_t *w,
                                                       const mipc_sensor_cf_euler_angles_t *in) {
    mipc_status_t st;
    if ((st = mipc_wr_f32(w, &in->roll)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_f32(w, &in->pitch)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_f32(w, &in->yaw)) != MIPC_OK) {
        return st;
    }
    return MIPC_OK;
}

mipc_status_t mipc_sensor_cf_euler_angles_encode(const mipc_sensor_cf_euler_angles_t *value, uint8_t *buf,
                                                 size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mipc_writer_init(&w, buf, cap);
    st = mipc_sensor_cf_euler_angles_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 12 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mipc_sensor_cf_euler_angles_load(const uint8_t *d, mipc_sensor_cf_euler_angles_t *out) {
    out->roll = mipc_ld_f32(d + 0);
    out->pitch = mipc_ld_f32(d + 4);
    out->yaw = mipc_ld_f32(d + 8);
    return 0;
}

/* The general reader: lengths other than 12, bad bool bytes, error details. */
static MIPC_NOINLINE mipc_status_t mipc_sensor_cf_euler_angles_decode_read(const uint8_t *data, size_t len,
                                                                           mipc_sensor_cf_euler_angles_t *out,
                                                                           mipc_decode_error_t *err) {
    mipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_sensor_cf_euler_angles_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t mipc_sensor_cf_euler_angles_decode(const uint8_t *data, size_t len,
                                                 mipc_sensor_cf_euler_angles_t *out,
                                                 mipc_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 12 && mipc_sensor_cf_euler_angles_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_sensor_cf_euler_angles_decode_read(data, len, out, err);
}

/* ---- mipc_sensor_cf_stabilized_north_t */

static int mipc_sensor_cf_stabilized_north_read(mipc_reader_t *r, mipc_sensor_cf_stabilized_north_t *out) {
    size_t i;
    mipc_rd_push(r, "stabilized_north");
    for (i = 0; i < 3; i++) {
        mipc_rd_index(r, i);
        if (mipc_rd_f32(r, &out->stabilized_north[i])) {
            return -1;
        }
    }
    mipc_rd_pop(r);
    return mipc_rd_finish(r);
}

static mipc_status_t mipc_sensor_cf_stabilized_north_write(mipc_writer_t *w,
                                                           const mipc_sensor_cf_stabilized_north_t *in) {
    mipc_status_t st;
    size_t i;
    for (i = 0; i < 3; i++) {
        if ((st = mipc_wr_f32(w, &in->stabilized_north[i])) != MIPC_OK) {
            return st;
        }
    }
    return MIPC_OK;
}

mipc_status_t mipc_sensor_cf_stabilized_north_encode(const mipc_sensor_cf_stabilized_north_t *value,
                                                     uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mipc_writer_init(&w, buf, cap);
    st = mipc_sensor_cf_stabilized_north_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 12 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mipc_sensor_cf_stabilized_north_load(const uint8_t *d, mipc_sensor_cf_stabilized_north_t *out) {
    out->stabilized_north[0] = mipc_ld_f32(d + 0);
    out->stabilized_north[1] = mipc_ld_f32(d + 4);
    out->stabilized_north[2] = mipc_ld_f32(d + 8);
    return 0;
}

/* The general reader: lengths other than 12, bad bool bytes, error details. */
static MIPC_NOINLINE mipc_status_t mipc_sensor_cf_stabilized_north_decode_read(
    const uint8_t *data, size_t len, mipc_sensor_cf_stabilized_north_t *out, mipc_decode_error_t *err) {
    mipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_sensor_cf_stabilized_north_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t mipc_sensor_cf_stabilized_north_decode(const uint8_t *data, size_t len,
                                                     mipc_sensor_cf_stabilized_north_t *out,
                                                     mipc_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 12 && mipc_sensor_cf_stabilized_north_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_sensor_cf_stabilized_north_decode_read(data, len, out, err);
}

/* ---- mipc_sensor_cf_stabilized_up_t */

static int mipc_sensor_cf_stabilized_up_read(mipc_reader_t *r, mipc_sensor_cf_stabilized_up_t *out) {
    size_t i;
    mipc_rd_push(r, "stabilized_up");
    for (i = 0; i < 3; i++) {
        mipc_rd_index(r, i);
        if (mipc_rd_f32(r, &out->stabilized_up[i])) {
            return -1;
        }
    }
    mipc_rd_pop(r);
    return mipc_rd_finish(r);
}

static mipc_status_t mipc_sensor_cf_stabilized_up_write(mipc_writer_t *w,
                                                        const mipc_sensor_cf_stabilized_up_t *in) {
    mipc_status_t st;
    size_t i;
    for (i = 0; i < 3; i++) {
        if ((st = mipc_wr_f32(w, &in->stabilized_up[i])) != MIPC_OK) {
            return st;
        }
    }
    return MIPC_OK;
}

mipc_status_t mipc_sensor_cf_stabilized_up_encode(const mipc_sensor_cf_stabilized_up_t *value, uint8_t *buf,
                                                  size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mipc_writer_init(&w, buf, cap);
    st = mipc_sensor_cf_stabilized_up_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 12 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mipc_sensor_cf_stabilized_up_load(const uint8_t *d, mipc_sensor_cf_stabilized_up_t *out) {
    out->stabilized_up[0] = mipc_ld_f32(d + 0);
    out->stabilized_up[1] = mipc_ld_f32(d + 4);
    out->stabilized_up[2] = mipc_ld_f32(d + 8);
    return 0;
}

/* The general reader: lengths other than 12, bad bool bytes, error details. */
static MIPC_NOINLINE mipc_status_t mipc_sensor_cf_stabilized_up_decode_read(
    const uint8_t *data, size_t len, mipc_sensor_cf_stabilized_up_t *out, mipc_decode_error_t *err) {
    mipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_sensor_cf_stabilized_up_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t mipc_sensor_cf_stabilized_up_decode(const uint8_t *data, size_t len,
                                                  mipc_sensor_cf_stabilized_up_t *out,
                                                  mipc_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 12 && mipc_sensor_cf_stabilized_up_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_sensor_cf_stabilized_up_decode_read(data, len, out, err);
}

/* ---- mipc_sensor_gps_timestamp_t */

static int mipc_sensor_gps_timestamp_read(mipc_reader_t *r, mipc_sensor_gps_timestamp_t *out) {
    mipc_rd_push(r, "tow");
    if (mipc_rd_f64(r, &out->tow)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "week_number");
    if (mipc_rd_u16(r, &out->week_number)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "valid_flags");
    if (mipc_rd_u16(r, &out->valid_flags)) {
        return -1;
    }
    mipc_rd_pop(r);
    return mipc_rd_finish(r);
}

static mipc_status_t mipc_sensor_gps_timestamp_write(mipc_writer_t *w,
                                                     const mipc_sensor_gps_timestamp_t *in) {
    mipc_status_t st;
    if ((st = mipc_wr_f64(w, &in->tow)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u16(w, &in->week_number)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u16(w, &in->valid_flags)) != MIPC_OK) {
        return st;
    }
    return MIPC_OK;
}

mipc_status_t mipc_sensor_gps_timestamp_encode(const mipc_sensor_gps_timestamp_t *value, uint8_t *buf,
                                               size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mipc_writer_init(&w, buf, cap);
    st = mipc_sensor_gps_timestamp_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 12 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mipc_sensor_gps_timestamp_load(const uint8_t *d, mipc_sensor_gps_timestamp_t *out) {
    out->tow = mipc_ld_f64(d + 0);
    out->week_number = mipc_ld_u16(d + 8);
    out->valid_flags = mipc_ld_u16(d + 10);
    return 0;
}

/* The general reader: lengths other than 12, bad bool bytes, error details. */
static MIPC_NOINLINE mipc_status_t mipc_sensor_gps_timestamp_decode_read(const uint8_t *data, size_t len,
                                                                         mipc_sensor_gps_timestamp_t *out,
                                                                         mipc_decode_error_t *err) {
    mipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_sensor_gps_timestamp_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t mipc_sensor_gps_timestamp_decode(const uint8_t *data, size_t len,
                                               mipc_sensor_gps_timestamp_t *out, mipc_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 12 && mipc_sensor_gps_timestamp_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_sensor_gps_timestamp_decode_read(data, len, out, err);
}

/* ---- mipc_sensor_temperature_statistics_t */

static int mipc_sensor_temperature_statistics_read(mipc_reader_t *r,
                                                   mipc_sensor_temperature_statistics_t *out) {
    mipc_rd_push(r, "min_temp");
    if (mipc_rd_f32(r, &out->min_temp)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "max_temp");
    if (mipc_rd_f32(r, &out->max_temp)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "mean_temp");
    if (mipc_rd_f32(r, &out->mean_temp)) {
        return -1;
    }
    mipc_rd_pop(r);
    return mipc_rd_finish(r);
}

static mipc_status_t
mipc_sensor_temperature_statistics_write(mipc_writer_t *w, const mipc_sensor_temperature_statistics_t *in) {
    mipc_status_t st;
    if ((st = mipc_wr_f32(w, &in->min_temp)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_f32(w, &in->max_temp)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_f32(w, &in->mean_temp)) != MIPC_OK) {
        return st;
    }
    return MIPC_OK;
}

mipc_status_t mipc_sensor_temperature_statistics_encode(const mipc_sensor_temperature_statistics_t *value,
                                                        uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mipc_writer_init(&w, buf, cap);
    st = mipc_sensor_temperature_statistics_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 12 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mipc_sensor_temperature_statistics_load(const uint8_t *d,
                                                   mipc_sensor_temperature_statistics_t *out) {
    out->min_temp = mipc_ld_f32(d + 0);
    out->max_temp = mipc_ld_f32(d + 4);
    out->mean_temp = mipc_ld_f32(d + 8);
    return 0;
}

/* The general reader: lengths other than 12, bad bool bytes, error details. */
static MIPC_NOINLINE mipc_status_t mipc_sensor_temperature_statistics_decode_read(
    const uint8_t *data, size_t len, mipc_sensor_temperature_statistics_t *out, mipc_decode_error_t *err) {
    mipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_sensor_temperature_statistics_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t mipc_sensor_temperature_statistics_decode(const uint8_t *data, size_t len,
                                                        mipc_sensor_temperature_statistics_t *out,
                                                        mipc_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 12 && mipc_sensor_temperature_statistics_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_sensor_temperature_statistics_decode_read(data, len, out, err);
}

/* ---- mipc_sensor_scaled_pressure_t */

static int mipc_sensor_scaled_pressure_read(mipc_reader_t *r, mipc_sensor_scaled_pressure_t *out) {
    mipc_rd_push(r, "scaled_pressure");
    if (mipc_rd_f32(r, &out->scaled_pressure)) {
        return -1;
    }
    mipc_rd_pop(r);
    return mipc_rd_finish(r);
}

static mipc_status_t mipc_sensor_scaled_pressure_write(mipc_writer_t *w,
                                                       const mipc_sensor_scaled_pressure_t *in) {
    mipc_status_t st;
    if ((st = mipc_wr_f32(w, &in->scaled_pressure)) != MIPC_OK) {
        return st;
    }
    return MIPC_OK;
}

mipc_status_t mipc_sensor_scaled_pressure_encode(const mipc_sensor_scaled_pressure_t *value, uint8_t *buf,
                                                 size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mipc_writer_init(&w, buf, cap);
    st = mipc_sensor_scaled_pressure_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 4 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mipc_sensor_scaled_pressure_load(const uint8_t *d, mipc_sensor_scaled_pressure_t *out) {
    out->scaled_pressure = mipc_ld_f32(d + 0);
    return 0;
}

/* The general reader: lengths other than 4, bad bool bytes, error details. */
static MIPC_NOINLINE mipc_status_t mipc_sensor_scaled_pressure_decode_read(const uint8_t *data, size_t len,
                                                                           mipc_sensor_scaled_pressure_t *out,
                                                                           mipc_decode_error_t *err) {
    mipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_sensor_scaled_pressure_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t mipc_sensor_scaled_pressure_decode(const uint8_t *data, size_t len,
                                                 mipc_sensor_scaled_pressure_t *out,
                                                 mipc_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 4 && mipc_sensor_scaled_pressure_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_sensor_scaled_pressure_decode_read(data, len, out, err);
}

/* ---- mipc_sensor_overrange_status_t */

static int mipc_sensor_overrange_status_read(mipc_reader_t *r, mipc_sensor_overrange_status_t *out) {
    mipc_rd_push(r, "status");
    if (mipc_rd_u16(r, &out->status)) {
        return -1;
    }
    mipc_rd_pop(r);
    return mipc_rd_finish(r);
}

static mipc_status_t mipc_sensor_overrange_status_write(mipc_writer_t *w,
                                                        const mipc_sensor_overrange_status_t *in) {
    mipc_status_t st;
    if ((st = mipc_wr_u16(w, &in->status)) != MIPC_OK) {
        return st;
    }
    return MIPC_OK;
}

mipc_status_t mipc_sensor_overrange_status_encode(const mipc_sensor_overrange_status_t *value, uint8_t *buf,
                                                  size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mipc_writer_init(&w, buf, cap);
    st = mipc_sensor_overrange_status_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 2 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mipc_sensor_overrange_status_load(const uint8_t *d, mipc_sensor_overrange_status_t *out) {
    out->status = mipc_ld_u16(d + 0);
    return 0;
}

/* The general reader: lengths other than 2, bad bool bytes, error details. */
static MIPC_NOINLINE mipc_status_t mipc_sensor_overrange_status_decode_read(
    const uint8_t *data, size_t len, mipc_sensor_overrange_status_t *out, mipc_decode_error_t *err) {
    mipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_sensor_overrange_status_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t mipc_sensor_overrange_status_decode(const uint8_t *data, size_t len,
                                                  mipc_sensor_overrange_status_t *out,
                                                  mipc_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 2 && mipc_sensor_overrange_status_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_sensor_overrange_status_decode_read(data, len, out, err);
}

/* ---- mipc_sensor_odometer_data_t */

static int mipc_sensor_odometer_data_read(mipc_reader_t *r, mipc_sensor_odometer_data_t *out) {
    mipc_rd_push(r, "speed");
    if (mipc_rd_f32(r, &out->speed)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "uncertainty");
    if (mipc_rd_f32(r, &out->uncertainty)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "valid_flags");
    if (mipc_rd_u16(r, &out->valid_flags)) {
        return -1;
    }
    mipc_rd_pop(r);
    return mipc_rd_finish(r);
}

static mipc_status_t mipc_sensor_odometer_data_write(mipc_writer_t *w,
                                                     const mipc_sensor_odometer_data_t *in) {
    mipc_status_t st;
    if ((st = mipc_wr_f32(w, &in->speed)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_f32(w, &in->uncertainty)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u16(w, &in->valid_flags)) != MIPC_OK) {
        return st;
    }
    return MIPC_OK;
}

mipc_status_t mipc_sensor_odometer_data_encode(const mipc_sensor_odometer_data_t *value, uint8_t *buf,
                                               size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mipc_writer_init(&w, buf, cap);
    st = mipc_sensor_odometer_data_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 10 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mipc_sensor_odometer_data_load(const uint8_t *d, mipc_sensor_odometer_data_t *out) {
    out->speed = mipc_ld_f32(d + 0);
    out->uncertainty = mipc_ld_f32(d + 4);
    out->valid_flags = mipc_ld_u16(d + 8);
    return 0;
}

/* The general reader: lengths other than 10, bad bool bytes, error details. */
static MIPC_NOINLINE mipc_status_t mipc_sensor_odometer_data_decode_read(const uint8_t *data, size_t len,
                                                                         mipc_sensor_odometer_data_t *out,
                                                                         mipc_decode_error_t *err) {
    mipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_sensor_odometer_data_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t mipc_sensor_odometer_data_decode(const uint8_t *data, size_t len,
                                               mipc_sensor_odometer_data_t *out, mipc_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 10 && mipc_sensor_odometer_data_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_sensor_odometer_data_decode_read(data, len, out, err);
}

/* ---- the straight-line packet decoder */

size_t mipc_sensor_decode_packet(const uint8_t *payload, size_t len, mipc_sensor_packet_t *out,
                                 mipc_field_entry_fn other, void *ctx) {
    size_t pos = 0;
    size_t n = 0;
    assert(payload != NULL || len == 0);
    assert(out != NULL);
    memset(out->index.present, 0, sizeof out->index.present);
    if (payload == NULL) {
        len = 0;
    }
    /* the field headers read in place (the iterator's entry is built only for what goes to other) */
    while (len - pos >= MIPC_FIELD_HEADER_SIZE) {
        const uint8_t *head = payload + pos;
        const uint8_t descriptor = head[MIPC_FIELD_DESCRIPTOR_OFFSET];
        const int data_len =
            (int)head[MIPC_FIELD_LENGTH_OFFSET] - mipc_field_length_adjust(MIPC_SENSOR_SET, descriptor);
        const uint8_t *d = head + MIPC_FIELD_HEADER_SIZE;
        const uint32_t bit = (uint32_t)1u << (descriptor % 32u);
        size_t length;
        size_t offset = 0;
        int ok = 0;
        if (data_len < 0 || (size_t)data_len > len - pos - MIPC_FIELD_HEADER_SIZE) {
            break; /* trailing bytes: the iterator reports them below */
        }
        length = (size_t)data_len;
        if ((out->index.present[descriptor / 32u] & bit) == 0) {
            switch (descriptor) {
            case 0x04:
                if (length == 12) {
                    out->sensor_scaled_accel.scaled_accel[0] = mipc_ld_f32(d + 0);
                    out->sensor_scaled_accel.scaled_accel[1] = mipc_ld_f32(d + 4);
                    out->sensor_scaled_accel.scaled_accel[2] = mipc_ld_f32(d + 8);
                    ok = 1;
                } else {
                    ok = mipc_sensor_scaled_accel_decode(d, length, &out->sensor_scaled_accel, NULL) ==
                         MIPC_OK;
                }
                offset = offsetof(mipc_sensor_packet_t, sensor_scaled_accel);
                break;
            case 0x05:
                if (length == 12) {
                    out->sensor_scaled_gyro.scaled_gyro[0] = mipc_ld_f32(d + 0);
                    out->sensor_scaled_gyro.scaled_gyro[1] = mipc_ld_f32(d + 4);
                    out->sensor_scaled_gyro.scaled_gyro[2] = mipc_ld_f32(d + 8);
                    ok = 1;
                } else {
                    ok = mipc_sensor_scaled_gyro_decode(d, length, &out->sensor_scaled_gyro, NULL) == MIPC_OK;
                }
                offset = offsetof(mipc_sensor_packet_t, sensor_scaled_gyro);
                break;
            case 0x06:
                if (length == 12) {
                    out->sensor_scaled_mag.scaled_mag[0] = mipc_ld_f32(d + 0);
                    out->sensor_scaled_mag.scaled_mag[1] = mipc_ld_f32(d + 4);
                    out->sensor_scaled_mag.scaled_mag[2] = mipc_ld_f32(d + 8);
                    ok = 1;
                } else {
                    ok = mipc_sensor_scaled_mag_decode(d, length, &out->sensor_scaled_mag, NULL) == MIPC_OK;
                }
                offset = offsetof(mipc_sensor_packet_t, sensor_scaled_mag);
                break;
            case 0x07:
                if (length == 12) {
                    out->sensor_delta_theta.delta_theta[0] = mipc_ld_f32(d + 0);
                    out->sensor_delta_theta.delta_theta[1] = mipc_ld_f32(d + 4);
                    out->sensor_delta_theta.delta_theta[2] = mipc_ld_f32(d + 8);
                    ok = 1;
                } else {
                    ok = mipc_sensor_delta_theta_decode(d, length, &out->sensor_delta_theta, NULL) == MIPC_OK;
                }
                offset = offsetof(mipc_sensor_packet_t, sensor_delta_theta);
                break;
            case 0x08:
                if (length == 12) {
                    out->sensor_delta_velocity.delta_velocity[0] = mipc_ld_f32(d + 0);
                    out->sensor_delta_velocity.delta_velocity[1] = mipc_ld_f32(d + 4);
                    out->sensor_delta_velocity.delta_velocity[2] = mipc_ld_f32(d + 8);
                    ok = 1;
                } else {
                    ok = mipc_sensor_delta_velocity_decode(d, length, &out->sensor_delta_velocity, NULL) ==
                         MIPC_OK;
                }
                offset = offsetof(mipc_sensor_packet_t, sensor_delta_velocity);
                break;
            case 0x09:
                if (length == 36) {
                    out->sensor_cf_orientation_matrix.m[0] = mipc_ld_f32(d + 0);
                    out->sensor_cf_orientation_matrix.m[1] = mipc_ld_f32(d + 4);
                    out->sensor_cf_orientation_matrix.m[2] = mipc_ld_f32(d + 8);
                    out->sensor_cf_orientation_matrix.m[3] = mipc_ld_f32(d + 12);
                    out->sensor_cf_orientation_matrix.m[4] = mipc_ld_f32(d + 16);
                    out->sensor_cf_orientation_matrix.m[5] = mipc_ld_f32(d + 20);
                    out->sensor_cf_orientation_matrix.m[6] = mipc_ld_f32(d + 24);
                    out->sensor_cf_orientation_matrix.m[7] = mipc_ld_f32(d + 28);
                    out->sensor_cf_orientation_matrix.m[8] = mipc_ld_f32(d + 32);
                    ok = 1;
                } else {
                    ok = mipc_sensor_cf_orientation_matrix_decode(
                             d, length, &out->sensor_cf_orientation_matrix, NULL) == MIPC_OK;
                }
                offset = offsetof(mipc_sensor_packet_t, sensor_cf_orientation_matrix);
                break;
            case 0x0A:
                if (length == 16) {
                    out->sensor_cf_quaternion.q[0] = mipc_ld_f32(d + 0);
                    out->sensor_cf_quaternion.q[1] = mipc_ld_f32(d + 4);
                    out->sensor_cf_quaternion.q[2] = mipc_ld_f32(d + 8);
                    out->sensor_cf_quaternion.q[3] = mipc_ld_f32(d + 12);
                    ok = 1;
                } else {
                    ok = mipc_sensor_cf_quaternion_decode(d, length, &out->sensor_cf_quaternion, NULL) ==
                         MIPC_OK;
                }
                offset = offsetof(mipc_sensor_packet_t, sensor_cf_quaternion);
                break;
            case 0x0C:
                if (length == 12) {
                    out->sensor_cf_euler_angles.roll = mipc_ld_f32(d + 0);
                    out->sensor_cf_euler_angles.pitch = mipc_ld_f32(d + 4);
                    out->sensor_cf_euler_angles.yaw = mipc_ld_f32(d + 8);
                    ok = 1;
                } else {
                    ok = mipc_sensor_cf_euler_angles_decode(d, length, &out->sensor_cf_euler_angles, NULL) ==
                         MIPC_OK;
                }
                offset = offsetof(mipc_sensor_packet_t, sensor_cf_euler_angles);
                break;
            case 0x10:
                if (length == 12) {
                    out->sensor_cf_stabilized_north.stabilized_north[0] = mipc_ld_f32(d + 0);
                    out->sensor_cf_stabilized_north.stabilized_north[1] = mipc_ld_f32(d + 4);
                    out->sensor_cf_stabilized_north.stabilized_north[2] = mipc_ld_f32(d + 8);
                    ok = 1;
                } else {
                    ok = mipc_sensor_cf_stabilized_north_decode(d, length, &out->sensor_cf_stabilized_north,
                                                                NULL) == MIPC_OK;
                }
                offset = offsetof(mipc_sensor_packet_t, sensor_cf_stabilized_north);
                break;
            case 0x11:
                if (length == 12) {
                    out->sensor_cf_stabilized_up.stabilized_up[0] = mipc_ld_f32(d + 0);
                    out->sensor_cf_stabilized_up.stabilized_up[1] = mipc_ld_f32(d + 4);
                    out->sensor_cf_stabilized_up.stabilized_up[2] = mipc_ld_f32(d + 8);
                    ok = 1;
                } else {
                    ok = mipc_sensor_cf_stabilized_up_decode(d, length, &out->sensor_cf_stabilized_up,
                                                             NULL) == MIPC_OK;
                }
                offset = offsetof(mipc_sensor_packet_t, sensor_cf_stabilized_up);
                break;
            case 0x12:
                if (length == 12) {
                    out->sensor_gps_timestamp.tow = mipc_ld_f64(d + 0);
                    out->sensor_gps_timestamp.week_number = mipc_ld_u16(d + 8);
                    out->sensor_gps_timestamp.valid_flags = mipc_ld_u16(d + 10);
                    ok = 1;
                } else {
                    ok = mipc_sensor_gps_timestamp_decode(d, length, &out->sensor_gps_timestamp, NULL) ==
                         MIPC_OK;
                }
                offset = offsetof(mipc_sensor_packet_t, sensor_gps_timestamp);
                break;
            case 0x14:
                if (length == 12) {
                    out->sensor_temperature_statistics.min_temp = mipc_ld_f32(d + 0);
                    out->sensor_temperature_statistics.max_temp = mipc_ld_f32(d + 4);
                    out->sensor_temperature_statistics.mean_temp = mipc_ld_f32(d + 8);
                    ok = 1;
                } else {
                    ok = mipc_sensor_temperature_statistics_decode(
                             d, length, &out->sensor_temperature_statistics, NULL) == MIPC_OK;
                }
                offset = offsetof(mipc_sensor_packet_t, sensor_temperature_statistics);
                break;
            case 0x17:
                if (length == 4) {
                    out->sensor_scaled_pressure.scaled_pressure = mipc_ld_f32(d + 0);
                    ok = 1;
                } else {
                    ok = mipc_sensor_scaled_pressure_decode(d, length, &out->sensor_scaled_pressure, NULL) ==
                         MIPC_OK;
                }
                offset = offsetof(mipc_sensor_packet_t, sensor_scaled_pressure);
                break;
            case 0x18:
                if (length == 2) {
                    out->sensor_overrange_status.status = mipc_ld_u16(d + 0);
                    ok = 1;
                } else {
                    ok = mipc_sensor_overrange_status_decode(d, length, &out->sensor_overrange_status,
                                                             NULL) == MIPC_OK;
                }
                offset = offsetof(mipc_sensor_packet_t, sensor_overrange_status);
                break;
            case 0x40:
                if (length == 10) {
                    out->sensor_odometer_data.speed = mipc_ld_f32(d + 0);
                    out->sensor_odometer_data.uncertainty = mipc_ld_f32(d + 4);
                    out->sensor_odometer_data.valid_flags = mipc_ld_u16(d + 8);
                    ok = 1;
                } else {
                    ok = mipc_sensor_odometer_data_decode(d, length, &out->sensor_odometer_data, NULL) ==
                         MIPC_OK;
                }
                offset = offsetof(mipc_sensor_packet_t, sensor_odometer_data);
                break;
            case 0xD0:
                if (length == 1) {
                    out->shared_event_source.trigger_id = mipc_ld_u8(d + 0);
                    ok = 1;
                } else {
                    ok = mipc_shared_event_source_decode(d, length, &out->shared_event_source, NULL) ==
                         MIPC_OK;
                }
                offset = offsetof(mipc_sensor_packet_t, shared_event_source);
                break;
            case 0xD3:
                if (length == 12) {
                    out->shared_gps_timestamp.tow = mipc_ld_f64(d + 0);
                    out->shared_gps_timestamp.week_number = mipc_ld_u16(d + 8);
                    out->shared_gps_timestamp.valid_flags = mipc_ld_u16(d + 10);
                    ok = 1;
                } else {
                    ok = mipc_shared_gps_timestamp_decode(d, length, &out->shared_gps_timestamp, NULL) ==
                         MIPC_OK;
                }
                offset = offsetof(mipc_sensor_packet_t, shared_gps_timestamp);
                break;
            case 0xD4:
                if (length == 8) {
                    out->shared_delta_time.seconds = mipc_ld_f64(d + 0);
                    ok = 1;
                } else {
                    ok = mipc_shared_delta_time_decode(d, length, &out->shared_delta_time, NULL) == MIPC_OK;
                }
                offset = offsetof(mipc_sensor_packet_t, shared_delta_time);
                break;
            case 0xD5:
                if (length == 8) {
                    out->shared_reference_timestamp.nanoseconds = mipc_ld_u64(d + 0);
                    ok = 1;
                } else {
                    ok = mipc_shared_reference_timestamp_decode(d, length, &out->shared_reference_timestamp,
                                                                NULL) == MIPC_OK;
                }
                offset = offsetof(mipc_sensor_packet_t, shared_reference_timestamp);
                break;
            case 0xD6:
                if (length == 8) {
                    out->shared_reference_time_delta.dt_nanos = mipc_ld_u64(d + 0);
                    ok = 1;
                } else {
                    ok = mipc_shared_reference_time_delta_decode(d, length, &out->shared_reference_time_delta,
                                                                 NULL) == MIPC_OK;
                }
                offset = offsetof(mipc_sensor_packet_t, shared_reference_time_delta);
                break;
            case 0xD7:
                if (length == 10) {
                    out->shared_external_timestamp.nanoseconds = mipc_ld_u64(d + 0);
                    out->shared_external_timestamp.valid_flags = mipc_ld_u16(d + 8);
                    ok = 1;
                } else {
                    ok = mipc_shared_external_timestamp_decode(d, length, &out->shared_external_timestamp,
                                                               NULL) == MIPC_OK;
                }
                offset = offsetof(mipc_sensor_packet_t, shared_external_timestamp);
                break;
            case 0xD8:
                if (length == 10) {
                    out->shared_external_time_delta.dt_nanos = mipc_ld_u64(d + 0);
                    out->shared_external_time_delta.valid_flags = mipc_ld_u16(d + 8);
                    ok = 1;
                } else {
                    ok = mipc_shared_external_time_delta_decode(d, length, &out->shared_external_time_delta,
                                                                NULL) == MIPC_OK;
                }
                offset = offsetof(mipc_sensor_packet_t, shared_external_time_delta);
                break;
            default:
                break;
            }
        }
        if (ok) {
            out->index.present[descriptor / 32u] |= bit;
            out->index.fields[n].descriptor = descriptor;
            out->index.fields[n].offset = (uint32_t)offset;
            n++;
        } else if (other) {
            mipc_field_visit_at_(MIPC_SENSOR_SET, payload, len, pos, other, ctx);
        }
        pos += MIPC_FIELD_HEADER_SIZE + length;
    }
    if (pos < len && other) {
        mipc_field_visit_at_(MIPC_SENSOR_SET, payload, len, pos, other, ctx);
    }
    out->index.count = n;
    return n;
}

/* ---- the members' loaders (mipc_decode_packet_cached, issue 38): each decodes its field's
 * data into its member of the mipc_sensor_packet_t at packet as mipc_sensor_decode_packet does; 0 when it
 * does not decode (the packet then takes the straight-line decoder, which gives the field to other) */

static int load_0x04(const uint8_t *d, size_t length, void *packet) {
    mipc_sensor_packet_t *out = packet;
    if (length == 12) {
        out->sensor_scaled_accel.scaled_accel[0] = mipc_ld_f32(d + 0);
        out->sensor_scaled_accel.scaled_accel[1] = mipc_ld_f32(d + 4);
        out->sensor_scaled_accel.scaled_accel[2] = mipc_ld_f32(d + 8);
        return 1;
    }
    return mipc_sensor_scaled_accel_decode(d, length, &out->sensor_scaled_accel, NULL) == MIPC_OK;
}

static int load_0x05(const uint8_t *d, size_t length, void *packet) {
    mipc_sensor_packet_t *out = packet;
    if (length == 12) {
        out->sensor_scaled_gyro.scaled_gyro[0] = mipc_ld_f32(d + 0);
        out->sensor_scaled_gyro.scaled_gyro[1] = mipc_ld_f32(d + 4);
        out->sensor_scaled_gyro.scaled_gyro[2] = mipc_ld_f32(d + 8);
        return 1;
    }
    return mipc_sensor_scaled_gyro_decode(d, length, &out->sensor_scaled_gyro, NULL) == MIPC_OK;
}

static int load_0x06(const uint8_t *d, size_t length, void *packet) {
    mipc_sensor_packet_t *out = packet;
    if (length == 12) {
        out->sensor_scaled_mag.scaled_mag[0] = mipc_ld_f32(d + 0);
        out->sensor_scaled_mag.scaled_mag[1] = mipc_ld_f32(d + 4);
        out->sensor_scaled_mag.scaled_mag[2] = mipc_ld_f32(d + 8);
        return 1;
    }
    return mipc_sensor_scaled_mag_decode(d, length, &out->sensor_scaled_mag, NULL) == MIPC_OK;
}

static int load_0x07(const uint8_t *d, size_t length, void *packet) {
    mipc_sensor_packet_t *out = packet;
    if (length == 12) {
        out->sensor_delta_theta.delta_theta[0] = mipc_ld_f32(d + 0);
        out->sensor_delta_theta.delta_theta[1] = mipc_ld_f32(d + 4);
        out->sensor_delta_theta.delta_theta[2] = mipc_ld_f32(d + 8);
        return 1;
    }
    return mipc_sensor_delta_theta_decode(d, length, &out->sensor_delta_theta, NULL) == MIPC_OK;
}

static int load_0x08(const uint8_t *d, size_t length, void *packet) {
    mipc_sensor_packet_t *out = packet;
    if (length == 12) {
        out->sensor_delta_velocity.delta_velocity[0] = mipc_ld_f32(d + 0);
        out->sensor_delta_velocity.delta_velocity[1] = mipc_ld_f32(d + 4);
        out->sensor_delta_velocity.delta_velocity[2] = mipc_ld_f32(d + 8);
        return 1;
    }
    return mipc_sensor_delta_velocity_decode(d, length, &out->sensor_delta_velocity, NULL) == MIPC_OK;
}

static int load_0x09(const uint8_t *d, size_t length, void *packet) {
    mipc_sensor_packet_t *out = packet;
    if (length == 36) {
        out->sensor_cf_orientation_matrix.m[0] = mipc_ld_f32(d + 0);
        out->sensor_cf_orientation_matrix.m[1] = mipc_ld_f32(d + 4);
        out->sensor_cf_orientation_matrix.m[2] = mipc_ld_f32(d + 8);
        out->sensor_cf_orientation_matrix.m[3] = mipc_ld_f32(d + 12);
        out->sensor_cf_orientation_matrix.m[4] = mipc_ld_f32(d + 16);
        out->sensor_cf_orientation_matrix.m[5] = mipc_ld_f32(d + 20);
        out->sensor_cf_orientation_matrix.m[6] = mipc_ld_f32(d + 24);
        out->sensor_cf_orientation_matrix.m[7] = mipc_ld_f32(d + 28);
        out->sensor_cf_orientation_matrix.m[8] = mipc_ld_f32(d + 32);
        return 1;
    }
    return mipc_sensor_cf_orientation_matrix_decode(d, length, &out->sensor_cf_orientation_matrix, NULL) ==
           MIPC_OK;
}

static int load_0x0a(const uint8_t *d, size_t length, void *packet) {
    mipc_sensor_packet_t *out = packet;
    if (length == 16) {
        out->sensor_cf_quaternion.q[0] = mipc_ld_f32(d + 0);
        out->sensor_cf_quaternion.q[1] = mipc_ld_f32(d + 4);
        out->sensor_cf_quaternion.q[2] = mipc_ld_f32(d + 8);
        out->sensor_cf_quaternion.q[3] = mipc_ld_f32(d + 12);
        return 1;
    }
    return mipc_sensor_cf_quaternion_decode(d, length, &out->sensor_cf_quaternion, NULL) == MIPC_OK;
}

static int load_0x0c(const uint8_t *d, size_t length, void *packet) {
    mipc_sensor_packet_t *out = packet;
    if (length == 12) {
        out->sensor_cf_euler_angles.roll = mipc_ld_f32(d + 0);
        out->sensor_cf_euler_angles.pitch = mipc_ld_f32(d + 4);
        out->sensor_cf_euler_angles.yaw = mipc_ld_f32(d + 8);
        return 1;
    }
    return mipc_sensor_cf_euler_angles_decode(d, length, &out->sensor_cf_euler_angles, NULL) == MIPC_OK;
}

static int load_0x10(const uint8_t *d, size_t length, void *packet) {
    mipc_sensor_packet_t *out = packet;
    if (length == 12) {
        out->sensor_cf_stabilized_north.stabilized_north[0] = mipc_ld_f32(d + 0);
        out->sensor_cf_stabilized_north.stabilized_north[1] = mipc_ld_f32(d + 4);
        out->sensor_cf_stabilized_north.stabilized_north[2] = mipc_ld_f32(d + 8);
        return 1;
    }
    return mipc_sensor_cf_stabilized_north_decode(d, length, &out->sensor_cf_stabilized_north, NULL) ==
           MIPC_OK;
}

static int load_0x11(const uint8_t *d, size_t length, void *packet) {
    mipc_sensor_packet_t *out = packet;
    if (length == 12) {
        out->sensor_cf_stabilized_up.stabilized_up[0] = mipc_ld_f32(d + 0);
        out->sensor_cf_stabilized_up.stabilized_up[1] = mipc_ld_f32(d + 4);
        out->sensor_cf_stabilized_up.stabilized_up[2] = mipc_ld_f32(d + 8);
        return 1;
    }
    return mipc_sensor_cf_stabilized_up_decode(d, length, &out->sensor_cf_stabilized_up, NULL) == MIPC_OK;
}

static int load_0x12(const uint8_t *d, size_t length, void *packet) {
    mipc_sensor_packet_t *out = packet;
    if (length == 12) {
        out->sensor_gps_timestamp.tow = mipc_ld_f64(d + 0);
        out->sensor_gps_timestamp.week_number = mipc_ld_u16(d + 8);
        out->sensor_gps_timestamp.valid_flags = mipc_ld_u16(d + 10);
        return 1;
    }
    return mipc_sensor_gps_timestamp_decode(d, length, &out->sensor_gps_timestamp, NULL) == MIPC_OK;
}

static int load_0x14(const uint8_t *d, size_t length, void *packet) {
    mipc_sensor_packet_t *out = packet;
    if (length == 12) {
        out->sensor_temperature_statistics.min_temp = mipc_ld_f32(d + 0);
        out->sensor_temperature_statistics.max_temp = mipc_ld_f32(d + 4);
        out->sensor_temperature_statistics.mean_temp = mipc_ld_f32(d + 8);
        return 1;
    }
    return mipc_sensor_temperature_statistics_decode(d, length, &out->sensor_temperature_statistics, NULL) ==
           MIPC_OK;
}

static int load_0x17(const uint8_t *d, size_t length, void *packet) {
    mipc_sensor_packet_t *out = packet;
    if (length == 4) {
        out->sensor_scaled_pressure.scaled_pressure = mipc_ld_f32(d + 0);
        return 1;
    }
    return mipc_sensor_scaled_pressure_decode(d, length, &out->sensor_scaled_pressure, NULL) == MIPC_OK;
}

static int load_0x18(const uint8_t *d, size_t length, void *packet) {
    mipc_sensor_packet_t *out = packet;
    if (length == 2) {
        out->sensor_overrange_status.status = mipc_ld_u16(d + 0);
        return 1;
    }
    return mipc_sensor_overrange_status_decode(d, length, &out->sensor_overrange_status, NULL) == MIPC_OK;
}

static int load_0x40(const uint8_t *d, size_t length, void *packet) {
    mipc_sensor_packet_t *out = packet;
    if (length == 10) {
        out->sensor_odometer_data.speed = mipc_ld_f32(d + 0);
        out->sensor_odometer_data.uncertainty = mipc_ld_f32(d + 4);
        out->sensor_odometer_data.valid_flags = mipc_ld_u16(d + 8);
        return 1;
    }
    return mipc_sensor_odometer_data_decode(d, length, &out->sensor_odometer_data, NULL) == MIPC_OK;
}

static int load_0xd0(const uint8_t *d, size_t length, void *packet) {
    mipc_sensor_packet_t *out = packet;
    if (length == 1) {
        out->shared_event_source.trigger_id = mipc_ld_u8(d + 0);
        return 1;
    }
    return mipc_shared_event_source_decode(d, length, &out->shared_event_source, NULL) == MIPC_OK;
}

static int load_0xd3(const uint8_t *d, size_t length, void *packet) {
    mipc_sensor_packet_t *out = packet;
    if (length == 12) {
        out->shared_gps_timestamp.tow = mipc_ld_f64(d + 0);
        out->shared_gps_timestamp.week_number = mipc_ld_u16(d + 8);
        out->shared_gps_timestamp.valid_flags = mipc_ld_u16(d + 10);
        return 1;
    }
    return mipc_shared_gps_timestamp_decode(d, length, &out->shared_gps_timestamp, NULL) == MIPC_OK;
}

static int load_0xd4(const uint8_t *d, size_t length, void *packet) {
    mipc_sensor_packet_t *out = packet;
    if (length == 8) {
        out->shared_delta_time.seconds = mipc_ld_f64(d + 0);
        return 1;
    }
    return mipc_shared_delta_time_decode(d, length, &out->shared_delta_time, NULL) == MIPC_OK;
}

static int load_0xd5(const uint8_t *d, size_t length, void *packet) {
    mipc_sensor_packet_t *out = packet;
    if (length == 8) {
        out->shared_reference_timestamp.nanoseconds = mipc_ld_u64(d + 0);
        return 1;
    }
    return mipc_shared_reference_timestamp_decode(d, length, &out->shared_reference_timestamp, NULL) ==
           MIPC_OK;
}

static int load_0xd6(const uint8_t *d, size_t length, void *packet) {
    mipc_sensor_packet_t *out = packet;
    if (length == 8) {
        out->shared_reference_time_delta.dt_nanos = mipc_ld_u64(d + 0);
        return 1;
    }
    return mipc_shared_reference_time_delta_decode(d, length, &out->shared_reference_time_delta, NULL) ==
           MIPC_OK;
}

static int load_0xd7(const uint8_t *d, size_t length, void *packet) {
    mipc_sensor_packet_t *out = packet;
    if (length == 10) {
        out->shared_external_timestamp.nanoseconds = mipc_ld_u64(d + 0);
        out->shared_external_timestamp.valid_flags = mipc_ld_u16(d + 8);
        return 1;
    }
    return mipc_shared_external_timestamp_decode(d, length, &out->shared_external_timestamp, NULL) == MIPC_OK;
}

static int load_0xd8(const uint8_t *d, size_t length, void *packet) {
    mipc_sensor_packet_t *out = packet;
    if (length == 10) {
        out->shared_external_time_delta.dt_nanos = mipc_ld_u64(d + 0);
        out->shared_external_time_delta.valid_flags = mipc_ld_u16(d + 8);
        return 1;
    }
    return mipc_shared_external_time_delta_decode(d, length, &out->shared_external_time_delta, NULL) ==
           MIPC_OK;
}

const mipc_layout_member_t mipc_sensor_layout_members_[22] = {
    {0x04, offsetof(mipc_sensor_packet_t, sensor_scaled_accel), load_0x04},
    {0x05, offsetof(mipc_sensor_packet_t, sensor_scaled_gyro), load_0x05},
    {0x06, offsetof(mipc_sensor_packet_t, sensor_scaled_mag), load_0x06},
    {0x07, offsetof(mipc_sensor_packet_t, sensor_delta_theta), load_0x07},
    {0x08, offsetof(mipc_sensor_packet_t, sensor_delta_velocity), load_0x08},
    {0x09, offsetof(mipc_sensor_packet_t, sensor_cf_orientation_matrix), load_0x09},
    {0x0A, offsetof(mipc_sensor_packet_t, sensor_cf_quaternion), load_0x0a},
    {0x0C, offsetof(mipc_sensor_packet_t, sensor_cf_euler_angles), load_0x0c},
    {0x10, offsetof(mipc_sensor_packet_t, sensor_cf_stabilized_north), load_0x10},
    {0x11, offsetof(mipc_sensor_packet_t, sensor_cf_stabilized_up), load_0x11},
    {0x12, offsetof(mipc_sensor_packet_t, sensor_gps_timestamp), load_0x12},
    {0x14, offsetof(mipc_sensor_packet_t, sensor_temperature_statistics), load_0x14},
    {0x17, offsetof(mipc_sensor_packet_t, sensor_scaled_pressure), load_0x17},
    {0x18, offsetof(mipc_sensor_packet_t, sensor_overrange_status), load_0x18},
    {0x40, offsetof(mipc_sensor_packet_t, sensor_odometer_data), load_0x40},
    {0xD0, offsetof(mipc_sensor_packet_t, shared_event_source), load_0xd0},
    {0xD3, offsetof(mipc_sensor_packet_t, shared_gps_timestamp), load_0xd3},
    {0xD4, offsetof(mipc_sensor_packet_t, shared_delta_time), load_0xd4},
    {0xD5, offsetof(mipc_sensor_packet_t, shared_reference_timestamp), load_0xd5},
    {0xD6, offsetof(mipc_sensor_packet_t, shared_reference_time_delta), load_0xd6},
    {0xD7, offsetof(mipc_sensor_packet_t, shared_external_timestamp), load_0xd7},
    {0xD8, offsetof(mipc_sensor_packet_t, shared_external_time_delta), load_0xd8},
};
