/* Encoders and decoders of IMU Configuration Messages. Generated from the spec: do not edit. */
#include "mscipcodec/sets/imu_config.h"
#include "layouts_internal.h"
#include "types_internal.h"

#include <assert.h>
#include <string.h>

/* ---- mscipc_imu_config_uart_baud_rate_t */

static int mscipc_imu_config_uart_baud_rate_read(mscipc_reader_t *r,
                                                 mscipc_imu_config_uart_baud_rate_t *out) {
    mscipc_rd_push(r, "function");
    if (mscipc_rd_u8(r, &out->function)) {
        return -1;
    }
    mscipc_rd_pop(r);
    if (r->pos < r->len) {
        out->has_baud_rate = true;
        mscipc_rd_push(r, "baud_rate");
        if (mscipc_rd_u32(r, &out->baud_rate)) {
            return -1;
        }
        mscipc_rd_pop(r);
    }
    return mscipc_rd_finish(r);
}

static mscipc_status_t mscipc_imu_config_uart_baud_rate_write(mscipc_writer_t *w,
                                                              const mscipc_imu_config_uart_baud_rate_t *in) {
    mscipc_status_t st;
    int absent = 0;
    if ((st = mscipc_wr_u8(w, &in->function)) != MSCIPC_OK) {
        return st;
    }
    if (!in->has_baud_rate) {
        absent = 1;
    } else if (absent) {
        return MSCIPC_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = mscipc_wr_u32(w, &in->baud_rate)) != MSCIPC_OK) {
            return st;
        }
    }
    return MSCIPC_OK;
}

mscipc_status_t mscipc_imu_config_uart_baud_rate_encode(const mscipc_imu_config_uart_baud_rate_t *value,
                                                        uint8_t *buf, size_t cap, size_t *len_out) {
    mscipc_writer_t w;
    mscipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mscipc_writer_init(&w, buf, cap);
    st = mscipc_imu_config_uart_baud_rate_write(&w, value);
    if (st == MSCIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mscipc_status_t mscipc_imu_config_uart_baud_rate_decode(const uint8_t *data, size_t len,
                                                        mscipc_imu_config_uart_baud_rate_t *out,
                                                        mscipc_decode_error_t *err) {
    mscipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mscipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mscipc_imu_config_uart_baud_rate_read(&r, out) ? MSCIPC_ERR_DECODE : MSCIPC_OK;
}

/* ---- mscipc_imu_config_uart_baud_rate_response_t */

static int mscipc_imu_config_uart_baud_rate_response_read(mscipc_reader_t *r,
                                                          mscipc_imu_config_uart_baud_rate_response_t *out) {
    mscipc_rd_push(r, "baud_rate");
    if (mscipc_rd_u32(r, &out->baud_rate)) {
        return -1;
    }
    mscipc_rd_pop(r);
    return mscipc_rd_finish(r);
}

static mscipc_status_t
mscipc_imu_config_uart_baud_rate_response_write(mscipc_writer_t *w,
                                                const mscipc_imu_config_uart_baud_rate_response_t *in) {
    mscipc_status_t st;
    if ((st = mscipc_wr_u32(w, &in->baud_rate)) != MSCIPC_OK) {
        return st;
    }
    return MSCIPC_OK;
}

mscipc_status_t
mscipc_imu_config_uart_baud_rate_response_encode(const mscipc_imu_config_uart_baud_rate_response_t *value,
                                                 uint8_t *buf, size_t cap, size_t *len_out) {
    mscipc_writer_t w;
    mscipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mscipc_writer_init(&w, buf, cap);
    st = mscipc_imu_config_uart_baud_rate_response_write(&w, value);
    if (st == MSCIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 4 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mscipc_imu_config_uart_baud_rate_response_load(const uint8_t *d,
                                                          mscipc_imu_config_uart_baud_rate_response_t *out) {
    out->baud_rate = mscipc_ld_u32(d + 0);
    return 0;
}

/* The general reader: lengths other than 4, bad bool bytes, error details. */
static MSCIPC_NOINLINE mscipc_status_t mscipc_imu_config_uart_baud_rate_response_decode_read(
    const uint8_t *data, size_t len, mscipc_imu_config_uart_baud_rate_response_t *out,
    mscipc_decode_error_t *err) {
    mscipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mscipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mscipc_imu_config_uart_baud_rate_response_read(&r, out) ? MSCIPC_ERR_DECODE : MSCIPC_OK;
}

mscipc_status_t
mscipc_imu_config_uart_baud_rate_response_decode(const uint8_t *data, size_t len,
                                                 mscipc_imu_config_uart_baud_rate_response_t *out,
                                                 mscipc_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 4 && mscipc_imu_config_uart_baud_rate_response_load(data, out) == 0) {
        return MSCIPC_OK;
    }
    return mscipc_imu_config_uart_baud_rate_response_decode_read(data, len, out, err);
}

/* ---- mscipc_imu_config_filter_t */

static int mscipc_imu_config_filter_read(mscipc_reader_t *r, mscipc_imu_config_filter_t *out) {
    mscipc_rd_push(r, "function");
    if (mscipc_rd_u8(r, &out->function)) {
        return -1;
    }
    mscipc_rd_pop(r);
    if (r->pos < r->len) {
        out->has_bandwidth = true;
        mscipc_rd_push(r, "bandwidth");
        if (mscipc_rd_u8(r, &out->bandwidth)) {
            return -1;
        }
        mscipc_rd_pop(r);
    }
    return mscipc_rd_finish(r);
}

static mscipc_status_t mscipc_imu_config_filter_write(mscipc_writer_t *w,
                                                      const mscipc_imu_config_filter_t *in) {
    mscipc_status_t st;
    int absent = 0;
    if ((st = mscipc_wr_u8(w, &in->function)) != MSCIPC_OK) {
        return st;
    }
    if (!in->has_bandwidth) {
        absent = 1;
    } else if (absent) {
        return MSCIPC_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = mscipc_wr_u8(w, &in->bandwidth)) != MSCIPC_OK) {
            return st;
        }
    }
    return MSCIPC_OK;
}

mscipc_status_t mscipc_imu_config_filter_encode(const mscipc_imu_config_filter_t *value, uint8_t *buf,
                                                size_t cap, size_t *len_out) {
    mscipc_writer_t w;
    mscipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mscipc_writer_init(&w, buf, cap);
    st = mscipc_imu_config_filter_write(&w, value);
    if (st == MSCIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mscipc_status_t mscipc_imu_config_filter_decode(const uint8_t *data, size_t len,
                                                mscipc_imu_config_filter_t *out, mscipc_decode_error_t *err) {
    mscipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mscipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mscipc_imu_config_filter_read(&r, out) ? MSCIPC_ERR_DECODE : MSCIPC_OK;
}

/* ---- mscipc_imu_config_filter_response_t */

static int mscipc_imu_config_filter_response_read(mscipc_reader_t *r,
                                                  mscipc_imu_config_filter_response_t *out) {
    mscipc_rd_push(r, "bandwidth");
    if (mscipc_rd_u8(r, &out->bandwidth)) {
        return -1;
    }
    mscipc_rd_pop(r);
    return mscipc_rd_finish(r);
}

static mscipc_status_t
mscipc_imu_config_filter_response_write(mscipc_writer_t *w, const mscipc_imu_config_filter_response_t *in) {
    mscipc_status_t st;
    if ((st = mscipc_wr_u8(w, &in->bandwidth)) != MSCIPC_OK) {
        return st;
    }
    return MSCIPC_OK;
}

mscipc_status_t mscipc_imu_config_filter_response_encode(const mscipc_imu_config_filter_response_t *value,
                                                         uint8_t *buf, size_t cap, size_t *len_out) {
    mscipc_writer_t w;
    mscipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mscipc_writer_init(&w, buf, cap);
    st = mscipc_imu_config_filter_response_write(&w, value);
    if (st == MSCIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 1 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mscipc_imu_config_filter_response_load(const uint8_t *d,
                                                  mscipc_imu_config_filter_response_t *out) {
    out->bandwidth = mscipc_ld_u8(d + 0);
    return 0;
}

/* The general reader: lengths other than 1, bad bool bytes, error details. */
static MSCIPC_NOINLINE mscipc_status_t mscipc_imu_config_filter_response_decode_read(
    const uint8_t *data, size_t len, mscipc_imu_config_filter_response_t *out, mscipc_decode_error_t *err) {
    mscipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mscipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mscipc_imu_config_filter_response_read(&r, out) ? MSCIPC_ERR_DECODE : MSCIPC_OK;
}

mscipc_status_t mscipc_imu_config_filter_response_decode(const uint8_t *data, size_t len,
                                                         mscipc_imu_config_filter_response_t *out,
                                                         mscipc_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 1 && mscipc_imu_config_filter_response_load(data, out) == 0) {
        return MSCIPC_OK;
    }
    return mscipc_imu_config_filter_response_decode_read(data, len, out, err);
}

/* ---- mscipc_imu_config_sample_rate_t */

static int mscipc_imu_config_sample_rate_read(mscipc_reader_t *r, mscipc_imu_config_sample_rate_t *out) {
    mscipc_rd_push(r, "function");
    if (mscipc_rd_u8(r, &out->function)) {
        return -1;
    }
    mscipc_rd_pop(r);
    if (r->pos < r->len) {
        out->has_decimation = true;
        mscipc_rd_push(r, "decimation");
        if (mscipc_rd_u16(r, &out->decimation)) {
            return -1;
        }
        mscipc_rd_pop(r);
    }
    return mscipc_rd_finish(r);
}

static mscipc_status_t mscipc_imu_config_sample_rate_write(mscipc_writer_t *w,
                                                           const mscipc_imu_config_sample_rate_t *in) {
    mscipc_status_t st;
    int absent = 0;
    if ((st = mscipc_wr_u8(w, &in->function)) != MSCIPC_OK) {
        return st;
    }
    if (!in->has_decimation) {
        absent = 1;
    } else if (absent) {
        return MSCIPC_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = mscipc_wr_u16(w, &in->decimation)) != MSCIPC_OK) {
            return st;
        }
    }
    return MSCIPC_OK;
}

mscipc_status_t mscipc_imu_config_sample_rate_encode(const mscipc_imu_config_sample_rate_t *value,
                                                     uint8_t *buf, size_t cap, size_t *len_out) {
    mscipc_writer_t w;
    mscipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mscipc_writer_init(&w, buf, cap);
    st = mscipc_imu_config_sample_rate_write(&w, value);
    if (st == MSCIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mscipc_status_t mscipc_imu_config_sample_rate_decode(const uint8_t *data, size_t len,
                                                     mscipc_imu_config_sample_rate_t *out,
                                                     mscipc_decode_error_t *err) {
    mscipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mscipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mscipc_imu_config_sample_rate_read(&r, out) ? MSCIPC_ERR_DECODE : MSCIPC_OK;
}

/* ---- mscipc_imu_config_sample_rate_response_t */

static int mscipc_imu_config_sample_rate_response_read(mscipc_reader_t *r,
                                                       mscipc_imu_config_sample_rate_response_t *out) {
    mscipc_rd_push(r, "decimation");
    if (mscipc_rd_u16(r, &out->decimation)) {
        return -1;
    }
    mscipc_rd_pop(r);
    return mscipc_rd_finish(r);
}

static mscipc_status_t
mscipc_imu_config_sample_rate_response_write(mscipc_writer_t *w,
                                             const mscipc_imu_config_sample_rate_response_t *in) {
    mscipc_status_t st;
    if ((st = mscipc_wr_u16(w, &in->decimation)) != MSCIPC_OK) {
        return st;
    }
    return MSCIPC_OK;
}

mscipc_status_t
mscipc_imu_config_sample_rate_response_encode(const mscipc_imu_config_sample_rate_response_t *value,
                                              uint8_t *buf, size_t cap, size_t *len_out) {
    mscipc_writer_t w;
    mscipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mscipc_writer_init(&w, buf, cap);
    st = mscipc_imu_config_sample_rate_response_write(&w, value);
    if (st == MSCIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 2 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mscipc_imu_config_sample_rate_response_load(const uint8_t *d,
                                                       mscipc_imu_config_sample_rate_response_t *out) {
    out->decimation = mscipc_ld_u16(d + 0);
    return 0;
}

/* The general reader: lengths other than 2, bad bool bytes, error details. */
static MSCIPC_NOINLINE mscipc_status_t mscipc_imu_config_sample_rate_response_decode_read(
    const uint8_t *data, size_t len, mscipc_imu_config_sample_rate_response_t *out,
    mscipc_decode_error_t *err) {
    mscipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mscipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mscipc_imu_config_sample_rate_response_read(&r, out) ? MSCIPC_ERR_DECODE : MSCIPC_OK;
}

mscipc_status_t mscipc_imu_config_sample_rate_response_decode(const uint8_t *data, size_t len,
                                                              mscipc_imu_config_sample_rate_response_t *out,
                                                              mscipc_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 2 && mscipc_imu_config_sample_rate_response_load(data, out) == 0) {
        return MSCIPC_OK;
    }
    return mscipc_imu_config_sample_rate_response_decode_read(data, len, out, err);
}

/* ---- mscipc_imu_config_select_sensors_t */

static int mscipc_imu_config_select_sensors_read(mscipc_reader_t *r,
                                                 mscipc_imu_config_select_sensors_t *out) {
    size_t i;
    size_t n;
    mscipc_rd_push(r, "function");
    if (mscipc_rd_u8(r, &out->function)) {
        return -1;
    }
    mscipc_rd_pop(r);
    if (r->pos < r->len) {
        out->has_reserved = true;
        mscipc_rd_push(r, "reserved");
        if (mscipc_rd_u8(r, &out->reserved)) {
            return -1;
        }
        mscipc_rd_pop(r);
    }
    if (r->pos < r->len) {
        out->has_sensors = true;
        mscipc_rd_push(r, "sensors");
        if (mscipc_rd_remaining(r, 1, 251, &n)) {
            return -1;
        }
        for (i = 0; i < n; i++) {
            mscipc_rd_index(r, i);
            if (mscipc_rd_u8(r, &out->sensors[i])) {
                return -1;
            }
        }
        out->sensors_count = n;
        mscipc_rd_pop(r);
    }
    return mscipc_rd_finish(r);
}

static mscipc_status_t mscipc_imu_config_select_sensors_write(mscipc_writer_t *w,
                                                              const mscipc_imu_config_select_sensors_t *in) {
    mscipc_status_t st;
    size_t i;
    int absent = 0;
    if ((st = mscipc_wr_u8(w, &in->function)) != MSCIPC_OK) {
        return st;
    }
    if (!in->has_reserved) {
        absent = 1;
    } else if (absent) {
        return MSCIPC_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = mscipc_wr_u8(w, &in->reserved)) != MSCIPC_OK) {
            return st;
        }
    }
    if (!in->has_sensors) {
        absent = 1;
    } else if (absent) {
        return MSCIPC_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if (in->sensors_count > 251) {
            return MSCIPC_ERR_INVALID;
        }
        for (i = 0; i < (size_t)in->sensors_count; i++) {
            if ((st = mscipc_wr_u8(w, &in->sensors[i])) != MSCIPC_OK) {
                return st;
            }
        }
    }
    return MSCIPC_OK;
}

mscipc_status_t mscipc_imu_config_select_sensors_encode(const mscipc_imu_config_select_sensors_t *value,
                                                        uint8_t *buf, size_t cap, size_t *len_out) {
    mscipc_writer_t w;
    mscipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mscipc_writer_init(&w, buf, cap);
    st = mscipc_imu_config_select_sensors_write(&w, value);
    if (st == MSCIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mscipc_status_t mscipc_imu_config_select_sensors_decode(const uint8_t *data, size_t len,
                                                        mscipc_imu_config_select_sensors_t *out,
                                                        mscipc_decode_error_t *err) {
    mscipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mscipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mscipc_imu_config_select_sensors_read(&r, out) ? MSCIPC_ERR_DECODE : MSCIPC_OK;
}

/* ---- mscipc_imu_config_select_sensors_response_t */

static int mscipc_imu_config_select_sensors_response_read(mscipc_reader_t *r,
                                                          mscipc_imu_config_select_sensors_response_t *out) {
    size_t i;
    size_t n;
    mscipc_rd_push(r, "sensors");
    if (mscipc_rd_remaining(r, 1, 253, &n)) {
        return -1;
    }
    for (i = 0; i < n; i++) {
        mscipc_rd_index(r, i);
        if (mscipc_rd_u8(r, &out->sensors[i])) {
            return -1;
        }
    }
    out->sensors_count = n;
    mscipc_rd_pop(r);
    return mscipc_rd_finish(r);
}

static mscipc_status_t
mscipc_imu_config_select_sensors_response_write(mscipc_writer_t *w,
                                                const mscipc_imu_config_select_sensors_response_t *in) {
    mscipc_status_t st;
    size_t i;
    if (in->sensors_count > 253) {
        return MSCIPC_ERR_INVALID;
    }
    for (i = 0; i < (size_t)in->sensors_count; i++) {
        if ((st = mscipc_wr_u8(w, &in->sensors[i])) != MSCIPC_OK) {
            return st;
        }
    }
    return MSCIPC_OK;
}

mscipc_status_t
mscipc_imu_config_select_sensors_response_encode(const mscipc_imu_config_select_sensors_response_t *value,
                                                 uint8_t *buf, size_t cap, size_t *len_out) {
    mscipc_writer_t w;
    mscipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mscipc_writer_init(&w, buf, cap);
    st = mscipc_imu_config_select_sensors_response_write(&w, value);
    if (st == MSCIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mscipc_status_t
mscipc_imu_config_select_sensors_response_decode(const uint8_t *data, size_t len,
                                                 mscipc_imu_config_select_sensors_response_t *out,
                                                 mscipc_decode_error_t *err) {
    mscipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mscipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mscipc_imu_config_select_sensors_response_read(&r, out) ? MSCIPC_ERR_DECODE : MSCIPC_OK;
}

/* ---- mscipc_imu_config_get_internal_sample_rate_t */

static int
mscipc_imu_config_get_internal_sample_rate_read(mscipc_reader_t *r,
                                                mscipc_imu_config_get_internal_sample_rate_t *out) {
    (void)out;
    return mscipc_rd_finish(r);
}

static mscipc_status_t
mscipc_imu_config_get_internal_sample_rate_write(mscipc_writer_t *w,
                                                 const mscipc_imu_config_get_internal_sample_rate_t *in) {
    (void)w;
    (void)in;
    return MSCIPC_OK;
}

mscipc_status_t
mscipc_imu_config_get_internal_sample_rate_encode(const mscipc_imu_config_get_internal_sample_rate_t *value,
                                                  uint8_t *buf, size_t cap, size_t *len_out) {
    mscipc_writer_t w;
    mscipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mscipc_writer_init(&w, buf, cap);
    st = mscipc_imu_config_get_internal_sample_rate_write(&w, value);
    if (st == MSCIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mscipc_status_t
mscipc_imu_config_get_internal_sample_rate_decode(const uint8_t *data, size_t len,
                                                  mscipc_imu_config_get_internal_sample_rate_t *out,
                                                  mscipc_decode_error_t *err) {
    mscipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mscipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mscipc_imu_config_get_internal_sample_rate_read(&r, out) ? MSCIPC_ERR_DECODE : MSCIPC_OK;
}

/* ---- mscipc_imu_config_internal_sample_rate_t */

static int mscipc_imu_config_internal_sample_rate_read(mscipc_reader_t *r,
                                                       mscipc_imu_config_internal_sample_rate_t *out) {
    mscipc_rd_push(r, "rate");
    if (mscipc_rd_u16(r, &out->rate)) {
        return -1;
    }
    mscipc_rd_pop(r);
    return mscipc_rd_finish(r);
}

static mscipc_status_t
mscipc_imu_config_internal_sample_rate_write(mscipc_writer_t *w,
                                             const mscipc_imu_config_internal_sample_rate_t *in) {
    mscipc_status_t st;
    if ((st = mscipc_wr_u16(w, &in->rate)) != MSCIPC_OK) {
        return st;
    }
    return MSCIPC_OK;
}

mscipc_status_t
mscipc_imu_config_internal_sample_rate_encode(const mscipc_imu_config_internal_sample_rate_t *value,
                                              uint8_t *buf, size_t cap, size_t *len_out) {
    mscipc_writer_t w;
    mscipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mscipc_writer_init(&w, buf, cap);
    st = mscipc_imu_config_internal_sample_rate_write(&w, value);
    if (st == MSCIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 2 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mscipc_imu_config_internal_sample_rate_load(const uint8_t *d,
                                                       mscipc_imu_config_internal_sample_rate_t *out) {
    out->rate = mscipc_ld_u16(d + 0);
    return 0;
}

/* The general reader: lengths other than 2, bad bool bytes, error details. */
static MSCIPC_NOINLINE mscipc_status_t mscipc_imu_config_internal_sample_rate_decode_read(
    const uint8_t *data, size_t len, mscipc_imu_config_internal_sample_rate_t *out,
    mscipc_decode_error_t *err) {
    mscipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mscipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mscipc_imu_config_internal_sample_rate_read(&r, out) ? MSCIPC_ERR_DECODE : MSCIPC_OK;
}

mscipc_status_t mscipc_imu_config_internal_sample_rate_decode(const uint8_t *data, size_t len,
                                                              mscipc_imu_config_internal_sample_rate_t *out,
                                                              mscipc_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 2 && mscipc_imu_config_internal_sample_rate_load(data, out) == 0) {
        return MSCIPC_OK;
    }
    return mscipc_imu_config_internal_sample_rate_decode_read(data, len, out, err);
}

/* ---- mscipc_imu_config_accel_range_t */

static int mscipc_imu_config_accel_range_read(mscipc_reader_t *r, mscipc_imu_config_accel_range_t *out) {
    mscipc_rd_push(r, "function");
    if (mscipc_rd_u8(r, &out->function)) {
        return -1;
    }
    mscipc_rd_pop(r);
    if (r->pos < r->len) {
        out->has_range = true;
        mscipc_rd_push(r, "range");
        if (mscipc_rd_u8(r, &out->range)) {
            return -1;
        }
        mscipc_rd_pop(r);
    }
    return mscipc_rd_finish(r);
}

static mscipc_status_t mscipc_imu_config_accel_range_write(mscipc_writer_t *w,
                                                           const mscipc_imu_config_accel_range_t *in) {
    mscipc_status_t st;
    int absent = 0;
    if ((st = mscipc_wr_u8(w, &in->function)) != MSCIPC_OK) {
        return st;
    }
    if (!in->has_range) {
        absent = 1;
    } else if (absent) {
        return MSCIPC_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = mscipc_wr_u8(w, &in->range)) != MSCIPC_OK) {
            return st;
        }
    }
    return MSCIPC_OK;
}

mscipc_status_t mscipc_imu_config_accel_range_encode(const mscipc_imu_config_accel_range_t *value,
                                                     uint8_t *buf, size_t cap, size_t *len_out) {
    mscipc_writer_t w;
    mscipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mscipc_writer_init(&w, buf, cap);
    st = mscipc_imu_config_accel_range_write(&w, value);
    if (st == MSCIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mscipc_status_t mscipc_imu_config_accel_range_decode(const uint8_t *data, size_t len,
                                                     mscipc_imu_config_accel_range_t *out,
                                                     mscipc_decode_error_t *err) {
    mscipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mscipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mscipc_imu_config_accel_range_read(&r, out) ? MSCIPC_ERR_DECODE : MSCIPC_OK;
}

/* ---- mscipc_imu_config_accel_range_response_t */

static int mscipc_imu_config_accel_range_response_read(mscipc_reader_t *r,
                                                       mscipc_imu_config_accel_range_response_t *out) {
    mscipc_rd_push(r, "range");
    if (mscipc_rd_u8(r, &out->range)) {
        return -1;
    }
    mscipc_rd_pop(r);
    return mscipc_rd_finish(r);
}

static mscipc_status_t
mscipc_imu_config_accel_range_response_write(mscipc_writer_t *w,
                                             const mscipc_imu_config_accel_range_response_t *in) {
    mscipc_status_t st;
    if ((st = mscipc_wr_u8(w, &in->range)) != MSCIPC_OK) {
        return st;
    }
    return MSCIPC_OK;
}

mscipc_status_t
mscipc_imu_config_accel_range_response_encode(const mscipc_imu_config_accel_range_response_t *value,
                                              uint8_t *buf, size_t cap, size_t *len_out) {
    mscipc_writer_t w;
    mscipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mscipc_writer_init(&w, buf, cap);
    st = mscipc_imu_config_accel_range_response_write(&w, value);
    if (st == MSCIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 1 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mscipc_imu_config_accel_range_response_load(const uint8_t *d,
                                                       mscipc_imu_config_accel_range_response_t *out) {
    out->range = mscipc_ld_u8(d + 0);
    return 0;
}

/* The general reader: lengths other than 1, bad bool bytes, error details. */
static MSCIPC_NOINLINE mscipc_status_t mscipc_imu_config_accel_range_response_decode_read(
    const uint8_t *data, size_t len, mscipc_imu_config_accel_range_response_t *out,
    mscipc_decode_error_t *err) {
    mscipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mscipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mscipc_imu_config_accel_range_response_read(&r, out) ? MSCIPC_ERR_DECODE : MSCIPC_OK;
}

mscipc_status_t mscipc_imu_config_accel_range_response_decode(const uint8_t *data, size_t len,
                                                              mscipc_imu_config_accel_range_response_t *out,
                                                              mscipc_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 1 && mscipc_imu_config_accel_range_response_load(data, out) == 0) {
        return MSCIPC_OK;
    }
    return mscipc_imu_config_accel_range_response_decode_read(data, len, out, err);
}

/* ---- mscipc_imu_config_gyro_range_t */

static int mscipc_imu_config_gyro_range_read(mscipc_reader_t *r, mscipc_imu_config_gyro_range_t *out) {
    mscipc_rd_push(r, "function");
    if (mscipc_rd_u8(r, &out->function)) {
        return -1;
    }
    mscipc_rd_pop(r);
    if (r->pos < r->len) {
        out->has_range = true;
        mscipc_rd_push(r, "range");
        if (mscipc_rd_u8(r, &out->range)) {
            return -1;
        }
        mscipc_rd_pop(r);
    }
    return mscipc_rd_finish(r);
}

static mscipc_status_t mscipc_imu_config_gyro_range_write(mscipc_writer_t *w,
                                                          const mscipc_imu_config_gyro_range_t *in) {
    mscipc_status_t st;
    int absent = 0;
    if ((st = mscipc_wr_u8(w, &in->function)) != MSCIPC_OK) {
        return st;
    }
    if (!in->has_range) {
        absent = 1;
    } else if (absent) {
        return MSCIPC_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = mscipc_wr_u8(w, &in->range)) != MSCIPC_OK) {
            return st;
        }
    }
    return MSCIPC_OK;
}

mscipc_status_t mscipc_imu_config_gyro_range_encode(const mscipc_imu_config_gyro_range_t *value, uint8_t *buf,
                                                    size_t cap, size_t *len_out) {
    mscipc_writer_t w;
    mscipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mscipc_writer_init(&w, buf, cap);
    st = mscipc_imu_config_gyro_range_write(&w, value);
    if (st == MSCIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mscipc_status_t mscipc_imu_config_gyro_range_decode(const uint8_t *data, size_t len,
                                                    mscipc_imu_config_gyro_range_t *out,
                                                    mscipc_decode_error_t *err) {
    mscipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mscipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mscipc_imu_config_gyro_range_read(&r, out) ? MSCIPC_ERR_DECODE : MSCIPC_OK;
}

/* ---- mscipc_imu_config_gyro_range_response_t */

static int mscipc_imu_config_gyro_range_response_read(mscipc_reader_t *r,
                                                      mscipc_imu_config_gyro_range_response_t *out) {
    mscipc_rd_push(r, "range");
    if (mscipc_rd_u8(r, &out->range)) {
        return -1;
    }
    mscipc_rd_pop(r);
    return mscipc_rd_finish(r);
}

static mscipc_status_t
mscipc_imu_config_gyro_range_response_write(mscipc_writer_t *w,
                                            const mscipc_imu_config_gyro_range_response_t *in) {
    mscipc_status_t st;
    if ((st = mscipc_wr_u8(w, &in->range)) != MSCIPC_OK) {
        return st;
    }
    return MSCIPC_OK;
}

mscipc_status_t
mscipc_imu_config_gyro_range_response_encode(const mscipc_imu_config_gyro_range_response_t *value,
                                             uint8_t *buf, size_t cap, size_t *len_out) {
    mscipc_writer_t w;
    mscipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mscipc_writer_init(&w, buf, cap);
    st = mscipc_imu_config_gyro_range_response_write(&w, value);
    if (st == MSCIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 1 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mscipc_imu_config_gyro_range_response_load(const uint8_t *d,
                                                      mscipc_imu_config_gyro_range_response_t *out) {
    out->range = mscipc_ld_u8(d + 0);
    return 0;
}

/* The general reader: lengths other than 1, bad bool bytes, error details. */
static MSCIPC_NOINLINE mscipc_status_t mscipc_imu_config_gyro_range_response_decode_read(
    const uint8_t *data, size_t len, mscipc_imu_config_gyro_range_response_t *out,
    mscipc_decode_error_t *err) {
    mscipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mscipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mscipc_imu_config_gyro_range_response_read(&r, out) ? MSCIPC_ERR_DECODE : MSCIPC_OK;
}

mscipc_status_t mscipc_imu_config_gyro_range_response_decode(const uint8_t *data, size_t len,
                                                             mscipc_imu_config_gyro_range_response_t *out,
                                                             mscipc_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 1 && mscipc_imu_config_gyro_range_response_load(data, out) == 0) {
        return MSCIPC_OK;
    }
    return mscipc_imu_config_gyro_range_response_decode_read(data, len, out, err);
}

/* ---- mscipc_imu_config_config_all_t */

static int mscipc_imu_config_config_all_read(mscipc_reader_t *r, mscipc_imu_config_config_all_t *out) {
    mscipc_rd_push(r, "function");
    if (mscipc_rd_u8(r, &out->function)) {
        return -1;
    }
    mscipc_rd_pop(r);
    return mscipc_rd_finish(r);
}

static mscipc_status_t mscipc_imu_config_config_all_write(mscipc_writer_t *w,
                                                          const mscipc_imu_config_config_all_t *in) {
    mscipc_status_t st;
    if ((st = mscipc_wr_u8(w, &in->function)) != MSCIPC_OK) {
        return st;
    }
    return MSCIPC_OK;
}

mscipc_status_t mscipc_imu_config_config_all_encode(const mscipc_imu_config_config_all_t *value, uint8_t *buf,
                                                    size_t cap, size_t *len_out) {
    mscipc_writer_t w;
    mscipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mscipc_writer_init(&w, buf, cap);
    st = mscipc_imu_config_config_all_write(&w, value);
    if (st == MSCIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 1 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mscipc_imu_config_config_all_load(const uint8_t *d, mscipc_imu_config_config_all_t *out) {
    out->function = mscipc_ld_u8(d + 0);
    return 0;
}

/* The general reader: lengths other than 1, bad bool bytes, error details. */
static MSCIPC_NOINLINE mscipc_status_t mscipc_imu_config_config_all_decode_read(
    const uint8_t *data, size_t len, mscipc_imu_config_config_all_t *out, mscipc_decode_error_t *err) {
    mscipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mscipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mscipc_imu_config_config_all_read(&r, out) ? MSCIPC_ERR_DECODE : MSCIPC_OK;
}

mscipc_status_t mscipc_imu_config_config_all_decode(const uint8_t *data, size_t len,
                                                    mscipc_imu_config_config_all_t *out,
                                                    mscipc_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 1 && mscipc_imu_config_config_all_load(data, out) == 0) {
        return MSCIPC_OK;
    }
    return mscipc_imu_config_config_all_decode_read(data, len, out, err);
}

/* ---- mscipc_imu_config_data_on_off_t */

static int mscipc_imu_config_data_on_off_read(mscipc_reader_t *r, mscipc_imu_config_data_on_off_t *out) {
    mscipc_rd_push(r, "function");
    if (mscipc_rd_u8(r, &out->function)) {
        return -1;
    }
    mscipc_rd_pop(r);
    if (r->pos < r->len) {
        out->has_control = true;
        mscipc_rd_push(r, "control");
        if (mscipc_rd_u8(r, &out->control)) {
            return -1;
        }
        mscipc_rd_pop(r);
    }
    return mscipc_rd_finish(r);
}

static mscipc_status_t mscipc_imu_config_data_on_off_write(mscipc_writer_t *w,
                                                           const mscipc_imu_config_data_on_off_t *in) {
    mscipc_status_t st;
    int absent = 0;
    if ((st = mscipc_wr_u8(w, &in->function)) != MSCIPC_OK) {
        return st;
    }
    if (!in->has_control) {
        absent = 1;
    } else if (absent) {
        return MSCIPC_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = mscipc_wr_u8(w, &in->control)) != MSCIPC_OK) {
            return st;
        }
    }
    return MSCIPC_OK;
}

mscipc_status_t mscipc_imu_config_data_on_off_encode(const mscipc_imu_config_data_on_off_t *value,
                                                     uint8_t *buf, size_t cap, size_t *len_out) {
    mscipc_writer_t w;
    mscipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mscipc_writer_init(&w, buf, cap);
    st = mscipc_imu_config_data_on_off_write(&w, value);
    if (st == MSCIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mscipc_status_t mscipc_imu_config_data_on_off_decode(const uint8_t *data, size_t len,
                                                     mscipc_imu_config_data_on_off_t *out,
                                                     mscipc_decode_error_t *err) {
    mscipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mscipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mscipc_imu_config_data_on_off_read(&r, out) ? MSCIPC_ERR_DECODE : MSCIPC_OK;
}

/* ---- mscipc_imu_config_data_on_off_response_t */

static int mscipc_imu_config_data_on_off_response_read(mscipc_reader_t *r,
                                                       mscipc_imu_config_data_on_off_response_t *out) {
    mscipc_rd_push(r, "control");
    if (mscipc_rd_u8(r, &out->control)) {
        return -1;
    }
    mscipc_rd_pop(r);
    return mscipc_rd_finish(r);
}

static mscipc_status_t
mscipc_imu_config_data_on_off_response_write(mscipc_writer_t *w,
                                             const mscipc_imu_config_data_on_off_response_t *in) {
    mscipc_status_t st;
    if ((st = mscipc_wr_u8(w, &in->control)) != MSCIPC_OK) {
        return st;
    }
    return MSCIPC_OK;
}

mscipc_status_t
mscipc_imu_config_data_on_off_response_encode(const mscipc_imu_config_data_on_off_response_t *value,
                                              uint8_t *buf, size_t cap, size_t *len_out) {
    mscipc_writer_t w;
    mscipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mscipc_writer_init(&w, buf, cap);
    st = mscipc_imu_config_data_on_off_response_write(&w, value);
    if (st == MSCIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 1 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mscipc_imu_config_data_on_off_response_load(const uint8_t *d,
                                                       mscipc_imu_config_data_on_off_response_t *out) {
    out->control = mscipc_ld_u8(d + 0);
    return 0;
}

/* The general reader: lengths other than 1, bad bool bytes, error details. */
static MSCIPC_NOINLINE mscipc_status_t mscipc_imu_config_data_on_off_response_decode_read(
    const uint8_t *data, size_t len, mscipc_imu_config_data_on_off_response_t *out,
    mscipc_decode_error_t *err) {
    mscipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mscipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mscipc_imu_config_data_on_off_response_read(&r, out) ? MSCIPC_ERR_DECODE : MSCIPC_OK;
}

mscipc_status_t mscipc_imu_config_data_on_off_response_decode(const uint8_t *data, size_t len,
                                                              mscipc_imu_config_data_on_off_response_t *out,
                                                              mscipc_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 1 && mscipc_imu_config_data_on_off_response_load(data, out) == 0) {
        return MSCIPC_OK;
    }
    return mscipc_imu_config_data_on_off_response_decode_read(data, len, out, err);
}

/* ---- mscipc_imu_config_xtrig_on_off_t */

static int mscipc_imu_config_xtrig_on_off_read(mscipc_reader_t *r, mscipc_imu_config_xtrig_on_off_t *out) {
    mscipc_rd_push(r, "function");
    if (mscipc_rd_u8(r, &out->function)) {
        return -1;
    }
    mscipc_rd_pop(r);
    if (r->pos < r->len) {
        out->has_control = true;
        mscipc_rd_push(r, "control");
        if (mscipc_rd_u8(r, &out->control)) {
            return -1;
        }
        mscipc_rd_pop(r);
    }
    return mscipc_rd_finish(r);
}

static mscipc_status_t mscipc_imu_config_xtrig_on_off_write(mscipc_writer_t *w,
                                                            const mscipc_imu_config_xtrig_on_off_t *in) {
    mscipc_status_t st;
    int absent = 0;
    if ((st = mscipc_wr_u8(w, &in->function)) != MSCIPC_OK) {
        return st;
    }
    if (!in->has_control) {
        absent = 1;
    } else if (absent) {
        return MSCIPC_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = mscipc_wr_u8(w, &in->control)) != MSCIPC_OK) {
            return st;
        }
    }
    return MSCIPC_OK;
}

mscipc_status_t mscipc_imu_config_xtrig_on_off_encode(const mscipc_imu_config_xtrig_on_off_t *value,
                                                      uint8_t *buf, size_t cap, size_t *len_out) {
    mscipc_writer_t w;
    mscipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mscipc_writer_init(&w, buf, cap);
    st = mscipc_imu_config_xtrig_on_off_write(&w, value);
    if (st == MSCIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mscipc_status_t mscipc_imu_config_xtrig_on_off_decode(const uint8_t *data, size_t len,
                                                      mscipc_imu_config_xtrig_on_off_t *out,
                                                      mscipc_decode_error_t *err) {
    mscipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mscipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mscipc_imu_config_xtrig_on_off_read(&r, out) ? MSCIPC_ERR_DECODE : MSCIPC_OK;
}

/* ---- mscipc_imu_config_xtrig_on_off_response_t */

static int mscipc_imu_config_xtrig_on_off_response_read(mscipc_reader_t *r,
                                                        mscipc_imu_config_xtrig_on_off_response_t *out) {
    mscipc_rd_push(r, "control");
    if (mscipc_rd_u8(r, &out->control)) {
        return -1;
    }
    mscipc_rd_pop(r);
    return mscipc_rd_finish(r);
}

static mscipc_status_t
mscipc_imu_config_xtrig_on_off_response_write(mscipc_writer_t *w,
                                              const mscipc_imu_config_xtrig_on_off_response_t *in) {
    mscipc_status_t st;
    if ((st = mscipc_wr_u8(w, &in->control)) != MSCIPC_OK) {
        return st;
    }
    return MSCIPC_OK;
}

mscipc_status_t
mscipc_imu_config_xtrig_on_off_response_encode(const mscipc_imu_config_xtrig_on_off_response_t *value,
                                               uint8_t *buf, size_t cap, size_t *len_out) {
    mscipc_writer_t w;
    mscipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mscipc_writer_init(&w, buf, cap);
    st = mscipc_imu_config_xtrig_on_off_response_write(&w, value);
    if (st == MSCIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 1 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mscipc_imu_config_xtrig_on_off_response_load(const uint8_t *d,
                                                        mscipc_imu_config_xtrig_on_off_response_t *out) {
    out->control = mscipc_ld_u8(d + 0);
    return 0;
}

/* The general reader: lengths other than 1, bad bool bytes, error details. */
static MSCIPC_NOINLINE mscipc_status_t mscipc_imu_config_xtrig_on_off_response_decode_read(
    const uint8_t *data, size_t len, mscipc_imu_config_xtrig_on_off_response_t *out,
    mscipc_decode_error_t *err) {
    mscipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mscipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mscipc_imu_config_xtrig_on_off_response_read(&r, out) ? MSCIPC_ERR_DECODE : MSCIPC_OK;
}

mscipc_status_t mscipc_imu_config_xtrig_on_off_response_decode(const uint8_t *data, size_t len,
                                                               mscipc_imu_config_xtrig_on_off_response_t *out,
                                                               mscipc_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 1 && mscipc_imu_config_xtrig_on_off_response_load(data, out) == 0) {
        return MSCIPC_OK;
    }
    return mscipc_imu_config_xtrig_on_off_response_decode_read(data, len, out, err);
}

/* ---- mscipc_imu_config_select_sensors_rev_b_t */

static int mscipc_imu_config_select_sensors_rev_b_read(mscipc_reader_t *r,
                                                       mscipc_imu_config_select_sensors_rev_b_t *out) {
    size_t i;
    size_t n;
    mscipc_rd_push(r, "function");
    if (mscipc_rd_u8(r, &out->function)) {
        return -1;
    }
    mscipc_rd_pop(r);
    if (r->pos < r->len) {
        out->has_sensors = true;
        mscipc_rd_push(r, "sensors");
        if (mscipc_rd_remaining(r, 1, 252, &n)) {
            return -1;
        }
        for (i = 0; i < n; i++) {
            mscipc_rd_index(r, i);
            if (mscipc_rd_u8(r, &out->sensors[i])) {
                return -1;
            }
        }
        out->sensors_count = n;
        mscipc_rd_pop(r);
    }
    return mscipc_rd_finish(r);
}

static mscipc_status_t
mscipc_imu_config_select_sensors_rev_b_write(mscipc_writer_t *w,
                                             const mscipc_imu_config_select_sensors_rev_b_t *in) {
    mscipc_status_t st;
    size_t i;
    int absent = 0;
    if ((st = mscipc_wr_u8(w, &in->function)) != MSCIPC_OK) {
        return st;
    }
    if (!in->has_sensors) {
        absent = 1;
    } else if (absent) {
        return MSCIPC_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if (in->sensors_count > 252) {
            return MSCIPC_ERR_INVALID;
        }
        for (i = 0; i < (size_t)in->sensors_count; i++) {
            if ((st = mscipc_wr_u8(w, &in->sensors[i])) != MSCIPC_OK) {
                return st;
            }
        }
    }
    return MSCIPC_OK;
}

mscipc_status_t
mscipc_imu_config_select_sensors_rev_b_encode(const mscipc_imu_config_select_sensors_rev_b_t *value,
                                              uint8_t *buf, size_t cap, size_t *len_out) {
    mscipc_writer_t w;
    mscipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mscipc_writer_init(&w, buf, cap);
    st = mscipc_imu_config_select_sensors_rev_b_write(&w, value);
    if (st == MSCIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mscipc_status_t mscipc_imu_config_select_sensors_rev_b_decode(const uint8_t *data, size_t len,
                                                              mscipc_imu_config_select_sensors_rev_b_t *out,
                                                              mscipc_decode_error_t *err) {
    mscipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mscipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mscipc_imu_config_select_sensors_rev_b_read(&r, out) ? MSCIPC_ERR_DECODE : MSCIPC_OK;
}

/* ---- mscipc_imu_config_select_sensors_rev_b_response_t */

static int
mscipc_imu_config_select_sensors_rev_b_response_read(mscipc_reader_t *r,
                                                     mscipc_imu_config_select_sensors_rev_b_response_t *out) {
    size_t i;
    size_t n;
    mscipc_rd_push(r, "sensors");
    if (mscipc_rd_remaining(r, 1, 253, &n)) {
        return -1;
    }
    for (i = 0; i < n; i++) {
        mscipc_rd_index(r, i);
        if (mscipc_rd_u8(r, &out->sensors[i])) {
            return -1;
        }
    }
    out->sensors_count = n;
    mscipc_rd_pop(r);
    return mscipc_rd_finish(r);
}

static mscipc_status_t mscipc_imu_config_select_sensors_rev_b_response_write(
    mscipc_writer_t *w, const mscipc_imu_config_select_sensors_rev_b_response_t *in) {
    mscipc_status_t st;
    size_t i;
    if (in->sensors_count > 253) {
        return MSCIPC_ERR_INVALID;
    }
    for (i = 0; i < (size_t)in->sensors_count; i++) {
        if ((st = mscipc_wr_u8(w, &in->sensors[i])) != MSCIPC_OK) {
            return st;
        }
    }
    return MSCIPC_OK;
}

mscipc_status_t mscipc_imu_config_select_sensors_rev_b_response_encode(
    const mscipc_imu_config_select_sensors_rev_b_response_t *value, uint8_t *buf, size_t cap,
    size_t *len_out) {
    mscipc_writer_t w;
    mscipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mscipc_writer_init(&w, buf, cap);
    st = mscipc_imu_config_select_sensors_rev_b_response_write(&w, value);
    if (st == MSCIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mscipc_status_t
mscipc_imu_config_select_sensors_rev_b_response_decode(const uint8_t *data, size_t len,
                                                       mscipc_imu_config_select_sensors_rev_b_response_t *out,
                                                       mscipc_decode_error_t *err) {
    mscipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mscipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mscipc_imu_config_select_sensors_rev_b_response_read(&r, out) ? MSCIPC_ERR_DECODE : MSCIPC_OK;
}

/* ---- mscipc_imu_config_aux_accel_range_t */

static int mscipc_imu_config_aux_accel_range_read(mscipc_reader_t *r,
                                                  mscipc_imu_config_aux_accel_range_t *out) {
    mscipc_rd_push(r, "function");
    if (mscipc_rd_u8(r, &out->function)) {
        return -1;
    }
    mscipc_rd_pop(r);
    if (r->pos < r->len) {
        out->has_range = true;
        mscipc_rd_push(r, "range");
        if (mscipc_rd_u8(r, &out->range)) {
            return -1;
        }
        mscipc_rd_pop(r);
    }
    return mscipc_rd_finish(r);
}

static mscipc_status_t
mscipc_imu_config_aux_accel_range_write(mscipc_writer_t *w, const mscipc_imu_config_aux_accel_range_t *in) {
    mscipc_status_t st;
    int absent = 0;
    if ((st = mscipc_wr_u8(w, &in->function)) != MSCIPC_OK) {
        return st;
    }
    if (!in->has_range) {
        absent = 1;
    } else if (absent) {
        return MSCIPC_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = mscipc_wr_u8(w, &in->range)) != MSCIPC_OK) {
            return st;
        }
    }
    return MSCIPC_OK;
}

mscipc_status_t mscipc_imu_config_aux_accel_range_encode(const mscipc_imu_config_aux_accel_range_t *value,
                                                         uint8_t *buf, size_t cap, size_t *len_out) {
    mscipc_writer_t w;
    mscipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mscipc_writer_init(&w, buf, cap);
    st = mscipc_imu_config_aux_accel_range_write(&w, value);
    if (st == MSCIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mscipc_status_t mscipc_imu_config_aux_accel_range_decode(const uint8_t *data, size_t len,
                                                         mscipc_imu_config_aux_accel_range_t *out,
                                                         mscipc_decode_error_t *err) {
    mscipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mscipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mscipc_imu_config_aux_accel_range_read(&r, out) ? MSCIPC_ERR_DECODE : MSCIPC_OK;
}

/* ---- mscipc_imu_config_aux_accel_range_response_t */

static int
mscipc_imu_config_aux_accel_range_response_read(mscipc_reader_t *r,
                                                mscipc_imu_config_aux_accel_range_response_t *out) {
    mscipc_rd_push(r, "range");
    if (mscipc_rd_u8(r, &out->range)) {
        return -1;
    }
    mscipc_rd_pop(r);
    return mscipc_rd_finish(r);
}

static mscipc_status_t
mscipc_imu_config_aux_accel_range_response_write(mscipc_writer_t *w,
                                                 const mscipc_imu_config_aux_accel_range_response_t *in) {
    mscipc_status_t st;
    if ((st = mscipc_wr_u8(w, &in->range)) != MSCIPC_OK) {
        return st;
    }
    return MSCIPC_OK;
}

mscipc_status_t
mscipc_imu_config_aux_accel_range_response_encode(const mscipc_imu_config_aux_accel_range_response_t *value,
                                                  uint8_t *buf, size_t cap, size_t *len_out) {
    mscipc_writer_t w;
    mscipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mscipc_writer_init(&w, buf, cap);
    st = mscipc_imu_config_aux_accel_range_response_write(&w, value);
    if (st == MSCIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 1 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int
mscipc_imu_config_aux_accel_range_response_load(const uint8_t *d,
                                                mscipc_imu_config_aux_accel_range_response_t *out) {
    out->range = mscipc_ld_u8(d + 0);
    return 0;
}

/* The general reader: lengths other than 1, bad bool bytes, error details. */
static MSCIPC_NOINLINE mscipc_status_t mscipc_imu_config_aux_accel_range_response_decode_read(
    const uint8_t *data, size_t len, mscipc_imu_config_aux_accel_range_response_t *out,
    mscipc_decode_error_t *err) {
    mscipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mscipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mscipc_imu_config_aux_accel_range_response_read(&r, out) ? MSCIPC_ERR_DECODE : MSCIPC_OK;
}

mscipc_status_t
mscipc_imu_config_aux_accel_range_response_decode(const uint8_t *data, size_t len,
                                                  mscipc_imu_config_aux_accel_range_response_t *out,
                                                  mscipc_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 1 && mscipc_imu_config_aux_accel_range_response_load(data, out) == 0) {
        return MSCIPC_OK;
    }
    return mscipc_imu_config_aux_accel_range_response_decode_read(data, len, out, err);
}
