/* Stand-in for a generated dispatch.h (templates/c/dispatch.h.j2) in the runtime's own tests: the
 * same declarations for a small test protocol, so that json_codec.c, the tools and the package
 * tests compile and run in place. Descriptor set 0x01 has two fields:
 *   0x01 "ping": no values;
 *   0x02 "rate": per-device variants, {"hz": u16} on device "alpha", {"hz": u32} on "beta".
 * Both devices ("Alpha", alpha.txt; "Beta", beta.txt) support both; no data quantities.
 * Hand-written (the generator writes the real one from the spec). */
#ifndef CODEC_DISPATCH_H
#define CODEC_DISPATCH_H

#include "codec/status.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef enum { CODEC_DEVICE_ANY = 0, CODEC_DEVICE_ALPHA = 1, CODEC_DEVICE_BETA = 2 } codec_device_t;

const char *codec_device_id(codec_device_t device);
bool codec_device_from_id(const char *id, codec_device_t *out);
const char *codec_device_title(codec_device_t device);
const char *codec_device_manual(codec_device_t device);
const uint16_t *codec_device_commands(codec_device_t device, size_t *count);
const uint16_t *codec_device_data(codec_device_t device, size_t *count);
bool codec_device_supports(codec_device_t device, uint8_t set, uint8_t descriptor);

typedef enum {
    CODEC_FIELD_NONE = 0,
    CODEC_FIELD_PING = 1,
    CODEC_FIELD_RATE_ALPHA = 2,
    CODEC_FIELD_RATE_BETA = 3
} codec_field_id_t;

typedef struct {
    codec_field_id_t id;
    union {
        uint16_t rate_alpha_hz;
        uint32_t rate_beta_hz;
    } u;
} codec_field_value_t;

typedef struct {
    codec_field_id_t id;
    const char *name;
    const char *device;
    codec_device_t device_id;
    uint8_t descriptor;
} codec_layout_info_t;

typedef struct {
    const char *name;
    uint8_t descriptor;
    codec_field_id_t first_layout;
    size_t layout_count;
} codec_field_info_t;

const codec_layout_info_t *codec_layout_info(codec_field_id_t id);
const codec_field_info_t *codec_find_field(uint8_t set, uint8_t descriptor, codec_status_t *why);
codec_status_t codec_decode_field(uint8_t set, uint8_t descriptor, const uint8_t *data, size_t len,
                                  codec_device_t device, codec_field_value_t *out, codec_decode_error_t *err);
codec_status_t codec_encode_field(const codec_field_value_t *value, uint8_t *buf, size_t cap,
                                  size_t *len_out);

#ifdef __cplusplus
}
#endif

#endif
