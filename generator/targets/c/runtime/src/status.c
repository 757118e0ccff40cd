/* Status texts and the exact messages of docs/conformance.md section 3 (decode errors, trailing
 * bytes of a payload), written without stdio so that the core builds freestanding (no printf on a
 * Cortex-M image). */
#include "codec/status.h"

#include <assert.h>
#include <string.h>

#include "codec/field_iter.h"

const char *codec_status_text(codec_status_t status) {
    switch (status) {
    case CODEC_OK:
        return "ok";
    case CODEC_ERR_DECODE:
        return "field data does not match the layout";
    case CODEC_ERR_BUFFER:
        return "output buffer too small";
    case CODEC_ERR_INVALID:
        return "value cannot be encoded";
    case CODEC_ERR_UNKNOWN_SET:
        return "unknown descriptor set";
    case CODEC_ERR_UNKNOWN_DESCRIPTOR:
        return "unknown descriptor";
    case CODEC_ERR_TOO_LONG:
        return "exceeds the framing limits";
    case CODEC_ERR_JSON:
        return "invalid JSON line";
    }
    return "unknown status";
}

/* Appends to buf like snprintf, keeping the total length in *len. */
static void append(char *buf, size_t cap, size_t *len, const char *text) {
    size_t n = strlen(text);
    if (*len < cap) {
        size_t room = cap - *len - 1;
        size_t k = n < room ? n : room;
        memcpy(buf + *len, text, k);
        buf[*len + k] = '\0';
    }
    *len += n;
}

/* Appends the decimal digits of v. */
static void append_u64(char *buf, size_t cap, size_t *len, uint64_t v) {
    char digits[21];
    size_t i = sizeof digits - 1;
    digits[i] = '\0';
    do {
        digits[--i] = (char)('0' + (int)(v % 10u));
        v /= 10u;
    } while (v != 0);
    append(buf, cap, len, digits + i);
}

/* Appends v (two's complement) as a signed decimal. */
static void append_i64(char *buf, size_t cap, size_t *len, uint64_t v) {
    if (v > (uint64_t)INT64_MAX) {
        append(buf, cap, len, "-");
        v = ~v + 1u;
    }
    append_u64(buf, cap, len, v);
}

size_t codec_decode_error_format(const codec_decode_error_t *err, char *buf, size_t cap) {
    assert(err != NULL);
    assert(buf != NULL || cap == 0);
    size_t len = 0;
    size_t i;
    if (cap > 0) {
        buf[0] = '\0';
    }
    if (err->kind != CODEC_DECODE_UNEXPECTED) {
        for (i = 0; i < err->depth && i < CODEC_PATH_MAX_DEPTH; i++) {
            if (i > 0) {
                append(buf, cap, &len, ".");
            }
            append(buf, cap, &len, err->path[i].name ? err->path[i].name : "?");
            if (err->path[i].index != SIZE_MAX) {
                append(buf, cap, &len, "[");
                append_u64(buf, cap, &len, err->path[i].index);
                append(buf, cap, &len, "]");
            }
        }
        append(buf, cap, &len, ": ");
    }
    switch (err->kind) {
    case CODEC_DECODE_NEEDS_BYTES:
        append(buf, cap, &len, "needs ");
        append_u64(buf, cap, &len, err->need);
        append(buf, cap, &len, " bytes at offset ");
        append_u64(buf, cap, &len, err->offset);
        append(buf, cap, &len, ", ");
        append_u64(buf, cap, &len, err->have);
        append(buf, cap, &len, " left");
        break;
    case CODEC_DECODE_COUNT:
        append(buf, cap, &len, "count ");
        append_u64(buf, cap, &len, err->count);
        append(buf, cap, &len, " exceeds maximum ");
        append_u64(buf, cap, &len, err->max);
        break;
    case CODEC_DECODE_REMAINING:
        append_u64(buf, cap, &len, err->have);
        append(buf, cap, &len, " bytes left at offset ");
        append_u64(buf, cap, &len, err->offset);
        append(buf, cap, &len, ", not a multiple of ");
        append_u64(buf, cap, &len, err->need);
        break;
    case CODEC_DECODE_BOOL:
        append(buf, cap, &len, "invalid bool value ");
        append_u64(buf, cap, &len, err->value);
        append(buf, cap, &len, " at offset ");
        append_u64(buf, cap, &len, err->offset);
        break;
    case CODEC_DECODE_SELECTOR:
        append(buf, cap, &len, "no member for selector value ");
        if (err->value_signed) {
            append_i64(buf, cap, &len, err->value);
        } else {
            append_u64(buf, cap, &len, err->value);
        }
        break;
    case CODEC_DECODE_UNEXPECTED:
        append_u64(buf, cap, &len, err->have);
        append(buf, cap, &len, " unexpected bytes at offset ");
        append_u64(buf, cap, &len, err->offset);
        break;
    case CODEC_DECODE_NONE:
    default:
        append(buf, cap, &len, "no error");
        break;
    }
    return len;
}

size_t codec_trailing_format(const codec_field_entry_t *entry, char *buf, size_t cap) {
    assert(entry != NULL);
    assert(buf != NULL || cap == 0);
    size_t len = 0;
    if (cap > 0) {
        buf[0] = '\0';
    }
    switch (entry->trailing) {
    case CODEC_TRAILING_SHORT_LENGTH:
        append(buf, cap, &len, "field length ");
        append_u64(buf, cap, &len, entry->length_byte);
        append(buf, cap, &len, " at payload offset ");
        append_u64(buf, cap, &len, entry->offset);
        append(buf, cap, &len, " is shorter than the field header");
        break;
    case CODEC_TRAILING_OVERRUN:
        append(buf, cap, &len, "field length ");
        append_u64(buf, cap, &len, entry->length_byte);
        append(buf, cap, &len, " at payload offset ");
        append_u64(buf, cap, &len, entry->offset);
        append(buf, cap, &len, " overruns the payload (");
        append_u64(buf, cap, &len, entry->length);
        append(buf, cap, &len, " bytes left)");
        break;
    case CODEC_TRAILING_SHORT_HEADER:
    default:
        append(buf, cap, &len, "field header at payload offset ");
        append_u64(buf, cap, &len, entry->offset);
        append(buf, cap, &len, " needs ");
        append_u64(buf, cap, &len, CODEC_FIELD_HEADER_SIZE);
        append(buf, cap, &len, " bytes, ");
        append_u64(buf, cap, &len, entry->length);
        append(buf, cap, &len, " left");
        break;
    }
    return len;
}
