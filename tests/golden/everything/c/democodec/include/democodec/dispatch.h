/* Dispatch by (descriptor set, descriptor): devices, set kinds, the value of any field, and
 * decode/encode of any field (docs/conformance.md section 2). Generated: do not edit. */
#ifndef DEMO_DISPATCH_H
#define DEMO_DISPATCH_H

#include "democodec/reserved.h"
#include "democodec/sets/commands.h"
#include "democodec/sets/data.h"
#include "democodec/sets/receiver_1.h"
#include "democodec/sets/receiver_2.h"
#include "democodec/sets/shared.h"

#ifdef __cplusplus
extern "C" {
#endif

/** Devices named by the spec; DEMO_DEVICE_ANY tries every per-device variant. */
typedef enum {
    DEMO_DEVICE_ANY = 0,
    DEMO_DEVICE_DEV_A = 1, /* Device A */
    DEMO_DEVICE_DEV_B = 2  /* Device B */
} demo_device_t;

/** The id of a device ("dev_a"), or NULL for DEMO_DEVICE_ANY. */
const char *demo_device_id(demo_device_t device);
/** Looks up a device by id; false if there is none. */
bool demo_device_from_id(const char *id, demo_device_t *out);

/** Kind of a descriptor set, from the set_kinds ranges. */
typedef enum {
    DEMO_SET_KIND_NONE = 0,
    DEMO_SET_KIND_COMMAND = 1, /* 0x01..0x7F */
    DEMO_SET_KIND_DATA = 2     /* 0x80..0xFF */
} demo_set_kind_t;

demo_set_kind_t demo_set_kind(uint8_t set);

/** One id per field layout (per-device variants have one each). */
typedef enum {
    DEMO_FIELD_NONE = 0,
    DEMO_FIELD_ACK = 1,
    DEMO_FIELD_COMMANDS_PING = 2,
    DEMO_FIELD_COMMANDS_CONFIGURE = 3,
    DEMO_FIELD_COMMANDS_CONFIGURATION = 4,
    DEMO_FIELD_COMMANDS_PER_DEVICE_DEV_A = 5,
    DEMO_FIELD_COMMANDS_PER_DEVICE_DEV_B = 6,
    DEMO_FIELD_DATA_SAMPLE = 7,
    DEMO_FIELD_RECEIVER_1_LLH_POSITION = 8,
    DEMO_FIELD_RECEIVER_2_LLH_POSITION = 9,
    DEMO_FIELD_SHARED_TIMESTAMP = 10,
    DEMO_FIELD_COUNT = 11
} demo_field_id_t;

/** A decoded field: which layout, and its value. */
typedef struct {
    demo_field_id_t id;
    union {
        demo_ack_t ack;
        demo_commands_ping_t commands_ping;
        demo_commands_configure_t commands_configure;
        demo_commands_configuration_t commands_configuration;
        demo_commands_per_device_dev_a_t commands_per_device_dev_a;
        demo_commands_per_device_dev_b_t commands_per_device_dev_b;
        demo_data_sample_t data_sample;
        demo_receiver_1_llh_position_t receiver_1_llh_position;
        demo_receiver_2_llh_position_t receiver_2_llh_position;
        demo_shared_timestamp_t shared_timestamp;
    } u;
} demo_field_value_t;

/** What the spec says about a field layout. */
typedef struct {
    demo_field_id_t id;
    const char *name;   /* field name */
    const char *device; /* device id when the field has per-device variants, else NULL */
    demo_device_t device_id;
    uint8_t descriptor;
} demo_layout_info_t;

/** A field: its layouts are ids first_layout .. first_layout + layout_count - 1, in IR order. */
typedef struct {
    const char *name;
    uint8_t descriptor;
    demo_field_id_t first_layout;
    size_t layout_count;
} demo_field_info_t;

/** Information on a layout id (NULL if out of range). */
const demo_layout_info_t *demo_layout_info(demo_field_id_t id);

/**
 * The field (set, descriptor) designates: a field of the set, a reserved field of the set's
 * kind, or a shared data field. NULL if none; *why is then DEMO_ERR_UNKNOWN_SET or
 * DEMO_ERR_UNKNOWN_DESCRIPTOR.
 */
const demo_field_info_t *demo_find_field(uint8_t set, uint8_t descriptor, demo_status_t *why);

/**
 * Decodes field data. Per-device variants are tried in IR order (only the one of `device`
 * when it has one); the first that decodes wins. If none does, *err is the error of the first.
 */
demo_status_t demo_decode_field(uint8_t set, uint8_t descriptor, const uint8_t *data, size_t len,
                                demo_device_t device, demo_field_value_t *out, demo_decode_error_t *err);

/** Encodes the data of a decoded field (no field header). */
demo_status_t demo_encode_field(const demo_field_value_t *value, uint8_t *buf, size_t cap, size_t *len_out);

#ifdef __cplusplus
}
#endif

#endif
