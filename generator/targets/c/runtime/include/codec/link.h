/* The blocking session API of docs/conformance.md section 8: a session over a transport given as
 * three callbacks (read with a timeout, write, clock). Freestanding: no OS calls, no heap; the
 * POSIX transports (TCP, serial) are in the optional codec/posix_transport.h. */
/*
 * Pointer arguments (every function of this header): a pointer must be valid for what the function
 * reads or writes, and not NULL, unless its documentation says "may be NULL". A buffer pointer
 * paired with a size (bytes/len, buf/cap, out/cap) may be NULL when that size is 0. Debug builds
 * (without NDEBUG) check these preconditions with assert(); docs/conformance.md section 7.
 */
#ifndef CODEC_LINK_H
#define CODEC_LINK_H

#include "codec/session.h"

#ifdef __cplusplus
extern "C" {
#endif

/** A byte transport. */
typedef struct {
    void *ctx;
    /** Waits up to timeout_ms for bytes: returns how many were read (> 0), 0 when none came,
     * < 0 when the transport failed (closed, I/O error). */
    int (*read)(void *ctx, uint8_t *buf, size_t cap, uint32_t timeout_ms);
    /** Writes all len bytes: 0, or < 0 when the transport failed. */
    int (*write)(void *ctx, const uint8_t *data, size_t len);
    /** A monotonic clock in milliseconds. */
    uint64_t (*now_ms)(void *ctx);
} codec_transport_t;

/** A session over a transport. */
typedef struct {
    codec_session_t session;
    codec_transport_t transport;
    codec_session_event_fn on_event; /* the caller's (every event, results included); may be NULL */
    void *ctx;
    uintptr_t tag;         /* of the command run waits for */
    bool done;             /* its result arrived */
    codec_result_t result; /* its result, with packet and error copied below */
    uint8_t reply[CODEC_MAX_PACKET];
    char error[CODEC_SESSION_ERROR_MAX];
    uintptr_t next_tag;
} codec_link_t;

/**
 * Starts a link: `config` as for codec_session_init (its on_event/ctx receive every event: data
 * packets, skip runs and every result); at most one command is pending at a time.
 */
codec_status_t codec_link_init(codec_link_t *link, const codec_transport_t *transport,
                               const codec_session_config_t *config);

/**
 * Sends a command and waits for its result, feeding every byte received to the session (data
 * packets reach the handlers meanwhile). Returns the result's kind: CODEC_RESULT_ACK or
 * CODEC_RESULT_SENT on success; CODEC_RESULT_REFUSED (also for a value that is not a command),
 * NACK, TIMEOUT, INVALID, or TRANSPORT when the transport failed. *result (may be NULL) receives
 * the result; its packet and error stay valid until the next call. options may be NULL (its tag
 * is replaced by the link's own).
 */
codec_result_kind_t codec_link_run(codec_link_t *link, const codec_field_value_t *command,
                                   const codec_start_options_t *options, codec_result_t *result);

/** Records a result the caller decided on without sending (kind, and the error text why) as the
 * link's last result and returns kind (the typed command API uses it for arguments it refuses). */
codec_result_kind_t codec_link_fail(codec_link_t *link, codec_result_kind_t kind, const char *why);

/** Waits up to wait_ms for bytes and feeds them (or runs the timeouts); < 0: the transport failed. */
int codec_link_pump(codec_link_t *link, uint32_t wait_ms);
/** Receives for duration_ms, routing every packet to the handlers; < 0: the transport failed. */
int codec_link_listen(codec_link_t *link, uint32_t duration_ms);
/** Closes the session (a trailing skip run is reported); the transport is the caller's. */
void codec_link_close(codec_link_t *link);

/**
 * Decodes the typed reply of an acknowledged result (codec_result_reply_entry) into *value for
 * the link's device. CODEC_ERR_UNKNOWN_DESCRIPTOR when the result has no reply field.
 */
codec_status_t codec_link_reply(const codec_link_t *link, const codec_result_t *result,
                                codec_field_value_t *value);

#ifdef __cplusplus
}
#endif

#endif
