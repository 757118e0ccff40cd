/* The blocking session API over a transport (docs/conformance.md section 8). No OS calls, no
 * heap. */
#include "codec/link.h"

#include <assert.h>
#include <string.h>

/* Every session event: the caller's callback, and the result run waits for kept (its packet and
 * error copied, as they are only valid during the callback). */
static void on_event(void *ctx, const codec_session_event_t *event) {
    codec_link_t *link = (codec_link_t *)ctx;
    if (event->kind == CODEC_SESSION_RESULT && event->result->tag == link->tag && !link->done) {
        const codec_result_t *r = event->result;
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
    if (link->on_event) {
        link->on_event(link->ctx, event);
    }
}

codec_status_t codec_link_init(codec_link_t *link, const codec_transport_t *transport,
                               const codec_session_config_t *config) {
    codec_session_config_t c;
    codec_status_t st;
    assert(link != NULL);
    assert(transport != NULL);
    assert(config != NULL);
    memset(link, 0, sizeof *link);
    if (transport->read == NULL || transport->write == NULL || transport->now_ms == NULL) {
        return CODEC_ERR_INVALID;
    }
    link->transport = *transport;
    link->on_event = config->on_event;
    link->ctx = config->ctx;
    c = *config;
    c.max_pending = 1;
    c.on_event = on_event;
    c.ctx = link;
    st = codec_session_init(&link->session, &c);
    link->next_tag = 1;
    return st;
}

int codec_link_pump(codec_link_t *link, uint32_t wait_ms) {
    uint8_t buf[512];
    int n;
    assert(link != NULL);
    n = link->transport.read(link->transport.ctx, buf, sizeof buf, wait_ms);
    if (n < 0) {
        return n;
    }
    codec_session_feed(&link->session, buf, (size_t)n, link->transport.now_ms(link->transport.ctx));
    return n;
}

static codec_result_kind_t failed(codec_link_t *link, codec_result_kind_t kind, const char *why,
                                  codec_result_t *result) {
    link->result.kind = kind;
    strncpy(link->error, why, sizeof link->error - 1);
    link->error[sizeof link->error - 1] = '\0';
    link->result.error = link->error;
    if (result) {
        *result = link->result;
    }
    return kind;
}

codec_result_kind_t codec_link_run(codec_link_t *link, const codec_field_value_t *command,
                                   const codec_start_options_t *options, codec_result_t *result) {
    codec_start_options_t opt;
    codec_started_t started;
    uint8_t packet[CODEC_MAX_PACKET];
    codec_status_t st;
    assert(link != NULL);
    assert(command != NULL);
    if (options) {
        opt = *options;
    } else {
        codec_start_options_init(&opt);
    }
    if (opt.tag == 0) {
        opt.tag = link->next_tag++;
    }
    memset(&link->result, 0, sizeof link->result);
    link->result.error = "";
    link->tag = opt.tag;
    link->done = false;
    st = codec_session_start(&link->session, command, link->transport.now_ms(link->transport.ctx), &opt,
                             packet, sizeof packet, &started);
    if (st != CODEC_OK) {
        return failed(link, CODEC_RESULT_REFUSED,
                      st == CODEC_ERR_INVALID ? "not a command, or its values cannot be encoded"
                                              : codec_status_text(st),
                      result);
    }
    if (started.packet_len > 0 &&
        link->transport.write(link->transport.ctx, packet, started.packet_len) < 0) {
        return failed(link, CODEC_RESULT_TRANSPORT, "write failed", result);
    }
    if (started.done) {
        codec_session_event_t ev;
        ev.kind = CODEC_SESSION_RESULT;
        ev.result = &started.result;
        ev.stream = NULL;
        on_event(link, &ev);
    }
    while (!link->done) {
        uint64_t now = link->transport.now_ms(link->transport.ctx);
        uint64_t deadline = started.deadline;
        uint64_t wait;
        codec_session_next_deadline(&link->session, &deadline);
        wait = deadline > now ? deadline - now : 0;
        if (codec_link_pump(link, wait > UINT32_MAX ? UINT32_MAX : (uint32_t)wait) < 0) {
            return failed(link, CODEC_RESULT_TRANSPORT, "the transport failed", result);
        }
    }
    if (result) {
        *result = link->result;
    }
    return link->result.kind;
}

codec_result_kind_t codec_link_fail(codec_link_t *link, codec_result_kind_t kind, const char *why) {
    assert(link != NULL);
    assert(why != NULL);
    memset(&link->result, 0, sizeof link->result);
    return failed(link, kind, why, NULL);
}

int codec_link_listen(codec_link_t *link, uint32_t duration_ms) {
    uint64_t end;
    assert(link != NULL);
    end = link->transport.now_ms(link->transport.ctx) + duration_ms;
    for (;;) {
        uint64_t now = link->transport.now_ms(link->transport.ctx);
        int n;
        if (now >= end) {
            return 0;
        }
        n = codec_link_pump(link, (uint32_t)(end - now));
        if (n < 0) {
            return n;
        }
    }
}

void codec_link_close(codec_link_t *link) {
    assert(link != NULL);
    codec_session_close(&link->session, link->transport.now_ms(link->transport.ctx));
}

codec_status_t codec_link_reply(const codec_link_t *link, const codec_result_t *result,
                                codec_field_value_t *value) {
    codec_field_entry_t e;
    assert(link != NULL);
    assert(result != NULL);
    assert(value != NULL);
    if (!codec_result_reply_entry(result, &e)) {
        return CODEC_ERR_UNKNOWN_DESCRIPTOR;
    }
    return codec_decode_field(result->set, e.descriptor, e.data, e.length, link->session.config.device, value,
                              NULL);
}
