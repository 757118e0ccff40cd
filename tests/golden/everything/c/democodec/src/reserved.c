/* Encoders and decoders of Reserved fields (valid in every set of their kind). Generated from the spec: do
 * not edit. */
#include "democodec/reserved.h"
#include "layouts_internal.h"
#include "types_internal.h"

#include <assert.h>
#include <string.h>

/* ---- demo_ack_t */

static int demo_ack_read(demo_reader_t *r, demo_ack_t *out) {
    demo_rd_push(r, "echo");
    if (demo_rd_u8(r, &out->echo)) {
        return -1;
    }
    demo_rd_pop(r);
    demo_rd_push(r, "code");
    if (demo_rd_u8(r, &out->code)) {
        return -1;
    }
    demo_rd_pop(r);
    return demo_rd_finish(r);
}

static demo_status_t demo_ack_write(demo_writer_t *w, const demo_ack_t *in) {
    demo_status_t st;
    if ((st = demo_wr_u8(w, &in->echo)) != DEMO_OK) {
        return st;
    }
    if ((st = demo_wr_u8(w, &in->code)) != DEMO_OK) {
        return st;
    }
    return DEMO_OK;
}

demo_status_t demo_ack_encode(const demo_ack_t *value, uint8_t *buf, size_t cap, size_t *len_out) {
    demo_writer_t w;
    demo_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    demo_writer_init(&w, buf, cap);
    st = demo_ack_write(&w, value);
    if (st == DEMO_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 2 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int demo_ack_load(const uint8_t *d, demo_ack_t *out) {
    out->echo = demo_ld_u8(d + 0);
    out->code = demo_ld_u8(d + 1);
    return 0;
}

/* The general reader: lengths other than 2, bad bool bytes, error details. */
static DEMO_NOINLINE demo_status_t demo_ack_decode_read(const uint8_t *data, size_t len, demo_ack_t *out,
                                                        demo_decode_error_t *err) {
    demo_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    demo_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return demo_ack_read(&r, out) ? DEMO_ERR_DECODE : DEMO_OK;
}

demo_status_t demo_ack_decode(const uint8_t *data, size_t len, demo_ack_t *out, demo_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 2 && demo_ack_load(data, out) == 0) {
        return DEMO_OK;
    }
    return demo_ack_decode_read(data, len, out, err);
}

void demo_ack_to_json(demo_jw_t *w, const demo_ack_t *in) {
    int first = 1;
    demo_jw_raw(w, "{", 1);
    demo_jw_key(w, &first, "echo");
    demo_jw_u8(w, &in->echo);
    demo_jw_key(w, &first, "code");
    demo_jw_u8(w, &in->code);
    demo_jw_raw(w, "}", 1);
}

int demo_ack_from_json(demo_jr_t *jr, size_t pos, demo_ack_t *out) {
    static const char *const keys[] = {"echo", "code"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (demo_jr_object(jr, pos, keys, 2)) {
        return -1;
    }
    found = demo_jr_get(jr, pos, "echo", &vp);
    if (found != 1) {
        return demo_jr_fail(jr, "missing parameter \"echo\"");
    }
    {
        demo_jr_push(jr, "echo");
        if (demo_jr_u8(jr, vp, &out->echo)) {
            return -1;
        }
        demo_jr_pop(jr);
    }
    found = demo_jr_get(jr, pos, "code", &vp);
    if (found != 1) {
        return demo_jr_fail(jr, "missing parameter \"code\"");
    }
    {
        demo_jr_push(jr, "code");
        if (demo_jr_u8(jr, vp, &out->code)) {
            return -1;
        }
        demo_jr_pop(jr);
    }
    return 0;
}
