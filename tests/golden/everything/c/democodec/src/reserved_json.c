/* Canonical JSON of Reserved fields (valid in every set of their kind) (the democodec_json library).
 * Generated from the spec: do not edit. */
#include "democodec/reserved.h"
#include "layouts_internal.h"
#include "types_internal.h"

#include <assert.h>
#include <string.h>

/* ---- democ_ack_t */

void democ_ack_to_json(democ_jw_t *w, const democ_ack_t *in) {
    int first = 1;
    democ_jw_raw(w, "{", 1);
    democ_jw_key(w, &first, "echo");
    democ_jw_u8(w, &in->echo);
    democ_jw_key(w, &first, "code");
    democ_jw_u8(w, &in->code);
    democ_jw_raw(w, "}", 1);
}

int democ_ack_from_json(democ_jr_t *jr, size_t pos, democ_ack_t *out) {
    static const char *const keys[] = {"echo", "code"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (democ_jr_object(jr, pos, keys, 2)) {
        return -1;
    }
    found = democ_jr_get(jr, pos, "echo", &vp);
    if (found != 1) {
        return democ_jr_fail(jr, "missing parameter \"echo\"");
    }
    {
        democ_jr_push(jr, "echo");
        if (democ_jr_u8(jr, vp, &out->echo)) {
            return -1;
        }
        democ_jr_pop(jr);
    }
    found = democ_jr_get(jr, pos, "code", &vp);
    if (found != 1) {
        return democ_jr_fail(jr, "missing parameter \"code\"");
    }
    {
        democ_jr_push(jr, "code");
        if (democ_jr_u8(jr, vp, &out->code)) {
            return -1;
        }
        democ_jr_pop(jr);
    }
    return 0;
}
