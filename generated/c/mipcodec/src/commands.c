/* The typed command API of MicroStrain MIP (mipcodec/commands.h). Generated: do not edit. */
#include "mipcodec/commands.h"

#include <string.h>

mipc_result_kind_t mipc_base_ping(mipc_link_t *link) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_BASE_PING;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_base_set_to_idle(mipc_link_t *link) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_BASE_SET_TO_IDLE;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_base_get_device_info(mipc_link_t *link, mipc_base_device_info_t *reply) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    mipc_result_t result_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_BASE_GET_DEVICE_INFO;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, &result_);
    if (kind_ == MIPC_RESULT_ACK && reply != NULL) {
        mipc_field_entry_t entry_;
        if (!mipc_result_reply_entry(&result_, &entry_) || entry_.descriptor != 0x81 ||
            mipc_base_device_info_decode(entry_.data, entry_.length, reply, NULL) != MIPC_OK) {
            return mipc_link_fail(link, MIPC_RESULT_INVALID, "missing reply field 0x81");
        }
    }
    return kind_;
}

mipc_result_kind_t mipc_base_get_device_descriptors(mipc_link_t *link,
                                                    mipc_base_device_descriptors_t *reply) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    mipc_result_t result_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_BASE_GET_DEVICE_DESCRIPTORS;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, &result_);
    if (kind_ == MIPC_RESULT_ACK && reply != NULL) {
        mipc_field_entry_t entry_;
        if (!mipc_result_reply_entry(&result_, &entry_) || entry_.descriptor != 0x82 ||
            mipc_base_device_descriptors_decode(entry_.data, entry_.length, reply, NULL) != MIPC_OK) {
            return mipc_link_fail(link, MIPC_RESULT_INVALID, "missing reply field 0x82");
        }
    }
    return kind_;
}

mipc_result_kind_t mipc_base_built_in_test(mipc_link_t *link, mipc_field_value_t *reply) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    mipc_result_t result_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_BASE_BUILT_IN_TEST;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, &result_);
    if (kind_ == MIPC_RESULT_ACK && reply != NULL) {
        if (mipc_link_reply(link, &result_, reply) != MIPC_OK) {
            return mipc_link_fail(link, MIPC_RESULT_INVALID, "the reply field does not decode");
        }
    }
    return kind_;
}

mipc_result_kind_t mipc_base_resume(mipc_link_t *link) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_BASE_RESUME;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_base_get_extended_descriptors(mipc_link_t *link,
                                                      mipc_base_extended_descriptors_t *reply) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    mipc_result_t result_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_BASE_GET_EXTENDED_DESCRIPTORS;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, &result_);
    if (kind_ == MIPC_RESULT_ACK && reply != NULL) {
        mipc_field_entry_t entry_;
        if (!mipc_result_reply_entry(&result_, &entry_) || entry_.descriptor != 0x86 ||
            mipc_base_extended_descriptors_decode(entry_.data, entry_.length, reply, NULL) != MIPC_OK) {
            return mipc_link_fail(link, MIPC_RESULT_INVALID, "missing reply field 0x86");
        }
    }
    return kind_;
}

mipc_result_kind_t mipc_base_continuous_bit(mipc_link_t *link, mipc_base_continuous_bit_result_t *reply) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    mipc_result_t result_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_BASE_CONTINUOUS_BIT;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, &result_);
    if (kind_ == MIPC_RESULT_ACK && reply != NULL) {
        mipc_field_entry_t entry_;
        if (!mipc_result_reply_entry(&result_, &entry_) || entry_.descriptor != 0x88 ||
            mipc_base_continuous_bit_result_decode(entry_.data, entry_.length, reply, NULL) != MIPC_OK) {
            return mipc_link_fail(link, MIPC_RESULT_INVALID, "missing reply field 0x88");
        }
    }
    return kind_;
}

mipc_result_kind_t mipc_base_comm_port_speed_write(mipc_link_t *link, uint8_t port, uint32_t baud) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_BASE_COMM_PORT_SPEED;
        cmd_.u.base_comm_port_speed.function = MIPC_FUNCTION_SELECTOR_WRITE;
        cmd_.u.base_comm_port_speed.port = port;
        cmd_.u.base_comm_port_speed.has_baud = true;
        cmd_.u.base_comm_port_speed.baud = baud;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_base_comm_port_speed_read(mipc_link_t *link, uint8_t port,
                                                  mipc_base_comm_port_speed_response_t *reply) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    mipc_result_t result_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_BASE_COMM_PORT_SPEED;
        cmd_.u.base_comm_port_speed.function = MIPC_FUNCTION_SELECTOR_READ;
        cmd_.u.base_comm_port_speed.port = port;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, &result_);
    if (kind_ == MIPC_RESULT_ACK && reply != NULL) {
        mipc_field_entry_t entry_;
        if (!mipc_result_reply_entry(&result_, &entry_) || entry_.descriptor != 0x89 ||
            mipc_base_comm_port_speed_response_decode(entry_.data, entry_.length, reply, NULL) != MIPC_OK) {
            return mipc_link_fail(link, MIPC_RESULT_INVALID, "missing reply field 0x89");
        }
    }
    return kind_;
}

mipc_result_kind_t mipc_base_comm_port_speed_save(mipc_link_t *link, uint8_t port) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_BASE_COMM_PORT_SPEED;
        cmd_.u.base_comm_port_speed.function = MIPC_FUNCTION_SELECTOR_SAVE;
        cmd_.u.base_comm_port_speed.port = port;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_base_comm_port_speed_load(mipc_link_t *link, uint8_t port) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_BASE_COMM_PORT_SPEED;
        cmd_.u.base_comm_port_speed.function = MIPC_FUNCTION_SELECTOR_LOAD;
        cmd_.u.base_comm_port_speed.port = port;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_base_comm_port_speed_default(mipc_link_t *link, uint8_t port) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_BASE_COMM_PORT_SPEED;
        cmd_.u.base_comm_port_speed.function = MIPC_FUNCTION_SELECTOR_DEFAULT;
        cmd_.u.base_comm_port_speed.port = port;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_base_gps_time_update_write(mipc_link_t *link, mipc_gps_time_field_t field_id,
                                                   uint32_t value) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    switch (link->session.config.device) {
    case MIPC_DEVICE_CV7_INS:
        cmd_.id = MIPC_FIELD_BASE_GPS_TIME_UPDATE_CV7_INS;
        cmd_.u.base_gps_time_update_cv7_ins.function = MIPC_FUNCTION_SELECTOR_WRITE;
        cmd_.u.base_gps_time_update_cv7_ins.field_id = field_id;
        cmd_.u.base_gps_time_update_cv7_ins.value = value;
        break;
    default:
        cmd_.id = MIPC_FIELD_BASE_GPS_TIME_UPDATE_GX5_45;
        cmd_.u.base_gps_time_update_gx5_45.function = MIPC_FUNCTION_SELECTOR_WRITE;
        cmd_.u.base_gps_time_update_gx5_45.field_id = field_id;
        cmd_.u.base_gps_time_update_gx5_45.has_value = true;
        cmd_.u.base_gps_time_update_gx5_45.value = value;
        break;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_base_gps_time_update_read(mipc_link_t *link, mipc_gps_time_field_t field_id,
                                                  mipc_field_value_t *reply) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    mipc_result_t result_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_BASE_GPS_TIME_UPDATE_GX5_45;
        cmd_.u.base_gps_time_update_gx5_45.function = MIPC_FUNCTION_SELECTOR_READ;
        cmd_.u.base_gps_time_update_gx5_45.field_id = field_id;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, &result_);
    if (kind_ == MIPC_RESULT_ACK && reply != NULL) {
        if (mipc_link_reply(link, &result_, reply) != MIPC_OK) {
            return mipc_link_fail(link, MIPC_RESULT_INVALID, "the reply field does not decode");
        }
    }
    return kind_;
}

mipc_result_kind_t mipc_base_gps_time_update_write_no_ack(mipc_link_t *link, mipc_gps_time_field_t field_id,
                                                          uint32_t value) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_BASE_GPS_TIME_UPDATE_GX5_45;
        cmd_.u.base_gps_time_update_gx5_45.function = MIPC_FUNCTION_SELECTOR_WRITE_NO_ACK;
        cmd_.u.base_gps_time_update_gx5_45.field_id = field_id;
        cmd_.u.base_gps_time_update_gx5_45.has_value = true;
        cmd_.u.base_gps_time_update_gx5_45.value = value;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_base_device_reset(mipc_link_t *link) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_BASE_DEVICE_RESET;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_threedm_event_control_write(mipc_link_t *link, uint8_t instance,
                                                    mipc_event_control_mode_t mode) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_THREEDM_EVENT_CONTROL;
        cmd_.u.threedm_event_control.function = MIPC_FUNCTION_SELECTOR_WRITE;
        cmd_.u.threedm_event_control.instance = instance;
        cmd_.u.threedm_event_control.has_mode = true;
        cmd_.u.threedm_event_control.mode = mode;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_threedm_event_control_read(mipc_link_t *link, uint8_t instance,
                                                   mipc_threedm_event_control_response_t *reply) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    mipc_result_t result_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_THREEDM_EVENT_CONTROL;
        cmd_.u.threedm_event_control.function = MIPC_FUNCTION_SELECTOR_READ;
        cmd_.u.threedm_event_control.instance = instance;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, &result_);
    if (kind_ == MIPC_RESULT_ACK && reply != NULL) {
        mipc_field_entry_t entry_;
        if (!mipc_result_reply_entry(&result_, &entry_) || entry_.descriptor != 0xB5 ||
            mipc_threedm_event_control_response_decode(entry_.data, entry_.length, reply, NULL) != MIPC_OK) {
            return mipc_link_fail(link, MIPC_RESULT_INVALID, "missing reply field 0xB5");
        }
    }
    return kind_;
}

mipc_result_kind_t mipc_threedm_event_control_save(mipc_link_t *link, uint8_t instance) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_THREEDM_EVENT_CONTROL;
        cmd_.u.threedm_event_control.function = MIPC_FUNCTION_SELECTOR_SAVE;
        cmd_.u.threedm_event_control.instance = instance;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_threedm_event_control_load(mipc_link_t *link, uint8_t instance) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_THREEDM_EVENT_CONTROL;
        cmd_.u.threedm_event_control.function = MIPC_FUNCTION_SELECTOR_LOAD;
        cmd_.u.threedm_event_control.instance = instance;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_threedm_event_control_default(mipc_link_t *link, uint8_t instance) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_THREEDM_EVENT_CONTROL;
        cmd_.u.threedm_event_control.function = MIPC_FUNCTION_SELECTOR_DEFAULT;
        cmd_.u.threedm_event_control.instance = instance;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_threedm_get_event_trigger_status(mipc_link_t *link,
                                                         const uint8_t *requested_instances,
                                                         size_t requested_instances_count,
                                                         mipc_threedm_event_trigger_status_t *reply) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    mipc_result_t result_;
    if (requested_instances_count > 252u) {
        return mipc_link_fail(link, MIPC_RESULT_REFUSED, "requested_instances: more than 252 elements");
    }
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_THREEDM_GET_EVENT_TRIGGER_STATUS;
        if (requested_instances_count > 0) {
            memcpy(cmd_.u.threedm_get_event_trigger_status.requested_instances, requested_instances,
                   requested_instances_count *
                       sizeof cmd_.u.threedm_get_event_trigger_status.requested_instances[0]);
        }
        cmd_.u.threedm_get_event_trigger_status.requested_count = (uint8_t)requested_instances_count;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, &result_);
    if (kind_ == MIPC_RESULT_ACK && reply != NULL) {
        mipc_field_entry_t entry_;
        if (!mipc_result_reply_entry(&result_, &entry_) || entry_.descriptor != 0xB6 ||
            mipc_threedm_event_trigger_status_decode(entry_.data, entry_.length, reply, NULL) != MIPC_OK) {
            return mipc_link_fail(link, MIPC_RESULT_INVALID, "missing reply field 0xB6");
        }
    }
    return kind_;
}

mipc_result_kind_t mipc_threedm_get_event_action_status(mipc_link_t *link, const uint8_t *requested_instances,
                                                        size_t requested_instances_count,
                                                        mipc_threedm_event_action_status_t *reply) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    mipc_result_t result_;
    if (requested_instances_count > 252u) {
        return mipc_link_fail(link, MIPC_RESULT_REFUSED, "requested_instances: more than 252 elements");
    }
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_THREEDM_GET_EVENT_ACTION_STATUS;
        if (requested_instances_count > 0) {
            memcpy(cmd_.u.threedm_get_event_action_status.requested_instances, requested_instances,
                   requested_instances_count *
                       sizeof cmd_.u.threedm_get_event_action_status.requested_instances[0]);
        }
        cmd_.u.threedm_get_event_action_status.requested_count = (uint8_t)requested_instances_count;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, &result_);
    if (kind_ == MIPC_RESULT_ACK && reply != NULL) {
        mipc_field_entry_t entry_;
        if (!mipc_result_reply_entry(&result_, &entry_) || entry_.descriptor != 0xB7 ||
            mipc_threedm_event_action_status_decode(entry_.data, entry_.length, reply, NULL) != MIPC_OK) {
            return mipc_link_fail(link, MIPC_RESULT_INVALID, "missing reply field 0xB7");
        }
    }
    return kind_;
}

mipc_result_kind_t mipc_threedm_event_trigger_config_write(mipc_link_t *link, uint8_t instance,
                                                           mipc_trigger_type_t type,
                                                           const mipc_trigger_params_t *parameters) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_THREEDM_EVENT_TRIGGER_CONFIG;
        cmd_.u.threedm_event_trigger_config.function = MIPC_FUNCTION_SELECTOR_WRITE;
        cmd_.u.threedm_event_trigger_config.instance = instance;
        cmd_.u.threedm_event_trigger_config.has_type = true;
        cmd_.u.threedm_event_trigger_config.type = type;
        cmd_.u.threedm_event_trigger_config.has_parameters = true;
        cmd_.u.threedm_event_trigger_config.parameters = *parameters;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t
mipc_threedm_event_trigger_config_read(mipc_link_t *link, uint8_t instance,
                                       mipc_threedm_event_trigger_config_response_t *reply) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    mipc_result_t result_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_THREEDM_EVENT_TRIGGER_CONFIG;
        cmd_.u.threedm_event_trigger_config.function = MIPC_FUNCTION_SELECTOR_READ;
        cmd_.u.threedm_event_trigger_config.instance = instance;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, &result_);
    if (kind_ == MIPC_RESULT_ACK && reply != NULL) {
        mipc_field_entry_t entry_;
        if (!mipc_result_reply_entry(&result_, &entry_) || entry_.descriptor != 0xB8 ||
            mipc_threedm_event_trigger_config_response_decode(entry_.data, entry_.length, reply, NULL) !=
                MIPC_OK) {
            return mipc_link_fail(link, MIPC_RESULT_INVALID, "missing reply field 0xB8");
        }
    }
    return kind_;
}

mipc_result_kind_t mipc_threedm_event_trigger_config_save(mipc_link_t *link, uint8_t instance) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_THREEDM_EVENT_TRIGGER_CONFIG;
        cmd_.u.threedm_event_trigger_config.function = MIPC_FUNCTION_SELECTOR_SAVE;
        cmd_.u.threedm_event_trigger_config.instance = instance;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_threedm_event_trigger_config_load(mipc_link_t *link, uint8_t instance) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_THREEDM_EVENT_TRIGGER_CONFIG;
        cmd_.u.threedm_event_trigger_config.function = MIPC_FUNCTION_SELECTOR_LOAD;
        cmd_.u.threedm_event_trigger_config.instance = instance;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_threedm_event_trigger_config_default(mipc_link_t *link, uint8_t instance) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_THREEDM_EVENT_TRIGGER_CONFIG;
        cmd_.u.threedm_event_trigger_config.function = MIPC_FUNCTION_SELECTOR_DEFAULT;
        cmd_.u.threedm_event_trigger_config.instance = instance;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_threedm_event_action_config_write(mipc_link_t *link, uint8_t instance,
                                                          uint8_t trigger, mipc_action_type_t type,
                                                          const mipc_action_params_t *parameters) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_THREEDM_EVENT_ACTION_CONFIG;
        cmd_.u.threedm_event_action_config.function = MIPC_FUNCTION_SELECTOR_WRITE;
        cmd_.u.threedm_event_action_config.instance = instance;
        cmd_.u.threedm_event_action_config.has_trigger = true;
        cmd_.u.threedm_event_action_config.trigger = trigger;
        cmd_.u.threedm_event_action_config.has_type = true;
        cmd_.u.threedm_event_action_config.type = type;
        cmd_.u.threedm_event_action_config.has_parameters = true;
        cmd_.u.threedm_event_action_config.parameters = *parameters;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_threedm_event_action_config_read(mipc_link_t *link, uint8_t instance,
                                                         mipc_threedm_event_action_config_response_t *reply) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    mipc_result_t result_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_THREEDM_EVENT_ACTION_CONFIG;
        cmd_.u.threedm_event_action_config.function = MIPC_FUNCTION_SELECTOR_READ;
        cmd_.u.threedm_event_action_config.instance = instance;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, &result_);
    if (kind_ == MIPC_RESULT_ACK && reply != NULL) {
        mipc_field_entry_t entry_;
        if (!mipc_result_reply_entry(&result_, &entry_) || entry_.descriptor != 0xB9 ||
            mipc_threedm_event_action_config_response_decode(entry_.data, entry_.length, reply, NULL) !=
                MIPC_OK) {
            return mipc_link_fail(link, MIPC_RESULT_INVALID, "missing reply field 0xB9");
        }
    }
    return kind_;
}

mipc_result_kind_t mipc_threedm_event_action_config_save(mipc_link_t *link, uint8_t instance) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_THREEDM_EVENT_ACTION_CONFIG;
        cmd_.u.threedm_event_action_config.function = MIPC_FUNCTION_SELECTOR_SAVE;
        cmd_.u.threedm_event_action_config.instance = instance;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_threedm_event_action_config_load(mipc_link_t *link, uint8_t instance) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_THREEDM_EVENT_ACTION_CONFIG;
        cmd_.u.threedm_event_action_config.function = MIPC_FUNCTION_SELECTOR_LOAD;
        cmd_.u.threedm_event_action_config.instance = instance;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_threedm_event_action_config_default(mipc_link_t *link, uint8_t instance) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_THREEDM_EVENT_ACTION_CONFIG;
        cmd_.u.threedm_event_action_config.function = MIPC_FUNCTION_SELECTOR_DEFAULT;
        cmd_.u.threedm_event_action_config.instance = instance;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_threedm_device_startup_settings_read(mipc_link_t *link) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_THREEDM_DEVICE_STARTUP_SETTINGS_GX5_45;
        cmd_.u.threedm_device_startup_settings_gx5_45.function = MIPC_FUNCTION_SELECTOR_READ;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_threedm_device_startup_settings_save(mipc_link_t *link) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    switch (link->session.config.device) {
    case MIPC_DEVICE_CV7_INS:
        cmd_.id = MIPC_FIELD_THREEDM_DEVICE_STARTUP_SETTINGS_CV7_INS;
        cmd_.u.threedm_device_startup_settings_cv7_ins.function = MIPC_FUNCTION_SELECTOR_SAVE;
        break;
    default:
        cmd_.id = MIPC_FIELD_THREEDM_DEVICE_STARTUP_SETTINGS_GX5_45;
        cmd_.u.threedm_device_startup_settings_gx5_45.function = MIPC_FUNCTION_SELECTOR_SAVE;
        break;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_threedm_device_startup_settings_load(mipc_link_t *link) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    switch (link->session.config.device) {
    case MIPC_DEVICE_CV7_INS:
        cmd_.id = MIPC_FIELD_THREEDM_DEVICE_STARTUP_SETTINGS_CV7_INS;
        cmd_.u.threedm_device_startup_settings_cv7_ins.function = MIPC_FUNCTION_SELECTOR_LOAD;
        break;
    default:
        cmd_.id = MIPC_FIELD_THREEDM_DEVICE_STARTUP_SETTINGS_GX5_45;
        cmd_.u.threedm_device_startup_settings_gx5_45.function = MIPC_FUNCTION_SELECTOR_LOAD;
        break;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_threedm_device_startup_settings_default(mipc_link_t *link) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    switch (link->session.config.device) {
    case MIPC_DEVICE_CV7_INS:
        cmd_.id = MIPC_FIELD_THREEDM_DEVICE_STARTUP_SETTINGS_CV7_INS;
        cmd_.u.threedm_device_startup_settings_cv7_ins.function = MIPC_FUNCTION_SELECTOR_DEFAULT;
        break;
    default:
        cmd_.id = MIPC_FIELD_THREEDM_DEVICE_STARTUP_SETTINGS_GX5_45;
        cmd_.u.threedm_device_startup_settings_gx5_45.function = MIPC_FUNCTION_SELECTOR_DEFAULT;
        break;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_threedm_sensor_to_vehicle_euler_write(mipc_link_t *link, float roll, float pitch,
                                                              float yaw) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_THREEDM_SENSOR_TO_VEHICLE_EULER;
        cmd_.u.threedm_sensor_to_vehicle_euler.function = MIPC_FUNCTION_SELECTOR_WRITE;
        cmd_.u.threedm_sensor_to_vehicle_euler.has_roll = true;
        cmd_.u.threedm_sensor_to_vehicle_euler.roll = roll;
        cmd_.u.threedm_sensor_to_vehicle_euler.has_pitch = true;
        cmd_.u.threedm_sensor_to_vehicle_euler.pitch = pitch;
        cmd_.u.threedm_sensor_to_vehicle_euler.has_yaw = true;
        cmd_.u.threedm_sensor_to_vehicle_euler.yaw = yaw;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t
mipc_threedm_sensor_to_vehicle_euler_read(mipc_link_t *link,
                                          mipc_threedm_sensor_to_vehicle_euler_response_t *reply) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    mipc_result_t result_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_THREEDM_SENSOR_TO_VEHICLE_EULER;
        cmd_.u.threedm_sensor_to_vehicle_euler.function = MIPC_FUNCTION_SELECTOR_READ;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, &result_);
    if (kind_ == MIPC_RESULT_ACK && reply != NULL) {
        mipc_field_entry_t entry_;
        if (!mipc_result_reply_entry(&result_, &entry_) || entry_.descriptor != 0xB1 ||
            mipc_threedm_sensor_to_vehicle_euler_response_decode(entry_.data, entry_.length, reply, NULL) !=
                MIPC_OK) {
            return mipc_link_fail(link, MIPC_RESULT_INVALID, "missing reply field 0xB1");
        }
    }
    return kind_;
}

mipc_result_kind_t mipc_threedm_sensor_to_vehicle_euler_save(mipc_link_t *link) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_THREEDM_SENSOR_TO_VEHICLE_EULER;
        cmd_.u.threedm_sensor_to_vehicle_euler.function = MIPC_FUNCTION_SELECTOR_SAVE;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_threedm_sensor_to_vehicle_euler_load(mipc_link_t *link) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_THREEDM_SENSOR_TO_VEHICLE_EULER;
        cmd_.u.threedm_sensor_to_vehicle_euler.function = MIPC_FUNCTION_SELECTOR_LOAD;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_threedm_sensor_to_vehicle_euler_default(mipc_link_t *link) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_THREEDM_SENSOR_TO_VEHICLE_EULER;
        cmd_.u.threedm_sensor_to_vehicle_euler.function = MIPC_FUNCTION_SELECTOR_DEFAULT;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_threedm_sensor_to_vehicle_quaternion_write(mipc_link_t *link, const float q[4]) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_THREEDM_SENSOR_TO_VEHICLE_QUATERNION;
        cmd_.u.threedm_sensor_to_vehicle_quaternion.function = MIPC_FUNCTION_SELECTOR_WRITE;
        cmd_.u.threedm_sensor_to_vehicle_quaternion.has_q = true;
        memcpy(cmd_.u.threedm_sensor_to_vehicle_quaternion.q, q,
               sizeof cmd_.u.threedm_sensor_to_vehicle_quaternion.q);
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t
mipc_threedm_sensor_to_vehicle_quaternion_read(mipc_link_t *link,
                                               mipc_threedm_sensor_to_vehicle_quaternion_response_t *reply) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    mipc_result_t result_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_THREEDM_SENSOR_TO_VEHICLE_QUATERNION;
        cmd_.u.threedm_sensor_to_vehicle_quaternion.function = MIPC_FUNCTION_SELECTOR_READ;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, &result_);
    if (kind_ == MIPC_RESULT_ACK && reply != NULL) {
        mipc_field_entry_t entry_;
        if (!mipc_result_reply_entry(&result_, &entry_) || entry_.descriptor != 0xB2 ||
            mipc_threedm_sensor_to_vehicle_quaternion_response_decode(entry_.data, entry_.length, reply,
                                                                      NULL) != MIPC_OK) {
            return mipc_link_fail(link, MIPC_RESULT_INVALID, "missing reply field 0xB2");
        }
    }
    return kind_;
}

mipc_result_kind_t mipc_threedm_sensor_to_vehicle_quaternion_save(mipc_link_t *link) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_THREEDM_SENSOR_TO_VEHICLE_QUATERNION;
        cmd_.u.threedm_sensor_to_vehicle_quaternion.function = MIPC_FUNCTION_SELECTOR_SAVE;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_threedm_sensor_to_vehicle_quaternion_load(mipc_link_t *link) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_THREEDM_SENSOR_TO_VEHICLE_QUATERNION;
        cmd_.u.threedm_sensor_to_vehicle_quaternion.function = MIPC_FUNCTION_SELECTOR_LOAD;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_threedm_sensor_to_vehicle_quaternion_default(mipc_link_t *link) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_THREEDM_SENSOR_TO_VEHICLE_QUATERNION;
        cmd_.u.threedm_sensor_to_vehicle_quaternion.function = MIPC_FUNCTION_SELECTOR_DEFAULT;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_threedm_sensor_to_vehicle_dcm_write(mipc_link_t *link, const float dcm[9]) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_THREEDM_SENSOR_TO_VEHICLE_DCM;
        cmd_.u.threedm_sensor_to_vehicle_dcm.function = MIPC_FUNCTION_SELECTOR_WRITE;
        cmd_.u.threedm_sensor_to_vehicle_dcm.has_dcm = true;
        memcpy(cmd_.u.threedm_sensor_to_vehicle_dcm.dcm, dcm,
               sizeof cmd_.u.threedm_sensor_to_vehicle_dcm.dcm);
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t
mipc_threedm_sensor_to_vehicle_dcm_read(mipc_link_t *link,
                                        mipc_threedm_sensor_to_vehicle_dcm_response_t *reply) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    mipc_result_t result_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_THREEDM_SENSOR_TO_VEHICLE_DCM;
        cmd_.u.threedm_sensor_to_vehicle_dcm.function = MIPC_FUNCTION_SELECTOR_READ;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, &result_);
    if (kind_ == MIPC_RESULT_ACK && reply != NULL) {
        mipc_field_entry_t entry_;
        if (!mipc_result_reply_entry(&result_, &entry_) || entry_.descriptor != 0xB3 ||
            mipc_threedm_sensor_to_vehicle_dcm_response_decode(entry_.data, entry_.length, reply, NULL) !=
                MIPC_OK) {
            return mipc_link_fail(link, MIPC_RESULT_INVALID, "missing reply field 0xB3");
        }
    }
    return kind_;
}

mipc_result_kind_t mipc_threedm_sensor_to_vehicle_dcm_save(mipc_link_t *link) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_THREEDM_SENSOR_TO_VEHICLE_DCM;
        cmd_.u.threedm_sensor_to_vehicle_dcm.function = MIPC_FUNCTION_SELECTOR_SAVE;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_threedm_sensor_to_vehicle_dcm_load(mipc_link_t *link) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_THREEDM_SENSOR_TO_VEHICLE_DCM;
        cmd_.u.threedm_sensor_to_vehicle_dcm.function = MIPC_FUNCTION_SELECTOR_LOAD;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_threedm_sensor_to_vehicle_dcm_default(mipc_link_t *link) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_THREEDM_SENSOR_TO_VEHICLE_DCM;
        cmd_.u.threedm_sensor_to_vehicle_dcm.function = MIPC_FUNCTION_SELECTOR_DEFAULT;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_threedm_accel_bias_write(mipc_link_t *link, const float bias[3]) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    switch (link->session.config.device) {
    case MIPC_DEVICE_CV7_INS:
        cmd_.id = MIPC_FIELD_THREEDM_ACCEL_BIAS_CV7_INS;
        cmd_.u.threedm_accel_bias_cv7_ins.function = MIPC_FUNCTION_SELECTOR_WRITE;
        cmd_.u.threedm_accel_bias_cv7_ins.has_bias = true;
        memcpy(cmd_.u.threedm_accel_bias_cv7_ins.bias, bias, sizeof cmd_.u.threedm_accel_bias_cv7_ins.bias);
        break;
    default:
        cmd_.id = MIPC_FIELD_THREEDM_ACCEL_BIAS_GX5_45;
        cmd_.u.threedm_accel_bias_gx5_45.function = MIPC_FUNCTION_SELECTOR_WRITE;
        cmd_.u.threedm_accel_bias_gx5_45.has_bias = true;
        memcpy(cmd_.u.threedm_accel_bias_gx5_45.bias, bias, sizeof cmd_.u.threedm_accel_bias_gx5_45.bias);
        break;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_threedm_accel_bias_read(mipc_link_t *link,
                                                mipc_threedm_accel_bias_response_t *reply) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    mipc_result_t result_;
    memset(&cmd_, 0, sizeof cmd_);
    switch (link->session.config.device) {
    case MIPC_DEVICE_CV7_INS:
        cmd_.id = MIPC_FIELD_THREEDM_ACCEL_BIAS_CV7_INS;
        cmd_.u.threedm_accel_bias_cv7_ins.function = MIPC_FUNCTION_SELECTOR_READ;
        break;
    default:
        cmd_.id = MIPC_FIELD_THREEDM_ACCEL_BIAS_GX5_45;
        cmd_.u.threedm_accel_bias_gx5_45.function = MIPC_FUNCTION_SELECTOR_READ;
        break;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, &result_);
    if (kind_ == MIPC_RESULT_ACK && reply != NULL) {
        mipc_field_entry_t entry_;
        if (!mipc_result_reply_entry(&result_, &entry_) || entry_.descriptor != 0x9A ||
            mipc_threedm_accel_bias_response_decode(entry_.data, entry_.length, reply, NULL) != MIPC_OK) {
            return mipc_link_fail(link, MIPC_RESULT_INVALID, "missing reply field 0x9A");
        }
    }
    return kind_;
}

mipc_result_kind_t mipc_threedm_accel_bias_save(mipc_link_t *link) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    switch (link->session.config.device) {
    case MIPC_DEVICE_CV7_INS:
        cmd_.id = MIPC_FIELD_THREEDM_ACCEL_BIAS_CV7_INS;
        cmd_.u.threedm_accel_bias_cv7_ins.function = MIPC_FUNCTION_SELECTOR_SAVE;
        break;
    default:
        cmd_.id = MIPC_FIELD_THREEDM_ACCEL_BIAS_GX5_45;
        cmd_.u.threedm_accel_bias_gx5_45.function = MIPC_FUNCTION_SELECTOR_SAVE;
        break;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_threedm_accel_bias_load(mipc_link_t *link) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    switch (link->session.config.device) {
    case MIPC_DEVICE_CV7_INS:
        cmd_.id = MIPC_FIELD_THREEDM_ACCEL_BIAS_CV7_INS;
        cmd_.u.threedm_accel_bias_cv7_ins.function = MIPC_FUNCTION_SELECTOR_LOAD;
        break;
    default:
        cmd_.id = MIPC_FIELD_THREEDM_ACCEL_BIAS_GX5_45;
        cmd_.u.threedm_accel_bias_gx5_45.function = MIPC_FUNCTION_SELECTOR_LOAD;
        break;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_threedm_accel_bias_default(mipc_link_t *link) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    switch (link->session.config.device) {
    case MIPC_DEVICE_CV7_INS:
        cmd_.id = MIPC_FIELD_THREEDM_ACCEL_BIAS_CV7_INS;
        cmd_.u.threedm_accel_bias_cv7_ins.function = MIPC_FUNCTION_SELECTOR_DEFAULT;
        break;
    default:
        cmd_.id = MIPC_FIELD_THREEDM_ACCEL_BIAS_GX5_45;
        cmd_.u.threedm_accel_bias_gx5_45.function = MIPC_FUNCTION_SELECTOR_DEFAULT;
        break;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_threedm_accel_bias_write_no_ack(mipc_link_t *link, const float bias[3]) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_THREEDM_ACCEL_BIAS_GX5_45;
        cmd_.u.threedm_accel_bias_gx5_45.function = MIPC_FUNCTION_SELECTOR_WRITE_NO_ACK;
        cmd_.u.threedm_accel_bias_gx5_45.has_bias = true;
        memcpy(cmd_.u.threedm_accel_bias_gx5_45.bias, bias, sizeof cmd_.u.threedm_accel_bias_gx5_45.bias);
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_threedm_gyro_bias_write(mipc_link_t *link, const float bias[3]) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    switch (link->session.config.device) {
    case MIPC_DEVICE_CV7_INS:
        cmd_.id = MIPC_FIELD_THREEDM_GYRO_BIAS_CV7_INS;
        cmd_.u.threedm_gyro_bias_cv7_ins.function = MIPC_FUNCTION_SELECTOR_WRITE;
        cmd_.u.threedm_gyro_bias_cv7_ins.has_bias = true;
        memcpy(cmd_.u.threedm_gyro_bias_cv7_ins.bias, bias, sizeof cmd_.u.threedm_gyro_bias_cv7_ins.bias);
        break;
    default:
        cmd_.id = MIPC_FIELD_THREEDM_GYRO_BIAS_GX5_45;
        cmd_.u.threedm_gyro_bias_gx5_45.function = MIPC_FUNCTION_SELECTOR_WRITE;
        cmd_.u.threedm_gyro_bias_gx5_45.has_bias = true;
        memcpy(cmd_.u.threedm_gyro_bias_gx5_45.bias, bias, sizeof cmd_.u.threedm_gyro_bias_gx5_45.bias);
        break;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_threedm_gyro_bias_read(mipc_link_t *link, mipc_threedm_gyro_bias_response_t *reply) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    mipc_result_t result_;
    memset(&cmd_, 0, sizeof cmd_);
    switch (link->session.config.device) {
    case MIPC_DEVICE_CV7_INS:
        cmd_.id = MIPC_FIELD_THREEDM_GYRO_BIAS_CV7_INS;
        cmd_.u.threedm_gyro_bias_cv7_ins.function = MIPC_FUNCTION_SELECTOR_READ;
        break;
    default:
        cmd_.id = MIPC_FIELD_THREEDM_GYRO_BIAS_GX5_45;
        cmd_.u.threedm_gyro_bias_gx5_45.function = MIPC_FUNCTION_SELECTOR_READ;
        break;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, &result_);
    if (kind_ == MIPC_RESULT_ACK && reply != NULL) {
        mipc_field_entry_t entry_;
        if (!mipc_result_reply_entry(&result_, &entry_) || entry_.descriptor != 0x9B ||
            mipc_threedm_gyro_bias_response_decode(entry_.data, entry_.length, reply, NULL) != MIPC_OK) {
            return mipc_link_fail(link, MIPC_RESULT_INVALID, "missing reply field 0x9B");
        }
    }
    return kind_;
}

mipc_result_kind_t mipc_threedm_gyro_bias_save(mipc_link_t *link) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    switch (link->session.config.device) {
    case MIPC_DEVICE_CV7_INS:
        cmd_.id = MIPC_FIELD_THREEDM_GYRO_BIAS_CV7_INS;
        cmd_.u.threedm_gyro_bias_cv7_ins.function = MIPC_FUNCTION_SELECTOR_SAVE;
        break;
    default:
        cmd_.id = MIPC_FIELD_THREEDM_GYRO_BIAS_GX5_45;
        cmd_.u.threedm_gyro_bias_gx5_45.function = MIPC_FUNCTION_SELECTOR_SAVE;
        break;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_threedm_gyro_bias_load(mipc_link_t *link) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    switch (link->session.config.device) {
    case MIPC_DEVICE_CV7_INS:
        cmd_.id = MIPC_FIELD_THREEDM_GYRO_BIAS_CV7_INS;
        cmd_.u.threedm_gyro_bias_cv7_ins.function = MIPC_FUNCTION_SELECTOR_LOAD;
        break;
    default:
        cmd_.id = MIPC_FIELD_THREEDM_GYRO_BIAS_GX5_45;
        cmd_.u.threedm_gyro_bias_gx5_45.function = MIPC_FUNCTION_SELECTOR_LOAD;
        break;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_threedm_gyro_bias_default(mipc_link_t *link) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    switch (link->session.config.device) {
    case MIPC_DEVICE_CV7_INS:
        cmd_.id = MIPC_FIELD_THREEDM_GYRO_BIAS_CV7_INS;
        cmd_.u.threedm_gyro_bias_cv7_ins.function = MIPC_FUNCTION_SELECTOR_DEFAULT;
        break;
    default:
        cmd_.id = MIPC_FIELD_THREEDM_GYRO_BIAS_GX5_45;
        cmd_.u.threedm_gyro_bias_gx5_45.function = MIPC_FUNCTION_SELECTOR_DEFAULT;
        break;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_threedm_gyro_bias_write_no_ack(mipc_link_t *link, const float bias[3]) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_THREEDM_GYRO_BIAS_GX5_45;
        cmd_.u.threedm_gyro_bias_gx5_45.function = MIPC_FUNCTION_SELECTOR_WRITE_NO_ACK;
        cmd_.u.threedm_gyro_bias_gx5_45.has_bias = true;
        memcpy(cmd_.u.threedm_gyro_bias_gx5_45.bias, bias, sizeof cmd_.u.threedm_gyro_bias_gx5_45.bias);
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_threedm_capture_gyro_bias(mipc_link_t *link, uint16_t averaging_time_ms,
                                                  mipc_threedm_gyro_bias_response_t *reply) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    mipc_result_t result_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_THREEDM_CAPTURE_GYRO_BIAS;
        cmd_.u.threedm_capture_gyro_bias.averaging_time_ms = averaging_time_ms;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, &result_);
    if (kind_ == MIPC_RESULT_ACK && reply != NULL) {
        mipc_field_entry_t entry_;
        if (!mipc_result_reply_entry(&result_, &entry_) || entry_.descriptor != 0x9B ||
            mipc_threedm_gyro_bias_response_decode(entry_.data, entry_.length, reply, NULL) != MIPC_OK) {
            return mipc_link_fail(link, MIPC_RESULT_INVALID, "missing reply field 0x9B");
        }
    }
    return kind_;
}

mipc_result_kind_t mipc_threedm_mag_hard_iron_offset_write(mipc_link_t *link, const float offset[3]) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    switch (link->session.config.device) {
    case MIPC_DEVICE_CV7_INS:
        cmd_.id = MIPC_FIELD_THREEDM_MAG_HARD_IRON_OFFSET_CV7_INS;
        cmd_.u.threedm_mag_hard_iron_offset_cv7_ins.function = MIPC_FUNCTION_SELECTOR_WRITE;
        cmd_.u.threedm_mag_hard_iron_offset_cv7_ins.has_offset = true;
        memcpy(cmd_.u.threedm_mag_hard_iron_offset_cv7_ins.offset, offset,
               sizeof cmd_.u.threedm_mag_hard_iron_offset_cv7_ins.offset);
        break;
    default:
        cmd_.id = MIPC_FIELD_THREEDM_MAG_HARD_IRON_OFFSET_GX5_45;
        cmd_.u.threedm_mag_hard_iron_offset_gx5_45.function = MIPC_FUNCTION_SELECTOR_WRITE;
        cmd_.u.threedm_mag_hard_iron_offset_gx5_45.has_offset = true;
        memcpy(cmd_.u.threedm_mag_hard_iron_offset_gx5_45.offset, offset,
               sizeof cmd_.u.threedm_mag_hard_iron_offset_gx5_45.offset);
        break;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t
mipc_threedm_mag_hard_iron_offset_read(mipc_link_t *link,
                                       mipc_threedm_mag_hard_iron_offset_response_t *reply) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    mipc_result_t result_;
    memset(&cmd_, 0, sizeof cmd_);
    switch (link->session.config.device) {
    case MIPC_DEVICE_CV7_INS:
        cmd_.id = MIPC_FIELD_THREEDM_MAG_HARD_IRON_OFFSET_CV7_INS;
        cmd_.u.threedm_mag_hard_iron_offset_cv7_ins.function = MIPC_FUNCTION_SELECTOR_READ;
        break;
    default:
        cmd_.id = MIPC_FIELD_THREEDM_MAG_HARD_IRON_OFFSET_GX5_45;
        cmd_.u.threedm_mag_hard_iron_offset_gx5_45.function = MIPC_FUNCTION_SELECTOR_READ;
        break;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, &result_);
    if (kind_ == MIPC_RESULT_ACK && reply != NULL) {
        mipc_field_entry_t entry_;
        if (!mipc_result_reply_entry(&result_, &entry_) || entry_.descriptor != 0x9C ||
            mipc_threedm_mag_hard_iron_offset_response_decode(entry_.data, entry_.length, reply, NULL) !=
                MIPC_OK) {
            return mipc_link_fail(link, MIPC_RESULT_INVALID, "missing reply field 0x9C");
        }
    }
    return kind_;
}

mipc_result_kind_t mipc_threedm_mag_hard_iron_offset_save(mipc_link_t *link) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    switch (link->session.config.device) {
    case MIPC_DEVICE_CV7_INS:
        cmd_.id = MIPC_FIELD_THREEDM_MAG_HARD_IRON_OFFSET_CV7_INS;
        cmd_.u.threedm_mag_hard_iron_offset_cv7_ins.function = MIPC_FUNCTION_SELECTOR_SAVE;
        break;
    default:
        cmd_.id = MIPC_FIELD_THREEDM_MAG_HARD_IRON_OFFSET_GX5_45;
        cmd_.u.threedm_mag_hard_iron_offset_gx5_45.function = MIPC_FUNCTION_SELECTOR_SAVE;
        break;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_threedm_mag_hard_iron_offset_load(mipc_link_t *link) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    switch (link->session.config.device) {
    case MIPC_DEVICE_CV7_INS:
        cmd_.id = MIPC_FIELD_THREEDM_MAG_HARD_IRON_OFFSET_CV7_INS;
        cmd_.u.threedm_mag_hard_iron_offset_cv7_ins.function = MIPC_FUNCTION_SELECTOR_LOAD;
        break;
    default:
        cmd_.id = MIPC_FIELD_THREEDM_MAG_HARD_IRON_OFFSET_GX5_45;
        cmd_.u.threedm_mag_hard_iron_offset_gx5_45.function = MIPC_FUNCTION_SELECTOR_LOAD;
        break;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_threedm_mag_hard_iron_offset_default(mipc_link_t *link) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    switch (link->session.config.device) {
    case MIPC_DEVICE_CV7_INS:
        cmd_.id = MIPC_FIELD_THREEDM_MAG_HARD_IRON_OFFSET_CV7_INS;
        cmd_.u.threedm_mag_hard_iron_offset_cv7_ins.function = MIPC_FUNCTION_SELECTOR_DEFAULT;
        break;
    default:
        cmd_.id = MIPC_FIELD_THREEDM_MAG_HARD_IRON_OFFSET_GX5_45;
        cmd_.u.threedm_mag_hard_iron_offset_gx5_45.function = MIPC_FUNCTION_SELECTOR_DEFAULT;
        break;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_threedm_mag_hard_iron_offset_write_no_ack(mipc_link_t *link, const float offset[3]) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_THREEDM_MAG_HARD_IRON_OFFSET_GX5_45;
        cmd_.u.threedm_mag_hard_iron_offset_gx5_45.function = MIPC_FUNCTION_SELECTOR_WRITE_NO_ACK;
        cmd_.u.threedm_mag_hard_iron_offset_gx5_45.has_offset = true;
        memcpy(cmd_.u.threedm_mag_hard_iron_offset_gx5_45.offset, offset,
               sizeof cmd_.u.threedm_mag_hard_iron_offset_gx5_45.offset);
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_threedm_mag_soft_iron_matrix_write(mipc_link_t *link, const float matrix[9]) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    switch (link->session.config.device) {
    case MIPC_DEVICE_CV7_INS:
        cmd_.id = MIPC_FIELD_THREEDM_MAG_SOFT_IRON_MATRIX_CV7_INS;
        cmd_.u.threedm_mag_soft_iron_matrix_cv7_ins.function = MIPC_FUNCTION_SELECTOR_WRITE;
        cmd_.u.threedm_mag_soft_iron_matrix_cv7_ins.has_matrix = true;
        memcpy(cmd_.u.threedm_mag_soft_iron_matrix_cv7_ins.matrix, matrix,
               sizeof cmd_.u.threedm_mag_soft_iron_matrix_cv7_ins.matrix);
        break;
    default:
        cmd_.id = MIPC_FIELD_THREEDM_MAG_SOFT_IRON_MATRIX_GX5_45;
        cmd_.u.threedm_mag_soft_iron_matrix_gx5_45.function = MIPC_FUNCTION_SELECTOR_WRITE;
        cmd_.u.threedm_mag_soft_iron_matrix_gx5_45.has_matrix = true;
        memcpy(cmd_.u.threedm_mag_soft_iron_matrix_gx5_45.matrix, matrix,
               sizeof cmd_.u.threedm_mag_soft_iron_matrix_gx5_45.matrix);
        break;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t
mipc_threedm_mag_soft_iron_matrix_read(mipc_link_t *link,
                                       mipc_threedm_mag_soft_iron_matrix_response_t *reply) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    mipc_result_t result_;
    memset(&cmd_, 0, sizeof cmd_);
    switch (link->session.config.device) {
    case MIPC_DEVICE_CV7_INS:
        cmd_.id = MIPC_FIELD_THREEDM_MAG_SOFT_IRON_MATRIX_CV7_INS;
        cmd_.u.threedm_mag_soft_iron_matrix_cv7_ins.function = MIPC_FUNCTION_SELECTOR_READ;
        break;
    default:
        cmd_.id = MIPC_FIELD_THREEDM_MAG_SOFT_IRON_MATRIX_GX5_45;
        cmd_.u.threedm_mag_soft_iron_matrix_gx5_45.function = MIPC_FUNCTION_SELECTOR_READ;
        break;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, &result_);
    if (kind_ == MIPC_RESULT_ACK && reply != NULL) {
        mipc_field_entry_t entry_;
        if (!mipc_result_reply_entry(&result_, &entry_) || entry_.descriptor != 0x9D ||
            mipc_threedm_mag_soft_iron_matrix_response_decode(entry_.data, entry_.length, reply, NULL) !=
                MIPC_OK) {
            return mipc_link_fail(link, MIPC_RESULT_INVALID, "missing reply field 0x9D");
        }
    }
    return kind_;
}

mipc_result_kind_t mipc_threedm_mag_soft_iron_matrix_save(mipc_link_t *link) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    switch (link->session.config.device) {
    case MIPC_DEVICE_CV7_INS:
        cmd_.id = MIPC_FIELD_THREEDM_MAG_SOFT_IRON_MATRIX_CV7_INS;
        cmd_.u.threedm_mag_soft_iron_matrix_cv7_ins.function = MIPC_FUNCTION_SELECTOR_SAVE;
        break;
    default:
        cmd_.id = MIPC_FIELD_THREEDM_MAG_SOFT_IRON_MATRIX_GX5_45;
        cmd_.u.threedm_mag_soft_iron_matrix_gx5_45.function = MIPC_FUNCTION_SELECTOR_SAVE;
        break;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_threedm_mag_soft_iron_matrix_load(mipc_link_t *link) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    switch (link->session.config.device) {
    case MIPC_DEVICE_CV7_INS:
        cmd_.id = MIPC_FIELD_THREEDM_MAG_SOFT_IRON_MATRIX_CV7_INS;
        cmd_.u.threedm_mag_soft_iron_matrix_cv7_ins.function = MIPC_FUNCTION_SELECTOR_LOAD;
        break;
    default:
        cmd_.id = MIPC_FIELD_THREEDM_MAG_SOFT_IRON_MATRIX_GX5_45;
        cmd_.u.threedm_mag_soft_iron_matrix_gx5_45.function = MIPC_FUNCTION_SELECTOR_LOAD;
        break;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_threedm_mag_soft_iron_matrix_default(mipc_link_t *link) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    switch (link->session.config.device) {
    case MIPC_DEVICE_CV7_INS:
        cmd_.id = MIPC_FIELD_THREEDM_MAG_SOFT_IRON_MATRIX_CV7_INS;
        cmd_.u.threedm_mag_soft_iron_matrix_cv7_ins.function = MIPC_FUNCTION_SELECTOR_DEFAULT;
        break;
    default:
        cmd_.id = MIPC_FIELD_THREEDM_MAG_SOFT_IRON_MATRIX_GX5_45;
        cmd_.u.threedm_mag_soft_iron_matrix_gx5_45.function = MIPC_FUNCTION_SELECTOR_DEFAULT;
        break;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_threedm_mag_soft_iron_matrix_write_no_ack(mipc_link_t *link, const float matrix[9]) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_THREEDM_MAG_SOFT_IRON_MATRIX_GX5_45;
        cmd_.u.threedm_mag_soft_iron_matrix_gx5_45.function = MIPC_FUNCTION_SELECTOR_WRITE_NO_ACK;
        cmd_.u.threedm_mag_soft_iron_matrix_gx5_45.has_matrix = true;
        memcpy(cmd_.u.threedm_mag_soft_iron_matrix_gx5_45.matrix, matrix,
               sizeof cmd_.u.threedm_mag_soft_iron_matrix_gx5_45.matrix);
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_threedm_coning_sculling_enable_write(mipc_link_t *link, bool enable) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_THREEDM_CONING_SCULLING_ENABLE;
        cmd_.u.threedm_coning_sculling_enable.function = MIPC_FUNCTION_SELECTOR_WRITE;
        cmd_.u.threedm_coning_sculling_enable.has_enable = true;
        cmd_.u.threedm_coning_sculling_enable.enable = enable;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t
mipc_threedm_coning_sculling_enable_read(mipc_link_t *link,
                                         mipc_threedm_coning_sculling_enable_response_t *reply) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    mipc_result_t result_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_THREEDM_CONING_SCULLING_ENABLE;
        cmd_.u.threedm_coning_sculling_enable.function = MIPC_FUNCTION_SELECTOR_READ;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, &result_);
    if (kind_ == MIPC_RESULT_ACK && reply != NULL) {
        mipc_field_entry_t entry_;
        if (!mipc_result_reply_entry(&result_, &entry_) || entry_.descriptor != 0x9E ||
            mipc_threedm_coning_sculling_enable_response_decode(entry_.data, entry_.length, reply, NULL) !=
                MIPC_OK) {
            return mipc_link_fail(link, MIPC_RESULT_INVALID, "missing reply field 0x9E");
        }
    }
    return kind_;
}

mipc_result_kind_t mipc_threedm_coning_sculling_enable_save(mipc_link_t *link) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_THREEDM_CONING_SCULLING_ENABLE;
        cmd_.u.threedm_coning_sculling_enable.function = MIPC_FUNCTION_SELECTOR_SAVE;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_threedm_coning_sculling_enable_load(mipc_link_t *link) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_THREEDM_CONING_SCULLING_ENABLE;
        cmd_.u.threedm_coning_sculling_enable.function = MIPC_FUNCTION_SELECTOR_LOAD;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_threedm_coning_sculling_enable_default(mipc_link_t *link) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_THREEDM_CONING_SCULLING_ENABLE;
        cmd_.u.threedm_coning_sculling_enable.function = MIPC_FUNCTION_SELECTOR_DEFAULT;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_threedm_uart_baudrate_write(mipc_link_t *link, uint32_t baud) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_THREEDM_UART_BAUDRATE;
        cmd_.u.threedm_uart_baudrate.function = MIPC_FUNCTION_SELECTOR_WRITE;
        cmd_.u.threedm_uart_baudrate.has_baud = true;
        cmd_.u.threedm_uart_baudrate.baud = baud;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_threedm_uart_baudrate_read(mipc_link_t *link,
                                                   mipc_threedm_uart_baudrate_response_t *reply) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    mipc_result_t result_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_THREEDM_UART_BAUDRATE;
        cmd_.u.threedm_uart_baudrate.function = MIPC_FUNCTION_SELECTOR_READ;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, &result_);
    if (kind_ == MIPC_RESULT_ACK && reply != NULL) {
        mipc_field_entry_t entry_;
        if (!mipc_result_reply_entry(&result_, &entry_) || entry_.descriptor != 0x87 ||
            mipc_threedm_uart_baudrate_response_decode(entry_.data, entry_.length, reply, NULL) != MIPC_OK) {
            return mipc_link_fail(link, MIPC_RESULT_INVALID, "missing reply field 0x87");
        }
    }
    return kind_;
}

mipc_result_kind_t mipc_threedm_uart_baudrate_save(mipc_link_t *link) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_THREEDM_UART_BAUDRATE;
        cmd_.u.threedm_uart_baudrate.function = MIPC_FUNCTION_SELECTOR_SAVE;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_threedm_uart_baudrate_load(mipc_link_t *link) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_THREEDM_UART_BAUDRATE;
        cmd_.u.threedm_uart_baudrate.function = MIPC_FUNCTION_SELECTOR_LOAD;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_threedm_uart_baudrate_default(mipc_link_t *link) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_THREEDM_UART_BAUDRATE;
        cmd_.u.threedm_uart_baudrate.function = MIPC_FUNCTION_SELECTOR_DEFAULT;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_threedm_gpio_config_write(mipc_link_t *link, uint8_t pin, mipc_gpio_feature_t feature,
                                                  const mipc_gpio_behavior_t *behavior,
                                                  mipc_gpio_pin_mode_t pin_mode) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_THREEDM_GPIO_CONFIG;
        cmd_.u.threedm_gpio_config.function = MIPC_FUNCTION_SELECTOR_WRITE;
        cmd_.u.threedm_gpio_config.pin = pin;
        cmd_.u.threedm_gpio_config.has_feature = true;
        cmd_.u.threedm_gpio_config.feature = feature;
        cmd_.u.threedm_gpio_config.has_behavior = true;
        cmd_.u.threedm_gpio_config.behavior = *behavior;
        cmd_.u.threedm_gpio_config.has_pin_mode = true;
        cmd_.u.threedm_gpio_config.pin_mode = pin_mode;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_threedm_gpio_config_read(mipc_link_t *link, uint8_t pin,
                                                 mipc_threedm_gpio_config_response_t *reply) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    mipc_result_t result_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_THREEDM_GPIO_CONFIG;
        cmd_.u.threedm_gpio_config.function = MIPC_FUNCTION_SELECTOR_READ;
        cmd_.u.threedm_gpio_config.pin = pin;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, &result_);
    if (kind_ == MIPC_RESULT_ACK && reply != NULL) {
        mipc_field_entry_t entry_;
        if (!mipc_result_reply_entry(&result_, &entry_) || entry_.descriptor != 0xC1 ||
            mipc_threedm_gpio_config_response_decode(entry_.data, entry_.length, reply, NULL) != MIPC_OK) {
            return mipc_link_fail(link, MIPC_RESULT_INVALID, "missing reply field 0xC1");
        }
    }
    return kind_;
}

mipc_result_kind_t mipc_threedm_gpio_config_save(mipc_link_t *link, uint8_t pin) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_THREEDM_GPIO_CONFIG;
        cmd_.u.threedm_gpio_config.function = MIPC_FUNCTION_SELECTOR_SAVE;
        cmd_.u.threedm_gpio_config.pin = pin;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_threedm_gpio_config_load(mipc_link_t *link, uint8_t pin) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_THREEDM_GPIO_CONFIG;
        cmd_.u.threedm_gpio_config.function = MIPC_FUNCTION_SELECTOR_LOAD;
        cmd_.u.threedm_gpio_config.pin = pin;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_threedm_gpio_config_default(mipc_link_t *link, uint8_t pin) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_THREEDM_GPIO_CONFIG;
        cmd_.u.threedm_gpio_config.function = MIPC_FUNCTION_SELECTOR_DEFAULT;
        cmd_.u.threedm_gpio_config.pin = pin;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_threedm_gpio_state_write(mipc_link_t *link, uint8_t pin, bool state) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_THREEDM_GPIO_STATE;
        cmd_.u.threedm_gpio_state.function = MIPC_FUNCTION_SELECTOR_WRITE;
        cmd_.u.threedm_gpio_state.pin = pin;
        cmd_.u.threedm_gpio_state.has_state = true;
        cmd_.u.threedm_gpio_state.state = state;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_threedm_gpio_state_read(mipc_link_t *link, uint8_t pin,
                                                mipc_threedm_gpio_state_response_t *reply) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    mipc_result_t result_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_THREEDM_GPIO_STATE;
        cmd_.u.threedm_gpio_state.function = MIPC_FUNCTION_SELECTOR_READ;
        cmd_.u.threedm_gpio_state.pin = pin;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, &result_);
    if (kind_ == MIPC_RESULT_ACK && reply != NULL) {
        mipc_field_entry_t entry_;
        if (!mipc_result_reply_entry(&result_, &entry_) || entry_.descriptor != 0xC2 ||
            mipc_threedm_gpio_state_response_decode(entry_.data, entry_.length, reply, NULL) != MIPC_OK) {
            return mipc_link_fail(link, MIPC_RESULT_INVALID, "missing reply field 0xC2");
        }
    }
    return kind_;
}

mipc_result_kind_t mipc_threedm_odometer_config_write(mipc_link_t *link, mipc_odometer_mode_t mode,
                                                      float scaling, float uncertainty) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_THREEDM_ODOMETER_CONFIG;
        cmd_.u.threedm_odometer_config.function = MIPC_FUNCTION_SELECTOR_WRITE;
        cmd_.u.threedm_odometer_config.has_mode = true;
        cmd_.u.threedm_odometer_config.mode = mode;
        cmd_.u.threedm_odometer_config.has_scaling = true;
        cmd_.u.threedm_odometer_config.scaling = scaling;
        cmd_.u.threedm_odometer_config.has_uncertainty = true;
        cmd_.u.threedm_odometer_config.uncertainty = uncertainty;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_threedm_odometer_config_read(mipc_link_t *link,
                                                     mipc_threedm_odometer_config_response_t *reply) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    mipc_result_t result_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_THREEDM_ODOMETER_CONFIG;
        cmd_.u.threedm_odometer_config.function = MIPC_FUNCTION_SELECTOR_READ;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, &result_);
    if (kind_ == MIPC_RESULT_ACK && reply != NULL) {
        mipc_field_entry_t entry_;
        if (!mipc_result_reply_entry(&result_, &entry_) || entry_.descriptor != 0xC3 ||
            mipc_threedm_odometer_config_response_decode(entry_.data, entry_.length, reply, NULL) !=
                MIPC_OK) {
            return mipc_link_fail(link, MIPC_RESULT_INVALID, "missing reply field 0xC3");
        }
    }
    return kind_;
}

mipc_result_kind_t mipc_threedm_odometer_config_save(mipc_link_t *link) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_THREEDM_ODOMETER_CONFIG;
        cmd_.u.threedm_odometer_config.function = MIPC_FUNCTION_SELECTOR_SAVE;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_threedm_odometer_config_load(mipc_link_t *link) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_THREEDM_ODOMETER_CONFIG;
        cmd_.u.threedm_odometer_config.function = MIPC_FUNCTION_SELECTOR_LOAD;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_threedm_odometer_config_default(mipc_link_t *link) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_THREEDM_ODOMETER_CONFIG;
        cmd_.u.threedm_odometer_config.function = MIPC_FUNCTION_SELECTOR_DEFAULT;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_threedm_advanced_lowpass_filter_write(mipc_link_t *link, uint8_t target_descriptor,
                                                              bool enable, bool manual, uint16_t frequency,
                                                              uint8_t reserved) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_THREEDM_ADVANCED_LOWPASS_FILTER;
        cmd_.u.threedm_advanced_lowpass_filter.function = MIPC_FUNCTION_SELECTOR_WRITE;
        cmd_.u.threedm_advanced_lowpass_filter.target_descriptor = target_descriptor;
        cmd_.u.threedm_advanced_lowpass_filter.has_enable = true;
        cmd_.u.threedm_advanced_lowpass_filter.enable = enable;
        cmd_.u.threedm_advanced_lowpass_filter.has_manual = true;
        cmd_.u.threedm_advanced_lowpass_filter.manual = manual;
        cmd_.u.threedm_advanced_lowpass_filter.has_frequency = true;
        cmd_.u.threedm_advanced_lowpass_filter.frequency = frequency;
        cmd_.u.threedm_advanced_lowpass_filter.has_reserved = true;
        cmd_.u.threedm_advanced_lowpass_filter.reserved = reserved;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t
mipc_threedm_advanced_lowpass_filter_read(mipc_link_t *link, uint8_t target_descriptor,
                                          mipc_threedm_advanced_lowpass_filter_response_t *reply) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    mipc_result_t result_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_THREEDM_ADVANCED_LOWPASS_FILTER;
        cmd_.u.threedm_advanced_lowpass_filter.function = MIPC_FUNCTION_SELECTOR_READ;
        cmd_.u.threedm_advanced_lowpass_filter.target_descriptor = target_descriptor;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, &result_);
    if (kind_ == MIPC_RESULT_ACK && reply != NULL) {
        mipc_field_entry_t entry_;
        if (!mipc_result_reply_entry(&result_, &entry_) || entry_.descriptor != 0x8B ||
            mipc_threedm_advanced_lowpass_filter_response_decode(entry_.data, entry_.length, reply, NULL) !=
                MIPC_OK) {
            return mipc_link_fail(link, MIPC_RESULT_INVALID, "missing reply field 0x8B");
        }
    }
    return kind_;
}

mipc_result_kind_t mipc_threedm_advanced_lowpass_filter_save(mipc_link_t *link, uint8_t target_descriptor) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_THREEDM_ADVANCED_LOWPASS_FILTER;
        cmd_.u.threedm_advanced_lowpass_filter.function = MIPC_FUNCTION_SELECTOR_SAVE;
        cmd_.u.threedm_advanced_lowpass_filter.target_descriptor = target_descriptor;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_threedm_advanced_lowpass_filter_load(mipc_link_t *link, uint8_t target_descriptor) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_THREEDM_ADVANCED_LOWPASS_FILTER;
        cmd_.u.threedm_advanced_lowpass_filter.function = MIPC_FUNCTION_SELECTOR_LOAD;
        cmd_.u.threedm_advanced_lowpass_filter.target_descriptor = target_descriptor;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_threedm_advanced_lowpass_filter_default(mipc_link_t *link,
                                                                uint8_t target_descriptor) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_THREEDM_ADVANCED_LOWPASS_FILTER;
        cmd_.u.threedm_advanced_lowpass_filter.function = MIPC_FUNCTION_SELECTOR_DEFAULT;
        cmd_.u.threedm_advanced_lowpass_filter.target_descriptor = target_descriptor;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_threedm_complementary_filter_write(mipc_link_t *link, bool pitch_roll_enable,
                                                           bool heading_enable,
                                                           float pitch_roll_time_constant,
                                                           float heading_time_constant) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_THREEDM_COMPLEMENTARY_FILTER;
        cmd_.u.threedm_complementary_filter.function = MIPC_FUNCTION_SELECTOR_WRITE;
        cmd_.u.threedm_complementary_filter.has_pitch_roll_enable = true;
        cmd_.u.threedm_complementary_filter.pitch_roll_enable = pitch_roll_enable;
        cmd_.u.threedm_complementary_filter.has_heading_enable = true;
        cmd_.u.threedm_complementary_filter.heading_enable = heading_enable;
        cmd_.u.threedm_complementary_filter.has_pitch_roll_time_constant = true;
        cmd_.u.threedm_complementary_filter.pitch_roll_time_constant = pitch_roll_time_constant;
        cmd_.u.threedm_complementary_filter.has_heading_time_constant = true;
        cmd_.u.threedm_complementary_filter.heading_time_constant = heading_time_constant;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t
mipc_threedm_complementary_filter_read(mipc_link_t *link,
                                       mipc_threedm_complementary_filter_response_t *reply) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    mipc_result_t result_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_THREEDM_COMPLEMENTARY_FILTER;
        cmd_.u.threedm_complementary_filter.function = MIPC_FUNCTION_SELECTOR_READ;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, &result_);
    if (kind_ == MIPC_RESULT_ACK && reply != NULL) {
        mipc_field_entry_t entry_;
        if (!mipc_result_reply_entry(&result_, &entry_) || entry_.descriptor != 0x97 ||
            mipc_threedm_complementary_filter_response_decode(entry_.data, entry_.length, reply, NULL) !=
                MIPC_OK) {
            return mipc_link_fail(link, MIPC_RESULT_INVALID, "missing reply field 0x97");
        }
    }
    return kind_;
}

mipc_result_kind_t mipc_threedm_complementary_filter_save(mipc_link_t *link) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_THREEDM_COMPLEMENTARY_FILTER;
        cmd_.u.threedm_complementary_filter.function = MIPC_FUNCTION_SELECTOR_SAVE;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_threedm_complementary_filter_load(mipc_link_t *link) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_THREEDM_COMPLEMENTARY_FILTER;
        cmd_.u.threedm_complementary_filter.function = MIPC_FUNCTION_SELECTOR_LOAD;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_threedm_complementary_filter_default(mipc_link_t *link) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_THREEDM_COMPLEMENTARY_FILTER;
        cmd_.u.threedm_complementary_filter.function = MIPC_FUNCTION_SELECTOR_DEFAULT;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_threedm_sensor_range_write(mipc_link_t *link, mipc_sensor_range_type_t sensor,
                                                   uint8_t setting) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_THREEDM_SENSOR_RANGE;
        cmd_.u.threedm_sensor_range.function = MIPC_FUNCTION_SELECTOR_WRITE;
        cmd_.u.threedm_sensor_range.sensor = sensor;
        cmd_.u.threedm_sensor_range.has_setting = true;
        cmd_.u.threedm_sensor_range.setting = setting;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_threedm_sensor_range_read(mipc_link_t *link, mipc_sensor_range_type_t sensor,
                                                  mipc_threedm_sensor_range_response_t *reply) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    mipc_result_t result_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_THREEDM_SENSOR_RANGE;
        cmd_.u.threedm_sensor_range.function = MIPC_FUNCTION_SELECTOR_READ;
        cmd_.u.threedm_sensor_range.sensor = sensor;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, &result_);
    if (kind_ == MIPC_RESULT_ACK && reply != NULL) {
        mipc_field_entry_t entry_;
        if (!mipc_result_reply_entry(&result_, &entry_) || entry_.descriptor != 0xD2 ||
            mipc_threedm_sensor_range_response_decode(entry_.data, entry_.length, reply, NULL) != MIPC_OK) {
            return mipc_link_fail(link, MIPC_RESULT_INVALID, "missing reply field 0xD2");
        }
    }
    return kind_;
}

mipc_result_kind_t mipc_threedm_sensor_range_save(mipc_link_t *link, mipc_sensor_range_type_t sensor) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_THREEDM_SENSOR_RANGE;
        cmd_.u.threedm_sensor_range.function = MIPC_FUNCTION_SELECTOR_SAVE;
        cmd_.u.threedm_sensor_range.sensor = sensor;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_threedm_sensor_range_load(mipc_link_t *link, mipc_sensor_range_type_t sensor) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_THREEDM_SENSOR_RANGE;
        cmd_.u.threedm_sensor_range.function = MIPC_FUNCTION_SELECTOR_LOAD;
        cmd_.u.threedm_sensor_range.sensor = sensor;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_threedm_sensor_range_default(mipc_link_t *link, mipc_sensor_range_type_t sensor) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_THREEDM_SENSOR_RANGE;
        cmd_.u.threedm_sensor_range.function = MIPC_FUNCTION_SELECTOR_DEFAULT;
        cmd_.u.threedm_sensor_range.sensor = sensor;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_threedm_get_calibrated_sensor_ranges(mipc_link_t *link,
                                                             mipc_sensor_range_type_t sensor,
                                                             mipc_threedm_calibrated_sensor_ranges_t *reply) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    mipc_result_t result_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_THREEDM_GET_CALIBRATED_SENSOR_RANGES;
        cmd_.u.threedm_get_calibrated_sensor_ranges.sensor = sensor;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, &result_);
    if (kind_ == MIPC_RESULT_ACK && reply != NULL) {
        mipc_field_entry_t entry_;
        if (!mipc_result_reply_entry(&result_, &entry_) || entry_.descriptor != 0xD3 ||
            mipc_threedm_calibrated_sensor_ranges_decode(entry_.data, entry_.length, reply, NULL) !=
                MIPC_OK) {
            return mipc_link_fail(link, MIPC_RESULT_INVALID, "missing reply field 0xD3");
        }
    }
    return kind_;
}

mipc_result_kind_t mipc_threedm_lowpass_filter_write(mipc_link_t *link, uint8_t desc_set, uint8_t field_desc,
                                                     bool enable, bool manual, float frequency) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_THREEDM_LOWPASS_FILTER;
        cmd_.u.threedm_lowpass_filter.function = MIPC_FUNCTION_SELECTOR_WRITE;
        cmd_.u.threedm_lowpass_filter.desc_set = desc_set;
        cmd_.u.threedm_lowpass_filter.field_desc = field_desc;
        cmd_.u.threedm_lowpass_filter.has_enable = true;
        cmd_.u.threedm_lowpass_filter.enable = enable;
        cmd_.u.threedm_lowpass_filter.has_manual = true;
        cmd_.u.threedm_lowpass_filter.manual = manual;
        cmd_.u.threedm_lowpass_filter.has_frequency = true;
        cmd_.u.threedm_lowpass_filter.frequency = frequency;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_threedm_lowpass_filter_read(mipc_link_t *link, uint8_t desc_set, uint8_t field_desc,
                                                    mipc_threedm_lowpass_filter_response_t *reply) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    mipc_result_t result_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_THREEDM_LOWPASS_FILTER;
        cmd_.u.threedm_lowpass_filter.function = MIPC_FUNCTION_SELECTOR_READ;
        cmd_.u.threedm_lowpass_filter.desc_set = desc_set;
        cmd_.u.threedm_lowpass_filter.field_desc = field_desc;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, &result_);
    if (kind_ == MIPC_RESULT_ACK && reply != NULL) {
        mipc_field_entry_t entry_;
        if (!mipc_result_reply_entry(&result_, &entry_) || entry_.descriptor != 0xD4 ||
            mipc_threedm_lowpass_filter_response_decode(entry_.data, entry_.length, reply, NULL) != MIPC_OK) {
            return mipc_link_fail(link, MIPC_RESULT_INVALID, "missing reply field 0xD4");
        }
    }
    return kind_;
}

mipc_result_kind_t mipc_threedm_lowpass_filter_save(mipc_link_t *link, uint8_t desc_set, uint8_t field_desc) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_THREEDM_LOWPASS_FILTER;
        cmd_.u.threedm_lowpass_filter.function = MIPC_FUNCTION_SELECTOR_SAVE;
        cmd_.u.threedm_lowpass_filter.desc_set = desc_set;
        cmd_.u.threedm_lowpass_filter.field_desc = field_desc;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_threedm_lowpass_filter_load(mipc_link_t *link, uint8_t desc_set, uint8_t field_desc) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_THREEDM_LOWPASS_FILTER;
        cmd_.u.threedm_lowpass_filter.function = MIPC_FUNCTION_SELECTOR_LOAD;
        cmd_.u.threedm_lowpass_filter.desc_set = desc_set;
        cmd_.u.threedm_lowpass_filter.field_desc = field_desc;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_threedm_lowpass_filter_default(mipc_link_t *link, uint8_t desc_set,
                                                       uint8_t field_desc) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_THREEDM_LOWPASS_FILTER;
        cmd_.u.threedm_lowpass_filter.function = MIPC_FUNCTION_SELECTOR_DEFAULT;
        cmd_.u.threedm_lowpass_filter.desc_set = desc_set;
        cmd_.u.threedm_lowpass_filter.field_desc = field_desc;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_threedm_poll_imu_data(mipc_link_t *link, mipc_gx5_poll_option_t option,
                                              const mipc_gx5_poll_descriptor_t *descriptors,
                                              size_t descriptors_count) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    if (descriptors_count > 83u) {
        return mipc_link_fail(link, MIPC_RESULT_REFUSED, "descriptors: more than 83 elements");
    }
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_THREEDM_POLL_IMU_DATA;
        cmd_.u.threedm_poll_imu_data.option = option;
        if (descriptors_count > 0) {
            memcpy(cmd_.u.threedm_poll_imu_data.descriptors, descriptors,
                   descriptors_count * sizeof cmd_.u.threedm_poll_imu_data.descriptors[0]);
        }
        cmd_.u.threedm_poll_imu_data.num_descriptors = (uint8_t)descriptors_count;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_threedm_poll_gnss_data(mipc_link_t *link, mipc_gx5_poll_option_t option,
                                               const mipc_gx5_poll_descriptor_t *descriptors,
                                               size_t descriptors_count) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    if (descriptors_count > 83u) {
        return mipc_link_fail(link, MIPC_RESULT_REFUSED, "descriptors: more than 83 elements");
    }
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_THREEDM_POLL_GNSS_DATA;
        cmd_.u.threedm_poll_gnss_data.option = option;
        if (descriptors_count > 0) {
            memcpy(cmd_.u.threedm_poll_gnss_data.descriptors, descriptors,
                   descriptors_count * sizeof cmd_.u.threedm_poll_gnss_data.descriptors[0]);
        }
        cmd_.u.threedm_poll_gnss_data.num_descriptors = (uint8_t)descriptors_count;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_threedm_poll_filter_data(mipc_link_t *link, mipc_gx5_poll_option_t option,
                                                 const mipc_gx5_poll_descriptor_t *descriptors,
                                                 size_t descriptors_count) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    if (descriptors_count > 83u) {
        return mipc_link_fail(link, MIPC_RESULT_REFUSED, "descriptors: more than 83 elements");
    }
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_THREEDM_POLL_FILTER_DATA;
        cmd_.u.threedm_poll_filter_data.option = option;
        if (descriptors_count > 0) {
            memcpy(cmd_.u.threedm_poll_filter_data.descriptors, descriptors,
                   descriptors_count * sizeof cmd_.u.threedm_poll_filter_data.descriptors[0]);
        }
        cmd_.u.threedm_poll_filter_data.num_descriptors = (uint8_t)descriptors_count;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_threedm_poll_nmea_data(mipc_link_t *link, bool suppress_ack,
                                               const mipc_nmea_message_t *format_entries,
                                               size_t format_entries_count) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    if (format_entries_count > 50u) {
        return mipc_link_fail(link, MIPC_RESULT_REFUSED, "format_entries: more than 50 elements");
    }
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_THREEDM_POLL_NMEA_DATA;
        cmd_.u.threedm_poll_nmea_data.suppress_ack = suppress_ack;
        if (format_entries_count > 0) {
            memcpy(cmd_.u.threedm_poll_nmea_data.format_entries, format_entries,
                   format_entries_count * sizeof cmd_.u.threedm_poll_nmea_data.format_entries[0]);
        }
        cmd_.u.threedm_poll_nmea_data.count = (uint8_t)format_entries_count;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_threedm_poll_data(mipc_link_t *link, uint8_t desc_set, bool suppress_ack,
                                          const uint8_t *descriptors, size_t descriptors_count) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    if (descriptors_count > 250u) {
        return mipc_link_fail(link, MIPC_RESULT_REFUSED, "descriptors: more than 250 elements");
    }
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_THREEDM_POLL_DATA;
        cmd_.u.threedm_poll_data.desc_set = desc_set;
        cmd_.u.threedm_poll_data.suppress_ack = suppress_ack;
        if (descriptors_count > 0) {
            memcpy(cmd_.u.threedm_poll_data.descriptors, descriptors,
                   descriptors_count * sizeof cmd_.u.threedm_poll_data.descriptors[0]);
        }
        cmd_.u.threedm_poll_data.num_descriptors = (uint8_t)descriptors_count;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_threedm_get_imu_base_rate(mipc_link_t *link, mipc_threedm_imu_base_rate_t *reply) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    mipc_result_t result_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_THREEDM_GET_IMU_BASE_RATE;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, &result_);
    if (kind_ == MIPC_RESULT_ACK && reply != NULL) {
        mipc_field_entry_t entry_;
        if (!mipc_result_reply_entry(&result_, &entry_) || entry_.descriptor != 0x83 ||
            mipc_threedm_imu_base_rate_decode(entry_.data, entry_.length, reply, NULL) != MIPC_OK) {
            return mipc_link_fail(link, MIPC_RESULT_INVALID, "missing reply field 0x83");
        }
    }
    return kind_;
}

mipc_result_kind_t mipc_threedm_get_gnss_base_rate(mipc_link_t *link, mipc_threedm_gnss_base_rate_t *reply) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    mipc_result_t result_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_THREEDM_GET_GNSS_BASE_RATE;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, &result_);
    if (kind_ == MIPC_RESULT_ACK && reply != NULL) {
        mipc_field_entry_t entry_;
        if (!mipc_result_reply_entry(&result_, &entry_) || entry_.descriptor != 0x84 ||
            mipc_threedm_gnss_base_rate_decode(entry_.data, entry_.length, reply, NULL) != MIPC_OK) {
            return mipc_link_fail(link, MIPC_RESULT_INVALID, "missing reply field 0x84");
        }
    }
    return kind_;
}

mipc_result_kind_t mipc_threedm_get_filter_base_rate(mipc_link_t *link,
                                                     mipc_threedm_filter_base_rate_t *reply) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    mipc_result_t result_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_THREEDM_GET_FILTER_BASE_RATE;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, &result_);
    if (kind_ == MIPC_RESULT_ACK && reply != NULL) {
        mipc_field_entry_t entry_;
        if (!mipc_result_reply_entry(&result_, &entry_) || entry_.descriptor != 0x8A ||
            mipc_threedm_filter_base_rate_decode(entry_.data, entry_.length, reply, NULL) != MIPC_OK) {
            return mipc_link_fail(link, MIPC_RESULT_INVALID, "missing reply field 0x8A");
        }
    }
    return kind_;
}

mipc_result_kind_t mipc_threedm_get_base_rate(mipc_link_t *link, uint8_t desc_set,
                                              mipc_threedm_base_rate_t *reply) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    mipc_result_t result_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_THREEDM_GET_BASE_RATE;
        cmd_.u.threedm_get_base_rate.desc_set = desc_set;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, &result_);
    if (kind_ == MIPC_RESULT_ACK && reply != NULL) {
        mipc_field_entry_t entry_;
        if (!mipc_result_reply_entry(&result_, &entry_) || entry_.descriptor != 0x8E ||
            mipc_threedm_base_rate_decode(entry_.data, entry_.length, reply, NULL) != MIPC_OK) {
            return mipc_link_fail(link, MIPC_RESULT_INVALID, "missing reply field 0x8E");
        }
    }
    return kind_;
}

mipc_result_kind_t mipc_threedm_imu_message_format_write(mipc_link_t *link,
                                                         const mipc_descriptor_rate_t *descriptors,
                                                         size_t descriptors_count) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    if (descriptors_count > 83u) {
        return mipc_link_fail(link, MIPC_RESULT_REFUSED, "descriptors: more than 83 elements");
    }
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_THREEDM_IMU_MESSAGE_FORMAT;
        cmd_.u.threedm_imu_message_format.function = MIPC_FUNCTION_SELECTOR_WRITE;
        cmd_.u.threedm_imu_message_format.has_descriptors = true;
        if (descriptors_count > 0) {
            memcpy(cmd_.u.threedm_imu_message_format.descriptors, descriptors,
                   descriptors_count * sizeof cmd_.u.threedm_imu_message_format.descriptors[0]);
        }
        cmd_.u.threedm_imu_message_format.has_num_descriptors = true;
        cmd_.u.threedm_imu_message_format.num_descriptors = (uint8_t)descriptors_count;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_threedm_imu_message_format_read(mipc_link_t *link,
                                                        const mipc_descriptor_rate_t *descriptors,
                                                        size_t descriptors_count,
                                                        mipc_threedm_imu_message_format_response_t *reply) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    mipc_result_t result_;
    if (descriptors_count > 83u) {
        return mipc_link_fail(link, MIPC_RESULT_REFUSED, "descriptors: more than 83 elements");
    }
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_THREEDM_IMU_MESSAGE_FORMAT;
        cmd_.u.threedm_imu_message_format.function = MIPC_FUNCTION_SELECTOR_READ;
        cmd_.u.threedm_imu_message_format.has_descriptors = true;
        if (descriptors_count > 0) {
            memcpy(cmd_.u.threedm_imu_message_format.descriptors, descriptors,
                   descriptors_count * sizeof cmd_.u.threedm_imu_message_format.descriptors[0]);
        }
        cmd_.u.threedm_imu_message_format.has_num_descriptors = true;
        cmd_.u.threedm_imu_message_format.num_descriptors = (uint8_t)descriptors_count;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, &result_);
    if (kind_ == MIPC_RESULT_ACK && reply != NULL) {
        mipc_field_entry_t entry_;
        if (!mipc_result_reply_entry(&result_, &entry_) || entry_.descriptor != 0x80 ||
            mipc_threedm_imu_message_format_response_decode(entry_.data, entry_.length, reply, NULL) !=
                MIPC_OK) {
            return mipc_link_fail(link, MIPC_RESULT_INVALID, "missing reply field 0x80");
        }
    }
    return kind_;
}

mipc_result_kind_t mipc_threedm_imu_message_format_save(mipc_link_t *link,
                                                        const mipc_descriptor_rate_t *descriptors,
                                                        size_t descriptors_count) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    if (descriptors_count > 83u) {
        return mipc_link_fail(link, MIPC_RESULT_REFUSED, "descriptors: more than 83 elements");
    }
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_THREEDM_IMU_MESSAGE_FORMAT;
        cmd_.u.threedm_imu_message_format.function = MIPC_FUNCTION_SELECTOR_SAVE;
        cmd_.u.threedm_imu_message_format.has_descriptors = true;
        if (descriptors_count > 0) {
            memcpy(cmd_.u.threedm_imu_message_format.descriptors, descriptors,
                   descriptors_count * sizeof cmd_.u.threedm_imu_message_format.descriptors[0]);
        }
        cmd_.u.threedm_imu_message_format.has_num_descriptors = true;
        cmd_.u.threedm_imu_message_format.num_descriptors = (uint8_t)descriptors_count;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_threedm_imu_message_format_load(mipc_link_t *link,
                                                        const mipc_descriptor_rate_t *descriptors,
                                                        size_t descriptors_count) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    if (descriptors_count > 83u) {
        return mipc_link_fail(link, MIPC_RESULT_REFUSED, "descriptors: more than 83 elements");
    }
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_THREEDM_IMU_MESSAGE_FORMAT;
        cmd_.u.threedm_imu_message_format.function = MIPC_FUNCTION_SELECTOR_LOAD;
        cmd_.u.threedm_imu_message_format.has_descriptors = true;
        if (descriptors_count > 0) {
            memcpy(cmd_.u.threedm_imu_message_format.descriptors, descriptors,
                   descriptors_count * sizeof cmd_.u.threedm_imu_message_format.descriptors[0]);
        }
        cmd_.u.threedm_imu_message_format.has_num_descriptors = true;
        cmd_.u.threedm_imu_message_format.num_descriptors = (uint8_t)descriptors_count;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_threedm_imu_message_format_default(mipc_link_t *link,
                                                           const mipc_descriptor_rate_t *descriptors,
                                                           size_t descriptors_count) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    if (descriptors_count > 83u) {
        return mipc_link_fail(link, MIPC_RESULT_REFUSED, "descriptors: more than 83 elements");
    }
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_THREEDM_IMU_MESSAGE_FORMAT;
        cmd_.u.threedm_imu_message_format.function = MIPC_FUNCTION_SELECTOR_DEFAULT;
        cmd_.u.threedm_imu_message_format.has_descriptors = true;
        if (descriptors_count > 0) {
            memcpy(cmd_.u.threedm_imu_message_format.descriptors, descriptors,
                   descriptors_count * sizeof cmd_.u.threedm_imu_message_format.descriptors[0]);
        }
        cmd_.u.threedm_imu_message_format.has_num_descriptors = true;
        cmd_.u.threedm_imu_message_format.num_descriptors = (uint8_t)descriptors_count;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_threedm_gnss_message_format_write(mipc_link_t *link,
                                                          const mipc_descriptor_rate_t *descriptors,
                                                          size_t descriptors_count) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    if (descriptors_count > 83u) {
        return mipc_link_fail(link, MIPC_RESULT_REFUSED, "descriptors: more than 83 elements");
    }
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_THREEDM_GNSS_MESSAGE_FORMAT;
        cmd_.u.threedm_gnss_message_format.function = MIPC_FUNCTION_SELECTOR_WRITE;
        cmd_.u.threedm_gnss_message_format.has_descriptors = true;
        if (descriptors_count > 0) {
            memcpy(cmd_.u.threedm_gnss_message_format.descriptors, descriptors,
                   descriptors_count * sizeof cmd_.u.threedm_gnss_message_format.descriptors[0]);
        }
        cmd_.u.threedm_gnss_message_format.has_num_descriptors = true;
        cmd_.u.threedm_gnss_message_format.num_descriptors = (uint8_t)descriptors_count;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_threedm_gnss_message_format_read(mipc_link_t *link,
                                                         const mipc_descriptor_rate_t *descriptors,
                                                         size_t descriptors_count,
                                                         mipc_threedm_gnss_message_format_response_t *reply) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    mipc_result_t result_;
    if (descriptors_count > 83u) {
        return mipc_link_fail(link, MIPC_RESULT_REFUSED, "descriptors: more than 83 elements");
    }
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_THREEDM_GNSS_MESSAGE_FORMAT;
        cmd_.u.threedm_gnss_message_format.function = MIPC_FUNCTION_SELECTOR_READ;
        cmd_.u.threedm_gnss_message_format.has_descriptors = true;
        if (descriptors_count > 0) {
            memcpy(cmd_.u.threedm_gnss_message_format.descriptors, descriptors,
                   descriptors_count * sizeof cmd_.u.threedm_gnss_message_format.descriptors[0]);
        }
        cmd_.u.threedm_gnss_message_format.has_num_descriptors = true;
        cmd_.u.threedm_gnss_message_format.num_descriptors = (uint8_t)descriptors_count;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, &result_);
    if (kind_ == MIPC_RESULT_ACK && reply != NULL) {
        mipc_field_entry_t entry_;
        if (!mipc_result_reply_entry(&result_, &entry_) || entry_.descriptor != 0x81 ||
            mipc_threedm_gnss_message_format_response_decode(entry_.data, entry_.length, reply, NULL) !=
                MIPC_OK) {
            return mipc_link_fail(link, MIPC_RESULT_INVALID, "missing reply field 0x81");
        }
    }
    return kind_;
}

mipc_result_kind_t mipc_threedm_gnss_message_format_save(mipc_link_t *link,
                                                         const mipc_descriptor_rate_t *descriptors,
                                                         size_t descriptors_count) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    if (descriptors_count > 83u) {
        return mipc_link_fail(link, MIPC_RESULT_REFUSED, "descriptors: more than 83 elements");
    }
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_THREEDM_GNSS_MESSAGE_FORMAT;
        cmd_.u.threedm_gnss_message_format.function = MIPC_FUNCTION_SELECTOR_SAVE;
        cmd_.u.threedm_gnss_message_format.has_descriptors = true;
        if (descriptors_count > 0) {
            memcpy(cmd_.u.threedm_gnss_message_format.descriptors, descriptors,
                   descriptors_count * sizeof cmd_.u.threedm_gnss_message_format.descriptors[0]);
        }
        cmd_.u.threedm_gnss_message_format.has_num_descriptors = true;
        cmd_.u.threedm_gnss_message_format.num_descriptors = (uint8_t)descriptors_count;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_threedm_gnss_message_format_load(mipc_link_t *link,
                                                         const mipc_descriptor_rate_t *descriptors,
                                                         size_t descriptors_count) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    if (descriptors_count > 83u) {
        return mipc_link_fail(link, MIPC_RESULT_REFUSED, "descriptors: more than 83 elements");
    }
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_THREEDM_GNSS_MESSAGE_FORMAT;
        cmd_.u.threedm_gnss_message_format.function = MIPC_FUNCTION_SELECTOR_LOAD;
        cmd_.u.threedm_gnss_message_format.has_descriptors = true;
        if (descriptors_count > 0) {
            memcpy(cmd_.u.threedm_gnss_message_format.descriptors, descriptors,
                   descriptors_count * sizeof cmd_.u.threedm_gnss_message_format.descriptors[0]);
        }
        cmd_.u.threedm_gnss_message_format.has_num_descriptors = true;
        cmd_.u.threedm_gnss_message_format.num_descriptors = (uint8_t)descriptors_count;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_threedm_gnss_message_format_default(mipc_link_t *link,
                                                            const mipc_descriptor_rate_t *descriptors,
                                                            size_t descriptors_count) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    if (descriptors_count > 83u) {
        return mipc_link_fail(link, MIPC_RESULT_REFUSED, "descriptors: more than 83 elements");
    }
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_THREEDM_GNSS_MESSAGE_FORMAT;
        cmd_.u.threedm_gnss_message_format.function = MIPC_FUNCTION_SELECTOR_DEFAULT;
        cmd_.u.threedm_gnss_message_format.has_descriptors = true;
        if (descriptors_count > 0) {
            memcpy(cmd_.u.threedm_gnss_message_format.descriptors, descriptors,
                   descriptors_count * sizeof cmd_.u.threedm_gnss_message_format.descriptors[0]);
        }
        cmd_.u.threedm_gnss_message_format.has_num_descriptors = true;
        cmd_.u.threedm_gnss_message_format.num_descriptors = (uint8_t)descriptors_count;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_threedm_filter_message_format_write(mipc_link_t *link,
                                                            const mipc_descriptor_rate_t *descriptors,
                                                            size_t descriptors_count) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    if (descriptors_count > 83u) {
        return mipc_link_fail(link, MIPC_RESULT_REFUSED, "descriptors: more than 83 elements");
    }
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_THREEDM_FILTER_MESSAGE_FORMAT;
        cmd_.u.threedm_filter_message_format.function = MIPC_FUNCTION_SELECTOR_WRITE;
        cmd_.u.threedm_filter_message_format.has_descriptors = true;
        if (descriptors_count > 0) {
            memcpy(cmd_.u.threedm_filter_message_format.descriptors, descriptors,
                   descriptors_count * sizeof cmd_.u.threedm_filter_message_format.descriptors[0]);
        }
        cmd_.u.threedm_filter_message_format.has_num_descriptors = true;
        cmd_.u.threedm_filter_message_format.num_descriptors = (uint8_t)descriptors_count;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t
mipc_threedm_filter_message_format_read(mipc_link_t *link, const mipc_descriptor_rate_t *descriptors,
                                        size_t descriptors_count,
                                        mipc_threedm_filter_message_format_response_t *reply) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    mipc_result_t result_;
    if (descriptors_count > 83u) {
        return mipc_link_fail(link, MIPC_RESULT_REFUSED, "descriptors: more than 83 elements");
    }
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_THREEDM_FILTER_MESSAGE_FORMAT;
        cmd_.u.threedm_filter_message_format.function = MIPC_FUNCTION_SELECTOR_READ;
        cmd_.u.threedm_filter_message_format.has_descriptors = true;
        if (descriptors_count > 0) {
            memcpy(cmd_.u.threedm_filter_message_format.descriptors, descriptors,
                   descriptors_count * sizeof cmd_.u.threedm_filter_message_format.descriptors[0]);
        }
        cmd_.u.threedm_filter_message_format.has_num_descriptors = true;
        cmd_.u.threedm_filter_message_format.num_descriptors = (uint8_t)descriptors_count;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, &result_);
    if (kind_ == MIPC_RESULT_ACK && reply != NULL) {
        mipc_field_entry_t entry_;
        if (!mipc_result_reply_entry(&result_, &entry_) || entry_.descriptor != 0x82 ||
            mipc_threedm_filter_message_format_response_decode(entry_.data, entry_.length, reply, NULL) !=
                MIPC_OK) {
            return mipc_link_fail(link, MIPC_RESULT_INVALID, "missing reply field 0x82");
        }
    }
    return kind_;
}

mipc_result_kind_t mipc_threedm_filter_message_format_save(mipc_link_t *link,
                                                           const mipc_descriptor_rate_t *descriptors,
                                                           size_t descriptors_count) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    if (descriptors_count > 83u) {
        return mipc_link_fail(link, MIPC_RESULT_REFUSED, "descriptors: more than 83 elements");
    }
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_THREEDM_FILTER_MESSAGE_FORMAT;
        cmd_.u.threedm_filter_message_format.function = MIPC_FUNCTION_SELECTOR_SAVE;
        cmd_.u.threedm_filter_message_format.has_descriptors = true;
        if (descriptors_count > 0) {
            memcpy(cmd_.u.threedm_filter_message_format.descriptors, descriptors,
                   descriptors_count * sizeof cmd_.u.threedm_filter_message_format.descriptors[0]);
        }
        cmd_.u.threedm_filter_message_format.has_num_descriptors = true;
        cmd_.u.threedm_filter_message_format.num_descriptors = (uint8_t)descriptors_count;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_threedm_filter_message_format_load(mipc_link_t *link,
                                                           const mipc_descriptor_rate_t *descriptors,
                                                           size_t descriptors_count) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    if (descriptors_count > 83u) {
        return mipc_link_fail(link, MIPC_RESULT_REFUSED, "descriptors: more than 83 elements");
    }
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_THREEDM_FILTER_MESSAGE_FORMAT;
        cmd_.u.threedm_filter_message_format.function = MIPC_FUNCTION_SELECTOR_LOAD;
        cmd_.u.threedm_filter_message_format.has_descriptors = true;
        if (descriptors_count > 0) {
            memcpy(cmd_.u.threedm_filter_message_format.descriptors, descriptors,
                   descriptors_count * sizeof cmd_.u.threedm_filter_message_format.descriptors[0]);
        }
        cmd_.u.threedm_filter_message_format.has_num_descriptors = true;
        cmd_.u.threedm_filter_message_format.num_descriptors = (uint8_t)descriptors_count;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_threedm_filter_message_format_default(mipc_link_t *link,
                                                              const mipc_descriptor_rate_t *descriptors,
                                                              size_t descriptors_count) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    if (descriptors_count > 83u) {
        return mipc_link_fail(link, MIPC_RESULT_REFUSED, "descriptors: more than 83 elements");
    }
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_THREEDM_FILTER_MESSAGE_FORMAT;
        cmd_.u.threedm_filter_message_format.function = MIPC_FUNCTION_SELECTOR_DEFAULT;
        cmd_.u.threedm_filter_message_format.has_descriptors = true;
        if (descriptors_count > 0) {
            memcpy(cmd_.u.threedm_filter_message_format.descriptors, descriptors,
                   descriptors_count * sizeof cmd_.u.threedm_filter_message_format.descriptors[0]);
        }
        cmd_.u.threedm_filter_message_format.has_num_descriptors = true;
        cmd_.u.threedm_filter_message_format.num_descriptors = (uint8_t)descriptors_count;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_threedm_nmea_message_format_write(mipc_link_t *link,
                                                          const mipc_nmea_message_t *format_entries,
                                                          size_t format_entries_count) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    if (format_entries_count > 50u) {
        return mipc_link_fail(link, MIPC_RESULT_REFUSED, "format_entries: more than 50 elements");
    }
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_THREEDM_NMEA_MESSAGE_FORMAT;
        cmd_.u.threedm_nmea_message_format.function = MIPC_FUNCTION_SELECTOR_WRITE;
        cmd_.u.threedm_nmea_message_format.has_format_entries = true;
        if (format_entries_count > 0) {
            memcpy(cmd_.u.threedm_nmea_message_format.format_entries, format_entries,
                   format_entries_count * sizeof cmd_.u.threedm_nmea_message_format.format_entries[0]);
        }
        cmd_.u.threedm_nmea_message_format.has_count = true;
        cmd_.u.threedm_nmea_message_format.count = (uint8_t)format_entries_count;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_threedm_nmea_message_format_read(mipc_link_t *link,
                                                         mipc_threedm_nmea_message_format_response_t *reply) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    mipc_result_t result_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_THREEDM_NMEA_MESSAGE_FORMAT;
        cmd_.u.threedm_nmea_message_format.function = MIPC_FUNCTION_SELECTOR_READ;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, &result_);
    if (kind_ == MIPC_RESULT_ACK && reply != NULL) {
        mipc_field_entry_t entry_;
        if (!mipc_result_reply_entry(&result_, &entry_) || entry_.descriptor != 0x8C ||
            mipc_threedm_nmea_message_format_response_decode(entry_.data, entry_.length, reply, NULL) !=
                MIPC_OK) {
            return mipc_link_fail(link, MIPC_RESULT_INVALID, "missing reply field 0x8C");
        }
    }
    return kind_;
}

mipc_result_kind_t mipc_threedm_nmea_message_format_save(mipc_link_t *link) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_THREEDM_NMEA_MESSAGE_FORMAT;
        cmd_.u.threedm_nmea_message_format.function = MIPC_FUNCTION_SELECTOR_SAVE;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_threedm_nmea_message_format_load(mipc_link_t *link) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_THREEDM_NMEA_MESSAGE_FORMAT;
        cmd_.u.threedm_nmea_message_format.function = MIPC_FUNCTION_SELECTOR_LOAD;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_threedm_nmea_message_format_default(mipc_link_t *link) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_THREEDM_NMEA_MESSAGE_FORMAT;
        cmd_.u.threedm_nmea_message_format.function = MIPC_FUNCTION_SELECTOR_DEFAULT;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_threedm_message_format_write(mipc_link_t *link, uint8_t desc_set,
                                                     const mipc_descriptor_rate_t *descriptors,
                                                     size_t descriptors_count) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    if (descriptors_count > 83u) {
        return mipc_link_fail(link, MIPC_RESULT_REFUSED, "descriptors: more than 83 elements");
    }
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_THREEDM_MESSAGE_FORMAT;
        cmd_.u.threedm_message_format.function = MIPC_FUNCTION_SELECTOR_WRITE;
        cmd_.u.threedm_message_format.desc_set = desc_set;
        cmd_.u.threedm_message_format.has_descriptors = true;
        if (descriptors_count > 0) {
            memcpy(cmd_.u.threedm_message_format.descriptors, descriptors,
                   descriptors_count * sizeof cmd_.u.threedm_message_format.descriptors[0]);
        }
        cmd_.u.threedm_message_format.has_num_descriptors = true;
        cmd_.u.threedm_message_format.num_descriptors = (uint8_t)descriptors_count;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_threedm_message_format_read(mipc_link_t *link, uint8_t desc_set,
                                                    mipc_threedm_message_format_response_t *reply) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    mipc_result_t result_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_THREEDM_MESSAGE_FORMAT;
        cmd_.u.threedm_message_format.function = MIPC_FUNCTION_SELECTOR_READ;
        cmd_.u.threedm_message_format.desc_set = desc_set;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, &result_);
    if (kind_ == MIPC_RESULT_ACK && reply != NULL) {
        mipc_field_entry_t entry_;
        if (!mipc_result_reply_entry(&result_, &entry_) || entry_.descriptor != 0x8F ||
            mipc_threedm_message_format_response_decode(entry_.data, entry_.length, reply, NULL) != MIPC_OK) {
            return mipc_link_fail(link, MIPC_RESULT_INVALID, "missing reply field 0x8F");
        }
    }
    return kind_;
}

mipc_result_kind_t mipc_threedm_message_format_save(mipc_link_t *link, uint8_t desc_set) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_THREEDM_MESSAGE_FORMAT;
        cmd_.u.threedm_message_format.function = MIPC_FUNCTION_SELECTOR_SAVE;
        cmd_.u.threedm_message_format.desc_set = desc_set;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_threedm_message_format_load(mipc_link_t *link, uint8_t desc_set) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_THREEDM_MESSAGE_FORMAT;
        cmd_.u.threedm_message_format.function = MIPC_FUNCTION_SELECTOR_LOAD;
        cmd_.u.threedm_message_format.desc_set = desc_set;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_threedm_message_format_default(mipc_link_t *link, uint8_t desc_set) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_THREEDM_MESSAGE_FORMAT;
        cmd_.u.threedm_message_format.function = MIPC_FUNCTION_SELECTOR_DEFAULT;
        cmd_.u.threedm_message_format.desc_set = desc_set;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_threedm_factory_streaming(mipc_link_t *link, mipc_factory_streaming_action_t action,
                                                  uint8_t reserved) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_THREEDM_FACTORY_STREAMING;
        cmd_.u.threedm_factory_streaming.action = action;
        cmd_.u.threedm_factory_streaming.reserved = reserved;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_threedm_data_stream_control_write_gx5_45(mipc_link_t *link,
                                                                 mipc_gx5_stream_selector_t device_selector,
                                                                 uint8_t enable) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_THREEDM_DATA_STREAM_CONTROL_GX5_45;
        cmd_.u.threedm_data_stream_control_gx5_45.function = MIPC_FUNCTION_SELECTOR_WRITE;
        cmd_.u.threedm_data_stream_control_gx5_45.device_selector = device_selector;
        cmd_.u.threedm_data_stream_control_gx5_45.has_enable = true;
        cmd_.u.threedm_data_stream_control_gx5_45.enable = enable;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_threedm_data_stream_control_write_cv7_ins(mipc_link_t *link, uint8_t desc_set,
                                                                  bool enable) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_THREEDM_DATA_STREAM_CONTROL_CV7_INS;
        cmd_.u.threedm_data_stream_control_cv7_ins.function = MIPC_FUNCTION_SELECTOR_WRITE;
        cmd_.u.threedm_data_stream_control_cv7_ins.desc_set = desc_set;
        cmd_.u.threedm_data_stream_control_cv7_ins.has_enable = true;
        cmd_.u.threedm_data_stream_control_cv7_ins.enable = enable;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_threedm_data_stream_control_read_gx5_45(mipc_link_t *link,
                                                                mipc_gx5_stream_selector_t device_selector,
                                                                uint8_t enable, mipc_field_value_t *reply) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    mipc_result_t result_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_THREEDM_DATA_STREAM_CONTROL_GX5_45;
        cmd_.u.threedm_data_stream_control_gx5_45.function = MIPC_FUNCTION_SELECTOR_READ;
        cmd_.u.threedm_data_stream_control_gx5_45.device_selector = device_selector;
        cmd_.u.threedm_data_stream_control_gx5_45.has_enable = true;
        cmd_.u.threedm_data_stream_control_gx5_45.enable = enable;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, &result_);
    if (kind_ == MIPC_RESULT_ACK && reply != NULL) {
        if (mipc_link_reply(link, &result_, reply) != MIPC_OK) {
            return mipc_link_fail(link, MIPC_RESULT_INVALID, "the reply field does not decode");
        }
    }
    return kind_;
}

mipc_result_kind_t mipc_threedm_data_stream_control_read_cv7_ins(mipc_link_t *link, uint8_t desc_set,
                                                                 mipc_field_value_t *reply) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    mipc_result_t result_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_THREEDM_DATA_STREAM_CONTROL_CV7_INS;
        cmd_.u.threedm_data_stream_control_cv7_ins.function = MIPC_FUNCTION_SELECTOR_READ;
        cmd_.u.threedm_data_stream_control_cv7_ins.desc_set = desc_set;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, &result_);
    if (kind_ == MIPC_RESULT_ACK && reply != NULL) {
        if (mipc_link_reply(link, &result_, reply) != MIPC_OK) {
            return mipc_link_fail(link, MIPC_RESULT_INVALID, "the reply field does not decode");
        }
    }
    return kind_;
}

mipc_result_kind_t mipc_threedm_data_stream_control_save_gx5_45(mipc_link_t *link,
                                                                mipc_gx5_stream_selector_t device_selector,
                                                                uint8_t enable) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_THREEDM_DATA_STREAM_CONTROL_GX5_45;
        cmd_.u.threedm_data_stream_control_gx5_45.function = MIPC_FUNCTION_SELECTOR_SAVE;
        cmd_.u.threedm_data_stream_control_gx5_45.device_selector = device_selector;
        cmd_.u.threedm_data_stream_control_gx5_45.has_enable = true;
        cmd_.u.threedm_data_stream_control_gx5_45.enable = enable;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_threedm_data_stream_control_save_cv7_ins(mipc_link_t *link, uint8_t desc_set) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_THREEDM_DATA_STREAM_CONTROL_CV7_INS;
        cmd_.u.threedm_data_stream_control_cv7_ins.function = MIPC_FUNCTION_SELECTOR_SAVE;
        cmd_.u.threedm_data_stream_control_cv7_ins.desc_set = desc_set;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_threedm_data_stream_control_load_gx5_45(mipc_link_t *link,
                                                                mipc_gx5_stream_selector_t device_selector,
                                                                uint8_t enable) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_THREEDM_DATA_STREAM_CONTROL_GX5_45;
        cmd_.u.threedm_data_stream_control_gx5_45.function = MIPC_FUNCTION_SELECTOR_LOAD;
        cmd_.u.threedm_data_stream_control_gx5_45.device_selector = device_selector;
        cmd_.u.threedm_data_stream_control_gx5_45.has_enable = true;
        cmd_.u.threedm_data_stream_control_gx5_45.enable = enable;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_threedm_data_stream_control_load_cv7_ins(mipc_link_t *link, uint8_t desc_set) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_THREEDM_DATA_STREAM_CONTROL_CV7_INS;
        cmd_.u.threedm_data_stream_control_cv7_ins.function = MIPC_FUNCTION_SELECTOR_LOAD;
        cmd_.u.threedm_data_stream_control_cv7_ins.desc_set = desc_set;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_threedm_data_stream_control_default_gx5_45(mipc_link_t *link,
                                                                   mipc_gx5_stream_selector_t device_selector,
                                                                   uint8_t enable) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_THREEDM_DATA_STREAM_CONTROL_GX5_45;
        cmd_.u.threedm_data_stream_control_gx5_45.function = MIPC_FUNCTION_SELECTOR_DEFAULT;
        cmd_.u.threedm_data_stream_control_gx5_45.device_selector = device_selector;
        cmd_.u.threedm_data_stream_control_gx5_45.has_enable = true;
        cmd_.u.threedm_data_stream_control_gx5_45.enable = enable;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_threedm_data_stream_control_default_cv7_ins(mipc_link_t *link, uint8_t desc_set) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_THREEDM_DATA_STREAM_CONTROL_CV7_INS;
        cmd_.u.threedm_data_stream_control_cv7_ins.function = MIPC_FUNCTION_SELECTOR_DEFAULT;
        cmd_.u.threedm_data_stream_control_cv7_ins.desc_set = desc_set;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_threedm_raw_rtcm_message(mipc_link_t *link, const uint8_t *data, size_t data_count) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    if (data_count > 253u) {
        return mipc_link_fail(link, MIPC_RESULT_REFUSED, "data: more than 253 elements");
    }
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_THREEDM_RAW_RTCM_MESSAGE;
        if (data_count > 0) {
            memcpy(cmd_.u.threedm_raw_rtcm_message.data, data,
                   data_count * sizeof cmd_.u.threedm_raw_rtcm_message.data[0]);
        }
        cmd_.u.threedm_raw_rtcm_message.data_count = data_count;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t
mipc_threedm_gnss_constellation_settings_write(mipc_link_t *link, uint16_t max_channels,
                                               const mipc_constellation_settings_t *settings,
                                               size_t settings_count) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    if (settings_count > 41u) {
        return mipc_link_fail(link, MIPC_RESULT_REFUSED, "settings: more than 41 elements");
    }
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_THREEDM_GNSS_CONSTELLATION_SETTINGS;
        cmd_.u.threedm_gnss_constellation_settings.function = MIPC_FUNCTION_SELECTOR_WRITE;
        cmd_.u.threedm_gnss_constellation_settings.has_max_channels = true;
        cmd_.u.threedm_gnss_constellation_settings.max_channels = max_channels;
        cmd_.u.threedm_gnss_constellation_settings.has_settings = true;
        if (settings_count > 0) {
            memcpy(cmd_.u.threedm_gnss_constellation_settings.settings, settings,
                   settings_count * sizeof cmd_.u.threedm_gnss_constellation_settings.settings[0]);
        }
        cmd_.u.threedm_gnss_constellation_settings.has_config_count = true;
        cmd_.u.threedm_gnss_constellation_settings.config_count = (uint8_t)settings_count;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_threedm_gnss_constellation_settings_read(
    mipc_link_t *link, uint16_t max_channels, const mipc_constellation_settings_t *settings,
    size_t settings_count, mipc_threedm_gnss_constellation_settings_response_t *reply) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    mipc_result_t result_;
    if (settings_count > 41u) {
        return mipc_link_fail(link, MIPC_RESULT_REFUSED, "settings: more than 41 elements");
    }
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_THREEDM_GNSS_CONSTELLATION_SETTINGS;
        cmd_.u.threedm_gnss_constellation_settings.function = MIPC_FUNCTION_SELECTOR_READ;
        cmd_.u.threedm_gnss_constellation_settings.has_max_channels = true;
        cmd_.u.threedm_gnss_constellation_settings.max_channels = max_channels;
        cmd_.u.threedm_gnss_constellation_settings.has_settings = true;
        if (settings_count > 0) {
            memcpy(cmd_.u.threedm_gnss_constellation_settings.settings, settings,
                   settings_count * sizeof cmd_.u.threedm_gnss_constellation_settings.settings[0]);
        }
        cmd_.u.threedm_gnss_constellation_settings.has_config_count = true;
        cmd_.u.threedm_gnss_constellation_settings.config_count = (uint8_t)settings_count;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, &result_);
    if (kind_ == MIPC_RESULT_ACK && reply != NULL) {
        mipc_field_entry_t entry_;
        if (!mipc_result_reply_entry(&result_, &entry_) || entry_.descriptor != 0xA0 ||
            mipc_threedm_gnss_constellation_settings_response_decode(entry_.data, entry_.length, reply,
                                                                     NULL) != MIPC_OK) {
            return mipc_link_fail(link, MIPC_RESULT_INVALID, "missing reply field 0xA0");
        }
    }
    return kind_;
}

mipc_result_kind_t
mipc_threedm_gnss_constellation_settings_save(mipc_link_t *link, uint16_t max_channels,
                                              const mipc_constellation_settings_t *settings,
                                              size_t settings_count) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    if (settings_count > 41u) {
        return mipc_link_fail(link, MIPC_RESULT_REFUSED, "settings: more than 41 elements");
    }
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_THREEDM_GNSS_CONSTELLATION_SETTINGS;
        cmd_.u.threedm_gnss_constellation_settings.function = MIPC_FUNCTION_SELECTOR_SAVE;
        cmd_.u.threedm_gnss_constellation_settings.has_max_channels = true;
        cmd_.u.threedm_gnss_constellation_settings.max_channels = max_channels;
        cmd_.u.threedm_gnss_constellation_settings.has_settings = true;
        if (settings_count > 0) {
            memcpy(cmd_.u.threedm_gnss_constellation_settings.settings, settings,
                   settings_count * sizeof cmd_.u.threedm_gnss_constellation_settings.settings[0]);
        }
        cmd_.u.threedm_gnss_constellation_settings.has_config_count = true;
        cmd_.u.threedm_gnss_constellation_settings.config_count = (uint8_t)settings_count;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t
mipc_threedm_gnss_constellation_settings_load(mipc_link_t *link, uint16_t max_channels,
                                              const mipc_constellation_settings_t *settings,
                                              size_t settings_count) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    if (settings_count > 41u) {
        return mipc_link_fail(link, MIPC_RESULT_REFUSED, "settings: more than 41 elements");
    }
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_THREEDM_GNSS_CONSTELLATION_SETTINGS;
        cmd_.u.threedm_gnss_constellation_settings.function = MIPC_FUNCTION_SELECTOR_LOAD;
        cmd_.u.threedm_gnss_constellation_settings.has_max_channels = true;
        cmd_.u.threedm_gnss_constellation_settings.max_channels = max_channels;
        cmd_.u.threedm_gnss_constellation_settings.has_settings = true;
        if (settings_count > 0) {
            memcpy(cmd_.u.threedm_gnss_constellation_settings.settings, settings,
                   settings_count * sizeof cmd_.u.threedm_gnss_constellation_settings.settings[0]);
        }
        cmd_.u.threedm_gnss_constellation_settings.has_config_count = true;
        cmd_.u.threedm_gnss_constellation_settings.config_count = (uint8_t)settings_count;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t
mipc_threedm_gnss_constellation_settings_default(mipc_link_t *link, uint16_t max_channels,
                                                 const mipc_constellation_settings_t *settings,
                                                 size_t settings_count) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    if (settings_count > 41u) {
        return mipc_link_fail(link, MIPC_RESULT_REFUSED, "settings: more than 41 elements");
    }
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_THREEDM_GNSS_CONSTELLATION_SETTINGS;
        cmd_.u.threedm_gnss_constellation_settings.function = MIPC_FUNCTION_SELECTOR_DEFAULT;
        cmd_.u.threedm_gnss_constellation_settings.has_max_channels = true;
        cmd_.u.threedm_gnss_constellation_settings.max_channels = max_channels;
        cmd_.u.threedm_gnss_constellation_settings.has_settings = true;
        if (settings_count > 0) {
            memcpy(cmd_.u.threedm_gnss_constellation_settings.settings, settings,
                   settings_count * sizeof cmd_.u.threedm_gnss_constellation_settings.settings[0]);
        }
        cmd_.u.threedm_gnss_constellation_settings.has_config_count = true;
        cmd_.u.threedm_gnss_constellation_settings.config_count = (uint8_t)settings_count;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_threedm_gnss_sbas_settings_write(mipc_link_t *link, uint8_t enable_sbas,
                                                         mipc_sbas_options_t sbas_options,
                                                         const uint16_t *included_prns,
                                                         size_t included_prns_count) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    if (included_prns_count > 124u) {
        return mipc_link_fail(link, MIPC_RESULT_REFUSED, "included_prns: more than 124 elements");
    }
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_THREEDM_GNSS_SBAS_SETTINGS;
        cmd_.u.threedm_gnss_sbas_settings.function = MIPC_FUNCTION_SELECTOR_WRITE;
        cmd_.u.threedm_gnss_sbas_settings.has_enable_sbas = true;
        cmd_.u.threedm_gnss_sbas_settings.enable_sbas = enable_sbas;
        cmd_.u.threedm_gnss_sbas_settings.has_sbas_options = true;
        cmd_.u.threedm_gnss_sbas_settings.sbas_options = sbas_options;
        cmd_.u.threedm_gnss_sbas_settings.has_included_prns = true;
        if (included_prns_count > 0) {
            memcpy(cmd_.u.threedm_gnss_sbas_settings.included_prns, included_prns,
                   included_prns_count * sizeof cmd_.u.threedm_gnss_sbas_settings.included_prns[0]);
        }
        cmd_.u.threedm_gnss_sbas_settings.has_num_included_prns = true;
        cmd_.u.threedm_gnss_sbas_settings.num_included_prns = (uint8_t)included_prns_count;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_threedm_gnss_sbas_settings_read(mipc_link_t *link,
                                                        mipc_threedm_gnss_sbas_settings_response_t *reply) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    mipc_result_t result_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_THREEDM_GNSS_SBAS_SETTINGS;
        cmd_.u.threedm_gnss_sbas_settings.function = MIPC_FUNCTION_SELECTOR_READ;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, &result_);
    if (kind_ == MIPC_RESULT_ACK && reply != NULL) {
        mipc_field_entry_t entry_;
        if (!mipc_result_reply_entry(&result_, &entry_) || entry_.descriptor != 0xA1 ||
            mipc_threedm_gnss_sbas_settings_response_decode(entry_.data, entry_.length, reply, NULL) !=
                MIPC_OK) {
            return mipc_link_fail(link, MIPC_RESULT_INVALID, "missing reply field 0xA1");
        }
    }
    return kind_;
}

mipc_result_kind_t mipc_threedm_gnss_sbas_settings_save(mipc_link_t *link) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_THREEDM_GNSS_SBAS_SETTINGS;
        cmd_.u.threedm_gnss_sbas_settings.function = MIPC_FUNCTION_SELECTOR_SAVE;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_threedm_gnss_sbas_settings_load(mipc_link_t *link) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_THREEDM_GNSS_SBAS_SETTINGS;
        cmd_.u.threedm_gnss_sbas_settings.function = MIPC_FUNCTION_SELECTOR_LOAD;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_threedm_gnss_sbas_settings_default(mipc_link_t *link) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_THREEDM_GNSS_SBAS_SETTINGS;
        cmd_.u.threedm_gnss_sbas_settings.function = MIPC_FUNCTION_SELECTOR_DEFAULT;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_threedm_gnss_assisted_fix_control_write(mipc_link_t *link,
                                                                mipc_assisted_fix_option_t option,
                                                                uint8_t flags) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_THREEDM_GNSS_ASSISTED_FIX_CONTROL;
        cmd_.u.threedm_gnss_assisted_fix_control.function = MIPC_FUNCTION_SELECTOR_WRITE;
        cmd_.u.threedm_gnss_assisted_fix_control.has_option = true;
        cmd_.u.threedm_gnss_assisted_fix_control.option = option;
        cmd_.u.threedm_gnss_assisted_fix_control.has_flags = true;
        cmd_.u.threedm_gnss_assisted_fix_control.flags = flags;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t
mipc_threedm_gnss_assisted_fix_control_read(mipc_link_t *link, mipc_assisted_fix_option_t option,
                                            uint8_t flags,
                                            mipc_threedm_gnss_assisted_fix_control_response_t *reply) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    mipc_result_t result_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_THREEDM_GNSS_ASSISTED_FIX_CONTROL;
        cmd_.u.threedm_gnss_assisted_fix_control.function = MIPC_FUNCTION_SELECTOR_READ;
        cmd_.u.threedm_gnss_assisted_fix_control.has_option = true;
        cmd_.u.threedm_gnss_assisted_fix_control.option = option;
        cmd_.u.threedm_gnss_assisted_fix_control.has_flags = true;
        cmd_.u.threedm_gnss_assisted_fix_control.flags = flags;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, &result_);
    if (kind_ == MIPC_RESULT_ACK && reply != NULL) {
        mipc_field_entry_t entry_;
        if (!mipc_result_reply_entry(&result_, &entry_) || entry_.descriptor != 0xA2 ||
            mipc_threedm_gnss_assisted_fix_control_response_decode(entry_.data, entry_.length, reply, NULL) !=
                MIPC_OK) {
            return mipc_link_fail(link, MIPC_RESULT_INVALID, "missing reply field 0xA2");
        }
    }
    return kind_;
}

mipc_result_kind_t mipc_threedm_gnss_assisted_fix_control_save(mipc_link_t *link,
                                                               mipc_assisted_fix_option_t option,
                                                               uint8_t flags) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_THREEDM_GNSS_ASSISTED_FIX_CONTROL;
        cmd_.u.threedm_gnss_assisted_fix_control.function = MIPC_FUNCTION_SELECTOR_SAVE;
        cmd_.u.threedm_gnss_assisted_fix_control.has_option = true;
        cmd_.u.threedm_gnss_assisted_fix_control.option = option;
        cmd_.u.threedm_gnss_assisted_fix_control.has_flags = true;
        cmd_.u.threedm_gnss_assisted_fix_control.flags = flags;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_threedm_gnss_assisted_fix_control_load(mipc_link_t *link,
                                                               mipc_assisted_fix_option_t option,
                                                               uint8_t flags) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_THREEDM_GNSS_ASSISTED_FIX_CONTROL;
        cmd_.u.threedm_gnss_assisted_fix_control.function = MIPC_FUNCTION_SELECTOR_LOAD;
        cmd_.u.threedm_gnss_assisted_fix_control.has_option = true;
        cmd_.u.threedm_gnss_assisted_fix_control.option = option;
        cmd_.u.threedm_gnss_assisted_fix_control.has_flags = true;
        cmd_.u.threedm_gnss_assisted_fix_control.flags = flags;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_threedm_gnss_assisted_fix_control_default(mipc_link_t *link,
                                                                  mipc_assisted_fix_option_t option,
                                                                  uint8_t flags) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_THREEDM_GNSS_ASSISTED_FIX_CONTROL;
        cmd_.u.threedm_gnss_assisted_fix_control.function = MIPC_FUNCTION_SELECTOR_DEFAULT;
        cmd_.u.threedm_gnss_assisted_fix_control.has_option = true;
        cmd_.u.threedm_gnss_assisted_fix_control.option = option;
        cmd_.u.threedm_gnss_assisted_fix_control.has_flags = true;
        cmd_.u.threedm_gnss_assisted_fix_control.flags = flags;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_threedm_gnss_assist_time_update_write(mipc_link_t *link, double tow,
                                                              uint16_t week_number, float accuracy) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_THREEDM_GNSS_ASSIST_TIME_UPDATE;
        cmd_.u.threedm_gnss_assist_time_update.function = MIPC_FUNCTION_SELECTOR_WRITE;
        cmd_.u.threedm_gnss_assist_time_update.has_tow = true;
        cmd_.u.threedm_gnss_assist_time_update.tow = tow;
        cmd_.u.threedm_gnss_assist_time_update.has_week_number = true;
        cmd_.u.threedm_gnss_assist_time_update.week_number = week_number;
        cmd_.u.threedm_gnss_assist_time_update.has_accuracy = true;
        cmd_.u.threedm_gnss_assist_time_update.accuracy = accuracy;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t
mipc_threedm_gnss_assist_time_update_read(mipc_link_t *link, double tow, uint16_t week_number, float accuracy,
                                          mipc_threedm_gnss_assist_time_update_response_t *reply) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    mipc_result_t result_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_THREEDM_GNSS_ASSIST_TIME_UPDATE;
        cmd_.u.threedm_gnss_assist_time_update.function = MIPC_FUNCTION_SELECTOR_READ;
        cmd_.u.threedm_gnss_assist_time_update.has_tow = true;
        cmd_.u.threedm_gnss_assist_time_update.tow = tow;
        cmd_.u.threedm_gnss_assist_time_update.has_week_number = true;
        cmd_.u.threedm_gnss_assist_time_update.week_number = week_number;
        cmd_.u.threedm_gnss_assist_time_update.has_accuracy = true;
        cmd_.u.threedm_gnss_assist_time_update.accuracy = accuracy;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, &result_);
    if (kind_ == MIPC_RESULT_ACK && reply != NULL) {
        mipc_field_entry_t entry_;
        if (!mipc_result_reply_entry(&result_, &entry_) || entry_.descriptor != 0xA3 ||
            mipc_threedm_gnss_assist_time_update_response_decode(entry_.data, entry_.length, reply, NULL) !=
                MIPC_OK) {
            return mipc_link_fail(link, MIPC_RESULT_INVALID, "missing reply field 0xA3");
        }
    }
    return kind_;
}

mipc_result_kind_t mipc_threedm_pps_source_write(mipc_link_t *link, mipc_pps_source_t source) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_THREEDM_PPS_SOURCE;
        cmd_.u.threedm_pps_source.function = MIPC_FUNCTION_SELECTOR_WRITE;
        cmd_.u.threedm_pps_source.has_source = true;
        cmd_.u.threedm_pps_source.source = source;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_threedm_pps_source_read(mipc_link_t *link,
                                                mipc_threedm_pps_source_response_t *reply) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    mipc_result_t result_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_THREEDM_PPS_SOURCE;
        cmd_.u.threedm_pps_source.function = MIPC_FUNCTION_SELECTOR_READ;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, &result_);
    if (kind_ == MIPC_RESULT_ACK && reply != NULL) {
        mipc_field_entry_t entry_;
        if (!mipc_result_reply_entry(&result_, &entry_) || entry_.descriptor != 0xA8 ||
            mipc_threedm_pps_source_response_decode(entry_.data, entry_.length, reply, NULL) != MIPC_OK) {
            return mipc_link_fail(link, MIPC_RESULT_INVALID, "missing reply field 0xA8");
        }
    }
    return kind_;
}

mipc_result_kind_t mipc_threedm_pps_source_save(mipc_link_t *link) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_THREEDM_PPS_SOURCE;
        cmd_.u.threedm_pps_source.function = MIPC_FUNCTION_SELECTOR_SAVE;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_threedm_pps_source_load(mipc_link_t *link) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_THREEDM_PPS_SOURCE;
        cmd_.u.threedm_pps_source.function = MIPC_FUNCTION_SELECTOR_LOAD;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_threedm_pps_source_default(mipc_link_t *link) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_THREEDM_PPS_SOURCE;
        cmd_.u.threedm_pps_source.function = MIPC_FUNCTION_SELECTOR_DEFAULT;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_threedm_get_supported_events(mipc_link_t *link, mipc_supported_events_query_t query,
                                                     mipc_threedm_supported_events_t *reply) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    mipc_result_t result_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_THREEDM_GET_SUPPORTED_EVENTS;
        cmd_.u.threedm_get_supported_events.query = query;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, &result_);
    if (kind_ == MIPC_RESULT_ACK && reply != NULL) {
        mipc_field_entry_t entry_;
        if (!mipc_result_reply_entry(&result_, &entry_) || entry_.descriptor != 0xB4 ||
            mipc_threedm_supported_events_decode(entry_.data, entry_.length, reply, NULL) != MIPC_OK) {
            return mipc_link_fail(link, MIPC_RESULT_INVALID, "missing reply field 0xB4");
        }
    }
    return kind_;
}

mipc_result_kind_t mipc_threedm_device_status(mipc_link_t *link, uint16_t model_number,
                                              mipc_device_status_selector_t status_selector,
                                              mipc_threedm_device_status_response_t *reply) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    mipc_result_t result_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_THREEDM_DEVICE_STATUS;
        cmd_.u.threedm_device_status.model_number = model_number;
        cmd_.u.threedm_device_status.status_selector = status_selector;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, &result_);
    if (kind_ == MIPC_RESULT_ACK && reply != NULL) {
        mipc_field_entry_t entry_;
        if (!mipc_result_reply_entry(&result_, &entry_) || entry_.descriptor != 0x90 ||
            mipc_threedm_device_status_response_decode(entry_.data, entry_.length, reply, NULL) != MIPC_OK) {
            return mipc_link_fail(link, MIPC_RESULT_INVALID, "missing reply field 0x90");
        }
    }
    return kind_;
}

mipc_result_kind_t mipc_filter_reset_filter(mipc_link_t *link) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_FILTER_RESET_FILTER;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_filter_set_initial_attitude(mipc_link_t *link, float roll, float pitch,
                                                    float heading) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_FILTER_SET_INITIAL_ATTITUDE;
        cmd_.u.filter_set_initial_attitude.roll = roll;
        cmd_.u.filter_set_initial_attitude.pitch = pitch;
        cmd_.u.filter_set_initial_attitude.heading = heading;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_filter_set_initial_heading(mipc_link_t *link, float heading) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_FILTER_SET_INITIAL_HEADING;
        cmd_.u.filter_set_initial_heading.heading = heading;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_filter_run_filter(mipc_link_t *link) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_FILTER_RUN_FILTER;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_filter_vehicle_dynamics_mode_write(mipc_link_t *link,
                                                           mipc_vehicle_dynamics_mode_t mode) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_FILTER_VEHICLE_DYNAMICS_MODE;
        cmd_.u.filter_vehicle_dynamics_mode.function = MIPC_FUNCTION_SELECTOR_WRITE;
        cmd_.u.filter_vehicle_dynamics_mode.has_mode = true;
        cmd_.u.filter_vehicle_dynamics_mode.mode = mode;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t
mipc_filter_vehicle_dynamics_mode_read(mipc_link_t *link,
                                       mipc_filter_vehicle_dynamics_mode_response_t *reply) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    mipc_result_t result_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_FILTER_VEHICLE_DYNAMICS_MODE;
        cmd_.u.filter_vehicle_dynamics_mode.function = MIPC_FUNCTION_SELECTOR_READ;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, &result_);
    if (kind_ == MIPC_RESULT_ACK && reply != NULL) {
        mipc_field_entry_t entry_;
        if (!mipc_result_reply_entry(&result_, &entry_) || entry_.descriptor != 0x80 ||
            mipc_filter_vehicle_dynamics_mode_response_decode(entry_.data, entry_.length, reply, NULL) !=
                MIPC_OK) {
            return mipc_link_fail(link, MIPC_RESULT_INVALID, "missing reply field 0x80");
        }
    }
    return kind_;
}

mipc_result_kind_t mipc_filter_vehicle_dynamics_mode_save(mipc_link_t *link) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_FILTER_VEHICLE_DYNAMICS_MODE;
        cmd_.u.filter_vehicle_dynamics_mode.function = MIPC_FUNCTION_SELECTOR_SAVE;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_filter_vehicle_dynamics_mode_load(mipc_link_t *link) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_FILTER_VEHICLE_DYNAMICS_MODE;
        cmd_.u.filter_vehicle_dynamics_mode.function = MIPC_FUNCTION_SELECTOR_LOAD;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_filter_vehicle_dynamics_mode_default(mipc_link_t *link) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_FILTER_VEHICLE_DYNAMICS_MODE;
        cmd_.u.filter_vehicle_dynamics_mode.function = MIPC_FUNCTION_SELECTOR_DEFAULT;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_filter_sensor_to_vehicle_transform_write(mipc_link_t *link, float roll, float pitch,
                                                                 float yaw) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_FILTER_SENSOR_TO_VEHICLE_TRANSFORM;
        cmd_.u.filter_sensor_to_vehicle_transform.function = MIPC_FUNCTION_SELECTOR_WRITE;
        cmd_.u.filter_sensor_to_vehicle_transform.has_roll = true;
        cmd_.u.filter_sensor_to_vehicle_transform.roll = roll;
        cmd_.u.filter_sensor_to_vehicle_transform.has_pitch = true;
        cmd_.u.filter_sensor_to_vehicle_transform.pitch = pitch;
        cmd_.u.filter_sensor_to_vehicle_transform.has_yaw = true;
        cmd_.u.filter_sensor_to_vehicle_transform.yaw = yaw;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t
mipc_filter_sensor_to_vehicle_transform_read(mipc_link_t *link,
                                             mipc_filter_sensor_to_vehicle_transform_response_t *reply) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    mipc_result_t result_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_FILTER_SENSOR_TO_VEHICLE_TRANSFORM;
        cmd_.u.filter_sensor_to_vehicle_transform.function = MIPC_FUNCTION_SELECTOR_READ;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, &result_);
    if (kind_ == MIPC_RESULT_ACK && reply != NULL) {
        mipc_field_entry_t entry_;
        if (!mipc_result_reply_entry(&result_, &entry_) || entry_.descriptor != 0x81 ||
            mipc_filter_sensor_to_vehicle_transform_response_decode(entry_.data, entry_.length, reply,
                                                                    NULL) != MIPC_OK) {
            return mipc_link_fail(link, MIPC_RESULT_INVALID, "missing reply field 0x81");
        }
    }
    return kind_;
}

mipc_result_kind_t mipc_filter_sensor_to_vehicle_transform_save(mipc_link_t *link) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_FILTER_SENSOR_TO_VEHICLE_TRANSFORM;
        cmd_.u.filter_sensor_to_vehicle_transform.function = MIPC_FUNCTION_SELECTOR_SAVE;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_filter_sensor_to_vehicle_transform_load(mipc_link_t *link) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_FILTER_SENSOR_TO_VEHICLE_TRANSFORM;
        cmd_.u.filter_sensor_to_vehicle_transform.function = MIPC_FUNCTION_SELECTOR_LOAD;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_filter_sensor_to_vehicle_transform_default(mipc_link_t *link) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_FILTER_SENSOR_TO_VEHICLE_TRANSFORM;
        cmd_.u.filter_sensor_to_vehicle_transform.function = MIPC_FUNCTION_SELECTOR_DEFAULT;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_filter_sensor_to_vehicle_offset_write(mipc_link_t *link, const float offset[3]) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_FILTER_SENSOR_TO_VEHICLE_OFFSET;
        cmd_.u.filter_sensor_to_vehicle_offset.function = MIPC_FUNCTION_SELECTOR_WRITE;
        cmd_.u.filter_sensor_to_vehicle_offset.has_offset = true;
        memcpy(cmd_.u.filter_sensor_to_vehicle_offset.offset, offset,
               sizeof cmd_.u.filter_sensor_to_vehicle_offset.offset);
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t
mipc_filter_sensor_to_vehicle_offset_read(mipc_link_t *link,
                                          mipc_filter_sensor_to_vehicle_offset_response_t *reply) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    mipc_result_t result_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_FILTER_SENSOR_TO_VEHICLE_OFFSET;
        cmd_.u.filter_sensor_to_vehicle_offset.function = MIPC_FUNCTION_SELECTOR_READ;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, &result_);
    if (kind_ == MIPC_RESULT_ACK && reply != NULL) {
        mipc_field_entry_t entry_;
        if (!mipc_result_reply_entry(&result_, &entry_) || entry_.descriptor != 0x82 ||
            mipc_filter_sensor_to_vehicle_offset_response_decode(entry_.data, entry_.length, reply, NULL) !=
                MIPC_OK) {
            return mipc_link_fail(link, MIPC_RESULT_INVALID, "missing reply field 0x82");
        }
    }
    return kind_;
}

mipc_result_kind_t mipc_filter_sensor_to_vehicle_offset_save(mipc_link_t *link) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_FILTER_SENSOR_TO_VEHICLE_OFFSET;
        cmd_.u.filter_sensor_to_vehicle_offset.function = MIPC_FUNCTION_SELECTOR_SAVE;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_filter_sensor_to_vehicle_offset_load(mipc_link_t *link) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_FILTER_SENSOR_TO_VEHICLE_OFFSET;
        cmd_.u.filter_sensor_to_vehicle_offset.function = MIPC_FUNCTION_SELECTOR_LOAD;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_filter_sensor_to_vehicle_offset_default(mipc_link_t *link) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_FILTER_SENSOR_TO_VEHICLE_OFFSET;
        cmd_.u.filter_sensor_to_vehicle_offset.function = MIPC_FUNCTION_SELECTOR_DEFAULT;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_filter_antenna_offset_write(mipc_link_t *link, const float offset[3]) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_FILTER_ANTENNA_OFFSET;
        cmd_.u.filter_antenna_offset.function = MIPC_FUNCTION_SELECTOR_WRITE;
        cmd_.u.filter_antenna_offset.has_offset = true;
        memcpy(cmd_.u.filter_antenna_offset.offset, offset, sizeof cmd_.u.filter_antenna_offset.offset);
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_filter_antenna_offset_read(mipc_link_t *link,
                                                   mipc_filter_antenna_offset_response_t *reply) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    mipc_result_t result_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_FILTER_ANTENNA_OFFSET;
        cmd_.u.filter_antenna_offset.function = MIPC_FUNCTION_SELECTOR_READ;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, &result_);
    if (kind_ == MIPC_RESULT_ACK && reply != NULL) {
        mipc_field_entry_t entry_;
        if (!mipc_result_reply_entry(&result_, &entry_) || entry_.descriptor != 0x83 ||
            mipc_filter_antenna_offset_response_decode(entry_.data, entry_.length, reply, NULL) != MIPC_OK) {
            return mipc_link_fail(link, MIPC_RESULT_INVALID, "missing reply field 0x83");
        }
    }
    return kind_;
}

mipc_result_kind_t mipc_filter_antenna_offset_save(mipc_link_t *link) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_FILTER_ANTENNA_OFFSET;
        cmd_.u.filter_antenna_offset.function = MIPC_FUNCTION_SELECTOR_SAVE;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_filter_antenna_offset_load(mipc_link_t *link) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_FILTER_ANTENNA_OFFSET;
        cmd_.u.filter_antenna_offset.function = MIPC_FUNCTION_SELECTOR_LOAD;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_filter_antenna_offset_default(mipc_link_t *link) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_FILTER_ANTENNA_OFFSET;
        cmd_.u.filter_antenna_offset.function = MIPC_FUNCTION_SELECTOR_DEFAULT;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_filter_estimation_control_write(mipc_link_t *link,
                                                        mipc_estimation_control_flags_t flags) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_FILTER_ESTIMATION_CONTROL;
        cmd_.u.filter_estimation_control.function = MIPC_FUNCTION_SELECTOR_WRITE;
        cmd_.u.filter_estimation_control.has_flags = true;
        cmd_.u.filter_estimation_control.flags = flags;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_filter_estimation_control_read(mipc_link_t *link,
                                                       mipc_filter_estimation_control_response_t *reply) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    mipc_result_t result_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_FILTER_ESTIMATION_CONTROL;
        cmd_.u.filter_estimation_control.function = MIPC_FUNCTION_SELECTOR_READ;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, &result_);
    if (kind_ == MIPC_RESULT_ACK && reply != NULL) {
        mipc_field_entry_t entry_;
        if (!mipc_result_reply_entry(&result_, &entry_) || entry_.descriptor != 0x84 ||
            mipc_filter_estimation_control_response_decode(entry_.data, entry_.length, reply, NULL) !=
                MIPC_OK) {
            return mipc_link_fail(link, MIPC_RESULT_INVALID, "missing reply field 0x84");
        }
    }
    return kind_;
}

mipc_result_kind_t mipc_filter_estimation_control_save(mipc_link_t *link) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_FILTER_ESTIMATION_CONTROL;
        cmd_.u.filter_estimation_control.function = MIPC_FUNCTION_SELECTOR_SAVE;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_filter_estimation_control_load(mipc_link_t *link) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_FILTER_ESTIMATION_CONTROL;
        cmd_.u.filter_estimation_control.function = MIPC_FUNCTION_SELECTOR_LOAD;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_filter_estimation_control_default(mipc_link_t *link) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_FILTER_ESTIMATION_CONTROL;
        cmd_.u.filter_estimation_control.function = MIPC_FUNCTION_SELECTOR_DEFAULT;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_filter_gnss_source_control_write(mipc_link_t *link,
                                                         mipc_filter_gnss_source_t source) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_FILTER_GNSS_SOURCE_CONTROL;
        cmd_.u.filter_gnss_source_control.function = MIPC_FUNCTION_SELECTOR_WRITE;
        cmd_.u.filter_gnss_source_control.has_source = true;
        cmd_.u.filter_gnss_source_control.source = source;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_filter_gnss_source_control_read(mipc_link_t *link,
                                                        mipc_filter_gnss_source_control_response_t *reply) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    mipc_result_t result_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_FILTER_GNSS_SOURCE_CONTROL;
        cmd_.u.filter_gnss_source_control.function = MIPC_FUNCTION_SELECTOR_READ;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, &result_);
    if (kind_ == MIPC_RESULT_ACK && reply != NULL) {
        mipc_field_entry_t entry_;
        if (!mipc_result_reply_entry(&result_, &entry_) || entry_.descriptor != 0x86 ||
            mipc_filter_gnss_source_control_response_decode(entry_.data, entry_.length, reply, NULL) !=
                MIPC_OK) {
            return mipc_link_fail(link, MIPC_RESULT_INVALID, "missing reply field 0x86");
        }
    }
    return kind_;
}

mipc_result_kind_t mipc_filter_gnss_source_control_save(mipc_link_t *link) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_FILTER_GNSS_SOURCE_CONTROL;
        cmd_.u.filter_gnss_source_control.function = MIPC_FUNCTION_SELECTOR_SAVE;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_filter_gnss_source_control_load(mipc_link_t *link) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_FILTER_GNSS_SOURCE_CONTROL;
        cmd_.u.filter_gnss_source_control.function = MIPC_FUNCTION_SELECTOR_LOAD;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_filter_gnss_source_control_default(mipc_link_t *link) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_FILTER_GNSS_SOURCE_CONTROL;
        cmd_.u.filter_gnss_source_control.function = MIPC_FUNCTION_SELECTOR_DEFAULT;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_filter_external_gnss_update(mipc_link_t *link, double gps_tow, uint16_t gps_week,
                                                    double latitude, double longitude, double height,
                                                    const float velocity[3],
                                                    const float position_uncertainty[3],
                                                    const float velocity_uncertainty[3]) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_FILTER_EXTERNAL_GNSS_UPDATE;
        cmd_.u.filter_external_gnss_update.gps_tow = gps_tow;
        cmd_.u.filter_external_gnss_update.gps_week = gps_week;
        cmd_.u.filter_external_gnss_update.latitude = latitude;
        cmd_.u.filter_external_gnss_update.longitude = longitude;
        cmd_.u.filter_external_gnss_update.height = height;
        memcpy(cmd_.u.filter_external_gnss_update.velocity, velocity,
               sizeof cmd_.u.filter_external_gnss_update.velocity);
        memcpy(cmd_.u.filter_external_gnss_update.position_uncertainty, position_uncertainty,
               sizeof cmd_.u.filter_external_gnss_update.position_uncertainty);
        memcpy(cmd_.u.filter_external_gnss_update.velocity_uncertainty, velocity_uncertainty,
               sizeof cmd_.u.filter_external_gnss_update.velocity_uncertainty);
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_filter_external_heading_update(mipc_link_t *link, float heading,
                                                       float heading_uncertainty,
                                                       mipc_external_heading_type_t type) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_FILTER_EXTERNAL_HEADING_UPDATE;
        cmd_.u.filter_external_heading_update.heading = heading;
        cmd_.u.filter_external_heading_update.heading_uncertainty = heading_uncertainty;
        cmd_.u.filter_external_heading_update.type = type;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_filter_heading_update_control_write(mipc_link_t *link,
                                                            mipc_heading_update_source_t source) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_FILTER_HEADING_UPDATE_CONTROL;
        cmd_.u.filter_heading_update_control.function = MIPC_FUNCTION_SELECTOR_WRITE;
        cmd_.u.filter_heading_update_control.has_source = true;
        cmd_.u.filter_heading_update_control.source = source;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t
mipc_filter_heading_update_control_read(mipc_link_t *link,
                                        mipc_filter_heading_update_control_response_t *reply) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    mipc_result_t result_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_FILTER_HEADING_UPDATE_CONTROL;
        cmd_.u.filter_heading_update_control.function = MIPC_FUNCTION_SELECTOR_READ;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, &result_);
    if (kind_ == MIPC_RESULT_ACK && reply != NULL) {
        mipc_field_entry_t entry_;
        if (!mipc_result_reply_entry(&result_, &entry_) || entry_.descriptor != 0x87 ||
            mipc_filter_heading_update_control_response_decode(entry_.data, entry_.length, reply, NULL) !=
                MIPC_OK) {
            return mipc_link_fail(link, MIPC_RESULT_INVALID, "missing reply field 0x87");
        }
    }
    return kind_;
}

mipc_result_kind_t mipc_filter_heading_update_control_save(mipc_link_t *link) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_FILTER_HEADING_UPDATE_CONTROL;
        cmd_.u.filter_heading_update_control.function = MIPC_FUNCTION_SELECTOR_SAVE;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_filter_heading_update_control_load(mipc_link_t *link) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_FILTER_HEADING_UPDATE_CONTROL;
        cmd_.u.filter_heading_update_control.function = MIPC_FUNCTION_SELECTOR_LOAD;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_filter_heading_update_control_default(mipc_link_t *link) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_FILTER_HEADING_UPDATE_CONTROL;
        cmd_.u.filter_heading_update_control.function = MIPC_FUNCTION_SELECTOR_DEFAULT;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_filter_auto_init_control_write(mipc_link_t *link, uint8_t enable) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_FILTER_AUTO_INIT_CONTROL;
        cmd_.u.filter_auto_init_control.function = MIPC_FUNCTION_SELECTOR_WRITE;
        cmd_.u.filter_auto_init_control.has_enable = true;
        cmd_.u.filter_auto_init_control.enable = enable;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_filter_auto_init_control_read(mipc_link_t *link,
                                                      mipc_filter_auto_init_control_response_t *reply) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    mipc_result_t result_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_FILTER_AUTO_INIT_CONTROL;
        cmd_.u.filter_auto_init_control.function = MIPC_FUNCTION_SELECTOR_READ;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, &result_);
    if (kind_ == MIPC_RESULT_ACK && reply != NULL) {
        mipc_field_entry_t entry_;
        if (!mipc_result_reply_entry(&result_, &entry_) || entry_.descriptor != 0x88 ||
            mipc_filter_auto_init_control_response_decode(entry_.data, entry_.length, reply, NULL) !=
                MIPC_OK) {
            return mipc_link_fail(link, MIPC_RESULT_INVALID, "missing reply field 0x88");
        }
    }
    return kind_;
}

mipc_result_kind_t mipc_filter_auto_init_control_save(mipc_link_t *link) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_FILTER_AUTO_INIT_CONTROL;
        cmd_.u.filter_auto_init_control.function = MIPC_FUNCTION_SELECTOR_SAVE;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_filter_auto_init_control_load(mipc_link_t *link) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_FILTER_AUTO_INIT_CONTROL;
        cmd_.u.filter_auto_init_control.function = MIPC_FUNCTION_SELECTOR_LOAD;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_filter_auto_init_control_default(mipc_link_t *link) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_FILTER_AUTO_INIT_CONTROL;
        cmd_.u.filter_auto_init_control.function = MIPC_FUNCTION_SELECTOR_DEFAULT;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_filter_accel_noise_write(mipc_link_t *link, const float noise[3]) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_FILTER_ACCEL_NOISE;
        cmd_.u.filter_accel_noise.function = MIPC_FUNCTION_SELECTOR_WRITE;
        cmd_.u.filter_accel_noise.has_noise = true;
        memcpy(cmd_.u.filter_accel_noise.noise, noise, sizeof cmd_.u.filter_accel_noise.noise);
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_filter_accel_noise_read(mipc_link_t *link,
                                                mipc_filter_accel_noise_response_t *reply) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    mipc_result_t result_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_FILTER_ACCEL_NOISE;
        cmd_.u.filter_accel_noise.function = MIPC_FUNCTION_SELECTOR_READ;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, &result_);
    if (kind_ == MIPC_RESULT_ACK && reply != NULL) {
        mipc_field_entry_t entry_;
        if (!mipc_result_reply_entry(&result_, &entry_) || entry_.descriptor != 0x89 ||
            mipc_filter_accel_noise_response_decode(entry_.data, entry_.length, reply, NULL) != MIPC_OK) {
            return mipc_link_fail(link, MIPC_RESULT_INVALID, "missing reply field 0x89");
        }
    }
    return kind_;
}

mipc_result_kind_t mipc_filter_accel_noise_save(mipc_link_t *link) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_FILTER_ACCEL_NOISE;
        cmd_.u.filter_accel_noise.function = MIPC_FUNCTION_SELECTOR_SAVE;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_filter_accel_noise_load(mipc_link_t *link) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_FILTER_ACCEL_NOISE;
        cmd_.u.filter_accel_noise.function = MIPC_FUNCTION_SELECTOR_LOAD;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_filter_accel_noise_default(mipc_link_t *link) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_FILTER_ACCEL_NOISE;
        cmd_.u.filter_accel_noise.function = MIPC_FUNCTION_SELECTOR_DEFAULT;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_filter_gyro_noise_write(mipc_link_t *link, const float noise[3]) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_FILTER_GYRO_NOISE;
        cmd_.u.filter_gyro_noise.function = MIPC_FUNCTION_SELECTOR_WRITE;
        cmd_.u.filter_gyro_noise.has_noise = true;
        memcpy(cmd_.u.filter_gyro_noise.noise, noise, sizeof cmd_.u.filter_gyro_noise.noise);
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_filter_gyro_noise_read(mipc_link_t *link, mipc_filter_gyro_noise_response_t *reply) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    mipc_result_t result_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_FILTER_GYRO_NOISE;
        cmd_.u.filter_gyro_noise.function = MIPC_FUNCTION_SELECTOR_READ;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, &result_);
    if (kind_ == MIPC_RESULT_ACK && reply != NULL) {
        mipc_field_entry_t entry_;
        if (!mipc_result_reply_entry(&result_, &entry_) || entry_.descriptor != 0x8A ||
            mipc_filter_gyro_noise_response_decode(entry_.data, entry_.length, reply, NULL) != MIPC_OK) {
            return mipc_link_fail(link, MIPC_RESULT_INVALID, "missing reply field 0x8A");
        }
    }
    return kind_;
}

mipc_result_kind_t mipc_filter_gyro_noise_save(mipc_link_t *link) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_FILTER_GYRO_NOISE;
        cmd_.u.filter_gyro_noise.function = MIPC_FUNCTION_SELECTOR_SAVE;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_filter_gyro_noise_load(mipc_link_t *link) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_FILTER_GYRO_NOISE;
        cmd_.u.filter_gyro_noise.function = MIPC_FUNCTION_SELECTOR_LOAD;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_filter_gyro_noise_default(mipc_link_t *link) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_FILTER_GYRO_NOISE;
        cmd_.u.filter_gyro_noise.function = MIPC_FUNCTION_SELECTOR_DEFAULT;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_filter_accel_bias_model_write(mipc_link_t *link, const float beta[3],
                                                      const float noise[3]) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_FILTER_ACCEL_BIAS_MODEL;
        cmd_.u.filter_accel_bias_model.function = MIPC_FUNCTION_SELECTOR_WRITE;
        cmd_.u.filter_accel_bias_model.has_beta = true;
        memcpy(cmd_.u.filter_accel_bias_model.beta, beta, sizeof cmd_.u.filter_accel_bias_model.beta);
        cmd_.u.filter_accel_bias_model.has_noise = true;
        memcpy(cmd_.u.filter_accel_bias_model.noise, noise, sizeof cmd_.u.filter_accel_bias_model.noise);
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_filter_accel_bias_model_read(mipc_link_t *link,
                                                     mipc_filter_accel_bias_model_response_t *reply) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    mipc_result_t result_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_FILTER_ACCEL_BIAS_MODEL;
        cmd_.u.filter_accel_bias_model.function = MIPC_FUNCTION_SELECTOR_READ;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, &result_);
    if (kind_ == MIPC_RESULT_ACK && reply != NULL) {
        mipc_field_entry_t entry_;
        if (!mipc_result_reply_entry(&result_, &entry_) || entry_.descriptor != 0x8B ||
            mipc_filter_accel_bias_model_response_decode(entry_.data, entry_.length, reply, NULL) !=
                MIPC_OK) {
            return mipc_link_fail(link, MIPC_RESULT_INVALID, "missing reply field 0x8B");
        }
    }
    return kind_;
}

mipc_result_kind_t mipc_filter_accel_bias_model_save(mipc_link_t *link) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_FILTER_ACCEL_BIAS_MODEL;
        cmd_.u.filter_accel_bias_model.function = MIPC_FUNCTION_SELECTOR_SAVE;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_filter_accel_bias_model_load(mipc_link_t *link) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_FILTER_ACCEL_BIAS_MODEL;
        cmd_.u.filter_accel_bias_model.function = MIPC_FUNCTION_SELECTOR_LOAD;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_filter_accel_bias_model_default(mipc_link_t *link) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_FILTER_ACCEL_BIAS_MODEL;
        cmd_.u.filter_accel_bias_model.function = MIPC_FUNCTION_SELECTOR_DEFAULT;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_filter_gyro_bias_model_write(mipc_link_t *link, const float beta[3],
                                                     const float noise[3]) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_FILTER_GYRO_BIAS_MODEL;
        cmd_.u.filter_gyro_bias_model.function = MIPC_FUNCTION_SELECTOR_WRITE;
        cmd_.u.filter_gyro_bias_model.has_beta = true;
        memcpy(cmd_.u.filter_gyro_bias_model.beta, beta, sizeof cmd_.u.filter_gyro_bias_model.beta);
        cmd_.u.filter_gyro_bias_model.has_noise = true;
        memcpy(cmd_.u.filter_gyro_bias_model.noise, noise, sizeof cmd_.u.filter_gyro_bias_model.noise);
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_filter_gyro_bias_model_read(mipc_link_t *link,
                                                    mipc_filter_gyro_bias_model_response_t *reply) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    mipc_result_t result_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_FILTER_GYRO_BIAS_MODEL;
        cmd_.u.filter_gyro_bias_model.function = MIPC_FUNCTION_SELECTOR_READ;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, &result_);
    if (kind_ == MIPC_RESULT_ACK && reply != NULL) {
        mipc_field_entry_t entry_;
        if (!mipc_result_reply_entry(&result_, &entry_) || entry_.descriptor != 0x8C ||
            mipc_filter_gyro_bias_model_response_decode(entry_.data, entry_.length, reply, NULL) != MIPC_OK) {
            return mipc_link_fail(link, MIPC_RESULT_INVALID, "missing reply field 0x8C");
        }
    }
    return kind_;
}

mipc_result_kind_t mipc_filter_gyro_bias_model_save(mipc_link_t *link) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_FILTER_GYRO_BIAS_MODEL;
        cmd_.u.filter_gyro_bias_model.function = MIPC_FUNCTION_SELECTOR_SAVE;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_filter_gyro_bias_model_load(mipc_link_t *link) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_FILTER_GYRO_BIAS_MODEL;
        cmd_.u.filter_gyro_bias_model.function = MIPC_FUNCTION_SELECTOR_LOAD;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_filter_gyro_bias_model_default(mipc_link_t *link) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_FILTER_GYRO_BIAS_MODEL;
        cmd_.u.filter_gyro_bias_model.function = MIPC_FUNCTION_SELECTOR_DEFAULT;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_filter_zupt_control_write(mipc_link_t *link, uint8_t enable, float threshold) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_FILTER_ZUPT_CONTROL;
        cmd_.u.filter_zupt_control.function = MIPC_FUNCTION_SELECTOR_WRITE;
        cmd_.u.filter_zupt_control.has_enable = true;
        cmd_.u.filter_zupt_control.enable = enable;
        cmd_.u.filter_zupt_control.has_threshold = true;
        cmd_.u.filter_zupt_control.threshold = threshold;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_filter_zupt_control_read(mipc_link_t *link,
                                                 mipc_filter_zupt_control_response_t *reply) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    mipc_result_t result_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_FILTER_ZUPT_CONTROL;
        cmd_.u.filter_zupt_control.function = MIPC_FUNCTION_SELECTOR_READ;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, &result_);
    if (kind_ == MIPC_RESULT_ACK && reply != NULL) {
        mipc_field_entry_t entry_;
        if (!mipc_result_reply_entry(&result_, &entry_) || entry_.descriptor != 0x8D ||
            mipc_filter_zupt_control_response_decode(entry_.data, entry_.length, reply, NULL) != MIPC_OK) {
            return mipc_link_fail(link, MIPC_RESULT_INVALID, "missing reply field 0x8D");
        }
    }
    return kind_;
}

mipc_result_kind_t mipc_filter_zupt_control_save(mipc_link_t *link) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_FILTER_ZUPT_CONTROL;
        cmd_.u.filter_zupt_control.function = MIPC_FUNCTION_SELECTOR_SAVE;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_filter_zupt_control_load(mipc_link_t *link) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_FILTER_ZUPT_CONTROL;
        cmd_.u.filter_zupt_control.function = MIPC_FUNCTION_SELECTOR_LOAD;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_filter_zupt_control_default(mipc_link_t *link) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_FILTER_ZUPT_CONTROL;
        cmd_.u.filter_zupt_control.function = MIPC_FUNCTION_SELECTOR_DEFAULT;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_filter_external_heading_update_with_time(mipc_link_t *link, double gps_tow,
                                                                 uint16_t gps_week, float heading,
                                                                 float heading_uncertainty,
                                                                 mipc_external_heading_type_t type) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_FILTER_EXTERNAL_HEADING_UPDATE_WITH_TIME;
        cmd_.u.filter_external_heading_update_with_time.gps_tow = gps_tow;
        cmd_.u.filter_external_heading_update_with_time.gps_week = gps_week;
        cmd_.u.filter_external_heading_update_with_time.heading = heading;
        cmd_.u.filter_external_heading_update_with_time.heading_uncertainty = heading_uncertainty;
        cmd_.u.filter_external_heading_update_with_time.type = type;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_filter_zero_angular_rate_update_control_write(mipc_link_t *link, uint8_t enable,
                                                                      float threshold) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_FILTER_ZERO_ANGULAR_RATE_UPDATE_CONTROL;
        cmd_.u.filter_zero_angular_rate_update_control.function = MIPC_FUNCTION_SELECTOR_WRITE;
        cmd_.u.filter_zero_angular_rate_update_control.has_enable = true;
        cmd_.u.filter_zero_angular_rate_update_control.enable = enable;
        cmd_.u.filter_zero_angular_rate_update_control.has_threshold = true;
        cmd_.u.filter_zero_angular_rate_update_control.threshold = threshold;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_filter_zero_angular_rate_update_control_read(
    mipc_link_t *link, mipc_filter_zero_angular_rate_update_control_response_t *reply) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    mipc_result_t result_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_FILTER_ZERO_ANGULAR_RATE_UPDATE_CONTROL;
        cmd_.u.filter_zero_angular_rate_update_control.function = MIPC_FUNCTION_SELECTOR_READ;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, &result_);
    if (kind_ == MIPC_RESULT_ACK && reply != NULL) {
        mipc_field_entry_t entry_;
        if (!mipc_result_reply_entry(&result_, &entry_) || entry_.descriptor != 0x8E ||
            mipc_filter_zero_angular_rate_update_control_response_decode(entry_.data, entry_.length, reply,
                                                                         NULL) != MIPC_OK) {
            return mipc_link_fail(link, MIPC_RESULT_INVALID, "missing reply field 0x8E");
        }
    }
    return kind_;
}

mipc_result_kind_t mipc_filter_zero_angular_rate_update_control_save(mipc_link_t *link) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_FILTER_ZERO_ANGULAR_RATE_UPDATE_CONTROL;
        cmd_.u.filter_zero_angular_rate_update_control.function = MIPC_FUNCTION_SELECTOR_SAVE;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_filter_zero_angular_rate_update_control_load(mipc_link_t *link) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_FILTER_ZERO_ANGULAR_RATE_UPDATE_CONTROL;
        cmd_.u.filter_zero_angular_rate_update_control.function = MIPC_FUNCTION_SELECTOR_LOAD;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_filter_zero_angular_rate_update_control_default(mipc_link_t *link) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_FILTER_ZERO_ANGULAR_RATE_UPDATE_CONTROL;
        cmd_.u.filter_zero_angular_rate_update_control.function = MIPC_FUNCTION_SELECTOR_DEFAULT;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_filter_tare_orientation_write(mipc_link_t *link, mipc_tare_axes_t axes) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_FILTER_TARE_ORIENTATION;
        cmd_.u.filter_tare_orientation.function = MIPC_FUNCTION_SELECTOR_WRITE;
        cmd_.u.filter_tare_orientation.has_axes = true;
        cmd_.u.filter_tare_orientation.axes = axes;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_filter_tare_orientation_save(mipc_link_t *link) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_FILTER_TARE_ORIENTATION;
        cmd_.u.filter_tare_orientation.function = MIPC_FUNCTION_SELECTOR_SAVE;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_filter_tare_orientation_load(mipc_link_t *link) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_FILTER_TARE_ORIENTATION;
        cmd_.u.filter_tare_orientation.function = MIPC_FUNCTION_SELECTOR_LOAD;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_filter_tare_orientation_default(mipc_link_t *link) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_FILTER_TARE_ORIENTATION;
        cmd_.u.filter_tare_orientation.function = MIPC_FUNCTION_SELECTOR_DEFAULT;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_filter_commanded_zupt(mipc_link_t *link) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_FILTER_COMMANDED_ZUPT;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_filter_commanded_zero_angular_rate_update(mipc_link_t *link) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_FILTER_COMMANDED_ZERO_ANGULAR_RATE_UPDATE;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_filter_mag_capture_auto_calibration_write(mipc_link_t *link) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_FILTER_MAG_CAPTURE_AUTO_CALIBRATION;
        cmd_.u.filter_mag_capture_auto_calibration.function = MIPC_FUNCTION_SELECTOR_WRITE;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_filter_mag_capture_auto_calibration_save(mipc_link_t *link) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_FILTER_MAG_CAPTURE_AUTO_CALIBRATION;
        cmd_.u.filter_mag_capture_auto_calibration.function = MIPC_FUNCTION_SELECTOR_SAVE;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_filter_gravity_noise_std_dev_write(mipc_link_t *link, const float noise[3]) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_FILTER_GRAVITY_NOISE_STD_DEV;
        cmd_.u.filter_gravity_noise_std_dev.function = MIPC_FUNCTION_SELECTOR_WRITE;
        cmd_.u.filter_gravity_noise_std_dev.has_noise = true;
        memcpy(cmd_.u.filter_gravity_noise_std_dev.noise, noise,
               sizeof cmd_.u.filter_gravity_noise_std_dev.noise);
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t
mipc_filter_gravity_noise_std_dev_read(mipc_link_t *link,
                                       mipc_filter_gravity_noise_std_dev_response_t *reply) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    mipc_result_t result_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_FILTER_GRAVITY_NOISE_STD_DEV;
        cmd_.u.filter_gravity_noise_std_dev.function = MIPC_FUNCTION_SELECTOR_READ;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, &result_);
    if (kind_ == MIPC_RESULT_ACK && reply != NULL) {
        mipc_field_entry_t entry_;
        if (!mipc_result_reply_entry(&result_, &entry_) || entry_.descriptor != 0x93 ||
            mipc_filter_gravity_noise_std_dev_response_decode(entry_.data, entry_.length, reply, NULL) !=
                MIPC_OK) {
            return mipc_link_fail(link, MIPC_RESULT_INVALID, "missing reply field 0x93");
        }
    }
    return kind_;
}

mipc_result_kind_t mipc_filter_gravity_noise_std_dev_save(mipc_link_t *link) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_FILTER_GRAVITY_NOISE_STD_DEV;
        cmd_.u.filter_gravity_noise_std_dev.function = MIPC_FUNCTION_SELECTOR_SAVE;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_filter_gravity_noise_std_dev_load(mipc_link_t *link) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_FILTER_GRAVITY_NOISE_STD_DEV;
        cmd_.u.filter_gravity_noise_std_dev.function = MIPC_FUNCTION_SELECTOR_LOAD;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_filter_gravity_noise_std_dev_default(mipc_link_t *link) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_FILTER_GRAVITY_NOISE_STD_DEV;
        cmd_.u.filter_gravity_noise_std_dev.function = MIPC_FUNCTION_SELECTOR_DEFAULT;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_filter_pressure_altitude_noise_std_dev_write(mipc_link_t *link, float noise) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_FILTER_PRESSURE_ALTITUDE_NOISE_STD_DEV;
        cmd_.u.filter_pressure_altitude_noise_std_dev.function = MIPC_FUNCTION_SELECTOR_WRITE;
        cmd_.u.filter_pressure_altitude_noise_std_dev.has_noise = true;
        cmd_.u.filter_pressure_altitude_noise_std_dev.noise = noise;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_filter_pressure_altitude_noise_std_dev_read(
    mipc_link_t *link, mipc_filter_pressure_altitude_noise_std_dev_response_t *reply) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    mipc_result_t result_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_FILTER_PRESSURE_ALTITUDE_NOISE_STD_DEV;
        cmd_.u.filter_pressure_altitude_noise_std_dev.function = MIPC_FUNCTION_SELECTOR_READ;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, &result_);
    if (kind_ == MIPC_RESULT_ACK && reply != NULL) {
        mipc_field_entry_t entry_;
        if (!mipc_result_reply_entry(&result_, &entry_) || entry_.descriptor != 0x94 ||
            mipc_filter_pressure_altitude_noise_std_dev_response_decode(entry_.data, entry_.length, reply,
                                                                        NULL) != MIPC_OK) {
            return mipc_link_fail(link, MIPC_RESULT_INVALID, "missing reply field 0x94");
        }
    }
    return kind_;
}

mipc_result_kind_t mipc_filter_pressure_altitude_noise_std_dev_save(mipc_link_t *link) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_FILTER_PRESSURE_ALTITUDE_NOISE_STD_DEV;
        cmd_.u.filter_pressure_altitude_noise_std_dev.function = MIPC_FUNCTION_SELECTOR_SAVE;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_filter_pressure_altitude_noise_std_dev_load(mipc_link_t *link) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_FILTER_PRESSURE_ALTITUDE_NOISE_STD_DEV;
        cmd_.u.filter_pressure_altitude_noise_std_dev.function = MIPC_FUNCTION_SELECTOR_LOAD;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_filter_pressure_altitude_noise_std_dev_default(mipc_link_t *link) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_FILTER_PRESSURE_ALTITUDE_NOISE_STD_DEV;
        cmd_.u.filter_pressure_altitude_noise_std_dev.function = MIPC_FUNCTION_SELECTOR_DEFAULT;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_filter_hard_iron_offset_noise_write(mipc_link_t *link, const float noise[3]) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_FILTER_HARD_IRON_OFFSET_NOISE;
        cmd_.u.filter_hard_iron_offset_noise.function = MIPC_FUNCTION_SELECTOR_WRITE;
        cmd_.u.filter_hard_iron_offset_noise.has_noise = true;
        memcpy(cmd_.u.filter_hard_iron_offset_noise.noise, noise,
               sizeof cmd_.u.filter_hard_iron_offset_noise.noise);
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t
mipc_filter_hard_iron_offset_noise_read(mipc_link_t *link,
                                        mipc_filter_hard_iron_offset_noise_response_t *reply) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    mipc_result_t result_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_FILTER_HARD_IRON_OFFSET_NOISE;
        cmd_.u.filter_hard_iron_offset_noise.function = MIPC_FUNCTION_SELECTOR_READ;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, &result_);
    if (kind_ == MIPC_RESULT_ACK && reply != NULL) {
        mipc_field_entry_t entry_;
        if (!mipc_result_reply_entry(&result_, &entry_) || entry_.descriptor != 0x96 ||
            mipc_filter_hard_iron_offset_noise_response_decode(entry_.data, entry_.length, reply, NULL) !=
                MIPC_OK) {
            return mipc_link_fail(link, MIPC_RESULT_INVALID, "missing reply field 0x96");
        }
    }
    return kind_;
}

mipc_result_kind_t mipc_filter_hard_iron_offset_noise_save(mipc_link_t *link) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_FILTER_HARD_IRON_OFFSET_NOISE;
        cmd_.u.filter_hard_iron_offset_noise.function = MIPC_FUNCTION_SELECTOR_SAVE;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_filter_hard_iron_offset_noise_load(mipc_link_t *link) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_FILTER_HARD_IRON_OFFSET_NOISE;
        cmd_.u.filter_hard_iron_offset_noise.function = MIPC_FUNCTION_SELECTOR_LOAD;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_filter_hard_iron_offset_noise_default(mipc_link_t *link) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_FILTER_HARD_IRON_OFFSET_NOISE;
        cmd_.u.filter_hard_iron_offset_noise.function = MIPC_FUNCTION_SELECTOR_DEFAULT;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_filter_soft_iron_matrix_noise_write(mipc_link_t *link, const float noise[9]) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_FILTER_SOFT_IRON_MATRIX_NOISE;
        cmd_.u.filter_soft_iron_matrix_noise.function = MIPC_FUNCTION_SELECTOR_WRITE;
        cmd_.u.filter_soft_iron_matrix_noise.has_noise = true;
        memcpy(cmd_.u.filter_soft_iron_matrix_noise.noise, noise,
               sizeof cmd_.u.filter_soft_iron_matrix_noise.noise);
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t
mipc_filter_soft_iron_matrix_noise_read(mipc_link_t *link,
                                        mipc_filter_soft_iron_matrix_noise_response_t *reply) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    mipc_result_t result_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_FILTER_SOFT_IRON_MATRIX_NOISE;
        cmd_.u.filter_soft_iron_matrix_noise.function = MIPC_FUNCTION_SELECTOR_READ;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, &result_);
    if (kind_ == MIPC_RESULT_ACK && reply != NULL) {
        mipc_field_entry_t entry_;
        if (!mipc_result_reply_entry(&result_, &entry_) || entry_.descriptor != 0x97 ||
            mipc_filter_soft_iron_matrix_noise_response_decode(entry_.data, entry_.length, reply, NULL) !=
                MIPC_OK) {
            return mipc_link_fail(link, MIPC_RESULT_INVALID, "missing reply field 0x97");
        }
    }
    return kind_;
}

mipc_result_kind_t mipc_filter_soft_iron_matrix_noise_save(mipc_link_t *link) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_FILTER_SOFT_IRON_MATRIX_NOISE;
        cmd_.u.filter_soft_iron_matrix_noise.function = MIPC_FUNCTION_SELECTOR_SAVE;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_filter_soft_iron_matrix_noise_load(mipc_link_t *link) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_FILTER_SOFT_IRON_MATRIX_NOISE;
        cmd_.u.filter_soft_iron_matrix_noise.function = MIPC_FUNCTION_SELECTOR_LOAD;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_filter_soft_iron_matrix_noise_default(mipc_link_t *link) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_FILTER_SOFT_IRON_MATRIX_NOISE;
        cmd_.u.filter_soft_iron_matrix_noise.function = MIPC_FUNCTION_SELECTOR_DEFAULT;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_filter_mag_noise_std_dev_write(mipc_link_t *link, const float noise[3]) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_FILTER_MAG_NOISE_STD_DEV;
        cmd_.u.filter_mag_noise_std_dev.function = MIPC_FUNCTION_SELECTOR_WRITE;
        cmd_.u.filter_mag_noise_std_dev.has_noise = true;
        memcpy(cmd_.u.filter_mag_noise_std_dev.noise, noise, sizeof cmd_.u.filter_mag_noise_std_dev.noise);
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_filter_mag_noise_std_dev_read(mipc_link_t *link,
                                                      mipc_filter_mag_noise_std_dev_response_t *reply) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    mipc_result_t result_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_FILTER_MAG_NOISE_STD_DEV;
        cmd_.u.filter_mag_noise_std_dev.function = MIPC_FUNCTION_SELECTOR_READ;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, &result_);
    if (kind_ == MIPC_RESULT_ACK && reply != NULL) {
        mipc_field_entry_t entry_;
        if (!mipc_result_reply_entry(&result_, &entry_) || entry_.descriptor != 0xB1 ||
            mipc_filter_mag_noise_std_dev_response_decode(entry_.data, entry_.length, reply, NULL) !=
                MIPC_OK) {
            return mipc_link_fail(link, MIPC_RESULT_INVALID, "missing reply field 0xB1");
        }
    }
    return kind_;
}

mipc_result_kind_t mipc_filter_mag_noise_std_dev_save(mipc_link_t *link) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_FILTER_MAG_NOISE_STD_DEV;
        cmd_.u.filter_mag_noise_std_dev.function = MIPC_FUNCTION_SELECTOR_SAVE;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_filter_mag_noise_std_dev_load(mipc_link_t *link) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_FILTER_MAG_NOISE_STD_DEV;
        cmd_.u.filter_mag_noise_std_dev.function = MIPC_FUNCTION_SELECTOR_LOAD;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_filter_mag_noise_std_dev_default(mipc_link_t *link) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_FILTER_MAG_NOISE_STD_DEV;
        cmd_.u.filter_mag_noise_std_dev.function = MIPC_FUNCTION_SELECTOR_DEFAULT;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_filter_declination_source_write(mipc_link_t *link,
                                                        mipc_magnetic_param_source_t source,
                                                        float declination) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_FILTER_DECLINATION_SOURCE;
        cmd_.u.filter_declination_source.function = MIPC_FUNCTION_SELECTOR_WRITE;
        cmd_.u.filter_declination_source.has_source = true;
        cmd_.u.filter_declination_source.source = source;
        cmd_.u.filter_declination_source.has_declination = true;
        cmd_.u.filter_declination_source.declination = declination;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_filter_declination_source_read(mipc_link_t *link,
                                                       mipc_filter_declination_source_response_t *reply) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    mipc_result_t result_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_FILTER_DECLINATION_SOURCE;
        cmd_.u.filter_declination_source.function = MIPC_FUNCTION_SELECTOR_READ;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, &result_);
    if (kind_ == MIPC_RESULT_ACK && reply != NULL) {
        mipc_field_entry_t entry_;
        if (!mipc_result_reply_entry(&result_, &entry_) || entry_.descriptor != 0xB2 ||
            mipc_filter_declination_source_response_decode(entry_.data, entry_.length, reply, NULL) !=
                MIPC_OK) {
            return mipc_link_fail(link, MIPC_RESULT_INVALID, "missing reply field 0xB2");
        }
    }
    return kind_;
}

mipc_result_kind_t mipc_filter_declination_source_save(mipc_link_t *link) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_FILTER_DECLINATION_SOURCE;
        cmd_.u.filter_declination_source.function = MIPC_FUNCTION_SELECTOR_SAVE;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_filter_declination_source_load(mipc_link_t *link) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_FILTER_DECLINATION_SOURCE;
        cmd_.u.filter_declination_source.function = MIPC_FUNCTION_SELECTOR_LOAD;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_filter_declination_source_default(mipc_link_t *link) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_FILTER_DECLINATION_SOURCE;
        cmd_.u.filter_declination_source.function = MIPC_FUNCTION_SELECTOR_DEFAULT;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_filter_gravity_magnitude_adaptive_measurement_write(
    mipc_link_t *link, mipc_adaptive_measurement_mode_t mode, float frequency, float low_limit,
    float high_limit, float low_limit_uncertainty, float high_limit_uncertainty, float minimum_uncertainty) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_FILTER_GRAVITY_MAGNITUDE_ADAPTIVE_MEASUREMENT;
        cmd_.u.filter_gravity_magnitude_adaptive_measurement.function = MIPC_FUNCTION_SELECTOR_WRITE;
        cmd_.u.filter_gravity_magnitude_adaptive_measurement.has_mode = true;
        cmd_.u.filter_gravity_magnitude_adaptive_measurement.mode = mode;
        cmd_.u.filter_gravity_magnitude_adaptive_measurement.has_frequency = true;
        cmd_.u.filter_gravity_magnitude_adaptive_measurement.frequency = frequency;
        cmd_.u.filter_gravity_magnitude_adaptive_measurement.has_low_limit = true;
        cmd_.u.filter_gravity_magnitude_adaptive_measurement.low_limit = low_limit;
        cmd_.u.filter_gravity_magnitude_adaptive_measurement.has_high_limit = true;
        cmd_.u.filter_gravity_magnitude_adaptive_measurement.high_limit = high_limit;
        cmd_.u.filter_gravity_magnitude_adaptive_measurement.has_low_limit_uncertainty = true;
        cmd_.u.filter_gravity_magnitude_adaptive_measurement.low_limit_uncertainty = low_limit_uncertainty;
        cmd_.u.filter_gravity_magnitude_adaptive_measurement.has_high_limit_uncertainty = true;
        cmd_.u.filter_gravity_magnitude_adaptive_measurement.high_limit_uncertainty = high_limit_uncertainty;
        cmd_.u.filter_gravity_magnitude_adaptive_measurement.has_minimum_uncertainty = true;
        cmd_.u.filter_gravity_magnitude_adaptive_measurement.minimum_uncertainty = minimum_uncertainty;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_filter_gravity_magnitude_adaptive_measurement_read(
    mipc_link_t *link, mipc_filter_gravity_magnitude_adaptive_measurement_response_t *reply) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    mipc_result_t result_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_FILTER_GRAVITY_MAGNITUDE_ADAPTIVE_MEASUREMENT;
        cmd_.u.filter_gravity_magnitude_adaptive_measurement.function = MIPC_FUNCTION_SELECTOR_READ;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, &result_);
    if (kind_ == MIPC_RESULT_ACK && reply != NULL) {
        mipc_field_entry_t entry_;
        if (!mipc_result_reply_entry(&result_, &entry_) || entry_.descriptor != 0xB3 ||
            mipc_filter_gravity_magnitude_adaptive_measurement_response_decode(entry_.data, entry_.length,
                                                                               reply, NULL) != MIPC_OK) {
            return mipc_link_fail(link, MIPC_RESULT_INVALID, "missing reply field 0xB3");
        }
    }
    return kind_;
}

mipc_result_kind_t mipc_filter_gravity_magnitude_adaptive_measurement_save(mipc_link_t *link) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_FILTER_GRAVITY_MAGNITUDE_ADAPTIVE_MEASUREMENT;
        cmd_.u.filter_gravity_magnitude_adaptive_measurement.function = MIPC_FUNCTION_SELECTOR_SAVE;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_filter_gravity_magnitude_adaptive_measurement_load(mipc_link_t *link) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_FILTER_GRAVITY_MAGNITUDE_ADAPTIVE_MEASUREMENT;
        cmd_.u.filter_gravity_magnitude_adaptive_measurement.function = MIPC_FUNCTION_SELECTOR_LOAD;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_filter_gravity_magnitude_adaptive_measurement_default(mipc_link_t *link) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_FILTER_GRAVITY_MAGNITUDE_ADAPTIVE_MEASUREMENT;
        cmd_.u.filter_gravity_magnitude_adaptive_measurement.function = MIPC_FUNCTION_SELECTOR_DEFAULT;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_filter_mag_magnitude_adaptive_measurement_write(
    mipc_link_t *link, mipc_adaptive_measurement_mode_t mode, float frequency, float low_limit,
    float high_limit, float low_limit_uncertainty, float high_limit_uncertainty, float minimum_uncertainty) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_FILTER_MAG_MAGNITUDE_ADAPTIVE_MEASUREMENT;
        cmd_.u.filter_mag_magnitude_adaptive_measurement.function = MIPC_FUNCTION_SELECTOR_WRITE;
        cmd_.u.filter_mag_magnitude_adaptive_measurement.has_mode = true;
        cmd_.u.filter_mag_magnitude_adaptive_measurement.mode = mode;
        cmd_.u.filter_mag_magnitude_adaptive_measurement.has_frequency = true;
        cmd_.u.filter_mag_magnitude_adaptive_measurement.frequency = frequency;
        cmd_.u.filter_mag_magnitude_adaptive_measurement.has_low_limit = true;
        cmd_.u.filter_mag_magnitude_adaptive_measurement.low_limit = low_limit;
        cmd_.u.filter_mag_magnitude_adaptive_measurement.has_high_limit = true;
        cmd_.u.filter_mag_magnitude_adaptive_measurement.high_limit = high_limit;
        cmd_.u.filter_mag_magnitude_adaptive_measurement.has_low_limit_uncertainty = true;
        cmd_.u.filter_mag_magnitude_adaptive_measurement.low_limit_uncertainty = low_limit_uncertainty;
        cmd_.u.filter_mag_magnitude_adaptive_measurement.has_high_limit_uncertainty = true;
        cmd_.u.filter_mag_magnitude_adaptive_measurement.high_limit_uncertainty = high_limit_uncertainty;
        cmd_.u.filter_mag_magnitude_adaptive_measurement.has_minimum_uncertainty = true;
        cmd_.u.filter_mag_magnitude_adaptive_measurement.minimum_uncertainty = minimum_uncertainty;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_filter_mag_magnitude_adaptive_measurement_read(
    mipc_link_t *link, mipc_filter_mag_magnitude_adaptive_measurement_response_t *reply) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    mipc_result_t result_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_FILTER_MAG_MAGNITUDE_ADAPTIVE_MEASUREMENT;
        cmd_.u.filter_mag_magnitude_adaptive_measurement.function = MIPC_FUNCTION_SELECTOR_READ;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, &result_);
    if (kind_ == MIPC_RESULT_ACK && reply != NULL) {
        mipc_field_entry_t entry_;
        if (!mipc_result_reply_entry(&result_, &entry_) || entry_.descriptor != 0xB4 ||
            mipc_filter_mag_magnitude_adaptive_measurement_response_decode(entry_.data, entry_.length, reply,
                                                                           NULL) != MIPC_OK) {
            return mipc_link_fail(link, MIPC_RESULT_INVALID, "missing reply field 0xB4");
        }
    }
    return kind_;
}

mipc_result_kind_t mipc_filter_mag_magnitude_adaptive_measurement_save(mipc_link_t *link) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_FILTER_MAG_MAGNITUDE_ADAPTIVE_MEASUREMENT;
        cmd_.u.filter_mag_magnitude_adaptive_measurement.function = MIPC_FUNCTION_SELECTOR_SAVE;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_filter_mag_magnitude_adaptive_measurement_load(mipc_link_t *link) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_FILTER_MAG_MAGNITUDE_ADAPTIVE_MEASUREMENT;
        cmd_.u.filter_mag_magnitude_adaptive_measurement.function = MIPC_FUNCTION_SELECTOR_LOAD;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_filter_mag_magnitude_adaptive_measurement_default(mipc_link_t *link) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_FILTER_MAG_MAGNITUDE_ADAPTIVE_MEASUREMENT;
        cmd_.u.filter_mag_magnitude_adaptive_measurement.function = MIPC_FUNCTION_SELECTOR_DEFAULT;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_filter_mag_dip_angle_adaptive_measurement_write(mipc_link_t *link,
                                                                        mipc_adaptive_measurement_mode_t mode,
                                                                        float frequency, float high_limit,
                                                                        float high_limit_uncertainty,
                                                                        float minimum_uncertainty) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_FILTER_MAG_DIP_ANGLE_ADAPTIVE_MEASUREMENT;
        cmd_.u.filter_mag_dip_angle_adaptive_measurement.function = MIPC_FUNCTION_SELECTOR_WRITE;
        cmd_.u.filter_mag_dip_angle_adaptive_measurement.has_mode = true;
        cmd_.u.filter_mag_dip_angle_adaptive_measurement.mode = mode;
        cmd_.u.filter_mag_dip_angle_adaptive_measurement.has_frequency = true;
        cmd_.u.filter_mag_dip_angle_adaptive_measurement.frequency = frequency;
        cmd_.u.filter_mag_dip_angle_adaptive_measurement.has_high_limit = true;
        cmd_.u.filter_mag_dip_angle_adaptive_measurement.high_limit = high_limit;
        cmd_.u.filter_mag_dip_angle_adaptive_measurement.has_high_limit_uncertainty = true;
        cmd_.u.filter_mag_dip_angle_adaptive_measurement.high_limit_uncertainty = high_limit_uncertainty;
        cmd_.u.filter_mag_dip_angle_adaptive_measurement.has_minimum_uncertainty = true;
        cmd_.u.filter_mag_dip_angle_adaptive_measurement.minimum_uncertainty = minimum_uncertainty;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_filter_mag_dip_angle_adaptive_measurement_read(
    mipc_link_t *link, mipc_filter_mag_dip_angle_adaptive_measurement_response_t *reply) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    mipc_result_t result_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_FILTER_MAG_DIP_ANGLE_ADAPTIVE_MEASUREMENT;
        cmd_.u.filter_mag_dip_angle_adaptive_measurement.function = MIPC_FUNCTION_SELECTOR_READ;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, &result_);
    if (kind_ == MIPC_RESULT_ACK && reply != NULL) {
        mipc_field_entry_t entry_;
        if (!mipc_result_reply_entry(&result_, &entry_) || entry_.descriptor != 0xB5 ||
            mipc_filter_mag_dip_angle_adaptive_measurement_response_decode(entry_.data, entry_.length, reply,
                                                                           NULL) != MIPC_OK) {
            return mipc_link_fail(link, MIPC_RESULT_INVALID, "missing reply field 0xB5");
        }
    }
    return kind_;
}

mipc_result_kind_t mipc_filter_mag_dip_angle_adaptive_measurement_save(mipc_link_t *link) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_FILTER_MAG_DIP_ANGLE_ADAPTIVE_MEASUREMENT;
        cmd_.u.filter_mag_dip_angle_adaptive_measurement.function = MIPC_FUNCTION_SELECTOR_SAVE;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_filter_mag_dip_angle_adaptive_measurement_load(mipc_link_t *link) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_FILTER_MAG_DIP_ANGLE_ADAPTIVE_MEASUREMENT;
        cmd_.u.filter_mag_dip_angle_adaptive_measurement.function = MIPC_FUNCTION_SELECTOR_LOAD;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_filter_mag_dip_angle_adaptive_measurement_default(mipc_link_t *link) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_FILTER_MAG_DIP_ANGLE_ADAPTIVE_MEASUREMENT;
        cmd_.u.filter_mag_dip_angle_adaptive_measurement.function = MIPC_FUNCTION_SELECTOR_DEFAULT;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_filter_altitude_aiding_control_write(mipc_link_t *link,
                                                             mipc_altitude_aiding_source_t source) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_FILTER_ALTITUDE_AIDING_CONTROL;
        cmd_.u.filter_altitude_aiding_control.function = MIPC_FUNCTION_SELECTOR_WRITE;
        cmd_.u.filter_altitude_aiding_control.has_source = true;
        cmd_.u.filter_altitude_aiding_control.source = source;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t
mipc_filter_altitude_aiding_control_read(mipc_link_t *link,
                                         mipc_filter_altitude_aiding_control_response_t *reply) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    mipc_result_t result_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_FILTER_ALTITUDE_AIDING_CONTROL;
        cmd_.u.filter_altitude_aiding_control.function = MIPC_FUNCTION_SELECTOR_READ;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, &result_);
    if (kind_ == MIPC_RESULT_ACK && reply != NULL) {
        mipc_field_entry_t entry_;
        if (!mipc_result_reply_entry(&result_, &entry_) || entry_.descriptor != 0xB7 ||
            mipc_filter_altitude_aiding_control_response_decode(entry_.data, entry_.length, reply, NULL) !=
                MIPC_OK) {
            return mipc_link_fail(link, MIPC_RESULT_INVALID, "missing reply field 0xB7");
        }
    }
    return kind_;
}

mipc_result_kind_t mipc_filter_altitude_aiding_control_save(mipc_link_t *link) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_FILTER_ALTITUDE_AIDING_CONTROL;
        cmd_.u.filter_altitude_aiding_control.function = MIPC_FUNCTION_SELECTOR_SAVE;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_filter_altitude_aiding_control_load(mipc_link_t *link) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_FILTER_ALTITUDE_AIDING_CONTROL;
        cmd_.u.filter_altitude_aiding_control.function = MIPC_FUNCTION_SELECTOR_LOAD;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_filter_altitude_aiding_control_default(mipc_link_t *link) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_FILTER_ALTITUDE_AIDING_CONTROL;
        cmd_.u.filter_altitude_aiding_control.function = MIPC_FUNCTION_SELECTOR_DEFAULT;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_filter_pitch_roll_aiding_control_write(mipc_link_t *link,
                                                               mipc_pitch_roll_aiding_source_t source) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_FILTER_PITCH_ROLL_AIDING_CONTROL;
        cmd_.u.filter_pitch_roll_aiding_control.function = MIPC_FUNCTION_SELECTOR_WRITE;
        cmd_.u.filter_pitch_roll_aiding_control.has_source = true;
        cmd_.u.filter_pitch_roll_aiding_control.source = source;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t
mipc_filter_pitch_roll_aiding_control_read(mipc_link_t *link,
                                           mipc_filter_pitch_roll_aiding_control_response_t *reply) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    mipc_result_t result_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_FILTER_PITCH_ROLL_AIDING_CONTROL;
        cmd_.u.filter_pitch_roll_aiding_control.function = MIPC_FUNCTION_SELECTOR_READ;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, &result_);
    if (kind_ == MIPC_RESULT_ACK && reply != NULL) {
        mipc_field_entry_t entry_;
        if (!mipc_result_reply_entry(&result_, &entry_) || entry_.descriptor != 0xBB ||
            mipc_filter_pitch_roll_aiding_control_response_decode(entry_.data, entry_.length, reply, NULL) !=
                MIPC_OK) {
            return mipc_link_fail(link, MIPC_RESULT_INVALID, "missing reply field 0xBB");
        }
    }
    return kind_;
}

mipc_result_kind_t mipc_filter_pitch_roll_aiding_control_save(mipc_link_t *link) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_FILTER_PITCH_ROLL_AIDING_CONTROL;
        cmd_.u.filter_pitch_roll_aiding_control.function = MIPC_FUNCTION_SELECTOR_SAVE;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_filter_pitch_roll_aiding_control_load(mipc_link_t *link) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_FILTER_PITCH_ROLL_AIDING_CONTROL;
        cmd_.u.filter_pitch_roll_aiding_control.function = MIPC_FUNCTION_SELECTOR_LOAD;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_filter_pitch_roll_aiding_control_default(mipc_link_t *link) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_FILTER_PITCH_ROLL_AIDING_CONTROL;
        cmd_.u.filter_pitch_roll_aiding_control.function = MIPC_FUNCTION_SELECTOR_DEFAULT;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_filter_inclination_source_write(mipc_link_t *link,
                                                        mipc_magnetic_param_source_t source,
                                                        float inclination) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_FILTER_INCLINATION_SOURCE;
        cmd_.u.filter_inclination_source.function = MIPC_FUNCTION_SELECTOR_WRITE;
        cmd_.u.filter_inclination_source.has_source = true;
        cmd_.u.filter_inclination_source.source = source;
        cmd_.u.filter_inclination_source.has_inclination = true;
        cmd_.u.filter_inclination_source.inclination = inclination;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_filter_inclination_source_read(mipc_link_t *link,
                                                       mipc_filter_inclination_source_response_t *reply) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    mipc_result_t result_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_FILTER_INCLINATION_SOURCE;
        cmd_.u.filter_inclination_source.function = MIPC_FUNCTION_SELECTOR_READ;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, &result_);
    if (kind_ == MIPC_RESULT_ACK && reply != NULL) {
        mipc_field_entry_t entry_;
        if (!mipc_result_reply_entry(&result_, &entry_) || entry_.descriptor != 0xBC ||
            mipc_filter_inclination_source_response_decode(entry_.data, entry_.length, reply, NULL) !=
                MIPC_OK) {
            return mipc_link_fail(link, MIPC_RESULT_INVALID, "missing reply field 0xBC");
        }
    }
    return kind_;
}

mipc_result_kind_t mipc_filter_inclination_source_save(mipc_link_t *link) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_FILTER_INCLINATION_SOURCE;
        cmd_.u.filter_inclination_source.function = MIPC_FUNCTION_SELECTOR_SAVE;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_filter_inclination_source_load(mipc_link_t *link) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_FILTER_INCLINATION_SOURCE;
        cmd_.u.filter_inclination_source.function = MIPC_FUNCTION_SELECTOR_LOAD;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_filter_inclination_source_default(mipc_link_t *link) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_FILTER_INCLINATION_SOURCE;
        cmd_.u.filter_inclination_source.function = MIPC_FUNCTION_SELECTOR_DEFAULT;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_filter_magnetic_field_magnitude_source_write(mipc_link_t *link,
                                                                     mipc_magnetic_param_source_t source,
                                                                     float magnitude) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_FILTER_MAGNETIC_FIELD_MAGNITUDE_SOURCE;
        cmd_.u.filter_magnetic_field_magnitude_source.function = MIPC_FUNCTION_SELECTOR_WRITE;
        cmd_.u.filter_magnetic_field_magnitude_source.has_source = true;
        cmd_.u.filter_magnetic_field_magnitude_source.source = source;
        cmd_.u.filter_magnetic_field_magnitude_source.has_magnitude = true;
        cmd_.u.filter_magnetic_field_magnitude_source.magnitude = magnitude;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_filter_magnetic_field_magnitude_source_read(
    mipc_link_t *link, mipc_filter_magnetic_field_magnitude_source_response_t *reply) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    mipc_result_t result_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_FILTER_MAGNETIC_FIELD_MAGNITUDE_SOURCE;
        cmd_.u.filter_magnetic_field_magnitude_source.function = MIPC_FUNCTION_SELECTOR_READ;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, &result_);
    if (kind_ == MIPC_RESULT_ACK && reply != NULL) {
        mipc_field_entry_t entry_;
        if (!mipc_result_reply_entry(&result_, &entry_) || entry_.descriptor != 0xBD ||
            mipc_filter_magnetic_field_magnitude_source_response_decode(entry_.data, entry_.length, reply,
                                                                        NULL) != MIPC_OK) {
            return mipc_link_fail(link, MIPC_RESULT_INVALID, "missing reply field 0xBD");
        }
    }
    return kind_;
}

mipc_result_kind_t mipc_filter_magnetic_field_magnitude_source_save(mipc_link_t *link) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_FILTER_MAGNETIC_FIELD_MAGNITUDE_SOURCE;
        cmd_.u.filter_magnetic_field_magnitude_source.function = MIPC_FUNCTION_SELECTOR_SAVE;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_filter_magnetic_field_magnitude_source_load(mipc_link_t *link) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_FILTER_MAGNETIC_FIELD_MAGNITUDE_SOURCE;
        cmd_.u.filter_magnetic_field_magnitude_source.function = MIPC_FUNCTION_SELECTOR_LOAD;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_filter_magnetic_field_magnitude_source_default(mipc_link_t *link) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_FILTER_MAGNETIC_FIELD_MAGNITUDE_SOURCE;
        cmd_.u.filter_magnetic_field_magnitude_source.function = MIPC_FUNCTION_SELECTOR_DEFAULT;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_filter_aiding_measurement_control_write(mipc_link_t *link,
                                                                mipc_aiding_measurement_source_t source,
                                                                bool enable) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_FILTER_AIDING_MEASUREMENT_CONTROL;
        cmd_.u.filter_aiding_measurement_control.function = MIPC_FUNCTION_SELECTOR_WRITE;
        cmd_.u.filter_aiding_measurement_control.source = source;
        cmd_.u.filter_aiding_measurement_control.has_enable = true;
        cmd_.u.filter_aiding_measurement_control.enable = enable;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t
mipc_filter_aiding_measurement_control_read(mipc_link_t *link, mipc_aiding_measurement_source_t source,
                                            mipc_filter_aiding_measurement_control_response_t *reply) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    mipc_result_t result_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_FILTER_AIDING_MEASUREMENT_CONTROL;
        cmd_.u.filter_aiding_measurement_control.function = MIPC_FUNCTION_SELECTOR_READ;
        cmd_.u.filter_aiding_measurement_control.source = source;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, &result_);
    if (kind_ == MIPC_RESULT_ACK && reply != NULL) {
        mipc_field_entry_t entry_;
        if (!mipc_result_reply_entry(&result_, &entry_) || entry_.descriptor != 0xD0 ||
            mipc_filter_aiding_measurement_control_response_decode(entry_.data, entry_.length, reply, NULL) !=
                MIPC_OK) {
            return mipc_link_fail(link, MIPC_RESULT_INVALID, "missing reply field 0xD0");
        }
    }
    return kind_;
}

mipc_result_kind_t mipc_filter_aiding_measurement_control_save(mipc_link_t *link,
                                                               mipc_aiding_measurement_source_t source) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_FILTER_AIDING_MEASUREMENT_CONTROL;
        cmd_.u.filter_aiding_measurement_control.function = MIPC_FUNCTION_SELECTOR_SAVE;
        cmd_.u.filter_aiding_measurement_control.source = source;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_filter_aiding_measurement_control_load(mipc_link_t *link,
                                                               mipc_aiding_measurement_source_t source) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_FILTER_AIDING_MEASUREMENT_CONTROL;
        cmd_.u.filter_aiding_measurement_control.function = MIPC_FUNCTION_SELECTOR_LOAD;
        cmd_.u.filter_aiding_measurement_control.source = source;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_filter_aiding_measurement_control_default(mipc_link_t *link,
                                                                  mipc_aiding_measurement_source_t source) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_FILTER_AIDING_MEASUREMENT_CONTROL;
        cmd_.u.filter_aiding_measurement_control.function = MIPC_FUNCTION_SELECTOR_DEFAULT;
        cmd_.u.filter_aiding_measurement_control.source = source;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_filter_initialization_configuration_write(
    mipc_link_t *link, uint8_t wait_for_run_command, mipc_filter_initial_condition_source_t initial_cond_src,
    mipc_heading_alignment_methods_t auto_heading_alignment_selector, float initial_heading,
    float initial_pitch, float initial_roll, const float initial_position[3], const float initial_velocity[3],
    mipc_filter_reference_frame_t reference_frame_selector) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_FILTER_INITIALIZATION_CONFIGURATION;
        cmd_.u.filter_initialization_configuration.function = MIPC_FUNCTION_SELECTOR_WRITE;
        cmd_.u.filter_initialization_configuration.has_wait_for_run_command = true;
        cmd_.u.filter_initialization_configuration.wait_for_run_command = wait_for_run_command;
        cmd_.u.filter_initialization_configuration.has_initial_cond_src = true;
        cmd_.u.filter_initialization_configuration.initial_cond_src = initial_cond_src;
        cmd_.u.filter_initialization_configuration.has_auto_heading_alignment_selector = true;
        cmd_.u.filter_initialization_configuration.auto_heading_alignment_selector =
            auto_heading_alignment_selector;
        cmd_.u.filter_initialization_configuration.has_initial_heading = true;
        cmd_.u.filter_initialization_configuration.initial_heading = initial_heading;
        cmd_.u.filter_initialization_configuration.has_initial_pitch = true;
        cmd_.u.filter_initialization_configuration.initial_pitch = initial_pitch;
        cmd_.u.filter_initialization_configuration.has_initial_roll = true;
        cmd_.u.filter_initialization_configuration.initial_roll = initial_roll;
        cmd_.u.filter_initialization_configuration.has_initial_position = true;
        memcpy(cmd_.u.filter_initialization_configuration.initial_position, initial_position,
               sizeof cmd_.u.filter_initialization_configuration.initial_position);
        cmd_.u.filter_initialization_configuration.has_initial_velocity = true;
        memcpy(cmd_.u.filter_initialization_configuration.initial_velocity, initial_velocity,
               sizeof cmd_.u.filter_initialization_configuration.initial_velocity);
        cmd_.u.filter_initialization_configuration.has_reference_frame_selector = true;
        cmd_.u.filter_initialization_configuration.reference_frame_selector = reference_frame_selector;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t
mipc_filter_initialization_configuration_read(mipc_link_t *link,
                                              mipc_filter_initialization_configuration_response_t *reply) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    mipc_result_t result_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_FILTER_INITIALIZATION_CONFIGURATION;
        cmd_.u.filter_initialization_configuration.function = MIPC_FUNCTION_SELECTOR_READ;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, &result_);
    if (kind_ == MIPC_RESULT_ACK && reply != NULL) {
        mipc_field_entry_t entry_;
        if (!mipc_result_reply_entry(&result_, &entry_) || entry_.descriptor != 0xD2 ||
            mipc_filter_initialization_configuration_response_decode(entry_.data, entry_.length, reply,
                                                                     NULL) != MIPC_OK) {
            return mipc_link_fail(link, MIPC_RESULT_INVALID, "missing reply field 0xD2");
        }
    }
    return kind_;
}

mipc_result_kind_t mipc_filter_initialization_configuration_save(mipc_link_t *link) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_FILTER_INITIALIZATION_CONFIGURATION;
        cmd_.u.filter_initialization_configuration.function = MIPC_FUNCTION_SELECTOR_SAVE;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_filter_initialization_configuration_load(mipc_link_t *link) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_FILTER_INITIALIZATION_CONFIGURATION;
        cmd_.u.filter_initialization_configuration.function = MIPC_FUNCTION_SELECTOR_LOAD;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_filter_initialization_configuration_default(mipc_link_t *link) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_FILTER_INITIALIZATION_CONFIGURATION;
        cmd_.u.filter_initialization_configuration.function = MIPC_FUNCTION_SELECTOR_DEFAULT;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_filter_adaptive_filter_control_write(mipc_link_t *link,
                                                             mipc_adaptive_filter_level_t level,
                                                             uint16_t time_limit) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_FILTER_ADAPTIVE_FILTER_CONTROL;
        cmd_.u.filter_adaptive_filter_control.function = MIPC_FUNCTION_SELECTOR_WRITE;
        cmd_.u.filter_adaptive_filter_control.has_level = true;
        cmd_.u.filter_adaptive_filter_control.level = level;
        cmd_.u.filter_adaptive_filter_control.has_time_limit = true;
        cmd_.u.filter_adaptive_filter_control.time_limit = time_limit;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t
mipc_filter_adaptive_filter_control_read(mipc_link_t *link,
                                         mipc_filter_adaptive_filter_control_response_t *reply) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    mipc_result_t result_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_FILTER_ADAPTIVE_FILTER_CONTROL;
        cmd_.u.filter_adaptive_filter_control.function = MIPC_FUNCTION_SELECTOR_READ;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, &result_);
    if (kind_ == MIPC_RESULT_ACK && reply != NULL) {
        mipc_field_entry_t entry_;
        if (!mipc_result_reply_entry(&result_, &entry_) || entry_.descriptor != 0xD3 ||
            mipc_filter_adaptive_filter_control_response_decode(entry_.data, entry_.length, reply, NULL) !=
                MIPC_OK) {
            return mipc_link_fail(link, MIPC_RESULT_INVALID, "missing reply field 0xD3");
        }
    }
    return kind_;
}

mipc_result_kind_t mipc_filter_adaptive_filter_control_save(mipc_link_t *link) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_FILTER_ADAPTIVE_FILTER_CONTROL;
        cmd_.u.filter_adaptive_filter_control.function = MIPC_FUNCTION_SELECTOR_SAVE;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_filter_adaptive_filter_control_load(mipc_link_t *link) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_FILTER_ADAPTIVE_FILTER_CONTROL;
        cmd_.u.filter_adaptive_filter_control.function = MIPC_FUNCTION_SELECTOR_LOAD;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_filter_adaptive_filter_control_default(mipc_link_t *link) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_FILTER_ADAPTIVE_FILTER_CONTROL;
        cmd_.u.filter_adaptive_filter_control.function = MIPC_FUNCTION_SELECTOR_DEFAULT;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_filter_multi_antenna_offset_write(mipc_link_t *link, uint8_t receiver_id,
                                                          const float antenna_offset[3]) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_FILTER_MULTI_ANTENNA_OFFSET;
        cmd_.u.filter_multi_antenna_offset.function = MIPC_FUNCTION_SELECTOR_WRITE;
        cmd_.u.filter_multi_antenna_offset.receiver_id = receiver_id;
        cmd_.u.filter_multi_antenna_offset.has_antenna_offset = true;
        memcpy(cmd_.u.filter_multi_antenna_offset.antenna_offset, antenna_offset,
               sizeof cmd_.u.filter_multi_antenna_offset.antenna_offset);
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_filter_multi_antenna_offset_read(mipc_link_t *link, uint8_t receiver_id,
                                                         mipc_filter_multi_antenna_offset_response_t *reply) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    mipc_result_t result_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_FILTER_MULTI_ANTENNA_OFFSET;
        cmd_.u.filter_multi_antenna_offset.function = MIPC_FUNCTION_SELECTOR_READ;
        cmd_.u.filter_multi_antenna_offset.receiver_id = receiver_id;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, &result_);
    if (kind_ == MIPC_RESULT_ACK && reply != NULL) {
        mipc_field_entry_t entry_;
        if (!mipc_result_reply_entry(&result_, &entry_) || entry_.descriptor != 0xD4 ||
            mipc_filter_multi_antenna_offset_response_decode(entry_.data, entry_.length, reply, NULL) !=
                MIPC_OK) {
            return mipc_link_fail(link, MIPC_RESULT_INVALID, "missing reply field 0xD4");
        }
    }
    return kind_;
}

mipc_result_kind_t mipc_filter_multi_antenna_offset_save(mipc_link_t *link, uint8_t receiver_id) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_FILTER_MULTI_ANTENNA_OFFSET;
        cmd_.u.filter_multi_antenna_offset.function = MIPC_FUNCTION_SELECTOR_SAVE;
        cmd_.u.filter_multi_antenna_offset.receiver_id = receiver_id;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_filter_multi_antenna_offset_load(mipc_link_t *link, uint8_t receiver_id) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_FILTER_MULTI_ANTENNA_OFFSET;
        cmd_.u.filter_multi_antenna_offset.function = MIPC_FUNCTION_SELECTOR_LOAD;
        cmd_.u.filter_multi_antenna_offset.receiver_id = receiver_id;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_filter_multi_antenna_offset_default(mipc_link_t *link, uint8_t receiver_id) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_FILTER_MULTI_ANTENNA_OFFSET;
        cmd_.u.filter_multi_antenna_offset.function = MIPC_FUNCTION_SELECTOR_DEFAULT;
        cmd_.u.filter_multi_antenna_offset.receiver_id = receiver_id;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t
mipc_filter_relative_position_configuration_write(mipc_link_t *link, mipc_relative_position_source_t source,
                                                  mipc_filter_reference_frame_t reference_frame_selector,
                                                  const double reference_coordinates[3]) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_FILTER_RELATIVE_POSITION_CONFIGURATION;
        cmd_.u.filter_relative_position_configuration.function = MIPC_FUNCTION_SELECTOR_WRITE;
        cmd_.u.filter_relative_position_configuration.has_source = true;
        cmd_.u.filter_relative_position_configuration.source = source;
        cmd_.u.filter_relative_position_configuration.has_reference_frame_selector = true;
        cmd_.u.filter_relative_position_configuration.reference_frame_selector = reference_frame_selector;
        cmd_.u.filter_relative_position_configuration.has_reference_coordinates = true;
        memcpy(cmd_.u.filter_relative_position_configuration.reference_coordinates, reference_coordinates,
               sizeof cmd_.u.filter_relative_position_configuration.reference_coordinates);
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_filter_relative_position_configuration_read(
    mipc_link_t *link, mipc_filter_relative_position_configuration_response_t *reply) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    mipc_result_t result_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_FILTER_RELATIVE_POSITION_CONFIGURATION;
        cmd_.u.filter_relative_position_configuration.function = MIPC_FUNCTION_SELECTOR_READ;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, &result_);
    if (kind_ == MIPC_RESULT_ACK && reply != NULL) {
        mipc_field_entry_t entry_;
        if (!mipc_result_reply_entry(&result_, &entry_) || entry_.descriptor != 0xD5 ||
            mipc_filter_relative_position_configuration_response_decode(entry_.data, entry_.length, reply,
                                                                        NULL) != MIPC_OK) {
            return mipc_link_fail(link, MIPC_RESULT_INVALID, "missing reply field 0xD5");
        }
    }
    return kind_;
}

mipc_result_kind_t mipc_filter_relative_position_configuration_save(mipc_link_t *link) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_FILTER_RELATIVE_POSITION_CONFIGURATION;
        cmd_.u.filter_relative_position_configuration.function = MIPC_FUNCTION_SELECTOR_SAVE;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_filter_relative_position_configuration_load(mipc_link_t *link) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_FILTER_RELATIVE_POSITION_CONFIGURATION;
        cmd_.u.filter_relative_position_configuration.function = MIPC_FUNCTION_SELECTOR_LOAD;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_filter_relative_position_configuration_default(mipc_link_t *link) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_FILTER_RELATIVE_POSITION_CONFIGURATION;
        cmd_.u.filter_relative_position_configuration.function = MIPC_FUNCTION_SELECTOR_DEFAULT;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_filter_reference_point_lever_arm_write(mipc_link_t *link,
                                                               mipc_reference_point_selector_t ref_point_sel,
                                                               const float lever_arm_offset[3]) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_FILTER_REFERENCE_POINT_LEVER_ARM;
        cmd_.u.filter_reference_point_lever_arm.function = MIPC_FUNCTION_SELECTOR_WRITE;
        cmd_.u.filter_reference_point_lever_arm.has_ref_point_sel = true;
        cmd_.u.filter_reference_point_lever_arm.ref_point_sel = ref_point_sel;
        cmd_.u.filter_reference_point_lever_arm.has_lever_arm_offset = true;
        memcpy(cmd_.u.filter_reference_point_lever_arm.lever_arm_offset, lever_arm_offset,
               sizeof cmd_.u.filter_reference_point_lever_arm.lever_arm_offset);
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t
mipc_filter_reference_point_lever_arm_read(mipc_link_t *link,
                                           mipc_filter_reference_point_lever_arm_response_t *reply) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    mipc_result_t result_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_FILTER_REFERENCE_POINT_LEVER_ARM;
        cmd_.u.filter_reference_point_lever_arm.function = MIPC_FUNCTION_SELECTOR_READ;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, &result_);
    if (kind_ == MIPC_RESULT_ACK && reply != NULL) {
        mipc_field_entry_t entry_;
        if (!mipc_result_reply_entry(&result_, &entry_) || entry_.descriptor != 0xD6 ||
            mipc_filter_reference_point_lever_arm_response_decode(entry_.data, entry_.length, reply, NULL) !=
                MIPC_OK) {
            return mipc_link_fail(link, MIPC_RESULT_INVALID, "missing reply field 0xD6");
        }
    }
    return kind_;
}

mipc_result_kind_t mipc_filter_reference_point_lever_arm_save(mipc_link_t *link) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_FILTER_REFERENCE_POINT_LEVER_ARM;
        cmd_.u.filter_reference_point_lever_arm.function = MIPC_FUNCTION_SELECTOR_SAVE;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_filter_reference_point_lever_arm_load(mipc_link_t *link) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_FILTER_REFERENCE_POINT_LEVER_ARM;
        cmd_.u.filter_reference_point_lever_arm.function = MIPC_FUNCTION_SELECTOR_LOAD;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_filter_reference_point_lever_arm_default(mipc_link_t *link) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_FILTER_REFERENCE_POINT_LEVER_ARM;
        cmd_.u.filter_reference_point_lever_arm.function = MIPC_FUNCTION_SELECTOR_DEFAULT;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_filter_speed_lever_arm_write(mipc_link_t *link, uint8_t source,
                                                     const float lever_arm_offset[3]) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_FILTER_SPEED_LEVER_ARM;
        cmd_.u.filter_speed_lever_arm.function = MIPC_FUNCTION_SELECTOR_WRITE;
        cmd_.u.filter_speed_lever_arm.source = source;
        cmd_.u.filter_speed_lever_arm.has_lever_arm_offset = true;
        memcpy(cmd_.u.filter_speed_lever_arm.lever_arm_offset, lever_arm_offset,
               sizeof cmd_.u.filter_speed_lever_arm.lever_arm_offset);
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_filter_speed_lever_arm_read(mipc_link_t *link, uint8_t source,
                                                    mipc_filter_speed_lever_arm_response_t *reply) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    mipc_result_t result_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_FILTER_SPEED_LEVER_ARM;
        cmd_.u.filter_speed_lever_arm.function = MIPC_FUNCTION_SELECTOR_READ;
        cmd_.u.filter_speed_lever_arm.source = source;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, &result_);
    if (kind_ == MIPC_RESULT_ACK && reply != NULL) {
        mipc_field_entry_t entry_;
        if (!mipc_result_reply_entry(&result_, &entry_) || entry_.descriptor != 0xE1 ||
            mipc_filter_speed_lever_arm_response_decode(entry_.data, entry_.length, reply, NULL) != MIPC_OK) {
            return mipc_link_fail(link, MIPC_RESULT_INVALID, "missing reply field 0xE1");
        }
    }
    return kind_;
}

mipc_result_kind_t mipc_filter_speed_lever_arm_save(mipc_link_t *link, uint8_t source) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_FILTER_SPEED_LEVER_ARM;
        cmd_.u.filter_speed_lever_arm.function = MIPC_FUNCTION_SELECTOR_SAVE;
        cmd_.u.filter_speed_lever_arm.source = source;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_filter_speed_lever_arm_load(mipc_link_t *link, uint8_t source) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_FILTER_SPEED_LEVER_ARM;
        cmd_.u.filter_speed_lever_arm.function = MIPC_FUNCTION_SELECTOR_LOAD;
        cmd_.u.filter_speed_lever_arm.source = source;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_filter_speed_lever_arm_default(mipc_link_t *link, uint8_t source) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_FILTER_SPEED_LEVER_ARM;
        cmd_.u.filter_speed_lever_arm.function = MIPC_FUNCTION_SELECTOR_DEFAULT;
        cmd_.u.filter_speed_lever_arm.source = source;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_filter_wheeled_vehicle_constraint_control_write(mipc_link_t *link, uint8_t enable) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_FILTER_WHEELED_VEHICLE_CONSTRAINT_CONTROL;
        cmd_.u.filter_wheeled_vehicle_constraint_control.function = MIPC_FUNCTION_SELECTOR_WRITE;
        cmd_.u.filter_wheeled_vehicle_constraint_control.has_enable = true;
        cmd_.u.filter_wheeled_vehicle_constraint_control.enable = enable;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_filter_wheeled_vehicle_constraint_control_read(
    mipc_link_t *link, mipc_filter_wheeled_vehicle_constraint_control_response_t *reply) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    mipc_result_t result_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_FILTER_WHEELED_VEHICLE_CONSTRAINT_CONTROL;
        cmd_.u.filter_wheeled_vehicle_constraint_control.function = MIPC_FUNCTION_SELECTOR_READ;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, &result_);
    if (kind_ == MIPC_RESULT_ACK && reply != NULL) {
        mipc_field_entry_t entry_;
        if (!mipc_result_reply_entry(&result_, &entry_) || entry_.descriptor != 0xE3 ||
            mipc_filter_wheeled_vehicle_constraint_control_response_decode(entry_.data, entry_.length, reply,
                                                                           NULL) != MIPC_OK) {
            return mipc_link_fail(link, MIPC_RESULT_INVALID, "missing reply field 0xE3");
        }
    }
    return kind_;
}

mipc_result_kind_t mipc_filter_wheeled_vehicle_constraint_control_save(mipc_link_t *link) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_FILTER_WHEELED_VEHICLE_CONSTRAINT_CONTROL;
        cmd_.u.filter_wheeled_vehicle_constraint_control.function = MIPC_FUNCTION_SELECTOR_SAVE;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_filter_wheeled_vehicle_constraint_control_load(mipc_link_t *link) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_FILTER_WHEELED_VEHICLE_CONSTRAINT_CONTROL;
        cmd_.u.filter_wheeled_vehicle_constraint_control.function = MIPC_FUNCTION_SELECTOR_LOAD;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_filter_wheeled_vehicle_constraint_control_default(mipc_link_t *link) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_FILTER_WHEELED_VEHICLE_CONSTRAINT_CONTROL;
        cmd_.u.filter_wheeled_vehicle_constraint_control.function = MIPC_FUNCTION_SELECTOR_DEFAULT;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_filter_gnss_antenna_calibration_control_write(mipc_link_t *link, uint8_t enable,
                                                                      float max_offset) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_FILTER_GNSS_ANTENNA_CALIBRATION_CONTROL;
        cmd_.u.filter_gnss_antenna_calibration_control.function = MIPC_FUNCTION_SELECTOR_WRITE;
        cmd_.u.filter_gnss_antenna_calibration_control.has_enable = true;
        cmd_.u.filter_gnss_antenna_calibration_control.enable = enable;
        cmd_.u.filter_gnss_antenna_calibration_control.has_max_offset = true;
        cmd_.u.filter_gnss_antenna_calibration_control.max_offset = max_offset;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_filter_gnss_antenna_calibration_control_read(
    mipc_link_t *link, mipc_filter_gnss_antenna_calibration_control_response_t *reply) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    mipc_result_t result_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_FILTER_GNSS_ANTENNA_CALIBRATION_CONTROL;
        cmd_.u.filter_gnss_antenna_calibration_control.function = MIPC_FUNCTION_SELECTOR_READ;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, &result_);
    if (kind_ == MIPC_RESULT_ACK && reply != NULL) {
        mipc_field_entry_t entry_;
        if (!mipc_result_reply_entry(&result_, &entry_) || entry_.descriptor != 0xE4 ||
            mipc_filter_gnss_antenna_calibration_control_response_decode(entry_.data, entry_.length, reply,
                                                                         NULL) != MIPC_OK) {
            return mipc_link_fail(link, MIPC_RESULT_INVALID, "missing reply field 0xE4");
        }
    }
    return kind_;
}

mipc_result_kind_t mipc_filter_gnss_antenna_calibration_control_save(mipc_link_t *link) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_FILTER_GNSS_ANTENNA_CALIBRATION_CONTROL;
        cmd_.u.filter_gnss_antenna_calibration_control.function = MIPC_FUNCTION_SELECTOR_SAVE;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_filter_gnss_antenna_calibration_control_load(mipc_link_t *link) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_FILTER_GNSS_ANTENNA_CALIBRATION_CONTROL;
        cmd_.u.filter_gnss_antenna_calibration_control.function = MIPC_FUNCTION_SELECTOR_LOAD;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_filter_gnss_antenna_calibration_control_default(mipc_link_t *link) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_FILTER_GNSS_ANTENNA_CALIBRATION_CONTROL;
        cmd_.u.filter_gnss_antenna_calibration_control.function = MIPC_FUNCTION_SELECTOR_DEFAULT;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_gnss_receiver_info(mipc_link_t *link, mipc_gnss_receiver_info_response_t *reply) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    mipc_result_t result_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_GNSS_RECEIVER_INFO;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, &result_);
    if (kind_ == MIPC_RESULT_ACK && reply != NULL) {
        mipc_field_entry_t entry_;
        if (!mipc_result_reply_entry(&result_, &entry_) || entry_.descriptor != 0x81 ||
            mipc_gnss_receiver_info_response_decode(entry_.data, entry_.length, reply, NULL) != MIPC_OK) {
            return mipc_link_fail(link, MIPC_RESULT_INVALID, "missing reply field 0x81");
        }
    }
    return kind_;
}

mipc_result_kind_t mipc_gnss_signal_configuration_write(mipc_link_t *link, mipc_gnss_gps_signals_t gps_enable,
                                                        mipc_gnss_glonass_signals_t glonass_enable,
                                                        mipc_gnss_galileo_signals_t galileo_enable,
                                                        mipc_gnss_beidou_signals_t beidou_enable,
                                                        const uint8_t reserved[4]) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_GNSS_SIGNAL_CONFIGURATION;
        cmd_.u.gnss_signal_configuration.function = MIPC_FUNCTION_SELECTOR_WRITE;
        cmd_.u.gnss_signal_configuration.has_gps_enable = true;
        cmd_.u.gnss_signal_configuration.gps_enable = gps_enable;
        cmd_.u.gnss_signal_configuration.has_glonass_enable = true;
        cmd_.u.gnss_signal_configuration.glonass_enable = glonass_enable;
        cmd_.u.gnss_signal_configuration.has_galileo_enable = true;
        cmd_.u.gnss_signal_configuration.galileo_enable = galileo_enable;
        cmd_.u.gnss_signal_configuration.has_beidou_enable = true;
        cmd_.u.gnss_signal_configuration.beidou_enable = beidou_enable;
        cmd_.u.gnss_signal_configuration.has_reserved = true;
        memcpy(cmd_.u.gnss_signal_configuration.reserved, reserved,
               sizeof cmd_.u.gnss_signal_configuration.reserved);
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_gnss_signal_configuration_read(mipc_link_t *link,
                                                       mipc_gnss_signal_configuration_response_t *reply) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    mipc_result_t result_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_GNSS_SIGNAL_CONFIGURATION;
        cmd_.u.gnss_signal_configuration.function = MIPC_FUNCTION_SELECTOR_READ;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, &result_);
    if (kind_ == MIPC_RESULT_ACK && reply != NULL) {
        mipc_field_entry_t entry_;
        if (!mipc_result_reply_entry(&result_, &entry_) || entry_.descriptor != 0x82 ||
            mipc_gnss_signal_configuration_response_decode(entry_.data, entry_.length, reply, NULL) !=
                MIPC_OK) {
            return mipc_link_fail(link, MIPC_RESULT_INVALID, "missing reply field 0x82");
        }
    }
    return kind_;
}

mipc_result_kind_t mipc_gnss_signal_configuration_save(mipc_link_t *link) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_GNSS_SIGNAL_CONFIGURATION;
        cmd_.u.gnss_signal_configuration.function = MIPC_FUNCTION_SELECTOR_SAVE;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_gnss_signal_configuration_load(mipc_link_t *link) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_GNSS_SIGNAL_CONFIGURATION;
        cmd_.u.gnss_signal_configuration.function = MIPC_FUNCTION_SELECTOR_LOAD;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_gnss_signal_configuration_default(mipc_link_t *link) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_GNSS_SIGNAL_CONFIGURATION;
        cmd_.u.gnss_signal_configuration.function = MIPC_FUNCTION_SELECTOR_DEFAULT;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_gnss_spartn_configuration_write(mipc_link_t *link, uint8_t enable,
                                                        mipc_spartn_connection_type_t type,
                                                        uint32_t current_key_tow, uint16_t current_key_week,
                                                        const char current_key[32], uint32_t next_key_tow,
                                                        uint16_t next_key_week, const char next_key[32]) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_GNSS_SPARTN_CONFIGURATION;
        cmd_.u.gnss_spartn_configuration.function = MIPC_FUNCTION_SELECTOR_WRITE;
        cmd_.u.gnss_spartn_configuration.has_enable = true;
        cmd_.u.gnss_spartn_configuration.enable = enable;
        cmd_.u.gnss_spartn_configuration.has_type = true;
        cmd_.u.gnss_spartn_configuration.type = type;
        cmd_.u.gnss_spartn_configuration.has_current_key_tow = true;
        cmd_.u.gnss_spartn_configuration.current_key_tow = current_key_tow;
        cmd_.u.gnss_spartn_configuration.has_current_key_week = true;
        cmd_.u.gnss_spartn_configuration.current_key_week = current_key_week;
        cmd_.u.gnss_spartn_configuration.has_current_key = true;
        memcpy(cmd_.u.gnss_spartn_configuration.current_key, current_key,
               sizeof cmd_.u.gnss_spartn_configuration.current_key);
        cmd_.u.gnss_spartn_configuration.has_next_key_tow = true;
        cmd_.u.gnss_spartn_configuration.next_key_tow = next_key_tow;
        cmd_.u.gnss_spartn_configuration.has_next_key_week = true;
        cmd_.u.gnss_spartn_configuration.next_key_week = next_key_week;
        cmd_.u.gnss_spartn_configuration.has_next_key = true;
        memcpy(cmd_.u.gnss_spartn_configuration.next_key, next_key,
               sizeof cmd_.u.gnss_spartn_configuration.next_key);
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_gnss_spartn_configuration_read(mipc_link_t *link,
                                                       mipc_gnss_spartn_configuration_response_t *reply) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    mipc_result_t result_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_GNSS_SPARTN_CONFIGURATION;
        cmd_.u.gnss_spartn_configuration.function = MIPC_FUNCTION_SELECTOR_READ;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, &result_);
    if (kind_ == MIPC_RESULT_ACK && reply != NULL) {
        mipc_field_entry_t entry_;
        if (!mipc_result_reply_entry(&result_, &entry_) || entry_.descriptor != 0xA0 ||
            mipc_gnss_spartn_configuration_response_decode(entry_.data, entry_.length, reply, NULL) !=
                MIPC_OK) {
            return mipc_link_fail(link, MIPC_RESULT_INVALID, "missing reply field 0xA0");
        }
    }
    return kind_;
}

mipc_result_kind_t mipc_gnss_spartn_configuration_save(mipc_link_t *link) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_GNSS_SPARTN_CONFIGURATION;
        cmd_.u.gnss_spartn_configuration.function = MIPC_FUNCTION_SELECTOR_SAVE;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_gnss_spartn_configuration_load(mipc_link_t *link) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_GNSS_SPARTN_CONFIGURATION;
        cmd_.u.gnss_spartn_configuration.function = MIPC_FUNCTION_SELECTOR_LOAD;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_gnss_spartn_configuration_default(mipc_link_t *link) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_GNSS_SPARTN_CONFIGURATION;
        cmd_.u.gnss_spartn_configuration.function = MIPC_FUNCTION_SELECTOR_DEFAULT;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_aiding_frame_config_write(mipc_link_t *link, uint8_t frame_id,
                                                  mipc_aiding_frame_format_t format, bool tracking_enabled,
                                                  const float translation[3],
                                                  const mipc_aiding_frame_rotation_t *rotation) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_AIDING_FRAME_CONFIG;
        cmd_.u.aiding_frame_config.function = MIPC_FUNCTION_SELECTOR_WRITE;
        cmd_.u.aiding_frame_config.frame_id = frame_id;
        cmd_.u.aiding_frame_config.has_format = true;
        cmd_.u.aiding_frame_config.format = format;
        cmd_.u.aiding_frame_config.has_tracking_enabled = true;
        cmd_.u.aiding_frame_config.tracking_enabled = tracking_enabled;
        cmd_.u.aiding_frame_config.has_translation = true;
        memcpy(cmd_.u.aiding_frame_config.translation, translation,
               sizeof cmd_.u.aiding_frame_config.translation);
        cmd_.u.aiding_frame_config.has_rotation = true;
        cmd_.u.aiding_frame_config.rotation = *rotation;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_aiding_frame_config_read(mipc_link_t *link, uint8_t frame_id,
                                                 mipc_aiding_frame_format_t format,
                                                 mipc_aiding_frame_config_response_t *reply) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    mipc_result_t result_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_AIDING_FRAME_CONFIG;
        cmd_.u.aiding_frame_config.function = MIPC_FUNCTION_SELECTOR_READ;
        cmd_.u.aiding_frame_config.frame_id = frame_id;
        cmd_.u.aiding_frame_config.has_format = true;
        cmd_.u.aiding_frame_config.format = format;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, &result_);
    if (kind_ == MIPC_RESULT_ACK && reply != NULL) {
        mipc_field_entry_t entry_;
        if (!mipc_result_reply_entry(&result_, &entry_) || entry_.descriptor != 0x81 ||
            mipc_aiding_frame_config_response_decode(entry_.data, entry_.length, reply, NULL) != MIPC_OK) {
            return mipc_link_fail(link, MIPC_RESULT_INVALID, "missing reply field 0x81");
        }
    }
    return kind_;
}

mipc_result_kind_t mipc_aiding_frame_config_save(mipc_link_t *link, uint8_t frame_id) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_AIDING_FRAME_CONFIG;
        cmd_.u.aiding_frame_config.function = MIPC_FUNCTION_SELECTOR_SAVE;
        cmd_.u.aiding_frame_config.frame_id = frame_id;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_aiding_frame_config_load(mipc_link_t *link, uint8_t frame_id) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_AIDING_FRAME_CONFIG;
        cmd_.u.aiding_frame_config.function = MIPC_FUNCTION_SELECTOR_LOAD;
        cmd_.u.aiding_frame_config.frame_id = frame_id;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_aiding_frame_config_default(mipc_link_t *link, uint8_t frame_id) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_AIDING_FRAME_CONFIG;
        cmd_.u.aiding_frame_config.function = MIPC_FUNCTION_SELECTOR_DEFAULT;
        cmd_.u.aiding_frame_config.frame_id = frame_id;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_aiding_echo_control_write(mipc_link_t *link, mipc_aiding_echo_mode_t mode) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_AIDING_ECHO_CONTROL;
        cmd_.u.aiding_echo_control.function = MIPC_FUNCTION_SELECTOR_WRITE;
        cmd_.u.aiding_echo_control.has_mode = true;
        cmd_.u.aiding_echo_control.mode = mode;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_aiding_echo_control_read(mipc_link_t *link,
                                                 mipc_aiding_echo_control_response_t *reply) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    mipc_result_t result_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_AIDING_ECHO_CONTROL;
        cmd_.u.aiding_echo_control.function = MIPC_FUNCTION_SELECTOR_READ;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, &result_);
    if (kind_ == MIPC_RESULT_ACK && reply != NULL) {
        mipc_field_entry_t entry_;
        if (!mipc_result_reply_entry(&result_, &entry_) || entry_.descriptor != 0x9F ||
            mipc_aiding_echo_control_response_decode(entry_.data, entry_.length, reply, NULL) != MIPC_OK) {
            return mipc_link_fail(link, MIPC_RESULT_INVALID, "missing reply field 0x9F");
        }
    }
    return kind_;
}

mipc_result_kind_t mipc_aiding_echo_control_save(mipc_link_t *link) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_AIDING_ECHO_CONTROL;
        cmd_.u.aiding_echo_control.function = MIPC_FUNCTION_SELECTOR_SAVE;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_aiding_echo_control_load(mipc_link_t *link) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_AIDING_ECHO_CONTROL;
        cmd_.u.aiding_echo_control.function = MIPC_FUNCTION_SELECTOR_LOAD;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_aiding_echo_control_default(mipc_link_t *link) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_AIDING_ECHO_CONTROL;
        cmd_.u.aiding_echo_control.function = MIPC_FUNCTION_SELECTOR_DEFAULT;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_aiding_ecef_position(mipc_link_t *link, const mipc_aiding_time_t *time,
                                             uint8_t frame_id, const double position[3],
                                             const float uncertainty[3],
                                             mipc_aiding_vector_valid_flags_t valid_flags) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_AIDING_ECEF_POSITION;
        cmd_.u.aiding_ecef_position.time = *time;
        cmd_.u.aiding_ecef_position.frame_id = frame_id;
        memcpy(cmd_.u.aiding_ecef_position.position, position, sizeof cmd_.u.aiding_ecef_position.position);
        memcpy(cmd_.u.aiding_ecef_position.uncertainty, uncertainty,
               sizeof cmd_.u.aiding_ecef_position.uncertainty);
        cmd_.u.aiding_ecef_position.valid_flags = valid_flags;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_aiding_llh_position(mipc_link_t *link, const mipc_aiding_time_t *time,
                                            uint8_t frame_id, double latitude, double longitude,
                                            double height, const float uncertainty[3],
                                            mipc_aiding_llh_valid_flags_t valid_flags) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_AIDING_LLH_POSITION;
        cmd_.u.aiding_llh_position.time = *time;
        cmd_.u.aiding_llh_position.frame_id = frame_id;
        cmd_.u.aiding_llh_position.latitude = latitude;
        cmd_.u.aiding_llh_position.longitude = longitude;
        cmd_.u.aiding_llh_position.height = height;
        memcpy(cmd_.u.aiding_llh_position.uncertainty, uncertainty,
               sizeof cmd_.u.aiding_llh_position.uncertainty);
        cmd_.u.aiding_llh_position.valid_flags = valid_flags;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_aiding_height_above_ellipsoid(mipc_link_t *link, const mipc_aiding_time_t *time,
                                                      uint8_t frame_id, float height, float uncertainty,
                                                      uint16_t valid_flags) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_AIDING_HEIGHT_ABOVE_ELLIPSOID;
        cmd_.u.aiding_height_above_ellipsoid.time = *time;
        cmd_.u.aiding_height_above_ellipsoid.frame_id = frame_id;
        cmd_.u.aiding_height_above_ellipsoid.height = height;
        cmd_.u.aiding_height_above_ellipsoid.uncertainty = uncertainty;
        cmd_.u.aiding_height_above_ellipsoid.valid_flags = valid_flags;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_aiding_ecef_velocity(mipc_link_t *link, const mipc_aiding_time_t *time,
                                             uint8_t frame_id, const float velocity[3],
                                             const float uncertainty[3],
                                             mipc_aiding_vector_valid_flags_t valid_flags) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_AIDING_ECEF_VELOCITY;
        cmd_.u.aiding_ecef_velocity.time = *time;
        cmd_.u.aiding_ecef_velocity.frame_id = frame_id;
        memcpy(cmd_.u.aiding_ecef_velocity.velocity, velocity, sizeof cmd_.u.aiding_ecef_velocity.velocity);
        memcpy(cmd_.u.aiding_ecef_velocity.uncertainty, uncertainty,
               sizeof cmd_.u.aiding_ecef_velocity.uncertainty);
        cmd_.u.aiding_ecef_velocity.valid_flags = valid_flags;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_aiding_ned_velocity(mipc_link_t *link, const mipc_aiding_time_t *time,
                                            uint8_t frame_id, const float velocity[3],
                                            const float uncertainty[3],
                                            mipc_aiding_vector_valid_flags_t valid_flags) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_AIDING_NED_VELOCITY;
        cmd_.u.aiding_ned_velocity.time = *time;
        cmd_.u.aiding_ned_velocity.frame_id = frame_id;
        memcpy(cmd_.u.aiding_ned_velocity.velocity, velocity, sizeof cmd_.u.aiding_ned_velocity.velocity);
        memcpy(cmd_.u.aiding_ned_velocity.uncertainty, uncertainty,
               sizeof cmd_.u.aiding_ned_velocity.uncertainty);
        cmd_.u.aiding_ned_velocity.valid_flags = valid_flags;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_aiding_body_frame_velocity(mipc_link_t *link, const mipc_aiding_time_t *time,
                                                   uint8_t frame_id, const float velocity[3],
                                                   const float uncertainty[3],
                                                   mipc_aiding_vector_valid_flags_t valid_flags) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_AIDING_BODY_FRAME_VELOCITY;
        cmd_.u.aiding_body_frame_velocity.time = *time;
        cmd_.u.aiding_body_frame_velocity.frame_id = frame_id;
        memcpy(cmd_.u.aiding_body_frame_velocity.velocity, velocity,
               sizeof cmd_.u.aiding_body_frame_velocity.velocity);
        memcpy(cmd_.u.aiding_body_frame_velocity.uncertainty, uncertainty,
               sizeof cmd_.u.aiding_body_frame_velocity.uncertainty);
        cmd_.u.aiding_body_frame_velocity.valid_flags = valid_flags;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_aiding_true_heading(mipc_link_t *link, const mipc_aiding_time_t *time,
                                            uint8_t frame_id, float heading, float uncertainty,
                                            uint16_t valid_flags) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_AIDING_TRUE_HEADING;
        cmd_.u.aiding_true_heading.time = *time;
        cmd_.u.aiding_true_heading.frame_id = frame_id;
        cmd_.u.aiding_true_heading.heading = heading;
        cmd_.u.aiding_true_heading.uncertainty = uncertainty;
        cmd_.u.aiding_true_heading.valid_flags = valid_flags;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_aiding_magnetic_field(mipc_link_t *link, const mipc_aiding_time_t *time,
                                              uint8_t frame_id, const float magnetic_field[3],
                                              const float uncertainty[3],
                                              mipc_aiding_vector_valid_flags_t valid_flags) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_AIDING_MAGNETIC_FIELD;
        cmd_.u.aiding_magnetic_field.time = *time;
        cmd_.u.aiding_magnetic_field.frame_id = frame_id;
        memcpy(cmd_.u.aiding_magnetic_field.magnetic_field, magnetic_field,
               sizeof cmd_.u.aiding_magnetic_field.magnetic_field);
        memcpy(cmd_.u.aiding_magnetic_field.uncertainty, uncertainty,
               sizeof cmd_.u.aiding_magnetic_field.uncertainty);
        cmd_.u.aiding_magnetic_field.valid_flags = valid_flags;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_aiding_pressure(mipc_link_t *link, const mipc_aiding_time_t *time, uint8_t frame_id,
                                        float pressure, float uncertainty, uint16_t valid_flags) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_AIDING_PRESSURE;
        cmd_.u.aiding_pressure.time = *time;
        cmd_.u.aiding_pressure.frame_id = frame_id;
        cmd_.u.aiding_pressure.pressure = pressure;
        cmd_.u.aiding_pressure.uncertainty = uncertainty;
        cmd_.u.aiding_pressure.valid_flags = valid_flags;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_system_communication_mode_write(mipc_link_t *link, mipc_system_comm_mode_t mode) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_SYSTEM_COMMUNICATION_MODE;
        cmd_.u.system_communication_mode.function = MIPC_FUNCTION_SELECTOR_WRITE;
        cmd_.u.system_communication_mode.has_mode = true;
        cmd_.u.system_communication_mode.mode = mode;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_system_communication_mode_read(mipc_link_t *link,
                                                       mipc_system_communication_mode_response_t *reply) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    mipc_result_t result_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_SYSTEM_COMMUNICATION_MODE;
        cmd_.u.system_communication_mode.function = MIPC_FUNCTION_SELECTOR_READ;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, &result_);
    if (kind_ == MIPC_RESULT_ACK && reply != NULL) {
        mipc_field_entry_t entry_;
        if (!mipc_result_reply_entry(&result_, &entry_) || entry_.descriptor != 0x90 ||
            mipc_system_communication_mode_response_decode(entry_.data, entry_.length, reply, NULL) !=
                MIPC_OK) {
            return mipc_link_fail(link, MIPC_RESULT_INVALID, "missing reply field 0x90");
        }
    }
    return kind_;
}

mipc_result_kind_t mipc_system_communication_mode_save(mipc_link_t *link) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_SYSTEM_COMMUNICATION_MODE;
        cmd_.u.system_communication_mode.function = MIPC_FUNCTION_SELECTOR_SAVE;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_system_communication_mode_load(mipc_link_t *link) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_SYSTEM_COMMUNICATION_MODE;
        cmd_.u.system_communication_mode.function = MIPC_FUNCTION_SELECTOR_LOAD;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

mipc_result_kind_t mipc_system_communication_mode_default(mipc_link_t *link) {
    mipc_field_value_t cmd_;
    mipc_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = MIPC_FIELD_SYSTEM_COMMUNICATION_MODE;
        cmd_.u.system_communication_mode.function = MIPC_FUNCTION_SELECTOR_DEFAULT;
    }
    kind_ = mipc_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}
