/* Encoders and decoders of GNSS Data Set. Generated from the spec: do not edit. */
#include "mipcodec/sets/gnss_data.h"
#include "layouts_internal.h"
#include "types_internal.h"

#include <assert.h>
#include <string.h>

/* ---- mip_gnss_data_llh_position_t */

static int mip_gnss_data_llh_position_read(mip_reader_t *r, mip_gnss_data_llh_position_t *out) {
    mip_rd_push(r, "latitude");
    if (mip_rd_f64(r, &out->latitude)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "longitude");
    if (mip_rd_f64(r, &out->longitude)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "ellipsoid_height");
    if (mip_rd_f64(r, &out->ellipsoid_height)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "msl_height");
    if (mip_rd_f64(r, &out->msl_height)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "horizontal_accuracy");
    if (mip_rd_f32(r, &out->horizontal_accuracy)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "vertical_accuracy");
    if (mip_rd_f32(r, &out->vertical_accuracy)) {
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

static mip_status_t mip_gnss_data_llh_position_write(mip_writer_t *w,
                                                     const mip_gnss_data_llh_position_t *in) {
    mip_status_t st;
    if ((st = mip_wr_f64(w, &in->latitude)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_f64(w, &in->longitude)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_f64(w, &in->ellipsoid_height)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_f64(w, &in->msl_height)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_f32(w, &in->horizontal_accuracy)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_f32(w, &in->vertical_accuracy)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_u16(w, &in->valid_flags)) != MIP_OK) {
        return st;
    }
    return MIP_OK;
}

mip_status_t mip_gnss_data_llh_position_encode(const mip_gnss_data_llh_position_t *value, uint8_t *buf,
                                               size_t cap, size_t *len_out) {
    mip_writer_t w;
    mip_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mip_writer_init(&w, buf, cap);
    st = mip_gnss_data_llh_position_write(&w, value);
    if (st == MIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 42 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mip_gnss_data_llh_position_load(const uint8_t *d, mip_gnss_data_llh_position_t *out) {
    out->latitude = mip_ld_f64(d + 0);
    out->longitude = mip_ld_f64(d + 8);
    out->ellipsoid_height = mip_ld_f64(d + 16);
    out->msl_height = mip_ld_f64(d + 24);
    out->horizontal_accuracy = mip_ld_f32(d + 32);
    out->vertical_accuracy = mip_ld_f32(d + 36);
    out->valid_flags = mip_ld_u16(d + 40);
    return 0;
}

/* The general reader: lengths other than 42, bad bool bytes, error details. */
static MIP_NOINLINE mip_status_t mip_gnss_data_llh_position_decode_read(const uint8_t *data, size_t len,
                                                                        mip_gnss_data_llh_position_t *out,
                                                                        mip_decode_error_t *err) {
    mip_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mip_gnss_data_llh_position_read(&r, out) ? MIP_ERR_DECODE : MIP_OK;
}

mip_status_t mip_gnss_data_llh_position_decode(const uint8_t *data, size_t len,
                                               mip_gnss_data_llh_position_t *out, mip_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 42 && mip_gnss_data_llh_position_load(data, out) == 0) {
        return MIP_OK;
    }
    return mip_gnss_data_llh_position_decode_read(data, len, out, err);
}

void mip_gnss_data_llh_position_to_json(mip_jw_t *w, const mip_gnss_data_llh_position_t *in) {
    int first = 1;
    mip_jw_raw(w, "{", 1);
    mip_jw_key(w, &first, "latitude");
    mip_jw_f64(w, &in->latitude);
    mip_jw_key(w, &first, "longitude");
    mip_jw_f64(w, &in->longitude);
    mip_jw_key(w, &first, "ellipsoid_height");
    mip_jw_f64(w, &in->ellipsoid_height);
    mip_jw_key(w, &first, "msl_height");
    mip_jw_f64(w, &in->msl_height);
    mip_jw_key(w, &first, "horizontal_accuracy");
    mip_jw_f32(w, &in->horizontal_accuracy);
    mip_jw_key(w, &first, "vertical_accuracy");
    mip_jw_f32(w, &in->vertical_accuracy);
    mip_jw_key(w, &first, "valid_flags");
    mip_jw_u16(w, &in->valid_flags);
    mip_jw_raw(w, "}", 1);
}

int mip_gnss_data_llh_position_from_json(mip_jr_t *jr, size_t pos, mip_gnss_data_llh_position_t *out) {
    static const char *const keys[] = {"latitude",   "longitude",           "ellipsoid_height",
                                       "msl_height", "horizontal_accuracy", "vertical_accuracy",
                                       "valid_flags"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mip_jr_object(jr, pos, keys, 7)) {
        return -1;
    }
    found = mip_jr_get(jr, pos, "latitude", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"latitude\"");
    }
    {
        mip_jr_push(jr, "latitude");
        if (mip_jr_f64(jr, vp, &out->latitude)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "longitude", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"longitude\"");
    }
    {
        mip_jr_push(jr, "longitude");
        if (mip_jr_f64(jr, vp, &out->longitude)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "ellipsoid_height", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"ellipsoid_height\"");
    }
    {
        mip_jr_push(jr, "ellipsoid_height");
        if (mip_jr_f64(jr, vp, &out->ellipsoid_height)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "msl_height", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"msl_height\"");
    }
    {
        mip_jr_push(jr, "msl_height");
        if (mip_jr_f64(jr, vp, &out->msl_height)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "horizontal_accuracy", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"horizontal_accuracy\"");
    }
    {
        mip_jr_push(jr, "horizontal_accuracy");
        if (mip_jr_f32(jr, vp, &out->horizontal_accuracy)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "vertical_accuracy", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"vertical_accuracy\"");
    }
    {
        mip_jr_push(jr, "vertical_accuracy");
        if (mip_jr_f32(jr, vp, &out->vertical_accuracy)) {
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

/* ---- mip_gnss_data_ecef_position_t */

static int mip_gnss_data_ecef_position_read(mip_reader_t *r, mip_gnss_data_ecef_position_t *out) {
    size_t i;
    mip_rd_push(r, "position");
    for (i = 0; i < 3; i++) {
        mip_rd_index(r, i);
        if (mip_rd_f64(r, &out->position[i])) {
            return -1;
        }
    }
    mip_rd_pop(r);
    mip_rd_push(r, "position_accuracy");
    if (mip_rd_f32(r, &out->position_accuracy)) {
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

static mip_status_t mip_gnss_data_ecef_position_write(mip_writer_t *w,
                                                      const mip_gnss_data_ecef_position_t *in) {
    mip_status_t st;
    size_t i;
    for (i = 0; i < 3; i++) {
        if ((st = mip_wr_f64(w, &in->position[i])) != MIP_OK) {
            return st;
        }
    }
    if ((st = mip_wr_f32(w, &in->position_accuracy)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_u16(w, &in->valid_flags)) != MIP_OK) {
        return st;
    }
    return MIP_OK;
}

mip_status_t mip_gnss_data_ecef_position_encode(const mip_gnss_data_ecef_position_t *value, uint8_t *buf,
                                                size_t cap, size_t *len_out) {
    mip_writer_t w;
    mip_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mip_writer_init(&w, buf, cap);
    st = mip_gnss_data_ecef_position_write(&w, value);
    if (st == MIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 30 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mip_gnss_data_ecef_position_load(const uint8_t *d, mip_gnss_data_ecef_position_t *out) {
    out->position[0] = mip_ld_f64(d + 0);
    out->position[1] = mip_ld_f64(d + 8);
    out->position[2] = mip_ld_f64(d + 16);
    out->position_accuracy = mip_ld_f32(d + 24);
    out->valid_flags = mip_ld_u16(d + 28);
    return 0;
}

/* The general reader: lengths other than 30, bad bool bytes, error details. */
static MIP_NOINLINE mip_status_t mip_gnss_data_ecef_position_decode_read(const uint8_t *data, size_t len,
                                                                         mip_gnss_data_ecef_position_t *out,
                                                                         mip_decode_error_t *err) {
    mip_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mip_gnss_data_ecef_position_read(&r, out) ? MIP_ERR_DECODE : MIP_OK;
}

mip_status_t mip_gnss_data_ecef_position_decode(const uint8_t *data, size_t len,
                                                mip_gnss_data_ecef_position_t *out, mip_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 30 && mip_gnss_data_ecef_position_load(data, out) == 0) {
        return MIP_OK;
    }
    return mip_gnss_data_ecef_position_decode_read(data, len, out, err);
}

void mip_gnss_data_ecef_position_to_json(mip_jw_t *w, const mip_gnss_data_ecef_position_t *in) {
    int first = 1;
    size_t i;
    mip_jw_raw(w, "{", 1);
    mip_jw_key(w, &first, "position");
    mip_jw_raw(w, "[", 1);
    for (i = 0; i < 3; i++) {
        mip_jw_sep(w, i);
        mip_jw_f64(w, &in->position[i]);
    }
    mip_jw_raw(w, "]", 1);
    mip_jw_key(w, &first, "position_accuracy");
    mip_jw_f32(w, &in->position_accuracy);
    mip_jw_key(w, &first, "valid_flags");
    mip_jw_u16(w, &in->valid_flags);
    mip_jw_raw(w, "}", 1);
}

int mip_gnss_data_ecef_position_from_json(mip_jr_t *jr, size_t pos, mip_gnss_data_ecef_position_t *out) {
    static const char *const keys[] = {"position", "position_accuracy", "valid_flags"};
    size_t vp = 0;
    int found;
    size_t i;
    size_t it = 0;
    size_t ep = 0;
    memset(out, 0, sizeof *out);
    if (mip_jr_object(jr, pos, keys, 3)) {
        return -1;
    }
    found = mip_jr_get(jr, pos, "position", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"position\"");
    }
    {
        mip_jr_push(jr, "position");
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
            if (mip_jr_f64(jr, ep, &out->position[i])) {
                return -1;
            }
        }
        mip_jr_index(jr, SIZE_MAX);
        if (i != 3) {
            return mip_jr_fail(jr, "expected 3 elements, got %zu", i);
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "position_accuracy", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"position_accuracy\"");
    }
    {
        mip_jr_push(jr, "position_accuracy");
        if (mip_jr_f32(jr, vp, &out->position_accuracy)) {
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

/* ---- mip_gnss_data_ned_velocity_t */

static int mip_gnss_data_ned_velocity_read(mip_reader_t *r, mip_gnss_data_ned_velocity_t *out) {
    size_t i;
    mip_rd_push(r, "velocity");
    for (i = 0; i < 3; i++) {
        mip_rd_index(r, i);
        if (mip_rd_f32(r, &out->velocity[i])) {
            return -1;
        }
    }
    mip_rd_pop(r);
    mip_rd_push(r, "speed");
    if (mip_rd_f32(r, &out->speed)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "ground_speed");
    if (mip_rd_f32(r, &out->ground_speed)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "heading");
    if (mip_rd_f32(r, &out->heading)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "speed_accuracy");
    if (mip_rd_f32(r, &out->speed_accuracy)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "heading_accuracy");
    if (mip_rd_f32(r, &out->heading_accuracy)) {
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

static mip_status_t mip_gnss_data_ned_velocity_write(mip_writer_t *w,
                                                     const mip_gnss_data_ned_velocity_t *in) {
    mip_status_t st;
    size_t i;
    for (i = 0; i < 3; i++) {
        if ((st = mip_wr_f32(w, &in->velocity[i])) != MIP_OK) {
            return st;
        }
    }
    if ((st = mip_wr_f32(w, &in->speed)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_f32(w, &in->ground_speed)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_f32(w, &in->heading)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_f32(w, &in->speed_accuracy)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_f32(w, &in->heading_accuracy)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_u16(w, &in->valid_flags)) != MIP_OK) {
        return st;
    }
    return MIP_OK;
}

mip_status_t mip_gnss_data_ned_velocity_encode(const mip_gnss_data_ned_velocity_t *value, uint8_t *buf,
                                               size_t cap, size_t *len_out) {
    mip_writer_t w;
    mip_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mip_writer_init(&w, buf, cap);
    st = mip_gnss_data_ned_velocity_write(&w, value);
    if (st == MIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 34 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mip_gnss_data_ned_velocity_load(const uint8_t *d, mip_gnss_data_ned_velocity_t *out) {
    out->velocity[0] = mip_ld_f32(d + 0);
    out->velocity[1] = mip_ld_f32(d + 4);
    out->velocity[2] = mip_ld_f32(d + 8);
    out->speed = mip_ld_f32(d + 12);
    out->ground_speed = mip_ld_f32(d + 16);
    out->heading = mip_ld_f32(d + 20);
    out->speed_accuracy = mip_ld_f32(d + 24);
    out->heading_accuracy = mip_ld_f32(d + 28);
    out->valid_flags = mip_ld_u16(d + 32);
    return 0;
}

/* The general reader: lengths other than 34, bad bool bytes, error details. */
static MIP_NOINLINE mip_status_t mip_gnss_data_ned_velocity_decode_read(const uint8_t *data, size_t len,
                                                                        mip_gnss_data_ned_velocity_t *out,
                                                                        mip_decode_error_t *err) {
    mip_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mip_gnss_data_ned_velocity_read(&r, out) ? MIP_ERR_DECODE : MIP_OK;
}

mip_status_t mip_gnss_data_ned_velocity_decode(const uint8_t *data, size_t len,
                                               mip_gnss_data_ned_velocity_t *out, mip_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 34 && mip_gnss_data_ned_velocity_load(data, out) == 0) {
        return MIP_OK;
    }
    return mip_gnss_data_ned_velocity_decode_read(data, len, out, err);
}

void mip_gnss_data_ned_velocity_to_json(mip_jw_t *w, const mip_gnss_data_ned_velocity_t *in) {
    int first = 1;
    size_t i;
    mip_jw_raw(w, "{", 1);
    mip_jw_key(w, &first, "velocity");
    mip_jw_raw(w, "[", 1);
    for (i = 0; i < 3; i++) {
        mip_jw_sep(w, i);
        mip_jw_f32(w, &in->velocity[i]);
    }
    mip_jw_raw(w, "]", 1);
    mip_jw_key(w, &first, "speed");
    mip_jw_f32(w, &in->speed);
    mip_jw_key(w, &first, "ground_speed");
    mip_jw_f32(w, &in->ground_speed);
    mip_jw_key(w, &first, "heading");
    mip_jw_f32(w, &in->heading);
    mip_jw_key(w, &first, "speed_accuracy");
    mip_jw_f32(w, &in->speed_accuracy);
    mip_jw_key(w, &first, "heading_accuracy");
    mip_jw_f32(w, &in->heading_accuracy);
    mip_jw_key(w, &first, "valid_flags");
    mip_jw_u16(w, &in->valid_flags);
    mip_jw_raw(w, "}", 1);
}

int mip_gnss_data_ned_velocity_from_json(mip_jr_t *jr, size_t pos, mip_gnss_data_ned_velocity_t *out) {
    static const char *const keys[] = {
        "velocity", "speed", "ground_speed", "heading", "speed_accuracy", "heading_accuracy", "valid_flags"};
    size_t vp = 0;
    int found;
    size_t i;
    size_t it = 0;
    size_t ep = 0;
    memset(out, 0, sizeof *out);
    if (mip_jr_object(jr, pos, keys, 7)) {
        return -1;
    }
    found = mip_jr_get(jr, pos, "velocity", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"velocity\"");
    }
    {
        mip_jr_push(jr, "velocity");
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
            if (mip_jr_f32(jr, ep, &out->velocity[i])) {
                return -1;
            }
        }
        mip_jr_index(jr, SIZE_MAX);
        if (i != 3) {
            return mip_jr_fail(jr, "expected 3 elements, got %zu", i);
        }
        mip_jr_pop(jr);
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
    found = mip_jr_get(jr, pos, "ground_speed", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"ground_speed\"");
    }
    {
        mip_jr_push(jr, "ground_speed");
        if (mip_jr_f32(jr, vp, &out->ground_speed)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "heading", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"heading\"");
    }
    {
        mip_jr_push(jr, "heading");
        if (mip_jr_f32(jr, vp, &out->heading)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "speed_accuracy", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"speed_accuracy\"");
    }
    {
        mip_jr_push(jr, "speed_accuracy");
        if (mip_jr_f32(jr, vp, &out->speed_accuracy)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "heading_accuracy", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"heading_accuracy\"");
    }
    {
        mip_jr_push(jr, "heading_accuracy");
        if (mip_jr_f32(jr, vp, &out->heading_accuracy)) {
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

/* ---- mip_gnss_data_ecef_velocity_t */

static int mip_gnss_data_ecef_velocity_read(mip_reader_t *r, mip_gnss_data_ecef_velocity_t *out) {
    size_t i;
    mip_rd_push(r, "velocity");
    for (i = 0; i < 3; i++) {
        mip_rd_index(r, i);
        if (mip_rd_f32(r, &out->velocity[i])) {
            return -1;
        }
    }
    mip_rd_pop(r);
    mip_rd_push(r, "velocity_accuracy");
    if (mip_rd_f32(r, &out->velocity_accuracy)) {
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

static mip_status_t mip_gnss_data_ecef_velocity_write(mip_writer_t *w,
                                                      const mip_gnss_data_ecef_velocity_t *in) {
    mip_status_t st;
    size_t i;
    for (i = 0; i < 3; i++) {
        if ((st = mip_wr_f32(w, &in->velocity[i])) != MIP_OK) {
            return st;
        }
    }
    if ((st = mip_wr_f32(w, &in->velocity_accuracy)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_u16(w, &in->valid_flags)) != MIP_OK) {
        return st;
    }
    return MIP_OK;
}

mip_status_t mip_gnss_data_ecef_velocity_encode(const mip_gnss_data_ecef_velocity_t *value, uint8_t *buf,
                                                size_t cap, size_t *len_out) {
    mip_writer_t w;
    mip_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mip_writer_init(&w, buf, cap);
    st = mip_gnss_data_ecef_velocity_write(&w, value);
    if (st == MIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 18 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mip_gnss_data_ecef_velocity_load(const uint8_t *d, mip_gnss_data_ecef_velocity_t *out) {
    out->velocity[0] = mip_ld_f32(d + 0);
    out->velocity[1] = mip_ld_f32(d + 4);
    out->velocity[2] = mip_ld_f32(d + 8);
    out->velocity_accuracy = mip_ld_f32(d + 12);
    out->valid_flags = mip_ld_u16(d + 16);
    return 0;
}

/* The general reader: lengths other than 18, bad bool bytes, error details. */
static MIP_NOINLINE mip_status_t mip_gnss_data_ecef_velocity_decode_read(const uint8_t *data, size_t len,
                                                                         mip_gnss_data_ecef_velocity_t *out,
                                                                         mip_decode_error_t *err) {
    mip_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mip_gnss_data_ecef_velocity_read(&r, out) ? MIP_ERR_DECODE : MIP_OK;
}

mip_status_t mip_gnss_data_ecef_velocity_decode(const uint8_t *data, size_t len,
                                                mip_gnss_data_ecef_velocity_t *out, mip_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 18 && mip_gnss_data_ecef_velocity_load(data, out) == 0) {
        return MIP_OK;
    }
    return mip_gnss_data_ecef_velocity_decode_read(data, len, out, err);
}

void mip_gnss_data_ecef_velocity_to_json(mip_jw_t *w, const mip_gnss_data_ecef_velocity_t *in) {
    int first = 1;
    size_t i;
    mip_jw_raw(w, "{", 1);
    mip_jw_key(w, &first, "velocity");
    mip_jw_raw(w, "[", 1);
    for (i = 0; i < 3; i++) {
        mip_jw_sep(w, i);
        mip_jw_f32(w, &in->velocity[i]);
    }
    mip_jw_raw(w, "]", 1);
    mip_jw_key(w, &first, "velocity_accuracy");
    mip_jw_f32(w, &in->velocity_accuracy);
    mip_jw_key(w, &first, "valid_flags");
    mip_jw_u16(w, &in->valid_flags);
    mip_jw_raw(w, "}", 1);
}

int mip_gnss_data_ecef_velocity_from_json(mip_jr_t *jr, size_t pos, mip_gnss_data_ecef_velocity_t *out) {
    static const char *const keys[] = {"velocity", "velocity_accuracy", "valid_flags"};
    size_t vp = 0;
    int found;
    size_t i;
    size_t it = 0;
    size_t ep = 0;
    memset(out, 0, sizeof *out);
    if (mip_jr_object(jr, pos, keys, 3)) {
        return -1;
    }
    found = mip_jr_get(jr, pos, "velocity", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"velocity\"");
    }
    {
        mip_jr_push(jr, "velocity");
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
            if (mip_jr_f32(jr, ep, &out->velocity[i])) {
                return -1;
            }
        }
        mip_jr_index(jr, SIZE_MAX);
        if (i != 3) {
            return mip_jr_fail(jr, "expected 3 elements, got %zu", i);
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "velocity_accuracy", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"velocity_accuracy\"");
    }
    {
        mip_jr_push(jr, "velocity_accuracy");
        if (mip_jr_f32(jr, vp, &out->velocity_accuracy)) {
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

/* ---- mip_gnss_data_dop_t */

static int mip_gnss_data_dop_read(mip_reader_t *r, mip_gnss_data_dop_t *out) {
    mip_rd_push(r, "gdop");
    if (mip_rd_f32(r, &out->gdop)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "pdop");
    if (mip_rd_f32(r, &out->pdop)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "hdop");
    if (mip_rd_f32(r, &out->hdop)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "vdop");
    if (mip_rd_f32(r, &out->vdop)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "tdop");
    if (mip_rd_f32(r, &out->tdop)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "ndop");
    if (mip_rd_f32(r, &out->ndop)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "edop");
    if (mip_rd_f32(r, &out->edop)) {
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

static mip_status_t mip_gnss_data_dop_write(mip_writer_t *w, const mip_gnss_data_dop_t *in) {
    mip_status_t st;
    if ((st = mip_wr_f32(w, &in->gdop)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_f32(w, &in->pdop)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_f32(w, &in->hdop)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_f32(w, &in->vdop)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_f32(w, &in->tdop)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_f32(w, &in->ndop)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_f32(w, &in->edop)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_u16(w, &in->valid_flags)) != MIP_OK) {
        return st;
    }
    return MIP_OK;
}

mip_status_t mip_gnss_data_dop_encode(const mip_gnss_data_dop_t *value, uint8_t *buf, size_t cap,
                                      size_t *len_out) {
    mip_writer_t w;
    mip_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mip_writer_init(&w, buf, cap);
    st = mip_gnss_data_dop_write(&w, value);
    if (st == MIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 30 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mip_gnss_data_dop_load(const uint8_t *d, mip_gnss_data_dop_t *out) {
    out->gdop = mip_ld_f32(d + 0);
    out->pdop = mip_ld_f32(d + 4);
    out->hdop = mip_ld_f32(d + 8);
    out->vdop = mip_ld_f32(d + 12);
    out->tdop = mip_ld_f32(d + 16);
    out->ndop = mip_ld_f32(d + 20);
    out->edop = mip_ld_f32(d + 24);
    out->valid_flags = mip_ld_u16(d + 28);
    return 0;
}

/* The general reader: lengths other than 30, bad bool bytes, error details. */
static MIP_NOINLINE mip_status_t mip_gnss_data_dop_decode_read(const uint8_t *data, size_t len,
                                                               mip_gnss_data_dop_t *out,
                                                               mip_decode_error_t *err) {
    mip_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mip_gnss_data_dop_read(&r, out) ? MIP_ERR_DECODE : MIP_OK;
}

mip_status_t mip_gnss_data_dop_decode(const uint8_t *data, size_t len, mip_gnss_data_dop_t *out,
                                      mip_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 30 && mip_gnss_data_dop_load(data, out) == 0) {
        return MIP_OK;
    }
    return mip_gnss_data_dop_decode_read(data, len, out, err);
}

void mip_gnss_data_dop_to_json(mip_jw_t *w, const mip_gnss_data_dop_t *in) {
    int first = 1;
    mip_jw_raw(w, "{", 1);
    mip_jw_key(w, &first, "gdop");
    mip_jw_f32(w, &in->gdop);
    mip_jw_key(w, &first, "pdop");
    mip_jw_f32(w, &in->pdop);
    mip_jw_key(w, &first, "hdop");
    mip_jw_f32(w, &in->hdop);
    mip_jw_key(w, &first, "vdop");
    mip_jw_f32(w, &in->vdop);
    mip_jw_key(w, &first, "tdop");
    mip_jw_f32(w, &in->tdop);
    mip_jw_key(w, &first, "ndop");
    mip_jw_f32(w, &in->ndop);
    mip_jw_key(w, &first, "edop");
    mip_jw_f32(w, &in->edop);
    mip_jw_key(w, &first, "valid_flags");
    mip_jw_u16(w, &in->valid_flags);
    mip_jw_raw(w, "}", 1);
}

int mip_gnss_data_dop_from_json(mip_jr_t *jr, size_t pos, mip_gnss_data_dop_t *out) {
    static const char *const keys[] = {"gdop", "pdop", "hdop", "vdop", "tdop", "ndop", "edop", "valid_flags"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mip_jr_object(jr, pos, keys, 8)) {
        return -1;
    }
    found = mip_jr_get(jr, pos, "gdop", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"gdop\"");
    }
    {
        mip_jr_push(jr, "gdop");
        if (mip_jr_f32(jr, vp, &out->gdop)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "pdop", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"pdop\"");
    }
    {
        mip_jr_push(jr, "pdop");
        if (mip_jr_f32(jr, vp, &out->pdop)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "hdop", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"hdop\"");
    }
    {
        mip_jr_push(jr, "hdop");
        if (mip_jr_f32(jr, vp, &out->hdop)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "vdop", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"vdop\"");
    }
    {
        mip_jr_push(jr, "vdop");
        if (mip_jr_f32(jr, vp, &out->vdop)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "tdop", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"tdop\"");
    }
    {
        mip_jr_push(jr, "tdop");
        if (mip_jr_f32(jr, vp, &out->tdop)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "ndop", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"ndop\"");
    }
    {
        mip_jr_push(jr, "ndop");
        if (mip_jr_f32(jr, vp, &out->ndop)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "edop", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"edop\"");
    }
    {
        mip_jr_push(jr, "edop");
        if (mip_jr_f32(jr, vp, &out->edop)) {
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

/* ---- mip_gnss_data_utc_time_t */

static int mip_gnss_data_utc_time_read(mip_reader_t *r, mip_gnss_data_utc_time_t *out) {
    mip_rd_push(r, "year");
    if (mip_rd_u16(r, &out->year)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "month");
    if (mip_rd_u8(r, &out->month)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "day");
    if (mip_rd_u8(r, &out->day)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "hour");
    if (mip_rd_u8(r, &out->hour)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "minute");
    if (mip_rd_u8(r, &out->minute)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "second");
    if (mip_rd_u8(r, &out->second)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "millisecond");
    if (mip_rd_u32(r, &out->millisecond)) {
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

static mip_status_t mip_gnss_data_utc_time_write(mip_writer_t *w, const mip_gnss_data_utc_time_t *in) {
    mip_status_t st;
    if ((st = mip_wr_u16(w, &in->year)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_u8(w, &in->month)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_u8(w, &in->day)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_u8(w, &in->hour)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_u8(w, &in->minute)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_u8(w, &in->second)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_u32(w, &in->millisecond)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_u16(w, &in->valid_flags)) != MIP_OK) {
        return st;
    }
    return MIP_OK;
}

mip_status_t mip_gnss_data_utc_time_encode(const mip_gnss_data_utc_time_t *value, uint8_t *buf, size_t cap,
                                           size_t *len_out) {
    mip_writer_t w;
    mip_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mip_writer_init(&w, buf, cap);
    st = mip_gnss_data_utc_time_write(&w, value);
    if (st == MIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 13 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mip_gnss_data_utc_time_load(const uint8_t *d, mip_gnss_data_utc_time_t *out) {
    out->year = mip_ld_u16(d + 0);
    out->month = mip_ld_u8(d + 2);
    out->day = mip_ld_u8(d + 3);
    out->hour = mip_ld_u8(d + 4);
    out->minute = mip_ld_u8(d + 5);
    out->second = mip_ld_u8(d + 6);
    out->millisecond = mip_ld_u32(d + 7);
    out->valid_flags = mip_ld_u16(d + 11);
    return 0;
}

/* The general reader: lengths other than 13, bad bool bytes, error details. */
static MIP_NOINLINE mip_status_t mip_gnss_data_utc_time_decode_read(const uint8_t *data, size_t len,
                                                                    mip_gnss_data_utc_time_t *out,
                                                                    mip_decode_error_t *err) {
    mip_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mip_gnss_data_utc_time_read(&r, out) ? MIP_ERR_DECODE : MIP_OK;
}

mip_status_t mip_gnss_data_utc_time_decode(const uint8_t *data, size_t len, mip_gnss_data_utc_time_t *out,
                                           mip_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 13 && mip_gnss_data_utc_time_load(data, out) == 0) {
        return MIP_OK;
    }
    return mip_gnss_data_utc_time_decode_read(data, len, out, err);
}

void mip_gnss_data_utc_time_to_json(mip_jw_t *w, const mip_gnss_data_utc_time_t *in) {
    int first = 1;
    mip_jw_raw(w, "{", 1);
    mip_jw_key(w, &first, "year");
    mip_jw_u16(w, &in->year);
    mip_jw_key(w, &first, "month");
    mip_jw_u8(w, &in->month);
    mip_jw_key(w, &first, "day");
    mip_jw_u8(w, &in->day);
    mip_jw_key(w, &first, "hour");
    mip_jw_u8(w, &in->hour);
    mip_jw_key(w, &first, "minute");
    mip_jw_u8(w, &in->minute);
    mip_jw_key(w, &first, "second");
    mip_jw_u8(w, &in->second);
    mip_jw_key(w, &first, "millisecond");
    mip_jw_u32(w, &in->millisecond);
    mip_jw_key(w, &first, "valid_flags");
    mip_jw_u16(w, &in->valid_flags);
    mip_jw_raw(w, "}", 1);
}

int mip_gnss_data_utc_time_from_json(mip_jr_t *jr, size_t pos, mip_gnss_data_utc_time_t *out) {
    static const char *const keys[] = {"year",   "month",  "day",         "hour",
                                       "minute", "second", "millisecond", "valid_flags"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mip_jr_object(jr, pos, keys, 8)) {
        return -1;
    }
    found = mip_jr_get(jr, pos, "year", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"year\"");
    }
    {
        mip_jr_push(jr, "year");
        if (mip_jr_u16(jr, vp, &out->year)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "month", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"month\"");
    }
    {
        mip_jr_push(jr, "month");
        if (mip_jr_u8(jr, vp, &out->month)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "day", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"day\"");
    }
    {
        mip_jr_push(jr, "day");
        if (mip_jr_u8(jr, vp, &out->day)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "hour", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"hour\"");
    }
    {
        mip_jr_push(jr, "hour");
        if (mip_jr_u8(jr, vp, &out->hour)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "minute", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"minute\"");
    }
    {
        mip_jr_push(jr, "minute");
        if (mip_jr_u8(jr, vp, &out->minute)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "second", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"second\"");
    }
    {
        mip_jr_push(jr, "second");
        if (mip_jr_u8(jr, vp, &out->second)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "millisecond", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"millisecond\"");
    }
    {
        mip_jr_push(jr, "millisecond");
        if (mip_jr_u32(jr, vp, &out->millisecond)) {
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

/* ---- mip_gnss_data_gps_time_t */

static int mip_gnss_data_gps_time_read(mip_reader_t *r, mip_gnss_data_gps_time_t *out) {
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

static mip_status_t mip_gnss_data_gps_time_write(mip_writer_t *w, const mip_gnss_data_gps_time_t *in) {
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

mip_status_t mip_gnss_data_gps_time_encode(const mip_gnss_data_gps_time_t *value, uint8_t *buf, size_t cap,
                                           size_t *len_out) {
    mip_writer_t w;
    mip_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mip_writer_init(&w, buf, cap);
    st = mip_gnss_data_gps_time_write(&w, value);
    if (st == MIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 12 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mip_gnss_data_gps_time_load(const uint8_t *d, mip_gnss_data_gps_time_t *out) {
    out->tow = mip_ld_f64(d + 0);
    out->week_number = mip_ld_u16(d + 8);
    out->valid_flags = mip_ld_u16(d + 10);
    return 0;
}

/* The general reader: lengths other than 12, bad bool bytes, error details. */
static MIP_NOINLINE mip_status_t mip_gnss_data_gps_time_decode_read(const uint8_t *data, size_t len,
                                                                    mip_gnss_data_gps_time_t *out,
                                                                    mip_decode_error_t *err) {
    mip_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mip_gnss_data_gps_time_read(&r, out) ? MIP_ERR_DECODE : MIP_OK;
}

mip_status_t mip_gnss_data_gps_time_decode(const uint8_t *data, size_t len, mip_gnss_data_gps_time_t *out,
                                           mip_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 12 && mip_gnss_data_gps_time_load(data, out) == 0) {
        return MIP_OK;
    }
    return mip_gnss_data_gps_time_decode_read(data, len, out, err);
}

void mip_gnss_data_gps_time_to_json(mip_jw_t *w, const mip_gnss_data_gps_time_t *in) {
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

int mip_gnss_data_gps_time_from_json(mip_jr_t *jr, size_t pos, mip_gnss_data_gps_time_t *out) {
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

/* ---- mip_gnss_data_clock_info_t */

static int mip_gnss_data_clock_info_read(mip_reader_t *r, mip_gnss_data_clock_info_t *out) {
    mip_rd_push(r, "bias");
    if (mip_rd_f64(r, &out->bias)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "drift");
    if (mip_rd_f64(r, &out->drift)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "accuracy_estimate");
    if (mip_rd_f64(r, &out->accuracy_estimate)) {
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

static mip_status_t mip_gnss_data_clock_info_write(mip_writer_t *w, const mip_gnss_data_clock_info_t *in) {
    mip_status_t st;
    if ((st = mip_wr_f64(w, &in->bias)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_f64(w, &in->drift)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_f64(w, &in->accuracy_estimate)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_u16(w, &in->valid_flags)) != MIP_OK) {
        return st;
    }
    return MIP_OK;
}

mip_status_t mip_gnss_data_clock_info_encode(const mip_gnss_data_clock_info_t *value, uint8_t *buf,
                                             size_t cap, size_t *len_out) {
    mip_writer_t w;
    mip_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mip_writer_init(&w, buf, cap);
    st = mip_gnss_data_clock_info_write(&w, value);
    if (st == MIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 26 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mip_gnss_data_clock_info_load(const uint8_t *d, mip_gnss_data_clock_info_t *out) {
    out->bias = mip_ld_f64(d + 0);
    out->drift = mip_ld_f64(d + 8);
    out->accuracy_estimate = mip_ld_f64(d + 16);
    out->valid_flags = mip_ld_u16(d + 24);
    return 0;
}

/* The general reader: lengths other than 26, bad bool bytes, error details. */
static MIP_NOINLINE mip_status_t mip_gnss_data_clock_info_decode_read(const uint8_t *data, size_t len,
                                                                      mip_gnss_data_clock_info_t *out,
                                                                      mip_decode_error_t *err) {
    mip_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mip_gnss_data_clock_info_read(&r, out) ? MIP_ERR_DECODE : MIP_OK;
}

mip_status_t mip_gnss_data_clock_info_decode(const uint8_t *data, size_t len, mip_gnss_data_clock_info_t *out,
                                             mip_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 26 && mip_gnss_data_clock_info_load(data, out) == 0) {
        return MIP_OK;
    }
    return mip_gnss_data_clock_info_decode_read(data, len, out, err);
}

void mip_gnss_data_clock_info_to_json(mip_jw_t *w, const mip_gnss_data_clock_info_t *in) {
    int first = 1;
    mip_jw_raw(w, "{", 1);
    mip_jw_key(w, &first, "bias");
    mip_jw_f64(w, &in->bias);
    mip_jw_key(w, &first, "drift");
    mip_jw_f64(w, &in->drift);
    mip_jw_key(w, &first, "accuracy_estimate");
    mip_jw_f64(w, &in->accuracy_estimate);
    mip_jw_key(w, &first, "valid_flags");
    mip_jw_u16(w, &in->valid_flags);
    mip_jw_raw(w, "}", 1);
}

int mip_gnss_data_clock_info_from_json(mip_jr_t *jr, size_t pos, mip_gnss_data_clock_info_t *out) {
    static const char *const keys[] = {"bias", "drift", "accuracy_estimate", "valid_flags"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mip_jr_object(jr, pos, keys, 4)) {
        return -1;
    }
    found = mip_jr_get(jr, pos, "bias", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"bias\"");
    }
    {
        mip_jr_push(jr, "bias");
        if (mip_jr_f64(jr, vp, &out->bias)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "drift", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"drift\"");
    }
    {
        mip_jr_push(jr, "drift");
        if (mip_jr_f64(jr, vp, &out->drift)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "accuracy_estimate", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"accuracy_estimate\"");
    }
    {
        mip_jr_push(jr, "accuracy_estimate");
        if (mip_jr_f64(jr, vp, &out->accuracy_estimate)) {
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

/* ---- mip_gnss_data_fix_info_t */

static int mip_gnss_data_fix_info_read(mip_reader_t *r, mip_gnss_data_fix_info_t *out) {
    mip_rd_push(r, "fix_type");
    if (mip_rd_u8(r, &out->fix_type)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "num_sv");
    if (mip_rd_u8(r, &out->num_sv)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "fix_flags");
    if (mip_rd_u16(r, &out->fix_flags)) {
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

static mip_status_t mip_gnss_data_fix_info_write(mip_writer_t *w, const mip_gnss_data_fix_info_t *in) {
    mip_status_t st;
    if ((st = mip_wr_u8(w, &in->fix_type)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_u8(w, &in->num_sv)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_u16(w, &in->fix_flags)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_u16(w, &in->valid_flags)) != MIP_OK) {
        return st;
    }
    return MIP_OK;
}

mip_status_t mip_gnss_data_fix_info_encode(const mip_gnss_data_fix_info_t *value, uint8_t *buf, size_t cap,
                                           size_t *len_out) {
    mip_writer_t w;
    mip_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mip_writer_init(&w, buf, cap);
    st = mip_gnss_data_fix_info_write(&w, value);
    if (st == MIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 6 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mip_gnss_data_fix_info_load(const uint8_t *d, mip_gnss_data_fix_info_t *out) {
    out->fix_type = mip_ld_u8(d + 0);
    out->num_sv = mip_ld_u8(d + 1);
    out->fix_flags = mip_ld_u16(d + 2);
    out->valid_flags = mip_ld_u16(d + 4);
    return 0;
}

/* The general reader: lengths other than 6, bad bool bytes, error details. */
static MIP_NOINLINE mip_status_t mip_gnss_data_fix_info_decode_read(const uint8_t *data, size_t len,
                                                                    mip_gnss_data_fix_info_t *out,
                                                                    mip_decode_error_t *err) {
    mip_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mip_gnss_data_fix_info_read(&r, out) ? MIP_ERR_DECODE : MIP_OK;
}

mip_status_t mip_gnss_data_fix_info_decode(const uint8_t *data, size_t len, mip_gnss_data_fix_info_t *out,
                                           mip_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 6 && mip_gnss_data_fix_info_load(data, out) == 0) {
        return MIP_OK;
    }
    return mip_gnss_data_fix_info_decode_read(data, len, out, err);
}

void mip_gnss_data_fix_info_to_json(mip_jw_t *w, const mip_gnss_data_fix_info_t *in) {
    int first = 1;
    mip_jw_raw(w, "{", 1);
    mip_jw_key(w, &first, "fix_type");
    mip_jw_u8(w, &in->fix_type);
    mip_jw_key(w, &first, "num_sv");
    mip_jw_u8(w, &in->num_sv);
    mip_jw_key(w, &first, "fix_flags");
    mip_jw_u16(w, &in->fix_flags);
    mip_jw_key(w, &first, "valid_flags");
    mip_jw_u16(w, &in->valid_flags);
    mip_jw_raw(w, "}", 1);
}

int mip_gnss_data_fix_info_from_json(mip_jr_t *jr, size_t pos, mip_gnss_data_fix_info_t *out) {
    static const char *const keys[] = {"fix_type", "num_sv", "fix_flags", "valid_flags"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mip_jr_object(jr, pos, keys, 4)) {
        return -1;
    }
    found = mip_jr_get(jr, pos, "fix_type", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"fix_type\"");
    }
    {
        mip_jr_push(jr, "fix_type");
        if (mip_jr_u8(jr, vp, &out->fix_type)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "num_sv", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"num_sv\"");
    }
    {
        mip_jr_push(jr, "num_sv");
        if (mip_jr_u8(jr, vp, &out->num_sv)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "fix_flags", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"fix_flags\"");
    }
    {
        mip_jr_push(jr, "fix_flags");
        if (mip_jr_u16(jr, vp, &out->fix_flags)) {
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

/* ---- mip_gnss_data_sv_info_t */

static int mip_gnss_data_sv_info_read(mip_reader_t *r, mip_gnss_data_sv_info_t *out) {
    mip_rd_push(r, "channel");
    if (mip_rd_u8(r, &out->channel)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "sv_id");
    if (mip_rd_u8(r, &out->sv_id)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "carrier_to_noise_ratio");
    if (mip_rd_u16(r, &out->carrier_to_noise_ratio)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "azimuth");
    if (mip_rd_s16(r, &out->azimuth)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "elevation");
    if (mip_rd_s16(r, &out->elevation)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "sv_flags");
    if (mip_rd_u16(r, &out->sv_flags)) {
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

static mip_status_t mip_gnss_data_sv_info_write(mip_writer_t *w, const mip_gnss_data_sv_info_t *in) {
    mip_status_t st;
    if ((st = mip_wr_u8(w, &in->channel)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_u8(w, &in->sv_id)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_u16(w, &in->carrier_to_noise_ratio)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_s16(w, &in->azimuth)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_s16(w, &in->elevation)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_u16(w, &in->sv_flags)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_u16(w, &in->valid_flags)) != MIP_OK) {
        return st;
    }
    return MIP_OK;
}

mip_status_t mip_gnss_data_sv_info_encode(const mip_gnss_data_sv_info_t *value, uint8_t *buf, size_t cap,
                                          size_t *len_out) {
    mip_writer_t w;
    mip_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mip_writer_init(&w, buf, cap);
    st = mip_gnss_data_sv_info_write(&w, value);
    if (st == MIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 12 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mip_gnss_data_sv_info_load(const uint8_t *d, mip_gnss_data_sv_info_t *out) {
    out->channel = mip_ld_u8(d + 0);
    out->sv_id = mip_ld_u8(d + 1);
    out->carrier_to_noise_ratio = mip_ld_u16(d + 2);
    out->azimuth = mip_ld_s16(d + 4);
    out->elevation = mip_ld_s16(d + 6);
    out->sv_flags = mip_ld_u16(d + 8);
    out->valid_flags = mip_ld_u16(d + 10);
    return 0;
}

/* The general reader: lengths other than 12, bad bool bytes, error details. */
static MIP_NOINLINE mip_status_t mip_gnss_data_sv_info_decode_read(const uint8_t *data, size_t len,
                                                                   mip_gnss_data_sv_info_t *out,
                                                                   mip_decode_error_t *err) {
    mip_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mip_gnss_data_sv_info_read(&r, out) ? MIP_ERR_DECODE : MIP_OK;
}

mip_status_t mip_gnss_data_sv_info_decode(const uint8_t *data, size_t len, mip_gnss_data_sv_info_t *out,
                                          mip_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 12 && mip_gnss_data_sv_info_load(data, out) == 0) {
        return MIP_OK;
    }
    return mip_gnss_data_sv_info_decode_read(data, len, out, err);
}

void mip_gnss_data_sv_info_to_json(mip_jw_t *w, const mip_gnss_data_sv_info_t *in) {
    int first = 1;
    mip_jw_raw(w, "{", 1);
    mip_jw_key(w, &first, "channel");
    mip_jw_u8(w, &in->channel);
    mip_jw_key(w, &first, "sv_id");
    mip_jw_u8(w, &in->sv_id);
    mip_jw_key(w, &first, "carrier_to_noise_ratio");
    mip_jw_u16(w, &in->carrier_to_noise_ratio);
    mip_jw_key(w, &first, "azimuth");
    mip_jw_s16(w, &in->azimuth);
    mip_jw_key(w, &first, "elevation");
    mip_jw_s16(w, &in->elevation);
    mip_jw_key(w, &first, "sv_flags");
    mip_jw_u16(w, &in->sv_flags);
    mip_jw_key(w, &first, "valid_flags");
    mip_jw_u16(w, &in->valid_flags);
    mip_jw_raw(w, "}", 1);
}

int mip_gnss_data_sv_info_from_json(mip_jr_t *jr, size_t pos, mip_gnss_data_sv_info_t *out) {
    static const char *const keys[] = {
        "channel", "sv_id", "carrier_to_noise_ratio", "azimuth", "elevation", "sv_flags", "valid_flags"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mip_jr_object(jr, pos, keys, 7)) {
        return -1;
    }
    found = mip_jr_get(jr, pos, "channel", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"channel\"");
    }
    {
        mip_jr_push(jr, "channel");
        if (mip_jr_u8(jr, vp, &out->channel)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "sv_id", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"sv_id\"");
    }
    {
        mip_jr_push(jr, "sv_id");
        if (mip_jr_u8(jr, vp, &out->sv_id)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "carrier_to_noise_ratio", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"carrier_to_noise_ratio\"");
    }
    {
        mip_jr_push(jr, "carrier_to_noise_ratio");
        if (mip_jr_u16(jr, vp, &out->carrier_to_noise_ratio)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "azimuth", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"azimuth\"");
    }
    {
        mip_jr_push(jr, "azimuth");
        if (mip_jr_s16(jr, vp, &out->azimuth)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "elevation", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"elevation\"");
    }
    {
        mip_jr_push(jr, "elevation");
        if (mip_jr_s16(jr, vp, &out->elevation)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "sv_flags", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"sv_flags\"");
    }
    {
        mip_jr_push(jr, "sv_flags");
        if (mip_jr_u16(jr, vp, &out->sv_flags)) {
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

/* ---- mip_gnss_data_hardware_status_t */

static int mip_gnss_data_hardware_status_read(mip_reader_t *r, mip_gnss_data_hardware_status_t *out) {
    mip_rd_push(r, "receiver_state");
    if (mip_rd_u8(r, &out->receiver_state)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "antenna_state");
    if (mip_rd_u8(r, &out->antenna_state)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "antenna_power");
    if (mip_rd_u8(r, &out->antenna_power)) {
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

static mip_status_t mip_gnss_data_hardware_status_write(mip_writer_t *w,
                                                        const mip_gnss_data_hardware_status_t *in) {
    mip_status_t st;
    if ((st = mip_wr_u8(w, &in->receiver_state)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_u8(w, &in->antenna_state)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_u8(w, &in->antenna_power)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_u16(w, &in->valid_flags)) != MIP_OK) {
        return st;
    }
    return MIP_OK;
}

mip_status_t mip_gnss_data_hardware_status_encode(const mip_gnss_data_hardware_status_t *value, uint8_t *buf,
                                                  size_t cap, size_t *len_out) {
    mip_writer_t w;
    mip_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mip_writer_init(&w, buf, cap);
    st = mip_gnss_data_hardware_status_write(&w, value);
    if (st == MIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 5 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mip_gnss_data_hardware_status_load(const uint8_t *d, mip_gnss_data_hardware_status_t *out) {
    out->receiver_state = mip_ld_u8(d + 0);
    out->antenna_state = mip_ld_u8(d + 1);
    out->antenna_power = mip_ld_u8(d + 2);
    out->valid_flags = mip_ld_u16(d + 3);
    return 0;
}

/* The general reader: lengths other than 5, bad bool bytes, error details. */
static MIP_NOINLINE mip_status_t mip_gnss_data_hardware_status_decode_read(
    const uint8_t *data, size_t len, mip_gnss_data_hardware_status_t *out, mip_decode_error_t *err) {
    mip_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mip_gnss_data_hardware_status_read(&r, out) ? MIP_ERR_DECODE : MIP_OK;
}

mip_status_t mip_gnss_data_hardware_status_decode(const uint8_t *data, size_t len,
                                                  mip_gnss_data_hardware_status_t *out,
                                                  mip_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 5 && mip_gnss_data_hardware_status_load(data, out) == 0) {
        return MIP_OK;
    }
    return mip_gnss_data_hardware_status_decode_read(data, len, out, err);
}

void mip_gnss_data_hardware_status_to_json(mip_jw_t *w, const mip_gnss_data_hardware_status_t *in) {
    int first = 1;
    mip_jw_raw(w, "{", 1);
    mip_jw_key(w, &first, "receiver_state");
    mip_jw_u8(w, &in->receiver_state);
    mip_jw_key(w, &first, "antenna_state");
    mip_jw_u8(w, &in->antenna_state);
    mip_jw_key(w, &first, "antenna_power");
    mip_jw_u8(w, &in->antenna_power);
    mip_jw_key(w, &first, "valid_flags");
    mip_jw_u16(w, &in->valid_flags);
    mip_jw_raw(w, "}", 1);
}

int mip_gnss_data_hardware_status_from_json(mip_jr_t *jr, size_t pos, mip_gnss_data_hardware_status_t *out) {
    static const char *const keys[] = {"receiver_state", "antenna_state", "antenna_power", "valid_flags"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mip_jr_object(jr, pos, keys, 4)) {
        return -1;
    }
    found = mip_jr_get(jr, pos, "receiver_state", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"receiver_state\"");
    }
    {
        mip_jr_push(jr, "receiver_state");
        if (mip_jr_u8(jr, vp, &out->receiver_state)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "antenna_state", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"antenna_state\"");
    }
    {
        mip_jr_push(jr, "antenna_state");
        if (mip_jr_u8(jr, vp, &out->antenna_state)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "antenna_power", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"antenna_power\"");
    }
    {
        mip_jr_push(jr, "antenna_power");
        if (mip_jr_u8(jr, vp, &out->antenna_power)) {
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

/* ---- mip_gnss_data_dgnss_info_t */

static int mip_gnss_data_dgnss_info_read(mip_reader_t *r, mip_gnss_data_dgnss_info_t *out) {
    mip_rd_push(r, "newest_age");
    if (mip_rd_f32(r, &out->newest_age)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "base_station_id");
    if (mip_rd_s16(r, &out->base_station_id)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "base_station_status");
    if (mip_rd_s16(r, &out->base_station_status)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "num_channels");
    if (mip_rd_u16(r, &out->num_channels)) {
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

static mip_status_t mip_gnss_data_dgnss_info_write(mip_writer_t *w, const mip_gnss_data_dgnss_info_t *in) {
    mip_status_t st;
    if ((st = mip_wr_f32(w, &in->newest_age)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_s16(w, &in->base_station_id)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_s16(w, &in->base_station_status)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_u16(w, &in->num_channels)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_u16(w, &in->valid_flags)) != MIP_OK) {
        return st;
    }
    return MIP_OK;
}

mip_status_t mip_gnss_data_dgnss_info_encode(const mip_gnss_data_dgnss_info_t *value, uint8_t *buf,
                                             size_t cap, size_t *len_out) {
    mip_writer_t w;
    mip_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mip_writer_init(&w, buf, cap);
    st = mip_gnss_data_dgnss_info_write(&w, value);
    if (st == MIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 12 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mip_gnss_data_dgnss_info_load(const uint8_t *d, mip_gnss_data_dgnss_info_t *out) {
    out->newest_age = mip_ld_f32(d + 0);
    out->base_station_id = mip_ld_s16(d + 4);
    out->base_station_status = mip_ld_s16(d + 6);
    out->num_channels = mip_ld_u16(d + 8);
    out->valid_flags = mip_ld_u16(d + 10);
    return 0;
}

/* The general reader: lengths other than 12, bad bool bytes, error details. */
static MIP_NOINLINE mip_status_t mip_gnss_data_dgnss_info_decode_read(const uint8_t *data, size_t len,
                                                                      mip_gnss_data_dgnss_info_t *out,
                                                                      mip_decode_error_t *err) {
    mip_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mip_gnss_data_dgnss_info_read(&r, out) ? MIP_ERR_DECODE : MIP_OK;
}

mip_status_t mip_gnss_data_dgnss_info_decode(const uint8_t *data, size_t len, mip_gnss_data_dgnss_info_t *out,
                                             mip_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 12 && mip_gnss_data_dgnss_info_load(data, out) == 0) {
        return MIP_OK;
    }
    return mip_gnss_data_dgnss_info_decode_read(data, len, out, err);
}

void mip_gnss_data_dgnss_info_to_json(mip_jw_t *w, const mip_gnss_data_dgnss_info_t *in) {
    int first = 1;
    mip_jw_raw(w, "{", 1);
    mip_jw_key(w, &first, "newest_age");
    mip_jw_f32(w, &in->newest_age);
    mip_jw_key(w, &first, "base_station_id");
    mip_jw_s16(w, &in->base_station_id);
    mip_jw_key(w, &first, "base_station_status");
    mip_jw_s16(w, &in->base_station_status);
    mip_jw_key(w, &first, "num_channels");
    mip_jw_u16(w, &in->num_channels);
    mip_jw_key(w, &first, "valid_flags");
    mip_jw_u16(w, &in->valid_flags);
    mip_jw_raw(w, "}", 1);
}

int mip_gnss_data_dgnss_info_from_json(mip_jr_t *jr, size_t pos, mip_gnss_data_dgnss_info_t *out) {
    static const char *const keys[] = {"newest_age", "base_station_id", "base_station_status", "num_channels",
                                       "valid_flags"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mip_jr_object(jr, pos, keys, 5)) {
        return -1;
    }
    found = mip_jr_get(jr, pos, "newest_age", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"newest_age\"");
    }
    {
        mip_jr_push(jr, "newest_age");
        if (mip_jr_f32(jr, vp, &out->newest_age)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "base_station_id", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"base_station_id\"");
    }
    {
        mip_jr_push(jr, "base_station_id");
        if (mip_jr_s16(jr, vp, &out->base_station_id)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "base_station_status", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"base_station_status\"");
    }
    {
        mip_jr_push(jr, "base_station_status");
        if (mip_jr_s16(jr, vp, &out->base_station_status)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "num_channels", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"num_channels\"");
    }
    {
        mip_jr_push(jr, "num_channels");
        if (mip_jr_u16(jr, vp, &out->num_channels)) {
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

/* ---- mip_gnss_data_dgnss_channel_status_t */

static int mip_gnss_data_dgnss_channel_status_read(mip_reader_t *r,
                                                   mip_gnss_data_dgnss_channel_status_t *out) {
    mip_rd_push(r, "sv_id");
    if (mip_rd_u8(r, &out->sv_id)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "age");
    if (mip_rd_f32(r, &out->age)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "pseudorange_correction");
    if (mip_rd_f32(r, &out->pseudorange_correction)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "pseudorange_rate_correction");
    if (mip_rd_f32(r, &out->pseudorange_rate_correction)) {
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

static mip_status_t mip_gnss_data_dgnss_channel_status_write(mip_writer_t *w,
                                                             const mip_gnss_data_dgnss_channel_status_t *in) {
    mip_status_t st;
    if ((st = mip_wr_u8(w, &in->sv_id)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_f32(w, &in->age)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_f32(w, &in->pseudorange_correction)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_f32(w, &in->pseudorange_rate_correction)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_u16(w, &in->valid_flags)) != MIP_OK) {
        return st;
    }
    return MIP_OK;
}

mip_status_t mip_gnss_data_dgnss_channel_status_encode(const mip_gnss_data_dgnss_channel_status_t *value,
                                                       uint8_t *buf, size_t cap, size_t *len_out) {
    mip_writer_t w;
    mip_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mip_writer_init(&w, buf, cap);
    st = mip_gnss_data_dgnss_channel_status_write(&w, value);
    if (st == MIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 15 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mip_gnss_data_dgnss_channel_status_load(const uint8_t *d,
                                                   mip_gnss_data_dgnss_channel_status_t *out) {
    out->sv_id = mip_ld_u8(d + 0);
    out->age = mip_ld_f32(d + 1);
    out->pseudorange_correction = mip_ld_f32(d + 5);
    out->pseudorange_rate_correction = mip_ld_f32(d + 9);
    out->valid_flags = mip_ld_u16(d + 13);
    return 0;
}

/* The general reader: lengths other than 15, bad bool bytes, error details. */
static MIP_NOINLINE mip_status_t mip_gnss_data_dgnss_channel_status_decode_read(
    const uint8_t *data, size_t len, mip_gnss_data_dgnss_channel_status_t *out, mip_decode_error_t *err) {
    mip_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mip_gnss_data_dgnss_channel_status_read(&r, out) ? MIP_ERR_DECODE : MIP_OK;
}

mip_status_t mip_gnss_data_dgnss_channel_status_decode(const uint8_t *data, size_t len,
                                                       mip_gnss_data_dgnss_channel_status_t *out,
                                                       mip_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 15 && mip_gnss_data_dgnss_channel_status_load(data, out) == 0) {
        return MIP_OK;
    }
    return mip_gnss_data_dgnss_channel_status_decode_read(data, len, out, err);
}

void mip_gnss_data_dgnss_channel_status_to_json(mip_jw_t *w, const mip_gnss_data_dgnss_channel_status_t *in) {
    int first = 1;
    mip_jw_raw(w, "{", 1);
    mip_jw_key(w, &first, "sv_id");
    mip_jw_u8(w, &in->sv_id);
    mip_jw_key(w, &first, "age");
    mip_jw_f32(w, &in->age);
    mip_jw_key(w, &first, "pseudorange_correction");
    mip_jw_f32(w, &in->pseudorange_correction);
    mip_jw_key(w, &first, "pseudorange_rate_correction");
    mip_jw_f32(w, &in->pseudorange_rate_correction);
    mip_jw_key(w, &first, "valid_flags");
    mip_jw_u16(w, &in->valid_flags);
    mip_jw_raw(w, "}", 1);
}

int mip_gnss_data_dgnss_channel_status_from_json(mip_jr_t *jr, size_t pos,
                                                 mip_gnss_data_dgnss_channel_status_t *out) {
    static const char *const keys[] = {"sv_id", "age", "pseudorange_correction",
                                       "pseudorange_rate_correction", "valid_flags"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mip_jr_object(jr, pos, keys, 5)) {
        return -1;
    }
    found = mip_jr_get(jr, pos, "sv_id", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"sv_id\"");
    }
    {
        mip_jr_push(jr, "sv_id");
        if (mip_jr_u8(jr, vp, &out->sv_id)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "age", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"age\"");
    }
    {
        mip_jr_push(jr, "age");
        if (mip_jr_f32(jr, vp, &out->age)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "pseudorange_correction", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"pseudorange_correction\"");
    }
    {
        mip_jr_push(jr, "pseudorange_correction");
        if (mip_jr_f32(jr, vp, &out->pseudorange_correction)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "pseudorange_rate_correction", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"pseudorange_rate_correction\"");
    }
    {
        mip_jr_push(jr, "pseudorange_rate_correction");
        if (mip_jr_f32(jr, vp, &out->pseudorange_rate_correction)) {
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
