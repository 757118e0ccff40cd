/* Encoders and decoders of Reserved fields (valid in every set of their kind). Generated from the spec: do
 * not edit. */
#include "mscipcodec/reserved.h"
#include "layouts_internal.h"
#include "types_internal.h"

#include <assert.h>
#include <string.h>

/* ---- mscipc_ack_t */

static int mscipc_ack_read(mscipc_reader_t *r, mscipc_ack_t *out) {
    mscipc_rd_push(r, "command_code");
    if (mscipc_rd_u8(r, &out->command_code)) {
        return -1;
    }
    mscipc_rd_pop(r);
    mscipc_rd_push(r, "error_code");
    if (mscipc_rd_u8(r, &out->error_code)) {
        return -1;
    }
    mscipc_rd_pop(r);
    return mscipc_rd_finish(r);
}

static mscipc_status_t mscipc_ack_write(mscipc_writer_t *w, const mscipc_ack_t *in) {
    mscipc_status_t st;
    if ((st = mscipc_wr_u8(w, &in->command_code)) != MSCIPC_OK) {
        return st;
    }
    if ((st = mscipc_wr_u8(w, &in->error_code)) != MSCIPC_OK) {
        return st;
    }
    return MSCIPC_OK;
}

mscipc_status_t mscipc_ack_encode(const mscipc_ack_t *value, uint8_t *buf, size_t cap, size_t *len_out) {
    mscipc_writer_t w;
    mscipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mscipc_writer_init(&w, buf, cap);
    st = mscipc_ack_write(&w, value);
    if (st == MSCIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 2 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mscipc_ack_load(const uint8_t *d, mscipc_ack_t *out) {
    out->command_code = mscipc_ld_u8(d + 0);
    out->error_code = mscipc_ld_u8(d + 1);
    return 0;
}

/* The general reader: lengths other than 2, bad bool bytes, error details. */
static MSCIPC_NOINLINE mscipc_status_t mscipc_ack_decode_read(const uint8_t *data, size_t len,
                                                              mscipc_ack_t *out, mscipc_decode_error_t *err) {
    mscipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mscipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mscipc_ack_read(&r, out) ? MSCIPC_ERR_DECODE : MSCIPC_OK;
}

mscipc_status_t mscipc_ack_decode(const uint8_t *data, size_t len, mscipc_ack_t *out,
                                  mscipc_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 2 && mscipc_ack_load(data, out) == 0) {
        return MSCIPC_OK;
    }
    return mscipc_ack_decode_read(data, len, out, err);
}
