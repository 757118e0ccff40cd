/* Encoders and decoders of Reserved fields (valid in every set of their kind). Generated from the spec: do
 * not edit. */
#include "mscipcodec/reserved.h"
#include "layouts_internal.h"
#include "types_internal.h"

#include <assert.h>
#include <string.h>

/* ---- mscip_ack_t */

static int mscip_ack_read(mscip_reader_t *r, mscip_ack_t *out) {
    mscip_rd_push(r, "command_code");
    if (mscip_rd_u8(r, &out->command_code)) {
        return -1;
    }
    mscip_rd_pop(r);
    mscip_rd_push(r, "error_code");
    if (mscip_rd_u8(r, &out->error_code)) {
        return -1;
    }
    mscip_rd_pop(r);
    return mscip_rd_finish(r);
}

static mscip_status_t mscip_ack_write(mscip_writer_t *w, const mscip_ack_t *in) {
    mscip_status_t st;
    if ((st = mscip_wr_u8(w, &in->command_code)) != MSCIP_OK) {
        return st;
    }
    if ((st = mscip_wr_u8(w, &in->error_code)) != MSCIP_OK) {
        return st;
    }
    return MSCIP_OK;
}

mscip_status_t mscip_ack_encode(const mscip_ack_t *value, uint8_t *buf, size_t cap, size_t *len_out) {
    mscip_writer_t w;
    mscip_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mscip_writer_init(&w, buf, cap);
    st = mscip_ack_write(&w, value);
    if (st == MSCIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 2 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mscip_ack_load(const uint8_t *d, mscip_ack_t *out) {
    out->command_code = mscip_ld_u8(d + 0);
    out->error_code = mscip_ld_u8(d + 1);
    return 0;
}

/* The general reader: lengths other than 2, bad bool bytes, error details. */
static MSCIP_NOINLINE mscip_status_t mscip_ack_decode_read(const uint8_t *data, size_t len, mscip_ack_t *out,
                                                           mscip_decode_error_t *err) {
    mscip_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mscip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mscip_ack_read(&r, out) ? MSCIP_ERR_DECODE : MSCIP_OK;
}

mscip_status_t mscip_ack_decode(const uint8_t *data, size_t len, mscip_ack_t *out,
                                mscip_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 2 && mscip_ack_load(data, out) == 0) {
        return MSCIP_OK;
    }
    return mscip_ack_decode_read(data, len, out, err);
}

void mscip_ack_to_json(mscip_jw_t *w, const mscip_ack_t *in) {
    int first = 1;
    mscip_jw_raw(w, "{", 1);
    mscip_jw_key(w, &first, "command_code");
    mscip_jw_u8(w, &in->command_code);
    mscip_jw_key(w, &first, "error_code");
    mscip_jw_u8(w, &in->error_code);
    mscip_jw_raw(w, "}", 1);
}

int mscip_ack_from_json(mscip_jr_t *jr, size_t pos, mscip_ack_t *out) {
    static const char *const keys[] = {"command_code", "error_code"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mscip_jr_object(jr, pos, keys, 2)) {
        return -1;
    }
    found = mscip_jr_get(jr, pos, "command_code", &vp);
    if (found != 1) {
        return mscip_jr_fail(jr, "missing parameter \"command_code\"");
    }
    {
        mscip_jr_push(jr, "command_code");
        if (mscip_jr_u8(jr, vp, &out->command_code)) {
            return -1;
        }
        mscip_jr_pop(jr);
    }
    found = mscip_jr_get(jr, pos, "error_code", &vp);
    if (found != 1) {
        return mscip_jr_fail(jr, "missing parameter \"error_code\"");
    }
    {
        mscip_jr_push(jr, "error_code");
        if (mscip_jr_u8(jr, vp, &out->error_code)) {
            return -1;
        }
        mscip_jr_pop(jr);
    }
    return 0;
}
