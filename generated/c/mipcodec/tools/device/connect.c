/* The spec's tables looked up by name, and the connection: open, identify, run a command and read
 * its result line. Generated: do not edit. */
#include "device.h"

const dev_model_t *model_by_id(const char *id) {
    size_t i;
    for (i = 0; i < DEV_MODEL_COUNT; i++) {
        if (strcmp(DEV_MODELS[i].id, id) == 0) {
            return &DEV_MODELS[i];
        }
    }
    return NULL;
}

int64_t function_value(const char *name) {
    size_t i;
    for (i = 0; i < DEV_FUNCTION_COUNT; i++) {
        if (strcmp(DEV_FUNCTIONS[i].name, name) == 0) {
            return DEV_FUNCTIONS[i].value;
        }
    }
    return -1;
}

const char *set_name(uint8_t id) {
    size_t i;
    for (i = 0; DEV_SET_NAMES[i].name; i++) {
        if (DEV_SET_NAMES[i].id == id) {
            return DEV_SET_NAMES[i].name;
        }
    }
    return "";
}

const char *enum_member(int index, int64_t value) {
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
const char *describe_model(mipc_device_t d) {
    static char text[200];
    snprintf(text, sizeof text, "%s (%s)", mipc_device_title(d), mipc_device_manual(d));
    return text;
}

/* The field of a command set named name (the first set that has one). */
const mipc_field_info_t *command_field(const char *name, uint8_t *set) {
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

char g_line[64 * 1024];

double now_s(void) {
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
    if (ev->kind == MIPC_SESSION_PACKET && c->packet_hook != NULL) {
        c->packet_hook(c->hook_ctx, ev);
    }
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

void result_free(result_t *r) {
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

char g_value_error[MIPC_ERROR_MESSAGE_MAX + 400];

/* Builds the command line of (set, descriptor) with the values (a JSON object) and runs it.
 * R_VALUE: the values do not fit the layout (g_value_error says why); R_LOST: the connection is
 * gone; R_OK: ack or sent; R_FAILED: nack, timeout, invalid, refused. */
run_t run_values(conn_t *c, uint8_t set, uint8_t descriptor, const char *variant, const char *values,
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
const val_t *reply_values(const result_t *r, const char *name) {
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

const char *identity_text(const conn_t *c, const char *item, buf_t *b) {
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

/* Opens ADDRESS and identifies the device: 0, or the exit status. */
int connect_device(conn_t *c, const char *address, const char *model, unsigned long baud,
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
        return EXIT_REFUSED; /* a device that does not answer: 1, as no reply to any command sent */
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

void disconnect(conn_t *c) {
    if (c->open) {
        mipc_link_close(&c->link);
        mipc_posix_close(&c->posix);
        c->open = false;
    }
    val_free(c->identity);
    c->identity = NULL;
}
