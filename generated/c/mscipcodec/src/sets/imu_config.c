/* Encoders and decoders of IMU Configuration Messages. Generated from the spec: do not edit. */
#include "mscipcodec/sets/imu_config.h"
#include "layouts_internal.h"
#include "types_internal.h"

#include <assert.h>
#include <string.h>

/* ---- mscip_imu_config_uart_baud_rate_t */

static int mscip_imu_config_uart_baud_rate_read(mscip_reader_t *r, mscip_imu_config_uart_baud_rate_t *out) {
    mscip_rd_push(r, "function");
    if (mscip_rd_u8(r, &out->function)) {
        return -1;
    }
    mscip_rd_pop(r);
    if (r->pos < r->len) {
        out->has_baud_rate = true;
        mscip_rd_push(r, "baud_rate");
        if (mscip_rd_u32(r, &out->baud_rate)) {
            return -1;
        }
        mscip_rd_pop(r);
    }
    return mscip_rd_finish(r);
}

static mscip_status_t mscip_imu_config_uart_baud_rate_write(mscip_writer_t *w,
                                                            const mscip_imu_config_uart_baud_rate_t *in) {
    mscip_status_t st;
    int absent = 0;
    if ((st = mscip_wr_u8(w, &in->function)) != MSCIP_OK) {
        return st;
    }
    if (!in->has_baud_rate) {
        absent = 1;
    } else if (absent) {
        return MSCIP_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = mscip_wr_u32(w, &in->baud_rate)) != MSCIP_OK) {
            return st;
        }
    }
    return MSCIP_OK;
}

mscip_status_t mscip_imu_config_uart_baud_rate_encode(const mscip_imu_config_uart_baud_rate_t *value,
                                                      uint8_t *buf, size_t cap, size_t *len_out) {
    mscip_writer_t w;
    mscip_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mscip_writer_init(&w, buf, cap);
    st = mscip_imu_config_uart_baud_rate_write(&w, value);
    if (st == MSCIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mscip_status_t mscip_imu_config_uart_baud_rate_decode(const uint8_t *data, size_t len,
                                                      mscip_imu_config_uart_baud_rate_t *out,
                                                      mscip_decode_error_t *err) {
    mscip_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mscip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mscip_imu_config_uart_baud_rate_read(&r, out) ? MSCIP_ERR_DECODE : MSCIP_OK;
}

void mscip_imu_config_uart_baud_rate_to_json(mscip_jw_t *w, const mscip_imu_config_uart_baud_rate_t *in) {
    int first = 1;
    mscip_jw_raw(w, "{", 1);
    mscip_jw_key(w, &first, "function");
    mscip_jw_u8(w, &in->function);
    if (in->has_baud_rate) {
        mscip_jw_key(w, &first, "baud_rate");
        mscip_jw_u32(w, &in->baud_rate);
    }
    mscip_jw_raw(w, "}", 1);
}

int mscip_imu_config_uart_baud_rate_from_json(mscip_jr_t *jr, size_t pos,
                                              mscip_imu_config_uart_baud_rate_t *out) {
    static const char *const keys[] = {"function", "baud_rate"};
    size_t vp = 0;
    int found;
    int absent = 0;
    memset(out, 0, sizeof *out);
    if (mscip_jr_object(jr, pos, keys, 2)) {
        return -1;
    }
    found = mscip_jr_get(jr, pos, "function", &vp);
    if (found != 1) {
        return mscip_jr_fail(jr, "missing parameter \"function\"");
    }
    {
        mscip_jr_push(jr, "function");
        if (mscip_jr_u8(jr, vp, &out->function)) {
            return -1;
        }
        mscip_jr_pop(jr);
    }
    found = mscip_jr_get(jr, pos, "baud_rate", &vp);
    out->has_baud_rate = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mscip_jr_fail(jr, "optional parameter \"baud_rate\" given after an absent one");
    } else {
        mscip_jr_push(jr, "baud_rate");
        if (mscip_jr_u32(jr, vp, &out->baud_rate)) {
            return -1;
        }
        mscip_jr_pop(jr);
    }
    return 0;
}

/* ---- mscip_imu_config_uart_baud_rate_response_t */

static int mscip_imu_config_uart_baud_rate_response_read(mscip_reader_t *r,
                                                         mscip_imu_config_uart_baud_rate_response_t *out) {
    mscip_rd_push(r, "baud_rate");
    if (mscip_rd_u32(r, &out->baud_rate)) {
        return -1;
    }
    mscip_rd_pop(r);
    return mscip_rd_finish(r);
}

static mscip_status_t
mscip_imu_config_uart_baud_rate_response_write(mscip_writer_t *w,
                                               const mscip_imu_config_uart_baud_rate_response_t *in) {
    mscip_status_t st;
    if ((st = mscip_wr_u32(w, &in->baud_rate)) != MSCIP_OK) {
        return st;
    }
    return MSCIP_OK;
}

mscip_status_t
mscip_imu_config_uart_baud_rate_response_encode(const mscip_imu_config_uart_baud_rate_response_t *value,
                                                uint8_t *buf, size_t cap, size_t *len_out) {
    mscip_writer_t w;
    mscip_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mscip_writer_init(&w, buf, cap);
    st = mscip_imu_config_uart_baud_rate_response_write(&w, value);
    if (st == MSCIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 4 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mscip_imu_config_uart_baud_rate_response_load(const uint8_t *d,
                                                         mscip_imu_config_uart_baud_rate_response_t *out) {
    out->baud_rate = mscip_ld_u32(d + 0);
    return 0;
}

/* The general reader: lengths other than 4, bad bool bytes, error details. */
static MSCIP_NOINLINE mscip_status_t mscip_imu_config_uart_baud_rate_response_decode_read(
    const uint8_t *data, size_t len, mscip_imu_config_uart_baud_rate_response_t *out,
    mscip_decode_error_t *err) {
    mscip_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mscip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mscip_imu_config_uart_baud_rate_response_read(&r, out) ? MSCIP_ERR_DECODE : MSCIP_OK;
}

mscip_status_t
mscip_imu_config_uart_baud_rate_response_decode(const uint8_t *data, size_t len,
                                                mscip_imu_config_uart_baud_rate_response_t *out,
                                                mscip_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 4 && mscip_imu_config_uart_baud_rate_response_load(data, out) == 0) {
        return MSCIP_OK;
    }
    return mscip_imu_config_uart_baud_rate_response_decode_read(data, len, out, err);
}

void mscip_imu_config_uart_baud_rate_response_to_json(mscip_jw_t *w,
                                                      const mscip_imu_config_uart_baud_rate_response_t *in) {
    int first = 1;
    mscip_jw_raw(w, "{", 1);
    mscip_jw_key(w, &first, "baud_rate");
    mscip_jw_u32(w, &in->baud_rate);
    mscip_jw_raw(w, "}", 1);
}

int mscip_imu_config_uart_baud_rate_response_from_json(mscip_jr_t *jr, size_t pos,
                                                       mscip_imu_config_uart_baud_rate_response_t *out) {
    static const char *const keys[] = {"baud_rate"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mscip_jr_object(jr, pos, keys, 1)) {
        return -1;
    }
    found = mscip_jr_get(jr, pos, "baud_rate", &vp);
    if (found != 1) {
        return mscip_jr_fail(jr, "missing parameter \"baud_rate\"");
    }
    {
        mscip_jr_push(jr, "baud_rate");
        if (mscip_jr_u32(jr, vp, &out->baud_rate)) {
            return -1;
        }
        mscip_jr_pop(jr);
    }
    return 0;
}

/* ---- mscip_imu_config_filter_t */

static int mscip_imu_config_filter_read(mscip_reader_t *r, mscip_imu_config_filter_t *out) {
    mscip_rd_push(r, "function");
    if (mscip_rd_u8(r, &out->function)) {
        return -1;
    }
    mscip_rd_pop(r);
    if (r->pos < r->len) {
        out->has_bandwidth = true;
        mscip_rd_push(r, "bandwidth");
        if (mscip_rd_u8(r, &out->bandwidth)) {
            return -1;
        }
        mscip_rd_pop(r);
    }
    return mscip_rd_finish(r);
}

static mscip_status_t mscip_imu_config_filter_write(mscip_writer_t *w, const mscip_imu_config_filter_t *in) {
    mscip_status_t st;
    int absent = 0;
    if ((st = mscip_wr_u8(w, &in->function)) != MSCIP_OK) {
        return st;
    }
    if (!in->has_bandwidth) {
        absent = 1;
    } else if (absent) {
        return MSCIP_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = mscip_wr_u8(w, &in->bandwidth)) != MSCIP_OK) {
            return st;
        }
    }
    return MSCIP_OK;
}

mscip_status_t mscip_imu_config_filter_encode(const mscip_imu_config_filter_t *value, uint8_t *buf,
                                              size_t cap, size_t *len_out) {
    mscip_writer_t w;
    mscip_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mscip_writer_init(&w, buf, cap);
    st = mscip_imu_config_filter_write(&w, value);
    if (st == MSCIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mscip_status_t mscip_imu_config_filter_decode(const uint8_t *data, size_t len, mscip_imu_config_filter_t *out,
                                              mscip_decode_error_t *err) {
    mscip_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mscip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mscip_imu_config_filter_read(&r, out) ? MSCIP_ERR_DECODE : MSCIP_OK;
}

void mscip_imu_config_filter_to_json(mscip_jw_t *w, const mscip_imu_config_filter_t *in) {
    int first = 1;
    mscip_jw_raw(w, "{", 1);
    mscip_jw_key(w, &first, "function");
    mscip_jw_u8(w, &in->function);
    if (in->has_bandwidth) {
        mscip_jw_key(w, &first, "bandwidth");
        mscip_jw_u8(w, &in->bandwidth);
    }
    mscip_jw_raw(w, "}", 1);
}

int mscip_imu_config_filter_from_json(mscip_jr_t *jr, size_t pos, mscip_imu_config_filter_t *out) {
    static const char *const keys[] = {"function", "bandwidth"};
    size_t vp = 0;
    int found;
    int absent = 0;
    memset(out, 0, sizeof *out);
    if (mscip_jr_object(jr, pos, keys, 2)) {
        return -1;
    }
    found = mscip_jr_get(jr, pos, "function", &vp);
    if (found != 1) {
        return mscip_jr_fail(jr, "missing parameter \"function\"");
    }
    {
        mscip_jr_push(jr, "function");
        if (mscip_jr_u8(jr, vp, &out->function)) {
            return -1;
        }
        mscip_jr_pop(jr);
    }
    found = mscip_jr_get(jr, pos, "bandwidth", &vp);
    out->has_bandwidth = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mscip_jr_fail(jr, "optional parameter \"bandwidth\" given after an absent one");
    } else {
        mscip_jr_push(jr, "bandwidth");
        if (mscip_jr_u8(jr, vp, &out->bandwidth)) {
            return -1;
        }
        mscip_jr_pop(jr);
    }
    return 0;
}

/* ---- mscip_imu_config_filter_response_t */

static int mscip_imu_config_filter_response_read(mscip_reader_t *r, mscip_imu_config_filter_response_t *out) {
    mscip_rd_push(r, "bandwidth");
    if (mscip_rd_u8(r, &out->bandwidth)) {
        return -1;
    }
    mscip_rd_pop(r);
    return mscip_rd_finish(r);
}

static mscip_status_t mscip_imu_config_filter_response_write(mscip_writer_t *w,
                                                             const mscip_imu_config_filter_response_t *in) {
    mscip_status_t st;
    if ((st = mscip_wr_u8(w, &in->bandwidth)) != MSCIP_OK) {
        return st;
    }
    return MSCIP_OK;
}

mscip_status_t mscip_imu_config_filter_response_encode(const mscip_imu_config_filter_response_t *value,
                                                       uint8_t *buf, size_t cap, size_t *len_out) {
    mscip_writer_t w;
    mscip_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mscip_writer_init(&w, buf, cap);
    st = mscip_imu_config_filter_response_write(&w, value);
    if (st == MSCIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 1 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mscip_imu_config_filter_response_load(const uint8_t *d, mscip_imu_config_filter_response_t *out) {
    out->bandwidth = mscip_ld_u8(d + 0);
    return 0;
}

/* The general reader: lengths other than 1, bad bool bytes, error details. */
static MSCIP_NOINLINE mscip_status_t mscip_imu_config_filter_response_decode_read(
    const uint8_t *data, size_t len, mscip_imu_config_filter_response_t *out, mscip_decode_error_t *err) {
    mscip_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mscip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mscip_imu_config_filter_response_read(&r, out) ? MSCIP_ERR_DECODE : MSCIP_OK;
}

mscip_status_t mscip_imu_config_filter_response_decode(const uint8_t *data, size_t len,
                                                       mscip_imu_config_filter_response_t *out,
                                                       mscip_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 1 && mscip_imu_config_filter_response_load(data, out) == 0) {
        return MSCIP_OK;
    }
    return mscip_imu_config_filter_response_decode_read(data, len, out, err);
}

void mscip_imu_config_filter_response_to_json(mscip_jw_t *w, const mscip_imu_config_filter_response_t *in) {
    int first = 1;
    mscip_jw_raw(w, "{", 1);
    mscip_jw_key(w, &first, "bandwidth");
    mscip_jw_u8(w, &in->bandwidth);
    mscip_jw_raw(w, "}", 1);
}

int mscip_imu_config_filter_response_from_json(mscip_jr_t *jr, size_t pos,
                                               mscip_imu_config_filter_response_t *out) {
    static const char *const keys[] = {"bandwidth"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mscip_jr_object(jr, pos, keys, 1)) {
        return -1;
    }
    found = mscip_jr_get(jr, pos, "bandwidth", &vp);
    if (found != 1) {
        return mscip_jr_fail(jr, "missing parameter \"bandwidth\"");
    }
    {
        mscip_jr_push(jr, "bandwidth");
        if (mscip_jr_u8(jr, vp, &out->bandwidth)) {
            return -1;
        }
        mscip_jr_pop(jr);
    }
    return 0;
}

/* ---- mscip_imu_config_sample_rate_t */

static int mscip_imu_config_sample_rate_read(mscip_reader_t *r, mscip_imu_config_sample_rate_t *out) {
    mscip_rd_push(r, "function");
    if (mscip_rd_u8(r, &out->function)) {
        return -1;
    }
    mscip_rd_pop(r);
    if (r->pos < r->len) {
        out->has_decimation = true;
        mscip_rd_push(r, "decimation");
        if (mscip_rd_u16(r, &out->decimation)) {
            return -1;
        }
        mscip_rd_pop(r);
    }
    return mscip_rd_finish(r);
}

static mscip_status_t mscip_imu_config_sample_rate_write(mscip_writer_t *w,
                                                         const mscip_imu_config_sample_rate_t *in) {
    mscip_status_t st;
    int absent = 0;
    if ((st = mscip_wr_u8(w, &in->function)) != MSCIP_OK) {
        return st;
    }
    if (!in->has_decimation) {
        absent = 1;
    } else if (absent) {
        return MSCIP_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = mscip_wr_u16(w, &in->decimation)) != MSCIP_OK) {
            return st;
        }
    }
    return MSCIP_OK;
}

mscip_status_t mscip_imu_config_sample_rate_encode(const mscip_imu_config_sample_rate_t *value, uint8_t *buf,
                                                   size_t cap, size_t *len_out) {
    mscip_writer_t w;
    mscip_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mscip_writer_init(&w, buf, cap);
    st = mscip_imu_config_sample_rate_write(&w, value);
    if (st == MSCIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mscip_status_t mscip_imu_config_sample_rate_decode(const uint8_t *data, size_t len,
                                                   mscip_imu_config_sample_rate_t *out,
                                                   mscip_decode_error_t *err) {
    mscip_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mscip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mscip_imu_config_sample_rate_read(&r, out) ? MSCIP_ERR_DECODE : MSCIP_OK;
}

void mscip_imu_config_sample_rate_to_json(mscip_jw_t *w, const mscip_imu_config_sample_rate_t *in) {
    int first = 1;
    mscip_jw_raw(w, "{", 1);
    mscip_jw_key(w, &first, "function");
    mscip_jw_u8(w, &in->function);
    if (in->has_decimation) {
        mscip_jw_key(w, &first, "decimation");
        mscip_jw_u16(w, &in->decimation);
    }
    mscip_jw_raw(w, "}", 1);
}

int mscip_imu_config_sample_rate_from_json(mscip_jr_t *jr, size_t pos, mscip_imu_config_sample_rate_t *out) {
    static const char *const keys[] = {"function", "decimation"};
    size_t vp = 0;
    int found;
    int absent = 0;
    memset(out, 0, sizeof *out);
    if (mscip_jr_object(jr, pos, keys, 2)) {
        return -1;
    }
    found = mscip_jr_get(jr, pos, "function", &vp);
    if (found != 1) {
        return mscip_jr_fail(jr, "missing parameter \"function\"");
    }
    {
        mscip_jr_push(jr, "function");
        if (mscip_jr_u8(jr, vp, &out->function)) {
            return -1;
        }
        mscip_jr_pop(jr);
    }
    found = mscip_jr_get(jr, pos, "decimation", &vp);
    out->has_decimation = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mscip_jr_fail(jr, "optional parameter \"decimation\" given after an absent one");
    } else {
        mscip_jr_push(jr, "decimation");
        if (mscip_jr_u16(jr, vp, &out->decimation)) {
            return -1;
        }
        mscip_jr_pop(jr);
    }
    return 0;
}

/* ---- mscip_imu_config_sample_rate_response_t */

static int mscip_imu_config_sample_rate_response_read(mscip_reader_t *r,
                                                      mscip_imu_config_sample_rate_response_t *out) {
    mscip_rd_push(r, "decimation");
    if (mscip_rd_u16(r, &out->decimation)) {
        return -1;
    }
    mscip_rd_pop(r);
    return mscip_rd_finish(r);
}

static mscip_status_t
mscip_imu_config_sample_rate_response_write(mscip_writer_t *w,
                                            const mscip_imu_config_sample_rate_response_t *in) {
    mscip_status_t st;
    if ((st = mscip_wr_u16(w, &in->decimation)) != MSCIP_OK) {
        return st;
    }
    return MSCIP_OK;
}

mscip_status_t
mscip_imu_config_sample_rate_response_encode(const mscip_imu_config_sample_rate_response_t *value,
                                             uint8_t *buf, size_t cap, size_t *len_out) {
    mscip_writer_t w;
    mscip_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mscip_writer_init(&w, buf, cap);
    st = mscip_imu_config_sample_rate_response_write(&w, value);
    if (st == MSCIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 2 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mscip_imu_config_sample_rate_response_load(const uint8_t *d,
                                                      mscip_imu_config_sample_rate_response_t *out) {
    out->decimation = mscip_ld_u16(d + 0);
    return 0;
}

/* The general reader: lengths other than 2, bad bool bytes, error details. */
static MSCIP_NOINLINE mscip_status_t mscip_imu_config_sample_rate_response_decode_read(
    const uint8_t *data, size_t len, mscip_imu_config_sample_rate_response_t *out,
    mscip_decode_error_t *err) {
    mscip_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mscip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mscip_imu_config_sample_rate_response_read(&r, out) ? MSCIP_ERR_DECODE : MSCIP_OK;
}

mscip_status_t mscip_imu_config_sample_rate_response_decode(const uint8_t *data, size_t len,
                                                            mscip_imu_config_sample_rate_response_t *out,
                                                            mscip_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 2 && mscip_imu_config_sample_rate_response_load(data, out) == 0) {
        return MSCIP_OK;
    }
    return mscip_imu_config_sample_rate_response_decode_read(data, len, out, err);
}

void mscip_imu_config_sample_rate_response_to_json(mscip_jw_t *w,
                                                   const mscip_imu_config_sample_rate_response_t *in) {
    int first = 1;
    mscip_jw_raw(w, "{", 1);
    mscip_jw_key(w, &first, "decimation");
    mscip_jw_u16(w, &in->decimation);
    mscip_jw_raw(w, "}", 1);
}

int mscip_imu_config_sample_rate_response_from_json(mscip_jr_t *jr, size_t pos,
                                                    mscip_imu_config_sample_rate_response_t *out) {
    static const char *const keys[] = {"decimation"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mscip_jr_object(jr, pos, keys, 1)) {
        return -1;
    }
    found = mscip_jr_get(jr, pos, "decimation", &vp);
    if (found != 1) {
        return mscip_jr_fail(jr, "missing parameter \"decimation\"");
    }
    {
        mscip_jr_push(jr, "decimation");
        if (mscip_jr_u16(jr, vp, &out->decimation)) {
            return -1;
        }
        mscip_jr_pop(jr);
    }
    return 0;
}

/* ---- mscip_imu_config_select_sensors_t */

static int mscip_imu_config_select_sensors_read(mscip_reader_t *r, mscip_imu_config_select_sensors_t *out) {
    size_t i;
    size_t n;
    mscip_rd_push(r, "function");
    if (mscip_rd_u8(r, &out->function)) {
        return -1;
    }
    mscip_rd_pop(r);
    if (r->pos < r->len) {
        out->has_reserved = true;
        mscip_rd_push(r, "reserved");
        if (mscip_rd_u8(r, &out->reserved)) {
            return -1;
        }
        mscip_rd_pop(r);
    }
    if (r->pos < r->len) {
        out->has_sensors = true;
        mscip_rd_push(r, "sensors");
        if (mscip_rd_remaining(r, 1, 251, &n)) {
            return -1;
        }
        for (i = 0; i < n; i++) {
            mscip_rd_index(r, i);
            if (mscip_rd_u8(r, &out->sensors[i])) {
                return -1;
            }
        }
        out->sensors_count = n;
        mscip_rd_pop(r);
    }
    return mscip_rd_finish(r);
}

static mscip_status_t mscip_imu_config_select_sensors_write(mscip_writer_t *w,
                                                            const mscip_imu_config_select_sensors_t *in) {
    mscip_status_t st;
    size_t i;
    int absent = 0;
    if ((st = mscip_wr_u8(w, &in->function)) != MSCIP_OK) {
        return st;
    }
    if (!in->has_reserved) {
        absent = 1;
    } else if (absent) {
        return MSCIP_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = mscip_wr_u8(w, &in->reserved)) != MSCIP_OK) {
            return st;
        }
    }
    if (!in->has_sensors) {
        absent = 1;
    } else if (absent) {
        return MSCIP_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if (in->sensors_count > 251) {
            return MSCIP_ERR_INVALID;
        }
        for (i = 0; i < (size_t)in->sensors_count; i++) {
            if ((st = mscip_wr_u8(w, &in->sensors[i])) != MSCIP_OK) {
                return st;
            }
        }
    }
    return MSCIP_OK;
}

mscip_status_t mscip_imu_config_select_sensors_encode(const mscip_imu_config_select_sensors_t *value,
                                                      uint8_t *buf, size_t cap, size_t *len_out) {
    mscip_writer_t w;
    mscip_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mscip_writer_init(&w, buf, cap);
    st = mscip_imu_config_select_sensors_write(&w, value);
    if (st == MSCIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mscip_status_t mscip_imu_config_select_sensors_decode(const uint8_t *data, size_t len,
                                                      mscip_imu_config_select_sensors_t *out,
                                                      mscip_decode_error_t *err) {
    mscip_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mscip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mscip_imu_config_select_sensors_read(&r, out) ? MSCIP_ERR_DECODE : MSCIP_OK;
}

void mscip_imu_config_select_sensors_to_json(mscip_jw_t *w, const mscip_imu_config_select_sensors_t *in) {
    int first = 1;
    size_t i;
    mscip_jw_raw(w, "{", 1);
    mscip_jw_key(w, &first, "function");
    mscip_jw_u8(w, &in->function);
    if (in->has_reserved) {
        mscip_jw_key(w, &first, "reserved");
        mscip_jw_u8(w, &in->reserved);
    }
    if (in->has_sensors) {
        mscip_jw_key(w, &first, "sensors");
        mscip_jw_raw(w, "[", 1);
        for (i = 0; i < (size_t)in->sensors_count && i < 251; i++) {
            mscip_jw_sep(w, i);
            mscip_jw_u8(w, &in->sensors[i]);
        }
        mscip_jw_raw(w, "]", 1);
    }
    mscip_jw_raw(w, "}", 1);
}

int mscip_imu_config_select_sensors_from_json(mscip_jr_t *jr, size_t pos,
                                              mscip_imu_config_select_sensors_t *out) {
    static const char *const keys[] = {"function", "reserved", "sensors"};
    size_t vp = 0;
    int found;
    int absent = 0;
    size_t i;
    size_t it = 0;
    size_t ep = 0;
    memset(out, 0, sizeof *out);
    if (mscip_jr_object(jr, pos, keys, 3)) {
        return -1;
    }
    found = mscip_jr_get(jr, pos, "function", &vp);
    if (found != 1) {
        return mscip_jr_fail(jr, "missing parameter \"function\"");
    }
    {
        mscip_jr_push(jr, "function");
        if (mscip_jr_u8(jr, vp, &out->function)) {
            return -1;
        }
        mscip_jr_pop(jr);
    }
    found = mscip_jr_get(jr, pos, "reserved", &vp);
    out->has_reserved = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mscip_jr_fail(jr, "optional parameter \"reserved\" given after an absent one");
    } else {
        mscip_jr_push(jr, "reserved");
        if (mscip_jr_u8(jr, vp, &out->reserved)) {
            return -1;
        }
        mscip_jr_pop(jr);
    }
    found = mscip_jr_get(jr, pos, "sensors", &vp);
    out->has_sensors = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mscip_jr_fail(jr, "optional parameter \"sensors\" given after an absent one");
    } else {
        mscip_jr_push(jr, "sensors");
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
            if (i >= 251) {
                return mscip_jr_fail(jr, "more than 251 elements");
            }
            mscip_jr_index(jr, i);
            if (mscip_jr_u8(jr, ep, &out->sensors[i])) {
                return -1;
            }
        }
        mscip_jr_index(jr, SIZE_MAX);
        out->sensors_count = i;
        mscip_jr_pop(jr);
    }
    return 0;
}

/* ---- mscip_imu_config_select_sensors_response_t */

static int mscip_imu_config_select_sensors_response_read(mscip_reader_t *r,
                                                         mscip_imu_config_select_sensors_response_t *out) {
    size_t i;
    size_t n;
    mscip_rd_push(r, "sensors");
    if (mscip_rd_remaining(r, 1, 253, &n)) {
        return -1;
    }
    for (i = 0; i < n; i++) {
        mscip_rd_index(r, i);
        if (mscip_rd_u8(r, &out->sensors[i])) {
            return -1;
        }
    }
    out->sensors_count = n;
    mscip_rd_pop(r);
    return mscip_rd_finish(r);
}

static mscip_status_t
mscip_imu_config_select_sensors_response_write(mscip_writer_t *w,
                                               const mscip_imu_config_select_sensors_response_t *in) {
    mscip_status_t st;
    size_t i;
    if (in->sensors_count > 253) {
        return MSCIP_ERR_INVALID;
    }
    for (i = 0; i < (size_t)in->sensors_count; i++) {
        if ((st = mscip_wr_u8(w, &in->sensors[i])) != MSCIP_OK) {
            return st;
        }
    }
    return MSCIP_OK;
}

mscip_status_t
mscip_imu_config_select_sensors_response_encode(const mscip_imu_config_select_sensors_response_t *value,
                                                uint8_t *buf, size_t cap, size_t *len_out) {
    mscip_writer_t w;
    mscip_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mscip_writer_init(&w, buf, cap);
    st = mscip_imu_config_select_sensors_response_write(&w, value);
    if (st == MSCIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mscip_status_t
mscip_imu_config_select_sensors_response_decode(const uint8_t *data, size_t len,
                                                mscip_imu_config_select_sensors_response_t *out,
                                                mscip_decode_error_t *err) {
    mscip_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mscip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mscip_imu_config_select_sensors_response_read(&r, out) ? MSCIP_ERR_DECODE : MSCIP_OK;
}

void mscip_imu_config_select_sensors_response_to_json(mscip_jw_t *w,
                                                      const mscip_imu_config_select_sensors_response_t *in) {
    int first = 1;
    size_t i;
    mscip_jw_raw(w, "{", 1);
    mscip_jw_key(w, &first, "sensors");
    mscip_jw_raw(w, "[", 1);
    for (i = 0; i < (size_t)in->sensors_count && i < 253; i++) {
        mscip_jw_sep(w, i);
        mscip_jw_u8(w, &in->sensors[i]);
    }
    mscip_jw_raw(w, "]", 1);
    mscip_jw_raw(w, "}", 1);
}

int mscip_imu_config_select_sensors_response_from_json(mscip_jr_t *jr, size_t pos,
                                                       mscip_imu_config_select_sensors_response_t *out) {
    static const char *const keys[] = {"sensors"};
    size_t vp = 0;
    int found;
    size_t i;
    size_t it = 0;
    size_t ep = 0;
    memset(out, 0, sizeof *out);
    if (mscip_jr_object(jr, pos, keys, 1)) {
        return -1;
    }
    found = mscip_jr_get(jr, pos, "sensors", &vp);
    if (found != 1) {
        return mscip_jr_fail(jr, "missing parameter \"sensors\"");
    }
    {
        mscip_jr_push(jr, "sensors");
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
            if (i >= 253) {
                return mscip_jr_fail(jr, "more than 253 elements");
            }
            mscip_jr_index(jr, i);
            if (mscip_jr_u8(jr, ep, &out->sensors[i])) {
                return -1;
            }
        }
        mscip_jr_index(jr, SIZE_MAX);
        out->sensors_count = i;
        mscip_jr_pop(jr);
    }
    return 0;
}

/* ---- mscip_imu_config_get_internal_sample_rate_t */

static int mscip_imu_config_get_internal_sample_rate_read(mscip_reader_t *r,
                                                          mscip_imu_config_get_internal_sample_rate_t *out) {
    (void)out;
    return mscip_rd_finish(r);
}

static mscip_status_t
mscip_imu_config_get_internal_sample_rate_write(mscip_writer_t *w,
                                                const mscip_imu_config_get_internal_sample_rate_t *in) {
    (void)w;
    (void)in;
    return MSCIP_OK;
}

mscip_status_t
mscip_imu_config_get_internal_sample_rate_encode(const mscip_imu_config_get_internal_sample_rate_t *value,
                                                 uint8_t *buf, size_t cap, size_t *len_out) {
    mscip_writer_t w;
    mscip_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mscip_writer_init(&w, buf, cap);
    st = mscip_imu_config_get_internal_sample_rate_write(&w, value);
    if (st == MSCIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mscip_status_t
mscip_imu_config_get_internal_sample_rate_decode(const uint8_t *data, size_t len,
                                                 mscip_imu_config_get_internal_sample_rate_t *out,
                                                 mscip_decode_error_t *err) {
    mscip_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mscip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mscip_imu_config_get_internal_sample_rate_read(&r, out) ? MSCIP_ERR_DECODE : MSCIP_OK;
}

void mscip_imu_config_get_internal_sample_rate_to_json(
    mscip_jw_t *w, const mscip_imu_config_get_internal_sample_rate_t *in) {
    int first = 1;
    mscip_jw_raw(w, "{", 1);
    mscip_jw_raw(w, "}", 1);
    (void)in;
    (void)first;
}

int mscip_imu_config_get_internal_sample_rate_from_json(mscip_jr_t *jr, size_t pos,
                                                        mscip_imu_config_get_internal_sample_rate_t *out) {
    memset(out, 0, sizeof *out);
    if (mscip_jr_object(jr, pos, NULL, 0)) {
        return -1;
    }
    return 0;
}

/* ---- mscip_imu_config_internal_sample_rate_t */

static int mscip_imu_config_internal_sample_rate_read(mscip_reader_t *r,
                                                      mscip_imu_config_internal_sample_rate_t *out) {
    mscip_rd_push(r, "rate");
    if (mscip_rd_u16(r, &out->rate)) {
        return -1;
    }
    mscip_rd_pop(r);
    return mscip_rd_finish(r);
}

static mscip_status_t
mscip_imu_config_internal_sample_rate_write(mscip_writer_t *w,
                                            const mscip_imu_config_internal_sample_rate_t *in) {
    mscip_status_t st;
    if ((st = mscip_wr_u16(w, &in->rate)) != MSCIP_OK) {
        return st;
    }
    return MSCIP_OK;
}

mscip_status_t
mscip_imu_config_internal_sample_rate_encode(const mscip_imu_config_internal_sample_rate_t *value,
                                             uint8_t *buf, size_t cap, size_t *len_out) {
    mscip_writer_t w;
    mscip_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mscip_writer_init(&w, buf, cap);
    st = mscip_imu_config_internal_sample_rate_write(&w, value);
    if (st == MSCIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 2 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mscip_imu_config_internal_sample_rate_load(const uint8_t *d,
                                                      mscip_imu_config_internal_sample_rate_t *out) {
    out->rate = mscip_ld_u16(d + 0);
    return 0;
}

/* The general reader: lengths other than 2, bad bool bytes, error details. */
static MSCIP_NOINLINE mscip_status_t mscip_imu_config_internal_sample_rate_decode_read(
    const uint8_t *data, size_t len, mscip_imu_config_internal_sample_rate_t *out,
    mscip_decode_error_t *err) {
    mscip_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mscip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mscip_imu_config_internal_sample_rate_read(&r, out) ? MSCIP_ERR_DECODE : MSCIP_OK;
}

mscip_status_t mscip_imu_config_internal_sample_rate_decode(const uint8_t *data, size_t len,
                                                            mscip_imu_config_internal_sample_rate_t *out,
                                                            mscip_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 2 && mscip_imu_config_internal_sample_rate_load(data, out) == 0) {
        return MSCIP_OK;
    }
    return mscip_imu_config_internal_sample_rate_decode_read(data, len, out, err);
}

void mscip_imu_config_internal_sample_rate_to_json(mscip_jw_t *w,
                                                   const mscip_imu_config_internal_sample_rate_t *in) {
    int first = 1;
    mscip_jw_raw(w, "{", 1);
    mscip_jw_key(w, &first, "rate");
    mscip_jw_u16(w, &in->rate);
    mscip_jw_raw(w, "}", 1);
}

int mscip_imu_config_internal_sample_rate_from_json(mscip_jr_t *jr, size_t pos,
                                                    mscip_imu_config_internal_sample_rate_t *out) {
    static const char *const keys[] = {"rate"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mscip_jr_object(jr, pos, keys, 1)) {
        return -1;
    }
    found = mscip_jr_get(jr, pos, "rate", &vp);
    if (found != 1) {
        return mscip_jr_fail(jr, "missing parameter \"rate\"");
    }
    {
        mscip_jr_push(jr, "rate");
        if (mscip_jr_u16(jr, vp, &out->rate)) {
            return -1;
        }
        mscip_jr_pop(jr);
    }
    return 0;
}

/* ---- mscip_imu_config_accel_range_t */

static int mscip_imu_config_accel_range_read(mscip_reader_t *r, mscip_imu_config_accel_range_t *out) {
    mscip_rd_push(r, "function");
    if (mscip_rd_u8(r, &out->function)) {
        return -1;
    }
    mscip_rd_pop(r);
    if (r->pos < r->len) {
        out->has_range = true;
        mscip_rd_push(r, "range");
        if (mscip_rd_u8(r, &out->range)) {
            return -1;
        }
        mscip_rd_pop(r);
    }
    return mscip_rd_finish(r);
}

static mscip_status_t mscip_imu_config_accel_range_write(mscip_writer_t *w,
                                                         const mscip_imu_config_accel_range_t *in) {
    mscip_status_t st;
    int absent = 0;
    if ((st = mscip_wr_u8(w, &in->function)) != MSCIP_OK) {
        return st;
    }
    if (!in->has_range) {
        absent = 1;
    } else if (absent) {
        return MSCIP_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = mscip_wr_u8(w, &in->range)) != MSCIP_OK) {
            return st;
        }
    }
    return MSCIP_OK;
}

mscip_status_t mscip_imu_config_accel_range_encode(const mscip_imu_config_accel_range_t *value, uint8_t *buf,
                                                   size_t cap, size_t *len_out) {
    mscip_writer_t w;
    mscip_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mscip_writer_init(&w, buf, cap);
    st = mscip_imu_config_accel_range_write(&w, value);
    if (st == MSCIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mscip_status_t mscip_imu_config_accel_range_decode(const uint8_t *data, size_t len,
                                                   mscip_imu_config_accel_range_t *out,
                                                   mscip_decode_error_t *err) {
    mscip_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mscip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mscip_imu_config_accel_range_read(&r, out) ? MSCIP_ERR_DECODE : MSCIP_OK;
}

void mscip_imu_config_accel_range_to_json(mscip_jw_t *w, const mscip_imu_config_accel_range_t *in) {
    int first = 1;
    mscip_jw_raw(w, "{", 1);
    mscip_jw_key(w, &first, "function");
    mscip_jw_u8(w, &in->function);
    if (in->has_range) {
        mscip_jw_key(w, &first, "range");
        mscip_jw_u8(w, &in->range);
    }
    mscip_jw_raw(w, "}", 1);
}

int mscip_imu_config_accel_range_from_json(mscip_jr_t *jr, size_t pos, mscip_imu_config_accel_range_t *out) {
    static const char *const keys[] = {"function", "range"};
    size_t vp = 0;
    int found;
    int absent = 0;
    memset(out, 0, sizeof *out);
    if (mscip_jr_object(jr, pos, keys, 2)) {
        return -1;
    }
    found = mscip_jr_get(jr, pos, "function", &vp);
    if (found != 1) {
        return mscip_jr_fail(jr, "missing parameter \"function\"");
    }
    {
        mscip_jr_push(jr, "function");
        if (mscip_jr_u8(jr, vp, &out->function)) {
            return -1;
        }
        mscip_jr_pop(jr);
    }
    found = mscip_jr_get(jr, pos, "range", &vp);
    out->has_range = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mscip_jr_fail(jr, "optional parameter \"range\" given after an absent one");
    } else {
        mscip_jr_push(jr, "range");
        if (mscip_jr_u8(jr, vp, &out->range)) {
            return -1;
        }
        mscip_jr_pop(jr);
    }
    return 0;
}

/* ---- mscip_imu_config_accel_range_response_t */

static int mscip_imu_config_accel_range_response_read(mscip_reader_t *r,
                                                      mscip_imu_config_accel_range_response_t *out) {
    mscip_rd_push(r, "range");
    if (mscip_rd_u8(r, &out->range)) {
        return -1;
    }
    mscip_rd_pop(r);
    return mscip_rd_finish(r);
}

static mscip_status_t
mscip_imu_config_accel_range_response_write(mscip_writer_t *w,
                                            const mscip_imu_config_accel_range_response_t *in) {
    mscip_status_t st;
    if ((st = mscip_wr_u8(w, &in->range)) != MSCIP_OK) {
        return st;
    }
    return MSCIP_OK;
}

mscip_status_t
mscip_imu_config_accel_range_response_encode(const mscip_imu_config_accel_range_response_t *value,
                                             uint8_t *buf, size_t cap, size_t *len_out) {
    mscip_writer_t w;
    mscip_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mscip_writer_init(&w, buf, cap);
    st = mscip_imu_config_accel_range_response_write(&w, value);
    if (st == MSCIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 1 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mscip_imu_config_accel_range_response_load(const uint8_t *d,
                                                      mscip_imu_config_accel_range_response_t *out) {
    out->range = mscip_ld_u8(d + 0);
    return 0;
}

/* The general reader: lengths other than 1, bad bool bytes, error details. */
static MSCIP_NOINLINE mscip_status_t mscip_imu_config_accel_range_response_decode_read(
    const uint8_t *data, size_t len, mscip_imu_config_accel_range_response_t *out,
    mscip_decode_error_t *err) {
    mscip_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mscip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mscip_imu_config_accel_range_response_read(&r, out) ? MSCIP_ERR_DECODE : MSCIP_OK;
}

mscip_status_t mscip_imu_config_accel_range_response_decode(const uint8_t *data, size_t len,
                                                            mscip_imu_config_accel_range_response_t *out,
                                                            mscip_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 1 && mscip_imu_config_accel_range_response_load(data, out) == 0) {
        return MSCIP_OK;
    }
    return mscip_imu_config_accel_range_response_decode_read(data, len, out, err);
}

void mscip_imu_config_accel_range_response_to_json(mscip_jw_t *w,
                                                   const mscip_imu_config_accel_range_response_t *in) {
    int first = 1;
    mscip_jw_raw(w, "{", 1);
    mscip_jw_key(w, &first, "range");
    mscip_jw_u8(w, &in->range);
    mscip_jw_raw(w, "}", 1);
}

int mscip_imu_config_accel_range_response_from_json(mscip_jr_t *jr, size_t pos,
                                                    mscip_imu_config_accel_range_response_t *out) {
    static const char *const keys[] = {"range"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mscip_jr_object(jr, pos, keys, 1)) {
        return -1;
    }
    found = mscip_jr_get(jr, pos, "range", &vp);
    if (found != 1) {
        return mscip_jr_fail(jr, "missing parameter \"range\"");
    }
    {
        mscip_jr_push(jr, "range");
        if (mscip_jr_u8(jr, vp, &out->range)) {
            return -1;
        }
        mscip_jr_pop(jr);
    }
    return 0;
}

/* ---- mscip_imu_config_gyro_range_t */

static int mscip_imu_config_gyro_range_read(mscip_reader_t *r, mscip_imu_config_gyro_range_t *out) {
    mscip_rd_push(r, "function");
    if (mscip_rd_u8(r, &out->function)) {
        return -1;
    }
    mscip_rd_pop(r);
    if (r->pos < r->len) {
        out->has_range = true;
        mscip_rd_push(r, "range");
        if (mscip_rd_u8(r, &out->range)) {
            return -1;
        }
        mscip_rd_pop(r);
    }
    return mscip_rd_finish(r);
}

static mscip_status_t mscip_imu_config_gyro_range_write(mscip_writer_t *w,
                                                        const mscip_imu_config_gyro_range_t *in) {
    mscip_status_t st;
    int absent = 0;
    if ((st = mscip_wr_u8(w, &in->function)) != MSCIP_OK) {
        return st;
    }
    if (!in->has_range) {
        absent = 1;
    } else if (absent) {
        return MSCIP_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = mscip_wr_u8(w, &in->range)) != MSCIP_OK) {
            return st;
        }
    }
    return MSCIP_OK;
}

mscip_status_t mscip_imu_config_gyro_range_encode(const mscip_imu_config_gyro_range_t *value, uint8_t *buf,
                                                  size_t cap, size_t *len_out) {
    mscip_writer_t w;
    mscip_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mscip_writer_init(&w, buf, cap);
    st = mscip_imu_config_gyro_range_write(&w, value);
    if (st == MSCIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mscip_status_t mscip_imu_config_gyro_range_decode(const uint8_t *data, size_t len,
                                                  mscip_imu_config_gyro_range_t *out,
                                                  mscip_decode_error_t *err) {
    mscip_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mscip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mscip_imu_config_gyro_range_read(&r, out) ? MSCIP_ERR_DECODE : MSCIP_OK;
}

void mscip_imu_config_gyro_range_to_json(mscip_jw_t *w, const mscip_imu_config_gyro_range_t *in) {
    int first = 1;
    mscip_jw_raw(w, "{", 1);
    mscip_jw_key(w, &first, "function");
    mscip_jw_u8(w, &in->function);
    if (in->has_range) {
        mscip_jw_key(w, &first, "range");
        mscip_jw_u8(w, &in->range);
    }
    mscip_jw_raw(w, "}", 1);
}

int mscip_imu_config_gyro_range_from_json(mscip_jr_t *jr, size_t pos, mscip_imu_config_gyro_range_t *out) {
    static const char *const keys[] = {"function", "range"};
    size_t vp = 0;
    int found;
    int absent = 0;
    memset(out, 0, sizeof *out);
    if (mscip_jr_object(jr, pos, keys, 2)) {
        return -1;
    }
    found = mscip_jr_get(jr, pos, "function", &vp);
    if (found != 1) {
        return mscip_jr_fail(jr, "missing parameter \"function\"");
    }
    {
        mscip_jr_push(jr, "function");
        if (mscip_jr_u8(jr, vp, &out->function)) {
            return -1;
        }
        mscip_jr_pop(jr);
    }
    found = mscip_jr_get(jr, pos, "range", &vp);
    out->has_range = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mscip_jr_fail(jr, "optional parameter \"range\" given after an absent one");
    } else {
        mscip_jr_push(jr, "range");
        if (mscip_jr_u8(jr, vp, &out->range)) {
            return -1;
        }
        mscip_jr_pop(jr);
    }
    return 0;
}

/* ---- mscip_imu_config_gyro_range_response_t */

static int mscip_imu_config_gyro_range_response_read(mscip_reader_t *r,
                                                     mscip_imu_config_gyro_range_response_t *out) {
    mscip_rd_push(r, "range");
    if (mscip_rd_u8(r, &out->range)) {
        return -1;
    }
    mscip_rd_pop(r);
    return mscip_rd_finish(r);
}

static mscip_status_t
mscip_imu_config_gyro_range_response_write(mscip_writer_t *w,
                                           const mscip_imu_config_gyro_range_response_t *in) {
    mscip_status_t st;
    if ((st = mscip_wr_u8(w, &in->range)) != MSCIP_OK) {
        return st;
    }
    return MSCIP_OK;
}

mscip_status_t
mscip_imu_config_gyro_range_response_encode(const mscip_imu_config_gyro_range_response_t *value, uint8_t *buf,
                                            size_t cap, size_t *len_out) {
    mscip_writer_t w;
    mscip_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mscip_writer_init(&w, buf, cap);
    st = mscip_imu_config_gyro_range_response_write(&w, value);
    if (st == MSCIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 1 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mscip_imu_config_gyro_range_response_load(const uint8_t *d,
                                                     mscip_imu_config_gyro_range_response_t *out) {
    out->range = mscip_ld_u8(d + 0);
    return 0;
}

/* The general reader: lengths other than 1, bad bool bytes, error details. */
static MSCIP_NOINLINE mscip_status_t mscip_imu_config_gyro_range_response_decode_read(
    const uint8_t *data, size_t len, mscip_imu_config_gyro_range_response_t *out, mscip_decode_error_t *err) {
    mscip_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mscip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mscip_imu_config_gyro_range_response_read(&r, out) ? MSCIP_ERR_DECODE : MSCIP_OK;
}

mscip_status_t mscip_imu_config_gyro_range_response_decode(const uint8_t *data, size_t len,
                                                           mscip_imu_config_gyro_range_response_t *out,
                                                           mscip_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 1 && mscip_imu_config_gyro_range_response_load(data, out) == 0) {
        return MSCIP_OK;
    }
    return mscip_imu_config_gyro_range_response_decode_read(data, len, out, err);
}

void mscip_imu_config_gyro_range_response_to_json(mscip_jw_t *w,
                                                  const mscip_imu_config_gyro_range_response_t *in) {
    int first = 1;
    mscip_jw_raw(w, "{", 1);
    mscip_jw_key(w, &first, "range");
    mscip_jw_u8(w, &in->range);
    mscip_jw_raw(w, "}", 1);
}

int mscip_imu_config_gyro_range_response_from_json(mscip_jr_t *jr, size_t pos,
                                                   mscip_imu_config_gyro_range_response_t *out) {
    static const char *const keys[] = {"range"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mscip_jr_object(jr, pos, keys, 1)) {
        return -1;
    }
    found = mscip_jr_get(jr, pos, "range", &vp);
    if (found != 1) {
        return mscip_jr_fail(jr, "missing parameter \"range\"");
    }
    {
        mscip_jr_push(jr, "range");
        if (mscip_jr_u8(jr, vp, &out->range)) {
            return -1;
        }
        mscip_jr_pop(jr);
    }
    return 0;
}

/* ---- mscip_imu_config_config_all_t */

static int mscip_imu_config_config_all_read(mscip_reader_t *r, mscip_imu_config_config_all_t *out) {
    mscip_rd_push(r, "function");
    if (mscip_rd_u8(r, &out->function)) {
        return -1;
    }
    mscip_rd_pop(r);
    return mscip_rd_finish(r);
}

static mscip_status_t mscip_imu_config_config_all_write(mscip_writer_t *w,
                                                        const mscip_imu_config_config_all_t *in) {
    mscip_status_t st;
    if ((st = mscip_wr_u8(w, &in->function)) != MSCIP_OK) {
        return st;
    }
    return MSCIP_OK;
}

mscip_status_t mscip_imu_config_config_all_encode(const mscip_imu_config_config_all_t *value, uint8_t *buf,
                                                  size_t cap, size_t *len_out) {
    mscip_writer_t w;
    mscip_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mscip_writer_init(&w, buf, cap);
    st = mscip_imu_config_config_all_write(&w, value);
    if (st == MSCIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 1 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mscip_imu_config_config_all_load(const uint8_t *d, mscip_imu_config_config_all_t *out) {
    out->function = mscip_ld_u8(d + 0);
    return 0;
}

/* The general reader: lengths other than 1, bad bool bytes, error details. */
static MSCIP_NOINLINE mscip_status_t mscip_imu_config_config_all_decode_read(
    const uint8_t *data, size_t len, mscip_imu_config_config_all_t *out, mscip_decode_error_t *err) {
    mscip_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mscip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mscip_imu_config_config_all_read(&r, out) ? MSCIP_ERR_DECODE : MSCIP_OK;
}

mscip_status_t mscip_imu_config_config_all_decode(const uint8_t *data, size_t len,
                                                  mscip_imu_config_config_all_t *out,
                                                  mscip_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 1 && mscip_imu_config_config_all_load(data, out) == 0) {
        return MSCIP_OK;
    }
    return mscip_imu_config_config_all_decode_read(data, len, out, err);
}

void mscip_imu_config_config_all_to_json(mscip_jw_t *w, const mscip_imu_config_config_all_t *in) {
    int first = 1;
    mscip_jw_raw(w, "{", 1);
    mscip_jw_key(w, &first, "function");
    mscip_jw_u8(w, &in->function);
    mscip_jw_raw(w, "}", 1);
}

int mscip_imu_config_config_all_from_json(mscip_jr_t *jr, size_t pos, mscip_imu_config_config_all_t *out) {
    static const char *const keys[] = {"function"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mscip_jr_object(jr, pos, keys, 1)) {
        return -1;
    }
    found = mscip_jr_get(jr, pos, "function", &vp);
    if (found != 1) {
        return mscip_jr_fail(jr, "missing parameter \"function\"");
    }
    {
        mscip_jr_push(jr, "function");
        if (mscip_jr_u8(jr, vp, &out->function)) {
            return -1;
        }
        mscip_jr_pop(jr);
    }
    return 0;
}

/* ---- mscip_imu_config_data_on_off_t */

static int mscip_imu_config_data_on_off_read(mscip_reader_t *r, mscip_imu_config_data_on_off_t *out) {
    mscip_rd_push(r, "function");
    if (mscip_rd_u8(r, &out->function)) {
        return -1;
    }
    mscip_rd_pop(r);
    if (r->pos < r->len) {
        out->has_control = true;
        mscip_rd_push(r, "control");
        if (mscip_rd_u8(r, &out->control)) {
            return -1;
        }
        mscip_rd_pop(r);
    }
    return mscip_rd_finish(r);
}

static mscip_status_t mscip_imu_config_data_on_off_write(mscip_writer_t *w,
                                                         const mscip_imu_config_data_on_off_t *in) {
    mscip_status_t st;
    int absent = 0;
    if ((st = mscip_wr_u8(w, &in->function)) != MSCIP_OK) {
        return st;
    }
    if (!in->has_control) {
        absent = 1;
    } else if (absent) {
        return MSCIP_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = mscip_wr_u8(w, &in->control)) != MSCIP_OK) {
            return st;
        }
    }
    return MSCIP_OK;
}

mscip_status_t mscip_imu_config_data_on_off_encode(const mscip_imu_config_data_on_off_t *value, uint8_t *buf,
                                                   size_t cap, size_t *len_out) {
    mscip_writer_t w;
    mscip_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mscip_writer_init(&w, buf, cap);
    st = mscip_imu_config_data_on_off_write(&w, value);
    if (st == MSCIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mscip_status_t mscip_imu_config_data_on_off_decode(const uint8_t *data, size_t len,
                                                   mscip_imu_config_data_on_off_t *out,
                                                   mscip_decode_error_t *err) {
    mscip_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mscip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mscip_imu_config_data_on_off_read(&r, out) ? MSCIP_ERR_DECODE : MSCIP_OK;
}

void mscip_imu_config_data_on_off_to_json(mscip_jw_t *w, const mscip_imu_config_data_on_off_t *in) {
    int first = 1;
    mscip_jw_raw(w, "{", 1);
    mscip_jw_key(w, &first, "function");
    mscip_jw_u8(w, &in->function);
    if (in->has_control) {
        mscip_jw_key(w, &first, "control");
        mscip_jw_u8(w, &in->control);
    }
    mscip_jw_raw(w, "}", 1);
}

int mscip_imu_config_data_on_off_from_json(mscip_jr_t *jr, size_t pos, mscip_imu_config_data_on_off_t *out) {
    static const char *const keys[] = {"function", "control"};
    size_t vp = 0;
    int found;
    int absent = 0;
    memset(out, 0, sizeof *out);
    if (mscip_jr_object(jr, pos, keys, 2)) {
        return -1;
    }
    found = mscip_jr_get(jr, pos, "function", &vp);
    if (found != 1) {
        return mscip_jr_fail(jr, "missing parameter \"function\"");
    }
    {
        mscip_jr_push(jr, "function");
        if (mscip_jr_u8(jr, vp, &out->function)) {
            return -1;
        }
        mscip_jr_pop(jr);
    }
    found = mscip_jr_get(jr, pos, "control", &vp);
    out->has_control = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mscip_jr_fail(jr, "optional parameter \"control\" given after an absent one");
    } else {
        mscip_jr_push(jr, "control");
        if (mscip_jr_u8(jr, vp, &out->control)) {
            return -1;
        }
        mscip_jr_pop(jr);
    }
    return 0;
}

/* ---- mscip_imu_config_data_on_off_response_t */

static int mscip_imu_config_data_on_off_response_read(mscip_reader_t *r,
                                                      mscip_imu_config_data_on_off_response_t *out) {
    mscip_rd_push(r, "control");
    if (mscip_rd_u8(r, &out->control)) {
        return -1;
    }
    mscip_rd_pop(r);
    return mscip_rd_finish(r);
}

static mscip_status_t
mscip_imu_config_data_on_off_response_write(mscip_writer_t *w,
                                            const mscip_imu_config_data_on_off_response_t *in) {
    mscip_status_t st;
    if ((st = mscip_wr_u8(w, &in->control)) != MSCIP_OK) {
        return st;
    }
    return MSCIP_OK;
}

mscip_status_t
mscip_imu_config_data_on_off_response_encode(const mscip_imu_config_data_on_off_response_t *value,
                                             uint8_t *buf, size_t cap, size_t *len_out) {
    mscip_writer_t w;
    mscip_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mscip_writer_init(&w, buf, cap);
    st = mscip_imu_config_data_on_off_response_write(&w, value);
    if (st == MSCIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 1 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mscip_imu_config_data_on_off_response_load(const uint8_t *d,
                                                      mscip_imu_config_data_on_off_response_t *out) {
    out->control = mscip_ld_u8(d + 0);
    return 0;
}

/* The general reader: lengths other than 1, bad bool bytes, error details. */
static MSCIP_NOINLINE mscip_status_t mscip_imu_config_data_on_off_response_decode_read(
    const uint8_t *data, size_t len, mscip_imu_config_data_on_off_response_t *out,
    mscip_decode_error_t *err) {
    mscip_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mscip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mscip_imu_config_data_on_off_response_read(&r, out) ? MSCIP_ERR_DECODE : MSCIP_OK;
}

mscip_status_t mscip_imu_config_data_on_off_response_decode(const uint8_t *data, size_t len,
                                                            mscip_imu_config_data_on_off_response_t *out,
                                                            mscip_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 1 && mscip_imu_config_data_on_off_response_load(data, out) == 0) {
        return MSCIP_OK;
    }
    return mscip_imu_config_data_on_off_response_decode_read(data, len, out, err);
}

void mscip_imu_config_data_on_off_response_to_json(mscip_jw_t *w,
                                                   const mscip_imu_config_data_on_off_response_t *in) {
    int first = 1;
    mscip_jw_raw(w, "{", 1);
    mscip_jw_key(w, &first, "control");
    mscip_jw_u8(w, &in->control);
    mscip_jw_raw(w, "}", 1);
}

int mscip_imu_config_data_on_off_response_from_json(mscip_jr_t *jr, size_t pos,
                                                    mscip_imu_config_data_on_off_response_t *out) {
    static const char *const keys[] = {"control"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mscip_jr_object(jr, pos, keys, 1)) {
        return -1;
    }
    found = mscip_jr_get(jr, pos, "control", &vp);
    if (found != 1) {
        return mscip_jr_fail(jr, "missing parameter \"control\"");
    }
    {
        mscip_jr_push(jr, "control");
        if (mscip_jr_u8(jr, vp, &out->control)) {
            return -1;
        }
        mscip_jr_pop(jr);
    }
    return 0;
}

/* ---- mscip_imu_config_xtrig_on_off_t */

static int mscip_imu_config_xtrig_on_off_read(mscip_reader_t *r, mscip_imu_config_xtrig_on_off_t *out) {
    mscip_rd_push(r, "function");
    if (mscip_rd_u8(r, &out->function)) {
        return -1;
    }
    mscip_rd_pop(r);
    if (r->pos < r->len) {
        out->has_control = true;
        mscip_rd_push(r, "control");
        if (mscip_rd_u8(r, &out->control)) {
            return -1;
        }
        mscip_rd_pop(r);
    }
    return mscip_rd_finish(r);
}

static mscip_status_t mscip_imu_config_xtrig_on_off_write(mscip_writer_t *w,
                                                          const mscip_imu_config_xtrig_on_off_t *in) {
    mscip_status_t st;
    int absent = 0;
    if ((st = mscip_wr_u8(w, &in->function)) != MSCIP_OK) {
        return st;
    }
    if (!in->has_control) {
        absent = 1;
    } else if (absent) {
        return MSCIP_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = mscip_wr_u8(w, &in->control)) != MSCIP_OK) {
            return st;
        }
    }
    return MSCIP_OK;
}

mscip_status_t mscip_imu_config_xtrig_on_off_encode(const mscip_imu_config_xtrig_on_off_t *value,
                                                    uint8_t *buf, size_t cap, size_t *len_out) {
    mscip_writer_t w;
    mscip_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mscip_writer_init(&w, buf, cap);
    st = mscip_imu_config_xtrig_on_off_write(&w, value);
    if (st == MSCIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mscip_status_t mscip_imu_config_xtrig_on_off_decode(const uint8_t *data, size_t len,
                                                    mscip_imu_config_xtrig_on_off_t *out,
                                                    mscip_decode_error_t *err) {
    mscip_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mscip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mscip_imu_config_xtrig_on_off_read(&r, out) ? MSCIP_ERR_DECODE : MSCIP_OK;
}

void mscip_imu_config_xtrig_on_off_to_json(mscip_jw_t *w, const mscip_imu_config_xtrig_on_off_t *in) {
    int first = 1;
    mscip_jw_raw(w, "{", 1);
    mscip_jw_key(w, &first, "function");
    mscip_jw_u8(w, &in->function);
    if (in->has_control) {
        mscip_jw_key(w, &first, "control");
        mscip_jw_u8(w, &in->control);
    }
    mscip_jw_raw(w, "}", 1);
}

int mscip_imu_config_xtrig_on_off_from_json(mscip_jr_t *jr, size_t pos,
                                            mscip_imu_config_xtrig_on_off_t *out) {
    static const char *const keys[] = {"function", "control"};
    size_t vp = 0;
    int found;
    int absent = 0;
    memset(out, 0, sizeof *out);
    if (mscip_jr_object(jr, pos, keys, 2)) {
        return -1;
    }
    found = mscip_jr_get(jr, pos, "function", &vp);
    if (found != 1) {
        return mscip_jr_fail(jr, "missing parameter \"function\"");
    }
    {
        mscip_jr_push(jr, "function");
        if (mscip_jr_u8(jr, vp, &out->function)) {
            return -1;
        }
        mscip_jr_pop(jr);
    }
    found = mscip_jr_get(jr, pos, "control", &vp);
    out->has_control = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mscip_jr_fail(jr, "optional parameter \"control\" given after an absent one");
    } else {
        mscip_jr_push(jr, "control");
        if (mscip_jr_u8(jr, vp, &out->control)) {
            return -1;
        }
        mscip_jr_pop(jr);
    }
    return 0;
}

/* ---- mscip_imu_config_xtrig_on_off_response_t */

static int mscip_imu_config_xtrig_on_off_response_read(mscip_reader_t *r,
                                                       mscip_imu_config_xtrig_on_off_response_t *out) {
    mscip_rd_push(r, "control");
    if (mscip_rd_u8(r, &out->control)) {
        return -1;
    }
    mscip_rd_pop(r);
    return mscip_rd_finish(r);
}

static mscip_status_t
mscip_imu_config_xtrig_on_off_response_write(mscip_writer_t *w,
                                             const mscip_imu_config_xtrig_on_off_response_t *in) {
    mscip_status_t st;
    if ((st = mscip_wr_u8(w, &in->control)) != MSCIP_OK) {
        return st;
    }
    return MSCIP_OK;
}

mscip_status_t
mscip_imu_config_xtrig_on_off_response_encode(const mscip_imu_config_xtrig_on_off_response_t *value,
                                              uint8_t *buf, size_t cap, size_t *len_out) {
    mscip_writer_t w;
    mscip_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mscip_writer_init(&w, buf, cap);
    st = mscip_imu_config_xtrig_on_off_response_write(&w, value);
    if (st == MSCIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 1 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mscip_imu_config_xtrig_on_off_response_load(const uint8_t *d,
                                                       mscip_imu_config_xtrig_on_off_response_t *out) {
    out->control = mscip_ld_u8(d + 0);
    return 0;
}

/* The general reader: lengths other than 1, bad bool bytes, error details. */
static MSCIP_NOINLINE mscip_status_t mscip_imu_config_xtrig_on_off_response_decode_read(
    const uint8_t *data, size_t len, mscip_imu_config_xtrig_on_off_response_t *out,
    mscip_decode_error_t *err) {
    mscip_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mscip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mscip_imu_config_xtrig_on_off_response_read(&r, out) ? MSCIP_ERR_DECODE : MSCIP_OK;
}

mscip_status_t mscip_imu_config_xtrig_on_off_response_decode(const uint8_t *data, size_t len,
                                                             mscip_imu_config_xtrig_on_off_response_t *out,
                                                             mscip_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 1 && mscip_imu_config_xtrig_on_off_response_load(data, out) == 0) {
        return MSCIP_OK;
    }
    return mscip_imu_config_xtrig_on_off_response_decode_read(data, len, out, err);
}

void mscip_imu_config_xtrig_on_off_response_to_json(mscip_jw_t *w,
                                                    const mscip_imu_config_xtrig_on_off_response_t *in) {
    int first = 1;
    mscip_jw_raw(w, "{", 1);
    mscip_jw_key(w, &first, "control");
    mscip_jw_u8(w, &in->control);
    mscip_jw_raw(w, "}", 1);
}

int mscip_imu_config_xtrig_on_off_response_from_json(mscip_jr_t *jr, size_t pos,
                                                     mscip_imu_config_xtrig_on_off_response_t *out) {
    static const char *const keys[] = {"control"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mscip_jr_object(jr, pos, keys, 1)) {
        return -1;
    }
    found = mscip_jr_get(jr, pos, "control", &vp);
    if (found != 1) {
        return mscip_jr_fail(jr, "missing parameter \"control\"");
    }
    {
        mscip_jr_push(jr, "control");
        if (mscip_jr_u8(jr, vp, &out->control)) {
            return -1;
        }
        mscip_jr_pop(jr);
    }
    return 0;
}

/* ---- mscip_imu_config_select_sensors_rev_b_t */

static int mscip_imu_config_select_sensors_rev_b_read(mscip_reader_t *r,
                                                      mscip_imu_config_select_sensors_rev_b_t *out) {
    size_t i;
    size_t n;
    mscip_rd_push(r, "function");
    if (mscip_rd_u8(r, &out->function)) {
        return -1;
    }
    mscip_rd_pop(r);
    if (r->pos < r->len) {
        out->has_sensors = true;
        mscip_rd_push(r, "sensors");
        if (mscip_rd_remaining(r, 1, 252, &n)) {
            return -1;
        }
        for (i = 0; i < n; i++) {
            mscip_rd_index(r, i);
            if (mscip_rd_u8(r, &out->sensors[i])) {
                return -1;
            }
        }
        out->sensors_count = n;
        mscip_rd_pop(r);
    }
    return mscip_rd_finish(r);
}

static mscip_status_t
mscip_imu_config_select_sensors_rev_b_write(mscip_writer_t *w,
                                            const mscip_imu_config_select_sensors_rev_b_t *in) {
    mscip_status_t st;
    size_t i;
    int absent = 0;
    if ((st = mscip_wr_u8(w, &in->function)) != MSCIP_OK) {
        return st;
    }
    if (!in->has_sensors) {
        absent = 1;
    } else if (absent) {
        return MSCIP_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if (in->sensors_count > 252) {
            return MSCIP_ERR_INVALID;
        }
        for (i = 0; i < (size_t)in->sensors_count; i++) {
            if ((st = mscip_wr_u8(w, &in->sensors[i])) != MSCIP_OK) {
                return st;
            }
        }
    }
    return MSCIP_OK;
}

mscip_status_t
mscip_imu_config_select_sensors_rev_b_encode(const mscip_imu_config_select_sensors_rev_b_t *value,
                                             uint8_t *buf, size_t cap, size_t *len_out) {
    mscip_writer_t w;
    mscip_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mscip_writer_init(&w, buf, cap);
    st = mscip_imu_config_select_sensors_rev_b_write(&w, value);
    if (st == MSCIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mscip_status_t mscip_imu_config_select_sensors_rev_b_decode(const uint8_t *data, size_t len,
                                                            mscip_imu_config_select_sensors_rev_b_t *out,
                                                            mscip_decode_error_t *err) {
    mscip_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mscip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mscip_imu_config_select_sensors_rev_b_read(&r, out) ? MSCIP_ERR_DECODE : MSCIP_OK;
}

void mscip_imu_config_select_sensors_rev_b_to_json(mscip_jw_t *w,
                                                   const mscip_imu_config_select_sensors_rev_b_t *in) {
    int first = 1;
    size_t i;
    mscip_jw_raw(w, "{", 1);
    mscip_jw_key(w, &first, "function");
    mscip_jw_u8(w, &in->function);
    if (in->has_sensors) {
        mscip_jw_key(w, &first, "sensors");
        mscip_jw_raw(w, "[", 1);
        for (i = 0; i < (size_t)in->sensors_count && i < 252; i++) {
            mscip_jw_sep(w, i);
            mscip_jw_u8(w, &in->sensors[i]);
        }
        mscip_jw_raw(w, "]", 1);
    }
    mscip_jw_raw(w, "}", 1);
}

int mscip_imu_config_select_sensors_rev_b_from_json(mscip_jr_t *jr, size_t pos,
                                                    mscip_imu_config_select_sensors_rev_b_t *out) {
    static const char *const keys[] = {"function", "sensors"};
    size_t vp = 0;
    int found;
    int absent = 0;
    size_t i;
    size_t it = 0;
    size_t ep = 0;
    memset(out, 0, sizeof *out);
    if (mscip_jr_object(jr, pos, keys, 2)) {
        return -1;
    }
    found = mscip_jr_get(jr, pos, "function", &vp);
    if (found != 1) {
        return mscip_jr_fail(jr, "missing parameter \"function\"");
    }
    {
        mscip_jr_push(jr, "function");
        if (mscip_jr_u8(jr, vp, &out->function)) {
            return -1;
        }
        mscip_jr_pop(jr);
    }
    found = mscip_jr_get(jr, pos, "sensors", &vp);
    out->has_sensors = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mscip_jr_fail(jr, "optional parameter \"sensors\" given after an absent one");
    } else {
        mscip_jr_push(jr, "sensors");
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
            if (i >= 252) {
                return mscip_jr_fail(jr, "more than 252 elements");
            }
            mscip_jr_index(jr, i);
            if (mscip_jr_u8(jr, ep, &out->sensors[i])) {
                return -1;
            }
        }
        mscip_jr_index(jr, SIZE_MAX);
        out->sensors_count = i;
        mscip_jr_pop(jr);
    }
    return 0;
}

/* ---- mscip_imu_config_select_sensors_rev_b_response_t */

static int
mscip_imu_config_select_sensors_rev_b_response_read(mscip_reader_t *r,
                                                    mscip_imu_config_select_sensors_rev_b_response_t *out) {
    size_t i;
    size_t n;
    mscip_rd_push(r, "sensors");
    if (mscip_rd_remaining(r, 1, 253, &n)) {
        return -1;
    }
    for (i = 0; i < n; i++) {
        mscip_rd_index(r, i);
        if (mscip_rd_u8(r, &out->sensors[i])) {
            return -1;
        }
    }
    out->sensors_count = n;
    mscip_rd_pop(r);
    return mscip_rd_finish(r);
}

static mscip_status_t mscip_imu_config_select_sensors_rev_b_response_write(
    mscip_writer_t *w, const mscip_imu_config_select_sensors_rev_b_response_t *in) {
    mscip_status_t st;
    size_t i;
    if (in->sensors_count > 253) {
        return MSCIP_ERR_INVALID;
    }
    for (i = 0; i < (size_t)in->sensors_count; i++) {
        if ((st = mscip_wr_u8(w, &in->sensors[i])) != MSCIP_OK) {
            return st;
        }
    }
    return MSCIP_OK;
}

mscip_status_t mscip_imu_config_select_sensors_rev_b_response_encode(
    const mscip_imu_config_select_sensors_rev_b_response_t *value, uint8_t *buf, size_t cap,
    size_t *len_out) {
    mscip_writer_t w;
    mscip_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mscip_writer_init(&w, buf, cap);
    st = mscip_imu_config_select_sensors_rev_b_response_write(&w, value);
    if (st == MSCIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mscip_status_t
mscip_imu_config_select_sensors_rev_b_response_decode(const uint8_t *data, size_t len,
                                                      mscip_imu_config_select_sensors_rev_b_response_t *out,
                                                      mscip_decode_error_t *err) {
    mscip_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mscip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mscip_imu_config_select_sensors_rev_b_response_read(&r, out) ? MSCIP_ERR_DECODE : MSCIP_OK;
}

void mscip_imu_config_select_sensors_rev_b_response_to_json(
    mscip_jw_t *w, const mscip_imu_config_select_sensors_rev_b_response_t *in) {
    int first = 1;
    size_t i;
    mscip_jw_raw(w, "{", 1);
    mscip_jw_key(w, &first, "sensors");
    mscip_jw_raw(w, "[", 1);
    for (i = 0; i < (size_t)in->sensors_count && i < 253; i++) {
        mscip_jw_sep(w, i);
        mscip_jw_u8(w, &in->sensors[i]);
    }
    mscip_jw_raw(w, "]", 1);
    mscip_jw_raw(w, "}", 1);
}

int mscip_imu_config_select_sensors_rev_b_response_from_json(
    mscip_jr_t *jr, size_t pos, mscip_imu_config_select_sensors_rev_b_response_t *out) {
    static const char *const keys[] = {"sensors"};
    size_t vp = 0;
    int found;
    size_t i;
    size_t it = 0;
    size_t ep = 0;
    memset(out, 0, sizeof *out);
    if (mscip_jr_object(jr, pos, keys, 1)) {
        return -1;
    }
    found = mscip_jr_get(jr, pos, "sensors", &vp);
    if (found != 1) {
        return mscip_jr_fail(jr, "missing parameter \"sensors\"");
    }
    {
        mscip_jr_push(jr, "sensors");
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
            if (i >= 253) {
                return mscip_jr_fail(jr, "more than 253 elements");
            }
            mscip_jr_index(jr, i);
            if (mscip_jr_u8(jr, ep, &out->sensors[i])) {
                return -1;
            }
        }
        mscip_jr_index(jr, SIZE_MAX);
        out->sensors_count = i;
        mscip_jr_pop(jr);
    }
    return 0;
}

/* ---- mscip_imu_config_aux_accel_range_t */

static int mscip_imu_config_aux_accel_range_read(mscip_reader_t *r, mscip_imu_config_aux_accel_range_t *out) {
    mscip_rd_push(r, "function");
    if (mscip_rd_u8(r, &out->function)) {
        return -1;
    }
    mscip_rd_pop(r);
    if (r->pos < r->len) {
        out->has_range = true;
        mscip_rd_push(r, "range");
        if (mscip_rd_u8(r, &out->range)) {
            return -1;
        }
        mscip_rd_pop(r);
    }
    return mscip_rd_finish(r);
}

static mscip_status_t mscip_imu_config_aux_accel_range_write(mscip_writer_t *w,
                                                             const mscip_imu_config_aux_accel_range_t *in) {
    mscip_status_t st;
    int absent = 0;
    if ((st = mscip_wr_u8(w, &in->function)) != MSCIP_OK) {
        return st;
    }
    if (!in->has_range) {
        absent = 1;
    } else if (absent) {
        return MSCIP_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = mscip_wr_u8(w, &in->range)) != MSCIP_OK) {
            return st;
        }
    }
    return MSCIP_OK;
}

mscip_status_t mscip_imu_config_aux_accel_range_encode(const mscip_imu_config_aux_accel_range_t *value,
                                                       uint8_t *buf, size_t cap, size_t *len_out) {
    mscip_writer_t w;
    mscip_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mscip_writer_init(&w, buf, cap);
    st = mscip_imu_config_aux_accel_range_write(&w, value);
    if (st == MSCIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mscip_status_t mscip_imu_config_aux_accel_range_decode(const uint8_t *data, size_t len,
                                                       mscip_imu_config_aux_accel_range_t *out,
                                                       mscip_decode_error_t *err) {
    mscip_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mscip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mscip_imu_config_aux_accel_range_read(&r, out) ? MSCIP_ERR_DECODE : MSCIP_OK;
}

void mscip_imu_config_aux_accel_range_to_json(mscip_jw_t *w, const mscip_imu_config_aux_accel_range_t *in) {
    int first = 1;
    mscip_jw_raw(w, "{", 1);
    mscip_jw_key(w, &first, "function");
    mscip_jw_u8(w, &in->function);
    if (in->has_range) {
        mscip_jw_key(w, &first, "range");
        mscip_jw_u8(w, &in->range);
    }
    mscip_jw_raw(w, "}", 1);
}

int mscip_imu_config_aux_accel_range_from_json(mscip_jr_t *jr, size_t pos,
                                               mscip_imu_config_aux_accel_range_t *out) {
    static const char *const keys[] = {"function", "range"};
    size_t vp = 0;
    int found;
    int absent = 0;
    memset(out, 0, sizeof *out);
    if (mscip_jr_object(jr, pos, keys, 2)) {
        return -1;
    }
    found = mscip_jr_get(jr, pos, "function", &vp);
    if (found != 1) {
        return mscip_jr_fail(jr, "missing parameter \"function\"");
    }
    {
        mscip_jr_push(jr, "function");
        if (mscip_jr_u8(jr, vp, &out->function)) {
            return -1;
        }
        mscip_jr_pop(jr);
    }
    found = mscip_jr_get(jr, pos, "range", &vp);
    out->has_range = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mscip_jr_fail(jr, "optional parameter \"range\" given after an absent one");
    } else {
        mscip_jr_push(jr, "range");
        if (mscip_jr_u8(jr, vp, &out->range)) {
            return -1;
        }
        mscip_jr_pop(jr);
    }
    return 0;
}

/* ---- mscip_imu_config_aux_accel_range_response_t */

static int mscip_imu_config_aux_accel_range_response_read(mscip_reader_t *r,
                                                          mscip_imu_config_aux_accel_range_response_t *out) {
    mscip_rd_push(r, "range");
    if (mscip_rd_u8(r, &out->range)) {
        return -1;
    }
    mscip_rd_pop(r);
    return mscip_rd_finish(r);
}

static mscip_status_t
mscip_imu_config_aux_accel_range_response_write(mscip_writer_t *w,
                                                const mscip_imu_config_aux_accel_range_response_t *in) {
    mscip_status_t st;
    if ((st = mscip_wr_u8(w, &in->range)) != MSCIP_OK) {
        return st;
    }
    return MSCIP_OK;
}

mscip_status_t
mscip_imu_config_aux_accel_range_response_encode(const mscip_imu_config_aux_accel_range_response_t *value,
                                                 uint8_t *buf, size_t cap, size_t *len_out) {
    mscip_writer_t w;
    mscip_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mscip_writer_init(&w, buf, cap);
    st = mscip_imu_config_aux_accel_range_response_write(&w, value);
    if (st == MSCIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 1 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mscip_imu_config_aux_accel_range_response_load(const uint8_t *d,
                                                          mscip_imu_config_aux_accel_range_response_t *out) {
    out->range = mscip_ld_u8(d + 0);
    return 0;
}

/* The general reader: lengths other than 1, bad bool bytes, error details. */
static MSCIP_NOINLINE mscip_status_t mscip_imu_config_aux_accel_range_response_decode_read(
    const uint8_t *data, size_t len, mscip_imu_config_aux_accel_range_response_t *out,
    mscip_decode_error_t *err) {
    mscip_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mscip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mscip_imu_config_aux_accel_range_response_read(&r, out) ? MSCIP_ERR_DECODE : MSCIP_OK;
}

mscip_status_t
mscip_imu_config_aux_accel_range_response_decode(const uint8_t *data, size_t len,
                                                 mscip_imu_config_aux_accel_range_response_t *out,
                                                 mscip_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 1 && mscip_imu_config_aux_accel_range_response_load(data, out) == 0) {
        return MSCIP_OK;
    }
    return mscip_imu_config_aux_accel_range_response_decode_read(data, len, out, err);
}

void mscip_imu_config_aux_accel_range_response_to_json(
    mscip_jw_t *w, const mscip_imu_config_aux_accel_range_response_t *in) {
    int first = 1;
    mscip_jw_raw(w, "{", 1);
    mscip_jw_key(w, &first, "range");
    mscip_jw_u8(w, &in->range);
    mscip_jw_raw(w, "}", 1);
}

int mscip_imu_config_aux_accel_range_response_from_json(mscip_jr_t *jr, size_t pos,
                                                        mscip_imu_config_aux_accel_range_response_t *out) {
    static const char *const keys[] = {"range"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mscip_jr_object(jr, pos, keys, 1)) {
        return -1;
    }
    found = mscip_jr_get(jr, pos, "range", &vp);
    if (found != 1) {
        return mscip_jr_fail(jr, "missing parameter \"range\"");
    }
    {
        mscip_jr_push(jr, "range");
        if (mscip_jr_u8(jr, vp, &out->range)) {
            return -1;
        }
        mscip_jr_pop(jr);
    }
    return 0;
}
