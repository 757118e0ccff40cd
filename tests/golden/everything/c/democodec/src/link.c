/* The blocking session API over a transport (docs/conformance.md section 8). No OS calls, no
 * heap. Generated: do not edit. */
#include "democodec/link.h"

#include <assert.h>
#include <string.h>

/* Every session event: the caller's callback, and the result run waits for kept (its packet and
 * error copied, as they are only valid during the callback). */
static void on_event(void *ctx, const democ_session_event_t *event) {
    democ_link_t *link = (democ_link_t *)ctx;
    if (event->kind == DEMOC_SESSION_RESULT && event->result->tag == link->tag && !link->done) {
        const democ_result_t *r = event->result;
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

democ_status_t democ_link_init(democ_link_t *link, const democ_transport_t *transport,
                               const democ_session_config_t *config) {
    democ_session_config_t c;
    democ_status_t st;
    assert(link != NULL);
    assert(transport != NULL);
    assert(config != NULL);
    memset(link, 0, sizeof *link);
    if (transport->read == NULL || transport->write == NULL || transport->now_ms == NULL) {
        return DEMOC_ERR_INVALID;
    }
    link->transport = *transport;
    link->on_event = config->on_event;
    link->ctx = config->ctx;
    c = *config;
    c.max_pending = 1;
    c.on_event = on_event;
    c.ctx = link;
    st = democ_session_init(&link->session, &c);
    link->next_tag = 1;
    return st;
}

int democ_link_pump(democ_link_t *link, uint32_t wait_ms) {
    uint8_t buf[512];
    int n;
    assert(link != NULL);
    n = link->transport.read(link->transport.ctx, buf, sizeof buf, wait_ms);
    if (n < 0) {
        return n;
    }
    democ_session_feed(&link->session, buf, (size_t)n, link->transport.now_ms(link->transport.ctx));
    return n;
}

static democ_result_kind_t failed(democ_link_t *link, democ_result_kind_t kind, const char *why,
                                  democ_result_t *result) {
    link->result.kind = kind;
    strncpy(link->error, why, sizeof link->error - 1);
    link->error[sizeof link->error - 1] = '\0';
    link->result.error = link->error;
    if (result) {
        *result = link->result;
    }
    return kind;
}

democ_result_kind_t democ_link_run(democ_link_t *link, const democ_field_value_t *command,
                                   const democ_start_options_t *options, democ_result_t *result) {
    democ_start_options_t opt;
    democ_started_t started;
    uint8_t packet[DEMOC_MAX_PACKET];
    democ_status_t st;
    assert(link != NULL);
    assert(command != NULL);
    if (options) {
        opt = *options;
    } else {
        democ_start_options_init(&opt);
    }
    if (opt.tag == 0) {
        opt.tag = link->next_tag++;
    }
    memset(&link->result, 0, sizeof link->result);
    link->result.error = "";
    link->tag = opt.tag;
    link->done = false;
    st = democ_session_start(&link->session, command, link->transport.now_ms(link->transport.ctx), &opt,
                             packet, sizeof packet, &started);
    if (st != DEMOC_OK) {
        return failed(link, DEMOC_RESULT_REFUSED,
                      st == DEMOC_ERR_INVALID ? "not a command, or its values cannot be encoded"
                                              : democ_status_text(st),
                      result);
    }
    if (started.packet_len > 0 &&
        link->transport.write(link->transport.ctx, packet, started.packet_len) < 0) {
        return failed(link, DEMOC_RESULT_TRANSPORT, "write failed", result);
    }
    if (started.done) {
        democ_session_event_t ev;
        ev.kind = DEMOC_SESSION_RESULT;
        ev.result = &started.result;
        ev.stream = NULL;
        on_event(link, &ev);
    }
    while (!link->done) {
        uint64_t now = link->transport.now_ms(link->transport.ctx);
        uint64_t deadline = started.deadline;
        uint64_t wait;
        democ_session_next_deadline(&link->session, &deadline);
        wait = deadline > now ? deadline - now : 0;
        if (democ_link_pump(link, wait > UINT32_MAX ? UINT32_MAX : (uint32_t)wait) < 0) {
            return failed(link, DEMOC_RESULT_TRANSPORT, "the transport failed", result);
        }
    }
    if (result) {
        *result = link->result;
    }
    return link->result.kind;
}

democ_result_kind_t democ_link_fail(democ_link_t *link, democ_result_kind_t kind, const char *why) {
    assert(link != NULL);
    assert(why != NULL);
    memset(&link->result, 0, sizeof link->result);
    return failed(link, kind, why, NULL);
}

int democ_link_listen(democ_link_t *link, uint32_t duration_ms) {
    uint64_t end;
    assert(link != NULL);
    end = link->transport.now_ms(link->transport.ctx) + duration_ms;
    for (;;) {
        uint64_t now = link->transport.now_ms(link->transport.ctx);
        int n;
        if (now >= end) {
            return 0;
        }
        n = democ_link_pump(link, (uint32_t)(end - now));
        if (n < 0) {
            return n;
        }
    }
}

void democ_link_close(democ_link_t *link) {
    assert(link != NULL);
    democ_session_close(&link->session, link->transport.now_ms(link->transport.ctx));
}

democ_status_t democ_link_reply(const democ_link_t *link, const democ_result_t *result,
                                democ_field_value_t *value) {
    democ_field_entry_t e;
    assert(link != NULL);
    assert(result != NULL);
    assert(value != NULL);
    if (!democ_result_reply_entry(result, &e)) {
        return DEMOC_ERR_UNKNOWN_DESCRIPTOR;
    }
    return democ_decode_field(result->set, e.descriptor, e.data, e.length, link->session.config.device, value,
                              NULL);
}
