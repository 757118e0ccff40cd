/* Encoders and decoders of Base Command Set. Generated from the spec: do not edit. */
#include "mipcodec/sets/base.h"
#include "layouts_internal.h"
#include "types_internal.h"

#include <assert.h>
#include <string.h>

/* ---- mipc_base_ping_t */

static int mipc_base_ping_read(mipc_reader_t *r, mipc_base_ping_t *out) {
    (void)out;
    return mipc_rd_finish(r);
}

static mipc_status_t mipc_base_ping_write(mipc_writer_t *w, const mipc_base_ping_t *in) {
    (void)w;
    (void)in;
    return MIPC_OK;
}

mipc_status_t mipc_base_ping_encode(const mipc_base_ping_t *value, uint8_t *buf, size_t cap,
                                    size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mipc_writer_init(&w, buf, cap);
    st = mipc_base_ping_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mipc_status_t mipc_base_ping_decode(const uint8_t *data, size_t len, mipc_base_ping_t *out,
                                    mipc_decode_error_t *err) {
    mipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_base_ping_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

/* ---- mipc_base_set_to_idle_t */

static int mipc_base_set_to_idle_read(mipc_reader_t *r, mipc_base_set_to_idle_t *out) {
    (void)out;
    return mipc_rd_finish(r);
}

static mipc_status_t mipc_base_set_to_idle_write(mipc_writer_t *w, const mipc_base_set_to_idle_t *in) {
    (void)w;
    (void)in;
    return MIPC_OK;
}

mipc_status_t mipc_base_set_to_idle_encode(const mipc_base_set_to_idle_t *value, uint8_t *buf, size_t cap,
                                           size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mipc_writer_init(&w, buf, cap);
    st = mipc_base_set_to_idle_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mipc_status_t mipc_base_set_to_idle_decode(const uint8_t *data, size_t len, mipc_base_set_to_idle_t *out,
                                           mipc_decode_error_t *err) {
    mipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_base_set_to_idle_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

/* ---- mipc_base_get_device_info_t */

static int mipc_base_get_device_info_read(mipc_reader_t *r, mipc_base_get_device_info_t *out) {
    (void)out;
    return mipc_rd_finish(r);
}

static mipc_status_t mipc_base_get_device_info_write(mipc_writer_t *w,
                                                     const mipc_base_get_device_info_t *in) {
    (void)w;
    (void)in;
    return MIPC_OK;
}

mipc_status_t mipc_base_get_device_info_encode(const mipc_base_get_device_info_t *value, uint8_t *buf,
                                               size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mipc_writer_init(&w, buf, cap);
    st = mipc_base_get_device_info_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mipc_status_t mipc_base_get_device_info_decode(const uint8_t *data, size_t len,
                                               mipc_base_get_device_info_t *out, mipc_decode_error_t *err) {
    mipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_base_get_device_info_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

/* ---- mipc_base_device_info_t */

static int mipc_base_device_info_read(mipc_reader_t *r, mipc_base_device_info_t *out) {
    mipc_rd_push(r, "info");
    if (mipc_device_info_read(r, &out->info)) {
        return -1;
    }
    mipc_rd_pop(r);
    return mipc_rd_finish(r);
}

static mipc_status_t mipc_base_device_info_write(mipc_writer_t *w, const mipc_base_device_info_t *in) {
    mipc_status_t st;
    if ((st = mipc_device_info_write(w, &in->info)) != MIPC_OK) {
        return st;
    }
    return MIPC_OK;
}

mipc_status_t mipc_base_device_info_encode(const mipc_base_device_info_t *value, uint8_t *buf, size_t cap,
                                           size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mipc_writer_init(&w, buf, cap);
    st = mipc_base_device_info_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mipc_status_t mipc_base_device_info_decode(const uint8_t *data, size_t len, mipc_base_device_info_t *out,
                                           mipc_decode_error_t *err) {
    mipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_base_device_info_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

/* ---- mipc_base_get_device_descriptors_t */

static int mipc_base_get_device_descriptors_read(mipc_reader_t *r, mipc_base_get_device_descriptors_t *out) {
    (void)out;
    return mipc_rd_finish(r);
}

static mipc_status_t mipc_base_get_device_descriptors_write(mipc_writer_t *w,
                                                            const mipc_base_get_device_descriptors_t *in) {
    (void)w;
    (void)in;
    return MIPC_OK;
}

mipc_status_t mipc_base_get_device_descriptors_encode(const mipc_base_get_device_descriptors_t *value,
                                                      uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mipc_writer_init(&w, buf, cap);
    st = mipc_base_get_device_descriptors_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mipc_status_t mipc_base_get_device_descriptors_decode(const uint8_t *data, size_t len,
                                                      mipc_base_get_device_descriptors_t *out,
                                                      mipc_decode_error_t *err) {
    mipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_base_get_device_descriptors_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

/* ---- mipc_base_device_descriptors_t */

static int mipc_base_device_descriptors_read(mipc_reader_t *r, mipc_base_device_descriptors_t *out) {
    size_t i;
    size_t n;
    mipc_rd_push(r, "descriptors");
    if (mipc_rd_remaining(r, 2, 126, &n)) {
        return -1;
    }
    for (i = 0; i < n; i++) {
        mipc_rd_index(r, i);
        if (mipc_rd_u16(r, &out->descriptors[i])) {
            return -1;
        }
    }
    out->descriptors_count = n;
    mipc_rd_pop(r);
    return mipc_rd_finish(r);
}

static mipc_status_t mipc_base_device_descriptors_write(mipc_writer_t *w,
                                                        const mipc_base_device_descriptors_t *in) {
    mipc_status_t st;
    size_t i;
    if (in->descriptors_count > 126) {
        return MIPC_ERR_INVALID;
    }
    for (i = 0; i < (size_t)in->descriptors_count; i++) {
        if ((st = mipc_wr_u16(w, &in->descriptors[i])) != MIPC_OK) {
            return st;
        }
    }
    return MIPC_OK;
}

mipc_status_t mipc_base_device_descriptors_encode(const mipc_base_device_descriptors_t *value, uint8_t *buf,
                                                  size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mipc_writer_init(&w, buf, cap);
    st = mipc_base_device_descriptors_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mipc_status_t mipc_base_device_descriptors_decode(const uint8_t *data, size_t len,
                                                  mipc_base_device_descriptors_t *out,
                                                  mipc_decode_error_t *err) {
    mipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_base_device_descriptors_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

/* ---- mipc_base_built_in_test_t */

static int mipc_base_built_in_test_read(mipc_reader_t *r, mipc_base_built_in_test_t *out) {
    (void)out;
    return mipc_rd_finish(r);
}

static mipc_status_t mipc_base_built_in_test_write(mipc_writer_t *w, const mipc_base_built_in_test_t *in) {
    (void)w;
    (void)in;
    return MIPC_OK;
}

mipc_status_t mipc_base_built_in_test_encode(const mipc_base_built_in_test_t *value, uint8_t *buf, size_t cap,
                                             size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mipc_writer_init(&w, buf, cap);
    st = mipc_base_built_in_test_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mipc_status_t mipc_base_built_in_test_decode(const uint8_t *data, size_t len, mipc_base_built_in_test_t *out,
                                             mipc_decode_error_t *err) {
    mipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_base_built_in_test_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

/* ---- mipc_base_built_in_test_result_gx5_45_t */

static int mipc_base_built_in_test_result_gx5_45_read(mipc_reader_t *r,
                                                      mipc_base_built_in_test_result_gx5_45_t *out) {
    mipc_rd_push(r, "flags");
    if (mipc_rd_u32(r, &out->flags)) {
        return -1;
    }
    mipc_rd_pop(r);
    return mipc_rd_finish(r);
}

static mipc_status_t
mipc_base_built_in_test_result_gx5_45_write(mipc_writer_t *w,
                                            const mipc_base_built_in_test_result_gx5_45_t *in) {
    mipc_status_t st;
    if ((st = mipc_wr_u32(w, &in->flags)) != MIPC_OK) {
        return st;
    }
    return MIPC_OK;
}

mipc_status_t
mipc_base_built_in_test_result_gx5_45_encode(const mipc_base_built_in_test_result_gx5_45_t *value,
                                             uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mipc_writer_init(&w, buf, cap);
    st = mipc_base_built_in_test_result_gx5_45_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 4 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mipc_base_built_in_test_result_gx5_45_load(const uint8_t *d,
                                                      mipc_base_built_in_test_result_gx5_45_t *out) {
    out->flags = mipc_ld_u32(d + 0);
    return 0;
}

/* The general reader: lengths other than 4, bad bool bytes, error details. */
static MIPC_NOINLINE mipc_status_t mipc_base_built_in_test_result_gx5_45_decode_read(
    const uint8_t *data, size_t len, mipc_base_built_in_test_result_gx5_45_t *out, mipc_decode_error_t *err) {
    mipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_base_built_in_test_result_gx5_45_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t mipc_base_built_in_test_result_gx5_45_decode(const uint8_t *data, size_t len,
                                                           mipc_base_built_in_test_result_gx5_45_t *out,
                                                           mipc_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 4 && mipc_base_built_in_test_result_gx5_45_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_base_built_in_test_result_gx5_45_decode_read(data, len, out, err);
}

/* ---- mipc_base_built_in_test_result_cv7_ins_t */

static int mipc_base_built_in_test_result_cv7_ins_read(mipc_reader_t *r,
                                                       mipc_base_built_in_test_result_cv7_ins_t *out) {
    mipc_rd_push(r, "flags");
    if (mipc_rd_u32(r, &out->flags)) {
        return -1;
    }
    mipc_rd_pop(r);
    return mipc_rd_finish(r);
}

static mipc_status_t
mipc_base_built_in_test_result_cv7_ins_write(mipc_writer_t *w,
                                             const mipc_base_built_in_test_result_cv7_ins_t *in) {
    mipc_status_t st;
    if ((st = mipc_wr_u32(w, &in->flags)) != MIPC_OK) {
        return st;
    }
    return MIPC_OK;
}

mipc_status_t
mipc_base_built_in_test_result_cv7_ins_encode(const mipc_base_built_in_test_result_cv7_ins_t *value,
                                              uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mipc_writer_init(&w, buf, cap);
    st = mipc_base_built_in_test_result_cv7_ins_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 4 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mipc_base_built_in_test_result_cv7_ins_load(const uint8_t *d,
                                                       mipc_base_built_in_test_result_cv7_ins_t *out) {
    out->flags = mipc_ld_u32(d + 0);
    return 0;
}

/* The general reader: lengths other than 4, bad bool bytes, error details. */
static MIPC_NOINLINE mipc_status_t mipc_base_built_in_test_result_cv7_ins_decode_read(
    const uint8_t *data, size_t len, mipc_base_built_in_test_result_cv7_ins_t *out,
    mipc_decode_error_t *err) {
    mipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_base_built_in_test_result_cv7_ins_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t mipc_base_built_in_test_result_cv7_ins_decode(const uint8_t *data, size_t len,
                                                            mipc_base_built_in_test_result_cv7_ins_t *out,
                                                            mipc_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 4 && mipc_base_built_in_test_result_cv7_ins_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_base_built_in_test_result_cv7_ins_decode_read(data, len, out, err);
}

/* ---- mipc_base_resume_t */

static int mipc_base_resume_read(mipc_reader_t *r, mipc_base_resume_t *out) {
    (void)out;
    return mipc_rd_finish(r);
}

static mipc_status_t mipc_base_resume_write(mipc_writer_t *w, const mipc_base_resume_t *in) {
    (void)w;
    (void)in;
    return MIPC_OK;
}

mipc_status_t mipc_base_resume_encode(const mipc_base_resume_t *value, uint8_t *buf, size_t cap,
                                      size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mipc_writer_init(&w, buf, cap);
    st = mipc_base_resume_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mipc_status_t mipc_base_resume_decode(const uint8_t *data, size_t len, mipc_base_resume_t *out,
                                      mipc_decode_error_t *err) {
    mipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_base_resume_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

/* ---- mipc_base_get_extended_descriptors_t */

static int mipc_base_get_extended_descriptors_read(mipc_reader_t *r,
                                                   mipc_base_get_extended_descriptors_t *out) {
    (void)out;
    return mipc_rd_finish(r);
}

static mipc_status_t
mipc_base_get_extended_descriptors_write(mipc_writer_t *w, const mipc_base_get_extended_descriptors_t *in) {
    (void)w;
    (void)in;
    return MIPC_OK;
}

mipc_status_t mipc_base_get_extended_descriptors_encode(const mipc_base_get_extended_descriptors_t *value,
                                                        uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mipc_writer_init(&w, buf, cap);
    st = mipc_base_get_extended_descriptors_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mipc_status_t mipc_base_get_extended_descriptors_decode(const uint8_t *data, size_t len,
                                                        mipc_base_get_extended_descriptors_t *out,
                                                        mipc_decode_error_t *err) {
    mipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_base_get_extended_descriptors_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

/* ---- mipc_base_extended_descriptors_t */

static int mipc_base_extended_descriptors_read(mipc_reader_t *r, mipc_base_extended_descriptors_t *out) {
    size_t i;
    size_t n;
    mipc_rd_push(r, "descriptors");
    if (mipc_rd_remaining(r, 2, 126, &n)) {
        return -1;
    }
    for (i = 0; i < n; i++) {
        mipc_rd_index(r, i);
        if (mipc_rd_u16(r, &out->descriptors[i])) {
            return -1;
        }
    }
    out->descriptors_count = n;
    mipc_rd_pop(r);
    return mipc_rd_finish(r);
}

static mipc_status_t mipc_base_extended_descriptors_write(mipc_writer_t *w,
                                                          const mipc_base_extended_descriptors_t *in) {
    mipc_status_t st;
    size_t i;
    if (in->descriptors_count > 126) {
        return MIPC_ERR_INVALID;
    }
    for (i = 0; i < (size_t)in->descriptors_count; i++) {
        if ((st = mipc_wr_u16(w, &in->descriptors[i])) != MIPC_OK) {
            return st;
        }
    }
    return MIPC_OK;
}

mipc_status_t mipc_base_extended_descriptors_encode(const mipc_base_extended_descriptors_t *value,
                                                    uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mipc_writer_init(&w, buf, cap);
    st = mipc_base_extended_descriptors_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mipc_status_t mipc_base_extended_descriptors_decode(const uint8_t *data, size_t len,
                                                    mipc_base_extended_descriptors_t *out,
                                                    mipc_decode_error_t *err) {
    mipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_base_extended_descriptors_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

/* ---- mipc_base_continuous_bit_t */

static int mipc_base_continuous_bit_read(mipc_reader_t *r, mipc_base_continuous_bit_t *out) {
    (void)out;
    return mipc_rd_finish(r);
}

static mipc_status_t mipc_base_continuous_bit_write(mipc_writer_t *w, const mipc_base_continuous_bit_t *in) {
    (void)w;
    (void)in;
    return MIPC_OK;
}

mipc_status_t mipc_base_continuous_bit_encode(const mipc_base_continuous_bit_t *value, uint8_t *buf,
                                              size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mipc_writer_init(&w, buf, cap);
    st = mipc_base_continuous_bit_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mipc_status_t mipc_base_continuous_bit_decode(const uint8_t *data, size_t len,
                                              mipc_base_continuous_bit_t *out, mipc_decode_error_t *err) {
    mipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_base_continuous_bit_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

/* ---- mipc_base_continuous_bit_result_t */

static int mipc_base_continuous_bit_result_read(mipc_reader_t *r, mipc_base_continuous_bit_result_t *out) {
    mipc_rd_push(r, "result");
    if (mipc_cv7_continuous_bit_read(r, &out->result)) {
        return -1;
    }
    mipc_rd_pop(r);
    return mipc_rd_finish(r);
}

static mipc_status_t mipc_base_continuous_bit_result_write(mipc_writer_t *w,
                                                           const mipc_base_continuous_bit_result_t *in) {
    mipc_status_t st;
    if ((st = mipc_cv7_continuous_bit_write(w, &in->result)) != MIPC_OK) {
        return st;
    }
    return MIPC_OK;
}

mipc_status_t mipc_base_continuous_bit_result_encode(const mipc_base_continuous_bit_result_t *value,
                                                     uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mipc_writer_init(&w, buf, cap);
    st = mipc_base_continuous_bit_result_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mipc_status_t mipc_base_continuous_bit_result_decode(const uint8_t *data, size_t len,
                                                     mipc_base_continuous_bit_result_t *out,
                                                     mipc_decode_error_t *err) {
    mipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_base_continuous_bit_result_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

/* ---- mipc_base_comm_port_speed_t */

static int mipc_base_comm_port_speed_read(mipc_reader_t *r, mipc_base_comm_port_speed_t *out) {
    mipc_rd_push(r, "function");
    if (mipc_rd_u8(r, &out->function)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "port");
    if (mipc_rd_u8(r, &out->port)) {
        return -1;
    }
    mipc_rd_pop(r);
    if (r->pos < r->len) {
        out->has_baud = true;
        mipc_rd_push(r, "baud");
        if (mipc_rd_u32(r, &out->baud)) {
            return -1;
        }
        mipc_rd_pop(r);
    }
    return mipc_rd_finish(r);
}

static mipc_status_t mipc_base_comm_port_speed_write(mipc_writer_t *w,
                                                     const mipc_base_comm_port_speed_t *in) {
    mipc_status_t st;
    int absent = 0;
    if ((st = mipc_wr_u8(w, &in->function)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u8(w, &in->port)) != MIPC_OK) {
        return st;
    }
    if (!in->has_baud) {
        absent = 1;
    } else if (absent) {
        return MIPC_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = mipc_wr_u32(w, &in->baud)) != MIPC_OK) {
            return st;
        }
    }
    return MIPC_OK;
}

mipc_status_t mipc_base_comm_port_speed_encode(const mipc_base_comm_port_speed_t *value, uint8_t *buf,
                                               size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mipc_writer_init(&w, buf, cap);
    st = mipc_base_comm_port_speed_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mipc_status_t mipc_base_comm_port_speed_decode(const uint8_t *data, size_t len,
                                               mipc_base_comm_port_speed_t *out, mipc_decode_error_t *err) {
    mipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_base_comm_port_speed_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

/* ---- mipc_base_comm_port_speed_response_t */

static int mipc_base_comm_port_speed_response_read(mipc_reader_t *r,
                                                   mipc_base_comm_port_speed_response_t *out) {
    mipc_rd_push(r, "port");
    if (mipc_rd_u8(r, &out->port)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "baud");
    if (mipc_rd_u32(r, &out->baud)) {
        return -1;
    }
    mipc_rd_pop(r);
    return mipc_rd_finish(r);
}

static mipc_status_t
mipc_base_comm_port_speed_response_write(mipc_writer_t *w, const mipc_base_comm_port_speed_response_t *in) {
    mipc_status_t st;
    if ((st = mipc_wr_u8(w, &in->port)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u32(w, &in->baud)) != MIPC_OK) {
        return st;
    }
    return MIPC_OK;
}

mipc_status_t mipc_base_comm_port_speed_response_encode(const mipc_base_comm_port_speed_response_t *value,
                                                        uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mipc_writer_init(&w, buf, cap);
    st = mipc_base_comm_port_speed_response_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 5 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mipc_base_comm_port_speed_response_load(const uint8_t *d,
                                                   mipc_base_comm_port_speed_response_t *out) {
    out->port = mipc_ld_u8(d + 0);
    out->baud = mipc_ld_u32(d + 1);
    return 0;
}

/* The general reader: lengths other than 5, bad bool bytes, error details. */
static MIPC_NOINLINE mipc_status_t mipc_base_comm_port_speed_response_decode_read(
    const uint8_t *data, size_t len, mipc_base_comm_port_speed_response_t *out, mipc_decode_error_t *err) {
    mipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_base_comm_port_speed_response_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t mipc_base_comm_port_speed_response_decode(const uint8_t *data, size_t len,
                                                        mipc_base_comm_port_speed_response_t *out,
                                                        mipc_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 5 && mipc_base_comm_port_speed_response_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_base_comm_port_speed_response_decode_read(data, len, out, err);
}

/* ---- mipc_base_gps_time_update_gx5_45_t */

static int mipc_base_gps_time_update_gx5_45_read(mipc_reader_t *r, mipc_base_gps_time_update_gx5_45_t *out) {
    mipc_rd_push(r, "function");
    if (mipc_rd_u8(r, &out->function)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "field_id");
    if (mipc_rd_u8(r, &out->field_id)) {
        return -1;
    }
    mipc_rd_pop(r);
    if (r->pos < r->len) {
        out->has_value = true;
        mipc_rd_push(r, "value");
        if (mipc_rd_u32(r, &out->value)) {
            return -1;
        }
        mipc_rd_pop(r);
    }
    return mipc_rd_finish(r);
}

static mipc_status_t mipc_base_gps_time_update_gx5_45_write(mipc_writer_t *w,
                                                            const mipc_base_gps_time_update_gx5_45_t *in) {
    mipc_status_t st;
    int absent = 0;
    if ((st = mipc_wr_u8(w, &in->function)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u8(w, &in->field_id)) != MIPC_OK) {
        return st;
    }
    if (!in->has_value) {
        absent = 1;
    } else if (absent) {
        return MIPC_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = mipc_wr_u32(w, &in->value)) != MIPC_OK) {
            return st;
        }
    }
    return MIPC_OK;
}

mipc_status_t mipc_base_gps_time_update_gx5_45_encode(const mipc_base_gps_time_update_gx5_45_t *value,
                                                      uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mipc_writer_init(&w, buf, cap);
    st = mipc_base_gps_time_update_gx5_45_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mipc_status_t mipc_base_gps_time_update_gx5_45_decode(const uint8_t *data, size_t len,
                                                      mipc_base_gps_time_update_gx5_45_t *out,
                                                      mipc_decode_error_t *err) {
    mipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_base_gps_time_update_gx5_45_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

/* ---- mipc_base_gps_time_update_cv7_ins_t */

static int mipc_base_gps_time_update_cv7_ins_read(mipc_reader_t *r,
                                                  mipc_base_gps_time_update_cv7_ins_t *out) {
    mipc_rd_push(r, "function");
    if (mipc_rd_u8(r, &out->function)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "field_id");
    if (mipc_rd_u8(r, &out->field_id)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "value");
    if (mipc_rd_u32(r, &out->value)) {
        return -1;
    }
    mipc_rd_pop(r);
    return mipc_rd_finish(r);
}

static mipc_status_t mipc_base_gps_time_update_cv7_ins_write(mipc_writer_t *w,
                                                             const mipc_base_gps_time_update_cv7_ins_t *in) {
    mipc_status_t st;
    if ((st = mipc_wr_u8(w, &in->function)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u8(w, &in->field_id)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u32(w, &in->value)) != MIPC_OK) {
        return st;
    }
    return MIPC_OK;
}

mipc_status_t mipc_base_gps_time_update_cv7_ins_encode(const mipc_base_gps_time_update_cv7_ins_t *value,
                                                       uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mipc_writer_init(&w, buf, cap);
    st = mipc_base_gps_time_update_cv7_ins_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 6 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mipc_base_gps_time_update_cv7_ins_load(const uint8_t *d,
                                                  mipc_base_gps_time_update_cv7_ins_t *out) {
    out->function = mipc_ld_u8(d + 0);
    out->field_id = mipc_ld_u8(d + 1);
    out->value = mipc_ld_u32(d + 2);
    return 0;
}

/* The general reader: lengths other than 6, bad bool bytes, error details. */
static MIPC_NOINLINE mipc_status_t mipc_base_gps_time_update_cv7_ins_decode_read(
    const uint8_t *data, size_t len, mipc_base_gps_time_update_cv7_ins_t *out, mipc_decode_error_t *err) {
    mipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_base_gps_time_update_cv7_ins_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t mipc_base_gps_time_update_cv7_ins_decode(const uint8_t *data, size_t len,
                                                       mipc_base_gps_time_update_cv7_ins_t *out,
                                                       mipc_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 6 && mipc_base_gps_time_update_cv7_ins_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_base_gps_time_update_cv7_ins_decode_read(data, len, out, err);
}

/* ---- mipc_base_gps_week_t */

static int mipc_base_gps_week_read(mipc_reader_t *r, mipc_base_gps_week_t *out) {
    mipc_rd_push(r, "week");
    if (mipc_rd_u32(r, &out->week)) {
        return -1;
    }
    mipc_rd_pop(r);
    return mipc_rd_finish(r);
}

static mipc_status_t mipc_base_gps_week_write(mipc_writer_t *w, const mipc_base_gps_week_t *in) {
    mipc_status_t st;
    if ((st = mipc_wr_u32(w, &in->week)) != MIPC_OK) {
        return st;
    }
    return MIPC_OK;
}

mipc_status_t mipc_base_gps_week_encode(const mipc_base_gps_week_t *value, uint8_t *buf, size_t cap,
                                        size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mipc_writer_init(&w, buf, cap);
    st = mipc_base_gps_week_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 4 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mipc_base_gps_week_load(const uint8_t *d, mipc_base_gps_week_t *out) {
    out->week = mipc_ld_u32(d + 0);
    return 0;
}

/* The general reader: lengths other than 4, bad bool bytes, error details. */
static MIPC_NOINLINE mipc_status_t mipc_base_gps_week_decode_read(const uint8_t *data, size_t len,
                                                                  mipc_base_gps_week_t *out,
                                                                  mipc_decode_error_t *err) {
    mipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_base_gps_week_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t mipc_base_gps_week_decode(const uint8_t *data, size_t len, mipc_base_gps_week_t *out,
                                        mipc_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 4 && mipc_base_gps_week_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_base_gps_week_decode_read(data, len, out, err);
}

/* ---- mipc_base_gps_seconds_t */

static int mipc_base_gps_seconds_read(mipc_reader_t *r, mipc_base_gps_seconds_t *out) {
    mipc_rd_push(r, "seconds");
    if (mipc_rd_u32(r, &out->seconds)) {
        return -1;
    }
    mipc_rd_pop(r);
    return mipc_rd_finish(r);
}

static mipc_status_t mipc_base_gps_seconds_write(mipc_writer_t *w, const mipc_base_gps_seconds_t *in) {
    mipc_status_t st;
    if ((st = mipc_wr_u32(w, &in->seconds)) != MIPC_OK) {
        return st;
    }
    return MIPC_OK;
}

mipc_status_t mipc_base_gps_seconds_encode(const mipc_base_gps_seconds_t *value, uint8_t *buf, size_t cap,
                                           size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mipc_writer_init(&w, buf, cap);
    st = mipc_base_gps_seconds_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 4 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mipc_base_gps_seconds_load(const uint8_t *d, mipc_base_gps_seconds_t *out) {
    out->seconds = mipc_ld_u32(d + 0);
    return 0;
}

/* The general reader: lengths other than 4, bad bool bytes, error details. */
static MIPC_NOINLINE mipc_status_t mipc_base_gps_seconds_decode_read(const uint8_t *data, size_t len,
                                                                     mipc_base_gps_seconds_t *out,
                                                                     mipc_decode_error_t *err) {
    mipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_base_gps_seconds_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t mipc_base_gps_seconds_decode(const uint8_t *data, size_t len, mipc_base_gps_seconds_t *out,
                                           mipc_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 4 && mipc_base_gps_seconds_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_base_gps_seconds_decode_read(data, len, out, err);
}

/* ---- mipc_base_device_reset_t */

static int mipc_base_device_reset_read(mipc_reader_t *r, mipc_base_device_reset_t *out) {
    (void)out;
    return mipc_rd_finish(r);
}

static mipc_status_t mipc_base_device_reset_write(mipc_writer_t *w, const mipc_base_device_reset_t *in) {
    (void)w;
    (void)in;
    return MIPC_OK;
}

mipc_status_t mipc_base_device_reset_encode(const mipc_base_device_reset_t *value, uint8_t *buf, size_t cap,
                                            size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mipc_writer_init(&w, buf, cap);
    st = mipc_base_device_reset_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mipc_status_t mipc_base_device_reset_decode(const uint8_t *data, size_t len, mipc_base_device_reset_t *out,
                                            mipc_decode_error_t *err) {
    mipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_base_device_reset_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}
