/* Canonical JSON of Estimation Filter Data Set (the mipcodec_json library). Generated from the spec: do not
 * edit. */
#include "mipcodec/sets/filter_data.h"
#include "layouts_internal.h"
#include "types_internal.h"

#include <assert.h>
#include <string.h>

/* ---- mipc_filter_data_llh_position_t */

void mipc_filter_data_llh_position_to_json(mipc_jw_t *w, const mipc_filter_data_llh_position_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "latitude");
    mipc_jw_f64(w, &in->latitude);
    mipc_jw_key(w, &first, "longitude");
    mipc_jw_f64(w, &in->longitude);
    mipc_jw_key(w, &first, "ellipsoid_height");
    mipc_jw_f64(w, &in->ellipsoid_height);
    mipc_jw_key(w, &first, "valid_flags");
    mipc_jw_u16(w, &in->valid_flags);
    mipc_jw_raw(w, "}", 1);
}

int mipc_filter_data_llh_position_from_json(mipc_jr_t *jr, size_t pos, mipc_filter_data_llh_position_t *out) {
    static const char *const keys[] = {"latitude", "longitude", "ellipsoid_height", "valid_flags"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 4)) {
        return -1;
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
    found = mipc_jr_get(jr, pos, "ellipsoid_height", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"ellipsoid_height\"");
    }
    {
        mipc_jr_push(jr, "ellipsoid_height");
        if (mipc_jr_f64(jr, vp, &out->ellipsoid_height)) {
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

/* ---- mipc_filter_data_ned_velocity_t */

void mipc_filter_data_ned_velocity_to_json(mipc_jw_t *w, const mipc_filter_data_ned_velocity_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "north");
    mipc_jw_f32(w, &in->north);
    mipc_jw_key(w, &first, "east");
    mipc_jw_f32(w, &in->east);
    mipc_jw_key(w, &first, "down");
    mipc_jw_f32(w, &in->down);
    mipc_jw_key(w, &first, "valid_flags");
    mipc_jw_u16(w, &in->valid_flags);
    mipc_jw_raw(w, "}", 1);
}

int mipc_filter_data_ned_velocity_from_json(mipc_jr_t *jr, size_t pos, mipc_filter_data_ned_velocity_t *out) {
    static const char *const keys[] = {"north", "east", "down", "valid_flags"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 4)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "north", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"north\"");
    }
    {
        mipc_jr_push(jr, "north");
        if (mipc_jr_f32(jr, vp, &out->north)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "east", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"east\"");
    }
    {
        mipc_jr_push(jr, "east");
        if (mipc_jr_f32(jr, vp, &out->east)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "down", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"down\"");
    }
    {
        mipc_jr_push(jr, "down");
        if (mipc_jr_f32(jr, vp, &out->down)) {
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

/* ---- mipc_filter_data_attitude_quaternion_t */

void mipc_filter_data_attitude_quaternion_to_json(mipc_jw_t *w,
                                                  const mipc_filter_data_attitude_quaternion_t *in) {
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
    mipc_jw_key(w, &first, "valid_flags");
    mipc_jw_u16(w, &in->valid_flags);
    mipc_jw_raw(w, "}", 1);
}

int mipc_filter_data_attitude_quaternion_from_json(mipc_jr_t *jr, size_t pos,
                                                   mipc_filter_data_attitude_quaternion_t *out) {
    static const char *const keys[] = {"q", "valid_flags"};
    size_t vp = 0;
    int found;
    size_t i;
    size_t it = 0;
    size_t ep = 0;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 2)) {
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

/* ---- mipc_filter_data_attitude_dcm_t */

void mipc_filter_data_attitude_dcm_to_json(mipc_jw_t *w, const mipc_filter_data_attitude_dcm_t *in) {
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
    mipc_jw_key(w, &first, "valid_flags");
    mipc_jw_u16(w, &in->valid_flags);
    mipc_jw_raw(w, "}", 1);
}

int mipc_filter_data_attitude_dcm_from_json(mipc_jr_t *jr, size_t pos, mipc_filter_data_attitude_dcm_t *out) {
    static const char *const keys[] = {"dcm", "valid_flags"};
    size_t vp = 0;
    int found;
    size_t i;
    size_t it = 0;
    size_t ep = 0;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 2)) {
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

/* ---- mipc_filter_data_euler_angles_t */

void mipc_filter_data_euler_angles_to_json(mipc_jw_t *w, const mipc_filter_data_euler_angles_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "roll");
    mipc_jw_f32(w, &in->roll);
    mipc_jw_key(w, &first, "pitch");
    mipc_jw_f32(w, &in->pitch);
    mipc_jw_key(w, &first, "yaw");
    mipc_jw_f32(w, &in->yaw);
    mipc_jw_key(w, &first, "valid_flags");
    mipc_jw_u16(w, &in->valid_flags);
    mipc_jw_raw(w, "}", 1);
}

int mipc_filter_data_euler_angles_from_json(mipc_jr_t *jr, size_t pos, mipc_filter_data_euler_angles_t *out) {
    static const char *const keys[] = {"roll", "pitch", "yaw", "valid_flags"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 4)) {
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

/* ---- mipc_filter_data_gyro_bias_t */

void mipc_filter_data_gyro_bias_to_json(mipc_jw_t *w, const mipc_filter_data_gyro_bias_t *in) {
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
    mipc_jw_key(w, &first, "valid_flags");
    mipc_jw_u16(w, &in->valid_flags);
    mipc_jw_raw(w, "}", 1);
}

int mipc_filter_data_gyro_bias_from_json(mipc_jr_t *jr, size_t pos, mipc_filter_data_gyro_bias_t *out) {
    static const char *const keys[] = {"bias", "valid_flags"};
    size_t vp = 0;
    int found;
    size_t i;
    size_t it = 0;
    size_t ep = 0;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 2)) {
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

/* ---- mipc_filter_data_accel_bias_t */

void mipc_filter_data_accel_bias_to_json(mipc_jw_t *w, const mipc_filter_data_accel_bias_t *in) {
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
    mipc_jw_key(w, &first, "valid_flags");
    mipc_jw_u16(w, &in->valid_flags);
    mipc_jw_raw(w, "}", 1);
}

int mipc_filter_data_accel_bias_from_json(mipc_jr_t *jr, size_t pos, mipc_filter_data_accel_bias_t *out) {
    static const char *const keys[] = {"bias", "valid_flags"};
    size_t vp = 0;
    int found;
    size_t i;
    size_t it = 0;
    size_t ep = 0;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 2)) {
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

/* ---- mipc_filter_data_llh_position_uncertainty_t */

void mipc_filter_data_llh_position_uncertainty_to_json(
    mipc_jw_t *w, const mipc_filter_data_llh_position_uncertainty_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "north");
    mipc_jw_f32(w, &in->north);
    mipc_jw_key(w, &first, "east");
    mipc_jw_f32(w, &in->east);
    mipc_jw_key(w, &first, "down");
    mipc_jw_f32(w, &in->down);
    mipc_jw_key(w, &first, "valid_flags");
    mipc_jw_u16(w, &in->valid_flags);
    mipc_jw_raw(w, "}", 1);
}

int mipc_filter_data_llh_position_uncertainty_from_json(mipc_jr_t *jr, size_t pos,
                                                        mipc_filter_data_llh_position_uncertainty_t *out) {
    static const char *const keys[] = {"north", "east", "down", "valid_flags"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 4)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "north", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"north\"");
    }
    {
        mipc_jr_push(jr, "north");
        if (mipc_jr_f32(jr, vp, &out->north)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "east", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"east\"");
    }
    {
        mipc_jr_push(jr, "east");
        if (mipc_jr_f32(jr, vp, &out->east)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "down", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"down\"");
    }
    {
        mipc_jr_push(jr, "down");
        if (mipc_jr_f32(jr, vp, &out->down)) {
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

/* ---- mipc_filter_data_ned_velocity_uncertainty_t */

void mipc_filter_data_ned_velocity_uncertainty_to_json(
    mipc_jw_t *w, const mipc_filter_data_ned_velocity_uncertainty_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "north");
    mipc_jw_f32(w, &in->north);
    mipc_jw_key(w, &first, "east");
    mipc_jw_f32(w, &in->east);
    mipc_jw_key(w, &first, "down");
    mipc_jw_f32(w, &in->down);
    mipc_jw_key(w, &first, "valid_flags");
    mipc_jw_u16(w, &in->valid_flags);
    mipc_jw_raw(w, "}", 1);
}

int mipc_filter_data_ned_velocity_uncertainty_from_json(mipc_jr_t *jr, size_t pos,
                                                        mipc_filter_data_ned_velocity_uncertainty_t *out) {
    static const char *const keys[] = {"north", "east", "down", "valid_flags"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 4)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "north", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"north\"");
    }
    {
        mipc_jr_push(jr, "north");
        if (mipc_jr_f32(jr, vp, &out->north)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "east", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"east\"");
    }
    {
        mipc_jr_push(jr, "east");
        if (mipc_jr_f32(jr, vp, &out->east)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "down", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"down\"");
    }
    {
        mipc_jr_push(jr, "down");
        if (mipc_jr_f32(jr, vp, &out->down)) {
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

/* ---- mipc_filter_data_euler_angles_uncertainty_t */

void mipc_filter_data_euler_angles_uncertainty_to_json(
    mipc_jw_t *w, const mipc_filter_data_euler_angles_uncertainty_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "roll");
    mipc_jw_f32(w, &in->roll);
    mipc_jw_key(w, &first, "pitch");
    mipc_jw_f32(w, &in->pitch);
    mipc_jw_key(w, &first, "yaw");
    mipc_jw_f32(w, &in->yaw);
    mipc_jw_key(w, &first, "valid_flags");
    mipc_jw_u16(w, &in->valid_flags);
    mipc_jw_raw(w, "}", 1);
}

int mipc_filter_data_euler_angles_uncertainty_from_json(mipc_jr_t *jr, size_t pos,
                                                        mipc_filter_data_euler_angles_uncertainty_t *out) {
    static const char *const keys[] = {"roll", "pitch", "yaw", "valid_flags"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 4)) {
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

/* ---- mipc_filter_data_gyro_bias_uncertainty_t */

void mipc_filter_data_gyro_bias_uncertainty_to_json(mipc_jw_t *w,
                                                    const mipc_filter_data_gyro_bias_uncertainty_t *in) {
    int first = 1;
    size_t i;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "bias_uncertainty");
    mipc_jw_raw(w, "[", 1);
    for (i = 0; i < 3; i++) {
        mipc_jw_sep(w, i);
        mipc_jw_f32(w, &in->bias_uncertainty[i]);
    }
    mipc_jw_raw(w, "]", 1);
    mipc_jw_key(w, &first, "valid_flags");
    mipc_jw_u16(w, &in->valid_flags);
    mipc_jw_raw(w, "}", 1);
}

int mipc_filter_data_gyro_bias_uncertainty_from_json(mipc_jr_t *jr, size_t pos,
                                                     mipc_filter_data_gyro_bias_uncertainty_t *out) {
    static const char *const keys[] = {"bias_uncertainty", "valid_flags"};
    size_t vp = 0;
    int found;
    size_t i;
    size_t it = 0;
    size_t ep = 0;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 2)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "bias_uncertainty", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"bias_uncertainty\"");
    }
    {
        mipc_jr_push(jr, "bias_uncertainty");
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
            if (mipc_jr_f32(jr, ep, &out->bias_uncertainty[i])) {
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

/* ---- mipc_filter_data_accel_bias_uncertainty_t */

void mipc_filter_data_accel_bias_uncertainty_to_json(mipc_jw_t *w,
                                                     const mipc_filter_data_accel_bias_uncertainty_t *in) {
    int first = 1;
    size_t i;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "bias_uncertainty");
    mipc_jw_raw(w, "[", 1);
    for (i = 0; i < 3; i++) {
        mipc_jw_sep(w, i);
        mipc_jw_f32(w, &in->bias_uncertainty[i]);
    }
    mipc_jw_raw(w, "]", 1);
    mipc_jw_key(w, &first, "valid_flags");
    mipc_jw_u16(w, &in->valid_flags);
    mipc_jw_raw(w, "}", 1);
}

int mipc_filter_data_accel_bias_uncertainty_from_json(mipc_jr_t *jr, size_t pos,
                                                      mipc_filter_data_accel_bias_uncertainty_t *out) {
    static const char *const keys[] = {"bias_uncertainty", "valid_flags"};
    size_t vp = 0;
    int found;
    size_t i;
    size_t it = 0;
    size_t ep = 0;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 2)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "bias_uncertainty", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"bias_uncertainty\"");
    }
    {
        mipc_jr_push(jr, "bias_uncertainty");
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
            if (mipc_jr_f32(jr, ep, &out->bias_uncertainty[i])) {
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

/* ---- mipc_filter_data_linear_accel_t */

void mipc_filter_data_linear_accel_to_json(mipc_jw_t *w, const mipc_filter_data_linear_accel_t *in) {
    int first = 1;
    size_t i;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "accel");
    mipc_jw_raw(w, "[", 1);
    for (i = 0; i < 3; i++) {
        mipc_jw_sep(w, i);
        mipc_jw_f32(w, &in->accel[i]);
    }
    mipc_jw_raw(w, "]", 1);
    mipc_jw_key(w, &first, "valid_flags");
    mipc_jw_u16(w, &in->valid_flags);
    mipc_jw_raw(w, "}", 1);
}

int mipc_filter_data_linear_accel_from_json(mipc_jr_t *jr, size_t pos, mipc_filter_data_linear_accel_t *out) {
    static const char *const keys[] = {"accel", "valid_flags"};
    size_t vp = 0;
    int found;
    size_t i;
    size_t it = 0;
    size_t ep = 0;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 2)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "accel", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"accel\"");
    }
    {
        mipc_jr_push(jr, "accel");
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
            if (mipc_jr_f32(jr, ep, &out->accel[i])) {
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

/* ---- mipc_filter_data_comp_angular_rate_t */

void mipc_filter_data_comp_angular_rate_to_json(mipc_jw_t *w,
                                                const mipc_filter_data_comp_angular_rate_t *in) {
    int first = 1;
    size_t i;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "gyro");
    mipc_jw_raw(w, "[", 1);
    for (i = 0; i < 3; i++) {
        mipc_jw_sep(w, i);
        mipc_jw_f32(w, &in->gyro[i]);
    }
    mipc_jw_raw(w, "]", 1);
    mipc_jw_key(w, &first, "valid_flags");
    mipc_jw_u16(w, &in->valid_flags);
    mipc_jw_raw(w, "}", 1);
}

int mipc_filter_data_comp_angular_rate_from_json(mipc_jr_t *jr, size_t pos,
                                                 mipc_filter_data_comp_angular_rate_t *out) {
    static const char *const keys[] = {"gyro", "valid_flags"};
    size_t vp = 0;
    int found;
    size_t i;
    size_t it = 0;
    size_t ep = 0;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 2)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "gyro", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"gyro\"");
    }
    {
        mipc_jr_push(jr, "gyro");
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
            if (mipc_jr_f32(jr, ep, &out->gyro[i])) {
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

/* ---- mipc_filter_data_wgs84_gravity_magnitude_t */

void mipc_filter_data_wgs84_gravity_magnitude_to_json(mipc_jw_t *w,
                                                      const mipc_filter_data_wgs84_gravity_magnitude_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "gravity_magnitude");
    mipc_jw_f32(w, &in->gravity_magnitude);
    mipc_jw_key(w, &first, "valid_flags");
    mipc_jw_u16(w, &in->valid_flags);
    mipc_jw_raw(w, "}", 1);
}

int mipc_filter_data_wgs84_gravity_magnitude_from_json(mipc_jr_t *jr, size_t pos,
                                                       mipc_filter_data_wgs84_gravity_magnitude_t *out) {
    static const char *const keys[] = {"gravity_magnitude", "valid_flags"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 2)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "gravity_magnitude", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"gravity_magnitude\"");
    }
    {
        mipc_jr_push(jr, "gravity_magnitude");
        if (mipc_jr_f32(jr, vp, &out->gravity_magnitude)) {
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

/* ---- mipc_filter_data_filter_status_gx5_45_t */

void mipc_filter_data_filter_status_gx5_45_to_json(mipc_jw_t *w,
                                                   const mipc_filter_data_filter_status_gx5_45_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "filter_state");
    mipc_jw_u16(w, &in->filter_state);
    mipc_jw_key(w, &first, "dynamics_mode");
    mipc_jw_u16(w, &in->dynamics_mode);
    mipc_jw_key(w, &first, "status_flags");
    mipc_jw_u16(w, &in->status_flags);
    mipc_jw_raw(w, "}", 1);
}

int mipc_filter_data_filter_status_gx5_45_from_json(mipc_jr_t *jr, size_t pos,
                                                    mipc_filter_data_filter_status_gx5_45_t *out) {
    static const char *const keys[] = {"filter_state", "dynamics_mode", "status_flags"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 3)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "filter_state", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"filter_state\"");
    }
    {
        mipc_jr_push(jr, "filter_state");
        if (mipc_jr_u16(jr, vp, &out->filter_state)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "dynamics_mode", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"dynamics_mode\"");
    }
    {
        mipc_jr_push(jr, "dynamics_mode");
        if (mipc_jr_u16(jr, vp, &out->dynamics_mode)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "status_flags", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"status_flags\"");
    }
    {
        mipc_jr_push(jr, "status_flags");
        if (mipc_jr_u16(jr, vp, &out->status_flags)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mipc_filter_data_filter_status_cv7_ins_t */

void mipc_filter_data_filter_status_cv7_ins_to_json(mipc_jw_t *w,
                                                    const mipc_filter_data_filter_status_cv7_ins_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "filter_state");
    mipc_jw_u16(w, &in->filter_state);
    mipc_jw_key(w, &first, "dynamics_mode");
    mipc_jw_u16(w, &in->dynamics_mode);
    mipc_jw_key(w, &first, "status_flags");
    mipc_jw_u16(w, &in->status_flags);
    mipc_jw_raw(w, "}", 1);
}

int mipc_filter_data_filter_status_cv7_ins_from_json(mipc_jr_t *jr, size_t pos,
                                                     mipc_filter_data_filter_status_cv7_ins_t *out) {
    static const char *const keys[] = {"filter_state", "dynamics_mode", "status_flags"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 3)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "filter_state", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"filter_state\"");
    }
    {
        mipc_jr_push(jr, "filter_state");
        if (mipc_jr_u16(jr, vp, &out->filter_state)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "dynamics_mode", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"dynamics_mode\"");
    }
    {
        mipc_jr_push(jr, "dynamics_mode");
        if (mipc_jr_u16(jr, vp, &out->dynamics_mode)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "status_flags", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"status_flags\"");
    }
    {
        mipc_jr_push(jr, "status_flags");
        if (mipc_jr_u16(jr, vp, &out->status_flags)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mipc_filter_data_gps_timestamp_t */

void mipc_filter_data_gps_timestamp_to_json(mipc_jw_t *w, const mipc_filter_data_gps_timestamp_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "tow");
    mipc_jw_f64(w, &in->tow);
    mipc_jw_key(w, &first, "week_number");
    mipc_jw_u16(w, &in->week_number);
    mipc_jw_key(w, &first, "valid_flags");
    mipc_jw_u16(w, &in->valid_flags);
    mipc_jw_raw(w, "}", 1);
}

int mipc_filter_data_gps_timestamp_from_json(mipc_jr_t *jr, size_t pos,
                                             mipc_filter_data_gps_timestamp_t *out) {
    static const char *const keys[] = {"tow", "week_number", "valid_flags"};
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

/* ---- mipc_filter_data_quaternion_attitude_uncertainty_t */

void mipc_filter_data_quaternion_attitude_uncertainty_to_json(
    mipc_jw_t *w, const mipc_filter_data_quaternion_attitude_uncertainty_t *in) {
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
    mipc_jw_key(w, &first, "valid_flags");
    mipc_jw_u16(w, &in->valid_flags);
    mipc_jw_raw(w, "}", 1);
}

int mipc_filter_data_quaternion_attitude_uncertainty_from_json(
    mipc_jr_t *jr, size_t pos, mipc_filter_data_quaternion_attitude_uncertainty_t *out) {
    static const char *const keys[] = {"q", "valid_flags"};
    size_t vp = 0;
    int found;
    size_t i;
    size_t it = 0;
    size_t ep = 0;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 2)) {
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

/* ---- mipc_filter_data_gravity_vector_t */

void mipc_filter_data_gravity_vector_to_json(mipc_jw_t *w, const mipc_filter_data_gravity_vector_t *in) {
    int first = 1;
    size_t i;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "gravity");
    mipc_jw_raw(w, "[", 1);
    for (i = 0; i < 3; i++) {
        mipc_jw_sep(w, i);
        mipc_jw_f32(w, &in->gravity[i]);
    }
    mipc_jw_raw(w, "]", 1);
    mipc_jw_key(w, &first, "valid_flags");
    mipc_jw_u16(w, &in->valid_flags);
    mipc_jw_raw(w, "}", 1);
}

int mipc_filter_data_gravity_vector_from_json(mipc_jr_t *jr, size_t pos,
                                              mipc_filter_data_gravity_vector_t *out) {
    static const char *const keys[] = {"gravity", "valid_flags"};
    size_t vp = 0;
    int found;
    size_t i;
    size_t it = 0;
    size_t ep = 0;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 2)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "gravity", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"gravity\"");
    }
    {
        mipc_jr_push(jr, "gravity");
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
            if (mipc_jr_f32(jr, ep, &out->gravity[i])) {
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

/* ---- mipc_filter_data_heading_update_state_t */

void mipc_filter_data_heading_update_state_to_json(mipc_jw_t *w,
                                                   const mipc_filter_data_heading_update_state_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "heading");
    mipc_jw_f32(w, &in->heading);
    mipc_jw_key(w, &first, "heading_uncertainty");
    mipc_jw_f32(w, &in->heading_uncertainty);
    mipc_jw_key(w, &first, "source");
    mipc_jw_u16(w, &in->source);
    mipc_jw_key(w, &first, "valid_flags");
    mipc_jw_u16(w, &in->valid_flags);
    mipc_jw_raw(w, "}", 1);
}

int mipc_filter_data_heading_update_state_from_json(mipc_jr_t *jr, size_t pos,
                                                    mipc_filter_data_heading_update_state_t *out) {
    static const char *const keys[] = {"heading", "heading_uncertainty", "source", "valid_flags"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 4)) {
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

/* ---- mipc_filter_data_magnetic_model_t */

void mipc_filter_data_magnetic_model_to_json(mipc_jw_t *w, const mipc_filter_data_magnetic_model_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "intensity_north");
    mipc_jw_f32(w, &in->intensity_north);
    mipc_jw_key(w, &first, "intensity_east");
    mipc_jw_f32(w, &in->intensity_east);
    mipc_jw_key(w, &first, "intensity_down");
    mipc_jw_f32(w, &in->intensity_down);
    mipc_jw_key(w, &first, "inclination");
    mipc_jw_f32(w, &in->inclination);
    mipc_jw_key(w, &first, "declination");
    mipc_jw_f32(w, &in->declination);
    mipc_jw_key(w, &first, "valid_flags");
    mipc_jw_u16(w, &in->valid_flags);
    mipc_jw_raw(w, "}", 1);
}

int mipc_filter_data_magnetic_model_from_json(mipc_jr_t *jr, size_t pos,
                                              mipc_filter_data_magnetic_model_t *out) {
    static const char *const keys[] = {"intensity_north", "intensity_east", "intensity_down",
                                       "inclination",     "declination",    "valid_flags"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 6)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "intensity_north", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"intensity_north\"");
    }
    {
        mipc_jr_push(jr, "intensity_north");
        if (mipc_jr_f32(jr, vp, &out->intensity_north)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "intensity_east", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"intensity_east\"");
    }
    {
        mipc_jr_push(jr, "intensity_east");
        if (mipc_jr_f32(jr, vp, &out->intensity_east)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "intensity_down", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"intensity_down\"");
    }
    {
        mipc_jr_push(jr, "intensity_down");
        if (mipc_jr_f32(jr, vp, &out->intensity_down)) {
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

/* ---- mipc_filter_data_gyro_scale_factor_t */

void mipc_filter_data_gyro_scale_factor_to_json(mipc_jw_t *w,
                                                const mipc_filter_data_gyro_scale_factor_t *in) {
    int first = 1;
    size_t i;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "scale_factor");
    mipc_jw_raw(w, "[", 1);
    for (i = 0; i < 3; i++) {
        mipc_jw_sep(w, i);
        mipc_jw_f32(w, &in->scale_factor[i]);
    }
    mipc_jw_raw(w, "]", 1);
    mipc_jw_key(w, &first, "valid_flags");
    mipc_jw_u16(w, &in->valid_flags);
    mipc_jw_raw(w, "}", 1);
}

int mipc_filter_data_gyro_scale_factor_from_json(mipc_jr_t *jr, size_t pos,
                                                 mipc_filter_data_gyro_scale_factor_t *out) {
    static const char *const keys[] = {"scale_factor", "valid_flags"};
    size_t vp = 0;
    int found;
    size_t i;
    size_t it = 0;
    size_t ep = 0;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 2)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "scale_factor", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"scale_factor\"");
    }
    {
        mipc_jr_push(jr, "scale_factor");
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
            if (mipc_jr_f32(jr, ep, &out->scale_factor[i])) {
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

/* ---- mipc_filter_data_accel_scale_factor_t */

void mipc_filter_data_accel_scale_factor_to_json(mipc_jw_t *w,
                                                 const mipc_filter_data_accel_scale_factor_t *in) {
    int first = 1;
    size_t i;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "scale_factor");
    mipc_jw_raw(w, "[", 1);
    for (i = 0; i < 3; i++) {
        mipc_jw_sep(w, i);
        mipc_jw_f32(w, &in->scale_factor[i]);
    }
    mipc_jw_raw(w, "]", 1);
    mipc_jw_key(w, &first, "valid_flags");
    mipc_jw_u16(w, &in->valid_flags);
    mipc_jw_raw(w, "}", 1);
}

int mipc_filter_data_accel_scale_factor_from_json(mipc_jr_t *jr, size_t pos,
                                                  mipc_filter_data_accel_scale_factor_t *out) {
    static const char *const keys[] = {"scale_factor", "valid_flags"};
    size_t vp = 0;
    int found;
    size_t i;
    size_t it = 0;
    size_t ep = 0;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 2)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "scale_factor", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"scale_factor\"");
    }
    {
        mipc_jr_push(jr, "scale_factor");
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
            if (mipc_jr_f32(jr, ep, &out->scale_factor[i])) {
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

/* ---- mipc_filter_data_gyro_scale_factor_uncertainty_t */

void mipc_filter_data_gyro_scale_factor_uncertainty_to_json(
    mipc_jw_t *w, const mipc_filter_data_gyro_scale_factor_uncertainty_t *in) {
    int first = 1;
    size_t i;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "scale_factor_uncertainty");
    mipc_jw_raw(w, "[", 1);
    for (i = 0; i < 3; i++) {
        mipc_jw_sep(w, i);
        mipc_jw_f32(w, &in->scale_factor_uncertainty[i]);
    }
    mipc_jw_raw(w, "]", 1);
    mipc_jw_key(w, &first, "valid_flags");
    mipc_jw_u16(w, &in->valid_flags);
    mipc_jw_raw(w, "}", 1);
}

int mipc_filter_data_gyro_scale_factor_uncertainty_from_json(
    mipc_jr_t *jr, size_t pos, mipc_filter_data_gyro_scale_factor_uncertainty_t *out) {
    static const char *const keys[] = {"scale_factor_uncertainty", "valid_flags"};
    size_t vp = 0;
    int found;
    size_t i;
    size_t it = 0;
    size_t ep = 0;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 2)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "scale_factor_uncertainty", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"scale_factor_uncertainty\"");
    }
    {
        mipc_jr_push(jr, "scale_factor_uncertainty");
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
            if (mipc_jr_f32(jr, ep, &out->scale_factor_uncertainty[i])) {
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

/* ---- mipc_filter_data_accel_scale_factor_uncertainty_t */

void mipc_filter_data_accel_scale_factor_uncertainty_to_json(
    mipc_jw_t *w, const mipc_filter_data_accel_scale_factor_uncertainty_t *in) {
    int first = 1;
    size_t i;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "scale_factor_uncertainty");
    mipc_jw_raw(w, "[", 1);
    for (i = 0; i < 3; i++) {
        mipc_jw_sep(w, i);
        mipc_jw_f32(w, &in->scale_factor_uncertainty[i]);
    }
    mipc_jw_raw(w, "]", 1);
    mipc_jw_key(w, &first, "valid_flags");
    mipc_jw_u16(w, &in->valid_flags);
    mipc_jw_raw(w, "}", 1);
}

int mipc_filter_data_accel_scale_factor_uncertainty_from_json(
    mipc_jr_t *jr, size_t pos, mipc_filter_data_accel_scale_factor_uncertainty_t *out) {
    static const char *const keys[] = {"scale_factor_uncertainty", "valid_flags"};
    size_t vp = 0;
    int found;
    size_t i;
    size_t it = 0;
    size_t ep = 0;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 2)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "scale_factor_uncertainty", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"scale_factor_uncertainty\"");
    }
    {
        mipc_jr_push(jr, "scale_factor_uncertainty");
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
            if (mipc_jr_f32(jr, ep, &out->scale_factor_uncertainty[i])) {
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

/* ---- mipc_filter_data_compensated_accel_t */

void mipc_filter_data_compensated_accel_to_json(mipc_jw_t *w,
                                                const mipc_filter_data_compensated_accel_t *in) {
    int first = 1;
    size_t i;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "accel");
    mipc_jw_raw(w, "[", 1);
    for (i = 0; i < 3; i++) {
        mipc_jw_sep(w, i);
        mipc_jw_f32(w, &in->accel[i]);
    }
    mipc_jw_raw(w, "]", 1);
    mipc_jw_key(w, &first, "valid_flags");
    mipc_jw_u16(w, &in->valid_flags);
    mipc_jw_raw(w, "}", 1);
}

int mipc_filter_data_compensated_accel_from_json(mipc_jr_t *jr, size_t pos,
                                                 mipc_filter_data_compensated_accel_t *out) {
    static const char *const keys[] = {"accel", "valid_flags"};
    size_t vp = 0;
    int found;
    size_t i;
    size_t it = 0;
    size_t ep = 0;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 2)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "accel", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"accel\"");
    }
    {
        mipc_jr_push(jr, "accel");
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
            if (mipc_jr_f32(jr, ep, &out->accel[i])) {
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

/* ---- mipc_filter_data_standard_atmosphere_t */

void mipc_filter_data_standard_atmosphere_to_json(mipc_jw_t *w,
                                                  const mipc_filter_data_standard_atmosphere_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "geometric_altitude");
    mipc_jw_f32(w, &in->geometric_altitude);
    mipc_jw_key(w, &first, "geopotential_altitude");
    mipc_jw_f32(w, &in->geopotential_altitude);
    mipc_jw_key(w, &first, "temperature");
    mipc_jw_f32(w, &in->temperature);
    mipc_jw_key(w, &first, "pressure");
    mipc_jw_f32(w, &in->pressure);
    mipc_jw_key(w, &first, "density");
    mipc_jw_f32(w, &in->density);
    mipc_jw_key(w, &first, "valid_flags");
    mipc_jw_u16(w, &in->valid_flags);
    mipc_jw_raw(w, "}", 1);
}

int mipc_filter_data_standard_atmosphere_from_json(mipc_jr_t *jr, size_t pos,
                                                   mipc_filter_data_standard_atmosphere_t *out) {
    static const char *const keys[] = {
        "geometric_altitude", "geopotential_altitude", "temperature", "pressure", "density", "valid_flags"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 6)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "geometric_altitude", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"geometric_altitude\"");
    }
    {
        mipc_jr_push(jr, "geometric_altitude");
        if (mipc_jr_f32(jr, vp, &out->geometric_altitude)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "geopotential_altitude", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"geopotential_altitude\"");
    }
    {
        mipc_jr_push(jr, "geopotential_altitude");
        if (mipc_jr_f32(jr, vp, &out->geopotential_altitude)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "temperature", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"temperature\"");
    }
    {
        mipc_jr_push(jr, "temperature");
        if (mipc_jr_f32(jr, vp, &out->temperature)) {
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
    found = mipc_jr_get(jr, pos, "density", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"density\"");
    }
    {
        mipc_jr_push(jr, "density");
        if (mipc_jr_f32(jr, vp, &out->density)) {
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

/* ---- mipc_filter_data_pressure_altitude_t */

void mipc_filter_data_pressure_altitude_to_json(mipc_jw_t *w,
                                                const mipc_filter_data_pressure_altitude_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "pressure_altitude");
    mipc_jw_f32(w, &in->pressure_altitude);
    mipc_jw_key(w, &first, "valid_flags");
    mipc_jw_u16(w, &in->valid_flags);
    mipc_jw_raw(w, "}", 1);
}

int mipc_filter_data_pressure_altitude_from_json(mipc_jr_t *jr, size_t pos,
                                                 mipc_filter_data_pressure_altitude_t *out) {
    static const char *const keys[] = {"pressure_altitude", "valid_flags"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 2)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "pressure_altitude", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"pressure_altitude\"");
    }
    {
        mipc_jr_push(jr, "pressure_altitude");
        if (mipc_jr_f32(jr, vp, &out->pressure_altitude)) {
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

/* ---- mipc_filter_data_mag_auto_hard_iron_offset_t */

void mipc_filter_data_mag_auto_hard_iron_offset_to_json(
    mipc_jw_t *w, const mipc_filter_data_mag_auto_hard_iron_offset_t *in) {
    int first = 1;
    size_t i;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "hard_iron_offset");
    mipc_jw_raw(w, "[", 1);
    for (i = 0; i < 3; i++) {
        mipc_jw_sep(w, i);
        mipc_jw_f32(w, &in->hard_iron_offset[i]);
    }
    mipc_jw_raw(w, "]", 1);
    mipc_jw_key(w, &first, "valid_flags");
    mipc_jw_u16(w, &in->valid_flags);
    mipc_jw_raw(w, "}", 1);
}

int mipc_filter_data_mag_auto_hard_iron_offset_from_json(mipc_jr_t *jr, size_t pos,
                                                         mipc_filter_data_mag_auto_hard_iron_offset_t *out) {
    static const char *const keys[] = {"hard_iron_offset", "valid_flags"};
    size_t vp = 0;
    int found;
    size_t i;
    size_t it = 0;
    size_t ep = 0;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 2)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "hard_iron_offset", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"hard_iron_offset\"");
    }
    {
        mipc_jr_push(jr, "hard_iron_offset");
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
            if (mipc_jr_f32(jr, ep, &out->hard_iron_offset[i])) {
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

/* ---- mipc_filter_data_mag_auto_soft_iron_matrix_t */

void mipc_filter_data_mag_auto_soft_iron_matrix_to_json(
    mipc_jw_t *w, const mipc_filter_data_mag_auto_soft_iron_matrix_t *in) {
    int first = 1;
    size_t i;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "soft_iron_matrix");
    mipc_jw_raw(w, "[", 1);
    for (i = 0; i < 9; i++) {
        mipc_jw_sep(w, i);
        mipc_jw_f32(w, &in->soft_iron_matrix[i]);
    }
    mipc_jw_raw(w, "]", 1);
    mipc_jw_key(w, &first, "valid_flags");
    mipc_jw_u16(w, &in->valid_flags);
    mipc_jw_raw(w, "}", 1);
}

int mipc_filter_data_mag_auto_soft_iron_matrix_from_json(mipc_jr_t *jr, size_t pos,
                                                         mipc_filter_data_mag_auto_soft_iron_matrix_t *out) {
    static const char *const keys[] = {"soft_iron_matrix", "valid_flags"};
    size_t vp = 0;
    int found;
    size_t i;
    size_t it = 0;
    size_t ep = 0;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 2)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "soft_iron_matrix", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"soft_iron_matrix\"");
    }
    {
        mipc_jr_push(jr, "soft_iron_matrix");
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
            if (mipc_jr_f32(jr, ep, &out->soft_iron_matrix[i])) {
                return -1;
            }
        }
        mipc_jr_index(jr, SIZE_MAX);
        if (i != 9) {
            return mipc_jr_fail(jr, "expected 9 elements, got %zu", i);
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

/* ---- mipc_filter_data_mag_auto_hard_iron_offset_uncertainty_t */

void mipc_filter_data_mag_auto_hard_iron_offset_uncertainty_to_json(
    mipc_jw_t *w, const mipc_filter_data_mag_auto_hard_iron_offset_uncertainty_t *in) {
    int first = 1;
    size_t i;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "hard_iron_offset_uncertainty");
    mipc_jw_raw(w, "[", 1);
    for (i = 0; i < 3; i++) {
        mipc_jw_sep(w, i);
        mipc_jw_f32(w, &in->hard_iron_offset_uncertainty[i]);
    }
    mipc_jw_raw(w, "]", 1);
    mipc_jw_key(w, &first, "valid_flags");
    mipc_jw_u16(w, &in->valid_flags);
    mipc_jw_raw(w, "}", 1);
}

int mipc_filter_data_mag_auto_hard_iron_offset_uncertainty_from_json(
    mipc_jr_t *jr, size_t pos, mipc_filter_data_mag_auto_hard_iron_offset_uncertainty_t *out) {
    static const char *const keys[] = {"hard_iron_offset_uncertainty", "valid_flags"};
    size_t vp = 0;
    int found;
    size_t i;
    size_t it = 0;
    size_t ep = 0;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 2)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "hard_iron_offset_uncertainty", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"hard_iron_offset_uncertainty\"");
    }
    {
        mipc_jr_push(jr, "hard_iron_offset_uncertainty");
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
            if (mipc_jr_f32(jr, ep, &out->hard_iron_offset_uncertainty[i])) {
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

/* ---- mipc_filter_data_mag_auto_soft_iron_matrix_uncertainty_t */

void mipc_filter_data_mag_auto_soft_iron_matrix_uncertainty_to_json(
    mipc_jw_t *w, const mipc_filter_data_mag_auto_soft_iron_matrix_uncertainty_t *in) {
    int first = 1;
    size_t i;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "soft_iron_matrix_uncertainty");
    mipc_jw_raw(w, "[", 1);
    for (i = 0; i < 9; i++) {
        mipc_jw_sep(w, i);
        mipc_jw_f32(w, &in->soft_iron_matrix_uncertainty[i]);
    }
    mipc_jw_raw(w, "]", 1);
    mipc_jw_key(w, &first, "valid_flags");
    mipc_jw_u16(w, &in->valid_flags);
    mipc_jw_raw(w, "}", 1);
}

int mipc_filter_data_mag_auto_soft_iron_matrix_uncertainty_from_json(
    mipc_jr_t *jr, size_t pos, mipc_filter_data_mag_auto_soft_iron_matrix_uncertainty_t *out) {
    static const char *const keys[] = {"soft_iron_matrix_uncertainty", "valid_flags"};
    size_t vp = 0;
    int found;
    size_t i;
    size_t it = 0;
    size_t ep = 0;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 2)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "soft_iron_matrix_uncertainty", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"soft_iron_matrix_uncertainty\"");
    }
    {
        mipc_jr_push(jr, "soft_iron_matrix_uncertainty");
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
            if (mipc_jr_f32(jr, ep, &out->soft_iron_matrix_uncertainty[i])) {
                return -1;
            }
        }
        mipc_jr_index(jr, SIZE_MAX);
        if (i != 9) {
            return mipc_jr_fail(jr, "expected 9 elements, got %zu", i);
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

/* ---- mipc_filter_data_gnss_antenna_offset_correction_t */

void mipc_filter_data_gnss_antenna_offset_correction_to_json(
    mipc_jw_t *w, const mipc_filter_data_gnss_antenna_offset_correction_t *in) {
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
    mipc_jw_key(w, &first, "valid_flags");
    mipc_jw_u16(w, &in->valid_flags);
    mipc_jw_raw(w, "}", 1);
}

int mipc_filter_data_gnss_antenna_offset_correction_from_json(
    mipc_jr_t *jr, size_t pos, mipc_filter_data_gnss_antenna_offset_correction_t *out) {
    static const char *const keys[] = {"offset", "valid_flags"};
    size_t vp = 0;
    int found;
    size_t i;
    size_t it = 0;
    size_t ep = 0;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 2)) {
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

/* ---- mipc_filter_data_gnss_antenna_offset_correction_uncertainty_t */

void mipc_filter_data_gnss_antenna_offset_correction_uncertainty_to_json(
    mipc_jw_t *w, const mipc_filter_data_gnss_antenna_offset_correction_uncertainty_t *in) {
    int first = 1;
    size_t i;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "offset_uncertainty");
    mipc_jw_raw(w, "[", 1);
    for (i = 0; i < 3; i++) {
        mipc_jw_sep(w, i);
        mipc_jw_f32(w, &in->offset_uncertainty[i]);
    }
    mipc_jw_raw(w, "]", 1);
    mipc_jw_key(w, &first, "valid_flags");
    mipc_jw_u16(w, &in->valid_flags);
    mipc_jw_raw(w, "}", 1);
}

int mipc_filter_data_gnss_antenna_offset_correction_uncertainty_from_json(
    mipc_jr_t *jr, size_t pos, mipc_filter_data_gnss_antenna_offset_correction_uncertainty_t *out) {
    static const char *const keys[] = {"offset_uncertainty", "valid_flags"};
    size_t vp = 0;
    int found;
    size_t i;
    size_t it = 0;
    size_t ep = 0;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 2)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "offset_uncertainty", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"offset_uncertainty\"");
    }
    {
        mipc_jr_push(jr, "offset_uncertainty");
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
            if (mipc_jr_f32(jr, ep, &out->offset_uncertainty[i])) {
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

/* ---- mipc_filter_data_multi_antenna_offset_correction_t */

void mipc_filter_data_multi_antenna_offset_correction_to_json(
    mipc_jw_t *w, const mipc_filter_data_multi_antenna_offset_correction_t *in) {
    int first = 1;
    size_t i;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "receiver_id");
    mipc_jw_u8(w, &in->receiver_id);
    mipc_jw_key(w, &first, "offset");
    mipc_jw_raw(w, "[", 1);
    for (i = 0; i < 3; i++) {
        mipc_jw_sep(w, i);
        mipc_jw_f32(w, &in->offset[i]);
    }
    mipc_jw_raw(w, "]", 1);
    mipc_jw_key(w, &first, "valid_flags");
    mipc_jw_u16(w, &in->valid_flags);
    mipc_jw_raw(w, "}", 1);
}

int mipc_filter_data_multi_antenna_offset_correction_from_json(
    mipc_jr_t *jr, size_t pos, mipc_filter_data_multi_antenna_offset_correction_t *out) {
    static const char *const keys[] = {"receiver_id", "offset", "valid_flags"};
    size_t vp = 0;
    int found;
    size_t i;
    size_t it = 0;
    size_t ep = 0;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 3)) {
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

/* ---- mipc_filter_data_multi_antenna_offset_correction_uncertainty_t */

void mipc_filter_data_multi_antenna_offset_correction_uncertainty_to_json(
    mipc_jw_t *w, const mipc_filter_data_multi_antenna_offset_correction_uncertainty_t *in) {
    int first = 1;
    size_t i;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "receiver_id");
    mipc_jw_u8(w, &in->receiver_id);
    mipc_jw_key(w, &first, "offset_uncertainty");
    mipc_jw_raw(w, "[", 1);
    for (i = 0; i < 3; i++) {
        mipc_jw_sep(w, i);
        mipc_jw_f32(w, &in->offset_uncertainty[i]);
    }
    mipc_jw_raw(w, "]", 1);
    mipc_jw_key(w, &first, "valid_flags");
    mipc_jw_u16(w, &in->valid_flags);
    mipc_jw_raw(w, "}", 1);
}

int mipc_filter_data_multi_antenna_offset_correction_uncertainty_from_json(
    mipc_jr_t *jr, size_t pos, mipc_filter_data_multi_antenna_offset_correction_uncertainty_t *out) {
    static const char *const keys[] = {"receiver_id", "offset_uncertainty", "valid_flags"};
    size_t vp = 0;
    int found;
    size_t i;
    size_t it = 0;
    size_t ep = 0;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 3)) {
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
    found = mipc_jr_get(jr, pos, "offset_uncertainty", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"offset_uncertainty\"");
    }
    {
        mipc_jr_push(jr, "offset_uncertainty");
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
            if (mipc_jr_f32(jr, ep, &out->offset_uncertainty[i])) {
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

/* ---- mipc_filter_data_ecef_position_uncertainty_t */

void mipc_filter_data_ecef_position_uncertainty_to_json(
    mipc_jw_t *w, const mipc_filter_data_ecef_position_uncertainty_t *in) {
    int first = 1;
    size_t i;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "position_uncertainty");
    mipc_jw_raw(w, "[", 1);
    for (i = 0; i < 3; i++) {
        mipc_jw_sep(w, i);
        mipc_jw_f32(w, &in->position_uncertainty[i]);
    }
    mipc_jw_raw(w, "]", 1);
    mipc_jw_key(w, &first, "valid_flags");
    mipc_jw_u16(w, &in->valid_flags);
    mipc_jw_raw(w, "}", 1);
}

int mipc_filter_data_ecef_position_uncertainty_from_json(mipc_jr_t *jr, size_t pos,
                                                         mipc_filter_data_ecef_position_uncertainty_t *out) {
    static const char *const keys[] = {"position_uncertainty", "valid_flags"};
    size_t vp = 0;
    int found;
    size_t i;
    size_t it = 0;
    size_t ep = 0;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 2)) {
        return -1;
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

/* ---- mipc_filter_data_ecef_velocity_uncertainty_t */

void mipc_filter_data_ecef_velocity_uncertainty_to_json(
    mipc_jw_t *w, const mipc_filter_data_ecef_velocity_uncertainty_t *in) {
    int first = 1;
    size_t i;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "velocity_uncertainty");
    mipc_jw_raw(w, "[", 1);
    for (i = 0; i < 3; i++) {
        mipc_jw_sep(w, i);
        mipc_jw_f32(w, &in->velocity_uncertainty[i]);
    }
    mipc_jw_raw(w, "]", 1);
    mipc_jw_key(w, &first, "valid_flags");
    mipc_jw_u16(w, &in->valid_flags);
    mipc_jw_raw(w, "}", 1);
}

int mipc_filter_data_ecef_velocity_uncertainty_from_json(mipc_jr_t *jr, size_t pos,
                                                         mipc_filter_data_ecef_velocity_uncertainty_t *out) {
    static const char *const keys[] = {"velocity_uncertainty", "valid_flags"};
    size_t vp = 0;
    int found;
    size_t i;
    size_t it = 0;
    size_t ep = 0;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 2)) {
        return -1;
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

/* ---- mipc_filter_data_ecef_position_t */

void mipc_filter_data_ecef_position_to_json(mipc_jw_t *w, const mipc_filter_data_ecef_position_t *in) {
    int first = 1;
    size_t i;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "position");
    mipc_jw_raw(w, "[", 1);
    for (i = 0; i < 3; i++) {
        mipc_jw_sep(w, i);
        mipc_jw_f64(w, &in->position[i]);
    }
    mipc_jw_raw(w, "]", 1);
    mipc_jw_key(w, &first, "valid_flags");
    mipc_jw_u16(w, &in->valid_flags);
    mipc_jw_raw(w, "}", 1);
}

int mipc_filter_data_ecef_position_from_json(mipc_jr_t *jr, size_t pos,
                                             mipc_filter_data_ecef_position_t *out) {
    static const char *const keys[] = {"position", "valid_flags"};
    size_t vp = 0;
    int found;
    size_t i;
    size_t it = 0;
    size_t ep = 0;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 2)) {
        return -1;
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

/* ---- mipc_filter_data_ecef_velocity_t */

void mipc_filter_data_ecef_velocity_to_json(mipc_jw_t *w, const mipc_filter_data_ecef_velocity_t *in) {
    int first = 1;
    size_t i;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "velocity");
    mipc_jw_raw(w, "[", 1);
    for (i = 0; i < 3; i++) {
        mipc_jw_sep(w, i);
        mipc_jw_f32(w, &in->velocity[i]);
    }
    mipc_jw_raw(w, "]", 1);
    mipc_jw_key(w, &first, "valid_flags");
    mipc_jw_u16(w, &in->valid_flags);
    mipc_jw_raw(w, "}", 1);
}

int mipc_filter_data_ecef_velocity_from_json(mipc_jr_t *jr, size_t pos,
                                             mipc_filter_data_ecef_velocity_t *out) {
    static const char *const keys[] = {"velocity", "valid_flags"};
    size_t vp = 0;
    int found;
    size_t i;
    size_t it = 0;
    size_t ep = 0;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 2)) {
        return -1;
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

/* ---- mipc_filter_data_ned_relative_position_t */

void mipc_filter_data_ned_relative_position_to_json(mipc_jw_t *w,
                                                    const mipc_filter_data_ned_relative_position_t *in) {
    int first = 1;
    size_t i;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "relative_position");
    mipc_jw_raw(w, "[", 1);
    for (i = 0; i < 3; i++) {
        mipc_jw_sep(w, i);
        mipc_jw_f64(w, &in->relative_position[i]);
    }
    mipc_jw_raw(w, "]", 1);
    mipc_jw_key(w, &first, "valid_flags");
    mipc_jw_u16(w, &in->valid_flags);
    mipc_jw_raw(w, "}", 1);
}

int mipc_filter_data_ned_relative_position_from_json(mipc_jr_t *jr, size_t pos,
                                                     mipc_filter_data_ned_relative_position_t *out) {
    static const char *const keys[] = {"relative_position", "valid_flags"};
    size_t vp = 0;
    int found;
    size_t i;
    size_t it = 0;
    size_t ep = 0;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 2)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "relative_position", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"relative_position\"");
    }
    {
        mipc_jr_push(jr, "relative_position");
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
            if (mipc_jr_f64(jr, ep, &out->relative_position[i])) {
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

/* ---- mipc_filter_data_gnss_position_aiding_status_t */

void mipc_filter_data_gnss_position_aiding_status_to_json(
    mipc_jw_t *w, const mipc_filter_data_gnss_position_aiding_status_t *in) {
    int first = 1;
    size_t i;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "receiver_id");
    mipc_jw_u8(w, &in->receiver_id);
    mipc_jw_key(w, &first, "time_of_week");
    mipc_jw_f32(w, &in->time_of_week);
    mipc_jw_key(w, &first, "status");
    mipc_jw_u16(w, &in->status);
    mipc_jw_key(w, &first, "reserved");
    mipc_jw_raw(w, "[", 1);
    for (i = 0; i < 8; i++) {
        mipc_jw_sep(w, i);
        mipc_jw_u8(w, &in->reserved[i]);
    }
    mipc_jw_raw(w, "]", 1);
    mipc_jw_raw(w, "}", 1);
}

int mipc_filter_data_gnss_position_aiding_status_from_json(
    mipc_jr_t *jr, size_t pos, mipc_filter_data_gnss_position_aiding_status_t *out) {
    static const char *const keys[] = {"receiver_id", "time_of_week", "status", "reserved"};
    size_t vp = 0;
    int found;
    size_t i;
    size_t it = 0;
    size_t ep = 0;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 4)) {
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
    found = mipc_jr_get(jr, pos, "time_of_week", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"time_of_week\"");
    }
    {
        mipc_jr_push(jr, "time_of_week");
        if (mipc_jr_f32(jr, vp, &out->time_of_week)) {
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
        if (mipc_jr_u16(jr, vp, &out->status)) {
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
            if (i >= 8) {
                return mipc_jr_fail(jr, "more than 8 elements");
            }
            mipc_jr_index(jr, i);
            if (mipc_jr_u8(jr, ep, &out->reserved[i])) {
                return -1;
            }
        }
        mipc_jr_index(jr, SIZE_MAX);
        if (i != 8) {
            return mipc_jr_fail(jr, "expected 8 elements, got %zu", i);
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mipc_filter_data_aiding_measurement_summary_t */

void mipc_filter_data_aiding_measurement_summary_to_json(
    mipc_jw_t *w, const mipc_filter_data_aiding_measurement_summary_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "time_of_week");
    mipc_jw_f32(w, &in->time_of_week);
    mipc_jw_key(w, &first, "source");
    mipc_jw_u8(w, &in->source);
    mipc_jw_key(w, &first, "type");
    mipc_jw_u8(w, &in->type);
    mipc_jw_key(w, &first, "indicator");
    mipc_jw_u8(w, &in->indicator);
    mipc_jw_raw(w, "}", 1);
}

int mipc_filter_data_aiding_measurement_summary_from_json(
    mipc_jr_t *jr, size_t pos, mipc_filter_data_aiding_measurement_summary_t *out) {
    static const char *const keys[] = {"time_of_week", "source", "type", "indicator"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 4)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "time_of_week", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"time_of_week\"");
    }
    {
        mipc_jr_push(jr, "time_of_week");
        if (mipc_jr_f32(jr, vp, &out->time_of_week)) {
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
    found = mipc_jr_get(jr, pos, "indicator", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"indicator\"");
    }
    {
        mipc_jr_push(jr, "indicator");
        if (mipc_jr_u8(jr, vp, &out->indicator)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mipc_filter_data_odometer_scale_factor_error_t */

void mipc_filter_data_odometer_scale_factor_error_to_json(
    mipc_jw_t *w, const mipc_filter_data_odometer_scale_factor_error_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "scale_factor_error");
    mipc_jw_f32(w, &in->scale_factor_error);
    mipc_jw_key(w, &first, "valid_flags");
    mipc_jw_u16(w, &in->valid_flags);
    mipc_jw_raw(w, "}", 1);
}

int mipc_filter_data_odometer_scale_factor_error_from_json(
    mipc_jr_t *jr, size_t pos, mipc_filter_data_odometer_scale_factor_error_t *out) {
    static const char *const keys[] = {"scale_factor_error", "valid_flags"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 2)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "scale_factor_error", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"scale_factor_error\"");
    }
    {
        mipc_jr_push(jr, "scale_factor_error");
        if (mipc_jr_f32(jr, vp, &out->scale_factor_error)) {
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

/* ---- mipc_filter_data_odometer_scale_factor_error_uncertainty_t */

void mipc_filter_data_odometer_scale_factor_error_uncertainty_to_json(
    mipc_jw_t *w, const mipc_filter_data_odometer_scale_factor_error_uncertainty_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "scale_factor_error_uncertainty");
    mipc_jw_f32(w, &in->scale_factor_error_uncertainty);
    mipc_jw_key(w, &first, "valid_flags");
    mipc_jw_u16(w, &in->valid_flags);
    mipc_jw_raw(w, "}", 1);
}

int mipc_filter_data_odometer_scale_factor_error_uncertainty_from_json(
    mipc_jr_t *jr, size_t pos, mipc_filter_data_odometer_scale_factor_error_uncertainty_t *out) {
    static const char *const keys[] = {"scale_factor_error_uncertainty", "valid_flags"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 2)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "scale_factor_error_uncertainty", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"scale_factor_error_uncertainty\"");
    }
    {
        mipc_jr_push(jr, "scale_factor_error_uncertainty");
        if (mipc_jr_f32(jr, vp, &out->scale_factor_error_uncertainty)) {
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

/* ---- mipc_filter_data_gnss_dual_antenna_status_t */

void mipc_filter_data_gnss_dual_antenna_status_to_json(
    mipc_jw_t *w, const mipc_filter_data_gnss_dual_antenna_status_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "time_of_week");
    mipc_jw_f32(w, &in->time_of_week);
    mipc_jw_key(w, &first, "heading");
    mipc_jw_f32(w, &in->heading);
    mipc_jw_key(w, &first, "heading_uncertainty");
    mipc_jw_f32(w, &in->heading_uncertainty);
    mipc_jw_key(w, &first, "fix_type");
    mipc_jw_u8(w, &in->fix_type);
    mipc_jw_key(w, &first, "status_flags");
    mipc_jw_u16(w, &in->status_flags);
    mipc_jw_key(w, &first, "valid_flags");
    mipc_jw_u16(w, &in->valid_flags);
    mipc_jw_raw(w, "}", 1);
}

int mipc_filter_data_gnss_dual_antenna_status_from_json(mipc_jr_t *jr, size_t pos,
                                                        mipc_filter_data_gnss_dual_antenna_status_t *out) {
    static const char *const keys[] = {"time_of_week", "heading",      "heading_uncertainty",
                                       "fix_type",     "status_flags", "valid_flags"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 6)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "time_of_week", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"time_of_week\"");
    }
    {
        mipc_jr_push(jr, "time_of_week");
        if (mipc_jr_f32(jr, vp, &out->time_of_week)) {
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
    found = mipc_jr_get(jr, pos, "fix_type", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"fix_type\"");
    }
    {
        mipc_jr_push(jr, "fix_type");
        if (mipc_jr_u8(jr, vp, &out->fix_type)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "status_flags", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"status_flags\"");
    }
    {
        mipc_jr_push(jr, "status_flags");
        if (mipc_jr_u16(jr, vp, &out->status_flags)) {
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

/* ---- mipc_filter_data_aiding_frame_config_error_t */

void mipc_filter_data_aiding_frame_config_error_to_json(
    mipc_jw_t *w, const mipc_filter_data_aiding_frame_config_error_t *in) {
    int first = 1;
    size_t i;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "frame_id");
    mipc_jw_u8(w, &in->frame_id);
    mipc_jw_key(w, &first, "translation");
    mipc_jw_raw(w, "[", 1);
    for (i = 0; i < 3; i++) {
        mipc_jw_sep(w, i);
        mipc_jw_f32(w, &in->translation[i]);
    }
    mipc_jw_raw(w, "]", 1);
    mipc_jw_key(w, &first, "attitude");
    mipc_jw_raw(w, "[", 1);
    for (i = 0; i < 4; i++) {
        mipc_jw_sep(w, i);
        mipc_jw_f32(w, &in->attitude[i]);
    }
    mipc_jw_raw(w, "]", 1);
    mipc_jw_raw(w, "}", 1);
}

int mipc_filter_data_aiding_frame_config_error_from_json(mipc_jr_t *jr, size_t pos,
                                                         mipc_filter_data_aiding_frame_config_error_t *out) {
    static const char *const keys[] = {"frame_id", "translation", "attitude"};
    size_t vp = 0;
    int found;
    size_t i;
    size_t it = 0;
    size_t ep = 0;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 3)) {
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
    found = mipc_jr_get(jr, pos, "attitude", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"attitude\"");
    }
    {
        mipc_jr_push(jr, "attitude");
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
            if (mipc_jr_f32(jr, ep, &out->attitude[i])) {
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

/* ---- mipc_filter_data_aiding_frame_config_error_uncertainty_t */

void mipc_filter_data_aiding_frame_config_error_uncertainty_to_json(
    mipc_jw_t *w, const mipc_filter_data_aiding_frame_config_error_uncertainty_t *in) {
    int first = 1;
    size_t i;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "frame_id");
    mipc_jw_u8(w, &in->frame_id);
    mipc_jw_key(w, &first, "translation_uncertainty");
    mipc_jw_raw(w, "[", 1);
    for (i = 0; i < 3; i++) {
        mipc_jw_sep(w, i);
        mipc_jw_f32(w, &in->translation_uncertainty[i]);
    }
    mipc_jw_raw(w, "]", 1);
    mipc_jw_key(w, &first, "attitude_uncertainty");
    mipc_jw_raw(w, "[", 1);
    for (i = 0; i < 3; i++) {
        mipc_jw_sep(w, i);
        mipc_jw_f32(w, &in->attitude_uncertainty[i]);
    }
    mipc_jw_raw(w, "]", 1);
    mipc_jw_raw(w, "}", 1);
}

int mipc_filter_data_aiding_frame_config_error_uncertainty_from_json(
    mipc_jr_t *jr, size_t pos, mipc_filter_data_aiding_frame_config_error_uncertainty_t *out) {
    static const char *const keys[] = {"frame_id", "translation_uncertainty", "attitude_uncertainty"};
    size_t vp = 0;
    int found;
    size_t i;
    size_t it = 0;
    size_t ep = 0;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 3)) {
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
    found = mipc_jr_get(jr, pos, "translation_uncertainty", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"translation_uncertainty\"");
    }
    {
        mipc_jr_push(jr, "translation_uncertainty");
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
            if (mipc_jr_f32(jr, ep, &out->translation_uncertainty[i])) {
                return -1;
            }
        }
        mipc_jr_index(jr, SIZE_MAX);
        if (i != 3) {
            return mipc_jr_fail(jr, "expected 3 elements, got %zu", i);
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "attitude_uncertainty", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"attitude_uncertainty\"");
    }
    {
        mipc_jr_push(jr, "attitude_uncertainty");
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
            if (mipc_jr_f32(jr, ep, &out->attitude_uncertainty[i])) {
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
