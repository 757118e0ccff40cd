/* Canonical JSON of GNSS Receiver 1 Data Set (the mipcodec_json library). Generated from the spec: do not
 * edit. */
#include "mipcodec/sets/gnss_receiver_1.h"
#include "layouts_internal.h"
#include "types_internal.h"

#include <assert.h>
#include <string.h>

/* ---- mipc_gnss_receiver_1_llh_position_t */

void mipc_gnss_receiver_1_llh_position_to_json(mipc_jw_t *w, const mipc_gnss_receiver_1_llh_position_t *in) {
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

int mipc_gnss_receiver_1_llh_position_from_json(mipc_jr_t *jr, size_t pos,
                                                mipc_gnss_receiver_1_llh_position_t *out) {
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

/* ---- mipc_gnss_receiver_1_ecef_position_t */

void mipc_gnss_receiver_1_ecef_position_to_json(mipc_jw_t *w,
                                                const mipc_gnss_receiver_1_ecef_position_t *in) {
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

int mipc_gnss_receiver_1_ecef_position_from_json(mipc_jr_t *jr, size_t pos,
                                                 mipc_gnss_receiver_1_ecef_position_t *out) {
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

/* ---- mipc_gnss_receiver_1_ned_velocity_t */

void mipc_gnss_receiver_1_ned_velocity_to_json(mipc_jw_t *w, const mipc_gnss_receiver_1_ned_velocity_t *in) {
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

int mipc_gnss_receiver_1_ned_velocity_from_json(mipc_jr_t *jr, size_t pos,
                                                mipc_gnss_receiver_1_ned_velocity_t *out) {
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

/* ---- mipc_gnss_receiver_1_ecef_velocity_t */

void mipc_gnss_receiver_1_ecef_velocity_to_json(mipc_jw_t *w,
                                                const mipc_gnss_receiver_1_ecef_velocity_t *in) {
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

int mipc_gnss_receiver_1_ecef_velocity_from_json(mipc_jr_t *jr, size_t pos,
                                                 mipc_gnss_receiver_1_ecef_velocity_t *out) {
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

/* ---- mipc_gnss_receiver_1_dop_t */

void mipc_gnss_receiver_1_dop_to_json(mipc_jw_t *w, const mipc_gnss_receiver_1_dop_t *in) {
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

int mipc_gnss_receiver_1_dop_from_json(mipc_jr_t *jr, size_t pos, mipc_gnss_receiver_1_dop_t *out) {
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

/* ---- mipc_gnss_receiver_1_utc_time_t */

void mipc_gnss_receiver_1_utc_time_to_json(mipc_jw_t *w, const mipc_gnss_receiver_1_utc_time_t *in) {
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

int mipc_gnss_receiver_1_utc_time_from_json(mipc_jr_t *jr, size_t pos, mipc_gnss_receiver_1_utc_time_t *out) {
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

/* ---- mipc_gnss_receiver_1_gps_time_t */

void mipc_gnss_receiver_1_gps_time_to_json(mipc_jw_t *w, const mipc_gnss_receiver_1_gps_time_t *in) {
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

int mipc_gnss_receiver_1_gps_time_from_json(mipc_jr_t *jr, size_t pos, mipc_gnss_receiver_1_gps_time_t *out) {
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

/* ---- mipc_gnss_receiver_1_fix_info_t */

void mipc_gnss_receiver_1_fix_info_to_json(mipc_jw_t *w, const mipc_gnss_receiver_1_fix_info_t *in) {
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

int mipc_gnss_receiver_1_fix_info_from_json(mipc_jr_t *jr, size_t pos, mipc_gnss_receiver_1_fix_info_t *out) {
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

/* ---- mipc_gnss_receiver_1_hardware_status_t */

void mipc_gnss_receiver_1_hardware_status_to_json(mipc_jw_t *w,
                                                  const mipc_gnss_receiver_1_hardware_status_t *in) {
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

int mipc_gnss_receiver_1_hardware_status_from_json(mipc_jr_t *jr, size_t pos,
                                                   mipc_gnss_receiver_1_hardware_status_t *out) {
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

/* ---- mipc_gnss_receiver_1_clock_info_2_t */

void mipc_gnss_receiver_1_clock_info_2_to_json(mipc_jw_t *w, const mipc_gnss_receiver_1_clock_info_2_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "bias");
    mipc_jw_f64(w, &in->bias);
    mipc_jw_key(w, &first, "drift");
    mipc_jw_f64(w, &in->drift);
    mipc_jw_key(w, &first, "bias_accuracy_estimate");
    mipc_jw_f64(w, &in->bias_accuracy_estimate);
    mipc_jw_key(w, &first, "drift_accuracy_estimate");
    mipc_jw_f64(w, &in->drift_accuracy_estimate);
    mipc_jw_key(w, &first, "valid_flags");
    mipc_jw_u16(w, &in->valid_flags);
    mipc_jw_raw(w, "}", 1);
}

int mipc_gnss_receiver_1_clock_info_2_from_json(mipc_jr_t *jr, size_t pos,
                                                mipc_gnss_receiver_1_clock_info_2_t *out) {
    static const char *const keys[] = {"bias", "drift", "bias_accuracy_estimate", "drift_accuracy_estimate",
                                       "valid_flags"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 5)) {
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
    found = mipc_jr_get(jr, pos, "bias_accuracy_estimate", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"bias_accuracy_estimate\"");
    }
    {
        mipc_jr_push(jr, "bias_accuracy_estimate");
        if (mipc_jr_f64(jr, vp, &out->bias_accuracy_estimate)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "drift_accuracy_estimate", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"drift_accuracy_estimate\"");
    }
    {
        mipc_jr_push(jr, "drift_accuracy_estimate");
        if (mipc_jr_f64(jr, vp, &out->drift_accuracy_estimate)) {
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

/* ---- mipc_gnss_receiver_1_gps_leap_seconds_t */

void mipc_gnss_receiver_1_gps_leap_seconds_to_json(mipc_jw_t *w,
                                                   const mipc_gnss_receiver_1_gps_leap_seconds_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "leap_seconds");
    mipc_jw_u8(w, &in->leap_seconds);
    mipc_jw_key(w, &first, "valid_flags");
    mipc_jw_u16(w, &in->valid_flags);
    mipc_jw_raw(w, "}", 1);
}

int mipc_gnss_receiver_1_gps_leap_seconds_from_json(mipc_jr_t *jr, size_t pos,
                                                    mipc_gnss_receiver_1_gps_leap_seconds_t *out) {
    static const char *const keys[] = {"leap_seconds", "valid_flags"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 2)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "leap_seconds", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"leap_seconds\"");
    }
    {
        mipc_jr_push(jr, "leap_seconds");
        if (mipc_jr_u8(jr, vp, &out->leap_seconds)) {
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

/* ---- mipc_gnss_receiver_1_sbas_info_t */

void mipc_gnss_receiver_1_sbas_info_to_json(mipc_jw_t *w, const mipc_gnss_receiver_1_sbas_info_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "tow");
    mipc_jw_f64(w, &in->tow);
    mipc_jw_key(w, &first, "week_number");
    mipc_jw_u16(w, &in->week_number);
    mipc_jw_key(w, &first, "sbas_system");
    mipc_jw_u8(w, &in->sbas_system);
    mipc_jw_key(w, &first, "sbas_id");
    mipc_jw_u8(w, &in->sbas_id);
    mipc_jw_key(w, &first, "count");
    mipc_jw_u8(w, &in->count);
    mipc_jw_key(w, &first, "sbas_status");
    mipc_jw_u8(w, &in->sbas_status);
    mipc_jw_key(w, &first, "valid_flags");
    mipc_jw_u16(w, &in->valid_flags);
    mipc_jw_raw(w, "}", 1);
}

int mipc_gnss_receiver_1_sbas_info_from_json(mipc_jr_t *jr, size_t pos,
                                             mipc_gnss_receiver_1_sbas_info_t *out) {
    static const char *const keys[] = {"tow",   "week_number", "sbas_system", "sbas_id",
                                       "count", "sbas_status", "valid_flags"};
    size_t vp = 0;
    int found;
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
    found = mipc_jr_get(jr, pos, "sbas_system", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"sbas_system\"");
    }
    {
        mipc_jr_push(jr, "sbas_system");
        if (mipc_jr_u8(jr, vp, &out->sbas_system)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "sbas_id", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"sbas_id\"");
    }
    {
        mipc_jr_push(jr, "sbas_id");
        if (mipc_jr_u8(jr, vp, &out->sbas_id)) {
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
    found = mipc_jr_get(jr, pos, "sbas_status", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"sbas_status\"");
    }
    {
        mipc_jr_push(jr, "sbas_status");
        if (mipc_jr_u8(jr, vp, &out->sbas_status)) {
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

/* ---- mipc_gnss_receiver_1_satellite_status_t */

void mipc_gnss_receiver_1_satellite_status_to_json(mipc_jw_t *w,
                                                   const mipc_gnss_receiver_1_satellite_status_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "index");
    mipc_jw_u8(w, &in->index);
    mipc_jw_key(w, &first, "count");
    mipc_jw_u8(w, &in->count);
    mipc_jw_key(w, &first, "tow");
    mipc_jw_f64(w, &in->tow);
    mipc_jw_key(w, &first, "week_number");
    mipc_jw_u16(w, &in->week_number);
    mipc_jw_key(w, &first, "gnss_id");
    mipc_jw_u8(w, &in->gnss_id);
    mipc_jw_key(w, &first, "satellite_id");
    mipc_jw_u8(w, &in->satellite_id);
    mipc_jw_key(w, &first, "elevation");
    mipc_jw_f32(w, &in->elevation);
    mipc_jw_key(w, &first, "azimuth");
    mipc_jw_f32(w, &in->azimuth);
    mipc_jw_key(w, &first, "health");
    mipc_jw_bool(w, &in->health);
    mipc_jw_key(w, &first, "valid_flags");
    mipc_jw_u16(w, &in->valid_flags);
    mipc_jw_raw(w, "}", 1);
}

int mipc_gnss_receiver_1_satellite_status_from_json(mipc_jr_t *jr, size_t pos,
                                                    mipc_gnss_receiver_1_satellite_status_t *out) {
    static const char *const keys[] = {"index",        "count",     "tow",     "week_number", "gnss_id",
                                       "satellite_id", "elevation", "azimuth", "health",      "valid_flags"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 10)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "index", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"index\"");
    }
    {
        mipc_jr_push(jr, "index");
        if (mipc_jr_u8(jr, vp, &out->index)) {
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
    found = mipc_jr_get(jr, pos, "gnss_id", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"gnss_id\"");
    }
    {
        mipc_jr_push(jr, "gnss_id");
        if (mipc_jr_u8(jr, vp, &out->gnss_id)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "satellite_id", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"satellite_id\"");
    }
    {
        mipc_jr_push(jr, "satellite_id");
        if (mipc_jr_u8(jr, vp, &out->satellite_id)) {
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
        if (mipc_jr_f32(jr, vp, &out->elevation)) {
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
        if (mipc_jr_f32(jr, vp, &out->azimuth)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "health", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"health\"");
    }
    {
        mipc_jr_push(jr, "health");
        if (mipc_jr_bool(jr, vp, &out->health)) {
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

/* ---- mipc_gnss_receiver_1_raw_t */

void mipc_gnss_receiver_1_raw_to_json(mipc_jw_t *w, const mipc_gnss_receiver_1_raw_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "index");
    mipc_jw_u8(w, &in->index);
    mipc_jw_key(w, &first, "count");
    mipc_jw_u8(w, &in->count);
    mipc_jw_key(w, &first, "tow");
    mipc_jw_f64(w, &in->tow);
    mipc_jw_key(w, &first, "week_number");
    mipc_jw_u16(w, &in->week_number);
    mipc_jw_key(w, &first, "receiver_id");
    mipc_jw_u16(w, &in->receiver_id);
    mipc_jw_key(w, &first, "tracking_channel");
    mipc_jw_u8(w, &in->tracking_channel);
    mipc_jw_key(w, &first, "gnss_id");
    mipc_jw_u8(w, &in->gnss_id);
    mipc_jw_key(w, &first, "satellite_id");
    mipc_jw_u8(w, &in->satellite_id);
    mipc_jw_key(w, &first, "signal_id");
    mipc_jw_u8(w, &in->signal_id);
    mipc_jw_key(w, &first, "signal_strength");
    mipc_jw_f32(w, &in->signal_strength);
    mipc_jw_key(w, &first, "quality");
    mipc_jw_u8(w, &in->quality);
    mipc_jw_key(w, &first, "pseudorange");
    mipc_jw_f64(w, &in->pseudorange);
    mipc_jw_key(w, &first, "carrier_phase");
    mipc_jw_f64(w, &in->carrier_phase);
    mipc_jw_key(w, &first, "doppler");
    mipc_jw_f32(w, &in->doppler);
    mipc_jw_key(w, &first, "range_uncert");
    mipc_jw_f32(w, &in->range_uncert);
    mipc_jw_key(w, &first, "phase_uncert");
    mipc_jw_f32(w, &in->phase_uncert);
    mipc_jw_key(w, &first, "doppler_uncert");
    mipc_jw_f32(w, &in->doppler_uncert);
    mipc_jw_key(w, &first, "lock_time");
    mipc_jw_f32(w, &in->lock_time);
    mipc_jw_key(w, &first, "valid_flags");
    mipc_jw_u16(w, &in->valid_flags);
    mipc_jw_raw(w, "}", 1);
}

int mipc_gnss_receiver_1_raw_from_json(mipc_jr_t *jr, size_t pos, mipc_gnss_receiver_1_raw_t *out) {
    static const char *const keys[] = {"index",           "count",          "tow",
                                       "week_number",     "receiver_id",    "tracking_channel",
                                       "gnss_id",         "satellite_id",   "signal_id",
                                       "signal_strength", "quality",        "pseudorange",
                                       "carrier_phase",   "doppler",        "range_uncert",
                                       "phase_uncert",    "doppler_uncert", "lock_time",
                                       "valid_flags"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 19)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "index", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"index\"");
    }
    {
        mipc_jr_push(jr, "index");
        if (mipc_jr_u8(jr, vp, &out->index)) {
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
    found = mipc_jr_get(jr, pos, "receiver_id", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"receiver_id\"");
    }
    {
        mipc_jr_push(jr, "receiver_id");
        if (mipc_jr_u16(jr, vp, &out->receiver_id)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "tracking_channel", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"tracking_channel\"");
    }
    {
        mipc_jr_push(jr, "tracking_channel");
        if (mipc_jr_u8(jr, vp, &out->tracking_channel)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "gnss_id", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"gnss_id\"");
    }
    {
        mipc_jr_push(jr, "gnss_id");
        if (mipc_jr_u8(jr, vp, &out->gnss_id)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "satellite_id", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"satellite_id\"");
    }
    {
        mipc_jr_push(jr, "satellite_id");
        if (mipc_jr_u8(jr, vp, &out->satellite_id)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "signal_id", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"signal_id\"");
    }
    {
        mipc_jr_push(jr, "signal_id");
        if (mipc_jr_u8(jr, vp, &out->signal_id)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "signal_strength", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"signal_strength\"");
    }
    {
        mipc_jr_push(jr, "signal_strength");
        if (mipc_jr_f32(jr, vp, &out->signal_strength)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "quality", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"quality\"");
    }
    {
        mipc_jr_push(jr, "quality");
        if (mipc_jr_u8(jr, vp, &out->quality)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "pseudorange", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"pseudorange\"");
    }
    {
        mipc_jr_push(jr, "pseudorange");
        if (mipc_jr_f64(jr, vp, &out->pseudorange)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "carrier_phase", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"carrier_phase\"");
    }
    {
        mipc_jr_push(jr, "carrier_phase");
        if (mipc_jr_f64(jr, vp, &out->carrier_phase)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "doppler", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"doppler\"");
    }
    {
        mipc_jr_push(jr, "doppler");
        if (mipc_jr_f32(jr, vp, &out->doppler)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "range_uncert", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"range_uncert\"");
    }
    {
        mipc_jr_push(jr, "range_uncert");
        if (mipc_jr_f32(jr, vp, &out->range_uncert)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "phase_uncert", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"phase_uncert\"");
    }
    {
        mipc_jr_push(jr, "phase_uncert");
        if (mipc_jr_f32(jr, vp, &out->phase_uncert)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "doppler_uncert", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"doppler_uncert\"");
    }
    {
        mipc_jr_push(jr, "doppler_uncert");
        if (mipc_jr_f32(jr, vp, &out->doppler_uncert)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "lock_time", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"lock_time\"");
    }
    {
        mipc_jr_push(jr, "lock_time");
        if (mipc_jr_f32(jr, vp, &out->lock_time)) {
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

/* ---- mipc_gnss_receiver_1_gps_ephemeris_t */

void mipc_gnss_receiver_1_gps_ephemeris_to_json(mipc_jw_t *w,
                                                const mipc_gnss_receiver_1_gps_ephemeris_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "index");
    mipc_jw_u8(w, &in->index);
    mipc_jw_key(w, &first, "count");
    mipc_jw_u8(w, &in->count);
    mipc_jw_key(w, &first, "tow");
    mipc_jw_f64(w, &in->tow);
    mipc_jw_key(w, &first, "week_number");
    mipc_jw_u16(w, &in->week_number);
    mipc_jw_key(w, &first, "satellite_id");
    mipc_jw_u8(w, &in->satellite_id);
    mipc_jw_key(w, &first, "health");
    mipc_jw_u8(w, &in->health);
    mipc_jw_key(w, &first, "iodc");
    mipc_jw_u8(w, &in->iodc);
    mipc_jw_key(w, &first, "iode");
    mipc_jw_u8(w, &in->iode);
    mipc_jw_key(w, &first, "t_oc");
    mipc_jw_f64(w, &in->t_oc);
    mipc_jw_key(w, &first, "af0");
    mipc_jw_f64(w, &in->af0);
    mipc_jw_key(w, &first, "af1");
    mipc_jw_f64(w, &in->af1);
    mipc_jw_key(w, &first, "af2");
    mipc_jw_f64(w, &in->af2);
    mipc_jw_key(w, &first, "t_gd");
    mipc_jw_f64(w, &in->t_gd);
    mipc_jw_key(w, &first, "isc_l1ca");
    mipc_jw_f64(w, &in->isc_l1ca);
    mipc_jw_key(w, &first, "isc_l2c");
    mipc_jw_f64(w, &in->isc_l2c);
    mipc_jw_key(w, &first, "t_oe");
    mipc_jw_f64(w, &in->t_oe);
    mipc_jw_key(w, &first, "a");
    mipc_jw_f64(w, &in->a);
    mipc_jw_key(w, &first, "a_dot");
    mipc_jw_f64(w, &in->a_dot);
    mipc_jw_key(w, &first, "mean_anomaly");
    mipc_jw_f64(w, &in->mean_anomaly);
    mipc_jw_key(w, &first, "delta_mean_motion");
    mipc_jw_f64(w, &in->delta_mean_motion);
    mipc_jw_key(w, &first, "delta_mean_motion_dot");
    mipc_jw_f64(w, &in->delta_mean_motion_dot);
    mipc_jw_key(w, &first, "eccentricity");
    mipc_jw_f64(w, &in->eccentricity);
    mipc_jw_key(w, &first, "argument_of_perigee");
    mipc_jw_f64(w, &in->argument_of_perigee);
    mipc_jw_key(w, &first, "omega");
    mipc_jw_f64(w, &in->omega);
    mipc_jw_key(w, &first, "omega_dot");
    mipc_jw_f64(w, &in->omega_dot);
    mipc_jw_key(w, &first, "inclination");
    mipc_jw_f64(w, &in->inclination);
    mipc_jw_key(w, &first, "inclination_dot");
    mipc_jw_f64(w, &in->inclination_dot);
    mipc_jw_key(w, &first, "c_ic");
    mipc_jw_f64(w, &in->c_ic);
    mipc_jw_key(w, &first, "c_is");
    mipc_jw_f64(w, &in->c_is);
    mipc_jw_key(w, &first, "c_uc");
    mipc_jw_f64(w, &in->c_uc);
    mipc_jw_key(w, &first, "c_us");
    mipc_jw_f64(w, &in->c_us);
    mipc_jw_key(w, &first, "c_rc");
    mipc_jw_f64(w, &in->c_rc);
    mipc_jw_key(w, &first, "c_rs");
    mipc_jw_f64(w, &in->c_rs);
    mipc_jw_key(w, &first, "valid_flags");
    mipc_jw_u16(w, &in->valid_flags);
    mipc_jw_raw(w, "}", 1);
}

int mipc_gnss_receiver_1_gps_ephemeris_from_json(mipc_jr_t *jr, size_t pos,
                                                 mipc_gnss_receiver_1_gps_ephemeris_t *out) {
    static const char *const keys[] = {"index",
                                       "count",
                                       "tow",
                                       "week_number",
                                       "satellite_id",
                                       "health",
                                       "iodc",
                                       "iode",
                                       "t_oc",
                                       "af0",
                                       "af1",
                                       "af2",
                                       "t_gd",
                                       "isc_l1ca",
                                       "isc_l2c",
                                       "t_oe",
                                       "a",
                                       "a_dot",
                                       "mean_anomaly",
                                       "delta_mean_motion",
                                       "delta_mean_motion_dot",
                                       "eccentricity",
                                       "argument_of_perigee",
                                       "omega",
                                       "omega_dot",
                                       "inclination",
                                       "inclination_dot",
                                       "c_ic",
                                       "c_is",
                                       "c_uc",
                                       "c_us",
                                       "c_rc",
                                       "c_rs",
                                       "valid_flags"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 34)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "index", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"index\"");
    }
    {
        mipc_jr_push(jr, "index");
        if (mipc_jr_u8(jr, vp, &out->index)) {
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
    found = mipc_jr_get(jr, pos, "satellite_id", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"satellite_id\"");
    }
    {
        mipc_jr_push(jr, "satellite_id");
        if (mipc_jr_u8(jr, vp, &out->satellite_id)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "health", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"health\"");
    }
    {
        mipc_jr_push(jr, "health");
        if (mipc_jr_u8(jr, vp, &out->health)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "iodc", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"iodc\"");
    }
    {
        mipc_jr_push(jr, "iodc");
        if (mipc_jr_u8(jr, vp, &out->iodc)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "iode", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"iode\"");
    }
    {
        mipc_jr_push(jr, "iode");
        if (mipc_jr_u8(jr, vp, &out->iode)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "t_oc", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"t_oc\"");
    }
    {
        mipc_jr_push(jr, "t_oc");
        if (mipc_jr_f64(jr, vp, &out->t_oc)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "af0", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"af0\"");
    }
    {
        mipc_jr_push(jr, "af0");
        if (mipc_jr_f64(jr, vp, &out->af0)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "af1", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"af1\"");
    }
    {
        mipc_jr_push(jr, "af1");
        if (mipc_jr_f64(jr, vp, &out->af1)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "af2", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"af2\"");
    }
    {
        mipc_jr_push(jr, "af2");
        if (mipc_jr_f64(jr, vp, &out->af2)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "t_gd", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"t_gd\"");
    }
    {
        mipc_jr_push(jr, "t_gd");
        if (mipc_jr_f64(jr, vp, &out->t_gd)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "isc_l1ca", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"isc_l1ca\"");
    }
    {
        mipc_jr_push(jr, "isc_l1ca");
        if (mipc_jr_f64(jr, vp, &out->isc_l1ca)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "isc_l2c", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"isc_l2c\"");
    }
    {
        mipc_jr_push(jr, "isc_l2c");
        if (mipc_jr_f64(jr, vp, &out->isc_l2c)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "t_oe", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"t_oe\"");
    }
    {
        mipc_jr_push(jr, "t_oe");
        if (mipc_jr_f64(jr, vp, &out->t_oe)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "a", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"a\"");
    }
    {
        mipc_jr_push(jr, "a");
        if (mipc_jr_f64(jr, vp, &out->a)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "a_dot", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"a_dot\"");
    }
    {
        mipc_jr_push(jr, "a_dot");
        if (mipc_jr_f64(jr, vp, &out->a_dot)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "mean_anomaly", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"mean_anomaly\"");
    }
    {
        mipc_jr_push(jr, "mean_anomaly");
        if (mipc_jr_f64(jr, vp, &out->mean_anomaly)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "delta_mean_motion", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"delta_mean_motion\"");
    }
    {
        mipc_jr_push(jr, "delta_mean_motion");
        if (mipc_jr_f64(jr, vp, &out->delta_mean_motion)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "delta_mean_motion_dot", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"delta_mean_motion_dot\"");
    }
    {
        mipc_jr_push(jr, "delta_mean_motion_dot");
        if (mipc_jr_f64(jr, vp, &out->delta_mean_motion_dot)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "eccentricity", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"eccentricity\"");
    }
    {
        mipc_jr_push(jr, "eccentricity");
        if (mipc_jr_f64(jr, vp, &out->eccentricity)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "argument_of_perigee", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"argument_of_perigee\"");
    }
    {
        mipc_jr_push(jr, "argument_of_perigee");
        if (mipc_jr_f64(jr, vp, &out->argument_of_perigee)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "omega", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"omega\"");
    }
    {
        mipc_jr_push(jr, "omega");
        if (mipc_jr_f64(jr, vp, &out->omega)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "omega_dot", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"omega_dot\"");
    }
    {
        mipc_jr_push(jr, "omega_dot");
        if (mipc_jr_f64(jr, vp, &out->omega_dot)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "inclination", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"inclination\"");
    }
    {
        mipc_jr_push(jr, "inclination");
        if (mipc_jr_f64(jr, vp, &out->inclination)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "inclination_dot", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"inclination_dot\"");
    }
    {
        mipc_jr_push(jr, "inclination_dot");
        if (mipc_jr_f64(jr, vp, &out->inclination_dot)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "c_ic", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"c_ic\"");
    }
    {
        mipc_jr_push(jr, "c_ic");
        if (mipc_jr_f64(jr, vp, &out->c_ic)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "c_is", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"c_is\"");
    }
    {
        mipc_jr_push(jr, "c_is");
        if (mipc_jr_f64(jr, vp, &out->c_is)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "c_uc", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"c_uc\"");
    }
    {
        mipc_jr_push(jr, "c_uc");
        if (mipc_jr_f64(jr, vp, &out->c_uc)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "c_us", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"c_us\"");
    }
    {
        mipc_jr_push(jr, "c_us");
        if (mipc_jr_f64(jr, vp, &out->c_us)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "c_rc", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"c_rc\"");
    }
    {
        mipc_jr_push(jr, "c_rc");
        if (mipc_jr_f64(jr, vp, &out->c_rc)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "c_rs", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"c_rs\"");
    }
    {
        mipc_jr_push(jr, "c_rs");
        if (mipc_jr_f64(jr, vp, &out->c_rs)) {
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

/* ---- mipc_gnss_receiver_1_glonass_ephemeris_t */

void mipc_gnss_receiver_1_glonass_ephemeris_to_json(mipc_jw_t *w,
                                                    const mipc_gnss_receiver_1_glonass_ephemeris_t *in) {
    int first = 1;
    size_t i;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "index");
    mipc_jw_u8(w, &in->index);
    mipc_jw_key(w, &first, "count");
    mipc_jw_u8(w, &in->count);
    mipc_jw_key(w, &first, "tow");
    mipc_jw_f64(w, &in->tow);
    mipc_jw_key(w, &first, "week_number");
    mipc_jw_u16(w, &in->week_number);
    mipc_jw_key(w, &first, "satellite_id");
    mipc_jw_u8(w, &in->satellite_id);
    mipc_jw_key(w, &first, "freq_number");
    mipc_jw_s8(w, &in->freq_number);
    mipc_jw_key(w, &first, "tk");
    mipc_jw_u32(w, &in->tk);
    mipc_jw_key(w, &first, "tb");
    mipc_jw_u32(w, &in->tb);
    mipc_jw_key(w, &first, "sat_type");
    mipc_jw_u8(w, &in->sat_type);
    mipc_jw_key(w, &first, "gamma");
    mipc_jw_f64(w, &in->gamma);
    mipc_jw_key(w, &first, "tau_n");
    mipc_jw_f64(w, &in->tau_n);
    mipc_jw_key(w, &first, "x");
    mipc_jw_raw(w, "[", 1);
    for (i = 0; i < 3; i++) {
        mipc_jw_sep(w, i);
        mipc_jw_f64(w, &in->x[i]);
    }
    mipc_jw_raw(w, "]", 1);
    mipc_jw_key(w, &first, "v");
    mipc_jw_raw(w, "[", 1);
    for (i = 0; i < 3; i++) {
        mipc_jw_sep(w, i);
        mipc_jw_f32(w, &in->v[i]);
    }
    mipc_jw_raw(w, "]", 1);
    mipc_jw_key(w, &first, "a");
    mipc_jw_raw(w, "[", 1);
    for (i = 0; i < 3; i++) {
        mipc_jw_sep(w, i);
        mipc_jw_f32(w, &in->a[i]);
    }
    mipc_jw_raw(w, "]", 1);
    mipc_jw_key(w, &first, "health");
    mipc_jw_u8(w, &in->health);
    mipc_jw_key(w, &first, "p");
    mipc_jw_u8(w, &in->p);
    mipc_jw_key(w, &first, "nt");
    mipc_jw_u8(w, &in->nt);
    mipc_jw_key(w, &first, "delta_tau_n");
    mipc_jw_f32(w, &in->delta_tau_n);
    mipc_jw_key(w, &first, "ft");
    mipc_jw_u8(w, &in->ft);
    mipc_jw_key(w, &first, "en");
    mipc_jw_u8(w, &in->en);
    mipc_jw_key(w, &first, "p1");
    mipc_jw_u8(w, &in->p1);
    mipc_jw_key(w, &first, "p2");
    mipc_jw_u8(w, &in->p2);
    mipc_jw_key(w, &first, "p3");
    mipc_jw_u8(w, &in->p3);
    mipc_jw_key(w, &first, "p4");
    mipc_jw_u8(w, &in->p4);
    mipc_jw_key(w, &first, "valid_flags");
    mipc_jw_u16(w, &in->valid_flags);
    mipc_jw_raw(w, "}", 1);
}

int mipc_gnss_receiver_1_glonass_ephemeris_from_json(mipc_jr_t *jr, size_t pos,
                                                     mipc_gnss_receiver_1_glonass_ephemeris_t *out) {
    static const char *const keys[] = {"index",       "count", "tow",         "week_number", "satellite_id",
                                       "freq_number", "tk",    "tb",          "sat_type",    "gamma",
                                       "tau_n",       "x",     "v",           "a",           "health",
                                       "p",           "nt",    "delta_tau_n", "ft",          "en",
                                       "p1",          "p2",    "p3",          "p4",          "valid_flags"};
    size_t vp = 0;
    int found;
    size_t i;
    size_t it = 0;
    size_t ep = 0;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 25)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "index", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"index\"");
    }
    {
        mipc_jr_push(jr, "index");
        if (mipc_jr_u8(jr, vp, &out->index)) {
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
    found = mipc_jr_get(jr, pos, "satellite_id", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"satellite_id\"");
    }
    {
        mipc_jr_push(jr, "satellite_id");
        if (mipc_jr_u8(jr, vp, &out->satellite_id)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "freq_number", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"freq_number\"");
    }
    {
        mipc_jr_push(jr, "freq_number");
        if (mipc_jr_s8(jr, vp, &out->freq_number)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "tk", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"tk\"");
    }
    {
        mipc_jr_push(jr, "tk");
        if (mipc_jr_u32(jr, vp, &out->tk)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "tb", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"tb\"");
    }
    {
        mipc_jr_push(jr, "tb");
        if (mipc_jr_u32(jr, vp, &out->tb)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "sat_type", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"sat_type\"");
    }
    {
        mipc_jr_push(jr, "sat_type");
        if (mipc_jr_u8(jr, vp, &out->sat_type)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "gamma", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"gamma\"");
    }
    {
        mipc_jr_push(jr, "gamma");
        if (mipc_jr_f64(jr, vp, &out->gamma)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "tau_n", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"tau_n\"");
    }
    {
        mipc_jr_push(jr, "tau_n");
        if (mipc_jr_f64(jr, vp, &out->tau_n)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "x", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"x\"");
    }
    {
        mipc_jr_push(jr, "x");
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
            if (mipc_jr_f64(jr, ep, &out->x[i])) {
                return -1;
            }
        }
        mipc_jr_index(jr, SIZE_MAX);
        if (i != 3) {
            return mipc_jr_fail(jr, "expected 3 elements, got %zu", i);
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "v", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"v\"");
    }
    {
        mipc_jr_push(jr, "v");
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
            if (mipc_jr_f32(jr, ep, &out->v[i])) {
                return -1;
            }
        }
        mipc_jr_index(jr, SIZE_MAX);
        if (i != 3) {
            return mipc_jr_fail(jr, "expected 3 elements, got %zu", i);
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "a", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"a\"");
    }
    {
        mipc_jr_push(jr, "a");
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
            if (mipc_jr_f32(jr, ep, &out->a[i])) {
                return -1;
            }
        }
        mipc_jr_index(jr, SIZE_MAX);
        if (i != 3) {
            return mipc_jr_fail(jr, "expected 3 elements, got %zu", i);
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "health", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"health\"");
    }
    {
        mipc_jr_push(jr, "health");
        if (mipc_jr_u8(jr, vp, &out->health)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "p", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"p\"");
    }
    {
        mipc_jr_push(jr, "p");
        if (mipc_jr_u8(jr, vp, &out->p)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "nt", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"nt\"");
    }
    {
        mipc_jr_push(jr, "nt");
        if (mipc_jr_u8(jr, vp, &out->nt)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "delta_tau_n", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"delta_tau_n\"");
    }
    {
        mipc_jr_push(jr, "delta_tau_n");
        if (mipc_jr_f32(jr, vp, &out->delta_tau_n)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "ft", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"ft\"");
    }
    {
        mipc_jr_push(jr, "ft");
        if (mipc_jr_u8(jr, vp, &out->ft)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "en", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"en\"");
    }
    {
        mipc_jr_push(jr, "en");
        if (mipc_jr_u8(jr, vp, &out->en)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "p1", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"p1\"");
    }
    {
        mipc_jr_push(jr, "p1");
        if (mipc_jr_u8(jr, vp, &out->p1)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "p2", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"p2\"");
    }
    {
        mipc_jr_push(jr, "p2");
        if (mipc_jr_u8(jr, vp, &out->p2)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "p3", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"p3\"");
    }
    {
        mipc_jr_push(jr, "p3");
        if (mipc_jr_u8(jr, vp, &out->p3)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "p4", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"p4\"");
    }
    {
        mipc_jr_push(jr, "p4");
        if (mipc_jr_u8(jr, vp, &out->p4)) {
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

/* ---- mipc_gnss_receiver_1_galileo_ephemeris_t */

void mipc_gnss_receiver_1_galileo_ephemeris_to_json(mipc_jw_t *w,
                                                    const mipc_gnss_receiver_1_galileo_ephemeris_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "index");
    mipc_jw_u8(w, &in->index);
    mipc_jw_key(w, &first, "count");
    mipc_jw_u8(w, &in->count);
    mipc_jw_key(w, &first, "tow");
    mipc_jw_f64(w, &in->tow);
    mipc_jw_key(w, &first, "week_number");
    mipc_jw_u16(w, &in->week_number);
    mipc_jw_key(w, &first, "satellite_id");
    mipc_jw_u8(w, &in->satellite_id);
    mipc_jw_key(w, &first, "health");
    mipc_jw_u8(w, &in->health);
    mipc_jw_key(w, &first, "iodc");
    mipc_jw_u8(w, &in->iodc);
    mipc_jw_key(w, &first, "iode");
    mipc_jw_u8(w, &in->iode);
    mipc_jw_key(w, &first, "t_oc");
    mipc_jw_f64(w, &in->t_oc);
    mipc_jw_key(w, &first, "af0");
    mipc_jw_f64(w, &in->af0);
    mipc_jw_key(w, &first, "af1");
    mipc_jw_f64(w, &in->af1);
    mipc_jw_key(w, &first, "af2");
    mipc_jw_f64(w, &in->af2);
    mipc_jw_key(w, &first, "t_gd");
    mipc_jw_f64(w, &in->t_gd);
    mipc_jw_key(w, &first, "isc_l1ca");
    mipc_jw_f64(w, &in->isc_l1ca);
    mipc_jw_key(w, &first, "isc_l2c");
    mipc_jw_f64(w, &in->isc_l2c);
    mipc_jw_key(w, &first, "t_oe");
    mipc_jw_f64(w, &in->t_oe);
    mipc_jw_key(w, &first, "a");
    mipc_jw_f64(w, &in->a);
    mipc_jw_key(w, &first, "a_dot");
    mipc_jw_f64(w, &in->a_dot);
    mipc_jw_key(w, &first, "mean_anomaly");
    mipc_jw_f64(w, &in->mean_anomaly);
    mipc_jw_key(w, &first, "delta_mean_motion");
    mipc_jw_f64(w, &in->delta_mean_motion);
    mipc_jw_key(w, &first, "delta_mean_motion_dot");
    mipc_jw_f64(w, &in->delta_mean_motion_dot);
    mipc_jw_key(w, &first, "eccentricity");
    mipc_jw_f64(w, &in->eccentricity);
    mipc_jw_key(w, &first, "argument_of_perigee");
    mipc_jw_f64(w, &in->argument_of_perigee);
    mipc_jw_key(w, &first, "omega");
    mipc_jw_f64(w, &in->omega);
    mipc_jw_key(w, &first, "omega_dot");
    mipc_jw_f64(w, &in->omega_dot);
    mipc_jw_key(w, &first, "inclination");
    mipc_jw_f64(w, &in->inclination);
    mipc_jw_key(w, &first, "inclination_dot");
    mipc_jw_f64(w, &in->inclination_dot);
    mipc_jw_key(w, &first, "c_ic");
    mipc_jw_f64(w, &in->c_ic);
    mipc_jw_key(w, &first, "c_is");
    mipc_jw_f64(w, &in->c_is);
    mipc_jw_key(w, &first, "c_uc");
    mipc_jw_f64(w, &in->c_uc);
    mipc_jw_key(w, &first, "c_us");
    mipc_jw_f64(w, &in->c_us);
    mipc_jw_key(w, &first, "c_rc");
    mipc_jw_f64(w, &in->c_rc);
    mipc_jw_key(w, &first, "c_rs");
    mipc_jw_f64(w, &in->c_rs);
    mipc_jw_key(w, &first, "valid_flags");
    mipc_jw_u16(w, &in->valid_flags);
    mipc_jw_raw(w, "}", 1);
}

int mipc_gnss_receiver_1_galileo_ephemeris_from_json(mipc_jr_t *jr, size_t pos,
                                                     mipc_gnss_receiver_1_galileo_ephemeris_t *out) {
    static const char *const keys[] = {"index",
                                       "count",
                                       "tow",
                                       "week_number",
                                       "satellite_id",
                                       "health",
                                       "iodc",
                                       "iode",
                                       "t_oc",
                                       "af0",
                                       "af1",
                                       "af2",
                                       "t_gd",
                                       "isc_l1ca",
                                       "isc_l2c",
                                       "t_oe",
                                       "a",
                                       "a_dot",
                                       "mean_anomaly",
                                       "delta_mean_motion",
                                       "delta_mean_motion_dot",
                                       "eccentricity",
                                       "argument_of_perigee",
                                       "omega",
                                       "omega_dot",
                                       "inclination",
                                       "inclination_dot",
                                       "c_ic",
                                       "c_is",
                                       "c_uc",
                                       "c_us",
                                       "c_rc",
                                       "c_rs",
                                       "valid_flags"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 34)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "index", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"index\"");
    }
    {
        mipc_jr_push(jr, "index");
        if (mipc_jr_u8(jr, vp, &out->index)) {
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
    found = mipc_jr_get(jr, pos, "satellite_id", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"satellite_id\"");
    }
    {
        mipc_jr_push(jr, "satellite_id");
        if (mipc_jr_u8(jr, vp, &out->satellite_id)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "health", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"health\"");
    }
    {
        mipc_jr_push(jr, "health");
        if (mipc_jr_u8(jr, vp, &out->health)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "iodc", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"iodc\"");
    }
    {
        mipc_jr_push(jr, "iodc");
        if (mipc_jr_u8(jr, vp, &out->iodc)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "iode", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"iode\"");
    }
    {
        mipc_jr_push(jr, "iode");
        if (mipc_jr_u8(jr, vp, &out->iode)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "t_oc", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"t_oc\"");
    }
    {
        mipc_jr_push(jr, "t_oc");
        if (mipc_jr_f64(jr, vp, &out->t_oc)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "af0", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"af0\"");
    }
    {
        mipc_jr_push(jr, "af0");
        if (mipc_jr_f64(jr, vp, &out->af0)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "af1", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"af1\"");
    }
    {
        mipc_jr_push(jr, "af1");
        if (mipc_jr_f64(jr, vp, &out->af1)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "af2", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"af2\"");
    }
    {
        mipc_jr_push(jr, "af2");
        if (mipc_jr_f64(jr, vp, &out->af2)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "t_gd", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"t_gd\"");
    }
    {
        mipc_jr_push(jr, "t_gd");
        if (mipc_jr_f64(jr, vp, &out->t_gd)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "isc_l1ca", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"isc_l1ca\"");
    }
    {
        mipc_jr_push(jr, "isc_l1ca");
        if (mipc_jr_f64(jr, vp, &out->isc_l1ca)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "isc_l2c", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"isc_l2c\"");
    }
    {
        mipc_jr_push(jr, "isc_l2c");
        if (mipc_jr_f64(jr, vp, &out->isc_l2c)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "t_oe", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"t_oe\"");
    }
    {
        mipc_jr_push(jr, "t_oe");
        if (mipc_jr_f64(jr, vp, &out->t_oe)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "a", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"a\"");
    }
    {
        mipc_jr_push(jr, "a");
        if (mipc_jr_f64(jr, vp, &out->a)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "a_dot", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"a_dot\"");
    }
    {
        mipc_jr_push(jr, "a_dot");
        if (mipc_jr_f64(jr, vp, &out->a_dot)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "mean_anomaly", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"mean_anomaly\"");
    }
    {
        mipc_jr_push(jr, "mean_anomaly");
        if (mipc_jr_f64(jr, vp, &out->mean_anomaly)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "delta_mean_motion", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"delta_mean_motion\"");
    }
    {
        mipc_jr_push(jr, "delta_mean_motion");
        if (mipc_jr_f64(jr, vp, &out->delta_mean_motion)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "delta_mean_motion_dot", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"delta_mean_motion_dot\"");
    }
    {
        mipc_jr_push(jr, "delta_mean_motion_dot");
        if (mipc_jr_f64(jr, vp, &out->delta_mean_motion_dot)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "eccentricity", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"eccentricity\"");
    }
    {
        mipc_jr_push(jr, "eccentricity");
        if (mipc_jr_f64(jr, vp, &out->eccentricity)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "argument_of_perigee", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"argument_of_perigee\"");
    }
    {
        mipc_jr_push(jr, "argument_of_perigee");
        if (mipc_jr_f64(jr, vp, &out->argument_of_perigee)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "omega", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"omega\"");
    }
    {
        mipc_jr_push(jr, "omega");
        if (mipc_jr_f64(jr, vp, &out->omega)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "omega_dot", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"omega_dot\"");
    }
    {
        mipc_jr_push(jr, "omega_dot");
        if (mipc_jr_f64(jr, vp, &out->omega_dot)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "inclination", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"inclination\"");
    }
    {
        mipc_jr_push(jr, "inclination");
        if (mipc_jr_f64(jr, vp, &out->inclination)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "inclination_dot", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"inclination_dot\"");
    }
    {
        mipc_jr_push(jr, "inclination_dot");
        if (mipc_jr_f64(jr, vp, &out->inclination_dot)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "c_ic", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"c_ic\"");
    }
    {
        mipc_jr_push(jr, "c_ic");
        if (mipc_jr_f64(jr, vp, &out->c_ic)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "c_is", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"c_is\"");
    }
    {
        mipc_jr_push(jr, "c_is");
        if (mipc_jr_f64(jr, vp, &out->c_is)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "c_uc", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"c_uc\"");
    }
    {
        mipc_jr_push(jr, "c_uc");
        if (mipc_jr_f64(jr, vp, &out->c_uc)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "c_us", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"c_us\"");
    }
    {
        mipc_jr_push(jr, "c_us");
        if (mipc_jr_f64(jr, vp, &out->c_us)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "c_rc", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"c_rc\"");
    }
    {
        mipc_jr_push(jr, "c_rc");
        if (mipc_jr_f64(jr, vp, &out->c_rc)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "c_rs", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"c_rs\"");
    }
    {
        mipc_jr_push(jr, "c_rs");
        if (mipc_jr_f64(jr, vp, &out->c_rs)) {
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

/* ---- mipc_gnss_receiver_1_beidou_ephemeris_t */

void mipc_gnss_receiver_1_beidou_ephemeris_to_json(mipc_jw_t *w,
                                                   const mipc_gnss_receiver_1_beidou_ephemeris_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "index");
    mipc_jw_u8(w, &in->index);
    mipc_jw_key(w, &first, "count");
    mipc_jw_u8(w, &in->count);
    mipc_jw_key(w, &first, "tow");
    mipc_jw_f64(w, &in->tow);
    mipc_jw_key(w, &first, "week_number");
    mipc_jw_u16(w, &in->week_number);
    mipc_jw_key(w, &first, "satellite_id");
    mipc_jw_u8(w, &in->satellite_id);
    mipc_jw_key(w, &first, "health");
    mipc_jw_u8(w, &in->health);
    mipc_jw_key(w, &first, "iodc");
    mipc_jw_u8(w, &in->iodc);
    mipc_jw_key(w, &first, "iode");
    mipc_jw_u8(w, &in->iode);
    mipc_jw_key(w, &first, "t_oc");
    mipc_jw_f64(w, &in->t_oc);
    mipc_jw_key(w, &first, "af0");
    mipc_jw_f64(w, &in->af0);
    mipc_jw_key(w, &first, "af1");
    mipc_jw_f64(w, &in->af1);
    mipc_jw_key(w, &first, "af2");
    mipc_jw_f64(w, &in->af2);
    mipc_jw_key(w, &first, "t_gd");
    mipc_jw_f64(w, &in->t_gd);
    mipc_jw_key(w, &first, "isc_l1ca");
    mipc_jw_f64(w, &in->isc_l1ca);
    mipc_jw_key(w, &first, "isc_l2c");
    mipc_jw_f64(w, &in->isc_l2c);
    mipc_jw_key(w, &first, "t_oe");
    mipc_jw_f64(w, &in->t_oe);
    mipc_jw_key(w, &first, "a");
    mipc_jw_f64(w, &in->a);
    mipc_jw_key(w, &first, "a_dot");
    mipc_jw_f64(w, &in->a_dot);
    mipc_jw_key(w, &first, "mean_anomaly");
    mipc_jw_f64(w, &in->mean_anomaly);
    mipc_jw_key(w, &first, "delta_mean_motion");
    mipc_jw_f64(w, &in->delta_mean_motion);
    mipc_jw_key(w, &first, "delta_mean_motion_dot");
    mipc_jw_f64(w, &in->delta_mean_motion_dot);
    mipc_jw_key(w, &first, "eccentricity");
    mipc_jw_f64(w, &in->eccentricity);
    mipc_jw_key(w, &first, "argument_of_perigee");
    mipc_jw_f64(w, &in->argument_of_perigee);
    mipc_jw_key(w, &first, "omega");
    mipc_jw_f64(w, &in->omega);
    mipc_jw_key(w, &first, "omega_dot");
    mipc_jw_f64(w, &in->omega_dot);
    mipc_jw_key(w, &first, "inclination");
    mipc_jw_f64(w, &in->inclination);
    mipc_jw_key(w, &first, "inclination_dot");
    mipc_jw_f64(w, &in->inclination_dot);
    mipc_jw_key(w, &first, "c_ic");
    mipc_jw_f64(w, &in->c_ic);
    mipc_jw_key(w, &first, "c_is");
    mipc_jw_f64(w, &in->c_is);
    mipc_jw_key(w, &first, "c_uc");
    mipc_jw_f64(w, &in->c_uc);
    mipc_jw_key(w, &first, "c_us");
    mipc_jw_f64(w, &in->c_us);
    mipc_jw_key(w, &first, "c_rc");
    mipc_jw_f64(w, &in->c_rc);
    mipc_jw_key(w, &first, "c_rs");
    mipc_jw_f64(w, &in->c_rs);
    mipc_jw_key(w, &first, "valid_flags");
    mipc_jw_u16(w, &in->valid_flags);
    mipc_jw_raw(w, "}", 1);
}

int mipc_gnss_receiver_1_beidou_ephemeris_from_json(mipc_jr_t *jr, size_t pos,
                                                    mipc_gnss_receiver_1_beidou_ephemeris_t *out) {
    static const char *const keys[] = {"index",
                                       "count",
                                       "tow",
                                       "week_number",
                                       "satellite_id",
                                       "health",
                                       "iodc",
                                       "iode",
                                       "t_oc",
                                       "af0",
                                       "af1",
                                       "af2",
                                       "t_gd",
                                       "isc_l1ca",
                                       "isc_l2c",
                                       "t_oe",
                                       "a",
                                       "a_dot",
                                       "mean_anomaly",
                                       "delta_mean_motion",
                                       "delta_mean_motion_dot",
                                       "eccentricity",
                                       "argument_of_perigee",
                                       "omega",
                                       "omega_dot",
                                       "inclination",
                                       "inclination_dot",
                                       "c_ic",
                                       "c_is",
                                       "c_uc",
                                       "c_us",
                                       "c_rc",
                                       "c_rs",
                                       "valid_flags"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 34)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "index", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"index\"");
    }
    {
        mipc_jr_push(jr, "index");
        if (mipc_jr_u8(jr, vp, &out->index)) {
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
    found = mipc_jr_get(jr, pos, "satellite_id", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"satellite_id\"");
    }
    {
        mipc_jr_push(jr, "satellite_id");
        if (mipc_jr_u8(jr, vp, &out->satellite_id)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "health", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"health\"");
    }
    {
        mipc_jr_push(jr, "health");
        if (mipc_jr_u8(jr, vp, &out->health)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "iodc", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"iodc\"");
    }
    {
        mipc_jr_push(jr, "iodc");
        if (mipc_jr_u8(jr, vp, &out->iodc)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "iode", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"iode\"");
    }
    {
        mipc_jr_push(jr, "iode");
        if (mipc_jr_u8(jr, vp, &out->iode)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "t_oc", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"t_oc\"");
    }
    {
        mipc_jr_push(jr, "t_oc");
        if (mipc_jr_f64(jr, vp, &out->t_oc)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "af0", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"af0\"");
    }
    {
        mipc_jr_push(jr, "af0");
        if (mipc_jr_f64(jr, vp, &out->af0)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "af1", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"af1\"");
    }
    {
        mipc_jr_push(jr, "af1");
        if (mipc_jr_f64(jr, vp, &out->af1)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "af2", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"af2\"");
    }
    {
        mipc_jr_push(jr, "af2");
        if (mipc_jr_f64(jr, vp, &out->af2)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "t_gd", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"t_gd\"");
    }
    {
        mipc_jr_push(jr, "t_gd");
        if (mipc_jr_f64(jr, vp, &out->t_gd)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "isc_l1ca", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"isc_l1ca\"");
    }
    {
        mipc_jr_push(jr, "isc_l1ca");
        if (mipc_jr_f64(jr, vp, &out->isc_l1ca)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "isc_l2c", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"isc_l2c\"");
    }
    {
        mipc_jr_push(jr, "isc_l2c");
        if (mipc_jr_f64(jr, vp, &out->isc_l2c)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "t_oe", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"t_oe\"");
    }
    {
        mipc_jr_push(jr, "t_oe");
        if (mipc_jr_f64(jr, vp, &out->t_oe)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "a", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"a\"");
    }
    {
        mipc_jr_push(jr, "a");
        if (mipc_jr_f64(jr, vp, &out->a)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "a_dot", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"a_dot\"");
    }
    {
        mipc_jr_push(jr, "a_dot");
        if (mipc_jr_f64(jr, vp, &out->a_dot)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "mean_anomaly", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"mean_anomaly\"");
    }
    {
        mipc_jr_push(jr, "mean_anomaly");
        if (mipc_jr_f64(jr, vp, &out->mean_anomaly)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "delta_mean_motion", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"delta_mean_motion\"");
    }
    {
        mipc_jr_push(jr, "delta_mean_motion");
        if (mipc_jr_f64(jr, vp, &out->delta_mean_motion)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "delta_mean_motion_dot", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"delta_mean_motion_dot\"");
    }
    {
        mipc_jr_push(jr, "delta_mean_motion_dot");
        if (mipc_jr_f64(jr, vp, &out->delta_mean_motion_dot)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "eccentricity", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"eccentricity\"");
    }
    {
        mipc_jr_push(jr, "eccentricity");
        if (mipc_jr_f64(jr, vp, &out->eccentricity)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "argument_of_perigee", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"argument_of_perigee\"");
    }
    {
        mipc_jr_push(jr, "argument_of_perigee");
        if (mipc_jr_f64(jr, vp, &out->argument_of_perigee)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "omega", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"omega\"");
    }
    {
        mipc_jr_push(jr, "omega");
        if (mipc_jr_f64(jr, vp, &out->omega)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "omega_dot", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"omega_dot\"");
    }
    {
        mipc_jr_push(jr, "omega_dot");
        if (mipc_jr_f64(jr, vp, &out->omega_dot)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "inclination", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"inclination\"");
    }
    {
        mipc_jr_push(jr, "inclination");
        if (mipc_jr_f64(jr, vp, &out->inclination)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "inclination_dot", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"inclination_dot\"");
    }
    {
        mipc_jr_push(jr, "inclination_dot");
        if (mipc_jr_f64(jr, vp, &out->inclination_dot)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "c_ic", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"c_ic\"");
    }
    {
        mipc_jr_push(jr, "c_ic");
        if (mipc_jr_f64(jr, vp, &out->c_ic)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "c_is", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"c_is\"");
    }
    {
        mipc_jr_push(jr, "c_is");
        if (mipc_jr_f64(jr, vp, &out->c_is)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "c_uc", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"c_uc\"");
    }
    {
        mipc_jr_push(jr, "c_uc");
        if (mipc_jr_f64(jr, vp, &out->c_uc)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "c_us", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"c_us\"");
    }
    {
        mipc_jr_push(jr, "c_us");
        if (mipc_jr_f64(jr, vp, &out->c_us)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "c_rc", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"c_rc\"");
    }
    {
        mipc_jr_push(jr, "c_rc");
        if (mipc_jr_f64(jr, vp, &out->c_rc)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "c_rs", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"c_rs\"");
    }
    {
        mipc_jr_push(jr, "c_rs");
        if (mipc_jr_f64(jr, vp, &out->c_rs)) {
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
