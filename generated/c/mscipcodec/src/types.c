/* Read/write/JSON functions of the named structs and unions. Generated: do not edit. */
#include "types_internal.h"

#include <string.h>

/* ---- MessageId */

int mscip_message_id_read(mscip_reader_t *r, mscip_message_id_t *out) {
    mscip_rd_push(r, "message_type");
    if (mscip_rd_u8(r, &out->message_type)) {
        return -1;
    }
    mscip_rd_pop(r);
    mscip_rd_push(r, "message_code");
    if (mscip_rd_u8(r, &out->message_code)) {
        return -1;
    }
    mscip_rd_pop(r);
    return 0;
}

mscip_status_t mscip_message_id_write(mscip_writer_t *w, const mscip_message_id_t *in) {
    mscip_status_t st;
    if ((st = mscip_wr_u8(w, &in->message_type)) != MSCIP_OK) {
        return st;
    }
    if ((st = mscip_wr_u8(w, &in->message_code)) != MSCIP_OK) {
        return st;
    }
    return MSCIP_OK;
}

void mscip_message_id_to_json(mscip_jw_t *w, const mscip_message_id_t *in) {
    int first = 1;
    mscip_jw_raw(w, "{", 1);
    mscip_jw_key(w, &first, "message_type");
    mscip_jw_u8(w, &in->message_type);
    mscip_jw_key(w, &first, "message_code");
    mscip_jw_u8(w, &in->message_code);
    mscip_jw_raw(w, "}", 1);
}

int mscip_message_id_from_json(mscip_jr_t *jr, size_t pos, mscip_message_id_t *out) {
    static const char *const keys[] = {"message_type", "message_code"};
    size_t vp = 0;
    int found;
    if (mscip_jr_object(jr, pos, keys, 2)) {
        return -1;
    }
    found = mscip_jr_get(jr, pos, "message_type", &vp);
    if (found != 1) {
        return mscip_jr_fail(jr, "missing parameter \"message_type\"");
    }
    {
        mscip_jr_push(jr, "message_type");
        if (mscip_jr_u8(jr, vp, &out->message_type)) {
            return -1;
        }
        mscip_jr_pop(jr);
    }
    found = mscip_jr_get(jr, pos, "message_code", &vp);
    if (found != 1) {
        return mscip_jr_fail(jr, "missing parameter \"message_code\"");
    }
    {
        mscip_jr_push(jr, "message_code");
        if (mscip_jr_u8(jr, vp, &out->message_code)) {
            return -1;
        }
        mscip_jr_pop(jr);
    }
    return 0;
}
