/* Stand-in for a generated session_facts.c (templates/c/session_facts.c.j2) in the runtime's own
 * tests: ping (0x01) is a command of both devices; rate (0x02) one layout per device, the beta
 * layout expecting a reply field 0x82 and suppressing its ack when the rate is 0. The ack field
 * (0xF1) is <echo u8> <code u8>. */
#include "codec/session.h"

#include <string.h>

const char *codec_function_name(int value) {
    return value == 1 ? "write" : NULL;
}

bool codec_command_facts(const codec_field_value_t *command, codec_command_facts_t *out) {
    memset(out, 0, sizeof *out);
    out->id = command->id;
    out->set = 0x01;
    out->function = -1;
    out->function_listed = true;
    out->function_devices = 0x6u;
    out->field_devices = 0x6u;
    out->layout_device = CODEC_DEVICE_ANY;
    switch (command->id) {
    case CODEC_FIELD_PING:
        out->descriptor = 0x01;
        return true;
    case CODEC_FIELD_RATE_ALPHA:
        out->descriptor = 0x02;
        out->layout_device = CODEC_DEVICE_ALPHA;
        out->allowance_ms = command->u.rate_alpha_hz;
        return true;
    case CODEC_FIELD_RATE_BETA:
        out->descriptor = 0x02;
        out->layout_device = CODEC_DEVICE_BETA;
        out->suppressed = command->u.rate_beta_hz == 0;
        out->expect[out->expect_count++] = 0x82;
        return true;
    default:
        return false;
    }
}

int codec_session_ack_decode(uint8_t set, const uint8_t *data, size_t len, codec_device_t device,
                             uint8_t *echo, uint32_t *code) {
    (void)set;
    (void)device;
    if (len != 2) {
        return 0;
    }
    *echo = data[0];
    *code = data[1];
    return 1;
}
