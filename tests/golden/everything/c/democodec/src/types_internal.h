/* Private: read/write/JSON functions of the named structs and unions. Generated: do not edit. */
#ifndef DEMO_TYPES_INTERNAL_H
#define DEMO_TYPES_INTERNAL_H

#include "democodec/types.h"
#include "json_reader.h"
#include "json_writer.h"
#include "wire.h"

int demo_gpio_params_read(demo_reader_t *r, demo_gpio_params_t *out);
demo_status_t demo_gpio_params_write(demo_writer_t *w, const demo_gpio_params_t *in);
void demo_gpio_params_to_json(demo_jw_t *w, const demo_gpio_params_t *in);
int demo_gpio_params_from_json(demo_jr_t *jr, size_t pos, demo_gpio_params_t *out);
int demo_threshold_params_read(demo_reader_t *r, demo_threshold_params_t *out);
demo_status_t demo_threshold_params_write(demo_writer_t *w, const demo_threshold_params_t *in);
void demo_threshold_params_to_json(demo_jw_t *w, const demo_threshold_params_t *in);
int demo_threshold_params_from_json(demo_jr_t *jr, size_t pos, demo_threshold_params_t *out);
int demo_trigger_params_read(demo_reader_t *r, demo_mode_t selector, demo_trigger_params_t *out);
demo_status_t demo_trigger_params_write(demo_writer_t *w, demo_mode_t selector,
                                        const demo_trigger_params_t *in);
void demo_trigger_params_to_json(demo_jw_t *w, demo_mode_t selector, const demo_trigger_params_t *in);
int demo_trigger_params_from_json(demo_jr_t *jr, size_t pos, demo_mode_t selector,
                                  demo_trigger_params_t *out);

#endif
