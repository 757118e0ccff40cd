/* Settings files in: the YAML subset of device.h, read into values with their line numbers; every
 * refusal is one located FILE:LINE: message. Generated: do not edit. */
#include "device.h"

static void yp_vfail(yp_t *p, int line, bool rule, const char *fmt, va_list ap) {
    if (p->err[0]) {
        return;
    }
    p->err_line = line;
    p->rule = rule;
    vsnprintf(p->err, sizeof p->err, fmt, ap);
    if (!p->err[0]) {
        snprintf(p->err, sizeof p->err, "not valid YAML");
    }
}

/* A text that is not in the YAML subset: "FILE:LINE: not valid YAML: ..." */
static void yp_fail(yp_t *p, int line, const char *fmt, ...) {
    va_list ap;
    va_start(ap, fmt);
    yp_vfail(p, line, false, fmt, ap);
    va_end(ap);
}

/* Valid YAML that a settings file may not be (a key that is no name, a key given twice), as the
 * Python CLI says it: "FILE:LINE: ..." */
static void yp_rule(yp_t *p, int line, const char *fmt, ...) {
    va_list ap;
    va_start(ap, fmt);
    yp_vfail(p, line, true, fmt, ap);
    va_end(ap);
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
                dv = (unsigned)mscipc_hex_value(d[i]);
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
                char out[MSCIPC_JSON_NUMBER_MAX];
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
                mscipc_json_format_double(x, out, sizeof out);
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
                    int h = k + 2 + j < n ? mscipc_hex_value(s[k + 2 + j]) : -1;
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

/* One key: value entry of a flow mapping at s[*i], put into v: false after yp_fail. */
static bool yp_flow_entry(yp_t *p, const char *s, size_t n, size_t *i, int line, int depth, val_t *v) {
    val_t *item;
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
            return false;
        }
        if (refused_start(p, s[start], line)) {
            return false;
        }
        key = yp_resolve(p, s + start, *i - start, line);
    }
    if (key == NULL) {
        return false;
    }
    skip_spaces(s, n, i);
    if (key->kind != V_STR) {
        buf_t t = {0};
        yp_rule(p, line, "a key must be a name, not %s", flow_text(&t, key));
        free(t.s);
        val_free(key);
        return false;
    }
    if (*i >= n || s[*i] != ':') {
        yp_fail(p, line, "expected ':' after the key %s of a flow mapping", key->text);
        val_free(key);
        return false;
    }
    (*i)++;
    if (val_index(v, key->text) >= 0) {
        yp_rule(p, line, "'%s' given twice (first on line %d)", key->text, line);
        val_free(key);
        return false;
    }
    skip_spaces(s, n, i);
    if (*i < n && (s[*i] == ',' || s[*i] == '}')) {
        item = val_new(V_NULL, line);
    } else {
        item = yp_flow(p, s, n, i, line, depth + 1, true);
    }
    if (item == NULL) {
        val_free(key);
        return false;
    }
    val_put(v, key->text, key->len, line, item);
    val_free(key);
    return true;
}

/* A flow value (inside [ ] or { }, or a whole inline value when flow is false) at s[*i]. */
val_t *yp_flow(yp_t *p, const char *s, size_t n, size_t *i, int line, int depth, bool flow) {
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
                if (!yp_flow_entry(p, s, n, i, line, depth, v)) {
                    val_free(v);
                    return NULL;
                }
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
            yp_rule(p, l->number, "a key must be a name, not %s", flow_text(&t, key));
            free(t.s);
            val_free(key);
            break;
        }
        seen = val_index(map, key->text);
        if (seen >= 0) {
            yp_rule(p, l->number, "'%s' given twice (first on line %d)", key->text, map->key_lines[seen]);
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
val_t *yaml_load(const char *text, size_t n, const char *filename, char *msg, size_t cap) {
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
        snprintf(msg, cap, "%s:%d: %s%s", filename, p.err_line ? p.err_line : 1,
                 p.rule ? "" : "not valid YAML: ", p.err);
        return NULL;
    }
    if (doc->kind != V_MAP) {
        snprintf(msg, cap, "%s:1: expected a mapping of setting names to values", filename);
        val_free(doc);
        return NULL;
    }
    return doc;
}
