/* Framing of the Demo protocol with every spec feature protocol, rendered from protocols[].framing of the IR.
 * Generated: do not edit. */
#ifndef DEMO_FRAMING_H
#define DEMO_FRAMING_H

#include "democodec/status.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Sync sequence that starts every packet. */
#define DEMO_SYNC_SIZE 2
#define DEMO_SYNC_0 0xA5
#define DEMO_SYNC_1 0xA5
/* Packet header: sync bytes, then set, payload_length. */
#define DEMO_HEADER_SIZE 4
#define DEMO_SET_OFFSET 2
#define DEMO_LENGTH_OFFSET 3
#define DEMO_MAX_PAYLOAD 255
#define DEMO_CHECKSUM_SIZE 2
/* Largest packet: header, maximum payload and checksum. */
#define DEMO_MAX_PACKET 261
/* Field header: descriptor, length. */
#define DEMO_FIELD_HEADER_SIZE 2
#define DEMO_FIELD_LENGTH_OFFSET 1
#define DEMO_FIELD_DESCRIPTOR_OFFSET 0
/* The field length byte counts only the data:
 * data length = length byte - DEMO_FIELD_LENGTH_ADJUST. */
#define DEMO_FIELD_LENGTH_ADJUST 0
/*
 * Length byte - data length of field (set, descriptor): DEMO_FIELD_LENGTH_ADJUST, except for the
 * fields the spec marks with length_byte_adjust (0 in this protocol).
 */
static inline int demo_field_length_adjust(uint8_t set, uint8_t descriptor) {
    (void)set;
    (void)descriptor;
    return DEMO_FIELD_LENGTH_ADJUST;
}
/* Largest data a single field can carry. */
#define DEMO_MAX_FIELD_DATA 253

/** The sync sequence as bytes. */
extern const uint8_t demo_sync[DEMO_SYNC_SIZE];

/**
 * Fletcher-16 over bytes: sum1 = sum1 + b, sum2 = sum2 + sum1 (mod 256).
 * out[0..1] receive the checksum in wire order (sum1, sum2).
 */
void demo_checksum(const uint8_t *bytes, size_t len, uint8_t out[DEMO_CHECKSUM_SIZE]);
/** The same checksum as one number: the first byte in wire order in the high 8 bits. */
uint16_t demo_checksum_word(const uint8_t *bytes, size_t len);
/** True when the DEMO_CHECKSUM_SIZE bytes at bytes + len are the checksum of bytes[0..len). */
bool demo_checksum_matches(const uint8_t *bytes, size_t len);

/** True when a complete packet (header, payload, checksum) has a valid checksum and length. */
bool demo_packet_valid(const uint8_t *packet, size_t len);
/* The header accessors are inline: a decode loop calls them for every packet. */
/** Descriptor set of a packet (at least DEMO_HEADER_SIZE bytes). */
static inline uint8_t demo_packet_set(const uint8_t *packet) {
    return packet[DEMO_SET_OFFSET];
}
/** Payload length byte of a packet (at least DEMO_HEADER_SIZE bytes). */
static inline uint8_t demo_packet_payload_length(const uint8_t *packet) {
    return packet[DEMO_LENGTH_OFFSET];
}
/** Start of the payload of a packet. */
static inline const uint8_t *demo_packet_payload(const uint8_t *packet) {
    return packet + DEMO_HEADER_SIZE;
}

/**
 * Builds one packet into a caller buffer: begin, add fields (or raw payload bytes), finish.
 * Errors are sticky: once an add fails, finish returns the first error.
 */
typedef struct {
    uint8_t *buf;
    size_t cap;
    size_t len;
    demo_status_t status;
    uint8_t set;
} demo_packet_builder_t;

/** Starts a packet of descriptor set `set` in buf (writes sync and header placeholders). */
void demo_packet_begin(demo_packet_builder_t *b, uint8_t *buf, size_t cap, uint8_t set);
/** Appends a field: header (descriptor, length) and data_len bytes of data. */
demo_status_t demo_packet_add_field(demo_packet_builder_t *b, uint8_t descriptor, const uint8_t *data,
                                    size_t data_len);
/** Appends bytes to the payload verbatim (used to rebuild trailing bytes). */
demo_status_t demo_packet_add_raw(demo_packet_builder_t *b, const uint8_t *bytes, size_t len);
/** Writes the payload length and checksum; *len_out receives the packet size. */
demo_status_t demo_packet_finish(demo_packet_builder_t *b, size_t *len_out);

#ifdef __cplusplus
}
#endif

#endif
