/* mipcodec-device ADDRESS SUBCOMMAND [OPTIONS]: the device command line of docs/configure-a-device.md
 * in C, for machines without Python: the same subcommands, arguments, output and exit statuses as
 * the Python package's device CLI (ping, info, send, save-startup, factory-reset, stream, settings
 * dump|diff|apply).
 *
 * What the spec says comes from tools/device_facts.h (generated from the same derivation as the
 * Python package's _settings.py: generator/settings_rows.py); values travel as the library's
 * canonical JSON (a command line -> mipc_json_command_line, a result -> mipc_json_result_line), so
 * the layouts are the library's own.
 *
 * Settings files: the YAML subset that the dumps of this tool and of the Python CLI are written in
 * (docs/configure-a-device.md "The YAML subset of the C tool"):
 *   - one document of block mappings and block sequences, indented with spaces;
 *   - flow sequences and flow mappings on one line ([1, 2], {descriptor: 4, decimation: 10});
 *   - plain, 'single-quoted' and "double-quoted" scalars (null, true/false, integers, floats and
 *     .inf/.nan as YAML 1.1 resolves them; everything else a string);
 *   - comments (# to the end of the line) and blank lines; a leading "---".
 * Anything else (anchors, aliases, tags, block scalars | >, multi-line flow collections, complex
 * keys, tabs in indentation, several documents) is refused with one located FILE:LINE: line.
 *
 * Exit status: 0 done (diff: the device matches the file); 1 the device said no or differs; 2
 * nothing was changed (usage, bad file, refused before sending, no connection); 130 interrupted
 * (stream: 0). Generated: do not edit. */
#if !defined(_POSIX_C_SOURCE) || _POSIX_C_SOURCE < 200809L
#undef _POSIX_C_SOURCE
#define _POSIX_C_SOURCE 200809L
#endif
#include <errno.h>
#include <glob.h>
#include <math.h>
#include <signal.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <time.h>

#include "mipcodec/json.h"
#include "mipcodec/link.h"
#include "mipcodec/posix_transport.h"
#include "device_facts.h"
#include "device_record.h"

#define PROG "mipcodec-device"
#define DEFAULT_BAUD 115200UL
#define MAX_PROBLEMS 200

/* ------------------------------------------------------------------------------ errors */

/* src into dst[cap], cut to fit. Not snprintf("%s"): gcc -O3 warns that it may truncate, which is
 * the point here. */
static void copy_text(char *dst, size_t cap, const char *src) {
    size_t n = strlen(src);
    if (cap == 0) {
        return;
    }
    if (n >= cap) {
        n = cap - 1;
    }
    memcpy(dst, src, n);
    dst[n] = '\0';
}

/* Set while `auto` tries a port: a failed attempt is not an error of the run. */
static bool quiet_notes;

static void note(const char *fmt, ...) {
    va_list ap;
    if (quiet_notes) {
        return;
    }
    fprintf(stderr, PROG ": ");
    va_start(ap, fmt);
    vfprintf(stderr, fmt, ap);
    va_end(ap);
    fputc('\n', stderr);
    fflush(stderr);
}

static void say(const char *fmt, ...) {
    va_list ap;
    va_start(ap, fmt);
    vprintf(fmt, ap);
    va_end(ap);
    fputc('\n', stdout);
    fflush(stdout);
}

static void *xalloc(size_t n) {
    void *p = calloc(1, n ? n : 1);
    if (p == NULL) {
        note("out of memory");
        exit(2);
    }
    return p;
}

static void *xrealloc(void *p, size_t n) {
    void *q = realloc(p, n ? n : 1);
    if (q == NULL) {
        note("out of memory");
        exit(2);
    }
    return q;
}

static char *xstrndup(const char *s, size_t n) {
    char *p = (char *)xalloc(n + 1);
    memcpy(p, s, n);
    p[n] = '\0';
    return p;
}

/* A growing string. */
typedef struct {
    char *s;
    size_t n;
    size_t cap;
} buf_t;

static void buf_add(buf_t *b, const char *s, size_t n) {
    if (b->n + n + 1 > b->cap) {
        b->cap = (b->n + n + 1) * 2;
        b->s = (char *)xrealloc(b->s, b->cap);
    }
    memcpy(b->s + b->n, s, n);
    b->n += n;
    b->s[b->n] = '\0';
}

static void buf_str(buf_t *b, const char *s) {
    buf_add(b, s, strlen(s));
}

static void buf_fmt(buf_t *b, const char *fmt, ...) {
    char tmp[512];
    va_list ap;
    int n;
    va_start(ap, fmt);
    n = vsnprintf(tmp, sizeof tmp, fmt, ap);
    va_end(ap);
    if (n < 0) {
        return;
    }
    if ((size_t)n >= sizeof tmp) {
        char *big = (char *)xalloc((size_t)n + 1);
        va_start(ap, fmt);
        vsnprintf(big, (size_t)n + 1, fmt, ap);
        va_end(ap);
        buf_add(b, big, (size_t)n);
        free(big);
        return;
    }
    buf_add(b, tmp, (size_t)n);
}

static void buf_reset(buf_t *b) {
    b->n = 0;
    if (b->s) {
        b->s[0] = '\0';
    }
}

static const char *buf_text(const buf_t *b) {
    return b->s ? b->s : "";
}

/* ------------------------------------------------------------------------------ values */
typedef enum { V_NULL, V_BOOL, V_INT, V_NUM, V_STR, V_LIST, V_MAP } vkind_t;

typedef struct val val_t;
struct val {
    vkind_t kind;
    int line;   /* where it starts in a file (0: not from a file) */
    char *text; /* V_INT, V_NUM: canonical JSON text of the number; V_STR: the bytes */
    size_t len; /* V_STR: length */
    bool b;
    size_t n;
    size_t cap;
    val_t **items;  /* V_LIST: items; V_MAP: values */
    char **keys;    /* V_MAP: keys */
    int *key_lines; /* V_MAP: the line of each key */
};

static val_t *val_new(vkind_t kind, int line) {
    val_t *v = (val_t *)xalloc(sizeof *v);
    v->kind = kind;
    v->line = line;
    return v;
}

static void val_free(val_t *v) {
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

static val_t *val_str(const char *s, size_t n, int line) {
    val_t *v = val_new(V_STR, line);
    v->text = xstrndup(s, n);
    v->len = n;
    return v;
}

static val_t *val_number(vkind_t kind, const char *text, int line) {
    val_t *v = val_new(kind, line);
    v->text = xstrndup(text, strlen(text));
    return v;
}

static void val_push(val_t *list, val_t *item) {
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

static void val_put(val_t *map, const char *key, size_t klen, int line, val_t *value) {
    val_push(map, value);
    map->keys[map->n - 1] = xstrndup(key, klen);
    map->key_lines[map->n - 1] = line;
}

static long val_index(const val_t *map, const char *key) {
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

static val_t *val_get(const val_t *map, const char *key) {
    long i = val_index(map, key);
    return i < 0 ? NULL : map->items[i];
}

static val_t *val_copy(const val_t *v) {
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

/* ------------------------------------------------------------------------------ JSON */
static void json_string(buf_t *b, const char *s, size_t n) {
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
static void val_json(buf_t *b, const val_t *v) {
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

static bool val_equal(const val_t *a, const val_t *b) {
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

typedef struct {
    const char *s;
    size_t n;
    size_t i;
    int depth;
} jp_t;

static void jp_ws(jp_t *p) {
    while (p->i < p->n &&
           (p->s[p->i] == ' ' || p->s[p->i] == '\t' || p->s[p->i] == '\r' || p->s[p->i] == '\n')) {
        p->i++;
    }
}

static int hexval(char c) {
    if (c >= '0' && c <= '9') {
        return c - '0';
    }
    if (c >= 'a' && c <= 'f') {
        return c - 'a' + 10;
    }
    if (c >= 'A' && c <= 'F') {
        return c - 'A' + 10;
    }
    return -1;
}

/* A JSON string at p->i (the quote) as bytes (\u00xx -> byte xx, as canonical JSON writes bytes). */
static bool jp_string(jp_t *p, buf_t *out) {
    if (p->i >= p->n || p->s[p->i] != '"') {
        return false;
    }
    p->i++;
    while (p->i < p->n && p->s[p->i] != '"') {
        char c = p->s[p->i++];
        if (c == '\\') {
            char e;
            if (p->i >= p->n) {
                return false;
            }
            e = p->s[p->i++];
            if (e == 'u') {
                unsigned code = 0;
                int k;
                for (k = 0; k < 4; k++) {
                    int h = p->i < p->n ? hexval(p->s[p->i]) : -1;
                    if (h < 0) {
                        return false;
                    }
                    code = code * 16 + (unsigned)h;
                    p->i++;
                }
                if (code < 256) {
                    char ch = (char)code;
                    buf_add(out, &ch, 1);
                } else {
                    buf_add(out, "?", 1);
                }
            } else {
                const char *from = "\"\\/bfnrt";
                const char *to = "\"\\/\b\f\n\r\t";
                const char *at = strchr(from, e);
                if (at == NULL || e == '\0') {
                    return false;
                }
                buf_add(out, to + (at - from), 1);
            }
        } else {
            buf_add(out, &c, 1);
        }
    }
    if (p->i >= p->n) {
        return false;
    }
    p->i++;
    return true;
}

static val_t *jp_value(jp_t *p) {
    val_t *v;
    jp_ws(p);
    if (p->i >= p->n || ++p->depth > 64) {
        return NULL;
    }
    if (p->s[p->i] == '{' || p->s[p->i] == '[') {
        bool map = p->s[p->i] == '{';
        v = val_new(map ? V_MAP : V_LIST, 0);
        p->i++;
        jp_ws(p);
        if (p->i < p->n && p->s[p->i] == (map ? '}' : ']')) {
            p->i++;
            p->depth--;
            return v;
        }
        for (;;) {
            val_t *item;
            buf_t key = {0};
            jp_ws(p);
            if (map) {
                if (!jp_string(p, &key)) {
                    free(key.s);
                    val_free(v);
                    return NULL;
                }
                jp_ws(p);
                if (p->i >= p->n || p->s[p->i] != ':') {
                    free(key.s);
                    val_free(v);
                    return NULL;
                }
                p->i++;
            }
            item = jp_value(p);
            if (item == NULL) {
                free(key.s);
                val_free(v);
                return NULL;
            }
            if (map) {
                val_put(v, buf_text(&key), key.n, 0, item);
            } else {
                val_push(v, item);
            }
            free(key.s);
            jp_ws(p);
            if (p->i < p->n && p->s[p->i] == ',') {
                p->i++;
                continue;
            }
            if (p->i < p->n && p->s[p->i] == (map ? '}' : ']')) {
                p->i++;
                break;
            }
            val_free(v);
            return NULL;
        }
        p->depth--;
        return v;
    }
    if (p->s[p->i] == '"') {
        buf_t s = {0};
        if (!jp_string(p, &s)) {
            free(s.s);
            return NULL;
        }
        v = val_str(buf_text(&s), s.n, 0);
        free(s.s);
        p->depth--;
        return v;
    }
    if (p->n - p->i >= 4 && strncmp(p->s + p->i, "true", 4) == 0) {
        p->i += 4;
        v = val_new(V_BOOL, 0);
        v->b = true;
    } else if (p->n - p->i >= 5 && strncmp(p->s + p->i, "false", 5) == 0) {
        p->i += 5;
        v = val_new(V_BOOL, 0);
    } else if (p->n - p->i >= 4 && strncmp(p->s + p->i, "null", 4) == 0) {
        p->i += 4;
        v = val_new(V_NULL, 0);
    } else {
        size_t start = p->i;
        bool real = false;
        char *t;
        while (p->i < p->n && strchr("+-0123456789.eE", p->s[p->i]) != NULL && p->s[p->i] != '\0') {
            if (strchr(".eE", p->s[p->i])) {
                real = true;
            }
            p->i++;
        }
        if (p->i == start) {
            return NULL;
        }
        t = xstrndup(p->s + start, p->i - start);
        v = val_number(real ? V_NUM : V_INT, t, 0);
        free(t);
    }
    p->depth--;
    return v;
}

static val_t *json_parse(const char *s, size_t n) {
    jp_t p = {s, n, 0, 0};
    val_t *v = jp_value(&p);
    jp_ws(&p);
    if (v != NULL && p.i != p.n) {
        val_free(v);
        return NULL;
    }
    return v;
}

/* ------------------------------------------------------------------------------ YAML out */
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

static const char *flow_text(buf_t *b, const val_t *v) {
    buf_reset(b);
    yaml_flow(b, v);
    return buf_text(b);
}

/* ------------------------------------------------------------------------------ YAML in */
typedef struct {
    int number; /* 1-based line number */
    int indent;
    char *text; /* without indentation and comment, right-trimmed (owned) */
} yline_t;

typedef struct {
    yline_t *lines;
    size_t count;
    size_t at;
    char err[300];
    int err_line;
} yp_t;

static void yp_fail(yp_t *p, int line, const char *fmt, ...) {
    va_list ap;
    if (p->err[0]) {
        return;
    }
    p->err_line = line;
    va_start(ap, fmt);
    vsnprintf(p->err, sizeof p->err, fmt, ap);
    va_end(ap);
    if (!p->err[0]) {
        snprintf(p->err, sizeof p->err, "not valid YAML");
    }
}

/* The end of a line's content: before a comment (# at the start or after white space, outside
 * quotes), trailing white space removed. */
static size_t content_end(const char *s, size_t n) {
    size_t i = 0;
    char quote = 0;
    while (i < n) {
        char c = s[i];
        if (quote) {
            if (quote == '"' && c == '\\' && i + 1 < n) {
                i += 2;
                continue;
            }
            if (c == quote) {
                if (quote == '\'' && i + 1 < n && s[i + 1] == '\'') {
                    i += 2;
                    continue;
                }
                quote = 0;
            }
        } else if (c == '#' && (i == 0 || s[i - 1] == ' ' || s[i - 1] == '\t')) {
            break;
        } else if ((c == '\'' || c == '"') && (i == 0 || strchr(" [{,:-", s[i - 1]) != NULL)) {
            quote = c;
        }
        i++;
    }
    while (i > 0 && (s[i - 1] == ' ' || s[i - 1] == '\t' || s[i - 1] == '\r')) {
        i--;
    }
    return i;
}

static bool yp_split(yp_t *p, const char *text, size_t n) {
    size_t i = 0;
    int number = 0;
    bool started = false;
    while (i < n || (i == n && n == 0)) {
        size_t start = i;
        size_t end;
        size_t k;
        int indent = 0;
        if (i >= n) {
            break;
        }
        while (i < n && text[i] != '\n') {
            i++;
        }
        end = i;
        if (i < n) {
            i++;
        }
        number++;
        for (k = start; k < end; k++) {
            if (text[k] == '\0') {
                yp_fail(p, number, "a NUL byte");
                return false;
            }
        }
        k = start;
        while (k < end && text[k] == ' ') {
            k++;
            indent++;
        }
        if (k < end && text[k] == '\t') {
            size_t rest = k;
            while (rest < end && (text[rest] == ' ' || text[rest] == '\t')) {
                rest++;
            }
            if (rest < end && text[rest] != '#' && text[rest] != '\r') {
                yp_fail(p, number, "a tab in the indentation (not in the YAML subset the C tool reads)");
                return false;
            }
        }
        end = k + content_end(text + k, end - k);
        if (end <= k) {
            continue;
        }
        if (indent == 0 && end - k >= 3 && strncmp(text + k, "---", 3) == 0 &&
            (end - k == 3 || text[k + 3] == ' ')) {
            if (started || end - k > 3) {
                yp_fail(
                    p, number,
                    "several documents, or content after ---, are not in the YAML subset the C tool reads");
                return false;
            }
            started = true;
            continue;
        }
        if (indent == 0 && end - k >= 3 && strncmp(text + k, "...", 3) == 0 &&
            (end - k == 3 || text[k + 3] == ' ')) {
            yp_fail(p, number, "a document end marker (...) is not in the YAML subset the C tool reads");
            return false;
        }
        started = true;
        p->lines = (yline_t *)xrealloc(p->lines, (p->count + 1) * sizeof *p->lines);
        p->lines[p->count].number = number;
        p->lines[p->count].indent = indent;
        p->lines[p->count].text = xstrndup(text + k, end - k);
        p->count++;
    }
    return true;
}

static bool all_of(const char *s, size_t n, const char *set) {
    size_t i;
    if (n == 0) {
        return false;
    }
    for (i = 0; i < n; i++) {
        if (strchr(set, s[i]) == NULL || s[i] == '\0') {
            return false;
        }
    }
    return true;
}

/* A plain scalar as PyYAML's (YAML 1.1) resolver reads it. */
static val_t *yp_resolve(yp_t *p, const char *s, size_t n, int line) {
    static const char *const nulls[] = {"~", "null", "Null", "NULL", NULL};
    static const char *const trues[] = {"yes", "Yes", "YES", "true", "True", "TRUE", "on", "On", "ON", NULL};
    static const char *const falses[] = {"no",    "No",  "NO",  "false", "False",
                                         "FALSE", "off", "Off", "OFF",   NULL};
    char digits[80];
    size_t i;
    size_t k = 0;
    size_t start = 0;
    bool neg = false;
    val_t *v;
    if (n == 0) {
        return val_new(V_NULL, line);
    }
    for (i = 0; nulls[i]; i++) {
        if (strlen(nulls[i]) == n && strncmp(s, nulls[i], n) == 0) {
            return val_new(V_NULL, line);
        }
    }
    for (i = 0; trues[i]; i++) {
        if (strlen(trues[i]) == n && strncmp(s, trues[i], n) == 0) {
            v = val_new(V_BOOL, line);
            v->b = true;
            return v;
        }
        if (strlen(falses[i]) == n && strncmp(s, falses[i], n) == 0) {
            return val_new(V_BOOL, line);
        }
    }
    if (s[0] == '-' || s[0] == '+') {
        neg = s[0] == '-';
        start = 1;
    }
    /* .inf, .nan */
    if (n - start == 4 && (strncmp(s + start, ".inf", 4) == 0 || strncmp(s + start, ".Inf", 4) == 0 ||
                           strncmp(s + start, ".INF", 4) == 0)) {
        return val_str(neg ? "-inf" : "inf", neg ? 4 : 3, line);
    }
    if (start == 0 && n == 4 &&
        (strncmp(s, ".nan", 4) == 0 || strncmp(s, ".NaN", 4) == 0 || strncmp(s, ".NAN", 4) == 0)) {
        return val_str("nan", 3, line);
    }
    if (n - start < sizeof digits - 2 && n > start) {
        const char *d = s + start;
        size_t m = n - start;
        unsigned long long u = 0;
        int base = 0;
        size_t from = 0;
        if (m > 2 && d[0] == '0' && d[1] == 'x' && all_of(d + 2, m - 2, "0123456789abcdefABCDEF_")) {
            base = 16, from = 2;
        } else if (m > 2 && d[0] == '0' && d[1] == 'b' && all_of(d + 2, m - 2, "01_")) {
            base = 2, from = 2;
        } else if (m > 1 && d[0] == '0' && all_of(d + 1, m - 1, "01234567_")) {
            base = 8, from = 1;
        } else if (m == 1 && d[0] == '0') {
            base = 10;
        } else if (d[0] >= '1' && d[0] <= '9' && all_of(d, m, "0123456789_")) {
            base = 10;
        }
        if (base) {
            bool overflow = false;
            for (i = from; i < m; i++) {
                unsigned dv;
                if (d[i] == '_') {
                    continue;
                }
                dv = (unsigned)hexval(d[i]);
                if (u > (~0ULL - dv) / (unsigned)base) {
                    overflow = true;
                    break;
                }
                u = u * (unsigned)base + dv;
            }
            if (overflow) {
                yp_fail(p, line, "the integer %.*s is out of any parameter's range", (int)(n > 60 ? 60 : n),
                        s);
                return NULL;
            }
            if (neg && u != 0) {
                if (u > 9223372036854775808ULL) {
                    yp_fail(p, line, "the integer %.*s is out of any parameter's range",
                            (int)(n > 60 ? 60 : n), s);
                    return NULL;
                }
                snprintf(digits, sizeof digits, "-%llu", u);
            } else {
                snprintf(digits, sizeof digits, "%llu", u);
            }
            return val_number(V_INT, digits, line);
        }
        /* floats: [-+]?[0-9][0-9_]*\.[0-9_]*([eE][-+][0-9]+)? or [-+]?\.[0-9_]+([eE][-+][0-9]+)? */
        {
            size_t j = 0;
            bool ok = false;
            while (j < m && ((d[j] >= '0' && d[j] <= '9') || (d[j] == '_' && j > 0))) {
                j++;
            }
            if (j < m && d[j] == '.' && (j > 0 || (j + 1 < m && d[j + 1] >= '0' && d[j + 1] <= '9'))) {
                j++;
                while (j < m && ((d[j] >= '0' && d[j] <= '9') || d[j] == '_')) {
                    j++;
                }
                ok = j == m;
                if (!ok && (d[j] == 'e' || d[j] == 'E') && j + 2 < m &&
                    (d[j + 1] == '-' || d[j + 1] == '+') && all_of(d + j + 2, m - j - 2, "0123456789")) {
                    ok = true;
                }
            }
            if (ok) {
                char number[80];
                char out[MIPC_JSON_NUMBER_MAX];
                double x;
                k = 0;
                if (neg) {
                    number[k++] = '-';
                }
                for (i = 0; i < m; i++) {
                    if (d[i] != '_') {
                        number[k++] = d[i];
                    }
                }
                number[k] = '\0';
                x = strtod(number, NULL);
                mipc_json_format_double(x, out, sizeof out);
                if (out[0] == '"') {
                    size_t len = strlen(out);
                    return val_str(out + 1, len - 2, line);
                }
                return val_number(V_NUM, out, line);
            }
        }
    }
    return val_str(s, n, line);
}

/* A quoted scalar at s[*i] (the quote); *i past it. */
static val_t *yp_quoted(yp_t *p, const char *s, size_t n, size_t *i, int line) {
    char q = s[*i];
    buf_t b = {0};
    val_t *v;
    size_t k = *i + 1;
    for (;;) {
        char c;
        if (k >= n) {
            yp_fail(
                p, line,
                "a quoted scalar that does not end on its line (not in the YAML subset the C tool reads)");
            free(b.s);
            return NULL;
        }
        c = s[k];
        if (c == q) {
            if (q == '\'' && k + 1 < n && s[k + 1] == '\'') {
                buf_add(&b, "'", 1);
                k += 2;
                continue;
            }
            k++;
            break;
        }
        if (q == '"' && c == '\\') {
            char e = k + 1 < n ? s[k + 1] : '\0';
            const char *from = "0abtnvfre \"/\\";
            const char *to = "\0\a\b\t\n\v\f\r\033 \"/\\";
            const char *at = e ? strchr(from, e) : NULL;
            if (at != NULL) {
                buf_add(&b, to + (at - from), 1);
                k += 2;
                continue;
            }
            if (e == 'x' || e == 'u') {
                size_t digits = e == 'x' ? 2 : 4;
                unsigned code = 0;
                size_t j;
                for (j = 0; j < digits; j++) {
                    int h = k + 2 + j < n ? hexval(s[k + 2 + j]) : -1;
                    if (h < 0) {
                        break;
                    }
                    code = code * 16 + (unsigned)h;
                }
                if (j == digits) {
                    if (code < 0x80 || (e == 'x')) {
                        char ch = (char)code;
                        buf_add(&b, &ch, 1);
                    } else if (code < 0x800) {
                        char u8[2] = {(char)(0xC0 | (code >> 6)), (char)(0x80 | (code & 0x3F))};
                        buf_add(&b, u8, 2);
                    } else {
                        char u8[3] = {(char)(0xE0 | (code >> 12)), (char)(0x80 | ((code >> 6) & 0x3F)),
                                      (char)(0x80 | (code & 0x3F))};
                        buf_add(&b, u8, 3);
                    }
                    k += 2 + digits;
                    continue;
                }
            }
            yp_fail(p, line, "an unknown escape in a double-quoted scalar");
            free(b.s);
            return NULL;
        }
        buf_add(&b, &c, 1);
        k++;
    }
    *i = k;
    v = val_str(buf_text(&b), b.n, line);
    free(b.s);
    return v;
}

static bool refused_start(yp_t *p, char c, int line) {
    static const char *const what[] = {"&anchors",
                                       "*aliases",
                                       "!tags",
                                       "|block scalars",
                                       ">block scalars",
                                       "%directives",
                                       "@reserved indicators",
                                       "`reserved indicators",
                                       "?complex keys",
                                       NULL};
    size_t i;
    for (i = 0; what[i]; i++) {
        if (what[i][0] == c) {
            yp_fail(p, line, "%s (%c) are not in the YAML subset the C tool reads", what[i] + 1, c);
            return true;
        }
    }
    return false;
}

static void skip_spaces(const char *s, size_t n, size_t *i) {
    while (*i < n && s[*i] == ' ') {
        (*i)++;
    }
}

/* A flow value (inside [ ] or { }, or a whole inline value when flow is false) at s[*i]. */
static val_t *yp_flow(yp_t *p, const char *s, size_t n, size_t *i, int line, int depth, bool flow) {
    skip_spaces(s, n, i);
    if (depth > 32) {
        yp_fail(p, line, "collections nested too deeply");
        return NULL;
    }
    if (*i >= n) {
        if (flow) {
            yp_fail(
                p, line,
                "a flow collection that does not end on its line (not in the YAML subset the C tool reads)");
            return NULL;
        }
        return val_new(V_NULL, line);
    }
    if (s[*i] == '[' || s[*i] == '{') {
        bool map = s[*i] == '{';
        char close = map ? '}' : ']';
        val_t *v = val_new(map ? V_MAP : V_LIST, line);
        (*i)++;
        skip_spaces(s, n, i);
        if (*i < n && s[*i] == close) {
            (*i)++;
            return v;
        }
        for (;;) {
            val_t *item;
            skip_spaces(s, n, i);
            if (map) {
                val_t *key;
                if (*i < n && (s[*i] == '\'' || s[*i] == '"')) {
                    key = yp_quoted(p, s, n, i, line);
                } else {
                    size_t start = *i;
                    while (*i < n && s[*i] != ':' && s[*i] != ',' && s[*i] != '}' && s[*i] != ']') {
                        (*i)++;
                    }
                    while (*i > start && s[*i - 1] == ' ') {
                        (*i)--;
                    }
                    if (*i == start) {
                        yp_fail(p, line, "a flow mapping entry without a key");
                        val_free(v);
                        return NULL;
                    }
                    if (refused_start(p, s[start], line)) {
                        val_free(v);
                        return NULL;
                    }
                    key = yp_resolve(p, s + start, *i - start, line);
                }
                if (key == NULL) {
                    val_free(v);
                    return NULL;
                }
                skip_spaces(s, n, i);
                if (key->kind != V_STR) {
                    buf_t t = {0};
                    yp_fail(p, line, "a key must be a name, not %s", flow_text(&t, key));
                    free(t.s);
                    val_free(key);
                    val_free(v);
                    return NULL;
                }
                if (*i >= n || s[*i] != ':') {
                    yp_fail(p, line, "expected ':' after the key %s of a flow mapping", key->text);
                    val_free(key);
                    val_free(v);
                    return NULL;
                }
                (*i)++;
                if (val_index(v, key->text) >= 0) {
                    yp_fail(p, line, "'%s' given twice (first on line %d)", key->text, line);
                    val_free(key);
                    val_free(v);
                    return NULL;
                }
                skip_spaces(s, n, i);
                if (*i < n && (s[*i] == ',' || s[*i] == '}')) {
                    item = val_new(V_NULL, line);
                } else {
                    item = yp_flow(p, s, n, i, line, depth + 1, true);
                }
                if (item == NULL) {
                    val_free(key);
                    val_free(v);
                    return NULL;
                }
                val_put(v, key->text, key->len, line, item);
                val_free(key);
            } else {
                item = yp_flow(p, s, n, i, line, depth + 1, true);
                if (item == NULL) {
                    val_free(v);
                    return NULL;
                }
                val_push(v, item);
            }
            skip_spaces(s, n, i);
            if (*i < n && s[*i] == ',') {
                (*i)++;
                skip_spaces(s, n, i);
                if (*i < n && s[*i] == close) {
                    (*i)++;
                    return v;
                }
                continue;
            }
            if (*i < n && s[*i] == close) {
                (*i)++;
                return v;
            }
            if (*i >= n) {
                yp_fail(p, line,
                        "a flow collection that does not end on its line (not in the YAML subset the C tool "
                        "reads)");
            } else {
                yp_fail(p, line, "expected ',' or '%c' in a flow collection, found '%c'", close, s[*i]);
            }
            val_free(v);
            return NULL;
        }
    }
    if (s[*i] == '\'' || s[*i] == '"') {
        return yp_quoted(p, s, n, i, line);
    }
    if (refused_start(p, s[*i], line)) {
        return NULL;
    }
    if (s[*i] == ']' || s[*i] == '}' || s[*i] == ',') {
        yp_fail(p, line, "unexpected '%c'", s[*i]);
        return NULL;
    }
    {
        size_t start = *i;
        size_t end;
        if (flow) {
            while (*i < n && s[*i] != ',' && s[*i] != ']' && s[*i] != '}' &&
                   !(s[*i] == ':' && (*i + 1 >= n || s[*i + 1] == ' '))) {
                (*i)++;
            }
        } else {
            size_t k;
            for (k = start; k < n; k++) {
                if (s[k] == ':' && (k + 1 == n || s[k + 1] == ' ')) {
                    yp_fail(p, line,
                            "a mapping is not allowed here (mapping values are not allowed in this context)");
                    return NULL;
                }
            }
            *i = n;
        }
        end = *i;
        while (end > start && s[end - 1] == ' ') {
            end--;
        }
        return yp_resolve(p, s + start, end - start, line);
    }
}

/* The end of a plain or quoted block mapping key in s (the ':' index), or n when none. */
static size_t key_colon(const char *s, size_t n) {
    size_t i = 0;
    if (n == 0 || s[0] == '[' || s[0] == '{') {
        return n;
    }
    if (s[0] == '\'' || s[0] == '"') {
        char q = s[0];
        for (i = 1; i < n; i++) {
            if (q == '"' && s[i] == '\\') {
                i++;
                continue;
            }
            if (s[i] == q) {
                if (q == '\'' && i + 1 < n && s[i + 1] == '\'') {
                    i++;
                    continue;
                }
                break;
            }
        }
        i++;
        while (i < n && s[i] == ' ') {
            i++;
        }
        return i < n && s[i] == ':' && (i + 1 == n || s[i + 1] == ' ') ? i : n;
    }
    for (i = 0; i < n; i++) {
        if (s[i] == ':' && (i + 1 == n || s[i + 1] == ' ')) {
            return i;
        }
    }
    return n;
}

static bool is_item(const yline_t *l) {
    return l->text[0] == '-' && (l->text[1] == '\0' || l->text[1] == ' ');
}

static val_t *yp_block(yp_t *p, int indent, int depth);

/* The value after "key:" or "- " when nothing follows on the line: a nested block, or null. */
static val_t *yp_nested(yp_t *p, int indent, int line, bool seq_same_indent, int depth) {
    if (p->at < p->count) {
        const yline_t *next = &p->lines[p->at];
        if (next->indent > indent || (seq_same_indent && next->indent == indent && is_item(next))) {
            return yp_block(p, next->indent, depth + 1);
        }
    }
    return val_new(V_NULL, line);
}

static val_t *yp_mapping(yp_t *p, int indent, int depth) {
    val_t *map = val_new(V_MAP, p->lines[p->at].number);
    while (p->at < p->count && !p->err[0]) {
        yline_t *l = &p->lines[p->at];
        size_t n = strlen(l->text);
        size_t colon;
        size_t i;
        val_t *key;
        val_t *value;
        long seen;
        if (l->indent < indent) {
            break;
        }
        if (l->indent > indent) {
            yp_fail(p, l->number, "unexpected indentation");
            break;
        }
        if (is_item(l)) {
            yp_fail(p, l->number, "a sequence item where a mapping key was expected");
            break;
        }
        colon = key_colon(l->text, n);
        if (colon == n) {
            if (refused_start(p, l->text[0], l->number)) {
                break;
            }
            yp_fail(p, l->number, "expected KEY: VALUE");
            break;
        }
        if (l->text[0] == '\'' || l->text[0] == '"') {
            i = 0;
            key = yp_quoted(p, l->text, n, &i, l->number);
        } else {
            size_t end = colon;
            while (end > 0 && l->text[end - 1] == ' ') {
                end--;
            }
            if (refused_start(p, l->text[0], l->number)) {
                break;
            }
            key = yp_resolve(p, l->text, end, l->number);
        }
        if (key == NULL) {
            break;
        }
        if (key->kind != V_STR) {
            buf_t t = {0};
            yp_fail(p, l->number, "a key must be a name, not %s", flow_text(&t, key));
            free(t.s);
            val_free(key);
            break;
        }
        seen = val_index(map, key->text);
        if (seen >= 0) {
            yp_fail(p, l->number, "'%s' given twice (first on line %d)", key->text, map->key_lines[seen]);
            val_free(key);
            break;
        }
        i = colon + 1;
        skip_spaces(l->text, n, &i);
        p->at++;
        if (i >= n) {
            value = yp_nested(p, indent, l->number, true, depth);
        } else {
            value = yp_flow(p, l->text, n, &i, l->number, depth, false);
            if (value != NULL) {
                skip_spaces(l->text, n, &i);
                if (i < n) {
                    yp_fail(p, l->number, "unexpected text after the value: %.40s", l->text + i);
                }
            }
        }
        if (value == NULL) {
            val_free(key);
            break;
        }
        val_put(map, key->text, key->len, l->number, value);
        val_free(key);
    }
    if (p->err[0]) {
        val_free(map);
        return NULL;
    }
    return map;
}

static val_t *yp_sequence(yp_t *p, int indent, int depth) {
    val_t *seq = val_new(V_LIST, p->lines[p->at].number);
    while (p->at < p->count && !p->err[0]) {
        yline_t *l = &p->lines[p->at];
        size_t n = strlen(l->text);
        size_t i = 1;
        val_t *item;
        if (l->indent < indent) {
            break;
        }
        if (l->indent > indent) {
            yp_fail(p, l->number, "unexpected indentation");
            break;
        }
        if (!is_item(l)) {
            break; /* "key:" after a sequence at the key's indentation: the parent mapping goes on */
        }
        skip_spaces(l->text, n, &i);
        if (i >= n) {
            p->at++;
            item = yp_nested(p, indent, l->number, false, depth);
        } else if (key_colon(l->text + i, n - i) < n - i || is_item(&(yline_t){0, 0, l->text + i})) {
            /* "- key: value" (a mapping) or "- - x": the rest is a block at its own indentation */
            char *rest = xstrndup(l->text + i, n - i);
            free(l->text);
            l->text = rest;
            l->indent = indent + (int)i;
            item = yp_block(p, l->indent, depth + 1);
        } else {
            p->at++;
            item = yp_flow(p, l->text, n, &i, l->number, depth, false);
            if (item != NULL) {
                skip_spaces(l->text, n, &i);
                if (i < n) {
                    yp_fail(p, l->number, "unexpected text after the value: %.40s", l->text + i);
                }
            }
        }
        if (item == NULL) {
            break;
        }
        item->line = l->number;
        val_push(seq, item);
    }
    if (p->err[0]) {
        val_free(seq);
        return NULL;
    }
    return seq;
}

static val_t *yp_block(yp_t *p, int indent, int depth) {
    if (depth > 32) {
        yp_fail(p, p->lines[p->at].number, "collections nested too deeply");
        return NULL;
    }
    if (is_item(&p->lines[p->at])) {
        return yp_sequence(p, indent, depth);
    }
    if (key_colon(p->lines[p->at].text, strlen(p->lines[p->at].text)) == strlen(p->lines[p->at].text)) {
        /* a lone scalar or flow collection */
        yline_t *l = &p->lines[p->at];
        size_t i = 0;
        size_t n = strlen(l->text);
        val_t *v;
        p->at++;
        v = yp_flow(p, l->text, n, &i, l->number, depth, false);
        if (v != NULL && p->at < p->count && p->lines[p->at].indent >= indent) {
            yp_fail(p, p->lines[p->at].number,
                    "a multi-line scalar or flow collection is not in the YAML subset the C tool reads");
            val_free(v);
            return NULL;
        }
        return v;
    }
    return yp_mapping(p, indent, depth);
}

/* The document of a settings file: a mapping with line numbers, or NULL with "FILE:LINE: ..." in
 * msg. */
static val_t *yaml_load(const char *text, size_t n, const char *filename, char *msg, size_t cap) {
    yp_t p;
    val_t *doc = NULL;
    size_t i;
    memset(&p, 0, sizeof p);
    if (yp_split(&p, text, n)) {
        if (p.count == 0) {
            doc = val_new(V_MAP, 1);
        } else {
            doc = yp_block(&p, p.lines[0].indent, 0);
            if (doc != NULL && p.at < p.count) {
                yp_fail(&p, p.lines[p.at].number, "unexpected indentation");
            }
            if (p.err[0]) {
                val_free(doc);
                doc = NULL;
            }
        }
    }
    for (i = 0; i < p.count; i++) {
        free(p.lines[i].text);
    }
    free(p.lines);
    if (doc == NULL) {
        snprintf(msg, cap, "%s:%d: not valid YAML: %s", filename, p.err_line ? p.err_line : 1, p.err);
        return NULL;
    }
    if (doc->kind != V_MAP) {
        snprintf(msg, cap, "%s:1: expected a mapping of setting names to values", filename);
        val_free(doc);
        return NULL;
    }
    return doc;
}

/* ------------------------------------------------------------------------------ the spec */
static const dev_model_t *model_by_id(const char *id) {
    size_t i;
    for (i = 0; i < DEV_MODEL_COUNT; i++) {
        if (strcmp(DEV_MODELS[i].id, id) == 0) {
            return &DEV_MODELS[i];
        }
    }
    return NULL;
}

static int64_t function_value(const char *name) {
    size_t i;
    for (i = 0; i < DEV_FUNCTION_COUNT; i++) {
        if (strcmp(DEV_FUNCTIONS[i].name, name) == 0) {
            return DEV_FUNCTIONS[i].value;
        }
    }
    return -1;
}

static const char *set_name(uint8_t id) {
    size_t i;
    for (i = 0; DEV_SET_NAMES[i].name; i++) {
        if (DEV_SET_NAMES[i].id == id) {
            return DEV_SET_NAMES[i].name;
        }
    }
    return "";
}

static const char *enum_member(int index, int64_t value) {
    size_t i;
    if (index < 0) {
        return NULL;
    }
    for (i = 0; i < DEV_ENUMS[index].count; i++) {
        if (DEV_ENUMS[index].members[i].value == value) {
            return DEV_ENUMS[index].members[i].name;
        }
    }
    return NULL;
}

/* "3DM-CV7-GNSS/INS (3dm-cv7-ins-docs.txt)" */
static const char *describe_model(mipc_device_t d) {
    static char text[200];
    snprintf(text, sizeof text, "%s (%s)", mipc_device_title(d), mipc_device_manual(d));
    return text;
}

/* The field of a command set named name (the first set that has one). */
static const mipc_field_info_t *command_field(const char *name, uint8_t *set) {
    unsigned s;
    unsigned d;
    for (s = 0; s < 256; s++) {
        if (mipc_set_kind((uint8_t)s) != MIPC_SET_KIND_COMMAND) {
            continue;
        }
        for (d = 0; d < 256; d++) {
            mipc_status_t why;
            const mipc_field_info_t *f = mipc_find_field((uint8_t)s, (uint8_t)d, &why);
            if (f != NULL && f->descriptor == d && strcmp(f->name, name) == 0) {
                *set = (uint8_t)s;
                return f;
            }
        }
    }
    return NULL;
}

/* ------------------------------------------------------------------------------ connecting */
typedef struct {
    mipc_posix_t posix;
    mipc_transport_t transport;
    mipc_port_t port;
    mipc_link_t link;
    mipc_device_t device;
    const dev_model_t *model;
    val_t *identity;    /* item -> value */
    unsigned long baud; /* the serial port's rate (0: TCP) */
    const char *address;
    bool open;
    /* stream: the data set printed, how, and what was seen */
    int stream_set;
    bool stream_json;
    unsigned long stream_limit;
    unsigned long stream_count;
    double stream_first;
    double stream_last;
} conn_t;

static char g_line[64 * 1024];

static double now_s(void) {
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + (double)ts.tv_nsec / 1e9;
}

static void print_fields_text(const val_t *fields) {
    buf_t out = {0};
    size_t i;
    for (i = 0; fields && i < fields->n; i++) {
        const val_t *f = fields->items[i];
        const val_t *name = val_get(f, "name");
        const val_t *values = val_get(f, "values");
        if (name == NULL || values == NULL || name->kind != V_STR) {
            continue;
        }
        if (out.n) {
            buf_str(&out, " ");
        }
        buf_add(&out, name->text, name->len);
        buf_str(&out, " ");
        val_json(&out, values);
    }
    say("%s", buf_text(&out));
    free(out.s);
}

static void on_event(void *ctx, const mipc_session_event_t *ev) {
    conn_t *c = (conn_t *)ctx;
    size_t n;
    val_t *line;
    if (ev->kind != MIPC_SESSION_PACKET || c->stream_set < 0) {
        return;
    }
    if (mipc_packet_set(ev->stream->packet) != (uint8_t)c->stream_set) {
        return;
    }
    c->stream_last = now_s();
    if (c->stream_count == 0) {
        c->stream_first = c->stream_last;
    }
    c->stream_count++;
    if (c->stream_limit && c->stream_count > c->stream_limit) {
        return;
    }
    n = mipc_json_packet_line(ev->stream->packet, (size_t)ev->stream->length, ev->stream->offset, c->device,
                              g_line, sizeof g_line);
    if (n >= sizeof g_line) {
        n = sizeof g_line - 1;
    }
    if (c->stream_json) {
        say("%.*s", (int)n, g_line);
        return;
    }
    line = json_parse(g_line, n);
    print_fields_text(val_get(line, "fields"));
    val_free(line);
}

typedef enum { R_OK = 0, R_FAILED = 1, R_VALUE = 2, R_LOST = 3 } run_t;

typedef struct {
    mipc_result_kind_t kind;
    val_t *line; /* the result line, parsed */
    char describe[MIPC_SESSION_ERROR_MAX + 200];
    char json[8192]; /* the result line */
} result_t;

static void result_free(result_t *r) {
    val_free(r->line);
    r->line = NULL;
}

/* Python's Result.describe(). */
static void describe_result(result_t *r, const char *name, const mipc_result_t *res) {
    if (res->kind == MIPC_RESULT_NACK) {
        const char *code = enum_member(DEV_ACK_ENUM, (int64_t)res->code);
        if (code) {
            snprintf(r->describe, sizeof r->describe, "%s: NACK, code %u (%s)", name, (unsigned)res->code,
                     code);
        } else {
            snprintf(r->describe, sizeof r->describe, "%s: NACK, code %u", name, (unsigned)res->code);
        }
    } else if (res->kind == MIPC_RESULT_TIMEOUT) {
        snprintf(r->describe, sizeof r->describe, "%s: no reply before the timeout", name);
    } else if (res->kind == MIPC_RESULT_INVALID || res->kind == MIPC_RESULT_REFUSED) {
        snprintf(r->describe, sizeof r->describe, "%s: %s", name, res->error);
    } else {
        snprintf(r->describe, sizeof r->describe, "%s: %s", name, mipc_result_kind_name(res->kind));
    }
}

static char g_value_error[MIPC_ERROR_MESSAGE_MAX + 400];

/* Builds the command line of (set, descriptor) with the values (a JSON object) and runs it.
 * R_VALUE: the values do not fit the layout (g_value_error says why); R_LOST: the connection is
 * gone; R_OK: ack or sent; R_FAILED: nack, timeout, invalid, refused. */
static run_t run_values(conn_t *c, uint8_t set, uint8_t descriptor, const char *variant, const char *values,
                        result_t *r) {
    buf_t line = {0};
    mipc_field_value_t command;
    const mipc_field_info_t *f;
    mipc_status_t why;
    mipc_start_options_t opt;
    char msg[MIPC_ERROR_MESSAGE_MAX + 200];
    size_t n;
    memset(r, 0, sizeof *r);
    f = mipc_find_field(set, descriptor, &why);
    if (f == NULL) {
        snprintf(g_value_error, sizeof g_value_error, "0x%02X,0x%02X is not a field of the spec", set,
                 descriptor);
        return R_VALUE;
    }
    buf_fmt(&line, "{\"offset\":0,\"set\":%u,\"fields\":[{\"descriptor\":%u,\"name\":", set, descriptor);
    json_string(&line, f->name, strlen(f->name));
    if (f->layout_count > 1) {
        const char *dev = variant ? variant : mipc_device_id(c->device);
        buf_str(&line, ",\"device\":");
        json_string(&line, dev, strlen(dev));
    }
    buf_fmt(&line, ",\"values\":%s}]}", values);
    if (mipc_json_command_line(buf_text(&line), line.n, &command, msg, sizeof msg) != MIPC_OK) {
        copy_text(g_value_error, sizeof g_value_error, msg);
        free(line.s);
        return R_VALUE;
    }
    free(line.s);
    mipc_start_options_init(&opt);
    r->kind = mipc_link_run(&c->link, &command, &opt, NULL);
    n = mipc_json_result_line(&c->link.result, 1, c->device, r->json, sizeof r->json);
    if (n >= sizeof r->json) {
        n = sizeof r->json - 1;
    }
    r->line = json_parse(r->json, n);
    describe_result(r, f->name, &c->link.result);
    if (r->kind == MIPC_RESULT_TRANSPORT || r->kind == MIPC_RESULT_LOST) {
        copy_text(r->describe, sizeof r->describe, c->posix.error[0] ? c->posix.error : c->link.result.error);
        return R_LOST;
    }
    return r->kind == MIPC_RESULT_ACK || r->kind == MIPC_RESULT_SENT ? R_OK : R_FAILED;
}

/* The values of the first reply field named name (NULL: none). */
static const val_t *reply_values(const result_t *r, const char *name) {
    const val_t *reply = val_get(r->line, "reply");
    size_t i;
    for (i = 0; reply && reply->kind == V_LIST && i < reply->n; i++) {
        const val_t *nm = val_get(reply->items[i], "name");
        if (nm && nm->kind == V_STR && (name == NULL || strcmp(nm->text, name) == 0)) {
            return val_get(reply->items[i], "values");
        }
    }
    return NULL;
}

static void trim_identity(val_t *v) {
    /* strings: strip(" \0") */
    size_t a = 0;
    size_t b;
    if (v->kind != V_STR) {
        return;
    }
    b = v->len;
    while (a < b && (v->text[a] == ' ' || v->text[a] == '\0')) {
        a++;
    }
    while (b > a && (v->text[b - 1] == ' ' || v->text[b - 1] == '\0')) {
        b--;
    }
    memmove(v->text, v->text + a, b - a);
    v->len = b - a;
    v->text[v->len] = '\0';
}

static void read_identity(conn_t *c, result_t *r) {
    const mipc_field_info_t *reply;
    mipc_status_t why;
    size_t i;
    c->identity = val_new(V_MAP, 0);
    if (DEV_REPORT_COUNT == 0) {
        return;
    }
    reply = mipc_find_field(DEV_REPORTS[0].set, DEV_REPORTS[0].descriptor, &why);
    if (reply == NULL) {
        return;
    }
    for (i = 0; i < DEV_REPORT_COUNT; i++) {
        const val_t *v = reply_values(r, reply->name);
        size_t k;
        for (k = 0; DEV_REPORTS[i].path[k] && v; k++) {
            v = val_get(v, DEV_REPORTS[i].path[k]);
        }
        if (v != NULL) {
            val_t *copy = val_copy(v);
            trim_identity(copy);
            val_put(c->identity, DEV_REPORTS[i].item, strlen(DEV_REPORTS[i].item), 0, copy);
        }
    }
}

static const char *identity_text(const conn_t *c, const char *item, buf_t *b) {
    const val_t *v = val_get(c->identity, item);
    buf_reset(b);
    if (v == NULL) {
        return NULL;
    }
    if (v->kind == V_STR) {
        buf_add(b, v->text, v->len);
    } else {
        val_json(b, v);
    }
    return buf_text(b);
}

static void link_log(void *ctx, const char *line) {
    (void)ctx;
    fprintf(stderr, "%s\n", line);
    fflush(stderr);
}

static int start_link(conn_t *c, mipc_device_t device, bool check) {
    mipc_session_config_t config;
    mipc_link_options_t options;
    unsigned long timeout = c->link.session.config.timeout_ms;
    mipc_session_config_init(&config);
    config.device = device;
    config.check_device = check;
    config.timeout_ms = (uint32_t)timeout;
    config.on_event = on_event;
    config.ctx = c;
    if (mipc_link_init(&c->link, &c->transport, &config) != MIPC_OK) {
        return -1;
    }
    mipc_link_options_init(&options);
    options.log = link_log;
    options.reconnect_ms = 0;
    mipc_link_attach(&c->link, &c->port, &options);
    c->device = device;
    return 0;
}

/* No reply to the device information command: 1, as no reply to any command that was sent (the
 * outcomes below are defined after this function). */
#define EXIT_REFUSED_EARLY 1

/* Opens ADDRESS and identifies the device: 0, or the exit status. */
static int connect_device(conn_t *c, const char *address, const char *model, unsigned long baud,
                          unsigned long timeout_ms) {
    result_t r;
    buf_t b = {0};
    mipc_device_t found = MIPC_DEVICE_ANY;
    run_t run;
    const char *name;
    size_t i;
    c->address = address;
    c->stream_set = -1;
    if (mipc_posix_open(&c->posix, address, baud ? baud : DEFAULT_BAUD) != MIPC_OK) {
        note("%s", c->posix.error);
        return 2;
    }
    c->open = true;
    c->baud = c->posix.socket ? baud : (baud ? baud : DEFAULT_BAUD);
    mipc_posix_transport(&c->posix, &c->transport);
    mipc_posix_port(&c->posix, &c->port);
    c->link.session.config.timeout_ms = (uint32_t)timeout_ms;
    if (start_link(c, MIPC_DEVICE_ANY, false) != 0) {
        note("cannot start the session");
        return 2;
    }
    if (DEV_IDENTITY_SET == 0) {
        note("%s: the spec names no device information command", address);
        return 2;
    }
    run = run_values(c, DEV_IDENTITY_SET, DEV_IDENTITY_DESCRIPTOR, NULL, "{}", &r);
    if (run != R_OK) {
        note("%s: no answer to the device information command (%s)", address, r.describe);
        result_free(&r);
        return EXIT_REFUSED_EARLY; /* a device that does not answer: 1, as any command sent */
    }
    read_identity(c, &r);
    result_free(&r);
    if (model != NULL) {
        char said[MIPC_LINK_NOTE_MAX];
        mipc_device_from_id(model, &found);
        name = identity_text(c, "model_name", &b);
        if (name != NULL &&
            mipc_link_model_note(found, (const uint8_t *)name, strlen(name), said, sizeof said)) {
            note("%s", said); /* told another model: said, and the command goes on with it */
        }
    } else {
        name = identity_text(c, "model_name", &b);
        for (i = 0; name && name[0] && i < DEV_MODEL_COUNT; i++) {
            mipc_device_t d;
            if (mipc_device_from_id(DEV_MODELS[i].id, &d) &&
                (strcmp(DEV_MODELS[i].model_name, name) == 0 || strcmp(mipc_device_title(d), name) == 0)) {
                found = d;
                break;
            }
        }
        if (found == MIPC_DEVICE_ANY && DEV_MODEL_COUNT == 1) {
            mipc_device_from_id(DEV_MODELS[0].id, &found);
        }
        if (found == MIPC_DEVICE_ANY) {
            buf_t ids = {0};
            for (i = 0; i < DEV_MODEL_COUNT; i++) {
                buf_fmt(&ids, "%s%s", i ? ", " : "", DEV_MODELS[i].id);
            }
            note("%s: unknown model '%s'; give --device (%s)", address, name ? name : "", buf_text(&ids));
            free(ids.s);
            free(b.s);
            return 2;
        }
    }
    free(b.s);
    c->model = model_by_id(mipc_device_id(found));
    if (c->model == NULL || start_link(c, found, true) != 0) {
        note("cannot start the session");
        return 2;
    }
    return 0;
}

static void disconnect(conn_t *c) {
    if (c->open) {
        mipc_link_close(&c->link);
        mipc_posix_close(&c->posix);
        c->open = false;
    }
    val_free(c->identity);
    c->identity = NULL;
}

/* ------------------------------------------------------------------------------ outcomes */
/* Every subcommand returns its exit status; the messages are printed where they arise. */
#define EXIT_REFUSED 1
#define EXIT_TROUBLE 2

/* ------------------------------------------------------------------------------ settings */
static const dev_format_t *format_of(const dev_setting_t *s) {
    size_t i;
    for (i = 0; i < DEV_FORMAT_COUNT; i++) {
        if (DEV_FORMATS[i].cmd_set == s->set && DEV_FORMATS[i].cmd_descriptor == s->descriptor) {
            return &DEV_FORMATS[i];
        }
    }
    return NULL;
}

static const char *baud_param(const dev_setting_t *s) {
    size_t i;
    for (i = 0; i < DEV_BAUD_COUNT; i++) {
        if (DEV_BAUD[i].cmd_set == s->set && DEV_BAUD[i].cmd_descriptor == s->descriptor) {
            return DEV_BAUD[i].param;
        }
    }
    return NULL;
}

static bool is_keyed(const dev_setting_t *s, const char *attr) {
    size_t i;
    for (i = 0; i < s->keyed_count; i++) {
        if (strcmp(s->keyed[i], attr) == 0) {
            return true;
        }
    }
    return false;
}

static const dev_attr_t *attr_of(const dev_setting_t *s, const char *name) {
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
static void py_str(buf_t *b, const val_t *v) {
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

static void key_text(buf_t *b, const dev_setting_t *s, const val_t *entry) {
    size_t i;
    buf_reset(b);
    for (i = 0; i < s->keyed_count; i++) {
        buf_fmt(b, "%s%s ", i ? ", " : "", s->keyed[i]);
        py_str(b, val_get(entry, s->keyed[i]));
    }
}

/* Whether a equals b ignoring ASCII case (an enum member given in any case, as value.upper()). */
static bool strcasecmp_ascii_eq(const char *a, const char *b) {
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
static bool command_values(const dev_setting_t *s, const val_t *entry, int64_t function, buf_t *out,
                           char *err, size_t cap) {
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
static run_t read_entry(conn_t *c, const dev_setting_t *s, const val_t *key, val_t **entry, bool *nack,
                        char *msg, size_t cap) {
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

/* An entry as the device would report it: through the command's encoding (f32 rounding, enum
 * names), so that a file and a device compare equal when the wire values are. NULL with err. */
static val_t *normalized(conn_t *c, const dev_setting_t *s, const val_t *entry, char *err, size_t cap) {
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
        if (at != NULL) {
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

/* ------------------------------------------------------------------------------ the link budget */
#define FORMAT_MAX 256
typedef struct {
    bool present;
    size_t n;
    uint16_t descriptor[FORMAT_MAX];
    uint32_t decimation[FORMAT_MAX];
} format_t;

/* set -> message format; set -> base rate (0: unknown) */
typedef struct {
    format_t set[256];
} formats_t;

static void formats_from_list(format_t *f, const val_t *list, const dev_format_t *spec) {
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
static const dev_setting_t *format_setting(const conn_t *c, int set, const char **param) {
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

static val_t *key_map(const char *param, int set) {
    val_t *key = val_new(V_MAP, 0);
    if (param) {
        char text[16];
        snprintf(text, sizeof text, "%d", set);
        val_put(key, param, strlen(param), 0, val_number(V_INT, text, 0));
    }
    return key;
}

/* Every data set's current message format; 0, or the exit status (the message printed). */
static int read_formats(conn_t *c, formats_t *out) {
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
static int read_base_rates(conn_t *c, double *rates) {
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
            if (!mipc_device_supports(c->device, rq->cmd_set, rq->cmd_descriptor)) {
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
static const double g_word_bits = MIPC_LINK_UART_WORD_BITS;

static int field_size(const conn_t *c, int set, int descriptor) {
    size_t i;
    int shared = -1;
    for (i = 0; i < c->model->size_count; i++) {
        if (c->model->sizes[i].set == set && c->model->sizes[i].descriptor == descriptor) {
            return c->model->sizes[i].size + MIPC_LINK_FIELD_OVERHEAD;
        }
        if (g_shared_set >= 0 && c->model->sizes[i].set == g_shared_set &&
            c->model->sizes[i].descriptor == descriptor) {
            shared = c->model->sizes[i].size + MIPC_LINK_FIELD_OVERHEAD;
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
        bits = MIPC_LINK_UART_WORD_BITS * (MIPC_LINK_PACKET_OVERHEAD * packet_hz + sum);
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
static void print_lines(FILE *to, const char *prefix, const char *text) {
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
static int check_budget(const conn_t *c, const formats_t *formats, const double *base, unsigned long baud,
                        const char *where, bool force, buf_t *lines) {
    double total;
    if (!MIPC_LINK_HAS_BANDWIDTH) {
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
static unsigned long link_baud(conn_t *c, unsigned long option, char *where, size_t cap) {
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

/* ------------------------------------------------------------------------------ options */
typedef struct {
    const char *model;
    unsigned long baud;
    unsigned long timeout_ms;
    double rate;
    double duration;
    unsigned long count;
    double split_size; /* record: --split-size BYTES, --split-time S */
    double split_time;
    bool json;
    bool force;
    bool keep;
    bool save;
    const char **pos; /* the positional arguments after the subcommand (and its action) */
    size_t npos;
    const char **ports; /* auto: --ports PATH ... (NULL: the system's serial ports) */
    size_t nports;
} opts_t;

/* ------------------------------------------------------------------------------ subcommands */
static int cmd_ping(conn_t *c, const opts_t *o) {
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

static int cmd_info(conn_t *c, const opts_t *o) {
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

/* Whether the command's layout has a function selector: probes the JSON reader. */
static bool has_function(const conn_t *c, uint8_t set, const mipc_field_info_t *f) {
    buf_t line = {0};
    mipc_field_value_t command;
    char msg[MIPC_ERROR_MESSAGE_MAX + 200];
    bool yes;
    buf_fmt(&line, "{\"offset\":0,\"set\":%u,\"fields\":[{\"descriptor\":%u,\"name\":", set, f->descriptor);
    json_string(&line, f->name, strlen(f->name));
    if (f->layout_count > 1) {
        buf_fmt(&line, ",\"device\":\"%s\"", mipc_device_id(c->device));
    }
    buf_str(&line, ",\"values\":{\"function\":1}}]}");
    msg[0] = '\0';
    yes = mipc_json_command_line(buf_text(&line), line.n, &command, msg, sizeof msg) == MIPC_OK ||
          strstr(msg, "unknown key \"function\"") == NULL;
    free(line.s);
    return yes;
}

/* The parameters a command's write leaves out (", " between, in the layout's order), for a
 * command that is no setting: the values given are read by the JSON reader, and every parameter it
 * says is missing is added (as 0) and read again. */
static void missing_params(conn_t *c, uint8_t set, const mipc_field_info_t *f, const char *values,
                           buf_t *out) {
    buf_t probe = {0};
    mipc_field_value_t command;
    char msg[MIPC_ERROR_MESSAGE_MAX + 200];
    int round;
    buf_str(&probe, values);
    for (round = 0; round < 64; round++) {
        buf_t line = {0};
        const char *at;
        const char *end;
        mipc_status_t st;
        buf_fmt(&line, "{\"offset\":0,\"set\":%u,\"fields\":[{\"descriptor\":%u,\"name\":", set,
                f->descriptor);
        json_string(&line, f->name, strlen(f->name));
        if (f->layout_count > 1) {
            buf_fmt(&line, ",\"device\":\"%s\"", mipc_device_id(c->device));
        }
        buf_fmt(&line, ",\"values\":%s}]}", buf_text(&probe));
        msg[0] = '\0';
        st = mipc_json_command_line(buf_text(&line), line.n, &command, msg, sizeof msg);
        free(line.s);
        at = strstr(msg, "missing parameter \"");
        if (st == MIPC_OK || at == NULL) {
            break;
        }
        at += strlen("missing parameter \"");
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

/* send NAME write P=V ... with parameters left out: a setting (a command the model also reads) is
 * read first (with the key parameters given) and the given parameters replace its values (read,
 * modify, write): *values becomes the write's; any other command needs every parameter. 0, or the
 * exit status (the message printed). */
static int complete_write(conn_t *c, uint8_t set, const mipc_field_info_t *f, const val_t *given,
                          buf_t *values, const char **variant) {
    const dev_setting_t *s = NULL;
    buf_t missing = {0};
    size_t i;
    int status = 0;
    for (i = 0; i < c->model->setting_count; i++) {
        if (c->model->settings[i].set == set && c->model->settings[i].descriptor == f->descriptor) {
            s = &c->model->settings[i];
        }
    }
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
        buf_t absent = {0};
        val_t *key = val_new(V_MAP, 0);
        val_t *entry = NULL;
        bool nack;
        char msg[1000];
        run_t run;
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
            buf_t kept = {0};
            for (i = 0; i < s->attr_count; i++) {
                const char *a = s->attrs[i].name;
                const val_t *v = val_get(given, a);
                if (v == NULL) {
                    buf_fmt(&kept, "%s%s", kept.n ? ", " : "", a);
                    continue;
                }
                {
                    long at = val_index(entry, a);
                    if (at >= 0) {
                        val_free(entry->items[at]);
                        entry->items[at] = val_copy(v);
                    } else {
                        val_put(entry, a, strlen(a), 0, val_copy(v));
                    }
                }
            }
            note("%s: %s as read from the device (read, modify, write)", f->name, buf_text(&kept));
            free(kept.s);
            if (!command_values(s, entry, function_value("write"), values, msg, sizeof msg)) {
                note("%s", msg);
                status = EXIT_TROUBLE;
            }
            *variant = s->device;
        }
        val_free(entry);
        val_free(key);
        free(absent.s);
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

static int cmd_send(conn_t *c, const opts_t *o) {
    uint8_t set = 0;
    const mipc_field_info_t *f;
    buf_t values = {0};
    size_t i = 1;
    result_t r;
    run_t run;
    const val_t *reply;
    bool first = true;
    bool write = false;
    const char *variant = NULL;
    val_t *given;
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
    buf_str(&values, "{");
    if (has_function(c, set, f)) {
        int64_t fn;
        if (o->npos < 2 || strchr(o->pos[1], '=') != NULL) {
            buf_t names = {0};
            function_names(&names);
            note("%s: give the function first (%s)", f->name, buf_text(&names));
            free(names.s);
            free(values.s);
            val_free(given);
            return EXIT_TROUBLE;
        }
        fn = function_value(o->pos[1]);
        if (fn < 0) {
            buf_t names = {0};
            function_names(&names);
            note("unknown function (one of: %s)", buf_text(&names));
            free(names.s);
            free(values.s);
            val_free(given);
            return EXIT_TROUBLE;
        }
        buf_fmt(&values, "\"function\":%lld", (long long)fn);
        write = fn == function_value("write");
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
            val_free(given);
            return EXIT_TROUBLE;
        }
        if (!first) {
            buf_str(&values, ",");
        }
        first = false;
        json_string(&values, arg, (size_t)(eq - arg));
        buf_str(&values, ":");
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
                    buf_fmt(&values, "%lld", (long long)DEV_ENUMS[e].members[k].value);
                    found = true;
                }
            }
            if (!found) {
                note("%s.%.*s: '%s' is not a member of %s", f->name, (int)(eq - arg), arg, v->text,
                     DEV_ENUMS[e].name);
                val_free(v);
                free(values.s);
                val_free(given);
                return EXIT_TROUBLE;
            }
        } else {
            val_json(&values, v);
        }
        val_free(v);
    }
    buf_str(&values, "}");
    if (write) {
        int status = complete_write(c, set, f, given, &values, &variant);
        if (status) {
            val_free(given);
            free(values.s);
            return status;
        }
    }
    val_free(given);
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

static int run_all_settings(conn_t *c, const char *function) {
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

static int cmd_save(conn_t *c, const opts_t *o) {
    int status = run_all_settings(c, "save");
    (void)o;
    if (status == 0) {
        say("current settings saved as startup settings");
    }
    return status;
}

static int cmd_factory(conn_t *c, const opts_t *o) {
    int status = run_all_settings(c, "default");
    (void)o;
    if (status == 0) {
        say("factory default settings loaded (not saved: save-startup saves them)");
    }
    return status;
}

/* ------------------------------------------------------------------------------ settings dump */
static void package_name(char *out, size_t cap) {
    const char *dash = strrchr(PROG, '-');
    snprintf(out, cap, "%.*s", (int)(dash ? dash - PROG : (long)strlen(PROG)), PROG);
}

static int cmd_dump(conn_t *c, const opts_t *o) {
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

/* ------------------------------------------------------------------------------ settings files */
typedef struct {
    const dev_setting_t *setting;
    val_t **entries; /* normalized */
    int *lines;
    size_t count;
} planned_t;

typedef struct {
    planned_t *items;
    size_t count;
    char **problems;
    size_t problem_count;
} plan_t;

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
        if (!mipc_device_supports(c->device, s->set, s->descriptor)) {
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

typedef struct {
    const dev_setting_t *setting;
    char key[300];
    val_t *device; /* normalized device values */
    const val_t *file;
} change_t;

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

static int cmd_diff(conn_t *c, const opts_t *o) {
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

static int cmd_apply(conn_t *c, const opts_t *o) {
    plan_t plan;
    change_t *changes = NULL;
    size_t count = 0;
    size_t i;
    size_t k;
    int status;
    formats_t *formats;
    bool touched = false;
    buf_t x = {0};
    buf_t y = {0};
    size_t written = 0;
    if (o->npos < 1) {
        note("settings apply: give the FILE");
        return EXIT_TROUBLE;
    }
    status = load_plan(c, o->pos[0], &plan);
    if (status) {
        return status;
    }
    formats = (formats_t *)xalloc(sizeof *formats);
    status = read_formats(c, formats);
    for (i = 0; status == 0 && i < plan.count; i++) {
        const dev_format_t *spec = format_of(plan.items[i].setting);
        for (k = 0; spec && k < plan.items[i].count; k++) {
            const val_t *entry = plan.items[i].entries[k];
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
        for (i = 0; i < plan.count; i++) { /* the file's baud rate */
            const char *param = baud_param(plan.items[i].setting);
            const val_t *v;
            if (param == NULL || plan.items[i].setting->keyed_count || plan.items[i].count == 0) {
                continue;
            }
            v = val_get(plan.items[i].entries[0], param);
            if (v && v->kind == V_INT) {
                baud = strtoul(v->text, NULL, 10);
                snprintf(where, sizeof where, " (the file's %s)", plan.items[i].setting->name);
                break;
            }
        }
        if (i == plan.count) {
            baud = link_baud(c, o->baud, where, sizeof where);
        }
        status = read_base_rates(c, base);
        if (status == 0) {
            status = check_budget(c, formats, base, baud, where, o->force, &lines);
        }
        free(lines.s);
    }
    free(formats);
    if (status == 0) {
        status = differences(c, &plan, &changes, &count, false);
    }
    if (status == 0) {
        /* a baud rate change goes last: the link follows it (a stable order otherwise) */
        change_t *ordered = (change_t *)xalloc((count ? count : 1) * sizeof *ordered);
        size_t n = 0;
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
        changes = ordered;
        if (count == 0) {
            say("nothing to write: the device matches the file");
        }
        for (i = 0; i < count && status == 0; i++) {
            const change_t *ch = &changes[i];
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
            what_of(ch, what, sizeof what);
            for (a = 0; a < s->keyed_count; a++) {
                val_put(key, s->keyed[a], strlen(s->keyed[a]), 0, val_copy(val_get(ch->file, s->keyed[a])));
            }
            command_values(s, ch->file, function_value("write"), &values, msg, sizeof msg);
            run = run_values(c, s->set, s->descriptor, s->device, buf_text(&values), &r);
            free(values.s);
            if (run == R_OK && is_baud_setting(s) && c->baud && c->port.set_baud) {
                const val_t *v = val_get(ch->file, baud_param(s));
                if (v && v->kind == V_INT) {
                    unsigned long rate = strtoul(v->text, NULL, 10);
                    if (MIPC_LINK_BAUD_SETTLE_MS > 0) {
                        struct timespec ts = {MIPC_LINK_BAUD_SETTLE_MS / 1000,
                                              (long)(MIPC_LINK_BAUD_SETTLE_MS % 1000) * 1000000L};
                        nanosleep(&ts, NULL);
                    }
                    c->port.set_baud(c->port.ctx, (uint32_t)rate);
                    c->baud = rate;
                }
            }
            if (run != R_OK) {
                note("%s: %s (%zu of %zu settings written before it)", what,
                     run == R_VALUE ? g_value_error : r.describe, written, count);
                status = EXIT_REFUSED;
            } else if (read_entry(c, s, key, &back, &nack, msg, sizeof msg) != R_OK) {
                note("%s: %s (%zu of %zu settings written before it)", what, msg, written, count);
                status = EXIT_REFUSED;
            } else if ((back_norm = normalized(c, s, back, msg, sizeof msg)) == NULL) {
                note("%s: %s (%zu of %zu settings written before it)", what, msg, written, count);
                status = EXIT_REFUSED;
            } else {
                written++;
                if (!val_equal(back_norm, ch->file)) {
                    buf_t t = {0};
                    val_json(&t, back_norm);
                    note("%s: written, but it reads back as %s (%zu of %zu written)", what, buf_text(&t),
                         written, count);
                    free(t.s);
                    status = EXIT_REFUSED;
                } else {
                    buf_t line = {0};
                    for (a = 0; a < ch->file->n; a++) {
                        const val_t *before = val_get(ch->device, ch->file->keys[a]);
                        const val_t *v = ch->file->items[a];
                        if (!val_equal(before, v)) {
                            buf_fmt(&line, "%s%s: %s -> %s", line.n ? "; " : "", ch->file->keys[a],
                                    flow_text(&x, before), flow_text(&y, v));
                        }
                    }
                    say("%s: %s", what, buf_text(&line));
                    free(line.s);
                }
            }
            if (run != R_VALUE) {
                result_free(&r);
            }
            val_free(key);
            val_free(back);
            val_free(back_norm);
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
    free(x.s);
    free(y.s);
    plan_free(&plan);
    return status;
}

/* ------------------------------------------------------------------------------ stream */
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
        mipc_status_t why;
        const mipc_field_info_t *f;
        free(a);
        if (bad) {
            note("bad data field '%s' (a name or SET:DESCRIPTOR, e.g. 0x80:0x04)", text);
            return EXIT_TROUBLE;
        }
        f = mipc_find_field((uint8_t)x, (uint8_t)y, &why);
        if (f == NULL || mipc_set_kind((uint8_t)x) != MIPC_SET_KIND_DATA) {
            note("0x%02lX:0x%02lX is not a data field of the spec", x, y);
            return EXIT_TROUBLE;
        }
        *set = (int)x;
        *descriptor = (int)y;
        return 0;
    }
    for (s = 0; s < 256; s++) {
        if (mipc_set_kind((uint8_t)s) != MIPC_SET_KIND_DATA) {
            continue;
        }
        for (d = 0; d < 256; d++) {
            mipc_status_t why;
            const mipc_field_info_t *f = mipc_find_field((uint8_t)s, (uint8_t)d, &why);
            if (f != NULL && strcmp(f->name, text) == 0 &&
                mipc_device_supports(c->device, (uint8_t)s, (uint8_t)d)) {
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
static int enable_stream(conn_t *c, int set) {
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
        if (!mipc_device_supports(c->device, e->cmd_set, e->cmd_descriptor)) {
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

static int cmd_stream(conn_t *c, const opts_t *o) {
    int set = -1;
    size_t i;
    int fields[FORMAT_MAX];
    size_t nf = 0;
    const dev_setting_t *s;
    const char *param = NULL;
    double base[256] = {0};
    double hz;
    double rate;
    unsigned long decimation;
    formats_t *formats;
    char where[300];
    unsigned long baud;
    buf_t lines = {0};
    val_t *key;
    val_t *previous = NULL;
    val_t *entry;
    val_t *list;
    const dev_format_t *spec;
    buf_t values = {0};
    char msg[1000];
    bool nack;
    result_t r;
    run_t run;
    int status;
    double end;
    double observed;
    unsigned long shown;
    if (o->npos < 1) {
        note("stream: give the data fields (names or SET:DESCRIPTOR)");
        return EXIT_TROUBLE;
    }
    for (i = 0; i < o->npos && nf < FORMAT_MAX; i++) {
        int fs;
        int fd;
        status = data_field(c, o->pos[i], &fs, &fd);
        if (status) {
            return status;
        }
        if (set >= 0 && fs != set) {
            note("stream: give fields of one data set");
            return EXIT_TROUBLE;
        }
        set = fs;
        fields[nf++] = fd;
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
    formats = (formats_t *)xalloc(sizeof *formats);
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
    if (status) {
        free(lines.s);
        return status;
    }
    print_lines(stderr, PROG ": link budget: ", buf_text(&lines));
    free(lines.s);
    key = key_map(param, set);
    run = read_entry(c, s, key, &previous, &nack, msg, sizeof msg);
    if (run != R_OK) {
        note("%s", msg);
        val_free(key);
        return run == R_FAILED ? EXIT_REFUSED : EXIT_TROUBLE;
    }
    entry = val_copy(previous);
    list = val_new(V_LIST, 0);
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
    {
        long at = val_index(entry, spec->list);
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
    }
    c->stream_set = set;
    c->stream_json = o->json;
    c->stream_limit = o->count;
    signal(SIGINT, on_sigint);
    status = 0;
    if (!command_values(s, entry, function_value("write"), &values, msg, sizeof msg)) {
        note("%s", msg);
        status = EXIT_TROUBLE;
    } else {
        run = run_values(c, s->set, s->descriptor, s->device, buf_text(&values), &r);
        if (run != R_OK) {
            note("%s", run == R_VALUE ? g_value_error : r.describe);
            status = run == R_FAILED ? EXIT_REFUSED : EXIT_TROUBLE;
        }
        result_free(&r);
    }
    free(values.s);
    if (status == 0) {
        status = enable_stream(c, set);
    }
    end = o->duration > 0 ? now_s() + o->duration : HUGE_VAL;
    while (status == 0 && !g_interrupted && now_s() < end && !(o->count && c->stream_count >= o->count)) {
        double left = end - now_s();
        double wait = left * 1000 < 200 ? left * 1000 : 200;
        if (mipc_link_pump(&c->link, (uint32_t)(wait > 0 ? wait : 0)) < 0) {
            note("%s", c->posix.error);
            status = EXIT_TROUBLE;
        }
    }
    c->stream_set = -1;
    if (!o->keep) {
        buf_t restore = {0};
        if (command_values(s, previous, function_value("write"), &restore, msg, sizeof msg)) {
            /* the previous entry holds the key parameters already (they are its attributes) */
            run = run_values(c, s->set, s->descriptor, s->device, buf_text(&restore), &r);
            if (run != R_OK) {
                note("could not restore the previous message format");
            }
            result_free(&r);
        } else {
            note("could not restore the previous message format");
        }
        free(restore.s);
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

/* ------------------------------------------------------------------------------ record */
static int cmd_record(const char *address, const opts_t *o) {
    device_record_options_t r;
    if (o->npos != 1) {
        note("record: give one FILE");
        return EXIT_TROUBLE;
    }
    if (DEV_IDENTITY_SET == 0 || DEV_REPORT_COUNT == 0) {
        note("the spec names no device information command");
        return EXIT_TROUBLE;
    }
    memset(&r, 0, sizeof r);
    r.address = address;
    r.path = o->pos[0];
    r.baud = o->baud ? o->baud : DEFAULT_BAUD;
    r.timeout_ms = o->timeout_ms;
    r.duration = o->duration;
    r.split_size = o->split_size;
    r.split_time = o->split_time;
    r.command_set = DEV_IDENTITY_SET;
    r.command_descriptor = DEV_IDENTITY_DESCRIPTOR;
    r.reply_set = DEV_REPORTS[0].set;
    r.reply_descriptor = DEV_REPORTS[0].descriptor;
    return device_record(&r);
}

/* ------------------------------------------------------------------------------ auto */
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
        mipc_device_t d;
        const uint32_t *rates;
        if (!mipc_device_from_id(DEV_MODELS[m].id, &d)) {
            continue;
        }
        rates = mipc_device_baud_rates(d, &count);
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
static int cmd_auto(const opts_t *o) {
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
                say("%s %lu %s (%s) serial %s", ports[p], rates[r], mipc_device_title(conn.device),
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

/* ------------------------------------------------------------------------------ main */
#define USAGE                                                                                                \
    "usage: " PROG " ADDRESS SUBCOMMAND [OPTIONS]\n"                                                         \
    "  ADDRESS: tcp:HOST:PORT, a serial port path, or auto (auto ping [--ports PATH ...])\n"                 \
    "  ping | info | send NAME [FUNCTION] [PARAM=VALUE ...] [--json] | save-startup | factory-reset\n"       \
    "  stream FIELD ... [--rate HZ] [--duration S] [--count N] [--json] [--force] [--keep]\n"                \
    "  settings dump [FILE|-] | settings diff FILE | settings apply FILE [--save] [--force]\n"               \
    "  record FILE [--duration S] [--split-size BYTES] [--split-time S] (docs/record.md)\n"                  \
    "  options of every subcommand: --device ID, --baud N, --timeout-ms N\n"                                 \
    "Exit status: 0 done; 1 the device said no or differs; 2 nothing was changed (usage, bad file, refused " \
    "before sending)."

static int usage(const char *fmt, const char *arg) {
    fprintf(stderr, PROG ": ");
    fprintf(stderr, fmt, arg);
    fprintf(stderr, " (" PROG " --help)\n");
    return EXIT_TROUBLE;
}

static bool number_option(const char *name, const char *text, double *out) {
    char *end;
    errno = 0;
    *out = strtod(text, &end);
    if (*text == '\0' || *end != '\0' || errno != 0 || !(*out >= 0) || *out > 4e9) {
        fprintf(stderr, PROG ": %s needs a number >= 0, not '%s'\n", name, text);
        return false;
    }
    return true;
}

static bool int_option(const char *name, const char *text, unsigned long *out) {
    double v;
    if (!number_option(name, text, &v)) {
        return false;
    }
    if (v != floor(v)) {
        fprintf(stderr, PROG ": %s needs an integer, not '%s'\n", name, text);
        return false;
    }
    *out = (unsigned long)v;
    return true;
}

int main(int argc, char **argv) {
    static conn_t conn;
    opts_t o;
    const char **pos = (const char **)xalloc((size_t)argc * sizeof *pos);
    size_t npos = 0;
    const char *sub;
    const char *action = NULL;
    int status;
    int i;
    memset(&o, 0, sizeof o);
    o.timeout_ms = 1000;
    for (i = 1; i < argc; i++) {
        const char *a = argv[i];
        const char *eq = strchr(a, '=');
        char name[32];
        const char *value = NULL;
        size_t n;
        if (strcmp(a, "-h") == 0 || strcmp(a, "--help") == 0) {
            printf("%s\n", USAGE);
            free(pos);
            return 0;
        }
        if (strncmp(a, "--", 2) != 0 || a[2] == '\0') {
            pos[npos++] = a;
            continue;
        }
        n = eq ? (size_t)(eq - a) : strlen(a);
        if (n >= sizeof name) {
            free(pos);
            return usage("unknown option '%s'", a);
        }
        memcpy(name, a, n);
        name[n] = '\0';
        if (strcmp(name, "--json") == 0 || strcmp(name, "--force") == 0 || strcmp(name, "--keep") == 0 ||
            strcmp(name, "--save") == 0) {
            if (eq) {
                free(pos);
                return usage("%s takes no value", name);
            }
            o.json = o.json || strcmp(name, "--json") == 0;
            o.force = o.force || strcmp(name, "--force") == 0;
            o.keep = o.keep || strcmp(name, "--keep") == 0;
            o.save = o.save || strcmp(name, "--save") == 0;
            continue;
        }
        if (strcmp(name, "--ports") == 0) {
            /* auto: the paths up to the next option */
            if (eq) {
                free(pos);
                return usage("%s takes paths after it, not '='", name);
            }
            if (o.ports != NULL) {
                free(pos);
                return usage("%s is given once", name);
            }
            o.ports = (const char **)(argv + i + 1); /* the paths stay in argv */
            while (i + 1 < argc && strncmp(argv[i + 1], "--", 2) != 0) {
                o.nports++;
                i++;
            }
            if (o.nports == 0) {
                free(pos);
                return usage("%s needs at least one path", name);
            }
            continue;
        }
        if (strcmp(name, "--device") != 0 && strcmp(name, "--baud") != 0 &&
            strcmp(name, "--timeout-ms") != 0 && strcmp(name, "--rate") != 0 &&
            strcmp(name, "--duration") != 0 && strcmp(name, "--count") != 0 &&
            strcmp(name, "--split-size") != 0 && strcmp(name, "--split-time") != 0) {
            free(pos);
            return usage("unknown option '%s'", a);
        }
        if (eq) {
            value = eq + 1;
        } else if (i + 1 < argc) {
            value = argv[++i];
        } else {
            free(pos);
            return usage("%s needs a value", name);
        }
        if (strcmp(name, "--device") == 0) {
            o.model = value;
        } else if ((strcmp(name, "--baud") == 0 && !int_option(name, value, &o.baud)) ||
                   (strcmp(name, "--timeout-ms") == 0 && !int_option(name, value, &o.timeout_ms)) ||
                   (strcmp(name, "--count") == 0 && !int_option(name, value, &o.count)) ||
                   (strcmp(name, "--rate") == 0 && !number_option(name, value, &o.rate)) ||
                   (strcmp(name, "--duration") == 0 && !number_option(name, value, &o.duration)) ||
                   (strcmp(name, "--split-size") == 0 && !number_option(name, value, &o.split_size)) ||
                   (strcmp(name, "--split-time") == 0 && !number_option(name, value, &o.split_time))) {
            free(pos);
            return EXIT_TROUBLE;
        }
    }
    if (npos < 2) {
        free(pos);
        return usage("%s", "give ADDRESS and SUBCOMMAND");
    }
    sub = pos[1];
    o.pos = pos + 2;
    o.npos = npos - 2;
    if (strcmp(sub, "settings") == 0) {
        if (o.npos < 1) {
            free(pos);
            return usage("%s", "settings: give dump, diff or apply");
        }
        action = o.pos[0];
        o.pos++;
        o.npos--;
        if (strcmp(action, "dump") != 0 && strcmp(action, "diff") != 0 && strcmp(action, "apply") != 0) {
            free(pos);
            if (strcmp(action, "schema") == 0) {
                return usage(
                    "%s", "settings schema: the JSON Schema is the Python package's (settings.schema.json)");
            }
            return usage("settings: unknown action '%s' (dump, diff, apply)", action);
        }
    } else if (strcmp(sub, "ping") != 0 && strcmp(sub, "info") != 0 && strcmp(sub, "send") != 0 &&
               strcmp(sub, "stream") != 0 && strcmp(sub, "save-startup") != 0 &&
               strcmp(sub, "factory-reset") != 0 && strcmp(sub, "record") != 0) {
        free(pos);
        return usage("unknown subcommand '%s'", sub);
    }
    if (o.model != NULL && model_by_id(o.model) == NULL) {
        buf_t ids = {0};
        size_t m;
        for (m = 0; m < DEV_MODEL_COUNT; m++) {
            buf_fmt(&ids, "%s%s", m ? ", " : "", DEV_MODELS[m].id);
        }
        note("unknown device '%s' (one of: %s)", o.model, buf_text(&ids));
        free(ids.s);
        free(pos);
        return EXIT_TROUBLE;
    }
    if (strcmp(pos[0], "auto") == 0) {
        free(pos);
        if (strcmp(sub, "ping") != 0) {
            return usage("%s", "auto lists the devices that answer: use `auto ping`");
        }
        return cmd_auto(&o);
    }
    if (o.ports != NULL) {
        free(pos);
        return usage("%s", "--ports goes with auto");
    }
    if (strcmp(sub, "record") == 0) { /* the device's own bytes: no session in between */
        status = cmd_record(pos[0], &o);
        free(pos);
        return status;
    }
    status = connect_device(&conn, pos[0], o.model, o.baud, o.timeout_ms);
    if (status == 0) {
        if (action != NULL) {
            status = strcmp(action, "dump") == 0   ? cmd_dump(&conn, &o)
                     : strcmp(action, "diff") == 0 ? cmd_diff(&conn, &o)
                                                   : cmd_apply(&conn, &o);
        } else if (strcmp(sub, "ping") == 0) {
            status = cmd_ping(&conn, &o);
        } else if (strcmp(sub, "info") == 0) {
            status = cmd_info(&conn, &o);
        } else if (strcmp(sub, "send") == 0) {
            status = cmd_send(&conn, &o);
        } else if (strcmp(sub, "stream") == 0) {
            status = cmd_stream(&conn, &o);
        } else if (strcmp(sub, "save-startup") == 0) {
            status = cmd_save(&conn, &o);
        } else {
            status = cmd_factory(&conn, &o);
        }
    }
    disconnect(&conn);
    free(pos);
    return status;
}
