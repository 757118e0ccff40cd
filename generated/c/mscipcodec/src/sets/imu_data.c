/* Encoders and decoders of IMU Data Message. Generated from the spec: do not edit. */
#include "mscipcodec/sets/imu_data.h"
#include "layouts_internal.h"
#include "types_internal.h"

#include <assert.h>
#include <stddef.h>
#include <string.h>

/* ---- mscipc_imu_data_scaled_accel_t */

static int mscipc_imu_data_scaled_accel_read(mscipc_reader_t *r, mscipc_imu_data_scaled_accel_t *out) {
    size_t i;
    mscipc_rd_push(r, "accel");
    for (i = 0; i < 3; i++) {
        mscipc_rd_index(r, i);
        if (mscipc_rd_f32(r, &out->accel[i])) {
            return -1;
        }
    }
    mscipc_rd_pop(r);
    return mscipc_rd_finish(r);
}

static mscipc_status_t mscipc_imu_data_scaled_accel_write(mscipc_writer_t *w,
                                                          const mscipc_imu_data_scaled_accel_t *in) {
    mscipc_status_t st;
    size_t i;
    for (i = 0; i < 3; i++) {
        if ((st = mscipc_wr_f32(w, &in->accel[i])) != MSCIPC_OK) {
            return st;
        }
    }
    return MSCIPC_OK;
}

mscipc_status_t mscipc_imu_data_scaled_accel_encode(const mscipc_imu_data_scaled_accel_t *value, uint8_t *buf,
                                                    size_t cap, size_t *len_out) {
    mscipc_writer_t w;
    mscipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mscipc_writer_init(&w, buf, cap);
    st = mscipc_imu_data_scaled_accel_write(&w, value);
    if (st == MSCIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 12 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mscipc_imu_data_scaled_accel_load(const uint8_t *d, mscipc_imu_data_scaled_accel_t *out) {
    out->accel[0] = mscipc_ld_f32(d + 0);
    out->accel[1] = mscipc_ld_f32(d + 4);
    out->accel[2] = mscipc_ld_f32(d + 8);
    return 0;
}

/* The general reader: lengths other than 12, bad bool bytes, error details. */
static MSCIPC_NOINLINE mscipc_status_t mscipc_imu_data_scaled_accel_decode_read(
    const uint8_t *data, size_t len, mscipc_imu_data_scaled_accel_t *out, mscipc_decode_error_t *err) {
    mscipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mscipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mscipc_imu_data_scaled_accel_read(&r, out) ? MSCIPC_ERR_DECODE : MSCIPC_OK;
}

mscipc_status_t mscipc_imu_data_scaled_accel_decode(const uint8_t *data, size_t len,
                                                    mscipc_imu_data_scaled_accel_t *out,
                                                    mscipc_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 12 && mscipc_imu_data_scaled_accel_load(data, out) == 0) {
        return MSCIPC_OK;
    }
    return mscipc_imu_data_scaled_accel_decode_read(data, len, out, err);
}

/* ---- mscipc_imu_data_scaled_gyro_t */

static int mscipc_imu_data_scaled_gyro_read(mscipc_reader_t *r, mscipc_imu_data_scaled_gyro_t *out) {
    size_t i;
    mscipc_rd_push(r, "gyro");
    for (i = 0; i < 3; i++) {
        mscipc_rd_index(r, i);
        if (mscipc_rd_f32(r, &out->gyro[i])) {
            return -1;
        }
    }
    mscipc_rd_pop(r);
    return mscipc_rd_finish(r);
}

static mscipc_status_t mscipc_imu_data_scaled_gyro_write(mscipc_writer_t *w,
                                                         const mscipc_imu_data_scaled_gyro_t *in) {
    mscipc_status_t st;
    size_t i;
    for (i = 0; i < 3; i++) {
        if ((st = mscipc_wr_f32(w, &in->gyro[i])) != MSCIPC_OK) {
            return st;
        }
    }
    return MSCIPC_OK;
}

mscipc_status_t mscipc_imu_data_scaled_gyro_encode(const mscipc_imu_data_scaled_gyro_t *value, uint8_t *buf,
                                                   size_t cap, size_t *len_out) {
    mscipc_writer_t w;
    mscipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mscipc_writer_init(&w, buf, cap);
    st = mscipc_imu_data_scaled_gyro_write(&w, value);
    if (st == MSCIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 12 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mscipc_imu_data_scaled_gyro_load(const uint8_t *d, mscipc_imu_data_scaled_gyro_t *out) {
    out->gyro[0] = mscipc_ld_f32(d + 0);
    out->gyro[1] = mscipc_ld_f32(d + 4);
    out->gyro[2] = mscipc_ld_f32(d + 8);
    return 0;
}

/* The general reader: lengths other than 12, bad bool bytes, error details. */
static MSCIPC_NOINLINE mscipc_status_t mscipc_imu_data_scaled_gyro_decode_read(
    const uint8_t *data, size_t len, mscipc_imu_data_scaled_gyro_t *out, mscipc_decode_error_t *err) {
    mscipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mscipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mscipc_imu_data_scaled_gyro_read(&r, out) ? MSCIPC_ERR_DECODE : MSCIPC_OK;
}

mscipc_status_t mscipc_imu_data_scaled_gyro_decode(const uint8_t *data, size_t len,
                                                   mscipc_imu_data_scaled_gyro_t *out,
                                                   mscipc_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 12 && mscipc_imu_data_scaled_gyro_load(data, out) == 0) {
        return MSCIPC_OK;
    }
    return mscipc_imu_data_scaled_gyro_decode_read(data, len, out, err);
}

/* ---- mscipc_imu_data_scaled_mag_t */

static int mscipc_imu_data_scaled_mag_read(mscipc_reader_t *r, mscipc_imu_data_scaled_mag_t *out) {
    size_t i;
    mscipc_rd_push(r, "mag");
    for (i = 0; i < 3; i++) {
        mscipc_rd_index(r, i);
        if (mscipc_rd_f32(r, &out->mag[i])) {
            return -1;
        }
    }
    mscipc_rd_pop(r);
    return mscipc_rd_finish(r);
}

static mscipc_status_t mscipc_imu_data_scaled_mag_write(mscipc_writer_t *w,
                                                        const mscipc_imu_data_scaled_mag_t *in) {
    mscipc_status_t st;
    size_t i;
    for (i = 0; i < 3; i++) {
        if ((st = mscipc_wr_f32(w, &in->mag[i])) != MSCIPC_OK) {
            return st;
        }
    }
    return MSCIPC_OK;
}

mscipc_status_t mscipc_imu_data_scaled_mag_encode(const mscipc_imu_data_scaled_mag_t *value, uint8_t *buf,
                                                  size_t cap, size_t *len_out) {
    mscipc_writer_t w;
    mscipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mscipc_writer_init(&w, buf, cap);
    st = mscipc_imu_data_scaled_mag_write(&w, value);
    if (st == MSCIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 12 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mscipc_imu_data_scaled_mag_load(const uint8_t *d, mscipc_imu_data_scaled_mag_t *out) {
    out->mag[0] = mscipc_ld_f32(d + 0);
    out->mag[1] = mscipc_ld_f32(d + 4);
    out->mag[2] = mscipc_ld_f32(d + 8);
    return 0;
}

/* The general reader: lengths other than 12, bad bool bytes, error details. */
static MSCIPC_NOINLINE mscipc_status_t mscipc_imu_data_scaled_mag_decode_read(
    const uint8_t *data, size_t len, mscipc_imu_data_scaled_mag_t *out, mscipc_decode_error_t *err) {
    mscipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mscipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mscipc_imu_data_scaled_mag_read(&r, out) ? MSCIPC_ERR_DECODE : MSCIPC_OK;
}

mscipc_status_t mscipc_imu_data_scaled_mag_decode(const uint8_t *data, size_t len,
                                                  mscipc_imu_data_scaled_mag_t *out,
                                                  mscipc_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 12 && mscipc_imu_data_scaled_mag_load(data, out) == 0) {
        return MSCIPC_OK;
    }
    return mscipc_imu_data_scaled_mag_decode_read(data, len, out, err);
}

/* ---- mscipc_imu_data_delta_theta_t */

static int mscipc_imu_data_delta_theta_read(mscipc_reader_t *r, mscipc_imu_data_delta_theta_t *out) {
    size_t i;
    mscipc_rd_push(r, "delta_theta");
    for (i = 0; i < 3; i++) {
        mscipc_rd_index(r, i);
        if (mscipc_rd_f32(r, &out->delta_theta[i])) {
            return -1;
        }
    }
    mscipc_rd_pop(r);
    return mscipc_rd_finish(r);
}

static mscipc_status_t mscipc_imu_data_delta_theta_write(mscipc_writer_t *w,
                                                         const mscipc_imu_data_delta_theta_t *in) {
    mscipc_status_t st;
    size_t i;
    for (i = 0; i < 3; i++) {
        if ((st = mscipc_wr_f32(w, &in->delta_theta[i])) != MSCIPC_OK) {
            return st;
        }
    }
    return MSCIPC_OK;
}

mscipc_status_t mscipc_imu_data_delta_theta_encode(const mscipc_imu_data_delta_theta_t *value, uint8_t *buf,
                                                   size_t cap, size_t *len_out) {
    mscipc_writer_t w;
    mscipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mscipc_writer_init(&w, buf, cap);
    st = mscipc_imu_data_delta_theta_write(&w, value);
    if (st == MSCIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 12 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mscipc_imu_data_delta_theta_load(const uint8_t *d, mscipc_imu_data_delta_theta_t *out) {
    out->delta_theta[0] = mscipc_ld_f32(d + 0);
    out->delta_theta[1] = mscipc_ld_f32(d + 4);
    out->delta_theta[2] = mscipc_ld_f32(d + 8);
    return 0;
}

/* The general reader: lengths other than 12, bad bool bytes, error details. */
static MSCIPC_NOINLINE mscipc_status_t mscipc_imu_data_delta_theta_decode_read(
    const uint8_t *data, size_t len, mscipc_imu_data_delta_theta_t *out, mscipc_decode_error_t *err) {
    mscipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mscipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mscipc_imu_data_delta_theta_read(&r, out) ? MSCIPC_ERR_DECODE : MSCIPC_OK;
}

mscipc_status_t mscipc_imu_data_delta_theta_decode(const uint8_t *data, size_t len,
                                                   mscipc_imu_data_delta_theta_t *out,
                                                   mscipc_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 12 && mscipc_imu_data_delta_theta_load(data, out) == 0) {
        return MSCIPC_OK;
    }
    return mscipc_imu_data_delta_theta_decode_read(data, len, out, err);
}

/* ---- mscipc_imu_data_delta_velocity_t */

static int mscipc_imu_data_delta_velocity_read(mscipc_reader_t *r, mscipc_imu_data_delta_velocity_t *out) {
    size_t i;
    mscipc_rd_push(r, "delta_velocity");
    for (i = 0; i < 3; i++) {
        mscipc_rd_index(r, i);
        if (mscipc_rd_f32(r, &out->delta_velocity[i])) {
            return -1;
        }
    }
    mscipc_rd_pop(r);
    return mscipc_rd_finish(r);
}

static mscipc_status_t mscipc_imu_data_delta_velocity_write(mscipc_writer_t *w,
                                                            const mscipc_imu_data_delta_velocity_t *in) {
    mscipc_status_t st;
    size_t i;
    for (i = 0; i < 3; i++) {
        if ((st = mscipc_wr_f32(w, &in->delta_velocity[i])) != MSCIPC_OK) {
            return st;
        }
    }
    return MSCIPC_OK;
}

mscipc_status_t mscipc_imu_data_delta_velocity_encode(const mscipc_imu_data_delta_velocity_t *value,
                                                      uint8_t *buf, size_t cap, size_t *len_out) {
    mscipc_writer_t w;
    mscipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mscipc_writer_init(&w, buf, cap);
    st = mscipc_imu_data_delta_velocity_write(&w, value);
    if (st == MSCIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 12 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mscipc_imu_data_delta_velocity_load(const uint8_t *d, mscipc_imu_data_delta_velocity_t *out) {
    out->delta_velocity[0] = mscipc_ld_f32(d + 0);
    out->delta_velocity[1] = mscipc_ld_f32(d + 4);
    out->delta_velocity[2] = mscipc_ld_f32(d + 8);
    return 0;
}

/* The general reader: lengths other than 12, bad bool bytes, error details. */
static MSCIPC_NOINLINE mscipc_status_t mscipc_imu_data_delta_velocity_decode_read(
    const uint8_t *data, size_t len, mscipc_imu_data_delta_velocity_t *out, mscipc_decode_error_t *err) {
    mscipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mscipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mscipc_imu_data_delta_velocity_read(&r, out) ? MSCIPC_ERR_DECODE : MSCIPC_OK;
}

mscipc_status_t mscipc_imu_data_delta_velocity_decode(const uint8_t *data, size_t len,
                                                      mscipc_imu_data_delta_velocity_t *out,
                                                      mscipc_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 12 && mscipc_imu_data_delta_velocity_load(data, out) == 0) {
        return MSCIPC_OK;
    }
    return mscipc_imu_data_delta_velocity_decode_read(data, len, out, err);
}

/* ---- mscipc_imu_data_scaled_pressure_t */

static int mscipc_imu_data_scaled_pressure_read(mscipc_reader_t *r, mscipc_imu_data_scaled_pressure_t *out) {
    mscipc_rd_push(r, "pressure");
    if (mscipc_rd_f32(r, &out->pressure)) {
        return -1;
    }
    mscipc_rd_pop(r);
    return mscipc_rd_finish(r);
}

static mscipc_status_t mscipc_imu_data_scaled_pressure_write(mscipc_writer_t *w,
                                                             const mscipc_imu_data_scaled_pressure_t *in) {
    mscipc_status_t st;
    if ((st = mscipc_wr_f32(w, &in->pressure)) != MSCIPC_OK) {
        return st;
    }
    return MSCIPC_OK;
}

mscipc_status_t mscipc_imu_data_scaled_pressure_encode(const mscipc_imu_data_scaled_pressure_t *value,
                                                       uint8_t *buf, size_t cap, size_t *len_out) {
    mscipc_writer_t w;
    mscipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mscipc_writer_init(&w, buf, cap);
    st = mscipc_imu_data_scaled_pressure_write(&w, value);
    if (st == MSCIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 4 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mscipc_imu_data_scaled_pressure_load(const uint8_t *d, mscipc_imu_data_scaled_pressure_t *out) {
    out->pressure = mscipc_ld_f32(d + 0);
    return 0;
}

/* The general reader: lengths other than 4, bad bool bytes, error details. */
static MSCIPC_NOINLINE mscipc_status_t mscipc_imu_data_scaled_pressure_decode_read(
    const uint8_t *data, size_t len, mscipc_imu_data_scaled_pressure_t *out, mscipc_decode_error_t *err) {
    mscipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mscipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mscipc_imu_data_scaled_pressure_read(&r, out) ? MSCIPC_ERR_DECODE : MSCIPC_OK;
}

mscipc_status_t mscipc_imu_data_scaled_pressure_decode(const uint8_t *data, size_t len,
                                                       mscipc_imu_data_scaled_pressure_t *out,
                                                       mscipc_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 4 && mscipc_imu_data_scaled_pressure_load(data, out) == 0) {
        return MSCIPC_OK;
    }
    return mscipc_imu_data_scaled_pressure_decode_read(data, len, out, err);
}

/* ---- mscipc_imu_data_scaled_temperature_t */

static int mscipc_imu_data_scaled_temperature_read(mscipc_reader_t *r,
                                                   mscipc_imu_data_scaled_temperature_t *out) {
    mscipc_rd_push(r, "temperature");
    if (mscipc_rd_f32(r, &out->temperature)) {
        return -1;
    }
    mscipc_rd_pop(r);
    return mscipc_rd_finish(r);
}

static mscipc_status_t
mscipc_imu_data_scaled_temperature_write(mscipc_writer_t *w, const mscipc_imu_data_scaled_temperature_t *in) {
    mscipc_status_t st;
    if ((st = mscipc_wr_f32(w, &in->temperature)) != MSCIPC_OK) {
        return st;
    }
    return MSCIPC_OK;
}

mscipc_status_t mscipc_imu_data_scaled_temperature_encode(const mscipc_imu_data_scaled_temperature_t *value,
                                                          uint8_t *buf, size_t cap, size_t *len_out) {
    mscipc_writer_t w;
    mscipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mscipc_writer_init(&w, buf, cap);
    st = mscipc_imu_data_scaled_temperature_write(&w, value);
    if (st == MSCIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 4 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mscipc_imu_data_scaled_temperature_load(const uint8_t *d,
                                                   mscipc_imu_data_scaled_temperature_t *out) {
    out->temperature = mscipc_ld_f32(d + 0);
    return 0;
}

/* The general reader: lengths other than 4, bad bool bytes, error details. */
static MSCIPC_NOINLINE mscipc_status_t mscipc_imu_data_scaled_temperature_decode_read(
    const uint8_t *data, size_t len, mscipc_imu_data_scaled_temperature_t *out, mscipc_decode_error_t *err) {
    mscipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mscipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mscipc_imu_data_scaled_temperature_read(&r, out) ? MSCIPC_ERR_DECODE : MSCIPC_OK;
}

mscipc_status_t mscipc_imu_data_scaled_temperature_decode(const uint8_t *data, size_t len,
                                                          mscipc_imu_data_scaled_temperature_t *out,
                                                          mscipc_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 4 && mscipc_imu_data_scaled_temperature_load(data, out) == 0) {
        return MSCIPC_OK;
    }
    return mscipc_imu_data_scaled_temperature_decode_read(data, len, out, err);
}

/* ---- mscipc_imu_data_gps_correlated_time_t */

static int mscipc_imu_data_gps_correlated_time_read(mscipc_reader_t *r,
                                                    mscipc_imu_data_gps_correlated_time_t *out) {
    mscipc_rd_push(r, "seconds");
    if (mscipc_rd_f64(r, &out->seconds)) {
        return -1;
    }
    mscipc_rd_pop(r);
    mscipc_rd_push(r, "week");
    if (mscipc_rd_u16(r, &out->week)) {
        return -1;
    }
    mscipc_rd_pop(r);
    mscipc_rd_push(r, "flags");
    if (mscipc_rd_u16(r, &out->flags)) {
        return -1;
    }
    mscipc_rd_pop(r);
    return mscipc_rd_finish(r);
}

static mscipc_status_t
mscipc_imu_data_gps_correlated_time_write(mscipc_writer_t *w,
                                          const mscipc_imu_data_gps_correlated_time_t *in) {
    mscipc_status_t st;
    if ((st = mscipc_wr_f64(w, &in->seconds)) != MSCIPC_OK) {
        return st;
    }
    if ((st = mscipc_wr_u16(w, &in->week)) != MSCIPC_OK) {
        return st;
    }
    if ((st = mscipc_wr_u16(w, &in->flags)) != MSCIPC_OK) {
        return st;
    }
    return MSCIPC_OK;
}

mscipc_status_t mscipc_imu_data_gps_correlated_time_encode(const mscipc_imu_data_gps_correlated_time_t *value,
                                                           uint8_t *buf, size_t cap, size_t *len_out) {
    mscipc_writer_t w;
    mscipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mscipc_writer_init(&w, buf, cap);
    st = mscipc_imu_data_gps_correlated_time_write(&w, value);
    if (st == MSCIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 12 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mscipc_imu_data_gps_correlated_time_load(const uint8_t *d,
                                                    mscipc_imu_data_gps_correlated_time_t *out) {
    out->seconds = mscipc_ld_f64(d + 0);
    out->week = mscipc_ld_u16(d + 8);
    out->flags = mscipc_ld_u16(d + 10);
    return 0;
}

/* The general reader: lengths other than 12, bad bool bytes, error details. */
static MSCIPC_NOINLINE mscipc_status_t mscipc_imu_data_gps_correlated_time_decode_read(
    const uint8_t *data, size_t len, mscipc_imu_data_gps_correlated_time_t *out, mscipc_decode_error_t *err) {
    mscipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mscipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mscipc_imu_data_gps_correlated_time_read(&r, out) ? MSCIPC_ERR_DECODE : MSCIPC_OK;
}

mscipc_status_t mscipc_imu_data_gps_correlated_time_decode(const uint8_t *data, size_t len,
                                                           mscipc_imu_data_gps_correlated_time_t *out,
                                                           mscipc_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 12 && mscipc_imu_data_gps_correlated_time_load(data, out) == 0) {
        return MSCIPC_OK;
    }
    return mscipc_imu_data_gps_correlated_time_decode_read(data, len, out, err);
}

/* ---- mscipc_imu_data_scaled_aux_accel_t */

static int mscipc_imu_data_scaled_aux_accel_read(mscipc_reader_t *r,
                                                 mscipc_imu_data_scaled_aux_accel_t *out) {
    size_t i;
    mscipc_rd_push(r, "accel");
    for (i = 0; i < 3; i++) {
        mscipc_rd_index(r, i);
        if (mscipc_rd_f32(r, &out->accel[i])) {
            return -1;
        }
    }
    mscipc_rd_pop(r);
    return mscipc_rd_finish(r);
}

static mscipc_status_t mscipc_imu_data_scaled_aux_accel_write(mscipc_writer_t *w,
                                                              const mscipc_imu_data_scaled_aux_accel_t *in) {
    mscipc_status_t st;
    size_t i;
    for (i = 0; i < 3; i++) {
        if ((st = mscipc_wr_f32(w, &in->accel[i])) != MSCIPC_OK) {
            return st;
        }
    }
    return MSCIPC_OK;
}

mscipc_status_t mscipc_imu_data_scaled_aux_accel_encode(const mscipc_imu_data_scaled_aux_accel_t *value,
                                                        uint8_t *buf, size_t cap, size_t *len_out) {
    mscipc_writer_t w;
    mscipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mscipc_writer_init(&w, buf, cap);
    st = mscipc_imu_data_scaled_aux_accel_write(&w, value);
    if (st == MSCIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 12 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mscipc_imu_data_scaled_aux_accel_load(const uint8_t *d, mscipc_imu_data_scaled_aux_accel_t *out) {
    out->accel[0] = mscipc_ld_f32(d + 0);
    out->accel[1] = mscipc_ld_f32(d + 4);
    out->accel[2] = mscipc_ld_f32(d + 8);
    return 0;
}

/* The general reader: lengths other than 12, bad bool bytes, error details. */
static MSCIPC_NOINLINE mscipc_status_t mscipc_imu_data_scaled_aux_accel_decode_read(
    const uint8_t *data, size_t len, mscipc_imu_data_scaled_aux_accel_t *out, mscipc_decode_error_t *err) {
    mscipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mscipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mscipc_imu_data_scaled_aux_accel_read(&r, out) ? MSCIPC_ERR_DECODE : MSCIPC_OK;
}

mscipc_status_t mscipc_imu_data_scaled_aux_accel_decode(const uint8_t *data, size_t len,
                                                        mscipc_imu_data_scaled_aux_accel_t *out,
                                                        mscipc_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 12 && mscipc_imu_data_scaled_aux_accel_load(data, out) == 0) {
        return MSCIPC_OK;
    }
    return mscipc_imu_data_scaled_aux_accel_decode_read(data, len, out, err);
}

/* ---- the straight-line packet decoder */

size_t mscipc_imu_data_decode_packet(const uint8_t *payload, size_t len, mscipc_imu_data_packet_t *out,
                                     mscipc_field_entry_fn other, void *ctx) {
    size_t pos = 0;
    size_t n = 0;
    assert(payload != NULL || len == 0);
    assert(out != NULL);
    memset(out->index.present, 0, sizeof out->index.present);
    if (payload == NULL) {
        len = 0;
    }
    /* the field headers read in place (the iterator's entry is built only for what goes to other) */
    while (len - pos >= MSCIPC_FIELD_HEADER_SIZE) {
        const uint8_t *head = payload + pos;
        const uint8_t descriptor = head[MSCIPC_FIELD_DESCRIPTOR_OFFSET];
        const int data_len = (int)head[MSCIPC_FIELD_LENGTH_OFFSET] -
                             mscipc_field_length_adjust(MSCIPC_IMU_DATA_SET, descriptor);
        const uint8_t *d = head + MSCIPC_FIELD_HEADER_SIZE;
        const uint32_t bit = (uint32_t)1u << (descriptor % 32u);
        size_t length;
        size_t offset = 0;
        int ok = 0;
        if (data_len < 0 || (size_t)data_len > len - pos - MSCIPC_FIELD_HEADER_SIZE) {
            break; /* trailing bytes: the iterator reports them below */
        }
        length = (size_t)data_len;
        if ((out->index.present[descriptor / 32u] & bit) == 0) {
            switch (descriptor) {
            case 0x81:
                if (length == 12) {
                    out->imu_data_scaled_accel.accel[0] = mscipc_ld_f32(d + 0);
                    out->imu_data_scaled_accel.accel[1] = mscipc_ld_f32(d + 4);
                    out->imu_data_scaled_accel.accel[2] = mscipc_ld_f32(d + 8);
                    ok = 1;
                } else {
                    ok = mscipc_imu_data_scaled_accel_decode(d, length, &out->imu_data_scaled_accel, NULL) ==
                         MSCIPC_OK;
                }
                offset = offsetof(mscipc_imu_data_packet_t, imu_data_scaled_accel);
                break;
            case 0x82:
                if (length == 12) {
                    out->imu_data_scaled_gyro.gyro[0] = mscipc_ld_f32(d + 0);
                    out->imu_data_scaled_gyro.gyro[1] = mscipc_ld_f32(d + 4);
                    out->imu_data_scaled_gyro.gyro[2] = mscipc_ld_f32(d + 8);
                    ok = 1;
                } else {
                    ok = mscipc_imu_data_scaled_gyro_decode(d, length, &out->imu_data_scaled_gyro, NULL) ==
                         MSCIPC_OK;
                }
                offset = offsetof(mscipc_imu_data_packet_t, imu_data_scaled_gyro);
                break;
            case 0x83:
                if (length == 12) {
                    out->imu_data_scaled_mag.mag[0] = mscipc_ld_f32(d + 0);
                    out->imu_data_scaled_mag.mag[1] = mscipc_ld_f32(d + 4);
                    out->imu_data_scaled_mag.mag[2] = mscipc_ld_f32(d + 8);
                    ok = 1;
                } else {
                    ok = mscipc_imu_data_scaled_mag_decode(d, length, &out->imu_data_scaled_mag, NULL) ==
                         MSCIPC_OK;
                }
                offset = offsetof(mscipc_imu_data_packet_t, imu_data_scaled_mag);
                break;
            case 0x84:
                if (length == 12) {
                    out->imu_data_delta_theta.delta_theta[0] = mscipc_ld_f32(d + 0);
                    out->imu_data_delta_theta.delta_theta[1] = mscipc_ld_f32(d + 4);
                    out->imu_data_delta_theta.delta_theta[2] = mscipc_ld_f32(d + 8);
                    ok = 1;
                } else {
                    ok = mscipc_imu_data_delta_theta_decode(d, length, &out->imu_data_delta_theta, NULL) ==
                         MSCIPC_OK;
                }
                offset = offsetof(mscipc_imu_data_packet_t, imu_data_delta_theta);
                break;
            case 0x85:
                if (length == 12) {
                    out->imu_data_delta_velocity.delta_velocity[0] = mscipc_ld_f32(d + 0);
                    out->imu_data_delta_velocity.delta_velocity[1] = mscipc_ld_f32(d + 4);
                    out->imu_data_delta_velocity.delta_velocity[2] = mscipc_ld_f32(d + 8);
                    ok = 1;
                } else {
                    ok = mscipc_imu_data_delta_velocity_decode(d, length, &out->imu_data_delta_velocity,
                                                               NULL) == MSCIPC_OK;
                }
                offset = offsetof(mscipc_imu_data_packet_t, imu_data_delta_velocity);
                break;
            case 0x86:
                if (length == 4) {
                    out->imu_data_scaled_pressure.pressure = mscipc_ld_f32(d + 0);
                    ok = 1;
                } else {
                    ok = mscipc_imu_data_scaled_pressure_decode(d, length, &out->imu_data_scaled_pressure,
                                                                NULL) == MSCIPC_OK;
                }
                offset = offsetof(mscipc_imu_data_packet_t, imu_data_scaled_pressure);
                break;
            case 0x87:
                if (length == 4) {
                    out->imu_data_scaled_temperature.temperature = mscipc_ld_f32(d + 0);
                    ok = 1;
                } else {
                    ok = mscipc_imu_data_scaled_temperature_decode(
                             d, length, &out->imu_data_scaled_temperature, NULL) == MSCIPC_OK;
                }
                offset = offsetof(mscipc_imu_data_packet_t, imu_data_scaled_temperature);
                break;
            case 0x88:
                if (length == 12) {
                    out->imu_data_gps_correlated_time.seconds = mscipc_ld_f64(d + 0);
                    out->imu_data_gps_correlated_time.week = mscipc_ld_u16(d + 8);
                    out->imu_data_gps_correlated_time.flags = mscipc_ld_u16(d + 10);
                    ok = 1;
                } else {
                    ok = mscipc_imu_data_gps_correlated_time_decode(
                             d, length, &out->imu_data_gps_correlated_time, NULL) == MSCIPC_OK;
                }
                offset = offsetof(mscipc_imu_data_packet_t, imu_data_gps_correlated_time);
                break;
            case 0x89:
                if (length == 12) {
                    out->imu_data_scaled_aux_accel.accel[0] = mscipc_ld_f32(d + 0);
                    out->imu_data_scaled_aux_accel.accel[1] = mscipc_ld_f32(d + 4);
                    out->imu_data_scaled_aux_accel.accel[2] = mscipc_ld_f32(d + 8);
                    ok = 1;
                } else {
                    ok = mscipc_imu_data_scaled_aux_accel_decode(d, length, &out->imu_data_scaled_aux_accel,
                                                                 NULL) == MSCIPC_OK;
                }
                offset = offsetof(mscipc_imu_data_packet_t, imu_data_scaled_aux_accel);
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
            mscipc_field_visit_at_(MSCIPC_IMU_DATA_SET, payload, len, pos, other, ctx);
        }
        pos += MSCIPC_FIELD_HEADER_SIZE + length;
    }
    if (pos < len && other) {
        mscipc_field_visit_at_(MSCIPC_IMU_DATA_SET, payload, len, pos, other, ctx);
    }
    out->index.count = n;
    return n;
}

/* ---- the members' loaders (mscipc_decode_packet_cached, issue 38): each decodes its field's
 * data into its member of the mscipc_imu_data_packet_t at packet as mscipc_imu_data_decode_packet does; 0
 * when it does not decode (the packet then takes the straight-line decoder, which gives the field to other)
 */

static int load_0x81(const uint8_t *d, size_t length, void *packet) {
    mscipc_imu_data_packet_t *out = packet;
    if (length == 12) {
        out->imu_data_scaled_accel.accel[0] = mscipc_ld_f32(d + 0);
        out->imu_data_scaled_accel.accel[1] = mscipc_ld_f32(d + 4);
        out->imu_data_scaled_accel.accel[2] = mscipc_ld_f32(d + 8);
        return 1;
    }
    return mscipc_imu_data_scaled_accel_decode(d, length, &out->imu_data_scaled_accel, NULL) == MSCIPC_OK;
}

static int load_0x82(const uint8_t *d, size_t length, void *packet) {
    mscipc_imu_data_packet_t *out = packet;
    if (length == 12) {
        out->imu_data_scaled_gyro.gyro[0] = mscipc_ld_f32(d + 0);
        out->imu_data_scaled_gyro.gyro[1] = mscipc_ld_f32(d + 4);
        out->imu_data_scaled_gyro.gyro[2] = mscipc_ld_f32(d + 8);
        return 1;
    }
    return mscipc_imu_data_scaled_gyro_decode(d, length, &out->imu_data_scaled_gyro, NULL) == MSCIPC_OK;
}

static int load_0x83(const uint8_t *d, size_t length, void *packet) {
    mscipc_imu_data_packet_t *out = packet;
    if (length == 12) {
        out->imu_data_scaled_mag.mag[0] = mscipc_ld_f32(d + 0);
        out->imu_data_scaled_mag.mag[1] = mscipc_ld_f32(d + 4);
        out->imu_data_scaled_mag.mag[2] = mscipc_ld_f32(d + 8);
        return 1;
    }
    return mscipc_imu_data_scaled_mag_decode(d, length, &out->imu_data_scaled_mag, NULL) == MSCIPC_OK;
}

static int load_0x84(const uint8_t *d, size_t length, void *packet) {
    mscipc_imu_data_packet_t *out = packet;
    if (length == 12) {
        out->imu_data_delta_theta.delta_theta[0] = mscipc_ld_f32(d + 0);
        out->imu_data_delta_theta.delta_theta[1] = mscipc_ld_f32(d + 4);
        out->imu_data_delta_theta.delta_theta[2] = mscipc_ld_f32(d + 8);
        return 1;
    }
    return mscipc_imu_data_delta_theta_decode(d, length, &out->imu_data_delta_theta, NULL) == MSCIPC_OK;
}

static int load_0x85(const uint8_t *d, size_t length, void *packet) {
    mscipc_imu_data_packet_t *out = packet;
    if (length == 12) {
        out->imu_data_delta_velocity.delta_velocity[0] = mscipc_ld_f32(d + 0);
        out->imu_data_delta_velocity.delta_velocity[1] = mscipc_ld_f32(d + 4);
        out->imu_data_delta_velocity.delta_velocity[2] = mscipc_ld_f32(d + 8);
        return 1;
    }
    return mscipc_imu_data_delta_velocity_decode(d, length, &out->imu_data_delta_velocity, NULL) == MSCIPC_OK;
}

static int load_0x86(const uint8_t *d, size_t length, void *packet) {
    mscipc_imu_data_packet_t *out = packet;
    if (length == 4) {
        out->imu_data_scaled_pressure.pressure = mscipc_ld_f32(d + 0);
        return 1;
    }
    return mscipc_imu_data_scaled_pressure_decode(d, length, &out->imu_data_scaled_pressure, NULL) ==
           MSCIPC_OK;
}

static int load_0x87(const uint8_t *d, size_t length, void *packet) {
    mscipc_imu_data_packet_t *out = packet;
    if (length == 4) {
        out->imu_data_scaled_temperature.temperature = mscipc_ld_f32(d + 0);
        return 1;
    }
    return mscipc_imu_data_scaled_temperature_decode(d, length, &out->imu_data_scaled_temperature, NULL) ==
           MSCIPC_OK;
}

static int load_0x88(const uint8_t *d, size_t length, void *packet) {
    mscipc_imu_data_packet_t *out = packet;
    if (length == 12) {
        out->imu_data_gps_correlated_time.seconds = mscipc_ld_f64(d + 0);
        out->imu_data_gps_correlated_time.week = mscipc_ld_u16(d + 8);
        out->imu_data_gps_correlated_time.flags = mscipc_ld_u16(d + 10);
        return 1;
    }
    return mscipc_imu_data_gps_correlated_time_decode(d, length, &out->imu_data_gps_correlated_time, NULL) ==
           MSCIPC_OK;
}

static int load_0x89(const uint8_t *d, size_t length, void *packet) {
    mscipc_imu_data_packet_t *out = packet;
    if (length == 12) {
        out->imu_data_scaled_aux_accel.accel[0] = mscipc_ld_f32(d + 0);
        out->imu_data_scaled_aux_accel.accel[1] = mscipc_ld_f32(d + 4);
        out->imu_data_scaled_aux_accel.accel[2] = mscipc_ld_f32(d + 8);
        return 1;
    }
    return mscipc_imu_data_scaled_aux_accel_decode(d, length, &out->imu_data_scaled_aux_accel, NULL) ==
           MSCIPC_OK;
}

const mscipc_layout_member_t mscipc_imu_data_layout_members_[9] = {
    {0x81, offsetof(mscipc_imu_data_packet_t, imu_data_scaled_accel), load_0x81},
    {0x82, offsetof(mscipc_imu_data_packet_t, imu_data_scaled_gyro), load_0x82},
    {0x83, offsetof(mscipc_imu_data_packet_t, imu_data_scaled_mag), load_0x83},
    {0x84, offsetof(mscipc_imu_data_packet_t, imu_data_delta_theta), load_0x84},
    {0x85, offsetof(mscipc_imu_data_packet_t, imu_data_delta_velocity), load_0x85},
    {0x86, offsetof(mscipc_imu_data_packet_t, imu_data_scaled_pressure), load_0x86},
    {0x87, offsetof(mscipc_imu_data_packet_t, imu_data_scaled_temperature), load_0x87},
    {0x88, offsetof(mscipc_imu_data_packet_t, imu_data_gps_correlated_time), load_0x88},
    {0x89, offsetof(mscipc_imu_data_packet_t, imu_data_scaled_aux_accel), load_0x89},
};
