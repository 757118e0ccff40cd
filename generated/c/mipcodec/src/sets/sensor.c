/* Encoders and decoders of Sensor (IMU) Data Set. Generated from the spec: do not edit. */
#include "mipcodec/sets/sensor.h"
#include "layouts_internal.h"
#include "types_internal.h"

#include <assert.h>
#include <string.h>

/* ---- mip_sensor_scaled_accel_t */

static int mip_sensor_scaled_accel_read(mip_reader_t *r, mip_sensor_scaled_accel_t *out) {
    size_t i;
    mip_rd_push(r, "scaled_accel");
    for (i = 0; i < 3; i++) {
        mip_rd_index(r, i);
        if (mip_rd_f32(r, &out->scaled_accel[i])) {
            return -1;
        }
    }
    mip_rd_pop(r);
    return mip_rd_finish(r);
}

static mip_status_t mip_sensor_scaled_accel_write(mip_writer_t *w, const mip_sensor_scaled_accel_t *in) {
    mip_status_t st;
    size_t i;
    for (i = 0; i < 3; i++) {
        if ((st = mip_wr_f32(w, &in->scaled_accel[i])) != MIP_OK) {
            return st;
        }
    }
    return MIP_OK;
}

mip_status_t mip_sensor_scaled_accel_encode(const mip_sensor_scaled_accel_t *value, uint8_t *buf, size_t cap,
                                            size_t *len_out) {
    mip_writer_t w;
    mip_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mip_writer_init(&w, buf, cap);
    st = mip_sensor_scaled_accel_write(&w, value);
    if (st == MIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 12 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mip_sensor_scaled_accel_load(const uint8_t *d, mip_sensor_scaled_accel_t *out) {
    out->scaled_accel[0] = mip_ld_f32(d + 0);
    out->scaled_accel[1] = mip_ld_f32(d + 4);
    out->scaled_accel[2] = mip_ld_f32(d + 8);
    return 0;
}

/* The general reader: lengths other than 12, bad bool bytes, error details. */
static MIP_NOINLINE mip_status_t mip_sensor_scaled_accel_decode_read(const uint8_t *data, size_t len,
                                                                     mip_sensor_scaled_accel_t *out,
                                                                     mip_decode_error_t *err) {
    mip_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mip_sensor_scaled_accel_read(&r, out) ? MIP_ERR_DECODE : MIP_OK;
}

mip_status_t mip_sensor_scaled_accel_decode(const uint8_t *data, size_t len, mip_sensor_scaled_accel_t *out,
                                            mip_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 12 && mip_sensor_scaled_accel_load(data, out) == 0) {
        return MIP_OK;
    }
    return mip_sensor_scaled_accel_decode_read(data, len, out, err);
}

void mip_sensor_scaled_accel_to_json(mip_jw_t *w, const mip_sensor_scaled_accel_t *in) {
    int first = 1;
    size_t i;
    mip_jw_raw(w, "{", 1);
    mip_jw_key(w, &first, "scaled_accel");
    mip_jw_raw(w, "[", 1);
    for (i = 0; i < 3; i++) {
        mip_jw_sep(w, i);
        mip_jw_f32(w, &in->scaled_accel[i]);
    }
    mip_jw_raw(w, "]", 1);
    mip_jw_raw(w, "}", 1);
}

int mip_sensor_scaled_accel_from_json(mip_jr_t *jr, size_t pos, mip_sensor_scaled_accel_t *out) {
    static const char *const keys[] = {"scaled_accel"};
    size_t vp = 0;
    int found;
    size_t i;
    size_t it = 0;
    size_t ep = 0;
    memset(out, 0, sizeof *out);
    if (mip_jr_object(jr, pos, keys, 1)) {
        return -1;
    }
    found = mip_jr_get(jr, pos, "scaled_accel", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"scaled_accel\"");
    }
    {
        mip_jr_push(jr, "scaled_accel");
        if (mip_jr_array(jr, vp, &it)) {
            return -1;
        }
        for (i = 0;; i++) {
            int more = mip_jr_next(jr, &it, &ep);
            if (more < 0) {
                return -1;
            }
            if (!more) {
                break;
            }
            if (i >= 3) {
                return mip_jr_fail(jr, "more than 3 elements");
            }
            mip_jr_index(jr, i);
            if (mip_jr_f32(jr, ep, &out->scaled_accel[i])) {
                return -1;
            }
        }
        mip_jr_index(jr, SIZE_MAX);
        if (i != 3) {
            return mip_jr_fail(jr, "expected 3 elements, got %zu", i);
        }
        mip_jr_pop(jr);
    }
    return 0;
}

/* ---- mip_sensor_scaled_gyro_t */

static int mip_sensor_scaled_gyro_read(mip_reader_t *r, mip_sensor_scaled_gyro_t *out) {
    size_t i;
    mip_rd_push(r, "scaled_gyro");
    for (i = 0; i < 3; i++) {
        mip_rd_index(r, i);
        if (mip_rd_f32(r, &out->scaled_gyro[i])) {
            return -1;
        }
    }
    mip_rd_pop(r);
    return mip_rd_finish(r);
}

static mip_status_t mip_sensor_scaled_gyro_write(mip_writer_t *w, const mip_sensor_scaled_gyro_t *in) {
    mip_status_t st;
    size_t i;
    for (i = 0; i < 3; i++) {
        if ((st = mip_wr_f32(w, &in->scaled_gyro[i])) != MIP_OK) {
            return st;
        }
    }
    return MIP_OK;
}

mip_status_t mip_sensor_scaled_gyro_encode(const mip_sensor_scaled_gyro_t *value, uint8_t *buf, size_t cap,
                                           size_t *len_out) {
    mip_writer_t w;
    mip_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mip_writer_init(&w, buf, cap);
    st = mip_sensor_scaled_gyro_write(&w, value);
    if (st == MIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 12 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mip_sensor_scaled_gyro_load(const uint8_t *d, mip_sensor_scaled_gyro_t *out) {
    out->scaled_gyro[0] = mip_ld_f32(d + 0);
    out->scaled_gyro[1] = mip_ld_f32(d + 4);
    out->scaled_gyro[2] = mip_ld_f32(d + 8);
    return 0;
}

/* The general reader: lengths other than 12, bad bool bytes, error details. */
static MIP_NOINLINE mip_status_t mip_sensor_scaled_gyro_decode_read(const uint8_t *data, size_t len,
                                                                    mip_sensor_scaled_gyro_t *out,
                                                                    mip_decode_error_t *err) {
    mip_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mip_sensor_scaled_gyro_read(&r, out) ? MIP_ERR_DECODE : MIP_OK;
}

mip_status_t mip_sensor_scaled_gyro_decode(const uint8_t *data, size_t len, mip_sensor_scaled_gyro_t *out,
                                           mip_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 12 && mip_sensor_scaled_gyro_load(data, out) == 0) {
        return MIP_OK;
    }
    return mip_sensor_scaled_gyro_decode_read(data, len, out, err);
}

void mip_sensor_scaled_gyro_to_json(mip_jw_t *w, const mip_sensor_scaled_gyro_t *in) {
    int first = 1;
    size_t i;
    mip_jw_raw(w, "{", 1);
    mip_jw_key(w, &first, "scaled_gyro");
    mip_jw_raw(w, "[", 1);
    for (i = 0; i < 3; i++) {
        mip_jw_sep(w, i);
        mip_jw_f32(w, &in->scaled_gyro[i]);
    }
    mip_jw_raw(w, "]", 1);
    mip_jw_raw(w, "}", 1);
}

int mip_sensor_scaled_gyro_from_json(mip_jr_t *jr, size_t pos, mip_sensor_scaled_gyro_t *out) {
    static const char *const keys[] = {"scaled_gyro"};
    size_t vp = 0;
    int found;
    size_t i;
    size_t it = 0;
    size_t ep = 0;
    memset(out, 0, sizeof *out);
    if (mip_jr_object(jr, pos, keys, 1)) {
        return -1;
    }
    found = mip_jr_get(jr, pos, "scaled_gyro", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"scaled_gyro\"");
    }
    {
        mip_jr_push(jr, "scaled_gyro");
        if (mip_jr_array(jr, vp, &it)) {
            return -1;
        }
        for (i = 0;; i++) {
            int more = mip_jr_next(jr, &it, &ep);
            if (more < 0) {
                return -1;
            }
            if (!more) {
                break;
            }
            if (i >= 3) {
                return mip_jr_fail(jr, "more than 3 elements");
            }
            mip_jr_index(jr, i);
            if (mip_jr_f32(jr, ep, &out->scaled_gyro[i])) {
                return -1;
            }
        }
        mip_jr_index(jr, SIZE_MAX);
        if (i != 3) {
            return mip_jr_fail(jr, "expected 3 elements, got %zu", i);
        }
        mip_jr_pop(jr);
    }
    return 0;
}

/* ---- mip_sensor_scaled_mag_t */

static int mip_sensor_scaled_mag_read(mip_reader_t *r, mip_sensor_scaled_mag_t *out) {
    size_t i;
    mip_rd_push(r, "scaled_mag");
    for (i = 0; i < 3; i++) {
        mip_rd_index(r, i);
        if (mip_rd_f32(r, &out->scaled_mag[i])) {
            return -1;
        }
    }
    mip_rd_pop(r);
    return mip_rd_finish(r);
}

static mip_status_t mip_sensor_scaled_mag_write(mip_writer_t *w, const mip_sensor_scaled_mag_t *in) {
    mip_status_t st;
    size_t i;
    for (i = 0; i < 3; i++) {
        if ((st = mip_wr_f32(w, &in->scaled_mag[i])) != MIP_OK) {
            return st;
        }
    }
    return MIP_OK;
}

mip_status_t mip_sensor_scaled_mag_encode(const mip_sensor_scaled_mag_t *value, uint8_t *buf, size_t cap,
                                          size_t *len_out) {
    mip_writer_t w;
    mip_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mip_writer_init(&w, buf, cap);
    st = mip_sensor_scaled_mag_write(&w, value);
    if (st == MIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 12 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mip_sensor_scaled_mag_load(const uint8_t *d, mip_sensor_scaled_mag_t *out) {
    out->scaled_mag[0] = mip_ld_f32(d + 0);
    out->scaled_mag[1] = mip_ld_f32(d + 4);
    out->scaled_mag[2] = mip_ld_f32(d + 8);
    return 0;
}

/* The general reader: lengths other than 12, bad bool bytes, error details. */
static MIP_NOINLINE mip_status_t mip_sensor_scaled_mag_decode_read(const uint8_t *data, size_t len,
                                                                   mip_sensor_scaled_mag_t *out,
                                                                   mip_decode_error_t *err) {
    mip_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mip_sensor_scaled_mag_read(&r, out) ? MIP_ERR_DECODE : MIP_OK;
}

mip_status_t mip_sensor_scaled_mag_decode(const uint8_t *data, size_t len, mip_sensor_scaled_mag_t *out,
                                          mip_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 12 && mip_sensor_scaled_mag_load(data, out) == 0) {
        return MIP_OK;
    }
    return mip_sensor_scaled_mag_decode_read(data, len, out, err);
}

void mip_sensor_scaled_mag_to_json(mip_jw_t *w, const mip_sensor_scaled_mag_t *in) {
    int first = 1;
    size_t i;
    mip_jw_raw(w, "{", 1);
    mip_jw_key(w, &first, "scaled_mag");
    mip_jw_raw(w, "[", 1);
    for (i = 0; i < 3; i++) {
        mip_jw_sep(w, i);
        mip_jw_f32(w, &in->scaled_mag[i]);
    }
    mip_jw_raw(w, "]", 1);
    mip_jw_raw(w, "}", 1);
}

int mip_sensor_scaled_mag_from_json(mip_jr_t *jr, size_t pos, mip_sensor_scaled_mag_t *out) {
    static const char *const keys[] = {"scaled_mag"};
    size_t vp = 0;
    int found;
    size_t i;
    size_t it = 0;
    size_t ep = 0;
    memset(out, 0, sizeof *out);
    if (mip_jr_object(jr, pos, keys, 1)) {
        return -1;
    }
    found = mip_jr_get(jr, pos, "scaled_mag", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"scaled_mag\"");
    }
    {
        mip_jr_push(jr, "scaled_mag");
        if (mip_jr_array(jr, vp, &it)) {
            return -1;
        }
        for (i = 0;; i++) {
            int more = mip_jr_next(jr, &it, &ep);
            if (more < 0) {
                return -1;
            }
            if (!more) {
                break;
            }
            if (i >= 3) {
                return mip_jr_fail(jr, "more than 3 elements");
            }
            mip_jr_index(jr, i);
            if (mip_jr_f32(jr, ep, &out->scaled_mag[i])) {
                return -1;
            }
        }
        mip_jr_index(jr, SIZE_MAX);
        if (i != 3) {
            return mip_jr_fail(jr, "expected 3 elements, got %zu", i);
        }
        mip_jr_pop(jr);
    }
    return 0;
}

/* ---- mip_sensor_delta_theta_t */

static int mip_sensor_delta_theta_read(mip_reader_t *r, mip_sensor_delta_theta_t *out) {
    size_t i;
    mip_rd_push(r, "delta_theta");
    for (i = 0; i < 3; i++) {
        mip_rd_index(r, i);
        if (mip_rd_f32(r, &out->delta_theta[i])) {
            return -1;
        }
    }
    mip_rd_pop(r);
    return mip_rd_finish(r);
}

static mip_status_t mip_sensor_delta_theta_write(mip_writer_t *w, const mip_sensor_delta_theta_t *in) {
    mip_status_t st;
    size_t i;
    for (i = 0; i < 3; i++) {
        if ((st = mip_wr_f32(w, &in->delta_theta[i])) != MIP_OK) {
            return st;
        }
    }
    return MIP_OK;
}

mip_status_t mip_sensor_delta_theta_encode(const mip_sensor_delta_theta_t *value, uint8_t *buf, size_t cap,
                                           size_t *len_out) {
    mip_writer_t w;
    mip_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mip_writer_init(&w, buf, cap);
    st = mip_sensor_delta_theta_write(&w, value);
    if (st == MIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 12 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mip_sensor_delta_theta_load(const uint8_t *d, mip_sensor_delta_theta_t *out) {
    out->delta_theta[0] = mip_ld_f32(d + 0);
    out->delta_theta[1] = mip_ld_f32(d + 4);
    out->delta_theta[2] = mip_ld_f32(d + 8);
    return 0;
}

/* The general reader: lengths other than 12, bad bool bytes, error details. */
static MIP_NOINLINE mip_status_t mip_sensor_delta_theta_decode_read(const uint8_t *data, size_t len,
                                                                    mip_sensor_delta_theta_t *out,
                                                                    mip_decode_error_t *err) {
    mip_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mip_sensor_delta_theta_read(&r, out) ? MIP_ERR_DECODE : MIP_OK;
}

mip_status_t mip_sensor_delta_theta_decode(const uint8_t *data, size_t len, mip_sensor_delta_theta_t *out,
                                           mip_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 12 && mip_sensor_delta_theta_load(data, out) == 0) {
        return MIP_OK;
    }
    return mip_sensor_delta_theta_decode_read(data, len, out, err);
}

void mip_sensor_delta_theta_to_json(mip_jw_t *w, const mip_sensor_delta_theta_t *in) {
    int first = 1;
    size_t i;
    mip_jw_raw(w, "{", 1);
    mip_jw_key(w, &first, "delta_theta");
    mip_jw_raw(w, "[", 1);
    for (i = 0; i < 3; i++) {
        mip_jw_sep(w, i);
        mip_jw_f32(w, &in->delta_theta[i]);
    }
    mip_jw_raw(w, "]", 1);
    mip_jw_raw(w, "}", 1);
}

int mip_sensor_delta_theta_from_json(mip_jr_t *jr, size_t pos, mip_sensor_delta_theta_t *out) {
    static const char *const keys[] = {"delta_theta"};
    size_t vp = 0;
    int found;
    size_t i;
    size_t it = 0;
    size_t ep = 0;
    memset(out, 0, sizeof *out);
    if (mip_jr_object(jr, pos, keys, 1)) {
        return -1;
    }
    found = mip_jr_get(jr, pos, "delta_theta", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"delta_theta\"");
    }
    {
        mip_jr_push(jr, "delta_theta");
        if (mip_jr_array(jr, vp, &it)) {
            return -1;
        }
        for (i = 0;; i++) {
            int more = mip_jr_next(jr, &it, &ep);
            if (more < 0) {
                return -1;
            }
            if (!more) {
                break;
            }
            if (i >= 3) {
                return mip_jr_fail(jr, "more than 3 elements");
            }
            mip_jr_index(jr, i);
            if (mip_jr_f32(jr, ep, &out->delta_theta[i])) {
                return -1;
            }
        }
        mip_jr_index(jr, SIZE_MAX);
        if (i != 3) {
            return mip_jr_fail(jr, "expected 3 elements, got %zu", i);
        }
        mip_jr_pop(jr);
    }
    return 0;
}

/* ---- mip_sensor_delta_velocity_t */

static int mip_sensor_delta_velocity_read(mip_reader_t *r, mip_sensor_delta_velocity_t *out) {
    size_t i;
    mip_rd_push(r, "delta_velocity");
    for (i = 0; i < 3; i++) {
        mip_rd_index(r, i);
        if (mip_rd_f32(r, &out->delta_velocity[i])) {
            return -1;
        }
    }
    mip_rd_pop(r);
    return mip_rd_finish(r);
}

static mip_status_t mip_sensor_delta_velocity_write(mip_writer_t *w, const mip_sensor_delta_velocity_t *in) {
    mip_status_t st;
    size_t i;
    for (i = 0; i < 3; i++) {
        if ((st = mip_wr_f32(w, &in->delta_velocity[i])) != MIP_OK) {
            return st;
        }
    }
    return MIP_OK;
}

mip_status_t mip_sensor_delta_velocity_encode(const mip_sensor_delta_velocity_t *value, uint8_t *buf,
                                              size_t cap, size_t *len_out) {
    mip_writer_t w;
    mip_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mip_writer_init(&w, buf, cap);
    st = mip_sensor_delta_velocity_write(&w, value);
    if (st == MIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 12 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mip_sensor_delta_velocity_load(const uint8_t *d, mip_sensor_delta_velocity_t *out) {
    out->delta_velocity[0] = mip_ld_f32(d + 0);
    out->delta_velocity[1] = mip_ld_f32(d + 4);
    out->delta_velocity[2] = mip_ld_f32(d + 8);
    return 0;
}

/* The general reader: lengths other than 12, bad bool bytes, error details. */
static MIP_NOINLINE mip_status_t mip_sensor_delta_velocity_decode_read(const uint8_t *data, size_t len,
                                                                       mip_sensor_delta_velocity_t *out,
                                                                       mip_decode_error_t *err) {
    mip_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mip_sensor_delta_velocity_read(&r, out) ? MIP_ERR_DECODE : MIP_OK;
}

mip_status_t mip_sensor_delta_velocity_decode(const uint8_t *data, size_t len,
                                              mip_sensor_delta_velocity_t *out, mip_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 12 && mip_sensor_delta_velocity_load(data, out) == 0) {
        return MIP_OK;
    }
    return mip_sensor_delta_velocity_decode_read(data, len, out, err);
}

void mip_sensor_delta_velocity_to_json(mip_jw_t *w, const mip_sensor_delta_velocity_t *in) {
    int first = 1;
    size_t i;
    mip_jw_raw(w, "{", 1);
    mip_jw_key(w, &first, "delta_velocity");
    mip_jw_raw(w, "[", 1);
    for (i = 0; i < 3; i++) {
        mip_jw_sep(w, i);
        mip_jw_f32(w, &in->delta_velocity[i]);
    }
    mip_jw_raw(w, "]", 1);
    mip_jw_raw(w, "}", 1);
}

int mip_sensor_delta_velocity_from_json(mip_jr_t *jr, size_t pos, mip_sensor_delta_velocity_t *out) {
    static const char *const keys[] = {"delta_velocity"};
    size_t vp = 0;
    int found;
    size_t i;
    size_t it = 0;
    size_t ep = 0;
    memset(out, 0, sizeof *out);
    if (mip_jr_object(jr, pos, keys, 1)) {
        return -1;
    }
    found = mip_jr_get(jr, pos, "delta_velocity", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"delta_velocity\"");
    }
    {
        mip_jr_push(jr, "delta_velocity");
        if (mip_jr_array(jr, vp, &it)) {
            return -1;
        }
        for (i = 0;; i++) {
            int more = mip_jr_next(jr, &it, &ep);
            if (more < 0) {
                return -1;
            }
            if (!more) {
                break;
            }
            if (i >= 3) {
                return mip_jr_fail(jr, "more than 3 elements");
            }
            mip_jr_index(jr, i);
            if (mip_jr_f32(jr, ep, &out->delta_velocity[i])) {
                return -1;
            }
        }
        mip_jr_index(jr, SIZE_MAX);
        if (i != 3) {
            return mip_jr_fail(jr, "expected 3 elements, got %zu", i);
        }
        mip_jr_pop(jr);
    }
    return 0;
}

/* ---- mip_sensor_cf_orientation_matrix_t */

static int mip_sensor_cf_orientation_matrix_read(mip_reader_t *r, mip_sensor_cf_orientation_matrix_t *out) {
    size_t i;
    mip_rd_push(r, "m");
    for (i = 0; i < 9; i++) {
        mip_rd_index(r, i);
        if (mip_rd_f32(r, &out->m[i])) {
            return -1;
        }
    }
    mip_rd_pop(r);
    return mip_rd_finish(r);
}

static mip_status_t mip_sensor_cf_orientation_matrix_write(mip_writer_t *w,
                                                           const mip_sensor_cf_orientation_matrix_t *in) {
    mip_status_t st;
    size_t i;
    for (i = 0; i < 9; i++) {
        if ((st = mip_wr_f32(w, &in->m[i])) != MIP_OK) {
            return st;
        }
    }
    return MIP_OK;
}

mip_status_t mip_sensor_cf_orientation_matrix_encode(const mip_sensor_cf_orientation_matrix_t *value,
                                                     uint8_t *buf, size_t cap, size_t *len_out) {
    mip_writer_t w;
    mip_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mip_writer_init(&w, buf, cap);
    st = mip_sensor_cf_orientation_matrix_write(&w, value);
    if (st == MIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 36 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mip_sensor_cf_orientation_matrix_load(const uint8_t *d, mip_sensor_cf_orientation_matrix_t *out) {
    out->m[0] = mip_ld_f32(d + 0);
    out->m[1] = mip_ld_f32(d + 4);
    out->m[2] = mip_ld_f32(d + 8);
    out->m[3] = mip_ld_f32(d + 12);
    out->m[4] = mip_ld_f32(d + 16);
    out->m[5] = mip_ld_f32(d + 20);
    out->m[6] = mip_ld_f32(d + 24);
    out->m[7] = mip_ld_f32(d + 28);
    out->m[8] = mip_ld_f32(d + 32);
    return 0;
}

/* The general reader: lengths other than 36, bad bool bytes, error details. */
static MIP_NOINLINE mip_status_t mip_sensor_cf_orientation_matrix_decode_read(
    const uint8_t *data, size_t len, mip_sensor_cf_orientation_matrix_t *out, mip_decode_error_t *err) {
    mip_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mip_sensor_cf_orientation_matrix_read(&r, out) ? MIP_ERR_DECODE : MIP_OK;
}

mip_status_t mip_sensor_cf_orientation_matrix_decode(const uint8_t *data, size_t len,
                                                     mip_sensor_cf_orientation_matrix_t *out,
                                                     mip_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 36 && mip_sensor_cf_orientation_matrix_load(data, out) == 0) {
        return MIP_OK;
    }
    return mip_sensor_cf_orientation_matrix_decode_read(data, len, out, err);
}

void mip_sensor_cf_orientation_matrix_to_json(mip_jw_t *w, const mip_sensor_cf_orientation_matrix_t *in) {
    int first = 1;
    size_t i;
    mip_jw_raw(w, "{", 1);
    mip_jw_key(w, &first, "m");
    mip_jw_raw(w, "[", 1);
    for (i = 0; i < 9; i++) {
        mip_jw_sep(w, i);
        mip_jw_f32(w, &in->m[i]);
    }
    mip_jw_raw(w, "]", 1);
    mip_jw_raw(w, "}", 1);
}

int mip_sensor_cf_orientation_matrix_from_json(mip_jr_t *jr, size_t pos,
                                               mip_sensor_cf_orientation_matrix_t *out) {
    static const char *const keys[] = {"m"};
    size_t vp = 0;
    int found;
    size_t i;
    size_t it = 0;
    size_t ep = 0;
    memset(out, 0, sizeof *out);
    if (mip_jr_object(jr, pos, keys, 1)) {
        return -1;
    }
    found = mip_jr_get(jr, pos, "m", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"m\"");
    }
    {
        mip_jr_push(jr, "m");
        if (mip_jr_array(jr, vp, &it)) {
            return -1;
        }
        for (i = 0;; i++) {
            int more = mip_jr_next(jr, &it, &ep);
            if (more < 0) {
                return -1;
            }
            if (!more) {
                break;
            }
            if (i >= 9) {
                return mip_jr_fail(jr, "more than 9 elements");
            }
            mip_jr_index(jr, i);
            if (mip_jr_f32(jr, ep, &out->m[i])) {
                return -1;
            }
        }
        mip_jr_index(jr, SIZE_MAX);
        if (i != 9) {
            return mip_jr_fail(jr, "expected 9 elements, got %zu", i);
        }
        mip_jr_pop(jr);
    }
    return 0;
}

/* ---- mip_sensor_cf_quaternion_t */

static int mip_sensor_cf_quaternion_read(mip_reader_t *r, mip_sensor_cf_quaternion_t *out) {
    size_t i;
    mip_rd_push(r, "q");
    for (i = 0; i < 4; i++) {
        mip_rd_index(r, i);
        if (mip_rd_f32(r, &out->q[i])) {
            return -1;
        }
    }
    mip_rd_pop(r);
    return mip_rd_finish(r);
}

static mip_status_t mip_sensor_cf_quaternion_write(mip_writer_t *w, const mip_sensor_cf_quaternion_t *in) {
    mip_status_t st;
    size_t i;
    for (i = 0; i < 4; i++) {
        if ((st = mip_wr_f32(w, &in->q[i])) != MIP_OK) {
            return st;
        }
    }
    return MIP_OK;
}

mip_status_t mip_sensor_cf_quaternion_encode(const mip_sensor_cf_quaternion_t *value, uint8_t *buf,
                                             size_t cap, size_t *len_out) {
    mip_writer_t w;
    mip_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mip_writer_init(&w, buf, cap);
    st = mip_sensor_cf_quaternion_write(&w, value);
    if (st == MIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 16 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mip_sensor_cf_quaternion_load(const uint8_t *d, mip_sensor_cf_quaternion_t *out) {
    out->q[0] = mip_ld_f32(d + 0);
    out->q[1] = mip_ld_f32(d + 4);
    out->q[2] = mip_ld_f32(d + 8);
    out->q[3] = mip_ld_f32(d + 12);
    return 0;
}

/* The general reader: lengths other than 16, bad bool bytes, error details. */
static MIP_NOINLINE mip_status_t mip_sensor_cf_quaternion_decode_read(const uint8_t *data, size_t len,
                                                                      mip_sensor_cf_quaternion_t *out,
                                                                      mip_decode_error_t *err) {
    mip_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mip_sensor_cf_quaternion_read(&r, out) ? MIP_ERR_DECODE : MIP_OK;
}

mip_status_t mip_sensor_cf_quaternion_decode(const uint8_t *data, size_t len, mip_sensor_cf_quaternion_t *out,
                                             mip_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 16 && mip_sensor_cf_quaternion_load(data, out) == 0) {
        return MIP_OK;
    }
    return mip_sensor_cf_quaternion_decode_read(data, len, out, err);
}

void mip_sensor_cf_quaternion_to_json(mip_jw_t *w, const mip_sensor_cf_quaternion_t *in) {
    int first = 1;
    size_t i;
    mip_jw_raw(w, "{", 1);
    mip_jw_key(w, &first, "q");
    mip_jw_raw(w, "[", 1);
    for (i = 0; i < 4; i++) {
        mip_jw_sep(w, i);
        mip_jw_f32(w, &in->q[i]);
    }
    mip_jw_raw(w, "]", 1);
    mip_jw_raw(w, "}", 1);
}

int mip_sensor_cf_quaternion_from_json(mip_jr_t *jr, size_t pos, mip_sensor_cf_quaternion_t *out) {
    static const char *const keys[] = {"q"};
    size_t vp = 0;
    int found;
    size_t i;
    size_t it = 0;
    size_t ep = 0;
    memset(out, 0, sizeof *out);
    if (mip_jr_object(jr, pos, keys, 1)) {
        return -1;
    }
    found = mip_jr_get(jr, pos, "q", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"q\"");
    }
    {
        mip_jr_push(jr, "q");
        if (mip_jr_array(jr, vp, &it)) {
            return -1;
        }
        for (i = 0;; i++) {
            int more = mip_jr_next(jr, &it, &ep);
            if (more < 0) {
                return -1;
            }
            if (!more) {
                break;
            }
            if (i >= 4) {
                return mip_jr_fail(jr, "more than 4 elements");
            }
            mip_jr_index(jr, i);
            if (mip_jr_f32(jr, ep, &out->q[i])) {
                return -1;
            }
        }
        mip_jr_index(jr, SIZE_MAX);
        if (i != 4) {
            return mip_jr_fail(jr, "expected 4 elements, got %zu", i);
        }
        mip_jr_pop(jr);
    }
    return 0;
}

/* ---- mip_sensor_cf_euler_angles_t */

static int mip_sensor_cf_euler_angles_read(mip_reader_t *r, mip_sensor_cf_euler_angles_t *out) {
    mip_rd_push(r, "roll");
    if (mip_rd_f32(r, &out->roll)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "pitch");
    if (mip_rd_f32(r, &out->pitch)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "yaw");
    if (mip_rd_f32(r, &out->yaw)) {
        return -1;
    }
    mip_rd_pop(r);
    return mip_rd_finish(r);
}

static mip_status_t mip_sensor_cf_euler_angles_write(mip_writer_t *w,
                                                     const mip_sensor_cf_euler_angles_t *in) {
    mip_status_t st;
    if ((st = mip_wr_f32(w, &in->roll)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_f32(w, &in->pitch)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_f32(w, &in->yaw)) != MIP_OK) {
        return st;
    }
    return MIP_OK;
}

mip_status_t mip_sensor_cf_euler_angles_encode(const mip_sensor_cf_euler_angles_t *value, uint8_t *buf,
                                               size_t cap, size_t *len_out) {
    mip_writer_t w;
    mip_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mip_writer_init(&w, buf, cap);
    st = mip_sensor_cf_euler_angles_write(&w, value);
    if (st == MIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 12 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mip_sensor_cf_euler_angles_load(const uint8_t *d, mip_sensor_cf_euler_angles_t *out) {
    out->roll = mip_ld_f32(d + 0);
    out->pitch = mip_ld_f32(d + 4);
    out->yaw = mip_ld_f32(d + 8);
    return 0;
}

/* The general reader: lengths other than 12, bad bool bytes, error details. */
static MIP_NOINLINE mip_status_t mip_sensor_cf_euler_angles_decode_read(const uint8_t *data, size_t len,
                                                                        mip_sensor_cf_euler_angles_t *out,
                                                                        mip_decode_error_t *err) {
    mip_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mip_sensor_cf_euler_angles_read(&r, out) ? MIP_ERR_DECODE : MIP_OK;
}

mip_status_t mip_sensor_cf_euler_angles_decode(const uint8_t *data, size_t len,
                                               mip_sensor_cf_euler_angles_t *out, mip_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 12 && mip_sensor_cf_euler_angles_load(data, out) == 0) {
        return MIP_OK;
    }
    return mip_sensor_cf_euler_angles_decode_read(data, len, out, err);
}

void mip_sensor_cf_euler_angles_to_json(mip_jw_t *w, const mip_sensor_cf_euler_angles_t *in) {
    int first = 1;
    mip_jw_raw(w, "{", 1);
    mip_jw_key(w, &first, "roll");
    mip_jw_f32(w, &in->roll);
    mip_jw_key(w, &first, "pitch");
    mip_jw_f32(w, &in->pitch);
    mip_jw_key(w, &first, "yaw");
    mip_jw_f32(w, &in->yaw);
    mip_jw_raw(w, "}", 1);
}

int mip_sensor_cf_euler_angles_from_json(mip_jr_t *jr, size_t pos, mip_sensor_cf_euler_angles_t *out) {
    static const char *const keys[] = {"roll", "pitch", "yaw"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mip_jr_object(jr, pos, keys, 3)) {
        return -1;
    }
    found = mip_jr_get(jr, pos, "roll", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"roll\"");
    }
    {
        mip_jr_push(jr, "roll");
        if (mip_jr_f32(jr, vp, &out->roll)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "pitch", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"pitch\"");
    }
    {
        mip_jr_push(jr, "pitch");
        if (mip_jr_f32(jr, vp, &out->pitch)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "yaw", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"yaw\"");
    }
    {
        mip_jr_push(jr, "yaw");
        if (mip_jr_f32(jr, vp, &out->yaw)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    return 0;
}

/* ---- mip_sensor_cf_stabilized_north_t */

static int mip_sensor_cf_stabilized_north_read(mip_reader_t *r, mip_sensor_cf_stabilized_north_t *out) {
    size_t i;
    mip_rd_push(r, "stabilized_north");
    for (i = 0; i < 3; i++) {
        mip_rd_index(r, i);
        if (mip_rd_f32(r, &out->stabilized_north[i])) {
            return -1;
        }
    }
    mip_rd_pop(r);
    return mip_rd_finish(r);
}

static mip_status_t mip_sensor_cf_stabilized_north_write(mip_writer_t *w,
                                                         const mip_sensor_cf_stabilized_north_t *in) {
    mip_status_t st;
    size_t i;
    for (i = 0; i < 3; i++) {
        if ((st = mip_wr_f32(w, &in->stabilized_north[i])) != MIP_OK) {
            return st;
        }
    }
    return MIP_OK;
}

mip_status_t mip_sensor_cf_stabilized_north_encode(const mip_sensor_cf_stabilized_north_t *value,
                                                   uint8_t *buf, size_t cap, size_t *len_out) {
    mip_writer_t w;
    mip_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mip_writer_init(&w, buf, cap);
    st = mip_sensor_cf_stabilized_north_write(&w, value);
    if (st == MIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 12 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mip_sensor_cf_stabilized_north_load(const uint8_t *d, mip_sensor_cf_stabilized_north_t *out) {
    out->stabilized_north[0] = mip_ld_f32(d + 0);
    out->stabilized_north[1] = mip_ld_f32(d + 4);
    out->stabilized_north[2] = mip_ld_f32(d + 8);
    return 0;
}

/* The general reader: lengths other than 12, bad bool bytes, error details. */
static MIP_NOINLINE mip_status_t mip_sensor_cf_stabilized_north_decode_read(
    const uint8_t *data, size_t len, mip_sensor_cf_stabilized_north_t *out, mip_decode_error_t *err) {
    mip_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mip_sensor_cf_stabilized_north_read(&r, out) ? MIP_ERR_DECODE : MIP_OK;
}

mip_status_t mip_sensor_cf_stabilized_north_decode(const uint8_t *data, size_t len,
                                                   mip_sensor_cf_stabilized_north_t *out,
                                                   mip_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 12 && mip_sensor_cf_stabilized_north_load(data, out) == 0) {
        return MIP_OK;
    }
    return mip_sensor_cf_stabilized_north_decode_read(data, len, out, err);
}

void mip_sensor_cf_stabilized_north_to_json(mip_jw_t *w, const mip_sensor_cf_stabilized_north_t *in) {
    int first = 1;
    size_t i;
    mip_jw_raw(w, "{", 1);
    mip_jw_key(w, &first, "stabilized_north");
    mip_jw_raw(w, "[", 1);
    for (i = 0; i < 3; i++) {
        mip_jw_sep(w, i);
        mip_jw_f32(w, &in->stabilized_north[i]);
    }
    mip_jw_raw(w, "]", 1);
    mip_jw_raw(w, "}", 1);
}

int mip_sensor_cf_stabilized_north_from_json(mip_jr_t *jr, size_t pos,
                                             mip_sensor_cf_stabilized_north_t *out) {
    static const char *const keys[] = {"stabilized_north"};
    size_t vp = 0;
    int found;
    size_t i;
    size_t it = 0;
    size_t ep = 0;
    memset(out, 0, sizeof *out);
    if (mip_jr_object(jr, pos, keys, 1)) {
        return -1;
    }
    found = mip_jr_get(jr, pos, "stabilized_north", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"stabilized_north\"");
    }
    {
        mip_jr_push(jr, "stabilized_north");
        if (mip_jr_array(jr, vp, &it)) {
            return -1;
        }
        for (i = 0;; i++) {
            int more = mip_jr_next(jr, &it, &ep);
            if (more < 0) {
                return -1;
            }
            if (!more) {
                break;
            }
            if (i >= 3) {
                return mip_jr_fail(jr, "more than 3 elements");
            }
            mip_jr_index(jr, i);
            if (mip_jr_f32(jr, ep, &out->stabilized_north[i])) {
                return -1;
            }
        }
        mip_jr_index(jr, SIZE_MAX);
        if (i != 3) {
            return mip_jr_fail(jr, "expected 3 elements, got %zu", i);
        }
        mip_jr_pop(jr);
    }
    return 0;
}

/* ---- mip_sensor_cf_stabilized_up_t */

static int mip_sensor_cf_stabilized_up_read(mip_reader_t *r, mip_sensor_cf_stabilized_up_t *out) {
    size_t i;
    mip_rd_push(r, "stabilized_up");
    for (i = 0; i < 3; i++) {
        mip_rd_index(r, i);
        if (mip_rd_f32(r, &out->stabilized_up[i])) {
            return -1;
        }
    }
    mip_rd_pop(r);
    return mip_rd_finish(r);
}

static mip_status_t mip_sensor_cf_stabilized_up_write(mip_writer_t *w,
                                                      const mip_sensor_cf_stabilized_up_t *in) {
    mip_status_t st;
    size_t i;
    for (i = 0; i < 3; i++) {
        if ((st = mip_wr_f32(w, &in->stabilized_up[i])) != MIP_OK) {
            return st;
        }
    }
    return MIP_OK;
}

mip_status_t mip_sensor_cf_stabilized_up_encode(const mip_sensor_cf_stabilized_up_t *value, uint8_t *buf,
                                                size_t cap, size_t *len_out) {
    mip_writer_t w;
    mip_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mip_writer_init(&w, buf, cap);
    st = mip_sensor_cf_stabilized_up_write(&w, value);
    if (st == MIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 12 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mip_sensor_cf_stabilized_up_load(const uint8_t *d, mip_sensor_cf_stabilized_up_t *out) {
    out->stabilized_up[0] = mip_ld_f32(d + 0);
    out->stabilized_up[1] = mip_ld_f32(d + 4);
    out->stabilized_up[2] = mip_ld_f32(d + 8);
    return 0;
}

/* The general reader: lengths other than 12, bad bool bytes, error details. */
static MIP_NOINLINE mip_status_t mip_sensor_cf_stabilized_up_decode_read(const uint8_t *data, size_t len,
                                                                         mip_sensor_cf_stabilized_up_t *out,
                                                                         mip_decode_error_t *err) {
    mip_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mip_sensor_cf_stabilized_up_read(&r, out) ? MIP_ERR_DECODE : MIP_OK;
}

mip_status_t mip_sensor_cf_stabilized_up_decode(const uint8_t *data, size_t len,
                                                mip_sensor_cf_stabilized_up_t *out, mip_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 12 && mip_sensor_cf_stabilized_up_load(data, out) == 0) {
        return MIP_OK;
    }
    return mip_sensor_cf_stabilized_up_decode_read(data, len, out, err);
}

void mip_sensor_cf_stabilized_up_to_json(mip_jw_t *w, const mip_sensor_cf_stabilized_up_t *in) {
    int first = 1;
    size_t i;
    mip_jw_raw(w, "{", 1);
    mip_jw_key(w, &first, "stabilized_up");
    mip_jw_raw(w, "[", 1);
    for (i = 0; i < 3; i++) {
        mip_jw_sep(w, i);
        mip_jw_f32(w, &in->stabilized_up[i]);
    }
    mip_jw_raw(w, "]", 1);
    mip_jw_raw(w, "}", 1);
}

int mip_sensor_cf_stabilized_up_from_json(mip_jr_t *jr, size_t pos, mip_sensor_cf_stabilized_up_t *out) {
    static const char *const keys[] = {"stabilized_up"};
    size_t vp = 0;
    int found;
    size_t i;
    size_t it = 0;
    size_t ep = 0;
    memset(out, 0, sizeof *out);
    if (mip_jr_object(jr, pos, keys, 1)) {
        return -1;
    }
    found = mip_jr_get(jr, pos, "stabilized_up", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"stabilized_up\"");
    }
    {
        mip_jr_push(jr, "stabilized_up");
        if (mip_jr_array(jr, vp, &it)) {
            return -1;
        }
        for (i = 0;; i++) {
            int more = mip_jr_next(jr, &it, &ep);
            if (more < 0) {
                return -1;
            }
            if (!more) {
                break;
            }
            if (i >= 3) {
                return mip_jr_fail(jr, "more than 3 elements");
            }
            mip_jr_index(jr, i);
            if (mip_jr_f32(jr, ep, &out->stabilized_up[i])) {
                return -1;
            }
        }
        mip_jr_index(jr, SIZE_MAX);
        if (i != 3) {
            return mip_jr_fail(jr, "expected 3 elements, got %zu", i);
        }
        mip_jr_pop(jr);
    }
    return 0;
}

/* ---- mip_sensor_gps_timestamp_t */

static int mip_sensor_gps_timestamp_read(mip_reader_t *r, mip_sensor_gps_timestamp_t *out) {
    mip_rd_push(r, "tow");
    if (mip_rd_f64(r, &out->tow)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "week_number");
    if (mip_rd_u16(r, &out->week_number)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "valid_flags");
    if (mip_rd_u16(r, &out->valid_flags)) {
        return -1;
    }
    mip_rd_pop(r);
    return mip_rd_finish(r);
}

static mip_status_t mip_sensor_gps_timestamp_write(mip_writer_t *w, const mip_sensor_gps_timestamp_t *in) {
    mip_status_t st;
    if ((st = mip_wr_f64(w, &in->tow)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_u16(w, &in->week_number)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_u16(w, &in->valid_flags)) != MIP_OK) {
        return st;
    }
    return MIP_OK;
}

mip_status_t mip_sensor_gps_timestamp_encode(const mip_sensor_gps_timestamp_t *value, uint8_t *buf,
                                             size_t cap, size_t *len_out) {
    mip_writer_t w;
    mip_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mip_writer_init(&w, buf, cap);
    st = mip_sensor_gps_timestamp_write(&w, value);
    if (st == MIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 12 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mip_sensor_gps_timestamp_load(const uint8_t *d, mip_sensor_gps_timestamp_t *out) {
    out->tow = mip_ld_f64(d + 0);
    out->week_number = mip_ld_u16(d + 8);
    out->valid_flags = mip_ld_u16(d + 10);
    return 0;
}

/* The general reader: lengths other than 12, bad bool bytes, error details. */
static MIP_NOINLINE mip_status_t mip_sensor_gps_timestamp_decode_read(const uint8_t *data, size_t len,
                                                                      mip_sensor_gps_timestamp_t *out,
                                                                      mip_decode_error_t *err) {
    mip_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mip_sensor_gps_timestamp_read(&r, out) ? MIP_ERR_DECODE : MIP_OK;
}

mip_status_t mip_sensor_gps_timestamp_decode(const uint8_t *data, size_t len, mip_sensor_gps_timestamp_t *out,
                                             mip_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 12 && mip_sensor_gps_timestamp_load(data, out) == 0) {
        return MIP_OK;
    }
    return mip_sensor_gps_timestamp_decode_read(data, len, out, err);
}

void mip_sensor_gps_timestamp_to_json(mip_jw_t *w, const mip_sensor_gps_timestamp_t *in) {
    int first = 1;
    mip_jw_raw(w, "{", 1);
    mip_jw_key(w, &first, "tow");
    mip_jw_f64(w, &in->tow);
    mip_jw_key(w, &first, "week_number");
    mip_jw_u16(w, &in->week_number);
    mip_jw_key(w, &first, "valid_flags");
    mip_jw_u16(w, &in->valid_flags);
    mip_jw_raw(w, "}", 1);
}

int mip_sensor_gps_timestamp_from_json(mip_jr_t *jr, size_t pos, mip_sensor_gps_timestamp_t *out) {
    static const char *const keys[] = {"tow", "week_number", "valid_flags"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mip_jr_object(jr, pos, keys, 3)) {
        return -1;
    }
    found = mip_jr_get(jr, pos, "tow", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"tow\"");
    }
    {
        mip_jr_push(jr, "tow");
        if (mip_jr_f64(jr, vp, &out->tow)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "week_number", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"week_number\"");
    }
    {
        mip_jr_push(jr, "week_number");
        if (mip_jr_u16(jr, vp, &out->week_number)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "valid_flags", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"valid_flags\"");
    }
    {
        mip_jr_push(jr, "valid_flags");
        if (mip_jr_u16(jr, vp, &out->valid_flags)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    return 0;
}

/* ---- mip_sensor_temperature_statistics_t */

static int mip_sensor_temperature_statistics_read(mip_reader_t *r, mip_sensor_temperature_statistics_t *out) {
    mip_rd_push(r, "min_temp");
    if (mip_rd_f32(r, &out->min_temp)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "max_temp");
    if (mip_rd_f32(r, &out->max_temp)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "mean_temp");
    if (mip_rd_f32(r, &out->mean_temp)) {
        return -1;
    }
    mip_rd_pop(r);
    return mip_rd_finish(r);
}

static mip_status_t mip_sensor_temperature_statistics_write(mip_writer_t *w,
                                                            const mip_sensor_temperature_statistics_t *in) {
    mip_status_t st;
    if ((st = mip_wr_f32(w, &in->min_temp)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_f32(w, &in->max_temp)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_f32(w, &in->mean_temp)) != MIP_OK) {
        return st;
    }
    return MIP_OK;
}

mip_status_t mip_sensor_temperature_statistics_encode(const mip_sensor_temperature_statistics_t *value,
                                                      uint8_t *buf, size_t cap, size_t *len_out) {
    mip_writer_t w;
    mip_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mip_writer_init(&w, buf, cap);
    st = mip_sensor_temperature_statistics_write(&w, value);
    if (st == MIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 12 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mip_sensor_temperature_statistics_load(const uint8_t *d,
                                                  mip_sensor_temperature_statistics_t *out) {
    out->min_temp = mip_ld_f32(d + 0);
    out->max_temp = mip_ld_f32(d + 4);
    out->mean_temp = mip_ld_f32(d + 8);
    return 0;
}

/* The general reader: lengths other than 12, bad bool bytes, error details. */
static MIP_NOINLINE mip_status_t mip_sensor_temperature_statistics_decode_read(
    const uint8_t *data, size_t len, mip_sensor_temperature_statistics_t *out, mip_decode_error_t *err) {
    mip_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mip_sensor_temperature_statistics_read(&r, out) ? MIP_ERR_DECODE : MIP_OK;
}

mip_status_t mip_sensor_temperature_statistics_decode(const uint8_t *data, size_t len,
                                                      mip_sensor_temperature_statistics_t *out,
                                                      mip_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 12 && mip_sensor_temperature_statistics_load(data, out) == 0) {
        return MIP_OK;
    }
    return mip_sensor_temperature_statistics_decode_read(data, len, out, err);
}

void mip_sensor_temperature_statistics_to_json(mip_jw_t *w, const mip_sensor_temperature_statistics_t *in) {
    int first = 1;
    mip_jw_raw(w, "{", 1);
    mip_jw_key(w, &first, "min_temp");
    mip_jw_f32(w, &in->min_temp);
    mip_jw_key(w, &first, "max_temp");
    mip_jw_f32(w, &in->max_temp);
    mip_jw_key(w, &first, "mean_temp");
    mip_jw_f32(w, &in->mean_temp);
    mip_jw_raw(w, "}", 1);
}

int mip_sensor_temperature_statistics_from_json(mip_jr_t *jr, size_t pos,
                                                mip_sensor_temperature_statistics_t *out) {
    static const char *const keys[] = {"min_temp", "max_temp", "mean_temp"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mip_jr_object(jr, pos, keys, 3)) {
        return -1;
    }
    found = mip_jr_get(jr, pos, "min_temp", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"min_temp\"");
    }
    {
        mip_jr_push(jr, "min_temp");
        if (mip_jr_f32(jr, vp, &out->min_temp)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "max_temp", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"max_temp\"");
    }
    {
        mip_jr_push(jr, "max_temp");
        if (mip_jr_f32(jr, vp, &out->max_temp)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "mean_temp", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"mean_temp\"");
    }
    {
        mip_jr_push(jr, "mean_temp");
        if (mip_jr_f32(jr, vp, &out->mean_temp)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    return 0;
}

/* ---- mip_sensor_scaled_pressure_t */

static int mip_sensor_scaled_pressure_read(mip_reader_t *r, mip_sensor_scaled_pressure_t *out) {
    mip_rd_push(r, "scaled_pressure");
    if (mip_rd_f32(r, &out->scaled_pressure)) {
        return -1;
    }
    mip_rd_pop(r);
    return mip_rd_finish(r);
}

static mip_status_t mip_sensor_scaled_pressure_write(mip_writer_t *w,
                                                     const mip_sensor_scaled_pressure_t *in) {
    mip_status_t st;
    if ((st = mip_wr_f32(w, &in->scaled_pressure)) != MIP_OK) {
        return st;
    }
    return MIP_OK;
}

mip_status_t mip_sensor_scaled_pressure_encode(const mip_sensor_scaled_pressure_t *value, uint8_t *buf,
                                               size_t cap, size_t *len_out) {
    mip_writer_t w;
    mip_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mip_writer_init(&w, buf, cap);
    st = mip_sensor_scaled_pressure_write(&w, value);
    if (st == MIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 4 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mip_sensor_scaled_pressure_load(const uint8_t *d, mip_sensor_scaled_pressure_t *out) {
    out->scaled_pressure = mip_ld_f32(d + 0);
    return 0;
}

/* The general reader: lengths other than 4, bad bool bytes, error details. */
static MIP_NOINLINE mip_status_t mip_sensor_scaled_pressure_decode_read(const uint8_t *data, size_t len,
                                                                        mip_sensor_scaled_pressure_t *out,
                                                                        mip_decode_error_t *err) {
    mip_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mip_sensor_scaled_pressure_read(&r, out) ? MIP_ERR_DECODE : MIP_OK;
}

mip_status_t mip_sensor_scaled_pressure_decode(const uint8_t *data, size_t len,
                                               mip_sensor_scaled_pressure_t *out, mip_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 4 && mip_sensor_scaled_pressure_load(data, out) == 0) {
        return MIP_OK;
    }
    return mip_sensor_scaled_pressure_decode_read(data, len, out, err);
}

void mip_sensor_scaled_pressure_to_json(mip_jw_t *w, const mip_sensor_scaled_pressure_t *in) {
    int first = 1;
    mip_jw_raw(w, "{", 1);
    mip_jw_key(w, &first, "scaled_pressure");
    mip_jw_f32(w, &in->scaled_pressure);
    mip_jw_raw(w, "}", 1);
}

int mip_sensor_scaled_pressure_from_json(mip_jr_t *jr, size_t pos, mip_sensor_scaled_pressure_t *out) {
    static const char *const keys[] = {"scaled_pressure"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mip_jr_object(jr, pos, keys, 1)) {
        return -1;
    }
    found = mip_jr_get(jr, pos, "scaled_pressure", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"scaled_pressure\"");
    }
    {
        mip_jr_push(jr, "scaled_pressure");
        if (mip_jr_f32(jr, vp, &out->scaled_pressure)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    return 0;
}

/* ---- mip_sensor_overrange_status_t */

static int mip_sensor_overrange_status_read(mip_reader_t *r, mip_sensor_overrange_status_t *out) {
    mip_rd_push(r, "status");
    if (mip_rd_u16(r, &out->status)) {
        return -1;
    }
    mip_rd_pop(r);
    return mip_rd_finish(r);
}

static mip_status_t mip_sensor_overrange_status_write(mip_writer_t *w,
                                                      const mip_sensor_overrange_status_t *in) {
    mip_status_t st;
    if ((st = mip_wr_u16(w, &in->status)) != MIP_OK) {
        return st;
    }
    return MIP_OK;
}

mip_status_t mip_sensor_overrange_status_encode(const mip_sensor_overrange_status_t *value, uint8_t *buf,
                                                size_t cap, size_t *len_out) {
    mip_writer_t w;
    mip_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mip_writer_init(&w, buf, cap);
    st = mip_sensor_overrange_status_write(&w, value);
    if (st == MIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 2 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mip_sensor_overrange_status_load(const uint8_t *d, mip_sensor_overrange_status_t *out) {
    out->status = mip_ld_u16(d + 0);
    return 0;
}

/* The general reader: lengths other than 2, bad bool bytes, error details. */
static MIP_NOINLINE mip_status_t mip_sensor_overrange_status_decode_read(const uint8_t *data, size_t len,
                                                                         mip_sensor_overrange_status_t *out,
                                                                         mip_decode_error_t *err) {
    mip_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mip_sensor_overrange_status_read(&r, out) ? MIP_ERR_DECODE : MIP_OK;
}

mip_status_t mip_sensor_overrange_status_decode(const uint8_t *data, size_t len,
                                                mip_sensor_overrange_status_t *out, mip_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 2 && mip_sensor_overrange_status_load(data, out) == 0) {
        return MIP_OK;
    }
    return mip_sensor_overrange_status_decode_read(data, len, out, err);
}

void mip_sensor_overrange_status_to_json(mip_jw_t *w, const mip_sensor_overrange_status_t *in) {
    int first = 1;
    mip_jw_raw(w, "{", 1);
    mip_jw_key(w, &first, "status");
    mip_jw_u16(w, &in->status);
    mip_jw_raw(w, "}", 1);
}

int mip_sensor_overrange_status_from_json(mip_jr_t *jr, size_t pos, mip_sensor_overrange_status_t *out) {
    static const char *const keys[] = {"status"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mip_jr_object(jr, pos, keys, 1)) {
        return -1;
    }
    found = mip_jr_get(jr, pos, "status", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"status\"");
    }
    {
        mip_jr_push(jr, "status");
        if (mip_jr_u16(jr, vp, &out->status)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    return 0;
}

/* ---- mip_sensor_odometer_data_t */

static int mip_sensor_odometer_data_read(mip_reader_t *r, mip_sensor_odometer_data_t *out) {
    mip_rd_push(r, "speed");
    if (mip_rd_f32(r, &out->speed)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "uncertainty");
    if (mip_rd_f32(r, &out->uncertainty)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "valid_flags");
    if (mip_rd_u16(r, &out->valid_flags)) {
        return -1;
    }
    mip_rd_pop(r);
    return mip_rd_finish(r);
}

static mip_status_t mip_sensor_odometer_data_write(mip_writer_t *w, const mip_sensor_odometer_data_t *in) {
    mip_status_t st;
    if ((st = mip_wr_f32(w, &in->speed)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_f32(w, &in->uncertainty)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_u16(w, &in->valid_flags)) != MIP_OK) {
        return st;
    }
    return MIP_OK;
}

mip_status_t mip_sensor_odometer_data_encode(const mip_sensor_odometer_data_t *value, uint8_t *buf,
                                             size_t cap, size_t *len_out) {
    mip_writer_t w;
    mip_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mip_writer_init(&w, buf, cap);
    st = mip_sensor_odometer_data_write(&w, value);
    if (st == MIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 10 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mip_sensor_odometer_data_load(const uint8_t *d, mip_sensor_odometer_data_t *out) {
    out->speed = mip_ld_f32(d + 0);
    out->uncertainty = mip_ld_f32(d + 4);
    out->valid_flags = mip_ld_u16(d + 8);
    return 0;
}

/* The general reader: lengths other than 10, bad bool bytes, error details. */
static MIP_NOINLINE mip_status_t mip_sensor_odometer_data_decode_read(const uint8_t *data, size_t len,
                                                                      mip_sensor_odometer_data_t *out,
                                                                      mip_decode_error_t *err) {
    mip_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mip_sensor_odometer_data_read(&r, out) ? MIP_ERR_DECODE : MIP_OK;
}

mip_status_t mip_sensor_odometer_data_decode(const uint8_t *data, size_t len, mip_sensor_odometer_data_t *out,
                                             mip_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 10 && mip_sensor_odometer_data_load(data, out) == 0) {
        return MIP_OK;
    }
    return mip_sensor_odometer_data_decode_read(data, len, out, err);
}

void mip_sensor_odometer_data_to_json(mip_jw_t *w, const mip_sensor_odometer_data_t *in) {
    int first = 1;
    mip_jw_raw(w, "{", 1);
    mip_jw_key(w, &first, "speed");
    mip_jw_f32(w, &in->speed);
    mip_jw_key(w, &first, "uncertainty");
    mip_jw_f32(w, &in->uncertainty);
    mip_jw_key(w, &first, "valid_flags");
    mip_jw_u16(w, &in->valid_flags);
    mip_jw_raw(w, "}", 1);
}

int mip_sensor_odometer_data_from_json(mip_jr_t *jr, size_t pos, mip_sensor_odometer_data_t *out) {
    static const char *const keys[] = {"speed", "uncertainty", "valid_flags"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mip_jr_object(jr, pos, keys, 3)) {
        return -1;
    }
    found = mip_jr_get(jr, pos, "speed", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"speed\"");
    }
    {
        mip_jr_push(jr, "speed");
        if (mip_jr_f32(jr, vp, &out->speed)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "uncertainty", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"uncertainty\"");
    }
    {
        mip_jr_push(jr, "uncertainty");
        if (mip_jr_f32(jr, vp, &out->uncertainty)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "valid_flags", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"valid_flags\"");
    }
    {
        mip_jr_push(jr, "valid_flags");
        if (mip_jr_u16(jr, vp, &out->valid_flags)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    return 0;
}
