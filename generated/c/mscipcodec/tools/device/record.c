/* The recorder (docs/record.md): mscipcodec-device ADDRESS record FILE [--duration S] [--split-size BYTES]
 * [--split-time S] asks the device for its Device Information, writes the reply packet first, then
 * every byte the device sends as it arrives, in whole packets (a packet cut by a read waits for its
 * end; bytes that are not part of a packet are kept). At the end (--duration, SIGINT or SIGTERM,
 * the device gone, a failed write) the bytes of a packet not finished yet are left out, so the log
 * is whole; a write that fails part way is cut back to the file's last whole packet. --split-size /
 * --split-time start FILE-stem.NNN.ext (000, 001, ...), each beginning with the Device Information
 * reply again. The Python CLI's device/record.py is the same rule, message for message.
 *
 * Exit status: 0 stopped by --duration, SIGINT or SIGTERM; 1 the device did not answer or went
 * away; 2 no connection, a file that exists or cannot be created, a failed write. No session runs:
 * the log holds the device's own bytes. Generated: do not edit. */
#include "device.h" /* first: it sets _POSIX_C_SOURCE */

#include <fcntl.h>
#include <unistd.h>

#include "mscipcodec/field_iter.h"
#include "mscipcodec/framing.h"

#define READ_WAIT_MS 200 /* a read waits at most this long (a stop request is seen within it) */
#define HELD_MAX (1u << 20)
#define READ_MAX 65536
#define PACKET_MAX (MSCIPC_HEADER_SIZE + MSCIPC_MAX_PAYLOAD + MSCIPC_CHECKSUM_SIZE)

static volatile sig_atomic_t g_stop; /* 0, or the signal that asked to stop */

static void on_stop(int sig) {
    g_stop = sig;
}

/* Whether the packet at p (a whole one) is of set `set` and holds a field `descriptor`. */
static bool holds_field(const uint8_t *p, uint8_t set, uint8_t descriptor) {
    mscipc_field_iter_t it;
    mscipc_field_entry_t e;
    if (mscipc_packet_set(p) != set) {
        return false;
    }
    mscipc_field_iter_init(&it, set, p + MSCIPC_HEADER_SIZE, p[MSCIPC_LENGTH_OFFSET]);
    while (mscipc_field_iter_next(&it, &e)) {
        if (e.kind == MSCIPC_ENTRY_FIELD && e.descriptor == descriptor) {
            return true;
        }
    }
    return false;
}

/* The end of the whole part of buf: whole packets and bytes that are not part of a packet; the rest
 * is the start of a packet that has not ended yet. With at: the (start, end) of the first packet
 * of set `set` holding a field `descriptor` (at[0] = at[1] = 0 when none). The framing rule of
 * docs/conformance.md section 1: a sync, a length at most the maximum payload and a matching
 * checksum make a packet; a false sync is one byte that is not part of a packet. */
static size_t whole(const uint8_t *buf, size_t n, uint8_t set, uint8_t descriptor, size_t *at) {
    size_t pos = 0;
    if (at != NULL) {
        at[0] = at[1] = 0;
    }
    while (pos < n) {
        size_t i = pos;
        size_t length;
        size_t body;
        size_t k;
        while (i < n && buf[i] != mscipc_sync[0]) {
            i++;
        }
        if (i == n) {
            return n;
        }
        for (k = 1; k < MSCIPC_SYNC_SIZE && i + k < n && buf[i + k] == mscipc_sync[k]; k++) {
        }
        if (k < MSCIPC_SYNC_SIZE && i + k == n) {
            return i; /* a partial sync at the very end */
        }
        if (k < MSCIPC_SYNC_SIZE) {
            pos = i + 1;
            continue;
        }
        if (n - i < MSCIPC_HEADER_SIZE) {
            return i;
        }
        length = buf[i + MSCIPC_LENGTH_OFFSET]; /* a size_t: MIP's maximum is the byte's (no warning) */
        body = MSCIPC_HEADER_SIZE + length;
        if (length <= (size_t)MSCIPC_MAX_PAYLOAD) {
            if (n - i < body + MSCIPC_CHECKSUM_SIZE) {
                return i;
            }
            if (mscipc_checksum_matches(buf + i, body)) {
                if (at != NULL && at[1] == 0 && holds_field(buf + i, set, descriptor)) {
                    at[0] = i;
                    at[1] = i + body + MSCIPC_CHECKSUM_SIZE;
                }
                pos = i + body + MSCIPC_CHECKSUM_SIZE;
                continue;
            }
        }
        pos = i + 1; /* a false sync */
    }
    return n;
}

typedef struct {
    const opts_t *o;
    const char *path;
    const uint8_t *reply;
    size_t reply_len;
    bool split;
    unsigned index;
    int fd;
    unsigned long long size;
    unsigned long long total;
    double started;
    char name[4200];
    buf_t files; /* the names written, ", " between */
    unsigned nfiles;
    char error[4400];
} log_t;

/* The index-th file of a split recording: FILE's stem, .NNN, its extension (run.bin ->
 * run.000.bin, run -> run.000). */
static void split_name(const char *path, unsigned index, char *out, size_t cap) {
    const char *slash = strrchr(path, '/');
    const char *base = slash ? slash + 1 : path;
    const char *dot = strrchr(base, '.');
    if (dot == NULL || dot == base) {
        snprintf(out, cap, "%s.%03u", path, index);
    } else {
        snprintf(out, cap, "%.*s.%03u%s", (int)(dot - path), path, index, dot);
    }
}

/* All of data, or what was written of it cut back to its last whole packet (false, l->error). */
static bool log_write_raw(log_t *l, const uint8_t *data, size_t len) {
    size_t done = 0;
    while (done < len) {
        ssize_t n = write(l->fd, data + done, len - done);
        if (n < 0) {
            int err = errno;
            if (err == EINTR) {
                continue;
            }
            if (done > 0) { /* what was written, cut back to its last whole packet */
                size_t keep = whole(data, done, 0, 0, NULL);
                if (ftruncate(l->fd, (off_t)(l->size + keep)) == 0) {
                    l->size += keep;
                    l->total += keep;
                }
            }
            snprintf(l->error, sizeof l->error, "cannot write %s: %s", l->name, strerror(err));
            return false;
        }
        done += (size_t)n;
    }
    l->size += len;
    l->total += len;
    return true;
}

static bool log_open(log_t *l) {
    if (l->split) {
        split_name(l->path, l->index, l->name, sizeof l->name);
    } else {
        copy_text(l->name, sizeof l->name, l->path);
    }
    l->fd = open(l->name, O_WRONLY | O_CREAT | O_EXCL, 0666);
    if (l->fd < 0) {
        snprintf(l->error, sizeof l->error, "cannot create %s: %s", l->name,
                 errno == EEXIST ? "exists" : strerror(errno));
        return false;
    }
    buf_fmt(&l->files, "%s%s", l->nfiles++ ? ", " : "", l->name);
    l->size = 0;
    l->started = now_s();
    return log_write_raw(l, l->reply, l->reply_len);
}

static void log_close(log_t *l) {
    if (l->fd >= 0) {
        close(l->fd);
        l->fd = -1;
    }
}

/* Whole packets (and bytes between packets); a new file first when the current one is full or
 * old. */
static bool log_write(log_t *l, const uint8_t *data, size_t len) {
    if (len == 0) {
        return true;
    }
    if (l->split && l->size > l->reply_len) {
        bool full = l->o->split_size > 0 && (double)l->size >= l->o->split_size;
        bool old = l->o->split_time > 0 && now_s() - l->started >= l->o->split_time;
        if (full || old) {
            log_close(l);
            l->index++;
            if (!log_open(l)) {
                return false;
            }
        }
    }
    return log_write_raw(l, data, len);
}

/* The bytes received and not written yet. */
typedef struct {
    uint8_t *bytes; /* HELD_MAX */
    size_t n;
} held_t;

/* Writes the whole part of what is held and keeps the rest: false when the write failed. */
static bool flush_whole(log_t *l, held_t *h) {
    size_t e = whole(h->bytes, h->n, 0, 0, NULL);
    if (!log_write(l, h->bytes, e)) {
        return false;
    }
    memmove(h->bytes, h->bytes + e, h->n - e);
    h->n -= e;
    return true;
}

/* Asks for the Device Information and waits for its reply: 0 with the reply moved out of what is
 * held (reply[*reply_len]), or 1 (the message printed). */
static int await_reply(const opts_t *o, mscipc_posix_t *posix, mscipc_transport_t *tr, held_t *h,
                       uint8_t *reply, size_t *reply_len) {
    mscipc_packet_builder_t b;
    uint8_t packet[PACKET_MAX];
    size_t len = 0;
    double deadline = now_s() + (double)o->timeout_ms / 1000.0;
    size_t at[2];
    mscipc_packet_begin(&b, packet, sizeof packet, DEV_IDENTITY_SET);
    mscipc_packet_add_field(&b, DEV_IDENTITY_DESCRIPTOR, NULL, 0);
    if (mscipc_packet_finish(&b, &len) != MSCIPC_OK || tr->write(tr->ctx, packet, len) != 0) {
        note("the device went away before it answered (%s)", posix->reason);
        return EXIT_REFUSED;
    }
    for (;;) {
        double left = deadline - now_s();
        int n;
        if (left <= 0 || g_stop) {
            mscipc_status_t why;
            const mscipc_field_info_t *f = mscipc_find_field(DEV_IDENTITY_SET, DEV_IDENTITY_DESCRIPTOR, &why);
            note("no answer to the device information command (%s: no reply before the timeout)",
                 f ? f->name : "?");
            return EXIT_REFUSED;
        }
        n = tr->read(tr->ctx, h->bytes + h->n, HELD_MAX - h->n,
                     (uint32_t)(left * 1000 < READ_WAIT_MS ? left * 1000 : READ_WAIT_MS));
        if (n < 0) {
            note("the device went away before it answered (%s)", posix->reason);
            return EXIT_REFUSED;
        }
        h->n += (size_t)n;
        whole(h->bytes, h->n, DEV_REPORTS[0].set, DEV_REPORTS[0].descriptor, at);
        if (at[1] > at[0]) {
            *reply_len = at[1] - at[0];
            memcpy(reply, h->bytes + at[0], *reply_len);
            memmove(h->bytes + at[0], h->bytes + at[1], h->n - at[1]);
            h->n -= *reply_len;
            return 0;
        }
        if (h->n == HELD_MAX) { /* a flood without the reply: keep the newest bytes' chance */
            size_t keep = whole(h->bytes, h->n, 0, 0, NULL);
            memmove(h->bytes, h->bytes + keep, h->n - keep);
            h->n -= keep;
        }
    }
}

/* Records until --duration, a signal, the device gone or a failed write: the exit status, why it
 * stopped in why. */
static int record_loop(log_t *l, mscipc_posix_t *posix, mscipc_transport_t *tr, held_t *h, char *why,
                       size_t cap) {
    double end = l->o->duration > 0 ? now_s() + l->o->duration : 0;
    copy_text(why, cap, "--duration");
    for (;;) {
        double now;
        double wait;
        int n;
        if (!flush_whole(l, h)) {
            break;
        }
        if (g_stop) {
            copy_text(why, cap, g_stop == SIGINT ? "interrupted" : "terminated");
            return 0;
        }
        now = now_s();
        if (end > 0 && now >= end) {
            return 0;
        }
        wait = end > 0 && (end - now) * 1000 < READ_WAIT_MS ? (end - now) * 1000 : READ_WAIT_MS;
        n = tr->read(tr->ctx, h->bytes + h->n, READ_MAX < HELD_MAX - h->n ? READ_MAX : HELD_MAX - h->n,
                     (uint32_t)wait);
        if (n < 0) {
            snprintf(why, cap, "the device went away (%s)", posix->reason);
            if (!flush_whole(l, h)) {
                break;
            }
            return EXIT_REFUSED;
        }
        h->n += (size_t)n;
    }
    note("%s", l->error);
    copy_text(why, cap, "the write failed");
    h->n = 0; /* not written: the disk is full, not a packet unfinished */
    return EXIT_TROUBLE;
}

/* Connected: the reply, the log and the recording; the exit status. */
static int record_device(const opts_t *o, const char *path, mscipc_posix_t *posix) {
    mscipc_transport_t tr;
    uint8_t reply[PACKET_MAX];
    held_t h;
    log_t l;
    char why[700];
    int status;
    mscipc_posix_transport(posix, &tr);
    h.bytes = (uint8_t *)xalloc(HELD_MAX);
    h.n = 0;
    memset(&l, 0, sizeof l);
    l.fd = -1;
    l.o = o;
    l.path = path;
    l.split = o->split_size > 0 || o->split_time > 0;
    l.reply = reply;
    status = await_reply(o, posix, &tr, &h, reply, &l.reply_len);
    if (status == 0 && !log_open(&l)) {
        note("%s", l.error);
        status = EXIT_TROUBLE;
    } else if (status == 0) {
        status = record_loop(&l, posix, &tr, &h, why, sizeof why);
        if (h.n) {
            note("%llu bytes in %u file(s) (%s); stopped: %s; %zu bytes of an unfinished packet left out",
                 l.total, l.nfiles, buf_text(&l.files), why, h.n);
        } else {
            note("%llu bytes in %u file(s) (%s); stopped: %s", l.total, l.nfiles, buf_text(&l.files), why);
        }
    }
    log_close(&l);
    free(l.files.s);
    free(h.bytes);
    return status;
}

/* A FILE ending in .mcap (any case). */
static int is_mcap(const char *path) {
    static const char ext[] = ".mcap";
    size_t n = strlen(path);
    size_t i;
    if (n < sizeof ext - 1) {
        return 0;
    }
    for (i = 0; i < sizeof ext - 1; i++) {
        char c = path[n - (sizeof ext - 1) + i];
        if (c >= 'A' && c <= 'Z') {
            c = (char)(c - 'A' + 'a');
        }
        if (c != ext[i]) {
            return 0;
        }
    }
    return 1;
}

int cmd_record(const char *address, const opts_t *o) {
    mscipc_posix_t posix;
    struct sigaction sa;
    struct sigaction old_int;
    struct sigaction old_term;
    char first[4200];
    struct stat st;
    int status;
    if (o->npos != 1) {
        note("record: give one FILE");
        return EXIT_TROUBLE;
    }
    if (DEV_IDENTITY_SET == 0 || DEV_REPORT_COUNT == 0) {
        note("the spec names no device information command");
        return EXIT_TROUBLE;
    }
    if (is_mcap(o->pos[0])) { /* not a raw log under an MCAP name (docs/mcap.md) */
        note("record: %s: MCAP files are written by the Python package's recorder (docs/mcap.md); "
             "this tool records raw logs",
             o->pos[0]);
        return EXIT_TROUBLE;
    }
    if (o->split_size > 0 || o->split_time > 0) {
        split_name(o->pos[0], 0, first, sizeof first);
    } else {
        copy_text(first, sizeof first, o->pos[0]);
    }
    if (lstat(first, &st) == 0) {
        note("cannot create %s: exists", first);
        return EXIT_TROUBLE;
    }
    if (mscipc_posix_open(&posix, address, o->baud ? o->baud : DEFAULT_BAUD) != MSCIPC_OK) {
        note("%s", posix.error);
        return EXIT_TROUBLE;
    }
    memset(&sa, 0, sizeof sa);
    sa.sa_handler = on_stop; /* no SA_RESTART: a read waiting returns at once */
    sigemptyset(&sa.sa_mask);
    sigaction(SIGINT, &sa, &old_int);
    sigaction(SIGTERM, &sa, &old_term);
    signal(SIGXFSZ, SIG_IGN); /* a file size limit: the write fails with EFBIG instead */
    status = record_device(o, o->pos[0], &posix);
    mscipc_posix_close(&posix);
    sigaction(SIGINT, &old_int, NULL);
    sigaction(SIGTERM, &old_term, NULL);
    return status;
}
