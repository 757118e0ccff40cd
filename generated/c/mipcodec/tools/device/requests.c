/* The subcommands ping, info, send, save-startup, factory-reset and settings dump.
 * Generated: do not edit. */
#include "device.h"

int cmd_ping(conn_t *c, const opts_t *o) {
    result_t r;
    double t0 = now_s();
    double ms;
    run_t run;
    buf_t serial = {0};
    const char *sn;
    (void)o;
    if (!MIPC_LINK_HAS_PING) {
        note("the spec has no ping command");
        return EXIT_TROUBLE;
    }
    run = run_values(c, MIPC_LINK_PING_SET, MIPC_LINK_PING_DESCRIPTOR, NULL, "{}", &r);
    ms = (now_s() - t0) * 1000;
    if (run != R_OK) {
        note("%s", r.describe);
        result_free(&r);
        return run == R_LOST ? EXIT_TROUBLE : EXIT_REFUSED;
    }
    result_free(&r);
    sn = identity_text(c, "serial_number", &serial);
    if (sn && sn[0]) {
        say("%s %s answered in %.0f ms", mipc_device_title(c->device), sn, ms);
    } else {
        say("%s answered in %.0f ms", mipc_device_title(c->device), ms);
    }
    free(serial.s);
    return 0;
}

static int cmp_u16(const void *a, const void *b) {
    return (int)*(const uint16_t *)a - (int)*(const uint16_t *)b;
}

int cmd_info(conn_t *c, const opts_t *o) {
    static const char *const items[][2] = {
        {"serial_number", "serial"}, {"model_number", "model number"}, {"firmware", "firmware"}};
    buf_t b = {0};
    buf_t lines = {0};
    const char *name = identity_text(c, "model_name", &b);
    uint16_t *listed = NULL;
    size_t count = 0;
    size_t i;
    size_t k;
    double base[256] = {0};
    formats_t *formats;
    char where[300];
    unsigned long baud;
    int status;
    say("model: %s (%s, manual %s)", name && name[0] ? name : mipc_device_title(c->device), c->model->id,
        mipc_device_manual(c->device));
    for (i = 0; i < 3; i++) {
        const char *v = identity_text(c, items[i][0], &b);
        if (v != NULL) {
            say("%s: %s", items[i][1], v);
        }
    }
    for (i = 0; i < DEV_LIST_COUNT; i++) {
        result_t r;
        const val_t *values;
        const val_t *list;
        const mipc_field_info_t *reply;
        mipc_status_t why;
        run_t run;
        if (!mipc_device_supports(c->device, DEV_LISTS[i].cmd_set, DEV_LISTS[i].cmd_descriptor)) {
            continue;
        }
        run = run_values(c, DEV_LISTS[i].cmd_set, DEV_LISTS[i].cmd_descriptor, NULL, "{}", &r);
        if (run == R_LOST) {
            note("%s", r.describe);
            result_free(&r);
            free(listed);
            free(b.s);
            return EXIT_TROUBLE;
        }
        reply = mipc_find_field(DEV_LISTS[i].cmd_set, DEV_LISTS[i].reply_descriptor, &why);
        values = run == R_OK && reply ? reply_values(&r, reply->name) : NULL;
        list = val_get(values, DEV_LISTS[i].param);
        for (k = 0; list && list->kind == V_LIST && k < list->n; k++) {
            const val_t *item = list->items[k];
            uint16_t v;
            if (item->kind == V_INT) {
                v = (uint16_t)strtoul(item->text, NULL, 10);
            } else if (item->kind == V_MAP && item->n >= 2 && item->items[0]->kind == V_INT &&
                       item->items[1]->kind == V_INT) {
                v = (uint16_t)((strtoul(item->items[0]->text, NULL, 10) << 8) |
                               (strtoul(item->items[1]->text, NULL, 10) & 0xFF));
            } else {
                continue;
            }
            listed = (uint16_t *)xrealloc(listed, (count + 1) * sizeof *listed);
            listed[count++] = v;
        }
        result_free(&r);
    }
    qsort(listed, count, sizeof *listed, cmp_u16);
    for (i = 0, k = 0; i < count; i++) { /* unique */
        if (k == 0 || listed[k - 1] != listed[i]) {
            listed[k++] = listed[i];
        }
    }
    count = k;
    say("descriptors: %zu (the device's descriptor lists)", count);
    for (i = 0; i < count;) {
        unsigned set = listed[i] >> 8;
        buf_reset(&b);
        buf_fmt(&b, "  0x%02X %s:", set, set_name((uint8_t)set));
        for (; i < count && (unsigned)(listed[i] >> 8) == set; i++) {
            buf_fmt(&b, " %02X", listed[i] & 0xFF);
        }
        say("%s", buf_text(&b));
    }
    free(listed);
    status = read_base_rates(c, base);
    if (status) {
        free(b.s);
        return status;
    }
    buf_reset(&b);
    for (i = 0; i < 256; i++) {
        if (base[i] > 0) {
            buf_fmt(&b, "%s0x%02X %g Hz", b.n ? ", " : "", (unsigned)i, base[i]);
        }
    }
    say("base rates: %s", b.n ? buf_text(&b) : "none");
    baud = link_baud(c, o->baud, where, sizeof where);
    formats = (formats_t *)xalloc(sizeof *formats);
    status = read_formats(c, formats);
    if (status == 0) {
        say("link budget:");
        status = check_budget(c, formats, base, baud, where, true, &lines);
        if (status == 0) {
            print_lines(stdout, "  ", buf_text(&lines));
        }
    }
    free(formats);
    free(lines.s);
    free(b.s);
    return status;
}

/* A value given on the command line (PARAM=VALUE), read as YAML reads a scalar or flow value. */
static val_t *parse_value(const char *text) {
    yp_t p;
    size_t i = 0;
    val_t *v;
    memset(&p, 0, sizeof p);
    v = yp_flow(&p, text, strlen(text), &i, 1, 0, false);
    if (v == NULL) {
        return val_str(text, strlen(text), 0); /* as yaml.safe_load's errors: the text as a string */
    }
    return v;
}

/* The enum of a command's parameter, where a setting of the model names it (-1: none). */
static int param_enum(const conn_t *c, uint8_t set, uint8_t descriptor, const char *param) {
    size_t i;
    for (i = 0; i < c->model->setting_count; i++) {
        const dev_setting_t *s = &c->model->settings[i];
        if (s->set == set && s->descriptor == descriptor) {
            const dev_attr_t *a = attr_of(s, param);
            return a ? a->enum_index : -1;
        }
    }
    return -1;
}

static bool layout_for(const mipc_field_info_t *f, mipc_device_t device) {
    size_t i;
    if (f->layout_count <= 1) {
        return true;
    }
    for (i = 0; i < f->layout_count; i++) {
        const mipc_layout_info_t *l = mipc_layout_info((mipc_field_id_t)(f->first_layout + i));
        if (l && (l->device_id == device || l->device_id == MIPC_DEVICE_ANY)) {
            return true;
        }
    }
    return false;
}

/* Reads the command line of (set, f) with the values (a JSON object) through the library's JSON
 * reader: its status, its message in msg. */
static mipc_status_t probe_command(const conn_t *c, uint8_t set, const mipc_field_info_t *f,
                                   const char *values, char *msg, size_t cap) {
    buf_t line = {0};
    mipc_field_value_t command;
    mipc_status_t st;
    buf_fmt(&line, "{\"offset\":0,\"set\":%u,\"fields\":[{\"descriptor\":%u,\"name\":", set, f->descriptor);
    json_string(&line, f->name, strlen(f->name));
    if (f->layout_count > 1) {
        buf_fmt(&line, ",\"device\":\"%s\"", mipc_device_id(c->device));
    }
    buf_fmt(&line, ",\"values\":%s}]}", values);
    msg[0] = '\0';
    st = mipc_json_command_line(buf_text(&line), line.n, &command, msg, cap);
    free(line.s);
    return st;
}

/* Whether the command's layout has a function selector: probes the JSON reader. */
static bool has_function(const conn_t *c, uint8_t set, const mipc_field_info_t *f) {
    char msg[MIPC_ERROR_MESSAGE_MAX + 200];
    return probe_command(c, set, f, "{\"function\":1}", msg, sizeof msg) == MIPC_OK ||
           strstr(msg, "unknown key \"function\"") == NULL;
}

/* The parameters a command's write leaves out (", " between, in the layout's order), for a
 * command that is no setting: the values given are read by the JSON reader, and every parameter it
 * says is missing is added (as 0) and read again. */
static void missing_params(const conn_t *c, uint8_t set, const mipc_field_info_t *f, const char *values,
                           buf_t *out) {
    static const char said[] = "missing parameter \"";
    buf_t probe = {0};
    char msg[MIPC_ERROR_MESSAGE_MAX + 200];
    int round;
    buf_str(&probe, values);
    for (round = 0; round < 64; round++) {
        const char *at;
        const char *end;
        if (probe_command(c, set, f, buf_text(&probe), msg, sizeof msg) == MIPC_OK ||
            (at = strstr(msg, said)) == NULL) {
            break;
        }
        at += strlen(said);
        end = strchr(at, '"');
        if (end == NULL) {
            break;
        }
        buf_fmt(out, "%s%.*s", out->n ? ", " : "", (int)(end - at), at);
        probe.n--; /* the closing brace */
        buf_fmt(&probe, "%s\"%.*s\":0}", probe.n > 1 ? "," : "", (int)(end - at), at);
    }
    free(probe.s);
}

/* The setting of the model that (set, descriptor) reads and writes (NULL: none). */
static const dev_setting_t *setting_of(const conn_t *c, uint8_t set, uint8_t descriptor) {
    size_t i;
    for (i = 0; i < c->model->setting_count; i++) {
        if (c->model->settings[i].set == set && c->model->settings[i].descriptor == descriptor) {
            return &c->model->settings[i];
        }
    }
    return NULL;
}

/* Reads the setting s for the key parameters given, replaces its values with the given ones and
 * writes the write's values into *values: 0, or the exit status (the message printed). */
static int read_modify(conn_t *c, const dev_setting_t *s, const mipc_field_info_t *f, const val_t *given,
                       buf_t *values) {
    buf_t absent = {0};
    buf_t kept = {0};
    val_t *key = val_new(V_MAP, 0);
    val_t *entry = NULL;
    bool nack;
    char msg[1000];
    run_t run;
    int status = 0;
    size_t i;
    for (i = 0; i < s->keyed_count; i++) {
        const val_t *v = val_get(given, s->keyed[i]);
        if (v == NULL) {
            buf_fmt(&absent, "%s%s", absent.n ? ", " : "", s->keyed[i]);
        } else {
            val_put(key, s->keyed[i], strlen(s->keyed[i]), 0, val_copy(v));
        }
    }
    if (absent.n) {
        note("%s write: give %s (the key of the read that fills the parameters left out)", f->name,
             buf_text(&absent));
        status = EXIT_TROUBLE;
    } else if ((run = read_entry(c, s, key, &entry, &nack, msg, sizeof msg)) != R_OK) {
        note("%s", msg);
        status = run == R_FAILED ? EXIT_REFUSED : EXIT_TROUBLE;
    } else {
        for (i = 0; i < s->attr_count; i++) {
            const char *a = s->attrs[i].name;
            const val_t *v = val_get(given, a);
            long at = val_index(entry, a);
            if (v == NULL) {
                buf_fmt(&kept, "%s%s", kept.n ? ", " : "", a);
            } else if (at >= 0) {
                val_free(entry->items[at]);
                entry->items[at] = val_copy(v);
            } else {
                val_put(entry, a, strlen(a), 0, val_copy(v));
            }
        }
        note("%s: %s as read from the device (read, modify, write)", f->name, buf_text(&kept));
        if (!command_values(s, entry, function_value("write"), values, msg, sizeof msg)) {
            note("%s", msg);
            status = EXIT_TROUBLE;
        }
    }
    val_free(entry);
    val_free(key);
    free(absent.s);
    free(kept.s);
    return status;
}

/* send NAME write P=V ... with parameters left out: a setting (a command the model also reads) is
 * read first (with the key parameters given) and the given parameters replace its values (read,
 * modify, write): *values becomes the write's, *variant the setting's device; any other command
 * needs every parameter. 0, or the exit status (the message printed). */
static int complete_write(conn_t *c, uint8_t set, const mipc_field_info_t *f, const val_t *given,
                          buf_t *values, const char **variant) {
    const dev_setting_t *s = setting_of(c, set, f->descriptor);
    buf_t missing = {0};
    size_t i;
    int status = 0;
    if (s == NULL) {
        missing_params(c, set, f, buf_text(values), &missing);
    }
    for (i = 0; s != NULL && i < s->attr_count; i++) {
        if (val_get(given, s->attrs[i].name) == NULL) {
            buf_fmt(&missing, "%s%s", missing.n ? ", " : "", s->attrs[i].name);
        }
    }
    if (missing.n && s == NULL) {
        note("%s write: give every parameter (%s left out; the command has no read to fill them from)",
             f->name, buf_text(&missing));
        status = EXIT_TROUBLE;
    } else if (missing.n) {
        status = read_modify(c, s, f, given, values);
        *variant = s->device;
    }
    free(missing.s);
    return status;
}

/* The function selector's names, ", " between. */
static void function_names(buf_t *names) {
    size_t k;
    for (k = 0; k < DEV_FUNCTION_COUNT; k++) {
        buf_fmt(names, "%s%s", k ? ", " : "", DEV_FUNCTIONS[k].name);
    }
}

/* The values of `send NAME [FUNCTION] [PARAM=VALUE ...]` as a JSON object into *values, each
 * parameter given also into the map given, *write when the function is write: 0, or the exit
 * status (the message printed). */
static int send_values(conn_t *c, uint8_t set, const mipc_field_info_t *f, const opts_t *o, buf_t *values,
                       val_t *given, bool *write) {
    size_t i = 1;
    bool first = true;
    buf_str(values, "{");
    if (has_function(c, set, f)) {
        int64_t fn = o->npos < 2 || strchr(o->pos[1], '=') != NULL ? -2 : function_value(o->pos[1]);
        if (fn < 0) {
            buf_t names = {0};
            function_names(&names);
            if (fn == -2) {
                note("%s: give the function first (%s)", f->name, buf_text(&names));
            } else {
                note("unknown function (one of: %s)", buf_text(&names));
            }
            free(names.s);
            return EXIT_TROUBLE;
        }
        buf_fmt(values, "\"function\":%lld", (long long)fn);
        *write = fn == function_value("write");
        first = false;
        i = 2;
    }
    for (; i < o->npos; i++) {
        const char *arg = o->pos[i];
        const char *eq = strchr(arg, '=');
        val_t *v;
        int e;
        if (eq == NULL || eq == arg) {
            note("%s: expected PARAMETER=VALUE, got '%s'", f->name, arg);
            return EXIT_TROUBLE;
        }
        if (!first) {
            buf_str(values, ",");
        }
        first = false;
        json_string(values, arg, (size_t)(eq - arg));
        buf_str(values, ":");
        v = parse_value(eq + 1);
        val_put(given, arg, (size_t)(eq - arg), 0, val_copy(v));
        {
            char *pname = xstrndup(arg, (size_t)(eq - arg));
            e = param_enum(c, set, f->descriptor, pname);
            free(pname);
        }
        if (e >= 0 && v->kind == V_STR) {
            size_t k;
            bool found = false;
            for (k = 0; k < DEV_ENUMS[e].count; k++) {
                if (strcasecmp_ascii_eq(DEV_ENUMS[e].members[k].name, v->text)) {
                    buf_fmt(values, "%lld", (long long)DEV_ENUMS[e].members[k].value);
                    found = true;
                }
            }
            if (!found) {
                note("%s.%.*s: '%s' is not a member of %s", f->name, (int)(eq - arg), arg, v->text,
                     DEV_ENUMS[e].name);
                val_free(v);
                return EXIT_TROUBLE;
            }
        } else {
            val_json(values, v);
        }
        val_free(v);
    }
    buf_str(values, "}");
    return 0;
}

int cmd_send(conn_t *c, const opts_t *o) {
    uint8_t set = 0;
    const mipc_field_info_t *f;
    buf_t values = {0};
    size_t i;
    result_t r;
    run_t run;
    const val_t *reply;
    bool write = false;
    const char *variant = NULL;
    val_t *given;
    int status;
    if (o->npos < 1) {
        note("send: give the command's NAME");
        return EXIT_TROUBLE;
    }
    f = command_field(o->pos[0], &set);
    if (f == NULL) {
        note("unknown command '%s'", o->pos[0]);
        return EXIT_TROUBLE;
    }
    if (!layout_for(f, c->device)) {
        note("%s is not supported by %s", f->name, describe_model(c->device));
        return EXIT_TROUBLE;
    }
    given = val_new(V_MAP, 0); /* the parameters given, by name */
    status = send_values(c, set, f, o, &values, given, &write);
    if (status == 0 && write) {
        status = complete_write(c, set, f, given, &values, &variant);
    }
    val_free(given);
    if (status != 0) {
        free(values.s);
        return status;
    }
    run = run_values(c, set, f->descriptor, variant, buf_text(&values), &r);
    free(values.s);
    if (run == R_VALUE) {
        note("%s", g_value_error);
        return EXIT_TROUBLE;
    }
    if (run == R_LOST) {
        note("%s", r.describe);
        result_free(&r);
        return EXIT_TROUBLE;
    }
    if (r.kind == MIPC_RESULT_REFUSED) {
        note("%s", r.describe);
        result_free(&r);
        return EXIT_TROUBLE;
    }
    if (o->json) {
        say("%s", r.json);
    } else {
        if (run == R_OK) {
            say("%s: %s", f->name, mipc_result_kind_name(r.kind));
        } else {
            say("%s", r.describe);
        }
        reply = val_get(r.line, "reply");
        for (i = 0; reply && reply->kind == V_LIST && i < reply->n; i++) {
            const val_t *name = val_get(reply->items[i], "name");
            const val_t *vals = val_get(reply->items[i], "values");
            if (name && vals && name->kind == V_STR) {
                buf_t out = {0};
                val_json(&out, vals);
                say("%s %s", name->text, buf_text(&out));
                free(out.s);
            }
        }
    }
    result_free(&r);
    return run == R_OK ? 0 : EXIT_REFUSED;
}

/* The command whose save and default apply to every setting: its (set, descriptor), or false. */
static bool all_settings(const conn_t *c, uint8_t *set, uint8_t *descriptor) {
    size_t i;
    for (i = 0; i < DEV_ALL_SETTINGS_COUNT; i++) {
        if (mipc_device_supports(c->device, DEV_ALL_SETTINGS[i][0], DEV_ALL_SETTINGS[i][1])) {
            *set = DEV_ALL_SETTINGS[i][0];
            *descriptor = DEV_ALL_SETTINGS[i][1];
            return true;
        }
    }
    return false;
}

int run_all_settings(conn_t *c, const char *function) {
    uint8_t set;
    uint8_t descriptor;
    char values[64];
    result_t r;
    run_t run;
    if (!all_settings(c, &set, &descriptor)) {
        note("%s has no command that saves every setting", describe_model(c->device));
        return EXIT_TROUBLE;
    }
    snprintf(values, sizeof values, "{\"function\":%lld}", (long long)function_value(function));
    run = run_values(c, set, descriptor, NULL, values, &r);
    if (run != R_OK) {
        note("%s", run == R_VALUE ? g_value_error : r.describe);
        result_free(&r);
        return run == R_FAILED ? EXIT_REFUSED : EXIT_TROUBLE;
    }
    result_free(&r);
    return 0;
}

int cmd_save(conn_t *c, const opts_t *o) {
    int status = run_all_settings(c, "save");
    (void)o;
    if (status == 0) {
        say("current settings saved as startup settings");
    }
    return status;
}

int cmd_factory(conn_t *c, const opts_t *o) {
    int status = run_all_settings(c, "default");
    (void)o;
    if (status == 0) {
        say("factory default settings loaded (not saved: save-startup saves them)");
    }
    return status;
}

static void package_name(char *out, size_t cap) {
    const char *dash = strrchr(PROG, '-');
    snprintf(out, cap, "%.*s", (int)(dash ? dash - PROG : (long)strlen(PROG)), PROG);
}

int cmd_dump(conn_t *c, const opts_t *o) {
    buf_t text = {0};
    buf_t flow = {0};
    buf_t b = {0};
    char package[64];
    size_t i;
    size_t written = 0;
    const char *file = o->npos ? o->pos[0] : NULL;
    package_name(package, sizeof package);
    buf_fmt(&text, "# %s settings of a %s (%s), serial ", package, mipc_device_title(c->device),
            c->model->id);
    buf_str(&text, identity_text(c, "serial_number", &b) ? buf_text(&b) : "?");
    buf_str(&text, ", firmware ");
    buf_str(&text, identity_text(c, "firmware", &b) ? buf_text(&b) : "?");
    buf_fmt(&text, "; the manual: %s\n", mipc_device_manual(c->device));
    buf_fmt(&text, "# Schema: %s/settings.schema.json. Units are comments; enum members by name.\n", package);
    buf_fmt(&text, "device: %s\n", c->model->id);
    for (i = 0; i < c->model->setting_count; i++) {
        const dev_setting_t *s = &c->model->settings[i];
        size_t combos = s->keyed_count ? s->key_count : 1;
        size_t k;
        size_t a;
        val_t **entries = (val_t **)xalloc(combos * sizeof *entries);
        bool skipped = false;
        for (k = 0; k < combos; k++) {
            val_t *key = val_new(V_MAP, 0);
            bool nack;
            char msg[600];
            run_t run;
            for (a = 0; a < s->keyed_count; a++) {
                char v[32];
                snprintf(v, sizeof v, "%lld", (long long)s->keys[k * s->keyed_count + a]);
                val_put(key, s->keyed[a], strlen(s->keyed[a]), 0, val_number(V_INT, v, 0));
            }
            run = read_entry(c, s, key, &entries[k], &nack, msg, sizeof msg);
            val_free(key);
            if (run == R_FAILED && nack) {
                note("%s: not read (%s)", s->name, msg);
                skipped = true;
                break;
            }
            if (run != R_OK) {
                note("%s", msg);
                for (a = 0; a < combos; a++) {
                    val_free(entries[a]);
                }
                free(entries);
                free(text.s);
                free(flow.s);
                free(b.s);
                return run == R_FAILED ? EXIT_REFUSED : EXIT_TROUBLE;
            }
        }
        if (!skipped) {
            buf_fmt(&text, "%s:\n", s->name);
            for (k = 0; k < combos; k++) {
                const val_t *e = entries[k];
                for (a = 0; a < e->n; a++) {
                    const char *prefix = s->keyed_count ? (a == 0 ? "  - " : "    ") : "  ";
                    const dev_attr_t *at = attr_of(s, e->keys[a]);
                    buf_fmt(&text, "%s%s: %s", prefix, e->keys[a], flow_text(&flow, e->items[a]));
                    if (at && at->units) {
                        buf_fmt(&text, "  # %s", at->units);
                    }
                    buf_str(&text, "\n");
                }
                if (s->keyed_count && e->n == 0) {
                    buf_str(&text, "  - {}\n");
                }
            }
            written += s->keyed_count ? combos : 1;
        }
        for (k = 0; k < combos; k++) {
            val_free(entries[k]);
        }
        free(entries);
    }
    if (file == NULL || strcmp(file, "-") == 0) {
        fwrite(buf_text(&text), 1, text.n, stdout);
        fflush(stdout);
    } else {
        FILE *out = fopen(file, "w");
        if (out == NULL || fwrite(buf_text(&text), 1, text.n, out) != text.n || fclose(out) != 0) {
            note("cannot write %s: %s", file, strerror(errno));
            free(text.s);
            free(flow.s);
            free(b.s);
            return EXIT_TROUBLE;
        }
        note("%zu settings written to %s", written, file);
    }
    free(text.s);
    free(flow.s);
    free(b.s);
    return 0;
}
