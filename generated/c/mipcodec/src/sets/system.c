/* Encoders and decoders of System Command Set. Generated from the spec: do not edit. */
#include "mipcodec/sets/system.h"
#include "layouts_internal.h"
#include "types_internal.h"

#include <assert.h>
#include <string.h>

/* ---- mip_system_communication_mode_t */

static int mip_system_communication_mode_read(mip_reader_t *r, mip_system_communication_mode_t *out) {
    mip_rd_push(r, "function");
    if (mip_rd_u8(r, &out->function)) {
        return -1;
    }
    mip_rd_pop(r);
    if (r->pos < r->len) {
        out->has_mode = true;
        mip_rd_push(r, "mode");
        if (mip_rd_u8(r, &out->mode)) {
            return -1;
        }
        mip_rd_pop(r);
    }
    return mip_rd_finish(r);
}

static mip_status_t mip_system_communication_mode_write(mip_writer_t *w,
                                                        const mip_system_communication_mode_t *in) {
    mip_status_t st;
    int absent = 0;
    if ((st = mip_wr_u8(w, &in->function)) != MIP_OK) {
        return st;
    }
    if (!in->has_mode) {
        absent = 1;
    } else if (absent) {
        return MIP_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = mip_wr_u8(w, &in->mode)) != MIP_OK) {
            return st;
        }
    }
    return MIP_OK;
}

mip_status_t mip_system_communication_mode_encode(const mip_system_communication_mode_t *value, uint8_t *buf,
                                                  size_t cap, size_t *len_out) {
    mip_writer_t w;
    mip_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mip_writer_init(&w, buf, cap);
    st = mip_system_communication_mode_write(&w, value);
    if (st == MIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mip_status_t mip_system_communication_mode_decode(const uint8_t *data, size_t len,
                                                  mip_system_communication_mode_t *out,
                                                  mip_decode_error_t *err) {
    mip_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mip_system_communication_mode_read(&r, out) ? MIP_ERR_DECODE : MIP_OK;
}

void mip_system_communication_mode_to_json(mip_jw_t *w, const mip_system_communication_mode_t *in) {
    int first = 1;
    mip_jw_raw(w, "{", 1);
    mip_jw_key(w, &first, "function");
    mip_jw_u8(w, &in->function);
    if (in->has_mode) {
        mip_jw_key(w, &first, "mode");
        mip_jw_u8(w, &in->mode);
    }
    mip_jw_raw(w, "}", 1);
}

int mip_system_communication_mode_from_json(mip_jr_t *jr, size_t pos, mip_system_communication_mode_t *out) {
    static const char *const keys[] = {"function", "mode"};
    size_t vp = 0;
    int found;
    int absent = 0;
    memset(out, 0, sizeof *out);
    if (mip_jr_object(jr, pos, keys, 2)) {
        return -1;
    }
    found = mip_jr_get(jr, pos, "function", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"function\"");
    }
    {
        mip_jr_push(jr, "function");
        if (mip_jr_u8(jr, vp, &out->function)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "mode", &vp);
    out->has_mode = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mip_jr_fail(jr, "optional parameter \"mode\" given after an absent one");
    } else {
        mip_jr_push(jr, "mode");
        if (mip_jr_u8(jr, vp, &out->mode)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    return 0;
}

/* ---- mip_system_communication_mode_response_t */

static int mip_system_communication_mode_response_read(mip_reader_t *r,
                                                       mip_system_communication_mode_response_t *out) {
    mip_rd_push(r, "mode");
    if (mip_rd_u8(r, &out->mode)) {
        return -1;
    }
    mip_rd_pop(r);
    return mip_rd_finish(r);
}

static mip_status_t
mip_system_communication_mode_response_write(mip_writer_t *w,
                                             const mip_system_communication_mode_response_t *in) {
    mip_status_t st;
    if ((st = mip_wr_u8(w, &in->mode)) != MIP_OK) {
        return st;
    }
    return MIP_OK;
}

mip_status_t
mip_system_communication_mode_response_encode(const mip_system_communication_mode_response_t *value,
                                              uint8_t *buf, size_t cap, size_t *len_out) {
    mip_writer_t w;
    mip_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mip_writer_init(&w, buf, cap);
    st = mip_system_communication_mode_response_write(&w, value);
    if (st == MIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 1 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mip_system_communication_mode_response_load(const uint8_t *d,
                                                       mip_system_communication_mode_response_t *out) {
    out->mode = mip_ld_u8(d + 0);
    return 0;
}

/* The general reader: lengths other than 1, bad bool bytes, error details. */
static MIP_NOINLINE mip_status_t mip_system_communication_mode_response_decode_read(
    const uint8_t *data, size_t len, mip_system_communication_mode_response_t *out, mip_decode_error_t *err) {
    mip_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mip_system_communication_mode_response_read(&r, out) ? MIP_ERR_DECODE : MIP_OK;
}

mip_status_t mip_system_communication_mode_response_decode(const uint8_t *data, size_t len,
                                                           mip_system_communication_mode_response_t *out,
                                                           mip_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 1 && mip_system_communication_mode_response_load(data, out) == 0) {
        return MIP_OK;
    }
    return mip_system_communication_mode_response_decode_read(data, len, out, err);
}

void mip_system_communication_mode_response_to_json(mip_jw_t *w,
                                                    const mip_system_communication_mode_response_t *in) {
    int first = 1;
    mip_jw_raw(w, "{", 1);
    mip_jw_key(w, &first, "mode");
    mip_jw_u8(w, &in->mode);
    mip_jw_raw(w, "}", 1);
}

int mip_system_communication_mode_response_from_json(mip_jr_t *jr, size_t pos,
                                                     mip_system_communication_mode_response_t *out) {
    static const char *const keys[] = {"mode"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mip_jr_object(jr, pos, keys, 1)) {
        return -1;
    }
    found = mip_jr_get(jr, pos, "mode", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"mode\"");
    }
    {
        mip_jr_push(jr, "mode");
        if (mip_jr_u8(jr, vp, &out->mode)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    return 0;
}
