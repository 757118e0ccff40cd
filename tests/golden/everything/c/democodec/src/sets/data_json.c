/* Canonical JSON of Data (the democodec_json library). Generated from the spec: do not edit. */
#include "democodec/sets/data.h"
#include "layouts_internal.h"
#include "types_internal.h"

#include <assert.h>
#include <string.h>

/* ---- democ_data_sample_t */

void democ_data_sample_to_json(democ_jw_t *w, const democ_data_sample_t *in) {
    int first = 1;
    size_t i;
    democ_jw_raw(w, "{", 1);
    democ_jw_key(w, &first, "quat");
    democ_jw_raw(w, "[", 1);
    for (i = 0; i < 4; i++) {
        democ_jw_sep(w, i);
        democ_jw_f32(w, &in->quat[i]);
    }
    democ_jw_raw(w, "]", 1);
    democ_jw_key(w, &first, "big");
    democ_jw_u64(w, &in->big);
    democ_jw_key(w, &first, "small");
    democ_jw_s8(w, &in->small);
    democ_jw_key(w, &first, "f");
    democ_jw_f32(w, &in->f);
    democ_jw_raw(w, "}", 1);
}

int democ_data_sample_from_json(democ_jr_t *jr, size_t pos, democ_data_sample_t *out) {
    static const char *const keys[] = {"quat", "big", "small", "f"};
    size_t vp = 0;
    int found;
    size_t i;
    size_t it = 0;
    size_t ep = 0;
    memset(out, 0, sizeof *out);
    if (democ_jr_object(jr, pos, keys, 4)) {
        return -1;
    }
    found = democ_jr_get(jr, pos, "quat", &vp);
    if (found != 1) {
        return democ_jr_fail(jr, "missing parameter \"quat\"");
    }
    {
        democ_jr_push(jr, "quat");
        if (democ_jr_array(jr, vp, &it)) {
            return -1;
        }
        for (i = 0;; i++) {
            int more = democ_jr_next(jr, &it, &ep);
            if (more < 0) {
                return -1;
            }
            if (!more) {
                break;
            }
            if (i >= 4) {
                return democ_jr_fail(jr, "more than 4 elements");
            }
            democ_jr_index(jr, i);
            if (democ_jr_f32(jr, ep, &out->quat[i])) {
                return -1;
            }
        }
        democ_jr_index(jr, SIZE_MAX);
        if (i != 4) {
            return democ_jr_fail(jr, "expected 4 elements, got %zu", i);
        }
        democ_jr_pop(jr);
    }
    found = democ_jr_get(jr, pos, "big", &vp);
    if (found != 1) {
        return democ_jr_fail(jr, "missing parameter \"big\"");
    }
    {
        democ_jr_push(jr, "big");
        if (democ_jr_u64(jr, vp, &out->big)) {
            return -1;
        }
        democ_jr_pop(jr);
    }
    found = democ_jr_get(jr, pos, "small", &vp);
    if (found != 1) {
        return democ_jr_fail(jr, "missing parameter \"small\"");
    }
    {
        democ_jr_push(jr, "small");
        if (democ_jr_s8(jr, vp, &out->small)) {
            return -1;
        }
        democ_jr_pop(jr);
    }
    found = democ_jr_get(jr, pos, "f", &vp);
    if (found != 1) {
        return democ_jr_fail(jr, "missing parameter \"f\"");
    }
    {
        democ_jr_push(jr, "f");
        if (democ_jr_f32(jr, vp, &out->f)) {
            return -1;
        }
        democ_jr_pop(jr);
    }
    return 0;
}
