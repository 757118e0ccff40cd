/* Dispatch by (descriptor set, descriptor): devices, set kinds, the value of any field, and
 * decode/encode of any field (docs/conformance.md section 2). Generated: do not edit. */
#ifndef DEMOC_DISPATCH_H
#define DEMOC_DISPATCH_H

#include "democodec/field_iter.h"
#include "democodec/reserved.h"
#include "democodec/sets/commands.h"
#include "democodec/sets/data.h"
#include "democodec/sets/receiver_1.h"
#include "democodec/sets/receiver_2.h"
#include "democodec/sets/shared.h"

#ifdef __cplusplus
extern "C" {
#endif

/** Devices named by the spec; DEMOC_DEVICE_ANY tries every per-device variant. */
typedef enum {
    DEMOC_DEVICE_ANY = 0,
    DEMOC_DEVICE_DEV_A = 1, /* Device A */
    DEMOC_DEVICE_DEV_B = 2  /* Device B */
} democ_device_t;

/** The id of a device ("dev_a"), or NULL for DEMOC_DEVICE_ANY. */
const char *democ_device_id(democ_device_t device);
/** Looks up a device by id; false if there is none. */
bool democ_device_from_id(const char *id, democ_device_t *out);
/** The device's title ("Device A") and the file name of its manual, or NULL for
 * DEMOC_DEVICE_ANY. */
const char *democ_device_title(democ_device_t device);
const char *democ_device_manual(democ_device_t device);
/** What the device supports, as its manual documents it (the IR's `capabilities`): the
 * (set << 8) | descriptor of every command, or of every data quantity, ascending, in a constant
 * table; *count is set to its length (0 and NULL for DEMOC_DEVICE_ANY). No allocation. */
const uint16_t *democ_device_commands(democ_device_t device, size_t *count);
const uint16_t *democ_device_data(democ_device_t device, size_t *count);
/** The baud rates of the device's main port as its manual lists them (the IR's `link`), ascending,
 * in a constant table; *count is set to its length (0 and NULL for DEMOC_DEVICE_ANY or a model
 * whose manual lists none). */
const uint32_t *democ_device_baud_rates(democ_device_t device, size_t *count);
/** The default baud rate of the device's main port; 0 when its manual states none. */
uint32_t democ_device_default_baud(democ_device_t device);
/** True when the device's manual documents the command or data quantity (set, descriptor); the
 * sessions refuse a command for which this is false, before sending it. */
bool democ_device_supports(democ_device_t device, uint8_t set, uint8_t descriptor);

/** Kind of a descriptor set, from the set_kinds ranges. */
typedef enum {
    DEMOC_SET_KIND_NONE = 0,
    DEMOC_SET_KIND_COMMAND = 1, /* 0x01..0x7F */
    DEMOC_SET_KIND_DATA = 2     /* 0x80..0xFF */
} democ_set_kind_t;

democ_set_kind_t democ_set_kind(uint8_t set);

/** One id per field layout (per-device variants have one each). */
typedef enum {
    DEMOC_FIELD_NONE = 0,
    DEMOC_FIELD_ACK,
    DEMOC_FIELD_COMMANDS_PING,
    DEMOC_FIELD_COMMANDS_CONFIGURE,
    DEMOC_FIELD_COMMANDS_CONFIGURATION,
    DEMOC_FIELD_COMMANDS_PER_DEVICE_DEV_A,
    DEMOC_FIELD_COMMANDS_PER_DEVICE_DEV_B,
    DEMOC_FIELD_DATA_SAMPLE,
    DEMOC_FIELD_RECEIVER_1_LLH_POSITION,
    DEMOC_FIELD_RECEIVER_2_LLH_POSITION,
    DEMOC_FIELD_SHARED_TIMESTAMP,
    DEMOC_FIELD_COUNT
} democ_field_id_t;

/** A decoded field: which layout, and its value. */
typedef struct {
    democ_field_id_t id;
    union {
        democ_ack_t ack;
        democ_commands_ping_t commands_ping;
        democ_commands_configure_t commands_configure;
        democ_commands_configuration_t commands_configuration;
        democ_commands_per_device_dev_a_t commands_per_device_dev_a;
        democ_commands_per_device_dev_b_t commands_per_device_dev_b;
        democ_data_sample_t data_sample;
        democ_receiver_1_llh_position_t receiver_1_llh_position;
        democ_receiver_2_llh_position_t receiver_2_llh_position;
        democ_shared_timestamp_t shared_timestamp;
    } u;
} democ_field_value_t;

/** What the spec says about a field layout. */
typedef struct {
    democ_field_id_t id;
    const char *name;   /* field name */
    const char *device; /* device id when the field has per-device variants, else NULL */
    democ_device_t device_id;
    uint8_t descriptor;
} democ_layout_info_t;

/** A field: its layouts are ids first_layout .. first_layout + layout_count - 1, in IR order. */
typedef struct {
    const char *name;
    uint8_t descriptor;
    democ_field_id_t first_layout;
    size_t layout_count;
} democ_field_info_t;

/** Information on a layout id (NULL if out of range). */
const democ_layout_info_t *democ_layout_info(democ_field_id_t id);

/**
 * The field (set, descriptor) designates: a field of the set, a reserved field of the set's
 * kind, or a shared data field. NULL if none; *why is then DEMOC_ERR_UNKNOWN_SET or
 * DEMOC_ERR_UNKNOWN_DESCRIPTOR.
 */
const democ_field_info_t *democ_find_field(uint8_t set, uint8_t descriptor, democ_status_t *why);

/**
 * Decodes field data. Per-device variants are tried in IR order (only the one of `device`
 * when it has one); the first that decodes wins. If none does, *err is the error of the first.
 */
democ_status_t democ_decode_field(uint8_t set, uint8_t descriptor, const uint8_t *data, size_t len,
                                  democ_device_t device, democ_field_value_t *out, democ_decode_error_t *err);

/** A packet of any data set decoded by its set's straight-line decoder (democ_decode_packet). */
typedef struct {
    uint8_t set;
    union {
        democ_data_packet_t data;
        democ_receiver_1_packet_t receiver_1;
        democ_receiver_2_packet_t receiver_2;
        democ_shared_packet_t shared;
        uint8_t none_; /* no data set */
    } u;
} democ_packet_t;

/**
 * Decodes a packet (sync, header and payload; its checksum is the parser's business) of a data set
 * with that set's straight-line decoder (<set>_decode_packet: entries it leaves go to other, which
 * may be NULL, with ctx) into the set's member of out->u, and returns its index (the fields
 * decoded, in packet order). For a set without one (not a data set, or not defined) every entry
 * goes to other and it returns NULL.
 */
const democ_packet_index_t *democ_decode_packet(const uint8_t *packet, democ_packet_t *out,
                                                democ_field_entry_fn other, void *ctx);

/**
 * democ_decode_packet through a layout cache (issue 38), with the same contract and results: a
 * packet whose shape (set, payload length, every field header) is in the cache is decoded at the
 * shape's offsets, without the header walk and the dispatch per descriptor; any other packet
 * takes democ_decode_packet, and its shape is recorded (round-robin over
 * DEMOC_LAYOUT_CACHE_SHAPES slots) when every entry was decoded into a member. cache: one per
 * stream, initialised with democ_layout_cache_init; fixed size, no allocation.
 */
const democ_packet_index_t *democ_decode_packet_cached(democ_layout_cache_t *cache, const uint8_t *packet,
                                                       democ_packet_t *out, democ_field_entry_fn other,
                                                       void *ctx);

/** Encodes the data of a decoded field (no field header). */
democ_status_t democ_encode_field(const democ_field_value_t *value, uint8_t *buf, size_t cap,
                                  size_t *len_out);

#ifdef __cplusplus
}
#endif

#endif
