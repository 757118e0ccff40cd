/* Canonical JSON of Base Messages (the mscipcodec_json library). Generated from the spec: do not edit. */
#include "mscipcodec/sets/base.h"
#include "layouts_internal.h"
#include "types_internal.h"

#include <assert.h>
#include <string.h>

/* ---- mscipc_base_ping_t */

void mscipc_base_ping_to_json(mscipc_jw_t *w, const mscipc_base_ping_t *in) {
    int first = 1;
    mscipc_jw_raw(w, "{", 1);
    mscipc_jw_raw(w, "}", 1);
    (void)in;
    (void)first;
}

int mscipc_base_ping_from_json(mscipc_jr_t *jr, size_t pos, mscipc_base_ping_t *out) {
    memset(out, 0, sizeof *out);
    if (mscipc_jr_object(jr, pos, NULL, 0)) {
        return -1;
    }
    return 0;
}

/* ---- mscipc_base_get_device_messages_t */

void mscipc_base_get_device_messages_to_json(mscipc_jw_t *w, const mscipc_base_get_device_messages_t *in) {
    int first = 1;
    mscipc_jw_raw(w, "{", 1);
    mscipc_jw_raw(w, "}", 1);
    (void)in;
    (void)first;
}

int mscipc_base_get_device_messages_from_json(mscipc_jr_t *jr, size_t pos,
                                              mscipc_base_get_device_messages_t *out) {
    memset(out, 0, sizeof *out);
    if (mscipc_jr_object(jr, pos, NULL, 0)) {
        return -1;
    }
    return 0;
}

/* ---- mscipc_base_device_messages_t */

void mscipc_base_device_messages_to_json(mscipc_jw_t *w, const mscipc_base_device_messages_t *in) {
    int first = 1;
    size_t i;
    mscipc_jw_raw(w, "{", 1);
    mscipc_jw_key(w, &first, "messages");
    mscipc_jw_raw(w, "[", 1);
    for (i = 0; i < (size_t)in->messages_count && i < 126; i++) {
        mscipc_jw_sep(w, i);
        mscipc_message_id_to_json(w, &in->messages[i]);
    }
    mscipc_jw_raw(w, "]", 1);
    mscipc_jw_raw(w, "}", 1);
}

int mscipc_base_device_messages_from_json(mscipc_jr_t *jr, size_t pos, mscipc_base_device_messages_t *out) {
    static const char *const keys[] = {"messages"};
    size_t vp = 0;
    int found;
    size_t i;
    size_t it = 0;
    size_t ep = 0;
    memset(out, 0, sizeof *out);
    if (mscipc_jr_object(jr, pos, keys, 1)) {
        return -1;
    }
    found = mscipc_jr_get(jr, pos, "messages", &vp);
    if (found != 1) {
        return mscipc_jr_fail(jr, "missing parameter \"messages\"");
    }
    {
        mscipc_jr_push(jr, "messages");
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
            if (i >= 126) {
                return mscipc_jr_fail(jr, "more than 126 elements");
            }
            mscipc_jr_index(jr, i);
            if (mscipc_message_id_from_json(jr, ep, &out->messages[i])) {
                return -1;
            }
        }
        mscipc_jr_index(jr, SIZE_MAX);
        out->messages_count = i;
        mscipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mscipc_base_device_reset_t */

void mscipc_base_device_reset_to_json(mscipc_jw_t *w, const mscipc_base_device_reset_t *in) {
    int first = 1;
    mscipc_jw_raw(w, "{", 1);
    mscipc_jw_raw(w, "}", 1);
    (void)in;
    (void)first;
}

int mscipc_base_device_reset_from_json(mscipc_jr_t *jr, size_t pos, mscipc_base_device_reset_t *out) {
    memset(out, 0, sizeof *out);
    if (mscipc_jr_object(jr, pos, NULL, 0)) {
        return -1;
    }
    return 0;
}

/* ---- mscipc_base_get_device_model_t */

void mscipc_base_get_device_model_to_json(mscipc_jw_t *w, const mscipc_base_get_device_model_t *in) {
    int first = 1;
    mscipc_jw_raw(w, "{", 1);
    mscipc_jw_raw(w, "}", 1);
    (void)in;
    (void)first;
}

int mscipc_base_get_device_model_from_json(mscipc_jr_t *jr, size_t pos, mscipc_base_get_device_model_t *out) {
    memset(out, 0, sizeof *out);
    if (mscipc_jr_object(jr, pos, NULL, 0)) {
        return -1;
    }
    return 0;
}

/* ---- mscipc_base_device_model_t */

void mscipc_base_device_model_to_json(mscipc_jw_t *w, const mscipc_base_device_model_t *in) {
    int first = 1;
    mscipc_jw_raw(w, "{", 1);
    mscipc_jw_key(w, &first, "model");
    mscipc_jw_chars(w, in->model, 16);
    mscipc_jw_raw(w, "}", 1);
}

int mscipc_base_device_model_from_json(mscipc_jr_t *jr, size_t pos, mscipc_base_device_model_t *out) {
    static const char *const keys[] = {"model"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mscipc_jr_object(jr, pos, keys, 1)) {
        return -1;
    }
    found = mscipc_jr_get(jr, pos, "model", &vp);
    if (found != 1) {
        return mscipc_jr_fail(jr, "missing parameter \"model\"");
    }
    {
        mscipc_jr_push(jr, "model");
        if (mscipc_jr_chars(jr, vp, out->model, 16)) {
            return -1;
        }
        mscipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mscipc_base_get_device_sn_t */

void mscipc_base_get_device_sn_to_json(mscipc_jw_t *w, const mscipc_base_get_device_sn_t *in) {
    int first = 1;
    mscipc_jw_raw(w, "{", 1);
    mscipc_jw_raw(w, "}", 1);
    (void)in;
    (void)first;
}

int mscipc_base_get_device_sn_from_json(mscipc_jr_t *jr, size_t pos, mscipc_base_get_device_sn_t *out) {
    memset(out, 0, sizeof *out);
    if (mscipc_jr_object(jr, pos, NULL, 0)) {
        return -1;
    }
    return 0;
}

/* ---- mscipc_base_device_sn_t */

void mscipc_base_device_sn_to_json(mscipc_jw_t *w, const mscipc_base_device_sn_t *in) {
    int first = 1;
    mscipc_jw_raw(w, "{", 1);
    mscipc_jw_key(w, &first, "serial_number");
    mscipc_jw_chars(w, in->serial_number, 16);
    mscipc_jw_raw(w, "}", 1);
}

int mscipc_base_device_sn_from_json(mscipc_jr_t *jr, size_t pos, mscipc_base_device_sn_t *out) {
    static const char *const keys[] = {"serial_number"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mscipc_jr_object(jr, pos, keys, 1)) {
        return -1;
    }
    found = mscipc_jr_get(jr, pos, "serial_number", &vp);
    if (found != 1) {
        return mscipc_jr_fail(jr, "missing parameter \"serial_number\"");
    }
    {
        mscipc_jr_push(jr, "serial_number");
        if (mscipc_jr_chars(jr, vp, out->serial_number, 16)) {
            return -1;
        }
        mscipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mscipc_base_get_device_fw_t */

void mscipc_base_get_device_fw_to_json(mscipc_jw_t *w, const mscipc_base_get_device_fw_t *in) {
    int first = 1;
    mscipc_jw_raw(w, "{", 1);
    mscipc_jw_raw(w, "}", 1);
    (void)in;
    (void)first;
}

int mscipc_base_get_device_fw_from_json(mscipc_jr_t *jr, size_t pos, mscipc_base_get_device_fw_t *out) {
    memset(out, 0, sizeof *out);
    if (mscipc_jr_object(jr, pos, NULL, 0)) {
        return -1;
    }
    return 0;
}

/* ---- mscipc_base_device_fw_t */

void mscipc_base_device_fw_to_json(mscipc_jw_t *w, const mscipc_base_device_fw_t *in) {
    int first = 1;
    mscipc_jw_raw(w, "{", 1);
    mscipc_jw_key(w, &first, "firmware");
    mscipc_jw_chars(w, in->firmware, 16);
    mscipc_jw_raw(w, "}", 1);
}

int mscipc_base_device_fw_from_json(mscipc_jr_t *jr, size_t pos, mscipc_base_device_fw_t *out) {
    static const char *const keys[] = {"firmware"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mscipc_jr_object(jr, pos, keys, 1)) {
        return -1;
    }
    found = mscipc_jr_get(jr, pos, "firmware", &vp);
    if (found != 1) {
        return mscipc_jr_fail(jr, "missing parameter \"firmware\"");
    }
    {
        mscipc_jr_push(jr, "firmware");
        if (mscipc_jr_chars(jr, vp, out->firmware, 16)) {
            return -1;
        }
        mscipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mscipc_base_get_device_cal_t */

void mscipc_base_get_device_cal_to_json(mscipc_jw_t *w, const mscipc_base_get_device_cal_t *in) {
    int first = 1;
    mscipc_jw_raw(w, "{", 1);
    mscipc_jw_raw(w, "}", 1);
    (void)in;
    (void)first;
}

int mscipc_base_get_device_cal_from_json(mscipc_jr_t *jr, size_t pos, mscipc_base_get_device_cal_t *out) {
    memset(out, 0, sizeof *out);
    if (mscipc_jr_object(jr, pos, NULL, 0)) {
        return -1;
    }
    return 0;
}

/* ---- mscipc_base_device_cal_t */

void mscipc_base_device_cal_to_json(mscipc_jw_t *w, const mscipc_base_device_cal_t *in) {
    int first = 1;
    mscipc_jw_raw(w, "{", 1);
    mscipc_jw_key(w, &first, "date");
    mscipc_jw_chars(w, in->date, 16);
    mscipc_jw_raw(w, "}", 1);
}

int mscipc_base_device_cal_from_json(mscipc_jr_t *jr, size_t pos, mscipc_base_device_cal_t *out) {
    static const char *const keys[] = {"date"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mscipc_jr_object(jr, pos, keys, 1)) {
        return -1;
    }
    found = mscipc_jr_get(jr, pos, "date", &vp);
    if (found != 1) {
        return mscipc_jr_fail(jr, "missing parameter \"date\"");
    }
    {
        mscipc_jr_push(jr, "date");
        if (mscipc_jr_chars(jr, vp, out->date, 16)) {
            return -1;
        }
        mscipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mscipc_base_correlate_gps_time_t */

void mscipc_base_correlate_gps_time_to_json(mscipc_jw_t *w, const mscipc_base_correlate_gps_time_t *in) {
    int first = 1;
    mscipc_jw_raw(w, "{", 1);
    mscipc_jw_key(w, &first, "week");
    mscipc_jw_u16(w, &in->week);
    mscipc_jw_key(w, &first, "seconds");
    mscipc_jw_u32(w, &in->seconds);
    mscipc_jw_raw(w, "}", 1);
}

int mscipc_base_correlate_gps_time_from_json(mscipc_jr_t *jr, size_t pos,
                                             mscipc_base_correlate_gps_time_t *out) {
    static const char *const keys[] = {"week", "seconds"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mscipc_jr_object(jr, pos, keys, 2)) {
        return -1;
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
    found = mscipc_jr_get(jr, pos, "seconds", &vp);
    if (found != 1) {
        return mscipc_jr_fail(jr, "missing parameter \"seconds\"");
    }
    {
        mscipc_jr_push(jr, "seconds");
        if (mscipc_jr_u32(jr, vp, &out->seconds)) {
            return -1;
        }
        mscipc_jr_pop(jr);
    }
    return 0;
}
