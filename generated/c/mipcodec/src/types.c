/* Read/write/JSON functions of the named structs and unions. Generated: do not edit. */
#include "types_internal.h"

#include <string.h>

/* ---- ActionGpioParams */

int mip_action_gpio_params_read(mip_reader_t *r, mip_action_gpio_params_t *out) {
    mip_rd_push(r, "pin");
    if (mip_rd_u8(r, &out->pin)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "mode");
    if (mip_rd_u8(r, &out->mode)) {
        return -1;
    }
    mip_rd_pop(r);
    return 0;
}

mip_status_t mip_action_gpio_params_write(mip_writer_t *w, const mip_action_gpio_params_t *in) {
    mip_status_t st;
    if ((st = mip_wr_u8(w, &in->pin)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_u8(w, &in->mode)) != MIP_OK) {
        return st;
    }
    return MIP_OK;
}

void mip_action_gpio_params_to_json(mip_jw_t *w, const mip_action_gpio_params_t *in) {
    int first = 1;
    mip_jw_raw(w, "{", 1);
    mip_jw_key(w, &first, "pin");
    mip_jw_u8(w, &in->pin);
    mip_jw_key(w, &first, "mode");
    mip_jw_u8(w, &in->mode);
    mip_jw_raw(w, "}", 1);
}

int mip_action_gpio_params_from_json(mip_jr_t *jr, size_t pos, mip_action_gpio_params_t *out) {
    static const char *const keys[] = {"pin", "mode"};
    size_t vp = 0;
    int found;
    if (mip_jr_object(jr, pos, keys, 2)) {
        return -1;
    }
    found = mip_jr_get(jr, pos, "pin", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"pin\"");
    }
    {
        mip_jr_push(jr, "pin");
        if (mip_jr_u8(jr, vp, &out->pin)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "mode", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"mode\"");
    }
    {
        mip_jr_push(jr, "mode");
        if (mip_jr_u8(jr, vp, &out->mode)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    return 0;
}

/* ---- MessageParams */

int mip_message_params_read(mip_reader_t *r, mip_message_params_t *out) {
    size_t i;
    mip_rd_push(r, "desc_set");
    if (mip_rd_u8(r, &out->desc_set)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "decimation");
    if (mip_rd_u16(r, &out->decimation)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "num_fields");
    if (mip_rd_u8(r, &out->num_fields)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "descriptors");
    if (out->num_fields > 12) {
        return mip_rd_count_error(r, (uint64_t)out->num_fields, 12);
    }
    for (i = 0; i < (size_t)out->num_fields; i++) {
        mip_rd_index(r, i);
        if (mip_rd_u8(r, &out->descriptors[i])) {
            return -1;
        }
    }
    mip_rd_pop(r);
    return 0;
}

mip_status_t mip_message_params_write(mip_writer_t *w, const mip_message_params_t *in) {
    mip_status_t st;
    size_t i;
    if ((st = mip_wr_u8(w, &in->desc_set)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_u16(w, &in->decimation)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_u8(w, &in->num_fields)) != MIP_OK) {
        return st;
    }
    if (in->num_fields > 12) {
        return MIP_ERR_INVALID;
    }
    for (i = 0; i < (size_t)in->num_fields; i++) {
        if ((st = mip_wr_u8(w, &in->descriptors[i])) != MIP_OK) {
            return st;
        }
    }
    return MIP_OK;
}

void mip_message_params_to_json(mip_jw_t *w, const mip_message_params_t *in) {
    int first = 1;
    size_t i;
    mip_jw_raw(w, "{", 1);
    mip_jw_key(w, &first, "desc_set");
    mip_jw_u8(w, &in->desc_set);
    mip_jw_key(w, &first, "decimation");
    mip_jw_u16(w, &in->decimation);
    mip_jw_key(w, &first, "num_fields");
    mip_jw_u8(w, &in->num_fields);
    mip_jw_key(w, &first, "descriptors");
    mip_jw_raw(w, "[", 1);
    for (i = 0; i < (size_t)in->num_fields && i < 12; i++) {
        mip_jw_sep(w, i);
        mip_jw_u8(w, &in->descriptors[i]);
    }
    mip_jw_raw(w, "]", 1);
    mip_jw_raw(w, "}", 1);
}

int mip_message_params_from_json(mip_jr_t *jr, size_t pos, mip_message_params_t *out) {
    static const char *const keys[] = {"desc_set", "decimation", "num_fields", "descriptors"};
    size_t vp = 0;
    int found;
    size_t i;
    size_t it = 0;
    size_t ep = 0;
    if (mip_jr_object(jr, pos, keys, 4)) {
        return -1;
    }
    found = mip_jr_get(jr, pos, "desc_set", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"desc_set\"");
    }
    {
        mip_jr_push(jr, "desc_set");
        if (mip_jr_u8(jr, vp, &out->desc_set)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "decimation", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"decimation\"");
    }
    {
        mip_jr_push(jr, "decimation");
        if (mip_jr_u16(jr, vp, &out->decimation)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "num_fields", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"num_fields\"");
    }
    {
        mip_jr_push(jr, "num_fields");
        if (mip_jr_u8(jr, vp, &out->num_fields)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "descriptors", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"descriptors\"");
    }
    {
        mip_jr_push(jr, "descriptors");
        if (mip_jr_array(jr, vp, &it)) {
            return -1;
        }
        for (i = 0;; i++) {
            int more = mip_jr_next(jr, &it, &ep);
            if (more < 0) {
                return -1;
            }
            if (!more) {
                break;
            }
            if (i >= 12) {
                return mip_jr_fail(jr, "more than 12 elements");
            }
            mip_jr_index(jr, i);
            if (mip_jr_u8(jr, ep, &out->descriptors[i])) {
                return -1;
            }
        }
        mip_jr_index(jr, SIZE_MAX);
        if (i != (size_t)out->num_fields) {
            return mip_jr_fail(jr, "%zu elements but num_fields is %zu", i, (size_t)out->num_fields);
        }
        mip_jr_pop(jr);
    }
    return 0;
}

/* ---- ActionStatusEntry */

int mip_action_status_entry_read(mip_reader_t *r, mip_action_status_entry_t *out) {
    mip_rd_push(r, "action_type");
    if (mip_rd_u8(r, &out->action_type)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "trigger_id");
    if (mip_rd_u8(r, &out->trigger_id)) {
        return -1;
    }
    mip_rd_pop(r);
    return 0;
}

mip_status_t mip_action_status_entry_write(mip_writer_t *w, const mip_action_status_entry_t *in) {
    mip_status_t st;
    if ((st = mip_wr_u8(w, &in->action_type)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_u8(w, &in->trigger_id)) != MIP_OK) {
        return st;
    }
    return MIP_OK;
}

void mip_action_status_entry_to_json(mip_jw_t *w, const mip_action_status_entry_t *in) {
    int first = 1;
    mip_jw_raw(w, "{", 1);
    mip_jw_key(w, &first, "action_type");
    mip_jw_u8(w, &in->action_type);
    mip_jw_key(w, &first, "trigger_id");
    mip_jw_u8(w, &in->trigger_id);
    mip_jw_raw(w, "}", 1);
}

int mip_action_status_entry_from_json(mip_jr_t *jr, size_t pos, mip_action_status_entry_t *out) {
    static const char *const keys[] = {"action_type", "trigger_id"};
    size_t vp = 0;
    int found;
    if (mip_jr_object(jr, pos, keys, 2)) {
        return -1;
    }
    found = mip_jr_get(jr, pos, "action_type", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"action_type\"");
    }
    {
        mip_jr_push(jr, "action_type");
        if (mip_jr_u8(jr, vp, &out->action_type)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "trigger_id", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"trigger_id\"");
    }
    {
        mip_jr_push(jr, "trigger_id");
        if (mip_jr_u8(jr, vp, &out->trigger_id)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    return 0;
}

/* ---- AidingFrameEuler */

int mip_aiding_frame_euler_read(mip_reader_t *r, mip_aiding_frame_euler_t *out) {
    size_t i;
    mip_rd_push(r, "euler");
    for (i = 0; i < 3; i++) {
        mip_rd_index(r, i);
        if (mip_rd_f32(r, &out->euler[i])) {
            return -1;
        }
    }
    mip_rd_pop(r);
    return 0;
}

mip_status_t mip_aiding_frame_euler_write(mip_writer_t *w, const mip_aiding_frame_euler_t *in) {
    mip_status_t st;
    size_t i;
    for (i = 0; i < 3; i++) {
        if ((st = mip_wr_f32(w, &in->euler[i])) != MIP_OK) {
            return st;
        }
    }
    return MIP_OK;
}

void mip_aiding_frame_euler_to_json(mip_jw_t *w, const mip_aiding_frame_euler_t *in) {
    int first = 1;
    size_t i;
    mip_jw_raw(w, "{", 1);
    mip_jw_key(w, &first, "euler");
    mip_jw_raw(w, "[", 1);
    for (i = 0; i < 3; i++) {
        mip_jw_sep(w, i);
        mip_jw_f32(w, &in->euler[i]);
    }
    mip_jw_raw(w, "]", 1);
    mip_jw_raw(w, "}", 1);
}

int mip_aiding_frame_euler_from_json(mip_jr_t *jr, size_t pos, mip_aiding_frame_euler_t *out) {
    static const char *const keys[] = {"euler"};
    size_t vp = 0;
    int found;
    size_t i;
    size_t it = 0;
    size_t ep = 0;
    if (mip_jr_object(jr, pos, keys, 1)) {
        return -1;
    }
    found = mip_jr_get(jr, pos, "euler", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"euler\"");
    }
    {
        mip_jr_push(jr, "euler");
        if (mip_jr_array(jr, vp, &it)) {
            return -1;
        }
        for (i = 0;; i++) {
            int more = mip_jr_next(jr, &it, &ep);
            if (more < 0) {
                return -1;
            }
            if (!more) {
                break;
            }
            if (i >= 3) {
                return mip_jr_fail(jr, "more than 3 elements");
            }
            mip_jr_index(jr, i);
            if (mip_jr_f32(jr, ep, &out->euler[i])) {
                return -1;
            }
        }
        mip_jr_index(jr, SIZE_MAX);
        if (i != 3) {
            return mip_jr_fail(jr, "expected 3 elements, got %zu", i);
        }
        mip_jr_pop(jr);
    }
    return 0;
}

/* ---- AidingFrameQuaternion */

int mip_aiding_frame_quaternion_read(mip_reader_t *r, mip_aiding_frame_quaternion_t *out) {
    size_t i;
    mip_rd_push(r, "quaternion");
    for (i = 0; i < 4; i++) {
        mip_rd_index(r, i);
        if (mip_rd_f32(r, &out->quaternion[i])) {
            return -1;
        }
    }
    mip_rd_pop(r);
    return 0;
}

mip_status_t mip_aiding_frame_quaternion_write(mip_writer_t *w, const mip_aiding_frame_quaternion_t *in) {
    mip_status_t st;
    size_t i;
    for (i = 0; i < 4; i++) {
        if ((st = mip_wr_f32(w, &in->quaternion[i])) != MIP_OK) {
            return st;
        }
    }
    return MIP_OK;
}

void mip_aiding_frame_quaternion_to_json(mip_jw_t *w, const mip_aiding_frame_quaternion_t *in) {
    int first = 1;
    size_t i;
    mip_jw_raw(w, "{", 1);
    mip_jw_key(w, &first, "quaternion");
    mip_jw_raw(w, "[", 1);
    for (i = 0; i < 4; i++) {
        mip_jw_sep(w, i);
        mip_jw_f32(w, &in->quaternion[i]);
    }
    mip_jw_raw(w, "]", 1);
    mip_jw_raw(w, "}", 1);
}

int mip_aiding_frame_quaternion_from_json(mip_jr_t *jr, size_t pos, mip_aiding_frame_quaternion_t *out) {
    static const char *const keys[] = {"quaternion"};
    size_t vp = 0;
    int found;
    size_t i;
    size_t it = 0;
    size_t ep = 0;
    if (mip_jr_object(jr, pos, keys, 1)) {
        return -1;
    }
    found = mip_jr_get(jr, pos, "quaternion", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"quaternion\"");
    }
    {
        mip_jr_push(jr, "quaternion");
        if (mip_jr_array(jr, vp, &it)) {
            return -1;
        }
        for (i = 0;; i++) {
            int more = mip_jr_next(jr, &it, &ep);
            if (more < 0) {
                return -1;
            }
            if (!more) {
                break;
            }
            if (i >= 4) {
                return mip_jr_fail(jr, "more than 4 elements");
            }
            mip_jr_index(jr, i);
            if (mip_jr_f32(jr, ep, &out->quaternion[i])) {
                return -1;
            }
        }
        mip_jr_index(jr, SIZE_MAX);
        if (i != 4) {
            return mip_jr_fail(jr, "expected 4 elements, got %zu", i);
        }
        mip_jr_pop(jr);
    }
    return 0;
}

/* ---- AidingTime */

int mip_aiding_time_read(mip_reader_t *r, mip_aiding_time_t *out) {
    mip_rd_push(r, "timebase");
    if (mip_rd_u8(r, &out->timebase)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "reserved");
    if (mip_rd_u8(r, &out->reserved)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "nanoseconds");
    if (mip_rd_u64(r, &out->nanoseconds)) {
        return -1;
    }
    mip_rd_pop(r);
    return 0;
}

mip_status_t mip_aiding_time_write(mip_writer_t *w, const mip_aiding_time_t *in) {
    mip_status_t st;
    if ((st = mip_wr_u8(w, &in->timebase)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_u8(w, &in->reserved)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_u64(w, &in->nanoseconds)) != MIP_OK) {
        return st;
    }
    return MIP_OK;
}

void mip_aiding_time_to_json(mip_jw_t *w, const mip_aiding_time_t *in) {
    int first = 1;
    mip_jw_raw(w, "{", 1);
    mip_jw_key(w, &first, "timebase");
    mip_jw_u8(w, &in->timebase);
    mip_jw_key(w, &first, "reserved");
    mip_jw_u8(w, &in->reserved);
    mip_jw_key(w, &first, "nanoseconds");
    mip_jw_u64(w, &in->nanoseconds);
    mip_jw_raw(w, "}", 1);
}

int mip_aiding_time_from_json(mip_jr_t *jr, size_t pos, mip_aiding_time_t *out) {
    static const char *const keys[] = {"timebase", "reserved", "nanoseconds"};
    size_t vp = 0;
    int found;
    if (mip_jr_object(jr, pos, keys, 3)) {
        return -1;
    }
    found = mip_jr_get(jr, pos, "timebase", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"timebase\"");
    }
    {
        mip_jr_push(jr, "timebase");
        if (mip_jr_u8(jr, vp, &out->timebase)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "reserved", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"reserved\"");
    }
    {
        mip_jr_push(jr, "reserved");
        if (mip_jr_u8(jr, vp, &out->reserved)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "nanoseconds", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"nanoseconds\"");
    }
    {
        mip_jr_push(jr, "nanoseconds");
        if (mip_jr_u64(jr, vp, &out->nanoseconds)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    return 0;
}

/* ---- CombinationParams */

int mip_combination_params_read(mip_reader_t *r, mip_combination_params_t *out) {
    size_t i;
    mip_rd_push(r, "logic_table");
    if (mip_rd_u16(r, &out->logic_table)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "input_triggers");
    for (i = 0; i < 4; i++) {
        mip_rd_index(r, i);
        if (mip_rd_u8(r, &out->input_triggers[i])) {
            return -1;
        }
    }
    mip_rd_pop(r);
    return 0;
}

mip_status_t mip_combination_params_write(mip_writer_t *w, const mip_combination_params_t *in) {
    mip_status_t st;
    size_t i;
    if ((st = mip_wr_u16(w, &in->logic_table)) != MIP_OK) {
        return st;
    }
    for (i = 0; i < 4; i++) {
        if ((st = mip_wr_u8(w, &in->input_triggers[i])) != MIP_OK) {
            return st;
        }
    }
    return MIP_OK;
}

void mip_combination_params_to_json(mip_jw_t *w, const mip_combination_params_t *in) {
    int first = 1;
    size_t i;
    mip_jw_raw(w, "{", 1);
    mip_jw_key(w, &first, "logic_table");
    mip_jw_u16(w, &in->logic_table);
    mip_jw_key(w, &first, "input_triggers");
    mip_jw_raw(w, "[", 1);
    for (i = 0; i < 4; i++) {
        mip_jw_sep(w, i);
        mip_jw_u8(w, &in->input_triggers[i]);
    }
    mip_jw_raw(w, "]", 1);
    mip_jw_raw(w, "}", 1);
}

int mip_combination_params_from_json(mip_jr_t *jr, size_t pos, mip_combination_params_t *out) {
    static const char *const keys[] = {"logic_table", "input_triggers"};
    size_t vp = 0;
    int found;
    size_t i;
    size_t it = 0;
    size_t ep = 0;
    if (mip_jr_object(jr, pos, keys, 2)) {
        return -1;
    }
    found = mip_jr_get(jr, pos, "logic_table", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"logic_table\"");
    }
    {
        mip_jr_push(jr, "logic_table");
        if (mip_jr_u16(jr, vp, &out->logic_table)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "input_triggers", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"input_triggers\"");
    }
    {
        mip_jr_push(jr, "input_triggers");
        if (mip_jr_array(jr, vp, &it)) {
            return -1;
        }
        for (i = 0;; i++) {
            int more = mip_jr_next(jr, &it, &ep);
            if (more < 0) {
                return -1;
            }
            if (!more) {
                break;
            }
            if (i >= 4) {
                return mip_jr_fail(jr, "more than 4 elements");
            }
            mip_jr_index(jr, i);
            if (mip_jr_u8(jr, ep, &out->input_triggers[i])) {
                return -1;
            }
        }
        mip_jr_index(jr, SIZE_MAX);
        if (i != 4) {
            return mip_jr_fail(jr, "expected 4 elements, got %zu", i);
        }
        mip_jr_pop(jr);
    }
    return 0;
}

/* ---- ConstellationSettings */

int mip_constellation_settings_read(mip_reader_t *r, mip_constellation_settings_t *out) {
    mip_rd_push(r, "constellation_id");
    if (mip_rd_u8(r, &out->constellation_id)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "enable");
    if (mip_rd_u8(r, &out->enable)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "reserved_channels");
    if (mip_rd_u8(r, &out->reserved_channels)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "max_channels");
    if (mip_rd_u8(r, &out->max_channels)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "option_flags");
    if (mip_rd_u16(r, &out->option_flags)) {
        return -1;
    }
    mip_rd_pop(r);
    return 0;
}

mip_status_t mip_constellation_settings_write(mip_writer_t *w, const mip_constellation_settings_t *in) {
    mip_status_t st;
    if ((st = mip_wr_u8(w, &in->constellation_id)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_u8(w, &in->enable)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_u8(w, &in->reserved_channels)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_u8(w, &in->max_channels)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_u16(w, &in->option_flags)) != MIP_OK) {
        return st;
    }
    return MIP_OK;
}

void mip_constellation_settings_to_json(mip_jw_t *w, const mip_constellation_settings_t *in) {
    int first = 1;
    mip_jw_raw(w, "{", 1);
    mip_jw_key(w, &first, "constellation_id");
    mip_jw_u8(w, &in->constellation_id);
    mip_jw_key(w, &first, "enable");
    mip_jw_u8(w, &in->enable);
    mip_jw_key(w, &first, "reserved_channels");
    mip_jw_u8(w, &in->reserved_channels);
    mip_jw_key(w, &first, "max_channels");
    mip_jw_u8(w, &in->max_channels);
    mip_jw_key(w, &first, "option_flags");
    mip_jw_u16(w, &in->option_flags);
    mip_jw_raw(w, "}", 1);
}

int mip_constellation_settings_from_json(mip_jr_t *jr, size_t pos, mip_constellation_settings_t *out) {
    static const char *const keys[] = {"constellation_id", "enable", "reserved_channels", "max_channels",
                                       "option_flags"};
    size_t vp = 0;
    int found;
    if (mip_jr_object(jr, pos, keys, 5)) {
        return -1;
    }
    found = mip_jr_get(jr, pos, "constellation_id", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"constellation_id\"");
    }
    {
        mip_jr_push(jr, "constellation_id");
        if (mip_jr_u8(jr, vp, &out->constellation_id)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "enable", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"enable\"");
    }
    {
        mip_jr_push(jr, "enable");
        if (mip_jr_u8(jr, vp, &out->enable)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "reserved_channels", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"reserved_channels\"");
    }
    {
        mip_jr_push(jr, "reserved_channels");
        if (mip_jr_u8(jr, vp, &out->reserved_channels)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "max_channels", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"max_channels\"");
    }
    {
        mip_jr_push(jr, "max_channels");
        if (mip_jr_u8(jr, vp, &out->max_channels)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "option_flags", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"option_flags\"");
    }
    {
        mip_jr_push(jr, "option_flags");
        if (mip_jr_u16(jr, vp, &out->option_flags)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    return 0;
}

/* ---- Cv7ContinuousBit */

int mip_cv7_continuous_bit_read(mip_reader_t *r, mip_cv7_continuous_bit_t *out) {
    mip_rd_push(r, "system_byte_0");
    if (mip_rd_u8(r, &out->system_byte_0)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "reserved_byte_1");
    if (mip_rd_u8(r, &out->reserved_byte_1)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "system_byte_2");
    if (mip_rd_u8(r, &out->system_byte_2)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "system_byte_3");
    if (mip_rd_u8(r, &out->system_byte_3)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "imu_byte_4");
    if (mip_rd_u8(r, &out->imu_byte_4)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "imu_byte_5");
    if (mip_rd_u8(r, &out->imu_byte_5)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "imu_byte_6");
    if (mip_rd_u8(r, &out->imu_byte_6)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "imu_byte_7");
    if (mip_rd_u8(r, &out->imu_byte_7)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "nav_byte_8");
    if (mip_rd_u8(r, &out->nav_byte_8)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "reserved_byte_9");
    if (mip_rd_u8(r, &out->reserved_byte_9)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "reserved_byte_10");
    if (mip_rd_u8(r, &out->reserved_byte_10)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "reserved_byte_11");
    if (mip_rd_u8(r, &out->reserved_byte_11)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "reserved_byte_12");
    if (mip_rd_u8(r, &out->reserved_byte_12)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "gnss_byte_13");
    if (mip_rd_u8(r, &out->gnss_byte_13)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "gnss_byte_14");
    if (mip_rd_u8(r, &out->gnss_byte_14)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "reserved_byte_15");
    if (mip_rd_u8(r, &out->reserved_byte_15)) {
        return -1;
    }
    mip_rd_pop(r);
    return 0;
}

mip_status_t mip_cv7_continuous_bit_write(mip_writer_t *w, const mip_cv7_continuous_bit_t *in) {
    mip_status_t st;
    if ((st = mip_wr_u8(w, &in->system_byte_0)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_u8(w, &in->reserved_byte_1)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_u8(w, &in->system_byte_2)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_u8(w, &in->system_byte_3)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_u8(w, &in->imu_byte_4)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_u8(w, &in->imu_byte_5)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_u8(w, &in->imu_byte_6)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_u8(w, &in->imu_byte_7)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_u8(w, &in->nav_byte_8)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_u8(w, &in->reserved_byte_9)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_u8(w, &in->reserved_byte_10)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_u8(w, &in->reserved_byte_11)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_u8(w, &in->reserved_byte_12)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_u8(w, &in->gnss_byte_13)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_u8(w, &in->gnss_byte_14)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_u8(w, &in->reserved_byte_15)) != MIP_OK) {
        return st;
    }
    return MIP_OK;
}

void mip_cv7_continuous_bit_to_json(mip_jw_t *w, const mip_cv7_continuous_bit_t *in) {
    int first = 1;
    mip_jw_raw(w, "{", 1);
    mip_jw_key(w, &first, "system_byte_0");
    mip_jw_u8(w, &in->system_byte_0);
    mip_jw_key(w, &first, "reserved_byte_1");
    mip_jw_u8(w, &in->reserved_byte_1);
    mip_jw_key(w, &first, "system_byte_2");
    mip_jw_u8(w, &in->system_byte_2);
    mip_jw_key(w, &first, "system_byte_3");
    mip_jw_u8(w, &in->system_byte_3);
    mip_jw_key(w, &first, "imu_byte_4");
    mip_jw_u8(w, &in->imu_byte_4);
    mip_jw_key(w, &first, "imu_byte_5");
    mip_jw_u8(w, &in->imu_byte_5);
    mip_jw_key(w, &first, "imu_byte_6");
    mip_jw_u8(w, &in->imu_byte_6);
    mip_jw_key(w, &first, "imu_byte_7");
    mip_jw_u8(w, &in->imu_byte_7);
    mip_jw_key(w, &first, "nav_byte_8");
    mip_jw_u8(w, &in->nav_byte_8);
    mip_jw_key(w, &first, "reserved_byte_9");
    mip_jw_u8(w, &in->reserved_byte_9);
    mip_jw_key(w, &first, "reserved_byte_10");
    mip_jw_u8(w, &in->reserved_byte_10);
    mip_jw_key(w, &first, "reserved_byte_11");
    mip_jw_u8(w, &in->reserved_byte_11);
    mip_jw_key(w, &first, "reserved_byte_12");
    mip_jw_u8(w, &in->reserved_byte_12);
    mip_jw_key(w, &first, "gnss_byte_13");
    mip_jw_u8(w, &in->gnss_byte_13);
    mip_jw_key(w, &first, "gnss_byte_14");
    mip_jw_u8(w, &in->gnss_byte_14);
    mip_jw_key(w, &first, "reserved_byte_15");
    mip_jw_u8(w, &in->reserved_byte_15);
    mip_jw_raw(w, "}", 1);
}

int mip_cv7_continuous_bit_from_json(mip_jr_t *jr, size_t pos, mip_cv7_continuous_bit_t *out) {
    static const char *const keys[] = {
        "system_byte_0",    "reserved_byte_1", "system_byte_2",    "system_byte_3",
        "imu_byte_4",       "imu_byte_5",      "imu_byte_6",       "imu_byte_7",
        "nav_byte_8",       "reserved_byte_9", "reserved_byte_10", "reserved_byte_11",
        "reserved_byte_12", "gnss_byte_13",    "gnss_byte_14",     "reserved_byte_15"};
    size_t vp = 0;
    int found;
    if (mip_jr_object(jr, pos, keys, 16)) {
        return -1;
    }
    found = mip_jr_get(jr, pos, "system_byte_0", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"system_byte_0\"");
    }
    {
        mip_jr_push(jr, "system_byte_0");
        if (mip_jr_u8(jr, vp, &out->system_byte_0)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "reserved_byte_1", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"reserved_byte_1\"");
    }
    {
        mip_jr_push(jr, "reserved_byte_1");
        if (mip_jr_u8(jr, vp, &out->reserved_byte_1)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "system_byte_2", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"system_byte_2\"");
    }
    {
        mip_jr_push(jr, "system_byte_2");
        if (mip_jr_u8(jr, vp, &out->system_byte_2)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "system_byte_3", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"system_byte_3\"");
    }
    {
        mip_jr_push(jr, "system_byte_3");
        if (mip_jr_u8(jr, vp, &out->system_byte_3)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "imu_byte_4", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"imu_byte_4\"");
    }
    {
        mip_jr_push(jr, "imu_byte_4");
        if (mip_jr_u8(jr, vp, &out->imu_byte_4)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "imu_byte_5", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"imu_byte_5\"");
    }
    {
        mip_jr_push(jr, "imu_byte_5");
        if (mip_jr_u8(jr, vp, &out->imu_byte_5)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "imu_byte_6", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"imu_byte_6\"");
    }
    {
        mip_jr_push(jr, "imu_byte_6");
        if (mip_jr_u8(jr, vp, &out->imu_byte_6)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "imu_byte_7", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"imu_byte_7\"");
    }
    {
        mip_jr_push(jr, "imu_byte_7");
        if (mip_jr_u8(jr, vp, &out->imu_byte_7)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "nav_byte_8", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"nav_byte_8\"");
    }
    {
        mip_jr_push(jr, "nav_byte_8");
        if (mip_jr_u8(jr, vp, &out->nav_byte_8)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "reserved_byte_9", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"reserved_byte_9\"");
    }
    {
        mip_jr_push(jr, "reserved_byte_9");
        if (mip_jr_u8(jr, vp, &out->reserved_byte_9)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "reserved_byte_10", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"reserved_byte_10\"");
    }
    {
        mip_jr_push(jr, "reserved_byte_10");
        if (mip_jr_u8(jr, vp, &out->reserved_byte_10)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "reserved_byte_11", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"reserved_byte_11\"");
    }
    {
        mip_jr_push(jr, "reserved_byte_11");
        if (mip_jr_u8(jr, vp, &out->reserved_byte_11)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "reserved_byte_12", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"reserved_byte_12\"");
    }
    {
        mip_jr_push(jr, "reserved_byte_12");
        if (mip_jr_u8(jr, vp, &out->reserved_byte_12)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "gnss_byte_13", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"gnss_byte_13\"");
    }
    {
        mip_jr_push(jr, "gnss_byte_13");
        if (mip_jr_u8(jr, vp, &out->gnss_byte_13)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "gnss_byte_14", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"gnss_byte_14\"");
    }
    {
        mip_jr_push(jr, "gnss_byte_14");
        if (mip_jr_u8(jr, vp, &out->gnss_byte_14)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "reserved_byte_15", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"reserved_byte_15\"");
    }
    {
        mip_jr_push(jr, "reserved_byte_15");
        if (mip_jr_u8(jr, vp, &out->reserved_byte_15)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    return 0;
}

/* ---- DescriptorRate */

int mip_descriptor_rate_read(mip_reader_t *r, mip_descriptor_rate_t *out) {
    mip_rd_push(r, "descriptor");
    if (mip_rd_u8(r, &out->descriptor)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "decimation");
    if (mip_rd_u16(r, &out->decimation)) {
        return -1;
    }
    mip_rd_pop(r);
    return 0;
}

mip_status_t mip_descriptor_rate_write(mip_writer_t *w, const mip_descriptor_rate_t *in) {
    mip_status_t st;
    if ((st = mip_wr_u8(w, &in->descriptor)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_u16(w, &in->decimation)) != MIP_OK) {
        return st;
    }
    return MIP_OK;
}

void mip_descriptor_rate_to_json(mip_jw_t *w, const mip_descriptor_rate_t *in) {
    int first = 1;
    mip_jw_raw(w, "{", 1);
    mip_jw_key(w, &first, "descriptor");
    mip_jw_u8(w, &in->descriptor);
    mip_jw_key(w, &first, "decimation");
    mip_jw_u16(w, &in->decimation);
    mip_jw_raw(w, "}", 1);
}

int mip_descriptor_rate_from_json(mip_jr_t *jr, size_t pos, mip_descriptor_rate_t *out) {
    static const char *const keys[] = {"descriptor", "decimation"};
    size_t vp = 0;
    int found;
    if (mip_jr_object(jr, pos, keys, 2)) {
        return -1;
    }
    found = mip_jr_get(jr, pos, "descriptor", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"descriptor\"");
    }
    {
        mip_jr_push(jr, "descriptor");
        if (mip_jr_u8(jr, vp, &out->descriptor)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "decimation", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"decimation\"");
    }
    {
        mip_jr_push(jr, "decimation");
        if (mip_jr_u16(jr, vp, &out->decimation)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    return 0;
}

/* ---- DeviceInfo */

int mip_device_info_read(mip_reader_t *r, mip_device_info_t *out) {
    mip_rd_push(r, "firmware_version");
    if (mip_rd_u16(r, &out->firmware_version)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "model_name");
    if (mip_rd_chars(r, out->model_name, 16)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "model_number");
    if (mip_rd_chars(r, out->model_number, 16)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "serial_number");
    if (mip_rd_chars(r, out->serial_number, 16)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "lot_number");
    if (mip_rd_chars(r, out->lot_number, 16)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "device_options");
    if (mip_rd_chars(r, out->device_options, 16)) {
        return -1;
    }
    mip_rd_pop(r);
    return 0;
}

mip_status_t mip_device_info_write(mip_writer_t *w, const mip_device_info_t *in) {
    mip_status_t st;
    if ((st = mip_wr_u16(w, &in->firmware_version)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_chars(w, in->model_name, 16)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_chars(w, in->model_number, 16)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_chars(w, in->serial_number, 16)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_chars(w, in->lot_number, 16)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_chars(w, in->device_options, 16)) != MIP_OK) {
        return st;
    }
    return MIP_OK;
}

void mip_device_info_to_json(mip_jw_t *w, const mip_device_info_t *in) {
    int first = 1;
    mip_jw_raw(w, "{", 1);
    mip_jw_key(w, &first, "firmware_version");
    mip_jw_u16(w, &in->firmware_version);
    mip_jw_key(w, &first, "model_name");
    mip_jw_chars(w, in->model_name, 16);
    mip_jw_key(w, &first, "model_number");
    mip_jw_chars(w, in->model_number, 16);
    mip_jw_key(w, &first, "serial_number");
    mip_jw_chars(w, in->serial_number, 16);
    mip_jw_key(w, &first, "lot_number");
    mip_jw_chars(w, in->lot_number, 16);
    mip_jw_key(w, &first, "device_options");
    mip_jw_chars(w, in->device_options, 16);
    mip_jw_raw(w, "}", 1);
}

int mip_device_info_from_json(mip_jr_t *jr, size_t pos, mip_device_info_t *out) {
    static const char *const keys[] = {"firmware_version", "model_name", "model_number",
                                       "serial_number",    "lot_number", "device_options"};
    size_t vp = 0;
    int found;
    if (mip_jr_object(jr, pos, keys, 6)) {
        return -1;
    }
    found = mip_jr_get(jr, pos, "firmware_version", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"firmware_version\"");
    }
    {
        mip_jr_push(jr, "firmware_version");
        if (mip_jr_u16(jr, vp, &out->firmware_version)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "model_name", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"model_name\"");
    }
    {
        mip_jr_push(jr, "model_name");
        if (mip_jr_chars(jr, vp, out->model_name, 16)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "model_number", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"model_number\"");
    }
    {
        mip_jr_push(jr, "model_number");
        if (mip_jr_chars(jr, vp, out->model_number, 16)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "serial_number", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"serial_number\"");
    }
    {
        mip_jr_push(jr, "serial_number");
        if (mip_jr_chars(jr, vp, out->serial_number, 16)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "lot_number", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"lot_number\"");
    }
    {
        mip_jr_push(jr, "lot_number");
        if (mip_jr_chars(jr, vp, out->lot_number, 16)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "device_options", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"device_options\"");
    }
    {
        mip_jr_push(jr, "device_options");
        if (mip_jr_chars(jr, vp, out->device_options, 16)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    return 0;
}

/* ---- GnssReceiverInfoEntry */

int mip_gnss_receiver_info_entry_read(mip_reader_t *r, mip_gnss_receiver_info_entry_t *out) {
    mip_rd_push(r, "receiver_id");
    if (mip_rd_u8(r, &out->receiver_id)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "mip_data_descriptor_set");
    if (mip_rd_u8(r, &out->mip_data_descriptor_set)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "description");
    if (mip_rd_chars(r, out->description, 32)) {
        return -1;
    }
    mip_rd_pop(r);
    return 0;
}

mip_status_t mip_gnss_receiver_info_entry_write(mip_writer_t *w, const mip_gnss_receiver_info_entry_t *in) {
    mip_status_t st;
    if ((st = mip_wr_u8(w, &in->receiver_id)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_u8(w, &in->mip_data_descriptor_set)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_chars(w, in->description, 32)) != MIP_OK) {
        return st;
    }
    return MIP_OK;
}

void mip_gnss_receiver_info_entry_to_json(mip_jw_t *w, const mip_gnss_receiver_info_entry_t *in) {
    int first = 1;
    mip_jw_raw(w, "{", 1);
    mip_jw_key(w, &first, "receiver_id");
    mip_jw_u8(w, &in->receiver_id);
    mip_jw_key(w, &first, "mip_data_descriptor_set");
    mip_jw_u8(w, &in->mip_data_descriptor_set);
    mip_jw_key(w, &first, "description");
    mip_jw_chars(w, in->description, 32);
    mip_jw_raw(w, "}", 1);
}

int mip_gnss_receiver_info_entry_from_json(mip_jr_t *jr, size_t pos, mip_gnss_receiver_info_entry_t *out) {
    static const char *const keys[] = {"receiver_id", "mip_data_descriptor_set", "description"};
    size_t vp = 0;
    int found;
    if (mip_jr_object(jr, pos, keys, 3)) {
        return -1;
    }
    found = mip_jr_get(jr, pos, "receiver_id", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"receiver_id\"");
    }
    {
        mip_jr_push(jr, "receiver_id");
        if (mip_jr_u8(jr, vp, &out->receiver_id)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "mip_data_descriptor_set", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"mip_data_descriptor_set\"");
    }
    {
        mip_jr_push(jr, "mip_data_descriptor_set");
        if (mip_jr_u8(jr, vp, &out->mip_data_descriptor_set)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "description", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"description\"");
    }
    {
        mip_jr_push(jr, "description");
        if (mip_jr_chars(jr, vp, out->description, 32)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    return 0;
}

/* ---- GpioBehaviorUnused */

int mip_gpio_behavior_unused_read(mip_reader_t *r, mip_gpio_behavior_unused_t *out) {
    mip_rd_push(r, "behavior");
    if (mip_rd_u8(r, &out->behavior)) {
        return -1;
    }
    mip_rd_pop(r);
    return 0;
}

mip_status_t mip_gpio_behavior_unused_write(mip_writer_t *w, const mip_gpio_behavior_unused_t *in) {
    mip_status_t st;
    if ((st = mip_wr_u8(w, &in->behavior)) != MIP_OK) {
        return st;
    }
    return MIP_OK;
}

void mip_gpio_behavior_unused_to_json(mip_jw_t *w, const mip_gpio_behavior_unused_t *in) {
    int first = 1;
    mip_jw_raw(w, "{", 1);
    mip_jw_key(w, &first, "behavior");
    mip_jw_u8(w, &in->behavior);
    mip_jw_raw(w, "}", 1);
}

int mip_gpio_behavior_unused_from_json(mip_jr_t *jr, size_t pos, mip_gpio_behavior_unused_t *out) {
    static const char *const keys[] = {"behavior"};
    size_t vp = 0;
    int found;
    if (mip_jr_object(jr, pos, keys, 1)) {
        return -1;
    }
    found = mip_jr_get(jr, pos, "behavior", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"behavior\"");
    }
    {
        mip_jr_push(jr, "behavior");
        if (mip_jr_u8(jr, vp, &out->behavior)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    return 0;
}

/* ---- GpioBehaviorIo */

int mip_gpio_behavior_io_read(mip_reader_t *r, mip_gpio_behavior_io_t *out) {
    mip_rd_push(r, "behavior");
    if (mip_rd_u8(r, &out->behavior)) {
        return -1;
    }
    mip_rd_pop(r);
    return 0;
}

mip_status_t mip_gpio_behavior_io_write(mip_writer_t *w, const mip_gpio_behavior_io_t *in) {
    mip_status_t st;
    if ((st = mip_wr_u8(w, &in->behavior)) != MIP_OK) {
        return st;
    }
    return MIP_OK;
}

void mip_gpio_behavior_io_to_json(mip_jw_t *w, const mip_gpio_behavior_io_t *in) {
    int first = 1;
    mip_jw_raw(w, "{", 1);
    mip_jw_key(w, &first, "behavior");
    mip_jw_u8(w, &in->behavior);
    mip_jw_raw(w, "}", 1);
}

int mip_gpio_behavior_io_from_json(mip_jr_t *jr, size_t pos, mip_gpio_behavior_io_t *out) {
    static const char *const keys[] = {"behavior"};
    size_t vp = 0;
    int found;
    if (mip_jr_object(jr, pos, keys, 1)) {
        return -1;
    }
    found = mip_jr_get(jr, pos, "behavior", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"behavior\"");
    }
    {
        mip_jr_push(jr, "behavior");
        if (mip_jr_u8(jr, vp, &out->behavior)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    return 0;
}

/* ---- GpioBehaviorPps */

int mip_gpio_behavior_pps_read(mip_reader_t *r, mip_gpio_behavior_pps_t *out) {
    mip_rd_push(r, "behavior");
    if (mip_rd_u8(r, &out->behavior)) {
        return -1;
    }
    mip_rd_pop(r);
    return 0;
}

mip_status_t mip_gpio_behavior_pps_write(mip_writer_t *w, const mip_gpio_behavior_pps_t *in) {
    mip_status_t st;
    if ((st = mip_wr_u8(w, &in->behavior)) != MIP_OK) {
        return st;
    }
    return MIP_OK;
}

void mip_gpio_behavior_pps_to_json(mip_jw_t *w, const mip_gpio_behavior_pps_t *in) {
    int first = 1;
    mip_jw_raw(w, "{", 1);
    mip_jw_key(w, &first, "behavior");
    mip_jw_u8(w, &in->behavior);
    mip_jw_raw(w, "}", 1);
}

int mip_gpio_behavior_pps_from_json(mip_jr_t *jr, size_t pos, mip_gpio_behavior_pps_t *out) {
    static const char *const keys[] = {"behavior"};
    size_t vp = 0;
    int found;
    if (mip_jr_object(jr, pos, keys, 1)) {
        return -1;
    }
    found = mip_jr_get(jr, pos, "behavior", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"behavior\"");
    }
    {
        mip_jr_push(jr, "behavior");
        if (mip_jr_u8(jr, vp, &out->behavior)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    return 0;
}

/* ---- GpioBehaviorEncoder */

int mip_gpio_behavior_encoder_read(mip_reader_t *r, mip_gpio_behavior_encoder_t *out) {
    mip_rd_push(r, "behavior");
    if (mip_rd_u8(r, &out->behavior)) {
        return -1;
    }
    mip_rd_pop(r);
    return 0;
}

mip_status_t mip_gpio_behavior_encoder_write(mip_writer_t *w, const mip_gpio_behavior_encoder_t *in) {
    mip_status_t st;
    if ((st = mip_wr_u8(w, &in->behavior)) != MIP_OK) {
        return st;
    }
    return MIP_OK;
}

void mip_gpio_behavior_encoder_to_json(mip_jw_t *w, const mip_gpio_behavior_encoder_t *in) {
    int first = 1;
    mip_jw_raw(w, "{", 1);
    mip_jw_key(w, &first, "behavior");
    mip_jw_u8(w, &in->behavior);
    mip_jw_raw(w, "}", 1);
}

int mip_gpio_behavior_encoder_from_json(mip_jr_t *jr, size_t pos, mip_gpio_behavior_encoder_t *out) {
    static const char *const keys[] = {"behavior"};
    size_t vp = 0;
    int found;
    if (mip_jr_object(jr, pos, keys, 1)) {
        return -1;
    }
    found = mip_jr_get(jr, pos, "behavior", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"behavior\"");
    }
    {
        mip_jr_push(jr, "behavior");
        if (mip_jr_u8(jr, vp, &out->behavior)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    return 0;
}

/* ---- GpioBehaviorTimestamp */

int mip_gpio_behavior_timestamp_read(mip_reader_t *r, mip_gpio_behavior_timestamp_t *out) {
    mip_rd_push(r, "behavior");
    if (mip_rd_u8(r, &out->behavior)) {
        return -1;
    }
    mip_rd_pop(r);
    return 0;
}

mip_status_t mip_gpio_behavior_timestamp_write(mip_writer_t *w, const mip_gpio_behavior_timestamp_t *in) {
    mip_status_t st;
    if ((st = mip_wr_u8(w, &in->behavior)) != MIP_OK) {
        return st;
    }
    return MIP_OK;
}

void mip_gpio_behavior_timestamp_to_json(mip_jw_t *w, const mip_gpio_behavior_timestamp_t *in) {
    int first = 1;
    mip_jw_raw(w, "{", 1);
    mip_jw_key(w, &first, "behavior");
    mip_jw_u8(w, &in->behavior);
    mip_jw_raw(w, "}", 1);
}

int mip_gpio_behavior_timestamp_from_json(mip_jr_t *jr, size_t pos, mip_gpio_behavior_timestamp_t *out) {
    static const char *const keys[] = {"behavior"};
    size_t vp = 0;
    int found;
    if (mip_jr_object(jr, pos, keys, 1)) {
        return -1;
    }
    found = mip_jr_get(jr, pos, "behavior", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"behavior\"");
    }
    {
        mip_jr_push(jr, "behavior");
        if (mip_jr_u8(jr, vp, &out->behavior)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    return 0;
}

/* ---- GpioBehaviorUart */

int mip_gpio_behavior_uart_read(mip_reader_t *r, mip_gpio_behavior_uart_t *out) {
    mip_rd_push(r, "behavior");
    if (mip_rd_u8(r, &out->behavior)) {
        return -1;
    }
    mip_rd_pop(r);
    return 0;
}

mip_status_t mip_gpio_behavior_uart_write(mip_writer_t *w, const mip_gpio_behavior_uart_t *in) {
    mip_status_t st;
    if ((st = mip_wr_u8(w, &in->behavior)) != MIP_OK) {
        return st;
    }
    return MIP_OK;
}

void mip_gpio_behavior_uart_to_json(mip_jw_t *w, const mip_gpio_behavior_uart_t *in) {
    int first = 1;
    mip_jw_raw(w, "{", 1);
    mip_jw_key(w, &first, "behavior");
    mip_jw_u8(w, &in->behavior);
    mip_jw_raw(w, "}", 1);
}

int mip_gpio_behavior_uart_from_json(mip_jr_t *jr, size_t pos, mip_gpio_behavior_uart_t *out) {
    static const char *const keys[] = {"behavior"};
    size_t vp = 0;
    int found;
    if (mip_jr_object(jr, pos, keys, 1)) {
        return -1;
    }
    found = mip_jr_get(jr, pos, "behavior", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"behavior\"");
    }
    {
        mip_jr_push(jr, "behavior");
        if (mip_jr_u8(jr, vp, &out->behavior)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    return 0;
}

/* ---- Gx5BasicStatus */

int mip_gx5_basic_status_read(mip_reader_t *r, mip_gx5_basic_status_t *out) {
    mip_rd_push(r, "status_flags");
    if (mip_rd_u32(r, &out->status_flags)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "system_state");
    if (mip_rd_u16(r, &out->system_state)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "system_timer");
    if (mip_rd_u32(r, &out->system_timer)) {
        return -1;
    }
    mip_rd_pop(r);
    return 0;
}

mip_status_t mip_gx5_basic_status_write(mip_writer_t *w, const mip_gx5_basic_status_t *in) {
    mip_status_t st;
    if ((st = mip_wr_u32(w, &in->status_flags)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_u16(w, &in->system_state)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_u32(w, &in->system_timer)) != MIP_OK) {
        return st;
    }
    return MIP_OK;
}

void mip_gx5_basic_status_to_json(mip_jw_t *w, const mip_gx5_basic_status_t *in) {
    int first = 1;
    mip_jw_raw(w, "{", 1);
    mip_jw_key(w, &first, "status_flags");
    mip_jw_u32(w, &in->status_flags);
    mip_jw_key(w, &first, "system_state");
    mip_jw_u16(w, &in->system_state);
    mip_jw_key(w, &first, "system_timer");
    mip_jw_u32(w, &in->system_timer);
    mip_jw_raw(w, "}", 1);
}

int mip_gx5_basic_status_from_json(mip_jr_t *jr, size_t pos, mip_gx5_basic_status_t *out) {
    static const char *const keys[] = {"status_flags", "system_state", "system_timer"};
    size_t vp = 0;
    int found;
    if (mip_jr_object(jr, pos, keys, 3)) {
        return -1;
    }
    found = mip_jr_get(jr, pos, "status_flags", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"status_flags\"");
    }
    {
        mip_jr_push(jr, "status_flags");
        if (mip_jr_u32(jr, vp, &out->status_flags)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "system_state", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"system_state\"");
    }
    {
        mip_jr_push(jr, "system_state");
        if (mip_jr_u16(jr, vp, &out->system_state)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "system_timer", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"system_timer\"");
    }
    {
        mip_jr_push(jr, "system_timer");
        if (mip_jr_u32(jr, vp, &out->system_timer)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    return 0;
}

/* ---- Gx5DiagnosticStatus */

int mip_gx5_diagnostic_status_read(mip_reader_t *r, mip_gx5_diagnostic_status_t *out) {
    mip_rd_push(r, "status_flags");
    if (mip_rd_u32(r, &out->status_flags)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "system_state");
    if (mip_rd_u16(r, &out->system_state)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "system_timer");
    if (mip_rd_u32(r, &out->system_timer)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "gnss_power_state");
    if (mip_rd_u8(r, &out->gnss_power_state)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "pps_pulse_count");
    if (mip_rd_u32(r, &out->pps_pulse_count)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "last_pps_time");
    if (mip_rd_u32(r, &out->last_pps_time)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "imu_stream_enabled");
    if (mip_rd_u8(r, &out->imu_stream_enabled)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "gnss_stream_enabled");
    if (mip_rd_u8(r, &out->gnss_stream_enabled)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "filter_stream_enabled");
    if (mip_rd_u8(r, &out->filter_stream_enabled)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "imu_dropped_packets");
    if (mip_rd_u32(r, &out->imu_dropped_packets)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "gnss_dropped_packets");
    if (mip_rd_u32(r, &out->gnss_dropped_packets)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "filter_dropped_packets");
    if (mip_rd_u32(r, &out->filter_dropped_packets)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "com_bytes_written");
    if (mip_rd_u32(r, &out->com_bytes_written)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "com_bytes_read");
    if (mip_rd_u32(r, &out->com_bytes_read)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "com_write_overruns");
    if (mip_rd_u32(r, &out->com_write_overruns)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "imu_parse_errors");
    if (mip_rd_u32(r, &out->imu_parse_errors)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "imu_messages_read");
    if (mip_rd_u32(r, &out->imu_messages_read)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "last_imu_message_time");
    if (mip_rd_u32(r, &out->last_imu_message_time)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "gnss_parse_errors");
    if (mip_rd_u32(r, &out->gnss_parse_errors)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "gnss_messages_read");
    if (mip_rd_u32(r, &out->gnss_messages_read)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "last_gnss_message_time");
    if (mip_rd_u32(r, &out->last_gnss_message_time)) {
        return -1;
    }
    mip_rd_pop(r);
    return 0;
}

mip_status_t mip_gx5_diagnostic_status_write(mip_writer_t *w, const mip_gx5_diagnostic_status_t *in) {
    mip_status_t st;
    if ((st = mip_wr_u32(w, &in->status_flags)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_u16(w, &in->system_state)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_u32(w, &in->system_timer)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_u8(w, &in->gnss_power_state)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_u32(w, &in->pps_pulse_count)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_u32(w, &in->last_pps_time)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_u8(w, &in->imu_stream_enabled)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_u8(w, &in->gnss_stream_enabled)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_u8(w, &in->filter_stream_enabled)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_u32(w, &in->imu_dropped_packets)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_u32(w, &in->gnss_dropped_packets)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_u32(w, &in->filter_dropped_packets)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_u32(w, &in->com_bytes_written)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_u32(w, &in->com_bytes_read)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_u32(w, &in->com_write_overruns)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_u32(w, &in->imu_parse_errors)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_u32(w, &in->imu_messages_read)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_u32(w, &in->last_imu_message_time)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_u32(w, &in->gnss_parse_errors)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_u32(w, &in->gnss_messages_read)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_u32(w, &in->last_gnss_message_time)) != MIP_OK) {
        return st;
    }
    return MIP_OK;
}

void mip_gx5_diagnostic_status_to_json(mip_jw_t *w, const mip_gx5_diagnostic_status_t *in) {
    int first = 1;
    mip_jw_raw(w, "{", 1);
    mip_jw_key(w, &first, "status_flags");
    mip_jw_u32(w, &in->status_flags);
    mip_jw_key(w, &first, "system_state");
    mip_jw_u16(w, &in->system_state);
    mip_jw_key(w, &first, "system_timer");
    mip_jw_u32(w, &in->system_timer);
    mip_jw_key(w, &first, "gnss_power_state");
    mip_jw_u8(w, &in->gnss_power_state);
    mip_jw_key(w, &first, "pps_pulse_count");
    mip_jw_u32(w, &in->pps_pulse_count);
    mip_jw_key(w, &first, "last_pps_time");
    mip_jw_u32(w, &in->last_pps_time);
    mip_jw_key(w, &first, "imu_stream_enabled");
    mip_jw_u8(w, &in->imu_stream_enabled);
    mip_jw_key(w, &first, "gnss_stream_enabled");
    mip_jw_u8(w, &in->gnss_stream_enabled);
    mip_jw_key(w, &first, "filter_stream_enabled");
    mip_jw_u8(w, &in->filter_stream_enabled);
    mip_jw_key(w, &first, "imu_dropped_packets");
    mip_jw_u32(w, &in->imu_dropped_packets);
    mip_jw_key(w, &first, "gnss_dropped_packets");
    mip_jw_u32(w, &in->gnss_dropped_packets);
    mip_jw_key(w, &first, "filter_dropped_packets");
    mip_jw_u32(w, &in->filter_dropped_packets);
    mip_jw_key(w, &first, "com_bytes_written");
    mip_jw_u32(w, &in->com_bytes_written);
    mip_jw_key(w, &first, "com_bytes_read");
    mip_jw_u32(w, &in->com_bytes_read);
    mip_jw_key(w, &first, "com_write_overruns");
    mip_jw_u32(w, &in->com_write_overruns);
    mip_jw_key(w, &first, "imu_parse_errors");
    mip_jw_u32(w, &in->imu_parse_errors);
    mip_jw_key(w, &first, "imu_messages_read");
    mip_jw_u32(w, &in->imu_messages_read);
    mip_jw_key(w, &first, "last_imu_message_time");
    mip_jw_u32(w, &in->last_imu_message_time);
    mip_jw_key(w, &first, "gnss_parse_errors");
    mip_jw_u32(w, &in->gnss_parse_errors);
    mip_jw_key(w, &first, "gnss_messages_read");
    mip_jw_u32(w, &in->gnss_messages_read);
    mip_jw_key(w, &first, "last_gnss_message_time");
    mip_jw_u32(w, &in->last_gnss_message_time);
    mip_jw_raw(w, "}", 1);
}

int mip_gx5_diagnostic_status_from_json(mip_jr_t *jr, size_t pos, mip_gx5_diagnostic_status_t *out) {
    static const char *const keys[] = {
        "status_flags",          "system_state",          "system_timer",         "gnss_power_state",
        "pps_pulse_count",       "last_pps_time",         "imu_stream_enabled",   "gnss_stream_enabled",
        "filter_stream_enabled", "imu_dropped_packets",   "gnss_dropped_packets", "filter_dropped_packets",
        "com_bytes_written",     "com_bytes_read",        "com_write_overruns",   "imu_parse_errors",
        "imu_messages_read",     "last_imu_message_time", "gnss_parse_errors",    "gnss_messages_read",
        "last_gnss_message_time"};
    size_t vp = 0;
    int found;
    if (mip_jr_object(jr, pos, keys, 21)) {
        return -1;
    }
    found = mip_jr_get(jr, pos, "status_flags", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"status_flags\"");
    }
    {
        mip_jr_push(jr, "status_flags");
        if (mip_jr_u32(jr, vp, &out->status_flags)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "system_state", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"system_state\"");
    }
    {
        mip_jr_push(jr, "system_state");
        if (mip_jr_u16(jr, vp, &out->system_state)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "system_timer", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"system_timer\"");
    }
    {
        mip_jr_push(jr, "system_timer");
        if (mip_jr_u32(jr, vp, &out->system_timer)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "gnss_power_state", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"gnss_power_state\"");
    }
    {
        mip_jr_push(jr, "gnss_power_state");
        if (mip_jr_u8(jr, vp, &out->gnss_power_state)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "pps_pulse_count", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"pps_pulse_count\"");
    }
    {
        mip_jr_push(jr, "pps_pulse_count");
        if (mip_jr_u32(jr, vp, &out->pps_pulse_count)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "last_pps_time", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"last_pps_time\"");
    }
    {
        mip_jr_push(jr, "last_pps_time");
        if (mip_jr_u32(jr, vp, &out->last_pps_time)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "imu_stream_enabled", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"imu_stream_enabled\"");
    }
    {
        mip_jr_push(jr, "imu_stream_enabled");
        if (mip_jr_u8(jr, vp, &out->imu_stream_enabled)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "gnss_stream_enabled", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"gnss_stream_enabled\"");
    }
    {
        mip_jr_push(jr, "gnss_stream_enabled");
        if (mip_jr_u8(jr, vp, &out->gnss_stream_enabled)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "filter_stream_enabled", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"filter_stream_enabled\"");
    }
    {
        mip_jr_push(jr, "filter_stream_enabled");
        if (mip_jr_u8(jr, vp, &out->filter_stream_enabled)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "imu_dropped_packets", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"imu_dropped_packets\"");
    }
    {
        mip_jr_push(jr, "imu_dropped_packets");
        if (mip_jr_u32(jr, vp, &out->imu_dropped_packets)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "gnss_dropped_packets", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"gnss_dropped_packets\"");
    }
    {
        mip_jr_push(jr, "gnss_dropped_packets");
        if (mip_jr_u32(jr, vp, &out->gnss_dropped_packets)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "filter_dropped_packets", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"filter_dropped_packets\"");
    }
    {
        mip_jr_push(jr, "filter_dropped_packets");
        if (mip_jr_u32(jr, vp, &out->filter_dropped_packets)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "com_bytes_written", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"com_bytes_written\"");
    }
    {
        mip_jr_push(jr, "com_bytes_written");
        if (mip_jr_u32(jr, vp, &out->com_bytes_written)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "com_bytes_read", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"com_bytes_read\"");
    }
    {
        mip_jr_push(jr, "com_bytes_read");
        if (mip_jr_u32(jr, vp, &out->com_bytes_read)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "com_write_overruns", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"com_write_overruns\"");
    }
    {
        mip_jr_push(jr, "com_write_overruns");
        if (mip_jr_u32(jr, vp, &out->com_write_overruns)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "imu_parse_errors", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"imu_parse_errors\"");
    }
    {
        mip_jr_push(jr, "imu_parse_errors");
        if (mip_jr_u32(jr, vp, &out->imu_parse_errors)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "imu_messages_read", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"imu_messages_read\"");
    }
    {
        mip_jr_push(jr, "imu_messages_read");
        if (mip_jr_u32(jr, vp, &out->imu_messages_read)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "last_imu_message_time", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"last_imu_message_time\"");
    }
    {
        mip_jr_push(jr, "last_imu_message_time");
        if (mip_jr_u32(jr, vp, &out->last_imu_message_time)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "gnss_parse_errors", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"gnss_parse_errors\"");
    }
    {
        mip_jr_push(jr, "gnss_parse_errors");
        if (mip_jr_u32(jr, vp, &out->gnss_parse_errors)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "gnss_messages_read", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"gnss_messages_read\"");
    }
    {
        mip_jr_push(jr, "gnss_messages_read");
        if (mip_jr_u32(jr, vp, &out->gnss_messages_read)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "last_gnss_message_time", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"last_gnss_message_time\"");
    }
    {
        mip_jr_push(jr, "last_gnss_message_time");
        if (mip_jr_u32(jr, vp, &out->last_gnss_message_time)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    return 0;
}

/* ---- Gx5PollDescriptor */

int mip_gx5_poll_descriptor_read(mip_reader_t *r, mip_gx5_poll_descriptor_t *out) {
    mip_rd_push(r, "descriptor");
    if (mip_rd_u8(r, &out->descriptor)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "reserved");
    if (mip_rd_u16(r, &out->reserved)) {
        return -1;
    }
    mip_rd_pop(r);
    return 0;
}

mip_status_t mip_gx5_poll_descriptor_write(mip_writer_t *w, const mip_gx5_poll_descriptor_t *in) {
    mip_status_t st;
    if ((st = mip_wr_u8(w, &in->descriptor)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_u16(w, &in->reserved)) != MIP_OK) {
        return st;
    }
    return MIP_OK;
}

void mip_gx5_poll_descriptor_to_json(mip_jw_t *w, const mip_gx5_poll_descriptor_t *in) {
    int first = 1;
    mip_jw_raw(w, "{", 1);
    mip_jw_key(w, &first, "descriptor");
    mip_jw_u8(w, &in->descriptor);
    mip_jw_key(w, &first, "reserved");
    mip_jw_u16(w, &in->reserved);
    mip_jw_raw(w, "}", 1);
}

int mip_gx5_poll_descriptor_from_json(mip_jr_t *jr, size_t pos, mip_gx5_poll_descriptor_t *out) {
    static const char *const keys[] = {"descriptor", "reserved"};
    size_t vp = 0;
    int found;
    if (mip_jr_object(jr, pos, keys, 2)) {
        return -1;
    }
    found = mip_jr_get(jr, pos, "descriptor", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"descriptor\"");
    }
    {
        mip_jr_push(jr, "descriptor");
        if (mip_jr_u8(jr, vp, &out->descriptor)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "reserved", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"reserved\"");
    }
    {
        mip_jr_push(jr, "reserved");
        if (mip_jr_u16(jr, vp, &out->reserved)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    return 0;
}

/* ---- NmeaMessage */

int mip_nmea_message_read(mip_reader_t *r, mip_nmea_message_t *out) {
    mip_rd_push(r, "message_id");
    if (mip_rd_u8(r, &out->message_id)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "talker_id");
    if (mip_rd_u8(r, &out->talker_id)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "source_desc_set");
    if (mip_rd_u8(r, &out->source_desc_set)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "decimation");
    if (mip_rd_u16(r, &out->decimation)) {
        return -1;
    }
    mip_rd_pop(r);
    return 0;
}

mip_status_t mip_nmea_message_write(mip_writer_t *w, const mip_nmea_message_t *in) {
    mip_status_t st;
    if ((st = mip_wr_u8(w, &in->message_id)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_u8(w, &in->talker_id)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_u8(w, &in->source_desc_set)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_u16(w, &in->decimation)) != MIP_OK) {
        return st;
    }
    return MIP_OK;
}

void mip_nmea_message_to_json(mip_jw_t *w, const mip_nmea_message_t *in) {
    int first = 1;
    mip_jw_raw(w, "{", 1);
    mip_jw_key(w, &first, "message_id");
    mip_jw_u8(w, &in->message_id);
    mip_jw_key(w, &first, "talker_id");
    mip_jw_u8(w, &in->talker_id);
    mip_jw_key(w, &first, "source_desc_set");
    mip_jw_u8(w, &in->source_desc_set);
    mip_jw_key(w, &first, "decimation");
    mip_jw_u16(w, &in->decimation);
    mip_jw_raw(w, "}", 1);
}

int mip_nmea_message_from_json(mip_jr_t *jr, size_t pos, mip_nmea_message_t *out) {
    static const char *const keys[] = {"message_id", "talker_id", "source_desc_set", "decimation"};
    size_t vp = 0;
    int found;
    if (mip_jr_object(jr, pos, keys, 4)) {
        return -1;
    }
    found = mip_jr_get(jr, pos, "message_id", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"message_id\"");
    }
    {
        mip_jr_push(jr, "message_id");
        if (mip_jr_u8(jr, vp, &out->message_id)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "talker_id", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"talker_id\"");
    }
    {
        mip_jr_push(jr, "talker_id");
        if (mip_jr_u8(jr, vp, &out->talker_id)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "source_desc_set", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"source_desc_set\"");
    }
    {
        mip_jr_push(jr, "source_desc_set");
        if (mip_jr_u8(jr, vp, &out->source_desc_set)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "decimation", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"decimation\"");
    }
    {
        mip_jr_push(jr, "decimation");
        if (mip_jr_u16(jr, vp, &out->decimation)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    return 0;
}

/* ---- SensorRangeEntry */

int mip_sensor_range_entry_read(mip_reader_t *r, mip_sensor_range_entry_t *out) {
    mip_rd_push(r, "setting");
    if (mip_rd_u8(r, &out->setting)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "range");
    if (mip_rd_f32(r, &out->range)) {
        return -1;
    }
    mip_rd_pop(r);
    return 0;
}

mip_status_t mip_sensor_range_entry_write(mip_writer_t *w, const mip_sensor_range_entry_t *in) {
    mip_status_t st;
    if ((st = mip_wr_u8(w, &in->setting)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_f32(w, &in->range)) != MIP_OK) {
        return st;
    }
    return MIP_OK;
}

void mip_sensor_range_entry_to_json(mip_jw_t *w, const mip_sensor_range_entry_t *in) {
    int first = 1;
    mip_jw_raw(w, "{", 1);
    mip_jw_key(w, &first, "setting");
    mip_jw_u8(w, &in->setting);
    mip_jw_key(w, &first, "range");
    mip_jw_f32(w, &in->range);
    mip_jw_raw(w, "}", 1);
}

int mip_sensor_range_entry_from_json(mip_jr_t *jr, size_t pos, mip_sensor_range_entry_t *out) {
    static const char *const keys[] = {"setting", "range"};
    size_t vp = 0;
    int found;
    if (mip_jr_object(jr, pos, keys, 2)) {
        return -1;
    }
    found = mip_jr_get(jr, pos, "setting", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"setting\"");
    }
    {
        mip_jr_push(jr, "setting");
        if (mip_jr_u8(jr, vp, &out->setting)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "range", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"range\"");
    }
    {
        mip_jr_push(jr, "range");
        if (mip_jr_f32(jr, vp, &out->range)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    return 0;
}

/* ---- SupportedActionType */

int mip_supported_action_type_read(mip_reader_t *r, mip_supported_action_type_t *out) {
    mip_rd_push(r, "type");
    if (mip_rd_u8(r, &out->type)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "count");
    if (mip_rd_u8(r, &out->count)) {
        return -1;
    }
    mip_rd_pop(r);
    return 0;
}

mip_status_t mip_supported_action_type_write(mip_writer_t *w, const mip_supported_action_type_t *in) {
    mip_status_t st;
    if ((st = mip_wr_u8(w, &in->type)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_u8(w, &in->count)) != MIP_OK) {
        return st;
    }
    return MIP_OK;
}

void mip_supported_action_type_to_json(mip_jw_t *w, const mip_supported_action_type_t *in) {
    int first = 1;
    mip_jw_raw(w, "{", 1);
    mip_jw_key(w, &first, "type");
    mip_jw_u8(w, &in->type);
    mip_jw_key(w, &first, "count");
    mip_jw_u8(w, &in->count);
    mip_jw_raw(w, "}", 1);
}

int mip_supported_action_type_from_json(mip_jr_t *jr, size_t pos, mip_supported_action_type_t *out) {
    static const char *const keys[] = {"type", "count"};
    size_t vp = 0;
    int found;
    if (mip_jr_object(jr, pos, keys, 2)) {
        return -1;
    }
    found = mip_jr_get(jr, pos, "type", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"type\"");
    }
    {
        mip_jr_push(jr, "type");
        if (mip_jr_u8(jr, vp, &out->type)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "count", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"count\"");
    }
    {
        mip_jr_push(jr, "count");
        if (mip_jr_u8(jr, vp, &out->count)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    return 0;
}

/* ---- SupportedActions */

int mip_supported_actions_read(mip_reader_t *r, mip_supported_actions_t *out) {
    size_t i;
    mip_rd_push(r, "max_instances");
    if (mip_rd_u8(r, &out->max_instances)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "num_entries");
    if (mip_rd_u8(r, &out->num_entries)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "entries");
    if (out->num_entries > 125) {
        return mip_rd_count_error(r, (uint64_t)out->num_entries, 125);
    }
    for (i = 0; i < (size_t)out->num_entries; i++) {
        mip_rd_index(r, i);
        if (mip_supported_action_type_read(r, &out->entries[i])) {
            return -1;
        }
    }
    mip_rd_pop(r);
    return 0;
}

mip_status_t mip_supported_actions_write(mip_writer_t *w, const mip_supported_actions_t *in) {
    mip_status_t st;
    size_t i;
    if ((st = mip_wr_u8(w, &in->max_instances)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_u8(w, &in->num_entries)) != MIP_OK) {
        return st;
    }
    if (in->num_entries > 125) {
        return MIP_ERR_INVALID;
    }
    for (i = 0; i < (size_t)in->num_entries; i++) {
        if ((st = mip_supported_action_type_write(w, &in->entries[i])) != MIP_OK) {
            return st;
        }
    }
    return MIP_OK;
}

void mip_supported_actions_to_json(mip_jw_t *w, const mip_supported_actions_t *in) {
    int first = 1;
    size_t i;
    mip_jw_raw(w, "{", 1);
    mip_jw_key(w, &first, "max_instances");
    mip_jw_u8(w, &in->max_instances);
    mip_jw_key(w, &first, "num_entries");
    mip_jw_u8(w, &in->num_entries);
    mip_jw_key(w, &first, "entries");
    mip_jw_raw(w, "[", 1);
    for (i = 0; i < (size_t)in->num_entries && i < 125; i++) {
        mip_jw_sep(w, i);
        mip_supported_action_type_to_json(w, &in->entries[i]);
    }
    mip_jw_raw(w, "]", 1);
    mip_jw_raw(w, "}", 1);
}

int mip_supported_actions_from_json(mip_jr_t *jr, size_t pos, mip_supported_actions_t *out) {
    static const char *const keys[] = {"max_instances", "num_entries", "entries"};
    size_t vp = 0;
    int found;
    size_t i;
    size_t it = 0;
    size_t ep = 0;
    if (mip_jr_object(jr, pos, keys, 3)) {
        return -1;
    }
    found = mip_jr_get(jr, pos, "max_instances", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"max_instances\"");
    }
    {
        mip_jr_push(jr, "max_instances");
        if (mip_jr_u8(jr, vp, &out->max_instances)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "num_entries", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"num_entries\"");
    }
    {
        mip_jr_push(jr, "num_entries");
        if (mip_jr_u8(jr, vp, &out->num_entries)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "entries", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"entries\"");
    }
    {
        mip_jr_push(jr, "entries");
        if (mip_jr_array(jr, vp, &it)) {
            return -1;
        }
        for (i = 0;; i++) {
            int more = mip_jr_next(jr, &it, &ep);
            if (more < 0) {
                return -1;
            }
            if (!more) {
                break;
            }
            if (i >= 125) {
                return mip_jr_fail(jr, "more than 125 elements");
            }
            mip_jr_index(jr, i);
            if (mip_supported_action_type_from_json(jr, ep, &out->entries[i])) {
                return -1;
            }
        }
        mip_jr_index(jr, SIZE_MAX);
        if (i != (size_t)out->num_entries) {
            return mip_jr_fail(jr, "%zu elements but num_entries is %zu", i, (size_t)out->num_entries);
        }
        mip_jr_pop(jr);
    }
    return 0;
}

/* ---- SupportedTriggerType */

int mip_supported_trigger_type_read(mip_reader_t *r, mip_supported_trigger_type_t *out) {
    mip_rd_push(r, "type");
    if (mip_rd_u8(r, &out->type)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "count");
    if (mip_rd_u8(r, &out->count)) {
        return -1;
    }
    mip_rd_pop(r);
    return 0;
}

mip_status_t mip_supported_trigger_type_write(mip_writer_t *w, const mip_supported_trigger_type_t *in) {
    mip_status_t st;
    if ((st = mip_wr_u8(w, &in->type)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_u8(w, &in->count)) != MIP_OK) {
        return st;
    }
    return MIP_OK;
}

void mip_supported_trigger_type_to_json(mip_jw_t *w, const mip_supported_trigger_type_t *in) {
    int first = 1;
    mip_jw_raw(w, "{", 1);
    mip_jw_key(w, &first, "type");
    mip_jw_u8(w, &in->type);
    mip_jw_key(w, &first, "count");
    mip_jw_u8(w, &in->count);
    mip_jw_raw(w, "}", 1);
}

int mip_supported_trigger_type_from_json(mip_jr_t *jr, size_t pos, mip_supported_trigger_type_t *out) {
    static const char *const keys[] = {"type", "count"};
    size_t vp = 0;
    int found;
    if (mip_jr_object(jr, pos, keys, 2)) {
        return -1;
    }
    found = mip_jr_get(jr, pos, "type", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"type\"");
    }
    {
        mip_jr_push(jr, "type");
        if (mip_jr_u8(jr, vp, &out->type)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "count", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"count\"");
    }
    {
        mip_jr_push(jr, "count");
        if (mip_jr_u8(jr, vp, &out->count)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    return 0;
}

/* ---- SupportedTriggers */

int mip_supported_triggers_read(mip_reader_t *r, mip_supported_triggers_t *out) {
    size_t i;
    mip_rd_push(r, "max_instances");
    if (mip_rd_u8(r, &out->max_instances)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "num_entries");
    if (mip_rd_u8(r, &out->num_entries)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "entries");
    if (out->num_entries > 125) {
        return mip_rd_count_error(r, (uint64_t)out->num_entries, 125);
    }
    for (i = 0; i < (size_t)out->num_entries; i++) {
        mip_rd_index(r, i);
        if (mip_supported_trigger_type_read(r, &out->entries[i])) {
            return -1;
        }
    }
    mip_rd_pop(r);
    return 0;
}

mip_status_t mip_supported_triggers_write(mip_writer_t *w, const mip_supported_triggers_t *in) {
    mip_status_t st;
    size_t i;
    if ((st = mip_wr_u8(w, &in->max_instances)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_u8(w, &in->num_entries)) != MIP_OK) {
        return st;
    }
    if (in->num_entries > 125) {
        return MIP_ERR_INVALID;
    }
    for (i = 0; i < (size_t)in->num_entries; i++) {
        if ((st = mip_supported_trigger_type_write(w, &in->entries[i])) != MIP_OK) {
            return st;
        }
    }
    return MIP_OK;
}

void mip_supported_triggers_to_json(mip_jw_t *w, const mip_supported_triggers_t *in) {
    int first = 1;
    size_t i;
    mip_jw_raw(w, "{", 1);
    mip_jw_key(w, &first, "max_instances");
    mip_jw_u8(w, &in->max_instances);
    mip_jw_key(w, &first, "num_entries");
    mip_jw_u8(w, &in->num_entries);
    mip_jw_key(w, &first, "entries");
    mip_jw_raw(w, "[", 1);
    for (i = 0; i < (size_t)in->num_entries && i < 125; i++) {
        mip_jw_sep(w, i);
        mip_supported_trigger_type_to_json(w, &in->entries[i]);
    }
    mip_jw_raw(w, "]", 1);
    mip_jw_raw(w, "}", 1);
}

int mip_supported_triggers_from_json(mip_jr_t *jr, size_t pos, mip_supported_triggers_t *out) {
    static const char *const keys[] = {"max_instances", "num_entries", "entries"};
    size_t vp = 0;
    int found;
    size_t i;
    size_t it = 0;
    size_t ep = 0;
    if (mip_jr_object(jr, pos, keys, 3)) {
        return -1;
    }
    found = mip_jr_get(jr, pos, "max_instances", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"max_instances\"");
    }
    {
        mip_jr_push(jr, "max_instances");
        if (mip_jr_u8(jr, vp, &out->max_instances)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "num_entries", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"num_entries\"");
    }
    {
        mip_jr_push(jr, "num_entries");
        if (mip_jr_u8(jr, vp, &out->num_entries)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "entries", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"entries\"");
    }
    {
        mip_jr_push(jr, "entries");
        if (mip_jr_array(jr, vp, &it)) {
            return -1;
        }
        for (i = 0;; i++) {
            int more = mip_jr_next(jr, &it, &ep);
            if (more < 0) {
                return -1;
            }
            if (!more) {
                break;
            }
            if (i >= 125) {
                return mip_jr_fail(jr, "more than 125 elements");
            }
            mip_jr_index(jr, i);
            if (mip_supported_trigger_type_from_json(jr, ep, &out->entries[i])) {
                return -1;
            }
        }
        mip_jr_index(jr, SIZE_MAX);
        if (i != (size_t)out->num_entries) {
            return mip_jr_fail(jr, "%zu elements but num_entries is %zu", i, (size_t)out->num_entries);
        }
        mip_jr_pop(jr);
    }
    return 0;
}

/* ---- ThresholdParams */

int mip_threshold_params_read(mip_reader_t *r, mip_threshold_params_t *out) {
    mip_rd_push(r, "desc_set");
    if (mip_rd_u8(r, &out->desc_set)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "field_desc");
    if (mip_rd_u8(r, &out->field_desc)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "param_id");
    if (mip_rd_u8(r, &out->param_id)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "type");
    if (mip_rd_u8(r, &out->type)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "low_thres");
    if (mip_rd_f64(r, &out->low_thres)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "high_thres");
    if (mip_rd_f64(r, &out->high_thres)) {
        return -1;
    }
    mip_rd_pop(r);
    return 0;
}

mip_status_t mip_threshold_params_write(mip_writer_t *w, const mip_threshold_params_t *in) {
    mip_status_t st;
    if ((st = mip_wr_u8(w, &in->desc_set)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_u8(w, &in->field_desc)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_u8(w, &in->param_id)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_u8(w, &in->type)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_f64(w, &in->low_thres)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_f64(w, &in->high_thres)) != MIP_OK) {
        return st;
    }
    return MIP_OK;
}

void mip_threshold_params_to_json(mip_jw_t *w, const mip_threshold_params_t *in) {
    int first = 1;
    mip_jw_raw(w, "{", 1);
    mip_jw_key(w, &first, "desc_set");
    mip_jw_u8(w, &in->desc_set);
    mip_jw_key(w, &first, "field_desc");
    mip_jw_u8(w, &in->field_desc);
    mip_jw_key(w, &first, "param_id");
    mip_jw_u8(w, &in->param_id);
    mip_jw_key(w, &first, "type");
    mip_jw_u8(w, &in->type);
    mip_jw_key(w, &first, "low_thres");
    mip_jw_f64(w, &in->low_thres);
    mip_jw_key(w, &first, "high_thres");
    mip_jw_f64(w, &in->high_thres);
    mip_jw_raw(w, "}", 1);
}

int mip_threshold_params_from_json(mip_jr_t *jr, size_t pos, mip_threshold_params_t *out) {
    static const char *const keys[] = {"desc_set", "field_desc", "param_id",
                                       "type",     "low_thres",  "high_thres"};
    size_t vp = 0;
    int found;
    if (mip_jr_object(jr, pos, keys, 6)) {
        return -1;
    }
    found = mip_jr_get(jr, pos, "desc_set", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"desc_set\"");
    }
    {
        mip_jr_push(jr, "desc_set");
        if (mip_jr_u8(jr, vp, &out->desc_set)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "field_desc", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"field_desc\"");
    }
    {
        mip_jr_push(jr, "field_desc");
        if (mip_jr_u8(jr, vp, &out->field_desc)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "param_id", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"param_id\"");
    }
    {
        mip_jr_push(jr, "param_id");
        if (mip_jr_u8(jr, vp, &out->param_id)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "type", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"type\"");
    }
    {
        mip_jr_push(jr, "type");
        if (mip_jr_u8(jr, vp, &out->type)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "low_thres", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"low_thres\"");
    }
    {
        mip_jr_push(jr, "low_thres");
        if (mip_jr_f64(jr, vp, &out->low_thres)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "high_thres", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"high_thres\"");
    }
    {
        mip_jr_push(jr, "high_thres");
        if (mip_jr_f64(jr, vp, &out->high_thres)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    return 0;
}

/* ---- TriggerGpioParams */

int mip_trigger_gpio_params_read(mip_reader_t *r, mip_trigger_gpio_params_t *out) {
    mip_rd_push(r, "pin");
    if (mip_rd_u8(r, &out->pin)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "mode");
    if (mip_rd_u8(r, &out->mode)) {
        return -1;
    }
    mip_rd_pop(r);
    return 0;
}

mip_status_t mip_trigger_gpio_params_write(mip_writer_t *w, const mip_trigger_gpio_params_t *in) {
    mip_status_t st;
    if ((st = mip_wr_u8(w, &in->pin)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_u8(w, &in->mode)) != MIP_OK) {
        return st;
    }
    return MIP_OK;
}

void mip_trigger_gpio_params_to_json(mip_jw_t *w, const mip_trigger_gpio_params_t *in) {
    int first = 1;
    mip_jw_raw(w, "{", 1);
    mip_jw_key(w, &first, "pin");
    mip_jw_u8(w, &in->pin);
    mip_jw_key(w, &first, "mode");
    mip_jw_u8(w, &in->mode);
    mip_jw_raw(w, "}", 1);
}

int mip_trigger_gpio_params_from_json(mip_jr_t *jr, size_t pos, mip_trigger_gpio_params_t *out) {
    static const char *const keys[] = {"pin", "mode"};
    size_t vp = 0;
    int found;
    if (mip_jr_object(jr, pos, keys, 2)) {
        return -1;
    }
    found = mip_jr_get(jr, pos, "pin", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"pin\"");
    }
    {
        mip_jr_push(jr, "pin");
        if (mip_jr_u8(jr, vp, &out->pin)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "mode", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"mode\"");
    }
    {
        mip_jr_push(jr, "mode");
        if (mip_jr_u8(jr, vp, &out->mode)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    return 0;
}

/* ---- TriggerStatusEntry */

int mip_trigger_status_entry_read(mip_reader_t *r, mip_trigger_status_entry_t *out) {
    mip_rd_push(r, "type");
    if (mip_rd_u8(r, &out->type)) {
        return -1;
    }
    mip_rd_pop(r);
    mip_rd_push(r, "status");
    if (mip_rd_u8(r, &out->status)) {
        return -1;
    }
    mip_rd_pop(r);
    return 0;
}

mip_status_t mip_trigger_status_entry_write(mip_writer_t *w, const mip_trigger_status_entry_t *in) {
    mip_status_t st;
    if ((st = mip_wr_u8(w, &in->type)) != MIP_OK) {
        return st;
    }
    if ((st = mip_wr_u8(w, &in->status)) != MIP_OK) {
        return st;
    }
    return MIP_OK;
}

void mip_trigger_status_entry_to_json(mip_jw_t *w, const mip_trigger_status_entry_t *in) {
    int first = 1;
    mip_jw_raw(w, "{", 1);
    mip_jw_key(w, &first, "type");
    mip_jw_u8(w, &in->type);
    mip_jw_key(w, &first, "status");
    mip_jw_u8(w, &in->status);
    mip_jw_raw(w, "}", 1);
}

int mip_trigger_status_entry_from_json(mip_jr_t *jr, size_t pos, mip_trigger_status_entry_t *out) {
    static const char *const keys[] = {"type", "status"};
    size_t vp = 0;
    int found;
    if (mip_jr_object(jr, pos, keys, 2)) {
        return -1;
    }
    found = mip_jr_get(jr, pos, "type", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"type\"");
    }
    {
        mip_jr_push(jr, "type");
        if (mip_jr_u8(jr, vp, &out->type)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    found = mip_jr_get(jr, pos, "status", &vp);
    if (found != 1) {
        return mip_jr_fail(jr, "missing parameter \"status\"");
    }
    {
        mip_jr_push(jr, "status");
        if (mip_jr_u8(jr, vp, &out->status)) {
            return -1;
        }
        mip_jr_pop(jr);
    }
    return 0;
}

/* ---- ActionParams (selected by mip_action_type_t) */

int mip_action_params_read(mip_reader_t *r, mip_action_type_t selector, mip_action_params_t *out) {
    switch (selector) {
    case MIP_ACTION_TYPE_NONE:
        return 0;
    case MIP_ACTION_TYPE_GPIO:
        return mip_action_gpio_params_read(r, &out->gpio);
    case MIP_ACTION_TYPE_MESSAGE:
        return mip_message_params_read(r, &out->message);
    default:
        return mip_rd_selector_error_u(r, (uint64_t)selector);
    }
}

mip_status_t mip_action_params_write(mip_writer_t *w, mip_action_type_t selector,
                                     const mip_action_params_t *in) {
    switch (selector) {
    case MIP_ACTION_TYPE_NONE:
        return MIP_OK;
    case MIP_ACTION_TYPE_GPIO:
        return mip_action_gpio_params_write(w, &in->gpio);
    case MIP_ACTION_TYPE_MESSAGE:
        return mip_message_params_write(w, &in->message);
    default:
        (void)w;
        (void)in;
        return MIP_ERR_INVALID;
    }
}

void mip_action_params_to_json(mip_jw_t *w, mip_action_type_t selector, const mip_action_params_t *in) {
    switch (selector) {
    case MIP_ACTION_TYPE_GPIO:
        mip_action_gpio_params_to_json(w, &in->gpio);
        return;
    case MIP_ACTION_TYPE_MESSAGE:
        mip_message_params_to_json(w, &in->message);
        return;
    default:
        (void)in;
        mip_jw_lit(w, "null");
        return;
    }
}

int mip_action_params_from_json(mip_jr_t *jr, size_t pos, mip_action_type_t selector,
                                mip_action_params_t *out) {
    switch (selector) {
    case MIP_ACTION_TYPE_NONE:
        return mip_jr_null(jr, pos);
    case MIP_ACTION_TYPE_GPIO:
        return mip_action_gpio_params_from_json(jr, pos, &out->gpio);
    case MIP_ACTION_TYPE_MESSAGE:
        return mip_message_params_from_json(jr, pos, &out->message);
    default:
        (void)pos;
        (void)out;
        return mip_jr_fail(jr, "no member for selector value %llu", (unsigned long long)selector);
    }
}

/* ---- AidingFrameRotation (selected by mip_aiding_frame_format_t) */

int mip_aiding_frame_rotation_read(mip_reader_t *r, mip_aiding_frame_format_t selector,
                                   mip_aiding_frame_rotation_t *out) {
    switch (selector) {
    case MIP_AIDING_FRAME_FORMAT_EULER:
        return mip_aiding_frame_euler_read(r, &out->euler);
    case MIP_AIDING_FRAME_FORMAT_QUATERNION:
        return mip_aiding_frame_quaternion_read(r, &out->quaternion);
    default:
        return mip_rd_selector_error_u(r, (uint64_t)selector);
    }
}

mip_status_t mip_aiding_frame_rotation_write(mip_writer_t *w, mip_aiding_frame_format_t selector,
                                             const mip_aiding_frame_rotation_t *in) {
    switch (selector) {
    case MIP_AIDING_FRAME_FORMAT_EULER:
        return mip_aiding_frame_euler_write(w, &in->euler);
    case MIP_AIDING_FRAME_FORMAT_QUATERNION:
        return mip_aiding_frame_quaternion_write(w, &in->quaternion);
    default:
        (void)w;
        (void)in;
        return MIP_ERR_INVALID;
    }
}

void mip_aiding_frame_rotation_to_json(mip_jw_t *w, mip_aiding_frame_format_t selector,
                                       const mip_aiding_frame_rotation_t *in) {
    switch (selector) {
    case MIP_AIDING_FRAME_FORMAT_EULER:
        mip_aiding_frame_euler_to_json(w, &in->euler);
        return;
    case MIP_AIDING_FRAME_FORMAT_QUATERNION:
        mip_aiding_frame_quaternion_to_json(w, &in->quaternion);
        return;
    default:
        (void)in;
        mip_jw_lit(w, "null");
        return;
    }
}

int mip_aiding_frame_rotation_from_json(mip_jr_t *jr, size_t pos, mip_aiding_frame_format_t selector,
                                        mip_aiding_frame_rotation_t *out) {
    switch (selector) {
    case MIP_AIDING_FRAME_FORMAT_EULER:
        return mip_aiding_frame_euler_from_json(jr, pos, &out->euler);
    case MIP_AIDING_FRAME_FORMAT_QUATERNION:
        return mip_aiding_frame_quaternion_from_json(jr, pos, &out->quaternion);
    default:
        (void)pos;
        (void)out;
        return mip_jr_fail(jr, "no member for selector value %llu", (unsigned long long)selector);
    }
}

/* ---- GpioBehavior (selected by mip_gpio_feature_t) */

int mip_gpio_behavior_read(mip_reader_t *r, mip_gpio_feature_t selector, mip_gpio_behavior_t *out) {
    switch (selector) {
    case MIP_GPIO_FEATURE_UNUSED:
        return mip_gpio_behavior_unused_read(r, &out->unused);
    case MIP_GPIO_FEATURE_GPIO:
        return mip_gpio_behavior_io_read(r, &out->gpio);
    case MIP_GPIO_FEATURE_PPS:
        return mip_gpio_behavior_pps_read(r, &out->pps);
    case MIP_GPIO_FEATURE_ENCODER:
        return mip_gpio_behavior_encoder_read(r, &out->encoder);
    case MIP_GPIO_FEATURE_TIMESTAMP:
        return mip_gpio_behavior_timestamp_read(r, &out->timestamp);
    case MIP_GPIO_FEATURE_UART:
        return mip_gpio_behavior_uart_read(r, &out->uart);
    default:
        return mip_rd_selector_error_u(r, (uint64_t)selector);
    }
}

mip_status_t mip_gpio_behavior_write(mip_writer_t *w, mip_gpio_feature_t selector,
                                     const mip_gpio_behavior_t *in) {
    switch (selector) {
    case MIP_GPIO_FEATURE_UNUSED:
        return mip_gpio_behavior_unused_write(w, &in->unused);
    case MIP_GPIO_FEATURE_GPIO:
        return mip_gpio_behavior_io_write(w, &in->gpio);
    case MIP_GPIO_FEATURE_PPS:
        return mip_gpio_behavior_pps_write(w, &in->pps);
    case MIP_GPIO_FEATURE_ENCODER:
        return mip_gpio_behavior_encoder_write(w, &in->encoder);
    case MIP_GPIO_FEATURE_TIMESTAMP:
        return mip_gpio_behavior_timestamp_write(w, &in->timestamp);
    case MIP_GPIO_FEATURE_UART:
        return mip_gpio_behavior_uart_write(w, &in->uart);
    default:
        (void)w;
        (void)in;
        return MIP_ERR_INVALID;
    }
}

void mip_gpio_behavior_to_json(mip_jw_t *w, mip_gpio_feature_t selector, const mip_gpio_behavior_t *in) {
    switch (selector) {
    case MIP_GPIO_FEATURE_UNUSED:
        mip_gpio_behavior_unused_to_json(w, &in->unused);
        return;
    case MIP_GPIO_FEATURE_GPIO:
        mip_gpio_behavior_io_to_json(w, &in->gpio);
        return;
    case MIP_GPIO_FEATURE_PPS:
        mip_gpio_behavior_pps_to_json(w, &in->pps);
        return;
    case MIP_GPIO_FEATURE_ENCODER:
        mip_gpio_behavior_encoder_to_json(w, &in->encoder);
        return;
    case MIP_GPIO_FEATURE_TIMESTAMP:
        mip_gpio_behavior_timestamp_to_json(w, &in->timestamp);
        return;
    case MIP_GPIO_FEATURE_UART:
        mip_gpio_behavior_uart_to_json(w, &in->uart);
        return;
    default:
        (void)in;
        mip_jw_lit(w, "null");
        return;
    }
}

int mip_gpio_behavior_from_json(mip_jr_t *jr, size_t pos, mip_gpio_feature_t selector,
                                mip_gpio_behavior_t *out) {
    switch (selector) {
    case MIP_GPIO_FEATURE_UNUSED:
        return mip_gpio_behavior_unused_from_json(jr, pos, &out->unused);
    case MIP_GPIO_FEATURE_GPIO:
        return mip_gpio_behavior_io_from_json(jr, pos, &out->gpio);
    case MIP_GPIO_FEATURE_PPS:
        return mip_gpio_behavior_pps_from_json(jr, pos, &out->pps);
    case MIP_GPIO_FEATURE_ENCODER:
        return mip_gpio_behavior_encoder_from_json(jr, pos, &out->encoder);
    case MIP_GPIO_FEATURE_TIMESTAMP:
        return mip_gpio_behavior_timestamp_from_json(jr, pos, &out->timestamp);
    case MIP_GPIO_FEATURE_UART:
        return mip_gpio_behavior_uart_from_json(jr, pos, &out->uart);
    default:
        (void)pos;
        (void)out;
        return mip_jr_fail(jr, "no member for selector value %llu", (unsigned long long)selector);
    }
}

/* ---- Gx5DeviceStatus (selected by mip_device_status_selector_t) */

int mip_gx5_device_status_read(mip_reader_t *r, mip_device_status_selector_t selector,
                               mip_gx5_device_status_t *out) {
    switch (selector) {
    case MIP_DEVICE_STATUS_SELECTOR_BASIC:
        return mip_gx5_basic_status_read(r, &out->basic);
    case MIP_DEVICE_STATUS_SELECTOR_DIAGNOSTIC:
        return mip_gx5_diagnostic_status_read(r, &out->diagnostic);
    default:
        return mip_rd_selector_error_u(r, (uint64_t)selector);
    }
}

mip_status_t mip_gx5_device_status_write(mip_writer_t *w, mip_device_status_selector_t selector,
                                         const mip_gx5_device_status_t *in) {
    switch (selector) {
    case MIP_DEVICE_STATUS_SELECTOR_BASIC:
        return mip_gx5_basic_status_write(w, &in->basic);
    case MIP_DEVICE_STATUS_SELECTOR_DIAGNOSTIC:
        return mip_gx5_diagnostic_status_write(w, &in->diagnostic);
    default:
        (void)w;
        (void)in;
        return MIP_ERR_INVALID;
    }
}

void mip_gx5_device_status_to_json(mip_jw_t *w, mip_device_status_selector_t selector,
                                   const mip_gx5_device_status_t *in) {
    switch (selector) {
    case MIP_DEVICE_STATUS_SELECTOR_BASIC:
        mip_gx5_basic_status_to_json(w, &in->basic);
        return;
    case MIP_DEVICE_STATUS_SELECTOR_DIAGNOSTIC:
        mip_gx5_diagnostic_status_to_json(w, &in->diagnostic);
        return;
    default:
        (void)in;
        mip_jw_lit(w, "null");
        return;
    }
}

int mip_gx5_device_status_from_json(mip_jr_t *jr, size_t pos, mip_device_status_selector_t selector,
                                    mip_gx5_device_status_t *out) {
    switch (selector) {
    case MIP_DEVICE_STATUS_SELECTOR_BASIC:
        return mip_gx5_basic_status_from_json(jr, pos, &out->basic);
    case MIP_DEVICE_STATUS_SELECTOR_DIAGNOSTIC:
        return mip_gx5_diagnostic_status_from_json(jr, pos, &out->diagnostic);
    default:
        (void)pos;
        (void)out;
        return mip_jr_fail(jr, "no member for selector value %llu", (unsigned long long)selector);
    }
}

/* ---- SupportedEventsInfo (selected by mip_supported_events_query_t) */

int mip_supported_events_info_read(mip_reader_t *r, mip_supported_events_query_t selector,
                                   mip_supported_events_info_t *out) {
    switch (selector) {
    case MIP_SUPPORTED_EVENTS_QUERY_TRIGGER_TYPES:
        return mip_supported_triggers_read(r, &out->trigger_types);
    case MIP_SUPPORTED_EVENTS_QUERY_ACTION_TYPES:
        return mip_supported_actions_read(r, &out->action_types);
    default:
        return mip_rd_selector_error_u(r, (uint64_t)selector);
    }
}

mip_status_t mip_supported_events_info_write(mip_writer_t *w, mip_supported_events_query_t selector,
                                             const mip_supported_events_info_t *in) {
    switch (selector) {
    case MIP_SUPPORTED_EVENTS_QUERY_TRIGGER_TYPES:
        return mip_supported_triggers_write(w, &in->trigger_types);
    case MIP_SUPPORTED_EVENTS_QUERY_ACTION_TYPES:
        return mip_supported_actions_write(w, &in->action_types);
    default:
        (void)w;
        (void)in;
        return MIP_ERR_INVALID;
    }
}

void mip_supported_events_info_to_json(mip_jw_t *w, mip_supported_events_query_t selector,
                                       const mip_supported_events_info_t *in) {
    switch (selector) {
    case MIP_SUPPORTED_EVENTS_QUERY_TRIGGER_TYPES:
        mip_supported_triggers_to_json(w, &in->trigger_types);
        return;
    case MIP_SUPPORTED_EVENTS_QUERY_ACTION_TYPES:
        mip_supported_actions_to_json(w, &in->action_types);
        return;
    default:
        (void)in;
        mip_jw_lit(w, "null");
        return;
    }
}

int mip_supported_events_info_from_json(mip_jr_t *jr, size_t pos, mip_supported_events_query_t selector,
                                        mip_supported_events_info_t *out) {
    switch (selector) {
    case MIP_SUPPORTED_EVENTS_QUERY_TRIGGER_TYPES:
        return mip_supported_triggers_from_json(jr, pos, &out->trigger_types);
    case MIP_SUPPORTED_EVENTS_QUERY_ACTION_TYPES:
        return mip_supported_actions_from_json(jr, pos, &out->action_types);
    default:
        (void)pos;
        (void)out;
        return mip_jr_fail(jr, "no member for selector value %llu", (unsigned long long)selector);
    }
}

/* ---- TriggerParams (selected by mip_trigger_type_t) */

int mip_trigger_params_read(mip_reader_t *r, mip_trigger_type_t selector, mip_trigger_params_t *out) {
    switch (selector) {
    case MIP_TRIGGER_TYPE_NONE:
        return 0;
    case MIP_TRIGGER_TYPE_GPIO:
        return mip_trigger_gpio_params_read(r, &out->gpio);
    case MIP_TRIGGER_TYPE_THRESHOLD:
        return mip_threshold_params_read(r, &out->threshold);
    case MIP_TRIGGER_TYPE_COMBINATION:
        return mip_combination_params_read(r, &out->combination);
    default:
        return mip_rd_selector_error_u(r, (uint64_t)selector);
    }
}

mip_status_t mip_trigger_params_write(mip_writer_t *w, mip_trigger_type_t selector,
                                      const mip_trigger_params_t *in) {
    switch (selector) {
    case MIP_TRIGGER_TYPE_NONE:
        return MIP_OK;
    case MIP_TRIGGER_TYPE_GPIO:
        return mip_trigger_gpio_params_write(w, &in->gpio);
    case MIP_TRIGGER_TYPE_THRESHOLD:
        return mip_threshold_params_write(w, &in->threshold);
    case MIP_TRIGGER_TYPE_COMBINATION:
        return mip_combination_params_write(w, &in->combination);
    default:
        (void)w;
        (void)in;
        return MIP_ERR_INVALID;
    }
}

void mip_trigger_params_to_json(mip_jw_t *w, mip_trigger_type_t selector, const mip_trigger_params_t *in) {
    switch (selector) {
    case MIP_TRIGGER_TYPE_GPIO:
        mip_trigger_gpio_params_to_json(w, &in->gpio);
        return;
    case MIP_TRIGGER_TYPE_THRESHOLD:
        mip_threshold_params_to_json(w, &in->threshold);
        return;
    case MIP_TRIGGER_TYPE_COMBINATION:
        mip_combination_params_to_json(w, &in->combination);
        return;
    default:
        (void)in;
        mip_jw_lit(w, "null");
        return;
    }
}

int mip_trigger_params_from_json(mip_jr_t *jr, size_t pos, mip_trigger_type_t selector,
                                 mip_trigger_params_t *out) {
    switch (selector) {
    case MIP_TRIGGER_TYPE_NONE:
        return mip_jr_null(jr, pos);
    case MIP_TRIGGER_TYPE_GPIO:
        return mip_trigger_gpio_params_from_json(jr, pos, &out->gpio);
    case MIP_TRIGGER_TYPE_THRESHOLD:
        return mip_threshold_params_from_json(jr, pos, &out->threshold);
    case MIP_TRIGGER_TYPE_COMBINATION:
        return mip_combination_params_from_json(jr, pos, &out->combination);
    default:
        (void)pos;
        (void)out;
        return mip_jr_fail(jr, "no member for selector value %llu", (unsigned long long)selector);
    }
}
