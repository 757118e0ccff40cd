/* The device tool's values: the model of a YAML or JSON value, the library's JSON lines read into
 * it through the runtime's JSON reader (src/json_reader.c), and values written as JSON and as YAML
 * flow text. Generated: do not edit. */
#include "device.h"

val_t *val_new(vkind_t kind, int line) {
    val_t *v = (val_t *)xalloc(sizeof *v);
    v->kind = kind;
    v->line = line;
    return v;
}

void val_free(val_t *v) {
    size_t i;
    if (v == NULL) {
        return;
    }
    for (i = 0; i < v->n; i++) {
        val_free(v->items[i]);
        if (v->keys) {
            free(v->keys[i]);
        }
    }
    free(v->items);
    free(v->keys);
    free(v->key_lines);
    free(v->text);
    free(v);
}

val_t *val_str(const char *s, size_t n, int line) {
    val_t *v = val_new(V_STR, line);
    v->text = xstrndup(s, n);
    v->len = n;
    return v;
}

val_t *val_number(vkind_t kind, const char *text, int line) {
    val_t *v = val_new(kind, line);
    v->text = xstrndup(text, strlen(text));
    return v;
}

void val_push(val_t *list, val_t *item) {
    if (list->n == list->cap) {
        list->cap = list->cap ? list->cap * 2 : 4;
        list->items = (val_t **)xrealloc(list->items, list->cap * sizeof *list->items);
        if (list->kind == V_MAP) {
            list->keys = (char **)xrealloc(list->keys, list->cap * sizeof *list->keys);
            list->key_lines = (int *)xrealloc(list->key_lines, list->cap * sizeof *list->key_lines);
        }
    }
    list->items[list->n++] = item;
}

void val_put(val_t *map, const char *key, size_t klen, int line, val_t *value) {
    val_push(map, value);
    map->keys[map->n - 1] = xstrndup(key, klen);
    map->key_lines[map->n - 1] = line;
}

long val_index(const val_t *map, const char *key) {
    size_t i;
    if (map == NULL || map->kind != V_MAP) {
        return -1;
    }
    for (i = 0; i < map->n; i++) {
        if (strcmp(map->keys[i], key) == 0) {
            return (long)i;
        }
    }
    return -1;
}

val_t *val_get(const val_t *map, const char *key) {
    long i = val_index(map, key);
    return i < 0 ? NULL : map->items[i];
}

val_t *val_copy(const val_t *v) {
    size_t i;
    val_t *c = val_new(v->kind, v->line);
    c->b = v->b;
    if (v->text) {
        c->text = xstrndup(v->text, v->kind == V_STR ? v->len : strlen(v->text));
        c->len = v->len;
    }
    for (i = 0; i < v->n; i++) {
        if (v->kind == V_MAP) {
            val_put(c, v->keys[i], strlen(v->keys[i]), v->key_lines[i], val_copy(v->items[i]));
        } else {
            val_push(c, val_copy(v->items[i]));
        }
    }
    return c;
}

void json_string(buf_t *b, const char *s, size_t n) {
    size_t i;
    buf_add(b, "\"", 1);
    for (i = 0; i < n; i++) {
        unsigned char c = (unsigned char)s[i];
        if (c == '"' || c == '\\') {
            char e[2] = {'\\', (char)c};
            buf_add(b, e, 2);
        } else if (c < 0x20 || c >= 0x7f) {
            buf_fmt(b, "\\u%04x", (unsigned)c);
        } else {
            buf_add(b, (const char *)&c, 1);
        }
    }
    buf_add(b, "\"", 1);
}

/* The canonical JSON of a value (no spaces; the library's number text kept). */
void val_json(buf_t *b, const val_t *v) {
    size_t i;
    switch (v->kind) {
    case V_NULL:
        buf_str(b, "null");
        break;
    case V_BOOL:
        buf_str(b, v->b ? "true" : "false");
        break;
    case V_INT:
    case V_NUM:
        buf_str(b, v->text);
        break;
    case V_STR:
        json_string(b, v->text, v->len);
        break;
    case V_LIST:
        buf_str(b, "[");
        for (i = 0; i < v->n; i++) {
            if (i) {
                buf_str(b, ",");
            }
            val_json(b, v->items[i]);
        }
        buf_str(b, "]");
        break;
    case V_MAP:
        buf_str(b, "{");
        for (i = 0; i < v->n; i++) {
            if (i) {
                buf_str(b, ",");
            }
            json_string(b, v->keys[i], strlen(v->keys[i]));
            buf_str(b, ":");
            val_json(b, v->items[i]);
        }
        buf_str(b, "}");
        break;
    }
}

bool val_equal(const val_t *a, const val_t *b) {
    buf_t x = {0};
    buf_t y = {0};
    bool same;
    if (a == NULL || b == NULL) {
        return a == b;
    }
    val_json(&x, a);
    val_json(&y, b);
    same = strcmp(buf_text(&x), buf_text(&y)) == 0;
    free(x.s);
    free(y.s);
    return same;
}

/* A string of the line at pos (a key or a value) as bytes. */
static bool jr_text(mscipc_jr_t *jr, size_t pos, buf_t *out) {
    size_t n = 0;
    char *bytes;
    if (mscipc_jr_bytes(jr, pos, NULL, 0, &n)) {
        return false;
    }
    bytes = (char *)xalloc(n + 1);
    (void)mscipc_jr_bytes(jr, pos, bytes, n, &n);
    buf_add(out, bytes, n);
    free(bytes);
    return true;
}

/* The value at pos of a line that mscipc_jr_skip accepted, read through the runtime's JSON reader
 * (src/json_reader.c): numbers keep their text. */
static val_t *jr_value(mscipc_jr_t *jr, size_t pos) {
    val_t *v;
    size_t it;
    size_t key;
    size_t at;
    pos = mscipc_jr_ws(jr, pos);
    switch (jr->s[pos]) {
    case '{':
        v = val_new(V_MAP, 0);
        (void)mscipc_jr_members(jr, pos, &it);
        while (mscipc_jr_next_member(jr, &it, &key, &at) == 1) {
            buf_t k = {0};
            val_t *item = jr_text(jr, key, &k) ? jr_value(jr, at) : NULL;
            if (item == NULL) {
                free(k.s);
                val_free(v);
                return NULL;
            }
            val_put(v, buf_text(&k), k.n, 0, item);
            free(k.s);
        }
        return v;
    case '[':
        v = val_new(V_LIST, 0);
        (void)mscipc_jr_array(jr, pos, &it);
        while (mscipc_jr_next(jr, &it, &at) == 1) {
            val_t *item = jr_value(jr, at);
            if (item == NULL) {
                val_free(v);
                return NULL;
            }
            val_push(v, item);
        }
        return v;
    case '"': {
        buf_t s = {0};
        v = jr_text(jr, pos, &s) ? val_str(buf_text(&s), s.n, 0) : NULL;
        free(s.s);
        return v;
    }
    case 't':
    case 'f':
        v = val_new(V_BOOL, 0);
        v->b = jr->s[pos] == 't';
        return v;
    case 'n':
        return val_new(V_NULL, 0);
    default: {
        size_t end;
        bool is_int;
        if (mscipc_jr_number(jr, pos, &end, &is_int)) {
            return NULL;
        }
        v = val_new(is_int ? V_INT : V_NUM, 0);
        v->text = xstrndup(jr->s + pos, end - pos);
        return v;
    }
    }
}

/* One JSON value (a line of the library's canonical JSON), or NULL when it is not one. */
val_t *json_parse(const char *s, size_t n) {
    mscipc_jr_t jr;
    size_t end;
    mscipc_jr_init(&jr, s, n, NULL, 0);
    if (mscipc_jr_skip(&jr, 0, &end) || mscipc_jr_ws(&jr, end) != n) {
        return NULL;
    }
    return jr_value(&jr, 0);
}

/* What PyYAML's resolver would read back as something else than a string. */
static bool yaml_resolves(const char *s) {
    static const char *const words[] = {"null",  "Null",  "NULL", "~",   "true", "True", "TRUE", "false",
                                        "False", "FALSE", "yes",  "Yes", "YES",  "no",   "No",   "NO",
                                        "on",    "On",    "ON",   "off", "Off",  "OFF",  "y",    "Y",
                                        "n",     "N",     "=",    "<<",  NULL};
    size_t i;
    char *end;
    for (i = 0; words[i]; i++) {
        if (strcmp(s, words[i]) == 0) {
            return true;
        }
    }
    if (s[0] == '\0') {
        return true;
    }
    errno = 0;
    (void)strtod(s, &end);
    if (*end == '\0') {
        return true;
    }
    if (s[0] == '.' || (s[0] && s[1] == '.')) {
        const char *t = s[0] == '.' ? s : s + 1;
        if (strcmp(t, ".inf") == 0 || strcmp(t, ".Inf") == 0 || strcmp(t, ".INF") == 0 ||
            strcmp(t, ".nan") == 0 || strcmp(t, ".NaN") == 0 || strcmp(t, ".NAN") == 0) {
            return true;
        }
    }
    return false;
}

static bool yaml_plain_ok(const char *s, size_t n) {
    size_t i;
    if (n == 0 || memchr(s, '\0', n) != NULL || yaml_resolves(s)) {
        return false;
    }
    if (s[0] == ' ' || s[n - 1] == ' ' || strchr("#,[]{}&*!|>'\"%@`", s[0]) != NULL) {
        return false;
    }
    if ((s[0] == '-' || s[0] == '?' || s[0] == ':') && (n == 1 || s[1] == ' ')) {
        return false;
    }
    if (n >= 3 && (strncmp(s, "---", 3) == 0 || strncmp(s, "...", 3) == 0)) {
        return false;
    }
    if (s[n - 1] == ':') {
        return false;
    }
    for (i = 0; i < n; i++) {
        unsigned char c = (unsigned char)s[i];
        if (c < 0x20 || c >= 0x7f || strchr(",?[]{}", (char)c) != NULL) {
            return false;
        }
        if (c == ':' && i + 1 < n && s[i + 1] == ' ') {
            return false;
        }
        if (c == '#' && i > 0 && s[i - 1] == ' ') {
            return false;
        }
    }
    return true;
}

/* A value as PyYAML's flow style writes it (yaml.safe_dump(default_flow_style=True)). */
static void yaml_flow(buf_t *b, const val_t *v) {
    size_t i;
    if (v == NULL) {
        buf_str(b, "null");
        return;
    }
    switch (v->kind) {
    case V_NULL:
        buf_str(b, "null");
        break;
    case V_BOOL:
        buf_str(b, v->b ? "true" : "false");
        break;
    case V_INT:
        buf_str(b, v->text);
        break;
    case V_NUM: {
        /* repr(float).lower(), with ".0" before an exponent that has no point (1e-05 -> 1.0e-05) */
        const char *e = strpbrk(v->text, "eE");
        if (e != NULL && strchr(v->text, '.') == NULL) {
            buf_add(b, v->text, (size_t)(e - v->text));
            buf_str(b, ".0e");
            buf_str(b, e + 1);
        } else {
            size_t k;
            for (k = 0; v->text[k]; k++) {
                char c = v->text[k] == 'E' ? 'e' : v->text[k];
                buf_add(b, &c, 1);
            }
        }
        break;
    }
    case V_STR:
        if (yaml_plain_ok(v->text, v->len)) {
            buf_add(b, v->text, v->len);
        } else {
            bool printable = true;
            for (i = 0; i < v->len; i++) {
                unsigned char c = (unsigned char)v->text[i];
                if (c < 0x20 || c == 0x7f) {
                    printable = false;
                }
            }
            if (printable) {
                buf_str(b, "'");
                for (i = 0; i < v->len; i++) {
                    if (v->text[i] == '\'') {
                        buf_str(b, "''");
                    } else {
                        buf_add(b, v->text + i, 1);
                    }
                }
                buf_str(b, "'");
            } else {
                buf_str(b, "\"");
                for (i = 0; i < v->len; i++) {
                    unsigned char c = (unsigned char)v->text[i];
                    if (c == '"' || c == '\\') {
                        buf_fmt(b, "\\%c", c);
                    } else if (c == 0) {
                        buf_str(b, "\\0");
                    } else if (c < 0x20 || c == 0x7f) {
                        buf_fmt(b, "\\x%02X", (unsigned)c);
                    } else {
                        buf_add(b, (const char *)&c, 1);
                    }
                }
                buf_str(b, "\"");
            }
        }
        break;
    case V_LIST:
        buf_str(b, "[");
        for (i = 0; i < v->n; i++) {
            if (i) {
                buf_str(b, ", ");
            }
            yaml_flow(b, v->items[i]);
        }
        buf_str(b, "]");
        break;
    case V_MAP:
        buf_str(b, "{");
        for (i = 0; i < v->n; i++) {
            val_t key = {V_STR, 0, v->keys[i], strlen(v->keys[i]), false, 0, 0, NULL, NULL, NULL};
            if (i) {
                buf_str(b, ", ");
            }
            yaml_flow(b, &key);
            buf_str(b, ": ");
            yaml_flow(b, v->items[i]);
        }
        buf_str(b, "}");
        break;
    }
}

const char *flow_text(buf_t *b, const val_t *v) {
    buf_reset(b);
    yaml_flow(b, v);
    return buf_text(b);
}
