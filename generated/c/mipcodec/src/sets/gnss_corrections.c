/* Encoders and decoders of GNSS Corrections Data Set. Generated from the spec: do not edit. */
#include "mipcodec/sets/gnss_corrections.h"
#include "layouts_internal.h"
#include "types_internal.h"

#include <assert.h>
#include <string.h>

/* ---- mip_gnss_corrections_base_station_info_t */

static int mip_gnss_corrections_base_station_info_read(mip_reader_t *r,
                                                       mip_gnss_corrections_base_station_info_t *out) {
    size_t i;
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
    mip_rd_push(r, "ecef_position");
    for (i = 0; i < 3; i++) {
        mip_rd_index(r, i);
        if (mip_rd_f64(r, &out->ecef_position[i])) {
            return -1;
        }
    }
    mip_rd_pop(r);
    mip_rd_push(r, "height");
    if (mip_rd_f32(r, &out->height)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "station_id");
    if (mip_rd_u16(r, &out->station_id)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "indicators");
    if (mip_rd_u16(r, &out->indicators)) {
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
mip_gnss_corrections_base_station_info_write(mip_writer_t *w,
                                             const mip_gnss_corrections_base_station_info_t *in) {
    mip_status_t st;
    size_t i;
    if ((st = mip_wr_f64(w, &in->tow)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_u16(w, &in->week_number)) != MIP_OK) {
        return st;
    }
    for (i = 0; i < 3; i++) {
        if ((st = mip_wr_f64(w, &in->ecef_position[i])) != MIP_OK) {
            return st;
        }
    }
    if ((st = mip_wr_f32(w, &in->height)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_u16(w, &in->station_id)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_u16(w, &in->indicators)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_u16(w, &in->valid_flags)) != MIP_OK) {
        return st;
    }
    return MIP_OK;
}

mip_status_t
mip_gnss_corrections_base_station_info_encode(const mip_gnss_corrections_base_station_info_t *value,
                                              uint8_t *buf, size_t cap, size_t *len_out) {
    mip_writer_t w;
    mip_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mip_writer_init(&w, buf, cap);
    st = mip_gnss_corrections_base_station_info_write(&w, value);
    if (st == MIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 44 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mip_gnss_corrections_base_station_info_load(const uint8_t *d,
                                                       mip_gnss_corrections_base_station_info_t *out) {
    out->tow = mip_ld_f64(d + 0);
    out->week_number = mip_ld_u16(d + 8);
    out->ecef_position[0] = mip_ld_f64(d + 10);
    out->ecef_position[1] = mip_ld_f64(d + 18);
    out->ecef_position[2] = mip_ld_f64(d + 26);
    out->height = mip_ld_f32(d + 34);
    out->station_id = mip_ld_u16(d + 38);
    out->indicators = mip_ld_u16(d + 40);
    out->valid_flags = mip_ld_u16(d + 42);
    return 0;
}

/* The general reader: lengths other than 44, bad bool bytes, error details. */
static MIP_NOINLINE mip_status_t mip_gnss_corrections_base_station_info_decode_read(
    const uint8_t *data, size_t len, mip_gnss_corrections_base_station_info_t *out, mip_decode_error_t *err) {
    mip_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mip_gnss_corrections_base_station_info_read(&r, out) ? MIP_ERR_DECODE : MIP_OK;
}

mip_status_t mip_gnss_corrections_base_station_info_decode(const uint8_t *data, size_t len,
                                                           mip_gnss_corrections_base_station_info_t *out,
                                                           mip_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 44 && mip_gnss_corrections_base_station_info_load(data, out) == 0) {
        return MIP_OK;
    }
    return mip_gnss_corrections_base_station_info_decode_read(data, len, out, err);
}

void mip_gnss_corrections_base_station_info_to_json(mip_jw_t *w,
                                                    const mip_gnss_corrections_base_station_info_t *in) {
    int first = 1;
    size_t i;
    mip_jw_raw(w, "{", 1);
    mip_jw_key(w, &first, "tow");
    mip_jw_f64(w, &in->tow);
    mip_jw_key(w, &first, "week_number");
    mip_jw_u16(w, &in->week_number);
    mip_jw_key(w, &first, "ecef_position");
    mip_jw_raw(w, "[", 1);
    for (i = 0; i < 3; i++) {
        mip_jw_sep(w, i);
        mip_jw_f64(w, &in->ecef_position[i]);
    }
    mip_jw_raw(w, "]", 1);
    mip_jw_key(w, &first, "height");
    mip_jw_f32(w, &in->height);
    mip_jw_key(w, &first, "station_id");
    mip_jw_u16(w, &in->station_id);
    mip_jw_key(w, &first, "indicators");
    mip_jw_u16(w, &in->indicators);
    mip_jw_key(w, &first, "valid_flags");
    mip_jw_u16(w, &in->valid_flags);
    mip_jw_raw(w, "}", 1);
}

int mip_gnss_corrections_base_station_info_from_json(mip_jr_t *jr, size_t pos,
                                                     mip_gnss_corrections_base_station_info_t *out) {
    static const char *const keys[] = {"tow",        "week_number", "ecef_position", "height",
                                       "station_id", "indicators",  "valid_flags"};
    size_t vp = 0;
    int found;
    size_t i;
    size_t it = 0;
    size_t ep = 0;
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
    found = mip_jr_get(jr, pos, "ecef_position", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"ecef_position\"");
    }
    {
        mip_jr_push(jr, "ecef_position");
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
            if (mip_jr_f64(jr, ep, &out->ecef_position[i])) {
                return -1;
            }
        }
        mip_jr_index(jr, SIZE_MAX);
        if (i != 3) {
            return mip_jr_fail(jr, "expected 3 elements, got %zu", i);
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "height", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"height\"");
    }
    {
        mip_jr_push(jr, "height");
        if (mip_jr_f32(jr, vp, &out->height)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "station_id", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"station_id\"");
    }
    {
        mip_jr_push(jr, "station_id");
        if (mip_jr_u16(jr, vp, &out->station_id)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "indicators", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"indicators\"");
    }
    {
        mip_jr_push(jr, "indicators");
        if (mip_jr_u16(jr, vp, &out->indicators)) {
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

/* ---- mip_gnss_corrections_rtk_corrections_status_t */

static int
mip_gnss_corrections_rtk_corrections_status_read(mip_reader_t *r,
                                                 mip_gnss_corrections_rtk_corrections_status_t *out) {
    size_t i;
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
    mip_rd_push(r, "epoch_status");
    if (mip_rd_u16(r, &out->epoch_status)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "dongle_status");
    if (mip_rd_u32(r, &out->dongle_status)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "gps_correction_latency");
    if (mip_rd_f32(r, &out->gps_correction_latency)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "glonass_correction_latency");
    if (mip_rd_f32(r, &out->glonass_correction_latency)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "galileo_correction_latency");
    if (mip_rd_f32(r, &out->galileo_correction_latency)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "beidou_correction_latency");
    if (mip_rd_f32(r, &out->beidou_correction_latency)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "reserved");
    for (i = 0; i < 4; i++) {
        mip_rd_index(r, i);
        if (mip_rd_u32(r, &out->reserved[i])) {
            return -1;
        }
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
mip_gnss_corrections_rtk_corrections_status_write(mip_writer_t *w,
                                                  const mip_gnss_corrections_rtk_corrections_status_t *in) {
    mip_status_t st;
    size_t i;
    if ((st = mip_wr_f64(w, &in->tow)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_u16(w, &in->week_number)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_u16(w, &in->epoch_status)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_u32(w, &in->dongle_status)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_f32(w, &in->gps_correction_latency)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_f32(w, &in->glonass_correction_latency)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_f32(w, &in->galileo_correction_latency)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_f32(w, &in->beidou_correction_latency)) != MIP_OK) {
        return st;
    }
    for (i = 0; i < 4; i++) {
        if ((st = mip_wr_u32(w, &in->reserved[i])) != MIP_OK) {
            return st;
        }
    }
    if ((st = mip_wr_u16(w, &in->valid_flags)) != MIP_OK) {
        return st;
    }
    return MIP_OK;
}

mip_status_t
mip_gnss_corrections_rtk_corrections_status_encode(const mip_gnss_corrections_rtk_corrections_status_t *value,
                                                   uint8_t *buf, size_t cap, size_t *len_out) {
    mip_writer_t w;
    mip_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mip_writer_init(&w, buf, cap);
    st = mip_gnss_corrections_rtk_corrections_status_write(&w, value);
    if (st == MIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 50 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int
mip_gnss_corrections_rtk_corrections_status_load(const uint8_t *d,
                                                 mip_gnss_corrections_rtk_corrections_status_t *out) {
    out->tow = mip_ld_f64(d + 0);
    out->week_number = mip_ld_u16(d + 8);
    out->epoch_status = mip_ld_u16(d + 10);
    out->dongle_status = mip_ld_u32(d + 12);
    out->gps_correction_latency = mip_ld_f32(d + 16);
    out->glonass_correction_latency = mip_ld_f32(d + 20);
    out->galileo_correction_latency = mip_ld_f32(d + 24);
    out->beidou_correction_latency = mip_ld_f32(d + 28);
    out->reserved[0] = mip_ld_u32(d + 32);
    out->reserved[1] = mip_ld_u32(d + 36);
    out->reserved[2] = mip_ld_u32(d + 40);
    out->reserved[3] = mip_ld_u32(d + 44);
    out->valid_flags = mip_ld_u16(d + 48);
    return 0;
}

/* The general reader: lengths other than 50, bad bool bytes, error details. */
static MIP_NOINLINE mip_status_t mip_gnss_corrections_rtk_corrections_status_decode_read(
    const uint8_t *data, size_t len, mip_gnss_corrections_rtk_corrections_status_t *out,
    mip_decode_error_t *err) {
    mip_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mip_gnss_corrections_rtk_corrections_status_read(&r, out) ? MIP_ERR_DECODE : MIP_OK;
}

mip_status_t
mip_gnss_corrections_rtk_corrections_status_decode(const uint8_t *data, size_t len,
                                                   mip_gnss_corrections_rtk_corrections_status_t *out,
                                                   mip_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 50 && mip_gnss_corrections_rtk_corrections_status_load(data, out) == 0) {
        return MIP_OK;
    }
    return mip_gnss_corrections_rtk_corrections_status_decode_read(data, len, out, err);
}

void mip_gnss_corrections_rtk_corrections_status_to_json(
    mip_jw_t *w, const mip_gnss_corrections_rtk_corrections_status_t *in) {
    int first = 1;
    size_t i;
    mip_jw_raw(w, "{", 1);
    mip_jw_key(w, &first, "tow");
    mip_jw_f64(w, &in->tow);
    mip_jw_key(w, &first, "week_number");
    mip_jw_u16(w, &in->week_number);
    mip_jw_key(w, &first, "epoch_status");
    mip_jw_u16(w, &in->epoch_status);
    mip_jw_key(w, &first, "dongle_status");
    mip_jw_u32(w, &in->dongle_status);
    mip_jw_key(w, &first, "gps_correction_latency");
    mip_jw_f32(w, &in->gps_correction_latency);
    mip_jw_key(w, &first, "glonass_correction_latency");
    mip_jw_f32(w, &in->glonass_correction_latency);
    mip_jw_key(w, &first, "galileo_correction_latency");
    mip_jw_f32(w, &in->galileo_correction_latency);
    mip_jw_key(w, &first, "beidou_correction_latency");
    mip_jw_f32(w, &in->beidou_correction_latency);
    mip_jw_key(w, &first, "reserved");
    mip_jw_raw(w, "[", 1);
    for (i = 0; i < 4; i++) {
        mip_jw_sep(w, i);
        mip_jw_u32(w, &in->reserved[i]);
    }
    mip_jw_raw(w, "]", 1);
    mip_jw_key(w, &first, "valid_flags");
    mip_jw_u16(w, &in->valid_flags);
    mip_jw_raw(w, "}", 1);
}

int mip_gnss_corrections_rtk_corrections_status_from_json(
    mip_jr_t *jr, size_t pos, mip_gnss_corrections_rtk_corrections_status_t *out) {
    static const char *const keys[] = {"tow",
                                       "week_number",
                                       "epoch_status",
                                       "dongle_status",
                                       "gps_correction_latency",
                                       "glonass_correction_latency",
                                       "galileo_correction_latency",
                                       "beidou_correction_latency",
                                       "reserved",
                                       "valid_flags"};
    size_t vp = 0;
    int found;
    size_t i;
    size_t it = 0;
    size_t ep = 0;
    memset(out, 0, sizeof *out);
    if (mip_jr_object(jr, pos, keys, 10)) {
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
    found = mip_jr_get(jr, pos, "epoch_status", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"epoch_status\"");
    }
    {
        mip_jr_push(jr, "epoch_status");
        if (mip_jr_u16(jr, vp, &out->epoch_status)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "dongle_status", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"dongle_status\"");
    }
    {
        mip_jr_push(jr, "dongle_status");
        if (mip_jr_u32(jr, vp, &out->dongle_status)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "gps_correction_latency", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"gps_correction_latency\"");
    }
    {
        mip_jr_push(jr, "gps_correction_latency");
        if (mip_jr_f32(jr, vp, &out->gps_correction_latency)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "glonass_correction_latency", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"glonass_correction_latency\"");
    }
    {
        mip_jr_push(jr, "glonass_correction_latency");
        if (mip_jr_f32(jr, vp, &out->glonass_correction_latency)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "galileo_correction_latency", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"galileo_correction_latency\"");
    }
    {
        mip_jr_push(jr, "galileo_correction_latency");
        if (mip_jr_f32(jr, vp, &out->galileo_correction_latency)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "beidou_correction_latency", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"beidou_correction_latency\"");
    }
    {
        mip_jr_push(jr, "beidou_correction_latency");
        if (mip_jr_f32(jr, vp, &out->beidou_correction_latency)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "reserved", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"reserved\"");
    }
    {
        mip_jr_push(jr, "reserved");
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
            if (mip_jr_u32(jr, ep, &out->reserved[i])) {
                return -1;
            }
        }
        mip_jr_index(jr, SIZE_MAX);
        if (i != 4) {
            return mip_jr_fail(jr, "expected 4 elements, got %zu", i);
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
