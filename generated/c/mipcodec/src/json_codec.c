/* Packet <-> canonical JSON line. Generated: do not edit. */
#include "mipcodec/json.h"
#include "mipcodec/field_iter.h"
#include "layouts_internal.h"

#include <assert.h>
#include <stdio.h>
#include <string.h>

size_t mip_json_skip_line(uint64_t offset, const uint8_t *bytes, size_t n, char *out, size_t cap) {
    assert(bytes != NULL || n == 0);
    assert(out != NULL || cap == 0);
    mip_jw_t w;
    mip_jw_init(&w, out, cap);
    mip_jw_lit(&w, "{\"offset\":");
    mip_jw_uint(&w, offset);
    mip_jw_lit(&w, ",\"skipped\":");
    mip_jw_hex(&w, bytes, n);
    mip_jw_lit(&w, "}");
    return mip_jw_finish(&w);
}

static void field_json(mip_jw_t *w, uint8_t set, const mip_field_entry_t *e, mip_device_t device) {
    mip_field_value_t value;
    mip_decode_error_t err;
    mip_status_t st;
    char msg[MIP_ERROR_MESSAGE_MAX];
    size_t n;
    if (e->kind == MIP_ENTRY_TRAILING) {
        n = mip_trailing_format(e, msg, sizeof msg);
        mip_jw_lit(w, "{\"trailing\":");
        mip_jw_hex(w, e->data, e->length);
        mip_jw_lit(w, ",\"error\":");
        mip_jw_string(w, msg, n < sizeof msg ? n : sizeof msg - 1);
        mip_jw_lit(w, "}");
        return;
    }
    mip_jw_lit(w, "{\"descriptor\":");
    mip_jw_uint(w, e->descriptor);
    st = mip_decode_field(set, e->descriptor, e->data, e->length, device, &value, &err);
    if (st == MIP_OK) {
        const mip_layout_info_t *info = mip_layout_info(value.id);
        mip_jw_lit(w, ",\"name\":\"");
        mip_jw_lit(w, info->name);
        mip_jw_lit(w, "\"");
        if (info->device) {
            mip_jw_lit(w, ",\"device\":\"");
            mip_jw_lit(w, info->device);
            mip_jw_lit(w, "\"");
        }
        mip_jw_lit(w, ",\"values\":");
        mip_value_to_json(w, &value);
        mip_jw_lit(w, "}");
        return;
    }
    if (st == MIP_ERR_DECODE) {
        n = mip_decode_error_format(&err, msg, sizeof msg);
        if (n >= sizeof msg) {
            n = sizeof msg - 1;
        }
    } else {
        const char *text = st == MIP_ERR_UNKNOWN_DESCRIPTOR ? "unknown descriptor" : "unknown descriptor set";
        n = strlen(text);
        memcpy(msg, text, n + 1);
    }
    mip_jw_lit(w, ",\"data\":");
    mip_jw_hex(w, e->data, e->length);
    mip_jw_lit(w, ",\"error\":");
    mip_jw_string(w, msg, n);
    mip_jw_lit(w, "}");
}

size_t mip_json_packet_line(const uint8_t *packet, size_t len, uint64_t offset, mip_device_t device,
                            char *out, size_t cap) {
    assert(packet != NULL || len == 0);
    assert(out != NULL || cap == 0);
    mip_jw_t w;
    mip_field_iter_t it;
    mip_field_entry_t e;
    size_t payload = 0;
    size_t i = 0;
    uint8_t set = 0;
    if (len >= MIP_HEADER_SIZE) {
        set = packet[MIP_SET_OFFSET];
        payload = packet[MIP_LENGTH_OFFSET];
        if (payload > len - MIP_HEADER_SIZE) {
            payload = len - MIP_HEADER_SIZE;
        }
    }
    mip_jw_init(&w, out, cap);
    mip_jw_lit(&w, "{\"offset\":");
    mip_jw_uint(&w, offset);
    mip_jw_lit(&w, ",\"set\":");
    mip_jw_uint(&w, set);
    mip_jw_lit(&w, ",\"fields\":[");
    mip_field_iter_init(&it, set, len >= MIP_HEADER_SIZE ? packet + MIP_HEADER_SIZE : NULL, payload);
    while (mip_field_iter_next(&it, &e)) {
        mip_jw_sep(&w, i++);
        field_json(&w, set, &e, device);
    }
    mip_jw_lit(&w, "]}");
    return mip_jw_finish(&w);
}

/* ------------------------------------------------------------------ JSON line -> bytes */

static const char *const k_packet_keys[] = {"offset", "set", "fields"};
static const char *const k_skip_keys[] = {"offset", "skipped"};
static const char *const k_trailing_keys[] = {"trailing", "error"};
static const char *const k_raw_keys[] = {"descriptor", "data", "error"};
static const char *const k_field_keys[] = {"descriptor", "name", "device", "values"};

static int check_offset(mip_jr_t *jr, size_t pos) {
    size_t vp;
    uint64_t offset;
    if (mip_jr_get(jr, pos, "offset", &vp) != 1) {
        return mip_jr_fail(jr, "missing \"offset\"");
    }
    mip_jr_push(jr, "offset");
    if (mip_jr_uint(jr, vp, UINT64_MAX, &offset)) {
        return -1;
    }
    mip_jr_pop(jr);
    return 0;
}

static int check_error_text(mip_jr_t *jr, size_t pos) {
    size_t vp;
    if (mip_jr_get(jr, pos, "error", &vp) != 1) {
        return mip_jr_fail(jr, "missing \"error\"");
    }
    if (!mip_jr_is_string(jr, vp)) {
        mip_jr_push(jr, "error");
        return mip_jr_fail(jr, "expected a string");
    }
    return 0;
}

/* A decoded field: find its layout from descriptor, name and device, then read its values. */
static int decoded_field(mip_jr_t *jr, size_t pos, uint8_t set, uint8_t descriptor,
                         mip_field_value_t *value) {
    mip_status_t why = MIP_ERR_UNKNOWN_SET;
    const mip_field_info_t *f = mip_find_field(set, descriptor, &why);
    mip_field_id_t id;
    size_t vp;
    char text[MIP_NAME_MAX]; /* longest field name or device id, and a NUL */
    size_t i;
    if (!f) {
        return mip_jr_fail(
            jr, "descriptor %u in set %u is not defined (%s); write it as a raw field with \"data\"",
            (unsigned)descriptor, (unsigned)set, mip_status_text(why));
    }
    if (mip_jr_get(jr, pos, "name", &vp) != 1) {
        return mip_jr_fail(jr, "missing \"name\"");
    }
    mip_jr_push(jr, "name");
    if (mip_jr_chars(jr, vp, text, strlen(f->name)) || memcmp(text, f->name, strlen(f->name)) != 0) {
        jr->failed = false;
        return mip_jr_fail(jr, "descriptor %u in set %u is \"%s\"", (unsigned)descriptor, (unsigned)set,
                           f->name);
    }
    mip_jr_pop(jr);
    id = f->first_layout;
    if (mip_jr_get(jr, pos, "device", &vp) == 1) {
        mip_jr_push(jr, "device");
        if (f->layout_count < 2) {
            return mip_jr_fail(jr, "field \"%s\" has no per-device variants", f->name);
        }
        for (i = 0; i < f->layout_count; i++) {
            const char *dev = mip_layout_info((mip_field_id_t)((size_t)f->first_layout + i))->device;
            size_t n = strlen(dev);
            if (mip_jr_chars(jr, vp, text, n) == 0 && memcmp(text, dev, n) == 0) {
                id = (mip_field_id_t)((size_t)f->first_layout + i);
                break;
            }
            jr->failed = false;
        }
        if (i == f->layout_count) {
            return mip_jr_fail(jr, "not a device with a variant of \"%s\"", f->name);
        }
        mip_jr_pop(jr);
    } else if (f->layout_count > 1) {
        return mip_jr_fail(jr, "field \"%s\" has per-device variants: \"device\" is required", f->name);
    }
    if (mip_jr_get(jr, pos, "values", &vp) != 1) {
        return mip_jr_fail(jr, "missing \"values\"");
    }
    mip_jr_push(jr, "values");
    if (mip_value_from_json(jr, vp, id, value)) {
        return -1;
    }
    mip_jr_pop(jr);
    return 0;
}

/* One entry of "fields", appended to the packet. */
static int field_entry(mip_jr_t *jr, size_t pos, uint8_t set, mip_packet_builder_t *b) {
    size_t vp;
    uint8_t data[MIP_MAX_PAYLOAD];
    size_t n = 0;
    uint8_t descriptor = 0;
    mip_status_t st;
    if (mip_jr_get(jr, pos, "trailing", &vp) == 1) {
        if (mip_jr_object(jr, pos, k_trailing_keys, 2) || check_error_text(jr, pos)) {
            return -1;
        }
        mip_jr_push(jr, "trailing");
        if (mip_jr_hex(jr, vp, data, sizeof data, &n)) {
            return -1;
        }
        mip_jr_pop(jr);
        st = mip_packet_add_raw(b, data, n);
    } else {
        int raw = mip_jr_get(jr, pos, "data", &vp) == 1;
        if (mip_jr_object(jr, pos, raw ? k_raw_keys : k_field_keys, raw ? 3 : 4)) {
            return -1;
        }
        if (mip_jr_get(jr, pos, "descriptor", &vp) != 1) {
            return mip_jr_fail(jr, "missing \"descriptor\"");
        }
        mip_jr_push(jr, "descriptor");
        if (mip_jr_u8(jr, vp, &descriptor)) {
            return -1;
        }
        mip_jr_pop(jr);
        if (raw) {
            if (check_error_text(jr, pos)) {
                return -1;
            }
            mip_jr_get(jr, pos, "data", &vp);
            mip_jr_push(jr, "data");
            if (mip_jr_hex(jr, vp, data, MIP_MAX_FIELD_DATA, &n)) {
                return -1;
            }
            mip_jr_pop(jr);
        } else {
            mip_field_value_t value;
            if (decoded_field(jr, pos, set, descriptor, &value)) {
                return -1;
            }
            st = mip_encode_field(&value, data, MIP_MAX_FIELD_DATA, &n);
            if (st == MIP_ERR_BUFFER) {
                return mip_jr_fail(jr, "the values need more than the %d bytes a field can carry",
                                   MIP_MAX_FIELD_DATA);
            }
            if (st != MIP_OK) {
                return mip_jr_fail(jr, "the values cannot be encoded (%s)", mip_status_text(st));
            }
        }
        st = mip_packet_add_field(b, descriptor, data, n);
    }
    if (st == MIP_ERR_TOO_LONG) {
        return mip_jr_fail(jr, "the payload would exceed %d bytes", MIP_MAX_PAYLOAD);
    }
    if (st == MIP_ERR_INVALID) {
        /* a field whose size byte is irregular needs at least -adjust bytes of data */
        return mip_jr_fail(
            jr, "field data of %u bytes is shorter than the minimum %d for descriptor %u of set %u",
            (unsigned)n, -mip_field_length_adjust(set, descriptor), (unsigned)descriptor, (unsigned)set);
    }
    if (st != MIP_OK && st != MIP_ERR_BUFFER) {
        return mip_jr_fail(jr, "%s", mip_status_text(st));
    }
    return st == MIP_OK ? 0 : -1;
}

mip_status_t mip_json_encode_line(const char *line, size_t len, uint8_t *out, size_t cap, size_t *out_len,
                                  char *msg, size_t msg_cap) {
    assert(line != NULL || len == 0);
    assert(out != NULL || cap == 0);
    assert(msg != NULL || msg_cap == 0);
    mip_jr_t jr;
    mip_packet_builder_t b;
    size_t pos;
    size_t vp;
    size_t it;
    size_t ep;
    size_t i;
    uint8_t set;
    mip_status_t st;
    mip_jr_init(&jr, line, len, msg, msg_cap);
    if (out_len) {
        *out_len = 0;
    }
    if (mip_jr_document(&jr, &pos)) {
        return MIP_ERR_JSON;
    }
    if (mip_jr_get(&jr, pos, "skipped", &vp) == 1) {
        size_t n;
        if (mip_jr_object(&jr, pos, k_skip_keys, 2) || check_offset(&jr, pos)) {
            return MIP_ERR_JSON;
        }
        mip_jr_push(&jr, "skipped");
        if (!mip_jr_is_string(&jr, vp)) {
            mip_jr_fail(&jr, "expected a hex string");
            return MIP_ERR_JSON;
        }
        if (mip_jr_hex(&jr, vp, out, cap, &n)) {
            return MIP_ERR_JSON;
        }
        if (out_len) {
            *out_len = n;
        }
        return MIP_OK;
    }
    if (mip_jr_object(&jr, pos, k_packet_keys, 3) || check_offset(&jr, pos)) {
        return MIP_ERR_JSON;
    }
    if (mip_jr_get(&jr, pos, "set", &vp) != 1) {
        mip_jr_fail(&jr, "missing \"set\" (or \"skipped\")");
        return MIP_ERR_JSON;
    }
    mip_jr_push(&jr, "set");
    if (mip_jr_u8(&jr, vp, &set)) {
        return MIP_ERR_JSON;
    }
    mip_jr_pop(&jr);
    if (mip_jr_get(&jr, pos, "fields", &vp) != 1) {
        mip_jr_fail(&jr, "missing \"fields\"");
        return MIP_ERR_JSON;
    }
    mip_jr_push(&jr, "fields");
    if (mip_jr_array(&jr, vp, &it)) {
        return MIP_ERR_JSON;
    }
    mip_packet_begin(&b, out, cap, set);
    for (i = 0;; i++) {
        int more = mip_jr_next(&jr, &it, &ep);
        if (more < 0) {
            return MIP_ERR_JSON;
        }
        if (!more) {
            break;
        }
        mip_jr_index(&jr, i);
        if (field_entry(&jr, ep, set, &b)) {
            if (b.status == MIP_ERR_BUFFER) {
                snprintf(msg, msg_cap, "output buffer too small");
                return MIP_ERR_BUFFER;
            }
            return MIP_ERR_JSON;
        }
    }
    st = mip_packet_finish(&b, out_len);
    if (st == MIP_ERR_BUFFER) {
        if (msg_cap > 0) {
            snprintf(msg, msg_cap, "output buffer too small");
        }
        return st;
    }
    return st == MIP_OK ? MIP_OK : MIP_ERR_JSON;
}
