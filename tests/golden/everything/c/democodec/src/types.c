/* Read/write functions of the named structs and unions. Generated: do not edit. */
#include "types_internal.h"

#include <string.h>

/* ---- GpioParams */

int democ_gpio_params_read(democ_reader_t *r, democ_gpio_params_t *out) {
    democ_rd_push(r, "pin");
    if (democ_rd_u8(r, &out->pin)) {
        return -1;
    }
    democ_rd_pop(r);
    democ_rd_push(r, "polarity");
    if (democ_rd_bool(r, &out->polarity)) {
        return -1;
    }
    democ_rd_pop(r);
    return 0;
}

democ_status_t democ_gpio_params_write(democ_writer_t *w, const democ_gpio_params_t *in) {
    democ_status_t st;
    if ((st = democ_wr_u8(w, &in->pin)) != DEMOC_OK) {
        return st;
    }
    if ((st = democ_wr_bool(w, &in->polarity)) != DEMOC_OK) {
        return st;
    }
    return DEMOC_OK;
}

/* ---- ThresholdParams */

int democ_threshold_params_read(democ_reader_t *r, democ_threshold_params_t *out) {
    size_t i;
    democ_rd_push(r, "low");
    if (democ_rd_f64(r, &out->low)) {
        return -1;
    }
    democ_rd_pop(r);
    democ_rd_push(r, "high");
    if (democ_rd_f64(r, &out->high)) {
        return -1;
    }
    democ_rd_pop(r);
    democ_rd_push(r, "axes");
    for (i = 0; i < 3; i++) {
        democ_rd_index(r, i);
        if (democ_rd_f32(r, &out->axes[i])) {
            return -1;
        }
    }
    democ_rd_pop(r);
    return 0;
}

democ_status_t democ_threshold_params_write(democ_writer_t *w, const democ_threshold_params_t *in) {
    democ_status_t st;
    size_t i;
    if ((st = democ_wr_f64(w, &in->low)) != DEMOC_OK) {
        return st;
    }
    if ((st = democ_wr_f64(w, &in->high)) != DEMOC_OK) {
        return st;
    }
    for (i = 0; i < 3; i++) {
        if ((st = democ_wr_f32(w, &in->axes[i])) != DEMOC_OK) {
            return st;
        }
    }
    return DEMOC_OK;
}

/* ---- TriggerParams (selected by democ_mode_t) */

int democ_trigger_params_read(democ_reader_t *r, democ_mode_t selector, democ_trigger_params_t *out) {
    switch (selector) {
    case DEMOC_MODE_NONE:
        return 0;
    case DEMOC_MODE_GPIO:
        return democ_gpio_params_read(r, &out->gpio);
    case DEMOC_MODE_THRESHOLD:
        return democ_threshold_params_read(r, &out->threshold);
    default:
        return democ_rd_selector_error_u(r, (uint64_t)selector);
    }
}

democ_status_t democ_trigger_params_write(democ_writer_t *w, democ_mode_t selector,
                                          const democ_trigger_params_t *in) {
    switch (selector) {
    case DEMOC_MODE_NONE:
        return DEMOC_OK;
    case DEMOC_MODE_GPIO:
        return democ_gpio_params_write(w, &in->gpio);
    case DEMOC_MODE_THRESHOLD:
        return democ_threshold_params_write(w, &in->threshold);
    default:
        (void)w;
        (void)in;
        return DEMOC_ERR_INVALID;
    }
}
