/* Command sessions of docs/conformance.md section 8: send commands, match their replies, route
 * data. The core is sans-I/O and allocates nothing: the caller gives it the current time in
 * milliseconds with every call, sends the packet bytes it builds and feeds it the bytes it
 * receives.
 *
 * Bounded state, whatever arrives: the session holds at most CODEC_MAX_PACKET (the protocol's
 * framing.max_packet) bytes of undecided input, the parser's candidate packet, plus the offset and
 * length of the pending skip run, which is reported as soon as it reaches CODEC_SESSION_SKIP_PIECE
 * bytes (so a caller that prints skipped bytes keeps fewer than that many). Replies are recognised
 * by content: a packet that arrives slowly is never dropped by time (the look-ahead rule of
 * codec_session_feed). */
/*
 * Pointer arguments (every function of this header): a pointer must be valid for what the function
 * reads or writes, and not NULL, unless its documentation says "may be NULL". A buffer pointer
 * paired with a size (bytes/len, buf/cap, out/cap) may be NULL when that size is 0. Debug builds
 * (without NDEBUG) check these preconditions with assert(); docs/conformance.md section 7.
 */
#ifndef CODEC_SESSION_H
#define CODEC_SESSION_H

#include "codec/clock.h"
#include "codec/dispatch.h"
#include "codec/field_iter.h"
#include "codec/parser.h"

#ifdef __cplusplus
extern "C" {
#endif

/** Commands waiting for their replies at once (the fixed pending queue); define it before
 * including this header (the same value in every translation unit) to change it. */
#ifndef CODEC_SESSION_MAX_PENDING
#define CODEC_SESSION_MAX_PENDING 8
#endif
/** Handlers per (set, descriptor) a session holds. */
#ifndef CODEC_SESSION_MAX_FIELD_HANDLERS
#define CODEC_SESSION_MAX_FIELD_HANDLERS 8
#endif
/** Room for any error text of a result (refusal, undecodable reply). */
#define CODEC_SESSION_ERROR_MAX (CODEC_ERROR_MESSAGE_MAX + 3 * CODEC_NAME_MAX + 64)

/** A skip run is reported when it ends or as soon as its pending length reaches this many bytes
 * (then a run of exactly this length; the bytes skipped after it start a new run). */
#define CODEC_SESSION_SKIP_PIECE 65536u

#define CODEC_SESSION_DEFAULT_TIMEOUT_MS 1000u
#define CODEC_SESSION_DEFAULT_INTER_PACKET_TIMEOUT_MS 100u

/** The one result every started command gets. */
typedef enum {
    CODEC_RESULT_ACK = 1,       /* acknowledged; the reply fields are valid */
    CODEC_RESULT_NACK = 2,      /* the device answered with an error code */
    CODEC_RESULT_TIMEOUT = 3,   /* no reply before the deadline */
    CODEC_RESULT_INVALID = 4,   /* acknowledged, but a reply field does not decode or is missing (error) */
    CODEC_RESULT_SENT = 5,      /* the command suppresses its ack: complete once sent */
    CODEC_RESULT_REFUSED = 6,   /* not sent (device support, full queue; error) */
    CODEC_RESULT_TRANSPORT = 7, /* blocking API only: the transport failed (error) */
    CODEC_RESULT_LOST = 8       /* blocking API, reconnecting: the port was lost under the command (error) */
} codec_result_kind_t;

/** "ack", "nack", "timeout", "invalid", "sent", "refused", "transport" or "lost". */
const char *codec_result_kind_name(codec_result_kind_t kind);

/** A command's result. Pointers are valid during the callback that delivers it (until the next
 * call into the session). */
typedef struct {
    codec_result_kind_t kind;
    uintptr_t tag;            /* the tag given to codec_session_start */
    codec_field_id_t command; /* the command's layout */
    uint8_t set;
    uint8_t descriptor;
    bool has_code;         /* ack, nack, invalid */
    uint32_t code;         /* the ack/nack code */
    const uint8_t *packet; /* the reply packet (ack, nack, invalid), else NULL */
    size_t packet_len;
    uint64_t offset;    /* its stream offset */
    size_t reply_begin; /* payload offsets of the reply field entries (after the ack) */
    size_t reply_end;
    uint8_t expect[CODEC_SESSION_MAX_EXPECT]; /* the reply descriptors the command expects */
    size_t expect_count;
    const char *error; /* invalid, refused, transport: why (NUL-terminated); else "" */
} codec_result_t;

/** Iterates the reply field entries of a result (none unless it has a packet); entry offsets are
 * payload offsets. */
void codec_result_reply_iter(const codec_result_t *result, codec_field_iter_t *it);
/** The typed reply entry: the first reply entry whose descriptor is expected, else the first
 * field entry. Returns false when there is none. */
bool codec_result_reply_entry(const codec_result_t *result, codec_field_entry_t *entry);

typedef enum {
    CODEC_SESSION_RESULT = 1, /* a command completed (result) */
    CODEC_SESSION_PACKET = 2, /* a packet that is not a reply (stream: its bytes and offset) */
    CODEC_SESSION_SKIP = 3,   /* a run of skipped bytes (stream: offset, length) */
    CODEC_SESSION_FOREIGN = 4 /* an NMEA sentence or RTCM3 frame between packets (stream: the parser's
                                 CODEC_EVENT_NMEA or CODEC_EVENT_RTCM event); ignore it if unwanted */
} codec_session_event_kind_t;

typedef struct {
    codec_session_event_kind_t kind;
    const codec_result_t *result; /* RESULT */
    const codec_event_t *stream;  /* PACKET, SKIP, FOREIGN: the parser's event */
} codec_session_event_t;

/** Receives every event in stream order (may be NULL in the configuration: no events). */
typedef void (*codec_session_event_fn)(void *ctx, const codec_session_event_t *event);
/** A data handler for a whole packet that is not a reply. */
typedef void (*codec_packet_handler_fn)(void *ctx, const codec_event_t *packet);
/** A data handler for one decoded field (set, descriptor) of a packet that is not a reply. */
typedef void (*codec_field_handler_fn)(void *ctx, const codec_field_value_t *value,
                                       const codec_event_t *packet);

typedef struct {
    codec_device_t device;            /* CODEC_DEVICE_ANY: none selected */
    uint32_t timeout_ms;              /* reply timeout T */
    uint32_t inter_packet_timeout_ms; /* P */
    size_t max_pending;               /* 1..CODEC_SESSION_MAX_PENDING */
    bool check_device;                /* refuse what the device does not support */
    codec_session_event_fn on_event;  /* may be NULL */
    void *ctx;
} codec_session_config_t;

/** Defaults: no device, T 1000 ms, P 100 ms, CODEC_SESSION_MAX_PENDING, device check on. */
void codec_session_config_init(codec_session_config_t *config);

typedef struct {
    bool used;
    uint8_t set;
    uint8_t descriptor;
    codec_field_id_t command;
    uint64_t deadline;
    uintptr_t tag;
    uint8_t expect[CODEC_SESSION_MAX_EXPECT];
    size_t expect_count;
} codec_pending_t;

typedef struct {
    uint8_t set;
    uint8_t descriptor;
    codec_field_handler_fn fn;
    void *ctx;
} codec_field_handler_t;

/** The session state: fixed size, no allocation (the caller places it). */
typedef struct {
    codec_session_config_t config;
    codec_parser_t parser;
    bool waiting; /* the parser waits for more input at stream offset wait_at */
    uint64_t wait_at;
    uint64_t wait_since; /* since this time */
    uint64_t now;
    codec_pending_t pending[CODEC_SESSION_MAX_PENDING]; /* oldest first; count used */
    size_t count;
    codec_packet_handler_fn packet_fn;
    void *packet_ctx;
    codec_field_handler_t fields[CODEC_SESSION_MAX_FIELD_HANDLERS];
    size_t field_count;
    char error[CODEC_SESSION_ERROR_MAX];
    codec_clock_t *clock;   /* the host clock model the data route feeds (NULL: none) */
    int64_t read_ns;        /* the host time of the bytes being fed (ns) */
    bool packet_host;       /* the packet being routed has a host time: */
    int64_t packet_host_ns; /* this one */
} codec_session_t;

/** Starts a session; CODEC_ERR_INVALID for a bad configuration (max_pending out of range, an
 * unknown device). */
codec_status_t codec_session_init(codec_session_t *session, const codec_session_config_t *config);

/** Calls fn for every packet that is not a reply (one handler; NULL removes it). */
void codec_session_on_packet(codec_session_t *session, codec_packet_handler_fn fn, void *ctx);
/** Calls fn with the decoded value of every field (set, descriptor) of a packet that is not a
 * reply. CODEC_ERR_BUFFER when CODEC_SESSION_MAX_FIELD_HANDLERS are registered already. */
codec_status_t codec_session_on_field(codec_session_t *session, uint8_t set, uint8_t descriptor,
                                      codec_field_handler_fn fn, void *ctx);

/**
 * The host clock model (docs/time.md): from now on every packet that is not a reply and carries
 * the device's reference time (the spec's time.reference_time: codec_reference_ns) feeds *clock
 * (placed and initialised by the caller) at the host time of its bytes. NULL stops it.
 */
void codec_session_use_clock(codec_session_t *session, codec_clock_t *clock);
/** codec_session_feed with the host time the bytes were read (ns of a monotonic clock), for the
 * clock model; codec_session_feed takes now (ms) x 1000000. */
void codec_session_feed_at(codec_session_t *session, const uint8_t *data, size_t len, uint64_t now,
                           int64_t read_ns);
/** Inside a packet or field handler (or the event callback of a packet): the packet's host time by
 * the clock model into *host_ns; false without a model, an estimate or the reference time. */
bool codec_session_host_ns(const codec_session_t *session, int64_t *host_ns);

/** Per-call options of codec_session_start (NULL: the session's). */
typedef struct {
    int64_t timeout_ms; /* < 0: the session's */
    int check_device;   /* < 0: the session's, 0 off, > 0 on */
    uintptr_t tag;      /* given back in the result */
} codec_start_options_t;

void codec_start_options_init(codec_start_options_t *options);

/** What codec_session_start did. */
typedef struct {
    size_t packet_len; /* bytes of the packet to send (0: nothing to send, refused) */
    bool done;         /* completed at once: result is refused or sent */
    uint64_t deadline; /* queued commands: when they time out */
    codec_result_t result;
} codec_started_t;

/**
 * Starts a command (a value of a layout whose role is command) at `now`: builds its packet into
 * packet[0..cap) and queues it, or completes it at once (refused: nothing to send; sent: the ack
 * is suppressed). Returns CODEC_OK, CODEC_ERR_INVALID (not a command, or its values cannot be
 * encoded) or CODEC_ERR_BUFFER (cap smaller than the packet). options may be NULL.
 */
codec_status_t codec_session_start(codec_session_t *session, const codec_field_value_t *command, uint64_t now,
                                   const codec_start_options_t *options, uint8_t *packet, size_t cap,
                                   codec_started_t *out);

/**
 * Bytes received at `now`: the timeouts first, then the look-ahead rule, then the bytes are
 * parsed, then the look-ahead rule again. The look-ahead rule: while the parser has waited at one
 * stream position (a partial sync, header or packet) since `s` and now - s > P (the inter-packet
 * timeout), the first complete packet with a valid checksum buffered after that position ends
 * the wait (the bytes before it are skipped and it is parsed); without one nothing is dropped.
 * It runs on the buffer as it was before the bytes (so polling in between changes nothing) and,
 * when the same wait had expired, after them.
 */
void codec_session_feed(codec_session_t *session, const uint8_t *data, size_t len, uint64_t now);
/** Nothing received: the timeouts and the look-ahead rule at `now`. */
void codec_session_poll(codec_session_t *session, uint64_t now);
/** End of input: poll at `now`, then the buffered bytes that are not a packet are skipped. */
void codec_session_close(codec_session_t *session, uint64_t now);
/** The earliest time poll has something to do: a command's deadline, or s + P + 1 while the
 * parser waits since s and that wait had not expired at the last call (once expired, only new
 * bytes can change it); false if none. */
bool codec_session_next_deadline(const codec_session_t *session, uint64_t *deadline);
/** Commands waiting for their replies. */
size_t codec_session_pending(const codec_session_t *session);
/** Drops the commands waiting for their replies without a result (the link to the device was lost:
 * the caller reports them; their replies, should they come, are data). */
void codec_session_forget(codec_session_t *session);

/* ------------------------------------------------------------------ generated per package
 * (src/session_facts.c, templates/c/session_facts.c.j2): what the spec says about commands. */

/** The facts of one command value (its layout, and the values it was given). */
typedef struct {
    codec_field_id_t id;
    uint8_t set;
    uint8_t descriptor;
    int function;                 /* function selector value, -1: no selector */
    bool function_listed;         /* the layout accepts the function (true without a selector) */
    uint32_t function_devices;    /* devices the function's value is limited to (bit 1 << device; all: ~0) */
    uint32_t field_devices;       /* devices any layout of (set, descriptor) lists */
    codec_device_t layout_device; /* the device of a per-device layout, else CODEC_DEVICE_ANY */
    bool suppressed;              /* the command as given suppresses its ack */
    uint32_t allowance_ms;        /* extra reply time (spec timeout) */
    uint8_t expect[CODEC_SESSION_MAX_EXPECT]; /* expected reply descriptors (spec responses, when) */
    size_t expect_count;
} codec_command_facts_t;

/** Fills *out; false when the value is not of a command layout. */
bool codec_command_facts(const codec_field_value_t *command, codec_command_facts_t *out);
/** The enum name of a function selector value, or NULL. */
const char *codec_function_name(int value);
/** The field data of descriptor CODEC_SESSION_ACK_DESCRIPTOR in a packet of `set`: 1 when it is the
 * ack field and decodes (*echo, *code), 0 when it does not decode (a raw field), -1 when it decodes
 * as another field. */
int codec_session_ack_decode(uint8_t set, const uint8_t *data, size_t len, codec_device_t device,
                             uint8_t *echo, uint32_t *code);
/** Per device, where a data packet carries the device's reference time (the spec's
 * time.reference_time; session_facts.c): a count of units (ns_per_unit ns each) or a GPS time. */
typedef struct {
    codec_device_t device;
    uint8_t set; /* the field's set */
    bool shared; /* the set is the shared one: the field is valid in every data set */
    uint8_t descriptor;
    bool gps;       /* tow (f64 s) at offset and week (week_size bytes) at week_offset */
    uint8_t offset; /* of the count or of tow, in the field data */
    uint8_t size;   /* of the count */
    uint8_t week_offset;
    uint8_t week_size;
    int64_t ns_per_unit; /* of the count */
} codec_reference_time_t;
extern const codec_reference_time_t codec_reference_times[];
extern const size_t codec_reference_time_count;
/** The device's reference time (ns) in the payload of a packet of `set`: the first field the table
 * names for `device` (every device's for CODEC_DEVICE_ANY); false when it carries none. */
bool codec_reference_ns(codec_device_t device, uint8_t set, const uint8_t *payload, size_t len, int64_t *ns);
/** The names `device` answers to in the wrong-model check (codec_link_t note): its title and its
 * identity model name, upper case without spaces and punctuation; a NULL-terminated list. */
const char *const *codec_device_model_names(codec_device_t device);

#ifdef __cplusplus
}
#endif

#endif
