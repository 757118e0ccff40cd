/* Encoders and decoders of Commands. Generated from the spec: do not edit. */
#include "democodec/sets/commands.h"
#include "layouts_internal.h"
#include "types_internal.h"

#include <assert.h>
#include <string.h>

/* ---- demo_commands_ping_t */

static int demo_commands_ping_read(demo_reader_t *r, demo_commands_ping_t *out) {
    (void)out;
    return demo_rd_finish(r);
}

static demo_status_t demo_commands_ping_write(demo_writer_t *w, const demo_commands_ping_t *in) {
    (void)w;
    (void)in;
    return DEMO_OK;
}

demo_status_t demo_commands_ping_encode(const demo_commands_ping_t *value, uint8_t *buf, size_t cap,
                                        size_t *len_out) {
    demo_writer_t w;
    demo_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    demo_writer_init(&w, buf, cap);
    st = demo_commands_ping_write(&w, value);
    if (st == DEMO_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

demo_status_t demo_commands_ping_decode(const uint8_t *data, size_t len, demo_commands_ping_t *out,
                                        demo_decode_error_t *err) {
    demo_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    demo_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return demo_commands_ping_read(&r, out) ? DEMO_ERR_DECODE : DEMO_OK;
}

void demo_commands_ping_to_json(demo_jw_t *w, const demo_commands_ping_t *in) {
    int first = 1;
    demo_jw_raw(w, "{", 1);
    demo_jw_raw(w, "}", 1);
    (void)in;
    (void)first;
}

int demo_commands_ping_from_json(demo_jr_t *jr, size_t pos, demo_commands_ping_t *out) {
    memset(out, 0, sizeof *out);
    if (demo_jr_object(jr, pos, NULL, 0)) {
        return -1;
    }
    return 0;
}

/* ---- demo_commands_configure_t */

static int demo_commands_configure_read(demo_reader_t *r, demo_commands_configure_t *out) {
    demo_rd_push(r, "function");
    if (demo_rd_u8(r, &out->function)) {
        return -1;
    }
    demo_rd_pop(r);
    demo_rd_push(r, "instance");
    if (demo_rd_u8(r, &out->instance)) {
        return -1;
    }
    demo_rd_pop(r);
    if (r->pos < r->len) {
        out->has_mode = true;
        demo_rd_push(r, "mode");
        if (demo_rd_u8(r, &out->mode)) {
            return -1;
        }
        demo_rd_pop(r);
    }
    if (r->pos < r->len) {
        out->has_params = true;
        demo_rd_push(r, "params");
        if (demo_trigger_params_read(r, out->mode, &out->params)) {
            return -1;
        }
        demo_rd_pop(r);
    }
    if (r->pos < r->len) {
        out->has_suppress_ack = true;
        demo_rd_push(r, "suppress_ack");
        if (demo_rd_bool(r, &out->suppress_ack)) {
            return -1;
        }
        demo_rd_pop(r);
    }
    return demo_rd_finish(r);
}

static demo_status_t demo_commands_configure_write(demo_writer_t *w, const demo_commands_configure_t *in) {
    demo_status_t st;
    int absent = 0;
    if ((st = demo_wr_u8(w, &in->function)) != DEMO_OK) {
        return st;
    }
    if ((st = demo_wr_u8(w, &in->instance)) != DEMO_OK) {
        return st;
    }
    if (!in->has_mode) {
        absent = 1;
    } else if (absent) {
        return DEMO_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = demo_wr_u8(w, &in->mode)) != DEMO_OK) {
            return st;
        }
    }
    if (!in->has_params) {
        absent = 1;
    } else if (absent) {
        return DEMO_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = demo_trigger_params_write(w, in->mode, &in->params)) != DEMO_OK) {
            return st;
        }
    }
    if (!in->has_suppress_ack) {
        absent = 1;
    } else if (absent) {
        return DEMO_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = demo_wr_bool(w, &in->suppress_ack)) != DEMO_OK) {
            return st;
        }
    }
    return DEMO_OK;
}

demo_status_t demo_commands_configure_encode(const demo_commands_configure_t *value, uint8_t *buf, size_t cap,
                                             size_t *len_out) {
    demo_writer_t w;
    demo_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    demo_writer_init(&w, buf, cap);
    st = demo_commands_configure_write(&w, value);
    if (st == DEMO_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

demo_status_t demo_commands_configure_decode(const uint8_t *data, size_t len, demo_commands_configure_t *out,
                                             demo_decode_error_t *err) {
    demo_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    demo_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return demo_commands_configure_read(&r, out) ? DEMO_ERR_DECODE : DEMO_OK;
}

void demo_commands_configure_to_json(demo_jw_t *w, const demo_commands_configure_t *in) {
    int first = 1;
    demo_jw_raw(w, "{", 1);
    demo_jw_key(w, &first, "function");
    demo_jw_u8(w, &in->function);
    demo_jw_key(w, &first, "instance");
    demo_jw_u8(w, &in->instance);
    if (in->has_mode) {
        demo_jw_key(w, &first, "mode");
        demo_jw_u8(w, &in->mode);
    }
    if (in->has_params) {
        demo_jw_key(w, &first, "params");
        demo_trigger_params_to_json(w, in->mode, &in->params);
    }
    if (in->has_suppress_ack) {
        demo_jw_key(w, &first, "suppress_ack");
        demo_jw_bool(w, &in->suppress_ack);
    }
    demo_jw_raw(w, "}", 1);
}

int demo_commands_configure_from_json(demo_jr_t *jr, size_t pos, demo_commands_configure_t *out) {
    static const char *const keys[] = {"function", "instance", "mode", "params", "suppress_ack"};
    size_t vp = 0;
    int found;
    int absent = 0;
    memset(out, 0, sizeof *out);
    if (demo_jr_object(jr, pos, keys, 5)) {
        return -1;
    }
    found = demo_jr_get(jr, pos, "function", &vp);
    if (found != 1) {
        return demo_jr_fail(jr, "missing parameter \"function\"");
    }
    {
        demo_jr_push(jr, "function");
        if (demo_jr_u8(jr, vp, &out->function)) {
            return -1;
        }
        demo_jr_pop(jr);
    }
    found = demo_jr_get(jr, pos, "instance", &vp);
    if (found != 1) {
        return demo_jr_fail(jr, "missing parameter \"instance\"");
    }
    {
        demo_jr_push(jr, "instance");
        if (demo_jr_u8(jr, vp, &out->instance)) {
            return -1;
        }
        demo_jr_pop(jr);
    }
    found = demo_jr_get(jr, pos, "mode", &vp);
    out->has_mode = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return demo_jr_fail(jr, "optional parameter \"mode\" given after an absent one");
    } else {
        demo_jr_push(jr, "mode");
        if (demo_jr_u8(jr, vp, &out->mode)) {
            return -1;
        }
        demo_jr_pop(jr);
    }
    found = demo_jr_get(jr, pos, "params", &vp);
    out->has_params = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return demo_jr_fail(jr, "optional parameter \"params\" given after an absent one");
    } else {
        demo_jr_push(jr, "params");
        if (demo_trigger_params_from_json(jr, vp, out->mode, &out->params)) {
            return -1;
        }
        demo_jr_pop(jr);
    }
    found = demo_jr_get(jr, pos, "suppress_ack", &vp);
    out->has_suppress_ack = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return demo_jr_fail(jr, "optional parameter \"suppress_ack\" given after an absent one");
    } else {
        demo_jr_push(jr, "suppress_ack");
        if (demo_jr_bool(jr, vp, &out->suppress_ack)) {
            return -1;
        }
        demo_jr_pop(jr);
    }
    return 0;
}

/* ---- demo_commands_configuration_t */

static int demo_commands_configuration_read(demo_reader_t *r, demo_commands_configuration_t *out) {
    size_t i;
    size_t n;
    demo_rd_push(r, "instance");
    if (demo_rd_u8(r, &out->instance)) {
        return -1;
    }
    demo_rd_pop(r);
    demo_rd_push(r, "count");
    if (demo_rd_u8(r, &out->count)) {
        return -1;
    }
    demo_rd_pop(r);
    demo_rd_push(r, "rates");
    if (out->count > 10) {
        return demo_rd_count_error(r, (uint64_t)out->count, 10);
    }
    for (i = 0; i < (size_t)out->count; i++) {
        demo_rd_index(r, i);
        if (demo_rd_u16(r, &out->rates[i])) {
            return -1;
        }
    }
    demo_rd_pop(r);
    demo_rd_push(r, "name");
    if (demo_rd_chars(r, out->name, 8)) {
        return -1;
    }
    demo_rd_pop(r);
    demo_rd_push(r, "label");
    if (demo_rd_chars(r, out->label, 16)) {
        return -1;
    }
    demo_rd_pop(r);
    demo_rd_push(r, "matrix");
    for (i = 0; i < 9; i++) {
        demo_rd_index(r, i);
        if (demo_rd_f64(r, &out->matrix[i])) {
            return -1;
        }
    }
    demo_rd_pop(r);
    demo_rd_push(r, "fixed");
    for (i = 0; i < 4; i++) {
        demo_rd_index(r, i);
        if (demo_rd_s32(r, &out->fixed[i])) {
            return -1;
        }
    }
    demo_rd_pop(r);
    demo_rd_push(r, "flags");
    if (demo_rd_u16(r, &out->flags)) {
        return -1;
    }
    demo_rd_pop(r);
    demo_rd_push(r, "signed");
    if (demo_rd_s16(r, &out->signed_)) {
        return -1;
    }
    demo_rd_pop(r);
    demo_rd_push(r, "tail");
    if (demo_rd_remaining(r, 1, 135, &n)) {
        return -1;
    }
    for (i = 0; i < n; i++) {
        demo_rd_index(r, i);
        if (demo_rd_char(r, &out->tail[i])) {
            return -1;
        }
    }
    out->tail_count = n;
    demo_rd_pop(r);
    return demo_rd_finish(r);
}

static demo_status_t demo_commands_configuration_write(demo_writer_t *w,
                                                       const demo_commands_configuration_t *in) {
    demo_status_t st;
    size_t i;
    if ((st = demo_wr_u8(w, &in->instance)) != DEMO_OK) {
        return st;
    }
    if ((st = demo_wr_u8(w, &in->count)) != DEMO_OK) {
        return st;
    }
    if (in->count > 10) {
        return DEMO_ERR_INVALID;
    }
    for (i = 0; i < (size_t)in->count; i++) {
        if ((st = demo_wr_u16(w, &in->rates[i])) != DEMO_OK) {
            return st;
        }
    }
    if ((st = demo_wr_chars(w, in->name, 8)) != DEMO_OK) {
        return st;
    }
    if ((st = demo_wr_chars(w, in->label, 16)) != DEMO_OK) {
        return st;
    }
    for (i = 0; i < 9; i++) {
        if ((st = demo_wr_f64(w, &in->matrix[i])) != DEMO_OK) {
            return st;
        }
    }
    for (i = 0; i < 4; i++) {
        if ((st = demo_wr_s32(w, &in->fixed[i])) != DEMO_OK) {
            return st;
        }
    }
    if ((st = demo_wr_u16(w, &in->flags)) != DEMO_OK) {
        return st;
    }
    if ((st = demo_wr_s16(w, &in->signed_)) != DEMO_OK) {
        return st;
    }
    if (in->tail_count > 135) {
        return DEMO_ERR_INVALID;
    }
    for (i = 0; i < (size_t)in->tail_count; i++) {
        if ((st = demo_wr_char(w, &in->tail[i])) != DEMO_OK) {
            return st;
        }
    }
    return DEMO_OK;
}

demo_status_t demo_commands_configuration_encode(const demo_commands_configuration_t *value, uint8_t *buf,
                                                 size_t cap, size_t *len_out) {
    demo_writer_t w;
    demo_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    demo_writer_init(&w, buf, cap);
    st = demo_commands_configuration_write(&w, value);
    if (st == DEMO_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

demo_status_t demo_commands_configuration_decode(const uint8_t *data, size_t len,
                                                 demo_commands_configuration_t *out,
                                                 demo_decode_error_t *err) {
    demo_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    demo_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return demo_commands_configuration_read(&r, out) ? DEMO_ERR_DECODE : DEMO_OK;
}

void demo_commands_configuration_to_json(demo_jw_t *w, const demo_commands_configuration_t *in) {
    int first = 1;
    size_t i;
    demo_jw_raw(w, "{", 1);
    demo_jw_key(w, &first, "instance");
    demo_jw_u8(w, &in->instance);
    demo_jw_key(w, &first, "count");
    demo_jw_u8(w, &in->count);
    demo_jw_key(w, &first, "rates");
    demo_jw_raw(w, "[", 1);
    for (i = 0; i < (size_t)in->count && i < 10; i++) {
        demo_jw_sep(w, i);
        demo_jw_u16(w, &in->rates[i]);
    }
    demo_jw_raw(w, "]", 1);
    demo_jw_key(w, &first, "name");
    demo_jw_chars(w, in->name, 8);
    demo_jw_key(w, &first, "label");
    demo_jw_chars(w, in->label, 16);
    demo_jw_key(w, &first, "matrix");
    demo_jw_raw(w, "[", 1);
    for (i = 0; i < 9; i++) {
        demo_jw_sep(w, i);
        demo_jw_f64(w, &in->matrix[i]);
    }
    demo_jw_raw(w, "]", 1);
    demo_jw_key(w, &first, "fixed");
    demo_jw_raw(w, "[", 1);
    for (i = 0; i < 4; i++) {
        demo_jw_sep(w, i);
        demo_jw_s32(w, &in->fixed[i]);
    }
    demo_jw_raw(w, "]", 1);
    demo_jw_key(w, &first, "flags");
    demo_jw_u16(w, &in->flags);
    demo_jw_key(w, &first, "signed");
    demo_jw_s16(w, &in->signed_);
    demo_jw_key(w, &first, "tail");
    demo_jw_raw(w, "[", 1);
    for (i = 0; i < (size_t)in->tail_count && i < 135; i++) {
        demo_jw_sep(w, i);
        demo_jw_char(w, &in->tail[i]);
    }
    demo_jw_raw(w, "]", 1);
    demo_jw_raw(w, "}", 1);
}

int demo_commands_configuration_from_json(demo_jr_t *jr, size_t pos, demo_commands_configuration_t *out) {
    static const char *const keys[] = {"instance", "count", "rates", "name",   "label",
                                       "matrix",   "fixed", "flags", "signed", "tail"};
    size_t vp = 0;
    int found;
    size_t i;
    size_t it = 0;
    size_t ep = 0;
    memset(out, 0, sizeof *out);
    if (demo_jr_object(jr, pos, keys, 10)) {
        return -1;
    }
    found = demo_jr_get(jr, pos, "instance", &vp);
    if (found != 1) {
        return demo_jr_fail(jr, "missing parameter \"instance\"");
    }
    {
        demo_jr_push(jr, "instance");
        if (demo_jr_u8(jr, vp, &out->instance)) {
            return -1;
        }
        demo_jr_pop(jr);
    }
    found = demo_jr_get(jr, pos, "count", &vp);
    if (found != 1) {
        return demo_jr_fail(jr, "missing parameter \"count\"");
    }
    {
        demo_jr_push(jr, "count");
        if (demo_jr_u8(jr, vp, &out->count)) {
            return -1;
        }
        demo_jr_pop(jr);
    }
    found = demo_jr_get(jr, pos, "rates", &vp);
    if (found != 1) {
        return demo_jr_fail(jr, "missing parameter \"rates\"");
    }
    {
        demo_jr_push(jr, "rates");
        if (demo_jr_array(jr, vp, &it)) {
            return -1;
        }
        for (i = 0;; i++) {
            int more = demo_jr_next(jr, &it, &ep);
            if (more < 0) {
                return -1;
            }
            if (!more) {
                break;
            }
            if (i >= 10) {
                return demo_jr_fail(jr, "more than 10 elements");
            }
            demo_jr_index(jr, i);
            if (demo_jr_u16(jr, ep, &out->rates[i])) {
                return -1;
            }
        }
        demo_jr_index(jr, SIZE_MAX);
        if (i != (size_t)out->count) {
            return demo_jr_fail(jr, "%zu elements but count is %zu", i, (size_t)out->count);
        }
        demo_jr_pop(jr);
    }
    found = demo_jr_get(jr, pos, "name", &vp);
    if (found != 1) {
        return demo_jr_fail(jr, "missing parameter \"name\"");
    }
    {
        demo_jr_push(jr, "name");
        if (demo_jr_chars(jr, vp, out->name, 8)) {
            return -1;
        }
        demo_jr_pop(jr);
    }
    found = demo_jr_get(jr, pos, "label", &vp);
    if (found != 1) {
        return demo_jr_fail(jr, "missing parameter \"label\"");
    }
    {
        demo_jr_push(jr, "label");
        if (demo_jr_chars(jr, vp, out->label, 16)) {
            return -1;
        }
        demo_jr_pop(jr);
    }
    found = demo_jr_get(jr, pos, "matrix", &vp);
    if (found != 1) {
        return demo_jr_fail(jr, "missing parameter \"matrix\"");
    }
    {
        demo_jr_push(jr, "matrix");
        if (demo_jr_array(jr, vp, &it)) {
            return -1;
        }
        for (i = 0;; i++) {
            int more = demo_jr_next(jr, &it, &ep);
            if (more < 0) {
                return -1;
            }
            if (!more) {
                break;
            }
            if (i >= 9) {
                return demo_jr_fail(jr, "more than 9 elements");
            }
            demo_jr_index(jr, i);
            if (demo_jr_f64(jr, ep, &out->matrix[i])) {
                return -1;
            }
        }
        demo_jr_index(jr, SIZE_MAX);
        if (i != 9) {
            return demo_jr_fail(jr, "expected 9 elements, got %zu", i);
        }
        demo_jr_pop(jr);
    }
    found = demo_jr_get(jr, pos, "fixed", &vp);
    if (found != 1) {
        return demo_jr_fail(jr, "missing parameter \"fixed\"");
    }
    {
        demo_jr_push(jr, "fixed");
        if (demo_jr_array(jr, vp, &it)) {
            return -1;
        }
        for (i = 0;; i++) {
            int more = demo_jr_next(jr, &it, &ep);
            if (more < 0) {
                return -1;
            }
            if (!more) {
                break;
            }
            if (i >= 4) {
                return demo_jr_fail(jr, "more than 4 elements");
            }
            demo_jr_index(jr, i);
            if (demo_jr_s32(jr, ep, &out->fixed[i])) {
                return -1;
            }
        }
        demo_jr_index(jr, SIZE_MAX);
        if (i != 4) {
            return demo_jr_fail(jr, "expected 4 elements, got %zu", i);
        }
        demo_jr_pop(jr);
    }
    found = demo_jr_get(jr, pos, "flags", &vp);
    if (found != 1) {
        return demo_jr_fail(jr, "missing parameter \"flags\"");
    }
    {
        demo_jr_push(jr, "flags");
        if (demo_jr_u16(jr, vp, &out->flags)) {
            return -1;
        }
        demo_jr_pop(jr);
    }
    found = demo_jr_get(jr, pos, "signed", &vp);
    if (found != 1) {
        return demo_jr_fail(jr, "missing parameter \"signed\"");
    }
    {
        demo_jr_push(jr, "signed");
        if (demo_jr_s16(jr, vp, &out->signed_)) {
            return -1;
        }
        demo_jr_pop(jr);
    }
    found = demo_jr_get(jr, pos, "tail", &vp);
    if (found != 1) {
        return demo_jr_fail(jr, "missing parameter \"tail\"");
    }
    {
        demo_jr_push(jr, "tail");
        if (demo_jr_array(jr, vp, &it)) {
            return -1;
        }
        for (i = 0;; i++) {
            int more = demo_jr_next(jr, &it, &ep);
            if (more < 0) {
                return -1;
            }
            if (!more) {
                break;
            }
            if (i >= 135) {
                return demo_jr_fail(jr, "more than 135 elements");
            }
            demo_jr_index(jr, i);
            if (demo_jr_char(jr, ep, &out->tail[i])) {
                return -1;
            }
        }
        demo_jr_index(jr, SIZE_MAX);
        out->tail_count = i;
        demo_jr_pop(jr);
    }
    return 0;
}

/* ---- demo_commands_per_device_dev_a_t */

static int demo_commands_per_device_dev_a_read(demo_reader_t *r, demo_commands_per_device_dev_a_t *out) {
    demo_rd_push(r, "a");
    if (demo_rd_u32(r, &out->a)) {
        return -1;
    }
    demo_rd_pop(r);
    return demo_rd_finish(r);
}

static demo_status_t demo_commands_per_device_dev_a_write(demo_writer_t *w,
                                                          const demo_commands_per_device_dev_a_t *in) {
    demo_status_t st;
    if ((st = demo_wr_u32(w, &in->a)) != DEMO_OK) {
        return st;
    }
    return DEMO_OK;
}

demo_status_t demo_commands_per_device_dev_a_encode(const demo_commands_per_device_dev_a_t *value,
                                                    uint8_t *buf, size_t cap, size_t *len_out) {
    demo_writer_t w;
    demo_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    demo_writer_init(&w, buf, cap);
    st = demo_commands_per_device_dev_a_write(&w, value);
    if (st == DEMO_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 4 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int demo_commands_per_device_dev_a_load(const uint8_t *d, demo_commands_per_device_dev_a_t *out) {
    out->a = demo_ld_u32(d + 0);
    return 0;
}

/* The general reader: lengths other than 4, bad bool bytes, error details. */
static DEMO_NOINLINE demo_status_t demo_commands_per_device_dev_a_decode_read(
    const uint8_t *data, size_t len, demo_commands_per_device_dev_a_t *out, demo_decode_error_t *err) {
    demo_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    demo_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return demo_commands_per_device_dev_a_read(&r, out) ? DEMO_ERR_DECODE : DEMO_OK;
}

demo_status_t demo_commands_per_device_dev_a_decode(const uint8_t *data, size_t len,
                                                    demo_commands_per_device_dev_a_t *out,
                                                    demo_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 4 && demo_commands_per_device_dev_a_load(data, out) == 0) {
        return DEMO_OK;
    }
    return demo_commands_per_device_dev_a_decode_read(data, len, out, err);
}

void demo_commands_per_device_dev_a_to_json(demo_jw_t *w, const demo_commands_per_device_dev_a_t *in) {
    int first = 1;
    demo_jw_raw(w, "{", 1);
    demo_jw_key(w, &first, "a");
    demo_jw_u32(w, &in->a);
    demo_jw_raw(w, "}", 1);
}

int demo_commands_per_device_dev_a_from_json(demo_jr_t *jr, size_t pos,
                                             demo_commands_per_device_dev_a_t *out) {
    static const char *const keys[] = {"a"};
    size_t vp = 0;
    int found;
    memset(out, 0, sizeof *out);
    if (demo_jr_object(jr, pos, keys, 1)) {
        return -1;
    }
    found = demo_jr_get(jr, pos, "a", &vp);
    if (found != 1) {
        return demo_jr_fail(jr, "missing parameter \"a\"");
    }
    {
        demo_jr_push(jr, "a");
        if (demo_jr_u32(jr, vp, &out->a)) {
            return -1;
        }
        demo_jr_pop(jr);
    }
    return 0;
}

/* ---- demo_commands_per_device_dev_b_t */

static int demo_commands_per_device_dev_b_read(demo_reader_t *r, demo_commands_per_device_dev_b_t *out) {
    demo_rd_push(r, "b");
    if (demo_rd_u64(r, &out->b)) {
        return -1;
    }
    demo_rd_pop(r);
    if (r->pos < r->len) {
        out->has_extra = true;
        demo_rd_push(r, "extra");
        if (demo_rd_u8(r, &out->extra)) {
            return -1;
        }
        demo_rd_pop(r);
    }
    return demo_rd_finish(r);
}

static demo_status_t demo_commands_per_device_dev_b_write(demo_writer_t *w,
                                                          const demo_commands_per_device_dev_b_t *in) {
    demo_status_t st;
    int absent = 0;
    if ((st = demo_wr_u64(w, &in->b)) != DEMO_OK) {
        return st;
    }
    if (!in->has_extra) {
        absent = 1;
    } else if (absent) {
        return DEMO_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = demo_wr_u8(w, &in->extra)) != DEMO_OK) {
            return st;
        }
    }
    return DEMO_OK;
}

demo_status_t demo_commands_per_device_dev_b_encode(const demo_commands_per_device_dev_b_t *value,
                                                    uint8_t *buf, size_t cap, size_t *len_out) {
    demo_writer_t w;
    demo_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    demo_writer_init(&w, buf, cap);
    st = demo_commands_per_device_dev_b_write(&w, value);
    if (st == DEMO_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

demo_status_t demo_commands_per_device_dev_b_decode(const uint8_t *data, size_t len,
                                                    demo_commands_per_device_dev_b_t *out,
                                                    demo_decode_error_t *err) {
    demo_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    demo_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return demo_commands_per_device_dev_b_read(&r, out) ? DEMO_ERR_DECODE : DEMO_OK;
}

void demo_commands_per_device_dev_b_to_json(demo_jw_t *w, const demo_commands_per_device_dev_b_t *in) {
    int first = 1;
    demo_jw_raw(w, "{", 1);
    demo_jw_key(w, &first, "b");
    demo_jw_u64(w, &in->b);
    if (in->has_extra) {
        demo_jw_key(w, &first, "extra");
        demo_jw_u8(w, &in->extra);
    }
    demo_jw_raw(w, "}", 1);
}

int demo_commands_per_device_dev_b_from_json(demo_jr_t *jr, size_t pos,
                                             demo_commands_per_device_dev_b_t *out) {
    static const char *const keys[] = {"b", "extra"};
    size_t vp = 0;
    int found;
    int absent = 0;
    memset(out, 0, sizeof *out);
    if (demo_jr_object(jr, pos, keys, 2)) {
        return -1;
    }
    found = demo_jr_get(jr, pos, "b", &vp);
    if (found != 1) {
        return demo_jr_fail(jr, "missing parameter \"b\"");
    }
    {
        demo_jr_push(jr, "b");
        if (demo_jr_u64(jr, vp, &out->b)) {
            return -1;
        }
        demo_jr_pop(jr);
    }
    found = demo_jr_get(jr, pos, "extra", &vp);
    out->has_extra = found == 1;
    if (found != 1) {
        absent = 1;
    } else if (absent) {
        return demo_jr_fail(jr, "optional parameter \"extra\" given after an absent one");
    } else {
        demo_jr_push(jr, "extra");
        if (demo_jr_u8(jr, vp, &out->extra)) {
            return -1;
        }
        demo_jr_pop(jr);
    }
    return 0;
}
