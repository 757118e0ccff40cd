/* Encoders and decoders of 3DM Command Set. Generated from the spec: do not edit. */
#include "mipcodec/sets/threedm.h"
#include "layouts_internal.h"
#include "types_internal.h"

#include <assert.h>
#include <string.h>

/* ---- mipc_threedm_event_control_t */

static int mipc_threedm_event_control_read(mipc_reader_t *r, mipc_threedm_event_control_t *out) {
    mipc_rd_push(r, "function");
    if (mipc_rd_u8(r, &out->function)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "instance");
    if (mipc_rd_u8(r, &out->instance)) {
        return -1;
    }
    mipc_rd_pop(r);
    if (r->pos < r->len) {
        out->has_mode = true;
        mipc_rd_push(r, "mode");
        if (mipc_rd_u8(r, &out->mode)) {
            return -1;
        }
        mipc_rd_pop(r);
    }
    return mipc_rd_finish(r);
}

static mipc_status_t mipc_threedm_event_control_write(mipc_writer_t *w,
                                                      const mipc_threedm_event_control_t *in) {
    mipc_status_t st;
    int absent = 0;
    if ((st = mipc_wr_u8(w, &in->function)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u8(w, &in->instance)) != MIPC_OK) {
        return st;
    }
    if (!in->has_mode) {
        absent = 1;
    } else if (absent) {
        return MIPC_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = mipc_wr_u8(w, &in->mode)) != MIPC_OK) {
            return st;
        }
    }
    return MIPC_OK;
}

mipc_status_t mipc_threedm_event_control_encode(const mipc_threedm_event_control_t *value, uint8_t *buf,
                                                size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mipc_writer_init(&w, buf, cap);
    st = mipc_threedm_event_control_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mipc_status_t mipc_threedm_event_control_decode(const uint8_t *data, size_t len,
                                                mipc_threedm_event_control_t *out, mipc_decode_error_t *err) {
    mipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_threedm_event_control_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

/* ---- mipc_threedm_event_control_response_t */

static int mipc_threedm_event_control_response_read(mipc_reader_t *r,
                                                    mipc_threedm_event_control_response_t *out) {
    mipc_rd_push(r, "instance");
    if (mipc_rd_u8(r, &out->instance)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "mode");
    if (mipc_rd_u8(r, &out->mode)) {
        return -1;
    }
    mipc_rd_pop(r);
    return mipc_rd_finish(r);
}

static mipc_status_t
mipc_threedm_event_control_response_write(mipc_writer_t *w, const mipc_threedm_event_control_response_t *in) {
    mipc_status_t st;
    if ((st = mipc_wr_u8(w, &in->instance)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u8(w, &in->mode)) != MIPC_OK) {
        return st;
    }
    return MIPC_OK;
}

mipc_status_t mipc_threedm_event_control_response_encode(const mipc_threedm_event_control_response_t *value,
                                                         uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mipc_writer_init(&w, buf, cap);
    st = mipc_threedm_event_control_response_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 2 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mipc_threedm_event_control_response_load(const uint8_t *d,
                                                    mipc_threedm_event_control_response_t *out) {
    out->instance = mipc_ld_u8(d + 0);
    out->mode = mipc_ld_u8(d + 1);
    return 0;
}

/* The general reader: lengths other than 2, bad bool bytes, error details. */
static MIPC_NOINLINE mipc_status_t mipc_threedm_event_control_response_decode_read(
    const uint8_t *data, size_t len, mipc_threedm_event_control_response_t *out, mipc_decode_error_t *err) {
    mipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_threedm_event_control_response_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t mipc_threedm_event_control_response_decode(const uint8_t *data, size_t len,
                                                         mipc_threedm_event_control_response_t *out,
                                                         mipc_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 2 && mipc_threedm_event_control_response_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_threedm_event_control_response_decode_read(data, len, out, err);
}

/* ---- mipc_threedm_get_event_trigger_status_t */

static int mipc_threedm_get_event_trigger_status_read(mipc_reader_t *r,
                                                      mipc_threedm_get_event_trigger_status_t *out) {
    size_t i;
    mipc_rd_push(r, "requested_count");
    if (mipc_rd_u8(r, &out->requested_count)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "requested_instances");
    if (out->requested_count > 252) {
        return mipc_rd_count_error(r, (uint64_t)out->requested_count, 252);
    }
    for (i = 0; i < (size_t)out->requested_count; i++) {
        mipc_rd_index(r, i);
        if (mipc_rd_u8(r, &out->requested_instances[i])) {
            return -1;
        }
    }
    mipc_rd_pop(r);
    return mipc_rd_finish(r);
}

static mipc_status_t
mipc_threedm_get_event_trigger_status_write(mipc_writer_t *w,
                                            const mipc_threedm_get_event_trigger_status_t *in) {
    mipc_status_t st;
    size_t i;
    if ((st = mipc_wr_u8(w, &in->requested_count)) != MIPC_OK) {
        return st;
    }
    if (in->requested_count > 252) {
        return MIPC_ERR_INVALID;
    }
    for (i = 0; i < (size_t)in->requested_count; i++) {
        if ((st = mipc_wr_u8(w, &in->requested_instances[i])) != MIPC_OK) {
            return st;
        }
    }
    return MIPC_OK;
}

mipc_status_t
mipc_threedm_get_event_trigger_status_encode(const mipc_threedm_get_event_trigger_status_t *value,
                                             uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mipc_writer_init(&w, buf, cap);
    st = mipc_threedm_get_event_trigger_status_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mipc_status_t mipc_threedm_get_event_trigger_status_decode(const uint8_t *data, size_t len,
                                                           mipc_threedm_get_event_trigger_status_t *out,
                                                           mipc_decode_error_t *err) {
    mipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_threedm_get_event_trigger_status_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

/* ---- mipc_threedm_event_trigger_status_t */

static int mipc_threedm_event_trigger_status_read(mipc_reader_t *r,
                                                  mipc_threedm_event_trigger_status_t *out) {
    size_t i;
    mipc_rd_push(r, "count");
    if (mipc_rd_u8(r, &out->count)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "triggers");
    if (out->count > 126) {
        return mipc_rd_count_error(r, (uint64_t)out->count, 126);
    }
    for (i = 0; i < (size_t)out->count; i++) {
        mipc_rd_index(r, i);
        if (mipc_trigger_status_entry_read(r, &out->triggers[i])) {
            return -1;
        }
    }
    mipc_rd_pop(r);
    return mipc_rd_finish(r);
}

static mipc_status_t mipc_threedm_event_trigger_status_write(mipc_writer_t *w,
                                                             const mipc_threedm_event_trigger_status_t *in) {
    mipc_status_t st;
    size_t i;
    if ((st = mipc_wr_u8(w, &in->count)) != MIPC_OK) {
        return st;
    }
    if (in->count > 126) {
        return MIPC_ERR_INVALID;
    }
    for (i = 0; i < (size_t)in->count; i++) {
        if ((st = mipc_trigger_status_entry_write(w, &in->triggers[i])) != MIPC_OK) {
            return st;
        }
    }
    return MIPC_OK;
}

mipc_status_t mipc_threedm_event_trigger_status_encode(const mipc_threedm_event_trigger_status_t *value,
                                                       uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mipc_writer_init(&w, buf, cap);
    st = mipc_threedm_event_trigger_status_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mipc_status_t mipc_threedm_event_trigger_status_decode(const uint8_t *data, size_t len,
                                                       mipc_threedm_event_trigger_status_t *out,
                                                       mipc_decode_error_t *err) {
    mipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_threedm_event_trigger_status_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

/* ---- mipc_threedm_get_event_action_status_t */

static int mipc_threedm_get_event_action_status_read(mipc_reader_t *r,
                                                     mipc_threedm_get_event_action_status_t *out) {
    size_t i;
    mipc_rd_push(r, "requested_count");
    if (mipc_rd_u8(r, &out->requested_count)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "requested_instances");
    if (out->requested_count > 252) {
        return mipc_rd_count_error(r, (uint64_t)out->requested_count, 252);
    }
    for (i = 0; i < (size_t)out->requested_count; i++) {
        mipc_rd_index(r, i);
        if (mipc_rd_u8(r, &out->requested_instances[i])) {
            return -1;
        }
    }
    mipc_rd_pop(r);
    return mipc_rd_finish(r);
}

static mipc_status_t
mipc_threedm_get_event_action_status_write(mipc_writer_t *w,
                                           const mipc_threedm_get_event_action_status_t *in) {
    mipc_status_t st;
    size_t i;
    if ((st = mipc_wr_u8(w, &in->requested_count)) != MIPC_OK) {
        return st;
    }
    if (in->requested_count > 252) {
        return MIPC_ERR_INVALID;
    }
    for (i = 0; i < (size_t)in->requested_count; i++) {
        if ((st = mipc_wr_u8(w, &in->requested_instances[i])) != MIPC_OK) {
            return st;
        }
    }
    return MIPC_OK;
}

mipc_status_t mipc_threedm_get_event_action_status_encode(const mipc_threedm_get_event_action_status_t *value,
                                                          uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mipc_writer_init(&w, buf, cap);
    st = mipc_threedm_get_event_action_status_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mipc_status_t mipc_threedm_get_event_action_status_decode(const uint8_t *data, size_t len,
                                                          mipc_threedm_get_event_action_status_t *out,
                                                          mipc_decode_error_t *err) {
    mipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_threedm_get_event_action_status_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

/* ---- mipc_threedm_event_action_status_t */

static int mipc_threedm_event_action_status_read(mipc_reader_t *r, mipc_threedm_event_action_status_t *out) {
    size_t i;
    mipc_rd_push(r, "count");
    if (mipc_rd_u8(r, &out->count)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "actions");
    if (out->count > 126) {
        return mipc_rd_count_error(r, (uint64_t)out->count, 126);
    }
    for (i = 0; i < (size_t)out->count; i++) {
        mipc_rd_index(r, i);
        if (mipc_action_status_entry_read(r, &out->actions[i])) {
            return -1;
        }
    }
    mipc_rd_pop(r);
    return mipc_rd_finish(r);
}

static mipc_status_t mipc_threedm_event_action_status_write(mipc_writer_t *w,
                                                            const mipc_threedm_event_action_status_t *in) {
    mipc_status_t st;
    size_t i;
    if ((st = mipc_wr_u8(w, &in->count)) != MIPC_OK) {
        return st;
    }
    if (in->count > 126) {
        return MIPC_ERR_INVALID;
    }
    for (i = 0; i < (size_t)in->count; i++) {
        if ((st = mipc_action_status_entry_write(w, &in->actions[i])) != MIPC_OK) {
            return st;
        }
    }
    return MIPC_OK;
}

mipc_status_t mipc_threedm_event_action_status_encode(const mipc_threedm_event_action_status_t *value,
                                                      uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mipc_writer_init(&w, buf, cap);
    st = mipc_threedm_event_action_status_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mipc_status_t mipc_threedm_event_action_status_decode(const uint8_t *data, size_t len,
                                                      mipc_threedm_event_action_status_t *out,
                                                      mipc_decode_error_t *err) {
    mipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_threedm_event_action_status_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

/* ---- mipc_threedm_event_trigger_config_t */

static int mipc_threedm_event_trigger_config_read(mipc_reader_t *r,
                                                  mipc_threedm_event_trigger_config_t *out) {
    mipc_rd_push(r, "function");
    if (mipc_rd_u8(r, &out->function)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "instance");
    if (mipc_rd_u8(r, &out->instance)) {
        return -1;
    }
    mipc_rd_pop(r);
    if (r->pos < r->len) {
        out->has_type = true;
        mipc_rd_push(r, "type");
        if (mipc_rd_u8(r, &out->type)) {
            return -1;
        }
        mipc_rd_pop(r);
    }
    if (r->pos < r->len) {
        out->has_parameters = true;
        mipc_rd_push(r, "parameters");
        if (mipc_trigger_params_read(r, out->type, &out->parameters)) {
            return -1;
        }
        mipc_rd_pop(r);
    }
    return mipc_rd_finish(r);
}

static mipc_status_t mipc_threedm_event_trigger_config_write(mipc_writer_t *w,
                                                             const mipc_threedm_event_trigger_config_t *in) {
    mipc_status_t st;
    int absent = 0;
    if ((st = mipc_wr_u8(w, &in->function)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u8(w, &in->instance)) != MIPC_OK) {
        return st;
    }
    if (!in->has_type) {
        absent = 1;
    } else if (absent) {
        return MIPC_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = mipc_wr_u8(w, &in->type)) != MIPC_OK) {
            return st;
        }
    }
    if (!in->has_parameters) {
        absent = 1;
    } else if (absent) {
        return MIPC_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = mipc_trigger_params_write(w, in->type, &in->parameters)) != MIPC_OK) {
            return st;
        }
    }
    return MIPC_OK;
}

mipc_status_t mipc_threedm_event_trigger_config_encode(const mipc_threedm_event_trigger_config_t *value,
                                                       uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mipc_writer_init(&w, buf, cap);
    st = mipc_threedm_event_trigger_config_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mipc_status_t mipc_threedm_event_trigger_config_decode(const uint8_t *data, size_t len,
                                                       mipc_threedm_event_trigger_config_t *out,
                                                       mipc_decode_error_t *err) {
    mipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_threedm_event_trigger_config_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

/* ---- mipc_threedm_event_trigger_config_response_t */

static int
mipc_threedm_event_trigger_config_response_read(mipc_reader_t *r,
                                                mipc_threedm_event_trigger_config_response_t *out) {
    mipc_rd_push(r, "instance");
    if (mipc_rd_u8(r, &out->instance)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "type");
    if (mipc_rd_u8(r, &out->type)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "parameters");
    if (mipc_trigger_params_read(r, out->type, &out->parameters)) {
        return -1;
    }
    mipc_rd_pop(r);
    return mipc_rd_finish(r);
}

static mipc_status_t
mipc_threedm_event_trigger_config_response_write(mipc_writer_t *w,
                                                 const mipc_threedm_event_trigger_config_response_t *in) {
    mipc_status_t st;
    if ((st = mipc_wr_u8(w, &in->instance)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u8(w, &in->type)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_trigger_params_write(w, in->type, &in->parameters)) != MIPC_OK) {
        return st;
    }
    return MIPC_OK;
}

mipc_status_t
mipc_threedm_event_trigger_config_response_encode(const mipc_threedm_event_trigger_config_response_t *value,
                                                  uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mipc_writer_init(&w, buf, cap);
    st = mipc_threedm_event_trigger_config_response_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mipc_status_t
mipc_threedm_event_trigger_config_response_decode(const uint8_t *data, size_t len,
                                                  mipc_threedm_event_trigger_config_response_t *out,
                                                  mipc_decode_error_t *err) {
    mipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_threedm_event_trigger_config_response_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

/* ---- mipc_threedm_event_action_config_t */

static int mipc_threedm_event_action_config_read(mipc_reader_t *r, mipc_threedm_event_action_config_t *out) {
    mipc_rd_push(r, "function");
    if (mipc_rd_u8(r, &out->function)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "instance");
    if (mipc_rd_u8(r, &out->instance)) {
        return -1;
    }
    mipc_rd_pop(r);
    if (r->pos < r->len) {
        out->has_trigger = true;
        mipc_rd_push(r, "trigger");
        if (mipc_rd_u8(r, &out->trigger)) {
            return -1;
        }
        mipc_rd_pop(r);
    }
    if (r->pos < r->len) {
        out->has_type = true;
        mipc_rd_push(r, "type");
        if (mipc_rd_u8(r, &out->type)) {
            return -1;
        }
        mipc_rd_pop(r);
    }
    if (r->pos < r->len) {
        out->has_parameters = true;
        mipc_rd_push(r, "parameters");
        if (mipc_action_params_read(r, out->type, &out->parameters)) {
            return -1;
        }
        mipc_rd_pop(r);
    }
    return mipc_rd_finish(r);
}

static mipc_status_t mipc_threedm_event_action_config_write(mipc_writer_t *w,
                                                            const mipc_threedm_event_action_config_t *in) {
    mipc_status_t st;
    int absent = 0;
    if ((st = mipc_wr_u8(w, &in->function)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u8(w, &in->instance)) != MIPC_OK) {
        return st;
    }
    if (!in->has_trigger) {
        absent = 1;
    } else if (absent) {
        return MIPC_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = mipc_wr_u8(w, &in->trigger)) != MIPC_OK) {
            return st;
        }
    }
    if (!in->has_type) {
        absent = 1;
    } else if (absent) {
        return MIPC_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = mipc_wr_u8(w, &in->type)) != MIPC_OK) {
            return st;
        }
    }
    if (!in->has_parameters) {
        absent = 1;
    } else if (absent) {
        return MIPC_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = mipc_action_params_write(w, in->type, &in->parameters)) != MIPC_OK) {
            return st;
        }
    }
    return MIPC_OK;
}

mipc_status_t mipc_threedm_event_action_config_encode(const mipc_threedm_event_action_config_t *value,
                                                      uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mipc_writer_init(&w, buf, cap);
    st = mipc_threedm_event_action_config_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mipc_status_t mipc_threedm_event_action_config_decode(const uint8_t *data, size_t len,
                                                      mipc_threedm_event_action_config_t *out,
                                                      mipc_decode_error_t *err) {
    mipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_threedm_event_action_config_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

/* ---- mipc_threedm_event_action_config_response_t */

static int mipc_threedm_event_action_config_response_read(mipc_reader_t *r,
                                                          mipc_threedm_event_action_config_response_t *out) {
    mipc_rd_push(r, "instance");
    if (mipc_rd_u8(r, &out->instance)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "trigger");
    if (mipc_rd_u8(r, &out->trigger)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "type");
    if (mipc_rd_u8(r, &out->type)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "parameters");
    if (mipc_action_params_read(r, out->type, &out->parameters)) {
        return -1;
    }
    mipc_rd_pop(r);
    return mipc_rd_finish(r);
}

static mipc_status_t
mipc_threedm_event_action_config_response_write(mipc_writer_t *w,
                                                const mipc_threedm_event_action_config_response_t *in) {
    mipc_status_t st;
    if ((st = mipc_wr_u8(w, &in->instance)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u8(w, &in->trigger)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u8(w, &in->type)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_action_params_write(w, in->type, &in->parameters)) != MIPC_OK) {
        return st;
    }
    return MIPC_OK;
}

mipc_status_t
mipc_threedm_event_action_config_response_encode(const mipc_threedm_event_action_config_response_t *value,
                                                 uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mipc_writer_init(&w, buf, cap);
    st = mipc_threedm_event_action_config_response_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mipc_status_t
mipc_threedm_event_action_config_response_decode(const uint8_t *data, size_t len,
                                                 mipc_threedm_event_action_config_response_t *out,
                                                 mipc_decode_error_t *err) {
    mipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_threedm_event_action_config_response_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

/* ---- mipc_threedm_device_startup_settings_gx5_45_t */

static int
mipc_threedm_device_startup_settings_gx5_45_read(mipc_reader_t *r,
                                                 mipc_threedm_device_startup_settings_gx5_45_t *out) {
    mipc_rd_push(r, "function");
    if (mipc_rd_u8(r, &out->function)) {
        return -1;
    }
    mipc_rd_pop(r);
    return mipc_rd_finish(r);
}

static mipc_status_t
mipc_threedm_device_startup_settings_gx5_45_write(mipc_writer_t *w,
                                                  const mipc_threedm_device_startup_settings_gx5_45_t *in) {
    mipc_status_t st;
    if ((st = mipc_wr_u8(w, &in->function)) != MIPC_OK) {
        return st;
    }
    return MIPC_OK;
}

mipc_status_t
mipc_threedm_device_startup_settings_gx5_45_encode(const mipc_threedm_device_startup_settings_gx5_45_t *value,
                                                   uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mipc_writer_init(&w, buf, cap);
    st = mipc_threedm_device_startup_settings_gx5_45_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 1 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int
mipc_threedm_device_startup_settings_gx5_45_load(const uint8_t *d,
                                                 mipc_threedm_device_startup_settings_gx5_45_t *out) {
    out->function = mipc_ld_u8(d + 0);
    return 0;
}

/* The general reader: lengths other than 1, bad bool bytes, error details. */
static MIPC_NOINLINE mipc_status_t mipc_threedm_device_startup_settings_gx5_45_decode_read(
    const uint8_t *data, size_t len, mipc_threedm_device_startup_settings_gx5_45_t *out,
    mipc_decode_error_t *err) {
    mipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_threedm_device_startup_settings_gx5_45_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t
mipc_threedm_device_startup_settings_gx5_45_decode(const uint8_t *data, size_t len,
                                                   mipc_threedm_device_startup_settings_gx5_45_t *out,
                                                   mipc_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 1 && mipc_threedm_device_startup_settings_gx5_45_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_threedm_device_startup_settings_gx5_45_decode_read(data, len, out, err);
}

/* ---- mipc_threedm_device_startup_settings_cv7_ins_t */

static int
mipc_threedm_device_startup_settings_cv7_ins_read(mipc_reader_t *r,
                                                  mipc_threedm_device_startup_settings_cv7_ins_t *out) {
    mipc_rd_push(r, "function");
    if (mipc_rd_u8(r, &out->function)) {
        return -1;
    }
    mipc_rd_pop(r);
    return mipc_rd_finish(r);
}

static mipc_status_t
mipc_threedm_device_startup_settings_cv7_ins_write(mipc_writer_t *w,
                                                   const mipc_threedm_device_startup_settings_cv7_ins_t *in) {
    mipc_status_t st;
    if ((st = mipc_wr_u8(w, &in->function)) != MIPC_OK) {
        return st;
    }
    return MIPC_OK;
}

mipc_status_t mipc_threedm_device_startup_settings_cv7_ins_encode(
    const mipc_threedm_device_startup_settings_cv7_ins_t *value, uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mipc_writer_init(&w, buf, cap);
    st = mipc_threedm_device_startup_settings_cv7_ins_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 1 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int
mipc_threedm_device_startup_settings_cv7_ins_load(const uint8_t *d,
                                                  mipc_threedm_device_startup_settings_cv7_ins_t *out) {
    out->function = mipc_ld_u8(d + 0);
    return 0;
}

/* The general reader: lengths other than 1, bad bool bytes, error details. */
static MIPC_NOINLINE mipc_status_t mipc_threedm_device_startup_settings_cv7_ins_decode_read(
    const uint8_t *data, size_t len, mipc_threedm_device_startup_settings_cv7_ins_t *out,
    mipc_decode_error_t *err) {
    mipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_threedm_device_startup_settings_cv7_ins_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t
mipc_threedm_device_startup_settings_cv7_ins_decode(const uint8_t *data, size_t len,
                                                    mipc_threedm_device_startup_settings_cv7_ins_t *out,
                                                    mipc_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 1 && mipc_threedm_device_startup_settings_cv7_ins_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_threedm_device_startup_settings_cv7_ins_decode_read(data, len, out, err);
}

/* ---- mipc_threedm_sensor_to_vehicle_euler_t */

static int mipc_threedm_sensor_to_vehicle_euler_read(mipc_reader_t *r,
                                                     mipc_threedm_sensor_to_vehicle_euler_t *out) {
    mipc_rd_push(r, "function");
    if (mipc_rd_u8(r, &out->function)) {
        return -1;
    }
    mipc_rd_pop(r);
    if (r->pos < r->len) {
        out->has_roll = true;
        mipc_rd_push(r, "roll");
        if (mipc_rd_f32(r, &out->roll)) {
            return -1;
        }
        mipc_rd_pop(r);
    }
    if (r->pos < r->len) {
        out->has_pitch = true;
        mipc_rd_push(r, "pitch");
        if (mipc_rd_f32(r, &out->pitch)) {
            return -1;
        }
        mipc_rd_pop(r);
    }
    if (r->pos < r->len) {
        out->has_yaw = true;
        mipc_rd_push(r, "yaw");
        if (mipc_rd_f32(r, &out->yaw)) {
            return -1;
        }
        mipc_rd_pop(r);
    }
    return mipc_rd_finish(r);
}

static mipc_status_t
mipc_threedm_sensor_to_vehicle_euler_write(mipc_writer_t *w,
                                           const mipc_threedm_sensor_to_vehicle_euler_t *in) {
    mipc_status_t st;
    int absent = 0;
    if ((st = mipc_wr_u8(w, &in->function)) != MIPC_OK) {
        return st;
    }
    if (!in->has_roll) {
        absent = 1;
    } else if (absent) {
        return MIPC_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = mipc_wr_f32(w, &in->roll)) != MIPC_OK) {
            return st;
        }
    }
    if (!in->has_pitch) {
        absent = 1;
    } else if (absent) {
        return MIPC_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = mipc_wr_f32(w, &in->pitch)) != MIPC_OK) {
            return st;
        }
    }
    if (!in->has_yaw) {
        absent = 1;
    } else if (absent) {
        return MIPC_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = mipc_wr_f32(w, &in->yaw)) != MIPC_OK) {
            return st;
        }
    }
    return MIPC_OK;
}

mipc_status_t mipc_threedm_sensor_to_vehicle_euler_encode(const mipc_threedm_sensor_to_vehicle_euler_t *value,
                                                          uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mipc_writer_init(&w, buf, cap);
    st = mipc_threedm_sensor_to_vehicle_euler_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mipc_status_t mipc_threedm_sensor_to_vehicle_euler_decode(const uint8_t *data, size_t len,
                                                          mipc_threedm_sensor_to_vehicle_euler_t *out,
                                                          mipc_decode_error_t *err) {
    mipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_threedm_sensor_to_vehicle_euler_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

/* ---- mipc_threedm_sensor_to_vehicle_euler_response_t */

static int
mipc_threedm_sensor_to_vehicle_euler_response_read(mipc_reader_t *r,
                                                   mipc_threedm_sensor_to_vehicle_euler_response_t *out) {
    mipc_rd_push(r, "roll");
    if (mipc_rd_f32(r, &out->roll)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "pitch");
    if (mipc_rd_f32(r, &out->pitch)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "yaw");
    if (mipc_rd_f32(r, &out->yaw)) {
        return -1;
    }
    mipc_rd_pop(r);
    return mipc_rd_finish(r);
}

static mipc_status_t mipc_threedm_sensor_to_vehicle_euler_response_write(
    mipc_writer_t *w, const mipc_threedm_sensor_to_vehicle_euler_response_t *in) {
    mipc_status_t st;
    if ((st = mipc_wr_f32(w, &in->roll)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_f32(w, &in->pitch)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_f32(w, &in->yaw)) != MIPC_OK) {
        return st;
    }
    return MIPC_OK;
}

mipc_status_t mipc_threedm_sensor_to_vehicle_euler_response_encode(
    const mipc_threedm_sensor_to_vehicle_euler_response_t *value, uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mipc_writer_init(&w, buf, cap);
    st = mipc_threedm_sensor_to_vehicle_euler_response_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 12 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int
mipc_threedm_sensor_to_vehicle_euler_response_load(const uint8_t *d,
                                                   mipc_threedm_sensor_to_vehicle_euler_response_t *out) {
    out->roll = mipc_ld_f32(d + 0);
    out->pitch = mipc_ld_f32(d + 4);
    out->yaw = mipc_ld_f32(d + 8);
    return 0;
}

/* The general reader: lengths other than 12, bad bool bytes, error details. */
static MIPC_NOINLINE mipc_status_t mipc_threedm_sensor_to_vehicle_euler_response_decode_read(
    const uint8_t *data, size_t len, mipc_threedm_sensor_to_vehicle_euler_response_t *out,
    mipc_decode_error_t *err) {
    mipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_threedm_sensor_to_vehicle_euler_response_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t
mipc_threedm_sensor_to_vehicle_euler_response_decode(const uint8_t *data, size_t len,
                                                     mipc_threedm_sensor_to_vehicle_euler_response_t *out,
                                                     mipc_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 12 && mipc_threedm_sensor_to_vehicle_euler_response_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_threedm_sensor_to_vehicle_euler_response_decode_read(data, len, out, err);
}

/* ---- mipc_threedm_sensor_to_vehicle_quaternion_t */

static int mipc_threedm_sensor_to_vehicle_quaternion_read(mipc_reader_t *r,
                                                          mipc_threedm_sensor_to_vehicle_quaternion_t *out) {
    size_t i;
    mipc_rd_push(r, "function");
    if (mipc_rd_u8(r, &out->function)) {
        return -1;
    }
    mipc_rd_pop(r);
    if (r->pos < r->len) {
        out->has_q = true;
        mipc_rd_push(r, "q");
        for (i = 0; i < 4; i++) {
            mipc_rd_index(r, i);
            if (mipc_rd_f32(r, &out->q[i])) {
                return -1;
            }
        }
        mipc_rd_pop(r);
    }
    return mipc_rd_finish(r);
}

static mipc_status_t
mipc_threedm_sensor_to_vehicle_quaternion_write(mipc_writer_t *w,
                                                const mipc_threedm_sensor_to_vehicle_quaternion_t *in) {
    mipc_status_t st;
    size_t i;
    int absent = 0;
    if ((st = mipc_wr_u8(w, &in->function)) != MIPC_OK) {
        return st;
    }
    if (!in->has_q) {
        absent = 1;
    } else if (absent) {
        return MIPC_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        for (i = 0; i < 4; i++) {
            if ((st = mipc_wr_f32(w, &in->q[i])) != MIPC_OK) {
                return st;
            }
        }
    }
    return MIPC_OK;
}

mipc_status_t
mipc_threedm_sensor_to_vehicle_quaternion_encode(const mipc_threedm_sensor_to_vehicle_quaternion_t *value,
                                                 uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mipc_writer_init(&w, buf, cap);
    st = mipc_threedm_sensor_to_vehicle_quaternion_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mipc_status_t
mipc_threedm_sensor_to_vehicle_quaternion_decode(const uint8_t *data, size_t len,
                                                 mipc_threedm_sensor_to_vehicle_quaternion_t *out,
                                                 mipc_decode_error_t *err) {
    mipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_threedm_sensor_to_vehicle_quaternion_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

/* ---- mipc_threedm_sensor_to_vehicle_quaternion_response_t */

static int mipc_threedm_sensor_to_vehicle_quaternion_response_read(
    mipc_reader_t *r, mipc_threedm_sensor_to_vehicle_quaternion_response_t *out) {
    size_t i;
    mipc_rd_push(r, "q");
    for (i = 0; i < 4; i++) {
        mipc_rd_index(r, i);
        if (mipc_rd_f32(r, &out->q[i])) {
            return -1;
        }
    }
    mipc_rd_pop(r);
    return mipc_rd_finish(r);
}

static mipc_status_t mipc_threedm_sensor_to_vehicle_quaternion_response_write(
    mipc_writer_t *w, const mipc_threedm_sensor_to_vehicle_quaternion_response_t *in) {
    mipc_status_t st;
    size_t i;
    for (i = 0; i < 4; i++) {
        if ((st = mipc_wr_f32(w, &in->q[i])) != MIPC_OK) {
            return st;
        }
    }
    return MIPC_OK;
}

mipc_status_t mipc_threedm_sensor_to_vehicle_quaternion_response_encode(
    const mipc_threedm_sensor_to_vehicle_quaternion_response_t *value, uint8_t *buf, size_t cap,
    size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mipc_writer_init(&w, buf, cap);
    st = mipc_threedm_sensor_to_vehicle_quaternion_response_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 16 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mipc_threedm_sensor_to_vehicle_quaternion_response_load(
    const uint8_t *d, mipc_threedm_sensor_to_vehicle_quaternion_response_t *out) {
    out->q[0] = mipc_ld_f32(d + 0);
    out->q[1] = mipc_ld_f32(d + 4);
    out->q[2] = mipc_ld_f32(d + 8);
    out->q[3] = mipc_ld_f32(d + 12);
    return 0;
}

/* The general reader: lengths other than 16, bad bool bytes, error details. */
static MIPC_NOINLINE mipc_status_t mipc_threedm_sensor_to_vehicle_quaternion_response_decode_read(
    const uint8_t *data, size_t len, mipc_threedm_sensor_to_vehicle_quaternion_response_t *out,
    mipc_decode_error_t *err) {
    mipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_threedm_sensor_to_vehicle_quaternion_response_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t mipc_threedm_sensor_to_vehicle_quaternion_response_decode(
    const uint8_t *data, size_t len, mipc_threedm_sensor_to_vehicle_quaternion_response_t *out,
    mipc_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 16 && mipc_threedm_sensor_to_vehicle_quaternion_response_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_threedm_sensor_to_vehicle_quaternion_response_decode_read(data, len, out, err);
}

/* ---- mipc_threedm_sensor_to_vehicle_dcm_t */

static int mipc_threedm_sensor_to_vehicle_dcm_read(mipc_reader_t *r,
                                                   mipc_threedm_sensor_to_vehicle_dcm_t *out) {
    size_t i;
    mipc_rd_push(r, "function");
    if (mipc_rd_u8(r, &out->function)) {
        return -1;
    }
    mipc_rd_pop(r);
    if (r->pos < r->len) {
        out->has_dcm = true;
        mipc_rd_push(r, "dcm");
        for (i = 0; i < 9; i++) {
            mipc_rd_index(r, i);
            if (mipc_rd_f32(r, &out->dcm[i])) {
                return -1;
            }
        }
        mipc_rd_pop(r);
    }
    return mipc_rd_finish(r);
}

static mipc_status_t
mipc_threedm_sensor_to_vehicle_dcm_write(mipc_writer_t *w, const mipc_threedm_sensor_to_vehicle_dcm_t *in) {
    mipc_status_t st;
    size_t i;
    int absent = 0;
    if ((st = mipc_wr_u8(w, &in->function)) != MIPC_OK) {
        return st;
    }
    if (!in->has_dcm) {
        absent = 1;
    } else if (absent) {
        return MIPC_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        for (i = 0; i < 9; i++) {
            if ((st = mipc_wr_f32(w, &in->dcm[i])) != MIPC_OK) {
                return st;
            }
        }
    }
    return MIPC_OK;
}

mipc_status_t mipc_threedm_sensor_to_vehicle_dcm_encode(const mipc_threedm_sensor_to_vehicle_dcm_t *value,
                                                        uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mipc_writer_init(&w, buf, cap);
    st = mipc_threedm_sensor_to_vehicle_dcm_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mipc_status_t mipc_threedm_sensor_to_vehicle_dcm_decode(const uint8_t *data, size_t len,
                                                        mipc_threedm_sensor_to_vehicle_dcm_t *out,
                                                        mipc_decode_error_t *err) {
    mipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_threedm_sensor_to_vehicle_dcm_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

/* ---- mipc_threedm_sensor_to_vehicle_dcm_response_t */

static int
mipc_threedm_sensor_to_vehicle_dcm_response_read(mipc_reader_t *r,
                                                 mipc_threedm_sensor_to_vehicle_dcm_response_t *out) {
    size_t i;
    mipc_rd_push(r, "dcm");
    for (i = 0; i < 9; i++) {
        mipc_rd_index(r, i);
        if (mipc_rd_f32(r, &out->dcm[i])) {
            return -1;
        }
    }
    mipc_rd_pop(r);
    return mipc_rd_finish(r);
}

static mipc_status_t
mipc_threedm_sensor_to_vehicle_dcm_response_write(mipc_writer_t *w,
                                                  const mipc_threedm_sensor_to_vehicle_dcm_response_t *in) {
    mipc_status_t st;
    size_t i;
    for (i = 0; i < 9; i++) {
        if ((st = mipc_wr_f32(w, &in->dcm[i])) != MIPC_OK) {
            return st;
        }
    }
    return MIPC_OK;
}

mipc_status_t
mipc_threedm_sensor_to_vehicle_dcm_response_encode(const mipc_threedm_sensor_to_vehicle_dcm_response_t *value,
                                                   uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mipc_writer_init(&w, buf, cap);
    st = mipc_threedm_sensor_to_vehicle_dcm_response_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 36 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int
mipc_threedm_sensor_to_vehicle_dcm_response_load(const uint8_t *d,
                                                 mipc_threedm_sensor_to_vehicle_dcm_response_t *out) {
    out->dcm[0] = mipc_ld_f32(d + 0);
    out->dcm[1] = mipc_ld_f32(d + 4);
    out->dcm[2] = mipc_ld_f32(d + 8);
    out->dcm[3] = mipc_ld_f32(d + 12);
    out->dcm[4] = mipc_ld_f32(d + 16);
    out->dcm[5] = mipc_ld_f32(d + 20);
    out->dcm[6] = mipc_ld_f32(d + 24);
    out->dcm[7] = mipc_ld_f32(d + 28);
    out->dcm[8] = mipc_ld_f32(d + 32);
    return 0;
}

/* The general reader: lengths other than 36, bad bool bytes, error details. */
static MIPC_NOINLINE mipc_status_t mipc_threedm_sensor_to_vehicle_dcm_response_decode_read(
    const uint8_t *data, size_t len, mipc_threedm_sensor_to_vehicle_dcm_response_t *out,
    mipc_decode_error_t *err) {
    mipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_threedm_sensor_to_vehicle_dcm_response_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t
mipc_threedm_sensor_to_vehicle_dcm_response_decode(const uint8_t *data, size_t len,
                                                   mipc_threedm_sensor_to_vehicle_dcm_response_t *out,
                                                   mipc_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 36 && mipc_threedm_sensor_to_vehicle_dcm_response_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_threedm_sensor_to_vehicle_dcm_response_decode_read(data, len, out, err);
}

/* ---- mipc_threedm_accel_bias_gx5_45_t */

static int mipc_threedm_accel_bias_gx5_45_read(mipc_reader_t *r, mipc_threedm_accel_bias_gx5_45_t *out) {
    size_t i;
    mipc_rd_push(r, "function");
    if (mipc_rd_u8(r, &out->function)) {
        return -1;
    }
    mipc_rd_pop(r);
    if (r->pos < r->len) {
        out->has_bias = true;
        mipc_rd_push(r, "bias");
        for (i = 0; i < 3; i++) {
            mipc_rd_index(r, i);
            if (mipc_rd_f32(r, &out->bias[i])) {
                return -1;
            }
        }
        mipc_rd_pop(r);
    }
    return mipc_rd_finish(r);
}

static mipc_status_t mipc_threedm_accel_bias_gx5_45_write(mipc_writer_t *w,
                                                          const mipc_threedm_accel_bias_gx5_45_t *in) {
    mipc_status_t st;
    size_t i;
    int absent = 0;
    if ((st = mipc_wr_u8(w, &in->function)) != MIPC_OK) {
        return st;
    }
    if (!in->has_bias) {
        absent = 1;
    } else if (absent) {
        return MIPC_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        for (i = 0; i < 3; i++) {
            if ((st = mipc_wr_f32(w, &in->bias[i])) != MIPC_OK) {
                return st;
            }
        }
    }
    return MIPC_OK;
}

mipc_status_t mipc_threedm_accel_bias_gx5_45_encode(const mipc_threedm_accel_bias_gx5_45_t *value,
                                                    uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mipc_writer_init(&w, buf, cap);
    st = mipc_threedm_accel_bias_gx5_45_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mipc_status_t mipc_threedm_accel_bias_gx5_45_decode(const uint8_t *data, size_t len,
                                                    mipc_threedm_accel_bias_gx5_45_t *out,
                                                    mipc_decode_error_t *err) {
    mipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_threedm_accel_bias_gx5_45_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

/* ---- mipc_threedm_accel_bias_cv7_ins_t */

static int mipc_threedm_accel_bias_cv7_ins_read(mipc_reader_t *r, mipc_threedm_accel_bias_cv7_ins_t *out) {
    size_t i;
    mipc_rd_push(r, "function");
    if (mipc_rd_u8(r, &out->function)) {
        return -1;
    }
    mipc_rd_pop(r);
    if (r->pos < r->len) {
        out->has_bias = true;
        mipc_rd_push(r, "bias");
        for (i = 0; i < 3; i++) {
            mipc_rd_index(r, i);
            if (mipc_rd_f32(r, &out->bias[i])) {
                return -1;
            }
        }
        mipc_rd_pop(r);
    }
    return mipc_rd_finish(r);
}

static mipc_status_t mipc_threedm_accel_bias_cv7_ins_write(mipc_writer_t *w,
                                                           const mipc_threedm_accel_bias_cv7_ins_t *in) {
    mipc_status_t st;
    size_t i;
    int absent = 0;
    if ((st = mipc_wr_u8(w, &in->function)) != MIPC_OK) {
        return st;
    }
    if (!in->has_bias) {
        absent = 1;
    } else if (absent) {
        return MIPC_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        for (i = 0; i < 3; i++) {
            if ((st = mipc_wr_f32(w, &in->bias[i])) != MIPC_OK) {
                return st;
            }
        }
    }
    return MIPC_OK;
}

mipc_status_t mipc_threedm_accel_bias_cv7_ins_encode(const mipc_threedm_accel_bias_cv7_ins_t *value,
                                                     uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mipc_writer_init(&w, buf, cap);
    st = mipc_threedm_accel_bias_cv7_ins_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mipc_status_t mipc_threedm_accel_bias_cv7_ins_decode(const uint8_t *data, size_t len,
                                                     mipc_threedm_accel_bias_cv7_ins_t *out,
                                                     mipc_decode_error_t *err) {
    mipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_threedm_accel_bias_cv7_ins_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

/* ---- mipc_threedm_accel_bias_response_t */

static int mipc_threedm_accel_bias_response_read(mipc_reader_t *r, mipc_threedm_accel_bias_response_t *out) {
    size_t i;
    mipc_rd_push(r, "bias");
    for (i = 0; i < 3; i++) {
        mipc_rd_index(r, i);
        if (mipc_rd_f32(r, &out->bias[i])) {
            return -1;
        }
    }
    mipc_rd_pop(r);
    return mipc_rd_finish(r);
}

static mipc_status_t mipc_threedm_accel_bias_response_write(mipc_writer_t *w,
                                                            const mipc_threedm_accel_bias_response_t *in) {
    mipc_status_t st;
    size_t i;
    for (i = 0; i < 3; i++) {
        if ((st = mipc_wr_f32(w, &in->bias[i])) != MIPC_OK) {
            return st;
        }
    }
    return MIPC_OK;
}

mipc_status_t mipc_threedm_accel_bias_response_encode(const mipc_threedm_accel_bias_response_t *value,
                                                      uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mipc_writer_init(&w, buf, cap);
    st = mipc_threedm_accel_bias_response_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 12 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mipc_threedm_accel_bias_response_load(const uint8_t *d, mipc_threedm_accel_bias_response_t *out) {
    out->bias[0] = mipc_ld_f32(d + 0);
    out->bias[1] = mipc_ld_f32(d + 4);
    out->bias[2] = mipc_ld_f32(d + 8);
    return 0;
}

/* The general reader: lengths other than 12, bad bool bytes, error details. */
static MIPC_NOINLINE mipc_status_t mipc_threedm_accel_bias_response_decode_read(
    const uint8_t *data, size_t len, mipc_threedm_accel_bias_response_t *out, mipc_decode_error_t *err) {
    mipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_threedm_accel_bias_response_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t mipc_threedm_accel_bias_response_decode(const uint8_t *data, size_t len,
                                                      mipc_threedm_accel_bias_response_t *out,
                                                      mipc_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 12 && mipc_threedm_accel_bias_response_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_threedm_accel_bias_response_decode_read(data, len, out, err);
}

/* ---- mipc_threedm_gyro_bias_gx5_45_t */

static int mipc_threedm_gyro_bias_gx5_45_read(mipc_reader_t *r, mipc_threedm_gyro_bias_gx5_45_t *out) {
    size_t i;
    mipc_rd_push(r, "function");
    if (mipc_rd_u8(r, &out->function)) {
        return -1;
    }
    mipc_rd_pop(r);
    if (r->pos < r->len) {
        out->has_bias = true;
        mipc_rd_push(r, "bias");
        for (i = 0; i < 3; i++) {
            mipc_rd_index(r, i);
            if (mipc_rd_f32(r, &out->bias[i])) {
                return -1;
            }
        }
        mipc_rd_pop(r);
    }
    return mipc_rd_finish(r);
}

static mipc_status_t mipc_threedm_gyro_bias_gx5_45_write(mipc_writer_t *w,
                                                         const mipc_threedm_gyro_bias_gx5_45_t *in) {
    mipc_status_t st;
    size_t i;
    int absent = 0;
    if ((st = mipc_wr_u8(w, &in->function)) != MIPC_OK) {
        return st;
    }
    if (!in->has_bias) {
        absent = 1;
    } else if (absent) {
        return MIPC_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        for (i = 0; i < 3; i++) {
            if ((st = mipc_wr_f32(w, &in->bias[i])) != MIPC_OK) {
                return st;
            }
        }
    }
    return MIPC_OK;
}

mipc_status_t mipc_threedm_gyro_bias_gx5_45_encode(const mipc_threedm_gyro_bias_gx5_45_t *value, uint8_t *buf,
                                                   size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mipc_writer_init(&w, buf, cap);
    st = mipc_threedm_gyro_bias_gx5_45_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mipc_status_t mipc_threedm_gyro_bias_gx5_45_decode(const uint8_t *data, size_t len,
                                                   mipc_threedm_gyro_bias_gx5_45_t *out,
                                                   mipc_decode_error_t *err) {
    mipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_threedm_gyro_bias_gx5_45_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

/* ---- mipc_threedm_gyro_bias_cv7_ins_t */

static int mipc_threedm_gyro_bias_cv7_ins_read(mipc_reader_t *r, mipc_threedm_gyro_bias_cv7_ins_t *out) {
    size_t i;
    mipc_rd_push(r, "function");
    if (mipc_rd_u8(r, &out->function)) {
        return -1;
    }
    mipc_rd_pop(r);
    if (r->pos < r->len) {
        out->has_bias = true;
        mipc_rd_push(r, "bias");
        for (i = 0; i < 3; i++) {
            mipc_rd_index(r, i);
            if (mipc_rd_f32(r, &out->bias[i])) {
                return -1;
            }
        }
        mipc_rd_pop(r);
    }
    return mipc_rd_finish(r);
}

static mipc_status_t mipc_threedm_gyro_bias_cv7_ins_write(mipc_writer_t *w,
                                                          const mipc_threedm_gyro_bias_cv7_ins_t *in) {
    mipc_status_t st;
    size_t i;
    int absent = 0;
    if ((st = mipc_wr_u8(w, &in->function)) != MIPC_OK) {
        return st;
    }
    if (!in->has_bias) {
        absent = 1;
    } else if (absent) {
        return MIPC_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        for (i = 0; i < 3; i++) {
            if ((st = mipc_wr_f32(w, &in->bias[i])) != MIPC_OK) {
                return st;
            }
        }
    }
    return MIPC_OK;
}

mipc_status_t mipc_threedm_gyro_bias_cv7_ins_encode(const mipc_threedm_gyro_bias_cv7_ins_t *value,
                                                    uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mipc_writer_init(&w, buf, cap);
    st = mipc_threedm_gyro_bias_cv7_ins_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mipc_status_t mipc_threedm_gyro_bias_cv7_ins_decode(const uint8_t *data, size_t len,
                                                    mipc_threedm_gyro_bias_cv7_ins_t *out,
                                                    mipc_decode_error_t *err) {
    mipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_threedm_gyro_bias_cv7_ins_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

/* ---- mipc_threedm_gyro_bias_response_t */

static int mipc_threedm_gyro_bias_response_read(mipc_reader_t *r, mipc_threedm_gyro_bias_response_t *out) {
    size_t i;
    mipc_rd_push(r, "bias");
    for (i = 0; i < 3; i++) {
        mipc_rd_index(r, i);
        if (mipc_rd_f32(r, &out->bias[i])) {
            return -1;
        }
    }
    mipc_rd_pop(r);
    return mipc_rd_finish(r);
}

static mipc_status_t mipc_threedm_gyro_bias_response_write(mipc_writer_t *w,
                                                           const mipc_threedm_gyro_bias_response_t *in) {
    mipc_status_t st;
    size_t i;
    for (i = 0; i < 3; i++) {
        if ((st = mipc_wr_f32(w, &in->bias[i])) != MIPC_OK) {
            return st;
        }
    }
    return MIPC_OK;
}

mipc_status_t mipc_threedm_gyro_bias_response_encode(const mipc_threedm_gyro_bias_response_t *value,
                                                     uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mipc_writer_init(&w, buf, cap);
    st = mipc_threedm_gyro_bias_response_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 12 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mipc_threedm_gyro_bias_response_load(const uint8_t *d, mipc_threedm_gyro_bias_response_t *out) {
    out->bias[0] = mipc_ld_f32(d + 0);
    out->bias[1] = mipc_ld_f32(d + 4);
    out->bias[2] = mipc_ld_f32(d + 8);
    return 0;
}

/* The general reader: lengths other than 12, bad bool bytes, error details. */
static MIPC_NOINLINE mipc_status_t mipc_threedm_gyro_bias_response_decode_read(
    const uint8_t *data, size_t len, mipc_threedm_gyro_bias_response_t *out, mipc_decode_error_t *err) {
    mipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_threedm_gyro_bias_response_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t mipc_threedm_gyro_bias_response_decode(const uint8_t *data, size_t len,
                                                     mipc_threedm_gyro_bias_response_t *out,
                                                     mipc_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 12 && mipc_threedm_gyro_bias_response_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_threedm_gyro_bias_response_decode_read(data, len, out, err);
}

/* ---- mipc_threedm_capture_gyro_bias_t */

static int mipc_threedm_capture_gyro_bias_read(mipc_reader_t *r, mipc_threedm_capture_gyro_bias_t *out) {
    mipc_rd_push(r, "averaging_time_ms");
    if (mipc_rd_u16(r, &out->averaging_time_ms)) {
        return -1;
    }
    mipc_rd_pop(r);
    return mipc_rd_finish(r);
}

static mipc_status_t mipc_threedm_capture_gyro_bias_write(mipc_writer_t *w,
                                                          const mipc_threedm_capture_gyro_bias_t *in) {
    mipc_status_t st;
    if ((st = mipc_wr_u16(w, &in->averaging_time_ms)) != MIPC_OK) {
        return st;
    }
    return MIPC_OK;
}

mipc_status_t mipc_threedm_capture_gyro_bias_encode(const mipc_threedm_capture_gyro_bias_t *value,
                                                    uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mipc_writer_init(&w, buf, cap);
    st = mipc_threedm_capture_gyro_bias_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 2 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mipc_threedm_capture_gyro_bias_load(const uint8_t *d, mipc_threedm_capture_gyro_bias_t *out) {
    out->averaging_time_ms = mipc_ld_u16(d + 0);
    return 0;
}

/* The general reader: lengths other than 2, bad bool bytes, error details. */
static MIPC_NOINLINE mipc_status_t mipc_threedm_capture_gyro_bias_decode_read(
    const uint8_t *data, size_t len, mipc_threedm_capture_gyro_bias_t *out, mipc_decode_error_t *err) {
    mipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_threedm_capture_gyro_bias_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t mipc_threedm_capture_gyro_bias_decode(const uint8_t *data, size_t len,
                                                    mipc_threedm_capture_gyro_bias_t *out,
                                                    mipc_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 2 && mipc_threedm_capture_gyro_bias_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_threedm_capture_gyro_bias_decode_read(data, len, out, err);
}

/* ---- mipc_threedm_mag_hard_iron_offset_gx5_45_t */

static int mipc_threedm_mag_hard_iron_offset_gx5_45_read(mipc_reader_t *r,
                                                         mipc_threedm_mag_hard_iron_offset_gx5_45_t *out) {
    size_t i;
    mipc_rd_push(r, "function");
    if (mipc_rd_u8(r, &out->function)) {
        return -1;
    }
    mipc_rd_pop(r);
    if (r->pos < r->len) {
        out->has_offset = true;
        mipc_rd_push(r, "offset");
        for (i = 0; i < 3; i++) {
            mipc_rd_index(r, i);
            if (mipc_rd_f32(r, &out->offset[i])) {
                return -1;
            }
        }
        mipc_rd_pop(r);
    }
    return mipc_rd_finish(r);
}

static mipc_status_t
mipc_threedm_mag_hard_iron_offset_gx5_45_write(mipc_writer_t *w,
                                               const mipc_threedm_mag_hard_iron_offset_gx5_45_t *in) {
    mipc_status_t st;
    size_t i;
    int absent = 0;
    if ((st = mipc_wr_u8(w, &in->function)) != MIPC_OK) {
        return st;
    }
    if (!in->has_offset) {
        absent = 1;
    } else if (absent) {
        return MIPC_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        for (i = 0; i < 3; i++) {
            if ((st = mipc_wr_f32(w, &in->offset[i])) != MIPC_OK) {
                return st;
            }
        }
    }
    return MIPC_OK;
}

mipc_status_t
mipc_threedm_mag_hard_iron_offset_gx5_45_encode(const mipc_threedm_mag_hard_iron_offset_gx5_45_t *value,
                                                uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mipc_writer_init(&w, buf, cap);
    st = mipc_threedm_mag_hard_iron_offset_gx5_45_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mipc_status_t mipc_threedm_mag_hard_iron_offset_gx5_45_decode(const uint8_t *data, size_t len,
                                                              mipc_threedm_mag_hard_iron_offset_gx5_45_t *out,
                                                              mipc_decode_error_t *err) {
    mipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_threedm_mag_hard_iron_offset_gx5_45_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

/* ---- mipc_threedm_mag_hard_iron_offset_cv7_ins_t */

static int mipc_threedm_mag_hard_iron_offset_cv7_ins_read(mipc_reader_t *r,
                                                          mipc_threedm_mag_hard_iron_offset_cv7_ins_t *out) {
    size_t i;
    mipc_rd_push(r, "function");
    if (mipc_rd_u8(r, &out->function)) {
        return -1;
    }
    mipc_rd_pop(r);
    if (r->pos < r->len) {
        out->has_offset = true;
        mipc_rd_push(r, "offset");
        for (i = 0; i < 3; i++) {
            mipc_rd_index(r, i);
            if (mipc_rd_f32(r, &out->offset[i])) {
                return -1;
            }
        }
        mipc_rd_pop(r);
    }
    return mipc_rd_finish(r);
}

static mipc_status_t
mipc_threedm_mag_hard_iron_offset_cv7_ins_write(mipc_writer_t *w,
                                                const mipc_threedm_mag_hard_iron_offset_cv7_ins_t *in) {
    mipc_status_t st;
    size_t i;
    int absent = 0;
    if ((st = mipc_wr_u8(w, &in->function)) != MIPC_OK) {
        return st;
    }
    if (!in->has_offset) {
        absent = 1;
    } else if (absent) {
        return MIPC_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        for (i = 0; i < 3; i++) {
            if ((st = mipc_wr_f32(w, &in->offset[i])) != MIPC_OK) {
                return st;
            }
        }
    }
    return MIPC_OK;
}

mipc_status_t
mipc_threedm_mag_hard_iron_offset_cv7_ins_encode(const mipc_threedm_mag_hard_iron_offset_cv7_ins_t *value,
                                                 uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mipc_writer_init(&w, buf, cap);
    st = mipc_threedm_mag_hard_iron_offset_cv7_ins_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mipc_status_t
mipc_threedm_mag_hard_iron_offset_cv7_ins_decode(const uint8_t *data, size_t len,
                                                 mipc_threedm_mag_hard_iron_offset_cv7_ins_t *out,
                                                 mipc_decode_error_t *err) {
    mipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_threedm_mag_hard_iron_offset_cv7_ins_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

/* ---- mipc_threedm_mag_hard_iron_offset_response_t */

static int
mipc_threedm_mag_hard_iron_offset_response_read(mipc_reader_t *r,
                                                mipc_threedm_mag_hard_iron_offset_response_t *out) {
    size_t i;
    mipc_rd_push(r, "offset");
    for (i = 0; i < 3; i++) {
        mipc_rd_index(r, i);
        if (mipc_rd_f32(r, &out->offset[i])) {
            return -1;
        }
    }
    mipc_rd_pop(r);
    return mipc_rd_finish(r);
}

static mipc_status_t
mipc_threedm_mag_hard_iron_offset_response_write(mipc_writer_t *w,
                                                 const mipc_threedm_mag_hard_iron_offset_response_t *in) {
    mipc_status_t st;
    size_t i;
    for (i = 0; i < 3; i++) {
        if ((st = mipc_wr_f32(w, &in->offset[i])) != MIPC_OK) {
            return st;
        }
    }
    return MIPC_OK;
}

mipc_status_t
mipc_threedm_mag_hard_iron_offset_response_encode(const mipc_threedm_mag_hard_iron_offset_response_t *value,
                                                  uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mipc_writer_init(&w, buf, cap);
    st = mipc_threedm_mag_hard_iron_offset_response_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 12 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int
mipc_threedm_mag_hard_iron_offset_response_load(const uint8_t *d,
                                                mipc_threedm_mag_hard_iron_offset_response_t *out) {
    out->offset[0] = mipc_ld_f32(d + 0);
    out->offset[1] = mipc_ld_f32(d + 4);
    out->offset[2] = mipc_ld_f32(d + 8);
    return 0;
}

/* The general reader: lengths other than 12, bad bool bytes, error details. */
static MIPC_NOINLINE mipc_status_t mipc_threedm_mag_hard_iron_offset_response_decode_read(
    const uint8_t *data, size_t len, mipc_threedm_mag_hard_iron_offset_response_t *out,
    mipc_decode_error_t *err) {
    mipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_threedm_mag_hard_iron_offset_response_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t
mipc_threedm_mag_hard_iron_offset_response_decode(const uint8_t *data, size_t len,
                                                  mipc_threedm_mag_hard_iron_offset_response_t *out,
                                                  mipc_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 12 && mipc_threedm_mag_hard_iron_offset_response_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_threedm_mag_hard_iron_offset_response_decode_read(data, len, out, err);
}

/* ---- mipc_threedm_mag_soft_iron_matrix_gx5_45_t */

static int mipc_threedm_mag_soft_iron_matrix_gx5_45_read(mipc_reader_t *r,
                                                         mipc_threedm_mag_soft_iron_matrix_gx5_45_t *out) {
    size_t i;
    mipc_rd_push(r, "function");
    if (mipc_rd_u8(r, &out->function)) {
        return -1;
    }
    mipc_rd_pop(r);
    if (r->pos < r->len) {
        out->has_matrix = true;
        mipc_rd_push(r, "matrix");
        for (i = 0; i < 9; i++) {
            mipc_rd_index(r, i);
            if (mipc_rd_f32(r, &out->matrix[i])) {
                return -1;
            }
        }
        mipc_rd_pop(r);
    }
    return mipc_rd_finish(r);
}

static mipc_status_t
mipc_threedm_mag_soft_iron_matrix_gx5_45_write(mipc_writer_t *w,
                                               const mipc_threedm_mag_soft_iron_matrix_gx5_45_t *in) {
    mipc_status_t st;
    size_t i;
    int absent = 0;
    if ((st = mipc_wr_u8(w, &in->function)) != MIPC_OK) {
        return st;
    }
    if (!in->has_matrix) {
        absent = 1;
    } else if (absent) {
        return MIPC_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        for (i = 0; i < 9; i++) {
            if ((st = mipc_wr_f32(w, &in->matrix[i])) != MIPC_OK) {
                return st;
            }
        }
    }
    return MIPC_OK;
}

mipc_status_t
mipc_threedm_mag_soft_iron_matrix_gx5_45_encode(const mipc_threedm_mag_soft_iron_matrix_gx5_45_t *value,
                                                uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mipc_writer_init(&w, buf, cap);
    st = mipc_threedm_mag_soft_iron_matrix_gx5_45_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mipc_status_t mipc_threedm_mag_soft_iron_matrix_gx5_45_decode(const uint8_t *data, size_t len,
                                                              mipc_threedm_mag_soft_iron_matrix_gx5_45_t *out,
                                                              mipc_decode_error_t *err) {
    mipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_threedm_mag_soft_iron_matrix_gx5_45_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

/* ---- mipc_threedm_mag_soft_iron_matrix_cv7_ins_t */

static int mipc_threedm_mag_soft_iron_matrix_cv7_ins_read(mipc_reader_t *r,
                                                          mipc_threedm_mag_soft_iron_matrix_cv7_ins_t *out) {
    size_t i;
    mipc_rd_push(r, "function");
    if (mipc_rd_u8(r, &out->function)) {
        return -1;
    }
    mipc_rd_pop(r);
    if (r->pos < r->len) {
        out->has_matrix = true;
        mipc_rd_push(r, "matrix");
        for (i = 0; i < 9; i++) {
            mipc_rd_index(r, i);
            if (mipc_rd_f32(r, &out->matrix[i])) {
                return -1;
            }
        }
        mipc_rd_pop(r);
    }
    return mipc_rd_finish(r);
}

static mipc_status_t
mipc_threedm_mag_soft_iron_matrix_cv7_ins_write(mipc_writer_t *w,
                                                const mipc_threedm_mag_soft_iron_matrix_cv7_ins_t *in) {
    mipc_status_t st;
    size_t i;
    int absent = 0;
    if ((st = mipc_wr_u8(w, &in->function)) != MIPC_OK) {
        return st;
    }
    if (!in->has_matrix) {
        absent = 1;
    } else if (absent) {
        return MIPC_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        for (i = 0; i < 9; i++) {
            if ((st = mipc_wr_f32(w, &in->matrix[i])) != MIPC_OK) {
                return st;
            }
        }
    }
    return MIPC_OK;
}

mipc_status_t
mipc_threedm_mag_soft_iron_matrix_cv7_ins_encode(const mipc_threedm_mag_soft_iron_matrix_cv7_ins_t *value,
                                                 uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mipc_writer_init(&w, buf, cap);
    st = mipc_threedm_mag_soft_iron_matrix_cv7_ins_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mipc_status_t
mipc_threedm_mag_soft_iron_matrix_cv7_ins_decode(const uint8_t *data, size_t len,
                                                 mipc_threedm_mag_soft_iron_matrix_cv7_ins_t *out,
                                                 mipc_decode_error_t *err) {
    mipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_threedm_mag_soft_iron_matrix_cv7_ins_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

/* ---- mipc_threedm_mag_soft_iron_matrix_response_t */

static int
mipc_threedm_mag_soft_iron_matrix_response_read(mipc_reader_t *r,
                                                mipc_threedm_mag_soft_iron_matrix_response_t *out) {
    size_t i;
    mipc_rd_push(r, "matrix");
    for (i = 0; i < 9; i++) {
        mipc_rd_index(r, i);
        if (mipc_rd_f32(r, &out->matrix[i])) {
            return -1;
        }
    }
    mipc_rd_pop(r);
    return mipc_rd_finish(r);
}

static mipc_status_t
mipc_threedm_mag_soft_iron_matrix_response_write(mipc_writer_t *w,
                                                 const mipc_threedm_mag_soft_iron_matrix_response_t *in) {
    mipc_status_t st;
    size_t i;
    for (i = 0; i < 9; i++) {
        if ((st = mipc_wr_f32(w, &in->matrix[i])) != MIPC_OK) {
            return st;
        }
    }
    return MIPC_OK;
}

mipc_status_t
mipc_threedm_mag_soft_iron_matrix_response_encode(const mipc_threedm_mag_soft_iron_matrix_response_t *value,
                                                  uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mipc_writer_init(&w, buf, cap);
    st = mipc_threedm_mag_soft_iron_matrix_response_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 36 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int
mipc_threedm_mag_soft_iron_matrix_response_load(const uint8_t *d,
                                                mipc_threedm_mag_soft_iron_matrix_response_t *out) {
    out->matrix[0] = mipc_ld_f32(d + 0);
    out->matrix[1] = mipc_ld_f32(d + 4);
    out->matrix[2] = mipc_ld_f32(d + 8);
    out->matrix[3] = mipc_ld_f32(d + 12);
    out->matrix[4] = mipc_ld_f32(d + 16);
    out->matrix[5] = mipc_ld_f32(d + 20);
    out->matrix[6] = mipc_ld_f32(d + 24);
    out->matrix[7] = mipc_ld_f32(d + 28);
    out->matrix[8] = mipc_ld_f32(d + 32);
    return 0;
}

/* The general reader: lengths other than 36, bad bool bytes, error details. */
static MIPC_NOINLINE mipc_status_t mipc_threedm_mag_soft_iron_matrix_response_decode_read(
    const uint8_t *data, size_t len, mipc_threedm_mag_soft_iron_matrix_response_t *out,
    mipc_decode_error_t *err) {
    mipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_threedm_mag_soft_iron_matrix_response_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t
mipc_threedm_mag_soft_iron_matrix_response_decode(const uint8_t *data, size_t len,
                                                  mipc_threedm_mag_soft_iron_matrix_response_t *out,
                                                  mipc_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 36 && mipc_threedm_mag_soft_iron_matrix_response_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_threedm_mag_soft_iron_matrix_response_decode_read(data, len, out, err);
}

/* ---- mipc_threedm_coning_sculling_enable_t */

static int mipc_threedm_coning_sculling_enable_read(mipc_reader_t *r,
                                                    mipc_threedm_coning_sculling_enable_t *out) {
    mipc_rd_push(r, "function");
    if (mipc_rd_u8(r, &out->function)) {
        return -1;
    }
    mipc_rd_pop(r);
    if (r->pos < r->len) {
        out->has_enable = true;
        mipc_rd_push(r, "enable");
        if (mipc_rd_bool(r, &out->enable)) {
            return -1;
        }
        mipc_rd_pop(r);
    }
    return mipc_rd_finish(r);
}

static mipc_status_t
mipc_threedm_coning_sculling_enable_write(mipc_writer_t *w, const mipc_threedm_coning_sculling_enable_t *in) {
    mipc_status_t st;
    int absent = 0;
    if ((st = mipc_wr_u8(w, &in->function)) != MIPC_OK) {
        return st;
    }
    if (!in->has_enable) {
        absent = 1;
    } else if (absent) {
        return MIPC_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = mipc_wr_bool(w, &in->enable)) != MIPC_OK) {
            return st;
        }
    }
    return MIPC_OK;
}

mipc_status_t mipc_threedm_coning_sculling_enable_encode(const mipc_threedm_coning_sculling_enable_t *value,
                                                         uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mipc_writer_init(&w, buf, cap);
    st = mipc_threedm_coning_sculling_enable_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mipc_status_t mipc_threedm_coning_sculling_enable_decode(const uint8_t *data, size_t len,
                                                         mipc_threedm_coning_sculling_enable_t *out,
                                                         mipc_decode_error_t *err) {
    mipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_threedm_coning_sculling_enable_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

/* ---- mipc_threedm_coning_sculling_enable_response_t */

static int
mipc_threedm_coning_sculling_enable_response_read(mipc_reader_t *r,
                                                  mipc_threedm_coning_sculling_enable_response_t *out) {
    mipc_rd_push(r, "enable");
    if (mipc_rd_bool(r, &out->enable)) {
        return -1;
    }
    mipc_rd_pop(r);
    return mipc_rd_finish(r);
}

static mipc_status_t
mipc_threedm_coning_sculling_enable_response_write(mipc_writer_t *w,
                                                   const mipc_threedm_coning_sculling_enable_response_t *in) {
    mipc_status_t st;
    if ((st = mipc_wr_bool(w, &in->enable)) != MIPC_OK) {
        return st;
    }
    return MIPC_OK;
}

mipc_status_t mipc_threedm_coning_sculling_enable_response_encode(
    const mipc_threedm_coning_sculling_enable_response_t *value, uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mipc_writer_init(&w, buf, cap);
    st = mipc_threedm_coning_sculling_enable_response_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 1 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int
mipc_threedm_coning_sculling_enable_response_load(const uint8_t *d,
                                                  mipc_threedm_coning_sculling_enable_response_t *out) {
    if (d[0] > 1) {
        return -1;
    }
    out->enable = mipc_ld_bool(d + 0);
    return 0;
}

/* The general reader: lengths other than 1, bad bool bytes, error details. */
static MIPC_NOINLINE mipc_status_t mipc_threedm_coning_sculling_enable_response_decode_read(
    const uint8_t *data, size_t len, mipc_threedm_coning_sculling_enable_response_t *out,
    mipc_decode_error_t *err) {
    mipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_threedm_coning_sculling_enable_response_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t
mipc_threedm_coning_sculling_enable_response_decode(const uint8_t *data, size_t len,
                                                    mipc_threedm_coning_sculling_enable_response_t *out,
                                                    mipc_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 1 && mipc_threedm_coning_sculling_enable_response_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_threedm_coning_sculling_enable_response_decode_read(data, len, out, err);
}

/* ---- mipc_threedm_uart_baudrate_t */

static int mipc_threedm_uart_baudrate_read(mipc_reader_t *r, mipc_threedm_uart_baudrate_t *out) {
    mipc_rd_push(r, "function");
    if (mipc_rd_u8(r, &out->function)) {
        return -1;
    }
    mipc_rd_pop(r);
    if (r->pos < r->len) {
        out->has_baud = true;
        mipc_rd_push(r, "baud");
        if (mipc_rd_u32(r, &out->baud)) {
            return -1;
        }
        mipc_rd_pop(r);
    }
    return mipc_rd_finish(r);
}

static mipc_status_t mipc_threedm_uart_baudrate_write(mipc_writer_t *w,
                                                      const mipc_threedm_uart_baudrate_t *in) {
    mipc_status_t st;
    int absent = 0;
    if ((st = mipc_wr_u8(w, &in->function)) != MIPC_OK) {
        return st;
    }
    if (!in->has_baud) {
        absent = 1;
    } else if (absent) {
        return MIPC_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = mipc_wr_u32(w, &in->baud)) != MIPC_OK) {
            return st;
        }
    }
    return MIPC_OK;
}

mipc_status_t mipc_threedm_uart_baudrate_encode(const mipc_threedm_uart_baudrate_t *value, uint8_t *buf,
                                                size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mipc_writer_init(&w, buf, cap);
    st = mipc_threedm_uart_baudrate_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mipc_status_t mipc_threedm_uart_baudrate_decode(const uint8_t *data, size_t len,
                                                mipc_threedm_uart_baudrate_t *out, mipc_decode_error_t *err) {
    mipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_threedm_uart_baudrate_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

/* ---- mipc_threedm_uart_baudrate_response_t */

static int mipc_threedm_uart_baudrate_response_read(mipc_reader_t *r,
                                                    mipc_threedm_uart_baudrate_response_t *out) {
    mipc_rd_push(r, "baud");
    if (mipc_rd_u32(r, &out->baud)) {
        return -1;
    }
    mipc_rd_pop(r);
    return mipc_rd_finish(r);
}

static mipc_status_t
mipc_threedm_uart_baudrate_response_write(mipc_writer_t *w, const mipc_threedm_uart_baudrate_response_t *in) {
    mipc_status_t st;
    if ((st = mipc_wr_u32(w, &in->baud)) != MIPC_OK) {
        return st;
    }
    return MIPC_OK;
}

mipc_status_t mipc_threedm_uart_baudrate_response_encode(const mipc_threedm_uart_baudrate_response_t *value,
                                                         uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mipc_writer_init(&w, buf, cap);
    st = mipc_threedm_uart_baudrate_response_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 4 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mipc_threedm_uart_baudrate_response_load(const uint8_t *d,
                                                    mipc_threedm_uart_baudrate_response_t *out) {
    out->baud = mipc_ld_u32(d + 0);
    return 0;
}

/* The general reader: lengths other than 4, bad bool bytes, error details. */
static MIPC_NOINLINE mipc_status_t mipc_threedm_uart_baudrate_response_decode_read(
    const uint8_t *data, size_t len, mipc_threedm_uart_baudrate_response_t *out, mipc_decode_error_t *err) {
    mipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_threedm_uart_baudrate_response_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t mipc_threedm_uart_baudrate_response_decode(const uint8_t *data, size_t len,
                                                         mipc_threedm_uart_baudrate_response_t *out,
                                                         mipc_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 4 && mipc_threedm_uart_baudrate_response_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_threedm_uart_baudrate_response_decode_read(data, len, out, err);
}

/* ---- mipc_threedm_gpio_config_t */

static int mipc_threedm_gpio_config_read(mipc_reader_t *r, mipc_threedm_gpio_config_t *out) {
    mipc_rd_push(r, "function");
    if (mipc_rd_u8(r, &out->function)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "pin");
    if (mipc_rd_u8(r, &out->pin)) {
        return -1;
    }
    mipc_rd_pop(r);
    if (r->pos < r->len) {
        out->has_feature = true;
        mipc_rd_push(r, "feature");
        if (mipc_rd_u8(r, &out->feature)) {
            return -1;
        }
        mipc_rd_pop(r);
    }
    if (r->pos < r->len) {
        out->has_behavior = true;
        mipc_rd_push(r, "behavior");
        if (mipc_gpio_behavior_read(r, out->feature, &out->behavior)) {
            return -1;
        }
        mipc_rd_pop(r);
    }
    if (r->pos < r->len) {
        out->has_pin_mode = true;
        mipc_rd_push(r, "pin_mode");
        if (mipc_rd_u8(r, &out->pin_mode)) {
            return -1;
        }
        mipc_rd_pop(r);
    }
    return mipc_rd_finish(r);
}

static mipc_status_t mipc_threedm_gpio_config_write(mipc_writer_t *w, const mipc_threedm_gpio_config_t *in) {
    mipc_status_t st;
    int absent = 0;
    if ((st = mipc_wr_u8(w, &in->function)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u8(w, &in->pin)) != MIPC_OK) {
        return st;
    }
    if (!in->has_feature) {
        absent = 1;
    } else if (absent) {
        return MIPC_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = mipc_wr_u8(w, &in->feature)) != MIPC_OK) {
            return st;
        }
    }
    if (!in->has_behavior) {
        absent = 1;
    } else if (absent) {
        return MIPC_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = mipc_gpio_behavior_write(w, in->feature, &in->behavior)) != MIPC_OK) {
            return st;
        }
    }
    if (!in->has_pin_mode) {
        absent = 1;
    } else if (absent) {
        return MIPC_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = mipc_wr_u8(w, &in->pin_mode)) != MIPC_OK) {
            return st;
        }
    }
    return MIPC_OK;
}

mipc_status_t mipc_threedm_gpio_config_encode(const mipc_threedm_gpio_config_t *value, uint8_t *buf,
                                              size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mipc_writer_init(&w, buf, cap);
    st = mipc_threedm_gpio_config_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mipc_status_t mipc_threedm_gpio_config_decode(const uint8_t *data, size_t len,
                                              mipc_threedm_gpio_config_t *out, mipc_decode_error_t *err) {
    mipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_threedm_gpio_config_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

/* ---- mipc_threedm_gpio_config_response_t */

static int mipc_threedm_gpio_config_response_read(mipc_reader_t *r,
                                                  mipc_threedm_gpio_config_response_t *out) {
    mipc_rd_push(r, "pin");
    if (mipc_rd_u8(r, &out->pin)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "feature");
    if (mipc_rd_u8(r, &out->feature)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "behavior");
    if (mipc_gpio_behavior_read(r, out->feature, &out->behavior)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "pin_mode");
    if (mipc_rd_u8(r, &out->pin_mode)) {
        return -1;
    }
    mipc_rd_pop(r);
    return mipc_rd_finish(r);
}

static mipc_status_t mipc_threedm_gpio_config_response_write(mipc_writer_t *w,
                                                             const mipc_threedm_gpio_config_response_t *in) {
    mipc_status_t st;
    if ((st = mipc_wr_u8(w, &in->pin)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u8(w, &in->feature)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_gpio_behavior_write(w, in->feature, &in->behavior)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u8(w, &in->pin_mode)) != MIPC_OK) {
        return st;
    }
    return MIPC_OK;
}

mipc_status_t mipc_threedm_gpio_config_response_encode(const mipc_threedm_gpio_config_response_t *value,
                                                       uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mipc_writer_init(&w, buf, cap);
    st = mipc_threedm_gpio_config_response_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mipc_status_t mipc_threedm_gpio_config_response_decode(const uint8_t *data, size_t len,
                                                       mipc_threedm_gpio_config_response_t *out,
                                                       mipc_decode_error_t *err) {
    mipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_threedm_gpio_config_response_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

/* ---- mipc_threedm_gpio_state_t */

static int mipc_threedm_gpio_state_read(mipc_reader_t *r, mipc_threedm_gpio_state_t *out) {
    mipc_rd_push(r, "function");
    if (mipc_rd_u8(r, &out->function)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "pin");
    if (mipc_rd_u8(r, &out->pin)) {
        return -1;
    }
    mipc_rd_pop(r);
    if (r->pos < r->len) {
        out->has_state = true;
        mipc_rd_push(r, "state");
        if (mipc_rd_bool(r, &out->state)) {
            return -1;
        }
        mipc_rd_pop(r);
    }
    return mipc_rd_finish(r);
}

static mipc_status_t mipc_threedm_gpio_state_write(mipc_writer_t *w, const mipc_threedm_gpio_state_t *in) {
    mipc_status_t st;
    int absent = 0;
    if ((st = mipc_wr_u8(w, &in->function)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u8(w, &in->pin)) != MIPC_OK) {
        return st;
    }
    if (!in->has_state) {
        absent = 1;
    } else if (absent) {
        return MIPC_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = mipc_wr_bool(w, &in->state)) != MIPC_OK) {
            return st;
        }
    }
    return MIPC_OK;
}

mipc_status_t mipc_threedm_gpio_state_encode(const mipc_threedm_gpio_state_t *value, uint8_t *buf, size_t cap,
                                             size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mipc_writer_init(&w, buf, cap);
    st = mipc_threedm_gpio_state_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mipc_status_t mipc_threedm_gpio_state_decode(const uint8_t *data, size_t len, mipc_threedm_gpio_state_t *out,
                                             mipc_decode_error_t *err) {
    mipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_threedm_gpio_state_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

/* ---- mipc_threedm_gpio_state_response_t */

static int mipc_threedm_gpio_state_response_read(mipc_reader_t *r, mipc_threedm_gpio_state_response_t *out) {
    mipc_rd_push(r, "pin");
    if (mipc_rd_u8(r, &out->pin)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "state");
    if (mipc_rd_bool(r, &out->state)) {
        return -1;
    }
    mipc_rd_pop(r);
    return mipc_rd_finish(r);
}

static mipc_status_t mipc_threedm_gpio_state_response_write(mipc_writer_t *w,
                                                            const mipc_threedm_gpio_state_response_t *in) {
    mipc_status_t st;
    if ((st = mipc_wr_u8(w, &in->pin)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_bool(w, &in->state)) != MIPC_OK) {
        return st;
    }
    return MIPC_OK;
}

mipc_status_t mipc_threedm_gpio_state_response_encode(const mipc_threedm_gpio_state_response_t *value,
                                                      uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mipc_writer_init(&w, buf, cap);
    st = mipc_threedm_gpio_state_response_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 2 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mipc_threedm_gpio_state_response_load(const uint8_t *d, mipc_threedm_gpio_state_response_t *out) {
    out->pin = mipc_ld_u8(d + 0);
    if (d[1] > 1) {
        return -1;
    }
    out->state = mipc_ld_bool(d + 1);
    return 0;
}

/* The general reader: lengths other than 2, bad bool bytes, error details. */
static MIPC_NOINLINE mipc_status_t mipc_threedm_gpio_state_response_decode_read(
    const uint8_t *data, size_t len, mipc_threedm_gpio_state_response_t *out, mipc_decode_error_t *err) {
    mipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_threedm_gpio_state_response_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t mipc_threedm_gpio_state_response_decode(const uint8_t *data, size_t len,
                                                      mipc_threedm_gpio_state_response_t *out,
                                                      mipc_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 2 && mipc_threedm_gpio_state_response_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_threedm_gpio_state_response_decode_read(data, len, out, err);
}

/* ---- mipc_threedm_odometer_config_t */

static int mipc_threedm_odometer_config_read(mipc_reader_t *r, mipc_threedm_odometer_config_t *out) {
    mipc_rd_push(r, "function");
    if (mipc_rd_u8(r, &out->function)) {
        return -1;
    }
    mipc_rd_pop(r);
    if (r->pos < r->len) {
        out->has_mode = true;
        mipc_rd_push(r, "mode");
        if (mipc_rd_u8(r, &out->mode)) {
            return -1;
        }
        mipc_rd_pop(r);
    }
    if (r->pos < r->len) {
        out->has_scaling = true;
        mipc_rd_push(r, "scaling");
        if (mipc_rd_f32(r, &out->scaling)) {
            return -1;
        }
        mipc_rd_pop(r);
    }
    if (r->pos < r->len) {
        out->has_uncertainty = true;
        mipc_rd_push(r, "uncertainty");
        if (mipc_rd_f32(r, &out->uncertainty)) {
            return -1;
        }
        mipc_rd_pop(r);
    }
    return mipc_rd_finish(r);
}

static mipc_status_t mipc_threedm_odometer_config_write(mipc_writer_t *w,
                                                        const mipc_threedm_odometer_config_t *in) {
    mipc_status_t st;
    int absent = 0;
    if ((st = mipc_wr_u8(w, &in->function)) != MIPC_OK) {
        return st;
    }
    if (!in->has_mode) {
        absent = 1;
    } else if (absent) {
        return MIPC_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = mipc_wr_u8(w, &in->mode)) != MIPC_OK) {
            return st;
        }
    }
    if (!in->has_scaling) {
        absent = 1;
    } else if (absent) {
        return MIPC_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = mipc_wr_f32(w, &in->scaling)) != MIPC_OK) {
            return st;
        }
    }
    if (!in->has_uncertainty) {
        absent = 1;
    } else if (absent) {
        return MIPC_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = mipc_wr_f32(w, &in->uncertainty)) != MIPC_OK) {
            return st;
        }
    }
    return MIPC_OK;
}

mipc_status_t mipc_threedm_odometer_config_encode(const mipc_threedm_odometer_config_t *value, uint8_t *buf,
                                                  size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mipc_writer_init(&w, buf, cap);
    st = mipc_threedm_odometer_config_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mipc_status_t mipc_threedm_odometer_config_decode(const uint8_t *data, size_t len,
                                                  mipc_threedm_odometer_config_t *out,
                                                  mipc_decode_error_t *err) {
    mipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_threedm_odometer_config_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

/* ---- mipc_threedm_odometer_config_response_t */

static int mipc_threedm_odometer_config_response_read(mipc_reader_t *r,
                                                      mipc_threedm_odometer_config_response_t *out) {
    mipc_rd_push(r, "mode");
    if (mipc_rd_u8(r, &out->mode)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "scaling");
    if (mipc_rd_f32(r, &out->scaling)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "uncertainty");
    if (mipc_rd_f32(r, &out->uncertainty)) {
        return -1;
    }
    mipc_rd_pop(r);
    return mipc_rd_finish(r);
}

static mipc_status_t
mipc_threedm_odometer_config_response_write(mipc_writer_t *w,
                                            const mipc_threedm_odometer_config_response_t *in) {
    mipc_status_t st;
    if ((st = mipc_wr_u8(w, &in->mode)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_f32(w, &in->scaling)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_f32(w, &in->uncertainty)) != MIPC_OK) {
        return st;
    }
    return MIPC_OK;
}

mipc_status_t
mipc_threedm_odometer_config_response_encode(const mipc_threedm_odometer_config_response_t *value,
                                             uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mipc_writer_init(&w, buf, cap);
    st = mipc_threedm_odometer_config_response_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 9 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mipc_threedm_odometer_config_response_load(const uint8_t *d,
                                                      mipc_threedm_odometer_config_response_t *out) {
    out->mode = mipc_ld_u8(d + 0);
    out->scaling = mipc_ld_f32(d + 1);
    out->uncertainty = mipc_ld_f32(d + 5);
    return 0;
}

/* The general reader: lengths other than 9, bad bool bytes, error details. */
static MIPC_NOINLINE mipc_status_t mipc_threedm_odometer_config_response_decode_read(
    const uint8_t *data, size_t len, mipc_threedm_odometer_config_response_t *out, mipc_decode_error_t *err) {
    mipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_threedm_odometer_config_response_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t mipc_threedm_odometer_config_response_decode(const uint8_t *data, size_t len,
                                                           mipc_threedm_odometer_config_response_t *out,
                                                           mipc_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 9 && mipc_threedm_odometer_config_response_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_threedm_odometer_config_response_decode_read(data, len, out, err);
}

/* ---- mipc_threedm_advanced_lowpass_filter_t */

static int mipc_threedm_advanced_lowpass_filter_read(mipc_reader_t *r,
                                                     mipc_threedm_advanced_lowpass_filter_t *out) {
    mipc_rd_push(r, "function");
    if (mipc_rd_u8(r, &out->function)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "target_descriptor");
    if (mipc_rd_u8(r, &out->target_descriptor)) {
        return -1;
    }
    mipc_rd_pop(r);
    if (r->pos < r->len) {
        out->has_enable = true;
        mipc_rd_push(r, "enable");
        if (mipc_rd_bool(r, &out->enable)) {
            return -1;
        }
        mipc_rd_pop(r);
    }
    if (r->pos < r->len) {
        out->has_manual = true;
        mipc_rd_push(r, "manual");
        if (mipc_rd_bool(r, &out->manual)) {
            return -1;
        }
        mipc_rd_pop(r);
    }
    if (r->pos < r->len) {
        out->has_frequency = true;
        mipc_rd_push(r, "frequency");
        if (mipc_rd_u16(r, &out->frequency)) {
            return -1;
        }
        mipc_rd_pop(r);
    }
    if (r->pos < r->len) {
        out->has_reserved = true;
        mipc_rd_push(r, "reserved");
        if (mipc_rd_u8(r, &out->reserved)) {
            return -1;
        }
        mipc_rd_pop(r);
    }
    return mipc_rd_finish(r);
}

static mipc_status_t
mipc_threedm_advanced_lowpass_filter_write(mipc_writer_t *w,
                                           const mipc_threedm_advanced_lowpass_filter_t *in) {
    mipc_status_t st;
    int absent = 0;
    if ((st = mipc_wr_u8(w, &in->function)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u8(w, &in->target_descriptor)) != MIPC_OK) {
        return st;
    }
    if (!in->has_enable) {
        absent = 1;
    } else if (absent) {
        return MIPC_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = mipc_wr_bool(w, &in->enable)) != MIPC_OK) {
            return st;
        }
    }
    if (!in->has_manual) {
        absent = 1;
    } else if (absent) {
        return MIPC_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = mipc_wr_bool(w, &in->manual)) != MIPC_OK) {
            return st;
        }
    }
    if (!in->has_frequency) {
        absent = 1;
    } else if (absent) {
        return MIPC_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = mipc_wr_u16(w, &in->frequency)) != MIPC_OK) {
            return st;
        }
    }
    if (!in->has_reserved) {
        absent = 1;
    } else if (absent) {
        return MIPC_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = mipc_wr_u8(w, &in->reserved)) != MIPC_OK) {
            return st;
        }
    }
    return MIPC_OK;
}

mipc_status_t mipc_threedm_advanced_lowpass_filter_encode(const mipc_threedm_advanced_lowpass_filter_t *value,
                                                          uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mipc_writer_init(&w, buf, cap);
    st = mipc_threedm_advanced_lowpass_filter_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mipc_status_t mipc_threedm_advanced_lowpass_filter_decode(const uint8_t *data, size_t len,
                                                          mipc_threedm_advanced_lowpass_filter_t *out,
                                                          mipc_decode_error_t *err) {
    mipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_threedm_advanced_lowpass_filter_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

/* ---- mipc_threedm_advanced_lowpass_filter_response_t */

static int
mipc_threedm_advanced_lowpass_filter_response_read(mipc_reader_t *r,
                                                   mipc_threedm_advanced_lowpass_filter_response_t *out) {
    mipc_rd_push(r, "target_descriptor");
    if (mipc_rd_u8(r, &out->target_descriptor)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "enable");
    if (mipc_rd_bool(r, &out->enable)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "manual");
    if (mipc_rd_bool(r, &out->manual)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "frequency");
    if (mipc_rd_u16(r, &out->frequency)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "reserved");
    if (mipc_rd_u8(r, &out->reserved)) {
        return -1;
    }
    mipc_rd_pop(r);
    return mipc_rd_finish(r);
}

static mipc_status_t mipc_threedm_advanced_lowpass_filter_response_write(
    mipc_writer_t *w, const mipc_threedm_advanced_lowpass_filter_response_t *in) {
    mipc_status_t st;
    if ((st = mipc_wr_u8(w, &in->target_descriptor)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_bool(w, &in->enable)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_bool(w, &in->manual)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u16(w, &in->frequency)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u8(w, &in->reserved)) != MIPC_OK) {
        return st;
    }
    return MIPC_OK;
}

mipc_status_t mipc_threedm_advanced_lowpass_filter_response_encode(
    const mipc_threedm_advanced_lowpass_filter_response_t *value, uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mipc_writer_init(&w, buf, cap);
    st = mipc_threedm_advanced_lowpass_filter_response_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 6 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int
mipc_threedm_advanced_lowpass_filter_response_load(const uint8_t *d,
                                                   mipc_threedm_advanced_lowpass_filter_response_t *out) {
    out->target_descriptor = mipc_ld_u8(d + 0);
    if (d[1] > 1) {
        return -1;
    }
    out->enable = mipc_ld_bool(d + 1);
    if (d[2] > 1) {
        return -1;
    }
    out->manual = mipc_ld_bool(d + 2);
    out->frequency = mipc_ld_u16(d + 3);
    out->reserved = mipc_ld_u8(d + 5);
    return 0;
}

/* The general reader: lengths other than 6, bad bool bytes, error details. */
static MIPC_NOINLINE mipc_status_t mipc_threedm_advanced_lowpass_filter_response_decode_read(
    const uint8_t *data, size_t len, mipc_threedm_advanced_lowpass_filter_response_t *out,
    mipc_decode_error_t *err) {
    mipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_threedm_advanced_lowpass_filter_response_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t
mipc_threedm_advanced_lowpass_filter_response_decode(const uint8_t *data, size_t len,
                                                     mipc_threedm_advanced_lowpass_filter_response_t *out,
                                                     mipc_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 6 && mipc_threedm_advanced_lowpass_filter_response_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_threedm_advanced_lowpass_filter_response_decode_read(data, len, out, err);
}

/* ---- mipc_threedm_complementary_filter_t */

static int mipc_threedm_complementary_filter_read(mipc_reader_t *r,
                                                  mipc_threedm_complementary_filter_t *out) {
    mipc_rd_push(r, "function");
    if (mipc_rd_u8(r, &out->function)) {
        return -1;
    }
    mipc_rd_pop(r);
    if (r->pos < r->len) {
        out->has_pitch_roll_enable = true;
        mipc_rd_push(r, "pitch_roll_enable");
        if (mipc_rd_bool(r, &out->pitch_roll_enable)) {
            return -1;
        }
        mipc_rd_pop(r);
    }
    if (r->pos < r->len) {
        out->has_heading_enable = true;
        mipc_rd_push(r, "heading_enable");
        if (mipc_rd_bool(r, &out->heading_enable)) {
            return -1;
        }
        mipc_rd_pop(r);
    }
    if (r->pos < r->len) {
        out->has_pitch_roll_time_constant = true;
        mipc_rd_push(r, "pitch_roll_time_constant");
        if (mipc_rd_f32(r, &out->pitch_roll_time_constant)) {
            return -1;
        }
        mipc_rd_pop(r);
    }
    if (r->pos < r->len) {
        out->has_heading_time_constant = true;
        mipc_rd_push(r, "heading_time_constant");
        if (mipc_rd_f32(r, &out->heading_time_constant)) {
            return -1;
        }
        mipc_rd_pop(r);
    }
    return mipc_rd_finish(r);
}

static mipc_status_t mipc_threedm_complementary_filter_write(mipc_writer_t *w,
                                                             const mipc_threedm_complementary_filter_t *in) {
    mipc_status_t st;
    int absent = 0;
    if ((st = mipc_wr_u8(w, &in->function)) != MIPC_OK) {
        return st;
    }
    if (!in->has_pitch_roll_enable) {
        absent = 1;
    } else if (absent) {
        return MIPC_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = mipc_wr_bool(w, &in->pitch_roll_enable)) != MIPC_OK) {
            return st;
        }
    }
    if (!in->has_heading_enable) {
        absent = 1;
    } else if (absent) {
        return MIPC_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = mipc_wr_bool(w, &in->heading_enable)) != MIPC_OK) {
            return st;
        }
    }
    if (!in->has_pitch_roll_time_constant) {
        absent = 1;
    } else if (absent) {
        return MIPC_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = mipc_wr_f32(w, &in->pitch_roll_time_constant)) != MIPC_OK) {
            return st;
        }
    }
    if (!in->has_heading_time_constant) {
        absent = 1;
    } else if (absent) {
        return MIPC_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = mipc_wr_f32(w, &in->heading_time_constant)) != MIPC_OK) {
            return st;
        }
    }
    return MIPC_OK;
}

mipc_status_t mipc_threedm_complementary_filter_encode(const mipc_threedm_complementary_filter_t *value,
                                                       uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mipc_writer_init(&w, buf, cap);
    st = mipc_threedm_complementary_filter_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mipc_status_t mipc_threedm_complementary_filter_decode(const uint8_t *data, size_t len,
                                                       mipc_threedm_complementary_filter_t *out,
                                                       mipc_decode_error_t *err) {
    mipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_threedm_complementary_filter_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

/* ---- mipc_threedm_complementary_filter_response_t */

static int
mipc_threedm_complementary_filter_response_read(mipc_reader_t *r,
                                                mipc_threedm_complementary_filter_response_t *out) {
    mipc_rd_push(r, "pitch_roll_enable");
    if (mipc_rd_bool(r, &out->pitch_roll_enable)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "heading_enable");
    if (mipc_rd_bool(r, &out->heading_enable)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "pitch_roll_time_constant");
    if (mipc_rd_f32(r, &out->pitch_roll_time_constant)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "heading_time_constant");
    if (mipc_rd_f32(r, &out->heading_time_constant)) {
        return -1;
    }
    mipc_rd_pop(r);
    return mipc_rd_finish(r);
}

static mipc_status_t
mipc_threedm_complementary_filter_response_write(mipc_writer_t *w,
                                                 const mipc_threedm_complementary_filter_response_t *in) {
    mipc_status_t st;
    if ((st = mipc_wr_bool(w, &in->pitch_roll_enable)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_bool(w, &in->heading_enable)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_f32(w, &in->pitch_roll_time_constant)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_f32(w, &in->heading_time_constant)) != MIPC_OK) {
        return st;
    }
    return MIPC_OK;
}

mipc_status_t
mipc_threedm_complementary_filter_response_encode(const mipc_threedm_complementary_filter_response_t *value,
                                                  uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mipc_writer_init(&w, buf, cap);
    st = mipc_threedm_complementary_filter_response_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 10 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int
mipc_threedm_complementary_filter_response_load(const uint8_t *d,
                                                mipc_threedm_complementary_filter_response_t *out) {
    if (d[0] > 1) {
        return -1;
    }
    out->pitch_roll_enable = mipc_ld_bool(d + 0);
    if (d[1] > 1) {
        return -1;
    }
    out->heading_enable = mipc_ld_bool(d + 1);
    out->pitch_roll_time_constant = mipc_ld_f32(d + 2);
    out->heading_time_constant = mipc_ld_f32(d + 6);
    return 0;
}

/* The general reader: lengths other than 10, bad bool bytes, error details. */
static MIPC_NOINLINE mipc_status_t mipc_threedm_complementary_filter_response_decode_read(
    const uint8_t *data, size_t len, mipc_threedm_complementary_filter_response_t *out,
    mipc_decode_error_t *err) {
    mipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_threedm_complementary_filter_response_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t
mipc_threedm_complementary_filter_response_decode(const uint8_t *data, size_t len,
                                                  mipc_threedm_complementary_filter_response_t *out,
                                                  mipc_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 10 && mipc_threedm_complementary_filter_response_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_threedm_complementary_filter_response_decode_read(data, len, out, err);
}

/* ---- mipc_threedm_sensor_range_t */

static int mipc_threedm_sensor_range_read(mipc_reader_t *r, mipc_threedm_sensor_range_t *out) {
    mipc_rd_push(r, "function");
    if (mipc_rd_u8(r, &out->function)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "sensor");
    if (mipc_rd_u8(r, &out->sensor)) {
        return -1;
    }
    mipc_rd_pop(r);
    if (r->pos < r->len) {
        out->has_setting = true;
        mipc_rd_push(r, "setting");
        if (mipc_rd_u8(r, &out->setting)) {
            return -1;
        }
        mipc_rd_pop(r);
    }
    return mipc_rd_finish(r);
}

static mipc_status_t mipc_threedm_sensor_range_write(mipc_writer_t *w,
                                                     const mipc_threedm_sensor_range_t *in) {
    mipc_status_t st;
    int absent = 0;
    if ((st = mipc_wr_u8(w, &in->function)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u8(w, &in->sensor)) != MIPC_OK) {
        return st;
    }
    if (!in->has_setting) {
        absent = 1;
    } else if (absent) {
        return MIPC_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = mipc_wr_u8(w, &in->setting)) != MIPC_OK) {
            return st;
        }
    }
    return MIPC_OK;
}

mipc_status_t mipc_threedm_sensor_range_encode(const mipc_threedm_sensor_range_t *value, uint8_t *buf,
                                               size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mipc_writer_init(&w, buf, cap);
    st = mipc_threedm_sensor_range_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mipc_status_t mipc_threedm_sensor_range_decode(const uint8_t *data, size_t len,
                                               mipc_threedm_sensor_range_t *out, mipc_decode_error_t *err) {
    mipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_threedm_sensor_range_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

/* ---- mipc_threedm_sensor_range_response_t */

static int mipc_threedm_sensor_range_response_read(mipc_reader_t *r,
                                                   mipc_threedm_sensor_range_response_t *out) {
    mipc_rd_push(r, "sensor");
    if (mipc_rd_u8(r, &out->sensor)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "setting");
    if (mipc_rd_u8(r, &out->setting)) {
        return -1;
    }
    mipc_rd_pop(r);
    return mipc_rd_finish(r);
}

static mipc_status_t
mipc_threedm_sensor_range_response_write(mipc_writer_t *w, const mipc_threedm_sensor_range_response_t *in) {
    mipc_status_t st;
    if ((st = mipc_wr_u8(w, &in->sensor)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u8(w, &in->setting)) != MIPC_OK) {
        return st;
    }
    return MIPC_OK;
}

mipc_status_t mipc_threedm_sensor_range_response_encode(const mipc_threedm_sensor_range_response_t *value,
                                                        uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mipc_writer_init(&w, buf, cap);
    st = mipc_threedm_sensor_range_response_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 2 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mipc_threedm_sensor_range_response_load(const uint8_t *d,
                                                   mipc_threedm_sensor_range_response_t *out) {
    out->sensor = mipc_ld_u8(d + 0);
    out->setting = mipc_ld_u8(d + 1);
    return 0;
}

/* The general reader: lengths other than 2, bad bool bytes, error details. */
static MIPC_NOINLINE mipc_status_t mipc_threedm_sensor_range_response_decode_read(
    const uint8_t *data, size_t len, mipc_threedm_sensor_range_response_t *out, mipc_decode_error_t *err) {
    mipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_threedm_sensor_range_response_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t mipc_threedm_sensor_range_response_decode(const uint8_t *data, size_t len,
                                                        mipc_threedm_sensor_range_response_t *out,
                                                        mipc_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 2 && mipc_threedm_sensor_range_response_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_threedm_sensor_range_response_decode_read(data, len, out, err);
}

/* ---- mipc_threedm_get_calibrated_sensor_ranges_t */

static int mipc_threedm_get_calibrated_sensor_ranges_read(mipc_reader_t *r,
                                                          mipc_threedm_get_calibrated_sensor_ranges_t *out) {
    mipc_rd_push(r, "sensor");
    if (mipc_rd_u8(r, &out->sensor)) {
        return -1;
    }
    mipc_rd_pop(r);
    return mipc_rd_finish(r);
}

static mipc_status_t
mipc_threedm_get_calibrated_sensor_ranges_write(mipc_writer_t *w,
                                                const mipc_threedm_get_calibrated_sensor_ranges_t *in) {
    mipc_status_t st;
    if ((st = mipc_wr_u8(w, &in->sensor)) != MIPC_OK) {
        return st;
    }
    return MIPC_OK;
}

mipc_status_t
mipc_threedm_get_calibrated_sensor_ranges_encode(const mipc_threedm_get_calibrated_sensor_ranges_t *value,
                                                 uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mipc_writer_init(&w, buf, cap);
    st = mipc_threedm_get_calibrated_sensor_ranges_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 1 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mipc_threedm_get_calibrated_sensor_ranges_load(const uint8_t *d,
                                                          mipc_threedm_get_calibrated_sensor_ranges_t *out) {
    out->sensor = mipc_ld_u8(d + 0);
    return 0;
}

/* The general reader: lengths other than 1, bad bool bytes, error details. */
static MIPC_NOINLINE mipc_status_t mipc_threedm_get_calibrated_sensor_ranges_decode_read(
    const uint8_t *data, size_t len, mipc_threedm_get_calibrated_sensor_ranges_t *out,
    mipc_decode_error_t *err) {
    mipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_threedm_get_calibrated_sensor_ranges_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t
mipc_threedm_get_calibrated_sensor_ranges_decode(const uint8_t *data, size_t len,
                                                 mipc_threedm_get_calibrated_sensor_ranges_t *out,
                                                 mipc_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 1 && mipc_threedm_get_calibrated_sensor_ranges_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_threedm_get_calibrated_sensor_ranges_decode_read(data, len, out, err);
}

/* ---- mipc_threedm_calibrated_sensor_ranges_t */

static int mipc_threedm_calibrated_sensor_ranges_read(mipc_reader_t *r,
                                                      mipc_threedm_calibrated_sensor_ranges_t *out) {
    size_t i;
    mipc_rd_push(r, "sensor");
    if (mipc_rd_u8(r, &out->sensor)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "num_ranges");
    if (mipc_rd_u8(r, &out->num_ranges)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "ranges");
    if (out->num_ranges > 50) {
        return mipc_rd_count_error(r, (uint64_t)out->num_ranges, 50);
    }
    for (i = 0; i < (size_t)out->num_ranges; i++) {
        mipc_rd_index(r, i);
        if (mipc_sensor_range_entry_read(r, &out->ranges[i])) {
            return -1;
        }
    }
    mipc_rd_pop(r);
    return mipc_rd_finish(r);
}

static mipc_status_t
mipc_threedm_calibrated_sensor_ranges_write(mipc_writer_t *w,
                                            const mipc_threedm_calibrated_sensor_ranges_t *in) {
    mipc_status_t st;
    size_t i;
    if ((st = mipc_wr_u8(w, &in->sensor)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u8(w, &in->num_ranges)) != MIPC_OK) {
        return st;
    }
    if (in->num_ranges > 50) {
        return MIPC_ERR_INVALID;
    }
    for (i = 0; i < (size_t)in->num_ranges; i++) {
        if ((st = mipc_sensor_range_entry_write(w, &in->ranges[i])) != MIPC_OK) {
            return st;
        }
    }
    return MIPC_OK;
}

mipc_status_t
mipc_threedm_calibrated_sensor_ranges_encode(const mipc_threedm_calibrated_sensor_ranges_t *value,
                                             uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mipc_writer_init(&w, buf, cap);
    st = mipc_threedm_calibrated_sensor_ranges_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mipc_status_t mipc_threedm_calibrated_sensor_ranges_decode(const uint8_t *data, size_t len,
                                                           mipc_threedm_calibrated_sensor_ranges_t *out,
                                                           mipc_decode_error_t *err) {
    mipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_threedm_calibrated_sensor_ranges_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

/* ---- mipc_threedm_lowpass_filter_t */

static int mipc_threedm_lowpass_filter_read(mipc_reader_t *r, mipc_threedm_lowpass_filter_t *out) {
    mipc_rd_push(r, "function");
    if (mipc_rd_u8(r, &out->function)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "desc_set");
    if (mipc_rd_u8(r, &out->desc_set)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "field_desc");
    if (mipc_rd_u8(r, &out->field_desc)) {
        return -1;
    }
    mipc_rd_pop(r);
    if (r->pos < r->len) {
        out->has_enable = true;
        mipc_rd_push(r, "enable");
        if (mipc_rd_bool(r, &out->enable)) {
            return -1;
        }
        mipc_rd_pop(r);
    }
    if (r->pos < r->len) {
        out->has_manual = true;
        mipc_rd_push(r, "manual");
        if (mipc_rd_bool(r, &out->manual)) {
            return -1;
        }
        mipc_rd_pop(r);
    }
    if (r->pos < r->len) {
        out->has_frequency = true;
        mipc_rd_push(r, "frequency");
        if (mipc_rd_f32(r, &out->frequency)) {
            return -1;
        }
        mipc_rd_pop(r);
    }
    return mipc_rd_finish(r);
}

static mipc_status_t mipc_threedm_lowpass_filter_write(mipc_writer_t *w,
                                                       const mipc_threedm_lowpass_filter_t *in) {
    mipc_status_t st;
    int absent = 0;
    if ((st = mipc_wr_u8(w, &in->function)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u8(w, &in->desc_set)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u8(w, &in->field_desc)) != MIPC_OK) {
        return st;
    }
    if (!in->has_enable) {
        absent = 1;
    } else if (absent) {
        return MIPC_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = mipc_wr_bool(w, &in->enable)) != MIPC_OK) {
            return st;
        }
    }
    if (!in->has_manual) {
        absent = 1;
    } else if (absent) {
        return MIPC_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = mipc_wr_bool(w, &in->manual)) != MIPC_OK) {
            return st;
        }
    }
    if (!in->has_frequency) {
        absent = 1;
    } else if (absent) {
        return MIPC_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = mipc_wr_f32(w, &in->frequency)) != MIPC_OK) {
            return st;
        }
    }
    return MIPC_OK;
}

mipc_status_t mipc_threedm_lowpass_filter_encode(const mipc_threedm_lowpass_filter_t *value, uint8_t *buf,
                                                 size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mipc_writer_init(&w, buf, cap);
    st = mipc_threedm_lowpass_filter_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mipc_status_t mipc_threedm_lowpass_filter_decode(const uint8_t *data, size_t len,
                                                 mipc_threedm_lowpass_filter_t *out,
                                                 mipc_decode_error_t *err) {
    mipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_threedm_lowpass_filter_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

/* ---- mipc_threedm_lowpass_filter_response_t */

static int mipc_threedm_lowpass_filter_response_read(mipc_reader_t *r,
                                                     mipc_threedm_lowpass_filter_response_t *out) {
    mipc_rd_push(r, "desc_set");
    if (mipc_rd_u8(r, &out->desc_set)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "field_desc");
    if (mipc_rd_u8(r, &out->field_desc)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "enable");
    if (mipc_rd_bool(r, &out->enable)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "manual");
    if (mipc_rd_bool(r, &out->manual)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "frequency");
    if (mipc_rd_f32(r, &out->frequency)) {
        return -1;
    }
    mipc_rd_pop(r);
    return mipc_rd_finish(r);
}

static mipc_status_t
mipc_threedm_lowpass_filter_response_write(mipc_writer_t *w,
                                           const mipc_threedm_lowpass_filter_response_t *in) {
    mipc_status_t st;
    if ((st = mipc_wr_u8(w, &in->desc_set)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u8(w, &in->field_desc)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_bool(w, &in->enable)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_bool(w, &in->manual)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_f32(w, &in->frequency)) != MIPC_OK) {
        return st;
    }
    return MIPC_OK;
}

mipc_status_t mipc_threedm_lowpass_filter_response_encode(const mipc_threedm_lowpass_filter_response_t *value,
                                                          uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mipc_writer_init(&w, buf, cap);
    st = mipc_threedm_lowpass_filter_response_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 8 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mipc_threedm_lowpass_filter_response_load(const uint8_t *d,
                                                     mipc_threedm_lowpass_filter_response_t *out) {
    out->desc_set = mipc_ld_u8(d + 0);
    out->field_desc = mipc_ld_u8(d + 1);
    if (d[2] > 1) {
        return -1;
    }
    out->enable = mipc_ld_bool(d + 2);
    if (d[3] > 1) {
        return -1;
    }
    out->manual = mipc_ld_bool(d + 3);
    out->frequency = mipc_ld_f32(d + 4);
    return 0;
}

/* The general reader: lengths other than 8, bad bool bytes, error details. */
static MIPC_NOINLINE mipc_status_t mipc_threedm_lowpass_filter_response_decode_read(
    const uint8_t *data, size_t len, mipc_threedm_lowpass_filter_response_t *out, mipc_decode_error_t *err) {
    mipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_threedm_lowpass_filter_response_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t mipc_threedm_lowpass_filter_response_decode(const uint8_t *data, size_t len,
                                                          mipc_threedm_lowpass_filter_response_t *out,
                                                          mipc_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 8 && mipc_threedm_lowpass_filter_response_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_threedm_lowpass_filter_response_decode_read(data, len, out, err);
}

/* ---- mipc_threedm_poll_imu_data_t */

static int mipc_threedm_poll_imu_data_read(mipc_reader_t *r, mipc_threedm_poll_imu_data_t *out) {
    size_t i;
    mipc_rd_push(r, "option");
    if (mipc_rd_u8(r, &out->option)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "num_descriptors");
    if (mipc_rd_u8(r, &out->num_descriptors)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "descriptors");
    if (out->num_descriptors > 83) {
        return mipc_rd_count_error(r, (uint64_t)out->num_descriptors, 83);
    }
    for (i = 0; i < (size_t)out->num_descriptors; i++) {
        mipc_rd_index(r, i);
        if (mipc_gx5_poll_descriptor_read(r, &out->descriptors[i])) {
            return -1;
        }
    }
    mipc_rd_pop(r);
    return mipc_rd_finish(r);
}

static mipc_status_t mipc_threedm_poll_imu_data_write(mipc_writer_t *w,
                                                      const mipc_threedm_poll_imu_data_t *in) {
    mipc_status_t st;
    size_t i;
    if ((st = mipc_wr_u8(w, &in->option)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u8(w, &in->num_descriptors)) != MIPC_OK) {
        return st;
    }
    if (in->num_descriptors > 83) {
        return MIPC_ERR_INVALID;
    }
    for (i = 0; i < (size_t)in->num_descriptors; i++) {
        if ((st = mipc_gx5_poll_descriptor_write(w, &in->descriptors[i])) != MIPC_OK) {
            return st;
        }
    }
    return MIPC_OK;
}

mipc_status_t mipc_threedm_poll_imu_data_encode(const mipc_threedm_poll_imu_data_t *value, uint8_t *buf,
                                                size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mipc_writer_init(&w, buf, cap);
    st = mipc_threedm_poll_imu_data_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mipc_status_t mipc_threedm_poll_imu_data_decode(const uint8_t *data, size_t len,
                                                mipc_threedm_poll_imu_data_t *out, mipc_decode_error_t *err) {
    mipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_threedm_poll_imu_data_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

/* ---- mipc_threedm_poll_gnss_data_t */

static int mipc_threedm_poll_gnss_data_read(mipc_reader_t *r, mipc_threedm_poll_gnss_data_t *out) {
    size_t i;
    mipc_rd_push(r, "option");
    if (mipc_rd_u8(r, &out->option)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "num_descriptors");
    if (mipc_rd_u8(r, &out->num_descriptors)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "descriptors");
    if (out->num_descriptors > 83) {
        return mipc_rd_count_error(r, (uint64_t)out->num_descriptors, 83);
    }
    for (i = 0; i < (size_t)out->num_descriptors; i++) {
        mipc_rd_index(r, i);
        if (mipc_gx5_poll_descriptor_read(r, &out->descriptors[i])) {
            return -1;
        }
    }
    mipc_rd_pop(r);
    return mipc_rd_finish(r);
}

static mipc_status_t mipc_threedm_poll_gnss_data_write(mipc_writer_t *w,
                                                       const mipc_threedm_poll_gnss_data_t *in) {
    mipc_status_t st;
    size_t i;
    if ((st = mipc_wr_u8(w, &in->option)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u8(w, &in->num_descriptors)) != MIPC_OK) {
        return st;
    }
    if (in->num_descriptors > 83) {
        return MIPC_ERR_INVALID;
    }
    for (i = 0; i < (size_t)in->num_descriptors; i++) {
        if ((st = mipc_gx5_poll_descriptor_write(w, &in->descriptors[i])) != MIPC_OK) {
            return st;
        }
    }
    return MIPC_OK;
}

mipc_status_t mipc_threedm_poll_gnss_data_encode(const mipc_threedm_poll_gnss_data_t *value, uint8_t *buf,
                                                 size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mipc_writer_init(&w, buf, cap);
    st = mipc_threedm_poll_gnss_data_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mipc_status_t mipc_threedm_poll_gnss_data_decode(const uint8_t *data, size_t len,
                                                 mipc_threedm_poll_gnss_data_t *out,
                                                 mipc_decode_error_t *err) {
    mipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_threedm_poll_gnss_data_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

/* ---- mipc_threedm_poll_filter_data_t */

static int mipc_threedm_poll_filter_data_read(mipc_reader_t *r, mipc_threedm_poll_filter_data_t *out) {
    size_t i;
    mipc_rd_push(r, "option");
    if (mipc_rd_u8(r, &out->option)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "num_descriptors");
    if (mipc_rd_u8(r, &out->num_descriptors)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "descriptors");
    if (out->num_descriptors > 83) {
        return mipc_rd_count_error(r, (uint64_t)out->num_descriptors, 83);
    }
    for (i = 0; i < (size_t)out->num_descriptors; i++) {
        mipc_rd_index(r, i);
        if (mipc_gx5_poll_descriptor_read(r, &out->descriptors[i])) {
            return -1;
        }
    }
    mipc_rd_pop(r);
    return mipc_rd_finish(r);
}

static mipc_status_t mipc_threedm_poll_filter_data_write(mipc_writer_t *w,
                                                         const mipc_threedm_poll_filter_data_t *in) {
    mipc_status_t st;
    size_t i;
    if ((st = mipc_wr_u8(w, &in->option)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u8(w, &in->num_descriptors)) != MIPC_OK) {
        return st;
    }
    if (in->num_descriptors > 83) {
        return MIPC_ERR_INVALID;
    }
    for (i = 0; i < (size_t)in->num_descriptors; i++) {
        if ((st = mipc_gx5_poll_descriptor_write(w, &in->descriptors[i])) != MIPC_OK) {
            return st;
        }
    }
    return MIPC_OK;
}

mipc_status_t mipc_threedm_poll_filter_data_encode(const mipc_threedm_poll_filter_data_t *value, uint8_t *buf,
                                                   size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mipc_writer_init(&w, buf, cap);
    st = mipc_threedm_poll_filter_data_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mipc_status_t mipc_threedm_poll_filter_data_decode(const uint8_t *data, size_t len,
                                                   mipc_threedm_poll_filter_data_t *out,
                                                   mipc_decode_error_t *err) {
    mipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_threedm_poll_filter_data_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

/* ---- mipc_threedm_poll_nmea_data_t */

static int mipc_threedm_poll_nmea_data_read(mipc_reader_t *r, mipc_threedm_poll_nmea_data_t *out) {
    size_t i;
    mipc_rd_push(r, "suppress_ack");
    if (mipc_rd_bool(r, &out->suppress_ack)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "count");
    if (mipc_rd_u8(r, &out->count)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "format_entries");
    if (out->count > 50) {
        return mipc_rd_count_error(r, (uint64_t)out->count, 50);
    }
    for (i = 0; i < (size_t)out->count; i++) {
        mipc_rd_index(r, i);
        if (mipc_nmea_message_read(r, &out->format_entries[i])) {
            return -1;
        }
    }
    mipc_rd_pop(r);
    return mipc_rd_finish(r);
}

static mipc_status_t mipc_threedm_poll_nmea_data_write(mipc_writer_t *w,
                                                       const mipc_threedm_poll_nmea_data_t *in) {
    mipc_status_t st;
    size_t i;
    if ((st = mipc_wr_bool(w, &in->suppress_ack)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u8(w, &in->count)) != MIPC_OK) {
        return st;
    }
    if (in->count > 50) {
        return MIPC_ERR_INVALID;
    }
    for (i = 0; i < (size_t)in->count; i++) {
        if ((st = mipc_nmea_message_write(w, &in->format_entries[i])) != MIPC_OK) {
            return st;
        }
    }
    return MIPC_OK;
}

mipc_status_t mipc_threedm_poll_nmea_data_encode(const mipc_threedm_poll_nmea_data_t *value, uint8_t *buf,
                                                 size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mipc_writer_init(&w, buf, cap);
    st = mipc_threedm_poll_nmea_data_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mipc_status_t mipc_threedm_poll_nmea_data_decode(const uint8_t *data, size_t len,
                                                 mipc_threedm_poll_nmea_data_t *out,
                                                 mipc_decode_error_t *err) {
    mipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_threedm_poll_nmea_data_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

/* ---- mipc_threedm_poll_data_t */

static int mipc_threedm_poll_data_read(mipc_reader_t *r, mipc_threedm_poll_data_t *out) {
    size_t i;
    mipc_rd_push(r, "desc_set");
    if (mipc_rd_u8(r, &out->desc_set)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "suppress_ack");
    if (mipc_rd_bool(r, &out->suppress_ack)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "num_descriptors");
    if (mipc_rd_u8(r, &out->num_descriptors)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "descriptors");
    if (out->num_descriptors > 250) {
        return mipc_rd_count_error(r, (uint64_t)out->num_descriptors, 250);
    }
    for (i = 0; i < (size_t)out->num_descriptors; i++) {
        mipc_rd_index(r, i);
        if (mipc_rd_u8(r, &out->descriptors[i])) {
            return -1;
        }
    }
    mipc_rd_pop(r);
    return mipc_rd_finish(r);
}

static mipc_status_t mipc_threedm_poll_data_write(mipc_writer_t *w, const mipc_threedm_poll_data_t *in) {
    mipc_status_t st;
    size_t i;
    if ((st = mipc_wr_u8(w, &in->desc_set)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_bool(w, &in->suppress_ack)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u8(w, &in->num_descriptors)) != MIPC_OK) {
        return st;
    }
    if (in->num_descriptors > 250) {
        return MIPC_ERR_INVALID;
    }
    for (i = 0; i < (size_t)in->num_descriptors; i++) {
        if ((st = mipc_wr_u8(w, &in->descriptors[i])) != MIPC_OK) {
            return st;
        }
    }
    return MIPC_OK;
}

mipc_status_t mipc_threedm_poll_data_encode(const mipc_threedm_poll_data_t *value, uint8_t *buf, size_t cap,
                                            size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mipc_writer_init(&w, buf, cap);
    st = mipc_threedm_poll_data_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mipc_status_t mipc_threedm_poll_data_decode(const uint8_t *data, size_t len, mipc_threedm_poll_data_t *out,
                                            mipc_decode_error_t *err) {
    mipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_threedm_poll_data_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

/* ---- mipc_threedm_get_imu_base_rate_t */

static int mipc_threedm_get_imu_base_rate_read(mipc_reader_t *r, mipc_threedm_get_imu_base_rate_t *out) {
    (void)out;
    return mipc_rd_finish(r);
}

static mipc_status_t mipc_threedm_get_imu_base_rate_write(mipc_writer_t *w,
                                                          const mipc_threedm_get_imu_base_rate_t *in) {
    (void)w;
    (void)in;
    return MIPC_OK;
}

mipc_status_t mipc_threedm_get_imu_base_rate_encode(const mipc_threedm_get_imu_base_rate_t *value,
                                                    uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mipc_writer_init(&w, buf, cap);
    st = mipc_threedm_get_imu_base_rate_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mipc_status_t mipc_threedm_get_imu_base_rate_decode(const uint8_t *data, size_t len,
                                                    mipc_threedm_get_imu_base_rate_t *out,
                                                    mipc_decode_error_t *err) {
    mipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_threedm_get_imu_base_rate_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

/* ---- mipc_threedm_imu_base_rate_t */

static int mipc_threedm_imu_base_rate_read(mipc_reader_t *r, mipc_threedm_imu_base_rate_t *out) {
    mipc_rd_push(r, "rate");
    if (mipc_rd_u16(r, &out->rate)) {
        return -1;
    }
    mipc_rd_pop(r);
    return mipc_rd_finish(r);
}

static mipc_status_t mipc_threedm_imu_base_rate_write(mipc_writer_t *w,
                                                      const mipc_threedm_imu_base_rate_t *in) {
    mipc_status_t st;
    if ((st = mipc_wr_u16(w, &in->rate)) != MIPC_OK) {
        return st;
    }
    return MIPC_OK;
}

mipc_status_t mipc_threedm_imu_base_rate_encode(const mipc_threedm_imu_base_rate_t *value, uint8_t *buf,
                                                size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mipc_writer_init(&w, buf, cap);
    st = mipc_threedm_imu_base_rate_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 2 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mipc_threedm_imu_base_rate_load(const uint8_t *d, mipc_threedm_imu_base_rate_t *out) {
    out->rate = mipc_ld_u16(d + 0);
    return 0;
}

/* The general reader: lengths other than 2, bad bool bytes, error details. */
static MIPC_NOINLINE mipc_status_t mipc_threedm_imu_base_rate_decode_read(const uint8_t *data, size_t len,
                                                                          mipc_threedm_imu_base_rate_t *out,
                                                                          mipc_decode_error_t *err) {
    mipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_threedm_imu_base_rate_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t mipc_threedm_imu_base_rate_decode(const uint8_t *data, size_t len,
                                                mipc_threedm_imu_base_rate_t *out, mipc_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 2 && mipc_threedm_imu_base_rate_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_threedm_imu_base_rate_decode_read(data, len, out, err);
}

/* ---- mipc_threedm_get_gnss_base_rate_t */

static int mipc_threedm_get_gnss_base_rate_read(mipc_reader_t *r, mipc_threedm_get_gnss_base_rate_t *out) {
    (void)out;
    return mipc_rd_finish(r);
}

static mipc_status_t mipc_threedm_get_gnss_base_rate_write(mipc_writer_t *w,
                                                           const mipc_threedm_get_gnss_base_rate_t *in) {
    (void)w;
    (void)in;
    return MIPC_OK;
}

mipc_status_t mipc_threedm_get_gnss_base_rate_encode(const mipc_threedm_get_gnss_base_rate_t *value,
                                                     uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mipc_writer_init(&w, buf, cap);
    st = mipc_threedm_get_gnss_base_rate_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mipc_status_t mipc_threedm_get_gnss_base_rate_decode(const uint8_t *data, size_t len,
                                                     mipc_threedm_get_gnss_base_rate_t *out,
                                                     mipc_decode_error_t *err) {
    mipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_threedm_get_gnss_base_rate_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

/* ---- mipc_threedm_gnss_base_rate_t */

static int mipc_threedm_gnss_base_rate_read(mipc_reader_t *r, mipc_threedm_gnss_base_rate_t *out) {
    mipc_rd_push(r, "rate");
    if (mipc_rd_u16(r, &out->rate)) {
        return -1;
    }
    mipc_rd_pop(r);
    return mipc_rd_finish(r);
}

static mipc_status_t mipc_threedm_gnss_base_rate_write(mipc_writer_t *w,
                                                       const mipc_threedm_gnss_base_rate_t *in) {
    mipc_status_t st;
    if ((st = mipc_wr_u16(w, &in->rate)) != MIPC_OK) {
        return st;
    }
    return MIPC_OK;
}

mipc_status_t mipc_threedm_gnss_base_rate_encode(const mipc_threedm_gnss_base_rate_t *value, uint8_t *buf,
                                                 size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mipc_writer_init(&w, buf, cap);
    st = mipc_threedm_gnss_base_rate_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 2 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mipc_threedm_gnss_base_rate_load(const uint8_t *d, mipc_threedm_gnss_base_rate_t *out) {
    out->rate = mipc_ld_u16(d + 0);
    return 0;
}

/* The general reader: lengths other than 2, bad bool bytes, error details. */
static MIPC_NOINLINE mipc_status_t mipc_threedm_gnss_base_rate_decode_read(const uint8_t *data, size_t len,
                                                                           mipc_threedm_gnss_base_rate_t *out,
                                                                           mipc_decode_error_t *err) {
    mipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_threedm_gnss_base_rate_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t mipc_threedm_gnss_base_rate_decode(const uint8_t *data, size_t len,
                                                 mipc_threedm_gnss_base_rate_t *out,
                                                 mipc_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 2 && mipc_threedm_gnss_base_rate_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_threedm_gnss_base_rate_decode_read(data, len, out, err);
}

/* ---- mipc_threedm_get_filter_base_rate_t */

static int mipc_threedm_get_filter_base_rate_read(mipc_reader_t *r,
                                                  mipc_threedm_get_filter_base_rate_t *out) {
    (void)out;
    return mipc_rd_finish(r);
}

static mipc_status_t mipc_threedm_get_filter_base_rate_write(mipc_writer_t *w,
                                                             const mipc_threedm_get_filter_base_rate_t *in) {
    (void)w;
    (void)in;
    return MIPC_OK;
}

mipc_status_t mipc_threedm_get_filter_base_rate_encode(const mipc_threedm_get_filter_base_rate_t *value,
                                                       uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mipc_writer_init(&w, buf, cap);
    st = mipc_threedm_get_filter_base_rate_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mipc_status_t mipc_threedm_get_filter_base_rate_decode(const uint8_t *data, size_t len,
                                                       mipc_threedm_get_filter_base_rate_t *out,
                                                       mipc_decode_error_t *err) {
    mipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_threedm_get_filter_base_rate_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

/* ---- mipc_threedm_filter_base_rate_t */

static int mipc_threedm_filter_base_rate_read(mipc_reader_t *r, mipc_threedm_filter_base_rate_t *out) {
    mipc_rd_push(r, "rate");
    if (mipc_rd_u16(r, &out->rate)) {
        return -1;
    }
    mipc_rd_pop(r);
    return mipc_rd_finish(r);
}

static mipc_status_t mipc_threedm_filter_base_rate_write(mipc_writer_t *w,
                                                         const mipc_threedm_filter_base_rate_t *in) {
    mipc_status_t st;
    if ((st = mipc_wr_u16(w, &in->rate)) != MIPC_OK) {
        return st;
    }
    return MIPC_OK;
}

mipc_status_t mipc_threedm_filter_base_rate_encode(const mipc_threedm_filter_base_rate_t *value, uint8_t *buf,
                                                   size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mipc_writer_init(&w, buf, cap);
    st = mipc_threedm_filter_base_rate_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 2 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mipc_threedm_filter_base_rate_load(const uint8_t *d, mipc_threedm_filter_base_rate_t *out) {
    out->rate = mipc_ld_u16(d + 0);
    return 0;
}

/* The general reader: lengths other than 2, bad bool bytes, error details. */
static MIPC_NOINLINE mipc_status_t mipc_threedm_filter_base_rate_decode_read(
    const uint8_t *data, size_t len, mipc_threedm_filter_base_rate_t *out, mipc_decode_error_t *err) {
    mipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_threedm_filter_base_rate_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t mipc_threedm_filter_base_rate_decode(const uint8_t *data, size_t len,
                                                   mipc_threedm_filter_base_rate_t *out,
                                                   mipc_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 2 && mipc_threedm_filter_base_rate_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_threedm_filter_base_rate_decode_read(data, len, out, err);
}

/* ---- mipc_threedm_get_base_rate_t */

static int mipc_threedm_get_base_rate_read(mipc_reader_t *r, mipc_threedm_get_base_rate_t *out) {
    mipc_rd_push(r, "desc_set");
    if (mipc_rd_u8(r, &out->desc_set)) {
        return -1;
    }
    mipc_rd_pop(r);
    return mipc_rd_finish(r);
}

static mipc_status_t mipc_threedm_get_base_rate_write(mipc_writer_t *w,
                                                      const mipc_threedm_get_base_rate_t *in) {
    mipc_status_t st;
    if ((st = mipc_wr_u8(w, &in->desc_set)) != MIPC_OK) {
        return st;
    }
    return MIPC_OK;
}

mipc_status_t mipc_threedm_get_base_rate_encode(const mipc_threedm_get_base_rate_t *value, uint8_t *buf,
                                                size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mipc_writer_init(&w, buf, cap);
    st = mipc_threedm_get_base_rate_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 1 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mipc_threedm_get_base_rate_load(const uint8_t *d, mipc_threedm_get_base_rate_t *out) {
    out->desc_set = mipc_ld_u8(d + 0);
    return 0;
}

/* The general reader: lengths other than 1, bad bool bytes, error details. */
static MIPC_NOINLINE mipc_status_t mipc_threedm_get_base_rate_decode_read(const uint8_t *data, size_t len,
                                                                          mipc_threedm_get_base_rate_t *out,
                                                                          mipc_decode_error_t *err) {
    mipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_threedm_get_base_rate_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t mipc_threedm_get_base_rate_decode(const uint8_t *data, size_t len,
                                                mipc_threedm_get_base_rate_t *out, mipc_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 1 && mipc_threedm_get_base_rate_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_threedm_get_base_rate_decode_read(data, len, out, err);
}

/* ---- mipc_threedm_base_rate_t */

static int mipc_threedm_base_rate_read(mipc_reader_t *r, mipc_threedm_base_rate_t *out) {
    mipc_rd_push(r, "desc_set");
    if (mipc_rd_u8(r, &out->desc_set)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "rate");
    if (mipc_rd_u16(r, &out->rate)) {
        return -1;
    }
    mipc_rd_pop(r);
    return mipc_rd_finish(r);
}

static mipc_status_t mipc_threedm_base_rate_write(mipc_writer_t *w, const mipc_threedm_base_rate_t *in) {
    mipc_status_t st;
    if ((st = mipc_wr_u8(w, &in->desc_set)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u16(w, &in->rate)) != MIPC_OK) {
        return st;
    }
    return MIPC_OK;
}

mipc_status_t mipc_threedm_base_rate_encode(const mipc_threedm_base_rate_t *value, uint8_t *buf, size_t cap,
                                            size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mipc_writer_init(&w, buf, cap);
    st = mipc_threedm_base_rate_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 3 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mipc_threedm_base_rate_load(const uint8_t *d, mipc_threedm_base_rate_t *out) {
    out->desc_set = mipc_ld_u8(d + 0);
    out->rate = mipc_ld_u16(d + 1);
    return 0;
}

/* The general reader: lengths other than 3, bad bool bytes, error details. */
static MIPC_NOINLINE mipc_status_t mipc_threedm_base_rate_decode_read(const uint8_t *data, size_t len,
                                                                      mipc_threedm_base_rate_t *out,
                                                                      mipc_decode_error_t *err) {
    mipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_threedm_base_rate_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t mipc_threedm_base_rate_decode(const uint8_t *data, size_t len, mipc_threedm_base_rate_t *out,
                                            mipc_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 3 && mipc_threedm_base_rate_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_threedm_base_rate_decode_read(data, len, out, err);
}

/* ---- mipc_threedm_imu_message_format_t */

static int mipc_threedm_imu_message_format_read(mipc_reader_t *r, mipc_threedm_imu_message_format_t *out) {
    size_t i;
    mipc_rd_push(r, "function");
    if (mipc_rd_u8(r, &out->function)) {
        return -1;
    }
    mipc_rd_pop(r);
    if (r->pos < r->len) {
        out->has_num_descriptors = true;
        mipc_rd_push(r, "num_descriptors");
        if (mipc_rd_u8(r, &out->num_descriptors)) {
            return -1;
        }
        mipc_rd_pop(r);
    }
    if (r->pos < r->len) {
        out->has_descriptors = true;
        mipc_rd_push(r, "descriptors");
        if (out->num_descriptors > 83) {
            return mipc_rd_count_error(r, (uint64_t)out->num_descriptors, 83);
        }
        for (i = 0; i < (size_t)out->num_descriptors; i++) {
            mipc_rd_index(r, i);
            if (mipc_descriptor_rate_read(r, &out->descriptors[i])) {
                return -1;
            }
        }
        mipc_rd_pop(r);
    }
    return mipc_rd_finish(r);
}

static mipc_status_t mipc_threedm_imu_message_format_write(mipc_writer_t *w,
                                                           const mipc_threedm_imu_message_format_t *in) {
    mipc_status_t st;
    size_t i;
    int absent = 0;
    if ((st = mipc_wr_u8(w, &in->function)) != MIPC_OK) {
        return st;
    }
    if (!in->has_num_descriptors) {
        absent = 1;
    } else if (absent) {
        return MIPC_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = mipc_wr_u8(w, &in->num_descriptors)) != MIPC_OK) {
            return st;
        }
    }
    if (!in->has_descriptors) {
        absent = 1;
    } else if (absent) {
        return MIPC_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if (in->num_descriptors > 83) {
            return MIPC_ERR_INVALID;
        }
        for (i = 0; i < (size_t)in->num_descriptors; i++) {
            if ((st = mipc_descriptor_rate_write(w, &in->descriptors[i])) != MIPC_OK) {
                return st;
            }
        }
    }
    return MIPC_OK;
}

mipc_status_t mipc_threedm_imu_message_format_encode(const mipc_threedm_imu_message_format_t *value,
                                                     uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mipc_writer_init(&w, buf, cap);
    st = mipc_threedm_imu_message_format_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mipc_status_t mipc_threedm_imu_message_format_decode(const uint8_t *data, size_t len,
                                                     mipc_threedm_imu_message_format_t *out,
                                                     mipc_decode_error_t *err) {
    mipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_threedm_imu_message_format_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

/* ---- mipc_threedm_imu_message_format_response_t */

static int mipc_threedm_imu_message_format_response_read(mipc_reader_t *r,
                                                         mipc_threedm_imu_message_format_response_t *out) {
    size_t i;
    mipc_rd_push(r, "num_descriptors");
    if (mipc_rd_u8(r, &out->num_descriptors)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "descriptors");
    if (out->num_descriptors > 84) {
        return mipc_rd_count_error(r, (uint64_t)out->num_descriptors, 84);
    }
    for (i = 0; i < (size_t)out->num_descriptors; i++) {
        mipc_rd_index(r, i);
        if (mipc_descriptor_rate_read(r, &out->descriptors[i])) {
            return -1;
        }
    }
    mipc_rd_pop(r);
    return mipc_rd_finish(r);
}

static mipc_status_t
mipc_threedm_imu_message_format_response_write(mipc_writer_t *w,
                                               const mipc_threedm_imu_message_format_response_t *in) {
    mipc_status_t st;
    size_t i;
    if ((st = mipc_wr_u8(w, &in->num_descriptors)) != MIPC_OK) {
        return st;
    }
    if (in->num_descriptors > 84) {
        return MIPC_ERR_INVALID;
    }
    for (i = 0; i < (size_t)in->num_descriptors; i++) {
        if ((st = mipc_descriptor_rate_write(w, &in->descriptors[i])) != MIPC_OK) {
            return st;
        }
    }
    return MIPC_OK;
}

mipc_status_t
mipc_threedm_imu_message_format_response_encode(const mipc_threedm_imu_message_format_response_t *value,
                                                uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mipc_writer_init(&w, buf, cap);
    st = mipc_threedm_imu_message_format_response_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mipc_status_t mipc_threedm_imu_message_format_response_decode(const uint8_t *data, size_t len,
                                                              mipc_threedm_imu_message_format_response_t *out,
                                                              mipc_decode_error_t *err) {
    mipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_threedm_imu_message_format_response_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

/* ---- mipc_threedm_gnss_message_format_t */

static int mipc_threedm_gnss_message_format_read(mipc_reader_t *r, mipc_threedm_gnss_message_format_t *out) {
    size_t i;
    mipc_rd_push(r, "function");
    if (mipc_rd_u8(r, &out->function)) {
        return -1;
    }
    mipc_rd_pop(r);
    if (r->pos < r->len) {
        out->has_num_descriptors = true;
        mipc_rd_push(r, "num_descriptors");
        if (mipc_rd_u8(r, &out->num_descriptors)) {
            return -1;
        }
        mipc_rd_pop(r);
    }
    if (r->pos < r->len) {
        out->has_descriptors = true;
        mipc_rd_push(r, "descriptors");
        if (out->num_descriptors > 83) {
            return mipc_rd_count_error(r, (uint64_t)out->num_descriptors, 83);
        }
        for (i = 0; i < (size_t)out->num_descriptors; i++) {
            mipc_rd_index(r, i);
            if (mipc_descriptor_rate_read(r, &out->descriptors[i])) {
                return -1;
            }
        }
        mipc_rd_pop(r);
    }
    return mipc_rd_finish(r);
}

static mipc_status_t mipc_threedm_gnss_message_format_write(mipc_writer_t *w,
                                                            const mipc_threedm_gnss_message_format_t *in) {
    mipc_status_t st;
    size_t i;
    int absent = 0;
    if ((st = mipc_wr_u8(w, &in->function)) != MIPC_OK) {
        return st;
    }
    if (!in->has_num_descriptors) {
        absent = 1;
    } else if (absent) {
        return MIPC_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = mipc_wr_u8(w, &in->num_descriptors)) != MIPC_OK) {
            return st;
        }
    }
    if (!in->has_descriptors) {
        absent = 1;
    } else if (absent) {
        return MIPC_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if (in->num_descriptors > 83) {
            return MIPC_ERR_INVALID;
        }
        for (i = 0; i < (size_t)in->num_descriptors; i++) {
            if ((st = mipc_descriptor_rate_write(w, &in->descriptors[i])) != MIPC_OK) {
                return st;
            }
        }
    }
    return MIPC_OK;
}

mipc_status_t mipc_threedm_gnss_message_format_encode(const mipc_threedm_gnss_message_format_t *value,
                                                      uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mipc_writer_init(&w, buf, cap);
    st = mipc_threedm_gnss_message_format_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mipc_status_t mipc_threedm_gnss_message_format_decode(const uint8_t *data, size_t len,
                                                      mipc_threedm_gnss_message_format_t *out,
                                                      mipc_decode_error_t *err) {
    mipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_threedm_gnss_message_format_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

/* ---- mipc_threedm_gnss_message_format_response_t */

static int mipc_threedm_gnss_message_format_response_read(mipc_reader_t *r,
                                                          mipc_threedm_gnss_message_format_response_t *out) {
    size_t i;
    mipc_rd_push(r, "num_descriptors");
    if (mipc_rd_u8(r, &out->num_descriptors)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "descriptors");
    if (out->num_descriptors > 84) {
        return mipc_rd_count_error(r, (uint64_t)out->num_descriptors, 84);
    }
    for (i = 0; i < (size_t)out->num_descriptors; i++) {
        mipc_rd_index(r, i);
        if (mipc_descriptor_rate_read(r, &out->descriptors[i])) {
            return -1;
        }
    }
    mipc_rd_pop(r);
    return mipc_rd_finish(r);
}

static mipc_status_t
mipc_threedm_gnss_message_format_response_write(mipc_writer_t *w,
                                                const mipc_threedm_gnss_message_format_response_t *in) {
    mipc_status_t st;
    size_t i;
    if ((st = mipc_wr_u8(w, &in->num_descriptors)) != MIPC_OK) {
        return st;
    }
    if (in->num_descriptors > 84) {
        return MIPC_ERR_INVALID;
    }
    for (i = 0; i < (size_t)in->num_descriptors; i++) {
        if ((st = mipc_descriptor_rate_write(w, &in->descriptors[i])) != MIPC_OK) {
            return st;
        }
    }
    return MIPC_OK;
}

mipc_status_t
mipc_threedm_gnss_message_format_response_encode(const mipc_threedm_gnss_message_format_response_t *value,
                                                 uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mipc_writer_init(&w, buf, cap);
    st = mipc_threedm_gnss_message_format_response_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mipc_status_t
mipc_threedm_gnss_message_format_response_decode(const uint8_t *data, size_t len,
                                                 mipc_threedm_gnss_message_format_response_t *out,
                                                 mipc_decode_error_t *err) {
    mipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_threedm_gnss_message_format_response_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

/* ---- mipc_threedm_filter_message_format_t */

static int mipc_threedm_filter_message_format_read(mipc_reader_t *r,
                                                   mipc_threedm_filter_message_format_t *out) {
    size_t i;
    mipc_rd_push(r, "function");
    if (mipc_rd_u8(r, &out->function)) {
        return -1;
    }
    mipc_rd_pop(r);
    if (r->pos < r->len) {
        out->has_num_descriptors = true;
        mipc_rd_push(r, "num_descriptors");
        if (mipc_rd_u8(r, &out->num_descriptors)) {
            return -1;
        }
        mipc_rd_pop(r);
    }
    if (r->pos < r->len) {
        out->has_descriptors = true;
        mipc_rd_push(r, "descriptors");
        if (out->num_descriptors > 83) {
            return mipc_rd_count_error(r, (uint64_t)out->num_descriptors, 83);
        }
        for (i = 0; i < (size_t)out->num_descriptors; i++) {
            mipc_rd_index(r, i);
            if (mipc_descriptor_rate_read(r, &out->descriptors[i])) {
                return -1;
            }
        }
        mipc_rd_pop(r);
    }
    return mipc_rd_finish(r);
}

static mipc_status_t
mipc_threedm_filter_message_format_write(mipc_writer_t *w, const mipc_threedm_filter_message_format_t *in) {
    mipc_status_t st;
    size_t i;
    int absent = 0;
    if ((st = mipc_wr_u8(w, &in->function)) != MIPC_OK) {
        return st;
    }
    if (!in->has_num_descriptors) {
        absent = 1;
    } else if (absent) {
        return MIPC_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = mipc_wr_u8(w, &in->num_descriptors)) != MIPC_OK) {
            return st;
        }
    }
    if (!in->has_descriptors) {
        absent = 1;
    } else if (absent) {
        return MIPC_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if (in->num_descriptors > 83) {
            return MIPC_ERR_INVALID;
        }
        for (i = 0; i < (size_t)in->num_descriptors; i++) {
            if ((st = mipc_descriptor_rate_write(w, &in->descriptors[i])) != MIPC_OK) {
                return st;
            }
        }
    }
    return MIPC_OK;
}

mipc_status_t mipc_threedm_filter_message_format_encode(const mipc_threedm_filter_message_format_t *value,
                                                        uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mipc_writer_init(&w, buf, cap);
    st = mipc_threedm_filter_message_format_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mipc_status_t mipc_threedm_filter_message_format_decode(const uint8_t *data, size_t len,
                                                        mipc_threedm_filter_message_format_t *out,
                                                        mipc_decode_error_t *err) {
    mipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_threedm_filter_message_format_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

/* ---- mipc_threedm_filter_message_format_response_t */

static int
mipc_threedm_filter_message_format_response_read(mipc_reader_t *r,
                                                 mipc_threedm_filter_message_format_response_t *out) {
    size_t i;
    mipc_rd_push(r, "num_descriptors");
    if (mipc_rd_u8(r, &out->num_descriptors)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "descriptors");
    if (out->num_descriptors > 84) {
        return mipc_rd_count_error(r, (uint64_t)out->num_descriptors, 84);
    }
    for (i = 0; i < (size_t)out->num_descriptors; i++) {
        mipc_rd_index(r, i);
        if (mipc_descriptor_rate_read(r, &out->descriptors[i])) {
            return -1;
        }
    }
    mipc_rd_pop(r);
    return mipc_rd_finish(r);
}

static mipc_status_t
mipc_threedm_filter_message_format_response_write(mipc_writer_t *w,
                                                  const mipc_threedm_filter_message_format_response_t *in) {
    mipc_status_t st;
    size_t i;
    if ((st = mipc_wr_u8(w, &in->num_descriptors)) != MIPC_OK) {
        return st;
    }
    if (in->num_descriptors > 84) {
        return MIPC_ERR_INVALID;
    }
    for (i = 0; i < (size_t)in->num_descriptors; i++) {
        if ((st = mipc_descriptor_rate_write(w, &in->descriptors[i])) != MIPC_OK) {
            return st;
        }
    }
    return MIPC_OK;
}

mipc_status_t
mipc_threedm_filter_message_format_response_encode(const mipc_threedm_filter_message_format_response_t *value,
                                                   uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mipc_writer_init(&w, buf, cap);
    st = mipc_threedm_filter_message_format_response_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mipc_status_t
mipc_threedm_filter_message_format_response_decode(const uint8_t *data, size_t len,
                                                   mipc_threedm_filter_message_format_response_t *out,
                                                   mipc_decode_error_t *err) {
    mipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_threedm_filter_message_format_response_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

/* ---- mipc_threedm_nmea_message_format_t */

static int mipc_threedm_nmea_message_format_read(mipc_reader_t *r, mipc_threedm_nmea_message_format_t *out) {
    size_t i;
    mipc_rd_push(r, "function");
    if (mipc_rd_u8(r, &out->function)) {
        return -1;
    }
    mipc_rd_pop(r);
    if (r->pos < r->len) {
        out->has_count = true;
        mipc_rd_push(r, "count");
        if (mipc_rd_u8(r, &out->count)) {
            return -1;
        }
        mipc_rd_pop(r);
    }
    if (r->pos < r->len) {
        out->has_format_entries = true;
        mipc_rd_push(r, "format_entries");
        if (out->count > 50) {
            return mipc_rd_count_error(r, (uint64_t)out->count, 50);
        }
        for (i = 0; i < (size_t)out->count; i++) {
            mipc_rd_index(r, i);
            if (mipc_nmea_message_read(r, &out->format_entries[i])) {
                return -1;
            }
        }
        mipc_rd_pop(r);
    }
    return mipc_rd_finish(r);
}

static mipc_status_t mipc_threedm_nmea_message_format_write(mipc_writer_t *w,
                                                            const mipc_threedm_nmea_message_format_t *in) {
    mipc_status_t st;
    size_t i;
    int absent = 0;
    if ((st = mipc_wr_u8(w, &in->function)) != MIPC_OK) {
        return st;
    }
    if (!in->has_count) {
        absent = 1;
    } else if (absent) {
        return MIPC_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = mipc_wr_u8(w, &in->count)) != MIPC_OK) {
            return st;
        }
    }
    if (!in->has_format_entries) {
        absent = 1;
    } else if (absent) {
        return MIPC_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if (in->count > 50) {
            return MIPC_ERR_INVALID;
        }
        for (i = 0; i < (size_t)in->count; i++) {
            if ((st = mipc_nmea_message_write(w, &in->format_entries[i])) != MIPC_OK) {
                return st;
            }
        }
    }
    return MIPC_OK;
}

mipc_status_t mipc_threedm_nmea_message_format_encode(const mipc_threedm_nmea_message_format_t *value,
                                                      uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mipc_writer_init(&w, buf, cap);
    st = mipc_threedm_nmea_message_format_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mipc_status_t mipc_threedm_nmea_message_format_decode(const uint8_t *data, size_t len,
                                                      mipc_threedm_nmea_message_format_t *out,
                                                      mipc_decode_error_t *err) {
    mipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_threedm_nmea_message_format_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

/* ---- mipc_threedm_nmea_message_format_response_t */

static int mipc_threedm_nmea_message_format_response_read(mipc_reader_t *r,
                                                          mipc_threedm_nmea_message_format_response_t *out) {
    size_t i;
    mipc_rd_push(r, "count");
    if (mipc_rd_u8(r, &out->count)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "format_entries");
    if (out->count > 50) {
        return mipc_rd_count_error(r, (uint64_t)out->count, 50);
    }
    for (i = 0; i < (size_t)out->count; i++) {
        mipc_rd_index(r, i);
        if (mipc_nmea_message_read(r, &out->format_entries[i])) {
            return -1;
        }
    }
    mipc_rd_pop(r);
    return mipc_rd_finish(r);
}

static mipc_status_t
mipc_threedm_nmea_message_format_response_write(mipc_writer_t *w,
                                                const mipc_threedm_nmea_message_format_response_t *in) {
    mipc_status_t st;
    size_t i;
    if ((st = mipc_wr_u8(w, &in->count)) != MIPC_OK) {
        return st;
    }
    if (in->count > 50) {
        return MIPC_ERR_INVALID;
    }
    for (i = 0; i < (size_t)in->count; i++) {
        if ((st = mipc_nmea_message_write(w, &in->format_entries[i])) != MIPC_OK) {
            return st;
        }
    }
    return MIPC_OK;
}

mipc_status_t
mipc_threedm_nmea_message_format_response_encode(const mipc_threedm_nmea_message_format_response_t *value,
                                                 uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mipc_writer_init(&w, buf, cap);
    st = mipc_threedm_nmea_message_format_response_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mipc_status_t
mipc_threedm_nmea_message_format_response_decode(const uint8_t *data, size_t len,
                                                 mipc_threedm_nmea_message_format_response_t *out,
                                                 mipc_decode_error_t *err) {
    mipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_threedm_nmea_message_format_response_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

/* ---- mipc_threedm_message_format_t */

static int mipc_threedm_message_format_read(mipc_reader_t *r, mipc_threedm_message_format_t *out) {
    size_t i;
    mipc_rd_push(r, "function");
    if (mipc_rd_u8(r, &out->function)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "desc_set");
    if (mipc_rd_u8(r, &out->desc_set)) {
        return -1;
    }
    mipc_rd_pop(r);
    if (r->pos < r->len) {
        out->has_num_descriptors = true;
        mipc_rd_push(r, "num_descriptors");
        if (mipc_rd_u8(r, &out->num_descriptors)) {
            return -1;
        }
        mipc_rd_pop(r);
    }
    if (r->pos < r->len) {
        out->has_descriptors = true;
        mipc_rd_push(r, "descriptors");
        if (out->num_descriptors > 83) {
            return mipc_rd_count_error(r, (uint64_t)out->num_descriptors, 83);
        }
        for (i = 0; i < (size_t)out->num_descriptors; i++) {
            mipc_rd_index(r, i);
            if (mipc_descriptor_rate_read(r, &out->descriptors[i])) {
                return -1;
            }
        }
        mipc_rd_pop(r);
    }
    return mipc_rd_finish(r);
}

static mipc_status_t mipc_threedm_message_format_write(mipc_writer_t *w,
                                                       const mipc_threedm_message_format_t *in) {
    mipc_status_t st;
    size_t i;
    int absent = 0;
    if ((st = mipc_wr_u8(w, &in->function)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u8(w, &in->desc_set)) != MIPC_OK) {
        return st;
    }
    if (!in->has_num_descriptors) {
        absent = 1;
    } else if (absent) {
        return MIPC_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = mipc_wr_u8(w, &in->num_descriptors)) != MIPC_OK) {
            return st;
        }
    }
    if (!in->has_descriptors) {
        absent = 1;
    } else if (absent) {
        return MIPC_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if (in->num_descriptors > 83) {
            return MIPC_ERR_INVALID;
        }
        for (i = 0; i < (size_t)in->num_descriptors; i++) {
            if ((st = mipc_descriptor_rate_write(w, &in->descriptors[i])) != MIPC_OK) {
                return st;
            }
        }
    }
    return MIPC_OK;
}

mipc_status_t mipc_threedm_message_format_encode(const mipc_threedm_message_format_t *value, uint8_t *buf,
                                                 size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mipc_writer_init(&w, buf, cap);
    st = mipc_threedm_message_format_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mipc_status_t mipc_threedm_message_format_decode(const uint8_t *data, size_t len,
                                                 mipc_threedm_message_format_t *out,
                                                 mipc_decode_error_t *err) {
    mipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_threedm_message_format_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

/* ---- mipc_threedm_message_format_response_t */

static int mipc_threedm_message_format_response_read(mipc_reader_t *r,
                                                     mipc_threedm_message_format_response_t *out) {
    size_t i;
    mipc_rd_push(r, "desc_set");
    if (mipc_rd_u8(r, &out->desc_set)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "num_descriptors");
    if (mipc_rd_u8(r, &out->num_descriptors)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "descriptors");
    if (out->num_descriptors > 83) {
        return mipc_rd_count_error(r, (uint64_t)out->num_descriptors, 83);
    }
    for (i = 0; i < (size_t)out->num_descriptors; i++) {
        mipc_rd_index(r, i);
        if (mipc_descriptor_rate_read(r, &out->descriptors[i])) {
            return -1;
        }
    }
    mipc_rd_pop(r);
    return mipc_rd_finish(r);
}

static mipc_status_t
mipc_threedm_message_format_response_write(mipc_writer_t *w,
                                           const mipc_threedm_message_format_response_t *in) {
    mipc_status_t st;
    size_t i;
    if ((st = mipc_wr_u8(w, &in->desc_set)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u8(w, &in->num_descriptors)) != MIPC_OK) {
        return st;
    }
    if (in->num_descriptors > 83) {
        return MIPC_ERR_INVALID;
    }
    for (i = 0; i < (size_t)in->num_descriptors; i++) {
        if ((st = mipc_descriptor_rate_write(w, &in->descriptors[i])) != MIPC_OK) {
            return st;
        }
    }
    return MIPC_OK;
}

mipc_status_t mipc_threedm_message_format_response_encode(const mipc_threedm_message_format_response_t *value,
                                                          uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mipc_writer_init(&w, buf, cap);
    st = mipc_threedm_message_format_response_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mipc_status_t mipc_threedm_message_format_response_decode(const uint8_t *data, size_t len,
                                                          mipc_threedm_message_format_response_t *out,
                                                          mipc_decode_error_t *err) {
    mipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_threedm_message_format_response_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

/* ---- mipc_threedm_factory_streaming_t */

static int mipc_threedm_factory_streaming_read(mipc_reader_t *r, mipc_threedm_factory_streaming_t *out) {
    mipc_rd_push(r, "action");
    if (mipc_rd_u8(r, &out->action)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "reserved");
    if (mipc_rd_u8(r, &out->reserved)) {
        return -1;
    }
    mipc_rd_pop(r);
    return mipc_rd_finish(r);
}

static mipc_status_t mipc_threedm_factory_streaming_write(mipc_writer_t *w,
                                                          const mipc_threedm_factory_streaming_t *in) {
    mipc_status_t st;
    if ((st = mipc_wr_u8(w, &in->action)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u8(w, &in->reserved)) != MIPC_OK) {
        return st;
    }
    return MIPC_OK;
}

mipc_status_t mipc_threedm_factory_streaming_encode(const mipc_threedm_factory_streaming_t *value,
                                                    uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mipc_writer_init(&w, buf, cap);
    st = mipc_threedm_factory_streaming_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 2 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mipc_threedm_factory_streaming_load(const uint8_t *d, mipc_threedm_factory_streaming_t *out) {
    out->action = mipc_ld_u8(d + 0);
    out->reserved = mipc_ld_u8(d + 1);
    return 0;
}

/* The general reader: lengths other than 2, bad bool bytes, error details. */
static MIPC_NOINLINE mipc_status_t mipc_threedm_factory_streaming_decode_read(
    const uint8_t *data, size_t len, mipc_threedm_factory_streaming_t *out, mipc_decode_error_t *err) {
    mipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_threedm_factory_streaming_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t mipc_threedm_factory_streaming_decode(const uint8_t *data, size_t len,
                                                    mipc_threedm_factory_streaming_t *out,
                                                    mipc_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 2 && mipc_threedm_factory_streaming_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_threedm_factory_streaming_decode_read(data, len, out, err);
}

/* ---- mipc_threedm_data_stream_control_gx5_45_t */

static int mipc_threedm_data_stream_control_gx5_45_read(mipc_reader_t *r,
                                                        mipc_threedm_data_stream_control_gx5_45_t *out) {
    mipc_rd_push(r, "function");
    if (mipc_rd_u8(r, &out->function)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "device_selector");
    if (mipc_rd_u8(r, &out->device_selector)) {
        return -1;
    }
    mipc_rd_pop(r);
    if (r->pos < r->len) {
        out->has_enable = true;
        mipc_rd_push(r, "enable");
        if (mipc_rd_u8(r, &out->enable)) {
            return -1;
        }
        mipc_rd_pop(r);
    }
    return mipc_rd_finish(r);
}

static mipc_status_t
mipc_threedm_data_stream_control_gx5_45_write(mipc_writer_t *w,
                                              const mipc_threedm_data_stream_control_gx5_45_t *in) {
    mipc_status_t st;
    int absent = 0;
    if ((st = mipc_wr_u8(w, &in->function)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u8(w, &in->device_selector)) != MIPC_OK) {
        return st;
    }
    if (!in->has_enable) {
        absent = 1;
    } else if (absent) {
        return MIPC_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = mipc_wr_u8(w, &in->enable)) != MIPC_OK) {
            return st;
        }
    }
    return MIPC_OK;
}

mipc_status_t
mipc_threedm_data_stream_control_gx5_45_encode(const mipc_threedm_data_stream_control_gx5_45_t *value,
                                               uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mipc_writer_init(&w, buf, cap);
    st = mipc_threedm_data_stream_control_gx5_45_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mipc_status_t mipc_threedm_data_stream_control_gx5_45_decode(const uint8_t *data, size_t len,
                                                             mipc_threedm_data_stream_control_gx5_45_t *out,
                                                             mipc_decode_error_t *err) {
    mipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_threedm_data_stream_control_gx5_45_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

/* ---- mipc_threedm_data_stream_control_cv7_ins_t */

static int mipc_threedm_data_stream_control_cv7_ins_read(mipc_reader_t *r,
                                                         mipc_threedm_data_stream_control_cv7_ins_t *out) {
    mipc_rd_push(r, "function");
    if (mipc_rd_u8(r, &out->function)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "desc_set");
    if (mipc_rd_u8(r, &out->desc_set)) {
        return -1;
    }
    mipc_rd_pop(r);
    if (r->pos < r->len) {
        out->has_enable = true;
        mipc_rd_push(r, "enable");
        if (mipc_rd_bool(r, &out->enable)) {
            return -1;
        }
        mipc_rd_pop(r);
    }
    return mipc_rd_finish(r);
}

static mipc_status_t
mipc_threedm_data_stream_control_cv7_ins_write(mipc_writer_t *w,
                                               const mipc_threedm_data_stream_control_cv7_ins_t *in) {
    mipc_status_t st;
    int absent = 0;
    if ((st = mipc_wr_u8(w, &in->function)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u8(w, &in->desc_set)) != MIPC_OK) {
        return st;
    }
    if (!in->has_enable) {
        absent = 1;
    } else if (absent) {
        return MIPC_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = mipc_wr_bool(w, &in->enable)) != MIPC_OK) {
            return st;
        }
    }
    return MIPC_OK;
}

mipc_status_t
mipc_threedm_data_stream_control_cv7_ins_encode(const mipc_threedm_data_stream_control_cv7_ins_t *value,
                                                uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mipc_writer_init(&w, buf, cap);
    st = mipc_threedm_data_stream_control_cv7_ins_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mipc_status_t mipc_threedm_data_stream_control_cv7_ins_decode(const uint8_t *data, size_t len,
                                                              mipc_threedm_data_stream_control_cv7_ins_t *out,
                                                              mipc_decode_error_t *err) {
    mipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_threedm_data_stream_control_cv7_ins_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

/* ---- mipc_threedm_data_stream_control_response_gx5_45_t */

static int mipc_threedm_data_stream_control_response_gx5_45_read(
    mipc_reader_t *r, mipc_threedm_data_stream_control_response_gx5_45_t *out) {
    mipc_rd_push(r, "device_selector");
    if (mipc_rd_u8(r, &out->device_selector)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "enabled");
    if (mipc_rd_u8(r, &out->enabled)) {
        return -1;
    }
    mipc_rd_pop(r);
    return mipc_rd_finish(r);
}

static mipc_status_t mipc_threedm_data_stream_control_response_gx5_45_write(
    mipc_writer_t *w, const mipc_threedm_data_stream_control_response_gx5_45_t *in) {
    mipc_status_t st;
    if ((st = mipc_wr_u8(w, &in->device_selector)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u8(w, &in->enabled)) != MIPC_OK) {
        return st;
    }
    return MIPC_OK;
}

mipc_status_t mipc_threedm_data_stream_control_response_gx5_45_encode(
    const mipc_threedm_data_stream_control_response_gx5_45_t *value, uint8_t *buf, size_t cap,
    size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mipc_writer_init(&w, buf, cap);
    st = mipc_threedm_data_stream_control_response_gx5_45_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 2 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mipc_threedm_data_stream_control_response_gx5_45_load(
    const uint8_t *d, mipc_threedm_data_stream_control_response_gx5_45_t *out) {
    out->device_selector = mipc_ld_u8(d + 0);
    out->enabled = mipc_ld_u8(d + 1);
    return 0;
}

/* The general reader: lengths other than 2, bad bool bytes, error details. */
static MIPC_NOINLINE mipc_status_t mipc_threedm_data_stream_control_response_gx5_45_decode_read(
    const uint8_t *data, size_t len, mipc_threedm_data_stream_control_response_gx5_45_t *out,
    mipc_decode_error_t *err) {
    mipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_threedm_data_stream_control_response_gx5_45_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t mipc_threedm_data_stream_control_response_gx5_45_decode(
    const uint8_t *data, size_t len, mipc_threedm_data_stream_control_response_gx5_45_t *out,
    mipc_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 2 && mipc_threedm_data_stream_control_response_gx5_45_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_threedm_data_stream_control_response_gx5_45_decode_read(data, len, out, err);
}

/* ---- mipc_threedm_data_stream_control_response_cv7_ins_t */

static int mipc_threedm_data_stream_control_response_cv7_ins_read(
    mipc_reader_t *r, mipc_threedm_data_stream_control_response_cv7_ins_t *out) {
    mipc_rd_push(r, "desc_set");
    if (mipc_rd_u8(r, &out->desc_set)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "enabled");
    if (mipc_rd_bool(r, &out->enabled)) {
        return -1;
    }
    mipc_rd_pop(r);
    return mipc_rd_finish(r);
}

static mipc_status_t mipc_threedm_data_stream_control_response_cv7_ins_write(
    mipc_writer_t *w, const mipc_threedm_data_stream_control_response_cv7_ins_t *in) {
    mipc_status_t st;
    if ((st = mipc_wr_u8(w, &in->desc_set)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_bool(w, &in->enabled)) != MIPC_OK) {
        return st;
    }
    return MIPC_OK;
}

mipc_status_t mipc_threedm_data_stream_control_response_cv7_ins_encode(
    const mipc_threedm_data_stream_control_response_cv7_ins_t *value, uint8_t *buf, size_t cap,
    size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mipc_writer_init(&w, buf, cap);
    st = mipc_threedm_data_stream_control_response_cv7_ins_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 2 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mipc_threedm_data_stream_control_response_cv7_ins_load(
    const uint8_t *d, mipc_threedm_data_stream_control_response_cv7_ins_t *out) {
    out->desc_set = mipc_ld_u8(d + 0);
    if (d[1] > 1) {
        return -1;
    }
    out->enabled = mipc_ld_bool(d + 1);
    return 0;
}

/* The general reader: lengths other than 2, bad bool bytes, error details. */
static MIPC_NOINLINE mipc_status_t mipc_threedm_data_stream_control_response_cv7_ins_decode_read(
    const uint8_t *data, size_t len, mipc_threedm_data_stream_control_response_cv7_ins_t *out,
    mipc_decode_error_t *err) {
    mipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_threedm_data_stream_control_response_cv7_ins_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t mipc_threedm_data_stream_control_response_cv7_ins_decode(
    const uint8_t *data, size_t len, mipc_threedm_data_stream_control_response_cv7_ins_t *out,
    mipc_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 2 && mipc_threedm_data_stream_control_response_cv7_ins_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_threedm_data_stream_control_response_cv7_ins_decode_read(data, len, out, err);
}

/* ---- mipc_threedm_raw_rtcm_message_t */

static int mipc_threedm_raw_rtcm_message_read(mipc_reader_t *r, mipc_threedm_raw_rtcm_message_t *out) {
    size_t i;
    size_t n;
    mipc_rd_push(r, "data");
    if (mipc_rd_remaining(r, 1, 253, &n)) {
        return -1;
    }
    for (i = 0; i < n; i++) {
        mipc_rd_index(r, i);
        if (mipc_rd_u8(r, &out->data[i])) {
            return -1;
        }
    }
    out->data_count = n;
    mipc_rd_pop(r);
    return mipc_rd_finish(r);
}

static mipc_status_t mipc_threedm_raw_rtcm_message_write(mipc_writer_t *w,
                                                         const mipc_threedm_raw_rtcm_message_t *in) {
    mipc_status_t st;
    size_t i;
    if (in->data_count > 253) {
        return MIPC_ERR_INVALID;
    }
    for (i = 0; i < (size_t)in->data_count; i++) {
        if ((st = mipc_wr_u8(w, &in->data[i])) != MIPC_OK) {
            return st;
        }
    }
    return MIPC_OK;
}

mipc_status_t mipc_threedm_raw_rtcm_message_encode(const mipc_threedm_raw_rtcm_message_t *value, uint8_t *buf,
                                                   size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mipc_writer_init(&w, buf, cap);
    st = mipc_threedm_raw_rtcm_message_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mipc_status_t mipc_threedm_raw_rtcm_message_decode(const uint8_t *data, size_t len,
                                                   mipc_threedm_raw_rtcm_message_t *out,
                                                   mipc_decode_error_t *err) {
    mipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_threedm_raw_rtcm_message_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

/* ---- mipc_threedm_gnss_constellation_settings_t */

static int mipc_threedm_gnss_constellation_settings_read(mipc_reader_t *r,
                                                         mipc_threedm_gnss_constellation_settings_t *out) {
    size_t i;
    mipc_rd_push(r, "function");
    if (mipc_rd_u8(r, &out->function)) {
        return -1;
    }
    mipc_rd_pop(r);
    if (r->pos < r->len) {
        out->has_max_channels = true;
        mipc_rd_push(r, "max_channels");
        if (mipc_rd_u16(r, &out->max_channels)) {
            return -1;
        }
        mipc_rd_pop(r);
    }
    if (r->pos < r->len) {
        out->has_config_count = true;
        mipc_rd_push(r, "config_count");
        if (mipc_rd_u8(r, &out->config_count)) {
            return -1;
        }
        mipc_rd_pop(r);
    }
    if (r->pos < r->len) {
        out->has_settings = true;
        mipc_rd_push(r, "settings");
        if (out->config_count > 41) {
            return mipc_rd_count_error(r, (uint64_t)out->config_count, 41);
        }
        for (i = 0; i < (size_t)out->config_count; i++) {
            mipc_rd_index(r, i);
            if (mipc_constellation_settings_read(r, &out->settings[i])) {
                return -1;
            }
        }
        mipc_rd_pop(r);
    }
    return mipc_rd_finish(r);
}

static mipc_status_t
mipc_threedm_gnss_constellation_settings_write(mipc_writer_t *w,
                                               const mipc_threedm_gnss_constellation_settings_t *in) {
    mipc_status_t st;
    size_t i;
    int absent = 0;
    if ((st = mipc_wr_u8(w, &in->function)) != MIPC_OK) {
        return st;
    }
    if (!in->has_max_channels) {
        absent = 1;
    } else if (absent) {
        return MIPC_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = mipc_wr_u16(w, &in->max_channels)) != MIPC_OK) {
            return st;
        }
    }
    if (!in->has_config_count) {
        absent = 1;
    } else if (absent) {
        return MIPC_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = mipc_wr_u8(w, &in->config_count)) != MIPC_OK) {
            return st;
        }
    }
    if (!in->has_settings) {
        absent = 1;
    } else if (absent) {
        return MIPC_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if (in->config_count > 41) {
            return MIPC_ERR_INVALID;
        }
        for (i = 0; i < (size_t)in->config_count; i++) {
            if ((st = mipc_constellation_settings_write(w, &in->settings[i])) != MIPC_OK) {
                return st;
            }
        }
    }
    return MIPC_OK;
}

mipc_status_t
mipc_threedm_gnss_constellation_settings_encode(const mipc_threedm_gnss_constellation_settings_t *value,
                                                uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mipc_writer_init(&w, buf, cap);
    st = mipc_threedm_gnss_constellation_settings_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mipc_status_t mipc_threedm_gnss_constellation_settings_decode(const uint8_t *data, size_t len,
                                                              mipc_threedm_gnss_constellation_settings_t *out,
                                                              mipc_decode_error_t *err) {
    mipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_threedm_gnss_constellation_settings_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

/* ---- mipc_threedm_gnss_constellation_settings_response_t */

static int mipc_threedm_gnss_constellation_settings_response_read(
    mipc_reader_t *r, mipc_threedm_gnss_constellation_settings_response_t *out) {
    size_t i;
    mipc_rd_push(r, "max_channels_available");
    if (mipc_rd_u16(r, &out->max_channels_available)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "max_channels");
    if (mipc_rd_u16(r, &out->max_channels)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "config_count");
    if (mipc_rd_u8(r, &out->config_count)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "settings");
    if (out->config_count > 41) {
        return mipc_rd_count_error(r, (uint64_t)out->config_count, 41);
    }
    for (i = 0; i < (size_t)out->config_count; i++) {
        mipc_rd_index(r, i);
        if (mipc_constellation_settings_read(r, &out->settings[i])) {
            return -1;
        }
    }
    mipc_rd_pop(r);
    return mipc_rd_finish(r);
}

static mipc_status_t mipc_threedm_gnss_constellation_settings_response_write(
    mipc_writer_t *w, const mipc_threedm_gnss_constellation_settings_response_t *in) {
    mipc_status_t st;
    size_t i;
    if ((st = mipc_wr_u16(w, &in->max_channels_available)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u16(w, &in->max_channels)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u8(w, &in->config_count)) != MIPC_OK) {
        return st;
    }
    if (in->config_count > 41) {
        return MIPC_ERR_INVALID;
    }
    for (i = 0; i < (size_t)in->config_count; i++) {
        if ((st = mipc_constellation_settings_write(w, &in->settings[i])) != MIPC_OK) {
            return st;
        }
    }
    return MIPC_OK;
}

mipc_status_t mipc_threedm_gnss_constellation_settings_response_encode(
    const mipc_threedm_gnss_constellation_settings_response_t *value, uint8_t *buf, size_t cap,
    size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mipc_writer_init(&w, buf, cap);
    st = mipc_threedm_gnss_constellation_settings_response_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mipc_status_t mipc_threedm_gnss_constellation_settings_response_decode(
    const uint8_t *data, size_t len, mipc_threedm_gnss_constellation_settings_response_t *out,
    mipc_decode_error_t *err) {
    mipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_threedm_gnss_constellation_settings_response_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

/* ---- mipc_threedm_gnss_sbas_settings_t */

static int mipc_threedm_gnss_sbas_settings_read(mipc_reader_t *r, mipc_threedm_gnss_sbas_settings_t *out) {
    size_t i;
    mipc_rd_push(r, "function");
    if (mipc_rd_u8(r, &out->function)) {
        return -1;
    }
    mipc_rd_pop(r);
    if (r->pos < r->len) {
        out->has_enable_sbas = true;
        mipc_rd_push(r, "enable_sbas");
        if (mipc_rd_u8(r, &out->enable_sbas)) {
            return -1;
        }
        mipc_rd_pop(r);
    }
    if (r->pos < r->len) {
        out->has_sbas_options = true;
        mipc_rd_push(r, "sbas_options");
        if (mipc_rd_u16(r, &out->sbas_options)) {
            return -1;
        }
        mipc_rd_pop(r);
    }
    if (r->pos < r->len) {
        out->has_num_included_prns = true;
        mipc_rd_push(r, "num_included_prns");
        if (mipc_rd_u8(r, &out->num_included_prns)) {
            return -1;
        }
        mipc_rd_pop(r);
    }
    if (r->pos < r->len) {
        out->has_included_prns = true;
        mipc_rd_push(r, "included_prns");
        if (out->num_included_prns > 124) {
            return mipc_rd_count_error(r, (uint64_t)out->num_included_prns, 124);
        }
        for (i = 0; i < (size_t)out->num_included_prns; i++) {
            mipc_rd_index(r, i);
            if (mipc_rd_u16(r, &out->included_prns[i])) {
                return -1;
            }
        }
        mipc_rd_pop(r);
    }
    return mipc_rd_finish(r);
}

static mipc_status_t mipc_threedm_gnss_sbas_settings_write(mipc_writer_t *w,
                                                           const mipc_threedm_gnss_sbas_settings_t *in) {
    mipc_status_t st;
    size_t i;
    int absent = 0;
    if ((st = mipc_wr_u8(w, &in->function)) != MIPC_OK) {
        return st;
    }
    if (!in->has_enable_sbas) {
        absent = 1;
    } else if (absent) {
        return MIPC_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = mipc_wr_u8(w, &in->enable_sbas)) != MIPC_OK) {
            return st;
        }
    }
    if (!in->has_sbas_options) {
        absent = 1;
    } else if (absent) {
        return MIPC_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = mipc_wr_u16(w, &in->sbas_options)) != MIPC_OK) {
            return st;
        }
    }
    if (!in->has_num_included_prns) {
        absent = 1;
    } else if (absent) {
        return MIPC_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = mipc_wr_u8(w, &in->num_included_prns)) != MIPC_OK) {
            return st;
        }
    }
    if (!in->has_included_prns) {
        absent = 1;
    } else if (absent) {
        return MIPC_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if (in->num_included_prns > 124) {
            return MIPC_ERR_INVALID;
        }
        for (i = 0; i < (size_t)in->num_included_prns; i++) {
            if ((st = mipc_wr_u16(w, &in->included_prns[i])) != MIPC_OK) {
                return st;
            }
        }
    }
    return MIPC_OK;
}

mipc_status_t mipc_threedm_gnss_sbas_settings_encode(const mipc_threedm_gnss_sbas_settings_t *value,
                                                     uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mipc_writer_init(&w, buf, cap);
    st = mipc_threedm_gnss_sbas_settings_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mipc_status_t mipc_threedm_gnss_sbas_settings_decode(const uint8_t *data, size_t len,
                                                     mipc_threedm_gnss_sbas_settings_t *out,
                                                     mipc_decode_error_t *err) {
    mipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_threedm_gnss_sbas_settings_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

/* ---- mipc_threedm_gnss_sbas_settings_response_t */

static int mipc_threedm_gnss_sbas_settings_response_read(mipc_reader_t *r,
                                                         mipc_threedm_gnss_sbas_settings_response_t *out) {
    size_t i;
    mipc_rd_push(r, "enable_sbas");
    if (mipc_rd_u8(r, &out->enable_sbas)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "sbas_options");
    if (mipc_rd_u16(r, &out->sbas_options)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "num_included_prns");
    if (mipc_rd_u8(r, &out->num_included_prns)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "included_prns");
    if (out->num_included_prns > 124) {
        return mipc_rd_count_error(r, (uint64_t)out->num_included_prns, 124);
    }
    for (i = 0; i < (size_t)out->num_included_prns; i++) {
        mipc_rd_index(r, i);
        if (mipc_rd_u16(r, &out->included_prns[i])) {
            return -1;
        }
    }
    mipc_rd_pop(r);
    return mipc_rd_finish(r);
}

static mipc_status_t
mipc_threedm_gnss_sbas_settings_response_write(mipc_writer_t *w,
                                               const mipc_threedm_gnss_sbas_settings_response_t *in) {
    mipc_status_t st;
    size_t i;
    if ((st = mipc_wr_u8(w, &in->enable_sbas)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u16(w, &in->sbas_options)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u8(w, &in->num_included_prns)) != MIPC_OK) {
        return st;
    }
    if (in->num_included_prns > 124) {
        return MIPC_ERR_INVALID;
    }
    for (i = 0; i < (size_t)in->num_included_prns; i++) {
        if ((st = mipc_wr_u16(w, &in->included_prns[i])) != MIPC_OK) {
            return st;
        }
    }
    return MIPC_OK;
}

mipc_status_t
mipc_threedm_gnss_sbas_settings_response_encode(const mipc_threedm_gnss_sbas_settings_response_t *value,
                                                uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mipc_writer_init(&w, buf, cap);
    st = mipc_threedm_gnss_sbas_settings_response_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mipc_status_t mipc_threedm_gnss_sbas_settings_response_decode(const uint8_t *data, size_t len,
                                                              mipc_threedm_gnss_sbas_settings_response_t *out,
                                                              mipc_decode_error_t *err) {
    mipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_threedm_gnss_sbas_settings_response_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

/* ---- mipc_threedm_gnss_assisted_fix_control_t */

static int mipc_threedm_gnss_assisted_fix_control_read(mipc_reader_t *r,
                                                       mipc_threedm_gnss_assisted_fix_control_t *out) {
    mipc_rd_push(r, "function");
    if (mipc_rd_u8(r, &out->function)) {
        return -1;
    }
    mipc_rd_pop(r);
    if (r->pos < r->len) {
        out->has_option = true;
        mipc_rd_push(r, "option");
        if (mipc_rd_u8(r, &out->option)) {
            return -1;
        }
        mipc_rd_pop(r);
    }
    if (r->pos < r->len) {
        out->has_flags = true;
        mipc_rd_push(r, "flags");
        if (mipc_rd_u8(r, &out->flags)) {
            return -1;
        }
        mipc_rd_pop(r);
    }
    return mipc_rd_finish(r);
}

static mipc_status_t
mipc_threedm_gnss_assisted_fix_control_write(mipc_writer_t *w,
                                             const mipc_threedm_gnss_assisted_fix_control_t *in) {
    mipc_status_t st;
    int absent = 0;
    if ((st = mipc_wr_u8(w, &in->function)) != MIPC_OK) {
        return st;
    }
    if (!in->has_option) {
        absent = 1;
    } else if (absent) {
        return MIPC_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = mipc_wr_u8(w, &in->option)) != MIPC_OK) {
            return st;
        }
    }
    if (!in->has_flags) {
        absent = 1;
    } else if (absent) {
        return MIPC_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = mipc_wr_u8(w, &in->flags)) != MIPC_OK) {
            return st;
        }
    }
    return MIPC_OK;
}

mipc_status_t
mipc_threedm_gnss_assisted_fix_control_encode(const mipc_threedm_gnss_assisted_fix_control_t *value,
                                              uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mipc_writer_init(&w, buf, cap);
    st = mipc_threedm_gnss_assisted_fix_control_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mipc_status_t mipc_threedm_gnss_assisted_fix_control_decode(const uint8_t *data, size_t len,
                                                            mipc_threedm_gnss_assisted_fix_control_t *out,
                                                            mipc_decode_error_t *err) {
    mipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_threedm_gnss_assisted_fix_control_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

/* ---- mipc_threedm_gnss_assisted_fix_control_response_t */

static int
mipc_threedm_gnss_assisted_fix_control_response_read(mipc_reader_t *r,
                                                     mipc_threedm_gnss_assisted_fix_control_response_t *out) {
    mipc_rd_push(r, "option");
    if (mipc_rd_u8(r, &out->option)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "flags");
    if (mipc_rd_u8(r, &out->flags)) {
        return -1;
    }
    mipc_rd_pop(r);
    return mipc_rd_finish(r);
}

static mipc_status_t mipc_threedm_gnss_assisted_fix_control_response_write(
    mipc_writer_t *w, const mipc_threedm_gnss_assisted_fix_control_response_t *in) {
    mipc_status_t st;
    if ((st = mipc_wr_u8(w, &in->option)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u8(w, &in->flags)) != MIPC_OK) {
        return st;
    }
    return MIPC_OK;
}

mipc_status_t mipc_threedm_gnss_assisted_fix_control_response_encode(
    const mipc_threedm_gnss_assisted_fix_control_response_t *value, uint8_t *buf, size_t cap,
    size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mipc_writer_init(&w, buf, cap);
    st = mipc_threedm_gnss_assisted_fix_control_response_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 2 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int
mipc_threedm_gnss_assisted_fix_control_response_load(const uint8_t *d,
                                                     mipc_threedm_gnss_assisted_fix_control_response_t *out) {
    out->option = mipc_ld_u8(d + 0);
    out->flags = mipc_ld_u8(d + 1);
    return 0;
}

/* The general reader: lengths other than 2, bad bool bytes, error details. */
static MIPC_NOINLINE mipc_status_t mipc_threedm_gnss_assisted_fix_control_response_decode_read(
    const uint8_t *data, size_t len, mipc_threedm_gnss_assisted_fix_control_response_t *out,
    mipc_decode_error_t *err) {
    mipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_threedm_gnss_assisted_fix_control_response_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t
mipc_threedm_gnss_assisted_fix_control_response_decode(const uint8_t *data, size_t len,
                                                       mipc_threedm_gnss_assisted_fix_control_response_t *out,
                                                       mipc_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 2 && mipc_threedm_gnss_assisted_fix_control_response_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_threedm_gnss_assisted_fix_control_response_decode_read(data, len, out, err);
}

/* ---- mipc_threedm_gnss_assist_time_update_t */

static int mipc_threedm_gnss_assist_time_update_read(mipc_reader_t *r,
                                                     mipc_threedm_gnss_assist_time_update_t *out) {
    mipc_rd_push(r, "function");
    if (mipc_rd_u8(r, &out->function)) {
        return -1;
    }
    mipc_rd_pop(r);
    if (r->pos < r->len) {
        out->has_tow = true;
        mipc_rd_push(r, "tow");
        if (mipc_rd_f64(r, &out->tow)) {
            return -1;
        }
        mipc_rd_pop(r);
    }
    if (r->pos < r->len) {
        out->has_week_number = true;
        mipc_rd_push(r, "week_number");
        if (mipc_rd_u16(r, &out->week_number)) {
            return -1;
        }
        mipc_rd_pop(r);
    }
    if (r->pos < r->len) {
        out->has_accuracy = true;
        mipc_rd_push(r, "accuracy");
        if (mipc_rd_f32(r, &out->accuracy)) {
            return -1;
        }
        mipc_rd_pop(r);
    }
    return mipc_rd_finish(r);
}

static mipc_status_t
mipc_threedm_gnss_assist_time_update_write(mipc_writer_t *w,
                                           const mipc_threedm_gnss_assist_time_update_t *in) {
    mipc_status_t st;
    int absent = 0;
    if ((st = mipc_wr_u8(w, &in->function)) != MIPC_OK) {
        return st;
    }
    if (!in->has_tow) {
        absent = 1;
    } else if (absent) {
        return MIPC_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = mipc_wr_f64(w, &in->tow)) != MIPC_OK) {
            return st;
        }
    }
    if (!in->has_week_number) {
        absent = 1;
    } else if (absent) {
        return MIPC_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = mipc_wr_u16(w, &in->week_number)) != MIPC_OK) {
            return st;
        }
    }
    if (!in->has_accuracy) {
        absent = 1;
    } else if (absent) {
        return MIPC_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = mipc_wr_f32(w, &in->accuracy)) != MIPC_OK) {
            return st;
        }
    }
    return MIPC_OK;
}

mipc_status_t mipc_threedm_gnss_assist_time_update_encode(const mipc_threedm_gnss_assist_time_update_t *value,
                                                          uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mipc_writer_init(&w, buf, cap);
    st = mipc_threedm_gnss_assist_time_update_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mipc_status_t mipc_threedm_gnss_assist_time_update_decode(const uint8_t *data, size_t len,
                                                          mipc_threedm_gnss_assist_time_update_t *out,
                                                          mipc_decode_error_t *err) {
    mipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_threedm_gnss_assist_time_update_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

/* ---- mipc_threedm_gnss_assist_time_update_response_t */

static int
mipc_threedm_gnss_assist_time_update_response_read(mipc_reader_t *r,
                                                   mipc_threedm_gnss_assist_time_update_response_t *out) {
    mipc_rd_push(r, "tow");
    if (mipc_rd_f64(r, &out->tow)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "week_number");
    if (mipc_rd_u16(r, &out->week_number)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "accuracy");
    if (mipc_rd_f32(r, &out->accuracy)) {
        return -1;
    }
    mipc_rd_pop(r);
    return mipc_rd_finish(r);
}

static mipc_status_t mipc_threedm_gnss_assist_time_update_response_write(
    mipc_writer_t *w, const mipc_threedm_gnss_assist_time_update_response_t *in) {
    mipc_status_t st;
    if ((st = mipc_wr_f64(w, &in->tow)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u16(w, &in->week_number)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_f32(w, &in->accuracy)) != MIPC_OK) {
        return st;
    }
    return MIPC_OK;
}

mipc_status_t mipc_threedm_gnss_assist_time_update_response_encode(
    const mipc_threedm_gnss_assist_time_update_response_t *value, uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mipc_writer_init(&w, buf, cap);
    st = mipc_threedm_gnss_assist_time_update_response_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 14 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int
mipc_threedm_gnss_assist_time_update_response_load(const uint8_t *d,
                                                   mipc_threedm_gnss_assist_time_update_response_t *out) {
    out->tow = mipc_ld_f64(d + 0);
    out->week_number = mipc_ld_u16(d + 8);
    out->accuracy = mipc_ld_f32(d + 10);
    return 0;
}

/* The general reader: lengths other than 14, bad bool bytes, error details. */
static MIPC_NOINLINE mipc_status_t mipc_threedm_gnss_assist_time_update_response_decode_read(
    const uint8_t *data, size_t len, mipc_threedm_gnss_assist_time_update_response_t *out,
    mipc_decode_error_t *err) {
    mipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_threedm_gnss_assist_time_update_response_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t
mipc_threedm_gnss_assist_time_update_response_decode(const uint8_t *data, size_t len,
                                                     mipc_threedm_gnss_assist_time_update_response_t *out,
                                                     mipc_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 14 && mipc_threedm_gnss_assist_time_update_response_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_threedm_gnss_assist_time_update_response_decode_read(data, len, out, err);
}

/* ---- mipc_threedm_pps_source_t */

static int mipc_threedm_pps_source_read(mipc_reader_t *r, mipc_threedm_pps_source_t *out) {
    mipc_rd_push(r, "function");
    if (mipc_rd_u8(r, &out->function)) {
        return -1;
    }
    mipc_rd_pop(r);
    if (r->pos < r->len) {
        out->has_source = true;
        mipc_rd_push(r, "source");
        if (mipc_rd_u8(r, &out->source)) {
            return -1;
        }
        mipc_rd_pop(r);
    }
    return mipc_rd_finish(r);
}

static mipc_status_t mipc_threedm_pps_source_write(mipc_writer_t *w, const mipc_threedm_pps_source_t *in) {
    mipc_status_t st;
    int absent = 0;
    if ((st = mipc_wr_u8(w, &in->function)) != MIPC_OK) {
        return st;
    }
    if (!in->has_source) {
        absent = 1;
    } else if (absent) {
        return MIPC_ERR_INVALID; /* an optional parameter after an absent one */
    } else {
        if ((st = mipc_wr_u8(w, &in->source)) != MIPC_OK) {
            return st;
        }
    }
    return MIPC_OK;
}

mipc_status_t mipc_threedm_pps_source_encode(const mipc_threedm_pps_source_t *value, uint8_t *buf, size_t cap,
                                             size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mipc_writer_init(&w, buf, cap);
    st = mipc_threedm_pps_source_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mipc_status_t mipc_threedm_pps_source_decode(const uint8_t *data, size_t len, mipc_threedm_pps_source_t *out,
                                             mipc_decode_error_t *err) {
    mipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_threedm_pps_source_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

/* ---- mipc_threedm_pps_source_response_t */

static int mipc_threedm_pps_source_response_read(mipc_reader_t *r, mipc_threedm_pps_source_response_t *out) {
    mipc_rd_push(r, "source");
    if (mipc_rd_u8(r, &out->source)) {
        return -1;
    }
    mipc_rd_pop(r);
    return mipc_rd_finish(r);
}

static mipc_status_t mipc_threedm_pps_source_response_write(mipc_writer_t *w,
                                                            const mipc_threedm_pps_source_response_t *in) {
    mipc_status_t st;
    if ((st = mipc_wr_u8(w, &in->source)) != MIPC_OK) {
        return st;
    }
    return MIPC_OK;
}

mipc_status_t mipc_threedm_pps_source_response_encode(const mipc_threedm_pps_source_response_t *value,
                                                      uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mipc_writer_init(&w, buf, cap);
    st = mipc_threedm_pps_source_response_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 1 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mipc_threedm_pps_source_response_load(const uint8_t *d, mipc_threedm_pps_source_response_t *out) {
    out->source = mipc_ld_u8(d + 0);
    return 0;
}

/* The general reader: lengths other than 1, bad bool bytes, error details. */
static MIPC_NOINLINE mipc_status_t mipc_threedm_pps_source_response_decode_read(
    const uint8_t *data, size_t len, mipc_threedm_pps_source_response_t *out, mipc_decode_error_t *err) {
    mipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_threedm_pps_source_response_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t mipc_threedm_pps_source_response_decode(const uint8_t *data, size_t len,
                                                      mipc_threedm_pps_source_response_t *out,
                                                      mipc_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 1 && mipc_threedm_pps_source_response_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_threedm_pps_source_response_decode_read(data, len, out, err);
}

/* ---- mipc_threedm_get_supported_events_t */

static int mipc_threedm_get_supported_events_read(mipc_reader_t *r,
                                                  mipc_threedm_get_supported_events_t *out) {
    mipc_rd_push(r, "query");
    if (mipc_rd_u8(r, &out->query)) {
        return -1;
    }
    mipc_rd_pop(r);
    return mipc_rd_finish(r);
}

static mipc_status_t mipc_threedm_get_supported_events_write(mipc_writer_t *w,
                                                             const mipc_threedm_get_supported_events_t *in) {
    mipc_status_t st;
    if ((st = mipc_wr_u8(w, &in->query)) != MIPC_OK) {
        return st;
    }
    return MIPC_OK;
}

mipc_status_t mipc_threedm_get_supported_events_encode(const mipc_threedm_get_supported_events_t *value,
                                                       uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mipc_writer_init(&w, buf, cap);
    st = mipc_threedm_get_supported_events_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 1 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mipc_threedm_get_supported_events_load(const uint8_t *d,
                                                  mipc_threedm_get_supported_events_t *out) {
    out->query = mipc_ld_u8(d + 0);
    return 0;
}

/* The general reader: lengths other than 1, bad bool bytes, error details. */
static MIPC_NOINLINE mipc_status_t mipc_threedm_get_supported_events_decode_read(
    const uint8_t *data, size_t len, mipc_threedm_get_supported_events_t *out, mipc_decode_error_t *err) {
    mipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_threedm_get_supported_events_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t mipc_threedm_get_supported_events_decode(const uint8_t *data, size_t len,
                                                       mipc_threedm_get_supported_events_t *out,
                                                       mipc_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 1 && mipc_threedm_get_supported_events_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_threedm_get_supported_events_decode_read(data, len, out, err);
}

/* ---- mipc_threedm_supported_events_t */

static int mipc_threedm_supported_events_read(mipc_reader_t *r, mipc_threedm_supported_events_t *out) {
    mipc_rd_push(r, "query");
    if (mipc_rd_u8(r, &out->query)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "info");
    if (mipc_supported_events_info_read(r, out->query, &out->info)) {
        return -1;
    }
    mipc_rd_pop(r);
    return mipc_rd_finish(r);
}

static mipc_status_t mipc_threedm_supported_events_write(mipc_writer_t *w,
                                                         const mipc_threedm_supported_events_t *in) {
    mipc_status_t st;
    if ((st = mipc_wr_u8(w, &in->query)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_supported_events_info_write(w, in->query, &in->info)) != MIPC_OK) {
        return st;
    }
    return MIPC_OK;
}

mipc_status_t mipc_threedm_supported_events_encode(const mipc_threedm_supported_events_t *value, uint8_t *buf,
                                                   size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mipc_writer_init(&w, buf, cap);
    st = mipc_threedm_supported_events_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mipc_status_t mipc_threedm_supported_events_decode(const uint8_t *data, size_t len,
                                                   mipc_threedm_supported_events_t *out,
                                                   mipc_decode_error_t *err) {
    mipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_threedm_supported_events_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

/* ---- mipc_threedm_device_status_t */

static int mipc_threedm_device_status_read(mipc_reader_t *r, mipc_threedm_device_status_t *out) {
    mipc_rd_push(r, "model_number");
    if (mipc_rd_u16(r, &out->model_number)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "status_selector");
    if (mipc_rd_u8(r, &out->status_selector)) {
        return -1;
    }
    mipc_rd_pop(r);
    return mipc_rd_finish(r);
}

static mipc_status_t mipc_threedm_device_status_write(mipc_writer_t *w,
                                                      const mipc_threedm_device_status_t *in) {
    mipc_status_t st;
    if ((st = mipc_wr_u16(w, &in->model_number)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u8(w, &in->status_selector)) != MIPC_OK) {
        return st;
    }
    return MIPC_OK;
}

mipc_status_t mipc_threedm_device_status_encode(const mipc_threedm_device_status_t *value, uint8_t *buf,
                                                size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mipc_writer_init(&w, buf, cap);
    st = mipc_threedm_device_status_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

/* The layout is 3 bytes of plain values: straight loads. -1 sends a bad bool
 * byte to the reader path, which reports it. */
static int mipc_threedm_device_status_load(const uint8_t *d, mipc_threedm_device_status_t *out) {
    out->model_number = mipc_ld_u16(d + 0);
    out->status_selector = mipc_ld_u8(d + 2);
    return 0;
}

/* The general reader: lengths other than 3, bad bool bytes, error details. */
static MIPC_NOINLINE mipc_status_t mipc_threedm_device_status_decode_read(const uint8_t *data, size_t len,
                                                                          mipc_threedm_device_status_t *out,
                                                                          mipc_decode_error_t *err) {
    mipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_threedm_device_status_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}

mipc_status_t mipc_threedm_device_status_decode(const uint8_t *data, size_t len,
                                                mipc_threedm_device_status_t *out, mipc_decode_error_t *err) {
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (len == 3 && mipc_threedm_device_status_load(data, out) == 0) {
        return MIPC_OK;
    }
    return mipc_threedm_device_status_decode_read(data, len, out, err);
}

/* ---- mipc_threedm_device_status_response_t */

static int mipc_threedm_device_status_response_read(mipc_reader_t *r,
                                                    mipc_threedm_device_status_response_t *out) {
    mipc_rd_push(r, "model_number");
    if (mipc_rd_u16(r, &out->model_number)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "status_selector");
    if (mipc_rd_u8(r, &out->status_selector)) {
        return -1;
    }
    mipc_rd_pop(r);
    mipc_rd_push(r, "status");
    if (mipc_gx5_device_status_read(r, out->status_selector, &out->status)) {
        return -1;
    }
    mipc_rd_pop(r);
    return mipc_rd_finish(r);
}

static mipc_status_t
mipc_threedm_device_status_response_write(mipc_writer_t *w, const mipc_threedm_device_status_response_t *in) {
    mipc_status_t st;
    if ((st = mipc_wr_u16(w, &in->model_number)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_wr_u8(w, &in->status_selector)) != MIPC_OK) {
        return st;
    }
    if ((st = mipc_gx5_device_status_write(w, in->status_selector, &in->status)) != MIPC_OK) {
        return st;
    }
    return MIPC_OK;
}

mipc_status_t mipc_threedm_device_status_response_encode(const mipc_threedm_device_status_response_t *value,
                                                         uint8_t *buf, size_t cap, size_t *len_out) {
    mipc_writer_t w;
    mipc_status_t st;
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    mipc_writer_init(&w, buf, cap);
    st = mipc_threedm_device_status_response_write(&w, value);
    if (st == MIPC_OK && len_out) {
        *len_out = w.len;
    }
    return st;
}

mipc_status_t mipc_threedm_device_status_response_decode(const uint8_t *data, size_t len,
                                                         mipc_threedm_device_status_response_t *out,
                                                         mipc_decode_error_t *err) {
    mipc_reader_t r;
    assert(data != NULL || len == 0);
    assert(out != NULL);
    mipc_reader_init(&r, data, len, err);
    memset(out, 0, sizeof *out);
    return mipc_threedm_device_status_response_read(&r, out) ? MIPC_ERR_DECODE : MIPC_OK;
}
