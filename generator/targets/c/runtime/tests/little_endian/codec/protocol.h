/* Test protocol "little": the constants a generated protocol.h provides (templates/c/protocol.h.j2),
 * written by hand for the runtime's own tests. MS-CIP-like framing with the other choices where
 * the spec allows them: little-endian, descriptor before length, a length byte that counts only
 * the data, one irregular field, sum2 first, no samples rule. */
#ifndef CODEC_PROTOCOL_H
#define CODEC_PROTOCOL_H

#include <stdint.h>

#define CODEC_LITTLE_ENDIAN 1

#define CODEC_SYNC_SIZE 2
#define CODEC_SYNC_0 0xA5
#define CODEC_SYNC_1 0x5A
#define CODEC_SYNC_BYTES {0xA5, 0x5A}
#define CODEC_HEADER_SIZE 4
#define CODEC_SET_OFFSET 2
#define CODEC_LENGTH_OFFSET 3
#define CODEC_MAX_PAYLOAD 255
#define CODEC_CHECKSUM_SIZE 2
#define CODEC_CHECKSUM_SUM1_FIRST 0
#define CODEC_MAX_PACKET 261
#define CODEC_FIELD_HEADER_SIZE 2
#define CODEC_FIELD_LENGTH_OFFSET 1
#define CODEC_FIELD_DESCRIPTOR_OFFSET 0
#define CODEC_FIELD_LENGTH_ADJUST 0
static inline int codec_field_length_adjust(uint8_t set, uint8_t descriptor) {
    if (set == 0x02 && descriptor == 0x05) {
        return CODEC_FIELD_LENGTH_ADJUST + (-1);
    }
    return CODEC_FIELD_LENGTH_ADJUST;
}
#define CODEC_MAX_FIELD_DATA 253

#define CODEC_SAMPLE_DATA_SET_COUNT 0
#define CODEC_SAMPLE_SETS 1
#define CODEC_SAMPLE_DATA_SETS {0x00}
#define CODEC_SAMPLE_FIRST_SHARED 256
#define CODEC_SAMPLE_TIMESTAMPS 0
#define CODEC_SAMPLE_STAMP_DESCRIPTORS {0x00}
#define CODEC_SAMPLE_STAMP_SIZES {0}
#define CODEC_SAMPLE_KEY_MAX 1

#define CODEC_SESSION_ACK_DESCRIPTOR 0xF1
#define CODEC_SESSION_ACK_OK 0u
#define CODEC_SESSION_MAX_EXPECT 1

#define CODEC_PATH_MAX_DEPTH 1
#define CODEC_ERROR_MESSAGE_MAX 200
#define CODEC_NAME_MAX 32

#endif
