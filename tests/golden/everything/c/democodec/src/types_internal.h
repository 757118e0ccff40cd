/* Private: read/write/JSON functions of the named structs and unions. Generated: do not edit. */
#ifndef DEMOC_TYPES_INTERNAL_H
#define DEMOC_TYPES_INTERNAL_H

#include "democodec/types.h"
#include "json_reader.h"
#include "json_writer.h"
#include "wire.h"

int democ_gpio_params_read(democ_reader_t *r, democ_gpio_params_t *out);
democ_status_t democ_gpio_params_write(democ_writer_t *w, const democ_gpio_params_t *in);
void democ_gpio_params_to_json(democ_jw_t *w, const democ_gpio_params_t *in);
int democ_gpio_params_from_json(democ_jr_t *jr, size_t pos, democ_gpio_params_t *out);
int democ_threshold_params_read(democ_reader_t *r, democ_threshold_params_t *out);
democ_status_t democ_threshold_params_write(democ_writer_t *w, const democ_threshold_params_t *in);
void democ_threshold_params_to_json(democ_jw_t *w, const democ_threshold_params_t *in);
int democ_threshold_params_from_json(democ_jr_t *jr, size_t pos, democ_threshold_params_t *out);
int democ_trigger_params_read(democ_reader_t *r, democ_mode_t selector, democ_trigger_params_t *out);
democ_status_t democ_trigger_params_write(democ_writer_t *w, democ_mode_t selector,
                                          const democ_trigger_params_t *in);
void democ_trigger_params_to_json(democ_jw_t *w, democ_mode_t selector, const democ_trigger_params_t *in);
int democ_trigger_params_from_json(democ_jr_t *jr, size_t pos, democ_mode_t selector,
                                   democ_trigger_params_t *out);

#endif
