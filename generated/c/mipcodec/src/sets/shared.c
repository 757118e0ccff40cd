/* Encoders and decoders of Shared Data Descriptors. Generated from the spec: do not edit. */
#include "mipcodec/sets/shared.h"
#include "layouts_internal.h"
#include "types_internal.h"

#include <assert.h>
#include <string.h>

/* ---- mipc_shared_event_source_t */

static int mipc_shared_event_source_read(mipc_reader_t *r, mipc_shared_event_source_t *out) {
    mipc_rd_push(r, "trigger_id");
    if (mipc_rd_u8(r, &out->trigger_id)) {
        return -1;
    }
    mipc_rd_pop(r);
    return mipc_rd_finish(r);
}

static mipc_status_t mipc_shared_event_source_write(mipc_writer_t *w, const mipc_shared_event_source_t *in) {
    mipc_status_t st;
    if ((st = mipc_wr_u8(w, &in->trigger_id)) != MIPC_OK) {
        return st;
    }
    return MIPC_OK;
}

mipc_status_t mipc_shared_event_source_encode(const mipc_shared_event_source_t *value, uint8_t *buf,
                                              size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mipc_writer_init(&w, buf, cap);
    st = mipc_shared_event_source_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 1 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mipc_shared_event_source_load(const uint8_t *d, mipc_shared_event_source_t *out) {
    out->trigger_id = mipc_ld_u8(d + 0);
    return 0;
}

/* The general reader: lengths other than 1, bad bool bytes, error details. */
static MIPC_NOINLINE mipc_status_t mipc_shared_event_source_decode_read(const uint8_t *data, size_t len,
                                                                        mipc_shared_event_source_t *out,
                                                                        mipc_decode_error_t *err) {
    mipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_shared_event_source_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t mipc_shared_event_source_decode(const uint8_t *data, size_t len,
                                              mipc_shared_event_source_t *out, mipc_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 1 && mipc_shared_event_source_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_shared_event_source_decode_read(data, len, out, err);
}

/* ---- mipc_shared_gps_timestamp_t */

static int mipc_shared_gps_timestamp_read(mipc_reader_t *r, mipc_shared_gps_timestamp_t *out) {
    mipc_rd_push(r, "tow");
    if (mipc_rd_f64(r, &out->tow)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "week_number");
    if (mipc_rd_u16(r, &out->week_number)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "valid_flags");
    if (mipc_rd_u16(r, &out->valid_flags)) {
        return -1;
    }
    mipc_rd_pop(r);
    return mipc_rd_finish(r);
}

static mipc_status_t mipc_shared_gps_timestamp_write(mipc_writer_t *w,
                                                     const mipc_shared_gps_timestamp_t *in) {
    mipc_status_t st;
    if ((st = mipc_wr_f64(w, &in->tow)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u16(w, &in->week_number)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u16(w, &in->valid_flags)) != MIPC_OK) {
        return st;
    }
    return MIPC_OK;
}

mipc_status_t mipc_shared_gps_timestamp_encode(const mipc_shared_gps_timestamp_t *value, uint8_t *buf,
                                               size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mipc_writer_init(&w, buf, cap);
    st = mipc_shared_gps_timestamp_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 12 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mipc_shared_gps_timestamp_load(const uint8_t *d, mipc_shared_gps_timestamp_t *out) {
    out->tow = mipc_ld_f64(d + 0);
    out->week_number = mipc_ld_u16(d + 8);
    out->valid_flags = mipc_ld_u16(d + 10);
    return 0;
}

/* The general reader: lengths other than 12, bad bool bytes, error details. */
static MIPC_NOINLINE mipc_status_t mipc_shared_gps_timestamp_decode_read(const uint8_t *data, size_t len,
                                                                         mipc_shared_gps_timestamp_t *out,
                                                                         mipc_decode_error_t *err) {
    mipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_shared_gps_timestamp_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t mipc_shared_gps_timestamp_decode(const uint8_t *data, size_t len,
                                               mipc_shared_gps_timestamp_t *out, mipc_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 12 && mipc_shared_gps_timestamp_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_shared_gps_timestamp_decode_read(data, len, out, err);
}

/* ---- mipc_shared_delta_time_t */

static int mipc_shared_delta_time_read(mipc_reader_t *r, mipc_shared_delta_time_t *out) {
    mipc_rd_push(r, "seconds");
    if (mipc_rd_f64(r, &out->seconds)) {
        return -1;
    }
    mipc_rd_pop(r);
    return mipc_rd_finish(r);
}

static mipc_status_t mipc_shared_delta_time_write(mipc_writer_t *w, const mipc_shared_delta_time_t *in) {
    mipc_status_t st;
    if ((st = mipc_wr_f64(w, &in->seconds)) != MIPC_OK) {
        return st;
    }
    return MIPC_OK;
}

mipc_status_t mipc_shared_delta_time_encode(const mipc_shared_delta_time_t *value, uint8_t *buf, size_t cap,
                                            size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mipc_writer_init(&w, buf, cap);
    st = mipc_shared_delta_time_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 8 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mipc_shared_delta_time_load(const uint8_t *d, mipc_shared_delta_time_t *out) {
    out->seconds = mipc_ld_f64(d + 0);
    return 0;
}

/* The general reader: lengths other than 8, bad bool bytes, error details. */
static MIPC_NOINLINE mipc_status_t mipc_shared_delta_time_decode_read(const uint8_t *data, size_t len,
                                                                      mipc_shared_delta_time_t *out,
                                                                      mipc_decode_error_t *err) {
    mipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_shared_delta_time_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t mipc_shared_delta_time_decode(const uint8_t *data, size_t len, mipc_shared_delta_time_t *out,
                                            mipc_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 8 && mipc_shared_delta_time_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_shared_delta_time_decode_read(data, len, out, err);
}

/* ---- mipc_shared_reference_timestamp_t */

static int mipc_shared_reference_timestamp_read(mipc_reader_t *r, mipc_shared_reference_timestamp_t *out) {
    mipc_rd_push(r, "nanoseconds");
    if (mipc_rd_u64(r, &out->nanoseconds)) {
        return -1;
    }
    mipc_rd_pop(r);
    return mipc_rd_finish(r);
}

static mipc_status_t mipc_shared_reference_timestamp_write(mipc_writer_t *w,
                                                           const mipc_shared_reference_timestamp_t *in) {
    mipc_status_t st;
    if ((st = mipc_wr_u64(w, &in->nanoseconds)) != MIPC_OK) {
        return st;
    }
    return MIPC_OK;
}

mipc_status_t mipc_shared_reference_timestamp_encode(const mipc_shared_reference_timestamp_t *value,
                                                     uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mipc_writer_init(&w, buf, cap);
    st = mipc_shared_reference_timestamp_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 8 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mipc_shared_reference_timestamp_load(const uint8_t *d, mipc_shared_reference_timestamp_t *out) {
    out->nanoseconds = mipc_ld_u64(d + 0);
    return 0;
}

/* The general reader: lengths other than 8, bad bool bytes, error details. */
static MIPC_NOINLINE mipc_status_t mipc_shared_reference_timestamp_decode_read(
    const uint8_t *data, size_t len, mipc_shared_reference_timestamp_t *out, mipc_decode_error_t *err) {
    mipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_shared_reference_timestamp_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t mipc_shared_reference_timestamp_decode(const uint8_t *data, size_t len,
                                                     mipc_shared_reference_timestamp_t *out,
                                                     mipc_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 8 && mipc_shared_reference_timestamp_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_shared_reference_timestamp_decode_read(data, len, out, err);
}

/* ---- mipc_shared_reference_time_delta_t */

static int mipc_shared_reference_time_delta_read(mipc_reader_t *r, mipc_shared_reference_time_delta_t *out) {
    mipc_rd_push(r, "dt_nanos");
    if (mipc_rd_u64(r, &out->dt_nanos)) {
        return -1;
    }
    mipc_rd_pop(r);
    return mipc_rd_finish(r);
}

static mipc_status_t mipc_shared_reference_time_delta_write(mipc_writer_t *w,
                                                            const mipc_shared_reference_time_delta_t *in) {
    mipc_status_t st;
    if ((st = mipc_wr_u64(w, &in->dt_nanos)) != MIPC_OK) {
        return st;
    }
    return MIPC_OK;
}

mipc_status_t mipc_shared_reference_time_delta_encode(const mipc_shared_reference_time_delta_t *value,
                                                      uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mipc_writer_init(&w, buf, cap);
    st = mipc_shared_reference_time_delta_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 8 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mipc_shared_reference_time_delta_load(const uint8_t *d, mipc_shared_reference_time_delta_t *out) {
    out->dt_nanos = mipc_ld_u64(d + 0);
    return 0;
}

/* The general reader: lengths other than 8, bad bool bytes, error details. */
static MIPC_NOINLINE mipc_status_t mipc_shared_reference_time_delta_decode_read(
    const uint8_t *data, size_t len, mipc_shared_reference_time_delta_t *out, mipc_decode_error_t *err) {
    mipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_shared_reference_time_delta_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t mipc_shared_reference_time_delta_decode(const uint8_t *data, size_t len,
                                                      mipc_shared_reference_time_delta_t *out,
                                                      mipc_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 8 && mipc_shared_reference_time_delta_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_shared_reference_time_delta_decode_read(data, len, out, err);
}

/* ---- mipc_shared_external_timestamp_t */

static int mipc_shared_external_timestamp_read(mipc_reader_t *r, mipc_shared_external_timestamp_t *out) {
    mipc_rd_push(r, "nanoseconds");
    if (mipc_rd_u64(r, &out->nanoseconds)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "valid_flags");
    if (mipc_rd_u16(r, &out->valid_flags)) {
        return -1;
    }
    mipc_rd_pop(r);
    return mipc_rd_finish(r);
}

static mipc_status_t mipc_shared_external_timestamp_write(mipc_writer_t *w,
                                                          const mipc_shared_external_timestamp_t *in) {
    mipc_status_t st;
    if ((st = mipc_wr_u64(w, &in->nanoseconds)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u16(w, &in->valid_flags)) != MIPC_OK) {
        return st;
    }
    return MIPC_OK;
}

mipc_status_t mipc_shared_external_timestamp_encode(const mipc_shared_external_timestamp_t *value,
                                                    uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mipc_writer_init(&w, buf, cap);
    st = mipc_shared_external_timestamp_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 10 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mipc_shared_external_timestamp_load(const uint8_t *d, mipc_shared_external_timestamp_t *out) {
    out->nanoseconds = mipc_ld_u64(d + 0);
    out->valid_flags = mipc_ld_u16(d + 8);
    return 0;
}

/* The general reader: lengths other than 10, bad bool bytes, error details. */
static MIPC_NOINLINE mipc_status_t mipc_shared_external_timestamp_decode_read(
    const uint8_t *data, size_t len, mipc_shared_external_timestamp_t *out, mipc_decode_error_t *err) {
    mipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_shared_external_timestamp_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t mipc_shared_external_timestamp_decode(const uint8_t *data, size_t len,
                                                    mipc_shared_external_timestamp_t *out,
                                                    mipc_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 10 && mipc_shared_external_timestamp_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_shared_external_timestamp_decode_read(data, len, out, err);
}

/* ---- mipc_shared_external_time_delta_t */

static int mipc_shared_external_time_delta_read(mipc_reader_t *r, mipc_shared_external_time_delta_t *out) {
    mipc_rd_push(r, "dt_nanos");
    if (mipc_rd_u64(r, &out->dt_nanos)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "valid_flags");
    if (mipc_rd_u16(r, &out->valid_flags)) {
        return -1;
    }
    mipc_rd_pop(r);
    return mipc_rd_finish(r);
}

static mipc_status_t mipc_shared_external_time_delta_write(mipc_writer_t *w,
                                                           const mipc_shared_external_time_delta_t *in) {
    mipc_status_t st;
    if ((st = mipc_wr_u64(w, &in->dt_nanos)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u16(w, &in->valid_flags)) != MIPC_OK) {
        return st;
    }
    return MIPC_OK;
}

mipc_status_t mipc_shared_external_time_delta_encode(const mipc_shared_external_time_delta_t *value,
                                                     uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mipc_writer_init(&w, buf, cap);
    st = mipc_shared_external_time_delta_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 10 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mipc_shared_external_time_delta_load(const uint8_t *d, mipc_shared_external_time_delta_t *out) {
    out->dt_nanos = mipc_ld_u64(d + 0);
    out->valid_flags = mipc_ld_u16(d + 8);
    return 0;
}

/* The general reader: lengths other than 10, bad bool bytes, error details. */
static MIPC_NOINLINE mipc_status_t mipc_shared_external_time_delta_decode_read(
    const uint8_t *data, size_t len, mipc_shared_external_time_delta_t *out, mipc_decode_error_t *err) {
    mipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_shared_external_time_delta_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t mipc_shared_external_time_delta_decode(const uint8_t *data, size_t len,
                                                     mipc_shared_external_time_delta_t *out,
                                                     mipc_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 10 && mipc_shared_external_time_delta_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_shared_external_time_delta_decode_read(data, len, out, err);
}
