/* Canonical JSON of GNSS External Data Set (the mipcodec_json library). Generated from the spec: do not edit.
 */
#include "mipcodec/sets/gnss_external.h"
#include "layouts_internal.h"
#include "types_internal.h"

#include <assert.h>
#include <string.h>

/* ---- mipc_gnss_external_llh_position_t */

void mipc_gnss_external_llh_position_to_json(mipc_jw_t *w, const mipc_gnss_external_llh_position_t *in) {
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

int mipc_gnss_external_llh_position_from_json(mipc_jr_t *jr, size_t pos,
                                              mipc_gnss_external_llh_position_t *out) {
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

/* ---- mipc_gnss_external_ned_velocity_t */

void mipc_gnss_external_ned_velocity_to_json(mipc_jw_t *w, const mipc_gnss_external_ned_velocity_t *in) {
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

int mipc_gnss_external_ned_velocity_from_json(mipc_jr_t *jr, size_t pos,
                                              mipc_gnss_external_ned_velocity_t *out) {
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

/* ---- mipc_gnss_external_utc_time_t */

void mipc_gnss_external_utc_time_to_json(mipc_jw_t *w, const mipc_gnss_external_utc_time_t *in) {
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

int mipc_gnss_external_utc_time_from_json(mipc_jr_t *jr, size_t pos, mipc_gnss_external_utc_time_t *out) {
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

/* ---- mipc_gnss_external_fix_info_t */

void mipc_gnss_external_fix_info_to_json(mipc_jw_t *w, const mipc_gnss_external_fix_info_t *in) {
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

int mipc_gnss_external_fix_info_from_json(mipc_jr_t *jr, size_t pos, mipc_gnss_external_fix_info_t *out) {
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

/* ---- mipc_gnss_external_satellite_status_t */

void mipc_gnss_external_satellite_status_to_json(mipc_jw_t *w,
                                                 const mipc_gnss_external_satellite_status_t *in) {
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

int mipc_gnss_external_satellite_status_from_json(mipc_jr_t *jr, size_t pos,
                                                  mipc_gnss_external_satellite_status_t *out) {
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
