/* stream (data sets enabled and printed until the count, the duration or an interrupt) and auto
 * ping (every serial port at every rate). */
#include "device.h"

static volatile sig_atomic_t g_interrupted;

static void on_sigint(int sig) {
    (void)sig;
    g_interrupted = 1;
}

/* A data field by name (of the model) or as SET:DESCRIPTOR: 0, or 2 (the message printed). */
static int data_field(const conn_t *c, const char *text, int *set, int *descriptor) {
    const char *colon = strchr(text, ':');
    unsigned s;
    unsigned d;
    int found = 0;
    buf_t where = {0};
    if (colon != NULL) {
        char *end1;
        char *end2;
        char *a = xstrndup(text, (size_t)(colon - text));
        long x = strtol(a, &end1, 0);
        long y = strtol(colon + 1, &end2, 0);
        bool bad = *a == '\0' || *end1 != '\0' || colon[1] == '\0' || *end2 != '\0' || x < 0 || x > 255 ||
                   y < 0 || y > 255;
        codec_status_t why;
        const codec_field_info_t *f;
        free(a);
        if (bad) {
            note("bad data field '%s' (a name or SET:DESCRIPTOR, e.g. 0x80:0x04)", text);
            return EXIT_TROUBLE;
        }
        f = codec_find_field((uint8_t)x, (uint8_t)y, &why);
        if (f == NULL || codec_set_kind((uint8_t)x) != CODEC_SET_KIND_DATA) {
            note("0x%02lX:0x%02lX is not a data field of the spec", x, y);
            return EXIT_TROUBLE;
        }
        *set = (int)x;
        *descriptor = (int)y;
        return 0;
    }
    for (s = 0; s < 256; s++) {
        if (codec_set_kind((uint8_t)s) != CODEC_SET_KIND_DATA) {
            continue;
        }
        for (d = 0; d < 256; d++) {
            codec_status_t why;
            const codec_field_info_t *f = codec_find_field((uint8_t)s, (uint8_t)d, &why);
            if (f != NULL && strcmp(f->name, text) == 0 &&
                codec_device_supports(c->device, (uint8_t)s, (uint8_t)d)) {
                *set = (int)s;
                *descriptor = (int)d;
                buf_fmt(&where, "%s0x%02X:0x%02X", found ? ", " : "", s, d);
                found++;
            }
        }
    }
    if (found == 0) {
        note("'%s' is not a data field of %s", text, describe_model(c->device));
        free(where.s);
        return EXIT_TROUBLE;
    }
    if (found > 1) {
        note("'%s' is a field of several data sets: give SET:DESCRIPTOR (%s)", text, buf_text(&where));
        free(where.s);
        return EXIT_TROUBLE;
    }
    free(where.s);
    return 0;
}

/* Turns the data set's stream on where the model's stream control addresses it. */
int enable_stream(conn_t *c, int set) {
    size_t i;
    size_t k;
    for (i = 0; i < c->model->unaddressed_count; i++) {
        if (c->model->unaddressed[i] == set) {
            return 0;
        }
    }
    for (i = 0; i < DEV_ENABLE_COUNT; i++) {
        const dev_enable_t *e = &DEV_ENABLES[i];
        int attempt;
        if (!codec_device_supports(c->device, e->cmd_set, e->cmd_descriptor)) {
            continue;
        }
        for (attempt = 0; attempt < 4; attempt++) {
            /* the selector (mapped) or the set parameter; the flag a bool or an integer */
            bool use_selector = attempt < 2 && e->selector != NULL;
            const char *flag = attempt % 2 == 0 ? "true" : "1";
            char values[200];
            result_t r;
            run_t run;
            if (use_selector) {
                int64_t value = -1;
                for (k = 0; k < e->selector_count; k++) {
                    if (e->selector_map[2 * k + 1] == set) {
                        value = e->selector_map[2 * k];
                    }
                }
                if (value < 0) {
                    return 0;
                }
                snprintf(values, sizeof values, "{\"function\":%lld,\"%s\":%lld,\"%s\":%s}",
                         (long long)function_value("write"), e->selector, (long long)value, e->flag, flag);
            } else if (e->set_param) {
                snprintf(values, sizeof values, "{\"function\":%lld,\"%s\":%d,\"%s\":%s}",
                         (long long)function_value("write"), e->set_param, set, e->flag, flag);
            } else {
                continue;
            }
            run = run_values(c, e->cmd_set, e->cmd_descriptor, NULL, values, &r);
            if (run == R_VALUE) {
                continue;
            }
            if (run != R_OK) {
                note("%s", r.describe);
                result_free(&r);
                return run == R_LOST ? EXIT_TROUBLE : EXIT_REFUSED;
            }
            result_free(&r);
            return 0;
        }
        return 0;
    }
    return 0;
}

/* The data fields of the command line, all of one data set: 0, or the exit status. */
static int stream_fields(conn_t *c, const opts_t *o, int *set, int *fields, size_t *nf) {
    size_t i;
    if (o->npos < 1) {
        note("stream: give the data fields (names or SET:DESCRIPTOR)");
        return EXIT_TROUBLE;
    }
    for (i = 0; i < o->npos && *nf < FORMAT_MAX; i++) {
        int fs;
        int fd;
        int status = data_field(c, o->pos[i], &fs, &fd);
        if (status) {
            return status;
        }
        if (*set >= 0 && fs != *set) {
            note("stream: give fields of one data set");
            return EXIT_TROUBLE;
        }
        *set = fs;
        fields[(*nf)++] = fd;
    }
    return 0;
}

/* The budget check of the set's new message format over the device's others: 0 (the budget's
 * lines printed), or the exit status. */
static int stream_budget(conn_t *c, const opts_t *o, int set, const dev_format_t *spec, const int *fields,
                         size_t nf, const double *base, unsigned long decimation) {
    char where[300];
    unsigned long baud;
    buf_t lines = {0};
    size_t i;
    int status;
    formats_t *formats = (formats_t *)xalloc(sizeof *formats);
    status = read_formats(c, formats);
    if (status) {
        free(formats);
        return status;
    }
    formats->set[set].present = true;
    formats->set[set].n = nf;
    for (i = 0; i < nf; i++) {
        formats->set[set].descriptor[i] = (uint16_t)fields[i];
        formats->set[set].decimation[i] = (uint32_t)(spec->decimation ? decimation : 1);
    }
    baud = link_baud(c, o->baud, where, sizeof where);
    status = check_budget(c, formats, base, baud, where, o->force, &lines);
    free(formats);
    if (status == 0) {
        print_lines(stderr, PROG ": link budget: ", buf_text(&lines));
    }
    free(lines.s);
    return status;
}

/* The message format entry to write: the previous one with the fields (at the decimation) as its
 * list and the key parameters of key. */
val_t *stream_entry(const val_t *previous, const val_t *key, const dev_format_t *spec, const int *fields,
                    size_t nf, unsigned long decimation) {
    val_t *entry = val_copy(previous);
    val_t *list = val_new(V_LIST, 0);
    size_t i;
    long at;
    for (i = 0; i < nf; i++) {
        char text[32];
        if (spec->descriptor) {
            val_t *item = val_new(V_MAP, 0);
            snprintf(text, sizeof text, "%d", fields[i]);
            val_put(item, spec->descriptor, strlen(spec->descriptor), 0, val_number(V_INT, text, 0));
            if (spec->decimation) {
                snprintf(text, sizeof text, "%lu", decimation);
                val_put(item, spec->decimation, strlen(spec->decimation), 0, val_number(V_INT, text, 0));
            }
            val_push(list, item);
        } else {
            snprintf(text, sizeof text, "%d", fields[i]);
            val_push(list, val_number(V_INT, text, 0));
        }
    }
    at = val_index(entry, spec->list);
    if (at >= 0) {
        val_free(entry->items[at]);
        entry->items[at] = list;
    } else {
        val_put(entry, spec->list, strlen(spec->list), 0, list);
    }
    for (i = 0; i < key->n; i++) {
        long k = val_index(entry, key->keys[i]);
        if (k >= 0) {
            val_free(entry->items[k]);
            entry->items[k] = val_copy(key->items[i]);
        }
    }
    return entry;
}

/* Writes an entry of the message format setting: 0, or the exit status (the note printed; what
 * is the note's text, NULL: the reason). */
int write_format(conn_t *c, const dev_setting_t *s, const val_t *entry, const char *what) {
    buf_t values = {0};
    char msg[1000];
    result_t r;
    run_t run;
    int status = 0;
    if (!command_values(s, entry, function_value("write"), &values, msg, sizeof msg)) {
        note("%s", what ? what : msg);
        status = EXIT_TROUBLE;
    } else {
        run = run_values(c, s->set, s->descriptor, s->device, buf_text(&values), &r);
        if (run != R_OK) {
            note("%s", what ? what : run == R_VALUE ? g_value_error : r.describe);
            status = run == R_FAILED ? EXIT_REFUSED : EXIT_TROUBLE;
        }
        result_free(&r);
    }
    free(values.s);
    return status;
}

/* Prints the packets until the count, the duration or an interrupt: 0, or the exit status. */
static int stream_until(conn_t *c, const opts_t *o) {
    double end = o->duration > 0 ? now_s() + o->duration : HUGE_VAL;
    while (!g_interrupted && now_s() < end && !(o->count && c->stream_count >= o->count)) {
        double left = end - now_s();
        double wait = left * 1000 < 200 ? left * 1000 : 200;
        if (codec_link_pump(&c->link, (uint32_t)(wait > 0 ? wait : 0)) < 0) {
            note("%s", c->posix.error);
            return EXIT_TROUBLE;
        }
    }
    return 0;
}

int cmd_stream(conn_t *c, const opts_t *o) {
    int set = -1;
    int fields[FORMAT_MAX];
    size_t nf = 0;
    const dev_setting_t *s;
    const char *param = NULL;
    double base[256] = {0};
    double hz;
    double rate;
    unsigned long decimation;
    val_t *key;
    val_t *previous = NULL;
    val_t *entry;
    const dev_format_t *spec;
    char msg[1000];
    bool nack;
    run_t run;
    int status = stream_fields(c, o, &set, fields, &nf);
    double observed;
    unsigned long shown;
    if (status) {
        return status;
    }
    s = format_setting(c, set, &param);
    if (s == NULL) {
        note("%s has no message format for data set 0x%02X", describe_model(c->device), set);
        return EXIT_TROUBLE;
    }
    spec = format_of(s);
    status = read_base_rates(c, base);
    if (status) {
        return status;
    }
    hz = base[set];
    if (hz <= 0) {
        note("no base rate known for data set 0x%02X", set);
        return EXIT_TROUBLE;
    }
    rate = o->rate > 0 ? o->rate : hz;
    if (!(rate > 0 && rate <= hz)) {
        note("--rate %g: expected a rate above 0 and at most the base rate %g Hz", rate, hz);
        return EXIT_TROUBLE;
    }
    decimation = (unsigned long)nearbyint(hz / rate);
    decimation = decimation < 1 ? 1 : decimation;
    status = stream_budget(c, o, set, spec, fields, nf, base, decimation);
    if (status) {
        return status;
    }
    key = key_map(param, set);
    run = read_entry(c, s, key, &previous, &nack, msg, sizeof msg);
    if (run != R_OK) {
        note("%s", msg);
        val_free(key);
        return run == R_FAILED ? EXIT_REFUSED : EXIT_TROUBLE;
    }
    entry = stream_entry(previous, key, spec, fields, nf, decimation);
    c->stream_set = set;
    c->stream_json = o->json;
    c->stream_limit = o->count;
    signal(SIGINT, on_sigint);
    status = write_format(c, s, entry, NULL);
    if (status == 0) {
        status = enable_stream(c, set);
    }
    if (status == 0) {
        status = stream_until(c, o);
    }
    c->stream_set = -1;
    if (!o->keep) {
        /* the previous entry holds the key parameters already (they are its attributes) */
        (void)write_format(c, s, previous, "could not restore the previous message format");
    }
    shown = o->count && c->stream_count > o->count ? o->count : c->stream_count;
    observed = c->stream_count > 1 && c->stream_last > c->stream_first
                   ? (double)(c->stream_count - 1) / (c->stream_last - c->stream_first)
                   : 0.0;
    note("%lu packets of set 0x%02X; observed %.1f Hz (configured %g Hz: base %g Hz / decimation %lu)", shown,
         set, observed, hz / (double)decimation, hz, decimation);
    val_free(key);
    val_free(previous);
    val_free(entry);
    if (status) {
        return status;
    }
    return c->stream_count ? 0 : EXIT_REFUSED;
}

static int cmp_rate_desc(const void *a, const void *b) {
    unsigned long x = *(const unsigned long *)a, y = *(const unsigned long *)b;
    return x < y ? 1 : x > y ? -1 : 0;
}

/* The rates `auto` tries: the default first, then every rate the spec lists for a model's main
 * port (link: baud_rates), highest first (the Python CLI's order). Returns how many. */
static size_t auto_rates(unsigned long *out, size_t cap) {
    size_t n = 0, m, k, i, count;
    out[n++] = DEFAULT_BAUD;
    for (m = 0; m < DEV_MODEL_COUNT; m++) {
        codec_device_t d;
        const uint32_t *rates;
        if (!codec_device_from_id(DEV_MODELS[m].id, &d)) {
            continue;
        }
        rates = codec_device_baud_rates(d, &count);
        for (k = 0; rates != NULL && k < count && n < cap; k++) {
            for (i = 0; i < n && out[i] != rates[k]; i++) {
            }
            if (i == n) {
                out[n++] = rates[k];
            }
        }
    }
    qsort(out + 1, n - 1, sizeof *out, cmp_rate_desc);
    return n;
}

/* The system's serial ports when --ports is not given: the device nodes of the kinds pyserial's
 * list_ports shows on Linux (USB serial, ACM, on-board UARTs, Bluetooth RFCOMM) that the kernel
 * backs with a device (/sys/class/tty/NAME/device). */
static glob_t system_ports(void) {
    static const char *const patterns[] = {"/dev/ttyS*", "/dev/ttyUSB*", "/dev/ttyACM*", "/dev/ttyAMA*",
                                           "/dev/rfcomm*"};
    glob_t g;
    size_t i;
    memset(&g, 0, sizeof g);
    for (i = 0; i < sizeof patterns / sizeof patterns[0]; i++) {
        (void)glob(patterns[i], i ? GLOB_APPEND : 0, NULL, &g);
    }
    return g;
}

static bool backed_by_a_device(const char *path) {
    char sys[512];
    struct stat st;
    const char *name = strrchr(path, '/');
    snprintf(sys, sizeof sys, "/sys/class/tty/%s/device", name ? name + 1 : path);
    return stat(sys, &st) == 0;
}

/* `auto ping`: pings every serial port at the rates above, one line per device that answers
 * (port, rate, model, serial number); a port that answers at no rate is one note. Exit 0 when a
 * device answered, 1 when none did. */
int cmd_auto(const opts_t *o) {
    static conn_t conn;
    unsigned long rates[64];
    size_t nrates = auto_rates(rates, sizeof rates / sizeof rates[0]);
    glob_t g;
    const char **ports = o->ports;
    size_t nports = o->nports, p, r;
    int found = 0;
    memset(&g, 0, sizeof g);
    if (ports == NULL) {
        g = system_ports();
        ports = (const char **)g.gl_pathv;
        nports = g.gl_pathc;
    }
    for (p = 0; p < nports; p++) {
        bool answered = false;
        if (o->ports == NULL && !backed_by_a_device(ports[p])) {
            continue;
        }
        for (r = 0; r < nrates && !answered; r++) {
            unsigned long timeout = o->timeout_ms < 300 ? o->timeout_ms : 300;
            int status;
            memset(&conn, 0, sizeof conn);
            quiet_notes = true;
            status = connect_device(&conn, ports[p], o->model, rates[r], timeout);
            quiet_notes = false;
            if (status == 0) {
                buf_t serial = {0};
                const char *sn = identity_text(&conn, "serial_number", &serial);
                say("%s %lu %s (%s) serial %s", ports[p], rates[r], codec_device_title(conn.device),
                    conn.model->id, sn && sn[0] ? sn : "?");
                free(serial.s);
                answered = true;
                found++;
            }
            disconnect(&conn);
        }
        if (!answered) {
            buf_t list = {0};
            for (r = 0; r < nrates; r++) {
                buf_fmt(&list, "%s%lu", r ? ", " : "", rates[r]);
            }
            note("%s: no answer at %s baud", ports[p], buf_text(&list));
            free(list.s);
        }
    }
    if (o->ports == NULL) {
        globfree(&g);
    }
    return found ? 0 : EXIT_REFUSED;
}
