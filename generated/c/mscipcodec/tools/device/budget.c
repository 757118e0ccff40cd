/* The link budget (docs/configure-a-device.md): the data sets' message formats and base rates read
 * from the device, and the manuals' UART bandwidth check of apply and stream.
 * Generated: do not edit. */
#include "device.h"

void formats_from_list(format_t *f, const val_t *list, const dev_format_t *spec) {
    size_t i;
    f->present = true;
    f->n = 0;
    for (i = 0; list && list->kind == V_LIST && i < list->n && f->n < FORMAT_MAX; i++) {
        const val_t *item = list->items[i];
        const val_t *d = item->kind == V_MAP && spec->descriptor ? val_get(item, spec->descriptor) : item;
        const val_t *k = item->kind == V_MAP && spec->decimation ? val_get(item, spec->decimation) : NULL;
        if (d == NULL || d->kind != V_INT) {
            continue;
        }
        f->descriptor[f->n] = (uint16_t)strtoul(d->text, NULL, 10);
        f->decimation[f->n] = k && k->kind == V_INT ? (uint32_t)strtoul(k->text, NULL, 10) : 1u;
        f->n++;
    }
}

/* The setting that holds a data set's message format on the model, and the key parameter (NULL:
 * unkeyed). */
const dev_setting_t *format_setting(const conn_t *c, int set, const char **param) {
    size_t i;
    for (i = 0; i < c->model->setting_count; i++) {
        const dev_setting_t *s = &c->model->settings[i];
        const dev_format_t *f = format_of(s);
        if (f == NULL) {
            continue;
        }
        if (f->set >= 0 && f->set == set) {
            *param = NULL;
            return s;
        }
        if (f->set_param && is_keyed(s, f->set_param)) {
            *param = f->set_param;
            return s;
        }
    }
    return NULL;
}

val_t *key_map(const char *param, int set) {
    val_t *key = val_new(V_MAP, 0);
    if (param) {
        char text[16];
        snprintf(text, sizeof text, "%d", set);
        val_put(key, param, strlen(param), 0, val_number(V_INT, text, 0));
    }
    return key;
}

/* Every data set's current message format; 0, or the exit status (the message printed). */
int read_formats(conn_t *c, formats_t *out) {
    size_t i;
    for (i = 0; i < c->model->base_rate_count; i++) {
        int set = c->model->base_rates[i].set;
        const char *param = NULL;
        const dev_setting_t *s = format_setting(c, set, &param);
        val_t *key;
        val_t *entry = NULL;
        bool nack;
        char msg[600];
        run_t run;
        if (s == NULL) {
            continue;
        }
        key = key_map(param, set);
        run = read_entry(c, s, key, &entry, &nack, msg, sizeof msg);
        val_free(key);
        if (run == R_FAILED && nack) {
            continue;
        }
        if (run != R_OK) {
            note("%s", msg);
            return run == R_VALUE ? EXIT_TROUBLE : EXIT_REFUSED;
        }
        formats_from_list(&out->set[set], val_get(entry, format_of(s)->list), format_of(s));
        val_free(entry);
    }
    return 0;
}

/* The base rate of every data set, read from the device (the spec's where no command reads one). */
int read_base_rates(conn_t *c, double *rates) {
    size_t i;
    size_t q;
    for (i = 0; i < c->model->base_rate_count; i++) {
        int set = c->model->base_rates[i].set;
        bool found = false;
        for (q = 0; q < DEV_RATE_QUERY_COUNT && !found; q++) {
            const dev_rate_query_t *rq = &DEV_RATE_QUERIES[q];
            char values[64];
            result_t r;
            run_t run;
            const val_t *reply;
            if (!mscipc_device_supports(c->device, rq->cmd_set, rq->cmd_descriptor)) {
                continue;
            }
            if (rq->set >= 0 && rq->set != set) {
                continue;
            }
            if (rq->set_param) {
                snprintf(values, sizeof values, "{\"%s\":%d}", rq->set_param, set);
            } else {
                snprintf(values, sizeof values, "{}");
            }
            run = run_values(c, rq->cmd_set, rq->cmd_descriptor, NULL, values, &r);
            if (run == R_LOST) {
                note("%s", r.describe);
                result_free(&r);
                return EXIT_TROUBLE;
            }
            reply = run == R_OK ? reply_values(&r, NULL) : NULL;
            if (reply != NULL && reply->kind == V_MAP && reply->n > 0) {
                const val_t *last = reply->items[reply->n - 1];
                if (last->kind == V_INT || last->kind == V_NUM) {
                    rates[set] = strtod(last->text, NULL);
                    found = true;
                }
            }
            result_free(&r);
        }
        if (!found) {
            rates[set] = c->model->base_rates[i].hz;
        }
    }
    return 0;
}

/* Objects, not macros: a protocol without shared data or a bandwidth calculation compares and
 * divides without a constant warning. */
static const int g_shared_set = DEV_SHARED_SET;

static const double g_word_bits = MSCIPC_LINK_UART_WORD_BITS;

static int field_size(const conn_t *c, int set, int descriptor) {
    size_t i;
    int shared = -1;
    for (i = 0; i < c->model->size_count; i++) {
        if (c->model->sizes[i].set == set && c->model->sizes[i].descriptor == descriptor) {
            return c->model->sizes[i].size + MSCIPC_LINK_FIELD_OVERHEAD;
        }
        if (g_shared_set >= 0 && c->model->sizes[i].set == g_shared_set &&
            c->model->sizes[i].descriptor == descriptor) {
            shared = c->model->sizes[i].size + MSCIPC_LINK_FIELD_OVERHEAD;
        }
    }
    return shared;
}

/* The budget lines (describe) into lines; *total the bits per second; false with the message
 * printed as "link budget: ..." when a stream cannot be costed. */
static bool budget_lines(const conn_t *c, const formats_t *formats, const double *base, unsigned long baud,
                         const char *where, buf_t *lines, double *total) {
    int set;
    *total = 0;
    buf_reset(lines);
    for (set = 0; set < 256; set++) {
        const format_t *f = &formats->set[set];
        double hz = base[set];
        double packet_hz = 0;
        double sum = 0;
        double bits;
        size_t i;
        buf_t fields = {0};
        if (!f->present || f->n == 0) {
            continue;
        }
        if (hz <= 0) {
            size_t k;
            for (k = 0; k < c->model->base_rate_count; k++) {
                if (c->model->base_rates[k].set == set) {
                    hz = c->model->base_rates[k].hz;
                }
            }
        }
        if (hz <= 0) {
            note("link budget: no base rate known for data set 0x%02X of %s", set, c->model->id);
            return false;
        }
        for (i = 0; i < f->n; i++) {
            int size = field_size(c, set, f->descriptor[i]);
            double rate;
            if (size < 0) {
                note("link budget: data field 0x%02X,0x%02X is not a data field of %s", set, f->descriptor[i],
                     c->model->id);
                free(fields.s);
                return false;
            }
            if (f->decimation[i] == 0) {
                note("link budget: data field 0x%02X,0x%02X: decimation 0 (expected 1 or more)", set,
                     f->descriptor[i]);
                free(fields.s);
                return false;
            }
            rate = hz / f->decimation[i];
            packet_hz = rate > packet_hz ? rate : packet_hz;
            sum += size * rate;
            buf_fmt(&fields, "%s0x%02X (%d B at %g Hz)", i ? ", " : "", f->descriptor[i], size, rate);
        }
        bits = MSCIPC_LINK_UART_WORD_BITS * (MSCIPC_LINK_PACKET_OVERHEAD * packet_hz + sum);
        *total += bits;
        buf_fmt(lines, "set 0x%02X: %.0f bit/s (%.0f bytes/s, %g packets/s): %s\n", set, bits,
                g_word_bits > 0 ? bits / g_word_bits : 0.0, packet_hz,
                fields.n ? buf_text(&fields) : "no fields");
        free(fields.s);
    }
    if (baud) {
        buf_fmt(lines, "total %.0f bit/s of %lu baud%s (%.0f%%)\n", *total, baud, where,
                100.0 * *total / (double)baud);
    } else {
        buf_fmt(lines, "total %.0f bit/s (no baud rate known: --baud gives one)\n", *total);
    }
    return true;
}

/* Prints each line of text with a prefix. */
void print_lines(FILE *to, const char *prefix, const char *text) {
    const char *s = text;
    while (*s) {
        const char *e = strchr(s, '\n');
        size_t n = e ? (size_t)(e - s) : strlen(s);
        fprintf(to, "%s%.*s\n", prefix, (int)n, s);
        s += n + (e ? 1 : 0);
    }
    fflush(to);
}

/* The budget check of apply and stream: 0 (the lines in lines), or 2 when over budget and not
 * forced (the lines and the refusal printed). */
int check_budget(const conn_t *c, const formats_t *formats, const double *base, unsigned long baud,
                 const char *where, bool force, buf_t *lines) {
    double total;
    if (!MSCIPC_LINK_HAS_BANDWIDTH) {
        buf_reset(lines);
        buf_str(lines, "the spec gives no UART bandwidth calculation\n");
        return 0;
    }
    if (!budget_lines(c, formats, base, baud, where, lines, &total)) {
        return EXIT_TROUBLE;
    }
    if (baud && total > (double)baud) {
        char text[600];
        snprintf(
            text, sizeof text,
            "link budget exceeded: the message formats need %.0f bit/s, the port carries %lu baud%s (the "
            "manuals' UART bandwidth calculation, %s)",
            total, baud, where, DEV_BANDWIDTH_SOURCES);
        if (!force) {
            print_lines(stderr, PROG ": ", buf_text(lines));
            note("%s; nothing was written (--force writes anyway)", text);
            return EXIT_TROUBLE;
        }
        note("warning: %s; writing anyway (--force)", text);
    }
    return 0;
}

/* The baud rate the budget is checked against and where it comes from. */
unsigned long link_baud(conn_t *c, unsigned long option, char *where, size_t cap) {
    size_t i;
    if (option) {
        snprintf(where, cap, " (--baud)");
        return option;
    }
    if (c->baud) {
        snprintf(where, cap, " (%s)", c->address);
        return c->baud;
    }
    where[0] = '\0';
    for (i = 0; i < c->model->setting_count; i++) {
        const dev_setting_t *s = &c->model->settings[i];
        const char *param = baud_param(s);
        val_t *key;
        val_t *entry = NULL;
        bool nack;
        char msg[600];
        const val_t *v;
        if (param == NULL || s->keyed_count) {
            continue;
        }
        key = val_new(V_MAP, 0);
        if (read_entry(c, s, key, &entry, &nack, msg, sizeof msg) != R_OK) {
            val_free(key);
            continue;
        }
        val_free(key);
        v = val_get(entry, param);
        if (v && v->kind == V_INT && strtoll(v->text, NULL, 10) > 0) {
            unsigned long rate = strtoul(v->text, NULL, 10);
            snprintf(where, cap, " (the device's %s)", s->name);
            val_free(entry);
            return rate;
        }
        val_free(entry);
    }
    return 0;
}
