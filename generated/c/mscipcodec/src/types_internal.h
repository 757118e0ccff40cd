/* Private: read/write/JSON functions of the named structs and unions. Generated: do not edit. */
#ifndef MSCIP_TYPES_INTERNAL_H
#define MSCIP_TYPES_INTERNAL_H

#include "mscipcodec/types.h"
#include "json_reader.h"
#include "json_writer.h"
#include "wire.h"

int mscip_message_id_read(mscip_reader_t *r, mscip_message_id_t *out);
mscip_status_t mscip_message_id_write(mscip_writer_t *w, const mscip_message_id_t *in);
void mscip_message_id_to_json(mscip_jw_t *w, const mscip_message_id_t *in);
int mscip_message_id_from_json(mscip_jr_t *jr, size_t pos, mscip_message_id_t *out);

#endif
