/* Encoders and decoders of 3DM Command Set. Generated from the spec: do not edit. */
#include "mipcodec/sets/threedm.h"
#include "layouts_internal.h"
#include "types_internal.h"

#include <string.h>

/* ---- mip_threedm_event_control_t */

static int mip_threedm_event_control_read(mip_reader_t *r, mip_threedm_event_control_t *out) {
    mip_rd_push(r, "function");
    if (mip_rd_u8(r, &out->function)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "instance");
    if (mip_rd_u8(r, &out->instance)) {
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

static mip_status_t mip_threedm_event_control_write(mip_writer_t *w, const mip_threedm_event_control_t *in) {
    mip_status_t st;
    int absent = 0;
    if ((st = mip_wr_u8(w, &in->function)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_u8(w, &in->instance)) != MIP_OK) {
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

mip_status_t mip_threedm_event_control_encode(const mip_threedm_event_control_t *value, uint8_t *buf,
                                              size_t cap, size_t *len_out) {
    mip_writer_t w;
    mip_status_t st;
    mip_writer_init(&w, buf, cap);
    st = mip_threedm_event_control_write(&w, value);
    if (st == MIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mip_status_t mip_threedm_event_control_decode(const uint8_t *data, size_t len,
                                              mip_threedm_event_control_t *out, mip_decode_error_t *err) {
    mip_reader_t r;
    mip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mip_threedm_event_control_read(&r, out) ? MIP_ERR_DECODE : MIP_OK;
}

void mip_threedm_event_control_to_json(mip_jw_t *w, const mip_threedm_event_control_t *in) {
    int first = 1;
    mip_jw_raw(w, "{", 1);
    mip_jw_key(w, &first, "function");
    mip_jw_u8(w, &in->function);
    mip_jw_key(w, &first, "instance");
    mip_jw_u8(w, &in->instance);
    if (in->has_mode) {
        mip_jw_key(w, &first, "mode");
        mip_jw_u8(w, &in->mode);
    }
    mip_jw_raw(w, "}", 1);
}

int mip_threedm_event_control_from_json(mip_jr_t *jr, size_t pos, mip_threedm_event_control_t *out) {
    static const char *const keys[] = {"function", "instance", "mode"};
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
    found = mip_jr_get(jr, pos, "instance", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"instance\"");
    }
    {
        mip_jr_push(jr, "instance");
        if (mip_jr_u8(jr, vp, &out->instance)) {
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

/* ---- mip_threedm_event_control_response_t */

static int mip_threedm_event_control_response_read(mip_reader_t *r,
                                                   mip_threedm_event_control_response_t *out) {
    mip_rd_push(r, "instance");
    if (mip_rd_u8(r, &out->instance)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "mode");
    if (mip_rd_u8(r, &out->mode)) {
        return -1;
    }
    mip_rd_pop(r);
    return mip_rd_finish(r);
}

static mip_status_t mip_threedm_event_control_response_write(mip_writer_t *w,
                                                             const mip_threedm_event_control_response_t *in) {
    mip_status_t st;
    if ((st = mip_wr_u8(w, &in->instance)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_u8(w, &in->mode)) != MIP_OK) {
        return st;
    }
    return MIP_OK;
}

mip_status_t mip_threedm_event_control_response_encode(const mip_threedm_event_control_response_t *value,
                                                       uint8_t *buf, size_t cap, size_t *len_out) {
    mip_writer_t w;
    mip_status_t st;
    mip_writer_init(&w, buf, cap);
    st = mip_threedm_event_control_response_write(&w, value);
    if (st == MIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mip_status_t mip_threedm_event_control_response_decode(const uint8_t *data, size_t len,
                                                       mip_threedm_event_control_response_t *out,
                                                       mip_decode_error_t *err) {
    mip_reader_t r;
    mip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mip_threedm_event_control_response_read(&r, out) ? MIP_ERR_DECODE : MIP_OK;
}

void mip_threedm_event_control_response_to_json(mip_jw_t *w, const mip_threedm_event_control_response_t *in) {
    int first = 1;
    mip_jw_raw(w, "{", 1);
    mip_jw_key(w, &first, "instance");
    mip_jw_u8(w, &in->instance);
    mip_jw_key(w, &first, "mode");
    mip_jw_u8(w, &in->mode);
    mip_jw_raw(w, "}", 1);
}

int mip_threedm_event_control_response_from_json(mip_jr_t *jr, size_t pos,
                                                 mip_threedm_event_control_response_t *out) {
    static const char *const keys[] = {"instance", "mode"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mip_jr_object(jr, pos, keys, 2)) {
        return -1;
    }
    found = mip_jr_get(jr, pos, "instance", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"instance\"");
    }
    {
        mip_jr_push(jr, "instance");
        if (mip_jr_u8(jr, vp, &out->instance)) {
            return -1;
        }
        mip_jr_pop(jr);
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

/* ---- mip_threedm_get_event_trigger_status_t */

static int mip_threedm_get_event_trigger_status_read(mip_reader_t *r,
                                                     mip_threedm_get_event_trigger_status_t *out) {
    size_t i;
    mip_rd_push(r, "requested_count");
    if (mip_rd_u8(r, &out->requested_count)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "requested_instances");
    if (out->requested_count > 252) {
        return mip_rd_count_error(r, (uint64_t)out->requested_count, 252);
    }
    for (i = 0; i < (size_t)out->requested_count; i++) {
        mip_rd_index(r, i);
        if (mip_rd_u8(r, &out->requested_instances[i])) {
            return -1;
        }
    }
    mip_rd_pop(r);
    return mip_rd_finish(r);
}

static mip_status_t
mip_threedm_get_event_trigger_status_write(mip_writer_t *w,
                                           const mip_threedm_get_event_trigger_status_t *in) {
    mip_status_t st;
    size_t i;
    if ((st = mip_wr_u8(w, &in->requested_count)) != MIP_OK) {
        return st;
    }
    if (in->requested_count > 252) {
        return MIP_ERR_INVALID;
    }
    for (i = 0; i < (size_t)in->requested_count; i++) {
        if ((st = mip_wr_u8(w, &in->requested_instances[i])) != MIP_OK) {
            return st;
        }
    }
    return MIP_OK;
}

mip_status_t mip_threedm_get_event_trigger_status_encode(const mip_threedm_get_event_trigger_status_t *value,
                                                         uint8_t *buf, size_t cap, size_t *len_out) {
    mip_writer_t w;
    mip_status_t st;
    mip_writer_init(&w, buf, cap);
    st = mip_threedm_get_event_trigger_status_write(&w, value);
    if (st == MIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mip_status_t mip_threedm_get_event_trigger_status_decode(const uint8_t *data, size_t len,
                                                         mip_threedm_get_event_trigger_status_t *out,
                                                         mip_decode_error_t *err) {
    mip_reader_t r;
    mip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mip_threedm_get_event_trigger_status_read(&r, out) ? MIP_ERR_DECODE : MIP_OK;
}

void mip_threedm_get_event_trigger_status_to_json(mip_jw_t *w,
                                                  const mip_threedm_get_event_trigger_status_t *in) {
    int first = 1;
    size_t i;
    mip_jw_raw(w, "{", 1);
    mip_jw_key(w, &first, "requested_count");
    mip_jw_u8(w, &in->requested_count);
    mip_jw_key(w, &first, "requested_instances");
    mip_jw_raw(w, "[", 1);
    for (i = 0; i < (size_t)in->requested_count && i < 252; i++) {
        mip_jw_sep(w, i);
        mip_jw_u8(w, &in->requested_instances[i]);
    }
    mip_jw_raw(w, "]", 1);
    mip_jw_raw(w, "}", 1);
}

int mip_threedm_get_event_trigger_status_from_json(mip_jr_t *jr, size_t pos,
                                                   mip_threedm_get_event_trigger_status_t *out) {
    static const char *const keys[] = {"requested_count", "requested_instances"};
    size_t vp = 0;
    int found;
    size_t i;
    size_t it = 0;
    size_t ep = 0;
    memset(out, 0, sizeof *out);
    if (mip_jr_object(jr, pos, keys, 2)) {
        return -1;
    }
    found = mip_jr_get(jr, pos, "requested_count", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"requested_count\"");
    }
    {
        mip_jr_push(jr, "requested_count");
        if (mip_jr_u8(jr, vp, &out->requested_count)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "requested_instances", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"requested_instances\"");
    }
    {
        mip_jr_push(jr, "requested_instances");
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
            if (i >= 252) {
                return mip_jr_fail(jr, "more than 252 elements");
            }
            mip_jr_index(jr, i);
            if (mip_jr_u8(jr, ep, &out->requested_instances[i])) {
                return -1;
            }
        }
        mip_jr_index(jr, SIZE_MAX);
        if (i != (size_t)out->requested_count) {
            return mip_jr_fail(jr, "%zu elements but requested_count is %zu", i,
                               (size_t)out->requested_count);
        }
        mip_jr_pop(jr);
    }
    return 0;
}

/* ---- mip_threedm_event_trigger_status_t */

static int mip_threedm_event_trigger_status_read(mip_reader_t *r, mip_threedm_event_trigger_status_t *out) {
    size_t i;
    mip_rd_push(r, "count");
    if (mip_rd_u8(r, &out->count)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "triggers");
    if (out->count > 126) {
        return mip_rd_count_error(r, (uint64_t)out->count, 126);
    }
    for (i = 0; i < (size_t)out->count; i++) {
        mip_rd_index(r, i);
        if (mip_trigger_status_entry_read(r, &out->triggers[i])) {
            return -1;
        }
    }
    mip_rd_pop(r);
    return mip_rd_finish(r);
}

static mip_status_t mip_threedm_event_trigger_status_write(mip_writer_t *w,
                                                           const mip_threedm_event_trigger_status_t *in) {
    mip_status_t st;
    size_t i;
    if ((st = mip_wr_u8(w, &in->count)) != MIP_OK) {
        return st;
    }
    if (in->count > 126) {
        return MIP_ERR_INVALID;
    }
    for (i = 0; i < (size_t)in->count; i++) {
        if ((st = mip_trigger_status_entry_write(w, &in->triggers[i])) != MIP_OK) {
            return st;
        }
    }
    return MIP_OK;
}

mip_status_t mip_threedm_event_trigger_status_encode(const mip_threedm_event_trigger_status_t *value,
                                                     uint8_t *buf, size_t cap, size_t *len_out) {
    mip_writer_t w;
    mip_status_t st;
    mip_writer_init(&w, buf, cap);
    st = mip_threedm_event_trigger_status_write(&w, value);
    if (st == MIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mip_status_t mip_threedm_event_trigger_status_decode(const uint8_t *data, size_t len,
                                                     mip_threedm_event_trigger_status_t *out,
                                                     mip_decode_error_t *err) {
    mip_reader_t r;
    mip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mip_threedm_event_trigger_status_read(&r, out) ? MIP_ERR_DECODE : MIP_OK;
}

void mip_threedm_event_trigger_status_to_json(mip_jw_t *w, const mip_threedm_event_trigger_status_t *in) {
    int first = 1;
    size_t i;
    mip_jw_raw(w, "{", 1);
    mip_jw_key(w, &first, "count");
    mip_jw_u8(w, &in->count);
    mip_jw_key(w, &first, "triggers");
    mip_jw_raw(w, "[", 1);
    for (i = 0; i < (size_t)in->count && i < 126; i++) {
        mip_jw_sep(w, i);
        mip_trigger_status_entry_to_json(w, &in->triggers[i]);
    }
    mip_jw_raw(w, "]", 1);
    mip_jw_raw(w, "}", 1);
}

int mip_threedm_event_trigger_status_from_json(mip_jr_t *jr, size_t pos,
                                               mip_threedm_event_trigger_status_t *out) {
    static const char *const keys[] = {"count", "triggers"};
    size_t vp = 0;
    int found;
    size_t i;
    size_t it = 0;
    size_t ep = 0;
    memset(out, 0, sizeof *out);
    if (mip_jr_object(jr, pos, keys, 2)) {
        return -1;
    }
    found = mip_jr_get(jr, pos, "count", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"count\"");
    }
    {
        mip_jr_push(jr, "count");
        if (mip_jr_u8(jr, vp, &out->count)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "triggers", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"triggers\"");
    }
    {
        mip_jr_push(jr, "triggers");
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
            if (mip_trigger_status_entry_from_json(jr, ep, &out->triggers[i])) {
                return -1;
            }
        }
        mip_jr_index(jr, SIZE_MAX);
        if (i != (size_t)out->count) {
            return mip_jr_fail(jr, "%zu elements but count is %zu", i, (size_t)out->count);
        }
        mip_jr_pop(jr);
    }
    return 0;
}

/* ---- mip_threedm_get_event_action_status_t */

static int mip_threedm_get_event_action_status_read(mip_reader_t *r,
                                                    mip_threedm_get_event_action_status_t *out) {
    size_t i;
    mip_rd_push(r, "requested_count");
    if (mip_rd_u8(r, &out->requested_count)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "requested_instances");
    if (out->requested_count > 252) {
        return mip_rd_count_error(r, (uint64_t)out->requested_count, 252);
    }
    for (i = 0; i < (size_t)out->requested_count; i++) {
        mip_rd_index(r, i);
        if (mip_rd_u8(r, &out->requested_instances[i])) {
            return -1;
        }
    }
    mip_rd_pop(r);
    return mip_rd_finish(r);
}

static mip_status_t
mip_threedm_get_event_action_status_write(mip_writer_t *w, const mip_threedm_get_event_action_status_t *in) {
    mip_status_t st;
    size_t i;
    if ((st = mip_wr_u8(w, &in->requested_count)) != MIP_OK) {
        return st;
    }
    if (in->requested_count > 252) {
        return MIP_ERR_INVALID;
    }
    for (i = 0; i < (size_t)in->requested_count; i++) {
        if ((st = mip_wr_u8(w, &in->requested_instances[i])) != MIP_OK) {
            return st;
        }
    }
    return MIP_OK;
}

mip_status_t mip_threedm_get_event_action_status_encode(const mip_threedm_get_event_action_status_t *value,
                                                        uint8_t *buf, size_t cap, size_t *len_out) {
    mip_writer_t w;
    mip_status_t st;
    mip_writer_init(&w, buf, cap);
    st = mip_threedm_get_event_action_status_write(&w, value);
    if (st == MIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mip_status_t mip_threedm_get_event_action_status_decode(const uint8_t *data, size_t len,
                                                        mip_threedm_get_event_action_status_t *out,
                                                        mip_decode_error_t *err) {
    mip_reader_t r;
    mip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mip_threedm_get_event_action_status_read(&r, out) ? MIP_ERR_DECODE : MIP_OK;
}

void mip_threedm_get_event_action_status_to_json(mip_jw_t *w,
                                                 const mip_threedm_get_event_action_status_t *in) {
    int first = 1;
    size_t i;
    mip_jw_raw(w, "{", 1);
    mip_jw_key(w, &first, "requested_count");
    mip_jw_u8(w, &in->requested_count);
    mip_jw_key(w, &first, "requested_instances");
    mip_jw_raw(w, "[", 1);
    for (i = 0; i < (size_t)in->requested_count && i < 252; i++) {
        mip_jw_sep(w, i);
        mip_jw_u8(w, &in->requested_instances[i]);
    }
    mip_jw_raw(w, "]", 1);
    mip_jw_raw(w, "}", 1);
}

int mip_threedm_get_event_action_status_from_json(mip_jr_t *jr, size_t pos,
                                                  mip_threedm_get_event_action_status_t *out) {
    static const char *const keys[] = {"requested_count", "requested_instances"};
    size_t vp = 0;
    int found;
    size_t i;
    size_t it = 0;
    size_t ep = 0;
    memset(out, 0, sizeof *out);
    if (mip_jr_object(jr, pos, keys, 2)) {
        return -1;
    }
    found = mip_jr_get(jr, pos, "requested_count", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"requested_count\"");
    }
    {
        mip_jr_push(jr, "requested_count");
        if (mip_jr_u8(jr, vp, &out->requested_count)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "requested_instances", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"requested_instances\"");
    }
    {
        mip_jr_push(jr, "requested_instances");
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
            if (i >= 252) {
                return mip_jr_fail(jr, "more than 252 elements");
            }
            mip_jr_index(jr, i);
            if (mip_jr_u8(jr, ep, &out->requested_instances[i])) {
                return -1;
            }
        }
        mip_jr_index(jr, SIZE_MAX);
        if (i != (size_t)out->requested_count) {
            return mip_jr_fail(jr, "%zu elements but requested_count is %zu", i,
                               (size_t)out->requested_count);
        }
        mip_jr_pop(jr);
    }
    return 0;
}

/* ---- mip_threedm_event_action_status_t */

static int mip_threedm_event_action_status_read(mip_reader_t *r, mip_threedm_event_action_status_t *out) {
    size_t i;
    mip_rd_push(r, "count");
    if (mip_rd_u8(r, &out->count)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "actions");
    if (out->count > 126) {
        return mip_rd_count_error(r, (uint64_t)out->count, 126);
    }
    for (i = 0; i < (size_t)out->count; i++) {
        mip_rd_index(r, i);
        if (mip_action_status_entry_read(r, &out->actions[i])) {
            return -1;
        }
    }
    mip_rd_pop(r);
    return mip_rd_finish(r);
}

static mip_status_t mip_threedm_event_action_status_write(mip_writer_t *w,
                                                          const mip_threedm_event_action_status_t *in) {
    mip_status_t st;
    size_t i;
    if ((st = mip_wr_u8(w, &in->count)) != MIP_OK) {
        return st;
    }
    if (in->count > 126) {
        return MIP_ERR_INVALID;
    }
    for (i = 0; i < (size_t)in->count; i++) {
        if ((st = mip_action_status_entry_write(w, &in->actions[i])) != MIP_OK) {
            return st;
        }
    }
    return MIP_OK;
}

mip_status_t mip_threedm_event_action_status_encode(const mip_threedm_event_action_status_t *value,
                                                    uint8_t *buf, size_t cap, size_t *len_out) {
    mip_writer_t w;
    mip_status_t st;
    mip_writer_init(&w, buf, cap);
    st = mip_threedm_event_action_status_write(&w, value);
    if (st == MIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mip_status_t mip_threedm_event_action_status_decode(const uint8_t *data, size_t len,
                                                    mip_threedm_event_action_status_t *out,
                                                    mip_decode_error_t *err) {
    mip_reader_t r;
    mip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mip_threedm_event_action_status_read(&r, out) ? MIP_ERR_DECODE : MIP_OK;
}

void mip_threedm_event_action_status_to_json(mip_jw_t *w, const mip_threedm_event_action_status_t *in) {
    int first = 1;
    size_t i;
    mip_jw_raw(w, "{", 1);
    mip_jw_key(w, &first, "count");
    mip_jw_u8(w, &in->count);
    mip_jw_key(w, &first, "actions");
    mip_jw_raw(w, "[", 1);
    for (i = 0; i < (size_t)in->count && i < 126; i++) {
        mip_jw_sep(w, i);
        mip_action_status_entry_to_json(w, &in->actions[i]);
    }
    mip_jw_raw(w, "]", 1);
    mip_jw_raw(w, "}", 1);
}

int mip_threedm_event_action_status_from_json(mip_jr_t *jr, size_t pos,
                                              mip_threedm_event_action_status_t *out) {
    static const char *const keys[] = {"count", "actions"};
    size_t vp = 0;
    int found;
    size_t i;
    size_t it = 0;
    size_t ep = 0;
    memset(out, 0, sizeof *out);
    if (mip_jr_object(jr, pos, keys, 2)) {
        return -1;
    }
    found = mip_jr_get(jr, pos, "count", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"count\"");
    }
    {
        mip_jr_push(jr, "count");
        if (mip_jr_u8(jr, vp, &out->count)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "actions", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"actions\"");
    }
    {
        mip_jr_push(jr, "actions");
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
            if (mip_action_status_entry_from_json(jr, ep, &out->actions[i])) {
                return -1;
            }
        }
        mip_jr_index(jr, SIZE_MAX);
        if (i != (size_t)out->count) {
            return mip_jr_fail(jr, "%zu elements but count is %zu", i, (size_t)out->count);
        }
        mip_jr_pop(jr);
    }
    return 0;
}

/* ---- mip_threedm_event_trigger_config_t */

static int mip_threedm_event_trigger_config_read(mip_reader_t *r, mip_threedm_event_trigger_config_t *out) {
    mip_rd_push(r, "function");
    if (mip_rd_u8(r, &out->function)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "instance");
    if (mip_rd_u8(r, &out->instance)) {
        return -1;
    }
    mip_rd_pop(r);
    if (r->pos < r->len) {
        out->has_type = true;
        mip_rd_push(r, "type");
        if (mip_rd_u8(r, &out->type)) {
            return -1;
        }
        mip_rd_pop(r);
    }
    if (r->pos < r->len) {
        out->has_parameters = true;
        mip_rd_push(r, "parameters");
        if (mip_trigger_params_read(r, out->type, &out->parameters)) {
            return -1;
        }
        mip_rd_pop(r);
    }
    return mip_rd_finish(r);
}

static mip_status_t mip_threedm_event_trigger_config_write(mip_writer_t *w,
                                                           const mip_threedm_event_trigger_config_t *in) {
    mip_status_t st;
    int absent = 0;
    if ((st = mip_wr_u8(w, &in->function)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_u8(w, &in->instance)) != MIP_OK) {
        return st;
    }
    if (!in->has_type) {
        absent = 1;
    } else if (absent) {
        return MIP_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = mip_wr_u8(w, &in->type)) != MIP_OK) {
            return st;
        }
    }
    if (!in->has_parameters) {
        absent = 1;
    } else if (absent) {
        return MIP_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = mip_trigger_params_write(w, in->type, &in->parameters)) != MIP_OK) {
            return st;
        }
    }
    return MIP_OK;
}

mip_status_t mip_threedm_event_trigger_config_encode(const mip_threedm_event_trigger_config_t *value,
                                                     uint8_t *buf, size_t cap, size_t *len_out) {
    mip_writer_t w;
    mip_status_t st;
    mip_writer_init(&w, buf, cap);
    st = mip_threedm_event_trigger_config_write(&w, value);
    if (st == MIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mip_status_t mip_threedm_event_trigger_config_decode(const uint8_t *data, size_t len,
                                                     mip_threedm_event_trigger_config_t *out,
                                                     mip_decode_error_t *err) {
    mip_reader_t r;
    mip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mip_threedm_event_trigger_config_read(&r, out) ? MIP_ERR_DECODE : MIP_OK;
}

void mip_threedm_event_trigger_config_to_json(mip_jw_t *w, const mip_threedm_event_trigger_config_t *in) {
    int first = 1;
    mip_jw_raw(w, "{", 1);
    mip_jw_key(w, &first, "function");
    mip_jw_u8(w, &in->function);
    mip_jw_key(w, &first, "instance");
    mip_jw_u8(w, &in->instance);
    if (in->has_type) {
        mip_jw_key(w, &first, "type");
        mip_jw_u8(w, &in->type);
    }
    if (in->has_parameters) {
        mip_jw_key(w, &first, "parameters");
        mip_trigger_params_to_json(w, in->type, &in->parameters);
    }
    mip_jw_raw(w, "}", 1);
}

int mip_threedm_event_trigger_config_from_json(mip_jr_t *jr, size_t pos,
                                               mip_threedm_event_trigger_config_t *out) {
    static const char *const keys[] = {"function", "instance", "type", "parameters"};
    size_t vp = 0;
    int found;
    int absent = 0;
    memset(out, 0, sizeof *out);
    if (mip_jr_object(jr, pos, keys, 4)) {
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
    found = mip_jr_get(jr, pos, "instance", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"instance\"");
    }
    {
        mip_jr_push(jr, "instance");
        if (mip_jr_u8(jr, vp, &out->instance)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "type", &vp);
    out->has_type = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mip_jr_fail(jr, "optional parameter \"type\" given after an absent one");
    } else {
        mip_jr_push(jr, "type");
        if (mip_jr_u8(jr, vp, &out->type)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "parameters", &vp);
    out->has_parameters = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mip_jr_fail(jr, "optional parameter \"parameters\" given after an absent one");
    } else {
        mip_jr_push(jr, "parameters");
        if (mip_trigger_params_from_json(jr, vp, out->type, &out->parameters)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    return 0;
}

/* ---- mip_threedm_event_trigger_config_response_t */

static int mip_threedm_event_trigger_config_response_read(mip_reader_t *r,
                                                          mip_threedm_event_trigger_config_response_t *out) {
    mip_rd_push(r, "instance");
    if (mip_rd_u8(r, &out->instance)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "type");
    if (mip_rd_u8(r, &out->type)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "parameters");
    if (mip_trigger_params_read(r, out->type, &out->parameters)) {
        return -1;
    }
    mip_rd_pop(r);
    return mip_rd_finish(r);
}

static mip_status_t
mip_threedm_event_trigger_config_response_write(mip_writer_t *w,
                                                const mip_threedm_event_trigger_config_response_t *in) {
    mip_status_t st;
    if ((st = mip_wr_u8(w, &in->instance)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_u8(w, &in->type)) != MIP_OK) {
        return st;
    }
    if ((st = mip_trigger_params_write(w, in->type, &in->parameters)) != MIP_OK) {
        return st;
    }
    return MIP_OK;
}

mip_status_t
mip_threedm_event_trigger_config_response_encode(const mip_threedm_event_trigger_config_response_t *value,
                                                 uint8_t *buf, size_t cap, size_t *len_out) {
    mip_writer_t w;
    mip_status_t st;
    mip_writer_init(&w, buf, cap);
    st = mip_threedm_event_trigger_config_response_write(&w, value);
    if (st == MIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mip_status_t
mip_threedm_event_trigger_config_response_decode(const uint8_t *data, size_t len,
                                                 mip_threedm_event_trigger_config_response_t *out,
                                                 mip_decode_error_t *err) {
    mip_reader_t r;
    mip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mip_threedm_event_trigger_config_response_read(&r, out) ? MIP_ERR_DECODE : MIP_OK;
}

void mip_threedm_event_trigger_config_response_to_json(
    mip_jw_t *w, const mip_threedm_event_trigger_config_response_t *in) {
    int first = 1;
    mip_jw_raw(w, "{", 1);
    mip_jw_key(w, &first, "instance");
    mip_jw_u8(w, &in->instance);
    mip_jw_key(w, &first, "type");
    mip_jw_u8(w, &in->type);
    mip_jw_key(w, &first, "parameters");
    mip_trigger_params_to_json(w, in->type, &in->parameters);
    mip_jw_raw(w, "}", 1);
}

int mip_threedm_event_trigger_config_response_from_json(mip_jr_t *jr, size_t pos,
                                                        mip_threedm_event_trigger_config_response_t *out) {
    static const char *const keys[] = {"instance", "type", "parameters"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mip_jr_object(jr, pos, keys, 3)) {
        return -1;
    }
    found = mip_jr_get(jr, pos, "instance", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"instance\"");
    }
    {
        mip_jr_push(jr, "instance");
        if (mip_jr_u8(jr, vp, &out->instance)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "type", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"type\"");
    }
    {
        mip_jr_push(jr, "type");
        if (mip_jr_u8(jr, vp, &out->type)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "parameters", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"parameters\"");
    }
    {
        mip_jr_push(jr, "parameters");
        if (mip_trigger_params_from_json(jr, vp, out->type, &out->parameters)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    return 0;
}

/* ---- mip_threedm_event_action_config_t */

static int mip_threedm_event_action_config_read(mip_reader_t *r, mip_threedm_event_action_config_t *out) {
    mip_rd_push(r, "function");
    if (mip_rd_u8(r, &out->function)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "instance");
    if (mip_rd_u8(r, &out->instance)) {
        return -1;
    }
    mip_rd_pop(r);
    if (r->pos < r->len) {
        out->has_trigger = true;
        mip_rd_push(r, "trigger");
        if (mip_rd_u8(r, &out->trigger)) {
            return -1;
        }
        mip_rd_pop(r);
    }
    if (r->pos < r->len) {
        out->has_type = true;
        mip_rd_push(r, "type");
        if (mip_rd_u8(r, &out->type)) {
            return -1;
        }
        mip_rd_pop(r);
    }
    if (r->pos < r->len) {
        out->has_parameters = true;
        mip_rd_push(r, "parameters");
        if (mip_action_params_read(r, out->type, &out->parameters)) {
            return -1;
        }
        mip_rd_pop(r);
    }
    return mip_rd_finish(r);
}

static mip_status_t mip_threedm_event_action_config_write(mip_writer_t *w,
                                                          const mip_threedm_event_action_config_t *in) {
    mip_status_t st;
    int absent = 0;
    if ((st = mip_wr_u8(w, &in->function)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_u8(w, &in->instance)) != MIP_OK) {
        return st;
    }
    if (!in->has_trigger) {
        absent = 1;
    } else if (absent) {
        return MIP_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = mip_wr_u8(w, &in->trigger)) != MIP_OK) {
            return st;
        }
    }
    if (!in->has_type) {
        absent = 1;
    } else if (absent) {
        return MIP_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = mip_wr_u8(w, &in->type)) != MIP_OK) {
            return st;
        }
    }
    if (!in->has_parameters) {
        absent = 1;
    } else if (absent) {
        return MIP_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = mip_action_params_write(w, in->type, &in->parameters)) != MIP_OK) {
            return st;
        }
    }
    return MIP_OK;
}

mip_status_t mip_threedm_event_action_config_encode(const mip_threedm_event_action_config_t *value,
                                                    uint8_t *buf, size_t cap, size_t *len_out) {
    mip_writer_t w;
    mip_status_t st;
    mip_writer_init(&w, buf, cap);
    st = mip_threedm_event_action_config_write(&w, value);
    if (st == MIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mip_status_t mip_threedm_event_action_config_decode(const uint8_t *data, size_t len,
                                                    mip_threedm_event_action_config_t *out,
                                                    mip_decode_error_t *err) {
    mip_reader_t r;
    mip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mip_threedm_event_action_config_read(&r, out) ? MIP_ERR_DECODE : MIP_OK;
}

void mip_threedm_event_action_config_to_json(mip_jw_t *w, const mip_threedm_event_action_config_t *in) {
    int first = 1;
    mip_jw_raw(w, "{", 1);
    mip_jw_key(w, &first, "function");
    mip_jw_u8(w, &in->function);
    mip_jw_key(w, &first, "instance");
    mip_jw_u8(w, &in->instance);
    if (in->has_trigger) {
        mip_jw_key(w, &first, "trigger");
        mip_jw_u8(w, &in->trigger);
    }
    if (in->has_type) {
        mip_jw_key(w, &first, "type");
        mip_jw_u8(w, &in->type);
    }
    if (in->has_parameters) {
        mip_jw_key(w, &first, "parameters");
        mip_action_params_to_json(w, in->type, &in->parameters);
    }
    mip_jw_raw(w, "}", 1);
}

int mip_threedm_event_action_config_from_json(mip_jr_t *jr, size_t pos,
                                              mip_threedm_event_action_config_t *out) {
    static const char *const keys[] = {"function", "instance", "trigger", "type", "parameters"};
    size_t vp = 0;
    int found;
    int absent = 0;
    memset(out, 0, sizeof *out);
    if (mip_jr_object(jr, pos, keys, 5)) {
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
    found = mip_jr_get(jr, pos, "instance", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"instance\"");
    }
    {
        mip_jr_push(jr, "instance");
        if (mip_jr_u8(jr, vp, &out->instance)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "trigger", &vp);
    out->has_trigger = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mip_jr_fail(jr, "optional parameter \"trigger\" given after an absent one");
    } else {
        mip_jr_push(jr, "trigger");
        if (mip_jr_u8(jr, vp, &out->trigger)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "type", &vp);
    out->has_type = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mip_jr_fail(jr, "optional parameter \"type\" given after an absent one");
    } else {
        mip_jr_push(jr, "type");
        if (mip_jr_u8(jr, vp, &out->type)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "parameters", &vp);
    out->has_parameters = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mip_jr_fail(jr, "optional parameter \"parameters\" given after an absent one");
    } else {
        mip_jr_push(jr, "parameters");
        if (mip_action_params_from_json(jr, vp, out->type, &out->parameters)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    return 0;
}

/* ---- mip_threedm_event_action_config_response_t */

static int mip_threedm_event_action_config_response_read(mip_reader_t *r,
                                                         mip_threedm_event_action_config_response_t *out) {
    mip_rd_push(r, "instance");
    if (mip_rd_u8(r, &out->instance)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "trigger");
    if (mip_rd_u8(r, &out->trigger)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "type");
    if (mip_rd_u8(r, &out->type)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "parameters");
    if (mip_action_params_read(r, out->type, &out->parameters)) {
        return -1;
    }
    mip_rd_pop(r);
    return mip_rd_finish(r);
}

static mip_status_t
mip_threedm_event_action_config_response_write(mip_writer_t *w,
                                               const mip_threedm_event_action_config_response_t *in) {
    mip_status_t st;
    if ((st = mip_wr_u8(w, &in->instance)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_u8(w, &in->trigger)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_u8(w, &in->type)) != MIP_OK) {
        return st;
    }
    if ((st = mip_action_params_write(w, in->type, &in->parameters)) != MIP_OK) {
        return st;
    }
    return MIP_OK;
}

mip_status_t
mip_threedm_event_action_config_response_encode(const mip_threedm_event_action_config_response_t *value,
                                                uint8_t *buf, size_t cap, size_t *len_out) {
    mip_writer_t w;
    mip_status_t st;
    mip_writer_init(&w, buf, cap);
    st = mip_threedm_event_action_config_response_write(&w, value);
    if (st == MIP_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mip_status_t mip_threedm_event_action_config_response_decode(const uint8_t *data, size_t len,
                                                             mip_threedm_event_action_config_response_t *out,
                                                             mip_decode_error_t *err) {
    mip_reader_t r;
    mip_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mip_threedm_event_action_config_response_read(&r, out) ? MIP_ERR_DECODE : MIP_OK;
}

void mip_threedm_event_action_config_response_to_json(mip_jw_t *w,
                                                      const mip_threedm_event_action_config_response_t *in) {
    int first = 1;
    mip_jw_raw(w, "{", 1);
    mip_jw_key(w, &first, "instance");
    mip_jw_u8(w, &in->instance);
    mip_jw_key(w, &first, "trigger");
    mip_jw_u8(w, &in->trigger);
    mip_jw_key(w, &first, "type");
    mip_jw_u8(w, &in->type);
    mip_jw_key(w, &first, "parameters");
    mip_action_params_to_json(w, in->type, &in->parameters);
    mip_jw_raw(w, "}", 1);
}

int mip_threedm_event_action_config_response_from_json(mip_jr_t *jr, size_t pos,
                                                       mip_threedm_event_action_config_response_t *out) {
    static const char *const keys[] = {"instance", "trigger", "type", "parameters"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mip_jr_object(jr, pos, keys, 4)) {
        return -1;
    }
    found = mip_jr_get(jr, pos, "instance", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"instance\"");
    }
    {
        mip_jr_push(jr, "instance");
        if (mip_jr_u8(jr, vp, &out->instance)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "trigger", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"trigger\"");
    }
    {
        mip_jr_push(jr, "trigger");
        if (mip_jr_u8(jr, vp, &out->trigger)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "type", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"type\"");
    }
    {
        mip_jr_push(jr, "type");
        if (mip_jr_u8(jr, vp, &out->type)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "parameters", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"parameters\"");
    }
    {
        mip_jr_push(jr, "parameters");
        if (mip_action_params_from_json(jr, vp, out->type, &out->parameters)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    return 0;
}
