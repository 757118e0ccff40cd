/* timesync (docs/timesync.md): sets up the device's time synchronization as its manual says, then
 * monitors it with the host clock model (codec/clock.h, docs/time.md), one line a second: the
 * Python package's device/timesync.py, line for line and with the same exit statuses.
 *
 * The facts come from the spec (DEV_TIMESYNC, the protocol's time.sync): the GPS Time Update
 * command and its selector values, the PPS source setting and each member's kind, the status
 * field, the external time fields and the correlation flags. A model with a PPS source setting
 * gets the source asked for (default: the first member of kind receiver); with a receiver's PPS
 * the device takes GPS time itself, otherwise the host sends GPS Time Updates (time of week, then
 * week) UPDATE_AFTER_S after the device's PPS edge, found from the fraction of its time of week.
 *
 * The host clock: the monotonic clock in ns from the start of the command (as the Python
 * session's, from its connection). The clock model is fed here, not by the session: the link
 * feeds its session with millisecond times, and a millisecond's rounding in every arrival time
 * leaves the drift of a 30 s run tens of ppm off; the transport is wrapped to note the time each
 * read returned, in ns, which is when the Python session dates the bytes of a read. */
#include "device.h"

#define RATE_HZ 50.0        /* the status and time fields' rate (packets for the clock model) */
#define UPDATE_AFTER_S 0.15 /* an update goes out this long after the device's PPS edge */
#define WEEK_S 604800LL
#define MAX_WEEK_S (7.0 * 86400.0) /* the longest --duration */

typedef struct {
    conn_t *c;
    const dev_timesync_t *facts;
    codec_transport_t inner; /* the link's transport, wrapped while timesync runs */
    int64_t t0_ns;           /* the monotonic clock at the start */
    int64_t read_ns;         /* host time of the latest read (since t0_ns) */
    codec_clock_t clock;     /* the host clock model, fed with every data packet's reference time */
    bool send_updates;       /* false: the device takes GPS time from its receiver's PPS */
    int64_t source;          /* the PPS source value to write (-1: the model has no such setting) */
    unsigned long updates;
    /* the monitor: what the device reports about its time */
    unsigned long packets;
    int pps;        /* -1: not reported yet */
    int time_valid; /* -1: not reported yet */
    bool have_edge;
    double edge; /* host time (s) of the device's latest PPS edge */
} sync_t;

/* An object, not the macro: a protocol without shared data compares without a constant warning. */
static const int g_shared = DEV_SHARED_SET;

typedef struct {
    double t;
    bool synced;
    bool pps;
    bool time_valid;
    bool estimated;
    double drift_ppm;
    double offset_ms;
    double jitter_ms;
    unsigned long updates;
    const char *reason; /* NULL when synced */
} line_t;

static int64_t monotonic_ns(void) {
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (int64_t)ts.tv_sec * 1000000000LL + (int64_t)ts.tv_nsec;
}

/* The host time: seconds since the start. */
static double host_now(const sync_t *s) {
    return (double)(monotonic_ns() - s->t0_ns) / 1e9;
}

/* The wrapped transport: the inner one's, and the time each read returned. */
static int wrap_read(void *ctx, uint8_t *buf, size_t cap, uint32_t timeout_ms) {
    sync_t *s = (sync_t *)ctx;
    int n = s->inner.read(s->inner.ctx, buf, cap, timeout_ms);
    s->read_ns = monotonic_ns() - s->t0_ns;
    return n;
}

static int wrap_write(void *ctx, const uint8_t *data, size_t len) {
    sync_t *s = (sync_t *)ctx;
    return s->inner.write(s->inner.ctx, data, len);
}

static uint64_t wrap_now_ms(void *ctx) {
    sync_t *s = (sync_t *)ctx;
    return s->inner.now_ms(s->inner.ctx);
}

/* The host's wall clock (UTC) as GPS seconds since the GPS epoch: GPS - UTC from the GPS time
   scale's table (DEV_LEAP_TABLE, spec/common/gps_time.yaml), as device/timesync.py does. */
static double host_gps_seconds(void) {
    struct timespec ts;
    int leap = 0;
    size_t i;
    clock_gettime(CLOCK_REALTIME, &ts);
    for (i = 0; i < DEV_LEAP_COUNT; i++) {
        if ((int64_t)ts.tv_sec >= DEV_LEAP_TABLE[i].from_unix_s) {
            leap = DEV_LEAP_TABLE[i].gps_minus_utc_s;
        }
    }
    return (double)ts.tv_sec + (double)ts.tv_nsec / 1e9 - (double)DEV_GPS_EPOCH_UNIX_S + (double)leap;
}

/* x rounded to 3 decimals as Python's round(x, 3) (correctly rounded). */
static double round3(double x) {
    char text[64];
    snprintf(text, sizeof text, "%.3f", x);
    return strtod(text, NULL);
}

/* A float as Python's repr prints it (these values are rounded to 3 decimals, below 1e16). */
static void py_float(buf_t *b, double x) {
    char text[64];
    int d;
    for (d = 0; d <= 17; d++) {
        snprintf(text, sizeof text, "%.*f", d, x);
        if (strtod(text, NULL) == x) {
            break;
        }
    }
    buf_str(b, text);
    if (d == 0) {
        buf_str(b, ".0");
    }
}

static const dev_timesync_t *facts_of(const char *model) {
    size_t i;
    for (i = 0; i < DEV_TIMESYNC_COUNT; i++) {
        if (strcmp(DEV_TIMESYNC[i].device, model) == 0) {
            return &DEV_TIMESYNC[i];
        }
    }
    return NULL;
}

int timesync_check(const opts_t *o) {
    if (o->duration_given && !(o->duration > 0 && o->duration <= MAX_WEEK_S)) {
        note("--duration %g: expected seconds above 0 (at most a week)", o->duration);
        return EXIT_TROUBLE;
    }
    return 0;
}

/* The PPS source to write (s->source, -1: none) and whether the host sends updates: 0, or 2 (a
 * usage error printed). */
static int choose_source(sync_t *s, const char *name) {
    const dev_timesync_t *f = s->facts;
    const dev_pps_member_t *chosen = NULL;
    buf_t list = {0};
    size_t i;
    s->source = -1;
    s->send_updates = true;
    if (f->pps_param == NULL) {
        if (name != NULL) {
            note("--pps-source: %s has no PPS source setting", s->c->model->id);
            return EXIT_TROUBLE;
        }
        return 0;
    }
    for (i = 0; i < f->pps_member_count; i++) {
        const dev_pps_member_t *m = &f->pps_members[i];
        buf_fmt(&list, "%s%s", i ? ", " : "", m->name);
        if (chosen == NULL && (name != NULL ? strcmp(m->name, name) == 0 : m->kind == DEV_PPS_RECEIVER)) {
            chosen = m;
        }
    }
    if (chosen == NULL) {
        note("--pps-source %s: expected one of %s", name ? name : "None", buf_text(&list));
    } else if (chosen->kind == DEV_PPS_NONE) {
        note("--pps-source %s: no PPS (expected one of %s but %s)", chosen->name, buf_text(&list),
             chosen->name);
        chosen = NULL;
    }
    free(list.s);
    if (chosen == NULL) {
        return EXIT_TROUBLE;
    }
    s->source = chosen->value;
    s->send_updates = chosen->kind != DEV_PPS_RECEIVER; /* a receiver's: the device takes GPS time */
    return 0;
}

/* Runs a command of the spec's (set, descriptor) with the values: 0, or the exit status. */
static int command(conn_t *c, uint8_t set, uint8_t descriptor, const char *values) {
    result_t r;
    run_t run = run_values(c, set, descriptor, NULL, values, &r);
    int status = 0;
    if (run != R_OK) {
        note("%s", run == R_VALUE ? g_value_error : r.describe);
        status = run == R_FAILED ? EXIT_REFUSED : EXIT_TROUBLE;
    }
    result_free(&r);
    return status;
}

/* ------------------------------------------------------------------ the monitor */
static void edge_from(sync_t *s, double tow, double at) {
    if (isfinite(tow) && tow >= 0) {
        s->edge = at - fmod(tow, 1.0);
        s->have_edge = true;
    }
}

static int64_t int_of(const val_t *values, const char *name) {
    const val_t *v = name ? val_get(values, name) : NULL;
    return v != NULL && (v->kind == V_INT || v->kind == V_NUM) ? (int64_t)strtod(v->text, NULL) : 0;
}

static double num_of(const val_t *values, const char *name) {
    const val_t *v = name ? val_get(values, name) : NULL;
    return v != NULL && (v->kind == V_INT || v->kind == V_NUM) ? strtod(v->text, NULL) : NAN;
}

static bool bool_of(const val_t *values, const char *name) {
    const val_t *v = val_get(values, name);
    return v != NULL && ((v->kind == V_BOOL && v->b) ||
                         ((v->kind == V_INT || v->kind == V_NUM) && strtod(v->text, NULL) != 0));
}

/* One field (set, descriptor, values) of a data packet received at host time at. */
static void monitor_field(sync_t *s, int set, int descriptor, const val_t *values, double at) {
    const dev_timesync_t *f = s->facts;
    size_t i;
    if (f->status_set >= 0 && set == f->status_set && descriptor == f->status_descriptor) {
        s->packets++;
        s->pps = bool_of(values, f->status_synced);
    }
    for (i = 0; i < f->external_count; i++) {
        const dev_sync_time_t *x = &f->external[i];
        if ((set == x->set || (int)x->set == g_shared) && descriptor == x->descriptor) {
            uint32_t want = x->tow_mask | x->week_mask;
            s->time_valid = ((uint32_t)int_of(values, x->flags) & want) == want;
            edge_from(s, num_of(values, x->tow), at);
        }
    }
    if (f->corr_set >= 0 && set == f->corr_set && descriptor == f->corr_descriptor) {
        uint32_t flags = (uint32_t)int_of(values, f->corr_flags);
        s->packets++;
        s->pps = (flags & f->corr_pps) != 0;
        s->time_valid = (flags & f->corr_initialized) != 0;
        edge_from(s, num_of(values, f->corr_tow), at);
    }
}

/* conn_t's packet hook: every data packet into the clock model, and dated by it (else the time
 * it was read). */
static void on_packet(void *ctx, const codec_session_event_t *ev) {
    sync_t *s = (sync_t *)ctx;
    const uint8_t *p = ev->stream->packet;
    int64_t device_ns;
    int64_t host_ns;
    double at = (double)s->read_ns / 1e9;
    size_t n;
    if (codec_reference_ns(s->c->device, codec_packet_set(p), codec_packet_payload(p),
                           codec_packet_payload_length(p), &device_ns) &&
        codec_clock_add(&s->clock, device_ns, s->read_ns, &host_ns)) {
        at = (double)host_ns / 1e9;
    }
    n = codec_json_packet_line(ev->stream->packet, (size_t)ev->stream->length, ev->stream->offset,
                               s->c->device, g_line, sizeof g_line);
    val_t *line = json_parse(g_line, n < sizeof g_line ? n : sizeof g_line - 1);
    const val_t *set = val_get(line, "set");
    const val_t *fields = val_get(line, "fields");
    size_t i;
    for (i = 0; set != NULL && set->kind == V_INT && fields != NULL && i < fields->n; i++) {
        const val_t *d = val_get(fields->items[i], "descriptor");
        const val_t *values = val_get(fields->items[i], "values");
        if (d != NULL && d->kind == V_INT && values != NULL && values->kind == V_MAP) {
            monitor_field(s, atoi(set->text), atoi(d->text), values, at);
        }
    }
    val_free(line);
}

/* ------------------------------------------------------------------ setup */
/* The data set to stream and its fields (the status or correlation field, the external times,
 * the clock model's reference time): false when the spec names none. */
static bool stream_fields(const sync_t *s, int *set, int *fields, size_t *nf) {
    const dev_timesync_t *f = s->facts;
    size_t i;
    *nf = 0;
    if (f->status_set >= 0) {
        *set = f->status_set;
        fields[(*nf)++] = f->status_descriptor;
        for (i = 0; i < f->external_count; i++) {
            fields[(*nf)++] = f->external[i].descriptor;
        }
    } else if (f->corr_set >= 0) {
        *set = f->corr_set;
        fields[(*nf)++] = f->corr_descriptor;
    } else {
        return false;
    }
    for (i = 0; i < codec_reference_time_count; i++) {
        const codec_reference_time_t *r = &codec_reference_times[i];
        size_t k;
        if (r->device != s->c->device) {
            continue;
        }
        for (k = 0; k < *nf && fields[k] != r->descriptor; k++) {
        }
        if (k == *nf && (r->set == *set || r->shared)) {
            fields[(*nf)++] = r->descriptor;
        }
        break;
    }
    return true;
}

/* Streams the status and time fields at RATE_HZ; *setting and *previous: what to restore. */
static int setup_stream(sync_t *s, const dev_setting_t **setting, val_t **previous) {
    conn_t *c = s->c;
    int set = -1;
    int fields[16];
    size_t nf;
    const char *param = NULL;
    double base[256] = {0};
    char msg[1000];
    bool nack;
    val_t *key;
    val_t *entry;
    run_t run;
    int status;
    if (!stream_fields(s, &set, fields, &nf)) {
        note("timesync: the spec names no status field for %s", c->model->id);
        return EXIT_TROUBLE;
    }
    *setting = format_setting(c, set, &param);
    if (*setting == NULL) {
        note("timesync: %s has no message format for data set 0x%02X", c->model->id, set);
        return EXIT_TROUBLE;
    }
    status = read_base_rates(c, base);
    if (status) {
        return status;
    }
    if (base[set] <= 0) {
        note("timesync: no base rate known for data set 0x%02X", set);
        return EXIT_TROUBLE;
    }
    key = key_map(param, set);
    run = read_entry(c, *setting, key, previous, &nack, msg, sizeof msg);
    if (run != R_OK) {
        note("%s", msg);
        val_free(key);
        *setting = NULL;
        return run == R_FAILED ? EXIT_REFUSED : EXIT_TROUBLE;
    }
    entry = stream_entry(*previous, key, format_of(*setting), fields, nf,
                         (unsigned long)fmax(1.0, nearbyint(base[set] / RATE_HZ)));
    status = write_format(c, *setting, entry, NULL);
    if (status == 0) {
        status = enable_stream(c, set);
    } else {
        *setting = NULL; /* not written: nothing to restore */
    }
    val_free(key);
    val_free(entry);
    return status;
}

static int setup(sync_t *s, const dev_setting_t **setting, val_t **previous) {
    const dev_timesync_t *f = s->facts;
    if (s->source >= 0) {
        char values[300];
        int status;
        snprintf(values, sizeof values, "{\"function\":%lld,\"%s\":%lld}", (long long)function_value("write"),
                 f->pps_param, (long long)s->source);
        status = command(s->c, f->pps_set, f->pps_descriptor, values);
        if (status) {
            return status;
        }
    }
    return setup_stream(s, setting, previous);
}

/* GPS Time Updates (time of week, then week) labelling the PPS edge at host time edge. */
static int send_update(sync_t *s, double edge, double now) {
    const dev_timesync_t *f = s->facts;
    long long label = (long long)nearbyint(host_gps_seconds() - (now - edge));
    long long tow = label % WEEK_S;
    long long week = label / WEEK_S;
    int k;
    for (k = 0; k < 2; k++) {
        char values[300];
        int status;
        snprintf(values, sizeof values, "{\"function\":%lld,\"%s\":%lld,\"%s\":%lld}",
                 (long long)function_value("write"), f->update_selector,
                 (long long)(k == 0 ? f->update_tow : f->update_week), f->update_value, k == 0 ? tow : week);
        status = command(s->c, f->update_set, f->update_descriptor, values);
        if (status) {
            return status;
        }
    }
    s->updates++;
    return 0;
}

/* ------------------------------------------------------------------ the lines */
static line_t state(const sync_t *s, double t) {
    line_t l;
    l.t = round3(t);
    l.pps = s->pps > 0;
    l.time_valid = s->time_valid > 0;
    l.synced = l.pps && l.time_valid;
    l.estimated = s->clock.estimated;
    l.drift_ppm = round3(codec_clock_drift_ppm(&s->clock));
    l.offset_ms = round3((double)codec_clock_offset_ns(&s->clock) / 1e6);
    l.jitter_ms = round3((double)s->clock.bound_ns / 1e6);
    l.updates = s->updates;
    l.reason = NULL;
    if (!l.synced) {
        l.reason = !s->packets                          ? "no data"
                   : !l.pps                             ? "no PPS"
                   : s->send_updates && s->updates >= 2 ? "updates outside the window"
                                                        : "no GPS time";
    }
    return l;
}

static void show(const line_t *l, bool json) {
    buf_t b = {0};
    if (json) {
        buf_str(&b, "{\"t\":");
        py_float(&b, l->t);
        buf_fmt(&b, ",\"synced\":%s,\"pps\":%s,\"time_valid\":%s", l->synced ? "true" : "false",
                l->pps ? "true" : "false", l->time_valid ? "true" : "false");
        buf_str(&b, ",\"drift_ppm\":");
        l->estimated ? py_float(&b, l->drift_ppm) : buf_str(&b, "null");
        buf_str(&b, ",\"offset_ms\":");
        l->estimated ? py_float(&b, l->offset_ms) : buf_str(&b, "null");
        buf_str(&b, ",\"jitter_ms\":");
        l->estimated ? py_float(&b, l->jitter_ms) : buf_str(&b, "null");
        buf_fmt(&b, ",\"updates\":%lu", l->updates);
        if (l->reason != NULL) {
            buf_fmt(&b, ",\"reason\":\"%s\"", l->reason);
        }
        buf_str(&b, "}");
    } else {
        buf_fmt(&b, "t=%.1fs ", l->t);
        l->synced ? buf_str(&b, "synced") : buf_fmt(&b, "not synced (%s)", l->reason);
        buf_fmt(&b, " pps=%s time_valid=%s", l->pps ? "yes" : "no", l->time_valid ? "yes" : "no");
        if (l->estimated) {
            buf_fmt(&b, " drift=%+.1fppm offset=%+.3fms jitter=%.3fms", l->drift_ppm, l->offset_ms,
                    l->jitter_ms);
        } else {
            buf_str(&b, " drift=- offset=- jitter=-");
        }
        buf_fmt(&b, " updates=%lu", l->updates);
    }
    say("%s", buf_text(&b));
    free(b.s);
}

/* The lines and the updates until the end: 0, or the exit status of a failed command. */
static int monitor(sync_t *s, double duration, bool json, line_t *last) {
    double start = host_now(s);
    double end = start + duration;
    double next_line = start + 1.0;
    double next_update = HUGE_VAL; /* HUGE_VAL: none scheduled */
    for (;;) {
        double t = host_now(s);
        double wake;
        if (t >= next_line || t >= end) {
            *last = state(s, t - start);
            show(last, json);
            next_line += 1.0;
            if (t >= end) {
                return 0;
            }
        }
        if (s->send_updates && s->have_edge) {
            if (next_update == HUGE_VAL) {
                next_update = s->edge + floor(t - s->edge - UPDATE_AFTER_S) + 1 + UPDATE_AFTER_S;
            }
            if (t >= next_update) {
                int status = send_update(s, next_update - UPDATE_AFTER_S, t);
                if (status) {
                    return status;
                }
                next_update = HUGE_VAL;
            }
        }
        wake = fmin(fmin(next_line, end), next_update);
        if (codec_link_pump(&s->c->link, (uint32_t)fmax(1.0, (wake - host_now(s)) * 1000.0)) < 0) {
            note("%s", s->c->posix.error);
            return EXIT_TROUBLE;
        }
    }
}

int cmd_timesync(conn_t *c, const opts_t *o) {
    static sync_t s;
    const dev_setting_t *setting = NULL;
    val_t *previous = NULL;
    line_t last;
    int status;
    memset(&s, 0, sizeof s);
    memset(&last, 0, sizeof last);
    s.c = c;
    s.pps = s.time_valid = -1;
    s.facts = facts_of(c->model->id);
    if (s.facts == NULL) {
        note("timesync: the spec gives no time synchronization facts for %s", c->model->id);
        return EXIT_TROUBLE;
    }
    status = choose_source(&s, o->pps_source);
    if (status) {
        return status;
    }
    codec_clock_init(&s.clock);
    s.t0_ns = monotonic_ns();
    s.inner = c->link.transport;
    c->link.transport.ctx = &s;
    c->link.transport.read = wrap_read;
    c->link.transport.write = wrap_write;
    c->link.transport.now_ms = wrap_now_ms;
    c->packet_hook = on_packet;
    c->hook_ctx = &s;
    status = setup(&s, &setting, &previous);
    if (status == 0) {
        status = monitor(&s, o->duration_given ? o->duration : 30.0, o->json, &last);
    }
    if (setting != NULL && previous != NULL) {
        (void)write_format(c, setting, previous, "could not restore the previous message format");
    }
    c->packet_hook = NULL;
    c->link.transport = s.inner;
    val_free(previous);
    if (status) {
        return status;
    }
    if (!last.synced) {
        note("not synchronized: %s", last.reason ? last.reason : "no data");
        return EXIT_REFUSED;
    }
    return 0;
}
