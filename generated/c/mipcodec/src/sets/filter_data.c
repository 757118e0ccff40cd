/* Encoders and decoders of Estimation Filter Data Set. Generated from the spec: do not edit. */
#include "mipcodec/sets/filter_data.h"
#include "layouts_internal.h"
#include "types_internal.h"

#include <assert.h>
#include <stddef.h>
#include <string.h>

/* ---- mipc_filter_data_llh_position_t */

static int mipc_filter_data_llh_position_read(mipc_reader_t *r, mipc_filter_data_llh_position_t *out) {
    mipc_rd_push(r, "latitude");
    if (mipc_rd_f64(r, &out->latitude)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "longitude");
    if (mipc_rd_f64(r, &out->longitude)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "ellipsoid_height");
    if (mipc_rd_f64(r, &out->ellipsoid_height)) {
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

static mipc_status_t mipc_filter_data_llh_position_write(mipc_writer_t *w,
                                                         const mipc_filter_data_llh_position_t *in) {
    mipc_status_t st;
    if ((st = mipc_wr_f64(w, &in->latitude)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_f64(w, &in->longitude)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_f64(w, &in->ellipsoid_height)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u16(w, &in->valid_flags)) != MIPC_OK) {
        return st;
    }
    return MIPC_OK;
}

mipc_status_t mipc_filter_data_llh_position_encode(const mipc_filter_data_llh_position_t *value, uint8_t *buf,
                                                   size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mipc_writer_init(&w, buf, cap);
    st = mipc_filter_data_llh_position_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 26 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mipc_filter_data_llh_position_load(const uint8_t *d, mipc_filter_data_llh_position_t *out) {
    out->latitude = mipc_ld_f64(d + 0);
    out->longitude = mipc_ld_f64(d + 8);
    out->ellipsoid_height = mipc_ld_f64(d + 16);
    out->valid_flags = mipc_ld_u16(d + 24);
    return 0;
}

/* The general reader: lengths other than 26, bad bool bytes, error details. */
static MIPC_NOINLINE mipc_status_t mipc_filter_data_llh_position_decode_read(
    const uint8_t *data, size_t len, mipc_filter_data_llh_position_t *out, mipc_decode_error_t *err) {
    mipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_filter_data_llh_position_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t mipc_filter_data_llh_position_decode(const uint8_t *data, size_t len,
                                                   mipc_filter_data_llh_position_t *out,
                                                   mipc_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 26 && mipc_filter_data_llh_position_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_filter_data_llh_position_decode_read(data, len, out, err);
}

/* ---- mipc_filter_data_ned_velocity_t */

static int mipc_filter_data_ned_velocity_read(mipc_reader_t *r, mipc_filter_data_ned_velocity_t *out) {
    mipc_rd_push(r, "north");
    if (mipc_rd_f32(r, &out->north)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "east");
    if (mipc_rd_f32(r, &out->east)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "down");
    if (mipc_rd_f32(r, &out->down)) {
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

static mipc_status_t mipc_filter_data_ned_velocity_write(mipc_writer_t *w,
                                                         const mipc_filter_data_ned_velocity_t *in) {
    mipc_status_t st;
    if ((st = mipc_wr_f32(w, &in->north)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_f32(w, &in->east)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_f32(w, &in->down)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u16(w, &in->valid_flags)) != MIPC_OK) {
        return st;
    }
    return MIPC_OK;
}

mipc_status_t mipc_filter_data_ned_velocity_encode(const mipc_filter_data_ned_velocity_t *value, uint8_t *buf,
                                                   size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mipc_writer_init(&w, buf, cap);
    st = mipc_filter_data_ned_velocity_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 14 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mipc_filter_data_ned_velocity_load(const uint8_t *d, mipc_filter_data_ned_velocity_t *out) {
    out->north = mipc_ld_f32(d + 0);
    out->east = mipc_ld_f32(d + 4);
    out->down = mipc_ld_f32(d + 8);
    out->valid_flags = mipc_ld_u16(d + 12);
    return 0;
}

/* The general reader: lengths other than 14, bad bool bytes, error details. */
static MIPC_NOINLINE mipc_status_t mipc_filter_data_ned_velocity_decode_read(
    const uint8_t *data, size_t len, mipc_filter_data_ned_velocity_t *out, mipc_decode_error_t *err) {
    mipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_filter_data_ned_velocity_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t mipc_filter_data_ned_velocity_decode(const uint8_t *data, size_t len,
                                                   mipc_filter_data_ned_velocity_t *out,
                                                   mipc_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 14 && mipc_filter_data_ned_velocity_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_filter_data_ned_velocity_decode_read(data, len, out, err);
}

/* ---- mipc_filter_data_attitude_quaternion_t */

static int mipc_filter_data_attitude_quaternion_read(mipc_reader_t *r,
                                                     mipc_filter_data_attitude_quaternion_t *out) {
    size_t i;
    mipc_rd_push(r, "q");
    for (i = 0; i < 4; i++) {
        mipc_rd_index(r, i);
        if (mipc_rd_f32(r, &out->q[i])) {
            return -1;
        }
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "valid_flags");
    if (mipc_rd_u16(r, &out->valid_flags)) {
        return -1;
    }
    mipc_rd_pop(r);
    return mipc_rd_finish(r);
}

static mipc_status_t
mipc_filter_data_attitude_quaternion_write(mipc_writer_t *w,
                                           const mipc_filter_data_attitude_quaternion_t *in) {
    mipc_status_t st;
    size_t i;
    for (i = 0; i < 4; i++) {
        if ((st = mipc_wr_f32(w, &in->q[i])) != MIPC_OK) {
            return st;
        }
    }
    if ((st = mipc_wr_u16(w, &in->valid_flags)) != MIPC_OK) {
        return st;
    }
    return MIPC_OK;
}

mipc_status_t mipc_filter_data_attitude_quaternion_encode(const mipc_filter_data_attitude_quaternion_t *value,
                                                          uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mipc_writer_init(&w, buf, cap);
    st = mipc_filter_data_attitude_quaternion_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 18 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mipc_filter_data_attitude_quaternion_load(const uint8_t *d,
                                                     mipc_filter_data_attitude_quaternion_t *out) {
    out->q[0] = mipc_ld_f32(d + 0);
    out->q[1] = mipc_ld_f32(d + 4);
    out->q[2] = mipc_ld_f32(d + 8);
    out->q[3] = mipc_ld_f32(d + 12);
    out->valid_flags = mipc_ld_u16(d + 16);
    return 0;
}

/* The general reader: lengths other than 18, bad bool bytes, error details. */
static MIPC_NOINLINE mipc_status_t mipc_filter_data_attitude_quaternion_decode_read(
    const uint8_t *data, size_t len, mipc_filter_data_attitude_quaternion_t *out, mipc_decode_error_t *err) {
    mipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_filter_data_attitude_quaternion_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t mipc_filter_data_attitude_quaternion_decode(const uint8_t *data, size_t len,
                                                          mipc_filter_data_attitude_quaternion_t *out,
                                                          mipc_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 18 && mipc_filter_data_attitude_quaternion_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_filter_data_attitude_quaternion_decode_read(data, len, out, err);
}

/* ---- mipc_filter_data_attitude_dcm_t */

static int mipc_filter_data_attitude_dcm_read(mipc_reader_t *r, mipc_filter_data_attitude_dcm_t *out) {
    size_t i;
    mipc_rd_push(r, "dcm");
    for (i = 0; i < 9; i++) {
        mipc_rd_index(r, i);
        if (mipc_rd_f32(r, &out->dcm[i])) {
            return -1;
        }
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "valid_flags");
    if (mipc_rd_u16(r, &out->valid_flags)) {
        return -1;
    }
    mipc_rd_pop(r);
    return mipc_rd_finish(r);
}

static mipc_status_t mipc_filter_data_attitude_dcm_write(mipc_writer_t *w,
                                                         const mipc_filter_data_attitude_dcm_t *in) {
    mipc_status_t st;
    size_t i;
    for (i = 0; i < 9; i++) {
        if ((st = mipc_wr_f32(w, &in->dcm[i])) != MIPC_OK) {
            return st;
        }
    }
    if ((st = mipc_wr_u16(w, &in->valid_flags)) != MIPC_OK) {
        return st;
    }
    return MIPC_OK;
}

mipc_status_t mipc_filter_data_attitude_dcm_encode(const mipc_filter_data_attitude_dcm_t *value, uint8_t *buf,
                                                   size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mipc_writer_init(&w, buf, cap);
    st = mipc_filter_data_attitude_dcm_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 38 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mipc_filter_data_attitude_dcm_load(const uint8_t *d, mipc_filter_data_attitude_dcm_t *out) {
    out->dcm[0] = mipc_ld_f32(d + 0);
    out->dcm[1] = mipc_ld_f32(d + 4);
    out->dcm[2] = mipc_ld_f32(d + 8);
    out->dcm[3] = mipc_ld_f32(d + 12);
    out->dcm[4] = mipc_ld_f32(d + 16);
    out->dcm[5] = mipc_ld_f32(d + 20);
    out->dcm[6] = mipc_ld_f32(d + 24);
    out->dcm[7] = mipc_ld_f32(d + 28);
    out->dcm[8] = mipc_ld_f32(d + 32);
    out->valid_flags = mipc_ld_u16(d + 36);
    return 0;
}

/* The general reader: lengths other than 38, bad bool bytes, error details. */
static MIPC_NOINLINE mipc_status_t mipc_filter_data_attitude_dcm_decode_read(
    const uint8_t *data, size_t len, mipc_filter_data_attitude_dcm_t *out, mipc_decode_error_t *err) {
    mipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_filter_data_attitude_dcm_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t mipc_filter_data_attitude_dcm_decode(const uint8_t *data, size_t len,
                                                   mipc_filter_data_attitude_dcm_t *out,
                                                   mipc_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 38 && mipc_filter_data_attitude_dcm_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_filter_data_attitude_dcm_decode_read(data, len, out, err);
}

/* ---- mipc_filter_data_euler_angles_t */

static int mipc_filter_data_euler_angles_read(mipc_reader_t *r, mipc_filter_data_euler_angles_t *out) {
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
    mipc_rd_push(r, "valid_flags");
    if (mipc_rd_u16(r, &out->valid_flags)) {
        return -1;
    }
    mipc_rd_pop(r);
    return mipc_rd_finish(r);
}

static mipc_status_t mipc_filter_data_euler_angles_write(mipc_writer_t *w,
                                                         const mipc_filter_data_euler_angles_t *in) {
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
    if ((st = mipc_wr_u16(w, &in->valid_flags)) != MIPC_OK) {
        return st;
    }
    return MIPC_OK;
}

mipc_status_t mipc_filter_data_euler_angles_encode(const mipc_filter_data_euler_angles_t *value, uint8_t *buf,
                                                   size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mipc_writer_init(&w, buf, cap);
    st = mipc_filter_data_euler_angles_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 14 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mipc_filter_data_euler_angles_load(const uint8_t *d, mipc_filter_data_euler_angles_t *out) {
    out->roll = mipc_ld_f32(d + 0);
    out->pitch = mipc_ld_f32(d + 4);
    out->yaw = mipc_ld_f32(d + 8);
    out->valid_flags = mipc_ld_u16(d + 12);
    return 0;
}

/* The general reader: lengths other than 14, bad bool bytes, error details. */
static MIPC_NOINLINE mipc_status_t mipc_filter_data_euler_angles_decode_read(
    const uint8_t *data, size_t len, mipc_filter_data_euler_angles_t *out, mipc_decode_error_t *err) {
    mipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_filter_data_euler_angles_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t mipc_filter_data_euler_angles_decode(const uint8_t *data, size_t len,
                                                   mipc_filter_data_euler_angles_t *out,
                                                   mipc_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 14 && mipc_filter_data_euler_angles_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_filter_data_euler_angles_decode_read(data, len, out, err);
}

/* ---- mipc_filter_data_gyro_bias_t */

static int mipc_filter_data_gyro_bias_read(mipc_reader_t *r, mipc_filter_data_gyro_bias_t *out) {
    size_t i;
    mipc_rd_push(r, "bias");
    for (i = 0; i < 3; i++) {
        mipc_rd_index(r, i);
        if (mipc_rd_f32(r, &out->bias[i])) {
            return -1;
        }
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "valid_flags");
    if (mipc_rd_u16(r, &out->valid_flags)) {
        return -1;
    }
    mipc_rd_pop(r);
    return mipc_rd_finish(r);
}

static mipc_status_t mipc_filter_data_gyro_bias_write(mipc_writer_t *w,
                                                      const mipc_filter_data_gyro_bias_t *in) {
    mipc_status_t st;
    size_t i;
    for (i = 0; i < 3; i++) {
        if ((st = mipc_wr_f32(w, &in->bias[i])) != MIPC_OK) {
            return st;
        }
    }
    if ((st = mipc_wr_u16(w, &in->valid_flags)) != MIPC_OK) {
        return st;
    }
    return MIPC_OK;
}

mipc_status_t mipc_filter_data_gyro_bias_encode(const mipc_filter_data_gyro_bias_t *value, uint8_t *buf,
                                                size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mipc_writer_init(&w, buf, cap);
    st = mipc_filter_data_gyro_bias_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 14 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mipc_filter_data_gyro_bias_load(const uint8_t *d, mipc_filter_data_gyro_bias_t *out) {
    out->bias[0] = mipc_ld_f32(d + 0);
    out->bias[1] = mipc_ld_f32(d + 4);
    out->bias[2] = mipc_ld_f32(d + 8);
    out->valid_flags = mipc_ld_u16(d + 12);
    return 0;
}

/* The general reader: lengths other than 14, bad bool bytes, error details. */
static MIPC_NOINLINE mipc_status_t mipc_filter_data_gyro_bias_decode_read(const uint8_t *data, size_t len,
                                                                          mipc_filter_data_gyro_bias_t *out,
                                                                          mipc_decode_error_t *err) {
    mipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_filter_data_gyro_bias_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t mipc_filter_data_gyro_bias_decode(const uint8_t *data, size_t len,
                                                mipc_filter_data_gyro_bias_t *out, mipc_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 14 && mipc_filter_data_gyro_bias_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_filter_data_gyro_bias_decode_read(data, len, out, err);
}

/* ---- mipc_filter_data_accel_bias_t */

static int mipc_filter_data_accel_bias_read(mipc_reader_t *r, mipc_filter_data_accel_bias_t *out) {
    size_t i;
    mipc_rd_push(r, "bias");
    for (i = 0; i < 3; i++) {
        mipc_rd_index(r, i);
        if (mipc_rd_f32(r, &out->bias[i])) {
            return -1;
        }
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "valid_flags");
    if (mipc_rd_u16(r, &out->valid_flags)) {
        return -1;
    }
    mipc_rd_pop(r);
    return mipc_rd_finish(r);
}

static mipc_status_t mipc_filter_data_accel_bias_write(mipc_writer_t *w,
                                                       const mipc_filter_data_accel_bias_t *in) {
    mipc_status_t st;
    size_t i;
    for (i = 0; i < 3; i++) {
        if ((st = mipc_wr_f32(w, &in->bias[i])) != MIPC_OK) {
            return st;
        }
    }
    if ((st = mipc_wr_u16(w, &in->valid_flags)) != MIPC_OK) {
        return st;
    }
    return MIPC_OK;
}

mipc_status_t mipc_filter_data_accel_bias_encode(const mipc_filter_data_accel_bias_t *value, uint8_t *buf,
                                                 size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mipc_writer_init(&w, buf, cap);
    st = mipc_filter_data_accel_bias_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 14 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mipc_filter_data_accel_bias_load(const uint8_t *d, mipc_filter_data_accel_bias_t *out) {
    out->bias[0] = mipc_ld_f32(d + 0);
    out->bias[1] = mipc_ld_f32(d + 4);
    out->bias[2] = mipc_ld_f32(d + 8);
    out->valid_flags = mipc_ld_u16(d + 12);
    return 0;
}

/* The general reader: lengths other than 14, bad bool bytes, error details. */
static MIPC_NOINLINE mipc_status_t mipc_filter_data_accel_bias_decode_read(const uint8_t *data, size_t len,
                                                                           mipc_filter_data_accel_bias_t *out,
                                                                           mipc_decode_error_t *err) {
    mipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_filter_data_accel_bias_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t mipc_filter_data_accel_bias_decode(const uint8_t *data, size_t len,
                                                 mipc_filter_data_accel_bias_t *out,
                                                 mipc_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 14 && mipc_filter_data_accel_bias_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_filter_data_accel_bias_decode_read(data, len, out, err);
}

/* ---- mipc_filter_data_llh_position_uncertainty_t */

static int mipc_filter_data_llh_position_uncertainty_read(mipc_reader_t *r,
                                                          mipc_filter_data_llh_position_uncertainty_t *out) {
    mipc_rd_push(r, "north");
    if (mipc_rd_f32(r, &out->north)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "east");
    if (mipc_rd_f32(r, &out->east)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "down");
    if (mipc_rd_f32(r, &out->down)) {
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

static mipc_status_t
mipc_filter_data_llh_position_uncertainty_write(mipc_writer_t *w,
                                                const mipc_filter_data_llh_position_uncertainty_t *in) {
    mipc_status_t st;
    if ((st = mipc_wr_f32(w, &in->north)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_f32(w, &in->east)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_f32(w, &in->down)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u16(w, &in->valid_flags)) != MIPC_OK) {
        return st;
    }
    return MIPC_OK;
}

mipc_status_t
mipc_filter_data_llh_position_uncertainty_encode(const mipc_filter_data_llh_position_uncertainty_t *value,
                                                 uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mipc_writer_init(&w, buf, cap);
    st = mipc_filter_data_llh_position_uncertainty_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 14 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mipc_filter_data_llh_position_uncertainty_load(const uint8_t *d,
                                                          mipc_filter_data_llh_position_uncertainty_t *out) {
    out->north = mipc_ld_f32(d + 0);
    out->east = mipc_ld_f32(d + 4);
    out->down = mipc_ld_f32(d + 8);
    out->valid_flags = mipc_ld_u16(d + 12);
    return 0;
}

/* The general reader: lengths other than 14, bad bool bytes, error details. */
static MIPC_NOINLINE mipc_status_t mipc_filter_data_llh_position_uncertainty_decode_read(
    const uint8_t *data, size_t len, mipc_filter_data_llh_position_uncertainty_t *out,
    mipc_decode_error_t *err) {
    mipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_filter_data_llh_position_uncertainty_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t
mipc_filter_data_llh_position_uncertainty_decode(const uint8_t *data, size_t len,
                                                 mipc_filter_data_llh_position_uncertainty_t *out,
                                                 mipc_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 14 && mipc_filter_data_llh_position_uncertainty_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_filter_data_llh_position_uncertainty_decode_read(data, len, out, err);
}

/* ---- mipc_filter_data_ned_velocity_uncertainty_t */

static int mipc_filter_data_ned_velocity_uncertainty_read(mipc_reader_t *r,
                                                          mipc_filter_data_ned_velocity_uncertainty_t *out) {
    mipc_rd_push(r, "north");
    if (mipc_rd_f32(r, &out->north)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "east");
    if (mipc_rd_f32(r, &out->east)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "down");
    if (mipc_rd_f32(r, &out->down)) {
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

static mipc_status_t
mipc_filter_data_ned_velocity_uncertainty_write(mipc_writer_t *w,
                                                const mipc_filter_data_ned_velocity_uncertainty_t *in) {
    mipc_status_t st;
    if ((st = mipc_wr_f32(w, &in->north)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_f32(w, &in->east)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_f32(w, &in->down)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u16(w, &in->valid_flags)) != MIPC_OK) {
        return st;
    }
    return MIPC_OK;
}

mipc_status_t
mipc_filter_data_ned_velocity_uncertainty_encode(const mipc_filter_data_ned_velocity_uncertainty_t *value,
                                                 uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mipc_writer_init(&w, buf, cap);
    st = mipc_filter_data_ned_velocity_uncertainty_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 14 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mipc_filter_data_ned_velocity_uncertainty_load(const uint8_t *d,
                                                          mipc_filter_data_ned_velocity_uncertainty_t *out) {
    out->north = mipc_ld_f32(d + 0);
    out->east = mipc_ld_f32(d + 4);
    out->down = mipc_ld_f32(d + 8);
    out->valid_flags = mipc_ld_u16(d + 12);
    return 0;
}

/* The general reader: lengths other than 14, bad bool bytes, error details. */
static MIPC_NOINLINE mipc_status_t mipc_filter_data_ned_velocity_uncertainty_decode_read(
    const uint8_t *data, size_t len, mipc_filter_data_ned_velocity_uncertainty_t *out,
    mipc_decode_error_t *err) {
    mipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_filter_data_ned_velocity_uncertainty_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t
mipc_filter_data_ned_velocity_uncertainty_decode(const uint8_t *data, size_t len,
                                                 mipc_filter_data_ned_velocity_uncertainty_t *out,
                                                 mipc_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 14 && mipc_filter_data_ned_velocity_uncertainty_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_filter_data_ned_velocity_uncertainty_decode_read(data, len, out, err);
}

/* ---- mipc_filter_data_euler_angles_uncertainty_t */

static int mipc_filter_data_euler_angles_uncertainty_read(mipc_reader_t *r,
                                                          mipc_filter_data_euler_angles_uncertainty_t *out) {
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
    mipc_rd_push(r, "valid_flags");
    if (mipc_rd_u16(r, &out->valid_flags)) {
        return -1;
    }
    mipc_rd_pop(r);
    return mipc_rd_finish(r);
}

static mipc_status_t
mipc_filter_data_euler_angles_uncertainty_write(mipc_writer_t *w,
                                                const mipc_filter_data_euler_angles_uncertainty_t *in) {
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
    if ((st = mipc_wr_u16(w, &in->valid_flags)) != MIPC_OK) {
        return st;
    }
    return MIPC_OK;
}

mipc_status_t
mipc_filter_data_euler_angles_uncertainty_encode(const mipc_filter_data_euler_angles_uncertainty_t *value,
                                                 uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mipc_writer_init(&w, buf, cap);
    st = mipc_filter_data_euler_angles_uncertainty_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 14 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mipc_filter_data_euler_angles_uncertainty_load(const uint8_t *d,
                                                          mipc_filter_data_euler_angles_uncertainty_t *out) {
    out->roll = mipc_ld_f32(d + 0);
    out->pitch = mipc_ld_f32(d + 4);
    out->yaw = mipc_ld_f32(d + 8);
    out->valid_flags = mipc_ld_u16(d + 12);
    return 0;
}

/* The general reader: lengths other than 14, bad bool bytes, error details. */
static MIPC_NOINLINE mipc_status_t mipc_filter_data_euler_angles_uncertainty_decode_read(
    const uint8_t *data, size_t len, mipc_filter_data_euler_angles_uncertainty_t *out,
    mipc_decode_error_t *err) {
    mipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_filter_data_euler_angles_uncertainty_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t
mipc_filter_data_euler_angles_uncertainty_decode(const uint8_t *data, size_t len,
                                                 mipc_filter_data_euler_angles_uncertainty_t *out,
                                                 mipc_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 14 && mipc_filter_data_euler_angles_uncertainty_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_filter_data_euler_angles_uncertainty_decode_read(data, len, out, err);
}

/* ---- mipc_filter_data_gyro_bias_uncertainty_t */

static int mipc_filter_data_gyro_bias_uncertainty_read(mipc_reader_t *r,
                                                       mipc_filter_data_gyro_bias_uncertainty_t *out) {
    size_t i;
    mipc_rd_push(r, "bias_uncertainty");
    for (i = 0; i < 3; i++) {
        mipc_rd_index(r, i);
        if (mipc_rd_f32(r, &out->bias_uncertainty[i])) {
            return -1;
        }
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "valid_flags");
    if (mipc_rd_u16(r, &out->valid_flags)) {
        return -1;
    }
    mipc_rd_pop(r);
    return mipc_rd_finish(r);
}

static mipc_status_t
mipc_filter_data_gyro_bias_uncertainty_write(mipc_writer_t *w,
                                             const mipc_filter_data_gyro_bias_uncertainty_t *in) {
    mipc_status_t st;
    size_t i;
    for (i = 0; i < 3; i++) {
        if ((st = mipc_wr_f32(w, &in->bias_uncertainty[i])) != MIPC_OK) {
            return st;
        }
    }
    if ((st = mipc_wr_u16(w, &in->valid_flags)) != MIPC_OK) {
        return st;
    }
    return MIPC_OK;
}

mipc_status_t
mipc_filter_data_gyro_bias_uncertainty_encode(const mipc_filter_data_gyro_bias_uncertainty_t *value,
                                              uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mipc_writer_init(&w, buf, cap);
    st = mipc_filter_data_gyro_bias_uncertainty_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 14 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mipc_filter_data_gyro_bias_uncertainty_load(const uint8_t *d,
                                                       mipc_filter_data_gyro_bias_uncertainty_t *out) {
    out->bias_uncertainty[0] = mipc_ld_f32(d + 0);
    out->bias_uncertainty[1] = mipc_ld_f32(d + 4);
    out->bias_uncertainty[2] = mipc_ld_f32(d + 8);
    out->valid_flags = mipc_ld_u16(d + 12);
    return 0;
}

/* The general reader: lengths other than 14, bad bool bytes, error details. */
static MIPC_NOINLINE mipc_status_t mipc_filter_data_gyro_bias_uncertainty_decode_read(
    const uint8_t *data, size_t len, mipc_filter_data_gyro_bias_uncertainty_t *out,
    mipc_decode_error_t *err) {
    mipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_filter_data_gyro_bias_uncertainty_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t mipc_filter_data_gyro_bias_uncertainty_decode(const uint8_t *data, size_t len,
                                                            mipc_filter_data_gyro_bias_uncertainty_t *out,
                                                            mipc_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 14 && mipc_filter_data_gyro_bias_uncertainty_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_filter_data_gyro_bias_uncertainty_decode_read(data, len, out, err);
}

/* ---- mipc_filter_data_accel_bias_uncertainty_t */

static int mipc_filter_data_accel_bias_uncertainty_read(mipc_reader_t *r,
                                                        mipc_filter_data_accel_bias_uncertainty_t *out) {
    size_t i;
    mipc_rd_push(r, "bias_uncertainty");
    for (i = 0; i < 3; i++) {
        mipc_rd_index(r, i);
        if (mipc_rd_f32(r, &out->bias_uncertainty[i])) {
            return -1;
        }
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "valid_flags");
    if (mipc_rd_u16(r, &out->valid_flags)) {
        return -1;
    }
    mipc_rd_pop(r);
    return mipc_rd_finish(r);
}

static mipc_status_t
mipc_filter_data_accel_bias_uncertainty_write(mipc_writer_t *w,
                                              const mipc_filter_data_accel_bias_uncertainty_t *in) {
    mipc_status_t st;
    size_t i;
    for (i = 0; i < 3; i++) {
        if ((st = mipc_wr_f32(w, &in->bias_uncertainty[i])) != MIPC_OK) {
            return st;
        }
    }
    if ((st = mipc_wr_u16(w, &in->valid_flags)) != MIPC_OK) {
        return st;
    }
    return MIPC_OK;
}

mipc_status_t
mipc_filter_data_accel_bias_uncertainty_encode(const mipc_filter_data_accel_bias_uncertainty_t *value,
                                               uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mipc_writer_init(&w, buf, cap);
    st = mipc_filter_data_accel_bias_uncertainty_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 14 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mipc_filter_data_accel_bias_uncertainty_load(const uint8_t *d,
                                                        mipc_filter_data_accel_bias_uncertainty_t *out) {
    out->bias_uncertainty[0] = mipc_ld_f32(d + 0);
    out->bias_uncertainty[1] = mipc_ld_f32(d + 4);
    out->bias_uncertainty[2] = mipc_ld_f32(d + 8);
    out->valid_flags = mipc_ld_u16(d + 12);
    return 0;
}

/* The general reader: lengths other than 14, bad bool bytes, error details. */
static MIPC_NOINLINE mipc_status_t mipc_filter_data_accel_bias_uncertainty_decode_read(
    const uint8_t *data, size_t len, mipc_filter_data_accel_bias_uncertainty_t *out,
    mipc_decode_error_t *err) {
    mipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_filter_data_accel_bias_uncertainty_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t mipc_filter_data_accel_bias_uncertainty_decode(const uint8_t *data, size_t len,
                                                             mipc_filter_data_accel_bias_uncertainty_t *out,
                                                             mipc_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 14 && mipc_filter_data_accel_bias_uncertainty_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_filter_data_accel_bias_uncertainty_decode_read(data, len, out, err);
}

/* ---- mipc_filter_data_linear_accel_t */

static int mipc_filter_data_linear_accel_read(mipc_reader_t *r, mipc_filter_data_linear_accel_t *out) {
    size_t i;
    mipc_rd_push(r, "accel");
    for (i = 0; i < 3; i++) {
        mipc_rd_index(r, i);
        if (mipc_rd_f32(r, &out->accel[i])) {
            return -1;
        }
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "valid_flags");
    if (mipc_rd_u16(r, &out->valid_flags)) {
        return -1;
    }
    mipc_rd_pop(r);
    return mipc_rd_finish(r);
}

static mipc_status_t mipc_filter_data_linear_accel_write(mipc_writer_t *w,
                                                         const mipc_filter_data_linear_accel_t *in) {
    mipc_status_t st;
    size_t i;
    for (i = 0; i < 3; i++) {
        if ((st = mipc_wr_f32(w, &in->accel[i])) != MIPC_OK) {
            return st;
        }
    }
    if ((st = mipc_wr_u16(w, &in->valid_flags)) != MIPC_OK) {
        return st;
    }
    return MIPC_OK;
}

mipc_status_t mipc_filter_data_linear_accel_encode(const mipc_filter_data_linear_accel_t *value, uint8_t *buf,
                                                   size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mipc_writer_init(&w, buf, cap);
    st = mipc_filter_data_linear_accel_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 14 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mipc_filter_data_linear_accel_load(const uint8_t *d, mipc_filter_data_linear_accel_t *out) {
    out->accel[0] = mipc_ld_f32(d + 0);
    out->accel[1] = mipc_ld_f32(d + 4);
    out->accel[2] = mipc_ld_f32(d + 8);
    out->valid_flags = mipc_ld_u16(d + 12);
    return 0;
}

/* The general reader: lengths other than 14, bad bool bytes, error details. */
static MIPC_NOINLINE mipc_status_t mipc_filter_data_linear_accel_decode_read(
    const uint8_t *data, size_t len, mipc_filter_data_linear_accel_t *out, mipc_decode_error_t *err) {
    mipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_filter_data_linear_accel_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t mipc_filter_data_linear_accel_decode(const uint8_t *data, size_t len,
                                                   mipc_filter_data_linear_accel_t *out,
                                                   mipc_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 14 && mipc_filter_data_linear_accel_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_filter_data_linear_accel_decode_read(data, len, out, err);
}

/* ---- mipc_filter_data_comp_angular_rate_t */

static int mipc_filter_data_comp_angular_rate_read(mipc_reader_t *r,
                                                   mipc_filter_data_comp_angular_rate_t *out) {
    size_t i;
    mipc_rd_push(r, "gyro");
    for (i = 0; i < 3; i++) {
        mipc_rd_index(r, i);
        if (mipc_rd_f32(r, &out->gyro[i])) {
            return -1;
        }
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "valid_flags");
    if (mipc_rd_u16(r, &out->valid_flags)) {
        return -1;
    }
    mipc_rd_pop(r);
    return mipc_rd_finish(r);
}

static mipc_status_t
mipc_filter_data_comp_angular_rate_write(mipc_writer_t *w, const mipc_filter_data_comp_angular_rate_t *in) {
    mipc_status_t st;
    size_t i;
    for (i = 0; i < 3; i++) {
        if ((st = mipc_wr_f32(w, &in->gyro[i])) != MIPC_OK) {
            return st;
        }
    }
    if ((st = mipc_wr_u16(w, &in->valid_flags)) != MIPC_OK) {
        return st;
    }
    return MIPC_OK;
}

mipc_status_t mipc_filter_data_comp_angular_rate_encode(const mipc_filter_data_comp_angular_rate_t *value,
                                                        uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mipc_writer_init(&w, buf, cap);
    st = mipc_filter_data_comp_angular_rate_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 14 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mipc_filter_data_comp_angular_rate_load(const uint8_t *d,
                                                   mipc_filter_data_comp_angular_rate_t *out) {
    out->gyro[0] = mipc_ld_f32(d + 0);
    out->gyro[1] = mipc_ld_f32(d + 4);
    out->gyro[2] = mipc_ld_f32(d + 8);
    out->valid_flags = mipc_ld_u16(d + 12);
    return 0;
}

/* The general reader: lengths other than 14, bad bool bytes, error details. */
static MIPC_NOINLINE mipc_status_t mipc_filter_data_comp_angular_rate_decode_read(
    const uint8_t *data, size_t len, mipc_filter_data_comp_angular_rate_t *out, mipc_decode_error_t *err) {
    mipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_filter_data_comp_angular_rate_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t mipc_filter_data_comp_angular_rate_decode(const uint8_t *data, size_t len,
                                                        mipc_filter_data_comp_angular_rate_t *out,
                                                        mipc_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 14 && mipc_filter_data_comp_angular_rate_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_filter_data_comp_angular_rate_decode_read(data, len, out, err);
}

/* ---- mipc_filter_data_wgs84_gravity_magnitude_t */

static int mipc_filter_data_wgs84_gravity_magnitude_read(mipc_reader_t *r,
                                                         mipc_filter_data_wgs84_gravity_magnitude_t *out) {
    mipc_rd_push(r, "gravity_magnitude");
    if (mipc_rd_f32(r, &out->gravity_magnitude)) {
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

static mipc_status_t
mipc_filter_data_wgs84_gravity_magnitude_write(mipc_writer_t *w,
                                               const mipc_filter_data_wgs84_gravity_magnitude_t *in) {
    mipc_status_t st;
    if ((st = mipc_wr_f32(w, &in->gravity_magnitude)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u16(w, &in->valid_flags)) != MIPC_OK) {
        return st;
    }
    return MIPC_OK;
}

mipc_status_t
mipc_filter_data_wgs84_gravity_magnitude_encode(const mipc_filter_data_wgs84_gravity_magnitude_t *value,
                                                uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mipc_writer_init(&w, buf, cap);
    st = mipc_filter_data_wgs84_gravity_magnitude_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 6 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mipc_filter_data_wgs84_gravity_magnitude_load(const uint8_t *d,
                                                         mipc_filter_data_wgs84_gravity_magnitude_t *out) {
    out->gravity_magnitude = mipc_ld_f32(d + 0);
    out->valid_flags = mipc_ld_u16(d + 4);
    return 0;
}

/* The general reader: lengths other than 6, bad bool bytes, error details. */
static MIPC_NOINLINE mipc_status_t mipc_filter_data_wgs84_gravity_magnitude_decode_read(
    const uint8_t *data, size_t len, mipc_filter_data_wgs84_gravity_magnitude_t *out,
    mipc_decode_error_t *err) {
    mipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_filter_data_wgs84_gravity_magnitude_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t mipc_filter_data_wgs84_gravity_magnitude_decode(const uint8_t *data, size_t len,
                                                              mipc_filter_data_wgs84_gravity_magnitude_t *out,
                                                              mipc_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 6 && mipc_filter_data_wgs84_gravity_magnitude_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_filter_data_wgs84_gravity_magnitude_decode_read(data, len, out, err);
}

/* ---- mipc_filter_data_filter_status_gx5_45_t */

static int mipc_filter_data_filter_status_gx5_45_read(mipc_reader_t *r,
                                                      mipc_filter_data_filter_status_gx5_45_t *out) {
    mipc_rd_push(r, "filter_state");
    if (mipc_rd_u16(r, &out->filter_state)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "dynamics_mode");
    if (mipc_rd_u16(r, &out->dynamics_mode)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "status_flags");
    if (mipc_rd_u16(r, &out->status_flags)) {
        return -1;
    }
    mipc_rd_pop(r);
    return mipc_rd_finish(r);
}

static mipc_status_t
mipc_filter_data_filter_status_gx5_45_write(mipc_writer_t *w,
                                            const mipc_filter_data_filter_status_gx5_45_t *in) {
    mipc_status_t st;
    if ((st = mipc_wr_u16(w, &in->filter_state)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u16(w, &in->dynamics_mode)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u16(w, &in->status_flags)) != MIPC_OK) {
        return st;
    }
    return MIPC_OK;
}

mipc_status_t
mipc_filter_data_filter_status_gx5_45_encode(const mipc_filter_data_filter_status_gx5_45_t *value,
                                             uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mipc_writer_init(&w, buf, cap);
    st = mipc_filter_data_filter_status_gx5_45_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 6 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mipc_filter_data_filter_status_gx5_45_load(const uint8_t *d,
                                                      mipc_filter_data_filter_status_gx5_45_t *out) {
    out->filter_state = mipc_ld_u16(d + 0);
    out->dynamics_mode = mipc_ld_u16(d + 2);
    out->status_flags = mipc_ld_u16(d + 4);
    return 0;
}

/* The general reader: lengths other than 6, bad bool bytes, error details. */
static MIPC_NOINLINE mipc_status_t mipc_filter_data_filter_status_gx5_45_decode_read(
    const uint8_t *data, size_t len, mipc_filter_data_filter_status_gx5_45_t *out, mipc_decode_error_t *err) {
    mipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_filter_data_filter_status_gx5_45_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t mipc_filter_data_filter_status_gx5_45_decode(const uint8_t *data, size_t len,
                                                           mipc_filter_data_filter_status_gx5_45_t *out,
                                                           mipc_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 6 && mipc_filter_data_filter_status_gx5_45_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_filter_data_filter_status_gx5_45_decode_read(data, len, out, err);
}

/* ---- mipc_filter_data_filter_status_cv7_ins_t */

static int mipc_filter_data_filter_status_cv7_ins_read(mipc_reader_t *r,
                                                       mipc_filter_data_filter_status_cv7_ins_t *out) {
    mipc_rd_push(r, "filter_state");
    if (mipc_rd_u16(r, &out->filter_state)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "dynamics_mode");
    if (mipc_rd_u16(r, &out->dynamics_mode)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "status_flags");
    if (mipc_rd_u16(r, &out->status_flags)) {
        return -1;
    }
    mipc_rd_pop(r);
    return mipc_rd_finish(r);
}

static mipc_status_t
mipc_filter_data_filter_status_cv7_ins_write(mipc_writer_t *w,
                                             const mipc_filter_data_filter_status_cv7_ins_t *in) {
    mipc_status_t st;
    if ((st = mipc_wr_u16(w, &in->filter_state)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u16(w, &in->dynamics_mode)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u16(w, &in->status_flags)) != MIPC_OK) {
        return st;
    }
    return MIPC_OK;
}

mipc_status_t
mipc_filter_data_filter_status_cv7_ins_encode(const mipc_filter_data_filter_status_cv7_ins_t *value,
                                              uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mipc_writer_init(&w, buf, cap);
    st = mipc_filter_data_filter_status_cv7_ins_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 6 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mipc_filter_data_filter_status_cv7_ins_load(const uint8_t *d,
                                                       mipc_filter_data_filter_status_cv7_ins_t *out) {
    out->filter_state = mipc_ld_u16(d + 0);
    out->dynamics_mode = mipc_ld_u16(d + 2);
    out->status_flags = mipc_ld_u16(d + 4);
    return 0;
}

/* The general reader: lengths other than 6, bad bool bytes, error details. */
static MIPC_NOINLINE mipc_status_t mipc_filter_data_filter_status_cv7_ins_decode_read(
    const uint8_t *data, size_t len, mipc_filter_data_filter_status_cv7_ins_t *out,
    mipc_decode_error_t *err) {
    mipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_filter_data_filter_status_cv7_ins_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t mipc_filter_data_filter_status_cv7_ins_decode(const uint8_t *data, size_t len,
                                                            mipc_filter_data_filter_status_cv7_ins_t *out,
                                                            mipc_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 6 && mipc_filter_data_filter_status_cv7_ins_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_filter_data_filter_status_cv7_ins_decode_read(data, len, out, err);
}

/* ---- mipc_filter_data_gps_timestamp_t */

static int mipc_filter_data_gps_timestamp_read(mipc_reader_t *r, mipc_filter_data_gps_timestamp_t *out) {
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

static mipc_status_t mipc_filter_data_gps_timestamp_write(mipc_writer_t *w,
                                                          const mipc_filter_data_gps_timestamp_t *in) {
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

mipc_status_t mipc_filter_data_gps_timestamp_encode(const mipc_filter_data_gps_timestamp_t *value,
                                                    uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mipc_writer_init(&w, buf, cap);
    st = mipc_filter_data_gps_timestamp_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 12 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mipc_filter_data_gps_timestamp_load(const uint8_t *d, mipc_filter_data_gps_timestamp_t *out) {
    out->tow = mipc_ld_f64(d + 0);
    out->week_number = mipc_ld_u16(d + 8);
    out->valid_flags = mipc_ld_u16(d + 10);
    return 0;
}

/* The general reader: lengths other than 12, bad bool bytes, error details. */
static MIPC_NOINLINE mipc_status_t mipc_filter_data_gps_timestamp_decode_read(
    const uint8_t *data, size_t len, mipc_filter_data_gps_timestamp_t *out, mipc_decode_error_t *err) {
    mipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_filter_data_gps_timestamp_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t mipc_filter_data_gps_timestamp_decode(const uint8_t *data, size_t len,
                                                    mipc_filter_data_gps_timestamp_t *out,
                                                    mipc_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 12 && mipc_filter_data_gps_timestamp_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_filter_data_gps_timestamp_decode_read(data, len, out, err);
}

/* ---- mipc_filter_data_quaternion_attitude_uncertainty_t */

static int mipc_filter_data_quaternion_attitude_uncertainty_read(
    mipc_reader_t *r, mipc_filter_data_quaternion_attitude_uncertainty_t *out) {
    size_t i;
    mipc_rd_push(r, "q");
    for (i = 0; i < 4; i++) {
        mipc_rd_index(r, i);
        if (mipc_rd_f32(r, &out->q[i])) {
            return -1;
        }
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "valid_flags");
    if (mipc_rd_u16(r, &out->valid_flags)) {
        return -1;
    }
    mipc_rd_pop(r);
    return mipc_rd_finish(r);
}

static mipc_status_t mipc_filter_data_quaternion_attitude_uncertainty_write(
    mipc_writer_t *w, const mipc_filter_data_quaternion_attitude_uncertainty_t *in) {
    mipc_status_t st;
    size_t i;
    for (i = 0; i < 4; i++) {
        if ((st = mipc_wr_f32(w, &in->q[i])) != MIPC_OK) {
            return st;
        }
    }
    if ((st = mipc_wr_u16(w, &in->valid_flags)) != MIPC_OK) {
        return st;
    }
    return MIPC_OK;
}

mipc_status_t mipc_filter_data_quaternion_attitude_uncertainty_encode(
    const mipc_filter_data_quaternion_attitude_uncertainty_t *value, uint8_t *buf, size_t cap,
    size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mipc_writer_init(&w, buf, cap);
    st = mipc_filter_data_quaternion_attitude_uncertainty_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 18 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mipc_filter_data_quaternion_attitude_uncertainty_load(
    const uint8_t *d, mipc_filter_data_quaternion_attitude_uncertainty_t *out) {
    out->q[0] = mipc_ld_f32(d + 0);
    out->q[1] = mipc_ld_f32(d + 4);
    out->q[2] = mipc_ld_f32(d + 8);
    out->q[3] = mipc_ld_f32(d + 12);
    out->valid_flags = mipc_ld_u16(d + 16);
    return 0;
}

/* The general reader: lengths other than 18, bad bool bytes, error details. */
static MIPC_NOINLINE mipc_status_t mipc_filter_data_quaternion_attitude_uncertainty_decode_read(
    const uint8_t *data, size_t len, mipc_filter_data_quaternion_attitude_uncertainty_t *out,
    mipc_decode_error_t *err) {
    mipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_filter_data_quaternion_attitude_uncertainty_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t mipc_filter_data_quaternion_attitude_uncertainty_decode(
    const uint8_t *data, size_t len, mipc_filter_data_quaternion_attitude_uncertainty_t *out,
    mipc_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 18 && mipc_filter_data_quaternion_attitude_uncertainty_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_filter_data_quaternion_attitude_uncertainty_decode_read(data, len, out, err);
}

/* ---- mipc_filter_data_gravity_vector_t */

static int mipc_filter_data_gravity_vector_read(mipc_reader_t *r, mipc_filter_data_gravity_vector_t *out) {
    size_t i;
    mipc_rd_push(r, "gravity");
    for (i = 0; i < 3; i++) {
        mipc_rd_index(r, i);
        if (mipc_rd_f32(r, &out->gravity[i])) {
            return -1;
        }
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "valid_flags");
    if (mipc_rd_u16(r, &out->valid_flags)) {
        return -1;
    }
    mipc_rd_pop(r);
    return mipc_rd_finish(r);
}

static mipc_status_t mipc_filter_data_gravity_vector_write(mipc_writer_t *w,
                                                           const mipc_filter_data_gravity_vector_t *in) {
    mipc_status_t st;
    size_t i;
    for (i = 0; i < 3; i++) {
        if ((st = mipc_wr_f32(w, &in->gravity[i])) != MIPC_OK) {
            return st;
        }
    }
    if ((st = mipc_wr_u16(w, &in->valid_flags)) != MIPC_OK) {
        return st;
    }
    return MIPC_OK;
}

mipc_status_t mipc_filter_data_gravity_vector_encode(const mipc_filter_data_gravity_vector_t *value,
                                                     uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mipc_writer_init(&w, buf, cap);
    st = mipc_filter_data_gravity_vector_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 14 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mipc_filter_data_gravity_vector_load(const uint8_t *d, mipc_filter_data_gravity_vector_t *out) {
    out->gravity[0] = mipc_ld_f32(d + 0);
    out->gravity[1] = mipc_ld_f32(d + 4);
    out->gravity[2] = mipc_ld_f32(d + 8);
    out->valid_flags = mipc_ld_u16(d + 12);
    return 0;
}

/* The general reader: lengths other than 14, bad bool bytes, error details. */
static MIPC_NOINLINE mipc_status_t mipc_filter_data_gravity_vector_decode_read(
    const uint8_t *data, size_t len, mipc_filter_data_gravity_vector_t *out, mipc_decode_error_t *err) {
    mipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_filter_data_gravity_vector_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t mipc_filter_data_gravity_vector_decode(const uint8_t *data, size_t len,
                                                     mipc_filter_data_gravity_vector_t *out,
                                                     mipc_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 14 && mipc_filter_data_gravity_vector_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_filter_data_gravity_vector_decode_read(data, len, out, err);
}

/* ---- mipc_filter_data_heading_update_state_t */

static int mipc_filter_data_heading_update_state_read(mipc_reader_t *r,
                                                      mipc_filter_data_heading_update_state_t *out) {
    mipc_rd_push(r, "heading");
    if (mipc_rd_f32(r, &out->heading)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "heading_uncertainty");
    if (mipc_rd_f32(r, &out->heading_uncertainty)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "source");
    if (mipc_rd_u16(r, &out->source)) {
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

static mipc_status_t
mipc_filter_data_heading_update_state_write(mipc_writer_t *w,
                                            const mipc_filter_data_heading_update_state_t *in) {
    mipc_status_t st;
    if ((st = mipc_wr_f32(w, &in->heading)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_f32(w, &in->heading_uncertainty)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u16(w, &in->source)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u16(w, &in->valid_flags)) != MIPC_OK) {
        return st;
    }
    return MIPC_OK;
}

mipc_status_t
mipc_filter_data_heading_update_state_encode(const mipc_filter_data_heading_update_state_t *value,
                                             uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mipc_writer_init(&w, buf, cap);
    st = mipc_filter_data_heading_update_state_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 12 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mipc_filter_data_heading_update_state_load(const uint8_t *d,
                                                      mipc_filter_data_heading_update_state_t *out) {
    out->heading = mipc_ld_f32(d + 0);
    out->heading_uncertainty = mipc_ld_f32(d + 4);
    out->source = mipc_ld_u16(d + 8);
    out->valid_flags = mipc_ld_u16(d + 10);
    return 0;
}

/* The general reader: lengths other than 12, bad bool bytes, error details. */
static MIPC_NOINLINE mipc_status_t mipc_filter_data_heading_update_state_decode_read(
    const uint8_t *data, size_t len, mipc_filter_data_heading_update_state_t *out, mipc_decode_error_t *err) {
    mipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_filter_data_heading_update_state_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t mipc_filter_data_heading_update_state_decode(const uint8_t *data, size_t len,
                                                           mipc_filter_data_heading_update_state_t *out,
                                                           mipc_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 12 && mipc_filter_data_heading_update_state_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_filter_data_heading_update_state_decode_read(data, len, out, err);
}

/* ---- mipc_filter_data_magnetic_model_t */

static int mipc_filter_data_magnetic_model_read(mipc_reader_t *r, mipc_filter_data_magnetic_model_t *out) {
    mipc_rd_push(r, "intensity_north");
    if (mipc_rd_f32(r, &out->intensity_north)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "intensity_east");
    if (mipc_rd_f32(r, &out->intensity_east)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "intensity_down");
    if (mipc_rd_f32(r, &out->intensity_down)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "inclination");
    if (mipc_rd_f32(r, &out->inclination)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "declination");
    if (mipc_rd_f32(r, &out->declination)) {
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

static mipc_status_t mipc_filter_data_magnetic_model_write(mipc_writer_t *w,
                                                           const mipc_filter_data_magnetic_model_t *in) {
    mipc_status_t st;
    if ((st = mipc_wr_f32(w, &in->intensity_north)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_f32(w, &in->intensity_east)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_f32(w, &in->intensity_down)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_f32(w, &in->inclination)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_f32(w, &in->declination)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u16(w, &in->valid_flags)) != MIPC_OK) {
        return st;
    }
    return MIPC_OK;
}

mipc_status_t mipc_filter_data_magnetic_model_encode(const mipc_filter_data_magnetic_model_t *value,
                                                     uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mipc_writer_init(&w, buf, cap);
    st = mipc_filter_data_magnetic_model_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 22 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mipc_filter_data_magnetic_model_load(const uint8_t *d, mipc_filter_data_magnetic_model_t *out) {
    out->intensity_north = mipc_ld_f32(d + 0);
    out->intensity_east = mipc_ld_f32(d + 4);
    out->intensity_down = mipc_ld_f32(d + 8);
    out->inclination = mipc_ld_f32(d + 12);
    out->declination = mipc_ld_f32(d + 16);
    out->valid_flags = mipc_ld_u16(d + 20);
    return 0;
}

/* The general reader: lengths other than 22, bad bool bytes, error details. */
static MIPC_NOINLINE mipc_status_t mipc_filter_data_magnetic_model_decode_read(
    const uint8_t *data, size_t len, mipc_filter_data_magnetic_model_t *out, mipc_decode_error_t *err) {
    mipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_filter_data_magnetic_model_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t mipc_filter_data_magnetic_model_decode(const uint8_t *data, size_t len,
                                                     mipc_filter_data_magnetic_model_t *out,
                                                     mipc_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 22 && mipc_filter_data_magnetic_model_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_filter_data_magnetic_model_decode_read(data, len, out, err);
}

/* ---- mipc_filter_data_gyro_scale_factor_t */

static int mipc_filter_data_gyro_scale_factor_read(mipc_reader_t *r,
                                                   mipc_filter_data_gyro_scale_factor_t *out) {
    size_t i;
    mipc_rd_push(r, "scale_factor");
    for (i = 0; i < 3; i++) {
        mipc_rd_index(r, i);
        if (mipc_rd_f32(r, &out->scale_factor[i])) {
            return -1;
        }
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "valid_flags");
    if (mipc_rd_u16(r, &out->valid_flags)) {
        return -1;
    }
    mipc_rd_pop(r);
    return mipc_rd_finish(r);
}

static mipc_status_t
mipc_filter_data_gyro_scale_factor_write(mipc_writer_t *w, const mipc_filter_data_gyro_scale_factor_t *in) {
    mipc_status_t st;
    size_t i;
    for (i = 0; i < 3; i++) {
        if ((st = mipc_wr_f32(w, &in->scale_factor[i])) != MIPC_OK) {
            return st;
        }
    }
    if ((st = mipc_wr_u16(w, &in->valid_flags)) != MIPC_OK) {
        return st;
    }
    return MIPC_OK;
}

mipc_status_t mipc_filter_data_gyro_scale_factor_encode(const mipc_filter_data_gyro_scale_factor_t *value,
                                                        uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mipc_writer_init(&w, buf, cap);
    st = mipc_filter_data_gyro_scale_factor_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 14 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mipc_filter_data_gyro_scale_factor_load(const uint8_t *d,
                                                   mipc_filter_data_gyro_scale_factor_t *out) {
    out->scale_factor[0] = mipc_ld_f32(d + 0);
    out->scale_factor[1] = mipc_ld_f32(d + 4);
    out->scale_factor[2] = mipc_ld_f32(d + 8);
    out->valid_flags = mipc_ld_u16(d + 12);
    return 0;
}

/* The general reader: lengths other than 14, bad bool bytes, error details. */
static MIPC_NOINLINE mipc_status_t mipc_filter_data_gyro_scale_factor_decode_read(
    const uint8_t *data, size_t len, mipc_filter_data_gyro_scale_factor_t *out, mipc_decode_error_t *err) {
    mipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_filter_data_gyro_scale_factor_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t mipc_filter_data_gyro_scale_factor_decode(const uint8_t *data, size_t len,
                                                        mipc_filter_data_gyro_scale_factor_t *out,
                                                        mipc_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 14 && mipc_filter_data_gyro_scale_factor_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_filter_data_gyro_scale_factor_decode_read(data, len, out, err);
}

/* ---- mipc_filter_data_accel_scale_factor_t */

static int mipc_filter_data_accel_scale_factor_read(mipc_reader_t *r,
                                                    mipc_filter_data_accel_scale_factor_t *out) {
    size_t i;
    mipc_rd_push(r, "scale_factor");
    for (i = 0; i < 3; i++) {
        mipc_rd_index(r, i);
        if (mipc_rd_f32(r, &out->scale_factor[i])) {
            return -1;
        }
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "valid_flags");
    if (mipc_rd_u16(r, &out->valid_flags)) {
        return -1;
    }
    mipc_rd_pop(r);
    return mipc_rd_finish(r);
}

static mipc_status_t
mipc_filter_data_accel_scale_factor_write(mipc_writer_t *w, const mipc_filter_data_accel_scale_factor_t *in) {
    mipc_status_t st;
    size_t i;
    for (i = 0; i < 3; i++) {
        if ((st = mipc_wr_f32(w, &in->scale_factor[i])) != MIPC_OK) {
            return st;
        }
    }
    if ((st = mipc_wr_u16(w, &in->valid_flags)) != MIPC_OK) {
        return st;
    }
    return MIPC_OK;
}

mipc_status_t mipc_filter_data_accel_scale_factor_encode(const mipc_filter_data_accel_scale_factor_t *value,
                                                         uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mipc_writer_init(&w, buf, cap);
    st = mipc_filter_data_accel_scale_factor_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 14 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mipc_filter_data_accel_scale_factor_load(const uint8_t *d,
                                                    mipc_filter_data_accel_scale_factor_t *out) {
    out->scale_factor[0] = mipc_ld_f32(d + 0);
    out->scale_factor[1] = mipc_ld_f32(d + 4);
    out->scale_factor[2] = mipc_ld_f32(d + 8);
    out->valid_flags = mipc_ld_u16(d + 12);
    return 0;
}

/* The general reader: lengths other than 14, bad bool bytes, error details. */
static MIPC_NOINLINE mipc_status_t mipc_filter_data_accel_scale_factor_decode_read(
    const uint8_t *data, size_t len, mipc_filter_data_accel_scale_factor_t *out, mipc_decode_error_t *err) {
    mipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_filter_data_accel_scale_factor_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t mipc_filter_data_accel_scale_factor_decode(const uint8_t *data, size_t len,
                                                         mipc_filter_data_accel_scale_factor_t *out,
                                                         mipc_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 14 && mipc_filter_data_accel_scale_factor_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_filter_data_accel_scale_factor_decode_read(data, len, out, err);
}

/* ---- mipc_filter_data_gyro_scale_factor_uncertainty_t */

static int
mipc_filter_data_gyro_scale_factor_uncertainty_read(mipc_reader_t *r,
                                                    mipc_filter_data_gyro_scale_factor_uncertainty_t *out) {
    size_t i;
    mipc_rd_push(r, "scale_factor_uncertainty");
    for (i = 0; i < 3; i++) {
        mipc_rd_index(r, i);
        if (mipc_rd_f32(r, &out->scale_factor_uncertainty[i])) {
            return -1;
        }
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "valid_flags");
    if (mipc_rd_u16(r, &out->valid_flags)) {
        return -1;
    }
    mipc_rd_pop(r);
    return mipc_rd_finish(r);
}

static mipc_status_t mipc_filter_data_gyro_scale_factor_uncertainty_write(
    mipc_writer_t *w, const mipc_filter_data_gyro_scale_factor_uncertainty_t *in) {
    mipc_status_t st;
    size_t i;
    for (i = 0; i < 3; i++) {
        if ((st = mipc_wr_f32(w, &in->scale_factor_uncertainty[i])) != MIPC_OK) {
            return st;
        }
    }
    if ((st = mipc_wr_u16(w, &in->valid_flags)) != MIPC_OK) {
        return st;
    }
    return MIPC_OK;
}

mipc_status_t mipc_filter_data_gyro_scale_factor_uncertainty_encode(
    const mipc_filter_data_gyro_scale_factor_uncertainty_t *value, uint8_t *buf, size_t cap,
    size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mipc_writer_init(&w, buf, cap);
    st = mipc_filter_data_gyro_scale_factor_uncertainty_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 14 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int
mipc_filter_data_gyro_scale_factor_uncertainty_load(const uint8_t *d,
                                                    mipc_filter_data_gyro_scale_factor_uncertainty_t *out) {
    out->scale_factor_uncertainty[0] = mipc_ld_f32(d + 0);
    out->scale_factor_uncertainty[1] = mipc_ld_f32(d + 4);
    out->scale_factor_uncertainty[2] = mipc_ld_f32(d + 8);
    out->valid_flags = mipc_ld_u16(d + 12);
    return 0;
}

/* The general reader: lengths other than 14, bad bool bytes, error details. */
static MIPC_NOINLINE mipc_status_t mipc_filter_data_gyro_scale_factor_uncertainty_decode_read(
    const uint8_t *data, size_t len, mipc_filter_data_gyro_scale_factor_uncertainty_t *out,
    mipc_decode_error_t *err) {
    mipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_filter_data_gyro_scale_factor_uncertainty_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t
mipc_filter_data_gyro_scale_factor_uncertainty_decode(const uint8_t *data, size_t len,
                                                      mipc_filter_data_gyro_scale_factor_uncertainty_t *out,
                                                      mipc_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 14 && mipc_filter_data_gyro_scale_factor_uncertainty_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_filter_data_gyro_scale_factor_uncertainty_decode_read(data, len, out, err);
}

/* ---- mipc_filter_data_accel_scale_factor_uncertainty_t */

static int
mipc_filter_data_accel_scale_factor_uncertainty_read(mipc_reader_t *r,
                                                     mipc_filter_data_accel_scale_factor_uncertainty_t *out) {
    size_t i;
    mipc_rd_push(r, "scale_factor_uncertainty");
    for (i = 0; i < 3; i++) {
        mipc_rd_index(r, i);
        if (mipc_rd_f32(r, &out->scale_factor_uncertainty[i])) {
            return -1;
        }
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "valid_flags");
    if (mipc_rd_u16(r, &out->valid_flags)) {
        return -1;
    }
    mipc_rd_pop(r);
    return mipc_rd_finish(r);
}

static mipc_status_t mipc_filter_data_accel_scale_factor_uncertainty_write(
    mipc_writer_t *w, const mipc_filter_data_accel_scale_factor_uncertainty_t *in) {
    mipc_status_t st;
    size_t i;
    for (i = 0; i < 3; i++) {
        if ((st = mipc_wr_f32(w, &in->scale_factor_uncertainty[i])) != MIPC_OK) {
            return st;
        }
    }
    if ((st = mipc_wr_u16(w, &in->valid_flags)) != MIPC_OK) {
        return st;
    }
    return MIPC_OK;
}

mipc_status_t mipc_filter_data_accel_scale_factor_uncertainty_encode(
    const mipc_filter_data_accel_scale_factor_uncertainty_t *value, uint8_t *buf, size_t cap,
    size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mipc_writer_init(&w, buf, cap);
    st = mipc_filter_data_accel_scale_factor_uncertainty_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 14 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int
mipc_filter_data_accel_scale_factor_uncertainty_load(const uint8_t *d,
                                                     mipc_filter_data_accel_scale_factor_uncertainty_t *out) {
    out->scale_factor_uncertainty[0] = mipc_ld_f32(d + 0);
    out->scale_factor_uncertainty[1] = mipc_ld_f32(d + 4);
    out->scale_factor_uncertainty[2] = mipc_ld_f32(d + 8);
    out->valid_flags = mipc_ld_u16(d + 12);
    return 0;
}

/* The general reader: lengths other than 14, bad bool bytes, error details. */
static MIPC_NOINLINE mipc_status_t mipc_filter_data_accel_scale_factor_uncertainty_decode_read(
    const uint8_t *data, size_t len, mipc_filter_data_accel_scale_factor_uncertainty_t *out,
    mipc_decode_error_t *err) {
    mipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_filter_data_accel_scale_factor_uncertainty_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t
mipc_filter_data_accel_scale_factor_uncertainty_decode(const uint8_t *data, size_t len,
                                                       mipc_filter_data_accel_scale_factor_uncertainty_t *out,
                                                       mipc_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 14 && mipc_filter_data_accel_scale_factor_uncertainty_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_filter_data_accel_scale_factor_uncertainty_decode_read(data, len, out, err);
}

/* ---- mipc_filter_data_compensated_accel_t */

static int mipc_filter_data_compensated_accel_read(mipc_reader_t *r,
                                                   mipc_filter_data_compensated_accel_t *out) {
    size_t i;
    mipc_rd_push(r, "accel");
    for (i = 0; i < 3; i++) {
        mipc_rd_index(r, i);
        if (mipc_rd_f32(r, &out->accel[i])) {
            return -1;
        }
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "valid_flags");
    if (mipc_rd_u16(r, &out->valid_flags)) {
        return -1;
    }
    mipc_rd_pop(r);
    return mipc_rd_finish(r);
}

static mipc_status_t
mipc_filter_data_compensated_accel_write(mipc_writer_t *w, const mipc_filter_data_compensated_accel_t *in) {
    mipc_status_t st;
    size_t i;
    for (i = 0; i < 3; i++) {
        if ((st = mipc_wr_f32(w, &in->accel[i])) != MIPC_OK) {
            return st;
        }
    }
    if ((st = mipc_wr_u16(w, &in->valid_flags)) != MIPC_OK) {
        return st;
    }
    return MIPC_OK;
}

mipc_status_t mipc_filter_data_compensated_accel_encode(const mipc_filter_data_compensated_accel_t *value,
                                                        uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mipc_writer_init(&w, buf, cap);
    st = mipc_filter_data_compensated_accel_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 14 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mipc_filter_data_compensated_accel_load(const uint8_t *d,
                                                   mipc_filter_data_compensated_accel_t *out) {
    out->accel[0] = mipc_ld_f32(d + 0);
    out->accel[1] = mipc_ld_f32(d + 4);
    out->accel[2] = mipc_ld_f32(d + 8);
    out->valid_flags = mipc_ld_u16(d + 12);
    return 0;
}

/* The general reader: lengths other than 14, bad bool bytes, error details. */
static MIPC_NOINLINE mipc_status_t mipc_filter_data_compensated_accel_decode_read(
    const uint8_t *data, size_t len, mipc_filter_data_compensated_accel_t *out, mipc_decode_error_t *err) {
    mipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_filter_data_compensated_accel_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t mipc_filter_data_compensated_accel_decode(const uint8_t *data, size_t len,
                                                        mipc_filter_data_compensated_accel_t *out,
                                                        mipc_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 14 && mipc_filter_data_compensated_accel_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_filter_data_compensated_accel_decode_read(data, len, out, err);
}

/* ---- mipc_filter_data_standard_atmosphere_t */

static int mipc_filter_data_standard_atmosphere_read(mipc_reader_t *r,
                                                     mipc_filter_data_standard_atmosphere_t *out) {
    mipc_rd_push(r, "geometric_altitude");
    if (mipc_rd_f32(r, &out->geometric_altitude)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "geopotential_altitude");
    if (mipc_rd_f32(r, &out->geopotential_altitude)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "temperature");
    if (mipc_rd_f32(r, &out->temperature)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "pressure");
    if (mipc_rd_f32(r, &out->pressure)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "density");
    if (mipc_rd_f32(r, &out->density)) {
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

static mipc_status_t
mipc_filter_data_standard_atmosphere_write(mipc_writer_t *w,
                                           const mipc_filter_data_standard_atmosphere_t *in) {
    mipc_status_t st;
    if ((st = mipc_wr_f32(w, &in->geometric_altitude)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_f32(w, &in->geopotential_altitude)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_f32(w, &in->temperature)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_f32(w, &in->pressure)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_f32(w, &in->density)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u16(w, &in->valid_flags)) != MIPC_OK) {
        return st;
    }
    return MIPC_OK;
}

mipc_status_t mipc_filter_data_standard_atmosphere_encode(const mipc_filter_data_standard_atmosphere_t *value,
                                                          uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mipc_writer_init(&w, buf, cap);
    st = mipc_filter_data_standard_atmosphere_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 22 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mipc_filter_data_standard_atmosphere_load(const uint8_t *d,
                                                     mipc_filter_data_standard_atmosphere_t *out) {
    out->geometric_altitude = mipc_ld_f32(d + 0);
    out->geopotential_altitude = mipc_ld_f32(d + 4);
    out->temperature = mipc_ld_f32(d + 8);
    out->pressure = mipc_ld_f32(d + 12);
    out->density = mipc_ld_f32(d + 16);
    out->valid_flags = mipc_ld_u16(d + 20);
    return 0;
}

/* The general reader: lengths other than 22, bad bool bytes, error details. */
static MIPC_NOINLINE mipc_status_t mipc_filter_data_standard_atmosphere_decode_read(
    const uint8_t *data, size_t len, mipc_filter_data_standard_atmosphere_t *out, mipc_decode_error_t *err) {
    mipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_filter_data_standard_atmosphere_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t mipc_filter_data_standard_atmosphere_decode(const uint8_t *data, size_t len,
                                                          mipc_filter_data_standard_atmosphere_t *out,
                                                          mipc_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 22 && mipc_filter_data_standard_atmosphere_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_filter_data_standard_atmosphere_decode_read(data, len, out, err);
}

/* ---- mipc_filter_data_pressure_altitude_t */

static int mipc_filter_data_pressure_altitude_read(mipc_reader_t *r,
                                                   mipc_filter_data_pressure_altitude_t *out) {
    mipc_rd_push(r, "pressure_altitude");
    if (mipc_rd_f32(r, &out->pressure_altitude)) {
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

static mipc_status_t
mipc_filter_data_pressure_altitude_write(mipc_writer_t *w, const mipc_filter_data_pressure_altitude_t *in) {
    mipc_status_t st;
    if ((st = mipc_wr_f32(w, &in->pressure_altitude)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u16(w, &in->valid_flags)) != MIPC_OK) {
        return st;
    }
    return MIPC_OK;
}

mipc_status_t mipc_filter_data_pressure_altitude_encode(const mipc_filter_data_pressure_altitude_t *value,
                                                        uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mipc_writer_init(&w, buf, cap);
    st = mipc_filter_data_pressure_altitude_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 6 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mipc_filter_data_pressure_altitude_load(const uint8_t *d,
                                                   mipc_filter_data_pressure_altitude_t *out) {
    out->pressure_altitude = mipc_ld_f32(d + 0);
    out->valid_flags = mipc_ld_u16(d + 4);
    return 0;
}

/* The general reader: lengths other than 6, bad bool bytes, error details. */
static MIPC_NOINLINE mipc_status_t mipc_filter_data_pressure_altitude_decode_read(
    const uint8_t *data, size_t len, mipc_filter_data_pressure_altitude_t *out, mipc_decode_error_t *err) {
    mipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_filter_data_pressure_altitude_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t mipc_filter_data_pressure_altitude_decode(const uint8_t *data, size_t len,
                                                        mipc_filter_data_pressure_altitude_t *out,
                                                        mipc_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 6 && mipc_filter_data_pressure_altitude_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_filter_data_pressure_altitude_decode_read(data, len, out, err);
}

/* ---- mipc_filter_data_mag_auto_hard_iron_offset_t */

static int
mipc_filter_data_mag_auto_hard_iron_offset_read(mipc_reader_t *r,
                                                mipc_filter_data_mag_auto_hard_iron_offset_t *out) {
    size_t i;
    mipc_rd_push(r, "hard_iron_offset");
    for (i = 0; i < 3; i++) {
        mipc_rd_index(r, i);
        if (mipc_rd_f32(r, &out->hard_iron_offset[i])) {
            return -1;
        }
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "valid_flags");
    if (mipc_rd_u16(r, &out->valid_flags)) {
        return -1;
    }
    mipc_rd_pop(r);
    return mipc_rd_finish(r);
}

static mipc_status_t
mipc_filter_data_mag_auto_hard_iron_offset_write(mipc_writer_t *w,
                                                 const mipc_filter_data_mag_auto_hard_iron_offset_t *in) {
    mipc_status_t st;
    size_t i;
    for (i = 0; i < 3; i++) {
        if ((st = mipc_wr_f32(w, &in->hard_iron_offset[i])) != MIPC_OK) {
            return st;
        }
    }
    if ((st = mipc_wr_u16(w, &in->valid_flags)) != MIPC_OK) {
        return st;
    }
    return MIPC_OK;
}

mipc_status_t
mipc_filter_data_mag_auto_hard_iron_offset_encode(const mipc_filter_data_mag_auto_hard_iron_offset_t *value,
                                                  uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mipc_writer_init(&w, buf, cap);
    st = mipc_filter_data_mag_auto_hard_iron_offset_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 14 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int
mipc_filter_data_mag_auto_hard_iron_offset_load(const uint8_t *d,
                                                mipc_filter_data_mag_auto_hard_iron_offset_t *out) {
    out->hard_iron_offset[0] = mipc_ld_f32(d + 0);
    out->hard_iron_offset[1] = mipc_ld_f32(d + 4);
    out->hard_iron_offset[2] = mipc_ld_f32(d + 8);
    out->valid_flags = mipc_ld_u16(d + 12);
    return 0;
}

/* The general reader: lengths other than 14, bad bool bytes, error details. */
static MIPC_NOINLINE mipc_status_t mipc_filter_data_mag_auto_hard_iron_offset_decode_read(
    const uint8_t *data, size_t len, mipc_filter_data_mag_auto_hard_iron_offset_t *out,
    mipc_decode_error_t *err) {
    mipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_filter_data_mag_auto_hard_iron_offset_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t
mipc_filter_data_mag_auto_hard_iron_offset_decode(const uint8_t *data, size_t len,
                                                  mipc_filter_data_mag_auto_hard_iron_offset_t *out,
                                                  mipc_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 14 && mipc_filter_data_mag_auto_hard_iron_offset_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_filter_data_mag_auto_hard_iron_offset_decode_read(data, len, out, err);
}

/* ---- mipc_filter_data_mag_auto_soft_iron_matrix_t */

static int
mipc_filter_data_mag_auto_soft_iron_matrix_read(mipc_reader_t *r,
                                                mipc_filter_data_mag_auto_soft_iron_matrix_t *out) {
    size_t i;
    mipc_rd_push(r, "soft_iron_matrix");
    for (i = 0; i < 9; i++) {
        mipc_rd_index(r, i);
        if (mipc_rd_f32(r, &out->soft_iron_matrix[i])) {
            return -1;
        }
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "valid_flags");
    if (mipc_rd_u16(r, &out->valid_flags)) {
        return -1;
    }
    mipc_rd_pop(r);
    return mipc_rd_finish(r);
}

static mipc_status_t
mipc_filter_data_mag_auto_soft_iron_matrix_write(mipc_writer_t *w,
                                                 const mipc_filter_data_mag_auto_soft_iron_matrix_t *in) {
    mipc_status_t st;
    size_t i;
    for (i = 0; i < 9; i++) {
        if ((st = mipc_wr_f32(w, &in->soft_iron_matrix[i])) != MIPC_OK) {
            return st;
        }
    }
    if ((st = mipc_wr_u16(w, &in->valid_flags)) != MIPC_OK) {
        return st;
    }
    return MIPC_OK;
}

mipc_status_t
mipc_filter_data_mag_auto_soft_iron_matrix_encode(const mipc_filter_data_mag_auto_soft_iron_matrix_t *value,
                                                  uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mipc_writer_init(&w, buf, cap);
    st = mipc_filter_data_mag_auto_soft_iron_matrix_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 38 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int
mipc_filter_data_mag_auto_soft_iron_matrix_load(const uint8_t *d,
                                                mipc_filter_data_mag_auto_soft_iron_matrix_t *out) {
    out->soft_iron_matrix[0] = mipc_ld_f32(d + 0);
    out->soft_iron_matrix[1] = mipc_ld_f32(d + 4);
    out->soft_iron_matrix[2] = mipc_ld_f32(d + 8);
    out->soft_iron_matrix[3] = mipc_ld_f32(d + 12);
    out->soft_iron_matrix[4] = mipc_ld_f32(d + 16);
    out->soft_iron_matrix[5] = mipc_ld_f32(d + 20);
    out->soft_iron_matrix[6] = mipc_ld_f32(d + 24);
    out->soft_iron_matrix[7] = mipc_ld_f32(d + 28);
    out->soft_iron_matrix[8] = mipc_ld_f32(d + 32);
    out->valid_flags = mipc_ld_u16(d + 36);
    return 0;
}

/* The general reader: lengths other than 38, bad bool bytes, error details. */
static MIPC_NOINLINE mipc_status_t mipc_filter_data_mag_auto_soft_iron_matrix_decode_read(
    const uint8_t *data, size_t len, mipc_filter_data_mag_auto_soft_iron_matrix_t *out,
    mipc_decode_error_t *err) {
    mipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_filter_data_mag_auto_soft_iron_matrix_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t
mipc_filter_data_mag_auto_soft_iron_matrix_decode(const uint8_t *data, size_t len,
                                                  mipc_filter_data_mag_auto_soft_iron_matrix_t *out,
                                                  mipc_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 38 && mipc_filter_data_mag_auto_soft_iron_matrix_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_filter_data_mag_auto_soft_iron_matrix_decode_read(data, len, out, err);
}

/* ---- mipc_filter_data_mag_auto_hard_iron_offset_uncertainty_t */

static int mipc_filter_data_mag_auto_hard_iron_offset_uncertainty_read(
    mipc_reader_t *r, mipc_filter_data_mag_auto_hard_iron_offset_uncertainty_t *out) {
    size_t i;
    mipc_rd_push(r, "hard_iron_offset_uncertainty");
    for (i = 0; i < 3; i++) {
        mipc_rd_index(r, i);
        if (mipc_rd_f32(r, &out->hard_iron_offset_uncertainty[i])) {
            return -1;
        }
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "valid_flags");
    if (mipc_rd_u16(r, &out->valid_flags)) {
        return -1;
    }
    mipc_rd_pop(r);
    return mipc_rd_finish(r);
}

static mipc_status_t mipc_filter_data_mag_auto_hard_iron_offset_uncertainty_write(
    mipc_writer_t *w, const mipc_filter_data_mag_auto_hard_iron_offset_uncertainty_t *in) {
    mipc_status_t st;
    size_t i;
    for (i = 0; i < 3; i++) {
        if ((st = mipc_wr_f32(w, &in->hard_iron_offset_uncertainty[i])) != MIPC_OK) {
            return st;
        }
    }
    if ((st = mipc_wr_u16(w, &in->valid_flags)) != MIPC_OK) {
        return st;
    }
    return MIPC_OK;
}

mipc_status_t mipc_filter_data_mag_auto_hard_iron_offset_uncertainty_encode(
    const mipc_filter_data_mag_auto_hard_iron_offset_uncertainty_t *value, uint8_t *buf, size_t cap,
    size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mipc_writer_init(&w, buf, cap);
    st = mipc_filter_data_mag_auto_hard_iron_offset_uncertainty_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 14 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mipc_filter_data_mag_auto_hard_iron_offset_uncertainty_load(
    const uint8_t *d, mipc_filter_data_mag_auto_hard_iron_offset_uncertainty_t *out) {
    out->hard_iron_offset_uncertainty[0] = mipc_ld_f32(d + 0);
    out->hard_iron_offset_uncertainty[1] = mipc_ld_f32(d + 4);
    out->hard_iron_offset_uncertainty[2] = mipc_ld_f32(d + 8);
    out->valid_flags = mipc_ld_u16(d + 12);
    return 0;
}

/* The general reader: lengths other than 14, bad bool bytes, error details. */
static MIPC_NOINLINE mipc_status_t mipc_filter_data_mag_auto_hard_iron_offset_uncertainty_decode_read(
    const uint8_t *data, size_t len, mipc_filter_data_mag_auto_hard_iron_offset_uncertainty_t *out,
    mipc_decode_error_t *err) {
    mipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_filter_data_mag_auto_hard_iron_offset_uncertainty_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t mipc_filter_data_mag_auto_hard_iron_offset_uncertainty_decode(
    const uint8_t *data, size_t len, mipc_filter_data_mag_auto_hard_iron_offset_uncertainty_t *out,
    mipc_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 14 && mipc_filter_data_mag_auto_hard_iron_offset_uncertainty_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_filter_data_mag_auto_hard_iron_offset_uncertainty_decode_read(data, len, out, err);
}

/* ---- mipc_filter_data_mag_auto_soft_iron_matrix_uncertainty_t */

static int mipc_filter_data_mag_auto_soft_iron_matrix_uncertainty_read(
    mipc_reader_t *r, mipc_filter_data_mag_auto_soft_iron_matrix_uncertainty_t *out) {
    size_t i;
    mipc_rd_push(r, "soft_iron_matrix_uncertainty");
    for (i = 0; i < 9; i++) {
        mipc_rd_index(r, i);
        if (mipc_rd_f32(r, &out->soft_iron_matrix_uncertainty[i])) {
            return -1;
        }
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "valid_flags");
    if (mipc_rd_u16(r, &out->valid_flags)) {
        return -1;
    }
    mipc_rd_pop(r);
    return mipc_rd_finish(r);
}

static mipc_status_t mipc_filter_data_mag_auto_soft_iron_matrix_uncertainty_write(
    mipc_writer_t *w, const mipc_filter_data_mag_auto_soft_iron_matrix_uncertainty_t *in) {
    mipc_status_t st;
    size_t i;
    for (i = 0; i < 9; i++) {
        if ((st = mipc_wr_f32(w, &in->soft_iron_matrix_uncertainty[i])) != MIPC_OK) {
            return st;
        }
    }
    if ((st = mipc_wr_u16(w, &in->valid_flags)) != MIPC_OK) {
        return st;
    }
    return MIPC_OK;
}

mipc_status_t mipc_filter_data_mag_auto_soft_iron_matrix_uncertainty_encode(
    const mipc_filter_data_mag_auto_soft_iron_matrix_uncertainty_t *value, uint8_t *buf, size_t cap,
    size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mipc_writer_init(&w, buf, cap);
    st = mipc_filter_data_mag_auto_soft_iron_matrix_uncertainty_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 38 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mipc_filter_data_mag_auto_soft_iron_matrix_uncertainty_load(
    const uint8_t *d, mipc_filter_data_mag_auto_soft_iron_matrix_uncertainty_t *out) {
    out->soft_iron_matrix_uncertainty[0] = mipc_ld_f32(d + 0);
    out->soft_iron_matrix_uncertainty[1] = mipc_ld_f32(d + 4);
    out->soft_iron_matrix_uncertainty[2] = mipc_ld_f32(d + 8);
    out->soft_iron_matrix_uncertainty[3] = mipc_ld_f32(d + 12);
    out->soft_iron_matrix_uncertainty[4] = mipc_ld_f32(d + 16);
    out->soft_iron_matrix_uncertainty[5] = mipc_ld_f32(d + 20);
    out->soft_iron_matrix_uncertainty[6] = mipc_ld_f32(d + 24);
    out->soft_iron_matrix_uncertainty[7] = mipc_ld_f32(d + 28);
    out->soft_iron_matrix_uncertainty[8] = mipc_ld_f32(d + 32);
    out->valid_flags = mipc_ld_u16(d + 36);
    return 0;
}

/* The general reader: lengths other than 38, bad bool bytes, error details. */
static MIPC_NOINLINE mipc_status_t mipc_filter_data_mag_auto_soft_iron_matrix_uncertainty_decode_read(
    const uint8_t *data, size_t len, mipc_filter_data_mag_auto_soft_iron_matrix_uncertainty_t *out,
    mipc_decode_error_t *err) {
    mipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_filter_data_mag_auto_soft_iron_matrix_uncertainty_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t mipc_filter_data_mag_auto_soft_iron_matrix_uncertainty_decode(
    const uint8_t *data, size_t len, mipc_filter_data_mag_auto_soft_iron_matrix_uncertainty_t *out,
    mipc_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 38 && mipc_filter_data_mag_auto_soft_iron_matrix_uncertainty_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_filter_data_mag_auto_soft_iron_matrix_uncertainty_decode_read(data, len, out, err);
}

/* ---- mipc_filter_data_gnss_antenna_offset_correction_t */

static int
mipc_filter_data_gnss_antenna_offset_correction_read(mipc_reader_t *r,
                                                     mipc_filter_data_gnss_antenna_offset_correction_t *out) {
    size_t i;
    mipc_rd_push(r, "offset");
    for (i = 0; i < 3; i++) {
        mipc_rd_index(r, i);
        if (mipc_rd_f32(r, &out->offset[i])) {
            return -1;
        }
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "valid_flags");
    if (mipc_rd_u16(r, &out->valid_flags)) {
        return -1;
    }
    mipc_rd_pop(r);
    return mipc_rd_finish(r);
}

static mipc_status_t mipc_filter_data_gnss_antenna_offset_correction_write(
    mipc_writer_t *w, const mipc_filter_data_gnss_antenna_offset_correction_t *in) {
    mipc_status_t st;
    size_t i;
    for (i = 0; i < 3; i++) {
        if ((st = mipc_wr_f32(w, &in->offset[i])) != MIPC_OK) {
            return st;
        }
    }
    if ((st = mipc_wr_u16(w, &in->valid_flags)) != MIPC_OK) {
        return st;
    }
    return MIPC_OK;
}

mipc_status_t mipc_filter_data_gnss_antenna_offset_correction_encode(
    const mipc_filter_data_gnss_antenna_offset_correction_t *value, uint8_t *buf, size_t cap,
    size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mipc_writer_init(&w, buf, cap);
    st = mipc_filter_data_gnss_antenna_offset_correction_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 14 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int
mipc_filter_data_gnss_antenna_offset_correction_load(const uint8_t *d,
                                                     mipc_filter_data_gnss_antenna_offset_correction_t *out) {
    out->offset[0] = mipc_ld_f32(d + 0);
    out->offset[1] = mipc_ld_f32(d + 4);
    out->offset[2] = mipc_ld_f32(d + 8);
    out->valid_flags = mipc_ld_u16(d + 12);
    return 0;
}

/* The general reader: lengths other than 14, bad bool bytes, error details. */
static MIPC_NOINLINE mipc_status_t mipc_filter_data_gnss_antenna_offset_correction_decode_read(
    const uint8_t *data, size_t len, mipc_filter_data_gnss_antenna_offset_correction_t *out,
    mipc_decode_error_t *err) {
    mipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_filter_data_gnss_antenna_offset_correction_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t
mipc_filter_data_gnss_antenna_offset_correction_decode(const uint8_t *data, size_t len,
                                                       mipc_filter_data_gnss_antenna_offset_correction_t *out,
                                                       mipc_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 14 && mipc_filter_data_gnss_antenna_offset_correction_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_filter_data_gnss_antenna_offset_correction_decode_read(data, len, out, err);
}

/* ---- mipc_filter_data_gnss_antenna_offset_correction_uncertainty_t */

static int mipc_filter_data_gnss_antenna_offset_correction_uncertainty_read(
    mipc_reader_t *r, mipc_filter_data_gnss_antenna_offset_correction_uncertainty_t *out) {
    size_t i;
    mipc_rd_push(r, "offset_uncertainty");
    for (i = 0; i < 3; i++) {
        mipc_rd_index(r, i);
        if (mipc_rd_f32(r, &out->offset_uncertainty[i])) {
            return -1;
        }
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "valid_flags");
    if (mipc_rd_u16(r, &out->valid_flags)) {
        return -1;
    }
    mipc_rd_pop(r);
    return mipc_rd_finish(r);
}

static mipc_status_t mipc_filter_data_gnss_antenna_offset_correction_uncertainty_write(
    mipc_writer_t *w, const mipc_filter_data_gnss_antenna_offset_correction_uncertainty_t *in) {
    mipc_status_t st;
    size_t i;
    for (i = 0; i < 3; i++) {
        if ((st = mipc_wr_f32(w, &in->offset_uncertainty[i])) != MIPC_OK) {
            return st;
        }
    }
    if ((st = mipc_wr_u16(w, &in->valid_flags)) != MIPC_OK) {
        return st;
    }
    return MIPC_OK;
}

mipc_status_t mipc_filter_data_gnss_antenna_offset_correction_uncertainty_encode(
    const mipc_filter_data_gnss_antenna_offset_correction_uncertainty_t *value, uint8_t *buf, size_t cap,
    size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mipc_writer_init(&w, buf, cap);
    st = mipc_filter_data_gnss_antenna_offset_correction_uncertainty_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 14 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mipc_filter_data_gnss_antenna_offset_correction_uncertainty_load(
    const uint8_t *d, mipc_filter_data_gnss_antenna_offset_correction_uncertainty_t *out) {
    out->offset_uncertainty[0] = mipc_ld_f32(d + 0);
    out->offset_uncertainty[1] = mipc_ld_f32(d + 4);
    out->offset_uncertainty[2] = mipc_ld_f32(d + 8);
    out->valid_flags = mipc_ld_u16(d + 12);
    return 0;
}

/* The general reader: lengths other than 14, bad bool bytes, error details. */
static MIPC_NOINLINE mipc_status_t mipc_filter_data_gnss_antenna_offset_correction_uncertainty_decode_read(
    const uint8_t *data, size_t len, mipc_filter_data_gnss_antenna_offset_correction_uncertainty_t *out,
    mipc_decode_error_t *err) {
    mipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_filter_data_gnss_antenna_offset_correction_uncertainty_read(&r, out) ? MIPC_ERR_DECODE
                                                                                     : MIPC_OK;
}

mipc_status_t mipc_filter_data_gnss_antenna_offset_correction_uncertainty_decode(
    const uint8_t *data, size_t len, mipc_filter_data_gnss_antenna_offset_correction_uncertainty_t *out,
    mipc_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 14 && mipc_filter_data_gnss_antenna_offset_correction_uncertainty_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_filter_data_gnss_antenna_offset_correction_uncertainty_decode_read(data, len, out, err);
}

/* ---- mipc_filter_data_multi_antenna_offset_correction_t */

static int mipc_filter_data_multi_antenna_offset_correction_read(
    mipc_reader_t *r, mipc_filter_data_multi_antenna_offset_correction_t *out) {
    size_t i;
    mipc_rd_push(r, "receiver_id");
    if (mipc_rd_u8(r, &out->receiver_id)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "offset");
    for (i = 0; i < 3; i++) {
        mipc_rd_index(r, i);
        if (mipc_rd_f32(r, &out->offset[i])) {
            return -1;
        }
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "valid_flags");
    if (mipc_rd_u16(r, &out->valid_flags)) {
        return -1;
    }
    mipc_rd_pop(r);
    return mipc_rd_finish(r);
}

static mipc_status_t mipc_filter_data_multi_antenna_offset_correction_write(
    mipc_writer_t *w, const mipc_filter_data_multi_antenna_offset_correction_t *in) {
    mipc_status_t st;
    size_t i;
    if ((st = mipc_wr_u8(w, &in->receiver_id)) != MIPC_OK) {
        return st;
    }
    for (i = 0; i < 3; i++) {
        if ((st = mipc_wr_f32(w, &in->offset[i])) != MIPC_OK) {
            return st;
        }
    }
    if ((st = mipc_wr_u16(w, &in->valid_flags)) != MIPC_OK) {
        return st;
    }
    return MIPC_OK;
}

mipc_status_t mipc_filter_data_multi_antenna_offset_correction_encode(
    const mipc_filter_data_multi_antenna_offset_correction_t *value, uint8_t *buf, size_t cap,
    size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mipc_writer_init(&w, buf, cap);
    st = mipc_filter_data_multi_antenna_offset_correction_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 15 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mipc_filter_data_multi_antenna_offset_correction_load(
    const uint8_t *d, mipc_filter_data_multi_antenna_offset_correction_t *out) {
    out->receiver_id = mipc_ld_u8(d + 0);
    out->offset[0] = mipc_ld_f32(d + 1);
    out->offset[1] = mipc_ld_f32(d + 5);
    out->offset[2] = mipc_ld_f32(d + 9);
    out->valid_flags = mipc_ld_u16(d + 13);
    return 0;
}

/* The general reader: lengths other than 15, bad bool bytes, error details. */
static MIPC_NOINLINE mipc_status_t mipc_filter_data_multi_antenna_offset_correction_decode_read(
    const uint8_t *data, size_t len, mipc_filter_data_multi_antenna_offset_correction_t *out,
    mipc_decode_error_t *err) {
    mipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_filter_data_multi_antenna_offset_correction_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t mipc_filter_data_multi_antenna_offset_correction_decode(
    const uint8_t *data, size_t len, mipc_filter_data_multi_antenna_offset_correction_t *out,
    mipc_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 15 && mipc_filter_data_multi_antenna_offset_correction_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_filter_data_multi_antenna_offset_correction_decode_read(data, len, out, err);
}

/* ---- mipc_filter_data_multi_antenna_offset_correction_uncertainty_t */

static int mipc_filter_data_multi_antenna_offset_correction_uncertainty_read(
    mipc_reader_t *r, mipc_filter_data_multi_antenna_offset_correction_uncertainty_t *out) {
    size_t i;
    mipc_rd_push(r, "receiver_id");
    if (mipc_rd_u8(r, &out->receiver_id)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "offset_uncertainty");
    for (i = 0; i < 3; i++) {
        mipc_rd_index(r, i);
        if (mipc_rd_f32(r, &out->offset_uncertainty[i])) {
            return -1;
        }
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "valid_flags");
    if (mipc_rd_u16(r, &out->valid_flags)) {
        return -1;
    }
    mipc_rd_pop(r);
    return mipc_rd_finish(r);
}

static mipc_status_t mipc_filter_data_multi_antenna_offset_correction_uncertainty_write(
    mipc_writer_t *w, const mipc_filter_data_multi_antenna_offset_correction_uncertainty_t *in) {
    mipc_status_t st;
    size_t i;
    if ((st = mipc_wr_u8(w, &in->receiver_id)) != MIPC_OK) {
        return st;
    }
    for (i = 0; i < 3; i++) {
        if ((st = mipc_wr_f32(w, &in->offset_uncertainty[i])) != MIPC_OK) {
            return st;
        }
    }
    if ((st = mipc_wr_u16(w, &in->valid_flags)) != MIPC_OK) {
        return st;
    }
    return MIPC_OK;
}

mipc_status_t mipc_filter_data_multi_antenna_offset_correction_uncertainty_encode(
    const mipc_filter_data_multi_antenna_offset_correction_uncertainty_t *value, uint8_t *buf, size_t cap,
    size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mipc_writer_init(&w, buf, cap);
    st = mipc_filter_data_multi_antenna_offset_correction_uncertainty_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 15 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mipc_filter_data_multi_antenna_offset_correction_uncertainty_load(
    const uint8_t *d, mipc_filter_data_multi_antenna_offset_correction_uncertainty_t *out) {
    out->receiver_id = mipc_ld_u8(d + 0);
    out->offset_uncertainty[0] = mipc_ld_f32(d + 1);
    out->offset_uncertainty[1] = mipc_ld_f32(d + 5);
    out->offset_uncertainty[2] = mipc_ld_f32(d + 9);
    out->valid_flags = mipc_ld_u16(d + 13);
    return 0;
}

/* The general reader: lengths other than 15, bad bool bytes, error details. */
static MIPC_NOINLINE mipc_status_t mipc_filter_data_multi_antenna_offset_correction_uncertainty_decode_read(
    const uint8_t *data, size_t len, mipc_filter_data_multi_antenna_offset_correction_uncertainty_t *out,
    mipc_decode_error_t *err) {
    mipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_filter_data_multi_antenna_offset_correction_uncertainty_read(&r, out) ? MIPC_ERR_DECODE
                                                                                      : MIPC_OK;
}

mipc_status_t mipc_filter_data_multi_antenna_offset_correction_uncertainty_decode(
    const uint8_t *data, size_t len, mipc_filter_data_multi_antenna_offset_correction_uncertainty_t *out,
    mipc_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 15 && mipc_filter_data_multi_antenna_offset_correction_uncertainty_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_filter_data_multi_antenna_offset_correction_uncertainty_decode_read(data, len, out, err);
}

/* ---- mipc_filter_data_ecef_position_uncertainty_t */

static int
mipc_filter_data_ecef_position_uncertainty_read(mipc_reader_t *r,
                                                mipc_filter_data_ecef_position_uncertainty_t *out) {
    size_t i;
    mipc_rd_push(r, "position_uncertainty");
    for (i = 0; i < 3; i++) {
        mipc_rd_index(r, i);
        if (mipc_rd_f32(r, &out->position_uncertainty[i])) {
            return -1;
        }
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "valid_flags");
    if (mipc_rd_u16(r, &out->valid_flags)) {
        return -1;
    }
    mipc_rd_pop(r);
    return mipc_rd_finish(r);
}

static mipc_status_t
mipc_filter_data_ecef_position_uncertainty_write(mipc_writer_t *w,
                                                 const mipc_filter_data_ecef_position_uncertainty_t *in) {
    mipc_status_t st;
    size_t i;
    for (i = 0; i < 3; i++) {
        if ((st = mipc_wr_f32(w, &in->position_uncertainty[i])) != MIPC_OK) {
            return st;
        }
    }
    if ((st = mipc_wr_u16(w, &in->valid_flags)) != MIPC_OK) {
        return st;
    }
    return MIPC_OK;
}

mipc_status_t
mipc_filter_data_ecef_position_uncertainty_encode(const mipc_filter_data_ecef_position_uncertainty_t *value,
                                                  uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mipc_writer_init(&w, buf, cap);
    st = mipc_filter_data_ecef_position_uncertainty_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 14 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int
mipc_filter_data_ecef_position_uncertainty_load(const uint8_t *d,
                                                mipc_filter_data_ecef_position_uncertainty_t *out) {
    out->position_uncertainty[0] = mipc_ld_f32(d + 0);
    out->position_uncertainty[1] = mipc_ld_f32(d + 4);
    out->position_uncertainty[2] = mipc_ld_f32(d + 8);
    out->valid_flags = mipc_ld_u16(d + 12);
    return 0;
}

/* The general reader: lengths other than 14, bad bool bytes, error details. */
static MIPC_NOINLINE mipc_status_t mipc_filter_data_ecef_position_uncertainty_decode_read(
    const uint8_t *data, size_t len, mipc_filter_data_ecef_position_uncertainty_t *out,
    mipc_decode_error_t *err) {
    mipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_filter_data_ecef_position_uncertainty_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t
mipc_filter_data_ecef_position_uncertainty_decode(const uint8_t *data, size_t len,
                                                  mipc_filter_data_ecef_position_uncertainty_t *out,
                                                  mipc_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 14 && mipc_filter_data_ecef_position_uncertainty_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_filter_data_ecef_position_uncertainty_decode_read(data, len, out, err);
}

/* ---- mipc_filter_data_ecef_velocity_uncertainty_t */

static int
mipc_filter_data_ecef_velocity_uncertainty_read(mipc_reader_t *r,
                                                mipc_filter_data_ecef_velocity_uncertainty_t *out) {
    size_t i;
    mipc_rd_push(r, "velocity_uncertainty");
    for (i = 0; i < 3; i++) {
        mipc_rd_index(r, i);
        if (mipc_rd_f32(r, &out->velocity_uncertainty[i])) {
            return -1;
        }
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "valid_flags");
    if (mipc_rd_u16(r, &out->valid_flags)) {
        return -1;
    }
    mipc_rd_pop(r);
    return mipc_rd_finish(r);
}

static mipc_status_t
mipc_filter_data_ecef_velocity_uncertainty_write(mipc_writer_t *w,
                                                 const mipc_filter_data_ecef_velocity_uncertainty_t *in) {
    mipc_status_t st;
    size_t i;
    for (i = 0; i < 3; i++) {
        if ((st = mipc_wr_f32(w, &in->velocity_uncertainty[i])) != MIPC_OK) {
            return st;
        }
    }
    if ((st = mipc_wr_u16(w, &in->valid_flags)) != MIPC_OK) {
        return st;
    }
    return MIPC_OK;
}

mipc_status_t
mipc_filter_data_ecef_velocity_uncertainty_encode(const mipc_filter_data_ecef_velocity_uncertainty_t *value,
                                                  uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mipc_writer_init(&w, buf, cap);
    st = mipc_filter_data_ecef_velocity_uncertainty_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 14 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int
mipc_filter_data_ecef_velocity_uncertainty_load(const uint8_t *d,
                                                mipc_filter_data_ecef_velocity_uncertainty_t *out) {
    out->velocity_uncertainty[0] = mipc_ld_f32(d + 0);
    out->velocity_uncertainty[1] = mipc_ld_f32(d + 4);
    out->velocity_uncertainty[2] = mipc_ld_f32(d + 8);
    out->valid_flags = mipc_ld_u16(d + 12);
    return 0;
}

/* The general reader: lengths other than 14, bad bool bytes, error details. */
static MIPC_NOINLINE mipc_status_t mipc_filter_data_ecef_velocity_uncertainty_decode_read(
    const uint8_t *data, size_t len, mipc_filter_data_ecef_velocity_uncertainty_t *out,
    mipc_decode_error_t *err) {
    mipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_filter_data_ecef_velocity_uncertainty_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t
mipc_filter_data_ecef_velocity_uncertainty_decode(const uint8_t *data, size_t len,
                                                  mipc_filter_data_ecef_velocity_uncertainty_t *out,
                                                  mipc_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 14 && mipc_filter_data_ecef_velocity_uncertainty_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_filter_data_ecef_velocity_uncertainty_decode_read(data, len, out, err);
}

/* ---- mipc_filter_data_ecef_position_t */

static int mipc_filter_data_ecef_position_read(mipc_reader_t *r, mipc_filter_data_ecef_position_t *out) {
    size_t i;
    mipc_rd_push(r, "position");
    for (i = 0; i < 3; i++) {
        mipc_rd_index(r, i);
        if (mipc_rd_f64(r, &out->position[i])) {
            return -1;
        }
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "valid_flags");
    if (mipc_rd_u16(r, &out->valid_flags)) {
        return -1;
    }
    mipc_rd_pop(r);
    return mipc_rd_finish(r);
}

static mipc_status_t mipc_filter_data_ecef_position_write(mipc_writer_t *w,
                                                          const mipc_filter_data_ecef_position_t *in) {
    mipc_status_t st;
    size_t i;
    for (i = 0; i < 3; i++) {
        if ((st = mipc_wr_f64(w, &in->position[i])) != MIPC_OK) {
            return st;
        }
    }
    if ((st = mipc_wr_u16(w, &in->valid_flags)) != MIPC_OK) {
        return st;
    }
    return MIPC_OK;
}

mipc_status_t mipc_filter_data_ecef_position_encode(const mipc_filter_data_ecef_position_t *value,
                                                    uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mipc_writer_init(&w, buf, cap);
    st = mipc_filter_data_ecef_position_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 26 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mipc_filter_data_ecef_position_load(const uint8_t *d, mipc_filter_data_ecef_position_t *out) {
    out->position[0] = mipc_ld_f64(d + 0);
    out->position[1] = mipc_ld_f64(d + 8);
    out->position[2] = mipc_ld_f64(d + 16);
    out->valid_flags = mipc_ld_u16(d + 24);
    return 0;
}

/* The general reader: lengths other than 26, bad bool bytes, error details. */
static MIPC_NOINLINE mipc_status_t mipc_filter_data_ecef_position_decode_read(
    const uint8_t *data, size_t len, mipc_filter_data_ecef_position_t *out, mipc_decode_error_t *err) {
    mipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_filter_data_ecef_position_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t mipc_filter_data_ecef_position_decode(const uint8_t *data, size_t len,
                                                    mipc_filter_data_ecef_position_t *out,
                                                    mipc_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 26 && mipc_filter_data_ecef_position_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_filter_data_ecef_position_decode_read(data, len, out, err);
}

/* ---- mipc_filter_data_ecef_velocity_t */

static int mipc_filter_data_ecef_velocity_read(mipc_reader_t *r, mipc_filter_data_ecef_velocity_t *out) {
    size_t i;
    mipc_rd_push(r, "velocity");
    for (i = 0; i < 3; i++) {
        mipc_rd_index(r, i);
        if (mipc_rd_f32(r, &out->velocity[i])) {
            return -1;
        }
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "valid_flags");
    if (mipc_rd_u16(r, &out->valid_flags)) {
        return -1;
    }
    mipc_rd_pop(r);
    return mipc_rd_finish(r);
}

static mipc_status_t mipc_filter_data_ecef_velocity_write(mipc_writer_t *w,
                                                          const mipc_filter_data_ecef_velocity_t *in) {
    mipc_status_t st;
    size_t i;
    for (i = 0; i < 3; i++) {
        if ((st = mipc_wr_f32(w, &in->velocity[i])) != MIPC_OK) {
            return st;
        }
    }
    if ((st = mipc_wr_u16(w, &in->valid_flags)) != MIPC_OK) {
        return st;
    }
    return MIPC_OK;
}

mipc_status_t mipc_filter_data_ecef_velocity_encode(const mipc_filter_data_ecef_velocity_t *value,
                                                    uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mipc_writer_init(&w, buf, cap);
    st = mipc_filter_data_ecef_velocity_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 14 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mipc_filter_data_ecef_velocity_load(const uint8_t *d, mipc_filter_data_ecef_velocity_t *out) {
    out->velocity[0] = mipc_ld_f32(d + 0);
    out->velocity[1] = mipc_ld_f32(d + 4);
    out->velocity[2] = mipc_ld_f32(d + 8);
    out->valid_flags = mipc_ld_u16(d + 12);
    return 0;
}

/* The general reader: lengths other than 14, bad bool bytes, error details. */
static MIPC_NOINLINE mipc_status_t mipc_filter_data_ecef_velocity_decode_read(
    const uint8_t *data, size_t len, mipc_filter_data_ecef_velocity_t *out, mipc_decode_error_t *err) {
    mipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_filter_data_ecef_velocity_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t mipc_filter_data_ecef_velocity_decode(const uint8_t *data, size_t len,
                                                    mipc_filter_data_ecef_velocity_t *out,
                                                    mipc_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 14 && mipc_filter_data_ecef_velocity_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_filter_data_ecef_velocity_decode_read(data, len, out, err);
}

/* ---- mipc_filter_data_ned_relative_position_t */

static int mipc_filter_data_ned_relative_position_read(mipc_reader_t *r,
                                                       mipc_filter_data_ned_relative_position_t *out) {
    size_t i;
    mipc_rd_push(r, "relative_position");
    for (i = 0; i < 3; i++) {
        mipc_rd_index(r, i);
        if (mipc_rd_f64(r, &out->relative_position[i])) {
            return -1;
        }
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "valid_flags");
    if (mipc_rd_u16(r, &out->valid_flags)) {
        return -1;
    }
    mipc_rd_pop(r);
    return mipc_rd_finish(r);
}

static mipc_status_t
mipc_filter_data_ned_relative_position_write(mipc_writer_t *w,
                                             const mipc_filter_data_ned_relative_position_t *in) {
    mipc_status_t st;
    size_t i;
    for (i = 0; i < 3; i++) {
        if ((st = mipc_wr_f64(w, &in->relative_position[i])) != MIPC_OK) {
            return st;
        }
    }
    if ((st = mipc_wr_u16(w, &in->valid_flags)) != MIPC_OK) {
        return st;
    }
    return MIPC_OK;
}

mipc_status_t
mipc_filter_data_ned_relative_position_encode(const mipc_filter_data_ned_relative_position_t *value,
                                              uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mipc_writer_init(&w, buf, cap);
    st = mipc_filter_data_ned_relative_position_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 26 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mipc_filter_data_ned_relative_position_load(const uint8_t *d,
                                                       mipc_filter_data_ned_relative_position_t *out) {
    out->relative_position[0] = mipc_ld_f64(d + 0);
    out->relative_position[1] = mipc_ld_f64(d + 8);
    out->relative_position[2] = mipc_ld_f64(d + 16);
    out->valid_flags = mipc_ld_u16(d + 24);
    return 0;
}

/* The general reader: lengths other than 26, bad bool bytes, error details. */
static MIPC_NOINLINE mipc_status_t mipc_filter_data_ned_relative_position_decode_read(
    const uint8_t *data, size_t len, mipc_filter_data_ned_relative_position_t *out,
    mipc_decode_error_t *err) {
    mipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_filter_data_ned_relative_position_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t mipc_filter_data_ned_relative_position_decode(const uint8_t *data, size_t len,
                                                            mipc_filter_data_ned_relative_position_t *out,
                                                            mipc_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 26 && mipc_filter_data_ned_relative_position_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_filter_data_ned_relative_position_decode_read(data, len, out, err);
}

/* ---- mipc_filter_data_gnss_position_aiding_status_t */

static int
mipc_filter_data_gnss_position_aiding_status_read(mipc_reader_t *r,
                                                  mipc_filter_data_gnss_position_aiding_status_t *out) {
    size_t i;
    mipc_rd_push(r, "receiver_id");
    if (mipc_rd_u8(r, &out->receiver_id)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "time_of_week");
    if (mipc_rd_f32(r, &out->time_of_week)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "status");
    if (mipc_rd_u16(r, &out->status)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "reserved");
    for (i = 0; i < 8; i++) {
        mipc_rd_index(r, i);
        if (mipc_rd_u8(r, &out->reserved[i])) {
            return -1;
        }
    }
    mipc_rd_pop(r);
    return mipc_rd_finish(r);
}

static mipc_status_t
mipc_filter_data_gnss_position_aiding_status_write(mipc_writer_t *w,
                                                   const mipc_filter_data_gnss_position_aiding_status_t *in) {
    mipc_status_t st;
    size_t i;
    if ((st = mipc_wr_u8(w, &in->receiver_id)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_f32(w, &in->time_of_week)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u16(w, &in->status)) != MIPC_OK) {
        return st;
    }
    for (i = 0; i < 8; i++) {
        if ((st = mipc_wr_u8(w, &in->reserved[i])) != MIPC_OK) {
            return st;
        }
    }
    return MIPC_OK;
}

mipc_status_t mipc_filter_data_gnss_position_aiding_status_encode(
    const mipc_filter_data_gnss_position_aiding_status_t *value, uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mipc_writer_init(&w, buf, cap);
    st = mipc_filter_data_gnss_position_aiding_status_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 15 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int
mipc_filter_data_gnss_position_aiding_status_load(const uint8_t *d,
                                                  mipc_filter_data_gnss_position_aiding_status_t *out) {
    out->receiver_id = mipc_ld_u8(d + 0);
    out->time_of_week = mipc_ld_f32(d + 1);
    out->status = mipc_ld_u16(d + 5);
    out->reserved[0] = mipc_ld_u8(d + 7);
    out->reserved[1] = mipc_ld_u8(d + 8);
    out->reserved[2] = mipc_ld_u8(d + 9);
    out->reserved[3] = mipc_ld_u8(d + 10);
    out->reserved[4] = mipc_ld_u8(d + 11);
    out->reserved[5] = mipc_ld_u8(d + 12);
    out->reserved[6] = mipc_ld_u8(d + 13);
    out->reserved[7] = mipc_ld_u8(d + 14);
    return 0;
}

/* The general reader: lengths other than 15, bad bool bytes, error details. */
static MIPC_NOINLINE mipc_status_t mipc_filter_data_gnss_position_aiding_status_decode_read(
    const uint8_t *data, size_t len, mipc_filter_data_gnss_position_aiding_status_t *out,
    mipc_decode_error_t *err) {
    mipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_filter_data_gnss_position_aiding_status_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t
mipc_filter_data_gnss_position_aiding_status_decode(const uint8_t *data, size_t len,
                                                    mipc_filter_data_gnss_position_aiding_status_t *out,
                                                    mipc_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 15 && mipc_filter_data_gnss_position_aiding_status_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_filter_data_gnss_position_aiding_status_decode_read(data, len, out, err);
}

/* ---- mipc_filter_data_aiding_measurement_summary_t */

static int
mipc_filter_data_aiding_measurement_summary_read(mipc_reader_t *r,
                                                 mipc_filter_data_aiding_measurement_summary_t *out) {
    mipc_rd_push(r, "time_of_week");
    if (mipc_rd_f32(r, &out->time_of_week)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "source");
    if (mipc_rd_u8(r, &out->source)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "type");
    if (mipc_rd_u8(r, &out->type)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "indicator");
    if (mipc_rd_u8(r, &out->indicator)) {
        return -1;
    }
    mipc_rd_pop(r);
    return mipc_rd_finish(r);
}

static mipc_status_t
mipc_filter_data_aiding_measurement_summary_write(mipc_writer_t *w,
                                                  const mipc_filter_data_aiding_measurement_summary_t *in) {
    mipc_status_t st;
    if ((st = mipc_wr_f32(w, &in->time_of_week)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u8(w, &in->source)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u8(w, &in->type)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u8(w, &in->indicator)) != MIPC_OK) {
        return st;
    }
    return MIPC_OK;
}

mipc_status_t
mipc_filter_data_aiding_measurement_summary_encode(const mipc_filter_data_aiding_measurement_summary_t *value,
                                                   uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mipc_writer_init(&w, buf, cap);
    st = mipc_filter_data_aiding_measurement_summary_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 7 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int
mipc_filter_data_aiding_measurement_summary_load(const uint8_t *d,
                                                 mipc_filter_data_aiding_measurement_summary_t *out) {
    out->time_of_week = mipc_ld_f32(d + 0);
    out->source = mipc_ld_u8(d + 4);
    out->type = mipc_ld_u8(d + 5);
    out->indicator = mipc_ld_u8(d + 6);
    return 0;
}

/* The general reader: lengths other than 7, bad bool bytes, error details. */
static MIPC_NOINLINE mipc_status_t mipc_filter_data_aiding_measurement_summary_decode_read(
    const uint8_t *data, size_t len, mipc_filter_data_aiding_measurement_summary_t *out,
    mipc_decode_error_t *err) {
    mipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_filter_data_aiding_measurement_summary_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t
mipc_filter_data_aiding_measurement_summary_decode(const uint8_t *data, size_t len,
                                                   mipc_filter_data_aiding_measurement_summary_t *out,
                                                   mipc_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 7 && mipc_filter_data_aiding_measurement_summary_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_filter_data_aiding_measurement_summary_decode_read(data, len, out, err);
}

/* ---- mipc_filter_data_odometer_scale_factor_error_t */

static int
mipc_filter_data_odometer_scale_factor_error_read(mipc_reader_t *r,
                                                  mipc_filter_data_odometer_scale_factor_error_t *out) {
    mipc_rd_push(r, "scale_factor_error");
    if (mipc_rd_f32(r, &out->scale_factor_error)) {
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

static mipc_status_t
mipc_filter_data_odometer_scale_factor_error_write(mipc_writer_t *w,
                                                   const mipc_filter_data_odometer_scale_factor_error_t *in) {
    mipc_status_t st;
    if ((st = mipc_wr_f32(w, &in->scale_factor_error)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u16(w, &in->valid_flags)) != MIPC_OK) {
        return st;
    }
    return MIPC_OK;
}

mipc_status_t mipc_filter_data_odometer_scale_factor_error_encode(
    const mipc_filter_data_odometer_scale_factor_error_t *value, uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mipc_writer_init(&w, buf, cap);
    st = mipc_filter_data_odometer_scale_factor_error_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 6 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int
mipc_filter_data_odometer_scale_factor_error_load(const uint8_t *d,
                                                  mipc_filter_data_odometer_scale_factor_error_t *out) {
    out->scale_factor_error = mipc_ld_f32(d + 0);
    out->valid_flags = mipc_ld_u16(d + 4);
    return 0;
}

/* The general reader: lengths other than 6, bad bool bytes, error details. */
static MIPC_NOINLINE mipc_status_t mipc_filter_data_odometer_scale_factor_error_decode_read(
    const uint8_t *data, size_t len, mipc_filter_data_odometer_scale_factor_error_t *out,
    mipc_decode_error_t *err) {
    mipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_filter_data_odometer_scale_factor_error_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t
mipc_filter_data_odometer_scale_factor_error_decode(const uint8_t *data, size_t len,
                                                    mipc_filter_data_odometer_scale_factor_error_t *out,
                                                    mipc_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 6 && mipc_filter_data_odometer_scale_factor_error_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_filter_data_odometer_scale_factor_error_decode_read(data, len, out, err);
}

/* ---- mipc_filter_data_odometer_scale_factor_error_uncertainty_t */

static int mipc_filter_data_odometer_scale_factor_error_uncertainty_read(
    mipc_reader_t *r, mipc_filter_data_odometer_scale_factor_error_uncertainty_t *out) {
    mipc_rd_push(r, "scale_factor_error_uncertainty");
    if (mipc_rd_f32(r, &out->scale_factor_error_uncertainty)) {
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

static mipc_status_t mipc_filter_data_odometer_scale_factor_error_uncertainty_write(
    mipc_writer_t *w, const mipc_filter_data_odometer_scale_factor_error_uncertainty_t *in) {
    mipc_status_t st;
    if ((st = mipc_wr_f32(w, &in->scale_factor_error_uncertainty)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u16(w, &in->valid_flags)) != MIPC_OK) {
        return st;
    }
    return MIPC_OK;
}

mipc_status_t mipc_filter_data_odometer_scale_factor_error_uncertainty_encode(
    const mipc_filter_data_odometer_scale_factor_error_uncertainty_t *value, uint8_t *buf, size_t cap,
    size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mipc_writer_init(&w, buf, cap);
    st = mipc_filter_data_odometer_scale_factor_error_uncertainty_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 6 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mipc_filter_data_odometer_scale_factor_error_uncertainty_load(
    const uint8_t *d, mipc_filter_data_odometer_scale_factor_error_uncertainty_t *out) {
    out->scale_factor_error_uncertainty = mipc_ld_f32(d + 0);
    out->valid_flags = mipc_ld_u16(d + 4);
    return 0;
}

/* The general reader: lengths other than 6, bad bool bytes, error details. */
static MIPC_NOINLINE mipc_status_t mipc_filter_data_odometer_scale_factor_error_uncertainty_decode_read(
    const uint8_t *data, size_t len, mipc_filter_data_odometer_scale_factor_error_uncertainty_t *out,
    mipc_decode_error_t *err) {
    mipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_filter_data_odometer_scale_factor_error_uncertainty_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t mipc_filter_data_odometer_scale_factor_error_uncertainty_decode(
    const uint8_t *data, size_t len, mipc_filter_data_odometer_scale_factor_error_uncertainty_t *out,
    mipc_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 6 && mipc_filter_data_odometer_scale_factor_error_uncertainty_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_filter_data_odometer_scale_factor_error_uncertainty_decode_read(data, len, out, err);
}

/* ---- mipc_filter_data_gnss_dual_antenna_status_t */

static int mipc_filter_data_gnss_dual_antenna_status_read(mipc_reader_t *r,
                                                          mipc_filter_data_gnss_dual_antenna_status_t *out) {
    mipc_rd_push(r, "time_of_week");
    if (mipc_rd_f32(r, &out->time_of_week)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "heading");
    if (mipc_rd_f32(r, &out->heading)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "heading_uncertainty");
    if (mipc_rd_f32(r, &out->heading_uncertainty)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "fix_type");
    if (mipc_rd_u8(r, &out->fix_type)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "status_flags");
    if (mipc_rd_u16(r, &out->status_flags)) {
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

static mipc_status_t
mipc_filter_data_gnss_dual_antenna_status_write(mipc_writer_t *w,
                                                const mipc_filter_data_gnss_dual_antenna_status_t *in) {
    mipc_status_t st;
    if ((st = mipc_wr_f32(w, &in->time_of_week)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_f32(w, &in->heading)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_f32(w, &in->heading_uncertainty)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u8(w, &in->fix_type)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u16(w, &in->status_flags)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u16(w, &in->valid_flags)) != MIPC_OK) {
        return st;
    }
    return MIPC_OK;
}

mipc_status_t
mipc_filter_data_gnss_dual_antenna_status_encode(const mipc_filter_data_gnss_dual_antenna_status_t *value,
                                                 uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mipc_writer_init(&w, buf, cap);
    st = mipc_filter_data_gnss_dual_antenna_status_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 17 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mipc_filter_data_gnss_dual_antenna_status_load(const uint8_t *d,
                                                          mipc_filter_data_gnss_dual_antenna_status_t *out) {
    out->time_of_week = mipc_ld_f32(d + 0);
    out->heading = mipc_ld_f32(d + 4);
    out->heading_uncertainty = mipc_ld_f32(d + 8);
    out->fix_type = mipc_ld_u8(d + 12);
    out->status_flags = mipc_ld_u16(d + 13);
    out->valid_flags = mipc_ld_u16(d + 15);
    return 0;
}

/* The general reader: lengths other than 17, bad bool bytes, error details. */
static MIPC_NOINLINE mipc_status_t mipc_filter_data_gnss_dual_antenna_status_decode_read(
    const uint8_t *data, size_t len, mipc_filter_data_gnss_dual_antenna_status_t *out,
    mipc_decode_error_t *err) {
    mipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_filter_data_gnss_dual_antenna_status_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t
mipc_filter_data_gnss_dual_antenna_status_decode(const uint8_t *data, size_t len,
                                                 mipc_filter_data_gnss_dual_antenna_status_t *out,
                                                 mipc_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 17 && mipc_filter_data_gnss_dual_antenna_status_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_filter_data_gnss_dual_antenna_status_decode_read(data, len, out, err);
}

/* ---- mipc_filter_data_aiding_frame_config_error_t */

static int
mipc_filter_data_aiding_frame_config_error_read(mipc_reader_t *r,
                                                mipc_filter_data_aiding_frame_config_error_t *out) {
    size_t i;
    mipc_rd_push(r, "frame_id");
    if (mipc_rd_u8(r, &out->frame_id)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "translation");
    for (i = 0; i < 3; i++) {
        mipc_rd_index(r, i);
        if (mipc_rd_f32(r, &out->translation[i])) {
            return -1;
        }
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "attitude");
    for (i = 0; i < 4; i++) {
        mipc_rd_index(r, i);
        if (mipc_rd_f32(r, &out->attitude[i])) {
            return -1;
        }
    }
    mipc_rd_pop(r);
    return mipc_rd_finish(r);
}

static mipc_status_t
mipc_filter_data_aiding_frame_config_error_write(mipc_writer_t *w,
                                                 const mipc_filter_data_aiding_frame_config_error_t *in) {
    mipc_status_t st;
    size_t i;
    if ((st = mipc_wr_u8(w, &in->frame_id)) != MIPC_OK) {
        return st;
    }
    for (i = 0; i < 3; i++) {
        if ((st = mipc_wr_f32(w, &in->translation[i])) != MIPC_OK) {
            return st;
        }
    }
    for (i = 0; i < 4; i++) {
        if ((st = mipc_wr_f32(w, &in->attitude[i])) != MIPC_OK) {
            return st;
        }
    }
    return MIPC_OK;
}

mipc_status_t
mipc_filter_data_aiding_frame_config_error_encode(const mipc_filter_data_aiding_frame_config_error_t *value,
                                                  uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mipc_writer_init(&w, buf, cap);
    st = mipc_filter_data_aiding_frame_config_error_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 29 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int
mipc_filter_data_aiding_frame_config_error_load(const uint8_t *d,
                                                mipc_filter_data_aiding_frame_config_error_t *out) {
    out->frame_id = mipc_ld_u8(d + 0);
    out->translation[0] = mipc_ld_f32(d + 1);
    out->translation[1] = mipc_ld_f32(d + 5);
    out->translation[2] = mipc_ld_f32(d + 9);
    out->attitude[0] = mipc_ld_f32(d + 13);
    out->attitude[1] = mipc_ld_f32(d + 17);
    out->attitude[2] = mipc_ld_f32(d + 21);
    out->attitude[3] = mipc_ld_f32(d + 25);
    return 0;
}

/* The general reader: lengths other than 29, bad bool bytes, error details. */
static MIPC_NOINLINE mipc_status_t mipc_filter_data_aiding_frame_config_error_decode_read(
    const uint8_t *data, size_t len, mipc_filter_data_aiding_frame_config_error_t *out,
    mipc_decode_error_t *err) {
    mipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_filter_data_aiding_frame_config_error_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t
mipc_filter_data_aiding_frame_config_error_decode(const uint8_t *data, size_t len,
                                                  mipc_filter_data_aiding_frame_config_error_t *out,
                                                  mipc_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 29 && mipc_filter_data_aiding_frame_config_error_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_filter_data_aiding_frame_config_error_decode_read(data, len, out, err);
}

/* ---- mipc_filter_data_aiding_frame_config_error_uncertainty_t */

static int mipc_filter_data_aiding_frame_config_error_uncertainty_read(
    mipc_reader_t *r, mipc_filter_data_aiding_frame_config_error_uncertainty_t *out) {
    size_t i;
    mipc_rd_push(r, "frame_id");
    if (mipc_rd_u8(r, &out->frame_id)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "translation_uncertainty");
    for (i = 0; i < 3; i++) {
        mipc_rd_index(r, i);
        if (mipc_rd_f32(r, &out->translation_uncertainty[i])) {
            return -1;
        }
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "attitude_uncertainty");
    for (i = 0; i < 3; i++) {
        mipc_rd_index(r, i);
        if (mipc_rd_f32(r, &out->attitude_uncertainty[i])) {
            return -1;
        }
    }
    mipc_rd_pop(r);
    return mipc_rd_finish(r);
}

static mipc_status_t mipc_filter_data_aiding_frame_config_error_uncertainty_write(
    mipc_writer_t *w, const mipc_filter_data_aiding_frame_config_error_uncertainty_t *in) {
    mipc_status_t st;
    size_t i;
    if ((st = mipc_wr_u8(w, &in->frame_id)) != MIPC_OK) {
        return st;
    }
    for (i = 0; i < 3; i++) {
        if ((st = mipc_wr_f32(w, &in->translation_uncertainty[i])) != MIPC_OK) {
            return st;
        }
    }
    for (i = 0; i < 3; i++) {
        if ((st = mipc_wr_f32(w, &in->attitude_uncertainty[i])) != MIPC_OK) {
            return st;
        }
    }
    return MIPC_OK;
}

mipc_status_t mipc_filter_data_aiding_frame_config_error_uncertainty_encode(
    const mipc_filter_data_aiding_frame_config_error_uncertainty_t *value, uint8_t *buf, size_t cap,
    size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mipc_writer_init(&w, buf, cap);
    st = mipc_filter_data_aiding_frame_config_error_uncertainty_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 25 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mipc_filter_data_aiding_frame_config_error_uncertainty_load(
    const uint8_t *d, mipc_filter_data_aiding_frame_config_error_uncertainty_t *out) {
    out->frame_id = mipc_ld_u8(d + 0);
    out->translation_uncertainty[0] = mipc_ld_f32(d + 1);
    out->translation_uncertainty[1] = mipc_ld_f32(d + 5);
    out->translation_uncertainty[2] = mipc_ld_f32(d + 9);
    out->attitude_uncertainty[0] = mipc_ld_f32(d + 13);
    out->attitude_uncertainty[1] = mipc_ld_f32(d + 17);
    out->attitude_uncertainty[2] = mipc_ld_f32(d + 21);
    return 0;
}

/* The general reader: lengths other than 25, bad bool bytes, error details. */
static MIPC_NOINLINE mipc_status_t mipc_filter_data_aiding_frame_config_error_uncertainty_decode_read(
    const uint8_t *data, size_t len, mipc_filter_data_aiding_frame_config_error_uncertainty_t *out,
    mipc_decode_error_t *err) {
    mipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_filter_data_aiding_frame_config_error_uncertainty_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t mipc_filter_data_aiding_frame_config_error_uncertainty_decode(
    const uint8_t *data, size_t len, mipc_filter_data_aiding_frame_config_error_uncertainty_t *out,
    mipc_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 25 && mipc_filter_data_aiding_frame_config_error_uncertainty_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_filter_data_aiding_frame_config_error_uncertainty_decode_read(data, len, out, err);
}

/* ---- the straight-line packet decoder */

size_t mipc_filter_data_decode_packet(const uint8_t *payload, size_t len, mipc_filter_data_packet_t *out,
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
            (int)head[MIPC_FIELD_LENGTH_OFFSET] - mipc_field_length_adjust(MIPC_FILTER_DATA_SET, descriptor);
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
            case 0x01:
                if (length == 26) {
                    out->filter_data_llh_position.latitude = mipc_ld_f64(d + 0);
                    out->filter_data_llh_position.longitude = mipc_ld_f64(d + 8);
                    out->filter_data_llh_position.ellipsoid_height = mipc_ld_f64(d + 16);
                    out->filter_data_llh_position.valid_flags = mipc_ld_u16(d + 24);
                    ok = 1;
                } else {
                    ok = mipc_filter_data_llh_position_decode(d, length, &out->filter_data_llh_position,
                                                              NULL) == MIPC_OK;
                }
                offset = offsetof(mipc_filter_data_packet_t, filter_data_llh_position);
                break;
            case 0x02:
                if (length == 14) {
                    out->filter_data_ned_velocity.north = mipc_ld_f32(d + 0);
                    out->filter_data_ned_velocity.east = mipc_ld_f32(d + 4);
                    out->filter_data_ned_velocity.down = mipc_ld_f32(d + 8);
                    out->filter_data_ned_velocity.valid_flags = mipc_ld_u16(d + 12);
                    ok = 1;
                } else {
                    ok = mipc_filter_data_ned_velocity_decode(d, length, &out->filter_data_ned_velocity,
                                                              NULL) == MIPC_OK;
                }
                offset = offsetof(mipc_filter_data_packet_t, filter_data_ned_velocity);
                break;
            case 0x03:
                if (length == 18) {
                    out->filter_data_attitude_quaternion.q[0] = mipc_ld_f32(d + 0);
                    out->filter_data_attitude_quaternion.q[1] = mipc_ld_f32(d + 4);
                    out->filter_data_attitude_quaternion.q[2] = mipc_ld_f32(d + 8);
                    out->filter_data_attitude_quaternion.q[3] = mipc_ld_f32(d + 12);
                    out->filter_data_attitude_quaternion.valid_flags = mipc_ld_u16(d + 16);
                    ok = 1;
                } else {
                    ok = mipc_filter_data_attitude_quaternion_decode(
                             d, length, &out->filter_data_attitude_quaternion, NULL) == MIPC_OK;
                }
                offset = offsetof(mipc_filter_data_packet_t, filter_data_attitude_quaternion);
                break;
            case 0x04:
                if (length == 38) {
                    out->filter_data_attitude_dcm.dcm[0] = mipc_ld_f32(d + 0);
                    out->filter_data_attitude_dcm.dcm[1] = mipc_ld_f32(d + 4);
                    out->filter_data_attitude_dcm.dcm[2] = mipc_ld_f32(d + 8);
                    out->filter_data_attitude_dcm.dcm[3] = mipc_ld_f32(d + 12);
                    out->filter_data_attitude_dcm.dcm[4] = mipc_ld_f32(d + 16);
                    out->filter_data_attitude_dcm.dcm[5] = mipc_ld_f32(d + 20);
                    out->filter_data_attitude_dcm.dcm[6] = mipc_ld_f32(d + 24);
                    out->filter_data_attitude_dcm.dcm[7] = mipc_ld_f32(d + 28);
                    out->filter_data_attitude_dcm.dcm[8] = mipc_ld_f32(d + 32);
                    out->filter_data_attitude_dcm.valid_flags = mipc_ld_u16(d + 36);
                    ok = 1;
                } else {
                    ok = mipc_filter_data_attitude_dcm_decode(d, length, &out->filter_data_attitude_dcm,
                                                              NULL) == MIPC_OK;
                }
                offset = offsetof(mipc_filter_data_packet_t, filter_data_attitude_dcm);
                break;
            case 0x05:
                if (length == 14) {
                    out->filter_data_euler_angles.roll = mipc_ld_f32(d + 0);
                    out->filter_data_euler_angles.pitch = mipc_ld_f32(d + 4);
                    out->filter_data_euler_angles.yaw = mipc_ld_f32(d + 8);
                    out->filter_data_euler_angles.valid_flags = mipc_ld_u16(d + 12);
                    ok = 1;
                } else {
                    ok = mipc_filter_data_euler_angles_decode(d, length, &out->filter_data_euler_angles,
                                                              NULL) == MIPC_OK;
                }
                offset = offsetof(mipc_filter_data_packet_t, filter_data_euler_angles);
                break;
            case 0x06:
                if (length == 14) {
                    out->filter_data_gyro_bias.bias[0] = mipc_ld_f32(d + 0);
                    out->filter_data_gyro_bias.bias[1] = mipc_ld_f32(d + 4);
                    out->filter_data_gyro_bias.bias[2] = mipc_ld_f32(d + 8);
                    out->filter_data_gyro_bias.valid_flags = mipc_ld_u16(d + 12);
                    ok = 1;
                } else {
                    ok = mipc_filter_data_gyro_bias_decode(d, length, &out->filter_data_gyro_bias, NULL) ==
                         MIPC_OK;
                }
                offset = offsetof(mipc_filter_data_packet_t, filter_data_gyro_bias);
                break;
            case 0x07:
                if (length == 14) {
                    out->filter_data_accel_bias.bias[0] = mipc_ld_f32(d + 0);
                    out->filter_data_accel_bias.bias[1] = mipc_ld_f32(d + 4);
                    out->filter_data_accel_bias.bias[2] = mipc_ld_f32(d + 8);
                    out->filter_data_accel_bias.valid_flags = mipc_ld_u16(d + 12);
                    ok = 1;
                } else {
                    ok = mipc_filter_data_accel_bias_decode(d, length, &out->filter_data_accel_bias, NULL) ==
                         MIPC_OK;
                }
                offset = offsetof(mipc_filter_data_packet_t, filter_data_accel_bias);
                break;
            case 0x08:
                if (length == 14) {
                    out->filter_data_llh_position_uncertainty.north = mipc_ld_f32(d + 0);
                    out->filter_data_llh_position_uncertainty.east = mipc_ld_f32(d + 4);
                    out->filter_data_llh_position_uncertainty.down = mipc_ld_f32(d + 8);
                    out->filter_data_llh_position_uncertainty.valid_flags = mipc_ld_u16(d + 12);
                    ok = 1;
                } else {
                    ok = mipc_filter_data_llh_position_uncertainty_decode(
                             d, length, &out->filter_data_llh_position_uncertainty, NULL) == MIPC_OK;
                }
                offset = offsetof(mipc_filter_data_packet_t, filter_data_llh_position_uncertainty);
                break;
            case 0x09:
                if (length == 14) {
                    out->filter_data_ned_velocity_uncertainty.north = mipc_ld_f32(d + 0);
                    out->filter_data_ned_velocity_uncertainty.east = mipc_ld_f32(d + 4);
                    out->filter_data_ned_velocity_uncertainty.down = mipc_ld_f32(d + 8);
                    out->filter_data_ned_velocity_uncertainty.valid_flags = mipc_ld_u16(d + 12);
                    ok = 1;
                } else {
                    ok = mipc_filter_data_ned_velocity_uncertainty_decode(
                             d, length, &out->filter_data_ned_velocity_uncertainty, NULL) == MIPC_OK;
                }
                offset = offsetof(mipc_filter_data_packet_t, filter_data_ned_velocity_uncertainty);
                break;
            case 0x0A:
                if (length == 14) {
                    out->filter_data_euler_angles_uncertainty.roll = mipc_ld_f32(d + 0);
                    out->filter_data_euler_angles_uncertainty.pitch = mipc_ld_f32(d + 4);
                    out->filter_data_euler_angles_uncertainty.yaw = mipc_ld_f32(d + 8);
                    out->filter_data_euler_angles_uncertainty.valid_flags = mipc_ld_u16(d + 12);
                    ok = 1;
                } else {
                    ok = mipc_filter_data_euler_angles_uncertainty_decode(
                             d, length, &out->filter_data_euler_angles_uncertainty, NULL) == MIPC_OK;
                }
                offset = offsetof(mipc_filter_data_packet_t, filter_data_euler_angles_uncertainty);
                break;
            case 0x0B:
                if (length == 14) {
                    out->filter_data_gyro_bias_uncertainty.bias_uncertainty[0] = mipc_ld_f32(d + 0);
                    out->filter_data_gyro_bias_uncertainty.bias_uncertainty[1] = mipc_ld_f32(d + 4);
                    out->filter_data_gyro_bias_uncertainty.bias_uncertainty[2] = mipc_ld_f32(d + 8);
                    out->filter_data_gyro_bias_uncertainty.valid_flags = mipc_ld_u16(d + 12);
                    ok = 1;
                } else {
                    ok = mipc_filter_data_gyro_bias_uncertainty_decode(
                             d, length, &out->filter_data_gyro_bias_uncertainty, NULL) == MIPC_OK;
                }
                offset = offsetof(mipc_filter_data_packet_t, filter_data_gyro_bias_uncertainty);
                break;
            case 0x0C:
                if (length == 14) {
                    out->filter_data_accel_bias_uncertainty.bias_uncertainty[0] = mipc_ld_f32(d + 0);
                    out->filter_data_accel_bias_uncertainty.bias_uncertainty[1] = mipc_ld_f32(d + 4);
                    out->filter_data_accel_bias_uncertainty.bias_uncertainty[2] = mipc_ld_f32(d + 8);
                    out->filter_data_accel_bias_uncertainty.valid_flags = mipc_ld_u16(d + 12);
                    ok = 1;
                } else {
                    ok = mipc_filter_data_accel_bias_uncertainty_decode(
                             d, length, &out->filter_data_accel_bias_uncertainty, NULL) == MIPC_OK;
                }
                offset = offsetof(mipc_filter_data_packet_t, filter_data_accel_bias_uncertainty);
                break;
            case 0x0D:
                if (length == 14) {
                    out->filter_data_linear_accel.accel[0] = mipc_ld_f32(d + 0);
                    out->filter_data_linear_accel.accel[1] = mipc_ld_f32(d + 4);
                    out->filter_data_linear_accel.accel[2] = mipc_ld_f32(d + 8);
                    out->filter_data_linear_accel.valid_flags = mipc_ld_u16(d + 12);
                    ok = 1;
                } else {
                    ok = mipc_filter_data_linear_accel_decode(d, length, &out->filter_data_linear_accel,
                                                              NULL) == MIPC_OK;
                }
                offset = offsetof(mipc_filter_data_packet_t, filter_data_linear_accel);
                break;
            case 0x0E:
                if (length == 14) {
                    out->filter_data_comp_angular_rate.gyro[0] = mipc_ld_f32(d + 0);
                    out->filter_data_comp_angular_rate.gyro[1] = mipc_ld_f32(d + 4);
                    out->filter_data_comp_angular_rate.gyro[2] = mipc_ld_f32(d + 8);
                    out->filter_data_comp_angular_rate.valid_flags = mipc_ld_u16(d + 12);
                    ok = 1;
                } else {
                    ok = mipc_filter_data_comp_angular_rate_decode(
                             d, length, &out->filter_data_comp_angular_rate, NULL) == MIPC_OK;
                }
                offset = offsetof(mipc_filter_data_packet_t, filter_data_comp_angular_rate);
                break;
            case 0x0F:
                if (length == 6) {
                    out->filter_data_wgs84_gravity_magnitude.gravity_magnitude = mipc_ld_f32(d + 0);
                    out->filter_data_wgs84_gravity_magnitude.valid_flags = mipc_ld_u16(d + 4);
                    ok = 1;
                } else {
                    ok = mipc_filter_data_wgs84_gravity_magnitude_decode(
                             d, length, &out->filter_data_wgs84_gravity_magnitude, NULL) == MIPC_OK;
                }
                offset = offsetof(mipc_filter_data_packet_t, filter_data_wgs84_gravity_magnitude);
                break;
            case 0x11:
                if (length == 12) {
                    out->filter_data_gps_timestamp.tow = mipc_ld_f64(d + 0);
                    out->filter_data_gps_timestamp.week_number = mipc_ld_u16(d + 8);
                    out->filter_data_gps_timestamp.valid_flags = mipc_ld_u16(d + 10);
                    ok = 1;
                } else {
                    ok = mipc_filter_data_gps_timestamp_decode(d, length, &out->filter_data_gps_timestamp,
                                                               NULL) == MIPC_OK;
                }
                offset = offsetof(mipc_filter_data_packet_t, filter_data_gps_timestamp);
                break;
            case 0x12:
                if (length == 18) {
                    out->filter_data_quaternion_attitude_uncertainty.q[0] = mipc_ld_f32(d + 0);
                    out->filter_data_quaternion_attitude_uncertainty.q[1] = mipc_ld_f32(d + 4);
                    out->filter_data_quaternion_attitude_uncertainty.q[2] = mipc_ld_f32(d + 8);
                    out->filter_data_quaternion_attitude_uncertainty.q[3] = mipc_ld_f32(d + 12);
                    out->filter_data_quaternion_attitude_uncertainty.valid_flags = mipc_ld_u16(d + 16);
                    ok = 1;
                } else {
                    ok = mipc_filter_data_quaternion_attitude_uncertainty_decode(
                             d, length, &out->filter_data_quaternion_attitude_uncertainty, NULL) == MIPC_OK;
                }
                offset = offsetof(mipc_filter_data_packet_t, filter_data_quaternion_attitude_uncertainty);
                break;
            case 0x13:
                if (length == 14) {
                    out->filter_data_gravity_vector.gravity[0] = mipc_ld_f32(d + 0);
                    out->filter_data_gravity_vector.gravity[1] = mipc_ld_f32(d + 4);
                    out->filter_data_gravity_vector.gravity[2] = mipc_ld_f32(d + 8);
                    out->filter_data_gravity_vector.valid_flags = mipc_ld_u16(d + 12);
                    ok = 1;
                } else {
                    ok = mipc_filter_data_gravity_vector_decode(d, length, &out->filter_data_gravity_vector,
                                                                NULL) == MIPC_OK;
                }
                offset = offsetof(mipc_filter_data_packet_t, filter_data_gravity_vector);
                break;
            case 0x14:
                if (length == 12) {
                    out->filter_data_heading_update_state.heading = mipc_ld_f32(d + 0);
                    out->filter_data_heading_update_state.heading_uncertainty = mipc_ld_f32(d + 4);
                    out->filter_data_heading_update_state.source = mipc_ld_u16(d + 8);
                    out->filter_data_heading_update_state.valid_flags = mipc_ld_u16(d + 10);
                    ok = 1;
                } else {
                    ok = mipc_filter_data_heading_update_state_decode(
                             d, length, &out->filter_data_heading_update_state, NULL) == MIPC_OK;
                }
                offset = offsetof(mipc_filter_data_packet_t, filter_data_heading_update_state);
                break;
            case 0x15:
                if (length == 22) {
                    out->filter_data_magnetic_model.intensity_north = mipc_ld_f32(d + 0);
                    out->filter_data_magnetic_model.intensity_east = mipc_ld_f32(d + 4);
                    out->filter_data_magnetic_model.intensity_down = mipc_ld_f32(d + 8);
                    out->filter_data_magnetic_model.inclination = mipc_ld_f32(d + 12);
                    out->filter_data_magnetic_model.declination = mipc_ld_f32(d + 16);
                    out->filter_data_magnetic_model.valid_flags = mipc_ld_u16(d + 20);
                    ok = 1;
                } else {
                    ok = mipc_filter_data_magnetic_model_decode(d, length, &out->filter_data_magnetic_model,
                                                                NULL) == MIPC_OK;
                }
                offset = offsetof(mipc_filter_data_packet_t, filter_data_magnetic_model);
                break;
            case 0x16:
                if (length == 14) {
                    out->filter_data_gyro_scale_factor.scale_factor[0] = mipc_ld_f32(d + 0);
                    out->filter_data_gyro_scale_factor.scale_factor[1] = mipc_ld_f32(d + 4);
                    out->filter_data_gyro_scale_factor.scale_factor[2] = mipc_ld_f32(d + 8);
                    out->filter_data_gyro_scale_factor.valid_flags = mipc_ld_u16(d + 12);
                    ok = 1;
                } else {
                    ok = mipc_filter_data_gyro_scale_factor_decode(
                             d, length, &out->filter_data_gyro_scale_factor, NULL) == MIPC_OK;
                }
                offset = offsetof(mipc_filter_data_packet_t, filter_data_gyro_scale_factor);
                break;
            case 0x17:
                if (length == 14) {
                    out->filter_data_accel_scale_factor.scale_factor[0] = mipc_ld_f32(d + 0);
                    out->filter_data_accel_scale_factor.scale_factor[1] = mipc_ld_f32(d + 4);
                    out->filter_data_accel_scale_factor.scale_factor[2] = mipc_ld_f32(d + 8);
                    out->filter_data_accel_scale_factor.valid_flags = mipc_ld_u16(d + 12);
                    ok = 1;
                } else {
                    ok = mipc_filter_data_accel_scale_factor_decode(
                             d, length, &out->filter_data_accel_scale_factor, NULL) == MIPC_OK;
                }
                offset = offsetof(mipc_filter_data_packet_t, filter_data_accel_scale_factor);
                break;
            case 0x18:
                if (length == 14) {
                    out->filter_data_gyro_scale_factor_uncertainty.scale_factor_uncertainty[0] =
                        mipc_ld_f32(d + 0);
                    out->filter_data_gyro_scale_factor_uncertainty.scale_factor_uncertainty[1] =
                        mipc_ld_f32(d + 4);
                    out->filter_data_gyro_scale_factor_uncertainty.scale_factor_uncertainty[2] =
                        mipc_ld_f32(d + 8);
                    out->filter_data_gyro_scale_factor_uncertainty.valid_flags = mipc_ld_u16(d + 12);
                    ok = 1;
                } else {
                    ok = mipc_filter_data_gyro_scale_factor_uncertainty_decode(
                             d, length, &out->filter_data_gyro_scale_factor_uncertainty, NULL) == MIPC_OK;
                }
                offset = offsetof(mipc_filter_data_packet_t, filter_data_gyro_scale_factor_uncertainty);
                break;
            case 0x19:
                if (length == 14) {
                    out->filter_data_accel_scale_factor_uncertainty.scale_factor_uncertainty[0] =
                        mipc_ld_f32(d + 0);
                    out->filter_data_accel_scale_factor_uncertainty.scale_factor_uncertainty[1] =
                        mipc_ld_f32(d + 4);
                    out->filter_data_accel_scale_factor_uncertainty.scale_factor_uncertainty[2] =
                        mipc_ld_f32(d + 8);
                    out->filter_data_accel_scale_factor_uncertainty.valid_flags = mipc_ld_u16(d + 12);
                    ok = 1;
                } else {
                    ok = mipc_filter_data_accel_scale_factor_uncertainty_decode(
                             d, length, &out->filter_data_accel_scale_factor_uncertainty, NULL) == MIPC_OK;
                }
                offset = offsetof(mipc_filter_data_packet_t, filter_data_accel_scale_factor_uncertainty);
                break;
            case 0x1C:
                if (length == 14) {
                    out->filter_data_compensated_accel.accel[0] = mipc_ld_f32(d + 0);
                    out->filter_data_compensated_accel.accel[1] = mipc_ld_f32(d + 4);
                    out->filter_data_compensated_accel.accel[2] = mipc_ld_f32(d + 8);
                    out->filter_data_compensated_accel.valid_flags = mipc_ld_u16(d + 12);
                    ok = 1;
                } else {
                    ok = mipc_filter_data_compensated_accel_decode(
                             d, length, &out->filter_data_compensated_accel, NULL) == MIPC_OK;
                }
                offset = offsetof(mipc_filter_data_packet_t, filter_data_compensated_accel);
                break;
            case 0x20:
                if (length == 22) {
                    out->filter_data_standard_atmosphere.geometric_altitude = mipc_ld_f32(d + 0);
                    out->filter_data_standard_atmosphere.geopotential_altitude = mipc_ld_f32(d + 4);
                    out->filter_data_standard_atmosphere.temperature = mipc_ld_f32(d + 8);
                    out->filter_data_standard_atmosphere.pressure = mipc_ld_f32(d + 12);
                    out->filter_data_standard_atmosphere.density = mipc_ld_f32(d + 16);
                    out->filter_data_standard_atmosphere.valid_flags = mipc_ld_u16(d + 20);
                    ok = 1;
                } else {
                    ok = mipc_filter_data_standard_atmosphere_decode(
                             d, length, &out->filter_data_standard_atmosphere, NULL) == MIPC_OK;
                }
                offset = offsetof(mipc_filter_data_packet_t, filter_data_standard_atmosphere);
                break;
            case 0x21:
                if (length == 6) {
                    out->filter_data_pressure_altitude.pressure_altitude = mipc_ld_f32(d + 0);
                    out->filter_data_pressure_altitude.valid_flags = mipc_ld_u16(d + 4);
                    ok = 1;
                } else {
                    ok = mipc_filter_data_pressure_altitude_decode(
                             d, length, &out->filter_data_pressure_altitude, NULL) == MIPC_OK;
                }
                offset = offsetof(mipc_filter_data_packet_t, filter_data_pressure_altitude);
                break;
            case 0x25:
                if (length == 14) {
                    out->filter_data_mag_auto_hard_iron_offset.hard_iron_offset[0] = mipc_ld_f32(d + 0);
                    out->filter_data_mag_auto_hard_iron_offset.hard_iron_offset[1] = mipc_ld_f32(d + 4);
                    out->filter_data_mag_auto_hard_iron_offset.hard_iron_offset[2] = mipc_ld_f32(d + 8);
                    out->filter_data_mag_auto_hard_iron_offset.valid_flags = mipc_ld_u16(d + 12);
                    ok = 1;
                } else {
                    ok = mipc_filter_data_mag_auto_hard_iron_offset_decode(
                             d, length, &out->filter_data_mag_auto_hard_iron_offset, NULL) == MIPC_OK;
                }
                offset = offsetof(mipc_filter_data_packet_t, filter_data_mag_auto_hard_iron_offset);
                break;
            case 0x26:
                if (length == 38) {
                    out->filter_data_mag_auto_soft_iron_matrix.soft_iron_matrix[0] = mipc_ld_f32(d + 0);
                    out->filter_data_mag_auto_soft_iron_matrix.soft_iron_matrix[1] = mipc_ld_f32(d + 4);
                    out->filter_data_mag_auto_soft_iron_matrix.soft_iron_matrix[2] = mipc_ld_f32(d + 8);
                    out->filter_data_mag_auto_soft_iron_matrix.soft_iron_matrix[3] = mipc_ld_f32(d + 12);
                    out->filter_data_mag_auto_soft_iron_matrix.soft_iron_matrix[4] = mipc_ld_f32(d + 16);
                    out->filter_data_mag_auto_soft_iron_matrix.soft_iron_matrix[5] = mipc_ld_f32(d + 20);
                    out->filter_data_mag_auto_soft_iron_matrix.soft_iron_matrix[6] = mipc_ld_f32(d + 24);
                    out->filter_data_mag_auto_soft_iron_matrix.soft_iron_matrix[7] = mipc_ld_f32(d + 28);
                    out->filter_data_mag_auto_soft_iron_matrix.soft_iron_matrix[8] = mipc_ld_f32(d + 32);
                    out->filter_data_mag_auto_soft_iron_matrix.valid_flags = mipc_ld_u16(d + 36);
                    ok = 1;
                } else {
                    ok = mipc_filter_data_mag_auto_soft_iron_matrix_decode(
                             d, length, &out->filter_data_mag_auto_soft_iron_matrix, NULL) == MIPC_OK;
                }
                offset = offsetof(mipc_filter_data_packet_t, filter_data_mag_auto_soft_iron_matrix);
                break;
            case 0x28:
                if (length == 14) {
                    out->filter_data_mag_auto_hard_iron_offset_uncertainty.hard_iron_offset_uncertainty[0] =
                        mipc_ld_f32(d + 0);
                    out->filter_data_mag_auto_hard_iron_offset_uncertainty.hard_iron_offset_uncertainty[1] =
                        mipc_ld_f32(d + 4);
                    out->filter_data_mag_auto_hard_iron_offset_uncertainty.hard_iron_offset_uncertainty[2] =
                        mipc_ld_f32(d + 8);
                    out->filter_data_mag_auto_hard_iron_offset_uncertainty.valid_flags = mipc_ld_u16(d + 12);
                    ok = 1;
                } else {
                    ok = mipc_filter_data_mag_auto_hard_iron_offset_uncertainty_decode(
                             d, length, &out->filter_data_mag_auto_hard_iron_offset_uncertainty, NULL) ==
                         MIPC_OK;
                }
                offset =
                    offsetof(mipc_filter_data_packet_t, filter_data_mag_auto_hard_iron_offset_uncertainty);
                break;
            case 0x29:
                if (length == 38) {
                    out->filter_data_mag_auto_soft_iron_matrix_uncertainty.soft_iron_matrix_uncertainty[0] =
                        mipc_ld_f32(d + 0);
                    out->filter_data_mag_auto_soft_iron_matrix_uncertainty.soft_iron_matrix_uncertainty[1] =
                        mipc_ld_f32(d + 4);
                    out->filter_data_mag_auto_soft_iron_matrix_uncertainty.soft_iron_matrix_uncertainty[2] =
                        mipc_ld_f32(d + 8);
                    out->filter_data_mag_auto_soft_iron_matrix_uncertainty.soft_iron_matrix_uncertainty[3] =
                        mipc_ld_f32(d + 12);
                    out->filter_data_mag_auto_soft_iron_matrix_uncertainty.soft_iron_matrix_uncertainty[4] =
                        mipc_ld_f32(d + 16);
                    out->filter_data_mag_auto_soft_iron_matrix_uncertainty.soft_iron_matrix_uncertainty[5] =
                        mipc_ld_f32(d + 20);
                    out->filter_data_mag_auto_soft_iron_matrix_uncertainty.soft_iron_matrix_uncertainty[6] =
                        mipc_ld_f32(d + 24);
                    out->filter_data_mag_auto_soft_iron_matrix_uncertainty.soft_iron_matrix_uncertainty[7] =
                        mipc_ld_f32(d + 28);
                    out->filter_data_mag_auto_soft_iron_matrix_uncertainty.soft_iron_matrix_uncertainty[8] =
                        mipc_ld_f32(d + 32);
                    out->filter_data_mag_auto_soft_iron_matrix_uncertainty.valid_flags = mipc_ld_u16(d + 36);
                    ok = 1;
                } else {
                    ok = mipc_filter_data_mag_auto_soft_iron_matrix_uncertainty_decode(
                             d, length, &out->filter_data_mag_auto_soft_iron_matrix_uncertainty, NULL) ==
                         MIPC_OK;
                }
                offset =
                    offsetof(mipc_filter_data_packet_t, filter_data_mag_auto_soft_iron_matrix_uncertainty);
                break;
            case 0x30:
                if (length == 14) {
                    out->filter_data_gnss_antenna_offset_correction.offset[0] = mipc_ld_f32(d + 0);
                    out->filter_data_gnss_antenna_offset_correction.offset[1] = mipc_ld_f32(d + 4);
                    out->filter_data_gnss_antenna_offset_correction.offset[2] = mipc_ld_f32(d + 8);
                    out->filter_data_gnss_antenna_offset_correction.valid_flags = mipc_ld_u16(d + 12);
                    ok = 1;
                } else {
                    ok = mipc_filter_data_gnss_antenna_offset_correction_decode(
                             d, length, &out->filter_data_gnss_antenna_offset_correction, NULL) == MIPC_OK;
                }
                offset = offsetof(mipc_filter_data_packet_t, filter_data_gnss_antenna_offset_correction);
                break;
            case 0x31:
                if (length == 14) {
                    out->filter_data_gnss_antenna_offset_correction_uncertainty.offset_uncertainty[0] =
                        mipc_ld_f32(d + 0);
                    out->filter_data_gnss_antenna_offset_correction_uncertainty.offset_uncertainty[1] =
                        mipc_ld_f32(d + 4);
                    out->filter_data_gnss_antenna_offset_correction_uncertainty.offset_uncertainty[2] =
                        mipc_ld_f32(d + 8);
                    out->filter_data_gnss_antenna_offset_correction_uncertainty.valid_flags =
                        mipc_ld_u16(d + 12);
                    ok = 1;
                } else {
                    ok = mipc_filter_data_gnss_antenna_offset_correction_uncertainty_decode(
                             d, length, &out->filter_data_gnss_antenna_offset_correction_uncertainty, NULL) ==
                         MIPC_OK;
                }
                offset = offsetof(mipc_filter_data_packet_t,
                                  filter_data_gnss_antenna_offset_correction_uncertainty);
                break;
            case 0x34:
                if (length == 15) {
                    out->filter_data_multi_antenna_offset_correction.receiver_id = mipc_ld_u8(d + 0);
                    out->filter_data_multi_antenna_offset_correction.offset[0] = mipc_ld_f32(d + 1);
                    out->filter_data_multi_antenna_offset_correction.offset[1] = mipc_ld_f32(d + 5);
                    out->filter_data_multi_antenna_offset_correction.offset[2] = mipc_ld_f32(d + 9);
                    out->filter_data_multi_antenna_offset_correction.valid_flags = mipc_ld_u16(d + 13);
                    ok = 1;
                } else {
                    ok = mipc_filter_data_multi_antenna_offset_correction_decode(
                             d, length, &out->filter_data_multi_antenna_offset_correction, NULL) == MIPC_OK;
                }
                offset = offsetof(mipc_filter_data_packet_t, filter_data_multi_antenna_offset_correction);
                break;
            case 0x35:
                if (length == 15) {
                    out->filter_data_multi_antenna_offset_correction_uncertainty.receiver_id =
                        mipc_ld_u8(d + 0);
                    out->filter_data_multi_antenna_offset_correction_uncertainty.offset_uncertainty[0] =
                        mipc_ld_f32(d + 1);
                    out->filter_data_multi_antenna_offset_correction_uncertainty.offset_uncertainty[1] =
                        mipc_ld_f32(d + 5);
                    out->filter_data_multi_antenna_offset_correction_uncertainty.offset_uncertainty[2] =
                        mipc_ld_f32(d + 9);
                    out->filter_data_multi_antenna_offset_correction_uncertainty.valid_flags =
                        mipc_ld_u16(d + 13);
                    ok = 1;
                } else {
                    ok = mipc_filter_data_multi_antenna_offset_correction_uncertainty_decode(
                             d, length, &out->filter_data_multi_antenna_offset_correction_uncertainty,
                             NULL) == MIPC_OK;
                }
                offset = offsetof(mipc_filter_data_packet_t,
                                  filter_data_multi_antenna_offset_correction_uncertainty);
                break;
            case 0x36:
                if (length == 14) {
                    out->filter_data_ecef_position_uncertainty.position_uncertainty[0] = mipc_ld_f32(d + 0);
                    out->filter_data_ecef_position_uncertainty.position_uncertainty[1] = mipc_ld_f32(d + 4);
                    out->filter_data_ecef_position_uncertainty.position_uncertainty[2] = mipc_ld_f32(d + 8);
                    out->filter_data_ecef_position_uncertainty.valid_flags = mipc_ld_u16(d + 12);
                    ok = 1;
                } else {
                    ok = mipc_filter_data_ecef_position_uncertainty_decode(
                             d, length, &out->filter_data_ecef_position_uncertainty, NULL) == MIPC_OK;
                }
                offset = offsetof(mipc_filter_data_packet_t, filter_data_ecef_position_uncertainty);
                break;
            case 0x37:
                if (length == 14) {
                    out->filter_data_ecef_velocity_uncertainty.velocity_uncertainty[0] = mipc_ld_f32(d + 0);
                    out->filter_data_ecef_velocity_uncertainty.velocity_uncertainty[1] = mipc_ld_f32(d + 4);
                    out->filter_data_ecef_velocity_uncertainty.velocity_uncertainty[2] = mipc_ld_f32(d + 8);
                    out->filter_data_ecef_velocity_uncertainty.valid_flags = mipc_ld_u16(d + 12);
                    ok = 1;
                } else {
                    ok = mipc_filter_data_ecef_velocity_uncertainty_decode(
                             d, length, &out->filter_data_ecef_velocity_uncertainty, NULL) == MIPC_OK;
                }
                offset = offsetof(mipc_filter_data_packet_t, filter_data_ecef_velocity_uncertainty);
                break;
            case 0x40:
                if (length == 26) {
                    out->filter_data_ecef_position.position[0] = mipc_ld_f64(d + 0);
                    out->filter_data_ecef_position.position[1] = mipc_ld_f64(d + 8);
                    out->filter_data_ecef_position.position[2] = mipc_ld_f64(d + 16);
                    out->filter_data_ecef_position.valid_flags = mipc_ld_u16(d + 24);
                    ok = 1;
                } else {
                    ok = mipc_filter_data_ecef_position_decode(d, length, &out->filter_data_ecef_position,
                                                               NULL) == MIPC_OK;
                }
                offset = offsetof(mipc_filter_data_packet_t, filter_data_ecef_position);
                break;
            case 0x41:
                if (length == 14) {
                    out->filter_data_ecef_velocity.velocity[0] = mipc_ld_f32(d + 0);
                    out->filter_data_ecef_velocity.velocity[1] = mipc_ld_f32(d + 4);
                    out->filter_data_ecef_velocity.velocity[2] = mipc_ld_f32(d + 8);
                    out->filter_data_ecef_velocity.valid_flags = mipc_ld_u16(d + 12);
                    ok = 1;
                } else {
                    ok = mipc_filter_data_ecef_velocity_decode(d, length, &out->filter_data_ecef_velocity,
                                                               NULL) == MIPC_OK;
                }
                offset = offsetof(mipc_filter_data_packet_t, filter_data_ecef_velocity);
                break;
            case 0x42:
                if (length == 26) {
                    out->filter_data_ned_relative_position.relative_position[0] = mipc_ld_f64(d + 0);
                    out->filter_data_ned_relative_position.relative_position[1] = mipc_ld_f64(d + 8);
                    out->filter_data_ned_relative_position.relative_position[2] = mipc_ld_f64(d + 16);
                    out->filter_data_ned_relative_position.valid_flags = mipc_ld_u16(d + 24);
                    ok = 1;
                } else {
                    ok = mipc_filter_data_ned_relative_position_decode(
                             d, length, &out->filter_data_ned_relative_position, NULL) == MIPC_OK;
                }
                offset = offsetof(mipc_filter_data_packet_t, filter_data_ned_relative_position);
                break;
            case 0x43:
                if (length == 15) {
                    out->filter_data_gnss_position_aiding_status.receiver_id = mipc_ld_u8(d + 0);
                    out->filter_data_gnss_position_aiding_status.time_of_week = mipc_ld_f32(d + 1);
                    out->filter_data_gnss_position_aiding_status.status = mipc_ld_u16(d + 5);
                    out->filter_data_gnss_position_aiding_status.reserved[0] = mipc_ld_u8(d + 7);
                    out->filter_data_gnss_position_aiding_status.reserved[1] = mipc_ld_u8(d + 8);
                    out->filter_data_gnss_position_aiding_status.reserved[2] = mipc_ld_u8(d + 9);
                    out->filter_data_gnss_position_aiding_status.reserved[3] = mipc_ld_u8(d + 10);
                    out->filter_data_gnss_position_aiding_status.reserved[4] = mipc_ld_u8(d + 11);
                    out->filter_data_gnss_position_aiding_status.reserved[5] = mipc_ld_u8(d + 12);
                    out->filter_data_gnss_position_aiding_status.reserved[6] = mipc_ld_u8(d + 13);
                    out->filter_data_gnss_position_aiding_status.reserved[7] = mipc_ld_u8(d + 14);
                    ok = 1;
                } else {
                    ok = mipc_filter_data_gnss_position_aiding_status_decode(
                             d, length, &out->filter_data_gnss_position_aiding_status, NULL) == MIPC_OK;
                }
                offset = offsetof(mipc_filter_data_packet_t, filter_data_gnss_position_aiding_status);
                break;
            case 0x46:
                if (length == 7) {
                    out->filter_data_aiding_measurement_summary.time_of_week = mipc_ld_f32(d + 0);
                    out->filter_data_aiding_measurement_summary.source = mipc_ld_u8(d + 4);
                    out->filter_data_aiding_measurement_summary.type = mipc_ld_u8(d + 5);
                    out->filter_data_aiding_measurement_summary.indicator = mipc_ld_u8(d + 6);
                    ok = 1;
                } else {
                    ok = mipc_filter_data_aiding_measurement_summary_decode(
                             d, length, &out->filter_data_aiding_measurement_summary, NULL) == MIPC_OK;
                }
                offset = offsetof(mipc_filter_data_packet_t, filter_data_aiding_measurement_summary);
                break;
            case 0x47:
                if (length == 6) {
                    out->filter_data_odometer_scale_factor_error.scale_factor_error = mipc_ld_f32(d + 0);
                    out->filter_data_odometer_scale_factor_error.valid_flags = mipc_ld_u16(d + 4);
                    ok = 1;
                } else {
                    ok = mipc_filter_data_odometer_scale_factor_error_decode(
                             d, length, &out->filter_data_odometer_scale_factor_error, NULL) == MIPC_OK;
                }
                offset = offsetof(mipc_filter_data_packet_t, filter_data_odometer_scale_factor_error);
                break;
            case 0x48:
                if (length == 6) {
                    out->filter_data_odometer_scale_factor_error_uncertainty.scale_factor_error_uncertainty =
                        mipc_ld_f32(d + 0);
                    out->filter_data_odometer_scale_factor_error_uncertainty.valid_flags = mipc_ld_u16(d + 4);
                    ok = 1;
                } else {
                    ok = mipc_filter_data_odometer_scale_factor_error_uncertainty_decode(
                             d, length, &out->filter_data_odometer_scale_factor_error_uncertainty, NULL) ==
                         MIPC_OK;
                }
                offset =
                    offsetof(mipc_filter_data_packet_t, filter_data_odometer_scale_factor_error_uncertainty);
                break;
            case 0x49:
                if (length == 17) {
                    out->filter_data_gnss_dual_antenna_status.time_of_week = mipc_ld_f32(d + 0);
                    out->filter_data_gnss_dual_antenna_status.heading = mipc_ld_f32(d + 4);
                    out->filter_data_gnss_dual_antenna_status.heading_uncertainty = mipc_ld_f32(d + 8);
                    out->filter_data_gnss_dual_antenna_status.fix_type = mipc_ld_u8(d + 12);
                    out->filter_data_gnss_dual_antenna_status.status_flags = mipc_ld_u16(d + 13);
                    out->filter_data_gnss_dual_antenna_status.valid_flags = mipc_ld_u16(d + 15);
                    ok = 1;
                } else {
                    ok = mipc_filter_data_gnss_dual_antenna_status_decode(
                             d, length, &out->filter_data_gnss_dual_antenna_status, NULL) == MIPC_OK;
                }
                offset = offsetof(mipc_filter_data_packet_t, filter_data_gnss_dual_antenna_status);
                break;
            case 0x50:
                if (length == 29) {
                    out->filter_data_aiding_frame_config_error.frame_id = mipc_ld_u8(d + 0);
                    out->filter_data_aiding_frame_config_error.translation[0] = mipc_ld_f32(d + 1);
                    out->filter_data_aiding_frame_config_error.translation[1] = mipc_ld_f32(d + 5);
                    out->filter_data_aiding_frame_config_error.translation[2] = mipc_ld_f32(d + 9);
                    out->filter_data_aiding_frame_config_error.attitude[0] = mipc_ld_f32(d + 13);
                    out->filter_data_aiding_frame_config_error.attitude[1] = mipc_ld_f32(d + 17);
                    out->filter_data_aiding_frame_config_error.attitude[2] = mipc_ld_f32(d + 21);
                    out->filter_data_aiding_frame_config_error.attitude[3] = mipc_ld_f32(d + 25);
                    ok = 1;
                } else {
                    ok = mipc_filter_data_aiding_frame_config_error_decode(
                             d, length, &out->filter_data_aiding_frame_config_error, NULL) == MIPC_OK;
                }
                offset = offsetof(mipc_filter_data_packet_t, filter_data_aiding_frame_config_error);
                break;
            case 0x51:
                if (length == 25) {
                    out->filter_data_aiding_frame_config_error_uncertainty.frame_id = mipc_ld_u8(d + 0);
                    out->filter_data_aiding_frame_config_error_uncertainty.translation_uncertainty[0] =
                        mipc_ld_f32(d + 1);
                    out->filter_data_aiding_frame_config_error_uncertainty.translation_uncertainty[1] =
                        mipc_ld_f32(d + 5);
                    out->filter_data_aiding_frame_config_error_uncertainty.translation_uncertainty[2] =
                        mipc_ld_f32(d + 9);
                    out->filter_data_aiding_frame_config_error_uncertainty.attitude_uncertainty[0] =
                        mipc_ld_f32(d + 13);
                    out->filter_data_aiding_frame_config_error_uncertainty.attitude_uncertainty[1] =
                        mipc_ld_f32(d + 17);
                    out->filter_data_aiding_frame_config_error_uncertainty.attitude_uncertainty[2] =
                        mipc_ld_f32(d + 21);
                    ok = 1;
                } else {
                    ok = mipc_filter_data_aiding_frame_config_error_uncertainty_decode(
                             d, length, &out->filter_data_aiding_frame_config_error_uncertainty, NULL) ==
                         MIPC_OK;
                }
                offset =
                    offsetof(mipc_filter_data_packet_t, filter_data_aiding_frame_config_error_uncertainty);
                break;
            case 0xD0:
                if (length == 1) {
                    out->shared_event_source.trigger_id = mipc_ld_u8(d + 0);
                    ok = 1;
                } else {
                    ok = mipc_shared_event_source_decode(d, length, &out->shared_event_source, NULL) ==
                         MIPC_OK;
                }
                offset = offsetof(mipc_filter_data_packet_t, shared_event_source);
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
                offset = offsetof(mipc_filter_data_packet_t, shared_gps_timestamp);
                break;
            case 0xD4:
                if (length == 8) {
                    out->shared_delta_time.seconds = mipc_ld_f64(d + 0);
                    ok = 1;
                } else {
                    ok = mipc_shared_delta_time_decode(d, length, &out->shared_delta_time, NULL) == MIPC_OK;
                }
                offset = offsetof(mipc_filter_data_packet_t, shared_delta_time);
                break;
            case 0xD5:
                if (length == 8) {
                    out->shared_reference_timestamp.nanoseconds = mipc_ld_u64(d + 0);
                    ok = 1;
                } else {
                    ok = mipc_shared_reference_timestamp_decode(d, length, &out->shared_reference_timestamp,
                                                                NULL) == MIPC_OK;
                }
                offset = offsetof(mipc_filter_data_packet_t, shared_reference_timestamp);
                break;
            case 0xD6:
                if (length == 8) {
                    out->shared_reference_time_delta.dt_nanos = mipc_ld_u64(d + 0);
                    ok = 1;
                } else {
                    ok = mipc_shared_reference_time_delta_decode(d, length, &out->shared_reference_time_delta,
                                                                 NULL) == MIPC_OK;
                }
                offset = offsetof(mipc_filter_data_packet_t, shared_reference_time_delta);
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
                offset = offsetof(mipc_filter_data_packet_t, shared_external_timestamp);
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
                offset = offsetof(mipc_filter_data_packet_t, shared_external_time_delta);
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
            mipc_field_visit_at_(MIPC_FILTER_DATA_SET, payload, len, pos, other, ctx);
        }
        pos += MIPC_FIELD_HEADER_SIZE + length;
    }
    if (pos < len && other) {
        mipc_field_visit_at_(MIPC_FILTER_DATA_SET, payload, len, pos, other, ctx);
    }
    out->index.count = n;
    return n;
}

/* ---- the members' loaders (mipc_decode_packet_cached, issue 38): each decodes its field's
 * data into its member of the mipc_filter_data_packet_t at packet as mipc_filter_data_decode_packet does; 0
 * when it does not decode (the packet then takes the straight-line decoder, which gives the field to other)
 */

static int load_0x01(const uint8_t *d, size_t length, void *packet) {
    mipc_filter_data_packet_t *out = packet;
    if (length == 26) {
        out->filter_data_llh_position.latitude = mipc_ld_f64(d + 0);
        out->filter_data_llh_position.longitude = mipc_ld_f64(d + 8);
        out->filter_data_llh_position.ellipsoid_height = mipc_ld_f64(d + 16);
        out->filter_data_llh_position.valid_flags = mipc_ld_u16(d + 24);
        return 1;
    }
    return mipc_filter_data_llh_position_decode(d, length, &out->filter_data_llh_position, NULL) == MIPC_OK;
}

static int load_0x02(const uint8_t *d, size_t length, void *packet) {
    mipc_filter_data_packet_t *out = packet;
    if (length == 14) {
        out->filter_data_ned_velocity.north = mipc_ld_f32(d + 0);
        out->filter_data_ned_velocity.east = mipc_ld_f32(d + 4);
        out->filter_data_ned_velocity.down = mipc_ld_f32(d + 8);
        out->filter_data_ned_velocity.valid_flags = mipc_ld_u16(d + 12);
        return 1;
    }
    return mipc_filter_data_ned_velocity_decode(d, length, &out->filter_data_ned_velocity, NULL) == MIPC_OK;
}

static int load_0x03(const uint8_t *d, size_t length, void *packet) {
    mipc_filter_data_packet_t *out = packet;
    if (length == 18) {
        out->filter_data_attitude_quaternion.q[0] = mipc_ld_f32(d + 0);
        out->filter_data_attitude_quaternion.q[1] = mipc_ld_f32(d + 4);
        out->filter_data_attitude_quaternion.q[2] = mipc_ld_f32(d + 8);
        out->filter_data_attitude_quaternion.q[3] = mipc_ld_f32(d + 12);
        out->filter_data_attitude_quaternion.valid_flags = mipc_ld_u16(d + 16);
        return 1;
    }
    return mipc_filter_data_attitude_quaternion_decode(d, length, &out->filter_data_attitude_quaternion,
                                                       NULL) == MIPC_OK;
}

static int load_0x04(const uint8_t *d, size_t length, void *packet) {
    mipc_filter_data_packet_t *out = packet;
    if (length == 38) {
        out->filter_data_attitude_dcm.dcm[0] = mipc_ld_f32(d + 0);
        out->filter_data_attitude_dcm.dcm[1] = mipc_ld_f32(d + 4);
        out->filter_data_attitude_dcm.dcm[2] = mipc_ld_f32(d + 8);
        out->filter_data_attitude_dcm.dcm[3] = mipc_ld_f32(d + 12);
        out->filter_data_attitude_dcm.dcm[4] = mipc_ld_f32(d + 16);
        out->filter_data_attitude_dcm.dcm[5] = mipc_ld_f32(d + 20);
        out->filter_data_attitude_dcm.dcm[6] = mipc_ld_f32(d + 24);
        out->filter_data_attitude_dcm.dcm[7] = mipc_ld_f32(d + 28);
        out->filter_data_attitude_dcm.dcm[8] = mipc_ld_f32(d + 32);
        out->filter_data_attitude_dcm.valid_flags = mipc_ld_u16(d + 36);
        return 1;
    }
    return mipc_filter_data_attitude_dcm_decode(d, length, &out->filter_data_attitude_dcm, NULL) == MIPC_OK;
}

static int load_0x05(const uint8_t *d, size_t length, void *packet) {
    mipc_filter_data_packet_t *out = packet;
    if (length == 14) {
        out->filter_data_euler_angles.roll = mipc_ld_f32(d + 0);
        out->filter_data_euler_angles.pitch = mipc_ld_f32(d + 4);
        out->filter_data_euler_angles.yaw = mipc_ld_f32(d + 8);
        out->filter_data_euler_angles.valid_flags = mipc_ld_u16(d + 12);
        return 1;
    }
    return mipc_filter_data_euler_angles_decode(d, length, &out->filter_data_euler_angles, NULL) == MIPC_OK;
}

static int load_0x06(const uint8_t *d, size_t length, void *packet) {
    mipc_filter_data_packet_t *out = packet;
    if (length == 14) {
        out->filter_data_gyro_bias.bias[0] = mipc_ld_f32(d + 0);
        out->filter_data_gyro_bias.bias[1] = mipc_ld_f32(d + 4);
        out->filter_data_gyro_bias.bias[2] = mipc_ld_f32(d + 8);
        out->filter_data_gyro_bias.valid_flags = mipc_ld_u16(d + 12);
        return 1;
    }
    return mipc_filter_data_gyro_bias_decode(d, length, &out->filter_data_gyro_bias, NULL) == MIPC_OK;
}

static int load_0x07(const uint8_t *d, size_t length, void *packet) {
    mipc_filter_data_packet_t *out = packet;
    if (length == 14) {
        out->filter_data_accel_bias.bias[0] = mipc_ld_f32(d + 0);
        out->filter_data_accel_bias.bias[1] = mipc_ld_f32(d + 4);
        out->filter_data_accel_bias.bias[2] = mipc_ld_f32(d + 8);
        out->filter_data_accel_bias.valid_flags = mipc_ld_u16(d + 12);
        return 1;
    }
    return mipc_filter_data_accel_bias_decode(d, length, &out->filter_data_accel_bias, NULL) == MIPC_OK;
}

static int load_0x08(const uint8_t *d, size_t length, void *packet) {
    mipc_filter_data_packet_t *out = packet;
    if (length == 14) {
        out->filter_data_llh_position_uncertainty.north = mipc_ld_f32(d + 0);
        out->filter_data_llh_position_uncertainty.east = mipc_ld_f32(d + 4);
        out->filter_data_llh_position_uncertainty.down = mipc_ld_f32(d + 8);
        out->filter_data_llh_position_uncertainty.valid_flags = mipc_ld_u16(d + 12);
        return 1;
    }
    return mipc_filter_data_llh_position_uncertainty_decode(
               d, length, &out->filter_data_llh_position_uncertainty, NULL) == MIPC_OK;
}

static int load_0x09(const uint8_t *d, size_t length, void *packet) {
    mipc_filter_data_packet_t *out = packet;
    if (length == 14) {
        out->filter_data_ned_velocity_uncertainty.north = mipc_ld_f32(d + 0);
        out->filter_data_ned_velocity_uncertainty.east = mipc_ld_f32(d + 4);
        out->filter_data_ned_velocity_uncertainty.down = mipc_ld_f32(d + 8);
        out->filter_data_ned_velocity_uncertainty.valid_flags = mipc_ld_u16(d + 12);
        return 1;
    }
    return mipc_filter_data_ned_velocity_uncertainty_decode(
               d, length, &out->filter_data_ned_velocity_uncertainty, NULL) == MIPC_OK;
}

static int load_0x0a(const uint8_t *d, size_t length, void *packet) {
    mipc_filter_data_packet_t *out = packet;
    if (length == 14) {
        out->filter_data_euler_angles_uncertainty.roll = mipc_ld_f32(d + 0);
        out->filter_data_euler_angles_uncertainty.pitch = mipc_ld_f32(d + 4);
        out->filter_data_euler_angles_uncertainty.yaw = mipc_ld_f32(d + 8);
        out->filter_data_euler_angles_uncertainty.valid_flags = mipc_ld_u16(d + 12);
        return 1;
    }
    return mipc_filter_data_euler_angles_uncertainty_decode(
               d, length, &out->filter_data_euler_angles_uncertainty, NULL) == MIPC_OK;
}

static int load_0x0b(const uint8_t *d, size_t length, void *packet) {
    mipc_filter_data_packet_t *out = packet;
    if (length == 14) {
        out->filter_data_gyro_bias_uncertainty.bias_uncertainty[0] = mipc_ld_f32(d + 0);
        out->filter_data_gyro_bias_uncertainty.bias_uncertainty[1] = mipc_ld_f32(d + 4);
        out->filter_data_gyro_bias_uncertainty.bias_uncertainty[2] = mipc_ld_f32(d + 8);
        out->filter_data_gyro_bias_uncertainty.valid_flags = mipc_ld_u16(d + 12);
        return 1;
    }
    return mipc_filter_data_gyro_bias_uncertainty_decode(d, length, &out->filter_data_gyro_bias_uncertainty,
                                                         NULL) == MIPC_OK;
}

static int load_0x0c(const uint8_t *d, size_t length, void *packet) {
    mipc_filter_data_packet_t *out = packet;
    if (length == 14) {
        out->filter_data_accel_bias_uncertainty.bias_uncertainty[0] = mipc_ld_f32(d + 0);
        out->filter_data_accel_bias_uncertainty.bias_uncertainty[1] = mipc_ld_f32(d + 4);
        out->filter_data_accel_bias_uncertainty.bias_uncertainty[2] = mipc_ld_f32(d + 8);
        out->filter_data_accel_bias_uncertainty.valid_flags = mipc_ld_u16(d + 12);
        return 1;
    }
    return mipc_filter_data_accel_bias_uncertainty_decode(d, length, &out->filter_data_accel_bias_uncertainty,
                                                          NULL) == MIPC_OK;
}

static int load_0x0d(const uint8_t *d, size_t length, void *packet) {
    mipc_filter_data_packet_t *out = packet;
    if (length == 14) {
        out->filter_data_linear_accel.accel[0] = mipc_ld_f32(d + 0);
        out->filter_data_linear_accel.accel[1] = mipc_ld_f32(d + 4);
        out->filter_data_linear_accel.accel[2] = mipc_ld_f32(d + 8);
        out->filter_data_linear_accel.valid_flags = mipc_ld_u16(d + 12);
        return 1;
    }
    return mipc_filter_data_linear_accel_decode(d, length, &out->filter_data_linear_accel, NULL) == MIPC_OK;
}

static int load_0x0e(const uint8_t *d, size_t length, void *packet) {
    mipc_filter_data_packet_t *out = packet;
    if (length == 14) {
        out->filter_data_comp_angular_rate.gyro[0] = mipc_ld_f32(d + 0);
        out->filter_data_comp_angular_rate.gyro[1] = mipc_ld_f32(d + 4);
        out->filter_data_comp_angular_rate.gyro[2] = mipc_ld_f32(d + 8);
        out->filter_data_comp_angular_rate.valid_flags = mipc_ld_u16(d + 12);
        return 1;
    }
    return mipc_filter_data_comp_angular_rate_decode(d, length, &out->filter_data_comp_angular_rate, NULL) ==
           MIPC_OK;
}

static int load_0x0f(const uint8_t *d, size_t length, void *packet) {
    mipc_filter_data_packet_t *out = packet;
    if (length == 6) {
        out->filter_data_wgs84_gravity_magnitude.gravity_magnitude = mipc_ld_f32(d + 0);
        out->filter_data_wgs84_gravity_magnitude.valid_flags = mipc_ld_u16(d + 4);
        return 1;
    }
    return mipc_filter_data_wgs84_gravity_magnitude_decode(
               d, length, &out->filter_data_wgs84_gravity_magnitude, NULL) == MIPC_OK;
}

static int load_0x11(const uint8_t *d, size_t length, void *packet) {
    mipc_filter_data_packet_t *out = packet;
    if (length == 12) {
        out->filter_data_gps_timestamp.tow = mipc_ld_f64(d + 0);
        out->filter_data_gps_timestamp.week_number = mipc_ld_u16(d + 8);
        out->filter_data_gps_timestamp.valid_flags = mipc_ld_u16(d + 10);
        return 1;
    }
    return mipc_filter_data_gps_timestamp_decode(d, length, &out->filter_data_gps_timestamp, NULL) == MIPC_OK;
}

static int load_0x12(const uint8_t *d, size_t length, void *packet) {
    mipc_filter_data_packet_t *out = packet;
    if (length == 18) {
        out->filter_data_quaternion_attitude_uncertainty.q[0] = mipc_ld_f32(d + 0);
        out->filter_data_quaternion_attitude_uncertainty.q[1] = mipc_ld_f32(d + 4);
        out->filter_data_quaternion_attitude_uncertainty.q[2] = mipc_ld_f32(d + 8);
        out->filter_data_quaternion_attitude_uncertainty.q[3] = mipc_ld_f32(d + 12);
        out->filter_data_quaternion_attitude_uncertainty.valid_flags = mipc_ld_u16(d + 16);
        return 1;
    }
    return mipc_filter_data_quaternion_attitude_uncertainty_decode(
               d, length, &out->filter_data_quaternion_attitude_uncertainty, NULL) == MIPC_OK;
}

static int load_0x13(const uint8_t *d, size_t length, void *packet) {
    mipc_filter_data_packet_t *out = packet;
    if (length == 14) {
        out->filter_data_gravity_vector.gravity[0] = mipc_ld_f32(d + 0);
        out->filter_data_gravity_vector.gravity[1] = mipc_ld_f32(d + 4);
        out->filter_data_gravity_vector.gravity[2] = mipc_ld_f32(d + 8);
        out->filter_data_gravity_vector.valid_flags = mipc_ld_u16(d + 12);
        return 1;
    }
    return mipc_filter_data_gravity_vector_decode(d, length, &out->filter_data_gravity_vector, NULL) ==
           MIPC_OK;
}

static int load_0x14(const uint8_t *d, size_t length, void *packet) {
    mipc_filter_data_packet_t *out = packet;
    if (length == 12) {
        out->filter_data_heading_update_state.heading = mipc_ld_f32(d + 0);
        out->filter_data_heading_update_state.heading_uncertainty = mipc_ld_f32(d + 4);
        out->filter_data_heading_update_state.source = mipc_ld_u16(d + 8);
        out->filter_data_heading_update_state.valid_flags = mipc_ld_u16(d + 10);
        return 1;
    }
    return mipc_filter_data_heading_update_state_decode(d, length, &out->filter_data_heading_update_state,
                                                        NULL) == MIPC_OK;
}

static int load_0x15(const uint8_t *d, size_t length, void *packet) {
    mipc_filter_data_packet_t *out = packet;
    if (length == 22) {
        out->filter_data_magnetic_model.intensity_north = mipc_ld_f32(d + 0);
        out->filter_data_magnetic_model.intensity_east = mipc_ld_f32(d + 4);
        out->filter_data_magnetic_model.intensity_down = mipc_ld_f32(d + 8);
        out->filter_data_magnetic_model.inclination = mipc_ld_f32(d + 12);
        out->filter_data_magnetic_model.declination = mipc_ld_f32(d + 16);
        out->filter_data_magnetic_model.valid_flags = mipc_ld_u16(d + 20);
        return 1;
    }
    return mipc_filter_data_magnetic_model_decode(d, length, &out->filter_data_magnetic_model, NULL) ==
           MIPC_OK;
}

static int load_0x16(const uint8_t *d, size_t length, void *packet) {
    mipc_filter_data_packet_t *out = packet;
    if (length == 14) {
        out->filter_data_gyro_scale_factor.scale_factor[0] = mipc_ld_f32(d + 0);
        out->filter_data_gyro_scale_factor.scale_factor[1] = mipc_ld_f32(d + 4);
        out->filter_data_gyro_scale_factor.scale_factor[2] = mipc_ld_f32(d + 8);
        out->filter_data_gyro_scale_factor.valid_flags = mipc_ld_u16(d + 12);
        return 1;
    }
    return mipc_filter_data_gyro_scale_factor_decode(d, length, &out->filter_data_gyro_scale_factor, NULL) ==
           MIPC_OK;
}

static int load_0x17(const uint8_t *d, size_t length, void *packet) {
    mipc_filter_data_packet_t *out = packet;
    if (length == 14) {
        out->filter_data_accel_scale_factor.scale_factor[0] = mipc_ld_f32(d + 0);
        out->filter_data_accel_scale_factor.scale_factor[1] = mipc_ld_f32(d + 4);
        out->filter_data_accel_scale_factor.scale_factor[2] = mipc_ld_f32(d + 8);
        out->filter_data_accel_scale_factor.valid_flags = mipc_ld_u16(d + 12);
        return 1;
    }
    return mipc_filter_data_accel_scale_factor_decode(d, length, &out->filter_data_accel_scale_factor,
                                                      NULL) == MIPC_OK;
}

static int load_0x18(const uint8_t *d, size_t length, void *packet) {
    mipc_filter_data_packet_t *out = packet;
    if (length == 14) {
        out->filter_data_gyro_scale_factor_uncertainty.scale_factor_uncertainty[0] = mipc_ld_f32(d + 0);
        out->filter_data_gyro_scale_factor_uncertainty.scale_factor_uncertainty[1] = mipc_ld_f32(d + 4);
        out->filter_data_gyro_scale_factor_uncertainty.scale_factor_uncertainty[2] = mipc_ld_f32(d + 8);
        out->filter_data_gyro_scale_factor_uncertainty.valid_flags = mipc_ld_u16(d + 12);
        return 1;
    }
    return mipc_filter_data_gyro_scale_factor_uncertainty_decode(
               d, length, &out->filter_data_gyro_scale_factor_uncertainty, NULL) == MIPC_OK;
}

static int load_0x19(const uint8_t *d, size_t length, void *packet) {
    mipc_filter_data_packet_t *out = packet;
    if (length == 14) {
        out->filter_data_accel_scale_factor_uncertainty.scale_factor_uncertainty[0] = mipc_ld_f32(d + 0);
        out->filter_data_accel_scale_factor_uncertainty.scale_factor_uncertainty[1] = mipc_ld_f32(d + 4);
        out->filter_data_accel_scale_factor_uncertainty.scale_factor_uncertainty[2] = mipc_ld_f32(d + 8);
        out->filter_data_accel_scale_factor_uncertainty.valid_flags = mipc_ld_u16(d + 12);
        return 1;
    }
    return mipc_filter_data_accel_scale_factor_uncertainty_decode(
               d, length, &out->filter_data_accel_scale_factor_uncertainty, NULL) == MIPC_OK;
}

static int load_0x1c(const uint8_t *d, size_t length, void *packet) {
    mipc_filter_data_packet_t *out = packet;
    if (length == 14) {
        out->filter_data_compensated_accel.accel[0] = mipc_ld_f32(d + 0);
        out->filter_data_compensated_accel.accel[1] = mipc_ld_f32(d + 4);
        out->filter_data_compensated_accel.accel[2] = mipc_ld_f32(d + 8);
        out->filter_data_compensated_accel.valid_flags = mipc_ld_u16(d + 12);
        return 1;
    }
    return mipc_filter_data_compensated_accel_decode(d, length, &out->filter_data_compensated_accel, NULL) ==
           MIPC_OK;
}

static int load_0x20(const uint8_t *d, size_t length, void *packet) {
    mipc_filter_data_packet_t *out = packet;
    if (length == 22) {
        out->filter_data_standard_atmosphere.geometric_altitude = mipc_ld_f32(d + 0);
        out->filter_data_standard_atmosphere.geopotential_altitude = mipc_ld_f32(d + 4);
        out->filter_data_standard_atmosphere.temperature = mipc_ld_f32(d + 8);
        out->filter_data_standard_atmosphere.pressure = mipc_ld_f32(d + 12);
        out->filter_data_standard_atmosphere.density = mipc_ld_f32(d + 16);
        out->filter_data_standard_atmosphere.valid_flags = mipc_ld_u16(d + 20);
        return 1;
    }
    return mipc_filter_data_standard_atmosphere_decode(d, length, &out->filter_data_standard_atmosphere,
                                                       NULL) == MIPC_OK;
}

static int load_0x21(const uint8_t *d, size_t length, void *packet) {
    mipc_filter_data_packet_t *out = packet;
    if (length == 6) {
        out->filter_data_pressure_altitude.pressure_altitude = mipc_ld_f32(d + 0);
        out->filter_data_pressure_altitude.valid_flags = mipc_ld_u16(d + 4);
        return 1;
    }
    return mipc_filter_data_pressure_altitude_decode(d, length, &out->filter_data_pressure_altitude, NULL) ==
           MIPC_OK;
}

static int load_0x25(const uint8_t *d, size_t length, void *packet) {
    mipc_filter_data_packet_t *out = packet;
    if (length == 14) {
        out->filter_data_mag_auto_hard_iron_offset.hard_iron_offset[0] = mipc_ld_f32(d + 0);
        out->filter_data_mag_auto_hard_iron_offset.hard_iron_offset[1] = mipc_ld_f32(d + 4);
        out->filter_data_mag_auto_hard_iron_offset.hard_iron_offset[2] = mipc_ld_f32(d + 8);
        out->filter_data_mag_auto_hard_iron_offset.valid_flags = mipc_ld_u16(d + 12);
        return 1;
    }
    return mipc_filter_data_mag_auto_hard_iron_offset_decode(
               d, length, &out->filter_data_mag_auto_hard_iron_offset, NULL) == MIPC_OK;
}

static int load_0x26(const uint8_t *d, size_t length, void *packet) {
    mipc_filter_data_packet_t *out = packet;
    if (length == 38) {
        out->filter_data_mag_auto_soft_iron_matrix.soft_iron_matrix[0] = mipc_ld_f32(d + 0);
        out->filter_data_mag_auto_soft_iron_matrix.soft_iron_matrix[1] = mipc_ld_f32(d + 4);
        out->filter_data_mag_auto_soft_iron_matrix.soft_iron_matrix[2] = mipc_ld_f32(d + 8);
        out->filter_data_mag_auto_soft_iron_matrix.soft_iron_matrix[3] = mipc_ld_f32(d + 12);
        out->filter_data_mag_auto_soft_iron_matrix.soft_iron_matrix[4] = mipc_ld_f32(d + 16);
        out->filter_data_mag_auto_soft_iron_matrix.soft_iron_matrix[5] = mipc_ld_f32(d + 20);
        out->filter_data_mag_auto_soft_iron_matrix.soft_iron_matrix[6] = mipc_ld_f32(d + 24);
        out->filter_data_mag_auto_soft_iron_matrix.soft_iron_matrix[7] = mipc_ld_f32(d + 28);
        out->filter_data_mag_auto_soft_iron_matrix.soft_iron_matrix[8] = mipc_ld_f32(d + 32);
        out->filter_data_mag_auto_soft_iron_matrix.valid_flags = mipc_ld_u16(d + 36);
        return 1;
    }
    return mipc_filter_data_mag_auto_soft_iron_matrix_decode(
               d, length, &out->filter_data_mag_auto_soft_iron_matrix, NULL) == MIPC_OK;
}

static int load_0x28(const uint8_t *d, size_t length, void *packet) {
    mipc_filter_data_packet_t *out = packet;
    if (length == 14) {
        out->filter_data_mag_auto_hard_iron_offset_uncertainty.hard_iron_offset_uncertainty[0] =
            mipc_ld_f32(d + 0);
        out->filter_data_mag_auto_hard_iron_offset_uncertainty.hard_iron_offset_uncertainty[1] =
            mipc_ld_f32(d + 4);
        out->filter_data_mag_auto_hard_iron_offset_uncertainty.hard_iron_offset_uncertainty[2] =
            mipc_ld_f32(d + 8);
        out->filter_data_mag_auto_hard_iron_offset_uncertainty.valid_flags = mipc_ld_u16(d + 12);
        return 1;
    }
    return mipc_filter_data_mag_auto_hard_iron_offset_uncertainty_decode(
               d, length, &out->filter_data_mag_auto_hard_iron_offset_uncertainty, NULL) == MIPC_OK;
}

static int load_0x29(const uint8_t *d, size_t length, void *packet) {
    mipc_filter_data_packet_t *out = packet;
    if (length == 38) {
        out->filter_data_mag_auto_soft_iron_matrix_uncertainty.soft_iron_matrix_uncertainty[0] =
            mipc_ld_f32(d + 0);
        out->filter_data_mag_auto_soft_iron_matrix_uncertainty.soft_iron_matrix_uncertainty[1] =
            mipc_ld_f32(d + 4);
        out->filter_data_mag_auto_soft_iron_matrix_uncertainty.soft_iron_matrix_uncertainty[2] =
            mipc_ld_f32(d + 8);
        out->filter_data_mag_auto_soft_iron_matrix_uncertainty.soft_iron_matrix_uncertainty[3] =
            mipc_ld_f32(d + 12);
        out->filter_data_mag_auto_soft_iron_matrix_uncertainty.soft_iron_matrix_uncertainty[4] =
            mipc_ld_f32(d + 16);
        out->filter_data_mag_auto_soft_iron_matrix_uncertainty.soft_iron_matrix_uncertainty[5] =
            mipc_ld_f32(d + 20);
        out->filter_data_mag_auto_soft_iron_matrix_uncertainty.soft_iron_matrix_uncertainty[6] =
            mipc_ld_f32(d + 24);
        out->filter_data_mag_auto_soft_iron_matrix_uncertainty.soft_iron_matrix_uncertainty[7] =
            mipc_ld_f32(d + 28);
        out->filter_data_mag_auto_soft_iron_matrix_uncertainty.soft_iron_matrix_uncertainty[8] =
            mipc_ld_f32(d + 32);
        out->filter_data_mag_auto_soft_iron_matrix_uncertainty.valid_flags = mipc_ld_u16(d + 36);
        return 1;
    }
    return mipc_filter_data_mag_auto_soft_iron_matrix_uncertainty_decode(
               d, length, &out->filter_data_mag_auto_soft_iron_matrix_uncertainty, NULL) == MIPC_OK;
}

static int load_0x30(const uint8_t *d, size_t length, void *packet) {
    mipc_filter_data_packet_t *out = packet;
    if (length == 14) {
        out->filter_data_gnss_antenna_offset_correction.offset[0] = mipc_ld_f32(d + 0);
        out->filter_data_gnss_antenna_offset_correction.offset[1] = mipc_ld_f32(d + 4);
        out->filter_data_gnss_antenna_offset_correction.offset[2] = mipc_ld_f32(d + 8);
        out->filter_data_gnss_antenna_offset_correction.valid_flags = mipc_ld_u16(d + 12);
        return 1;
    }
    return mipc_filter_data_gnss_antenna_offset_correction_decode(
               d, length, &out->filter_data_gnss_antenna_offset_correction, NULL) == MIPC_OK;
}

static int load_0x31(const uint8_t *d, size_t length, void *packet) {
    mipc_filter_data_packet_t *out = packet;
    if (length == 14) {
        out->filter_data_gnss_antenna_offset_correction_uncertainty.offset_uncertainty[0] =
            mipc_ld_f32(d + 0);
        out->filter_data_gnss_antenna_offset_correction_uncertainty.offset_uncertainty[1] =
            mipc_ld_f32(d + 4);
        out->filter_data_gnss_antenna_offset_correction_uncertainty.offset_uncertainty[2] =
            mipc_ld_f32(d + 8);
        out->filter_data_gnss_antenna_offset_correction_uncertainty.valid_flags = mipc_ld_u16(d + 12);
        return 1;
    }
    return mipc_filter_data_gnss_antenna_offset_correction_uncertainty_decode(
               d, length, &out->filter_data_gnss_antenna_offset_correction_uncertainty, NULL) == MIPC_OK;
}

static int load_0x34(const uint8_t *d, size_t length, void *packet) {
    mipc_filter_data_packet_t *out = packet;
    if (length == 15) {
        out->filter_data_multi_antenna_offset_correction.receiver_id = mipc_ld_u8(d + 0);
        out->filter_data_multi_antenna_offset_correction.offset[0] = mipc_ld_f32(d + 1);
        out->filter_data_multi_antenna_offset_correction.offset[1] = mipc_ld_f32(d + 5);
        out->filter_data_multi_antenna_offset_correction.offset[2] = mipc_ld_f32(d + 9);
        out->filter_data_multi_antenna_offset_correction.valid_flags = mipc_ld_u16(d + 13);
        return 1;
    }
    return mipc_filter_data_multi_antenna_offset_correction_decode(
               d, length, &out->filter_data_multi_antenna_offset_correction, NULL) == MIPC_OK;
}

static int load_0x35(const uint8_t *d, size_t length, void *packet) {
    mipc_filter_data_packet_t *out = packet;
    if (length == 15) {
        out->filter_data_multi_antenna_offset_correction_uncertainty.receiver_id = mipc_ld_u8(d + 0);
        out->filter_data_multi_antenna_offset_correction_uncertainty.offset_uncertainty[0] =
            mipc_ld_f32(d + 1);
        out->filter_data_multi_antenna_offset_correction_uncertainty.offset_uncertainty[1] =
            mipc_ld_f32(d + 5);
        out->filter_data_multi_antenna_offset_correction_uncertainty.offset_uncertainty[2] =
            mipc_ld_f32(d + 9);
        out->filter_data_multi_antenna_offset_correction_uncertainty.valid_flags = mipc_ld_u16(d + 13);
        return 1;
    }
    return mipc_filter_data_multi_antenna_offset_correction_uncertainty_decode(
               d, length, &out->filter_data_multi_antenna_offset_correction_uncertainty, NULL) == MIPC_OK;
}

static int load_0x36(const uint8_t *d, size_t length, void *packet) {
    mipc_filter_data_packet_t *out = packet;
    if (length == 14) {
        out->filter_data_ecef_position_uncertainty.position_uncertainty[0] = mipc_ld_f32(d + 0);
        out->filter_data_ecef_position_uncertainty.position_uncertainty[1] = mipc_ld_f32(d + 4);
        out->filter_data_ecef_position_uncertainty.position_uncertainty[2] = mipc_ld_f32(d + 8);
        out->filter_data_ecef_position_uncertainty.valid_flags = mipc_ld_u16(d + 12);
        return 1;
    }
    return mipc_filter_data_ecef_position_uncertainty_decode(
               d, length, &out->filter_data_ecef_position_uncertainty, NULL) == MIPC_OK;
}

static int load_0x37(const uint8_t *d, size_t length, void *packet) {
    mipc_filter_data_packet_t *out = packet;
    if (length == 14) {
        out->filter_data_ecef_velocity_uncertainty.velocity_uncertainty[0] = mipc_ld_f32(d + 0);
        out->filter_data_ecef_velocity_uncertainty.velocity_uncertainty[1] = mipc_ld_f32(d + 4);
        out->filter_data_ecef_velocity_uncertainty.velocity_uncertainty[2] = mipc_ld_f32(d + 8);
        out->filter_data_ecef_velocity_uncertainty.valid_flags = mipc_ld_u16(d + 12);
        return 1;
    }
    return mipc_filter_data_ecef_velocity_uncertainty_decode(
               d, length, &out->filter_data_ecef_velocity_uncertainty, NULL) == MIPC_OK;
}

static int load_0x40(const uint8_t *d, size_t length, void *packet) {
    mipc_filter_data_packet_t *out = packet;
    if (length == 26) {
        out->filter_data_ecef_position.position[0] = mipc_ld_f64(d + 0);
        out->filter_data_ecef_position.position[1] = mipc_ld_f64(d + 8);
        out->filter_data_ecef_position.position[2] = mipc_ld_f64(d + 16);
        out->filter_data_ecef_position.valid_flags = mipc_ld_u16(d + 24);
        return 1;
    }
    return mipc_filter_data_ecef_position_decode(d, length, &out->filter_data_ecef_position, NULL) == MIPC_OK;
}

static int load_0x41(const uint8_t *d, size_t length, void *packet) {
    mipc_filter_data_packet_t *out = packet;
    if (length == 14) {
        out->filter_data_ecef_velocity.velocity[0] = mipc_ld_f32(d + 0);
        out->filter_data_ecef_velocity.velocity[1] = mipc_ld_f32(d + 4);
        out->filter_data_ecef_velocity.velocity[2] = mipc_ld_f32(d + 8);
        out->filter_data_ecef_velocity.valid_flags = mipc_ld_u16(d + 12);
        return 1;
    }
    return mipc_filter_data_ecef_velocity_decode(d, length, &out->filter_data_ecef_velocity, NULL) == MIPC_OK;
}

static int load_0x42(const uint8_t *d, size_t length, void *packet) {
    mipc_filter_data_packet_t *out = packet;
    if (length == 26) {
        out->filter_data_ned_relative_position.relative_position[0] = mipc_ld_f64(d + 0);
        out->filter_data_ned_relative_position.relative_position[1] = mipc_ld_f64(d + 8);
        out->filter_data_ned_relative_position.relative_position[2] = mipc_ld_f64(d + 16);
        out->filter_data_ned_relative_position.valid_flags = mipc_ld_u16(d + 24);
        return 1;
    }
    return mipc_filter_data_ned_relative_position_decode(d, length, &out->filter_data_ned_relative_position,
                                                         NULL) == MIPC_OK;
}

static int load_0x43(const uint8_t *d, size_t length, void *packet) {
    mipc_filter_data_packet_t *out = packet;
    if (length == 15) {
        out->filter_data_gnss_position_aiding_status.receiver_id = mipc_ld_u8(d + 0);
        out->filter_data_gnss_position_aiding_status.time_of_week = mipc_ld_f32(d + 1);
        out->filter_data_gnss_position_aiding_status.status = mipc_ld_u16(d + 5);
        out->filter_data_gnss_position_aiding_status.reserved[0] = mipc_ld_u8(d + 7);
        out->filter_data_gnss_position_aiding_status.reserved[1] = mipc_ld_u8(d + 8);
        out->filter_data_gnss_position_aiding_status.reserved[2] = mipc_ld_u8(d + 9);
        out->filter_data_gnss_position_aiding_status.reserved[3] = mipc_ld_u8(d + 10);
        out->filter_data_gnss_position_aiding_status.reserved[4] = mipc_ld_u8(d + 11);
        out->filter_data_gnss_position_aiding_status.reserved[5] = mipc_ld_u8(d + 12);
        out->filter_data_gnss_position_aiding_status.reserved[6] = mipc_ld_u8(d + 13);
        out->filter_data_gnss_position_aiding_status.reserved[7] = mipc_ld_u8(d + 14);
        return 1;
    }
    return mipc_filter_data_gnss_position_aiding_status_decode(
               d, length, &out->filter_data_gnss_position_aiding_status, NULL) == MIPC_OK;
}

static int load_0x46(const uint8_t *d, size_t length, void *packet) {
    mipc_filter_data_packet_t *out = packet;
    if (length == 7) {
        out->filter_data_aiding_measurement_summary.time_of_week = mipc_ld_f32(d + 0);
        out->filter_data_aiding_measurement_summary.source = mipc_ld_u8(d + 4);
        out->filter_data_aiding_measurement_summary.type = mipc_ld_u8(d + 5);
        out->filter_data_aiding_measurement_summary.indicator = mipc_ld_u8(d + 6);
        return 1;
    }
    return mipc_filter_data_aiding_measurement_summary_decode(
               d, length, &out->filter_data_aiding_measurement_summary, NULL) == MIPC_OK;
}

static int load_0x47(const uint8_t *d, size_t length, void *packet) {
    mipc_filter_data_packet_t *out = packet;
    if (length == 6) {
        out->filter_data_odometer_scale_factor_error.scale_factor_error = mipc_ld_f32(d + 0);
        out->filter_data_odometer_scale_factor_error.valid_flags = mipc_ld_u16(d + 4);
        return 1;
    }
    return mipc_filter_data_odometer_scale_factor_error_decode(
               d, length, &out->filter_data_odometer_scale_factor_error, NULL) == MIPC_OK;
}

static int load_0x48(const uint8_t *d, size_t length, void *packet) {
    mipc_filter_data_packet_t *out = packet;
    if (length == 6) {
        out->filter_data_odometer_scale_factor_error_uncertainty.scale_factor_error_uncertainty =
            mipc_ld_f32(d + 0);
        out->filter_data_odometer_scale_factor_error_uncertainty.valid_flags = mipc_ld_u16(d + 4);
        return 1;
    }
    return mipc_filter_data_odometer_scale_factor_error_uncertainty_decode(
               d, length, &out->filter_data_odometer_scale_factor_error_uncertainty, NULL) == MIPC_OK;
}

static int load_0x49(const uint8_t *d, size_t length, void *packet) {
    mipc_filter_data_packet_t *out = packet;
    if (length == 17) {
        out->filter_data_gnss_dual_antenna_status.time_of_week = mipc_ld_f32(d + 0);
        out->filter_data_gnss_dual_antenna_status.heading = mipc_ld_f32(d + 4);
        out->filter_data_gnss_dual_antenna_status.heading_uncertainty = mipc_ld_f32(d + 8);
        out->filter_data_gnss_dual_antenna_status.fix_type = mipc_ld_u8(d + 12);
        out->filter_data_gnss_dual_antenna_status.status_flags = mipc_ld_u16(d + 13);
        out->filter_data_gnss_dual_antenna_status.valid_flags = mipc_ld_u16(d + 15);
        return 1;
    }
    return mipc_filter_data_gnss_dual_antenna_status_decode(
               d, length, &out->filter_data_gnss_dual_antenna_status, NULL) == MIPC_OK;
}

static int load_0x50(const uint8_t *d, size_t length, void *packet) {
    mipc_filter_data_packet_t *out = packet;
    if (length == 29) {
        out->filter_data_aiding_frame_config_error.frame_id = mipc_ld_u8(d + 0);
        out->filter_data_aiding_frame_config_error.translation[0] = mipc_ld_f32(d + 1);
        out->filter_data_aiding_frame_config_error.translation[1] = mipc_ld_f32(d + 5);
        out->filter_data_aiding_frame_config_error.translation[2] = mipc_ld_f32(d + 9);
        out->filter_data_aiding_frame_config_error.attitude[0] = mipc_ld_f32(d + 13);
        out->filter_data_aiding_frame_config_error.attitude[1] = mipc_ld_f32(d + 17);
        out->filter_data_aiding_frame_config_error.attitude[2] = mipc_ld_f32(d + 21);
        out->filter_data_aiding_frame_config_error.attitude[3] = mipc_ld_f32(d + 25);
        return 1;
    }
    return mipc_filter_data_aiding_frame_config_error_decode(
               d, length, &out->filter_data_aiding_frame_config_error, NULL) == MIPC_OK;
}

static int load_0x51(const uint8_t *d, size_t length, void *packet) {
    mipc_filter_data_packet_t *out = packet;
    if (length == 25) {
        out->filter_data_aiding_frame_config_error_uncertainty.frame_id = mipc_ld_u8(d + 0);
        out->filter_data_aiding_frame_config_error_uncertainty.translation_uncertainty[0] =
            mipc_ld_f32(d + 1);
        out->filter_data_aiding_frame_config_error_uncertainty.translation_uncertainty[1] =
            mipc_ld_f32(d + 5);
        out->filter_data_aiding_frame_config_error_uncertainty.translation_uncertainty[2] =
            mipc_ld_f32(d + 9);
        out->filter_data_aiding_frame_config_error_uncertainty.attitude_uncertainty[0] = mipc_ld_f32(d + 13);
        out->filter_data_aiding_frame_config_error_uncertainty.attitude_uncertainty[1] = mipc_ld_f32(d + 17);
        out->filter_data_aiding_frame_config_error_uncertainty.attitude_uncertainty[2] = mipc_ld_f32(d + 21);
        return 1;
    }
    return mipc_filter_data_aiding_frame_config_error_uncertainty_decode(
               d, length, &out->filter_data_aiding_frame_config_error_uncertainty, NULL) == MIPC_OK;
}

static int load_0xd0(const uint8_t *d, size_t length, void *packet) {
    mipc_filter_data_packet_t *out = packet;
    if (length == 1) {
        out->shared_event_source.trigger_id = mipc_ld_u8(d + 0);
        return 1;
    }
    return mipc_shared_event_source_decode(d, length, &out->shared_event_source, NULL) == MIPC_OK;
}

static int load_0xd3(const uint8_t *d, size_t length, void *packet) {
    mipc_filter_data_packet_t *out = packet;
    if (length == 12) {
        out->shared_gps_timestamp.tow = mipc_ld_f64(d + 0);
        out->shared_gps_timestamp.week_number = mipc_ld_u16(d + 8);
        out->shared_gps_timestamp.valid_flags = mipc_ld_u16(d + 10);
        return 1;
    }
    return mipc_shared_gps_timestamp_decode(d, length, &out->shared_gps_timestamp, NULL) == MIPC_OK;
}

static int load_0xd4(const uint8_t *d, size_t length, void *packet) {
    mipc_filter_data_packet_t *out = packet;
    if (length == 8) {
        out->shared_delta_time.seconds = mipc_ld_f64(d + 0);
        return 1;
    }
    return mipc_shared_delta_time_decode(d, length, &out->shared_delta_time, NULL) == MIPC_OK;
}

static int load_0xd5(const uint8_t *d, size_t length, void *packet) {
    mipc_filter_data_packet_t *out = packet;
    if (length == 8) {
        out->shared_reference_timestamp.nanoseconds = mipc_ld_u64(d + 0);
        return 1;
    }
    return mipc_shared_reference_timestamp_decode(d, length, &out->shared_reference_timestamp, NULL) ==
           MIPC_OK;
}

static int load_0xd6(const uint8_t *d, size_t length, void *packet) {
    mipc_filter_data_packet_t *out = packet;
    if (length == 8) {
        out->shared_reference_time_delta.dt_nanos = mipc_ld_u64(d + 0);
        return 1;
    }
    return mipc_shared_reference_time_delta_decode(d, length, &out->shared_reference_time_delta, NULL) ==
           MIPC_OK;
}

static int load_0xd7(const uint8_t *d, size_t length, void *packet) {
    mipc_filter_data_packet_t *out = packet;
    if (length == 10) {
        out->shared_external_timestamp.nanoseconds = mipc_ld_u64(d + 0);
        out->shared_external_timestamp.valid_flags = mipc_ld_u16(d + 8);
        return 1;
    }
    return mipc_shared_external_timestamp_decode(d, length, &out->shared_external_timestamp, NULL) == MIPC_OK;
}

static int load_0xd8(const uint8_t *d, size_t length, void *packet) {
    mipc_filter_data_packet_t *out = packet;
    if (length == 10) {
        out->shared_external_time_delta.dt_nanos = mipc_ld_u64(d + 0);
        out->shared_external_time_delta.valid_flags = mipc_ld_u16(d + 8);
        return 1;
    }
    return mipc_shared_external_time_delta_decode(d, length, &out->shared_external_time_delta, NULL) ==
           MIPC_OK;
}

const mipc_layout_member_t mipc_filter_data_layout_members_[54] = {
    {0x01, offsetof(mipc_filter_data_packet_t, filter_data_llh_position), load_0x01},
    {0x02, offsetof(mipc_filter_data_packet_t, filter_data_ned_velocity), load_0x02},
    {0x03, offsetof(mipc_filter_data_packet_t, filter_data_attitude_quaternion), load_0x03},
    {0x04, offsetof(mipc_filter_data_packet_t, filter_data_attitude_dcm), load_0x04},
    {0x05, offsetof(mipc_filter_data_packet_t, filter_data_euler_angles), load_0x05},
    {0x06, offsetof(mipc_filter_data_packet_t, filter_data_gyro_bias), load_0x06},
    {0x07, offsetof(mipc_filter_data_packet_t, filter_data_accel_bias), load_0x07},
    {0x08, offsetof(mipc_filter_data_packet_t, filter_data_llh_position_uncertainty), load_0x08},
    {0x09, offsetof(mipc_filter_data_packet_t, filter_data_ned_velocity_uncertainty), load_0x09},
    {0x0A, offsetof(mipc_filter_data_packet_t, filter_data_euler_angles_uncertainty), load_0x0a},
    {0x0B, offsetof(mipc_filter_data_packet_t, filter_data_gyro_bias_uncertainty), load_0x0b},
    {0x0C, offsetof(mipc_filter_data_packet_t, filter_data_accel_bias_uncertainty), load_0x0c},
    {0x0D, offsetof(mipc_filter_data_packet_t, filter_data_linear_accel), load_0x0d},
    {0x0E, offsetof(mipc_filter_data_packet_t, filter_data_comp_angular_rate), load_0x0e},
    {0x0F, offsetof(mipc_filter_data_packet_t, filter_data_wgs84_gravity_magnitude), load_0x0f},
    {0x11, offsetof(mipc_filter_data_packet_t, filter_data_gps_timestamp), load_0x11},
    {0x12, offsetof(mipc_filter_data_packet_t, filter_data_quaternion_attitude_uncertainty), load_0x12},
    {0x13, offsetof(mipc_filter_data_packet_t, filter_data_gravity_vector), load_0x13},
    {0x14, offsetof(mipc_filter_data_packet_t, filter_data_heading_update_state), load_0x14},
    {0x15, offsetof(mipc_filter_data_packet_t, filter_data_magnetic_model), load_0x15},
    {0x16, offsetof(mipc_filter_data_packet_t, filter_data_gyro_scale_factor), load_0x16},
    {0x17, offsetof(mipc_filter_data_packet_t, filter_data_accel_scale_factor), load_0x17},
    {0x18, offsetof(mipc_filter_data_packet_t, filter_data_gyro_scale_factor_uncertainty), load_0x18},
    {0x19, offsetof(mipc_filter_data_packet_t, filter_data_accel_scale_factor_uncertainty), load_0x19},
    {0x1C, offsetof(mipc_filter_data_packet_t, filter_data_compensated_accel), load_0x1c},
    {0x20, offsetof(mipc_filter_data_packet_t, filter_data_standard_atmosphere), load_0x20},
    {0x21, offsetof(mipc_filter_data_packet_t, filter_data_pressure_altitude), load_0x21},
    {0x25, offsetof(mipc_filter_data_packet_t, filter_data_mag_auto_hard_iron_offset), load_0x25},
    {0x26, offsetof(mipc_filter_data_packet_t, filter_data_mag_auto_soft_iron_matrix), load_0x26},
    {0x28, offsetof(mipc_filter_data_packet_t, filter_data_mag_auto_hard_iron_offset_uncertainty), load_0x28},
    {0x29, offsetof(mipc_filter_data_packet_t, filter_data_mag_auto_soft_iron_matrix_uncertainty), load_0x29},
    {0x30, offsetof(mipc_filter_data_packet_t, filter_data_gnss_antenna_offset_correction), load_0x30},
    {0x31, offsetof(mipc_filter_data_packet_t, filter_data_gnss_antenna_offset_correction_uncertainty),
     load_0x31},
    {0x34, offsetof(mipc_filter_data_packet_t, filter_data_multi_antenna_offset_correction), load_0x34},
    {0x35, offsetof(mipc_filter_data_packet_t, filter_data_multi_antenna_offset_correction_uncertainty),
     load_0x35},
    {0x36, offsetof(mipc_filter_data_packet_t, filter_data_ecef_position_uncertainty), load_0x36},
    {0x37, offsetof(mipc_filter_data_packet_t, filter_data_ecef_velocity_uncertainty), load_0x37},
    {0x40, offsetof(mipc_filter_data_packet_t, filter_data_ecef_position), load_0x40},
    {0x41, offsetof(mipc_filter_data_packet_t, filter_data_ecef_velocity), load_0x41},
    {0x42, offsetof(mipc_filter_data_packet_t, filter_data_ned_relative_position), load_0x42},
    {0x43, offsetof(mipc_filter_data_packet_t, filter_data_gnss_position_aiding_status), load_0x43},
    {0x46, offsetof(mipc_filter_data_packet_t, filter_data_aiding_measurement_summary), load_0x46},
    {0x47, offsetof(mipc_filter_data_packet_t, filter_data_odometer_scale_factor_error), load_0x47},
    {0x48, offsetof(mipc_filter_data_packet_t, filter_data_odometer_scale_factor_error_uncertainty),
     load_0x48},
    {0x49, offsetof(mipc_filter_data_packet_t, filter_data_gnss_dual_antenna_status), load_0x49},
    {0x50, offsetof(mipc_filter_data_packet_t, filter_data_aiding_frame_config_error), load_0x50},
    {0x51, offsetof(mipc_filter_data_packet_t, filter_data_aiding_frame_config_error_uncertainty), load_0x51},
    {0xD0, offsetof(mipc_filter_data_packet_t, shared_event_source), load_0xd0},
    {0xD3, offsetof(mipc_filter_data_packet_t, shared_gps_timestamp), load_0xd3},
    {0xD4, offsetof(mipc_filter_data_packet_t, shared_delta_time), load_0xd4},
    {0xD5, offsetof(mipc_filter_data_packet_t, shared_reference_timestamp), load_0xd5},
    {0xD6, offsetof(mipc_filter_data_packet_t, shared_reference_time_delta), load_0xd6},
    {0xD7, offsetof(mipc_filter_data_packet_t, shared_external_timestamp), load_0xd7},
    {0xD8, offsetof(mipc_filter_data_packet_t, shared_external_time_delta), load_0xd8},
};
