/* Constants of the MicroStrain MIP protocol, rendered from protocols[] of the IR: the only protocol
 * input of the runtime (the files copied from generator/targets/c/runtime/).
 * Generated: do not edit. */
#ifndef MIPC_PROTOCOL_H
#define MIPC_PROTOCOL_H

#include <stdint.h>

/* The protocol's name in the IR (protocols[].name), as the tools name it in messages. */
#define MIPC_PROTOCOL_NAME "mip"

/* Byte order of multi-byte values in field data (byte_order: big). */
#define MIPC_LITTLE_ENDIAN 0

/* Sync sequence that starts every packet. */
#define MIPC_SYNC_SIZE 2
#define MIPC_SYNC_0 0x75
#define MIPC_SYNC_1 0x65
#define MIPC_SYNC_BYTES {0x75, 0x65}
/* Packet header: sync bytes, then set, payload_length. */
#define MIPC_HEADER_SIZE 4
#define MIPC_SET_OFFSET 2
#define MIPC_LENGTH_OFFSET 3
#define MIPC_MAX_PAYLOAD 255
#define MIPC_CHECKSUM_SIZE 2
/* Checksum bytes in wire order: sum1, sum2. */
#define MIPC_CHECKSUM_SUM1_FIRST 1
/* Largest packet: header, maximum payload and checksum. */
#define MIPC_MAX_PACKET 261
/* Foreign frames the parser reports between packets (docs/conformance.md section 1): NMEA-0183
 * sentences (MIPC_NMEA_MAX bytes at most, '$' to LF) and RTCM3 frames; 0 where the protocol has none. */
#define MIPC_FOREIGN_NMEA 1
#define MIPC_FOREIGN_RTCM3 1
#define MIPC_NMEA_MAX 128
/* The parser's buffer: the longest candidate it may wait for (a packet or a foreign frame). */
#define MIPC_PARSER_CAPACITY 1029
/* Field header: length, descriptor. */
#define MIPC_FIELD_HEADER_SIZE 2
#define MIPC_FIELD_LENGTH_OFFSET 0
#define MIPC_FIELD_DESCRIPTOR_OFFSET 1
/* The field length byte counts the field header and the data:
 * data length = length byte - MIPC_FIELD_LENGTH_ADJUST. */
#define MIPC_FIELD_LENGTH_ADJUST 2
/*
 * Length byte - data length of field (set, descriptor): MIPC_FIELD_LENGTH_ADJUST, except for the
 * fields the spec marks with length_byte_adjust (0 in this protocol).
 */
static inline int mipc_field_length_adjust(uint8_t set, uint8_t descriptor) {
    (void)set;
    (void)descriptor;
    return MIPC_FIELD_LENGTH_ADJUST;
}
/* Largest data a single field can carry. */
#define MIPC_MAX_FIELD_DATA 253

/* Samples (docs/conformance.md section 6). Data sets that group continuation packets (one
 * tracker slot each; MIPC_SAMPLE_DATA_SET_COUNT of them, the array never empty). */
#define MIPC_SAMPLE_DATA_SET_COUNT 8
#define MIPC_SAMPLE_SETS 8
#define MIPC_SAMPLE_DATA_SETS {0x80, 0x81, 0x82, 0x91, 0x92, 0x93, 0x94, 0xA0}
/* Shared descriptors: from MIPC_SAMPLE_FIRST_SHARED up (256: none). */
#define MIPC_SAMPLE_FIRST_SHARED 0xD0
/* Shared timestamp fields (descriptor, data size) that make up the sample key. */
#define MIPC_SAMPLE_TIMESTAMPS 3
#define MIPC_SAMPLE_STAMP_DESCRIPTORS {0xD3, 0xD5, 0xD7}
#define MIPC_SAMPLE_STAMP_SIZES {12, 8, 10}
/* Largest sample key: field header + data of every shared timestamp field. */
#define MIPC_SAMPLE_KEY_MAX 36

/* Command sessions (docs/conformance.md section 8): the ack field's descriptor and the code of
 * success; the most reply descriptors one command expects. */
#define MIPC_SESSION_ACK_DESCRIPTOR 0xF1
#define MIPC_SESSION_ACK_OK 0u
#define MIPC_SESSION_MAX_EXPECT 2

/* The host clock model's parameters (the spec's time.clock_model, the project's own; codec/clock.h,
 * docs/time.md): device time per bucket (ns), closed buckets kept, closed buckets before there is
 * an estimate, and the step disagreement (ns) above which consecutive packets restart the model. */
#define MIPC_CLOCK_BUCKET_NS 1000000000LL
#define MIPC_CLOCK_BUCKETS 64
#define MIPC_CLOCK_MIN_BUCKETS 2
#define MIPC_CLOCK_RESTART_NS 1000000000LL

/* Getting through to a device (the IR's `link`, docs/conformance.md section 8 "Getting through"):
 * the idle, ping and resume commands (HAS 0: the manual names none), how many times the idle
 * command is sent before giving up, the milliseconds after a baud-rate change before the device
 * answers at the new rate (-1: the manual states none) and the manuals' UART bandwidth calculation
 * (HAS 0: none): bits/s = UART_WORD_BITS * (PACKET_OVERHEAD * packets/s + sum of
 * (field data size + FIELD_OVERHEAD) * field rate). Per device: mipc_device_baud_rates(). */
/* set_to_idle: 3dm-gx5-45-dcp.txt:363, 3dm-gx5-45-dcp.txt:759, 3dm-cv7-ins-docs.txt:8043 */
#define MIPC_LINK_HAS_IDLE 1
#define MIPC_LINK_IDLE_SET 0x01
#define MIPC_LINK_IDLE_DESCRIPTOR 0x02
/* ping: 3dm-gx5-45-dcp.txt:748, 3dm-cv7-ins-docs.txt:8032 */
#define MIPC_LINK_HAS_PING 1
#define MIPC_LINK_PING_SET 0x01
#define MIPC_LINK_PING_DESCRIPTOR 0x01
/* resume: 3dm-gx5-45-dcp.txt:832, 3dm-cv7-ins-docs.txt:8099 */
#define MIPC_LINK_HAS_RESUME 1
#define MIPC_LINK_RESUME_SET 0x01
#define MIPC_LINK_RESUME_DESCRIPTOR 0x06
#define MIPC_LINK_IDLE_ATTEMPTS 3
/* 3dm-gx5-45-dcp.txt:1297, 3dm-cv7-ins-docs.txt:7417, 3dm-cv7-ins-docs.txt:8144 */
#define MIPC_LINK_BAUD_SETTLE_MS 250
/* 3dm-gx5-45-dcp.txt:536, 3dm-cv7-ins-docs.txt:4099 */
#define MIPC_LINK_HAS_BANDWIDTH 1
#define MIPC_LINK_UART_WORD_BITS 10
#define MIPC_LINK_PACKET_OVERHEAD 6
#define MIPC_LINK_FIELD_OVERHEAD 2

/* The wrong-model check (issue 39, docs/conformance.md section 8): after the first NACK whose code
 * is an unknown-command code (the spec's simulation.nack unknown_descriptor and unknown_set), a link
 * told a device sends the identity command once and compares the model name it reports (the
 * MODEL_LENGTH bytes at MODEL_OFFSET of the reply field's data) with that device's names
 * (mipc_device_model_names); HAS 0: the spec names no identity. */
/* get_device_info answered by device_info */
#define MIPC_IDENTITY_HAS 1
#define MIPC_IDENTITY_SET 0x01
#define MIPC_IDENTITY_COMMAND 0x03
#define MIPC_IDENTITY_REPLY 0x81
#define MIPC_IDENTITY_MODEL_OFFSET 2u
#define MIPC_IDENTITY_MODEL_LENGTH 16u
#define MIPC_IDENTITY_UNKNOWN_CODES {1u, 6u}
#define MIPC_IDENTITY_UNKNOWN_COUNT 2u

/** Deepest parameter path a layout of this protocol can have (members of nested structs). */
#define MIPC_PATH_MAX_DEPTH 3
/** Enough room for any message mipc_decode_error_format() can produce. */
#define MIPC_ERROR_MESSAGE_MAX 325
/* Longest field name or device id, and a NUL. */
#define MIPC_NAME_MAX 48

#endif
