/* Encoders and decoders of 3DM Command Set. Generated from the spec: do not edit. */
#include "mipcodec/sets/threedm.h"
#include "layouts_internal.h"
#include "types_internal.h"

#include <string.h>

/* ---- mipc_threedm_event_control_t */

static int mipc_threedm_event_control_read(mipc_reader_t *r, mipc_threedm_event_control_t *out) {
    mipc_rd_push(r, "function");
    if (mipc_rd_u8(r, &out->function)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "instance");
    if (mipc_rd_u8(r, &out->instance)) {
        return -1;
    }
    mipc_rd_pop(r);
    if (r->pos < r->len) {
        out->has_mode = true;
        mipc_rd_push(r, "mode");
        if (mipc_rd_u8(r, &out->mode)) {
            return -1;
        }
        mipc_rd_pop(r);
    }
    return mipc_rd_finish(r);
}

static mipc_status_t mipc_threedm_event_control_write(mipc_writer_t *w,
                                                      const mipc_threedm_event_control_t *in) {
    mipc_status_t st;
    int absent = 0;
    if ((st = mipc_wr_u8(w, &in->function)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u8(w, &in->instance)) != MIPC_OK) {
        return st;
    }
    if (!in->has_mode) {
        absent = 1;
    } else if (absent) {
        return MIPC_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = mipc_wr_u8(w, &in->mode)) != MIPC_OK) {
            return st;
        }
    }
    return MIPC_OK;
}

mipc_status_t mipc_threedm_event_control_encode(const mipc_threedm_event_control_t *value, uint8_t *buf,
                                                size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    mipc_writer_init(&w, buf, cap);
    st = mipc_threedm_event_control_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mipc_status_t mipc_threedm_event_control_decode(const uint8_t *data, size_t len,
                                                mipc_threedm_event_control_t *out, mipc_decode_error_t *err) {
    mipc_reader_t r;
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_threedm_event_control_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

void mipc_threedm_event_control_to_json(mipc_jw_t *w, const mipc_threedm_event_control_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "function");
    mipc_jw_u8(w, &in->function);
    mipc_jw_key(w, &first, "instance");
    mipc_jw_u8(w, &in->instance);
    if (in->has_mode) {
        mipc_jw_key(w, &first, "mode");
        mipc_jw_u8(w, &in->mode);
    }
    mipc_jw_raw(w, "}", 1);
}

int mipc_threedm_event_control_from_json(mipc_jr_t *jr, size_t pos, mipc_threedm_event_control_t *out) {
    static const char *const keys[] = {"function", "instance", "mode"};
    size_t vp = 0;
    int found;
    int absent = 0;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 3)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "function", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"function\"");
    }
    {
        mipc_jr_push(jr, "function");
        if (mipc_jr_u8(jr, vp, &out->function)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "instance", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"instance\"");
    }
    {
        mipc_jr_push(jr, "instance");
        if (mipc_jr_u8(jr, vp, &out->instance)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "mode", &vp);
    out->has_mode = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mipc_jr_fail(jr, "optional parameter \"mode\" given after an absent one");
    } else {
        mipc_jr_push(jr, "mode");
        if (mipc_jr_u8(jr, vp, &out->mode)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mipc_threedm_event_control_response_t */

static int mipc_threedm_event_control_response_read(mipc_reader_t *r,
                                                    mipc_threedm_event_control_response_t *out) {
    mipc_rd_push(r, "instance");
    if (mipc_rd_u8(r, &out->instance)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "mode");
    if (mipc_rd_u8(r, &out->mode)) {
        return -1;
    }
    mipc_rd_pop(r);
    return mipc_rd_finish(r);
}

static mipc_status_t
mipc_threedm_event_control_response_write(mipc_writer_t *w, const mipc_threedm_event_control_response_t *in) {
    mipc_status_t st;
    if ((st = mipc_wr_u8(w, &in->instance)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u8(w, &in->mode)) != MIPC_OK) {
        return st;
    }
    return MIPC_OK;
}

mipc_status_t mipc_threedm_event_control_response_encode(const mipc_threedm_event_control_response_t *value,
                                                         uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    mipc_writer_init(&w, buf, cap);
    st = mipc_threedm_event_control_response_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 2 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mipc_threedm_event_control_response_load(const uint8_t *d,
                                                    mipc_threedm_event_control_response_t *out) {
    out->instance = mipc_ld_u8(d + 0);
    out->mode = mipc_ld_u8(d + 1);
    return 0;
}

/* The general reader: lengths other than 2, bad bool bytes, error details. */
static MIPC_NOINLINE mipc_status_t mipc_threedm_event_control_response_decode_read(
    const uint8_t *data, size_t len, mipc_threedm_event_control_response_t *out, mipc_decode_error_t *err) {
    mipc_reader_t r;
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_threedm_event_control_response_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t mipc_threedm_event_control_response_decode(const uint8_t *data, size_t len,
                                                         mipc_threedm_event_control_response_t *out,
                                                         mipc_decode_error_t *err) {
    if (len == 2 && mipc_threedm_event_control_response_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_threedm_event_control_response_decode_read(data, len, out, err);
}

void mipc_threedm_event_control_response_to_json(mipc_jw_t *w,
                                                 const mipc_threedm_event_control_response_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "instance");
    mipc_jw_u8(w, &in->instance);
    mipc_jw_key(w, &first, "mode");
    mipc_jw_u8(w, &in->mode);
    mipc_jw_raw(w, "}", 1);
}

int mipc_threedm_event_control_response_from_json(mipc_jr_t *jr, size_t pos,
                                                  mipc_threedm_event_control_response_t *out) {
    static const char *const keys[] = {"instance", "mode"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 2)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "instance", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"instance\"");
    }
    {
        mipc_jr_push(jr, "instance");
        if (mipc_jr_u8(jr, vp, &out->instance)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "mode", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"mode\"");
    }
    {
        mipc_jr_push(jr, "mode");
        if (mipc_jr_u8(jr, vp, &out->mode)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mipc_threedm_get_event_trigger_status_t */

static int mipc_threedm_get_event_trigger_status_read(mipc_reader_t *r,
                                                      mipc_threedm_get_event_trigger_status_t *out) {
    size_t i;
    mipc_rd_push(r, "requested_count");
    if (mipc_rd_u8(r, &out->requested_count)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "requested_instances");
    if (out->requested_count > 252) {
        return mipc_rd_count_error(r, (uint64_t)out->requested_count, 252);
    }
    for (i = 0; i < (size_t)out->requested_count; i++) {
        mipc_rd_index(r, i);
        if (mipc_rd_u8(r, &out->requested_instances[i])) {
            return -1;
        }
    }
    mipc_rd_pop(r);
    return mipc_rd_finish(r);
}

static mipc_status_t
mipc_threedm_get_event_trigger_status_write(mipc_writer_t *w,
                                            const mipc_threedm_get_event_trigger_status_t *in) {
    mipc_status_t st;
    size_t i;
    if ((st = mipc_wr_u8(w, &in->requested_count)) != MIPC_OK) {
        return st;
    }
    if (in->requested_count > 252) {
        return MIPC_ERR_INVALID;
    }
    for (i = 0; i < (size_t)in->requested_count; i++) {
        if ((st = mipc_wr_u8(w, &in->requested_instances[i])) != MIPC_OK) {
            return st;
        }
    }
    return MIPC_OK;
}

mipc_status_t
mipc_threedm_get_event_trigger_status_encode(const mipc_threedm_get_event_trigger_status_t *value,
                                             uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    mipc_writer_init(&w, buf, cap);
    st = mipc_threedm_get_event_trigger_status_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mipc_status_t mipc_threedm_get_event_trigger_status_decode(const uint8_t *data, size_t len,
                                                           mipc_threedm_get_event_trigger_status_t *out,
                                                           mipc_decode_error_t *err) {
    mipc_reader_t r;
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_threedm_get_event_trigger_status_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

void mipc_threedm_get_event_trigger_status_to_json(mipc_jw_t *w,
                                                   const mipc_threedm_get_event_trigger_status_t *in) {
    int first = 1;
    size_t i;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "requested_count");
    mipc_jw_u8(w, &in->requested_count);
    mipc_jw_key(w, &first, "requested_instances");
    mipc_jw_raw(w, "[", 1);
    for (i = 0; i < (size_t)in->requested_count && i < 252; i++) {
        mipc_jw_sep(w, i);
        mipc_jw_u8(w, &in->requested_instances[i]);
    }
    mipc_jw_raw(w, "]", 1);
    mipc_jw_raw(w, "}", 1);
}

int mipc_threedm_get_event_trigger_status_from_json(mipc_jr_t *jr, size_t pos,
                                                    mipc_threedm_get_event_trigger_status_t *out) {
    static const char *const keys[] = {"requested_count", "requested_instances"};
    size_t vp = 0;
    int found;
    size_t i;
    size_t it = 0;
    size_t ep = 0;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 2)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "requested_count", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"requested_count\"");
    }
    {
        mipc_jr_push(jr, "requested_count");
        if (mipc_jr_u8(jr, vp, &out->requested_count)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "requested_instances", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"requested_instances\"");
    }
    {
        mipc_jr_push(jr, "requested_instances");
        if (mipc_jr_array(jr, vp, &it)) {
            return -1;
        }
        for (i = 0;; i++) {
            int more = mipc_jr_next(jr, &it, &ep);
            if (more < 0) {
                return -1;
            }
            if (!more) {
                break;
            }
            if (i >= 252) {
                return mipc_jr_fail(jr, "more than 252 elements");
            }
            mipc_jr_index(jr, i);
            if (mipc_jr_u8(jr, ep, &out->requested_instances[i])) {
                return -1;
            }
        }
        mipc_jr_index(jr, SIZE_MAX);
        if (i != (size_t)out->requested_count) {
            return mipc_jr_fail(jr, "%zu elements but requested_count is %zu", i,
                                (size_t)out->requested_count);
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mipc_threedm_event_trigger_status_t */

static int mipc_threedm_event_trigger_status_read(mipc_reader_t *r,
                                                  mipc_threedm_event_trigger_status_t *out) {
    size_t i;
    mipc_rd_push(r, "count");
    if (mipc_rd_u8(r, &out->count)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "triggers");
    if (out->count > 126) {
        return mipc_rd_count_error(r, (uint64_t)out->count, 126);
    }
    for (i = 0; i < (size_t)out->count; i++) {
        mipc_rd_index(r, i);
        if (mipc_trigger_status_entry_read(r, &out->triggers[i])) {
            return -1;
        }
    }
    mipc_rd_pop(r);
    return mipc_rd_finish(r);
}

static mipc_status_t mipc_threedm_event_trigger_status_write(mipc_writer_t *w,
                                                             const mipc_threedm_event_trigger_status_t *in) {
    mipc_status_t st;
    size_t i;
    if ((st = mipc_wr_u8(w, &in->count)) != MIPC_OK) {
        return st;
    }
    if (in->count > 126) {
        return MIPC_ERR_INVALID;
    }
    for (i = 0; i < (size_t)in->count; i++) {
        if ((st = mipc_trigger_status_entry_write(w, &in->triggers[i])) != MIPC_OK) {
            return st;
        }
    }
    return MIPC_OK;
}

mipc_status_t mipc_threedm_event_trigger_status_encode(const mipc_threedm_event_trigger_status_t *value,
                                                       uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    mipc_writer_init(&w, buf, cap);
    st = mipc_threedm_event_trigger_status_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mipc_status_t mipc_threedm_event_trigger_status_decode(const uint8_t *data, size_t len,
                                                       mipc_threedm_event_trigger_status_t *out,
                                                       mipc_decode_error_t *err) {
    mipc_reader_t r;
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_threedm_event_trigger_status_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

void mipc_threedm_event_trigger_status_to_json(mipc_jw_t *w, const mipc_threedm_event_trigger_status_t *in) {
    int first = 1;
    size_t i;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "count");
    mipc_jw_u8(w, &in->count);
    mipc_jw_key(w, &first, "triggers");
    mipc_jw_raw(w, "[", 1);
    for (i = 0; i < (size_t)in->count && i < 126; i++) {
        mipc_jw_sep(w, i);
        mipc_trigger_status_entry_to_json(w, &in->triggers[i]);
    }
    mipc_jw_raw(w, "]", 1);
    mipc_jw_raw(w, "}", 1);
}

int mipc_threedm_event_trigger_status_from_json(mipc_jr_t *jr, size_t pos,
                                                mipc_threedm_event_trigger_status_t *out) {
    static const char *const keys[] = {"count", "triggers"};
    size_t vp = 0;
    int found;
    size_t i;
    size_t it = 0;
    size_t ep = 0;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 2)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "count", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"count\"");
    }
    {
        mipc_jr_push(jr, "count");
        if (mipc_jr_u8(jr, vp, &out->count)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "triggers", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"triggers\"");
    }
    {
        mipc_jr_push(jr, "triggers");
        if (mipc_jr_array(jr, vp, &it)) {
            return -1;
        }
        for (i = 0;; i++) {
            int more = mipc_jr_next(jr, &it, &ep);
            if (more < 0) {
                return -1;
            }
            if (!more) {
                break;
            }
            if (i >= 126) {
                return mipc_jr_fail(jr, "more than 126 elements");
            }
            mipc_jr_index(jr, i);
            if (mipc_trigger_status_entry_from_json(jr, ep, &out->triggers[i])) {
                return -1;
            }
        }
        mipc_jr_index(jr, SIZE_MAX);
        if (i != (size_t)out->count) {
            return mipc_jr_fail(jr, "%zu elements but count is %zu", i, (size_t)out->count);
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mipc_threedm_get_event_action_status_t */

static int mipc_threedm_get_event_action_status_read(mipc_reader_t *r,
                                                     mipc_threedm_get_event_action_status_t *out) {
    size_t i;
    mipc_rd_push(r, "requested_count");
    if (mipc_rd_u8(r, &out->requested_count)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "requested_instances");
    if (out->requested_count > 252) {
        return mipc_rd_count_error(r, (uint64_t)out->requested_count, 252);
    }
    for (i = 0; i < (size_t)out->requested_count; i++) {
        mipc_rd_index(r, i);
        if (mipc_rd_u8(r, &out->requested_instances[i])) {
            return -1;
        }
    }
    mipc_rd_pop(r);
    return mipc_rd_finish(r);
}

static mipc_status_t
mipc_threedm_get_event_action_status_write(mipc_writer_t *w,
                                           const mipc_threedm_get_event_action_status_t *in) {
    mipc_status_t st;
    size_t i;
    if ((st = mipc_wr_u8(w, &in->requested_count)) != MIPC_OK) {
        return st;
    }
    if (in->requested_count > 252) {
        return MIPC_ERR_INVALID;
    }
    for (i = 0; i < (size_t)in->requested_count; i++) {
        if ((st = mipc_wr_u8(w, &in->requested_instances[i])) != MIPC_OK) {
            return st;
        }
    }
    return MIPC_OK;
}

mipc_status_t mipc_threedm_get_event_action_status_encode(const mipc_threedm_get_event_action_status_t *value,
                                                          uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    mipc_writer_init(&w, buf, cap);
    st = mipc_threedm_get_event_action_status_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mipc_status_t mipc_threedm_get_event_action_status_decode(const uint8_t *data, size_t len,
                                                          mipc_threedm_get_event_action_status_t *out,
                                                          mipc_decode_error_t *err) {
    mipc_reader_t r;
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_threedm_get_event_action_status_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

void mipc_threedm_get_event_action_status_to_json(mipc_jw_t *w,
                                                  const mipc_threedm_get_event_action_status_t *in) {
    int first = 1;
    size_t i;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "requested_count");
    mipc_jw_u8(w, &in->requested_count);
    mipc_jw_key(w, &first, "requested_instances");
    mipc_jw_raw(w, "[", 1);
    for (i = 0; i < (size_t)in->requested_count && i < 252; i++) {
        mipc_jw_sep(w, i);
        mipc_jw_u8(w, &in->requested_instances[i]);
    }
    mipc_jw_raw(w, "]", 1);
    mipc_jw_raw(w, "}", 1);
}

int mipc_threedm_get_event_action_status_from_json(mipc_jr_t *jr, size_t pos,
                                                   mipc_threedm_get_event_action_status_t *out) {
    static const char *const keys[] = {"requested_count", "requested_instances"};
    size_t vp = 0;
    int found;
    size_t i;
    size_t it = 0;
    size_t ep = 0;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 2)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "requested_count", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"requested_count\"");
    }
    {
        mipc_jr_push(jr, "requested_count");
        if (mipc_jr_u8(jr, vp, &out->requested_count)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "requested_instances", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"requested_instances\"");
    }
    {
        mipc_jr_push(jr, "requested_instances");
        if (mipc_jr_array(jr, vp, &it)) {
            return -1;
        }
        for (i = 0;; i++) {
            int more = mipc_jr_next(jr, &it, &ep);
            if (more < 0) {
                return -1;
            }
            if (!more) {
                break;
            }
            if (i >= 252) {
                return mipc_jr_fail(jr, "more than 252 elements");
            }
            mipc_jr_index(jr, i);
            if (mipc_jr_u8(jr, ep, &out->requested_instances[i])) {
                return -1;
            }
        }
        mipc_jr_index(jr, SIZE_MAX);
        if (i != (size_t)out->requested_count) {
            return mipc_jr_fail(jr, "%zu elements but requested_count is %zu", i,
                                (size_t)out->requested_count);
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mipc_threedm_event_action_status_t */

static int mipc_threedm_event_action_status_read(mipc_reader_t *r, mipc_threedm_event_action_status_t *out) {
    size_t i;
    mipc_rd_push(r, "count");
    if (mipc_rd_u8(r, &out->count)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "actions");
    if (out->count > 126) {
        return mipc_rd_count_error(r, (uint64_t)out->count, 126);
    }
    for (i = 0; i < (size_t)out->count; i++) {
        mipc_rd_index(r, i);
        if (mipc_action_status_entry_read(r, &out->actions[i])) {
            return -1;
        }
    }
    mipc_rd_pop(r);
    return mipc_rd_finish(r);
}

static mipc_status_t mipc_threedm_event_action_status_write(mipc_writer_t *w,
                                                            const mipc_threedm_event_action_status_t *in) {
    mipc_status_t st;
    size_t i;
    if ((st = mipc_wr_u8(w, &in->count)) != MIPC_OK) {
        return st;
    }
    if (in->count > 126) {
        return MIPC_ERR_INVALID;
    }
    for (i = 0; i < (size_t)in->count; i++) {
        if ((st = mipc_action_status_entry_write(w, &in->actions[i])) != MIPC_OK) {
            return st;
        }
    }
    return MIPC_OK;
}

mipc_status_t mipc_threedm_event_action_status_encode(const mipc_threedm_event_action_status_t *value,
                                                      uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    mipc_writer_init(&w, buf, cap);
    st = mipc_threedm_event_action_status_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mipc_status_t mipc_threedm_event_action_status_decode(const uint8_t *data, size_t len,
                                                      mipc_threedm_event_action_status_t *out,
                                                      mipc_decode_error_t *err) {
    mipc_reader_t r;
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_threedm_event_action_status_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

void mipc_threedm_event_action_status_to_json(mipc_jw_t *w, const mipc_threedm_event_action_status_t *in) {
    int first = 1;
    size_t i;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "count");
    mipc_jw_u8(w, &in->count);
    mipc_jw_key(w, &first, "actions");
    mipc_jw_raw(w, "[", 1);
    for (i = 0; i < (size_t)in->count && i < 126; i++) {
        mipc_jw_sep(w, i);
        mipc_action_status_entry_to_json(w, &in->actions[i]);
    }
    mipc_jw_raw(w, "]", 1);
    mipc_jw_raw(w, "}", 1);
}

int mipc_threedm_event_action_status_from_json(mipc_jr_t *jr, size_t pos,
                                               mipc_threedm_event_action_status_t *out) {
    static const char *const keys[] = {"count", "actions"};
    size_t vp = 0;
    int found;
    size_t i;
    size_t it = 0;
    size_t ep = 0;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 2)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "count", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"count\"");
    }
    {
        mipc_jr_push(jr, "count");
        if (mipc_jr_u8(jr, vp, &out->count)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "actions", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"actions\"");
    }
    {
        mipc_jr_push(jr, "actions");
        if (mipc_jr_array(jr, vp, &it)) {
            return -1;
        }
        for (i = 0;; i++) {
            int more = mipc_jr_next(jr, &it, &ep);
            if (more < 0) {
                return -1;
            }
            if (!more) {
                break;
            }
            if (i >= 126) {
                return mipc_jr_fail(jr, "more than 126 elements");
            }
            mipc_jr_index(jr, i);
            if (mipc_action_status_entry_from_json(jr, ep, &out->actions[i])) {
                return -1;
            }
        }
        mipc_jr_index(jr, SIZE_MAX);
        if (i != (size_t)out->count) {
            return mipc_jr_fail(jr, "%zu elements but count is %zu", i, (size_t)out->count);
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mipc_threedm_event_trigger_config_t */

static int mipc_threedm_event_trigger_config_read(mipc_reader_t *r,
                                                  mipc_threedm_event_trigger_config_t *out) {
    mipc_rd_push(r, "function");
    if (mipc_rd_u8(r, &out->function)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "instance");
    if (mipc_rd_u8(r, &out->instance)) {
        return -1;
    }
    mipc_rd_pop(r);
    if (r->pos < r->len) {
        out->has_type = true;
        mipc_rd_push(r, "type");
        if (mipc_rd_u8(r, &out->type)) {
            return -1;
        }
        mipc_rd_pop(r);
    }
    if (r->pos < r->len) {
        out->has_parameters = true;
        mipc_rd_push(r, "parameters");
        if (mipc_trigger_params_read(r, out->type, &out->parameters)) {
            return -1;
        }
        mipc_rd_pop(r);
    }
    return mipc_rd_finish(r);
}

static mipc_status_t mipc_threedm_event_trigger_config_write(mipc_writer_t *w,
                                                             const mipc_threedm_event_trigger_config_t *in) {
    mipc_status_t st;
    int absent = 0;
    if ((st = mipc_wr_u8(w, &in->function)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u8(w, &in->instance)) != MIPC_OK) {
        return st;
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
    if (!in->has_parameters) {
        absent = 1;
    } else if (absent) {
        return MIPC_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = mipc_trigger_params_write(w, in->type, &in->parameters)) != MIPC_OK) {
            return st;
        }
    }
    return MIPC_OK;
}

mipc_status_t mipc_threedm_event_trigger_config_encode(const mipc_threedm_event_trigger_config_t *value,
                                                       uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    mipc_writer_init(&w, buf, cap);
    st = mipc_threedm_event_trigger_config_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mipc_status_t mipc_threedm_event_trigger_config_decode(const uint8_t *data, size_t len,
                                                       mipc_threedm_event_trigger_config_t *out,
                                                       mipc_decode_error_t *err) {
    mipc_reader_t r;
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_threedm_event_trigger_config_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

void mipc_threedm_event_trigger_config_to_json(mipc_jw_t *w, const mipc_threedm_event_trigger_config_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "function");
    mipc_jw_u8(w, &in->function);
    mipc_jw_key(w, &first, "instance");
    mipc_jw_u8(w, &in->instance);
    if (in->has_type) {
        mipc_jw_key(w, &first, "type");
        mipc_jw_u8(w, &in->type);
    }
    if (in->has_parameters) {
        mipc_jw_key(w, &first, "parameters");
        mipc_trigger_params_to_json(w, in->type, &in->parameters);
    }
    mipc_jw_raw(w, "}", 1);
}

int mipc_threedm_event_trigger_config_from_json(mipc_jr_t *jr, size_t pos,
                                                mipc_threedm_event_trigger_config_t *out) {
    static const char *const keys[] = {"function", "instance", "type", "parameters"};
    size_t vp = 0;
    int found;
    int absent = 0;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 4)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "function", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"function\"");
    }
    {
        mipc_jr_push(jr, "function");
        if (mipc_jr_u8(jr, vp, &out->function)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "instance", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"instance\"");
    }
    {
        mipc_jr_push(jr, "instance");
        if (mipc_jr_u8(jr, vp, &out->instance)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "type", &vp);
    out->has_type = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mipc_jr_fail(jr, "optional parameter \"type\" given after an absent one");
    } else {
        mipc_jr_push(jr, "type");
        if (mipc_jr_u8(jr, vp, &out->type)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "parameters", &vp);
    out->has_parameters = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mipc_jr_fail(jr, "optional parameter \"parameters\" given after an absent one");
    } else {
        mipc_jr_push(jr, "parameters");
        if (mipc_trigger_params_from_json(jr, vp, out->type, &out->parameters)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mipc_threedm_event_trigger_config_response_t */

static int
mipc_threedm_event_trigger_config_response_read(mipc_reader_t *r,
                                                mipc_threedm_event_trigger_config_response_t *out) {
    mipc_rd_push(r, "instance");
    if (mipc_rd_u8(r, &out->instance)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "type");
    if (mipc_rd_u8(r, &out->type)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "parameters");
    if (mipc_trigger_params_read(r, out->type, &out->parameters)) {
        return -1;
    }
    mipc_rd_pop(r);
    return mipc_rd_finish(r);
}

static mipc_status_t
mipc_threedm_event_trigger_config_response_write(mipc_writer_t *w,
                                                 const mipc_threedm_event_trigger_config_response_t *in) {
    mipc_status_t st;
    if ((st = mipc_wr_u8(w, &in->instance)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u8(w, &in->type)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_trigger_params_write(w, in->type, &in->parameters)) != MIPC_OK) {
        return st;
    }
    return MIPC_OK;
}

mipc_status_t
mipc_threedm_event_trigger_config_response_encode(const mipc_threedm_event_trigger_config_response_t *value,
                                                  uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    mipc_writer_init(&w, buf, cap);
    st = mipc_threedm_event_trigger_config_response_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mipc_status_t
mipc_threedm_event_trigger_config_response_decode(const uint8_t *data, size_t len,
                                                  mipc_threedm_event_trigger_config_response_t *out,
                                                  mipc_decode_error_t *err) {
    mipc_reader_t r;
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_threedm_event_trigger_config_response_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

void mipc_threedm_event_trigger_config_response_to_json(
    mipc_jw_t *w, const mipc_threedm_event_trigger_config_response_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "instance");
    mipc_jw_u8(w, &in->instance);
    mipc_jw_key(w, &first, "type");
    mipc_jw_u8(w, &in->type);
    mipc_jw_key(w, &first, "parameters");
    mipc_trigger_params_to_json(w, in->type, &in->parameters);
    mipc_jw_raw(w, "}", 1);
}

int mipc_threedm_event_trigger_config_response_from_json(mipc_jr_t *jr, size_t pos,
                                                         mipc_threedm_event_trigger_config_response_t *out) {
    static const char *const keys[] = {"instance", "type", "parameters"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 3)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "instance", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"instance\"");
    }
    {
        mipc_jr_push(jr, "instance");
        if (mipc_jr_u8(jr, vp, &out->instance)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "type", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"type\"");
    }
    {
        mipc_jr_push(jr, "type");
        if (mipc_jr_u8(jr, vp, &out->type)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "parameters", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"parameters\"");
    }
    {
        mipc_jr_push(jr, "parameters");
        if (mipc_trigger_params_from_json(jr, vp, out->type, &out->parameters)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mipc_threedm_event_action_config_t */

static int mipc_threedm_event_action_config_read(mipc_reader_t *r, mipc_threedm_event_action_config_t *out) {
    mipc_rd_push(r, "function");
    if (mipc_rd_u8(r, &out->function)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "instance");
    if (mipc_rd_u8(r, &out->instance)) {
        return -1;
    }
    mipc_rd_pop(r);
    if (r->pos < r->len) {
        out->has_trigger = true;
        mipc_rd_push(r, "trigger");
        if (mipc_rd_u8(r, &out->trigger)) {
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
        out->has_parameters = true;
        mipc_rd_push(r, "parameters");
        if (mipc_action_params_read(r, out->type, &out->parameters)) {
            return -1;
        }
        mipc_rd_pop(r);
    }
    return mipc_rd_finish(r);
}

static mipc_status_t mipc_threedm_event_action_config_write(mipc_writer_t *w,
                                                            const mipc_threedm_event_action_config_t *in) {
    mipc_status_t st;
    int absent = 0;
    if ((st = mipc_wr_u8(w, &in->function)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u8(w, &in->instance)) != MIPC_OK) {
        return st;
    }
    if (!in->has_trigger) {
        absent = 1;
    } else if (absent) {
        return MIPC_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = mipc_wr_u8(w, &in->trigger)) != MIPC_OK) {
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
    if (!in->has_parameters) {
        absent = 1;
    } else if (absent) {
        return MIPC_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = mipc_action_params_write(w, in->type, &in->parameters)) != MIPC_OK) {
            return st;
        }
    }
    return MIPC_OK;
}

mipc_status_t mipc_threedm_event_action_config_encode(const mipc_threedm_event_action_config_t *value,
                                                      uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    mipc_writer_init(&w, buf, cap);
    st = mipc_threedm_event_action_config_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mipc_status_t mipc_threedm_event_action_config_decode(const uint8_t *data, size_t len,
                                                      mipc_threedm_event_action_config_t *out,
                                                      mipc_decode_error_t *err) {
    mipc_reader_t r;
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_threedm_event_action_config_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

void mipc_threedm_event_action_config_to_json(mipc_jw_t *w, const mipc_threedm_event_action_config_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "function");
    mipc_jw_u8(w, &in->function);
    mipc_jw_key(w, &first, "instance");
    mipc_jw_u8(w, &in->instance);
    if (in->has_trigger) {
        mipc_jw_key(w, &first, "trigger");
        mipc_jw_u8(w, &in->trigger);
    }
    if (in->has_type) {
        mipc_jw_key(w, &first, "type");
        mipc_jw_u8(w, &in->type);
    }
    if (in->has_parameters) {
        mipc_jw_key(w, &first, "parameters");
        mipc_action_params_to_json(w, in->type, &in->parameters);
    }
    mipc_jw_raw(w, "}", 1);
}

int mipc_threedm_event_action_config_from_json(mipc_jr_t *jr, size_t pos,
                                               mipc_threedm_event_action_config_t *out) {
    static const char *const keys[] = {"function", "instance", "trigger", "type", "parameters"};
    size_t vp = 0;
    int found;
    int absent = 0;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 5)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "function", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"function\"");
    }
    {
        mipc_jr_push(jr, "function");
        if (mipc_jr_u8(jr, vp, &out->function)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "instance", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"instance\"");
    }
    {
        mipc_jr_push(jr, "instance");
        if (mipc_jr_u8(jr, vp, &out->instance)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "trigger", &vp);
    out->has_trigger = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mipc_jr_fail(jr, "optional parameter \"trigger\" given after an absent one");
    } else {
        mipc_jr_push(jr, "trigger");
        if (mipc_jr_u8(jr, vp, &out->trigger)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "type", &vp);
    out->has_type = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mipc_jr_fail(jr, "optional parameter \"type\" given after an absent one");
    } else {
        mipc_jr_push(jr, "type");
        if (mipc_jr_u8(jr, vp, &out->type)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "parameters", &vp);
    out->has_parameters = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mipc_jr_fail(jr, "optional parameter \"parameters\" given after an absent one");
    } else {
        mipc_jr_push(jr, "parameters");
        if (mipc_action_params_from_json(jr, vp, out->type, &out->parameters)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mipc_threedm_event_action_config_response_t */

static int mipc_threedm_event_action_config_response_read(mipc_reader_t *r,
                                                          mipc_threedm_event_action_config_response_t *out) {
    mipc_rd_push(r, "instance");
    if (mipc_rd_u8(r, &out->instance)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "trigger");
    if (mipc_rd_u8(r, &out->trigger)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "type");
    if (mipc_rd_u8(r, &out->type)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "parameters");
    if (mipc_action_params_read(r, out->type, &out->parameters)) {
        return -1;
    }
    mipc_rd_pop(r);
    return mipc_rd_finish(r);
}

static mipc_status_t
mipc_threedm_event_action_config_response_write(mipc_writer_t *w,
                                                const mipc_threedm_event_action_config_response_t *in) {
    mipc_status_t st;
    if ((st = mipc_wr_u8(w, &in->instance)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u8(w, &in->trigger)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u8(w, &in->type)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_action_params_write(w, in->type, &in->parameters)) != MIPC_OK) {
        return st;
    }
    return MIPC_OK;
}

mipc_status_t
mipc_threedm_event_action_config_response_encode(const mipc_threedm_event_action_config_response_t *value,
                                                 uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    mipc_writer_init(&w, buf, cap);
    st = mipc_threedm_event_action_config_response_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mipc_status_t
mipc_threedm_event_action_config_response_decode(const uint8_t *data, size_t len,
                                                 mipc_threedm_event_action_config_response_t *out,
                                                 mipc_decode_error_t *err) {
    mipc_reader_t r;
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_threedm_event_action_config_response_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

void mipc_threedm_event_action_config_response_to_json(
    mipc_jw_t *w, const mipc_threedm_event_action_config_response_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "instance");
    mipc_jw_u8(w, &in->instance);
    mipc_jw_key(w, &first, "trigger");
    mipc_jw_u8(w, &in->trigger);
    mipc_jw_key(w, &first, "type");
    mipc_jw_u8(w, &in->type);
    mipc_jw_key(w, &first, "parameters");
    mipc_action_params_to_json(w, in->type, &in->parameters);
    mipc_jw_raw(w, "}", 1);
}

int mipc_threedm_event_action_config_response_from_json(mipc_jr_t *jr, size_t pos,
                                                        mipc_threedm_event_action_config_response_t *out) {
    static const char *const keys[] = {"instance", "trigger", "type", "parameters"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 4)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "instance", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"instance\"");
    }
    {
        mipc_jr_push(jr, "instance");
        if (mipc_jr_u8(jr, vp, &out->instance)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "trigger", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"trigger\"");
    }
    {
        mipc_jr_push(jr, "trigger");
        if (mipc_jr_u8(jr, vp, &out->trigger)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "type", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"type\"");
    }
    {
        mipc_jr_push(jr, "type");
        if (mipc_jr_u8(jr, vp, &out->type)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "parameters", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"parameters\"");
    }
    {
        mipc_jr_push(jr, "parameters");
        if (mipc_action_params_from_json(jr, vp, out->type, &out->parameters)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mipc_threedm_device_startup_settings_gx5_45_t */

static int
mipc_threedm_device_startup_settings_gx5_45_read(mipc_reader_t *r,
                                                 mipc_threedm_device_startup_settings_gx5_45_t *out) {
    mipc_rd_push(r, "function");
    if (mipc_rd_u8(r, &out->function)) {
        return -1;
    }
    mipc_rd_pop(r);
    return mipc_rd_finish(r);
}

static mipc_status_t
mipc_threedm_device_startup_settings_gx5_45_write(mipc_writer_t *w,
                                                  const mipc_threedm_device_startup_settings_gx5_45_t *in) {
    mipc_status_t st;
    if ((st = mipc_wr_u8(w, &in->function)) != MIPC_OK) {
        return st;
    }
    return MIPC_OK;
}

mipc_status_t
mipc_threedm_device_startup_settings_gx5_45_encode(const mipc_threedm_device_startup_settings_gx5_45_t *value,
                                                   uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    mipc_writer_init(&w, buf, cap);
    st = mipc_threedm_device_startup_settings_gx5_45_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 1 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int
mipc_threedm_device_startup_settings_gx5_45_load(const uint8_t *d,
                                                 mipc_threedm_device_startup_settings_gx5_45_t *out) {
    out->function = mipc_ld_u8(d + 0);
    return 0;
}

/* The general reader: lengths other than 1, bad bool bytes, error details. */
static MIPC_NOINLINE mipc_status_t mipc_threedm_device_startup_settings_gx5_45_decode_read(
    const uint8_t *data, size_t len, mipc_threedm_device_startup_settings_gx5_45_t *out,
    mipc_decode_error_t *err) {
    mipc_reader_t r;
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_threedm_device_startup_settings_gx5_45_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t
mipc_threedm_device_startup_settings_gx5_45_decode(const uint8_t *data, size_t len,
                                                   mipc_threedm_device_startup_settings_gx5_45_t *out,
                                                   mipc_decode_error_t *err) {
    if (len == 1 && mipc_threedm_device_startup_settings_gx5_45_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_threedm_device_startup_settings_gx5_45_decode_read(data, len, out, err);
}

void mipc_threedm_device_startup_settings_gx5_45_to_json(
    mipc_jw_t *w, const mipc_threedm_device_startup_settings_gx5_45_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "function");
    mipc_jw_u8(w, &in->function);
    mipc_jw_raw(w, "}", 1);
}

int mipc_threedm_device_startup_settings_gx5_45_from_json(
    mipc_jr_t *jr, size_t pos, mipc_threedm_device_startup_settings_gx5_45_t *out) {
    static const char *const keys[] = {"function"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 1)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "function", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"function\"");
    }
    {
        mipc_jr_push(jr, "function");
        if (mipc_jr_u8(jr, vp, &out->function)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mipc_threedm_device_startup_settings_cv7_ins_t */

static int
mipc_threedm_device_startup_settings_cv7_ins_read(mipc_reader_t *r,
                                                  mipc_threedm_device_startup_settings_cv7_ins_t *out) {
    mipc_rd_push(r, "function");
    if (mipc_rd_u8(r, &out->function)) {
        return -1;
    }
    mipc_rd_pop(r);
    return mipc_rd_finish(r);
}

static mipc_status_t
mipc_threedm_device_startup_settings_cv7_ins_write(mipc_writer_t *w,
                                                   const mipc_threedm_device_startup_settings_cv7_ins_t *in) {
    mipc_status_t st;
    if ((st = mipc_wr_u8(w, &in->function)) != MIPC_OK) {
        return st;
    }
    return MIPC_OK;
}

mipc_status_t mipc_threedm_device_startup_settings_cv7_ins_encode(
    const mipc_threedm_device_startup_settings_cv7_ins_t *value, uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    mipc_writer_init(&w, buf, cap);
    st = mipc_threedm_device_startup_settings_cv7_ins_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 1 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int
mipc_threedm_device_startup_settings_cv7_ins_load(const uint8_t *d,
                                                  mipc_threedm_device_startup_settings_cv7_ins_t *out) {
    out->function = mipc_ld_u8(d + 0);
    return 0;
}

/* The general reader: lengths other than 1, bad bool bytes, error details. */
static MIPC_NOINLINE mipc_status_t mipc_threedm_device_startup_settings_cv7_ins_decode_read(
    const uint8_t *data, size_t len, mipc_threedm_device_startup_settings_cv7_ins_t *out,
    mipc_decode_error_t *err) {
    mipc_reader_t r;
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_threedm_device_startup_settings_cv7_ins_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t
mipc_threedm_device_startup_settings_cv7_ins_decode(const uint8_t *data, size_t len,
                                                    mipc_threedm_device_startup_settings_cv7_ins_t *out,
                                                    mipc_decode_error_t *err) {
    if (len == 1 && mipc_threedm_device_startup_settings_cv7_ins_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_threedm_device_startup_settings_cv7_ins_decode_read(data, len, out, err);
}

void mipc_threedm_device_startup_settings_cv7_ins_to_json(
    mipc_jw_t *w, const mipc_threedm_device_startup_settings_cv7_ins_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "function");
    mipc_jw_u8(w, &in->function);
    mipc_jw_raw(w, "}", 1);
}

int mipc_threedm_device_startup_settings_cv7_ins_from_json(
    mipc_jr_t *jr, size_t pos, mipc_threedm_device_startup_settings_cv7_ins_t *out) {
    static const char *const keys[] = {"function"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 1)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "function", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"function\"");
    }
    {
        mipc_jr_push(jr, "function");
        if (mipc_jr_u8(jr, vp, &out->function)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mipc_threedm_sensor_to_vehicle_euler_t */

static int mipc_threedm_sensor_to_vehicle_euler_read(mipc_reader_t *r,
                                                     mipc_threedm_sensor_to_vehicle_euler_t *out) {
    mipc_rd_push(r, "function");
    if (mipc_rd_u8(r, &out->function)) {
        return -1;
    }
    mipc_rd_pop(r);
    if (r->pos < r->len) {
        out->has_roll = true;
        mipc_rd_push(r, "roll");
        if (mipc_rd_f32(r, &out->roll)) {
            return -1;
        }
        mipc_rd_pop(r);
    }
    if (r->pos < r->len) {
        out->has_pitch = true;
        mipc_rd_push(r, "pitch");
        if (mipc_rd_f32(r, &out->pitch)) {
            return -1;
        }
        mipc_rd_pop(r);
    }
    if (r->pos < r->len) {
        out->has_yaw = true;
        mipc_rd_push(r, "yaw");
        if (mipc_rd_f32(r, &out->yaw)) {
            return -1;
        }
        mipc_rd_pop(r);
    }
    return mipc_rd_finish(r);
}

static mipc_status_t
mipc_threedm_sensor_to_vehicle_euler_write(mipc_writer_t *w,
                                           const mipc_threedm_sensor_to_vehicle_euler_t *in) {
    mipc_status_t st;
    int absent = 0;
    if ((st = mipc_wr_u8(w, &in->function)) != MIPC_OK) {
        return st;
    }
    if (!in->has_roll) {
        absent = 1;
    } else if (absent) {
        return MIPC_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = mipc_wr_f32(w, &in->roll)) != MIPC_OK) {
            return st;
        }
    }
    if (!in->has_pitch) {
        absent = 1;
    } else if (absent) {
        return MIPC_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = mipc_wr_f32(w, &in->pitch)) != MIPC_OK) {
            return st;
        }
    }
    if (!in->has_yaw) {
        absent = 1;
    } else if (absent) {
        return MIPC_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = mipc_wr_f32(w, &in->yaw)) != MIPC_OK) {
            return st;
        }
    }
    return MIPC_OK;
}

mipc_status_t mipc_threedm_sensor_to_vehicle_euler_encode(const mipc_threedm_sensor_to_vehicle_euler_t *value,
                                                          uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    mipc_writer_init(&w, buf, cap);
    st = mipc_threedm_sensor_to_vehicle_euler_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mipc_status_t mipc_threedm_sensor_to_vehicle_euler_decode(const uint8_t *data, size_t len,
                                                          mipc_threedm_sensor_to_vehicle_euler_t *out,
                                                          mipc_decode_error_t *err) {
    mipc_reader_t r;
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_threedm_sensor_to_vehicle_euler_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

void mipc_threedm_sensor_to_vehicle_euler_to_json(mipc_jw_t *w,
                                                  const mipc_threedm_sensor_to_vehicle_euler_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "function");
    mipc_jw_u8(w, &in->function);
    if (in->has_roll) {
        mipc_jw_key(w, &first, "roll");
        mipc_jw_f32(w, &in->roll);
    }
    if (in->has_pitch) {
        mipc_jw_key(w, &first, "pitch");
        mipc_jw_f32(w, &in->pitch);
    }
    if (in->has_yaw) {
        mipc_jw_key(w, &first, "yaw");
        mipc_jw_f32(w, &in->yaw);
    }
    mipc_jw_raw(w, "}", 1);
}

int mipc_threedm_sensor_to_vehicle_euler_from_json(mipc_jr_t *jr, size_t pos,
                                                   mipc_threedm_sensor_to_vehicle_euler_t *out) {
    static const char *const keys[] = {"function", "roll", "pitch", "yaw"};
    size_t vp = 0;
    int found;
    int absent = 0;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 4)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "function", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"function\"");
    }
    {
        mipc_jr_push(jr, "function");
        if (mipc_jr_u8(jr, vp, &out->function)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "roll", &vp);
    out->has_roll = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mipc_jr_fail(jr, "optional parameter \"roll\" given after an absent one");
    } else {
        mipc_jr_push(jr, "roll");
        if (mipc_jr_f32(jr, vp, &out->roll)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "pitch", &vp);
    out->has_pitch = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mipc_jr_fail(jr, "optional parameter \"pitch\" given after an absent one");
    } else {
        mipc_jr_push(jr, "pitch");
        if (mipc_jr_f32(jr, vp, &out->pitch)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "yaw", &vp);
    out->has_yaw = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mipc_jr_fail(jr, "optional parameter \"yaw\" given after an absent one");
    } else {
        mipc_jr_push(jr, "yaw");
        if (mipc_jr_f32(jr, vp, &out->yaw)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mipc_threedm_sensor_to_vehicle_euler_response_t */

static int
mipc_threedm_sensor_to_vehicle_euler_response_read(mipc_reader_t *r,
                                                   mipc_threedm_sensor_to_vehicle_euler_response_t *out) {
    mipc_rd_push(r, "roll");
    if (mipc_rd_f32(r, &out->roll)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "pitch");
    if (mipc_rd_f32(r, &out->pitch)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "yaw");
    if (mipc_rd_f32(r, &out->yaw)) {
        return -1;
    }
    mipc_rd_pop(r);
    return mipc_rd_finish(r);
}

static mipc_status_t mipc_threedm_sensor_to_vehicle_euler_response_write(
    mipc_writer_t *w, const mipc_threedm_sensor_to_vehicle_euler_response_t *in) {
    mipc_status_t st;
    if ((st = mipc_wr_f32(w, &in->roll)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_f32(w, &in->pitch)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_f32(w, &in->yaw)) != MIPC_OK) {
        return st;
    }
    return MIPC_OK;
}

mipc_status_t mipc_threedm_sensor_to_vehicle_euler_response_encode(
    const mipc_threedm_sensor_to_vehicle_euler_response_t *value, uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    mipc_writer_init(&w, buf, cap);
    st = mipc_threedm_sensor_to_vehicle_euler_response_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 12 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int
mipc_threedm_sensor_to_vehicle_euler_response_load(const uint8_t *d,
                                                   mipc_threedm_sensor_to_vehicle_euler_response_t *out) {
    out->roll = mipc_ld_f32(d + 0);
    out->pitch = mipc_ld_f32(d + 4);
    out->yaw = mipc_ld_f32(d + 8);
    return 0;
}

/* The general reader: lengths other than 12, bad bool bytes, error details. */
static MIPC_NOINLINE mipc_status_t mipc_threedm_sensor_to_vehicle_euler_response_decode_read(
    const uint8_t *data, size_t len, mipc_threedm_sensor_to_vehicle_euler_response_t *out,
    mipc_decode_error_t *err) {
    mipc_reader_t r;
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_threedm_sensor_to_vehicle_euler_response_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t
mipc_threedm_sensor_to_vehicle_euler_response_decode(const uint8_t *data, size_t len,
                                                     mipc_threedm_sensor_to_vehicle_euler_response_t *out,
                                                     mipc_decode_error_t *err) {
    if (len == 12 && mipc_threedm_sensor_to_vehicle_euler_response_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_threedm_sensor_to_vehicle_euler_response_decode_read(data, len, out, err);
}

void mipc_threedm_sensor_to_vehicle_euler_response_to_json(
    mipc_jw_t *w, const mipc_threedm_sensor_to_vehicle_euler_response_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "roll");
    mipc_jw_f32(w, &in->roll);
    mipc_jw_key(w, &first, "pitch");
    mipc_jw_f32(w, &in->pitch);
    mipc_jw_key(w, &first, "yaw");
    mipc_jw_f32(w, &in->yaw);
    mipc_jw_raw(w, "}", 1);
}

int mipc_threedm_sensor_to_vehicle_euler_response_from_json(
    mipc_jr_t *jr, size_t pos, mipc_threedm_sensor_to_vehicle_euler_response_t *out) {
    static const char *const keys[] = {"roll", "pitch", "yaw"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 3)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "roll", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"roll\"");
    }
    {
        mipc_jr_push(jr, "roll");
        if (mipc_jr_f32(jr, vp, &out->roll)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "pitch", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"pitch\"");
    }
    {
        mipc_jr_push(jr, "pitch");
        if (mipc_jr_f32(jr, vp, &out->pitch)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "yaw", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"yaw\"");
    }
    {
        mipc_jr_push(jr, "yaw");
        if (mipc_jr_f32(jr, vp, &out->yaw)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mipc_threedm_sensor_to_vehicle_quaternion_t */

static int mipc_threedm_sensor_to_vehicle_quaternion_read(mipc_reader_t *r,
                                                          mipc_threedm_sensor_to_vehicle_quaternion_t *out) {
    size_t i;
    mipc_rd_push(r, "function");
    if (mipc_rd_u8(r, &out->function)) {
        return -1;
    }
    mipc_rd_pop(r);
    if (r->pos < r->len) {
        out->has_q = true;
        mipc_rd_push(r, "q");
        for (i = 0; i < 4; i++) {
            mipc_rd_index(r, i);
            if (mipc_rd_f32(r, &out->q[i])) {
                return -1;
            }
        }
        mipc_rd_pop(r);
    }
    return mipc_rd_finish(r);
}

static mipc_status_t
mipc_threedm_sensor_to_vehicle_quaternion_write(mipc_writer_t *w,
                                                const mipc_threedm_sensor_to_vehicle_quaternion_t *in) {
    mipc_status_t st;
    size_t i;
    int absent = 0;
    if ((st = mipc_wr_u8(w, &in->function)) != MIPC_OK) {
        return st;
    }
    if (!in->has_q) {
        absent = 1;
    } else if (absent) {
        return MIPC_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        for (i = 0; i < 4; i++) {
            if ((st = mipc_wr_f32(w, &in->q[i])) != MIPC_OK) {
                return st;
            }
        }
    }
    return MIPC_OK;
}

mipc_status_t
mipc_threedm_sensor_to_vehicle_quaternion_encode(const mipc_threedm_sensor_to_vehicle_quaternion_t *value,
                                                 uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    mipc_writer_init(&w, buf, cap);
    st = mipc_threedm_sensor_to_vehicle_quaternion_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mipc_status_t
mipc_threedm_sensor_to_vehicle_quaternion_decode(const uint8_t *data, size_t len,
                                                 mipc_threedm_sensor_to_vehicle_quaternion_t *out,
                                                 mipc_decode_error_t *err) {
    mipc_reader_t r;
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_threedm_sensor_to_vehicle_quaternion_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

void mipc_threedm_sensor_to_vehicle_quaternion_to_json(
    mipc_jw_t *w, const mipc_threedm_sensor_to_vehicle_quaternion_t *in) {
    int first = 1;
    size_t i;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "function");
    mipc_jw_u8(w, &in->function);
    if (in->has_q) {
        mipc_jw_key(w, &first, "q");
        mipc_jw_raw(w, "[", 1);
        for (i = 0; i < 4; i++) {
            mipc_jw_sep(w, i);
            mipc_jw_f32(w, &in->q[i]);
        }
        mipc_jw_raw(w, "]", 1);
    }
    mipc_jw_raw(w, "}", 1);
}

int mipc_threedm_sensor_to_vehicle_quaternion_from_json(mipc_jr_t *jr, size_t pos,
                                                        mipc_threedm_sensor_to_vehicle_quaternion_t *out) {
    static const char *const keys[] = {"function", "q"};
    size_t vp = 0;
    int found;
    int absent = 0;
    size_t i;
    size_t it = 0;
    size_t ep = 0;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 2)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "function", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"function\"");
    }
    {
        mipc_jr_push(jr, "function");
        if (mipc_jr_u8(jr, vp, &out->function)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "q", &vp);
    out->has_q = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mipc_jr_fail(jr, "optional parameter \"q\" given after an absent one");
    } else {
        mipc_jr_push(jr, "q");
        if (mipc_jr_array(jr, vp, &it)) {
            return -1;
        }
        for (i = 0;; i++) {
            int more = mipc_jr_next(jr, &it, &ep);
            if (more < 0) {
                return -1;
            }
            if (!more) {
                break;
            }
            if (i >= 4) {
                return mipc_jr_fail(jr, "more than 4 elements");
            }
            mipc_jr_index(jr, i);
            if (mipc_jr_f32(jr, ep, &out->q[i])) {
                return -1;
            }
        }
        mipc_jr_index(jr, SIZE_MAX);
        if (i != 4) {
            return mipc_jr_fail(jr, "expected 4 elements, got %zu", i);
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mipc_threedm_sensor_to_vehicle_quaternion_response_t */

static int mipc_threedm_sensor_to_vehicle_quaternion_response_read(
    mipc_reader_t *r, mipc_threedm_sensor_to_vehicle_quaternion_response_t *out) {
    size_t i;
    mipc_rd_push(r, "q");
    for (i = 0; i < 4; i++) {
        mipc_rd_index(r, i);
        if (mipc_rd_f32(r, &out->q[i])) {
            return -1;
        }
    }
    mipc_rd_pop(r);
    return mipc_rd_finish(r);
}

static mipc_status_t mipc_threedm_sensor_to_vehicle_quaternion_response_write(
    mipc_writer_t *w, const mipc_threedm_sensor_to_vehicle_quaternion_response_t *in) {
    mipc_status_t st;
    size_t i;
    for (i = 0; i < 4; i++) {
        if ((st = mipc_wr_f32(w, &in->q[i])) != MIPC_OK) {
            return st;
        }
    }
    return MIPC_OK;
}

mipc_status_t mipc_threedm_sensor_to_vehicle_quaternion_response_encode(
    const mipc_threedm_sensor_to_vehicle_quaternion_response_t *value, uint8_t *buf, size_t cap,
    size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    mipc_writer_init(&w, buf, cap);
    st = mipc_threedm_sensor_to_vehicle_quaternion_response_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 16 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mipc_threedm_sensor_to_vehicle_quaternion_response_load(
    const uint8_t *d, mipc_threedm_sensor_to_vehicle_quaternion_response_t *out) {
    out->q[0] = mipc_ld_f32(d + 0);
    out->q[1] = mipc_ld_f32(d + 4);
    out->q[2] = mipc_ld_f32(d + 8);
    out->q[3] = mipc_ld_f32(d + 12);
    return 0;
}

/* The general reader: lengths other than 16, bad bool bytes, error details. */
static MIPC_NOINLINE mipc_status_t mipc_threedm_sensor_to_vehicle_quaternion_response_decode_read(
    const uint8_t *data, size_t len, mipc_threedm_sensor_to_vehicle_quaternion_response_t *out,
    mipc_decode_error_t *err) {
    mipc_reader_t r;
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_threedm_sensor_to_vehicle_quaternion_response_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t mipc_threedm_sensor_to_vehicle_quaternion_response_decode(
    const uint8_t *data, size_t len, mipc_threedm_sensor_to_vehicle_quaternion_response_t *out,
    mipc_decode_error_t *err) {
    if (len == 16 && mipc_threedm_sensor_to_vehicle_quaternion_response_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_threedm_sensor_to_vehicle_quaternion_response_decode_read(data, len, out, err);
}

void mipc_threedm_sensor_to_vehicle_quaternion_response_to_json(
    mipc_jw_t *w, const mipc_threedm_sensor_to_vehicle_quaternion_response_t *in) {
    int first = 1;
    size_t i;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "q");
    mipc_jw_raw(w, "[", 1);
    for (i = 0; i < 4; i++) {
        mipc_jw_sep(w, i);
        mipc_jw_f32(w, &in->q[i]);
    }
    mipc_jw_raw(w, "]", 1);
    mipc_jw_raw(w, "}", 1);
}

int mipc_threedm_sensor_to_vehicle_quaternion_response_from_json(
    mipc_jr_t *jr, size_t pos, mipc_threedm_sensor_to_vehicle_quaternion_response_t *out) {
    static const char *const keys[] = {"q"};
    size_t vp = 0;
    int found;
    size_t i;
    size_t it = 0;
    size_t ep = 0;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 1)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "q", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"q\"");
    }
    {
        mipc_jr_push(jr, "q");
        if (mipc_jr_array(jr, vp, &it)) {
            return -1;
        }
        for (i = 0;; i++) {
            int more = mipc_jr_next(jr, &it, &ep);
            if (more < 0) {
                return -1;
            }
            if (!more) {
                break;
            }
            if (i >= 4) {
                return mipc_jr_fail(jr, "more than 4 elements");
            }
            mipc_jr_index(jr, i);
            if (mipc_jr_f32(jr, ep, &out->q[i])) {
                return -1;
            }
        }
        mipc_jr_index(jr, SIZE_MAX);
        if (i != 4) {
            return mipc_jr_fail(jr, "expected 4 elements, got %zu", i);
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mipc_threedm_sensor_to_vehicle_dcm_t */

static int mipc_threedm_sensor_to_vehicle_dcm_read(mipc_reader_t *r,
                                                   mipc_threedm_sensor_to_vehicle_dcm_t *out) {
    size_t i;
    mipc_rd_push(r, "function");
    if (mipc_rd_u8(r, &out->function)) {
        return -1;
    }
    mipc_rd_pop(r);
    if (r->pos < r->len) {
        out->has_dcm = true;
        mipc_rd_push(r, "dcm");
        for (i = 0; i < 9; i++) {
            mipc_rd_index(r, i);
            if (mipc_rd_f32(r, &out->dcm[i])) {
                return -1;
            }
        }
        mipc_rd_pop(r);
    }
    return mipc_rd_finish(r);
}

static mipc_status_t
mipc_threedm_sensor_to_vehicle_dcm_write(mipc_writer_t *w, const mipc_threedm_sensor_to_vehicle_dcm_t *in) {
    mipc_status_t st;
    size_t i;
    int absent = 0;
    if ((st = mipc_wr_u8(w, &in->function)) != MIPC_OK) {
        return st;
    }
    if (!in->has_dcm) {
        absent = 1;
    } else if (absent) {
        return MIPC_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        for (i = 0; i < 9; i++) {
            if ((st = mipc_wr_f32(w, &in->dcm[i])) != MIPC_OK) {
                return st;
            }
        }
    }
    return MIPC_OK;
}

mipc_status_t mipc_threedm_sensor_to_vehicle_dcm_encode(const mipc_threedm_sensor_to_vehicle_dcm_t *value,
                                                        uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    mipc_writer_init(&w, buf, cap);
    st = mipc_threedm_sensor_to_vehicle_dcm_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mipc_status_t mipc_threedm_sensor_to_vehicle_dcm_decode(const uint8_t *data, size_t len,
                                                        mipc_threedm_sensor_to_vehicle_dcm_t *out,
                                                        mipc_decode_error_t *err) {
    mipc_reader_t r;
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_threedm_sensor_to_vehicle_dcm_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

void mipc_threedm_sensor_to_vehicle_dcm_to_json(mipc_jw_t *w,
                                                const mipc_threedm_sensor_to_vehicle_dcm_t *in) {
    int first = 1;
    size_t i;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "function");
    mipc_jw_u8(w, &in->function);
    if (in->has_dcm) {
        mipc_jw_key(w, &first, "dcm");
        mipc_jw_raw(w, "[", 1);
        for (i = 0; i < 9; i++) {
            mipc_jw_sep(w, i);
            mipc_jw_f32(w, &in->dcm[i]);
        }
        mipc_jw_raw(w, "]", 1);
    }
    mipc_jw_raw(w, "}", 1);
}

int mipc_threedm_sensor_to_vehicle_dcm_from_json(mipc_jr_t *jr, size_t pos,
                                                 mipc_threedm_sensor_to_vehicle_dcm_t *out) {
    static const char *const keys[] = {"function", "dcm"};
    size_t vp = 0;
    int found;
    int absent = 0;
    size_t i;
    size_t it = 0;
    size_t ep = 0;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 2)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "function", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"function\"");
    }
    {
        mipc_jr_push(jr, "function");
        if (mipc_jr_u8(jr, vp, &out->function)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "dcm", &vp);
    out->has_dcm = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mipc_jr_fail(jr, "optional parameter \"dcm\" given after an absent one");
    } else {
        mipc_jr_push(jr, "dcm");
        if (mipc_jr_array(jr, vp, &it)) {
            return -1;
        }
        for (i = 0;; i++) {
            int more = mipc_jr_next(jr, &it, &ep);
            if (more < 0) {
                return -1;
            }
            if (!more) {
                break;
            }
            if (i >= 9) {
                return mipc_jr_fail(jr, "more than 9 elements");
            }
            mipc_jr_index(jr, i);
            if (mipc_jr_f32(jr, ep, &out->dcm[i])) {
                return -1;
            }
        }
        mipc_jr_index(jr, SIZE_MAX);
        if (i != 9) {
            return mipc_jr_fail(jr, "expected 9 elements, got %zu", i);
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mipc_threedm_sensor_to_vehicle_dcm_response_t */

static int
mipc_threedm_sensor_to_vehicle_dcm_response_read(mipc_reader_t *r,
                                                 mipc_threedm_sensor_to_vehicle_dcm_response_t *out) {
    size_t i;
    mipc_rd_push(r, "dcm");
    for (i = 0; i < 9; i++) {
        mipc_rd_index(r, i);
        if (mipc_rd_f32(r, &out->dcm[i])) {
            return -1;
        }
    }
    mipc_rd_pop(r);
    return mipc_rd_finish(r);
}

static mipc_status_t
mipc_threedm_sensor_to_vehicle_dcm_response_write(mipc_writer_t *w,
                                                  const mipc_threedm_sensor_to_vehicle_dcm_response_t *in) {
    mipc_status_t st;
    size_t i;
    for (i = 0; i < 9; i++) {
        if ((st = mipc_wr_f32(w, &in->dcm[i])) != MIPC_OK) {
            return st;
        }
    }
    return MIPC_OK;
}

mipc_status_t
mipc_threedm_sensor_to_vehicle_dcm_response_encode(const mipc_threedm_sensor_to_vehicle_dcm_response_t *value,
                                                   uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    mipc_writer_init(&w, buf, cap);
    st = mipc_threedm_sensor_to_vehicle_dcm_response_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 36 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int
mipc_threedm_sensor_to_vehicle_dcm_response_load(const uint8_t *d,
                                                 mipc_threedm_sensor_to_vehicle_dcm_response_t *out) {
    out->dcm[0] = mipc_ld_f32(d + 0);
    out->dcm[1] = mipc_ld_f32(d + 4);
    out->dcm[2] = mipc_ld_f32(d + 8);
    out->dcm[3] = mipc_ld_f32(d + 12);
    out->dcm[4] = mipc_ld_f32(d + 16);
    out->dcm[5] = mipc_ld_f32(d + 20);
    out->dcm[6] = mipc_ld_f32(d + 24);
    out->dcm[7] = mipc_ld_f32(d + 28);
    out->dcm[8] = mipc_ld_f32(d + 32);
    return 0;
}

/* The general reader: lengths other than 36, bad bool bytes, error details. */
static MIPC_NOINLINE mipc_status_t mipc_threedm_sensor_to_vehicle_dcm_response_decode_read(
    const uint8_t *data, size_t len, mipc_threedm_sensor_to_vehicle_dcm_response_t *out,
    mipc_decode_error_t *err) {
    mipc_reader_t r;
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_threedm_sensor_to_vehicle_dcm_response_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t
mipc_threedm_sensor_to_vehicle_dcm_response_decode(const uint8_t *data, size_t len,
                                                   mipc_threedm_sensor_to_vehicle_dcm_response_t *out,
                                                   mipc_decode_error_t *err) {
    if (len == 36 && mipc_threedm_sensor_to_vehicle_dcm_response_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_threedm_sensor_to_vehicle_dcm_response_decode_read(data, len, out, err);
}

void mipc_threedm_sensor_to_vehicle_dcm_response_to_json(
    mipc_jw_t *w, const mipc_threedm_sensor_to_vehicle_dcm_response_t *in) {
    int first = 1;
    size_t i;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "dcm");
    mipc_jw_raw(w, "[", 1);
    for (i = 0; i < 9; i++) {
        mipc_jw_sep(w, i);
        mipc_jw_f32(w, &in->dcm[i]);
    }
    mipc_jw_raw(w, "]", 1);
    mipc_jw_raw(w, "}", 1);
}

int mipc_threedm_sensor_to_vehicle_dcm_response_from_json(
    mipc_jr_t *jr, size_t pos, mipc_threedm_sensor_to_vehicle_dcm_response_t *out) {
    static const char *const keys[] = {"dcm"};
    size_t vp = 0;
    int found;
    size_t i;
    size_t it = 0;
    size_t ep = 0;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 1)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "dcm", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"dcm\"");
    }
    {
        mipc_jr_push(jr, "dcm");
        if (mipc_jr_array(jr, vp, &it)) {
            return -1;
        }
        for (i = 0;; i++) {
            int more = mipc_jr_next(jr, &it, &ep);
            if (more < 0) {
                return -1;
            }
            if (!more) {
                break;
            }
            if (i >= 9) {
                return mipc_jr_fail(jr, "more than 9 elements");
            }
            mipc_jr_index(jr, i);
            if (mipc_jr_f32(jr, ep, &out->dcm[i])) {
                return -1;
            }
        }
        mipc_jr_index(jr, SIZE_MAX);
        if (i != 9) {
            return mipc_jr_fail(jr, "expected 9 elements, got %zu", i);
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mipc_threedm_accel_bias_gx5_45_t */

static int mipc_threedm_accel_bias_gx5_45_read(mipc_reader_t *r, mipc_threedm_accel_bias_gx5_45_t *out) {
    size_t i;
    mipc_rd_push(r, "function");
    if (mipc_rd_u8(r, &out->function)) {
        return -1;
    }
    mipc_rd_pop(r);
    if (r->pos < r->len) {
        out->has_bias = true;
        mipc_rd_push(r, "bias");
        for (i = 0; i < 3; i++) {
            mipc_rd_index(r, i);
            if (mipc_rd_f32(r, &out->bias[i])) {
                return -1;
            }
        }
        mipc_rd_pop(r);
    }
    return mipc_rd_finish(r);
}

static mipc_status_t mipc_threedm_accel_bias_gx5_45_write(mipc_writer_t *w,
                                                          const mipc_threedm_accel_bias_gx5_45_t *in) {
    mipc_status_t st;
    size_t i;
    int absent = 0;
    if ((st = mipc_wr_u8(w, &in->function)) != MIPC_OK) {
        return st;
    }
    if (!in->has_bias) {
        absent = 1;
    } else if (absent) {
        return MIPC_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        for (i = 0; i < 3; i++) {
            if ((st = mipc_wr_f32(w, &in->bias[i])) != MIPC_OK) {
                return st;
            }
        }
    }
    return MIPC_OK;
}

mipc_status_t mipc_threedm_accel_bias_gx5_45_encode(const mipc_threedm_accel_bias_gx5_45_t *value,
                                                    uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    mipc_writer_init(&w, buf, cap);
    st = mipc_threedm_accel_bias_gx5_45_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mipc_status_t mipc_threedm_accel_bias_gx5_45_decode(const uint8_t *data, size_t len,
                                                    mipc_threedm_accel_bias_gx5_45_t *out,
                                                    mipc_decode_error_t *err) {
    mipc_reader_t r;
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_threedm_accel_bias_gx5_45_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

void mipc_threedm_accel_bias_gx5_45_to_json(mipc_jw_t *w, const mipc_threedm_accel_bias_gx5_45_t *in) {
    int first = 1;
    size_t i;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "function");
    mipc_jw_u8(w, &in->function);
    if (in->has_bias) {
        mipc_jw_key(w, &first, "bias");
        mipc_jw_raw(w, "[", 1);
        for (i = 0; i < 3; i++) {
            mipc_jw_sep(w, i);
            mipc_jw_f32(w, &in->bias[i]);
        }
        mipc_jw_raw(w, "]", 1);
    }
    mipc_jw_raw(w, "}", 1);
}

int mipc_threedm_accel_bias_gx5_45_from_json(mipc_jr_t *jr, size_t pos,
                                             mipc_threedm_accel_bias_gx5_45_t *out) {
    static const char *const keys[] = {"function", "bias"};
    size_t vp = 0;
    int found;
    int absent = 0;
    size_t i;
    size_t it = 0;
    size_t ep = 0;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 2)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "function", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"function\"");
    }
    {
        mipc_jr_push(jr, "function");
        if (mipc_jr_u8(jr, vp, &out->function)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "bias", &vp);
    out->has_bias = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mipc_jr_fail(jr, "optional parameter \"bias\" given after an absent one");
    } else {
        mipc_jr_push(jr, "bias");
        if (mipc_jr_array(jr, vp, &it)) {
            return -1;
        }
        for (i = 0;; i++) {
            int more = mipc_jr_next(jr, &it, &ep);
            if (more < 0) {
                return -1;
            }
            if (!more) {
                break;
            }
            if (i >= 3) {
                return mipc_jr_fail(jr, "more than 3 elements");
            }
            mipc_jr_index(jr, i);
            if (mipc_jr_f32(jr, ep, &out->bias[i])) {
                return -1;
            }
        }
        mipc_jr_index(jr, SIZE_MAX);
        if (i != 3) {
            return mipc_jr_fail(jr, "expected 3 elements, got %zu", i);
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mipc_threedm_accel_bias_cv7_ins_t */

static int mipc_threedm_accel_bias_cv7_ins_read(mipc_reader_t *r, mipc_threedm_accel_bias_cv7_ins_t *out) {
    size_t i;
    mipc_rd_push(r, "function");
    if (mipc_rd_u8(r, &out->function)) {
        return -1;
    }
    mipc_rd_pop(r);
    if (r->pos < r->len) {
        out->has_bias = true;
        mipc_rd_push(r, "bias");
        for (i = 0; i < 3; i++) {
            mipc_rd_index(r, i);
            if (mipc_rd_f32(r, &out->bias[i])) {
                return -1;
            }
        }
        mipc_rd_pop(r);
    }
    return mipc_rd_finish(r);
}

static mipc_status_t mipc_threedm_accel_bias_cv7_ins_write(mipc_writer_t *w,
                                                           const mipc_threedm_accel_bias_cv7_ins_t *in) {
    mipc_status_t st;
    size_t i;
    int absent = 0;
    if ((st = mipc_wr_u8(w, &in->function)) != MIPC_OK) {
        return st;
    }
    if (!in->has_bias) {
        absent = 1;
    } else if (absent) {
        return MIPC_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        for (i = 0; i < 3; i++) {
            if ((st = mipc_wr_f32(w, &in->bias[i])) != MIPC_OK) {
                return st;
            }
        }
    }
    return MIPC_OK;
}

mipc_status_t mipc_threedm_accel_bias_cv7_ins_encode(const mipc_threedm_accel_bias_cv7_ins_t *value,
                                                     uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    mipc_writer_init(&w, buf, cap);
    st = mipc_threedm_accel_bias_cv7_ins_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mipc_status_t mipc_threedm_accel_bias_cv7_ins_decode(const uint8_t *data, size_t len,
                                                     mipc_threedm_accel_bias_cv7_ins_t *out,
                                                     mipc_decode_error_t *err) {
    mipc_reader_t r;
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_threedm_accel_bias_cv7_ins_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

void mipc_threedm_accel_bias_cv7_ins_to_json(mipc_jw_t *w, const mipc_threedm_accel_bias_cv7_ins_t *in) {
    int first = 1;
    size_t i;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "function");
    mipc_jw_u8(w, &in->function);
    if (in->has_bias) {
        mipc_jw_key(w, &first, "bias");
        mipc_jw_raw(w, "[", 1);
        for (i = 0; i < 3; i++) {
            mipc_jw_sep(w, i);
            mipc_jw_f32(w, &in->bias[i]);
        }
        mipc_jw_raw(w, "]", 1);
    }
    mipc_jw_raw(w, "}", 1);
}

int mipc_threedm_accel_bias_cv7_ins_from_json(mipc_jr_t *jr, size_t pos,
                                              mipc_threedm_accel_bias_cv7_ins_t *out) {
    static const char *const keys[] = {"function", "bias"};
    size_t vp = 0;
    int found;
    int absent = 0;
    size_t i;
    size_t it = 0;
    size_t ep = 0;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 2)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "function", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"function\"");
    }
    {
        mipc_jr_push(jr, "function");
        if (mipc_jr_u8(jr, vp, &out->function)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "bias", &vp);
    out->has_bias = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mipc_jr_fail(jr, "optional parameter \"bias\" given after an absent one");
    } else {
        mipc_jr_push(jr, "bias");
        if (mipc_jr_array(jr, vp, &it)) {
            return -1;
        }
        for (i = 0;; i++) {
            int more = mipc_jr_next(jr, &it, &ep);
            if (more < 0) {
                return -1;
            }
            if (!more) {
                break;
            }
            if (i >= 3) {
                return mipc_jr_fail(jr, "more than 3 elements");
            }
            mipc_jr_index(jr, i);
            if (mipc_jr_f32(jr, ep, &out->bias[i])) {
                return -1;
            }
        }
        mipc_jr_index(jr, SIZE_MAX);
        if (i != 3) {
            return mipc_jr_fail(jr, "expected 3 elements, got %zu", i);
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mipc_threedm_accel_bias_response_t */

static int mipc_threedm_accel_bias_response_read(mipc_reader_t *r, mipc_threedm_accel_bias_response_t *out) {
    size_t i;
    mipc_rd_push(r, "bias");
    for (i = 0; i < 3; i++) {
        mipc_rd_index(r, i);
        if (mipc_rd_f32(r, &out->bias[i])) {
            return -1;
        }
    }
    mipc_rd_pop(r);
    return mipc_rd_finish(r);
}

static mipc_status_t mipc_threedm_accel_bias_response_write(mipc_writer_t *w,
                                                            const mipc_threedm_accel_bias_response_t *in) {
    mipc_status_t st;
    size_t i;
    for (i = 0; i < 3; i++) {
        if ((st = mipc_wr_f32(w, &in->bias[i])) != MIPC_OK) {
            return st;
        }
    }
    return MIPC_OK;
}

mipc_status_t mipc_threedm_accel_bias_response_encode(const mipc_threedm_accel_bias_response_t *value,
                                                      uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    mipc_writer_init(&w, buf, cap);
    st = mipc_threedm_accel_bias_response_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 12 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mipc_threedm_accel_bias_response_load(const uint8_t *d, mipc_threedm_accel_bias_response_t *out) {
    out->bias[0] = mipc_ld_f32(d + 0);
    out->bias[1] = mipc_ld_f32(d + 4);
    out->bias[2] = mipc_ld_f32(d + 8);
    return 0;
}

/* The general reader: lengths other than 12, bad bool bytes, error details. */
static MIPC_NOINLINE mipc_status_t mipc_threedm_accel_bias_response_decode_read(
    const uint8_t *data, size_t len, mipc_threedm_accel_bias_response_t *out, mipc_decode_error_t *err) {
    mipc_reader_t r;
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_threedm_accel_bias_response_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t mipc_threedm_accel_bias_response_decode(const uint8_t *data, size_t len,
                                                      mipc_threedm_accel_bias_response_t *out,
                                                      mipc_decode_error_t *err) {
    if (len == 12 && mipc_threedm_accel_bias_response_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_threedm_accel_bias_response_decode_read(data, len, out, err);
}

void mipc_threedm_accel_bias_response_to_json(mipc_jw_t *w, const mipc_threedm_accel_bias_response_t *in) {
    int first = 1;
    size_t i;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "bias");
    mipc_jw_raw(w, "[", 1);
    for (i = 0; i < 3; i++) {
        mipc_jw_sep(w, i);
        mipc_jw_f32(w, &in->bias[i]);
    }
    mipc_jw_raw(w, "]", 1);
    mipc_jw_raw(w, "}", 1);
}

int mipc_threedm_accel_bias_response_from_json(mipc_jr_t *jr, size_t pos,
                                               mipc_threedm_accel_bias_response_t *out) {
    static const char *const keys[] = {"bias"};
    size_t vp = 0;
    int found;
    size_t i;
    size_t it = 0;
    size_t ep = 0;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 1)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "bias", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"bias\"");
    }
    {
        mipc_jr_push(jr, "bias");
        if (mipc_jr_array(jr, vp, &it)) {
            return -1;
        }
        for (i = 0;; i++) {
            int more = mipc_jr_next(jr, &it, &ep);
            if (more < 0) {
                return -1;
            }
            if (!more) {
                break;
            }
            if (i >= 3) {
                return mipc_jr_fail(jr, "more than 3 elements");
            }
            mipc_jr_index(jr, i);
            if (mipc_jr_f32(jr, ep, &out->bias[i])) {
                return -1;
            }
        }
        mipc_jr_index(jr, SIZE_MAX);
        if (i != 3) {
            return mipc_jr_fail(jr, "expected 3 elements, got %zu", i);
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mipc_threedm_gyro_bias_gx5_45_t */

static int mipc_threedm_gyro_bias_gx5_45_read(mipc_reader_t *r, mipc_threedm_gyro_bias_gx5_45_t *out) {
    size_t i;
    mipc_rd_push(r, "function");
    if (mipc_rd_u8(r, &out->function)) {
        return -1;
    }
    mipc_rd_pop(r);
    if (r->pos < r->len) {
        out->has_bias = true;
        mipc_rd_push(r, "bias");
        for (i = 0; i < 3; i++) {
            mipc_rd_index(r, i);
            if (mipc_rd_f32(r, &out->bias[i])) {
                return -1;
            }
        }
        mipc_rd_pop(r);
    }
    return mipc_rd_finish(r);
}

static mipc_status_t mipc_threedm_gyro_bias_gx5_45_write(mipc_writer_t *w,
                                                         const mipc_threedm_gyro_bias_gx5_45_t *in) {
    mipc_status_t st;
    size_t i;
    int absent = 0;
    if ((st = mipc_wr_u8(w, &in->function)) != MIPC_OK) {
        return st;
    }
    if (!in->has_bias) {
        absent = 1;
    } else if (absent) {
        return MIPC_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        for (i = 0; i < 3; i++) {
            if ((st = mipc_wr_f32(w, &in->bias[i])) != MIPC_OK) {
                return st;
            }
        }
    }
    return MIPC_OK;
}

mipc_status_t mipc_threedm_gyro_bias_gx5_45_encode(const mipc_threedm_gyro_bias_gx5_45_t *value, uint8_t *buf,
                                                   size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    mipc_writer_init(&w, buf, cap);
    st = mipc_threedm_gyro_bias_gx5_45_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mipc_status_t mipc_threedm_gyro_bias_gx5_45_decode(const uint8_t *data, size_t len,
                                                   mipc_threedm_gyro_bias_gx5_45_t *out,
                                                   mipc_decode_error_t *err) {
    mipc_reader_t r;
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_threedm_gyro_bias_gx5_45_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

void mipc_threedm_gyro_bias_gx5_45_to_json(mipc_jw_t *w, const mipc_threedm_gyro_bias_gx5_45_t *in) {
    int first = 1;
    size_t i;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "function");
    mipc_jw_u8(w, &in->function);
    if (in->has_bias) {
        mipc_jw_key(w, &first, "bias");
        mipc_jw_raw(w, "[", 1);
        for (i = 0; i < 3; i++) {
            mipc_jw_sep(w, i);
            mipc_jw_f32(w, &in->bias[i]);
        }
        mipc_jw_raw(w, "]", 1);
    }
    mipc_jw_raw(w, "}", 1);
}

int mipc_threedm_gyro_bias_gx5_45_from_json(mipc_jr_t *jr, size_t pos, mipc_threedm_gyro_bias_gx5_45_t *out) {
    static const char *const keys[] = {"function", "bias"};
    size_t vp = 0;
    int found;
    int absent = 0;
    size_t i;
    size_t it = 0;
    size_t ep = 0;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 2)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "function", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"function\"");
    }
    {
        mipc_jr_push(jr, "function");
        if (mipc_jr_u8(jr, vp, &out->function)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "bias", &vp);
    out->has_bias = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mipc_jr_fail(jr, "optional parameter \"bias\" given after an absent one");
    } else {
        mipc_jr_push(jr, "bias");
        if (mipc_jr_array(jr, vp, &it)) {
            return -1;
        }
        for (i = 0;; i++) {
            int more = mipc_jr_next(jr, &it, &ep);
            if (more < 0) {
                return -1;
            }
            if (!more) {
                break;
            }
            if (i >= 3) {
                return mipc_jr_fail(jr, "more than 3 elements");
            }
            mipc_jr_index(jr, i);
            if (mipc_jr_f32(jr, ep, &out->bias[i])) {
                return -1;
            }
        }
        mipc_jr_index(jr, SIZE_MAX);
        if (i != 3) {
            return mipc_jr_fail(jr, "expected 3 elements, got %zu", i);
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mipc_threedm_gyro_bias_cv7_ins_t */

static int mipc_threedm_gyro_bias_cv7_ins_read(mipc_reader_t *r, mipc_threedm_gyro_bias_cv7_ins_t *out) {
    size_t i;
    mipc_rd_push(r, "function");
    if (mipc_rd_u8(r, &out->function)) {
        return -1;
    }
    mipc_rd_pop(r);
    if (r->pos < r->len) {
        out->has_bias = true;
        mipc_rd_push(r, "bias");
        for (i = 0; i < 3; i++) {
            mipc_rd_index(r, i);
            if (mipc_rd_f32(r, &out->bias[i])) {
                return -1;
            }
        }
        mipc_rd_pop(r);
    }
    return mipc_rd_finish(r);
}

static mipc_status_t mipc_threedm_gyro_bias_cv7_ins_write(mipc_writer_t *w,
                                                          const mipc_threedm_gyro_bias_cv7_ins_t *in) {
    mipc_status_t st;
    size_t i;
    int absent = 0;
    if ((st = mipc_wr_u8(w, &in->function)) != MIPC_OK) {
        return st;
    }
    if (!in->has_bias) {
        absent = 1;
    } else if (absent) {
        return MIPC_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        for (i = 0; i < 3; i++) {
            if ((st = mipc_wr_f32(w, &in->bias[i])) != MIPC_OK) {
                return st;
            }
        }
    }
    return MIPC_OK;
}

mipc_status_t mipc_threedm_gyro_bias_cv7_ins_encode(const mipc_threedm_gyro_bias_cv7_ins_t *value,
                                                    uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    mipc_writer_init(&w, buf, cap);
    st = mipc_threedm_gyro_bias_cv7_ins_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mipc_status_t mipc_threedm_gyro_bias_cv7_ins_decode(const uint8_t *data, size_t len,
                                                    mipc_threedm_gyro_bias_cv7_ins_t *out,
                                                    mipc_decode_error_t *err) {
    mipc_reader_t r;
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_threedm_gyro_bias_cv7_ins_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

void mipc_threedm_gyro_bias_cv7_ins_to_json(mipc_jw_t *w, const mipc_threedm_gyro_bias_cv7_ins_t *in) {
    int first = 1;
    size_t i;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "function");
    mipc_jw_u8(w, &in->function);
    if (in->has_bias) {
        mipc_jw_key(w, &first, "bias");
        mipc_jw_raw(w, "[", 1);
        for (i = 0; i < 3; i++) {
            mipc_jw_sep(w, i);
            mipc_jw_f32(w, &in->bias[i]);
        }
        mipc_jw_raw(w, "]", 1);
    }
    mipc_jw_raw(w, "}", 1);
}

int mipc_threedm_gyro_bias_cv7_ins_from_json(mipc_jr_t *jr, size_t pos,
                                             mipc_threedm_gyro_bias_cv7_ins_t *out) {
    static const char *const keys[] = {"function", "bias"};
    size_t vp = 0;
    int found;
    int absent = 0;
    size_t i;
    size_t it = 0;
    size_t ep = 0;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 2)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "function", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"function\"");
    }
    {
        mipc_jr_push(jr, "function");
        if (mipc_jr_u8(jr, vp, &out->function)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "bias", &vp);
    out->has_bias = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mipc_jr_fail(jr, "optional parameter \"bias\" given after an absent one");
    } else {
        mipc_jr_push(jr, "bias");
        if (mipc_jr_array(jr, vp, &it)) {
            return -1;
        }
        for (i = 0;; i++) {
            int more = mipc_jr_next(jr, &it, &ep);
            if (more < 0) {
                return -1;
            }
            if (!more) {
                break;
            }
            if (i >= 3) {
                return mipc_jr_fail(jr, "more than 3 elements");
            }
            mipc_jr_index(jr, i);
            if (mipc_jr_f32(jr, ep, &out->bias[i])) {
                return -1;
            }
        }
        mipc_jr_index(jr, SIZE_MAX);
        if (i != 3) {
            return mipc_jr_fail(jr, "expected 3 elements, got %zu", i);
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mipc_threedm_gyro_bias_response_t */

static int mipc_threedm_gyro_bias_response_read(mipc_reader_t *r, mipc_threedm_gyro_bias_response_t *out) {
    size_t i;
    mipc_rd_push(r, "bias");
    for (i = 0; i < 3; i++) {
        mipc_rd_index(r, i);
        if (mipc_rd_f32(r, &out->bias[i])) {
            return -1;
        }
    }
    mipc_rd_pop(r);
    return mipc_rd_finish(r);
}

static mipc_status_t mipc_threedm_gyro_bias_response_write(mipc_writer_t *w,
                                                           const mipc_threedm_gyro_bias_response_t *in) {
    mipc_status_t st;
    size_t i;
    for (i = 0; i < 3; i++) {
        if ((st = mipc_wr_f32(w, &in->bias[i])) != MIPC_OK) {
            return st;
        }
    }
    return MIPC_OK;
}

mipc_status_t mipc_threedm_gyro_bias_response_encode(const mipc_threedm_gyro_bias_response_t *value,
                                                     uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    mipc_writer_init(&w, buf, cap);
    st = mipc_threedm_gyro_bias_response_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 12 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mipc_threedm_gyro_bias_response_load(const uint8_t *d, mipc_threedm_gyro_bias_response_t *out) {
    out->bias[0] = mipc_ld_f32(d + 0);
    out->bias[1] = mipc_ld_f32(d + 4);
    out->bias[2] = mipc_ld_f32(d + 8);
    return 0;
}

/* The general reader: lengths other than 12, bad bool bytes, error details. */
static MIPC_NOINLINE mipc_status_t mipc_threedm_gyro_bias_response_decode_read(
    const uint8_t *data, size_t len, mipc_threedm_gyro_bias_response_t *out, mipc_decode_error_t *err) {
    mipc_reader_t r;
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_threedm_gyro_bias_response_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t mipc_threedm_gyro_bias_response_decode(const uint8_t *data, size_t len,
                                                     mipc_threedm_gyro_bias_response_t *out,
                                                     mipc_decode_error_t *err) {
    if (len == 12 && mipc_threedm_gyro_bias_response_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_threedm_gyro_bias_response_decode_read(data, len, out, err);
}

void mipc_threedm_gyro_bias_response_to_json(mipc_jw_t *w, const mipc_threedm_gyro_bias_response_t *in) {
    int first = 1;
    size_t i;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "bias");
    mipc_jw_raw(w, "[", 1);
    for (i = 0; i < 3; i++) {
        mipc_jw_sep(w, i);
        mipc_jw_f32(w, &in->bias[i]);
    }
    mipc_jw_raw(w, "]", 1);
    mipc_jw_raw(w, "}", 1);
}

int mipc_threedm_gyro_bias_response_from_json(mipc_jr_t *jr, size_t pos,
                                              mipc_threedm_gyro_bias_response_t *out) {
    static const char *const keys[] = {"bias"};
    size_t vp = 0;
    int found;
    size_t i;
    size_t it = 0;
    size_t ep = 0;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 1)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "bias", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"bias\"");
    }
    {
        mipc_jr_push(jr, "bias");
        if (mipc_jr_array(jr, vp, &it)) {
            return -1;
        }
        for (i = 0;; i++) {
            int more = mipc_jr_next(jr, &it, &ep);
            if (more < 0) {
                return -1;
            }
            if (!more) {
                break;
            }
            if (i >= 3) {
                return mipc_jr_fail(jr, "more than 3 elements");
            }
            mipc_jr_index(jr, i);
            if (mipc_jr_f32(jr, ep, &out->bias[i])) {
                return -1;
            }
        }
        mipc_jr_index(jr, SIZE_MAX);
        if (i != 3) {
            return mipc_jr_fail(jr, "expected 3 elements, got %zu", i);
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mipc_threedm_capture_gyro_bias_t */

static int mipc_threedm_capture_gyro_bias_read(mipc_reader_t *r, mipc_threedm_capture_gyro_bias_t *out) {
    mipc_rd_push(r, "averaging_time_ms");
    if (mipc_rd_u16(r, &out->averaging_time_ms)) {
        return -1;
    }
    mipc_rd_pop(r);
    return mipc_rd_finish(r);
}

static mipc_status_t mipc_threedm_capture_gyro_bias_write(mipc_writer_t *w,
                                                          const mipc_threedm_capture_gyro_bias_t *in) {
    mipc_status_t st;
    if ((st = mipc_wr_u16(w, &in->averaging_time_ms)) != MIPC_OK) {
        return st;
    }
    return MIPC_OK;
}

mipc_status_t mipc_threedm_capture_gyro_bias_encode(const mipc_threedm_capture_gyro_bias_t *value,
                                                    uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    mipc_writer_init(&w, buf, cap);
    st = mipc_threedm_capture_gyro_bias_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 2 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mipc_threedm_capture_gyro_bias_load(const uint8_t *d, mipc_threedm_capture_gyro_bias_t *out) {
    out->averaging_time_ms = mipc_ld_u16(d + 0);
    return 0;
}

/* The general reader: lengths other than 2, bad bool bytes, error details. */
static MIPC_NOINLINE mipc_status_t mipc_threedm_capture_gyro_bias_decode_read(
    const uint8_t *data, size_t len, mipc_threedm_capture_gyro_bias_t *out, mipc_decode_error_t *err) {
    mipc_reader_t r;
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_threedm_capture_gyro_bias_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t mipc_threedm_capture_gyro_bias_decode(const uint8_t *data, size_t len,
                                                    mipc_threedm_capture_gyro_bias_t *out,
                                                    mipc_decode_error_t *err) {
    if (len == 2 && mipc_threedm_capture_gyro_bias_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_threedm_capture_gyro_bias_decode_read(data, len, out, err);
}

void mipc_threedm_capture_gyro_bias_to_json(mipc_jw_t *w, const mipc_threedm_capture_gyro_bias_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "averaging_time_ms");
    mipc_jw_u16(w, &in->averaging_time_ms);
    mipc_jw_raw(w, "}", 1);
}

int mipc_threedm_capture_gyro_bias_from_json(mipc_jr_t *jr, size_t pos,
                                             mipc_threedm_capture_gyro_bias_t *out) {
    static const char *const keys[] = {"averaging_time_ms"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 1)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "averaging_time_ms", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"averaging_time_ms\"");
    }
    {
        mipc_jr_push(jr, "averaging_time_ms");
        if (mipc_jr_u16(jr, vp, &out->averaging_time_ms)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mipc_threedm_mag_hard_iron_offset_gx5_45_t */

static int mipc_threedm_mag_hard_iron_offset_gx5_45_read(mipc_reader_t *r,
                                                         mipc_threedm_mag_hard_iron_offset_gx5_45_t *out) {
    size_t i;
    mipc_rd_push(r, "function");
    if (mipc_rd_u8(r, &out->function)) {
        return -1;
    }
    mipc_rd_pop(r);
    if (r->pos < r->len) {
        out->has_offset = true;
        mipc_rd_push(r, "offset");
        for (i = 0; i < 3; i++) {
            mipc_rd_index(r, i);
            if (mipc_rd_f32(r, &out->offset[i])) {
                return -1;
            }
        }
        mipc_rd_pop(r);
    }
    return mipc_rd_finish(r);
}

static mipc_status_t
mipc_threedm_mag_hard_iron_offset_gx5_45_write(mipc_writer_t *w,
                                               const mipc_threedm_mag_hard_iron_offset_gx5_45_t *in) {
    mipc_status_t st;
    size_t i;
    int absent = 0;
    if ((st = mipc_wr_u8(w, &in->function)) != MIPC_OK) {
        return st;
    }
    if (!in->has_offset) {
        absent = 1;
    } else if (absent) {
        return MIPC_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        for (i = 0; i < 3; i++) {
            if ((st = mipc_wr_f32(w, &in->offset[i])) != MIPC_OK) {
                return st;
            }
        }
    }
    return MIPC_OK;
}

mipc_status_t
mipc_threedm_mag_hard_iron_offset_gx5_45_encode(const mipc_threedm_mag_hard_iron_offset_gx5_45_t *value,
                                                uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    mipc_writer_init(&w, buf, cap);
    st = mipc_threedm_mag_hard_iron_offset_gx5_45_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mipc_status_t mipc_threedm_mag_hard_iron_offset_gx5_45_decode(const uint8_t *data, size_t len,
                                                              mipc_threedm_mag_hard_iron_offset_gx5_45_t *out,
                                                              mipc_decode_error_t *err) {
    mipc_reader_t r;
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_threedm_mag_hard_iron_offset_gx5_45_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

void mipc_threedm_mag_hard_iron_offset_gx5_45_to_json(mipc_jw_t *w,
                                                      const mipc_threedm_mag_hard_iron_offset_gx5_45_t *in) {
    int first = 1;
    size_t i;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "function");
    mipc_jw_u8(w, &in->function);
    if (in->has_offset) {
        mipc_jw_key(w, &first, "offset");
        mipc_jw_raw(w, "[", 1);
        for (i = 0; i < 3; i++) {
            mipc_jw_sep(w, i);
            mipc_jw_f32(w, &in->offset[i]);
        }
        mipc_jw_raw(w, "]", 1);
    }
    mipc_jw_raw(w, "}", 1);
}

int mipc_threedm_mag_hard_iron_offset_gx5_45_from_json(mipc_jr_t *jr, size_t pos,
                                                       mipc_threedm_mag_hard_iron_offset_gx5_45_t *out) {
    static const char *const keys[] = {"function", "offset"};
    size_t vp = 0;
    int found;
    int absent = 0;
    size_t i;
    size_t it = 0;
    size_t ep = 0;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 2)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "function", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"function\"");
    }
    {
        mipc_jr_push(jr, "function");
        if (mipc_jr_u8(jr, vp, &out->function)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "offset", &vp);
    out->has_offset = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mipc_jr_fail(jr, "optional parameter \"offset\" given after an absent one");
    } else {
        mipc_jr_push(jr, "offset");
        if (mipc_jr_array(jr, vp, &it)) {
            return -1;
        }
        for (i = 0;; i++) {
            int more = mipc_jr_next(jr, &it, &ep);
            if (more < 0) {
                return -1;
            }
            if (!more) {
                break;
            }
            if (i >= 3) {
                return mipc_jr_fail(jr, "more than 3 elements");
            }
            mipc_jr_index(jr, i);
            if (mipc_jr_f32(jr, ep, &out->offset[i])) {
                return -1;
            }
        }
        mipc_jr_index(jr, SIZE_MAX);
        if (i != 3) {
            return mipc_jr_fail(jr, "expected 3 elements, got %zu", i);
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mipc_threedm_mag_hard_iron_offset_cv7_ins_t */

static int mipc_threedm_mag_hard_iron_offset_cv7_ins_read(mipc_reader_t *r,
                                                          mipc_threedm_mag_hard_iron_offset_cv7_ins_t *out) {
    size_t i;
    mipc_rd_push(r, "function");
    if (mipc_rd_u8(r, &out->function)) {
        return -1;
    }
    mipc_rd_pop(r);
    if (r->pos < r->len) {
        out->has_offset = true;
        mipc_rd_push(r, "offset");
        for (i = 0; i < 3; i++) {
            mipc_rd_index(r, i);
            if (mipc_rd_f32(r, &out->offset[i])) {
                return -1;
            }
        }
        mipc_rd_pop(r);
    }
    return mipc_rd_finish(r);
}

static mipc_status_t
mipc_threedm_mag_hard_iron_offset_cv7_ins_write(mipc_writer_t *w,
                                                const mipc_threedm_mag_hard_iron_offset_cv7_ins_t *in) {
    mipc_status_t st;
    size_t i;
    int absent = 0;
    if ((st = mipc_wr_u8(w, &in->function)) != MIPC_OK) {
        return st;
    }
    if (!in->has_offset) {
        absent = 1;
    } else if (absent) {
        return MIPC_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        for (i = 0; i < 3; i++) {
            if ((st = mipc_wr_f32(w, &in->offset[i])) != MIPC_OK) {
                return st;
            }
        }
    }
    return MIPC_OK;
}

mipc_status_t
mipc_threedm_mag_hard_iron_offset_cv7_ins_encode(const mipc_threedm_mag_hard_iron_offset_cv7_ins_t *value,
                                                 uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    mipc_writer_init(&w, buf, cap);
    st = mipc_threedm_mag_hard_iron_offset_cv7_ins_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mipc_status_t
mipc_threedm_mag_hard_iron_offset_cv7_ins_decode(const uint8_t *data, size_t len,
                                                 mipc_threedm_mag_hard_iron_offset_cv7_ins_t *out,
                                                 mipc_decode_error_t *err) {
    mipc_reader_t r;
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_threedm_mag_hard_iron_offset_cv7_ins_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

void mipc_threedm_mag_hard_iron_offset_cv7_ins_to_json(
    mipc_jw_t *w, const mipc_threedm_mag_hard_iron_offset_cv7_ins_t *in) {
    int first = 1;
    size_t i;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "function");
    mipc_jw_u8(w, &in->function);
    if (in->has_offset) {
        mipc_jw_key(w, &first, "offset");
        mipc_jw_raw(w, "[", 1);
        for (i = 0; i < 3; i++) {
            mipc_jw_sep(w, i);
            mipc_jw_f32(w, &in->offset[i]);
        }
        mipc_jw_raw(w, "]", 1);
    }
    mipc_jw_raw(w, "}", 1);
}

int mipc_threedm_mag_hard_iron_offset_cv7_ins_from_json(mipc_jr_t *jr, size_t pos,
                                                        mipc_threedm_mag_hard_iron_offset_cv7_ins_t *out) {
    static const char *const keys[] = {"function", "offset"};
    size_t vp = 0;
    int found;
    int absent = 0;
    size_t i;
    size_t it = 0;
    size_t ep = 0;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 2)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "function", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"function\"");
    }
    {
        mipc_jr_push(jr, "function");
        if (mipc_jr_u8(jr, vp, &out->function)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "offset", &vp);
    out->has_offset = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mipc_jr_fail(jr, "optional parameter \"offset\" given after an absent one");
    } else {
        mipc_jr_push(jr, "offset");
        if (mipc_jr_array(jr, vp, &it)) {
            return -1;
        }
        for (i = 0;; i++) {
            int more = mipc_jr_next(jr, &it, &ep);
            if (more < 0) {
                return -1;
            }
            if (!more) {
                break;
            }
            if (i >= 3) {
                return mipc_jr_fail(jr, "more than 3 elements");
            }
            mipc_jr_index(jr, i);
            if (mipc_jr_f32(jr, ep, &out->offset[i])) {
                return -1;
            }
        }
        mipc_jr_index(jr, SIZE_MAX);
        if (i != 3) {
            return mipc_jr_fail(jr, "expected 3 elements, got %zu", i);
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mipc_threedm_mag_hard_iron_offset_response_t */

static int
mipc_threedm_mag_hard_iron_offset_response_read(mipc_reader_t *r,
                                                mipc_threedm_mag_hard_iron_offset_response_t *out) {
    size_t i;
    mipc_rd_push(r, "offset");
    for (i = 0; i < 3; i++) {
        mipc_rd_index(r, i);
        if (mipc_rd_f32(r, &out->offset[i])) {
            return -1;
        }
    }
    mipc_rd_pop(r);
    return mipc_rd_finish(r);
}

static mipc_status_t
mipc_threedm_mag_hard_iron_offset_response_write(mipc_writer_t *w,
                                                 const mipc_threedm_mag_hard_iron_offset_response_t *in) {
    mipc_status_t st;
    size_t i;
    for (i = 0; i < 3; i++) {
        if ((st = mipc_wr_f32(w, &in->offset[i])) != MIPC_OK) {
            return st;
        }
    }
    return MIPC_OK;
}

mipc_status_t
mipc_threedm_mag_hard_iron_offset_response_encode(const mipc_threedm_mag_hard_iron_offset_response_t *value,
                                                  uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    mipc_writer_init(&w, buf, cap);
    st = mipc_threedm_mag_hard_iron_offset_response_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 12 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int
mipc_threedm_mag_hard_iron_offset_response_load(const uint8_t *d,
                                                mipc_threedm_mag_hard_iron_offset_response_t *out) {
    out->offset[0] = mipc_ld_f32(d + 0);
    out->offset[1] = mipc_ld_f32(d + 4);
    out->offset[2] = mipc_ld_f32(d + 8);
    return 0;
}

/* The general reader: lengths other than 12, bad bool bytes, error details. */
static MIPC_NOINLINE mipc_status_t mipc_threedm_mag_hard_iron_offset_response_decode_read(
    const uint8_t *data, size_t len, mipc_threedm_mag_hard_iron_offset_response_t *out,
    mipc_decode_error_t *err) {
    mipc_reader_t r;
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_threedm_mag_hard_iron_offset_response_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t
mipc_threedm_mag_hard_iron_offset_response_decode(const uint8_t *data, size_t len,
                                                  mipc_threedm_mag_hard_iron_offset_response_t *out,
                                                  mipc_decode_error_t *err) {
    if (len == 12 && mipc_threedm_mag_hard_iron_offset_response_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_threedm_mag_hard_iron_offset_response_decode_read(data, len, out, err);
}

void mipc_threedm_mag_hard_iron_offset_response_to_json(
    mipc_jw_t *w, const mipc_threedm_mag_hard_iron_offset_response_t *in) {
    int first = 1;
    size_t i;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "offset");
    mipc_jw_raw(w, "[", 1);
    for (i = 0; i < 3; i++) {
        mipc_jw_sep(w, i);
        mipc_jw_f32(w, &in->offset[i]);
    }
    mipc_jw_raw(w, "]", 1);
    mipc_jw_raw(w, "}", 1);
}

int mipc_threedm_mag_hard_iron_offset_response_from_json(mipc_jr_t *jr, size_t pos,
                                                         mipc_threedm_mag_hard_iron_offset_response_t *out) {
    static const char *const keys[] = {"offset"};
    size_t vp = 0;
    int found;
    size_t i;
    size_t it = 0;
    size_t ep = 0;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 1)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "offset", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"offset\"");
    }
    {
        mipc_jr_push(jr, "offset");
        if (mipc_jr_array(jr, vp, &it)) {
            return -1;
        }
        for (i = 0;; i++) {
            int more = mipc_jr_next(jr, &it, &ep);
            if (more < 0) {
                return -1;
            }
            if (!more) {
                break;
            }
            if (i >= 3) {
                return mipc_jr_fail(jr, "more than 3 elements");
            }
            mipc_jr_index(jr, i);
            if (mipc_jr_f32(jr, ep, &out->offset[i])) {
                return -1;
            }
        }
        mipc_jr_index(jr, SIZE_MAX);
        if (i != 3) {
            return mipc_jr_fail(jr, "expected 3 elements, got %zu", i);
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mipc_threedm_mag_soft_iron_matrix_gx5_45_t */

static int mipc_threedm_mag_soft_iron_matrix_gx5_45_read(mipc_reader_t *r,
                                                         mipc_threedm_mag_soft_iron_matrix_gx5_45_t *out) {
    size_t i;
    mipc_rd_push(r, "function");
    if (mipc_rd_u8(r, &out->function)) {
        return -1;
    }
    mipc_rd_pop(r);
    if (r->pos < r->len) {
        out->has_matrix = true;
        mipc_rd_push(r, "matrix");
        for (i = 0; i < 9; i++) {
            mipc_rd_index(r, i);
            if (mipc_rd_f32(r, &out->matrix[i])) {
                return -1;
            }
        }
        mipc_rd_pop(r);
    }
    return mipc_rd_finish(r);
}

static mipc_status_t
mipc_threedm_mag_soft_iron_matrix_gx5_45_write(mipc_writer_t *w,
                                               const mipc_threedm_mag_soft_iron_matrix_gx5_45_t *in) {
    mipc_status_t st;
    size_t i;
    int absent = 0;
    if ((st = mipc_wr_u8(w, &in->function)) != MIPC_OK) {
        return st;
    }
    if (!in->has_matrix) {
        absent = 1;
    } else if (absent) {
        return MIPC_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        for (i = 0; i < 9; i++) {
            if ((st = mipc_wr_f32(w, &in->matrix[i])) != MIPC_OK) {
                return st;
            }
        }
    }
    return MIPC_OK;
}

mipc_status_t
mipc_threedm_mag_soft_iron_matrix_gx5_45_encode(const mipc_threedm_mag_soft_iron_matrix_gx5_45_t *value,
                                                uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    mipc_writer_init(&w, buf, cap);
    st = mipc_threedm_mag_soft_iron_matrix_gx5_45_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mipc_status_t mipc_threedm_mag_soft_iron_matrix_gx5_45_decode(const uint8_t *data, size_t len,
                                                              mipc_threedm_mag_soft_iron_matrix_gx5_45_t *out,
                                                              mipc_decode_error_t *err) {
    mipc_reader_t r;
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_threedm_mag_soft_iron_matrix_gx5_45_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

void mipc_threedm_mag_soft_iron_matrix_gx5_45_to_json(mipc_jw_t *w,
                                                      const mipc_threedm_mag_soft_iron_matrix_gx5_45_t *in) {
    int first = 1;
    size_t i;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "function");
    mipc_jw_u8(w, &in->function);
    if (in->has_matrix) {
        mipc_jw_key(w, &first, "matrix");
        mipc_jw_raw(w, "[", 1);
        for (i = 0; i < 9; i++) {
            mipc_jw_sep(w, i);
            mipc_jw_f32(w, &in->matrix[i]);
        }
        mipc_jw_raw(w, "]", 1);
    }
    mipc_jw_raw(w, "}", 1);
}

int mipc_threedm_mag_soft_iron_matrix_gx5_45_from_json(mipc_jr_t *jr, size_t pos,
                                                       mipc_threedm_mag_soft_iron_matrix_gx5_45_t *out) {
    static const char *const keys[] = {"function", "matrix"};
    size_t vp = 0;
    int found;
    int absent = 0;
    size_t i;
    size_t it = 0;
    size_t ep = 0;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 2)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "function", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"function\"");
    }
    {
        mipc_jr_push(jr, "function");
        if (mipc_jr_u8(jr, vp, &out->function)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "matrix", &vp);
    out->has_matrix = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mipc_jr_fail(jr, "optional parameter \"matrix\" given after an absent one");
    } else {
        mipc_jr_push(jr, "matrix");
        if (mipc_jr_array(jr, vp, &it)) {
            return -1;
        }
        for (i = 0;; i++) {
            int more = mipc_jr_next(jr, &it, &ep);
            if (more < 0) {
                return -1;
            }
            if (!more) {
                break;
            }
            if (i >= 9) {
                return mipc_jr_fail(jr, "more than 9 elements");
            }
            mipc_jr_index(jr, i);
            if (mipc_jr_f32(jr, ep, &out->matrix[i])) {
                return -1;
            }
        }
        mipc_jr_index(jr, SIZE_MAX);
        if (i != 9) {
            return mipc_jr_fail(jr, "expected 9 elements, got %zu", i);
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mipc_threedm_mag_soft_iron_matrix_cv7_ins_t */

static int mipc_threedm_mag_soft_iron_matrix_cv7_ins_read(mipc_reader_t *r,
                                                          mipc_threedm_mag_soft_iron_matrix_cv7_ins_t *out) {
    size_t i;
    mipc_rd_push(r, "function");
    if (mipc_rd_u8(r, &out->function)) {
        return -1;
    }
    mipc_rd_pop(r);
    if (r->pos < r->len) {
        out->has_matrix = true;
        mipc_rd_push(r, "matrix");
        for (i = 0; i < 9; i++) {
            mipc_rd_index(r, i);
            if (mipc_rd_f32(r, &out->matrix[i])) {
                return -1;
            }
        }
        mipc_rd_pop(r);
    }
    return mipc_rd_finish(r);
}

static mipc_status_t
mipc_threedm_mag_soft_iron_matrix_cv7_ins_write(mipc_writer_t *w,
                                                const mipc_threedm_mag_soft_iron_matrix_cv7_ins_t *in) {
    mipc_status_t st;
    size_t i;
    int absent = 0;
    if ((st = mipc_wr_u8(w, &in->function)) != MIPC_OK) {
        return st;
    }
    if (!in->has_matrix) {
        absent = 1;
    } else if (absent) {
        return MIPC_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        for (i = 0; i < 9; i++) {
            if ((st = mipc_wr_f32(w, &in->matrix[i])) != MIPC_OK) {
                return st;
            }
        }
    }
    return MIPC_OK;
}

mipc_status_t
mipc_threedm_mag_soft_iron_matrix_cv7_ins_encode(const mipc_threedm_mag_soft_iron_matrix_cv7_ins_t *value,
                                                 uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    mipc_writer_init(&w, buf, cap);
    st = mipc_threedm_mag_soft_iron_matrix_cv7_ins_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mipc_status_t
mipc_threedm_mag_soft_iron_matrix_cv7_ins_decode(const uint8_t *data, size_t len,
                                                 mipc_threedm_mag_soft_iron_matrix_cv7_ins_t *out,
                                                 mipc_decode_error_t *err) {
    mipc_reader_t r;
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_threedm_mag_soft_iron_matrix_cv7_ins_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

void mipc_threedm_mag_soft_iron_matrix_cv7_ins_to_json(
    mipc_jw_t *w, const mipc_threedm_mag_soft_iron_matrix_cv7_ins_t *in) {
    int first = 1;
    size_t i;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "function");
    mipc_jw_u8(w, &in->function);
    if (in->has_matrix) {
        mipc_jw_key(w, &first, "matrix");
        mipc_jw_raw(w, "[", 1);
        for (i = 0; i < 9; i++) {
            mipc_jw_sep(w, i);
            mipc_jw_f32(w, &in->matrix[i]);
        }
        mipc_jw_raw(w, "]", 1);
    }
    mipc_jw_raw(w, "}", 1);
}

int mipc_threedm_mag_soft_iron_matrix_cv7_ins_from_json(mipc_jr_t *jr, size_t pos,
                                                        mipc_threedm_mag_soft_iron_matrix_cv7_ins_t *out) {
    static const char *const keys[] = {"function", "matrix"};
    size_t vp = 0;
    int found;
    int absent = 0;
    size_t i;
    size_t it = 0;
    size_t ep = 0;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 2)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "function", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"function\"");
    }
    {
        mipc_jr_push(jr, "function");
        if (mipc_jr_u8(jr, vp, &out->function)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "matrix", &vp);
    out->has_matrix = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mipc_jr_fail(jr, "optional parameter \"matrix\" given after an absent one");
    } else {
        mipc_jr_push(jr, "matrix");
        if (mipc_jr_array(jr, vp, &it)) {
            return -1;
        }
        for (i = 0;; i++) {
            int more = mipc_jr_next(jr, &it, &ep);
            if (more < 0) {
                return -1;
            }
            if (!more) {
                break;
            }
            if (i >= 9) {
                return mipc_jr_fail(jr, "more than 9 elements");
            }
            mipc_jr_index(jr, i);
            if (mipc_jr_f32(jr, ep, &out->matrix[i])) {
                return -1;
            }
        }
        mipc_jr_index(jr, SIZE_MAX);
        if (i != 9) {
            return mipc_jr_fail(jr, "expected 9 elements, got %zu", i);
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mipc_threedm_mag_soft_iron_matrix_response_t */

static int
mipc_threedm_mag_soft_iron_matrix_response_read(mipc_reader_t *r,
                                                mipc_threedm_mag_soft_iron_matrix_response_t *out) {
    size_t i;
    mipc_rd_push(r, "matrix");
    for (i = 0; i < 9; i++) {
        mipc_rd_index(r, i);
        if (mipc_rd_f32(r, &out->matrix[i])) {
            return -1;
        }
    }
    mipc_rd_pop(r);
    return mipc_rd_finish(r);
}

static mipc_status_t
mipc_threedm_mag_soft_iron_matrix_response_write(mipc_writer_t *w,
                                                 const mipc_threedm_mag_soft_iron_matrix_response_t *in) {
    mipc_status_t st;
    size_t i;
    for (i = 0; i < 9; i++) {
        if ((st = mipc_wr_f32(w, &in->matrix[i])) != MIPC_OK) {
            return st;
        }
    }
    return MIPC_OK;
}

mipc_status_t
mipc_threedm_mag_soft_iron_matrix_response_encode(const mipc_threedm_mag_soft_iron_matrix_response_t *value,
                                                  uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    mipc_writer_init(&w, buf, cap);
    st = mipc_threedm_mag_soft_iron_matrix_response_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 36 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int
mipc_threedm_mag_soft_iron_matrix_response_load(const uint8_t *d,
                                                mipc_threedm_mag_soft_iron_matrix_response_t *out) {
    out->matrix[0] = mipc_ld_f32(d + 0);
    out->matrix[1] = mipc_ld_f32(d + 4);
    out->matrix[2] = mipc_ld_f32(d + 8);
    out->matrix[3] = mipc_ld_f32(d + 12);
    out->matrix[4] = mipc_ld_f32(d + 16);
    out->matrix[5] = mipc_ld_f32(d + 20);
    out->matrix[6] = mipc_ld_f32(d + 24);
    out->matrix[7] = mipc_ld_f32(d + 28);
    out->matrix[8] = mipc_ld_f32(d + 32);
    return 0;
}

/* The general reader: lengths other than 36, bad bool bytes, error details. */
static MIPC_NOINLINE mipc_status_t mipc_threedm_mag_soft_iron_matrix_response_decode_read(
    const uint8_t *data, size_t len, mipc_threedm_mag_soft_iron_matrix_response_t *out,
    mipc_decode_error_t *err) {
    mipc_reader_t r;
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_threedm_mag_soft_iron_matrix_response_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t
mipc_threedm_mag_soft_iron_matrix_response_decode(const uint8_t *data, size_t len,
                                                  mipc_threedm_mag_soft_iron_matrix_response_t *out,
                                                  mipc_decode_error_t *err) {
    if (len == 36 && mipc_threedm_mag_soft_iron_matrix_response_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_threedm_mag_soft_iron_matrix_response_decode_read(data, len, out, err);
}

void mipc_threedm_mag_soft_iron_matrix_response_to_json(
    mipc_jw_t *w, const mipc_threedm_mag_soft_iron_matrix_response_t *in) {
    int first = 1;
    size_t i;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "matrix");
    mipc_jw_raw(w, "[", 1);
    for (i = 0; i < 9; i++) {
        mipc_jw_sep(w, i);
        mipc_jw_f32(w, &in->matrix[i]);
    }
    mipc_jw_raw(w, "]", 1);
    mipc_jw_raw(w, "}", 1);
}

int mipc_threedm_mag_soft_iron_matrix_response_from_json(mipc_jr_t *jr, size_t pos,
                                                         mipc_threedm_mag_soft_iron_matrix_response_t *out) {
    static const char *const keys[] = {"matrix"};
    size_t vp = 0;
    int found;
    size_t i;
    size_t it = 0;
    size_t ep = 0;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 1)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "matrix", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"matrix\"");
    }
    {
        mipc_jr_push(jr, "matrix");
        if (mipc_jr_array(jr, vp, &it)) {
            return -1;
        }
        for (i = 0;; i++) {
            int more = mipc_jr_next(jr, &it, &ep);
            if (more < 0) {
                return -1;
            }
            if (!more) {
                break;
            }
            if (i >= 9) {
                return mipc_jr_fail(jr, "more than 9 elements");
            }
            mipc_jr_index(jr, i);
            if (mipc_jr_f32(jr, ep, &out->matrix[i])) {
                return -1;
            }
        }
        mipc_jr_index(jr, SIZE_MAX);
        if (i != 9) {
            return mipc_jr_fail(jr, "expected 9 elements, got %zu", i);
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mipc_threedm_coning_sculling_enable_t */

static int mipc_threedm_coning_sculling_enable_read(mipc_reader_t *r,
                                                    mipc_threedm_coning_sculling_enable_t *out) {
    mipc_rd_push(r, "function");
    if (mipc_rd_u8(r, &out->function)) {
        return -1;
    }
    mipc_rd_pop(r);
    if (r->pos < r->len) {
        out->has_enable = true;
        mipc_rd_push(r, "enable");
        if (mipc_rd_bool(r, &out->enable)) {
            return -1;
        }
        mipc_rd_pop(r);
    }
    return mipc_rd_finish(r);
}

static mipc_status_t
mipc_threedm_coning_sculling_enable_write(mipc_writer_t *w, const mipc_threedm_coning_sculling_enable_t *in) {
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
        if ((st = mipc_wr_bool(w, &in->enable)) != MIPC_OK) {
            return st;
        }
    }
    return MIPC_OK;
}

mipc_status_t mipc_threedm_coning_sculling_enable_encode(const mipc_threedm_coning_sculling_enable_t *value,
                                                         uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    mipc_writer_init(&w, buf, cap);
    st = mipc_threedm_coning_sculling_enable_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mipc_status_t mipc_threedm_coning_sculling_enable_decode(const uint8_t *data, size_t len,
                                                         mipc_threedm_coning_sculling_enable_t *out,
                                                         mipc_decode_error_t *err) {
    mipc_reader_t r;
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_threedm_coning_sculling_enable_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

void mipc_threedm_coning_sculling_enable_to_json(mipc_jw_t *w,
                                                 const mipc_threedm_coning_sculling_enable_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "function");
    mipc_jw_u8(w, &in->function);
    if (in->has_enable) {
        mipc_jw_key(w, &first, "enable");
        mipc_jw_bool(w, &in->enable);
    }
    mipc_jw_raw(w, "}", 1);
}

int mipc_threedm_coning_sculling_enable_from_json(mipc_jr_t *jr, size_t pos,
                                                  mipc_threedm_coning_sculling_enable_t *out) {
    static const char *const keys[] = {"function", "enable"};
    size_t vp = 0;
    int found;
    int absent = 0;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 2)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "function", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"function\"");
    }
    {
        mipc_jr_push(jr, "function");
        if (mipc_jr_u8(jr, vp, &out->function)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "enable", &vp);
    out->has_enable = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mipc_jr_fail(jr, "optional parameter \"enable\" given after an absent one");
    } else {
        mipc_jr_push(jr, "enable");
        if (mipc_jr_bool(jr, vp, &out->enable)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mipc_threedm_coning_sculling_enable_response_t */

static int
mipc_threedm_coning_sculling_enable_response_read(mipc_reader_t *r,
                                                  mipc_threedm_coning_sculling_enable_response_t *out) {
    mipc_rd_push(r, "enable");
    if (mipc_rd_bool(r, &out->enable)) {
        return -1;
    }
    mipc_rd_pop(r);
    return mipc_rd_finish(r);
}

static mipc_status_t
mipc_threedm_coning_sculling_enable_response_write(mipc_writer_t *w,
                                                   const mipc_threedm_coning_sculling_enable_response_t *in) {
    mipc_status_t st;
    if ((st = mipc_wr_bool(w, &in->enable)) != MIPC_OK) {
        return st;
    }
    return MIPC_OK;
}

mipc_status_t mipc_threedm_coning_sculling_enable_response_encode(
    const mipc_threedm_coning_sculling_enable_response_t *value, uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    mipc_writer_init(&w, buf, cap);
    st = mipc_threedm_coning_sculling_enable_response_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 1 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int
mipc_threedm_coning_sculling_enable_response_load(const uint8_t *d,
                                                  mipc_threedm_coning_sculling_enable_response_t *out) {
    if (d[0] > 1) {
        return -1;
    }
    out->enable = mipc_ld_bool(d + 0);
    return 0;
}

/* The general reader: lengths other than 1, bad bool bytes, error details. */
static MIPC_NOINLINE mipc_status_t mipc_threedm_coning_sculling_enable_response_decode_read(
    const uint8_t *data, size_t len, mipc_threedm_coning_sculling_enable_response_t *out,
    mipc_decode_error_t *err) {
    mipc_reader_t r;
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_threedm_coning_sculling_enable_response_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t
mipc_threedm_coning_sculling_enable_response_decode(const uint8_t *data, size_t len,
                                                    mipc_threedm_coning_sculling_enable_response_t *out,
                                                    mipc_decode_error_t *err) {
    if (len == 1 && mipc_threedm_coning_sculling_enable_response_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_threedm_coning_sculling_enable_response_decode_read(data, len, out, err);
}

void mipc_threedm_coning_sculling_enable_response_to_json(
    mipc_jw_t *w, const mipc_threedm_coning_sculling_enable_response_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "enable");
    mipc_jw_bool(w, &in->enable);
    mipc_jw_raw(w, "}", 1);
}

int mipc_threedm_coning_sculling_enable_response_from_json(
    mipc_jr_t *jr, size_t pos, mipc_threedm_coning_sculling_enable_response_t *out) {
    static const char *const keys[] = {"enable"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 1)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "enable", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"enable\"");
    }
    {
        mipc_jr_push(jr, "enable");
        if (mipc_jr_bool(jr, vp, &out->enable)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mipc_threedm_uart_baudrate_t */

static int mipc_threedm_uart_baudrate_read(mipc_reader_t *r, mipc_threedm_uart_baudrate_t *out) {
    mipc_rd_push(r, "function");
    if (mipc_rd_u8(r, &out->function)) {
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

static mipc_status_t mipc_threedm_uart_baudrate_write(mipc_writer_t *w,
                                                      const mipc_threedm_uart_baudrate_t *in) {
    mipc_status_t st;
    int absent = 0;
    if ((st = mipc_wr_u8(w, &in->function)) != MIPC_OK) {
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

mipc_status_t mipc_threedm_uart_baudrate_encode(const mipc_threedm_uart_baudrate_t *value, uint8_t *buf,
                                                size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    mipc_writer_init(&w, buf, cap);
    st = mipc_threedm_uart_baudrate_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mipc_status_t mipc_threedm_uart_baudrate_decode(const uint8_t *data, size_t len,
                                                mipc_threedm_uart_baudrate_t *out, mipc_decode_error_t *err) {
    mipc_reader_t r;
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_threedm_uart_baudrate_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

void mipc_threedm_uart_baudrate_to_json(mipc_jw_t *w, const mipc_threedm_uart_baudrate_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "function");
    mipc_jw_u8(w, &in->function);
    if (in->has_baud) {
        mipc_jw_key(w, &first, "baud");
        mipc_jw_u32(w, &in->baud);
    }
    mipc_jw_raw(w, "}", 1);
}

int mipc_threedm_uart_baudrate_from_json(mipc_jr_t *jr, size_t pos, mipc_threedm_uart_baudrate_t *out) {
    static const char *const keys[] = {"function", "baud"};
    size_t vp = 0;
    int found;
    int absent = 0;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 2)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "function", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"function\"");
    }
    {
        mipc_jr_push(jr, "function");
        if (mipc_jr_u8(jr, vp, &out->function)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "baud", &vp);
    out->has_baud = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mipc_jr_fail(jr, "optional parameter \"baud\" given after an absent one");
    } else {
        mipc_jr_push(jr, "baud");
        if (mipc_jr_u32(jr, vp, &out->baud)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mipc_threedm_uart_baudrate_response_t */

static int mipc_threedm_uart_baudrate_response_read(mipc_reader_t *r,
                                                    mipc_threedm_uart_baudrate_response_t *out) {
    mipc_rd_push(r, "baud");
    if (mipc_rd_u32(r, &out->baud)) {
        return -1;
    }
    mipc_rd_pop(r);
    return mipc_rd_finish(r);
}

static mipc_status_t
mipc_threedm_uart_baudrate_response_write(mipc_writer_t *w, const mipc_threedm_uart_baudrate_response_t *in) {
    mipc_status_t st;
    if ((st = mipc_wr_u32(w, &in->baud)) != MIPC_OK) {
        return st;
    }
    return MIPC_OK;
}

mipc_status_t mipc_threedm_uart_baudrate_response_encode(const mipc_threedm_uart_baudrate_response_t *value,
                                                         uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    mipc_writer_init(&w, buf, cap);
    st = mipc_threedm_uart_baudrate_response_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 4 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mipc_threedm_uart_baudrate_response_load(const uint8_t *d,
                                                    mipc_threedm_uart_baudrate_response_t *out) {
    out->baud = mipc_ld_u32(d + 0);
    return 0;
}

/* The general reader: lengths other than 4, bad bool bytes, error details. */
static MIPC_NOINLINE mipc_status_t mipc_threedm_uart_baudrate_response_decode_read(
    const uint8_t *data, size_t len, mipc_threedm_uart_baudrate_response_t *out, mipc_decode_error_t *err) {
    mipc_reader_t r;
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_threedm_uart_baudrate_response_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t mipc_threedm_uart_baudrate_response_decode(const uint8_t *data, size_t len,
                                                         mipc_threedm_uart_baudrate_response_t *out,
                                                         mipc_decode_error_t *err) {
    if (len == 4 && mipc_threedm_uart_baudrate_response_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_threedm_uart_baudrate_response_decode_read(data, len, out, err);
}

void mipc_threedm_uart_baudrate_response_to_json(mipc_jw_t *w,
                                                 const mipc_threedm_uart_baudrate_response_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "baud");
    mipc_jw_u32(w, &in->baud);
    mipc_jw_raw(w, "}", 1);
}

int mipc_threedm_uart_baudrate_response_from_json(mipc_jr_t *jr, size_t pos,
                                                  mipc_threedm_uart_baudrate_response_t *out) {
    static const char *const keys[] = {"baud"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 1)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "baud", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"baud\"");
    }
    {
        mipc_jr_push(jr, "baud");
        if (mipc_jr_u32(jr, vp, &out->baud)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mipc_threedm_gpio_config_t */

static int mipc_threedm_gpio_config_read(mipc_reader_t *r, mipc_threedm_gpio_config_t *out) {
    mipc_rd_push(r, "function");
    if (mipc_rd_u8(r, &out->function)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "pin");
    if (mipc_rd_u8(r, &out->pin)) {
        return -1;
    }
    mipc_rd_pop(r);
    if (r->pos < r->len) {
        out->has_feature = true;
        mipc_rd_push(r, "feature");
        if (mipc_rd_u8(r, &out->feature)) {
            return -1;
        }
        mipc_rd_pop(r);
    }
    if (r->pos < r->len) {
        out->has_behavior = true;
        mipc_rd_push(r, "behavior");
        if (mipc_gpio_behavior_read(r, out->feature, &out->behavior)) {
            return -1;
        }
        mipc_rd_pop(r);
    }
    if (r->pos < r->len) {
        out->has_pin_mode = true;
        mipc_rd_push(r, "pin_mode");
        if (mipc_rd_u8(r, &out->pin_mode)) {
            return -1;
        }
        mipc_rd_pop(r);
    }
    return mipc_rd_finish(r);
}

static mipc_status_t mipc_threedm_gpio_config_write(mipc_writer_t *w, const mipc_threedm_gpio_config_t *in) {
    mipc_status_t st;
    int absent = 0;
    if ((st = mipc_wr_u8(w, &in->function)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u8(w, &in->pin)) != MIPC_OK) {
        return st;
    }
    if (!in->has_feature) {
        absent = 1;
    } else if (absent) {
        return MIPC_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = mipc_wr_u8(w, &in->feature)) != MIPC_OK) {
            return st;
        }
    }
    if (!in->has_behavior) {
        absent = 1;
    } else if (absent) {
        return MIPC_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = mipc_gpio_behavior_write(w, in->feature, &in->behavior)) != MIPC_OK) {
            return st;
        }
    }
    if (!in->has_pin_mode) {
        absent = 1;
    } else if (absent) {
        return MIPC_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = mipc_wr_u8(w, &in->pin_mode)) != MIPC_OK) {
            return st;
        }
    }
    return MIPC_OK;
}

mipc_status_t mipc_threedm_gpio_config_encode(const mipc_threedm_gpio_config_t *value, uint8_t *buf,
                                              size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    mipc_writer_init(&w, buf, cap);
    st = mipc_threedm_gpio_config_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mipc_status_t mipc_threedm_gpio_config_decode(const uint8_t *data, size_t len,
                                              mipc_threedm_gpio_config_t *out, mipc_decode_error_t *err) {
    mipc_reader_t r;
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_threedm_gpio_config_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

void mipc_threedm_gpio_config_to_json(mipc_jw_t *w, const mipc_threedm_gpio_config_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "function");
    mipc_jw_u8(w, &in->function);
    mipc_jw_key(w, &first, "pin");
    mipc_jw_u8(w, &in->pin);
    if (in->has_feature) {
        mipc_jw_key(w, &first, "feature");
        mipc_jw_u8(w, &in->feature);
    }
    if (in->has_behavior) {
        mipc_jw_key(w, &first, "behavior");
        mipc_gpio_behavior_to_json(w, in->feature, &in->behavior);
    }
    if (in->has_pin_mode) {
        mipc_jw_key(w, &first, "pin_mode");
        mipc_jw_u8(w, &in->pin_mode);
    }
    mipc_jw_raw(w, "}", 1);
}

int mipc_threedm_gpio_config_from_json(mipc_jr_t *jr, size_t pos, mipc_threedm_gpio_config_t *out) {
    static const char *const keys[] = {"function", "pin", "feature", "behavior", "pin_mode"};
    size_t vp = 0;
    int found;
    int absent = 0;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 5)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "function", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"function\"");
    }
    {
        mipc_jr_push(jr, "function");
        if (mipc_jr_u8(jr, vp, &out->function)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "pin", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"pin\"");
    }
    {
        mipc_jr_push(jr, "pin");
        if (mipc_jr_u8(jr, vp, &out->pin)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "feature", &vp);
    out->has_feature = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mipc_jr_fail(jr, "optional parameter \"feature\" given after an absent one");
    } else {
        mipc_jr_push(jr, "feature");
        if (mipc_jr_u8(jr, vp, &out->feature)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "behavior", &vp);
    out->has_behavior = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mipc_jr_fail(jr, "optional parameter \"behavior\" given after an absent one");
    } else {
        mipc_jr_push(jr, "behavior");
        if (mipc_gpio_behavior_from_json(jr, vp, out->feature, &out->behavior)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "pin_mode", &vp);
    out->has_pin_mode = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mipc_jr_fail(jr, "optional parameter \"pin_mode\" given after an absent one");
    } else {
        mipc_jr_push(jr, "pin_mode");
        if (mipc_jr_u8(jr, vp, &out->pin_mode)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mipc_threedm_gpio_config_response_t */

static int mipc_threedm_gpio_config_response_read(mipc_reader_t *r,
                                                  mipc_threedm_gpio_config_response_t *out) {
    mipc_rd_push(r, "pin");
    if (mipc_rd_u8(r, &out->pin)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "feature");
    if (mipc_rd_u8(r, &out->feature)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "behavior");
    if (mipc_gpio_behavior_read(r, out->feature, &out->behavior)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "pin_mode");
    if (mipc_rd_u8(r, &out->pin_mode)) {
        return -1;
    }
    mipc_rd_pop(r);
    return mipc_rd_finish(r);
}

static mipc_status_t mipc_threedm_gpio_config_response_write(mipc_writer_t *w,
                                                             const mipc_threedm_gpio_config_response_t *in) {
    mipc_status_t st;
    if ((st = mipc_wr_u8(w, &in->pin)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u8(w, &in->feature)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_gpio_behavior_write(w, in->feature, &in->behavior)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u8(w, &in->pin_mode)) != MIPC_OK) {
        return st;
    }
    return MIPC_OK;
}

mipc_status_t mipc_threedm_gpio_config_response_encode(const mipc_threedm_gpio_config_response_t *value,
                                                       uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    mipc_writer_init(&w, buf, cap);
    st = mipc_threedm_gpio_config_response_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mipc_status_t mipc_threedm_gpio_config_response_decode(const uint8_t *data, size_t len,
                                                       mipc_threedm_gpio_config_response_t *out,
                                                       mipc_decode_error_t *err) {
    mipc_reader_t r;
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_threedm_gpio_config_response_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

void mipc_threedm_gpio_config_response_to_json(mipc_jw_t *w, const mipc_threedm_gpio_config_response_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "pin");
    mipc_jw_u8(w, &in->pin);
    mipc_jw_key(w, &first, "feature");
    mipc_jw_u8(w, &in->feature);
    mipc_jw_key(w, &first, "behavior");
    mipc_gpio_behavior_to_json(w, in->feature, &in->behavior);
    mipc_jw_key(w, &first, "pin_mode");
    mipc_jw_u8(w, &in->pin_mode);
    mipc_jw_raw(w, "}", 1);
}

int mipc_threedm_gpio_config_response_from_json(mipc_jr_t *jr, size_t pos,
                                                mipc_threedm_gpio_config_response_t *out) {
    static const char *const keys[] = {"pin", "feature", "behavior", "pin_mode"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 4)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "pin", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"pin\"");
    }
    {
        mipc_jr_push(jr, "pin");
        if (mipc_jr_u8(jr, vp, &out->pin)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "feature", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"feature\"");
    }
    {
        mipc_jr_push(jr, "feature");
        if (mipc_jr_u8(jr, vp, &out->feature)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "behavior", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"behavior\"");
    }
    {
        mipc_jr_push(jr, "behavior");
        if (mipc_gpio_behavior_from_json(jr, vp, out->feature, &out->behavior)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "pin_mode", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"pin_mode\"");
    }
    {
        mipc_jr_push(jr, "pin_mode");
        if (mipc_jr_u8(jr, vp, &out->pin_mode)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mipc_threedm_gpio_state_t */

static int mipc_threedm_gpio_state_read(mipc_reader_t *r, mipc_threedm_gpio_state_t *out) {
    mipc_rd_push(r, "function");
    if (mipc_rd_u8(r, &out->function)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "pin");
    if (mipc_rd_u8(r, &out->pin)) {
        return -1;
    }
    mipc_rd_pop(r);
    if (r->pos < r->len) {
        out->has_state = true;
        mipc_rd_push(r, "state");
        if (mipc_rd_bool(r, &out->state)) {
            return -1;
        }
        mipc_rd_pop(r);
    }
    return mipc_rd_finish(r);
}

static mipc_status_t mipc_threedm_gpio_state_write(mipc_writer_t *w, const mipc_threedm_gpio_state_t *in) {
    mipc_status_t st;
    int absent = 0;
    if ((st = mipc_wr_u8(w, &in->function)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u8(w, &in->pin)) != MIPC_OK) {
        return st;
    }
    if (!in->has_state) {
        absent = 1;
    } else if (absent) {
        return MIPC_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = mipc_wr_bool(w, &in->state)) != MIPC_OK) {
            return st;
        }
    }
    return MIPC_OK;
}

mipc_status_t mipc_threedm_gpio_state_encode(const mipc_threedm_gpio_state_t *value, uint8_t *buf, size_t cap,
                                             size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    mipc_writer_init(&w, buf, cap);
    st = mipc_threedm_gpio_state_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mipc_status_t mipc_threedm_gpio_state_decode(const uint8_t *data, size_t len, mipc_threedm_gpio_state_t *out,
                                             mipc_decode_error_t *err) {
    mipc_reader_t r;
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_threedm_gpio_state_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

void mipc_threedm_gpio_state_to_json(mipc_jw_t *w, const mipc_threedm_gpio_state_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "function");
    mipc_jw_u8(w, &in->function);
    mipc_jw_key(w, &first, "pin");
    mipc_jw_u8(w, &in->pin);
    if (in->has_state) {
        mipc_jw_key(w, &first, "state");
        mipc_jw_bool(w, &in->state);
    }
    mipc_jw_raw(w, "}", 1);
}

int mipc_threedm_gpio_state_from_json(mipc_jr_t *jr, size_t pos, mipc_threedm_gpio_state_t *out) {
    static const char *const keys[] = {"function", "pin", "state"};
    size_t vp = 0;
    int found;
    int absent = 0;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 3)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "function", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"function\"");
    }
    {
        mipc_jr_push(jr, "function");
        if (mipc_jr_u8(jr, vp, &out->function)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "pin", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"pin\"");
    }
    {
        mipc_jr_push(jr, "pin");
        if (mipc_jr_u8(jr, vp, &out->pin)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "state", &vp);
    out->has_state = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mipc_jr_fail(jr, "optional parameter \"state\" given after an absent one");
    } else {
        mipc_jr_push(jr, "state");
        if (mipc_jr_bool(jr, vp, &out->state)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mipc_threedm_gpio_state_response_t */

static int mipc_threedm_gpio_state_response_read(mipc_reader_t *r, mipc_threedm_gpio_state_response_t *out) {
    mipc_rd_push(r, "pin");
    if (mipc_rd_u8(r, &out->pin)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "state");
    if (mipc_rd_bool(r, &out->state)) {
        return -1;
    }
    mipc_rd_pop(r);
    return mipc_rd_finish(r);
}

static mipc_status_t mipc_threedm_gpio_state_response_write(mipc_writer_t *w,
                                                            const mipc_threedm_gpio_state_response_t *in) {
    mipc_status_t st;
    if ((st = mipc_wr_u8(w, &in->pin)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_bool(w, &in->state)) != MIPC_OK) {
        return st;
    }
    return MIPC_OK;
}

mipc_status_t mipc_threedm_gpio_state_response_encode(const mipc_threedm_gpio_state_response_t *value,
                                                      uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    mipc_writer_init(&w, buf, cap);
    st = mipc_threedm_gpio_state_response_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 2 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mipc_threedm_gpio_state_response_load(const uint8_t *d, mipc_threedm_gpio_state_response_t *out) {
    out->pin = mipc_ld_u8(d + 0);
    if (d[1] > 1) {
        return -1;
    }
    out->state = mipc_ld_bool(d + 1);
    return 0;
}

/* The general reader: lengths other than 2, bad bool bytes, error details. */
static MIPC_NOINLINE mipc_status_t mipc_threedm_gpio_state_response_decode_read(
    const uint8_t *data, size_t len, mipc_threedm_gpio_state_response_t *out, mipc_decode_error_t *err) {
    mipc_reader_t r;
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_threedm_gpio_state_response_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t mipc_threedm_gpio_state_response_decode(const uint8_t *data, size_t len,
                                                      mipc_threedm_gpio_state_response_t *out,
                                                      mipc_decode_error_t *err) {
    if (len == 2 && mipc_threedm_gpio_state_response_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_threedm_gpio_state_response_decode_read(data, len, out, err);
}

void mipc_threedm_gpio_state_response_to_json(mipc_jw_t *w, const mipc_threedm_gpio_state_response_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "pin");
    mipc_jw_u8(w, &in->pin);
    mipc_jw_key(w, &first, "state");
    mipc_jw_bool(w, &in->state);
    mipc_jw_raw(w, "}", 1);
}

int mipc_threedm_gpio_state_response_from_json(mipc_jr_t *jr, size_t pos,
                                               mipc_threedm_gpio_state_response_t *out) {
    static const char *const keys[] = {"pin", "state"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 2)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "pin", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"pin\"");
    }
    {
        mipc_jr_push(jr, "pin");
        if (mipc_jr_u8(jr, vp, &out->pin)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "state", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"state\"");
    }
    {
        mipc_jr_push(jr, "state");
        if (mipc_jr_bool(jr, vp, &out->state)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mipc_threedm_odometer_config_t */

static int mipc_threedm_odometer_config_read(mipc_reader_t *r, mipc_threedm_odometer_config_t *out) {
    mipc_rd_push(r, "function");
    if (mipc_rd_u8(r, &out->function)) {
        return -1;
    }
    mipc_rd_pop(r);
    if (r->pos < r->len) {
        out->has_mode = true;
        mipc_rd_push(r, "mode");
        if (mipc_rd_u8(r, &out->mode)) {
            return -1;
        }
        mipc_rd_pop(r);
    }
    if (r->pos < r->len) {
        out->has_scaling = true;
        mipc_rd_push(r, "scaling");
        if (mipc_rd_f32(r, &out->scaling)) {
            return -1;
        }
        mipc_rd_pop(r);
    }
    if (r->pos < r->len) {
        out->has_uncertainty = true;
        mipc_rd_push(r, "uncertainty");
        if (mipc_rd_f32(r, &out->uncertainty)) {
            return -1;
        }
        mipc_rd_pop(r);
    }
    return mipc_rd_finish(r);
}

static mipc_status_t mipc_threedm_odometer_config_write(mipc_writer_t *w,
                                                        const mipc_threedm_odometer_config_t *in) {
    mipc_status_t st;
    int absent = 0;
    if ((st = mipc_wr_u8(w, &in->function)) != MIPC_OK) {
        return st;
    }
    if (!in->has_mode) {
        absent = 1;
    } else if (absent) {
        return MIPC_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = mipc_wr_u8(w, &in->mode)) != MIPC_OK) {
            return st;
        }
    }
    if (!in->has_scaling) {
        absent = 1;
    } else if (absent) {
        return MIPC_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = mipc_wr_f32(w, &in->scaling)) != MIPC_OK) {
            return st;
        }
    }
    if (!in->has_uncertainty) {
        absent = 1;
    } else if (absent) {
        return MIPC_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = mipc_wr_f32(w, &in->uncertainty)) != MIPC_OK) {
            return st;
        }
    }
    return MIPC_OK;
}

mipc_status_t mipc_threedm_odometer_config_encode(const mipc_threedm_odometer_config_t *value, uint8_t *buf,
                                                  size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    mipc_writer_init(&w, buf, cap);
    st = mipc_threedm_odometer_config_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mipc_status_t mipc_threedm_odometer_config_decode(const uint8_t *data, size_t len,
                                                  mipc_threedm_odometer_config_t *out,
                                                  mipc_decode_error_t *err) {
    mipc_reader_t r;
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_threedm_odometer_config_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

void mipc_threedm_odometer_config_to_json(mipc_jw_t *w, const mipc_threedm_odometer_config_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "function");
    mipc_jw_u8(w, &in->function);
    if (in->has_mode) {
        mipc_jw_key(w, &first, "mode");
        mipc_jw_u8(w, &in->mode);
    }
    if (in->has_scaling) {
        mipc_jw_key(w, &first, "scaling");
        mipc_jw_f32(w, &in->scaling);
    }
    if (in->has_uncertainty) {
        mipc_jw_key(w, &first, "uncertainty");
        mipc_jw_f32(w, &in->uncertainty);
    }
    mipc_jw_raw(w, "}", 1);
}

int mipc_threedm_odometer_config_from_json(mipc_jr_t *jr, size_t pos, mipc_threedm_odometer_config_t *out) {
    static const char *const keys[] = {"function", "mode", "scaling", "uncertainty"};
    size_t vp = 0;
    int found;
    int absent = 0;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 4)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "function", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"function\"");
    }
    {
        mipc_jr_push(jr, "function");
        if (mipc_jr_u8(jr, vp, &out->function)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "mode", &vp);
    out->has_mode = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mipc_jr_fail(jr, "optional parameter \"mode\" given after an absent one");
    } else {
        mipc_jr_push(jr, "mode");
        if (mipc_jr_u8(jr, vp, &out->mode)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "scaling", &vp);
    out->has_scaling = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mipc_jr_fail(jr, "optional parameter \"scaling\" given after an absent one");
    } else {
        mipc_jr_push(jr, "scaling");
        if (mipc_jr_f32(jr, vp, &out->scaling)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "uncertainty", &vp);
    out->has_uncertainty = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mipc_jr_fail(jr, "optional parameter \"uncertainty\" given after an absent one");
    } else {
        mipc_jr_push(jr, "uncertainty");
        if (mipc_jr_f32(jr, vp, &out->uncertainty)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mipc_threedm_odometer_config_response_t */

static int mipc_threedm_odometer_config_response_read(mipc_reader_t *r,
                                                      mipc_threedm_odometer_config_response_t *out) {
    mipc_rd_push(r, "mode");
    if (mipc_rd_u8(r, &out->mode)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "scaling");
    if (mipc_rd_f32(r, &out->scaling)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "uncertainty");
    if (mipc_rd_f32(r, &out->uncertainty)) {
        return -1;
    }
    mipc_rd_pop(r);
    return mipc_rd_finish(r);
}

static mipc_status_t
mipc_threedm_odometer_config_response_write(mipc_writer_t *w,
                                            const mipc_threedm_odometer_config_response_t *in) {
    mipc_status_t st;
    if ((st = mipc_wr_u8(w, &in->mode)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_f32(w, &in->scaling)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_f32(w, &in->uncertainty)) != MIPC_OK) {
        return st;
    }
    return MIPC_OK;
}

mipc_status_t
mipc_threedm_odometer_config_response_encode(const mipc_threedm_odometer_config_response_t *value,
                                             uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    mipc_writer_init(&w, buf, cap);
    st = mipc_threedm_odometer_config_response_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 9 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mipc_threedm_odometer_config_response_load(const uint8_t *d,
                                                      mipc_threedm_odometer_config_response_t *out) {
    out->mode = mipc_ld_u8(d + 0);
    out->scaling = mipc_ld_f32(d + 1);
    out->uncertainty = mipc_ld_f32(d + 5);
    return 0;
}

/* The general reader: lengths other than 9, bad bool bytes, error details. */
static MIPC_NOINLINE mipc_status_t mipc_threedm_odometer_config_response_decode_read(
    const uint8_t *data, size_t len, mipc_threedm_odometer_config_response_t *out, mipc_decode_error_t *err) {
    mipc_reader_t r;
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_threedm_odometer_config_response_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t mipc_threedm_odometer_config_response_decode(const uint8_t *data, size_t len,
                                                           mipc_threedm_odometer_config_response_t *out,
                                                           mipc_decode_error_t *err) {
    if (len == 9 && mipc_threedm_odometer_config_response_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_threedm_odometer_config_response_decode_read(data, len, out, err);
}

void mipc_threedm_odometer_config_response_to_json(mipc_jw_t *w,
                                                   const mipc_threedm_odometer_config_response_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "mode");
    mipc_jw_u8(w, &in->mode);
    mipc_jw_key(w, &first, "scaling");
    mipc_jw_f32(w, &in->scaling);
    mipc_jw_key(w, &first, "uncertainty");
    mipc_jw_f32(w, &in->uncertainty);
    mipc_jw_raw(w, "}", 1);
}

int mipc_threedm_odometer_config_response_from_json(mipc_jr_t *jr, size_t pos,
                                                    mipc_threedm_odometer_config_response_t *out) {
    static const char *const keys[] = {"mode", "scaling", "uncertainty"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 3)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "mode", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"mode\"");
    }
    {
        mipc_jr_push(jr, "mode");
        if (mipc_jr_u8(jr, vp, &out->mode)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "scaling", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"scaling\"");
    }
    {
        mipc_jr_push(jr, "scaling");
        if (mipc_jr_f32(jr, vp, &out->scaling)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "uncertainty", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"uncertainty\"");
    }
    {
        mipc_jr_push(jr, "uncertainty");
        if (mipc_jr_f32(jr, vp, &out->uncertainty)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mipc_threedm_advanced_lowpass_filter_t */

static int mipc_threedm_advanced_lowpass_filter_read(mipc_reader_t *r,
                                                     mipc_threedm_advanced_lowpass_filter_t *out) {
    mipc_rd_push(r, "function");
    if (mipc_rd_u8(r, &out->function)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "target_descriptor");
    if (mipc_rd_u8(r, &out->target_descriptor)) {
        return -1;
    }
    mipc_rd_pop(r);
    if (r->pos < r->len) {
        out->has_enable = true;
        mipc_rd_push(r, "enable");
        if (mipc_rd_bool(r, &out->enable)) {
            return -1;
        }
        mipc_rd_pop(r);
    }
    if (r->pos < r->len) {
        out->has_manual = true;
        mipc_rd_push(r, "manual");
        if (mipc_rd_bool(r, &out->manual)) {
            return -1;
        }
        mipc_rd_pop(r);
    }
    if (r->pos < r->len) {
        out->has_frequency = true;
        mipc_rd_push(r, "frequency");
        if (mipc_rd_u16(r, &out->frequency)) {
            return -1;
        }
        mipc_rd_pop(r);
    }
    if (r->pos < r->len) {
        out->has_reserved = true;
        mipc_rd_push(r, "reserved");
        if (mipc_rd_u8(r, &out->reserved)) {
            return -1;
        }
        mipc_rd_pop(r);
    }
    return mipc_rd_finish(r);
}

static mipc_status_t
mipc_threedm_advanced_lowpass_filter_write(mipc_writer_t *w,
                                           const mipc_threedm_advanced_lowpass_filter_t *in) {
    mipc_status_t st;
    int absent = 0;
    if ((st = mipc_wr_u8(w, &in->function)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u8(w, &in->target_descriptor)) != MIPC_OK) {
        return st;
    }
    if (!in->has_enable) {
        absent = 1;
    } else if (absent) {
        return MIPC_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = mipc_wr_bool(w, &in->enable)) != MIPC_OK) {
            return st;
        }
    }
    if (!in->has_manual) {
        absent = 1;
    } else if (absent) {
        return MIPC_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = mipc_wr_bool(w, &in->manual)) != MIPC_OK) {
            return st;
        }
    }
    if (!in->has_frequency) {
        absent = 1;
    } else if (absent) {
        return MIPC_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = mipc_wr_u16(w, &in->frequency)) != MIPC_OK) {
            return st;
        }
    }
    if (!in->has_reserved) {
        absent = 1;
    } else if (absent) {
        return MIPC_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = mipc_wr_u8(w, &in->reserved)) != MIPC_OK) {
            return st;
        }
    }
    return MIPC_OK;
}

mipc_status_t mipc_threedm_advanced_lowpass_filter_encode(const mipc_threedm_advanced_lowpass_filter_t *value,
                                                          uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    mipc_writer_init(&w, buf, cap);
    st = mipc_threedm_advanced_lowpass_filter_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mipc_status_t mipc_threedm_advanced_lowpass_filter_decode(const uint8_t *data, size_t len,
                                                          mipc_threedm_advanced_lowpass_filter_t *out,
                                                          mipc_decode_error_t *err) {
    mipc_reader_t r;
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_threedm_advanced_lowpass_filter_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

void mipc_threedm_advanced_lowpass_filter_to_json(mipc_jw_t *w,
                                                  const mipc_threedm_advanced_lowpass_filter_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "function");
    mipc_jw_u8(w, &in->function);
    mipc_jw_key(w, &first, "target_descriptor");
    mipc_jw_u8(w, &in->target_descriptor);
    if (in->has_enable) {
        mipc_jw_key(w, &first, "enable");
        mipc_jw_bool(w, &in->enable);
    }
    if (in->has_manual) {
        mipc_jw_key(w, &first, "manual");
        mipc_jw_bool(w, &in->manual);
    }
    if (in->has_frequency) {
        mipc_jw_key(w, &first, "frequency");
        mipc_jw_u16(w, &in->frequency);
    }
    if (in->has_reserved) {
        mipc_jw_key(w, &first, "reserved");
        mipc_jw_u8(w, &in->reserved);
    }
    mipc_jw_raw(w, "}", 1);
}

int mipc_threedm_advanced_lowpass_filter_from_json(mipc_jr_t *jr, size_t pos,
                                                   mipc_threedm_advanced_lowpass_filter_t *out) {
    static const char *const keys[] = {"function", "target_descriptor", "enable",
                                       "manual",   "frequency",         "reserved"};
    size_t vp = 0;
    int found;
    int absent = 0;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 6)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "function", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"function\"");
    }
    {
        mipc_jr_push(jr, "function");
        if (mipc_jr_u8(jr, vp, &out->function)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "target_descriptor", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"target_descriptor\"");
    }
    {
        mipc_jr_push(jr, "target_descriptor");
        if (mipc_jr_u8(jr, vp, &out->target_descriptor)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "enable", &vp);
    out->has_enable = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mipc_jr_fail(jr, "optional parameter \"enable\" given after an absent one");
    } else {
        mipc_jr_push(jr, "enable");
        if (mipc_jr_bool(jr, vp, &out->enable)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "manual", &vp);
    out->has_manual = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mipc_jr_fail(jr, "optional parameter \"manual\" given after an absent one");
    } else {
        mipc_jr_push(jr, "manual");
        if (mipc_jr_bool(jr, vp, &out->manual)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "frequency", &vp);
    out->has_frequency = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mipc_jr_fail(jr, "optional parameter \"frequency\" given after an absent one");
    } else {
        mipc_jr_push(jr, "frequency");
        if (mipc_jr_u16(jr, vp, &out->frequency)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "reserved", &vp);
    out->has_reserved = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mipc_jr_fail(jr, "optional parameter \"reserved\" given after an absent one");
    } else {
        mipc_jr_push(jr, "reserved");
        if (mipc_jr_u8(jr, vp, &out->reserved)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mipc_threedm_advanced_lowpass_filter_response_t */

static int
mipc_threedm_advanced_lowpass_filter_response_read(mipc_reader_t *r,
                                                   mipc_threedm_advanced_lowpass_filter_response_t *out) {
    mipc_rd_push(r, "target_descriptor");
    if (mipc_rd_u8(r, &out->target_descriptor)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "enable");
    if (mipc_rd_bool(r, &out->enable)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "manual");
    if (mipc_rd_bool(r, &out->manual)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "frequency");
    if (mipc_rd_u16(r, &out->frequency)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "reserved");
    if (mipc_rd_u8(r, &out->reserved)) {
        return -1;
    }
    mipc_rd_pop(r);
    return mipc_rd_finish(r);
}

static mipc_status_t mipc_threedm_advanced_lowpass_filter_response_write(
    mipc_writer_t *w, const mipc_threedm_advanced_lowpass_filter_response_t *in) {
    mipc_status_t st;
    if ((st = mipc_wr_u8(w, &in->target_descriptor)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_bool(w, &in->enable)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_bool(w, &in->manual)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u16(w, &in->frequency)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u8(w, &in->reserved)) != MIPC_OK) {
        return st;
    }
    return MIPC_OK;
}

mipc_status_t mipc_threedm_advanced_lowpass_filter_response_encode(
    const mipc_threedm_advanced_lowpass_filter_response_t *value, uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    mipc_writer_init(&w, buf, cap);
    st = mipc_threedm_advanced_lowpass_filter_response_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 6 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int
mipc_threedm_advanced_lowpass_filter_response_load(const uint8_t *d,
                                                   mipc_threedm_advanced_lowpass_filter_response_t *out) {
    out->target_descriptor = mipc_ld_u8(d + 0);
    if (d[1] > 1) {
        return -1;
    }
    out->enable = mipc_ld_bool(d + 1);
    if (d[2] > 1) {
        return -1;
    }
    out->manual = mipc_ld_bool(d + 2);
    out->frequency = mipc_ld_u16(d + 3);
    out->reserved = mipc_ld_u8(d + 5);
    return 0;
}

/* The general reader: lengths other than 6, bad bool bytes, error details. */
static MIPC_NOINLINE mipc_status_t mipc_threedm_advanced_lowpass_filter_response_decode_read(
    const uint8_t *data, size_t len, mipc_threedm_advanced_lowpass_filter_response_t *out,
    mipc_decode_error_t *err) {
    mipc_reader_t r;
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_threedm_advanced_lowpass_filter_response_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t
mipc_threedm_advanced_lowpass_filter_response_decode(const uint8_t *data, size_t len,
                                                     mipc_threedm_advanced_lowpass_filter_response_t *out,
                                                     mipc_decode_error_t *err) {
    if (len == 6 && mipc_threedm_advanced_lowpass_filter_response_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_threedm_advanced_lowpass_filter_response_decode_read(data, len, out, err);
}

void mipc_threedm_advanced_lowpass_filter_response_to_json(
    mipc_jw_t *w, const mipc_threedm_advanced_lowpass_filter_response_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "target_descriptor");
    mipc_jw_u8(w, &in->target_descriptor);
    mipc_jw_key(w, &first, "enable");
    mipc_jw_bool(w, &in->enable);
    mipc_jw_key(w, &first, "manual");
    mipc_jw_bool(w, &in->manual);
    mipc_jw_key(w, &first, "frequency");
    mipc_jw_u16(w, &in->frequency);
    mipc_jw_key(w, &first, "reserved");
    mipc_jw_u8(w, &in->reserved);
    mipc_jw_raw(w, "}", 1);
}

int mipc_threedm_advanced_lowpass_filter_response_from_json(
    mipc_jr_t *jr, size_t pos, mipc_threedm_advanced_lowpass_filter_response_t *out) {
    static const char *const keys[] = {"target_descriptor", "enable", "manual", "frequency", "reserved"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 5)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "target_descriptor", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"target_descriptor\"");
    }
    {
        mipc_jr_push(jr, "target_descriptor");
        if (mipc_jr_u8(jr, vp, &out->target_descriptor)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "enable", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"enable\"");
    }
    {
        mipc_jr_push(jr, "enable");
        if (mipc_jr_bool(jr, vp, &out->enable)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "manual", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"manual\"");
    }
    {
        mipc_jr_push(jr, "manual");
        if (mipc_jr_bool(jr, vp, &out->manual)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "frequency", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"frequency\"");
    }
    {
        mipc_jr_push(jr, "frequency");
        if (mipc_jr_u16(jr, vp, &out->frequency)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "reserved", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"reserved\"");
    }
    {
        mipc_jr_push(jr, "reserved");
        if (mipc_jr_u8(jr, vp, &out->reserved)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mipc_threedm_complementary_filter_t */

static int mipc_threedm_complementary_filter_read(mipc_reader_t *r,
                                                  mipc_threedm_complementary_filter_t *out) {
    mipc_rd_push(r, "function");
    if (mipc_rd_u8(r, &out->function)) {
        return -1;
    }
    mipc_rd_pop(r);
    if (r->pos < r->len) {
        out->has_pitch_roll_enable = true;
        mipc_rd_push(r, "pitch_roll_enable");
        if (mipc_rd_bool(r, &out->pitch_roll_enable)) {
            return -1;
        }
        mipc_rd_pop(r);
    }
    if (r->pos < r->len) {
        out->has_heading_enable = true;
        mipc_rd_push(r, "heading_enable");
        if (mipc_rd_bool(r, &out->heading_enable)) {
            return -1;
        }
        mipc_rd_pop(r);
    }
    if (r->pos < r->len) {
        out->has_pitch_roll_time_constant = true;
        mipc_rd_push(r, "pitch_roll_time_constant");
        if (mipc_rd_f32(r, &out->pitch_roll_time_constant)) {
            return -1;
        }
        mipc_rd_pop(r);
    }
    if (r->pos < r->len) {
        out->has_heading_time_constant = true;
        mipc_rd_push(r, "heading_time_constant");
        if (mipc_rd_f32(r, &out->heading_time_constant)) {
            return -1;
        }
        mipc_rd_pop(r);
    }
    return mipc_rd_finish(r);
}

static mipc_status_t mipc_threedm_complementary_filter_write(mipc_writer_t *w,
                                                             const mipc_threedm_complementary_filter_t *in) {
    mipc_status_t st;
    int absent = 0;
    if ((st = mipc_wr_u8(w, &in->function)) != MIPC_OK) {
        return st;
    }
    if (!in->has_pitch_roll_enable) {
        absent = 1;
    } else if (absent) {
        return MIPC_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = mipc_wr_bool(w, &in->pitch_roll_enable)) != MIPC_OK) {
            return st;
        }
    }
    if (!in->has_heading_enable) {
        absent = 1;
    } else if (absent) {
        return MIPC_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = mipc_wr_bool(w, &in->heading_enable)) != MIPC_OK) {
            return st;
        }
    }
    if (!in->has_pitch_roll_time_constant) {
        absent = 1;
    } else if (absent) {
        return MIPC_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = mipc_wr_f32(w, &in->pitch_roll_time_constant)) != MIPC_OK) {
            return st;
        }
    }
    if (!in->has_heading_time_constant) {
        absent = 1;
    } else if (absent) {
        return MIPC_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = mipc_wr_f32(w, &in->heading_time_constant)) != MIPC_OK) {
            return st;
        }
    }
    return MIPC_OK;
}

mipc_status_t mipc_threedm_complementary_filter_encode(const mipc_threedm_complementary_filter_t *value,
                                                       uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    mipc_writer_init(&w, buf, cap);
    st = mipc_threedm_complementary_filter_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mipc_status_t mipc_threedm_complementary_filter_decode(const uint8_t *data, size_t len,
                                                       mipc_threedm_complementary_filter_t *out,
                                                       mipc_decode_error_t *err) {
    mipc_reader_t r;
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_threedm_complementary_filter_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

void mipc_threedm_complementary_filter_to_json(mipc_jw_t *w, const mipc_threedm_complementary_filter_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "function");
    mipc_jw_u8(w, &in->function);
    if (in->has_pitch_roll_enable) {
        mipc_jw_key(w, &first, "pitch_roll_enable");
        mipc_jw_bool(w, &in->pitch_roll_enable);
    }
    if (in->has_heading_enable) {
        mipc_jw_key(w, &first, "heading_enable");
        mipc_jw_bool(w, &in->heading_enable);
    }
    if (in->has_pitch_roll_time_constant) {
        mipc_jw_key(w, &first, "pitch_roll_time_constant");
        mipc_jw_f32(w, &in->pitch_roll_time_constant);
    }
    if (in->has_heading_time_constant) {
        mipc_jw_key(w, &first, "heading_time_constant");
        mipc_jw_f32(w, &in->heading_time_constant);
    }
    mipc_jw_raw(w, "}", 1);
}

int mipc_threedm_complementary_filter_from_json(mipc_jr_t *jr, size_t pos,
                                                mipc_threedm_complementary_filter_t *out) {
    static const char *const keys[] = {"function", "pitch_roll_enable", "heading_enable",
                                       "pitch_roll_time_constant", "heading_time_constant"};
    size_t vp = 0;
    int found;
    int absent = 0;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 5)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "function", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"function\"");
    }
    {
        mipc_jr_push(jr, "function");
        if (mipc_jr_u8(jr, vp, &out->function)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "pitch_roll_enable", &vp);
    out->has_pitch_roll_enable = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mipc_jr_fail(jr, "optional parameter \"pitch_roll_enable\" given after an absent one");
    } else {
        mipc_jr_push(jr, "pitch_roll_enable");
        if (mipc_jr_bool(jr, vp, &out->pitch_roll_enable)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "heading_enable", &vp);
    out->has_heading_enable = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mipc_jr_fail(jr, "optional parameter \"heading_enable\" given after an absent one");
    } else {
        mipc_jr_push(jr, "heading_enable");
        if (mipc_jr_bool(jr, vp, &out->heading_enable)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "pitch_roll_time_constant", &vp);
    out->has_pitch_roll_time_constant = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mipc_jr_fail(jr, "optional parameter \"pitch_roll_time_constant\" given after an absent one");
    } else {
        mipc_jr_push(jr, "pitch_roll_time_constant");
        if (mipc_jr_f32(jr, vp, &out->pitch_roll_time_constant)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "heading_time_constant", &vp);
    out->has_heading_time_constant = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mipc_jr_fail(jr, "optional parameter \"heading_time_constant\" given after an absent one");
    } else {
        mipc_jr_push(jr, "heading_time_constant");
        if (mipc_jr_f32(jr, vp, &out->heading_time_constant)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mipc_threedm_complementary_filter_response_t */

static int
mipc_threedm_complementary_filter_response_read(mipc_reader_t *r,
                                                mipc_threedm_complementary_filter_response_t *out) {
    mipc_rd_push(r, "pitch_roll_enable");
    if (mipc_rd_bool(r, &out->pitch_roll_enable)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "heading_enable");
    if (mipc_rd_bool(r, &out->heading_enable)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "pitch_roll_time_constant");
    if (mipc_rd_f32(r, &out->pitch_roll_time_constant)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "heading_time_constant");
    if (mipc_rd_f32(r, &out->heading_time_constant)) {
        return -1;
    }
    mipc_rd_pop(r);
    return mipc_rd_finish(r);
}

static mipc_status_t
mipc_threedm_complementary_filter_response_write(mipc_writer_t *w,
                                                 const mipc_threedm_complementary_filter_response_t *in) {
    mipc_status_t st;
    if ((st = mipc_wr_bool(w, &in->pitch_roll_enable)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_bool(w, &in->heading_enable)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_f32(w, &in->pitch_roll_time_constant)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_f32(w, &in->heading_time_constant)) != MIPC_OK) {
        return st;
    }
    return MIPC_OK;
}

mipc_status_t
mipc_threedm_complementary_filter_response_encode(const mipc_threedm_complementary_filter_response_t *value,
                                                  uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    mipc_writer_init(&w, buf, cap);
    st = mipc_threedm_complementary_filter_response_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 10 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int
mipc_threedm_complementary_filter_response_load(const uint8_t *d,
                                                mipc_threedm_complementary_filter_response_t *out) {
    if (d[0] > 1) {
        return -1;
    }
    out->pitch_roll_enable = mipc_ld_bool(d + 0);
    if (d[1] > 1) {
        return -1;
    }
    out->heading_enable = mipc_ld_bool(d + 1);
    out->pitch_roll_time_constant = mipc_ld_f32(d + 2);
    out->heading_time_constant = mipc_ld_f32(d + 6);
    return 0;
}

/* The general reader: lengths other than 10, bad bool bytes, error details. */
static MIPC_NOINLINE mipc_status_t mipc_threedm_complementary_filter_response_decode_read(
    const uint8_t *data, size_t len, mipc_threedm_complementary_filter_response_t *out,
    mipc_decode_error_t *err) {
    mipc_reader_t r;
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_threedm_complementary_filter_response_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t
mipc_threedm_complementary_filter_response_decode(const uint8_t *data, size_t len,
                                                  mipc_threedm_complementary_filter_response_t *out,
                                                  mipc_decode_error_t *err) {
    if (len == 10 && mipc_threedm_complementary_filter_response_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_threedm_complementary_filter_response_decode_read(data, len, out, err);
}

void mipc_threedm_complementary_filter_response_to_json(
    mipc_jw_t *w, const mipc_threedm_complementary_filter_response_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "pitch_roll_enable");
    mipc_jw_bool(w, &in->pitch_roll_enable);
    mipc_jw_key(w, &first, "heading_enable");
    mipc_jw_bool(w, &in->heading_enable);
    mipc_jw_key(w, &first, "pitch_roll_time_constant");
    mipc_jw_f32(w, &in->pitch_roll_time_constant);
    mipc_jw_key(w, &first, "heading_time_constant");
    mipc_jw_f32(w, &in->heading_time_constant);
    mipc_jw_raw(w, "}", 1);
}

int mipc_threedm_complementary_filter_response_from_json(mipc_jr_t *jr, size_t pos,
                                                         mipc_threedm_complementary_filter_response_t *out) {
    static const char *const keys[] = {"pitch_roll_enable", "heading_enable", "pitch_roll_time_constant",
                                       "heading_time_constant"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 4)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "pitch_roll_enable", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"pitch_roll_enable\"");
    }
    {
        mipc_jr_push(jr, "pitch_roll_enable");
        if (mipc_jr_bool(jr, vp, &out->pitch_roll_enable)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "heading_enable", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"heading_enable\"");
    }
    {
        mipc_jr_push(jr, "heading_enable");
        if (mipc_jr_bool(jr, vp, &out->heading_enable)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "pitch_roll_time_constant", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"pitch_roll_time_constant\"");
    }
    {
        mipc_jr_push(jr, "pitch_roll_time_constant");
        if (mipc_jr_f32(jr, vp, &out->pitch_roll_time_constant)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "heading_time_constant", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"heading_time_constant\"");
    }
    {
        mipc_jr_push(jr, "heading_time_constant");
        if (mipc_jr_f32(jr, vp, &out->heading_time_constant)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mipc_threedm_sensor_range_t */

static int mipc_threedm_sensor_range_read(mipc_reader_t *r, mipc_threedm_sensor_range_t *out) {
    mipc_rd_push(r, "function");
    if (mipc_rd_u8(r, &out->function)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "sensor");
    if (mipc_rd_u8(r, &out->sensor)) {
        return -1;
    }
    mipc_rd_pop(r);
    if (r->pos < r->len) {
        out->has_setting = true;
        mipc_rd_push(r, "setting");
        if (mipc_rd_u8(r, &out->setting)) {
            return -1;
        }
        mipc_rd_pop(r);
    }
    return mipc_rd_finish(r);
}

static mipc_status_t mipc_threedm_sensor_range_write(mipc_writer_t *w,
                                                     const mipc_threedm_sensor_range_t *in) {
    mipc_status_t st;
    int absent = 0;
    if ((st = mipc_wr_u8(w, &in->function)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u8(w, &in->sensor)) != MIPC_OK) {
        return st;
    }
    if (!in->has_setting) {
        absent = 1;
    } else if (absent) {
        return MIPC_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = mipc_wr_u8(w, &in->setting)) != MIPC_OK) {
            return st;
        }
    }
    return MIPC_OK;
}

mipc_status_t mipc_threedm_sensor_range_encode(const mipc_threedm_sensor_range_t *value, uint8_t *buf,
                                               size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    mipc_writer_init(&w, buf, cap);
    st = mipc_threedm_sensor_range_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mipc_status_t mipc_threedm_sensor_range_decode(const uint8_t *data, size_t len,
                                               mipc_threedm_sensor_range_t *out, mipc_decode_error_t *err) {
    mipc_reader_t r;
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_threedm_sensor_range_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

void mipc_threedm_sensor_range_to_json(mipc_jw_t *w, const mipc_threedm_sensor_range_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "function");
    mipc_jw_u8(w, &in->function);
    mipc_jw_key(w, &first, "sensor");
    mipc_jw_u8(w, &in->sensor);
    if (in->has_setting) {
        mipc_jw_key(w, &first, "setting");
        mipc_jw_u8(w, &in->setting);
    }
    mipc_jw_raw(w, "}", 1);
}

int mipc_threedm_sensor_range_from_json(mipc_jr_t *jr, size_t pos, mipc_threedm_sensor_range_t *out) {
    static const char *const keys[] = {"function", "sensor", "setting"};
    size_t vp = 0;
    int found;
    int absent = 0;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 3)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "function", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"function\"");
    }
    {
        mipc_jr_push(jr, "function");
        if (mipc_jr_u8(jr, vp, &out->function)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "sensor", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"sensor\"");
    }
    {
        mipc_jr_push(jr, "sensor");
        if (mipc_jr_u8(jr, vp, &out->sensor)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "setting", &vp);
    out->has_setting = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mipc_jr_fail(jr, "optional parameter \"setting\" given after an absent one");
    } else {
        mipc_jr_push(jr, "setting");
        if (mipc_jr_u8(jr, vp, &out->setting)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mipc_threedm_sensor_range_response_t */

static int mipc_threedm_sensor_range_response_read(mipc_reader_t *r,
                                                   mipc_threedm_sensor_range_response_t *out) {
    mipc_rd_push(r, "sensor");
    if (mipc_rd_u8(r, &out->sensor)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "setting");
    if (mipc_rd_u8(r, &out->setting)) {
        return -1;
    }
    mipc_rd_pop(r);
    return mipc_rd_finish(r);
}

static mipc_status_t
mipc_threedm_sensor_range_response_write(mipc_writer_t *w, const mipc_threedm_sensor_range_response_t *in) {
    mipc_status_t st;
    if ((st = mipc_wr_u8(w, &in->sensor)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u8(w, &in->setting)) != MIPC_OK) {
        return st;
    }
    return MIPC_OK;
}

mipc_status_t mipc_threedm_sensor_range_response_encode(const mipc_threedm_sensor_range_response_t *value,
                                                        uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    mipc_writer_init(&w, buf, cap);
    st = mipc_threedm_sensor_range_response_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 2 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mipc_threedm_sensor_range_response_load(const uint8_t *d,
                                                   mipc_threedm_sensor_range_response_t *out) {
    out->sensor = mipc_ld_u8(d + 0);
    out->setting = mipc_ld_u8(d + 1);
    return 0;
}

/* The general reader: lengths other than 2, bad bool bytes, error details. */
static MIPC_NOINLINE mipc_status_t mipc_threedm_sensor_range_response_decode_read(
    const uint8_t *data, size_t len, mipc_threedm_sensor_range_response_t *out, mipc_decode_error_t *err) {
    mipc_reader_t r;
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_threedm_sensor_range_response_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t mipc_threedm_sensor_range_response_decode(const uint8_t *data, size_t len,
                                                        mipc_threedm_sensor_range_response_t *out,
                                                        mipc_decode_error_t *err) {
    if (len == 2 && mipc_threedm_sensor_range_response_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_threedm_sensor_range_response_decode_read(data, len, out, err);
}

void mipc_threedm_sensor_range_response_to_json(mipc_jw_t *w,
                                                const mipc_threedm_sensor_range_response_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "sensor");
    mipc_jw_u8(w, &in->sensor);
    mipc_jw_key(w, &first, "setting");
    mipc_jw_u8(w, &in->setting);
    mipc_jw_raw(w, "}", 1);
}

int mipc_threedm_sensor_range_response_from_json(mipc_jr_t *jr, size_t pos,
                                                 mipc_threedm_sensor_range_response_t *out) {
    static const char *const keys[] = {"sensor", "setting"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 2)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "sensor", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"sensor\"");
    }
    {
        mipc_jr_push(jr, "sensor");
        if (mipc_jr_u8(jr, vp, &out->sensor)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "setting", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"setting\"");
    }
    {
        mipc_jr_push(jr, "setting");
        if (mipc_jr_u8(jr, vp, &out->setting)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mipc_threedm_get_calibrated_sensor_ranges_t */

static int mipc_threedm_get_calibrated_sensor_ranges_read(mipc_reader_t *r,
                                                          mipc_threedm_get_calibrated_sensor_ranges_t *out) {
    mipc_rd_push(r, "sensor");
    if (mipc_rd_u8(r, &out->sensor)) {
        return -1;
    }
    mipc_rd_pop(r);
    return mipc_rd_finish(r);
}

static mipc_status_t
mipc_threedm_get_calibrated_sensor_ranges_write(mipc_writer_t *w,
                                                const mipc_threedm_get_calibrated_sensor_ranges_t *in) {
    mipc_status_t st;
    if ((st = mipc_wr_u8(w, &in->sensor)) != MIPC_OK) {
        return st;
    }
    return MIPC_OK;
}

mipc_status_t
mipc_threedm_get_calibrated_sensor_ranges_encode(const mipc_threedm_get_calibrated_sensor_ranges_t *value,
                                                 uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    mipc_writer_init(&w, buf, cap);
    st = mipc_threedm_get_calibrated_sensor_ranges_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 1 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mipc_threedm_get_calibrated_sensor_ranges_load(const uint8_t *d,
                                                          mipc_threedm_get_calibrated_sensor_ranges_t *out) {
    out->sensor = mipc_ld_u8(d + 0);
    return 0;
}

/* The general reader: lengths other than 1, bad bool bytes, error details. */
static MIPC_NOINLINE mipc_status_t mipc_threedm_get_calibrated_sensor_ranges_decode_read(
    const uint8_t *data, size_t len, mipc_threedm_get_calibrated_sensor_ranges_t *out,
    mipc_decode_error_t *err) {
    mipc_reader_t r;
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_threedm_get_calibrated_sensor_ranges_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t
mipc_threedm_get_calibrated_sensor_ranges_decode(const uint8_t *data, size_t len,
                                                 mipc_threedm_get_calibrated_sensor_ranges_t *out,
                                                 mipc_decode_error_t *err) {
    if (len == 1 && mipc_threedm_get_calibrated_sensor_ranges_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_threedm_get_calibrated_sensor_ranges_decode_read(data, len, out, err);
}

void mipc_threedm_get_calibrated_sensor_ranges_to_json(
    mipc_jw_t *w, const mipc_threedm_get_calibrated_sensor_ranges_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "sensor");
    mipc_jw_u8(w, &in->sensor);
    mipc_jw_raw(w, "}", 1);
}

int mipc_threedm_get_calibrated_sensor_ranges_from_json(mipc_jr_t *jr, size_t pos,
                                                        mipc_threedm_get_calibrated_sensor_ranges_t *out) {
    static const char *const keys[] = {"sensor"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 1)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "sensor", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"sensor\"");
    }
    {
        mipc_jr_push(jr, "sensor");
        if (mipc_jr_u8(jr, vp, &out->sensor)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mipc_threedm_calibrated_sensor_ranges_t */

static int mipc_threedm_calibrated_sensor_ranges_read(mipc_reader_t *r,
                                                      mipc_threedm_calibrated_sensor_ranges_t *out) {
    size_t i;
    mipc_rd_push(r, "sensor");
    if (mipc_rd_u8(r, &out->sensor)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "num_ranges");
    if (mipc_rd_u8(r, &out->num_ranges)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "ranges");
    if (out->num_ranges > 50) {
        return mipc_rd_count_error(r, (uint64_t)out->num_ranges, 50);
    }
    for (i = 0; i < (size_t)out->num_ranges; i++) {
        mipc_rd_index(r, i);
        if (mipc_sensor_range_entry_read(r, &out->ranges[i])) {
            return -1;
        }
    }
    mipc_rd_pop(r);
    return mipc_rd_finish(r);
}

static mipc_status_t
mipc_threedm_calibrated_sensor_ranges_write(mipc_writer_t *w,
                                            const mipc_threedm_calibrated_sensor_ranges_t *in) {
    mipc_status_t st;
    size_t i;
    if ((st = mipc_wr_u8(w, &in->sensor)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u8(w, &in->num_ranges)) != MIPC_OK) {
        return st;
    }
    if (in->num_ranges > 50) {
        return MIPC_ERR_INVALID;
    }
    for (i = 0; i < (size_t)in->num_ranges; i++) {
        if ((st = mipc_sensor_range_entry_write(w, &in->ranges[i])) != MIPC_OK) {
            return st;
        }
    }
    return MIPC_OK;
}

mipc_status_t
mipc_threedm_calibrated_sensor_ranges_encode(const mipc_threedm_calibrated_sensor_ranges_t *value,
                                             uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    mipc_writer_init(&w, buf, cap);
    st = mipc_threedm_calibrated_sensor_ranges_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mipc_status_t mipc_threedm_calibrated_sensor_ranges_decode(const uint8_t *data, size_t len,
                                                           mipc_threedm_calibrated_sensor_ranges_t *out,
                                                           mipc_decode_error_t *err) {
    mipc_reader_t r;
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_threedm_calibrated_sensor_ranges_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

void mipc_threedm_calibrated_sensor_ranges_to_json(mipc_jw_t *w,
                                                   const mipc_threedm_calibrated_sensor_ranges_t *in) {
    int first = 1;
    size_t i;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "sensor");
    mipc_jw_u8(w, &in->sensor);
    mipc_jw_key(w, &first, "num_ranges");
    mipc_jw_u8(w, &in->num_ranges);
    mipc_jw_key(w, &first, "ranges");
    mipc_jw_raw(w, "[", 1);
    for (i = 0; i < (size_t)in->num_ranges && i < 50; i++) {
        mipc_jw_sep(w, i);
        mipc_sensor_range_entry_to_json(w, &in->ranges[i]);
    }
    mipc_jw_raw(w, "]", 1);
    mipc_jw_raw(w, "}", 1);
}

int mipc_threedm_calibrated_sensor_ranges_from_json(mipc_jr_t *jr, size_t pos,
                                                    mipc_threedm_calibrated_sensor_ranges_t *out) {
    static const char *const keys[] = {"sensor", "num_ranges", "ranges"};
    size_t vp = 0;
    int found;
    size_t i;
    size_t it = 0;
    size_t ep = 0;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 3)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "sensor", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"sensor\"");
    }
    {
        mipc_jr_push(jr, "sensor");
        if (mipc_jr_u8(jr, vp, &out->sensor)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "num_ranges", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"num_ranges\"");
    }
    {
        mipc_jr_push(jr, "num_ranges");
        if (mipc_jr_u8(jr, vp, &out->num_ranges)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "ranges", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"ranges\"");
    }
    {
        mipc_jr_push(jr, "ranges");
        if (mipc_jr_array(jr, vp, &it)) {
            return -1;
        }
        for (i = 0;; i++) {
            int more = mipc_jr_next(jr, &it, &ep);
            if (more < 0) {
                return -1;
            }
            if (!more) {
                break;
            }
            if (i >= 50) {
                return mipc_jr_fail(jr, "more than 50 elements");
            }
            mipc_jr_index(jr, i);
            if (mipc_sensor_range_entry_from_json(jr, ep, &out->ranges[i])) {
                return -1;
            }
        }
        mipc_jr_index(jr, SIZE_MAX);
        if (i != (size_t)out->num_ranges) {
            return mipc_jr_fail(jr, "%zu elements but num_ranges is %zu", i, (size_t)out->num_ranges);
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mipc_threedm_lowpass_filter_t */

static int mipc_threedm_lowpass_filter_read(mipc_reader_t *r, mipc_threedm_lowpass_filter_t *out) {
    mipc_rd_push(r, "function");
    if (mipc_rd_u8(r, &out->function)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "desc_set");
    if (mipc_rd_u8(r, &out->desc_set)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "field_desc");
    if (mipc_rd_u8(r, &out->field_desc)) {
        return -1;
    }
    mipc_rd_pop(r);
    if (r->pos < r->len) {
        out->has_enable = true;
        mipc_rd_push(r, "enable");
        if (mipc_rd_bool(r, &out->enable)) {
            return -1;
        }
        mipc_rd_pop(r);
    }
    if (r->pos < r->len) {
        out->has_manual = true;
        mipc_rd_push(r, "manual");
        if (mipc_rd_bool(r, &out->manual)) {
            return -1;
        }
        mipc_rd_pop(r);
    }
    if (r->pos < r->len) {
        out->has_frequency = true;
        mipc_rd_push(r, "frequency");
        if (mipc_rd_f32(r, &out->frequency)) {
            return -1;
        }
        mipc_rd_pop(r);
    }
    return mipc_rd_finish(r);
}

static mipc_status_t mipc_threedm_lowpass_filter_write(mipc_writer_t *w,
                                                       const mipc_threedm_lowpass_filter_t *in) {
    mipc_status_t st;
    int absent = 0;
    if ((st = mipc_wr_u8(w, &in->function)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u8(w, &in->desc_set)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u8(w, &in->field_desc)) != MIPC_OK) {
        return st;
    }
    if (!in->has_enable) {
        absent = 1;
    } else if (absent) {
        return MIPC_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = mipc_wr_bool(w, &in->enable)) != MIPC_OK) {
            return st;
        }
    }
    if (!in->has_manual) {
        absent = 1;
    } else if (absent) {
        return MIPC_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = mipc_wr_bool(w, &in->manual)) != MIPC_OK) {
            return st;
        }
    }
    if (!in->has_frequency) {
        absent = 1;
    } else if (absent) {
        return MIPC_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = mipc_wr_f32(w, &in->frequency)) != MIPC_OK) {
            return st;
        }
    }
    return MIPC_OK;
}

mipc_status_t mipc_threedm_lowpass_filter_encode(const mipc_threedm_lowpass_filter_t *value, uint8_t *buf,
                                                 size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    mipc_writer_init(&w, buf, cap);
    st = mipc_threedm_lowpass_filter_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mipc_status_t mipc_threedm_lowpass_filter_decode(const uint8_t *data, size_t len,
                                                 mipc_threedm_lowpass_filter_t *out,
                                                 mipc_decode_error_t *err) {
    mipc_reader_t r;
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_threedm_lowpass_filter_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

void mipc_threedm_lowpass_filter_to_json(mipc_jw_t *w, const mipc_threedm_lowpass_filter_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "function");
    mipc_jw_u8(w, &in->function);
    mipc_jw_key(w, &first, "desc_set");
    mipc_jw_u8(w, &in->desc_set);
    mipc_jw_key(w, &first, "field_desc");
    mipc_jw_u8(w, &in->field_desc);
    if (in->has_enable) {
        mipc_jw_key(w, &first, "enable");
        mipc_jw_bool(w, &in->enable);
    }
    if (in->has_manual) {
        mipc_jw_key(w, &first, "manual");
        mipc_jw_bool(w, &in->manual);
    }
    if (in->has_frequency) {
        mipc_jw_key(w, &first, "frequency");
        mipc_jw_f32(w, &in->frequency);
    }
    mipc_jw_raw(w, "}", 1);
}

int mipc_threedm_lowpass_filter_from_json(mipc_jr_t *jr, size_t pos, mipc_threedm_lowpass_filter_t *out) {
    static const char *const keys[] = {"function", "desc_set", "field_desc", "enable", "manual", "frequency"};
    size_t vp = 0;
    int found;
    int absent = 0;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 6)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "function", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"function\"");
    }
    {
        mipc_jr_push(jr, "function");
        if (mipc_jr_u8(jr, vp, &out->function)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "desc_set", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"desc_set\"");
    }
    {
        mipc_jr_push(jr, "desc_set");
        if (mipc_jr_u8(jr, vp, &out->desc_set)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "field_desc", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"field_desc\"");
    }
    {
        mipc_jr_push(jr, "field_desc");
        if (mipc_jr_u8(jr, vp, &out->field_desc)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "enable", &vp);
    out->has_enable = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mipc_jr_fail(jr, "optional parameter \"enable\" given after an absent one");
    } else {
        mipc_jr_push(jr, "enable");
        if (mipc_jr_bool(jr, vp, &out->enable)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "manual", &vp);
    out->has_manual = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mipc_jr_fail(jr, "optional parameter \"manual\" given after an absent one");
    } else {
        mipc_jr_push(jr, "manual");
        if (mipc_jr_bool(jr, vp, &out->manual)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "frequency", &vp);
    out->has_frequency = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mipc_jr_fail(jr, "optional parameter \"frequency\" given after an absent one");
    } else {
        mipc_jr_push(jr, "frequency");
        if (mipc_jr_f32(jr, vp, &out->frequency)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mipc_threedm_lowpass_filter_response_t */

static int mipc_threedm_lowpass_filter_response_read(mipc_reader_t *r,
                                                     mipc_threedm_lowpass_filter_response_t *out) {
    mipc_rd_push(r, "desc_set");
    if (mipc_rd_u8(r, &out->desc_set)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "field_desc");
    if (mipc_rd_u8(r, &out->field_desc)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "enable");
    if (mipc_rd_bool(r, &out->enable)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "manual");
    if (mipc_rd_bool(r, &out->manual)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "frequency");
    if (mipc_rd_f32(r, &out->frequency)) {
        return -1;
    }
    mipc_rd_pop(r);
    return mipc_rd_finish(r);
}

static mipc_status_t
mipc_threedm_lowpass_filter_response_write(mipc_writer_t *w,
                                           const mipc_threedm_lowpass_filter_response_t *in) {
    mipc_status_t st;
    if ((st = mipc_wr_u8(w, &in->desc_set)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u8(w, &in->field_desc)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_bool(w, &in->enable)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_bool(w, &in->manual)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_f32(w, &in->frequency)) != MIPC_OK) {
        return st;
    }
    return MIPC_OK;
}

mipc_status_t mipc_threedm_lowpass_filter_response_encode(const mipc_threedm_lowpass_filter_response_t *value,
                                                          uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    mipc_writer_init(&w, buf, cap);
    st = mipc_threedm_lowpass_filter_response_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 8 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mipc_threedm_lowpass_filter_response_load(const uint8_t *d,
                                                     mipc_threedm_lowpass_filter_response_t *out) {
    out->desc_set = mipc_ld_u8(d + 0);
    out->field_desc = mipc_ld_u8(d + 1);
    if (d[2] > 1) {
        return -1;
    }
    out->enable = mipc_ld_bool(d + 2);
    if (d[3] > 1) {
        return -1;
    }
    out->manual = mipc_ld_bool(d + 3);
    out->frequency = mipc_ld_f32(d + 4);
    return 0;
}

/* The general reader: lengths other than 8, bad bool bytes, error details. */
static MIPC_NOINLINE mipc_status_t mipc_threedm_lowpass_filter_response_decode_read(
    const uint8_t *data, size_t len, mipc_threedm_lowpass_filter_response_t *out, mipc_decode_error_t *err) {
    mipc_reader_t r;
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_threedm_lowpass_filter_response_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t mipc_threedm_lowpass_filter_response_decode(const uint8_t *data, size_t len,
                                                          mipc_threedm_lowpass_filter_response_t *out,
                                                          mipc_decode_error_t *err) {
    if (len == 8 && mipc_threedm_lowpass_filter_response_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_threedm_lowpass_filter_response_decode_read(data, len, out, err);
}

void mipc_threedm_lowpass_filter_response_to_json(mipc_jw_t *w,
                                                  const mipc_threedm_lowpass_filter_response_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "desc_set");
    mipc_jw_u8(w, &in->desc_set);
    mipc_jw_key(w, &first, "field_desc");
    mipc_jw_u8(w, &in->field_desc);
    mipc_jw_key(w, &first, "enable");
    mipc_jw_bool(w, &in->enable);
    mipc_jw_key(w, &first, "manual");
    mipc_jw_bool(w, &in->manual);
    mipc_jw_key(w, &first, "frequency");
    mipc_jw_f32(w, &in->frequency);
    mipc_jw_raw(w, "}", 1);
}

int mipc_threedm_lowpass_filter_response_from_json(mipc_jr_t *jr, size_t pos,
                                                   mipc_threedm_lowpass_filter_response_t *out) {
    static const char *const keys[] = {"desc_set", "field_desc", "enable", "manual", "frequency"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 5)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "desc_set", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"desc_set\"");
    }
    {
        mipc_jr_push(jr, "desc_set");
        if (mipc_jr_u8(jr, vp, &out->desc_set)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "field_desc", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"field_desc\"");
    }
    {
        mipc_jr_push(jr, "field_desc");
        if (mipc_jr_u8(jr, vp, &out->field_desc)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "enable", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"enable\"");
    }
    {
        mipc_jr_push(jr, "enable");
        if (mipc_jr_bool(jr, vp, &out->enable)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "manual", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"manual\"");
    }
    {
        mipc_jr_push(jr, "manual");
        if (mipc_jr_bool(jr, vp, &out->manual)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "frequency", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"frequency\"");
    }
    {
        mipc_jr_push(jr, "frequency");
        if (mipc_jr_f32(jr, vp, &out->frequency)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mipc_threedm_poll_imu_data_t */

static int mipc_threedm_poll_imu_data_read(mipc_reader_t *r, mipc_threedm_poll_imu_data_t *out) {
    size_t i;
    mipc_rd_push(r, "option");
    if (mipc_rd_u8(r, &out->option)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "num_descriptors");
    if (mipc_rd_u8(r, &out->num_descriptors)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "descriptors");
    if (out->num_descriptors > 83) {
        return mipc_rd_count_error(r, (uint64_t)out->num_descriptors, 83);
    }
    for (i = 0; i < (size_t)out->num_descriptors; i++) {
        mipc_rd_index(r, i);
        if (mipc_gx5_poll_descriptor_read(r, &out->descriptors[i])) {
            return -1;
        }
    }
    mipc_rd_pop(r);
    return mipc_rd_finish(r);
}

static mipc_status_t mipc_threedm_poll_imu_data_write(mipc_writer_t *w,
                                                      const mipc_threedm_poll_imu_data_t *in) {
    mipc_status_t st;
    size_t i;
    if ((st = mipc_wr_u8(w, &in->option)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u8(w, &in->num_descriptors)) != MIPC_OK) {
        return st;
    }
    if (in->num_descriptors > 83) {
        return MIPC_ERR_INVALID;
    }
    for (i = 0; i < (size_t)in->num_descriptors; i++) {
        if ((st = mipc_gx5_poll_descriptor_write(w, &in->descriptors[i])) != MIPC_OK) {
            return st;
        }
    }
    return MIPC_OK;
}

mipc_status_t mipc_threedm_poll_imu_data_encode(const mipc_threedm_poll_imu_data_t *value, uint8_t *buf,
                                                size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    mipc_writer_init(&w, buf, cap);
    st = mipc_threedm_poll_imu_data_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mipc_status_t mipc_threedm_poll_imu_data_decode(const uint8_t *data, size_t len,
                                                mipc_threedm_poll_imu_data_t *out, mipc_decode_error_t *err) {
    mipc_reader_t r;
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_threedm_poll_imu_data_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

void mipc_threedm_poll_imu_data_to_json(mipc_jw_t *w, const mipc_threedm_poll_imu_data_t *in) {
    int first = 1;
    size_t i;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "option");
    mipc_jw_u8(w, &in->option);
    mipc_jw_key(w, &first, "num_descriptors");
    mipc_jw_u8(w, &in->num_descriptors);
    mipc_jw_key(w, &first, "descriptors");
    mipc_jw_raw(w, "[", 1);
    for (i = 0; i < (size_t)in->num_descriptors && i < 83; i++) {
        mipc_jw_sep(w, i);
        mipc_gx5_poll_descriptor_to_json(w, &in->descriptors[i]);
    }
    mipc_jw_raw(w, "]", 1);
    mipc_jw_raw(w, "}", 1);
}

int mipc_threedm_poll_imu_data_from_json(mipc_jr_t *jr, size_t pos, mipc_threedm_poll_imu_data_t *out) {
    static const char *const keys[] = {"option", "num_descriptors", "descriptors"};
    size_t vp = 0;
    int found;
    size_t i;
    size_t it = 0;
    size_t ep = 0;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 3)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "option", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"option\"");
    }
    {
        mipc_jr_push(jr, "option");
        if (mipc_jr_u8(jr, vp, &out->option)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "num_descriptors", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"num_descriptors\"");
    }
    {
        mipc_jr_push(jr, "num_descriptors");
        if (mipc_jr_u8(jr, vp, &out->num_descriptors)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "descriptors", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"descriptors\"");
    }
    {
        mipc_jr_push(jr, "descriptors");
        if (mipc_jr_array(jr, vp, &it)) {
            return -1;
        }
        for (i = 0;; i++) {
            int more = mipc_jr_next(jr, &it, &ep);
            if (more < 0) {
                return -1;
            }
            if (!more) {
                break;
            }
            if (i >= 83) {
                return mipc_jr_fail(jr, "more than 83 elements");
            }
            mipc_jr_index(jr, i);
            if (mipc_gx5_poll_descriptor_from_json(jr, ep, &out->descriptors[i])) {
                return -1;
            }
        }
        mipc_jr_index(jr, SIZE_MAX);
        if (i != (size_t)out->num_descriptors) {
            return mipc_jr_fail(jr, "%zu elements but num_descriptors is %zu", i,
                                (size_t)out->num_descriptors);
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mipc_threedm_poll_gnss_data_t */

static int mipc_threedm_poll_gnss_data_read(mipc_reader_t *r, mipc_threedm_poll_gnss_data_t *out) {
    size_t i;
    mipc_rd_push(r, "option");
    if (mipc_rd_u8(r, &out->option)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "num_descriptors");
    if (mipc_rd_u8(r, &out->num_descriptors)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "descriptors");
    if (out->num_descriptors > 83) {
        return mipc_rd_count_error(r, (uint64_t)out->num_descriptors, 83);
    }
    for (i = 0; i < (size_t)out->num_descriptors; i++) {
        mipc_rd_index(r, i);
        if (mipc_gx5_poll_descriptor_read(r, &out->descriptors[i])) {
            return -1;
        }
    }
    mipc_rd_pop(r);
    return mipc_rd_finish(r);
}

static mipc_status_t mipc_threedm_poll_gnss_data_write(mipc_writer_t *w,
                                                       const mipc_threedm_poll_gnss_data_t *in) {
    mipc_status_t st;
    size_t i;
    if ((st = mipc_wr_u8(w, &in->option)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u8(w, &in->num_descriptors)) != MIPC_OK) {
        return st;
    }
    if (in->num_descriptors > 83) {
        return MIPC_ERR_INVALID;
    }
    for (i = 0; i < (size_t)in->num_descriptors; i++) {
        if ((st = mipc_gx5_poll_descriptor_write(w, &in->descriptors[i])) != MIPC_OK) {
            return st;
        }
    }
    return MIPC_OK;
}

mipc_status_t mipc_threedm_poll_gnss_data_encode(const mipc_threedm_poll_gnss_data_t *value, uint8_t *buf,
                                                 size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    mipc_writer_init(&w, buf, cap);
    st = mipc_threedm_poll_gnss_data_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mipc_status_t mipc_threedm_poll_gnss_data_decode(const uint8_t *data, size_t len,
                                                 mipc_threedm_poll_gnss_data_t *out,
                                                 mipc_decode_error_t *err) {
    mipc_reader_t r;
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_threedm_poll_gnss_data_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

void mipc_threedm_poll_gnss_data_to_json(mipc_jw_t *w, const mipc_threedm_poll_gnss_data_t *in) {
    int first = 1;
    size_t i;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "option");
    mipc_jw_u8(w, &in->option);
    mipc_jw_key(w, &first, "num_descriptors");
    mipc_jw_u8(w, &in->num_descriptors);
    mipc_jw_key(w, &first, "descriptors");
    mipc_jw_raw(w, "[", 1);
    for (i = 0; i < (size_t)in->num_descriptors && i < 83; i++) {
        mipc_jw_sep(w, i);
        mipc_gx5_poll_descriptor_to_json(w, &in->descriptors[i]);
    }
    mipc_jw_raw(w, "]", 1);
    mipc_jw_raw(w, "}", 1);
}

int mipc_threedm_poll_gnss_data_from_json(mipc_jr_t *jr, size_t pos, mipc_threedm_poll_gnss_data_t *out) {
    static const char *const keys[] = {"option", "num_descriptors", "descriptors"};
    size_t vp = 0;
    int found;
    size_t i;
    size_t it = 0;
    size_t ep = 0;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 3)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "option", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"option\"");
    }
    {
        mipc_jr_push(jr, "option");
        if (mipc_jr_u8(jr, vp, &out->option)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "num_descriptors", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"num_descriptors\"");
    }
    {
        mipc_jr_push(jr, "num_descriptors");
        if (mipc_jr_u8(jr, vp, &out->num_descriptors)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "descriptors", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"descriptors\"");
    }
    {
        mipc_jr_push(jr, "descriptors");
        if (mipc_jr_array(jr, vp, &it)) {
            return -1;
        }
        for (i = 0;; i++) {
            int more = mipc_jr_next(jr, &it, &ep);
            if (more < 0) {
                return -1;
            }
            if (!more) {
                break;
            }
            if (i >= 83) {
                return mipc_jr_fail(jr, "more than 83 elements");
            }
            mipc_jr_index(jr, i);
            if (mipc_gx5_poll_descriptor_from_json(jr, ep, &out->descriptors[i])) {
                return -1;
            }
        }
        mipc_jr_index(jr, SIZE_MAX);
        if (i != (size_t)out->num_descriptors) {
            return mipc_jr_fail(jr, "%zu elements but num_descriptors is %zu", i,
                                (size_t)out->num_descriptors);
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mipc_threedm_poll_filter_data_t */

static int mipc_threedm_poll_filter_data_read(mipc_reader_t *r, mipc_threedm_poll_filter_data_t *out) {
    size_t i;
    mipc_rd_push(r, "option");
    if (mipc_rd_u8(r, &out->option)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "num_descriptors");
    if (mipc_rd_u8(r, &out->num_descriptors)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "descriptors");
    if (out->num_descriptors > 83) {
        return mipc_rd_count_error(r, (uint64_t)out->num_descriptors, 83);
    }
    for (i = 0; i < (size_t)out->num_descriptors; i++) {
        mipc_rd_index(r, i);
        if (mipc_gx5_poll_descriptor_read(r, &out->descriptors[i])) {
            return -1;
        }
    }
    mipc_rd_pop(r);
    return mipc_rd_finish(r);
}

static mipc_status_t mipc_threedm_poll_filter_data_write(mipc_writer_t *w,
                                                         const mipc_threedm_poll_filter_data_t *in) {
    mipc_status_t st;
    size_t i;
    if ((st = mipc_wr_u8(w, &in->option)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u8(w, &in->num_descriptors)) != MIPC_OK) {
        return st;
    }
    if (in->num_descriptors > 83) {
        return MIPC_ERR_INVALID;
    }
    for (i = 0; i < (size_t)in->num_descriptors; i++) {
        if ((st = mipc_gx5_poll_descriptor_write(w, &in->descriptors[i])) != MIPC_OK) {
            return st;
        }
    }
    return MIPC_OK;
}

mipc_status_t mipc_threedm_poll_filter_data_encode(const mipc_threedm_poll_filter_data_t *value, uint8_t *buf,
                                                   size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    mipc_writer_init(&w, buf, cap);
    st = mipc_threedm_poll_filter_data_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mipc_status_t mipc_threedm_poll_filter_data_decode(const uint8_t *data, size_t len,
                                                   mipc_threedm_poll_filter_data_t *out,
                                                   mipc_decode_error_t *err) {
    mipc_reader_t r;
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_threedm_poll_filter_data_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

void mipc_threedm_poll_filter_data_to_json(mipc_jw_t *w, const mipc_threedm_poll_filter_data_t *in) {
    int first = 1;
    size_t i;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "option");
    mipc_jw_u8(w, &in->option);
    mipc_jw_key(w, &first, "num_descriptors");
    mipc_jw_u8(w, &in->num_descriptors);
    mipc_jw_key(w, &first, "descriptors");
    mipc_jw_raw(w, "[", 1);
    for (i = 0; i < (size_t)in->num_descriptors && i < 83; i++) {
        mipc_jw_sep(w, i);
        mipc_gx5_poll_descriptor_to_json(w, &in->descriptors[i]);
    }
    mipc_jw_raw(w, "]", 1);
    mipc_jw_raw(w, "}", 1);
}

int mipc_threedm_poll_filter_data_from_json(mipc_jr_t *jr, size_t pos, mipc_threedm_poll_filter_data_t *out) {
    static const char *const keys[] = {"option", "num_descriptors", "descriptors"};
    size_t vp = 0;
    int found;
    size_t i;
    size_t it = 0;
    size_t ep = 0;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 3)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "option", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"option\"");
    }
    {
        mipc_jr_push(jr, "option");
        if (mipc_jr_u8(jr, vp, &out->option)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "num_descriptors", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"num_descriptors\"");
    }
    {
        mipc_jr_push(jr, "num_descriptors");
        if (mipc_jr_u8(jr, vp, &out->num_descriptors)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "descriptors", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"descriptors\"");
    }
    {
        mipc_jr_push(jr, "descriptors");
        if (mipc_jr_array(jr, vp, &it)) {
            return -1;
        }
        for (i = 0;; i++) {
            int more = mipc_jr_next(jr, &it, &ep);
            if (more < 0) {
                return -1;
            }
            if (!more) {
                break;
            }
            if (i >= 83) {
                return mipc_jr_fail(jr, "more than 83 elements");
            }
            mipc_jr_index(jr, i);
            if (mipc_gx5_poll_descriptor_from_json(jr, ep, &out->descriptors[i])) {
                return -1;
            }
        }
        mipc_jr_index(jr, SIZE_MAX);
        if (i != (size_t)out->num_descriptors) {
            return mipc_jr_fail(jr, "%zu elements but num_descriptors is %zu", i,
                                (size_t)out->num_descriptors);
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mipc_threedm_poll_nmea_data_t */

static int mipc_threedm_poll_nmea_data_read(mipc_reader_t *r, mipc_threedm_poll_nmea_data_t *out) {
    size_t i;
    mipc_rd_push(r, "suppress_ack");
    if (mipc_rd_bool(r, &out->suppress_ack)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "count");
    if (mipc_rd_u8(r, &out->count)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "format_entries");
    if (out->count > 50) {
        return mipc_rd_count_error(r, (uint64_t)out->count, 50);
    }
    for (i = 0; i < (size_t)out->count; i++) {
        mipc_rd_index(r, i);
        if (mipc_nmea_message_read(r, &out->format_entries[i])) {
            return -1;
        }
    }
    mipc_rd_pop(r);
    return mipc_rd_finish(r);
}

static mipc_status_t mipc_threedm_poll_nmea_data_write(mipc_writer_t *w,
                                                       const mipc_threedm_poll_nmea_data_t *in) {
    mipc_status_t st;
    size_t i;
    if ((st = mipc_wr_bool(w, &in->suppress_ack)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u8(w, &in->count)) != MIPC_OK) {
        return st;
    }
    if (in->count > 50) {
        return MIPC_ERR_INVALID;
    }
    for (i = 0; i < (size_t)in->count; i++) {
        if ((st = mipc_nmea_message_write(w, &in->format_entries[i])) != MIPC_OK) {
            return st;
        }
    }
    return MIPC_OK;
}

mipc_status_t mipc_threedm_poll_nmea_data_encode(const mipc_threedm_poll_nmea_data_t *value, uint8_t *buf,
                                                 size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    mipc_writer_init(&w, buf, cap);
    st = mipc_threedm_poll_nmea_data_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mipc_status_t mipc_threedm_poll_nmea_data_decode(const uint8_t *data, size_t len,
                                                 mipc_threedm_poll_nmea_data_t *out,
                                                 mipc_decode_error_t *err) {
    mipc_reader_t r;
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_threedm_poll_nmea_data_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

void mipc_threedm_poll_nmea_data_to_json(mipc_jw_t *w, const mipc_threedm_poll_nmea_data_t *in) {
    int first = 1;
    size_t i;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "suppress_ack");
    mipc_jw_bool(w, &in->suppress_ack);
    mipc_jw_key(w, &first, "count");
    mipc_jw_u8(w, &in->count);
    mipc_jw_key(w, &first, "format_entries");
    mipc_jw_raw(w, "[", 1);
    for (i = 0; i < (size_t)in->count && i < 50; i++) {
        mipc_jw_sep(w, i);
        mipc_nmea_message_to_json(w, &in->format_entries[i]);
    }
    mipc_jw_raw(w, "]", 1);
    mipc_jw_raw(w, "}", 1);
}

int mipc_threedm_poll_nmea_data_from_json(mipc_jr_t *jr, size_t pos, mipc_threedm_poll_nmea_data_t *out) {
    static const char *const keys[] = {"suppress_ack", "count", "format_entries"};
    size_t vp = 0;
    int found;
    size_t i;
    size_t it = 0;
    size_t ep = 0;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 3)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "suppress_ack", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"suppress_ack\"");
    }
    {
        mipc_jr_push(jr, "suppress_ack");
        if (mipc_jr_bool(jr, vp, &out->suppress_ack)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "count", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"count\"");
    }
    {
        mipc_jr_push(jr, "count");
        if (mipc_jr_u8(jr, vp, &out->count)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "format_entries", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"format_entries\"");
    }
    {
        mipc_jr_push(jr, "format_entries");
        if (mipc_jr_array(jr, vp, &it)) {
            return -1;
        }
        for (i = 0;; i++) {
            int more = mipc_jr_next(jr, &it, &ep);
            if (more < 0) {
                return -1;
            }
            if (!more) {
                break;
            }
            if (i >= 50) {
                return mipc_jr_fail(jr, "more than 50 elements");
            }
            mipc_jr_index(jr, i);
            if (mipc_nmea_message_from_json(jr, ep, &out->format_entries[i])) {
                return -1;
            }
        }
        mipc_jr_index(jr, SIZE_MAX);
        if (i != (size_t)out->count) {
            return mipc_jr_fail(jr, "%zu elements but count is %zu", i, (size_t)out->count);
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mipc_threedm_poll_data_t */

static int mipc_threedm_poll_data_read(mipc_reader_t *r, mipc_threedm_poll_data_t *out) {
    size_t i;
    mipc_rd_push(r, "desc_set");
    if (mipc_rd_u8(r, &out->desc_set)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "suppress_ack");
    if (mipc_rd_bool(r, &out->suppress_ack)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "num_descriptors");
    if (mipc_rd_u8(r, &out->num_descriptors)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "descriptors");
    if (out->num_descriptors > 250) {
        return mipc_rd_count_error(r, (uint64_t)out->num_descriptors, 250);
    }
    for (i = 0; i < (size_t)out->num_descriptors; i++) {
        mipc_rd_index(r, i);
        if (mipc_rd_u8(r, &out->descriptors[i])) {
            return -1;
        }
    }
    mipc_rd_pop(r);
    return mipc_rd_finish(r);
}

static mipc_status_t mipc_threedm_poll_data_write(mipc_writer_t *w, const mipc_threedm_poll_data_t *in) {
    mipc_status_t st;
    size_t i;
    if ((st = mipc_wr_u8(w, &in->desc_set)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_bool(w, &in->suppress_ack)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u8(w, &in->num_descriptors)) != MIPC_OK) {
        return st;
    }
    if (in->num_descriptors > 250) {
        return MIPC_ERR_INVALID;
    }
    for (i = 0; i < (size_t)in->num_descriptors; i++) {
        if ((st = mipc_wr_u8(w, &in->descriptors[i])) != MIPC_OK) {
            return st;
        }
    }
    return MIPC_OK;
}

mipc_status_t mipc_threedm_poll_data_encode(const mipc_threedm_poll_data_t *value, uint8_t *buf, size_t cap,
                                            size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    mipc_writer_init(&w, buf, cap);
    st = mipc_threedm_poll_data_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mipc_status_t mipc_threedm_poll_data_decode(const uint8_t *data, size_t len, mipc_threedm_poll_data_t *out,
                                            mipc_decode_error_t *err) {
    mipc_reader_t r;
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_threedm_poll_data_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

void mipc_threedm_poll_data_to_json(mipc_jw_t *w, const mipc_threedm_poll_data_t *in) {
    int first = 1;
    size_t i;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "desc_set");
    mipc_jw_u8(w, &in->desc_set);
    mipc_jw_key(w, &first, "suppress_ack");
    mipc_jw_bool(w, &in->suppress_ack);
    mipc_jw_key(w, &first, "num_descriptors");
    mipc_jw_u8(w, &in->num_descriptors);
    mipc_jw_key(w, &first, "descriptors");
    mipc_jw_raw(w, "[", 1);
    for (i = 0; i < (size_t)in->num_descriptors && i < 250; i++) {
        mipc_jw_sep(w, i);
        mipc_jw_u8(w, &in->descriptors[i]);
    }
    mipc_jw_raw(w, "]", 1);
    mipc_jw_raw(w, "}", 1);
}

int mipc_threedm_poll_data_from_json(mipc_jr_t *jr, size_t pos, mipc_threedm_poll_data_t *out) {
    static const char *const keys[] = {"desc_set", "suppress_ack", "num_descriptors", "descriptors"};
    size_t vp = 0;
    int found;
    size_t i;
    size_t it = 0;
    size_t ep = 0;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 4)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "desc_set", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"desc_set\"");
    }
    {
        mipc_jr_push(jr, "desc_set");
        if (mipc_jr_u8(jr, vp, &out->desc_set)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "suppress_ack", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"suppress_ack\"");
    }
    {
        mipc_jr_push(jr, "suppress_ack");
        if (mipc_jr_bool(jr, vp, &out->suppress_ack)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "num_descriptors", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"num_descriptors\"");
    }
    {
        mipc_jr_push(jr, "num_descriptors");
        if (mipc_jr_u8(jr, vp, &out->num_descriptors)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "descriptors", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"descriptors\"");
    }
    {
        mipc_jr_push(jr, "descriptors");
        if (mipc_jr_array(jr, vp, &it)) {
            return -1;
        }
        for (i = 0;; i++) {
            int more = mipc_jr_next(jr, &it, &ep);
            if (more < 0) {
                return -1;
            }
            if (!more) {
                break;
            }
            if (i >= 250) {
                return mipc_jr_fail(jr, "more than 250 elements");
            }
            mipc_jr_index(jr, i);
            if (mipc_jr_u8(jr, ep, &out->descriptors[i])) {
                return -1;
            }
        }
        mipc_jr_index(jr, SIZE_MAX);
        if (i != (size_t)out->num_descriptors) {
            return mipc_jr_fail(jr, "%zu elements but num_descriptors is %zu", i,
                                (size_t)out->num_descriptors);
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mipc_threedm_get_imu_base_rate_t */

static int mipc_threedm_get_imu_base_rate_read(mipc_reader_t *r, mipc_threedm_get_imu_base_rate_t *out) {
    (void)out;
    return mipc_rd_finish(r);
}

static mipc_status_t mipc_threedm_get_imu_base_rate_write(mipc_writer_t *w,
                                                          const mipc_threedm_get_imu_base_rate_t *in) {
    (void)w;
    (void)in;
    return MIPC_OK;
}

mipc_status_t mipc_threedm_get_imu_base_rate_encode(const mipc_threedm_get_imu_base_rate_t *value,
                                                    uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    mipc_writer_init(&w, buf, cap);
    st = mipc_threedm_get_imu_base_rate_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mipc_status_t mipc_threedm_get_imu_base_rate_decode(const uint8_t *data, size_t len,
                                                    mipc_threedm_get_imu_base_rate_t *out,
                                                    mipc_decode_error_t *err) {
    mipc_reader_t r;
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_threedm_get_imu_base_rate_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

void mipc_threedm_get_imu_base_rate_to_json(mipc_jw_t *w, const mipc_threedm_get_imu_base_rate_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_raw(w, "}", 1);
    (void)in;
    (void)first;
}

int mipc_threedm_get_imu_base_rate_from_json(mipc_jr_t *jr, size_t pos,
                                             mipc_threedm_get_imu_base_rate_t *out) {
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, NULL, 0)) {
        return -1;
    }
    return 0;
}

/* ---- mipc_threedm_imu_base_rate_t */

static int mipc_threedm_imu_base_rate_read(mipc_reader_t *r, mipc_threedm_imu_base_rate_t *out) {
    mipc_rd_push(r, "rate");
    if (mipc_rd_u16(r, &out->rate)) {
        return -1;
    }
    mipc_rd_pop(r);
    return mipc_rd_finish(r);
}

static mipc_status_t mipc_threedm_imu_base_rate_write(mipc_writer_t *w,
                                                      const mipc_threedm_imu_base_rate_t *in) {
    mipc_status_t st;
    if ((st = mipc_wr_u16(w, &in->rate)) != MIPC_OK) {
        return st;
    }
    return MIPC_OK;
}

mipc_status_t mipc_threedm_imu_base_rate_encode(const mipc_threedm_imu_base_rate_t *value, uint8_t *buf,
                                                size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    mipc_writer_init(&w, buf, cap);
    st = mipc_threedm_imu_base_rate_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 2 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mipc_threedm_imu_base_rate_load(const uint8_t *d, mipc_threedm_imu_base_rate_t *out) {
    out->rate = mipc_ld_u16(d + 0);
    return 0;
}

/* The general reader: lengths other than 2, bad bool bytes, error details. */
static MIPC_NOINLINE mipc_status_t mipc_threedm_imu_base_rate_decode_read(const uint8_t *data, size_t len,
                                                                          mipc_threedm_imu_base_rate_t *out,
                                                                          mipc_decode_error_t *err) {
    mipc_reader_t r;
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_threedm_imu_base_rate_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t mipc_threedm_imu_base_rate_decode(const uint8_t *data, size_t len,
                                                mipc_threedm_imu_base_rate_t *out, mipc_decode_error_t *err) {
    if (len == 2 && mipc_threedm_imu_base_rate_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_threedm_imu_base_rate_decode_read(data, len, out, err);
}

void mipc_threedm_imu_base_rate_to_json(mipc_jw_t *w, const mipc_threedm_imu_base_rate_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "rate");
    mipc_jw_u16(w, &in->rate);
    mipc_jw_raw(w, "}", 1);
}

int mipc_threedm_imu_base_rate_from_json(mipc_jr_t *jr, size_t pos, mipc_threedm_imu_base_rate_t *out) {
    static const char *const keys[] = {"rate"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 1)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "rate", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"rate\"");
    }
    {
        mipc_jr_push(jr, "rate");
        if (mipc_jr_u16(jr, vp, &out->rate)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mipc_threedm_get_gnss_base_rate_t */

static int mipc_threedm_get_gnss_base_rate_read(mipc_reader_t *r, mipc_threedm_get_gnss_base_rate_t *out) {
    (void)out;
    return mipc_rd_finish(r);
}

static mipc_status_t mipc_threedm_get_gnss_base_rate_write(mipc_writer_t *w,
                                                           const mipc_threedm_get_gnss_base_rate_t *in) {
    (void)w;
    (void)in;
    return MIPC_OK;
}

mipc_status_t mipc_threedm_get_gnss_base_rate_encode(const mipc_threedm_get_gnss_base_rate_t *value,
                                                     uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    mipc_writer_init(&w, buf, cap);
    st = mipc_threedm_get_gnss_base_rate_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mipc_status_t mipc_threedm_get_gnss_base_rate_decode(const uint8_t *data, size_t len,
                                                     mipc_threedm_get_gnss_base_rate_t *out,
                                                     mipc_decode_error_t *err) {
    mipc_reader_t r;
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_threedm_get_gnss_base_rate_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

void mipc_threedm_get_gnss_base_rate_to_json(mipc_jw_t *w, const mipc_threedm_get_gnss_base_rate_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_raw(w, "}", 1);
    (void)in;
    (void)first;
}

int mipc_threedm_get_gnss_base_rate_from_json(mipc_jr_t *jr, size_t pos,
                                              mipc_threedm_get_gnss_base_rate_t *out) {
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, NULL, 0)) {
        return -1;
    }
    return 0;
}

/* ---- mipc_threedm_gnss_base_rate_t */

static int mipc_threedm_gnss_base_rate_read(mipc_reader_t *r, mipc_threedm_gnss_base_rate_t *out) {
    mipc_rd_push(r, "rate");
    if (mipc_rd_u16(r, &out->rate)) {
        return -1;
    }
    mipc_rd_pop(r);
    return mipc_rd_finish(r);
}

static mipc_status_t mipc_threedm_gnss_base_rate_write(mipc_writer_t *w,
                                                       const mipc_threedm_gnss_base_rate_t *in) {
    mipc_status_t st;
    if ((st = mipc_wr_u16(w, &in->rate)) != MIPC_OK) {
        return st;
    }
    return MIPC_OK;
}

mipc_status_t mipc_threedm_gnss_base_rate_encode(const mipc_threedm_gnss_base_rate_t *value, uint8_t *buf,
                                                 size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    mipc_writer_init(&w, buf, cap);
    st = mipc_threedm_gnss_base_rate_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 2 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mipc_threedm_gnss_base_rate_load(const uint8_t *d, mipc_threedm_gnss_base_rate_t *out) {
    out->rate = mipc_ld_u16(d + 0);
    return 0;
}

/* The general reader: lengths other than 2, bad bool bytes, error details. */
static MIPC_NOINLINE mipc_status_t mipc_threedm_gnss_base_rate_decode_read(const uint8_t *data, size_t len,
                                                                           mipc_threedm_gnss_base_rate_t *out,
                                                                           mipc_decode_error_t *err) {
    mipc_reader_t r;
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_threedm_gnss_base_rate_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t mipc_threedm_gnss_base_rate_decode(const uint8_t *data, size_t len,
                                                 mipc_threedm_gnss_base_rate_t *out,
                                                 mipc_decode_error_t *err) {
    if (len == 2 && mipc_threedm_gnss_base_rate_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_threedm_gnss_base_rate_decode_read(data, len, out, err);
}

void mipc_threedm_gnss_base_rate_to_json(mipc_jw_t *w, const mipc_threedm_gnss_base_rate_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "rate");
    mipc_jw_u16(w, &in->rate);
    mipc_jw_raw(w, "}", 1);
}

int mipc_threedm_gnss_base_rate_from_json(mipc_jr_t *jr, size_t pos, mipc_threedm_gnss_base_rate_t *out) {
    static const char *const keys[] = {"rate"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 1)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "rate", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"rate\"");
    }
    {
        mipc_jr_push(jr, "rate");
        if (mipc_jr_u16(jr, vp, &out->rate)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mipc_threedm_get_filter_base_rate_t */

static int mipc_threedm_get_filter_base_rate_read(mipc_reader_t *r,
                                                  mipc_threedm_get_filter_base_rate_t *out) {
    (void)out;
    return mipc_rd_finish(r);
}

static mipc_status_t mipc_threedm_get_filter_base_rate_write(mipc_writer_t *w,
                                                             const mipc_threedm_get_filter_base_rate_t *in) {
    (void)w;
    (void)in;
    return MIPC_OK;
}

mipc_status_t mipc_threedm_get_filter_base_rate_encode(const mipc_threedm_get_filter_base_rate_t *value,
                                                       uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    mipc_writer_init(&w, buf, cap);
    st = mipc_threedm_get_filter_base_rate_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mipc_status_t mipc_threedm_get_filter_base_rate_decode(const uint8_t *data, size_t len,
                                                       mipc_threedm_get_filter_base_rate_t *out,
                                                       mipc_decode_error_t *err) {
    mipc_reader_t r;
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_threedm_get_filter_base_rate_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

void mipc_threedm_get_filter_base_rate_to_json(mipc_jw_t *w, const mipc_threedm_get_filter_base_rate_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_raw(w, "}", 1);
    (void)in;
    (void)first;
}

int mipc_threedm_get_filter_base_rate_from_json(mipc_jr_t *jr, size_t pos,
                                                mipc_threedm_get_filter_base_rate_t *out) {
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, NULL, 0)) {
        return -1;
    }
    return 0;
}

/* ---- mipc_threedm_filter_base_rate_t */

static int mipc_threedm_filter_base_rate_read(mipc_reader_t *r, mipc_threedm_filter_base_rate_t *out) {
    mipc_rd_push(r, "rate");
    if (mipc_rd_u16(r, &out->rate)) {
        return -1;
    }
    mipc_rd_pop(r);
    return mipc_rd_finish(r);
}

static mipc_status_t mipc_threedm_filter_base_rate_write(mipc_writer_t *w,
                                                         const mipc_threedm_filter_base_rate_t *in) {
    mipc_status_t st;
    if ((st = mipc_wr_u16(w, &in->rate)) != MIPC_OK) {
        return st;
    }
    return MIPC_OK;
}

mipc_status_t mipc_threedm_filter_base_rate_encode(const mipc_threedm_filter_base_rate_t *value, uint8_t *buf,
                                                   size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    mipc_writer_init(&w, buf, cap);
    st = mipc_threedm_filter_base_rate_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 2 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mipc_threedm_filter_base_rate_load(const uint8_t *d, mipc_threedm_filter_base_rate_t *out) {
    out->rate = mipc_ld_u16(d + 0);
    return 0;
}

/* The general reader: lengths other than 2, bad bool bytes, error details. */
static MIPC_NOINLINE mipc_status_t mipc_threedm_filter_base_rate_decode_read(
    const uint8_t *data, size_t len, mipc_threedm_filter_base_rate_t *out, mipc_decode_error_t *err) {
    mipc_reader_t r;
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_threedm_filter_base_rate_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t mipc_threedm_filter_base_rate_decode(const uint8_t *data, size_t len,
                                                   mipc_threedm_filter_base_rate_t *out,
                                                   mipc_decode_error_t *err) {
    if (len == 2 && mipc_threedm_filter_base_rate_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_threedm_filter_base_rate_decode_read(data, len, out, err);
}

void mipc_threedm_filter_base_rate_to_json(mipc_jw_t *w, const mipc_threedm_filter_base_rate_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "rate");
    mipc_jw_u16(w, &in->rate);
    mipc_jw_raw(w, "}", 1);
}

int mipc_threedm_filter_base_rate_from_json(mipc_jr_t *jr, size_t pos, mipc_threedm_filter_base_rate_t *out) {
    static const char *const keys[] = {"rate"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 1)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "rate", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"rate\"");
    }
    {
        mipc_jr_push(jr, "rate");
        if (mipc_jr_u16(jr, vp, &out->rate)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mipc_threedm_get_base_rate_t */

static int mipc_threedm_get_base_rate_read(mipc_reader_t *r, mipc_threedm_get_base_rate_t *out) {
    mipc_rd_push(r, "desc_set");
    if (mipc_rd_u8(r, &out->desc_set)) {
        return -1;
    }
    mipc_rd_pop(r);
    return mipc_rd_finish(r);
}

static mipc_status_t mipc_threedm_get_base_rate_write(mipc_writer_t *w,
                                                      const mipc_threedm_get_base_rate_t *in) {
    mipc_status_t st;
    if ((st = mipc_wr_u8(w, &in->desc_set)) != MIPC_OK) {
        return st;
    }
    return MIPC_OK;
}

mipc_status_t mipc_threedm_get_base_rate_encode(const mipc_threedm_get_base_rate_t *value, uint8_t *buf,
                                                size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    mipc_writer_init(&w, buf, cap);
    st = mipc_threedm_get_base_rate_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 1 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mipc_threedm_get_base_rate_load(const uint8_t *d, mipc_threedm_get_base_rate_t *out) {
    out->desc_set = mipc_ld_u8(d + 0);
    return 0;
}

/* The general reader: lengths other than 1, bad bool bytes, error details. */
static MIPC_NOINLINE mipc_status_t mipc_threedm_get_base_rate_decode_read(const uint8_t *data, size_t len,
                                                                          mipc_threedm_get_base_rate_t *out,
                                                                          mipc_decode_error_t *err) {
    mipc_reader_t r;
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_threedm_get_base_rate_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t mipc_threedm_get_base_rate_decode(const uint8_t *data, size_t len,
                                                mipc_threedm_get_base_rate_t *out, mipc_decode_error_t *err) {
    if (len == 1 && mipc_threedm_get_base_rate_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_threedm_get_base_rate_decode_read(data, len, out, err);
}

void mipc_threedm_get_base_rate_to_json(mipc_jw_t *w, const mipc_threedm_get_base_rate_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "desc_set");
    mipc_jw_u8(w, &in->desc_set);
    mipc_jw_raw(w, "}", 1);
}

int mipc_threedm_get_base_rate_from_json(mipc_jr_t *jr, size_t pos, mipc_threedm_get_base_rate_t *out) {
    static const char *const keys[] = {"desc_set"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 1)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "desc_set", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"desc_set\"");
    }
    {
        mipc_jr_push(jr, "desc_set");
        if (mipc_jr_u8(jr, vp, &out->desc_set)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mipc_threedm_base_rate_t */

static int mipc_threedm_base_rate_read(mipc_reader_t *r, mipc_threedm_base_rate_t *out) {
    mipc_rd_push(r, "desc_set");
    if (mipc_rd_u8(r, &out->desc_set)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "rate");
    if (mipc_rd_u16(r, &out->rate)) {
        return -1;
    }
    mipc_rd_pop(r);
    return mipc_rd_finish(r);
}

static mipc_status_t mipc_threedm_base_rate_write(mipc_writer_t *w, const mipc_threedm_base_rate_t *in) {
    mipc_status_t st;
    if ((st = mipc_wr_u8(w, &in->desc_set)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u16(w, &in->rate)) != MIPC_OK) {
        return st;
    }
    return MIPC_OK;
}

mipc_status_t mipc_threedm_base_rate_encode(const mipc_threedm_base_rate_t *value, uint8_t *buf, size_t cap,
                                            size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    mipc_writer_init(&w, buf, cap);
    st = mipc_threedm_base_rate_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 3 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mipc_threedm_base_rate_load(const uint8_t *d, mipc_threedm_base_rate_t *out) {
    out->desc_set = mipc_ld_u8(d + 0);
    out->rate = mipc_ld_u16(d + 1);
    return 0;
}

/* The general reader: lengths other than 3, bad bool bytes, error details. */
static MIPC_NOINLINE mipc_status_t mipc_threedm_base_rate_decode_read(const uint8_t *data, size_t len,
                                                                      mipc_threedm_base_rate_t *out,
                                                                      mipc_decode_error_t *err) {
    mipc_reader_t r;
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_threedm_base_rate_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t mipc_threedm_base_rate_decode(const uint8_t *data, size_t len, mipc_threedm_base_rate_t *out,
                                            mipc_decode_error_t *err) {
    if (len == 3 && mipc_threedm_base_rate_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_threedm_base_rate_decode_read(data, len, out, err);
}

void mipc_threedm_base_rate_to_json(mipc_jw_t *w, const mipc_threedm_base_rate_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "desc_set");
    mipc_jw_u8(w, &in->desc_set);
    mipc_jw_key(w, &first, "rate");
    mipc_jw_u16(w, &in->rate);
    mipc_jw_raw(w, "}", 1);
}

int mipc_threedm_base_rate_from_json(mipc_jr_t *jr, size_t pos, mipc_threedm_base_rate_t *out) {
    static const char *const keys[] = {"desc_set", "rate"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 2)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "desc_set", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"desc_set\"");
    }
    {
        mipc_jr_push(jr, "desc_set");
        if (mipc_jr_u8(jr, vp, &out->desc_set)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "rate", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"rate\"");
    }
    {
        mipc_jr_push(jr, "rate");
        if (mipc_jr_u16(jr, vp, &out->rate)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mipc_threedm_imu_message_format_t */

static int mipc_threedm_imu_message_format_read(mipc_reader_t *r, mipc_threedm_imu_message_format_t *out) {
    size_t i;
    mipc_rd_push(r, "function");
    if (mipc_rd_u8(r, &out->function)) {
        return -1;
    }
    mipc_rd_pop(r);
    if (r->pos < r->len) {
        out->has_num_descriptors = true;
        mipc_rd_push(r, "num_descriptors");
        if (mipc_rd_u8(r, &out->num_descriptors)) {
            return -1;
        }
        mipc_rd_pop(r);
    }
    if (r->pos < r->len) {
        out->has_descriptors = true;
        mipc_rd_push(r, "descriptors");
        if (out->num_descriptors > 83) {
            return mipc_rd_count_error(r, (uint64_t)out->num_descriptors, 83);
        }
        for (i = 0; i < (size_t)out->num_descriptors; i++) {
            mipc_rd_index(r, i);
            if (mipc_descriptor_rate_read(r, &out->descriptors[i])) {
                return -1;
            }
        }
        mipc_rd_pop(r);
    }
    return mipc_rd_finish(r);
}

static mipc_status_t mipc_threedm_imu_message_format_write(mipc_writer_t *w,
                                                           const mipc_threedm_imu_message_format_t *in) {
    mipc_status_t st;
    size_t i;
    int absent = 0;
    if ((st = mipc_wr_u8(w, &in->function)) != MIPC_OK) {
        return st;
    }
    if (!in->has_num_descriptors) {
        absent = 1;
    } else if (absent) {
        return MIPC_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = mipc_wr_u8(w, &in->num_descriptors)) != MIPC_OK) {
            return st;
        }
    }
    if (!in->has_descriptors) {
        absent = 1;
    } else if (absent) {
        return MIPC_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if (in->num_descriptors > 83) {
            return MIPC_ERR_INVALID;
        }
        for (i = 0; i < (size_t)in->num_descriptors; i++) {
            if ((st = mipc_descriptor_rate_write(w, &in->descriptors[i])) != MIPC_OK) {
                return st;
            }
        }
    }
    return MIPC_OK;
}

mipc_status_t mipc_threedm_imu_message_format_encode(const mipc_threedm_imu_message_format_t *value,
                                                     uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    mipc_writer_init(&w, buf, cap);
    st = mipc_threedm_imu_message_format_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mipc_status_t mipc_threedm_imu_message_format_decode(const uint8_t *data, size_t len,
                                                     mipc_threedm_imu_message_format_t *out,
                                                     mipc_decode_error_t *err) {
    mipc_reader_t r;
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_threedm_imu_message_format_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

void mipc_threedm_imu_message_format_to_json(mipc_jw_t *w, const mipc_threedm_imu_message_format_t *in) {
    int first = 1;
    size_t i;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "function");
    mipc_jw_u8(w, &in->function);
    if (in->has_num_descriptors) {
        mipc_jw_key(w, &first, "num_descriptors");
        mipc_jw_u8(w, &in->num_descriptors);
    }
    if (in->has_descriptors) {
        mipc_jw_key(w, &first, "descriptors");
        mipc_jw_raw(w, "[", 1);
        for (i = 0; i < (size_t)in->num_descriptors && i < 83; i++) {
            mipc_jw_sep(w, i);
            mipc_descriptor_rate_to_json(w, &in->descriptors[i]);
        }
        mipc_jw_raw(w, "]", 1);
    }
    mipc_jw_raw(w, "}", 1);
}

int mipc_threedm_imu_message_format_from_json(mipc_jr_t *jr, size_t pos,
                                              mipc_threedm_imu_message_format_t *out) {
    static const char *const keys[] = {"function", "num_descriptors", "descriptors"};
    size_t vp = 0;
    int found;
    int absent = 0;
    size_t i;
    size_t it = 0;
    size_t ep = 0;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 3)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "function", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"function\"");
    }
    {
        mipc_jr_push(jr, "function");
        if (mipc_jr_u8(jr, vp, &out->function)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "num_descriptors", &vp);
    out->has_num_descriptors = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mipc_jr_fail(jr, "optional parameter \"num_descriptors\" given after an absent one");
    } else {
        mipc_jr_push(jr, "num_descriptors");
        if (mipc_jr_u8(jr, vp, &out->num_descriptors)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "descriptors", &vp);
    out->has_descriptors = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mipc_jr_fail(jr, "optional parameter \"descriptors\" given after an absent one");
    } else {
        mipc_jr_push(jr, "descriptors");
        if (mipc_jr_array(jr, vp, &it)) {
            return -1;
        }
        for (i = 0;; i++) {
            int more = mipc_jr_next(jr, &it, &ep);
            if (more < 0) {
                return -1;
            }
            if (!more) {
                break;
            }
            if (i >= 83) {
                return mipc_jr_fail(jr, "more than 83 elements");
            }
            mipc_jr_index(jr, i);
            if (mipc_descriptor_rate_from_json(jr, ep, &out->descriptors[i])) {
                return -1;
            }
        }
        mipc_jr_index(jr, SIZE_MAX);
        if (i != (size_t)out->num_descriptors) {
            return mipc_jr_fail(jr, "%zu elements but num_descriptors is %zu", i,
                                (size_t)out->num_descriptors);
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mipc_threedm_imu_message_format_response_t */

static int mipc_threedm_imu_message_format_response_read(mipc_reader_t *r,
                                                         mipc_threedm_imu_message_format_response_t *out) {
    size_t i;
    mipc_rd_push(r, "num_descriptors");
    if (mipc_rd_u8(r, &out->num_descriptors)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "descriptors");
    if (out->num_descriptors > 84) {
        return mipc_rd_count_error(r, (uint64_t)out->num_descriptors, 84);
    }
    for (i = 0; i < (size_t)out->num_descriptors; i++) {
        mipc_rd_index(r, i);
        if (mipc_descriptor_rate_read(r, &out->descriptors[i])) {
            return -1;
        }
    }
    mipc_rd_pop(r);
    return mipc_rd_finish(r);
}

static mipc_status_t
mipc_threedm_imu_message_format_response_write(mipc_writer_t *w,
                                               const mipc_threedm_imu_message_format_response_t *in) {
    mipc_status_t st;
    size_t i;
    if ((st = mipc_wr_u8(w, &in->num_descriptors)) != MIPC_OK) {
        return st;
    }
    if (in->num_descriptors > 84) {
        return MIPC_ERR_INVALID;
    }
    for (i = 0; i < (size_t)in->num_descriptors; i++) {
        if ((st = mipc_descriptor_rate_write(w, &in->descriptors[i])) != MIPC_OK) {
            return st;
        }
    }
    return MIPC_OK;
}

mipc_status_t
mipc_threedm_imu_message_format_response_encode(const mipc_threedm_imu_message_format_response_t *value,
                                                uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    mipc_writer_init(&w, buf, cap);
    st = mipc_threedm_imu_message_format_response_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mipc_status_t mipc_threedm_imu_message_format_response_decode(const uint8_t *data, size_t len,
                                                              mipc_threedm_imu_message_format_response_t *out,
                                                              mipc_decode_error_t *err) {
    mipc_reader_t r;
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_threedm_imu_message_format_response_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

void mipc_threedm_imu_message_format_response_to_json(mipc_jw_t *w,
                                                      const mipc_threedm_imu_message_format_response_t *in) {
    int first = 1;
    size_t i;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "num_descriptors");
    mipc_jw_u8(w, &in->num_descriptors);
    mipc_jw_key(w, &first, "descriptors");
    mipc_jw_raw(w, "[", 1);
    for (i = 0; i < (size_t)in->num_descriptors && i < 84; i++) {
        mipc_jw_sep(w, i);
        mipc_descriptor_rate_to_json(w, &in->descriptors[i]);
    }
    mipc_jw_raw(w, "]", 1);
    mipc_jw_raw(w, "}", 1);
}

int mipc_threedm_imu_message_format_response_from_json(mipc_jr_t *jr, size_t pos,
                                                       mipc_threedm_imu_message_format_response_t *out) {
    static const char *const keys[] = {"num_descriptors", "descriptors"};
    size_t vp = 0;
    int found;
    size_t i;
    size_t it = 0;
    size_t ep = 0;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 2)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "num_descriptors", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"num_descriptors\"");
    }
    {
        mipc_jr_push(jr, "num_descriptors");
        if (mipc_jr_u8(jr, vp, &out->num_descriptors)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "descriptors", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"descriptors\"");
    }
    {
        mipc_jr_push(jr, "descriptors");
        if (mipc_jr_array(jr, vp, &it)) {
            return -1;
        }
        for (i = 0;; i++) {
            int more = mipc_jr_next(jr, &it, &ep);
            if (more < 0) {
                return -1;
            }
            if (!more) {
                break;
            }
            if (i >= 84) {
                return mipc_jr_fail(jr, "more than 84 elements");
            }
            mipc_jr_index(jr, i);
            if (mipc_descriptor_rate_from_json(jr, ep, &out->descriptors[i])) {
                return -1;
            }
        }
        mipc_jr_index(jr, SIZE_MAX);
        if (i != (size_t)out->num_descriptors) {
            return mipc_jr_fail(jr, "%zu elements but num_descriptors is %zu", i,
                                (size_t)out->num_descriptors);
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mipc_threedm_gnss_message_format_t */

static int mipc_threedm_gnss_message_format_read(mipc_reader_t *r, mipc_threedm_gnss_message_format_t *out) {
    size_t i;
    mipc_rd_push(r, "function");
    if (mipc_rd_u8(r, &out->function)) {
        return -1;
    }
    mipc_rd_pop(r);
    if (r->pos < r->len) {
        out->has_num_descriptors = true;
        mipc_rd_push(r, "num_descriptors");
        if (mipc_rd_u8(r, &out->num_descriptors)) {
            return -1;
        }
        mipc_rd_pop(r);
    }
    if (r->pos < r->len) {
        out->has_descriptors = true;
        mipc_rd_push(r, "descriptors");
        if (out->num_descriptors > 83) {
            return mipc_rd_count_error(r, (uint64_t)out->num_descriptors, 83);
        }
        for (i = 0; i < (size_t)out->num_descriptors; i++) {
            mipc_rd_index(r, i);
            if (mipc_descriptor_rate_read(r, &out->descriptors[i])) {
                return -1;
            }
        }
        mipc_rd_pop(r);
    }
    return mipc_rd_finish(r);
}

static mipc_status_t mipc_threedm_gnss_message_format_write(mipc_writer_t *w,
                                                            const mipc_threedm_gnss_message_format_t *in) {
    mipc_status_t st;
    size_t i;
    int absent = 0;
    if ((st = mipc_wr_u8(w, &in->function)) != MIPC_OK) {
        return st;
    }
    if (!in->has_num_descriptors) {
        absent = 1;
    } else if (absent) {
        return MIPC_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = mipc_wr_u8(w, &in->num_descriptors)) != MIPC_OK) {
            return st;
        }
    }
    if (!in->has_descriptors) {
        absent = 1;
    } else if (absent) {
        return MIPC_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if (in->num_descriptors > 83) {
            return MIPC_ERR_INVALID;
        }
        for (i = 0; i < (size_t)in->num_descriptors; i++) {
            if ((st = mipc_descriptor_rate_write(w, &in->descriptors[i])) != MIPC_OK) {
                return st;
            }
        }
    }
    return MIPC_OK;
}

mipc_status_t mipc_threedm_gnss_message_format_encode(const mipc_threedm_gnss_message_format_t *value,
                                                      uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    mipc_writer_init(&w, buf, cap);
    st = mipc_threedm_gnss_message_format_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mipc_status_t mipc_threedm_gnss_message_format_decode(const uint8_t *data, size_t len,
                                                      mipc_threedm_gnss_message_format_t *out,
                                                      mipc_decode_error_t *err) {
    mipc_reader_t r;
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_threedm_gnss_message_format_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

void mipc_threedm_gnss_message_format_to_json(mipc_jw_t *w, const mipc_threedm_gnss_message_format_t *in) {
    int first = 1;
    size_t i;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "function");
    mipc_jw_u8(w, &in->function);
    if (in->has_num_descriptors) {
        mipc_jw_key(w, &first, "num_descriptors");
        mipc_jw_u8(w, &in->num_descriptors);
    }
    if (in->has_descriptors) {
        mipc_jw_key(w, &first, "descriptors");
        mipc_jw_raw(w, "[", 1);
        for (i = 0; i < (size_t)in->num_descriptors && i < 83; i++) {
            mipc_jw_sep(w, i);
            mipc_descriptor_rate_to_json(w, &in->descriptors[i]);
        }
        mipc_jw_raw(w, "]", 1);
    }
    mipc_jw_raw(w, "}", 1);
}

int mipc_threedm_gnss_message_format_from_json(mipc_jr_t *jr, size_t pos,
                                               mipc_threedm_gnss_message_format_t *out) {
    static const char *const keys[] = {"function", "num_descriptors", "descriptors"};
    size_t vp = 0;
    int found;
    int absent = 0;
    size_t i;
    size_t it = 0;
    size_t ep = 0;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 3)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "function", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"function\"");
    }
    {
        mipc_jr_push(jr, "function");
        if (mipc_jr_u8(jr, vp, &out->function)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "num_descriptors", &vp);
    out->has_num_descriptors = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mipc_jr_fail(jr, "optional parameter \"num_descriptors\" given after an absent one");
    } else {
        mipc_jr_push(jr, "num_descriptors");
        if (mipc_jr_u8(jr, vp, &out->num_descriptors)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "descriptors", &vp);
    out->has_descriptors = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mipc_jr_fail(jr, "optional parameter \"descriptors\" given after an absent one");
    } else {
        mipc_jr_push(jr, "descriptors");
        if (mipc_jr_array(jr, vp, &it)) {
            return -1;
        }
        for (i = 0;; i++) {
            int more = mipc_jr_next(jr, &it, &ep);
            if (more < 0) {
                return -1;
            }
            if (!more) {
                break;
            }
            if (i >= 83) {
                return mipc_jr_fail(jr, "more than 83 elements");
            }
            mipc_jr_index(jr, i);
            if (mipc_descriptor_rate_from_json(jr, ep, &out->descriptors[i])) {
                return -1;
            }
        }
        mipc_jr_index(jr, SIZE_MAX);
        if (i != (size_t)out->num_descriptors) {
            return mipc_jr_fail(jr, "%zu elements but num_descriptors is %zu", i,
                                (size_t)out->num_descriptors);
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mipc_threedm_gnss_message_format_response_t */

static int mipc_threedm_gnss_message_format_response_read(mipc_reader_t *r,
                                                          mipc_threedm_gnss_message_format_response_t *out) {
    size_t i;
    mipc_rd_push(r, "num_descriptors");
    if (mipc_rd_u8(r, &out->num_descriptors)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "descriptors");
    if (out->num_descriptors > 84) {
        return mipc_rd_count_error(r, (uint64_t)out->num_descriptors, 84);
    }
    for (i = 0; i < (size_t)out->num_descriptors; i++) {
        mipc_rd_index(r, i);
        if (mipc_descriptor_rate_read(r, &out->descriptors[i])) {
            return -1;
        }
    }
    mipc_rd_pop(r);
    return mipc_rd_finish(r);
}

static mipc_status_t
mipc_threedm_gnss_message_format_response_write(mipc_writer_t *w,
                                                const mipc_threedm_gnss_message_format_response_t *in) {
    mipc_status_t st;
    size_t i;
    if ((st = mipc_wr_u8(w, &in->num_descriptors)) != MIPC_OK) {
        return st;
    }
    if (in->num_descriptors > 84) {
        return MIPC_ERR_INVALID;
    }
    for (i = 0; i < (size_t)in->num_descriptors; i++) {
        if ((st = mipc_descriptor_rate_write(w, &in->descriptors[i])) != MIPC_OK) {
            return st;
        }
    }
    return MIPC_OK;
}

mipc_status_t
mipc_threedm_gnss_message_format_response_encode(const mipc_threedm_gnss_message_format_response_t *value,
                                                 uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    mipc_writer_init(&w, buf, cap);
    st = mipc_threedm_gnss_message_format_response_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mipc_status_t
mipc_threedm_gnss_message_format_response_decode(const uint8_t *data, size_t len,
                                                 mipc_threedm_gnss_message_format_response_t *out,
                                                 mipc_decode_error_t *err) {
    mipc_reader_t r;
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_threedm_gnss_message_format_response_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

void mipc_threedm_gnss_message_format_response_to_json(
    mipc_jw_t *w, const mipc_threedm_gnss_message_format_response_t *in) {
    int first = 1;
    size_t i;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "num_descriptors");
    mipc_jw_u8(w, &in->num_descriptors);
    mipc_jw_key(w, &first, "descriptors");
    mipc_jw_raw(w, "[", 1);
    for (i = 0; i < (size_t)in->num_descriptors && i < 84; i++) {
        mipc_jw_sep(w, i);
        mipc_descriptor_rate_to_json(w, &in->descriptors[i]);
    }
    mipc_jw_raw(w, "]", 1);
    mipc_jw_raw(w, "}", 1);
}

int mipc_threedm_gnss_message_format_response_from_json(mipc_jr_t *jr, size_t pos,
                                                        mipc_threedm_gnss_message_format_response_t *out) {
    static const char *const keys[] = {"num_descriptors", "descriptors"};
    size_t vp = 0;
    int found;
    size_t i;
    size_t it = 0;
    size_t ep = 0;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 2)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "num_descriptors", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"num_descriptors\"");
    }
    {
        mipc_jr_push(jr, "num_descriptors");
        if (mipc_jr_u8(jr, vp, &out->num_descriptors)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "descriptors", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"descriptors\"");
    }
    {
        mipc_jr_push(jr, "descriptors");
        if (mipc_jr_array(jr, vp, &it)) {
            return -1;
        }
        for (i = 0;; i++) {
            int more = mipc_jr_next(jr, &it, &ep);
            if (more < 0) {
                return -1;
            }
            if (!more) {
                break;
            }
            if (i >= 84) {
                return mipc_jr_fail(jr, "more than 84 elements");
            }
            mipc_jr_index(jr, i);
            if (mipc_descriptor_rate_from_json(jr, ep, &out->descriptors[i])) {
                return -1;
            }
        }
        mipc_jr_index(jr, SIZE_MAX);
        if (i != (size_t)out->num_descriptors) {
            return mipc_jr_fail(jr, "%zu elements but num_descriptors is %zu", i,
                                (size_t)out->num_descriptors);
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mipc_threedm_filter_message_format_t */

static int mipc_threedm_filter_message_format_read(mipc_reader_t *r,
                                                   mipc_threedm_filter_message_format_t *out) {
    size_t i;
    mipc_rd_push(r, "function");
    if (mipc_rd_u8(r, &out->function)) {
        return -1;
    }
    mipc_rd_pop(r);
    if (r->pos < r->len) {
        out->has_num_descriptors = true;
        mipc_rd_push(r, "num_descriptors");
        if (mipc_rd_u8(r, &out->num_descriptors)) {
            return -1;
        }
        mipc_rd_pop(r);
    }
    if (r->pos < r->len) {
        out->has_descriptors = true;
        mipc_rd_push(r, "descriptors");
        if (out->num_descriptors > 83) {
            return mipc_rd_count_error(r, (uint64_t)out->num_descriptors, 83);
        }
        for (i = 0; i < (size_t)out->num_descriptors; i++) {
            mipc_rd_index(r, i);
            if (mipc_descriptor_rate_read(r, &out->descriptors[i])) {
                return -1;
            }
        }
        mipc_rd_pop(r);
    }
    return mipc_rd_finish(r);
}

static mipc_status_t
mipc_threedm_filter_message_format_write(mipc_writer_t *w, const mipc_threedm_filter_message_format_t *in) {
    mipc_status_t st;
    size_t i;
    int absent = 0;
    if ((st = mipc_wr_u8(w, &in->function)) != MIPC_OK) {
        return st;
    }
    if (!in->has_num_descriptors) {
        absent = 1;
    } else if (absent) {
        return MIPC_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = mipc_wr_u8(w, &in->num_descriptors)) != MIPC_OK) {
            return st;
        }
    }
    if (!in->has_descriptors) {
        absent = 1;
    } else if (absent) {
        return MIPC_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if (in->num_descriptors > 83) {
            return MIPC_ERR_INVALID;
        }
        for (i = 0; i < (size_t)in->num_descriptors; i++) {
            if ((st = mipc_descriptor_rate_write(w, &in->descriptors[i])) != MIPC_OK) {
                return st;
            }
        }
    }
    return MIPC_OK;
}

mipc_status_t mipc_threedm_filter_message_format_encode(const mipc_threedm_filter_message_format_t *value,
                                                        uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    mipc_writer_init(&w, buf, cap);
    st = mipc_threedm_filter_message_format_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mipc_status_t mipc_threedm_filter_message_format_decode(const uint8_t *data, size_t len,
                                                        mipc_threedm_filter_message_format_t *out,
                                                        mipc_decode_error_t *err) {
    mipc_reader_t r;
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_threedm_filter_message_format_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

void mipc_threedm_filter_message_format_to_json(mipc_jw_t *w,
                                                const mipc_threedm_filter_message_format_t *in) {
    int first = 1;
    size_t i;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "function");
    mipc_jw_u8(w, &in->function);
    if (in->has_num_descriptors) {
        mipc_jw_key(w, &first, "num_descriptors");
        mipc_jw_u8(w, &in->num_descriptors);
    }
    if (in->has_descriptors) {
        mipc_jw_key(w, &first, "descriptors");
        mipc_jw_raw(w, "[", 1);
        for (i = 0; i < (size_t)in->num_descriptors && i < 83; i++) {
            mipc_jw_sep(w, i);
            mipc_descriptor_rate_to_json(w, &in->descriptors[i]);
        }
        mipc_jw_raw(w, "]", 1);
    }
    mipc_jw_raw(w, "}", 1);
}

int mipc_threedm_filter_message_format_from_json(mipc_jr_t *jr, size_t pos,
                                                 mipc_threedm_filter_message_format_t *out) {
    static const char *const keys[] = {"function", "num_descriptors", "descriptors"};
    size_t vp = 0;
    int found;
    int absent = 0;
    size_t i;
    size_t it = 0;
    size_t ep = 0;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 3)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "function", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"function\"");
    }
    {
        mipc_jr_push(jr, "function");
        if (mipc_jr_u8(jr, vp, &out->function)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "num_descriptors", &vp);
    out->has_num_descriptors = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mipc_jr_fail(jr, "optional parameter \"num_descriptors\" given after an absent one");
    } else {
        mipc_jr_push(jr, "num_descriptors");
        if (mipc_jr_u8(jr, vp, &out->num_descriptors)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "descriptors", &vp);
    out->has_descriptors = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mipc_jr_fail(jr, "optional parameter \"descriptors\" given after an absent one");
    } else {
        mipc_jr_push(jr, "descriptors");
        if (mipc_jr_array(jr, vp, &it)) {
            return -1;
        }
        for (i = 0;; i++) {
            int more = mipc_jr_next(jr, &it, &ep);
            if (more < 0) {
                return -1;
            }
            if (!more) {
                break;
            }
            if (i >= 83) {
                return mipc_jr_fail(jr, "more than 83 elements");
            }
            mipc_jr_index(jr, i);
            if (mipc_descriptor_rate_from_json(jr, ep, &out->descriptors[i])) {
                return -1;
            }
        }
        mipc_jr_index(jr, SIZE_MAX);
        if (i != (size_t)out->num_descriptors) {
            return mipc_jr_fail(jr, "%zu elements but num_descriptors is %zu", i,
                                (size_t)out->num_descriptors);
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mipc_threedm_filter_message_format_response_t */

static int
mipc_threedm_filter_message_format_response_read(mipc_reader_t *r,
                                                 mipc_threedm_filter_message_format_response_t *out) {
    size_t i;
    mipc_rd_push(r, "num_descriptors");
    if (mipc_rd_u8(r, &out->num_descriptors)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "descriptors");
    if (out->num_descriptors > 84) {
        return mipc_rd_count_error(r, (uint64_t)out->num_descriptors, 84);
    }
    for (i = 0; i < (size_t)out->num_descriptors; i++) {
        mipc_rd_index(r, i);
        if (mipc_descriptor_rate_read(r, &out->descriptors[i])) {
            return -1;
        }
    }
    mipc_rd_pop(r);
    return mipc_rd_finish(r);
}

static mipc_status_t
mipc_threedm_filter_message_format_response_write(mipc_writer_t *w,
                                                  const mipc_threedm_filter_message_format_response_t *in) {
    mipc_status_t st;
    size_t i;
    if ((st = mipc_wr_u8(w, &in->num_descriptors)) != MIPC_OK) {
        return st;
    }
    if (in->num_descriptors > 84) {
        return MIPC_ERR_INVALID;
    }
    for (i = 0; i < (size_t)in->num_descriptors; i++) {
        if ((st = mipc_descriptor_rate_write(w, &in->descriptors[i])) != MIPC_OK) {
            return st;
        }
    }
    return MIPC_OK;
}

mipc_status_t
mipc_threedm_filter_message_format_response_encode(const mipc_threedm_filter_message_format_response_t *value,
                                                   uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    mipc_writer_init(&w, buf, cap);
    st = mipc_threedm_filter_message_format_response_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mipc_status_t
mipc_threedm_filter_message_format_response_decode(const uint8_t *data, size_t len,
                                                   mipc_threedm_filter_message_format_response_t *out,
                                                   mipc_decode_error_t *err) {
    mipc_reader_t r;
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_threedm_filter_message_format_response_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

void mipc_threedm_filter_message_format_response_to_json(
    mipc_jw_t *w, const mipc_threedm_filter_message_format_response_t *in) {
    int first = 1;
    size_t i;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "num_descriptors");
    mipc_jw_u8(w, &in->num_descriptors);
    mipc_jw_key(w, &first, "descriptors");
    mipc_jw_raw(w, "[", 1);
    for (i = 0; i < (size_t)in->num_descriptors && i < 84; i++) {
        mipc_jw_sep(w, i);
        mipc_descriptor_rate_to_json(w, &in->descriptors[i]);
    }
    mipc_jw_raw(w, "]", 1);
    mipc_jw_raw(w, "}", 1);
}

int mipc_threedm_filter_message_format_response_from_json(
    mipc_jr_t *jr, size_t pos, mipc_threedm_filter_message_format_response_t *out) {
    static const char *const keys[] = {"num_descriptors", "descriptors"};
    size_t vp = 0;
    int found;
    size_t i;
    size_t it = 0;
    size_t ep = 0;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 2)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "num_descriptors", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"num_descriptors\"");
    }
    {
        mipc_jr_push(jr, "num_descriptors");
        if (mipc_jr_u8(jr, vp, &out->num_descriptors)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "descriptors", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"descriptors\"");
    }
    {
        mipc_jr_push(jr, "descriptors");
        if (mipc_jr_array(jr, vp, &it)) {
            return -1;
        }
        for (i = 0;; i++) {
            int more = mipc_jr_next(jr, &it, &ep);
            if (more < 0) {
                return -1;
            }
            if (!more) {
                break;
            }
            if (i >= 84) {
                return mipc_jr_fail(jr, "more than 84 elements");
            }
            mipc_jr_index(jr, i);
            if (mipc_descriptor_rate_from_json(jr, ep, &out->descriptors[i])) {
                return -1;
            }
        }
        mipc_jr_index(jr, SIZE_MAX);
        if (i != (size_t)out->num_descriptors) {
            return mipc_jr_fail(jr, "%zu elements but num_descriptors is %zu", i,
                                (size_t)out->num_descriptors);
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mipc_threedm_nmea_message_format_t */

static int mipc_threedm_nmea_message_format_read(mipc_reader_t *r, mipc_threedm_nmea_message_format_t *out) {
    size_t i;
    mipc_rd_push(r, "function");
    if (mipc_rd_u8(r, &out->function)) {
        return -1;
    }
    mipc_rd_pop(r);
    if (r->pos < r->len) {
        out->has_count = true;
        mipc_rd_push(r, "count");
        if (mipc_rd_u8(r, &out->count)) {
            return -1;
        }
        mipc_rd_pop(r);
    }
    if (r->pos < r->len) {
        out->has_format_entries = true;
        mipc_rd_push(r, "format_entries");
        if (out->count > 50) {
            return mipc_rd_count_error(r, (uint64_t)out->count, 50);
        }
        for (i = 0; i < (size_t)out->count; i++) {
            mipc_rd_index(r, i);
            if (mipc_nmea_message_read(r, &out->format_entries[i])) {
                return -1;
            }
        }
        mipc_rd_pop(r);
    }
    return mipc_rd_finish(r);
}

static mipc_status_t mipc_threedm_nmea_message_format_write(mipc_writer_t *w,
                                                            const mipc_threedm_nmea_message_format_t *in) {
    mipc_status_t st;
    size_t i;
    int absent = 0;
    if ((st = mipc_wr_u8(w, &in->function)) != MIPC_OK) {
        return st;
    }
    if (!in->has_count) {
        absent = 1;
    } else if (absent) {
        return MIPC_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = mipc_wr_u8(w, &in->count)) != MIPC_OK) {
            return st;
        }
    }
    if (!in->has_format_entries) {
        absent = 1;
    } else if (absent) {
        return MIPC_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if (in->count > 50) {
            return MIPC_ERR_INVALID;
        }
        for (i = 0; i < (size_t)in->count; i++) {
            if ((st = mipc_nmea_message_write(w, &in->format_entries[i])) != MIPC_OK) {
                return st;
            }
        }
    }
    return MIPC_OK;
}

mipc_status_t mipc_threedm_nmea_message_format_encode(const mipc_threedm_nmea_message_format_t *value,
                                                      uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    mipc_writer_init(&w, buf, cap);
    st = mipc_threedm_nmea_message_format_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mipc_status_t mipc_threedm_nmea_message_format_decode(const uint8_t *data, size_t len,
                                                      mipc_threedm_nmea_message_format_t *out,
                                                      mipc_decode_error_t *err) {
    mipc_reader_t r;
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_threedm_nmea_message_format_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

void mipc_threedm_nmea_message_format_to_json(mipc_jw_t *w, const mipc_threedm_nmea_message_format_t *in) {
    int first = 1;
    size_t i;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "function");
    mipc_jw_u8(w, &in->function);
    if (in->has_count) {
        mipc_jw_key(w, &first, "count");
        mipc_jw_u8(w, &in->count);
    }
    if (in->has_format_entries) {
        mipc_jw_key(w, &first, "format_entries");
        mipc_jw_raw(w, "[", 1);
        for (i = 0; i < (size_t)in->count && i < 50; i++) {
            mipc_jw_sep(w, i);
            mipc_nmea_message_to_json(w, &in->format_entries[i]);
        }
        mipc_jw_raw(w, "]", 1);
    }
    mipc_jw_raw(w, "}", 1);
}

int mipc_threedm_nmea_message_format_from_json(mipc_jr_t *jr, size_t pos,
                                               mipc_threedm_nmea_message_format_t *out) {
    static const char *const keys[] = {"function", "count", "format_entries"};
    size_t vp = 0;
    int found;
    int absent = 0;
    size_t i;
    size_t it = 0;
    size_t ep = 0;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 3)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "function", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"function\"");
    }
    {
        mipc_jr_push(jr, "function");
        if (mipc_jr_u8(jr, vp, &out->function)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "count", &vp);
    out->has_count = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mipc_jr_fail(jr, "optional parameter \"count\" given after an absent one");
    } else {
        mipc_jr_push(jr, "count");
        if (mipc_jr_u8(jr, vp, &out->count)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "format_entries", &vp);
    out->has_format_entries = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mipc_jr_fail(jr, "optional parameter \"format_entries\" given after an absent one");
    } else {
        mipc_jr_push(jr, "format_entries");
        if (mipc_jr_array(jr, vp, &it)) {
            return -1;
        }
        for (i = 0;; i++) {
            int more = mipc_jr_next(jr, &it, &ep);
            if (more < 0) {
                return -1;
            }
            if (!more) {
                break;
            }
            if (i >= 50) {
                return mipc_jr_fail(jr, "more than 50 elements");
            }
            mipc_jr_index(jr, i);
            if (mipc_nmea_message_from_json(jr, ep, &out->format_entries[i])) {
                return -1;
            }
        }
        mipc_jr_index(jr, SIZE_MAX);
        if (i != (size_t)out->count) {
            return mipc_jr_fail(jr, "%zu elements but count is %zu", i, (size_t)out->count);
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mipc_threedm_nmea_message_format_response_t */

static int mipc_threedm_nmea_message_format_response_read(mipc_reader_t *r,
                                                          mipc_threedm_nmea_message_format_response_t *out) {
    size_t i;
    mipc_rd_push(r, "count");
    if (mipc_rd_u8(r, &out->count)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "format_entries");
    if (out->count > 50) {
        return mipc_rd_count_error(r, (uint64_t)out->count, 50);
    }
    for (i = 0; i < (size_t)out->count; i++) {
        mipc_rd_index(r, i);
        if (mipc_nmea_message_read(r, &out->format_entries[i])) {
            return -1;
        }
    }
    mipc_rd_pop(r);
    return mipc_rd_finish(r);
}

static mipc_status_t
mipc_threedm_nmea_message_format_response_write(mipc_writer_t *w,
                                                const mipc_threedm_nmea_message_format_response_t *in) {
    mipc_status_t st;
    size_t i;
    if ((st = mipc_wr_u8(w, &in->count)) != MIPC_OK) {
        return st;
    }
    if (in->count > 50) {
        return MIPC_ERR_INVALID;
    }
    for (i = 0; i < (size_t)in->count; i++) {
        if ((st = mipc_nmea_message_write(w, &in->format_entries[i])) != MIPC_OK) {
            return st;
        }
    }
    return MIPC_OK;
}

mipc_status_t
mipc_threedm_nmea_message_format_response_encode(const mipc_threedm_nmea_message_format_response_t *value,
                                                 uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    mipc_writer_init(&w, buf, cap);
    st = mipc_threedm_nmea_message_format_response_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mipc_status_t
mipc_threedm_nmea_message_format_response_decode(const uint8_t *data, size_t len,
                                                 mipc_threedm_nmea_message_format_response_t *out,
                                                 mipc_decode_error_t *err) {
    mipc_reader_t r;
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_threedm_nmea_message_format_response_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

void mipc_threedm_nmea_message_format_response_to_json(
    mipc_jw_t *w, const mipc_threedm_nmea_message_format_response_t *in) {
    int first = 1;
    size_t i;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "count");
    mipc_jw_u8(w, &in->count);
    mipc_jw_key(w, &first, "format_entries");
    mipc_jw_raw(w, "[", 1);
    for (i = 0; i < (size_t)in->count && i < 50; i++) {
        mipc_jw_sep(w, i);
        mipc_nmea_message_to_json(w, &in->format_entries[i]);
    }
    mipc_jw_raw(w, "]", 1);
    mipc_jw_raw(w, "}", 1);
}

int mipc_threedm_nmea_message_format_response_from_json(mipc_jr_t *jr, size_t pos,
                                                        mipc_threedm_nmea_message_format_response_t *out) {
    static const char *const keys[] = {"count", "format_entries"};
    size_t vp = 0;
    int found;
    size_t i;
    size_t it = 0;
    size_t ep = 0;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 2)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "count", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"count\"");
    }
    {
        mipc_jr_push(jr, "count");
        if (mipc_jr_u8(jr, vp, &out->count)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "format_entries", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"format_entries\"");
    }
    {
        mipc_jr_push(jr, "format_entries");
        if (mipc_jr_array(jr, vp, &it)) {
            return -1;
        }
        for (i = 0;; i++) {
            int more = mipc_jr_next(jr, &it, &ep);
            if (more < 0) {
                return -1;
            }
            if (!more) {
                break;
            }
            if (i >= 50) {
                return mipc_jr_fail(jr, "more than 50 elements");
            }
            mipc_jr_index(jr, i);
            if (mipc_nmea_message_from_json(jr, ep, &out->format_entries[i])) {
                return -1;
            }
        }
        mipc_jr_index(jr, SIZE_MAX);
        if (i != (size_t)out->count) {
            return mipc_jr_fail(jr, "%zu elements but count is %zu", i, (size_t)out->count);
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mipc_threedm_message_format_t */

static int mipc_threedm_message_format_read(mipc_reader_t *r, mipc_threedm_message_format_t *out) {
    size_t i;
    mipc_rd_push(r, "function");
    if (mipc_rd_u8(r, &out->function)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "desc_set");
    if (mipc_rd_u8(r, &out->desc_set)) {
        return -1;
    }
    mipc_rd_pop(r);
    if (r->pos < r->len) {
        out->has_num_descriptors = true;
        mipc_rd_push(r, "num_descriptors");
        if (mipc_rd_u8(r, &out->num_descriptors)) {
            return -1;
        }
        mipc_rd_pop(r);
    }
    if (r->pos < r->len) {
        out->has_descriptors = true;
        mipc_rd_push(r, "descriptors");
        if (out->num_descriptors > 83) {
            return mipc_rd_count_error(r, (uint64_t)out->num_descriptors, 83);
        }
        for (i = 0; i < (size_t)out->num_descriptors; i++) {
            mipc_rd_index(r, i);
            if (mipc_descriptor_rate_read(r, &out->descriptors[i])) {
                return -1;
            }
        }
        mipc_rd_pop(r);
    }
    return mipc_rd_finish(r);
}

static mipc_status_t mipc_threedm_message_format_write(mipc_writer_t *w,
                                                       const mipc_threedm_message_format_t *in) {
    mipc_status_t st;
    size_t i;
    int absent = 0;
    if ((st = mipc_wr_u8(w, &in->function)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u8(w, &in->desc_set)) != MIPC_OK) {
        return st;
    }
    if (!in->has_num_descriptors) {
        absent = 1;
    } else if (absent) {
        return MIPC_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = mipc_wr_u8(w, &in->num_descriptors)) != MIPC_OK) {
            return st;
        }
    }
    if (!in->has_descriptors) {
        absent = 1;
    } else if (absent) {
        return MIPC_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if (in->num_descriptors > 83) {
            return MIPC_ERR_INVALID;
        }
        for (i = 0; i < (size_t)in->num_descriptors; i++) {
            if ((st = mipc_descriptor_rate_write(w, &in->descriptors[i])) != MIPC_OK) {
                return st;
            }
        }
    }
    return MIPC_OK;
}

mipc_status_t mipc_threedm_message_format_encode(const mipc_threedm_message_format_t *value, uint8_t *buf,
                                                 size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    mipc_writer_init(&w, buf, cap);
    st = mipc_threedm_message_format_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mipc_status_t mipc_threedm_message_format_decode(const uint8_t *data, size_t len,
                                                 mipc_threedm_message_format_t *out,
                                                 mipc_decode_error_t *err) {
    mipc_reader_t r;
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_threedm_message_format_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

void mipc_threedm_message_format_to_json(mipc_jw_t *w, const mipc_threedm_message_format_t *in) {
    int first = 1;
    size_t i;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "function");
    mipc_jw_u8(w, &in->function);
    mipc_jw_key(w, &first, "desc_set");
    mipc_jw_u8(w, &in->desc_set);
    if (in->has_num_descriptors) {
        mipc_jw_key(w, &first, "num_descriptors");
        mipc_jw_u8(w, &in->num_descriptors);
    }
    if (in->has_descriptors) {
        mipc_jw_key(w, &first, "descriptors");
        mipc_jw_raw(w, "[", 1);
        for (i = 0; i < (size_t)in->num_descriptors && i < 83; i++) {
            mipc_jw_sep(w, i);
            mipc_descriptor_rate_to_json(w, &in->descriptors[i]);
        }
        mipc_jw_raw(w, "]", 1);
    }
    mipc_jw_raw(w, "}", 1);
}

int mipc_threedm_message_format_from_json(mipc_jr_t *jr, size_t pos, mipc_threedm_message_format_t *out) {
    static const char *const keys[] = {"function", "desc_set", "num_descriptors", "descriptors"};
    size_t vp = 0;
    int found;
    int absent = 0;
    size_t i;
    size_t it = 0;
    size_t ep = 0;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 4)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "function", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"function\"");
    }
    {
        mipc_jr_push(jr, "function");
        if (mipc_jr_u8(jr, vp, &out->function)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "desc_set", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"desc_set\"");
    }
    {
        mipc_jr_push(jr, "desc_set");
        if (mipc_jr_u8(jr, vp, &out->desc_set)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "num_descriptors", &vp);
    out->has_num_descriptors = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mipc_jr_fail(jr, "optional parameter \"num_descriptors\" given after an absent one");
    } else {
        mipc_jr_push(jr, "num_descriptors");
        if (mipc_jr_u8(jr, vp, &out->num_descriptors)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "descriptors", &vp);
    out->has_descriptors = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mipc_jr_fail(jr, "optional parameter \"descriptors\" given after an absent one");
    } else {
        mipc_jr_push(jr, "descriptors");
        if (mipc_jr_array(jr, vp, &it)) {
            return -1;
        }
        for (i = 0;; i++) {
            int more = mipc_jr_next(jr, &it, &ep);
            if (more < 0) {
                return -1;
            }
            if (!more) {
                break;
            }
            if (i >= 83) {
                return mipc_jr_fail(jr, "more than 83 elements");
            }
            mipc_jr_index(jr, i);
            if (mipc_descriptor_rate_from_json(jr, ep, &out->descriptors[i])) {
                return -1;
            }
        }
        mipc_jr_index(jr, SIZE_MAX);
        if (i != (size_t)out->num_descriptors) {
            return mipc_jr_fail(jr, "%zu elements but num_descriptors is %zu", i,
                                (size_t)out->num_descriptors);
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mipc_threedm_message_format_response_t */

static int mipc_threedm_message_format_response_read(mipc_reader_t *r,
                                                     mipc_threedm_message_format_response_t *out) {
    size_t i;
    mipc_rd_push(r, "desc_set");
    if (mipc_rd_u8(r, &out->desc_set)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "num_descriptors");
    if (mipc_rd_u8(r, &out->num_descriptors)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "descriptors");
    if (out->num_descriptors > 83) {
        return mipc_rd_count_error(r, (uint64_t)out->num_descriptors, 83);
    }
    for (i = 0; i < (size_t)out->num_descriptors; i++) {
        mipc_rd_index(r, i);
        if (mipc_descriptor_rate_read(r, &out->descriptors[i])) {
            return -1;
        }
    }
    mipc_rd_pop(r);
    return mipc_rd_finish(r);
}

static mipc_status_t
mipc_threedm_message_format_response_write(mipc_writer_t *w,
                                           const mipc_threedm_message_format_response_t *in) {
    mipc_status_t st;
    size_t i;
    if ((st = mipc_wr_u8(w, &in->desc_set)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u8(w, &in->num_descriptors)) != MIPC_OK) {
        return st;
    }
    if (in->num_descriptors > 83) {
        return MIPC_ERR_INVALID;
    }
    for (i = 0; i < (size_t)in->num_descriptors; i++) {
        if ((st = mipc_descriptor_rate_write(w, &in->descriptors[i])) != MIPC_OK) {
            return st;
        }
    }
    return MIPC_OK;
}

mipc_status_t mipc_threedm_message_format_response_encode(const mipc_threedm_message_format_response_t *value,
                                                          uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    mipc_writer_init(&w, buf, cap);
    st = mipc_threedm_message_format_response_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mipc_status_t mipc_threedm_message_format_response_decode(const uint8_t *data, size_t len,
                                                          mipc_threedm_message_format_response_t *out,
                                                          mipc_decode_error_t *err) {
    mipc_reader_t r;
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_threedm_message_format_response_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

void mipc_threedm_message_format_response_to_json(mipc_jw_t *w,
                                                  const mipc_threedm_message_format_response_t *in) {
    int first = 1;
    size_t i;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "desc_set");
    mipc_jw_u8(w, &in->desc_set);
    mipc_jw_key(w, &first, "num_descriptors");
    mipc_jw_u8(w, &in->num_descriptors);
    mipc_jw_key(w, &first, "descriptors");
    mipc_jw_raw(w, "[", 1);
    for (i = 0; i < (size_t)in->num_descriptors && i < 83; i++) {
        mipc_jw_sep(w, i);
        mipc_descriptor_rate_to_json(w, &in->descriptors[i]);
    }
    mipc_jw_raw(w, "]", 1);
    mipc_jw_raw(w, "}", 1);
}

int mipc_threedm_message_format_response_from_json(mipc_jr_t *jr, size_t pos,
                                                   mipc_threedm_message_format_response_t *out) {
    static const char *const keys[] = {"desc_set", "num_descriptors", "descriptors"};
    size_t vp = 0;
    int found;
    size_t i;
    size_t it = 0;
    size_t ep = 0;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 3)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "desc_set", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"desc_set\"");
    }
    {
        mipc_jr_push(jr, "desc_set");
        if (mipc_jr_u8(jr, vp, &out->desc_set)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "num_descriptors", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"num_descriptors\"");
    }
    {
        mipc_jr_push(jr, "num_descriptors");
        if (mipc_jr_u8(jr, vp, &out->num_descriptors)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "descriptors", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"descriptors\"");
    }
    {
        mipc_jr_push(jr, "descriptors");
        if (mipc_jr_array(jr, vp, &it)) {
            return -1;
        }
        for (i = 0;; i++) {
            int more = mipc_jr_next(jr, &it, &ep);
            if (more < 0) {
                return -1;
            }
            if (!more) {
                break;
            }
            if (i >= 83) {
                return mipc_jr_fail(jr, "more than 83 elements");
            }
            mipc_jr_index(jr, i);
            if (mipc_descriptor_rate_from_json(jr, ep, &out->descriptors[i])) {
                return -1;
            }
        }
        mipc_jr_index(jr, SIZE_MAX);
        if (i != (size_t)out->num_descriptors) {
            return mipc_jr_fail(jr, "%zu elements but num_descriptors is %zu", i,
                                (size_t)out->num_descriptors);
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mipc_threedm_factory_streaming_t */

static int mipc_threedm_factory_streaming_read(mipc_reader_t *r, mipc_threedm_factory_streaming_t *out) {
    mipc_rd_push(r, "action");
    if (mipc_rd_u8(r, &out->action)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "reserved");
    if (mipc_rd_u8(r, &out->reserved)) {
        return -1;
    }
    mipc_rd_pop(r);
    return mipc_rd_finish(r);
}

static mipc_status_t mipc_threedm_factory_streaming_write(mipc_writer_t *w,
                                                          const mipc_threedm_factory_streaming_t *in) {
    mipc_status_t st;
    if ((st = mipc_wr_u8(w, &in->action)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u8(w, &in->reserved)) != MIPC_OK) {
        return st;
    }
    return MIPC_OK;
}

mipc_status_t mipc_threedm_factory_streaming_encode(const mipc_threedm_factory_streaming_t *value,
                                                    uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    mipc_writer_init(&w, buf, cap);
    st = mipc_threedm_factory_streaming_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 2 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mipc_threedm_factory_streaming_load(const uint8_t *d, mipc_threedm_factory_streaming_t *out) {
    out->action = mipc_ld_u8(d + 0);
    out->reserved = mipc_ld_u8(d + 1);
    return 0;
}

/* The general reader: lengths other than 2, bad bool bytes, error details. */
static MIPC_NOINLINE mipc_status_t mipc_threedm_factory_streaming_decode_read(
    const uint8_t *data, size_t len, mipc_threedm_factory_streaming_t *out, mipc_decode_error_t *err) {
    mipc_reader_t r;
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_threedm_factory_streaming_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t mipc_threedm_factory_streaming_decode(const uint8_t *data, size_t len,
                                                    mipc_threedm_factory_streaming_t *out,
                                                    mipc_decode_error_t *err) {
    if (len == 2 && mipc_threedm_factory_streaming_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_threedm_factory_streaming_decode_read(data, len, out, err);
}

void mipc_threedm_factory_streaming_to_json(mipc_jw_t *w, const mipc_threedm_factory_streaming_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "action");
    mipc_jw_u8(w, &in->action);
    mipc_jw_key(w, &first, "reserved");
    mipc_jw_u8(w, &in->reserved);
    mipc_jw_raw(w, "}", 1);
}

int mipc_threedm_factory_streaming_from_json(mipc_jr_t *jr, size_t pos,
                                             mipc_threedm_factory_streaming_t *out) {
    static const char *const keys[] = {"action", "reserved"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 2)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "action", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"action\"");
    }
    {
        mipc_jr_push(jr, "action");
        if (mipc_jr_u8(jr, vp, &out->action)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "reserved", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"reserved\"");
    }
    {
        mipc_jr_push(jr, "reserved");
        if (mipc_jr_u8(jr, vp, &out->reserved)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mipc_threedm_data_stream_control_gx5_45_t */

static int mipc_threedm_data_stream_control_gx5_45_read(mipc_reader_t *r,
                                                        mipc_threedm_data_stream_control_gx5_45_t *out) {
    mipc_rd_push(r, "function");
    if (mipc_rd_u8(r, &out->function)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "device_selector");
    if (mipc_rd_u8(r, &out->device_selector)) {
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
    return mipc_rd_finish(r);
}

static mipc_status_t
mipc_threedm_data_stream_control_gx5_45_write(mipc_writer_t *w,
                                              const mipc_threedm_data_stream_control_gx5_45_t *in) {
    mipc_status_t st;
    int absent = 0;
    if ((st = mipc_wr_u8(w, &in->function)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u8(w, &in->device_selector)) != MIPC_OK) {
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
    return MIPC_OK;
}

mipc_status_t
mipc_threedm_data_stream_control_gx5_45_encode(const mipc_threedm_data_stream_control_gx5_45_t *value,
                                               uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    mipc_writer_init(&w, buf, cap);
    st = mipc_threedm_data_stream_control_gx5_45_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mipc_status_t mipc_threedm_data_stream_control_gx5_45_decode(const uint8_t *data, size_t len,
                                                             mipc_threedm_data_stream_control_gx5_45_t *out,
                                                             mipc_decode_error_t *err) {
    mipc_reader_t r;
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_threedm_data_stream_control_gx5_45_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

void mipc_threedm_data_stream_control_gx5_45_to_json(mipc_jw_t *w,
                                                     const mipc_threedm_data_stream_control_gx5_45_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "function");
    mipc_jw_u8(w, &in->function);
    mipc_jw_key(w, &first, "device_selector");
    mipc_jw_u8(w, &in->device_selector);
    if (in->has_enable) {
        mipc_jw_key(w, &first, "enable");
        mipc_jw_u8(w, &in->enable);
    }
    mipc_jw_raw(w, "}", 1);
}

int mipc_threedm_data_stream_control_gx5_45_from_json(mipc_jr_t *jr, size_t pos,
                                                      mipc_threedm_data_stream_control_gx5_45_t *out) {
    static const char *const keys[] = {"function", "device_selector", "enable"};
    size_t vp = 0;
    int found;
    int absent = 0;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 3)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "function", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"function\"");
    }
    {
        mipc_jr_push(jr, "function");
        if (mipc_jr_u8(jr, vp, &out->function)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "device_selector", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"device_selector\"");
    }
    {
        mipc_jr_push(jr, "device_selector");
        if (mipc_jr_u8(jr, vp, &out->device_selector)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "enable", &vp);
    out->has_enable = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mipc_jr_fail(jr, "optional parameter \"enable\" given after an absent one");
    } else {
        mipc_jr_push(jr, "enable");
        if (mipc_jr_u8(jr, vp, &out->enable)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mipc_threedm_data_stream_control_cv7_ins_t */

static int mipc_threedm_data_stream_control_cv7_ins_read(mipc_reader_t *r,
                                                         mipc_threedm_data_stream_control_cv7_ins_t *out) {
    mipc_rd_push(r, "function");
    if (mipc_rd_u8(r, &out->function)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "desc_set");
    if (mipc_rd_u8(r, &out->desc_set)) {
        return -1;
    }
    mipc_rd_pop(r);
    if (r->pos < r->len) {
        out->has_enable = true;
        mipc_rd_push(r, "enable");
        if (mipc_rd_bool(r, &out->enable)) {
            return -1;
        }
        mipc_rd_pop(r);
    }
    return mipc_rd_finish(r);
}

static mipc_status_t
mipc_threedm_data_stream_control_cv7_ins_write(mipc_writer_t *w,
                                               const mipc_threedm_data_stream_control_cv7_ins_t *in) {
    mipc_status_t st;
    int absent = 0;
    if ((st = mipc_wr_u8(w, &in->function)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u8(w, &in->desc_set)) != MIPC_OK) {
        return st;
    }
    if (!in->has_enable) {
        absent = 1;
    } else if (absent) {
        return MIPC_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = mipc_wr_bool(w, &in->enable)) != MIPC_OK) {
            return st;
        }
    }
    return MIPC_OK;
}

mipc_status_t
mipc_threedm_data_stream_control_cv7_ins_encode(const mipc_threedm_data_stream_control_cv7_ins_t *value,
                                                uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    mipc_writer_init(&w, buf, cap);
    st = mipc_threedm_data_stream_control_cv7_ins_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mipc_status_t mipc_threedm_data_stream_control_cv7_ins_decode(const uint8_t *data, size_t len,
                                                              mipc_threedm_data_stream_control_cv7_ins_t *out,
                                                              mipc_decode_error_t *err) {
    mipc_reader_t r;
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_threedm_data_stream_control_cv7_ins_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

void mipc_threedm_data_stream_control_cv7_ins_to_json(mipc_jw_t *w,
                                                      const mipc_threedm_data_stream_control_cv7_ins_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "function");
    mipc_jw_u8(w, &in->function);
    mipc_jw_key(w, &first, "desc_set");
    mipc_jw_u8(w, &in->desc_set);
    if (in->has_enable) {
        mipc_jw_key(w, &first, "enable");
        mipc_jw_bool(w, &in->enable);
    }
    mipc_jw_raw(w, "}", 1);
}

int mipc_threedm_data_stream_control_cv7_ins_from_json(mipc_jr_t *jr, size_t pos,
                                                       mipc_threedm_data_stream_control_cv7_ins_t *out) {
    static const char *const keys[] = {"function", "desc_set", "enable"};
    size_t vp = 0;
    int found;
    int absent = 0;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 3)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "function", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"function\"");
    }
    {
        mipc_jr_push(jr, "function");
        if (mipc_jr_u8(jr, vp, &out->function)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "desc_set", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"desc_set\"");
    }
    {
        mipc_jr_push(jr, "desc_set");
        if (mipc_jr_u8(jr, vp, &out->desc_set)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "enable", &vp);
    out->has_enable = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mipc_jr_fail(jr, "optional parameter \"enable\" given after an absent one");
    } else {
        mipc_jr_push(jr, "enable");
        if (mipc_jr_bool(jr, vp, &out->enable)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mipc_threedm_data_stream_control_response_gx5_45_t */

static int mipc_threedm_data_stream_control_response_gx5_45_read(
    mipc_reader_t *r, mipc_threedm_data_stream_control_response_gx5_45_t *out) {
    mipc_rd_push(r, "device_selector");
    if (mipc_rd_u8(r, &out->device_selector)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "enabled");
    if (mipc_rd_u8(r, &out->enabled)) {
        return -1;
    }
    mipc_rd_pop(r);
    return mipc_rd_finish(r);
}

static mipc_status_t mipc_threedm_data_stream_control_response_gx5_45_write(
    mipc_writer_t *w, const mipc_threedm_data_stream_control_response_gx5_45_t *in) {
    mipc_status_t st;
    if ((st = mipc_wr_u8(w, &in->device_selector)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u8(w, &in->enabled)) != MIPC_OK) {
        return st;
    }
    return MIPC_OK;
}

mipc_status_t mipc_threedm_data_stream_control_response_gx5_45_encode(
    const mipc_threedm_data_stream_control_response_gx5_45_t *value, uint8_t *buf, size_t cap,
    size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    mipc_writer_init(&w, buf, cap);
    st = mipc_threedm_data_stream_control_response_gx5_45_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 2 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mipc_threedm_data_stream_control_response_gx5_45_load(
    const uint8_t *d, mipc_threedm_data_stream_control_response_gx5_45_t *out) {
    out->device_selector = mipc_ld_u8(d + 0);
    out->enabled = mipc_ld_u8(d + 1);
    return 0;
}

/* The general reader: lengths other than 2, bad bool bytes, error details. */
static MIPC_NOINLINE mipc_status_t mipc_threedm_data_stream_control_response_gx5_45_decode_read(
    const uint8_t *data, size_t len, mipc_threedm_data_stream_control_response_gx5_45_t *out,
    mipc_decode_error_t *err) {
    mipc_reader_t r;
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_threedm_data_stream_control_response_gx5_45_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t mipc_threedm_data_stream_control_response_gx5_45_decode(
    const uint8_t *data, size_t len, mipc_threedm_data_stream_control_response_gx5_45_t *out,
    mipc_decode_error_t *err) {
    if (len == 2 && mipc_threedm_data_stream_control_response_gx5_45_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_threedm_data_stream_control_response_gx5_45_decode_read(data, len, out, err);
}

void mipc_threedm_data_stream_control_response_gx5_45_to_json(
    mipc_jw_t *w, const mipc_threedm_data_stream_control_response_gx5_45_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "device_selector");
    mipc_jw_u8(w, &in->device_selector);
    mipc_jw_key(w, &first, "enabled");
    mipc_jw_u8(w, &in->enabled);
    mipc_jw_raw(w, "}", 1);
}

int mipc_threedm_data_stream_control_response_gx5_45_from_json(
    mipc_jr_t *jr, size_t pos, mipc_threedm_data_stream_control_response_gx5_45_t *out) {
    static const char *const keys[] = {"device_selector", "enabled"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 2)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "device_selector", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"device_selector\"");
    }
    {
        mipc_jr_push(jr, "device_selector");
        if (mipc_jr_u8(jr, vp, &out->device_selector)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "enabled", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"enabled\"");
    }
    {
        mipc_jr_push(jr, "enabled");
        if (mipc_jr_u8(jr, vp, &out->enabled)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mipc_threedm_data_stream_control_response_cv7_ins_t */

static int mipc_threedm_data_stream_control_response_cv7_ins_read(
    mipc_reader_t *r, mipc_threedm_data_stream_control_response_cv7_ins_t *out) {
    mipc_rd_push(r, "desc_set");
    if (mipc_rd_u8(r, &out->desc_set)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "enabled");
    if (mipc_rd_bool(r, &out->enabled)) {
        return -1;
    }
    mipc_rd_pop(r);
    return mipc_rd_finish(r);
}

static mipc_status_t mipc_threedm_data_stream_control_response_cv7_ins_write(
    mipc_writer_t *w, const mipc_threedm_data_stream_control_response_cv7_ins_t *in) {
    mipc_status_t st;
    if ((st = mipc_wr_u8(w, &in->desc_set)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_bool(w, &in->enabled)) != MIPC_OK) {
        return st;
    }
    return MIPC_OK;
}

mipc_status_t mipc_threedm_data_stream_control_response_cv7_ins_encode(
    const mipc_threedm_data_stream_control_response_cv7_ins_t *value, uint8_t *buf, size_t cap,
    size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    mipc_writer_init(&w, buf, cap);
    st = mipc_threedm_data_stream_control_response_cv7_ins_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 2 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mipc_threedm_data_stream_control_response_cv7_ins_load(
    const uint8_t *d, mipc_threedm_data_stream_control_response_cv7_ins_t *out) {
    out->desc_set = mipc_ld_u8(d + 0);
    if (d[1] > 1) {
        return -1;
    }
    out->enabled = mipc_ld_bool(d + 1);
    return 0;
}

/* The general reader: lengths other than 2, bad bool bytes, error details. */
static MIPC_NOINLINE mipc_status_t mipc_threedm_data_stream_control_response_cv7_ins_decode_read(
    const uint8_t *data, size_t len, mipc_threedm_data_stream_control_response_cv7_ins_t *out,
    mipc_decode_error_t *err) {
    mipc_reader_t r;
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_threedm_data_stream_control_response_cv7_ins_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t mipc_threedm_data_stream_control_response_cv7_ins_decode(
    const uint8_t *data, size_t len, mipc_threedm_data_stream_control_response_cv7_ins_t *out,
    mipc_decode_error_t *err) {
    if (len == 2 && mipc_threedm_data_stream_control_response_cv7_ins_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_threedm_data_stream_control_response_cv7_ins_decode_read(data, len, out, err);
}

void mipc_threedm_data_stream_control_response_cv7_ins_to_json(
    mipc_jw_t *w, const mipc_threedm_data_stream_control_response_cv7_ins_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "desc_set");
    mipc_jw_u8(w, &in->desc_set);
    mipc_jw_key(w, &first, "enabled");
    mipc_jw_bool(w, &in->enabled);
    mipc_jw_raw(w, "}", 1);
}

int mipc_threedm_data_stream_control_response_cv7_ins_from_json(
    mipc_jr_t *jr, size_t pos, mipc_threedm_data_stream_control_response_cv7_ins_t *out) {
    static const char *const keys[] = {"desc_set", "enabled"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 2)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "desc_set", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"desc_set\"");
    }
    {
        mipc_jr_push(jr, "desc_set");
        if (mipc_jr_u8(jr, vp, &out->desc_set)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "enabled", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"enabled\"");
    }
    {
        mipc_jr_push(jr, "enabled");
        if (mipc_jr_bool(jr, vp, &out->enabled)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mipc_threedm_raw_rtcm_message_t */

static int mipc_threedm_raw_rtcm_message_read(mipc_reader_t *r, mipc_threedm_raw_rtcm_message_t *out) {
    size_t i;
    size_t n;
    mipc_rd_push(r, "data");
    if (mipc_rd_remaining(r, 1, 253, &n)) {
        return -1;
    }
    for (i = 0; i < n; i++) {
        mipc_rd_index(r, i);
        if (mipc_rd_u8(r, &out->data[i])) {
            return -1;
        }
    }
    out->data_count = n;
    mipc_rd_pop(r);
    return mipc_rd_finish(r);
}

static mipc_status_t mipc_threedm_raw_rtcm_message_write(mipc_writer_t *w,
                                                         const mipc_threedm_raw_rtcm_message_t *in) {
    mipc_status_t st;
    size_t i;
    if (in->data_count > 253) {
        return MIPC_ERR_INVALID;
    }
    for (i = 0; i < (size_t)in->data_count; i++) {
        if ((st = mipc_wr_u8(w, &in->data[i])) != MIPC_OK) {
            return st;
        }
    }
    return MIPC_OK;
}

mipc_status_t mipc_threedm_raw_rtcm_message_encode(const mipc_threedm_raw_rtcm_message_t *value, uint8_t *buf,
                                                   size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    mipc_writer_init(&w, buf, cap);
    st = mipc_threedm_raw_rtcm_message_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mipc_status_t mipc_threedm_raw_rtcm_message_decode(const uint8_t *data, size_t len,
                                                   mipc_threedm_raw_rtcm_message_t *out,
                                                   mipc_decode_error_t *err) {
    mipc_reader_t r;
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_threedm_raw_rtcm_message_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

void mipc_threedm_raw_rtcm_message_to_json(mipc_jw_t *w, const mipc_threedm_raw_rtcm_message_t *in) {
    int first = 1;
    size_t i;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "data");
    mipc_jw_raw(w, "[", 1);
    for (i = 0; i < (size_t)in->data_count && i < 253; i++) {
        mipc_jw_sep(w, i);
        mipc_jw_u8(w, &in->data[i]);
    }
    mipc_jw_raw(w, "]", 1);
    mipc_jw_raw(w, "}", 1);
}

int mipc_threedm_raw_rtcm_message_from_json(mipc_jr_t *jr, size_t pos, mipc_threedm_raw_rtcm_message_t *out) {
    static const char *const keys[] = {"data"};
    size_t vp = 0;
    int found;
    size_t i;
    size_t it = 0;
    size_t ep = 0;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 1)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "data", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"data\"");
    }
    {
        mipc_jr_push(jr, "data");
        if (mipc_jr_array(jr, vp, &it)) {
            return -1;
        }
        for (i = 0;; i++) {
            int more = mipc_jr_next(jr, &it, &ep);
            if (more < 0) {
                return -1;
            }
            if (!more) {
                break;
            }
            if (i >= 253) {
                return mipc_jr_fail(jr, "more than 253 elements");
            }
            mipc_jr_index(jr, i);
            if (mipc_jr_u8(jr, ep, &out->data[i])) {
                return -1;
            }
        }
        mipc_jr_index(jr, SIZE_MAX);
        out->data_count = i;
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mipc_threedm_gnss_constellation_settings_t */

static int mipc_threedm_gnss_constellation_settings_read(mipc_reader_t *r,
                                                         mipc_threedm_gnss_constellation_settings_t *out) {
    size_t i;
    mipc_rd_push(r, "function");
    if (mipc_rd_u8(r, &out->function)) {
        return -1;
    }
    mipc_rd_pop(r);
    if (r->pos < r->len) {
        out->has_max_channels = true;
        mipc_rd_push(r, "max_channels");
        if (mipc_rd_u16(r, &out->max_channels)) {
            return -1;
        }
        mipc_rd_pop(r);
    }
    if (r->pos < r->len) {
        out->has_config_count = true;
        mipc_rd_push(r, "config_count");
        if (mipc_rd_u8(r, &out->config_count)) {
            return -1;
        }
        mipc_rd_pop(r);
    }
    if (r->pos < r->len) {
        out->has_settings = true;
        mipc_rd_push(r, "settings");
        if (out->config_count > 41) {
            return mipc_rd_count_error(r, (uint64_t)out->config_count, 41);
        }
        for (i = 0; i < (size_t)out->config_count; i++) {
            mipc_rd_index(r, i);
            if (mipc_constellation_settings_read(r, &out->settings[i])) {
                return -1;
            }
        }
        mipc_rd_pop(r);
    }
    return mipc_rd_finish(r);
}

static mipc_status_t
mipc_threedm_gnss_constellation_settings_write(mipc_writer_t *w,
                                               const mipc_threedm_gnss_constellation_settings_t *in) {
    mipc_status_t st;
    size_t i;
    int absent = 0;
    if ((st = mipc_wr_u8(w, &in->function)) != MIPC_OK) {
        return st;
    }
    if (!in->has_max_channels) {
        absent = 1;
    } else if (absent) {
        return MIPC_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = mipc_wr_u16(w, &in->max_channels)) != MIPC_OK) {
            return st;
        }
    }
    if (!in->has_config_count) {
        absent = 1;
    } else if (absent) {
        return MIPC_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = mipc_wr_u8(w, &in->config_count)) != MIPC_OK) {
            return st;
        }
    }
    if (!in->has_settings) {
        absent = 1;
    } else if (absent) {
        return MIPC_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if (in->config_count > 41) {
            return MIPC_ERR_INVALID;
        }
        for (i = 0; i < (size_t)in->config_count; i++) {
            if ((st = mipc_constellation_settings_write(w, &in->settings[i])) != MIPC_OK) {
                return st;
            }
        }
    }
    return MIPC_OK;
}

mipc_status_t
mipc_threedm_gnss_constellation_settings_encode(const mipc_threedm_gnss_constellation_settings_t *value,
                                                uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    mipc_writer_init(&w, buf, cap);
    st = mipc_threedm_gnss_constellation_settings_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mipc_status_t mipc_threedm_gnss_constellation_settings_decode(const uint8_t *data, size_t len,
                                                              mipc_threedm_gnss_constellation_settings_t *out,
                                                              mipc_decode_error_t *err) {
    mipc_reader_t r;
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_threedm_gnss_constellation_settings_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

void mipc_threedm_gnss_constellation_settings_to_json(mipc_jw_t *w,
                                                      const mipc_threedm_gnss_constellation_settings_t *in) {
    int first = 1;
    size_t i;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "function");
    mipc_jw_u8(w, &in->function);
    if (in->has_max_channels) {
        mipc_jw_key(w, &first, "max_channels");
        mipc_jw_u16(w, &in->max_channels);
    }
    if (in->has_config_count) {
        mipc_jw_key(w, &first, "config_count");
        mipc_jw_u8(w, &in->config_count);
    }
    if (in->has_settings) {
        mipc_jw_key(w, &first, "settings");
        mipc_jw_raw(w, "[", 1);
        for (i = 0; i < (size_t)in->config_count && i < 41; i++) {
            mipc_jw_sep(w, i);
            mipc_constellation_settings_to_json(w, &in->settings[i]);
        }
        mipc_jw_raw(w, "]", 1);
    }
    mipc_jw_raw(w, "}", 1);
}

int mipc_threedm_gnss_constellation_settings_from_json(mipc_jr_t *jr, size_t pos,
                                                       mipc_threedm_gnss_constellation_settings_t *out) {
    static const char *const keys[] = {"function", "max_channels", "config_count", "settings"};
    size_t vp = 0;
    int found;
    int absent = 0;
    size_t i;
    size_t it = 0;
    size_t ep = 0;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 4)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "function", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"function\"");
    }
    {
        mipc_jr_push(jr, "function");
        if (mipc_jr_u8(jr, vp, &out->function)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "max_channels", &vp);
    out->has_max_channels = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mipc_jr_fail(jr, "optional parameter \"max_channels\" given after an absent one");
    } else {
        mipc_jr_push(jr, "max_channels");
        if (mipc_jr_u16(jr, vp, &out->max_channels)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "config_count", &vp);
    out->has_config_count = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mipc_jr_fail(jr, "optional parameter \"config_count\" given after an absent one");
    } else {
        mipc_jr_push(jr, "config_count");
        if (mipc_jr_u8(jr, vp, &out->config_count)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "settings", &vp);
    out->has_settings = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mipc_jr_fail(jr, "optional parameter \"settings\" given after an absent one");
    } else {
        mipc_jr_push(jr, "settings");
        if (mipc_jr_array(jr, vp, &it)) {
            return -1;
        }
        for (i = 0;; i++) {
            int more = mipc_jr_next(jr, &it, &ep);
            if (more < 0) {
                return -1;
            }
            if (!more) {
                break;
            }
            if (i >= 41) {
                return mipc_jr_fail(jr, "more than 41 elements");
            }
            mipc_jr_index(jr, i);
            if (mipc_constellation_settings_from_json(jr, ep, &out->settings[i])) {
                return -1;
            }
        }
        mipc_jr_index(jr, SIZE_MAX);
        if (i != (size_t)out->config_count) {
            return mipc_jr_fail(jr, "%zu elements but config_count is %zu", i, (size_t)out->config_count);
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mipc_threedm_gnss_constellation_settings_response_t */

static int mipc_threedm_gnss_constellation_settings_response_read(
    mipc_reader_t *r, mipc_threedm_gnss_constellation_settings_response_t *out) {
    size_t i;
    mipc_rd_push(r, "max_channels_available");
    if (mipc_rd_u16(r, &out->max_channels_available)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "max_channels");
    if (mipc_rd_u16(r, &out->max_channels)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "config_count");
    if (mipc_rd_u8(r, &out->config_count)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "settings");
    if (out->config_count > 41) {
        return mipc_rd_count_error(r, (uint64_t)out->config_count, 41);
    }
    for (i = 0; i < (size_t)out->config_count; i++) {
        mipc_rd_index(r, i);
        if (mipc_constellation_settings_read(r, &out->settings[i])) {
            return -1;
        }
    }
    mipc_rd_pop(r);
    return mipc_rd_finish(r);
}

static mipc_status_t mipc_threedm_gnss_constellation_settings_response_write(
    mipc_writer_t *w, const mipc_threedm_gnss_constellation_settings_response_t *in) {
    mipc_status_t st;
    size_t i;
    if ((st = mipc_wr_u16(w, &in->max_channels_available)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u16(w, &in->max_channels)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u8(w, &in->config_count)) != MIPC_OK) {
        return st;
    }
    if (in->config_count > 41) {
        return MIPC_ERR_INVALID;
    }
    for (i = 0; i < (size_t)in->config_count; i++) {
        if ((st = mipc_constellation_settings_write(w, &in->settings[i])) != MIPC_OK) {
            return st;
        }
    }
    return MIPC_OK;
}

mipc_status_t mipc_threedm_gnss_constellation_settings_response_encode(
    const mipc_threedm_gnss_constellation_settings_response_t *value, uint8_t *buf, size_t cap,
    size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    mipc_writer_init(&w, buf, cap);
    st = mipc_threedm_gnss_constellation_settings_response_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mipc_status_t mipc_threedm_gnss_constellation_settings_response_decode(
    const uint8_t *data, size_t len, mipc_threedm_gnss_constellation_settings_response_t *out,
    mipc_decode_error_t *err) {
    mipc_reader_t r;
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_threedm_gnss_constellation_settings_response_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

void mipc_threedm_gnss_constellation_settings_response_to_json(
    mipc_jw_t *w, const mipc_threedm_gnss_constellation_settings_response_t *in) {
    int first = 1;
    size_t i;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "max_channels_available");
    mipc_jw_u16(w, &in->max_channels_available);
    mipc_jw_key(w, &first, "max_channels");
    mipc_jw_u16(w, &in->max_channels);
    mipc_jw_key(w, &first, "config_count");
    mipc_jw_u8(w, &in->config_count);
    mipc_jw_key(w, &first, "settings");
    mipc_jw_raw(w, "[", 1);
    for (i = 0; i < (size_t)in->config_count && i < 41; i++) {
        mipc_jw_sep(w, i);
        mipc_constellation_settings_to_json(w, &in->settings[i]);
    }
    mipc_jw_raw(w, "]", 1);
    mipc_jw_raw(w, "}", 1);
}

int mipc_threedm_gnss_constellation_settings_response_from_json(
    mipc_jr_t *jr, size_t pos, mipc_threedm_gnss_constellation_settings_response_t *out) {
    static const char *const keys[] = {"max_channels_available", "max_channels", "config_count", "settings"};
    size_t vp = 0;
    int found;
    size_t i;
    size_t it = 0;
    size_t ep = 0;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 4)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "max_channels_available", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"max_channels_available\"");
    }
    {
        mipc_jr_push(jr, "max_channels_available");
        if (mipc_jr_u16(jr, vp, &out->max_channels_available)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "max_channels", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"max_channels\"");
    }
    {
        mipc_jr_push(jr, "max_channels");
        if (mipc_jr_u16(jr, vp, &out->max_channels)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "config_count", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"config_count\"");
    }
    {
        mipc_jr_push(jr, "config_count");
        if (mipc_jr_u8(jr, vp, &out->config_count)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "settings", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"settings\"");
    }
    {
        mipc_jr_push(jr, "settings");
        if (mipc_jr_array(jr, vp, &it)) {
            return -1;
        }
        for (i = 0;; i++) {
            int more = mipc_jr_next(jr, &it, &ep);
            if (more < 0) {
                return -1;
            }
            if (!more) {
                break;
            }
            if (i >= 41) {
                return mipc_jr_fail(jr, "more than 41 elements");
            }
            mipc_jr_index(jr, i);
            if (mipc_constellation_settings_from_json(jr, ep, &out->settings[i])) {
                return -1;
            }
        }
        mipc_jr_index(jr, SIZE_MAX);
        if (i != (size_t)out->config_count) {
            return mipc_jr_fail(jr, "%zu elements but config_count is %zu", i, (size_t)out->config_count);
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mipc_threedm_gnss_sbas_settings_t */

static int mipc_threedm_gnss_sbas_settings_read(mipc_reader_t *r, mipc_threedm_gnss_sbas_settings_t *out) {
    size_t i;
    mipc_rd_push(r, "function");
    if (mipc_rd_u8(r, &out->function)) {
        return -1;
    }
    mipc_rd_pop(r);
    if (r->pos < r->len) {
        out->has_enable_sbas = true;
        mipc_rd_push(r, "enable_sbas");
        if (mipc_rd_u8(r, &out->enable_sbas)) {
            return -1;
        }
        mipc_rd_pop(r);
    }
    if (r->pos < r->len) {
        out->has_sbas_options = true;
        mipc_rd_push(r, "sbas_options");
        if (mipc_rd_u16(r, &out->sbas_options)) {
            return -1;
        }
        mipc_rd_pop(r);
    }
    if (r->pos < r->len) {
        out->has_num_included_prns = true;
        mipc_rd_push(r, "num_included_prns");
        if (mipc_rd_u8(r, &out->num_included_prns)) {
            return -1;
        }
        mipc_rd_pop(r);
    }
    if (r->pos < r->len) {
        out->has_included_prns = true;
        mipc_rd_push(r, "included_prns");
        if (out->num_included_prns > 124) {
            return mipc_rd_count_error(r, (uint64_t)out->num_included_prns, 124);
        }
        for (i = 0; i < (size_t)out->num_included_prns; i++) {
            mipc_rd_index(r, i);
            if (mipc_rd_u16(r, &out->included_prns[i])) {
                return -1;
            }
        }
        mipc_rd_pop(r);
    }
    return mipc_rd_finish(r);
}

static mipc_status_t mipc_threedm_gnss_sbas_settings_write(mipc_writer_t *w,
                                                           const mipc_threedm_gnss_sbas_settings_t *in) {
    mipc_status_t st;
    size_t i;
    int absent = 0;
    if ((st = mipc_wr_u8(w, &in->function)) != MIPC_OK) {
        return st;
    }
    if (!in->has_enable_sbas) {
        absent = 1;
    } else if (absent) {
        return MIPC_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = mipc_wr_u8(w, &in->enable_sbas)) != MIPC_OK) {
            return st;
        }
    }
    if (!in->has_sbas_options) {
        absent = 1;
    } else if (absent) {
        return MIPC_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = mipc_wr_u16(w, &in->sbas_options)) != MIPC_OK) {
            return st;
        }
    }
    if (!in->has_num_included_prns) {
        absent = 1;
    } else if (absent) {
        return MIPC_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = mipc_wr_u8(w, &in->num_included_prns)) != MIPC_OK) {
            return st;
        }
    }
    if (!in->has_included_prns) {
        absent = 1;
    } else if (absent) {
        return MIPC_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if (in->num_included_prns > 124) {
            return MIPC_ERR_INVALID;
        }
        for (i = 0; i < (size_t)in->num_included_prns; i++) {
            if ((st = mipc_wr_u16(w, &in->included_prns[i])) != MIPC_OK) {
                return st;
            }
        }
    }
    return MIPC_OK;
}

mipc_status_t mipc_threedm_gnss_sbas_settings_encode(const mipc_threedm_gnss_sbas_settings_t *value,
                                                     uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    mipc_writer_init(&w, buf, cap);
    st = mipc_threedm_gnss_sbas_settings_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mipc_status_t mipc_threedm_gnss_sbas_settings_decode(const uint8_t *data, size_t len,
                                                     mipc_threedm_gnss_sbas_settings_t *out,
                                                     mipc_decode_error_t *err) {
    mipc_reader_t r;
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_threedm_gnss_sbas_settings_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

void mipc_threedm_gnss_sbas_settings_to_json(mipc_jw_t *w, const mipc_threedm_gnss_sbas_settings_t *in) {
    int first = 1;
    size_t i;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "function");
    mipc_jw_u8(w, &in->function);
    if (in->has_enable_sbas) {
        mipc_jw_key(w, &first, "enable_sbas");
        mipc_jw_u8(w, &in->enable_sbas);
    }
    if (in->has_sbas_options) {
        mipc_jw_key(w, &first, "sbas_options");
        mipc_jw_u16(w, &in->sbas_options);
    }
    if (in->has_num_included_prns) {
        mipc_jw_key(w, &first, "num_included_prns");
        mipc_jw_u8(w, &in->num_included_prns);
    }
    if (in->has_included_prns) {
        mipc_jw_key(w, &first, "included_prns");
        mipc_jw_raw(w, "[", 1);
        for (i = 0; i < (size_t)in->num_included_prns && i < 124; i++) {
            mipc_jw_sep(w, i);
            mipc_jw_u16(w, &in->included_prns[i]);
        }
        mipc_jw_raw(w, "]", 1);
    }
    mipc_jw_raw(w, "}", 1);
}

int mipc_threedm_gnss_sbas_settings_from_json(mipc_jr_t *jr, size_t pos,
                                              mipc_threedm_gnss_sbas_settings_t *out) {
    static const char *const keys[] = {"function", "enable_sbas", "sbas_options", "num_included_prns",
                                       "included_prns"};
    size_t vp = 0;
    int found;
    int absent = 0;
    size_t i;
    size_t it = 0;
    size_t ep = 0;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 5)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "function", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"function\"");
    }
    {
        mipc_jr_push(jr, "function");
        if (mipc_jr_u8(jr, vp, &out->function)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "enable_sbas", &vp);
    out->has_enable_sbas = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mipc_jr_fail(jr, "optional parameter \"enable_sbas\" given after an absent one");
    } else {
        mipc_jr_push(jr, "enable_sbas");
        if (mipc_jr_u8(jr, vp, &out->enable_sbas)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "sbas_options", &vp);
    out->has_sbas_options = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mipc_jr_fail(jr, "optional parameter \"sbas_options\" given after an absent one");
    } else {
        mipc_jr_push(jr, "sbas_options");
        if (mipc_jr_u16(jr, vp, &out->sbas_options)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "num_included_prns", &vp);
    out->has_num_included_prns = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mipc_jr_fail(jr, "optional parameter \"num_included_prns\" given after an absent one");
    } else {
        mipc_jr_push(jr, "num_included_prns");
        if (mipc_jr_u8(jr, vp, &out->num_included_prns)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "included_prns", &vp);
    out->has_included_prns = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mipc_jr_fail(jr, "optional parameter \"included_prns\" given after an absent one");
    } else {
        mipc_jr_push(jr, "included_prns");
        if (mipc_jr_array(jr, vp, &it)) {
            return -1;
        }
        for (i = 0;; i++) {
            int more = mipc_jr_next(jr, &it, &ep);
            if (more < 0) {
                return -1;
            }
            if (!more) {
                break;
            }
            if (i >= 124) {
                return mipc_jr_fail(jr, "more than 124 elements");
            }
            mipc_jr_index(jr, i);
            if (mipc_jr_u16(jr, ep, &out->included_prns[i])) {
                return -1;
            }
        }
        mipc_jr_index(jr, SIZE_MAX);
        if (i != (size_t)out->num_included_prns) {
            return mipc_jr_fail(jr, "%zu elements but num_included_prns is %zu", i,
                                (size_t)out->num_included_prns);
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mipc_threedm_gnss_sbas_settings_response_t */

static int mipc_threedm_gnss_sbas_settings_response_read(mipc_reader_t *r,
                                                         mipc_threedm_gnss_sbas_settings_response_t *out) {
    size_t i;
    mipc_rd_push(r, "enable_sbas");
    if (mipc_rd_u8(r, &out->enable_sbas)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "sbas_options");
    if (mipc_rd_u16(r, &out->sbas_options)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "num_included_prns");
    if (mipc_rd_u8(r, &out->num_included_prns)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "included_prns");
    if (out->num_included_prns > 124) {
        return mipc_rd_count_error(r, (uint64_t)out->num_included_prns, 124);
    }
    for (i = 0; i < (size_t)out->num_included_prns; i++) {
        mipc_rd_index(r, i);
        if (mipc_rd_u16(r, &out->included_prns[i])) {
            return -1;
        }
    }
    mipc_rd_pop(r);
    return mipc_rd_finish(r);
}

static mipc_status_t
mipc_threedm_gnss_sbas_settings_response_write(mipc_writer_t *w,
                                               const mipc_threedm_gnss_sbas_settings_response_t *in) {
    mipc_status_t st;
    size_t i;
    if ((st = mipc_wr_u8(w, &in->enable_sbas)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u16(w, &in->sbas_options)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u8(w, &in->num_included_prns)) != MIPC_OK) {
        return st;
    }
    if (in->num_included_prns > 124) {
        return MIPC_ERR_INVALID;
    }
    for (i = 0; i < (size_t)in->num_included_prns; i++) {
        if ((st = mipc_wr_u16(w, &in->included_prns[i])) != MIPC_OK) {
            return st;
        }
    }
    return MIPC_OK;
}

mipc_status_t
mipc_threedm_gnss_sbas_settings_response_encode(const mipc_threedm_gnss_sbas_settings_response_t *value,
                                                uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    mipc_writer_init(&w, buf, cap);
    st = mipc_threedm_gnss_sbas_settings_response_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mipc_status_t mipc_threedm_gnss_sbas_settings_response_decode(const uint8_t *data, size_t len,
                                                              mipc_threedm_gnss_sbas_settings_response_t *out,
                                                              mipc_decode_error_t *err) {
    mipc_reader_t r;
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_threedm_gnss_sbas_settings_response_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

void mipc_threedm_gnss_sbas_settings_response_to_json(mipc_jw_t *w,
                                                      const mipc_threedm_gnss_sbas_settings_response_t *in) {
    int first = 1;
    size_t i;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "enable_sbas");
    mipc_jw_u8(w, &in->enable_sbas);
    mipc_jw_key(w, &first, "sbas_options");
    mipc_jw_u16(w, &in->sbas_options);
    mipc_jw_key(w, &first, "num_included_prns");
    mipc_jw_u8(w, &in->num_included_prns);
    mipc_jw_key(w, &first, "included_prns");
    mipc_jw_raw(w, "[", 1);
    for (i = 0; i < (size_t)in->num_included_prns && i < 124; i++) {
        mipc_jw_sep(w, i);
        mipc_jw_u16(w, &in->included_prns[i]);
    }
    mipc_jw_raw(w, "]", 1);
    mipc_jw_raw(w, "}", 1);
}

int mipc_threedm_gnss_sbas_settings_response_from_json(mipc_jr_t *jr, size_t pos,
                                                       mipc_threedm_gnss_sbas_settings_response_t *out) {
    static const char *const keys[] = {"enable_sbas", "sbas_options", "num_included_prns", "included_prns"};
    size_t vp = 0;
    int found;
    size_t i;
    size_t it = 0;
    size_t ep = 0;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 4)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "enable_sbas", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"enable_sbas\"");
    }
    {
        mipc_jr_push(jr, "enable_sbas");
        if (mipc_jr_u8(jr, vp, &out->enable_sbas)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "sbas_options", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"sbas_options\"");
    }
    {
        mipc_jr_push(jr, "sbas_options");
        if (mipc_jr_u16(jr, vp, &out->sbas_options)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "num_included_prns", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"num_included_prns\"");
    }
    {
        mipc_jr_push(jr, "num_included_prns");
        if (mipc_jr_u8(jr, vp, &out->num_included_prns)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "included_prns", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"included_prns\"");
    }
    {
        mipc_jr_push(jr, "included_prns");
        if (mipc_jr_array(jr, vp, &it)) {
            return -1;
        }
        for (i = 0;; i++) {
            int more = mipc_jr_next(jr, &it, &ep);
            if (more < 0) {
                return -1;
            }
            if (!more) {
                break;
            }
            if (i >= 124) {
                return mipc_jr_fail(jr, "more than 124 elements");
            }
            mipc_jr_index(jr, i);
            if (mipc_jr_u16(jr, ep, &out->included_prns[i])) {
                return -1;
            }
        }
        mipc_jr_index(jr, SIZE_MAX);
        if (i != (size_t)out->num_included_prns) {
            return mipc_jr_fail(jr, "%zu elements but num_included_prns is %zu", i,
                                (size_t)out->num_included_prns);
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mipc_threedm_gnss_assisted_fix_control_t */

static int mipc_threedm_gnss_assisted_fix_control_read(mipc_reader_t *r,
                                                       mipc_threedm_gnss_assisted_fix_control_t *out) {
    mipc_rd_push(r, "function");
    if (mipc_rd_u8(r, &out->function)) {
        return -1;
    }
    mipc_rd_pop(r);
    if (r->pos < r->len) {
        out->has_option = true;
        mipc_rd_push(r, "option");
        if (mipc_rd_u8(r, &out->option)) {
            return -1;
        }
        mipc_rd_pop(r);
    }
    if (r->pos < r->len) {
        out->has_flags = true;
        mipc_rd_push(r, "flags");
        if (mipc_rd_u8(r, &out->flags)) {
            return -1;
        }
        mipc_rd_pop(r);
    }
    return mipc_rd_finish(r);
}

static mipc_status_t
mipc_threedm_gnss_assisted_fix_control_write(mipc_writer_t *w,
                                             const mipc_threedm_gnss_assisted_fix_control_t *in) {
    mipc_status_t st;
    int absent = 0;
    if ((st = mipc_wr_u8(w, &in->function)) != MIPC_OK) {
        return st;
    }
    if (!in->has_option) {
        absent = 1;
    } else if (absent) {
        return MIPC_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = mipc_wr_u8(w, &in->option)) != MIPC_OK) {
            return st;
        }
    }
    if (!in->has_flags) {
        absent = 1;
    } else if (absent) {
        return MIPC_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = mipc_wr_u8(w, &in->flags)) != MIPC_OK) {
            return st;
        }
    }
    return MIPC_OK;
}

mipc_status_t
mipc_threedm_gnss_assisted_fix_control_encode(const mipc_threedm_gnss_assisted_fix_control_t *value,
                                              uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    mipc_writer_init(&w, buf, cap);
    st = mipc_threedm_gnss_assisted_fix_control_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mipc_status_t mipc_threedm_gnss_assisted_fix_control_decode(const uint8_t *data, size_t len,
                                                            mipc_threedm_gnss_assisted_fix_control_t *out,
                                                            mipc_decode_error_t *err) {
    mipc_reader_t r;
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_threedm_gnss_assisted_fix_control_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

void mipc_threedm_gnss_assisted_fix_control_to_json(mipc_jw_t *w,
                                                    const mipc_threedm_gnss_assisted_fix_control_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "function");
    mipc_jw_u8(w, &in->function);
    if (in->has_option) {
        mipc_jw_key(w, &first, "option");
        mipc_jw_u8(w, &in->option);
    }
    if (in->has_flags) {
        mipc_jw_key(w, &first, "flags");
        mipc_jw_u8(w, &in->flags);
    }
    mipc_jw_raw(w, "}", 1);
}

int mipc_threedm_gnss_assisted_fix_control_from_json(mipc_jr_t *jr, size_t pos,
                                                     mipc_threedm_gnss_assisted_fix_control_t *out) {
    static const char *const keys[] = {"function", "option", "flags"};
    size_t vp = 0;
    int found;
    int absent = 0;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 3)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "function", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"function\"");
    }
    {
        mipc_jr_push(jr, "function");
        if (mipc_jr_u8(jr, vp, &out->function)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "option", &vp);
    out->has_option = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mipc_jr_fail(jr, "optional parameter \"option\" given after an absent one");
    } else {
        mipc_jr_push(jr, "option");
        if (mipc_jr_u8(jr, vp, &out->option)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "flags", &vp);
    out->has_flags = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mipc_jr_fail(jr, "optional parameter \"flags\" given after an absent one");
    } else {
        mipc_jr_push(jr, "flags");
        if (mipc_jr_u8(jr, vp, &out->flags)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mipc_threedm_gnss_assisted_fix_control_response_t */

static int
mipc_threedm_gnss_assisted_fix_control_response_read(mipc_reader_t *r,
                                                     mipc_threedm_gnss_assisted_fix_control_response_t *out) {
    mipc_rd_push(r, "option");
    if (mipc_rd_u8(r, &out->option)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "flags");
    if (mipc_rd_u8(r, &out->flags)) {
        return -1;
    }
    mipc_rd_pop(r);
    return mipc_rd_finish(r);
}

static mipc_status_t mipc_threedm_gnss_assisted_fix_control_response_write(
    mipc_writer_t *w, const mipc_threedm_gnss_assisted_fix_control_response_t *in) {
    mipc_status_t st;
    if ((st = mipc_wr_u8(w, &in->option)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u8(w, &in->flags)) != MIPC_OK) {
        return st;
    }
    return MIPC_OK;
}

mipc_status_t mipc_threedm_gnss_assisted_fix_control_response_encode(
    const mipc_threedm_gnss_assisted_fix_control_response_t *value, uint8_t *buf, size_t cap,
    size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    mipc_writer_init(&w, buf, cap);
    st = mipc_threedm_gnss_assisted_fix_control_response_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 2 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int
mipc_threedm_gnss_assisted_fix_control_response_load(const uint8_t *d,
                                                     mipc_threedm_gnss_assisted_fix_control_response_t *out) {
    out->option = mipc_ld_u8(d + 0);
    out->flags = mipc_ld_u8(d + 1);
    return 0;
}

/* The general reader: lengths other than 2, bad bool bytes, error details. */
static MIPC_NOINLINE mipc_status_t mipc_threedm_gnss_assisted_fix_control_response_decode_read(
    const uint8_t *data, size_t len, mipc_threedm_gnss_assisted_fix_control_response_t *out,
    mipc_decode_error_t *err) {
    mipc_reader_t r;
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_threedm_gnss_assisted_fix_control_response_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t
mipc_threedm_gnss_assisted_fix_control_response_decode(const uint8_t *data, size_t len,
                                                       mipc_threedm_gnss_assisted_fix_control_response_t *out,
                                                       mipc_decode_error_t *err) {
    if (len == 2 && mipc_threedm_gnss_assisted_fix_control_response_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_threedm_gnss_assisted_fix_control_response_decode_read(data, len, out, err);
}

void mipc_threedm_gnss_assisted_fix_control_response_to_json(
    mipc_jw_t *w, const mipc_threedm_gnss_assisted_fix_control_response_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "option");
    mipc_jw_u8(w, &in->option);
    mipc_jw_key(w, &first, "flags");
    mipc_jw_u8(w, &in->flags);
    mipc_jw_raw(w, "}", 1);
}

int mipc_threedm_gnss_assisted_fix_control_response_from_json(
    mipc_jr_t *jr, size_t pos, mipc_threedm_gnss_assisted_fix_control_response_t *out) {
    static const char *const keys[] = {"option", "flags"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 2)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "option", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"option\"");
    }
    {
        mipc_jr_push(jr, "option");
        if (mipc_jr_u8(jr, vp, &out->option)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "flags", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"flags\"");
    }
    {
        mipc_jr_push(jr, "flags");
        if (mipc_jr_u8(jr, vp, &out->flags)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mipc_threedm_gnss_assist_time_update_t */

static int mipc_threedm_gnss_assist_time_update_read(mipc_reader_t *r,
                                                     mipc_threedm_gnss_assist_time_update_t *out) {
    mipc_rd_push(r, "function");
    if (mipc_rd_u8(r, &out->function)) {
        return -1;
    }
    mipc_rd_pop(r);
    if (r->pos < r->len) {
        out->has_tow = true;
        mipc_rd_push(r, "tow");
        if (mipc_rd_f64(r, &out->tow)) {
            return -1;
        }
        mipc_rd_pop(r);
    }
    if (r->pos < r->len) {
        out->has_week_number = true;
        mipc_rd_push(r, "week_number");
        if (mipc_rd_u16(r, &out->week_number)) {
            return -1;
        }
        mipc_rd_pop(r);
    }
    if (r->pos < r->len) {
        out->has_accuracy = true;
        mipc_rd_push(r, "accuracy");
        if (mipc_rd_f32(r, &out->accuracy)) {
            return -1;
        }
        mipc_rd_pop(r);
    }
    return mipc_rd_finish(r);
}

static mipc_status_t
mipc_threedm_gnss_assist_time_update_write(mipc_writer_t *w,
                                           const mipc_threedm_gnss_assist_time_update_t *in) {
    mipc_status_t st;
    int absent = 0;
    if ((st = mipc_wr_u8(w, &in->function)) != MIPC_OK) {
        return st;
    }
    if (!in->has_tow) {
        absent = 1;
    } else if (absent) {
        return MIPC_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = mipc_wr_f64(w, &in->tow)) != MIPC_OK) {
            return st;
        }
    }
    if (!in->has_week_number) {
        absent = 1;
    } else if (absent) {
        return MIPC_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = mipc_wr_u16(w, &in->week_number)) != MIPC_OK) {
            return st;
        }
    }
    if (!in->has_accuracy) {
        absent = 1;
    } else if (absent) {
        return MIPC_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = mipc_wr_f32(w, &in->accuracy)) != MIPC_OK) {
            return st;
        }
    }
    return MIPC_OK;
}

mipc_status_t mipc_threedm_gnss_assist_time_update_encode(const mipc_threedm_gnss_assist_time_update_t *value,
                                                          uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    mipc_writer_init(&w, buf, cap);
    st = mipc_threedm_gnss_assist_time_update_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mipc_status_t mipc_threedm_gnss_assist_time_update_decode(const uint8_t *data, size_t len,
                                                          mipc_threedm_gnss_assist_time_update_t *out,
                                                          mipc_decode_error_t *err) {
    mipc_reader_t r;
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_threedm_gnss_assist_time_update_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

void mipc_threedm_gnss_assist_time_update_to_json(mipc_jw_t *w,
                                                  const mipc_threedm_gnss_assist_time_update_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "function");
    mipc_jw_u8(w, &in->function);
    if (in->has_tow) {
        mipc_jw_key(w, &first, "tow");
        mipc_jw_f64(w, &in->tow);
    }
    if (in->has_week_number) {
        mipc_jw_key(w, &first, "week_number");
        mipc_jw_u16(w, &in->week_number);
    }
    if (in->has_accuracy) {
        mipc_jw_key(w, &first, "accuracy");
        mipc_jw_f32(w, &in->accuracy);
    }
    mipc_jw_raw(w, "}", 1);
}

int mipc_threedm_gnss_assist_time_update_from_json(mipc_jr_t *jr, size_t pos,
                                                   mipc_threedm_gnss_assist_time_update_t *out) {
    static const char *const keys[] = {"function", "tow", "week_number", "accuracy"};
    size_t vp = 0;
    int found;
    int absent = 0;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 4)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "function", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"function\"");
    }
    {
        mipc_jr_push(jr, "function");
        if (mipc_jr_u8(jr, vp, &out->function)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "tow", &vp);
    out->has_tow = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mipc_jr_fail(jr, "optional parameter \"tow\" given after an absent one");
    } else {
        mipc_jr_push(jr, "tow");
        if (mipc_jr_f64(jr, vp, &out->tow)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "week_number", &vp);
    out->has_week_number = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mipc_jr_fail(jr, "optional parameter \"week_number\" given after an absent one");
    } else {
        mipc_jr_push(jr, "week_number");
        if (mipc_jr_u16(jr, vp, &out->week_number)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "accuracy", &vp);
    out->has_accuracy = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mipc_jr_fail(jr, "optional parameter \"accuracy\" given after an absent one");
    } else {
        mipc_jr_push(jr, "accuracy");
        if (mipc_jr_f32(jr, vp, &out->accuracy)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mipc_threedm_gnss_assist_time_update_response_t */

static int
mipc_threedm_gnss_assist_time_update_response_read(mipc_reader_t *r,
                                                   mipc_threedm_gnss_assist_time_update_response_t *out) {
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
    mipc_rd_push(r, "accuracy");
    if (mipc_rd_f32(r, &out->accuracy)) {
        return -1;
    }
    mipc_rd_pop(r);
    return mipc_rd_finish(r);
}

static mipc_status_t mipc_threedm_gnss_assist_time_update_response_write(
    mipc_writer_t *w, const mipc_threedm_gnss_assist_time_update_response_t *in) {
    mipc_status_t st;
    if ((st = mipc_wr_f64(w, &in->tow)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u16(w, &in->week_number)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_f32(w, &in->accuracy)) != MIPC_OK) {
        return st;
    }
    return MIPC_OK;
}

mipc_status_t mipc_threedm_gnss_assist_time_update_response_encode(
    const mipc_threedm_gnss_assist_time_update_response_t *value, uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    mipc_writer_init(&w, buf, cap);
    st = mipc_threedm_gnss_assist_time_update_response_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 14 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int
mipc_threedm_gnss_assist_time_update_response_load(const uint8_t *d,
                                                   mipc_threedm_gnss_assist_time_update_response_t *out) {
    out->tow = mipc_ld_f64(d + 0);
    out->week_number = mipc_ld_u16(d + 8);
    out->accuracy = mipc_ld_f32(d + 10);
    return 0;
}

/* The general reader: lengths other than 14, bad bool bytes, error details. */
static MIPC_NOINLINE mipc_status_t mipc_threedm_gnss_assist_time_update_response_decode_read(
    const uint8_t *data, size_t len, mipc_threedm_gnss_assist_time_update_response_t *out,
    mipc_decode_error_t *err) {
    mipc_reader_t r;
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_threedm_gnss_assist_time_update_response_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t
mipc_threedm_gnss_assist_time_update_response_decode(const uint8_t *data, size_t len,
                                                     mipc_threedm_gnss_assist_time_update_response_t *out,
                                                     mipc_decode_error_t *err) {
    if (len == 14 && mipc_threedm_gnss_assist_time_update_response_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_threedm_gnss_assist_time_update_response_decode_read(data, len, out, err);
}

void mipc_threedm_gnss_assist_time_update_response_to_json(
    mipc_jw_t *w, const mipc_threedm_gnss_assist_time_update_response_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "tow");
    mipc_jw_f64(w, &in->tow);
    mipc_jw_key(w, &first, "week_number");
    mipc_jw_u16(w, &in->week_number);
    mipc_jw_key(w, &first, "accuracy");
    mipc_jw_f32(w, &in->accuracy);
    mipc_jw_raw(w, "}", 1);
}

int mipc_threedm_gnss_assist_time_update_response_from_json(
    mipc_jr_t *jr, size_t pos, mipc_threedm_gnss_assist_time_update_response_t *out) {
    static const char *const keys[] = {"tow", "week_number", "accuracy"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 3)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "tow", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"tow\"");
    }
    {
        mipc_jr_push(jr, "tow");
        if (mipc_jr_f64(jr, vp, &out->tow)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "week_number", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"week_number\"");
    }
    {
        mipc_jr_push(jr, "week_number");
        if (mipc_jr_u16(jr, vp, &out->week_number)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "accuracy", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"accuracy\"");
    }
    {
        mipc_jr_push(jr, "accuracy");
        if (mipc_jr_f32(jr, vp, &out->accuracy)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mipc_threedm_pps_source_t */

static int mipc_threedm_pps_source_read(mipc_reader_t *r, mipc_threedm_pps_source_t *out) {
    mipc_rd_push(r, "function");
    if (mipc_rd_u8(r, &out->function)) {
        return -1;
    }
    mipc_rd_pop(r);
    if (r->pos < r->len) {
        out->has_source = true;
        mipc_rd_push(r, "source");
        if (mipc_rd_u8(r, &out->source)) {
            return -1;
        }
        mipc_rd_pop(r);
    }
    return mipc_rd_finish(r);
}

static mipc_status_t mipc_threedm_pps_source_write(mipc_writer_t *w, const mipc_threedm_pps_source_t *in) {
    mipc_status_t st;
    int absent = 0;
    if ((st = mipc_wr_u8(w, &in->function)) != MIPC_OK) {
        return st;
    }
    if (!in->has_source) {
        absent = 1;
    } else if (absent) {
        return MIPC_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = mipc_wr_u8(w, &in->source)) != MIPC_OK) {
            return st;
        }
    }
    return MIPC_OK;
}

mipc_status_t mipc_threedm_pps_source_encode(const mipc_threedm_pps_source_t *value, uint8_t *buf, size_t cap,
                                             size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    mipc_writer_init(&w, buf, cap);
    st = mipc_threedm_pps_source_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mipc_status_t mipc_threedm_pps_source_decode(const uint8_t *data, size_t len, mipc_threedm_pps_source_t *out,
                                             mipc_decode_error_t *err) {
    mipc_reader_t r;
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_threedm_pps_source_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

void mipc_threedm_pps_source_to_json(mipc_jw_t *w, const mipc_threedm_pps_source_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "function");
    mipc_jw_u8(w, &in->function);
    if (in->has_source) {
        mipc_jw_key(w, &first, "source");
        mipc_jw_u8(w, &in->source);
    }
    mipc_jw_raw(w, "}", 1);
}

int mipc_threedm_pps_source_from_json(mipc_jr_t *jr, size_t pos, mipc_threedm_pps_source_t *out) {
    static const char *const keys[] = {"function", "source"};
    size_t vp = 0;
    int found;
    int absent = 0;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 2)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "function", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"function\"");
    }
    {
        mipc_jr_push(jr, "function");
        if (mipc_jr_u8(jr, vp, &out->function)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "source", &vp);
    out->has_source = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mipc_jr_fail(jr, "optional parameter \"source\" given after an absent one");
    } else {
        mipc_jr_push(jr, "source");
        if (mipc_jr_u8(jr, vp, &out->source)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mipc_threedm_pps_source_response_t */

static int mipc_threedm_pps_source_response_read(mipc_reader_t *r, mipc_threedm_pps_source_response_t *out) {
    mipc_rd_push(r, "source");
    if (mipc_rd_u8(r, &out->source)) {
        return -1;
    }
    mipc_rd_pop(r);
    return mipc_rd_finish(r);
}

static mipc_status_t mipc_threedm_pps_source_response_write(mipc_writer_t *w,
                                                            const mipc_threedm_pps_source_response_t *in) {
    mipc_status_t st;
    if ((st = mipc_wr_u8(w, &in->source)) != MIPC_OK) {
        return st;
    }
    return MIPC_OK;
}

mipc_status_t mipc_threedm_pps_source_response_encode(const mipc_threedm_pps_source_response_t *value,
                                                      uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    mipc_writer_init(&w, buf, cap);
    st = mipc_threedm_pps_source_response_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 1 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mipc_threedm_pps_source_response_load(const uint8_t *d, mipc_threedm_pps_source_response_t *out) {
    out->source = mipc_ld_u8(d + 0);
    return 0;
}

/* The general reader: lengths other than 1, bad bool bytes, error details. */
static MIPC_NOINLINE mipc_status_t mipc_threedm_pps_source_response_decode_read(
    const uint8_t *data, size_t len, mipc_threedm_pps_source_response_t *out, mipc_decode_error_t *err) {
    mipc_reader_t r;
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_threedm_pps_source_response_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t mipc_threedm_pps_source_response_decode(const uint8_t *data, size_t len,
                                                      mipc_threedm_pps_source_response_t *out,
                                                      mipc_decode_error_t *err) {
    if (len == 1 && mipc_threedm_pps_source_response_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_threedm_pps_source_response_decode_read(data, len, out, err);
}

void mipc_threedm_pps_source_response_to_json(mipc_jw_t *w, const mipc_threedm_pps_source_response_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "source");
    mipc_jw_u8(w, &in->source);
    mipc_jw_raw(w, "}", 1);
}

int mipc_threedm_pps_source_response_from_json(mipc_jr_t *jr, size_t pos,
                                               mipc_threedm_pps_source_response_t *out) {
    static const char *const keys[] = {"source"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 1)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "source", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"source\"");
    }
    {
        mipc_jr_push(jr, "source");
        if (mipc_jr_u8(jr, vp, &out->source)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mipc_threedm_get_supported_events_t */

static int mipc_threedm_get_supported_events_read(mipc_reader_t *r,
                                                  mipc_threedm_get_supported_events_t *out) {
    mipc_rd_push(r, "query");
    if (mipc_rd_u8(r, &out->query)) {
        return -1;
    }
    mipc_rd_pop(r);
    return mipc_rd_finish(r);
}

static mipc_status_t mipc_threedm_get_supported_events_write(mipc_writer_t *w,
                                                             const mipc_threedm_get_supported_events_t *in) {
    mipc_status_t st;
    if ((st = mipc_wr_u8(w, &in->query)) != MIPC_OK) {
        return st;
    }
    return MIPC_OK;
}

mipc_status_t mipc_threedm_get_supported_events_encode(const mipc_threedm_get_supported_events_t *value,
                                                       uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    mipc_writer_init(&w, buf, cap);
    st = mipc_threedm_get_supported_events_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 1 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mipc_threedm_get_supported_events_load(const uint8_t *d,
                                                  mipc_threedm_get_supported_events_t *out) {
    out->query = mipc_ld_u8(d + 0);
    return 0;
}

/* The general reader: lengths other than 1, bad bool bytes, error details. */
static MIPC_NOINLINE mipc_status_t mipc_threedm_get_supported_events_decode_read(
    const uint8_t *data, size_t len, mipc_threedm_get_supported_events_t *out, mipc_decode_error_t *err) {
    mipc_reader_t r;
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_threedm_get_supported_events_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t mipc_threedm_get_supported_events_decode(const uint8_t *data, size_t len,
                                                       mipc_threedm_get_supported_events_t *out,
                                                       mipc_decode_error_t *err) {
    if (len == 1 && mipc_threedm_get_supported_events_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_threedm_get_supported_events_decode_read(data, len, out, err);
}

void mipc_threedm_get_supported_events_to_json(mipc_jw_t *w, const mipc_threedm_get_supported_events_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "query");
    mipc_jw_u8(w, &in->query);
    mipc_jw_raw(w, "}", 1);
}

int mipc_threedm_get_supported_events_from_json(mipc_jr_t *jr, size_t pos,
                                                mipc_threedm_get_supported_events_t *out) {
    static const char *const keys[] = {"query"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 1)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "query", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"query\"");
    }
    {
        mipc_jr_push(jr, "query");
        if (mipc_jr_u8(jr, vp, &out->query)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mipc_threedm_supported_events_t */

static int mipc_threedm_supported_events_read(mipc_reader_t *r, mipc_threedm_supported_events_t *out) {
    mipc_rd_push(r, "query");
    if (mipc_rd_u8(r, &out->query)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "info");
    if (mipc_supported_events_info_read(r, out->query, &out->info)) {
        return -1;
    }
    mipc_rd_pop(r);
    return mipc_rd_finish(r);
}

static mipc_status_t mipc_threedm_supported_events_write(mipc_writer_t *w,
                                                         const mipc_threedm_supported_events_t *in) {
    mipc_status_t st;
    if ((st = mipc_wr_u8(w, &in->query)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_supported_events_info_write(w, in->query, &in->info)) != MIPC_OK) {
        return st;
    }
    return MIPC_OK;
}

mipc_status_t mipc_threedm_supported_events_encode(const mipc_threedm_supported_events_t *value, uint8_t *buf,
                                                   size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    mipc_writer_init(&w, buf, cap);
    st = mipc_threedm_supported_events_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mipc_status_t mipc_threedm_supported_events_decode(const uint8_t *data, size_t len,
                                                   mipc_threedm_supported_events_t *out,
                                                   mipc_decode_error_t *err) {
    mipc_reader_t r;
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_threedm_supported_events_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

void mipc_threedm_supported_events_to_json(mipc_jw_t *w, const mipc_threedm_supported_events_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "query");
    mipc_jw_u8(w, &in->query);
    mipc_jw_key(w, &first, "info");
    mipc_supported_events_info_to_json(w, in->query, &in->info);
    mipc_jw_raw(w, "}", 1);
}

int mipc_threedm_supported_events_from_json(mipc_jr_t *jr, size_t pos, mipc_threedm_supported_events_t *out) {
    static const char *const keys[] = {"query", "info"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 2)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "query", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"query\"");
    }
    {
        mipc_jr_push(jr, "query");
        if (mipc_jr_u8(jr, vp, &out->query)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "info", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"info\"");
    }
    {
        mipc_jr_push(jr, "info");
        if (mipc_supported_events_info_from_json(jr, vp, out->query, &out->info)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mipc_threedm_device_status_t */

static int mipc_threedm_device_status_read(mipc_reader_t *r, mipc_threedm_device_status_t *out) {
    mipc_rd_push(r, "model_number");
    if (mipc_rd_u16(r, &out->model_number)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "status_selector");
    if (mipc_rd_u8(r, &out->status_selector)) {
        return -1;
    }
    mipc_rd_pop(r);
    return mipc_rd_finish(r);
}

static mipc_status_t mipc_threedm_device_status_write(mipc_writer_t *w,
                                                      const mipc_threedm_device_status_t *in) {
    mipc_status_t st;
    if ((st = mipc_wr_u16(w, &in->model_number)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u8(w, &in->status_selector)) != MIPC_OK) {
        return st;
    }
    return MIPC_OK;
}

mipc_status_t mipc_threedm_device_status_encode(const mipc_threedm_device_status_t *value, uint8_t *buf,
                                                size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    mipc_writer_init(&w, buf, cap);
    st = mipc_threedm_device_status_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 3 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mipc_threedm_device_status_load(const uint8_t *d, mipc_threedm_device_status_t *out) {
    out->model_number = mipc_ld_u16(d + 0);
    out->status_selector = mipc_ld_u8(d + 2);
    return 0;
}

/* The general reader: lengths other than 3, bad bool bytes, error details. */
static MIPC_NOINLINE mipc_status_t mipc_threedm_device_status_decode_read(const uint8_t *data, size_t len,
                                                                          mipc_threedm_device_status_t *out,
                                                                          mipc_decode_error_t *err) {
    mipc_reader_t r;
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_threedm_device_status_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t mipc_threedm_device_status_decode(const uint8_t *data, size_t len,
                                                mipc_threedm_device_status_t *out, mipc_decode_error_t *err) {
    if (len == 3 && mipc_threedm_device_status_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_threedm_device_status_decode_read(data, len, out, err);
}

void mipc_threedm_device_status_to_json(mipc_jw_t *w, const mipc_threedm_device_status_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "model_number");
    mipc_jw_u16(w, &in->model_number);
    mipc_jw_key(w, &first, "status_selector");
    mipc_jw_u8(w, &in->status_selector);
    mipc_jw_raw(w, "}", 1);
}

int mipc_threedm_device_status_from_json(mipc_jr_t *jr, size_t pos, mipc_threedm_device_status_t *out) {
    static const char *const keys[] = {"model_number", "status_selector"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 2)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "model_number", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"model_number\"");
    }
    {
        mipc_jr_push(jr, "model_number");
        if (mipc_jr_u16(jr, vp, &out->model_number)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "status_selector", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"status_selector\"");
    }
    {
        mipc_jr_push(jr, "status_selector");
        if (mipc_jr_u8(jr, vp, &out->status_selector)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mipc_threedm_device_status_response_t */

static int mipc_threedm_device_status_response_read(mipc_reader_t *r,
                                                    mipc_threedm_device_status_response_t *out) {
    mipc_rd_push(r, "model_number");
    if (mipc_rd_u16(r, &out->model_number)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "status_selector");
    if (mipc_rd_u8(r, &out->status_selector)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "status");
    if (mipc_gx5_device_status_read(r, out->status_selector, &out->status)) {
        return -1;
    }
    mipc_rd_pop(r);
    return mipc_rd_finish(r);
}

static mipc_status_t
mipc_threedm_device_status_response_write(mipc_writer_t *w, const mipc_threedm_device_status_response_t *in) {
    mipc_status_t st;
    if ((st = mipc_wr_u16(w, &in->model_number)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u8(w, &in->status_selector)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_gx5_device_status_write(w, in->status_selector, &in->status)) != MIPC_OK) {
        return st;
    }
    return MIPC_OK;
}

mipc_status_t mipc_threedm_device_status_response_encode(const mipc_threedm_device_status_response_t *value,
                                                         uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    mipc_writer_init(&w, buf, cap);
    st = mipc_threedm_device_status_response_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mipc_status_t mipc_threedm_device_status_response_decode(const uint8_t *data, size_t len,
                                                         mipc_threedm_device_status_response_t *out,
                                                         mipc_decode_error_t *err) {
    mipc_reader_t r;
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_threedm_device_status_response_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

void mipc_threedm_device_status_response_to_json(mipc_jw_t *w,
                                                 const mipc_threedm_device_status_response_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "model_number");
    mipc_jw_u16(w, &in->model_number);
    mipc_jw_key(w, &first, "status_selector");
    mipc_jw_u8(w, &in->status_selector);
    mipc_jw_key(w, &first, "status");
    mipc_gx5_device_status_to_json(w, in->status_selector, &in->status);
    mipc_jw_raw(w, "}", 1);
}

int mipc_threedm_device_status_response_from_json(mipc_jr_t *jr, size_t pos,
                                                  mipc_threedm_device_status_response_t *out) {
    static const char *const keys[] = {"model_number", "status_selector", "status"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 3)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "model_number", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"model_number\"");
    }
    {
        mipc_jr_push(jr, "model_number");
        if (mipc_jr_u16(jr, vp, &out->model_number)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "status_selector", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"status_selector\"");
    }
    {
        mipc_jr_push(jr, "status_selector");
        if (mipc_jr_u8(jr, vp, &out->status_selector)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "status", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"status\"");
    }
    {
        mipc_jr_push(jr, "status");
        if (mipc_gx5_device_status_from_json(jr, vp, out->status_selector, &out->status)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    return 0;
}
