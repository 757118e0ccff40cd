/* Encoders and decoders of Sensor (IMU) Data Set. Generated from the spec: do not edit. */
#include "mipcodec/sets/sensor.h"
#include "layouts_internal.h"
#include "types_internal.h"

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
    mip_writer_init(&w, buf, cap);
    st = mip_sensor_scaled_accel_write(&w, value);
    if (st == MIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mip_status_t mip_sensor_scaled_accel_decode(const uint8_t *data, size_t len, mip_sensor_scaled_accel_t *out,
                                            mip_decode_error_t *err) {
    mip_reader_t r;
    mip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mip_sensor_scaled_accel_read(&r, out) ? MIP_ERR_DECODE : MIP_OK;
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
    mip_writer_init(&w, buf, cap);
    st = mip_sensor_scaled_gyro_write(&w, value);
    if (st == MIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mip_status_t mip_sensor_scaled_gyro_decode(const uint8_t *data, size_t len, mip_sensor_scaled_gyro_t *out,
                                           mip_decode_error_t *err) {
    mip_reader_t r;
    mip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mip_sensor_scaled_gyro_read(&r, out) ? MIP_ERR_DECODE : MIP_OK;
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
    mip_writer_init(&w, buf, cap);
    st = mip_sensor_scaled_mag_write(&w, value);
    if (st == MIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mip_status_t mip_sensor_scaled_mag_decode(const uint8_t *data, size_t len, mip_sensor_scaled_mag_t *out,
                                          mip_decode_error_t *err) {
    mip_reader_t r;
    mip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mip_sensor_scaled_mag_read(&r, out) ? MIP_ERR_DECODE : MIP_OK;
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
