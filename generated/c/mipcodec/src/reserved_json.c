/* Canonical JSON of Reserved fields (valid in every set of their kind) (the mipcodec_json library). Generated
 * from the spec: do not edit. */
#include "mipcodec/reserved.h"
#include "layouts_internal.h"
#include "types_internal.h"

#include <assert.h>
#include <string.h>

/* ---- mipc_ack_nack_t */

void mipc_ack_nack_to_json(mipc_jw_t *w, const mipc_ack_nack_t *in) {
    int first = 1;
    mipc_jw_raw(w, "{", 1);
    mipc_jw_key(w, &first, "command_descriptor");
    mipc_jw_u8(w, &in->command_descriptor);
    mipc_jw_key(w, &first, "ack_code");
    mipc_jw_u8(w, &in->ack_code);
    mipc_jw_raw(w, "}", 1);
}

int mipc_ack_nack_from_json(mipc_jr_t *jr, size_t pos, mipc_ack_nack_t *out) {
    static const char *const keys[] = {"command_descriptor", "ack_code"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (mipc_jr_object(jr, pos, keys, 2)) {
        return -1;
    }
    found = mipc_jr_get(jr, pos, "command_descriptor", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"command_descriptor\"");
    }
    {
        mipc_jr_push(jr, "command_descriptor");
        if (mipc_jr_u8(jr, vp, &out->command_descriptor)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    found = mipc_jr_get(jr, pos, "ack_code", &vp);
    if (found != 1) {
        return mipc_jr_fail(jr, "missing parameter \"ack_code\"");
    }
    {
        mipc_jr_push(jr, "ack_code");
        if (mipc_jr_u8(jr, vp, &out->ack_code)) {
            return -1;
        }
        mipc_jr_pop(jr);
    }
    return 0;
}
