/* getting_started FILE: builds a ping command with mipcodec, then decodes
 * the packets in FILE (read in blocks, as from a serial port) and prints the name of every field.
 * The documentation quotes the parts between the [...] and [end] comments. Generated: do not edit. */
#include <errno.h>
#include <stdio.h>
#include <string.h>

#include "mipcodec/mipcodec.h"

// [parse-stream]
/* Called by the parser for every packet and every run of skipped bytes. */
static void on_event(void *ctx, const mipc_event_t *event) {
    mipc_field_iter_t fields;
    mipc_field_entry_t entry;
    const char *separator = "";
    uint8_t set;
    (void)ctx;
    if (event->kind == MIPC_EVENT_SKIP) {
        printf("skipped %llu\n", (unsigned long long)event->length);
        return;
    }
    set = mipc_packet_set(event->packet);
    printf("packet set=0x%02x fields=", set);
    mipc_field_iter_init(&fields, set, mipc_packet_payload(event->packet),
                         mipc_packet_payload_length(event->packet));
    while (mipc_field_iter_next(&fields, &entry)) {
        mipc_field_value_t value;
        const char *name = "?"; /* trailing bytes, or a field that does not decode */
        if (entry.kind == MIPC_ENTRY_FIELD &&
            mipc_decode_field(set, entry.descriptor, entry.data, entry.length, MIPC_DEVICE_ANY, &value,
                              NULL) == MIPC_OK) {
            name = mipc_layout_info(value.id)->name;
        }
        printf("%s%s", separator, name);
        separator = ",";
    }
    printf("\n");
}
// [end]

// [build-command]
/* Builds the command with its typed value and prints the packet bytes. */
static int print_command(void) {
    mipc_base_ping_t command;
    uint8_t data[MIPC_MAX_FIELD_DATA];
    uint8_t packet[MIPC_MAX_PACKET];
    size_t data_len = 0;
    size_t packet_len = 0;
    size_t i;
    mipc_packet_builder_t builder;
    memset(&command, 0, sizeof command);
    mipc_packet_begin(&builder, packet, sizeof packet, MIPC_BASE_SET);
    if (mipc_base_ping_encode(&command, data, sizeof data, &data_len) != MIPC_OK ||
        mipc_packet_add_field(&builder, MIPC_BASE_PING_DESCRIPTOR, data, data_len) != MIPC_OK ||
        mipc_packet_finish(&builder, &packet_len) != MIPC_OK) {
        fprintf(stderr, "getting_started: cannot build the command\n");
        return 1;
    }
    printf("command ");
    for (i = 0; i < packet_len; i++) {
        printf("%02x", packet[i]);
    }
    printf("\n");
    return 0;
}
// [end]

// [read-file]
/* Feeds the file to the parser block by block, then flushes it at the end of the input. */
static int decode_file(const char *path) {
    mipc_parser_t parser;
    uint8_t block[4096];
    size_t n;
    FILE *file = fopen(path, "rb");
    if (!file) {
        fprintf(stderr, "getting_started: cannot open %s: %s\n", path, strerror(errno));
        return 1;
    }
    mipc_parser_init(&parser);
    while ((n = fread(block, 1, sizeof block, file)) > 0) {
        mipc_parser_feed(&parser, block, n, on_event, NULL);
    }
    if (ferror(file)) {
        fprintf(stderr, "getting_started: cannot read %s\n", path);
        fclose(file);
        return 1;
    }
    fclose(file);
    mipc_parser_flush(&parser, on_event, NULL);
    return 0;
}
// [end]

int main(int argc, char **argv) {
    if (argc != 2) {
        fprintf(stderr, "usage: getting_started FILE\n");
        return 2;
    }
    if (print_command() != 0) {
        return 1;
    }
    return decode_file(argv[1]);
}
