/* Encoders and decoders of GNSS External Data Set. Generated from the spec: do not edit. */
#include "mipcodec/sets/gnss_external.h"
#include "layouts_internal.h"
#include "types_internal.h"

#include <assert.h>
#include <string.h>

/* ---- mip_gnss_external_llh_position_t */

static int mip_gnss_external_llh_position_read(mip_reader_t *r, mip_gnss_external_llh_position_t *out) {
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

static mip_status_t mip_gnss_external_llh_position_write(mip_writer_t *w,
                                                         const mip_gnss_external_llh_position_t *in) {
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

mip_status_t mip_gnss_external_llh_position_encode(const mip_gnss_external_llh_position_t *value,
                                                   uint8_t *buf, size_t cap, size_t *len_out) {
    mip_writer_t w;
    mip_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mip_writer_init(&w, buf, cap);
    st = mip_gnss_external_llh_position_write(&w, value);
    if (st == MIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 42 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mip_gnss_external_llh_position_load(const uint8_t *d, mip_gnss_external_llh_position_t *out) {
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
static MIP_NOINLINE mip_status_t mip_gnss_external_llh_position_decode_read(
    const uint8_t *data, size_t len, mip_gnss_external_llh_position_t *out, mip_decode_error_t *err) {
    mip_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mip_gnss_external_llh_position_read(&r, out) ? MIP_ERR_DECODE : MIP_OK;
}

mip_status_t mip_gnss_external_llh_position_decode(const uint8_t *data, size_t len,
                                                   mip_gnss_external_llh_position_t *out,
                                                   mip_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 42 && mip_gnss_external_llh_position_load(data, out) == 0) {
        return MIP_OK;
    }
    return mip_gnss_external_llh_position_decode_read(data, len, out, err);
}

void mip_gnss_external_llh_position_to_json(mip_jw_t *w, const mip_gnss_external_llh_position_t *in) {
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

int mip_gnss_external_llh_position_from_json(mip_jr_t *jr, size_t pos,
                                             mip_gnss_external_llh_position_t *out) {
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

/* ---- mip_gnss_external_ned_velocity_t */

static int mip_gnss_external_ned_velocity_read(mip_reader_t *r, mip_gnss_external_ned_velocity_t *out) {
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

static mip_status_t mip_gnss_external_ned_velocity_write(mip_writer_t *w,
                                                         const mip_gnss_external_ned_velocity_t *in) {
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

mip_status_t mip_gnss_external_ned_velocity_encode(const mip_gnss_external_ned_velocity_t *value,
                                                   uint8_t *buf, size_t cap, size_t *len_out) {
    mip_writer_t w;
    mip_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mip_writer_init(&w, buf, cap);
    st = mip_gnss_external_ned_velocity_write(&w, value);
    if (st == MIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 34 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mip_gnss_external_ned_velocity_load(const uint8_t *d, mip_gnss_external_ned_velocity_t *out) {
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
static MIP_NOINLINE mip_status_t mip_gnss_external_ned_velocity_decode_read(
    const uint8_t *data, size_t len, mip_gnss_external_ned_velocity_t *out, mip_decode_error_t *err) {
    mip_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mip_gnss_external_ned_velocity_read(&r, out) ? MIP_ERR_DECODE : MIP_OK;
}

mip_status_t mip_gnss_external_ned_velocity_decode(const uint8_t *data, size_t len,
                                                   mip_gnss_external_ned_velocity_t *out,
                                                   mip_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 34 && mip_gnss_external_ned_velocity_load(data, out) == 0) {
        return MIP_OK;
    }
    return mip_gnss_external_ned_velocity_decode_read(data, len, out, err);
}

void mip_gnss_external_ned_velocity_to_json(mip_jw_t *w, const mip_gnss_external_ned_velocity_t *in) {
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

int mip_gnss_external_ned_velocity_from_json(mip_jr_t *jr, size_t pos,
                                             mip_gnss_external_ned_velocity_t *out) {
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

/* ---- mip_gnss_external_utc_time_t */

static int mip_gnss_external_utc_time_read(mip_reader_t *r, mip_gnss_external_utc_time_t *out) {
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

static mip_status_t mip_gnss_external_utc_time_write(mip_writer_t *w,
                                                     const mip_gnss_external_utc_time_t *in) {
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

mip_status_t mip_gnss_external_utc_time_encode(const mip_gnss_external_utc_time_t *value, uint8_t *buf,
                                               size_t cap, size_t *len_out) {
    mip_writer_t w;
    mip_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mip_writer_init(&w, buf, cap);
    st = mip_gnss_external_utc_time_write(&w, value);
    if (st == MIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 13 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mip_gnss_external_utc_time_load(const uint8_t *d, mip_gnss_external_utc_time_t *out) {
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
static MIP_NOINLINE mip_status_t mip_gnss_external_utc_time_decode_read(const uint8_t *data, size_t len,
                                                                        mip_gnss_external_utc_time_t *out,
                                                                        mip_decode_error_t *err) {
    mip_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mip_gnss_external_utc_time_read(&r, out) ? MIP_ERR_DECODE : MIP_OK;
}

mip_status_t mip_gnss_external_utc_time_decode(const uint8_t *data, size_t len,
                                               mip_gnss_external_utc_time_t *out, mip_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 13 && mip_gnss_external_utc_time_load(data, out) == 0) {
        return MIP_OK;
    }
    return mip_gnss_external_utc_time_decode_read(data, len, out, err);
}

void mip_gnss_external_utc_time_to_json(mip_jw_t *w, const mip_gnss_external_utc_time_t *in) {
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

int mip_gnss_external_utc_time_from_json(mip_jr_t *jr, size_t pos, mip_gnss_external_utc_time_t *out) {
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

/* ---- mip_gnss_external_fix_info_t */

static int mip_gnss_external_fix_info_read(mip_reader_t *r, mip_gnss_external_fix_info_t *out) {
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

static mip_status_t mip_gnss_external_fix_info_write(mip_writer_t *w,
                                                     const mip_gnss_external_fix_info_t *in) {
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

mip_status_t mip_gnss_external_fix_info_encode(const mip_gnss_external_fix_info_t *value, uint8_t *buf,
                                               size_t cap, size_t *len_out) {
    mip_writer_t w;
    mip_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mip_writer_init(&w, buf, cap);
    st = mip_gnss_external_fix_info_write(&w, value);
    if (st == MIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 6 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mip_gnss_external_fix_info_load(const uint8_t *d, mip_gnss_external_fix_info_t *out) {
    out->fix_type = mip_ld_u8(d + 0);
    out->num_sv = mip_ld_u8(d + 1);
    out->fix_flags = mip_ld_u16(d + 2);
    out->valid_flags = mip_ld_u16(d + 4);
    return 0;
}

/* The general reader: lengths other than 6, bad bool bytes, error details. */
static MIP_NOINLINE mip_status_t mip_gnss_external_fix_info_decode_read(const uint8_t *data, size_t len,
                                                                        mip_gnss_external_fix_info_t *out,
                                                                        mip_decode_error_t *err) {
    mip_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mip_gnss_external_fix_info_read(&r, out) ? MIP_ERR_DECODE : MIP_OK;
}

mip_status_t mip_gnss_external_fix_info_decode(const uint8_t *data, size_t len,
                                               mip_gnss_external_fix_info_t *out, mip_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 6 && mip_gnss_external_fix_info_load(data, out) == 0) {
        return MIP_OK;
    }
    return mip_gnss_external_fix_info_decode_read(data, len, out, err);
}

void mip_gnss_external_fix_info_to_json(mip_jw_t *w, const mip_gnss_external_fix_info_t *in) {
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

int mip_gnss_external_fix_info_from_json(mip_jr_t *jr, size_t pos, mip_gnss_external_fix_info_t *out) {
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

/* ---- mip_gnss_external_satellite_status_t */

static int mip_gnss_external_satellite_status_read(mip_reader_t *r,
                                                   mip_gnss_external_satellite_status_t *out) {
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

static mip_status_t mip_gnss_external_satellite_status_write(mip_writer_t *w,
                                                             const mip_gnss_external_satellite_status_t *in) {
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

mip_status_t mip_gnss_external_satellite_status_encode(const mip_gnss_external_satellite_status_t *value,
                                                       uint8_t *buf, size_t cap, size_t *len_out) {
    mip_writer_t w;
    mip_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mip_writer_init(&w, buf, cap);
    st = mip_gnss_external_satellite_status_write(&w, value);
    if (st == MIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 25 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mip_gnss_external_satellite_status_load(const uint8_t *d,
                                                   mip_gnss_external_satellite_status_t *out) {
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
static MIP_NOINLINE mip_status_t mip_gnss_external_satellite_status_decode_read(
    const uint8_t *data, size_t len, mip_gnss_external_satellite_status_t *out, mip_decode_error_t *err) {
    mip_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mip_gnss_external_satellite_status_read(&r, out) ? MIP_ERR_DECODE : MIP_OK;
}

mip_status_t mip_gnss_external_satellite_status_decode(const uint8_t *data, size_t len,
                                                       mip_gnss_external_satellite_status_t *out,
                                                       mip_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 25 && mip_gnss_external_satellite_status_load(data, out) == 0) {
        return MIP_OK;
    }
    return mip_gnss_external_satellite_status_decode_read(data, len, out, err);
}

void mip_gnss_external_satellite_status_to_json(mip_jw_t *w, const mip_gnss_external_satellite_status_t *in) {
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

int mip_gnss_external_satellite_status_from_json(mip_jr_t *jr, size_t pos,
                                                 mip_gnss_external_satellite_status_t *out) {
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
