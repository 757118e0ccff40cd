/* Canonical JSON of Base Command Set (the mipcodec_json library). Generated from the spec: do not edit. */
#include "mipcodec/sets/base.h"
#include "layouts_internal.h"
#include "types_internal.h"

#include <assert.h>
#include <string.h>

/* ---- mipc_base_ping_t */

void mipc_base_ping_to_json(mipc_jw_t *w, const mipc_base_ping_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_raw(w, "}", 1);
    (void)in;
    (void)first;
}

int mipc_base_ping_from_json(mipc_jr_t *jr, size_t pos, mipc_base_ping_t *out) {
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, NULL, 0)) {
        return -1;
    }
    return 0;
}

/* ---- mipc_base_set_to_idle_t */

void mipc_base_set_to_idle_to_json(mipc_jw_t *w, const mipc_base_set_to_idle_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_raw(w, "}", 1);
    (void)in;
    (void)first;
}

int mipc_base_set_to_idle_from_json(mipc_jr_t *jr, size_t pos, mipc_base_set_to_idle_t *out) {
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, NULL, 0)) {
        return -1;
    }
    return 0;
}

/* ---- mipc_base_get_device_info_t */

void mipc_base_get_device_info_to_json(mipc_jw_t *w, const mipc_base_get_device_info_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_raw(w, "}", 1);
    (void)in;
    (void)first;
}

int mipc_base_get_device_info_from_json(mipc_jr_t *jr, size_t pos, mipc_base_get_device_info_t *out) {
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, NULL, 0)) {
        return -1;
    }
    return 0;
}

/* ---- mipc_base_device_info_t */

void mipc_base_device_info_to_json(mipc_jw_t *w, const mipc_base_device_info_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "info");
    mipc_device_info_to_json(w, &in->info);
    mipc_jw_raw(w, "}", 1);
}

int mipc_base_device_info_from_json(mipc_jr_t *jr, size_t pos, mipc_base_device_info_t *out) {
    static const char *const keys[] = {"info"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 1)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "info", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"info\"");
    }
    {
        mipc_jr_push(jr, "info");
        if (mipc_device_info_from_json(jr, vp, &out->info)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mipc_base_get_device_descriptors_t */

void mipc_base_get_device_descriptors_to_json(mipc_jw_t *w, const mipc_base_get_device_descriptors_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_raw(w, "}", 1);
    (void)in;
    (void)first;
}

int mipc_base_get_device_descriptors_from_json(mipc_jr_t *jr, size_t pos,
                                               mipc_base_get_device_descriptors_t *out) {
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, NULL, 0)) {
        return -1;
    }
    return 0;
}

/* ---- mipc_base_device_descriptors_t */

void mipc_base_device_descriptors_to_json(mipc_jw_t *w, const mipc_base_device_descriptors_t *in) {
    int first = 1;
    size_t i;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "descriptors");
    mipc_jw_raw(w, "[", 1);
    for (i = 0; i < (size_t)in->descriptors_count && i < 126; i++) {
        mipc_jw_sep(w, i);
        mipc_jw_u16(w, &in->descriptors[i]);
    }
    mipc_jw_raw(w, "]", 1);
    mipc_jw_raw(w, "}", 1);
}

int mipc_base_device_descriptors_from_json(mipc_jr_t *jr, size_t pos, mipc_base_device_descriptors_t *out) {
    static const char *const keys[] = {"descriptors"};
    size_t vp = 0;
    int found;
    size_t i;
    size_t it = 0;
    size_t ep = 0;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 1)) {
        return -1;
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
            if (i >= 126) {
                return mipc_jr_fail(jr, "more than 126 elements");
            }
            mipc_jr_index(jr, i);
            if (mipc_jr_u16(jr, ep, &out->descriptors[i])) {
                return -1;
            }
        }
        mipc_jr_index(jr, SIZE_MAX);
        out->descriptors_count = i;
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mipc_base_built_in_test_t */

void mipc_base_built_in_test_to_json(mipc_jw_t *w, const mipc_base_built_in_test_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_raw(w, "}", 1);
    (void)in;
    (void)first;
}

int mipc_base_built_in_test_from_json(mipc_jr_t *jr, size_t pos, mipc_base_built_in_test_t *out) {
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, NULL, 0)) {
        return -1;
    }
    return 0;
}

/* ---- mipc_base_built_in_test_result_gx5_45_t */

void mipc_base_built_in_test_result_gx5_45_to_json(mipc_jw_t *w,
                                                   const mipc_base_built_in_test_result_gx5_45_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "flags");
    mipc_jw_u32(w, &in->flags);
    mipc_jw_raw(w, "}", 1);
}

int mipc_base_built_in_test_result_gx5_45_from_json(mipc_jr_t *jr, size_t pos,
                                                    mipc_base_built_in_test_result_gx5_45_t *out) {
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
        if (mipc_jr_u32(jr, vp, &out->flags)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mipc_base_built_in_test_result_cv7_ins_t */

void mipc_base_built_in_test_result_cv7_ins_to_json(mipc_jw_t *w,
                                                    const mipc_base_built_in_test_result_cv7_ins_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "flags");
    mipc_jw_u32(w, &in->flags);
    mipc_jw_raw(w, "}", 1);
}

int mipc_base_built_in_test_result_cv7_ins_from_json(mipc_jr_t *jr, size_t pos,
                                                     mipc_base_built_in_test_result_cv7_ins_t *out) {
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
        if (mipc_jr_u32(jr, vp, &out->flags)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mipc_base_resume_t */

void mipc_base_resume_to_json(mipc_jw_t *w, const mipc_base_resume_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_raw(w, "}", 1);
    (void)in;
    (void)first;
}

int mipc_base_resume_from_json(mipc_jr_t *jr, size_t pos, mipc_base_resume_t *out) {
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, NULL, 0)) {
        return -1;
    }
    return 0;
}

/* ---- mipc_base_get_extended_descriptors_t */

void mipc_base_get_extended_descriptors_to_json(mipc_jw_t *w,
                                                const mipc_base_get_extended_descriptors_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_raw(w, "}", 1);
    (void)in;
    (void)first;
}

int mipc_base_get_extended_descriptors_from_json(mipc_jr_t *jr, size_t pos,
                                                 mipc_base_get_extended_descriptors_t *out) {
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, NULL, 0)) {
        return -1;
    }
    return 0;
}

/* ---- mipc_base_extended_descriptors_t */

void mipc_base_extended_descriptors_to_json(mipc_jw_t *w, const mipc_base_extended_descriptors_t *in) {
    int first = 1;
    size_t i;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "descriptors");
    mipc_jw_raw(w, "[", 1);
    for (i = 0; i < (size_t)in->descriptors_count && i < 126; i++) {
        mipc_jw_sep(w, i);
        mipc_jw_u16(w, &in->descriptors[i]);
    }
    mipc_jw_raw(w, "]", 1);
    mipc_jw_raw(w, "}", 1);
}

int mipc_base_extended_descriptors_from_json(mipc_jr_t *jr, size_t pos,
                                             mipc_base_extended_descriptors_t *out) {
    static const char *const keys[] = {"descriptors"};
    size_t vp = 0;
    int found;
    size_t i;
    size_t it = 0;
    size_t ep = 0;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 1)) {
        return -1;
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
            if (i >= 126) {
                return mipc_jr_fail(jr, "more than 126 elements");
            }
            mipc_jr_index(jr, i);
            if (mipc_jr_u16(jr, ep, &out->descriptors[i])) {
                return -1;
            }
        }
        mipc_jr_index(jr, SIZE_MAX);
        out->descriptors_count = i;
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mipc_base_continuous_bit_t */

void mipc_base_continuous_bit_to_json(mipc_jw_t *w, const mipc_base_continuous_bit_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_raw(w, "}", 1);
    (void)in;
    (void)first;
}

int mipc_base_continuous_bit_from_json(mipc_jr_t *jr, size_t pos, mipc_base_continuous_bit_t *out) {
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, NULL, 0)) {
        return -1;
    }
    return 0;
}

/* ---- mipc_base_continuous_bit_result_t */

void mipc_base_continuous_bit_result_to_json(mipc_jw_t *w, const mipc_base_continuous_bit_result_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "result");
    mipc_cv7_continuous_bit_to_json(w, &in->result);
    mipc_jw_raw(w, "}", 1);
}

int mipc_base_continuous_bit_result_from_json(mipc_jr_t *jr, size_t pos,
                                              mipc_base_continuous_bit_result_t *out) {
    static const char *const keys[] = {"result"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 1)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "result", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"result\"");
    }
    {
        mipc_jr_push(jr, "result");
        if (mipc_cv7_continuous_bit_from_json(jr, vp, &out->result)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mipc_base_comm_port_speed_t */

void mipc_base_comm_port_speed_to_json(mipc_jw_t *w, const mipc_base_comm_port_speed_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "function");
    mipc_jw_u8(w, &in->function);
    mipc_jw_key(w, &first, "port");
    mipc_jw_u8(w, &in->port);
    if (in->has_baud) {
        mipc_jw_key(w, &first, "baud");
        mipc_jw_u32(w, &in->baud);
    }
    mipc_jw_raw(w, "}", 1);
}

int mipc_base_comm_port_speed_from_json(mipc_jr_t *jr, size_t pos, mipc_base_comm_port_speed_t *out) {
    static const char *const keys[] = {"function", "port", "baud"};
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
    found = mipc_jr_get(jr, pos, "port", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"port\"");
    }
    {
        mipc_jr_push(jr, "port");
        if (mipc_jr_u8(jr, vp, &out->port)) {
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

/* ---- mipc_base_comm_port_speed_response_t */

void mipc_base_comm_port_speed_response_to_json(mipc_jw_t *w,
                                                const mipc_base_comm_port_speed_response_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "port");
    mipc_jw_u8(w, &in->port);
    mipc_jw_key(w, &first, "baud");
    mipc_jw_u32(w, &in->baud);
    mipc_jw_raw(w, "}", 1);
}

int mipc_base_comm_port_speed_response_from_json(mipc_jr_t *jr, size_t pos,
                                                 mipc_base_comm_port_speed_response_t *out) {
    static const char *const keys[] = {"port", "baud"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 2)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "port", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"port\"");
    }
    {
        mipc_jr_push(jr, "port");
        if (mipc_jr_u8(jr, vp, &out->port)) {
            return -1;
        }
        mipc_jr_pop(jr);
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

/* ---- mipc_base_gps_time_update_gx5_45_t */

void mipc_base_gps_time_update_gx5_45_to_json(mipc_jw_t *w, const mipc_base_gps_time_update_gx5_45_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "function");
    mipc_jw_u8(w, &in->function);
    mipc_jw_key(w, &first, "field_id");
    mipc_jw_u8(w, &in->field_id);
    if (in->has_value) {
        mipc_jw_key(w, &first, "value");
        mipc_jw_u32(w, &in->value);
    }
    mipc_jw_raw(w, "}", 1);
}

int mipc_base_gps_time_update_gx5_45_from_json(mipc_jr_t *jr, size_t pos,
                                               mipc_base_gps_time_update_gx5_45_t *out) {
    static const char *const keys[] = {"function", "field_id", "value"};
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
    found = mipc_jr_get(jr, pos, "field_id", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"field_id\"");
    }
    {
        mipc_jr_push(jr, "field_id");
        if (mipc_jr_u8(jr, vp, &out->field_id)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "value", &vp);
    out->has_value = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mipc_jr_fail(jr, "optional parameter \"value\" given after an absent one");
    } else {
        mipc_jr_push(jr, "value");
        if (mipc_jr_u32(jr, vp, &out->value)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mipc_base_gps_time_update_cv7_ins_t */

void mipc_base_gps_time_update_cv7_ins_to_json(mipc_jw_t *w, const mipc_base_gps_time_update_cv7_ins_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "function");
    mipc_jw_u8(w, &in->function);
    mipc_jw_key(w, &first, "field_id");
    mipc_jw_u8(w, &in->field_id);
    mipc_jw_key(w, &first, "value");
    mipc_jw_u32(w, &in->value);
    mipc_jw_raw(w, "}", 1);
}

int mipc_base_gps_time_update_cv7_ins_from_json(mipc_jr_t *jr, size_t pos,
                                                mipc_base_gps_time_update_cv7_ins_t *out) {
    static const char *const keys[] = {"function", "field_id", "value"};
    size_t vp = 0;
    int found;
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
    found = mipc_jr_get(jr, pos, "field_id", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"field_id\"");
    }
    {
        mipc_jr_push(jr, "field_id");
        if (mipc_jr_u8(jr, vp, &out->field_id)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "value", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"value\"");
    }
    {
        mipc_jr_push(jr, "value");
        if (mipc_jr_u32(jr, vp, &out->value)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mipc_base_gps_week_t */

void mipc_base_gps_week_to_json(mipc_jw_t *w, const mipc_base_gps_week_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "week");
    mipc_jw_u32(w, &in->week);
    mipc_jw_raw(w, "}", 1);
}

int mipc_base_gps_week_from_json(mipc_jr_t *jr, size_t pos, mipc_base_gps_week_t *out) {
    static const char *const keys[] = {"week"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 1)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "week", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"week\"");
    }
    {
        mipc_jr_push(jr, "week");
        if (mipc_jr_u32(jr, vp, &out->week)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mipc_base_gps_seconds_t */

void mipc_base_gps_seconds_to_json(mipc_jw_t *w, const mipc_base_gps_seconds_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "seconds");
    mipc_jw_u32(w, &in->seconds);
    mipc_jw_raw(w, "}", 1);
}

int mipc_base_gps_seconds_from_json(mipc_jr_t *jr, size_t pos, mipc_base_gps_seconds_t *out) {
    static const char *const keys[] = {"seconds"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 1)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "seconds", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"seconds\"");
    }
    {
        mipc_jr_push(jr, "seconds");
        if (mipc_jr_u32(jr, vp, &out->seconds)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mipc_base_device_reset_t */

void mipc_base_device_reset_to_json(mipc_jw_t *w, const mipc_base_device_reset_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_raw(w, "}", 1);
    (void)in;
    (void)first;
}

int mipc_base_device_reset_from_json(mipc_jr_t *jr, size_t pos, mipc_base_device_reset_t *out) {
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, NULL, 0)) {
        return -1;
    }
    return 0;
}
