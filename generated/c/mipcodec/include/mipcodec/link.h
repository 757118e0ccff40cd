/* The blocking session API of docs/conformance.md section 8: a session over a transport given as
 * three callbacks (read with a timeout, write, clock). Freestanding: no OS calls, no heap; the
 * POSIX transports (TCP, serial) are in the optional mipcodec/posix_transport.h.
 * Generated: do not edit. */
/*
 * Pointer arguments (every function of this header): a pointer must be valid for what the function
 * reads or writes, and not NULL, unless its documentation says "may be NULL". A buffer pointer
 * paired with a size (bytes/len, buf/cap, out/cap) may be NULL when that size is 0. Debug builds
 * (without NDEBUG) check these preconditions with assert(); docs/conformance.md section 7.
 */
#ifndef MIPC_LINK_H
#define MIPC_LINK_H

#include "mipcodec/session.h"

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
} mipc_transport_t;

/* ------------------------------------------------------------------ getting through
 * (docs/conformance.md section 8, "Getting through"): the optional port operations, the options and
 * the settings recorded for a reconnect. */

/** What a port can do beyond reading and writing (each may be NULL: not available). */
typedef struct {
    void *ctx;
    /** Discards the input received and not yet read: 0, or < 0. */
    int (*flush)(void *ctx);
    /** Changes the host side's baud rate: 0, or < 0. NULL: the port has no baud rate (TCP). */
    int (*set_baud)(void *ctx, uint32_t baud);
    /** Closes and opens the same address again: 0 when it is open, < 0 when not (yet). */
    int (*reopen)(void *ctx);
    /** The address, for the log ("/tmp/x/dev"). */
    const char *(*address)(void *ctx);
    /** Why the port failed last ("Input/output error"), for the log. */
    const char *(*reason)(void *ctx);
    /** Sleeps ms milliseconds (between reopen attempts, the settle time of a baud change). */
    void (*sleep_ms)(void *ctx, uint32_t ms);
    uint32_t baud; /* the rate it is open at (0: none) */
} mipc_port_t;

/** Receives each step of getting through as one line ("link: baud: device answers at 921600"),
 * without a newline; valid during the call. */
typedef void (*mipc_link_log_fn)(void *ctx, const char *line);

/** A command the link sends without parameters (idle, ping, resume); present false: none. */
typedef struct {
    bool present;
    uint8_t set;
    uint8_t descriptor;
} mipc_link_command_t;

typedef struct {
    mipc_link_log_fn log; /* may be NULL */
    void *log_ctx;
    uint32_t reconnect_ms;       /* reopen a lost port for up to this long (0: no reconnect) */
    uint32_t reopen_interval_ms; /* between reopen attempts */
    uint32_t quiet_ms;           /* the input drained after a flush, before the next attempt */
    bool auto_baud;              /* the application searches the baud rate at connect (mipc_link_find_baud) */
    mipc_link_command_t idle;    /* the spec's (MIPC_LINK_IDLE_*) */
    mipc_link_command_t ping;    /* the spec's (MIPC_LINK_PING_*) */
    mipc_link_command_t resume;  /* the spec's (MIPC_LINK_RESUME_*) */
} mipc_link_options_t;

#define MIPC_LINK_DEFAULT_RECONNECT_MS 10000u
#define MIPC_LINK_REOPEN_INTERVAL_MS 500u
#define MIPC_LINK_QUIET_MS 50u
/** Settings recorded for a reconnect (the latest per key wins; one more forgets the oldest). */
#ifndef MIPC_LINK_MAX_SETTINGS
#define MIPC_LINK_MAX_SETTINGS 64
#endif
#define MIPC_LINK_LOG_MAX 320
/** The most bytes one read asks the transport for (at most 65536, docs/conformance.md section 8):
 * after each read the bytes are fed with the current time and their events handled, so a deadline
 * is kept under a continuous flood. */
#ifndef MIPC_LINK_READ_MAX
#define MIPC_LINK_READ_MAX 4096
#endif
#if MIPC_LINK_READ_MAX < 1 || MIPC_LINK_READ_MAX > 65536
#error "MIPC_LINK_READ_MAX must be from 1 to 65536"
#endif
/** Room for a link's note ("connected device is NAME, this session was told ID": the model name
 * as shown, at most 4 characters per byte, and a device id). */
#define MIPC_LINK_NOTE_MAX (64u + 4u * MIPC_IDENTITY_MODEL_LENGTH + MIPC_NAME_MAX)
/** The most baud rates a search tries (every device's supported rates). */
#define MIPC_LINK_MAX_BAUD_RATES 16

/** A setting as written: its field data (re-sent after a reconnect). Its key: set, descriptor and
 * the first key_len data bytes after the function selector (the parameters its read sends). */
typedef struct {
    uint8_t set;
    uint8_t descriptor;
    uint8_t key_len;
    uint8_t len;
    uint8_t data[MIPC_MAX_FIELD_DATA];
} mipc_link_setting_t;

/** A session over a transport. */
typedef struct {
    mipc_session_t session;
    mipc_transport_t transport;
    mipc_session_event_fn on_event; /* the caller's (every event, results included); may be NULL */
    void *ctx;
    uintptr_t tag;        /* of the command run waits for */
    bool done;            /* its result arrived */
    mipc_result_t result; /* its result, with packet and error copied below */
    uint8_t reply[MIPC_MAX_PACKET];
    char error[MIPC_SESSION_ERROR_MAX];
    uint8_t rx[MIPC_LINK_READ_MAX]; /* one read */
    uintptr_t next_tag;
    /* getting through (mipc_link_attach) */
    mipc_port_t port;
    mipc_link_options_t options;
    bool internal;    /* an operation of the link itself: events counted and dropped, not recorded */
    bool connected;   /* false after a loss that was not repaired */
    uint64_t dropped; /* bytes of packets and skip runs dropped while internal */
    mipc_link_setting_t settings[MIPC_LINK_MAX_SETTINGS];
    size_t setting_count;
    bool idled; /* the application's last idle or resume command was an idle (no resume after a reconnect) */
    char line[MIPC_LINK_LOG_MAX];
    /* the wrong-model check: done (or not to do: no device selected), and the note of the last run */
    bool identified;
    /** After mipc_link_run: what its result alone does not tell, else "". The first NACK for a
     * command the device does not know (an unknown-command code) makes a link told a device ask
     * the device what it is (the spec's identity command, once); when the model name it reports
     * is not that device's (mipc_link_model_note), the note is "connected device is 3DM-GX5-45,
     * this session was told cv7_ins". */
    char note[MIPC_LINK_NOTE_MAX];
} mipc_link_t;

/**
 * Starts a link: `config` as for mipc_session_init (its on_event/ctx receive every event: data
 * packets, skip runs and every result); at most one command is pending at a time.
 */
mipc_status_t mipc_link_init(mipc_link_t *link, const mipc_transport_t *transport,
                             const mipc_session_config_t *config);

/**
 * Sends a command and waits for its result, feeding every byte received to the session (data
 * packets reach the handlers meanwhile). Returns the result's kind: MIPC_RESULT_ACK or
 * MIPC_RESULT_SENT on success; MIPC_RESULT_REFUSED (also for a value that is not a command),
 * NACK, TIMEOUT, INVALID, or TRANSPORT when the transport failed. *result (may be NULL) receives
 * the result; its packet and error stay valid until the next call. options may be NULL (its tag
 * is replaced by the link's own).
 */
mipc_result_kind_t mipc_link_run(mipc_link_t *link, const mipc_field_value_t *command,
                                 const mipc_start_options_t *options, mipc_result_t *result);

/** Records a result the caller decided on without sending (kind, and the error text why) as the
 * link's last result and returns kind (the typed command API uses it for arguments it refuses). */
mipc_result_kind_t mipc_link_fail(mipc_link_t *link, mipc_result_kind_t kind, const char *why);

/** Waits up to wait_ms for bytes and feeds them (or runs the timeouts); < 0: the transport failed. */
int mipc_link_pump(mipc_link_t *link, uint32_t wait_ms);
/** Receives for duration_ms, routing every packet to the handlers; < 0: the transport failed. */
int mipc_link_listen(mipc_link_t *link, uint32_t duration_ms);
/** Closes the session (a trailing skip run is reported); the transport is the caller's. */
void mipc_link_close(mipc_link_t *link);

/** Defaults: no log, reconnect for MIPC_LINK_DEFAULT_RECONNECT_MS every
 * MIPC_LINK_REOPEN_INTERVAL_MS, quiet time MIPC_LINK_QUIET_MS, no baud search, the idle, ping and
 * resume commands of the spec's link section. */
void mipc_link_options_init(mipc_link_options_t *options);

/** Gives the link its port operations and options (either may be NULL: none, the defaults).
 * Without it a link neither flushes, nor changes baud rates, nor reconnects. */
void mipc_link_attach(mipc_link_t *link, const mipc_port_t *port, const mipc_link_options_t *options);

/**
 * Gets the device to idle (the protocol's idle command), also while it streams at full rate: the
 * packets that arrive meanwhile are counted and dropped; on no ACK the input is flushed (port and
 * parser), drained for the quiet time and the command sent again, MIPC_LINK_IDLE_ATTEMPTS times in
 * all, each with the command's timeout; a NACK is not retried. Returns ACK, or the last attempt's
 * result (the error in link->result.error). REFUSED when the protocol has no idle command.
 */
mipc_result_kind_t mipc_link_to_idle(mipc_link_t *link);

/**
 * Pings the device; with a port that has a baud rate and no answer, tries the device's supported
 * rates (the configured one, the default, then from the highest down; with no device selected the
 * defaults of every device, then every device's rates), each after switching and a flush, and
 * stays at the first that answers (port.baud). Returns ACK, or the failure.
 */
mipc_result_kind_t mipc_link_find_baud(mipc_link_t *link);

/**
 * Reopens a lost port every reopen_interval_ms until reconnect_ms have passed since the loss, then
 * gets to idle, re-sends the recorded settings in order and the resume command (unless the
 * application's last idle or resume command was an idle). mipc_link_run and the pumps call it
 * when the transport fails (the command in flight fails with MIPC_RESULT_LOST, "link lost:
 * REASON"). Returns 0 when reconnected, < 0 when not (link->connected false).
 */
int mipc_link_reconnect(mipc_link_t *link);

/**
 * The wrong-model rule (the same in every language): `name` (len bytes, as the device reported
 * it) with spaces and NULs at either end removed, is not empty and, upper case without spaces and
 * punctuation (a byte outside ASCII kept), is none of mipc_device_model_names(told): writes
 * "connected device is NAME, this session was told ID" to out (NAME with every byte outside
 * printable ASCII written \xNN, truncated to fit cap) and returns true; else false (out "").
 */
bool mipc_link_model_note(mipc_device_t told, const uint8_t *name, size_t len, char *out, size_t cap);

/**
 * Decodes the typed reply of an acknowledged result (mipc_result_reply_entry) into *value for
 * the link's device. MIPC_ERR_UNKNOWN_DESCRIPTOR when the result has no reply field.
 */
mipc_status_t mipc_link_reply(const mipc_link_t *link, const mipc_result_t *result,
                              mipc_field_value_t *value);

#ifdef __cplusplus
}
#endif

#endif
