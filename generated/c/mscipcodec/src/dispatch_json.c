/* Canonical JSON of a decoded field value (the mscipcodec_json library). Generated from the spec: do
 * not edit. */
#include "mscipcodec/dispatch.h"
#include "layouts_internal.h"

void mscipc_value_to_json(mscipc_jw_t *w, const mscipc_field_value_t *value) {
    mscipc_layout_to_json(w, value->id, &value->u);
}

void mscipc_layout_to_json(mscipc_jw_t *w, mscipc_field_id_t id, const void *in) {
    switch (id) {
    case MSCIPC_FIELD_ACK:
        mscipc_ack_to_json(w, (const mscipc_ack_t *)in);
        return;
    case MSCIPC_FIELD_BASE_PING:
        mscipc_base_ping_to_json(w, (const mscipc_base_ping_t *)in);
        return;
    case MSCIPC_FIELD_BASE_GET_DEVICE_MESSAGES:
        mscipc_base_get_device_messages_to_json(w, (const mscipc_base_get_device_messages_t *)in);
        return;
    case MSCIPC_FIELD_BASE_DEVICE_MESSAGES:
        mscipc_base_device_messages_to_json(w, (const mscipc_base_device_messages_t *)in);
        return;
    case MSCIPC_FIELD_BASE_DEVICE_RESET:
        mscipc_base_device_reset_to_json(w, (const mscipc_base_device_reset_t *)in);
        return;
    case MSCIPC_FIELD_BASE_GET_DEVICE_MODEL:
        mscipc_base_get_device_model_to_json(w, (const mscipc_base_get_device_model_t *)in);
        return;
    case MSCIPC_FIELD_BASE_DEVICE_MODEL:
        mscipc_base_device_model_to_json(w, (const mscipc_base_device_model_t *)in);
        return;
    case MSCIPC_FIELD_BASE_GET_DEVICE_SN:
        mscipc_base_get_device_sn_to_json(w, (const mscipc_base_get_device_sn_t *)in);
        return;
    case MSCIPC_FIELD_BASE_DEVICE_SN:
        mscipc_base_device_sn_to_json(w, (const mscipc_base_device_sn_t *)in);
        return;
    case MSCIPC_FIELD_BASE_GET_DEVICE_FW:
        mscipc_base_get_device_fw_to_json(w, (const mscipc_base_get_device_fw_t *)in);
        return;
    case MSCIPC_FIELD_BASE_DEVICE_FW:
        mscipc_base_device_fw_to_json(w, (const mscipc_base_device_fw_t *)in);
        return;
    case MSCIPC_FIELD_BASE_GET_DEVICE_CAL:
        mscipc_base_get_device_cal_to_json(w, (const mscipc_base_get_device_cal_t *)in);
        return;
    case MSCIPC_FIELD_BASE_DEVICE_CAL:
        mscipc_base_device_cal_to_json(w, (const mscipc_base_device_cal_t *)in);
        return;
    case MSCIPC_FIELD_BASE_CORRELATE_GPS_TIME:
        mscipc_base_correlate_gps_time_to_json(w, (const mscipc_base_correlate_gps_time_t *)in);
        return;
    case MSCIPC_FIELD_IMU_CONFIG_UART_BAUD_RATE:
        mscipc_imu_config_uart_baud_rate_to_json(w, (const mscipc_imu_config_uart_baud_rate_t *)in);
        return;
    case MSCIPC_FIELD_IMU_CONFIG_UART_BAUD_RATE_RESPONSE:
        mscipc_imu_config_uart_baud_rate_response_to_json(
            w, (const mscipc_imu_config_uart_baud_rate_response_t *)in);
        return;
    case MSCIPC_FIELD_IMU_CONFIG_FILTER:
        mscipc_imu_config_filter_to_json(w, (const mscipc_imu_config_filter_t *)in);
        return;
    case MSCIPC_FIELD_IMU_CONFIG_FILTER_RESPONSE:
        mscipc_imu_config_filter_response_to_json(w, (const mscipc_imu_config_filter_response_t *)in);
        return;
    case MSCIPC_FIELD_IMU_CONFIG_SAMPLE_RATE:
        mscipc_imu_config_sample_rate_to_json(w, (const mscipc_imu_config_sample_rate_t *)in);
        return;
    case MSCIPC_FIELD_IMU_CONFIG_SAMPLE_RATE_RESPONSE:
        mscipc_imu_config_sample_rate_response_to_json(w,
                                                       (const mscipc_imu_config_sample_rate_response_t *)in);
        return;
    case MSCIPC_FIELD_IMU_CONFIG_SELECT_SENSORS:
        mscipc_imu_config_select_sensors_to_json(w, (const mscipc_imu_config_select_sensors_t *)in);
        return;
    case MSCIPC_FIELD_IMU_CONFIG_SELECT_SENSORS_RESPONSE:
        mscipc_imu_config_select_sensors_response_to_json(
            w, (const mscipc_imu_config_select_sensors_response_t *)in);
        return;
    case MSCIPC_FIELD_IMU_CONFIG_GET_INTERNAL_SAMPLE_RATE:
        mscipc_imu_config_get_internal_sample_rate_to_json(
            w, (const mscipc_imu_config_get_internal_sample_rate_t *)in);
        return;
    case MSCIPC_FIELD_IMU_CONFIG_INTERNAL_SAMPLE_RATE:
        mscipc_imu_config_internal_sample_rate_to_json(w,
                                                       (const mscipc_imu_config_internal_sample_rate_t *)in);
        return;
    case MSCIPC_FIELD_IMU_CONFIG_ACCEL_RANGE:
        mscipc_imu_config_accel_range_to_json(w, (const mscipc_imu_config_accel_range_t *)in);
        return;
    case MSCIPC_FIELD_IMU_CONFIG_ACCEL_RANGE_RESPONSE:
        mscipc_imu_config_accel_range_response_to_json(w,
                                                       (const mscipc_imu_config_accel_range_response_t *)in);
        return;
    case MSCIPC_FIELD_IMU_CONFIG_GYRO_RANGE:
        mscipc_imu_config_gyro_range_to_json(w, (const mscipc_imu_config_gyro_range_t *)in);
        return;
    case MSCIPC_FIELD_IMU_CONFIG_GYRO_RANGE_RESPONSE:
        mscipc_imu_config_gyro_range_response_to_json(w, (const mscipc_imu_config_gyro_range_response_t *)in);
        return;
    case MSCIPC_FIELD_IMU_CONFIG_CONFIG_ALL:
        mscipc_imu_config_config_all_to_json(w, (const mscipc_imu_config_config_all_t *)in);
        return;
    case MSCIPC_FIELD_IMU_CONFIG_DATA_ON_OFF:
        mscipc_imu_config_data_on_off_to_json(w, (const mscipc_imu_config_data_on_off_t *)in);
        return;
    case MSCIPC_FIELD_IMU_CONFIG_DATA_ON_OFF_RESPONSE:
        mscipc_imu_config_data_on_off_response_to_json(w,
                                                       (const mscipc_imu_config_data_on_off_response_t *)in);
        return;
    case MSCIPC_FIELD_IMU_CONFIG_XTRIG_ON_OFF:
        mscipc_imu_config_xtrig_on_off_to_json(w, (const mscipc_imu_config_xtrig_on_off_t *)in);
        return;
    case MSCIPC_FIELD_IMU_CONFIG_XTRIG_ON_OFF_RESPONSE:
        mscipc_imu_config_xtrig_on_off_response_to_json(
            w, (const mscipc_imu_config_xtrig_on_off_response_t *)in);
        return;
    case MSCIPC_FIELD_IMU_CONFIG_SELECT_SENSORS_REV_B:
        mscipc_imu_config_select_sensors_rev_b_to_json(w,
                                                       (const mscipc_imu_config_select_sensors_rev_b_t *)in);
        return;
    case MSCIPC_FIELD_IMU_CONFIG_SELECT_SENSORS_REV_B_RESPONSE:
        mscipc_imu_config_select_sensors_rev_b_response_to_json(
            w, (const mscipc_imu_config_select_sensors_rev_b_response_t *)in);
        return;
    case MSCIPC_FIELD_IMU_CONFIG_AUX_ACCEL_RANGE:
        mscipc_imu_config_aux_accel_range_to_json(w, (const mscipc_imu_config_aux_accel_range_t *)in);
        return;
    case MSCIPC_FIELD_IMU_CONFIG_AUX_ACCEL_RANGE_RESPONSE:
        mscipc_imu_config_aux_accel_range_response_to_json(
            w, (const mscipc_imu_config_aux_accel_range_response_t *)in);
        return;
    case MSCIPC_FIELD_IMU_DATA_SCALED_ACCEL:
        mscipc_imu_data_scaled_accel_to_json(w, (const mscipc_imu_data_scaled_accel_t *)in);
        return;
    case MSCIPC_FIELD_IMU_DATA_SCALED_GYRO:
        mscipc_imu_data_scaled_gyro_to_json(w, (const mscipc_imu_data_scaled_gyro_t *)in);
        return;
    case MSCIPC_FIELD_IMU_DATA_SCALED_MAG:
        mscipc_imu_data_scaled_mag_to_json(w, (const mscipc_imu_data_scaled_mag_t *)in);
        return;
    case MSCIPC_FIELD_IMU_DATA_DELTA_THETA:
        mscipc_imu_data_delta_theta_to_json(w, (const mscipc_imu_data_delta_theta_t *)in);
        return;
    case MSCIPC_FIELD_IMU_DATA_DELTA_VELOCITY:
        mscipc_imu_data_delta_velocity_to_json(w, (const mscipc_imu_data_delta_velocity_t *)in);
        return;
    case MSCIPC_FIELD_IMU_DATA_SCALED_PRESSURE:
        mscipc_imu_data_scaled_pressure_to_json(w, (const mscipc_imu_data_scaled_pressure_t *)in);
        return;
    case MSCIPC_FIELD_IMU_DATA_SCALED_TEMPERATURE:
        mscipc_imu_data_scaled_temperature_to_json(w, (const mscipc_imu_data_scaled_temperature_t *)in);
        return;
    case MSCIPC_FIELD_IMU_DATA_GPS_CORRELATED_TIME:
        mscipc_imu_data_gps_correlated_time_to_json(w, (const mscipc_imu_data_gps_correlated_time_t *)in);
        return;
    case MSCIPC_FIELD_IMU_DATA_SCALED_AUX_ACCEL:
        mscipc_imu_data_scaled_aux_accel_to_json(w, (const mscipc_imu_data_scaled_aux_accel_t *)in);
        return;
    case MSCIPC_FIELD_NONE:
    case MSCIPC_FIELD_COUNT:
    default:
        mscipc_jw_lit(w, "null");
        return;
    }
}

int mscipc_value_from_json(mscipc_jr_t *jr, size_t pos, mscipc_field_id_t id, mscipc_field_value_t *value) {
    value->id = id;
    switch (id) {
    case MSCIPC_FIELD_ACK:
        return mscipc_ack_from_json(jr, pos, &value->u.ack);
    case MSCIPC_FIELD_BASE_PING:
        return mscipc_base_ping_from_json(jr, pos, &value->u.base_ping);
    case MSCIPC_FIELD_BASE_GET_DEVICE_MESSAGES:
        return mscipc_base_get_device_messages_from_json(jr, pos, &value->u.base_get_device_messages);
    case MSCIPC_FIELD_BASE_DEVICE_MESSAGES:
        return mscipc_base_device_messages_from_json(jr, pos, &value->u.base_device_messages);
    case MSCIPC_FIELD_BASE_DEVICE_RESET:
        return mscipc_base_device_reset_from_json(jr, pos, &value->u.base_device_reset);
    case MSCIPC_FIELD_BASE_GET_DEVICE_MODEL:
        return mscipc_base_get_device_model_from_json(jr, pos, &value->u.base_get_device_model);
    case MSCIPC_FIELD_BASE_DEVICE_MODEL:
        return mscipc_base_device_model_from_json(jr, pos, &value->u.base_device_model);
    case MSCIPC_FIELD_BASE_GET_DEVICE_SN:
        return mscipc_base_get_device_sn_from_json(jr, pos, &value->u.base_get_device_sn);
    case MSCIPC_FIELD_BASE_DEVICE_SN:
        return mscipc_base_device_sn_from_json(jr, pos, &value->u.base_device_sn);
    case MSCIPC_FIELD_BASE_GET_DEVICE_FW:
        return mscipc_base_get_device_fw_from_json(jr, pos, &value->u.base_get_device_fw);
    case MSCIPC_FIELD_BASE_DEVICE_FW:
        return mscipc_base_device_fw_from_json(jr, pos, &value->u.base_device_fw);
    case MSCIPC_FIELD_BASE_GET_DEVICE_CAL:
        return mscipc_base_get_device_cal_from_json(jr, pos, &value->u.base_get_device_cal);
    case MSCIPC_FIELD_BASE_DEVICE_CAL:
        return mscipc_base_device_cal_from_json(jr, pos, &value->u.base_device_cal);
    case MSCIPC_FIELD_BASE_CORRELATE_GPS_TIME:
        return mscipc_base_correlate_gps_time_from_json(jr, pos, &value->u.base_correlate_gps_time);
    case MSCIPC_FIELD_IMU_CONFIG_UART_BAUD_RATE:
        return mscipc_imu_config_uart_baud_rate_from_json(jr, pos, &value->u.imu_config_uart_baud_rate);
    case MSCIPC_FIELD_IMU_CONFIG_UART_BAUD_RATE_RESPONSE:
        return mscipc_imu_config_uart_baud_rate_response_from_json(
            jr, pos, &value->u.imu_config_uart_baud_rate_response);
    case MSCIPC_FIELD_IMU_CONFIG_FILTER:
        return mscipc_imu_config_filter_from_json(jr, pos, &value->u.imu_config_filter);
    case MSCIPC_FIELD_IMU_CONFIG_FILTER_RESPONSE:
        return mscipc_imu_config_filter_response_from_json(jr, pos, &value->u.imu_config_filter_response);
    case MSCIPC_FIELD_IMU_CONFIG_SAMPLE_RATE:
        return mscipc_imu_config_sample_rate_from_json(jr, pos, &value->u.imu_config_sample_rate);
    case MSCIPC_FIELD_IMU_CONFIG_SAMPLE_RATE_RESPONSE:
        return mscipc_imu_config_sample_rate_response_from_json(jr, pos,
                                                                &value->u.imu_config_sample_rate_response);
    case MSCIPC_FIELD_IMU_CONFIG_SELECT_SENSORS:
        return mscipc_imu_config_select_sensors_from_json(jr, pos, &value->u.imu_config_select_sensors);
    case MSCIPC_FIELD_IMU_CONFIG_SELECT_SENSORS_RESPONSE:
        return mscipc_imu_config_select_sensors_response_from_json(
            jr, pos, &value->u.imu_config_select_sensors_response);
    case MSCIPC_FIELD_IMU_CONFIG_GET_INTERNAL_SAMPLE_RATE:
        return mscipc_imu_config_get_internal_sample_rate_from_json(
            jr, pos, &value->u.imu_config_get_internal_sample_rate);
    case MSCIPC_FIELD_IMU_CONFIG_INTERNAL_SAMPLE_RATE:
        return mscipc_imu_config_internal_sample_rate_from_json(jr, pos,
                                                                &value->u.imu_config_internal_sample_rate);
    case MSCIPC_FIELD_IMU_CONFIG_ACCEL_RANGE:
        return mscipc_imu_config_accel_range_from_json(jr, pos, &value->u.imu_config_accel_range);
    case MSCIPC_FIELD_IMU_CONFIG_ACCEL_RANGE_RESPONSE:
        return mscipc_imu_config_accel_range_response_from_json(jr, pos,
                                                                &value->u.imu_config_accel_range_response);
    case MSCIPC_FIELD_IMU_CONFIG_GYRO_RANGE:
        return mscipc_imu_config_gyro_range_from_json(jr, pos, &value->u.imu_config_gyro_range);
    case MSCIPC_FIELD_IMU_CONFIG_GYRO_RANGE_RESPONSE:
        return mscipc_imu_config_gyro_range_response_from_json(jr, pos,
                                                               &value->u.imu_config_gyro_range_response);
    case MSCIPC_FIELD_IMU_CONFIG_CONFIG_ALL:
        return mscipc_imu_config_config_all_from_json(jr, pos, &value->u.imu_config_config_all);
    case MSCIPC_FIELD_IMU_CONFIG_DATA_ON_OFF:
        return mscipc_imu_config_data_on_off_from_json(jr, pos, &value->u.imu_config_data_on_off);
    case MSCIPC_FIELD_IMU_CONFIG_DATA_ON_OFF_RESPONSE:
        return mscipc_imu_config_data_on_off_response_from_json(jr, pos,
                                                                &value->u.imu_config_data_on_off_response);
    case MSCIPC_FIELD_IMU_CONFIG_XTRIG_ON_OFF:
        return mscipc_imu_config_xtrig_on_off_from_json(jr, pos, &value->u.imu_config_xtrig_on_off);
    case MSCIPC_FIELD_IMU_CONFIG_XTRIG_ON_OFF_RESPONSE:
        return mscipc_imu_config_xtrig_on_off_response_from_json(jr, pos,
                                                                 &value->u.imu_config_xtrig_on_off_response);
    case MSCIPC_FIELD_IMU_CONFIG_SELECT_SENSORS_REV_B:
        return mscipc_imu_config_select_sensors_rev_b_from_json(jr, pos,
                                                                &value->u.imu_config_select_sensors_rev_b);
    case MSCIPC_FIELD_IMU_CONFIG_SELECT_SENSORS_REV_B_RESPONSE:
        return mscipc_imu_config_select_sensors_rev_b_response_from_json(
            jr, pos, &value->u.imu_config_select_sensors_rev_b_response);
    case MSCIPC_FIELD_IMU_CONFIG_AUX_ACCEL_RANGE:
        return mscipc_imu_config_aux_accel_range_from_json(jr, pos, &value->u.imu_config_aux_accel_range);
    case MSCIPC_FIELD_IMU_CONFIG_AUX_ACCEL_RANGE_RESPONSE:
        return mscipc_imu_config_aux_accel_range_response_from_json(
            jr, pos, &value->u.imu_config_aux_accel_range_response);
    case MSCIPC_FIELD_IMU_DATA_SCALED_ACCEL:
        return mscipc_imu_data_scaled_accel_from_json(jr, pos, &value->u.imu_data_scaled_accel);
    case MSCIPC_FIELD_IMU_DATA_SCALED_GYRO:
        return mscipc_imu_data_scaled_gyro_from_json(jr, pos, &value->u.imu_data_scaled_gyro);
    case MSCIPC_FIELD_IMU_DATA_SCALED_MAG:
        return mscipc_imu_data_scaled_mag_from_json(jr, pos, &value->u.imu_data_scaled_mag);
    case MSCIPC_FIELD_IMU_DATA_DELTA_THETA:
        return mscipc_imu_data_delta_theta_from_json(jr, pos, &value->u.imu_data_delta_theta);
    case MSCIPC_FIELD_IMU_DATA_DELTA_VELOCITY:
        return mscipc_imu_data_delta_velocity_from_json(jr, pos, &value->u.imu_data_delta_velocity);
    case MSCIPC_FIELD_IMU_DATA_SCALED_PRESSURE:
        return mscipc_imu_data_scaled_pressure_from_json(jr, pos, &value->u.imu_data_scaled_pressure);
    case MSCIPC_FIELD_IMU_DATA_SCALED_TEMPERATURE:
        return mscipc_imu_data_scaled_temperature_from_json(jr, pos, &value->u.imu_data_scaled_temperature);
    case MSCIPC_FIELD_IMU_DATA_GPS_CORRELATED_TIME:
        return mscipc_imu_data_gps_correlated_time_from_json(jr, pos, &value->u.imu_data_gps_correlated_time);
    case MSCIPC_FIELD_IMU_DATA_SCALED_AUX_ACCEL:
        return mscipc_imu_data_scaled_aux_accel_from_json(jr, pos, &value->u.imu_data_scaled_aux_accel);
    case MSCIPC_FIELD_NONE:
    case MSCIPC_FIELD_COUNT:
    default:
        (void)pos;
        return mscipc_jr_fail(jr, "no such field layout");
    }
}
