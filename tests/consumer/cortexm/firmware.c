/* A minimal Cortex-M4 firmware image on the mipcodec C core: at reset it sends a ping command on
 * a UART, then feeds every received byte to the stream parser and decodes the scaled accelerometer
 * field of each sensor data packet. No stdio, no heap, no C start-up files: what the code size of
 * the core costs in a real image (tests/consumer/test_consumers.py prints it). The UART is a
 * made-up memory-mapped register pair; the image is measured, not run. */
#include <stddef.h>
#include <stdint.h>

#include "mipcodec/mipcodec.h"

#define UART_DATA (*(volatile uint32_t *)0x40011004u)
#define UART_STATUS (*(volatile uint32_t *)0x40011000u)
#define UART_RX_READY 0x20u
#define UART_TX_READY 0x80u

static mipc_parser_t parser;
volatile float accel[3];
volatile uint32_t accel_samples;
volatile uint32_t skipped_bytes;

static void uart_write(const uint8_t *data, size_t len) {
    size_t i;
    for (i = 0; i < len; i++) {
        while ((UART_STATUS & UART_TX_READY) == 0) {
        }
        UART_DATA = data[i];
    }
}

static void on_event(void *ctx, const mipc_event_t *event) {
    mipc_field_iter_t fields;
    mipc_field_entry_t entry;
    uint8_t set;
    (void)ctx;
    if (event->kind != MIPC_EVENT_PACKET) {
        skipped_bytes += (uint32_t)event->length;
        return;
    }
    set = mipc_packet_set(event->packet);
    if (set != MIPC_SENSOR_SET) {
        return;
    }
    mipc_field_iter_init(&fields, set, mipc_packet_payload(event->packet), mipc_packet_payload_length(event->packet));
    while (mipc_field_iter_next(&fields, &entry)) {
        mipc_sensor_scaled_accel_t value;
        if (entry.kind == MIPC_ENTRY_FIELD && entry.descriptor == MIPC_SENSOR_SCALED_ACCEL_DESCRIPTOR &&
            mipc_sensor_scaled_accel_decode(entry.data, entry.length, &value, NULL) == MIPC_OK) {
            accel[0] = value.scaled_accel[0];
            accel[1] = value.scaled_accel[1];
            accel[2] = value.scaled_accel[2];
            accel_samples++;
        }
    }
}

int main(void) {
    uint8_t packet[MIPC_MAX_PACKET];
    uint8_t data[MIPC_MAX_FIELD_DATA];
    size_t data_len = 0;
    size_t packet_len = 0;
    mipc_base_ping_t ping = {0};
    mipc_packet_builder_t builder;
    mipc_packet_begin(&builder, packet, sizeof packet, MIPC_BASE_SET);
    if (mipc_base_ping_encode(&ping, data, sizeof data, &data_len) == MIPC_OK &&
        mipc_packet_add_field(&builder, MIPC_BASE_PING_DESCRIPTOR, data, data_len) == MIPC_OK &&
        mipc_packet_finish(&builder, &packet_len) == MIPC_OK) {
        uart_write(packet, packet_len);
    }
    mipc_parser_init(&parser);
    for (;;) {
        if (UART_STATUS & UART_RX_READY) {
            uint8_t byte = (uint8_t)UART_DATA;
            mipc_parser_feed(&parser, &byte, 1, on_event, NULL);
        }
    }
}

/* Reset: zero .bss is skipped (the image is measured, not run); call main. */
void reset_handler(void);
void reset_handler(void) {
    (void)main();
    for (;;) {
    }
}

/* The vector table: initial stack pointer (top of a 64 KiB SRAM) and the reset handler. */
extern const uintptr_t vectors[2];
__attribute__((section(".isr_vector"))) const uintptr_t vectors[2] = {0x20010000u, (uintptr_t)&reset_handler};
