/* Canonical JSON of GNSS Command Set (the mipcodec_json library). Generated from the spec: do not edit. */
#include "mipcodec/sets/gnss.h"
#include "layouts_internal.h"
#include "types_internal.h"

#include <assert.h>
#include <string.h>

/* ---- mipc_gnss_receiver_info_t */

void mipc_gnss_receiver_info_to_json(mipc_jw_t *w, const mipc_gnss_receiver_info_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_raw(w, "}", 1);
    (void)in;
    (void)first;
}

int mipc_gnss_receiver_info_from_json(mipc_jr_t *jr, size_t pos, mipc_gnss_receiver_info_t *out) {
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, NULL, 0)) {
        return -1;
    }
    return 0;
}

/* ---- mipc_gnss_receiver_info_response_t */

void mipc_gnss_receiver_info_response_to_json(mipc_jw_t *w, const mipc_gnss_receiver_info_response_t *in) {
    int first = 1;
    size_t i;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "num_receivers");
    mipc_jw_u8(w, &in->num_receivers);
    mipc_jw_key(w, &first, "receiver_info");
    mipc_jw_raw(w, "[", 1);
    for (i = 0; i < (size_t)in->num_receivers && i < 7; i++) {
        mipc_jw_sep(w, i);
        mipc_gnss_receiver_info_entry_to_json(w, &in->receiver_info[i]);
    }
    mipc_jw_raw(w, "]", 1);
    mipc_jw_raw(w, "}", 1);
}

int mipc_gnss_receiver_info_response_from_json(mipc_jr_t *jr, size_t pos,
                                               mipc_gnss_receiver_info_response_t *out) {
    static const char *const keys[] = {"num_receivers", "receiver_info"};
    size_t vp = 0;
    int found;
    size_t i;
    size_t it = 0;
    size_t ep = 0;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 2)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "num_receivers", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"num_receivers\"");
    }
    {
        mipc_jr_push(jr, "num_receivers");
        if (mipc_jr_u8(jr, vp, &out->num_receivers)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "receiver_info", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"receiver_info\"");
    }
    {
        mipc_jr_push(jr, "receiver_info");
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
            if (i >= 7) {
                return mipc_jr_fail(jr, "more than 7 elements");
            }
            mipc_jr_index(jr, i);
            if (mipc_gnss_receiver_info_entry_from_json(jr, ep, &out->receiver_info[i])) {
                return -1;
            }
        }
        mipc_jr_index(jr, SIZE_MAX);
        if (i != (size_t)out->num_receivers) {
            return mipc_jr_fail(jr, "%zu elements but num_receivers is %zu", i, (size_t)out->num_receivers);
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mipc_gnss_signal_configuration_t */

void mipc_gnss_signal_configuration_to_json(mipc_jw_t *w, const mipc_gnss_signal_configuration_t *in) {
    int first = 1;
    size_t i;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "function");
    mipc_jw_u8(w, &in->function);
    if (in->has_gps_enable) {
        mipc_jw_key(w, &first, "gps_enable");
        mipc_jw_u8(w, &in->gps_enable);
    }
    if (in->has_glonass_enable) {
        mipc_jw_key(w, &first, "glonass_enable");
        mipc_jw_u8(w, &in->glonass_enable);
    }
    if (in->has_galileo_enable) {
        mipc_jw_key(w, &first, "galileo_enable");
        mipc_jw_u8(w, &in->galileo_enable);
    }
    if (in->has_beidou_enable) {
        mipc_jw_key(w, &first, "beidou_enable");
        mipc_jw_u8(w, &in->beidou_enable);
    }
    if (in->has_reserved) {
        mipc_jw_key(w, &first, "reserved");
        mipc_jw_raw(w, "[", 1);
        for (i = 0; i < 4; i++) {
            mipc_jw_sep(w, i);
            mipc_jw_u8(w, &in->reserved[i]);
        }
        mipc_jw_raw(w, "]", 1);
    }
    mipc_jw_raw(w, "}", 1);
}

int mipc_gnss_signal_configuration_from_json(mipc_jr_t *jr, size_t pos,
                                             mipc_gnss_signal_configuration_t *out) {
    static const char *const keys[] = {"function",       "gps_enable",    "glonass_enable",
                                       "galileo_enable", "beidou_enable", "reserved"};
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
    found = mipc_jr_get(jr, pos, "gps_enable", &vp);
    out->has_gps_enable = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mipc_jr_fail(jr, "optional parameter \"gps_enable\" given after an absent one");
    } else {
        mipc_jr_push(jr, "gps_enable");
        if (mipc_jr_u8(jr, vp, &out->gps_enable)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "glonass_enable", &vp);
    out->has_glonass_enable = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mipc_jr_fail(jr, "optional parameter \"glonass_enable\" given after an absent one");
    } else {
        mipc_jr_push(jr, "glonass_enable");
        if (mipc_jr_u8(jr, vp, &out->glonass_enable)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "galileo_enable", &vp);
    out->has_galileo_enable = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mipc_jr_fail(jr, "optional parameter \"galileo_enable\" given after an absent one");
    } else {
        mipc_jr_push(jr, "galileo_enable");
        if (mipc_jr_u8(jr, vp, &out->galileo_enable)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "beidou_enable", &vp);
    out->has_beidou_enable = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mipc_jr_fail(jr, "optional parameter \"beidou_enable\" given after an absent one");
    } else {
        mipc_jr_push(jr, "beidou_enable");
        if (mipc_jr_u8(jr, vp, &out->beidou_enable)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "reserved", &vp);
    out->has_reserved = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mipc_jr_fail(jr, "optional parameter \"reserved\" given after an absent one");
    } else {
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
            if (i >= 4) {
                return mipc_jr_fail(jr, "more than 4 elements");
            }
            mipc_jr_index(jr, i);
            if (mipc_jr_u8(jr, ep, &out->reserved[i])) {
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

/* ---- mipc_gnss_signal_configuration_response_t */

void mipc_gnss_signal_configuration_response_to_json(mipc_jw_t *w,
                                                     const mipc_gnss_signal_configuration_response_t *in) {
    int first = 1;
    size_t i;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "gps_enable");
    mipc_jw_u8(w, &in->gps_enable);
    mipc_jw_key(w, &first, "glonass_enable");
    mipc_jw_u8(w, &in->glonass_enable);
    mipc_jw_key(w, &first, "galileo_enable");
    mipc_jw_u8(w, &in->galileo_enable);
    mipc_jw_key(w, &first, "beidou_enable");
    mipc_jw_u8(w, &in->beidou_enable);
    mipc_jw_key(w, &first, "reserved");
    mipc_jw_raw(w, "[", 1);
    for (i = 0; i < 4; i++) {
        mipc_jw_sep(w, i);
        mipc_jw_u8(w, &in->reserved[i]);
    }
    mipc_jw_raw(w, "]", 1);
    mipc_jw_raw(w, "}", 1);
}

int mipc_gnss_signal_configuration_response_from_json(mipc_jr_t *jr, size_t pos,
                                                      mipc_gnss_signal_configuration_response_t *out) {
    static const char *const keys[] = {"gps_enable", "glonass_enable", "galileo_enable", "beidou_enable",
                                       "reserved"};
    size_t vp = 0;
    int found;
    size_t i;
    size_t it = 0;
    size_t ep = 0;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 5)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "gps_enable", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"gps_enable\"");
    }
    {
        mipc_jr_push(jr, "gps_enable");
        if (mipc_jr_u8(jr, vp, &out->gps_enable)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "glonass_enable", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"glonass_enable\"");
    }
    {
        mipc_jr_push(jr, "glonass_enable");
        if (mipc_jr_u8(jr, vp, &out->glonass_enable)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "galileo_enable", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"galileo_enable\"");
    }
    {
        mipc_jr_push(jr, "galileo_enable");
        if (mipc_jr_u8(jr, vp, &out->galileo_enable)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "beidou_enable", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"beidou_enable\"");
    }
    {
        mipc_jr_push(jr, "beidou_enable");
        if (mipc_jr_u8(jr, vp, &out->beidou_enable)) {
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
            if (i >= 4) {
                return mipc_jr_fail(jr, "more than 4 elements");
            }
            mipc_jr_index(jr, i);
            if (mipc_jr_u8(jr, ep, &out->reserved[i])) {
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

/* ---- mipc_gnss_spartn_configuration_t */

void mipc_gnss_spartn_configuration_to_json(mipc_jw_t *w, const mipc_gnss_spartn_configuration_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "function");
    mipc_jw_u8(w, &in->function);
    if (in->has_enable) {
        mipc_jw_key(w, &first, "enable");
        mipc_jw_u8(w, &in->enable);
    }
    if (in->has_type) {
        mipc_jw_key(w, &first, "type");
        mipc_jw_u8(w, &in->type);
    }
    if (in->has_current_key_tow) {
        mipc_jw_key(w, &first, "current_key_tow");
        mipc_jw_u32(w, &in->current_key_tow);
    }
    if (in->has_current_key_week) {
        mipc_jw_key(w, &first, "current_key_week");
        mipc_jw_u16(w, &in->current_key_week);
    }
    if (in->has_current_key) {
        mipc_jw_key(w, &first, "current_key");
        mipc_jw_chars(w, in->current_key, 32);
    }
    if (in->has_next_key_tow) {
        mipc_jw_key(w, &first, "next_key_tow");
        mipc_jw_u32(w, &in->next_key_tow);
    }
    if (in->has_next_key_week) {
        mipc_jw_key(w, &first, "next_key_week");
        mipc_jw_u16(w, &in->next_key_week);
    }
    if (in->has_next_key) {
        mipc_jw_key(w, &first, "next_key");
        mipc_jw_chars(w, in->next_key, 32);
    }
    mipc_jw_raw(w, "}", 1);
}

int mipc_gnss_spartn_configuration_from_json(mipc_jr_t *jr, size_t pos,
                                             mipc_gnss_spartn_configuration_t *out) {
    static const char *const keys[] = {"function",        "enable",           "type",
                                       "current_key_tow", "current_key_week", "current_key",
                                       "next_key_tow",    "next_key_week",    "next_key"};
    size_t vp = 0;
    int found;
    int absent = 0;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 9)) {
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
    found = mipc_jr_get(jr, pos, "type", &vp);
    out->has_type = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mipc_jr_fail(jr, "optional parameter \"type\" given after an absent one");
    } else {
        mipc_jr_push(jr, "type");
        if (mipc_jr_u8(jr, vp, &out->type)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "current_key_tow", &vp);
    out->has_current_key_tow = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mipc_jr_fail(jr, "optional parameter \"current_key_tow\" given after an absent one");
    } else {
        mipc_jr_push(jr, "current_key_tow");
        if (mipc_jr_u32(jr, vp, &out->current_key_tow)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "current_key_week", &vp);
    out->has_current_key_week = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mipc_jr_fail(jr, "optional parameter \"current_key_week\" given after an absent one");
    } else {
        mipc_jr_push(jr, "current_key_week");
        if (mipc_jr_u16(jr, vp, &out->current_key_week)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "current_key", &vp);
    out->has_current_key = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mipc_jr_fail(jr, "optional parameter \"current_key\" given after an absent one");
    } else {
        mipc_jr_push(jr, "current_key");
        if (mipc_jr_chars(jr, vp, out->current_key, 32)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "next_key_tow", &vp);
    out->has_next_key_tow = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mipc_jr_fail(jr, "optional parameter \"next_key_tow\" given after an absent one");
    } else {
        mipc_jr_push(jr, "next_key_tow");
        if (mipc_jr_u32(jr, vp, &out->next_key_tow)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "next_key_week", &vp);
    out->has_next_key_week = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mipc_jr_fail(jr, "optional parameter \"next_key_week\" given after an absent one");
    } else {
        mipc_jr_push(jr, "next_key_week");
        if (mipc_jr_u16(jr, vp, &out->next_key_week)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "next_key", &vp);
    out->has_next_key = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return mipc_jr_fail(jr, "optional parameter \"next_key\" given after an absent one");
    } else {
        mipc_jr_push(jr, "next_key");
        if (mipc_jr_chars(jr, vp, out->next_key, 32)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mipc_gnss_spartn_configuration_response_t */

void mipc_gnss_spartn_configuration_response_to_json(mipc_jw_t *w,
                                                     const mipc_gnss_spartn_configuration_response_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "enable");
    mipc_jw_u8(w, &in->enable);
    mipc_jw_key(w, &first, "type");
    mipc_jw_u8(w, &in->type);
    mipc_jw_key(w, &first, "current_key_tow");
    mipc_jw_u32(w, &in->current_key_tow);
    mipc_jw_key(w, &first, "current_key_week");
    mipc_jw_u16(w, &in->current_key_week);
    mipc_jw_key(w, &first, "current_key");
    mipc_jw_chars(w, in->current_key, 32);
    mipc_jw_key(w, &first, "next_key_tow");
    mipc_jw_u32(w, &in->next_key_tow);
    mipc_jw_key(w, &first, "next_key_week");
    mipc_jw_u16(w, &in->next_key_week);
    mipc_jw_key(w, &first, "next_key");
    mipc_jw_chars(w, in->next_key, 32);
    mipc_jw_raw(w, "}", 1);
}

int mipc_gnss_spartn_configuration_response_from_json(mipc_jr_t *jr, size_t pos,
                                                      mipc_gnss_spartn_configuration_response_t *out) {
    static const char *const keys[] = {"enable",      "type",         "current_key_tow", "current_key_week",
                                       "current_key", "next_key_tow", "next_key_week",   "next_key"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 8)) {
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
    found = mipc_jr_get(jr, pos, "current_key_tow", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"current_key_tow\"");
    }
    {
        mipc_jr_push(jr, "current_key_tow");
        if (mipc_jr_u32(jr, vp, &out->current_key_tow)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "current_key_week", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"current_key_week\"");
    }
    {
        mipc_jr_push(jr, "current_key_week");
        if (mipc_jr_u16(jr, vp, &out->current_key_week)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "current_key", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"current_key\"");
    }
    {
        mipc_jr_push(jr, "current_key");
        if (mipc_jr_chars(jr, vp, out->current_key, 32)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "next_key_tow", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"next_key_tow\"");
    }
    {
        mipc_jr_push(jr, "next_key_tow");
        if (mipc_jr_u32(jr, vp, &out->next_key_tow)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "next_key_week", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"next_key_week\"");
    }
    {
        mipc_jr_push(jr, "next_key_week");
        if (mipc_jr_u16(jr, vp, &out->next_key_week)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "next_key", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"next_key\"");
    }
    {
        mipc_jr_push(jr, "next_key");
        if (mipc_jr_chars(jr, vp, out->next_key, 32)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    return 0;
}
