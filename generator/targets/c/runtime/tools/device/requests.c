/* The subcommands ping, info, send, save-startup, factory-reset and settings dump. */
#include "device.h"

int cmd_ping(conn_t *c, const opts_t *o) {
    result_t r;
    double t0 = now_s();
    double ms;
    run_t run;
    buf_t serial = {0};
    const char *sn;
    (void)o;
    if (!CODEC_LINK_HAS_PING) {
        note("the spec has no ping command");
        return EXIT_TROUBLE;
    }
    run = run_values(c, CODEC_LINK_PING_SET, CODEC_LINK_PING_DESCRIPTOR, NULL, "{}", &r);
    ms = (now_s() - t0) * 1000;
    if (run != R_OK) {
        note("%s", r.describe);
        result_free(&r);
        return run == R_LOST ? EXIT_TROUBLE : EXIT_REFUSED;
    }
    result_free(&r);
    sn = identity_text(c, "serial_number", &serial);
    if (sn && sn[0]) {
        say("%s %s answered in %.0f ms", codec_device_title(c->device), sn, ms);
    } else {
        say("%s answered in %.0f ms", codec_device_title(c->device), ms);
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
    say("model: %s (%s, manual %s)", name && name[0] ? name : codec_device_title(c->device), c->model->id,
        codec_device_manual(c->device));
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
        const codec_field_info_t *reply;
        codec_status_t why;
        run_t run;
        if (!codec_device_supports(c->device, DEV_LISTS[i].cmd_set, DEV_LISTS[i].cmd_descriptor)) {
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
        reply = codec_find_field(DEV_LISTS[i].cmd_set, DEV_LISTS[i].reply_descriptor, &why);
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

static bool layout_for(const codec_field_info_t *f, codec_device_t device) {
    size_t i;
    if (f->layout_count <= 1) {
        return true;
    }
    for (i = 0; i < f->layout_count; i++) {
        const codec_layout_info_t *l = codec_layout_info((codec_field_id_t)(f->first_layout + i));
        if (l && (l->device_id == device || l->device_id == CODEC_DEVICE_ANY)) {
            return true;
        }
    }
    return false;
}

/* Whether the command's layout has a function selector: probes the JSON reader. */
static bool has_function(const conn_t *c, uint8_t set, const codec_field_info_t *f) {
    buf_t line = {0};
    codec_field_value_t command;
    char msg[CODEC_ERROR_MESSAGE_MAX + 200];
    bool yes;
    buf_fmt(&line, "{\"offset\":0,\"set\":%u,\"fields\":[{\"descriptor\":%u,\"name\":", set, f->descriptor);
    json_string(&line, f->name, strlen(f->name));
    if (f->layout_count > 1) {
        buf_fmt(&line, ",\"device\":\"%s\"", codec_device_id(c->device));
    }
    buf_str(&line, ",\"values\":{\"function\":1}}]}");
    msg[0] = '\0';
    yes = codec_json_command_line(buf_text(&line), line.n, &command, msg, sizeof msg) == CODEC_OK ||
          strstr(msg, "unknown key \"function\"") == NULL;
    free(line.s);
    return yes;
}

int cmd_send(conn_t *c, const opts_t *o) {
    uint8_t set = 0;
    const codec_field_info_t *f;
    buf_t values = {0};
    size_t i = 1;
    result_t r;
    run_t run;
    const val_t *reply;
    bool first = true;
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
    buf_str(&values, "{");
    if (has_function(c, set, f)) {
        int64_t fn;
        if (o->npos < 2 || strchr(o->pos[1], '=') != NULL) {
            buf_t names = {0};
            size_t k;
            for (k = 0; k < DEV_FUNCTION_COUNT; k++) {
                buf_fmt(&names, "%s%s", k ? ", " : "", DEV_FUNCTIONS[k].name);
            }
            note("%s: give the function first (%s)", f->name, buf_text(&names));
            free(names.s);
            free(values.s);
            return EXIT_TROUBLE;
        }
        fn = function_value(o->pos[1]);
        if (fn < 0) {
            buf_t names = {0};
            size_t k;
            for (k = 0; k < DEV_FUNCTION_COUNT; k++) {
                buf_fmt(&names, "%s%s", k ? ", " : "", DEV_FUNCTIONS[k].name);
            }
            note("unknown function (one of: %s)", buf_text(&names));
            free(names.s);
            free(values.s);
            return EXIT_TROUBLE;
        }
        buf_fmt(&values, "\"function\":%lld", (long long)fn);
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
            free(values.s);
            return EXIT_TROUBLE;
        }
        if (!first) {
            buf_str(&values, ",");
        }
        first = false;
        json_string(&values, arg, (size_t)(eq - arg));
        buf_str(&values, ":");
        v = parse_value(eq + 1);
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
                    buf_fmt(&values, "%lld", (long long)DEV_ENUMS[e].members[k].value);
                    found = true;
                }
            }
            if (!found) {
                note("%s.%.*s: '%s' is not a member of %s", f->name, (int)(eq - arg), arg, v->text,
                     DEV_ENUMS[e].name);
                val_free(v);
                free(values.s);
                return EXIT_TROUBLE;
            }
        } else {
            val_json(&values, v);
        }
        val_free(v);
    }
    buf_str(&values, "}");
    run = run_values(c, set, f->descriptor, NULL, buf_text(&values), &r);
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
    if (r.kind == CODEC_RESULT_REFUSED) {
        note("%s", r.describe);
        result_free(&r);
        return EXIT_TROUBLE;
    }
    if (o->json) {
        say("%s", r.json);
    } else {
        if (run == R_OK) {
            say("%s: %s", f->name, codec_result_kind_name(r.kind));
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
        if (codec_device_supports(c->device, DEV_ALL_SETTINGS[i][0], DEV_ALL_SETTINGS[i][1])) {
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
    buf_fmt(&text, "# %s settings of a %s (%s), serial ", package, codec_device_title(c->device),
            c->model->id);
    buf_str(&text, identity_text(c, "serial_number", &b) ? buf_text(&b) : "?");
    buf_str(&text, ", firmware ");
    buf_str(&text, identity_text(c, "firmware", &b) ? buf_text(&b) : "?");
    buf_fmt(&text, "; the manual: %s\n", codec_device_manual(c->device));
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
