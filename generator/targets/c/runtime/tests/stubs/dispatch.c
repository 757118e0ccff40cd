/* Stand-in for the generated dispatch of a protocol (see codec/dispatch.h): devices, the field
 * table of descriptor set 0x01, decode/encode and JSON of its layouts, written the way the
 * generated code does it (reader/writer of wire.h, JSON reader/writer). */
#include "codec/dispatch.h"

#include <string.h>

#include "layouts_internal.h"
#include "wire.h"

static const char *const k_devices[] = {NULL, "alpha", "beta"};

const char *codec_device_id(codec_device_t device) {
    return device == CODEC_DEVICE_ALPHA || device == CODEC_DEVICE_BETA ? k_devices[device] : NULL;
}

bool codec_device_from_id(const char *id, codec_device_t *out) {
    if (strcmp(id, "alpha") == 0) {
        *out = CODEC_DEVICE_ALPHA;
        return true;
    }
    if (strcmp(id, "beta") == 0) {
        *out = CODEC_DEVICE_BETA;
        return true;
    }
    return false;
}

const char *codec_device_title(codec_device_t device) {
    return device == CODEC_DEVICE_ALPHA ? "Alpha" : device == CODEC_DEVICE_BETA ? "Beta" : NULL;
}

const char *codec_device_manual(codec_device_t device) {
    return device == CODEC_DEVICE_ALPHA ? "alpha.txt" : device == CODEC_DEVICE_BETA ? "beta.txt" : NULL;
}

static const uint16_t k_commands[] = {0x0101, 0x0102};

const uint16_t *codec_device_commands(codec_device_t device, size_t *count) {
    bool known = device == CODEC_DEVICE_ALPHA || device == CODEC_DEVICE_BETA;
    *count = known ? 2u : 0u;
    return known ? k_commands : NULL;
}

const uint16_t *codec_device_data(codec_device_t device, size_t *count) {
    (void)device;
    *count = 0;
    return NULL;
}

bool codec_device_supports(codec_device_t device, uint8_t set, uint8_t descriptor) {
    size_t n, i;
    const uint16_t *t = codec_device_commands(device, &n);
    for (i = 0; i < n; i++) {
        if (t[i] == (uint16_t)((set << 8) | descriptor)) {
            return true;
        }
    }
    return false;
}

static const codec_layout_info_t k_layouts[] = {
    {CODEC_FIELD_NONE, "", NULL, CODEC_DEVICE_ANY, 0x00},
    {CODEC_FIELD_PING, "ping", NULL, CODEC_DEVICE_ANY, 0x01},
    {CODEC_FIELD_RATE_ALPHA, "rate", "alpha", CODEC_DEVICE_ALPHA, 0x02},
    {CODEC_FIELD_RATE_BETA, "rate", "beta", CODEC_DEVICE_BETA, 0x02},
};

static const codec_field_info_t k_fields[] = {
    {"ping", 0x01, CODEC_FIELD_PING, 1},
    {"rate", 0x02, CODEC_FIELD_RATE_ALPHA, 2},
};

const codec_layout_info_t *codec_layout_info(codec_field_id_t id) {
    return (size_t)id < sizeof k_layouts / sizeof k_layouts[0] ? &k_layouts[id] : NULL;
}

const codec_field_info_t *codec_find_field(uint8_t set, uint8_t descriptor, codec_status_t *why) {
    size_t i;
    if (set != 0x01) {
        *why = CODEC_ERR_UNKNOWN_SET;
        return NULL;
    }
    for (i = 0; i < sizeof k_fields / sizeof k_fields[0]; i++) {
        if (k_fields[i].descriptor == descriptor) {
            return &k_fields[i];
        }
    }
    *why = CODEC_ERR_UNKNOWN_DESCRIPTOR;
    return NULL;
}

static int decode_layout(codec_field_id_t id, const uint8_t *data, size_t len, codec_field_value_t *out,
                         codec_decode_error_t *err) {
    codec_reader_t r;
    codec_reader_init(&r, data, len, err);
    out->id = id;
    if (id == CODEC_FIELD_RATE_ALPHA || id == CODEC_FIELD_RATE_BETA) {
        codec_rd_push(&r, "hz");
        if (id == CODEC_FIELD_RATE_ALPHA ? codec_rd_u16(&r, &out->u.rate_alpha_hz)
                                         : codec_rd_u32(&r, &out->u.rate_beta_hz)) {
            return -1;
        }
        codec_rd_pop(&r);
    }
    return codec_rd_finish(&r);
}

codec_status_t codec_decode_field(uint8_t set, uint8_t descriptor, const uint8_t *data, size_t len,
                                  codec_device_t device, codec_field_value_t *out,
                                  codec_decode_error_t *err) {
    codec_status_t why = CODEC_OK;
    const codec_field_info_t *f = codec_find_field(set, descriptor, &why);
    codec_decode_error_t first;
    bool failed = false;
    size_t i;
    if (!f) {
        return why;
    }
    memset(&first, 0, sizeof first);
    for (i = 0; i < f->layout_count; i++) {
        codec_field_id_t id = (codec_field_id_t)((size_t)f->first_layout + i);
        codec_device_t only = k_layouts[id].device_id;
        if (device != CODEC_DEVICE_ANY && only != CODEC_DEVICE_ANY && only != device) {
            continue;
        }
        if (decode_layout(id, data, len, out, failed ? NULL : &first) == 0) {
            return CODEC_OK;
        }
        failed = true;
    }
    *err = first;
    return CODEC_ERR_DECODE;
}

codec_status_t codec_encode_field(const codec_field_value_t *value, uint8_t *buf, size_t cap,
                                  size_t *len_out) {
    codec_writer_t w;
    codec_status_t st = CODEC_OK;
    codec_writer_init(&w, buf, cap);
    if (value->id == CODEC_FIELD_RATE_ALPHA) {
        st = codec_wr_u16(&w, &value->u.rate_alpha_hz);
    } else if (value->id == CODEC_FIELD_RATE_BETA) {
        st = codec_wr_u32(&w, &value->u.rate_beta_hz);
    } else if (value->id != CODEC_FIELD_PING) {
        st = CODEC_ERR_INVALID;
    }
    *len_out = w.len;
    return st;
}

void codec_value_to_json(codec_jw_t *w, const codec_field_value_t *value) {
    int first = 1;
    codec_jw_lit(w, "{");
    if (value->id == CODEC_FIELD_RATE_ALPHA) {
        codec_jw_key(w, &first, "hz");
        codec_jw_u16(w, &value->u.rate_alpha_hz);
    } else if (value->id == CODEC_FIELD_RATE_BETA) {
        codec_jw_key(w, &first, "hz");
        codec_jw_u32(w, &value->u.rate_beta_hz);
    }
    codec_jw_lit(w, "}");
}

int codec_value_from_json(codec_jr_t *jr, size_t pos, codec_field_id_t id, codec_field_value_t *value) {
    static const char *const k_rate_keys[] = {"hz"};
    size_t vp;
    int rc;
    value->id = id;
    if (id == CODEC_FIELD_PING) {
        return codec_jr_object(jr, pos, NULL, 0);
    }
    if (codec_jr_object(jr, pos, k_rate_keys, 1)) {
        return -1;
    }
    if (codec_jr_get(jr, pos, "hz", &vp) != 1) {
        return codec_jr_fail(jr, "missing \"hz\"");
    }
    codec_jr_push(jr, "hz");
    rc = id == CODEC_FIELD_RATE_ALPHA ? codec_jr_u16(jr, vp, &value->u.rate_alpha_hz)
                                      : codec_jr_u32(jr, vp, &value->u.rate_beta_hz);
    codec_jr_pop(jr);
    return rc;
}
