/* Encoders and decoders of IMU Data Message. Generated from the spec: do not edit. */
#include "mscipcodec/sets/imu_data.h"
#include "layouts_internal.h"
#include "types_internal.h"

#include <assert.h>
#include <string.h>

/* ---- mscip_imu_data_scaled_accel_t */

static int mscip_imu_data_scaled_accel_read(mscip_reader_t *r, mscip_imu_data_scaled_accel_t *out) {
    size_t i;
    mscip_rd_push(r, "accel");
    for (i = 0; i < 3; i++) {
        mscip_rd_index(r, i);
        if (mscip_rd_f32(r, &out->accel[i])) {
            return -1;
        }
    }
    mscip_rd_pop(r);
    return mscip_rd_finish(r);
}

static mscip_status_t mscip_imu_data_scaled_accel_write(mscip_writer_t *w,
                                                        const mscip_imu_data_scaled_accel_t *in) {
    mscip_status_t st;
    size_t i;
    for (i = 0; i < 3; i++) {
        if ((st = mscip_wr_f32(w, &in->accel[i])) != MSCIP_OK) {
            return st;
        }
    }
    return MSCIP_OK;
}

mscip_status_t mscip_imu_data_scaled_accel_encode(const mscip_imu_data_scaled_accel_t *value, uint8_t *buf,
                                                  size_t cap, size_t *len_out) {
    mscip_writer_t w;
    mscip_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mscip_writer_init(&w, buf, cap);
    st = mscip_imu_data_scaled_accel_write(&w, value);
    if (st == MSCIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 12 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mscip_imu_data_scaled_accel_load(const uint8_t *d, mscip_imu_data_scaled_accel_t *out) {
    out->accel[0] = mscip_ld_f32(d + 0);
    out->accel[1] = mscip_ld_f32(d + 4);
    out->accel[2] = mscip_ld_f32(d + 8);
    return 0;
}

/* The general reader: lengths other than 12, bad bool bytes, error details. */
static MSCIP_NOINLINE mscip_status_t mscip_imu_data_scaled_accel_decode_read(
    const uint8_t *data, size_t len, mscip_imu_data_scaled_accel_t *out, mscip_decode_error_t *err) {
    mscip_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mscip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mscip_imu_data_scaled_accel_read(&r, out) ? MSCIP_ERR_DECODE : MSCIP_OK;
}

mscip_status_t mscip_imu_data_scaled_accel_decode(const uint8_t *data, size_t len,
                                                  mscip_imu_data_scaled_accel_t *out,
                                                  mscip_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 12 && mscip_imu_data_scaled_accel_load(data, out) == 0) {
        return MSCIP_OK;
    }
    return mscip_imu_data_scaled_accel_decode_read(data, len, out, err);
}

void mscip_imu_data_scaled_accel_to_json(mscip_jw_t *w, const mscip_imu_data_scaled_accel_t *in) {
    int first = 1;
    size_t i;
    mscip_jw_raw(w, "{", 1);
    mscip_jw_key(w, &first, "accel");
    mscip_jw_raw(w, "[", 1);
    for (i = 0; i < 3; i++) {
        mscip_jw_sep(w, i);
        mscip_jw_f32(w, &in->accel[i]);
    }
    mscip_jw_raw(w, "]", 1);
    mscip_jw_raw(w, "}", 1);
}

int mscip_imu_data_scaled_accel_from_json(mscip_jr_t *jr, size_t pos, mscip_imu_data_scaled_accel_t *out) {
    static const char *const keys[] = {"accel"};
    size_t vp = 0;
    int found;
    size_t i;
    size_t it = 0;
    size_t ep = 0;
    memset(out, 0, sizeof *out);
    if (mscip_jr_object(jr, pos, keys, 1)) {
        return -1;
    }
    found = mscip_jr_get(jr, pos, "accel", &vp);
    if (found != 1) {
        return mscip_jr_fail(jr, "missing parameter \"accel\"");
    }
    {
        mscip_jr_push(jr, "accel");
        if (mscip_jr_array(jr, vp, &it)) {
            return -1;
        }
        for (i = 0;; i++) {
            int more = mscip_jr_next(jr, &it, &ep);
            if (more < 0) {
                return -1;
            }
            if (!more) {
                break;
            }
            if (i >= 3) {
                return mscip_jr_fail(jr, "more than 3 elements");
            }
            mscip_jr_index(jr, i);
            if (mscip_jr_f32(jr, ep, &out->accel[i])) {
                return -1;
            }
        }
        mscip_jr_index(jr, SIZE_MAX);
        if (i != 3) {
            return mscip_jr_fail(jr, "expected 3 elements, got %zu", i);
        }
        mscip_jr_pop(jr);
    }
    return 0;
}

/* ---- mscip_imu_data_scaled_gyro_t */

static int mscip_imu_data_scaled_gyro_read(mscip_reader_t *r, mscip_imu_data_scaled_gyro_t *out) {
    size_t i;
    mscip_rd_push(r, "gyro");
    for (i = 0; i < 3; i++) {
        mscip_rd_index(r, i);
        if (mscip_rd_f32(r, &out->gyro[i])) {
            return -1;
        }
    }
    mscip_rd_pop(r);
    return mscip_rd_finish(r);
}

static mscip_status_t mscip_imu_data_scaled_gyro_write(mscip_writer_t *w,
                                                       const mscip_imu_data_scaled_gyro_t *in) {
    mscip_status_t st;
    size_t i;
    for (i = 0; i < 3; i++) {
        if ((st = mscip_wr_f32(w, &in->gyro[i])) != MSCIP_OK) {
            return st;
        }
    }
    return MSCIP_OK;
}

mscip_status_t mscip_imu_data_scaled_gyro_encode(const mscip_imu_data_scaled_gyro_t *value, uint8_t *buf,
                                                 size_t cap, size_t *len_out) {
    mscip_writer_t w;
    mscip_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mscip_writer_init(&w, buf, cap);
    st = mscip_imu_data_scaled_gyro_write(&w, value);
    if (st == MSCIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 12 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mscip_imu_data_scaled_gyro_load(const uint8_t *d, mscip_imu_data_scaled_gyro_t *out) {
    out->gyro[0] = mscip_ld_f32(d + 0);
    out->gyro[1] = mscip_ld_f32(d + 4);
    out->gyro[2] = mscip_ld_f32(d + 8);
    return 0;
}

/* The general reader: lengths other than 12, bad bool bytes, error details. */
static MSCIP_NOINLINE mscip_status_t mscip_imu_data_scaled_gyro_decode_read(const uint8_t *data, size_t len,
                                                                            mscip_imu_data_scaled_gyro_t *out,
                                                                            mscip_decode_error_t *err) {
    mscip_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mscip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mscip_imu_data_scaled_gyro_read(&r, out) ? MSCIP_ERR_DECODE : MSCIP_OK;
}

mscip_status_t mscip_imu_data_scaled_gyro_decode(const uint8_t *data, size_t len,
                                                 mscip_imu_data_scaled_gyro_t *out,
                                                 mscip_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 12 && mscip_imu_data_scaled_gyro_load(data, out) == 0) {
        return MSCIP_OK;
    }
    return mscip_imu_data_scaled_gyro_decode_read(data, len, out, err);
}

void mscip_imu_data_scaled_gyro_to_json(mscip_jw_t *w, const mscip_imu_data_scaled_gyro_t *in) {
    int first = 1;
    size_t i;
    mscip_jw_raw(w, "{", 1);
    mscip_jw_key(w, &first, "gyro");
    mscip_jw_raw(w, "[", 1);
    for (i = 0; i < 3; i++) {
        mscip_jw_sep(w, i);
        mscip_jw_f32(w, &in->gyro[i]);
    }
    mscip_jw_raw(w, "]", 1);
    mscip_jw_raw(w, "}", 1);
}

int mscip_imu_data_scaled_gyro_from_json(mscip_jr_t *jr, size_t pos, mscip_imu_data_scaled_gyro_t *out) {
    static const char *const keys[] = {"gyro"};
    size_t vp = 0;
    int found;
    size_t i;
    size_t it = 0;
    size_t ep = 0;
    memset(out, 0, sizeof *out);
    if (mscip_jr_object(jr, pos, keys, 1)) {
        return -1;
    }
    found = mscip_jr_get(jr, pos, "gyro", &vp);
    if (found != 1) {
        return mscip_jr_fail(jr, "missing parameter \"gyro\"");
    }
    {
        mscip_jr_push(jr, "gyro");
        if (mscip_jr_array(jr, vp, &it)) {
            return -1;
        }
        for (i = 0;; i++) {
            int more = mscip_jr_next(jr, &it, &ep);
            if (more < 0) {
                return -1;
            }
            if (!more) {
                break;
            }
            if (i >= 3) {
                return mscip_jr_fail(jr, "more than 3 elements");
            }
            mscip_jr_index(jr, i);
            if (mscip_jr_f32(jr, ep, &out->gyro[i])) {
                return -1;
            }
        }
        mscip_jr_index(jr, SIZE_MAX);
        if (i != 3) {
            return mscip_jr_fail(jr, "expected 3 elements, got %zu", i);
        }
        mscip_jr_pop(jr);
    }
    return 0;
}

/* ---- mscip_imu_data_scaled_mag_t */

static int mscip_imu_data_scaled_mag_read(mscip_reader_t *r, mscip_imu_data_scaled_mag_t *out) {
    size_t i;
    mscip_rd_push(r, "mag");
    for (i = 0; i < 3; i++) {
        mscip_rd_index(r, i);
        if (mscip_rd_f32(r, &out->mag[i])) {
            return -1;
        }
    }
    mscip_rd_pop(r);
    return mscip_rd_finish(r);
}

static mscip_status_t mscip_imu_data_scaled_mag_write(mscip_writer_t *w,
                                                      const mscip_imu_data_scaled_mag_t *in) {
    mscip_status_t st;
    size_t i;
    for (i = 0; i < 3; i++) {
        if ((st = mscip_wr_f32(w, &in->mag[i])) != MSCIP_OK) {
            return st;
        }
    }
    return MSCIP_OK;
}

mscip_status_t mscip_imu_data_scaled_mag_encode(const mscip_imu_data_scaled_mag_t *value, uint8_t *buf,
                                                size_t cap, size_t *len_out) {
    mscip_writer_t w;
    mscip_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mscip_writer_init(&w, buf, cap);
    st = mscip_imu_data_scaled_mag_write(&w, value);
    if (st == MSCIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 12 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mscip_imu_data_scaled_mag_load(const uint8_t *d, mscip_imu_data_scaled_mag_t *out) {
    out->mag[0] = mscip_ld_f32(d + 0);
    out->mag[1] = mscip_ld_f32(d + 4);
    out->mag[2] = mscip_ld_f32(d + 8);
    return 0;
}

/* The general reader: lengths other than 12, bad bool bytes, error details. */
static MSCIP_NOINLINE mscip_status_t mscip_imu_data_scaled_mag_decode_read(const uint8_t *data, size_t len,
                                                                           mscip_imu_data_scaled_mag_t *out,
                                                                           mscip_decode_error_t *err) {
    mscip_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mscip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mscip_imu_data_scaled_mag_read(&r, out) ? MSCIP_ERR_DECODE : MSCIP_OK;
}

mscip_status_t mscip_imu_data_scaled_mag_decode(const uint8_t *data, size_t len,
                                                mscip_imu_data_scaled_mag_t *out, mscip_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 12 && mscip_imu_data_scaled_mag_load(data, out) == 0) {
        return MSCIP_OK;
    }
    return mscip_imu_data_scaled_mag_decode_read(data, len, out, err);
}

void mscip_imu_data_scaled_mag_to_json(mscip_jw_t *w, const mscip_imu_data_scaled_mag_t *in) {
    int first = 1;
    size_t i;
    mscip_jw_raw(w, "{", 1);
    mscip_jw_key(w, &first, "mag");
    mscip_jw_raw(w, "[", 1);
    for (i = 0; i < 3; i++) {
        mscip_jw_sep(w, i);
        mscip_jw_f32(w, &in->mag[i]);
    }
    mscip_jw_raw(w, "]", 1);
    mscip_jw_raw(w, "}", 1);
}

int mscip_imu_data_scaled_mag_from_json(mscip_jr_t *jr, size_t pos, mscip_imu_data_scaled_mag_t *out) {
    static const char *const keys[] = {"mag"};
    size_t vp = 0;
    int found;
    size_t i;
    size_t it = 0;
    size_t ep = 0;
    memset(out, 0, sizeof *out);
    if (mscip_jr_object(jr, pos, keys, 1)) {
        return -1;
    }
    found = mscip_jr_get(jr, pos, "mag", &vp);
    if (found != 1) {
        return mscip_jr_fail(jr, "missing parameter \"mag\"");
    }
    {
        mscip_jr_push(jr, "mag");
        if (mscip_jr_array(jr, vp, &it)) {
            return -1;
        }
        for (i = 0;; i++) {
            int more = mscip_jr_next(jr, &it, &ep);
            if (more < 0) {
                return -1;
            }
            if (!more) {
                break;
            }
            if (i >= 3) {
                return mscip_jr_fail(jr, "more than 3 elements");
            }
            mscip_jr_index(jr, i);
            if (mscip_jr_f32(jr, ep, &out->mag[i])) {
                return -1;
            }
        }
        mscip_jr_index(jr, SIZE_MAX);
        if (i != 3) {
            return mscip_jr_fail(jr, "expected 3 elements, got %zu", i);
        }
        mscip_jr_pop(jr);
    }
    return 0;
}

/* ---- mscip_imu_data_delta_theta_t */

static int mscip_imu_data_delta_theta_read(mscip_reader_t *r, mscip_imu_data_delta_theta_t *out) {
    size_t i;
    mscip_rd_push(r, "delta_theta");
    for (i = 0; i < 3; i++) {
        mscip_rd_index(r, i);
        if (mscip_rd_f32(r, &out->delta_theta[i])) {
            return -1;
        }
    }
    mscip_rd_pop(r);
    return mscip_rd_finish(r);
}

static mscip_status_t mscip_imu_data_delta_theta_write(mscip_writer_t *w,
                                                       const mscip_imu_data_delta_theta_t *in) {
    mscip_status_t st;
    size_t i;
    for (i = 0; i < 3; i++) {
        if ((st = mscip_wr_f32(w, &in->delta_theta[i])) != MSCIP_OK) {
            return st;
        }
    }
    return MSCIP_OK;
}

mscip_status_t mscip_imu_data_delta_theta_encode(const mscip_imu_data_delta_theta_t *value, uint8_t *buf,
                                                 size_t cap, size_t *len_out) {
    mscip_writer_t w;
    mscip_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mscip_writer_init(&w, buf, cap);
    st = mscip_imu_data_delta_theta_write(&w, value);
    if (st == MSCIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 12 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mscip_imu_data_delta_theta_load(const uint8_t *d, mscip_imu_data_delta_theta_t *out) {
    out->delta_theta[0] = mscip_ld_f32(d + 0);
    out->delta_theta[1] = mscip_ld_f32(d + 4);
    out->delta_theta[2] = mscip_ld_f32(d + 8);
    return 0;
}

/* The general reader: lengths other than 12, bad bool bytes, error details. */
static MSCIP_NOINLINE mscip_status_t mscip_imu_data_delta_theta_decode_read(const uint8_t *data, size_t len,
                                                                            mscip_imu_data_delta_theta_t *out,
                                                                            mscip_decode_error_t *err) {
    mscip_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mscip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mscip_imu_data_delta_theta_read(&r, out) ? MSCIP_ERR_DECODE : MSCIP_OK;
}

mscip_status_t mscip_imu_data_delta_theta_decode(const uint8_t *data, size_t len,
                                                 mscip_imu_data_delta_theta_t *out,
                                                 mscip_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 12 && mscip_imu_data_delta_theta_load(data, out) == 0) {
        return MSCIP_OK;
    }
    return mscip_imu_data_delta_theta_decode_read(data, len, out, err);
}

void mscip_imu_data_delta_theta_to_json(mscip_jw_t *w, const mscip_imu_data_delta_theta_t *in) {
    int first = 1;
    size_t i;
    mscip_jw_raw(w, "{", 1);
    mscip_jw_key(w, &first, "delta_theta");
    mscip_jw_raw(w, "[", 1);
    for (i = 0; i < 3; i++) {
        mscip_jw_sep(w, i);
        mscip_jw_f32(w, &in->delta_theta[i]);
    }
    mscip_jw_raw(w, "]", 1);
    mscip_jw_raw(w, "}", 1);
}

int mscip_imu_data_delta_theta_from_json(mscip_jr_t *jr, size_t pos, mscip_imu_data_delta_theta_t *out) {
    static const char *const keys[] = {"delta_theta"};
    size_t vp = 0;
    int found;
    size_t i;
    size_t it = 0;
    size_t ep = 0;
    memset(out, 0, sizeof *out);
    if (mscip_jr_object(jr, pos, keys, 1)) {
        return -1;
    }
    found = mscip_jr_get(jr, pos, "delta_theta", &vp);
    if (found != 1) {
        return mscip_jr_fail(jr, "missing parameter \"delta_theta\"");
    }
    {
        mscip_jr_push(jr, "delta_theta");
        if (mscip_jr_array(jr, vp, &it)) {
            return -1;
        }
        for (i = 0;; i++) {
            int more = mscip_jr_next(jr, &it, &ep);
            if (more < 0) {
                return -1;
            }
            if (!more) {
                break;
            }
            if (i >= 3) {
                return mscip_jr_fail(jr, "more than 3 elements");
            }
            mscip_jr_index(jr, i);
            if (mscip_jr_f32(jr, ep, &out->delta_theta[i])) {
                return -1;
            }
        }
        mscip_jr_index(jr, SIZE_MAX);
        if (i != 3) {
            return mscip_jr_fail(jr, "expected 3 elements, got %zu", i);
        }
        mscip_jr_pop(jr);
    }
    return 0;
}

/* ---- mscip_imu_data_delta_velocity_t */

static int mscip_imu_data_delta_velocity_read(mscip_reader_t *r, mscip_imu_data_delta_velocity_t *out) {
    size_t i;
    mscip_rd_push(r, "delta_velocity");
    for (i = 0; i < 3; i++) {
        mscip_rd_index(r, i);
        if (mscip_rd_f32(r, &out->delta_velocity[i])) {
            return -1;
        }
    }
    mscip_rd_pop(r);
    return mscip_rd_finish(r);
}

static mscip_status_t mscip_imu_data_delta_velocity_write(mscip_writer_t *w,
                                                          const mscip_imu_data_delta_velocity_t *in) {
    mscip_status_t st;
    size_t i;
    for (i = 0; i < 3; i++) {
        if ((st = mscip_wr_f32(w, &in->delta_velocity[i])) != MSCIP_OK) {
            return st;
        }
    }
    return MSCIP_OK;
}

mscip_status_t mscip_imu_data_delta_velocity_encode(const mscip_imu_data_delta_velocity_t *value,
                                                    uint8_t *buf, size_t cap, size_t *len_out) {
    mscip_writer_t w;
    mscip_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mscip_writer_init(&w, buf, cap);
    st = mscip_imu_data_delta_velocity_write(&w, value);
    if (st == MSCIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 12 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mscip_imu_data_delta_velocity_load(const uint8_t *d, mscip_imu_data_delta_velocity_t *out) {
    out->delta_velocity[0] = mscip_ld_f32(d + 0);
    out->delta_velocity[1] = mscip_ld_f32(d + 4);
    out->delta_velocity[2] = mscip_ld_f32(d + 8);
    return 0;
}

/* The general reader: lengths other than 12, bad bool bytes, error details. */
static MSCIP_NOINLINE mscip_status_t mscip_imu_data_delta_velocity_decode_read(
    const uint8_t *data, size_t len, mscip_imu_data_delta_velocity_t *out, mscip_decode_error_t *err) {
    mscip_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mscip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mscip_imu_data_delta_velocity_read(&r, out) ? MSCIP_ERR_DECODE : MSCIP_OK;
}

mscip_status_t mscip_imu_data_delta_velocity_decode(const uint8_t *data, size_t len,
                                                    mscip_imu_data_delta_velocity_t *out,
                                                    mscip_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 12 && mscip_imu_data_delta_velocity_load(data, out) == 0) {
        return MSCIP_OK;
    }
    return mscip_imu_data_delta_velocity_decode_read(data, len, out, err);
}

void mscip_imu_data_delta_velocity_to_json(mscip_jw_t *w, const mscip_imu_data_delta_velocity_t *in) {
    int first = 1;
    size_t i;
    mscip_jw_raw(w, "{", 1);
    mscip_jw_key(w, &first, "delta_velocity");
    mscip_jw_raw(w, "[", 1);
    for (i = 0; i < 3; i++) {
        mscip_jw_sep(w, i);
        mscip_jw_f32(w, &in->delta_velocity[i]);
    }
    mscip_jw_raw(w, "]", 1);
    mscip_jw_raw(w, "}", 1);
}

int mscip_imu_data_delta_velocity_from_json(mscip_jr_t *jr, size_t pos,
                                            mscip_imu_data_delta_velocity_t *out) {
    static const char *const keys[] = {"delta_velocity"};
    size_t vp = 0;
    int found;
    size_t i;
    size_t it = 0;
    size_t ep = 0;
    memset(out, 0, sizeof *out);
    if (mscip_jr_object(jr, pos, keys, 1)) {
        return -1;
    }
    found = mscip_jr_get(jr, pos, "delta_velocity", &vp);
    if (found != 1) {
        return mscip_jr_fail(jr, "missing parameter \"delta_velocity\"");
    }
    {
        mscip_jr_push(jr, "delta_velocity");
        if (mscip_jr_array(jr, vp, &it)) {
            return -1;
        }
        for (i = 0;; i++) {
            int more = mscip_jr_next(jr, &it, &ep);
            if (more < 0) {
                return -1;
            }
            if (!more) {
                break;
            }
            if (i >= 3) {
                return mscip_jr_fail(jr, "more than 3 elements");
            }
            mscip_jr_index(jr, i);
            if (mscip_jr_f32(jr, ep, &out->delta_velocity[i])) {
                return -1;
            }
        }
        mscip_jr_index(jr, SIZE_MAX);
        if (i != 3) {
            return mscip_jr_fail(jr, "expected 3 elements, got %zu", i);
        }
        mscip_jr_pop(jr);
    }
    return 0;
}

/* ---- mscip_imu_data_scaled_pressure_t */

static int mscip_imu_data_scaled_pressure_read(mscip_reader_t *r, mscip_imu_data_scaled_pressure_t *out) {
    mscip_rd_push(r, "pressure");
    if (mscip_rd_f32(r, &out->pressure)) {
        return -1;
    }
    mscip_rd_pop(r);
    return mscip_rd_finish(r);
}

static mscip_status_t mscip_imu_data_scaled_pressure_write(mscip_writer_t *w,
                                                           const mscip_imu_data_scaled_pressure_t *in) {
    mscip_status_t st;
    if ((st = mscip_wr_f32(w, &in->pressure)) != MSCIP_OK) {
        return st;
    }
    return MSCIP_OK;
}

mscip_status_t mscip_imu_data_scaled_pressure_encode(const mscip_imu_data_scaled_pressure_t *value,
                                                     uint8_t *buf, size_t cap, size_t *len_out) {
    mscip_writer_t w;
    mscip_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mscip_writer_init(&w, buf, cap);
    st = mscip_imu_data_scaled_pressure_write(&w, value);
    if (st == MSCIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 4 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mscip_imu_data_scaled_pressure_load(const uint8_t *d, mscip_imu_data_scaled_pressure_t *out) {
    out->pressure = mscip_ld_f32(d + 0);
    return 0;
}

/* The general reader: lengths other than 4, bad bool bytes, error details. */
static MSCIP_NOINLINE mscip_status_t mscip_imu_data_scaled_pressure_decode_read(
    const uint8_t *data, size_t len, mscip_imu_data_scaled_pressure_t *out, mscip_decode_error_t *err) {
    mscip_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mscip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mscip_imu_data_scaled_pressure_read(&r, out) ? MSCIP_ERR_DECODE : MSCIP_OK;
}

mscip_status_t mscip_imu_data_scaled_pressure_decode(const uint8_t *data, size_t len,
                                                     mscip_imu_data_scaled_pressure_t *out,
                                                     mscip_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 4 && mscip_imu_data_scaled_pressure_load(data, out) == 0) {
        return MSCIP_OK;
    }
    return mscip_imu_data_scaled_pressure_decode_read(data, len, out, err);
}

void mscip_imu_data_scaled_pressure_to_json(mscip_jw_t *w, const mscip_imu_data_scaled_pressure_t *in) {
    int first = 1;
    mscip_jw_raw(w, "{", 1);
    mscip_jw_key(w, &first, "pressure");
    mscip_jw_f32(w, &in->pressure);
    mscip_jw_raw(w, "}", 1);
}

int mscip_imu_data_scaled_pressure_from_json(mscip_jr_t *jr, size_t pos,
                                             mscip_imu_data_scaled_pressure_t *out) {
    static const char *const keys[] = {"pressure"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mscip_jr_object(jr, pos, keys, 1)) {
        return -1;
    }
    found = mscip_jr_get(jr, pos, "pressure", &vp);
    if (found != 1) {
        return mscip_jr_fail(jr, "missing parameter \"pressure\"");
    }
    {
        mscip_jr_push(jr, "pressure");
        if (mscip_jr_f32(jr, vp, &out->pressure)) {
            return -1;
        }
        mscip_jr_pop(jr);
    }
    return 0;
}

/* ---- mscip_imu_data_scaled_temperature_t */

static int mscip_imu_data_scaled_temperature_read(mscip_reader_t *r,
                                                  mscip_imu_data_scaled_temperature_t *out) {
    mscip_rd_push(r, "temperature");
    if (mscip_rd_f32(r, &out->temperature)) {
        return -1;
    }
    mscip_rd_pop(r);
    return mscip_rd_finish(r);
}

static mscip_status_t mscip_imu_data_scaled_temperature_write(mscip_writer_t *w,
                                                              const mscip_imu_data_scaled_temperature_t *in) {
    mscip_status_t st;
    if ((st = mscip_wr_f32(w, &in->temperature)) != MSCIP_OK) {
        return st;
    }
    return MSCIP_OK;
}

mscip_status_t mscip_imu_data_scaled_temperature_encode(const mscip_imu_data_scaled_temperature_t *value,
                                                        uint8_t *buf, size_t cap, size_t *len_out) {
    mscip_writer_t w;
    mscip_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mscip_writer_init(&w, buf, cap);
    st = mscip_imu_data_scaled_temperature_write(&w, value);
    if (st == MSCIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 4 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mscip_imu_data_scaled_temperature_load(const uint8_t *d,
                                                  mscip_imu_data_scaled_temperature_t *out) {
    out->temperature = mscip_ld_f32(d + 0);
    return 0;
}

/* The general reader: lengths other than 4, bad bool bytes, error details. */
static MSCIP_NOINLINE mscip_status_t mscip_imu_data_scaled_temperature_decode_read(
    const uint8_t *data, size_t len, mscip_imu_data_scaled_temperature_t *out, mscip_decode_error_t *err) {
    mscip_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mscip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mscip_imu_data_scaled_temperature_read(&r, out) ? MSCIP_ERR_DECODE : MSCIP_OK;
}

mscip_status_t mscip_imu_data_scaled_temperature_decode(const uint8_t *data, size_t len,
                                                        mscip_imu_data_scaled_temperature_t *out,
                                                        mscip_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 4 && mscip_imu_data_scaled_temperature_load(data, out) == 0) {
        return MSCIP_OK;
    }
    return mscip_imu_data_scaled_temperature_decode_read(data, len, out, err);
}

void mscip_imu_data_scaled_temperature_to_json(mscip_jw_t *w, const mscip_imu_data_scaled_temperature_t *in) {
    int first = 1;
    mscip_jw_raw(w, "{", 1);
    mscip_jw_key(w, &first, "temperature");
    mscip_jw_f32(w, &in->temperature);
    mscip_jw_raw(w, "}", 1);
}

int mscip_imu_data_scaled_temperature_from_json(mscip_jr_t *jr, size_t pos,
                                                mscip_imu_data_scaled_temperature_t *out) {
    static const char *const keys[] = {"temperature"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mscip_jr_object(jr, pos, keys, 1)) {
        return -1;
    }
    found = mscip_jr_get(jr, pos, "temperature", &vp);
    if (found != 1) {
        return mscip_jr_fail(jr, "missing parameter \"temperature\"");
    }
    {
        mscip_jr_push(jr, "temperature");
        if (mscip_jr_f32(jr, vp, &out->temperature)) {
            return -1;
        }
        mscip_jr_pop(jr);
    }
    return 0;
}

/* ---- mscip_imu_data_gps_correlated_time_t */

static int mscip_imu_data_gps_correlated_time_read(mscip_reader_t *r,
                                                   mscip_imu_data_gps_correlated_time_t *out) {
    mscip_rd_push(r, "seconds");
    if (mscip_rd_f64(r, &out->seconds)) {
        return -1;
    }
    mscip_rd_pop(r);
    mscip_rd_push(r, "week");
    if (mscip_rd_u16(r, &out->week)) {
        return -1;
    }
    mscip_rd_pop(r);
    mscip_rd_push(r, "flags");
    if (mscip_rd_u16(r, &out->flags)) {
        return -1;
    }
    mscip_rd_pop(r);
    return mscip_rd_finish(r);
}

static mscip_status_t
mscip_imu_data_gps_correlated_time_write(mscip_writer_t *w, const mscip_imu_data_gps_correlated_time_t *in) {
    mscip_status_t st;
    if ((st = mscip_wr_f64(w, &in->seconds)) != MSCIP_OK) {
        return st;
    }
    if ((st = mscip_wr_u16(w, &in->week)) != MSCIP_OK) {
        return st;
    }
    if ((st = mscip_wr_u16(w, &in->flags)) != MSCIP_OK) {
        return st;
    }
    return MSCIP_OK;
}

mscip_status_t mscip_imu_data_gps_correlated_time_encode(const mscip_imu_data_gps_correlated_time_t *value,
                                                         uint8_t *buf, size_t cap, size_t *len_out) {
    mscip_writer_t w;
    mscip_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mscip_writer_init(&w, buf, cap);
    st = mscip_imu_data_gps_correlated_time_write(&w, value);
    if (st == MSCIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 12 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mscip_imu_data_gps_correlated_time_load(const uint8_t *d,
                                                   mscip_imu_data_gps_correlated_time_t *out) {
    out->seconds = mscip_ld_f64(d + 0);
    out->week = mscip_ld_u16(d + 8);
    out->flags = mscip_ld_u16(d + 10);
    return 0;
}

/* The general reader: lengths other than 12, bad bool bytes, error details. */
static MSCIP_NOINLINE mscip_status_t mscip_imu_data_gps_correlated_time_decode_read(
    const uint8_t *data, size_t len, mscip_imu_data_gps_correlated_time_t *out, mscip_decode_error_t *err) {
    mscip_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mscip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mscip_imu_data_gps_correlated_time_read(&r, out) ? MSCIP_ERR_DECODE : MSCIP_OK;
}

mscip_status_t mscip_imu_data_gps_correlated_time_decode(const uint8_t *data, size_t len,
                                                         mscip_imu_data_gps_correlated_time_t *out,
                                                         mscip_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 12 && mscip_imu_data_gps_correlated_time_load(data, out) == 0) {
        return MSCIP_OK;
    }
    return mscip_imu_data_gps_correlated_time_decode_read(data, len, out, err);
}

void mscip_imu_data_gps_correlated_time_to_json(mscip_jw_t *w,
                                                const mscip_imu_data_gps_correlated_time_t *in) {
    int first = 1;
    mscip_jw_raw(w, "{", 1);
    mscip_jw_key(w, &first, "seconds");
    mscip_jw_f64(w, &in->seconds);
    mscip_jw_key(w, &first, "week");
    mscip_jw_u16(w, &in->week);
    mscip_jw_key(w, &first, "flags");
    mscip_jw_u16(w, &in->flags);
    mscip_jw_raw(w, "}", 1);
}

int mscip_imu_data_gps_correlated_time_from_json(mscip_jr_t *jr, size_t pos,
                                                 mscip_imu_data_gps_correlated_time_t *out) {
    static const char *const keys[] = {"seconds", "week", "flags"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mscip_jr_object(jr, pos, keys, 3)) {
        return -1;
    }
    found = mscip_jr_get(jr, pos, "seconds", &vp);
    if (found != 1) {
        return mscip_jr_fail(jr, "missing parameter \"seconds\"");
    }
    {
        mscip_jr_push(jr, "seconds");
        if (mscip_jr_f64(jr, vp, &out->seconds)) {
            return -1;
        }
        mscip_jr_pop(jr);
    }
    found = mscip_jr_get(jr, pos, "week", &vp);
    if (found != 1) {
        return mscip_jr_fail(jr, "missing parameter \"week\"");
    }
    {
        mscip_jr_push(jr, "week");
        if (mscip_jr_u16(jr, vp, &out->week)) {
            return -1;
        }
        mscip_jr_pop(jr);
    }
    found = mscip_jr_get(jr, pos, "flags", &vp);
    if (found != 1) {
        return mscip_jr_fail(jr, "missing parameter \"flags\"");
    }
    {
        mscip_jr_push(jr, "flags");
        if (mscip_jr_u16(jr, vp, &out->flags)) {
            return -1;
        }
        mscip_jr_pop(jr);
    }
    return 0;
}

/* ---- mscip_imu_data_scaled_aux_accel_t */

static int mscip_imu_data_scaled_aux_accel_read(mscip_reader_t *r, mscip_imu_data_scaled_aux_accel_t *out) {
    size_t i;
    mscip_rd_push(r, "accel");
    for (i = 0; i < 3; i++) {
        mscip_rd_index(r, i);
        if (mscip_rd_f32(r, &out->accel[i])) {
            return -1;
        }
    }
    mscip_rd_pop(r);
    return mscip_rd_finish(r);
}

static mscip_status_t mscip_imu_data_scaled_aux_accel_write(mscip_writer_t *w,
                                                            const mscip_imu_data_scaled_aux_accel_t *in) {
    mscip_status_t st;
    size_t i;
    for (i = 0; i < 3; i++) {
        if ((st = mscip_wr_f32(w, &in->accel[i])) != MSCIP_OK) {
            return st;
        }
    }
    return MSCIP_OK;
}

mscip_status_t mscip_imu_data_scaled_aux_accel_encode(const mscip_imu_data_scaled_aux_accel_t *value,
                                                      uint8_t *buf, size_t cap, size_t *len_out) {
    mscip_writer_t w;
    mscip_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mscip_writer_init(&w, buf, cap);
    st = mscip_imu_data_scaled_aux_accel_write(&w, value);
    if (st == MSCIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 12 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mscip_imu_data_scaled_aux_accel_load(const uint8_t *d, mscip_imu_data_scaled_aux_accel_t *out) {
    out->accel[0] = mscip_ld_f32(d + 0);
    out->accel[1] = mscip_ld_f32(d + 4);
    out->accel[2] = mscip_ld_f32(d + 8);
    return 0;
}

/* The general reader: lengths other than 12, bad bool bytes, error details. */
static MSCIP_NOINLINE mscip_status_t mscip_imu_data_scaled_aux_accel_decode_read(
    const uint8_t *data, size_t len, mscip_imu_data_scaled_aux_accel_t *out, mscip_decode_error_t *err) {
    mscip_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mscip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mscip_imu_data_scaled_aux_accel_read(&r, out) ? MSCIP_ERR_DECODE : MSCIP_OK;
}

mscip_status_t mscip_imu_data_scaled_aux_accel_decode(const uint8_t *data, size_t len,
                                                      mscip_imu_data_scaled_aux_accel_t *out,
                                                      mscip_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 12 && mscip_imu_data_scaled_aux_accel_load(data, out) == 0) {
        return MSCIP_OK;
    }
    return mscip_imu_data_scaled_aux_accel_decode_read(data, len, out, err);
}

void mscip_imu_data_scaled_aux_accel_to_json(mscip_jw_t *w, const mscip_imu_data_scaled_aux_accel_t *in) {
    int first = 1;
    size_t i;
    mscip_jw_raw(w, "{", 1);
    mscip_jw_key(w, &first, "accel");
    mscip_jw_raw(w, "[", 1);
    for (i = 0; i < 3; i++) {
        mscip_jw_sep(w, i);
        mscip_jw_f32(w, &in->accel[i]);
    }
    mscip_jw_raw(w, "]", 1);
    mscip_jw_raw(w, "}", 1);
}

int mscip_imu_data_scaled_aux_accel_from_json(mscip_jr_t *jr, size_t pos,
                                              mscip_imu_data_scaled_aux_accel_t *out) {
    static const char *const keys[] = {"accel"};
    size_t vp = 0;
    int found;
    size_t i;
    size_t it = 0;
    size_t ep = 0;
    memset(out, 0, sizeof *out);
    if (mscip_jr_object(jr, pos, keys, 1)) {
        return -1;
    }
    found = mscip_jr_get(jr, pos, "accel", &vp);
    if (found != 1) {
        return mscip_jr_fail(jr, "missing parameter \"accel\"");
    }
    {
        mscip_jr_push(jr, "accel");
        if (mscip_jr_array(jr, vp, &it)) {
            return -1;
        }
        for (i = 0;; i++) {
            int more = mscip_jr_next(jr, &it, &ep);
            if (more < 0) {
                return -1;
            }
            if (!more) {
                break;
            }
            if (i >= 3) {
                return mscip_jr_fail(jr, "more than 3 elements");
            }
            mscip_jr_index(jr, i);
            if (mscip_jr_f32(jr, ep, &out->accel[i])) {
                return -1;
            }
        }
        mscip_jr_index(jr, SIZE_MAX);
        if (i != 3) {
            return mscip_jr_fail(jr, "expected 3 elements, got %zu", i);
        }
        mscip_jr_pop(jr);
    }
    return 0;
}
