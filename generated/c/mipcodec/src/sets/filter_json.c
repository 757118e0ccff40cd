/* Canonical JSON of Filter Command Set (the mipcodec_json library). Generated from the spec: do not edit. */
#include "mipcodec/sets/filter.h"
#include "layouts_internal.h"
#include "types_internal.h"

#include <assert.h>
#include <string.h>

/* ---- mipc_filter_reset_filter_t */

void mipc_filter_reset_filter_to_json(mipc_jw_t *w, const mipc_filter_reset_filter_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_raw(w, "}", 1);
    (void)in;
    (void)first;
}

int mipc_filter_reset_filter_from_json(mipc_jr_t *jr, size_t pos, mipc_filter_reset_filter_t *out) {
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, NULL, 0)) {
        return -1;
    }
    return 0;
}

/* ---- mipc_filter_set_initial_attitude_t */

void mipc_filter_set_initial_attitude_to_json(mipc_jw_t *w, const mipc_filter_set_initial_attitude_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "roll");
    mipc_jw_f32(w, &in->roll);
    mipc_jw_key(w, &first, "pitch");
    mipc_jw_f32(w, &in->pitch);
    mipc_jw_key(w, &first, "heading");
    mipc_jw_f32(w, &in->heading);
    mipc_jw_raw(w, "}", 1);
}

int mipc_filter_set_initial_attitude_from_json(mipc_jr_t *jr, size_t pos,
                                               mipc_filter_set_initial_attitude_t *out) {
    static const char *const keys[] = {"roll", "pitch", "heading"};
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
    found = mipc_jr_get(jr, pos, "heading", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"heading\"");
    }
    {
        mipc_jr_push(jr, "heading");
        if (mipc_jr_f32(jr, vp, &out->heading)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mipc_filter_set_initial_heading_t */

void mipc_filter_set_initial_heading_to_json(mipc_jw_t *w, const mipc_filter_set_initial_heading_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "heading");
    mipc_jw_f32(w, &in->heading);
    mipc_jw_raw(w, "}", 1);
}

int mipc_filter_set_initial_heading_from_json(mipc_jr_t *jr, size_t pos,
                                              mipc_filter_set_initial_heading_t *out) {
    static const char *const keys[] = {"heading"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 1)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "heading", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"heading\"");
    }
    {
        mipc_jr_push(jr, "heading");
        if (mipc_jr_f32(jr, vp, &out->heading)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mipc_filter_run_filter_t */

void mipc_filter_run_filter_to_json(mipc_jw_t *w, const mipc_filter_run_filter_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_raw(w, "}", 1);
    (void)in;
    (void)first;
}

int mipc_filter_run_filter_from_json(mipc_jr_t *jr, size_t pos, mipc_filter_run_filter_t *out) {
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, NULL, 0)) {
        return -1;
    }
    return 0;
}

/* ---- mipc_filter_vehicle_dynamics_mode_t */

void mipc_filter_vehicle_dynamics_mode_to_json(mipc_jw_t *w, const mipc_filter_vehicle_dynamics_mode_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "function");
    mipc_jw_u8(w, &in->function);
    if (in->has_mode) {
        mipc_jw_key(w, &first, "mode");
        mipc_jw_u8(w, &in->mode);
    }
    mipc_jw_raw(w, "}", 1);
}

int mipc_filter_vehicle_dynamics_mode_from_json(mipc_jr_t *jr, size_t pos,
                                                mipc_filter_vehicle_dynamics_mode_t *out) {
    static const char *const keys[] = {"function", "mode"};
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

/* ---- mipc_filter_vehicle_dynamics_mode_response_t */

void mipc_filter_vehicle_dynamics_mode_response_to_json(
    mipc_jw_t *w, const mipc_filter_vehicle_dynamics_mode_response_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "mode");
    mipc_jw_u8(w, &in->mode);
    mipc_jw_raw(w, "}", 1);
}

int mipc_filter_vehicle_dynamics_mode_response_from_json(mipc_jr_t *jr, size_t pos,
                                                         mipc_filter_vehicle_dynamics_mode_response_t *out) {
    static const char *const keys[] = {"mode"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 1)) {
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
    return 0;
}

/* ---- mipc_filter_sensor_to_vehicle_transform_t */

void mipc_filter_sensor_to_vehicle_transform_to_json(mipc_jw_t *w,
                                                     const mipc_filter_sensor_to_vehicle_transform_t *in) {
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

int mipc_filter_sensor_to_vehicle_transform_from_json(mipc_jr_t *jr, size_t pos,
                                                      mipc_filter_sensor_to_vehicle_transform_t *out) {
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

/* ---- mipc_filter_sensor_to_vehicle_transform_response_t */

void mipc_filter_sensor_to_vehicle_transform_response_to_json(
    mipc_jw_t *w, const mipc_filter_sensor_to_vehicle_transform_response_t *in) {
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

int mipc_filter_sensor_to_vehicle_transform_response_from_json(
    mipc_jr_t *jr, size_t pos, mipc_filter_sensor_to_vehicle_transform_response_t *out) {
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

/* ---- mipc_filter_sensor_to_vehicle_offset_t */

void mipc_filter_sensor_to_vehicle_offset_to_json(mipc_jw_t *w,
                                                  const mipc_filter_sensor_to_vehicle_offset_t *in) {
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

int mipc_filter_sensor_to_vehicle_offset_from_json(mipc_jr_t *jr, size_t pos,
                                                   mipc_filter_sensor_to_vehicle_offset_t *out) {
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

/* ---- mipc_filter_sensor_to_vehicle_offset_response_t */

void mipc_filter_sensor_to_vehicle_offset_response_to_json(
    mipc_jw_t *w, const mipc_filter_sensor_to_vehicle_offset_response_t *in) {
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

int mipc_filter_sensor_to_vehicle_offset_response_from_json(
    mipc_jr_t *jr, size_t pos, mipc_filter_sensor_to_vehicle_offset_response_t *out) {
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

/* ---- mipc_filter_antenna_offset_t */

void mipc_filter_antenna_offset_to_json(mipc_jw_t *w, const mipc_filter_antenna_offset_t *in) {
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

int mipc_filter_antenna_offset_from_json(mipc_jr_t *jr, size_t pos, mipc_filter_antenna_offset_t *out) {
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

/* ---- mipc_filter_antenna_offset_response_t */

void mipc_filter_antenna_offset_response_to_json(mipc_jw_t *w,
                                                 const mipc_filter_antenna_offset_response_t *in) {
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

int mipc_filter_antenna_offset_response_from_json(mipc_jr_t *jr, size_t pos,
                                                  mipc_filter_antenna_offset_response_t *out) {
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

/* ---- mipc_filter_estimation_control_t */

void mipc_filter_estimation_control_to_json(mipc_jw_t *w, const mipc_filter_estimation_control_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "function");
    mipc_jw_u8(w, &in->function);
    if (in->has_flags) {
        mipc_jw_key(w, &first, "flags");
        mipc_jw_u16(w, &in->flags);
    }
    mipc_jw_raw(w, "}", 1);
}

int mipc_filter_estimation_control_from_json(mipc_jr_t *jr, size_t pos,
                                             mipc_filter_estimation_control_t *out) {
    static const char *const keys[] = {"function", "flags"};
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
    found = mipc_jr_get(jr, pos, "flags", &vp);
    out->has_flags = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mipc_jr_fail(jr, "optional parameter \"flags\" given after an absent one");
    } else {
        mipc_jr_push(jr, "flags");
        if (mipc_jr_u16(jr, vp, &out->flags)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mipc_filter_estimation_control_response_t */

void mipc_filter_estimation_control_response_to_json(mipc_jw_t *w,
                                                     const mipc_filter_estimation_control_response_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "flags");
    mipc_jw_u16(w, &in->flags);
    mipc_jw_raw(w, "}", 1);
}

int mipc_filter_estimation_control_response_from_json(mipc_jr_t *jr, size_t pos,
                                                      mipc_filter_estimation_control_response_t *out) {
    static const char *const keys[] = {"flags"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 1)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "flags", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"flags\"");
    }
    {
        mipc_jr_push(jr, "flags");
        if (mipc_jr_u16(jr, vp, &out->flags)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mipc_filter_gnss_source_control_t */

void mipc_filter_gnss_source_control_to_json(mipc_jw_t *w, const mipc_filter_gnss_source_control_t *in) {
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

int mipc_filter_gnss_source_control_from_json(mipc_jr_t *jr, size_t pos,
                                              mipc_filter_gnss_source_control_t *out) {
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

/* ---- mipc_filter_gnss_source_control_response_t */

void mipc_filter_gnss_source_control_response_to_json(mipc_jw_t *w,
                                                      const mipc_filter_gnss_source_control_response_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "source");
    mipc_jw_u8(w, &in->source);
    mipc_jw_raw(w, "}", 1);
}

int mipc_filter_gnss_source_control_response_from_json(mipc_jr_t *jr, size_t pos,
                                                       mipc_filter_gnss_source_control_response_t *out) {
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

/* ---- mipc_filter_external_gnss_update_t */

void mipc_filter_external_gnss_update_to_json(mipc_jw_t *w, const mipc_filter_external_gnss_update_t *in) {
    int first = 1;
    size_t i;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "gps_tow");
    mipc_jw_f64(w, &in->gps_tow);
    mipc_jw_key(w, &first, "gps_week");
    mipc_jw_u16(w, &in->gps_week);
    mipc_jw_key(w, &first, "latitude");
    mipc_jw_f64(w, &in->latitude);
    mipc_jw_key(w, &first, "longitude");
    mipc_jw_f64(w, &in->longitude);
    mipc_jw_key(w, &first, "height");
    mipc_jw_f64(w, &in->height);
    mipc_jw_key(w, &first, "velocity");
    mipc_jw_raw(w, "[", 1);
    for (i = 0; i < 3; i++) {
        mipc_jw_sep(w, i);
        mipc_jw_f32(w, &in->velocity[i]);
    }
    mipc_jw_raw(w, "]", 1);
    mipc_jw_key(w, &first, "position_uncertainty");
    mipc_jw_raw(w, "[", 1);
    for (i = 0; i < 3; i++) {
        mipc_jw_sep(w, i);
        mipc_jw_f32(w, &in->position_uncertainty[i]);
    }
    mipc_jw_raw(w, "]", 1);
    mipc_jw_key(w, &first, "velocity_uncertainty");
    mipc_jw_raw(w, "[", 1);
    for (i = 0; i < 3; i++) {
        mipc_jw_sep(w, i);
        mipc_jw_f32(w, &in->velocity_uncertainty[i]);
    }
    mipc_jw_raw(w, "]", 1);
    mipc_jw_raw(w, "}", 1);
}

int mipc_filter_external_gnss_update_from_json(mipc_jr_t *jr, size_t pos,
                                               mipc_filter_external_gnss_update_t *out) {
    static const char *const keys[] = {"gps_tow",
                                       "gps_week",
                                       "latitude",
                                       "longitude",
                                       "height",
                                       "velocity",
                                       "position_uncertainty",
                                       "velocity_uncertainty"};
    size_t vp = 0;
    int found;
    size_t i;
    size_t it = 0;
    size_t ep = 0;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 8)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "gps_tow", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"gps_tow\"");
    }
    {
        mipc_jr_push(jr, "gps_tow");
        if (mipc_jr_f64(jr, vp, &out->gps_tow)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "gps_week", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"gps_week\"");
    }
    {
        mipc_jr_push(jr, "gps_week");
        if (mipc_jr_u16(jr, vp, &out->gps_week)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "latitude", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"latitude\"");
    }
    {
        mipc_jr_push(jr, "latitude");
        if (mipc_jr_f64(jr, vp, &out->latitude)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "longitude", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"longitude\"");
    }
    {
        mipc_jr_push(jr, "longitude");
        if (mipc_jr_f64(jr, vp, &out->longitude)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "height", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"height\"");
    }
    {
        mipc_jr_push(jr, "height");
        if (mipc_jr_f64(jr, vp, &out->height)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "velocity", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"velocity\"");
    }
    {
        mipc_jr_push(jr, "velocity");
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
            if (mipc_jr_f32(jr, ep, &out->velocity[i])) {
                return -1;
            }
        }
        mipc_jr_index(jr, SIZE_MAX);
        if (i != 3) {
            return mipc_jr_fail(jr, "expected 3 elements, got %zu", i);
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "position_uncertainty", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"position_uncertainty\"");
    }
    {
        mipc_jr_push(jr, "position_uncertainty");
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
            if (mipc_jr_f32(jr, ep, &out->position_uncertainty[i])) {
                return -1;
            }
        }
        mipc_jr_index(jr, SIZE_MAX);
        if (i != 3) {
            return mipc_jr_fail(jr, "expected 3 elements, got %zu", i);
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "velocity_uncertainty", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"velocity_uncertainty\"");
    }
    {
        mipc_jr_push(jr, "velocity_uncertainty");
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
            if (mipc_jr_f32(jr, ep, &out->velocity_uncertainty[i])) {
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

/* ---- mipc_filter_external_heading_update_t */

void mipc_filter_external_heading_update_to_json(mipc_jw_t *w,
                                                 const mipc_filter_external_heading_update_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "heading");
    mipc_jw_f32(w, &in->heading);
    mipc_jw_key(w, &first, "heading_uncertainty");
    mipc_jw_f32(w, &in->heading_uncertainty);
    mipc_jw_key(w, &first, "type");
    mipc_jw_u8(w, &in->type);
    mipc_jw_raw(w, "}", 1);
}

int mipc_filter_external_heading_update_from_json(mipc_jr_t *jr, size_t pos,
                                                  mipc_filter_external_heading_update_t *out) {
    static const char *const keys[] = {"heading", "heading_uncertainty", "type"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 3)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "heading", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"heading\"");
    }
    {
        mipc_jr_push(jr, "heading");
        if (mipc_jr_f32(jr, vp, &out->heading)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "heading_uncertainty", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"heading_uncertainty\"");
    }
    {
        mipc_jr_push(jr, "heading_uncertainty");
        if (mipc_jr_f32(jr, vp, &out->heading_uncertainty)) {
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
    return 0;
}

/* ---- mipc_filter_heading_update_control_t */

void mipc_filter_heading_update_control_to_json(mipc_jw_t *w,
                                                const mipc_filter_heading_update_control_t *in) {
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

int mipc_filter_heading_update_control_from_json(mipc_jr_t *jr, size_t pos,
                                                 mipc_filter_heading_update_control_t *out) {
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

/* ---- mipc_filter_heading_update_control_response_t */

void mipc_filter_heading_update_control_response_to_json(
    mipc_jw_t *w, const mipc_filter_heading_update_control_response_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "source");
    mipc_jw_u8(w, &in->source);
    mipc_jw_raw(w, "}", 1);
}

int mipc_filter_heading_update_control_response_from_json(
    mipc_jr_t *jr, size_t pos, mipc_filter_heading_update_control_response_t *out) {
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

/* ---- mipc_filter_auto_init_control_t */

void mipc_filter_auto_init_control_to_json(mipc_jw_t *w, const mipc_filter_auto_init_control_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "function");
    mipc_jw_u8(w, &in->function);
    if (in->has_enable) {
        mipc_jw_key(w, &first, "enable");
        mipc_jw_u8(w, &in->enable);
    }
    mipc_jw_raw(w, "}", 1);
}

int mipc_filter_auto_init_control_from_json(mipc_jr_t *jr, size_t pos, mipc_filter_auto_init_control_t *out) {
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
        if (mipc_jr_u8(jr, vp, &out->enable)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mipc_filter_auto_init_control_response_t */

void mipc_filter_auto_init_control_response_to_json(mipc_jw_t *w,
                                                    const mipc_filter_auto_init_control_response_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "enable");
    mipc_jw_u8(w, &in->enable);
    mipc_jw_raw(w, "}", 1);
}

int mipc_filter_auto_init_control_response_from_json(mipc_jr_t *jr, size_t pos,
                                                     mipc_filter_auto_init_control_response_t *out) {
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
        if (mipc_jr_u8(jr, vp, &out->enable)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mipc_filter_accel_noise_t */

void mipc_filter_accel_noise_to_json(mipc_jw_t *w, const mipc_filter_accel_noise_t *in) {
    int first = 1;
    size_t i;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "function");
    mipc_jw_u8(w, &in->function);
    if (in->has_noise) {
        mipc_jw_key(w, &first, "noise");
        mipc_jw_raw(w, "[", 1);
        for (i = 0; i < 3; i++) {
            mipc_jw_sep(w, i);
            mipc_jw_f32(w, &in->noise[i]);
        }
        mipc_jw_raw(w, "]", 1);
    }
    mipc_jw_raw(w, "}", 1);
}

int mipc_filter_accel_noise_from_json(mipc_jr_t *jr, size_t pos, mipc_filter_accel_noise_t *out) {
    static const char *const keys[] = {"function", "noise"};
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
    found = mipc_jr_get(jr, pos, "noise", &vp);
    out->has_noise = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mipc_jr_fail(jr, "optional parameter \"noise\" given after an absent one");
    } else {
        mipc_jr_push(jr, "noise");
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
            if (mipc_jr_f32(jr, ep, &out->noise[i])) {
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

/* ---- mipc_filter_accel_noise_response_t */

void mipc_filter_accel_noise_response_to_json(mipc_jw_t *w, const mipc_filter_accel_noise_response_t *in) {
    int first = 1;
    size_t i;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "noise");
    mipc_jw_raw(w, "[", 1);
    for (i = 0; i < 3; i++) {
        mipc_jw_sep(w, i);
        mipc_jw_f32(w, &in->noise[i]);
    }
    mipc_jw_raw(w, "]", 1);
    mipc_jw_raw(w, "}", 1);
}

int mipc_filter_accel_noise_response_from_json(mipc_jr_t *jr, size_t pos,
                                               mipc_filter_accel_noise_response_t *out) {
    static const char *const keys[] = {"noise"};
    size_t vp = 0;
    int found;
    size_t i;
    size_t it = 0;
    size_t ep = 0;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 1)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "noise", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"noise\"");
    }
    {
        mipc_jr_push(jr, "noise");
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
            if (mipc_jr_f32(jr, ep, &out->noise[i])) {
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

/* ---- mipc_filter_gyro_noise_t */

void mipc_filter_gyro_noise_to_json(mipc_jw_t *w, const mipc_filter_gyro_noise_t *in) {
    int first = 1;
    size_t i;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "function");
    mipc_jw_u8(w, &in->function);
    if (in->has_noise) {
        mipc_jw_key(w, &first, "noise");
        mipc_jw_raw(w, "[", 1);
        for (i = 0; i < 3; i++) {
            mipc_jw_sep(w, i);
            mipc_jw_f32(w, &in->noise[i]);
        }
        mipc_jw_raw(w, "]", 1);
    }
    mipc_jw_raw(w, "}", 1);
}

int mipc_filter_gyro_noise_from_json(mipc_jr_t *jr, size_t pos, mipc_filter_gyro_noise_t *out) {
    static const char *const keys[] = {"function", "noise"};
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
    found = mipc_jr_get(jr, pos, "noise", &vp);
    out->has_noise = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mipc_jr_fail(jr, "optional parameter \"noise\" given after an absent one");
    } else {
        mipc_jr_push(jr, "noise");
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
            if (mipc_jr_f32(jr, ep, &out->noise[i])) {
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

/* ---- mipc_filter_gyro_noise_response_t */

void mipc_filter_gyro_noise_response_to_json(mipc_jw_t *w, const mipc_filter_gyro_noise_response_t *in) {
    int first = 1;
    size_t i;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "noise");
    mipc_jw_raw(w, "[", 1);
    for (i = 0; i < 3; i++) {
        mipc_jw_sep(w, i);
        mipc_jw_f32(w, &in->noise[i]);
    }
    mipc_jw_raw(w, "]", 1);
    mipc_jw_raw(w, "}", 1);
}

int mipc_filter_gyro_noise_response_from_json(mipc_jr_t *jr, size_t pos,
                                              mipc_filter_gyro_noise_response_t *out) {
    static const char *const keys[] = {"noise"};
    size_t vp = 0;
    int found;
    size_t i;
    size_t it = 0;
    size_t ep = 0;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 1)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "noise", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"noise\"");
    }
    {
        mipc_jr_push(jr, "noise");
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
            if (mipc_jr_f32(jr, ep, &out->noise[i])) {
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

/* ---- mipc_filter_accel_bias_model_t */

void mipc_filter_accel_bias_model_to_json(mipc_jw_t *w, const mipc_filter_accel_bias_model_t *in) {
    int first = 1;
    size_t i;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "function");
    mipc_jw_u8(w, &in->function);
    if (in->has_beta) {
        mipc_jw_key(w, &first, "beta");
        mipc_jw_raw(w, "[", 1);
        for (i = 0; i < 3; i++) {
            mipc_jw_sep(w, i);
            mipc_jw_f32(w, &in->beta[i]);
        }
        mipc_jw_raw(w, "]", 1);
    }
    if (in->has_noise) {
        mipc_jw_key(w, &first, "noise");
        mipc_jw_raw(w, "[", 1);
        for (i = 0; i < 3; i++) {
            mipc_jw_sep(w, i);
            mipc_jw_f32(w, &in->noise[i]);
        }
        mipc_jw_raw(w, "]", 1);
    }
    mipc_jw_raw(w, "}", 1);
}

int mipc_filter_accel_bias_model_from_json(mipc_jr_t *jr, size_t pos, mipc_filter_accel_bias_model_t *out) {
    static const char *const keys[] = {"function", "beta", "noise"};
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
    found = mipc_jr_get(jr, pos, "beta", &vp);
    out->has_beta = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mipc_jr_fail(jr, "optional parameter \"beta\" given after an absent one");
    } else {
        mipc_jr_push(jr, "beta");
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
            if (mipc_jr_f32(jr, ep, &out->beta[i])) {
                return -1;
            }
        }
        mipc_jr_index(jr, SIZE_MAX);
        if (i != 3) {
            return mipc_jr_fail(jr, "expected 3 elements, got %zu", i);
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "noise", &vp);
    out->has_noise = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mipc_jr_fail(jr, "optional parameter \"noise\" given after an absent one");
    } else {
        mipc_jr_push(jr, "noise");
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
            if (mipc_jr_f32(jr, ep, &out->noise[i])) {
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

/* ---- mipc_filter_accel_bias_model_response_t */

void mipc_filter_accel_bias_model_response_to_json(mipc_jw_t *w,
                                                   const mipc_filter_accel_bias_model_response_t *in) {
    int first = 1;
    size_t i;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "beta");
    mipc_jw_raw(w, "[", 1);
    for (i = 0; i < 3; i++) {
        mipc_jw_sep(w, i);
        mipc_jw_f32(w, &in->beta[i]);
    }
    mipc_jw_raw(w, "]", 1);
    mipc_jw_key(w, &first, "noise");
    mipc_jw_raw(w, "[", 1);
    for (i = 0; i < 3; i++) {
        mipc_jw_sep(w, i);
        mipc_jw_f32(w, &in->noise[i]);
    }
    mipc_jw_raw(w, "]", 1);
    mipc_jw_raw(w, "}", 1);
}

int mipc_filter_accel_bias_model_response_from_json(mipc_jr_t *jr, size_t pos,
                                                    mipc_filter_accel_bias_model_response_t *out) {
    static const char *const keys[] = {"beta", "noise"};
    size_t vp = 0;
    int found;
    size_t i;
    size_t it = 0;
    size_t ep = 0;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 2)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "beta", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"beta\"");
    }
    {
        mipc_jr_push(jr, "beta");
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
            if (mipc_jr_f32(jr, ep, &out->beta[i])) {
                return -1;
            }
        }
        mipc_jr_index(jr, SIZE_MAX);
        if (i != 3) {
            return mipc_jr_fail(jr, "expected 3 elements, got %zu", i);
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "noise", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"noise\"");
    }
    {
        mipc_jr_push(jr, "noise");
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
            if (mipc_jr_f32(jr, ep, &out->noise[i])) {
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

/* ---- mipc_filter_gyro_bias_model_t */

void mipc_filter_gyro_bias_model_to_json(mipc_jw_t *w, const mipc_filter_gyro_bias_model_t *in) {
    int first = 1;
    size_t i;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "function");
    mipc_jw_u8(w, &in->function);
    if (in->has_beta) {
        mipc_jw_key(w, &first, "beta");
        mipc_jw_raw(w, "[", 1);
        for (i = 0; i < 3; i++) {
            mipc_jw_sep(w, i);
            mipc_jw_f32(w, &in->beta[i]);
        }
        mipc_jw_raw(w, "]", 1);
    }
    if (in->has_noise) {
        mipc_jw_key(w, &first, "noise");
        mipc_jw_raw(w, "[", 1);
        for (i = 0; i < 3; i++) {
            mipc_jw_sep(w, i);
            mipc_jw_f32(w, &in->noise[i]);
        }
        mipc_jw_raw(w, "]", 1);
    }
    mipc_jw_raw(w, "}", 1);
}

int mipc_filter_gyro_bias_model_from_json(mipc_jr_t *jr, size_t pos, mipc_filter_gyro_bias_model_t *out) {
    static const char *const keys[] = {"function", "beta", "noise"};
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
    found = mipc_jr_get(jr, pos, "beta", &vp);
    out->has_beta = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mipc_jr_fail(jr, "optional parameter \"beta\" given after an absent one");
    } else {
        mipc_jr_push(jr, "beta");
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
            if (mipc_jr_f32(jr, ep, &out->beta[i])) {
                return -1;
            }
        }
        mipc_jr_index(jr, SIZE_MAX);
        if (i != 3) {
            return mipc_jr_fail(jr, "expected 3 elements, got %zu", i);
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "noise", &vp);
    out->has_noise = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mipc_jr_fail(jr, "optional parameter \"noise\" given after an absent one");
    } else {
        mipc_jr_push(jr, "noise");
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
            if (mipc_jr_f32(jr, ep, &out->noise[i])) {
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

/* ---- mipc_filter_gyro_bias_model_response_t */

void mipc_filter_gyro_bias_model_response_to_json(mipc_jw_t *w,
                                                  const mipc_filter_gyro_bias_model_response_t *in) {
    int first = 1;
    size_t i;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "beta");
    mipc_jw_raw(w, "[", 1);
    for (i = 0; i < 3; i++) {
        mipc_jw_sep(w, i);
        mipc_jw_f32(w, &in->beta[i]);
    }
    mipc_jw_raw(w, "]", 1);
    mipc_jw_key(w, &first, "noise");
    mipc_jw_raw(w, "[", 1);
    for (i = 0; i < 3; i++) {
        mipc_jw_sep(w, i);
        mipc_jw_f32(w, &in->noise[i]);
    }
    mipc_jw_raw(w, "]", 1);
    mipc_jw_raw(w, "}", 1);
}

int mipc_filter_gyro_bias_model_response_from_json(mipc_jr_t *jr, size_t pos,
                                                   mipc_filter_gyro_bias_model_response_t *out) {
    static const char *const keys[] = {"beta", "noise"};
    size_t vp = 0;
    int found;
    size_t i;
    size_t it = 0;
    size_t ep = 0;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 2)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "beta", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"beta\"");
    }
    {
        mipc_jr_push(jr, "beta");
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
            if (mipc_jr_f32(jr, ep, &out->beta[i])) {
                return -1;
            }
        }
        mipc_jr_index(jr, SIZE_MAX);
        if (i != 3) {
            return mipc_jr_fail(jr, "expected 3 elements, got %zu", i);
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "noise", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"noise\"");
    }
    {
        mipc_jr_push(jr, "noise");
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
            if (mipc_jr_f32(jr, ep, &out->noise[i])) {
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

/* ---- mipc_filter_zupt_control_t */

void mipc_filter_zupt_control_to_json(mipc_jw_t *w, const mipc_filter_zupt_control_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "function");
    mipc_jw_u8(w, &in->function);
    if (in->has_enable) {
        mipc_jw_key(w, &first, "enable");
        mipc_jw_u8(w, &in->enable);
    }
    if (in->has_threshold) {
        mipc_jw_key(w, &first, "threshold");
        mipc_jw_f32(w, &in->threshold);
    }
    mipc_jw_raw(w, "}", 1);
}

int mipc_filter_zupt_control_from_json(mipc_jr_t *jr, size_t pos, mipc_filter_zupt_control_t *out) {
    static const char *const keys[] = {"function", "enable", "threshold"};
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
    found = mipc_jr_get(jr, pos, "threshold", &vp);
    out->has_threshold = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mipc_jr_fail(jr, "optional parameter \"threshold\" given after an absent one");
    } else {
        mipc_jr_push(jr, "threshold");
        if (mipc_jr_f32(jr, vp, &out->threshold)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mipc_filter_zupt_control_response_t */

void mipc_filter_zupt_control_response_to_json(mipc_jw_t *w, const mipc_filter_zupt_control_response_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "enable");
    mipc_jw_u8(w, &in->enable);
    mipc_jw_key(w, &first, "threshold");
    mipc_jw_f32(w, &in->threshold);
    mipc_jw_raw(w, "}", 1);
}

int mipc_filter_zupt_control_response_from_json(mipc_jr_t *jr, size_t pos,
                                                mipc_filter_zupt_control_response_t *out) {
    static const char *const keys[] = {"enable", "threshold"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 2)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "enable", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"enable\"");
    }
    {
        mipc_jr_push(jr, "enable");
        if (mipc_jr_u8(jr, vp, &out->enable)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "threshold", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"threshold\"");
    }
    {
        mipc_jr_push(jr, "threshold");
        if (mipc_jr_f32(jr, vp, &out->threshold)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mipc_filter_external_heading_update_with_time_t */

void mipc_filter_external_heading_update_with_time_to_json(
    mipc_jw_t *w, const mipc_filter_external_heading_update_with_time_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "gps_tow");
    mipc_jw_f64(w, &in->gps_tow);
    mipc_jw_key(w, &first, "gps_week");
    mipc_jw_u16(w, &in->gps_week);
    mipc_jw_key(w, &first, "heading");
    mipc_jw_f32(w, &in->heading);
    mipc_jw_key(w, &first, "heading_uncertainty");
    mipc_jw_f32(w, &in->heading_uncertainty);
    mipc_jw_key(w, &first, "type");
    mipc_jw_u8(w, &in->type);
    mipc_jw_raw(w, "}", 1);
}

int mipc_filter_external_heading_update_with_time_from_json(
    mipc_jr_t *jr, size_t pos, mipc_filter_external_heading_update_with_time_t *out) {
    static const char *const keys[] = {"gps_tow", "gps_week", "heading", "heading_uncertainty", "type"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 5)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "gps_tow", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"gps_tow\"");
    }
    {
        mipc_jr_push(jr, "gps_tow");
        if (mipc_jr_f64(jr, vp, &out->gps_tow)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "gps_week", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"gps_week\"");
    }
    {
        mipc_jr_push(jr, "gps_week");
        if (mipc_jr_u16(jr, vp, &out->gps_week)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "heading", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"heading\"");
    }
    {
        mipc_jr_push(jr, "heading");
        if (mipc_jr_f32(jr, vp, &out->heading)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "heading_uncertainty", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"heading_uncertainty\"");
    }
    {
        mipc_jr_push(jr, "heading_uncertainty");
        if (mipc_jr_f32(jr, vp, &out->heading_uncertainty)) {
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
    return 0;
}

/* ---- mipc_filter_zero_angular_rate_update_control_t */

void mipc_filter_zero_angular_rate_update_control_to_json(
    mipc_jw_t *w, const mipc_filter_zero_angular_rate_update_control_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "function");
    mipc_jw_u8(w, &in->function);
    if (in->has_enable) {
        mipc_jw_key(w, &first, "enable");
        mipc_jw_u8(w, &in->enable);
    }
    if (in->has_threshold) {
        mipc_jw_key(w, &first, "threshold");
        mipc_jw_f32(w, &in->threshold);
    }
    mipc_jw_raw(w, "}", 1);
}

int mipc_filter_zero_angular_rate_update_control_from_json(
    mipc_jr_t *jr, size_t pos, mipc_filter_zero_angular_rate_update_control_t *out) {
    static const char *const keys[] = {"function", "enable", "threshold"};
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
    found = mipc_jr_get(jr, pos, "threshold", &vp);
    out->has_threshold = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mipc_jr_fail(jr, "optional parameter \"threshold\" given after an absent one");
    } else {
        mipc_jr_push(jr, "threshold");
        if (mipc_jr_f32(jr, vp, &out->threshold)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mipc_filter_zero_angular_rate_update_control_response_t */

void mipc_filter_zero_angular_rate_update_control_response_to_json(
    mipc_jw_t *w, const mipc_filter_zero_angular_rate_update_control_response_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "enable");
    mipc_jw_u8(w, &in->enable);
    mipc_jw_key(w, &first, "threshold");
    mipc_jw_f32(w, &in->threshold);
    mipc_jw_raw(w, "}", 1);
}

int mipc_filter_zero_angular_rate_update_control_response_from_json(
    mipc_jr_t *jr, size_t pos, mipc_filter_zero_angular_rate_update_control_response_t *out) {
    static const char *const keys[] = {"enable", "threshold"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 2)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "enable", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"enable\"");
    }
    {
        mipc_jr_push(jr, "enable");
        if (mipc_jr_u8(jr, vp, &out->enable)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "threshold", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"threshold\"");
    }
    {
        mipc_jr_push(jr, "threshold");
        if (mipc_jr_f32(jr, vp, &out->threshold)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mipc_filter_tare_orientation_t */

void mipc_filter_tare_orientation_to_json(mipc_jw_t *w, const mipc_filter_tare_orientation_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "function");
    mipc_jw_u8(w, &in->function);
    if (in->has_axes) {
        mipc_jw_key(w, &first, "axes");
        mipc_jw_u8(w, &in->axes);
    }
    mipc_jw_raw(w, "}", 1);
}

int mipc_filter_tare_orientation_from_json(mipc_jr_t *jr, size_t pos, mipc_filter_tare_orientation_t *out) {
    static const char *const keys[] = {"function", "axes"};
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
    found = mipc_jr_get(jr, pos, "axes", &vp);
    out->has_axes = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mipc_jr_fail(jr, "optional parameter \"axes\" given after an absent one");
    } else {
        mipc_jr_push(jr, "axes");
        if (mipc_jr_u8(jr, vp, &out->axes)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mipc_filter_commanded_zupt_t */

void mipc_filter_commanded_zupt_to_json(mipc_jw_t *w, const mipc_filter_commanded_zupt_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_raw(w, "}", 1);
    (void)in;
    (void)first;
}

int mipc_filter_commanded_zupt_from_json(mipc_jr_t *jr, size_t pos, mipc_filter_commanded_zupt_t *out) {
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, NULL, 0)) {
        return -1;
    }
    return 0;
}

/* ---- mipc_filter_commanded_zero_angular_rate_update_t */

void mipc_filter_commanded_zero_angular_rate_update_to_json(
    mipc_jw_t *w, const mipc_filter_commanded_zero_angular_rate_update_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_raw(w, "}", 1);
    (void)in;
    (void)first;
}

int mipc_filter_commanded_zero_angular_rate_update_from_json(
    mipc_jr_t *jr, size_t pos, mipc_filter_commanded_zero_angular_rate_update_t *out) {
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, NULL, 0)) {
        return -1;
    }
    return 0;
}

/* ---- mipc_filter_mag_capture_auto_calibration_t */

void mipc_filter_mag_capture_auto_calibration_to_json(mipc_jw_t *w,
                                                      const mipc_filter_mag_capture_auto_calibration_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "function");
    mipc_jw_u8(w, &in->function);
    mipc_jw_raw(w, "}", 1);
}

int mipc_filter_mag_capture_auto_calibration_from_json(mipc_jr_t *jr, size_t pos,
                                                       mipc_filter_mag_capture_auto_calibration_t *out) {
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

/* ---- mipc_filter_gravity_noise_std_dev_t */

void mipc_filter_gravity_noise_std_dev_to_json(mipc_jw_t *w, const mipc_filter_gravity_noise_std_dev_t *in) {
    int first = 1;
    size_t i;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "function");
    mipc_jw_u8(w, &in->function);
    if (in->has_noise) {
        mipc_jw_key(w, &first, "noise");
        mipc_jw_raw(w, "[", 1);
        for (i = 0; i < 3; i++) {
            mipc_jw_sep(w, i);
            mipc_jw_f32(w, &in->noise[i]);
        }
        mipc_jw_raw(w, "]", 1);
    }
    mipc_jw_raw(w, "}", 1);
}

int mipc_filter_gravity_noise_std_dev_from_json(mipc_jr_t *jr, size_t pos,
                                                mipc_filter_gravity_noise_std_dev_t *out) {
    static const char *const keys[] = {"function", "noise"};
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
    found = mipc_jr_get(jr, pos, "noise", &vp);
    out->has_noise = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mipc_jr_fail(jr, "optional parameter \"noise\" given after an absent one");
    } else {
        mipc_jr_push(jr, "noise");
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
            if (mipc_jr_f32(jr, ep, &out->noise[i])) {
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

/* ---- mipc_filter_gravity_noise_std_dev_response_t */

void mipc_filter_gravity_noise_std_dev_response_to_json(
    mipc_jw_t *w, const mipc_filter_gravity_noise_std_dev_response_t *in) {
    int first = 1;
    size_t i;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "noise");
    mipc_jw_raw(w, "[", 1);
    for (i = 0; i < 3; i++) {
        mipc_jw_sep(w, i);
        mipc_jw_f32(w, &in->noise[i]);
    }
    mipc_jw_raw(w, "]", 1);
    mipc_jw_raw(w, "}", 1);
}

int mipc_filter_gravity_noise_std_dev_response_from_json(mipc_jr_t *jr, size_t pos,
                                                         mipc_filter_gravity_noise_std_dev_response_t *out) {
    static const char *const keys[] = {"noise"};
    size_t vp = 0;
    int found;
    size_t i;
    size_t it = 0;
    size_t ep = 0;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 1)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "noise", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"noise\"");
    }
    {
        mipc_jr_push(jr, "noise");
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
            if (mipc_jr_f32(jr, ep, &out->noise[i])) {
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

/* ---- mipc_filter_pressure_altitude_noise_std_dev_t */

void mipc_filter_pressure_altitude_noise_std_dev_to_json(
    mipc_jw_t *w, const mipc_filter_pressure_altitude_noise_std_dev_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "function");
    mipc_jw_u8(w, &in->function);
    if (in->has_noise) {
        mipc_jw_key(w, &first, "noise");
        mipc_jw_f32(w, &in->noise);
    }
    mipc_jw_raw(w, "}", 1);
}

int mipc_filter_pressure_altitude_noise_std_dev_from_json(
    mipc_jr_t *jr, size_t pos, mipc_filter_pressure_altitude_noise_std_dev_t *out) {
    static const char *const keys[] = {"function", "noise"};
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
    found = mipc_jr_get(jr, pos, "noise", &vp);
    out->has_noise = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mipc_jr_fail(jr, "optional parameter \"noise\" given after an absent one");
    } else {
        mipc_jr_push(jr, "noise");
        if (mipc_jr_f32(jr, vp, &out->noise)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mipc_filter_pressure_altitude_noise_std_dev_response_t */

void mipc_filter_pressure_altitude_noise_std_dev_response_to_json(
    mipc_jw_t *w, const mipc_filter_pressure_altitude_noise_std_dev_response_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "noise");
    mipc_jw_f32(w, &in->noise);
    mipc_jw_raw(w, "}", 1);
}

int mipc_filter_pressure_altitude_noise_std_dev_response_from_json(
    mipc_jr_t *jr, size_t pos, mipc_filter_pressure_altitude_noise_std_dev_response_t *out) {
    static const char *const keys[] = {"noise"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 1)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "noise", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"noise\"");
    }
    {
        mipc_jr_push(jr, "noise");
        if (mipc_jr_f32(jr, vp, &out->noise)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mipc_filter_hard_iron_offset_noise_t */

void mipc_filter_hard_iron_offset_noise_to_json(mipc_jw_t *w,
                                                const mipc_filter_hard_iron_offset_noise_t *in) {
    int first = 1;
    size_t i;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "function");
    mipc_jw_u8(w, &in->function);
    if (in->has_noise) {
        mipc_jw_key(w, &first, "noise");
        mipc_jw_raw(w, "[", 1);
        for (i = 0; i < 3; i++) {
            mipc_jw_sep(w, i);
            mipc_jw_f32(w, &in->noise[i]);
        }
        mipc_jw_raw(w, "]", 1);
    }
    mipc_jw_raw(w, "}", 1);
}

int mipc_filter_hard_iron_offset_noise_from_json(mipc_jr_t *jr, size_t pos,
                                                 mipc_filter_hard_iron_offset_noise_t *out) {
    static const char *const keys[] = {"function", "noise"};
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
    found = mipc_jr_get(jr, pos, "noise", &vp);
    out->has_noise = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mipc_jr_fail(jr, "optional parameter \"noise\" given after an absent one");
    } else {
        mipc_jr_push(jr, "noise");
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
            if (mipc_jr_f32(jr, ep, &out->noise[i])) {
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

/* ---- mipc_filter_hard_iron_offset_noise_response_t */

void mipc_filter_hard_iron_offset_noise_response_to_json(
    mipc_jw_t *w, const mipc_filter_hard_iron_offset_noise_response_t *in) {
    int first = 1;
    size_t i;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "noise");
    mipc_jw_raw(w, "[", 1);
    for (i = 0; i < 3; i++) {
        mipc_jw_sep(w, i);
        mipc_jw_f32(w, &in->noise[i]);
    }
    mipc_jw_raw(w, "]", 1);
    mipc_jw_raw(w, "}", 1);
}

int mipc_filter_hard_iron_offset_noise_response_from_json(
    mipc_jr_t *jr, size_t pos, mipc_filter_hard_iron_offset_noise_response_t *out) {
    static const char *const keys[] = {"noise"};
    size_t vp = 0;
    int found;
    size_t i;
    size_t it = 0;
    size_t ep = 0;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 1)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "noise", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"noise\"");
    }
    {
        mipc_jr_push(jr, "noise");
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
            if (mipc_jr_f32(jr, ep, &out->noise[i])) {
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

/* ---- mipc_filter_soft_iron_matrix_noise_t */

void mipc_filter_soft_iron_matrix_noise_to_json(mipc_jw_t *w,
                                                const mipc_filter_soft_iron_matrix_noise_t *in) {
    int first = 1;
    size_t i;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "function");
    mipc_jw_u8(w, &in->function);
    if (in->has_noise) {
        mipc_jw_key(w, &first, "noise");
        mipc_jw_raw(w, "[", 1);
        for (i = 0; i < 9; i++) {
            mipc_jw_sep(w, i);
            mipc_jw_f32(w, &in->noise[i]);
        }
        mipc_jw_raw(w, "]", 1);
    }
    mipc_jw_raw(w, "}", 1);
}

int mipc_filter_soft_iron_matrix_noise_from_json(mipc_jr_t *jr, size_t pos,
                                                 mipc_filter_soft_iron_matrix_noise_t *out) {
    static const char *const keys[] = {"function", "noise"};
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
    found = mipc_jr_get(jr, pos, "noise", &vp);
    out->has_noise = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mipc_jr_fail(jr, "optional parameter \"noise\" given after an absent one");
    } else {
        mipc_jr_push(jr, "noise");
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
            if (mipc_jr_f32(jr, ep, &out->noise[i])) {
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

/* ---- mipc_filter_soft_iron_matrix_noise_response_t */

void mipc_filter_soft_iron_matrix_noise_response_to_json(
    mipc_jw_t *w, const mipc_filter_soft_iron_matrix_noise_response_t *in) {
    int first = 1;
    size_t i;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "noise");
    mipc_jw_raw(w, "[", 1);
    for (i = 0; i < 9; i++) {
        mipc_jw_sep(w, i);
        mipc_jw_f32(w, &in->noise[i]);
    }
    mipc_jw_raw(w, "]", 1);
    mipc_jw_raw(w, "}", 1);
}

int mipc_filter_soft_iron_matrix_noise_response_from_json(
    mipc_jr_t *jr, size_t pos, mipc_filter_soft_iron_matrix_noise_response_t *out) {
    static const char *const keys[] = {"noise"};
    size_t vp = 0;
    int found;
    size_t i;
    size_t it = 0;
    size_t ep = 0;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 1)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "noise", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"noise\"");
    }
    {
        mipc_jr_push(jr, "noise");
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
            if (mipc_jr_f32(jr, ep, &out->noise[i])) {
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

/* ---- mipc_filter_mag_noise_std_dev_t */

void mipc_filter_mag_noise_std_dev_to_json(mipc_jw_t *w, const mipc_filter_mag_noise_std_dev_t *in) {
    int first = 1;
    size_t i;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "function");
    mipc_jw_u8(w, &in->function);
    if (in->has_noise) {
        mipc_jw_key(w, &first, "noise");
        mipc_jw_raw(w, "[", 1);
        for (i = 0; i < 3; i++) {
            mipc_jw_sep(w, i);
            mipc_jw_f32(w, &in->noise[i]);
        }
        mipc_jw_raw(w, "]", 1);
    }
    mipc_jw_raw(w, "}", 1);
}

int mipc_filter_mag_noise_std_dev_from_json(mipc_jr_t *jr, size_t pos, mipc_filter_mag_noise_std_dev_t *out) {
    static const char *const keys[] = {"function", "noise"};
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
    found = mipc_jr_get(jr, pos, "noise", &vp);
    out->has_noise = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mipc_jr_fail(jr, "optional parameter \"noise\" given after an absent one");
    } else {
        mipc_jr_push(jr, "noise");
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
            if (mipc_jr_f32(jr, ep, &out->noise[i])) {
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

/* ---- mipc_filter_mag_noise_std_dev_response_t */

void mipc_filter_mag_noise_std_dev_response_to_json(mipc_jw_t *w,
                                                    const mipc_filter_mag_noise_std_dev_response_t *in) {
    int first = 1;
    size_t i;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "noise");
    mipc_jw_raw(w, "[", 1);
    for (i = 0; i < 3; i++) {
        mipc_jw_sep(w, i);
        mipc_jw_f32(w, &in->noise[i]);
    }
    mipc_jw_raw(w, "]", 1);
    mipc_jw_raw(w, "}", 1);
}

int mipc_filter_mag_noise_std_dev_response_from_json(mipc_jr_t *jr, size_t pos,
                                                     mipc_filter_mag_noise_std_dev_response_t *out) {
    static const char *const keys[] = {"noise"};
    size_t vp = 0;
    int found;
    size_t i;
    size_t it = 0;
    size_t ep = 0;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 1)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "noise", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"noise\"");
    }
    {
        mipc_jr_push(jr, "noise");
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
            if (mipc_jr_f32(jr, ep, &out->noise[i])) {
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

/* ---- mipc_filter_declination_source_t */

void mipc_filter_declination_source_to_json(mipc_jw_t *w, const mipc_filter_declination_source_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "function");
    mipc_jw_u8(w, &in->function);
    if (in->has_source) {
        mipc_jw_key(w, &first, "source");
        mipc_jw_u8(w, &in->source);
    }
    if (in->has_declination) {
        mipc_jw_key(w, &first, "declination");
        mipc_jw_f32(w, &in->declination);
    }
    mipc_jw_raw(w, "}", 1);
}

int mipc_filter_declination_source_from_json(mipc_jr_t *jr, size_t pos,
                                             mipc_filter_declination_source_t *out) {
    static const char *const keys[] = {"function", "source", "declination"};
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
    found = mipc_jr_get(jr, pos, "declination", &vp);
    out->has_declination = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mipc_jr_fail(jr, "optional parameter \"declination\" given after an absent one");
    } else {
        mipc_jr_push(jr, "declination");
        if (mipc_jr_f32(jr, vp, &out->declination)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mipc_filter_declination_source_response_t */

void mipc_filter_declination_source_response_to_json(mipc_jw_t *w,
                                                     const mipc_filter_declination_source_response_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "source");
    mipc_jw_u8(w, &in->source);
    mipc_jw_key(w, &first, "declination");
    mipc_jw_f32(w, &in->declination);
    mipc_jw_raw(w, "}", 1);
}

int mipc_filter_declination_source_response_from_json(mipc_jr_t *jr, size_t pos,
                                                      mipc_filter_declination_source_response_t *out) {
    static const char *const keys[] = {"source", "declination"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 2)) {
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
    found = mipc_jr_get(jr, pos, "declination", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"declination\"");
    }
    {
        mipc_jr_push(jr, "declination");
        if (mipc_jr_f32(jr, vp, &out->declination)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mipc_filter_gravity_magnitude_adaptive_measurement_t */

void mipc_filter_gravity_magnitude_adaptive_measurement_to_json(
    mipc_jw_t *w, const mipc_filter_gravity_magnitude_adaptive_measurement_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "function");
    mipc_jw_u8(w, &in->function);
    if (in->has_mode) {
        mipc_jw_key(w, &first, "mode");
        mipc_jw_u8(w, &in->mode);
    }
    if (in->has_frequency) {
        mipc_jw_key(w, &first, "frequency");
        mipc_jw_f32(w, &in->frequency);
    }
    if (in->has_low_limit) {
        mipc_jw_key(w, &first, "low_limit");
        mipc_jw_f32(w, &in->low_limit);
    }
    if (in->has_high_limit) {
        mipc_jw_key(w, &first, "high_limit");
        mipc_jw_f32(w, &in->high_limit);
    }
    if (in->has_low_limit_uncertainty) {
        mipc_jw_key(w, &first, "low_limit_uncertainty");
        mipc_jw_f32(w, &in->low_limit_uncertainty);
    }
    if (in->has_high_limit_uncertainty) {
        mipc_jw_key(w, &first, "high_limit_uncertainty");
        mipc_jw_f32(w, &in->high_limit_uncertainty);
    }
    if (in->has_minimum_uncertainty) {
        mipc_jw_key(w, &first, "minimum_uncertainty");
        mipc_jw_f32(w, &in->minimum_uncertainty);
    }
    mipc_jw_raw(w, "}", 1);
}

int mipc_filter_gravity_magnitude_adaptive_measurement_from_json(
    mipc_jr_t *jr, size_t pos, mipc_filter_gravity_magnitude_adaptive_measurement_t *out) {
    static const char *const keys[] = {"function",
                                       "mode",
                                       "frequency",
                                       "low_limit",
                                       "high_limit",
                                       "low_limit_uncertainty",
                                       "high_limit_uncertainty",
                                       "minimum_uncertainty"};
    size_t vp = 0;
    int found;
    int absent = 0;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 8)) {
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
    found = mipc_jr_get(jr, pos, "low_limit", &vp);
    out->has_low_limit = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mipc_jr_fail(jr, "optional parameter \"low_limit\" given after an absent one");
    } else {
        mipc_jr_push(jr, "low_limit");
        if (mipc_jr_f32(jr, vp, &out->low_limit)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "high_limit", &vp);
    out->has_high_limit = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mipc_jr_fail(jr, "optional parameter \"high_limit\" given after an absent one");
    } else {
        mipc_jr_push(jr, "high_limit");
        if (mipc_jr_f32(jr, vp, &out->high_limit)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "low_limit_uncertainty", &vp);
    out->has_low_limit_uncertainty = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mipc_jr_fail(jr, "optional parameter \"low_limit_uncertainty\" given after an absent one");
    } else {
        mipc_jr_push(jr, "low_limit_uncertainty");
        if (mipc_jr_f32(jr, vp, &out->low_limit_uncertainty)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "high_limit_uncertainty", &vp);
    out->has_high_limit_uncertainty = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mipc_jr_fail(jr, "optional parameter \"high_limit_uncertainty\" given after an absent one");
    } else {
        mipc_jr_push(jr, "high_limit_uncertainty");
        if (mipc_jr_f32(jr, vp, &out->high_limit_uncertainty)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "minimum_uncertainty", &vp);
    out->has_minimum_uncertainty = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mipc_jr_fail(jr, "optional parameter \"minimum_uncertainty\" given after an absent one");
    } else {
        mipc_jr_push(jr, "minimum_uncertainty");
        if (mipc_jr_f32(jr, vp, &out->minimum_uncertainty)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mipc_filter_gravity_magnitude_adaptive_measurement_response_t */

void mipc_filter_gravity_magnitude_adaptive_measurement_response_to_json(
    mipc_jw_t *w, const mipc_filter_gravity_magnitude_adaptive_measurement_response_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "mode");
    mipc_jw_u8(w, &in->mode);
    mipc_jw_key(w, &first, "frequency");
    mipc_jw_f32(w, &in->frequency);
    mipc_jw_key(w, &first, "low_limit");
    mipc_jw_f32(w, &in->low_limit);
    mipc_jw_key(w, &first, "high_limit");
    mipc_jw_f32(w, &in->high_limit);
    mipc_jw_key(w, &first, "low_limit_uncertainty");
    mipc_jw_f32(w, &in->low_limit_uncertainty);
    mipc_jw_key(w, &first, "high_limit_uncertainty");
    mipc_jw_f32(w, &in->high_limit_uncertainty);
    mipc_jw_key(w, &first, "minimum_uncertainty");
    mipc_jw_f32(w, &in->minimum_uncertainty);
    mipc_jw_raw(w, "}", 1);
}

int mipc_filter_gravity_magnitude_adaptive_measurement_response_from_json(
    mipc_jr_t *jr, size_t pos, mipc_filter_gravity_magnitude_adaptive_measurement_response_t *out) {
    static const char *const keys[] = {"mode",
                                       "frequency",
                                       "low_limit",
                                       "high_limit",
                                       "low_limit_uncertainty",
                                       "high_limit_uncertainty",
                                       "minimum_uncertainty"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 7)) {
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
    found = mipc_jr_get(jr, pos, "low_limit", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"low_limit\"");
    }
    {
        mipc_jr_push(jr, "low_limit");
        if (mipc_jr_f32(jr, vp, &out->low_limit)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "high_limit", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"high_limit\"");
    }
    {
        mipc_jr_push(jr, "high_limit");
        if (mipc_jr_f32(jr, vp, &out->high_limit)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "low_limit_uncertainty", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"low_limit_uncertainty\"");
    }
    {
        mipc_jr_push(jr, "low_limit_uncertainty");
        if (mipc_jr_f32(jr, vp, &out->low_limit_uncertainty)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "high_limit_uncertainty", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"high_limit_uncertainty\"");
    }
    {
        mipc_jr_push(jr, "high_limit_uncertainty");
        if (mipc_jr_f32(jr, vp, &out->high_limit_uncertainty)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "minimum_uncertainty", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"minimum_uncertainty\"");
    }
    {
        mipc_jr_push(jr, "minimum_uncertainty");
        if (mipc_jr_f32(jr, vp, &out->minimum_uncertainty)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mipc_filter_mag_magnitude_adaptive_measurement_t */

void mipc_filter_mag_magnitude_adaptive_measurement_to_json(
    mipc_jw_t *w, const mipc_filter_mag_magnitude_adaptive_measurement_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "function");
    mipc_jw_u8(w, &in->function);
    if (in->has_mode) {
        mipc_jw_key(w, &first, "mode");
        mipc_jw_u8(w, &in->mode);
    }
    if (in->has_frequency) {
        mipc_jw_key(w, &first, "frequency");
        mipc_jw_f32(w, &in->frequency);
    }
    if (in->has_low_limit) {
        mipc_jw_key(w, &first, "low_limit");
        mipc_jw_f32(w, &in->low_limit);
    }
    if (in->has_high_limit) {
        mipc_jw_key(w, &first, "high_limit");
        mipc_jw_f32(w, &in->high_limit);
    }
    if (in->has_low_limit_uncertainty) {
        mipc_jw_key(w, &first, "low_limit_uncertainty");
        mipc_jw_f32(w, &in->low_limit_uncertainty);
    }
    if (in->has_high_limit_uncertainty) {
        mipc_jw_key(w, &first, "high_limit_uncertainty");
        mipc_jw_f32(w, &in->high_limit_uncertainty);
    }
    if (in->has_minimum_uncertainty) {
        mipc_jw_key(w, &first, "minimum_uncertainty");
        mipc_jw_f32(w, &in->minimum_uncertainty);
    }
    mipc_jw_raw(w, "}", 1);
}

int mipc_filter_mag_magnitude_adaptive_measurement_from_json(
    mipc_jr_t *jr, size_t pos, mipc_filter_mag_magnitude_adaptive_measurement_t *out) {
    static const char *const keys[] = {"function",
                                       "mode",
                                       "frequency",
                                       "low_limit",
                                       "high_limit",
                                       "low_limit_uncertainty",
                                       "high_limit_uncertainty",
                                       "minimum_uncertainty"};
    size_t vp = 0;
    int found;
    int absent = 0;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 8)) {
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
    found = mipc_jr_get(jr, pos, "low_limit", &vp);
    out->has_low_limit = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mipc_jr_fail(jr, "optional parameter \"low_limit\" given after an absent one");
    } else {
        mipc_jr_push(jr, "low_limit");
        if (mipc_jr_f32(jr, vp, &out->low_limit)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "high_limit", &vp);
    out->has_high_limit = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mipc_jr_fail(jr, "optional parameter \"high_limit\" given after an absent one");
    } else {
        mipc_jr_push(jr, "high_limit");
        if (mipc_jr_f32(jr, vp, &out->high_limit)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "low_limit_uncertainty", &vp);
    out->has_low_limit_uncertainty = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mipc_jr_fail(jr, "optional parameter \"low_limit_uncertainty\" given after an absent one");
    } else {
        mipc_jr_push(jr, "low_limit_uncertainty");
        if (mipc_jr_f32(jr, vp, &out->low_limit_uncertainty)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "high_limit_uncertainty", &vp);
    out->has_high_limit_uncertainty = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mipc_jr_fail(jr, "optional parameter \"high_limit_uncertainty\" given after an absent one");
    } else {
        mipc_jr_push(jr, "high_limit_uncertainty");
        if (mipc_jr_f32(jr, vp, &out->high_limit_uncertainty)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "minimum_uncertainty", &vp);
    out->has_minimum_uncertainty = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mipc_jr_fail(jr, "optional parameter \"minimum_uncertainty\" given after an absent one");
    } else {
        mipc_jr_push(jr, "minimum_uncertainty");
        if (mipc_jr_f32(jr, vp, &out->minimum_uncertainty)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mipc_filter_mag_magnitude_adaptive_measurement_response_t */

void mipc_filter_mag_magnitude_adaptive_measurement_response_to_json(
    mipc_jw_t *w, const mipc_filter_mag_magnitude_adaptive_measurement_response_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "mode");
    mipc_jw_u8(w, &in->mode);
    mipc_jw_key(w, &first, "frequency");
    mipc_jw_f32(w, &in->frequency);
    mipc_jw_key(w, &first, "low_limit");
    mipc_jw_f32(w, &in->low_limit);
    mipc_jw_key(w, &first, "high_limit");
    mipc_jw_f32(w, &in->high_limit);
    mipc_jw_key(w, &first, "low_limit_uncertainty");
    mipc_jw_f32(w, &in->low_limit_uncertainty);
    mipc_jw_key(w, &first, "high_limit_uncertainty");
    mipc_jw_f32(w, &in->high_limit_uncertainty);
    mipc_jw_key(w, &first, "minimum_uncertainty");
    mipc_jw_f32(w, &in->minimum_uncertainty);
    mipc_jw_raw(w, "}", 1);
}

int mipc_filter_mag_magnitude_adaptive_measurement_response_from_json(
    mipc_jr_t *jr, size_t pos, mipc_filter_mag_magnitude_adaptive_measurement_response_t *out) {
    static const char *const keys[] = {"mode",
                                       "frequency",
                                       "low_limit",
                                       "high_limit",
                                       "low_limit_uncertainty",
                                       "high_limit_uncertainty",
                                       "minimum_uncertainty"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 7)) {
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
    found = mipc_jr_get(jr, pos, "low_limit", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"low_limit\"");
    }
    {
        mipc_jr_push(jr, "low_limit");
        if (mipc_jr_f32(jr, vp, &out->low_limit)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "high_limit", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"high_limit\"");
    }
    {
        mipc_jr_push(jr, "high_limit");
        if (mipc_jr_f32(jr, vp, &out->high_limit)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "low_limit_uncertainty", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"low_limit_uncertainty\"");
    }
    {
        mipc_jr_push(jr, "low_limit_uncertainty");
        if (mipc_jr_f32(jr, vp, &out->low_limit_uncertainty)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "high_limit_uncertainty", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"high_limit_uncertainty\"");
    }
    {
        mipc_jr_push(jr, "high_limit_uncertainty");
        if (mipc_jr_f32(jr, vp, &out->high_limit_uncertainty)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "minimum_uncertainty", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"minimum_uncertainty\"");
    }
    {
        mipc_jr_push(jr, "minimum_uncertainty");
        if (mipc_jr_f32(jr, vp, &out->minimum_uncertainty)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mipc_filter_mag_dip_angle_adaptive_measurement_t */

void mipc_filter_mag_dip_angle_adaptive_measurement_to_json(
    mipc_jw_t *w, const mipc_filter_mag_dip_angle_adaptive_measurement_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "function");
    mipc_jw_u8(w, &in->function);
    if (in->has_mode) {
        mipc_jw_key(w, &first, "mode");
        mipc_jw_u8(w, &in->mode);
    }
    if (in->has_frequency) {
        mipc_jw_key(w, &first, "frequency");
        mipc_jw_f32(w, &in->frequency);
    }
    if (in->has_high_limit) {
        mipc_jw_key(w, &first, "high_limit");
        mipc_jw_f32(w, &in->high_limit);
    }
    if (in->has_high_limit_uncertainty) {
        mipc_jw_key(w, &first, "high_limit_uncertainty");
        mipc_jw_f32(w, &in->high_limit_uncertainty);
    }
    if (in->has_minimum_uncertainty) {
        mipc_jw_key(w, &first, "minimum_uncertainty");
        mipc_jw_f32(w, &in->minimum_uncertainty);
    }
    mipc_jw_raw(w, "}", 1);
}

int mipc_filter_mag_dip_angle_adaptive_measurement_from_json(
    mipc_jr_t *jr, size_t pos, mipc_filter_mag_dip_angle_adaptive_measurement_t *out) {
    static const char *const keys[] = {
        "function", "mode", "frequency", "high_limit", "high_limit_uncertainty", "minimum_uncertainty"};
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
    found = mipc_jr_get(jr, pos, "high_limit", &vp);
    out->has_high_limit = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mipc_jr_fail(jr, "optional parameter \"high_limit\" given after an absent one");
    } else {
        mipc_jr_push(jr, "high_limit");
        if (mipc_jr_f32(jr, vp, &out->high_limit)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "high_limit_uncertainty", &vp);
    out->has_high_limit_uncertainty = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mipc_jr_fail(jr, "optional parameter \"high_limit_uncertainty\" given after an absent one");
    } else {
        mipc_jr_push(jr, "high_limit_uncertainty");
        if (mipc_jr_f32(jr, vp, &out->high_limit_uncertainty)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "minimum_uncertainty", &vp);
    out->has_minimum_uncertainty = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mipc_jr_fail(jr, "optional parameter \"minimum_uncertainty\" given after an absent one");
    } else {
        mipc_jr_push(jr, "minimum_uncertainty");
        if (mipc_jr_f32(jr, vp, &out->minimum_uncertainty)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mipc_filter_mag_dip_angle_adaptive_measurement_response_t */

void mipc_filter_mag_dip_angle_adaptive_measurement_response_to_json(
    mipc_jw_t *w, const mipc_filter_mag_dip_angle_adaptive_measurement_response_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "mode");
    mipc_jw_u8(w, &in->mode);
    mipc_jw_key(w, &first, "frequency");
    mipc_jw_f32(w, &in->frequency);
    mipc_jw_key(w, &first, "high_limit");
    mipc_jw_f32(w, &in->high_limit);
    mipc_jw_key(w, &first, "high_limit_uncertainty");
    mipc_jw_f32(w, &in->high_limit_uncertainty);
    mipc_jw_key(w, &first, "minimum_uncertainty");
    mipc_jw_f32(w, &in->minimum_uncertainty);
    mipc_jw_raw(w, "}", 1);
}

int mipc_filter_mag_dip_angle_adaptive_measurement_response_from_json(
    mipc_jr_t *jr, size_t pos, mipc_filter_mag_dip_angle_adaptive_measurement_response_t *out) {
    static const char *const keys[] = {"mode", "frequency", "high_limit", "high_limit_uncertainty",
                                       "minimum_uncertainty"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 5)) {
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
    found = mipc_jr_get(jr, pos, "high_limit", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"high_limit\"");
    }
    {
        mipc_jr_push(jr, "high_limit");
        if (mipc_jr_f32(jr, vp, &out->high_limit)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "high_limit_uncertainty", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"high_limit_uncertainty\"");
    }
    {
        mipc_jr_push(jr, "high_limit_uncertainty");
        if (mipc_jr_f32(jr, vp, &out->high_limit_uncertainty)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "minimum_uncertainty", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"minimum_uncertainty\"");
    }
    {
        mipc_jr_push(jr, "minimum_uncertainty");
        if (mipc_jr_f32(jr, vp, &out->minimum_uncertainty)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mipc_filter_altitude_aiding_control_t */

void mipc_filter_altitude_aiding_control_to_json(mipc_jw_t *w,
                                                 const mipc_filter_altitude_aiding_control_t *in) {
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

int mipc_filter_altitude_aiding_control_from_json(mipc_jr_t *jr, size_t pos,
                                                  mipc_filter_altitude_aiding_control_t *out) {
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

/* ---- mipc_filter_altitude_aiding_control_response_t */

void mipc_filter_altitude_aiding_control_response_to_json(
    mipc_jw_t *w, const mipc_filter_altitude_aiding_control_response_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "source");
    mipc_jw_u8(w, &in->source);
    mipc_jw_raw(w, "}", 1);
}

int mipc_filter_altitude_aiding_control_response_from_json(
    mipc_jr_t *jr, size_t pos, mipc_filter_altitude_aiding_control_response_t *out) {
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

/* ---- mipc_filter_pitch_roll_aiding_control_t */

void mipc_filter_pitch_roll_aiding_control_to_json(mipc_jw_t *w,
                                                   const mipc_filter_pitch_roll_aiding_control_t *in) {
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

int mipc_filter_pitch_roll_aiding_control_from_json(mipc_jr_t *jr, size_t pos,
                                                    mipc_filter_pitch_roll_aiding_control_t *out) {
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

/* ---- mipc_filter_pitch_roll_aiding_control_response_t */

void mipc_filter_pitch_roll_aiding_control_response_to_json(
    mipc_jw_t *w, const mipc_filter_pitch_roll_aiding_control_response_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "source");
    mipc_jw_u8(w, &in->source);
    mipc_jw_raw(w, "}", 1);
}

int mipc_filter_pitch_roll_aiding_control_response_from_json(
    mipc_jr_t *jr, size_t pos, mipc_filter_pitch_roll_aiding_control_response_t *out) {
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

/* ---- mipc_filter_inclination_source_t */

void mipc_filter_inclination_source_to_json(mipc_jw_t *w, const mipc_filter_inclination_source_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "function");
    mipc_jw_u8(w, &in->function);
    if (in->has_source) {
        mipc_jw_key(w, &first, "source");
        mipc_jw_u8(w, &in->source);
    }
    if (in->has_inclination) {
        mipc_jw_key(w, &first, "inclination");
        mipc_jw_f32(w, &in->inclination);
    }
    mipc_jw_raw(w, "}", 1);
}

int mipc_filter_inclination_source_from_json(mipc_jr_t *jr, size_t pos,
                                             mipc_filter_inclination_source_t *out) {
    static const char *const keys[] = {"function", "source", "inclination"};
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
    found = mipc_jr_get(jr, pos, "inclination", &vp);
    out->has_inclination = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mipc_jr_fail(jr, "optional parameter \"inclination\" given after an absent one");
    } else {
        mipc_jr_push(jr, "inclination");
        if (mipc_jr_f32(jr, vp, &out->inclination)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mipc_filter_inclination_source_response_t */

void mipc_filter_inclination_source_response_to_json(mipc_jw_t *w,
                                                     const mipc_filter_inclination_source_response_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "source");
    mipc_jw_u8(w, &in->source);
    mipc_jw_key(w, &first, "inclination");
    mipc_jw_f32(w, &in->inclination);
    mipc_jw_raw(w, "}", 1);
}

int mipc_filter_inclination_source_response_from_json(mipc_jr_t *jr, size_t pos,
                                                      mipc_filter_inclination_source_response_t *out) {
    static const char *const keys[] = {"source", "inclination"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 2)) {
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
    found = mipc_jr_get(jr, pos, "inclination", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"inclination\"");
    }
    {
        mipc_jr_push(jr, "inclination");
        if (mipc_jr_f32(jr, vp, &out->inclination)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mipc_filter_magnetic_field_magnitude_source_t */

void mipc_filter_magnetic_field_magnitude_source_to_json(
    mipc_jw_t *w, const mipc_filter_magnetic_field_magnitude_source_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "function");
    mipc_jw_u8(w, &in->function);
    if (in->has_source) {
        mipc_jw_key(w, &first, "source");
        mipc_jw_u8(w, &in->source);
    }
    if (in->has_magnitude) {
        mipc_jw_key(w, &first, "magnitude");
        mipc_jw_f32(w, &in->magnitude);
    }
    mipc_jw_raw(w, "}", 1);
}

int mipc_filter_magnetic_field_magnitude_source_from_json(
    mipc_jr_t *jr, size_t pos, mipc_filter_magnetic_field_magnitude_source_t *out) {
    static const char *const keys[] = {"function", "source", "magnitude"};
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
    found = mipc_jr_get(jr, pos, "magnitude", &vp);
    out->has_magnitude = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mipc_jr_fail(jr, "optional parameter \"magnitude\" given after an absent one");
    } else {
        mipc_jr_push(jr, "magnitude");
        if (mipc_jr_f32(jr, vp, &out->magnitude)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mipc_filter_magnetic_field_magnitude_source_response_t */

void mipc_filter_magnetic_field_magnitude_source_response_to_json(
    mipc_jw_t *w, const mipc_filter_magnetic_field_magnitude_source_response_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "source");
    mipc_jw_u8(w, &in->source);
    mipc_jw_key(w, &first, "magnitude");
    mipc_jw_f32(w, &in->magnitude);
    mipc_jw_raw(w, "}", 1);
}

int mipc_filter_magnetic_field_magnitude_source_response_from_json(
    mipc_jr_t *jr, size_t pos, mipc_filter_magnetic_field_magnitude_source_response_t *out) {
    static const char *const keys[] = {"source", "magnitude"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 2)) {
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
    found = mipc_jr_get(jr, pos, "magnitude", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"magnitude\"");
    }
    {
        mipc_jr_push(jr, "magnitude");
        if (mipc_jr_f32(jr, vp, &out->magnitude)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mipc_filter_aiding_measurement_control_t */

void mipc_filter_aiding_measurement_control_to_json(mipc_jw_t *w,
                                                    const mipc_filter_aiding_measurement_control_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "function");
    mipc_jw_u8(w, &in->function);
    mipc_jw_key(w, &first, "source");
    mipc_jw_u16(w, &in->source);
    if (in->has_enable) {
        mipc_jw_key(w, &first, "enable");
        mipc_jw_bool(w, &in->enable);
    }
    mipc_jw_raw(w, "}", 1);
}

int mipc_filter_aiding_measurement_control_from_json(mipc_jr_t *jr, size_t pos,
                                                     mipc_filter_aiding_measurement_control_t *out) {
    static const char *const keys[] = {"function", "source", "enable"};
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
    found = mipc_jr_get(jr, pos, "source", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"source\"");
    }
    {
        mipc_jr_push(jr, "source");
        if (mipc_jr_u16(jr, vp, &out->source)) {
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

/* ---- mipc_filter_aiding_measurement_control_response_t */

void mipc_filter_aiding_measurement_control_response_to_json(
    mipc_jw_t *w, const mipc_filter_aiding_measurement_control_response_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "source");
    mipc_jw_u16(w, &in->source);
    mipc_jw_key(w, &first, "enable");
    mipc_jw_bool(w, &in->enable);
    mipc_jw_raw(w, "}", 1);
}

int mipc_filter_aiding_measurement_control_response_from_json(
    mipc_jr_t *jr, size_t pos, mipc_filter_aiding_measurement_control_response_t *out) {
    static const char *const keys[] = {"source", "enable"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 2)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "source", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"source\"");
    }
    {
        mipc_jr_push(jr, "source");
        if (mipc_jr_u16(jr, vp, &out->source)) {
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
    return 0;
}

/* ---- mipc_filter_initialization_configuration_t */

void mipc_filter_initialization_configuration_to_json(mipc_jw_t *w,
                                                      const mipc_filter_initialization_configuration_t *in) {
    int first = 1;
    size_t i;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "function");
    mipc_jw_u8(w, &in->function);
    if (in->has_wait_for_run_command) {
        mipc_jw_key(w, &first, "wait_for_run_command");
        mipc_jw_u8(w, &in->wait_for_run_command);
    }
    if (in->has_initial_cond_src) {
        mipc_jw_key(w, &first, "initial_cond_src");
        mipc_jw_u8(w, &in->initial_cond_src);
    }
    if (in->has_auto_heading_alignment_selector) {
        mipc_jw_key(w, &first, "auto_heading_alignment_selector");
        mipc_jw_u8(w, &in->auto_heading_alignment_selector);
    }
    if (in->has_initial_heading) {
        mipc_jw_key(w, &first, "initial_heading");
        mipc_jw_f32(w, &in->initial_heading);
    }
    if (in->has_initial_pitch) {
        mipc_jw_key(w, &first, "initial_pitch");
        mipc_jw_f32(w, &in->initial_pitch);
    }
    if (in->has_initial_roll) {
        mipc_jw_key(w, &first, "initial_roll");
        mipc_jw_f32(w, &in->initial_roll);
    }
    if (in->has_initial_position) {
        mipc_jw_key(w, &first, "initial_position");
        mipc_jw_raw(w, "[", 1);
        for (i = 0; i < 3; i++) {
            mipc_jw_sep(w, i);
            mipc_jw_f32(w, &in->initial_position[i]);
        }
        mipc_jw_raw(w, "]", 1);
    }
    if (in->has_initial_velocity) {
        mipc_jw_key(w, &first, "initial_velocity");
        mipc_jw_raw(w, "[", 1);
        for (i = 0; i < 3; i++) {
            mipc_jw_sep(w, i);
            mipc_jw_f32(w, &in->initial_velocity[i]);
        }
        mipc_jw_raw(w, "]", 1);
    }
    if (in->has_reference_frame_selector) {
        mipc_jw_key(w, &first, "reference_frame_selector");
        mipc_jw_u8(w, &in->reference_frame_selector);
    }
    mipc_jw_raw(w, "}", 1);
}

int mipc_filter_initialization_configuration_from_json(mipc_jr_t *jr, size_t pos,
                                                       mipc_filter_initialization_configuration_t *out) {
    static const char *const keys[] = {
        "function",         "wait_for_run_command",    "initial_cond_src", "auto_heading_alignment_selector",
        "initial_heading",  "initial_pitch",           "initial_roll",     "initial_position",
        "initial_velocity", "reference_frame_selector"};
    size_t vp = 0;
    int found;
    int absent = 0;
    size_t i;
    size_t it = 0;
    size_t ep = 0;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 10)) {
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
    found = mipc_jr_get(jr, pos, "wait_for_run_command", &vp);
    out->has_wait_for_run_command = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mipc_jr_fail(jr, "optional parameter \"wait_for_run_command\" given after an absent one");
    } else {
        mipc_jr_push(jr, "wait_for_run_command");
        if (mipc_jr_u8(jr, vp, &out->wait_for_run_command)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "initial_cond_src", &vp);
    out->has_initial_cond_src = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mipc_jr_fail(jr, "optional parameter \"initial_cond_src\" given after an absent one");
    } else {
        mipc_jr_push(jr, "initial_cond_src");
        if (mipc_jr_u8(jr, vp, &out->initial_cond_src)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "auto_heading_alignment_selector", &vp);
    out->has_auto_heading_alignment_selector = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mipc_jr_fail(
            jr, "optional parameter \"auto_heading_alignment_selector\" given after an absent one");
    } else {
        mipc_jr_push(jr, "auto_heading_alignment_selector");
        if (mipc_jr_u8(jr, vp, &out->auto_heading_alignment_selector)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "initial_heading", &vp);
    out->has_initial_heading = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mipc_jr_fail(jr, "optional parameter \"initial_heading\" given after an absent one");
    } else {
        mipc_jr_push(jr, "initial_heading");
        if (mipc_jr_f32(jr, vp, &out->initial_heading)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "initial_pitch", &vp);
    out->has_initial_pitch = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mipc_jr_fail(jr, "optional parameter \"initial_pitch\" given after an absent one");
    } else {
        mipc_jr_push(jr, "initial_pitch");
        if (mipc_jr_f32(jr, vp, &out->initial_pitch)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "initial_roll", &vp);
    out->has_initial_roll = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mipc_jr_fail(jr, "optional parameter \"initial_roll\" given after an absent one");
    } else {
        mipc_jr_push(jr, "initial_roll");
        if (mipc_jr_f32(jr, vp, &out->initial_roll)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "initial_position", &vp);
    out->has_initial_position = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mipc_jr_fail(jr, "optional parameter \"initial_position\" given after an absent one");
    } else {
        mipc_jr_push(jr, "initial_position");
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
            if (mipc_jr_f32(jr, ep, &out->initial_position[i])) {
                return -1;
            }
        }
        mipc_jr_index(jr, SIZE_MAX);
        if (i != 3) {
            return mipc_jr_fail(jr, "expected 3 elements, got %zu", i);
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "initial_velocity", &vp);
    out->has_initial_velocity = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mipc_jr_fail(jr, "optional parameter \"initial_velocity\" given after an absent one");
    } else {
        mipc_jr_push(jr, "initial_velocity");
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
            if (mipc_jr_f32(jr, ep, &out->initial_velocity[i])) {
                return -1;
            }
        }
        mipc_jr_index(jr, SIZE_MAX);
        if (i != 3) {
            return mipc_jr_fail(jr, "expected 3 elements, got %zu", i);
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "reference_frame_selector", &vp);
    out->has_reference_frame_selector = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mipc_jr_fail(jr, "optional parameter \"reference_frame_selector\" given after an absent one");
    } else {
        mipc_jr_push(jr, "reference_frame_selector");
        if (mipc_jr_u8(jr, vp, &out->reference_frame_selector)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mipc_filter_initialization_configuration_response_t */

void mipc_filter_initialization_configuration_response_to_json(
    mipc_jw_t *w, const mipc_filter_initialization_configuration_response_t *in) {
    int first = 1;
    size_t i;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "wait_for_run_command");
    mipc_jw_u8(w, &in->wait_for_run_command);
    mipc_jw_key(w, &first, "initial_cond_src");
    mipc_jw_u8(w, &in->initial_cond_src);
    mipc_jw_key(w, &first, "auto_heading_alignment_selector");
    mipc_jw_u8(w, &in->auto_heading_alignment_selector);
    mipc_jw_key(w, &first, "initial_heading");
    mipc_jw_f32(w, &in->initial_heading);
    mipc_jw_key(w, &first, "initial_pitch");
    mipc_jw_f32(w, &in->initial_pitch);
    mipc_jw_key(w, &first, "initial_roll");
    mipc_jw_f32(w, &in->initial_roll);
    mipc_jw_key(w, &first, "initial_position");
    mipc_jw_raw(w, "[", 1);
    for (i = 0; i < 3; i++) {
        mipc_jw_sep(w, i);
        mipc_jw_f32(w, &in->initial_position[i]);
    }
    mipc_jw_raw(w, "]", 1);
    mipc_jw_key(w, &first, "initial_velocity");
    mipc_jw_raw(w, "[", 1);
    for (i = 0; i < 3; i++) {
        mipc_jw_sep(w, i);
        mipc_jw_f32(w, &in->initial_velocity[i]);
    }
    mipc_jw_raw(w, "]", 1);
    mipc_jw_key(w, &first, "reference_frame_selector");
    mipc_jw_u8(w, &in->reference_frame_selector);
    mipc_jw_raw(w, "}", 1);
}

int mipc_filter_initialization_configuration_response_from_json(
    mipc_jr_t *jr, size_t pos, mipc_filter_initialization_configuration_response_t *out) {
    static const char *const keys[] = {
        "wait_for_run_command", "initial_cond_src", "auto_heading_alignment_selector",
        "initial_heading",      "initial_pitch",    "initial_roll",
        "initial_position",     "initial_velocity", "reference_frame_selector"};
    size_t vp = 0;
    int found;
    size_t i;
    size_t it = 0;
    size_t ep = 0;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 9)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "wait_for_run_command", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"wait_for_run_command\"");
    }
    {
        mipc_jr_push(jr, "wait_for_run_command");
        if (mipc_jr_u8(jr, vp, &out->wait_for_run_command)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "initial_cond_src", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"initial_cond_src\"");
    }
    {
        mipc_jr_push(jr, "initial_cond_src");
        if (mipc_jr_u8(jr, vp, &out->initial_cond_src)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "auto_heading_alignment_selector", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"auto_heading_alignment_selector\"");
    }
    {
        mipc_jr_push(jr, "auto_heading_alignment_selector");
        if (mipc_jr_u8(jr, vp, &out->auto_heading_alignment_selector)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "initial_heading", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"initial_heading\"");
    }
    {
        mipc_jr_push(jr, "initial_heading");
        if (mipc_jr_f32(jr, vp, &out->initial_heading)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "initial_pitch", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"initial_pitch\"");
    }
    {
        mipc_jr_push(jr, "initial_pitch");
        if (mipc_jr_f32(jr, vp, &out->initial_pitch)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "initial_roll", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"initial_roll\"");
    }
    {
        mipc_jr_push(jr, "initial_roll");
        if (mipc_jr_f32(jr, vp, &out->initial_roll)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "initial_position", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"initial_position\"");
    }
    {
        mipc_jr_push(jr, "initial_position");
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
            if (mipc_jr_f32(jr, ep, &out->initial_position[i])) {
                return -1;
            }
        }
        mipc_jr_index(jr, SIZE_MAX);
        if (i != 3) {
            return mipc_jr_fail(jr, "expected 3 elements, got %zu", i);
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "initial_velocity", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"initial_velocity\"");
    }
    {
        mipc_jr_push(jr, "initial_velocity");
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
            if (mipc_jr_f32(jr, ep, &out->initial_velocity[i])) {
                return -1;
            }
        }
        mipc_jr_index(jr, SIZE_MAX);
        if (i != 3) {
            return mipc_jr_fail(jr, "expected 3 elements, got %zu", i);
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "reference_frame_selector", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"reference_frame_selector\"");
    }
    {
        mipc_jr_push(jr, "reference_frame_selector");
        if (mipc_jr_u8(jr, vp, &out->reference_frame_selector)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mipc_filter_adaptive_filter_control_t */

void mipc_filter_adaptive_filter_control_to_json(mipc_jw_t *w,
                                                 const mipc_filter_adaptive_filter_control_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "function");
    mipc_jw_u8(w, &in->function);
    if (in->has_level) {
        mipc_jw_key(w, &first, "level");
        mipc_jw_u8(w, &in->level);
    }
    if (in->has_time_limit) {
        mipc_jw_key(w, &first, "time_limit");
        mipc_jw_u16(w, &in->time_limit);
    }
    mipc_jw_raw(w, "}", 1);
}

int mipc_filter_adaptive_filter_control_from_json(mipc_jr_t *jr, size_t pos,
                                                  mipc_filter_adaptive_filter_control_t *out) {
    static const char *const keys[] = {"function", "level", "time_limit"};
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
    found = mipc_jr_get(jr, pos, "level", &vp);
    out->has_level = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mipc_jr_fail(jr, "optional parameter \"level\" given after an absent one");
    } else {
        mipc_jr_push(jr, "level");
        if (mipc_jr_u8(jr, vp, &out->level)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "time_limit", &vp);
    out->has_time_limit = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mipc_jr_fail(jr, "optional parameter \"time_limit\" given after an absent one");
    } else {
        mipc_jr_push(jr, "time_limit");
        if (mipc_jr_u16(jr, vp, &out->time_limit)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mipc_filter_adaptive_filter_control_response_t */

void mipc_filter_adaptive_filter_control_response_to_json(
    mipc_jw_t *w, const mipc_filter_adaptive_filter_control_response_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "level");
    mipc_jw_u8(w, &in->level);
    mipc_jw_key(w, &first, "time_limit");
    mipc_jw_u16(w, &in->time_limit);
    mipc_jw_raw(w, "}", 1);
}

int mipc_filter_adaptive_filter_control_response_from_json(
    mipc_jr_t *jr, size_t pos, mipc_filter_adaptive_filter_control_response_t *out) {
    static const char *const keys[] = {"level", "time_limit"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 2)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "level", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"level\"");
    }
    {
        mipc_jr_push(jr, "level");
        if (mipc_jr_u8(jr, vp, &out->level)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "time_limit", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"time_limit\"");
    }
    {
        mipc_jr_push(jr, "time_limit");
        if (mipc_jr_u16(jr, vp, &out->time_limit)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mipc_filter_multi_antenna_offset_t */

void mipc_filter_multi_antenna_offset_to_json(mipc_jw_t *w, const mipc_filter_multi_antenna_offset_t *in) {
    int first = 1;
    size_t i;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "function");
    mipc_jw_u8(w, &in->function);
    mipc_jw_key(w, &first, "receiver_id");
    mipc_jw_u8(w, &in->receiver_id);
    if (in->has_antenna_offset) {
        mipc_jw_key(w, &first, "antenna_offset");
        mipc_jw_raw(w, "[", 1);
        for (i = 0; i < 3; i++) {
            mipc_jw_sep(w, i);
            mipc_jw_f32(w, &in->antenna_offset[i]);
        }
        mipc_jw_raw(w, "]", 1);
    }
    mipc_jw_raw(w, "}", 1);
}

int mipc_filter_multi_antenna_offset_from_json(mipc_jr_t *jr, size_t pos,
                                               mipc_filter_multi_antenna_offset_t *out) {
    static const char *const keys[] = {"function", "receiver_id", "antenna_offset"};
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
    found = mipc_jr_get(jr, pos, "receiver_id", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"receiver_id\"");
    }
    {
        mipc_jr_push(jr, "receiver_id");
        if (mipc_jr_u8(jr, vp, &out->receiver_id)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "antenna_offset", &vp);
    out->has_antenna_offset = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mipc_jr_fail(jr, "optional parameter \"antenna_offset\" given after an absent one");
    } else {
        mipc_jr_push(jr, "antenna_offset");
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
            if (mipc_jr_f32(jr, ep, &out->antenna_offset[i])) {
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

/* ---- mipc_filter_multi_antenna_offset_response_t */

void mipc_filter_multi_antenna_offset_response_to_json(
    mipc_jw_t *w, const mipc_filter_multi_antenna_offset_response_t *in) {
    int first = 1;
    size_t i;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "receiver_id");
    mipc_jw_u8(w, &in->receiver_id);
    mipc_jw_key(w, &first, "antenna_offset");
    mipc_jw_raw(w, "[", 1);
    for (i = 0; i < 3; i++) {
        mipc_jw_sep(w, i);
        mipc_jw_f32(w, &in->antenna_offset[i]);
    }
    mipc_jw_raw(w, "]", 1);
    mipc_jw_raw(w, "}", 1);
}

int mipc_filter_multi_antenna_offset_response_from_json(mipc_jr_t *jr, size_t pos,
                                                        mipc_filter_multi_antenna_offset_response_t *out) {
    static const char *const keys[] = {"receiver_id", "antenna_offset"};
    size_t vp = 0;
    int found;
    size_t i;
    size_t it = 0;
    size_t ep = 0;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 2)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "receiver_id", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"receiver_id\"");
    }
    {
        mipc_jr_push(jr, "receiver_id");
        if (mipc_jr_u8(jr, vp, &out->receiver_id)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "antenna_offset", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"antenna_offset\"");
    }
    {
        mipc_jr_push(jr, "antenna_offset");
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
            if (mipc_jr_f32(jr, ep, &out->antenna_offset[i])) {
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

/* ---- mipc_filter_relative_position_configuration_t */

void mipc_filter_relative_position_configuration_to_json(
    mipc_jw_t *w, const mipc_filter_relative_position_configuration_t *in) {
    int first = 1;
    size_t i;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "function");
    mipc_jw_u8(w, &in->function);
    if (in->has_source) {
        mipc_jw_key(w, &first, "source");
        mipc_jw_u8(w, &in->source);
    }
    if (in->has_reference_frame_selector) {
        mipc_jw_key(w, &first, "reference_frame_selector");
        mipc_jw_u8(w, &in->reference_frame_selector);
    }
    if (in->has_reference_coordinates) {
        mipc_jw_key(w, &first, "reference_coordinates");
        mipc_jw_raw(w, "[", 1);
        for (i = 0; i < 3; i++) {
            mipc_jw_sep(w, i);
            mipc_jw_f64(w, &in->reference_coordinates[i]);
        }
        mipc_jw_raw(w, "]", 1);
    }
    mipc_jw_raw(w, "}", 1);
}

int mipc_filter_relative_position_configuration_from_json(
    mipc_jr_t *jr, size_t pos, mipc_filter_relative_position_configuration_t *out) {
    static const char *const keys[] = {"function", "source", "reference_frame_selector",
                                       "reference_coordinates"};
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
    found = mipc_jr_get(jr, pos, "reference_frame_selector", &vp);
    out->has_reference_frame_selector = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mipc_jr_fail(jr, "optional parameter \"reference_frame_selector\" given after an absent one");
    } else {
        mipc_jr_push(jr, "reference_frame_selector");
        if (mipc_jr_u8(jr, vp, &out->reference_frame_selector)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "reference_coordinates", &vp);
    out->has_reference_coordinates = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mipc_jr_fail(jr, "optional parameter \"reference_coordinates\" given after an absent one");
    } else {
        mipc_jr_push(jr, "reference_coordinates");
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
            if (mipc_jr_f64(jr, ep, &out->reference_coordinates[i])) {
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

/* ---- mipc_filter_relative_position_configuration_response_t */

void mipc_filter_relative_position_configuration_response_to_json(
    mipc_jw_t *w, const mipc_filter_relative_position_configuration_response_t *in) {
    int first = 1;
    size_t i;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "source");
    mipc_jw_u8(w, &in->source);
    mipc_jw_key(w, &first, "reference_frame_selector");
    mipc_jw_u8(w, &in->reference_frame_selector);
    mipc_jw_key(w, &first, "reference_coordinates");
    mipc_jw_raw(w, "[", 1);
    for (i = 0; i < 3; i++) {
        mipc_jw_sep(w, i);
        mipc_jw_f64(w, &in->reference_coordinates[i]);
    }
    mipc_jw_raw(w, "]", 1);
    mipc_jw_raw(w, "}", 1);
}

int mipc_filter_relative_position_configuration_response_from_json(
    mipc_jr_t *jr, size_t pos, mipc_filter_relative_position_configuration_response_t *out) {
    static const char *const keys[] = {"source", "reference_frame_selector", "reference_coordinates"};
    size_t vp = 0;
    int found;
    size_t i;
    size_t it = 0;
    size_t ep = 0;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 3)) {
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
    found = mipc_jr_get(jr, pos, "reference_frame_selector", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"reference_frame_selector\"");
    }
    {
        mipc_jr_push(jr, "reference_frame_selector");
        if (mipc_jr_u8(jr, vp, &out->reference_frame_selector)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "reference_coordinates", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"reference_coordinates\"");
    }
    {
        mipc_jr_push(jr, "reference_coordinates");
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
            if (mipc_jr_f64(jr, ep, &out->reference_coordinates[i])) {
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

/* ---- mipc_filter_reference_point_lever_arm_t */

void mipc_filter_reference_point_lever_arm_to_json(mipc_jw_t *w,
                                                   const mipc_filter_reference_point_lever_arm_t *in) {
    int first = 1;
    size_t i;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "function");
    mipc_jw_u8(w, &in->function);
    if (in->has_ref_point_sel) {
        mipc_jw_key(w, &first, "ref_point_sel");
        mipc_jw_u8(w, &in->ref_point_sel);
    }
    if (in->has_lever_arm_offset) {
        mipc_jw_key(w, &first, "lever_arm_offset");
        mipc_jw_raw(w, "[", 1);
        for (i = 0; i < 3; i++) {
            mipc_jw_sep(w, i);
            mipc_jw_f32(w, &in->lever_arm_offset[i]);
        }
        mipc_jw_raw(w, "]", 1);
    }
    mipc_jw_raw(w, "}", 1);
}

int mipc_filter_reference_point_lever_arm_from_json(mipc_jr_t *jr, size_t pos,
                                                    mipc_filter_reference_point_lever_arm_t *out) {
    static const char *const keys[] = {"function", "ref_point_sel", "lever_arm_offset"};
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
    found = mipc_jr_get(jr, pos, "ref_point_sel", &vp);
    out->has_ref_point_sel = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mipc_jr_fail(jr, "optional parameter \"ref_point_sel\" given after an absent one");
    } else {
        mipc_jr_push(jr, "ref_point_sel");
        if (mipc_jr_u8(jr, vp, &out->ref_point_sel)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "lever_arm_offset", &vp);
    out->has_lever_arm_offset = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mipc_jr_fail(jr, "optional parameter \"lever_arm_offset\" given after an absent one");
    } else {
        mipc_jr_push(jr, "lever_arm_offset");
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
            if (mipc_jr_f32(jr, ep, &out->lever_arm_offset[i])) {
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

/* ---- mipc_filter_reference_point_lever_arm_response_t */

void mipc_filter_reference_point_lever_arm_response_to_json(
    mipc_jw_t *w, const mipc_filter_reference_point_lever_arm_response_t *in) {
    int first = 1;
    size_t i;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "ref_point_sel");
    mipc_jw_u8(w, &in->ref_point_sel);
    mipc_jw_key(w, &first, "lever_arm_offset");
    mipc_jw_raw(w, "[", 1);
    for (i = 0; i < 3; i++) {
        mipc_jw_sep(w, i);
        mipc_jw_f32(w, &in->lever_arm_offset[i]);
    }
    mipc_jw_raw(w, "]", 1);
    mipc_jw_raw(w, "}", 1);
}

int mipc_filter_reference_point_lever_arm_response_from_json(
    mipc_jr_t *jr, size_t pos, mipc_filter_reference_point_lever_arm_response_t *out) {
    static const char *const keys[] = {"ref_point_sel", "lever_arm_offset"};
    size_t vp = 0;
    int found;
    size_t i;
    size_t it = 0;
    size_t ep = 0;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 2)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "ref_point_sel", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"ref_point_sel\"");
    }
    {
        mipc_jr_push(jr, "ref_point_sel");
        if (mipc_jr_u8(jr, vp, &out->ref_point_sel)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "lever_arm_offset", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"lever_arm_offset\"");
    }
    {
        mipc_jr_push(jr, "lever_arm_offset");
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
            if (mipc_jr_f32(jr, ep, &out->lever_arm_offset[i])) {
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

/* ---- mipc_filter_speed_lever_arm_t */

void mipc_filter_speed_lever_arm_to_json(mipc_jw_t *w, const mipc_filter_speed_lever_arm_t *in) {
    int first = 1;
    size_t i;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "function");
    mipc_jw_u8(w, &in->function);
    mipc_jw_key(w, &first, "source");
    mipc_jw_u8(w, &in->source);
    if (in->has_lever_arm_offset) {
        mipc_jw_key(w, &first, "lever_arm_offset");
        mipc_jw_raw(w, "[", 1);
        for (i = 0; i < 3; i++) {
            mipc_jw_sep(w, i);
            mipc_jw_f32(w, &in->lever_arm_offset[i]);
        }
        mipc_jw_raw(w, "]", 1);
    }
    mipc_jw_raw(w, "}", 1);
}

int mipc_filter_speed_lever_arm_from_json(mipc_jr_t *jr, size_t pos, mipc_filter_speed_lever_arm_t *out) {
    static const char *const keys[] = {"function", "source", "lever_arm_offset"};
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
    found = mipc_jr_get(jr, pos, "lever_arm_offset", &vp);
    out->has_lever_arm_offset = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mipc_jr_fail(jr, "optional parameter \"lever_arm_offset\" given after an absent one");
    } else {
        mipc_jr_push(jr, "lever_arm_offset");
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
            if (mipc_jr_f32(jr, ep, &out->lever_arm_offset[i])) {
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

/* ---- mipc_filter_speed_lever_arm_response_t */

void mipc_filter_speed_lever_arm_response_to_json(mipc_jw_t *w,
                                                  const mipc_filter_speed_lever_arm_response_t *in) {
    int first = 1;
    size_t i;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "source");
    mipc_jw_u8(w, &in->source);
    mipc_jw_key(w, &first, "lever_arm_offset");
    mipc_jw_raw(w, "[", 1);
    for (i = 0; i < 3; i++) {
        mipc_jw_sep(w, i);
        mipc_jw_f32(w, &in->lever_arm_offset[i]);
    }
    mipc_jw_raw(w, "]", 1);
    mipc_jw_raw(w, "}", 1);
}

int mipc_filter_speed_lever_arm_response_from_json(mipc_jr_t *jr, size_t pos,
                                                   mipc_filter_speed_lever_arm_response_t *out) {
    static const char *const keys[] = {"source", "lever_arm_offset"};
    size_t vp = 0;
    int found;
    size_t i;
    size_t it = 0;
    size_t ep = 0;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 2)) {
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
    found = mipc_jr_get(jr, pos, "lever_arm_offset", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"lever_arm_offset\"");
    }
    {
        mipc_jr_push(jr, "lever_arm_offset");
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
            if (mipc_jr_f32(jr, ep, &out->lever_arm_offset[i])) {
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

/* ---- mipc_filter_wheeled_vehicle_constraint_control_t */

void mipc_filter_wheeled_vehicle_constraint_control_to_json(
    mipc_jw_t *w, const mipc_filter_wheeled_vehicle_constraint_control_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "function");
    mipc_jw_u8(w, &in->function);
    if (in->has_enable) {
        mipc_jw_key(w, &first, "enable");
        mipc_jw_u8(w, &in->enable);
    }
    mipc_jw_raw(w, "}", 1);
}

int mipc_filter_wheeled_vehicle_constraint_control_from_json(
    mipc_jr_t *jr, size_t pos, mipc_filter_wheeled_vehicle_constraint_control_t *out) {
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
        if (mipc_jr_u8(jr, vp, &out->enable)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mipc_filter_wheeled_vehicle_constraint_control_response_t */

void mipc_filter_wheeled_vehicle_constraint_control_response_to_json(
    mipc_jw_t *w, const mipc_filter_wheeled_vehicle_constraint_control_response_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "enable");
    mipc_jw_u8(w, &in->enable);
    mipc_jw_raw(w, "}", 1);
}

int mipc_filter_wheeled_vehicle_constraint_control_response_from_json(
    mipc_jr_t *jr, size_t pos, mipc_filter_wheeled_vehicle_constraint_control_response_t *out) {
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
        if (mipc_jr_u8(jr, vp, &out->enable)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mipc_filter_gnss_antenna_calibration_control_t */

void mipc_filter_gnss_antenna_calibration_control_to_json(
    mipc_jw_t *w, const mipc_filter_gnss_antenna_calibration_control_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "function");
    mipc_jw_u8(w, &in->function);
    if (in->has_enable) {
        mipc_jw_key(w, &first, "enable");
        mipc_jw_u8(w, &in->enable);
    }
    if (in->has_max_offset) {
        mipc_jw_key(w, &first, "max_offset");
        mipc_jw_f32(w, &in->max_offset);
    }
    mipc_jw_raw(w, "}", 1);
}

int mipc_filter_gnss_antenna_calibration_control_from_json(
    mipc_jr_t *jr, size_t pos, mipc_filter_gnss_antenna_calibration_control_t *out) {
    static const char *const keys[] = {"function", "enable", "max_offset"};
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
    found = mipc_jr_get(jr, pos, "max_offset", &vp);
    out->has_max_offset = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mipc_jr_fail(jr, "optional parameter \"max_offset\" given after an absent one");
    } else {
        mipc_jr_push(jr, "max_offset");
        if (mipc_jr_f32(jr, vp, &out->max_offset)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mipc_filter_gnss_antenna_calibration_control_response_t */

void mipc_filter_gnss_antenna_calibration_control_response_to_json(
    mipc_jw_t *w, const mipc_filter_gnss_antenna_calibration_control_response_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "enable");
    mipc_jw_u8(w, &in->enable);
    mipc_jw_key(w, &first, "max_offset");
    mipc_jw_f32(w, &in->max_offset);
    mipc_jw_raw(w, "}", 1);
}

int mipc_filter_gnss_antenna_calibration_control_response_from_json(
    mipc_jr_t *jr, size_t pos, mipc_filter_gnss_antenna_calibration_control_response_t *out) {
    static const char *const keys[] = {"enable", "max_offset"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 2)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "enable", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"enable\"");
    }
    {
        mipc_jr_push(jr, "enable");
        if (mipc_jr_u8(jr, vp, &out->enable)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "max_offset", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"max_offset\"");
    }
    {
        mipc_jr_push(jr, "max_offset");
        if (mipc_jr_f32(jr, vp, &out->max_offset)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    return 0;
}
