/* Canonical JSON of the named structs and unions (the democodec_json library). Generated: do not edit. */
#include "types_internal.h"

#include <string.h>

/* ---- GpioParams */

void democ_gpio_params_to_json(democ_jw_t *w, const democ_gpio_params_t *in) {
    int first = 1;
    democ_jw_raw(w, "{", 1);
    democ_jw_key(w, &first, "pin");
    democ_jw_u8(w, &in->pin);
    democ_jw_key(w, &first, "polarity");
    democ_jw_bool(w, &in->polarity);
    democ_jw_raw(w, "}", 1);
}

int democ_gpio_params_from_json(democ_jr_t *jr, size_t pos, democ_gpio_params_t *out) {
    static const char *const keys[] = {"pin", "polarity"};
    size_t vp = 0;
    int found;
    if (democ_jr_object(jr, pos, keys, 2)) {
        return -1;
    }
    found = democ_jr_get(jr, pos, "pin", &vp);
    if (found != 1) {
        return democ_jr_fail(jr, "missing parameter \"pin\"");
    }
    {
        democ_jr_push(jr, "pin");
        if (democ_jr_u8(jr, vp, &out->pin)) {
            return -1;
        }
        democ_jr_pop(jr);
    }
    found = democ_jr_get(jr, pos, "polarity", &vp);
    if (found != 1) {
        return democ_jr_fail(jr, "missing parameter \"polarity\"");
    }
    {
        democ_jr_push(jr, "polarity");
        if (democ_jr_bool(jr, vp, &out->polarity)) {
            return -1;
        }
        democ_jr_pop(jr);
    }
    return 0;
}

/* ---- ThresholdParams */

void democ_threshold_params_to_json(democ_jw_t *w, const democ_threshold_params_t *in) {
    int first = 1;
    size_t i;
    democ_jw_raw(w, "{", 1);
    democ_jw_key(w, &first, "low");
    democ_jw_f64(w, &in->low);
    democ_jw_key(w, &first, "high");
    democ_jw_f64(w, &in->high);
    democ_jw_key(w, &first, "axes");
    democ_jw_raw(w, "[", 1);
    for (i = 0; i < 3; i++) {
        democ_jw_sep(w, i);
        democ_jw_f32(w, &in->axes[i]);
    }
    democ_jw_raw(w, "]", 1);
    democ_jw_raw(w, "}", 1);
}

int democ_threshold_params_from_json(democ_jr_t *jr, size_t pos, democ_threshold_params_t *out) {
    static const char *const keys[] = {"low", "high", "axes"};
    size_t vp = 0;
    int found;
    size_t i;
    size_t it = 0;
    size_t ep = 0;
    if (democ_jr_object(jr, pos, keys, 3)) {
        return -1;
    }
    found = democ_jr_get(jr, pos, "low", &vp);
    if (found != 1) {
        return democ_jr_fail(jr, "missing parameter \"low\"");
    }
    {
        democ_jr_push(jr, "low");
        if (democ_jr_f64(jr, vp, &out->low)) {
            return -1;
        }
        democ_jr_pop(jr);
    }
    found = democ_jr_get(jr, pos, "high", &vp);
    if (found != 1) {
        return democ_jr_fail(jr, "missing parameter \"high\"");
    }
    {
        democ_jr_push(jr, "high");
        if (democ_jr_f64(jr, vp, &out->high)) {
            return -1;
        }
        democ_jr_pop(jr);
    }
    found = democ_jr_get(jr, pos, "axes", &vp);
    if (found != 1) {
        return democ_jr_fail(jr, "missing parameter \"axes\"");
    }
    {
        democ_jr_push(jr, "axes");
        if (democ_jr_array(jr, vp, &it)) {
            return -1;
        }
        for (i = 0;; i++) {
            int more = democ_jr_next(jr, &it, &ep);
            if (more < 0) {
                return -1;
            }
            if (!more) {
                break;
            }
            if (i >= 3) {
                return democ_jr_fail(jr, "more than 3 elements");
            }
            democ_jr_index(jr, i);
            if (democ_jr_f32(jr, ep, &out->axes[i])) {
                return -1;
            }
        }
        democ_jr_index(jr, SIZE_MAX);
        if (i != 3) {
            return democ_jr_fail(jr, "expected 3 elements, got %zu", i);
        }
        democ_jr_pop(jr);
    }
    return 0;
}

/* ---- TriggerParams (selected by democ_mode_t) */

void democ_trigger_params_to_json(democ_jw_t *w, democ_mode_t selector, const democ_trigger_params_t *in) {
    switch (selector) {
    case DEMOC_MODE_GPIO:
        democ_gpio_params_to_json(w, &in->gpio);
        return;
    case DEMOC_MODE_THRESHOLD:
        democ_threshold_params_to_json(w, &in->threshold);
        return;
    default:
        (void)in;
        democ_jw_lit(w, "null");
        return;
    }
}

int democ_trigger_params_from_json(democ_jr_t *jr, size_t pos, democ_mode_t selector,
                                   democ_trigger_params_t *out) {
    switch (selector) {
    case DEMOC_MODE_NONE:
        return democ_jr_null(jr, pos);
    case DEMOC_MODE_GPIO:
        return democ_gpio_params_from_json(jr, pos, &out->gpio);
    case DEMOC_MODE_THRESHOLD:
        return democ_threshold_params_from_json(jr, pos, &out->threshold);
    default:
        (void)pos;
        (void)out;
        return democ_jr_fail(jr, "no member for selector value %llu", (unsigned long long)selector);
    }
}
