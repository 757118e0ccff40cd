/* Canonical JSON of IMU Data Message (the mscipcodec_json library). Generated from the spec: do not edit. */
#include "mscipcodec/sets/imu_data.h"
#include "layouts_internal.h"
#include "types_internal.h"

#include <assert.h>
#include <string.h>

/* ---- mscipc_imu_data_scaled_accel_t */

void mscipc_imu_data_scaled_accel_to_json(mscipc_jw_t *w, const mscipc_imu_data_scaled_accel_t *in) {
    int first = 1;
    size_t i;
    mscipc_jw_raw(w, "{", 1);
    mscipc_jw_key(w, &first, "accel");
    mscipc_jw_raw(w, "[", 1);
    for (i = 0; i < 3; i++) {
        mscipc_jw_sep(w, i);
        mscipc_jw_f32(w, &in->accel[i]);
    }
    mscipc_jw_raw(w, "]", 1);
    mscipc_jw_raw(w, "}", 1);
}

int mscipc_imu_data_scaled_accel_from_json(mscipc_jr_t *jr, size_t pos, mscipc_imu_data_scaled_accel_t *out) {
    static const char *const keys[] = {"accel"};
    size_t vp = 0;
    int found;
    size_t i;
    size_t it = 0;
    size_t ep = 0;
    memset(out, 0, sizeof *out);
    if (mscipc_jr_object(jr, pos, keys, 1)) {
        return -1;
    }
    found = mscipc_jr_get(jr, pos, "accel", &vp);
    if (found != 1) {
        return mscipc_jr_fail(jr, "missing parameter \"accel\"");
    }
    {
        mscipc_jr_push(jr, "accel");
        if (mscipc_jr_array(jr, vp, &it)) {
            return -1;
        }
        for (i = 0;; i++) {
            int more = mscipc_jr_next(jr, &it, &ep);
            if (more < 0) {
                return -1;
            }
            if (!more) {
                break;
            }
            if (i >= 3) {
                return mscipc_jr_fail(jr, "more than 3 elements");
            }
            mscipc_jr_index(jr, i);
            if (mscipc_jr_f32(jr, ep, &out->accel[i])) {
                return -1;
            }
        }
        mscipc_jr_index(jr, SIZE_MAX);
        if (i != 3) {
            return mscipc_jr_fail(jr, "expected 3 elements, got %zu", i);
        }
        mscipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mscipc_imu_data_scaled_gyro_t */

void mscipc_imu_data_scaled_gyro_to_json(mscipc_jw_t *w, const mscipc_imu_data_scaled_gyro_t *in) {
    int first = 1;
    size_t i;
    mscipc_jw_raw(w, "{", 1);
    mscipc_jw_key(w, &first, "gyro");
    mscipc_jw_raw(w, "[", 1);
    for (i = 0; i < 3; i++) {
        mscipc_jw_sep(w, i);
        mscipc_jw_f32(w, &in->gyro[i]);
    }
    mscipc_jw_raw(w, "]", 1);
    mscipc_jw_raw(w, "}", 1);
}

int mscipc_imu_data_scaled_gyro_from_json(mscipc_jr_t *jr, size_t pos, mscipc_imu_data_scaled_gyro_t *out) {
    static const char *const keys[] = {"gyro"};
    size_t vp = 0;
    int found;
    size_t i;
    size_t it = 0;
    size_t ep = 0;
    memset(out, 0, sizeof *out);
    if (mscipc_jr_object(jr, pos, keys, 1)) {
        return -1;
    }
    found = mscipc_jr_get(jr, pos, "gyro", &vp);
    if (found != 1) {
        return mscipc_jr_fail(jr, "missing parameter \"gyro\"");
    }
    {
        mscipc_jr_push(jr, "gyro");
        if (mscipc_jr_array(jr, vp, &it)) {
            return -1;
        }
        for (i = 0;; i++) {
            int more = mscipc_jr_next(jr, &it, &ep);
            if (more < 0) {
                return -1;
            }
            if (!more) {
                break;
            }
            if (i >= 3) {
                return mscipc_jr_fail(jr, "more than 3 elements");
            }
            mscipc_jr_index(jr, i);
            if (mscipc_jr_f32(jr, ep, &out->gyro[i])) {
                return -1;
            }
        }
        mscipc_jr_index(jr, SIZE_MAX);
        if (i != 3) {
            return mscipc_jr_fail(jr, "expected 3 elements, got %zu", i);
        }
        mscipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mscipc_imu_data_scaled_mag_t */

void mscipc_imu_data_scaled_mag_to_json(mscipc_jw_t *w, const mscipc_imu_data_scaled_mag_t *in) {
    int first = 1;
    size_t i;
    mscipc_jw_raw(w, "{", 1);
    mscipc_jw_key(w, &first, "mag");
    mscipc_jw_raw(w, "[", 1);
    for (i = 0; i < 3; i++) {
        mscipc_jw_sep(w, i);
        mscipc_jw_f32(w, &in->mag[i]);
    }
    mscipc_jw_raw(w, "]", 1);
    mscipc_jw_raw(w, "}", 1);
}

int mscipc_imu_data_scaled_mag_from_json(mscipc_jr_t *jr, size_t pos, mscipc_imu_data_scaled_mag_t *out) {
    static const char *const keys[] = {"mag"};
    size_t vp = 0;
    int found;
    size_t i;
    size_t it = 0;
    size_t ep = 0;
    memset(out, 0, sizeof *out);
    if (mscipc_jr_object(jr, pos, keys, 1)) {
        return -1;
    }
    found = mscipc_jr_get(jr, pos, "mag", &vp);
    if (found != 1) {
        return mscipc_jr_fail(jr, "missing parameter \"mag\"");
    }
    {
        mscipc_jr_push(jr, "mag");
        if (mscipc_jr_array(jr, vp, &it)) {
            return -1;
        }
        for (i = 0;; i++) {
            int more = mscipc_jr_next(jr, &it, &ep);
            if (more < 0) {
                return -1;
            }
            if (!more) {
                break;
            }
            if (i >= 3) {
                return mscipc_jr_fail(jr, "more than 3 elements");
            }
            mscipc_jr_index(jr, i);
            if (mscipc_jr_f32(jr, ep, &out->mag[i])) {
                return -1;
            }
        }
        mscipc_jr_index(jr, SIZE_MAX);
        if (i != 3) {
            return mscipc_jr_fail(jr, "expected 3 elements, got %zu", i);
        }
        mscipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mscipc_imu_data_delta_theta_t */

void mscipc_imu_data_delta_theta_to_json(mscipc_jw_t *w, const mscipc_imu_data_delta_theta_t *in) {
    int first = 1;
    size_t i;
    mscipc_jw_raw(w, "{", 1);
    mscipc_jw_key(w, &first, "delta_theta");
    mscipc_jw_raw(w, "[", 1);
    for (i = 0; i < 3; i++) {
        mscipc_jw_sep(w, i);
        mscipc_jw_f32(w, &in->delta_theta[i]);
    }
    mscipc_jw_raw(w, "]", 1);
    mscipc_jw_raw(w, "}", 1);
}

int mscipc_imu_data_delta_theta_from_json(mscipc_jr_t *jr, size_t pos, mscipc_imu_data_delta_theta_t *out) {
    static const char *const keys[] = {"delta_theta"};
    size_t vp = 0;
    int found;
    size_t i;
    size_t it = 0;
    size_t ep = 0;
    memset(out, 0, sizeof *out);
    if (mscipc_jr_object(jr, pos, keys, 1)) {
        return -1;
    }
    found = mscipc_jr_get(jr, pos, "delta_theta", &vp);
    if (found != 1) {
        return mscipc_jr_fail(jr, "missing parameter \"delta_theta\"");
    }
    {
        mscipc_jr_push(jr, "delta_theta");
        if (mscipc_jr_array(jr, vp, &it)) {
            return -1;
        }
        for (i = 0;; i++) {
            int more = mscipc_jr_next(jr, &it, &ep);
            if (more < 0) {
                return -1;
            }
            if (!more) {
                break;
            }
            if (i >= 3) {
                return mscipc_jr_fail(jr, "more than 3 elements");
            }
            mscipc_jr_index(jr, i);
            if (mscipc_jr_f32(jr, ep, &out->delta_theta[i])) {
                return -1;
            }
        }
        mscipc_jr_index(jr, SIZE_MAX);
        if (i != 3) {
            return mscipc_jr_fail(jr, "expected 3 elements, got %zu", i);
        }
        mscipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mscipc_imu_data_delta_velocity_t */

void mscipc_imu_data_delta_velocity_to_json(mscipc_jw_t *w, const mscipc_imu_data_delta_velocity_t *in) {
    int first = 1;
    size_t i;
    mscipc_jw_raw(w, "{", 1);
    mscipc_jw_key(w, &first, "delta_velocity");
    mscipc_jw_raw(w, "[", 1);
    for (i = 0; i < 3; i++) {
        mscipc_jw_sep(w, i);
        mscipc_jw_f32(w, &in->delta_velocity[i]);
    }
    mscipc_jw_raw(w, "]", 1);
    mscipc_jw_raw(w, "}", 1);
}

int mscipc_imu_data_delta_velocity_from_json(mscipc_jr_t *jr, size_t pos,
                                             mscipc_imu_data_delta_velocity_t *out) {
    static const char *const keys[] = {"delta_velocity"};
    size_t vp = 0;
    int found;
    size_t i;
    size_t it = 0;
    size_t ep = 0;
    memset(out, 0, sizeof *out);
    if (mscipc_jr_object(jr, pos, keys, 1)) {
        return -1;
    }
    found = mscipc_jr_get(jr, pos, "delta_velocity", &vp);
    if (found != 1) {
        return mscipc_jr_fail(jr, "missing parameter \"delta_velocity\"");
    }
    {
        mscipc_jr_push(jr, "delta_velocity");
        if (mscipc_jr_array(jr, vp, &it)) {
            return -1;
        }
        for (i = 0;; i++) {
            int more = mscipc_jr_next(jr, &it, &ep);
            if (more < 0) {
                return -1;
            }
            if (!more) {
                break;
            }
            if (i >= 3) {
                return mscipc_jr_fail(jr, "more than 3 elements");
            }
            mscipc_jr_index(jr, i);
            if (mscipc_jr_f32(jr, ep, &out->delta_velocity[i])) {
                return -1;
            }
        }
        mscipc_jr_index(jr, SIZE_MAX);
        if (i != 3) {
            return mscipc_jr_fail(jr, "expected 3 elements, got %zu", i);
        }
        mscipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mscipc_imu_data_scaled_pressure_t */

void mscipc_imu_data_scaled_pressure_to_json(mscipc_jw_t *w, const mscipc_imu_data_scaled_pressure_t *in) {
    int first = 1;
    mscipc_jw_raw(w, "{", 1);
    mscipc_jw_key(w, &first, "pressure");
    mscipc_jw_f32(w, &in->pressure);
    mscipc_jw_raw(w, "}", 1);
}

int mscipc_imu_data_scaled_pressure_from_json(mscipc_jr_t *jr, size_t pos,
                                              mscipc_imu_data_scaled_pressure_t *out) {
    static const char *const keys[] = {"pressure"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mscipc_jr_object(jr, pos, keys, 1)) {
        return -1;
    }
    found = mscipc_jr_get(jr, pos, "pressure", &vp);
    if (found != 1) {
        return mscipc_jr_fail(jr, "missing parameter \"pressure\"");
    }
    {
        mscipc_jr_push(jr, "pressure");
        if (mscipc_jr_f32(jr, vp, &out->pressure)) {
            return -1;
        }
        mscipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mscipc_imu_data_scaled_temperature_t */

void mscipc_imu_data_scaled_temperature_to_json(mscipc_jw_t *w,
                                                const mscipc_imu_data_scaled_temperature_t *in) {
    int first = 1;
    mscipc_jw_raw(w, "{", 1);
    mscipc_jw_key(w, &first, "temperature");
    mscipc_jw_f32(w, &in->temperature);
    mscipc_jw_raw(w, "}", 1);
}

int mscipc_imu_data_scaled_temperature_from_json(mscipc_jr_t *jr, size_t pos,
                                                 mscipc_imu_data_scaled_temperature_t *out) {
    static const char *const keys[] = {"temperature"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mscipc_jr_object(jr, pos, keys, 1)) {
        return -1;
    }
    found = mscipc_jr_get(jr, pos, "temperature", &vp);
    if (found != 1) {
        return mscipc_jr_fail(jr, "missing parameter \"temperature\"");
    }
    {
        mscipc_jr_push(jr, "temperature");
        if (mscipc_jr_f32(jr, vp, &out->temperature)) {
            return -1;
        }
        mscipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mscipc_imu_data_gps_correlated_time_t */

void mscipc_imu_data_gps_correlated_time_to_json(mscipc_jw_t *w,
                                                 const mscipc_imu_data_gps_correlated_time_t *in) {
    int first = 1;
    mscipc_jw_raw(w, "{", 1);
    mscipc_jw_key(w, &first, "seconds");
    mscipc_jw_f64(w, &in->seconds);
    mscipc_jw_key(w, &first, "week");
    mscipc_jw_u16(w, &in->week);
    mscipc_jw_key(w, &first, "flags");
    mscipc_jw_u16(w, &in->flags);
    mscipc_jw_raw(w, "}", 1);
}

int mscipc_imu_data_gps_correlated_time_from_json(mscipc_jr_t *jr, size_t pos,
                                                  mscipc_imu_data_gps_correlated_time_t *out) {
    static const char *const keys[] = {"seconds", "week", "flags"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mscipc_jr_object(jr, pos, keys, 3)) {
        return -1;
    }
    found = mscipc_jr_get(jr, pos, "seconds", &vp);
    if (found != 1) {
        return mscipc_jr_fail(jr, "missing parameter \"seconds\"");
    }
    {
        mscipc_jr_push(jr, "seconds");
        if (mscipc_jr_f64(jr, vp, &out->seconds)) {
            return -1;
        }
        mscipc_jr_pop(jr);
    }
    found = mscipc_jr_get(jr, pos, "week", &vp);
    if (found != 1) {
        return mscipc_jr_fail(jr, "missing parameter \"week\"");
    }
    {
        mscipc_jr_push(jr, "week");
        if (mscipc_jr_u16(jr, vp, &out->week)) {
            return -1;
        }
        mscipc_jr_pop(jr);
    }
    found = mscipc_jr_get(jr, pos, "flags", &vp);
    if (found != 1) {
        return mscipc_jr_fail(jr, "missing parameter \"flags\"");
    }
    {
        mscipc_jr_push(jr, "flags");
        if (mscipc_jr_u16(jr, vp, &out->flags)) {
            return -1;
        }
        mscipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mscipc_imu_data_scaled_aux_accel_t */

void mscipc_imu_data_scaled_aux_accel_to_json(mscipc_jw_t *w, const mscipc_imu_data_scaled_aux_accel_t *in) {
    int first = 1;
    size_t i;
    mscipc_jw_raw(w, "{", 1);
    mscipc_jw_key(w, &first, "accel");
    mscipc_jw_raw(w, "[", 1);
    for (i = 0; i < 3; i++) {
        mscipc_jw_sep(w, i);
        mscipc_jw_f32(w, &in->accel[i]);
    }
    mscipc_jw_raw(w, "]", 1);
    mscipc_jw_raw(w, "}", 1);
}

int mscipc_imu_data_scaled_aux_accel_from_json(mscipc_jr_t *jr, size_t pos,
                                               mscipc_imu_data_scaled_aux_accel_t *out) {
    static const char *const keys[] = {"accel"};
    size_t vp = 0;
    int found;
    size_t i;
    size_t it = 0;
    size_t ep = 0;
    memset(out, 0, sizeof *out);
    if (mscipc_jr_object(jr, pos, keys, 1)) {
        return -1;
    }
    found = mscipc_jr_get(jr, pos, "accel", &vp);
    if (found != 1) {
        return mscipc_jr_fail(jr, "missing parameter \"accel\"");
    }
    {
        mscipc_jr_push(jr, "accel");
        if (mscipc_jr_array(jr, vp, &it)) {
            return -1;
        }
        for (i = 0;; i++) {
            int more = mscipc_jr_next(jr, &it, &ep);
            if (more < 0) {
                return -1;
            }
            if (!more) {
                break;
            }
            if (i >= 3) {
                return mscipc_jr_fail(jr, "more than 3 elements");
            }
            mscipc_jr_index(jr, i);
            if (mscipc_jr_f32(jr, ep, &out->accel[i])) {
                return -1;
            }
        }
        mscipc_jr_index(jr, SIZE_MAX);
        if (i != 3) {
            return mscipc_jr_fail(jr, "expected 3 elements, got %zu", i);
        }
        mscipc_jr_pop(jr);
    }
    return 0;
}
