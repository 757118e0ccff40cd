/* Framing: checksum, packet header accessors and the packet builder; the framing constants are
 * in protocol.h. */
/*
 * Pointer arguments (every function of this header): a pointer must be valid for what the function
 * reads or writes, and not NULL, unless its documentation says "may be NULL". A buffer pointer
 * paired with a size (bytes/len, buf/cap, out/cap) may be NULL when that size is 0. Debug builds
 * (without NDEBUG) check these preconditions with assert(); docs/conformance.md section 7.
 */
#ifndef CODEC_FRAMING_H
#define CODEC_FRAMING_H

#include "codec/protocol.h"
#include "codec/status.h"

#ifdef __cplusplus
extern "C" {
#endif

/** The sync sequence as bytes. */
extern const uint8_t codec_sync[CODEC_SYNC_SIZE];

/**
 * Fletcher-16 over bytes: sum1 = sum1 + b, sum2 = sum2 + sum1 (mod 256).
 * out[0..1] receive the checksum in wire order (see CODEC_CHECKSUM_SUM1_FIRST).
 */
void codec_checksum(const uint8_t *bytes, size_t len, uint8_t out[CODEC_CHECKSUM_SIZE]);
/** The same checksum as one number: the first byte in wire order in the high 8 bits. */
uint16_t codec_checksum_word(const uint8_t *bytes, size_t len);
/** The checksum's implementations: the portable one, and the vector ones of x86-64 (SSE2 in
 * every x86-64 build, AVX2 where the compiler can target it, used when the CPU has it).
 * codec_checksum_word() picks the fastest available; all give the same checksum. */
typedef enum {
    CODEC_CHECKSUM_IMPL_SCALAR = 0,
    CODEC_CHECKSUM_IMPL_SSE2 = 1,
    CODEC_CHECKSUM_IMPL_AVX2 = 2,
    CODEC_CHECKSUM_IMPL_COUNT = 3
} codec_checksum_impl_t;
/** codec_checksum_word() with one implementation (for tests and benchmarks): false when this
 * build or this CPU does not have it (*word unchanged). */
bool codec_checksum_word_impl(codec_checksum_impl_t impl, const uint8_t *bytes, size_t len, uint16_t *word);
/** True when the CODEC_CHECKSUM_SIZE bytes at bytes + len are the checksum of bytes[0..len). */
bool codec_checksum_matches(const uint8_t *bytes, size_t len);

/** True when a complete packet (header, payload, checksum) has a valid checksum and length. */
bool codec_packet_valid(const uint8_t *packet, size_t len);
/* The header accessors are inline: a decode loop calls them for every packet. */
/** Descriptor set of a packet (at least CODEC_HEADER_SIZE bytes: check the length first). */
static inline uint8_t codec_packet_set(const uint8_t *packet) {
    return packet[CODEC_SET_OFFSET];
}
/** Payload length byte of a packet (at least CODEC_HEADER_SIZE bytes). */
static inline uint8_t codec_packet_payload_length(const uint8_t *packet) {
    return packet[CODEC_LENGTH_OFFSET];
}
/** Start of the payload of a packet. */
static inline const uint8_t *codec_packet_payload(const uint8_t *packet) {
    return packet + CODEC_HEADER_SIZE;
}

/**
 * Builds one packet into a caller buffer: begin, add fields (or raw payload bytes), finish.
 * Errors are sticky: once an add fails, finish returns the first error.
 */
typedef struct {
    uint8_t *buf;
    size_t cap;
    size_t len;
    codec_status_t status;
    uint8_t set;
} codec_packet_builder_t;

/** Starts a packet of descriptor set `set` in buf (writes sync and header placeholders). */
void codec_packet_begin(codec_packet_builder_t *b, uint8_t *buf, size_t cap, uint8_t set);
/** Appends a field: header (descriptor, length) and data_len bytes of data. */
codec_status_t codec_packet_add_field(codec_packet_builder_t *b, uint8_t descriptor, const uint8_t *data,
                                      size_t data_len);
/** Appends bytes to the payload verbatim (used to rebuild trailing bytes). */
codec_status_t codec_packet_add_raw(codec_packet_builder_t *b, const uint8_t *bytes, size_t len);
/** Writes the payload length and checksum; *len_out (len_out may be NULL) receives the packet size. */
codec_status_t codec_packet_finish(codec_packet_builder_t *b, size_t *len_out);

#ifdef __cplusplus
}
#endif

#endif
