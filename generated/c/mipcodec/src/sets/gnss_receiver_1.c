/* Encoders and decoders of GNSS Receiver 1 Data Set. Generated from the spec: do not edit. */
#include "mipcodec/sets/gnss_receiver_1.h"
#include "layouts_internal.h"
#include "types_internal.h"

#include <assert.h>
#include <string.h>

/* ---- mip_gnss_receiver_1_llh_position_t */

static int mip_gnss_receiver_1_llh_position_read(mip_reader_t *r, mip_gnss_receiver_1_llh_position_t *out) {
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

static mip_status_t mip_gnss_receiver_1_llh_position_write(mip_writer_t *w,
                                                           const mip_gnss_receiver_1_llh_position_t *in) {
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

mip_status_t mip_gnss_receiver_1_llh_position_encode(const mip_gnss_receiver_1_llh_position_t *value,
                                                     uint8_t *buf, size_t cap, size_t *len_out) {
    mip_writer_t w;
    mip_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mip_writer_init(&w, buf, cap);
    st = mip_gnss_receiver_1_llh_position_write(&w, value);
    if (st == MIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 42 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mip_gnss_receiver_1_llh_position_load(const uint8_t *d, mip_gnss_receiver_1_llh_position_t *out) {
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
static MIP_NOINLINE mip_status_t mip_gnss_receiver_1_llh_position_decode_read(
    const uint8_t *data, size_t len, mip_gnss_receiver_1_llh_position_t *out, mip_decode_error_t *err) {
    mip_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mip_gnss_receiver_1_llh_position_read(&r, out) ? MIP_ERR_DECODE : MIP_OK;
}

mip_status_t mip_gnss_receiver_1_llh_position_decode(const uint8_t *data, size_t len,
                                                     mip_gnss_receiver_1_llh_position_t *out,
                                                     mip_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 42 && mip_gnss_receiver_1_llh_position_load(data, out) == 0) {
        return MIP_OK;
    }
    return mip_gnss_receiver_1_llh_position_decode_read(data, len, out, err);
}

void mip_gnss_receiver_1_llh_position_to_json(mip_jw_t *w, const mip_gnss_receiver_1_llh_position_t *in) {
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

int mip_gnss_receiver_1_llh_position_from_json(mip_jr_t *jr, size_t pos,
                                               mip_gnss_receiver_1_llh_position_t *out) {
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

/* ---- mip_gnss_receiver_1_ecef_position_t */

static int mip_gnss_receiver_1_ecef_position_read(mip_reader_t *r, mip_gnss_receiver_1_ecef_position_t *out) {
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

static mip_status_t mip_gnss_receiver_1_ecef_position_write(mip_writer_t *w,
                                                            const mip_gnss_receiver_1_ecef_position_t *in) {
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

mip_status_t mip_gnss_receiver_1_ecef_position_encode(const mip_gnss_receiver_1_ecef_position_t *value,
                                                      uint8_t *buf, size_t cap, size_t *len_out) {
    mip_writer_t w;
    mip_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mip_writer_init(&w, buf, cap);
    st = mip_gnss_receiver_1_ecef_position_write(&w, value);
    if (st == MIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 30 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mip_gnss_receiver_1_ecef_position_load(const uint8_t *d,
                                                  mip_gnss_receiver_1_ecef_position_t *out) {
    out->position[0] = mip_ld_f64(d + 0);
    out->position[1] = mip_ld_f64(d + 8);
    out->position[2] = mip_ld_f64(d + 16);
    out->position_accuracy = mip_ld_f32(d + 24);
    out->valid_flags = mip_ld_u16(d + 28);
    return 0;
}

/* The general reader: lengths other than 30, bad bool bytes, error details. */
static MIP_NOINLINE mip_status_t mip_gnss_receiver_1_ecef_position_decode_read(
    const uint8_t *data, size_t len, mip_gnss_receiver_1_ecef_position_t *out, mip_decode_error_t *err) {
    mip_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mip_gnss_receiver_1_ecef_position_read(&r, out) ? MIP_ERR_DECODE : MIP_OK;
}

mip_status_t mip_gnss_receiver_1_ecef_position_decode(const uint8_t *data, size_t len,
                                                      mip_gnss_receiver_1_ecef_position_t *out,
                                                      mip_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 30 && mip_gnss_receiver_1_ecef_position_load(data, out) == 0) {
        return MIP_OK;
    }
    return mip_gnss_receiver_1_ecef_position_decode_read(data, len, out, err);
}

void mip_gnss_receiver_1_ecef_position_to_json(mip_jw_t *w, const mip_gnss_receiver_1_ecef_position_t *in) {
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

int mip_gnss_receiver_1_ecef_position_from_json(mip_jr_t *jr, size_t pos,
                                                mip_gnss_receiver_1_ecef_position_t *out) {
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

/* ---- mip_gnss_receiver_1_ned_velocity_t */

static int mip_gnss_receiver_1_ned_velocity_read(mip_reader_t *r, mip_gnss_receiver_1_ned_velocity_t *out) {
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

static mip_status_t mip_gnss_receiver_1_ned_velocity_write(mip_writer_t *w,
                                                           const mip_gnss_receiver_1_ned_velocity_t *in) {
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

mip_status_t mip_gnss_receiver_1_ned_velocity_encode(const mip_gnss_receiver_1_ned_velocity_t *value,
                                                     uint8_t *buf, size_t cap, size_t *len_out) {
    mip_writer_t w;
    mip_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mip_writer_init(&w, buf, cap);
    st = mip_gnss_receiver_1_ned_velocity_write(&w, value);
    if (st == MIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 34 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mip_gnss_receiver_1_ned_velocity_load(const uint8_t *d, mip_gnss_receiver_1_ned_velocity_t *out) {
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
static MIP_NOINLINE mip_status_t mip_gnss_receiver_1_ned_velocity_decode_read(
    const uint8_t *data, size_t len, mip_gnss_receiver_1_ned_velocity_t *out, mip_decode_error_t *err) {
    mip_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mip_gnss_receiver_1_ned_velocity_read(&r, out) ? MIP_ERR_DECODE : MIP_OK;
}

mip_status_t mip_gnss_receiver_1_ned_velocity_decode(const uint8_t *data, size_t len,
                                                     mip_gnss_receiver_1_ned_velocity_t *out,
                                                     mip_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 34 && mip_gnss_receiver_1_ned_velocity_load(data, out) == 0) {
        return MIP_OK;
    }
    return mip_gnss_receiver_1_ned_velocity_decode_read(data, len, out, err);
}

void mip_gnss_receiver_1_ned_velocity_to_json(mip_jw_t *w, const mip_gnss_receiver_1_ned_velocity_t *in) {
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

int mip_gnss_receiver_1_ned_velocity_from_json(mip_jr_t *jr, size_t pos,
                                               mip_gnss_receiver_1_ned_velocity_t *out) {
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

/* ---- mip_gnss_receiver_1_ecef_velocity_t */

static int mip_gnss_receiver_1_ecef_velocity_read(mip_reader_t *r, mip_gnss_receiver_1_ecef_velocity_t *out) {
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

static mip_status_t mip_gnss_receiver_1_ecef_velocity_write(mip_writer_t *w,
                                                            const mip_gnss_receiver_1_ecef_velocity_t *in) {
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

mip_status_t mip_gnss_receiver_1_ecef_velocity_encode(const mip_gnss_receiver_1_ecef_velocity_t *value,
                                                      uint8_t *buf, size_t cap, size_t *len_out) {
    mip_writer_t w;
    mip_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mip_writer_init(&w, buf, cap);
    st = mip_gnss_receiver_1_ecef_velocity_write(&w, value);
    if (st == MIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 18 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mip_gnss_receiver_1_ecef_velocity_load(const uint8_t *d,
                                                  mip_gnss_receiver_1_ecef_velocity_t *out) {
    out->velocity[0] = mip_ld_f32(d + 0);
    out->velocity[1] = mip_ld_f32(d + 4);
    out->velocity[2] = mip_ld_f32(d + 8);
    out->velocity_accuracy = mip_ld_f32(d + 12);
    out->valid_flags = mip_ld_u16(d + 16);
    return 0;
}

/* The general reader: lengths other than 18, bad bool bytes, error details. */
static MIP_NOINLINE mip_status_t mip_gnss_receiver_1_ecef_velocity_decode_read(
    const uint8_t *data, size_t len, mip_gnss_receiver_1_ecef_velocity_t *out, mip_decode_error_t *err) {
    mip_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mip_gnss_receiver_1_ecef_velocity_read(&r, out) ? MIP_ERR_DECODE : MIP_OK;
}

mip_status_t mip_gnss_receiver_1_ecef_velocity_decode(const uint8_t *data, size_t len,
                                                      mip_gnss_receiver_1_ecef_velocity_t *out,
                                                      mip_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 18 && mip_gnss_receiver_1_ecef_velocity_load(data, out) == 0) {
        return MIP_OK;
    }
    return mip_gnss_receiver_1_ecef_velocity_decode_read(data, len, out, err);
}

void mip_gnss_receiver_1_ecef_velocity_to_json(mip_jw_t *w, const mip_gnss_receiver_1_ecef_velocity_t *in) {
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

int mip_gnss_receiver_1_ecef_velocity_from_json(mip_jr_t *jr, size_t pos,
                                                mip_gnss_receiver_1_ecef_velocity_t *out) {
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

/* ---- mip_gnss_receiver_1_dop_t */

static int mip_gnss_receiver_1_dop_read(mip_reader_t *r, mip_gnss_receiver_1_dop_t *out) {
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

static mip_status_t mip_gnss_receiver_1_dop_write(mip_writer_t *w, const mip_gnss_receiver_1_dop_t *in) {
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

mip_status_t mip_gnss_receiver_1_dop_encode(const mip_gnss_receiver_1_dop_t *value, uint8_t *buf, size_t cap,
                                            size_t *len_out) {
    mip_writer_t w;
    mip_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mip_writer_init(&w, buf, cap);
    st = mip_gnss_receiver_1_dop_write(&w, value);
    if (st == MIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 30 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mip_gnss_receiver_1_dop_load(const uint8_t *d, mip_gnss_receiver_1_dop_t *out) {
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
static MIP_NOINLINE mip_status_t mip_gnss_receiver_1_dop_decode_read(const uint8_t *data, size_t len,
                                                                     mip_gnss_receiver_1_dop_t *out,
                                                                     mip_decode_error_t *err) {
    mip_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mip_gnss_receiver_1_dop_read(&r, out) ? MIP_ERR_DECODE : MIP_OK;
}

mip_status_t mip_gnss_receiver_1_dop_decode(const uint8_t *data, size_t len, mip_gnss_receiver_1_dop_t *out,
                                            mip_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 30 && mip_gnss_receiver_1_dop_load(data, out) == 0) {
        return MIP_OK;
    }
    return mip_gnss_receiver_1_dop_decode_read(data, len, out, err);
}

void mip_gnss_receiver_1_dop_to_json(mip_jw_t *w, const mip_gnss_receiver_1_dop_t *in) {
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

int mip_gnss_receiver_1_dop_from_json(mip_jr_t *jr, size_t pos, mip_gnss_receiver_1_dop_t *out) {
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

/* ---- mip_gnss_receiver_1_utc_time_t */

static int mip_gnss_receiver_1_utc_time_read(mip_reader_t *r, mip_gnss_receiver_1_utc_time_t *out) {
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

static mip_status_t mip_gnss_receiver_1_utc_time_write(mip_writer_t *w,
                                                       const mip_gnss_receiver_1_utc_time_t *in) {
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

mip_status_t mip_gnss_receiver_1_utc_time_encode(const mip_gnss_receiver_1_utc_time_t *value, uint8_t *buf,
                                                 size_t cap, size_t *len_out) {
    mip_writer_t w;
    mip_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mip_writer_init(&w, buf, cap);
    st = mip_gnss_receiver_1_utc_time_write(&w, value);
    if (st == MIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 13 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mip_gnss_receiver_1_utc_time_load(const uint8_t *d, mip_gnss_receiver_1_utc_time_t *out) {
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
static MIP_NOINLINE mip_status_t mip_gnss_receiver_1_utc_time_decode_read(const uint8_t *data, size_t len,
                                                                          mip_gnss_receiver_1_utc_time_t *out,
                                                                          mip_decode_error_t *err) {
    mip_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mip_gnss_receiver_1_utc_time_read(&r, out) ? MIP_ERR_DECODE : MIP_OK;
}

mip_status_t mip_gnss_receiver_1_utc_time_decode(const uint8_t *data, size_t len,
                                                 mip_gnss_receiver_1_utc_time_t *out,
                                                 mip_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 13 && mip_gnss_receiver_1_utc_time_load(data, out) == 0) {
        return MIP_OK;
    }
    return mip_gnss_receiver_1_utc_time_decode_read(data, len, out, err);
}

void mip_gnss_receiver_1_utc_time_to_json(mip_jw_t *w, const mip_gnss_receiver_1_utc_time_t *in) {
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

int mip_gnss_receiver_1_utc_time_from_json(mip_jr_t *jr, size_t pos, mip_gnss_receiver_1_utc_time_t *out) {
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

/* ---- mip_gnss_receiver_1_gps_time_t */

static int mip_gnss_receiver_1_gps_time_read(mip_reader_t *r, mip_gnss_receiver_1_gps_time_t *out) {
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

static mip_status_t mip_gnss_receiver_1_gps_time_write(mip_writer_t *w,
                                                       const mip_gnss_receiver_1_gps_time_t *in) {
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

mip_status_t mip_gnss_receiver_1_gps_time_encode(const mip_gnss_receiver_1_gps_time_t *value, uint8_t *buf,
                                                 size_t cap, size_t *len_out) {
    mip_writer_t w;
    mip_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mip_writer_init(&w, buf, cap);
    st = mip_gnss_receiver_1_gps_time_write(&w, value);
    if (st == MIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 12 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mip_gnss_receiver_1_gps_time_load(const uint8_t *d, mip_gnss_receiver_1_gps_time_t *out) {
    out->tow = mip_ld_f64(d + 0);
    out->week_number = mip_ld_u16(d + 8);
    out->valid_flags = mip_ld_u16(d + 10);
    return 0;
}

/* The general reader: lengths other than 12, bad bool bytes, error details. */
static MIP_NOINLINE mip_status_t mip_gnss_receiver_1_gps_time_decode_read(const uint8_t *data, size_t len,
                                                                          mip_gnss_receiver_1_gps_time_t *out,
                                                                          mip_decode_error_t *err) {
    mip_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mip_gnss_receiver_1_gps_time_read(&r, out) ? MIP_ERR_DECODE : MIP_OK;
}

mip_status_t mip_gnss_receiver_1_gps_time_decode(const uint8_t *data, size_t len,
                                                 mip_gnss_receiver_1_gps_time_t *out,
                                                 mip_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 12 && mip_gnss_receiver_1_gps_time_load(data, out) == 0) {
        return MIP_OK;
    }
    return mip_gnss_receiver_1_gps_time_decode_read(data, len, out, err);
}

void mip_gnss_receiver_1_gps_time_to_json(mip_jw_t *w, const mip_gnss_receiver_1_gps_time_t *in) {
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

int mip_gnss_receiver_1_gps_time_from_json(mip_jr_t *jr, size_t pos, mip_gnss_receiver_1_gps_time_t *out) {
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

/* ---- mip_gnss_receiver_1_fix_info_t */

static int mip_gnss_receiver_1_fix_info_read(mip_reader_t *r, mip_gnss_receiver_1_fix_info_t *out) {
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

static mip_status_t mip_gnss_receiver_1_fix_info_write(mip_writer_t *w,
                                                       const mip_gnss_receiver_1_fix_info_t *in) {
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

mip_status_t mip_gnss_receiver_1_fix_info_encode(const mip_gnss_receiver_1_fix_info_t *value, uint8_t *buf,
                                                 size_t cap, size_t *len_out) {
    mip_writer_t w;
    mip_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mip_writer_init(&w, buf, cap);
    st = mip_gnss_receiver_1_fix_info_write(&w, value);
    if (st == MIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 6 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mip_gnss_receiver_1_fix_info_load(const uint8_t *d, mip_gnss_receiver_1_fix_info_t *out) {
    out->fix_type = mip_ld_u8(d + 0);
    out->num_sv = mip_ld_u8(d + 1);
    out->fix_flags = mip_ld_u16(d + 2);
    out->valid_flags = mip_ld_u16(d + 4);
    return 0;
}

/* The general reader: lengths other than 6, bad bool bytes, error details. */
static MIP_NOINLINE mip_status_t mip_gnss_receiver_1_fix_info_decode_read(const uint8_t *data, size_t len,
                                                                          mip_gnss_receiver_1_fix_info_t *out,
                                                                          mip_decode_error_t *err) {
    mip_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mip_gnss_receiver_1_fix_info_read(&r, out) ? MIP_ERR_DECODE : MIP_OK;
}

mip_status_t mip_gnss_receiver_1_fix_info_decode(const uint8_t *data, size_t len,
                                                 mip_gnss_receiver_1_fix_info_t *out,
                                                 mip_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 6 && mip_gnss_receiver_1_fix_info_load(data, out) == 0) {
        return MIP_OK;
    }
    return mip_gnss_receiver_1_fix_info_decode_read(data, len, out, err);
}

void mip_gnss_receiver_1_fix_info_to_json(mip_jw_t *w, const mip_gnss_receiver_1_fix_info_t *in) {
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

int mip_gnss_receiver_1_fix_info_from_json(mip_jr_t *jr, size_t pos, mip_gnss_receiver_1_fix_info_t *out) {
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

/* ---- mip_gnss_receiver_1_hardware_status_t */

static int mip_gnss_receiver_1_hardware_status_read(mip_reader_t *r,
                                                    mip_gnss_receiver_1_hardware_status_t *out) {
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

static mip_status_t
mip_gnss_receiver_1_hardware_status_write(mip_writer_t *w, const mip_gnss_receiver_1_hardware_status_t *in) {
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

mip_status_t mip_gnss_receiver_1_hardware_status_encode(const mip_gnss_receiver_1_hardware_status_t *value,
                                                        uint8_t *buf, size_t cap, size_t *len_out) {
    mip_writer_t w;
    mip_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mip_writer_init(&w, buf, cap);
    st = mip_gnss_receiver_1_hardware_status_write(&w, value);
    if (st == MIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 5 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mip_gnss_receiver_1_hardware_status_load(const uint8_t *d,
                                                    mip_gnss_receiver_1_hardware_status_t *out) {
    out->receiver_state = mip_ld_u8(d + 0);
    out->antenna_state = mip_ld_u8(d + 1);
    out->antenna_power = mip_ld_u8(d + 2);
    out->valid_flags = mip_ld_u16(d + 3);
    return 0;
}

/* The general reader: lengths other than 5, bad bool bytes, error details. */
static MIP_NOINLINE mip_status_t mip_gnss_receiver_1_hardware_status_decode_read(
    const uint8_t *data, size_t len, mip_gnss_receiver_1_hardware_status_t *out, mip_decode_error_t *err) {
    mip_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mip_gnss_receiver_1_hardware_status_read(&r, out) ? MIP_ERR_DECODE : MIP_OK;
}

mip_status_t mip_gnss_receiver_1_hardware_status_decode(const uint8_t *data, size_t len,
                                                        mip_gnss_receiver_1_hardware_status_t *out,
                                                        mip_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 5 && mip_gnss_receiver_1_hardware_status_load(data, out) == 0) {
        return MIP_OK;
    }
    return mip_gnss_receiver_1_hardware_status_decode_read(data, len, out, err);
}

void mip_gnss_receiver_1_hardware_status_to_json(mip_jw_t *w,
                                                 const mip_gnss_receiver_1_hardware_status_t *in) {
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

int mip_gnss_receiver_1_hardware_status_from_json(mip_jr_t *jr, size_t pos,
                                                  mip_gnss_receiver_1_hardware_status_t *out) {
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

/* ---- mip_gnss_receiver_1_clock_info_2_t */

static int mip_gnss_receiver_1_clock_info_2_read(mip_reader_t *r, mip_gnss_receiver_1_clock_info_2_t *out) {
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
    mip_rd_push(r, "bias_accuracy_estimate");
    if (mip_rd_f64(r, &out->bias_accuracy_estimate)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "drift_accuracy_estimate");
    if (mip_rd_f64(r, &out->drift_accuracy_estimate)) {
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

static mip_status_t mip_gnss_receiver_1_clock_info_2_write(mip_writer_t *w,
                                                           const mip_gnss_receiver_1_clock_info_2_t *in) {
    mip_status_t st;
    if ((st = mip_wr_f64(w, &in->bias)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_f64(w, &in->drift)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_f64(w, &in->bias_accuracy_estimate)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_f64(w, &in->drift_accuracy_estimate)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_u16(w, &in->valid_flags)) != MIP_OK) {
        return st;
    }
    return MIP_OK;
}

mip_status_t mip_gnss_receiver_1_clock_info_2_encode(const mip_gnss_receiver_1_clock_info_2_t *value,
                                                     uint8_t *buf, size_t cap, size_t *len_out) {
    mip_writer_t w;
    mip_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mip_writer_init(&w, buf, cap);
    st = mip_gnss_receiver_1_clock_info_2_write(&w, value);
    if (st == MIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 34 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mip_gnss_receiver_1_clock_info_2_load(const uint8_t *d, mip_gnss_receiver_1_clock_info_2_t *out) {
    out->bias = mip_ld_f64(d + 0);
    out->drift = mip_ld_f64(d + 8);
    out->bias_accuracy_estimate = mip_ld_f64(d + 16);
    out->drift_accuracy_estimate = mip_ld_f64(d + 24);
    out->valid_flags = mip_ld_u16(d + 32);
    return 0;
}

/* The general reader: lengths other than 34, bad bool bytes, error details. */
static MIP_NOINLINE mip_status_t mip_gnss_receiver_1_clock_info_2_decode_read(
    const uint8_t *data, size_t len, mip_gnss_receiver_1_clock_info_2_t *out, mip_decode_error_t *err) {
    mip_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mip_gnss_receiver_1_clock_info_2_read(&r, out) ? MIP_ERR_DECODE : MIP_OK;
}

mip_status_t mip_gnss_receiver_1_clock_info_2_decode(const uint8_t *data, size_t len,
                                                     mip_gnss_receiver_1_clock_info_2_t *out,
                                                     mip_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 34 && mip_gnss_receiver_1_clock_info_2_load(data, out) == 0) {
        return MIP_OK;
    }
    return mip_gnss_receiver_1_clock_info_2_decode_read(data, len, out, err);
}

void mip_gnss_receiver_1_clock_info_2_to_json(mip_jw_t *w, const mip_gnss_receiver_1_clock_info_2_t *in) {
    int first = 1;
    mip_jw_raw(w, "{", 1);
    mip_jw_key(w, &first, "bias");
    mip_jw_f64(w, &in->bias);
    mip_jw_key(w, &first, "drift");
    mip_jw_f64(w, &in->drift);
    mip_jw_key(w, &first, "bias_accuracy_estimate");
    mip_jw_f64(w, &in->bias_accuracy_estimate);
    mip_jw_key(w, &first, "drift_accuracy_estimate");
    mip_jw_f64(w, &in->drift_accuracy_estimate);
    mip_jw_key(w, &first, "valid_flags");
    mip_jw_u16(w, &in->valid_flags);
    mip_jw_raw(w, "}", 1);
}

int mip_gnss_receiver_1_clock_info_2_from_json(mip_jr_t *jr, size_t pos,
                                               mip_gnss_receiver_1_clock_info_2_t *out) {
    static const char *const keys[] = {"bias", "drift", "bias_accuracy_estimate", "drift_accuracy_estimate",
                                       "valid_flags"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mip_jr_object(jr, pos, keys, 5)) {
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
    found = mip_jr_get(jr, pos, "bias_accuracy_estimate", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"bias_accuracy_estimate\"");
    }
    {
        mip_jr_push(jr, "bias_accuracy_estimate");
        if (mip_jr_f64(jr, vp, &out->bias_accuracy_estimate)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "drift_accuracy_estimate", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"drift_accuracy_estimate\"");
    }
    {
        mip_jr_push(jr, "drift_accuracy_estimate");
        if (mip_jr_f64(jr, vp, &out->drift_accuracy_estimate)) {
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

/* ---- mip_gnss_receiver_1_gps_leap_seconds_t */

static int mip_gnss_receiver_1_gps_leap_seconds_read(mip_reader_t *r,
                                                     mip_gnss_receiver_1_gps_leap_seconds_t *out) {
    mip_rd_push(r, "leap_seconds");
    if (mip_rd_u8(r, &out->leap_seconds)) {
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

static mip_status_t
mip_gnss_receiver_1_gps_leap_seconds_write(mip_writer_t *w,
                                           const mip_gnss_receiver_1_gps_leap_seconds_t *in) {
    mip_status_t st;
    if ((st = mip_wr_u8(w, &in->leap_seconds)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_u16(w, &in->valid_flags)) != MIP_OK) {
        return st;
    }
    return MIP_OK;
}

mip_status_t mip_gnss_receiver_1_gps_leap_seconds_encode(const mip_gnss_receiver_1_gps_leap_seconds_t *value,
                                                         uint8_t *buf, size_t cap, size_t *len_out) {
    mip_writer_t w;
    mip_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mip_writer_init(&w, buf, cap);
    st = mip_gnss_receiver_1_gps_leap_seconds_write(&w, value);
    if (st == MIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 3 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mip_gnss_receiver_1_gps_leap_seconds_load(const uint8_t *d,
                                                     mip_gnss_receiver_1_gps_leap_seconds_t *out) {
    out->leap_seconds = mip_ld_u8(d + 0);
    out->valid_flags = mip_ld_u16(d + 1);
    return 0;
}

/* The general reader: lengths other than 3, bad bool bytes, error details. */
static MIP_NOINLINE mip_status_t mip_gnss_receiver_1_gps_leap_seconds_decode_read(
    const uint8_t *data, size_t len, mip_gnss_receiver_1_gps_leap_seconds_t *out, mip_decode_error_t *err) {
    mip_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mip_gnss_receiver_1_gps_leap_seconds_read(&r, out) ? MIP_ERR_DECODE : MIP_OK;
}

mip_status_t mip_gnss_receiver_1_gps_leap_seconds_decode(const uint8_t *data, size_t len,
                                                         mip_gnss_receiver_1_gps_leap_seconds_t *out,
                                                         mip_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 3 && mip_gnss_receiver_1_gps_leap_seconds_load(data, out) == 0) {
        return MIP_OK;
    }
    return mip_gnss_receiver_1_gps_leap_seconds_decode_read(data, len, out, err);
}

void mip_gnss_receiver_1_gps_leap_seconds_to_json(mip_jw_t *w,
                                                  const mip_gnss_receiver_1_gps_leap_seconds_t *in) {
    int first = 1;
    mip_jw_raw(w, "{", 1);
    mip_jw_key(w, &first, "leap_seconds");
    mip_jw_u8(w, &in->leap_seconds);
    mip_jw_key(w, &first, "valid_flags");
    mip_jw_u16(w, &in->valid_flags);
    mip_jw_raw(w, "}", 1);
}

int mip_gnss_receiver_1_gps_leap_seconds_from_json(mip_jr_t *jr, size_t pos,
                                                   mip_gnss_receiver_1_gps_leap_seconds_t *out) {
    static const char *const keys[] = {"leap_seconds", "valid_flags"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mip_jr_object(jr, pos, keys, 2)) {
        return -1;
    }
    found = mip_jr_get(jr, pos, "leap_seconds", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"leap_seconds\"");
    }
    {
        mip_jr_push(jr, "leap_seconds");
        if (mip_jr_u8(jr, vp, &out->leap_seconds)) {
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

/* ---- mip_gnss_receiver_1_sbas_info_t */

static int mip_gnss_receiver_1_sbas_info_read(mip_reader_t *r, mip_gnss_receiver_1_sbas_info_t *out) {
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
    mip_rd_push(r, "sbas_system");
    if (mip_rd_u8(r, &out->sbas_system)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "sbas_id");
    if (mip_rd_u8(r, &out->sbas_id)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "count");
    if (mip_rd_u8(r, &out->count)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "sbas_status");
    if (mip_rd_u8(r, &out->sbas_status)) {
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

static mip_status_t mip_gnss_receiver_1_sbas_info_write(mip_writer_t *w,
                                                        const mip_gnss_receiver_1_sbas_info_t *in) {
    mip_status_t st;
    if ((st = mip_wr_f64(w, &in->tow)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_u16(w, &in->week_number)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_u8(w, &in->sbas_system)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_u8(w, &in->sbas_id)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_u8(w, &in->count)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_u8(w, &in->sbas_status)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_u16(w, &in->valid_flags)) != MIP_OK) {
        return st;
    }
    return MIP_OK;
}

mip_status_t mip_gnss_receiver_1_sbas_info_encode(const mip_gnss_receiver_1_sbas_info_t *value, uint8_t *buf,
                                                  size_t cap, size_t *len_out) {
    mip_writer_t w;
    mip_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mip_writer_init(&w, buf, cap);
    st = mip_gnss_receiver_1_sbas_info_write(&w, value);
    if (st == MIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 16 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mip_gnss_receiver_1_sbas_info_load(const uint8_t *d, mip_gnss_receiver_1_sbas_info_t *out) {
    out->tow = mip_ld_f64(d + 0);
    out->week_number = mip_ld_u16(d + 8);
    out->sbas_system = mip_ld_u8(d + 10);
    out->sbas_id = mip_ld_u8(d + 11);
    out->count = mip_ld_u8(d + 12);
    out->sbas_status = mip_ld_u8(d + 13);
    out->valid_flags = mip_ld_u16(d + 14);
    return 0;
}

/* The general reader: lengths other than 16, bad bool bytes, error details. */
static MIP_NOINLINE mip_status_t mip_gnss_receiver_1_sbas_info_decode_read(
    const uint8_t *data, size_t len, mip_gnss_receiver_1_sbas_info_t *out, mip_decode_error_t *err) {
    mip_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mip_gnss_receiver_1_sbas_info_read(&r, out) ? MIP_ERR_DECODE : MIP_OK;
}

mip_status_t mip_gnss_receiver_1_sbas_info_decode(const uint8_t *data, size_t len,
                                                  mip_gnss_receiver_1_sbas_info_t *out,
                                                  mip_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 16 && mip_gnss_receiver_1_sbas_info_load(data, out) == 0) {
        return MIP_OK;
    }
    return mip_gnss_receiver_1_sbas_info_decode_read(data, len, out, err);
}

void mip_gnss_receiver_1_sbas_info_to_json(mip_jw_t *w, const mip_gnss_receiver_1_sbas_info_t *in) {
    int first = 1;
    mip_jw_raw(w, "{", 1);
    mip_jw_key(w, &first, "tow");
    mip_jw_f64(w, &in->tow);
    mip_jw_key(w, &first, "week_number");
    mip_jw_u16(w, &in->week_number);
    mip_jw_key(w, &first, "sbas_system");
    mip_jw_u8(w, &in->sbas_system);
    mip_jw_key(w, &first, "sbas_id");
    mip_jw_u8(w, &in->sbas_id);
    mip_jw_key(w, &first, "count");
    mip_jw_u8(w, &in->count);
    mip_jw_key(w, &first, "sbas_status");
    mip_jw_u8(w, &in->sbas_status);
    mip_jw_key(w, &first, "valid_flags");
    mip_jw_u16(w, &in->valid_flags);
    mip_jw_raw(w, "}", 1);
}

int mip_gnss_receiver_1_sbas_info_from_json(mip_jr_t *jr, size_t pos, mip_gnss_receiver_1_sbas_info_t *out) {
    static const char *const keys[] = {"tow",   "week_number", "sbas_system", "sbas_id",
                                       "count", "sbas_status", "valid_flags"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mip_jr_object(jr, pos, keys, 7)) {
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
    found = mip_jr_get(jr, pos, "sbas_system", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"sbas_system\"");
    }
    {
        mip_jr_push(jr, "sbas_system");
        if (mip_jr_u8(jr, vp, &out->sbas_system)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "sbas_id", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"sbas_id\"");
    }
    {
        mip_jr_push(jr, "sbas_id");
        if (mip_jr_u8(jr, vp, &out->sbas_id)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "count", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"count\"");
    }
    {
        mip_jr_push(jr, "count");
        if (mip_jr_u8(jr, vp, &out->count)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "sbas_status", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"sbas_status\"");
    }
    {
        mip_jr_push(jr, "sbas_status");
        if (mip_jr_u8(jr, vp, &out->sbas_status)) {
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

/* ---- mip_gnss_receiver_1_satellite_status_t */

static int mip_gnss_receiver_1_satellite_status_read(mip_reader_t *r,
                                                     mip_gnss_receiver_1_satellite_status_t *out) {
    mip_rd_push(r, "index");
    if (mip_rd_u8(r, &out->index)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "count");
    if (mip_rd_u8(r, &out->count)) {
        return -1;
    }
    mip_rd_pop(r);
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
    mip_rd_push(r, "gnss_id");
    if (mip_rd_u8(r, &out->gnss_id)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "satellite_id");
    if (mip_rd_u8(r, &out->satellite_id)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "elevation");
    if (mip_rd_f32(r, &out->elevation)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "azimuth");
    if (mip_rd_f32(r, &out->azimuth)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "health");
    if (mip_rd_bool(r, &out->health)) {
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

static mip_status_t
mip_gnss_receiver_1_satellite_status_write(mip_writer_t *w,
                                           const mip_gnss_receiver_1_satellite_status_t *in) {
    mip_status_t st;
    if ((st = mip_wr_u8(w, &in->index)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_u8(w, &in->count)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_f64(w, &in->tow)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_u16(w, &in->week_number)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_u8(w, &in->gnss_id)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_u8(w, &in->satellite_id)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_f32(w, &in->elevation)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_f32(w, &in->azimuth)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_bool(w, &in->health)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_u16(w, &in->valid_flags)) != MIP_OK) {
        return st;
    }
    return MIP_OK;
}

mip_status_t mip_gnss_receiver_1_satellite_status_encode(const mip_gnss_receiver_1_satellite_status_t *value,
                                                         uint8_t *buf, size_t cap, size_t *len_out) {
    mip_writer_t w;
    mip_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mip_writer_init(&w, buf, cap);
    st = mip_gnss_receiver_1_satellite_status_write(&w, value);
    if (st == MIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 25 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mip_gnss_receiver_1_satellite_status_load(const uint8_t *d,
                                                     mip_gnss_receiver_1_satellite_status_t *out) {
    out->index = mip_ld_u8(d + 0);
    out->count = mip_ld_u8(d + 1);
    out->tow = mip_ld_f64(d + 2);
    out->week_number = mip_ld_u16(d + 10);
    out->gnss_id = mip_ld_u8(d + 12);
    out->satellite_id = mip_ld_u8(d + 13);
    out->elevation = mip_ld_f32(d + 14);
    out->azimuth = mip_ld_f32(d + 18);
    if (d[22] > 1) {
        return -1;
    }
    out->health = mip_ld_bool(d + 22);
    out->valid_flags = mip_ld_u16(d + 23);
    return 0;
}

/* The general reader: lengths other than 25, bad bool bytes, error details. */
static MIP_NOINLINE mip_status_t mip_gnss_receiver_1_satellite_status_decode_read(
    const uint8_t *data, size_t len, mip_gnss_receiver_1_satellite_status_t *out, mip_decode_error_t *err) {
    mip_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mip_gnss_receiver_1_satellite_status_read(&r, out) ? MIP_ERR_DECODE : MIP_OK;
}

mip_status_t mip_gnss_receiver_1_satellite_status_decode(const uint8_t *data, size_t len,
                                                         mip_gnss_receiver_1_satellite_status_t *out,
                                                         mip_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 25 && mip_gnss_receiver_1_satellite_status_load(data, out) == 0) {
        return MIP_OK;
    }
    return mip_gnss_receiver_1_satellite_status_decode_read(data, len, out, err);
}

void mip_gnss_receiver_1_satellite_status_to_json(mip_jw_t *w,
                                                  const mip_gnss_receiver_1_satellite_status_t *in) {
    int first = 1;
    mip_jw_raw(w, "{", 1);
    mip_jw_key(w, &first, "index");
    mip_jw_u8(w, &in->index);
    mip_jw_key(w, &first, "count");
    mip_jw_u8(w, &in->count);
    mip_jw_key(w, &first, "tow");
    mip_jw_f64(w, &in->tow);
    mip_jw_key(w, &first, "week_number");
    mip_jw_u16(w, &in->week_number);
    mip_jw_key(w, &first, "gnss_id");
    mip_jw_u8(w, &in->gnss_id);
    mip_jw_key(w, &first, "satellite_id");
    mip_jw_u8(w, &in->satellite_id);
    mip_jw_key(w, &first, "elevation");
    mip_jw_f32(w, &in->elevation);
    mip_jw_key(w, &first, "azimuth");
    mip_jw_f32(w, &in->azimuth);
    mip_jw_key(w, &first, "health");
    mip_jw_bool(w, &in->health);
    mip_jw_key(w, &first, "valid_flags");
    mip_jw_u16(w, &in->valid_flags);
    mip_jw_raw(w, "}", 1);
}

int mip_gnss_receiver_1_satellite_status_from_json(mip_jr_t *jr, size_t pos,
                                                   mip_gnss_receiver_1_satellite_status_t *out) {
    static const char *const keys[] = {"index",        "count",     "tow",     "week_number", "gnss_id",
                                       "satellite_id", "elevation", "azimuth", "health",      "valid_flags"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mip_jr_object(jr, pos, keys, 10)) {
        return -1;
    }
    found = mip_jr_get(jr, pos, "index", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"index\"");
    }
    {
        mip_jr_push(jr, "index");
        if (mip_jr_u8(jr, vp, &out->index)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "count", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"count\"");
    }
    {
        mip_jr_push(jr, "count");
        if (mip_jr_u8(jr, vp, &out->count)) {
            return -1;
        }
        mip_jr_pop(jr);
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
    found = mip_jr_get(jr, pos, "gnss_id", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"gnss_id\"");
    }
    {
        mip_jr_push(jr, "gnss_id");
        if (mip_jr_u8(jr, vp, &out->gnss_id)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "satellite_id", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"satellite_id\"");
    }
    {
        mip_jr_push(jr, "satellite_id");
        if (mip_jr_u8(jr, vp, &out->satellite_id)) {
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
        if (mip_jr_f32(jr, vp, &out->elevation)) {
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
        if (mip_jr_f32(jr, vp, &out->azimuth)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "health", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"health\"");
    }
    {
        mip_jr_push(jr, "health");
        if (mip_jr_bool(jr, vp, &out->health)) {
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

/* ---- mip_gnss_receiver_1_raw_t */

static int mip_gnss_receiver_1_raw_read(mip_reader_t *r, mip_gnss_receiver_1_raw_t *out) {
    mip_rd_push(r, "index");
    if (mip_rd_u8(r, &out->index)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "count");
    if (mip_rd_u8(r, &out->count)) {
        return -1;
    }
    mip_rd_pop(r);
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
    mip_rd_push(r, "receiver_id");
    if (mip_rd_u16(r, &out->receiver_id)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "tracking_channel");
    if (mip_rd_u8(r, &out->tracking_channel)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "gnss_id");
    if (mip_rd_u8(r, &out->gnss_id)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "satellite_id");
    if (mip_rd_u8(r, &out->satellite_id)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "signal_id");
    if (mip_rd_u8(r, &out->signal_id)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "signal_strength");
    if (mip_rd_f32(r, &out->signal_strength)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "quality");
    if (mip_rd_u8(r, &out->quality)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "pseudorange");
    if (mip_rd_f64(r, &out->pseudorange)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "carrier_phase");
    if (mip_rd_f64(r, &out->carrier_phase)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "doppler");
    if (mip_rd_f32(r, &out->doppler)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "range_uncert");
    if (mip_rd_f32(r, &out->range_uncert)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "phase_uncert");
    if (mip_rd_f32(r, &out->phase_uncert)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "doppler_uncert");
    if (mip_rd_f32(r, &out->doppler_uncert)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "lock_time");
    if (mip_rd_f32(r, &out->lock_time)) {
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

static mip_status_t mip_gnss_receiver_1_raw_write(mip_writer_t *w, const mip_gnss_receiver_1_raw_t *in) {
    mip_status_t st;
    if ((st = mip_wr_u8(w, &in->index)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_u8(w, &in->count)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_f64(w, &in->tow)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_u16(w, &in->week_number)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_u16(w, &in->receiver_id)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_u8(w, &in->tracking_channel)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_u8(w, &in->gnss_id)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_u8(w, &in->satellite_id)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_u8(w, &in->signal_id)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_f32(w, &in->signal_strength)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_u8(w, &in->quality)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_f64(w, &in->pseudorange)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_f64(w, &in->carrier_phase)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_f32(w, &in->doppler)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_f32(w, &in->range_uncert)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_f32(w, &in->phase_uncert)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_f32(w, &in->doppler_uncert)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_f32(w, &in->lock_time)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_u16(w, &in->valid_flags)) != MIP_OK) {
        return st;
    }
    return MIP_OK;
}

mip_status_t mip_gnss_receiver_1_raw_encode(const mip_gnss_receiver_1_raw_t *value, uint8_t *buf, size_t cap,
                                            size_t *len_out) {
    mip_writer_t w;
    mip_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mip_writer_init(&w, buf, cap);
    st = mip_gnss_receiver_1_raw_write(&w, value);
    if (st == MIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 61 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mip_gnss_receiver_1_raw_load(const uint8_t *d, mip_gnss_receiver_1_raw_t *out) {
    out->index = mip_ld_u8(d + 0);
    out->count = mip_ld_u8(d + 1);
    out->tow = mip_ld_f64(d + 2);
    out->week_number = mip_ld_u16(d + 10);
    out->receiver_id = mip_ld_u16(d + 12);
    out->tracking_channel = mip_ld_u8(d + 14);
    out->gnss_id = mip_ld_u8(d + 15);
    out->satellite_id = mip_ld_u8(d + 16);
    out->signal_id = mip_ld_u8(d + 17);
    out->signal_strength = mip_ld_f32(d + 18);
    out->quality = mip_ld_u8(d + 22);
    out->pseudorange = mip_ld_f64(d + 23);
    out->carrier_phase = mip_ld_f64(d + 31);
    out->doppler = mip_ld_f32(d + 39);
    out->range_uncert = mip_ld_f32(d + 43);
    out->phase_uncert = mip_ld_f32(d + 47);
    out->doppler_uncert = mip_ld_f32(d + 51);
    out->lock_time = mip_ld_f32(d + 55);
    out->valid_flags = mip_ld_u16(d + 59);
    return 0;
}

/* The general reader: lengths other than 61, bad bool bytes, error details. */
static MIP_NOINLINE mip_status_t mip_gnss_receiver_1_raw_decode_read(const uint8_t *data, size_t len,
                                                                     mip_gnss_receiver_1_raw_t *out,
                                                                     mip_decode_error_t *err) {
    mip_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mip_gnss_receiver_1_raw_read(&r, out) ? MIP_ERR_DECODE : MIP_OK;
}

mip_status_t mip_gnss_receiver_1_raw_decode(const uint8_t *data, size_t len, mip_gnss_receiver_1_raw_t *out,
                                            mip_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 61 && mip_gnss_receiver_1_raw_load(data, out) == 0) {
        return MIP_OK;
    }
    return mip_gnss_receiver_1_raw_decode_read(data, len, out, err);
}

void mip_gnss_receiver_1_raw_to_json(mip_jw_t *w, const mip_gnss_receiver_1_raw_t *in) {
    int first = 1;
    mip_jw_raw(w, "{", 1);
    mip_jw_key(w, &first, "index");
    mip_jw_u8(w, &in->index);
    mip_jw_key(w, &first, "count");
    mip_jw_u8(w, &in->count);
    mip_jw_key(w, &first, "tow");
    mip_jw_f64(w, &in->tow);
    mip_jw_key(w, &first, "week_number");
    mip_jw_u16(w, &in->week_number);
    mip_jw_key(w, &first, "receiver_id");
    mip_jw_u16(w, &in->receiver_id);
    mip_jw_key(w, &first, "tracking_channel");
    mip_jw_u8(w, &in->tracking_channel);
    mip_jw_key(w, &first, "gnss_id");
    mip_jw_u8(w, &in->gnss_id);
    mip_jw_key(w, &first, "satellite_id");
    mip_jw_u8(w, &in->satellite_id);
    mip_jw_key(w, &first, "signal_id");
    mip_jw_u8(w, &in->signal_id);
    mip_jw_key(w, &first, "signal_strength");
    mip_jw_f32(w, &in->signal_strength);
    mip_jw_key(w, &first, "quality");
    mip_jw_u8(w, &in->quality);
    mip_jw_key(w, &first, "pseudorange");
    mip_jw_f64(w, &in->pseudorange);
    mip_jw_key(w, &first, "carrier_phase");
    mip_jw_f64(w, &in->carrier_phase);
    mip_jw_key(w, &first, "doppler");
    mip_jw_f32(w, &in->doppler);
    mip_jw_key(w, &first, "range_uncert");
    mip_jw_f32(w, &in->range_uncert);
    mip_jw_key(w, &first, "phase_uncert");
    mip_jw_f32(w, &in->phase_uncert);
    mip_jw_key(w, &first, "doppler_uncert");
    mip_jw_f32(w, &in->doppler_uncert);
    mip_jw_key(w, &first, "lock_time");
    mip_jw_f32(w, &in->lock_time);
    mip_jw_key(w, &first, "valid_flags");
    mip_jw_u16(w, &in->valid_flags);
    mip_jw_raw(w, "}", 1);
}

int mip_gnss_receiver_1_raw_from_json(mip_jr_t *jr, size_t pos, mip_gnss_receiver_1_raw_t *out) {
    static const char *const keys[] = {"index",           "count",          "tow",
                                       "week_number",     "receiver_id",    "tracking_channel",
                                       "gnss_id",         "satellite_id",   "signal_id",
                                       "signal_strength", "quality",        "pseudorange",
                                       "carrier_phase",   "doppler",        "range_uncert",
                                       "phase_uncert",    "doppler_uncert", "lock_time",
                                       "valid_flags"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mip_jr_object(jr, pos, keys, 19)) {
        return -1;
    }
    found = mip_jr_get(jr, pos, "index", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"index\"");
    }
    {
        mip_jr_push(jr, "index");
        if (mip_jr_u8(jr, vp, &out->index)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "count", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"count\"");
    }
    {
        mip_jr_push(jr, "count");
        if (mip_jr_u8(jr, vp, &out->count)) {
            return -1;
        }
        mip_jr_pop(jr);
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
    found = mip_jr_get(jr, pos, "receiver_id", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"receiver_id\"");
    }
    {
        mip_jr_push(jr, "receiver_id");
        if (mip_jr_u16(jr, vp, &out->receiver_id)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "tracking_channel", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"tracking_channel\"");
    }
    {
        mip_jr_push(jr, "tracking_channel");
        if (mip_jr_u8(jr, vp, &out->tracking_channel)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "gnss_id", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"gnss_id\"");
    }
    {
        mip_jr_push(jr, "gnss_id");
        if (mip_jr_u8(jr, vp, &out->gnss_id)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "satellite_id", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"satellite_id\"");
    }
    {
        mip_jr_push(jr, "satellite_id");
        if (mip_jr_u8(jr, vp, &out->satellite_id)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "signal_id", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"signal_id\"");
    }
    {
        mip_jr_push(jr, "signal_id");
        if (mip_jr_u8(jr, vp, &out->signal_id)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "signal_strength", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"signal_strength\"");
    }
    {
        mip_jr_push(jr, "signal_strength");
        if (mip_jr_f32(jr, vp, &out->signal_strength)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "quality", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"quality\"");
    }
    {
        mip_jr_push(jr, "quality");
        if (mip_jr_u8(jr, vp, &out->quality)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "pseudorange", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"pseudorange\"");
    }
    {
        mip_jr_push(jr, "pseudorange");
        if (mip_jr_f64(jr, vp, &out->pseudorange)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "carrier_phase", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"carrier_phase\"");
    }
    {
        mip_jr_push(jr, "carrier_phase");
        if (mip_jr_f64(jr, vp, &out->carrier_phase)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "doppler", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"doppler\"");
    }
    {
        mip_jr_push(jr, "doppler");
        if (mip_jr_f32(jr, vp, &out->doppler)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "range_uncert", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"range_uncert\"");
    }
    {
        mip_jr_push(jr, "range_uncert");
        if (mip_jr_f32(jr, vp, &out->range_uncert)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "phase_uncert", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"phase_uncert\"");
    }
    {
        mip_jr_push(jr, "phase_uncert");
        if (mip_jr_f32(jr, vp, &out->phase_uncert)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "doppler_uncert", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"doppler_uncert\"");
    }
    {
        mip_jr_push(jr, "doppler_uncert");
        if (mip_jr_f32(jr, vp, &out->doppler_uncert)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "lock_time", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"lock_time\"");
    }
    {
        mip_jr_push(jr, "lock_time");
        if (mip_jr_f32(jr, vp, &out->lock_time)) {
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

/* ---- mip_gnss_receiver_1_gps_ephemeris_t */

static int mip_gnss_receiver_1_gps_ephemeris_read(mip_reader_t *r, mip_gnss_receiver_1_gps_ephemeris_t *out) {
    mip_rd_push(r, "index");
    if (mip_rd_u8(r, &out->index)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "count");
    if (mip_rd_u8(r, &out->count)) {
        return -1;
    }
    mip_rd_pop(r);
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
    mip_rd_push(r, "satellite_id");
    if (mip_rd_u8(r, &out->satellite_id)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "health");
    if (mip_rd_u8(r, &out->health)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "iodc");
    if (mip_rd_u8(r, &out->iodc)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "iode");
    if (mip_rd_u8(r, &out->iode)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "t_oc");
    if (mip_rd_f64(r, &out->t_oc)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "af0");
    if (mip_rd_f64(r, &out->af0)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "af1");
    if (mip_rd_f64(r, &out->af1)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "af2");
    if (mip_rd_f64(r, &out->af2)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "t_gd");
    if (mip_rd_f64(r, &out->t_gd)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "isc_l1ca");
    if (mip_rd_f64(r, &out->isc_l1ca)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "isc_l2c");
    if (mip_rd_f64(r, &out->isc_l2c)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "t_oe");
    if (mip_rd_f64(r, &out->t_oe)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "a");
    if (mip_rd_f64(r, &out->a)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "a_dot");
    if (mip_rd_f64(r, &out->a_dot)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "mean_anomaly");
    if (mip_rd_f64(r, &out->mean_anomaly)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "delta_mean_motion");
    if (mip_rd_f64(r, &out->delta_mean_motion)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "delta_mean_motion_dot");
    if (mip_rd_f64(r, &out->delta_mean_motion_dot)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "eccentricity");
    if (mip_rd_f64(r, &out->eccentricity)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "argument_of_perigee");
    if (mip_rd_f64(r, &out->argument_of_perigee)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "omega");
    if (mip_rd_f64(r, &out->omega)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "omega_dot");
    if (mip_rd_f64(r, &out->omega_dot)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "inclination");
    if (mip_rd_f64(r, &out->inclination)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "inclination_dot");
    if (mip_rd_f64(r, &out->inclination_dot)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "c_ic");
    if (mip_rd_f64(r, &out->c_ic)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "c_is");
    if (mip_rd_f64(r, &out->c_is)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "c_uc");
    if (mip_rd_f64(r, &out->c_uc)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "c_us");
    if (mip_rd_f64(r, &out->c_us)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "c_rc");
    if (mip_rd_f64(r, &out->c_rc)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "c_rs");
    if (mip_rd_f64(r, &out->c_rs)) {
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

static mip_status_t mip_gnss_receiver_1_gps_ephemeris_write(mip_writer_t *w,
                                                            const mip_gnss_receiver_1_gps_ephemeris_t *in) {
    mip_status_t st;
    if ((st = mip_wr_u8(w, &in->index)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_u8(w, &in->count)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_f64(w, &in->tow)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_u16(w, &in->week_number)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_u8(w, &in->satellite_id)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_u8(w, &in->health)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_u8(w, &in->iodc)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_u8(w, &in->iode)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_f64(w, &in->t_oc)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_f64(w, &in->af0)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_f64(w, &in->af1)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_f64(w, &in->af2)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_f64(w, &in->t_gd)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_f64(w, &in->isc_l1ca)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_f64(w, &in->isc_l2c)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_f64(w, &in->t_oe)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_f64(w, &in->a)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_f64(w, &in->a_dot)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_f64(w, &in->mean_anomaly)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_f64(w, &in->delta_mean_motion)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_f64(w, &in->delta_mean_motion_dot)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_f64(w, &in->eccentricity)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_f64(w, &in->argument_of_perigee)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_f64(w, &in->omega)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_f64(w, &in->omega_dot)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_f64(w, &in->inclination)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_f64(w, &in->inclination_dot)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_f64(w, &in->c_ic)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_f64(w, &in->c_is)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_f64(w, &in->c_uc)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_f64(w, &in->c_us)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_f64(w, &in->c_rc)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_f64(w, &in->c_rs)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_u16(w, &in->valid_flags)) != MIP_OK) {
        return st;
    }
    return MIP_OK;
}

mip_status_t mip_gnss_receiver_1_gps_ephemeris_encode(const mip_gnss_receiver_1_gps_ephemeris_t *value,
                                                      uint8_t *buf, size_t cap, size_t *len_out) {
    mip_writer_t w;
    mip_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mip_writer_init(&w, buf, cap);
    st = mip_gnss_receiver_1_gps_ephemeris_write(&w, value);
    if (st == MIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 218 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mip_gnss_receiver_1_gps_ephemeris_load(const uint8_t *d,
                                                  mip_gnss_receiver_1_gps_ephemeris_t *out) {
    out->index = mip_ld_u8(d + 0);
    out->count = mip_ld_u8(d + 1);
    out->tow = mip_ld_f64(d + 2);
    out->week_number = mip_ld_u16(d + 10);
    out->satellite_id = mip_ld_u8(d + 12);
    out->health = mip_ld_u8(d + 13);
    out->iodc = mip_ld_u8(d + 14);
    out->iode = mip_ld_u8(d + 15);
    out->t_oc = mip_ld_f64(d + 16);
    out->af0 = mip_ld_f64(d + 24);
    out->af1 = mip_ld_f64(d + 32);
    out->af2 = mip_ld_f64(d + 40);
    out->t_gd = mip_ld_f64(d + 48);
    out->isc_l1ca = mip_ld_f64(d + 56);
    out->isc_l2c = mip_ld_f64(d + 64);
    out->t_oe = mip_ld_f64(d + 72);
    out->a = mip_ld_f64(d + 80);
    out->a_dot = mip_ld_f64(d + 88);
    out->mean_anomaly = mip_ld_f64(d + 96);
    out->delta_mean_motion = mip_ld_f64(d + 104);
    out->delta_mean_motion_dot = mip_ld_f64(d + 112);
    out->eccentricity = mip_ld_f64(d + 120);
    out->argument_of_perigee = mip_ld_f64(d + 128);
    out->omega = mip_ld_f64(d + 136);
    out->omega_dot = mip_ld_f64(d + 144);
    out->inclination = mip_ld_f64(d + 152);
    out->inclination_dot = mip_ld_f64(d + 160);
    out->c_ic = mip_ld_f64(d + 168);
    out->c_is = mip_ld_f64(d + 176);
    out->c_uc = mip_ld_f64(d + 184);
    out->c_us = mip_ld_f64(d + 192);
    out->c_rc = mip_ld_f64(d + 200);
    out->c_rs = mip_ld_f64(d + 208);
    out->valid_flags = mip_ld_u16(d + 216);
    return 0;
}

/* The general reader: lengths other than 218, bad bool bytes, error details. */
static MIP_NOINLINE mip_status_t mip_gnss_receiver_1_gps_ephemeris_decode_read(
    const uint8_t *data, size_t len, mip_gnss_receiver_1_gps_ephemeris_t *out, mip_decode_error_t *err) {
    mip_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mip_gnss_receiver_1_gps_ephemeris_read(&r, out) ? MIP_ERR_DECODE : MIP_OK;
}

mip_status_t mip_gnss_receiver_1_gps_ephemeris_decode(const uint8_t *data, size_t len,
                                                      mip_gnss_receiver_1_gps_ephemeris_t *out,
                                                      mip_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 218 && mip_gnss_receiver_1_gps_ephemeris_load(data, out) == 0) {
        return MIP_OK;
    }
    return mip_gnss_receiver_1_gps_ephemeris_decode_read(data, len, out, err);
}

void mip_gnss_receiver_1_gps_ephemeris_to_json(mip_jw_t *w, const mip_gnss_receiver_1_gps_ephemeris_t *in) {
    int first = 1;
    mip_jw_raw(w, "{", 1);
    mip_jw_key(w, &first, "index");
    mip_jw_u8(w, &in->index);
    mip_jw_key(w, &first, "count");
    mip_jw_u8(w, &in->count);
    mip_jw_key(w, &first, "tow");
    mip_jw_f64(w, &in->tow);
    mip_jw_key(w, &first, "week_number");
    mip_jw_u16(w, &in->week_number);
    mip_jw_key(w, &first, "satellite_id");
    mip_jw_u8(w, &in->satellite_id);
    mip_jw_key(w, &first, "health");
    mip_jw_u8(w, &in->health);
    mip_jw_key(w, &first, "iodc");
    mip_jw_u8(w, &in->iodc);
    mip_jw_key(w, &first, "iode");
    mip_jw_u8(w, &in->iode);
    mip_jw_key(w, &first, "t_oc");
    mip_jw_f64(w, &in->t_oc);
    mip_jw_key(w, &first, "af0");
    mip_jw_f64(w, &in->af0);
    mip_jw_key(w, &first, "af1");
    mip_jw_f64(w, &in->af1);
    mip_jw_key(w, &first, "af2");
    mip_jw_f64(w, &in->af2);
    mip_jw_key(w, &first, "t_gd");
    mip_jw_f64(w, &in->t_gd);
    mip_jw_key(w, &first, "isc_l1ca");
    mip_jw_f64(w, &in->isc_l1ca);
    mip_jw_key(w, &first, "isc_l2c");
    mip_jw_f64(w, &in->isc_l2c);
    mip_jw_key(w, &first, "t_oe");
    mip_jw_f64(w, &in->t_oe);
    mip_jw_key(w, &first, "a");
    mip_jw_f64(w, &in->a);
    mip_jw_key(w, &first, "a_dot");
    mip_jw_f64(w, &in->a_dot);
    mip_jw_key(w, &first, "mean_anomaly");
    mip_jw_f64(w, &in->mean_anomaly);
    mip_jw_key(w, &first, "delta_mean_motion");
    mip_jw_f64(w, &in->delta_mean_motion);
    mip_jw_key(w, &first, "delta_mean_motion_dot");
    mip_jw_f64(w, &in->delta_mean_motion_dot);
    mip_jw_key(w, &first, "eccentricity");
    mip_jw_f64(w, &in->eccentricity);
    mip_jw_key(w, &first, "argument_of_perigee");
    mip_jw_f64(w, &in->argument_of_perigee);
    mip_jw_key(w, &first, "omega");
    mip_jw_f64(w, &in->omega);
    mip_jw_key(w, &first, "omega_dot");
    mip_jw_f64(w, &in->omega_dot);
    mip_jw_key(w, &first, "inclination");
    mip_jw_f64(w, &in->inclination);
    mip_jw_key(w, &first, "inclination_dot");
    mip_jw_f64(w, &in->inclination_dot);
    mip_jw_key(w, &first, "c_ic");
    mip_jw_f64(w, &in->c_ic);
    mip_jw_key(w, &first, "c_is");
    mip_jw_f64(w, &in->c_is);
    mip_jw_key(w, &first, "c_uc");
    mip_jw_f64(w, &in->c_uc);
    mip_jw_key(w, &first, "c_us");
    mip_jw_f64(w, &in->c_us);
    mip_jw_key(w, &first, "c_rc");
    mip_jw_f64(w, &in->c_rc);
    mip_jw_key(w, &first, "c_rs");
    mip_jw_f64(w, &in->c_rs);
    mip_jw_key(w, &first, "valid_flags");
    mip_jw_u16(w, &in->valid_flags);
    mip_jw_raw(w, "}", 1);
}

int mip_gnss_receiver_1_gps_ephemeris_from_json(mip_jr_t *jr, size_t pos,
                                                mip_gnss_receiver_1_gps_ephemeris_t *out) {
    static const char *const keys[] = {"index",
                                       "count",
                                       "tow",
                                       "week_number",
                                       "satellite_id",
                                       "health",
                                       "iodc",
                                       "iode",
                                       "t_oc",
                                       "af0",
                                       "af1",
                                       "af2",
                                       "t_gd",
                                       "isc_l1ca",
                                       "isc_l2c",
                                       "t_oe",
                                       "a",
                                       "a_dot",
                                       "mean_anomaly",
                                       "delta_mean_motion",
                                       "delta_mean_motion_dot",
                                       "eccentricity",
                                       "argument_of_perigee",
                                       "omega",
                                       "omega_dot",
                                       "inclination",
                                       "inclination_dot",
                                       "c_ic",
                                       "c_is",
                                       "c_uc",
                                       "c_us",
                                       "c_rc",
                                       "c_rs",
                                       "valid_flags"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mip_jr_object(jr, pos, keys, 34)) {
        return -1;
    }
    found = mip_jr_get(jr, pos, "index", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"index\"");
    }
    {
        mip_jr_push(jr, "index");
        if (mip_jr_u8(jr, vp, &out->index)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "count", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"count\"");
    }
    {
        mip_jr_push(jr, "count");
        if (mip_jr_u8(jr, vp, &out->count)) {
            return -1;
        }
        mip_jr_pop(jr);
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
    found = mip_jr_get(jr, pos, "satellite_id", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"satellite_id\"");
    }
    {
        mip_jr_push(jr, "satellite_id");
        if (mip_jr_u8(jr, vp, &out->satellite_id)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "health", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"health\"");
    }
    {
        mip_jr_push(jr, "health");
        if (mip_jr_u8(jr, vp, &out->health)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "iodc", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"iodc\"");
    }
    {
        mip_jr_push(jr, "iodc");
        if (mip_jr_u8(jr, vp, &out->iodc)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "iode", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"iode\"");
    }
    {
        mip_jr_push(jr, "iode");
        if (mip_jr_u8(jr, vp, &out->iode)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "t_oc", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"t_oc\"");
    }
    {
        mip_jr_push(jr, "t_oc");
        if (mip_jr_f64(jr, vp, &out->t_oc)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "af0", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"af0\"");
    }
    {
        mip_jr_push(jr, "af0");
        if (mip_jr_f64(jr, vp, &out->af0)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "af1", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"af1\"");
    }
    {
        mip_jr_push(jr, "af1");
        if (mip_jr_f64(jr, vp, &out->af1)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "af2", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"af2\"");
    }
    {
        mip_jr_push(jr, "af2");
        if (mip_jr_f64(jr, vp, &out->af2)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "t_gd", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"t_gd\"");
    }
    {
        mip_jr_push(jr, "t_gd");
        if (mip_jr_f64(jr, vp, &out->t_gd)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "isc_l1ca", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"isc_l1ca\"");
    }
    {
        mip_jr_push(jr, "isc_l1ca");
        if (mip_jr_f64(jr, vp, &out->isc_l1ca)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "isc_l2c", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"isc_l2c\"");
    }
    {
        mip_jr_push(jr, "isc_l2c");
        if (mip_jr_f64(jr, vp, &out->isc_l2c)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "t_oe", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"t_oe\"");
    }
    {
        mip_jr_push(jr, "t_oe");
        if (mip_jr_f64(jr, vp, &out->t_oe)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "a", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"a\"");
    }
    {
        mip_jr_push(jr, "a");
        if (mip_jr_f64(jr, vp, &out->a)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "a_dot", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"a_dot\"");
    }
    {
        mip_jr_push(jr, "a_dot");
        if (mip_jr_f64(jr, vp, &out->a_dot)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "mean_anomaly", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"mean_anomaly\"");
    }
    {
        mip_jr_push(jr, "mean_anomaly");
        if (mip_jr_f64(jr, vp, &out->mean_anomaly)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "delta_mean_motion", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"delta_mean_motion\"");
    }
    {
        mip_jr_push(jr, "delta_mean_motion");
        if (mip_jr_f64(jr, vp, &out->delta_mean_motion)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "delta_mean_motion_dot", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"delta_mean_motion_dot\"");
    }
    {
        mip_jr_push(jr, "delta_mean_motion_dot");
        if (mip_jr_f64(jr, vp, &out->delta_mean_motion_dot)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "eccentricity", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"eccentricity\"");
    }
    {
        mip_jr_push(jr, "eccentricity");
        if (mip_jr_f64(jr, vp, &out->eccentricity)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "argument_of_perigee", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"argument_of_perigee\"");
    }
    {
        mip_jr_push(jr, "argument_of_perigee");
        if (mip_jr_f64(jr, vp, &out->argument_of_perigee)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "omega", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"omega\"");
    }
    {
        mip_jr_push(jr, "omega");
        if (mip_jr_f64(jr, vp, &out->omega)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "omega_dot", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"omega_dot\"");
    }
    {
        mip_jr_push(jr, "omega_dot");
        if (mip_jr_f64(jr, vp, &out->omega_dot)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "inclination", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"inclination\"");
    }
    {
        mip_jr_push(jr, "inclination");
        if (mip_jr_f64(jr, vp, &out->inclination)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "inclination_dot", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"inclination_dot\"");
    }
    {
        mip_jr_push(jr, "inclination_dot");
        if (mip_jr_f64(jr, vp, &out->inclination_dot)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "c_ic", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"c_ic\"");
    }
    {
        mip_jr_push(jr, "c_ic");
        if (mip_jr_f64(jr, vp, &out->c_ic)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "c_is", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"c_is\"");
    }
    {
        mip_jr_push(jr, "c_is");
        if (mip_jr_f64(jr, vp, &out->c_is)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "c_uc", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"c_uc\"");
    }
    {
        mip_jr_push(jr, "c_uc");
        if (mip_jr_f64(jr, vp, &out->c_uc)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "c_us", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"c_us\"");
    }
    {
        mip_jr_push(jr, "c_us");
        if (mip_jr_f64(jr, vp, &out->c_us)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "c_rc", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"c_rc\"");
    }
    {
        mip_jr_push(jr, "c_rc");
        if (mip_jr_f64(jr, vp, &out->c_rc)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "c_rs", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"c_rs\"");
    }
    {
        mip_jr_push(jr, "c_rs");
        if (mip_jr_f64(jr, vp, &out->c_rs)) {
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

/* ---- mip_gnss_receiver_1_glonass_ephemeris_t */

static int mip_gnss_receiver_1_glonass_ephemeris_read(mip_reader_t *r,
                                                      mip_gnss_receiver_1_glonass_ephemeris_t *out) {
    size_t i;
    mip_rd_push(r, "index");
    if (mip_rd_u8(r, &out->index)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "count");
    if (mip_rd_u8(r, &out->count)) {
        return -1;
    }
    mip_rd_pop(r);
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
    mip_rd_push(r, "satellite_id");
    if (mip_rd_u8(r, &out->satellite_id)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "freq_number");
    if (mip_rd_s8(r, &out->freq_number)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "tk");
    if (mip_rd_u32(r, &out->tk)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "tb");
    if (mip_rd_u32(r, &out->tb)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "sat_type");
    if (mip_rd_u8(r, &out->sat_type)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "gamma");
    if (mip_rd_f64(r, &out->gamma)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "tau_n");
    if (mip_rd_f64(r, &out->tau_n)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "x");
    for (i = 0; i < 3; i++) {
        mip_rd_index(r, i);
        if (mip_rd_f64(r, &out->x[i])) {
            return -1;
        }
    }
    mip_rd_pop(r);
    mip_rd_push(r, "v");
    for (i = 0; i < 3; i++) {
        mip_rd_index(r, i);
        if (mip_rd_f32(r, &out->v[i])) {
            return -1;
        }
    }
    mip_rd_pop(r);
    mip_rd_push(r, "a");
    for (i = 0; i < 3; i++) {
        mip_rd_index(r, i);
        if (mip_rd_f32(r, &out->a[i])) {
            return -1;
        }
    }
    mip_rd_pop(r);
    mip_rd_push(r, "health");
    if (mip_rd_u8(r, &out->health)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "p");
    if (mip_rd_u8(r, &out->p)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "nt");
    if (mip_rd_u8(r, &out->nt)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "delta_tau_n");
    if (mip_rd_f32(r, &out->delta_tau_n)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "ft");
    if (mip_rd_u8(r, &out->ft)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "en");
    if (mip_rd_u8(r, &out->en)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "p1");
    if (mip_rd_u8(r, &out->p1)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "p2");
    if (mip_rd_u8(r, &out->p2)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "p3");
    if (mip_rd_u8(r, &out->p3)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "p4");
    if (mip_rd_u8(r, &out->p4)) {
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

static mip_status_t
mip_gnss_receiver_1_glonass_ephemeris_write(mip_writer_t *w,
                                            const mip_gnss_receiver_1_glonass_ephemeris_t *in) {
    mip_status_t st;
    size_t i;
    if ((st = mip_wr_u8(w, &in->index)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_u8(w, &in->count)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_f64(w, &in->tow)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_u16(w, &in->week_number)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_u8(w, &in->satellite_id)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_s8(w, &in->freq_number)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_u32(w, &in->tk)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_u32(w, &in->tb)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_u8(w, &in->sat_type)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_f64(w, &in->gamma)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_f64(w, &in->tau_n)) != MIP_OK) {
        return st;
    }
    for (i = 0; i < 3; i++) {
        if ((st = mip_wr_f64(w, &in->x[i])) != MIP_OK) {
            return st;
        }
    }
    for (i = 0; i < 3; i++) {
        if ((st = mip_wr_f32(w, &in->v[i])) != MIP_OK) {
            return st;
        }
    }
    for (i = 0; i < 3; i++) {
        if ((st = mip_wr_f32(w, &in->a[i])) != MIP_OK) {
            return st;
        }
    }
    if ((st = mip_wr_u8(w, &in->health)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_u8(w, &in->p)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_u8(w, &in->nt)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_f32(w, &in->delta_tau_n)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_u8(w, &in->ft)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_u8(w, &in->en)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_u8(w, &in->p1)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_u8(w, &in->p2)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_u8(w, &in->p3)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_u8(w, &in->p4)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_u16(w, &in->valid_flags)) != MIP_OK) {
        return st;
    }
    return MIP_OK;
}

mip_status_t
mip_gnss_receiver_1_glonass_ephemeris_encode(const mip_gnss_receiver_1_glonass_ephemeris_t *value,
                                             uint8_t *buf, size_t cap, size_t *len_out) {
    mip_writer_t w;
    mip_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mip_writer_init(&w, buf, cap);
    st = mip_gnss_receiver_1_glonass_ephemeris_write(&w, value);
    if (st == MIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 102 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mip_gnss_receiver_1_glonass_ephemeris_load(const uint8_t *d,
                                                      mip_gnss_receiver_1_glonass_ephemeris_t *out) {
    out->index = mip_ld_u8(d + 0);
    out->count = mip_ld_u8(d + 1);
    out->tow = mip_ld_f64(d + 2);
    out->week_number = mip_ld_u16(d + 10);
    out->satellite_id = mip_ld_u8(d + 12);
    out->freq_number = mip_ld_s8(d + 13);
    out->tk = mip_ld_u32(d + 14);
    out->tb = mip_ld_u32(d + 18);
    out->sat_type = mip_ld_u8(d + 22);
    out->gamma = mip_ld_f64(d + 23);
    out->tau_n = mip_ld_f64(d + 31);
    out->x[0] = mip_ld_f64(d + 39);
    out->x[1] = mip_ld_f64(d + 47);
    out->x[2] = mip_ld_f64(d + 55);
    out->v[0] = mip_ld_f32(d + 63);
    out->v[1] = mip_ld_f32(d + 67);
    out->v[2] = mip_ld_f32(d + 71);
    out->a[0] = mip_ld_f32(d + 75);
    out->a[1] = mip_ld_f32(d + 79);
    out->a[2] = mip_ld_f32(d + 83);
    out->health = mip_ld_u8(d + 87);
    out->p = mip_ld_u8(d + 88);
    out->nt = mip_ld_u8(d + 89);
    out->delta_tau_n = mip_ld_f32(d + 90);
    out->ft = mip_ld_u8(d + 94);
    out->en = mip_ld_u8(d + 95);
    out->p1 = mip_ld_u8(d + 96);
    out->p2 = mip_ld_u8(d + 97);
    out->p3 = mip_ld_u8(d + 98);
    out->p4 = mip_ld_u8(d + 99);
    out->valid_flags = mip_ld_u16(d + 100);
    return 0;
}

/* The general reader: lengths other than 102, bad bool bytes, error details. */
static MIP_NOINLINE mip_status_t mip_gnss_receiver_1_glonass_ephemeris_decode_read(
    const uint8_t *data, size_t len, mip_gnss_receiver_1_glonass_ephemeris_t *out, mip_decode_error_t *err) {
    mip_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mip_gnss_receiver_1_glonass_ephemeris_read(&r, out) ? MIP_ERR_DECODE : MIP_OK;
}

mip_status_t mip_gnss_receiver_1_glonass_ephemeris_decode(const uint8_t *data, size_t len,
                                                          mip_gnss_receiver_1_glonass_ephemeris_t *out,
                                                          mip_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 102 && mip_gnss_receiver_1_glonass_ephemeris_load(data, out) == 0) {
        return MIP_OK;
    }
    return mip_gnss_receiver_1_glonass_ephemeris_decode_read(data, len, out, err);
}

void mip_gnss_receiver_1_glonass_ephemeris_to_json(mip_jw_t *w,
                                                   const mip_gnss_receiver_1_glonass_ephemeris_t *in) {
    int first = 1;
    size_t i;
    mip_jw_raw(w, "{", 1);
    mip_jw_key(w, &first, "index");
    mip_jw_u8(w, &in->index);
    mip_jw_key(w, &first, "count");
    mip_jw_u8(w, &in->count);
    mip_jw_key(w, &first, "tow");
    mip_jw_f64(w, &in->tow);
    mip_jw_key(w, &first, "week_number");
    mip_jw_u16(w, &in->week_number);
    mip_jw_key(w, &first, "satellite_id");
    mip_jw_u8(w, &in->satellite_id);
    mip_jw_key(w, &first, "freq_number");
    mip_jw_s8(w, &in->freq_number);
    mip_jw_key(w, &first, "tk");
    mip_jw_u32(w, &in->tk);
    mip_jw_key(w, &first, "tb");
    mip_jw_u32(w, &in->tb);
    mip_jw_key(w, &first, "sat_type");
    mip_jw_u8(w, &in->sat_type);
    mip_jw_key(w, &first, "gamma");
    mip_jw_f64(w, &in->gamma);
    mip_jw_key(w, &first, "tau_n");
    mip_jw_f64(w, &in->tau_n);
    mip_jw_key(w, &first, "x");
    mip_jw_raw(w, "[", 1);
    for (i = 0; i < 3; i++) {
        mip_jw_sep(w, i);
        mip_jw_f64(w, &in->x[i]);
    }
    mip_jw_raw(w, "]", 1);
    mip_jw_key(w, &first, "v");
    mip_jw_raw(w, "[", 1);
    for (i = 0; i < 3; i++) {
        mip_jw_sep(w, i);
        mip_jw_f32(w, &in->v[i]);
    }
    mip_jw_raw(w, "]", 1);
    mip_jw_key(w, &first, "a");
    mip_jw_raw(w, "[", 1);
    for (i = 0; i < 3; i++) {
        mip_jw_sep(w, i);
        mip_jw_f32(w, &in->a[i]);
    }
    mip_jw_raw(w, "]", 1);
    mip_jw_key(w, &first, "health");
    mip_jw_u8(w, &in->health);
    mip_jw_key(w, &first, "p");
    mip_jw_u8(w, &in->p);
    mip_jw_key(w, &first, "nt");
    mip_jw_u8(w, &in->nt);
    mip_jw_key(w, &first, "delta_tau_n");
    mip_jw_f32(w, &in->delta_tau_n);
    mip_jw_key(w, &first, "ft");
    mip_jw_u8(w, &in->ft);
    mip_jw_key(w, &first, "en");
    mip_jw_u8(w, &in->en);
    mip_jw_key(w, &first, "p1");
    mip_jw_u8(w, &in->p1);
    mip_jw_key(w, &first, "p2");
    mip_jw_u8(w, &in->p2);
    mip_jw_key(w, &first, "p3");
    mip_jw_u8(w, &in->p3);
    mip_jw_key(w, &first, "p4");
    mip_jw_u8(w, &in->p4);
    mip_jw_key(w, &first, "valid_flags");
    mip_jw_u16(w, &in->valid_flags);
    mip_jw_raw(w, "}", 1);
}

int mip_gnss_receiver_1_glonass_ephemeris_from_json(mip_jr_t *jr, size_t pos,
                                                    mip_gnss_receiver_1_glonass_ephemeris_t *out) {
    static const char *const keys[] = {"index",       "count", "tow",         "week_number", "satellite_id",
                                       "freq_number", "tk",    "tb",          "sat_type",    "gamma",
                                       "tau_n",       "x",     "v",           "a",           "health",
                                       "p",           "nt",    "delta_tau_n", "ft",          "en",
                                       "p1",          "p2",    "p3",          "p4",          "valid_flags"};
    size_t vp = 0;
    int found;
    size_t i;
    size_t it = 0;
    size_t ep = 0;
    memset(out, 0, sizeof *out);
    if (mip_jr_object(jr, pos, keys, 25)) {
        return -1;
    }
    found = mip_jr_get(jr, pos, "index", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"index\"");
    }
    {
        mip_jr_push(jr, "index");
        if (mip_jr_u8(jr, vp, &out->index)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "count", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"count\"");
    }
    {
        mip_jr_push(jr, "count");
        if (mip_jr_u8(jr, vp, &out->count)) {
            return -1;
        }
        mip_jr_pop(jr);
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
    found = mip_jr_get(jr, pos, "satellite_id", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"satellite_id\"");
    }
    {
        mip_jr_push(jr, "satellite_id");
        if (mip_jr_u8(jr, vp, &out->satellite_id)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "freq_number", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"freq_number\"");
    }
    {
        mip_jr_push(jr, "freq_number");
        if (mip_jr_s8(jr, vp, &out->freq_number)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "tk", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"tk\"");
    }
    {
        mip_jr_push(jr, "tk");
        if (mip_jr_u32(jr, vp, &out->tk)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "tb", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"tb\"");
    }
    {
        mip_jr_push(jr, "tb");
        if (mip_jr_u32(jr, vp, &out->tb)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "sat_type", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"sat_type\"");
    }
    {
        mip_jr_push(jr, "sat_type");
        if (mip_jr_u8(jr, vp, &out->sat_type)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "gamma", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"gamma\"");
    }
    {
        mip_jr_push(jr, "gamma");
        if (mip_jr_f64(jr, vp, &out->gamma)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "tau_n", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"tau_n\"");
    }
    {
        mip_jr_push(jr, "tau_n");
        if (mip_jr_f64(jr, vp, &out->tau_n)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "x", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"x\"");
    }
    {
        mip_jr_push(jr, "x");
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
            if (mip_jr_f64(jr, ep, &out->x[i])) {
                return -1;
            }
        }
        mip_jr_index(jr, SIZE_MAX);
        if (i != 3) {
            return mip_jr_fail(jr, "expected 3 elements, got %zu", i);
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "v", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"v\"");
    }
    {
        mip_jr_push(jr, "v");
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
            if (mip_jr_f32(jr, ep, &out->v[i])) {
                return -1;
            }
        }
        mip_jr_index(jr, SIZE_MAX);
        if (i != 3) {
            return mip_jr_fail(jr, "expected 3 elements, got %zu", i);
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "a", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"a\"");
    }
    {
        mip_jr_push(jr, "a");
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
            if (mip_jr_f32(jr, ep, &out->a[i])) {
                return -1;
            }
        }
        mip_jr_index(jr, SIZE_MAX);
        if (i != 3) {
            return mip_jr_fail(jr, "expected 3 elements, got %zu", i);
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "health", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"health\"");
    }
    {
        mip_jr_push(jr, "health");
        if (mip_jr_u8(jr, vp, &out->health)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "p", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"p\"");
    }
    {
        mip_jr_push(jr, "p");
        if (mip_jr_u8(jr, vp, &out->p)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "nt", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"nt\"");
    }
    {
        mip_jr_push(jr, "nt");
        if (mip_jr_u8(jr, vp, &out->nt)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "delta_tau_n", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"delta_tau_n\"");
    }
    {
        mip_jr_push(jr, "delta_tau_n");
        if (mip_jr_f32(jr, vp, &out->delta_tau_n)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "ft", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"ft\"");
    }
    {
        mip_jr_push(jr, "ft");
        if (mip_jr_u8(jr, vp, &out->ft)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "en", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"en\"");
    }
    {
        mip_jr_push(jr, "en");
        if (mip_jr_u8(jr, vp, &out->en)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "p1", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"p1\"");
    }
    {
        mip_jr_push(jr, "p1");
        if (mip_jr_u8(jr, vp, &out->p1)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "p2", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"p2\"");
    }
    {
        mip_jr_push(jr, "p2");
        if (mip_jr_u8(jr, vp, &out->p2)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "p3", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"p3\"");
    }
    {
        mip_jr_push(jr, "p3");
        if (mip_jr_u8(jr, vp, &out->p3)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "p4", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"p4\"");
    }
    {
        mip_jr_push(jr, "p4");
        if (mip_jr_u8(jr, vp, &out->p4)) {
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

/* ---- mip_gnss_receiver_1_galileo_ephemeris_t */

static int mip_gnss_receiver_1_galileo_ephemeris_read(mip_reader_t *r,
                                                      mip_gnss_receiver_1_galileo_ephemeris_t *out) {
    mip_rd_push(r, "index");
    if (mip_rd_u8(r, &out->index)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "count");
    if (mip_rd_u8(r, &out->count)) {
        return -1;
    }
    mip_rd_pop(r);
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
    mip_rd_push(r, "satellite_id");
    if (mip_rd_u8(r, &out->satellite_id)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "health");
    if (mip_rd_u8(r, &out->health)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "iodc");
    if (mip_rd_u8(r, &out->iodc)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "iode");
    if (mip_rd_u8(r, &out->iode)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "t_oc");
    if (mip_rd_f64(r, &out->t_oc)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "af0");
    if (mip_rd_f64(r, &out->af0)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "af1");
    if (mip_rd_f64(r, &out->af1)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "af2");
    if (mip_rd_f64(r, &out->af2)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "t_gd");
    if (mip_rd_f64(r, &out->t_gd)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "isc_l1ca");
    if (mip_rd_f64(r, &out->isc_l1ca)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "isc_l2c");
    if (mip_rd_f64(r, &out->isc_l2c)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "t_oe");
    if (mip_rd_f64(r, &out->t_oe)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "a");
    if (mip_rd_f64(r, &out->a)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "a_dot");
    if (mip_rd_f64(r, &out->a_dot)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "mean_anomaly");
    if (mip_rd_f64(r, &out->mean_anomaly)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "delta_mean_motion");
    if (mip_rd_f64(r, &out->delta_mean_motion)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "delta_mean_motion_dot");
    if (mip_rd_f64(r, &out->delta_mean_motion_dot)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "eccentricity");
    if (mip_rd_f64(r, &out->eccentricity)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "argument_of_perigee");
    if (mip_rd_f64(r, &out->argument_of_perigee)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "omega");
    if (mip_rd_f64(r, &out->omega)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "omega_dot");
    if (mip_rd_f64(r, &out->omega_dot)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "inclination");
    if (mip_rd_f64(r, &out->inclination)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "inclination_dot");
    if (mip_rd_f64(r, &out->inclination_dot)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "c_ic");
    if (mip_rd_f64(r, &out->c_ic)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "c_is");
    if (mip_rd_f64(r, &out->c_is)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "c_uc");
    if (mip_rd_f64(r, &out->c_uc)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "c_us");
    if (mip_rd_f64(r, &out->c_us)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "c_rc");
    if (mip_rd_f64(r, &out->c_rc)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "c_rs");
    if (mip_rd_f64(r, &out->c_rs)) {
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

static mip_status_t
mip_gnss_receiver_1_galileo_ephemeris_write(mip_writer_t *w,
                                            const mip_gnss_receiver_1_galileo_ephemeris_t *in) {
    mip_status_t st;
    if ((st = mip_wr_u8(w, &in->index)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_u8(w, &in->count)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_f64(w, &in->tow)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_u16(w, &in->week_number)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_u8(w, &in->satellite_id)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_u8(w, &in->health)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_u8(w, &in->iodc)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_u8(w, &in->iode)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_f64(w, &in->t_oc)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_f64(w, &in->af0)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_f64(w, &in->af1)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_f64(w, &in->af2)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_f64(w, &in->t_gd)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_f64(w, &in->isc_l1ca)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_f64(w, &in->isc_l2c)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_f64(w, &in->t_oe)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_f64(w, &in->a)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_f64(w, &in->a_dot)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_f64(w, &in->mean_anomaly)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_f64(w, &in->delta_mean_motion)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_f64(w, &in->delta_mean_motion_dot)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_f64(w, &in->eccentricity)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_f64(w, &in->argument_of_perigee)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_f64(w, &in->omega)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_f64(w, &in->omega_dot)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_f64(w, &in->inclination)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_f64(w, &in->inclination_dot)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_f64(w, &in->c_ic)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_f64(w, &in->c_is)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_f64(w, &in->c_uc)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_f64(w, &in->c_us)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_f64(w, &in->c_rc)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_f64(w, &in->c_rs)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_u16(w, &in->valid_flags)) != MIP_OK) {
        return st;
    }
    return MIP_OK;
}

mip_status_t
mip_gnss_receiver_1_galileo_ephemeris_encode(const mip_gnss_receiver_1_galileo_ephemeris_t *value,
                                             uint8_t *buf, size_t cap, size_t *len_out) {
    mip_writer_t w;
    mip_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mip_writer_init(&w, buf, cap);
    st = mip_gnss_receiver_1_galileo_ephemeris_write(&w, value);
    if (st == MIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 218 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mip_gnss_receiver_1_galileo_ephemeris_load(const uint8_t *d,
                                                      mip_gnss_receiver_1_galileo_ephemeris_t *out) {
    out->index = mip_ld_u8(d + 0);
    out->count = mip_ld_u8(d + 1);
    out->tow = mip_ld_f64(d + 2);
    out->week_number = mip_ld_u16(d + 10);
    out->satellite_id = mip_ld_u8(d + 12);
    out->health = mip_ld_u8(d + 13);
    out->iodc = mip_ld_u8(d + 14);
    out->iode = mip_ld_u8(d + 15);
    out->t_oc = mip_ld_f64(d + 16);
    out->af0 = mip_ld_f64(d + 24);
    out->af1 = mip_ld_f64(d + 32);
    out->af2 = mip_ld_f64(d + 40);
    out->t_gd = mip_ld_f64(d + 48);
    out->isc_l1ca = mip_ld_f64(d + 56);
    out->isc_l2c = mip_ld_f64(d + 64);
    out->t_oe = mip_ld_f64(d + 72);
    out->a = mip_ld_f64(d + 80);
    out->a_dot = mip_ld_f64(d + 88);
    out->mean_anomaly = mip_ld_f64(d + 96);
    out->delta_mean_motion = mip_ld_f64(d + 104);
    out->delta_mean_motion_dot = mip_ld_f64(d + 112);
    out->eccentricity = mip_ld_f64(d + 120);
    out->argument_of_perigee = mip_ld_f64(d + 128);
    out->omega = mip_ld_f64(d + 136);
    out->omega_dot = mip_ld_f64(d + 144);
    out->inclination = mip_ld_f64(d + 152);
    out->inclination_dot = mip_ld_f64(d + 160);
    out->c_ic = mip_ld_f64(d + 168);
    out->c_is = mip_ld_f64(d + 176);
    out->c_uc = mip_ld_f64(d + 184);
    out->c_us = mip_ld_f64(d + 192);
    out->c_rc = mip_ld_f64(d + 200);
    out->c_rs = mip_ld_f64(d + 208);
    out->valid_flags = mip_ld_u16(d + 216);
    return 0;
}

/* The general reader: lengths other than 218, bad bool bytes, error details. */
static MIP_NOINLINE mip_status_t mip_gnss_receiver_1_galileo_ephemeris_decode_read(
    const uint8_t *data, size_t len, mip_gnss_receiver_1_galileo_ephemeris_t *out, mip_decode_error_t *err) {
    mip_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mip_gnss_receiver_1_galileo_ephemeris_read(&r, out) ? MIP_ERR_DECODE : MIP_OK;
}

mip_status_t mip_gnss_receiver_1_galileo_ephemeris_decode(const uint8_t *data, size_t len,
                                                          mip_gnss_receiver_1_galileo_ephemeris_t *out,
                                                          mip_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 218 && mip_gnss_receiver_1_galileo_ephemeris_load(data, out) == 0) {
        return MIP_OK;
    }
    return mip_gnss_receiver_1_galileo_ephemeris_decode_read(data, len, out, err);
}

void mip_gnss_receiver_1_galileo_ephemeris_to_json(mip_jw_t *w,
                                                   const mip_gnss_receiver_1_galileo_ephemeris_t *in) {
    int first = 1;
    mip_jw_raw(w, "{", 1);
    mip_jw_key(w, &first, "index");
    mip_jw_u8(w, &in->index);
    mip_jw_key(w, &first, "count");
    mip_jw_u8(w, &in->count);
    mip_jw_key(w, &first, "tow");
    mip_jw_f64(w, &in->tow);
    mip_jw_key(w, &first, "week_number");
    mip_jw_u16(w, &in->week_number);
    mip_jw_key(w, &first, "satellite_id");
    mip_jw_u8(w, &in->satellite_id);
    mip_jw_key(w, &first, "health");
    mip_jw_u8(w, &in->health);
    mip_jw_key(w, &first, "iodc");
    mip_jw_u8(w, &in->iodc);
    mip_jw_key(w, &first, "iode");
    mip_jw_u8(w, &in->iode);
    mip_jw_key(w, &first, "t_oc");
    mip_jw_f64(w, &in->t_oc);
    mip_jw_key(w, &first, "af0");
    mip_jw_f64(w, &in->af0);
    mip_jw_key(w, &first, "af1");
    mip_jw_f64(w, &in->af1);
    mip_jw_key(w, &first, "af2");
    mip_jw_f64(w, &in->af2);
    mip_jw_key(w, &first, "t_gd");
    mip_jw_f64(w, &in->t_gd);
    mip_jw_key(w, &first, "isc_l1ca");
    mip_jw_f64(w, &in->isc_l1ca);
    mip_jw_key(w, &first, "isc_l2c");
    mip_jw_f64(w, &in->isc_l2c);
    mip_jw_key(w, &first, "t_oe");
    mip_jw_f64(w, &in->t_oe);
    mip_jw_key(w, &first, "a");
    mip_jw_f64(w, &in->a);
    mip_jw_key(w, &first, "a_dot");
    mip_jw_f64(w, &in->a_dot);
    mip_jw_key(w, &first, "mean_anomaly");
    mip_jw_f64(w, &in->mean_anomaly);
    mip_jw_key(w, &first, "delta_mean_motion");
    mip_jw_f64(w, &in->delta_mean_motion);
    mip_jw_key(w, &first, "delta_mean_motion_dot");
    mip_jw_f64(w, &in->delta_mean_motion_dot);
    mip_jw_key(w, &first, "eccentricity");
    mip_jw_f64(w, &in->eccentricity);
    mip_jw_key(w, &first, "argument_of_perigee");
    mip_jw_f64(w, &in->argument_of_perigee);
    mip_jw_key(w, &first, "omega");
    mip_jw_f64(w, &in->omega);
    mip_jw_key(w, &first, "omega_dot");
    mip_jw_f64(w, &in->omega_dot);
    mip_jw_key(w, &first, "inclination");
    mip_jw_f64(w, &in->inclination);
    mip_jw_key(w, &first, "inclination_dot");
    mip_jw_f64(w, &in->inclination_dot);
    mip_jw_key(w, &first, "c_ic");
    mip_jw_f64(w, &in->c_ic);
    mip_jw_key(w, &first, "c_is");
    mip_jw_f64(w, &in->c_is);
    mip_jw_key(w, &first, "c_uc");
    mip_jw_f64(w, &in->c_uc);
    mip_jw_key(w, &first, "c_us");
    mip_jw_f64(w, &in->c_us);
    mip_jw_key(w, &first, "c_rc");
    mip_jw_f64(w, &in->c_rc);
    mip_jw_key(w, &first, "c_rs");
    mip_jw_f64(w, &in->c_rs);
    mip_jw_key(w, &first, "valid_flags");
    mip_jw_u16(w, &in->valid_flags);
    mip_jw_raw(w, "}", 1);
}

int mip_gnss_receiver_1_galileo_ephemeris_from_json(mip_jr_t *jr, size_t pos,
                                                    mip_gnss_receiver_1_galileo_ephemeris_t *out) {
    static const char *const keys[] = {"index",
                                       "count",
                                       "tow",
                                       "week_number",
                                       "satellite_id",
                                       "health",
                                       "iodc",
                                       "iode",
                                       "t_oc",
                                       "af0",
                                       "af1",
                                       "af2",
                                       "t_gd",
                                       "isc_l1ca",
                                       "isc_l2c",
                                       "t_oe",
                                       "a",
                                       "a_dot",
                                       "mean_anomaly",
                                       "delta_mean_motion",
                                       "delta_mean_motion_dot",
                                       "eccentricity",
                                       "argument_of_perigee",
                                       "omega",
                                       "omega_dot",
                                       "inclination",
                                       "inclination_dot",
                                       "c_ic",
                                       "c_is",
                                       "c_uc",
                                       "c_us",
                                       "c_rc",
                                       "c_rs",
                                       "valid_flags"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mip_jr_object(jr, pos, keys, 34)) {
        return -1;
    }
    found = mip_jr_get(jr, pos, "index", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"index\"");
    }
    {
        mip_jr_push(jr, "index");
        if (mip_jr_u8(jr, vp, &out->index)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "count", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"count\"");
    }
    {
        mip_jr_push(jr, "count");
        if (mip_jr_u8(jr, vp, &out->count)) {
            return -1;
        }
        mip_jr_pop(jr);
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
    found = mip_jr_get(jr, pos, "satellite_id", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"satellite_id\"");
    }
    {
        mip_jr_push(jr, "satellite_id");
        if (mip_jr_u8(jr, vp, &out->satellite_id)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "health", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"health\"");
    }
    {
        mip_jr_push(jr, "health");
        if (mip_jr_u8(jr, vp, &out->health)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "iodc", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"iodc\"");
    }
    {
        mip_jr_push(jr, "iodc");
        if (mip_jr_u8(jr, vp, &out->iodc)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "iode", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"iode\"");
    }
    {
        mip_jr_push(jr, "iode");
        if (mip_jr_u8(jr, vp, &out->iode)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "t_oc", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"t_oc\"");
    }
    {
        mip_jr_push(jr, "t_oc");
        if (mip_jr_f64(jr, vp, &out->t_oc)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "af0", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"af0\"");
    }
    {
        mip_jr_push(jr, "af0");
        if (mip_jr_f64(jr, vp, &out->af0)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "af1", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"af1\"");
    }
    {
        mip_jr_push(jr, "af1");
        if (mip_jr_f64(jr, vp, &out->af1)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "af2", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"af2\"");
    }
    {
        mip_jr_push(jr, "af2");
        if (mip_jr_f64(jr, vp, &out->af2)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "t_gd", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"t_gd\"");
    }
    {
        mip_jr_push(jr, "t_gd");
        if (mip_jr_f64(jr, vp, &out->t_gd)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "isc_l1ca", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"isc_l1ca\"");
    }
    {
        mip_jr_push(jr, "isc_l1ca");
        if (mip_jr_f64(jr, vp, &out->isc_l1ca)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "isc_l2c", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"isc_l2c\"");
    }
    {
        mip_jr_push(jr, "isc_l2c");
        if (mip_jr_f64(jr, vp, &out->isc_l2c)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "t_oe", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"t_oe\"");
    }
    {
        mip_jr_push(jr, "t_oe");
        if (mip_jr_f64(jr, vp, &out->t_oe)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "a", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"a\"");
    }
    {
        mip_jr_push(jr, "a");
        if (mip_jr_f64(jr, vp, &out->a)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "a_dot", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"a_dot\"");
    }
    {
        mip_jr_push(jr, "a_dot");
        if (mip_jr_f64(jr, vp, &out->a_dot)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "mean_anomaly", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"mean_anomaly\"");
    }
    {
        mip_jr_push(jr, "mean_anomaly");
        if (mip_jr_f64(jr, vp, &out->mean_anomaly)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "delta_mean_motion", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"delta_mean_motion\"");
    }
    {
        mip_jr_push(jr, "delta_mean_motion");
        if (mip_jr_f64(jr, vp, &out->delta_mean_motion)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "delta_mean_motion_dot", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"delta_mean_motion_dot\"");
    }
    {
        mip_jr_push(jr, "delta_mean_motion_dot");
        if (mip_jr_f64(jr, vp, &out->delta_mean_motion_dot)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "eccentricity", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"eccentricity\"");
    }
    {
        mip_jr_push(jr, "eccentricity");
        if (mip_jr_f64(jr, vp, &out->eccentricity)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "argument_of_perigee", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"argument_of_perigee\"");
    }
    {
        mip_jr_push(jr, "argument_of_perigee");
        if (mip_jr_f64(jr, vp, &out->argument_of_perigee)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "omega", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"omega\"");
    }
    {
        mip_jr_push(jr, "omega");
        if (mip_jr_f64(jr, vp, &out->omega)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "omega_dot", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"omega_dot\"");
    }
    {
        mip_jr_push(jr, "omega_dot");
        if (mip_jr_f64(jr, vp, &out->omega_dot)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "inclination", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"inclination\"");
    }
    {
        mip_jr_push(jr, "inclination");
        if (mip_jr_f64(jr, vp, &out->inclination)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "inclination_dot", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"inclination_dot\"");
    }
    {
        mip_jr_push(jr, "inclination_dot");
        if (mip_jr_f64(jr, vp, &out->inclination_dot)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "c_ic", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"c_ic\"");
    }
    {
        mip_jr_push(jr, "c_ic");
        if (mip_jr_f64(jr, vp, &out->c_ic)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "c_is", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"c_is\"");
    }
    {
        mip_jr_push(jr, "c_is");
        if (mip_jr_f64(jr, vp, &out->c_is)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "c_uc", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"c_uc\"");
    }
    {
        mip_jr_push(jr, "c_uc");
        if (mip_jr_f64(jr, vp, &out->c_uc)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "c_us", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"c_us\"");
    }
    {
        mip_jr_push(jr, "c_us");
        if (mip_jr_f64(jr, vp, &out->c_us)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "c_rc", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"c_rc\"");
    }
    {
        mip_jr_push(jr, "c_rc");
        if (mip_jr_f64(jr, vp, &out->c_rc)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "c_rs", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"c_rs\"");
    }
    {
        mip_jr_push(jr, "c_rs");
        if (mip_jr_f64(jr, vp, &out->c_rs)) {
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

/* ---- mip_gnss_receiver_1_beidou_ephemeris_t */

static int mip_gnss_receiver_1_beidou_ephemeris_read(mip_reader_t *r,
                                                     mip_gnss_receiver_1_beidou_ephemeris_t *out) {
    mip_rd_push(r, "index");
    if (mip_rd_u8(r, &out->index)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "count");
    if (mip_rd_u8(r, &out->count)) {
        return -1;
    }
    mip_rd_pop(r);
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
    mip_rd_push(r, "satellite_id");
    if (mip_rd_u8(r, &out->satellite_id)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "health");
    if (mip_rd_u8(r, &out->health)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "iodc");
    if (mip_rd_u8(r, &out->iodc)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "iode");
    if (mip_rd_u8(r, &out->iode)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "t_oc");
    if (mip_rd_f64(r, &out->t_oc)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "af0");
    if (mip_rd_f64(r, &out->af0)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "af1");
    if (mip_rd_f64(r, &out->af1)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "af2");
    if (mip_rd_f64(r, &out->af2)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "t_gd");
    if (mip_rd_f64(r, &out->t_gd)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "isc_l1ca");
    if (mip_rd_f64(r, &out->isc_l1ca)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "isc_l2c");
    if (mip_rd_f64(r, &out->isc_l2c)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "t_oe");
    if (mip_rd_f64(r, &out->t_oe)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "a");
    if (mip_rd_f64(r, &out->a)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "a_dot");
    if (mip_rd_f64(r, &out->a_dot)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "mean_anomaly");
    if (mip_rd_f64(r, &out->mean_anomaly)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "delta_mean_motion");
    if (mip_rd_f64(r, &out->delta_mean_motion)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "delta_mean_motion_dot");
    if (mip_rd_f64(r, &out->delta_mean_motion_dot)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "eccentricity");
    if (mip_rd_f64(r, &out->eccentricity)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "argument_of_perigee");
    if (mip_rd_f64(r, &out->argument_of_perigee)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "omega");
    if (mip_rd_f64(r, &out->omega)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "omega_dot");
    if (mip_rd_f64(r, &out->omega_dot)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "inclination");
    if (mip_rd_f64(r, &out->inclination)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "inclination_dot");
    if (mip_rd_f64(r, &out->inclination_dot)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "c_ic");
    if (mip_rd_f64(r, &out->c_ic)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "c_is");
    if (mip_rd_f64(r, &out->c_is)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "c_uc");
    if (mip_rd_f64(r, &out->c_uc)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "c_us");
    if (mip_rd_f64(r, &out->c_us)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "c_rc");
    if (mip_rd_f64(r, &out->c_rc)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "c_rs");
    if (mip_rd_f64(r, &out->c_rs)) {
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

static mip_status_t
mip_gnss_receiver_1_beidou_ephemeris_write(mip_writer_t *w,
                                           const mip_gnss_receiver_1_beidou_ephemeris_t *in) {
    mip_status_t st;
    if ((st = mip_wr_u8(w, &in->index)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_u8(w, &in->count)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_f64(w, &in->tow)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_u16(w, &in->week_number)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_u8(w, &in->satellite_id)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_u8(w, &in->health)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_u8(w, &in->iodc)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_u8(w, &in->iode)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_f64(w, &in->t_oc)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_f64(w, &in->af0)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_f64(w, &in->af1)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_f64(w, &in->af2)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_f64(w, &in->t_gd)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_f64(w, &in->isc_l1ca)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_f64(w, &in->isc_l2c)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_f64(w, &in->t_oe)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_f64(w, &in->a)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_f64(w, &in->a_dot)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_f64(w, &in->mean_anomaly)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_f64(w, &in->delta_mean_motion)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_f64(w, &in->delta_mean_motion_dot)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_f64(w, &in->eccentricity)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_f64(w, &in->argument_of_perigee)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_f64(w, &in->omega)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_f64(w, &in->omega_dot)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_f64(w, &in->inclination)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_f64(w, &in->inclination_dot)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_f64(w, &in->c_ic)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_f64(w, &in->c_is)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_f64(w, &in->c_uc)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_f64(w, &in->c_us)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_f64(w, &in->c_rc)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_f64(w, &in->c_rs)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_u16(w, &in->valid_flags)) != MIP_OK) {
        return st;
    }
    return MIP_OK;
}

mip_status_t mip_gnss_receiver_1_beidou_ephemeris_encode(const mip_gnss_receiver_1_beidou_ephemeris_t *value,
                                                         uint8_t *buf, size_t cap, size_t *len_out) {
    mip_writer_t w;
    mip_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mip_writer_init(&w, buf, cap);
    st = mip_gnss_receiver_1_beidou_ephemeris_write(&w, value);
    if (st == MIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 218 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mip_gnss_receiver_1_beidou_ephemeris_load(const uint8_t *d,
                                                     mip_gnss_receiver_1_beidou_ephemeris_t *out) {
    out->index = mip_ld_u8(d + 0);
    out->count = mip_ld_u8(d + 1);
    out->tow = mip_ld_f64(d + 2);
    out->week_number = mip_ld_u16(d + 10);
    out->satellite_id = mip_ld_u8(d + 12);
    out->health = mip_ld_u8(d + 13);
    out->iodc = mip_ld_u8(d + 14);
    out->iode = mip_ld_u8(d + 15);
    out->t_oc = mip_ld_f64(d + 16);
    out->af0 = mip_ld_f64(d + 24);
    out->af1 = mip_ld_f64(d + 32);
    out->af2 = mip_ld_f64(d + 40);
    out->t_gd = mip_ld_f64(d + 48);
    out->isc_l1ca = mip_ld_f64(d + 56);
    out->isc_l2c = mip_ld_f64(d + 64);
    out->t_oe = mip_ld_f64(d + 72);
    out->a = mip_ld_f64(d + 80);
    out->a_dot = mip_ld_f64(d + 88);
    out->mean_anomaly = mip_ld_f64(d + 96);
    out->delta_mean_motion = mip_ld_f64(d + 104);
    out->delta_mean_motion_dot = mip_ld_f64(d + 112);
    out->eccentricity = mip_ld_f64(d + 120);
    out->argument_of_perigee = mip_ld_f64(d + 128);
    out->omega = mip_ld_f64(d + 136);
    out->omega_dot = mip_ld_f64(d + 144);
    out->inclination = mip_ld_f64(d + 152);
    out->inclination_dot = mip_ld_f64(d + 160);
    out->c_ic = mip_ld_f64(d + 168);
    out->c_is = mip_ld_f64(d + 176);
    out->c_uc = mip_ld_f64(d + 184);
    out->c_us = mip_ld_f64(d + 192);
    out->c_rc = mip_ld_f64(d + 200);
    out->c_rs = mip_ld_f64(d + 208);
    out->valid_flags = mip_ld_u16(d + 216);
    return 0;
}

/* The general reader: lengths other than 218, bad bool bytes, error details. */
static MIP_NOINLINE mip_status_t mip_gnss_receiver_1_beidou_ephemeris_decode_read(
    const uint8_t *data, size_t len, mip_gnss_receiver_1_beidou_ephemeris_t *out, mip_decode_error_t *err) {
    mip_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mip_gnss_receiver_1_beidou_ephemeris_read(&r, out) ? MIP_ERR_DECODE : MIP_OK;
}

mip_status_t mip_gnss_receiver_1_beidou_ephemeris_decode(const uint8_t *data, size_t len,
                                                         mip_gnss_receiver_1_beidou_ephemeris_t *out,
                                                         mip_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 218 && mip_gnss_receiver_1_beidou_ephemeris_load(data, out) == 0) {
        return MIP_OK;
    }
    return mip_gnss_receiver_1_beidou_ephemeris_decode_read(data, len, out, err);
}

void mip_gnss_receiver_1_beidou_ephemeris_to_json(mip_jw_t *w,
                                                  const mip_gnss_receiver_1_beidou_ephemeris_t *in) {
    int first = 1;
    mip_jw_raw(w, "{", 1);
    mip_jw_key(w, &first, "index");
    mip_jw_u8(w, &in->index);
    mip_jw_key(w, &first, "count");
    mip_jw_u8(w, &in->count);
    mip_jw_key(w, &first, "tow");
    mip_jw_f64(w, &in->tow);
    mip_jw_key(w, &first, "week_number");
    mip_jw_u16(w, &in->week_number);
    mip_jw_key(w, &first, "satellite_id");
    mip_jw_u8(w, &in->satellite_id);
    mip_jw_key(w, &first, "health");
    mip_jw_u8(w, &in->health);
    mip_jw_key(w, &first, "iodc");
    mip_jw_u8(w, &in->iodc);
    mip_jw_key(w, &first, "iode");
    mip_jw_u8(w, &in->iode);
    mip_jw_key(w, &first, "t_oc");
    mip_jw_f64(w, &in->t_oc);
    mip_jw_key(w, &first, "af0");
    mip_jw_f64(w, &in->af0);
    mip_jw_key(w, &first, "af1");
    mip_jw_f64(w, &in->af1);
    mip_jw_key(w, &first, "af2");
    mip_jw_f64(w, &in->af2);
    mip_jw_key(w, &first, "t_gd");
    mip_jw_f64(w, &in->t_gd);
    mip_jw_key(w, &first, "isc_l1ca");
    mip_jw_f64(w, &in->isc_l1ca);
    mip_jw_key(w, &first, "isc_l2c");
    mip_jw_f64(w, &in->isc_l2c);
    mip_jw_key(w, &first, "t_oe");
    mip_jw_f64(w, &in->t_oe);
    mip_jw_key(w, &first, "a");
    mip_jw_f64(w, &in->a);
    mip_jw_key(w, &first, "a_dot");
    mip_jw_f64(w, &in->a_dot);
    mip_jw_key(w, &first, "mean_anomaly");
    mip_jw_f64(w, &in->mean_anomaly);
    mip_jw_key(w, &first, "delta_mean_motion");
    mip_jw_f64(w, &in->delta_mean_motion);
    mip_jw_key(w, &first, "delta_mean_motion_dot");
    mip_jw_f64(w, &in->delta_mean_motion_dot);
    mip_jw_key(w, &first, "eccentricity");
    mip_jw_f64(w, &in->eccentricity);
    mip_jw_key(w, &first, "argument_of_perigee");
    mip_jw_f64(w, &in->argument_of_perigee);
    mip_jw_key(w, &first, "omega");
    mip_jw_f64(w, &in->omega);
    mip_jw_key(w, &first, "omega_dot");
    mip_jw_f64(w, &in->omega_dot);
    mip_jw_key(w, &first, "inclination");
    mip_jw_f64(w, &in->inclination);
    mip_jw_key(w, &first, "inclination_dot");
    mip_jw_f64(w, &in->inclination_dot);
    mip_jw_key(w, &first, "c_ic");
    mip_jw_f64(w, &in->c_ic);
    mip_jw_key(w, &first, "c_is");
    mip_jw_f64(w, &in->c_is);
    mip_jw_key(w, &first, "c_uc");
    mip_jw_f64(w, &in->c_uc);
    mip_jw_key(w, &first, "c_us");
    mip_jw_f64(w, &in->c_us);
    mip_jw_key(w, &first, "c_rc");
    mip_jw_f64(w, &in->c_rc);
    mip_jw_key(w, &first, "c_rs");
    mip_jw_f64(w, &in->c_rs);
    mip_jw_key(w, &first, "valid_flags");
    mip_jw_u16(w, &in->valid_flags);
    mip_jw_raw(w, "}", 1);
}

int mip_gnss_receiver_1_beidou_ephemeris_from_json(mip_jr_t *jr, size_t pos,
                                                   mip_gnss_receiver_1_beidou_ephemeris_t *out) {
    static const char *const keys[] = {"index",
                                       "count",
                                       "tow",
                                       "week_number",
                                       "satellite_id",
                                       "health",
                                       "iodc",
                                       "iode",
                                       "t_oc",
                                       "af0",
                                       "af1",
                                       "af2",
                                       "t_gd",
                                       "isc_l1ca",
                                       "isc_l2c",
                                       "t_oe",
                                       "a",
                                       "a_dot",
                                       "mean_anomaly",
                                       "delta_mean_motion",
                                       "delta_mean_motion_dot",
                                       "eccentricity",
                                       "argument_of_perigee",
                                       "omega",
                                       "omega_dot",
                                       "inclination",
                                       "inclination_dot",
                                       "c_ic",
                                       "c_is",
                                       "c_uc",
                                       "c_us",
                                       "c_rc",
                                       "c_rs",
                                       "valid_flags"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mip_jr_object(jr, pos, keys, 34)) {
        return -1;
    }
    found = mip_jr_get(jr, pos, "index", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"index\"");
    }
    {
        mip_jr_push(jr, "index");
        if (mip_jr_u8(jr, vp, &out->index)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "count", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"count\"");
    }
    {
        mip_jr_push(jr, "count");
        if (mip_jr_u8(jr, vp, &out->count)) {
            return -1;
        }
        mip_jr_pop(jr);
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
    found = mip_jr_get(jr, pos, "satellite_id", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"satellite_id\"");
    }
    {
        mip_jr_push(jr, "satellite_id");
        if (mip_jr_u8(jr, vp, &out->satellite_id)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "health", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"health\"");
    }
    {
        mip_jr_push(jr, "health");
        if (mip_jr_u8(jr, vp, &out->health)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "iodc", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"iodc\"");
    }
    {
        mip_jr_push(jr, "iodc");
        if (mip_jr_u8(jr, vp, &out->iodc)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "iode", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"iode\"");
    }
    {
        mip_jr_push(jr, "iode");
        if (mip_jr_u8(jr, vp, &out->iode)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "t_oc", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"t_oc\"");
    }
    {
        mip_jr_push(jr, "t_oc");
        if (mip_jr_f64(jr, vp, &out->t_oc)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "af0", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"af0\"");
    }
    {
        mip_jr_push(jr, "af0");
        if (mip_jr_f64(jr, vp, &out->af0)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "af1", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"af1\"");
    }
    {
        mip_jr_push(jr, "af1");
        if (mip_jr_f64(jr, vp, &out->af1)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "af2", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"af2\"");
    }
    {
        mip_jr_push(jr, "af2");
        if (mip_jr_f64(jr, vp, &out->af2)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "t_gd", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"t_gd\"");
    }
    {
        mip_jr_push(jr, "t_gd");
        if (mip_jr_f64(jr, vp, &out->t_gd)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "isc_l1ca", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"isc_l1ca\"");
    }
    {
        mip_jr_push(jr, "isc_l1ca");
        if (mip_jr_f64(jr, vp, &out->isc_l1ca)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "isc_l2c", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"isc_l2c\"");
    }
    {
        mip_jr_push(jr, "isc_l2c");
        if (mip_jr_f64(jr, vp, &out->isc_l2c)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "t_oe", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"t_oe\"");
    }
    {
        mip_jr_push(jr, "t_oe");
        if (mip_jr_f64(jr, vp, &out->t_oe)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "a", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"a\"");
    }
    {
        mip_jr_push(jr, "a");
        if (mip_jr_f64(jr, vp, &out->a)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "a_dot", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"a_dot\"");
    }
    {
        mip_jr_push(jr, "a_dot");
        if (mip_jr_f64(jr, vp, &out->a_dot)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "mean_anomaly", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"mean_anomaly\"");
    }
    {
        mip_jr_push(jr, "mean_anomaly");
        if (mip_jr_f64(jr, vp, &out->mean_anomaly)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "delta_mean_motion", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"delta_mean_motion\"");
    }
    {
        mip_jr_push(jr, "delta_mean_motion");
        if (mip_jr_f64(jr, vp, &out->delta_mean_motion)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "delta_mean_motion_dot", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"delta_mean_motion_dot\"");
    }
    {
        mip_jr_push(jr, "delta_mean_motion_dot");
        if (mip_jr_f64(jr, vp, &out->delta_mean_motion_dot)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "eccentricity", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"eccentricity\"");
    }
    {
        mip_jr_push(jr, "eccentricity");
        if (mip_jr_f64(jr, vp, &out->eccentricity)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "argument_of_perigee", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"argument_of_perigee\"");
    }
    {
        mip_jr_push(jr, "argument_of_perigee");
        if (mip_jr_f64(jr, vp, &out->argument_of_perigee)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "omega", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"omega\"");
    }
    {
        mip_jr_push(jr, "omega");
        if (mip_jr_f64(jr, vp, &out->omega)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "omega_dot", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"omega_dot\"");
    }
    {
        mip_jr_push(jr, "omega_dot");
        if (mip_jr_f64(jr, vp, &out->omega_dot)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "inclination", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"inclination\"");
    }
    {
        mip_jr_push(jr, "inclination");
        if (mip_jr_f64(jr, vp, &out->inclination)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "inclination_dot", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"inclination_dot\"");
    }
    {
        mip_jr_push(jr, "inclination_dot");
        if (mip_jr_f64(jr, vp, &out->inclination_dot)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "c_ic", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"c_ic\"");
    }
    {
        mip_jr_push(jr, "c_ic");
        if (mip_jr_f64(jr, vp, &out->c_ic)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "c_is", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"c_is\"");
    }
    {
        mip_jr_push(jr, "c_is");
        if (mip_jr_f64(jr, vp, &out->c_is)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "c_uc", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"c_uc\"");
    }
    {
        mip_jr_push(jr, "c_uc");
        if (mip_jr_f64(jr, vp, &out->c_uc)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "c_us", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"c_us\"");
    }
    {
        mip_jr_push(jr, "c_us");
        if (mip_jr_f64(jr, vp, &out->c_us)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "c_rc", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"c_rc\"");
    }
    {
        mip_jr_push(jr, "c_rc");
        if (mip_jr_f64(jr, vp, &out->c_rc)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "c_rs", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"c_rs\"");
    }
    {
        mip_jr_push(jr, "c_rs");
        if (mip_jr_f64(jr, vp, &out->c_rs)) {
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
