/* Canonical JSON of System Data Set (the mipcodec_json library). Generated from the spec: do not edit. */
#include "mipcodec/sets/system_data.h"
#include "layouts_internal.h"
#include "types_internal.h"

#include <assert.h>
#include <string.h>

/* ---- mipc_system_data_built_in_test_t */

void mipc_system_data_built_in_test_to_json(mipc_jw_t *w, const mipc_system_data_built_in_test_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "result");
    mipc_cv7_continuous_bit_to_json(w, &in->result);
    mipc_jw_raw(w, "}", 1);
}

int mipc_system_data_built_in_test_from_json(mipc_jr_t *jr, size_t pos,
                                             mipc_system_data_built_in_test_t *out) {
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

/* ---- mipc_system_data_time_sync_status_t */

void mipc_system_data_time_sync_status_to_json(mipc_jw_t *w, const mipc_system_data_time_sync_status_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "time_sync");
    mipc_jw_bool(w, &in->time_sync);
    mipc_jw_key(w, &first, "last_pps_rcvd");
    mipc_jw_u8(w, &in->last_pps_rcvd);
    mipc_jw_raw(w, "}", 1);
}

int mipc_system_data_time_sync_status_from_json(mipc_jr_t *jr, size_t pos,
                                                mipc_system_data_time_sync_status_t *out) {
    static const char *const keys[] = {"time_sync", "last_pps_rcvd"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 2)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "time_sync", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"time_sync\"");
    }
    {
        mipc_jr_push(jr, "time_sync");
        if (mipc_jr_bool(jr, vp, &out->time_sync)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "last_pps_rcvd", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"last_pps_rcvd\"");
    }
    {
        mipc_jr_push(jr, "last_pps_rcvd");
        if (mipc_jr_u8(jr, vp, &out->last_pps_rcvd)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    return 0;
}

/* ---- mipc_system_data_gpio_state_t */

void mipc_system_data_gpio_state_to_json(mipc_jw_t *w, const mipc_system_data_gpio_state_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "states");
    mipc_jw_u8(w, &in->states);
    mipc_jw_raw(w, "}", 1);
}

int mipc_system_data_gpio_state_from_json(mipc_jr_t *jr, size_t pos, mipc_system_data_gpio_state_t *out) {
    static const char *const keys[] = {"states"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 1)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "states", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"states\"");
    }
    {
        mipc_jr_push(jr, "states");
        if (mipc_jr_u8(jr, vp, &out->states)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    return 0;
}
