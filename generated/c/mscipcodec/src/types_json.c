/* Canonical JSON of the named structs and unions (the mscipcodec_json library). Generated: do not edit. */
#include "types_internal.h"

#include <string.h>

/* ---- MessageId */

void mscipc_message_id_to_json(mscipc_jw_t *w, const mscipc_message_id_t *in) {
    int first = 1;
    mscipc_jw_raw(w, "{", 1);
    mscipc_jw_key(w, &first, "message_type");
    mscipc_jw_u8(w, &in->message_type);
    mscipc_jw_key(w, &first, "message_code");
    mscipc_jw_u8(w, &in->message_code);
    mscipc_jw_raw(w, "}", 1);
}

int mscipc_message_id_from_json(mscipc_jr_t *jr, size_t pos, mscipc_message_id_t *out) {
    static const char *const keys[] = {"message_type", "message_code"};
    size_t vp = 0;
    int found;
    if (mscipc_jr_object(jr, pos, keys, 2)) {
        return -1;
    }
    found = mscipc_jr_get(jr, pos, "message_type", &vp);
    if (found != 1) {
        return mscipc_jr_fail(jr, "missing parameter \"message_type\"");
    }
    {
        mscipc_jr_push(jr, "message_type");
        if (mscipc_jr_u8(jr, vp, &out->message_type)) {
            return -1;
        }
        mscipc_jr_pop(jr);
    }
    found = mscipc_jr_get(jr, pos, "message_code", &vp);
    if (found != 1) {
        return mscipc_jr_fail(jr, "missing parameter \"message_code\"");
    }
    {
        mscipc_jr_push(jr, "message_code");
        if (mscipc_jr_u8(jr, vp, &out->message_code)) {
            return -1;
        }
        mscipc_jr_pop(jr);
    }
    return 0;
}
