/* Encoders and decoders of Commands. Generated from the spec: do not edit. */
#include "democodec/sets/commands.h"
#include "layouts_internal.h"
#include "types_internal.h"

#include <assert.h>
#include <string.h>

/* ---- democ_commands_ping_t */

static int democ_commands_ping_read(democ_reader_t *r, democ_commands_ping_t *out) {
    (void)out;
    return democ_rd_finish(r);
}

static democ_status_t democ_commands_ping_write(democ_writer_t *w, const democ_commands_ping_t *in) {
    (void)w;
    (void)in;
    return DEMOC_OK;
}

democ_status_t democ_commands_ping_encode(const democ_commands_ping_t *value, uint8_t *buf, size_t cap,
                                          size_t *len_out) {
    democ_writer_t w;
    democ_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    democ_writer_init(&w, buf, cap);
    st = democ_commands_ping_write(&w, value);
    if (st == DEMOC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

democ_status_t democ_commands_ping_decode(const uint8_t *data, size_t len, democ_commands_ping_t *out,
                                          democ_decode_error_t *err) {
    democ_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    democ_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return democ_commands_ping_read(&r, out) ? DEMOC_ERR_DECODE : DEMOC_OK;
}

/* ---- democ_commands_configure_t */

static int democ_commands_configure_read(democ_reader_t *r, democ_commands_configure_t *out) {
    democ_rd_push(r, "function");
    if (democ_rd_u8(r, &out->function)) {
        return -1;
    }
    democ_rd_pop(r);
    democ_rd_push(r, "instance");
    if (democ_rd_u8(r, &out->instance)) {
        return -1;
    }
    democ_rd_pop(r);
    if (r->pos < r->len) {
        out->has_mode = true;
        democ_rd_push(r, "mode");
        if (democ_rd_u8(r, &out->mode)) {
            return -1;
        }
        democ_rd_pop(r);
    }
    if (r->pos < r->len) {
        out->has_params = true;
        democ_rd_push(r, "params");
        if (democ_trigger_params_read(r, out->mode, &out->params)) {
            return -1;
        }
        democ_rd_pop(r);
    }
    if (r->pos < r->len) {
        out->has_suppress_ack = true;
        democ_rd_push(r, "suppress_ack");
        if (democ_rd_bool(r, &out->suppress_ack)) {
            return -1;
        }
        democ_rd_pop(r);
    }
    return democ_rd_finish(r);
}

static democ_status_t democ_commands_configure_write(democ_writer_t *w,
                                                     const democ_commands_configure_t *in) {
    democ_status_t st;
    int absent = 0;
    if ((st = democ_wr_u8(w, &in->function)) != DEMOC_OK) {
        return st;
    }
    if ((st = democ_wr_u8(w, &in->instance)) != DEMOC_OK) {
        return st;
    }
    if (!in->has_mode) {
        absent = 1;
    } else if (absent) {
        return DEMOC_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = democ_wr_u8(w, &in->mode)) != DEMOC_OK) {
            return st;
        }
    }
    if (!in->has_params) {
        absent = 1;
    } else if (absent) {
        return DEMOC_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = democ_trigger_params_write(w, in->mode, &in->params)) != DEMOC_OK) {
            return st;
        }
    }
    if (!in->has_suppress_ack) {
        absent = 1;
    } else if (absent) {
        return DEMOC_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = democ_wr_bool(w, &in->suppress_ack)) != DEMOC_OK) {
            return st;
        }
    }
    return DEMOC_OK;
}

democ_status_t democ_commands_configure_encode(const democ_commands_configure_t *value, uint8_t *buf,
                                               size_t cap, size_t *len_out) {
    democ_writer_t w;
    democ_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    democ_writer_init(&w, buf, cap);
    st = democ_commands_configure_write(&w, value);
    if (st == DEMOC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

democ_status_t democ_commands_configure_decode(const uint8_t *data, size_t len,
                                               democ_commands_configure_t *out, democ_decode_error_t *err) {
    democ_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    democ_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return democ_commands_configure_read(&r, out) ? DEMOC_ERR_DECODE : DEMOC_OK;
}

/* ---- democ_commands_configuration_t */

static int democ_commands_configuration_read(democ_reader_t *r, democ_commands_configuration_t *out) {
    size_t i;
    size_t n;
    democ_rd_push(r, "instance");
    if (democ_rd_u8(r, &out->instance)) {
        return -1;
    }
    democ_rd_pop(r);
    democ_rd_push(r, "count");
    if (democ_rd_u8(r, &out->count)) {
        return -1;
    }
    democ_rd_pop(r);
    democ_rd_push(r, "rates");
    if (out->count > 10) {
        return democ_rd_count_error(r, (uint64_t)out->count, 10);
    }
    for (i = 0; i < (size_t)out->count; i++) {
        democ_rd_index(r, i);
        if (democ_rd_u16(r, &out->rates[i])) {
            return -1;
        }
    }
    democ_rd_pop(r);
    democ_rd_push(r, "name");
    if (democ_rd_chars(r, out->name, 8)) {
        return -1;
    }
    democ_rd_pop(r);
    democ_rd_push(r, "label");
    if (democ_rd_chars(r, out->label, 16)) {
        return -1;
    }
    democ_rd_pop(r);
    democ_rd_push(r, "matrix");
    for (i = 0; i < 9; i++) {
        democ_rd_index(r, i);
        if (democ_rd_f64(r, &out->matrix[i])) {
            return -1;
        }
    }
    democ_rd_pop(r);
    democ_rd_push(r, "fixed");
    for (i = 0; i < 4; i++) {
        democ_rd_index(r, i);
        if (democ_rd_s32(r, &out->fixed[i])) {
            return -1;
        }
    }
    democ_rd_pop(r);
    democ_rd_push(r, "flags");
    if (democ_rd_u16(r, &out->flags)) {
        return -1;
    }
    democ_rd_pop(r);
    democ_rd_push(r, "signed");
    if (democ_rd_s16(r, &out->signed_)) {
        return -1;
    }
    democ_rd_pop(r);
    democ_rd_push(r, "tail");
    if (democ_rd_remaining(r, 1, 135, &n)) {
        return -1;
    }
    for (i = 0; i < n; i++) {
        democ_rd_index(r, i);
        if (democ_rd_char(r, &out->tail[i])) {
            return -1;
        }
    }
    out->tail_count = n;
    democ_rd_pop(r);
    return democ_rd_finish(r);
}

static democ_status_t democ_commands_configuration_write(democ_writer_t *w,
                                                         const democ_commands_configuration_t *in) {
    democ_status_t st;
    size_t i;
    if ((st = democ_wr_u8(w, &in->instance)) != DEMOC_OK) {
        return st;
    }
    if ((st = democ_wr_u8(w, &in->count)) != DEMOC_OK) {
        return st;
    }
    if (in->count > 10) {
        return DEMOC_ERR_INVALID;
    }
    for (i = 0; i < (size_t)in->count; i++) {
        if ((st = democ_wr_u16(w, &in->rates[i])) != DEMOC_OK) {
            return st;
        }
    }
    if ((st = democ_wr_chars(w, in->name, 8)) != DEMOC_OK) {
        return st;
    }
    if ((st = democ_wr_chars(w, in->label, 16)) != DEMOC_OK) {
        return st;
    }
    for (i = 0; i < 9; i++) {
        if ((st = democ_wr_f64(w, &in->matrix[i])) != DEMOC_OK) {
            return st;
        }
    }
    for (i = 0; i < 4; i++) {
        if ((st = democ_wr_s32(w, &in->fixed[i])) != DEMOC_OK) {
            return st;
        }
    }
    if ((st = democ_wr_u16(w, &in->flags)) != DEMOC_OK) {
        return st;
    }
    if ((st = democ_wr_s16(w, &in->signed_)) != DEMOC_OK) {
        return st;
    }
    if (in->tail_count > 135) {
        return DEMOC_ERR_INVALID;
    }
    for (i = 0; i < (size_t)in->tail_count; i++) {
        if ((st = democ_wr_char(w, &in->tail[i])) != DEMOC_OK) {
            return st;
        }
    }
    return DEMOC_OK;
}

democ_status_t democ_commands_configuration_encode(const democ_commands_configuration_t *value, uint8_t *buf,
                                                   size_t cap, size_t *len_out) {
    democ_writer_t w;
    democ_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    democ_writer_init(&w, buf, cap);
    st = democ_commands_configuration_write(&w, value);
    if (st == DEMOC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

democ_status_t democ_commands_configuration_decode(const uint8_t *data, size_t len,
                                                   democ_commands_configuration_t *out,
                                                   democ_decode_error_t *err) {
    democ_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    democ_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return democ_commands_configuration_read(&r, out) ? DEMOC_ERR_DECODE : DEMOC_OK;
}

/* ---- democ_commands_per_device_dev_a_t */

static int democ_commands_per_device_dev_a_read(democ_reader_t *r, democ_commands_per_device_dev_a_t *out) {
    democ_rd_push(r, "a");
    if (democ_rd_u32(r, &out->a)) {
        return -1;
    }
    democ_rd_pop(r);
    return democ_rd_finish(r);
}

static democ_status_t democ_commands_per_device_dev_a_write(democ_writer_t *w,
                                                            const democ_commands_per_device_dev_a_t *in) {
    democ_status_t st;
    if ((st = democ_wr_u32(w, &in->a)) != DEMOC_OK) {
        return st;
    }
    return DEMOC_OK;
}

democ_status_t democ_commands_per_device_dev_a_encode(const democ_commands_per_device_dev_a_t *value,
                                                      uint8_t *buf, size_t cap, size_t *len_out) {
    democ_writer_t w;
    democ_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    democ_writer_init(&w, buf, cap);
    st = democ_commands_per_device_dev_a_write(&w, value);
    if (st == DEMOC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 4 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int democ_commands_per_device_dev_a_load(const uint8_t *d, democ_commands_per_device_dev_a_t *out) {
    out->a = democ_ld_u32(d + 0);
    return 0;
}

/* The general reader: lengths other than 4, bad bool bytes, error details. */
static DEMOC_NOINLINE democ_status_t democ_commands_per_device_dev_a_decode_read(
    const uint8_t *data, size_t len, democ_commands_per_device_dev_a_t *out, democ_decode_error_t *err) {
    democ_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    democ_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return democ_commands_per_device_dev_a_read(&r, out) ? DEMOC_ERR_DECODE : DEMOC_OK;
}

democ_status_t democ_commands_per_device_dev_a_decode(const uint8_t *data, size_t len,
                                                      democ_commands_per_device_dev_a_t *out,
                                                      democ_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 4 && democ_commands_per_device_dev_a_load(data, out) == 0) {
        return DEMOC_OK;
    }
    return democ_commands_per_device_dev_a_decode_read(data, len, out, err);
}

/* ---- democ_commands_per_device_dev_b_t */

static int democ_commands_per_device_dev_b_read(democ_reader_t *r, democ_commands_per_device_dev_b_t *out) {
    democ_rd_push(r, "b");
    if (democ_rd_u64(r, &out->b)) {
        return -1;
    }
    democ_rd_pop(r);
    if (r->pos < r->len) {
        out->has_extra = true;
        democ_rd_push(r, "extra");
        if (democ_rd_u8(r, &out->extra)) {
            return -1;
        }
        democ_rd_pop(r);
    }
    return democ_rd_finish(r);
}

static democ_status_t democ_commands_per_device_dev_b_write(democ_writer_t *w,
                                                            const democ_commands_per_device_dev_b_t *in) {
    democ_status_t st;
    int absent = 0;
    if ((st = democ_wr_u64(w, &in->b)) != DEMOC_OK) {
        return st;
    }
    if (!in->has_extra) {
        absent = 1;
    } else if (absent) {
        return DEMOC_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = democ_wr_u8(w, &in->extra)) != DEMOC_OK) {
            return st;
        }
    }
    return DEMOC_OK;
}

democ_status_t democ_commands_per_device_dev_b_encode(const democ_commands_per_device_dev_b_t *value,
                                                      uint8_t *buf, size_t cap, size_t *len_out) {
    democ_writer_t w;
    democ_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    democ_writer_init(&w, buf, cap);
    st = democ_commands_per_device_dev_b_write(&w, value);
    if (st == DEMOC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

democ_status_t democ_commands_per_device_dev_b_decode(const uint8_t *data, size_t len,
                                                      democ_commands_per_device_dev_b_t *out,
                                                      democ_decode_error_t *err) {
    democ_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    democ_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return democ_commands_per_device_dev_b_read(&r, out) ? DEMOC_ERR_DECODE : DEMOC_OK;
}
