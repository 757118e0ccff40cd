/* Settings: the command values of an entry, reading one entry from the device, and an entry
 * normalized through the command's encoding. Generated: do not edit. */
#include "device.h"

const dev_format_t *format_of(const dev_setting_t *s) {
    size_t i;
    for (i = 0; i < DEV_FORMAT_COUNT; i++) {
        if (DEV_FORMATS[i].cmd_set == s->set && DEV_FORMATS[i].cmd_descriptor == s->descriptor) {
            return &DEV_FORMATS[i];
        }
    }
    return NULL;
}

const char *baud_param(const dev_setting_t *s) {
    size_t i;
    for (i = 0; i < DEV_BAUD_COUNT; i++) {
        if (DEV_BAUD[i].cmd_set == s->set && DEV_BAUD[i].cmd_descriptor == s->descriptor) {
            return DEV_BAUD[i].param;
        }
    }
    return NULL;
}

bool is_keyed(const dev_setting_t *s, const char *attr) {
    size_t i;
    for (i = 0; i < s->keyed_count; i++) {
        if (strcmp(s->keyed[i], attr) == 0) {
            return true;
        }
    }
    return false;
}

const dev_attr_t *attr_of(const dev_setting_t *s, const char *name) {
    size_t i;
    for (i = 0; i < s->attr_count; i++) {
        if (strcmp(s->attrs[i].name, name) == 0) {
            return &s->attrs[i];
        }
    }
    return NULL;
}

/* The file entry of a read reply: the write's parameters, enum members by name. */
static val_t *entry_of_reply(const dev_setting_t *s, const val_t *values) {
    val_t *out = val_new(V_MAP, 0);
    size_t i;
    for (i = 0; i < s->attr_count; i++) {
        const val_t *v = val_get(values, s->attrs[i].reply);
        val_t *copy = v ? val_copy(v) : val_new(V_NULL, 0);
        if (copy->kind == V_INT && s->attrs[i].enum_index >= 0) {
            const char *m = enum_member(s->attrs[i].enum_index, strtoll(copy->text, NULL, 10));
            if (m != NULL) {
                val_t *named = val_str(m, strlen(m), 0);
                val_free(copy);
                copy = named;
            }
        }
        val_put(out, s->attrs[i].name, strlen(s->attrs[i].name), 0, copy);
    }
    return out;
}

/* Python's str() of a key value in messages ("desc_set 128", "enable True"). */
void py_str(buf_t *b, const val_t *v) {
    if (v == NULL || v->kind == V_NULL) {
        buf_str(b, "None");
    } else if (v->kind == V_BOOL) {
        buf_str(b, v->b ? "True" : "False");
    } else if (v->kind == V_STR) {
        buf_add(b, v->text, v->len);
    } else if (v->kind == V_INT || v->kind == V_NUM) {
        buf_str(b, v->text);
    } else {
        val_json(b, v);
    }
}

void key_text(buf_t *b, const dev_setting_t *s, const val_t *entry) {
    size_t i;
    buf_reset(b);
    for (i = 0; i < s->keyed_count; i++) {
        buf_fmt(b, "%s%s ", i ? ", " : "", s->keyed[i]);
        py_str(b, val_get(entry, s->keyed[i]));
    }
}

/* Whether a equals b ignoring ASCII case (an enum member given in any case, as value.upper()). */
bool strcasecmp_ascii_eq(const char *a, const char *b) {
    for (; *a && *b; a++, b++) {
        char x = (*a >= 'a' && *a <= 'z') ? (char)(*a - 32) : *a;
        char y = (*b >= 'a' && *b <= 'z') ? (char)(*b - 32) : *b;
        if (x != y) {
            return false;
        }
    }
    return *a == *b;
}

/* The JSON values of the command that writes an entry (function write) or reads it (read: its key
 * parameters only). false with the reason in err. */
bool command_values(const dev_setting_t *s, const val_t *entry, int64_t function, buf_t *out, char *err,
                    size_t cap) {
    size_t i;
    bool write = function == function_value("write");
    buf_reset(out);
    buf_fmt(out, "{\"function\":%lld", (long long)function);
    for (i = 0; i < (write ? s->attr_count : s->keyed_count); i++) {
        const char *attr = write ? s->attrs[i].name : s->keyed[i];
        const dev_attr_t *a = attr_of(s, attr);
        const val_t *v = val_get(entry, attr);
        if (v == NULL) {
            snprintf(err, cap, "%s: missing parameter '%s'", s->name, attr);
            return false;
        }
        buf_str(out, ",");
        json_string(out, attr, strlen(attr));
        buf_str(out, ":");
        if (a != NULL && a->enum_index >= 0 && v->kind == V_STR) {
            const dev_enum_t *e = &DEV_ENUMS[a->enum_index];
            size_t k;
            bool found = false;
            for (k = 0; k < e->count; k++) {
                if (strcmp(e->members[k].name, v->text) == 0 ||
                    strcasecmp_ascii_eq(e->members[k].name, v->text)) {
                    buf_fmt(out, "%lld", (long long)e->members[k].value);
                    found = true;
                    break;
                }
            }
            if (!found) {
                buf_t names = {0};
                for (k = 0; k < e->count; k++) {
                    buf_fmt(&names, "%s%s", k ? ", " : "", e->members[k].name);
                }
                snprintf(err, cap, "%s.%s: '%s' is not a member of %s (one of: %s)", s->name, attr, v->text,
                         e->name, buf_text(&names));
                free(names.s);
                return false;
            }
        } else {
            val_json(out, v);
        }
    }
    if (write) {
        for (i = 0; i < s->fill_count; i++) {
            buf_str(out, ",");
            json_string(out, s->fill[i], strlen(s->fill[i]));
            buf_str(out, s->fill_list[i] ? ":[]" : ":0");
        }
        for (i = 0; i < s->count_count; i++) {
            const val_t *lst = val_get(entry, s->counts[2 * i + 1]);
            buf_str(out, ",");
            json_string(out, s->counts[2 * i], strlen(s->counts[2 * i]));
            buf_fmt(out, ":%zu", lst && lst->kind == V_LIST ? lst->n : (size_t)0);
        }
    }
    buf_str(out, "}");
    return true;
}

/* Reads one setting for one key (a map of its key parameters): R_OK with *entry, R_FAILED with
 * the result's description in msg (a NACK: *nack), R_VALUE, R_LOST. */
run_t read_entry(conn_t *c, const dev_setting_t *s, const val_t *key, val_t **entry, bool *nack, char *msg,
                 size_t cap) {
    buf_t values = {0};
    result_t r;
    run_t run;
    const val_t *reply;
    *entry = NULL;
    *nack = false;
    if (!command_values(s, key, function_value("read"), &values, msg, cap)) {
        free(values.s);
        return R_VALUE;
    }
    run = run_values(c, s->set, s->descriptor, s->device, buf_text(&values), &r);
    free(values.s);
    if (run == R_VALUE) {
        copy_text(msg, cap, g_value_error);
        return run;
    }
    if (run != R_OK) {
        *nack = r.kind == MIPC_RESULT_NACK;
        copy_text(msg, cap, r.describe);
        result_free(&r);
        return run;
    }
    reply = reply_values(&r, s->reply);
    if (reply == NULL) {
        snprintf(msg, cap, "%s: the read's reply carries no %s", s->name, s->reply);
        result_free(&r);
        return R_VALUE;
    }
    *entry = entry_of_reply(s, reply);
    result_free(&r);
    return R_OK;
}

/* The value at a parameter path of the reader's messages ("bias", "descriptors[0].decimation"). */
static const val_t *value_at(const val_t *v, const char *path, size_t n) {
    size_t i = 0;
    while (v != NULL && i < n) {
        size_t start = i;
        char name[128];
        while (i < n && path[i] != '.' && path[i] != '[') {
            i++;
        }
        if (i > start) {
            if (i - start >= sizeof name) {
                return NULL;
            }
            memcpy(name, path + start, i - start);
            name[i - start] = '\0';
            v = val_get(v, name);
        }
        while (v != NULL && i < n && path[i] == '[') {
            size_t k = strtoul(path + i + 1, NULL, 10);
            v = v->kind == V_LIST && k < v->n ? v->items[k] : NULL;
            while (i < n && path[i] != ']') {
                i++;
            }
            i++;
        }
        if (i < n && path[i] == '.') {
            i++;
        }
    }
    return v;
}

/* An integer out of its type's range, from the reader's "PATH: expected an integer in LO..HI": in
 * err as "SETTING: PATH: VALUE is out of range for TYPE (LO..HI)". false for any other message. */
static bool out_of_range(const dev_setting_t *s, const val_t *entry, const char *msg, char *err, size_t cap) {
    static const char *const k_types[][2] = {{"0..255", "u8"},
                                             {"0..65535", "u16"},
                                             {"0..4294967295", "u32"},
                                             {"0..18446744073709551615", "u64"},
                                             {"-128..127", "s8"},
                                             {"-32768..32767", "s16"},
                                             {"-2147483648..2147483647", "s32"},
                                             {"-9223372036854775808..9223372036854775807", "s64"}};
    const char *tail = strstr(msg, ": expected an integer in ");
    const char *range;
    const val_t *v;
    size_t i;
    if (tail == NULL) {
        return false;
    }
    range = tail + strlen(": expected an integer in ");
    v = value_at(entry, msg, (size_t)(tail - msg));
    if (v == NULL || v->kind != V_INT) {
        return false;
    }
    for (i = 0; i < sizeof k_types / sizeof k_types[0]; i++) {
        if (strcmp(range, k_types[i][0]) == 0) {
            snprintf(err, cap, "%s: %.*s: %s is out of range for %s (%s)", s->name, (int)(tail - msg), msg,
                     v->text, k_types[i][1], range);
            return true;
        }
    }
    return false;
}

/* An entry as the device would report it: through the command's encoding (f32 rounding, enum
 * names), so that a file and a device compare equal when the wire values are. NULL with err. */
val_t *normalized(conn_t *c, const dev_setting_t *s, const val_t *entry, char *err, size_t cap) {
    buf_t values = {0};
    buf_t line = {0};
    uint8_t packet[MIPC_MAX_PACKET];
    size_t len = 0;
    char msg[MIPC_ERROR_MESSAGE_MAX + 200];
    size_t n;
    val_t *parsed;
    const val_t *fields;
    const val_t *got;
    val_t *out;
    size_t i;
    const mipc_field_info_t *f;
    mipc_status_t why;
    mipc_field_value_t command;
    if (!command_values(s, entry, function_value("write"), &values, err, cap)) {
        free(values.s);
        return NULL;
    }
    f = mipc_find_field(s->set, s->descriptor, &why);
    buf_fmt(&line, "{\"offset\":0,\"set\":%u,\"fields\":[{\"descriptor\":%u,\"name\":", s->set,
            s->descriptor);
    json_string(&line, s->name, strlen(s->name));
    if (f != NULL && f->layout_count > 1) {
        const char *dev = s->device ? s->device : mipc_device_id(c->device);
        buf_str(&line, ",\"device\":");
        json_string(&line, dev, strlen(dev));
    }
    buf_fmt(&line, ",\"values\":%s}]}", buf_text(&values));
    free(values.s);
    if (mipc_json_command_line(buf_text(&line), line.n, &command, msg, sizeof msg) != MIPC_OK ||
        mipc_json_encode_line(buf_text(&line), line.n, packet, sizeof packet, &len, msg, sizeof msg) !=
            MIPC_OK) {
        /* the reader names the parameter by its place in the line: fields[0].values.NAME */
        const char *at = strstr(msg, "fields[0].values.");
        if (at != NULL && out_of_range(s, entry, at + strlen("fields[0].values."), err, cap)) {
            /* said as the Python CLI says it */
        } else if (at != NULL) {
            snprintf(err, cap, "%s.%s", s->name, at + strlen("fields[0].values."));
        } else if (strncmp(msg, s->name, strlen(s->name)) == 0) {
            copy_text(err, cap, msg);
        } else {
            snprintf(err, cap, "%s: %s", s->name, msg);
        }
        free(line.s);
        return NULL;
    }
    free(line.s);
    n = mipc_json_packet_line(packet, len, 0, c->device, g_line, sizeof g_line);
    parsed = json_parse(g_line, n < sizeof g_line ? n : sizeof g_line - 1);
    fields = val_get(parsed, "fields");
    got = fields && fields->kind == V_LIST && fields->n ? val_get(fields->items[0], "values") : NULL;
    if (got == NULL) {
        const val_t *e = fields && fields->n ? val_get(fields->items[0], "error") : NULL;
        snprintf(err, cap, "%s: %s", s->name, e && e->kind == V_STR ? e->text : "does not encode");
        val_free(parsed);
        return NULL;
    }
    out = val_new(V_MAP, 0);
    for (i = 0; i < s->attr_count; i++) {
        const val_t *v = val_get(got, s->attrs[i].name);
        val_t *copy;
        size_t k;
        bool list = false;
        for (k = 0; k < s->count_count; k++) {
            list = list || strcmp(s->counts[2 * k + 1], s->attrs[i].name) == 0;
        }
        copy = v ? val_copy(v) : val_new(list ? V_LIST : V_NULL, 0);
        if (copy->kind == V_INT && s->attrs[i].enum_index >= 0) {
            const char *m = enum_member(s->attrs[i].enum_index, strtoll(copy->text, NULL, 10));
            if (m != NULL) {
                val_t *named = val_str(m, strlen(m), 0);
                val_free(copy);
                copy = named;
            }
        }
        val_put(out, s->attrs[i].name, strlen(s->attrs[i].name), 0, copy);
    }
    val_free(parsed);
    return out;
}
