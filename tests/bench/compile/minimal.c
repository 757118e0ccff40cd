/* The minimal translation unit of the compile-cost benchmark (tests/bench/run.py --compile), C
 * side: includes the umbrella header, builds one command (ping) and feeds bytes to the stream
 * parser; minimal.cpp is the same program with the C++ package. */
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include "mipcodec/mipcodec.h"

static size_t packets = 0;

static void on_event(void *ctx, const mipc_event_t *event) {
    (void)ctx;
    if (event->kind == MIPC_EVENT_PACKET) {
        ++packets;
    }
}

int main(void) {
    mipc_base_ping_t command;
    uint8_t data[MIPC_MAX_FIELD_DATA];
    uint8_t packet[MIPC_MAX_PACKET];
    size_t data_len = 0;
    size_t packet_len = 0;
    mipc_packet_builder_t builder;
    mipc_parser_t parser;
    memset(&command, 0, sizeof command);
    mipc_packet_begin(&builder, packet, sizeof packet, MIPC_BASE_SET);
    if (mipc_base_ping_encode(&command, data, sizeof data, &data_len) != MIPC_OK ||
        mipc_packet_add_field(&builder, MIPC_BASE_PING_DESCRIPTOR, data, data_len) != MIPC_OK ||
        mipc_packet_finish(&builder, &packet_len) != MIPC_OK) {
        return 1;
    }
    mipc_parser_init(&parser);
    mipc_parser_feed(&parser, packet, packet_len, on_event, NULL);
    mipc_parser_flush(&parser, on_event, NULL);
    printf("%zu\n", packets);
    return packets == 1 ? 0 : 1;
}
