/* Encoders and decoders of System Data Set. Generated from the spec: do not edit. */
#include "mipcodec/sets/system_data.h"
#include "layouts_internal.h"
#include "types_internal.h"

#include <assert.h>
#include <string.h>

/* ---- mip_system_data_built_in_test_t */

static int mip_system_data_built_in_test_read(mip_reader_t *r, mip_system_data_built_in_test_t *out) {
    mip_rd_push(r, "result");
    if (mip_cv7_continuous_bit_read(r, &out->result)) {
        return -1;
    }
    mip_rd_pop(r);
    return mip_rd_finish(r);
}

static mip_status_t mip_system_data_built_in_test_write(mip_writer_t *w,
                                                        const mip_system_data_built_in_test_t *in) {
    mip_status_t st;
    if ((st = mip_cv7_continuous_bit_write(w, &in->result)) != MIP_OK) {
        return st;
    }
    return MIP_OK;
}

mip_status_t mip_system_data_built_in_test_encode(const mip_system_data_built_in_test_t *value, uint8_t *buf,
                                                  size_t cap, size_t *len_out) {
    mip_writer_t w;
    mip_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mip_writer_init(&w, buf, cap);
    st = mip_system_data_built_in_test_write(&w, value);
    if (st == MIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mip_status_t mip_system_data_built_in_test_decode(const uint8_t *data, size_t len,
                                                  mip_system_data_built_in_test_t *out,
                                                  mip_decode_error_t *err) {
    mip_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mip_system_data_built_in_test_read(&r, out) ? MIP_ERR_DECODE : MIP_OK;
}

void mip_system_data_built_in_test_to_json(mip_jw_t *w, const mip_system_data_built_in_test_t *in) {
    int first = 1;
    mip_jw_raw(w, "{", 1);
    mip_jw_key(w, &first, "result");
    mip_cv7_continuous_bit_to_json(w, &in->result);
    mip_jw_raw(w, "}", 1);
}

int mip_system_data_built_in_test_from_json(mip_jr_t *jr, size_t pos, mip_system_data_built_in_test_t *out) {
    static const char *const keys[] = {"result"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mip_jr_object(jr, pos, keys, 1)) {
        return -1;
    }
    found = mip_jr_get(jr, pos, "result", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"result\"");
    }
    {
        mip_jr_push(jr, "result");
        if (mip_cv7_continuous_bit_from_json(jr, vp, &out->result)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    return 0;
}

/* ---- mip_system_data_time_sync_status_t */

static int mip_system_data_time_sync_status_read(mip_reader_t *r, mip_system_data_time_sync_status_t *out) {
    mip_rd_push(r, "time_sync");
    if (mip_rd_bool(r, &out->time_sync)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "last_pps_rcvd");
    if (mip_rd_u8(r, &out->last_pps_rcvd)) {
        return -1;
    }
    mip_rd_pop(r);
    return mip_rd_finish(r);
}

static mip_status_t mip_system_data_time_sync_status_write(mip_writer_t *w,
                                                           const mip_system_data_time_sync_status_t *in) {
    mip_status_t st;
    if ((st = mip_wr_bool(w, &in->time_sync)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_u8(w, &in->last_pps_rcvd)) != MIP_OK) {
        return st;
    }
    return MIP_OK;
}

mip_status_t mip_system_data_time_sync_status_encode(const mip_system_data_time_sync_status_t *value,
                                                     uint8_t *buf, size_t cap, size_t *len_out) {
    mip_writer_t w;
    mip_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mip_writer_init(&w, buf, cap);
    st = mip_system_data_time_sync_status_write(&w, value);
    if (st == MIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 2 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mip_system_data_time_sync_status_load(const uint8_t *d, mip_system_data_time_sync_status_t *out) {
    if (d[0] > 1) {
        return -1;
    }
    out->time_sync = mip_ld_bool(d + 0);
    out->last_pps_rcvd = mip_ld_u8(d + 1);
    return 0;
}

/* The general reader: lengths other than 2, bad bool bytes, error details. */
static MIP_NOINLINE mip_status_t mip_system_data_time_sync_status_decode_read(
    const uint8_t *data, size_t len, mip_system_data_time_sync_status_t *out, mip_decode_error_t *err) {
    mip_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mip_system_data_time_sync_status_read(&r, out) ? MIP_ERR_DECODE : MIP_OK;
}

mip_status_t mip_system_data_time_sync_status_decode(const uint8_t *data, size_t len,
                                                     mip_system_data_time_sync_status_t *out,
                                                     mip_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 2 && mip_system_data_time_sync_status_load(data, out) == 0) {
        return MIP_OK;
    }
    return mip_system_data_time_sync_status_decode_read(data, len, out, err);
}

void mip_system_data_time_sync_status_to_json(mip_jw_t *w, const mip_system_data_time_sync_status_t *in) {
    int first = 1;
    mip_jw_raw(w, "{", 1);
    mip_jw_key(w, &first, "time_sync");
    mip_jw_bool(w, &in->time_sync);
    mip_jw_key(w, &first, "last_pps_rcvd");
    mip_jw_u8(w, &in->last_pps_rcvd);
    mip_jw_raw(w, "}", 1);
}

int mip_system_data_time_sync_status_from_json(mip_jr_t *jr, size_t pos,
                                               mip_system_data_time_sync_status_t *out) {
    static const char *const keys[] = {"time_sync", "last_pps_rcvd"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mip_jr_object(jr, pos, keys, 2)) {
        return -1;
    }
    found = mip_jr_get(jr, pos, "time_sync", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"time_sync\"");
    }
    {
        mip_jr_push(jr, "time_sync");
        if (mip_jr_bool(jr, vp, &out->time_sync)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "last_pps_rcvd", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"last_pps_rcvd\"");
    }
    {
        mip_jr_push(jr, "last_pps_rcvd");
        if (mip_jr_u8(jr, vp, &out->last_pps_rcvd)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    return 0;
}

/* ---- mip_system_data_gpio_state_t */

static int mip_system_data_gpio_state_read(mip_reader_t *r, mip_system_data_gpio_state_t *out) {
    mip_rd_push(r, "states");
    if (mip_rd_u8(r, &out->states)) {
        return -1;
    }
    mip_rd_pop(r);
    return mip_rd_finish(r);
}

static mip_status_t mip_system_data_gpio_state_write(mip_writer_t *w,
                                                     const mip_system_data_gpio_state_t *in) {
    mip_status_t st;
    if ((st = mip_wr_u8(w, &in->states)) != MIP_OK) {
        return st;
    }
    return MIP_OK;
}

mip_status_t mip_system_data_gpio_state_encode(const mip_system_data_gpio_state_t *value, uint8_t *buf,
                                               size_t cap, size_t *len_out) {
    mip_writer_t w;
    mip_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mip_writer_init(&w, buf, cap);
    st = mip_system_data_gpio_state_write(&w, value);
    if (st == MIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 1 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mip_system_data_gpio_state_load(const uint8_t *d, mip_system_data_gpio_state_t *out) {
    out->states = mip_ld_u8(d + 0);
    return 0;
}

/* The general reader: lengths other than 1, bad bool bytes, error details. */
static MIP_NOINLINE mip_status_t mip_system_data_gpio_state_decode_read(const uint8_t *data, size_t len,
                                                                        mip_system_data_gpio_state_t *out,
                                                                        mip_decode_error_t *err) {
    mip_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mip_system_data_gpio_state_read(&r, out) ? MIP_ERR_DECODE : MIP_OK;
}

mip_status_t mip_system_data_gpio_state_decode(const uint8_t *data, size_t len,
                                               mip_system_data_gpio_state_t *out, mip_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 1 && mip_system_data_gpio_state_load(data, out) == 0) {
        return MIP_OK;
    }
    return mip_system_data_gpio_state_decode_read(data, len, out, err);
}

void mip_system_data_gpio_state_to_json(mip_jw_t *w, const mip_system_data_gpio_state_t *in) {
    int first = 1;
    mip_jw_raw(w, "{", 1);
    mip_jw_key(w, &first, "states");
    mip_jw_u8(w, &in->states);
    mip_jw_raw(w, "}", 1);
}

int mip_system_data_gpio_state_from_json(mip_jr_t *jr, size_t pos, mip_system_data_gpio_state_t *out) {
    static const char *const keys[] = {"states"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mip_jr_object(jr, pos, keys, 1)) {
        return -1;
    }
    found = mip_jr_get(jr, pos, "states", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"states\"");
    }
    {
        mip_jr_push(jr, "states");
        if (mip_jr_u8(jr, vp, &out->states)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    return 0;
}
