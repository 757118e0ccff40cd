/* Encoders and decoders of System Data Set. Generated from the spec: do not edit. */
#include "mipcodec/sets/system_data.h"
#include "layouts_internal.h"
#include "types_internal.h"

#include <assert.h>
#include <string.h>

/* ---- mipc_system_data_built_in_test_t */

static int mipc_system_data_built_in_test_read(mipc_reader_t *r, mipc_system_data_built_in_test_t *out) {
    mipc_rd_push(r, "result");
    if (mipc_cv7_continuous_bit_read(r, &out->result)) {
        return -1;
    }
    mipc_rd_pop(r);
    return mipc_rd_finish(r);
}

static mipc_status_t mipc_system_data_built_in_test_write(mipc_writer_t *w,
                                                          const mipc_system_data_built_in_test_t *in) {
    mipc_status_t st;
    if ((st = mipc_cv7_continuous_bit_write(w, &in->result)) != MIPC_OK) {
        return st;
    }
    return MIPC_OK;
}

mipc_status_t mipc_system_data_built_in_test_encode(const mipc_system_data_built_in_test_t *value,
                                                    uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mipc_writer_init(&w, buf, cap);
    st = mipc_system_data_built_in_test_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mipc_status_t mipc_system_data_built_in_test_decode(const uint8_t *data, size_t len,
                                                    mipc_system_data_built_in_test_t *out,
                                                    mipc_decode_error_t *err) {
    mipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_system_data_built_in_test_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

/* ---- mipc_system_data_time_sync_status_t */

static int mipc_system_data_time_sync_status_read(mipc_reader_t *r,
                                                  mipc_system_data_time_sync_status_t *out) {
    mipc_rd_push(r, "time_sync");
    if (mipc_rd_bool(r, &out->time_sync)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "last_pps_rcvd");
    if (mipc_rd_u8(r, &out->last_pps_rcvd)) {
        return -1;
    }
    mipc_rd_pop(r);
    return mipc_rd_finish(r);
}

static mipc_status_t mipc_system_data_time_sync_status_write(mipc_writer_t *w,
                                                             const mipc_system_data_time_sync_status_t *in) {
    mipc_status_t st;
    if ((st = mipc_wr_bool(w, &in->time_sync)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u8(w, &in->last_pps_rcvd)) != MIPC_OK) {
        return st;
    }
    return MIPC_OK;
}

mipc_status_t mipc_system_data_time_sync_status_encode(const mipc_system_data_time_sync_status_t *value,
                                                       uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mipc_writer_init(&w, buf, cap);
    st = mipc_system_data_time_sync_status_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 2 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mipc_system_data_time_sync_status_load(const uint8_t *d,
                                                  mipc_system_data_time_sync_status_t *out) {
    if (d[0] > 1) {
        return -1;
    }
    out->time_sync = mipc_ld_bool(d + 0);
    out->last_pps_rcvd = mipc_ld_u8(d + 1);
    return 0;
}

/* The general reader: lengths other than 2, bad bool bytes, error details. */
static MIPC_NOINLINE mipc_status_t mipc_system_data_time_sync_status_decode_read(
    const uint8_t *data, size_t len, mipc_system_data_time_sync_status_t *out, mipc_decode_error_t *err) {
    mipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_system_data_time_sync_status_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t mipc_system_data_time_sync_status_decode(const uint8_t *data, size_t len,
                                                       mipc_system_data_time_sync_status_t *out,
                                                       mipc_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 2 && mipc_system_data_time_sync_status_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_system_data_time_sync_status_decode_read(data, len, out, err);
}

/* ---- mipc_system_data_gpio_state_t */

static int mipc_system_data_gpio_state_read(mipc_reader_t *r, mipc_system_data_gpio_state_t *out) {
    mipc_rd_push(r, "states");
    if (mipc_rd_u8(r, &out->states)) {
        return -1;
    }
    mipc_rd_pop(r);
    return mipc_rd_finish(r);
}

static mipc_status_t mipc_system_data_gpio_state_write(mipc_writer_t *w,
                                                       const mipc_system_data_gpio_state_t *in) {
    mipc_status_t st;
    if ((st = mipc_wr_u8(w, &in->states)) != MIPC_OK) {
        return st;
    }
    return MIPC_OK;
}

mipc_status_t mipc_system_data_gpio_state_encode(const mipc_system_data_gpio_state_t *value, uint8_t *buf,
                                                 size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mipc_writer_init(&w, buf, cap);
    st = mipc_system_data_gpio_state_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 1 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mipc_system_data_gpio_state_load(const uint8_t *d, mipc_system_data_gpio_state_t *out) {
    out->states = mipc_ld_u8(d + 0);
    return 0;
}

/* The general reader: lengths other than 1, bad bool bytes, error details. */
static MIPC_NOINLINE mipc_status_t mipc_system_data_gpio_state_decode_read(const uint8_t *data, size_t len,
                                                                           mipc_system_data_gpio_state_t *out,
                                                                           mipc_decode_error_t *err) {
    mipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_system_data_gpio_state_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t mipc_system_data_gpio_state_decode(const uint8_t *data, size_t len,
                                                 mipc_system_data_gpio_state_t *out,
                                                 mipc_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 1 && mipc_system_data_gpio_state_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_system_data_gpio_state_decode_read(data, len, out, err);
}
