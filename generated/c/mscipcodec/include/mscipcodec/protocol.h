/* Constants of the Memsense MS-CIP protocol, rendered from protocols[] of the IR: the only protocol
 * input of the runtime (the files copied from generator/targets/c/runtime/).
 * Generated: do not edit. */
#ifndef MSCIP_PROTOCOL_H
#define MSCIP_PROTOCOL_H

#include <stdint.h>

/* Byte order of multi-byte values in field data (byte_order: big). */
#define MSCIP_LITTLE_ENDIAN 0

/* Sync sequence that starts every packet. */
#define MSCIP_SYNC_SIZE 2
#define MSCIP_SYNC_0 0xA5
#define MSCIP_SYNC_1 0xA5
#define MSCIP_SYNC_BYTES {0xA5, 0xA5}
/* Packet header: sync bytes, then set, payload_length. */
#define MSCIP_HEADER_SIZE 4
#define MSCIP_SET_OFFSET 2
#define MSCIP_LENGTH_OFFSET 3
#define MSCIP_MAX_PAYLOAD 255
#define MSCIP_CHECKSUM_SIZE 2
/* Checksum bytes in wire order: sum1, sum2. */
#define MSCIP_CHECKSUM_SUM1_FIRST 1
/* Largest packet: header, maximum payload and checksum. */
#define MSCIP_MAX_PACKET 261
/* Field header: descriptor, length. */
#define MSCIP_FIELD_HEADER_SIZE 2
#define MSCIP_FIELD_LENGTH_OFFSET 1
#define MSCIP_FIELD_DESCRIPTOR_OFFSET 0
/* The field length byte counts only the data:
 * data length = length byte - MSCIP_FIELD_LENGTH_ADJUST. */
#define MSCIP_FIELD_LENGTH_ADJUST 0
/*
 * Length byte - data length of field (set, descriptor): MSCIP_FIELD_LENGTH_ADJUST, except for the
 * fields the spec marks with length_byte_adjust (1 in this protocol).
 */
static inline int mscip_field_length_adjust(uint8_t set, uint8_t descriptor) {
    if (set == 0x02 && descriptor == 0x05) {
        return MSCIP_FIELD_LENGTH_ADJUST + (-1);
    }
    return MSCIP_FIELD_LENGTH_ADJUST;
}
/* Largest data a single field can carry. */
#define MSCIP_MAX_FIELD_DATA 253

/* Samples (docs/conformance.md section 6). Data sets that group continuation packets (one
 * tracker slot each; MSCIP_SAMPLE_DATA_SET_COUNT of them, the array never empty). */
#define MSCIP_SAMPLE_DATA_SET_COUNT 0
#define MSCIP_SAMPLE_SETS 1
#define MSCIP_SAMPLE_DATA_SETS {0x00}
/* Shared descriptors: from MSCIP_SAMPLE_FIRST_SHARED up (256: none). */
#define MSCIP_SAMPLE_FIRST_SHARED 256
/* Shared timestamp fields (descriptor, data size) that make up the sample key. */
#define MSCIP_SAMPLE_TIMESTAMPS 0
#define MSCIP_SAMPLE_STAMP_DESCRIPTORS {0x00}
#define MSCIP_SAMPLE_STAMP_SIZES {0}
/* Largest sample key: field header + data of every shared timestamp field. */
#define MSCIP_SAMPLE_KEY_MAX 1

/** Deepest parameter path a layout of this protocol can have (members of nested structs). */
#define MSCIP_PATH_MAX_DEPTH 2
/** Enough room for any message mscip_decode_error_format() can produce. */
#define MSCIP_ERROR_MESSAGE_MAX 236
/* Longest field name or device id, and a NUL. */
#define MSCIP_NAME_MAX 30

#endif
