/* Stand-in for a generated layouts_internal.h (templates/c/layouts_internal.h.j2): the JSON
 * functions of the test protocol's layouts (see codec/dispatch.h). */
#ifndef CODEC_LAYOUTS_INTERNAL_H
#define CODEC_LAYOUTS_INTERNAL_H

#include "codec/dispatch.h"
#include "json_reader.h"
#include "json_writer.h"

void codec_value_to_json(codec_jw_t *w, const codec_field_value_t *value);
int codec_value_from_json(codec_jr_t *jr, size_t pos, codec_field_id_t id, codec_field_value_t *value);

#endif
