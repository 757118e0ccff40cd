/* Private: read/write/JSON functions of the named structs and unions. Generated: do not edit. */
#ifndef MIP_TYPES_INTERNAL_H
#define MIP_TYPES_INTERNAL_H

#include "mipcodec/types.h"
#include "json_reader.h"
#include "json_writer.h"
#include "wire.h"

int mip_action_gpio_params_read(mip_reader_t *r, mip_action_gpio_params_t *out);
mip_status_t mip_action_gpio_params_write(mip_writer_t *w, const mip_action_gpio_params_t *in);
void mip_action_gpio_params_to_json(mip_jw_t *w, const mip_action_gpio_params_t *in);
int mip_action_gpio_params_from_json(mip_jr_t *jr, size_t pos, mip_action_gpio_params_t *out);
int mip_message_params_read(mip_reader_t *r, mip_message_params_t *out);
mip_status_t mip_message_params_write(mip_writer_t *w, const mip_message_params_t *in);
void mip_message_params_to_json(mip_jw_t *w, const mip_message_params_t *in);
int mip_message_params_from_json(mip_jr_t *jr, size_t pos, mip_message_params_t *out);
int mip_action_status_entry_read(mip_reader_t *r, mip_action_status_entry_t *out);
mip_status_t mip_action_status_entry_write(mip_writer_t *w, const mip_action_status_entry_t *in);
void mip_action_status_entry_to_json(mip_jw_t *w, const mip_action_status_entry_t *in);
int mip_action_status_entry_from_json(mip_jr_t *jr, size_t pos, mip_action_status_entry_t *out);
int mip_aiding_frame_euler_read(mip_reader_t *r, mip_aiding_frame_euler_t *out);
mip_status_t mip_aiding_frame_euler_write(mip_writer_t *w, const mip_aiding_frame_euler_t *in);
void mip_aiding_frame_euler_to_json(mip_jw_t *w, const mip_aiding_frame_euler_t *in);
int mip_aiding_frame_euler_from_json(mip_jr_t *jr, size_t pos, mip_aiding_frame_euler_t *out);
int mip_aiding_frame_quaternion_read(mip_reader_t *r, mip_aiding_frame_quaternion_t *out);
mip_status_t mip_aiding_frame_quaternion_write(mip_writer_t *w, const mip_aiding_frame_quaternion_t *in);
void mip_aiding_frame_quaternion_to_json(mip_jw_t *w, const mip_aiding_frame_quaternion_t *in);
int mip_aiding_frame_quaternion_from_json(mip_jr_t *jr, size_t pos, mip_aiding_frame_quaternion_t *out);
int mip_aiding_time_read(mip_reader_t *r, mip_aiding_time_t *out);
mip_status_t mip_aiding_time_write(mip_writer_t *w, const mip_aiding_time_t *in);
void mip_aiding_time_to_json(mip_jw_t *w, const mip_aiding_time_t *in);
int mip_aiding_time_from_json(mip_jr_t *jr, size_t pos, mip_aiding_time_t *out);
int mip_combination_params_read(mip_reader_t *r, mip_combination_params_t *out);
mip_status_t mip_combination_params_write(mip_writer_t *w, const mip_combination_params_t *in);
void mip_combination_params_to_json(mip_jw_t *w, const mip_combination_params_t *in);
int mip_combination_params_from_json(mip_jr_t *jr, size_t pos, mip_combination_params_t *out);
int mip_device_info_read(mip_reader_t *r, mip_device_info_t *out);
mip_status_t mip_device_info_write(mip_writer_t *w, const mip_device_info_t *in);
void mip_device_info_to_json(mip_jw_t *w, const mip_device_info_t *in);
int mip_device_info_from_json(mip_jr_t *jr, size_t pos, mip_device_info_t *out);
int mip_gnss_receiver_info_entry_read(mip_reader_t *r, mip_gnss_receiver_info_entry_t *out);
mip_status_t mip_gnss_receiver_info_entry_write(mip_writer_t *w, const mip_gnss_receiver_info_entry_t *in);
void mip_gnss_receiver_info_entry_to_json(mip_jw_t *w, const mip_gnss_receiver_info_entry_t *in);
int mip_gnss_receiver_info_entry_from_json(mip_jr_t *jr, size_t pos, mip_gnss_receiver_info_entry_t *out);
int mip_threshold_params_read(mip_reader_t *r, mip_threshold_params_t *out);
mip_status_t mip_threshold_params_write(mip_writer_t *w, const mip_threshold_params_t *in);
void mip_threshold_params_to_json(mip_jw_t *w, const mip_threshold_params_t *in);
int mip_threshold_params_from_json(mip_jr_t *jr, size_t pos, mip_threshold_params_t *out);
int mip_trigger_gpio_params_read(mip_reader_t *r, mip_trigger_gpio_params_t *out);
mip_status_t mip_trigger_gpio_params_write(mip_writer_t *w, const mip_trigger_gpio_params_t *in);
void mip_trigger_gpio_params_to_json(mip_jw_t *w, const mip_trigger_gpio_params_t *in);
int mip_trigger_gpio_params_from_json(mip_jr_t *jr, size_t pos, mip_trigger_gpio_params_t *out);
int mip_trigger_status_entry_read(mip_reader_t *r, mip_trigger_status_entry_t *out);
mip_status_t mip_trigger_status_entry_write(mip_writer_t *w, const mip_trigger_status_entry_t *in);
void mip_trigger_status_entry_to_json(mip_jw_t *w, const mip_trigger_status_entry_t *in);
int mip_trigger_status_entry_from_json(mip_jr_t *jr, size_t pos, mip_trigger_status_entry_t *out);
int mip_action_params_read(mip_reader_t *r, mip_action_type_t selector, mip_action_params_t *out);
mip_status_t mip_action_params_write(mip_writer_t *w, mip_action_type_t selector,
                                     const mip_action_params_t *in);
void mip_action_params_to_json(mip_jw_t *w, mip_action_type_t selector, const mip_action_params_t *in);
int mip_action_params_from_json(mip_jr_t *jr, size_t pos, mip_action_type_t selector,
                                mip_action_params_t *out);
int mip_aiding_frame_rotation_read(mip_reader_t *r, mip_aiding_frame_format_t selector,
                                   mip_aiding_frame_rotation_t *out);
mip_status_t mip_aiding_frame_rotation_write(mip_writer_t *w, mip_aiding_frame_format_t selector,
                                             const mip_aiding_frame_rotation_t *in);
void mip_aiding_frame_rotation_to_json(mip_jw_t *w, mip_aiding_frame_format_t selector,
                                       const mip_aiding_frame_rotation_t *in);
int mip_aiding_frame_rotation_from_json(mip_jr_t *jr, size_t pos, mip_aiding_frame_format_t selector,
                                        mip_aiding_frame_rotation_t *out);
int mip_trigger_params_read(mip_reader_t *r, mip_trigger_type_t selector, mip_trigger_params_t *out);
mip_status_t mip_trigger_params_write(mip_writer_t *w, mip_trigger_type_t selector,
                                      const mip_trigger_params_t *in);
void mip_trigger_params_to_json(mip_jw_t *w, mip_trigger_type_t selector, const mip_trigger_params_t *in);
int mip_trigger_params_from_json(mip_jr_t *jr, size_t pos, mip_trigger_type_t selector,
                                 mip_trigger_params_t *out);

#endif
