/* Encoders and decoders of Receiver 1. Generated from the spec: do not edit. */
#include "democodec/sets/receiver_1.h"
#include "layouts_internal.h"
#include "types_internal.h"

#include <assert.h>
#include <string.h>

/* ---- democ_receiver_1_llh_position_t */

static int democ_receiver_1_llh_position_read(democ_reader_t *r, democ_receiver_1_llh_position_t *out) {
    democ_rd_push(r, "latitude");
    if (democ_rd_f64(r, &out->latitude)) {
        return -1;
    }
    democ_rd_pop(r);
    democ_rd_push(r, "longitude");
    if (democ_rd_f64(r, &out->longitude)) {
        return -1;
    }
    democ_rd_pop(r);
    democ_rd_push(r, "valid_flags");
    if (democ_rd_u16(r, &out->valid_flags)) {
        return -1;
    }
    democ_rd_pop(r);
    return democ_rd_finish(r);
}

static democ_status_t democ_receiver_1_llh_position_write(democ_writer_t *w,
                                                          const democ_receiver_1_llh_position_t *in) {
    democ_status_t st;
    if ((st = democ_wr_f64(w, &in->latitude)) != DEMOC_OK) {
        return st;
    }
    if ((st = democ_wr_f64(w, &in->longitude)) != DEMOC_OK) {
        return st;
    }
    if ((st = democ_wr_u16(w, &in->valid_flags)) != DEMOC_OK) {
        return st;
    }
    return DEMOC_OK;
}

democ_status_t democ_receiver_1_llh_position_encode(const democ_receiver_1_llh_position_t *value,
                                                    uint8_t *buf, size_t cap, size_t *len_out) {
    democ_writer_t w;
    democ_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    democ_writer_init(&w, buf, cap);
    st = democ_receiver_1_llh_position_write(&w, value);
    if (st == DEMOC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 18 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int democ_receiver_1_llh_position_load(const uint8_t *d, democ_receiver_1_llh_position_t *out) {
    out->latitude = democ_ld_f64(d + 0);
    out->longitude = democ_ld_f64(d + 8);
    out->valid_flags = democ_ld_u16(d + 16);
    return 0;
}

/* The general reader: lengths other than 18, bad bool bytes, error details. */
static DEMOC_NOINLINE democ_status_t democ_receiver_1_llh_position_decode_read(
    const uint8_t *data, size_t len, democ_receiver_1_llh_position_t *out, democ_decode_error_t *err) {
    democ_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    democ_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return democ_receiver_1_llh_position_read(&r, out) ? DEMOC_ERR_DECODE : DEMOC_OK;
}

democ_status_t democ_receiver_1_llh_position_decode(const uint8_t *data, size_t len,
                                                    democ_receiver_1_llh_position_t *out,
                                                    democ_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 18 && democ_receiver_1_llh_position_load(data, out) == 0) {
        return DEMOC_OK;
    }
    return democ_receiver_1_llh_position_decode_read(data, len, out, err);
}
