/* The typed command API of Memsense MS-CIP (mscipcodec/commands.h). Generated: do not edit. */
#include "mscipcodec/commands.h"

#include <string.h>

mscipc_result_kind_t mscipc_base_ping(mscipc_link_t *link) {
    mscipc_field_value_t cmd_;
    mscipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MSCIPC_FIELD_BASE_PING;
    }
    kind_ = mscipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mscipc_result_kind_t mscipc_base_get_device_messages(mscipc_link_t *link,
                                                     mscipc_base_device_messages_t *reply) {
    mscipc_field_value_t cmd_;
    mscipc_result_kind_t kind_;
    mscipc_result_t result_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MSCIPC_FIELD_BASE_GET_DEVICE_MESSAGES;
    }
    kind_ = mscipc_link_run(link, &cmd_, NULL, &result_);
    if (kind_ == MSCIPC_RESULT_ACK && reply != NULL) {
        mscipc_field_entry_t entry_;
        if (!mscipc_result_reply_entry(&result_, &entry_) || entry_.descriptor != 0x83 ||
            mscipc_base_device_messages_decode(entry_.data, entry_.length, reply, NULL) != MSCIPC_OK) {
            return mscipc_link_fail(link, MSCIPC_RESULT_INVALID, "missing reply field 0x83");
        }
    }
    return kind_;
}

mscipc_result_kind_t mscipc_base_device_reset(mscipc_link_t *link) {
    mscipc_field_value_t cmd_;
    mscipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MSCIPC_FIELD_BASE_DEVICE_RESET;
    }
    kind_ = mscipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mscipc_result_kind_t mscipc_base_get_device_model(mscipc_link_t *link, mscipc_base_device_model_t *reply) {
    mscipc_field_value_t cmd_;
    mscipc_result_kind_t kind_;
    mscipc_result_t result_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MSCIPC_FIELD_BASE_GET_DEVICE_MODEL;
    }
    kind_ = mscipc_link_run(link, &cmd_, NULL, &result_);
    if (kind_ == MSCIPC_RESULT_ACK && reply != NULL) {
        mscipc_field_entry_t entry_;
        if (!mscipc_result_reply_entry(&result_, &entry_) || entry_.descriptor != 0x85 ||
            mscipc_base_device_model_decode(entry_.data, entry_.length, reply, NULL) != MSCIPC_OK) {
            return mscipc_link_fail(link, MSCIPC_RESULT_INVALID, "missing reply field 0x85");
        }
    }
    return kind_;
}

mscipc_result_kind_t mscipc_base_get_device_sn(mscipc_link_t *link, mscipc_base_device_sn_t *reply) {
    mscipc_field_value_t cmd_;
    mscipc_result_kind_t kind_;
    mscipc_result_t result_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MSCIPC_FIELD_BASE_GET_DEVICE_SN;
    }
    kind_ = mscipc_link_run(link, &cmd_, NULL, &result_);
    if (kind_ == MSCIPC_RESULT_ACK && reply != NULL) {
        mscipc_field_entry_t entry_;
        if (!mscipc_result_reply_entry(&result_, &entry_) || entry_.descriptor != 0x86 ||
            mscipc_base_device_sn_decode(entry_.data, entry_.length, reply, NULL) != MSCIPC_OK) {
            return mscipc_link_fail(link, MSCIPC_RESULT_INVALID, "missing reply field 0x86");
        }
    }
    return kind_;
}

mscipc_result_kind_t mscipc_base_get_device_fw(mscipc_link_t *link, mscipc_base_device_fw_t *reply) {
    mscipc_field_value_t cmd_;
    mscipc_result_kind_t kind_;
    mscipc_result_t result_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MSCIPC_FIELD_BASE_GET_DEVICE_FW;
    }
    kind_ = mscipc_link_run(link, &cmd_, NULL, &result_);
    if (kind_ == MSCIPC_RESULT_ACK && reply != NULL) {
        mscipc_field_entry_t entry_;
        if (!mscipc_result_reply_entry(&result_, &entry_) || entry_.descriptor != 0x87 ||
            mscipc_base_device_fw_decode(entry_.data, entry_.length, reply, NULL) != MSCIPC_OK) {
            return mscipc_link_fail(link, MSCIPC_RESULT_INVALID, "missing reply field 0x87");
        }
    }
    return kind_;
}

mscipc_result_kind_t mscipc_base_get_device_cal(mscipc_link_t *link, mscipc_base_device_cal_t *reply) {
    mscipc_field_value_t cmd_;
    mscipc_result_kind_t kind_;
    mscipc_result_t result_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MSCIPC_FIELD_BASE_GET_DEVICE_CAL;
    }
    kind_ = mscipc_link_run(link, &cmd_, NULL, &result_);
    if (kind_ == MSCIPC_RESULT_ACK && reply != NULL) {
        mscipc_field_entry_t entry_;
        if (!mscipc_result_reply_entry(&result_, &entry_) || entry_.descriptor != 0x88 ||
            mscipc_base_device_cal_decode(entry_.data, entry_.length, reply, NULL) != MSCIPC_OK) {
            return mscipc_link_fail(link, MSCIPC_RESULT_INVALID, "missing reply field 0x88");
        }
    }
    return kind_;
}

mscipc_result_kind_t mscipc_base_correlate_gps_time(mscipc_link_t *link, uint16_t week, uint32_t seconds) {
    mscipc_field_value_t cmd_;
    mscipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MSCIPC_FIELD_BASE_CORRELATE_GPS_TIME;
        cmd_.u.base_correlate_gps_time.week = week;
        cmd_.u.base_correlate_gps_time.seconds = seconds;
    }
    kind_ = mscipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mscipc_result_kind_t mscipc_imu_config_uart_baud_rate_write(mscipc_link_t *link,
                                                            mscipc_baud_rate_t baud_rate) {
    mscipc_field_value_t cmd_;
    mscipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MSCIPC_FIELD_IMU_CONFIG_UART_BAUD_RATE;
        cmd_.u.imu_config_uart_baud_rate.function = MSCIPC_FUNCTION_CODE_WRITE;
        cmd_.u.imu_config_uart_baud_rate.has_baud_rate = true;
        cmd_.u.imu_config_uart_baud_rate.baud_rate = baud_rate;
    }
    kind_ = mscipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mscipc_result_kind_t
mscipc_imu_config_uart_baud_rate_read(mscipc_link_t *link,
                                      mscipc_imu_config_uart_baud_rate_response_t *reply) {
    mscipc_field_value_t cmd_;
    mscipc_result_kind_t kind_;
    mscipc_result_t result_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MSCIPC_FIELD_IMU_CONFIG_UART_BAUD_RATE;
        cmd_.u.imu_config_uart_baud_rate.function = MSCIPC_FUNCTION_CODE_READ;
    }
    kind_ = mscipc_link_run(link, &cmd_, NULL, &result_);
    if (kind_ == MSCIPC_RESULT_ACK && reply != NULL) {
        mscipc_field_entry_t entry_;
        if (!mscipc_result_reply_entry(&result_, &entry_) || entry_.descriptor != 0x81 ||
            mscipc_imu_config_uart_baud_rate_response_decode(entry_.data, entry_.length, reply, NULL) !=
                MSCIPC_OK) {
            return mscipc_link_fail(link, MSCIPC_RESULT_INVALID, "missing reply field 0x81");
        }
    }
    return kind_;
}

mscipc_result_kind_t mscipc_imu_config_uart_baud_rate_save(mscipc_link_t *link) {
    mscipc_field_value_t cmd_;
    mscipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MSCIPC_FIELD_IMU_CONFIG_UART_BAUD_RATE;
        cmd_.u.imu_config_uart_baud_rate.function = MSCIPC_FUNCTION_CODE_SAVE;
    }
    kind_ = mscipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mscipc_result_kind_t mscipc_imu_config_uart_baud_rate_load(mscipc_link_t *link) {
    mscipc_field_value_t cmd_;
    mscipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MSCIPC_FIELD_IMU_CONFIG_UART_BAUD_RATE;
        cmd_.u.imu_config_uart_baud_rate.function = MSCIPC_FUNCTION_CODE_LOAD;
    }
    kind_ = mscipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mscipc_result_kind_t mscipc_imu_config_uart_baud_rate_default(mscipc_link_t *link) {
    mscipc_field_value_t cmd_;
    mscipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MSCIPC_FIELD_IMU_CONFIG_UART_BAUD_RATE;
        cmd_.u.imu_config_uart_baud_rate.function = MSCIPC_FUNCTION_CODE_DEFAULT;
    }
    kind_ = mscipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mscipc_result_kind_t mscipc_imu_config_filter_write(mscipc_link_t *link,
                                                    mscipc_filter_bandwidth_t bandwidth) {
    mscipc_field_value_t cmd_;
    mscipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MSCIPC_FIELD_IMU_CONFIG_FILTER;
        cmd_.u.imu_config_filter.function = MSCIPC_FUNCTION_CODE_WRITE;
        cmd_.u.imu_config_filter.has_bandwidth = true;
        cmd_.u.imu_config_filter.bandwidth = bandwidth;
    }
    kind_ = mscipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mscipc_result_kind_t mscipc_imu_config_filter_read(mscipc_link_t *link,
                                                   mscipc_imu_config_filter_response_t *reply) {
    mscipc_field_value_t cmd_;
    mscipc_result_kind_t kind_;
    mscipc_result_t result_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MSCIPC_FIELD_IMU_CONFIG_FILTER;
        cmd_.u.imu_config_filter.function = MSCIPC_FUNCTION_CODE_READ;
    }
    kind_ = mscipc_link_run(link, &cmd_, NULL, &result_);
    if (kind_ == MSCIPC_RESULT_ACK && reply != NULL) {
        mscipc_field_entry_t entry_;
        if (!mscipc_result_reply_entry(&result_, &entry_) || entry_.descriptor != 0x83 ||
            mscipc_imu_config_filter_response_decode(entry_.data, entry_.length, reply, NULL) != MSCIPC_OK) {
            return mscipc_link_fail(link, MSCIPC_RESULT_INVALID, "missing reply field 0x83");
        }
    }
    return kind_;
}

mscipc_result_kind_t mscipc_imu_config_filter_save(mscipc_link_t *link) {
    mscipc_field_value_t cmd_;
    mscipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MSCIPC_FIELD_IMU_CONFIG_FILTER;
        cmd_.u.imu_config_filter.function = MSCIPC_FUNCTION_CODE_SAVE;
    }
    kind_ = mscipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mscipc_result_kind_t mscipc_imu_config_filter_load(mscipc_link_t *link) {
    mscipc_field_value_t cmd_;
    mscipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MSCIPC_FIELD_IMU_CONFIG_FILTER;
        cmd_.u.imu_config_filter.function = MSCIPC_FUNCTION_CODE_LOAD;
    }
    kind_ = mscipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mscipc_result_kind_t mscipc_imu_config_filter_default(mscipc_link_t *link) {
    mscipc_field_value_t cmd_;
    mscipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MSCIPC_FIELD_IMU_CONFIG_FILTER;
        cmd_.u.imu_config_filter.function = MSCIPC_FUNCTION_CODE_DEFAULT;
    }
    kind_ = mscipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mscipc_result_kind_t mscipc_imu_config_sample_rate_write(mscipc_link_t *link, uint16_t decimation) {
    mscipc_field_value_t cmd_;
    mscipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MSCIPC_FIELD_IMU_CONFIG_SAMPLE_RATE;
        cmd_.u.imu_config_sample_rate.function = MSCIPC_FUNCTION_CODE_WRITE;
        cmd_.u.imu_config_sample_rate.has_decimation = true;
        cmd_.u.imu_config_sample_rate.decimation = decimation;
    }
    kind_ = mscipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mscipc_result_kind_t mscipc_imu_config_sample_rate_read(mscipc_link_t *link,
                                                        mscipc_imu_config_sample_rate_response_t *reply) {
    mscipc_field_value_t cmd_;
    mscipc_result_kind_t kind_;
    mscipc_result_t result_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MSCIPC_FIELD_IMU_CONFIG_SAMPLE_RATE;
        cmd_.u.imu_config_sample_rate.function = MSCIPC_FUNCTION_CODE_READ;
    }
    kind_ = mscipc_link_run(link, &cmd_, NULL, &result_);
    if (kind_ == MSCIPC_RESULT_ACK && reply != NULL) {
        mscipc_field_entry_t entry_;
        if (!mscipc_result_reply_entry(&result_, &entry_) || entry_.descriptor != 0x84 ||
            mscipc_imu_config_sample_rate_response_decode(entry_.data, entry_.length, reply, NULL) !=
                MSCIPC_OK) {
            return mscipc_link_fail(link, MSCIPC_RESULT_INVALID, "missing reply field 0x84");
        }
    }
    return kind_;
}

mscipc_result_kind_t mscipc_imu_config_sample_rate_save(mscipc_link_t *link) {
    mscipc_field_value_t cmd_;
    mscipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MSCIPC_FIELD_IMU_CONFIG_SAMPLE_RATE;
        cmd_.u.imu_config_sample_rate.function = MSCIPC_FUNCTION_CODE_SAVE;
    }
    kind_ = mscipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mscipc_result_kind_t mscipc_imu_config_sample_rate_load(mscipc_link_t *link) {
    mscipc_field_value_t cmd_;
    mscipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MSCIPC_FIELD_IMU_CONFIG_SAMPLE_RATE;
        cmd_.u.imu_config_sample_rate.function = MSCIPC_FUNCTION_CODE_LOAD;
    }
    kind_ = mscipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mscipc_result_kind_t mscipc_imu_config_sample_rate_default(mscipc_link_t *link) {
    mscipc_field_value_t cmd_;
    mscipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MSCIPC_FIELD_IMU_CONFIG_SAMPLE_RATE;
        cmd_.u.imu_config_sample_rate.function = MSCIPC_FUNCTION_CODE_DEFAULT;
    }
    kind_ = mscipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mscipc_result_kind_t mscipc_imu_config_select_sensors_write(mscipc_link_t *link, uint8_t reserved,
                                                            const mscipc_sensor_code_t *sensors,
                                                            size_t sensors_count) {
    mscipc_field_value_t cmd_;
    mscipc_result_kind_t kind_;
    if (sensors_count > 251u) {
        return mscipc_link_fail(link, MSCIPC_RESULT_REFUSED, "sensors: more than 251 elements");
    }
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MSCIPC_FIELD_IMU_CONFIG_SELECT_SENSORS;
        cmd_.u.imu_config_select_sensors.function = MSCIPC_FUNCTION_CODE_WRITE;
        cmd_.u.imu_config_select_sensors.has_reserved = true;
        cmd_.u.imu_config_select_sensors.reserved = reserved;
        cmd_.u.imu_config_select_sensors.has_sensors = true;
        if (sensors_count > 0) {
            memcpy(cmd_.u.imu_config_select_sensors.sensors, sensors,
                   sensors_count * sizeof cmd_.u.imu_config_select_sensors.sensors[0]);
        }
        cmd_.u.imu_config_select_sensors.sensors_count = sensors_count;
    }
    kind_ = mscipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mscipc_result_kind_t
mscipc_imu_config_select_sensors_read(mscipc_link_t *link,
                                      mscipc_imu_config_select_sensors_response_t *reply) {
    mscipc_field_value_t cmd_;
    mscipc_result_kind_t kind_;
    mscipc_result_t result_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MSCIPC_FIELD_IMU_CONFIG_SELECT_SENSORS;
        cmd_.u.imu_config_select_sensors.function = MSCIPC_FUNCTION_CODE_READ;
    }
    kind_ = mscipc_link_run(link, &cmd_, NULL, &result_);
    if (kind_ == MSCIPC_RESULT_ACK && reply != NULL) {
        mscipc_field_entry_t entry_;
        if (!mscipc_result_reply_entry(&result_, &entry_) || entry_.descriptor != 0x85 ||
            mscipc_imu_config_select_sensors_response_decode(entry_.data, entry_.length, reply, NULL) !=
                MSCIPC_OK) {
            return mscipc_link_fail(link, MSCIPC_RESULT_INVALID, "missing reply field 0x85");
        }
    }
    return kind_;
}

mscipc_result_kind_t mscipc_imu_config_select_sensors_save(mscipc_link_t *link) {
    mscipc_field_value_t cmd_;
    mscipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MSCIPC_FIELD_IMU_CONFIG_SELECT_SENSORS;
        cmd_.u.imu_config_select_sensors.function = MSCIPC_FUNCTION_CODE_SAVE;
    }
    kind_ = mscipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mscipc_result_kind_t mscipc_imu_config_select_sensors_load(mscipc_link_t *link) {
    mscipc_field_value_t cmd_;
    mscipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MSCIPC_FIELD_IMU_CONFIG_SELECT_SENSORS;
        cmd_.u.imu_config_select_sensors.function = MSCIPC_FUNCTION_CODE_LOAD;
    }
    kind_ = mscipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mscipc_result_kind_t mscipc_imu_config_select_sensors_default(mscipc_link_t *link) {
    mscipc_field_value_t cmd_;
    mscipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MSCIPC_FIELD_IMU_CONFIG_SELECT_SENSORS;
        cmd_.u.imu_config_select_sensors.function = MSCIPC_FUNCTION_CODE_DEFAULT;
    }
    kind_ = mscipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mscipc_result_kind_t
mscipc_imu_config_get_internal_sample_rate(mscipc_link_t *link,
                                           mscipc_imu_config_internal_sample_rate_t *reply) {
    mscipc_field_value_t cmd_;
    mscipc_result_kind_t kind_;
    mscipc_result_t result_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MSCIPC_FIELD_IMU_CONFIG_GET_INTERNAL_SAMPLE_RATE;
    }
    kind_ = mscipc_link_run(link, &cmd_, NULL, &result_);
    if (kind_ == MSCIPC_RESULT_ACK && reply != NULL) {
        mscipc_field_entry_t entry_;
        if (!mscipc_result_reply_entry(&result_, &entry_) || entry_.descriptor != 0x86 ||
            mscipc_imu_config_internal_sample_rate_decode(entry_.data, entry_.length, reply, NULL) !=
                MSCIPC_OK) {
            return mscipc_link_fail(link, MSCIPC_RESULT_INVALID, "missing reply field 0x86");
        }
    }
    return kind_;
}

mscipc_result_kind_t mscipc_imu_config_accel_range_write(mscipc_link_t *link, mscipc_accel_range_t range) {
    mscipc_field_value_t cmd_;
    mscipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MSCIPC_FIELD_IMU_CONFIG_ACCEL_RANGE;
        cmd_.u.imu_config_accel_range.function = MSCIPC_FUNCTION_CODE_WRITE;
        cmd_.u.imu_config_accel_range.has_range = true;
        cmd_.u.imu_config_accel_range.range = range;
    }
    kind_ = mscipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mscipc_result_kind_t mscipc_imu_config_accel_range_read(mscipc_link_t *link,
                                                        mscipc_imu_config_accel_range_response_t *reply) {
    mscipc_field_value_t cmd_;
    mscipc_result_kind_t kind_;
    mscipc_result_t result_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MSCIPC_FIELD_IMU_CONFIG_ACCEL_RANGE;
        cmd_.u.imu_config_accel_range.function = MSCIPC_FUNCTION_CODE_READ;
    }
    kind_ = mscipc_link_run(link, &cmd_, NULL, &result_);
    if (kind_ == MSCIPC_RESULT_ACK && reply != NULL) {
        mscipc_field_entry_t entry_;
        if (!mscipc_result_reply_entry(&result_, &entry_) || entry_.descriptor != 0x87 ||
            mscipc_imu_config_accel_range_response_decode(entry_.data, entry_.length, reply, NULL) !=
                MSCIPC_OK) {
            return mscipc_link_fail(link, MSCIPC_RESULT_INVALID, "missing reply field 0x87");
        }
    }
    return kind_;
}

mscipc_result_kind_t mscipc_imu_config_accel_range_save(mscipc_link_t *link) {
    mscipc_field_value_t cmd_;
    mscipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MSCIPC_FIELD_IMU_CONFIG_ACCEL_RANGE;
        cmd_.u.imu_config_accel_range.function = MSCIPC_FUNCTION_CODE_SAVE;
    }
    kind_ = mscipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mscipc_result_kind_t mscipc_imu_config_accel_range_load(mscipc_link_t *link) {
    mscipc_field_value_t cmd_;
    mscipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MSCIPC_FIELD_IMU_CONFIG_ACCEL_RANGE;
        cmd_.u.imu_config_accel_range.function = MSCIPC_FUNCTION_CODE_LOAD;
    }
    kind_ = mscipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mscipc_result_kind_t mscipc_imu_config_accel_range_default(mscipc_link_t *link) {
    mscipc_field_value_t cmd_;
    mscipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MSCIPC_FIELD_IMU_CONFIG_ACCEL_RANGE;
        cmd_.u.imu_config_accel_range.function = MSCIPC_FUNCTION_CODE_DEFAULT;
    }
    kind_ = mscipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mscipc_result_kind_t mscipc_imu_config_gyro_range_write(mscipc_link_t *link, mscipc_gyro_range_t range) {
    mscipc_field_value_t cmd_;
    mscipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MSCIPC_FIELD_IMU_CONFIG_GYRO_RANGE;
        cmd_.u.imu_config_gyro_range.function = MSCIPC_FUNCTION_CODE_WRITE;
        cmd_.u.imu_config_gyro_range.has_range = true;
        cmd_.u.imu_config_gyro_range.range = range;
    }
    kind_ = mscipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mscipc_result_kind_t mscipc_imu_config_gyro_range_read(mscipc_link_t *link,
                                                       mscipc_imu_config_gyro_range_response_t *reply) {
    mscipc_field_value_t cmd_;
    mscipc_result_kind_t kind_;
    mscipc_result_t result_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MSCIPC_FIELD_IMU_CONFIG_GYRO_RANGE;
        cmd_.u.imu_config_gyro_range.function = MSCIPC_FUNCTION_CODE_READ;
    }
    kind_ = mscipc_link_run(link, &cmd_, NULL, &result_);
    if (kind_ == MSCIPC_RESULT_ACK && reply != NULL) {
        mscipc_field_entry_t entry_;
        if (!mscipc_result_reply_entry(&result_, &entry_) || entry_.descriptor != 0x88 ||
            mscipc_imu_config_gyro_range_response_decode(entry_.data, entry_.length, reply, NULL) !=
                MSCIPC_OK) {
            return mscipc_link_fail(link, MSCIPC_RESULT_INVALID, "missing reply field 0x88");
        }
    }
    return kind_;
}

mscipc_result_kind_t mscipc_imu_config_gyro_range_save(mscipc_link_t *link) {
    mscipc_field_value_t cmd_;
    mscipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MSCIPC_FIELD_IMU_CONFIG_GYRO_RANGE;
        cmd_.u.imu_config_gyro_range.function = MSCIPC_FUNCTION_CODE_SAVE;
    }
    kind_ = mscipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mscipc_result_kind_t mscipc_imu_config_gyro_range_load(mscipc_link_t *link) {
    mscipc_field_value_t cmd_;
    mscipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MSCIPC_FIELD_IMU_CONFIG_GYRO_RANGE;
        cmd_.u.imu_config_gyro_range.function = MSCIPC_FUNCTION_CODE_LOAD;
    }
    kind_ = mscipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mscipc_result_kind_t mscipc_imu_config_gyro_range_default(mscipc_link_t *link) {
    mscipc_field_value_t cmd_;
    mscipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MSCIPC_FIELD_IMU_CONFIG_GYRO_RANGE;
        cmd_.u.imu_config_gyro_range.function = MSCIPC_FUNCTION_CODE_DEFAULT;
    }
    kind_ = mscipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mscipc_result_kind_t mscipc_imu_config_config_all_save(mscipc_link_t *link) {
    mscipc_field_value_t cmd_;
    mscipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MSCIPC_FIELD_IMU_CONFIG_CONFIG_ALL;
        cmd_.u.imu_config_config_all.function = MSCIPC_FUNCTION_CODE_SAVE;
    }
    kind_ = mscipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mscipc_result_kind_t mscipc_imu_config_config_all_load(mscipc_link_t *link) {
    mscipc_field_value_t cmd_;
    mscipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MSCIPC_FIELD_IMU_CONFIG_CONFIG_ALL;
        cmd_.u.imu_config_config_all.function = MSCIPC_FUNCTION_CODE_LOAD;
    }
    kind_ = mscipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mscipc_result_kind_t mscipc_imu_config_config_all_default(mscipc_link_t *link) {
    mscipc_field_value_t cmd_;
    mscipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MSCIPC_FIELD_IMU_CONFIG_CONFIG_ALL;
        cmd_.u.imu_config_config_all.function = MSCIPC_FUNCTION_CODE_DEFAULT;
    }
    kind_ = mscipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mscipc_result_kind_t mscipc_imu_config_data_on_off_write(mscipc_link_t *link, mscipc_on_off_t control) {
    mscipc_field_value_t cmd_;
    mscipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MSCIPC_FIELD_IMU_CONFIG_DATA_ON_OFF;
        cmd_.u.imu_config_data_on_off.function = MSCIPC_FUNCTION_CODE_WRITE;
        cmd_.u.imu_config_data_on_off.has_control = true;
        cmd_.u.imu_config_data_on_off.control = control;
    }
    kind_ = mscipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mscipc_result_kind_t mscipc_imu_config_data_on_off_read(mscipc_link_t *link,
                                                        mscipc_imu_config_data_on_off_response_t *reply) {
    mscipc_field_value_t cmd_;
    mscipc_result_kind_t kind_;
    mscipc_result_t result_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MSCIPC_FIELD_IMU_CONFIG_DATA_ON_OFF;
        cmd_.u.imu_config_data_on_off.function = MSCIPC_FUNCTION_CODE_READ;
    }
    kind_ = mscipc_link_run(link, &cmd_, NULL, &result_);
    if (kind_ == MSCIPC_RESULT_ACK && reply != NULL) {
        mscipc_field_entry_t entry_;
        if (!mscipc_result_reply_entry(&result_, &entry_) || entry_.descriptor != 0x8A ||
            mscipc_imu_config_data_on_off_response_decode(entry_.data, entry_.length, reply, NULL) !=
                MSCIPC_OK) {
            return mscipc_link_fail(link, MSCIPC_RESULT_INVALID, "missing reply field 0x8A");
        }
    }
    return kind_;
}

mscipc_result_kind_t mscipc_imu_config_data_on_off_save(mscipc_link_t *link) {
    mscipc_field_value_t cmd_;
    mscipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MSCIPC_FIELD_IMU_CONFIG_DATA_ON_OFF;
        cmd_.u.imu_config_data_on_off.function = MSCIPC_FUNCTION_CODE_SAVE;
    }
    kind_ = mscipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mscipc_result_kind_t mscipc_imu_config_data_on_off_load(mscipc_link_t *link) {
    mscipc_field_value_t cmd_;
    mscipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MSCIPC_FIELD_IMU_CONFIG_DATA_ON_OFF;
        cmd_.u.imu_config_data_on_off.function = MSCIPC_FUNCTION_CODE_LOAD;
    }
    kind_ = mscipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mscipc_result_kind_t mscipc_imu_config_data_on_off_default(mscipc_link_t *link) {
    mscipc_field_value_t cmd_;
    mscipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MSCIPC_FIELD_IMU_CONFIG_DATA_ON_OFF;
        cmd_.u.imu_config_data_on_off.function = MSCIPC_FUNCTION_CODE_DEFAULT;
    }
    kind_ = mscipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mscipc_result_kind_t mscipc_imu_config_xtrig_on_off_write(mscipc_link_t *link, mscipc_on_off_t control) {
    mscipc_field_value_t cmd_;
    mscipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MSCIPC_FIELD_IMU_CONFIG_XTRIG_ON_OFF;
        cmd_.u.imu_config_xtrig_on_off.function = MSCIPC_FUNCTION_CODE_WRITE;
        cmd_.u.imu_config_xtrig_on_off.has_control = true;
        cmd_.u.imu_config_xtrig_on_off.control = control;
    }
    kind_ = mscipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mscipc_result_kind_t mscipc_imu_config_xtrig_on_off_read(mscipc_link_t *link,
                                                         mscipc_imu_config_xtrig_on_off_response_t *reply) {
    mscipc_field_value_t cmd_;
    mscipc_result_kind_t kind_;
    mscipc_result_t result_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MSCIPC_FIELD_IMU_CONFIG_XTRIG_ON_OFF;
        cmd_.u.imu_config_xtrig_on_off.function = MSCIPC_FUNCTION_CODE_READ;
    }
    kind_ = mscipc_link_run(link, &cmd_, NULL, &result_);
    if (kind_ == MSCIPC_RESULT_ACK && reply != NULL) {
        mscipc_field_entry_t entry_;
        if (!mscipc_result_reply_entry(&result_, &entry_) || entry_.descriptor != 0x8B ||
            mscipc_imu_config_xtrig_on_off_response_decode(entry_.data, entry_.length, reply, NULL) !=
                MSCIPC_OK) {
            return mscipc_link_fail(link, MSCIPC_RESULT_INVALID, "missing reply field 0x8B");
        }
    }
    return kind_;
}

mscipc_result_kind_t mscipc_imu_config_xtrig_on_off_save(mscipc_link_t *link) {
    mscipc_field_value_t cmd_;
    mscipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MSCIPC_FIELD_IMU_CONFIG_XTRIG_ON_OFF;
        cmd_.u.imu_config_xtrig_on_off.function = MSCIPC_FUNCTION_CODE_SAVE;
    }
    kind_ = mscipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mscipc_result_kind_t mscipc_imu_config_xtrig_on_off_load(mscipc_link_t *link) {
    mscipc_field_value_t cmd_;
    mscipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MSCIPC_FIELD_IMU_CONFIG_XTRIG_ON_OFF;
        cmd_.u.imu_config_xtrig_on_off.function = MSCIPC_FUNCTION_CODE_LOAD;
    }
    kind_ = mscipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mscipc_result_kind_t mscipc_imu_config_xtrig_on_off_default(mscipc_link_t *link) {
    mscipc_field_value_t cmd_;
    mscipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MSCIPC_FIELD_IMU_CONFIG_XTRIG_ON_OFF;
        cmd_.u.imu_config_xtrig_on_off.function = MSCIPC_FUNCTION_CODE_DEFAULT;
    }
    kind_ = mscipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mscipc_result_kind_t mscipc_imu_config_select_sensors_rev_b_write(mscipc_link_t *link,
                                                                  const mscipc_sensor_code_t *sensors,
                                                                  size_t sensors_count) {
    mscipc_field_value_t cmd_;
    mscipc_result_kind_t kind_;
    if (sensors_count > 252u) {
        return mscipc_link_fail(link, MSCIPC_RESULT_REFUSED, "sensors: more than 252 elements");
    }
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MSCIPC_FIELD_IMU_CONFIG_SELECT_SENSORS_REV_B;
        cmd_.u.imu_config_select_sensors_rev_b.function = MSCIPC_FUNCTION_CODE_WRITE;
        cmd_.u.imu_config_select_sensors_rev_b.has_sensors = true;
        if (sensors_count > 0) {
            memcpy(cmd_.u.imu_config_select_sensors_rev_b.sensors, sensors,
                   sensors_count * sizeof cmd_.u.imu_config_select_sensors_rev_b.sensors[0]);
        }
        cmd_.u.imu_config_select_sensors_rev_b.sensors_count = sensors_count;
    }
    kind_ = mscipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mscipc_result_kind_t
mscipc_imu_config_select_sensors_rev_b_read(mscipc_link_t *link,
                                            mscipc_imu_config_select_sensors_rev_b_response_t *reply) {
    mscipc_field_value_t cmd_;
    mscipc_result_kind_t kind_;
    mscipc_result_t result_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MSCIPC_FIELD_IMU_CONFIG_SELECT_SENSORS_REV_B;
        cmd_.u.imu_config_select_sensors_rev_b.function = MSCIPC_FUNCTION_CODE_READ;
    }
    kind_ = mscipc_link_run(link, &cmd_, NULL, &result_);
    if (kind_ == MSCIPC_RESULT_ACK && reply != NULL) {
        mscipc_field_entry_t entry_;
        if (!mscipc_result_reply_entry(&result_, &entry_) || entry_.descriptor != 0x8C ||
            mscipc_imu_config_select_sensors_rev_b_response_decode(entry_.data, entry_.length, reply, NULL) !=
                MSCIPC_OK) {
            return mscipc_link_fail(link, MSCIPC_RESULT_INVALID, "missing reply field 0x8C");
        }
    }
    return kind_;
}

mscipc_result_kind_t mscipc_imu_config_select_sensors_rev_b_save(mscipc_link_t *link) {
    mscipc_field_value_t cmd_;
    mscipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MSCIPC_FIELD_IMU_CONFIG_SELECT_SENSORS_REV_B;
        cmd_.u.imu_config_select_sensors_rev_b.function = MSCIPC_FUNCTION_CODE_SAVE;
    }
    kind_ = mscipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mscipc_result_kind_t mscipc_imu_config_select_sensors_rev_b_load(mscipc_link_t *link) {
    mscipc_field_value_t cmd_;
    mscipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MSCIPC_FIELD_IMU_CONFIG_SELECT_SENSORS_REV_B;
        cmd_.u.imu_config_select_sensors_rev_b.function = MSCIPC_FUNCTION_CODE_LOAD;
    }
    kind_ = mscipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mscipc_result_kind_t mscipc_imu_config_select_sensors_rev_b_default(mscipc_link_t *link) {
    mscipc_field_value_t cmd_;
    mscipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MSCIPC_FIELD_IMU_CONFIG_SELECT_SENSORS_REV_B;
        cmd_.u.imu_config_select_sensors_rev_b.function = MSCIPC_FUNCTION_CODE_DEFAULT;
    }
    kind_ = mscipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mscipc_result_kind_t mscipc_imu_config_aux_accel_range_write(mscipc_link_t *link,
                                                             mscipc_accel_range_t range) {
    mscipc_field_value_t cmd_;
    mscipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MSCIPC_FIELD_IMU_CONFIG_AUX_ACCEL_RANGE;
        cmd_.u.imu_config_aux_accel_range.function = MSCIPC_FUNCTION_CODE_WRITE;
        cmd_.u.imu_config_aux_accel_range.has_range = true;
        cmd_.u.imu_config_aux_accel_range.range = range;
    }
    kind_ = mscipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mscipc_result_kind_t
mscipc_imu_config_aux_accel_range_read(mscipc_link_t *link,
                                       mscipc_imu_config_aux_accel_range_response_t *reply) {
    mscipc_field_value_t cmd_;
    mscipc_result_kind_t kind_;
    mscipc_result_t result_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MSCIPC_FIELD_IMU_CONFIG_AUX_ACCEL_RANGE;
        cmd_.u.imu_config_aux_accel_range.function = MSCIPC_FUNCTION_CODE_READ;
    }
    kind_ = mscipc_link_run(link, &cmd_, NULL, &result_);
    if (kind_ == MSCIPC_RESULT_ACK && reply != NULL) {
        mscipc_field_entry_t entry_;
        if (!mscipc_result_reply_entry(&result_, &entry_) || entry_.descriptor != 0x8D ||
            mscipc_imu_config_aux_accel_range_response_decode(entry_.data, entry_.length, reply, NULL) !=
                MSCIPC_OK) {
            return mscipc_link_fail(link, MSCIPC_RESULT_INVALID, "missing reply field 0x8D");
        }
    }
    return kind_;
}

mscipc_result_kind_t mscipc_imu_config_aux_accel_range_save(mscipc_link_t *link) {
    mscipc_field_value_t cmd_;
    mscipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MSCIPC_FIELD_IMU_CONFIG_AUX_ACCEL_RANGE;
        cmd_.u.imu_config_aux_accel_range.function = MSCIPC_FUNCTION_CODE_SAVE;
    }
    kind_ = mscipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mscipc_result_kind_t mscipc_imu_config_aux_accel_range_load(mscipc_link_t *link) {
    mscipc_field_value_t cmd_;
    mscipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MSCIPC_FIELD_IMU_CONFIG_AUX_ACCEL_RANGE;
        cmd_.u.imu_config_aux_accel_range.function = MSCIPC_FUNCTION_CODE_LOAD;
    }
    kind_ = mscipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mscipc_result_kind_t mscipc_imu_config_aux_accel_range_default(mscipc_link_t *link) {
    mscipc_field_value_t cmd_;
    mscipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MSCIPC_FIELD_IMU_CONFIG_AUX_ACCEL_RANGE;
        cmd_.u.imu_config_aux_accel_range.function = MSCIPC_FUNCTION_CODE_DEFAULT;
    }
    kind_ = mscipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}
