/* Canonical JSON of Aiding Command Set (the mipcodec_json library). Generated from the spec: do not edit. */
#include "mipcodec/sets/aiding.h"
#include "layouts_internal.h"
#include "types_internal.h"

#include <assert.h>
#include <string.h>

/* ---- mipc_aiding_frame_config_t */

void mipc_aiding_frame_config_to_json(mipc_jw_t *w, const mipc_aiding_frame_config_t *in) {
    int first = 1;
    size_t i;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "function");
    mipc_jw_u8(w, &in->function);
    mipc_jw_key(w, &first, "frame_id");
    mipc_jw_u8(w, &in->frame_id);
    if (in->has_format) {
        mipc_jw_key(w, &first, "format");
        mipc_jw_u8(w, &in->format);
    }
    if (in->has_tracking_enabled) {
        mipc_jw_key(w, &first, "tracking_enabled");
        mipc_jw_bool(w, &in->tracking_enabled);
    }
    if (in->has_translation) {
        mipc_jw_key(w, &first, "translation");
        mipc_jw_raw(w, "[", 1);
        for (i = 0; i < 3; i++) {
            mipc_jw_sep(w, i);
            mipc_jw_f32(w, &in->translation[i]);
        }
        mipc_jw_raw(w, "]", 1);
    }
    if (in->has_rotation) {
        mipc_jw_key(w, &first, "rotation");
        mipc_aiding_frame_rotation_to_json(w, in->format, &in->rotation);
    }
    mipc_jw_raw(w, "}", 1);
}

int mipc_aiding_frame_config_from_json(mipc_jr_t *jr, size_t pos, mipc_aiding_frame_config_t *out) {
    static const char *const keys[] = {"function",         "frame_id",    "format",
                                       "tracking_enabled", "translation", "rotation"};
    size_t vp = 0;
    int found;
    int absent = 0;
    size_t i;
    size_t it = 0;
    size_t ep = 0;
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
    found = mipc_jr_get(jr, pos, "frame_id", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"frame_id\"");
    }
    {
        mipc_jr_push(jr, "frame_id");
        if (mipc_jr_u8(jr, vp, &out->frame_id)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "format", &vp);
    out->has_format = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mipc_jr_fail(jr, "optional parameter \"format\" given after an absent one");
    } else {
        mipc_jr_push(jr, "format");
        if (mipc_jr_u8(jr, vp, &out->format)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "tracking_enabled", &vp);
    out->has_tracking_enabled = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mipc_jr_fail(jr, "optional parameter \"tracking_enabled\" given after an absent one");
    } else {
        mipc_jr_push(jr, "tracking_enabled");
        if (mipc_jr_bool(jr, vp, &out->tracking_enabled)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "translation", &vp);
    out->has_translation = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mipc_jr_fail(jr, "optional parameter \"translation\" given after an absent one");
    } else {
        mipc_jr_push(jr, "translation");
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
            if (mipc_jr_f32(jr, ep, &out->translation[i])) {
                return -1;
            }
        }
        mipc_jr_index(jr, SIZE_MAX);
        if (i != 3) {
            return mipc_jr_fail(jr, "expected 3 elements, got %zu", i);
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "rotation", &vp);
    out->has_rotation = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mipc_jr_fail(jr, "optional parameter \"rotation\" given after an absent one");
    } else {
        mipc_jr_push(jr, "rotation");
        if (mipc_aiding_frame_rotation_from_json(jr, vp, out->format, &out->rotation)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mipc_aiding_frame_config_response_t */

void mipc_aiding_frame_config_response_to_json(mipc_jw_t *w, const mipc_aiding_frame_config_response_t *in) {
    int first = 1;
    size_t i;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "frame_id");
    mipc_jw_u8(w, &in->frame_id);
    mipc_jw_key(w, &first, "format");
    mipc_jw_u8(w, &in->format);
    mipc_jw_key(w, &first, "tracking_enabled");
    mipc_jw_bool(w, &in->tracking_enabled);
    mipc_jw_key(w, &first, "translation");
    mipc_jw_raw(w, "[", 1);
    for (i = 0; i < 3; i++) {
        mipc_jw_sep(w, i);
        mipc_jw_f32(w, &in->translation[i]);
    }
    mipc_jw_raw(w, "]", 1);
    mipc_jw_key(w, &first, "rotation");
    mipc_aiding_frame_rotation_to_json(w, in->format, &in->rotation);
    mipc_jw_raw(w, "}", 1);
}

int mipc_aiding_frame_config_response_from_json(mipc_jr_t *jr, size_t pos,
                                                mipc_aiding_frame_config_response_t *out) {
    static const char *const keys[] = {"frame_id", "format", "tracking_enabled", "translation", "rotation"};
    size_t vp = 0;
    int found;
    size_t i;
    size_t it = 0;
    size_t ep = 0;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 5)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "frame_id", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"frame_id\"");
    }
    {
        mipc_jr_push(jr, "frame_id");
        if (mipc_jr_u8(jr, vp, &out->frame_id)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "format", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"format\"");
    }
    {
        mipc_jr_push(jr, "format");
        if (mipc_jr_u8(jr, vp, &out->format)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "tracking_enabled", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"tracking_enabled\"");
    }
    {
        mipc_jr_push(jr, "tracking_enabled");
        if (mipc_jr_bool(jr, vp, &out->tracking_enabled)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "translation", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"translation\"");
    }
    {
        mipc_jr_push(jr, "translation");
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
            if (mipc_jr_f32(jr, ep, &out->translation[i])) {
                return -1;
            }
        }
        mipc_jr_index(jr, SIZE_MAX);
        if (i != 3) {
            return mipc_jr_fail(jr, "expected 3 elements, got %zu", i);
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "rotation", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"rotation\"");
    }
    {
        mipc_jr_push(jr, "rotation");
        if (mipc_aiding_frame_rotation_from_json(jr, vp, out->format, &out->rotation)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mipc_aiding_echo_control_t */

void mipc_aiding_echo_control_to_json(mipc_jw_t *w, const mipc_aiding_echo_control_t *in) {
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

int mipc_aiding_echo_control_from_json(mipc_jr_t *jr, size_t pos, mipc_aiding_echo_control_t *out) {
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

/* ---- mipc_aiding_echo_control_response_t */

void mipc_aiding_echo_control_response_to_json(mipc_jw_t *w, const mipc_aiding_echo_control_response_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "mode");
    mipc_jw_u8(w, &in->mode);
    mipc_jw_raw(w, "}", 1);
}

int mipc_aiding_echo_control_response_from_json(mipc_jr_t *jr, size_t pos,
                                                mipc_aiding_echo_control_response_t *out) {
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

/* ---- mipc_aiding_ecef_position_t */

void mipc_aiding_ecef_position_to_json(mipc_jw_t *w, const mipc_aiding_ecef_position_t *in) {
    int first = 1;
    size_t i;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "time");
    mipc_aiding_time_to_json(w, &in->time);
    mipc_jw_key(w, &first, "frame_id");
    mipc_jw_u8(w, &in->frame_id);
    mipc_jw_key(w, &first, "position");
    mipc_jw_raw(w, "[", 1);
    for (i = 0; i < 3; i++) {
        mipc_jw_sep(w, i);
        mipc_jw_f64(w, &in->position[i]);
    }
    mipc_jw_raw(w, "]", 1);
    mipc_jw_key(w, &first, "uncertainty");
    mipc_jw_raw(w, "[", 1);
    for (i = 0; i < 3; i++) {
        mipc_jw_sep(w, i);
        mipc_jw_f32(w, &in->uncertainty[i]);
    }
    mipc_jw_raw(w, "]", 1);
    mipc_jw_key(w, &first, "valid_flags");
    mipc_jw_u16(w, &in->valid_flags);
    mipc_jw_raw(w, "}", 1);
}

int mipc_aiding_ecef_position_from_json(mipc_jr_t *jr, size_t pos, mipc_aiding_ecef_position_t *out) {
    static const char *const keys[] = {"time", "frame_id", "position", "uncertainty", "valid_flags"};
    size_t vp = 0;
    int found;
    size_t i;
    size_t it = 0;
    size_t ep = 0;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 5)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "time", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"time\"");
    }
    {
        mipc_jr_push(jr, "time");
        if (mipc_aiding_time_from_json(jr, vp, &out->time)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "frame_id", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"frame_id\"");
    }
    {
        mipc_jr_push(jr, "frame_id");
        if (mipc_jr_u8(jr, vp, &out->frame_id)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "position", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"position\"");
    }
    {
        mipc_jr_push(jr, "position");
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
            if (mipc_jr_f64(jr, ep, &out->position[i])) {
                return -1;
            }
        }
        mipc_jr_index(jr, SIZE_MAX);
        if (i != 3) {
            return mipc_jr_fail(jr, "expected 3 elements, got %zu", i);
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "uncertainty", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"uncertainty\"");
    }
    {
        mipc_jr_push(jr, "uncertainty");
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
            if (mipc_jr_f32(jr, ep, &out->uncertainty[i])) {
                return -1;
            }
        }
        mipc_jr_index(jr, SIZE_MAX);
        if (i != 3) {
            return mipc_jr_fail(jr, "expected 3 elements, got %zu", i);
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "valid_flags", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"valid_flags\"");
    }
    {
        mipc_jr_push(jr, "valid_flags");
        if (mipc_jr_u16(jr, vp, &out->valid_flags)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mipc_aiding_llh_position_t */

void mipc_aiding_llh_position_to_json(mipc_jw_t *w, const mipc_aiding_llh_position_t *in) {
    int first = 1;
    size_t i;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "time");
    mipc_aiding_time_to_json(w, &in->time);
    mipc_jw_key(w, &first, "frame_id");
    mipc_jw_u8(w, &in->frame_id);
    mipc_jw_key(w, &first, "latitude");
    mipc_jw_f64(w, &in->latitude);
    mipc_jw_key(w, &first, "longitude");
    mipc_jw_f64(w, &in->longitude);
    mipc_jw_key(w, &first, "height");
    mipc_jw_f64(w, &in->height);
    mipc_jw_key(w, &first, "uncertainty");
    mipc_jw_raw(w, "[", 1);
    for (i = 0; i < 3; i++) {
        mipc_jw_sep(w, i);
        mipc_jw_f32(w, &in->uncertainty[i]);
    }
    mipc_jw_raw(w, "]", 1);
    mipc_jw_key(w, &first, "valid_flags");
    mipc_jw_u16(w, &in->valid_flags);
    mipc_jw_raw(w, "}", 1);
}

int mipc_aiding_llh_position_from_json(mipc_jr_t *jr, size_t pos, mipc_aiding_llh_position_t *out) {
    static const char *const keys[] = {"time",   "frame_id",    "latitude",   "longitude",
                                       "height", "uncertainty", "valid_flags"};
    size_t vp = 0;
    int found;
    size_t i;
    size_t it = 0;
    size_t ep = 0;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 7)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "time", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"time\"");
    }
    {
        mipc_jr_push(jr, "time");
        if (mipc_aiding_time_from_json(jr, vp, &out->time)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "frame_id", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"frame_id\"");
    }
    {
        mipc_jr_push(jr, "frame_id");
        if (mipc_jr_u8(jr, vp, &out->frame_id)) {
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
    found = mipc_jr_get(jr, pos, "uncertainty", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"uncertainty\"");
    }
    {
        mipc_jr_push(jr, "uncertainty");
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
            if (mipc_jr_f32(jr, ep, &out->uncertainty[i])) {
                return -1;
            }
        }
        mipc_jr_index(jr, SIZE_MAX);
        if (i != 3) {
            return mipc_jr_fail(jr, "expected 3 elements, got %zu", i);
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "valid_flags", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"valid_flags\"");
    }
    {
        mipc_jr_push(jr, "valid_flags");
        if (mipc_jr_u16(jr, vp, &out->valid_flags)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mipc_aiding_height_above_ellipsoid_t */

void mipc_aiding_height_above_ellipsoid_to_json(mipc_jw_t *w,
                                                const mipc_aiding_height_above_ellipsoid_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "time");
    mipc_aiding_time_to_json(w, &in->time);
    mipc_jw_key(w, &first, "frame_id");
    mipc_jw_u8(w, &in->frame_id);
    mipc_jw_key(w, &first, "height");
    mipc_jw_f32(w, &in->height);
    mipc_jw_key(w, &first, "uncertainty");
    mipc_jw_f32(w, &in->uncertainty);
    mipc_jw_key(w, &first, "valid_flags");
    mipc_jw_u16(w, &in->valid_flags);
    mipc_jw_raw(w, "}", 1);
}

int mipc_aiding_height_above_ellipsoid_from_json(mipc_jr_t *jr, size_t pos,
                                                 mipc_aiding_height_above_ellipsoid_t *out) {
    static const char *const keys[] = {"time", "frame_id", "height", "uncertainty", "valid_flags"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 5)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "time", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"time\"");
    }
    {
        mipc_jr_push(jr, "time");
        if (mipc_aiding_time_from_json(jr, vp, &out->time)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "frame_id", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"frame_id\"");
    }
    {
        mipc_jr_push(jr, "frame_id");
        if (mipc_jr_u8(jr, vp, &out->frame_id)) {
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
        if (mipc_jr_f32(jr, vp, &out->height)) {
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
    found = mipc_jr_get(jr, pos, "valid_flags", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"valid_flags\"");
    }
    {
        mipc_jr_push(jr, "valid_flags");
        if (mipc_jr_u16(jr, vp, &out->valid_flags)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mipc_aiding_ecef_velocity_t */

void mipc_aiding_ecef_velocity_to_json(mipc_jw_t *w, const mipc_aiding_ecef_velocity_t *in) {
    int first = 1;
    size_t i;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "time");
    mipc_aiding_time_to_json(w, &in->time);
    mipc_jw_key(w, &first, "frame_id");
    mipc_jw_u8(w, &in->frame_id);
    mipc_jw_key(w, &first, "velocity");
    mipc_jw_raw(w, "[", 1);
    for (i = 0; i < 3; i++) {
        mipc_jw_sep(w, i);
        mipc_jw_f32(w, &in->velocity[i]);
    }
    mipc_jw_raw(w, "]", 1);
    mipc_jw_key(w, &first, "uncertainty");
    mipc_jw_raw(w, "[", 1);
    for (i = 0; i < 3; i++) {
        mipc_jw_sep(w, i);
        mipc_jw_f32(w, &in->uncertainty[i]);
    }
    mipc_jw_raw(w, "]", 1);
    mipc_jw_key(w, &first, "valid_flags");
    mipc_jw_u16(w, &in->valid_flags);
    mipc_jw_raw(w, "}", 1);
}

int mipc_aiding_ecef_velocity_from_json(mipc_jr_t *jr, size_t pos, mipc_aiding_ecef_velocity_t *out) {
    static const char *const keys[] = {"time", "frame_id", "velocity", "uncertainty", "valid_flags"};
    size_t vp = 0;
    int found;
    size_t i;
    size_t it = 0;
    size_t ep = 0;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 5)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "time", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"time\"");
    }
    {
        mipc_jr_push(jr, "time");
        if (mipc_aiding_time_from_json(jr, vp, &out->time)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "frame_id", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"frame_id\"");
    }
    {
        mipc_jr_push(jr, "frame_id");
        if (mipc_jr_u8(jr, vp, &out->frame_id)) {
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
    found = mipc_jr_get(jr, pos, "uncertainty", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"uncertainty\"");
    }
    {
        mipc_jr_push(jr, "uncertainty");
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
            if (mipc_jr_f32(jr, ep, &out->uncertainty[i])) {
                return -1;
            }
        }
        mipc_jr_index(jr, SIZE_MAX);
        if (i != 3) {
            return mipc_jr_fail(jr, "expected 3 elements, got %zu", i);
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "valid_flags", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"valid_flags\"");
    }
    {
        mipc_jr_push(jr, "valid_flags");
        if (mipc_jr_u16(jr, vp, &out->valid_flags)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mipc_aiding_ned_velocity_t */

void mipc_aiding_ned_velocity_to_json(mipc_jw_t *w, const mipc_aiding_ned_velocity_t *in) {
    int first = 1;
    size_t i;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "time");
    mipc_aiding_time_to_json(w, &in->time);
    mipc_jw_key(w, &first, "frame_id");
    mipc_jw_u8(w, &in->frame_id);
    mipc_jw_key(w, &first, "velocity");
    mipc_jw_raw(w, "[", 1);
    for (i = 0; i < 3; i++) {
        mipc_jw_sep(w, i);
        mipc_jw_f32(w, &in->velocity[i]);
    }
    mipc_jw_raw(w, "]", 1);
    mipc_jw_key(w, &first, "uncertainty");
    mipc_jw_raw(w, "[", 1);
    for (i = 0; i < 3; i++) {
        mipc_jw_sep(w, i);
        mipc_jw_f32(w, &in->uncertainty[i]);
    }
    mipc_jw_raw(w, "]", 1);
    mipc_jw_key(w, &first, "valid_flags");
    mipc_jw_u16(w, &in->valid_flags);
    mipc_jw_raw(w, "}", 1);
}

int mipc_aiding_ned_velocity_from_json(mipc_jr_t *jr, size_t pos, mipc_aiding_ned_velocity_t *out) {
    static const char *const keys[] = {"time", "frame_id", "velocity", "uncertainty", "valid_flags"};
    size_t vp = 0;
    int found;
    size_t i;
    size_t it = 0;
    size_t ep = 0;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 5)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "time", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"time\"");
    }
    {
        mipc_jr_push(jr, "time");
        if (mipc_aiding_time_from_json(jr, vp, &out->time)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "frame_id", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"frame_id\"");
    }
    {
        mipc_jr_push(jr, "frame_id");
        if (mipc_jr_u8(jr, vp, &out->frame_id)) {
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
    found = mipc_jr_get(jr, pos, "uncertainty", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"uncertainty\"");
    }
    {
        mipc_jr_push(jr, "uncertainty");
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
            if (mipc_jr_f32(jr, ep, &out->uncertainty[i])) {
                return -1;
            }
        }
        mipc_jr_index(jr, SIZE_MAX);
        if (i != 3) {
            return mipc_jr_fail(jr, "expected 3 elements, got %zu", i);
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "valid_flags", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"valid_flags\"");
    }
    {
        mipc_jr_push(jr, "valid_flags");
        if (mipc_jr_u16(jr, vp, &out->valid_flags)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mipc_aiding_body_frame_velocity_t */

void mipc_aiding_body_frame_velocity_to_json(mipc_jw_t *w, const mipc_aiding_body_frame_velocity_t *in) {
    int first = 1;
    size_t i;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "time");
    mipc_aiding_time_to_json(w, &in->time);
    mipc_jw_key(w, &first, "frame_id");
    mipc_jw_u8(w, &in->frame_id);
    mipc_jw_key(w, &first, "velocity");
    mipc_jw_raw(w, "[", 1);
    for (i = 0; i < 3; i++) {
        mipc_jw_sep(w, i);
        mipc_jw_f32(w, &in->velocity[i]);
    }
    mipc_jw_raw(w, "]", 1);
    mipc_jw_key(w, &first, "uncertainty");
    mipc_jw_raw(w, "[", 1);
    for (i = 0; i < 3; i++) {
        mipc_jw_sep(w, i);
        mipc_jw_f32(w, &in->uncertainty[i]);
    }
    mipc_jw_raw(w, "]", 1);
    mipc_jw_key(w, &first, "valid_flags");
    mipc_jw_u16(w, &in->valid_flags);
    mipc_jw_raw(w, "}", 1);
}

int mipc_aiding_body_frame_velocity_from_json(mipc_jr_t *jr, size_t pos,
                                              mipc_aiding_body_frame_velocity_t *out) {
    static const char *const keys[] = {"time", "frame_id", "velocity", "uncertainty", "valid_flags"};
    size_t vp = 0;
    int found;
    size_t i;
    size_t it = 0;
    size_t ep = 0;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 5)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "time", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"time\"");
    }
    {
        mipc_jr_push(jr, "time");
        if (mipc_aiding_time_from_json(jr, vp, &out->time)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "frame_id", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"frame_id\"");
    }
    {
        mipc_jr_push(jr, "frame_id");
        if (mipc_jr_u8(jr, vp, &out->frame_id)) {
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
    found = mipc_jr_get(jr, pos, "uncertainty", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"uncertainty\"");
    }
    {
        mipc_jr_push(jr, "uncertainty");
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
            if (mipc_jr_f32(jr, ep, &out->uncertainty[i])) {
                return -1;
            }
        }
        mipc_jr_index(jr, SIZE_MAX);
        if (i != 3) {
            return mipc_jr_fail(jr, "expected 3 elements, got %zu", i);
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "valid_flags", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"valid_flags\"");
    }
    {
        mipc_jr_push(jr, "valid_flags");
        if (mipc_jr_u16(jr, vp, &out->valid_flags)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mipc_aiding_true_heading_t */

void mipc_aiding_true_heading_to_json(mipc_jw_t *w, const mipc_aiding_true_heading_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "time");
    mipc_aiding_time_to_json(w, &in->time);
    mipc_jw_key(w, &first, "frame_id");
    mipc_jw_u8(w, &in->frame_id);
    mipc_jw_key(w, &first, "heading");
    mipc_jw_f32(w, &in->heading);
    mipc_jw_key(w, &first, "uncertainty");
    mipc_jw_f32(w, &in->uncertainty);
    mipc_jw_key(w, &first, "valid_flags");
    mipc_jw_u16(w, &in->valid_flags);
    mipc_jw_raw(w, "}", 1);
}

int mipc_aiding_true_heading_from_json(mipc_jr_t *jr, size_t pos, mipc_aiding_true_heading_t *out) {
    static const char *const keys[] = {"time", "frame_id", "heading", "uncertainty", "valid_flags"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 5)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "time", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"time\"");
    }
    {
        mipc_jr_push(jr, "time");
        if (mipc_aiding_time_from_json(jr, vp, &out->time)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "frame_id", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"frame_id\"");
    }
    {
        mipc_jr_push(jr, "frame_id");
        if (mipc_jr_u8(jr, vp, &out->frame_id)) {
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
    found = mipc_jr_get(jr, pos, "valid_flags", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"valid_flags\"");
    }
    {
        mipc_jr_push(jr, "valid_flags");
        if (mipc_jr_u16(jr, vp, &out->valid_flags)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mipc_aiding_magnetic_field_t */

void mipc_aiding_magnetic_field_to_json(mipc_jw_t *w, const mipc_aiding_magnetic_field_t *in) {
    int first = 1;
    size_t i;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "time");
    mipc_aiding_time_to_json(w, &in->time);
    mipc_jw_key(w, &first, "frame_id");
    mipc_jw_u8(w, &in->frame_id);
    mipc_jw_key(w, &first, "magnetic_field");
    mipc_jw_raw(w, "[", 1);
    for (i = 0; i < 3; i++) {
        mipc_jw_sep(w, i);
        mipc_jw_f32(w, &in->magnetic_field[i]);
    }
    mipc_jw_raw(w, "]", 1);
    mipc_jw_key(w, &first, "uncertainty");
    mipc_jw_raw(w, "[", 1);
    for (i = 0; i < 3; i++) {
        mipc_jw_sep(w, i);
        mipc_jw_f32(w, &in->uncertainty[i]);
    }
    mipc_jw_raw(w, "]", 1);
    mipc_jw_key(w, &first, "valid_flags");
    mipc_jw_u16(w, &in->valid_flags);
    mipc_jw_raw(w, "}", 1);
}

int mipc_aiding_magnetic_field_from_json(mipc_jr_t *jr, size_t pos, mipc_aiding_magnetic_field_t *out) {
    static const char *const keys[] = {"time", "frame_id", "magnetic_field", "uncertainty", "valid_flags"};
    size_t vp = 0;
    int found;
    size_t i;
    size_t it = 0;
    size_t ep = 0;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 5)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "time", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"time\"");
    }
    {
        mipc_jr_push(jr, "time");
        if (mipc_aiding_time_from_json(jr, vp, &out->time)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "frame_id", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"frame_id\"");
    }
    {
        mipc_jr_push(jr, "frame_id");
        if (mipc_jr_u8(jr, vp, &out->frame_id)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "magnetic_field", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"magnetic_field\"");
    }
    {
        mipc_jr_push(jr, "magnetic_field");
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
            if (mipc_jr_f32(jr, ep, &out->magnetic_field[i])) {
                return -1;
            }
        }
        mipc_jr_index(jr, SIZE_MAX);
        if (i != 3) {
            return mipc_jr_fail(jr, "expected 3 elements, got %zu", i);
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "uncertainty", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"uncertainty\"");
    }
    {
        mipc_jr_push(jr, "uncertainty");
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
            if (mipc_jr_f32(jr, ep, &out->uncertainty[i])) {
                return -1;
            }
        }
        mipc_jr_index(jr, SIZE_MAX);
        if (i != 3) {
            return mipc_jr_fail(jr, "expected 3 elements, got %zu", i);
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "valid_flags", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"valid_flags\"");
    }
    {
        mipc_jr_push(jr, "valid_flags");
        if (mipc_jr_u16(jr, vp, &out->valid_flags)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mipc_aiding_pressure_t */

void mipc_aiding_pressure_to_json(mipc_jw_t *w, const mipc_aiding_pressure_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "time");
    mipc_aiding_time_to_json(w, &in->time);
    mipc_jw_key(w, &first, "frame_id");
    mipc_jw_u8(w, &in->frame_id);
    mipc_jw_key(w, &first, "pressure");
    mipc_jw_f32(w, &in->pressure);
    mipc_jw_key(w, &first, "uncertainty");
    mipc_jw_f32(w, &in->uncertainty);
    mipc_jw_key(w, &first, "valid_flags");
    mipc_jw_u16(w, &in->valid_flags);
    mipc_jw_raw(w, "}", 1);
}

int mipc_aiding_pressure_from_json(mipc_jr_t *jr, size_t pos, mipc_aiding_pressure_t *out) {
    static const char *const keys[] = {"time", "frame_id", "pressure", "uncertainty", "valid_flags"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 5)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "time", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"time\"");
    }
    {
        mipc_jr_push(jr, "time");
        if (mipc_aiding_time_from_json(jr, vp, &out->time)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "frame_id", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"frame_id\"");
    }
    {
        mipc_jr_push(jr, "frame_id");
        if (mipc_jr_u8(jr, vp, &out->frame_id)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "pressure", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"pressure\"");
    }
    {
        mipc_jr_push(jr, "pressure");
        if (mipc_jr_f32(jr, vp, &out->pressure)) {
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
    found = mipc_jr_get(jr, pos, "valid_flags", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"valid_flags\"");
    }
    {
        mipc_jr_push(jr, "valid_flags");
        if (mipc_jr_u16(jr, vp, &out->valid_flags)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    return 0;
}
