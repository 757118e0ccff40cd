/* A C program that uses the mipcodec package as its documentation says (docs/packaging.md), built
 * by tests/consumer/test_consumers.py in each documented way: prints the ping command's bytes,
 * then the canonical JSON line of every packet and skip run of FILE. */
#include <stdio.h>
#include <string.h>

#include "mipcodec/mipcodec.h"

static uint8_t input[1 << 16];

static void on_event(void *ctx, const mipc_event_t *event) {
    char line[8192];
    (void)ctx;
    if (event->kind == MIPC_EVENT_PACKET) {
        mipc_json_packet_line(event->packet, (size_t)event->length, event->offset, MIPC_DEVICE_ANY, line,
                              sizeof line);
    } else {
        mipc_json_skip_line(event->offset, input + event->offset, (size_t)event->length, line, sizeof line);
    }
    printf("%s\n", line);
}

int main(int argc, char **argv) {
    uint8_t packet[MIPC_MAX_PACKET];
    uint8_t data[MIPC_MAX_FIELD_DATA];
    size_t data_len = 0;
    size_t packet_len = 0;
    size_t i;
    size_t n;
    mipc_base_ping_t ping;
    mipc_packet_builder_t builder;
    mipc_parser_t parser;
    FILE *file;
    if (argc != 2 || (file = fopen(argv[1], "rb")) == NULL) {
        fprintf(stderr, "usage: consumer FILE\n");
        return 2;
    }
    n = fread(input, 1, sizeof input, file);
    fclose(file);
    memset(&ping, 0, sizeof ping);
    mipc_packet_begin(&builder, packet, sizeof packet, MIPC_BASE_SET);
    if (mipc_base_ping_encode(&ping, data, sizeof data, &data_len) != MIPC_OK ||
        mipc_packet_add_field(&builder, MIPC_BASE_PING_DESCRIPTOR, data, data_len) != MIPC_OK ||
        mipc_packet_finish(&builder, &packet_len) != MIPC_OK) {
        return 1;
    }
    printf("command ");
    for (i = 0; i < packet_len; i++) {
        printf("%02x", packet[i]);
    }
    printf("\n");
    mipc_parser_init(&parser);
    mipc_parser_feed(&parser, input, n, on_event, NULL);
    mipc_parser_flush(&parser, on_event, NULL);
    return 0;
}
