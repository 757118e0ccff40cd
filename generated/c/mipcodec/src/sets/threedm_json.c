/* Canonical JSON of 3DM Command Set (the mipcodec_json library). Generated from the spec: do not edit. */
#include "mipcodec/sets/threedm.h"
#include "layouts_internal.h"
#include "types_internal.h"

#include <assert.h>
#include <string.h>

/* ---- mipc_threedm_event_control_t */

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
