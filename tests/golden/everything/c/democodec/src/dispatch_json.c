/* Canonical JSON of a decoded field value (the democodec_json library). Generated from the spec: do
 * not edit. */
#include "democodec/dispatch.h"
#include "layouts_internal.h"

void democ_value_to_json(democ_jw_t *w, const democ_field_value_t *value) {
    democ_layout_to_json(w, value->id, &value->u);
}

void democ_layout_to_json(democ_jw_t *w, democ_field_id_t id, const void *in) {
    switch (id) {
    case DEMOC_FIELD_ACK:
        democ_ack_to_json(w, (const democ_ack_t *)in);
        return;
    case DEMOC_FIELD_COMMANDS_PING:
        democ_commands_ping_to_json(w, (const democ_commands_ping_t *)in);
        return;
    case DEMOC_FIELD_COMMANDS_CONFIGURE:
        democ_commands_configure_to_json(w, (const democ_commands_configure_t *)in);
        return;
    case DEMOC_FIELD_COMMANDS_CONFIGURATION:
        democ_commands_configuration_to_json(w, (const democ_commands_configuration_t *)in);
        return;
    case DEMOC_FIELD_COMMANDS_PER_DEVICE_DEV_A:
        democ_commands_per_device_dev_a_to_json(w, (const democ_commands_per_device_dev_a_t *)in);
        return;
    case DEMOC_FIELD_COMMANDS_PER_DEVICE_DEV_B:
        democ_commands_per_device_dev_b_to_json(w, (const democ_commands_per_device_dev_b_t *)in);
        return;
    case DEMOC_FIELD_DATA_SAMPLE:
        democ_data_sample_to_json(w, (const democ_data_sample_t *)in);
        return;
    case DEMOC_FIELD_RECEIVER_1_LLH_POSITION:
        democ_receiver_1_llh_position_to_json(w, (const democ_receiver_1_llh_position_t *)in);
        return;
    case DEMOC_FIELD_RECEIVER_2_LLH_POSITION:
        democ_receiver_2_llh_position_to_json(w, (const democ_receiver_2_llh_position_t *)in);
        return;
    case DEMOC_FIELD_SHARED_TIMESTAMP:
        democ_shared_timestamp_to_json(w, (const democ_shared_timestamp_t *)in);
        return;
    case DEMOC_FIELD_NONE:
    case DEMOC_FIELD_COUNT:
    default:
        democ_jw_lit(w, "null");
        return;
    }
}

int democ_value_from_json(democ_jr_t *jr, size_t pos, democ_field_id_t id, democ_field_value_t *value) {
    value->id = id;
    switch (id) {
    case DEMOC_FIELD_ACK:
        return democ_ack_from_json(jr, pos, &value->u.ack);
    case DEMOC_FIELD_COMMANDS_PING:
        return democ_commands_ping_from_json(jr, pos, &value->u.commands_ping);
    case DEMOC_FIELD_COMMANDS_CONFIGURE:
        return democ_commands_configure_from_json(jr, pos, &value->u.commands_configure);
    case DEMOC_FIELD_COMMANDS_CONFIGURATION:
        return democ_commands_configuration_from_json(jr, pos, &value->u.commands_configuration);
    case DEMOC_FIELD_COMMANDS_PER_DEVICE_DEV_A:
        return democ_commands_per_device_dev_a_from_json(jr, pos, &value->u.commands_per_device_dev_a);
    case DEMOC_FIELD_COMMANDS_PER_DEVICE_DEV_B:
        return democ_commands_per_device_dev_b_from_json(jr, pos, &value->u.commands_per_device_dev_b);
    case DEMOC_FIELD_DATA_SAMPLE:
        return democ_data_sample_from_json(jr, pos, &value->u.data_sample);
    case DEMOC_FIELD_RECEIVER_1_LLH_POSITION:
        return democ_receiver_1_llh_position_from_json(jr, pos, &value->u.receiver_1_llh_position);
    case DEMOC_FIELD_RECEIVER_2_LLH_POSITION:
        return democ_receiver_2_llh_position_from_json(jr, pos, &value->u.receiver_2_llh_position);
    case DEMOC_FIELD_SHARED_TIMESTAMP:
        return democ_shared_timestamp_from_json(jr, pos, &value->u.shared_timestamp);
    case DEMOC_FIELD_NONE:
    case DEMOC_FIELD_COUNT:
    default:
        (void)pos;
        return democ_jr_fail(jr, "no such field layout");
    }
}
