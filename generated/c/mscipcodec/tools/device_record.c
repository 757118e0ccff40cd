/* The recorder of the device tool (docs/record.md): asks the device for its Device Information,
 * writes the reply packet first, then every byte the device sends as it arrives, in whole packets
 * (a packet cut by a read waits for its end; bytes that are not part of a packet are kept). At the
 * end (--duration, SIGINT or SIGTERM, the device gone, a failed write) the bytes of a packet not
 * finished yet are left out, so the log is whole; a write that fails part way is cut back to the
 * file's last whole packet. --split-size / --split-time start FILE-stem.NNN.ext (000, 001, ...),
 * each beginning with the Device Information reply again. The Python CLI's recorder.py is the same
 * rule, message for message. Generated: do not edit. */
#if !defined(_POSIX_C_SOURCE) || _POSIX_C_SOURCE < 200809L
#undef _POSIX_C_SOURCE
#define _POSIX_C_SOURCE 200809L
#endif
#include "device_record.h"

#include <errno.h>
#include <fcntl.h>
#include <signal.h>
#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <time.h>
#include <unistd.h>

#include "mscipcodec/field_iter.h"
#include "mscipcodec/framing.h"
#include "mscipcodec/json.h"
#include "mscipcodec/posix_transport.h"

#define PROG "mscipcodec-device"
#define READ_WAIT_MS 200 /* a read waits at most this long (a stop request is seen within it) */
#define HELD_MAX (1u << 20)
#define READ_MAX 65536

static volatile sig_atomic_t g_stop; /* 0, or the signal that asked to stop */

static void on_stop(int sig) {
    g_stop = sig;
}

static double now_s(void) {
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + (double)ts.tv_nsec / 1e9;
}

/* The end of the whole part of buf: whole packets and bytes that are not part of a packet; the rest
 * is the start of a packet that has not ended yet. With at: the (start, end) of the first packet
 * of set `set` holding a field `descriptor` (at[0] = at[1] = 0 when none). The framing rule of
 * docs/conformance.md section 1: a sync, a length at most the maximum payload and a matching
 * checksum make a packet; a false sync is one byte that is not part of a packet. */
static size_t whole(const uint8_t *buf, size_t n, int set, int descriptor, size_t *at) {
    size_t pos = 0;
    if (at != NULL) {
        at[0] = at[1] = 0;
    }
    while (pos < n) {
        size_t i = pos;
        size_t body;
        size_t k;
        while (i < n && buf[i] != mscipc_sync[0]) {
            i++;
        }
        if (i == n) {
            return n;
        }
        for (k = 1; k < MSCIPC_SYNC_SIZE; k++) {
            if (i + k == n) {
                return i; /* a partial sync at the very end */
            }
            if (buf[i + k] != mscipc_sync[k]) {
                break;
            }
        }
        if (k < MSCIPC_SYNC_SIZE) {
            pos = i + 1;
            continue;
        }
        if (n - i < MSCIPC_HEADER_SIZE) {
            return i;
        }
        body = MSCIPC_HEADER_SIZE + buf[i + MSCIPC_LENGTH_OFFSET];
        if ((unsigned)buf[i + MSCIPC_LENGTH_OFFSET] + 0u <= (unsigned)MSCIPC_MAX_PAYLOAD) {
            if (n - i < body + MSCIPC_CHECKSUM_SIZE) {
                return i;
            }
            if (mscipc_checksum_matches(buf + i, body)) {
                if (at != NULL && at[1] == 0 && set >= 0 && mscipc_packet_set(buf + i) == (uint8_t)set) {
                    mscipc_field_iter_t it;
                    mscipc_field_entry_t e;
                    mscipc_field_iter_init(&it, (uint8_t)set, buf + i + MSCIPC_HEADER_SIZE,
                                           buf[i + MSCIPC_LENGTH_OFFSET]);
                    while (mscipc_field_iter_next(&it, &e)) {
                        if (e.kind == MSCIPC_ENTRY_FIELD && e.descriptor == (uint8_t)descriptor) {
                            at[0] = i;
                            at[1] = body + MSCIPC_CHECKSUM_SIZE + i;
                            break;
                        }
                    }
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
    const device_record_options_t *o;
    const uint8_t *reply;
    size_t reply_len;
    bool split;
    unsigned index;
    int fd;
    unsigned long long size;
    unsigned long long total;
    double started;
    char name[4200];
    char *files; /* the names written, ", " between */
    size_t files_len;
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
                size_t keep = whole(data, done, -1, 0, NULL);
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
    size_t n;
    if (l->split) {
        split_name(l->o->path, l->index, l->name, sizeof l->name);
    } else {
        snprintf(l->name, sizeof l->name, "%s", l->o->path);
    }
    l->fd = open(l->name, O_WRONLY | O_CREAT | O_EXCL, 0666);
    if (l->fd < 0) {
        snprintf(l->error, sizeof l->error, "cannot create %s: %s", l->name,
                 errno == EEXIST ? "exists" : strerror(errno));
        return false;
    }
    n = strlen(l->name);
    l->files = (char *)realloc(l->files, l->files_len + n + 3);
    if (l->files == NULL) {
        fprintf(stderr, PROG ": out of memory\n");
        exit(2);
    }
    if (l->nfiles++) {
        memcpy(l->files + l->files_len, ", ", 2);
        l->files_len += 2;
    }
    memcpy(l->files + l->files_len, l->name, n + 1);
    l->files_len += n;
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

static void note(const char *text) {
    fprintf(stderr, PROG ": %s\n", text);
    fflush(stderr);
}

/* Waits for the Device Information reply: 0 with the reply moved out of held (*reply), or 1. */
static int await_reply(const device_record_options_t *o, mscipc_transport_t *tr, mscipc_posix_t *posix,
                       uint8_t *held, size_t *nheld, uint8_t *reply, size_t *reply_len) {
    double deadline = now_s() + (double)o->timeout_ms / 1000.0;
    size_t at[2];
    for (;;) {
        double left = deadline - now_s();
        int n;
        if (left <= 0 || g_stop) {
            char msg[300];
            const mscipc_field_info_t *f;
            mscipc_status_t why;
            f = mscipc_find_field(o->command_set, o->command_descriptor, &why);
            snprintf(msg, sizeof msg,
                     "no answer to the device information command (%s: no reply before the timeout)",
                     f ? f->name : "?");
            note(msg);
            return 1;
        }
        n = tr->read(tr->ctx, held + *nheld, HELD_MAX - *nheld,
                     (uint32_t)(left * 1000 < READ_WAIT_MS ? left * 1000 : READ_WAIT_MS));
        if (n < 0) {
            char msg[600];
            snprintf(msg, sizeof msg, "the device went away before it answered (%s)", posix->reason);
            note(msg);
            return 1;
        }
        *nheld += (size_t)n;
        whole(held, *nheld, o->reply_set, o->reply_descriptor, at);
        if (at[1] > at[0]) {
            *reply_len = at[1] - at[0];
            memcpy(reply, held + at[0], *reply_len);
            memmove(held + at[0], held + at[1], *nheld - at[1]);
            *nheld -= *reply_len;
            return 0;
        }
        if (*nheld == HELD_MAX) { /* a flood without the reply: keep the newest bytes' chance */
            size_t keep = whole(held, *nheld, -1, 0, NULL);
            memmove(held, held + keep, *nheld - keep);
            *nheld -= keep;
        }
    }
}

int device_record(const device_record_options_t *o) {
    mscipc_posix_t posix;
    mscipc_transport_t tr;
    mscipc_packet_builder_t b;
    uint8_t packet[MSCIPC_HEADER_SIZE + MSCIPC_MAX_PAYLOAD + MSCIPC_CHECKSUM_SIZE];
    uint8_t reply[MSCIPC_HEADER_SIZE + MSCIPC_MAX_PAYLOAD + MSCIPC_CHECKSUM_SIZE];
    size_t reply_len = 0;
    size_t len = 0;
    uint8_t *held;
    size_t nheld = 0;
    log_t l;
    struct sigaction sa;
    struct sigaction old_int;
    struct sigaction old_term;
    int status = 0;
    char why[700] = "--duration";
    char first[4200];
    double end;
    struct stat st;
    memset(&l, 0, sizeof l);
    l.fd = -1;
    l.o = o;
    l.split = o->split_size > 0 || o->split_time > 0;
    if (l.split) {
        split_name(o->path, 0, first, sizeof first);
    } else {
        snprintf(first, sizeof first, "%s", o->path);
    }
    if (lstat(first, &st) == 0) {
        char msg[4300];
        snprintf(msg, sizeof msg, "cannot create %s: exists", first);
        note(msg);
        return 2;
    }
    if (mscipc_posix_open(&posix, o->address, o->baud) != MSCIPC_OK) {
        note(posix.error);
        return 2;
    }
    mscipc_posix_transport(&posix, &tr);
    memset(&sa, 0, sizeof sa);
    sa.sa_handler = on_stop; /* no SA_RESTART: a read waiting returns at once */
    sigemptyset(&sa.sa_mask);
    sigaction(SIGINT, &sa, &old_int);
    sigaction(SIGTERM, &sa, &old_term);
    signal(SIGXFSZ, SIG_IGN); /* a file size limit: the write fails with EFBIG instead */
    held = (uint8_t *)malloc(HELD_MAX);
    if (held == NULL) {
        note("out of memory");
        mscipc_posix_close(&posix);
        return 2;
    }
    mscipc_packet_begin(&b, packet, sizeof packet, o->command_set);
    mscipc_packet_add_field(&b, o->command_descriptor, NULL, 0);
    if (mscipc_packet_finish(&b, &len) != MSCIPC_OK || tr.write(tr.ctx, packet, len) != 0) {
        char msg[600];
        snprintf(msg, sizeof msg, "the device went away before it answered (%s)", posix.reason);
        note(msg);
        status = 1;
    }
    if (status == 0) {
        status = await_reply(o, &tr, &posix, held, &nheld, reply, &reply_len);
    }
    if (status == 0) {
        l.reply = reply;
        l.reply_len = reply_len;
        if (!log_open(&l)) {
            note(l.error);
            status = 2;
            log_close(&l);
            free(l.files);
            l.files = NULL;
        }
    }
    if (status != 0) {
        free(held);
        mscipc_posix_close(&posix);
        sigaction(SIGINT, &old_int, NULL);
        sigaction(SIGTERM, &old_term, NULL);
        return status;
    }
    end = o->duration > 0 ? now_s() + o->duration : 0;
    for (;;) {
        size_t e = whole(held, nheld, -1, 0, NULL);
        double now;
        double wait;
        int n;
        if (!log_write(&l, held, e)) {
            note(l.error);
            status = 2;
            snprintf(why, sizeof why, "the write failed");
            nheld = 0; /* not written: the disk is full, not a packet unfinished */
            break;
        }
        memmove(held, held + e, nheld - e);
        nheld -= e;
        if (g_stop) {
            snprintf(why, sizeof why, "%s", g_stop == SIGINT ? "interrupted" : "terminated");
            break;
        }
        now = now_s();
        if (end > 0 && now >= end) {
            break;
        }
        wait = end > 0 && (end - now) * 1000 < READ_WAIT_MS ? (end - now) * 1000 : READ_WAIT_MS;
        n = tr.read(tr.ctx, held + nheld, READ_MAX < HELD_MAX - nheld ? READ_MAX : HELD_MAX - nheld,
                    (uint32_t)wait);
        if (n < 0) {
            status = 1;
            snprintf(why, sizeof why, "the device went away (%s)", posix.reason);
            e = whole(held, nheld, -1, 0, NULL);
            if (!log_write(&l, held, e)) {
                note(l.error);
                status = 2;
                snprintf(why, sizeof why, "the write failed");
                nheld = 0;
            } else {
                memmove(held, held + e, nheld - e);
                nheld -= e;
            }
            break;
        }
        nheld += (size_t)n;
    }
    log_close(&l);
    {
        char left[100] = "";
        if (nheld) {
            snprintf(left, sizeof left, "; %zu bytes of an unfinished packet left out", nheld);
        }
        fprintf(stderr, PROG ": %llu bytes in %u file(s) (%s); stopped: %s%s\n", l.total, l.nfiles,
                l.files ? l.files : "", why, left);
    }
    free(l.files);
    free(held);
    mscipc_posix_close(&posix);
    sigaction(SIGINT, &old_int, NULL);
    sigaction(SIGTERM, &old_term, NULL);
    return status;
}
