/* Command sessions of docs/conformance.md section 8 (the sans-I/O core). No stdio, no heap.
 * Generated: do not edit. */
#include "mscipcodec/session.h"

#include <assert.h>
#include <string.h>

#include "mscipcodec/field_iter.h"
#include "wire.h"

const char *mscipc_result_kind_name(mscipc_result_kind_t kind) {
    switch (kind) {
    case MSCIPC_RESULT_ACK:
        return "ack";
    case MSCIPC_RESULT_NACK:
        return "nack";
    case MSCIPC_RESULT_TIMEOUT:
        return "timeout";
    case MSCIPC_RESULT_INVALID:
        return "invalid";
    case MSCIPC_RESULT_SENT:
        return "sent";
    case MSCIPC_RESULT_REFUSED:
        return "refused";
    case MSCIPC_RESULT_TRANSPORT:
        return "transport";
    case MSCIPC_RESULT_LOST:
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
void mscipc_result_reply_iter(const mscipc_result_t *result, mscipc_field_iter_t *it) {
    assert(result != NULL);
    assert(it != NULL);
    if (result->packet == NULL || result->reply_end <= result->reply_begin) {
        mscipc_field_iter_init(it, result->set, NULL, 0);
        return;
    }
    /* over the payload up to the reply's end, from its beginning: an entry's offset (a trailing
     * entry's in its message) is its payload offset, as in every other language */
    mscipc_field_iter_init(it, result->set, mscipc_packet_payload(result->packet), result->reply_end);
    it->pos = result->reply_begin;
}

bool mscipc_result_reply_entry(const mscipc_result_t *result, mscipc_field_entry_t *entry) {
    mscipc_field_iter_t it;
    mscipc_field_entry_t e;
    bool have_first = false;
    size_t i;
    assert(entry != NULL);
    mscipc_result_reply_iter(result, &it);
    while (mscipc_field_iter_next(&it, &e)) {
        if (e.kind != MSCIPC_ENTRY_FIELD) {
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
void mscipc_session_config_init(mscipc_session_config_t *config) {
    assert(config != NULL);
    memset(config, 0, sizeof *config);
    config->device = MSCIPC_DEVICE_ANY;
    config->timeout_ms = MSCIPC_SESSION_DEFAULT_TIMEOUT_MS;
    config->inter_packet_timeout_ms = MSCIPC_SESSION_DEFAULT_INTER_PACKET_TIMEOUT_MS;
    config->max_pending = MSCIPC_SESSION_MAX_PENDING;
    config->check_device = true;
}

mscipc_status_t mscipc_session_init(mscipc_session_t *session, const mscipc_session_config_t *config) {
    assert(session != NULL);
    assert(config != NULL);
    memset(session, 0, sizeof *session);
    if (config->max_pending < 1 || config->max_pending > MSCIPC_SESSION_MAX_PENDING) {
        return MSCIPC_ERR_INVALID;
    }
    if (config->device != MSCIPC_DEVICE_ANY && mscipc_device_id(config->device) == NULL) {
        return MSCIPC_ERR_INVALID;
    }
    session->config = *config;
    mscipc_parser_init(&session->parser);
    session->parser.skip_piece = MSCIPC_SESSION_SKIP_PIECE;
    return MSCIPC_OK;
}

void mscipc_session_on_packet(mscipc_session_t *session, mscipc_packet_handler_fn fn, void *ctx) {
    assert(session != NULL);
    session->packet_fn = fn;
    session->packet_ctx = ctx;
}

mscipc_status_t mscipc_session_on_field(mscipc_session_t *session, uint8_t set, uint8_t descriptor,
                                        mscipc_field_handler_fn fn, void *ctx) {
    mscipc_field_handler_t *h;
    assert(session != NULL);
    assert(fn != NULL);
    if (session->field_count >= MSCIPC_SESSION_MAX_FIELD_HANDLERS) {
        return MSCIPC_ERR_BUFFER;
    }
    h = &session->fields[session->field_count++];
    h->set = set;
    h->descriptor = descriptor;
    h->fn = fn;
    h->ctx = ctx;
    return MSCIPC_OK;
}

void mscipc_start_options_init(mscipc_start_options_t *options) {
    assert(options != NULL);
    options->timeout_ms = -1;
    options->check_device = -1;
    options->tag = 0;
}

size_t mscipc_session_pending(const mscipc_session_t *session) {
    assert(session != NULL);
    return session->count;
}

void mscipc_session_forget(mscipc_session_t *session) {
    assert(session != NULL);
    memset(session->pending, 0, sizeof session->pending);
    session->count = 0;
}

/* ------------------------------------------------------------------ start */
static void result_init(mscipc_result_t *r, mscipc_result_kind_t kind, const mscipc_command_facts_t *facts,
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

static uint32_t device_bit(mscipc_device_t device) {
    unsigned d = (unsigned)device;
    return d < 32u ? (uint32_t)1u << d : 0u;
}

/* The model as refusals name it: its title and manual, "3DM-GX5-45 (3dm-gx5-45-dcp.txt)". */
static void add_model(text_t *t, mscipc_device_t device) {
    text_add(t, mscipc_device_title(device));
    text_add(t, " (");
    text_add(t, mscipc_device_manual(device));
    text_add(t, ")");
}

/* Why the session's device does not support the command (section 8, start step 1): writes the
 * message and returns true, or returns false. */
static bool support_error(const mscipc_command_facts_t *f, mscipc_device_t device, char *buf, size_t cap) {
    const char *name = mscipc_layout_info(f->id)->name;
    const char *dev = mscipc_device_id(device);
    text_t t;
    text_init(&t, buf, cap);
    if (!mscipc_device_supports(device, f->set, f->descriptor)) {
        text_add(&t, name);
        text_add(&t, " is not supported by ");
        add_model(&t, device);
        return true;
    }
    if (f->layout_device != MSCIPC_DEVICE_ANY && f->layout_device != device) {
        text_add(&t, name);
        text_add(&t, ": this layout is for ");
        text_add(&t, mscipc_device_id(f->layout_device));
        text_add(&t, ", not ");
        text_add(&t, dev);
        return true;
    }
    if (f->function >= 0 && (!f->function_listed || (f->function_devices & device_bit(device)) == 0)) {
        const char *fn = mscipc_function_name(f->function);
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

mscipc_status_t mscipc_session_start(mscipc_session_t *session, const mscipc_field_value_t *command,
                                     uint64_t now, const mscipc_start_options_t *options, uint8_t *packet,
                                     size_t cap, mscipc_started_t *out) {
    mscipc_command_facts_t facts;
    mscipc_start_options_t opt;
    mscipc_packet_builder_t b;
    uint8_t data[MSCIPC_MAX_FIELD_DATA];
    size_t n = 0;
    mscipc_status_t st;
    bool check;
    uint64_t base;
    mscipc_pending_t *p;
    assert(session != NULL);
    assert(command != NULL);
    assert(packet != NULL || cap == 0);
    assert(out != NULL);
    memset(out, 0, sizeof *out);
    if (options) {
        opt = *options;
    } else {
        mscipc_start_options_init(&opt);
    }
    if (!mscipc_command_facts(command, &facts)) {
        return MSCIPC_ERR_INVALID;
    }
    check = opt.check_device < 0 ? session->config.check_device : opt.check_device > 0;
    base = opt.timeout_ms < 0 ? session->config.timeout_ms : (uint64_t)opt.timeout_ms;
    if (check && session->config.device != MSCIPC_DEVICE_ANY &&
        support_error(&facts, session->config.device, session->error, sizeof session->error)) {
        result_init(&out->result, MSCIPC_RESULT_REFUSED, &facts, opt.tag);
        out->result.error = session->error;
        out->done = true;
        out->deadline = now;
        return MSCIPC_OK;
    }
    st = mscipc_encode_field(command, data, sizeof data, &n);
    if (st != MSCIPC_OK) {
        return MSCIPC_ERR_INVALID;
    }
    mscipc_packet_begin(&b, packet, cap, facts.set);
    mscipc_packet_add_field(&b, facts.descriptor, data, n);
    st = mscipc_packet_finish(&b, &out->packet_len);
    if (st != MSCIPC_OK) {
        out->packet_len = 0;
        return st == MSCIPC_ERR_BUFFER ? MSCIPC_ERR_BUFFER : MSCIPC_ERR_INVALID;
    }
    out->deadline = now + base + facts.allowance_ms;
    if (facts.suppressed) {
        result_init(&out->result, MSCIPC_RESULT_SENT, &facts, opt.tag);
        out->done = true;
        return MSCIPC_OK;
    }
    if (session->count >= session->config.max_pending) {
        text_t t;
        text_init(&t, session->error, sizeof session->error);
        text_uint(&t, session->config.max_pending);
        text_add(&t, " commands already pending");
        result_init(&out->result, MSCIPC_RESULT_REFUSED, &facts, opt.tag);
        out->result.error = session->error;
        out->packet_len = 0;
        out->done = true;
        return MSCIPC_OK;
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
    return MSCIPC_OK;
}

/* ------------------------------------------------------------------ input */
static void emit(mscipc_session_t *s, const mscipc_session_event_t *ev) {
    if (s->config.on_event) {
        s->config.on_event(s->config.ctx, ev);
    }
}

static void remove_pending(mscipc_session_t *s, size_t i) {
    memmove(&s->pending[i], &s->pending[i + 1], (s->count - i - 1) * sizeof s->pending[0]);
    s->count--;
    memset(&s->pending[s->count], 0, sizeof s->pending[0]);
}

static void pending_result(const mscipc_pending_t *p, mscipc_result_kind_t kind, mscipc_result_t *r) {
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

static void expire(mscipc_session_t *s, uint64_t now) {
    size_t i = 0;
    while (i < s->count) {
        if (now >= s->pending[i].deadline) {
            mscipc_result_t r;
            mscipc_session_event_t ev;
            mscipc_pending_t p = s->pending[i];
            remove_pending(s, i);
            pending_result(&p, MSCIPC_RESULT_TIMEOUT, &r);
            ev.kind = MSCIPC_SESSION_RESULT;
            ev.result = &r;
            ev.stream = NULL;
            emit(s, &ev);
        } else {
            i++;
        }
    }
}

/* The result of an ack (code) whose reply is payload[begin, end) (section 8, feed step 4). */
static void complete(mscipc_session_t *s, const mscipc_pending_t *p, const mscipc_event_t *pkt, uint32_t code,
                     size_t begin, size_t end) {
    mscipc_result_t r;
    mscipc_session_event_t ev;
    mscipc_field_iter_t it;
    mscipc_field_entry_t e;
    size_t i;
    pending_result(p, MSCIPC_RESULT_ACK, &r);
    r.has_code = true;
    r.code = code;
    r.packet = pkt->packet;
    r.packet_len = (size_t)pkt->length;
    r.offset = pkt->offset;
    r.reply_begin = begin;
    r.reply_end = end;
    if (code != MSCIPC_SESSION_ACK_OK) {
        r.kind = MSCIPC_RESULT_NACK;
    } else {
        bool found = p->expect_count == 0;
        mscipc_result_reply_iter(&r, &it);
        while (mscipc_field_iter_next(&it, &e)) {
            if (e.kind == MSCIPC_ENTRY_TRAILING) {
                mscipc_trailing_format(&e, s->error, sizeof s->error);
                r.kind = MSCIPC_RESULT_INVALID;
                break;
            } else {
                mscipc_field_value_t value;
                mscipc_decode_error_t err;
                mscipc_status_t st = mscipc_decode_field(p->set, e.descriptor, e.data, e.length,
                                                         s->config.device, &value, &err);
                if (st != MSCIPC_OK) {
                    text_t t;
                    if (st == MSCIPC_ERR_DECODE) {
                        mscipc_decode_error_format(&err, s->error, sizeof s->error);
                    } else {
                        text_init(&t, s->error, sizeof s->error);
                        text_add(&t, mscipc_status_text(st));
                    }
                    r.kind = MSCIPC_RESULT_INVALID;
                    break;
                }
                for (i = 0; i < p->expect_count; i++) {
                    found = found || p->expect[i] == e.descriptor;
                }
            }
        }
        if (r.kind == MSCIPC_RESULT_ACK && !found) {
            text_t t;
            text_init(&t, s->error, sizeof s->error);
            text_add(&t, "missing reply field ");
            text_uint(&t, p->expect[0]);
            r.kind = MSCIPC_RESULT_INVALID;
        }
        if (r.kind == MSCIPC_RESULT_INVALID) {
            r.error = s->error;
        }
    }
    ev.kind = MSCIPC_SESSION_RESULT;
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
static bool match(mscipc_session_t *s, const mscipc_event_t *pkt) {
    const uint8_t set = mscipc_packet_set(pkt->packet);
    const uint8_t *payload = mscipc_packet_payload(pkt->packet);
    const size_t len = mscipc_packet_payload_length(pkt->packet);
    mscipc_field_iter_t it;
    mscipc_field_entry_t e;
    bool answered = false;
    bool have_ack = false;
    uint8_t echo = 0;
    uint32_t code = 0;
    size_t begin = 0;
    mscipc_field_iter_init(&it, set, payload, len);
    for (;;) {
        bool more = mscipc_field_iter_next(&it, &e);
        bool boundary = !more;
        bool is_ack = false;
        uint8_t next_echo = 0;
        uint32_t next_code = 0;
        if (more && e.kind == MSCIPC_ENTRY_FIELD && e.descriptor == MSCIPC_SESSION_ACK_DESCRIPTOR) {
            int ack =
                mscipc_session_ack_decode(set, e.data, e.length, s->config.device, &next_echo, &next_code);
            /* an ack field that does not decode (raw) also ends the reply of the ack before it */
            is_ack = ack > 0;
            boundary = ack >= 0;
        }
        if (boundary && have_ack) {
            size_t end = more ? e.offset : len;
            size_t i;
            for (i = 0; i < s->count; i++) {
                if (s->pending[i].set == set && s->pending[i].descriptor == echo) {
                    mscipc_pending_t p = s->pending[i];
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
static void route_fields(mscipc_session_t *s, const mscipc_event_t *pkt, uint8_t set) {
    size_t i;
    mscipc_field_iter_t it;
    mscipc_field_entry_t e;
    mscipc_field_iter_init(&it, set, mscipc_packet_payload(pkt->packet),
                           mscipc_packet_payload_length(pkt->packet));
    while (mscipc_field_iter_next(&it, &e)) {
        mscipc_field_value_t value;
        bool decoded = false;
        if (e.kind != MSCIPC_ENTRY_FIELD) {
            continue;
        }
        for (i = 0; i < s->field_count; i++) {
            const mscipc_field_handler_t *h = &s->fields[i];
            if (h->set != set || h->descriptor != e.descriptor) {
                continue;
            }
            if (!decoded) {
                if (mscipc_decode_field(set, e.descriptor, e.data, e.length, s->config.device, &value,
                                        NULL) != MSCIPC_OK) {
                    break;
                }
                decoded = true;
            }
            h->fn(h->ctx, &value, pkt);
        }
    }
}

static bool field_reference(const mscipc_reference_time_t *r, const mscipc_field_entry_t *e, int64_t *ns) {
    uint64_t bits;
    double tow, t;
    int64_t whole;
    if (!r->gps) {
        if ((size_t)r->offset + r->size > e->length) {
            return false;
        }
        bits = r->size == 8   ? mscipc_ld_u64(e->data + r->offset)
               : r->size == 4 ? mscipc_ld_u32(e->data + r->offset)
               : r->size == 2 ? mscipc_ld_u16(e->data + r->offset)
                              : mscipc_ld_u8(e->data + r->offset);
        *ns = (int64_t)bits * r->ns_per_unit;
        return true;
    }
    if ((size_t)r->offset + 8 > e->length || (size_t)r->week_offset + r->week_size > e->length) {
        return false;
    }
    bits = mscipc_ld_u64(e->data + r->offset);
    memcpy(&tow, &bits, sizeof tow);
    bits =
        r->week_size == 4 ? mscipc_ld_u32(e->data + r->week_offset) : mscipc_ld_u16(e->data + r->week_offset);
    if (!(tow >= 0.0 && tow < 1e7)) {
        return false; /* not a time of week (NaN, negative, absurd) */
    }
    t = tow * 1e9 + 0.5;
    whole = (int64_t)t; /* floor, t >= 0 */
    *ns = (int64_t)bits * 604800000000000LL + whole;
    return true;
}

bool mscipc_reference_ns(mscipc_device_t device, uint8_t set, const uint8_t *payload, size_t len,
                         int64_t *ns) {
    size_t i;
    mscipc_field_iter_t it;
    mscipc_field_entry_t e;
    assert(ns != NULL);
    for (i = 0; i < mscipc_reference_time_count; i++) {
        const mscipc_reference_time_t *r = &mscipc_reference_times[i];
        if ((device != MSCIPC_DEVICE_ANY && r->device != device) || (!r->shared && r->set != set)) {
            continue;
        }
        mscipc_field_iter_init(&it, set, payload, len);
        while (mscipc_field_iter_next(&it, &e)) {
            if (e.kind == MSCIPC_ENTRY_FIELD && e.descriptor == r->descriptor && field_reference(r, &e, ns)) {
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
static void clock_packet(mscipc_session_t *s, const mscipc_event_t *pkt, uint8_t set) {
    int64_t d;
    if (mscipc_reference_ns(s->config.device, set, mscipc_packet_payload(pkt->packet),
                            mscipc_packet_payload_length(pkt->packet), &d)) {
        s->packet_host = mscipc_clock_add(s->clock, d, s->read_ns, &s->packet_host_ns);
    }
}

void mscipc_session_use_clock(mscipc_session_t *session, mscipc_clock_t *clock) {
    assert(session != NULL);
    session->clock = clock;
}

bool mscipc_session_host_ns(const mscipc_session_t *session, int64_t *host_ns) {
    assert(session != NULL && host_ns != NULL);
    if (session->packet_host) {
        *host_ns = session->packet_host_ns;
    }
    return session->packet_host;
}

static void route(mscipc_session_t *s, const mscipc_event_t *pkt) {
    mscipc_session_event_t ev;
    size_t i;
    const uint8_t set = mscipc_packet_set(pkt->packet);
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
        ev.kind = MSCIPC_SESSION_PACKET;
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

static void on_stream(void *ctx, const mscipc_event_t *event) {
    mscipc_session_t *s = (mscipc_session_t *)ctx;
    if (event->kind != MSCIPC_EVENT_PACKET) {
        mscipc_session_event_t ev;
        ev.kind = event->kind == MSCIPC_EVENT_SKIP ? MSCIPC_SESSION_SKIP : MSCIPC_SESSION_FOREIGN;
        ev.result = NULL;
        ev.stream = event;
        emit(s, &ev);
        return;
    }
    route(s, event);
}

/* Notes where the parser waits after a change: a new position starts its wait at `now`. */
static void note_wait(mscipc_session_t *s, uint64_t now) {
    const mscipc_parser_t *parser = &s->parser;
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
static void look_ahead(mscipc_session_t *s, uint64_t now) {
    while (s->waiting && s->parser.used > 0 && s->wait_at == s->parser.base &&
           now - s->wait_since > s->config.inter_packet_timeout_ms) {
        if (!mscipc_parser_look_ahead(&s->parser, on_stream, s)) {
            return;
        }
        note_wait(s, now);
    }
}

void mscipc_session_feed(mscipc_session_t *session, const uint8_t *data, size_t len, uint64_t now) {
    mscipc_session_feed_at(session, data, len, now, (int64_t)now * 1000000);
}

void mscipc_session_feed_at(mscipc_session_t *session, const uint8_t *data, size_t len, uint64_t now,
                            int64_t read_ns) {
    assert(session != NULL);
    assert(data != NULL || len == 0);
    session->now = now;
    session->read_ns = read_ns;
    expire(session, now);
    /* (a) on the buffer as it was, before the new bytes: the same whether the caller polled */
    look_ahead(session, now);
    if (len > 0) {
        mscipc_parser_feed(&session->parser, data, len, on_stream, session);
    }
    note_wait(session, now);
    /* (b) with the new bytes, when the wait at the same position had expired already */
    look_ahead(session, now);
}

void mscipc_session_poll(mscipc_session_t *session, uint64_t now) {
    mscipc_session_feed(session, NULL, 0, now);
}

void mscipc_session_close(mscipc_session_t *session, uint64_t now) {
    assert(session != NULL);
    mscipc_session_poll(session, now);
    mscipc_parser_flush(&session->parser, on_stream, session);
    session->waiting = false;
}

bool mscipc_session_next_deadline(const mscipc_session_t *session, uint64_t *deadline) {
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
