/* Encoders and decoders of Shared Data Descriptors. Generated from the spec: do not edit. */
#include "mipcodec/sets/shared.h"
#include "layouts_internal.h"
#include "types_internal.h"

#include <assert.h>
#include <stddef.h>
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

/* ---- the straight-line packet decoder */

size_t mipc_shared_decode_packet(const uint8_t *payload, size_t len, mipc_shared_packet_t *out,
                                 mipc_field_entry_fn other, void *ctx) {
    size_t pos = 0;
    size_t n = 0;
    assert(payload != NULL || len == 0);
    assert(out != NULL);
    memset(out->index.present, 0, sizeof out->index.present);
    if (payload == NULL) {
        len = 0;
    }
    /* the field headers read in place (the iterator's entry is built only for what goes to other) */
    while (len - pos >= MIPC_FIELD_HEADER_SIZE) {
        const uint8_t *head = payload + pos;
        const uint8_t descriptor = head[MIPC_FIELD_DESCRIPTOR_OFFSET];
        const int data_len =
            (int)head[MIPC_FIELD_LENGTH_OFFSET] - mipc_field_length_adjust(MIPC_SHARED_SET, descriptor);
        const uint8_t *d = head + MIPC_FIELD_HEADER_SIZE;
        const uint32_t bit = (uint32_t)1u << (descriptor % 32u);
        size_t length;
        size_t offset = 0;
        int ok = 0;
        if (data_len < 0 || (size_t)data_len > len - pos - MIPC_FIELD_HEADER_SIZE) {
            break; /* trailing bytes: the iterator reports them below */
        }
        length = (size_t)data_len;
        if ((out->index.present[descriptor / 32u] & bit) == 0) {
            switch (descriptor) {
            case 0xD0:
                if (length == 1) {
                    out->shared_event_source.trigger_id = mipc_ld_u8(d + 0);
                    ok = 1;
                } else {
                    ok = mipc_shared_event_source_decode(d, length, &out->shared_event_source, NULL) ==
                         MIPC_OK;
                }
                offset = offsetof(mipc_shared_packet_t, shared_event_source);
                break;
            case 0xD3:
                if (length == 12) {
                    out->shared_gps_timestamp.tow = mipc_ld_f64(d + 0);
                    out->shared_gps_timestamp.week_number = mipc_ld_u16(d + 8);
                    out->shared_gps_timestamp.valid_flags = mipc_ld_u16(d + 10);
                    ok = 1;
                } else {
                    ok = mipc_shared_gps_timestamp_decode(d, length, &out->shared_gps_timestamp, NULL) ==
                         MIPC_OK;
                }
                offset = offsetof(mipc_shared_packet_t, shared_gps_timestamp);
                break;
            case 0xD4:
                if (length == 8) {
                    out->shared_delta_time.seconds = mipc_ld_f64(d + 0);
                    ok = 1;
                } else {
                    ok = mipc_shared_delta_time_decode(d, length, &out->shared_delta_time, NULL) == MIPC_OK;
                }
                offset = offsetof(mipc_shared_packet_t, shared_delta_time);
                break;
            case 0xD5:
                if (length == 8) {
                    out->shared_reference_timestamp.nanoseconds = mipc_ld_u64(d + 0);
                    ok = 1;
                } else {
                    ok = mipc_shared_reference_timestamp_decode(d, length, &out->shared_reference_timestamp,
                                                                NULL) == MIPC_OK;
                }
                offset = offsetof(mipc_shared_packet_t, shared_reference_timestamp);
                break;
            case 0xD6:
                if (length == 8) {
                    out->shared_reference_time_delta.dt_nanos = mipc_ld_u64(d + 0);
                    ok = 1;
                } else {
                    ok = mipc_shared_reference_time_delta_decode(d, length, &out->shared_reference_time_delta,
                                                                 NULL) == MIPC_OK;
                }
                offset = offsetof(mipc_shared_packet_t, shared_reference_time_delta);
                break;
            case 0xD7:
                if (length == 10) {
                    out->shared_external_timestamp.nanoseconds = mipc_ld_u64(d + 0);
                    out->shared_external_timestamp.valid_flags = mipc_ld_u16(d + 8);
                    ok = 1;
                } else {
                    ok = mipc_shared_external_timestamp_decode(d, length, &out->shared_external_timestamp,
                                                               NULL) == MIPC_OK;
                }
                offset = offsetof(mipc_shared_packet_t, shared_external_timestamp);
                break;
            case 0xD8:
                if (length == 10) {
                    out->shared_external_time_delta.dt_nanos = mipc_ld_u64(d + 0);
                    out->shared_external_time_delta.valid_flags = mipc_ld_u16(d + 8);
                    ok = 1;
                } else {
                    ok = mipc_shared_external_time_delta_decode(d, length, &out->shared_external_time_delta,
                                                                NULL) == MIPC_OK;
                }
                offset = offsetof(mipc_shared_packet_t, shared_external_time_delta);
                break;
            default:
                break;
            }
        }
        if (ok) {
            out->index.present[descriptor / 32u] |= bit;
            out->index.fields[n].descriptor = descriptor;
            out->index.fields[n].offset = (uint32_t)offset;
            n++;
        } else if (other) {
            mipc_field_visit_at_(MIPC_SHARED_SET, payload, len, pos, other, ctx);
        }
        pos += MIPC_FIELD_HEADER_SIZE + length;
    }
    if (pos < len && other) {
        mipc_field_visit_at_(MIPC_SHARED_SET, payload, len, pos, other, ctx);
    }
    out->index.count = n;
    return n;
}

/* ---- the members' loaders (mipc_decode_packet_cached, issue 38): each decodes its field's
 * data into its member of the mipc_shared_packet_t at packet as mipc_shared_decode_packet does; 0 when it
 * does not decode (the packet then takes the straight-line decoder, which gives the field to other) */

static int load_0xd0(const uint8_t *d, size_t length, void *packet) {
    mipc_shared_packet_t *out = packet;
    if (length == 1) {
        out->shared_event_source.trigger_id = mipc_ld_u8(d + 0);
        return 1;
    }
    return mipc_shared_event_source_decode(d, length, &out->shared_event_source, NULL) == MIPC_OK;
}

static int load_0xd3(const uint8_t *d, size_t length, void *packet) {
    mipc_shared_packet_t *out = packet;
    if (length == 12) {
        out->shared_gps_timestamp.tow = mipc_ld_f64(d + 0);
        out->shared_gps_timestamp.week_number = mipc_ld_u16(d + 8);
        out->shared_gps_timestamp.valid_flags = mipc_ld_u16(d + 10);
        return 1;
    }
    return mipc_shared_gps_timestamp_decode(d, length, &out->shared_gps_timestamp, NULL) == MIPC_OK;
}

static int load_0xd4(const uint8_t *d, size_t length, void *packet) {
    mipc_shared_packet_t *out = packet;
    if (length == 8) {
        out->shared_delta_time.seconds = mipc_ld_f64(d + 0);
        return 1;
    }
    return mipc_shared_delta_time_decode(d, length, &out->shared_delta_time, NULL) == MIPC_OK;
}

static int load_0xd5(const uint8_t *d, size_t length, void *packet) {
    mipc_shared_packet_t *out = packet;
    if (length == 8) {
        out->shared_reference_timestamp.nanoseconds = mipc_ld_u64(d + 0);
        return 1;
    }
    return mipc_shared_reference_timestamp_decode(d, length, &out->shared_reference_timestamp, NULL) ==
           MIPC_OK;
}

static int load_0xd6(const uint8_t *d, size_t length, void *packet) {
    mipc_shared_packet_t *out = packet;
    if (length == 8) {
        out->shared_reference_time_delta.dt_nanos = mipc_ld_u64(d + 0);
        return 1;
    }
    return mipc_shared_reference_time_delta_decode(d, length, &out->shared_reference_time_delta, NULL) ==
           MIPC_OK;
}

static int load_0xd7(const uint8_t *d, size_t length, void *packet) {
    mipc_shared_packet_t *out = packet;
    if (length == 10) {
        out->shared_external_timestamp.nanoseconds = mipc_ld_u64(d + 0);
        out->shared_external_timestamp.valid_flags = mipc_ld_u16(d + 8);
        return 1;
    }
    return mipc_shared_external_timestamp_decode(d, length, &out->shared_external_timestamp, NULL) == MIPC_OK;
}

static int load_0xd8(const uint8_t *d, size_t length, void *packet) {
    mipc_shared_packet_t *out = packet;
    if (length == 10) {
        out->shared_external_time_delta.dt_nanos = mipc_ld_u64(d + 0);
        out->shared_external_time_delta.valid_flags = mipc_ld_u16(d + 8);
        return 1;
    }
    return mipc_shared_external_time_delta_decode(d, length, &out->shared_external_time_delta, NULL) ==
           MIPC_OK;
}

const mipc_layout_member_t mipc_shared_layout_members_[7] = {
    {0xD0, offsetof(mipc_shared_packet_t, shared_event_source), load_0xd0},
    {0xD3, offsetof(mipc_shared_packet_t, shared_gps_timestamp), load_0xd3},
    {0xD4, offsetof(mipc_shared_packet_t, shared_delta_time), load_0xd4},
    {0xD5, offsetof(mipc_shared_packet_t, shared_reference_timestamp), load_0xd5},
    {0xD6, offsetof(mipc_shared_packet_t, shared_reference_time_delta), load_0xd6},
    {0xD7, offsetof(mipc_shared_packet_t, shared_external_timestamp), load_0xd7},
    {0xD8, offsetof(mipc_shared_packet_t, shared_external_time_delta), load_0xd8},
};
