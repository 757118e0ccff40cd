/* The blocking session API over a transport (docs/conformance.md section 8). No OS calls, no
 * heap. Generated: do not edit. */
#include "mscipcodec/link.h"

#include "hex.h"

#include <assert.h>
#include <string.h>

/* Every session event: the caller's callback, and the result run waits for kept (its packet and
 * error copied, as they are only valid during the callback). */
static void on_event(void *ctx, const mscipc_session_event_t *event) {
    mscipc_link_t *link = (mscipc_link_t *)ctx;
    if (event->kind == MSCIPC_SESSION_RESULT && event->result->tag == link->tag && !link->done) {
        const mscipc_result_t *r = event->result;
        link->result = *r;
        if (r->packet != NULL) {
            size_t n = r->packet_len < sizeof link->reply ? r->packet_len : sizeof link->reply;
            memcpy(link->reply, r->packet, n);
            link->result.packet = link->reply;
            link->result.packet_len = n;
        }
        strncpy(link->error, r->error ? r->error : "", sizeof link->error - 1);
        link->error[sizeof link->error - 1] = '\0';
        link->result.error = link->error;
        link->done = true;
    }
    if (link->internal) { /* the link's own operation: dropped (its bytes counted as read) */
        return;
    }
    if (link->on_event) {
        link->on_event(link->ctx, event);
    }
}

mscipc_status_t mscipc_link_init(mscipc_link_t *link, const mscipc_transport_t *transport,
                                 const mscipc_session_config_t *config) {
    mscipc_session_config_t c;
    mscipc_status_t st;
    assert(link != NULL);
    assert(transport != NULL);
    assert(config != NULL);
    memset(link, 0, sizeof *link);
    if (transport->read == NULL || transport->write == NULL || transport->now_ms == NULL) {
        return MSCIPC_ERR_INVALID;
    }
    link->transport = *transport;
    link->on_event = config->on_event;
    link->ctx = config->ctx;
    c = *config;
    c.max_pending = 1;
    c.on_event = on_event;
    c.ctx = link;
    st = mscipc_session_init(&link->session, &c);
    link->next_tag = 1;
    link->connected = true;
    link->identified = config->device == MSCIPC_DEVICE_ANY;
    mscipc_link_options_init(&link->options);
    link->options.reconnect_ms = 0;
    return st;
}

static int lost(mscipc_link_t *link);

int mscipc_link_pump(mscipc_link_t *link, uint32_t wait_ms) {
    int n;
    assert(link != NULL);
    n = link->transport.read(link->transport.ctx, link->rx, sizeof link->rx, wait_ms);
    if (n < 0) {
        if (!link->internal && lost(link) == 0) {
            return 0; /* reconnected: the caller goes on receiving */
        }
        return n;
    }
    if (link->internal) {
        link->dropped += (size_t)n; /* data, garbage and the reply alike */
    }
    mscipc_session_feed(&link->session, link->rx, (size_t)n, link->transport.now_ms(link->transport.ctx));
    return n;
}

static mscipc_result_kind_t failed(mscipc_link_t *link, mscipc_result_kind_t kind, const char *why,
                                   mscipc_result_t *result) {
    link->result.kind = kind;
    strncpy(link->error, why, sizeof link->error - 1);
    link->error[sizeof link->error - 1] = '\0';
    link->result.error = link->error;
    if (result) {
        *result = link->result;
    }
    return kind;
}

/* ------------------------------------------------------------------ log lines without stdio */
typedef struct {
    char *buf;
    size_t cap;
    size_t len;
} line_t;

static void line_init(line_t *l, mscipc_link_t *link) {
    l->buf = link->line;
    l->cap = sizeof link->line;
    l->len = 0;
    l->buf[0] = '\0';
}

static void line_add(line_t *l, const char *s) {
    while (*s != '\0' && l->len + 1 < l->cap) {
        l->buf[l->len++] = *s++;
    }
    l->buf[l->len] = '\0';
}

static void line_uint(line_t *l, uint64_t v) {
    char digits[21];
    size_t i = sizeof digits - 1;
    digits[i] = '\0';
    do {
        digits[--i] = (char)('0' + (int)(v % 10u));
        v /= 10u;
    } while (v != 0);
    line_add(l, digits + i);
}

/* Milliseconds as seconds with one decimal ("1.4"), rounded to the nearest tenth. */
static void line_seconds(line_t *l, uint64_t ms) {
    char tenth[2];
    uint64_t tenths = (ms + 50u) / 100u;
    line_uint(l, tenths / 10u);
    tenth[0] = (char)('0' + (int)(tenths % 10u));
    tenth[1] = '\0';
    line_add(l, ".");
    line_add(l, tenth);
}

static void log_line(mscipc_link_t *link, const line_t *l) {
    if (link->options.log) {
        link->options.log(link->options.log_ctx, l->buf);
    }
}

/* ------------------------------------------------------------------ the recorded configuration */
/* The key of a setting: how many data bytes after the function selector its read sends. The
 * shortest prefix of the written data that decodes as that command's read (function 2) is the
 * read as the device would get it; without one (no read) every byte is key. */
static uint8_t key_length(const mscipc_link_t *link, uint8_t set, uint8_t descriptor, const uint8_t *data,
                          size_t n) {
    uint8_t read[MSCIPC_MAX_FIELD_DATA];
    size_t k;
    memcpy(read, data, n);
    read[0] = 2;
    for (k = 1; k <= n; k++) {
        mscipc_field_value_t value;
        if (mscipc_decode_field(set, descriptor, read, k, link->session.config.device, &value, NULL) ==
            MSCIPC_OK) {
            return (uint8_t)(k - 1);
        }
    }
    return (uint8_t)(n - 1);
}

static bool is_command(const mscipc_link_command_t *c, const mscipc_command_facts_t *facts) {
    return c->present && c->set == facts->set && c->descriptor == facts->descriptor;
}

/* Records a setting the application wrote (function write or write_no_ack of a command with a
 * function selector, acknowledged or sent): the latest per key replaces the earlier one and moves
 * to the end (the order of the writes); one more than MSCIPC_LINK_MAX_SETTINGS keys forgets the
 * oldest. Also notes whether the last idle or resume command was an idle. */
static void record(mscipc_link_t *link, const mscipc_field_value_t *command) {
    mscipc_command_facts_t facts;
    mscipc_link_setting_t *slot;
    uint8_t data[MSCIPC_MAX_FIELD_DATA];
    size_t n = 0;
    size_t i;
    uint8_t key_len;
    if (!mscipc_command_facts(command, &facts)) {
        return;
    }
    if (is_command(&link->options.idle, &facts)) {
        link->idled = true;
    }
    if (is_command(&link->options.resume, &facts)) {
        link->idled = false;
    }
    if ((facts.function != 1 && facts.function != 6) ||
        mscipc_encode_field(command, data, sizeof data, &n) != MSCIPC_OK || n == 0) {
        return;
    }
    key_len = key_length(link, facts.set, facts.descriptor, data, n);
    for (i = 0; i < link->setting_count; i++) {
        const mscipc_link_setting_t *r = &link->settings[i];
        if (r->set == facts.set && r->descriptor == facts.descriptor && r->key_len == key_len &&
            memcmp(r->data + 1, data + 1, key_len) == 0) {
            break;
        }
    }
    if (i == link->setting_count && link->setting_count == MSCIPC_LINK_MAX_SETTINGS) {
        i = 0; /* full: the oldest goes */
    }
    if (i < link->setting_count) {
        memmove(&link->settings[i], &link->settings[i + 1],
                (link->setting_count - i - 1) * sizeof link->settings[0]);
        link->setting_count--;
    }
    slot = &link->settings[link->setting_count++];
    slot->set = facts.set;
    slot->descriptor = facts.descriptor;
    slot->key_len = key_len;
    slot->len = (uint8_t)n;
    memcpy(slot->data, data, n);
}

/* The transport failed under a command: the port is reopened (when the link may reconnect) and
 * the command fails with "link lost: REASON" either way; it is not sent again. */
static mscipc_result_kind_t link_lost(mscipc_link_t *link, const char *what, mscipc_result_t *result) {
    char why[MSCIPC_SESSION_ERROR_MAX];
    line_t l;
    const char *reason = link->port.reason ? link->port.reason(link->port.ctx) : what;
    l.buf = why;
    l.cap = sizeof why;
    l.len = 0;
    why[0] = '\0';
    line_add(&l, "link lost: ");
    line_add(&l, reason != NULL && reason[0] != '\0' ? reason : what);
    if (!link->internal && link->port.reopen != NULL && link->options.reconnect_ms > 0) {
        (void)lost(link);
        memset(&link->result, 0, sizeof link->result);
        return failed(link, MSCIPC_RESULT_LOST, why, result);
    }
    link->connected = link->internal && link->connected;
    memset(&link->result, 0, sizeof link->result);
    return failed(link, MSCIPC_RESULT_TRANSPORT, why, result);
}

/* ------------------------------------------------------------------ the wrong-model check */
static mscipc_result_kind_t run_internal(mscipc_link_t *link, const mscipc_field_value_t *command,
                                         const mscipc_start_options_t *options);

/* A NACK code of a command the device does not know (the spec's simulation.nack). */
static bool unknown_command(uint32_t code) {
    static const uint32_t codes[] = MSCIPC_IDENTITY_UNKNOWN_CODES;
    size_t count = MSCIPC_IDENTITY_UNKNOWN_COUNT;
    size_t i;
    for (i = 0; i < count; i++) {
        if (codes[i] == code) {
            return true;
        }
    }
    return false;
}

static bool ascii_alnum(uint8_t c) {
    return (c >= '0' && c <= '9') || (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z');
}

bool mscipc_link_model_note(mscipc_device_t told, const uint8_t *name, size_t len, char *out, size_t cap) {
    uint8_t plain[256];
    size_t n = 0;
    size_t a = 0;
    size_t b = len;
    size_t i;
    const char *const *names = mscipc_device_model_names(told);
    const char *id = mscipc_device_id(told);
    line_t l;
    assert(name != NULL || len == 0);
    assert(out != NULL && cap > 0);
    out[0] = '\0';
    while (a < b && (name[a] == ' ' || name[a] == '\0')) {
        a++;
    }
    while (b > a && (name[b - 1] == ' ' || name[b - 1] == '\0')) {
        b--;
    }
    if (a == b || id == NULL) {
        return false; /* the device does not say */
    }
    for (i = a; i < b && n < sizeof plain; i++) {
        uint8_t c = name[i];
        if (ascii_alnum(c)) {
            plain[n++] = (uint8_t)(c >= 'a' && c <= 'z' ? c - ('a' - 'A') : c);
        } else if (c >= 0x80u) {
            plain[n++] = c; /* matches no name: the spec's are ASCII */
        }
    }
    for (i = 0; n > 0 && names[i] != NULL; i++) {
        if (strlen(names[i]) == n && memcmp(names[i], plain, n) == 0) {
            return false;
        }
    }
    l.buf = out;
    l.cap = cap;
    l.len = 0;
    line_add(&l, "connected device is ");
    for (i = a; i < b; i++) {
        char shown[5];
        uint8_t c = name[i];
        if (c >= 0x20u && c <= 0x7Eu) {
            shown[0] = (char)c;
            shown[1] = '\0';
        } else {
            shown[0] = '\\';
            shown[1] = 'x';
            shown[2] = mscipc_hex_digit(c >> 4u);
            shown[3] = mscipc_hex_digit(c);
            shown[4] = '\0';
        }
        line_add(&l, shown);
    }
    line_add(&l, ", this session was told ");
    line_add(&l, id);
    return true;
}

/* After the first unknown-command NACK: asks the device what it is (the spec's identity command,
 * not checked against the device) and notes when it is another model. The NACK stays the result. */
static void check_model(mscipc_link_t *link) {
#if MSCIPC_IDENTITY_HAS
    mscipc_result_t saved = link->result;
    uint8_t reply[MSCIPC_MAX_PACKET];
    char error[MSCIPC_SESSION_ERROR_MAX];
    uintptr_t tag = link->tag;
    bool done = link->done;
    mscipc_field_value_t identity;
    mscipc_start_options_t opt;
    size_t n = saved.packet != NULL && saved.packet_len <= sizeof reply ? saved.packet_len : 0;
    memcpy(reply, link->reply, n);
    memcpy(error, link->error, sizeof error);
    mscipc_start_options_init(&opt);
    opt.check_device = 0;
    if (mscipc_decode_field(MSCIPC_IDENTITY_SET, MSCIPC_IDENTITY_COMMAND, NULL, 0,
                            link->session.config.device, &identity, NULL) == MSCIPC_OK &&
        run_internal(link, &identity, &opt) == MSCIPC_RESULT_ACK) {
        mscipc_field_iter_t it;
        mscipc_field_entry_t e;
        mscipc_result_reply_iter(&link->result, &it);
        while (mscipc_field_iter_next(&it, &e)) {
            if (e.kind == MSCIPC_ENTRY_FIELD && e.descriptor == MSCIPC_IDENTITY_REPLY &&
                e.length >= MSCIPC_IDENTITY_MODEL_OFFSET + MSCIPC_IDENTITY_MODEL_LENGTH) {
                (void)mscipc_link_model_note(link->session.config.device,
                                             e.data + MSCIPC_IDENTITY_MODEL_OFFSET,
                                             MSCIPC_IDENTITY_MODEL_LENGTH, link->note, sizeof link->note);
                break;
            }
        }
    }
    link->result = saved;
    memcpy(link->reply, reply, n);
    memcpy(link->error, error, sizeof error);
    link->result.packet = saved.packet != NULL ? link->reply : NULL;
    link->result.packet_len = n;
    link->result.error = link->error;
    link->tag = tag;
    link->done = done;
#else
    (void)link;
#endif
}

mscipc_result_kind_t mscipc_link_run(mscipc_link_t *link, const mscipc_field_value_t *command,
                                     const mscipc_start_options_t *options, mscipc_result_t *result) {
    mscipc_start_options_t opt;
    mscipc_started_t started;
    uint8_t packet[MSCIPC_MAX_PACKET];
    mscipc_status_t st;
    assert(link != NULL);
    assert(command != NULL);
    if (options) {
        opt = *options;
    } else {
        mscipc_start_options_init(&opt);
    }
    if (opt.tag == 0) {
        opt.tag = link->next_tag++;
    }
    memset(&link->result, 0, sizeof link->result);
    link->result.error = "";
    if (!link->internal) {
        link->note[0] = '\0';
    }
    link->tag = opt.tag;
    link->done = false;
    st = mscipc_session_start(&link->session, command, link->transport.now_ms(link->transport.ctx), &opt,
                              packet, sizeof packet, &started);
    if (st != MSCIPC_OK) {
        return failed(link, MSCIPC_RESULT_REFUSED,
                      st == MSCIPC_ERR_INVALID ? "not a command, or its values cannot be encoded"
                                               : mscipc_status_text(st),
                      result);
    }
    if (started.packet_len > 0 &&
        link->transport.write(link->transport.ctx, packet, started.packet_len) < 0) {
        return link_lost(link, "write failed", result);
    }
    if (started.done) {
        mscipc_session_event_t ev;
        ev.kind = MSCIPC_SESSION_RESULT;
        ev.result = &started.result;
        ev.stream = NULL;
        on_event(link, &ev);
    }
    while (!link->done) {
        uint64_t now = link->transport.now_ms(link->transport.ctx);
        uint64_t deadline = started.deadline;
        uint64_t wait;
        mscipc_session_next_deadline(&link->session, &deadline);
        wait = deadline > now ? deadline - now : 0;
        /* one read of at most MSCIPC_LINK_READ_MAX bytes, no longer than the next wake-up, fed with
           the time it returned: a deadline passes at the first feed at or after it, whatever arrives */
        int n = link->transport.read(link->transport.ctx, link->rx, sizeof link->rx,
                                     wait > UINT32_MAX ? UINT32_MAX : (uint32_t)wait);
        if (n < 0) {
            return link_lost(link, "the transport failed", result);
        }
        if (link->internal) {
            link->dropped += (size_t)n; /* data, garbage and the reply alike */
        }
        mscipc_session_feed(&link->session, link->rx, (size_t)n, link->transport.now_ms(link->transport.ctx));
    }
    if (!link->internal && !link->identified && link->result.kind == MSCIPC_RESULT_NACK &&
        unknown_command(link->result.code)) {
        link->identified = true;
        check_model(link);
    }
    if (!link->internal &&
        (link->result.kind == MSCIPC_RESULT_ACK || link->result.kind == MSCIPC_RESULT_SENT)) {
        record(link, command);
    }
    if (result) {
        *result = link->result;
    }
    return link->result.kind;
}

mscipc_result_kind_t mscipc_link_fail(mscipc_link_t *link, mscipc_result_kind_t kind, const char *why) {
    assert(link != NULL);
    assert(why != NULL);
    memset(&link->result, 0, sizeof link->result);
    return failed(link, kind, why, NULL);
}

int mscipc_link_listen(mscipc_link_t *link, uint32_t duration_ms) {
    uint64_t end;
    assert(link != NULL);
    end = link->transport.now_ms(link->transport.ctx) + duration_ms;
    for (;;) {
        uint64_t now = link->transport.now_ms(link->transport.ctx);
        uint64_t wake = end;
        uint64_t next = 0;
        int n;
        if (now >= end) {
            return 0;
        }
        /* no longer than the session's next wake-up (a timeout, the look-ahead) */
        if (mscipc_session_next_deadline(&link->session, &next) && next < end) {
            wake = next;
        }
        n = mscipc_link_pump(link, wake > now ? (uint32_t)(wake - now) : 0u);
        if (n < 0) {
            return n;
        }
    }
}

void mscipc_link_close(mscipc_link_t *link) {
    assert(link != NULL);
    mscipc_session_close(&link->session, link->transport.now_ms(link->transport.ctx));
}

/* ------------------------------------------------------------------ getting through */
void mscipc_link_options_init(mscipc_link_options_t *options) {
    assert(options != NULL);
    memset(options, 0, sizeof *options);
    options->reconnect_ms = MSCIPC_LINK_DEFAULT_RECONNECT_MS;
    options->reopen_interval_ms = MSCIPC_LINK_REOPEN_INTERVAL_MS;
    options->quiet_ms = MSCIPC_LINK_QUIET_MS;
    options->idle.present = MSCIPC_LINK_HAS_IDLE != 0;
    options->idle.set = MSCIPC_LINK_IDLE_SET;
    options->idle.descriptor = MSCIPC_LINK_IDLE_DESCRIPTOR;
    options->ping.present = MSCIPC_LINK_HAS_PING != 0;
    options->ping.set = MSCIPC_LINK_PING_SET;
    options->ping.descriptor = MSCIPC_LINK_PING_DESCRIPTOR;
    options->resume.present = MSCIPC_LINK_HAS_RESUME != 0;
    options->resume.set = MSCIPC_LINK_RESUME_SET;
    options->resume.descriptor = MSCIPC_LINK_RESUME_DESCRIPTOR;
}

void mscipc_link_attach(mscipc_link_t *link, const mscipc_port_t *port,
                        const mscipc_link_options_t *options) {
    assert(link != NULL);
    if (port) {
        link->port = *port;
    } else {
        memset(&link->port, 0, sizeof link->port);
    }
    if (options) {
        link->options = *options;
    } else {
        mscipc_link_options_init(&link->options);
    }
}

static uint64_t now_ms(const mscipc_link_t *link) {
    return link->transport.now_ms(link->transport.ctx);
}

/* Runs a command of the link itself: its events counted and dropped, the data handlers paused, the
 * command not recorded. */
static mscipc_result_kind_t run_internal(mscipc_link_t *link, const mscipc_field_value_t *command,
                                         const mscipc_start_options_t *options) {
    bool was = link->internal;
    mscipc_packet_handler_fn packet_fn = link->session.packet_fn;
    size_t field_count = link->session.field_count;
    mscipc_result_kind_t kind;
    link->internal = true;
    link->session.packet_fn = NULL;
    link->session.field_count = 0;
    kind = mscipc_link_run(link, command, options, NULL);
    link->session.packet_fn = packet_fn;
    link->session.field_count = field_count;
    link->internal = was;
    return kind;
}

/* Receives for ms milliseconds with the events counted and dropped; < 0: the transport failed. */
static int drain(mscipc_link_t *link, uint32_t ms) {
    bool was = link->internal;
    mscipc_packet_handler_fn packet_fn = link->session.packet_fn;
    size_t field_count = link->session.field_count;
    int rc;
    link->internal = true;
    link->session.packet_fn = NULL;
    link->session.field_count = 0;
    rc = mscipc_link_listen(link, ms);
    link->session.packet_fn = packet_fn;
    link->session.field_count = field_count;
    link->internal = was;
    return rc;
}

/* Flushes the input: the port's, then the parser's buffered bytes (skipped; stream offsets go on). */
static void flush_input(mscipc_link_t *link) {
    bool was = link->internal;
    if (link->port.flush) {
        (void)link->port.flush(link->port.ctx);
    }
    link->internal = true;
    mscipc_session_close(&link->session, now_ms(link));
    link->internal = was;
}

/* A command without parameters as a value; false when there is none or it does not decode. */
static bool bare_command(const mscipc_link_t *link, const mscipc_link_command_t *c,
                         mscipc_field_value_t *value) {
    return c->present && mscipc_decode_field(c->set, c->descriptor, NULL, 0, link->session.config.device,
                                             value, NULL) == MSCIPC_OK;
}

/* The reply timeout of a command as the session gives it (T + the spec's allowance). */
static uint64_t command_timeout(const mscipc_link_t *link, const mscipc_field_value_t *command) {
    mscipc_command_facts_t facts;
    uint64_t t = link->session.config.timeout_ms;
    if (mscipc_command_facts(command, &facts)) {
        t += facts.allowance_ms;
    }
    return t;
}

mscipc_result_kind_t mscipc_link_to_idle(mscipc_link_t *link) {
    mscipc_field_value_t idle;
    mscipc_result_kind_t kind = MSCIPC_RESULT_TIMEOUT;
    unsigned attempt;
    uint64_t timeout;
    line_t l;
    assert(link != NULL);
    if (!bare_command(link, &link->options.idle, &idle)) {
        line_init(&l, link);
        line_add(&l, "link: idle: the protocol has no idle command");
        log_line(link, &l);
        return mscipc_link_fail(link, MSCIPC_RESULT_REFUSED, "the protocol has no idle command");
    }
    timeout = command_timeout(link, &idle);
    for (attempt = 1; attempt <= MSCIPC_LINK_IDLE_ATTEMPTS; attempt++) {
        link->dropped = 0;
        kind = run_internal(link, &idle, NULL);
        if (kind == MSCIPC_RESULT_TRANSPORT && !link->internal) {
            /* the application's idle command went with the port: lost, and reconnected as for
               its other commands (not retried) */
            return link_lost(link, "the transport failed", NULL);
        }
        if (kind == MSCIPC_RESULT_ACK) {
            line_init(&l, link);
            line_add(&l, "link: idle: ACK on attempt ");
            line_uint(&l, attempt);
            line_add(&l, " of ");
            line_uint(&l, MSCIPC_LINK_IDLE_ATTEMPTS);
            line_add(&l, " (");
            line_uint(&l, link->dropped);
            line_add(&l, " bytes dropped)");
            log_line(link, &l);
            if (!link->internal) {
                link->idled = true;
            }
            return kind;
        }
        if (kind != MSCIPC_RESULT_TIMEOUT) {
            return kind;
        }
        if (attempt == MSCIPC_LINK_IDLE_ATTEMPTS) {
            break;
        }
        line_init(&l, link);
        line_add(&l, "link: idle: no ACK in ");
        line_uint(&l, timeout);
        line_add(&l, " ms");
        if (link->dropped > 0) {
            line_add(&l, " while streaming (");
            line_uint(&l, link->dropped);
            line_add(&l, " bytes dropped)");
        }
        line_add(&l, ", flushing, attempt ");
        line_uint(&l, attempt + 1u);
        line_add(&l, " of ");
        line_uint(&l, MSCIPC_LINK_IDLE_ATTEMPTS);
        log_line(link, &l);
        flush_input(link);
        if (drain(link, link->options.quiet_ms) < 0) {
            return mscipc_link_fail(link, MSCIPC_RESULT_TRANSPORT, "link lost while getting to idle");
        }
        flush_input(link);
    }
    line_init(&l, link);
    line_add(&l, "link: idle: no ACK after ");
    line_uint(&l, MSCIPC_LINK_IDLE_ATTEMPTS);
    line_add(&l, " attempts, giving up");
    log_line(link, &l);
    return kind;
}

static void sleep_ms(mscipc_link_t *link, uint32_t ms) {
    if (ms == 0) {
        return;
    }
    if (link->port.sleep_ms) {
        link->port.sleep_ms(link->port.ctx, ms);
    } else {
        (void)drain(link, ms);
    }
}

/* Adds rate v to out[0..*n) unless it is 0 or there already. */
static void add_rate(uint32_t *out, size_t cap, size_t *n, uint32_t v) {
    size_t j;
    for (j = 0; j < *n; j++) {
        if (out[j] == v) {
            return;
        }
    }
    if (v != 0 && *n < cap) {
        out[(*n)++] = v;
    }
}

/* The rates to try, most likely first: the configured one, the default, then the supported rates
 * from the highest down (with no device selected, every device's), each once. Returns how many. */
static size_t candidate_rates(const mscipc_link_t *link, uint32_t *out, size_t cap) {
    uint32_t all[MSCIPC_LINK_MAX_BAUD_RATES];
    size_t count = 0;
    size_t n = 0;
    size_t i;
    size_t j;
    unsigned d;
    mscipc_device_t device = link->session.config.device;
    add_rate(out, cap, &n, link->port.baud);
    for (d = 1u; device == MSCIPC_DEVICE_ANY && d < 32u && mscipc_device_id((mscipc_device_t)d) != NULL;
         d++) {
        add_rate(out, cap, &n, mscipc_device_default_baud((mscipc_device_t)d));
    }
    for (d = device == MSCIPC_DEVICE_ANY ? 1u : (unsigned)device; d < 32u; d++) {
        size_t k = 0;
        const uint32_t *rates;
        if (mscipc_device_id((mscipc_device_t)d) == NULL) {
            break;
        }
        rates = mscipc_device_baud_rates((mscipc_device_t)d, &k);
        if (device != MSCIPC_DEVICE_ANY) {
            add_rate(out, cap, &n, mscipc_device_default_baud((mscipc_device_t)d));
        }
        for (i = 0; i < k; i++) { /* kept in descending order */
            uint32_t v = rates[i];
            bool seen = false;
            for (j = 0; j < count && !seen; j++) {
                seen = all[j] == v;
            }
            if (seen || count == MSCIPC_LINK_MAX_BAUD_RATES) {
                continue;
            }
            for (j = count++; j > 0 && all[j - 1] < v; j--) {
                all[j] = all[j - 1];
            }
            all[j] = v;
        }
        if (device != MSCIPC_DEVICE_ANY) {
            break;
        }
    }
    for (i = 0; i < count; i++) {
        add_rate(out, cap, &n, all[i]);
    }
    return n;
}

mscipc_result_kind_t mscipc_link_find_baud(mscipc_link_t *link) {
    mscipc_field_value_t ping;
    uint32_t rates[MSCIPC_LINK_MAX_BAUD_RATES + 2];
    size_t n;
    size_t i;
    mscipc_result_kind_t kind;
    uint32_t configured;
    assert(link != NULL);
    if (!bare_command(link, &link->options.ping, &ping)) {
        return mscipc_link_fail(link, MSCIPC_RESULT_REFUSED, "the protocol has no ping command");
    }
    kind = run_internal(link, &ping, NULL);
    if (kind != MSCIPC_RESULT_TIMEOUT || link->port.set_baud == NULL) {
        return kind; /* an answer, or no baud rate to change (TCP) */
    }
    configured = link->port.baud;
    n = candidate_rates(link, rates, sizeof rates / sizeof rates[0]);
    i = n > 0 && rates[0] == link->port.baud ? 0 : (size_t)-1;
    for (;;) {
        line_t l;
        size_t next = i + 1;
        uint32_t current = link->port.baud;
        if (next >= n) {
            line_init(&l, link);
            line_add(&l, "link: baud: no answer at any rate");
            log_line(link, &l);
            if (link->port.baud != configured && link->port.set_baud(link->port.ctx, configured) == 0) {
                link->port.baud = configured; /* back at the configured rate */
            }
            return mscipc_link_fail(link, MSCIPC_RESULT_TIMEOUT, "no answer at any baud rate");
        }
        line_init(&l, link);
        line_add(&l, "link: baud: no answer at ");
        line_uint(&l, current);
        line_add(&l, ", trying ");
        line_uint(&l, rates[next]);
        log_line(link, &l);
        i = next;
        if (link->port.set_baud(link->port.ctx, rates[i]) < 0) {
            continue;
        }
        link->port.baud = rates[i];
        flush_input(link);
        kind = run_internal(link, &ping, NULL);
        if (kind == MSCIPC_RESULT_ACK) {
            line_init(&l, link);
            line_add(&l, "link: baud: device answers at ");
            line_uint(&l, rates[i]);
            log_line(link, &l);
            return kind;
        }
        if (kind == MSCIPC_RESULT_TRANSPORT) {
            return kind;
        }
    }
}

/* Re-sends the recorded settings in order; returns how many were acknowledged (or sent). */
static size_t reapply(mscipc_link_t *link) {
    size_t i;
    size_t done = 0;
    for (i = 0; i < link->setting_count; i++) {
        const mscipc_link_setting_t *r = &link->settings[i];
        mscipc_field_value_t value;
        mscipc_result_kind_t kind;
        if (mscipc_decode_field(r->set, r->descriptor, r->data, r->len, link->session.config.device, &value,
                                NULL) != MSCIPC_OK) {
            continue;
        }
        kind = run_internal(link, &value, NULL);
        if (kind == MSCIPC_RESULT_ACK || kind == MSCIPC_RESULT_SENT) {
            done++;
        }
    }
    if (!link->idled) {
        mscipc_field_value_t resume;
        if (bare_command(link, &link->options.resume, &resume)) {
            (void)run_internal(link, &resume, NULL);
        }
    }
    return done;
}

int mscipc_link_reconnect(mscipc_link_t *link) {
    uint64_t start;
    line_t l;
    const char *reason;
    const char *address;
    bool was;
    size_t applied;
    assert(link != NULL);
    was = link->internal;
    if (link->port.reopen == NULL || link->options.reconnect_ms == 0) {
        link->connected = false;
        return -1;
    }
    reason = link->port.reason ? link->port.reason(link->port.ctx) : NULL;
    address = link->port.address ? link->port.address(link->port.ctx) : NULL;
    address = address != NULL ? address : "the port";
    line_init(&l, link);
    line_add(&l, "link: port lost (");
    line_add(&l, reason != NULL && reason[0] != '\0' ? reason : "unknown error");
    line_add(&l, "), reopening ");
    line_add(&l, address);
    line_add(&l, " every ");
    line_uint(&l, link->options.reopen_interval_ms);
    line_add(&l, " ms");
    log_line(link, &l);
    /* the command in flight is not answered any more; the partial packet of the old port goes */
    mscipc_session_forget(&link->session);
    link->internal = true;
    mscipc_session_close(&link->session, now_ms(link));
    start = now_ms(link);
    for (;;) {
        if (link->port.reopen(link->port.ctx) == 0) {
            break;
        }
        if (now_ms(link) - start + link->options.reopen_interval_ms > link->options.reconnect_ms) {
            link->internal = was;
            link->connected = false;
            line_init(&l, link);
            line_add(&l, "link: gave up reopening ");
            line_add(&l, address);
            line_add(&l, " after ");
            line_uint(&l, link->options.reconnect_ms);
            line_add(&l, " ms");
            log_line(link, &l);
            return -1;
        }
        sleep_ms(link, link->options.reopen_interval_ms);
    }
    link->connected = true;
    applied = 0;
    if (mscipc_link_to_idle(link) == MSCIPC_RESULT_ACK) {
        (void)reapply(link);
        applied = link->setting_count;
    }
    link->internal = was;
    line_init(&l, link);
    line_add(&l, "link: reconnected after ");
    line_seconds(&l, now_ms(link) - start);
    line_add(&l, " s, re-applied ");
    line_uint(&l, applied);
    line_add(&l, " settings");
    log_line(link, &l);
    return 0;
}

static int lost(mscipc_link_t *link) {
    return mscipc_link_reconnect(link);
}

mscipc_status_t mscipc_link_reply(const mscipc_link_t *link, const mscipc_result_t *result,
                                  mscipc_field_value_t *value) {
    mscipc_field_entry_t e;
    assert(link != NULL);
    assert(result != NULL);
    assert(value != NULL);
    if (!mscipc_result_reply_entry(result, &e)) {
        return MSCIPC_ERR_UNKNOWN_DESCRIPTOR;
    }
    return mscipc_decode_field(result->set, e.descriptor, e.data, e.length, link->session.config.device,
                               value, NULL);
}
