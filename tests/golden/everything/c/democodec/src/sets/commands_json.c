/* Canonical JSON of Commands (the democodec_json library). Generated from the spec: do not edit. */
#include "democodec/sets/commands.h"
#include "layouts_internal.h"
#include "types_internal.h"

#include <assert.h>
#include <string.h>

/* ---- democ_commands_ping_t */

void democ_commands_ping_to_json(democ_jw_t *w, const democ_commands_ping_t *in) {
    int first = 1;
    democ_jw_raw(w, "{", 1);
    democ_jw_raw(w, "}", 1);
    (void)in;
    (void)first;
}

int democ_commands_ping_from_json(democ_jr_t *jr, size_t pos, democ_commands_ping_t *out) {
    memset(out, 0, sizeof *out);
    if (democ_jr_object(jr, pos, NULL, 0)) {
        return -1;
    }
    return 0;
}

/* ---- democ_commands_configure_t */

void democ_commands_configure_to_json(democ_jw_t *w, const democ_commands_configure_t *in) {
    int first = 1;
    democ_jw_raw(w, "{", 1);
    democ_jw_key(w, &first, "function");
    democ_jw_u8(w, &in->function);
    democ_jw_key(w, &first, "instance");
    democ_jw_u8(w, &in->instance);
    if (in->has_mode) {
        democ_jw_key(w, &first, "mode");
        democ_jw_u8(w, &in->mode);
    }
    if (in->has_params) {
        democ_jw_key(w, &first, "params");
        democ_trigger_params_to_json(w, in->mode, &in->params);
    }
    if (in->has_suppress_ack) {
        democ_jw_key(w, &first, "suppress_ack");
        democ_jw_bool(w, &in->suppress_ack);
    }
    democ_jw_raw(w, "}", 1);
}

int democ_commands_configure_from_json(democ_jr_t *jr, size_t pos, democ_commands_configure_t *out) {
    static const char *const keys[] = {"function", "instance", "mode", "params", "suppress_ack"};
    size_t vp = 0;
    int found;
    int absent = 0;
    memset(out, 0, sizeof *out);
    if (democ_jr_object(jr, pos, keys, 5)) {
        return -1;
    }
    found = democ_jr_get(jr, pos, "function", &vp);
    if (found != 1) {
        return democ_jr_fail(jr, "missing parameter \"function\"");
    }
    {
        democ_jr_push(jr, "function");
        if (democ_jr_u8(jr, vp, &out->function)) {
            return -1;
        }
        democ_jr_pop(jr);
    }
    found = democ_jr_get(jr, pos, "instance", &vp);
    if (found != 1) {
        return democ_jr_fail(jr, "missing parameter \"instance\"");
    }
    {
        democ_jr_push(jr, "instance");
        if (democ_jr_u8(jr, vp, &out->instance)) {
            return -1;
        }
        democ_jr_pop(jr);
    }
    found = democ_jr_get(jr, pos, "mode", &vp);
    out->has_mode = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return democ_jr_fail(jr, "optional parameter \"mode\" given after an absent one");
    } else {
        democ_jr_push(jr, "mode");
        if (democ_jr_u8(jr, vp, &out->mode)) {
            return -1;
        }
        democ_jr_pop(jr);
    }
    found = democ_jr_get(jr, pos, "params", &vp);
    out->has_params = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return democ_jr_fail(jr, "optional parameter \"params\" given after an absent one");
    } else {
        democ_jr_push(jr, "params");
        if (democ_trigger_params_from_json(jr, vp, out->mode, &out->params)) {
            return -1;
        }
        democ_jr_pop(jr);
    }
    found = democ_jr_get(jr, pos, "suppress_ack", &vp);
    out->has_suppress_ack = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return democ_jr_fail(jr, "optional parameter \"suppress_ack\" given after an absent one");
    } else {
        democ_jr_push(jr, "suppress_ack");
        if (democ_jr_bool(jr, vp, &out->suppress_ack)) {
            return -1;
        }
        democ_jr_pop(jr);
    }
    return 0;
}

/* ---- democ_commands_configuration_t */

void democ_commands_configuration_to_json(democ_jw_t *w, const democ_commands_configuration_t *in) {
    int first = 1;
    size_t i;
    democ_jw_raw(w, "{", 1);
    democ_jw_key(w, &first, "instance");
    democ_jw_u8(w, &in->instance);
    democ_jw_key(w, &first, "count");
    democ_jw_u8(w, &in->count);
    democ_jw_key(w, &first, "rates");
    democ_jw_raw(w, "[", 1);
    for (i = 0; i < (size_t)in->count && i < 10; i++) {
        democ_jw_sep(w, i);
        democ_jw_u16(w, &in->rates[i]);
    }
    democ_jw_raw(w, "]", 1);
    democ_jw_key(w, &first, "name");
    democ_jw_chars(w, in->name, 8);
    democ_jw_key(w, &first, "label");
    democ_jw_chars(w, in->label, 16);
    democ_jw_key(w, &first, "matrix");
    democ_jw_raw(w, "[", 1);
    for (i = 0; i < 9; i++) {
        democ_jw_sep(w, i);
        democ_jw_f64(w, &in->matrix[i]);
    }
    democ_jw_raw(w, "]", 1);
    democ_jw_key(w, &first, "fixed");
    democ_jw_raw(w, "[", 1);
    for (i = 0; i < 4; i++) {
        democ_jw_sep(w, i);
        democ_jw_s32(w, &in->fixed[i]);
    }
    democ_jw_raw(w, "]", 1);
    democ_jw_key(w, &first, "flags");
    democ_jw_u16(w, &in->flags);
    democ_jw_key(w, &first, "signed");
    democ_jw_s16(w, &in->signed_);
    democ_jw_key(w, &first, "tail");
    democ_jw_raw(w, "[", 1);
    for (i = 0; i < (size_t)in->tail_count && i < 135; i++) {
        democ_jw_sep(w, i);
        democ_jw_char(w, &in->tail[i]);
    }
    democ_jw_raw(w, "]", 1);
    democ_jw_raw(w, "}", 1);
}

int democ_commands_configuration_from_json(democ_jr_t *jr, size_t pos, democ_commands_configuration_t *out) {
    static const char *const keys[] = {"instance", "count", "rates", "name",   "label",
                                       "matrix",   "fixed", "flags", "signed", "tail"};
    size_t vp = 0;
    int found;
    size_t i;
    size_t it = 0;
    size_t ep = 0;
    memset(out, 0, sizeof *out);
    if (democ_jr_object(jr, pos, keys, 10)) {
        return -1;
    }
    found = democ_jr_get(jr, pos, "instance", &vp);
    if (found != 1) {
        return democ_jr_fail(jr, "missing parameter \"instance\"");
    }
    {
        democ_jr_push(jr, "instance");
        if (democ_jr_u8(jr, vp, &out->instance)) {
            return -1;
        }
        democ_jr_pop(jr);
    }
    found = democ_jr_get(jr, pos, "count", &vp);
    if (found != 1) {
        return democ_jr_fail(jr, "missing parameter \"count\"");
    }
    {
        democ_jr_push(jr, "count");
        if (democ_jr_u8(jr, vp, &out->count)) {
            return -1;
        }
        democ_jr_pop(jr);
    }
    found = democ_jr_get(jr, pos, "rates", &vp);
    if (found != 1) {
        return democ_jr_fail(jr, "missing parameter \"rates\"");
    }
    {
        democ_jr_push(jr, "rates");
        if (democ_jr_array(jr, vp, &it)) {
            return -1;
        }
        for (i = 0;; i++) {
            int more = democ_jr_next(jr, &it, &ep);
            if (more < 0) {
                return -1;
            }
            if (!more) {
                break;
            }
            if (i >= 10) {
                return democ_jr_fail(jr, "more than 10 elements");
            }
            democ_jr_index(jr, i);
            if (democ_jr_u16(jr, ep, &out->rates[i])) {
                return -1;
            }
        }
        democ_jr_index(jr, SIZE_MAX);
        if (i != (size_t)out->count) {
            return democ_jr_fail(jr, "%zu elements but count is %zu", i, (size_t)out->count);
        }
        democ_jr_pop(jr);
    }
    found = democ_jr_get(jr, pos, "name", &vp);
    if (found != 1) {
        return democ_jr_fail(jr, "missing parameter \"name\"");
    }
    {
        democ_jr_push(jr, "name");
        if (democ_jr_chars(jr, vp, out->name, 8)) {
            return -1;
        }
        democ_jr_pop(jr);
    }
    found = democ_jr_get(jr, pos, "label", &vp);
    if (found != 1) {
        return democ_jr_fail(jr, "missing parameter \"label\"");
    }
    {
        democ_jr_push(jr, "label");
        if (democ_jr_chars(jr, vp, out->label, 16)) {
            return -1;
        }
        democ_jr_pop(jr);
    }
    found = democ_jr_get(jr, pos, "matrix", &vp);
    if (found != 1) {
        return democ_jr_fail(jr, "missing parameter \"matrix\"");
    }
    {
        democ_jr_push(jr, "matrix");
        if (democ_jr_array(jr, vp, &it)) {
            return -1;
        }
        for (i = 0;; i++) {
            int more = democ_jr_next(jr, &it, &ep);
            if (more < 0) {
                return -1;
            }
            if (!more) {
                break;
            }
            if (i >= 9) {
                return democ_jr_fail(jr, "more than 9 elements");
            }
            democ_jr_index(jr, i);
            if (democ_jr_f64(jr, ep, &out->matrix[i])) {
                return -1;
            }
        }
        democ_jr_index(jr, SIZE_MAX);
        if (i != 9) {
            return democ_jr_fail(jr, "expected 9 elements, got %zu", i);
        }
        democ_jr_pop(jr);
    }
    found = democ_jr_get(jr, pos, "fixed", &vp);
    if (found != 1) {
        return democ_jr_fail(jr, "missing parameter \"fixed\"");
    }
    {
        democ_jr_push(jr, "fixed");
        if (democ_jr_array(jr, vp, &it)) {
            return -1;
        }
        for (i = 0;; i++) {
            int more = democ_jr_next(jr, &it, &ep);
            if (more < 0) {
                return -1;
            }
            if (!more) {
                break;
            }
            if (i >= 4) {
                return democ_jr_fail(jr, "more than 4 elements");
            }
            democ_jr_index(jr, i);
            if (democ_jr_s32(jr, ep, &out->fixed[i])) {
                return -1;
            }
        }
        democ_jr_index(jr, SIZE_MAX);
        if (i != 4) {
            return democ_jr_fail(jr, "expected 4 elements, got %zu", i);
        }
        democ_jr_pop(jr);
    }
    found = democ_jr_get(jr, pos, "flags", &vp);
    if (found != 1) {
        return democ_jr_fail(jr, "missing parameter \"flags\"");
    }
    {
        democ_jr_push(jr, "flags");
        if (democ_jr_u16(jr, vp, &out->flags)) {
            return -1;
        }
        democ_jr_pop(jr);
    }
    found = democ_jr_get(jr, pos, "signed", &vp);
    if (found != 1) {
        return democ_jr_fail(jr, "missing parameter \"signed\"");
    }
    {
        democ_jr_push(jr, "signed");
        if (democ_jr_s16(jr, vp, &out->signed_)) {
            return -1;
        }
        democ_jr_pop(jr);
    }
    found = democ_jr_get(jr, pos, "tail", &vp);
    if (found != 1) {
        return democ_jr_fail(jr, "missing parameter \"tail\"");
    }
    {
        democ_jr_push(jr, "tail");
        if (democ_jr_array(jr, vp, &it)) {
            return -1;
        }
        for (i = 0;; i++) {
            int more = democ_jr_next(jr, &it, &ep);
            if (more < 0) {
                return -1;
            }
            if (!more) {
                break;
            }
            if (i >= 135) {
                return democ_jr_fail(jr, "more than 135 elements");
            }
            democ_jr_index(jr, i);
            if (democ_jr_char(jr, ep, &out->tail[i])) {
                return -1;
            }
        }
        democ_jr_index(jr, SIZE_MAX);
        out->tail_count = i;
        democ_jr_pop(jr);
    }
    return 0;
}

/* ---- democ_commands_per_device_dev_a_t */

void democ_commands_per_device_dev_a_to_json(democ_jw_t *w, const democ_commands_per_device_dev_a_t *in) {
    int first = 1;
    democ_jw_raw(w, "{", 1);
    democ_jw_key(w, &first, "a");
    democ_jw_u32(w, &in->a);
    democ_jw_raw(w, "}", 1);
}

int democ_commands_per_device_dev_a_from_json(democ_jr_t *jr, size_t pos,
                                              democ_commands_per_device_dev_a_t *out) {
    static const char *const keys[] = {"a"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (democ_jr_object(jr, pos, keys, 1)) {
        return -1;
    }
    found = democ_jr_get(jr, pos, "a", &vp);
    if (found != 1) {
        return democ_jr_fail(jr, "missing parameter \"a\"");
    }
    {
        democ_jr_push(jr, "a");
        if (democ_jr_u32(jr, vp, &out->a)) {
            return -1;
        }
        democ_jr_pop(jr);
    }
    return 0;
}

/* ---- democ_commands_per_device_dev_b_t */

void democ_commands_per_device_dev_b_to_json(democ_jw_t *w, const democ_commands_per_device_dev_b_t *in) {
    int first = 1;
    democ_jw_raw(w, "{", 1);
    democ_jw_key(w, &first, "b");
    democ_jw_u64(w, &in->b);
    if (in->has_extra) {
        democ_jw_key(w, &first, "extra");
        democ_jw_u8(w, &in->extra);
    }
    democ_jw_raw(w, "}", 1);
}

int democ_commands_per_device_dev_b_from_json(democ_jr_t *jr, size_t pos,
                                              democ_commands_per_device_dev_b_t *out) {
    static const char *const keys[] = {"b", "extra"};
    size_t vp = 0;
    int found;
    int absent = 0;
    memset(out, 0, sizeof *out);
    if (democ_jr_object(jr, pos, keys, 2)) {
        return -1;
    }
    found = democ_jr_get(jr, pos, "b", &vp);
    if (found != 1) {
        return democ_jr_fail(jr, "missing parameter \"b\"");
    }
    {
        democ_jr_push(jr, "b");
        if (democ_jr_u64(jr, vp, &out->b)) {
            return -1;
        }
        democ_jr_pop(jr);
    }
    found = democ_jr_get(jr, pos, "extra", &vp);
    out->has_extra = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return democ_jr_fail(jr, "optional parameter \"extra\" given after an absent one");
    } else {
        democ_jr_push(jr, "extra");
        if (democ_jr_u8(jr, vp, &out->extra)) {
            return -1;
        }
        democ_jr_pop(jr);
    }
    return 0;
}
