/* configure_and_stream ADDRESS [N]: connects to a MicroStrain MIP device (ADDRESS tcp:HOST:PORT or a
 * serial port path, opened at 115200 baud), pings it, reads its device information, writes one
 * setting and reads it back, starts the data stream and prints the first N data packets (default
 * 5). The documentation quotes the parts between the [...] and [end] comments.
 * Generated: do not edit. */
#include <stdio.h>
#include <stdlib.h>

#include "mipcodec/mipcodec.h"
#include "mipcodec/posix_transport.h"

/* Stops the program with the result of a command that did not succeed. */
static int failed(const char *what, mipc_link_t *link) {
    fprintf(stderr, "%s: %s%s%s\n", what, mipc_result_kind_name(link->result.kind),
            link->result.error[0] ? ": " : "", link->result.error);
    return 1;
}

// [stream]
/* Called for every packet that is not a reply to a command: prints the data packets. */
typedef struct {
    unsigned seen;
} stream_t;

static void on_packet(void *ctx, const mipc_event_t *packet) {
    stream_t *stream = (stream_t *)ctx;
    mipc_field_iter_t fields;
    mipc_field_entry_t entry;
    uint8_t set = mipc_packet_set(packet->packet);
    unsigned count = 0;
    if (mipc_set_kind(set) != MIPC_SET_KIND_DATA) {
        return;
    }
    mipc_field_iter_init(&fields, set, mipc_packet_payload(packet->packet),
                         mipc_packet_payload_length(packet->packet));
    while (mipc_field_iter_next(&fields, &entry)) {
        count++;
    }
    stream->seen++;
    printf("data packet %u: set 0x%02X, %u fields\n", stream->seen, set, count);
}
// [end]

int main(int argc, char **argv) {
    static mipc_link_t link;
    mipc_posix_t port;
    mipc_transport_t transport;
    mipc_session_config_t config;
    mipc_base_device_info_t info;
    mipc_threedm_sensor_to_vehicle_euler_response_t setting;
    stream_t stream = {0};
    unsigned wanted = argc > 2 ? (unsigned)strtoul(argv[2], NULL, 10) : 5u;
    if (argc < 2) {
        fprintf(stderr, "usage: %s ADDRESS [N]\n", argv[0]);
        return 2;
    }
    // [connect]
    if (mipc_posix_open(&port, argv[1], 115200) != MIPC_OK) {
        fprintf(stderr, "%s\n", port.error);
        return 2;
    }
    mipc_posix_transport(&port, &transport);
    mipc_session_config_init(&config);
    config.device = MIPC_DEVICE_CV7_INS; /* commands this model does not support are refused, not sent */
    if (mipc_link_init(&link, &transport, &config) != MIPC_OK) {
        return 2;
    }
    mipc_session_on_packet(&link.session, on_packet, &stream);
    if (mipc_base_ping(&link) != MIPC_RESULT_ACK) {
        return failed("ping", &link);
    }
    printf("ping: ack\n");
    // [end]

    // [configure]
    if (mipc_base_get_device_info(&link, &info) != MIPC_RESULT_ACK) {
        return failed("device information", &link);
    }
    printf("model: %.*s\n", (int)sizeof info.info.model_name, info.info.model_name);
    if (mipc_threedm_sensor_to_vehicle_euler_write(&link, 0.0f, 0.0f, 1.5708f) != MIPC_RESULT_ACK) {
        return failed("write", &link);
    }
    if (mipc_threedm_sensor_to_vehicle_euler_read(&link, &setting) != MIPC_RESULT_ACK) {
        return failed("read", &link);
    }
    printf("sensor to vehicle: roll %.4f pitch %.4f yaw %.4f\n", (double)setting.roll, (double)setting.pitch,
           (double)setting.yaw);
    // [end]

    // [stream]
    if (mipc_threedm_data_stream_control_write_cv7_ins(&link, 0x80, true) != MIPC_RESULT_ACK) {
        return failed("start the data stream", &link);
    }
    while (stream.seen < wanted) {
        if (mipc_link_pump(&link, 1000) < 0) {
            fprintf(stderr, "%s\n", port.error);
            break;
        }
    }
    // [end]
    mipc_link_close(&link);
    mipc_posix_close(&port);
    return stream.seen >= wanted ? 0 : 1;
}
