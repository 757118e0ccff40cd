/* Canonical JSON of Sensor (IMU) Data Set (the mipcodec_json library). Generated from the spec: do not edit.
 */
#include "mipcodec/sets/sensor.h"
#include "layouts_internal.h"
#include "types_internal.h"

#include <assert.h>
#include <string.h>

/* ---- mipc_sensor_scaled_accel_t */

void mipc_sensor_scaled_accel_to_json(mipc_jw_t *w, const mipc_sensor_scaled_accel_t *in) {
    int first = 1;
    size_t i;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "scaled_accel");
    mipc_jw_raw(w, "[", 1);
    for (i = 0; i < 3; i++) {
        mipc_jw_sep(w, i);
        mipc_jw_f32(w, &in->scaled_accel[i]);
    }
    mipc_jw_raw(w, "]", 1);
    mipc_jw_raw(w, "}", 1);
}

int mipc_sensor_scaled_accel_from_json(mipc_jr_t *jr, size_t pos, mipc_sensor_scaled_accel_t *out) {
    static const char *const keys[] = {"scaled_accel"};
    size_t vp = 0;
    int found;
    size_t i;
    size_t it = 0;
    size_t ep = 0;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 1)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "scaled_accel", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"scaled_accel\"");
    }
    {
        mipc_jr_push(jr, "scaled_accel");
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
            if (mipc_jr_f32(jr, ep, &out->scaled_accel[i])) {
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

/* ---- mipc_sensor_scaled_gyro_t */

void mipc_sensor_scaled_gyro_to_json(mipc_jw_t *w, const mipc_sensor_scaled_gyro_t *in) {
    int first = 1;
    size_t i;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "scaled_gyro");
    mipc_jw_raw(w, "[", 1);
    for (i = 0; i < 3; i++) {
        mipc_jw_sep(w, i);
        mipc_jw_f32(w, &in->scaled_gyro[i]);
    }
    mipc_jw_raw(w, "]", 1);
    mipc_jw_raw(w, "}", 1);
}

int mipc_sensor_scaled_gyro_from_json(mipc_jr_t *jr, size_t pos, mipc_sensor_scaled_gyro_t *out) {
    static const char *const keys[] = {"scaled_gyro"};
    size_t vp = 0;
    int found;
    size_t i;
    size_t it = 0;
    size_t ep = 0;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 1)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "scaled_gyro", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"scaled_gyro\"");
    }
    {
        mipc_jr_push(jr, "scaled_gyro");
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
            if (mipc_jr_f32(jr, ep, &out->scaled_gyro[i])) {
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

/* ---- mipc_sensor_scaled_mag_t */

void mipc_sensor_scaled_mag_to_json(mipc_jw_t *w, const mipc_sensor_scaled_mag_t *in) {
    int first = 1;
    size_t i;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "scaled_mag");
    mipc_jw_raw(w, "[", 1);
    for (i = 0; i < 3; i++) {
        mipc_jw_sep(w, i);
        mipc_jw_f32(w, &in->scaled_mag[i]);
    }
    mipc_jw_raw(w, "]", 1);
    mipc_jw_raw(w, "}", 1);
}

int mipc_sensor_scaled_mag_from_json(mipc_jr_t *jr, size_t pos, mipc_sensor_scaled_mag_t *out) {
    static const char *const keys[] = {"scaled_mag"};
    size_t vp = 0;
    int found;
    size_t i;
    size_t it = 0;
    size_t ep = 0;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 1)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "scaled_mag", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"scaled_mag\"");
    }
    {
        mipc_jr_push(jr, "scaled_mag");
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
            if (mipc_jr_f32(jr, ep, &out->scaled_mag[i])) {
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

/* ---- mipc_sensor_delta_theta_t */

void mipc_sensor_delta_theta_to_json(mipc_jw_t *w, const mipc_sensor_delta_theta_t *in) {
    int first = 1;
    size_t i;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "delta_theta");
    mipc_jw_raw(w, "[", 1);
    for (i = 0; i < 3; i++) {
        mipc_jw_sep(w, i);
        mipc_jw_f32(w, &in->delta_theta[i]);
    }
    mipc_jw_raw(w, "]", 1);
    mipc_jw_raw(w, "}", 1);
}

int mipc_sensor_delta_theta_from_json(mipc_jr_t *jr, size_t pos, mipc_sensor_delta_theta_t *out) {
    static const char *const keys[] = {"delta_theta"};
    size_t vp = 0;
    int found;
    size_t i;
    size_t it = 0;
    size_t ep = 0;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 1)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "delta_theta", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"delta_theta\"");
    }
    {
        mipc_jr_push(jr, "delta_theta");
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
            if (mipc_jr_f32(jr, ep, &out->delta_theta[i])) {
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

/* ---- mipc_sensor_delta_velocity_t */

void mipc_sensor_delta_velocity_to_json(mipc_jw_t *w, const mipc_sensor_delta_velocity_t *in) {
    int first = 1;
    size_t i;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "delta_velocity");
    mipc_jw_raw(w, "[", 1);
    for (i = 0; i < 3; i++) {
        mipc_jw_sep(w, i);
        mipc_jw_f32(w, &in->delta_velocity[i]);
    }
    mipc_jw_raw(w, "]", 1);
    mipc_jw_raw(w, "}", 1);
}

int mipc_sensor_delta_velocity_from_json(mipc_jr_t *jr, size_t pos, mipc_sensor_delta_velocity_t *out) {
    static const char *const keys[] = {"delta_velocity"};
    size_t vp = 0;
    int found;
    size_t i;
    size_t it = 0;
    size_t ep = 0;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 1)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "delta_velocity", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"delta_velocity\"");
    }
    {
        mipc_jr_push(jr, "delta_velocity");
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
            if (mipc_jr_f32(jr, ep, &out->delta_velocity[i])) {
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

/* ---- mipc_sensor_cf_orientation_matrix_t */

void mipc_sensor_cf_orientation_matrix_to_json(mipc_jw_t *w, const mipc_sensor_cf_orientation_matrix_t *in) {
    int first = 1;
    size_t i;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "m");
    mipc_jw_raw(w, "[", 1);
    for (i = 0; i < 9; i++) {
        mipc_jw_sep(w, i);
        mipc_jw_f32(w, &in->m[i]);
    }
    mipc_jw_raw(w, "]", 1);
    mipc_jw_raw(w, "}", 1);
}

int mipc_sensor_cf_orientation_matrix_from_json(mipc_jr_t *jr, size_t pos,
                                                mipc_sensor_cf_orientation_matrix_t *out) {
    static const char *const keys[] = {"m"};
    size_t vp = 0;
    int found;
    size_t i;
    size_t it = 0;
    size_t ep = 0;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 1)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "m", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"m\"");
    }
    {
        mipc_jr_push(jr, "m");
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
            if (mipc_jr_f32(jr, ep, &out->m[i])) {
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

/* ---- mipc_sensor_cf_quaternion_t */

void mipc_sensor_cf_quaternion_to_json(mipc_jw_t *w, const mipc_sensor_cf_quaternion_t *in) {
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

int mipc_sensor_cf_quaternion_from_json(mipc_jr_t *jr, size_t pos, mipc_sensor_cf_quaternion_t *out) {
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

/* ---- mipc_sensor_cf_euler_angles_t */

void mipc_sensor_cf_euler_angles_to_json(mipc_jw_t *w, const mipc_sensor_cf_euler_angles_t *in) {
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

int mipc_sensor_cf_euler_angles_from_json(mipc_jr_t *jr, size_t pos, mipc_sensor_cf_euler_angles_t *out) {
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

/* ---- mipc_sensor_cf_stabilized_north_t */

void mipc_sensor_cf_stabilized_north_to_json(mipc_jw_t *w, const mipc_sensor_cf_stabilized_north_t *in) {
    int first = 1;
    size_t i;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "stabilized_north");
    mipc_jw_raw(w, "[", 1);
    for (i = 0; i < 3; i++) {
        mipc_jw_sep(w, i);
        mipc_jw_f32(w, &in->stabilized_north[i]);
    }
    mipc_jw_raw(w, "]", 1);
    mipc_jw_raw(w, "}", 1);
}

int mipc_sensor_cf_stabilized_north_from_json(mipc_jr_t *jr, size_t pos,
                                              mipc_sensor_cf_stabilized_north_t *out) {
    static const char *const keys[] = {"stabilized_north"};
    size_t vp = 0;
    int found;
    size_t i;
    size_t it = 0;
    size_t ep = 0;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 1)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "stabilized_north", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"stabilized_north\"");
    }
    {
        mipc_jr_push(jr, "stabilized_north");
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
            if (mipc_jr_f32(jr, ep, &out->stabilized_north[i])) {
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

/* ---- mipc_sensor_cf_stabilized_up_t */

void mipc_sensor_cf_stabilized_up_to_json(mipc_jw_t *w, const mipc_sensor_cf_stabilized_up_t *in) {
    int first = 1;
    size_t i;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "stabilized_up");
    mipc_jw_raw(w, "[", 1);
    for (i = 0; i < 3; i++) {
        mipc_jw_sep(w, i);
        mipc_jw_f32(w, &in->stabilized_up[i]);
    }
    mipc_jw_raw(w, "]", 1);
    mipc_jw_raw(w, "}", 1);
}

int mipc_sensor_cf_stabilized_up_from_json(mipc_jr_t *jr, size_t pos, mipc_sensor_cf_stabilized_up_t *out) {
    static const char *const keys[] = {"stabilized_up"};
    size_t vp = 0;
    int found;
    size_t i;
    size_t it = 0;
    size_t ep = 0;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 1)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "stabilized_up", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"stabilized_up\"");
    }
    {
        mipc_jr_push(jr, "stabilized_up");
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
            if (mipc_jr_f32(jr, ep, &out->stabilized_up[i])) {
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

/* ---- mipc_sensor_gps_timestamp_t */

void mipc_sensor_gps_timestamp_to_json(mipc_jw_t *w, const mipc_sensor_gps_timestamp_t *in) {
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

int mipc_sensor_gps_timestamp_from_json(mipc_jr_t *jr, size_t pos, mipc_sensor_gps_timestamp_t *out) {
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

/* ---- mipc_sensor_temperature_statistics_t */

void mipc_sensor_temperature_statistics_to_json(mipc_jw_t *w,
                                                const mipc_sensor_temperature_statistics_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "min_temp");
    mipc_jw_f32(w, &in->min_temp);
    mipc_jw_key(w, &first, "max_temp");
    mipc_jw_f32(w, &in->max_temp);
    mipc_jw_key(w, &first, "mean_temp");
    mipc_jw_f32(w, &in->mean_temp);
    mipc_jw_raw(w, "}", 1);
}

int mipc_sensor_temperature_statistics_from_json(mipc_jr_t *jr, size_t pos,
                                                 mipc_sensor_temperature_statistics_t *out) {
    static const char *const keys[] = {"min_temp", "max_temp", "mean_temp"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 3)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "min_temp", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"min_temp\"");
    }
    {
        mipc_jr_push(jr, "min_temp");
        if (mipc_jr_f32(jr, vp, &out->min_temp)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "max_temp", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"max_temp\"");
    }
    {
        mipc_jr_push(jr, "max_temp");
        if (mipc_jr_f32(jr, vp, &out->max_temp)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "mean_temp", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"mean_temp\"");
    }
    {
        mipc_jr_push(jr, "mean_temp");
        if (mipc_jr_f32(jr, vp, &out->mean_temp)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mipc_sensor_scaled_pressure_t */

void mipc_sensor_scaled_pressure_to_json(mipc_jw_t *w, const mipc_sensor_scaled_pressure_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "scaled_pressure");
    mipc_jw_f32(w, &in->scaled_pressure);
    mipc_jw_raw(w, "}", 1);
}

int mipc_sensor_scaled_pressure_from_json(mipc_jr_t *jr, size_t pos, mipc_sensor_scaled_pressure_t *out) {
    static const char *const keys[] = {"scaled_pressure"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 1)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "scaled_pressure", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"scaled_pressure\"");
    }
    {
        mipc_jr_push(jr, "scaled_pressure");
        if (mipc_jr_f32(jr, vp, &out->scaled_pressure)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mipc_sensor_overrange_status_t */

void mipc_sensor_overrange_status_to_json(mipc_jw_t *w, const mipc_sensor_overrange_status_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "status");
    mipc_jw_u16(w, &in->status);
    mipc_jw_raw(w, "}", 1);
}

int mipc_sensor_overrange_status_from_json(mipc_jr_t *jr, size_t pos, mipc_sensor_overrange_status_t *out) {
    static const char *const keys[] = {"status"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 1)) {
        return -1;
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
    return 0;
}

/* ---- mipc_sensor_odometer_data_t */

void mipc_sensor_odometer_data_to_json(mipc_jw_t *w, const mipc_sensor_odometer_data_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "speed");
    mipc_jw_f32(w, &in->speed);
    mipc_jw_key(w, &first, "uncertainty");
    mipc_jw_f32(w, &in->uncertainty);
    mipc_jw_key(w, &first, "valid_flags");
    mipc_jw_u16(w, &in->valid_flags);
    mipc_jw_raw(w, "}", 1);
}

int mipc_sensor_odometer_data_from_json(mipc_jr_t *jr, size_t pos, mipc_sensor_odometer_data_t *out) {
    static const char *const keys[] = {"speed", "uncertainty", "valid_flags"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 3)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "speed", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"speed\"");
    }
    {
        mipc_jr_push(jr, "speed");
        if (mipc_jr_f32(jr, vp, &out->speed)) {
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
