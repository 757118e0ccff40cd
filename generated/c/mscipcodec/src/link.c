/* The blocking session API over a transport (docs/conformance.md section 8). No OS calls, no
 * heap. Generated: do not edit. */
#include "mscipcodec/link.h"

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
    return st;
}

int mscipc_link_pump(mscipc_link_t *link, uint32_t wait_ms) {
    uint8_t buf[512];
    int n;
    assert(link != NULL);
    n = link->transport.read(link->transport.ctx, buf, sizeof buf, wait_ms);
    if (n < 0) {
        return n;
    }
    mscipc_session_feed(&link->session, buf, (size_t)n, link->transport.now_ms(link->transport.ctx));
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
        return failed(link, MSCIPC_RESULT_TRANSPORT, "write failed", result);
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
        if (mscipc_link_pump(link, wait > UINT32_MAX ? UINT32_MAX : (uint32_t)wait) < 0) {
            return failed(link, MSCIPC_RESULT_TRANSPORT, "the transport failed", result);
        }
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
        int n;
        if (now >= end) {
            return 0;
        }
        n = mscipc_link_pump(link, (uint32_t)(end - now));
        if (n < 0) {
            return n;
        }
    }
}

void mscipc_link_close(mscipc_link_t *link) {
    assert(link != NULL);
    mscipc_session_close(&link->session, link->transport.now_ms(link->transport.ctx));
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
