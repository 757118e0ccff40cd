/* Encoders and decoders of Base Command Set. Generated from the spec: do not edit. */
#include "mipcodec/sets/base.h"
#include "layouts_internal.h"
#include "types_internal.h"

#include <assert.h>
#include <string.h>

/* ---- mip_base_ping_t */

static int mip_base_ping_read(mip_reader_t *r, mip_base_ping_t *out) {
    (void)out;
    return mip_rd_finish(r);
}

static mip_status_t mip_base_ping_write(mip_writer_t *w, const mip_base_ping_t *in) {
    (void)w;
    (void)in;
    return MIP_OK;
}

mip_status_t mip_base_ping_encode(const mip_base_ping_t *value, uint8_t *buf, size_t cap, size_t *len_out) {
    mip_writer_t w;
    mip_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mip_writer_init(&w, buf, cap);
    st = mip_base_ping_write(&w, value);
    if (st == MIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mip_status_t mip_base_ping_decode(const uint8_t *data, size_t len, mip_base_ping_t *out,
                                  mip_decode_error_t *err) {
    mip_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mip_base_ping_read(&r, out) ? MIP_ERR_DECODE : MIP_OK;
}

void mip_base_ping_to_json(mip_jw_t *w, const mip_base_ping_t *in) {
    int first = 1;
    mip_jw_raw(w, "{", 1);
    mip_jw_raw(w, "}", 1);
    (void)in;
    (void)first;
}

int mip_base_ping_from_json(mip_jr_t *jr, size_t pos, mip_base_ping_t *out) {
    memset(out, 0, sizeof *out);
    if (mip_jr_object(jr, pos, NULL, 0)) {
        return -1;
    }
    return 0;
}

/* ---- mip_base_set_to_idle_t */

static int mip_base_set_to_idle_read(mip_reader_t *r, mip_base_set_to_idle_t *out) {
    (void)out;
    return mip_rd_finish(r);
}

static mip_status_t mip_base_set_to_idle_write(mip_writer_t *w, const mip_base_set_to_idle_t *in) {
    (void)w;
    (void)in;
    return MIP_OK;
}

mip_status_t mip_base_set_to_idle_encode(const mip_base_set_to_idle_t *value, uint8_t *buf, size_t cap,
                                         size_t *len_out) {
    mip_writer_t w;
    mip_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mip_writer_init(&w, buf, cap);
    st = mip_base_set_to_idle_write(&w, value);
    if (st == MIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mip_status_t mip_base_set_to_idle_decode(const uint8_t *data, size_t len, mip_base_set_to_idle_t *out,
                                         mip_decode_error_t *err) {
    mip_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mip_base_set_to_idle_read(&r, out) ? MIP_ERR_DECODE : MIP_OK;
}

void mip_base_set_to_idle_to_json(mip_jw_t *w, const mip_base_set_to_idle_t *in) {
    int first = 1;
    mip_jw_raw(w, "{", 1);
    mip_jw_raw(w, "}", 1);
    (void)in;
    (void)first;
}

int mip_base_set_to_idle_from_json(mip_jr_t *jr, size_t pos, mip_base_set_to_idle_t *out) {
    memset(out, 0, sizeof *out);
    if (mip_jr_object(jr, pos, NULL, 0)) {
        return -1;
    }
    return 0;
}

/* ---- mip_base_get_device_info_t */

static int mip_base_get_device_info_read(mip_reader_t *r, mip_base_get_device_info_t *out) {
    (void)out;
    return mip_rd_finish(r);
}

static mip_status_t mip_base_get_device_info_write(mip_writer_t *w, const mip_base_get_device_info_t *in) {
    (void)w;
    (void)in;
    return MIP_OK;
}

mip_status_t mip_base_get_device_info_encode(const mip_base_get_device_info_t *value, uint8_t *buf,
                                             size_t cap, size_t *len_out) {
    mip_writer_t w;
    mip_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mip_writer_init(&w, buf, cap);
    st = mip_base_get_device_info_write(&w, value);
    if (st == MIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mip_status_t mip_base_get_device_info_decode(const uint8_t *data, size_t len, mip_base_get_device_info_t *out,
                                             mip_decode_error_t *err) {
    mip_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mip_base_get_device_info_read(&r, out) ? MIP_ERR_DECODE : MIP_OK;
}

void mip_base_get_device_info_to_json(mip_jw_t *w, const mip_base_get_device_info_t *in) {
    int first = 1;
    mip_jw_raw(w, "{", 1);
    mip_jw_raw(w, "}", 1);
    (void)in;
    (void)first;
}

int mip_base_get_device_info_from_json(mip_jr_t *jr, size_t pos, mip_base_get_device_info_t *out) {
    memset(out, 0, sizeof *out);
    if (mip_jr_object(jr, pos, NULL, 0)) {
        return -1;
    }
    return 0;
}

/* ---- mip_base_device_info_t */

static int mip_base_device_info_read(mip_reader_t *r, mip_base_device_info_t *out) {
    mip_rd_push(r, "info");
    if (mip_device_info_read(r, &out->info)) {
        return -1;
    }
    mip_rd_pop(r);
    return mip_rd_finish(r);
}

static mip_status_t mip_base_device_info_write(mip_writer_t *w, const mip_base_device_info_t *in) {
    mip_status_t st;
    if ((st = mip_device_info_write(w, &in->info)) != MIP_OK) {
        return st;
    }
    return MIP_OK;
}

mip_status_t mip_base_device_info_encode(const mip_base_device_info_t *value, uint8_t *buf, size_t cap,
                                         size_t *len_out) {
    mip_writer_t w;
    mip_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mip_writer_init(&w, buf, cap);
    st = mip_base_device_info_write(&w, value);
    if (st == MIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mip_status_t mip_base_device_info_decode(const uint8_t *data, size_t len, mip_base_device_info_t *out,
                                         mip_decode_error_t *err) {
    mip_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mip_base_device_info_read(&r, out) ? MIP_ERR_DECODE : MIP_OK;
}

void mip_base_device_info_to_json(mip_jw_t *w, const mip_base_device_info_t *in) {
    int first = 1;
    mip_jw_raw(w, "{", 1);
    mip_jw_key(w, &first, "info");
    mip_device_info_to_json(w, &in->info);
    mip_jw_raw(w, "}", 1);
}

int mip_base_device_info_from_json(mip_jr_t *jr, size_t pos, mip_base_device_info_t *out) {
    static const char *const keys[] = {"info"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mip_jr_object(jr, pos, keys, 1)) {
        return -1;
    }
    found = mip_jr_get(jr, pos, "info", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"info\"");
    }
    {
        mip_jr_push(jr, "info");
        if (mip_device_info_from_json(jr, vp, &out->info)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    return 0;
}

/* ---- mip_base_get_device_descriptors_t */

static int mip_base_get_device_descriptors_read(mip_reader_t *r, mip_base_get_device_descriptors_t *out) {
    (void)out;
    return mip_rd_finish(r);
}

static mip_status_t mip_base_get_device_descriptors_write(mip_writer_t *w,
                                                          const mip_base_get_device_descriptors_t *in) {
    (void)w;
    (void)in;
    return MIP_OK;
}

mip_status_t mip_base_get_device_descriptors_encode(const mip_base_get_device_descriptors_t *value,
                                                    uint8_t *buf, size_t cap, size_t *len_out) {
    mip_writer_t w;
    mip_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mip_writer_init(&w, buf, cap);
    st = mip_base_get_device_descriptors_write(&w, value);
    if (st == MIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mip_status_t mip_base_get_device_descriptors_decode(const uint8_t *data, size_t len,
                                                    mip_base_get_device_descriptors_t *out,
                                                    mip_decode_error_t *err) {
    mip_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mip_base_get_device_descriptors_read(&r, out) ? MIP_ERR_DECODE : MIP_OK;
}

void mip_base_get_device_descriptors_to_json(mip_jw_t *w, const mip_base_get_device_descriptors_t *in) {
    int first = 1;
    mip_jw_raw(w, "{", 1);
    mip_jw_raw(w, "}", 1);
    (void)in;
    (void)first;
}

int mip_base_get_device_descriptors_from_json(mip_jr_t *jr, size_t pos,
                                              mip_base_get_device_descriptors_t *out) {
    memset(out, 0, sizeof *out);
    if (mip_jr_object(jr, pos, NULL, 0)) {
        return -1;
    }
    return 0;
}

/* ---- mip_base_device_descriptors_t */

static int mip_base_device_descriptors_read(mip_reader_t *r, mip_base_device_descriptors_t *out) {
    size_t i;
    size_t n;
    mip_rd_push(r, "descriptors");
    if (mip_rd_remaining(r, 2, 126, &n)) {
        return -1;
    }
    for (i = 0; i < n; i++) {
        mip_rd_index(r, i);
        if (mip_rd_u16(r, &out->descriptors[i])) {
            return -1;
        }
    }
    out->descriptors_count = n;
    mip_rd_pop(r);
    return mip_rd_finish(r);
}

static mip_status_t mip_base_device_descriptors_write(mip_writer_t *w,
                                                      const mip_base_device_descriptors_t *in) {
    mip_status_t st;
    size_t i;
    if (in->descriptors_count > 126) {
        return MIP_ERR_INVALID;
    }
    for (i = 0; i < (size_t)in->descriptors_count; i++) {
        if ((st = mip_wr_u16(w, &in->descriptors[i])) != MIP_OK) {
            return st;
        }
    }
    return MIP_OK;
}

mip_status_t mip_base_device_descriptors_encode(const mip_base_device_descriptors_t *value, uint8_t *buf,
                                                size_t cap, size_t *len_out) {
    mip_writer_t w;
    mip_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mip_writer_init(&w, buf, cap);
    st = mip_base_device_descriptors_write(&w, value);
    if (st == MIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mip_status_t mip_base_device_descriptors_decode(const uint8_t *data, size_t len,
                                                mip_base_device_descriptors_t *out, mip_decode_error_t *err) {
    mip_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mip_base_device_descriptors_read(&r, out) ? MIP_ERR_DECODE : MIP_OK;
}

void mip_base_device_descriptors_to_json(mip_jw_t *w, const mip_base_device_descriptors_t *in) {
    int first = 1;
    size_t i;
    mip_jw_raw(w, "{", 1);
    mip_jw_key(w, &first, "descriptors");
    mip_jw_raw(w, "[", 1);
    for (i = 0; i < (size_t)in->descriptors_count && i < 126; i++) {
        mip_jw_sep(w, i);
        mip_jw_u16(w, &in->descriptors[i]);
    }
    mip_jw_raw(w, "]", 1);
    mip_jw_raw(w, "}", 1);
}

int mip_base_device_descriptors_from_json(mip_jr_t *jr, size_t pos, mip_base_device_descriptors_t *out) {
    static const char *const keys[] = {"descriptors"};
    size_t vp = 0;
    int found;
    size_t i;
    size_t it = 0;
    size_t ep = 0;
    memset(out, 0, sizeof *out);
    if (mip_jr_object(jr, pos, keys, 1)) {
        return -1;
    }
    found = mip_jr_get(jr, pos, "descriptors", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"descriptors\"");
    }
    {
        mip_jr_push(jr, "descriptors");
        if (mip_jr_array(jr, vp, &it)) {
            return -1;
        }
        for (i = 0;; i++) {
            int more = mip_jr_next(jr, &it, &ep);
            if (more < 0) {
                return -1;
            }
            if (!more) {
                break;
            }
            if (i >= 126) {
                return mip_jr_fail(jr, "more than 126 elements");
            }
            mip_jr_index(jr, i);
            if (mip_jr_u16(jr, ep, &out->descriptors[i])) {
                return -1;
            }
        }
        mip_jr_index(jr, SIZE_MAX);
        out->descriptors_count = i;
        mip_jr_pop(jr);
    }
    return 0;
}

/* ---- mip_base_built_in_test_t */

static int mip_base_built_in_test_read(mip_reader_t *r, mip_base_built_in_test_t *out) {
    (void)out;
    return mip_rd_finish(r);
}

static mip_status_t mip_base_built_in_test_write(mip_writer_t *w, const mip_base_built_in_test_t *in) {
    (void)w;
    (void)in;
    return MIP_OK;
}

mip_status_t mip_base_built_in_test_encode(const mip_base_built_in_test_t *value, uint8_t *buf, size_t cap,
                                           size_t *len_out) {
    mip_writer_t w;
    mip_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mip_writer_init(&w, buf, cap);
    st = mip_base_built_in_test_write(&w, value);
    if (st == MIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mip_status_t mip_base_built_in_test_decode(const uint8_t *data, size_t len, mip_base_built_in_test_t *out,
                                           mip_decode_error_t *err) {
    mip_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mip_base_built_in_test_read(&r, out) ? MIP_ERR_DECODE : MIP_OK;
}

void mip_base_built_in_test_to_json(mip_jw_t *w, const mip_base_built_in_test_t *in) {
    int first = 1;
    mip_jw_raw(w, "{", 1);
    mip_jw_raw(w, "}", 1);
    (void)in;
    (void)first;
}

int mip_base_built_in_test_from_json(mip_jr_t *jr, size_t pos, mip_base_built_in_test_t *out) {
    memset(out, 0, sizeof *out);
    if (mip_jr_object(jr, pos, NULL, 0)) {
        return -1;
    }
    return 0;
}

/* ---- mip_base_built_in_test_result_gx5_45_t */

static int mip_base_built_in_test_result_gx5_45_read(mip_reader_t *r,
                                                     mip_base_built_in_test_result_gx5_45_t *out) {
    mip_rd_push(r, "flags");
    if (mip_rd_u32(r, &out->flags)) {
        return -1;
    }
    mip_rd_pop(r);
    return mip_rd_finish(r);
}

static mip_status_t
mip_base_built_in_test_result_gx5_45_write(mip_writer_t *w,
                                           const mip_base_built_in_test_result_gx5_45_t *in) {
    mip_status_t st;
    if ((st = mip_wr_u32(w, &in->flags)) != MIP_OK) {
        return st;
    }
    return MIP_OK;
}

mip_status_t mip_base_built_in_test_result_gx5_45_encode(const mip_base_built_in_test_result_gx5_45_t *value,
                                                         uint8_t *buf, size_t cap, size_t *len_out) {
    mip_writer_t w;
    mip_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mip_writer_init(&w, buf, cap);
    st = mip_base_built_in_test_result_gx5_45_write(&w, value);
    if (st == MIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 4 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mip_base_built_in_test_result_gx5_45_load(const uint8_t *d,
                                                     mip_base_built_in_test_result_gx5_45_t *out) {
    out->flags = mip_ld_u32(d + 0);
    return 0;
}

/* The general reader: lengths other than 4, bad bool bytes, error details. */
static MIP_NOINLINE mip_status_t mip_base_built_in_test_result_gx5_45_decode_read(
    const uint8_t *data, size_t len, mip_base_built_in_test_result_gx5_45_t *out, mip_decode_error_t *err) {
    mip_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mip_base_built_in_test_result_gx5_45_read(&r, out) ? MIP_ERR_DECODE : MIP_OK;
}

mip_status_t mip_base_built_in_test_result_gx5_45_decode(const uint8_t *data, size_t len,
                                                         mip_base_built_in_test_result_gx5_45_t *out,
                                                         mip_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 4 && mip_base_built_in_test_result_gx5_45_load(data, out) == 0) {
        return MIP_OK;
    }
    return mip_base_built_in_test_result_gx5_45_decode_read(data, len, out, err);
}

void mip_base_built_in_test_result_gx5_45_to_json(mip_jw_t *w,
                                                  const mip_base_built_in_test_result_gx5_45_t *in) {
    int first = 1;
    mip_jw_raw(w, "{", 1);
    mip_jw_key(w, &first, "flags");
    mip_jw_u32(w, &in->flags);
    mip_jw_raw(w, "}", 1);
}

int mip_base_built_in_test_result_gx5_45_from_json(mip_jr_t *jr, size_t pos,
                                                   mip_base_built_in_test_result_gx5_45_t *out) {
    static const char *const keys[] = {"flags"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mip_jr_object(jr, pos, keys, 1)) {
        return -1;
    }
    found = mip_jr_get(jr, pos, "flags", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"flags\"");
    }
    {
        mip_jr_push(jr, "flags");
        if (mip_jr_u32(jr, vp, &out->flags)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    return 0;
}

/* ---- mip_base_built_in_test_result_cv7_ins_t */

static int mip_base_built_in_test_result_cv7_ins_read(mip_reader_t *r,
                                                      mip_base_built_in_test_result_cv7_ins_t *out) {
    mip_rd_push(r, "flags");
    if (mip_rd_u32(r, &out->flags)) {
        return -1;
    }
    mip_rd_pop(r);
    return mip_rd_finish(r);
}

static mip_status_t
mip_base_built_in_test_result_cv7_ins_write(mip_writer_t *w,
                                            const mip_base_built_in_test_result_cv7_ins_t *in) {
    mip_status_t st;
    if ((st = mip_wr_u32(w, &in->flags)) != MIP_OK) {
        return st;
    }
    return MIP_OK;
}

mip_status_t
mip_base_built_in_test_result_cv7_ins_encode(const mip_base_built_in_test_result_cv7_ins_t *value,
                                             uint8_t *buf, size_t cap, size_t *len_out) {
    mip_writer_t w;
    mip_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mip_writer_init(&w, buf, cap);
    st = mip_base_built_in_test_result_cv7_ins_write(&w, value);
    if (st == MIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 4 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mip_base_built_in_test_result_cv7_ins_load(const uint8_t *d,
                                                      mip_base_built_in_test_result_cv7_ins_t *out) {
    out->flags = mip_ld_u32(d + 0);
    return 0;
}

/* The general reader: lengths other than 4, bad bool bytes, error details. */
static MIP_NOINLINE mip_status_t mip_base_built_in_test_result_cv7_ins_decode_read(
    const uint8_t *data, size_t len, mip_base_built_in_test_result_cv7_ins_t *out, mip_decode_error_t *err) {
    mip_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mip_base_built_in_test_result_cv7_ins_read(&r, out) ? MIP_ERR_DECODE : MIP_OK;
}

mip_status_t mip_base_built_in_test_result_cv7_ins_decode(const uint8_t *data, size_t len,
                                                          mip_base_built_in_test_result_cv7_ins_t *out,
                                                          mip_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 4 && mip_base_built_in_test_result_cv7_ins_load(data, out) == 0) {
        return MIP_OK;
    }
    return mip_base_built_in_test_result_cv7_ins_decode_read(data, len, out, err);
}

void mip_base_built_in_test_result_cv7_ins_to_json(mip_jw_t *w,
                                                   const mip_base_built_in_test_result_cv7_ins_t *in) {
    int first = 1;
    mip_jw_raw(w, "{", 1);
    mip_jw_key(w, &first, "flags");
    mip_jw_u32(w, &in->flags);
    mip_jw_raw(w, "}", 1);
}

int mip_base_built_in_test_result_cv7_ins_from_json(mip_jr_t *jr, size_t pos,
                                                    mip_base_built_in_test_result_cv7_ins_t *out) {
    static const char *const keys[] = {"flags"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mip_jr_object(jr, pos, keys, 1)) {
        return -1;
    }
    found = mip_jr_get(jr, pos, "flags", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"flags\"");
    }
    {
        mip_jr_push(jr, "flags");
        if (mip_jr_u32(jr, vp, &out->flags)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    return 0;
}

/* ---- mip_base_resume_t */

static int mip_base_resume_read(mip_reader_t *r, mip_base_resume_t *out) {
    (void)out;
    return mip_rd_finish(r);
}

static mip_status_t mip_base_resume_write(mip_writer_t *w, const mip_base_resume_t *in) {
    (void)w;
    (void)in;
    return MIP_OK;
}

mip_status_t mip_base_resume_encode(const mip_base_resume_t *value, uint8_t *buf, size_t cap,
                                    size_t *len_out) {
    mip_writer_t w;
    mip_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mip_writer_init(&w, buf, cap);
    st = mip_base_resume_write(&w, value);
    if (st == MIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mip_status_t mip_base_resume_decode(const uint8_t *data, size_t len, mip_base_resume_t *out,
                                    mip_decode_error_t *err) {
    mip_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mip_base_resume_read(&r, out) ? MIP_ERR_DECODE : MIP_OK;
}

void mip_base_resume_to_json(mip_jw_t *w, const mip_base_resume_t *in) {
    int first = 1;
    mip_jw_raw(w, "{", 1);
    mip_jw_raw(w, "}", 1);
    (void)in;
    (void)first;
}

int mip_base_resume_from_json(mip_jr_t *jr, size_t pos, mip_base_resume_t *out) {
    memset(out, 0, sizeof *out);
    if (mip_jr_object(jr, pos, NULL, 0)) {
        return -1;
    }
    return 0;
}

/* ---- mip_base_get_extended_descriptors_t */

static int mip_base_get_extended_descriptors_read(mip_reader_t *r, mip_base_get_extended_descriptors_t *out) {
    (void)out;
    return mip_rd_finish(r);
}

static mip_status_t mip_base_get_extended_descriptors_write(mip_writer_t *w,
                                                            const mip_base_get_extended_descriptors_t *in) {
    (void)w;
    (void)in;
    return MIP_OK;
}

mip_status_t mip_base_get_extended_descriptors_encode(const mip_base_get_extended_descriptors_t *value,
                                                      uint8_t *buf, size_t cap, size_t *len_out) {
    mip_writer_t w;
    mip_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mip_writer_init(&w, buf, cap);
    st = mip_base_get_extended_descriptors_write(&w, value);
    if (st == MIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mip_status_t mip_base_get_extended_descriptors_decode(const uint8_t *data, size_t len,
                                                      mip_base_get_extended_descriptors_t *out,
                                                      mip_decode_error_t *err) {
    mip_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mip_base_get_extended_descriptors_read(&r, out) ? MIP_ERR_DECODE : MIP_OK;
}

void mip_base_get_extended_descriptors_to_json(mip_jw_t *w, const mip_base_get_extended_descriptors_t *in) {
    int first = 1;
    mip_jw_raw(w, "{", 1);
    mip_jw_raw(w, "}", 1);
    (void)in;
    (void)first;
}

int mip_base_get_extended_descriptors_from_json(mip_jr_t *jr, size_t pos,
                                                mip_base_get_extended_descriptors_t *out) {
    memset(out, 0, sizeof *out);
    if (mip_jr_object(jr, pos, NULL, 0)) {
        return -1;
    }
    return 0;
}

/* ---- mip_base_extended_descriptors_t */

static int mip_base_extended_descriptors_read(mip_reader_t *r, mip_base_extended_descriptors_t *out) {
    size_t i;
    size_t n;
    mip_rd_push(r, "descriptors");
    if (mip_rd_remaining(r, 2, 126, &n)) {
        return -1;
    }
    for (i = 0; i < n; i++) {
        mip_rd_index(r, i);
        if (mip_rd_u16(r, &out->descriptors[i])) {
            return -1;
        }
    }
    out->descriptors_count = n;
    mip_rd_pop(r);
    return mip_rd_finish(r);
}

static mip_status_t mip_base_extended_descriptors_write(mip_writer_t *w,
                                                        const mip_base_extended_descriptors_t *in) {
    mip_status_t st;
    size_t i;
    if (in->descriptors_count > 126) {
        return MIP_ERR_INVALID;
    }
    for (i = 0; i < (size_t)in->descriptors_count; i++) {
        if ((st = mip_wr_u16(w, &in->descriptors[i])) != MIP_OK) {
            return st;
        }
    }
    return MIP_OK;
}

mip_status_t mip_base_extended_descriptors_encode(const mip_base_extended_descriptors_t *value, uint8_t *buf,
                                                  size_t cap, size_t *len_out) {
    mip_writer_t w;
    mip_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mip_writer_init(&w, buf, cap);
    st = mip_base_extended_descriptors_write(&w, value);
    if (st == MIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mip_status_t mip_base_extended_descriptors_decode(const uint8_t *data, size_t len,
                                                  mip_base_extended_descriptors_t *out,
                                                  mip_decode_error_t *err) {
    mip_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mip_base_extended_descriptors_read(&r, out) ? MIP_ERR_DECODE : MIP_OK;
}

void mip_base_extended_descriptors_to_json(mip_jw_t *w, const mip_base_extended_descriptors_t *in) {
    int first = 1;
    size_t i;
    mip_jw_raw(w, "{", 1);
    mip_jw_key(w, &first, "descriptors");
    mip_jw_raw(w, "[", 1);
    for (i = 0; i < (size_t)in->descriptors_count && i < 126; i++) {
        mip_jw_sep(w, i);
        mip_jw_u16(w, &in->descriptors[i]);
    }
    mip_jw_raw(w, "]", 1);
    mip_jw_raw(w, "}", 1);
}

int mip_base_extended_descriptors_from_json(mip_jr_t *jr, size_t pos, mip_base_extended_descriptors_t *out) {
    static const char *const keys[] = {"descriptors"};
    size_t vp = 0;
    int found;
    size_t i;
    size_t it = 0;
    size_t ep = 0;
    memset(out, 0, sizeof *out);
    if (mip_jr_object(jr, pos, keys, 1)) {
        return -1;
    }
    found = mip_jr_get(jr, pos, "descriptors", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"descriptors\"");
    }
    {
        mip_jr_push(jr, "descriptors");
        if (mip_jr_array(jr, vp, &it)) {
            return -1;
        }
        for (i = 0;; i++) {
            int more = mip_jr_next(jr, &it, &ep);
            if (more < 0) {
                return -1;
            }
            if (!more) {
                break;
            }
            if (i >= 126) {
                return mip_jr_fail(jr, "more than 126 elements");
            }
            mip_jr_index(jr, i);
            if (mip_jr_u16(jr, ep, &out->descriptors[i])) {
                return -1;
            }
        }
        mip_jr_index(jr, SIZE_MAX);
        out->descriptors_count = i;
        mip_jr_pop(jr);
    }
    return 0;
}

/* ---- mip_base_continuous_bit_t */

static int mip_base_continuous_bit_read(mip_reader_t *r, mip_base_continuous_bit_t *out) {
    (void)out;
    return mip_rd_finish(r);
}

static mip_status_t mip_base_continuous_bit_write(mip_writer_t *w, const mip_base_continuous_bit_t *in) {
    (void)w;
    (void)in;
    return MIP_OK;
}

mip_status_t mip_base_continuous_bit_encode(const mip_base_continuous_bit_t *value, uint8_t *buf, size_t cap,
                                            size_t *len_out) {
    mip_writer_t w;
    mip_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mip_writer_init(&w, buf, cap);
    st = mip_base_continuous_bit_write(&w, value);
    if (st == MIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mip_status_t mip_base_continuous_bit_decode(const uint8_t *data, size_t len, mip_base_continuous_bit_t *out,
                                            mip_decode_error_t *err) {
    mip_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mip_base_continuous_bit_read(&r, out) ? MIP_ERR_DECODE : MIP_OK;
}

void mip_base_continuous_bit_to_json(mip_jw_t *w, const mip_base_continuous_bit_t *in) {
    int first = 1;
    mip_jw_raw(w, "{", 1);
    mip_jw_raw(w, "}", 1);
    (void)in;
    (void)first;
}

int mip_base_continuous_bit_from_json(mip_jr_t *jr, size_t pos, mip_base_continuous_bit_t *out) {
    memset(out, 0, sizeof *out);
    if (mip_jr_object(jr, pos, NULL, 0)) {
        return -1;
    }
    return 0;
}

/* ---- mip_base_continuous_bit_result_t */

static int mip_base_continuous_bit_result_read(mip_reader_t *r, mip_base_continuous_bit_result_t *out) {
    mip_rd_push(r, "result");
    if (mip_cv7_continuous_bit_read(r, &out->result)) {
        return -1;
    }
    mip_rd_pop(r);
    return mip_rd_finish(r);
}

static mip_status_t mip_base_continuous_bit_result_write(mip_writer_t *w,
                                                         const mip_base_continuous_bit_result_t *in) {
    mip_status_t st;
    if ((st = mip_cv7_continuous_bit_write(w, &in->result)) != MIP_OK) {
        return st;
    }
    return MIP_OK;
}

mip_status_t mip_base_continuous_bit_result_encode(const mip_base_continuous_bit_result_t *value,
                                                   uint8_t *buf, size_t cap, size_t *len_out) {
    mip_writer_t w;
    mip_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mip_writer_init(&w, buf, cap);
    st = mip_base_continuous_bit_result_write(&w, value);
    if (st == MIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mip_status_t mip_base_continuous_bit_result_decode(const uint8_t *data, size_t len,
                                                   mip_base_continuous_bit_result_t *out,
                                                   mip_decode_error_t *err) {
    mip_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mip_base_continuous_bit_result_read(&r, out) ? MIP_ERR_DECODE : MIP_OK;
}

void mip_base_continuous_bit_result_to_json(mip_jw_t *w, const mip_base_continuous_bit_result_t *in) {
    int first = 1;
    mip_jw_raw(w, "{", 1);
    mip_jw_key(w, &first, "result");
    mip_cv7_continuous_bit_to_json(w, &in->result);
    mip_jw_raw(w, "}", 1);
}

int mip_base_continuous_bit_result_from_json(mip_jr_t *jr, size_t pos,
                                             mip_base_continuous_bit_result_t *out) {
    static const char *const keys[] = {"result"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mip_jr_object(jr, pos, keys, 1)) {
        return -1;
    }
    found = mip_jr_get(jr, pos, "result", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"result\"");
    }
    {
        mip_jr_push(jr, "result");
        if (mip_cv7_continuous_bit_from_json(jr, vp, &out->result)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    return 0;
}

/* ---- mip_base_comm_port_speed_t */

static int mip_base_comm_port_speed_read(mip_reader_t *r, mip_base_comm_port_speed_t *out) {
    mip_rd_push(r, "function");
    if (mip_rd_u8(r, &out->function)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "port");
    if (mip_rd_u8(r, &out->port)) {
        return -1;
    }
    mip_rd_pop(r);
    if (r->pos < r->len) {
        out->has_baud = true;
        mip_rd_push(r, "baud");
        if (mip_rd_u32(r, &out->baud)) {
            return -1;
        }
        mip_rd_pop(r);
    }
    return mip_rd_finish(r);
}

static mip_status_t mip_base_comm_port_speed_write(mip_writer_t *w, const mip_base_comm_port_speed_t *in) {
    mip_status_t st;
    int absent = 0;
    if ((st = mip_wr_u8(w, &in->function)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_u8(w, &in->port)) != MIP_OK) {
        return st;
    }
    if (!in->has_baud) {
        absent = 1;
    } else if (absent) {
        return MIP_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = mip_wr_u32(w, &in->baud)) != MIP_OK) {
            return st;
        }
    }
    return MIP_OK;
}

mip_status_t mip_base_comm_port_speed_encode(const mip_base_comm_port_speed_t *value, uint8_t *buf,
                                             size_t cap, size_t *len_out) {
    mip_writer_t w;
    mip_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mip_writer_init(&w, buf, cap);
    st = mip_base_comm_port_speed_write(&w, value);
    if (st == MIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mip_status_t mip_base_comm_port_speed_decode(const uint8_t *data, size_t len, mip_base_comm_port_speed_t *out,
                                             mip_decode_error_t *err) {
    mip_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mip_base_comm_port_speed_read(&r, out) ? MIP_ERR_DECODE : MIP_OK;
}

void mip_base_comm_port_speed_to_json(mip_jw_t *w, const mip_base_comm_port_speed_t *in) {
    int first = 1;
    mip_jw_raw(w, "{", 1);
    mip_jw_key(w, &first, "function");
    mip_jw_u8(w, &in->function);
    mip_jw_key(w, &first, "port");
    mip_jw_u8(w, &in->port);
    if (in->has_baud) {
        mip_jw_key(w, &first, "baud");
        mip_jw_u32(w, &in->baud);
    }
    mip_jw_raw(w, "}", 1);
}

int mip_base_comm_port_speed_from_json(mip_jr_t *jr, size_t pos, mip_base_comm_port_speed_t *out) {
    static const char *const keys[] = {"function", "port", "baud"};
    size_t vp = 0;
    int found;
    int absent = 0;
    memset(out, 0, sizeof *out);
    if (mip_jr_object(jr, pos, keys, 3)) {
        return -1;
    }
    found = mip_jr_get(jr, pos, "function", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"function\"");
    }
    {
        mip_jr_push(jr, "function");
        if (mip_jr_u8(jr, vp, &out->function)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "port", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"port\"");
    }
    {
        mip_jr_push(jr, "port");
        if (mip_jr_u8(jr, vp, &out->port)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "baud", &vp);
    out->has_baud = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mip_jr_fail(jr, "optional parameter \"baud\" given after an absent one");
    } else {
        mip_jr_push(jr, "baud");
        if (mip_jr_u32(jr, vp, &out->baud)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    return 0;
}

/* ---- mip_base_comm_port_speed_response_t */

static int mip_base_comm_port_speed_response_read(mip_reader_t *r, mip_base_comm_port_speed_response_t *out) {
    mip_rd_push(r, "port");
    if (mip_rd_u8(r, &out->port)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "baud");
    if (mip_rd_u32(r, &out->baud)) {
        return -1;
    }
    mip_rd_pop(r);
    return mip_rd_finish(r);
}

static mip_status_t mip_base_comm_port_speed_response_write(mip_writer_t *w,
                                                            const mip_base_comm_port_speed_response_t *in) {
    mip_status_t st;
    if ((st = mip_wr_u8(w, &in->port)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_u32(w, &in->baud)) != MIP_OK) {
        return st;
    }
    return MIP_OK;
}

mip_status_t mip_base_comm_port_speed_response_encode(const mip_base_comm_port_speed_response_t *value,
                                                      uint8_t *buf, size_t cap, size_t *len_out) {
    mip_writer_t w;
    mip_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mip_writer_init(&w, buf, cap);
    st = mip_base_comm_port_speed_response_write(&w, value);
    if (st == MIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 5 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mip_base_comm_port_speed_response_load(const uint8_t *d,
                                                  mip_base_comm_port_speed_response_t *out) {
    out->port = mip_ld_u8(d + 0);
    out->baud = mip_ld_u32(d + 1);
    return 0;
}

/* The general reader: lengths other than 5, bad bool bytes, error details. */
static MIP_NOINLINE mip_status_t mip_base_comm_port_speed_response_decode_read(
    const uint8_t *data, size_t len, mip_base_comm_port_speed_response_t *out, mip_decode_error_t *err) {
    mip_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mip_base_comm_port_speed_response_read(&r, out) ? MIP_ERR_DECODE : MIP_OK;
}

mip_status_t mip_base_comm_port_speed_response_decode(const uint8_t *data, size_t len,
                                                      mip_base_comm_port_speed_response_t *out,
                                                      mip_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 5 && mip_base_comm_port_speed_response_load(data, out) == 0) {
        return MIP_OK;
    }
    return mip_base_comm_port_speed_response_decode_read(data, len, out, err);
}

void mip_base_comm_port_speed_response_to_json(mip_jw_t *w, const mip_base_comm_port_speed_response_t *in) {
    int first = 1;
    mip_jw_raw(w, "{", 1);
    mip_jw_key(w, &first, "port");
    mip_jw_u8(w, &in->port);
    mip_jw_key(w, &first, "baud");
    mip_jw_u32(w, &in->baud);
    mip_jw_raw(w, "}", 1);
}

int mip_base_comm_port_speed_response_from_json(mip_jr_t *jr, size_t pos,
                                                mip_base_comm_port_speed_response_t *out) {
    static const char *const keys[] = {"port", "baud"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mip_jr_object(jr, pos, keys, 2)) {
        return -1;
    }
    found = mip_jr_get(jr, pos, "port", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"port\"");
    }
    {
        mip_jr_push(jr, "port");
        if (mip_jr_u8(jr, vp, &out->port)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "baud", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"baud\"");
    }
    {
        mip_jr_push(jr, "baud");
        if (mip_jr_u32(jr, vp, &out->baud)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    return 0;
}

/* ---- mip_base_gps_time_update_gx5_45_t */

static int mip_base_gps_time_update_gx5_45_read(mip_reader_t *r, mip_base_gps_time_update_gx5_45_t *out) {
    mip_rd_push(r, "function");
    if (mip_rd_u8(r, &out->function)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "field_id");
    if (mip_rd_u8(r, &out->field_id)) {
        return -1;
    }
    mip_rd_pop(r);
    if (r->pos < r->len) {
        out->has_value = true;
        mip_rd_push(r, "value");
        if (mip_rd_u32(r, &out->value)) {
            return -1;
        }
        mip_rd_pop(r);
    }
    return mip_rd_finish(r);
}

static mip_status_t mip_base_gps_time_update_gx5_45_write(mip_writer_t *w,
                                                          const mip_base_gps_time_update_gx5_45_t *in) {
    mip_status_t st;
    int absent = 0;
    if ((st = mip_wr_u8(w, &in->function)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_u8(w, &in->field_id)) != MIP_OK) {
        return st;
    }
    if (!in->has_value) {
        absent = 1;
    } else if (absent) {
        return MIP_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = mip_wr_u32(w, &in->value)) != MIP_OK) {
            return st;
        }
    }
    return MIP_OK;
}

mip_status_t mip_base_gps_time_update_gx5_45_encode(const mip_base_gps_time_update_gx5_45_t *value,
                                                    uint8_t *buf, size_t cap, size_t *len_out) {
    mip_writer_t w;
    mip_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mip_writer_init(&w, buf, cap);
    st = mip_base_gps_time_update_gx5_45_write(&w, value);
    if (st == MIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mip_status_t mip_base_gps_time_update_gx5_45_decode(const uint8_t *data, size_t len,
                                                    mip_base_gps_time_update_gx5_45_t *out,
                                                    mip_decode_error_t *err) {
    mip_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mip_base_gps_time_update_gx5_45_read(&r, out) ? MIP_ERR_DECODE : MIP_OK;
}

void mip_base_gps_time_update_gx5_45_to_json(mip_jw_t *w, const mip_base_gps_time_update_gx5_45_t *in) {
    int first = 1;
    mip_jw_raw(w, "{", 1);
    mip_jw_key(w, &first, "function");
    mip_jw_u8(w, &in->function);
    mip_jw_key(w, &first, "field_id");
    mip_jw_u8(w, &in->field_id);
    if (in->has_value) {
        mip_jw_key(w, &first, "value");
        mip_jw_u32(w, &in->value);
    }
    mip_jw_raw(w, "}", 1);
}

int mip_base_gps_time_update_gx5_45_from_json(mip_jr_t *jr, size_t pos,
                                              mip_base_gps_time_update_gx5_45_t *out) {
    static const char *const keys[] = {"function", "field_id", "value"};
    size_t vp = 0;
    int found;
    int absent = 0;
    memset(out, 0, sizeof *out);
    if (mip_jr_object(jr, pos, keys, 3)) {
        return -1;
    }
    found = mip_jr_get(jr, pos, "function", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"function\"");
    }
    {
        mip_jr_push(jr, "function");
        if (mip_jr_u8(jr, vp, &out->function)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "field_id", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"field_id\"");
    }
    {
        mip_jr_push(jr, "field_id");
        if (mip_jr_u8(jr, vp, &out->field_id)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "value", &vp);
    out->has_value = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mip_jr_fail(jr, "optional parameter \"value\" given after an absent one");
    } else {
        mip_jr_push(jr, "value");
        if (mip_jr_u32(jr, vp, &out->value)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    return 0;
}

/* ---- mip_base_gps_time_update_cv7_ins_t */

static int mip_base_gps_time_update_cv7_ins_read(mip_reader_t *r, mip_base_gps_time_update_cv7_ins_t *out) {
    mip_rd_push(r, "function");
    if (mip_rd_u8(r, &out->function)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "field_id");
    if (mip_rd_u8(r, &out->field_id)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "value");
    if (mip_rd_u32(r, &out->value)) {
        return -1;
    }
    mip_rd_pop(r);
    return mip_rd_finish(r);
}

static mip_status_t mip_base_gps_time_update_cv7_ins_write(mip_writer_t *w,
                                                           const mip_base_gps_time_update_cv7_ins_t *in) {
    mip_status_t st;
    if ((st = mip_wr_u8(w, &in->function)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_u8(w, &in->field_id)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_u32(w, &in->value)) != MIP_OK) {
        return st;
    }
    return MIP_OK;
}

mip_status_t mip_base_gps_time_update_cv7_ins_encode(const mip_base_gps_time_update_cv7_ins_t *value,
                                                     uint8_t *buf, size_t cap, size_t *len_out) {
    mip_writer_t w;
    mip_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mip_writer_init(&w, buf, cap);
    st = mip_base_gps_time_update_cv7_ins_write(&w, value);
    if (st == MIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 6 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mip_base_gps_time_update_cv7_ins_load(const uint8_t *d, mip_base_gps_time_update_cv7_ins_t *out) {
    out->function = mip_ld_u8(d + 0);
    out->field_id = mip_ld_u8(d + 1);
    out->value = mip_ld_u32(d + 2);
    return 0;
}

/* The general reader: lengths other than 6, bad bool bytes, error details. */
static MIP_NOINLINE mip_status_t mip_base_gps_time_update_cv7_ins_decode_read(
    const uint8_t *data, size_t len, mip_base_gps_time_update_cv7_ins_t *out, mip_decode_error_t *err) {
    mip_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mip_base_gps_time_update_cv7_ins_read(&r, out) ? MIP_ERR_DECODE : MIP_OK;
}

mip_status_t mip_base_gps_time_update_cv7_ins_decode(const uint8_t *data, size_t len,
                                                     mip_base_gps_time_update_cv7_ins_t *out,
                                                     mip_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 6 && mip_base_gps_time_update_cv7_ins_load(data, out) == 0) {
        return MIP_OK;
    }
    return mip_base_gps_time_update_cv7_ins_decode_read(data, len, out, err);
}

void mip_base_gps_time_update_cv7_ins_to_json(mip_jw_t *w, const mip_base_gps_time_update_cv7_ins_t *in) {
    int first = 1;
    mip_jw_raw(w, "{", 1);
    mip_jw_key(w, &first, "function");
    mip_jw_u8(w, &in->function);
    mip_jw_key(w, &first, "field_id");
    mip_jw_u8(w, &in->field_id);
    mip_jw_key(w, &first, "value");
    mip_jw_u32(w, &in->value);
    mip_jw_raw(w, "}", 1);
}

int mip_base_gps_time_update_cv7_ins_from_json(mip_jr_t *jr, size_t pos,
                                               mip_base_gps_time_update_cv7_ins_t *out) {
    static const char *const keys[] = {"function", "field_id", "value"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mip_jr_object(jr, pos, keys, 3)) {
        return -1;
    }
    found = mip_jr_get(jr, pos, "function", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"function\"");
    }
    {
        mip_jr_push(jr, "function");
        if (mip_jr_u8(jr, vp, &out->function)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "field_id", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"field_id\"");
    }
    {
        mip_jr_push(jr, "field_id");
        if (mip_jr_u8(jr, vp, &out->field_id)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "value", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"value\"");
    }
    {
        mip_jr_push(jr, "value");
        if (mip_jr_u32(jr, vp, &out->value)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    return 0;
}

/* ---- mip_base_gps_week_t */

static int mip_base_gps_week_read(mip_reader_t *r, mip_base_gps_week_t *out) {
    mip_rd_push(r, "week");
    if (mip_rd_u32(r, &out->week)) {
        return -1;
    }
    mip_rd_pop(r);
    return mip_rd_finish(r);
}

static mip_status_t mip_base_gps_week_write(mip_writer_t *w, const mip_base_gps_week_t *in) {
    mip_status_t st;
    if ((st = mip_wr_u32(w, &in->week)) != MIP_OK) {
        return st;
    }
    return MIP_OK;
}

mip_status_t mip_base_gps_week_encode(const mip_base_gps_week_t *value, uint8_t *buf, size_t cap,
                                      size_t *len_out) {
    mip_writer_t w;
    mip_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mip_writer_init(&w, buf, cap);
    st = mip_base_gps_week_write(&w, value);
    if (st == MIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 4 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mip_base_gps_week_load(const uint8_t *d, mip_base_gps_week_t *out) {
    out->week = mip_ld_u32(d + 0);
    return 0;
}

/* The general reader: lengths other than 4, bad bool bytes, error details. */
static MIP_NOINLINE mip_status_t mip_base_gps_week_decode_read(const uint8_t *data, size_t len,
                                                               mip_base_gps_week_t *out,
                                                               mip_decode_error_t *err) {
    mip_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mip_base_gps_week_read(&r, out) ? MIP_ERR_DECODE : MIP_OK;
}

mip_status_t mip_base_gps_week_decode(const uint8_t *data, size_t len, mip_base_gps_week_t *out,
                                      mip_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 4 && mip_base_gps_week_load(data, out) == 0) {
        return MIP_OK;
    }
    return mip_base_gps_week_decode_read(data, len, out, err);
}

void mip_base_gps_week_to_json(mip_jw_t *w, const mip_base_gps_week_t *in) {
    int first = 1;
    mip_jw_raw(w, "{", 1);
    mip_jw_key(w, &first, "week");
    mip_jw_u32(w, &in->week);
    mip_jw_raw(w, "}", 1);
}

int mip_base_gps_week_from_json(mip_jr_t *jr, size_t pos, mip_base_gps_week_t *out) {
    static const char *const keys[] = {"week"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mip_jr_object(jr, pos, keys, 1)) {
        return -1;
    }
    found = mip_jr_get(jr, pos, "week", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"week\"");
    }
    {
        mip_jr_push(jr, "week");
        if (mip_jr_u32(jr, vp, &out->week)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    return 0;
}

/* ---- mip_base_gps_seconds_t */

static int mip_base_gps_seconds_read(mip_reader_t *r, mip_base_gps_seconds_t *out) {
    mip_rd_push(r, "seconds");
    if (mip_rd_u32(r, &out->seconds)) {
        return -1;
    }
    mip_rd_pop(r);
    return mip_rd_finish(r);
}

static mip_status_t mip_base_gps_seconds_write(mip_writer_t *w, const mip_base_gps_seconds_t *in) {
    mip_status_t st;
    if ((st = mip_wr_u32(w, &in->seconds)) != MIP_OK) {
        return st;
    }
    return MIP_OK;
}

mip_status_t mip_base_gps_seconds_encode(const mip_base_gps_seconds_t *value, uint8_t *buf, size_t cap,
                                         size_t *len_out) {
    mip_writer_t w;
    mip_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mip_writer_init(&w, buf, cap);
    st = mip_base_gps_seconds_write(&w, value);
    if (st == MIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 4 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mip_base_gps_seconds_load(const uint8_t *d, mip_base_gps_seconds_t *out) {
    out->seconds = mip_ld_u32(d + 0);
    return 0;
}

/* The general reader: lengths other than 4, bad bool bytes, error details. */
static MIP_NOINLINE mip_status_t mip_base_gps_seconds_decode_read(const uint8_t *data, size_t len,
                                                                  mip_base_gps_seconds_t *out,
                                                                  mip_decode_error_t *err) {
    mip_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mip_base_gps_seconds_read(&r, out) ? MIP_ERR_DECODE : MIP_OK;
}

mip_status_t mip_base_gps_seconds_decode(const uint8_t *data, size_t len, mip_base_gps_seconds_t *out,
                                         mip_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 4 && mip_base_gps_seconds_load(data, out) == 0) {
        return MIP_OK;
    }
    return mip_base_gps_seconds_decode_read(data, len, out, err);
}

void mip_base_gps_seconds_to_json(mip_jw_t *w, const mip_base_gps_seconds_t *in) {
    int first = 1;
    mip_jw_raw(w, "{", 1);
    mip_jw_key(w, &first, "seconds");
    mip_jw_u32(w, &in->seconds);
    mip_jw_raw(w, "}", 1);
}

int mip_base_gps_seconds_from_json(mip_jr_t *jr, size_t pos, mip_base_gps_seconds_t *out) {
    static const char *const keys[] = {"seconds"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mip_jr_object(jr, pos, keys, 1)) {
        return -1;
    }
    found = mip_jr_get(jr, pos, "seconds", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"seconds\"");
    }
    {
        mip_jr_push(jr, "seconds");
        if (mip_jr_u32(jr, vp, &out->seconds)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    return 0;
}

/* ---- mip_base_device_reset_t */

static int mip_base_device_reset_read(mip_reader_t *r, mip_base_device_reset_t *out) {
    (void)out;
    return mip_rd_finish(r);
}

static mip_status_t mip_base_device_reset_write(mip_writer_t *w, const mip_base_device_reset_t *in) {
    (void)w;
    (void)in;
    return MIP_OK;
}

mip_status_t mip_base_device_reset_encode(const mip_base_device_reset_t *value, uint8_t *buf, size_t cap,
                                          size_t *len_out) {
    mip_writer_t w;
    mip_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mip_writer_init(&w, buf, cap);
    st = mip_base_device_reset_write(&w, value);
    if (st == MIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mip_status_t mip_base_device_reset_decode(const uint8_t *data, size_t len, mip_base_device_reset_t *out,
                                          mip_decode_error_t *err) {
    mip_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mip_base_device_reset_read(&r, out) ? MIP_ERR_DECODE : MIP_OK;
}

void mip_base_device_reset_to_json(mip_jw_t *w, const mip_base_device_reset_t *in) {
    int first = 1;
    mip_jw_raw(w, "{", 1);
    mip_jw_raw(w, "}", 1);
    (void)in;
    (void)first;
}

int mip_base_device_reset_from_json(mip_jr_t *jr, size_t pos, mip_base_device_reset_t *out) {
    memset(out, 0, sizeof *out);
    if (mip_jr_object(jr, pos, NULL, 0)) {
        return -1;
    }
    return 0;
}
