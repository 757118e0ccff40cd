/* Receiver 1 (descriptor set 0x91): one struct per field layout, with its
 * encoder and decoder. Generated from the spec: do not edit. */
#ifndef DEMOC_SETS_RECEIVER_1_H
#define DEMOC_SETS_RECEIVER_1_H

#include "democodec/types.h"
#include "democodec/field_iter.h"
#include "democodec/sets/shared.h"

#ifdef __cplusplus
extern "C" {
#endif

#define DEMOC_RECEIVER_1_SET 0x91

/* ---- llh_position (data): LLH position */
#define DEMOC_RECEIVER_1_LLH_POSITION_DESCRIPTOR 0x03

/** LLH position.  */
typedef struct {
    double latitude;      /*  [deg] */
    double longitude;     /*  [deg] */
    uint16_t valid_flags; /*  */
} democ_receiver_1_llh_position_t;

/* Largest encoded data (after the field header). */
#define DEMOC_RECEIVER_1_LLH_POSITION_MAX_SIZE 18

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
democ_status_t democ_receiver_1_llh_position_encode(const democ_receiver_1_llh_position_t *value,
                                                    uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on DEMOC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
democ_status_t democ_receiver_1_llh_position_decode(const uint8_t *data, size_t len,
                                                    democ_receiver_1_llh_position_t *out,
                                                    democ_decode_error_t *err);

/**
 * The fields of one packet of this set, decoded in place by democ_receiver_1_decode_packet: one member per
 * field the set defines with a single layout (its own, the reserved fields of its kind and the
 * shared data fields); `index` says which members hold a field of the packet, in packet order.
 */
typedef struct {
    democ_packet_index_t index;
    democ_receiver_1_llh_position_t receiver_1_llh_position; /* 0x03 */
    democ_shared_timestamp_t shared_timestamp;               /* 0xD3 (shared) */
} democ_receiver_1_packet_t;

/**
 * The straight-line decoder of a packet of this set (issue 38): walks the fields of the payload
 * (len bytes at payload) with a switch on the descriptor and decodes each field's layout into its
 * member of *out, giving the value democ_decode_field gives; no general value, no indirect call. Every
 * other entry goes to other (may be NULL: they are dropped) with ctx, in packet order with the
 * fields: a descriptor without a member (undefined, or a field with per-device variants), a field
 * that does not decode (its member is then unspecified), a second field with a descriptor already
 * decoded, trailing bytes. Returns out->index.count, the number of fields decoded into members.
 */
size_t democ_receiver_1_decode_packet(const uint8_t *payload, size_t len, democ_receiver_1_packet_t *out,
                                      democ_field_entry_fn other, void *ctx);

/* Private (democ_decode_packet_cached): the members of democ_receiver_1_packet_t: descriptor, offset,
 * loader. */
extern const democ_layout_member_t democ_receiver_1_layout_members_[2];

#ifdef __cplusplus
}
#endif

#endif
