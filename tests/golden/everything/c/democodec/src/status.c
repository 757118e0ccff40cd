/* Status texts and the exact decode error messages of docs/conformance.md section 3.
 * Generated: do not edit. */
#include "democodec/status.h"

#include <inttypes.h>
#include <stdio.h>
#include <string.h>

const char *democ_status_text(democ_status_t status) {
    switch (status) {
    case DEMOC_OK:
        return "ok";
    case DEMOC_ERR_DECODE:
        return "field data does not match the layout";
    case DEMOC_ERR_BUFFER:
        return "output buffer too small";
    case DEMOC_ERR_INVALID:
        return "value cannot be encoded";
    case DEMOC_ERR_UNKNOWN_SET:
        return "unknown descriptor set";
    case DEMOC_ERR_UNKNOWN_DESCRIPTOR:
        return "unknown descriptor";
    case DEMOC_ERR_TOO_LONG:
        return "exceeds the framing limits";
    case DEMOC_ERR_JSON:
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

size_t democ_decode_error_format(const democ_decode_error_t *err, char *buf, size_t cap) {
    char num[96];
    size_t len = 0;
    size_t i;
    if (cap > 0) {
        buf[0] = '\0';
    }
    if (err->kind != DEMOC_DECODE_UNEXPECTED) {
        for (i = 0; i < err->depth && i < DEMOC_PATH_MAX_DEPTH; i++) {
            if (i > 0) {
                append(buf, cap, &len, ".");
            }
            append(buf, cap, &len, err->path[i].name ? err->path[i].name : "?");
            if (err->path[i].index != SIZE_MAX) {
                snprintf(num, sizeof num, "[%zu]", err->path[i].index);
                append(buf, cap, &len, num);
            }
        }
        append(buf, cap, &len, ": ");
    }
    switch (err->kind) {
    case DEMOC_DECODE_NEEDS_BYTES:
        snprintf(num, sizeof num, "needs %zu bytes at offset %zu, %zu left", err->need, err->offset,
                 err->have);
        break;
    case DEMOC_DECODE_COUNT:
        snprintf(num, sizeof num, "count %" PRIu64 " exceeds maximum %" PRIu64, err->count, err->max);
        break;
    case DEMOC_DECODE_REMAINING:
        snprintf(num, sizeof num, "%zu bytes left at offset %zu, not a multiple of %zu", err->have,
                 err->offset, err->need);
        break;
    case DEMOC_DECODE_BOOL:
        snprintf(num, sizeof num, "invalid bool value %" PRIu64 " at offset %zu", err->value, err->offset);
        break;
    case DEMOC_DECODE_SELECTOR:
        if (err->value_signed) {
            int64_t v = err->value > (uint64_t)INT64_MAX ? -(int64_t)(~err->value) - 1 : (int64_t)err->value;
            snprintf(num, sizeof num, "no member for selector value %" PRId64, v);
        } else {
            snprintf(num, sizeof num, "no member for selector value %" PRIu64, err->value);
        }
        break;
    case DEMOC_DECODE_UNEXPECTED:
        snprintf(num, sizeof num, "%zu unexpected bytes at offset %zu", err->have, err->offset);
        break;
    case DEMOC_DECODE_NONE:
    default:
        snprintf(num, sizeof num, "no error");
        break;
    }
    append(buf, cap, &len, num);
    return len;
}
