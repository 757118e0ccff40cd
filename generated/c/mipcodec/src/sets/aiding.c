/* Encoders and decoders of Aiding Command Set. Generated from the spec: do not edit. */
#include "mipcodec/sets/aiding.h"
#include "layouts_internal.h"
#include "types_internal.h"

#include <assert.h>
#include <string.h>

/* ---- mip_aiding_frame_config_t */

static int mip_aiding_frame_config_read(mip_reader_t *r, mip_aiding_frame_config_t *out) {
    size_t i;
    mip_rd_push(r, "function");
    if (mip_rd_u8(r, &out->function)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "frame_id");
    if (mip_rd_u8(r, &out->frame_id)) {
        return -1;
    }
    mip_rd_pop(r);
    if (r->pos < r->len) {
        out->has_format = true;
        mip_rd_push(r, "format");
        if (mip_rd_u8(r, &out->format)) {
            return -1;
        }
        mip_rd_pop(r);
    }
    if (r->pos < r->len) {
        out->has_tracking_enabled = true;
        mip_rd_push(r, "tracking_enabled");
        if (mip_rd_bool(r, &out->tracking_enabled)) {
            return -1;
        }
        mip_rd_pop(r);
    }
    if (r->pos < r->len) {
        out->has_translation = true;
        mip_rd_push(r, "translation");
        for (i = 0; i < 3; i++) {
            mip_rd_index(r, i);
            if (mip_rd_f32(r, &out->translation[i])) {
                return -1;
            }
        }
        mip_rd_pop(r);
    }
    if (r->pos < r->len) {
        out->has_rotation = true;
        mip_rd_push(r, "rotation");
        if (mip_aiding_frame_rotation_read(r, out->format, &out->rotation)) {
            return -1;
        }
        mip_rd_pop(r);
    }
    return mip_rd_finish(r);
}

static mip_status_t mip_aiding_frame_config_write(mip_writer_t *w, const mip_aiding_frame_config_t *in) {
    mip_status_t st;
    size_t i;
    int absent = 0;
    if ((st = mip_wr_u8(w, &in->function)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_u8(w, &in->frame_id)) != MIP_OK) {
        return st;
    }
    if (!in->has_format) {
        absent = 1;
    } else if (absent) {
        return MIP_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = mip_wr_u8(w, &in->format)) != MIP_OK) {
            return st;
        }
    }
    if (!in->has_tracking_enabled) {
        absent = 1;
    } else if (absent) {
        return MIP_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = mip_wr_bool(w, &in->tracking_enabled)) != MIP_OK) {
            return st;
        }
    }
    if (!in->has_translation) {
        absent = 1;
    } else if (absent) {
        return MIP_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        for (i = 0; i < 3; i++) {
            if ((st = mip_wr_f32(w, &in->translation[i])) != MIP_OK) {
                return st;
            }
        }
    }
    if (!in->has_rotation) {
        absent = 1;
    } else if (absent) {
        return MIP_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = mip_aiding_frame_rotation_write(w, in->format, &in->rotation)) != MIP_OK) {
            return st;
        }
    }
    return MIP_OK;
}

mip_status_t mip_aiding_frame_config_encode(const mip_aiding_frame_config_t *value, uint8_t *buf, size_t cap,
                                            size_t *len_out) {
    mip_writer_t w;
    mip_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mip_writer_init(&w, buf, cap);
    st = mip_aiding_frame_config_write(&w, value);
    if (st == MIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mip_status_t mip_aiding_frame_config_decode(const uint8_t *data, size_t len, mip_aiding_frame_config_t *out,
                                            mip_decode_error_t *err) {
    mip_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mip_aiding_frame_config_read(&r, out) ? MIP_ERR_DECODE : MIP_OK;
}

void mip_aiding_frame_config_to_json(mip_jw_t *w, const mip_aiding_frame_config_t *in) {
    int first = 1;
    size_t i;
    mip_jw_raw(w, "{", 1);
    mip_jw_key(w, &first, "function");
    mip_jw_u8(w, &in->function);
    mip_jw_key(w, &first, "frame_id");
    mip_jw_u8(w, &in->frame_id);
    if (in->has_format) {
        mip_jw_key(w, &first, "format");
        mip_jw_u8(w, &in->format);
    }
    if (in->has_tracking_enabled) {
        mip_jw_key(w, &first, "tracking_enabled");
        mip_jw_bool(w, &in->tracking_enabled);
    }
    if (in->has_translation) {
        mip_jw_key(w, &first, "translation");
        mip_jw_raw(w, "[", 1);
        for (i = 0; i < 3; i++) {
            mip_jw_sep(w, i);
            mip_jw_f32(w, &in->translation[i]);
        }
        mip_jw_raw(w, "]", 1);
    }
    if (in->has_rotation) {
        mip_jw_key(w, &first, "rotation");
        mip_aiding_frame_rotation_to_json(w, in->format, &in->rotation);
    }
    mip_jw_raw(w, "}", 1);
}

int mip_aiding_frame_config_from_json(mip_jr_t *jr, size_t pos, mip_aiding_frame_config_t *out) {
    static const char *const keys[] = {"function",         "frame_id",    "format",
                                       "tracking_enabled", "translation", "rotation"};
    size_t vp = 0;
    int found;
    int absent = 0;
    size_t i;
    size_t it = 0;
    size_t ep = 0;
    memset(out, 0, sizeof *out);
    if (mip_jr_object(jr, pos, keys, 6)) {
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
    found = mip_jr_get(jr, pos, "frame_id", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"frame_id\"");
    }
    {
        mip_jr_push(jr, "frame_id");
        if (mip_jr_u8(jr, vp, &out->frame_id)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "format", &vp);
    out->has_format = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mip_jr_fail(jr, "optional parameter \"format\" given after an absent one");
    } else {
        mip_jr_push(jr, "format");
        if (mip_jr_u8(jr, vp, &out->format)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "tracking_enabled", &vp);
    out->has_tracking_enabled = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mip_jr_fail(jr, "optional parameter \"tracking_enabled\" given after an absent one");
    } else {
        mip_jr_push(jr, "tracking_enabled");
        if (mip_jr_bool(jr, vp, &out->tracking_enabled)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "translation", &vp);
    out->has_translation = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mip_jr_fail(jr, "optional parameter \"translation\" given after an absent one");
    } else {
        mip_jr_push(jr, "translation");
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
            if (i >= 3) {
                return mip_jr_fail(jr, "more than 3 elements");
            }
            mip_jr_index(jr, i);
            if (mip_jr_f32(jr, ep, &out->translation[i])) {
                return -1;
            }
        }
        mip_jr_index(jr, SIZE_MAX);
        if (i != 3) {
            return mip_jr_fail(jr, "expected 3 elements, got %zu", i);
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "rotation", &vp);
    out->has_rotation = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mip_jr_fail(jr, "optional parameter \"rotation\" given after an absent one");
    } else {
        mip_jr_push(jr, "rotation");
        if (mip_aiding_frame_rotation_from_json(jr, vp, out->format, &out->rotation)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    return 0;
}

/* ---- mip_aiding_frame_config_response_t */

static int mip_aiding_frame_config_response_read(mip_reader_t *r, mip_aiding_frame_config_response_t *out) {
    size_t i;
    mip_rd_push(r, "frame_id");
    if (mip_rd_u8(r, &out->frame_id)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "format");
    if (mip_rd_u8(r, &out->format)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "tracking_enabled");
    if (mip_rd_bool(r, &out->tracking_enabled)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "translation");
    for (i = 0; i < 3; i++) {
        mip_rd_index(r, i);
        if (mip_rd_f32(r, &out->translation[i])) {
            return -1;
        }
    }
    mip_rd_pop(r);
    mip_rd_push(r, "rotation");
    if (mip_aiding_frame_rotation_read(r, out->format, &out->rotation)) {
        return -1;
    }
    mip_rd_pop(r);
    return mip_rd_finish(r);
}

static mip_status_t mip_aiding_frame_config_response_write(mip_writer_t *w,
                                                           const mip_aiding_frame_config_response_t *in) {
    mip_status_t st;
    size_t i;
    if ((st = mip_wr_u8(w, &in->frame_id)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_u8(w, &in->format)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_bool(w, &in->tracking_enabled)) != MIP_OK) {
        return st;
    }
    for (i = 0; i < 3; i++) {
        if ((st = mip_wr_f32(w, &in->translation[i])) != MIP_OK) {
            return st;
        }
    }
    if ((st = mip_aiding_frame_rotation_write(w, in->format, &in->rotation)) != MIP_OK) {
        return st;
    }
    return MIP_OK;
}

mip_status_t mip_aiding_frame_config_response_encode(const mip_aiding_frame_config_response_t *value,
                                                     uint8_t *buf, size_t cap, size_t *len_out) {
    mip_writer_t w;
    mip_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mip_writer_init(&w, buf, cap);
    st = mip_aiding_frame_config_response_write(&w, value);
    if (st == MIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mip_status_t mip_aiding_frame_config_response_decode(const uint8_t *data, size_t len,
                                                     mip_aiding_frame_config_response_t *out,
                                                     mip_decode_error_t *err) {
    mip_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mip_aiding_frame_config_response_read(&r, out) ? MIP_ERR_DECODE : MIP_OK;
}

void mip_aiding_frame_config_response_to_json(mip_jw_t *w, const mip_aiding_frame_config_response_t *in) {
    int first = 1;
    size_t i;
    mip_jw_raw(w, "{", 1);
    mip_jw_key(w, &first, "frame_id");
    mip_jw_u8(w, &in->frame_id);
    mip_jw_key(w, &first, "format");
    mip_jw_u8(w, &in->format);
    mip_jw_key(w, &first, "tracking_enabled");
    mip_jw_bool(w, &in->tracking_enabled);
    mip_jw_key(w, &first, "translation");
    mip_jw_raw(w, "[", 1);
    for (i = 0; i < 3; i++) {
        mip_jw_sep(w, i);
        mip_jw_f32(w, &in->translation[i]);
    }
    mip_jw_raw(w, "]", 1);
    mip_jw_key(w, &first, "rotation");
    mip_aiding_frame_rotation_to_json(w, in->format, &in->rotation);
    mip_jw_raw(w, "}", 1);
}

int mip_aiding_frame_config_response_from_json(mip_jr_t *jr, size_t pos,
                                               mip_aiding_frame_config_response_t *out) {
    static const char *const keys[] = {"frame_id", "format", "tracking_enabled", "translation", "rotation"};
    size_t vp = 0;
    int found;
    size_t i;
    size_t it = 0;
    size_t ep = 0;
    memset(out, 0, sizeof *out);
    if (mip_jr_object(jr, pos, keys, 5)) {
        return -1;
    }
    found = mip_jr_get(jr, pos, "frame_id", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"frame_id\"");
    }
    {
        mip_jr_push(jr, "frame_id");
        if (mip_jr_u8(jr, vp, &out->frame_id)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "format", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"format\"");
    }
    {
        mip_jr_push(jr, "format");
        if (mip_jr_u8(jr, vp, &out->format)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "tracking_enabled", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"tracking_enabled\"");
    }
    {
        mip_jr_push(jr, "tracking_enabled");
        if (mip_jr_bool(jr, vp, &out->tracking_enabled)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "translation", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"translation\"");
    }
    {
        mip_jr_push(jr, "translation");
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
            if (i >= 3) {
                return mip_jr_fail(jr, "more than 3 elements");
            }
            mip_jr_index(jr, i);
            if (mip_jr_f32(jr, ep, &out->translation[i])) {
                return -1;
            }
        }
        mip_jr_index(jr, SIZE_MAX);
        if (i != 3) {
            return mip_jr_fail(jr, "expected 3 elements, got %zu", i);
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "rotation", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"rotation\"");
    }
    {
        mip_jr_push(jr, "rotation");
        if (mip_aiding_frame_rotation_from_json(jr, vp, out->format, &out->rotation)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    return 0;
}

/* ---- mip_aiding_echo_control_t */

static int mip_aiding_echo_control_read(mip_reader_t *r, mip_aiding_echo_control_t *out) {
    mip_rd_push(r, "function");
    if (mip_rd_u8(r, &out->function)) {
        return -1;
    }
    mip_rd_pop(r);
    if (r->pos < r->len) {
        out->has_mode = true;
        mip_rd_push(r, "mode");
        if (mip_rd_u8(r, &out->mode)) {
            return -1;
        }
        mip_rd_pop(r);
    }
    return mip_rd_finish(r);
}

static mip_status_t mip_aiding_echo_control_write(mip_writer_t *w, const mip_aiding_echo_control_t *in) {
    mip_status_t st;
    int absent = 0;
    if ((st = mip_wr_u8(w, &in->function)) != MIP_OK) {
        return st;
    }
    if (!in->has_mode) {
        absent = 1;
    } else if (absent) {
        return MIP_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = mip_wr_u8(w, &in->mode)) != MIP_OK) {
            return st;
        }
    }
    return MIP_OK;
}

mip_status_t mip_aiding_echo_control_encode(const mip_aiding_echo_control_t *value, uint8_t *buf, size_t cap,
                                            size_t *len_out) {
    mip_writer_t w;
    mip_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mip_writer_init(&w, buf, cap);
    st = mip_aiding_echo_control_write(&w, value);
    if (st == MIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mip_status_t mip_aiding_echo_control_decode(const uint8_t *data, size_t len, mip_aiding_echo_control_t *out,
                                            mip_decode_error_t *err) {
    mip_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mip_aiding_echo_control_read(&r, out) ? MIP_ERR_DECODE : MIP_OK;
}

void mip_aiding_echo_control_to_json(mip_jw_t *w, const mip_aiding_echo_control_t *in) {
    int first = 1;
    mip_jw_raw(w, "{", 1);
    mip_jw_key(w, &first, "function");
    mip_jw_u8(w, &in->function);
    if (in->has_mode) {
        mip_jw_key(w, &first, "mode");
        mip_jw_u8(w, &in->mode);
    }
    mip_jw_raw(w, "}", 1);
}

int mip_aiding_echo_control_from_json(mip_jr_t *jr, size_t pos, mip_aiding_echo_control_t *out) {
    static const char *const keys[] = {"function", "mode"};
    size_t vp = 0;
    int found;
    int absent = 0;
    memset(out, 0, sizeof *out);
    if (mip_jr_object(jr, pos, keys, 2)) {
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
    found = mip_jr_get(jr, pos, "mode", &vp);
    out->has_mode = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mip_jr_fail(jr, "optional parameter \"mode\" given after an absent one");
    } else {
        mip_jr_push(jr, "mode");
        if (mip_jr_u8(jr, vp, &out->mode)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    return 0;
}

/* ---- mip_aiding_echo_control_response_t */

static int mip_aiding_echo_control_response_read(mip_reader_t *r, mip_aiding_echo_control_response_t *out) {
    mip_rd_push(r, "mode");
    if (mip_rd_u8(r, &out->mode)) {
        return -1;
    }
    mip_rd_pop(r);
    return mip_rd_finish(r);
}

static mip_status_t mip_aiding_echo_control_response_write(mip_writer_t *w,
                                                           const mip_aiding_echo_control_response_t *in) {
    mip_status_t st;
    if ((st = mip_wr_u8(w, &in->mode)) != MIP_OK) {
        return st;
    }
    return MIP_OK;
}

mip_status_t mip_aiding_echo_control_response_encode(const mip_aiding_echo_control_response_t *value,
                                                     uint8_t *buf, size_t cap, size_t *len_out) {
    mip_writer_t w;
    mip_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mip_writer_init(&w, buf, cap);
    st = mip_aiding_echo_control_response_write(&w, value);
    if (st == MIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 1 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mip_aiding_echo_control_response_load(const uint8_t *d, mip_aiding_echo_control_response_t *out) {
    out->mode = mip_ld_u8(d + 0);
    return 0;
}

/* The general reader: lengths other than 1, bad bool bytes, error details. */
static MIP_NOINLINE mip_status_t mip_aiding_echo_control_response_decode_read(
    const uint8_t *data, size_t len, mip_aiding_echo_control_response_t *out, mip_decode_error_t *err) {
    mip_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mip_aiding_echo_control_response_read(&r, out) ? MIP_ERR_DECODE : MIP_OK;
}

mip_status_t mip_aiding_echo_control_response_decode(const uint8_t *data, size_t len,
                                                     mip_aiding_echo_control_response_t *out,
                                                     mip_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 1 && mip_aiding_echo_control_response_load(data, out) == 0) {
        return MIP_OK;
    }
    return mip_aiding_echo_control_response_decode_read(data, len, out, err);
}

void mip_aiding_echo_control_response_to_json(mip_jw_t *w, const mip_aiding_echo_control_response_t *in) {
    int first = 1;
    mip_jw_raw(w, "{", 1);
    mip_jw_key(w, &first, "mode");
    mip_jw_u8(w, &in->mode);
    mip_jw_raw(w, "}", 1);
}

int mip_aiding_echo_control_response_from_json(mip_jr_t *jr, size_t pos,
                                               mip_aiding_echo_control_response_t *out) {
    static const char *const keys[] = {"mode"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mip_jr_object(jr, pos, keys, 1)) {
        return -1;
    }
    found = mip_jr_get(jr, pos, "mode", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"mode\"");
    }
    {
        mip_jr_push(jr, "mode");
        if (mip_jr_u8(jr, vp, &out->mode)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    return 0;
}

/* ---- mip_aiding_ecef_position_t */

static int mip_aiding_ecef_position_read(mip_reader_t *r, mip_aiding_ecef_position_t *out) {
    size_t i;
    mip_rd_push(r, "time");
    if (mip_aiding_time_read(r, &out->time)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "frame_id");
    if (mip_rd_u8(r, &out->frame_id)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "position");
    for (i = 0; i < 3; i++) {
        mip_rd_index(r, i);
        if (mip_rd_f64(r, &out->position[i])) {
            return -1;
        }
    }
    mip_rd_pop(r);
    mip_rd_push(r, "uncertainty");
    for (i = 0; i < 3; i++) {
        mip_rd_index(r, i);
        if (mip_rd_f32(r, &out->uncertainty[i])) {
            return -1;
        }
    }
    mip_rd_pop(r);
    mip_rd_push(r, "valid_flags");
    if (mip_rd_u16(r, &out->valid_flags)) {
        return -1;
    }
    mip_rd_pop(r);
    return mip_rd_finish(r);
}

static mip_status_t mip_aiding_ecef_position_write(mip_writer_t *w, const mip_aiding_ecef_position_t *in) {
    mip_status_t st;
    size_t i;
    if ((st = mip_aiding_time_write(w, &in->time)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_u8(w, &in->frame_id)) != MIP_OK) {
        return st;
    }
    for (i = 0; i < 3; i++) {
        if ((st = mip_wr_f64(w, &in->position[i])) != MIP_OK) {
            return st;
        }
    }
    for (i = 0; i < 3; i++) {
        if ((st = mip_wr_f32(w, &in->uncertainty[i])) != MIP_OK) {
            return st;
        }
    }
    if ((st = mip_wr_u16(w, &in->valid_flags)) != MIP_OK) {
        return st;
    }
    return MIP_OK;
}

mip_status_t mip_aiding_ecef_position_encode(const mip_aiding_ecef_position_t *value, uint8_t *buf,
                                             size_t cap, size_t *len_out) {
    mip_writer_t w;
    mip_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mip_writer_init(&w, buf, cap);
    st = mip_aiding_ecef_position_write(&w, value);
    if (st == MIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mip_status_t mip_aiding_ecef_position_decode(const uint8_t *data, size_t len, mip_aiding_ecef_position_t *out,
                                             mip_decode_error_t *err) {
    mip_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mip_aiding_ecef_position_read(&r, out) ? MIP_ERR_DECODE : MIP_OK;
}

void mip_aiding_ecef_position_to_json(mip_jw_t *w, const mip_aiding_ecef_position_t *in) {
    int first = 1;
    size_t i;
    mip_jw_raw(w, "{", 1);
    mip_jw_key(w, &first, "time");
    mip_aiding_time_to_json(w, &in->time);
    mip_jw_key(w, &first, "frame_id");
    mip_jw_u8(w, &in->frame_id);
    mip_jw_key(w, &first, "position");
    mip_jw_raw(w, "[", 1);
    for (i = 0; i < 3; i++) {
        mip_jw_sep(w, i);
        mip_jw_f64(w, &in->position[i]);
    }
    mip_jw_raw(w, "]", 1);
    mip_jw_key(w, &first, "uncertainty");
    mip_jw_raw(w, "[", 1);
    for (i = 0; i < 3; i++) {
        mip_jw_sep(w, i);
        mip_jw_f32(w, &in->uncertainty[i]);
    }
    mip_jw_raw(w, "]", 1);
    mip_jw_key(w, &first, "valid_flags");
    mip_jw_u16(w, &in->valid_flags);
    mip_jw_raw(w, "}", 1);
}

int mip_aiding_ecef_position_from_json(mip_jr_t *jr, size_t pos, mip_aiding_ecef_position_t *out) {
    static const char *const keys[] = {"time", "frame_id", "position", "uncertainty", "valid_flags"};
    size_t vp = 0;
    int found;
    size_t i;
    size_t it = 0;
    size_t ep = 0;
    memset(out, 0, sizeof *out);
    if (mip_jr_object(jr, pos, keys, 5)) {
        return -1;
    }
    found = mip_jr_get(jr, pos, "time", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"time\"");
    }
    {
        mip_jr_push(jr, "time");
        if (mip_aiding_time_from_json(jr, vp, &out->time)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "frame_id", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"frame_id\"");
    }
    {
        mip_jr_push(jr, "frame_id");
        if (mip_jr_u8(jr, vp, &out->frame_id)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "position", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"position\"");
    }
    {
        mip_jr_push(jr, "position");
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
            if (i >= 3) {
                return mip_jr_fail(jr, "more than 3 elements");
            }
            mip_jr_index(jr, i);
            if (mip_jr_f64(jr, ep, &out->position[i])) {
                return -1;
            }
        }
        mip_jr_index(jr, SIZE_MAX);
        if (i != 3) {
            return mip_jr_fail(jr, "expected 3 elements, got %zu", i);
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "uncertainty", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"uncertainty\"");
    }
    {
        mip_jr_push(jr, "uncertainty");
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
            if (i >= 3) {
                return mip_jr_fail(jr, "more than 3 elements");
            }
            mip_jr_index(jr, i);
            if (mip_jr_f32(jr, ep, &out->uncertainty[i])) {
                return -1;
            }
        }
        mip_jr_index(jr, SIZE_MAX);
        if (i != 3) {
            return mip_jr_fail(jr, "expected 3 elements, got %zu", i);
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "valid_flags", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"valid_flags\"");
    }
    {
        mip_jr_push(jr, "valid_flags");
        if (mip_jr_u16(jr, vp, &out->valid_flags)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    return 0;
}

/* ---- mip_aiding_llh_position_t */

static int mip_aiding_llh_position_read(mip_reader_t *r, mip_aiding_llh_position_t *out) {
    size_t i;
    mip_rd_push(r, "time");
    if (mip_aiding_time_read(r, &out->time)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "frame_id");
    if (mip_rd_u8(r, &out->frame_id)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "latitude");
    if (mip_rd_f64(r, &out->latitude)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "longitude");
    if (mip_rd_f64(r, &out->longitude)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "height");
    if (mip_rd_f64(r, &out->height)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "uncertainty");
    for (i = 0; i < 3; i++) {
        mip_rd_index(r, i);
        if (mip_rd_f32(r, &out->uncertainty[i])) {
            return -1;
        }
    }
    mip_rd_pop(r);
    mip_rd_push(r, "valid_flags");
    if (mip_rd_u16(r, &out->valid_flags)) {
        return -1;
    }
    mip_rd_pop(r);
    return mip_rd_finish(r);
}

static mip_status_t mip_aiding_llh_position_write(mip_writer_t *w, const mip_aiding_llh_position_t *in) {
    mip_status_t st;
    size_t i;
    if ((st = mip_aiding_time_write(w, &in->time)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_u8(w, &in->frame_id)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_f64(w, &in->latitude)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_f64(w, &in->longitude)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_f64(w, &in->height)) != MIP_OK) {
        return st;
    }
    for (i = 0; i < 3; i++) {
        if ((st = mip_wr_f32(w, &in->uncertainty[i])) != MIP_OK) {
            return st;
        }
    }
    if ((st = mip_wr_u16(w, &in->valid_flags)) != MIP_OK) {
        return st;
    }
    return MIP_OK;
}

mip_status_t mip_aiding_llh_position_encode(const mip_aiding_llh_position_t *value, uint8_t *buf, size_t cap,
                                            size_t *len_out) {
    mip_writer_t w;
    mip_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mip_writer_init(&w, buf, cap);
    st = mip_aiding_llh_position_write(&w, value);
    if (st == MIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mip_status_t mip_aiding_llh_position_decode(const uint8_t *data, size_t len, mip_aiding_llh_position_t *out,
                                            mip_decode_error_t *err) {
    mip_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mip_aiding_llh_position_read(&r, out) ? MIP_ERR_DECODE : MIP_OK;
}

void mip_aiding_llh_position_to_json(mip_jw_t *w, const mip_aiding_llh_position_t *in) {
    int first = 1;
    size_t i;
    mip_jw_raw(w, "{", 1);
    mip_jw_key(w, &first, "time");
    mip_aiding_time_to_json(w, &in->time);
    mip_jw_key(w, &first, "frame_id");
    mip_jw_u8(w, &in->frame_id);
    mip_jw_key(w, &first, "latitude");
    mip_jw_f64(w, &in->latitude);
    mip_jw_key(w, &first, "longitude");
    mip_jw_f64(w, &in->longitude);
    mip_jw_key(w, &first, "height");
    mip_jw_f64(w, &in->height);
    mip_jw_key(w, &first, "uncertainty");
    mip_jw_raw(w, "[", 1);
    for (i = 0; i < 3; i++) {
        mip_jw_sep(w, i);
        mip_jw_f32(w, &in->uncertainty[i]);
    }
    mip_jw_raw(w, "]", 1);
    mip_jw_key(w, &first, "valid_flags");
    mip_jw_u16(w, &in->valid_flags);
    mip_jw_raw(w, "}", 1);
}

int mip_aiding_llh_position_from_json(mip_jr_t *jr, size_t pos, mip_aiding_llh_position_t *out) {
    static const char *const keys[] = {"time",   "frame_id",    "latitude",   "longitude",
                                       "height", "uncertainty", "valid_flags"};
    size_t vp = 0;
    int found;
    size_t i;
    size_t it = 0;
    size_t ep = 0;
    memset(out, 0, sizeof *out);
    if (mip_jr_object(jr, pos, keys, 7)) {
        return -1;
    }
    found = mip_jr_get(jr, pos, "time", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"time\"");
    }
    {
        mip_jr_push(jr, "time");
        if (mip_aiding_time_from_json(jr, vp, &out->time)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "frame_id", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"frame_id\"");
    }
    {
        mip_jr_push(jr, "frame_id");
        if (mip_jr_u8(jr, vp, &out->frame_id)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "latitude", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"latitude\"");
    }
    {
        mip_jr_push(jr, "latitude");
        if (mip_jr_f64(jr, vp, &out->latitude)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "longitude", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"longitude\"");
    }
    {
        mip_jr_push(jr, "longitude");
        if (mip_jr_f64(jr, vp, &out->longitude)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "height", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"height\"");
    }
    {
        mip_jr_push(jr, "height");
        if (mip_jr_f64(jr, vp, &out->height)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "uncertainty", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"uncertainty\"");
    }
    {
        mip_jr_push(jr, "uncertainty");
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
            if (i >= 3) {
                return mip_jr_fail(jr, "more than 3 elements");
            }
            mip_jr_index(jr, i);
            if (mip_jr_f32(jr, ep, &out->uncertainty[i])) {
                return -1;
            }
        }
        mip_jr_index(jr, SIZE_MAX);
        if (i != 3) {
            return mip_jr_fail(jr, "expected 3 elements, got %zu", i);
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "valid_flags", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"valid_flags\"");
    }
    {
        mip_jr_push(jr, "valid_flags");
        if (mip_jr_u16(jr, vp, &out->valid_flags)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    return 0;
}

/* ---- mip_aiding_height_above_ellipsoid_t */

static int mip_aiding_height_above_ellipsoid_read(mip_reader_t *r, mip_aiding_height_above_ellipsoid_t *out) {
    mip_rd_push(r, "time");
    if (mip_aiding_time_read(r, &out->time)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "frame_id");
    if (mip_rd_u8(r, &out->frame_id)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "height");
    if (mip_rd_f32(r, &out->height)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "uncertainty");
    if (mip_rd_f32(r, &out->uncertainty)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "valid_flags");
    if (mip_rd_u16(r, &out->valid_flags)) {
        return -1;
    }
    mip_rd_pop(r);
    return mip_rd_finish(r);
}

static mip_status_t mip_aiding_height_above_ellipsoid_write(mip_writer_t *w,
                                                            const mip_aiding_height_above_ellipsoid_t *in) {
    mip_status_t st;
    if ((st = mip_aiding_time_write(w, &in->time)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_u8(w, &in->frame_id)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_f32(w, &in->height)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_f32(w, &in->uncertainty)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_u16(w, &in->valid_flags)) != MIP_OK) {
        return st;
    }
    return MIP_OK;
}

mip_status_t mip_aiding_height_above_ellipsoid_encode(const mip_aiding_height_above_ellipsoid_t *value,
                                                      uint8_t *buf, size_t cap, size_t *len_out) {
    mip_writer_t w;
    mip_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mip_writer_init(&w, buf, cap);
    st = mip_aiding_height_above_ellipsoid_write(&w, value);
    if (st == MIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mip_status_t mip_aiding_height_above_ellipsoid_decode(const uint8_t *data, size_t len,
                                                      mip_aiding_height_above_ellipsoid_t *out,
                                                      mip_decode_error_t *err) {
    mip_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mip_aiding_height_above_ellipsoid_read(&r, out) ? MIP_ERR_DECODE : MIP_OK;
}

void mip_aiding_height_above_ellipsoid_to_json(mip_jw_t *w, const mip_aiding_height_above_ellipsoid_t *in) {
    int first = 1;
    mip_jw_raw(w, "{", 1);
    mip_jw_key(w, &first, "time");
    mip_aiding_time_to_json(w, &in->time);
    mip_jw_key(w, &first, "frame_id");
    mip_jw_u8(w, &in->frame_id);
    mip_jw_key(w, &first, "height");
    mip_jw_f32(w, &in->height);
    mip_jw_key(w, &first, "uncertainty");
    mip_jw_f32(w, &in->uncertainty);
    mip_jw_key(w, &first, "valid_flags");
    mip_jw_u16(w, &in->valid_flags);
    mip_jw_raw(w, "}", 1);
}

int mip_aiding_height_above_ellipsoid_from_json(mip_jr_t *jr, size_t pos,
                                                mip_aiding_height_above_ellipsoid_t *out) {
    static const char *const keys[] = {"time", "frame_id", "height", "uncertainty", "valid_flags"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mip_jr_object(jr, pos, keys, 5)) {
        return -1;
    }
    found = mip_jr_get(jr, pos, "time", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"time\"");
    }
    {
        mip_jr_push(jr, "time");
        if (mip_aiding_time_from_json(jr, vp, &out->time)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "frame_id", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"frame_id\"");
    }
    {
        mip_jr_push(jr, "frame_id");
        if (mip_jr_u8(jr, vp, &out->frame_id)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "height", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"height\"");
    }
    {
        mip_jr_push(jr, "height");
        if (mip_jr_f32(jr, vp, &out->height)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "uncertainty", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"uncertainty\"");
    }
    {
        mip_jr_push(jr, "uncertainty");
        if (mip_jr_f32(jr, vp, &out->uncertainty)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "valid_flags", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"valid_flags\"");
    }
    {
        mip_jr_push(jr, "valid_flags");
        if (mip_jr_u16(jr, vp, &out->valid_flags)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    return 0;
}

/* ---- mip_aiding_ecef_velocity_t */

static int mip_aiding_ecef_velocity_read(mip_reader_t *r, mip_aiding_ecef_velocity_t *out) {
    size_t i;
    mip_rd_push(r, "time");
    if (mip_aiding_time_read(r, &out->time)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "frame_id");
    if (mip_rd_u8(r, &out->frame_id)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "velocity");
    for (i = 0; i < 3; i++) {
        mip_rd_index(r, i);
        if (mip_rd_f32(r, &out->velocity[i])) {
            return -1;
        }
    }
    mip_rd_pop(r);
    mip_rd_push(r, "uncertainty");
    for (i = 0; i < 3; i++) {
        mip_rd_index(r, i);
        if (mip_rd_f32(r, &out->uncertainty[i])) {
            return -1;
        }
    }
    mip_rd_pop(r);
    mip_rd_push(r, "valid_flags");
    if (mip_rd_u16(r, &out->valid_flags)) {
        return -1;
    }
    mip_rd_pop(r);
    return mip_rd_finish(r);
}

static mip_status_t mip_aiding_ecef_velocity_write(mip_writer_t *w, const mip_aiding_ecef_velocity_t *in) {
    mip_status_t st;
    size_t i;
    if ((st = mip_aiding_time_write(w, &in->time)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_u8(w, &in->frame_id)) != MIP_OK) {
        return st;
    }
    for (i = 0; i < 3; i++) {
        if ((st = mip_wr_f32(w, &in->velocity[i])) != MIP_OK) {
            return st;
        }
    }
    for (i = 0; i < 3; i++) {
        if ((st = mip_wr_f32(w, &in->uncertainty[i])) != MIP_OK) {
            return st;
        }
    }
    if ((st = mip_wr_u16(w, &in->valid_flags)) != MIP_OK) {
        return st;
    }
    return MIP_OK;
}

mip_status_t mip_aiding_ecef_velocity_encode(const mip_aiding_ecef_velocity_t *value, uint8_t *buf,
                                             size_t cap, size_t *len_out) {
    mip_writer_t w;
    mip_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mip_writer_init(&w, buf, cap);
    st = mip_aiding_ecef_velocity_write(&w, value);
    if (st == MIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mip_status_t mip_aiding_ecef_velocity_decode(const uint8_t *data, size_t len, mip_aiding_ecef_velocity_t *out,
                                             mip_decode_error_t *err) {
    mip_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mip_aiding_ecef_velocity_read(&r, out) ? MIP_ERR_DECODE : MIP_OK;
}

void mip_aiding_ecef_velocity_to_json(mip_jw_t *w, const mip_aiding_ecef_velocity_t *in) {
    int first = 1;
    size_t i;
    mip_jw_raw(w, "{", 1);
    mip_jw_key(w, &first, "time");
    mip_aiding_time_to_json(w, &in->time);
    mip_jw_key(w, &first, "frame_id");
    mip_jw_u8(w, &in->frame_id);
    mip_jw_key(w, &first, "velocity");
    mip_jw_raw(w, "[", 1);
    for (i = 0; i < 3; i++) {
        mip_jw_sep(w, i);
        mip_jw_f32(w, &in->velocity[i]);
    }
    mip_jw_raw(w, "]", 1);
    mip_jw_key(w, &first, "uncertainty");
    mip_jw_raw(w, "[", 1);
    for (i = 0; i < 3; i++) {
        mip_jw_sep(w, i);
        mip_jw_f32(w, &in->uncertainty[i]);
    }
    mip_jw_raw(w, "]", 1);
    mip_jw_key(w, &first, "valid_flags");
    mip_jw_u16(w, &in->valid_flags);
    mip_jw_raw(w, "}", 1);
}

int mip_aiding_ecef_velocity_from_json(mip_jr_t *jr, size_t pos, mip_aiding_ecef_velocity_t *out) {
    static const char *const keys[] = {"time", "frame_id", "velocity", "uncertainty", "valid_flags"};
    size_t vp = 0;
    int found;
    size_t i;
    size_t it = 0;
    size_t ep = 0;
    memset(out, 0, sizeof *out);
    if (mip_jr_object(jr, pos, keys, 5)) {
        return -1;
    }
    found = mip_jr_get(jr, pos, "time", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"time\"");
    }
    {
        mip_jr_push(jr, "time");
        if (mip_aiding_time_from_json(jr, vp, &out->time)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "frame_id", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"frame_id\"");
    }
    {
        mip_jr_push(jr, "frame_id");
        if (mip_jr_u8(jr, vp, &out->frame_id)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "velocity", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"velocity\"");
    }
    {
        mip_jr_push(jr, "velocity");
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
            if (i >= 3) {
                return mip_jr_fail(jr, "more than 3 elements");
            }
            mip_jr_index(jr, i);
            if (mip_jr_f32(jr, ep, &out->velocity[i])) {
                return -1;
            }
        }
        mip_jr_index(jr, SIZE_MAX);
        if (i != 3) {
            return mip_jr_fail(jr, "expected 3 elements, got %zu", i);
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "uncertainty", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"uncertainty\"");
    }
    {
        mip_jr_push(jr, "uncertainty");
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
            if (i >= 3) {
                return mip_jr_fail(jr, "more than 3 elements");
            }
            mip_jr_index(jr, i);
            if (mip_jr_f32(jr, ep, &out->uncertainty[i])) {
                return -1;
            }
        }
        mip_jr_index(jr, SIZE_MAX);
        if (i != 3) {
            return mip_jr_fail(jr, "expected 3 elements, got %zu", i);
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "valid_flags", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"valid_flags\"");
    }
    {
        mip_jr_push(jr, "valid_flags");
        if (mip_jr_u16(jr, vp, &out->valid_flags)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    return 0;
}

/* ---- mip_aiding_ned_velocity_t */

static int mip_aiding_ned_velocity_read(mip_reader_t *r, mip_aiding_ned_velocity_t *out) {
    size_t i;
    mip_rd_push(r, "time");
    if (mip_aiding_time_read(r, &out->time)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "frame_id");
    if (mip_rd_u8(r, &out->frame_id)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "velocity");
    for (i = 0; i < 3; i++) {
        mip_rd_index(r, i);
        if (mip_rd_f32(r, &out->velocity[i])) {
            return -1;
        }
    }
    mip_rd_pop(r);
    mip_rd_push(r, "uncertainty");
    for (i = 0; i < 3; i++) {
        mip_rd_index(r, i);
        if (mip_rd_f32(r, &out->uncertainty[i])) {
            return -1;
        }
    }
    mip_rd_pop(r);
    mip_rd_push(r, "valid_flags");
    if (mip_rd_u16(r, &out->valid_flags)) {
        return -1;
    }
    mip_rd_pop(r);
    return mip_rd_finish(r);
}

static mip_status_t mip_aiding_ned_velocity_write(mip_writer_t *w, const mip_aiding_ned_velocity_t *in) {
    mip_status_t st;
    size_t i;
    if ((st = mip_aiding_time_write(w, &in->time)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_u8(w, &in->frame_id)) != MIP_OK) {
        return st;
    }
    for (i = 0; i < 3; i++) {
        if ((st = mip_wr_f32(w, &in->velocity[i])) != MIP_OK) {
            return st;
        }
    }
    for (i = 0; i < 3; i++) {
        if ((st = mip_wr_f32(w, &in->uncertainty[i])) != MIP_OK) {
            return st;
        }
    }
    if ((st = mip_wr_u16(w, &in->valid_flags)) != MIP_OK) {
        return st;
    }
    return MIP_OK;
}

mip_status_t mip_aiding_ned_velocity_encode(const mip_aiding_ned_velocity_t *value, uint8_t *buf, size_t cap,
                                            size_t *len_out) {
    mip_writer_t w;
    mip_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mip_writer_init(&w, buf, cap);
    st = mip_aiding_ned_velocity_write(&w, value);
    if (st == MIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mip_status_t mip_aiding_ned_velocity_decode(const uint8_t *data, size_t len, mip_aiding_ned_velocity_t *out,
                                            mip_decode_error_t *err) {
    mip_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mip_aiding_ned_velocity_read(&r, out) ? MIP_ERR_DECODE : MIP_OK;
}

void mip_aiding_ned_velocity_to_json(mip_jw_t *w, const mip_aiding_ned_velocity_t *in) {
    int first = 1;
    size_t i;
    mip_jw_raw(w, "{", 1);
    mip_jw_key(w, &first, "time");
    mip_aiding_time_to_json(w, &in->time);
    mip_jw_key(w, &first, "frame_id");
    mip_jw_u8(w, &in->frame_id);
    mip_jw_key(w, &first, "velocity");
    mip_jw_raw(w, "[", 1);
    for (i = 0; i < 3; i++) {
        mip_jw_sep(w, i);
        mip_jw_f32(w, &in->velocity[i]);
    }
    mip_jw_raw(w, "]", 1);
    mip_jw_key(w, &first, "uncertainty");
    mip_jw_raw(w, "[", 1);
    for (i = 0; i < 3; i++) {
        mip_jw_sep(w, i);
        mip_jw_f32(w, &in->uncertainty[i]);
    }
    mip_jw_raw(w, "]", 1);
    mip_jw_key(w, &first, "valid_flags");
    mip_jw_u16(w, &in->valid_flags);
    mip_jw_raw(w, "}", 1);
}

int mip_aiding_ned_velocity_from_json(mip_jr_t *jr, size_t pos, mip_aiding_ned_velocity_t *out) {
    static const char *const keys[] = {"time", "frame_id", "velocity", "uncertainty", "valid_flags"};
    size_t vp = 0;
    int found;
    size_t i;
    size_t it = 0;
    size_t ep = 0;
    memset(out, 0, sizeof *out);
    if (mip_jr_object(jr, pos, keys, 5)) {
        return -1;
    }
    found = mip_jr_get(jr, pos, "time", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"time\"");
    }
    {
        mip_jr_push(jr, "time");
        if (mip_aiding_time_from_json(jr, vp, &out->time)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "frame_id", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"frame_id\"");
    }
    {
        mip_jr_push(jr, "frame_id");
        if (mip_jr_u8(jr, vp, &out->frame_id)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "velocity", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"velocity\"");
    }
    {
        mip_jr_push(jr, "velocity");
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
            if (i >= 3) {
                return mip_jr_fail(jr, "more than 3 elements");
            }
            mip_jr_index(jr, i);
            if (mip_jr_f32(jr, ep, &out->velocity[i])) {
                return -1;
            }
        }
        mip_jr_index(jr, SIZE_MAX);
        if (i != 3) {
            return mip_jr_fail(jr, "expected 3 elements, got %zu", i);
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "uncertainty", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"uncertainty\"");
    }
    {
        mip_jr_push(jr, "uncertainty");
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
            if (i >= 3) {
                return mip_jr_fail(jr, "more than 3 elements");
            }
            mip_jr_index(jr, i);
            if (mip_jr_f32(jr, ep, &out->uncertainty[i])) {
                return -1;
            }
        }
        mip_jr_index(jr, SIZE_MAX);
        if (i != 3) {
            return mip_jr_fail(jr, "expected 3 elements, got %zu", i);
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "valid_flags", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"valid_flags\"");
    }
    {
        mip_jr_push(jr, "valid_flags");
        if (mip_jr_u16(jr, vp, &out->valid_flags)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    return 0;
}

/* ---- mip_aiding_body_frame_velocity_t */

static int mip_aiding_body_frame_velocity_read(mip_reader_t *r, mip_aiding_body_frame_velocity_t *out) {
    size_t i;
    mip_rd_push(r, "time");
    if (mip_aiding_time_read(r, &out->time)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "frame_id");
    if (mip_rd_u8(r, &out->frame_id)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "velocity");
    for (i = 0; i < 3; i++) {
        mip_rd_index(r, i);
        if (mip_rd_f32(r, &out->velocity[i])) {
            return -1;
        }
    }
    mip_rd_pop(r);
    mip_rd_push(r, "uncertainty");
    for (i = 0; i < 3; i++) {
        mip_rd_index(r, i);
        if (mip_rd_f32(r, &out->uncertainty[i])) {
            return -1;
        }
    }
    mip_rd_pop(r);
    mip_rd_push(r, "valid_flags");
    if (mip_rd_u16(r, &out->valid_flags)) {
        return -1;
    }
    mip_rd_pop(r);
    return mip_rd_finish(r);
}

static mip_status_t mip_aiding_body_frame_velocity_write(mip_writer_t *w,
                                                         const mip_aiding_body_frame_velocity_t *in) {
    mip_status_t st;
    size_t i;
    if ((st = mip_aiding_time_write(w, &in->time)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_u8(w, &in->frame_id)) != MIP_OK) {
        return st;
    }
    for (i = 0; i < 3; i++) {
        if ((st = mip_wr_f32(w, &in->velocity[i])) != MIP_OK) {
            return st;
        }
    }
    for (i = 0; i < 3; i++) {
        if ((st = mip_wr_f32(w, &in->uncertainty[i])) != MIP_OK) {
            return st;
        }
    }
    if ((st = mip_wr_u16(w, &in->valid_flags)) != MIP_OK) {
        return st;
    }
    return MIP_OK;
}

mip_status_t mip_aiding_body_frame_velocity_encode(const mip_aiding_body_frame_velocity_t *value,
                                                   uint8_t *buf, size_t cap, size_t *len_out) {
    mip_writer_t w;
    mip_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mip_writer_init(&w, buf, cap);
    st = mip_aiding_body_frame_velocity_write(&w, value);
    if (st == MIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mip_status_t mip_aiding_body_frame_velocity_decode(const uint8_t *data, size_t len,
                                                   mip_aiding_body_frame_velocity_t *out,
                                                   mip_decode_error_t *err) {
    mip_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mip_aiding_body_frame_velocity_read(&r, out) ? MIP_ERR_DECODE : MIP_OK;
}

void mip_aiding_body_frame_velocity_to_json(mip_jw_t *w, const mip_aiding_body_frame_velocity_t *in) {
    int first = 1;
    size_t i;
    mip_jw_raw(w, "{", 1);
    mip_jw_key(w, &first, "time");
    mip_aiding_time_to_json(w, &in->time);
    mip_jw_key(w, &first, "frame_id");
    mip_jw_u8(w, &in->frame_id);
    mip_jw_key(w, &first, "velocity");
    mip_jw_raw(w, "[", 1);
    for (i = 0; i < 3; i++) {
        mip_jw_sep(w, i);
        mip_jw_f32(w, &in->velocity[i]);
    }
    mip_jw_raw(w, "]", 1);
    mip_jw_key(w, &first, "uncertainty");
    mip_jw_raw(w, "[", 1);
    for (i = 0; i < 3; i++) {
        mip_jw_sep(w, i);
        mip_jw_f32(w, &in->uncertainty[i]);
    }
    mip_jw_raw(w, "]", 1);
    mip_jw_key(w, &first, "valid_flags");
    mip_jw_u16(w, &in->valid_flags);
    mip_jw_raw(w, "}", 1);
}

int mip_aiding_body_frame_velocity_from_json(mip_jr_t *jr, size_t pos,
                                             mip_aiding_body_frame_velocity_t *out) {
    static const char *const keys[] = {"time", "frame_id", "velocity", "uncertainty", "valid_flags"};
    size_t vp = 0;
    int found;
    size_t i;
    size_t it = 0;
    size_t ep = 0;
    memset(out, 0, sizeof *out);
    if (mip_jr_object(jr, pos, keys, 5)) {
        return -1;
    }
    found = mip_jr_get(jr, pos, "time", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"time\"");
    }
    {
        mip_jr_push(jr, "time");
        if (mip_aiding_time_from_json(jr, vp, &out->time)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "frame_id", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"frame_id\"");
    }
    {
        mip_jr_push(jr, "frame_id");
        if (mip_jr_u8(jr, vp, &out->frame_id)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "velocity", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"velocity\"");
    }
    {
        mip_jr_push(jr, "velocity");
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
            if (i >= 3) {
                return mip_jr_fail(jr, "more than 3 elements");
            }
            mip_jr_index(jr, i);
            if (mip_jr_f32(jr, ep, &out->velocity[i])) {
                return -1;
            }
        }
        mip_jr_index(jr, SIZE_MAX);
        if (i != 3) {
            return mip_jr_fail(jr, "expected 3 elements, got %zu", i);
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "uncertainty", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"uncertainty\"");
    }
    {
        mip_jr_push(jr, "uncertainty");
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
            if (i >= 3) {
                return mip_jr_fail(jr, "more than 3 elements");
            }
            mip_jr_index(jr, i);
            if (mip_jr_f32(jr, ep, &out->uncertainty[i])) {
                return -1;
            }
        }
        mip_jr_index(jr, SIZE_MAX);
        if (i != 3) {
            return mip_jr_fail(jr, "expected 3 elements, got %zu", i);
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "valid_flags", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"valid_flags\"");
    }
    {
        mip_jr_push(jr, "valid_flags");
        if (mip_jr_u16(jr, vp, &out->valid_flags)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    return 0;
}

/* ---- mip_aiding_true_heading_t */

static int mip_aiding_true_heading_read(mip_reader_t *r, mip_aiding_true_heading_t *out) {
    mip_rd_push(r, "time");
    if (mip_aiding_time_read(r, &out->time)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "frame_id");
    if (mip_rd_u8(r, &out->frame_id)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "heading");
    if (mip_rd_f32(r, &out->heading)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "uncertainty");
    if (mip_rd_f32(r, &out->uncertainty)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "valid_flags");
    if (mip_rd_u16(r, &out->valid_flags)) {
        return -1;
    }
    mip_rd_pop(r);
    return mip_rd_finish(r);
}

static mip_status_t mip_aiding_true_heading_write(mip_writer_t *w, const mip_aiding_true_heading_t *in) {
    mip_status_t st;
    if ((st = mip_aiding_time_write(w, &in->time)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_u8(w, &in->frame_id)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_f32(w, &in->heading)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_f32(w, &in->uncertainty)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_u16(w, &in->valid_flags)) != MIP_OK) {
        return st;
    }
    return MIP_OK;
}

mip_status_t mip_aiding_true_heading_encode(const mip_aiding_true_heading_t *value, uint8_t *buf, size_t cap,
                                            size_t *len_out) {
    mip_writer_t w;
    mip_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mip_writer_init(&w, buf, cap);
    st = mip_aiding_true_heading_write(&w, value);
    if (st == MIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mip_status_t mip_aiding_true_heading_decode(const uint8_t *data, size_t len, mip_aiding_true_heading_t *out,
                                            mip_decode_error_t *err) {
    mip_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mip_aiding_true_heading_read(&r, out) ? MIP_ERR_DECODE : MIP_OK;
}

void mip_aiding_true_heading_to_json(mip_jw_t *w, const mip_aiding_true_heading_t *in) {
    int first = 1;
    mip_jw_raw(w, "{", 1);
    mip_jw_key(w, &first, "time");
    mip_aiding_time_to_json(w, &in->time);
    mip_jw_key(w, &first, "frame_id");
    mip_jw_u8(w, &in->frame_id);
    mip_jw_key(w, &first, "heading");
    mip_jw_f32(w, &in->heading);
    mip_jw_key(w, &first, "uncertainty");
    mip_jw_f32(w, &in->uncertainty);
    mip_jw_key(w, &first, "valid_flags");
    mip_jw_u16(w, &in->valid_flags);
    mip_jw_raw(w, "}", 1);
}

int mip_aiding_true_heading_from_json(mip_jr_t *jr, size_t pos, mip_aiding_true_heading_t *out) {
    static const char *const keys[] = {"time", "frame_id", "heading", "uncertainty", "valid_flags"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mip_jr_object(jr, pos, keys, 5)) {
        return -1;
    }
    found = mip_jr_get(jr, pos, "time", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"time\"");
    }
    {
        mip_jr_push(jr, "time");
        if (mip_aiding_time_from_json(jr, vp, &out->time)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "frame_id", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"frame_id\"");
    }
    {
        mip_jr_push(jr, "frame_id");
        if (mip_jr_u8(jr, vp, &out->frame_id)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "heading", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"heading\"");
    }
    {
        mip_jr_push(jr, "heading");
        if (mip_jr_f32(jr, vp, &out->heading)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "uncertainty", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"uncertainty\"");
    }
    {
        mip_jr_push(jr, "uncertainty");
        if (mip_jr_f32(jr, vp, &out->uncertainty)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "valid_flags", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"valid_flags\"");
    }
    {
        mip_jr_push(jr, "valid_flags");
        if (mip_jr_u16(jr, vp, &out->valid_flags)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    return 0;
}

/* ---- mip_aiding_magnetic_field_t */

static int mip_aiding_magnetic_field_read(mip_reader_t *r, mip_aiding_magnetic_field_t *out) {
    size_t i;
    mip_rd_push(r, "time");
    if (mip_aiding_time_read(r, &out->time)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "frame_id");
    if (mip_rd_u8(r, &out->frame_id)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "magnetic_field");
    for (i = 0; i < 3; i++) {
        mip_rd_index(r, i);
        if (mip_rd_f32(r, &out->magnetic_field[i])) {
            return -1;
        }
    }
    mip_rd_pop(r);
    mip_rd_push(r, "uncertainty");
    for (i = 0; i < 3; i++) {
        mip_rd_index(r, i);
        if (mip_rd_f32(r, &out->uncertainty[i])) {
            return -1;
        }
    }
    mip_rd_pop(r);
    mip_rd_push(r, "valid_flags");
    if (mip_rd_u16(r, &out->valid_flags)) {
        return -1;
    }
    mip_rd_pop(r);
    return mip_rd_finish(r);
}

static mip_status_t mip_aiding_magnetic_field_write(mip_writer_t *w, const mip_aiding_magnetic_field_t *in) {
    mip_status_t st;
    size_t i;
    if ((st = mip_aiding_time_write(w, &in->time)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_u8(w, &in->frame_id)) != MIP_OK) {
        return st;
    }
    for (i = 0; i < 3; i++) {
        if ((st = mip_wr_f32(w, &in->magnetic_field[i])) != MIP_OK) {
            return st;
        }
    }
    for (i = 0; i < 3; i++) {
        if ((st = mip_wr_f32(w, &in->uncertainty[i])) != MIP_OK) {
            return st;
        }
    }
    if ((st = mip_wr_u16(w, &in->valid_flags)) != MIP_OK) {
        return st;
    }
    return MIP_OK;
}

mip_status_t mip_aiding_magnetic_field_encode(const mip_aiding_magnetic_field_t *value, uint8_t *buf,
                                              size_t cap, size_t *len_out) {
    mip_writer_t w;
    mip_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mip_writer_init(&w, buf, cap);
    st = mip_aiding_magnetic_field_write(&w, value);
    if (st == MIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mip_status_t mip_aiding_magnetic_field_decode(const uint8_t *data, size_t len,
                                              mip_aiding_magnetic_field_t *out, mip_decode_error_t *err) {
    mip_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mip_aiding_magnetic_field_read(&r, out) ? MIP_ERR_DECODE : MIP_OK;
}

void mip_aiding_magnetic_field_to_json(mip_jw_t *w, const mip_aiding_magnetic_field_t *in) {
    int first = 1;
    size_t i;
    mip_jw_raw(w, "{", 1);
    mip_jw_key(w, &first, "time");
    mip_aiding_time_to_json(w, &in->time);
    mip_jw_key(w, &first, "frame_id");
    mip_jw_u8(w, &in->frame_id);
    mip_jw_key(w, &first, "magnetic_field");
    mip_jw_raw(w, "[", 1);
    for (i = 0; i < 3; i++) {
        mip_jw_sep(w, i);
        mip_jw_f32(w, &in->magnetic_field[i]);
    }
    mip_jw_raw(w, "]", 1);
    mip_jw_key(w, &first, "uncertainty");
    mip_jw_raw(w, "[", 1);
    for (i = 0; i < 3; i++) {
        mip_jw_sep(w, i);
        mip_jw_f32(w, &in->uncertainty[i]);
    }
    mip_jw_raw(w, "]", 1);
    mip_jw_key(w, &first, "valid_flags");
    mip_jw_u16(w, &in->valid_flags);
    mip_jw_raw(w, "}", 1);
}

int mip_aiding_magnetic_field_from_json(mip_jr_t *jr, size_t pos, mip_aiding_magnetic_field_t *out) {
    static const char *const keys[] = {"time", "frame_id", "magnetic_field", "uncertainty", "valid_flags"};
    size_t vp = 0;
    int found;
    size_t i;
    size_t it = 0;
    size_t ep = 0;
    memset(out, 0, sizeof *out);
    if (mip_jr_object(jr, pos, keys, 5)) {
        return -1;
    }
    found = mip_jr_get(jr, pos, "time", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"time\"");
    }
    {
        mip_jr_push(jr, "time");
        if (mip_aiding_time_from_json(jr, vp, &out->time)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "frame_id", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"frame_id\"");
    }
    {
        mip_jr_push(jr, "frame_id");
        if (mip_jr_u8(jr, vp, &out->frame_id)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "magnetic_field", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"magnetic_field\"");
    }
    {
        mip_jr_push(jr, "magnetic_field");
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
            if (i >= 3) {
                return mip_jr_fail(jr, "more than 3 elements");
            }
            mip_jr_index(jr, i);
            if (mip_jr_f32(jr, ep, &out->magnetic_field[i])) {
                return -1;
            }
        }
        mip_jr_index(jr, SIZE_MAX);
        if (i != 3) {
            return mip_jr_fail(jr, "expected 3 elements, got %zu", i);
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "uncertainty", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"uncertainty\"");
    }
    {
        mip_jr_push(jr, "uncertainty");
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
            if (i >= 3) {
                return mip_jr_fail(jr, "more than 3 elements");
            }
            mip_jr_index(jr, i);
            if (mip_jr_f32(jr, ep, &out->uncertainty[i])) {
                return -1;
            }
        }
        mip_jr_index(jr, SIZE_MAX);
        if (i != 3) {
            return mip_jr_fail(jr, "expected 3 elements, got %zu", i);
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "valid_flags", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"valid_flags\"");
    }
    {
        mip_jr_push(jr, "valid_flags");
        if (mip_jr_u16(jr, vp, &out->valid_flags)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    return 0;
}

/* ---- mip_aiding_pressure_t */

static int mip_aiding_pressure_read(mip_reader_t *r, mip_aiding_pressure_t *out) {
    mip_rd_push(r, "time");
    if (mip_aiding_time_read(r, &out->time)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "frame_id");
    if (mip_rd_u8(r, &out->frame_id)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "pressure");
    if (mip_rd_f32(r, &out->pressure)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "uncertainty");
    if (mip_rd_f32(r, &out->uncertainty)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "valid_flags");
    if (mip_rd_u16(r, &out->valid_flags)) {
        return -1;
    }
    mip_rd_pop(r);
    return mip_rd_finish(r);
}

static mip_status_t mip_aiding_pressure_write(mip_writer_t *w, const mip_aiding_pressure_t *in) {
    mip_status_t st;
    if ((st = mip_aiding_time_write(w, &in->time)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_u8(w, &in->frame_id)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_f32(w, &in->pressure)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_f32(w, &in->uncertainty)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_u16(w, &in->valid_flags)) != MIP_OK) {
        return st;
    }
    return MIP_OK;
}

mip_status_t mip_aiding_pressure_encode(const mip_aiding_pressure_t *value, uint8_t *buf, size_t cap,
                                        size_t *len_out) {
    mip_writer_t w;
    mip_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mip_writer_init(&w, buf, cap);
    st = mip_aiding_pressure_write(&w, value);
    if (st == MIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mip_status_t mip_aiding_pressure_decode(const uint8_t *data, size_t len, mip_aiding_pressure_t *out,
                                        mip_decode_error_t *err) {
    mip_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mip_aiding_pressure_read(&r, out) ? MIP_ERR_DECODE : MIP_OK;
}

void mip_aiding_pressure_to_json(mip_jw_t *w, const mip_aiding_pressure_t *in) {
    int first = 1;
    mip_jw_raw(w, "{", 1);
    mip_jw_key(w, &first, "time");
    mip_aiding_time_to_json(w, &in->time);
    mip_jw_key(w, &first, "frame_id");
    mip_jw_u8(w, &in->frame_id);
    mip_jw_key(w, &first, "pressure");
    mip_jw_f32(w, &in->pressure);
    mip_jw_key(w, &first, "uncertainty");
    mip_jw_f32(w, &in->uncertainty);
    mip_jw_key(w, &first, "valid_flags");
    mip_jw_u16(w, &in->valid_flags);
    mip_jw_raw(w, "}", 1);
}

int mip_aiding_pressure_from_json(mip_jr_t *jr, size_t pos, mip_aiding_pressure_t *out) {
    static const char *const keys[] = {"time", "frame_id", "pressure", "uncertainty", "valid_flags"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mip_jr_object(jr, pos, keys, 5)) {
        return -1;
    }
    found = mip_jr_get(jr, pos, "time", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"time\"");
    }
    {
        mip_jr_push(jr, "time");
        if (mip_aiding_time_from_json(jr, vp, &out->time)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "frame_id", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"frame_id\"");
    }
    {
        mip_jr_push(jr, "frame_id");
        if (mip_jr_u8(jr, vp, &out->frame_id)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "pressure", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"pressure\"");
    }
    {
        mip_jr_push(jr, "pressure");
        if (mip_jr_f32(jr, vp, &out->pressure)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "uncertainty", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"uncertainty\"");
    }
    {
        mip_jr_push(jr, "uncertainty");
        if (mip_jr_f32(jr, vp, &out->uncertainty)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "valid_flags", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"valid_flags\"");
    }
    {
        mip_jr_push(jr, "valid_flags");
        if (mip_jr_u16(jr, vp, &out->valid_flags)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    return 0;
}
