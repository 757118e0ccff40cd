/* Encoders and decoders of Sensor (IMU) Data Set. Generated from the spec: do not edit. */
#include "mipcodec/sets/sensor.h"
#include "layouts_internal.h"
#include "types_internal.h"

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
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_sensor_scaled_accel_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t mipc_sensor_scaled_accel_decode(const uint8_t *data, size_t len,
                                              mipc_sensor_scaled_accel_t *out, mipc_decode_error_t *err) {
    if (len == 12 && mipc_sensor_scaled_accel_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_sensor_scaled_accel_decode_read(data, len, out, err);
}

void mipc_sensor_scaled_accel_to_json(mipc_jw_t *w, const mipc_sensor_scaled_accel_t *in) {
    int first = 1;
    size_t i;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "scaled_accel");
    mipc_jw_raw(w, "[", 1);
    for (i = 0; i < 3; i++) {
        mipc_jw_sep(w, i);
        mipc_jw_f32(w, &in->scaled_accel[i]);
    }
    mipc_jw_raw(w, "]", 1);
    mipc_jw_raw(w, "}", 1);
}

int mipc_sensor_scaled_accel_from_json(mipc_jr_t *jr, size_t pos, mipc_sensor_scaled_accel_t *out) {
    static const char *const keys[] = {"scaled_accel"};
    size_t vp = 0;
    int found;
    size_t i;
    size_t it = 0;
    size_t ep = 0;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 1)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "scaled_accel", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"scaled_accel\"");
    }
    {
        mipc_jr_push(jr, "scaled_accel");
        if (mipc_jr_array(jr, vp, &it)) {
            return -1;
        }
        for (i = 0;; i++) {
            int more = mipc_jr_next(jr, &it, &ep);
            if (more < 0) {
                return -1;
            }
            if (!more) {
                break;
            }
            if (i >= 3) {
                return mipc_jr_fail(jr, "more than 3 elements");
            }
            mipc_jr_index(jr, i);
            if (mipc_jr_f32(jr, ep, &out->scaled_accel[i])) {
                return -1;
            }
        }
        mipc_jr_index(jr, SIZE_MAX);
        if (i != 3) {
            return mipc_jr_fail(jr, "expected 3 elements, got %zu", i);
        }
        mipc_jr_pop(jr);
    }
    return 0;
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
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_sensor_scaled_gyro_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t mipc_sensor_scaled_gyro_decode(const uint8_t *data, size_t len, mipc_sensor_scaled_gyro_t *out,
                                             mipc_decode_error_t *err) {
    if (len == 12 && mipc_sensor_scaled_gyro_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_sensor_scaled_gyro_decode_read(data, len, out, err);
}

void mipc_sensor_scaled_gyro_to_json(mipc_jw_t *w, const mipc_sensor_scaled_gyro_t *in) {
    int first = 1;
    size_t i;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "scaled_gyro");
    mipc_jw_raw(w, "[", 1);
    for (i = 0; i < 3; i++) {
        mipc_jw_sep(w, i);
        mipc_jw_f32(w, &in->scaled_gyro[i]);
    }
    mipc_jw_raw(w, "]", 1);
    mipc_jw_raw(w, "}", 1);
}

int mipc_sensor_scaled_gyro_from_json(mipc_jr_t *jr, size_t pos, mipc_sensor_scaled_gyro_t *out) {
    static const char *const keys[] = {"scaled_gyro"};
    size_t vp = 0;
    int found;
    size_t i;
    size_t it = 0;
    size_t ep = 0;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 1)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "scaled_gyro", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"scaled_gyro\"");
    }
    {
        mipc_jr_push(jr, "scaled_gyro");
        if (mipc_jr_array(jr, vp, &it)) {
            return -1;
        }
        for (i = 0;; i++) {
            int more = mipc_jr_next(jr, &it, &ep);
            if (more < 0) {
                return -1;
            }
            if (!more) {
                break;
            }
            if (i >= 3) {
                return mipc_jr_fail(jr, "more than 3 elements");
            }
            mipc_jr_index(jr, i);
            if (mipc_jr_f32(jr, ep, &out->scaled_gyro[i])) {
                return -1;
            }
        }
        mipc_jr_index(jr, SIZE_MAX);
        if (i != 3) {
            return mipc_jr_fail(jr, "expected 3 elements, got %zu", i);
        }
        mipc_jr_pop(jr);
    }
    return 0;
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
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_sensor_scaled_mag_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t mipc_sensor_scaled_mag_decode(const uint8_t *data, size_t len, mipc_sensor_scaled_mag_t *out,
                                            mipc_decode_error_t *err) {
    if (len == 12 && mipc_sensor_scaled_mag_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_sensor_scaled_mag_decode_read(data, len, out, err);
}

void mipc_sensor_scaled_mag_to_json(mipc_jw_t *w, const mipc_sensor_scaled_mag_t *in) {
    int first = 1;
    size_t i;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "scaled_mag");
    mipc_jw_raw(w, "[", 1);
    for (i = 0; i < 3; i++) {
        mipc_jw_sep(w, i);
        mipc_jw_f32(w, &in->scaled_mag[i]);
    }
    mipc_jw_raw(w, "]", 1);
    mipc_jw_raw(w, "}", 1);
}

int mipc_sensor_scaled_mag_from_json(mipc_jr_t *jr, size_t pos, mipc_sensor_scaled_mag_t *out) {
    static const char *const keys[] = {"scaled_mag"};
    size_t vp = 0;
    int found;
    size_t i;
    size_t it = 0;
    size_t ep = 0;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 1)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "scaled_mag", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"scaled_mag\"");
    }
    {
        mipc_jr_push(jr, "scaled_mag");
        if (mipc_jr_array(jr, vp, &it)) {
            return -1;
        }
        for (i = 0;; i++) {
            int more = mipc_jr_next(jr, &it, &ep);
            if (more < 0) {
                return -1;
            }
            if (!more) {
                break;
            }
            if (i >= 3) {
                return mipc_jr_fail(jr, "more than 3 elements");
            }
            mipc_jr_index(jr, i);
            if (mipc_jr_f32(jr, ep, &out->scaled_mag[i])) {
                return -1;
            }
        }
        mipc_jr_index(jr, SIZE_MAX);
        if (i != 3) {
            return mipc_jr_fail(jr, "expected 3 elements, got %zu", i);
        }
        mipc_jr_pop(jr);
    }
    return 0;
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
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_sensor_delta_theta_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t mipc_sensor_delta_theta_decode(const uint8_t *data, size_t len, mipc_sensor_delta_theta_t *out,
                                             mipc_decode_error_t *err) {
    if (len == 12 && mipc_sensor_delta_theta_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_sensor_delta_theta_decode_read(data, len, out, err);
}

void mipc_sensor_delta_theta_to_json(mipc_jw_t *w, const mipc_sensor_delta_theta_t *in) {
    int first = 1;
    size_t i;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "delta_theta");
    mipc_jw_raw(w, "[", 1);
    for (i = 0; i < 3; i++) {
        mipc_jw_sep(w, i);
        mipc_jw_f32(w, &in->delta_theta[i]);
    }
    mipc_jw_raw(w, "]", 1);
    mipc_jw_raw(w, "}", 1);
}

int mipc_sensor_delta_theta_from_json(mipc_jr_t *jr, size_t pos, mipc_sensor_delta_theta_t *out) {
    static const char *const keys[] = {"delta_theta"};
    size_t vp = 0;
    int found;
    size_t i;
    size_t it = 0;
    size_t ep = 0;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 1)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "delta_theta", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"delta_theta\"");
    }
    {
        mipc_jr_push(jr, "delta_theta");
        if (mipc_jr_array(jr, vp, &it)) {
            return -1;
        }
        for (i = 0;; i++) {
            int more = mipc_jr_next(jr, &it, &ep);
            if (more < 0) {
                return -1;
            }
            if (!more) {
                break;
            }
            if (i >= 3) {
                return mipc_jr_fail(jr, "more than 3 elements");
            }
            mipc_jr_index(jr, i);
            if (mipc_jr_f32(jr, ep, &out->delta_theta[i])) {
                return -1;
            }
        }
        mipc_jr_index(jr, SIZE_MAX);
        if (i != 3) {
            return mipc_jr_fail(jr, "expected 3 elements, got %zu", i);
        }
        mipc_jr_pop(jr);
    }
    return 0;
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
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_sensor_delta_velocity_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t mipc_sensor_delta_velocity_decode(const uint8_t *data, size_t len,
                                                mipc_sensor_delta_velocity_t *out, mipc_decode_error_t *err) {
    if (len == 12 && mipc_sensor_delta_velocity_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_sensor_delta_velocity_decode_read(data, len, out, err);
}

void mipc_sensor_delta_velocity_to_json(mipc_jw_t *w, const mipc_sensor_delta_velocity_t *in) {
    int first = 1;
    size_t i;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "delta_velocity");
    mipc_jw_raw(w, "[", 1);
    for (i = 0; i < 3; i++) {
        mipc_jw_sep(w, i);
        mipc_jw_f32(w, &in->delta_velocity[i]);
    }
    mipc_jw_raw(w, "]", 1);
    mipc_jw_raw(w, "}", 1);
}

int mipc_sensor_delta_velocity_from_json(mipc_jr_t *jr, size_t pos, mipc_sensor_delta_velocity_t *out) {
    static const char *const keys[] = {"delta_velocity"};
    size_t vp = 0;
    int found;
    size_t i;
    size_t it = 0;
    size_t ep = 0;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 1)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "delta_velocity", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"delta_velocity\"");
    }
    {
        mipc_jr_push(jr, "delta_velocity");
        if (mipc_jr_array(jr, vp, &it)) {
            return -1;
        }
        for (i = 0;; i++) {
            int more = mipc_jr_next(jr, &it, &ep);
            if (more < 0) {
                return -1;
            }
            if (!more) {
                break;
            }
            if (i >= 3) {
                return mipc_jr_fail(jr, "more than 3 elements");
            }
            mipc_jr_index(jr, i);
            if (mipc_jr_f32(jr, ep, &out->delta_velocity[i])) {
                return -1;
            }
        }
        mipc_jr_index(jr, SIZE_MAX);
        if (i != 3) {
            return mipc_jr_fail(jr, "expected 3 elements, got %zu", i);
        }
        mipc_jr_pop(jr);
    }
    return 0;
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
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_sensor_cf_orientation_matrix_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t mipc_sensor_cf_orientation_matrix_decode(const uint8_t *data, size_t len,
                                                       mipc_sensor_cf_orientation_matrix_t *out,
                                                       mipc_decode_error_t *err) {
    if (len == 36 && mipc_sensor_cf_orientation_matrix_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_sensor_cf_orientation_matrix_decode_read(data, len, out, err);
}

void mipc_sensor_cf_orientation_matrix_to_json(mipc_jw_t *w, const mipc_sensor_cf_orientation_matrix_t *in) {
    int first = 1;
    size_t i;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "m");
    mipc_jw_raw(w, "[", 1);
    for (i = 0; i < 9; i++) {
        mipc_jw_sep(w, i);
        mipc_jw_f32(w, &in->m[i]);
    }
    mipc_jw_raw(w, "]", 1);
    mipc_jw_raw(w, "}", 1);
}

int mipc_sensor_cf_orientation_matrix_from_json(mipc_jr_t *jr, size_t pos,
                                                mipc_sensor_cf_orientation_matrix_t *out) {
    static const char *const keys[] = {"m"};
    size_t vp = 0;
    int found;
    size_t i;
    size_t it = 0;
    size_t ep = 0;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 1)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "m", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"m\"");
    }
    {
        mipc_jr_push(jr, "m");
        if (mipc_jr_array(jr, vp, &it)) {
            return -1;
        }
        for (i = 0;; i++) {
            int more = mipc_jr_next(jr, &it, &ep);
            if (more < 0) {
                return -1;
            }
            if (!more) {
                break;
            }
            if (i >= 9) {
                return mipc_jr_fail(jr, "more than 9 elements");
            }
            mipc_jr_index(jr, i);
            if (mipc_jr_f32(jr, ep, &out->m[i])) {
                return -1;
            }
        }
        mipc_jr_index(jr, SIZE_MAX);
        if (i != 9) {
            return mipc_jr_fail(jr, "expected 9 elements, got %zu", i);
        }
        mipc_jr_pop(jr);
    }
    return 0;
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
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_sensor_cf_quaternion_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t mipc_sensor_cf_quaternion_decode(const uint8_t *data, size_t len,
                                               mipc_sensor_cf_quaternion_t *out, mipc_decode_error_t *err) {
    if (len == 16 && mipc_sensor_cf_quaternion_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_sensor_cf_quaternion_decode_read(data, len, out, err);
}

void mipc_sensor_cf_quaternion_to_json(mipc_jw_t *w, const mipc_sensor_cf_quaternion_t *in) {
    int first = 1;
    size_t i;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "q");
    mipc_jw_raw(w, "[", 1);
    for (i = 0; i < 4; i++) {
        mipc_jw_sep(w, i);
        mipc_jw_f32(w, &in->q[i]);
    }
    mipc_jw_raw(w, "]", 1);
    mipc_jw_raw(w, "}", 1);
}

int mipc_sensor_cf_quaternion_from_json(mipc_jr_t *jr, size_t pos, mipc_sensor_cf_quaternion_t *out) {
    static const char *const keys[] = {"q"};
    size_t vp = 0;
    int found;
    size_t i;
    size_t it = 0;
    size_t ep = 0;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 1)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "q", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"q\"");
    }
    {
        mipc_jr_push(jr, "q");
        if (mipc_jr_array(jr, vp, &it)) {
            return -1;
        }
        for (i = 0;; i++) {
            int more = mipc_jr_next(jr, &it, &ep);
            if (more < 0) {
                return -1;
            }
            if (!more) {
                break;
            }
            if (i >= 4) {
                return mipc_jr_fail(jr, "more than 4 elements");
            }
            mipc_jr_index(jr, i);
            if (mipc_jr_f32(jr, ep, &out->q[i])) {
                return -1;
            }
        }
        mipc_jr_index(jr, SIZE_MAX);
        if (i != 4) {
            return mipc_jr_fail(jr, "expected 4 elements, got %zu", i);
        }
        mipc_jr_pop(jr);
    }
    return 0;
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
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_sensor_cf_euler_angles_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t mipc_sensor_cf_euler_angles_decode(const uint8_t *data, size_t len,
                                                 mipc_sensor_cf_euler_angles_t *out,
                                                 mipc_decode_error_t *err) {
    if (len == 12 && mipc_sensor_cf_euler_angles_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_sensor_cf_euler_angles_decode_read(data, len, out, err);
}

void mipc_sensor_cf_euler_angles_to_json(mipc_jw_t *w, const mipc_sensor_cf_euler_angles_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "roll");
    mipc_jw_f32(w, &in->roll);
    mipc_jw_key(w, &first, "pitch");
    mipc_jw_f32(w, &in->pitch);
    mipc_jw_key(w, &first, "yaw");
    mipc_jw_f32(w, &in->yaw);
    mipc_jw_raw(w, "}", 1);
}

int mipc_sensor_cf_euler_angles_from_json(mipc_jr_t *jr, size_t pos, mipc_sensor_cf_euler_angles_t *out) {
    static const char *const keys[] = {"roll", "pitch", "yaw"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 3)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "roll", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"roll\"");
    }
    {
        mipc_jr_push(jr, "roll");
        if (mipc_jr_f32(jr, vp, &out->roll)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "pitch", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"pitch\"");
    }
    {
        mipc_jr_push(jr, "pitch");
        if (mipc_jr_f32(jr, vp, &out->pitch)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "yaw", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"yaw\"");
    }
    {
        mipc_jr_push(jr, "yaw");
        if (mipc_jr_f32(jr, vp, &out->yaw)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    return 0;
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
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_sensor_cf_stabilized_north_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t mipc_sensor_cf_stabilized_north_decode(const uint8_t *data, size_t len,
                                                     mipc_sensor_cf_stabilized_north_t *out,
                                                     mipc_decode_error_t *err) {
    if (len == 12 && mipc_sensor_cf_stabilized_north_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_sensor_cf_stabilized_north_decode_read(data, len, out, err);
}

void mipc_sensor_cf_stabilized_north_to_json(mipc_jw_t *w, const mipc_sensor_cf_stabilized_north_t *in) {
    int first = 1;
    size_t i;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "stabilized_north");
    mipc_jw_raw(w, "[", 1);
    for (i = 0; i < 3; i++) {
        mipc_jw_sep(w, i);
        mipc_jw_f32(w, &in->stabilized_north[i]);
    }
    mipc_jw_raw(w, "]", 1);
    mipc_jw_raw(w, "}", 1);
}

int mipc_sensor_cf_stabilized_north_from_json(mipc_jr_t *jr, size_t pos,
                                              mipc_sensor_cf_stabilized_north_t *out) {
    static const char *const keys[] = {"stabilized_north"};
    size_t vp = 0;
    int found;
    size_t i;
    size_t it = 0;
    size_t ep = 0;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 1)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "stabilized_north", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"stabilized_north\"");
    }
    {
        mipc_jr_push(jr, "stabilized_north");
        if (mipc_jr_array(jr, vp, &it)) {
            return -1;
        }
        for (i = 0;; i++) {
            int more = mipc_jr_next(jr, &it, &ep);
            if (more < 0) {
                return -1;
            }
            if (!more) {
                break;
            }
            if (i >= 3) {
                return mipc_jr_fail(jr, "more than 3 elements");
            }
            mipc_jr_index(jr, i);
            if (mipc_jr_f32(jr, ep, &out->stabilized_north[i])) {
                return -1;
            }
        }
        mipc_jr_index(jr, SIZE_MAX);
        if (i != 3) {
            return mipc_jr_fail(jr, "expected 3 elements, got %zu", i);
        }
        mipc_jr_pop(jr);
    }
    return 0;
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
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_sensor_cf_stabilized_up_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t mipc_sensor_cf_stabilized_up_decode(const uint8_t *data, size_t len,
                                                  mipc_sensor_cf_stabilized_up_t *out,
                                                  mipc_decode_error_t *err) {
    if (len == 12 && mipc_sensor_cf_stabilized_up_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_sensor_cf_stabilized_up_decode_read(data, len, out, err);
}

void mipc_sensor_cf_stabilized_up_to_json(mipc_jw_t *w, const mipc_sensor_cf_stabilized_up_t *in) {
    int first = 1;
    size_t i;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "stabilized_up");
    mipc_jw_raw(w, "[", 1);
    for (i = 0; i < 3; i++) {
        mipc_jw_sep(w, i);
        mipc_jw_f32(w, &in->stabilized_up[i]);
    }
    mipc_jw_raw(w, "]", 1);
    mipc_jw_raw(w, "}", 1);
}

int mipc_sensor_cf_stabilized_up_from_json(mipc_jr_t *jr, size_t pos, mipc_sensor_cf_stabilized_up_t *out) {
    static const char *const keys[] = {"stabilized_up"};
    size_t vp = 0;
    int found;
    size_t i;
    size_t it = 0;
    size_t ep = 0;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 1)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "stabilized_up", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"stabilized_up\"");
    }
    {
        mipc_jr_push(jr, "stabilized_up");
        if (mipc_jr_array(jr, vp, &it)) {
            return -1;
        }
        for (i = 0;; i++) {
            int more = mipc_jr_next(jr, &it, &ep);
            if (more < 0) {
                return -1;
            }
            if (!more) {
                break;
            }
            if (i >= 3) {
                return mipc_jr_fail(jr, "more than 3 elements");
            }
            mipc_jr_index(jr, i);
            if (mipc_jr_f32(jr, ep, &out->stabilized_up[i])) {
                return -1;
            }
        }
        mipc_jr_index(jr, SIZE_MAX);
        if (i != 3) {
            return mipc_jr_fail(jr, "expected 3 elements, got %zu", i);
        }
        mipc_jr_pop(jr);
    }
    return 0;
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
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_sensor_gps_timestamp_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t mipc_sensor_gps_timestamp_decode(const uint8_t *data, size_t len,
                                               mipc_sensor_gps_timestamp_t *out, mipc_decode_error_t *err) {
    if (len == 12 && mipc_sensor_gps_timestamp_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_sensor_gps_timestamp_decode_read(data, len, out, err);
}

void mipc_sensor_gps_timestamp_to_json(mipc_jw_t *w, const mipc_sensor_gps_timestamp_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "tow");
    mipc_jw_f64(w, &in->tow);
    mipc_jw_key(w, &first, "week_number");
    mipc_jw_u16(w, &in->week_number);
    mipc_jw_key(w, &first, "valid_flags");
    mipc_jw_u16(w, &in->valid_flags);
    mipc_jw_raw(w, "}", 1);
}

int mipc_sensor_gps_timestamp_from_json(mipc_jr_t *jr, size_t pos, mipc_sensor_gps_timestamp_t *out) {
    static const char *const keys[] = {"tow", "week_number", "valid_flags"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 3)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "tow", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"tow\"");
    }
    {
        mipc_jr_push(jr, "tow");
        if (mipc_jr_f64(jr, vp, &out->tow)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "week_number", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"week_number\"");
    }
    {
        mipc_jr_push(jr, "week_number");
        if (mipc_jr_u16(jr, vp, &out->week_number)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "valid_flags", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"valid_flags\"");
    }
    {
        mipc_jr_push(jr, "valid_flags");
        if (mipc_jr_u16(jr, vp, &out->valid_flags)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    return 0;
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
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_sensor_temperature_statistics_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t mipc_sensor_temperature_statistics_decode(const uint8_t *data, size_t len,
                                                        mipc_sensor_temperature_statistics_t *out,
                                                        mipc_decode_error_t *err) {
    if (len == 12 && mipc_sensor_temperature_statistics_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_sensor_temperature_statistics_decode_read(data, len, out, err);
}

void mipc_sensor_temperature_statistics_to_json(mipc_jw_t *w,
                                                const mipc_sensor_temperature_statistics_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "min_temp");
    mipc_jw_f32(w, &in->min_temp);
    mipc_jw_key(w, &first, "max_temp");
    mipc_jw_f32(w, &in->max_temp);
    mipc_jw_key(w, &first, "mean_temp");
    mipc_jw_f32(w, &in->mean_temp);
    mipc_jw_raw(w, "}", 1);
}

int mipc_sensor_temperature_statistics_from_json(mipc_jr_t *jr, size_t pos,
                                                 mipc_sensor_temperature_statistics_t *out) {
    static const char *const keys[] = {"min_temp", "max_temp", "mean_temp"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 3)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "min_temp", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"min_temp\"");
    }
    {
        mipc_jr_push(jr, "min_temp");
        if (mipc_jr_f32(jr, vp, &out->min_temp)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "max_temp", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"max_temp\"");
    }
    {
        mipc_jr_push(jr, "max_temp");
        if (mipc_jr_f32(jr, vp, &out->max_temp)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "mean_temp", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"mean_temp\"");
    }
    {
        mipc_jr_push(jr, "mean_temp");
        if (mipc_jr_f32(jr, vp, &out->mean_temp)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    return 0;
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
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_sensor_scaled_pressure_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t mipc_sensor_scaled_pressure_decode(const uint8_t *data, size_t len,
                                                 mipc_sensor_scaled_pressure_t *out,
                                                 mipc_decode_error_t *err) {
    if (len == 4 && mipc_sensor_scaled_pressure_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_sensor_scaled_pressure_decode_read(data, len, out, err);
}

void mipc_sensor_scaled_pressure_to_json(mipc_jw_t *w, const mipc_sensor_scaled_pressure_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "scaled_pressure");
    mipc_jw_f32(w, &in->scaled_pressure);
    mipc_jw_raw(w, "}", 1);
}

int mipc_sensor_scaled_pressure_from_json(mipc_jr_t *jr, size_t pos, mipc_sensor_scaled_pressure_t *out) {
    static const char *const keys[] = {"scaled_pressure"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 1)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "scaled_pressure", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"scaled_pressure\"");
    }
    {
        mipc_jr_push(jr, "scaled_pressure");
        if (mipc_jr_f32(jr, vp, &out->scaled_pressure)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    return 0;
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
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_sensor_overrange_status_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t mipc_sensor_overrange_status_decode(const uint8_t *data, size_t len,
                                                  mipc_sensor_overrange_status_t *out,
                                                  mipc_decode_error_t *err) {
    if (len == 2 && mipc_sensor_overrange_status_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_sensor_overrange_status_decode_read(data, len, out, err);
}

void mipc_sensor_overrange_status_to_json(mipc_jw_t *w, const mipc_sensor_overrange_status_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "status");
    mipc_jw_u16(w, &in->status);
    mipc_jw_raw(w, "}", 1);
}

int mipc_sensor_overrange_status_from_json(mipc_jr_t *jr, size_t pos, mipc_sensor_overrange_status_t *out) {
    static const char *const keys[] = {"status"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 1)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "status", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"status\"");
    }
    {
        mipc_jr_push(jr, "status");
        if (mipc_jr_u16(jr, vp, &out->status)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    return 0;
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
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_sensor_odometer_data_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t mipc_sensor_odometer_data_decode(const uint8_t *data, size_t len,
                                               mipc_sensor_odometer_data_t *out, mipc_decode_error_t *err) {
    if (len == 10 && mipc_sensor_odometer_data_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_sensor_odometer_data_decode_read(data, len, out, err);
}

void mipc_sensor_odometer_data_to_json(mipc_jw_t *w, const mipc_sensor_odometer_data_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "speed");
    mipc_jw_f32(w, &in->speed);
    mipc_jw_key(w, &first, "uncertainty");
    mipc_jw_f32(w, &in->uncertainty);
    mipc_jw_key(w, &first, "valid_flags");
    mipc_jw_u16(w, &in->valid_flags);
    mipc_jw_raw(w, "}", 1);
}

int mipc_sensor_odometer_data_from_json(mipc_jr_t *jr, size_t pos, mipc_sensor_odometer_data_t *out) {
    static const char *const keys[] = {"speed", "uncertainty", "valid_flags"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 3)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "speed", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"speed\"");
    }
    {
        mipc_jr_push(jr, "speed");
        if (mipc_jr_f32(jr, vp, &out->speed)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "uncertainty", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"uncertainty\"");
    }
    {
        mipc_jr_push(jr, "uncertainty");
        if (mipc_jr_f32(jr, vp, &out->uncertainty)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "valid_flags", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"valid_flags\"");
    }
    {
        mipc_jr_push(jr, "valid_flags");
        if (mipc_jr_u16(jr, vp, &out->valid_flags)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    return 0;
}
