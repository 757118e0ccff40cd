/* Packet <-> canonical JSON line. Generated: do not edit. */
#include "mscipcodec/json.h"
#include "mscipcodec/field_iter.h"
#include "layouts_internal.h"

#include <assert.h>
#include <stdio.h>
#include <string.h>

size_t mscip_json_skip_line(uint64_t offset, const uint8_t *bytes, size_t n, char *out, size_t cap) {
    assert(bytes != NULL || n == 0);
    assert(out != NULL || cap == 0);
    mscip_jw_t w;
    mscip_jw_init(&w, out, cap);
    mscip_jw_lit(&w, "{\"offset\":");
    mscip_jw_uint(&w, offset);
    mscip_jw_lit(&w, ",\"skipped\":");
    mscip_jw_hex(&w, bytes, n);
    mscip_jw_lit(&w, "}");
    return mscip_jw_finish(&w);
}

static void field_json(mscip_jw_t *w, uint8_t set, const mscip_field_entry_t *e, mscip_device_t device) {
    mscip_field_value_t value;
    mscip_decode_error_t err;
    mscip_status_t st;
    char msg[MSCIP_ERROR_MESSAGE_MAX];
    size_t n;
    if (e->kind == MSCIP_ENTRY_TRAILING) {
        n = mscip_trailing_format(e, msg, sizeof msg);
        mscip_jw_lit(w, "{\"trailing\":");
        mscip_jw_hex(w, e->data, e->length);
        mscip_jw_lit(w, ",\"error\":");
        mscip_jw_string(w, msg, n < sizeof msg ? n : sizeof msg - 1);
        mscip_jw_lit(w, "}");
        return;
    }
    mscip_jw_lit(w, "{\"descriptor\":");
    mscip_jw_uint(w, e->descriptor);
    st = mscip_decode_field(set, e->descriptor, e->data, e->length, device, &value, &err);
    if (st == MSCIP_OK) {
        const mscip_layout_info_t *info = mscip_layout_info(value.id);
        mscip_jw_lit(w, ",\"name\":\"");
        mscip_jw_lit(w, info->name);
        mscip_jw_lit(w, "\"");
        if (info->device) {
            mscip_jw_lit(w, ",\"device\":\"");
            mscip_jw_lit(w, info->device);
            mscip_jw_lit(w, "\"");
        }
        mscip_jw_lit(w, ",\"values\":");
        mscip_value_to_json(w, &value);
        mscip_jw_lit(w, "}");
        return;
    }
    if (st == MSCIP_ERR_DECODE) {
        n = mscip_decode_error_format(&err, msg, sizeof msg);
        if (n >= sizeof msg) {
            n = sizeof msg - 1;
        }
    } else {
        const char *text =
            st == MSCIP_ERR_UNKNOWN_DESCRIPTOR ? "unknown descriptor" : "unknown descriptor set";
        n = strlen(text);
        memcpy(msg, text, n + 1);
    }
    mscip_jw_lit(w, ",\"data\":");
    mscip_jw_hex(w, e->data, e->length);
    mscip_jw_lit(w, ",\"error\":");
    mscip_jw_string(w, msg, n);
    mscip_jw_lit(w, "}");
}

size_t mscip_json_packet_line(const uint8_t *packet, size_t len, uint64_t offset, mscip_device_t device,
                              char *out, size_t cap) {
    assert(packet != NULL || len == 0);
    assert(out != NULL || cap == 0);
    mscip_jw_t w;
    mscip_field_iter_t it;
    mscip_field_entry_t e;
    size_t payload = 0;
    size_t i = 0;
    uint8_t set = 0;
    if (len >= MSCIP_HEADER_SIZE) {
        set = packet[MSCIP_SET_OFFSET];
        payload = packet[MSCIP_LENGTH_OFFSET];
        if (payload > len - MSCIP_HEADER_SIZE) {
            payload = len - MSCIP_HEADER_SIZE;
        }
    }
    mscip_jw_init(&w, out, cap);
    mscip_jw_lit(&w, "{\"offset\":");
    mscip_jw_uint(&w, offset);
    mscip_jw_lit(&w, ",\"set\":");
    mscip_jw_uint(&w, set);
    mscip_jw_lit(&w, ",\"fields\":[");
    mscip_field_iter_init(&it, set, len >= MSCIP_HEADER_SIZE ? packet + MSCIP_HEADER_SIZE : NULL, payload);
    while (mscip_field_iter_next(&it, &e)) {
        mscip_jw_sep(&w, i++);
        field_json(&w, set, &e, device);
    }
    mscip_jw_lit(&w, "]}");
    return mscip_jw_finish(&w);
}

/* ------------------------------------------------------------------ JSON line -> bytes */

static const char *const k_packet_keys[] = {"offset", "set", "fields"};
static const char *const k_skip_keys[] = {"offset", "skipped"};
static const char *const k_trailing_keys[] = {"trailing", "error"};
static const char *const k_raw_keys[] = {"descriptor", "data", "error"};
static const char *const k_field_keys[] = {"descriptor", "name", "device", "values"};

static int check_offset(mscip_jr_t *jr, size_t pos) {
    size_t vp;
    uint64_t offset;
    if (mscip_jr_get(jr, pos, "offset", &vp) != 1) {
        return mscip_jr_fail(jr, "missing \"offset\"");
    }
    mscip_jr_push(jr, "offset");
    if (mscip_jr_uint(jr, vp, UINT64_MAX, &offset)) {
        return -1;
    }
    mscip_jr_pop(jr);
    return 0;
}

static int check_error_text(mscip_jr_t *jr, size_t pos) {
    size_t vp;
    if (mscip_jr_get(jr, pos, "error", &vp) != 1) {
        return mscip_jr_fail(jr, "missing \"error\"");
    }
    if (!mscip_jr_is_string(jr, vp)) {
        mscip_jr_push(jr, "error");
        return mscip_jr_fail(jr, "expected a string");
    }
    return 0;
}

/* A decoded field: find its layout from descriptor, name and device, then read its values. */
static int decoded_field(mscip_jr_t *jr, size_t pos, uint8_t set, uint8_t descriptor,
                         mscip_field_value_t *value) {
    mscip_status_t why = MSCIP_ERR_UNKNOWN_SET;
    const mscip_field_info_t *f = mscip_find_field(set, descriptor, &why);
    mscip_field_id_t id;
    size_t vp;
    char text[MSCIP_NAME_MAX]; /* longest field name or device id, and a NUL */
    size_t i;
    if (!f) {
        return mscip_jr_fail(
            jr, "descriptor %u in set %u is not defined (%s); write it as a raw field with \"data\"",
            (unsigned)descriptor, (unsigned)set, mscip_status_text(why));
    }
    if (mscip_jr_get(jr, pos, "name", &vp) != 1) {
        return mscip_jr_fail(jr, "missing \"name\"");
    }
    mscip_jr_push(jr, "name");
    if (mscip_jr_chars(jr, vp, text, strlen(f->name)) || memcmp(text, f->name, strlen(f->name)) != 0) {
        jr->failed = false;
        return mscip_jr_fail(jr, "descriptor %u in set %u is \"%s\"", (unsigned)descriptor, (unsigned)set,
                             f->name);
    }
    mscip_jr_pop(jr);
    id = f->first_layout;
    if (mscip_jr_get(jr, pos, "device", &vp) == 1) {
        mscip_jr_push(jr, "device");
        if (f->layout_count < 2) {
            return mscip_jr_fail(jr, "field \"%s\" has no per-device variants", f->name);
        }
        for (i = 0; i < f->layout_count; i++) {
            const char *dev = mscip_layout_info((mscip_field_id_t)((size_t)f->first_layout + i))->device;
            size_t n = strlen(dev);
            if (mscip_jr_chars(jr, vp, text, n) == 0 && memcmp(text, dev, n) == 0) {
                id = (mscip_field_id_t)((size_t)f->first_layout + i);
                break;
            }
            jr->failed = false;
        }
        if (i == f->layout_count) {
            return mscip_jr_fail(jr, "not a device with a variant of \"%s\"", f->name);
        }
        mscip_jr_pop(jr);
    } else if (f->layout_count > 1) {
        return mscip_jr_fail(jr, "field \"%s\" has per-device variants: \"device\" is required", f->name);
    }
    if (mscip_jr_get(jr, pos, "values", &vp) != 1) {
        return mscip_jr_fail(jr, "missing \"values\"");
    }
    mscip_jr_push(jr, "values");
    if (mscip_value_from_json(jr, vp, id, value)) {
        return -1;
    }
    mscip_jr_pop(jr);
    return 0;
}

/* One entry of "fields", appended to the packet. */
static int field_entry(mscip_jr_t *jr, size_t pos, uint8_t set, mscip_packet_builder_t *b) {
    size_t vp;
    uint8_t data[MSCIP_MAX_PAYLOAD];
    size_t n = 0;
    uint8_t descriptor = 0;
    mscip_status_t st;
    if (mscip_jr_get(jr, pos, "trailing", &vp) == 1) {
        if (mscip_jr_object(jr, pos, k_trailing_keys, 2) || check_error_text(jr, pos)) {
            return -1;
        }
        mscip_jr_push(jr, "trailing");
        if (mscip_jr_hex(jr, vp, data, sizeof data, &n)) {
            return -1;
        }
        mscip_jr_pop(jr);
        st = mscip_packet_add_raw(b, data, n);
    } else {
        int raw = mscip_jr_get(jr, pos, "data", &vp) == 1;
        if (mscip_jr_object(jr, pos, raw ? k_raw_keys : k_field_keys, raw ? 3 : 4)) {
            return -1;
        }
        if (mscip_jr_get(jr, pos, "descriptor", &vp) != 1) {
            return mscip_jr_fail(jr, "missing \"descriptor\"");
        }
        mscip_jr_push(jr, "descriptor");
        if (mscip_jr_u8(jr, vp, &descriptor)) {
            return -1;
        }
        mscip_jr_pop(jr);
        if (raw) {
            if (check_error_text(jr, pos)) {
                return -1;
            }
            mscip_jr_get(jr, pos, "data", &vp);
            mscip_jr_push(jr, "data");
            if (mscip_jr_hex(jr, vp, data, MSCIP_MAX_FIELD_DATA, &n)) {
                return -1;
            }
            mscip_jr_pop(jr);
        } else {
            mscip_field_value_t value;
            if (decoded_field(jr, pos, set, descriptor, &value)) {
                return -1;
            }
            st = mscip_encode_field(&value, data, MSCIP_MAX_FIELD_DATA, &n);
            if (st == MSCIP_ERR_BUFFER) {
                return mscip_jr_fail(jr, "the values need more than the %d bytes a field can carry",
                                     MSCIP_MAX_FIELD_DATA);
            }
            if (st != MSCIP_OK) {
                return mscip_jr_fail(jr, "the values cannot be encoded (%s)", mscip_status_text(st));
            }
        }
        st = mscip_packet_add_field(b, descriptor, data, n);
    }
    if (st == MSCIP_ERR_TOO_LONG) {
        return mscip_jr_fail(jr, "the payload would exceed %d bytes", MSCIP_MAX_PAYLOAD);
    }
    if (st == MSCIP_ERR_INVALID) {
        /* a field whose size byte is irregular needs at least -adjust bytes of data */
        return mscip_jr_fail(
            jr, "field data of %u bytes is shorter than the minimum %d for descriptor %u of set %u",
            (unsigned)n, -mscip_field_length_adjust(set, descriptor), (unsigned)descriptor, (unsigned)set);
    }
    if (st != MSCIP_OK && st != MSCIP_ERR_BUFFER) {
        return mscip_jr_fail(jr, "%s", mscip_status_text(st));
    }
    return st == MSCIP_OK ? 0 : -1;
}

mscip_status_t mscip_json_encode_line(const char *line, size_t len, uint8_t *out, size_t cap, size_t *out_len,
                                      char *msg, size_t msg_cap) {
    assert(line != NULL || len == 0);
    assert(out != NULL || cap == 0);
    assert(msg != NULL || msg_cap == 0);
    mscip_jr_t jr;
    mscip_packet_builder_t b;
    size_t pos;
    size_t vp;
    size_t it;
    size_t ep;
    size_t i;
    uint8_t set;
    mscip_status_t st;
    mscip_jr_init(&jr, line, len, msg, msg_cap);
    if (out_len) {
        *out_len = 0;
    }
    if (mscip_jr_document(&jr, &pos)) {
        return MSCIP_ERR_JSON;
    }
    if (mscip_jr_get(&jr, pos, "skipped", &vp) == 1) {
        size_t n;
        if (mscip_jr_object(&jr, pos, k_skip_keys, 2) || check_offset(&jr, pos)) {
            return MSCIP_ERR_JSON;
        }
        mscip_jr_push(&jr, "skipped");
        if (!mscip_jr_is_string(&jr, vp)) {
            mscip_jr_fail(&jr, "expected a hex string");
            return MSCIP_ERR_JSON;
        }
        if (mscip_jr_hex(&jr, vp, out, cap, &n)) {
            return MSCIP_ERR_JSON;
        }
        if (out_len) {
            *out_len = n;
        }
        return MSCIP_OK;
    }
    if (mscip_jr_object(&jr, pos, k_packet_keys, 3) || check_offset(&jr, pos)) {
        return MSCIP_ERR_JSON;
    }
    if (mscip_jr_get(&jr, pos, "set", &vp) != 1) {
        mscip_jr_fail(&jr, "missing \"set\" (or \"skipped\")");
        return MSCIP_ERR_JSON;
    }
    mscip_jr_push(&jr, "set");
    if (mscip_jr_u8(&jr, vp, &set)) {
        return MSCIP_ERR_JSON;
    }
    mscip_jr_pop(&jr);
    if (mscip_jr_get(&jr, pos, "fields", &vp) != 1) {
        mscip_jr_fail(&jr, "missing \"fields\"");
        return MSCIP_ERR_JSON;
    }
    mscip_jr_push(&jr, "fields");
    if (mscip_jr_array(&jr, vp, &it)) {
        return MSCIP_ERR_JSON;
    }
    mscip_packet_begin(&b, out, cap, set);
    for (i = 0;; i++) {
        int more = mscip_jr_next(&jr, &it, &ep);
        if (more < 0) {
            return MSCIP_ERR_JSON;
        }
        if (!more) {
            break;
        }
        mscip_jr_index(&jr, i);
        if (field_entry(&jr, ep, set, &b)) {
            if (b.status == MSCIP_ERR_BUFFER) {
                snprintf(msg, msg_cap, "output buffer too small");
                return MSCIP_ERR_BUFFER;
            }
            return MSCIP_ERR_JSON;
        }
    }
    st = mscip_packet_finish(&b, out_len);
    if (st == MSCIP_ERR_BUFFER) {
        if (msg_cap > 0) {
            snprintf(msg, msg_cap, "output buffer too small");
        }
        return st;
    }
    return st == MSCIP_OK ? MSCIP_OK : MSCIP_ERR_JSON;
}
