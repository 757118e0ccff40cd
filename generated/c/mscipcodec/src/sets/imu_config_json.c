/* Canonical JSON of IMU Configuration Messages (the mscipcodec_json library). Generated from the spec: do not
 * edit. */
#include "mscipcodec/sets/imu_config.h"
#include "layouts_internal.h"
#include "types_internal.h"

#include <assert.h>
#include <string.h>

/* ---- mscipc_imu_config_uart_baud_rate_t */

void mscipc_imu_config_uart_baud_rate_to_json(mscipc_jw_t *w, const mscipc_imu_config_uart_baud_rate_t *in) {
    int first = 1;
    mscipc_jw_raw(w, "{", 1);
    mscipc_jw_key(w, &first, "function");
    mscipc_jw_u8(w, &in->function);
    if (in->has_baud_rate) {
        mscipc_jw_key(w, &first, "baud_rate");
        mscipc_jw_u32(w, &in->baud_rate);
    }
    mscipc_jw_raw(w, "}", 1);
}

int mscipc_imu_config_uart_baud_rate_from_json(mscipc_jr_t *jr, size_t pos,
                                               mscipc_imu_config_uart_baud_rate_t *out) {
    static const char *const keys[] = {"function", "baud_rate"};
    size_t vp = 0;
    int found;
    int absent = 0;
    memset(out, 0, sizeof *out);
    if (mscipc_jr_object(jr, pos, keys, 2)) {
        return -1;
    }
    found = mscipc_jr_get(jr, pos, "function", &vp);
    if (found != 1) {
        return mscipc_jr_fail(jr, "missing parameter \"function\"");
    }
    {
        mscipc_jr_push(jr, "function");
        if (mscipc_jr_u8(jr, vp, &out->function)) {
            return -1;
        }
        mscipc_jr_pop(jr);
    }
    found = mscipc_jr_get(jr, pos, "baud_rate", &vp);
    out->has_baud_rate = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mscipc_jr_fail(jr, "optional parameter \"baud_rate\" given after an absent one");
    } else {
        mscipc_jr_push(jr, "baud_rate");
        if (mscipc_jr_u32(jr, vp, &out->baud_rate)) {
            return -1;
        }
        mscipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mscipc_imu_config_uart_baud_rate_response_t */

void mscipc_imu_config_uart_baud_rate_response_to_json(
    mscipc_jw_t *w, const mscipc_imu_config_uart_baud_rate_response_t *in) {
    int first = 1;
    mscipc_jw_raw(w, "{", 1);
    mscipc_jw_key(w, &first, "baud_rate");
    mscipc_jw_u32(w, &in->baud_rate);
    mscipc_jw_raw(w, "}", 1);
}

int mscipc_imu_config_uart_baud_rate_response_from_json(mscipc_jr_t *jr, size_t pos,
                                                        mscipc_imu_config_uart_baud_rate_response_t *out) {
    static const char *const keys[] = {"baud_rate"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mscipc_jr_object(jr, pos, keys, 1)) {
        return -1;
    }
    found = mscipc_jr_get(jr, pos, "baud_rate", &vp);
    if (found != 1) {
        return mscipc_jr_fail(jr, "missing parameter \"baud_rate\"");
    }
    {
        mscipc_jr_push(jr, "baud_rate");
        if (mscipc_jr_u32(jr, vp, &out->baud_rate)) {
            return -1;
        }
        mscipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mscipc_imu_config_filter_t */

void mscipc_imu_config_filter_to_json(mscipc_jw_t *w, const mscipc_imu_config_filter_t *in) {
    int first = 1;
    mscipc_jw_raw(w, "{", 1);
    mscipc_jw_key(w, &first, "function");
    mscipc_jw_u8(w, &in->function);
    if (in->has_bandwidth) {
        mscipc_jw_key(w, &first, "bandwidth");
        mscipc_jw_u8(w, &in->bandwidth);
    }
    mscipc_jw_raw(w, "}", 1);
}

int mscipc_imu_config_filter_from_json(mscipc_jr_t *jr, size_t pos, mscipc_imu_config_filter_t *out) {
    static const char *const keys[] = {"function", "bandwidth"};
    size_t vp = 0;
    int found;
    int absent = 0;
    memset(out, 0, sizeof *out);
    if (mscipc_jr_object(jr, pos, keys, 2)) {
        return -1;
    }
    found = mscipc_jr_get(jr, pos, "function", &vp);
    if (found != 1) {
        return mscipc_jr_fail(jr, "missing parameter \"function\"");
    }
    {
        mscipc_jr_push(jr, "function");
        if (mscipc_jr_u8(jr, vp, &out->function)) {
            return -1;
        }
        mscipc_jr_pop(jr);
    }
    found = mscipc_jr_get(jr, pos, "bandwidth", &vp);
    out->has_bandwidth = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mscipc_jr_fail(jr, "optional parameter \"bandwidth\" given after an absent one");
    } else {
        mscipc_jr_push(jr, "bandwidth");
        if (mscipc_jr_u8(jr, vp, &out->bandwidth)) {
            return -1;
        }
        mscipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mscipc_imu_config_filter_response_t */

void mscipc_imu_config_filter_response_to_json(mscipc_jw_t *w,
                                               const mscipc_imu_config_filter_response_t *in) {
    int first = 1;
    mscipc_jw_raw(w, "{", 1);
    mscipc_jw_key(w, &first, "bandwidth");
    mscipc_jw_u8(w, &in->bandwidth);
    mscipc_jw_raw(w, "}", 1);
}

int mscipc_imu_config_filter_response_from_json(mscipc_jr_t *jr, size_t pos,
                                                mscipc_imu_config_filter_response_t *out) {
    static const char *const keys[] = {"bandwidth"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mscipc_jr_object(jr, pos, keys, 1)) {
        return -1;
    }
    found = mscipc_jr_get(jr, pos, "bandwidth", &vp);
    if (found != 1) {
        return mscipc_jr_fail(jr, "missing parameter \"bandwidth\"");
    }
    {
        mscipc_jr_push(jr, "bandwidth");
        if (mscipc_jr_u8(jr, vp, &out->bandwidth)) {
            return -1;
        }
        mscipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mscipc_imu_config_sample_rate_t */

void mscipc_imu_config_sample_rate_to_json(mscipc_jw_t *w, const mscipc_imu_config_sample_rate_t *in) {
    int first = 1;
    mscipc_jw_raw(w, "{", 1);
    mscipc_jw_key(w, &first, "function");
    mscipc_jw_u8(w, &in->function);
    if (in->has_decimation) {
        mscipc_jw_key(w, &first, "decimation");
        mscipc_jw_u16(w, &in->decimation);
    }
    mscipc_jw_raw(w, "}", 1);
}

int mscipc_imu_config_sample_rate_from_json(mscipc_jr_t *jr, size_t pos,
                                            mscipc_imu_config_sample_rate_t *out) {
    static const char *const keys[] = {"function", "decimation"};
    size_t vp = 0;
    int found;
    int absent = 0;
    memset(out, 0, sizeof *out);
    if (mscipc_jr_object(jr, pos, keys, 2)) {
        return -1;
    }
    found = mscipc_jr_get(jr, pos, "function", &vp);
    if (found != 1) {
        return mscipc_jr_fail(jr, "missing parameter \"function\"");
    }
    {
        mscipc_jr_push(jr, "function");
        if (mscipc_jr_u8(jr, vp, &out->function)) {
            return -1;
        }
        mscipc_jr_pop(jr);
    }
    found = mscipc_jr_get(jr, pos, "decimation", &vp);
    out->has_decimation = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mscipc_jr_fail(jr, "optional parameter \"decimation\" given after an absent one");
    } else {
        mscipc_jr_push(jr, "decimation");
        if (mscipc_jr_u16(jr, vp, &out->decimation)) {
            return -1;
        }
        mscipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mscipc_imu_config_sample_rate_response_t */

void mscipc_imu_config_sample_rate_response_to_json(mscipc_jw_t *w,
                                                    const mscipc_imu_config_sample_rate_response_t *in) {
    int first = 1;
    mscipc_jw_raw(w, "{", 1);
    mscipc_jw_key(w, &first, "decimation");
    mscipc_jw_u16(w, &in->decimation);
    mscipc_jw_raw(w, "}", 1);
}

int mscipc_imu_config_sample_rate_response_from_json(mscipc_jr_t *jr, size_t pos,
                                                     mscipc_imu_config_sample_rate_response_t *out) {
    static const char *const keys[] = {"decimation"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mscipc_jr_object(jr, pos, keys, 1)) {
        return -1;
    }
    found = mscipc_jr_get(jr, pos, "decimation", &vp);
    if (found != 1) {
        return mscipc_jr_fail(jr, "missing parameter \"decimation\"");
    }
    {
        mscipc_jr_push(jr, "decimation");
        if (mscipc_jr_u16(jr, vp, &out->decimation)) {
            return -1;
        }
        mscipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mscipc_imu_config_select_sensors_t */

void mscipc_imu_config_select_sensors_to_json(mscipc_jw_t *w, const mscipc_imu_config_select_sensors_t *in) {
    int first = 1;
    size_t i;
    mscipc_jw_raw(w, "{", 1);
    mscipc_jw_key(w, &first, "function");
    mscipc_jw_u8(w, &in->function);
    if (in->has_reserved) {
        mscipc_jw_key(w, &first, "reserved");
        mscipc_jw_u8(w, &in->reserved);
    }
    if (in->has_sensors) {
        mscipc_jw_key(w, &first, "sensors");
        mscipc_jw_raw(w, "[", 1);
        for (i = 0; i < (size_t)in->sensors_count && i < 251; i++) {
            mscipc_jw_sep(w, i);
            mscipc_jw_u8(w, &in->sensors[i]);
        }
        mscipc_jw_raw(w, "]", 1);
    }
    mscipc_jw_raw(w, "}", 1);
}

int mscipc_imu_config_select_sensors_from_json(mscipc_jr_t *jr, size_t pos,
                                               mscipc_imu_config_select_sensors_t *out) {
    static const char *const keys[] = {"function", "reserved", "sensors"};
    size_t vp = 0;
    int found;
    int absent = 0;
    size_t i;
    size_t it = 0;
    size_t ep = 0;
    memset(out, 0, sizeof *out);
    if (mscipc_jr_object(jr, pos, keys, 3)) {
        return -1;
    }
    found = mscipc_jr_get(jr, pos, "function", &vp);
    if (found != 1) {
        return mscipc_jr_fail(jr, "missing parameter \"function\"");
    }
    {
        mscipc_jr_push(jr, "function");
        if (mscipc_jr_u8(jr, vp, &out->function)) {
            return -1;
        }
        mscipc_jr_pop(jr);
    }
    found = mscipc_jr_get(jr, pos, "reserved", &vp);
    out->has_reserved = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mscipc_jr_fail(jr, "optional parameter \"reserved\" given after an absent one");
    } else {
        mscipc_jr_push(jr, "reserved");
        if (mscipc_jr_u8(jr, vp, &out->reserved)) {
            return -1;
        }
        mscipc_jr_pop(jr);
    }
    found = mscipc_jr_get(jr, pos, "sensors", &vp);
    out->has_sensors = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mscipc_jr_fail(jr, "optional parameter \"sensors\" given after an absent one");
    } else {
        mscipc_jr_push(jr, "sensors");
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
            if (i >= 251) {
                return mscipc_jr_fail(jr, "more than 251 elements");
            }
            mscipc_jr_index(jr, i);
            if (mscipc_jr_u8(jr, ep, &out->sensors[i])) {
                return -1;
            }
        }
        mscipc_jr_index(jr, SIZE_MAX);
        out->sensors_count = i;
        mscipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mscipc_imu_config_select_sensors_response_t */

void mscipc_imu_config_select_sensors_response_to_json(
    mscipc_jw_t *w, const mscipc_imu_config_select_sensors_response_t *in) {
    int first = 1;
    size_t i;
    mscipc_jw_raw(w, "{", 1);
    mscipc_jw_key(w, &first, "sensors");
    mscipc_jw_raw(w, "[", 1);
    for (i = 0; i < (size_t)in->sensors_count && i < 253; i++) {
        mscipc_jw_sep(w, i);
        mscipc_jw_u8(w, &in->sensors[i]);
    }
    mscipc_jw_raw(w, "]", 1);
    mscipc_jw_raw(w, "}", 1);
}

int mscipc_imu_config_select_sensors_response_from_json(mscipc_jr_t *jr, size_t pos,
                                                        mscipc_imu_config_select_sensors_response_t *out) {
    static const char *const keys[] = {"sensors"};
    size_t vp = 0;
    int found;
    size_t i;
    size_t it = 0;
    size_t ep = 0;
    memset(out, 0, sizeof *out);
    if (mscipc_jr_object(jr, pos, keys, 1)) {
        return -1;
    }
    found = mscipc_jr_get(jr, pos, "sensors", &vp);
    if (found != 1) {
        return mscipc_jr_fail(jr, "missing parameter \"sensors\"");
    }
    {
        mscipc_jr_push(jr, "sensors");
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
            if (i >= 253) {
                return mscipc_jr_fail(jr, "more than 253 elements");
            }
            mscipc_jr_index(jr, i);
            if (mscipc_jr_u8(jr, ep, &out->sensors[i])) {
                return -1;
            }
        }
        mscipc_jr_index(jr, SIZE_MAX);
        out->sensors_count = i;
        mscipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mscipc_imu_config_get_internal_sample_rate_t */

void mscipc_imu_config_get_internal_sample_rate_to_json(
    mscipc_jw_t *w, const mscipc_imu_config_get_internal_sample_rate_t *in) {
    int first = 1;
    mscipc_jw_raw(w, "{", 1);
    mscipc_jw_raw(w, "}", 1);
    (void)in;
    (void)first;
}

int mscipc_imu_config_get_internal_sample_rate_from_json(mscipc_jr_t *jr, size_t pos,
                                                         mscipc_imu_config_get_internal_sample_rate_t *out) {
    memset(out, 0, sizeof *out);
    if (mscipc_jr_object(jr, pos, NULL, 0)) {
        return -1;
    }
    return 0;
}

/* ---- mscipc_imu_config_internal_sample_rate_t */

void mscipc_imu_config_internal_sample_rate_to_json(mscipc_jw_t *w,
                                                    const mscipc_imu_config_internal_sample_rate_t *in) {
    int first = 1;
    mscipc_jw_raw(w, "{", 1);
    mscipc_jw_key(w, &first, "rate");
    mscipc_jw_u16(w, &in->rate);
    mscipc_jw_raw(w, "}", 1);
}

int mscipc_imu_config_internal_sample_rate_from_json(mscipc_jr_t *jr, size_t pos,
                                                     mscipc_imu_config_internal_sample_rate_t *out) {
    static const char *const keys[] = {"rate"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mscipc_jr_object(jr, pos, keys, 1)) {
        return -1;
    }
    found = mscipc_jr_get(jr, pos, "rate", &vp);
    if (found != 1) {
        return mscipc_jr_fail(jr, "missing parameter \"rate\"");
    }
    {
        mscipc_jr_push(jr, "rate");
        if (mscipc_jr_u16(jr, vp, &out->rate)) {
            return -1;
        }
        mscipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mscipc_imu_config_accel_range_t */

void mscipc_imu_config_accel_range_to_json(mscipc_jw_t *w, const mscipc_imu_config_accel_range_t *in) {
    int first = 1;
    mscipc_jw_raw(w, "{", 1);
    mscipc_jw_key(w, &first, "function");
    mscipc_jw_u8(w, &in->function);
    if (in->has_range) {
        mscipc_jw_key(w, &first, "range");
        mscipc_jw_u8(w, &in->range);
    }
    mscipc_jw_raw(w, "}", 1);
}

int mscipc_imu_config_accel_range_from_json(mscipc_jr_t *jr, size_t pos,
                                            mscipc_imu_config_accel_range_t *out) {
    static const char *const keys[] = {"function", "range"};
    size_t vp = 0;
    int found;
    int absent = 0;
    memset(out, 0, sizeof *out);
    if (mscipc_jr_object(jr, pos, keys, 2)) {
        return -1;
    }
    found = mscipc_jr_get(jr, pos, "function", &vp);
    if (found != 1) {
        return mscipc_jr_fail(jr, "missing parameter \"function\"");
    }
    {
        mscipc_jr_push(jr, "function");
        if (mscipc_jr_u8(jr, vp, &out->function)) {
            return -1;
        }
        mscipc_jr_pop(jr);
    }
    found = mscipc_jr_get(jr, pos, "range", &vp);
    out->has_range = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mscipc_jr_fail(jr, "optional parameter \"range\" given after an absent one");
    } else {
        mscipc_jr_push(jr, "range");
        if (mscipc_jr_u8(jr, vp, &out->range)) {
            return -1;
        }
        mscipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mscipc_imu_config_accel_range_response_t */

void mscipc_imu_config_accel_range_response_to_json(mscipc_jw_t *w,
                                                    const mscipc_imu_config_accel_range_response_t *in) {
    int first = 1;
    mscipc_jw_raw(w, "{", 1);
    mscipc_jw_key(w, &first, "range");
    mscipc_jw_u8(w, &in->range);
    mscipc_jw_raw(w, "}", 1);
}

int mscipc_imu_config_accel_range_response_from_json(mscipc_jr_t *jr, size_t pos,
                                                     mscipc_imu_config_accel_range_response_t *out) {
    static const char *const keys[] = {"range"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mscipc_jr_object(jr, pos, keys, 1)) {
        return -1;
    }
    found = mscipc_jr_get(jr, pos, "range", &vp);
    if (found != 1) {
        return mscipc_jr_fail(jr, "missing parameter \"range\"");
    }
    {
        mscipc_jr_push(jr, "range");
        if (mscipc_jr_u8(jr, vp, &out->range)) {
            return -1;
        }
        mscipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mscipc_imu_config_gyro_range_t */

void mscipc_imu_config_gyro_range_to_json(mscipc_jw_t *w, const mscipc_imu_config_gyro_range_t *in) {
    int first = 1;
    mscipc_jw_raw(w, "{", 1);
    mscipc_jw_key(w, &first, "function");
    mscipc_jw_u8(w, &in->function);
    if (in->has_range) {
        mscipc_jw_key(w, &first, "range");
        mscipc_jw_u8(w, &in->range);
    }
    mscipc_jw_raw(w, "}", 1);
}

int mscipc_imu_config_gyro_range_from_json(mscipc_jr_t *jr, size_t pos, mscipc_imu_config_gyro_range_t *out) {
    static const char *const keys[] = {"function", "range"};
    size_t vp = 0;
    int found;
    int absent = 0;
    memset(out, 0, sizeof *out);
    if (mscipc_jr_object(jr, pos, keys, 2)) {
        return -1;
    }
    found = mscipc_jr_get(jr, pos, "function", &vp);
    if (found != 1) {
        return mscipc_jr_fail(jr, "missing parameter \"function\"");
    }
    {
        mscipc_jr_push(jr, "function");
        if (mscipc_jr_u8(jr, vp, &out->function)) {
            return -1;
        }
        mscipc_jr_pop(jr);
    }
    found = mscipc_jr_get(jr, pos, "range", &vp);
    out->has_range = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mscipc_jr_fail(jr, "optional parameter \"range\" given after an absent one");
    } else {
        mscipc_jr_push(jr, "range");
        if (mscipc_jr_u8(jr, vp, &out->range)) {
            return -1;
        }
        mscipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mscipc_imu_config_gyro_range_response_t */

void mscipc_imu_config_gyro_range_response_to_json(mscipc_jw_t *w,
                                                   const mscipc_imu_config_gyro_range_response_t *in) {
    int first = 1;
    mscipc_jw_raw(w, "{", 1);
    mscipc_jw_key(w, &first, "range");
    mscipc_jw_u8(w, &in->range);
    mscipc_jw_raw(w, "}", 1);
}

int mscipc_imu_config_gyro_range_response_from_json(mscipc_jr_t *jr, size_t pos,
                                                    mscipc_imu_config_gyro_range_response_t *out) {
    static const char *const keys[] = {"range"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mscipc_jr_object(jr, pos, keys, 1)) {
        return -1;
    }
    found = mscipc_jr_get(jr, pos, "range", &vp);
    if (found != 1) {
        return mscipc_jr_fail(jr, "missing parameter \"range\"");
    }
    {
        mscipc_jr_push(jr, "range");
        if (mscipc_jr_u8(jr, vp, &out->range)) {
            return -1;
        }
        mscipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mscipc_imu_config_config_all_t */

void mscipc_imu_config_config_all_to_json(mscipc_jw_t *w, const mscipc_imu_config_config_all_t *in) {
    int first = 1;
    mscipc_jw_raw(w, "{", 1);
    mscipc_jw_key(w, &first, "function");
    mscipc_jw_u8(w, &in->function);
    mscipc_jw_raw(w, "}", 1);
}

int mscipc_imu_config_config_all_from_json(mscipc_jr_t *jr, size_t pos, mscipc_imu_config_config_all_t *out) {
    static const char *const keys[] = {"function"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mscipc_jr_object(jr, pos, keys, 1)) {
        return -1;
    }
    found = mscipc_jr_get(jr, pos, "function", &vp);
    if (found != 1) {
        return mscipc_jr_fail(jr, "missing parameter \"function\"");
    }
    {
        mscipc_jr_push(jr, "function");
        if (mscipc_jr_u8(jr, vp, &out->function)) {
            return -1;
        }
        mscipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mscipc_imu_config_data_on_off_t */

void mscipc_imu_config_data_on_off_to_json(mscipc_jw_t *w, const mscipc_imu_config_data_on_off_t *in) {
    int first = 1;
    mscipc_jw_raw(w, "{", 1);
    mscipc_jw_key(w, &first, "function");
    mscipc_jw_u8(w, &in->function);
    if (in->has_control) {
        mscipc_jw_key(w, &first, "control");
        mscipc_jw_u8(w, &in->control);
    }
    mscipc_jw_raw(w, "}", 1);
}

int mscipc_imu_config_data_on_off_from_json(mscipc_jr_t *jr, size_t pos,
                                            mscipc_imu_config_data_on_off_t *out) {
    static const char *const keys[] = {"function", "control"};
    size_t vp = 0;
    int found;
    int absent = 0;
    memset(out, 0, sizeof *out);
    if (mscipc_jr_object(jr, pos, keys, 2)) {
        return -1;
    }
    found = mscipc_jr_get(jr, pos, "function", &vp);
    if (found != 1) {
        return mscipc_jr_fail(jr, "missing parameter \"function\"");
    }
    {
        mscipc_jr_push(jr, "function");
        if (mscipc_jr_u8(jr, vp, &out->function)) {
            return -1;
        }
        mscipc_jr_pop(jr);
    }
    found = mscipc_jr_get(jr, pos, "control", &vp);
    out->has_control = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mscipc_jr_fail(jr, "optional parameter \"control\" given after an absent one");
    } else {
        mscipc_jr_push(jr, "control");
        if (mscipc_jr_u8(jr, vp, &out->control)) {
            return -1;
        }
        mscipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mscipc_imu_config_data_on_off_response_t */

void mscipc_imu_config_data_on_off_response_to_json(mscipc_jw_t *w,
                                                    const mscipc_imu_config_data_on_off_response_t *in) {
    int first = 1;
    mscipc_jw_raw(w, "{", 1);
    mscipc_jw_key(w, &first, "control");
    mscipc_jw_u8(w, &in->control);
    mscipc_jw_raw(w, "}", 1);
}

int mscipc_imu_config_data_on_off_response_from_json(mscipc_jr_t *jr, size_t pos,
                                                     mscipc_imu_config_data_on_off_response_t *out) {
    static const char *const keys[] = {"control"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mscipc_jr_object(jr, pos, keys, 1)) {
        return -1;
    }
    found = mscipc_jr_get(jr, pos, "control", &vp);
    if (found != 1) {
        return mscipc_jr_fail(jr, "missing parameter \"control\"");
    }
    {
        mscipc_jr_push(jr, "control");
        if (mscipc_jr_u8(jr, vp, &out->control)) {
            return -1;
        }
        mscipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mscipc_imu_config_xtrig_on_off_t */

void mscipc_imu_config_xtrig_on_off_to_json(mscipc_jw_t *w, const mscipc_imu_config_xtrig_on_off_t *in) {
    int first = 1;
    mscipc_jw_raw(w, "{", 1);
    mscipc_jw_key(w, &first, "function");
    mscipc_jw_u8(w, &in->function);
    if (in->has_control) {
        mscipc_jw_key(w, &first, "control");
        mscipc_jw_u8(w, &in->control);
    }
    mscipc_jw_raw(w, "}", 1);
}

int mscipc_imu_config_xtrig_on_off_from_json(mscipc_jr_t *jr, size_t pos,
                                             mscipc_imu_config_xtrig_on_off_t *out) {
    static const char *const keys[] = {"function", "control"};
    size_t vp = 0;
    int found;
    int absent = 0;
    memset(out, 0, sizeof *out);
    if (mscipc_jr_object(jr, pos, keys, 2)) {
        return -1;
    }
    found = mscipc_jr_get(jr, pos, "function", &vp);
    if (found != 1) {
        return mscipc_jr_fail(jr, "missing parameter \"function\"");
    }
    {
        mscipc_jr_push(jr, "function");
        if (mscipc_jr_u8(jr, vp, &out->function)) {
            return -1;
        }
        mscipc_jr_pop(jr);
    }
    found = mscipc_jr_get(jr, pos, "control", &vp);
    out->has_control = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mscipc_jr_fail(jr, "optional parameter \"control\" given after an absent one");
    } else {
        mscipc_jr_push(jr, "control");
        if (mscipc_jr_u8(jr, vp, &out->control)) {
            return -1;
        }
        mscipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mscipc_imu_config_xtrig_on_off_response_t */

void mscipc_imu_config_xtrig_on_off_response_to_json(mscipc_jw_t *w,
                                                     const mscipc_imu_config_xtrig_on_off_response_t *in) {
    int first = 1;
    mscipc_jw_raw(w, "{", 1);
    mscipc_jw_key(w, &first, "control");
    mscipc_jw_u8(w, &in->control);
    mscipc_jw_raw(w, "}", 1);
}

int mscipc_imu_config_xtrig_on_off_response_from_json(mscipc_jr_t *jr, size_t pos,
                                                      mscipc_imu_config_xtrig_on_off_response_t *out) {
    static const char *const keys[] = {"control"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mscipc_jr_object(jr, pos, keys, 1)) {
        return -1;
    }
    found = mscipc_jr_get(jr, pos, "control", &vp);
    if (found != 1) {
        return mscipc_jr_fail(jr, "missing parameter \"control\"");
    }
    {
        mscipc_jr_push(jr, "control");
        if (mscipc_jr_u8(jr, vp, &out->control)) {
            return -1;
        }
        mscipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mscipc_imu_config_select_sensors_rev_b_t */

void mscipc_imu_config_select_sensors_rev_b_to_json(mscipc_jw_t *w,
                                                    const mscipc_imu_config_select_sensors_rev_b_t *in) {
    int first = 1;
    size_t i;
    mscipc_jw_raw(w, "{", 1);
    mscipc_jw_key(w, &first, "function");
    mscipc_jw_u8(w, &in->function);
    if (in->has_sensors) {
        mscipc_jw_key(w, &first, "sensors");
        mscipc_jw_raw(w, "[", 1);
        for (i = 0; i < (size_t)in->sensors_count && i < 252; i++) {
            mscipc_jw_sep(w, i);
            mscipc_jw_u8(w, &in->sensors[i]);
        }
        mscipc_jw_raw(w, "]", 1);
    }
    mscipc_jw_raw(w, "}", 1);
}

int mscipc_imu_config_select_sensors_rev_b_from_json(mscipc_jr_t *jr, size_t pos,
                                                     mscipc_imu_config_select_sensors_rev_b_t *out) {
    static const char *const keys[] = {"function", "sensors"};
    size_t vp = 0;
    int found;
    int absent = 0;
    size_t i;
    size_t it = 0;
    size_t ep = 0;
    memset(out, 0, sizeof *out);
    if (mscipc_jr_object(jr, pos, keys, 2)) {
        return -1;
    }
    found = mscipc_jr_get(jr, pos, "function", &vp);
    if (found != 1) {
        return mscipc_jr_fail(jr, "missing parameter \"function\"");
    }
    {
        mscipc_jr_push(jr, "function");
        if (mscipc_jr_u8(jr, vp, &out->function)) {
            return -1;
        }
        mscipc_jr_pop(jr);
    }
    found = mscipc_jr_get(jr, pos, "sensors", &vp);
    out->has_sensors = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mscipc_jr_fail(jr, "optional parameter \"sensors\" given after an absent one");
    } else {
        mscipc_jr_push(jr, "sensors");
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
            if (i >= 252) {
                return mscipc_jr_fail(jr, "more than 252 elements");
            }
            mscipc_jr_index(jr, i);
            if (mscipc_jr_u8(jr, ep, &out->sensors[i])) {
                return -1;
            }
        }
        mscipc_jr_index(jr, SIZE_MAX);
        out->sensors_count = i;
        mscipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mscipc_imu_config_select_sensors_rev_b_response_t */

void mscipc_imu_config_select_sensors_rev_b_response_to_json(
    mscipc_jw_t *w, const mscipc_imu_config_select_sensors_rev_b_response_t *in) {
    int first = 1;
    size_t i;
    mscipc_jw_raw(w, "{", 1);
    mscipc_jw_key(w, &first, "sensors");
    mscipc_jw_raw(w, "[", 1);
    for (i = 0; i < (size_t)in->sensors_count && i < 253; i++) {
        mscipc_jw_sep(w, i);
        mscipc_jw_u8(w, &in->sensors[i]);
    }
    mscipc_jw_raw(w, "]", 1);
    mscipc_jw_raw(w, "}", 1);
}

int mscipc_imu_config_select_sensors_rev_b_response_from_json(
    mscipc_jr_t *jr, size_t pos, mscipc_imu_config_select_sensors_rev_b_response_t *out) {
    static const char *const keys[] = {"sensors"};
    size_t vp = 0;
    int found;
    size_t i;
    size_t it = 0;
    size_t ep = 0;
    memset(out, 0, sizeof *out);
    if (mscipc_jr_object(jr, pos, keys, 1)) {
        return -1;
    }
    found = mscipc_jr_get(jr, pos, "sensors", &vp);
    if (found != 1) {
        return mscipc_jr_fail(jr, "missing parameter \"sensors\"");
    }
    {
        mscipc_jr_push(jr, "sensors");
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
            if (i >= 253) {
                return mscipc_jr_fail(jr, "more than 253 elements");
            }
            mscipc_jr_index(jr, i);
            if (mscipc_jr_u8(jr, ep, &out->sensors[i])) {
                return -1;
            }
        }
        mscipc_jr_index(jr, SIZE_MAX);
        out->sensors_count = i;
        mscipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mscipc_imu_config_aux_accel_range_t */

void mscipc_imu_config_aux_accel_range_to_json(mscipc_jw_t *w,
                                               const mscipc_imu_config_aux_accel_range_t *in) {
    int first = 1;
    mscipc_jw_raw(w, "{", 1);
    mscipc_jw_key(w, &first, "function");
    mscipc_jw_u8(w, &in->function);
    if (in->has_range) {
        mscipc_jw_key(w, &first, "range");
        mscipc_jw_u8(w, &in->range);
    }
    mscipc_jw_raw(w, "}", 1);
}

int mscipc_imu_config_aux_accel_range_from_json(mscipc_jr_t *jr, size_t pos,
                                                mscipc_imu_config_aux_accel_range_t *out) {
    static const char *const keys[] = {"function", "range"};
    size_t vp = 0;
    int found;
    int absent = 0;
    memset(out, 0, sizeof *out);
    if (mscipc_jr_object(jr, pos, keys, 2)) {
        return -1;
    }
    found = mscipc_jr_get(jr, pos, "function", &vp);
    if (found != 1) {
        return mscipc_jr_fail(jr, "missing parameter \"function\"");
    }
    {
        mscipc_jr_push(jr, "function");
        if (mscipc_jr_u8(jr, vp, &out->function)) {
            return -1;
        }
        mscipc_jr_pop(jr);
    }
    found = mscipc_jr_get(jr, pos, "range", &vp);
    out->has_range = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mscipc_jr_fail(jr, "optional parameter \"range\" given after an absent one");
    } else {
        mscipc_jr_push(jr, "range");
        if (mscipc_jr_u8(jr, vp, &out->range)) {
            return -1;
        }
        mscipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mscipc_imu_config_aux_accel_range_response_t */

void mscipc_imu_config_aux_accel_range_response_to_json(
    mscipc_jw_t *w, const mscipc_imu_config_aux_accel_range_response_t *in) {
    int first = 1;
    mscipc_jw_raw(w, "{", 1);
    mscipc_jw_key(w, &first, "range");
    mscipc_jw_u8(w, &in->range);
    mscipc_jw_raw(w, "}", 1);
}

int mscipc_imu_config_aux_accel_range_response_from_json(mscipc_jr_t *jr, size_t pos,
                                                         mscipc_imu_config_aux_accel_range_response_t *out) {
    static const char *const keys[] = {"range"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mscipc_jr_object(jr, pos, keys, 1)) {
        return -1;
    }
    found = mscipc_jr_get(jr, pos, "range", &vp);
    if (found != 1) {
        return mscipc_jr_fail(jr, "missing parameter \"range\"");
    }
    {
        mscipc_jr_push(jr, "range");
        if (mscipc_jr_u8(jr, vp, &out->range)) {
            return -1;
        }
        mscipc_jr_pop(jr);
    }
    return 0;
}
