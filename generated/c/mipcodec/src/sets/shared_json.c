/* Canonical JSON of Shared Data Descriptors (the mipcodec_json library). Generated from the spec: do not
 * edit. */
#include "mipcodec/sets/shared.h"
#include "layouts_internal.h"
#include "types_internal.h"

#include <assert.h>
#include <string.h>

/* ---- mipc_shared_event_source_t */

void mipc_shared_event_source_to_json(mipc_jw_t *w, const mipc_shared_event_source_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "trigger_id");
    mipc_jw_u8(w, &in->trigger_id);
    mipc_jw_raw(w, "}", 1);
}

int mipc_shared_event_source_from_json(mipc_jr_t *jr, size_t pos, mipc_shared_event_source_t *out) {
    static const char *const keys[] = {"trigger_id"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 1)) {
        return -1;
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

/* ---- mipc_shared_gps_timestamp_t */

void mipc_shared_gps_timestamp_to_json(mipc_jw_t *w, const mipc_shared_gps_timestamp_t *in) {
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

int mipc_shared_gps_timestamp_from_json(mipc_jr_t *jr, size_t pos, mipc_shared_gps_timestamp_t *out) {
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

/* ---- mipc_shared_delta_time_t */

void mipc_shared_delta_time_to_json(mipc_jw_t *w, const mipc_shared_delta_time_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "seconds");
    mipc_jw_f64(w, &in->seconds);
    mipc_jw_raw(w, "}", 1);
}

int mipc_shared_delta_time_from_json(mipc_jr_t *jr, size_t pos, mipc_shared_delta_time_t *out) {
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
        if (mipc_jr_f64(jr, vp, &out->seconds)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mipc_shared_reference_timestamp_t */

void mipc_shared_reference_timestamp_to_json(mipc_jw_t *w, const mipc_shared_reference_timestamp_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "nanoseconds");
    mipc_jw_u64(w, &in->nanoseconds);
    mipc_jw_raw(w, "}", 1);
}

int mipc_shared_reference_timestamp_from_json(mipc_jr_t *jr, size_t pos,
                                              mipc_shared_reference_timestamp_t *out) {
    static const char *const keys[] = {"nanoseconds"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 1)) {
        return -1;
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

/* ---- mipc_shared_reference_time_delta_t */

void mipc_shared_reference_time_delta_to_json(mipc_jw_t *w, const mipc_shared_reference_time_delta_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "dt_nanos");
    mipc_jw_u64(w, &in->dt_nanos);
    mipc_jw_raw(w, "}", 1);
}

int mipc_shared_reference_time_delta_from_json(mipc_jr_t *jr, size_t pos,
                                               mipc_shared_reference_time_delta_t *out) {
    static const char *const keys[] = {"dt_nanos"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 1)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "dt_nanos", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"dt_nanos\"");
    }
    {
        mipc_jr_push(jr, "dt_nanos");
        if (mipc_jr_u64(jr, vp, &out->dt_nanos)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mipc_shared_external_timestamp_t */

void mipc_shared_external_timestamp_to_json(mipc_jw_t *w, const mipc_shared_external_timestamp_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "nanoseconds");
    mipc_jw_u64(w, &in->nanoseconds);
    mipc_jw_key(w, &first, "valid_flags");
    mipc_jw_u16(w, &in->valid_flags);
    mipc_jw_raw(w, "}", 1);
}

int mipc_shared_external_timestamp_from_json(mipc_jr_t *jr, size_t pos,
                                             mipc_shared_external_timestamp_t *out) {
    static const char *const keys[] = {"nanoseconds", "valid_flags"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 2)) {
        return -1;
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

/* ---- mipc_shared_external_time_delta_t */

void mipc_shared_external_time_delta_to_json(mipc_jw_t *w, const mipc_shared_external_time_delta_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "dt_nanos");
    mipc_jw_u64(w, &in->dt_nanos);
    mipc_jw_key(w, &first, "valid_flags");
    mipc_jw_u16(w, &in->valid_flags);
    mipc_jw_raw(w, "}", 1);
}

int mipc_shared_external_time_delta_from_json(mipc_jr_t *jr, size_t pos,
                                              mipc_shared_external_time_delta_t *out) {
    static const char *const keys[] = {"dt_nanos", "valid_flags"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 2)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "dt_nanos", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"dt_nanos\"");
    }
    {
        mipc_jr_push(jr, "dt_nanos");
        if (mipc_jr_u64(jr, vp, &out->dt_nanos)) {
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
