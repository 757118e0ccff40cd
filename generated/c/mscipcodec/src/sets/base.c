/* Encoders and decoders of Base Messages. Generated from the spec: do not edit. */
#include "mscipcodec/sets/base.h"
#include "layouts_internal.h"
#include "types_internal.h"

#include <assert.h>
#include <string.h>

/* ---- mscip_base_ping_t */

static int mscip_base_ping_read(mscip_reader_t *r, mscip_base_ping_t *out) {
    (void)out;
    return mscip_rd_finish(r);
}

static mscip_status_t mscip_base_ping_write(mscip_writer_t *w, const mscip_base_ping_t *in) {
    (void)w;
    (void)in;
    return MSCIP_OK;
}

mscip_status_t mscip_base_ping_encode(const mscip_base_ping_t *value, uint8_t *buf, size_t cap,
                                      size_t *len_out) {
    mscip_writer_t w;
    mscip_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mscip_writer_init(&w, buf, cap);
    st = mscip_base_ping_write(&w, value);
    if (st == MSCIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mscip_status_t mscip_base_ping_decode(const uint8_t *data, size_t len, mscip_base_ping_t *out,
                                      mscip_decode_error_t *err) {
    mscip_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mscip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mscip_base_ping_read(&r, out) ? MSCIP_ERR_DECODE : MSCIP_OK;
}

void mscip_base_ping_to_json(mscip_jw_t *w, const mscip_base_ping_t *in) {
    int first = 1;
    mscip_jw_raw(w, "{", 1);
    mscip_jw_raw(w, "}", 1);
    (void)in;
    (void)first;
}

int mscip_base_ping_from_json(mscip_jr_t *jr, size_t pos, mscip_base_ping_t *out) {
    memset(out, 0, sizeof *out);
    if (mscip_jr_object(jr, pos, NULL, 0)) {
        return -1;
    }
    return 0;
}

/* ---- mscip_base_get_device_messages_t */

static int mscip_base_get_device_messages_read(mscip_reader_t *r, mscip_base_get_device_messages_t *out) {
    (void)out;
    return mscip_rd_finish(r);
}

static mscip_status_t mscip_base_get_device_messages_write(mscip_writer_t *w,
                                                           const mscip_base_get_device_messages_t *in) {
    (void)w;
    (void)in;
    return MSCIP_OK;
}

mscip_status_t mscip_base_get_device_messages_encode(const mscip_base_get_device_messages_t *value,
                                                     uint8_t *buf, size_t cap, size_t *len_out) {
    mscip_writer_t w;
    mscip_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mscip_writer_init(&w, buf, cap);
    st = mscip_base_get_device_messages_write(&w, value);
    if (st == MSCIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mscip_status_t mscip_base_get_device_messages_decode(const uint8_t *data, size_t len,
                                                     mscip_base_get_device_messages_t *out,
                                                     mscip_decode_error_t *err) {
    mscip_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mscip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mscip_base_get_device_messages_read(&r, out) ? MSCIP_ERR_DECODE : MSCIP_OK;
}

void mscip_base_get_device_messages_to_json(mscip_jw_t *w, const mscip_base_get_device_messages_t *in) {
    int first = 1;
    mscip_jw_raw(w, "{", 1);
    mscip_jw_raw(w, "}", 1);
    (void)in;
    (void)first;
}

int mscip_base_get_device_messages_from_json(mscip_jr_t *jr, size_t pos,
                                             mscip_base_get_device_messages_t *out) {
    memset(out, 0, sizeof *out);
    if (mscip_jr_object(jr, pos, NULL, 0)) {
        return -1;
    }
    return 0;
}

/* ---- mscip_base_device_messages_t */

static int mscip_base_device_messages_read(mscip_reader_t *r, mscip_base_device_messages_t *out) {
    size_t i;
    size_t n;
    mscip_rd_push(r, "messages");
    if (mscip_rd_remaining(r, 2, 126, &n)) {
        return -1;
    }
    for (i = 0; i < n; i++) {
        mscip_rd_index(r, i);
        if (mscip_message_id_read(r, &out->messages[i])) {
            return -1;
        }
    }
    out->messages_count = n;
    mscip_rd_pop(r);
    return mscip_rd_finish(r);
}

static mscip_status_t mscip_base_device_messages_write(mscip_writer_t *w,
                                                       const mscip_base_device_messages_t *in) {
    mscip_status_t st;
    size_t i;
    if (in->messages_count > 126) {
        return MSCIP_ERR_INVALID;
    }
    for (i = 0; i < (size_t)in->messages_count; i++) {
        if ((st = mscip_message_id_write(w, &in->messages[i])) != MSCIP_OK) {
            return st;
        }
    }
    return MSCIP_OK;
}

mscip_status_t mscip_base_device_messages_encode(const mscip_base_device_messages_t *value, uint8_t *buf,
                                                 size_t cap, size_t *len_out) {
    mscip_writer_t w;
    mscip_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mscip_writer_init(&w, buf, cap);
    st = mscip_base_device_messages_write(&w, value);
    if (st == MSCIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mscip_status_t mscip_base_device_messages_decode(const uint8_t *data, size_t len,
                                                 mscip_base_device_messages_t *out,
                                                 mscip_decode_error_t *err) {
    mscip_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mscip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mscip_base_device_messages_read(&r, out) ? MSCIP_ERR_DECODE : MSCIP_OK;
}

void mscip_base_device_messages_to_json(mscip_jw_t *w, const mscip_base_device_messages_t *in) {
    int first = 1;
    size_t i;
    mscip_jw_raw(w, "{", 1);
    mscip_jw_key(w, &first, "messages");
    mscip_jw_raw(w, "[", 1);
    for (i = 0; i < (size_t)in->messages_count && i < 126; i++) {
        mscip_jw_sep(w, i);
        mscip_message_id_to_json(w, &in->messages[i]);
    }
    mscip_jw_raw(w, "]", 1);
    mscip_jw_raw(w, "}", 1);
}

int mscip_base_device_messages_from_json(mscip_jr_t *jr, size_t pos, mscip_base_device_messages_t *out) {
    static const char *const keys[] = {"messages"};
    size_t vp = 0;
    int found;
    size_t i;
    size_t it = 0;
    size_t ep = 0;
    memset(out, 0, sizeof *out);
    if (mscip_jr_object(jr, pos, keys, 1)) {
        return -1;
    }
    found = mscip_jr_get(jr, pos, "messages", &vp);
    if (found != 1) {
        return mscip_jr_fail(jr, "missing parameter \"messages\"");
    }
    {
        mscip_jr_push(jr, "messages");
        if (mscip_jr_array(jr, vp, &it)) {
            return -1;
        }
        for (i = 0;; i++) {
            int more = mscip_jr_next(jr, &it, &ep);
            if (more < 0) {
                return -1;
            }
            if (!more) {
                break;
            }
            if (i >= 126) {
                return mscip_jr_fail(jr, "more than 126 elements");
            }
            mscip_jr_index(jr, i);
            if (mscip_message_id_from_json(jr, ep, &out->messages[i])) {
                return -1;
            }
        }
        mscip_jr_index(jr, SIZE_MAX);
        out->messages_count = i;
        mscip_jr_pop(jr);
    }
    return 0;
}

/* ---- mscip_base_device_reset_t */

static int mscip_base_device_reset_read(mscip_reader_t *r, mscip_base_device_reset_t *out) {
    (void)out;
    return mscip_rd_finish(r);
}

static mscip_status_t mscip_base_device_reset_write(mscip_writer_t *w, const mscip_base_device_reset_t *in) {
    (void)w;
    (void)in;
    return MSCIP_OK;
}

mscip_status_t mscip_base_device_reset_encode(const mscip_base_device_reset_t *value, uint8_t *buf,
                                              size_t cap, size_t *len_out) {
    mscip_writer_t w;
    mscip_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mscip_writer_init(&w, buf, cap);
    st = mscip_base_device_reset_write(&w, value);
    if (st == MSCIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mscip_status_t mscip_base_device_reset_decode(const uint8_t *data, size_t len, mscip_base_device_reset_t *out,
                                              mscip_decode_error_t *err) {
    mscip_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mscip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mscip_base_device_reset_read(&r, out) ? MSCIP_ERR_DECODE : MSCIP_OK;
}

void mscip_base_device_reset_to_json(mscip_jw_t *w, const mscip_base_device_reset_t *in) {
    int first = 1;
    mscip_jw_raw(w, "{", 1);
    mscip_jw_raw(w, "}", 1);
    (void)in;
    (void)first;
}

int mscip_base_device_reset_from_json(mscip_jr_t *jr, size_t pos, mscip_base_device_reset_t *out) {
    memset(out, 0, sizeof *out);
    if (mscip_jr_object(jr, pos, NULL, 0)) {
        return -1;
    }
    return 0;
}

/* ---- mscip_base_get_device_model_t */

static int mscip_base_get_device_model_read(mscip_reader_t *r, mscip_base_get_device_model_t *out) {
    (void)out;
    return mscip_rd_finish(r);
}

static mscip_status_t mscip_base_get_device_model_write(mscip_writer_t *w,
                                                        const mscip_base_get_device_model_t *in) {
    (void)w;
    (void)in;
    return MSCIP_OK;
}

mscip_status_t mscip_base_get_device_model_encode(const mscip_base_get_device_model_t *value, uint8_t *buf,
                                                  size_t cap, size_t *len_out) {
    mscip_writer_t w;
    mscip_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mscip_writer_init(&w, buf, cap);
    st = mscip_base_get_device_model_write(&w, value);
    if (st == MSCIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mscip_status_t mscip_base_get_device_model_decode(const uint8_t *data, size_t len,
                                                  mscip_base_get_device_model_t *out,
                                                  mscip_decode_error_t *err) {
    mscip_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mscip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mscip_base_get_device_model_read(&r, out) ? MSCIP_ERR_DECODE : MSCIP_OK;
}

void mscip_base_get_device_model_to_json(mscip_jw_t *w, const mscip_base_get_device_model_t *in) {
    int first = 1;
    mscip_jw_raw(w, "{", 1);
    mscip_jw_raw(w, "}", 1);
    (void)in;
    (void)first;
}

int mscip_base_get_device_model_from_json(mscip_jr_t *jr, size_t pos, mscip_base_get_device_model_t *out) {
    memset(out, 0, sizeof *out);
    if (mscip_jr_object(jr, pos, NULL, 0)) {
        return -1;
    }
    return 0;
}

/* ---- mscip_base_device_model_t */

static int mscip_base_device_model_read(mscip_reader_t *r, mscip_base_device_model_t *out) {
    mscip_rd_push(r, "model");
    if (mscip_rd_chars(r, out->model, 16)) {
        return -1;
    }
    mscip_rd_pop(r);
    return mscip_rd_finish(r);
}

static mscip_status_t mscip_base_device_model_write(mscip_writer_t *w, const mscip_base_device_model_t *in) {
    mscip_status_t st;
    if ((st = mscip_wr_chars(w, in->model, 16)) != MSCIP_OK) {
        return st;
    }
    return MSCIP_OK;
}

mscip_status_t mscip_base_device_model_encode(const mscip_base_device_model_t *value, uint8_t *buf,
                                              size_t cap, size_t *len_out) {
    mscip_writer_t w;
    mscip_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mscip_writer_init(&w, buf, cap);
    st = mscip_base_device_model_write(&w, value);
    if (st == MSCIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mscip_status_t mscip_base_device_model_decode(const uint8_t *data, size_t len, mscip_base_device_model_t *out,
                                              mscip_decode_error_t *err) {
    mscip_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mscip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mscip_base_device_model_read(&r, out) ? MSCIP_ERR_DECODE : MSCIP_OK;
}

void mscip_base_device_model_to_json(mscip_jw_t *w, const mscip_base_device_model_t *in) {
    int first = 1;
    mscip_jw_raw(w, "{", 1);
    mscip_jw_key(w, &first, "model");
    mscip_jw_chars(w, in->model, 16);
    mscip_jw_raw(w, "}", 1);
}

int mscip_base_device_model_from_json(mscip_jr_t *jr, size_t pos, mscip_base_device_model_t *out) {
    static const char *const keys[] = {"model"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mscip_jr_object(jr, pos, keys, 1)) {
        return -1;
    }
    found = mscip_jr_get(jr, pos, "model", &vp);
    if (found != 1) {
        return mscip_jr_fail(jr, "missing parameter \"model\"");
    }
    {
        mscip_jr_push(jr, "model");
        if (mscip_jr_chars(jr, vp, out->model, 16)) {
            return -1;
        }
        mscip_jr_pop(jr);
    }
    return 0;
}

/* ---- mscip_base_get_device_sn_t */

static int mscip_base_get_device_sn_read(mscip_reader_t *r, mscip_base_get_device_sn_t *out) {
    (void)out;
    return mscip_rd_finish(r);
}

static mscip_status_t mscip_base_get_device_sn_write(mscip_writer_t *w,
                                                     const mscip_base_get_device_sn_t *in) {
    (void)w;
    (void)in;
    return MSCIP_OK;
}

mscip_status_t mscip_base_get_device_sn_encode(const mscip_base_get_device_sn_t *value, uint8_t *buf,
                                               size_t cap, size_t *len_out) {
    mscip_writer_t w;
    mscip_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mscip_writer_init(&w, buf, cap);
    st = mscip_base_get_device_sn_write(&w, value);
    if (st == MSCIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mscip_status_t mscip_base_get_device_sn_decode(const uint8_t *data, size_t len,
                                               mscip_base_get_device_sn_t *out, mscip_decode_error_t *err) {
    mscip_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mscip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mscip_base_get_device_sn_read(&r, out) ? MSCIP_ERR_DECODE : MSCIP_OK;
}

void mscip_base_get_device_sn_to_json(mscip_jw_t *w, const mscip_base_get_device_sn_t *in) {
    int first = 1;
    mscip_jw_raw(w, "{", 1);
    mscip_jw_raw(w, "}", 1);
    (void)in;
    (void)first;
}

int mscip_base_get_device_sn_from_json(mscip_jr_t *jr, size_t pos, mscip_base_get_device_sn_t *out) {
    memset(out, 0, sizeof *out);
    if (mscip_jr_object(jr, pos, NULL, 0)) {
        return -1;
    }
    return 0;
}

/* ---- mscip_base_device_sn_t */

static int mscip_base_device_sn_read(mscip_reader_t *r, mscip_base_device_sn_t *out) {
    mscip_rd_push(r, "serial_number");
    if (mscip_rd_chars(r, out->serial_number, 16)) {
        return -1;
    }
    mscip_rd_pop(r);
    return mscip_rd_finish(r);
}

static mscip_status_t mscip_base_device_sn_write(mscip_writer_t *w, const mscip_base_device_sn_t *in) {
    mscip_status_t st;
    if ((st = mscip_wr_chars(w, in->serial_number, 16)) != MSCIP_OK) {
        return st;
    }
    return MSCIP_OK;
}

mscip_status_t mscip_base_device_sn_encode(const mscip_base_device_sn_t *value, uint8_t *buf, size_t cap,
                                           size_t *len_out) {
    mscip_writer_t w;
    mscip_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mscip_writer_init(&w, buf, cap);
    st = mscip_base_device_sn_write(&w, value);
    if (st == MSCIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mscip_status_t mscip_base_device_sn_decode(const uint8_t *data, size_t len, mscip_base_device_sn_t *out,
                                           mscip_decode_error_t *err) {
    mscip_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mscip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mscip_base_device_sn_read(&r, out) ? MSCIP_ERR_DECODE : MSCIP_OK;
}

void mscip_base_device_sn_to_json(mscip_jw_t *w, const mscip_base_device_sn_t *in) {
    int first = 1;
    mscip_jw_raw(w, "{", 1);
    mscip_jw_key(w, &first, "serial_number");
    mscip_jw_chars(w, in->serial_number, 16);
    mscip_jw_raw(w, "}", 1);
}

int mscip_base_device_sn_from_json(mscip_jr_t *jr, size_t pos, mscip_base_device_sn_t *out) {
    static const char *const keys[] = {"serial_number"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mscip_jr_object(jr, pos, keys, 1)) {
        return -1;
    }
    found = mscip_jr_get(jr, pos, "serial_number", &vp);
    if (found != 1) {
        return mscip_jr_fail(jr, "missing parameter \"serial_number\"");
    }
    {
        mscip_jr_push(jr, "serial_number");
        if (mscip_jr_chars(jr, vp, out->serial_number, 16)) {
            return -1;
        }
        mscip_jr_pop(jr);
    }
    return 0;
}

/* ---- mscip_base_get_device_fw_t */

static int mscip_base_get_device_fw_read(mscip_reader_t *r, mscip_base_get_device_fw_t *out) {
    (void)out;
    return mscip_rd_finish(r);
}

static mscip_status_t mscip_base_get_device_fw_write(mscip_writer_t *w,
                                                     const mscip_base_get_device_fw_t *in) {
    (void)w;
    (void)in;
    return MSCIP_OK;
}

mscip_status_t mscip_base_get_device_fw_encode(const mscip_base_get_device_fw_t *value, uint8_t *buf,
                                               size_t cap, size_t *len_out) {
    mscip_writer_t w;
    mscip_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mscip_writer_init(&w, buf, cap);
    st = mscip_base_get_device_fw_write(&w, value);
    if (st == MSCIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mscip_status_t mscip_base_get_device_fw_decode(const uint8_t *data, size_t len,
                                               mscip_base_get_device_fw_t *out, mscip_decode_error_t *err) {
    mscip_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mscip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mscip_base_get_device_fw_read(&r, out) ? MSCIP_ERR_DECODE : MSCIP_OK;
}

void mscip_base_get_device_fw_to_json(mscip_jw_t *w, const mscip_base_get_device_fw_t *in) {
    int first = 1;
    mscip_jw_raw(w, "{", 1);
    mscip_jw_raw(w, "}", 1);
    (void)in;
    (void)first;
}

int mscip_base_get_device_fw_from_json(mscip_jr_t *jr, size_t pos, mscip_base_get_device_fw_t *out) {
    memset(out, 0, sizeof *out);
    if (mscip_jr_object(jr, pos, NULL, 0)) {
        return -1;
    }
    return 0;
}

/* ---- mscip_base_device_fw_t */

static int mscip_base_device_fw_read(mscip_reader_t *r, mscip_base_device_fw_t *out) {
    mscip_rd_push(r, "firmware");
    if (mscip_rd_chars(r, out->firmware, 16)) {
        return -1;
    }
    mscip_rd_pop(r);
    return mscip_rd_finish(r);
}

static mscip_status_t mscip_base_device_fw_write(mscip_writer_t *w, const mscip_base_device_fw_t *in) {
    mscip_status_t st;
    if ((st = mscip_wr_chars(w, in->firmware, 16)) != MSCIP_OK) {
        return st;
    }
    return MSCIP_OK;
}

mscip_status_t mscip_base_device_fw_encode(const mscip_base_device_fw_t *value, uint8_t *buf, size_t cap,
                                           size_t *len_out) {
    mscip_writer_t w;
    mscip_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mscip_writer_init(&w, buf, cap);
    st = mscip_base_device_fw_write(&w, value);
    if (st == MSCIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mscip_status_t mscip_base_device_fw_decode(const uint8_t *data, size_t len, mscip_base_device_fw_t *out,
                                           mscip_decode_error_t *err) {
    mscip_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mscip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mscip_base_device_fw_read(&r, out) ? MSCIP_ERR_DECODE : MSCIP_OK;
}

void mscip_base_device_fw_to_json(mscip_jw_t *w, const mscip_base_device_fw_t *in) {
    int first = 1;
    mscip_jw_raw(w, "{", 1);
    mscip_jw_key(w, &first, "firmware");
    mscip_jw_chars(w, in->firmware, 16);
    mscip_jw_raw(w, "}", 1);
}

int mscip_base_device_fw_from_json(mscip_jr_t *jr, size_t pos, mscip_base_device_fw_t *out) {
    static const char *const keys[] = {"firmware"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mscip_jr_object(jr, pos, keys, 1)) {
        return -1;
    }
    found = mscip_jr_get(jr, pos, "firmware", &vp);
    if (found != 1) {
        return mscip_jr_fail(jr, "missing parameter \"firmware\"");
    }
    {
        mscip_jr_push(jr, "firmware");
        if (mscip_jr_chars(jr, vp, out->firmware, 16)) {
            return -1;
        }
        mscip_jr_pop(jr);
    }
    return 0;
}

/* ---- mscip_base_get_device_cal_t */

static int mscip_base_get_device_cal_read(mscip_reader_t *r, mscip_base_get_device_cal_t *out) {
    (void)out;
    return mscip_rd_finish(r);
}

static mscip_status_t mscip_base_get_device_cal_write(mscip_writer_t *w,
                                                      const mscip_base_get_device_cal_t *in) {
    (void)w;
    (void)in;
    return MSCIP_OK;
}

mscip_status_t mscip_base_get_device_cal_encode(const mscip_base_get_device_cal_t *value, uint8_t *buf,
                                                size_t cap, size_t *len_out) {
    mscip_writer_t w;
    mscip_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mscip_writer_init(&w, buf, cap);
    st = mscip_base_get_device_cal_write(&w, value);
    if (st == MSCIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mscip_status_t mscip_base_get_device_cal_decode(const uint8_t *data, size_t len,
                                                mscip_base_get_device_cal_t *out, mscip_decode_error_t *err) {
    mscip_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mscip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mscip_base_get_device_cal_read(&r, out) ? MSCIP_ERR_DECODE : MSCIP_OK;
}

void mscip_base_get_device_cal_to_json(mscip_jw_t *w, const mscip_base_get_device_cal_t *in) {
    int first = 1;
    mscip_jw_raw(w, "{", 1);
    mscip_jw_raw(w, "}", 1);
    (void)in;
    (void)first;
}

int mscip_base_get_device_cal_from_json(mscip_jr_t *jr, size_t pos, mscip_base_get_device_cal_t *out) {
    memset(out, 0, sizeof *out);
    if (mscip_jr_object(jr, pos, NULL, 0)) {
        return -1;
    }
    return 0;
}

/* ---- mscip_base_device_cal_t */

static int mscip_base_device_cal_read(mscip_reader_t *r, mscip_base_device_cal_t *out) {
    mscip_rd_push(r, "date");
    if (mscip_rd_chars(r, out->date, 16)) {
        return -1;
    }
    mscip_rd_pop(r);
    return mscip_rd_finish(r);
}

static mscip_status_t mscip_base_device_cal_write(mscip_writer_t *w, const mscip_base_device_cal_t *in) {
    mscip_status_t st;
    if ((st = mscip_wr_chars(w, in->date, 16)) != MSCIP_OK) {
        return st;
    }
    return MSCIP_OK;
}

mscip_status_t mscip_base_device_cal_encode(const mscip_base_device_cal_t *value, uint8_t *buf, size_t cap,
                                            size_t *len_out) {
    mscip_writer_t w;
    mscip_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mscip_writer_init(&w, buf, cap);
    st = mscip_base_device_cal_write(&w, value);
    if (st == MSCIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mscip_status_t mscip_base_device_cal_decode(const uint8_t *data, size_t len, mscip_base_device_cal_t *out,
                                            mscip_decode_error_t *err) {
    mscip_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mscip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mscip_base_device_cal_read(&r, out) ? MSCIP_ERR_DECODE : MSCIP_OK;
}

void mscip_base_device_cal_to_json(mscip_jw_t *w, const mscip_base_device_cal_t *in) {
    int first = 1;
    mscip_jw_raw(w, "{", 1);
    mscip_jw_key(w, &first, "date");
    mscip_jw_chars(w, in->date, 16);
    mscip_jw_raw(w, "}", 1);
}

int mscip_base_device_cal_from_json(mscip_jr_t *jr, size_t pos, mscip_base_device_cal_t *out) {
    static const char *const keys[] = {"date"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mscip_jr_object(jr, pos, keys, 1)) {
        return -1;
    }
    found = mscip_jr_get(jr, pos, "date", &vp);
    if (found != 1) {
        return mscip_jr_fail(jr, "missing parameter \"date\"");
    }
    {
        mscip_jr_push(jr, "date");
        if (mscip_jr_chars(jr, vp, out->date, 16)) {
            return -1;
        }
        mscip_jr_pop(jr);
    }
    return 0;
}

/* ---- mscip_base_correlate_gps_time_t */

static int mscip_base_correlate_gps_time_read(mscip_reader_t *r, mscip_base_correlate_gps_time_t *out) {
    mscip_rd_push(r, "week");
    if (mscip_rd_u16(r, &out->week)) {
        return -1;
    }
    mscip_rd_pop(r);
    mscip_rd_push(r, "seconds");
    if (mscip_rd_u32(r, &out->seconds)) {
        return -1;
    }
    mscip_rd_pop(r);
    return mscip_rd_finish(r);
}

static mscip_status_t mscip_base_correlate_gps_time_write(mscip_writer_t *w,
                                                          const mscip_base_correlate_gps_time_t *in) {
    mscip_status_t st;
    if ((st = mscip_wr_u16(w, &in->week)) != MSCIP_OK) {
        return st;
    }
    if ((st = mscip_wr_u32(w, &in->seconds)) != MSCIP_OK) {
        return st;
    }
    return MSCIP_OK;
}

mscip_status_t mscip_base_correlate_gps_time_encode(const mscip_base_correlate_gps_time_t *value,
                                                    uint8_t *buf, size_t cap, size_t *len_out) {
    mscip_writer_t w;
    mscip_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mscip_writer_init(&w, buf, cap);
    st = mscip_base_correlate_gps_time_write(&w, value);
    if (st == MSCIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 6 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mscip_base_correlate_gps_time_load(const uint8_t *d, mscip_base_correlate_gps_time_t *out) {
    out->week = mscip_ld_u16(d + 0);
    out->seconds = mscip_ld_u32(d + 2);
    return 0;
}

/* The general reader: lengths other than 6, bad bool bytes, error details. */
static MSCIP_NOINLINE mscip_status_t mscip_base_correlate_gps_time_decode_read(
    const uint8_t *data, size_t len, mscip_base_correlate_gps_time_t *out, mscip_decode_error_t *err) {
    mscip_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mscip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mscip_base_correlate_gps_time_read(&r, out) ? MSCIP_ERR_DECODE : MSCIP_OK;
}

mscip_status_t mscip_base_correlate_gps_time_decode(const uint8_t *data, size_t len,
                                                    mscip_base_correlate_gps_time_t *out,
                                                    mscip_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 6 && mscip_base_correlate_gps_time_load(data, out) == 0) {
        return MSCIP_OK;
    }
    return mscip_base_correlate_gps_time_decode_read(data, len, out, err);
}

void mscip_base_correlate_gps_time_to_json(mscip_jw_t *w, const mscip_base_correlate_gps_time_t *in) {
    int first = 1;
    mscip_jw_raw(w, "{", 1);
    mscip_jw_key(w, &first, "week");
    mscip_jw_u16(w, &in->week);
    mscip_jw_key(w, &first, "seconds");
    mscip_jw_u32(w, &in->seconds);
    mscip_jw_raw(w, "}", 1);
}

int mscip_base_correlate_gps_time_from_json(mscip_jr_t *jr, size_t pos,
                                            mscip_base_correlate_gps_time_t *out) {
    static const char *const keys[] = {"week", "seconds"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mscip_jr_object(jr, pos, keys, 2)) {
        return -1;
    }
    found = mscip_jr_get(jr, pos, "week", &vp);
    if (found != 1) {
        return mscip_jr_fail(jr, "missing parameter \"week\"");
    }
    {
        mscip_jr_push(jr, "week");
        if (mscip_jr_u16(jr, vp, &out->week)) {
            return -1;
        }
        mscip_jr_pop(jr);
    }
    found = mscip_jr_get(jr, pos, "seconds", &vp);
    if (found != 1) {
        return mscip_jr_fail(jr, "missing parameter \"seconds\"");
    }
    {
        mscip_jr_push(jr, "seconds");
        if (mscip_jr_u32(jr, vp, &out->seconds)) {
            return -1;
        }
        mscip_jr_pop(jr);
    }
    return 0;
}
