/* Constants of the Demo protocol with every spec feature protocol, rendered from protocols[] of the IR: the
 * only protocol input of the runtime (the files copied from generator/targets/c/runtime/). Generated: do not
 * edit. */
#ifndef DEMOC_PROTOCOL_H
#define DEMOC_PROTOCOL_H

#include <stdint.h>

/* The protocol's name in the IR (protocols[].name), as the tools name it in messages. */
#define DEMOC_PROTOCOL_NAME "demo"

/* Byte order of multi-byte values in field data (byte_order: big). */
#define DEMOC_LITTLE_ENDIAN 0

/* Sync sequence that starts every packet. */
#define DEMOC_SYNC_SIZE 2
#define DEMOC_SYNC_0 0xA5
#define DEMOC_SYNC_1 0xA5
#define DEMOC_SYNC_BYTES {0xA5, 0xA5}
/* Packet header: sync bytes, then set, payload_length. */
#define DEMOC_HEADER_SIZE 4
#define DEMOC_SET_OFFSET 2
#define DEMOC_LENGTH_OFFSET 3
#define DEMOC_MAX_PAYLOAD 255
#define DEMOC_CHECKSUM_SIZE 2
/* Checksum bytes in wire order: sum1, sum2. */
#define DEMOC_CHECKSUM_SUM1_FIRST 1
/* Largest packet: header, maximum payload and checksum. */
#define DEMOC_MAX_PACKET 261
/* Foreign frames the parser reports between packets (docs/conformance.md section 1): NMEA-0183
 * sentences (DEMOC_NMEA_MAX bytes at most, '$' to LF) and RTCM3 frames; 0 where the protocol has none. */
#define DEMOC_FOREIGN_NMEA 0
#define DEMOC_FOREIGN_RTCM3 0
#define DEMOC_NMEA_MAX 0
/* The parser's buffer: the longest candidate it may wait for (a packet or a foreign frame). */
#define DEMOC_PARSER_CAPACITY 261
/* Field header: descriptor, length. */
#define DEMOC_FIELD_HEADER_SIZE 2
#define DEMOC_FIELD_LENGTH_OFFSET 1
#define DEMOC_FIELD_DESCRIPTOR_OFFSET 0
/* The field length byte counts only the data:
 * data length = length byte - DEMOC_FIELD_LENGTH_ADJUST. */
#define DEMOC_FIELD_LENGTH_ADJUST 0
/*
 * Length byte - data length of field (set, descriptor): DEMOC_FIELD_LENGTH_ADJUST, except for the
 * fields the spec marks with length_byte_adjust (0 in this protocol).
 */
static inline int democ_field_length_adjust(uint8_t set, uint8_t descriptor) {
    (void)set;
    (void)descriptor;
    return DEMOC_FIELD_LENGTH_ADJUST;
}
/* Largest data a single field can carry. */
#define DEMOC_MAX_FIELD_DATA 253

/* Samples (docs/conformance.md section 6). Data sets that group continuation packets (one
 * tracker slot each; DEMOC_SAMPLE_DATA_SET_COUNT of them, the array never empty). */
#define DEMOC_SAMPLE_DATA_SET_COUNT 3
#define DEMOC_SAMPLE_SETS 3
#define DEMOC_SAMPLE_DATA_SETS {0x90, 0x91, 0x92}
/* Shared descriptors: from DEMOC_SAMPLE_FIRST_SHARED up (256: none). */
#define DEMOC_SAMPLE_FIRST_SHARED 0xD0
/* Shared timestamp fields (descriptor, data size) that make up the sample key. */
#define DEMOC_SAMPLE_TIMESTAMPS 0
#define DEMOC_SAMPLE_STAMP_DESCRIPTORS {0x00}
#define DEMOC_SAMPLE_STAMP_SIZES {0}
/* Largest sample key: field header + data of every shared timestamp field. */
#define DEMOC_SAMPLE_KEY_MAX 1

/* Command sessions (docs/conformance.md section 8): the ack field's descriptor and the code of
 * success; the most reply descriptors one command expects. */
#define DEMOC_SESSION_ACK_DESCRIPTOR 0x80
#define DEMOC_SESSION_ACK_OK 0u
#define DEMOC_SESSION_MAX_EXPECT 1

/* The host clock model's parameters (the spec's time.clock_model, the project's own; codec/clock.h,
 * docs/time.md): device time per bucket (ns), closed buckets kept, closed buckets before there is
 * an estimate, and the step disagreement (ns) above which consecutive packets restart the model. */
#define DEMOC_CLOCK_BUCKET_NS 1000000000LL
#define DEMOC_CLOCK_BUCKETS 2
#define DEMOC_CLOCK_MIN_BUCKETS 3
#define DEMOC_CLOCK_RESTART_NS 1000000000LL

/* Getting through to a device (the IR's `link`, docs/conformance.md section 8 "Getting through"):
 * the idle, ping and resume commands (HAS 0: the manual names none), how many times the idle
 * command is sent before giving up, the milliseconds after a baud-rate change before the device
 * answers at the new rate (-1: the manual states none) and the manuals' UART bandwidth calculation
 * (HAS 0: none): bits/s = UART_WORD_BITS * (PACKET_OVERHEAD * packets/s + sum of
 * (field data size + FIELD_OVERHEAD) * field rate). Per device: democ_device_baud_rates(). */
#define DEMOC_LINK_HAS_IDLE 0
#define DEMOC_LINK_IDLE_SET 0x00
#define DEMOC_LINK_IDLE_DESCRIPTOR 0x00
#define DEMOC_LINK_HAS_PING 0
#define DEMOC_LINK_PING_SET 0x00
#define DEMOC_LINK_PING_DESCRIPTOR 0x00
#define DEMOC_LINK_HAS_RESUME 0
#define DEMOC_LINK_RESUME_SET 0x00
#define DEMOC_LINK_RESUME_DESCRIPTOR 0x00
#define DEMOC_LINK_IDLE_ATTEMPTS 3
#define DEMOC_LINK_BAUD_SETTLE_MS -1
#define DEMOC_LINK_HAS_BANDWIDTH 0
#define DEMOC_LINK_UART_WORD_BITS 0
#define DEMOC_LINK_PACKET_OVERHEAD 0
#define DEMOC_LINK_FIELD_OVERHEAD 0

/* The wrong-model check (issue 39, docs/conformance.md section 8): after the first NACK whose code
 * is an unknown-command code (the spec's simulation.nack unknown_descriptor and unknown_set), a link
 * told a device sends the identity command once and compares the model name it reports (the
 * MODEL_LENGTH bytes at MODEL_OFFSET of the reply field's data) with that device's names
 * (democ_device_model_names); HAS 0: the spec names no identity. */
#define DEMOC_IDENTITY_HAS 0
#define DEMOC_IDENTITY_SET 0x00
#define DEMOC_IDENTITY_COMMAND 0x00
#define DEMOC_IDENTITY_REPLY 0x00
#define DEMOC_IDENTITY_MODEL_OFFSET 0u
#define DEMOC_IDENTITY_MODEL_LENGTH 0u
#define DEMOC_IDENTITY_UNKNOWN_CODES {0u}
#define DEMOC_IDENTITY_UNKNOWN_COUNT 0u

/** Deepest parameter path a layout of this protocol can have (members of nested structs). */
#define DEMOC_PATH_MAX_DEPTH 2
/** Enough room for any message democ_decode_error_format() can produce. */
#define DEMOC_ERROR_MESSAGE_MAX 232
/* Longest field name or device id, and a NUL. */
#define DEMOC_NAME_MAX 14

#endif
