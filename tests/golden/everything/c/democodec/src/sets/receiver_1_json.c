/* Canonical JSON of Receiver 1 (the democodec_json library). Generated from the spec: do not edit. */
#include "democodec/sets/receiver_1.h"
#include "layouts_internal.h"
#include "types_internal.h"

#include <assert.h>
#include <string.h>

/* ---- democ_receiver_1_llh_position_t */

void democ_receiver_1_llh_position_to_json(democ_jw_t *w, const democ_receiver_1_llh_position_t *in) {
    int first = 1;
    democ_jw_raw(w, "{", 1);
    democ_jw_key(w, &first, "latitude");
    democ_jw_f64(w, &in->latitude);
    democ_jw_key(w, &first, "longitude");
    democ_jw_f64(w, &in->longitude);
    democ_jw_key(w, &first, "valid_flags");
    democ_jw_u16(w, &in->valid_flags);
    democ_jw_raw(w, "}", 1);
}

int democ_receiver_1_llh_position_from_json(democ_jr_t *jr, size_t pos,
                                            democ_receiver_1_llh_position_t *out) {
    static const char *const keys[] = {"latitude", "longitude", "valid_flags"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (democ_jr_object(jr, pos, keys, 3)) {
        return -1;
    }
    found = democ_jr_get(jr, pos, "latitude", &vp);
    if (found != 1) {
        return democ_jr_fail(jr, "missing parameter \"latitude\"");
    }
    {
        democ_jr_push(jr, "latitude");
        if (democ_jr_f64(jr, vp, &out->latitude)) {
            return -1;
        }
        democ_jr_pop(jr);
    }
    found = democ_jr_get(jr, pos, "longitude", &vp);
    if (found != 1) {
        return democ_jr_fail(jr, "missing parameter \"longitude\"");
    }
    {
        democ_jr_push(jr, "longitude");
        if (democ_jr_f64(jr, vp, &out->longitude)) {
            return -1;
        }
        democ_jr_pop(jr);
    }
    found = democ_jr_get(jr, pos, "valid_flags", &vp);
    if (found != 1) {
        return democ_jr_fail(jr, "missing parameter \"valid_flags\"");
    }
    {
        democ_jr_push(jr, "valid_flags");
        if (democ_jr_u16(jr, vp, &out->valid_flags)) {
            return -1;
        }
        democ_jr_pop(jr);
    }
    return 0;
}
