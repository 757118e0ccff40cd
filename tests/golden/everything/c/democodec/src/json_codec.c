/* Packet <-> canonical JSON line. Generated: do not edit. */
#include "democodec/json.h"
#include "democodec/field_iter.h"
#include "layouts_internal.h"

#include <assert.h>
#include <stdio.h>
#include <string.h>

size_t demo_json_skip_line(uint64_t offset, const uint8_t *bytes, size_t n, char *out, size_t cap) {
    assert(bytes != NULL || n == 0);
    assert(out != NULL || cap == 0);
    demo_jw_t w;
    demo_jw_init(&w, out, cap);
    demo_jw_lit(&w, "{\"offset\":");
    demo_jw_uint(&w, offset);
    demo_jw_lit(&w, ",\"skipped\":");
    demo_jw_hex(&w, bytes, n);
    demo_jw_lit(&w, "}");
    return demo_jw_finish(&w);
}

static void field_json(demo_jw_t *w, uint8_t set, const demo_field_entry_t *e, demo_device_t device) {
    demo_field_value_t value;
    demo_decode_error_t err;
    demo_status_t st;
    char msg[DEMO_ERROR_MESSAGE_MAX];
    size_t n;
    if (e->kind == DEMO_ENTRY_TRAILING) {
        n = demo_trailing_format(e, msg, sizeof msg);
        demo_jw_lit(w, "{\"trailing\":");
        demo_jw_hex(w, e->data, e->length);
        demo_jw_lit(w, ",\"error\":");
        demo_jw_string(w, msg, n < sizeof msg ? n : sizeof msg - 1);
        demo_jw_lit(w, "}");
        return;
    }
    demo_jw_lit(w, "{\"descriptor\":");
    demo_jw_uint(w, e->descriptor);
    st = demo_decode_field(set, e->descriptor, e->data, e->length, device, &value, &err);
    if (st == DEMO_OK) {
        const demo_layout_info_t *info = demo_layout_info(value.id);
        demo_jw_lit(w, ",\"name\":\"");
        demo_jw_lit(w, info->name);
        demo_jw_lit(w, "\"");
        if (info->device) {
            demo_jw_lit(w, ",\"device\":\"");
            demo_jw_lit(w, info->device);
            demo_jw_lit(w, "\"");
        }
        demo_jw_lit(w, ",\"values\":");
        demo_value_to_json(w, &value);
        demo_jw_lit(w, "}");
        return;
    }
    if (st == DEMO_ERR_DECODE) {
        n = demo_decode_error_format(&err, msg, sizeof msg);
        if (n >= sizeof msg) {
            n = sizeof msg - 1;
        }
    } else {
        const char *text =
            st == DEMO_ERR_UNKNOWN_DESCRIPTOR ? "unknown descriptor" : "unknown descriptor set";
        n = strlen(text);
        memcpy(msg, text, n + 1);
    }
    demo_jw_lit(w, ",\"data\":");
    demo_jw_hex(w, e->data, e->length);
    demo_jw_lit(w, ",\"error\":");
    demo_jw_string(w, msg, n);
    demo_jw_lit(w, "}");
}

size_t demo_json_packet_line(const uint8_t *packet, size_t len, uint64_t offset, demo_device_t device,
                             char *out, size_t cap) {
    assert(packet != NULL || len == 0);
    assert(out != NULL || cap == 0);
    demo_jw_t w;
    demo_field_iter_t it;
    demo_field_entry_t e;
    size_t payload = 0;
    size_t i = 0;
    uint8_t set = 0;
    if (len >= DEMO_HEADER_SIZE) {
        set = packet[DEMO_SET_OFFSET];
        payload = packet[DEMO_LENGTH_OFFSET];
        if (payload > len - DEMO_HEADER_SIZE) {
            payload = len - DEMO_HEADER_SIZE;
        }
    }
    demo_jw_init(&w, out, cap);
    demo_jw_lit(&w, "{\"offset\":");
    demo_jw_uint(&w, offset);
    demo_jw_lit(&w, ",\"set\":");
    demo_jw_uint(&w, set);
    demo_jw_lit(&w, ",\"fields\":[");
    demo_field_iter_init(&it, set, len >= DEMO_HEADER_SIZE ? packet + DEMO_HEADER_SIZE : NULL, payload);
    while (demo_field_iter_next(&it, &e)) {
        demo_jw_sep(&w, i++);
        field_json(&w, set, &e, device);
    }
    demo_jw_lit(&w, "]}");
    return demo_jw_finish(&w);
}

/* ------------------------------------------------------------------ JSON line -> bytes */

static const char *const k_packet_keys[] = {"offset", "set", "fields"};
static const char *const k_skip_keys[] = {"offset", "skipped"};
static const char *const k_trailing_keys[] = {"trailing", "error"};
static const char *const k_raw_keys[] = {"descriptor", "data", "error"};
static const char *const k_field_keys[] = {"descriptor", "name", "device", "values"};

static int check_offset(demo_jr_t *jr, size_t pos) {
    size_t vp;
    uint64_t offset;
    if (demo_jr_get(jr, pos, "offset", &vp) != 1) {
        return demo_jr_fail(jr, "missing \"offset\"");
    }
    demo_jr_push(jr, "offset");
    if (demo_jr_uint(jr, vp, UINT64_MAX, &offset)) {
        return -1;
    }
    demo_jr_pop(jr);
    return 0;
}

static int check_error_text(demo_jr_t *jr, size_t pos) {
    size_t vp;
    if (demo_jr_get(jr, pos, "error", &vp) != 1) {
        return demo_jr_fail(jr, "missing \"error\"");
    }
    if (!demo_jr_is_string(jr, vp)) {
        demo_jr_push(jr, "error");
        return demo_jr_fail(jr, "expected a string");
    }
    return 0;
}

/* A decoded field: find its layout from descriptor, name and device, then read its values. */
static int decoded_field(demo_jr_t *jr, size_t pos, uint8_t set, uint8_t descriptor,
                         demo_field_value_t *value) {
    demo_status_t why = DEMO_ERR_UNKNOWN_SET;
    const demo_field_info_t *f = demo_find_field(set, descriptor, &why);
    demo_field_id_t id;
    size_t vp;
    char text[DEMO_NAME_MAX]; /* longest field name or device id, and a NUL */
    size_t i;
    if (!f) {
        return demo_jr_fail(
            jr, "descriptor %u in set %u is not defined (%s); write it as a raw field with \"data\"",
            (unsigned)descriptor, (unsigned)set, demo_status_text(why));
    }
    if (demo_jr_get(jr, pos, "name", &vp) != 1) {
        return demo_jr_fail(jr, "missing \"name\"");
    }
    demo_jr_push(jr, "name");
    if (demo_jr_chars(jr, vp, text, strlen(f->name)) || memcmp(text, f->name, strlen(f->name)) != 0) {
        jr->failed = false;
        return demo_jr_fail(jr, "descriptor %u in set %u is \"%s\"", (unsigned)descriptor, (unsigned)set,
                            f->name);
    }
    demo_jr_pop(jr);
    id = f->first_layout;
    if (demo_jr_get(jr, pos, "device", &vp) == 1) {
        demo_jr_push(jr, "device");
        if (f->layout_count < 2) {
            return demo_jr_fail(jr, "field \"%s\" has no per-device variants", f->name);
        }
        for (i = 0; i < f->layout_count; i++) {
            const char *dev = demo_layout_info((demo_field_id_t)((size_t)f->first_layout + i))->device;
            size_t n = strlen(dev);
            if (demo_jr_chars(jr, vp, text, n) == 0 && memcmp(text, dev, n) == 0) {
                id = (demo_field_id_t)((size_t)f->first_layout + i);
                break;
            }
            jr->failed = false;
        }
        if (i == f->layout_count) {
            return demo_jr_fail(jr, "not a device with a variant of \"%s\"", f->name);
        }
        demo_jr_pop(jr);
    } else if (f->layout_count > 1) {
        return demo_jr_fail(jr, "field \"%s\" has per-device variants: \"device\" is required", f->name);
    }
    if (demo_jr_get(jr, pos, "values", &vp) != 1) {
        return demo_jr_fail(jr, "missing \"values\"");
    }
    demo_jr_push(jr, "values");
    if (demo_value_from_json(jr, vp, id, value)) {
        return -1;
    }
    demo_jr_pop(jr);
    return 0;
}

/* One entry of "fields", appended to the packet. */
static int field_entry(demo_jr_t *jr, size_t pos, uint8_t set, demo_packet_builder_t *b) {
    size_t vp;
    uint8_t data[DEMO_MAX_PAYLOAD];
    size_t n = 0;
    uint8_t descriptor = 0;
    demo_status_t st;
    if (demo_jr_get(jr, pos, "trailing", &vp) == 1) {
        if (demo_jr_object(jr, pos, k_trailing_keys, 2) || check_error_text(jr, pos)) {
            return -1;
        }
        demo_jr_push(jr, "trailing");
        if (demo_jr_hex(jr, vp, data, sizeof data, &n)) {
            return -1;
        }
        demo_jr_pop(jr);
        st = demo_packet_add_raw(b, data, n);
    } else {
        int raw = demo_jr_get(jr, pos, "data", &vp) == 1;
        if (demo_jr_object(jr, pos, raw ? k_raw_keys : k_field_keys, raw ? 3 : 4)) {
            return -1;
        }
        if (demo_jr_get(jr, pos, "descriptor", &vp) != 1) {
            return demo_jr_fail(jr, "missing \"descriptor\"");
        }
        demo_jr_push(jr, "descriptor");
        if (demo_jr_u8(jr, vp, &descriptor)) {
            return -1;
        }
        demo_jr_pop(jr);
        if (raw) {
            if (check_error_text(jr, pos)) {
                return -1;
            }
            demo_jr_get(jr, pos, "data", &vp);
            demo_jr_push(jr, "data");
            if (demo_jr_hex(jr, vp, data, DEMO_MAX_FIELD_DATA, &n)) {
                return -1;
            }
            demo_jr_pop(jr);
        } else {
            demo_field_value_t value;
            if (decoded_field(jr, pos, set, descriptor, &value)) {
                return -1;
            }
            st = demo_encode_field(&value, data, DEMO_MAX_FIELD_DATA, &n);
            if (st == DEMO_ERR_BUFFER) {
                return demo_jr_fail(jr, "the values need more than the %d bytes a field can carry",
                                    DEMO_MAX_FIELD_DATA);
            }
            if (st != DEMO_OK) {
                return demo_jr_fail(jr, "the values cannot be encoded (%s)", demo_status_text(st));
            }
        }
        st = demo_packet_add_field(b, descriptor, data, n);
    }
    if (st == DEMO_ERR_TOO_LONG) {
        return demo_jr_fail(jr, "the payload would exceed %d bytes", DEMO_MAX_PAYLOAD);
    }
    if (st == DEMO_ERR_INVALID) {
        /* a field whose size byte is irregular needs at least -adjust bytes of data */
        return demo_jr_fail(
            jr, "field data of %u bytes is shorter than the minimum %d for descriptor %u of set %u",
            (unsigned)n, -demo_field_length_adjust(set, descriptor), (unsigned)descriptor, (unsigned)set);
    }
    if (st != DEMO_OK && st != DEMO_ERR_BUFFER) {
        return demo_jr_fail(jr, "%s", demo_status_text(st));
    }
    return st == DEMO_OK ? 0 : -1;
}

demo_status_t demo_json_encode_line(const char *line, size_t len, uint8_t *out, size_t cap, size_t *out_len,
                                    char *msg, size_t msg_cap) {
    assert(line != NULL || len == 0);
    assert(out != NULL || cap == 0);
    assert(msg != NULL || msg_cap == 0);
    demo_jr_t jr;
    demo_packet_builder_t b;
    size_t pos;
    size_t vp;
    size_t it;
    size_t ep;
    size_t i;
    uint8_t set;
    demo_status_t st;
    demo_jr_init(&jr, line, len, msg, msg_cap);
    if (out_len) {
        *out_len = 0;
    }
    if (demo_jr_document(&jr, &pos)) {
        return DEMO_ERR_JSON;
    }
    if (demo_jr_get(&jr, pos, "skipped", &vp) == 1) {
        size_t n;
        if (demo_jr_object(&jr, pos, k_skip_keys, 2) || check_offset(&jr, pos)) {
            return DEMO_ERR_JSON;
        }
        demo_jr_push(&jr, "skipped");
        if (!demo_jr_is_string(&jr, vp)) {
            demo_jr_fail(&jr, "expected a hex string");
            return DEMO_ERR_JSON;
        }
        if (demo_jr_hex(&jr, vp, out, cap, &n)) {
            return DEMO_ERR_JSON;
        }
        if (out_len) {
            *out_len = n;
        }
        return DEMO_OK;
    }
    if (demo_jr_object(&jr, pos, k_packet_keys, 3) || check_offset(&jr, pos)) {
        return DEMO_ERR_JSON;
    }
    if (demo_jr_get(&jr, pos, "set", &vp) != 1) {
        demo_jr_fail(&jr, "missing \"set\" (or \"skipped\")");
        return DEMO_ERR_JSON;
    }
    demo_jr_push(&jr, "set");
    if (demo_jr_u8(&jr, vp, &set)) {
        return DEMO_ERR_JSON;
    }
    demo_jr_pop(&jr);
    if (demo_jr_get(&jr, pos, "fields", &vp) != 1) {
        demo_jr_fail(&jr, "missing \"fields\"");
        return DEMO_ERR_JSON;
    }
    demo_jr_push(&jr, "fields");
    if (demo_jr_array(&jr, vp, &it)) {
        return DEMO_ERR_JSON;
    }
    demo_packet_begin(&b, out, cap, set);
    for (i = 0;; i++) {
        int more = demo_jr_next(&jr, &it, &ep);
        if (more < 0) {
            return DEMO_ERR_JSON;
        }
        if (!more) {
            break;
        }
        demo_jr_index(&jr, i);
        if (field_entry(&jr, ep, set, &b)) {
            if (b.status == DEMO_ERR_BUFFER) {
                snprintf(msg, msg_cap, "output buffer too small");
                return DEMO_ERR_BUFFER;
            }
            return DEMO_ERR_JSON;
        }
    }
    st = demo_packet_finish(&b, out_len);
    if (st == DEMO_ERR_BUFFER) {
        if (msg_cap > 0) {
            snprintf(msg, msg_cap, "output buffer too small");
        }
        return st;
    }
    return st == DEMO_OK ? DEMO_OK : DEMO_ERR_JSON;
}
