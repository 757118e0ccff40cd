/* Private: JSON functions of every field layout. Generated: do not edit. */
#ifndef DEMOC_LAYOUTS_INTERNAL_H
#define DEMOC_LAYOUTS_INTERNAL_H

#include "democodec/dispatch.h"
#include "json_reader.h"
#include "json_writer.h"

/* Keeps a rarely taken path (the general reader, error details) out of line so that the common
 * path around it stays a short function without register saves. */
#if defined(__GNUC__) || defined(__clang__)
#define DEMOC_NOINLINE __attribute__((noinline))
#elif defined(_MSC_VER)
#define DEMOC_NOINLINE __declspec(noinline)
#else
#define DEMOC_NOINLINE
#endif

void democ_ack_to_json(democ_jw_t *w, const democ_ack_t *in);
int democ_ack_from_json(democ_jr_t *jr, size_t pos, democ_ack_t *out);
void democ_commands_ping_to_json(democ_jw_t *w, const democ_commands_ping_t *in);
int democ_commands_ping_from_json(democ_jr_t *jr, size_t pos, democ_commands_ping_t *out);
void democ_commands_configure_to_json(democ_jw_t *w, const democ_commands_configure_t *in);
int democ_commands_configure_from_json(democ_jr_t *jr, size_t pos, democ_commands_configure_t *out);
void democ_commands_configuration_to_json(democ_jw_t *w, const democ_commands_configuration_t *in);
int democ_commands_configuration_from_json(democ_jr_t *jr, size_t pos, democ_commands_configuration_t *out);
void democ_commands_per_device_dev_a_to_json(democ_jw_t *w, const democ_commands_per_device_dev_a_t *in);
int democ_commands_per_device_dev_a_from_json(democ_jr_t *jr, size_t pos,
                                              democ_commands_per_device_dev_a_t *out);
void democ_commands_per_device_dev_b_to_json(democ_jw_t *w, const democ_commands_per_device_dev_b_t *in);
int democ_commands_per_device_dev_b_from_json(democ_jr_t *jr, size_t pos,
                                              democ_commands_per_device_dev_b_t *out);
void democ_data_sample_to_json(democ_jw_t *w, const democ_data_sample_t *in);
int democ_data_sample_from_json(democ_jr_t *jr, size_t pos, democ_data_sample_t *out);
void democ_receiver_1_llh_position_to_json(democ_jw_t *w, const democ_receiver_1_llh_position_t *in);
int democ_receiver_1_llh_position_from_json(democ_jr_t *jr, size_t pos, democ_receiver_1_llh_position_t *out);
void democ_receiver_2_llh_position_to_json(democ_jw_t *w, const democ_receiver_2_llh_position_t *in);
int democ_receiver_2_llh_position_from_json(democ_jr_t *jr, size_t pos, democ_receiver_2_llh_position_t *out);
void democ_shared_timestamp_to_json(democ_jw_t *w, const democ_shared_timestamp_t *in);
int democ_shared_timestamp_from_json(democ_jr_t *jr, size_t pos, democ_shared_timestamp_t *out);

/* The "values" object of a decoded field. */
void democ_value_to_json(democ_jw_t *w, const democ_field_value_t *value);
/* The "values" object of a typed struct of layout id (in: a democ_<layout>_t, e.g. a member of a
 * set's packet struct that a straight-line decoder filled). */
void democ_layout_to_json(democ_jw_t *w, democ_field_id_t id, const void *in);
/* Reads the "values" object of layout id into *value (sets value->id). */
int democ_value_from_json(democ_jr_t *jr, size_t pos, democ_field_id_t id, democ_field_value_t *value);

#endif
