/* Settings files against the device: the file validated into a plan, settings diff and settings
 * apply. */
#include "device.h"

static void problem(plan_t *p, const char *fmt, ...) {
    char text[1200];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(text, sizeof text, fmt, ap);
    va_end(ap);
    if (p->problem_count < MAX_PROBLEMS) {
        p->problems = (char **)xrealloc(p->problems, (p->problem_count + 1) * sizeof *p->problems);
        p->problems[p->problem_count++] = xstrndup(text, strlen(text));
    }
}

static void plan_free(plan_t *p) {
    size_t i;
    size_t k;
    for (i = 0; i < p->count; i++) {
        for (k = 0; k < p->items[i].count; k++) {
            val_free(p->items[i].entries[k]);
        }
        free(p->items[i].entries);
        free(p->items[i].lines);
    }
    free(p->items);
    for (i = 0; i < p->problem_count; i++) {
        free(p->problems[i]);
    }
    free(p->problems);
}

static const dev_setting_t *setting_named(const dev_model_t *m, const char *name) {
    size_t i;
    for (i = 0; i < m->setting_count; i++) {
        if (strcmp(m->settings[i].name, name) == 0) {
            return &m->settings[i];
        }
    }
    return NULL;
}

/* The line of the parameter a message names ("name.attr: ..."), else def. */
static int line_of(const val_t *entry, const char *message, int def) {
    size_t i;
    for (i = 0; entry->kind == V_MAP && i < entry->n; i++) {
        const char *k = entry->keys[i];
        const char *at = strstr(message, k);
        while (at != NULL) {
            char before = at == message ? ' ' : at[-1];
            char after = at[strlen(k)];
            if ((before == '.' || before == ' ' || before == '\'' || before == '"') &&
                (after == ':' || after == '.' || after == '[' || after == ' ' || after == '\'' ||
                 after == '"' || after == '\0')) {
                return entry->key_lines[i];
            }
            at = strstr(at + 1, k);
        }
    }
    return def;
}

static void validate(conn_t *c, const val_t *doc, const char *filename, plan_t *plan) {
    size_t i;
    const char *manual = describe_model(c->device);
    char manual_copy[200];
    copy_text(manual_copy, sizeof manual_copy, manual);
    for (i = 0; i < doc->n; i++) {
        const char *name = doc->keys[i];
        const val_t *value = doc->items[i];
        int line = doc->key_lines[i];
        const dev_setting_t *s;
        size_t k;
        size_t count;
        planned_t planned;
        if (strcmp(name, "device") == 0) {
            if (value->kind != V_STR || strcmp(value->text, c->model->id) != 0) {
                buf_t t = {0};
                py_str(&t, value);
                problem(plan, "%s:%d: the file is for '%s', the connected model is %s (%s)", filename, line,
                        buf_text(&t), c->model->id, manual_copy);
                free(t.s);
            }
            continue;
        }
        s = setting_named(c->model, name);
        if (s == NULL) {
            buf_t others = {0};
            size_t m;
            for (m = 0; m < DEV_MODEL_COUNT; m++) {
                if (setting_named(&DEV_MODELS[m], name)) {
                    buf_fmt(&others, "%s%s", others.n ? ", " : "", DEV_MODELS[m].id);
                }
            }
            if (others.n) {
                problem(plan, "%s:%d: %s is not supported by %s (a setting of %s)", filename, line, name,
                        manual_copy, buf_text(&others));
            } else {
                problem(plan, "%s:%d: unknown setting '%s' (not a setting of the spec's commands)", filename,
                        line, name);
            }
            free(others.s);
            continue;
        }
        if (!codec_device_supports(c->device, s->set, s->descriptor)) {
            problem(plan, "%s:%d: %s is not supported by %s", filename, line, s->name, manual_copy);
            continue;
        }
        if (s->keyed_count && value->kind != V_LIST) {
            buf_t keys = {0};
            for (k = 0; k < s->keyed_count; k++) {
                buf_fmt(&keys, "%s%s", k ? ", " : "", s->keyed[k]);
            }
            problem(plan, "%s:%d: %s is read per %s: expected a list of entries", filename, line, name,
                    buf_text(&keys));
            free(keys.s);
            continue;
        }
        count = s->keyed_count ? value->n : 1;
        memset(&planned, 0, sizeof planned);
        planned.setting = s;
        planned.entries = (val_t **)xalloc((count ? count : 1) * sizeof *planned.entries);
        planned.lines = (int *)xalloc((count ? count : 1) * sizeof *planned.lines);
        for (k = 0; k < count; k++) {
            const val_t *entry = s->keyed_count ? value->items[k] : value;
            int eline = s->keyed_count ? (entry->line ? entry->line : line) : line;
            size_t a;
            bool bad = false;
            buf_t missing = {0};
            val_t *norm;
            char err[1000];
            size_t j;
            if (entry->kind != V_MAP) {
                problem(plan, "%s:%d: %s: expected a mapping of parameter names to values", filename, eline,
                        name);
                continue;
            }
            for (a = 0; a < entry->n; a++) {
                if (attr_of(s, entry->keys[a]) == NULL) {
                    buf_t allowed = {0};
                    size_t m;
                    for (m = 0; m < s->attr_count; m++) {
                        buf_fmt(&allowed, "%s%s", m ? ", " : "", s->attrs[m].name);
                    }
                    problem(plan, "%s:%d: %s: unknown parameter '%s' (expected: %s)", filename,
                            entry->key_lines[a], name, entry->keys[a], buf_text(&allowed));
                    free(allowed.s);
                    bad = true;
                }
            }
            for (a = 0; a < s->attr_count; a++) {
                if (val_get(entry, s->attrs[a].name) == NULL) {
                    buf_fmt(&missing, "%s%s", missing.n ? ", " : "", s->attrs[a].name);
                }
            }
            if (missing.n) {
                problem(plan, "%s:%d: %s: missing %s", filename, eline, name, buf_text(&missing));
                bad = true;
            }
            free(missing.s);
            if (bad) {
                continue;
            }
            norm = normalized(c, s, entry, err, sizeof err);
            if (norm == NULL) {
                problem(plan, "%s:%d: %s (%s)", filename, line_of(entry, err, eline), err, manual_copy);
                continue;
            }
            if (s->keyed_count) {
                bool twice = false;
                for (j = 0; j < planned.count; j++) {
                    size_t m;
                    bool same = true;
                    for (m = 0; m < s->keyed_count; m++) {
                        same = same && val_equal(val_get(planned.entries[j], s->keyed[m]),
                                                 val_get(norm, s->keyed[m]));
                    }
                    if (same) {
                        buf_t t = {0};
                        key_text(&t, s, norm);
                        problem(plan, "%s:%d: %s: the entry for %s is given twice (first on line %d)",
                                filename, eline, name, buf_text(&t), planned.lines[j]);
                        free(t.s);
                        twice = true;
                        break;
                    }
                }
                if (twice) {
                    val_free(norm);
                    continue;
                }
            }
            planned.entries[planned.count] = norm;
            planned.lines[planned.count] = eline;
            planned.count++;
        }
        plan->items = (planned_t *)xrealloc(plan->items, (plan->count + 1) * sizeof *plan->items);
        plan->items[plan->count++] = planned;
    }
}

/* Reads and checks FILE: 0 with the plan, or 2 (every problem printed). */
static int load_plan(conn_t *c, const char *path, plan_t *plan) {
    buf_t text = {0};
    FILE *in;
    char chunk[4096];
    size_t n;
    char msg[600];
    val_t *doc;
    size_t i;
    memset(plan, 0, sizeof *plan);
    in = strcmp(path, "-") == 0 ? stdin : fopen(path, "rb");
    if (in == NULL) {
        note("cannot read %s: %s", path, strerror(errno));
        return EXIT_TROUBLE;
    }
    while ((n = fread(chunk, 1, sizeof chunk, in)) > 0) {
        buf_add(&text, chunk, n);
    }
    if (ferror(in)) {
        note("cannot read %s: %s", path, strerror(errno));
        if (in != stdin) {
            fclose(in);
        }
        free(text.s);
        return EXIT_TROUBLE;
    }
    if (in != stdin) {
        fclose(in);
    }
    doc = yaml_load(buf_text(&text), text.n, path, msg, sizeof msg);
    free(text.s);
    if (doc == NULL) {
        fprintf(stderr, "%s\n", msg);
        note("1 problem(s) in the settings file; nothing was written");
        return EXIT_TROUBLE;
    }
    validate(c, doc, path, plan);
    val_free(doc);
    if (plan->problem_count) {
        for (i = 0; i < plan->problem_count; i++) {
            fprintf(stderr, "%s\n", plan->problems[i]);
        }
        note("%zu problem(s) in the settings file; nothing was written", plan->problem_count);
        plan_free(plan);
        return EXIT_TROUBLE;
    }
    return 0;
}

/* The file's entries that differ from what the device reads now: 0, or the exit status. */
static int differences(conn_t *c, const plan_t *plan, change_t **out, size_t *count, bool diff) {
    size_t i;
    size_t k;
    *out = NULL;
    *count = 0;
    for (i = 0; i < plan->count; i++) {
        const planned_t *p = &plan->items[i];
        for (k = 0; k < p->count; k++) {
            const val_t *entry = p->entries[k];
            val_t *key = val_new(V_MAP, 0);
            val_t *current = NULL;
            val_t *norm;
            bool nack;
            char msg[1000];
            size_t a;
            run_t run;
            bool same;
            for (a = 0; a < p->setting->keyed_count; a++) {
                const val_t *v = val_get(entry, p->setting->keyed[a]);
                val_put(key, p->setting->keyed[a], strlen(p->setting->keyed[a]), 0, val_copy(v));
            }
            run = read_entry(c, p->setting, key, &current, &nack, msg, sizeof msg);
            val_free(key);
            if (run != R_OK && diff) { /* trouble, not a difference (exit 2, as diff(1)) */
                note("cannot read the device: %s", msg);
                return EXIT_TROUBLE;
            }
            if (run != R_OK) {
                note("%s", msg);
                return run == R_FAILED ? EXIT_REFUSED : EXIT_TROUBLE;
            }
            norm = normalized(c, p->setting, current, msg, sizeof msg);
            val_free(current);
            if (norm == NULL) {
                note("%s", msg);
                return EXIT_TROUBLE;
            }
            same = val_equal(norm, entry);
            if (same) {
                val_free(norm);
                continue;
            }
            *out = (change_t *)xrealloc(*out, (*count + 1) * sizeof **out);
            (*out)[*count].setting = p->setting;
            {
                buf_t t = {0};
                key_text(&t, p->setting, entry);
                copy_text((*out)[*count].key, sizeof(*out)[*count].key, buf_text(&t));
                free(t.s);
            }
            (*out)[*count].device = norm;
            (*out)[*count].file = entry;
            (*count)++;
        }
    }
    return 0;
}

static void changes_free(change_t *changes, size_t count) {
    size_t i;
    for (i = 0; i < count; i++) {
        val_free(changes[i].device);
    }
    free(changes);
}

static void what_of(const change_t *ch, char *what, size_t cap) {
    if (ch->key[0]) {
        snprintf(what, cap, "%s (%s)", ch->setting->name, ch->key);
    } else {
        copy_text(what, cap, ch->setting->name);
    }
}

int cmd_diff(conn_t *c, const opts_t *o) {
    plan_t plan;
    change_t *changes;
    size_t count;
    size_t i;
    size_t a;
    int status;
    buf_t x = {0};
    buf_t y = {0};
    if (o->npos < 1) {
        note("settings diff: give the FILE");
        return EXIT_TROUBLE;
    }
    status = load_plan(c, o->pos[0], &plan);
    if (status) {
        return status;
    }
    status = differences(c, &plan, &changes, &count, true);
    if (status == 0) {
        for (i = 0; i < count; i++) {
            char what[400];
            what_of(&changes[i], what, sizeof what);
            for (a = 0; a < changes[i].file->n; a++) {
                const val_t *before = val_get(changes[i].device, changes[i].file->keys[a]);
                const val_t *v = changes[i].file->items[a];
                if (!val_equal(before, v)) {
                    say("%s.%s: device %s, file %s", what, changes[i].file->keys[a], flow_text(&x, before),
                        flow_text(&y, v));
                }
            }
        }
        status = count ? EXIT_REFUSED : 0;
        changes_free(changes, count);
    }
    free(x.s);
    free(y.s);
    plan_free(&plan);
    return status;
}

static bool is_baud_setting(const dev_setting_t *s) {
    return baud_param(s) != NULL;
}

/* The budget check of apply: the message formats the file sets, over the device's others, against
 * the file's baud rate (else the link's): 0, or the exit status. */
static int apply_budget(conn_t *c, const opts_t *o, const plan_t *plan) {
    size_t i;
    size_t k;
    bool touched = false;
    formats_t *formats = (formats_t *)xalloc(sizeof *formats);
    int status = read_formats(c, formats);
    for (i = 0; status == 0 && i < plan->count; i++) {
        const dev_format_t *spec = format_of(plan->items[i].setting);
        for (k = 0; spec && k < plan->items[i].count; k++) {
            const val_t *entry = plan->items[i].entries[k];
            int set = spec->set;
            if (set < 0) {
                const val_t *v = val_get(entry, spec->set_param);
                set = v && v->kind == V_INT ? atoi(v->text) : -1;
            }
            if (set >= 0 && set < 256) {
                formats_from_list(&formats->set[set], val_get(entry, spec->list), spec);
                touched = true;
            }
        }
    }
    if (status == 0 && touched) {
        double base[256] = {0};
        char where[300] = "";
        unsigned long baud = 0;
        buf_t lines = {0};
        for (i = 0; i < plan->count; i++) { /* the file's baud rate */
            const char *param = baud_param(plan->items[i].setting);
            const val_t *v;
            if (param == NULL || plan->items[i].setting->keyed_count || plan->items[i].count == 0) {
                continue;
            }
            v = val_get(plan->items[i].entries[0], param);
            if (v && v->kind == V_INT) {
                baud = strtoul(v->text, NULL, 10);
                snprintf(where, sizeof where, " (the file's %s)", plan->items[i].setting->name);
                break;
            }
        }
        if (i == plan->count) {
            baud = link_baud(c, o->baud, where, sizeof where);
        }
        status = read_base_rates(c, base);
        if (status == 0) {
            status = check_budget(c, formats, base, baud, where, o->force, &lines);
        }
        free(lines.s);
    }
    free(formats);
    return status;
}

/* After a baud rate setting is written: the port follows it (after the link's settle time). */
static void follow_baud(conn_t *c, const change_t *ch) {
    const val_t *v = val_get(ch->file, baud_param(ch->setting));
    if (v && v->kind == V_INT) {
        unsigned long rate = strtoul(v->text, NULL, 10);
        if (CODEC_LINK_BAUD_SETTLE_MS > 0) {
            struct timespec ts = {CODEC_LINK_BAUD_SETTLE_MS / 1000,
                                  (long)(CODEC_LINK_BAUD_SETTLE_MS % 1000) * 1000000L};
            nanosleep(&ts, NULL);
        }
        c->port.set_baud(c->port.ctx, (uint32_t)rate);
        c->baud = rate;
    }
}

/* The line of a change written and read back: "what: param: before -> after; ...". */
static void say_written(const change_t *ch, const char *what) {
    buf_t line = {0};
    buf_t x = {0};
    buf_t y = {0};
    size_t a;
    for (a = 0; a < ch->file->n; a++) {
        const val_t *before = val_get(ch->device, ch->file->keys[a]);
        const val_t *v = ch->file->items[a];
        if (!val_equal(before, v)) {
            buf_fmt(&line, "%s%s: %s -> %s", line.n ? "; " : "", ch->file->keys[a], flow_text(&x, before),
                    flow_text(&y, v));
        }
    }
    say("%s: %s", what, buf_text(&line));
    free(line.s);
    free(x.s);
    free(y.s);
}

/* Writes one change and reads it back: 0 (*written counted), or EXIT_REFUSED (the note printed). */
static int apply_change(conn_t *c, const change_t *ch, size_t *written, size_t count) {
    const dev_setting_t *s = ch->setting;
    char what[400];
    char msg[1000];
    buf_t values = {0};
    result_t r;
    run_t run;
    val_t *key = val_new(V_MAP, 0);
    val_t *back = NULL;
    val_t *back_norm = NULL;
    bool nack;
    size_t a;
    int status = EXIT_REFUSED;
    what_of(ch, what, sizeof what);
    for (a = 0; a < s->keyed_count; a++) {
        val_put(key, s->keyed[a], strlen(s->keyed[a]), 0, val_copy(val_get(ch->file, s->keyed[a])));
    }
    command_values(s, ch->file, function_value("write"), &values, msg, sizeof msg);
    run = run_values(c, s->set, s->descriptor, s->device, buf_text(&values), &r);
    free(values.s);
    if (run == R_OK && is_baud_setting(s) && c->baud && c->port.set_baud) {
        follow_baud(c, ch);
    }
    if (run != R_OK) {
        note("%s: %s (%zu of %zu settings written before it)", what,
             run == R_VALUE ? g_value_error : r.describe, *written, count);
    } else if (read_entry(c, s, key, &back, &nack, msg, sizeof msg) != R_OK) {
        note("%s: %s (%zu of %zu settings written before it)", what, msg, *written, count);
    } else if ((back_norm = normalized(c, s, back, msg, sizeof msg)) == NULL) {
        note("%s: %s (%zu of %zu settings written before it)", what, msg, *written, count);
    } else {
        (*written)++;
        if (!val_equal(back_norm, ch->file)) {
            buf_t t = {0};
            val_json(&t, back_norm);
            note("%s: written, but it reads back as %s (%zu of %zu written)", what, buf_text(&t), *written,
                 count);
            free(t.s);
        } else {
            say_written(ch, what);
            status = 0;
        }
    }
    if (run != R_VALUE) {
        result_free(&r);
    }
    val_free(key);
    val_free(back);
    val_free(back_norm);
    return status;
}

/* The changes in the order they are written: a baud rate change last, since the link follows it
 * (a stable order otherwise); frees changes. */
static change_t *baud_last(change_t *changes, size_t count) {
    change_t *ordered = (change_t *)xalloc((count ? count : 1) * sizeof *ordered);
    size_t n = 0;
    size_t i;
    for (i = 0; i < count; i++) {
        if (!is_baud_setting(changes[i].setting)) {
            ordered[n++] = changes[i];
        }
    }
    for (i = 0; i < count; i++) {
        if (is_baud_setting(changes[i].setting)) {
            ordered[n++] = changes[i];
        }
    }
    free(changes);
    return ordered;
}

int cmd_apply(conn_t *c, const opts_t *o) {
    plan_t plan;
    change_t *changes = NULL;
    size_t count = 0;
    size_t i;
    int status;
    size_t written = 0;
    if (o->npos < 1) {
        note("settings apply: give the FILE");
        return EXIT_TROUBLE;
    }
    status = load_plan(c, o->pos[0], &plan);
    if (status) {
        return status;
    }
    status = apply_budget(c, o, &plan);
    if (status == 0) {
        status = differences(c, &plan, &changes, &count, false);
    }
    if (status == 0) {
        changes = baud_last(changes, count);
        if (count == 0) {
            say("nothing to write: the device matches the file");
        }
        for (i = 0; i < count && status == 0; i++) {
            status = apply_change(c, &changes[i], &written, count);
        }
        if (status == 0 && count) {
            say("%zu settings written and read back", written);
        }
        if (status == 0 && o->save) {
            status = run_all_settings(c, "save");
            if (status == 0) {
                say("saved as startup settings");
            }
        }
        changes_free(changes, count);
    }
    plan_free(&plan);
    return status;
}
