/* Encoders and decoders of Base Messages. Generated from the spec: do not edit. */
#include "mscipcodec/sets/base.h"
#include "layouts_internal.h"
#include "types_internal.h"

#include <assert.h>
#include <string.h>

/* ---- mscipc_base_ping_t */

static int mscipc_base_ping_read(mscipc_reader_t *r, mscipc_base_ping_t *out) {
    (void)out;
    return mscipc_rd_finish(r);
}

static mscipc_status_t mscipc_base_ping_write(mscipc_writer_t *w, const mscipc_base_ping_t *in) {
    (void)w;
    (void)in;
    return MSCIPC_OK;
}

mscipc_status_t mscipc_base_ping_encode(const mscipc_base_ping_t *value, uint8_t *buf, size_t cap,
                                        size_t *len_out) {
    mscipc_writer_t w;
    mscipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mscipc_writer_init(&w, buf, cap);
    st = mscipc_base_ping_write(&w, value);
    if (st == MSCIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mscipc_status_t mscipc_base_ping_decode(const uint8_t *data, size_t len, mscipc_base_ping_t *out,
                                        mscipc_decode_error_t *err) {
    mscipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mscipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mscipc_base_ping_read(&r, out) ? MSCIPC_ERR_DECODE : MSCIPC_OK;
}

/* ---- mscipc_base_get_device_messages_t */

static int mscipc_base_get_device_messages_read(mscipc_reader_t *r, mscipc_base_get_device_messages_t *out) {
    (void)out;
    return mscipc_rd_finish(r);
}

static mscipc_status_t mscipc_base_get_device_messages_write(mscipc_writer_t *w,
                                                             const mscipc_base_get_device_messages_t *in) {
    (void)w;
    (void)in;
    return MSCIPC_OK;
}

mscipc_status_t mscipc_base_get_device_messages_encode(const mscipc_base_get_device_messages_t *value,
                                                       uint8_t *buf, size_t cap, size_t *len_out) {
    mscipc_writer_t w;
    mscipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mscipc_writer_init(&w, buf, cap);
    st = mscipc_base_get_device_messages_write(&w, value);
    if (st == MSCIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mscipc_status_t mscipc_base_get_device_messages_decode(const uint8_t *data, size_t len,
                                                       mscipc_base_get_device_messages_t *out,
                                                       mscipc_decode_error_t *err) {
    mscipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mscipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mscipc_base_get_device_messages_read(&r, out) ? MSCIPC_ERR_DECODE : MSCIPC_OK;
}

/* ---- mscipc_base_device_messages_t */

static int mscipc_base_device_messages_read(mscipc_reader_t *r, mscipc_base_device_messages_t *out) {
    size_t i;
    size_t n;
    mscipc_rd_push(r, "messages");
    if (mscipc_rd_remaining(r, 2, 126, &n)) {
        return -1;
    }
    for (i = 0; i < n; i++) {
        mscipc_rd_index(r, i);
        if (mscipc_message_id_read(r, &out->messages[i])) {
            return -1;
        }
    }
    out->messages_count = n;
    mscipc_rd_pop(r);
    return mscipc_rd_finish(r);
}

static mscipc_status_t mscipc_base_device_messages_write(mscipc_writer_t *w,
                                                         const mscipc_base_device_messages_t *in) {
    mscipc_status_t st;
    size_t i;
    if (in->messages_count > 126) {
        return MSCIPC_ERR_INVALID;
    }
    for (i = 0; i < (size_t)in->messages_count; i++) {
        if ((st = mscipc_message_id_write(w, &in->messages[i])) != MSCIPC_OK) {
            return st;
        }
    }
    return MSCIPC_OK;
}

mscipc_status_t mscipc_base_device_messages_encode(const mscipc_base_device_messages_t *value, uint8_t *buf,
                                                   size_t cap, size_t *len_out) {
    mscipc_writer_t w;
    mscipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mscipc_writer_init(&w, buf, cap);
    st = mscipc_base_device_messages_write(&w, value);
    if (st == MSCIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mscipc_status_t mscipc_base_device_messages_decode(const uint8_t *data, size_t len,
                                                   mscipc_base_device_messages_t *out,
                                                   mscipc_decode_error_t *err) {
    mscipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mscipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mscipc_base_device_messages_read(&r, out) ? MSCIPC_ERR_DECODE : MSCIPC_OK;
}

/* ---- mscipc_base_device_reset_t */

static int mscipc_base_device_reset_read(mscipc_reader_t *r, mscipc_base_device_reset_t *out) {
    (void)out;
    return mscipc_rd_finish(r);
}

static mscipc_status_t mscipc_base_device_reset_write(mscipc_writer_t *w,
                                                      const mscipc_base_device_reset_t *in) {
    (void)w;
    (void)in;
    return MSCIPC_OK;
}

mscipc_status_t mscipc_base_device_reset_encode(const mscipc_base_device_reset_t *value, uint8_t *buf,
                                                size_t cap, size_t *len_out) {
    mscipc_writer_t w;
    mscipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mscipc_writer_init(&w, buf, cap);
    st = mscipc_base_device_reset_write(&w, value);
    if (st == MSCIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mscipc_status_t mscipc_base_device_reset_decode(const uint8_t *data, size_t len,
                                                mscipc_base_device_reset_t *out, mscipc_decode_error_t *err) {
    mscipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mscipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mscipc_base_device_reset_read(&r, out) ? MSCIPC_ERR_DECODE : MSCIPC_OK;
}

/* ---- mscipc_base_get_device_model_t */

static int mscipc_base_get_device_model_read(mscipc_reader_t *r, mscipc_base_get_device_model_t *out) {
    (void)out;
    return mscipc_rd_finish(r);
}

static mscipc_status_t mscipc_base_get_device_model_write(mscipc_writer_t *w,
                                                          const mscipc_base_get_device_model_t *in) {
    (void)w;
    (void)in;
    return MSCIPC_OK;
}

mscipc_status_t mscipc_base_get_device_model_encode(const mscipc_base_get_device_model_t *value, uint8_t *buf,
                                                    size_t cap, size_t *len_out) {
    mscipc_writer_t w;
    mscipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mscipc_writer_init(&w, buf, cap);
    st = mscipc_base_get_device_model_write(&w, value);
    if (st == MSCIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mscipc_status_t mscipc_base_get_device_model_decode(const uint8_t *data, size_t len,
                                                    mscipc_base_get_device_model_t *out,
                                                    mscipc_decode_error_t *err) {
    mscipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mscipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mscipc_base_get_device_model_read(&r, out) ? MSCIPC_ERR_DECODE : MSCIPC_OK;
}

/* ---- mscipc_base_device_model_t */

static int mscipc_base_device_model_read(mscipc_reader_t *r, mscipc_base_device_model_t *out) {
    mscipc_rd_push(r, "model");
    if (mscipc_rd_chars(r, out->model, 16)) {
        return -1;
    }
    mscipc_rd_pop(r);
    return mscipc_rd_finish(r);
}

static mscipc_status_t mscipc_base_device_model_write(mscipc_writer_t *w,
                                                      const mscipc_base_device_model_t *in) {
    mscipc_status_t st;
    if ((st = mscipc_wr_chars(w, in->model, 16)) != MSCIPC_OK) {
        return st;
    }
    return MSCIPC_OK;
}

mscipc_status_t mscipc_base_device_model_encode(const mscipc_base_device_model_t *value, uint8_t *buf,
                                                size_t cap, size_t *len_out) {
    mscipc_writer_t w;
    mscipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mscipc_writer_init(&w, buf, cap);
    st = mscipc_base_device_model_write(&w, value);
    if (st == MSCIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mscipc_status_t mscipc_base_device_model_decode(const uint8_t *data, size_t len,
                                                mscipc_base_device_model_t *out, mscipc_decode_error_t *err) {
    mscipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mscipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mscipc_base_device_model_read(&r, out) ? MSCIPC_ERR_DECODE : MSCIPC_OK;
}

/* ---- mscipc_base_get_device_sn_t */

static int mscipc_base_get_device_sn_read(mscipc_reader_t *r, mscipc_base_get_device_sn_t *out) {
    (void)out;
    return mscipc_rd_finish(r);
}

static mscipc_status_t mscipc_base_get_device_sn_write(mscipc_writer_t *w,
                                                       const mscipc_base_get_device_sn_t *in) {
    (void)w;
    (void)in;
    return MSCIPC_OK;
}

mscipc_status_t mscipc_base_get_device_sn_encode(const mscipc_base_get_device_sn_t *value, uint8_t *buf,
                                                 size_t cap, size_t *len_out) {
    mscipc_writer_t w;
    mscipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mscipc_writer_init(&w, buf, cap);
    st = mscipc_base_get_device_sn_write(&w, value);
    if (st == MSCIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mscipc_status_t mscipc_base_get_device_sn_decode(const uint8_t *data, size_t len,
                                                 mscipc_base_get_device_sn_t *out,
                                                 mscipc_decode_error_t *err) {
    mscipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mscipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mscipc_base_get_device_sn_read(&r, out) ? MSCIPC_ERR_DECODE : MSCIPC_OK;
}

/* ---- mscipc_base_device_sn_t */

static int mscipc_base_device_sn_read(mscipc_reader_t *r, mscipc_base_device_sn_t *out) {
    mscipc_rd_push(r, "serial_number");
    if (mscipc_rd_chars(r, out->serial_number, 16)) {
        return -1;
    }
    mscipc_rd_pop(r);
    return mscipc_rd_finish(r);
}

static mscipc_status_t mscipc_base_device_sn_write(mscipc_writer_t *w, const mscipc_base_device_sn_t *in) {
    mscipc_status_t st;
    if ((st = mscipc_wr_chars(w, in->serial_number, 16)) != MSCIPC_OK) {
        return st;
    }
    return MSCIPC_OK;
}

mscipc_status_t mscipc_base_device_sn_encode(const mscipc_base_device_sn_t *value, uint8_t *buf, size_t cap,
                                             size_t *len_out) {
    mscipc_writer_t w;
    mscipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mscipc_writer_init(&w, buf, cap);
    st = mscipc_base_device_sn_write(&w, value);
    if (st == MSCIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mscipc_status_t mscipc_base_device_sn_decode(const uint8_t *data, size_t len, mscipc_base_device_sn_t *out,
                                             mscipc_decode_error_t *err) {
    mscipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mscipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mscipc_base_device_sn_read(&r, out) ? MSCIPC_ERR_DECODE : MSCIPC_OK;
}

/* ---- mscipc_base_get_device_fw_t */

static int mscipc_base_get_device_fw_read(mscipc_reader_t *r, mscipc_base_get_device_fw_t *out) {
    (void)out;
    return mscipc_rd_finish(r);
}

static mscipc_status_t mscipc_base_get_device_fw_write(mscipc_writer_t *w,
                                                       const mscipc_base_get_device_fw_t *in) {
    (void)w;
    (void)in;
    return MSCIPC_OK;
}

mscipc_status_t mscipc_base_get_device_fw_encode(const mscipc_base_get_device_fw_t *value, uint8_t *buf,
                                                 size_t cap, size_t *len_out) {
    mscipc_writer_t w;
    mscipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mscipc_writer_init(&w, buf, cap);
    st = mscipc_base_get_device_fw_write(&w, value);
    if (st == MSCIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mscipc_status_t mscipc_base_get_device_fw_decode(const uint8_t *data, size_t len,
                                                 mscipc_base_get_device_fw_t *out,
                                                 mscipc_decode_error_t *err) {
    mscipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mscipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mscipc_base_get_device_fw_read(&r, out) ? MSCIPC_ERR_DECODE : MSCIPC_OK;
}

/* ---- mscipc_base_device_fw_t */

static int mscipc_base_device_fw_read(mscipc_reader_t *r, mscipc_base_device_fw_t *out) {
    mscipc_rd_push(r, "firmware");
    if (mscipc_rd_chars(r, out->firmware, 16)) {
        return -1;
    }
    mscipc_rd_pop(r);
    return mscipc_rd_finish(r);
}

static mscipc_status_t mscipc_base_device_fw_write(mscipc_writer_t *w, const mscipc_base_device_fw_t *in) {
    mscipc_status_t st;
    if ((st = mscipc_wr_chars(w, in->firmware, 16)) != MSCIPC_OK) {
        return st;
    }
    return MSCIPC_OK;
}

mscipc_status_t mscipc_base_device_fw_encode(const mscipc_base_device_fw_t *value, uint8_t *buf, size_t cap,
                                             size_t *len_out) {
    mscipc_writer_t w;
    mscipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mscipc_writer_init(&w, buf, cap);
    st = mscipc_base_device_fw_write(&w, value);
    if (st == MSCIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mscipc_status_t mscipc_base_device_fw_decode(const uint8_t *data, size_t len, mscipc_base_device_fw_t *out,
                                             mscipc_decode_error_t *err) {
    mscipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mscipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mscipc_base_device_fw_read(&r, out) ? MSCIPC_ERR_DECODE : MSCIPC_OK;
}

/* ---- mscipc_base_get_device_cal_t */

static int mscipc_base_get_device_cal_read(mscipc_reader_t *r, mscipc_base_get_device_cal_t *out) {
    (void)out;
    return mscipc_rd_finish(r);
}

static mscipc_status_t mscipc_base_get_device_cal_write(mscipc_writer_t *w,
                                                        const mscipc_base_get_device_cal_t *in) {
    (void)w;
    (void)in;
    return MSCIPC_OK;
}

mscipc_status_t mscipc_base_get_device_cal_encode(const mscipc_base_get_device_cal_t *value, uint8_t *buf,
                                                  size_t cap, size_t *len_out) {
    mscipc_writer_t w;
    mscipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mscipc_writer_init(&w, buf, cap);
    st = mscipc_base_get_device_cal_write(&w, value);
    if (st == MSCIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mscipc_status_t mscipc_base_get_device_cal_decode(const uint8_t *data, size_t len,
                                                  mscipc_base_get_device_cal_t *out,
                                                  mscipc_decode_error_t *err) {
    mscipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mscipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mscipc_base_get_device_cal_read(&r, out) ? MSCIPC_ERR_DECODE : MSCIPC_OK;
}

/* ---- mscipc_base_device_cal_t */

static int mscipc_base_device_cal_read(mscipc_reader_t *r, mscipc_base_device_cal_t *out) {
    mscipc_rd_push(r, "date");
    if (mscipc_rd_chars(r, out->date, 16)) {
        return -1;
    }
    mscipc_rd_pop(r);
    return mscipc_rd_finish(r);
}

static mscipc_status_t mscipc_base_device_cal_write(mscipc_writer_t *w, const mscipc_base_device_cal_t *in) {
    mscipc_status_t st;
    if ((st = mscipc_wr_chars(w, in->date, 16)) != MSCIPC_OK) {
        return st;
    }
    return MSCIPC_OK;
}

mscipc_status_t mscipc_base_device_cal_encode(const mscipc_base_device_cal_t *value, uint8_t *buf, size_t cap,
                                              size_t *len_out) {
    mscipc_writer_t w;
    mscipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mscipc_writer_init(&w, buf, cap);
    st = mscipc_base_device_cal_write(&w, value);
    if (st == MSCIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mscipc_status_t mscipc_base_device_cal_decode(const uint8_t *data, size_t len, mscipc_base_device_cal_t *out,
                                              mscipc_decode_error_t *err) {
    mscipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mscipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mscipc_base_device_cal_read(&r, out) ? MSCIPC_ERR_DECODE : MSCIPC_OK;
}

/* ---- mscipc_base_correlate_gps_time_t */

static int mscipc_base_correlate_gps_time_read(mscipc_reader_t *r, mscipc_base_correlate_gps_time_t *out) {
    mscipc_rd_push(r, "week");
    if (mscipc_rd_u16(r, &out->week)) {
        return -1;
    }
    mscipc_rd_pop(r);
    mscipc_rd_push(r, "seconds");
    if (mscipc_rd_u32(r, &out->seconds)) {
        return -1;
    }
    mscipc_rd_pop(r);
    return mscipc_rd_finish(r);
}

static mscipc_status_t mscipc_base_correlate_gps_time_write(mscipc_writer_t *w,
                                                            const mscipc_base_correlate_gps_time_t *in) {
    mscipc_status_t st;
    if ((st = mscipc_wr_u16(w, &in->week)) != MSCIPC_OK) {
        return st;
    }
    if ((st = mscipc_wr_u32(w, &in->seconds)) != MSCIPC_OK) {
        return st;
    }
    return MSCIPC_OK;
}

mscipc_status_t mscipc_base_correlate_gps_time_encode(const mscipc_base_correlate_gps_time_t *value,
                                                      uint8_t *buf, size_t cap, size_t *len_out) {
    mscipc_writer_t w;
    mscipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mscipc_writer_init(&w, buf, cap);
    st = mscipc_base_correlate_gps_time_write(&w, value);
    if (st == MSCIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 6 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mscipc_base_correlate_gps_time_load(const uint8_t *d, mscipc_base_correlate_gps_time_t *out) {
    out->week = mscipc_ld_u16(d + 0);
    out->seconds = mscipc_ld_u32(d + 2);
    return 0;
}

/* The general reader: lengths other than 6, bad bool bytes, error details. */
static MSCIPC_NOINLINE mscipc_status_t mscipc_base_correlate_gps_time_decode_read(
    const uint8_t *data, size_t len, mscipc_base_correlate_gps_time_t *out, mscipc_decode_error_t *err) {
    mscipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mscipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mscipc_base_correlate_gps_time_read(&r, out) ? MSCIPC_ERR_DECODE : MSCIPC_OK;
}

mscipc_status_t mscipc_base_correlate_gps_time_decode(const uint8_t *data, size_t len,
                                                      mscipc_base_correlate_gps_time_t *out,
                                                      mscipc_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 6 && mscipc_base_correlate_gps_time_load(data, out) == 0) {
        return MSCIPC_OK;
    }
    return mscipc_base_correlate_gps_time_decode_read(data, len, out, err);
}
