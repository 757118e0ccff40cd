/* Packet <-> canonical JSON line. Generated: do not edit. */
#include "mipcodec/json.h"
#include "mipcodec/field_iter.h"
#include "layouts_internal.h"

#include <assert.h>
#include <stdio.h>
#include <string.h>

/* The line of a foreign frame into out (cap bytes); returns its full length: an NMEA sentence
 * without its CR LF ('"' and '\\' escaped: the rest is printable ASCII), an RTCM3 frame's message
 * number and payload length (docs/conformance.md section 5). */
size_t mipc_json_foreign_line(const mipc_event_t *ev, char *out, size_t cap) {
    char head[96];
    size_t n;
    size_t i;
    if (ev->kind == MIPC_EVENT_RTCM) {
        int k = snprintf(head, sizeof head, "{\"offset\":%llu,\"rtcm\":%u,\"length\":%llu}",
                         (unsigned long long)ev->offset, mipc_rtcm_type(ev->packet),
                         (unsigned long long)(ev->length - 6));
        n = (size_t)k;
        if (n < cap) {
            memcpy(out, head, n + 1);
        }
        return n;
    }
    n = (size_t)snprintf(head, sizeof head, "{\"offset\":%llu,\"nmea\":\"", (unsigned long long)ev->offset);
    if (n < cap) {
        memcpy(out, head, n);
    }
    for (i = 0; i + 2 < ev->length; i++) {
        const char c = (char)ev->packet[i];
        if (c == '"' || c == '\\') {
            if (n < cap) {
                out[n] = '\\';
            }
            n++;
        }
        if (n < cap) {
            out[n] = c;
        }
        n++;
    }
    if (n + 2 < cap) {
        out[n] = '"';
        out[n + 1] = '}';
        out[n + 2] = '\0';
    }
    return n + 2;
}

size_t mipc_json_skip_line(uint64_t offset, const uint8_t *bytes, size_t n, char *out, size_t cap) {
    assert(bytes != NULL || n == 0);
    assert(out != NULL || cap == 0);
    mipc_jw_t w;
    mipc_jw_init(&w, out, cap);
    mipc_jw_lit(&w, "{\"offset\":");
    mipc_jw_uint(&w, offset);
    mipc_jw_lit(&w, ",\"skipped\":");
    mipc_jw_hex(&w, bytes, n);
    mipc_jw_lit(&w, "}");
    return mipc_jw_finish(&w);
}

static void field_json(mipc_jw_t *w, uint8_t set, const mipc_field_entry_t *e, mipc_device_t device) {
    mipc_field_value_t value;
    mipc_decode_error_t err;
    mipc_status_t st;
    char msg[MIPC_ERROR_MESSAGE_MAX];
    size_t n;
    if (e->kind == MIPC_ENTRY_TRAILING) {
        n = mipc_trailing_format(e, msg, sizeof msg);
        mipc_jw_lit(w, "{\"trailing\":");
        mipc_jw_hex(w, e->data, e->length);
        mipc_jw_lit(w, ",\"error\":");
        mipc_jw_string(w, msg, n < sizeof msg ? n : sizeof msg - 1);
        mipc_jw_lit(w, "}");
        return;
    }
    mipc_jw_lit(w, "{\"descriptor\":");
    mipc_jw_uint(w, e->descriptor);
    st = mipc_decode_field(set, e->descriptor, e->data, e->length, device, &value, &err);
    if (st == MIPC_OK) {
        const mipc_layout_info_t *info = mipc_layout_info(value.id);
        mipc_jw_lit(w, ",\"name\":\"");
        mipc_jw_lit(w, info->name);
        mipc_jw_lit(w, "\"");
        if (info->device) {
            mipc_jw_lit(w, ",\"device\":\"");
            mipc_jw_lit(w, info->device);
            mipc_jw_lit(w, "\"");
        }
        mipc_jw_lit(w, ",\"values\":");
        mipc_value_to_json(w, &value);
        mipc_jw_lit(w, "}");
        return;
    }
    if (st == MIPC_ERR_DECODE) {
        n = mipc_decode_error_format(&err, msg, sizeof msg);
        if (n >= sizeof msg) {
            n = sizeof msg - 1;
        }
    } else {
        const char *text =
            st == MIPC_ERR_UNKNOWN_DESCRIPTOR ? "unknown descriptor" : "unknown descriptor set";
        n = strlen(text);
        memcpy(msg, text, n + 1);
    }
    mipc_jw_lit(w, ",\"data\":");
    mipc_jw_hex(w, e->data, e->length);
    mipc_jw_lit(w, ",\"error\":");
    mipc_jw_string(w, msg, n);
    mipc_jw_lit(w, "}");
}

/* The start of a packet's line, `{"offset":N,"set":S,"fields":[`, written to w (over out, cap),
 * and the iterator over the packet's fields (its payload as far as len holds it); the set. */
static uint8_t packet_line_head(mipc_jw_t *w, mipc_field_iter_t *it, const uint8_t *packet, size_t len,
                                uint64_t offset, char *out, size_t cap) {
    size_t payload = 0;
    uint8_t set = 0;
    if (len >= MIPC_HEADER_SIZE) {
        set = packet[MIPC_SET_OFFSET];
        payload = packet[MIPC_LENGTH_OFFSET];
        if (payload > len - MIPC_HEADER_SIZE) {
            payload = len - MIPC_HEADER_SIZE;
        }
    }
    mipc_jw_init(w, out, cap);
    mipc_jw_lit(w, "{\"offset\":");
    mipc_jw_uint(w, offset);
    mipc_jw_lit(w, ",\"set\":");
    mipc_jw_uint(w, set);
    mipc_jw_lit(w, ",\"fields\":[");
    mipc_field_iter_init(it, set, len >= MIPC_HEADER_SIZE ? packet + MIPC_HEADER_SIZE : NULL, payload);
    return set;
}

size_t mipc_json_packet_line(const uint8_t *packet, size_t len, uint64_t offset, mipc_device_t device,
                             char *out, size_t cap) {
    assert(packet != NULL || len == 0);
    assert(out != NULL || cap == 0);
    mipc_jw_t w;
    mipc_field_iter_t it;
    mipc_field_entry_t e;
    size_t i = 0;
    const uint8_t set = packet_line_head(&w, &it, packet, len, offset, out, cap);
    while (mipc_field_iter_next(&it, &e)) {
        mipc_jw_sep(&w, i++);
        field_json(&w, set, &e, device);
    }
    mipc_jw_lit(&w, "]}");
    return mipc_jw_finish(&w);
}

/* The object of the i-th field a straight-line decoder decoded (set's field with a single layout),
 * written from its typed member with the writer the general path uses. */
static void member_json(mipc_jw_t *w, uint8_t set, const mipc_packet_index_t *index, size_t i) {
    const uint8_t descriptor = index->fields[i].descriptor;
    mipc_status_t why = MIPC_ERR_UNKNOWN_SET;
    const mipc_field_info_t *f = mipc_find_field(set, descriptor, &why);
    const mipc_layout_info_t *info;
    mipc_jw_lit(w, "{\"descriptor\":");
    mipc_jw_uint(w, descriptor);
    if (!f) {
        mipc_jw_lit(w, ",\"error\":\"no field for a decoded member\"}"); /* never: a member is a field */
        return;
    }
    info = mipc_layout_info(f->first_layout);
    mipc_jw_lit(w, ",\"name\":\"");
    mipc_jw_lit(w, info->name);
    mipc_jw_lit(w, "\"");
    if (info->device) {
        mipc_jw_lit(w, ",\"device\":\"");
        mipc_jw_lit(w, info->device);
        mipc_jw_lit(w, "\"");
    }
    mipc_jw_lit(w, ",\"values\":");
    mipc_layout_to_json(w, f->first_layout, mipc_packet_value(index, i));
    mipc_jw_lit(w, "}");
}

size_t mipc_json_decoded_packet_line(const uint8_t *packet, size_t len, uint64_t offset, mipc_device_t device,
                                     const mipc_packet_index_t *index, const mipc_field_entry_t *others,
                                     size_t other_count, char *out, size_t cap) {
    assert(packet != NULL || len == 0);
    assert(others != NULL || other_count == 0);
    assert(out != NULL || cap == 0);
    mipc_jw_t w;
    mipc_field_iter_t it;
    mipc_field_entry_t e;
    size_t i = 0;
    size_t decoded = 0;
    size_t passed = 0;
    /* The entries in packet order (the walk only places them): each is the next entry passed on
     * when it starts where that one does, else the next decoded field, which must have its
     * descriptor. */
    const uint8_t set = packet_line_head(&w, &it, packet, len, offset, out, cap);
    while (mipc_field_iter_next(&it, &e)) {
        mipc_jw_sep(&w, i++);
        if (passed < other_count && others[passed].offset == e.offset && others[passed].kind == e.kind) {
            field_json(&w, set, &others[passed++], device);
        } else if (e.kind == MIPC_ENTRY_FIELD && index != NULL && decoded < index->count &&
                   index->fields[decoded].descriptor == e.descriptor) {
            member_json(&w, set, index, decoded++);
        } else {
            return 0;
        }
    }
    if (passed != other_count || decoded != (index != NULL ? index->count : 0)) {
        return 0;
    }
    mipc_jw_lit(&w, "]}");
    return mipc_jw_finish(&w);
}

/* ------------------------------------------------------------------ JSON line -> bytes */

static const char *const k_packet_keys[] = {"offset", "set", "fields"};
static const char *const k_skip_keys[] = {"offset", "skipped"};
static const char *const k_trailing_keys[] = {"trailing", "error"};
static const char *const k_raw_keys[] = {"descriptor", "data", "error"};
static const char *const k_field_keys[] = {"descriptor", "name", "device", "values"};

static int check_offset(mipc_jr_t *jr, size_t pos) {
    size_t vp;
    uint64_t offset;
    if (mipc_jr_get(jr, pos, "offset", &vp) != 1) {
        return mipc_jr_fail(jr, "missing \"offset\"");
    }
    mipc_jr_push(jr, "offset");
    if (mipc_jr_uint(jr, vp, UINT64_MAX, &offset)) {
        return -1;
    }
    mipc_jr_pop(jr);
    return 0;
}

static int check_error_text(mipc_jr_t *jr, size_t pos) {
    size_t vp;
    if (mipc_jr_get(jr, pos, "error", &vp) != 1) {
        return mipc_jr_fail(jr, "missing \"error\"");
    }
    if (!mipc_jr_is_string(jr, vp)) {
        mipc_jr_push(jr, "error");
        return mipc_jr_fail(jr, "expected a string");
    }
    return 0;
}

/* A decoded field: find its layout from descriptor, name and device, then read its values. */
static int decoded_field(mipc_jr_t *jr, size_t pos, uint8_t set, uint8_t descriptor,
                         mipc_field_value_t *value) {
    mipc_status_t why = MIPC_ERR_UNKNOWN_SET;
    const mipc_field_info_t *f = mipc_find_field(set, descriptor, &why);
    mipc_field_id_t id;
    size_t vp;
    char text[MIPC_NAME_MAX]; /* longest field name or device id, and a NUL */
    size_t i;
    if (!f) {
        return mipc_jr_fail(
            jr, "descriptor %u in set %u is not defined (%s); write it as a raw field with \"data\"",
            (unsigned)descriptor, (unsigned)set, mipc_status_text(why));
    }
    if (mipc_jr_get(jr, pos, "name", &vp) != 1) {
        return mipc_jr_fail(jr, "missing \"name\"");
    }
    mipc_jr_push(jr, "name");
    if (mipc_jr_chars(jr, vp, text, strlen(f->name)) || memcmp(text, f->name, strlen(f->name)) != 0) {
        jr->failed = false;
        return mipc_jr_fail(jr, "descriptor %u in set %u is \"%s\"", (unsigned)descriptor, (unsigned)set,
                            f->name);
    }
    mipc_jr_pop(jr);
    id = f->first_layout;
    if (mipc_jr_get(jr, pos, "device", &vp) == 1) {
        mipc_jr_push(jr, "device");
        if (f->layout_count < 2) {
            return mipc_jr_fail(jr, "field \"%s\" has no per-device variants", f->name);
        }
        for (i = 0; i < f->layout_count; i++) {
            const char *dev = mipc_layout_info((mipc_field_id_t)((size_t)f->first_layout + i))->device;
            size_t n = strlen(dev);
            if (mipc_jr_chars(jr, vp, text, n) == 0 && memcmp(text, dev, n) == 0) {
                id = (mipc_field_id_t)((size_t)f->first_layout + i);
                break;
            }
            jr->failed = false;
        }
        if (i == f->layout_count) {
            return mipc_jr_fail(jr, "not a device with a variant of \"%s\"", f->name);
        }
        mipc_jr_pop(jr);
    } else if (f->layout_count > 1) {
        return mipc_jr_fail(jr, "field \"%s\" has per-device variants: \"device\" is required", f->name);
    }
    if (mipc_jr_get(jr, pos, "values", &vp) != 1) {
        return mipc_jr_fail(jr, "missing \"values\"");
    }
    mipc_jr_push(jr, "values");
    if (mipc_value_from_json(jr, vp, id, value)) {
        return -1;
    }
    mipc_jr_pop(jr);
    return 0;
}

/* One entry of "fields", appended to the packet. */
static int field_entry(mipc_jr_t *jr, size_t pos, uint8_t set, mipc_packet_builder_t *b) {
    size_t vp;
    uint8_t data[MIPC_MAX_PAYLOAD];
    size_t n = 0;
    uint8_t descriptor = 0;
    mipc_status_t st;
    if (mipc_jr_get(jr, pos, "trailing", &vp) == 1) {
        if (mipc_jr_object(jr, pos, k_trailing_keys, 2) || check_error_text(jr, pos)) {
            return -1;
        }
        mipc_jr_push(jr, "trailing");
        if (mipc_jr_hex(jr, vp, data, sizeof data, &n)) {
            return -1;
        }
        mipc_jr_pop(jr);
        st = mipc_packet_add_raw(b, data, n);
    } else {
        int raw = mipc_jr_get(jr, pos, "data", &vp) == 1;
        if (mipc_jr_object(jr, pos, raw ? k_raw_keys : k_field_keys, raw ? 3 : 4)) {
            return -1;
        }
        if (mipc_jr_get(jr, pos, "descriptor", &vp) != 1) {
            return mipc_jr_fail(jr, "missing \"descriptor\"");
        }
        mipc_jr_push(jr, "descriptor");
        if (mipc_jr_u8(jr, vp, &descriptor)) {
            return -1;
        }
        mipc_jr_pop(jr);
        if (raw) {
            if (check_error_text(jr, pos)) {
                return -1;
            }
            mipc_jr_get(jr, pos, "data", &vp);
            mipc_jr_push(jr, "data");
            if (mipc_jr_hex(jr, vp, data, MIPC_MAX_FIELD_DATA, &n)) {
                return -1;
            }
            mipc_jr_pop(jr);
        } else {
            mipc_field_value_t value;
            if (decoded_field(jr, pos, set, descriptor, &value)) {
                return -1;
            }
            st = mipc_encode_field(&value, data, MIPC_MAX_FIELD_DATA, &n);
            if (st == MIPC_ERR_BUFFER) {
                return mipc_jr_fail(jr, "the values need more than the %d bytes a field can carry",
                                    MIPC_MAX_FIELD_DATA);
            }
            if (st != MIPC_OK) {
                return mipc_jr_fail(jr, "the values cannot be encoded (%s)", mipc_status_text(st));
            }
        }
        st = mipc_packet_add_field(b, descriptor, data, n);
    }
    if (st == MIPC_ERR_TOO_LONG) {
        return mipc_jr_fail(jr, "the payload would exceed %d bytes", MIPC_MAX_PAYLOAD);
    }
    if (st == MIPC_ERR_INVALID) {
        /* a field whose size byte is irregular needs at least -adjust bytes of data */
        return mipc_jr_fail(
            jr, "field data of %u bytes is shorter than the minimum %d for descriptor %u of set %u",
            (unsigned)n, -mipc_field_length_adjust(set, descriptor), (unsigned)descriptor, (unsigned)set);
    }
    if (st != MIPC_OK && st != MIPC_ERR_BUFFER) {
        return mipc_jr_fail(jr, "%s", mipc_status_text(st));
    }
    return st == MIPC_OK ? 0 : -1;
}

mipc_status_t mipc_json_encode_line(const char *line, size_t len, uint8_t *out, size_t cap, size_t *out_len,
                                    char *msg, size_t msg_cap) {
    assert(line != NULL || len == 0);
    assert(out != NULL || cap == 0);
    assert(msg != NULL || msg_cap == 0);
    mipc_jr_t jr;
    mipc_packet_builder_t b;
    size_t pos;
    size_t vp;
    size_t it;
    size_t ep;
    size_t i;
    uint8_t set;
    mipc_status_t st;
    mipc_jr_init(&jr, line, len, msg, msg_cap);
    if (out_len) {
        *out_len = 0;
    }
    if (mipc_jr_document(&jr, &pos)) {
        return MIPC_ERR_JSON;
    }
    if (mipc_jr_get(&jr, pos, "skipped", &vp) == 1) {
        size_t n;
        if (mipc_jr_object(&jr, pos, k_skip_keys, 2) || check_offset(&jr, pos)) {
            return MIPC_ERR_JSON;
        }
        mipc_jr_push(&jr, "skipped");
        if (!mipc_jr_is_string(&jr, vp)) {
            mipc_jr_fail(&jr, "expected a hex string");
            return MIPC_ERR_JSON;
        }
        if (mipc_jr_hex(&jr, vp, out, cap, &n)) {
            return MIPC_ERR_JSON;
        }
        if (out_len) {
            *out_len = n;
        }
        return MIPC_OK;
    }
    if (mipc_jr_object(&jr, pos, k_packet_keys, 3) || check_offset(&jr, pos)) {
        return MIPC_ERR_JSON;
    }
    if (mipc_jr_get(&jr, pos, "set", &vp) != 1) {
        mipc_jr_fail(&jr, "missing \"set\" (or \"skipped\")");
        return MIPC_ERR_JSON;
    }
    mipc_jr_push(&jr, "set");
    if (mipc_jr_u8(&jr, vp, &set)) {
        return MIPC_ERR_JSON;
    }
    mipc_jr_pop(&jr);
    if (mipc_jr_get(&jr, pos, "fields", &vp) != 1) {
        mipc_jr_fail(&jr, "missing \"fields\"");
        return MIPC_ERR_JSON;
    }
    mipc_jr_push(&jr, "fields");
    if (mipc_jr_array(&jr, vp, &it)) {
        return MIPC_ERR_JSON;
    }
    mipc_packet_begin(&b, out, cap, set);
    for (i = 0;; i++) {
        int more = mipc_jr_next(&jr, &it, &ep);
        if (more < 0) {
            return MIPC_ERR_JSON;
        }
        if (!more) {
            break;
        }
        mipc_jr_index(&jr, i);
        if (field_entry(&jr, ep, set, &b)) {
            if (b.status == MIPC_ERR_BUFFER) {
                snprintf(msg, msg_cap, "output buffer too small");
                return MIPC_ERR_BUFFER;
            }
            return MIPC_ERR_JSON;
        }
    }
    st = mipc_packet_finish(&b, out_len);
    if (st == MIPC_ERR_BUFFER) {
        if (msg_cap > 0) {
            snprintf(msg, msg_cap, "output buffer too small");
        }
        return st;
    }
    return st == MIPC_OK ? MIPC_OK : MIPC_ERR_JSON;
}

/* ------------------------------------------------------------------ session lines */

size_t mipc_json_result_line(const mipc_result_t *result, uint64_t line, mipc_device_t device, char *out,
                             size_t cap) {
    assert(result != NULL);
    assert(out != NULL || cap == 0);
    mipc_jw_t w;
    mipc_field_iter_t it;
    mipc_field_entry_t e;
    size_t i = 0;
    mipc_jw_init(&w, out, cap);
    mipc_jw_lit(&w, "{\"line\":");
    mipc_jw_uint(&w, line);
    mipc_jw_lit(&w, ",\"result\":\"");
    mipc_jw_lit(&w, mipc_result_kind_name(result->kind));
    mipc_jw_lit(&w, "\",\"code\":");
    if (result->has_code) {
        mipc_jw_uint(&w, result->code);
    } else {
        mipc_jw_lit(&w, "null");
    }
    mipc_jw_lit(&w, ",\"reply\":[");
    mipc_result_reply_iter(result, &it);
    while (mipc_field_iter_next(&it, &e)) {
        mipc_jw_sep(&w, i++);
        field_json(&w, result->set, &e, device);
    }
    mipc_jw_lit(&w, "]");
    if (result->kind == MIPC_RESULT_INVALID || result->kind == MIPC_RESULT_REFUSED ||
        result->kind == MIPC_RESULT_TRANSPORT || result->kind == MIPC_RESULT_LOST) {
        mipc_jw_lit(&w, ",\"error\":");
        mipc_jw_string(&w, result->error, strlen(result->error));
    }
    mipc_jw_lit(&w, "}");
    return mipc_jw_finish(&w);
}

mipc_status_t mipc_json_command_line(const char *line, size_t len, mipc_field_value_t *out, char *msg,
                                     size_t msg_cap) {
    assert(line != NULL || len == 0);
    assert(out != NULL);
    assert(msg != NULL || msg_cap == 0);
    static const char *const keys[] = {"offset", "set", "fields"};
    uint8_t packet[MIPC_MAX_PACKET];
    mipc_jr_t jr;
    size_t n = 0;
    size_t pos;
    size_t vp;
    size_t it;
    size_t ep;
    size_t count = 0;
    size_t field = 0;
    uint8_t set;
    uint8_t descriptor;
    mipc_status_t st = mipc_json_encode_line(line, len, packet, sizeof packet, &n, msg, msg_cap);
    if (st != MIPC_OK) {
        return MIPC_ERR_JSON;
    }
    mipc_jr_init(&jr, line, len, msg, msg_cap);
    if (mipc_jr_document(&jr, &pos)) {
        return MIPC_ERR_JSON;
    }
    if (mipc_jr_get(&jr, pos, "skipped", &vp) == 1) {
        mipc_jr_fail(&jr, "expected a packet line with one command field, not a skip run");
        jr.depth = 0;
        return MIPC_ERR_JSON;
    }
    if (mipc_jr_object(&jr, pos, keys, 3) || mipc_jr_get(&jr, pos, "set", &vp) != 1 ||
        mipc_jr_u8(&jr, vp, &set) || mipc_jr_get(&jr, pos, "fields", &vp) != 1 ||
        mipc_jr_array(&jr, vp, &it)) {
        return MIPC_ERR_JSON;
    }
    for (;;) {
        int more = mipc_jr_next(&jr, &it, &ep);
        if (more < 0) {
            return MIPC_ERR_JSON;
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
        return MIPC_ERR_JSON;
    }
    if (mipc_jr_get(&jr, field, "values", &vp) != 1) {
        if (msg_cap > 0) {
            snprintf(msg, msg_cap,
                     "expected a decoded command field (descriptor, name, values), not a raw field");
        }
        return MIPC_ERR_JSON;
    }
    if (mipc_jr_get(&jr, field, "descriptor", &vp) != 1 || mipc_jr_u8(&jr, vp, &descriptor) ||
        decoded_field(&jr, field, set, descriptor, out)) {
        return MIPC_ERR_JSON;
    }
    return MIPC_OK;
}
