/* Canonical JSON of Shared data (the democodec_json library). Generated from the spec: do not edit. */
#include "democodec/sets/shared.h"
#include "layouts_internal.h"
#include "types_internal.h"

#include <assert.h>
#include <string.h>

/* ---- democ_shared_timestamp_t */

void democ_shared_timestamp_to_json(democ_jw_t *w, const democ_shared_timestamp_t *in) {
    int first = 1;
    democ_jw_raw(w, "{", 1);
    democ_jw_key(w, &first, "nanoseconds");
    democ_jw_u64(w, &in->nanoseconds);
    democ_jw_raw(w, "}", 1);
}

int democ_shared_timestamp_from_json(democ_jr_t *jr, size_t pos, democ_shared_timestamp_t *out) {
    static const char *const keys[] = {"nanoseconds"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (democ_jr_object(jr, pos, keys, 1)) {
        return -1;
    }
    found = democ_jr_get(jr, pos, "nanoseconds", &vp);
    if (found != 1) {
        return democ_jr_fail(jr, "missing parameter \"nanoseconds\"");
    }
    {
        democ_jr_push(jr, "nanoseconds");
        if (democ_jr_u64(jr, vp, &out->nanoseconds)) {
            return -1;
        }
        democ_jr_pop(jr);
    }
    return 0;
}
