/* Canonical JSON of the named structs and unions (the mipcodec_json library). Generated: do not edit. */
#include "types_internal.h"

#include <string.h>

/* ---- ActionGpioParams */

void mipc_action_gpio_params_to_json(mipc_jw_t *w, const mipc_action_gpio_params_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "pin");
    mipc_jw_u8(w, &in->pin);
    mipc_jw_key(w, &first, "mode");
    mipc_jw_u8(w, &in->mode);
    mipc_jw_raw(w, "}", 1);
}

int mipc_action_gpio_params_from_json(mipc_jr_t *jr, size_t pos, mipc_action_gpio_params_t *out) {
    static const char *const keys[] = {"pin", "mode"};
    size_t vp = 0;
    int found;
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

/* ---- MessageParams */

void mipc_message_params_to_json(mipc_jw_t *w, const mipc_message_params_t *in) {
    int first = 1;
    size_t i;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "desc_set");
    mipc_jw_u8(w, &in->desc_set);
    mipc_jw_key(w, &first, "decimation");
    mipc_jw_u16(w, &in->decimation);
    mipc_jw_key(w, &first, "num_fields");
    mipc_jw_u8(w, &in->num_fields);
    mipc_jw_key(w, &first, "descriptors");
    mipc_jw_raw(w, "[", 1);
    for (i = 0; i < (size_t)in->num_fields && i < 12; i++) {
        mipc_jw_sep(w, i);
        mipc_jw_u8(w, &in->descriptors[i]);
    }
    mipc_jw_raw(w, "]", 1);
    mipc_jw_raw(w, "}", 1);
}

int mipc_message_params_from_json(mipc_jr_t *jr, size_t pos, mipc_message_params_t *out) {
    static const char *const keys[] = {"desc_set", "decimation", "num_fields", "descriptors"};
    size_t vp = 0;
    int found;
    size_t i;
    size_t it = 0;
    size_t ep = 0;
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
    found = mipc_jr_get(jr, pos, "decimation", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"decimation\"");
    }
    {
        mipc_jr_push(jr, "decimation");
        if (mipc_jr_u16(jr, vp, &out->decimation)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "num_fields", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"num_fields\"");
    }
    {
        mipc_jr_push(jr, "num_fields");
        if (mipc_jr_u8(jr, vp, &out->num_fields)) {
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
            if (i >= 12) {
                return mipc_jr_fail(jr, "more than 12 elements");
            }
            mipc_jr_index(jr, i);
            if (mipc_jr_u8(jr, ep, &out->descriptors[i])) {
                return -1;
            }
        }
        mipc_jr_index(jr, SIZE_MAX);
        if (i != (size_t)out->num_fields) {
            return mipc_jr_fail(jr, "%zu elements but num_fields is %zu", i, (size_t)out->num_fields);
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- ActionStatusEntry */

void mipc_action_status_entry_to_json(mipc_jw_t *w, const mipc_action_status_entry_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "action_type");
    mipc_jw_u8(w, &in->action_type);
    mipc_jw_key(w, &first, "trigger_id");
    mipc_jw_u8(w, &in->trigger_id);
    mipc_jw_raw(w, "}", 1);
}

int mipc_action_status_entry_from_json(mipc_jr_t *jr, size_t pos, mipc_action_status_entry_t *out) {
    static const char *const keys[] = {"action_type", "trigger_id"};
    size_t vp = 0;
    int found;
    if (mipc_jr_object(jr, pos, keys, 2)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "action_type", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"action_type\"");
    }
    {
        mipc_jr_push(jr, "action_type");
        if (mipc_jr_u8(jr, vp, &out->action_type)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "trigger_id", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"trigger_id\"");
    }
    {
        mipc_jr_push(jr, "trigger_id");
        if (mipc_jr_u8(jr, vp, &out->trigger_id)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- AidingFrameEuler */

void mipc_aiding_frame_euler_to_json(mipc_jw_t *w, const mipc_aiding_frame_euler_t *in) {
    int first = 1;
    size_t i;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "euler");
    mipc_jw_raw(w, "[", 1);
    for (i = 0; i < 3; i++) {
        mipc_jw_sep(w, i);
        mipc_jw_f32(w, &in->euler[i]);
    }
    mipc_jw_raw(w, "]", 1);
    mipc_jw_raw(w, "}", 1);
}

int mipc_aiding_frame_euler_from_json(mipc_jr_t *jr, size_t pos, mipc_aiding_frame_euler_t *out) {
    static const char *const keys[] = {"euler"};
    size_t vp = 0;
    int found;
    size_t i;
    size_t it = 0;
    size_t ep = 0;
    if (mipc_jr_object(jr, pos, keys, 1)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "euler", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"euler\"");
    }
    {
        mipc_jr_push(jr, "euler");
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
            if (mipc_jr_f32(jr, ep, &out->euler[i])) {
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

/* ---- AidingFrameQuaternion */

void mipc_aiding_frame_quaternion_to_json(mipc_jw_t *w, const mipc_aiding_frame_quaternion_t *in) {
    int first = 1;
    size_t i;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "quaternion");
    mipc_jw_raw(w, "[", 1);
    for (i = 0; i < 4; i++) {
        mipc_jw_sep(w, i);
        mipc_jw_f32(w, &in->quaternion[i]);
    }
    mipc_jw_raw(w, "]", 1);
    mipc_jw_raw(w, "}", 1);
}

int mipc_aiding_frame_quaternion_from_json(mipc_jr_t *jr, size_t pos, mipc_aiding_frame_quaternion_t *out) {
    static const char *const keys[] = {"quaternion"};
    size_t vp = 0;
    int found;
    size_t i;
    size_t it = 0;
    size_t ep = 0;
    if (mipc_jr_object(jr, pos, keys, 1)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "quaternion", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"quaternion\"");
    }
    {
        mipc_jr_push(jr, "quaternion");
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
            if (mipc_jr_f32(jr, ep, &out->quaternion[i])) {
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

/* ---- AidingTime */

void mipc_aiding_time_to_json(mipc_jw_t *w, const mipc_aiding_time_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "timebase");
    mipc_jw_u8(w, &in->timebase);
    mipc_jw_key(w, &first, "reserved");
    mipc_jw_u8(w, &in->reserved);
    mipc_jw_key(w, &first, "nanoseconds");
    mipc_jw_u64(w, &in->nanoseconds);
    mipc_jw_raw(w, "}", 1);
}

int mipc_aiding_time_from_json(mipc_jr_t *jr, size_t pos, mipc_aiding_time_t *out) {
    static const char *const keys[] = {"timebase", "reserved", "nanoseconds"};
    size_t vp = 0;
    int found;
    if (mipc_jr_object(jr, pos, keys, 3)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "timebase", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"timebase\"");
    }
    {
        mipc_jr_push(jr, "timebase");
        if (mipc_jr_u8(jr, vp, &out->timebase)) {
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
    found = mipc_jr_get(jr, pos, "nanoseconds", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"nanoseconds\"");
    }
    {
        mipc_jr_push(jr, "nanoseconds");
        if (mipc_jr_u64(jr, vp, &out->nanoseconds)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- CombinationParams */

void mipc_combination_params_to_json(mipc_jw_t *w, const mipc_combination_params_t *in) {
    int first = 1;
    size_t i;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "logic_table");
    mipc_jw_u16(w, &in->logic_table);
    mipc_jw_key(w, &first, "input_triggers");
    mipc_jw_raw(w, "[", 1);
    for (i = 0; i < 4; i++) {
        mipc_jw_sep(w, i);
        mipc_jw_u8(w, &in->input_triggers[i]);
    }
    mipc_jw_raw(w, "]", 1);
    mipc_jw_raw(w, "}", 1);
}

int mipc_combination_params_from_json(mipc_jr_t *jr, size_t pos, mipc_combination_params_t *out) {
    static const char *const keys[] = {"logic_table", "input_triggers"};
    size_t vp = 0;
    int found;
    size_t i;
    size_t it = 0;
    size_t ep = 0;
    if (mipc_jr_object(jr, pos, keys, 2)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "logic_table", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"logic_table\"");
    }
    {
        mipc_jr_push(jr, "logic_table");
        if (mipc_jr_u16(jr, vp, &out->logic_table)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "input_triggers", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"input_triggers\"");
    }
    {
        mipc_jr_push(jr, "input_triggers");
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
            if (mipc_jr_u8(jr, ep, &out->input_triggers[i])) {
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

/* ---- ConstellationSettings */

void mipc_constellation_settings_to_json(mipc_jw_t *w, const mipc_constellation_settings_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "constellation_id");
    mipc_jw_u8(w, &in->constellation_id);
    mipc_jw_key(w, &first, "enable");
    mipc_jw_u8(w, &in->enable);
    mipc_jw_key(w, &first, "reserved_channels");
    mipc_jw_u8(w, &in->reserved_channels);
    mipc_jw_key(w, &first, "max_channels");
    mipc_jw_u8(w, &in->max_channels);
    mipc_jw_key(w, &first, "option_flags");
    mipc_jw_u16(w, &in->option_flags);
    mipc_jw_raw(w, "}", 1);
}

int mipc_constellation_settings_from_json(mipc_jr_t *jr, size_t pos, mipc_constellation_settings_t *out) {
    static const char *const keys[] = {"constellation_id", "enable", "reserved_channels", "max_channels",
                                       "option_flags"};
    size_t vp = 0;
    int found;
    if (mipc_jr_object(jr, pos, keys, 5)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "constellation_id", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"constellation_id\"");
    }
    {
        mipc_jr_push(jr, "constellation_id");
        if (mipc_jr_u8(jr, vp, &out->constellation_id)) {
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
        if (mipc_jr_u8(jr, vp, &out->enable)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "reserved_channels", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"reserved_channels\"");
    }
    {
        mipc_jr_push(jr, "reserved_channels");
        if (mipc_jr_u8(jr, vp, &out->reserved_channels)) {
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
        if (mipc_jr_u8(jr, vp, &out->max_channels)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "option_flags", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"option_flags\"");
    }
    {
        mipc_jr_push(jr, "option_flags");
        if (mipc_jr_u16(jr, vp, &out->option_flags)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- Cv7ContinuousBit */

void mipc_cv7_continuous_bit_to_json(mipc_jw_t *w, const mipc_cv7_continuous_bit_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "system_byte_0");
    mipc_jw_u8(w, &in->system_byte_0);
    mipc_jw_key(w, &first, "reserved_byte_1");
    mipc_jw_u8(w, &in->reserved_byte_1);
    mipc_jw_key(w, &first, "system_byte_2");
    mipc_jw_u8(w, &in->system_byte_2);
    mipc_jw_key(w, &first, "system_byte_3");
    mipc_jw_u8(w, &in->system_byte_3);
    mipc_jw_key(w, &first, "imu_byte_4");
    mipc_jw_u8(w, &in->imu_byte_4);
    mipc_jw_key(w, &first, "imu_byte_5");
    mipc_jw_u8(w, &in->imu_byte_5);
    mipc_jw_key(w, &first, "imu_byte_6");
    mipc_jw_u8(w, &in->imu_byte_6);
    mipc_jw_key(w, &first, "imu_byte_7");
    mipc_jw_u8(w, &in->imu_byte_7);
    mipc_jw_key(w, &first, "nav_byte_8");
    mipc_jw_u8(w, &in->nav_byte_8);
    mipc_jw_key(w, &first, "reserved_byte_9");
    mipc_jw_u8(w, &in->reserved_byte_9);
    mipc_jw_key(w, &first, "reserved_byte_10");
    mipc_jw_u8(w, &in->reserved_byte_10);
    mipc_jw_key(w, &first, "reserved_byte_11");
    mipc_jw_u8(w, &in->reserved_byte_11);
    mipc_jw_key(w, &first, "reserved_byte_12");
    mipc_jw_u8(w, &in->reserved_byte_12);
    mipc_jw_key(w, &first, "gnss_byte_13");
    mipc_jw_u8(w, &in->gnss_byte_13);
    mipc_jw_key(w, &first, "gnss_byte_14");
    mipc_jw_u8(w, &in->gnss_byte_14);
    mipc_jw_key(w, &first, "reserved_byte_15");
    mipc_jw_u8(w, &in->reserved_byte_15);
    mipc_jw_raw(w, "}", 1);
}

int mipc_cv7_continuous_bit_from_json(mipc_jr_t *jr, size_t pos, mipc_cv7_continuous_bit_t *out) {
    static const char *const keys[] = {
        "system_byte_0",    "reserved_byte_1", "system_byte_2",    "system_byte_3",
        "imu_byte_4",       "imu_byte_5",      "imu_byte_6",       "imu_byte_7",
        "nav_byte_8",       "reserved_byte_9", "reserved_byte_10", "reserved_byte_11",
        "reserved_byte_12", "gnss_byte_13",    "gnss_byte_14",     "reserved_byte_15"};
    size_t vp = 0;
    int found;
    if (mipc_jr_object(jr, pos, keys, 16)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "system_byte_0", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"system_byte_0\"");
    }
    {
        mipc_jr_push(jr, "system_byte_0");
        if (mipc_jr_u8(jr, vp, &out->system_byte_0)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "reserved_byte_1", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"reserved_byte_1\"");
    }
    {
        mipc_jr_push(jr, "reserved_byte_1");
        if (mipc_jr_u8(jr, vp, &out->reserved_byte_1)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "system_byte_2", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"system_byte_2\"");
    }
    {
        mipc_jr_push(jr, "system_byte_2");
        if (mipc_jr_u8(jr, vp, &out->system_byte_2)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "system_byte_3", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"system_byte_3\"");
    }
    {
        mipc_jr_push(jr, "system_byte_3");
        if (mipc_jr_u8(jr, vp, &out->system_byte_3)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "imu_byte_4", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"imu_byte_4\"");
    }
    {
        mipc_jr_push(jr, "imu_byte_4");
        if (mipc_jr_u8(jr, vp, &out->imu_byte_4)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "imu_byte_5", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"imu_byte_5\"");
    }
    {
        mipc_jr_push(jr, "imu_byte_5");
        if (mipc_jr_u8(jr, vp, &out->imu_byte_5)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "imu_byte_6", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"imu_byte_6\"");
    }
    {
        mipc_jr_push(jr, "imu_byte_6");
        if (mipc_jr_u8(jr, vp, &out->imu_byte_6)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "imu_byte_7", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"imu_byte_7\"");
    }
    {
        mipc_jr_push(jr, "imu_byte_7");
        if (mipc_jr_u8(jr, vp, &out->imu_byte_7)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "nav_byte_8", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"nav_byte_8\"");
    }
    {
        mipc_jr_push(jr, "nav_byte_8");
        if (mipc_jr_u8(jr, vp, &out->nav_byte_8)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "reserved_byte_9", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"reserved_byte_9\"");
    }
    {
        mipc_jr_push(jr, "reserved_byte_9");
        if (mipc_jr_u8(jr, vp, &out->reserved_byte_9)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "reserved_byte_10", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"reserved_byte_10\"");
    }
    {
        mipc_jr_push(jr, "reserved_byte_10");
        if (mipc_jr_u8(jr, vp, &out->reserved_byte_10)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "reserved_byte_11", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"reserved_byte_11\"");
    }
    {
        mipc_jr_push(jr, "reserved_byte_11");
        if (mipc_jr_u8(jr, vp, &out->reserved_byte_11)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "reserved_byte_12", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"reserved_byte_12\"");
    }
    {
        mipc_jr_push(jr, "reserved_byte_12");
        if (mipc_jr_u8(jr, vp, &out->reserved_byte_12)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "gnss_byte_13", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"gnss_byte_13\"");
    }
    {
        mipc_jr_push(jr, "gnss_byte_13");
        if (mipc_jr_u8(jr, vp, &out->gnss_byte_13)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "gnss_byte_14", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"gnss_byte_14\"");
    }
    {
        mipc_jr_push(jr, "gnss_byte_14");
        if (mipc_jr_u8(jr, vp, &out->gnss_byte_14)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "reserved_byte_15", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"reserved_byte_15\"");
    }
    {
        mipc_jr_push(jr, "reserved_byte_15");
        if (mipc_jr_u8(jr, vp, &out->reserved_byte_15)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- DescriptorRate */

void mipc_descriptor_rate_to_json(mipc_jw_t *w, const mipc_descriptor_rate_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "descriptor");
    mipc_jw_u8(w, &in->descriptor);
    mipc_jw_key(w, &first, "decimation");
    mipc_jw_u16(w, &in->decimation);
    mipc_jw_raw(w, "}", 1);
}

int mipc_descriptor_rate_from_json(mipc_jr_t *jr, size_t pos, mipc_descriptor_rate_t *out) {
    static const char *const keys[] = {"descriptor", "decimation"};
    size_t vp = 0;
    int found;
    if (mipc_jr_object(jr, pos, keys, 2)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "descriptor", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"descriptor\"");
    }
    {
        mipc_jr_push(jr, "descriptor");
        if (mipc_jr_u8(jr, vp, &out->descriptor)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "decimation", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"decimation\"");
    }
    {
        mipc_jr_push(jr, "decimation");
        if (mipc_jr_u16(jr, vp, &out->decimation)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- DeviceInfo */

void mipc_device_info_to_json(mipc_jw_t *w, const mipc_device_info_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "firmware_version");
    mipc_jw_u16(w, &in->firmware_version);
    mipc_jw_key(w, &first, "model_name");
    mipc_jw_chars(w, in->model_name, 16);
    mipc_jw_key(w, &first, "model_number");
    mipc_jw_chars(w, in->model_number, 16);
    mipc_jw_key(w, &first, "serial_number");
    mipc_jw_chars(w, in->serial_number, 16);
    mipc_jw_key(w, &first, "lot_number");
    mipc_jw_chars(w, in->lot_number, 16);
    mipc_jw_key(w, &first, "device_options");
    mipc_jw_chars(w, in->device_options, 16);
    mipc_jw_raw(w, "}", 1);
}

int mipc_device_info_from_json(mipc_jr_t *jr, size_t pos, mipc_device_info_t *out) {
    static const char *const keys[] = {"firmware_version", "model_name", "model_number",
                                       "serial_number",    "lot_number", "device_options"};
    size_t vp = 0;
    int found;
    if (mipc_jr_object(jr, pos, keys, 6)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "firmware_version", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"firmware_version\"");
    }
    {
        mipc_jr_push(jr, "firmware_version");
        if (mipc_jr_u16(jr, vp, &out->firmware_version)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "model_name", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"model_name\"");
    }
    {
        mipc_jr_push(jr, "model_name");
        if (mipc_jr_chars(jr, vp, out->model_name, 16)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "model_number", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"model_number\"");
    }
    {
        mipc_jr_push(jr, "model_number");
        if (mipc_jr_chars(jr, vp, out->model_number, 16)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "serial_number", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"serial_number\"");
    }
    {
        mipc_jr_push(jr, "serial_number");
        if (mipc_jr_chars(jr, vp, out->serial_number, 16)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "lot_number", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"lot_number\"");
    }
    {
        mipc_jr_push(jr, "lot_number");
        if (mipc_jr_chars(jr, vp, out->lot_number, 16)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "device_options", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"device_options\"");
    }
    {
        mipc_jr_push(jr, "device_options");
        if (mipc_jr_chars(jr, vp, out->device_options, 16)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- GnssReceiverInfoEntry */

void mipc_gnss_receiver_info_entry_to_json(mipc_jw_t *w, const mipc_gnss_receiver_info_entry_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "receiver_id");
    mipc_jw_u8(w, &in->receiver_id);
    mipc_jw_key(w, &first, "mip_data_descriptor_set");
    mipc_jw_u8(w, &in->mip_data_descriptor_set);
    mipc_jw_key(w, &first, "description");
    mipc_jw_chars(w, in->description, 32);
    mipc_jw_raw(w, "}", 1);
}

int mipc_gnss_receiver_info_entry_from_json(mipc_jr_t *jr, size_t pos, mipc_gnss_receiver_info_entry_t *out) {
    static const char *const keys[] = {"receiver_id", "mip_data_descriptor_set", "description"};
    size_t vp = 0;
    int found;
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
    found = mipc_jr_get(jr, pos, "mip_data_descriptor_set", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"mip_data_descriptor_set\"");
    }
    {
        mipc_jr_push(jr, "mip_data_descriptor_set");
        if (mipc_jr_u8(jr, vp, &out->mip_data_descriptor_set)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "description", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"description\"");
    }
    {
        mipc_jr_push(jr, "description");
        if (mipc_jr_chars(jr, vp, out->description, 32)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- GpioBehaviorUnused */

void mipc_gpio_behavior_unused_to_json(mipc_jw_t *w, const mipc_gpio_behavior_unused_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "behavior");
    mipc_jw_u8(w, &in->behavior);
    mipc_jw_raw(w, "}", 1);
}

int mipc_gpio_behavior_unused_from_json(mipc_jr_t *jr, size_t pos, mipc_gpio_behavior_unused_t *out) {
    static const char *const keys[] = {"behavior"};
    size_t vp = 0;
    int found;
    if (mipc_jr_object(jr, pos, keys, 1)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "behavior", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"behavior\"");
    }
    {
        mipc_jr_push(jr, "behavior");
        if (mipc_jr_u8(jr, vp, &out->behavior)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- GpioBehaviorIo */

void mipc_gpio_behavior_io_to_json(mipc_jw_t *w, const mipc_gpio_behavior_io_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "behavior");
    mipc_jw_u8(w, &in->behavior);
    mipc_jw_raw(w, "}", 1);
}

int mipc_gpio_behavior_io_from_json(mipc_jr_t *jr, size_t pos, mipc_gpio_behavior_io_t *out) {
    static const char *const keys[] = {"behavior"};
    size_t vp = 0;
    int found;
    if (mipc_jr_object(jr, pos, keys, 1)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "behavior", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"behavior\"");
    }
    {
        mipc_jr_push(jr, "behavior");
        if (mipc_jr_u8(jr, vp, &out->behavior)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- GpioBehaviorPps */

void mipc_gpio_behavior_pps_to_json(mipc_jw_t *w, const mipc_gpio_behavior_pps_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "behavior");
    mipc_jw_u8(w, &in->behavior);
    mipc_jw_raw(w, "}", 1);
}

int mipc_gpio_behavior_pps_from_json(mipc_jr_t *jr, size_t pos, mipc_gpio_behavior_pps_t *out) {
    static const char *const keys[] = {"behavior"};
    size_t vp = 0;
    int found;
    if (mipc_jr_object(jr, pos, keys, 1)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "behavior", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"behavior\"");
    }
    {
        mipc_jr_push(jr, "behavior");
        if (mipc_jr_u8(jr, vp, &out->behavior)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- GpioBehaviorEncoder */

void mipc_gpio_behavior_encoder_to_json(mipc_jw_t *w, const mipc_gpio_behavior_encoder_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "behavior");
    mipc_jw_u8(w, &in->behavior);
    mipc_jw_raw(w, "}", 1);
}

int mipc_gpio_behavior_encoder_from_json(mipc_jr_t *jr, size_t pos, mipc_gpio_behavior_encoder_t *out) {
    static const char *const keys[] = {"behavior"};
    size_t vp = 0;
    int found;
    if (mipc_jr_object(jr, pos, keys, 1)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "behavior", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"behavior\"");
    }
    {
        mipc_jr_push(jr, "behavior");
        if (mipc_jr_u8(jr, vp, &out->behavior)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- GpioBehaviorTimestamp */

void mipc_gpio_behavior_timestamp_to_json(mipc_jw_t *w, const mipc_gpio_behavior_timestamp_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "behavior");
    mipc_jw_u8(w, &in->behavior);
    mipc_jw_raw(w, "}", 1);
}

int mipc_gpio_behavior_timestamp_from_json(mipc_jr_t *jr, size_t pos, mipc_gpio_behavior_timestamp_t *out) {
    static const char *const keys[] = {"behavior"};
    size_t vp = 0;
    int found;
    if (mipc_jr_object(jr, pos, keys, 1)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "behavior", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"behavior\"");
    }
    {
        mipc_jr_push(jr, "behavior");
        if (mipc_jr_u8(jr, vp, &out->behavior)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- GpioBehaviorUart */

void mipc_gpio_behavior_uart_to_json(mipc_jw_t *w, const mipc_gpio_behavior_uart_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "behavior");
    mipc_jw_u8(w, &in->behavior);
    mipc_jw_raw(w, "}", 1);
}

int mipc_gpio_behavior_uart_from_json(mipc_jr_t *jr, size_t pos, mipc_gpio_behavior_uart_t *out) {
    static const char *const keys[] = {"behavior"};
    size_t vp = 0;
    int found;
    if (mipc_jr_object(jr, pos, keys, 1)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "behavior", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"behavior\"");
    }
    {
        mipc_jr_push(jr, "behavior");
        if (mipc_jr_u8(jr, vp, &out->behavior)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- Gx5BasicStatus */

void mipc_gx5_basic_status_to_json(mipc_jw_t *w, const mipc_gx5_basic_status_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "status_flags");
    mipc_jw_u32(w, &in->status_flags);
    mipc_jw_key(w, &first, "system_state");
    mipc_jw_u16(w, &in->system_state);
    mipc_jw_key(w, &first, "system_timer");
    mipc_jw_u32(w, &in->system_timer);
    mipc_jw_raw(w, "}", 1);
}

int mipc_gx5_basic_status_from_json(mipc_jr_t *jr, size_t pos, mipc_gx5_basic_status_t *out) {
    static const char *const keys[] = {"status_flags", "system_state", "system_timer"};
    size_t vp = 0;
    int found;
    if (mipc_jr_object(jr, pos, keys, 3)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "status_flags", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"status_flags\"");
    }
    {
        mipc_jr_push(jr, "status_flags");
        if (mipc_jr_u32(jr, vp, &out->status_flags)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "system_state", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"system_state\"");
    }
    {
        mipc_jr_push(jr, "system_state");
        if (mipc_jr_u16(jr, vp, &out->system_state)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "system_timer", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"system_timer\"");
    }
    {
        mipc_jr_push(jr, "system_timer");
        if (mipc_jr_u32(jr, vp, &out->system_timer)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- Gx5DiagnosticStatus */

void mipc_gx5_diagnostic_status_to_json(mipc_jw_t *w, const mipc_gx5_diagnostic_status_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "status_flags");
    mipc_jw_u32(w, &in->status_flags);
    mipc_jw_key(w, &first, "system_state");
    mipc_jw_u16(w, &in->system_state);
    mipc_jw_key(w, &first, "system_timer");
    mipc_jw_u32(w, &in->system_timer);
    mipc_jw_key(w, &first, "gnss_power_state");
    mipc_jw_u8(w, &in->gnss_power_state);
    mipc_jw_key(w, &first, "pps_pulse_count");
    mipc_jw_u32(w, &in->pps_pulse_count);
    mipc_jw_key(w, &first, "last_pps_time");
    mipc_jw_u32(w, &in->last_pps_time);
    mipc_jw_key(w, &first, "imu_stream_enabled");
    mipc_jw_u8(w, &in->imu_stream_enabled);
    mipc_jw_key(w, &first, "gnss_stream_enabled");
    mipc_jw_u8(w, &in->gnss_stream_enabled);
    mipc_jw_key(w, &first, "filter_stream_enabled");
    mipc_jw_u8(w, &in->filter_stream_enabled);
    mipc_jw_key(w, &first, "imu_dropped_packets");
    mipc_jw_u32(w, &in->imu_dropped_packets);
    mipc_jw_key(w, &first, "gnss_dropped_packets");
    mipc_jw_u32(w, &in->gnss_dropped_packets);
    mipc_jw_key(w, &first, "filter_dropped_packets");
    mipc_jw_u32(w, &in->filter_dropped_packets);
    mipc_jw_key(w, &first, "com_bytes_written");
    mipc_jw_u32(w, &in->com_bytes_written);
    mipc_jw_key(w, &first, "com_bytes_read");
    mipc_jw_u32(w, &in->com_bytes_read);
    mipc_jw_key(w, &first, "com_write_overruns");
    mipc_jw_u32(w, &in->com_write_overruns);
    mipc_jw_key(w, &first, "imu_parse_errors");
    mipc_jw_u32(w, &in->imu_parse_errors);
    mipc_jw_key(w, &first, "imu_messages_read");
    mipc_jw_u32(w, &in->imu_messages_read);
    mipc_jw_key(w, &first, "last_imu_message_time");
    mipc_jw_u32(w, &in->last_imu_message_time);
    mipc_jw_key(w, &first, "gnss_parse_errors");
    mipc_jw_u32(w, &in->gnss_parse_errors);
    mipc_jw_key(w, &first, "gnss_messages_read");
    mipc_jw_u32(w, &in->gnss_messages_read);
    mipc_jw_key(w, &first, "last_gnss_message_time");
    mipc_jw_u32(w, &in->last_gnss_message_time);
    mipc_jw_raw(w, "}", 1);
}

int mipc_gx5_diagnostic_status_from_json(mipc_jr_t *jr, size_t pos, mipc_gx5_diagnostic_status_t *out) {
    static const char *const keys[] = {
        "status_flags",          "system_state",          "system_timer",         "gnss_power_state",
        "pps_pulse_count",       "last_pps_time",         "imu_stream_enabled",   "gnss_stream_enabled",
        "filter_stream_enabled", "imu_dropped_packets",   "gnss_dropped_packets", "filter_dropped_packets",
        "com_bytes_written",     "com_bytes_read",        "com_write_overruns",   "imu_parse_errors",
        "imu_messages_read",     "last_imu_message_time", "gnss_parse_errors",    "gnss_messages_read",
        "last_gnss_message_time"};
    size_t vp = 0;
    int found;
    if (mipc_jr_object(jr, pos, keys, 21)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "status_flags", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"status_flags\"");
    }
    {
        mipc_jr_push(jr, "status_flags");
        if (mipc_jr_u32(jr, vp, &out->status_flags)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "system_state", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"system_state\"");
    }
    {
        mipc_jr_push(jr, "system_state");
        if (mipc_jr_u16(jr, vp, &out->system_state)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "system_timer", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"system_timer\"");
    }
    {
        mipc_jr_push(jr, "system_timer");
        if (mipc_jr_u32(jr, vp, &out->system_timer)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "gnss_power_state", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"gnss_power_state\"");
    }
    {
        mipc_jr_push(jr, "gnss_power_state");
        if (mipc_jr_u8(jr, vp, &out->gnss_power_state)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "pps_pulse_count", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"pps_pulse_count\"");
    }
    {
        mipc_jr_push(jr, "pps_pulse_count");
        if (mipc_jr_u32(jr, vp, &out->pps_pulse_count)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "last_pps_time", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"last_pps_time\"");
    }
    {
        mipc_jr_push(jr, "last_pps_time");
        if (mipc_jr_u32(jr, vp, &out->last_pps_time)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "imu_stream_enabled", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"imu_stream_enabled\"");
    }
    {
        mipc_jr_push(jr, "imu_stream_enabled");
        if (mipc_jr_u8(jr, vp, &out->imu_stream_enabled)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "gnss_stream_enabled", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"gnss_stream_enabled\"");
    }
    {
        mipc_jr_push(jr, "gnss_stream_enabled");
        if (mipc_jr_u8(jr, vp, &out->gnss_stream_enabled)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "filter_stream_enabled", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"filter_stream_enabled\"");
    }
    {
        mipc_jr_push(jr, "filter_stream_enabled");
        if (mipc_jr_u8(jr, vp, &out->filter_stream_enabled)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "imu_dropped_packets", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"imu_dropped_packets\"");
    }
    {
        mipc_jr_push(jr, "imu_dropped_packets");
        if (mipc_jr_u32(jr, vp, &out->imu_dropped_packets)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "gnss_dropped_packets", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"gnss_dropped_packets\"");
    }
    {
        mipc_jr_push(jr, "gnss_dropped_packets");
        if (mipc_jr_u32(jr, vp, &out->gnss_dropped_packets)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "filter_dropped_packets", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"filter_dropped_packets\"");
    }
    {
        mipc_jr_push(jr, "filter_dropped_packets");
        if (mipc_jr_u32(jr, vp, &out->filter_dropped_packets)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "com_bytes_written", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"com_bytes_written\"");
    }
    {
        mipc_jr_push(jr, "com_bytes_written");
        if (mipc_jr_u32(jr, vp, &out->com_bytes_written)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "com_bytes_read", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"com_bytes_read\"");
    }
    {
        mipc_jr_push(jr, "com_bytes_read");
        if (mipc_jr_u32(jr, vp, &out->com_bytes_read)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "com_write_overruns", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"com_write_overruns\"");
    }
    {
        mipc_jr_push(jr, "com_write_overruns");
        if (mipc_jr_u32(jr, vp, &out->com_write_overruns)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "imu_parse_errors", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"imu_parse_errors\"");
    }
    {
        mipc_jr_push(jr, "imu_parse_errors");
        if (mipc_jr_u32(jr, vp, &out->imu_parse_errors)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "imu_messages_read", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"imu_messages_read\"");
    }
    {
        mipc_jr_push(jr, "imu_messages_read");
        if (mipc_jr_u32(jr, vp, &out->imu_messages_read)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "last_imu_message_time", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"last_imu_message_time\"");
    }
    {
        mipc_jr_push(jr, "last_imu_message_time");
        if (mipc_jr_u32(jr, vp, &out->last_imu_message_time)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "gnss_parse_errors", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"gnss_parse_errors\"");
    }
    {
        mipc_jr_push(jr, "gnss_parse_errors");
        if (mipc_jr_u32(jr, vp, &out->gnss_parse_errors)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "gnss_messages_read", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"gnss_messages_read\"");
    }
    {
        mipc_jr_push(jr, "gnss_messages_read");
        if (mipc_jr_u32(jr, vp, &out->gnss_messages_read)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "last_gnss_message_time", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"last_gnss_message_time\"");
    }
    {
        mipc_jr_push(jr, "last_gnss_message_time");
        if (mipc_jr_u32(jr, vp, &out->last_gnss_message_time)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- Gx5PollDescriptor */

void mipc_gx5_poll_descriptor_to_json(mipc_jw_t *w, const mipc_gx5_poll_descriptor_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "descriptor");
    mipc_jw_u8(w, &in->descriptor);
    mipc_jw_key(w, &first, "reserved");
    mipc_jw_u16(w, &in->reserved);
    mipc_jw_raw(w, "}", 1);
}

int mipc_gx5_poll_descriptor_from_json(mipc_jr_t *jr, size_t pos, mipc_gx5_poll_descriptor_t *out) {
    static const char *const keys[] = {"descriptor", "reserved"};
    size_t vp = 0;
    int found;
    if (mipc_jr_object(jr, pos, keys, 2)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "descriptor", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"descriptor\"");
    }
    {
        mipc_jr_push(jr, "descriptor");
        if (mipc_jr_u8(jr, vp, &out->descriptor)) {
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
        if (mipc_jr_u16(jr, vp, &out->reserved)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- NmeaMessage */

void mipc_nmea_message_to_json(mipc_jw_t *w, const mipc_nmea_message_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "message_id");
    mipc_jw_u8(w, &in->message_id);
    mipc_jw_key(w, &first, "talker_id");
    mipc_jw_u8(w, &in->talker_id);
    mipc_jw_key(w, &first, "source_desc_set");
    mipc_jw_u8(w, &in->source_desc_set);
    mipc_jw_key(w, &first, "decimation");
    mipc_jw_u16(w, &in->decimation);
    mipc_jw_raw(w, "}", 1);
}

int mipc_nmea_message_from_json(mipc_jr_t *jr, size_t pos, mipc_nmea_message_t *out) {
    static const char *const keys[] = {"message_id", "talker_id", "source_desc_set", "decimation"};
    size_t vp = 0;
    int found;
    if (mipc_jr_object(jr, pos, keys, 4)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "message_id", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"message_id\"");
    }
    {
        mipc_jr_push(jr, "message_id");
        if (mipc_jr_u8(jr, vp, &out->message_id)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "talker_id", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"talker_id\"");
    }
    {
        mipc_jr_push(jr, "talker_id");
        if (mipc_jr_u8(jr, vp, &out->talker_id)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "source_desc_set", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"source_desc_set\"");
    }
    {
        mipc_jr_push(jr, "source_desc_set");
        if (mipc_jr_u8(jr, vp, &out->source_desc_set)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "decimation", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"decimation\"");
    }
    {
        mipc_jr_push(jr, "decimation");
        if (mipc_jr_u16(jr, vp, &out->decimation)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- SensorRangeEntry */

void mipc_sensor_range_entry_to_json(mipc_jw_t *w, const mipc_sensor_range_entry_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "setting");
    mipc_jw_u8(w, &in->setting);
    mipc_jw_key(w, &first, "range");
    mipc_jw_f32(w, &in->range);
    mipc_jw_raw(w, "}", 1);
}

int mipc_sensor_range_entry_from_json(mipc_jr_t *jr, size_t pos, mipc_sensor_range_entry_t *out) {
    static const char *const keys[] = {"setting", "range"};
    size_t vp = 0;
    int found;
    if (mipc_jr_object(jr, pos, keys, 2)) {
        return -1;
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
    found = mipc_jr_get(jr, pos, "range", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"range\"");
    }
    {
        mipc_jr_push(jr, "range");
        if (mipc_jr_f32(jr, vp, &out->range)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- SupportedActionType */

void mipc_supported_action_type_to_json(mipc_jw_t *w, const mipc_supported_action_type_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "type");
    mipc_jw_u8(w, &in->type);
    mipc_jw_key(w, &first, "count");
    mipc_jw_u8(w, &in->count);
    mipc_jw_raw(w, "}", 1);
}

int mipc_supported_action_type_from_json(mipc_jr_t *jr, size_t pos, mipc_supported_action_type_t *out) {
    static const char *const keys[] = {"type", "count"};
    size_t vp = 0;
    int found;
    if (mipc_jr_object(jr, pos, keys, 2)) {
        return -1;
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
    return 0;
}

/* ---- SupportedActions */

void mipc_supported_actions_to_json(mipc_jw_t *w, const mipc_supported_actions_t *in) {
    int first = 1;
    size_t i;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "max_instances");
    mipc_jw_u8(w, &in->max_instances);
    mipc_jw_key(w, &first, "num_entries");
    mipc_jw_u8(w, &in->num_entries);
    mipc_jw_key(w, &first, "entries");
    mipc_jw_raw(w, "[", 1);
    for (i = 0; i < (size_t)in->num_entries && i < 125; i++) {
        mipc_jw_sep(w, i);
        mipc_supported_action_type_to_json(w, &in->entries[i]);
    }
    mipc_jw_raw(w, "]", 1);
    mipc_jw_raw(w, "}", 1);
}

int mipc_supported_actions_from_json(mipc_jr_t *jr, size_t pos, mipc_supported_actions_t *out) {
    static const char *const keys[] = {"max_instances", "num_entries", "entries"};
    size_t vp = 0;
    int found;
    size_t i;
    size_t it = 0;
    size_t ep = 0;
    if (mipc_jr_object(jr, pos, keys, 3)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "max_instances", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"max_instances\"");
    }
    {
        mipc_jr_push(jr, "max_instances");
        if (mipc_jr_u8(jr, vp, &out->max_instances)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "num_entries", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"num_entries\"");
    }
    {
        mipc_jr_push(jr, "num_entries");
        if (mipc_jr_u8(jr, vp, &out->num_entries)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "entries", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"entries\"");
    }
    {
        mipc_jr_push(jr, "entries");
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
            if (i >= 125) {
                return mipc_jr_fail(jr, "more than 125 elements");
            }
            mipc_jr_index(jr, i);
            if (mipc_supported_action_type_from_json(jr, ep, &out->entries[i])) {
                return -1;
            }
        }
        mipc_jr_index(jr, SIZE_MAX);
        if (i != (size_t)out->num_entries) {
            return mipc_jr_fail(jr, "%zu elements but num_entries is %zu", i, (size_t)out->num_entries);
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- SupportedTriggerType */

void mipc_supported_trigger_type_to_json(mipc_jw_t *w, const mipc_supported_trigger_type_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "type");
    mipc_jw_u8(w, &in->type);
    mipc_jw_key(w, &first, "count");
    mipc_jw_u8(w, &in->count);
    mipc_jw_raw(w, "}", 1);
}

int mipc_supported_trigger_type_from_json(mipc_jr_t *jr, size_t pos, mipc_supported_trigger_type_t *out) {
    static const char *const keys[] = {"type", "count"};
    size_t vp = 0;
    int found;
    if (mipc_jr_object(jr, pos, keys, 2)) {
        return -1;
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
    return 0;
}

/* ---- SupportedTriggers */

void mipc_supported_triggers_to_json(mipc_jw_t *w, const mipc_supported_triggers_t *in) {
    int first = 1;
    size_t i;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "max_instances");
    mipc_jw_u8(w, &in->max_instances);
    mipc_jw_key(w, &first, "num_entries");
    mipc_jw_u8(w, &in->num_entries);
    mipc_jw_key(w, &first, "entries");
    mipc_jw_raw(w, "[", 1);
    for (i = 0; i < (size_t)in->num_entries && i < 125; i++) {
        mipc_jw_sep(w, i);
        mipc_supported_trigger_type_to_json(w, &in->entries[i]);
    }
    mipc_jw_raw(w, "]", 1);
    mipc_jw_raw(w, "}", 1);
}

int mipc_supported_triggers_from_json(mipc_jr_t *jr, size_t pos, mipc_supported_triggers_t *out) {
    static const char *const keys[] = {"max_instances", "num_entries", "entries"};
    size_t vp = 0;
    int found;
    size_t i;
    size_t it = 0;
    size_t ep = 0;
    if (mipc_jr_object(jr, pos, keys, 3)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "max_instances", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"max_instances\"");
    }
    {
        mipc_jr_push(jr, "max_instances");
        if (mipc_jr_u8(jr, vp, &out->max_instances)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "num_entries", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"num_entries\"");
    }
    {
        mipc_jr_push(jr, "num_entries");
        if (mipc_jr_u8(jr, vp, &out->num_entries)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "entries", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"entries\"");
    }
    {
        mipc_jr_push(jr, "entries");
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
            if (i >= 125) {
                return mipc_jr_fail(jr, "more than 125 elements");
            }
            mipc_jr_index(jr, i);
            if (mipc_supported_trigger_type_from_json(jr, ep, &out->entries[i])) {
                return -1;
            }
        }
        mipc_jr_index(jr, SIZE_MAX);
        if (i != (size_t)out->num_entries) {
            return mipc_jr_fail(jr, "%zu elements but num_entries is %zu", i, (size_t)out->num_entries);
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- ThresholdParams */

void mipc_threshold_params_to_json(mipc_jw_t *w, const mipc_threshold_params_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "desc_set");
    mipc_jw_u8(w, &in->desc_set);
    mipc_jw_key(w, &first, "field_desc");
    mipc_jw_u8(w, &in->field_desc);
    mipc_jw_key(w, &first, "param_id");
    mipc_jw_u8(w, &in->param_id);
    mipc_jw_key(w, &first, "type");
    mipc_jw_u8(w, &in->type);
    mipc_jw_key(w, &first, "low_thres");
    mipc_jw_f64(w, &in->low_thres);
    mipc_jw_key(w, &first, "high_thres");
    mipc_jw_f64(w, &in->high_thres);
    mipc_jw_raw(w, "}", 1);
}

int mipc_threshold_params_from_json(mipc_jr_t *jr, size_t pos, mipc_threshold_params_t *out) {
    static const char *const keys[] = {"desc_set", "field_desc", "param_id",
                                       "type",     "low_thres",  "high_thres"};
    size_t vp = 0;
    int found;
    if (mipc_jr_object(jr, pos, keys, 6)) {
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
    found = mipc_jr_get(jr, pos, "param_id", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"param_id\"");
    }
    {
        mipc_jr_push(jr, "param_id");
        if (mipc_jr_u8(jr, vp, &out->param_id)) {
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
    found = mipc_jr_get(jr, pos, "low_thres", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"low_thres\"");
    }
    {
        mipc_jr_push(jr, "low_thres");
        if (mipc_jr_f64(jr, vp, &out->low_thres)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "high_thres", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"high_thres\"");
    }
    {
        mipc_jr_push(jr, "high_thres");
        if (mipc_jr_f64(jr, vp, &out->high_thres)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- TriggerGpioParams */

void mipc_trigger_gpio_params_to_json(mipc_jw_t *w, const mipc_trigger_gpio_params_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "pin");
    mipc_jw_u8(w, &in->pin);
    mipc_jw_key(w, &first, "mode");
    mipc_jw_u8(w, &in->mode);
    mipc_jw_raw(w, "}", 1);
}

int mipc_trigger_gpio_params_from_json(mipc_jr_t *jr, size_t pos, mipc_trigger_gpio_params_t *out) {
    static const char *const keys[] = {"pin", "mode"};
    size_t vp = 0;
    int found;
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

/* ---- TriggerStatusEntry */

void mipc_trigger_status_entry_to_json(mipc_jw_t *w, const mipc_trigger_status_entry_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "type");
    mipc_jw_u8(w, &in->type);
    mipc_jw_key(w, &first, "status");
    mipc_jw_u8(w, &in->status);
    mipc_jw_raw(w, "}", 1);
}

int mipc_trigger_status_entry_from_json(mipc_jr_t *jr, size_t pos, mipc_trigger_status_entry_t *out) {
    static const char *const keys[] = {"type", "status"};
    size_t vp = 0;
    int found;
    if (mipc_jr_object(jr, pos, keys, 2)) {
        return -1;
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
    found = mipc_jr_get(jr, pos, "status", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"status\"");
    }
    {
        mipc_jr_push(jr, "status");
        if (mipc_jr_u8(jr, vp, &out->status)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- ActionParams (selected by mipc_action_type_t) */

void mipc_action_params_to_json(mipc_jw_t *w, mipc_action_type_t selector, const mipc_action_params_t *in) {
    switch (selector) {
    case MIPC_ACTION_TYPE_GPIO:
        mipc_action_gpio_params_to_json(w, &in->gpio);
        return;
    case MIPC_ACTION_TYPE_MESSAGE:
        mipc_message_params_to_json(w, &in->message);
        return;
    default:
        (void)in;
        mipc_jw_lit(w, "null");
        return;
    }
}

int mipc_action_params_from_json(mipc_jr_t *jr, size_t pos, mipc_action_type_t selector,
                                 mipc_action_params_t *out) {
    switch (selector) {
    case MIPC_ACTION_TYPE_NONE:
        return mipc_jr_null(jr, pos);
    case MIPC_ACTION_TYPE_GPIO:
        return mipc_action_gpio_params_from_json(jr, pos, &out->gpio);
    case MIPC_ACTION_TYPE_MESSAGE:
        return mipc_message_params_from_json(jr, pos, &out->message);
    default:
        (void)pos;
        (void)out;
        return mipc_jr_fail(jr, "no member for selector value %llu", (unsigned long long)selector);
    }
}

/* ---- AidingFrameRotation (selected by mipc_aiding_frame_format_t) */

void mipc_aiding_frame_rotation_to_json(mipc_jw_t *w, mipc_aiding_frame_format_t selector,
                                        const mipc_aiding_frame_rotation_t *in) {
    switch (selector) {
    case MIPC_AIDING_FRAME_FORMAT_EULER:
        mipc_aiding_frame_euler_to_json(w, &in->euler);
        return;
    case MIPC_AIDING_FRAME_FORMAT_QUATERNION:
        mipc_aiding_frame_quaternion_to_json(w, &in->quaternion);
        return;
    default:
        (void)in;
        mipc_jw_lit(w, "null");
        return;
    }
}

int mipc_aiding_frame_rotation_from_json(mipc_jr_t *jr, size_t pos, mipc_aiding_frame_format_t selector,
                                         mipc_aiding_frame_rotation_t *out) {
    switch (selector) {
    case MIPC_AIDING_FRAME_FORMAT_EULER:
        return mipc_aiding_frame_euler_from_json(jr, pos, &out->euler);
    case MIPC_AIDING_FRAME_FORMAT_QUATERNION:
        return mipc_aiding_frame_quaternion_from_json(jr, pos, &out->quaternion);
    default:
        (void)pos;
        (void)out;
        return mipc_jr_fail(jr, "no member for selector value %llu", (unsigned long long)selector);
    }
}

/* ---- GpioBehavior (selected by mipc_gpio_feature_t) */

void mipc_gpio_behavior_to_json(mipc_jw_t *w, mipc_gpio_feature_t selector, const mipc_gpio_behavior_t *in) {
    switch (selector) {
    case MIPC_GPIO_FEATURE_UNUSED:
        mipc_gpio_behavior_unused_to_json(w, &in->unused);
        return;
    case MIPC_GPIO_FEATURE_GPIO:
        mipc_gpio_behavior_io_to_json(w, &in->gpio);
        return;
    case MIPC_GPIO_FEATURE_PPS:
        mipc_gpio_behavior_pps_to_json(w, &in->pps);
        return;
    case MIPC_GPIO_FEATURE_ENCODER:
        mipc_gpio_behavior_encoder_to_json(w, &in->encoder);
        return;
    case MIPC_GPIO_FEATURE_TIMESTAMP:
        mipc_gpio_behavior_timestamp_to_json(w, &in->timestamp);
        return;
    case MIPC_GPIO_FEATURE_UART:
        mipc_gpio_behavior_uart_to_json(w, &in->uart);
        return;
    default:
        (void)in;
        mipc_jw_lit(w, "null");
        return;
    }
}

int mipc_gpio_behavior_from_json(mipc_jr_t *jr, size_t pos, mipc_gpio_feature_t selector,
                                 mipc_gpio_behavior_t *out) {
    switch (selector) {
    case MIPC_GPIO_FEATURE_UNUSED:
        return mipc_gpio_behavior_unused_from_json(jr, pos, &out->unused);
    case MIPC_GPIO_FEATURE_GPIO:
        return mipc_gpio_behavior_io_from_json(jr, pos, &out->gpio);
    case MIPC_GPIO_FEATURE_PPS:
        return mipc_gpio_behavior_pps_from_json(jr, pos, &out->pps);
    case MIPC_GPIO_FEATURE_ENCODER:
        return mipc_gpio_behavior_encoder_from_json(jr, pos, &out->encoder);
    case MIPC_GPIO_FEATURE_TIMESTAMP:
        return mipc_gpio_behavior_timestamp_from_json(jr, pos, &out->timestamp);
    case MIPC_GPIO_FEATURE_UART:
        return mipc_gpio_behavior_uart_from_json(jr, pos, &out->uart);
    default:
        (void)pos;
        (void)out;
        return mipc_jr_fail(jr, "no member for selector value %llu", (unsigned long long)selector);
    }
}

/* ---- Gx5DeviceStatus (selected by mipc_device_status_selector_t) */

void mipc_gx5_device_status_to_json(mipc_jw_t *w, mipc_device_status_selector_t selector,
                                    const mipc_gx5_device_status_t *in) {
    switch (selector) {
    case MIPC_DEVICE_STATUS_SELECTOR_BASIC:
        mipc_gx5_basic_status_to_json(w, &in->basic);
        return;
    case MIPC_DEVICE_STATUS_SELECTOR_DIAGNOSTIC:
        mipc_gx5_diagnostic_status_to_json(w, &in->diagnostic);
        return;
    default:
        (void)in;
        mipc_jw_lit(w, "null");
        return;
    }
}

int mipc_gx5_device_status_from_json(mipc_jr_t *jr, size_t pos, mipc_device_status_selector_t selector,
                                     mipc_gx5_device_status_t *out) {
    switch (selector) {
    case MIPC_DEVICE_STATUS_SELECTOR_BASIC:
        return mipc_gx5_basic_status_from_json(jr, pos, &out->basic);
    case MIPC_DEVICE_STATUS_SELECTOR_DIAGNOSTIC:
        return mipc_gx5_diagnostic_status_from_json(jr, pos, &out->diagnostic);
    default:
        (void)pos;
        (void)out;
        return mipc_jr_fail(jr, "no member for selector value %llu", (unsigned long long)selector);
    }
}

/* ---- SupportedEventsInfo (selected by mipc_supported_events_query_t) */

void mipc_supported_events_info_to_json(mipc_jw_t *w, mipc_supported_events_query_t selector,
                                        const mipc_supported_events_info_t *in) {
    switch (selector) {
    case MIPC_SUPPORTED_EVENTS_QUERY_TRIGGER_TYPES:
        mipc_supported_triggers_to_json(w, &in->trigger_types);
        return;
    case MIPC_SUPPORTED_EVENTS_QUERY_ACTION_TYPES:
        mipc_supported_actions_to_json(w, &in->action_types);
        return;
    default:
        (void)in;
        mipc_jw_lit(w, "null");
        return;
    }
}

int mipc_supported_events_info_from_json(mipc_jr_t *jr, size_t pos, mipc_supported_events_query_t selector,
                                         mipc_supported_events_info_t *out) {
    switch (selector) {
    case MIPC_SUPPORTED_EVENTS_QUERY_TRIGGER_TYPES:
        return mipc_supported_triggers_from_json(jr, pos, &out->trigger_types);
    case MIPC_SUPPORTED_EVENTS_QUERY_ACTION_TYPES:
        return mipc_supported_actions_from_json(jr, pos, &out->action_types);
    default:
        (void)pos;
        (void)out;
        return mipc_jr_fail(jr, "no member for selector value %llu", (unsigned long long)selector);
    }
}

/* ---- TriggerParams (selected by mipc_trigger_type_t) */

void mipc_trigger_params_to_json(mipc_jw_t *w, mipc_trigger_type_t selector,
                                 const mipc_trigger_params_t *in) {
    switch (selector) {
    case MIPC_TRIGGER_TYPE_GPIO:
        mipc_trigger_gpio_params_to_json(w, &in->gpio);
        return;
    case MIPC_TRIGGER_TYPE_THRESHOLD:
        mipc_threshold_params_to_json(w, &in->threshold);
        return;
    case MIPC_TRIGGER_TYPE_COMBINATION:
        mipc_combination_params_to_json(w, &in->combination);
        return;
    default:
        (void)in;
        mipc_jw_lit(w, "null");
        return;
    }
}

int mipc_trigger_params_from_json(mipc_jr_t *jr, size_t pos, mipc_trigger_type_t selector,
                                  mipc_trigger_params_t *out) {
    switch (selector) {
    case MIPC_TRIGGER_TYPE_NONE:
        return mipc_jr_null(jr, pos);
    case MIPC_TRIGGER_TYPE_GPIO:
        return mipc_trigger_gpio_params_from_json(jr, pos, &out->gpio);
    case MIPC_TRIGGER_TYPE_THRESHOLD:
        return mipc_threshold_params_from_json(jr, pos, &out->threshold);
    case MIPC_TRIGGER_TYPE_COMBINATION:
        return mipc_combination_params_from_json(jr, pos, &out->combination);
    default:
        (void)pos;
        (void)out;
        return mipc_jr_fail(jr, "no member for selector value %llu", (unsigned long long)selector);
    }
}
