/* Constants of the MicroStrain MIP for the C accelerator (codec/_speedups*.c), generated from the IR:
 * the same facts as _protocol.py, the only protocol input of the runtime. */
#ifndef MIPCODEC_PROTOCOL_H
#define MIPCODEC_PROTOCOL_H

#define PROTOCOL_PACKAGE "mipcodec"
#define SYNC_LEN 2
static const unsigned char SYNC[SYNC_LEN] = {
    0x75,
    0x65,
};
#define HEADER_SIZE 4
#define SET_OFFSET 2
#define LENGTH_OFFSET 3
#define FIELD_HEADER_SIZE 2
#define FIELD_LENGTH_OFFSET 0
#define FIELD_DESCRIPTOR_OFFSET 1
#define FIELD_LENGTH_ADJUST 2
#define MAX_PAYLOAD 255
/* Foreign frames between packets (docs/conformance.md section 1). */
#define FOREIGN_NMEA 1
#define FOREIGN_RTCM3 1
#define NMEA_MAX 128
#define CHECKSUM_SIZE 2
#define CHECKSUM_SUM1_FIRST 1
#define BIG_ENDIAN_WIRE 1

/* Length byte - data length of a field (framing.field_length_adjust). */
static inline int field_length_adjust(int set_id, int descriptor) {
    (void)set_id;
    (void)descriptor;
    return FIELD_LENGTH_ADJUST;
}

#endif
