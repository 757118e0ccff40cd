/* The typed command API of Demo protocol with every spec feature (democodec/commands.h). Generated: do not
 * edit. */
#include "democodec/commands.h"

#include <string.h>

democ_result_kind_t democ_commands_ping(democ_link_t *link) {
    democ_field_value_t cmd_;
    democ_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = DEMOC_FIELD_COMMANDS_PING;
    }
    kind_ = democ_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

democ_result_kind_t democ_commands_configure_write(democ_link_t *link, uint8_t instance, democ_mode_t mode,
                                                   const democ_trigger_params_t *params, bool suppress_ack) {
    democ_field_value_t cmd_;
    democ_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = DEMOC_FIELD_COMMANDS_CONFIGURE;
        cmd_.u.commands_configure.function = DEMOC_FUNCTION_WRITE;
        cmd_.u.commands_configure.instance = instance;
        cmd_.u.commands_configure.has_mode = true;
        cmd_.u.commands_configure.mode = mode;
        cmd_.u.commands_configure.has_params = true;
        cmd_.u.commands_configure.params = *params;
        cmd_.u.commands_configure.has_suppress_ack = true;
        cmd_.u.commands_configure.suppress_ack = suppress_ack;
    }
    kind_ = democ_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

democ_result_kind_t democ_commands_configure_read(democ_link_t *link, uint8_t instance,
                                                  democ_commands_configuration_t *reply) {
    democ_field_value_t cmd_;
    democ_result_kind_t kind_;
    democ_result_t result_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = DEMOC_FIELD_COMMANDS_CONFIGURE;
        cmd_.u.commands_configure.function = DEMOC_FUNCTION_READ;
        cmd_.u.commands_configure.instance = instance;
    }
    kind_ = democ_link_run(link, &cmd_, NULL, &result_);
    if (kind_ == DEMOC_RESULT_ACK && reply != NULL) {
        democ_field_entry_t entry_;
        if (!democ_result_reply_entry(&result_, &entry_) || entry_.descriptor != 0x82 ||
            democ_commands_configuration_decode(entry_.data, entry_.length, reply, NULL) != DEMOC_OK) {
            return democ_link_fail(link, DEMOC_RESULT_INVALID, "missing reply field 0x82");
        }
    }
    return kind_;
}

democ_result_kind_t democ_commands_configure_save(democ_link_t *link, uint8_t instance) {
    democ_field_value_t cmd_;
    democ_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = DEMOC_FIELD_COMMANDS_CONFIGURE;
        cmd_.u.commands_configure.function = DEMOC_FUNCTION_SAVE;
        cmd_.u.commands_configure.instance = instance;
    }
    kind_ = democ_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

democ_result_kind_t democ_commands_per_device_dev_a(democ_link_t *link, uint32_t a) {
    democ_field_value_t cmd_;
    democ_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = DEMOC_FIELD_COMMANDS_PER_DEVICE_DEV_A;
        cmd_.u.commands_per_device_dev_a.a = a;
    }
    kind_ = democ_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}

democ_result_kind_t democ_commands_per_device_dev_b(democ_link_t *link, uint64_t b, uint8_t extra) {
    democ_field_value_t cmd_;
    democ_result_kind_t kind_;
    memset(&cmd_, 0, sizeof cmd_);
    {
        cmd_.id = DEMOC_FIELD_COMMANDS_PER_DEVICE_DEV_B;
        cmd_.u.commands_per_device_dev_b.b = b;
        cmd_.u.commands_per_device_dev_b.has_extra = true;
        cmd_.u.commands_per_device_dev_b.extra = extra;
    }
    kind_ = democ_link_run(link, &cmd_, NULL, NULL);
    return kind_;
}
