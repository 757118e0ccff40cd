/* System Data Set (descriptor set 0xA0): one struct per field layout, with its
 * encoder and decoder. Generated from the spec: do not edit. */
#ifndef MIPC_SETS_SYSTEM_DATA_H
#define MIPC_SETS_SYSTEM_DATA_H

#include "mipcodec/types.h"
#include "mipcodec/field_iter.h"
#include "mipcodec/sets/shared.h"

#ifdef __cplusplus
extern "C" {
#endif

#define MIPC_SYSTEM_DATA_SET 0xA0

/* ---- built_in_test (data): Built-in test (streaming continuous BIT) */
#define MIPC_SYSTEM_DATA_BUILT_IN_TEST_DESCRIPTOR 0x01

/** Built-in test (streaming continuous BIT). The continuous built-in test result, streamed or polled (the
 * same bits as the Continuous BIT command 0x01,0x08). The bits latch until the next output of this message;
 * some may be set in normal situations (e.g. no GNSS fix yet). Large: stream at a low rate. */
typedef struct {
    mipc_cv7_continuous_bit_t result; /* Continuous BIT bit map, 16 bytes, least-significant byte first. */
} mipc_system_data_built_in_test_t;

/* Largest encoded data (after the field header). */
#define MIPC_SYSTEM_DATA_BUILT_IN_TEST_MAX_SIZE 16

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_system_data_built_in_test_encode(const mipc_system_data_built_in_test_t *value,
                                                    uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_system_data_built_in_test_decode(const uint8_t *data, size_t len,
                                                    mipc_system_data_built_in_test_t *out,
                                                    mipc_decode_error_t *err);

/* ---- time_sync_status (data): Time sync status */
#define MIPC_SYSTEM_DATA_TIME_SYNC_STATUS_DESCRIPTOR 0x02

/** Time sync status. Whether the device is synchronised to the PPS signal, and how long ago the last pulse
 * came. */
typedef struct {
    bool time_sync;        /* True while PPS sync is valid; false if PPS is disabled or not detected. */
    uint8_t last_pps_rcvd; /* Seconds since the last PPS pulse, saturating at 255. [s] */
} mipc_system_data_time_sync_status_t;

/* Largest encoded data (after the field header). */
#define MIPC_SYSTEM_DATA_TIME_SYNC_STATUS_MAX_SIZE 2

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_system_data_time_sync_status_encode(const mipc_system_data_time_sync_status_t *value,
                                                       uint8_t *buf, size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_system_data_time_sync_status_decode(const uint8_t *data, size_t len,
                                                       mipc_system_data_time_sync_status_t *out,
                                                       mipc_decode_error_t *err);

/* ---- gpio_state (data): GPIO state */
#define MIPC_SYSTEM_DATA_GPIO_STATE_DESCRIPTOR 0x03

/** GPIO state. States of the user GPIO pins, sampled within one base period of the system data set. For slow
 * signals; pins must be configured with the GPIO feature (0x0C,0x41) to read validly. */
typedef struct {
    mipc_gpio_pin_states_t states; /* One bit per pin; pins that do not exist read 0. */
} mipc_system_data_gpio_state_t;

/* Largest encoded data (after the field header). */
#define MIPC_SYSTEM_DATA_GPIO_STATE_MAX_SIZE 1

/** Encodes the field data (no field header) into buf; *len_out receives its size. */
mipc_status_t mipc_system_data_gpio_state_encode(const mipc_system_data_gpio_state_t *value, uint8_t *buf,
                                                 size_t cap, size_t *len_out);
/** Decodes field data; on MIPC_ERR_DECODE, *err (if not NULL) tells what is wrong. */
mipc_status_t mipc_system_data_gpio_state_decode(const uint8_t *data, size_t len,
                                                 mipc_system_data_gpio_state_t *out,
                                                 mipc_decode_error_t *err);

/**
 * The fields of one packet of this set, decoded in place by mipc_system_data_decode_packet: one member per
 * field the set defines with a single layout (its own, the reserved fields of its kind and the
 * shared data fields); `index` says which members hold a field of the packet, in packet order.
 */
typedef struct {
    mipc_packet_index_t index;
    mipc_system_data_built_in_test_t system_data_built_in_test;       /* 0x01 */
    mipc_system_data_time_sync_status_t system_data_time_sync_status; /* 0x02 */
    mipc_system_data_gpio_state_t system_data_gpio_state;             /* 0x03 */
    mipc_shared_event_source_t shared_event_source;                   /* 0xD0 (shared) */
    mipc_shared_gps_timestamp_t shared_gps_timestamp;                 /* 0xD3 (shared) */
    mipc_shared_delta_time_t shared_delta_time;                       /* 0xD4 (shared) */
    mipc_shared_reference_timestamp_t shared_reference_timestamp;     /* 0xD5 (shared) */
    mipc_shared_reference_time_delta_t shared_reference_time_delta;   /* 0xD6 (shared) */
    mipc_shared_external_timestamp_t shared_external_timestamp;       /* 0xD7 (shared) */
    mipc_shared_external_time_delta_t shared_external_time_delta;     /* 0xD8 (shared) */
} mipc_system_data_packet_t;

/**
 * The straight-line decoder of a packet of this set (issue 38): walks the fields of the payload
 * (len bytes at payload) with a switch on the descriptor and decodes each field's layout into its
 * member of *out, giving the value mipc_decode_field gives; no general value, no indirect call. Every
 * other entry goes to other (may be NULL: they are dropped) with ctx, in packet order with the
 * fields: a descriptor without a member (undefined, or a field with per-device variants), a field
 * that does not decode (its member is then unspecified), a second field with a descriptor already
 * decoded, trailing bytes. Returns out->index.count, the number of fields decoded into members.
 */
size_t mipc_system_data_decode_packet(const uint8_t *payload, size_t len, mipc_system_data_packet_t *out,
                                      mipc_field_entry_fn other, void *ctx);

/* Private (mipc_decode_packet_cached): the members of mipc_system_data_packet_t: descriptor, offset,
 * loader. */
extern const mipc_layout_member_t mipc_system_data_layout_members_[10];

#ifdef __cplusplus
}
#endif

#endif
