/* Read/write/JSON functions of the named structs and unions. Generated: do not edit. */
#include "types_internal.h"

#include <string.h>

/* ---- GpioParams */

int demo_gpio_params_read(demo_reader_t *r, demo_gpio_params_t *out) {
    demo_rd_push(r, "pin");
    if (demo_rd_u8(r, &out->pin)) {
        return -1;
    }
    demo_rd_pop(r);
    demo_rd_push(r, "polarity");
    if (demo_rd_bool(r, &out->polarity)) {
        return -1;
    }
    demo_rd_pop(r);
    return 0;
}

demo_status_t demo_gpio_params_write(demo_writer_t *w, const demo_gpio_params_t *in) {
    demo_status_t st;
    if ((st = demo_wr_u8(w, &in->pin)) != DEMO_OK) {
        return st;
    }
    if ((st = demo_wr_bool(w, &in->polarity)) != DEMO_OK) {
        return st;
    }
    return DEMO_OK;
}

void demo_gpio_params_to_json(demo_jw_t *w, const demo_gpio_params_t *in) {
    int first = 1;
    demo_jw_raw(w, "{", 1);
    demo_jw_key(w, &first, "pin");
    demo_jw_u8(w, &in->pin);
    demo_jw_key(w, &first, "polarity");
    demo_jw_bool(w, &in->polarity);
    demo_jw_raw(w, "}", 1);
}

int demo_gpio_params_from_json(demo_jr_t *jr, size_t pos, demo_gpio_params_t *out) {
    static const char *const keys[] = {"pin", "polarity"};
    size_t vp = 0;
    int found;
    if (demo_jr_object(jr, pos, keys, 2)) {
        return -1;
    }
    found = demo_jr_get(jr, pos, "pin", &vp);
    if (found != 1) {
        return demo_jr_fail(jr, "missing parameter \"pin\"");
    }
    {
        demo_jr_push(jr, "pin");
        if (demo_jr_u8(jr, vp, &out->pin)) {
            return -1;
        }
        demo_jr_pop(jr);
    }
    found = demo_jr_get(jr, pos, "polarity", &vp);
    if (found != 1) {
        return demo_jr_fail(jr, "missing parameter \"polarity\"");
    }
    {
        demo_jr_push(jr, "polarity");
        if (demo_jr_bool(jr, vp, &out->polarity)) {
            return -1;
        }
        demo_jr_pop(jr);
    }
    return 0;
}

/* ---- ThresholdParams */

int demo_threshold_params_read(demo_reader_t *r, demo_threshold_params_t *out) {
    size_t i;
    demo_rd_push(r, "low");
    if (demo_rd_f64(r, &out->low)) {
        return -1;
    }
    demo_rd_pop(r);
    demo_rd_push(r, "high");
    if (demo_rd_f64(r, &out->high)) {
        return -1;
    }
    demo_rd_pop(r);
    demo_rd_push(r, "axes");
    for (i = 0; i < 3; i++) {
        demo_rd_index(r, i);
        if (demo_rd_f32(r, &out->axes[i])) {
            return -1;
        }
    }
    demo_rd_pop(r);
    return 0;
}

demo_status_t demo_threshold_params_write(demo_writer_t *w, const demo_threshold_params_t *in) {
    demo_status_t st;
    size_t i;
    if ((st = demo_wr_f64(w, &in->low)) != DEMO_OK) {
        return st;
    }
    if ((st = demo_wr_f64(w, &in->high)) != DEMO_OK) {
        return st;
    }
    for (i = 0; i < 3; i++) {
        if ((st = demo_wr_f32(w, &in->axes[i])) != DEMO_OK) {
            return st;
        }
    }
    return DEMO_OK;
}

void demo_threshold_params_to_json(demo_jw_t *w, const demo_threshold_params_t *in) {
    int first = 1;
    size_t i;
    demo_jw_raw(w, "{", 1);
    demo_jw_key(w, &first, "low");
    demo_jw_f64(w, &in->low);
    demo_jw_key(w, &first, "high");
    demo_jw_f64(w, &in->high);
    demo_jw_key(w, &first, "axes");
    demo_jw_raw(w, "[", 1);
    for (i = 0; i < 3; i++) {
        demo_jw_sep(w, i);
        demo_jw_f32(w, &in->axes[i]);
    }
    demo_jw_raw(w, "]", 1);
    demo_jw_raw(w, "}", 1);
}

int demo_threshold_params_from_json(demo_jr_t *jr, size_t pos, demo_threshold_params_t *out) {
    static const char *const keys[] = {"low", "high", "axes"};
    size_t vp = 0;
    int found;
    size_t i;
    size_t it = 0;
    size_t ep = 0;
    if (demo_jr_object(jr, pos, keys, 3)) {
        return -1;
    }
    found = demo_jr_get(jr, pos, "low", &vp);
    if (found != 1) {
        return demo_jr_fail(jr, "missing parameter \"low\"");
    }
    {
        demo_jr_push(jr, "low");
        if (demo_jr_f64(jr, vp, &out->low)) {
            return -1;
        }
        demo_jr_pop(jr);
    }
    found = demo_jr_get(jr, pos, "high", &vp);
    if (found != 1) {
        return demo_jr_fail(jr, "missing parameter \"high\"");
    }
    {
        demo_jr_push(jr, "high");
        if (demo_jr_f64(jr, vp, &out->high)) {
            return -1;
        }
        demo_jr_pop(jr);
    }
    found = demo_jr_get(jr, pos, "axes", &vp);
    if (found != 1) {
        return demo_jr_fail(jr, "missing parameter \"axes\"");
    }
    {
        demo_jr_push(jr, "axes");
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
            if (i >= 3) {
                return demo_jr_fail(jr, "more than 3 elements");
            }
            demo_jr_index(jr, i);
            if (demo_jr_f32(jr, ep, &out->axes[i])) {
                return -1;
            }
        }
        demo_jr_index(jr, SIZE_MAX);
        if (i != 3) {
            return demo_jr_fail(jr, "expected 3 elements, got %zu", i);
        }
        demo_jr_pop(jr);
    }
    return 0;
}

/* ---- TriggerParams (selected by demo_mode_t) */

int demo_trigger_params_read(demo_reader_t *r, demo_mode_t selector, demo_trigger_params_t *out) {
    switch (selector) {
    case DEMO_MODE_NONE:
        return 0;
    case DEMO_MODE_GPIO:
        return demo_gpio_params_read(r, &out->gpio);
    case DEMO_MODE_THRESHOLD:
        return demo_threshold_params_read(r, &out->threshold);
    default:
        return demo_rd_selector_error_u(r, (uint64_t)selector);
    }
}

demo_status_t demo_trigger_params_write(demo_writer_t *w, demo_mode_t selector,
                                        const demo_trigger_params_t *in) {
    switch (selector) {
    case DEMO_MODE_NONE:
        return DEMO_OK;
    case DEMO_MODE_GPIO:
        return demo_gpio_params_write(w, &in->gpio);
    case DEMO_MODE_THRESHOLD:
        return demo_threshold_params_write(w, &in->threshold);
    default:
        (void)w;
        (void)in;
        return DEMO_ERR_INVALID;
    }
}

void demo_trigger_params_to_json(demo_jw_t *w, demo_mode_t selector, const demo_trigger_params_t *in) {
    switch (selector) {
    case DEMO_MODE_GPIO:
        demo_gpio_params_to_json(w, &in->gpio);
        return;
    case DEMO_MODE_THRESHOLD:
        demo_threshold_params_to_json(w, &in->threshold);
        return;
    default:
        (void)in;
        demo_jw_lit(w, "null");
        return;
    }
}

int demo_trigger_params_from_json(demo_jr_t *jr, size_t pos, demo_mode_t selector,
                                  demo_trigger_params_t *out) {
    switch (selector) {
    case DEMO_MODE_NONE:
        return demo_jr_null(jr, pos);
    case DEMO_MODE_GPIO:
        return demo_gpio_params_from_json(jr, pos, &out->gpio);
    case DEMO_MODE_THRESHOLD:
        return demo_threshold_params_from_json(jr, pos, &out->threshold);
    default:
        (void)pos;
        (void)out;
        return demo_jr_fail(jr, "no member for selector value %llu", (unsigned long long)selector);
    }
}
