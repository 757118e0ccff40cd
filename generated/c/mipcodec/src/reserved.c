/* Encoders and decoders of Reserved fields (valid in every set of their kind). Generated from the spec: do
 * not edit. */
#include "mipcodec/reserved.h"
#include "layouts_internal.h"
#include "types_internal.h"

#include <assert.h>
#include <string.h>

/* ---- mipc_ack_nack_t */

static int mipc_ack_nack_read(mipc_reader_t *r, mipc_ack_nack_t *out) {
    mipc_rd_push(r, "command_descriptor");
    if (mipc_rd_u8(r, &out->command_descriptor)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "ack_code");
    if (mipc_rd_u8(r, &out->ack_code)) {
        return -1;
    }
    mipc_rd_pop(r);
    return mipc_rd_finish(r);
}

static mipc_status_t mipc_ack_nack_write(mipc_writer_t *w, const mipc_ack_nack_t *in) {
    mipc_status_t st;
    if ((st = mipc_wr_u8(w, &in->command_descriptor)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u8(w, &in->ack_code)) != MIPC_OK) {
        return st;
    }
    return MIPC_OK;
}

mipc_status_t mipc_ack_nack_encode(const mipc_ack_nack_t *value, uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mipc_writer_init(&w, buf, cap);
    st = mipc_ack_nack_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 2 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mipc_ack_nack_load(const uint8_t *d, mipc_ack_nack_t *out) {
    out->command_descriptor = mipc_ld_u8(d + 0);
    out->ack_code = mipc_ld_u8(d + 1);
    return 0;
}

/* The general reader: lengths other than 2, bad bool bytes, error details. */
static MIPC_NOINLINE mipc_status_t mipc_ack_nack_decode_read(const uint8_t *data, size_t len,
                                                             mipc_ack_nack_t *out, mipc_decode_error_t *err) {
    mipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_ack_nack_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t mipc_ack_nack_decode(const uint8_t *data, size_t len, mipc_ack_nack_t *out,
                                   mipc_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 2 && mipc_ack_nack_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_ack_nack_decode_read(data, len, out, err);
}
