/* Packet <-> canonical JSON line. Generated: do not edit. */
#include "mscipcodec/json.h"
#include "mscipcodec/field_iter.h"
#include "layouts_internal.h"

#include <assert.h>
#include <stdio.h>
#include <string.h>

/* The line of a foreign frame into out (cap bytes); returns its full length: an NMEA sentence
 * without its CR LF ('"' and '\\' escaped: the rest is printable ASCII), an RTCM3 frame's message
 * number and payload length (docs/conformance.md section 5). */
size_t mscipc_json_foreign_line(const mscipc_event_t *ev, char *out, size_t cap) {
    char head[96];
    size_t n;
    size_t i;
    if (ev->kind == MSCIPC_EVENT_RTCM) {
        int k = snprintf(head, sizeof head, "{\"offset\":%llu,\"rtcm\":%u,\"length\":%llu}",
                         (unsigned long long)ev->offset, mscipc_rtcm_type(ev->packet),
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

size_t mscipc_json_skip_line(uint64_t offset, const uint8_t *bytes, size_t n, char *out, size_t cap) {
    assert(bytes != NULL || n == 0);
    assert(out != NULL || cap == 0);
    mscipc_jw_t w;
    mscipc_jw_init(&w, out, cap);
    mscipc_jw_lit(&w, "{\"offset\":");
    mscipc_jw_uint(&w, offset);
    mscipc_jw_lit(&w, ",\"skipped\":");
    mscipc_jw_hex(&w, bytes, n);
    mscipc_jw_lit(&w, "}");
    return mscipc_jw_finish(&w);
}

static void field_json(mscipc_jw_t *w, uint8_t set, const mscipc_field_entry_t *e, mscipc_device_t device) {
    mscipc_field_value_t value;
    mscipc_decode_error_t err;
    mscipc_status_t st;
    char msg[MSCIPC_ERROR_MESSAGE_MAX];
    size_t n;
    if (e->kind == MSCIPC_ENTRY_TRAILING) {
        n = mscipc_trailing_format(e, msg, sizeof msg);
        mscipc_jw_lit(w, "{\"trailing\":");
        mscipc_jw_hex(w, e->data, e->length);
        mscipc_jw_lit(w, ",\"error\":");
        mscipc_jw_string(w, msg, n < sizeof msg ? n : sizeof msg - 1);
        mscipc_jw_lit(w, "}");
        return;
    }
    mscipc_jw_lit(w, "{\"descriptor\":");
    mscipc_jw_uint(w, e->descriptor);
    st = mscipc_decode_field(set, e->descriptor, e->data, e->length, device, &value, &err);
    if (st == MSCIPC_OK) {
        const mscipc_layout_info_t *info = mscipc_layout_info(value.id);
        mscipc_jw_lit(w, ",\"name\":\"");
        mscipc_jw_lit(w, info->name);
        mscipc_jw_lit(w, "\"");
        if (info->device) {
            mscipc_jw_lit(w, ",\"device\":\"");
            mscipc_jw_lit(w, info->device);
            mscipc_jw_lit(w, "\"");
        }
        mscipc_jw_lit(w, ",\"values\":");
        mscipc_value_to_json(w, &value);
        mscipc_jw_lit(w, "}");
        return;
    }
    if (st == MSCIPC_ERR_DECODE) {
        n = mscipc_decode_error_format(&err, msg, sizeof msg);
        if (n >= sizeof msg) {
            n = sizeof msg - 1;
        }
    } else {
        const char *text =
            st == MSCIPC_ERR_UNKNOWN_DESCRIPTOR ? "unknown descriptor" : "unknown descriptor set";
        n = strlen(text);
        memcpy(msg, text, n + 1);
    }
    mscipc_jw_lit(w, ",\"data\":");
    mscipc_jw_hex(w, e->data, e->length);
    mscipc_jw_lit(w, ",\"error\":");
    mscipc_jw_string(w, msg, n);
    mscipc_jw_lit(w, "}");
}

/* The start of a packet's line, `{"offset":N,"set":S,"fields":[`, written to w (over out, cap),
 * and the iterator over the packet's fields (its payload as far as len holds it); the set. */
static uint8_t packet_line_head(mscipc_jw_t *w, mscipc_field_iter_t *it, const uint8_t *packet, size_t len,
                                uint64_t offset, char *out, size_t cap) {
    size_t payload = 0;
    uint8_t set = 0;
    if (len >= MSCIPC_HEADER_SIZE) {
        set = packet[MSCIPC_SET_OFFSET];
        payload = packet[MSCIPC_LENGTH_OFFSET];
        if (payload > len - MSCIPC_HEADER_SIZE) {
            payload = len - MSCIPC_HEADER_SIZE;
        }
    }
    mscipc_jw_init(w, out, cap);
    mscipc_jw_lit(w, "{\"offset\":");
    mscipc_jw_uint(w, offset);
    mscipc_jw_lit(w, ",\"set\":");
    mscipc_jw_uint(w, set);
    mscipc_jw_lit(w, ",\"fields\":[");
    mscipc_field_iter_init(it, set, len >= MSCIPC_HEADER_SIZE ? packet + MSCIPC_HEADER_SIZE : NULL, payload);
    return set;
}

size_t mscipc_json_packet_line(const uint8_t *packet, size_t len, uint64_t offset, mscipc_device_t device,
                               char *out, size_t cap) {
    assert(packet != NULL || len == 0);
    assert(out != NULL || cap == 0);
    mscipc_jw_t w;
    mscipc_field_iter_t it;
    mscipc_field_entry_t e;
    size_t i = 0;
    const uint8_t set = packet_line_head(&w, &it, packet, len, offset, out, cap);
    while (mscipc_field_iter_next(&it, &e)) {
        mscipc_jw_sep(&w, i++);
        field_json(&w, set, &e, device);
    }
    mscipc_jw_lit(&w, "]}");
    return mscipc_jw_finish(&w);
}

/* The object of the i-th field a straight-line decoder decoded (set's field with a single layout),
 * written from its typed member with the writer the general path uses. */
static void member_json(mscipc_jw_t *w, uint8_t set, const mscipc_packet_index_t *index, size_t i) {
    const uint8_t descriptor = index->fields[i].descriptor;
    mscipc_status_t why = MSCIPC_ERR_UNKNOWN_SET;
    const mscipc_field_info_t *f = mscipc_find_field(set, descriptor, &why);
    const mscipc_layout_info_t *info;
    mscipc_jw_lit(w, "{\"descriptor\":");
    mscipc_jw_uint(w, descriptor);
    if (!f) {
        mscipc_jw_lit(w, ",\"error\":\"no field for a decoded member\"}"); /* never: a member is a field */
        return;
    }
    info = mscipc_layout_info(f->first_layout);
    mscipc_jw_lit(w, ",\"name\":\"");
    mscipc_jw_lit(w, info->name);
    mscipc_jw_lit(w, "\"");
    if (info->device) {
        mscipc_jw_lit(w, ",\"device\":\"");
        mscipc_jw_lit(w, info->device);
        mscipc_jw_lit(w, "\"");
    }
    mscipc_jw_lit(w, ",\"values\":");
    mscipc_layout_to_json(w, f->first_layout, mscipc_packet_value(index, i));
    mscipc_jw_lit(w, "}");
}

size_t mscipc_json_decoded_packet_line(const uint8_t *packet, size_t len, uint64_t offset,
                                       mscipc_device_t device, const mscipc_packet_index_t *index,
                                       const mscipc_field_entry_t *others, size_t other_count, char *out,
                                       size_t cap) {
    assert(packet != NULL || len == 0);
    assert(others != NULL || other_count == 0);
    assert(out != NULL || cap == 0);
    mscipc_jw_t w;
    mscipc_field_iter_t it;
    mscipc_field_entry_t e;
    size_t i = 0;
    size_t decoded = 0;
    size_t passed = 0;
    /* The entries in packet order (the walk only places them): each is the next entry passed on
     * when it starts where that one does, else the next decoded field, which must have its
     * descriptor. */
    const uint8_t set = packet_line_head(&w, &it, packet, len, offset, out, cap);
    while (mscipc_field_iter_next(&it, &e)) {
        mscipc_jw_sep(&w, i++);
        if (passed < other_count && others[passed].offset == e.offset && others[passed].kind == e.kind) {
            field_json(&w, set, &others[passed++], device);
        } else if (e.kind == MSCIPC_ENTRY_FIELD && index != NULL && decoded < index->count &&
                   index->fields[decoded].descriptor == e.descriptor) {
            member_json(&w, set, index, decoded++);
        } else {
            return 0;
        }
    }
    if (passed != other_count || decoded != (index != NULL ? index->count : 0)) {
        return 0;
    }
    mscipc_jw_lit(&w, "]}");
    return mscipc_jw_finish(&w);
}

/* ------------------------------------------------------------------ JSON line -> bytes */

static const char *const k_packet_keys[] = {"offset", "set", "fields"};
static const char *const k_skip_keys[] = {"offset", "skipped"};
static const char *const k_trailing_keys[] = {"trailing", "error"};
static const char *const k_raw_keys[] = {"descriptor", "data", "error"};
static const char *const k_field_keys[] = {"descriptor", "name", "device", "values"};

static int check_offset(mscipc_jr_t *jr, size_t pos) {
    size_t vp;
    uint64_t offset;
    if (mscipc_jr_get(jr, pos, "offset", &vp) != 1) {
        return mscipc_jr_fail(jr, "missing \"offset\"");
    }
    mscipc_jr_push(jr, "offset");
    if (mscipc_jr_uint(jr, vp, UINT64_MAX, &offset)) {
        return -1;
    }
    mscipc_jr_pop(jr);
    return 0;
}

static int check_error_text(mscipc_jr_t *jr, size_t pos) {
    size_t vp;
    if (mscipc_jr_get(jr, pos, "error", &vp) != 1) {
        return mscipc_jr_fail(jr, "missing \"error\"");
    }
    if (!mscipc_jr_is_string(jr, vp)) {
        mscipc_jr_push(jr, "error");
        return mscipc_jr_fail(jr, "expected a string");
    }
    return 0;
}

/* A decoded field: find its layout from descriptor, name and device, then read its values. */
static int decoded_field(mscipc_jr_t *jr, size_t pos, uint8_t set, uint8_t descriptor,
                         mscipc_field_value_t *value) {
    mscipc_status_t why = MSCIPC_ERR_UNKNOWN_SET;
    const mscipc_field_info_t *f = mscipc_find_field(set, descriptor, &why);
    mscipc_field_id_t id;
    size_t vp;
    char text[MSCIPC_NAME_MAX]; /* longest field name or device id, and a NUL */
    size_t i;
    if (!f) {
        return mscipc_jr_fail(
            jr, "descriptor %u in set %u is not defined (%s); write it as a raw field with \"data\"",
            (unsigned)descriptor, (unsigned)set, mscipc_status_text(why));
    }
    if (mscipc_jr_get(jr, pos, "name", &vp) != 1) {
        return mscipc_jr_fail(jr, "missing \"name\"");
    }
    mscipc_jr_push(jr, "name");
    if (mscipc_jr_chars(jr, vp, text, strlen(f->name)) || memcmp(text, f->name, strlen(f->name)) != 0) {
        jr->failed = false;
        return mscipc_jr_fail(jr, "descriptor %u in set %u is \"%s\"", (unsigned)descriptor, (unsigned)set,
                              f->name);
    }
    mscipc_jr_pop(jr);
    id = f->first_layout;
    if (mscipc_jr_get(jr, pos, "device", &vp) == 1) {
        mscipc_jr_push(jr, "device");
        if (f->layout_count < 2) {
            return mscipc_jr_fail(jr, "field \"%s\" has no per-device variants", f->name);
        }
        for (i = 0; i < f->layout_count; i++) {
            const char *dev = mscipc_layout_info((mscipc_field_id_t)((size_t)f->first_layout + i))->device;
            size_t n = strlen(dev);
            if (mscipc_jr_chars(jr, vp, text, n) == 0 && memcmp(text, dev, n) == 0) {
                id = (mscipc_field_id_t)((size_t)f->first_layout + i);
                break;
            }
            jr->failed = false;
        }
        if (i == f->layout_count) {
            return mscipc_jr_fail(jr, "not a device with a variant of \"%s\"", f->name);
        }
        mscipc_jr_pop(jr);
    } else if (f->layout_count > 1) {
        return mscipc_jr_fail(jr, "field \"%s\" has per-device variants: \"device\" is required", f->name);
    }
    if (mscipc_jr_get(jr, pos, "values", &vp) != 1) {
        return mscipc_jr_fail(jr, "missing \"values\"");
    }
    mscipc_jr_push(jr, "values");
    if (mscipc_value_from_json(jr, vp, id, value)) {
        return -1;
    }
    mscipc_jr_pop(jr);
    return 0;
}

/* One entry of "fields", appended to the packet. */
static int field_entry(mscipc_jr_t *jr, size_t pos, uint8_t set, mscipc_packet_builder_t *b) {
    size_t vp;
    uint8_t data[MSCIPC_MAX_PAYLOAD];
    size_t n = 0;
    uint8_t descriptor = 0;
    mscipc_status_t st;
    if (mscipc_jr_get(jr, pos, "trailing", &vp) == 1) {
        if (mscipc_jr_object(jr, pos, k_trailing_keys, 2) || check_error_text(jr, pos)) {
            return -1;
        }
        mscipc_jr_push(jr, "trailing");
        if (mscipc_jr_hex(jr, vp, data, sizeof data, &n)) {
            return -1;
        }
        mscipc_jr_pop(jr);
        st = mscipc_packet_add_raw(b, data, n);
    } else {
        int raw = mscipc_jr_get(jr, pos, "data", &vp) == 1;
        if (mscipc_jr_object(jr, pos, raw ? k_raw_keys : k_field_keys, raw ? 3 : 4)) {
            return -1;
        }
        if (mscipc_jr_get(jr, pos, "descriptor", &vp) != 1) {
            return mscipc_jr_fail(jr, "missing \"descriptor\"");
        }
        mscipc_jr_push(jr, "descriptor");
        if (mscipc_jr_u8(jr, vp, &descriptor)) {
            return -1;
        }
        mscipc_jr_pop(jr);
        if (raw) {
            if (check_error_text(jr, pos)) {
                return -1;
            }
            mscipc_jr_get(jr, pos, "data", &vp);
            mscipc_jr_push(jr, "data");
            if (mscipc_jr_hex(jr, vp, data, MSCIPC_MAX_FIELD_DATA, &n)) {
                return -1;
            }
            mscipc_jr_pop(jr);
        } else {
            mscipc_field_value_t value;
            if (decoded_field(jr, pos, set, descriptor, &value)) {
                return -1;
            }
            st = mscipc_encode_field(&value, data, MSCIPC_MAX_FIELD_DATA, &n);
            if (st == MSCIPC_ERR_BUFFER) {
                return mscipc_jr_fail(jr, "the values need more than the %d bytes a field can carry",
                                      MSCIPC_MAX_FIELD_DATA);
            }
            if (st != MSCIPC_OK) {
                return mscipc_jr_fail(jr, "the values cannot be encoded (%s)", mscipc_status_text(st));
            }
        }
        st = mscipc_packet_add_field(b, descriptor, data, n);
    }
    if (st == MSCIPC_ERR_TOO_LONG) {
        return mscipc_jr_fail(jr, "the payload would exceed %d bytes", MSCIPC_MAX_PAYLOAD);
    }
    if (st == MSCIPC_ERR_INVALID) {
        /* a field whose size byte is irregular needs at least -adjust bytes of data */
        return mscipc_jr_fail(
            jr, "field data of %u bytes is shorter than the minimum %d for descriptor %u of set %u",
            (unsigned)n, -mscipc_field_length_adjust(set, descriptor), (unsigned)descriptor, (unsigned)set);
    }
    if (st != MSCIPC_OK && st != MSCIPC_ERR_BUFFER) {
        return mscipc_jr_fail(jr, "%s", mscipc_status_text(st));
    }
    return st == MSCIPC_OK ? 0 : -1;
}

mscipc_status_t mscipc_json_encode_line(const char *line, size_t len, uint8_t *out, size_t cap,
                                        size_t *out_len, char *msg, size_t msg_cap) {
    assert(line != NULL || len == 0);
    assert(out != NULL || cap == 0);
    assert(msg != NULL || msg_cap == 0);
    mscipc_jr_t jr;
    mscipc_packet_builder_t b;
    size_t pos;
    size_t vp;
    size_t it;
    size_t ep;
    size_t i;
    uint8_t set;
    mscipc_status_t st;
    mscipc_jr_init(&jr, line, len, msg, msg_cap);
    if (out_len) {
        *out_len = 0;
    }
    if (mscipc_jr_document(&jr, &pos)) {
        return MSCIPC_ERR_JSON;
    }
    if (mscipc_jr_get(&jr, pos, "skipped", &vp) == 1) {
        size_t n;
        if (mscipc_jr_object(&jr, pos, k_skip_keys, 2) || check_offset(&jr, pos)) {
            return MSCIPC_ERR_JSON;
        }
        mscipc_jr_push(&jr, "skipped");
        if (!mscipc_jr_is_string(&jr, vp)) {
            mscipc_jr_fail(&jr, "expected a hex string");
            return MSCIPC_ERR_JSON;
        }
        if (mscipc_jr_hex(&jr, vp, out, cap, &n)) {
            return MSCIPC_ERR_JSON;
        }
        if (out_len) {
            *out_len = n;
        }
        return MSCIPC_OK;
    }
    if (mscipc_jr_object(&jr, pos, k_packet_keys, 3) || check_offset(&jr, pos)) {
        return MSCIPC_ERR_JSON;
    }
    if (mscipc_jr_get(&jr, pos, "set", &vp) != 1) {
        mscipc_jr_fail(&jr, "missing \"set\" (or \"skipped\")");
        return MSCIPC_ERR_JSON;
    }
    mscipc_jr_push(&jr, "set");
    if (mscipc_jr_u8(&jr, vp, &set)) {
        return MSCIPC_ERR_JSON;
    }
    mscipc_jr_pop(&jr);
    if (mscipc_jr_get(&jr, pos, "fields", &vp) != 1) {
        mscipc_jr_fail(&jr, "missing \"fields\"");
        return MSCIPC_ERR_JSON;
    }
    mscipc_jr_push(&jr, "fields");
    if (mscipc_jr_array(&jr, vp, &it)) {
        return MSCIPC_ERR_JSON;
    }
    mscipc_packet_begin(&b, out, cap, set);
    for (i = 0;; i++) {
        int more = mscipc_jr_next(&jr, &it, &ep);
        if (more < 0) {
            return MSCIPC_ERR_JSON;
        }
        if (!more) {
            break;
        }
        mscipc_jr_index(&jr, i);
        if (field_entry(&jr, ep, set, &b)) {
            if (b.status == MSCIPC_ERR_BUFFER) {
                snprintf(msg, msg_cap, "output buffer too small");
                return MSCIPC_ERR_BUFFER;
            }
            return MSCIPC_ERR_JSON;
        }
    }
    st = mscipc_packet_finish(&b, out_len);
    if (st == MSCIPC_ERR_BUFFER) {
        if (msg_cap > 0) {
            snprintf(msg, msg_cap, "output buffer too small");
        }
        return st;
    }
    return st == MSCIPC_OK ? MSCIPC_OK : MSCIPC_ERR_JSON;
}

/* ------------------------------------------------------------------ session lines */

size_t mscipc_json_result_line(const mscipc_result_t *result, uint64_t line, mscipc_device_t device,
                               char *out, size_t cap) {
    assert(result != NULL);
    assert(out != NULL || cap == 0);
    mscipc_jw_t w;
    mscipc_field_iter_t it;
    mscipc_field_entry_t e;
    size_t i = 0;
    mscipc_jw_init(&w, out, cap);
    mscipc_jw_lit(&w, "{\"line\":");
    mscipc_jw_uint(&w, line);
    mscipc_jw_lit(&w, ",\"result\":\"");
    mscipc_jw_lit(&w, mscipc_result_kind_name(result->kind));
    mscipc_jw_lit(&w, "\",\"code\":");
    if (result->has_code) {
        mscipc_jw_uint(&w, result->code);
    } else {
        mscipc_jw_lit(&w, "null");
    }
    mscipc_jw_lit(&w, ",\"reply\":[");
    mscipc_result_reply_iter(result, &it);
    while (mscipc_field_iter_next(&it, &e)) {
        mscipc_jw_sep(&w, i++);
        field_json(&w, result->set, &e, device);
    }
    mscipc_jw_lit(&w, "]");
    if (result->kind == MSCIPC_RESULT_INVALID || result->kind == MSCIPC_RESULT_REFUSED ||
        result->kind == MSCIPC_RESULT_TRANSPORT || result->kind == MSCIPC_RESULT_LOST) {
        mscipc_jw_lit(&w, ",\"error\":");
        mscipc_jw_string(&w, result->error, strlen(result->error));
    }
    mscipc_jw_lit(&w, "}");
    return mscipc_jw_finish(&w);
}

mscipc_status_t mscipc_json_command_line(const char *line, size_t len, mscipc_field_value_t *out, char *msg,
                                         size_t msg_cap) {
    assert(line != NULL || len == 0);
    assert(out != NULL);
    assert(msg != NULL || msg_cap == 0);
    static const char *const keys[] = {"offset", "set", "fields"};
    uint8_t packet[MSCIPC_MAX_PACKET];
    mscipc_jr_t jr;
    size_t n = 0;
    size_t pos;
    size_t vp;
    size_t it;
    size_t ep;
    size_t count = 0;
    size_t field = 0;
    uint8_t set;
    uint8_t descriptor;
    mscipc_status_t st = mscipc_json_encode_line(line, len, packet, sizeof packet, &n, msg, msg_cap);
    if (st != MSCIPC_OK) {
        return MSCIPC_ERR_JSON;
    }
    mscipc_jr_init(&jr, line, len, msg, msg_cap);
    if (mscipc_jr_document(&jr, &pos)) {
        return MSCIPC_ERR_JSON;
    }
    if (mscipc_jr_get(&jr, pos, "skipped", &vp) == 1) {
        mscipc_jr_fail(&jr, "expected a packet line with one command field, not a skip run");
        jr.depth = 0;
        return MSCIPC_ERR_JSON;
    }
    if (mscipc_jr_object(&jr, pos, keys, 3) || mscipc_jr_get(&jr, pos, "set", &vp) != 1 ||
        mscipc_jr_u8(&jr, vp, &set) || mscipc_jr_get(&jr, pos, "fields", &vp) != 1 ||
        mscipc_jr_array(&jr, vp, &it)) {
        return MSCIPC_ERR_JSON;
    }
    for (;;) {
        int more = mscipc_jr_next(&jr, &it, &ep);
        if (more < 0) {
            return MSCIPC_ERR_JSON;
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
        return MSCIPC_ERR_JSON;
    }
    if (mscipc_jr_get(&jr, field, "values", &vp) != 1) {
        if (msg_cap > 0) {
            snprintf(msg, msg_cap,
                     "expected a decoded command field (descriptor, name, values), not a raw field");
        }
        return MSCIPC_ERR_JSON;
    }
    if (mscipc_jr_get(&jr, field, "descriptor", &vp) != 1 || mscipc_jr_u8(&jr, vp, &descriptor) ||
        decoded_field(&jr, field, set, descriptor, out)) {
        return MSCIPC_ERR_JSON;
    }
    return MSCIPC_OK;
}
