/* Canonical JSON of Reserved fields (valid in every set of their kind) (the mscipcodec_json library).
 * Generated from the spec: do not edit. */
#include "mscipcodec/reserved.h"
#include "layouts_internal.h"
#include "types_internal.h"

#include <assert.h>
#include <string.h>

/* ---- mscipc_ack_t */

void mscipc_ack_to_json(mscipc_jw_t *w, const mscipc_ack_t *in) {
    int first = 1;
    mscipc_jw_raw(w, "{", 1);
    mscipc_jw_key(w, &first, "command_code");
    mscipc_jw_u8(w, &in->command_code);
    mscipc_jw_key(w, &first, "error_code");
    mscipc_jw_u8(w, &in->error_code);
    mscipc_jw_raw(w, "}", 1);
}

int mscipc_ack_from_json(mscipc_jr_t *jr, size_t pos, mscipc_ack_t *out) {
    static const char *const keys[] = {"command_code", "error_code"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mscipc_jr_object(jr, pos, keys, 2)) {
        return -1;
    }
    found = mscipc_jr_get(jr, pos, "command_code", &vp);
    if (found != 1) {
        return mscipc_jr_fail(jr, "missing parameter \"command_code\"");
    }
    {
        mscipc_jr_push(jr, "command_code");
        if (mscipc_jr_u8(jr, vp, &out->command_code)) {
            return -1;
        }
        mscipc_jr_pop(jr);
    }
    found = mscipc_jr_get(jr, pos, "error_code", &vp);
    if (found != 1) {
        return mscipc_jr_fail(jr, "missing parameter \"error_code\"");
    }
    {
        mscipc_jr_push(jr, "error_code");
        if (mscipc_jr_u8(jr, vp, &out->error_code)) {
            return -1;
        }
        mscipc_jr_pop(jr);
    }
    return 0;
}
