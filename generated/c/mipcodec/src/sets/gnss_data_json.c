/* Canonical JSON of GNSS Data Set (the mipcodec_json library). Generated from the spec: do not edit. */
#include "mipcodec/sets/gnss_data.h"
#include "layouts_internal.h"
#include "types_internal.h"

#include <assert.h>
#include <string.h>

/* ---- mipc_gnss_data_llh_position_t */

void mipc_gnss_data_llh_position_to_json(mipc_jw_t *w, const mipc_gnss_data_llh_position_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "latitude");
    mipc_jw_f64(w, &in->latitude);
    mipc_jw_key(w, &first, "longitude");
    mipc_jw_f64(w, &in->longitude);
    mipc_jw_key(w, &first, "ellipsoid_height");
    mipc_jw_f64(w, &in->ellipsoid_height);
    mipc_jw_key(w, &first, "msl_height");
    mipc_jw_f64(w, &in->msl_height);
    mipc_jw_key(w, &first, "horizontal_accuracy");
    mipc_jw_f32(w, &in->horizontal_accuracy);
    mipc_jw_key(w, &first, "vertical_accuracy");
    mipc_jw_f32(w, &in->vertical_accuracy);
    mipc_jw_key(w, &first, "valid_flags");
    mipc_jw_u16(w, &in->valid_flags);
    mipc_jw_raw(w, "}", 1);
}

int mipc_gnss_data_llh_position_from_json(mipc_jr_t *jr, size_t pos, mipc_gnss_data_llh_position_t *out) {
    static const char *const keys[] = {"latitude",   "longitude",           "ellipsoid_height",
                                       "msl_height", "horizontal_accuracy", "vertical_accuracy",
                                       "valid_flags"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 7)) {
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
    found = mipc_jr_get(jr, pos, "msl_height", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"msl_height\"");
    }
    {
        mipc_jr_push(jr, "msl_height");
        if (mipc_jr_f64(jr, vp, &out->msl_height)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "horizontal_accuracy", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"horizontal_accuracy\"");
    }
    {
        mipc_jr_push(jr, "horizontal_accuracy");
        if (mipc_jr_f32(jr, vp, &out->horizontal_accuracy)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "vertical_accuracy", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"vertical_accuracy\"");
    }
    {
        mipc_jr_push(jr, "vertical_accuracy");
        if (mipc_jr_f32(jr, vp, &out->vertical_accuracy)) {
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

/* ---- mipc_gnss_data_ecef_position_t */

void mipc_gnss_data_ecef_position_to_json(mipc_jw_t *w, const mipc_gnss_data_ecef_position_t *in) {
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
    mipc_jw_key(w, &first, "position_accuracy");
    mipc_jw_f32(w, &in->position_accuracy);
    mipc_jw_key(w, &first, "valid_flags");
    mipc_jw_u16(w, &in->valid_flags);
    mipc_jw_raw(w, "}", 1);
}

int mipc_gnss_data_ecef_position_from_json(mipc_jr_t *jr, size_t pos, mipc_gnss_data_ecef_position_t *out) {
    static const char *const keys[] = {"position", "position_accuracy", "valid_flags"};
    size_t vp = 0;
    int found;
    size_t i;
    size_t it = 0;
    size_t ep = 0;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 3)) {
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
    found = mipc_jr_get(jr, pos, "position_accuracy", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"position_accuracy\"");
    }
    {
        mipc_jr_push(jr, "position_accuracy");
        if (mipc_jr_f32(jr, vp, &out->position_accuracy)) {
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

/* ---- mipc_gnss_data_ned_velocity_t */

void mipc_gnss_data_ned_velocity_to_json(mipc_jw_t *w, const mipc_gnss_data_ned_velocity_t *in) {
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
    mipc_jw_key(w, &first, "speed");
    mipc_jw_f32(w, &in->speed);
    mipc_jw_key(w, &first, "ground_speed");
    mipc_jw_f32(w, &in->ground_speed);
    mipc_jw_key(w, &first, "heading");
    mipc_jw_f32(w, &in->heading);
    mipc_jw_key(w, &first, "speed_accuracy");
    mipc_jw_f32(w, &in->speed_accuracy);
    mipc_jw_key(w, &first, "heading_accuracy");
    mipc_jw_f32(w, &in->heading_accuracy);
    mipc_jw_key(w, &first, "valid_flags");
    mipc_jw_u16(w, &in->valid_flags);
    mipc_jw_raw(w, "}", 1);
}

int mipc_gnss_data_ned_velocity_from_json(mipc_jr_t *jr, size_t pos, mipc_gnss_data_ned_velocity_t *out) {
    static const char *const keys[] = {
        "velocity", "speed", "ground_speed", "heading", "speed_accuracy", "heading_accuracy", "valid_flags"};
    size_t vp = 0;
    int found;
    size_t i;
    size_t it = 0;
    size_t ep = 0;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 7)) {
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
    found = mipc_jr_get(jr, pos, "ground_speed", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"ground_speed\"");
    }
    {
        mipc_jr_push(jr, "ground_speed");
        if (mipc_jr_f32(jr, vp, &out->ground_speed)) {
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
    found = mipc_jr_get(jr, pos, "speed_accuracy", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"speed_accuracy\"");
    }
    {
        mipc_jr_push(jr, "speed_accuracy");
        if (mipc_jr_f32(jr, vp, &out->speed_accuracy)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "heading_accuracy", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"heading_accuracy\"");
    }
    {
        mipc_jr_push(jr, "heading_accuracy");
        if (mipc_jr_f32(jr, vp, &out->heading_accuracy)) {
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

/* ---- mipc_gnss_data_ecef_velocity_t */

void mipc_gnss_data_ecef_velocity_to_json(mipc_jw_t *w, const mipc_gnss_data_ecef_velocity_t *in) {
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
    mipc_jw_key(w, &first, "velocity_accuracy");
    mipc_jw_f32(w, &in->velocity_accuracy);
    mipc_jw_key(w, &first, "valid_flags");
    mipc_jw_u16(w, &in->valid_flags);
    mipc_jw_raw(w, "}", 1);
}

int mipc_gnss_data_ecef_velocity_from_json(mipc_jr_t *jr, size_t pos, mipc_gnss_data_ecef_velocity_t *out) {
    static const char *const keys[] = {"velocity", "velocity_accuracy", "valid_flags"};
    size_t vp = 0;
    int found;
    size_t i;
    size_t it = 0;
    size_t ep = 0;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 3)) {
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
    found = mipc_jr_get(jr, pos, "velocity_accuracy", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"velocity_accuracy\"");
    }
    {
        mipc_jr_push(jr, "velocity_accuracy");
        if (mipc_jr_f32(jr, vp, &out->velocity_accuracy)) {
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

/* ---- mipc_gnss_data_dop_t */

void mipc_gnss_data_dop_to_json(mipc_jw_t *w, const mipc_gnss_data_dop_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "gdop");
    mipc_jw_f32(w, &in->gdop);
    mipc_jw_key(w, &first, "pdop");
    mipc_jw_f32(w, &in->pdop);
    mipc_jw_key(w, &first, "hdop");
    mipc_jw_f32(w, &in->hdop);
    mipc_jw_key(w, &first, "vdop");
    mipc_jw_f32(w, &in->vdop);
    mipc_jw_key(w, &first, "tdop");
    mipc_jw_f32(w, &in->tdop);
    mipc_jw_key(w, &first, "ndop");
    mipc_jw_f32(w, &in->ndop);
    mipc_jw_key(w, &first, "edop");
    mipc_jw_f32(w, &in->edop);
    mipc_jw_key(w, &first, "valid_flags");
    mipc_jw_u16(w, &in->valid_flags);
    mipc_jw_raw(w, "}", 1);
}

int mipc_gnss_data_dop_from_json(mipc_jr_t *jr, size_t pos, mipc_gnss_data_dop_t *out) {
    static const char *const keys[] = {"gdop", "pdop", "hdop", "vdop", "tdop", "ndop", "edop", "valid_flags"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 8)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "gdop", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"gdop\"");
    }
    {
        mipc_jr_push(jr, "gdop");
        if (mipc_jr_f32(jr, vp, &out->gdop)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "pdop", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"pdop\"");
    }
    {
        mipc_jr_push(jr, "pdop");
        if (mipc_jr_f32(jr, vp, &out->pdop)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "hdop", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"hdop\"");
    }
    {
        mipc_jr_push(jr, "hdop");
        if (mipc_jr_f32(jr, vp, &out->hdop)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "vdop", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"vdop\"");
    }
    {
        mipc_jr_push(jr, "vdop");
        if (mipc_jr_f32(jr, vp, &out->vdop)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "tdop", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"tdop\"");
    }
    {
        mipc_jr_push(jr, "tdop");
        if (mipc_jr_f32(jr, vp, &out->tdop)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "ndop", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"ndop\"");
    }
    {
        mipc_jr_push(jr, "ndop");
        if (mipc_jr_f32(jr, vp, &out->ndop)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "edop", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"edop\"");
    }
    {
        mipc_jr_push(jr, "edop");
        if (mipc_jr_f32(jr, vp, &out->edop)) {
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

/* ---- mipc_gnss_data_utc_time_t */

void mipc_gnss_data_utc_time_to_json(mipc_jw_t *w, const mipc_gnss_data_utc_time_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "year");
    mipc_jw_u16(w, &in->year);
    mipc_jw_key(w, &first, "month");
    mipc_jw_u8(w, &in->month);
    mipc_jw_key(w, &first, "day");
    mipc_jw_u8(w, &in->day);
    mipc_jw_key(w, &first, "hour");
    mipc_jw_u8(w, &in->hour);
    mipc_jw_key(w, &first, "minute");
    mipc_jw_u8(w, &in->minute);
    mipc_jw_key(w, &first, "second");
    mipc_jw_u8(w, &in->second);
    mipc_jw_key(w, &first, "millisecond");
    mipc_jw_u32(w, &in->millisecond);
    mipc_jw_key(w, &first, "valid_flags");
    mipc_jw_u16(w, &in->valid_flags);
    mipc_jw_raw(w, "}", 1);
}

int mipc_gnss_data_utc_time_from_json(mipc_jr_t *jr, size_t pos, mipc_gnss_data_utc_time_t *out) {
    static const char *const keys[] = {"year",   "month",  "day",         "hour",
                                       "minute", "second", "millisecond", "valid_flags"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 8)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "year", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"year\"");
    }
    {
        mipc_jr_push(jr, "year");
        if (mipc_jr_u16(jr, vp, &out->year)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "month", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"month\"");
    }
    {
        mipc_jr_push(jr, "month");
        if (mipc_jr_u8(jr, vp, &out->month)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "day", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"day\"");
    }
    {
        mipc_jr_push(jr, "day");
        if (mipc_jr_u8(jr, vp, &out->day)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "hour", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"hour\"");
    }
    {
        mipc_jr_push(jr, "hour");
        if (mipc_jr_u8(jr, vp, &out->hour)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "minute", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"minute\"");
    }
    {
        mipc_jr_push(jr, "minute");
        if (mipc_jr_u8(jr, vp, &out->minute)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "second", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"second\"");
    }
    {
        mipc_jr_push(jr, "second");
        if (mipc_jr_u8(jr, vp, &out->second)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "millisecond", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"millisecond\"");
    }
    {
        mipc_jr_push(jr, "millisecond");
        if (mipc_jr_u32(jr, vp, &out->millisecond)) {
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

/* ---- mipc_gnss_data_gps_time_t */

void mipc_gnss_data_gps_time_to_json(mipc_jw_t *w, const mipc_gnss_data_gps_time_t *in) {
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

int mipc_gnss_data_gps_time_from_json(mipc_jr_t *jr, size_t pos, mipc_gnss_data_gps_time_t *out) {
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

/* ---- mipc_gnss_data_clock_info_t */

void mipc_gnss_data_clock_info_to_json(mipc_jw_t *w, const mipc_gnss_data_clock_info_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "bias");
    mipc_jw_f64(w, &in->bias);
    mipc_jw_key(w, &first, "drift");
    mipc_jw_f64(w, &in->drift);
    mipc_jw_key(w, &first, "accuracy_estimate");
    mipc_jw_f64(w, &in->accuracy_estimate);
    mipc_jw_key(w, &first, "valid_flags");
    mipc_jw_u16(w, &in->valid_flags);
    mipc_jw_raw(w, "}", 1);
}

int mipc_gnss_data_clock_info_from_json(mipc_jr_t *jr, size_t pos, mipc_gnss_data_clock_info_t *out) {
    static const char *const keys[] = {"bias", "drift", "accuracy_estimate", "valid_flags"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 4)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "bias", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"bias\"");
    }
    {
        mipc_jr_push(jr, "bias");
        if (mipc_jr_f64(jr, vp, &out->bias)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "drift", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"drift\"");
    }
    {
        mipc_jr_push(jr, "drift");
        if (mipc_jr_f64(jr, vp, &out->drift)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "accuracy_estimate", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"accuracy_estimate\"");
    }
    {
        mipc_jr_push(jr, "accuracy_estimate");
        if (mipc_jr_f64(jr, vp, &out->accuracy_estimate)) {
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

/* ---- mipc_gnss_data_fix_info_t */

void mipc_gnss_data_fix_info_to_json(mipc_jw_t *w, const mipc_gnss_data_fix_info_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "fix_type");
    mipc_jw_u8(w, &in->fix_type);
    mipc_jw_key(w, &first, "num_sv");
    mipc_jw_u8(w, &in->num_sv);
    mipc_jw_key(w, &first, "fix_flags");
    mipc_jw_u16(w, &in->fix_flags);
    mipc_jw_key(w, &first, "valid_flags");
    mipc_jw_u16(w, &in->valid_flags);
    mipc_jw_raw(w, "}", 1);
}

int mipc_gnss_data_fix_info_from_json(mipc_jr_t *jr, size_t pos, mipc_gnss_data_fix_info_t *out) {
    static const char *const keys[] = {"fix_type", "num_sv", "fix_flags", "valid_flags"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 4)) {
        return -1;
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
    found = mipc_jr_get(jr, pos, "num_sv", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"num_sv\"");
    }
    {
        mipc_jr_push(jr, "num_sv");
        if (mipc_jr_u8(jr, vp, &out->num_sv)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "fix_flags", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"fix_flags\"");
    }
    {
        mipc_jr_push(jr, "fix_flags");
        if (mipc_jr_u16(jr, vp, &out->fix_flags)) {
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

/* ---- mipc_gnss_data_sv_info_t */

void mipc_gnss_data_sv_info_to_json(mipc_jw_t *w, const mipc_gnss_data_sv_info_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "channel");
    mipc_jw_u8(w, &in->channel);
    mipc_jw_key(w, &first, "sv_id");
    mipc_jw_u8(w, &in->sv_id);
    mipc_jw_key(w, &first, "carrier_to_noise_ratio");
    mipc_jw_u16(w, &in->carrier_to_noise_ratio);
    mipc_jw_key(w, &first, "azimuth");
    mipc_jw_s16(w, &in->azimuth);
    mipc_jw_key(w, &first, "elevation");
    mipc_jw_s16(w, &in->elevation);
    mipc_jw_key(w, &first, "sv_flags");
    mipc_jw_u16(w, &in->sv_flags);
    mipc_jw_key(w, &first, "valid_flags");
    mipc_jw_u16(w, &in->valid_flags);
    mipc_jw_raw(w, "}", 1);
}

int mipc_gnss_data_sv_info_from_json(mipc_jr_t *jr, size_t pos, mipc_gnss_data_sv_info_t *out) {
    static const char *const keys[] = {
        "channel", "sv_id", "carrier_to_noise_ratio", "azimuth", "elevation", "sv_flags", "valid_flags"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 7)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "channel", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"channel\"");
    }
    {
        mipc_jr_push(jr, "channel");
        if (mipc_jr_u8(jr, vp, &out->channel)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "sv_id", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"sv_id\"");
    }
    {
        mipc_jr_push(jr, "sv_id");
        if (mipc_jr_u8(jr, vp, &out->sv_id)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "carrier_to_noise_ratio", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"carrier_to_noise_ratio\"");
    }
    {
        mipc_jr_push(jr, "carrier_to_noise_ratio");
        if (mipc_jr_u16(jr, vp, &out->carrier_to_noise_ratio)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "azimuth", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"azimuth\"");
    }
    {
        mipc_jr_push(jr, "azimuth");
        if (mipc_jr_s16(jr, vp, &out->azimuth)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "elevation", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"elevation\"");
    }
    {
        mipc_jr_push(jr, "elevation");
        if (mipc_jr_s16(jr, vp, &out->elevation)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "sv_flags", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"sv_flags\"");
    }
    {
        mipc_jr_push(jr, "sv_flags");
        if (mipc_jr_u16(jr, vp, &out->sv_flags)) {
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

/* ---- mipc_gnss_data_hardware_status_t */

void mipc_gnss_data_hardware_status_to_json(mipc_jw_t *w, const mipc_gnss_data_hardware_status_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "receiver_state");
    mipc_jw_u8(w, &in->receiver_state);
    mipc_jw_key(w, &first, "antenna_state");
    mipc_jw_u8(w, &in->antenna_state);
    mipc_jw_key(w, &first, "antenna_power");
    mipc_jw_u8(w, &in->antenna_power);
    mipc_jw_key(w, &first, "valid_flags");
    mipc_jw_u16(w, &in->valid_flags);
    mipc_jw_raw(w, "}", 1);
}

int mipc_gnss_data_hardware_status_from_json(mipc_jr_t *jr, size_t pos,
                                             mipc_gnss_data_hardware_status_t *out) {
    static const char *const keys[] = {"receiver_state", "antenna_state", "antenna_power", "valid_flags"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 4)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "receiver_state", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"receiver_state\"");
    }
    {
        mipc_jr_push(jr, "receiver_state");
        if (mipc_jr_u8(jr, vp, &out->receiver_state)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "antenna_state", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"antenna_state\"");
    }
    {
        mipc_jr_push(jr, "antenna_state");
        if (mipc_jr_u8(jr, vp, &out->antenna_state)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "antenna_power", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"antenna_power\"");
    }
    {
        mipc_jr_push(jr, "antenna_power");
        if (mipc_jr_u8(jr, vp, &out->antenna_power)) {
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

/* ---- mipc_gnss_data_dgnss_info_t */

void mipc_gnss_data_dgnss_info_to_json(mipc_jw_t *w, const mipc_gnss_data_dgnss_info_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "newest_age");
    mipc_jw_f32(w, &in->newest_age);
    mipc_jw_key(w, &first, "base_station_id");
    mipc_jw_s16(w, &in->base_station_id);
    mipc_jw_key(w, &first, "base_station_status");
    mipc_jw_s16(w, &in->base_station_status);
    mipc_jw_key(w, &first, "num_channels");
    mipc_jw_u16(w, &in->num_channels);
    mipc_jw_key(w, &first, "valid_flags");
    mipc_jw_u16(w, &in->valid_flags);
    mipc_jw_raw(w, "}", 1);
}

int mipc_gnss_data_dgnss_info_from_json(mipc_jr_t *jr, size_t pos, mipc_gnss_data_dgnss_info_t *out) {
    static const char *const keys[] = {"newest_age", "base_station_id", "base_station_status", "num_channels",
                                       "valid_flags"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 5)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "newest_age", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"newest_age\"");
    }
    {
        mipc_jr_push(jr, "newest_age");
        if (mipc_jr_f32(jr, vp, &out->newest_age)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "base_station_id", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"base_station_id\"");
    }
    {
        mipc_jr_push(jr, "base_station_id");
        if (mipc_jr_s16(jr, vp, &out->base_station_id)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "base_station_status", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"base_station_status\"");
    }
    {
        mipc_jr_push(jr, "base_station_status");
        if (mipc_jr_s16(jr, vp, &out->base_station_status)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "num_channels", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"num_channels\"");
    }
    {
        mipc_jr_push(jr, "num_channels");
        if (mipc_jr_u16(jr, vp, &out->num_channels)) {
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

/* ---- mipc_gnss_data_dgnss_channel_status_t */

void mipc_gnss_data_dgnss_channel_status_to_json(mipc_jw_t *w,
                                                 const mipc_gnss_data_dgnss_channel_status_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "sv_id");
    mipc_jw_u8(w, &in->sv_id);
    mipc_jw_key(w, &first, "age");
    mipc_jw_f32(w, &in->age);
    mipc_jw_key(w, &first, "pseudorange_correction");
    mipc_jw_f32(w, &in->pseudorange_correction);
    mipc_jw_key(w, &first, "pseudorange_rate_correction");
    mipc_jw_f32(w, &in->pseudorange_rate_correction);
    mipc_jw_key(w, &first, "valid_flags");
    mipc_jw_u16(w, &in->valid_flags);
    mipc_jw_raw(w, "}", 1);
}

int mipc_gnss_data_dgnss_channel_status_from_json(mipc_jr_t *jr, size_t pos,
                                                  mipc_gnss_data_dgnss_channel_status_t *out) {
    static const char *const keys[] = {"sv_id", "age", "pseudorange_correction",
                                       "pseudorange_rate_correction", "valid_flags"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 5)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "sv_id", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"sv_id\"");
    }
    {
        mipc_jr_push(jr, "sv_id");
        if (mipc_jr_u8(jr, vp, &out->sv_id)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "age", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"age\"");
    }
    {
        mipc_jr_push(jr, "age");
        if (mipc_jr_f32(jr, vp, &out->age)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "pseudorange_correction", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"pseudorange_correction\"");
    }
    {
        mipc_jr_push(jr, "pseudorange_correction");
        if (mipc_jr_f32(jr, vp, &out->pseudorange_correction)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "pseudorange_rate_correction", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"pseudorange_rate_correction\"");
    }
    {
        mipc_jr_push(jr, "pseudorange_rate_correction");
        if (mipc_jr_f32(jr, vp, &out->pseudorange_rate_correction)) {
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
