/* Read/write functions of the named structs and unions. Generated: do not edit. */
#include "types_internal.h"

#include <string.h>

/* ---- ActionGpioParams */

int mipc_action_gpio_params_read(mipc_reader_t *r, mipc_action_gpio_params_t *out) {
    mipc_rd_push(r, "pin");
    if (mipc_rd_u8(r, &out->pin)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "mode");
    if (mipc_rd_u8(r, &out->mode)) {
        return -1;
    }
    mipc_rd_pop(r);
    return 0;
}

mipc_status_t mipc_action_gpio_params_write(mipc_writer_t *w, const mipc_action_gpio_params_t *in) {
    mipc_status_t st;
    if ((st = mipc_wr_u8(w, &in->pin)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u8(w, &in->mode)) != MIPC_OK) {
        return st;
    }
    return MIPC_OK;
}

/* ---- MessageParams */

int mipc_message_params_read(mipc_reader_t *r, mipc_message_params_t *out) {
    size_t i;
    mipc_rd_push(r, "desc_set");
    if (mipc_rd_u8(r, &out->desc_set)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "decimation");
    if (mipc_rd_u16(r, &out->decimation)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "num_fields");
    if (mipc_rd_u8(r, &out->num_fields)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "descriptors");
    if (out->num_fields > 12) {
        return mipc_rd_count_error(r, (uint64_t)out->num_fields, 12);
    }
    for (i = 0; i < (size_t)out->num_fields; i++) {
        mipc_rd_index(r, i);
        if (mipc_rd_u8(r, &out->descriptors[i])) {
            return -1;
        }
    }
    mipc_rd_pop(r);
    return 0;
}

mipc_status_t mipc_message_params_write(mipc_writer_t *w, const mipc_message_params_t *in) {
    mipc_status_t st;
    size_t i;
    if ((st = mipc_wr_u8(w, &in->desc_set)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u16(w, &in->decimation)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u8(w, &in->num_fields)) != MIPC_OK) {
        return st;
    }
    if (in->num_fields > 12) {
        return MIPC_ERR_INVALID;
    }
    for (i = 0; i < (size_t)in->num_fields; i++) {
        if ((st = mipc_wr_u8(w, &in->descriptors[i])) != MIPC_OK) {
            return st;
        }
    }
    return MIPC_OK;
}

/* ---- ActionStatusEntry */

int mipc_action_status_entry_read(mipc_reader_t *r, mipc_action_status_entry_t *out) {
    mipc_rd_push(r, "action_type");
    if (mipc_rd_u8(r, &out->action_type)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "trigger_id");
    if (mipc_rd_u8(r, &out->trigger_id)) {
        return -1;
    }
    mipc_rd_pop(r);
    return 0;
}

mipc_status_t mipc_action_status_entry_write(mipc_writer_t *w, const mipc_action_status_entry_t *in) {
    mipc_status_t st;
    if ((st = mipc_wr_u8(w, &in->action_type)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u8(w, &in->trigger_id)) != MIPC_OK) {
        return st;
    }
    return MIPC_OK;
}

/* ---- AidingFrameEuler */

int mipc_aiding_frame_euler_read(mipc_reader_t *r, mipc_aiding_frame_euler_t *out) {
    size_t i;
    mipc_rd_push(r, "euler");
    for (i = 0; i < 3; i++) {
        mipc_rd_index(r, i);
        if (mipc_rd_f32(r, &out->euler[i])) {
            return -1;
        }
    }
    mipc_rd_pop(r);
    return 0;
}

mipc_status_t mipc_aiding_frame_euler_write(mipc_writer_t *w, const mipc_aiding_frame_euler_t *in) {
    mipc_status_t st;
    size_t i;
    for (i = 0; i < 3; i++) {
        if ((st = mipc_wr_f32(w, &in->euler[i])) != MIPC_OK) {
            return st;
        }
    }
    return MIPC_OK;
}

/* ---- AidingFrameQuaternion */

int mipc_aiding_frame_quaternion_read(mipc_reader_t *r, mipc_aiding_frame_quaternion_t *out) {
    size_t i;
    mipc_rd_push(r, "quaternion");
    for (i = 0; i < 4; i++) {
        mipc_rd_index(r, i);
        if (mipc_rd_f32(r, &out->quaternion[i])) {
            return -1;
        }
    }
    mipc_rd_pop(r);
    return 0;
}

mipc_status_t mipc_aiding_frame_quaternion_write(mipc_writer_t *w, const mipc_aiding_frame_quaternion_t *in) {
    mipc_status_t st;
    size_t i;
    for (i = 0; i < 4; i++) {
        if ((st = mipc_wr_f32(w, &in->quaternion[i])) != MIPC_OK) {
            return st;
        }
    }
    return MIPC_OK;
}

/* ---- AidingTime */

int mipc_aiding_time_read(mipc_reader_t *r, mipc_aiding_time_t *out) {
    mipc_rd_push(r, "timebase");
    if (mipc_rd_u8(r, &out->timebase)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "reserved");
    if (mipc_rd_u8(r, &out->reserved)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "nanoseconds");
    if (mipc_rd_u64(r, &out->nanoseconds)) {
        return -1;
    }
    mipc_rd_pop(r);
    return 0;
}

mipc_status_t mipc_aiding_time_write(mipc_writer_t *w, const mipc_aiding_time_t *in) {
    mipc_status_t st;
    if ((st = mipc_wr_u8(w, &in->timebase)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u8(w, &in->reserved)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u64(w, &in->nanoseconds)) != MIPC_OK) {
        return st;
    }
    return MIPC_OK;
}

/* ---- CombinationParams */

int mipc_combination_params_read(mipc_reader_t *r, mipc_combination_params_t *out) {
    size_t i;
    mipc_rd_push(r, "logic_table");
    if (mipc_rd_u16(r, &out->logic_table)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "input_triggers");
    for (i = 0; i < 4; i++) {
        mipc_rd_index(r, i);
        if (mipc_rd_u8(r, &out->input_triggers[i])) {
            return -1;
        }
    }
    mipc_rd_pop(r);
    return 0;
}

mipc_status_t mipc_combination_params_write(mipc_writer_t *w, const mipc_combination_params_t *in) {
    mipc_status_t st;
    size_t i;
    if ((st = mipc_wr_u16(w, &in->logic_table)) != MIPC_OK) {
        return st;
    }
    for (i = 0; i < 4; i++) {
        if ((st = mipc_wr_u8(w, &in->input_triggers[i])) != MIPC_OK) {
            return st;
        }
    }
    return MIPC_OK;
}

/* ---- ConstellationSettings */

int mipc_constellation_settings_read(mipc_reader_t *r, mipc_constellation_settings_t *out) {
    mipc_rd_push(r, "constellation_id");
    if (mipc_rd_u8(r, &out->constellation_id)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "enable");
    if (mipc_rd_u8(r, &out->enable)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "reserved_channels");
    if (mipc_rd_u8(r, &out->reserved_channels)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "max_channels");
    if (mipc_rd_u8(r, &out->max_channels)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "option_flags");
    if (mipc_rd_u16(r, &out->option_flags)) {
        return -1;
    }
    mipc_rd_pop(r);
    return 0;
}

mipc_status_t mipc_constellation_settings_write(mipc_writer_t *w, const mipc_constellation_settings_t *in) {
    mipc_status_t st;
    if ((st = mipc_wr_u8(w, &in->constellation_id)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u8(w, &in->enable)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u8(w, &in->reserved_channels)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u8(w, &in->max_channels)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u16(w, &in->option_flags)) != MIPC_OK) {
        return st;
    }
    return MIPC_OK;
}

/* ---- Cv7ContinuousBit */

int mipc_cv7_continuous_bit_read(mipc_reader_t *r, mipc_cv7_continuous_bit_t *out) {
    mipc_rd_push(r, "system_byte_0");
    if (mipc_rd_u8(r, &out->system_byte_0)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "reserved_byte_1");
    if (mipc_rd_u8(r, &out->reserved_byte_1)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "system_byte_2");
    if (mipc_rd_u8(r, &out->system_byte_2)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "system_byte_3");
    if (mipc_rd_u8(r, &out->system_byte_3)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "imu_byte_4");
    if (mipc_rd_u8(r, &out->imu_byte_4)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "imu_byte_5");
    if (mipc_rd_u8(r, &out->imu_byte_5)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "imu_byte_6");
    if (mipc_rd_u8(r, &out->imu_byte_6)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "imu_byte_7");
    if (mipc_rd_u8(r, &out->imu_byte_7)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "nav_byte_8");
    if (mipc_rd_u8(r, &out->nav_byte_8)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "reserved_byte_9");
    if (mipc_rd_u8(r, &out->reserved_byte_9)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "reserved_byte_10");
    if (mipc_rd_u8(r, &out->reserved_byte_10)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "reserved_byte_11");
    if (mipc_rd_u8(r, &out->reserved_byte_11)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "reserved_byte_12");
    if (mipc_rd_u8(r, &out->reserved_byte_12)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "gnss_byte_13");
    if (mipc_rd_u8(r, &out->gnss_byte_13)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "gnss_byte_14");
    if (mipc_rd_u8(r, &out->gnss_byte_14)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "reserved_byte_15");
    if (mipc_rd_u8(r, &out->reserved_byte_15)) {
        return -1;
    }
    mipc_rd_pop(r);
    return 0;
}

mipc_status_t mipc_cv7_continuous_bit_write(mipc_writer_t *w, const mipc_cv7_continuous_bit_t *in) {
    mipc_status_t st;
    if ((st = mipc_wr_u8(w, &in->system_byte_0)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u8(w, &in->reserved_byte_1)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u8(w, &in->system_byte_2)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u8(w, &in->system_byte_3)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u8(w, &in->imu_byte_4)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u8(w, &in->imu_byte_5)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u8(w, &in->imu_byte_6)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u8(w, &in->imu_byte_7)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u8(w, &in->nav_byte_8)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u8(w, &in->reserved_byte_9)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u8(w, &in->reserved_byte_10)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u8(w, &in->reserved_byte_11)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u8(w, &in->reserved_byte_12)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u8(w, &in->gnss_byte_13)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u8(w, &in->gnss_byte_14)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u8(w, &in->reserved_byte_15)) != MIPC_OK) {
        return st;
    }
    return MIPC_OK;
}

/* ---- DescriptorRate */

int mipc_descriptor_rate_read(mipc_reader_t *r, mipc_descriptor_rate_t *out) {
    mipc_rd_push(r, "descriptor");
    if (mipc_rd_u8(r, &out->descriptor)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "decimation");
    if (mipc_rd_u16(r, &out->decimation)) {
        return -1;
    }
    mipc_rd_pop(r);
    return 0;
}

mipc_status_t mipc_descriptor_rate_write(mipc_writer_t *w, const mipc_descriptor_rate_t *in) {
    mipc_status_t st;
    if ((st = mipc_wr_u8(w, &in->descriptor)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u16(w, &in->decimation)) != MIPC_OK) {
        return st;
    }
    return MIPC_OK;
}

/* ---- DeviceInfo */

int mipc_device_info_read(mipc_reader_t *r, mipc_device_info_t *out) {
    mipc_rd_push(r, "firmware_version");
    if (mipc_rd_u16(r, &out->firmware_version)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "model_name");
    if (mipc_rd_chars(r, out->model_name, 16)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "model_number");
    if (mipc_rd_chars(r, out->model_number, 16)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "serial_number");
    if (mipc_rd_chars(r, out->serial_number, 16)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "lot_number");
    if (mipc_rd_chars(r, out->lot_number, 16)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "device_options");
    if (mipc_rd_chars(r, out->device_options, 16)) {
        return -1;
    }
    mipc_rd_pop(r);
    return 0;
}

mipc_status_t mipc_device_info_write(mipc_writer_t *w, const mipc_device_info_t *in) {
    mipc_status_t st;
    if ((st = mipc_wr_u16(w, &in->firmware_version)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_chars(w, in->model_name, 16)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_chars(w, in->model_number, 16)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_chars(w, in->serial_number, 16)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_chars(w, in->lot_number, 16)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_chars(w, in->device_options, 16)) != MIPC_OK) {
        return st;
    }
    return MIPC_OK;
}

/* ---- GnssReceiverInfoEntry */

int mipc_gnss_receiver_info_entry_read(mipc_reader_t *r, mipc_gnss_receiver_info_entry_t *out) {
    mipc_rd_push(r, "receiver_id");
    if (mipc_rd_u8(r, &out->receiver_id)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "mip_data_descriptor_set");
    if (mipc_rd_u8(r, &out->mip_data_descriptor_set)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "description");
    if (mipc_rd_chars(r, out->description, 32)) {
        return -1;
    }
    mipc_rd_pop(r);
    return 0;
}

mipc_status_t mipc_gnss_receiver_info_entry_write(mipc_writer_t *w,
                                                  const mipc_gnss_receiver_info_entry_t *in) {
    mipc_status_t st;
    if ((st = mipc_wr_u8(w, &in->receiver_id)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u8(w, &in->mip_data_descriptor_set)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_chars(w, in->description, 32)) != MIPC_OK) {
        return st;
    }
    return MIPC_OK;
}

/* ---- GpioBehaviorUnused */

int mipc_gpio_behavior_unused_read(mipc_reader_t *r, mipc_gpio_behavior_unused_t *out) {
    mipc_rd_push(r, "behavior");
    if (mipc_rd_u8(r, &out->behavior)) {
        return -1;
    }
    mipc_rd_pop(r);
    return 0;
}

mipc_status_t mipc_gpio_behavior_unused_write(mipc_writer_t *w, const mipc_gpio_behavior_unused_t *in) {
    mipc_status_t st;
    if ((st = mipc_wr_u8(w, &in->behavior)) != MIPC_OK) {
        return st;
    }
    return MIPC_OK;
}

/* ---- GpioBehaviorIo */

int mipc_gpio_behavior_io_read(mipc_reader_t *r, mipc_gpio_behavior_io_t *out) {
    mipc_rd_push(r, "behavior");
    if (mipc_rd_u8(r, &out->behavior)) {
        return -1;
    }
    mipc_rd_pop(r);
    return 0;
}

mipc_status_t mipc_gpio_behavior_io_write(mipc_writer_t *w, const mipc_gpio_behavior_io_t *in) {
    mipc_status_t st;
    if ((st = mipc_wr_u8(w, &in->behavior)) != MIPC_OK) {
        return st;
    }
    return MIPC_OK;
}

/* ---- GpioBehaviorPps */

int mipc_gpio_behavior_pps_read(mipc_reader_t *r, mipc_gpio_behavior_pps_t *out) {
    mipc_rd_push(r, "behavior");
    if (mipc_rd_u8(r, &out->behavior)) {
        return -1;
    }
    mipc_rd_pop(r);
    return 0;
}

mipc_status_t mipc_gpio_behavior_pps_write(mipc_writer_t *w, const mipc_gpio_behavior_pps_t *in) {
    mipc_status_t st;
    if ((st = mipc_wr_u8(w, &in->behavior)) != MIPC_OK) {
        return st;
    }
    return MIPC_OK;
}

/* ---- GpioBehaviorEncoder */

int mipc_gpio_behavior_encoder_read(mipc_reader_t *r, mipc_gpio_behavior_encoder_t *out) {
    mipc_rd_push(r, "behavior");
    if (mipc_rd_u8(r, &out->behavior)) {
        return -1;
    }
    mipc_rd_pop(r);
    return 0;
}

mipc_status_t mipc_gpio_behavior_encoder_write(mipc_writer_t *w, const mipc_gpio_behavior_encoder_t *in) {
    mipc_status_t st;
    if ((st = mipc_wr_u8(w, &in->behavior)) != MIPC_OK) {
        return st;
    }
    return MIPC_OK;
}

/* ---- GpioBehaviorTimestamp */

int mipc_gpio_behavior_timestamp_read(mipc_reader_t *r, mipc_gpio_behavior_timestamp_t *out) {
    mipc_rd_push(r, "behavior");
    if (mipc_rd_u8(r, &out->behavior)) {
        return -1;
    }
    mipc_rd_pop(r);
    return 0;
}

mipc_status_t mipc_gpio_behavior_timestamp_write(mipc_writer_t *w, const mipc_gpio_behavior_timestamp_t *in) {
    mipc_status_t st;
    if ((st = mipc_wr_u8(w, &in->behavior)) != MIPC_OK) {
        return st;
    }
    return MIPC_OK;
}

/* ---- GpioBehaviorUart */

int mipc_gpio_behavior_uart_read(mipc_reader_t *r, mipc_gpio_behavior_uart_t *out) {
    mipc_rd_push(r, "behavior");
    if (mipc_rd_u8(r, &out->behavior)) {
        return -1;
    }
    mipc_rd_pop(r);
    return 0;
}

mipc_status_t mipc_gpio_behavior_uart_write(mipc_writer_t *w, const mipc_gpio_behavior_uart_t *in) {
    mipc_status_t st;
    if ((st = mipc_wr_u8(w, &in->behavior)) != MIPC_OK) {
        return st;
    }
    return MIPC_OK;
}

/* ---- Gx5BasicStatus */

int mipc_gx5_basic_status_read(mipc_reader_t *r, mipc_gx5_basic_status_t *out) {
    mipc_rd_push(r, "status_flags");
    if (mipc_rd_u32(r, &out->status_flags)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "system_state");
    if (mipc_rd_u16(r, &out->system_state)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "system_timer");
    if (mipc_rd_u32(r, &out->system_timer)) {
        return -1;
    }
    mipc_rd_pop(r);
    return 0;
}

mipc_status_t mipc_gx5_basic_status_write(mipc_writer_t *w, const mipc_gx5_basic_status_t *in) {
    mipc_status_t st;
    if ((st = mipc_wr_u32(w, &in->status_flags)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u16(w, &in->system_state)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u32(w, &in->system_timer)) != MIPC_OK) {
        return st;
    }
    return MIPC_OK;
}

/* ---- Gx5DiagnosticStatus */

int mipc_gx5_diagnostic_status_read(mipc_reader_t *r, mipc_gx5_diagnostic_status_t *out) {
    mipc_rd_push(r, "status_flags");
    if (mipc_rd_u32(r, &out->status_flags)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "system_state");
    if (mipc_rd_u16(r, &out->system_state)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "system_timer");
    if (mipc_rd_u32(r, &out->system_timer)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "gnss_power_state");
    if (mipc_rd_u8(r, &out->gnss_power_state)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "pps_pulse_count");
    if (mipc_rd_u32(r, &out->pps_pulse_count)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "last_pps_time");
    if (mipc_rd_u32(r, &out->last_pps_time)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "imu_stream_enabled");
    if (mipc_rd_u8(r, &out->imu_stream_enabled)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "gnss_stream_enabled");
    if (mipc_rd_u8(r, &out->gnss_stream_enabled)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "filter_stream_enabled");
    if (mipc_rd_u8(r, &out->filter_stream_enabled)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "imu_dropped_packets");
    if (mipc_rd_u32(r, &out->imu_dropped_packets)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "gnss_dropped_packets");
    if (mipc_rd_u32(r, &out->gnss_dropped_packets)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "filter_dropped_packets");
    if (mipc_rd_u32(r, &out->filter_dropped_packets)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "com_bytes_written");
    if (mipc_rd_u32(r, &out->com_bytes_written)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "com_bytes_read");
    if (mipc_rd_u32(r, &out->com_bytes_read)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "com_write_overruns");
    if (mipc_rd_u32(r, &out->com_write_overruns)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "imu_parse_errors");
    if (mipc_rd_u32(r, &out->imu_parse_errors)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "imu_messages_read");
    if (mipc_rd_u32(r, &out->imu_messages_read)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "last_imu_message_time");
    if (mipc_rd_u32(r, &out->last_imu_message_time)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "gnss_parse_errors");
    if (mipc_rd_u32(r, &out->gnss_parse_errors)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "gnss_messages_read");
    if (mipc_rd_u32(r, &out->gnss_messages_read)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "last_gnss_message_time");
    if (mipc_rd_u32(r, &out->last_gnss_message_time)) {
        return -1;
    }
    mipc_rd_pop(r);
    return 0;
}

mipc_status_t mipc_gx5_diagnostic_status_write(mipc_writer_t *w, const mipc_gx5_diagnostic_status_t *in) {
    mipc_status_t st;
    if ((st = mipc_wr_u32(w, &in->status_flags)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u16(w, &in->system_state)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u32(w, &in->system_timer)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u8(w, &in->gnss_power_state)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u32(w, &in->pps_pulse_count)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u32(w, &in->last_pps_time)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u8(w, &in->imu_stream_enabled)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u8(w, &in->gnss_stream_enabled)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u8(w, &in->filter_stream_enabled)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u32(w, &in->imu_dropped_packets)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u32(w, &in->gnss_dropped_packets)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u32(w, &in->filter_dropped_packets)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u32(w, &in->com_bytes_written)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u32(w, &in->com_bytes_read)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u32(w, &in->com_write_overruns)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u32(w, &in->imu_parse_errors)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u32(w, &in->imu_messages_read)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u32(w, &in->last_imu_message_time)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u32(w, &in->gnss_parse_errors)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u32(w, &in->gnss_messages_read)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u32(w, &in->last_gnss_message_time)) != MIPC_OK) {
        return st;
    }
    return MIPC_OK;
}

/* ---- Gx5PollDescriptor */

int mipc_gx5_poll_descriptor_read(mipc_reader_t *r, mipc_gx5_poll_descriptor_t *out) {
    mipc_rd_push(r, "descriptor");
    if (mipc_rd_u8(r, &out->descriptor)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "reserved");
    if (mipc_rd_u16(r, &out->reserved)) {
        return -1;
    }
    mipc_rd_pop(r);
    return 0;
}

mipc_status_t mipc_gx5_poll_descriptor_write(mipc_writer_t *w, const mipc_gx5_poll_descriptor_t *in) {
    mipc_status_t st;
    if ((st = mipc_wr_u8(w, &in->descriptor)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u16(w, &in->reserved)) != MIPC_OK) {
        return st;
    }
    return MIPC_OK;
}

/* ---- NmeaMessage */

int mipc_nmea_message_read(mipc_reader_t *r, mipc_nmea_message_t *out) {
    mipc_rd_push(r, "message_id");
    if (mipc_rd_u8(r, &out->message_id)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "talker_id");
    if (mipc_rd_u8(r, &out->talker_id)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "source_desc_set");
    if (mipc_rd_u8(r, &out->source_desc_set)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "decimation");
    if (mipc_rd_u16(r, &out->decimation)) {
        return -1;
    }
    mipc_rd_pop(r);
    return 0;
}

mipc_status_t mipc_nmea_message_write(mipc_writer_t *w, const mipc_nmea_message_t *in) {
    mipc_status_t st;
    if ((st = mipc_wr_u8(w, &in->message_id)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u8(w, &in->talker_id)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u8(w, &in->source_desc_set)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u16(w, &in->decimation)) != MIPC_OK) {
        return st;
    }
    return MIPC_OK;
}

/* ---- SensorRangeEntry */

int mipc_sensor_range_entry_read(mipc_reader_t *r, mipc_sensor_range_entry_t *out) {
    mipc_rd_push(r, "setting");
    if (mipc_rd_u8(r, &out->setting)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "range");
    if (mipc_rd_f32(r, &out->range)) {
        return -1;
    }
    mipc_rd_pop(r);
    return 0;
}

mipc_status_t mipc_sensor_range_entry_write(mipc_writer_t *w, const mipc_sensor_range_entry_t *in) {
    mipc_status_t st;
    if ((st = mipc_wr_u8(w, &in->setting)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_f32(w, &in->range)) != MIPC_OK) {
        return st;
    }
    return MIPC_OK;
}

/* ---- SupportedActionType */

int mipc_supported_action_type_read(mipc_reader_t *r, mipc_supported_action_type_t *out) {
    mipc_rd_push(r, "type");
    if (mipc_rd_u8(r, &out->type)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "count");
    if (mipc_rd_u8(r, &out->count)) {
        return -1;
    }
    mipc_rd_pop(r);
    return 0;
}

mipc_status_t mipc_supported_action_type_write(mipc_writer_t *w, const mipc_supported_action_type_t *in) {
    mipc_status_t st;
    if ((st = mipc_wr_u8(w, &in->type)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u8(w, &in->count)) != MIPC_OK) {
        return st;
    }
    return MIPC_OK;
}

/* ---- SupportedActions */

int mipc_supported_actions_read(mipc_reader_t *r, mipc_supported_actions_t *out) {
    size_t i;
    mipc_rd_push(r, "max_instances");
    if (mipc_rd_u8(r, &out->max_instances)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "num_entries");
    if (mipc_rd_u8(r, &out->num_entries)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "entries");
    if (out->num_entries > 125) {
        return mipc_rd_count_error(r, (uint64_t)out->num_entries, 125);
    }
    for (i = 0; i < (size_t)out->num_entries; i++) {
        mipc_rd_index(r, i);
        if (mipc_supported_action_type_read(r, &out->entries[i])) {
            return -1;
        }
    }
    mipc_rd_pop(r);
    return 0;
}

mipc_status_t mipc_supported_actions_write(mipc_writer_t *w, const mipc_supported_actions_t *in) {
    mipc_status_t st;
    size_t i;
    if ((st = mipc_wr_u8(w, &in->max_instances)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u8(w, &in->num_entries)) != MIPC_OK) {
        return st;
    }
    if (in->num_entries > 125) {
        return MIPC_ERR_INVALID;
    }
    for (i = 0; i < (size_t)in->num_entries; i++) {
        if ((st = mipc_supported_action_type_write(w, &in->entries[i])) != MIPC_OK) {
            return st;
        }
    }
    return MIPC_OK;
}

/* ---- SupportedTriggerType */

int mipc_supported_trigger_type_read(mipc_reader_t *r, mipc_supported_trigger_type_t *out) {
    mipc_rd_push(r, "type");
    if (mipc_rd_u8(r, &out->type)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "count");
    if (mipc_rd_u8(r, &out->count)) {
        return -1;
    }
    mipc_rd_pop(r);
    return 0;
}

mipc_status_t mipc_supported_trigger_type_write(mipc_writer_t *w, const mipc_supported_trigger_type_t *in) {
    mipc_status_t st;
    if ((st = mipc_wr_u8(w, &in->type)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u8(w, &in->count)) != MIPC_OK) {
        return st;
    }
    return MIPC_OK;
}

/* ---- SupportedTriggers */

int mipc_supported_triggers_read(mipc_reader_t *r, mipc_supported_triggers_t *out) {
    size_t i;
    mipc_rd_push(r, "max_instances");
    if (mipc_rd_u8(r, &out->max_instances)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "num_entries");
    if (mipc_rd_u8(r, &out->num_entries)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "entries");
    if (out->num_entries > 125) {
        return mipc_rd_count_error(r, (uint64_t)out->num_entries, 125);
    }
    for (i = 0; i < (size_t)out->num_entries; i++) {
        mipc_rd_index(r, i);
        if (mipc_supported_trigger_type_read(r, &out->entries[i])) {
            return -1;
        }
    }
    mipc_rd_pop(r);
    return 0;
}

mipc_status_t mipc_supported_triggers_write(mipc_writer_t *w, const mipc_supported_triggers_t *in) {
    mipc_status_t st;
    size_t i;
    if ((st = mipc_wr_u8(w, &in->max_instances)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u8(w, &in->num_entries)) != MIPC_OK) {
        return st;
    }
    if (in->num_entries > 125) {
        return MIPC_ERR_INVALID;
    }
    for (i = 0; i < (size_t)in->num_entries; i++) {
        if ((st = mipc_supported_trigger_type_write(w, &in->entries[i])) != MIPC_OK) {
            return st;
        }
    }
    return MIPC_OK;
}

/* ---- ThresholdParams */

int mipc_threshold_params_read(mipc_reader_t *r, mipc_threshold_params_t *out) {
    mipc_rd_push(r, "desc_set");
    if (mipc_rd_u8(r, &out->desc_set)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "field_desc");
    if (mipc_rd_u8(r, &out->field_desc)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "param_id");
    if (mipc_rd_u8(r, &out->param_id)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "type");
    if (mipc_rd_u8(r, &out->type)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "low_thres");
    if (mipc_rd_f64(r, &out->low_thres)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "high_thres");
    if (mipc_rd_f64(r, &out->high_thres)) {
        return -1;
    }
    mipc_rd_pop(r);
    return 0;
}

mipc_status_t mipc_threshold_params_write(mipc_writer_t *w, const mipc_threshold_params_t *in) {
    mipc_status_t st;
    if ((st = mipc_wr_u8(w, &in->desc_set)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u8(w, &in->field_desc)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u8(w, &in->param_id)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u8(w, &in->type)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_f64(w, &in->low_thres)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_f64(w, &in->high_thres)) != MIPC_OK) {
        return st;
    }
    return MIPC_OK;
}

/* ---- TriggerGpioParams */

int mipc_trigger_gpio_params_read(mipc_reader_t *r, mipc_trigger_gpio_params_t *out) {
    mipc_rd_push(r, "pin");
    if (mipc_rd_u8(r, &out->pin)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "mode");
    if (mipc_rd_u8(r, &out->mode)) {
        return -1;
    }
    mipc_rd_pop(r);
    return 0;
}

mipc_status_t mipc_trigger_gpio_params_write(mipc_writer_t *w, const mipc_trigger_gpio_params_t *in) {
    mipc_status_t st;
    if ((st = mipc_wr_u8(w, &in->pin)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u8(w, &in->mode)) != MIPC_OK) {
        return st;
    }
    return MIPC_OK;
}

/* ---- TriggerStatusEntry */

int mipc_trigger_status_entry_read(mipc_reader_t *r, mipc_trigger_status_entry_t *out) {
    mipc_rd_push(r, "type");
    if (mipc_rd_u8(r, &out->type)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "status");
    if (mipc_rd_u8(r, &out->status)) {
        return -1;
    }
    mipc_rd_pop(r);
    return 0;
}

mipc_status_t mipc_trigger_status_entry_write(mipc_writer_t *w, const mipc_trigger_status_entry_t *in) {
    mipc_status_t st;
    if ((st = mipc_wr_u8(w, &in->type)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u8(w, &in->status)) != MIPC_OK) {
        return st;
    }
    return MIPC_OK;
}

/* ---- ActionParams (selected by mipc_action_type_t) */

int mipc_action_params_read(mipc_reader_t *r, mipc_action_type_t selector, mipc_action_params_t *out) {
    switch (selector) {
    case MIPC_ACTION_TYPE_NONE:
        return 0;
    case MIPC_ACTION_TYPE_GPIO:
        return mipc_action_gpio_params_read(r, &out->gpio);
    case MIPC_ACTION_TYPE_MESSAGE:
        return mipc_message_params_read(r, &out->message);
    default:
        return mipc_rd_selector_error_u(r, (uint64_t)selector);
    }
}

mipc_status_t mipc_action_params_write(mipc_writer_t *w, mipc_action_type_t selector,
                                       const mipc_action_params_t *in) {
    switch (selector) {
    case MIPC_ACTION_TYPE_NONE:
        return MIPC_OK;
    case MIPC_ACTION_TYPE_GPIO:
        return mipc_action_gpio_params_write(w, &in->gpio);
    case MIPC_ACTION_TYPE_MESSAGE:
        return mipc_message_params_write(w, &in->message);
    default:
        (void)w;
        (void)in;
        return MIPC_ERR_INVALID;
    }
}

/* ---- AidingFrameRotation (selected by mipc_aiding_frame_format_t) */

int mipc_aiding_frame_rotation_read(mipc_reader_t *r, mipc_aiding_frame_format_t selector,
                                    mipc_aiding_frame_rotation_t *out) {
    switch (selector) {
    case MIPC_AIDING_FRAME_FORMAT_EULER:
        return mipc_aiding_frame_euler_read(r, &out->euler);
    case MIPC_AIDING_FRAME_FORMAT_QUATERNION:
        return mipc_aiding_frame_quaternion_read(r, &out->quaternion);
    default:
        return mipc_rd_selector_error_u(r, (uint64_t)selector);
    }
}

mipc_status_t mipc_aiding_frame_rotation_write(mipc_writer_t *w, mipc_aiding_frame_format_t selector,
                                               const mipc_aiding_frame_rotation_t *in) {
    switch (selector) {
    case MIPC_AIDING_FRAME_FORMAT_EULER:
        return mipc_aiding_frame_euler_write(w, &in->euler);
    case MIPC_AIDING_FRAME_FORMAT_QUATERNION:
        return mipc_aiding_frame_quaternion_write(w, &in->quaternion);
    default:
        (void)w;
        (void)in;
        return MIPC_ERR_INVALID;
    }
}

/* ---- GpioBehavior (selected by mipc_gpio_feature_t) */

int mipc_gpio_behavior_read(mipc_reader_t *r, mipc_gpio_feature_t selector, mipc_gpio_behavior_t *out) {
    switch (selector) {
    case MIPC_GPIO_FEATURE_UNUSED:
        return mipc_gpio_behavior_unused_read(r, &out->unused);
    case MIPC_GPIO_FEATURE_GPIO:
        return mipc_gpio_behavior_io_read(r, &out->gpio);
    case MIPC_GPIO_FEATURE_PPS:
        return mipc_gpio_behavior_pps_read(r, &out->pps);
    case MIPC_GPIO_FEATURE_ENCODER:
        return mipc_gpio_behavior_encoder_read(r, &out->encoder);
    case MIPC_GPIO_FEATURE_TIMESTAMP:
        return mipc_gpio_behavior_timestamp_read(r, &out->timestamp);
    case MIPC_GPIO_FEATURE_UART:
        return mipc_gpio_behavior_uart_read(r, &out->uart);
    default:
        return mipc_rd_selector_error_u(r, (uint64_t)selector);
    }
}

mipc_status_t mipc_gpio_behavior_write(mipc_writer_t *w, mipc_gpio_feature_t selector,
                                       const mipc_gpio_behavior_t *in) {
    switch (selector) {
    case MIPC_GPIO_FEATURE_UNUSED:
        return mipc_gpio_behavior_unused_write(w, &in->unused);
    case MIPC_GPIO_FEATURE_GPIO:
        return mipc_gpio_behavior_io_write(w, &in->gpio);
    case MIPC_GPIO_FEATURE_PPS:
        return mipc_gpio_behavior_pps_write(w, &in->pps);
    case MIPC_GPIO_FEATURE_ENCODER:
        return mipc_gpio_behavior_encoder_write(w, &in->encoder);
    case MIPC_GPIO_FEATURE_TIMESTAMP:
        return mipc_gpio_behavior_timestamp_write(w, &in->timestamp);
    case MIPC_GPIO_FEATURE_UART:
        return mipc_gpio_behavior_uart_write(w, &in->uart);
    default:
        (void)w;
        (void)in;
        return MIPC_ERR_INVALID;
    }
}

/* ---- Gx5DeviceStatus (selected by mipc_device_status_selector_t) */

int mipc_gx5_device_status_read(mipc_reader_t *r, mipc_device_status_selector_t selector,
                                mipc_gx5_device_status_t *out) {
    switch (selector) {
    case MIPC_DEVICE_STATUS_SELECTOR_BASIC:
        return mipc_gx5_basic_status_read(r, &out->basic);
    case MIPC_DEVICE_STATUS_SELECTOR_DIAGNOSTIC:
        return mipc_gx5_diagnostic_status_read(r, &out->diagnostic);
    default:
        return mipc_rd_selector_error_u(r, (uint64_t)selector);
    }
}

mipc_status_t mipc_gx5_device_status_write(mipc_writer_t *w, mipc_device_status_selector_t selector,
                                           const mipc_gx5_device_status_t *in) {
    switch (selector) {
    case MIPC_DEVICE_STATUS_SELECTOR_BASIC:
        return mipc_gx5_basic_status_write(w, &in->basic);
    case MIPC_DEVICE_STATUS_SELECTOR_DIAGNOSTIC:
        return mipc_gx5_diagnostic_status_write(w, &in->diagnostic);
    default:
        (void)w;
        (void)in;
        return MIPC_ERR_INVALID;
    }
}

/* ---- SupportedEventsInfo (selected by mipc_supported_events_query_t) */

int mipc_supported_events_info_read(mipc_reader_t *r, mipc_supported_events_query_t selector,
                                    mipc_supported_events_info_t *out) {
    switch (selector) {
    case MIPC_SUPPORTED_EVENTS_QUERY_TRIGGER_TYPES:
        return mipc_supported_triggers_read(r, &out->trigger_types);
    case MIPC_SUPPORTED_EVENTS_QUERY_ACTION_TYPES:
        return mipc_supported_actions_read(r, &out->action_types);
    default:
        return mipc_rd_selector_error_u(r, (uint64_t)selector);
    }
}

mipc_status_t mipc_supported_events_info_write(mipc_writer_t *w, mipc_supported_events_query_t selector,
                                               const mipc_supported_events_info_t *in) {
    switch (selector) {
    case MIPC_SUPPORTED_EVENTS_QUERY_TRIGGER_TYPES:
        return mipc_supported_triggers_write(w, &in->trigger_types);
    case MIPC_SUPPORTED_EVENTS_QUERY_ACTION_TYPES:
        return mipc_supported_actions_write(w, &in->action_types);
    default:
        (void)w;
        (void)in;
        return MIPC_ERR_INVALID;
    }
}

/* ---- TriggerParams (selected by mipc_trigger_type_t) */

int mipc_trigger_params_read(mipc_reader_t *r, mipc_trigger_type_t selector, mipc_trigger_params_t *out) {
    switch (selector) {
    case MIPC_TRIGGER_TYPE_NONE:
        return 0;
    case MIPC_TRIGGER_TYPE_GPIO:
        return mipc_trigger_gpio_params_read(r, &out->gpio);
    case MIPC_TRIGGER_TYPE_THRESHOLD:
        return mipc_threshold_params_read(r, &out->threshold);
    case MIPC_TRIGGER_TYPE_COMBINATION:
        return mipc_combination_params_read(r, &out->combination);
    default:
        return mipc_rd_selector_error_u(r, (uint64_t)selector);
    }
}

mipc_status_t mipc_trigger_params_write(mipc_writer_t *w, mipc_trigger_type_t selector,
                                        const mipc_trigger_params_t *in) {
    switch (selector) {
    case MIPC_TRIGGER_TYPE_NONE:
        return MIPC_OK;
    case MIPC_TRIGGER_TYPE_GPIO:
        return mipc_trigger_gpio_params_write(w, &in->gpio);
    case MIPC_TRIGGER_TYPE_THRESHOLD:
        return mipc_threshold_params_write(w, &in->threshold);
    case MIPC_TRIGGER_TYPE_COMBINATION:
        return mipc_combination_params_write(w, &in->combination);
    default:
        (void)w;
        (void)in;
        return MIPC_ERR_INVALID;
    }
}
