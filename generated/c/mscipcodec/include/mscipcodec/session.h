/* Command sessions of docs/conformance.md section 8: send commands, match their replies, route
 * data. The core is sans-I/O and allocates nothing: the caller gives it the current time in
 * milliseconds with every call, sends the packet bytes it builds and feeds it the bytes it
 * receives.
 *
 * Bounded state, whatever arrives: the session holds at most MSCIPC_MAX_PACKET (the protocol's
 * framing.max_packet) bytes of undecided input, the parser's candidate packet, plus the offset and
 * length of the pending skip run, which is reported as soon as it reaches MSCIPC_SESSION_SKIP_PIECE
 * bytes (so a caller that prints skipped bytes keeps fewer than that many). Replies are recognised
 * by content: a packet that arrives slowly is never dropped by time (the look-ahead rule of
 * mscipc_session_feed). Generated: do not edit. */
/*
 * Pointer arguments (every function of this header): a pointer must be valid for what the function
 * reads or writes, and not NULL, unless its documentation says "may be NULL". A buffer pointer
 * paired with a size (bytes/len, buf/cap, out/cap) may be NULL when that size is 0. Debug builds
 * (without NDEBUG) check these preconditions with assert(); docs/conformance.md section 7.
 */
#ifndef MSCIPC_SESSION_H
#define MSCIPC_SESSION_H

#include "mscipcodec/clock.h"
#include "mscipcodec/dispatch.h"
#include "mscipcodec/field_iter.h"
#include "mscipcodec/parser.h"

#ifdef __cplusplus
extern "C" {
#endif

/** Commands waiting for their replies at once (the fixed pending queue); define it before
 * including this header (the same value in every translation unit) to change it. */
#ifndef MSCIPC_SESSION_MAX_PENDING
#define MSCIPC_SESSION_MAX_PENDING 8
#endif
/** Handlers per (set, descriptor) a session holds. */
#ifndef MSCIPC_SESSION_MAX_FIELD_HANDLERS
#define MSCIPC_SESSION_MAX_FIELD_HANDLERS 8
#endif
/** Room for any error text of a result (refusal, undecodable reply). */
#define MSCIPC_SESSION_ERROR_MAX (MSCIPC_ERROR_MESSAGE_MAX + 3 * MSCIPC_NAME_MAX + 64)

/** A skip run is reported when it ends or as soon as its pending length reaches this many bytes
 * (then a run of exactly this length; the bytes skipped after it start a new run). */
#define MSCIPC_SESSION_SKIP_PIECE 65536u

#define MSCIPC_SESSION_DEFAULT_TIMEOUT_MS 1000u
#define MSCIPC_SESSION_DEFAULT_INTER_PACKET_TIMEOUT_MS 100u

/** The one result every started command gets. */
typedef enum {
    MSCIPC_RESULT_ACK = 1,       /* acknowledged; the reply fields are valid */
    MSCIPC_RESULT_NACK = 2,      /* the device answered with an error code */
    MSCIPC_RESULT_TIMEOUT = 3,   /* no reply before the deadline */
    MSCIPC_RESULT_INVALID = 4,   /* acknowledged, but a reply field does not decode or is missing (error) */
    MSCIPC_RESULT_SENT = 5,      /* the command suppresses its ack: complete once sent */
    MSCIPC_RESULT_REFUSED = 6,   /* not sent (device support, full queue; error) */
    MSCIPC_RESULT_TRANSPORT = 7, /* blocking API only: the transport failed (error) */
    MSCIPC_RESULT_LOST = 8       /* blocking API, reconnecting: the port was lost under the command (error) */
} mscipc_result_kind_t;

/** "ack", "nack", "timeout", "invalid", "sent", "refused", "transport" or "lost". */
const char *mscipc_result_kind_name(mscipc_result_kind_t kind);

/** A command's result. Pointers are valid during the callback that delivers it (until the next
 * call into the session). */
typedef struct {
    mscipc_result_kind_t kind;
    uintptr_t tag;             /* the tag given to mscipc_session_start */
    mscipc_field_id_t command; /* the command's layout */
    uint8_t set;
    uint8_t descriptor;
    bool has_code;         /* ack, nack, invalid */
    uint32_t code;         /* the ack/nack code */
    const uint8_t *packet; /* the reply packet (ack, nack, invalid), else NULL */
    size_t packet_len;
    uint64_t offset;    /* its stream offset */
    size_t reply_begin; /* payload offsets of the reply field entries (after the ack) */
    size_t reply_end;
    uint8_t expect[MSCIPC_SESSION_MAX_EXPECT]; /* the reply descriptors the command expects */
    size_t expect_count;
    const char *error; /* invalid, refused, transport: why (NUL-terminated); else "" */
} mscipc_result_t;

/** Iterates the reply field entries of a result (none unless it has a packet); entry offsets are
 * payload offsets. */
void mscipc_result_reply_iter(const mscipc_result_t *result, mscipc_field_iter_t *it);
/** The typed reply entry: the first reply entry whose descriptor is expected, else the first
 * field entry. Returns false when there is none. */
bool mscipc_result_reply_entry(const mscipc_result_t *result, mscipc_field_entry_t *entry);

typedef enum {
    MSCIPC_SESSION_RESULT = 1, /* a command completed (result) */
    MSCIPC_SESSION_PACKET = 2, /* a packet that is not a reply (stream: its bytes and offset) */
    MSCIPC_SESSION_SKIP = 3,   /* a run of skipped bytes (stream: offset, length) */
    MSCIPC_SESSION_FOREIGN = 4 /* an NMEA sentence or RTCM3 frame between packets (stream: the parser's
                                 MSCIPC_EVENT_NMEA or MSCIPC_EVENT_RTCM event); ignore it if unwanted */
} mscipc_session_event_kind_t;

typedef struct {
    mscipc_session_event_kind_t kind;
    const mscipc_result_t *result; /* RESULT */
    const mscipc_event_t *stream;  /* PACKET, SKIP, FOREIGN: the parser's event */
} mscipc_session_event_t;

/** Receives every event in stream order (may be NULL in the configuration: no events). */
typedef void (*mscipc_session_event_fn)(void *ctx, const mscipc_session_event_t *event);
/** A data handler for a whole packet that is not a reply. */
typedef void (*mscipc_packet_handler_fn)(void *ctx, const mscipc_event_t *packet);
/** A data handler for one decoded field (set, descriptor) of a packet that is not a reply. */
typedef void (*mscipc_field_handler_fn)(void *ctx, const mscipc_field_value_t *value,
                                        const mscipc_event_t *packet);

typedef struct {
    mscipc_device_t device;           /* MSCIPC_DEVICE_ANY: none selected */
    uint32_t timeout_ms;              /* reply timeout T */
    uint32_t inter_packet_timeout_ms; /* P */
    size_t max_pending;               /* 1..MSCIPC_SESSION_MAX_PENDING */
    bool check_device;                /* refuse what the device does not support */
    mscipc_session_event_fn on_event; /* may be NULL */
    void *ctx;
} mscipc_session_config_t;

/** Defaults: no device, T 1000 ms, P 100 ms, MSCIPC_SESSION_MAX_PENDING, device check on. */
void mscipc_session_config_init(mscipc_session_config_t *config);

typedef struct {
    bool used;
    uint8_t set;
    uint8_t descriptor;
    mscipc_field_id_t command;
    uint64_t deadline;
    uintptr_t tag;
    uint8_t expect[MSCIPC_SESSION_MAX_EXPECT];
    size_t expect_count;
} mscipc_pending_t;

typedef struct {
    uint8_t set;
    uint8_t descriptor;
    mscipc_field_handler_fn fn;
    void *ctx;
} mscipc_field_handler_t;

/** The session state: fixed size, no allocation (the caller places it). */
typedef struct {
    mscipc_session_config_t config;
    mscipc_parser_t parser;
    bool waiting; /* the parser waits for more input at stream offset wait_at */
    uint64_t wait_at;
    uint64_t wait_since; /* since this time */
    uint64_t now;
    mscipc_pending_t pending[MSCIPC_SESSION_MAX_PENDING]; /* oldest first; count used */
    size_t count;
    mscipc_packet_handler_fn packet_fn;
    void *packet_ctx;
    mscipc_field_handler_t fields[MSCIPC_SESSION_MAX_FIELD_HANDLERS];
    size_t field_count;
    char error[MSCIPC_SESSION_ERROR_MAX];
    mscipc_clock_t *clock;  /* the host clock model the data route feeds (NULL: none) */
    int64_t read_ns;        /* the host time of the bytes being fed (ns) */
    bool packet_host;       /* the packet being routed has a host time: */
    int64_t packet_host_ns; /* this one */
} mscipc_session_t;

/** Starts a session; MSCIPC_ERR_INVALID for a bad configuration (max_pending out of range, an
 * unknown device). */
mscipc_status_t mscipc_session_init(mscipc_session_t *session, const mscipc_session_config_t *config);

/** Calls fn for every packet that is not a reply (one handler; NULL removes it). */
void mscipc_session_on_packet(mscipc_session_t *session, mscipc_packet_handler_fn fn, void *ctx);
/** Calls fn with the decoded value of every field (set, descriptor) of a packet that is not a
 * reply. MSCIPC_ERR_BUFFER when MSCIPC_SESSION_MAX_FIELD_HANDLERS are registered already. */
mscipc_status_t mscipc_session_on_field(mscipc_session_t *session, uint8_t set, uint8_t descriptor,
                                        mscipc_field_handler_fn fn, void *ctx);

/**
 * The host clock model (docs/time.md): from now on every packet that is not a reply and carries
 * the device's reference time (the spec's time.reference_time: mscipc_reference_ns) feeds *clock
 * (placed and initialised by the caller) at the host time of its bytes. NULL stops it.
 */
void mscipc_session_use_clock(mscipc_session_t *session, mscipc_clock_t *clock);
/** mscipc_session_feed with the host time the bytes were read (ns of a monotonic clock), for the
 * clock model; mscipc_session_feed takes now (ms) x 1000000. */
void mscipc_session_feed_at(mscipc_session_t *session, const uint8_t *data, size_t len, uint64_t now,
                            int64_t read_ns);
/** Inside a packet or field handler (or the event callback of a packet): the packet's host time by
 * the clock model into *host_ns; false without a model, an estimate or the reference time. */
bool mscipc_session_host_ns(const mscipc_session_t *session, int64_t *host_ns);

/** Per-call options of mscipc_session_start (NULL: the session's). */
typedef struct {
    int64_t timeout_ms; /* < 0: the session's */
    int check_device;   /* < 0: the session's, 0 off, > 0 on */
    uintptr_t tag;      /* given back in the result */
} mscipc_start_options_t;

void mscipc_start_options_init(mscipc_start_options_t *options);

/** What mscipc_session_start did. */
typedef struct {
    size_t packet_len; /* bytes of the packet to send (0: nothing to send, refused) */
    bool done;         /* completed at once: result is refused or sent */
    uint64_t deadline; /* queued commands: when they time out */
    mscipc_result_t result;
} mscipc_started_t;

/**
 * Starts a command (a value of a layout whose role is command) at `now`: builds its packet into
 * packet[0..cap) and queues it, or completes it at once (refused: nothing to send; sent: the ack
 * is suppressed). Returns MSCIPC_OK, MSCIPC_ERR_INVALID (not a command, or its values cannot be
 * encoded) or MSCIPC_ERR_BUFFER (cap smaller than the packet). options may be NULL.
 */
mscipc_status_t mscipc_session_start(mscipc_session_t *session, const mscipc_field_value_t *command,
                                     uint64_t now, const mscipc_start_options_t *options, uint8_t *packet,
                                     size_t cap, mscipc_started_t *out);

/**
 * Bytes received at `now`: the timeouts first, then the look-ahead rule, then the bytes are
 * parsed, then the look-ahead rule again. The look-ahead rule: while the parser has waited at one
 * stream position (a partial sync, header or packet) since `s` and now - s > P (the inter-packet
 * timeout), the first complete packet with a valid checksum buffered after that position ends
 * the wait (the bytes before it are skipped and it is parsed); without one nothing is dropped.
 * It runs on the buffer as it was before the bytes (so polling in between changes nothing) and,
 * when the same wait had expired, after them.
 */
void mscipc_session_feed(mscipc_session_t *session, const uint8_t *data, size_t len, uint64_t now);
/** Nothing received: the timeouts and the look-ahead rule at `now`. */
void mscipc_session_poll(mscipc_session_t *session, uint64_t now);
/** End of input: poll at `now`, then the buffered bytes that are not a packet are skipped. */
void mscipc_session_close(mscipc_session_t *session, uint64_t now);
/** The earliest time poll has something to do: a command's deadline, or s + P + 1 while the
 * parser waits since s and that wait had not expired at the last call (once expired, only new
 * bytes can change it); false if none. */
bool mscipc_session_next_deadline(const mscipc_session_t *session, uint64_t *deadline);
/** Commands waiting for their replies. */
size_t mscipc_session_pending(const mscipc_session_t *session);
/** Drops the commands waiting for their replies without a result (the link to the device was lost:
 * the caller reports them; their replies, should they come, are data). */
void mscipc_session_forget(mscipc_session_t *session);

/* ------------------------------------------------------------------ generated per package
 * (src/session_facts.c, templates/c/session_facts.c.j2): what the spec says about commands. */

/** The facts of one command value (its layout, and the values it was given). */
typedef struct {
    mscipc_field_id_t id;
    uint8_t set;
    uint8_t descriptor;
    int function;                  /* function selector value, -1: no selector */
    bool function_listed;          /* the layout accepts the function (true without a selector) */
    uint32_t function_devices;     /* devices the function's value is limited to (bit 1 << device; all: ~0) */
    uint32_t field_devices;        /* devices any layout of (set, descriptor) lists */
    mscipc_device_t layout_device; /* the device of a per-device layout, else MSCIPC_DEVICE_ANY */
    bool suppressed;               /* the command as given suppresses its ack */
    uint32_t allowance_ms;         /* extra reply time (spec timeout) */
    uint8_t expect[MSCIPC_SESSION_MAX_EXPECT]; /* expected reply descriptors (spec responses, when) */
    size_t expect_count;
} mscipc_command_facts_t;

/** Fills *out; false when the value is not of a command layout. */
bool mscipc_command_facts(const mscipc_field_value_t *command, mscipc_command_facts_t *out);
/** The enum name of a function selector value, or NULL. */
const char *mscipc_function_name(int value);
/** The field data of descriptor MSCIPC_SESSION_ACK_DESCRIPTOR in a packet of `set`: 1 when it is the
 * ack field and decodes (*echo, *code), 0 when it does not decode (a raw field), -1 when it decodes
 * as another field. */
int mscipc_session_ack_decode(uint8_t set, const uint8_t *data, size_t len, mscipc_device_t device,
                              uint8_t *echo, uint32_t *code);
/** Per device, where a data packet carries the device's reference time (the spec's
 * time.reference_time; session_facts.c): a count of units (ns_per_unit ns each) or a GPS time. */
typedef struct {
    mscipc_device_t device;
    uint8_t set; /* the field's set */
    bool shared; /* the set is the shared one: the field is valid in every data set */
    uint8_t descriptor;
    bool gps;       /* tow (f64 s) at offset and week (week_size bytes) at week_offset */
    uint8_t offset; /* of the count or of tow, in the field data */
    uint8_t size;   /* of the count */
    uint8_t week_offset;
    uint8_t week_size;
    int64_t ns_per_unit; /* of the count */
} mscipc_reference_time_t;
extern const mscipc_reference_time_t mscipc_reference_times[];
extern const size_t mscipc_reference_time_count;
/** The device's reference time (ns) in the payload of a packet of `set`: the first field the table
 * names for `device` (every device's for MSCIPC_DEVICE_ANY); false when it carries none. */
bool mscipc_reference_ns(mscipc_device_t device, uint8_t set, const uint8_t *payload, size_t len,
                         int64_t *ns);
/** The names `device` answers to in the wrong-model check (mscipc_link_t note): its title and its
 * identity model name, upper case without spaces and punctuation; a NULL-terminated list. */
const char *const *mscipc_device_model_names(mscipc_device_t device);

#ifdef __cplusplus
}
#endif

#endif
