/* Encoders and decoders of Shared Data Descriptors. Generated from the spec: do not edit. */
#include "mipcodec/sets/shared.h"
#include "layouts_internal.h"
#include "types_internal.h"

#include <assert.h>
#include <string.h>

/* ---- mip_shared_event_source_t */

static int mip_shared_event_source_read(mip_reader_t *r, mip_shared_event_source_t *out) {
    mip_rd_push(r, "trigger_id");
    if (mip_rd_u8(r, &out->trigger_id)) {
        return -1;
    }
    mip_rd_pop(r);
    return mip_rd_finish(r);
}

static mip_status_t mip_shared_event_source_write(mip_writer_t *w, const mip_shared_event_source_t *in) {
    mip_status_t st;
    if ((st = mip_wr_u8(w, &in->trigger_id)) != MIP_OK) {
        return st;
    }
    return MIP_OK;
}

mip_status_t mip_shared_event_source_encode(const mip_shared_event_source_t *value, uint8_t *buf, size_t cap,
                                            size_t *len_out) {
    mip_writer_t w;
    mip_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mip_writer_init(&w, buf, cap);
    st = mip_shared_event_source_write(&w, value);
    if (st == MIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 1 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mip_shared_event_source_load(const uint8_t *d, mip_shared_event_source_t *out) {
    out->trigger_id = mip_ld_u8(d + 0);
    return 0;
}

/* The general reader: lengths other than 1, bad bool bytes, error details. */
static MIP_NOINLINE mip_status_t mip_shared_event_source_decode_read(const uint8_t *data, size_t len,
                                                                     mip_shared_event_source_t *out,
                                                                     mip_decode_error_t *err) {
    mip_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mip_shared_event_source_read(&r, out) ? MIP_ERR_DECODE : MIP_OK;
}

mip_status_t mip_shared_event_source_decode(const uint8_t *data, size_t len, mip_shared_event_source_t *out,
                                            mip_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 1 && mip_shared_event_source_load(data, out) == 0) {
        return MIP_OK;
    }
    return mip_shared_event_source_decode_read(data, len, out, err);
}

void mip_shared_event_source_to_json(mip_jw_t *w, const mip_shared_event_source_t *in) {
    int first = 1;
    mip_jw_raw(w, "{", 1);
    mip_jw_key(w, &first, "trigger_id");
    mip_jw_u8(w, &in->trigger_id);
    mip_jw_raw(w, "}", 1);
}

int mip_shared_event_source_from_json(mip_jr_t *jr, size_t pos, mip_shared_event_source_t *out) {
    static const char *const keys[] = {"trigger_id"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mip_jr_object(jr, pos, keys, 1)) {
        return -1;
    }
    found = mip_jr_get(jr, pos, "trigger_id", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"trigger_id\"");
    }
    {
        mip_jr_push(jr, "trigger_id");
        if (mip_jr_u8(jr, vp, &out->trigger_id)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    return 0;
}

/* ---- mip_shared_gps_timestamp_t */

static int mip_shared_gps_timestamp_read(mip_reader_t *r, mip_shared_gps_timestamp_t *out) {
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

static mip_status_t mip_shared_gps_timestamp_write(mip_writer_t *w, const mip_shared_gps_timestamp_t *in) {
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

mip_status_t mip_shared_gps_timestamp_encode(const mip_shared_gps_timestamp_t *value, uint8_t *buf,
                                             size_t cap, size_t *len_out) {
    mip_writer_t w;
    mip_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mip_writer_init(&w, buf, cap);
    st = mip_shared_gps_timestamp_write(&w, value);
    if (st == MIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 12 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mip_shared_gps_timestamp_load(const uint8_t *d, mip_shared_gps_timestamp_t *out) {
    out->tow = mip_ld_f64(d + 0);
    out->week_number = mip_ld_u16(d + 8);
    out->valid_flags = mip_ld_u16(d + 10);
    return 0;
}

/* The general reader: lengths other than 12, bad bool bytes, error details. */
static MIP_NOINLINE mip_status_t mip_shared_gps_timestamp_decode_read(const uint8_t *data, size_t len,
                                                                      mip_shared_gps_timestamp_t *out,
                                                                      mip_decode_error_t *err) {
    mip_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mip_shared_gps_timestamp_read(&r, out) ? MIP_ERR_DECODE : MIP_OK;
}

mip_status_t mip_shared_gps_timestamp_decode(const uint8_t *data, size_t len, mip_shared_gps_timestamp_t *out,
                                             mip_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 12 && mip_shared_gps_timestamp_load(data, out) == 0) {
        return MIP_OK;
    }
    return mip_shared_gps_timestamp_decode_read(data, len, out, err);
}

void mip_shared_gps_timestamp_to_json(mip_jw_t *w, const mip_shared_gps_timestamp_t *in) {
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

int mip_shared_gps_timestamp_from_json(mip_jr_t *jr, size_t pos, mip_shared_gps_timestamp_t *out) {
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

/* ---- mip_shared_delta_time_t */

static int mip_shared_delta_time_read(mip_reader_t *r, mip_shared_delta_time_t *out) {
    mip_rd_push(r, "seconds");
    if (mip_rd_f64(r, &out->seconds)) {
        return -1;
    }
    mip_rd_pop(r);
    return mip_rd_finish(r);
}

static mip_status_t mip_shared_delta_time_write(mip_writer_t *w, const mip_shared_delta_time_t *in) {
    mip_status_t st;
    if ((st = mip_wr_f64(w, &in->seconds)) != MIP_OK) {
        return st;
    }
    return MIP_OK;
}

mip_status_t mip_shared_delta_time_encode(const mip_shared_delta_time_t *value, uint8_t *buf, size_t cap,
                                          size_t *len_out) {
    mip_writer_t w;
    mip_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mip_writer_init(&w, buf, cap);
    st = mip_shared_delta_time_write(&w, value);
    if (st == MIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 8 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mip_shared_delta_time_load(const uint8_t *d, mip_shared_delta_time_t *out) {
    out->seconds = mip_ld_f64(d + 0);
    return 0;
}

/* The general reader: lengths other than 8, bad bool bytes, error details. */
static MIP_NOINLINE mip_status_t mip_shared_delta_time_decode_read(const uint8_t *data, size_t len,
                                                                   mip_shared_delta_time_t *out,
                                                                   mip_decode_error_t *err) {
    mip_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mip_shared_delta_time_read(&r, out) ? MIP_ERR_DECODE : MIP_OK;
}

mip_status_t mip_shared_delta_time_decode(const uint8_t *data, size_t len, mip_shared_delta_time_t *out,
                                          mip_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 8 && mip_shared_delta_time_load(data, out) == 0) {
        return MIP_OK;
    }
    return mip_shared_delta_time_decode_read(data, len, out, err);
}

void mip_shared_delta_time_to_json(mip_jw_t *w, const mip_shared_delta_time_t *in) {
    int first = 1;
    mip_jw_raw(w, "{", 1);
    mip_jw_key(w, &first, "seconds");
    mip_jw_f64(w, &in->seconds);
    mip_jw_raw(w, "}", 1);
}

int mip_shared_delta_time_from_json(mip_jr_t *jr, size_t pos, mip_shared_delta_time_t *out) {
    static const char *const keys[] = {"seconds"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mip_jr_object(jr, pos, keys, 1)) {
        return -1;
    }
    found = mip_jr_get(jr, pos, "seconds", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"seconds\"");
    }
    {
        mip_jr_push(jr, "seconds");
        if (mip_jr_f64(jr, vp, &out->seconds)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    return 0;
}

/* ---- mip_shared_reference_timestamp_t */

static int mip_shared_reference_timestamp_read(mip_reader_t *r, mip_shared_reference_timestamp_t *out) {
    mip_rd_push(r, "nanoseconds");
    if (mip_rd_u64(r, &out->nanoseconds)) {
        return -1;
    }
    mip_rd_pop(r);
    return mip_rd_finish(r);
}

static mip_status_t mip_shared_reference_timestamp_write(mip_writer_t *w,
                                                         const mip_shared_reference_timestamp_t *in) {
    mip_status_t st;
    if ((st = mip_wr_u64(w, &in->nanoseconds)) != MIP_OK) {
        return st;
    }
    return MIP_OK;
}

mip_status_t mip_shared_reference_timestamp_encode(const mip_shared_reference_timestamp_t *value,
                                                   uint8_t *buf, size_t cap, size_t *len_out) {
    mip_writer_t w;
    mip_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mip_writer_init(&w, buf, cap);
    st = mip_shared_reference_timestamp_write(&w, value);
    if (st == MIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 8 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mip_shared_reference_timestamp_load(const uint8_t *d, mip_shared_reference_timestamp_t *out) {
    out->nanoseconds = mip_ld_u64(d + 0);
    return 0;
}

/* The general reader: lengths other than 8, bad bool bytes, error details. */
static MIP_NOINLINE mip_status_t mip_shared_reference_timestamp_decode_read(
    const uint8_t *data, size_t len, mip_shared_reference_timestamp_t *out, mip_decode_error_t *err) {
    mip_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mip_shared_reference_timestamp_read(&r, out) ? MIP_ERR_DECODE : MIP_OK;
}

mip_status_t mip_shared_reference_timestamp_decode(const uint8_t *data, size_t len,
                                                   mip_shared_reference_timestamp_t *out,
                                                   mip_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 8 && mip_shared_reference_timestamp_load(data, out) == 0) {
        return MIP_OK;
    }
    return mip_shared_reference_timestamp_decode_read(data, len, out, err);
}

void mip_shared_reference_timestamp_to_json(mip_jw_t *w, const mip_shared_reference_timestamp_t *in) {
    int first = 1;
    mip_jw_raw(w, "{", 1);
    mip_jw_key(w, &first, "nanoseconds");
    mip_jw_u64(w, &in->nanoseconds);
    mip_jw_raw(w, "}", 1);
}

int mip_shared_reference_timestamp_from_json(mip_jr_t *jr, size_t pos,
                                             mip_shared_reference_timestamp_t *out) {
    static const char *const keys[] = {"nanoseconds"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mip_jr_object(jr, pos, keys, 1)) {
        return -1;
    }
    found = mip_jr_get(jr, pos, "nanoseconds", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"nanoseconds\"");
    }
    {
        mip_jr_push(jr, "nanoseconds");
        if (mip_jr_u64(jr, vp, &out->nanoseconds)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    return 0;
}

/* ---- mip_shared_reference_time_delta_t */

static int mip_shared_reference_time_delta_read(mip_reader_t *r, mip_shared_reference_time_delta_t *out) {
    mip_rd_push(r, "dt_nanos");
    if (mip_rd_u64(r, &out->dt_nanos)) {
        return -1;
    }
    mip_rd_pop(r);
    return mip_rd_finish(r);
}

static mip_status_t mip_shared_reference_time_delta_write(mip_writer_t *w,
                                                          const mip_shared_reference_time_delta_t *in) {
    mip_status_t st;
    if ((st = mip_wr_u64(w, &in->dt_nanos)) != MIP_OK) {
        return st;
    }
    return MIP_OK;
}

mip_status_t mip_shared_reference_time_delta_encode(const mip_shared_reference_time_delta_t *value,
                                                    uint8_t *buf, size_t cap, size_t *len_out) {
    mip_writer_t w;
    mip_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mip_writer_init(&w, buf, cap);
    st = mip_shared_reference_time_delta_write(&w, value);
    if (st == MIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 8 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mip_shared_reference_time_delta_load(const uint8_t *d, mip_shared_reference_time_delta_t *out) {
    out->dt_nanos = mip_ld_u64(d + 0);
    return 0;
}

/* The general reader: lengths other than 8, bad bool bytes, error details. */
static MIP_NOINLINE mip_status_t mip_shared_reference_time_delta_decode_read(
    const uint8_t *data, size_t len, mip_shared_reference_time_delta_t *out, mip_decode_error_t *err) {
    mip_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mip_shared_reference_time_delta_read(&r, out) ? MIP_ERR_DECODE : MIP_OK;
}

mip_status_t mip_shared_reference_time_delta_decode(const uint8_t *data, size_t len,
                                                    mip_shared_reference_time_delta_t *out,
                                                    mip_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 8 && mip_shared_reference_time_delta_load(data, out) == 0) {
        return MIP_OK;
    }
    return mip_shared_reference_time_delta_decode_read(data, len, out, err);
}

void mip_shared_reference_time_delta_to_json(mip_jw_t *w, const mip_shared_reference_time_delta_t *in) {
    int first = 1;
    mip_jw_raw(w, "{", 1);
    mip_jw_key(w, &first, "dt_nanos");
    mip_jw_u64(w, &in->dt_nanos);
    mip_jw_raw(w, "}", 1);
}

int mip_shared_reference_time_delta_from_json(mip_jr_t *jr, size_t pos,
                                              mip_shared_reference_time_delta_t *out) {
    static const char *const keys[] = {"dt_nanos"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mip_jr_object(jr, pos, keys, 1)) {
        return -1;
    }
    found = mip_jr_get(jr, pos, "dt_nanos", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"dt_nanos\"");
    }
    {
        mip_jr_push(jr, "dt_nanos");
        if (mip_jr_u64(jr, vp, &out->dt_nanos)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    return 0;
}

/* ---- mip_shared_external_timestamp_t */

static int mip_shared_external_timestamp_read(mip_reader_t *r, mip_shared_external_timestamp_t *out) {
    mip_rd_push(r, "nanoseconds");
    if (mip_rd_u64(r, &out->nanoseconds)) {
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

static mip_status_t mip_shared_external_timestamp_write(mip_writer_t *w,
                                                        const mip_shared_external_timestamp_t *in) {
    mip_status_t st;
    if ((st = mip_wr_u64(w, &in->nanoseconds)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_u16(w, &in->valid_flags)) != MIP_OK) {
        return st;
    }
    return MIP_OK;
}

mip_status_t mip_shared_external_timestamp_encode(const mip_shared_external_timestamp_t *value, uint8_t *buf,
                                                  size_t cap, size_t *len_out) {
    mip_writer_t w;
    mip_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mip_writer_init(&w, buf, cap);
    st = mip_shared_external_timestamp_write(&w, value);
    if (st == MIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 10 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mip_shared_external_timestamp_load(const uint8_t *d, mip_shared_external_timestamp_t *out) {
    out->nanoseconds = mip_ld_u64(d + 0);
    out->valid_flags = mip_ld_u16(d + 8);
    return 0;
}

/* The general reader: lengths other than 10, bad bool bytes, error details. */
static MIP_NOINLINE mip_status_t mip_shared_external_timestamp_decode_read(
    const uint8_t *data, size_t len, mip_shared_external_timestamp_t *out, mip_decode_error_t *err) {
    mip_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mip_shared_external_timestamp_read(&r, out) ? MIP_ERR_DECODE : MIP_OK;
}

mip_status_t mip_shared_external_timestamp_decode(const uint8_t *data, size_t len,
                                                  mip_shared_external_timestamp_t *out,
                                                  mip_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 10 && mip_shared_external_timestamp_load(data, out) == 0) {
        return MIP_OK;
    }
    return mip_shared_external_timestamp_decode_read(data, len, out, err);
}

void mip_shared_external_timestamp_to_json(mip_jw_t *w, const mip_shared_external_timestamp_t *in) {
    int first = 1;
    mip_jw_raw(w, "{", 1);
    mip_jw_key(w, &first, "nanoseconds");
    mip_jw_u64(w, &in->nanoseconds);
    mip_jw_key(w, &first, "valid_flags");
    mip_jw_u16(w, &in->valid_flags);
    mip_jw_raw(w, "}", 1);
}

int mip_shared_external_timestamp_from_json(mip_jr_t *jr, size_t pos, mip_shared_external_timestamp_t *out) {
    static const char *const keys[] = {"nanoseconds", "valid_flags"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mip_jr_object(jr, pos, keys, 2)) {
        return -1;
    }
    found = mip_jr_get(jr, pos, "nanoseconds", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"nanoseconds\"");
    }
    {
        mip_jr_push(jr, "nanoseconds");
        if (mip_jr_u64(jr, vp, &out->nanoseconds)) {
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

/* ---- mip_shared_external_time_delta_t */

static int mip_shared_external_time_delta_read(mip_reader_t *r, mip_shared_external_time_delta_t *out) {
    mip_rd_push(r, "dt_nanos");
    if (mip_rd_u64(r, &out->dt_nanos)) {
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

static mip_status_t mip_shared_external_time_delta_write(mip_writer_t *w,
                                                         const mip_shared_external_time_delta_t *in) {
    mip_status_t st;
    if ((st = mip_wr_u64(w, &in->dt_nanos)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_u16(w, &in->valid_flags)) != MIP_OK) {
        return st;
    }
    return MIP_OK;
}

mip_status_t mip_shared_external_time_delta_encode(const mip_shared_external_time_delta_t *value,
                                                   uint8_t *buf, size_t cap, size_t *len_out) {
    mip_writer_t w;
    mip_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mip_writer_init(&w, buf, cap);
    st = mip_shared_external_time_delta_write(&w, value);
    if (st == MIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 10 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mip_shared_external_time_delta_load(const uint8_t *d, mip_shared_external_time_delta_t *out) {
    out->dt_nanos = mip_ld_u64(d + 0);
    out->valid_flags = mip_ld_u16(d + 8);
    return 0;
}

/* The general reader: lengths other than 10, bad bool bytes, error details. */
static MIP_NOINLINE mip_status_t mip_shared_external_time_delta_decode_read(
    const uint8_t *data, size_t len, mip_shared_external_time_delta_t *out, mip_decode_error_t *err) {
    mip_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mip_shared_external_time_delta_read(&r, out) ? MIP_ERR_DECODE : MIP_OK;
}

mip_status_t mip_shared_external_time_delta_decode(const uint8_t *data, size_t len,
                                                   mip_shared_external_time_delta_t *out,
                                                   mip_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 10 && mip_shared_external_time_delta_load(data, out) == 0) {
        return MIP_OK;
    }
    return mip_shared_external_time_delta_decode_read(data, len, out, err);
}

void mip_shared_external_time_delta_to_json(mip_jw_t *w, const mip_shared_external_time_delta_t *in) {
    int first = 1;
    mip_jw_raw(w, "{", 1);
    mip_jw_key(w, &first, "dt_nanos");
    mip_jw_u64(w, &in->dt_nanos);
    mip_jw_key(w, &first, "valid_flags");
    mip_jw_u16(w, &in->valid_flags);
    mip_jw_raw(w, "}", 1);
}

int mip_shared_external_time_delta_from_json(mip_jr_t *jr, size_t pos,
                                             mip_shared_external_time_delta_t *out) {
    static const char *const keys[] = {"dt_nanos", "valid_flags"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mip_jr_object(jr, pos, keys, 2)) {
        return -1;
    }
    found = mip_jr_get(jr, pos, "dt_nanos", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"dt_nanos\"");
    }
    {
        mip_jr_push(jr, "dt_nanos");
        if (mip_jr_u64(jr, vp, &out->dt_nanos)) {
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
