/* Encoders and decoders of Reserved fields (valid in every set of their kind). Generated from the spec: do
 * not edit. */
#include "mipcodec/reserved.h"
#include "layouts_internal.h"
#include "types_internal.h"

#include <assert.h>
#include <string.h>

/* ---- mip_ack_nack_t */

static int mip_ack_nack_read(mip_reader_t *r, mip_ack_nack_t *out) {
    mip_rd_push(r, "command_descriptor");
    if (mip_rd_u8(r, &out->command_descriptor)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "ack_code");
    if (mip_rd_u8(r, &out->ack_code)) {
        return -1;
    }
    mip_rd_pop(r);
    return mip_rd_finish(r);
}

static mip_status_t mip_ack_nack_write(mip_writer_t *w, const mip_ack_nack_t *in) {
    mip_status_t st;
    if ((st = mip_wr_u8(w, &in->command_descriptor)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_u8(w, &in->ack_code)) != MIP_OK) {
        return st;
    }
    return MIP_OK;
}

mip_status_t mip_ack_nack_encode(const mip_ack_nack_t *value, uint8_t *buf, size_t cap, size_t *len_out) {
    mip_writer_t w;
    mip_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mip_writer_init(&w, buf, cap);
    st = mip_ack_nack_write(&w, value);
    if (st == MIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 2 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mip_ack_nack_load(const uint8_t *d, mip_ack_nack_t *out) {
    out->command_descriptor = mip_ld_u8(d + 0);
    out->ack_code = mip_ld_u8(d + 1);
    return 0;
}

/* The general reader: lengths other than 2, bad bool bytes, error details. */
static MIP_NOINLINE mip_status_t mip_ack_nack_decode_read(const uint8_t *data, size_t len,
                                                          mip_ack_nack_t *out, mip_decode_error_t *err) {
    mip_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mip_ack_nack_read(&r, out) ? MIP_ERR_DECODE : MIP_OK;
}

mip_status_t mip_ack_nack_decode(const uint8_t *data, size_t len, mip_ack_nack_t *out,
                                 mip_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 2 && mip_ack_nack_load(data, out) == 0) {
        return MIP_OK;
    }
    return mip_ack_nack_decode_read(data, len, out, err);
}

void mip_ack_nack_to_json(mip_jw_t *w, const mip_ack_nack_t *in) {
    int first = 1;
    mip_jw_raw(w, "{", 1);
    mip_jw_key(w, &first, "command_descriptor");
    mip_jw_u8(w, &in->command_descriptor);
    mip_jw_key(w, &first, "ack_code");
    mip_jw_u8(w, &in->ack_code);
    mip_jw_raw(w, "}", 1);
}

int mip_ack_nack_from_json(mip_jr_t *jr, size_t pos, mip_ack_nack_t *out) {
    static const char *const keys[] = {"command_descriptor", "ack_code"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mip_jr_object(jr, pos, keys, 2)) {
        return -1;
    }
    found = mip_jr_get(jr, pos, "command_descriptor", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"command_descriptor\"");
    }
    {
        mip_jr_push(jr, "command_descriptor");
        if (mip_jr_u8(jr, vp, &out->command_descriptor)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "ack_code", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"ack_code\"");
    }
    {
        mip_jr_push(jr, "ack_code");
        if (mip_jr_u8(jr, vp, &out->ack_code)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    return 0;
}
