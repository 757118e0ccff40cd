/* Canonical JSON of GNSS Corrections Data Set (the mipcodec_json library). Generated from the spec: do not
 * edit. */
#include "mipcodec/sets/gnss_corrections.h"
#include "layouts_internal.h"
#include "types_internal.h"

#include <assert.h>
#include <string.h>

/* ---- mipc_gnss_corrections_base_station_info_t */

void mipc_gnss_corrections_base_station_info_to_json(mipc_jw_t *w,
                                                     const mipc_gnss_corrections_base_station_info_t *in) {
    int first = 1;
    size_t i;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "tow");
    mipc_jw_f64(w, &in->tow);
    mipc_jw_key(w, &first, "week_number");
    mipc_jw_u16(w, &in->week_number);
    mipc_jw_key(w, &first, "ecef_position");
    mipc_jw_raw(w, "[", 1);
    for (i = 0; i < 3; i++) {
        mipc_jw_sep(w, i);
        mipc_jw_f64(w, &in->ecef_position[i]);
    }
    mipc_jw_raw(w, "]", 1);
    mipc_jw_key(w, &first, "height");
    mipc_jw_f32(w, &in->height);
    mipc_jw_key(w, &first, "station_id");
    mipc_jw_u16(w, &in->station_id);
    mipc_jw_key(w, &first, "indicators");
    mipc_jw_u16(w, &in->indicators);
    mipc_jw_key(w, &first, "valid_flags");
    mipc_jw_u16(w, &in->valid_flags);
    mipc_jw_raw(w, "}", 1);
}

int mipc_gnss_corrections_base_station_info_from_json(mipc_jr_t *jr, size_t pos,
                                                      mipc_gnss_corrections_base_station_info_t *out) {
    static const char *const keys[] = {"tow",        "week_number", "ecef_position", "height",
                                       "station_id", "indicators",  "valid_flags"};
    size_t vp = 0;
    int found;
    size_t i;
    size_t it = 0;
    size_t ep = 0;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 7)) {
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
    found = mipc_jr_get(jr, pos, "ecef_position", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"ecef_position\"");
    }
    {
        mipc_jr_push(jr, "ecef_position");
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
            if (mipc_jr_f64(jr, ep, &out->ecef_position[i])) {
                return -1;
            }
        }
        mipc_jr_index(jr, SIZE_MAX);
        if (i != 3) {
            return mipc_jr_fail(jr, "expected 3 elements, got %zu", i);
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
    found = mipc_jr_get(jr, pos, "station_id", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"station_id\"");
    }
    {
        mipc_jr_push(jr, "station_id");
        if (mipc_jr_u16(jr, vp, &out->station_id)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "indicators", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"indicators\"");
    }
    {
        mipc_jr_push(jr, "indicators");
        if (mipc_jr_u16(jr, vp, &out->indicators)) {
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

/* ---- mipc_gnss_corrections_rtk_corrections_status_t */

void mipc_gnss_corrections_rtk_corrections_status_to_json(
    mipc_jw_t *w, const mipc_gnss_corrections_rtk_corrections_status_t *in) {
    int first = 1;
    size_t i;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "tow");
    mipc_jw_f64(w, &in->tow);
    mipc_jw_key(w, &first, "week_number");
    mipc_jw_u16(w, &in->week_number);
    mipc_jw_key(w, &first, "epoch_status");
    mipc_jw_u16(w, &in->epoch_status);
    mipc_jw_key(w, &first, "dongle_status");
    mipc_jw_u32(w, &in->dongle_status);
    mipc_jw_key(w, &first, "gps_correction_latency");
    mipc_jw_f32(w, &in->gps_correction_latency);
    mipc_jw_key(w, &first, "glonass_correction_latency");
    mipc_jw_f32(w, &in->glonass_correction_latency);
    mipc_jw_key(w, &first, "galileo_correction_latency");
    mipc_jw_f32(w, &in->galileo_correction_latency);
    mipc_jw_key(w, &first, "beidou_correction_latency");
    mipc_jw_f32(w, &in->beidou_correction_latency);
    mipc_jw_key(w, &first, "reserved");
    mipc_jw_raw(w, "[", 1);
    for (i = 0; i < 4; i++) {
        mipc_jw_sep(w, i);
        mipc_jw_u32(w, &in->reserved[i]);
    }
    mipc_jw_raw(w, "]", 1);
    mipc_jw_key(w, &first, "valid_flags");
    mipc_jw_u16(w, &in->valid_flags);
    mipc_jw_raw(w, "}", 1);
}

int mipc_gnss_corrections_rtk_corrections_status_from_json(
    mipc_jr_t *jr, size_t pos, mipc_gnss_corrections_rtk_corrections_status_t *out) {
    static const char *const keys[] = {"tow",
                                       "week_number",
                                       "epoch_status",
                                       "dongle_status",
                                       "gps_correction_latency",
                                       "glonass_correction_latency",
                                       "galileo_correction_latency",
                                       "beidou_correction_latency",
                                       "reserved",
                                       "valid_flags"};
    size_t vp = 0;
    int found;
    size_t i;
    size_t it = 0;
    size_t ep = 0;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 10)) {
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
    found = mipc_jr_get(jr, pos, "epoch_status", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"epoch_status\"");
    }
    {
        mipc_jr_push(jr, "epoch_status");
        if (mipc_jr_u16(jr, vp, &out->epoch_status)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "dongle_status", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"dongle_status\"");
    }
    {
        mipc_jr_push(jr, "dongle_status");
        if (mipc_jr_u32(jr, vp, &out->dongle_status)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "gps_correction_latency", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"gps_correction_latency\"");
    }
    {
        mipc_jr_push(jr, "gps_correction_latency");
        if (mipc_jr_f32(jr, vp, &out->gps_correction_latency)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "glonass_correction_latency", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"glonass_correction_latency\"");
    }
    {
        mipc_jr_push(jr, "glonass_correction_latency");
        if (mipc_jr_f32(jr, vp, &out->glonass_correction_latency)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "galileo_correction_latency", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"galileo_correction_latency\"");
    }
    {
        mipc_jr_push(jr, "galileo_correction_latency");
        if (mipc_jr_f32(jr, vp, &out->galileo_correction_latency)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "beidou_correction_latency", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"beidou_correction_latency\"");
    }
    {
        mipc_jr_push(jr, "beidou_correction_latency");
        if (mipc_jr_f32(jr, vp, &out->beidou_correction_latency)) {
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
            if (mipc_jr_u32(jr, ep, &out->reserved[i])) {
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
