/* Packet <-> canonical JSON line. Generated: do not edit. */
#include "democodec/json.h"
#include "democodec/field_iter.h"
#include "layouts_internal.h"

#include <assert.h>
#include <stdio.h>
#include <string.h>

size_t democ_json_skip_line(uint64_t offset, const uint8_t *bytes, size_t n, char *out, size_t cap) {
    assert(bytes != NULL || n == 0);
    assert(out != NULL || cap == 0);
    democ_jw_t w;
    democ_jw_init(&w, out, cap);
    democ_jw_lit(&w, "{\"offset\":");
    democ_jw_uint(&w, offset);
    democ_jw_lit(&w, ",\"skipped\":");
    democ_jw_hex(&w, bytes, n);
    democ_jw_lit(&w, "}");
    return democ_jw_finish(&w);
}

static void field_json(democ_jw_t *w, uint8_t set, const democ_field_entry_t *e, democ_device_t device) {
    democ_field_value_t value;
    democ_decode_error_t err;
    democ_status_t st;
    char msg[DEMOC_ERROR_MESSAGE_MAX];
    size_t n;
    if (e->kind == DEMOC_ENTRY_TRAILING) {
        n = democ_trailing_format(e, msg, sizeof msg);
        democ_jw_lit(w, "{\"trailing\":");
        democ_jw_hex(w, e->data, e->length);
        democ_jw_lit(w, ",\"error\":");
        democ_jw_string(w, msg, n < sizeof msg ? n : sizeof msg - 1);
        democ_jw_lit(w, "}");
        return;
    }
    democ_jw_lit(w, "{\"descriptor\":");
    democ_jw_uint(w, e->descriptor);
    st = democ_decode_field(set, e->descriptor, e->data, e->length, device, &value, &err);
    if (st == DEMOC_OK) {
        const democ_layout_info_t *info = democ_layout_info(value.id);
        democ_jw_lit(w, ",\"name\":\"");
        democ_jw_lit(w, info->name);
        democ_jw_lit(w, "\"");
        if (info->device) {
            democ_jw_lit(w, ",\"device\":\"");
            democ_jw_lit(w, info->device);
            democ_jw_lit(w, "\"");
        }
        democ_jw_lit(w, ",\"values\":");
        democ_value_to_json(w, &value);
        democ_jw_lit(w, "}");
        return;
    }
    if (st == DEMOC_ERR_DECODE) {
        n = democ_decode_error_format(&err, msg, sizeof msg);
        if (n >= sizeof msg) {
            n = sizeof msg - 1;
        }
    } else {
        const char *text =
            st == DEMOC_ERR_UNKNOWN_DESCRIPTOR ? "unknown descriptor" : "unknown descriptor set";
        n = strlen(text);
        memcpy(msg, text, n + 1);
    }
    democ_jw_lit(w, ",\"data\":");
    democ_jw_hex(w, e->data, e->length);
    democ_jw_lit(w, ",\"error\":");
    democ_jw_string(w, msg, n);
    democ_jw_lit(w, "}");
}

size_t democ_json_packet_line(const uint8_t *packet, size_t len, uint64_t offset, democ_device_t device,
                              char *out, size_t cap) {
    assert(packet != NULL || len == 0);
    assert(out != NULL || cap == 0);
    democ_jw_t w;
    democ_field_iter_t it;
    democ_field_entry_t e;
    size_t payload = 0;
    size_t i = 0;
    uint8_t set = 0;
    if (len >= DEMOC_HEADER_SIZE) {
        set = packet[DEMOC_SET_OFFSET];
        payload = packet[DEMOC_LENGTH_OFFSET];
        if (payload > len - DEMOC_HEADER_SIZE) {
            payload = len - DEMOC_HEADER_SIZE;
        }
    }
    democ_jw_init(&w, out, cap);
    democ_jw_lit(&w, "{\"offset\":");
    democ_jw_uint(&w, offset);
    democ_jw_lit(&w, ",\"set\":");
    democ_jw_uint(&w, set);
    democ_jw_lit(&w, ",\"fields\":[");
    democ_field_iter_init(&it, set, len >= DEMOC_HEADER_SIZE ? packet + DEMOC_HEADER_SIZE : NULL, payload);
    while (democ_field_iter_next(&it, &e)) {
        democ_jw_sep(&w, i++);
        field_json(&w, set, &e, device);
    }
    democ_jw_lit(&w, "]}");
    return democ_jw_finish(&w);
}

/* ------------------------------------------------------------------ JSON line -> bytes */

static const char *const k_packet_keys[] = {"offset", "set", "fields"};
static const char *const k_skip_keys[] = {"offset", "skipped"};
static const char *const k_trailing_keys[] = {"trailing", "error"};
static const char *const k_raw_keys[] = {"descriptor", "data", "error"};
static const char *const k_field_keys[] = {"descriptor", "name", "device", "values"};

static int check_offset(democ_jr_t *jr, size_t pos) {
    size_t vp;
    uint64_t offset;
    if (democ_jr_get(jr, pos, "offset", &vp) != 1) {
        return democ_jr_fail(jr, "missing \"offset\"");
    }
    democ_jr_push(jr, "offset");
    if (democ_jr_uint(jr, vp, UINT64_MAX, &offset)) {
        return -1;
    }
    democ_jr_pop(jr);
    return 0;
}

static int check_error_text(democ_jr_t *jr, size_t pos) {
    size_t vp;
    if (democ_jr_get(jr, pos, "error", &vp) != 1) {
        return democ_jr_fail(jr, "missing \"error\"");
    }
    if (!democ_jr_is_string(jr, vp)) {
        democ_jr_push(jr, "error");
        return democ_jr_fail(jr, "expected a string");
    }
    return 0;
}

/* A decoded field: find its layout from descriptor, name and device, then read its values. */
static int decoded_field(democ_jr_t *jr, size_t pos, uint8_t set, uint8_t descriptor,
                         democ_field_value_t *value) {
    democ_status_t why = DEMOC_ERR_UNKNOWN_SET;
    const democ_field_info_t *f = democ_find_field(set, descriptor, &why);
    democ_field_id_t id;
    size_t vp;
    char text[DEMOC_NAME_MAX]; /* longest field name or device id, and a NUL */
    size_t i;
    if (!f) {
        return democ_jr_fail(
            jr, "descriptor %u in set %u is not defined (%s); write it as a raw field with \"data\"",
            (unsigned)descriptor, (unsigned)set, democ_status_text(why));
    }
    if (democ_jr_get(jr, pos, "name", &vp) != 1) {
        return democ_jr_fail(jr, "missing \"name\"");
    }
    democ_jr_push(jr, "name");
    if (democ_jr_chars(jr, vp, text, strlen(f->name)) || memcmp(text, f->name, strlen(f->name)) != 0) {
        jr->failed = false;
        return democ_jr_fail(jr, "descriptor %u in set %u is \"%s\"", (unsigned)descriptor, (unsigned)set,
                             f->name);
    }
    democ_jr_pop(jr);
    id = f->first_layout;
    if (democ_jr_get(jr, pos, "device", &vp) == 1) {
        democ_jr_push(jr, "device");
        if (f->layout_count < 2) {
            return democ_jr_fail(jr, "field \"%s\" has no per-device variants", f->name);
        }
        for (i = 0; i < f->layout_count; i++) {
            const char *dev = democ_layout_info((democ_field_id_t)((size_t)f->first_layout + i))->device;
            size_t n = strlen(dev);
            if (democ_jr_chars(jr, vp, text, n) == 0 && memcmp(text, dev, n) == 0) {
                id = (democ_field_id_t)((size_t)f->first_layout + i);
                break;
            }
            jr->failed = false;
        }
        if (i == f->layout_count) {
            return democ_jr_fail(jr, "not a device with a variant of \"%s\"", f->name);
        }
        democ_jr_pop(jr);
    } else if (f->layout_count > 1) {
        return democ_jr_fail(jr, "field \"%s\" has per-device variants: \"device\" is required", f->name);
    }
    if (democ_jr_get(jr, pos, "values", &vp) != 1) {
        return democ_jr_fail(jr, "missing \"values\"");
    }
    democ_jr_push(jr, "values");
    if (democ_value_from_json(jr, vp, id, value)) {
        return -1;
    }
    democ_jr_pop(jr);
    return 0;
}

/* One entry of "fields", appended to the packet. */
static int field_entry(democ_jr_t *jr, size_t pos, uint8_t set, democ_packet_builder_t *b) {
    size_t vp;
    uint8_t data[DEMOC_MAX_PAYLOAD];
    size_t n = 0;
    uint8_t descriptor = 0;
    democ_status_t st;
    if (democ_jr_get(jr, pos, "trailing", &vp) == 1) {
        if (democ_jr_object(jr, pos, k_trailing_keys, 2) || check_error_text(jr, pos)) {
            return -1;
        }
        democ_jr_push(jr, "trailing");
        if (democ_jr_hex(jr, vp, data, sizeof data, &n)) {
            return -1;
        }
        democ_jr_pop(jr);
        st = democ_packet_add_raw(b, data, n);
    } else {
        int raw = democ_jr_get(jr, pos, "data", &vp) == 1;
        if (democ_jr_object(jr, pos, raw ? k_raw_keys : k_field_keys, raw ? 3 : 4)) {
            return -1;
        }
        if (democ_jr_get(jr, pos, "descriptor", &vp) != 1) {
            return democ_jr_fail(jr, "missing \"descriptor\"");
        }
        democ_jr_push(jr, "descriptor");
        if (democ_jr_u8(jr, vp, &descriptor)) {
            return -1;
        }
        democ_jr_pop(jr);
        if (raw) {
            if (check_error_text(jr, pos)) {
                return -1;
            }
            democ_jr_get(jr, pos, "data", &vp);
            democ_jr_push(jr, "data");
            if (democ_jr_hex(jr, vp, data, DEMOC_MAX_FIELD_DATA, &n)) {
                return -1;
            }
            democ_jr_pop(jr);
        } else {
            democ_field_value_t value;
            if (decoded_field(jr, pos, set, descriptor, &value)) {
                return -1;
            }
            st = democ_encode_field(&value, data, DEMOC_MAX_FIELD_DATA, &n);
            if (st == DEMOC_ERR_BUFFER) {
                return democ_jr_fail(jr, "the values need more than the %d bytes a field can carry",
                                     DEMOC_MAX_FIELD_DATA);
            }
            if (st != DEMOC_OK) {
                return democ_jr_fail(jr, "the values cannot be encoded (%s)", democ_status_text(st));
            }
        }
        st = democ_packet_add_field(b, descriptor, data, n);
    }
    if (st == DEMOC_ERR_TOO_LONG) {
        return democ_jr_fail(jr, "the payload would exceed %d bytes", DEMOC_MAX_PAYLOAD);
    }
    if (st == DEMOC_ERR_INVALID) {
        /* a field whose size byte is irregular needs at least -adjust bytes of data */
        return democ_jr_fail(
            jr, "field data of %u bytes is shorter than the minimum %d for descriptor %u of set %u",
            (unsigned)n, -democ_field_length_adjust(set, descriptor), (unsigned)descriptor, (unsigned)set);
    }
    if (st != DEMOC_OK && st != DEMOC_ERR_BUFFER) {
        return democ_jr_fail(jr, "%s", democ_status_text(st));
    }
    return st == DEMOC_OK ? 0 : -1;
}

democ_status_t democ_json_encode_line(const char *line, size_t len, uint8_t *out, size_t cap, size_t *out_len,
                                      char *msg, size_t msg_cap) {
    assert(line != NULL || len == 0);
    assert(out != NULL || cap == 0);
    assert(msg != NULL || msg_cap == 0);
    democ_jr_t jr;
    democ_packet_builder_t b;
    size_t pos;
    size_t vp;
    size_t it;
    size_t ep;
    size_t i;
    uint8_t set;
    democ_status_t st;
    democ_jr_init(&jr, line, len, msg, msg_cap);
    if (out_len) {
        *out_len = 0;
    }
    if (democ_jr_document(&jr, &pos)) {
        return DEMOC_ERR_JSON;
    }
    if (democ_jr_get(&jr, pos, "skipped", &vp) == 1) {
        size_t n;
        if (democ_jr_object(&jr, pos, k_skip_keys, 2) || check_offset(&jr, pos)) {
            return DEMOC_ERR_JSON;
        }
        democ_jr_push(&jr, "skipped");
        if (!democ_jr_is_string(&jr, vp)) {
            democ_jr_fail(&jr, "expected a hex string");
            return DEMOC_ERR_JSON;
        }
        if (democ_jr_hex(&jr, vp, out, cap, &n)) {
            return DEMOC_ERR_JSON;
        }
        if (out_len) {
            *out_len = n;
        }
        return DEMOC_OK;
    }
    if (democ_jr_object(&jr, pos, k_packet_keys, 3) || check_offset(&jr, pos)) {
        return DEMOC_ERR_JSON;
    }
    if (democ_jr_get(&jr, pos, "set", &vp) != 1) {
        democ_jr_fail(&jr, "missing \"set\" (or \"skipped\")");
        return DEMOC_ERR_JSON;
    }
    democ_jr_push(&jr, "set");
    if (democ_jr_u8(&jr, vp, &set)) {
        return DEMOC_ERR_JSON;
    }
    democ_jr_pop(&jr);
    if (democ_jr_get(&jr, pos, "fields", &vp) != 1) {
        democ_jr_fail(&jr, "missing \"fields\"");
        return DEMOC_ERR_JSON;
    }
    democ_jr_push(&jr, "fields");
    if (democ_jr_array(&jr, vp, &it)) {
        return DEMOC_ERR_JSON;
    }
    democ_packet_begin(&b, out, cap, set);
    for (i = 0;; i++) {
        int more = democ_jr_next(&jr, &it, &ep);
        if (more < 0) {
            return DEMOC_ERR_JSON;
        }
        if (!more) {
            break;
        }
        democ_jr_index(&jr, i);
        if (field_entry(&jr, ep, set, &b)) {
            if (b.status == DEMOC_ERR_BUFFER) {
                snprintf(msg, msg_cap, "output buffer too small");
                return DEMOC_ERR_BUFFER;
            }
            return DEMOC_ERR_JSON;
        }
    }
    st = democ_packet_finish(&b, out_len);
    if (st == DEMOC_ERR_BUFFER) {
        if (msg_cap > 0) {
            snprintf(msg, msg_cap, "output buffer too small");
        }
        return st;
    }
    return st == DEMOC_OK ? DEMOC_OK : DEMOC_ERR_JSON;
}

/* ------------------------------------------------------------------ session lines */

size_t democ_json_result_line(const democ_result_t *result, uint64_t line, democ_device_t device, char *out,
                              size_t cap) {
    assert(result != NULL);
    assert(out != NULL || cap == 0);
    democ_jw_t w;
    democ_field_iter_t it;
    democ_field_entry_t e;
    size_t i = 0;
    democ_jw_init(&w, out, cap);
    democ_jw_lit(&w, "{\"line\":");
    democ_jw_uint(&w, line);
    democ_jw_lit(&w, ",\"result\":\"");
    democ_jw_lit(&w, democ_result_kind_name(result->kind));
    democ_jw_lit(&w, "\",\"code\":");
    if (result->has_code) {
        democ_jw_uint(&w, result->code);
    } else {
        democ_jw_lit(&w, "null");
    }
    democ_jw_lit(&w, ",\"reply\":[");
    democ_result_reply_iter(result, &it);
    while (democ_field_iter_next(&it, &e)) {
        democ_jw_sep(&w, i++);
        field_json(&w, result->set, &e, device);
    }
    democ_jw_lit(&w, "]");
    if (result->kind == DEMOC_RESULT_INVALID || result->kind == DEMOC_RESULT_REFUSED ||
        result->kind == DEMOC_RESULT_TRANSPORT) {
        democ_jw_lit(&w, ",\"error\":");
        democ_jw_string(&w, result->error, strlen(result->error));
    }
    democ_jw_lit(&w, "}");
    return democ_jw_finish(&w);
}

democ_status_t democ_json_command_line(const char *line, size_t len, democ_field_value_t *out, char *msg,
                                       size_t msg_cap) {
    assert(line != NULL || len == 0);
    assert(out != NULL);
    assert(msg != NULL || msg_cap == 0);
    static const char *const keys[] = {"offset", "set", "fields"};
    uint8_t packet[DEMOC_MAX_PACKET];
    democ_jr_t jr;
    size_t n = 0;
    size_t pos;
    size_t vp;
    size_t it;
    size_t ep;
    size_t count = 0;
    size_t field = 0;
    uint8_t set;
    uint8_t descriptor;
    democ_status_t st = democ_json_encode_line(line, len, packet, sizeof packet, &n, msg, msg_cap);
    if (st != DEMOC_OK) {
        return DEMOC_ERR_JSON;
    }
    democ_jr_init(&jr, line, len, msg, msg_cap);
    if (democ_jr_document(&jr, &pos)) {
        return DEMOC_ERR_JSON;
    }
    if (democ_jr_get(&jr, pos, "skipped", &vp) == 1) {
        democ_jr_fail(&jr, "expected a packet line with one command field, not a skip run");
        jr.depth = 0;
        return DEMOC_ERR_JSON;
    }
    if (democ_jr_object(&jr, pos, keys, 3) || democ_jr_get(&jr, pos, "set", &vp) != 1 ||
        democ_jr_u8(&jr, vp, &set) || democ_jr_get(&jr, pos, "fields", &vp) != 1 ||
        democ_jr_array(&jr, vp, &it)) {
        return DEMOC_ERR_JSON;
    }
    for (;;) {
        int more = democ_jr_next(&jr, &it, &ep);
        if (more < 0) {
            return DEMOC_ERR_JSON;
        }
        if (!more) {
            break;
        }
        if (count++ == 0) {
            field = ep;
        }
    }
    if (count != 1) {
        if (msg_cap > 0) {
            snprintf(msg, msg_cap, "expected exactly one command field, got %u", (unsigned)count);
        }
        return DEMOC_ERR_JSON;
    }
    if (democ_jr_get(&jr, field, "values", &vp) != 1) {
        if (msg_cap > 0) {
            snprintf(msg, msg_cap,
                     "expected a decoded command field (descriptor, name, values), not a raw field");
        }
        return DEMOC_ERR_JSON;
    }
    if (democ_jr_get(&jr, field, "descriptor", &vp) != 1 || democ_jr_u8(&jr, vp, &descriptor) ||
        decoded_field(&jr, field, set, descriptor, out)) {
        return DEMOC_ERR_JSON;
    }
    return DEMOC_OK;
}
