/* Shared Data Descriptors (descriptor set 0xFF): one struct per field layout, with its
 * encoder and decoder. Generated from the spec: do not edit. */
#ifndef MIPC_SETS_SHARED_H
#define MIPC_SETS_SHARED_H

#include "mipcodec/types.h"
#include "mipcodec/field_iter.h"

#ifdef __cplusplus
extern "C" {
#endif

#define MIPC_SHARED_SET 0xFF

/* ---- event_source (data): Event source */
#define MIPC_SHARED_EVENT_SOURCE_DESCRIPTOR 0xD0

/** Event source. Which event trigger caused this packet to be sent; 0 for packets sent by the scheduled
 * streaming of the message format (0x0C,0x0F). Recommended as the first field of every event packet; as a
 * shared descriptor it is repeated in continuation packets. */
typedef struct {
    uint8_t trigger_id; /* Trigger (or, per line 1836, action) instance ID; 0 for scheduled streaming. */
} mipc_shared_event_source_t;

/* Largest encoded data (after the field header). */
#define MIPC_SHARED_EVENT_SOURCE_MAX_SIZE 1

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_shared_event_source_encode(const mipc_shared_event_source_t *value, uint8_t *buf,
                                              size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_shared_event_source_decode(const uint8_t *data, size_t len,
                                              mipc_shared_event_source_t *out, mipc_decode_error_t *err);

/* ---- gps_timestamp (data): GPS timestamp */
#define MIPC_SHARED_GPS_TIMESTAMP_DESCRIPTOR 0xD3

/** GPS timestamp. GPS time of the sample (for event packets, of the event trigger) as time of week and week
 * number. Valid after PPS synchronisation and after both the time of week and the week number have been sent
 * with the GPS Time Update command (0x01,0x72). */
typedef struct {
    double tow;                                          /* GPS time of week. [s] */
    uint16_t week_number;                                /* GPS week number since 1980. [weeks] */
    mipc_shared_gps_timestamp_valid_flags_t valid_flags; /* Which parts of the time have been set. */
} mipc_shared_gps_timestamp_t;

/* Largest encoded data (after the field header). */
#define MIPC_SHARED_GPS_TIMESTAMP_MAX_SIZE 12

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_shared_gps_timestamp_encode(const mipc_shared_gps_timestamp_t *value, uint8_t *buf,
                                               size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_shared_gps_timestamp_decode(const uint8_t *data, size_t len,
                                               mipc_shared_gps_timestamp_t *out, mipc_decode_error_t *err);

/* ---- delta_time (data): Delta time */
#define MIPC_SHARED_DELTA_TIME_DESCRIPTOR 0xD4

/** Delta time. Seconds in the synchronised (external/GPS) clock domain since the last output of this field in
 * the same descriptor set and event instance. The same value as external time delta 0xD8 in seconds; both
 * restart one shared counter, so stream only one of them. */
typedef struct {
    double seconds; /* Seconds since the last output. [s] */
} mipc_shared_delta_time_t;

/* Largest encoded data (after the field header). */
#define MIPC_SHARED_DELTA_TIME_MAX_SIZE 8

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_shared_delta_time_encode(const mipc_shared_delta_time_t *value, uint8_t *buf, size_t cap,
                                            size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_shared_delta_time_decode(const uint8_t *data, size_t len, mipc_shared_delta_time_t *out,
                                            mipc_decode_error_t *err);

/* ---- reference_timestamp (data): Reference timestamp */
#define MIPC_SHARED_REFERENCE_TIMESTAMP_DESCRIPTOR 0xD5

/** Reference timestamp. Time at which the data was sampled (for events, of the trigger) on the internal
 * monotonic reference clock, in nanoseconds since power-on. Never jumps; always valid. */
typedef struct {
    uint64_t nanoseconds; /* Nanoseconds since initialization. [ns] */
} mipc_shared_reference_timestamp_t;

/* Largest encoded data (after the field header). */
#define MIPC_SHARED_REFERENCE_TIMESTAMP_MAX_SIZE 8

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_shared_reference_timestamp_encode(const mipc_shared_reference_timestamp_t *value,
                                                     uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_shared_reference_timestamp_decode(const uint8_t *data, size_t len,
                                                     mipc_shared_reference_timestamp_t *out,
                                                     mipc_decode_error_t *err);

/* ---- reference_time_delta (data): Reference time delta */
#define MIPC_SHARED_REFERENCE_TIME_DELTA_DESCRIPTOR 0xD6

/** Reference time delta. Difference between the reference timestamp (0xD5) now and at the previous output of
 * this field in the same descriptor set and event instance. Always valid. */
typedef struct {
    uint64_t dt_nanos; /* Nanoseconds since the last occurrence of this field. [ns] */
} mipc_shared_reference_time_delta_t;

/* Largest encoded data (after the field header). */
#define MIPC_SHARED_REFERENCE_TIME_DELTA_MAX_SIZE 8

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_shared_reference_time_delta_encode(const mipc_shared_reference_time_delta_t *value,
                                                      uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_shared_reference_time_delta_decode(const uint8_t *data, size_t len,
                                                      mipc_shared_reference_time_delta_t *out,
                                                      mipc_decode_error_t *err);

/* ---- external_timestamp (data): External timestamp */
#define MIPC_SHARED_EXTERNAL_TIMESTAMP_DESCRIPTOR 0xD7

/** External timestamp. Time at which the data was sampled (for events, of the trigger) in the external clock
 * domain, in nanoseconds: the GPS timestamp in nanoseconds. Valid once the external clock is synchronised
 * with the PPS input. */
typedef struct {
    uint64_t nanoseconds;                              /* External time in nanoseconds. [ns] */
    mipc_external_timestamp_valid_flags_t valid_flags; /* Bit 0: nanoseconds valid. */
} mipc_shared_external_timestamp_t;

/* Largest encoded data (after the field header). */
#define MIPC_SHARED_EXTERNAL_TIMESTAMP_MAX_SIZE 10

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_shared_external_timestamp_encode(const mipc_shared_external_timestamp_t *value,
                                                    uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_shared_external_timestamp_decode(const uint8_t *data, size_t len,
                                                    mipc_shared_external_timestamp_t *out,
                                                    mipc_decode_error_t *err);

/* ---- external_time_delta (data): External time delta */
#define MIPC_SHARED_EXTERNAL_TIME_DELTA_DESCRIPTOR 0xD8

/** External time delta. Difference between the external timestamp (0xD7) now and at the previous output of
 * this field in the same descriptor set and event instance. The same value as delta time 0xD4 in nanoseconds;
 * both restart one shared counter. */
typedef struct {
    uint64_t dt_nanos; /* Nanoseconds since the last occurrence of this field. [ns] */
    mipc_external_time_delta_valid_flags_t valid_flags; /* Bit 0: delta valid. */
} mipc_shared_external_time_delta_t;

/* Largest encoded data (after the field header). */
#define MIPC_SHARED_EXTERNAL_TIME_DELTA_MAX_SIZE 10

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_shared_external_time_delta_encode(const mipc_shared_external_time_delta_t *value,
                                                     uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_shared_external_time_delta_decode(const uint8_t *data, size_t len,
                                                     mipc_shared_external_time_delta_t *out,
                                                     mipc_decode_error_t *err);

/**
 * The fields of one packet of this set, decoded in place by mipc_shared_decode_packet: one member per
 * field the set defines with a single layout (its own, the reserved fields of its kind and the
 * shared data fields); `index` says which members hold a field of the packet, in packet order.
 */
typedef struct {
    mipc_packet_index_t index;
    mipc_shared_event_source_t shared_event_source;                 /* 0xD0 */
    mipc_shared_gps_timestamp_t shared_gps_timestamp;               /* 0xD3 */
    mipc_shared_delta_time_t shared_delta_time;                     /* 0xD4 */
    mipc_shared_reference_timestamp_t shared_reference_timestamp;   /* 0xD5 */
    mipc_shared_reference_time_delta_t shared_reference_time_delta; /* 0xD6 */
    mipc_shared_external_timestamp_t shared_external_timestamp;     /* 0xD7 */
    mipc_shared_external_time_delta_t shared_external_time_delta;   /* 0xD8 */
} mipc_shared_packet_t;

/**
 * The straight-line decoder of a packet of this set (issue 38): walks the fields of the payload
 * (len bytes at payload) with a switch on the descriptor and decodes each field's layout into its
 * member of *out, giving the value mipc_decode_field gives; no general value, no indirect call. Every
 * other entry goes to other (may be NULL: they are dropped) with ctx, in packet order with the
 * fields: a descriptor without a member (undefined, or a field with per-device variants), a field
 * that does not decode (its member is then unspecified), a second field with a descriptor already
 * decoded, trailing bytes. Returns out->index.count, the number of fields decoded into members.
 */
size_t mipc_shared_decode_packet(const uint8_t *payload, size_t len, mipc_shared_packet_t *out,
                                 mipc_field_entry_fn other, void *ctx);

/* Private (mipc_decode_packet_cached): the members of mipc_shared_packet_t: descriptor, offset,
 * loader. */
extern const mipc_layout_member_t mipc_shared_layout_members_[7];

#ifdef __cplusplus
}
#endif

#endif
