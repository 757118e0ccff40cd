/* Private: read/write/JSON functions of the named structs and unions. Generated: do not edit. */
#ifndef MSCIPC_TYPES_INTERNAL_H
#define MSCIPC_TYPES_INTERNAL_H

#include "mscipcodec/types.h"
#include "json_reader.h"
#include "json_writer.h"
#include "wire.h"

int mscipc_message_id_read(mscipc_reader_t *r, mscipc_message_id_t *out);
mscipc_status_t mscipc_message_id_write(mscipc_writer_t *w, const mscipc_message_id_t *in);
void mscipc_message_id_to_json(mscipc_jw_t *w, const mscipc_message_id_t *in);
int mscipc_message_id_from_json(mscipc_jr_t *jr, size_t pos, mscipc_message_id_t *out);

#endif
