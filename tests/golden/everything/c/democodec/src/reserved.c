/* Encoders and decoders of Reserved fields (valid in every set of their kind). Generated from the spec: do
 * not edit. */
#include "democodec/reserved.h"
#include "layouts_internal.h"
#include "types_internal.h"

#include <assert.h>
#include <string.h>

/* ---- democ_ack_t */

static int democ_ack_read(democ_reader_t *r, democ_ack_t *out) {
    democ_rd_push(r, "echo");
    if (democ_rd_u8(r, &out->echo)) {
        return -1;
    }
    democ_rd_pop(r);
    democ_rd_push(r, "code");
    if (democ_rd_u8(r, &out->code)) {
        return -1;
    }
    democ_rd_pop(r);
    return democ_rd_finish(r);
}

static democ_status_t democ_ack_write(democ_writer_t *w, const democ_ack_t *in) {
    democ_status_t st;
    if ((st = democ_wr_u8(w, &in->echo)) != DEMOC_OK) {
        return st;
    }
    if ((st = democ_wr_u8(w, &in->code)) != DEMOC_OK) {
        return st;
    }
    return DEMOC_OK;
}

democ_status_t democ_ack_encode(const democ_ack_t *value, uint8_t *buf, size_t cap, size_t *len_out) {
    democ_writer_t w;
    democ_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    democ_writer_init(&w, buf, cap);
    st = democ_ack_write(&w, value);
    if (st == DEMOC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 2 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int democ_ack_load(const uint8_t *d, democ_ack_t *out) {
    out->echo = democ_ld_u8(d + 0);
    out->code = democ_ld_u8(d + 1);
    return 0;
}

/* The general reader: lengths other than 2, bad bool bytes, error details. */
static DEMOC_NOINLINE democ_status_t democ_ack_decode_read(const uint8_t *data, size_t len, democ_ack_t *out,
                                                           democ_decode_error_t *err) {
    democ_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    democ_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return democ_ack_read(&r, out) ? DEMOC_ERR_DECODE : DEMOC_OK;
}

democ_status_t democ_ack_decode(const uint8_t *data, size_t len, democ_ack_t *out,
                                democ_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 2 && democ_ack_load(data, out) == 0) {
        return DEMOC_OK;
    }
    return democ_ack_decode_read(data, len, out, err);
}
