/* Read/write functions of the named structs and unions. Generated: do not edit. */
#include "types_internal.h"

#include <string.h>

/* ---- MessageId */

int mscipc_message_id_read(mscipc_reader_t *r, mscipc_message_id_t *out) {
    mscipc_rd_push(r, "message_type");
    if (mscipc_rd_u8(r, &out->message_type)) {
        return -1;
    }
    mscipc_rd_pop(r);
    mscipc_rd_push(r, "message_code");
    if (mscipc_rd_u8(r, &out->message_code)) {
        return -1;
    }
    mscipc_rd_pop(r);
    return 0;
}

mscipc_status_t mscipc_message_id_write(mscipc_writer_t *w, const mscipc_message_id_t *in) {
    mscipc_status_t st;
    if ((st = mscipc_wr_u8(w, &in->message_type)) != MSCIPC_OK) {
        return st;
    }
    if ((st = mscipc_wr_u8(w, &in->message_code)) != MSCIPC_OK) {
        return st;
    }
    return MSCIPC_OK;
}
