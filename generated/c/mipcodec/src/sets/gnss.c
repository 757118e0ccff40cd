/* Encoders and decoders of GNSS Command Set. Generated from the spec: do not edit. */
#include "mipcodec/sets/gnss.h"
#include "layouts_internal.h"
#include "types_internal.h"

#include <assert.h>
#include <string.h>

/* ---- mipc_gnss_receiver_info_t */

static int mipc_gnss_receiver_info_read(mipc_reader_t *r, mipc_gnss_receiver_info_t *out) {
    (void)out;
    return mipc_rd_finish(r);
}

static mipc_status_t mipc_gnss_receiver_info_write(mipc_writer_t *w, const mipc_gnss_receiver_info_t *in) {
    (void)w;
    (void)in;
    return MIPC_OK;
}

mipc_status_t mipc_gnss_receiver_info_encode(const mipc_gnss_receiver_info_t *value, uint8_t *buf, size_t cap,
                                             size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mipc_writer_init(&w, buf, cap);
    st = mipc_gnss_receiver_info_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mipc_status_t mipc_gnss_receiver_info_decode(const uint8_t *data, size_t len, mipc_gnss_receiver_info_t *out,
                                             mipc_decode_error_t *err) {
    mipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_gnss_receiver_info_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

/* ---- mipc_gnss_receiver_info_response_t */

static int mipc_gnss_receiver_info_response_read(mipc_reader_t *r, mipc_gnss_receiver_info_response_t *out) {
    size_t i;
    mipc_rd_push(r, "num_receivers");
    if (mipc_rd_u8(r, &out->num_receivers)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "receiver_info");
    if (out->num_receivers > 7) {
        return mipc_rd_count_error(r, (uint64_t)out->num_receivers, 7);
    }
    for (i = 0; i < (size_t)out->num_receivers; i++) {
        mipc_rd_index(r, i);
        if (mipc_gnss_receiver_info_entry_read(r, &out->receiver_info[i])) {
            return -1;
        }
    }
    mipc_rd_pop(r);
    return mipc_rd_finish(r);
}

static mipc_status_t mipc_gnss_receiver_info_response_write(mipc_writer_t *w,
                                                            const mipc_gnss_receiver_info_response_t *in) {
    mipc_status_t st;
    size_t i;
    if ((st = mipc_wr_u8(w, &in->num_receivers)) != MIPC_OK) {
        return st;
    }
    if (in->num_receivers > 7) {
        return MIPC_ERR_INVALID;
    }
    for (i = 0; i < (size_t)in->num_receivers; i++) {
        if ((st = mipc_gnss_receiver_info_entry_write(w, &in->receiver_info[i])) != MIPC_OK) {
            return st;
        }
    }
    return MIPC_OK;
}

mipc_status_t mipc_gnss_receiver_info_response_encode(const mipc_gnss_receiver_info_response_t *value,
                                                      uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mipc_writer_init(&w, buf, cap);
    st = mipc_gnss_receiver_info_response_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mipc_status_t mipc_gnss_receiver_info_response_decode(const uint8_t *data, size_t len,
                                                      mipc_gnss_receiver_info_response_t *out,
                                                      mipc_decode_error_t *err) {
    mipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_gnss_receiver_info_response_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

/* ---- mipc_gnss_signal_configuration_t */

static int mipc_gnss_signal_configuration_read(mipc_reader_t *r, mipc_gnss_signal_configuration_t *out) {
    size_t i;
    mipc_rd_push(r, "function");
    if (mipc_rd_u8(r, &out->function)) {
        return -1;
    }
    mipc_rd_pop(r);
    if (r->pos < r->len) {
        out->has_gps_enable = true;
        mipc_rd_push(r, "gps_enable");
        if (mipc_rd_u8(r, &out->gps_enable)) {
            return -1;
        }
        mipc_rd_pop(r);
    }
    if (r->pos < r->len) {
        out->has_glonass_enable = true;
        mipc_rd_push(r, "glonass_enable");
        if (mipc_rd_u8(r, &out->glonass_enable)) {
            return -1;
        }
        mipc_rd_pop(r);
    }
    if (r->pos < r->len) {
        out->has_galileo_enable = true;
        mipc_rd_push(r, "galileo_enable");
        if (mipc_rd_u8(r, &out->galileo_enable)) {
            return -1;
        }
        mipc_rd_pop(r);
    }
    if (r->pos < r->len) {
        out->has_beidou_enable = true;
        mipc_rd_push(r, "beidou_enable");
        if (mipc_rd_u8(r, &out->beidou_enable)) {
            return -1;
        }
        mipc_rd_pop(r);
    }
    if (r->pos < r->len) {
        out->has_reserved = true;
        mipc_rd_push(r, "reserved");
        for (i = 0; i < 4; i++) {
            mipc_rd_index(r, i);
            if (mipc_rd_u8(r, &out->reserved[i])) {
                return -1;
            }
        }
        mipc_rd_pop(r);
    }
    return mipc_rd_finish(r);
}

static mipc_status_t mipc_gnss_signal_configuration_write(mipc_writer_t *w,
                                                          const mipc_gnss_signal_configuration_t *in) {
    mipc_status_t st;
    size_t i;
    int absent = 0;
    if ((st = mipc_wr_u8(w, &in->function)) != MIPC_OK) {
        return st;
    }
    if (!in->has_gps_enable) {
        absent = 1;
    } else if (absent) {
        return MIPC_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = mipc_wr_u8(w, &in->gps_enable)) != MIPC_OK) {
            return st;
        }
    }
    if (!in->has_glonass_enable) {
        absent = 1;
    } else if (absent) {
        return MIPC_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = mipc_wr_u8(w, &in->glonass_enable)) != MIPC_OK) {
            return st;
        }
    }
    if (!in->has_galileo_enable) {
        absent = 1;
    } else if (absent) {
        return MIPC_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = mipc_wr_u8(w, &in->galileo_enable)) != MIPC_OK) {
            return st;
        }
    }
    if (!in->has_beidou_enable) {
        absent = 1;
    } else if (absent) {
        return MIPC_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = mipc_wr_u8(w, &in->beidou_enable)) != MIPC_OK) {
            return st;
        }
    }
    if (!in->has_reserved) {
        absent = 1;
    } else if (absent) {
        return MIPC_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        for (i = 0; i < 4; i++) {
            if ((st = mipc_wr_u8(w, &in->reserved[i])) != MIPC_OK) {
                return st;
            }
        }
    }
    return MIPC_OK;
}

mipc_status_t mipc_gnss_signal_configuration_encode(const mipc_gnss_signal_configuration_t *value,
                                                    uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mipc_writer_init(&w, buf, cap);
    st = mipc_gnss_signal_configuration_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mipc_status_t mipc_gnss_signal_configuration_decode(const uint8_t *data, size_t len,
                                                    mipc_gnss_signal_configuration_t *out,
                                                    mipc_decode_error_t *err) {
    mipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_gnss_signal_configuration_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

/* ---- mipc_gnss_signal_configuration_response_t */

static int mipc_gnss_signal_configuration_response_read(mipc_reader_t *r,
                                                        mipc_gnss_signal_configuration_response_t *out) {
    size_t i;
    mipc_rd_push(r, "gps_enable");
    if (mipc_rd_u8(r, &out->gps_enable)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "glonass_enable");
    if (mipc_rd_u8(r, &out->glonass_enable)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "galileo_enable");
    if (mipc_rd_u8(r, &out->galileo_enable)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "beidou_enable");
    if (mipc_rd_u8(r, &out->beidou_enable)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "reserved");
    for (i = 0; i < 4; i++) {
        mipc_rd_index(r, i);
        if (mipc_rd_u8(r, &out->reserved[i])) {
            return -1;
        }
    }
    mipc_rd_pop(r);
    return mipc_rd_finish(r);
}

static mipc_status_t
mipc_gnss_signal_configuration_response_write(mipc_writer_t *w,
                                              const mipc_gnss_signal_configuration_response_t *in) {
    mipc_status_t st;
    size_t i;
    if ((st = mipc_wr_u8(w, &in->gps_enable)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u8(w, &in->glonass_enable)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u8(w, &in->galileo_enable)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u8(w, &in->beidou_enable)) != MIPC_OK) {
        return st;
    }
    for (i = 0; i < 4; i++) {
        if ((st = mipc_wr_u8(w, &in->reserved[i])) != MIPC_OK) {
            return st;
        }
    }
    return MIPC_OK;
}

mipc_status_t
mipc_gnss_signal_configuration_response_encode(const mipc_gnss_signal_configuration_response_t *value,
                                               uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mipc_writer_init(&w, buf, cap);
    st = mipc_gnss_signal_configuration_response_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 8 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mipc_gnss_signal_configuration_response_load(const uint8_t *d,
                                                        mipc_gnss_signal_configuration_response_t *out) {
    out->gps_enable = mipc_ld_u8(d + 0);
    out->glonass_enable = mipc_ld_u8(d + 1);
    out->galileo_enable = mipc_ld_u8(d + 2);
    out->beidou_enable = mipc_ld_u8(d + 3);
    out->reserved[0] = mipc_ld_u8(d + 4);
    out->reserved[1] = mipc_ld_u8(d + 5);
    out->reserved[2] = mipc_ld_u8(d + 6);
    out->reserved[3] = mipc_ld_u8(d + 7);
    return 0;
}

/* The general reader: lengths other than 8, bad bool bytes, error details. */
static MIPC_NOINLINE mipc_status_t mipc_gnss_signal_configuration_response_decode_read(
    const uint8_t *data, size_t len, mipc_gnss_signal_configuration_response_t *out,
    mipc_decode_error_t *err) {
    mipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_gnss_signal_configuration_response_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t mipc_gnss_signal_configuration_response_decode(const uint8_t *data, size_t len,
                                                             mipc_gnss_signal_configuration_response_t *out,
                                                             mipc_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 8 && mipc_gnss_signal_configuration_response_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_gnss_signal_configuration_response_decode_read(data, len, out, err);
}

/* ---- mipc_gnss_spartn_configuration_t */

static int mipc_gnss_spartn_configuration_read(mipc_reader_t *r, mipc_gnss_spartn_configuration_t *out) {
    mipc_rd_push(r, "function");
    if (mipc_rd_u8(r, &out->function)) {
        return -1;
    }
    mipc_rd_pop(r);
    if (r->pos < r->len) {
        out->has_enable = true;
        mipc_rd_push(r, "enable");
        if (mipc_rd_u8(r, &out->enable)) {
            return -1;
        }
        mipc_rd_pop(r);
    }
    if (r->pos < r->len) {
        out->has_type = true;
        mipc_rd_push(r, "type");
        if (mipc_rd_u8(r, &out->type)) {
            return -1;
        }
        mipc_rd_pop(r);
    }
    if (r->pos < r->len) {
        out->has_current_key_tow = true;
        mipc_rd_push(r, "current_key_tow");
        if (mipc_rd_u32(r, &out->current_key_tow)) {
            return -1;
        }
        mipc_rd_pop(r);
    }
    if (r->pos < r->len) {
        out->has_current_key_week = true;
        mipc_rd_push(r, "current_key_week");
        if (mipc_rd_u16(r, &out->current_key_week)) {
            return -1;
        }
        mipc_rd_pop(r);
    }
    if (r->pos < r->len) {
        out->has_current_key = true;
        mipc_rd_push(r, "current_key");
        if (mipc_rd_chars(r, out->current_key, 32)) {
            return -1;
        }
        mipc_rd_pop(r);
    }
    if (r->pos < r->len) {
        out->has_next_key_tow = true;
        mipc_rd_push(r, "next_key_tow");
        if (mipc_rd_u32(r, &out->next_key_tow)) {
            return -1;
        }
        mipc_rd_pop(r);
    }
    if (r->pos < r->len) {
        out->has_next_key_week = true;
        mipc_rd_push(r, "next_key_week");
        if (mipc_rd_u16(r, &out->next_key_week)) {
            return -1;
        }
        mipc_rd_pop(r);
    }
    if (r->pos < r->len) {
        out->has_next_key = true;
        mipc_rd_push(r, "next_key");
        if (mipc_rd_chars(r, out->next_key, 32)) {
            return -1;
        }
        mipc_rd_pop(r);
    }
    return mipc_rd_finish(r);
}

static mipc_status_t mipc_gnss_spartn_configuration_write(mipc_writer_t *w,
                                                          const mipc_gnss_spartn_configuration_t *in) {
    mipc_status_t st;
    int absent = 0;
    if ((st = mipc_wr_u8(w, &in->function)) != MIPC_OK) {
        return st;
    }
    if (!in->has_enable) {
        absent = 1;
    } else if (absent) {
        return MIPC_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = mipc_wr_u8(w, &in->enable)) != MIPC_OK) {
            return st;
        }
    }
    if (!in->has_type) {
        absent = 1;
    } else if (absent) {
        return MIPC_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = mipc_wr_u8(w, &in->type)) != MIPC_OK) {
            return st;
        }
    }
    if (!in->has_current_key_tow) {
        absent = 1;
    } else if (absent) {
        return MIPC_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = mipc_wr_u32(w, &in->current_key_tow)) != MIPC_OK) {
            return st;
        }
    }
    if (!in->has_current_key_week) {
        absent = 1;
    } else if (absent) {
        return MIPC_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = mipc_wr_u16(w, &in->current_key_week)) != MIPC_OK) {
            return st;
        }
    }
    if (!in->has_current_key) {
        absent = 1;
    } else if (absent) {
        return MIPC_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = mipc_wr_chars(w, in->current_key, 32)) != MIPC_OK) {
            return st;
        }
    }
    if (!in->has_next_key_tow) {
        absent = 1;
    } else if (absent) {
        return MIPC_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = mipc_wr_u32(w, &in->next_key_tow)) != MIPC_OK) {
            return st;
        }
    }
    if (!in->has_next_key_week) {
        absent = 1;
    } else if (absent) {
        return MIPC_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = mipc_wr_u16(w, &in->next_key_week)) != MIPC_OK) {
            return st;
        }
    }
    if (!in->has_next_key) {
        absent = 1;
    } else if (absent) {
        return MIPC_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = mipc_wr_chars(w, in->next_key, 32)) != MIPC_OK) {
            return st;
        }
    }
    return MIPC_OK;
}

mipc_status_t mipc_gnss_spartn_configuration_encode(const mipc_gnss_spartn_configuration_t *value,
                                                    uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mipc_writer_init(&w, buf, cap);
    st = mipc_gnss_spartn_configuration_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mipc_status_t mipc_gnss_spartn_configuration_decode(const uint8_t *data, size_t len,
                                                    mipc_gnss_spartn_configuration_t *out,
                                                    mipc_decode_error_t *err) {
    mipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_gnss_spartn_configuration_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

/* ---- mipc_gnss_spartn_configuration_response_t */

static int mipc_gnss_spartn_configuration_response_read(mipc_reader_t *r,
                                                        mipc_gnss_spartn_configuration_response_t *out) {
    mipc_rd_push(r, "enable");
    if (mipc_rd_u8(r, &out->enable)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "type");
    if (mipc_rd_u8(r, &out->type)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "current_key_tow");
    if (mipc_rd_u32(r, &out->current_key_tow)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "current_key_week");
    if (mipc_rd_u16(r, &out->current_key_week)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "current_key");
    if (mipc_rd_chars(r, out->current_key, 32)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "next_key_tow");
    if (mipc_rd_u32(r, &out->next_key_tow)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "next_key_week");
    if (mipc_rd_u16(r, &out->next_key_week)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "next_key");
    if (mipc_rd_chars(r, out->next_key, 32)) {
        return -1;
    }
    mipc_rd_pop(r);
    return mipc_rd_finish(r);
}

static mipc_status_t
mipc_gnss_spartn_configuration_response_write(mipc_writer_t *w,
                                              const mipc_gnss_spartn_configuration_response_t *in) {
    mipc_status_t st;
    if ((st = mipc_wr_u8(w, &in->enable)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u8(w, &in->type)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u32(w, &in->current_key_tow)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u16(w, &in->current_key_week)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_chars(w, in->current_key, 32)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u32(w, &in->next_key_tow)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u16(w, &in->next_key_week)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_chars(w, in->next_key, 32)) != MIPC_OK) {
        return st;
    }
    return MIPC_OK;
}

mipc_status_t
mipc_gnss_spartn_configuration_response_encode(const mipc_gnss_spartn_configuration_response_t *value,
                                               uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mipc_writer_init(&w, buf, cap);
    st = mipc_gnss_spartn_configuration_response_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mipc_status_t mipc_gnss_spartn_configuration_response_decode(const uint8_t *data, size_t len,
                                                             mipc_gnss_spartn_configuration_response_t *out,
                                                             mipc_decode_error_t *err) {
    mipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_gnss_spartn_configuration_response_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}
