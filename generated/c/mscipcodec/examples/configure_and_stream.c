/* configure_and_stream ADDRESS [N]: connects to a Memsense MS-CIP device (ADDRESS tcp:HOST:PORT or a
 * serial port path, opened at 115200 baud), pings it, reads its device information, writes one
 * setting and reads it back, starts the data stream and prints the first N data packets (default
 * 5). The documentation quotes the parts between the [...] and [end] comments.
 * Generated: do not edit. */
#include <stdio.h>
#include <stdlib.h>

#include "mscipcodec/mscipcodec.h"
#include "mscipcodec/posix_transport.h"

/* Stops the program with the result of a command that did not succeed. */
static int failed(const char *what, mscipc_link_t *link) {
    fprintf(stderr, "%s: %s%s%s\n", what, mscipc_result_kind_name(link->result.kind),
            link->result.error[0] ? ": " : "", link->result.error);
    return 1;
}

// [stream]
/* Called for every packet that is not a reply to a command: prints the data packets. */
typedef struct {
    unsigned seen;
} stream_t;

static void on_packet(void *ctx, const mscipc_event_t *packet) {
    stream_t *stream = (stream_t *)ctx;
    mscipc_field_iter_t fields;
    mscipc_field_entry_t entry;
    uint8_t set = mscipc_packet_set(packet->packet);
    unsigned count = 0;
    if (mscipc_set_kind(set) != MSCIPC_SET_KIND_DATA) {
        return;
    }
    mscipc_field_iter_init(&fields, set, mscipc_packet_payload(packet->packet),
                           mscipc_packet_payload_length(packet->packet));
    while (mscipc_field_iter_next(&fields, &entry)) {
        count++;
    }
    stream->seen++;
    printf("data packet %u: set 0x%02X, %u fields\n", stream->seen, set, count);
}
// [end]

int main(int argc, char **argv) {
    static mscipc_link_t link;
    mscipc_posix_t port;
    mscipc_transport_t transport;
    mscipc_session_config_t config;
    mscipc_base_device_model_t info;
    mscipc_imu_config_sample_rate_response_t setting;
    stream_t stream = {0};
    unsigned wanted = argc > 2 ? (unsigned)strtoul(argv[2], NULL, 10) : 5u;
    if (argc < 2) {
        fprintf(stderr, "usage: %s ADDRESS [N]\n", argv[0]);
        return 2;
    }
    // [connect]
    if (mscipc_posix_open(&port, argv[1], 115200) != MSCIPC_OK) {
        fprintf(stderr, "%s\n", port.error);
        return 2;
    }
    mscipc_posix_transport(&port, &transport);
    mscipc_session_config_init(&config);
    config.device = MSCIPC_DEVICE_ANY; /* commands this model does not support are refused, not sent */
    if (mscipc_link_init(&link, &transport, &config) != MSCIPC_OK) {
        return 2;
    }
    mscipc_session_on_packet(&link.session, on_packet, &stream);
    if (mscipc_base_ping(&link) != MSCIPC_RESULT_ACK) {
        return failed("ping", &link);
    }
    printf("ping: ack\n");
    // [end]

    // [configure]
    if (mscipc_base_get_device_model(&link, &info) != MSCIPC_RESULT_ACK) {
        return failed("device information", &link);
    }
    printf("model: %.*s\n", (int)sizeof info.model, info.model);
    if (mscipc_imu_config_sample_rate_write(&link, 4) != MSCIPC_RESULT_ACK) {
        return failed("write", &link);
    }
    if (mscipc_imu_config_sample_rate_read(&link, &setting) != MSCIPC_RESULT_ACK) {
        return failed("read", &link);
    }
    printf("sample rate decimation: %u\n", (unsigned)setting.decimation);
    // [end]

    // [stream]
    if (mscipc_imu_config_data_on_off_write(&link, MSCIPC_ON_OFF_ON) != MSCIPC_RESULT_ACK) {
        return failed("start the data stream", &link);
    }
    while (stream.seen < wanted) {
        if (mscipc_link_pump(&link, 1000) < 0) {
            fprintf(stderr, "%s\n", port.error);
            break;
        }
    }
    // [end]
    mscipc_link_close(&link);
    mscipc_posix_close(&port);
    return stream.seen >= wanted ? 0 : 1;
}
