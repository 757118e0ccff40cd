/* Command sessions of docs/conformance.md section 8 (the sans-I/O core). No stdio, no heap.
 * Generated: do not edit. */
#include "mipcodec/session.h"

#include <assert.h>
#include <string.h>

#include "mipcodec/field_iter.h"
#include "wire.h"

const char *mipc_result_kind_name(mipc_result_kind_t kind) {
    switch (kind) {
    case MIPC_RESULT_ACK:
        return "ack";
    case MIPC_RESULT_NACK:
        return "nack";
    case MIPC_RESULT_TIMEOUT:
        return "timeout";
    case MIPC_RESULT_INVALID:
        return "invalid";
    case MIPC_RESULT_SENT:
        return "sent";
    case MIPC_RESULT_REFUSED:
        return "refused";
    case MIPC_RESULT_TRANSPORT:
        return "transport";
    case MIPC_RESULT_LOST:
        return "lost";
    }
    return "unknown";
}

/* ------------------------------------------------------------------ text without stdio */
typedef struct {
    char *buf;
    size_t cap;
    size_t len;
} text_t;

static void text_init(text_t *t, char *buf, size_t cap) {
    t->buf = buf;
    t->cap = cap;
    t->len = 0;
    if (cap > 0) {
        buf[0] = '\0';
    }
}

static void text_add(text_t *t, const char *s) {
    size_t n = strlen(s);
    if (t->len + 1 < t->cap) {
        size_t room = t->cap - t->len - 1;
        size_t k = n < room ? n : room;
        memcpy(t->buf + t->len, s, k);
        t->buf[t->len + k] = '\0';
    }
    t->len += n;
}

static void text_uint(text_t *t, uint64_t v) {
    char digits[21];
    size_t i = sizeof digits - 1;
    digits[i] = '\0';
    do {
        digits[--i] = (char)('0' + (int)(v % 10u));
        v /= 10u;
    } while (v != 0);
    text_add(t, digits + i);
}

/* ------------------------------------------------------------------ results */
void mipc_result_reply_iter(const mipc_result_t *result, mipc_field_iter_t *it) {
    assert(result != NULL);
    assert(it != NULL);
    if (result->packet == NULL || result->reply_end <= result->reply_begin) {
        mipc_field_iter_init(it, result->set, NULL, 0);
        return;
    }
    /* over the payload up to the reply's end, from its beginning: an entry's offset (a trailing
     * entry's in its message) is its payload offset, as in every other language */
    mipc_field_iter_init(it, result->set, mipc_packet_payload(result->packet), result->reply_end);
    it->pos = result->reply_begin;
}

bool mipc_result_reply_entry(const mipc_result_t *result, mipc_field_entry_t *entry) {
    mipc_field_iter_t it;
    mipc_field_entry_t e;
    bool have_first = false;
    size_t i;
    assert(entry != NULL);
    mipc_result_reply_iter(result, &it);
    while (mipc_field_iter_next(&it, &e)) {
        if (e.kind != MIPC_ENTRY_FIELD) {
            continue;
        }
        for (i = 0; i < result->expect_count; i++) {
            if (result->expect[i] == e.descriptor) {
                *entry = e;
                return true;
            }
        }
        if (!have_first) {
            *entry = e;
            have_first = true;
        }
    }
    return have_first;
}

/* ------------------------------------------------------------------ configuration */
void mipc_session_config_init(mipc_session_config_t *config) {
    assert(config != NULL);
    memset(config, 0, sizeof *config);
    config->device = MIPC_DEVICE_ANY;
    config->timeout_ms = MIPC_SESSION_DEFAULT_TIMEOUT_MS;
    config->inter_packet_timeout_ms = MIPC_SESSION_DEFAULT_INTER_PACKET_TIMEOUT_MS;
    config->max_pending = MIPC_SESSION_MAX_PENDING;
    config->check_device = true;
}

mipc_status_t mipc_session_init(mipc_session_t *session, const mipc_session_config_t *config) {
    assert(session != NULL);
    assert(config != NULL);
    memset(session, 0, sizeof *session);
    if (config->max_pending < 1 || config->max_pending > MIPC_SESSION_MAX_PENDING) {
        return MIPC_ERR_INVALID;
    }
    if (config->device != MIPC_DEVICE_ANY && mipc_device_id(config->device) == NULL) {
        return MIPC_ERR_INVALID;
    }
    session->config = *config;
    mipc_parser_init(&session->parser);
    session->parser.skip_piece = MIPC_SESSION_SKIP_PIECE;
    return MIPC_OK;
}

void mipc_session_on_packet(mipc_session_t *session, mipc_packet_handler_fn fn, void *ctx) {
    assert(session != NULL);
    session->packet_fn = fn;
    session->packet_ctx = ctx;
}

mipc_status_t mipc_session_on_field(mipc_session_t *session, uint8_t set, uint8_t descriptor,
                                    mipc_field_handler_fn fn, void *ctx) {
    mipc_field_handler_t *h;
    assert(session != NULL);
    assert(fn != NULL);
    if (session->field_count >= MIPC_SESSION_MAX_FIELD_HANDLERS) {
        return MIPC_ERR_BUFFER;
    }
    h = &session->fields[session->field_count++];
    h->set = set;
    h->descriptor = descriptor;
    h->fn = fn;
    h->ctx = ctx;
    return MIPC_OK;
}

void mipc_start_options_init(mipc_start_options_t *options) {
    assert(options != NULL);
    options->timeout_ms = -1;
    options->check_device = -1;
    options->tag = 0;
}

size_t mipc_session_pending(const mipc_session_t *session) {
    assert(session != NULL);
    return session->count;
}

void mipc_session_forget(mipc_session_t *session) {
    assert(session != NULL);
    memset(session->pending, 0, sizeof session->pending);
    session->count = 0;
}

/* ------------------------------------------------------------------ start */
static void result_init(mipc_result_t *r, mipc_result_kind_t kind, const mipc_command_facts_t *facts,
                        uintptr_t tag) {
    memset(r, 0, sizeof *r);
    r->kind = kind;
    r->tag = tag;
    r->command = facts->id;
    r->set = facts->set;
    r->descriptor = facts->descriptor;
    memcpy(r->expect, facts->expect, sizeof r->expect);
    r->expect_count = facts->expect_count;
    r->error = "";
}

static uint32_t device_bit(mipc_device_t device) {
    unsigned d = (unsigned)device;
    return d < 32u ? (uint32_t)1u << d : 0u;
}

/* The model as refusals name it: its title and manual, "3DM-GX5-45 (3dm-gx5-45-dcp.txt)". */
static void add_model(text_t *t, mipc_device_t device) {
    text_add(t, mipc_device_title(device));
    text_add(t, " (");
    text_add(t, mipc_device_manual(device));
    text_add(t, ")");
}

/* Why the session's device does not support the command (section 8, start step 1): writes the
 * message and returns true, or returns false. */
static bool support_error(const mipc_command_facts_t *f, mipc_device_t device, char *buf, size_t cap) {
    const char *name = mipc_layout_info(f->id)->name;
    const char *dev = mipc_device_id(device);
    text_t t;
    text_init(&t, buf, cap);
    if (!mipc_device_supports(device, f->set, f->descriptor)) {
        text_add(&t, name);
        text_add(&t, " is not supported by ");
        add_model(&t, device);
        return true;
    }
    if (f->layout_device != MIPC_DEVICE_ANY && f->layout_device != device) {
        text_add(&t, name);
        text_add(&t, ": this layout is for ");
        text_add(&t, mipc_device_id(f->layout_device));
        text_add(&t, ", not ");
        text_add(&t, dev);
        return true;
    }
    if (f->function >= 0 && (!f->function_listed || (f->function_devices & device_bit(device)) == 0)) {
        const char *fn = mipc_function_name(f->function);
        text_add(&t, "function ");
        if (fn) {
            text_add(&t, fn);
        } else {
            text_uint(&t, (uint64_t)f->function);
        }
        text_add(&t, " of ");
        text_add(&t, name);
        text_add(&t, " is not supported by ");
        add_model(&t, device);
        return true;
    }
    return false;
}

mipc_status_t mipc_session_start(mipc_session_t *session, const mipc_field_value_t *command, uint64_t now,
                                 const mipc_start_options_t *options, uint8_t *packet, size_t cap,
                                 mipc_started_t *out) {
    mipc_command_facts_t facts;
    mipc_start_options_t opt;
    mipc_packet_builder_t b;
    uint8_t data[MIPC_MAX_FIELD_DATA];
    size_t n = 0;
    mipc_status_t st;
    bool check;
    uint64_t base;
    mipc_pending_t *p;
    assert(session != NULL);
    assert(command != NULL);
    assert(packet != NULL || cap == 0);
    assert(out != NULL);
    memset(out, 0, sizeof *out);
    if (options) {
        opt = *options;
    } else {
        mipc_start_options_init(&opt);
    }
    if (!mipc_command_facts(command, &facts)) {
        return MIPC_ERR_INVALID;
    }
    check = opt.check_device < 0 ? session->config.check_device : opt.check_device > 0;
    base = opt.timeout_ms < 0 ? session->config.timeout_ms : (uint64_t)opt.timeout_ms;
    if (check && session->config.device != MIPC_DEVICE_ANY &&
        support_error(&facts, session->config.device, session->error, sizeof session->error)) {
        result_init(&out->result, MIPC_RESULT_REFUSED, &facts, opt.tag);
        out->result.error = session->error;
        out->done = true;
        out->deadline = now;
        return MIPC_OK;
    }
    st = mipc_encode_field(command, data, sizeof data, &n);
    if (st != MIPC_OK) {
        return MIPC_ERR_INVALID;
    }
    mipc_packet_begin(&b, packet, cap, facts.set);
    mipc_packet_add_field(&b, facts.descriptor, data, n);
    st = mipc_packet_finish(&b, &out->packet_len);
    if (st != MIPC_OK) {
        out->packet_len = 0;
        return st == MIPC_ERR_BUFFER ? MIPC_ERR_BUFFER : MIPC_ERR_INVALID;
    }
    out->deadline = now + base + facts.allowance_ms;
    if (facts.suppressed) {
        result_init(&out->result, MIPC_RESULT_SENT, &facts, opt.tag);
        out->done = true;
        return MIPC_OK;
    }
    if (session->count >= session->config.max_pending) {
        text_t t;
        text_init(&t, session->error, sizeof session->error);
        text_uint(&t, session->config.max_pending);
        text_add(&t, " commands already pending");
        result_init(&out->result, MIPC_RESULT_REFUSED, &facts, opt.tag);
        out->result.error = session->error;
        out->packet_len = 0;
        out->done = true;
        return MIPC_OK;
    }
    p = &session->pending[session->count++];
    p->used = true;
    p->set = facts.set;
    p->descriptor = facts.descriptor;
    p->command = facts.id;
    p->deadline = out->deadline;
    p->tag = opt.tag;
    memcpy(p->expect, facts.expect, sizeof p->expect);
    p->expect_count = facts.expect_count;
    return MIPC_OK;
}

/* ------------------------------------------------------------------ input */
static void emit(mipc_session_t *s, const mipc_session_event_t *ev) {
    if (s->config.on_event) {
        s->config.on_event(s->config.ctx, ev);
    }
}

static void remove_pending(mipc_session_t *s, size_t i) {
    memmove(&s->pending[i], &s->pending[i + 1], (s->count - i - 1) * sizeof s->pending[0]);
    s->count--;
    memset(&s->pending[s->count], 0, sizeof s->pending[0]);
}

static void pending_result(const mipc_pending_t *p, mipc_result_kind_t kind, mipc_result_t *r) {
    memset(r, 0, sizeof *r);
    r->kind = kind;
    r->tag = p->tag;
    r->command = p->command;
    r->set = p->set;
    r->descriptor = p->descriptor;
    memcpy(r->expect, p->expect, sizeof r->expect);
    r->expect_count = p->expect_count;
    r->error = "";
}

static void expire(mipc_session_t *s, uint64_t now) {
    size_t i = 0;
    while (i < s->count) {
        if (now >= s->pending[i].deadline) {
            mipc_result_t r;
            mipc_session_event_t ev;
            mipc_pending_t p = s->pending[i];
            remove_pending(s, i);
            pending_result(&p, MIPC_RESULT_TIMEOUT, &r);
            ev.kind = MIPC_SESSION_RESULT;
            ev.result = &r;
            ev.stream = NULL;
            emit(s, &ev);
        } else {
            i++;
        }
    }
}

/* The result of an ack (code) whose reply is payload[begin, end) (section 8, feed step 4). */
static void complete(mipc_session_t *s, const mipc_pending_t *p, const mipc_event_t *pkt, uint32_t code,
                     size_t begin, size_t end) {
    mipc_result_t r;
    mipc_session_event_t ev;
    mipc_field_iter_t it;
    mipc_field_entry_t e;
    size_t i;
    pending_result(p, MIPC_RESULT_ACK, &r);
    r.has_code = true;
    r.code = code;
    r.packet = pkt->packet;
    r.packet_len = (size_t)pkt->length;
    r.offset = pkt->offset;
    r.reply_begin = begin;
    r.reply_end = end;
    if (code != MIPC_SESSION_ACK_OK) {
        r.kind = MIPC_RESULT_NACK;
    } else {
        bool found = p->expect_count == 0;
        mipc_result_reply_iter(&r, &it);
        while (mipc_field_iter_next(&it, &e)) {
            if (e.kind == MIPC_ENTRY_TRAILING) {
                mipc_trailing_format(&e, s->error, sizeof s->error);
                r.kind = MIPC_RESULT_INVALID;
                break;
            } else {
                mipc_field_value_t value;
                mipc_decode_error_t err;
                mipc_status_t st =
                    mipc_decode_field(p->set, e.descriptor, e.data, e.length, s->config.device, &value, &err);
                if (st != MIPC_OK) {
                    text_t t;
                    if (st == MIPC_ERR_DECODE) {
                        mipc_decode_error_format(&err, s->error, sizeof s->error);
                    } else {
                        text_init(&t, s->error, sizeof s->error);
                        text_add(&t, mipc_status_text(st));
                    }
                    r.kind = MIPC_RESULT_INVALID;
                    break;
                }
                for (i = 0; i < p->expect_count; i++) {
                    found = found || p->expect[i] == e.descriptor;
                }
            }
        }
        if (r.kind == MIPC_RESULT_ACK && !found) {
            text_t t;
            text_init(&t, s->error, sizeof s->error);
            text_add(&t, "missing reply field ");
            text_uint(&t, p->expect[0]);
            r.kind = MIPC_RESULT_INVALID;
        }
        if (r.kind == MIPC_RESULT_INVALID) {
            r.error = s->error;
        }
    }
    ev.kind = MIPC_SESSION_RESULT;
    ev.result = &r;
    ev.stream = NULL;
    emit(s, &ev);
}

/* Matches the ack fields of a packet of a set with a pending command; true when it answered at
 * least one (then it is a reply, not data). Out of line: route() stays a short function for the
 * data packets that make up a stream (issue 38: the session's ingest at the rate of decode). */
#if defined(__GNUC__) || defined(__clang__)
__attribute__((noinline))
#endif
static bool match(mipc_session_t *s, const mipc_event_t *pkt) {
    const uint8_t set = mipc_packet_set(pkt->packet);
    const uint8_t *payload = mipc_packet_payload(pkt->packet);
    const size_t len = mipc_packet_payload_length(pkt->packet);
    mipc_field_iter_t it;
    mipc_field_entry_t e;
    bool answered = false;
    bool have_ack = false;
    uint8_t echo = 0;
    uint32_t code = 0;
    size_t begin = 0;
    mipc_field_iter_init(&it, set, payload, len);
    for (;;) {
        bool more = mipc_field_iter_next(&it, &e);
        bool boundary = !more;
        bool is_ack = false;
        uint8_t next_echo = 0;
        uint32_t next_code = 0;
        if (more && e.kind == MIPC_ENTRY_FIELD && e.descriptor == MIPC_SESSION_ACK_DESCRIPTOR) {
            int ack =
                mipc_session_ack_decode(set, e.data, e.length, s->config.device, &next_echo, &next_code);
            /* an ack field that does not decode (raw) also ends the reply of the ack before it */
            is_ack = ack > 0;
            boundary = ack >= 0;
        }
        if (boundary && have_ack) {
            size_t end = more ? e.offset : len;
            size_t i;
            for (i = 0; i < s->count; i++) {
                if (s->pending[i].set == set && s->pending[i].descriptor == echo) {
                    mipc_pending_t p = s->pending[i];
                    remove_pending(s, i);
                    complete(s, &p, pkt, code, begin, end);
                    answered = true;
                    break;
                }
            }
            have_ack = false;
        }
        if (!more) {
            return answered;
        }
        if (is_ack) {
            have_ack = true;
            echo = next_echo;
            code = next_code;
            begin = it.pos;
        }
    }
}

/* The field handlers of a data packet (out of line, like match()). */
#if defined(__GNUC__) || defined(__clang__)
__attribute__((noinline))
#endif
static void route_fields(mipc_session_t *s, const mipc_event_t *pkt, uint8_t set) {
    size_t i;
    mipc_field_iter_t it;
    mipc_field_entry_t e;
    mipc_field_iter_init(&it, set, mipc_packet_payload(pkt->packet), mipc_packet_payload_length(pkt->packet));
    while (mipc_field_iter_next(&it, &e)) {
        mipc_field_value_t value;
        bool decoded = false;
        if (e.kind != MIPC_ENTRY_FIELD) {
            continue;
        }
        for (i = 0; i < s->field_count; i++) {
            const mipc_field_handler_t *h = &s->fields[i];
            if (h->set != set || h->descriptor != e.descriptor) {
                continue;
            }
            if (!decoded) {
                if (mipc_decode_field(set, e.descriptor, e.data, e.length, s->config.device, &value, NULL) !=
                    MIPC_OK) {
                    break;
                }
                decoded = true;
            }
            h->fn(h->ctx, &value, pkt);
        }
    }
}

static bool field_reference(const mipc_reference_time_t *r, const mipc_field_entry_t *e, int64_t *ns) {
    uint64_t bits;
    double tow, t;
    int64_t whole;
    if (!r->gps) {
        if ((size_t)r->offset + r->size > e->length) {
            return false;
        }
        bits = r->size == 8   ? mipc_ld_u64(e->data + r->offset)
               : r->size == 4 ? mipc_ld_u32(e->data + r->offset)
               : r->size == 2 ? mipc_ld_u16(e->data + r->offset)
                              : mipc_ld_u8(e->data + r->offset);
        *ns = (int64_t)bits * r->ns_per_unit;
        return true;
    }
    if ((size_t)r->offset + 8 > e->length || (size_t)r->week_offset + r->week_size > e->length) {
        return false;
    }
    bits = mipc_ld_u64(e->data + r->offset);
    memcpy(&tow, &bits, sizeof tow);
    bits = r->week_size == 4 ? mipc_ld_u32(e->data + r->week_offset) : mipc_ld_u16(e->data + r->week_offset);
    if (!(tow >= 0.0 && tow < 1e7)) {
        return false; /* not a time of week (NaN, negative, absurd) */
    }
    t = tow * 1e9 + 0.5;
    whole = (int64_t)t; /* floor, t >= 0 */
    *ns = (int64_t)bits * 604800000000000LL + whole;
    return true;
}

bool mipc_reference_ns(mipc_device_t device, uint8_t set, const uint8_t *payload, size_t len, int64_t *ns) {
    size_t i;
    mipc_field_iter_t it;
    mipc_field_entry_t e;
    assert(ns != NULL);
    for (i = 0; i < mipc_reference_time_count; i++) {
        const mipc_reference_time_t *r = &mipc_reference_times[i];
        if ((device != MIPC_DEVICE_ANY && r->device != device) || (!r->shared && r->set != set)) {
            continue;
        }
        mipc_field_iter_init(&it, set, payload, len);
        while (mipc_field_iter_next(&it, &e)) {
            if (e.kind == MIPC_ENTRY_FIELD && e.descriptor == r->descriptor && field_reference(r, &e, ns)) {
                return true;
            }
        }
    }
    return false;
}

/* The clock model's step for a data packet (docs/time.md): its host time for the handlers. */
#if defined(__GNUC__)
__attribute__((noinline))
#endif
static void clock_packet(mipc_session_t *s, const mipc_event_t *pkt, uint8_t set) {
    int64_t d;
    if (mipc_reference_ns(s->config.device, set, mipc_packet_payload(pkt->packet),
                          mipc_packet_payload_length(pkt->packet), &d)) {
        s->packet_host = mipc_clock_add(s->clock, d, s->read_ns, &s->packet_host_ns);
    }
}

void mipc_session_use_clock(mipc_session_t *session, mipc_clock_t *clock) {
    assert(session != NULL);
    session->clock = clock;
}

bool mipc_session_host_ns(const mipc_session_t *session, int64_t *host_ns) {
    assert(session != NULL && host_ns != NULL);
    if (session->packet_host) {
        *host_ns = session->packet_host_ns;
    }
    return session->packet_host;
}

static void route(mipc_session_t *s, const mipc_event_t *pkt) {
    mipc_session_event_t ev;
    size_t i;
    const uint8_t set = mipc_packet_set(pkt->packet);
    for (i = 0; i < s->count; i++) {
        if (s->pending[i].set == set) {
            if (match(s, pkt)) {
                return;
            }
            break;
        }
    }
    s->packet_host = false;
    if (s->clock) {
        clock_packet(s, pkt, set);
    }
    if (s->config.on_event) {
        ev.kind = MIPC_SESSION_PACKET;
        ev.result = NULL;
        ev.stream = pkt;
        s->config.on_event(s->config.ctx, &ev);
    }
    if (s->packet_fn) {
        s->packet_fn(s->packet_ctx, pkt);
    }
    if (s->field_count > 0) {
        route_fields(s, pkt, set);
    }
}

static void on_stream(void *ctx, const mipc_event_t *event) {
    mipc_session_t *s = (mipc_session_t *)ctx;
    if (event->kind != MIPC_EVENT_PACKET) {
        mipc_session_event_t ev;
        ev.kind = event->kind == MIPC_EVENT_SKIP ? MIPC_SESSION_SKIP : MIPC_SESSION_FOREIGN;
        ev.result = NULL;
        ev.stream = event;
        emit(s, &ev);
        return;
    }
    route(s, event);
}

/* Notes where the parser waits after a change: a new position starts its wait at `now`. */
static void note_wait(mipc_session_t *s, uint64_t now) {
    const mipc_parser_t *parser = &s->parser;
    if (parser->used == 0) {
        s->waiting = false;
    } else if (!s->waiting || s->wait_at != parser->base) {
        s->waiting = true;
        s->wait_at = parser->base;
        s->wait_since = now;
    }
}

/* The look-ahead rule (section 8, feed step 2): while the parser has waited at one position for
 * more than P, the first complete packet with a valid checksum buffered after it ends the wait
 * (the bytes before it are skipped); with none, nothing is dropped. */
static void look_ahead(mipc_session_t *s, uint64_t now) {
    while (s->waiting && s->parser.used > 0 && s->wait_at == s->parser.base &&
           now - s->wait_since > s->config.inter_packet_timeout_ms) {
        if (!mipc_parser_look_ahead(&s->parser, on_stream, s)) {
            return;
        }
        note_wait(s, now);
    }
}

void mipc_session_feed(mipc_session_t *session, const uint8_t *data, size_t len, uint64_t now) {
    mipc_session_feed_at(session, data, len, now, (int64_t)now * 1000000);
}

void mipc_session_feed_at(mipc_session_t *session, const uint8_t *data, size_t len, uint64_t now,
                          int64_t read_ns) {
    assert(session != NULL);
    assert(data != NULL || len == 0);
    session->now = now;
    session->read_ns = read_ns;
    expire(session, now);
    /* (a) on the buffer as it was, before the new bytes: the same whether the caller polled */
    look_ahead(session, now);
    if (len > 0) {
        mipc_parser_feed(&session->parser, data, len, on_stream, session);
    }
    note_wait(session, now);
    /* (b) with the new bytes, when the wait at the same position had expired already */
    look_ahead(session, now);
}

void mipc_session_poll(mipc_session_t *session, uint64_t now) {
    mipc_session_feed(session, NULL, 0, now);
}

void mipc_session_close(mipc_session_t *session, uint64_t now) {
    assert(session != NULL);
    mipc_session_poll(session, now);
    mipc_parser_flush(&session->parser, on_stream, session);
    session->waiting = false;
}

bool mipc_session_next_deadline(const mipc_session_t *session, uint64_t *deadline) {
    bool any = false;
    uint64_t best = 0;
    size_t i;
    assert(session != NULL);
    assert(deadline != NULL);
    for (i = 0; i < session->count; i++) {
        if (!any || session->pending[i].deadline < best) {
            best = session->pending[i].deadline;
            any = true;
        }
    }
    /* the look-ahead: once, when the wait expires (later a poll without bytes changes nothing) */
    if (session->parser.used > 0 && session->waiting &&
        session->now - session->wait_since <= session->config.inter_packet_timeout_ms) {
        uint64_t w = session->wait_since + session->config.inter_packet_timeout_ms + 1u;
        if (!any || w < best) {
            best = w;
            any = true;
        }
    }
    *deadline = best;
    return any;
}
